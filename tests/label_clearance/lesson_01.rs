//! Lesson 01: its figures' labels keep clear of what they name (see main.rs).

use super::*;

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
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    view,
                    size,
                    |fig, out| {
                        fig.draw(out).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
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
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        view,
                        size,
                        |fig, out| {
                            fig.draw(out, stage).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
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
fn lesson_01_order_names_keep_off_the_boxes_axes_and_paths() {
    // Figure 1 at the page's camera (lessons/01-transforms/lesson.js), both canvases, through
    // both steps of the timeline, T·R solid (the page's start): "T·R" and "R·T" keep off the
    // solid box's axes (which turn with it), the paths, the arm and the dots. They are placed
    // first (the highest priority), so the frame's other labels, left out here, never move
    // them. With R·T solid, its x axis ends near T·R's name at the end of the timeline. As on
    // the page, the figure places them for the view of the frame before.
    use inbetween::figures::transforms::{Order, SingleShape};
    for order in [Order::RotateFirst] {
        let mut scene = SingleShape::new();
        scene.set_order(order);
        for stage in [0.0, 0.1, 0.36, 1.0, 1.5, 2.0] {
            for size in CANVASES {
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    [0.5, 0.3, 0.0, 5.0, 0.6, 0.45],
                    size,
                    |fig, out| {
                        fig.draw(out, stage).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let names: Vec<_> = frame
                    .labels
                    .iter()
                    .filter(|l| l.text == "T·R" || l.text == "R·T")
                    .cloned()
                    .collect();
                assert_eq!(names.len(), 2);
                assert!(frame.labels.iter().all(|l| l.priority <= 3));
                // Each name stays apart from the world axes' names ("y R·T" would read as one
                // string at the y axis's tip).
                let boxes = label_boxes(&frame, &camera, size);
                for (text, rect) in boxes.iter().filter(|(t, _)| t == "T·R" || t == "R·T") {
                    for (axis, other) in boxes.iter().filter(|(t, _)| t.len() == 1) {
                        assert!(
                            !rect.overlaps(other, 2.0),
                            "01 orders, stage {stage} on {size}: {text:?} touches {axis:?}"
                        );
                    }
                }
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
fn lesson_01_order_names_keep_off_the_axes_when_the_box_turns_half_round() {
    // Figure 1 from the page's camera and after the page test's drag, with the box turned
    // about z by 180° and 90° (its x axis's head then points back at the name above the box),
    // both orders solid, over the steps: "T·R" and "R·T" cover no dot or line (the axes'
    // heads included) and neither box.
    use inbetween::figures::transforms::{Order, SingleShape};
    let page = [0.5, 0.3, 0.0, 5.0, 0.6, 0.45];
    let mut failures = Vec::new();
    for angles in [
        Vec3::new(0.0, 0.0, 180.0),
        Vec3::new(0.0, 0.0, 90.0),
        Vec3::splat(-109.0),
    ] {
        for order in [Order::RotateFirst, Order::TranslateFirst] {
            let mut scene = SingleShape::new();
            scene
                .set_transform(Vec3::new(1.0, 0.5, 0.0), angles)
                .unwrap();
            scene.set_order(order);
            for stage in [0.0, 0.5, 1.0, 1.5, 2.0] {
                for view in [
                    page,
                    [0.5, 0.3, 0.0, 5.0, 0.6 - 0.008 * 130.0, 0.45 + 0.008 * 42.0],
                ] {
                    for size in CANVASES {
                        let (frame, camera) = drawn_for_view(
                            &mut scene,
                            view,
                            size,
                            |fig, out| {
                                fig.draw(out, stage).unwrap();
                            },
                            |fig, cam, px| fig.set_view(cam, px.x, px.y),
                        );
                        let name = format!(
                            "01 orders, angles {angles}, {order:?}, stage {stage}, view {view:?}"
                        );
                        let boxes = cube_points(&frame, &camera, size);
                        let named = |text: &str| text == "T·R" || text == "R·T";
                        failures.extend(failure_of(|| {
                            assert_clear_of(&name, &frame, &camera, size, named);
                            let mut only = frame.clone();
                            only.labels.retain(|l| named(&l.text));
                            assert_off(&name, &only, &camera, size, &boxes);
                        }));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_01_body_names_keep_off_the_body_when_orbited_and_scaled() {
    // Figure 2 (lessons/01-transforms/lesson.js: target (0, 0.9, 0), distance 3.6, yaw 0.45,
    // pitch 0.2) from the page's camera and orbited round, through the walk, at rest scale and
    // with the page test's settings (forearm.L selected, turned (−22°, −109°, −109°), scaled
    // by 2.42 with children inheriting it): "left wrist", "left thigh" and the selected joint's
    // name cover none of the body's boxes (their guide lines join them to what they name).
    use inbetween::figures::transforms::HierarchyFigure;
    let mut failures = Vec::new();
    for moved in [false, true] {
        for yaw in [0.45, 0.45 - 1.04, -1.2, 1.6, 2.8] {
            for pitch in [0.2, 0.54] {
                for time in [0.0, 0.3, 0.7] {
                    for size in CANVASES {
                        failures.extend(failure_of(|| {
                            let mut scene = HierarchyFigure::new();
                            if moved {
                                let forearm = scene
                                    .joint_names()
                                    .iter()
                                    .position(|n| n == "forearm.L")
                                    .unwrap();
                                scene.select(forearm).unwrap();
                                scene
                                    .set_joint_angles_deg(forearm, Vec3::new(-22.0, -109.0, -109.0))
                                    .unwrap();
                                scene.set_joint_scale(forearm, Vec3::splat(2.42)).unwrap();
                                scene.set_inherit_scale(true);
                                scene.set_animate(true);
                            }
                            let view = [0.0, 0.9, 0.0, 3.6, yaw, pitch];
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
                                "01 body, moved {moved}, yaw {yaw}, pitch {pitch}, t {time}"
                            );
                            let boxes = cube_points(&frame, &camera, size);
                            let mut only = frame.clone();
                            only.labels.retain(|l| l.priority == 1 && l.text.len() > 2);
                            assert_eq!(only.labels.len(), 3, "{name}: three names");
                            assert_off(&name, &only, &camera, size, &boxes);
                        }));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_01_box_axes_show_over_the_box_and_no_name_sits_at_their_tips() {
    // Figure 1 from the page's camera and after the page test's drag, both canvases, over the
    // steps, at the page's start and at the page test's settings, each order solid: the solid
    // box's own axes (0.6 m long) are drawn over everything (the box would hide them), and no
    // name ("T·R", "R·T", p's, v's) ends within 16 px of one of their tips, where it would read
    // as that axis's name.
    use inbetween::draw::{palette, ON_TOP};
    use inbetween::figures::transforms::{Order, SingleShape};
    let page = [0.5, 0.3, 0.0, 5.0, 0.6, 0.45];
    let dragged = [0.5, 0.3, 0.0, 5.0, 0.6 - 0.008 * 130.0, 0.45 + 0.008 * 42.0];
    let mut failures = Vec::new();
    for (t, angles) in [
        (Vec3::new(1.0, 0.5, 0.0), Vec3::new(0.0, 0.0, 30.0)),
        (Vec3::splat(-1.21), Vec3::splat(-109.0)),
    ] {
        for order in [Order::RotateFirst, Order::TranslateFirst] {
            let mut scene = SingleShape::new();
            scene.set_transform(t, angles).unwrap();
            scene.set_order(order);
            for stage in [0.0, 0.5, 1.0, 1.5, 2.0] {
                for view in [page, dragged] {
                    for size in CANVASES {
                        let (frame, camera) = drawn_for_view(
                            &mut scene,
                            view,
                            size,
                            |fig, out| {
                                fig.draw(out, stage).unwrap();
                            },
                            |fig, cam, px| fig.set_view(cam, px.x, px.y),
                        );
                        let name =
                            format!("01 box axes, t {t}, {order:?}, stage {stage}, view {view:?}");
                        let m = scene.matrix_at(order, stage);
                        let centre = m.w_axis.truncate().to_array();
                        let view_proj = camera.projection(size.x / size.y) * camera.view();
                        let boxes = label_boxes(&frame, &camera, size);
                        failures.extend(failure_of(|| {
                            // The world axes' letters keep off p's dot.
                            let p = frame
                                .markers
                                .iter()
                                .find(|d| d.color[..3] == palette::PINK.to_array()[..])
                                .expect("p's dot");
                            let dot = project_to_canvas(view_proj, size, Vec3::from(p.center));
                            for (text, rect) in boxes.iter().filter(|(t, _)| t.chars().count() == 1)
                            {
                                let Some(dot) = dot else { continue };
                                let gap = rect.nearest(dot).distance(dot);
                                assert!(
                                    gap > 0.5 * p.size_px,
                                    "{name} on {size}: {text:?} {gap} px from p's dot"
                                );
                            }
                            for (axis, color) in [
                                (Vec3::X, palette::X_AXIS),
                                (Vec3::Y, palette::Y_AXIS),
                                (Vec3::Z, palette::Z_AXIS),
                            ] {
                                let own = frame
                                    .strokes
                                    .iter()
                                    .find(|s| {
                                        let length = Vec3::from(s.b).distance(Vec3::from(s.a));
                                        s.a == centre
                                            && (length - 0.6).abs() < 1e-4
                                            && s.color[..3] == color.to_array()[..]
                                    })
                                    .expect("the box's axis");
                                assert_eq!(
                                    own.depth_bias, ON_TOP,
                                    "{name}: axis {axis} under the box"
                                );
                                let tip = m.transform_point3(axis * 0.6);
                                let Some(tip) = project_to_canvas(view_proj, size, tip) else {
                                    continue;
                                };
                                for (text, rect) in
                                    boxes.iter().filter(|(t, _)| t.chars().count() > 1)
                                {
                                    let gap = rect.nearest(tip).distance(tip);
                                    assert!(
                                        gap >= 16.0,
                                        "{name} on {size}: {text:?} {gap} px from axis {axis}'s tip"
                                    );
                                }
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
fn lesson_01_order_names_hang_on_leaders_from_their_boxes_away_from_arrowheads() {
    // Figure 1 at the page's camera, both canvases, over the steps, at the page's start, at
    // the page test's settings (every slider at −1.21 m or −109°, R·T solid) and with the box
    // turned half round about z: each order's name ends a thin leader of its own colour that
    // starts on its own box, and its box as the page lays it out keeps 12 px from every
    // arrowhead (the world axes' and the solid box's), where it would read as an axis's name.
    use glam::Mat4;
    use inbetween::figures::transforms::{Order, SingleShape, BOX_HALF};
    let mut failures = Vec::new();
    for (t, angles, order) in [
        (Vec3::new(1.0, 0.5, 0.0), Vec3::new(0.0, 0.0, 30.0), Order::RotateFirst),
        (Vec3::splat(-1.21), Vec3::splat(-109.0), Order::TranslateFirst),
        (Vec3::new(1.0, 0.5, 0.0), Vec3::new(0.0, 0.0, 180.0), Order::RotateFirst),
    ] {
        let mut scene = SingleShape::new();
        scene.set_transform(t, angles).unwrap();
        scene.set_order(order);
        for stage in [0.0, 0.5, 1.0, 1.5, 2.0] {
            for size in CANVASES {
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    [0.5, 0.3, 0.0, 5.0, 0.6, 0.45],
                    size,
                    |fig, out| {
                        fig.draw(out, stage).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let name = format!("01 leaders, t {t}, angles {angles}, stage {stage} on {size}");
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let solid = scene.matrix_at(order, stage);
                let tips: Vec<Vec2> = [Vec3::X, Vec3::Y, Vec3::Z]
                    .into_iter()
                    .chain([Vec3::X, Vec3::Y, Vec3::Z].map(|a| solid.transform_point3(a * 0.6)))
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                let boxes = label_boxes(&frame, &camera, size);
                for named in [Order::RotateFirst, Order::TranslateFirst] {
                    let placed: Mat4 = scene.matrix_at(named, stage);
                    let label = frame.labels.iter().find(|l| l.text == named.name()).unwrap();
                    failures.extend(failure_of(|| {
                        let leader = frame.strokes.iter().find(|s| {
                            let local = placed.inverse().transform_point3(Vec3::from(s.a));
                            s.color[..3] == named.color().to_array()
                                && Vec3::from(s.b).distance(label.anchor) < 1e-4
                                && local.abs().cmple(BOX_HALF + 1e-3).all()
                        });
                        assert!(leader.is_some(), "{name}: {} has no leader from its box", named.name());
                        let (_, rect) = boxes.iter().find(|(t, _)| t == named.name()).unwrap();
                        for tip in &tips {
                            let gap = rect.nearest(*tip).distance(*tip);
                            assert!(gap >= 12.0, "{name}: {} {gap} px from an arrowhead at {tip}", named.name());
                        }
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}
