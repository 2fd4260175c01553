//! Lesson 02b: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_02b_path_names_keep_off_the_ghosts_and_balls_when_orbited() {
    // Figure 1 with the straight line beside (lessons/02b-expressive-animation/lesson.js: target
    // (0, 0.9, 0), distance 7.5, yaw 0, pitch 0.35), orbited round, at the page's 12 ghosts and at
    // 48 (with the page's arc and a tall one), at a few times of the loop: "arc" and "straight line" are shown where the figure put
    // them, cover no ghost or ball (their discs on the canvas), no dot or wide line, and keep
    // apart.
    use inbetween::figures::expressive::Spacing;
    let mut failures = Vec::new();
    for (ghosts, arc) in [(12.0, 1.2), (48.0, 1.2), (48.0, 2.35)] {
        for yaw in [-1.6, -1.04, -0.5, 0.0, 0.5, 1.04, 1.6] {
            for pitch in [0.1, 0.35, 0.7] {
                for time in [0.0, 0.4, 0.75, 2.2] {
                    for size in CANVASES_02B {
                        failures.extend(failure_of(|| {
                            let mut scene = Spacing::new();
                            scene.set_ghosts(ghosts).unwrap();
                            scene.set_arc_height(arc).unwrap();
                            let view = [0.0, 0.9, 0.0, 7.5, yaw, pitch];
                            let (frame, camera) = drawn_for_view(
                                &mut scene,
                                view,
                                size,
                                |fig, out| {
                                    fig.draw(out, time).unwrap();
                                },
                                |fig, cam, px| fig.set_view(cam, px.x, px.y),
                            );
                            let name = format!(
                                "02b spacing, {ghosts} ghosts, arc {arc} m, yaw {yaw}, pitch {pitch}, t {time}"
                            );
                            let view_proj = camera.projection(size.x / size.y) * camera.view();
                            let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                            // The ghosts (points) and the balls (meshes, by their translation).
                            let mut discs: Vec<(Vec2, f32)> = frame
                                .points
                                .iter()
                                .map(|p| {
                                    let c = Vec3::from(p.center);
                                    (at(c), at(c).distance(at(c + Vec3::Y * p.radius.abs())))
                                })
                                .collect();
                            for m in &frame.meshes {
                                let model = m.model;
                                let c = model.w_axis.truncate();
                                let r = model
                                    .x_axis
                                    .truncate()
                                    .length()
                                    .max(model.y_axis.truncate().length());
                                if r < 0.5 {
                                    discs.push((at(c), at(c).distance(at(c + Vec3::Y * r))));
                                }
                            }
                            let placed = layout(&frame, &camera, size);
                            let mut boxes = Vec::new();
                            for (i, (l, b, p)) in placed.iter().enumerate() {
                                if l.text != "arc" && l.text != "straight line" {
                                    continue;
                                }
                                let rect = Rect {
                                    min: p.top_left,
                                    size: b.size,
                                };
                                for &(c, r) in &discs {
                                    assert!(
                                        rect.nearest(c).distance(c) > r,
                                        "{name} on {size}: {:?} at {:?} over a ball at {c}",
                                        l.text,
                                        rect.min
                                    );
                                }
                                assert_shown_clear_by(&name, &frame, &camera, size, &[i], 0.0);
                                boxes.push(rect);
                            }
                            assert_eq!(boxes.len(), 2, "{name}: both names");
                            assert!(
                                !boxes[0].overlaps(&boxes[1], 2.0),
                                "{name} on {size}: names touch"
                            );
                        }));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_02b_straight_line_name_sits_under_its_row_at_the_page_camera() {
    // Figure 1 at the page's camera and settings (12 ghosts, the straight line beside), both
    // canvases, times when the twin's ball is near a key: "straight line" is shown where the
    // figure put it, just under the middle of the twin's row of ghosts (the line from
    // (-2.5, 0.3, -1.4) to (2.5, 0.3, -1.4)), not by the arc's end where the two paths' ghosts
    // meet.
    use inbetween::figures::expressive::Spacing;
    for time in [0.0, 0.2, 1.4, 2.9] {
        for size in CANVASES_02B {
            let mut scene = Spacing::new();
            let (frame, camera) = drawn_for_view(
                &mut scene,
                [0.0, 0.9, 0.0, 7.5, 0.0, 0.35],
                size,
                |fig, out| {
                    fig.draw(out, time).unwrap();
                },
                |fig, cam, px| fig.set_view(cam, px.x, px.y),
            );
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let mid = project_to_canvas(view_proj, size, Vec3::new(0.0, 0.3, -1.4)).unwrap();
            let i = frame.labels.iter().position(|l| l.text == "straight line").unwrap();
            let (_, b, p) = &layout(&frame, &camera, size)[i];
            let at = format!("t {time} on {size}");
            assert!(p.shown && p.leader_to.is_none(), "{at}: moved");
            let centre = p.top_left + 0.5 * b.size;
            assert!((centre.x - mid.x).abs() < 20.0, "{at}: {centre} beside {mid}");
            assert!(
                (mid.y..mid.y + 40.0).contains(&p.top_left.y),
                "{at}: {:?} under {mid}",
                p.top_left
            );
        }
    }
}

#[test]
fn lesson_02b_straight_line_name_keeps_to_its_row_where_the_rows_meet() {
    // Figure 1 with a tall arc (2.35 m) and 48 ghosts, orbited as the page test's drag across the
    // canvas turns it (yaw 0 to -1.04, pitch 0.35 to 0.69), both canvases, through the loop: the
    // two rows meet on the canvas near key 2, and "straight line" lies nearer its own row (the
    // twin's line, 1.4 m behind) than the arc's, so it names one row.
    use inbetween::expressive::arc_point;
    use inbetween::figures::expressive::Spacing;
    let (start, end) = (Vec3::new(-2.5, 0.3, 0.0), Vec3::new(2.5, 0.3, 0.0));
    let mut failures = Vec::new();
    for (yaw, pitch) in [(-0.59, 0.69), (-1.04, 0.69), (-0.59, 0.5)] {
        for time in [0.0, 0.4, 1.1, 2.2] {
            for size in CANVASES_02B {
                let mut scene = Spacing::new();
                scene.set_ghosts(48.0).unwrap();
                scene.set_arc_height(2.35).unwrap();
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    [0.0, 0.9, 0.0, 7.5, yaw, pitch],
                    size,
                    |fig, out| {
                        fig.draw(out, time).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                let (_, rect) = label_boxes(&frame, &camera, size)
                    .into_iter()
                    .find(|(t, _)| t == "straight line")
                    .unwrap();
                // Each row sampled every 1/32 of the way.
                let nearest = |row: &dyn Fn(f32) -> Vec3| {
                    (0..=32)
                        .map(|k| rect.nearest(at(row(k as f32 / 32.0))).distance(at(row(k as f32 / 32.0))))
                        .fold(f32::MAX, f32::min)
                };
                let twin = nearest(&|f| start.lerp(end, f) + Vec3::new(0.0, 0.0, -1.4));
                let arc = nearest(&|f| arc_point(start, end, Vec3::Y, 2.35, f));
                let name = format!("02b spacing, yaw {yaw}, pitch {pitch}, t {time} on {size}");
                failures.extend(failure_of(|| {
                    assert!(
                        twin < arc,
                        "{name}: \"straight line\" at {:?} is {twin} px from its row, {arc} px from the arc",
                        rect.min
                    )
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

/// Points on the frame's spheres (`MeshId::SPHERE`, the unit sphere under each model) as seen
/// on the canvas: a 24 × 48 grid of latitudes and longitudes on each.
fn sphere_points(frame: &Frame, camera: &OrbitCamera, size: Vec2) -> Vec<Vec2> {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    frame
        .meshes
        .iter()
        .filter(|m| m.mesh == inbetween::draw::MeshId::SPHERE)
        .flat_map(|m| {
            (0..24 * 48).map(move |i| {
                let (lat, lon) = ((i / 48) as f32 / 23.0 * std::f32::consts::PI, (i % 48) as f32);
                let lon = lon / 48.0 * std::f32::consts::TAU;
                let d = Vec3::new(lat.sin() * lon.cos(), -lat.cos(), lat.sin() * lon.sin());
                m.model.transform_point3(d)
            })
        })
        .filter_map(|p| project_to_canvas(view_proj, size, p))
        .collect()
}

#[test]
fn lesson_02b_jump_names_sit_clear_under_their_balls() {
    // Figure 3 at its page camera (lessons/02b-expressive-animation/lesson.js: target (0, 1.1, 0),
    // distance 6, pitch 0.15) and orbited a little higher, both canvases, at the default and
    // the caption's heavy crouch, through the crouch, the flight and the landing: "plain" and
    // "principles" keep at least 3 px from every ball's outline (a name that touches the ball
    // reads as part of it).
    use inbetween::figures::expressive::JumpComparison;
    let mut failures = Vec::new();
    for anticipation in [0.3, 0.6] {
        for pitch in [0.15, 0.35] {
            for time in [0.0, 0.2, 0.5, 1.0, 1.6, 2.0] {
                for size in CANVASES_02B {
                    failures.extend(failure_of(|| {
                        let mut scene = JumpComparison::new();
                        scene.set_principles(anticipation, 0.06).unwrap();
                        let (frame, camera) = drawn_for_view(
                            &mut scene,
                            [0.0, 1.1, 0.0, 6.0, 0.0, pitch],
                            size,
                            |fig, out| {
                                fig.draw(out, time).unwrap();
                            },
                            |_, _, _| {},
                        );
                        let balls = sphere_points(&frame, &camera, size);
                        let boxes = label_boxes(&frame, &camera, size);
                        for (text, rect) in boxes.iter().filter(|(t, _)| t == "plain" || t == "principles") {
                            let gap = balls
                                .iter()
                                .map(|&c| rect.nearest(c).distance(c))
                                .fold(f32::INFINITY, f32::min);
                            assert!(
                                gap >= 3.0,
                                "02b jump, crouch {anticipation}, pitch {pitch}, t {time} on {size}: {text:?} at {:?} is {gap} px from a ball",
                                rect.min
                            );
                        }
                        assert_eq!(boxes.iter().filter(|(t, _)| t == "plain" || t == "principles").count(), 2);
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_02b_antenna_stands_up_on_screen_from_any_orbit() {
    // Figure 4 at its page camera (lessons/02b-expressive-animation/lesson.js: target
    // (0, 1.3, 0), distance 4.2, yaw -0.3, pitch 0.35) and orbited higher, up to the pole, as a
    // drag does, with the viewer's fit: the antenna (its wide line) stays at least 0.7 of its
    // height on screen at the page camera, so its joints never stack into a dot seen from above
    // and the sideways lag still reads against the body's slide.
    use inbetween::figures::expressive::{FollowThrough, ANTENNA};
    let height = |pitch: f32, size: Vec2| {
        let mut scene = FollowThrough::default();
        let (frame, camera) = drawn_for_view(
            &mut scene,
            [0.0, 1.3, 0.0, 4.2, -0.3, pitch],
            size,
            |fig, out| {
                fig.draw(out, 0.0).unwrap();
            },
            |_, _, _| {},
        );
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let ys: Vec<f32> = frame
            .strokes
            .iter()
            .filter(|s| Vec3::new(s.color[0], s.color[1], s.color[2]).distance(ANTENNA) < 1e-3)
            .flat_map(|s| [s.a, s.b])
            .filter_map(|p| project_to_canvas(view_proj, size, Vec3::from(p)))
            .map(|p| p.y)
            .collect();
        assert!(!ys.is_empty(), "the antenna is drawn");
        let (lo, hi) = ys.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
        hi - lo
    };
    for size in CANVASES_02B {
        let page = height(0.35, size);
        for pitch in [0.6, 0.9, 1.2, 1.55] {
            let seen = height(pitch, size);
            assert!(seen >= 0.7 * page, "pitch {pitch} on {size}: the antenna is {seen} px tall, {page} px at the page camera");
        }
    }
}
