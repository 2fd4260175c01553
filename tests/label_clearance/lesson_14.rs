//! Lesson 14: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_14_drift_labels_stay_inside_the_canvas_and_apart() {
    // Figure 2 at its page camera (lessons/14-rigid-bodies/lesson.js), both canvases, at the
    // start, part-way and at the end of the run, at the page's spin and step and at the
    // sliders' largest (where the unnormalised box grows too large to draw and its label reads
    // "(not drawn)"): every label is shown where the figure put it, inside the canvas
    // with EDGE_PX to spare (the rightmost read out past the right edge), and over its box.
    use inbetween::draw::layout::EDGE_PX;
    use inbetween::figures::rigid_body::DriftFigure;
    for (spin, step_ms) in [(5.0, 10.0), (30.0, 50.0)] {
        let mut scene = DriftFigure::new();
        scene.set_drift(spin, step_ms).unwrap();
        let end = scene.duration_sec();
        for time_sec in [0.0, 0.35, 0.5 * end, end] {
            scene.advance_to(time_sec).unwrap();
            let mut frame = Frame::default();
            scene.draw(&mut frame);
            assert_eq!(frame.labels.len(), 3);
            for size in CANVASES {
                let camera = page_camera([0.0, 1.0, 0.0, 6.0, 0.0, 0.12], &frame, size);
                let name = format!("14 drift, spin {spin}, step {step_ms} ms, t {time_sec}");
                for (l, b, p) in layout(&frame, &camera, size) {
                    assert!(p.shown, "{name} on {size}: {:?} hidden", l.text);
                    assert!(
                        p.leader_to.is_none(),
                        "{name} on {size}: {:?} moved",
                        l.text
                    );
                    let max = p.top_left + b.size;
                    assert!(
                        p.top_left.cmpge(Vec2::splat(EDGE_PX)).all()
                            && max.cmple(size - EDGE_PX).all(),
                        "{name} on {size}: {:?} at {} to {max} touches the edge",
                        l.text,
                        p.top_left
                    );
                }
            }
        }
    }
}

#[test]
fn lesson_14_throw_names_l_and_omega_apart_at_their_tips() {
    // Figure 1 at the page's default camera (the figure sets none; the viewer fits it), both
    // canvases, through the flight, for spins and tilts across the sliders: L's and ω's names
    // are spelt out, each shown where the figure put it, its box within 42 px of its arrow's tip
    // (just off it unless the trail or the path is there), at least 6 px from the other's box,
    // and off the trail, the path, the shafts and the dot.
    // As on the page, the figure places them for the view of the frame before (set_view).
    use inbetween::draw::LABEL_DOT_GAP_PX;
    use inbetween::figures::rigid_body::ThrowFigure;
    let view = [0.0, 1.0, 0.0, 4.0, 0.5, 0.3];
    let mut failures = Vec::new();
    for (spin, tilt) in [
        (10.0, 20.0),
        (15.0, 50.0),
        (5.0, 80.0),
        (10.0, 5.0),
        (15.0, 80.0),
    ] {
        for k in 0..=8 {
            for size in CANVASES {
                let mut f = ThrowFigure::new();
                f.set_throw(spin, tilt).unwrap();
                f.advance_to(f.duration_sec() * k as f32 / 8.0).unwrap();
                let (frame, camera) = drawn!(&mut f, view, size);
                let name = format!("14 throw, spin {spin}, tilt {tilt}°, step {k}/8");
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let check = || {
                    assert_clear(&name, &frame, &camera, size);
                    let placed = layout(&frame, &camera, size);
                    assert_eq!(placed.len(), 2, "{name}");
                    let mut boxes = Vec::new();
                    for (l, b, p) in &placed {
                        assert!(p.shown && p.leader_to.is_none(), "{name}: {} moved", l.text);
                        let rect = Rect {
                            min: p.top_left,
                            size: b.size,
                        };
                        // The tip: the label's anchor (its offset is on screen).
                        let label = frame.labels.iter().find(|f| f.text == l.text).unwrap();
                        let tip = project_to_canvas(view_proj, size, label.anchor).unwrap();
                        let gap = rect.nearest(tip).distance(tip);
                        assert!(
                            (LABEL_DOT_GAP_PX..=42.0).contains(&gap),
                            "{name} on {size}: {} {gap} px from its tip",
                            l.text
                        );
                        boxes.push(rect);
                    }
                    assert!(
                        !boxes[0].overlaps(&boxes[1], 6.0),
                        "{name} on {size}: the names crowd: {boxes:?}"
                    );
                };
                failures.extend(failure_of(check));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_14_stack_names_its_top_box_just_above_it() {
    // Figure 5 at the page's default camera (the figure sets none; the viewer fits it), both
    // canvases, the stack and the dominoes, settled and after a push: the tracked body's name
    // sits over it, its box's bottom between 14 px above the body's topmost point on screen
    // and 2 px into it, its middle over the body.
    use inbetween::figures::rigid_body::{StackFigure, StackPreset};
    let view = [0.0, 1.0, 0.0, 4.0, 0.5, 0.3];
    for preset in [StackPreset::Stack, StackPreset::Dominoes] {
        for (push, t) in [(false, 0.0), (false, 1.0), (true, 0.5), (true, 2.0)] {
            let mut f = StackFigure::new(preset);
            if push {
                f.advance_to(0.5).unwrap();
                f.push().unwrap();
            }
            f.advance_to(t + if push { 0.5 } else { 0.0 }).unwrap();
            let mut frame = Frame::default();
            f.draw(&mut frame);
            for size in CANVASES {
                let camera = page_camera(view, &frame, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let name = format!("14 stack {preset:?}, push {push}, t {t} s");
                let placed = layout(&frame, &camera, size);
                assert_eq!(placed.len(), 1, "{name}");
                let (l, b, p) = &placed[0];
                assert!(p.shown && p.leader_to.is_none(), "{name}: moved");
                // The tracked body: the last cube the frame draws.
                let model = frame.meshes.last().unwrap().model;
                let corners: Vec<Vec2> = (0..8)
                    .map(|i| {
                        let s = Vec3::new(
                            if i & 1 == 0 { -1.0 } else { 1.0 },
                            if i & 2 == 0 { -1.0 } else { 1.0 },
                            if i & 4 == 0 { -1.0 } else { 1.0 },
                        );
                        project_to_canvas(view_proj, size, model.transform_point3(s)).unwrap()
                    })
                    .collect();
                let (bottom, middle) = (p.top_left.y + b.size.y, p.top_left.x + 0.5 * b.size.x);
                let at = format!("{name} on {size}: {:?}", l.text);
                assert_just_above(&at, bottom, middle, &corners, 14.0, "body");
            }
        }
    }
}

#[test]
fn lesson_14_impulse_names_its_arrows_beside_them_off_the_boxes() {
    // Figure 4 at the page's default camera (the figure sets none; the viewer fits it), both
    // canvases, from the hit to the end, across tilts, restitutions and heights: every name
    // (j n, v and ω before and after) is shown where the figure put it, 2 px off every line
    // and dot (the arrows, the outline of the box at the hit), within 60 px of its arrow's
    // head (j n of its shaft's middle), and off the box now and the box at the hit: a name
    // over the box or on an arrow reads as part of it. As on the page, the figure places the
    // names for the view of the frame before (set_view).
    use inbetween::draw::palette;
    use inbetween::figures::rigid_body::{ImpulseFigure, DROP_HALF};
    use inbetween::rigid_body::contact::corners;
    let view = [0.0, 1.0, 0.0, 4.0, 0.5, 0.3];
    let mut failures = Vec::new();
    for (tilt, e, height) in [(20.0, 0.5, 1.0), (36.0, 0.2, 1.6), (0.0, 0.5, 1.0), (45.0, 1.0, 2.0), (10.0, 0.0, 0.2)] {
        let mut f = ImpulseFigure::new();
        f.set_drop(tilt, e, height).unwrap();
        f.advance_to(f.duration_sec()).unwrap();
        let hit = f.impact_details().copied().expect("a hit");
        for k in 0..=6 {
            let t = hit.time_sec + 0.02 + (f.duration_sec() - hit.time_sec - 0.02) * k as f32 / 6.0;
            for size in CANVASES {
                let mut f = f.clone();
                f.advance_to(t).unwrap();
                let now = *f.body();
                let (frame, camera) = drawn!(&mut f, view, size);
                let name = format!("14 impulse, tilt {tilt}°, e {e}, {height} m, t {t:.2} s");
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let check = || {
                    let placed = layout(&frame, &camera, size);
                    let all: Vec<usize> = (0..placed.len()).collect();
                    assert!(placed.len() >= 3, "{name}: {} names", placed.len());
                    assert_shown_clear_by(&name, &frame, &camera, size, &all, 2.0);
                    // The boxes' faces, sampled: each name's box holds none of the points.
                    let mut then = now;
                    then.position = hit.centre;
                    then.orientation = hit.orientation;
                    for body in [now, then] {
                        let c = corners(&body, DROP_HALF);
                        let points: Vec<Vec2> = (0..8)
                            .flat_map(|i| (0..8).map(move |j| (i, j)))
                            .flat_map(|(i, j)| (0..=4).map(move |s| c[i].lerp(c[j], s as f32 / 4.0)))
                            .filter_map(|p| project_to_canvas(view_proj, size, p))
                            .collect();
                        for (l, b, p) in &placed {
                            let r = Rect { min: p.top_left, size: b.size };
                            assert!(
                                !points.iter().any(|q| q.cmpgt(r.min).all() && q.cmplt(r.max()).all()),
                                "{name} on {size}: {:?} at {} over a box",
                                l.text,
                                p.top_left
                            );
                        }
                    }
                    // The ω arrows keep 20 px off the line v lies on (straight down through
                    // the centre at the hit) on screen, so the two never cover each other.
                    let (Some(c), Some(down)) = (
                        project_to_canvas(view_proj, size, hit.centre),
                        project_to_canvas(view_proj, size, hit.centre - Vec3::Y),
                    ) else {
                        panic!("{name}: the centre is behind the camera")
                    };
                    let across = (down - c).normalize().perp();
                    let teal = [palette::TEAL, palette::TEAL.lerp(Vec3::ONE, 0.55)];
                    let is_teal = |s: &&inbetween::draw::StrokeSegment| {
                        teal.contains(&Vec3::from_slice(&s.color[..3]))
                    };
                    for s in frame.strokes.iter().filter(is_teal) {
                        for p in [s.a, s.b] {
                            let q = project_to_canvas(view_proj, size, Vec3::from(p)).unwrap();
                            let off = (q - c).dot(across).abs();
                            assert!(off >= 20.0, "{name} on {size}: ω {off} px from v's line");
                        }
                    }
                    // Each name near what it names (its anchor: the head, or j n's shaft).
                    for (l, b, p) in &placed {
                        let label = frame.labels.iter().find(|f| f.text == l.text).unwrap();
                        let tip = project_to_canvas(view_proj, size, label.anchor).unwrap();
                        let r = Rect { min: p.top_left, size: b.size };
                        let gap = r.nearest(tip).distance(tip);
                        assert!(gap <= 60.0, "{name} on {size}: {} {gap} px from its arrow", l.text);
                    }
                };
                failures.extend(failure_of(check));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_14_drift_names_sit_by_their_boxes_when_orbited() {
    // Figure 2 at the page's camera and orbited (yawed and tipped as a drag does), both
    // canvases, at the start, part-way and at the end, at the page's spin and step and at the
    // sliders' largest: every name is shown where the figure put it, 2 px off every line (the
    // outline of the box the unnormalised one should be), over none of the boxes, and within
    // 56 px of its own box on screen (as drawn, or the box it should be). As on the page, the figure places the names for the view
    // of the frame before (set_view).
    use inbetween::figures::rigid_body::{DriftFigure, DRIFT_HALF};
    use inbetween::rigid_body::contact::corners;
    let mut failures = Vec::new();
    for (spin, step_ms) in [(5.0, 10.0), (24.0, 39.7), (30.0, 50.0)] {
        for view in [
            [0.0, 1.0, 0.0, 6.0, 0.0, 0.12],
            [0.0, 1.0, 0.0, 6.0, 0.8, 0.5],
            [0.0, 1.0, 0.0, 6.0, -0.7, 0.9],
            [0.0, 1.0, 0.0, 6.0, -1.4, 0.46],
            [0.0, 1.0, 0.0, 6.0, 1.4, 0.46],
            [0.0, 1.0, 0.0, 6.0, -1.1, 0.3],
            [0.0, 1.0, 0.0, 6.0, -1.6, 0.6],
            [0.0, 1.0, 0.0, 6.0, -1.25, 0.4],
        ] {
            let mut scene = DriftFigure::new();
            scene.set_drift(spin, step_ms).unwrap();
            let end = scene.duration_sec();
            for time_sec in [0.0, 0.35, 3.67, 0.43 * end, end] {
                scene.advance_to(time_sec).unwrap();
                for size in CANVASES {
                    let (frame, camera) = drawn!(&mut scene, view, size);
                    let name =
                        format!("14 drift, spin {spin}, step {step_ms} ms, t {time_sec}, view {view:?}");
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let check = || {
                        assert_eq!(frame.labels.len(), 3, "{name}");
                        assert_shown_clear_by(&name, &frame, &camera, size, &[0, 1, 2], 2.0);
                        // A box's points on screen: its edges and the lines across it.
                        let on_screen = |c: &[Vec3]| -> Vec<Vec2> {
                            let mut out = Vec::new();
                            for i in 0..c.len() {
                                for j in 0..c.len() {
                                    for s in 0..=4 {
                                        let p = c[i].lerp(c[j], s as f32 / 4.0);
                                        out.extend(project_to_canvas(view_proj, size, p));
                                    }
                                }
                            }
                            out
                        };
                        // Each box at its unit quaternion (the one the unnormalised should be),
                        // and each cube drawn (the unnormalised one stretched).
                        let units: Vec<Vec<Vec2>> = (0..3)
                            .map(|k| {
                                let mut unit = scene.bodies()[k];
                                unit.orientation = unit.orientation.normalize();
                                unit.position = DriftFigure::place(k);
                                on_screen(&corners(&unit, DRIFT_HALF))
                            })
                            .collect();
                        let drawn = frame.meshes.iter().map(|m| {
                            let c: Vec<Vec3> = (0..8)
                                .map(|i| {
                                    let s = Vec3::new(
                                        if i & 1 == 0 { -1.0 } else { 1.0 },
                                        if i & 2 == 0 { -1.0 } else { 1.0 },
                                        if i & 4 == 0 { -1.0 } else { 1.0 },
                                    );
                                    m.model.transform_point3(s)
                                })
                                .collect();
                            on_screen(&c)
                        });
                        let drawn: Vec<Vec<Vec2>> = drawn.collect();
                        // The cube drawn for box k: every box's, or the outer two's.
                        let drawn_k = |k: usize| match drawn.len() {
                            3 => Some(&drawn[k]),
                            _ if k != 1 => Some(&drawn[k / 2]),
                            _ => None,
                        };
                        let boxes: Vec<Vec<Vec2>> = units.iter().chain(&drawn).cloned().collect();
                        let placed = layout(&frame, &camera, size);
                        for (k, (l, b, p)) in placed.iter().enumerate() {
                            let r = Rect { min: p.top_left, size: b.size };
                            for points in &boxes {
                                assert!(
                                    !points.iter().any(|q| q.cmpgt(r.min).all() && q.cmplt(r.max()).all()),
                                    "{name} on {size}: {:?} at {} over a box",
                                    l.text,
                                    p.top_left
                                );
                            }
                            let gap = units[k]
                                .iter()
                                .chain(drawn_k(k).into_iter().flatten())
                                .map(|q| r.nearest(*q).distance(*q))
                                .fold(f32::MAX, f32::min);
                            // The page draws a leader to the anchor from a name that ends
                            // more than LEADER_PX from it: the names sit at their anchors (at
                            // the steepest orbit the long "(not drawn)" name steps further out
                            // and gets its leader).
                            let label = frame.labels.iter().find(|f| f.text == l.text).unwrap();
                            let anchor = project_to_canvas(view_proj, size, label.anchor).unwrap();
                            let off = r.nearest(anchor).distance(anchor);
                            assert!(
                                off <= inbetween::draw::layout::LEADER_PX || view[4] < -1.5,
                                "{name} on {size}: {:?} {off} px from its anchor",
                                l.text
                            );
                            assert!(
                                gap <= 56.0,
                                "{name} on {size}: {:?} {gap} px from its box",
                                l.text
                            );
                        }
                    };
                    failures.extend(failure_of(check));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_14_racket_names_sit_by_their_rackets_when_orbited() {
    // Figure 3 at the page's camera and orbited, both canvases, at the page's spin and wobble
    // and at a spin and wobble where the explicit racket explodes, across the run: every name is
    // shown where the figure put it, 2 px off every line, over none of the rackets, and within
    // 24 px of its own racket on screen, placed as the page places it (for the view of the frame
    // before, set_view).
    use inbetween::draw::MeshId;
    use inbetween::figures::rigid_body::{RacketFigure, INTEGRATORS};
    let mut failures = Vec::new();
    for (spin, wobble) in [(6.0, 0.05), (16.0, 0.79)] {
        for view in [
            [0.0, 0.9, 0.0, 5.0, 0.0, 0.15],
            [0.0, 0.9, 0.0, 5.0, 0.8, 0.5],
            [0.0, 0.9, 0.0, 5.0, -0.7, 0.9],
            [0.0, 0.9, 0.0, 5.0, 1.4, 0.46],
        ] {
            let mut scene = RacketFigure::new();
            scene.set_spin(spin, wobble).unwrap();
            for time_sec in [0.0, 2.0, 4.4, 12.0] {
                scene.advance_to(time_sec).unwrap();
                for size in CANVASES {
                    let (frame, camera) = drawn!(&mut scene, view, size);
                    let name = format!("14 racket, spin {spin}, wobble {wobble}, t {time_sec}, view {view:?}");
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    // Each cube's corners and the lines between them, on screen.
                    let rackets: Vec<Vec<Vec2>> = frame
                        .meshes
                        .iter()
                        .filter(|m| m.mesh == MeshId::CUBE)
                        .map(|m| {
                            let mut out = Vec::new();
                            for i in 0..8 {
                                for j in 0..8 {
                                    let c = |i: usize| {
                                        let s = |b: usize| if i & b == 0 { -1.0 } else { 1.0 };
                                        m.model.transform_point3(Vec3::new(s(1), s(2), s(4)))
                                    };
                                    for s in 0..=4 {
                                        let p = c(i).lerp(c(j), s as f32 / 4.0);
                                        out.extend(project_to_canvas(view_proj, size, p));
                                    }
                                }
                            }
                            out
                        })
                        .collect();
                    let check = || {
                        assert_eq!(frame.labels.len(), 3, "{name}");
                        assert_eq!(rackets.len(), 3, "{name}");
                        assert_shown_clear_by(&name, &frame, &camera, size, &[0, 1, 2], 2.0);
                        for (k, (l, b, p)) in layout(&frame, &camera, size).iter().enumerate() {
                            assert_eq!(l.text, INTEGRATORS[k].1, "{name}");
                            let r = Rect { min: p.top_left, size: b.size };
                            let at = format!("{name} on {size}: {:?}", l.text);
                            for points in &rackets {
                                assert_names_cover_none(&at, size, &[(l.text.clone(), r)], &[&l.text], points, "a racket");
                            }
                            let gap = rackets[k]
                                .iter()
                                .map(|c| (c.clamp(r.min, r.max()) - *c).length())
                                .fold(f32::INFINITY, f32::min);
                            assert!(gap <= 24.0, "{at} {gap} px from its racket");
                        }
                    };
                    failures.extend(failure_of(std::panic::AssertUnwindSafe(check)));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_14_impulse_keeps_every_arrow_and_its_name_inside_the_canvas() {
    // Figure 4 at the page's default camera, fitted by the viewer, on the canvases the page
    // gives it at 800 x 600 (760 x 420, the panel under it) and 1600 x 1000 (650 x 420, the
    // panel beside it), from the hit to the end of the timeline, at the defaults and the
    // sliders' ends: every line (the arrows and their heads included) ends 8 px or more inside
    // the canvas, and every name is shown where the figure put it, near its arrow, 8 px or more
    // inside. The mistake: a camera that keeps only the arrows' ends in view puts a long arrow
    // (ω after, 0.9 m at the defaults' 18 rad/s) against the canvas's edge, and the layout
    // pushes its name back onto the canvas, EDGE_PX from the edge, off the side the figure chose.
    use inbetween::figures::rigid_body::ImpulseFigure;
    let view = [0.0, 1.0, 0.0, 4.0, 0.5, 0.3];
    let canvases = [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0)];
    let margin = 8.0;
    let mut failures = Vec::new();
    for tilt in [0.0, 20.0, 45.0] {
        for e in [0.0, 0.5, 1.0] {
            for height in [0.2, 1.0, 2.0] {
                let mut f = ImpulseFigure::new();
                f.set_drop(tilt, e, height).unwrap();
                f.advance_to(f.duration_sec()).unwrap();
                let hit = f.impact_details().copied().expect("a hit");
                for k in 0..=6 {
                    let t = hit.time_sec + 0.02 + (f.duration_sec() - hit.time_sec - 0.02) * k as f32 / 6.0;
                    for size in canvases {
                        let mut f = f.clone();
                        f.advance_to(t).unwrap();
                        let (frame, camera) = drawn!(&mut f, view, size);
                        let name = format!("14 impulse, tilt {tilt}°, e {e}, {height} m, t {t:.2} s on {size}");
                        let check = || {
                            let view_proj = camera.projection(size.x / size.y) * camera.view();
                            let inside = |min: Vec2, max: Vec2| {
                                min.min_element().min((size - max).min_element())
                            };
                            for s in &frame.strokes {
                                for p in [s.a, s.b] {
                                    let q = project_to_canvas(view_proj, size, Vec3::from(p))
                                        .expect("in front of the camera");
                                    let m = inside(q, q);
                                    assert!(m >= margin, "{name}: a line ends at {q}, {m} px inside");
                                }
                            }
                            for (l, b, p) in layout(&frame, &camera, size) {
                                assert!(p.shown && p.leader_to.is_none(), "{name}: {:?} moved", l.text);
                                let m = inside(p.top_left, p.top_left + b.size);
                                assert!(m >= margin, "{name}: {:?} at {}, {m} px inside", l.text, p.top_left);
                                let r = Rect { min: p.top_left, size: b.size };
                                let anchor = Vec2::new(l.x_px, l.y_px);
                                let gap = r.nearest(anchor).distance(anchor);
                                assert!(gap <= 60.0, "{name}: {:?} {gap} px from its arrow", l.text);
                            }
                        };
                        failures.extend(failure_of(check));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_14_impulse_keeps_v_before_and_after_apart_when_the_box_bounces_straight_up() {
    // Figure 4 at the page's default camera, both canvases, after a level hit (tilt 0: v after
    // points back up along v before's line) at restitutions and heights across the sliders:
    // v before's arrow (faded blue) and v after's (blue) keep 8 px or more apart on screen, so
    // neither lies on the other. The mistake: both drawn from the centre of mass, after up over
    // before's shaft. (After a tilted hit v after points down, on from where v before ends.)
    use inbetween::draw::palette;
    use inbetween::figures::rigid_body::ImpulseFigure;
    let view = [0.0, 1.0, 0.0, 4.0, 0.5, 0.3];
    let mut failures = Vec::new();
    for (tilt, e, height) in [(0.0, 0.5, 1.0), (0.0, 1.0, 2.0), (0.0, 0.2, 0.5), (0.0, 0.05, 0.2)] {
        let mut f = ImpulseFigure::new();
        f.set_drop(tilt, e, height).unwrap();
        f.advance_to(f.duration_sec()).unwrap();
        let hit = f.impact_details().copied().expect("a hit");
        f.advance_to(hit.time_sec + 0.15).unwrap();
        for size in CANVASES {
            let mut f = f.clone();
            let (frame, camera) = drawn!(&mut f, view, size);
            let name = format!("14 impulse, tilt {tilt}°, e {e}, {height} m on {size}");
            let check = || {
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let dots = |color: Vec3| -> Vec<Vec2> {
                    frame
                        .strokes
                        .iter()
                        .filter(|s| Vec3::from_slice(&s.color[..3]) == color)
                        .flat_map(|s| (0..=16).map(move |k| Vec3::from(s.a).lerp(Vec3::from(s.b), k as f32 / 16.0)))
                        .filter_map(|p| project_to_canvas(view_proj, size, p))
                        .collect()
                };
                let after = dots(palette::BLUE);
                let before = dots(palette::BLUE.lerp(Vec3::ONE, 0.55));
                assert!(!after.is_empty() && !before.is_empty(), "{name}: both v arrows drawn");
                let gap = before
                    .iter()
                    .flat_map(|p| after.iter().map(move |q| p.distance(*q)))
                    .fold(f32::MAX, f32::min);
                assert!(gap >= 8.0, "{name}: v before and v after {gap} px apart");
            };
            failures.extend(failure_of(check));
        }
    }
    assert_none_failed(&failures);
}
