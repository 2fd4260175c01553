//! Native tests that a figure's labels, placed by the shell's layout (src/draw/layout.rs) on the
//! canvas the page gives the figure at 800 × 600 and 1600 × 1000, keep off the dots (markers) and
//! wide lines (strokes) of the figure, so that no label hides what it names. Text is measured as
//! the page sets it (bold, 0.8 rem): about 7.5 px a character and 16 px tall.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Vec2, Vec3};
use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
use inbetween::draw::inset::inset_rect;
use inbetween::draw::layout::{place_avoiding, LabelBox, Placement, Rect};
use inbetween::draw::{project_labels, Frame, ScreenLabel};

/// The canvases a 3D figure gets at the two page sizes (beside or under its 270 px panel), CSS px.
const CANVASES: [Vec2; 2] = [Vec2::new(760.0, 380.0), Vec2::new(650.0, 420.0)];

/// Every label of the frame as the page lays it out: its projection, its box as measured, and
/// where the layout put it.
fn layout(
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
) -> Vec<(ScreenLabel, LabelBox, Placement)> {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let labels = project_labels(&frame.labels, view_proj, size.x, size.y);
    let boxes: Vec<LabelBox> = labels
        .iter()
        .map(|l| LabelBox {
            anchor: Vec2::new(l.x_px, l.y_px),
            size: Vec2::new(7.5 * l.text.chars().count() as f32, 16.0),
            left: l.left,
            visible: l.visible,
            priority: l.priority,
        })
        .collect();
    // As the page: with an inset, the labels keep off its square.
    let obstacles: Vec<Rect> = frame.inset.iter().map(|_| inset_rect(size)).collect();
    let placed = place_avoiding(&boxes, size, &obstacles);
    labels
        .into_iter()
        .zip(boxes)
        .zip(placed)
        .map(|((l, b), p)| (l, b, p))
        .collect()
}

/// The shown labels' boxes, as the page lays them out.
fn label_boxes(frame: &Frame, camera: &OrbitCamera, size: Vec2) -> Vec<(String, Rect)> {
    layout(frame, camera, size)
        .into_iter()
        .filter(|(_, _, p)| p.shown)
        .map(|(l, b, p)| {
            let rect = Rect {
                min: p.top_left,
                size: b.size,
            };
            (l.text, rect)
        })
        .collect()
}

/// Asserts that no shown label's box covers a marker (its whole dot) or a point of a stroke.
fn assert_clear(name: &str, frame: &Frame, camera: &OrbitCamera, size: Vec2) {
    assert_clear_of(name, frame, camera, size, |_| true);
}

/// [`assert_clear`] for the labels whose text passes `checked`, laid out among all the frame's.
fn assert_clear_of(
    name: &str,
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
    checked: impl Fn(&str) -> bool,
) {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let at = |p: [f32; 3]| project_to_canvas(view_proj, size, Vec3::from(p));
    for (text, rect) in label_boxes(frame, camera, size) {
        if !checked(&text) {
            continue;
        }
        for m in &frame.markers {
            let Some(c) = at(m.center) else { continue };
            let r = 0.5 * m.size_px.abs();
            let grown = Rect {
                min: rect.min - r,
                size: rect.size + 2.0 * r,
            };
            let inside = c.cmpge(grown.min).all() && c.cmple(grown.max()).all();
            assert!(
                !inside,
                "{name} on {size}: label {text:?} at {:?} covers a dot at {c}",
                rect.min
            );
        }
        for s in &frame.strokes {
            let (Some(a), Some(b)) = (at(s.a), at(s.b)) else {
                continue;
            };
            for k in 0..=16 {
                let p = a.lerp(b, k as f32 / 16.0);
                let inside = p.cmpgt(rect.min).all() && p.cmplt(rect.max()).all();
                assert!(
                    !inside,
                    "{name} on {size}: label {text:?} at {:?} crosses a line at {p} (colour {:?})",
                    rect.min, s.color
                );
            }
        }
    }
}

/// The camera a page's `setCamera` places, fitted to what the frame declares (as the viewer does:
/// left of the inset when the frame has one).
fn page_camera(view: [f32; 6], frame: &Frame, size: Vec2) -> OrbitCamera {
    let mut camera = OrbitCamera::from_view(view);
    if !frame.keep_in_view.is_empty() {
        let points = frame.fit_points();
        let beside = frame
            .inset
            .as_ref()
            .is_some_and(|_| camera.fit_left_of(&points, size, inset_rect(size).min.x, FIT_PAD_PX));
        if !beside {
            camera.fit(&points, size, FIT_PAD_PX);
        }
    }
    camera
}

/// Runs one case's checks and returns its assertion's message, if it failed: a sweep keeps going
/// and reports how many cases fail, with a few of them.
fn failure_of(check: impl FnOnce() + std::panic::UnwindSafe) -> Option<String> {
    std::panic::catch_unwind(check)
        .err()
        .map(|e| e.downcast_ref::<String>().cloned().unwrap_or_default())
}

/// Fails with the number of failed cases and the first twelve messages.
fn assert_none_failed(failures: &[String]) {
    assert!(
        failures.is_empty(),
        "{} failures, e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

/// A name just above what it names: its box's bottom from `gap` px above the topmost of
/// `points` (on the canvas) to 2 px into it, and its middle over them.
fn assert_just_above(at: &str, bottom: f32, middle: f32, points: &[Vec2], gap: f32, what: &str) {
    let top = points.iter().map(|c| c.y).fold(f32::MAX, f32::min);
    let (left, right) = points.iter().fold((f32::MAX, f32::MIN), |(lo, hi), c| {
        (lo.min(c.x), hi.max(c.x))
    });
    assert!(
        (top - gap..=top + 2.0).contains(&bottom),
        "{at}'s bottom at {bottom}, the {what}'s top at {top}"
    );
    assert!(
        (left..=right).contains(&middle),
        "{at}'s middle at {middle}, the {what} from {left} to {right}"
    );
}

#[test]
fn lesson_00_depth_side_view_labels_keep_off_the_bars_and_the_line() {
    // The page's defaults (lessons/00-triangles-to-pixels/lesson.js): 16 bits, 0.1 m to 1 km.
    // As on the page, the figure places its labels for the view of the frame before.
    let view = [0.0, 3.0, -20.0, 30.0, 1.2, 0.45];
    for size in CANVASES {
        let mut scene = inbetween::figures::raster::DepthPrecision::new();
        scene.set(0.1, 1000.0, 0.01, 16.0).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        scene.set_view(page_camera(view, &frame, size), size.x, size.y);
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        let camera = page_camera(view, &frame, size);
        assert_clear("00 depth", &frame, &camera, size);
    }
}

#[test]
fn lesson_02_keys_time_axis_labels_keep_off_the_curves() {
    let mut scene = inbetween::figures::curves::KeyframesScene::new();
    for tau in [0.0, 1.7, 3.6] {
        let mut frame = Frame::default();
        scene.draw(&mut frame, tau).unwrap();
        for size in [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)] {
            let camera = page_camera([0.3, 0.8, -1.3, 6.5, 0.75, 0.4], &frame, size);
            assert_clear("02 keys", &frame, &camera, size);
        }
    }
}

/// The orbits Figure 4 of lesson 09 is checked from: the page's (lessons/09-skinning/lesson.js)
/// and the page's after the page test's drag (a fifth of a 650 px canvas across, a tenth of its
/// 420 px down, at 0.008 rad a pixel).
const HUMAN_ORBITS: [[f32; 6]; 2] = [
    [0.0, 0.9, 0.0, 3.2, 1.45, 0.15],
    [
        0.0,
        0.9,
        0.0,
        3.2,
        1.45 - 0.008 * 130.0,
        0.15 + 0.008 * 42.0,
    ],
];

#[test]
fn lesson_09_human_pair_names_keep_off_the_bodies_and_the_skeletons() {
    // Both bodies side by side with the skeleton X-rayed and a heat map's joint named, in both
    // views, through the run and the walk, from both orbits: the titles and the joint's names
    // cover no vertex of either body (as skinned, on the CPU), no joint dot or bone, and no
    // other name. As on the page, the joint's names are placed for the view of the frame
    // before (set_canvas_view).
    use inbetween::draw::MeshId;
    use inbetween::figures::skinning::HumanFigure;
    let places = [Vec3::new(0.0, 0.0, 0.5), Vec3::new(0.0, 0.0, -0.5)];
    let mut failures = Vec::new();
    for clip in ["walk", "run"] {
        for view in ["whole body", "left legs"] {
            for joint in ["pelvis", "thigh.L", "chest"] {
                let mut h = HumanFigure::new();
                h.set_compare(true);
                h.set_clip(clip).unwrap();
                h.set_view(view).unwrap();
                h.set_heat_joint(joint).unwrap();
                h.set_show_skeleton(true);
                for t in [0.0, 0.21, 0.42] {
                    h.skin(t).unwrap();
                    for size in CANVASES {
                        for orbit in HUMAN_ORBITS {
                            let mut frame = Frame::default();
                            h.draw_pair(&mut frame, [MeshId(3), MeshId(4)]);
                            let camera = page_camera(orbit, &frame, size);
                            h.set_canvas_view(camera, size.x, size.y);
                            let mut frame = Frame::default();
                            h.draw_pair(&mut frame, [MeshId(3), MeshId(4)]);
                            let camera = page_camera(orbit, &frame, size);
                            let name = format!(
                                "09 pair, {clip} at {t} s, {view}, {joint}, orbit {orbit:?}"
                            );
                            let view_proj = camera.projection(size.x / size.y) * camera.view();
                            let body: Vec<Vec2> = [&h.mesh, &h.mesh_dqs]
                                .into_iter()
                                .zip(places)
                                .flat_map(|(m, place)| m.positions.iter().map(move |p| *p + place))
                                .filter_map(|p| project_to_canvas(view_proj, size, p))
                                .collect();
                            let labels = label_boxes(&frame, &camera, size);
                            failures.extend(failure_of(|| {
                                assert_eq!(labels.len(), 4, "{name} on {size}: all shown");
                                assert_clear(&name, &frame, &camera, size);
                                for (text, rect) in &labels {
                                    let on = body
                                        .iter()
                                        .find(|p| p.cmpgt(rect.min).all() && p.cmplt(rect.max()).all());
                                    assert!(on.is_none(), "{name} on {size}: {text:?} at {:?} covers a body at {on:?}", rect.min);
                                }
                            }));
                        }
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_09_cylinder_names_keep_off_the_tubes_and_each_other() {
    // Figure 1 at its defaults, at the page test's settings (bend 36°, twist −109°, falloff
    // 0.79 m, ring 8) and at a straight and a fully bent elbow, from the page's orbit and the
    // page test's drag: each elbow's name is anchored at the elbow joint and covers neither
    // tube (placed off it, the page draws a leader line); no name covers a dot or line; K₁p's
    // and K₂p's boxes (large text) stay apart. As on the page, the labels are placed for the
    // view of the frame before (set_view).
    use inbetween::draw::layout::{leader, LEADER_PX};
    use inbetween::draw::{MeshId, LABELS_APART_PX};
    use inbetween::figures::skinning::{CylinderFigure, DQS_OFFSET, LBS_OFFSET};
    let orbits = [
        [0.3, 0.7, 0.0, 5.0, 0.0, 0.2],
        [0.3, 0.7, 0.0, 5.0, -0.008 * 130.0, 0.2 + 0.008 * 42.0],
    ];
    let mut failures = Vec::new();
    for (bend, twist, falloff, ring) in [
        (90.0, 0.0, 0.15, 20),
        (36.0, -109.0, 0.79, 8),
        (0.0, 0.0, 0.15, 20),
        (180.0, 45.0, 0.05, 23),
    ] {
        let mut f = CylinderFigure::new();
        f.set_bend_deg(bend).unwrap();
        f.set_twist_deg(twist).unwrap();
        f.set_falloff(falloff).unwrap();
        f.set_probe_ring(ring).unwrap();
        let elbow = f.rig().segments[1].0;
        for size in CANVASES {
            for orbit in orbits {
                let mut frame = Frame::default();
                f.draw(&mut frame, [MeshId(1), MeshId(2)]).unwrap();
                f.set_view(page_camera(orbit, &frame, size), size.x, size.y);
                let mut frame = Frame::default();
                f.draw(&mut frame, [MeshId(1), MeshId(2)]).unwrap();
                let camera = page_camera(orbit, &frame, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let name = format!("09 cylinder, bend {bend}, twist {twist}, orbit {orbit:?}");
                let tubes: Vec<Vec2> = [(LBS_OFFSET, &f.lbs), (DQS_OFFSET, &f.dqs)]
                    .into_iter()
                    .flat_map(|(o, m)| m.positions.iter().map(move |p| o + *p))
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                let placed = layout(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    assert_clear(&name, &frame, &camera, size);
                    let elbows: Vec<_> = placed
                        .iter()
                        .filter(|(l, _, _)| l.text == "elbow")
                        .collect();
                    assert_eq!(elbows.len(), 2, "{name}");
                    for ((l, b, p), offset) in elbows.into_iter().zip([LBS_OFFSET, DQS_OFFSET]) {
                        let at = project_to_canvas(view_proj, size, offset + elbow).unwrap();
                        assert!(
                            l.dot_px.distance(at) < 0.01,
                            "{name}: anchored at the elbow"
                        );
                        assert!(p.shown, "{name} on {size}: elbow shown");
                        let rect = Rect {
                            min: p.top_left,
                            size: b.size,
                        };
                        let on = tubes
                            .iter()
                            .find(|q| q.cmpgt(rect.min).all() && q.cmplt(rect.max()).all());
                        assert!(
                            on.is_none(),
                            "{name} on {size}: elbow at {:?} covers a tube at {on:?}",
                            rect.min
                        );
                        // Further than a label's height from the joint, it gets a leader line.
                        if rect.nearest(at).distance(at) > LEADER_PX {
                            assert!(leader(rect, at, false).is_some());
                        }
                    }
                    let k: Vec<Rect> = frame
                        .labels
                        .iter()
                        .filter(|l| l.text.starts_with('K'))
                        .map(|l| l.first_place(view_proj, size).unwrap())
                        .collect();
                    if let [a, b] = k[..] {
                        assert!(
                            !a.overlaps(&b, LABELS_APART_PX - 0.5),
                            "{name} on {size}: K₁p and K₂p at {a:?} and {b:?}"
                        );
                    }
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_09_sign_circle_labels_keep_off_the_points_and_each_other() {
    // Over the whole twist slider, with the fix on and off: every label is shown where the
    // figure put it (no leader line from the page's layout), clear of every dot and line. Near
    // 0° and 360° three points meet at 1, so their labels are stacked by the figure.
    use inbetween::draw::MeshId;
    use inbetween::figures::skinning::SignFigure;
    for fix in [true, false] {
        for deg in (0..=360).step_by(5) {
            let mut scene = SignFigure::new();
            scene.set_fix(fix);
            scene.set_twist_deg(deg as f32).unwrap();
            let mut frame = Frame::default();
            scene.draw(&mut frame, MeshId(1)).unwrap();
            assert_eq!(frame.labels.len(), 6);
            let name = format!("09 sign at {deg}°, fix {fix}");
            for size in CANVASES {
                // The page's camera (lessons/09-skinning/lesson.js).
                let camera = page_camera([0.8, 1.0, 0.0, 5.5, 0.0, 0.1], &frame, size);
                for (l, _, p) in layout(&frame, &camera, size) {
                    assert!(p.shown, "{name} on {size}: {:?} hidden", l.text);
                    assert!(
                        p.leader_to.is_none(),
                        "{name} on {size}: {:?} moved off its place",
                        l.text
                    );
                }
                assert_clear(&name, &frame, &camera, size);
            }
        }
    }
}

#[test]
fn lesson_07_law_of_cosines_labels_keep_off_its_lines() {
    // Figure 1's page camera (lessons/07-inverse-kinematics/lesson.js), pole at 0° (the page's
    // start and its reset), at the home target and others above and beside the root: the
    // labels of sides a, b and d, of α and of the pole keep off the dashed lines, the circle of
    // middle joints, the bars and the dots.
    use inbetween::figures::ik::IkFigure;
    for target in [
        Vec3::new(0.55, 0.65, 0.15),
        Vec3::new(0.4, 0.8, 0.1),
        Vec3::new(0.3, 0.9, -0.3),
    ] {
        for pole in [0.0] {
            let mut scene = IkFigure::new();
            scene.set_target(target).unwrap();
            scene.set_pole_angle_deg(pole).unwrap();
            let mut frame = Frame::default();
            scene.draw(&mut frame).unwrap();
            for size in CANVASES {
                let camera = page_camera([0.25, 0.45, 0.0, 4.3, 0.1, 0.25], &frame, size);
                let name = format!("07 law of cosines, target {target}, pole {pole}°");
                assert_clear(&name, &frame, &camera, size);
            }
        }
    }
}

/// Points on the frame's boxes (`MeshId::CUBE`) as seen on the canvas: a 9 × 9 × 9 grid
/// through each.
fn cube_points(frame: &Frame, camera: &OrbitCamera, size: Vec2) -> Vec<Vec2> {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    frame
        .meshes
        .iter()
        .filter(|m| m.mesh == inbetween::draw::MeshId::CUBE)
        .flat_map(|m| {
            (0..729).map(move |i| {
                let g = Vec3::new((i % 9) as f32, (i / 9 % 9) as f32, (i / 81) as f32);
                m.model.transform_point3(g * 0.25 - 1.0)
            })
        })
        .filter_map(|p| project_to_canvas(view_proj, size, p))
        .collect()
}

/// Asserts that no shown label's box covers one of `points` (canvas pixels).
fn assert_off(name: &str, frame: &Frame, camera: &OrbitCamera, size: Vec2, points: &[Vec2]) {
    for (text, rect) in label_boxes(frame, camera, size) {
        let on = points
            .iter()
            .find(|p| p.cmpgt(rect.min).all() && p.cmplt(rect.max()).all());
        assert!(
            on.is_none(),
            "{name} on {size}: {text:?} at {:?} covers a box at {on:?}",
            rect.min
        );
    }
}

#[test]
fn lesson_01_scale_comparison_labels_keep_off_the_outlines_and_the_bodies() {
    // Figure 3 from the page's camera (lessons/01-transforms/lesson.js: from +x) and after the
    // page test's drag (a fifth of a 650 px canvas across, a tenth of 420 px down, 0.008 rad a
    // pixel), at the page's start, at the caption's two tries (a uniform scale; the elbow at
    // 0°), another stretch and the page test's settings: the titles, the corner angles and the
    // forearms' names sit off the outlines, the arcs, the skeletons' lines and dots, and the
    // bodies' boxes. As on the page, they are placed for the view of the frame before.
    use inbetween::figures::transforms::ScaleComparison;
    let mut failures = Vec::new();
    for (scale, angles) in [
        (Vec3::new(1.0, 2.0, 1.0), Vec3::new(-70.0, 0.0, 0.0)),
        (Vec3::new(2.0, 2.0, 2.0), Vec3::new(-70.0, 0.0, 0.0)),
        (Vec3::new(1.0, 2.0, 1.0), Vec3::ZERO),
        (Vec3::new(1.0, 1.5, 1.0), Vec3::new(-90.0, 0.0, 0.0)),
        (Vec3::new(2.42, 0.8, 2.42), Vec3::new(105.0, -109.0, -109.0)),
    ] {
        let mut scene = ScaleComparison::new();
        scene.set_upper_arm_scale(scale).unwrap();
        scene.set_forearm_angles_deg(angles).unwrap();
        let yaw = std::f32::consts::FRAC_PI_2;
        for view in [
            [0.0, 1.0, 0.0, 3.6, yaw, 0.12],
            [0.0, 1.0, 0.0, 3.6, yaw - 0.008 * 130.0, 0.12 + 0.008 * 42.0],
        ] {
            for size in CANVASES {
                let mut frame = Frame::default();
                scene.draw(&mut frame).unwrap();
                scene.set_view(page_camera(view, &frame, size), size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame).unwrap();
                let camera = page_camera(view, &frame, size);
                let name =
                    format!("01 scale comparison, scale {scale}, angles {angles}, view {view:?}");
                let boxes = cube_points(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    assert_clear(&name, &frame, &camera, size);
                    assert_off(&name, &frame, &camera, size, &boxes);
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_01_point_and_direction_names_keep_off_the_boxes() {
    // Figure 1 from the page's camera and after the page test's drag, at the page's start and
    // at the page test's settings (every slider at −1.21 m or −109°, the solid box R·T), over
    // the steps: p's and v's names cover neither box, no dot or line, and no other name.
    use inbetween::figures::transforms::{Order, SingleShape};
    let page = [0.5, 0.3, 0.0, 5.0, 0.6, 0.45];
    let mut failures = Vec::new();
    for (t, angles, order) in [
        (
            Vec3::new(1.0, 0.5, 0.0),
            Vec3::new(0.0, 0.0, 30.0),
            Order::RotateFirst,
        ),
        (
            Vec3::splat(-1.21),
            Vec3::splat(-109.0),
            Order::TranslateFirst,
        ),
    ] {
        let mut scene = SingleShape::new();
        scene.set_transform(t, angles).unwrap();
        scene.set_order(order);
        for stage in [0.0, 0.5, 1.0, 1.35, 2.0] {
            for view in [
                page,
                [0.5, 0.3, 0.0, 5.0, 0.6 - 0.008 * 130.0, 0.45 + 0.008 * 42.0],
            ] {
                for size in CANVASES {
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, stage).unwrap();
                    scene.set_view(page_camera(view, &frame, size), size.x, size.y);
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, stage).unwrap();
                    let camera = page_camera(view, &frame, size);
                    let name = format!("01 single shape, t {t}, stage {stage}, view {view:?}");
                    // The solid box and the ghost's corners and edges (its wireframe).
                    let mut boxes = cube_points(&frame, &camera, size);
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    boxes.extend(frame.segments_of(order.other().color()).flat_map(|(a, b)| {
                        (0..=8).filter_map(move |k| {
                            project_to_canvas(view_proj, size, a.lerp(b, k as f32 / 8.0))
                        })
                    }));
                    let pink = |text: &str| text.starts_with("p (") || text.starts_with("v (");
                    failures.extend(failure_of(|| {
                        assert_clear_of(&name, &frame, &camera, size, pink);
                        let mut only = frame.clone();
                        only.labels.retain(|l| pink(&l.text));
                        assert_off(&name, &only, &camera, size, &boxes);
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_11_spring_labels_keep_off_the_walls_springs_and_bars() {
    // Figure 3 at the page's camera (SpringFigure::view), at both canvases, for the default
    // step and the caption's 0.1 s: the three names and "exact" keep off the coils, the exact
    // bars, the rest and turning-point ticks, and the walls (the grey boxes the springs hang
    // from, checked at their eight corners and centre). At times when the exact mass is at or
    // right of the rest position: at 760 × 380 the longest name reaches about x = −0.3 m,
    // which the exact bar crosses later in each swing.
    use inbetween::draw::palette;
    use inbetween::figures::particles::SpringFigure;
    for dt in [0.02, 0.1] {
        let mut scene = SpringFigure::new();
        scene.set_dt(dt).unwrap();
        for time_sec in [0.0, 0.25, 0.5, 2.5] {
            let mut frame = Frame::default();
            scene.draw(&mut frame, time_sec).unwrap();
            for size in CANVASES {
                let camera = page_camera(scene.view(), &frame, size);
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

#[test]
fn lesson_01_order_names_keep_off_the_boxes_axes_and_paths() {
    // Figure 1 at the page's camera (lessons/01-transforms/lesson.js), both canvases, through
    // both steps of the timeline, T·R solid (the page's start): "T·R" and "R·T" keep off the
    // solid box's axes (which turn with it), the paths, the arm and the dots. They are placed
    // first (the highest priority), so the frame's other labels, left out here, never move
    // them. With R·T solid, its x axis ends near T·R's name at the end of the timeline.
    use inbetween::figures::transforms::{Order, SingleShape};
    for order in [Order::RotateFirst] {
        let mut scene = SingleShape::new();
        scene.set_order(order);
        for stage in [0.0, 0.36, 1.0, 1.5, 2.0] {
            let mut frame = Frame::default();
            scene.draw(&mut frame, stage).unwrap();
            let names: Vec<_> = frame
                .labels
                .iter()
                .filter(|l| l.priority == 3)
                .cloned()
                .collect();
            assert_eq!(names.len(), 2);
            assert!(frame.labels.iter().all(|l| l.priority <= 3));
            for size in CANVASES {
                let camera = page_camera([0.5, 0.3, 0.0, 5.0, 0.6, 0.45], &frame, size);
                let mut names_only = frame.clone();
                names_only.labels = names.clone();
                assert_clear(
                    &format!("01 orders, stage {stage}"),
                    &names_only,
                    &camera,
                    size,
                );
            }
        }
    }
}

#[test]
fn lesson_07_root_labels_keep_off_the_chains_at_every_pole_and_target() {
    // Figure 1 at its page camera, both canvases: each chain's name and α, the labels at the
    // roots, keep off every dot and line of the figure (the reach circle, the bars, side d, the
    // pole's line) at every pole angle of the slider, for targets above, beside and below the
    // roots (a low target bends the chains down past their roots), as far as the sliders go.
    // As on the page, the figure places them for the view of the frame before (set_view); a
    // failing case is collected so the message shows how many fail, not only the first.
    use inbetween::figures::ik::{IkFigure, SOLVERS};
    let mut targets = vec![Vec3::new(0.55, 0.65, 0.15)];
    for x in [-1.5, -0.8, -0.3, 0.0, 0.3, 0.8, 1.5] {
        for y in [-1.5, -0.8, -0.3, 0.0, 0.3, 1.0, 1.5] {
            for z in [-0.6, 0.0, 0.6] {
                targets.push(Vec3::new(x, y, z));
            }
        }
    }
    let mut failures = Vec::new();
    for &target in &targets {
        for pole in (-180..=180).step_by(30) {
            let mut scene = IkFigure::new();
            scene.set_target(target).unwrap();
            scene.set_pole_angle_deg(pole as f32).unwrap();
            let mut frame = Frame::default();
            scene.draw(&mut frame).unwrap();
            for size in CANVASES {
                let camera = page_camera([0.25, 0.45, 0.0, 4.3, 0.1, 0.25], &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame).unwrap();
                let camera = page_camera([0.25, 0.45, 0.0, 4.3, 0.1, 0.25], &frame, size);
                let mut roots = frame.clone();
                roots
                    .labels
                    .retain(|l| SOLVERS.contains(&l.text.as_str()) || l.text.starts_with("α"));
                let name = format!("07 roots, target {target}, pole {pole}°");
                failures.extend(failure_of(|| assert_clear(&name, &roots, &camera, size)));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_point_and_image_labels_stay_apart_where_the_point_crosses_the_near_plane() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js), both canvases,
    // through the first third of the point's path (t = 0.2 s of the 6 s timeline is s ≈ 0.07,
    // where the point crosses z_near and its dot meets its image's), for the page's point and
    // two others: "p" and "image" stay where the figure put them (no leader line), keep a few
    // pixels from each other, and cover neither dot nor the dashed ray from the eye.
    use inbetween::draw::palette;
    use inbetween::figures::raster::Frustum;
    for (x, y) in [(0.6, 0.3), (0.9, 0.2), (1.0, -0.2)] {
        let mut scene = Frustum::new();
        scene.set_offset(x, y).unwrap();
        for k in 0..=30 {
            let s = k as f32 * 0.01;
            let mut frame = Frame::default();
            scene.draw(&mut frame, s).unwrap();
            for size in CANVASES {
                let camera = page_camera([4.5, 1.2, -4.0, 17.0, 0.45, 0.45], &frame, size);
                let name = format!("00 frustum, point ({x}, {y}), s {s}");
                let mut pair = frame.clone();
                // The point's label in the frustum (the NDC box's comes later) and the image's.
                let p = pair.labels.iter().position(|l| l.text == "p").unwrap();
                let image = pair.labels.iter().position(|l| l.text == "image").unwrap();
                pair.labels = vec![pair.labels[p].clone(), pair.labels[image].clone()];
                // The ray from the eye (grey, dashed); the frustum's edges pass the point and
                // its image near the apex.
                pair.strokes
                    .retain(|s| s.color[..3] == palette::GREY.to_array() && s.dash[3] > 0.0);
                assert_clear(&name, &pair, &camera, size);
                let placed = layout(&frame, &camera, size);
                let boxes: Vec<Rect> = [p, image]
                    .map(|i| {
                        let (l, b, at) = &placed[i];
                        assert!(at.shown, "{name} on {size}: {:?} hidden", l.text);
                        assert!(
                            at.leader_to.is_none(),
                            "{name} on {size}: {:?} moved",
                            l.text
                        );
                        Rect {
                            min: at.top_left,
                            size: b.size,
                        }
                    })
                    .into();
                assert!(
                    !boxes[0].overlaps(&boxes[1], 4.0),
                    "{name} on {size}: \"p\" at {:?} and \"image\" at {:?} crowd",
                    boxes[0].min,
                    boxes[1].min
                );
            }
        }
    }
}

#[test]
fn lesson_04_key_names_sit_at_their_keys_and_off_the_paths() {
    // Figure 1 at its page camera (lessons/04-rigid-motions/lesson.js), both canvases, at the
    // keys, the page's start (t = 0.5 at 1 s of the 4 s ping-pong), a third and the end, for
    // the page's key B and a turn of 0°: "A" and "B" each end within the reach of their key's
    // axes (0.5 m) and 10 px on screen from its origin (they lay 1 m out to the side), clear
    // of every path, tick and dot and of the aeroplanes.
    use inbetween::figures::rigid::{RigidMotion, KEY_LABEL_M};
    for angle in [150.0, 0.0] {
        let mut scene = RigidMotion::new();
        scene
            .set_end(Vec3::new(0.2, 1.0, 0.3), angle, Vec3::new(1.5, 1.4, 0.3))
            .unwrap();
        for t in [0.0, 0.33, 0.5, 1.0] {
            let mut frame = Frame::default();
            scene.draw(&mut frame, t).unwrap();
            for size in CANVASES {
                let camera = page_camera([0.0, 1.0, 0.0, 6.5, 0.35, 0.4], &frame, size);
                let name = format!("04 keys, angle {angle}°, t {t}");
                let mut keys = frame.clone();
                keys.labels.retain(|l| l.text == "A" || l.text == "B");
                assert_eq!(keys.labels.len(), 2);
                assert_clear(&name, &keys, &camera, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                for (text, rect) in label_boxes(&keys, &camera, size) {
                    // The key's origin, KEY_LABEL_M below the name's anchor.
                    let anchor = keys.labels.iter().find(|l| l.text == text).unwrap().anchor;
                    let key = anchor - Vec3::Y * KEY_LABEL_M;
                    let origin = project_to_canvas(view_proj, size, key).unwrap();
                    let gap = rect.nearest(origin).distance(origin);
                    // The key's axes are 0.5 m long; the name ends no more than 10 px past
                    // their tips' reach.
                    let axis = project_to_canvas(view_proj, size, key + Vec3::Y * 0.5)
                        .unwrap()
                        .distance(origin);
                    assert!(
                        gap <= axis + 10.0,
                        "{name} on {size}: {text:?} {gap} px from its key (axes {axis} px)"
                    );
                    // Nor over the aeroplanes' parts (boxes: their corners and centres).
                    for m in &frame.meshes {
                        for c in 0..9 {
                            let s = |bit: i32| if c & bit == 0 { -1.0 } else { 1.0 };
                            let local = if c == 8 {
                                Vec3::ZERO
                            } else {
                                Vec3::new(s(1), s(2), s(4))
                            };
                            let Some(p) =
                                project_to_canvas(view_proj, size, m.model.transform_point3(local))
                            else {
                                continue;
                            };
                            assert!(
                                !(p.cmpgt(rect.min).all() && p.cmplt(rect.max()).all()),
                                "{name} on {size}: {text:?} covers a plane's part at {p}"
                            );
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn lesson_04_thirds_names_sit_at_their_aeroplanes_and_off_the_paths() {
    // Figure 1 with "a third, three times" on, at its page camera (lessons/04-rigid-motions/
    // lesson.js) and orbited round it, both canvases, for the page's key B, a turn of 90° and one
    // of 0° (where the two methods' thirds coincide), all three methods shown and each of the two
    // with thirds alone, at the keys and half-way: each "k/3" (the screw's third lands on B,
    // which "B" names) is shown where the figure put it, keeps 2 px off every dot, tick and line
    // (the paths, the axes, the screw axis), covers no aeroplane's part (its boxes' corners,
    // edge and face middles and centres), and ends within three label heights (48 px) of its
    // own aeroplane (the method's first third applied k times to A). As on the page, the figure
    // places them for the view of the frame before.
    use inbetween::figures::palette;
    use inbetween::figures::rigid::{Method, RigidMotion};
    let mut failures = Vec::new();
    for (angle, show) in [(150.0, 0), (150.0, 1), (150.0, 3), (90.0, 0), (0.0, 0)] {
        for t in [0.0, 0.5, 1.0] {
            for (yaw, pitch) in [
                (0.35, 0.4),
                (0.0, 0.2),
                (1.0, 0.4),
                (-0.5, 0.6),
                (0.35, 1.1),
                (2.5, 0.3),
            ] {
                for size in CANVASES {
                    let mut scene = RigidMotion::new();
                    scene
                        .set_end(Vec3::new(0.2, 1.0, 0.3), angle, Vec3::new(1.5, 1.4, 0.3))
                        .unwrap();
                    scene.set_show(show).unwrap();
                    scene.set_thirds(true);
                    let view = [0.0, 1.0, 0.0, 6.5, yaw, pitch];
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, t).unwrap();
                    let camera = page_camera(view, &frame, size);
                    scene.set_view(camera, size.x, size.y);
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, t).unwrap();
                    let camera = page_camera(view, &frame, size);
                    let name = format!(
                        "04 thirds, angle {angle}°, show {show}, t {t}, orbit ({yaw}, {pitch})"
                    );
                    // The screw's 3/3 is B, which "B" names.
                    let thirds: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| frame.labels[i].text.ends_with("/3"))
                        .collect();
                    assert_eq!(thirds.len(), [5, 3, 0, 2][show as usize], "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &thirds, 2.0)
                    }));
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let at = |p: Vec3| project_to_canvas(view_proj, size, p);
                    // Each aeroplane part's points: a box's corners, edge and face middles and
                    // centre.
                    let points = |m: &inbetween::draw::MeshDraw| -> Vec<Vec2> {
                        (0..27)
                            .filter_map(|i| {
                                let c = |k: i32| (k % 3 - 1) as f32;
                                at(m.model
                                    .transform_point3(Vec3::new(c(i), c(i / 3), c(i / 9))))
                            })
                            .collect()
                    };
                    let parts: Vec<Vec2> = frame.meshes.iter().flat_map(points).collect();
                    let placed = layout(&frame, &camera, size);
                    let a = scene.motion(Method::LerpSlerp, 0.0);
                    for &i in &thirds {
                        let label = &frame.labels[i];
                        let (_, b, p) = &placed[i];
                        let rect = Rect {
                            min: p.top_left,
                            size: b.size,
                        };
                        let method = if label.color == palette::Z_AXIS {
                            Method::Screw
                        } else {
                            Method::LerpSlerp
                        };
                        let step = scene.motion(method, 1.0 / 3.0) * a.conjugate();
                        let k: usize = label.text[..1].parse().unwrap();
                        // The gap to its aeroplane: to the points of the four boxes from the one
                        // centred there.
                        let gap = || {
                            let centre = (0..k).fold(a, |f, _| step * f).translation();
                            let first = frame
                                .meshes
                                .iter()
                                .position(|m| m.model.w_axis.truncate().distance(centre) < 1e-4)
                                .unwrap();
                            frame.meshes[first..first + 4]
                                .iter()
                                .flat_map(points)
                                .map(|q| rect.nearest(q).distance(q))
                                .fold(f32::MAX, f32::min)
                        };
                        let text = &label.text;
                        failures.extend(failure_of(|| {
                            let own = gap();
                            assert!(
                                own <= 48.0,
                                "{name} on {size}: {text:?} {own} px from its aeroplane"
                            );
                            for q in &parts {
                                assert!(
                                    !(q.cmpgt(rect.min).all() && q.cmplt(rect.max()).all()),
                                    "{name} on {size}: {text:?} at {:?} covers an aeroplane's part at {q}",
                                    rect.min
                                );
                            }
                        }));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_14_drift_labels_stay_inside_the_canvas_and_apart() {
    // Figure 2 at its page camera (lessons/14-rigid-bodies/lesson.js), both canvases, at the
    // start, part-way and at the end of the run, at the page's spin and step and at the
    // sliders' largest (where the unnormalised box grows too large to draw and its label reads
    // "too large to draw"): every label is shown where the figure put it, inside the canvas
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
fn lesson_00_light_label_sits_on_its_lamp() {
    // Figure 5 at its page camera (lessons/00-triangles-to-pixels/lesson.js), both canvases,
    // the page's light and two others: "light" is shown beside the lamp's dot (its box within
    // 12 px of the dot's edge; 0.25 m up left a 20 px gap), covering no dot or line.
    use inbetween::draw::MeshId;
    use inbetween::figures::raster::Shading;
    for (azimuth, elevation) in [(40.0, 35.0), (-60.0, 10.0), (120.0, 70.0)] {
        let mut scene = Shading::new();
        scene.set_light_deg(azimuth, elevation).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame, MeshId(1));
        for size in CANVASES {
            let camera = page_camera([0.0, 1.5, 0.0, 7.5, -0.5, 0.55], &frame, size);
            let name = format!("00 shading, light at {azimuth}°, {elevation}°");
            let mut light = frame.clone();
            light.labels.retain(|l| l.text == "light");
            assert_clear(&name, &light, &camera, size);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let lamp = frame.markers.iter().find(|m| m.size_px == 16.0).unwrap();
            let dot = project_to_canvas(view_proj, size, Vec3::from(lamp.center)).unwrap();
            let (_, rect) = label_boxes(&light, &camera, size).pop().unwrap();
            let gap = rect.nearest(dot).distance(dot) - 8.0;
            assert!(
                gap <= 12.0,
                "{name} on {size}: \"light\" {gap} px from its lamp"
            );
        }
    }
}

#[test]
fn lesson_07_hinge_figure_labels_keep_off_the_hinges_and_their_plane() {
    // Figure 3 at its page camera (from the front right, lessons/07-inverse-kinematics/
    // lesson.js), both canvases, over its controls: 2, 3 and 8 segments, each kind of joint
    // limit, targets above, beside and below the roots within the chains' reach in the
    // hinges' plane, and off that plane on either side as far as the z slider goes. The
    // targets' names, the misses' lengths, side d, α and the chains' names keep off every dot
    // and line (the grey squares of the hinges' plane, the hinges' arcs, the cones' rims, the
    // dashed drops and misses) and off the inset. As on the page, the figure places them for
    // the view of the frame before (set_view). At the page's start (x, y = 0.55, 0.65) with z
    // anywhere on its slider every case passes; over the sweep at most 1 % of the cases may
    // fail, where the two-joint chain's triangle, circle and pole crowd its root or a long miss
    // crosses a neighbouring chain and no place near the label's point is clear. Targets far
    // past the reach are left out: their misses cross the whole figure.
    use inbetween::figures::ik::{IkFigure, SOLVERS};
    let mut targets: Vec<Vec3> = [-0.8, -0.3, 0.0, 0.15, 0.4, 0.8]
        .map(|z| Vec3::new(0.55, 0.65, z))
        .to_vec();
    let start = targets.len();
    for x in [-1.0, -0.6, -0.3, 0.0, 0.3, 0.55, 1.0] {
        for y in [-1.0, -0.5, 0.0, 0.3, 0.65, 1.0] {
            for z in [-0.8, -0.3, 0.15, 0.8] {
                if glam::Vec2::new(x, y).length() <= 1.0 {
                    targets.push(Vec3::new(x, y, z));
                }
            }
        }
    }
    let placed = |text: &str| {
        SOLVERS.contains(&text)
            || text.ends_with(" target")
            || text.ends_with(" mm short")
            || text.starts_with("d = ")
            || text.starts_with("α")
    };
    let mut failures = Vec::new();
    let mut at_start = Vec::new();
    let mut cases = 0;
    for segments in [2.0, 3.0, 8.0] {
        for limits in ["hinges (bend one way)", "cones (40°)", "none"] {
            for (i, &target) in targets.iter().enumerate() {
                let mut scene = IkFigure::new();
                scene.set_segments(segments).unwrap();
                scene.set_limits(limits).unwrap();
                scene.set_target(target).unwrap();
                let mut frame = Frame::default();
                scene.draw(&mut frame).unwrap();
                for size in CANVASES {
                    let view = [0.25, 0.45, 0.0, 4.3, 0.5, 0.3];
                    let camera = page_camera(view, &frame, size);
                    scene.set_view(camera, size.x, size.y);
                    let mut frame = Frame::default();
                    scene.draw(&mut frame).unwrap();
                    let camera = page_camera(view, &frame, size);
                    cases += 1;
                    let name = format!("07 Fig 3, {segments} segments, {limits}, target {target}");
                    if let Some(message) =
                        failure_of(|| assert_clear_of(&name, &frame, &camera, size, placed))
                    {
                        if i < start {
                            at_start.push(message.clone());
                        }
                        failures.push(message);
                    }
                }
            }
        }
    }
    assert!(
        at_start.is_empty(),
        "at the start:\n{}",
        at_start.join("\n")
    );
    assert!(
        failures.len() * 100 <= cases,
        "{} of {cases} cases fail (at most 1 % may), e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

#[test]
fn lesson_07_side_d_label_sits_beside_its_line() {
    // Figures 1 and 3 at their page cameras, both canvases, two segments, Figure 3 with each
    // kind of joint limit: side d's label ("d = 0.865 m", or "d" alone where the full text fits
    // nowhere beside the line; the note gives the length) sits beside the grey dashed line from
    // the two-joint chain's root to its target, its box within 16 px of that segment at the
    // page's start and within 24 px (beside it, or past the target on its continuation) in at
    // least 94 % of the cases over the targets of Figure 3's sweep: where the two-joint chain's
    // circle, pole and labels crowd the line on both sides it goes further. As on the page, the figure
    // places it for the view of the frame before (set_view). Clear of the other dots and lines
    // it must be too: the two tests above check that.
    use inbetween::figures::ik::{IkFigure, ROOTS_X};
    let root = Vec3::new(ROOTS_X[0], 0.0, 0.0);
    let start = Vec3::new(0.55, 0.65, 0.15);
    let mut targets = vec![start];
    for x in [-1.0, -0.6, -0.3, 0.0, 0.3, 0.55, 1.0] {
        for y in [-1.0, -0.5, 0.0, 0.3, 0.65, 1.0] {
            for z in [-0.8, -0.3, 0.15, 0.8] {
                if glam::Vec2::new(x, y).length() <= 1.0 {
                    targets.push(Vec3::new(x, y, z));
                }
            }
        }
    }
    let figures = [
        ("Fig 1", [0.25, 0.45, 0.0, 4.3, 0.1, 0.25], "none"),
        (
            "Fig 3",
            [0.25, 0.45, 0.0, 4.3, 0.5, 0.3],
            "hinges (bend one way)",
        ),
        ("Fig 3", [0.25, 0.45, 0.0, 4.3, 0.5, 0.3], "cones (40°)"),
        ("Fig 3", [0.25, 0.45, 0.0, 4.3, 0.5, 0.3], "none"),
    ];
    let (mut cases, mut far, mut at_start) = (0, Vec::new(), Vec::new());
    for (figure, view, limits) in figures {
        for &target in &targets {
            let mut scene = IkFigure::new();
            scene.set_limits(limits).unwrap();
            scene.set_target(target).unwrap();
            let mut frame = Frame::default();
            scene.draw(&mut frame).unwrap();
            for size in CANVASES {
                let camera = page_camera(view, &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame).unwrap();
                let camera = page_camera(view, &frame, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                let (r, g) = (at(root), at(root + target));
                let boxes: Vec<Rect> = label_boxes(&frame, &camera, size)
                    .into_iter()
                    .filter(|(text, _)| text == "d" || text.starts_with("d = "))
                    .map(|(_, rect)| rect)
                    .collect();
                let name = format!("07 {figure}, {limits}, target {target} on {size}");
                assert_eq!(boxes.len(), 1, "{name}: side d's label");
                let gap = (0..=64)
                    .map(|k| {
                        let p = r.lerp(g, k as f32 / 64.0);
                        boxes[0].nearest(p).distance(p)
                    })
                    .fold(f32::MAX, f32::min);
                cases += 1;
                if target == start && gap > 16.0 {
                    at_start.push(format!("{name}: {gap} px from its line"));
                }
                if gap > 24.0 {
                    far.push(format!("{name}: {gap} px from its line"));
                }
            }
        }
    }
    assert_none_failed(&at_start);
    assert!(
        far.len() * 100 <= 6 * cases,
        "{} of {cases} cases have side d's label over 24 px from its line (at most 6 % may), \
         e.g.\n{}",
        far.len(),
        far[..far.len().min(12)].join("\n")
    );
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
                let mut frame = Frame::default();
                f.draw(&mut frame);
                let camera = page_camera(view, &frame, size);
                f.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                f.draw(&mut frame);
                let camera = page_camera(view, &frame, size);
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
    // names it) beside its latest dot, at most 60 px off it, the three 6 px apart and off every
    // dot and path. As on the page, the figure places them for the view of the frame before.
    use inbetween::figures::particles::FreeFallFigure;
    let view = [-0.3, 1.3, 0.0, 5.5, 0.0, 0.1];
    let mut failures = Vec::new();
    for dt in [0.1, 0.03, 0.05, 0.2, 0.3] {
        for k in 0..=10 {
            let t = 1.3 * k as f32 / 10.0;
            for size in CANVASES {
                let mut f = FreeFallFigure::new();
                f.set_dt(dt).unwrap();
                let mut frame = Frame::default();
                f.draw(&mut frame, t).unwrap();
                let camera = page_camera(view, &frame, size);
                f.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                f.draw(&mut frame, t).unwrap();
                let camera = page_camera(view, &frame, size);
                let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
                assert_eq!(
                    texts,
                    ["explicit Euler", "semi-implicit Euler", "velocity Verlet"]
                );
                let name = format!("11 free fall, dt {dt} s, t {t} s");
                failures.extend(failure_of(|| {
                    assert_named_beside_dots(&name, &frame, &camera, size, 60.0)
                }));
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
                    let mut frame = Frame::default();
                    f.draw(&mut frame, t).unwrap();
                    let camera = page_camera(view, &frame, size);
                    f.set_view(camera, size.x, size.y);
                    let mut frame = Frame::default();
                    f.draw(&mut frame, t).unwrap();
                    let camera = page_camera(view, &frame, size);
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
    // another), keep off every dot and line, and cover no wall (its corners and centre) and no
    // mass (its centre and six points of its rim). As on the page, the figure places them for
    // the view of the frame before.
    use inbetween::draw::palette;
    use inbetween::figures::particles::SpringFigure;
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
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, time_sec).unwrap();
                    let camera = page_camera(view, &frame, size);
                    scene.set_view(camera, size.x, size.y);
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, time_sec).unwrap();
                    let camera = page_camera(view, &frame, size);
                    let name = format!("11 spring, orbit ({yaw}, {pitch}), dt {dt}, t {time_sec}");
                    let named: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| NAMES.contains(&&*frame.labels[i].text))
                        .collect();
                    assert_eq!(named.len(), 3, "{name}");
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
                    let boxes = label_boxes(&frame, &camera, size);
                    failures.extend(failure_of(|| {
                        for (text, rect) in boxes.iter().filter(|(t, _)| NAMES.contains(&&**t)) {
                            for c in &solid {
                                assert!(
                                    !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                                    "{name} on {size}: {text:?} at {:?} covers a wall or mass at {c}",
                                    rect.min
                                );
                            }
                        }
                    }));
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
                        for (text, rect) in boxes.iter().filter(|(t, _)| NAMES.contains(&&**t)) {
                            for c in &solid {
                                assert!(
                                    !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                                    "{name} on {size}: {text:?} at {:?} covers a puff or the atlas at {c}",
                                    rect.min
                                );
                            }
                        }
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_03_rodrigues_terms_sit_beside_their_arrows() {
    // Figure 4 at its page camera (lessons/03-rotations/lesson.js), both canvases, through the
    // sweep, at the page's axis, angle and v and others across the sliders: each term's label
    // (v cos θ, (n × v) sin θ, n (n·v)(1 − cos θ)) is shown where the figure put it, at most
    // 70 px from a point of its arrow, and covers no arrow, circle or dot (the terms run tip to
    // tail beside v and v′). As on the page, the
    // figure places them for the view of the frame before (set_view).
    use inbetween::figures::rotations::Rodrigues;
    let view = [0.0, 0.3, 0.0, 4.2, 0.5, 0.35];
    let term = |text: &str| text.contains("θ") && !text.starts_with("v′");
    let mut failures = Vec::new();
    let mut cases = 0;
    let settings = [
        (Vec3::new(0.3, 1.0, 0.2), 120.0, Vec3::new(1.2, 0.4, 0.3)),
        (Vec3::new(0.3, 1.0, 0.2), 60.0, Vec3::new(1.2, 0.4, 0.3)),
        (Vec3::new(0.3, 1.0, 0.2), -200.0, Vec3::new(1.2, 0.4, 0.3)),
        (Vec3::new(0.0, 1.0, 0.0), 90.0, Vec3::new(1.0, 1.0, 0.0)),
        (Vec3::new(1.0, 0.2, -0.3), 150.0, Vec3::new(0.5, 1.5, 0.8)),
        (Vec3::new(0.3, 1.0, 0.2), 300.0, Vec3::new(-1.5, 0.2, 1.0)),
    ];
    for (n, angle, v) in settings {
        for k in 1..=8 {
            let s = k as f32 / 8.0;
            for size in CANVASES {
                let mut f = Rodrigues::new();
                f.set_axis_angle(n, angle).unwrap();
                f.set_vector(v).unwrap();
                let mut frame = Frame::default();
                f.draw(&mut frame, s).unwrap();
                let camera = page_camera(view, &frame, size);
                f.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                f.draw(&mut frame, s).unwrap();
                let camera = page_camera(view, &frame, size);
                cases += 1;
                let name = format!("03 Rodrigues, n {n}, θ {angle}°, v {v}, s {s}");
                let check = || {
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    for ((l, b, p), label) in
                        layout(&frame, &camera, size).into_iter().zip(&frame.labels)
                    {
                        if term(&l.text) {
                            assert!(
                                p.shown && p.leader_to.is_none(),
                                "{name} on {size}: {} moved",
                                l.text
                            );
                            // Its anchor is the point of the arrow it sits beside.
                            let at = project_to_canvas(view_proj, size, label.anchor).unwrap();
                            let rect = Rect {
                                min: p.top_left,
                                size: b.size,
                            };
                            let gap = rect.nearest(at).distance(at);
                            assert!(
                                gap <= 70.0,
                                "{name} on {size}: {} {gap} px off its arrow",
                                l.text
                            );
                        }
                    }
                    assert_clear_of(&name, &frame, &camera, size, term);
                };
                failures.extend(failure_of(check));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {cases} cases fail, e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

#[test]
fn lesson_03_rodrigues_names_keep_apart_with_v_along_the_axis() {
    // Figure 4 at its page camera, both canvases, through the sweep: at the page's settings,
    // and with v along the axis n (either way, short and long), where n, v, v′ and the box
    // meet near the origin on the screen. The names n, v, "v′ = R v" and "turned by q" are
    // shown where the figure put them (so none sits on another), keep off every line and dot,
    // and cover no corner of the box. As on the page, the figure places them for the view of the
    // frame before.
    use glam::{Mat4, Quat};
    use inbetween::figures::rotations::{Rodrigues, QUAT_BOX_AT};
    const NAMES: [&str; 4] = ["n", "v", "v′ = R v", "turned by q"];
    let view = [0.0, 0.3, 0.0, 4.2, 0.5, 0.35];
    let mut failures = Vec::new();
    let settings = [
        (Vec3::new(0.3, 1.0, 0.2), 120.0, Vec3::new(1.2, 0.4, 0.3)),
        (Vec3::splat(-0.6), -217.0, Vec3::splat(-1.21)),
        (Vec3::splat(0.6), 90.0, Vec3::splat(0.7)),
        (
            Vec3::new(0.3, 1.0, 0.2),
            120.0,
            Vec3::new(0.3, 1.0, 0.2) * 1.5,
        ),
        (
            Vec3::new(0.3, 1.0, 0.2),
            60.0,
            Vec3::new(0.3, 1.0, 0.2) * -0.8,
        ),
    ];
    for (n, angle, v) in settings {
        for k in [1, 4, 8] {
            let s = k as f32 / 8.0;
            for size in CANVASES {
                let mut f = Rodrigues::new();
                f.set_axis_angle(n, angle).unwrap();
                f.set_vector(v).unwrap();
                let mut frame = Frame::default();
                f.draw(&mut frame, s).unwrap();
                let camera = page_camera(view, &frame, size);
                f.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                f.draw(&mut frame, s).unwrap();
                let camera = page_camera(view, &frame, size);
                let name = format!("03 Rodrigues names, n {n}, θ {angle}°, v {v}, s {s}");
                let named: Vec<usize> = (0..frame.labels.len())
                    .filter(|&i| NAMES.contains(&&*frame.labels[i].text))
                    .collect();
                assert_eq!(named.len(), 4, "{name}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &named, 0.0)
                }));
                // The box, turned by the quaternion of the rotation swept so far.
                let q = Quat::from_axis_angle(n.normalize(), s * angle.to_radians());
                let place = Mat4::from_translation(QUAT_BOX_AT) * Mat4::from_quat(q);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let corners: Vec<Vec2> = (0..8)
                    .map(|c| {
                        let s = |bit: i32| if c & bit == 0 { -1.0 } else { 1.0 };
                        place.transform_point3(Vec3::new(0.22 * s(1), 0.12 * s(2), 0.08 * s(4)))
                    })
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                let boxes = label_boxes(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    for (text, rect) in boxes.iter().filter(|(t, _)| NAMES.contains(&&**t)) {
                        for c in &corners {
                            assert!(
                                !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                                "{name} on {size}: {text:?} at {:?} covers the box at {c}",
                                rect.min
                            );
                        }
                    }
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_03_circle_key_names_keep_off_the_dots_when_orbited() {
    // Figure 2 at its page camera (lessons/03-rotations/lesson.js) and orbited round it (the
    // page sweep's drag turns it by −1.2 rad and tilts it by 0.3 rad), both canvases, at the
    // default keys and at 170° and −170° about x (a and −b 10° apart), on either arc, at t = 0,
    // where slerp's and nlerp's dots sit on a, and across the timeline: the names a, −a, b and
    // −b are shown where the figure put them (so none sits on another) and keep off every dot
    // and line. As on the page, the figure places them for the view of the frame before.
    use inbetween::figures::rotations::Interpolation;
    const NAMES: [&str; 4] = ["a", "−a", "b", "−b"];
    let mut failures = Vec::new();
    for (yaw, pitch) in [(0.0, 0.0), (-1.216, 0.304), (1.216, 0.304), (-0.6, 0.6)] {
        let view = [0.0, 1.3, 0.0, 5.0, yaw, pitch];
        for (across, long) in [(false, false), (false, true), (true, false), (true, true)] {
            for t in [0.0, 0.02, 0.3, 0.5, 1.0] {
                for size in CANVASES {
                    let mut scene = Interpolation::new();
                    if across {
                        scene
                            .set_keys_euler_deg(
                                Vec3::new(170.0, 0.0, 0.0),
                                Vec3::new(-170.0, 0.0, 0.0),
                            )
                            .unwrap();
                    }
                    scene.set_long_arc(long);
                    let mut frame = Frame::default();
                    scene.draw_circle(&mut frame, t).unwrap();
                    let camera = page_camera(view, &frame, size);
                    scene.set_circle_view(camera, size.x, size.y);
                    let mut frame = Frame::default();
                    scene.draw_circle(&mut frame, t).unwrap();
                    let camera = page_camera(view, &frame, size);
                    let name = format!(
                        "03 circle, orbit ({yaw}, {pitch}), across {across}, long {long}, t {t}"
                    );
                    let named: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| NAMES.contains(&&*frame.labels[i].text))
                        .collect();
                    assert_eq!(named.len(), 4, "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &named, 0.0)
                    }));
                }
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
fn lesson_13_drape_name_sits_on_the_cloth() {
    // Figure 3 at its page camera (lessons/13-cloth/lesson.js), both canvases, each method, as
    // the cloth falls and after it has draped: the method's name sits just above the cloth's
    // topmost point on screen (its box's bottom between 12 px above it and 2 px into it), over
    // that point. As on the page, the figure places it for the view of the frame before.
    use inbetween::draw::MeshId;
    use inbetween::figures::cloth::{ClothFigure, Preset};
    let view = [0.5, 0.6, 0.0, 5.0, 0.45, 0.5];
    for method in ["mass-spring", "XPBD"] {
        for size in CANVASES {
            let mut f = ClothFigure::new(Preset::Drape);
            f.set_method(method).unwrap();
            let meshes = [MeshId(10)];
            let mut frame = Frame::default();
            f.draw(&mut frame, &meshes, 0.0).unwrap();
            let camera = page_camera(view, &frame, size);
            f.set_view(camera, size.x, size.y);
            for t in [0.0, 0.3, 0.8, 2.0] {
                let mut frame = Frame::default();
                f.draw(&mut frame, &meshes, t).unwrap();
                let camera = page_camera(view, &frame, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let name = format!("13 drape, {method}, t {t} s");
                let placed = layout(&frame, &camera, size);
                let (l, b, p) = placed
                    .iter()
                    .find(|(l, _, _)| l.text == method)
                    .unwrap_or_else(|| panic!("{name}: no name"));
                assert!(p.shown && p.leader_to.is_none(), "{name}: moved");
                let tops: Vec<Vec2> = f
                    .positions(0)
                    .iter()
                    .filter_map(|q| project_to_canvas(view_proj, size, *q))
                    .collect();
                let (bottom, middle) = (p.top_left.y + b.size.y, p.top_left.x + 0.5 * b.size.x);
                let at = format!("{name} on {size}: {:?}", l.text);
                assert_just_above(&at, bottom, middle, &tops, 12.0, "cloth");
            }
        }
    }
}

/// Asserts that the labels of `frame` at `indices` are shown where the figure put them (no
/// leader line) and keep `margin_px` off every marker's dot and every stroke's edge: a label
/// that touches a line reads as part of it.
fn assert_shown_clear_by(
    name: &str,
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
    indices: &[usize],
    margin_px: f32,
) {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let at = |p: [f32; 3]| project_to_canvas(view_proj, size, Vec3::from(p));
    let placed = layout(frame, camera, size);
    for &i in indices {
        let (l, b, p) = &placed[i];
        assert!(
            p.shown && p.leader_to.is_none(),
            "{name} on {size}: {:?} moved",
            l.text
        );
        let grown = |r: f32| Rect {
            min: p.top_left - (r + margin_px),
            size: b.size + 2.0 * (r + margin_px),
        };
        for m in &frame.markers {
            let Some(c) = at(m.center) else { continue };
            let rect = grown(0.5 * m.size_px.abs());
            assert!(
                !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                "{name} on {size}: {:?} at {:?} within {margin_px} px of a dot at {c}",
                l.text,
                p.top_left
            );
        }
        for s in &frame.strokes {
            let (Some(a), Some(e)) = (at(s.a), at(s.b)) else {
                continue;
            };
            let rect = grown(0.5 * s.width_px);
            for k in 0..=32 {
                let q = a.lerp(e, k as f32 / 32.0);
                assert!(
                    !(q.cmpgt(rect.min).all() && q.cmplt(rect.max()).all()),
                    "{name} on {size}: {:?} at {:?} within {margin_px} px of a line at {q} (colour {:?})",
                    l.text,
                    p.top_left,
                    s.color
                );
            }
        }
    }
}

#[test]
fn lesson_00_ndc_box_labels_keep_off_its_lines() {
    // Figure 2's NDC box at its page camera (lessons/00-triangles-to-pixels/lesson.js), both
    // canvases, along the point's path, for the page's point and two others: "depth 0",
    // "depth 1", "NDC (wgpu)" and the box's "p" stay where the figure put them and keep 2 px
    // off every line and dot (three lines meet at each corner the depth labels name, and the
    // point's dot moves among them). As on the page, the figure places them for the view of
    // the frame before.
    use inbetween::figures::raster::Frustum;
    let mut failures = Vec::new();
    for (x, y) in [(0.6, 0.3), (0.9, 0.2), (-1.0, -0.4)] {
        for k in 0..=10 {
            let s = k as f32 * 0.1;
            for size in CANVASES {
                let mut scene = Frustum::new();
                scene.set_offset(x, y).unwrap();
                let mut frame = Frame::default();
                scene.draw(&mut frame, s).unwrap();
                let camera = page_camera([4.5, 1.2, -4.0, 17.0, 0.45, 0.45], &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame, s).unwrap();
                let camera = page_camera([4.5, 1.2, -4.0, 17.0, 0.45, 0.45], &frame, size);
                let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
                let mut checked: Vec<usize> = ["depth 0", "depth 1", "NDC (wgpu)"]
                    .iter()
                    .map(|t| texts.iter().position(|l| l == t).unwrap())
                    .collect();
                // The box's p (drawn while the point is in front of the eye) comes after the
                // frustum's p and image.
                let image = texts.iter().position(|l| *l == "image").unwrap();
                checked.extend(texts.iter().rposition(|l| *l == "p").filter(|&i| i > image));
                let name = format!("00 NDC box, point ({x}, {y}), s {s}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &checked, 2.0)
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_03_gimbal_axle_names_keep_off_the_rings_and_axles() {
    // Figure 3 at its page camera (lessons/03-rotations/lesson.js), both canvases, at the page's
    // angles, at gimbal lock both ways and at others across the sliders: each axle's name is
    // shown where the figure put it, keeps 2 px off every line and dot, and covers no point of
    // the three rings (drawn as meshes, sampled here as the figure builds them: yaw's ring in
    // its x-y plane, 1.3 m; pitch's in x-z, 1.1 m; roll's in y-z, 0.9 m). As on the page, the
    // figure places them for the view of the frame before.
    use glam::Mat4;
    use inbetween::figures::rotations::Gimbal;
    let view = [0.0, 1.4, 0.0, 5.2, 0.7, 0.35];
    let mut failures = Vec::new();
    for [yaw, pitch, roll] in [
        [30.0, 0.0, 20.0],
        [30.0, 90.0, 20.0],
        [30.0, -90.0, 20.0],
        [-120.0, 45.0, 90.0],
        [150.0, -30.0, -160.0],
        [0.0, 60.0, 0.0],
    ] {
        for size in CANVASES {
            let mut scene = Gimbal::new();
            scene.set_angles_deg(yaw, pitch, roll).unwrap();
            let camera = page_camera(view, &Frame::default(), size);
            scene.set_view(camera, size.x, size.y);
            let mut frame = Frame::default();
            scene.draw(&mut frame);
            let name = format!("03 gimbal ({yaw}, {pitch}, {roll})");
            let names: Vec<usize> = (0..frame.labels.len())
                .filter(|&i| frame.labels[i].text.ends_with("axle"))
                .collect();
            assert_eq!(names.len(), 3);
            failures.extend(failure_of(|| {
                assert_shown_clear_by(&name, &frame, &camera, size, &names, 2.0)
            }));
            // The rings.
            let deg = std::f32::consts::PI / 180.0;
            let outer =
                Mat4::from_translation(Vec3::new(0.0, 1.5, 0.0)) * Mat4::from_rotation_y(yaw * deg);
            let middle = outer * Mat4::from_rotation_x(pitch * deg);
            let inner = middle * Mat4::from_rotation_z(roll * deg);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let boxes = label_boxes(&frame, &camera, size);
            failures.extend(failure_of(|| {
                for (m, u, v, r) in [
                    (outer, Vec3::X, Vec3::Y, 1.3),
                    (middle, Vec3::X, Vec3::Z, 1.1),
                    (inner, Vec3::Y, Vec3::Z, 0.9),
                ] {
                    for k in 0..80 {
                        let phi = k as f32 / 80.0 * std::f32::consts::TAU;
                        let p = m.transform_point3((u * phi.cos() + v * phi.sin()) * r);
                        let Some(c) = project_to_canvas(view_proj, size, p) else {
                            continue;
                        };
                        for (text, rect) in boxes.iter().filter(|(t, _)| t.ends_with("axle")) {
                            let inside = c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all();
                            assert!(
                                !inside,
                                "{name} on {size}: {text:?} at {:?} covers a ring at {c}",
                                rect.min
                            );
                        }
                    }
                }
            }));
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_eye_and_z_near_labels_stay_apart_at_a_small_z_near() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js), both canvases,
    // across the z_near slider's low end (0.05 m, the lesson's 0.1 m and 0.2 m) and at the
    // page's 1 m, along the point's path: near the eye the near plane's corner, which "z_near"
    // names, is a few pixels from the eye's dot and from the point's image, so "eye", "z_near"
    // and "image" sit at least LABELS_APART_PX apart, each where the figure put it (no leader
    // line), and "z_near" and "image" cover no dot. As on the page, the figure places them for
    // the view of the frame before.
    use inbetween::draw::LABELS_APART_PX;
    use inbetween::figures::raster::Frustum;
    let view = [4.5, 1.2, -4.0, 17.0, 0.45, 0.45];
    let mut failures = Vec::new();
    for near in [0.05, 0.1, 0.15, 0.2, 0.5, 1.0] {
        for s in [0.0, 0.03, 0.07, 0.15, 0.5, 1.0] {
            for size in CANVASES {
                let mut scene = Frustum::new();
                scene.set_frustum(50.0, near, 8.0).unwrap();
                let mut frame = Frame::default();
                scene.draw(&mut frame, s).unwrap();
                let camera = page_camera(view, &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame, s).unwrap();
                let camera = page_camera(view, &frame, size);
                let name = format!("00 frustum, z_near {near}, s {s}");
                let index = |t: &str| frame.labels.iter().position(|l| l.text == t).unwrap();
                let (eye, z_near, image) = (index("eye"), index("z_near"), index("image"));
                let placed = layout(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    let boxes = [eye, z_near, image].map(|i| {
                        let (l, b, at) = &placed[i];
                        assert!(
                            at.shown && at.leader_to.is_none(),
                            "{name} on {size}: {:?} moved",
                            l.text
                        );
                        Rect {
                            min: at.top_left,
                            size: b.size,
                        }
                    });
                    for (a, b) in [(0, 1), (1, 2), (0, 2)] {
                        assert!(
                            !boxes[a].overlaps(&boxes[b], LABELS_APART_PX - 0.5),
                            "{name} on {size}: {:?} at {:?} and {:?} at {:?} butt",
                            frame.labels[[eye, z_near, image][a]].text,
                            boxes[a].min,
                            frame.labels[[eye, z_near, image][b]].text,
                            boxes[b].min
                        );
                    }
                    let mut only = frame.clone();
                    only.labels = vec![frame.labels[z_near].clone(), frame.labels[image].clone()];
                    only.strokes.clear();
                    assert_clear(&name, &only, &camera, size);
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_depth_eye_and_fighting_labels_keep_off_the_floor_and_bars_when_orbited() {
    // Figure 3 at its page camera (lessons/00-triangles-to-pixels/lesson.js) and orbited round
    // it (azimuths round the side view, from low to steep), both canvases, at the page's
    // settings and with half the gap (the fighting line nearer, at 10.9 m): "eye", "fighting
    // from here" and the bars' and the grey line's names are shown where the figure put them
    // (so none sits on another), keep 2 px off every dot and line, and cover no point of the
    // upper floor (a mesh, sampled here every half metre). As on the page, the figure places
    // them for the view of the frame before.
    use inbetween::figures::raster::DepthPrecision;
    const NAMES: [&str; 4] = [
        "eye",
        "fighting from here",
        "one depth step (×40)",
        "separation d·gap/h (×40)",
    ];
    let mut failures = Vec::new();
    for gap in [0.01, 0.005] {
        for (yaw, pitch) in [
            (1.2, 0.45),
            (0.6, 0.45),
            (0.0, 0.3),
            (-0.6, 0.45),
            (1.8, 0.3),
            (2.6, 0.45),
            (1.2, 0.9),
            (0.3, 1.1),
            (1.2, 0.1),
        ] {
            let view = [0.0, 3.0, -20.0, 30.0, yaw, pitch];
            for size in CANVASES {
                let mut scene = DepthPrecision::new();
                scene.set(0.1, 1000.0, gap, 16.0).unwrap();
                let mut frame = Frame::default();
                scene.draw(&mut frame);
                let camera = page_camera(view, &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame);
                let camera = page_camera(view, &frame, size);
                let name = format!("00 depth, gap {gap}, orbit ({yaw}, {pitch})");
                let named: Vec<usize> = (0..frame.labels.len())
                    .filter(|&i| NAMES.contains(&&*frame.labels[i].text))
                    .collect();
                assert_eq!(named.len(), NAMES.len(), "{name}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
                }));
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let floor: Vec<Vec2> = (0..=4)
                    .flat_map(|i| {
                        (0..=80)
                            .map(move |k| Vec3::new(-1.0 + 0.5 * i as f32, 0.0, -0.5 * k as f32))
                    })
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                let boxes = label_boxes(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    for (text, rect) in boxes.iter().filter(|(t, _)| NAMES.contains(&&**t)) {
                        for c in &floor {
                            assert!(
                                !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                                "{name} on {size}: {text:?} at {:?} covers the floor at {c}",
                                rect.min
                            );
                        }
                    }
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_05_probe_value_keeps_off_the_cell_square_and_the_arrows() {
    // Figure 2 at its page camera (lessons/05-noise/lesson.js), both canvases, for the
    // page's probe (0.4, 0.7) and others across the grid, on the 2D noise and on slices of 3D
    // noise (z = 0.5, whose sticks join the dots to the surface, and 1.3): the probe's "n = …"
    // is shown where the figure put it and keeps 2 px off every dot and line (the purple
    // square of the probe's cell, the sticks, the arrows, the probe's stem). As on the page,
    // the figure places it for the view of the frame before.
    use inbetween::figures::noise::{Noise2d, TerrainFigure};
    let view = [0.0, 0.0, 0.0, 2.9, 0.35, 0.75];
    let mut failures = Vec::new();
    for (x, y) in [
        (0.4, 0.7),
        (0.1, 0.1),
        (-0.5, 0.5),
        (0.9, -0.9),
        (-1.5, -1.2),
        (1.5, 1.5),
    ] {
        for z in [0.0, 0.5, 1.3] {
            for size in CANVASES {
                let mut scene = Noise2d::new();
                scene.set_probe(x, y).unwrap();
                scene.set_z(z).unwrap();
                scene.take_dirty();
                let mut frame = Frame::default();
                scene.draw(&mut frame, inbetween::draw::MeshId(1));
                let camera = page_camera(view, &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame, inbetween::draw::MeshId(1));
                let camera = page_camera(view, &frame, size);
                let name = format!("05 noise 2D, probe ({x}, {y}), z {z}");
                let value: Vec<usize> = (0..frame.labels.len())
                    .filter(|&i| frame.labels[i].text.starts_with("n = "))
                    .collect();
                assert_eq!(value.len(), 1, "{name}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &value, 2.0)
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_06_selected_joint_name_keeps_off_the_path_ticks_and_bones() {
    // Figures 1 and 2 at their page cameras (lessons/06-skeletons/lesson.js), both canvases,
    // with each figure's starting clip, keys, interpolations and joint, across a cycle: the
    // selected joint's name is shown where the figure put it and keeps 2 px off every dot,
    // tick and line (the ring of path ticks round the joint's path, the bones). As on the page,
    // the figure places it for the view of the frame before.
    use inbetween::figures::skeleton::SkeletonFigure;
    let mut failures = Vec::new();
    for (clip, keys, joint, compare, yaw, pitch) in [
        ("walk", 9.0, "thigh.L", "none", 0.5, 0.2),
        (
            "arm circles",
            4.0,
            "upper_arm.L",
            "linear (nlerp)",
            1.2,
            0.15,
        ),
    ] {
        for k in 0..8 {
            let t = k as f32 * 0.15;
            for size in CANVASES {
                let mut scene = SkeletonFigure::new();
                scene.set_clip(clip).unwrap();
                scene.set_keys_per_cycle(keys).unwrap();
                scene.set_interpolation("linear (slerp)").unwrap();
                scene.set_compare(compare).unwrap();
                let index = scene
                    .skeleton()
                    .names()
                    .iter()
                    .position(|n| n == joint)
                    .unwrap();
                scene.select(index).unwrap();
                let view = [0.0, 0.85, 0.0, 2.5, yaw, pitch];
                let mut frame = Frame::default();
                scene.draw(&mut frame, t).unwrap();
                let camera = page_camera(view, &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame, t).unwrap();
                let camera = page_camera(view, &frame, size);
                let name = format!("06 {clip}, {joint}, t {t}");
                let named: Vec<usize> = (0..frame.labels.len())
                    .filter(|&i| frame.labels[i].text == joint)
                    .collect();
                assert_eq!(named.len(), 1, "{name}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_06_gltf_root_name_keeps_off_the_bones() {
    // Lesson 06's glTF figure at the camera the page fits to each sample character
    // (www/gltf-figure.js: the figure's fit, yaw 0.6, pitch 0.15) and orbited round it (from
    // the side, from behind, from above, from below), both canvases, across the first clip:
    // "root" is shown where the figure put it, keeps 2 px off every bone and dot (CesiumMan's
    // spine rises straight up from its root) and off the mesh's grey dots (its hips surround
    // the root), keeps 11 px off every other joint's ball (beside one, it would seem to name
    // it) and ends within 64 px (four label heights) of the root's ball, so that it still names
    // it. As on the page, the figure places it for the view of the frame before. The
    // characters are read from ../shared/assets/gltf (or INBETWEEN_GLTF_ASSETS); without them
    // the check is not run, as in tests/gltf_import.rs.
    use inbetween::figures::gltf::GltfFigure;
    use inbetween::figures::palette;
    let dir = std::env::var_os("INBETWEEN_GLTF_ASSETS")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| {
            std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/assets/gltf")
        });
    if !dir.join("CesiumMan.gltf").exists() {
        assert!(
            std::env::var_os("INBETWEEN_REQUIRE_ASSETS").is_none(),
            "the glTF sample characters are not in {}",
            dir.display()
        );
        eprintln!("glTF sample characters not found: root label check not run");
        return;
    }
    let mut failures = Vec::new();
    for character in ["CesiumMan", "RiggedFigure"] {
        let bytes = std::fs::read(dir.join(format!("{character}.gltf"))).unwrap();
        for (yaw, pitch) in [
            (0.6, 0.15),
            (-0.6, 0.15),
            (1.6, 0.3),
            (3.1, 0.15),
            (0.6, 0.9),
            (0.6, -0.3),
        ] {
            for k in 0..6 {
                for size in CANVASES {
                    let mut scene = GltfFigure::new();
                    scene.load(character, &bytes).unwrap();
                    let t = k as f32 / 6.0 * scene.duration_sec();
                    let [x, y, z, distance] = scene.fit();
                    let view = [x, y, z, distance, yaw, pitch];
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, t, &[]).unwrap();
                    let camera = page_camera(view, &frame, size);
                    scene.set_view(camera, size.x, size.y);
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, t, &[]).unwrap();
                    let camera = page_camera(view, &frame, size);
                    let name = format!("06 glTF {character}, t {t}, orbit ({yaw}, {pitch})");
                    let root: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| frame.labels[i].text == "root")
                        .collect();
                    assert_eq!(root.len(), 1, "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &root, 2.0)
                    }));
                    // The mesh's dots are points of a radius in metres: their disc on screen,
                    // measured along the camera's right.
                    assert!(!frame.points.is_empty(), "{name}: no mesh dots drawn");
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let at = |p: Vec3| project_to_canvas(view_proj, size, p);
                    let right = camera.view().row(0).truncate();
                    let ball = frame
                        .meshes
                        .iter()
                        .find(|m| m.color.truncate() == palette::ORANGE)
                        .unwrap();
                    let ball = at(ball.model.w_axis.truncate()).unwrap();
                    let boxes = label_boxes(&frame, &camera, size);
                    failures.extend(failure_of(|| {
                        let (_, rect) = boxes.iter().find(|(t, _)| t == "root").unwrap();
                        let gap = rect.nearest(ball).distance(ball);
                        assert!(
                            gap <= 64.0,
                            "{name} on {size}: \"root\" {gap} px from the root's ball"
                        );
                        // Nor beside another joint's ball (dark), which it would seem to name.
                        let joints = frame.meshes.iter();
                        for m in joints.filter(|m| m.color.truncate() == palette::DARK) {
                            let centre = m.model.w_axis.truncate();
                            let Some(c) = at(centre) else { continue };
                            let edge = at(centre + right * m.model.x_axis.length());
                            let r = edge.map_or(0.0, |e| e.distance(c));
                            let gap = rect.nearest(c).distance(c);
                            assert!(
                                gap > r + 11.0,
                                "{name} on {size}: \"root\" {gap} px from a joint's centre at {c}"
                            );
                        }
                        for d in &frame.points {
                            let centre = Vec3::from(d.center);
                            let Some(c) = at(centre) else { continue };
                            let r = at(centre + right * d.radius).map_or(0.0, |e| e.distance(c));
                            assert!(
                                rect.nearest(c).distance(c) > r + 2.0,
                                "{name} on {size}: \"root\" at {:?} within 2 px of a mesh dot at {c}",
                                rect.min
                            );
                        }
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_12_rule_names_keep_off_the_cells_the_circle_and_the_arrows() {
    // Figure 1 at its page camera (lessons/12-boids/lesson.js: the figure's view, fitted to its
    // grid), both canvases, at the defaults and after every slider has moved: each rule's name
    // is shown where the figure put it and keeps 2 px off the cells' squares, the radius circle,
    // the field-of-view edges, the arrows and the dots. As on the page, the figure places them
    // for the view of the frame before.
    use inbetween::figures::boids::RulesFigure;
    let mut failures = Vec::new();
    // (x, z, heading °, radius, field of view °, cell size): the defaults, the page sweep's
    // last state, and a few between.
    let states = [
        (0.0, 0.0, 0.0, 1.2, 270.0, 1.2),
        (-1.15, -1.15, -110.0, 2.4, 70.0, 0.6),
        (0.8, -0.4, 45.0, 1.5, 270.0, 1.0),
        (-0.5, 0.9, 160.0, 2.0, 200.0, 0.8),
        (1.2, 1.2, -45.0, 3.0, 360.0, 1.5),
    ];
    for (x, z, heading, radius, fov, cell) in states {
        for size in CANVASES {
            let mut scene = RulesFigure::new();
            scene.set_cell_size(cell).unwrap();
            scene.set_position(x, z).unwrap();
            scene.set_heading_deg(heading).unwrap();
            scene.set_radius(radius).unwrap();
            scene.set_fov_deg(fov).unwrap();
            let mut frame = Frame::default();
            scene.draw(&mut frame);
            let camera = page_camera(scene.view(), &frame, size);
            scene.set_view(camera, size.x, size.y);
            let mut frame = Frame::default();
            scene.draw(&mut frame);
            let camera = page_camera(scene.view(), &frame, size);
            let name = format!("12 rules at ({x}, {z}), heading {heading}, cell {cell}");
            let named: Vec<usize> = (0..frame.labels.len()).collect();
            assert!(!named.is_empty(), "{name}");
            failures.extend(failure_of(|| {
                assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
            }));
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_12_leader_and_predator_names_keep_off_the_neighbour_lines() {
    // Figure 2 at its page camera (lessons/12-boids/lesson.js: target 0, distance 9, yaw 0.5,
    // pitch 0.45, fitted to the box), both canvases, with the leader and the predator on, as the
    // flock flies: "leader" and "predator" are shown where the figure put them and keep 2 px off
    // the orange boid's neighbour lines, its steering arrow and the box (no place in a flock is
    // clear of every boid's tail, so those are not checked).
    use inbetween::figures::boids::{FlockFigure, TAIL_PX};
    let view = [0.0, 0.0, 0.0, 9.0, 0.5, 0.45];
    let mut failures = Vec::new();
    for size in CANVASES {
        let mut scene = FlockFigure::new();
        scene.set_leader(true);
        scene.set_predator(true);
        for k in 0..=300 {
            scene.advance_to(k as f32 / 60.0).unwrap();
            if k % 30 != 0 {
                continue;
            }
            let mut frame = Frame::default();
            scene.draw(&mut frame);
            let camera = page_camera(view, &frame, size);
            scene.set_view(camera, size.x, size.y);
            let mut frame = Frame::default();
            scene.draw(&mut frame);
            let camera = page_camera(view, &frame, size);
            // The boids' own tails (TAIL_PX wide) are left out; the neighbour lines, the arrow
            // and the box stay.
            frame.strokes.retain(|s| s.width_px != TAIL_PX);
            let name = format!("12 flock at t {}", k as f32 / 60.0);
            let named: Vec<usize> = (0..frame.labels.len()).collect();
            assert_eq!(named.len(), 2, "{name}");
            failures.extend(failure_of(|| {
                assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
            }));
        }
    }
    assert_none_failed(&failures);
}
