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
