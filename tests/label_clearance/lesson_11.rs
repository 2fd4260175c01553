//! Lesson 11: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_11_spring_labels_keep_off_the_walls_springs_and_bars() {
    // Figure 3 at the page's camera (SpringFigure::view), at both canvases, for the default
    // step and the caption's 0.1 s: the three names and "exact" keep off the coils, the exact
    // bars, the rest and turning-point ticks, and the walls (the grey boxes the springs hang
    // from, checked at their eight corners and centre). At times when the exact mass is at or
    // right of the rest position. As on the page, the figure places the names for the view of
    // the frame before.
    use inbetween::draw::palette;
    use inbetween::figures::particles::{SpringFigure, EXACT_COLOR};
    for dt in [0.02, 0.1] {
        let mut scene = SpringFigure::new();
        scene.set_dt(dt).unwrap();
        for time_sec in [0.0, 0.25, 0.5, 2.5] {
            for size in CANVASES {
                let view = scene.view();
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    view,
                    size,
                    |fig, out| {
                        fig.draw(out, time_sec).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let name = format!("11 spring, dt {dt}, t {time_sec}");
                assert_clear(&name, &frame, &camera, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let walls: Vec<Vec2> = frame
                    .meshes
                    .iter()
                    .filter(|m| m.color.truncate() == palette::GREY)
                    .flat_map(|m| {
                        let mut points: Vec<Vec3> = (0..8)
                            .map(|c| {
                                let s = |bit: i32| if c & bit == 0 { -1.0 } else { 1.0 };
                                m.model.transform_point3(Vec3::new(s(1), s(2), s(4)))
                            })
                            .collect();
                        points.push(m.model.w_axis.truncate());
                        points
                    })
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                assert_eq!(walls.len(), 27, "three walls");
                // "exact" just below the front row's bar (its near end, the lowest on screen):
                // its box's top 4 to 12 px under the bar's end, which lies within its width.
                let bars: Vec<Vec2> = frame
                    .strokes
                    .iter()
                    .filter(|s| Vec3::from_slice(&s.color[..3]) == EXACT_COLOR && s.width_px == 5.0)
                    .flat_map(|s| [s.a, s.b])
                    .filter_map(|p| project_to_canvas(view_proj, size, Vec3::from(p)))
                    .collect();
                assert_eq!(bars.len(), 6, "{name}: three bars");
                let end = bars.iter().copied().fold(Vec2::MIN, |a, b| if b.y > a.y { b } else { a });
                let (_, exact) = label_boxes(&frame, &camera, size)
                    .into_iter()
                    .find(|(t, _)| t == "exact")
                    .unwrap();
                let below = exact.min.y - end.y;
                assert!(
                    (4.0..=12.0).contains(&below) && (exact.min.x..=exact.max().x).contains(&end.x),
                    "{name} on {size}: \"exact\" at {:?}, the front bar's end at {end}",
                    exact.min
                );
                for (text, rect) in label_boxes(&frame, &camera, size) {
                    for w in &walls {
                        assert!(
                            !(w.cmpgt(rect.min).all() && w.cmplt(rect.max()).all()),
                            "{name} on {size}: {text:?} covers a wall at {w}"
                        );
                    }
                }
            }
        }
    }
}

/// Checks that every label of `frame` is shown where the figure put it, its box `reach_px` at
/// most from its anchor's projection (the dot it names; `LABEL_DOT_GAP_PX` at least), every two
/// boxes at least 6 px apart, and all clear of the dots and lines.
fn assert_named_beside_dots(
    name: &str,
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
    reach_px: f32,
) {
    use inbetween::draw::LABEL_DOT_GAP_PX;
    assert_clear(name, frame, camera, size);
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let mut boxes: Vec<(String, Rect)> = Vec::new();
    for ((l, b, p), label) in layout(frame, camera, size).into_iter().zip(&frame.labels) {
        assert!(
            p.shown && p.leader_to.is_none(),
            "{name} on {size}: {} moved",
            l.text
        );
        let rect = Rect {
            min: p.top_left,
            size: b.size,
        };
        let dot = project_to_canvas(view_proj, size, label.anchor).unwrap();
        let gap = rect.nearest(dot).distance(dot);
        assert!(
            (LABEL_DOT_GAP_PX - 0.01..=reach_px).contains(&gap),
            "{name} on {size}: {} {gap} px from its dot",
            l.text
        );
        for (other, r) in &boxes {
            assert!(
                !r.overlaps(&rect, 6.0),
                "{name} on {size}: {} and {other} crowd",
                l.text
            );
        }
        boxes.push((l.text, rect));
    }
}

#[test]
fn lesson_11_integrators_are_named_beside_their_dots() {
    // Figure 2 at its page camera (lessons/11-particles/lesson.js), both canvases, through the
    // throw, at the page's step and across the slider: each integrator's name (as the text
    // names it) beside its latest dot, at most 72 px off it, the three 6 px apart and off every
    // dot and path. At the page's step, over the first steps, where the three dots lie on one
    // spot, the names stack in the order of the dots: explicit Euler (above the parabola) over
    // velocity Verlet over semi-implicit Euler. Also on the 920 × 420 canvas of the page at
    // 1100 px (the page test's figure screenshots). As on the page, the figure places them for
    // the view of the frame before.
    use inbetween::figures::particles::FreeFallFigure;
    let view = [-0.3, 1.3, 0.0, 5.5, 0.0, 0.1];
    let mut failures = Vec::new();
    for dt in [0.1, 0.03, 0.05, 0.2, 0.3] {
        for k in 0..=10 {
            let t = 1.3 * k as f32 / 10.0;
            for size in CANVASES.into_iter().chain([Vec2::new(920.0, 420.0)]) {
                let mut f = FreeFallFigure::new();
                f.set_dt(dt).unwrap();
                let (frame, camera) = drawn_for_view(
                    &mut f,
                    view,
                    size,
                    |fig, out| {
                        fig.draw(out, t).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
                assert_eq!(
                    texts,
                    ["velocity Verlet", "explicit Euler", "semi-implicit Euler"]
                );
                let name = format!("11 free fall, dt {dt} s, t {t} s");
                failures.extend(failure_of(|| {
                    assert_named_beside_dots(&name, &frame, &camera, size, 72.0)
                }));
                if dt == 0.1 && t < 0.3 {
                    let middle = |text: &str| {
                        let (_, r) = label_boxes(&frame, &camera, size)
                            .into_iter()
                            .find(|(l, _)| l == text)
                            .unwrap();
                        r.min.y + 0.5 * r.size.y
                    };
                    let ys = ["explicit Euler", "velocity Verlet", "semi-implicit Euler"].map(middle);
                    failures.extend(failure_of(|| {
                        assert!(ys[0] < ys[1] && ys[1] < ys[2], "{name} on {size}: names at {ys:?}")
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_11_integrators_are_named_beside_their_dots_when_orbited() {
    // Figure 2 orbited round its page camera (the page sweep's drag turns it by −1.2 rad and
    // tilts it by 0.3 rad), both canvases, through the throw, at small and large steps: the
    // names keep beside their latest dots (at most 100 px off), 6 px apart, off every dot and
    // path, where the three paths bunch at the top of the throw. As on the page, the figure
    // places them for the view of the frame before.
    use inbetween::figures::particles::FreeFallFigure;
    let mut failures = Vec::new();
    for (yaw, pitch) in [
        (-1.216, 0.404),
        (-0.6, 0.3),
        (0.6, 0.5),
        (1.2, 0.4),
        (-1.5, 0.9),
    ] {
        let view = [-0.3, 1.3, 0.0, 5.5, yaw, pitch];
        for dt in [0.05, 0.03, 0.1, 0.24] {
            for k in 0..=13 {
                let t = 1.3 * k as f32 / 13.0;
                for size in CANVASES {
                    let mut f = FreeFallFigure::new();
                    f.set_dt(dt).unwrap();
                    let (frame, camera) = drawn_for_view(
                        &mut f,
                        view,
                        size,
                        |fig, out| {
                            fig.draw(out, t).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!("11 free fall, orbit ({yaw}, {pitch}), dt {dt} s, t {t} s");
                    failures.extend(failure_of(|| {
                        assert_named_beside_dots(&name, &frame, &camera, size, 100.0)
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_11_spring_names_keep_off_the_walls_and_masses_when_orbited() {
    // Figure 3 at its page camera (SpringFigure::view) and orbited round it (the page sweep's
    // drag, −1.2 rad and 0.3 rad, looks along the springs: the rows line up on the screen), both
    // canvases, at the default step, the caption's 0.1 s and 0.16 s (explicit Euler's mass cut
    // short at the wall): the three names are shown where the figure put them (so none sits on
    // another), keep off every dot and line, cover no wall (its corners and centre) and no mass
    // (its centre and six points of its rim), and each lies beside its own mass (its box 40 px
    // from it at most, 72 px orbited). As on the page, the figure places them for
    // the view of the frame before.
    use inbetween::draw::layout::LEADER_PX;
    use inbetween::draw::palette;
    use inbetween::figures::particles::{SpringFigure, SPRING_DRAW_MAX_M};
    const NAMES: [&str; 3] = ["explicit Euler", "semi-implicit Euler", "velocity Verlet"];
    let mut failures = Vec::new();
    for (yaw, pitch) in [
        (0.0, 1.0),
        (-1.216, 1.304),
        (1.216, 1.304),
        (-0.6, 0.6),
        (0.6, 0.4),
    ] {
        let view = [0.0, 0.0, 0.0, 8.0, yaw, pitch];
        for dt in [0.02, 0.1, 0.16] {
            for time_sec in [0.0, 0.5, 1.0, 2.5, 3.8] {
                for size in CANVASES {
                    let mut scene = SpringFigure::new();
                    scene.set_dt(dt).unwrap();
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        view,
                        size,
                        |fig, out| {
                            fig.draw(out, time_sec).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!("11 spring, orbit ({yaw}, {pitch}), dt {dt}, t {time_sec}");
                    // A mass drawn cut short (explicit Euler's, past SPRING_DRAW_MAX_M) says so
                    // in its name.
                    let cut = frame.points[0].center[0].abs() >= SPRING_DRAW_MAX_M - 1e-4;
                    let explicit = if cut { "explicit Euler (drawn cut)" } else { NAMES[0] };
                    assert!(frame.labels.iter().any(|l| l.text == explicit), "{name}");
                    // The three names and "exact".
                    let named: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| {
                            let t = &frame.labels[i].text;
                            t == "exact" || NAMES.iter().any(|n| t.starts_with(n))
                        })
                        .collect();
                    assert_eq!(named.len(), 4, "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &named, 0.0)
                    }));
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let solid: Vec<Vec2> = frame
                        .meshes
                        .iter()
                        .filter(|m| m.color.truncate() == palette::GREY)
                        .flat_map(|m| {
                            let mut points: Vec<Vec3> = (0..8)
                                .map(|c| {
                                    let s = |bit: i32| if c & bit == 0 { -1.0 } else { 1.0 };
                                    m.model.transform_point3(Vec3::new(s(1), s(2), s(4)))
                                })
                                .collect();
                            points.push(m.model.w_axis.truncate());
                            points
                        })
                        .chain(frame.points.iter().flat_map(|p| {
                            let (c, r) = (Vec3::from(p.center), p.radius.abs());
                            [
                                Vec3::ZERO,
                                Vec3::X,
                                -Vec3::X,
                                Vec3::Y,
                                -Vec3::Y,
                                Vec3::Z,
                                -Vec3::Z,
                            ]
                            .map(|d| c + d * r)
                        }))
                        .filter_map(|p| project_to_canvas(view_proj, size, p))
                        .collect();
                    assert_eq!(solid.len(), 27 + 21, "{name}: three walls and three masses");
                    let boxes: Vec<(String, Rect)> = label_boxes(&frame, &camera, size)
                        .into_iter()
                        .map(|(t, r)| (t.trim_end_matches(" (drawn cut)").to_string(), r))
                        .collect();
                    failures.extend(failure_of(|| {
                        assert_names_cover_none(&name, size, &boxes, &NAMES, &solid, "a wall or mass")
                    }));
                    // No name and not "exact" on any ball's disc (its rim's farthest projection
                    // from its centre): a name over another row's ball reads as naming it.
                    for p in &frame.points {
                        let c = project_to_canvas(view_proj, size, Vec3::from(p.center)).unwrap();
                        let rim = [Vec3::X, Vec3::Y, Vec3::Z]
                            .iter()
                            .filter_map(|&d| {
                                let q = Vec3::from(p.center) + d * p.radius.abs();
                                project_to_canvas(view_proj, size, q)
                            })
                            .fold(0.0, |r: f32, q| r.max(q.distance(c)));
                        for (t, rect) in &boxes {
                            let gap = rect.nearest(c).distance(c);
                            failures.extend(failure_of(|| {
                                assert!(gap >= rim, "{name} on {size}: {t} {gap} px from a ball's centre, inside its {rim} px disc")
                            }));
                        }
                    }
                    // Each name beside the mass it names: its box within 40 px of the mass's
                    // centre on screen at the page's view, 72 px orbited, where the rows close
                    // up round the middle one (the masses are drawn in the names' order), and
                    // 100 px for a name the page joins to its mass by a leader line (see
                    // lesson_11_spring_names_read_as_their_own_masses_when_orbited).
                    let reach = if (yaw, pitch) == (0.0, 1.0) { 40.0 } else { 72.0 };
                    for (n, p) in NAMES.iter().zip(&frame.points) {
                        let c = project_to_canvas(view_proj, size, Vec3::from(p.center)).unwrap();
                        let (_, rect) = boxes.iter().find(|(t, _)| t == n).unwrap();
                        let gap = rect.nearest(c).distance(c);
                        let reach = if gap > LEADER_PX && reach > 40.0 { 100.0 } else { reach };
                        failures.extend(failure_of(|| {
                            assert!(gap <= reach, "{name} on {size}: {n} {gap} px from its mass")
                        }));
                        // (Off its own ball's disc too: the loop over every ball above.)
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_11_sprite_names_keep_off_the_puffs_and_the_atlas_when_orbited() {
    // Figure 5 at its page camera (lessons/11-particles/lesson.js) and orbited round it (the
    // page sweep's drag turns it by −1.2 rad and tilts it by 0.3 rad: the columns line up on
    // the screen and the atlas's board turns edge on), both canvases, at 30 and 64 puffs,
    // through the puffs' life: the two columns' names and the atlas's are shown where the
    // figure put them (so none sits on another), keep off every line, and cover no puff's
    // centre and no point of the atlas's board (7 × 7 points). As on the page, the figure
    // places them for the view of the frame before.
    use inbetween::figures::particles_sprites::{SmokeFigure, COLUMN_GAP};
    use inbetween::texture::TextureId;
    const NAMES: [&str; 3] = [
        "sorted back to front",
        "unsorted (storage order)",
        "the atlas: 16 frames",
    ];
    let mut failures = Vec::new();
    for (yaw, pitch) in [(0.25, 0.15), (-0.966, 0.454), (1.466, 0.454), (-0.4, 0.6)] {
        let view = [0.2, 1.3, 0.0, 8.0, yaw, pitch];
        for puffs in [30.0, 64.0] {
            for time_sec in [0.5, 2.0, 4.37] {
                for size in CANVASES {
                    let mut scene = SmokeFigure::new();
                    scene.set_params(puffs, 4.0).unwrap();
                    let draw = |scene: &mut SmokeFigure, camera: &OrbitCamera| {
                        let mut frame = Frame::default();
                        let (eye, target) = (camera.eye(), camera.target);
                        scene
                            .draw(&mut frame, TextureId(0), eye, target, time_sec)
                            .unwrap();
                        frame
                    };
                    let frame = draw(&mut scene, &OrbitCamera::from_view(view));
                    let camera = page_camera(view, &frame, size);
                    scene.set_view(camera, size.x, size.y);
                    let frame = draw(&mut scene, &camera);
                    let camera = page_camera(view, &frame, size);
                    let name =
                        format!("11 sprites, orbit ({yaw}, {pitch}), {puffs} puffs, t {time_sec}");
                    let named: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| NAMES.contains(&&*frame.labels[i].text))
                        .collect();
                    assert_eq!(named.len(), 3, "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &named, 0.0)
                    }));
                    // The atlas stands at (−3.2, 1.0, 0.0), 0.64 m each side of its centre.
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let puffs_at = frame.sprites.iter().map(|s| Vec3::from(s.center));
                    let board = (0..49).map(|k| {
                        let s = |i: i32| (i as f32 / 3.0 - 1.0) * 0.64;
                        Vec3::new(-3.2 + s(k % 7), 1.0 + s(k / 7), 0.0)
                    });
                    let solid: Vec<Vec2> = puffs_at
                        .chain(board)
                        .filter_map(|p| project_to_canvas(view_proj, size, p))
                        .collect();
                    assert!(solid.len() >= 2 * puffs as usize, "{name}: {COLUMN_GAP}");
                    let boxes = label_boxes(&frame, &camera, size);
                    failures.extend(failure_of(|| {
                        assert_names_cover_none(&name, size, &boxes, &NAMES, &solid, "a puff or the atlas")
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_11_spring_names_read_as_their_own_masses_when_orbited() {
    // Figure 3 orbited as the page sweep's drag leaves it (a fifth of the canvas's width right
    // and 42 px down at 0.008 rad a pixel: yaw −0.0016 × width, pitch 1.0 + 0.336, which looks
    // along the springs with the rows side by side), on the 920 × 420 canvas of the sweep's
    // figure shots and both page canvases, and at the other orbits of the sweep above: a name
    // that sits by its mass (its box within LEADER_PX of it, so the page draws no leader line)
    // has its middle nearer its own mass than any other, so that it does not read as naming
    // the next row's mass; a name further off gets a leader line from its mass to its box's
    // nearest point, and that line enters no other name's box and no other mass's disc.
    use inbetween::draw::layout::LEADER_PX;
    use inbetween::figures::particles::SpringFigure;
    let mut failures = Vec::new();
    let mut views = Vec::new();
    for width in [920.0, 760.0, 650.0] {
        views.push((Vec2::new(width, 420.0), -0.0016 * width, 1.336));
        for (yaw, pitch) in [(-1.216, 1.304), (1.216, 1.304), (-0.6, 0.6), (0.6, 0.4)] {
            views.push((Vec2::new(width, 420.0), yaw, pitch));
        }
    }
    for (size, yaw, pitch) in views {
        let view = [0.0, 0.0, 0.0, 8.0, yaw, pitch];
        for dt in [0.02, 0.1, 0.16] {
            for time_sec in [0.0, 0.4, 0.5, 1.0, 2.5, 3.8] {
                let mut scene = SpringFigure::new();
                scene.set_dt(dt).unwrap();
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    view,
                    size,
                    |fig, out| {
                        fig.draw(out, time_sec).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let name = format!("11 spring, orbit ({yaw}, {pitch}), dt {dt}, t {time_sec} on {size}");
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                // Each mass's centre and disc radius on the canvas, in the names' order.
                let masses: Vec<(Vec2, f32)> = frame
                    .points
                    .iter()
                    .map(|p| {
                        let c = project_to_canvas(view_proj, size, Vec3::from(p.center)).unwrap();
                        let r = [Vec3::X, Vec3::Y, Vec3::Z]
                            .iter()
                            .filter_map(|&d| {
                                project_to_canvas(view_proj, size, Vec3::from(p.center) + d * p.radius.abs())
                            })
                            .fold(0.0, |r: f32, q| r.max(q.distance(c)));
                        (c, r)
                    })
                    .collect();
                let boxes = label_boxes(&frame, &camera, size);
                for (i, n) in ["explicit Euler", "semi-implicit Euler", "velocity Verlet"].iter().enumerate() {
                    let (_, rect) = boxes.iter().find(|(t, _)| t.starts_with(n)).unwrap();
                    let (c, _) = masses[i];
                    let near = rect.nearest(c);
                    if near.distance(c) <= LEADER_PX {
                        let middle = rect.min + 0.5 * rect.size;
                        let own = middle.distance(c);
                        for (j, &(o, _)) in masses.iter().enumerate().filter(|&(j, _)| j != i) {
                            failures.extend(failure_of(|| {
                                assert!(own < middle.distance(o), "{name}: {n}'s middle {middle} nearer mass {j} at {o} than its own at {c}")
                            }));
                        }
                    } else {
                        for (t, other) in boxes.iter().filter(|(t, _)| !t.starts_with(n)) {
                            failures.extend(failure_of(|| {
                                assert!(!inbetween::draw::segment_enters(c, near, other.min, other.max()), "{name}: {n}'s leader from {c} to {near} crosses {t:?}")
                            }));
                        }
                        for (j, &(o, r)) in masses.iter().enumerate().filter(|&(j, _)| j != i) {
                            let lo = o - r / 2f32.sqrt();
                            let hi = o + r / 2f32.sqrt();
                            failures.extend(failure_of(|| {
                                assert!(!inbetween::draw::segment_enters(c, near, lo, hi), "{name}: {n}'s leader from {c} to {near} crosses mass {j} at {o}")
                            }));
                        }
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}
