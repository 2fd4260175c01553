//! Lesson 01's figures, natively: what they draw, what they reject, and what they say about the
//! student's exercises (through test runners that answer wrongly or panic).

use glam::{Mat4, Vec3};
#[path = "support/flat.rs"]
mod flat;
use inbetween::draw::{palette, Frame, MeshId};
use inbetween::exercises::run::{self, Failure};
use inbetween::figures::transforms::{HierarchyFigure, Order, SingleShape, BOX_HALF};

fn near(a: Vec3, b: Vec3, eps: f32) -> bool {
    a.distance(b) < eps
}

// Figure 1.

#[test]
fn both_orders_are_drawn_solid_and_ghost_with_labels() {
    let shape = SingleShape::new();
    let mut frame = Frame::default();
    shape.draw(&mut frame, 2.0).unwrap();
    let solid = frame
        .meshes
        .iter()
        .find(|m| m.mesh == MeshId::CUBE)
        .unwrap();
    assert_eq!(solid.color.truncate(), Order::RotateFirst.color());
    // The ghost is the R·T box's 12 edges (plus the arm and the arc in the same colour).
    let ghost_centre = shape.matrix(Order::TranslateFirst).w_axis.truncate();
    let ghost_edges = frame
        .segments_of(Order::TranslateFirst.color())
        .filter(|(a, b)| near((*a + *b) * 0.5, ghost_centre, BOX_HALF.length() + 1e-3))
        .count();
    assert!(ghost_edges >= 12, "{ghost_edges} ghost edges");
    let labels: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    for text in ["T·R", "R·T", "p (w = 1)", "v (w = 0)", "x", "y", "z"] {
        assert!(labels.contains(&text), "missing label {text}: {labels:?}");
    }
}

#[test]
fn translate_first_makes_rt_the_solid_box() {
    let mut shape = SingleShape::new();
    shape.set_order(Order::TranslateFirst);
    let mut frame = Frame::default();
    shape.draw(&mut frame, 2.0).unwrap();
    let solid = frame
        .meshes
        .iter()
        .find(|m| m.mesh == MeshId::CUBE)
        .unwrap();
    assert_eq!(solid.color.truncate(), Order::TranslateFirst.color());
    let expected = shape.matrix(Order::TranslateFirst) * Mat4::from_scale(BOX_HALF);
    assert!(solid.model.abs_diff_eq(expected, 1e-6));
}

#[test]
fn rt_swings_about_the_origin_and_tr_stays_at_t() {
    let mut shape = SingleShape::new();
    shape
        .set_transform(Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 90.0))
        .unwrap();
    let tr = shape.matrix(Order::RotateFirst).w_axis.truncate();
    let rt = shape.matrix(Order::TranslateFirst).w_axis.truncate();
    assert!(near(tr, Vec3::X, 1e-6), "{tr}");
    assert!(near(rt, Vec3::Y, 1e-6), "{rt}");
    // The arc goes from t to R·t, staying on the circle of radius |t| about the origin.
    let arc = shape.swing_arc(20);
    assert!(near(arc[0], Vec3::X, 1e-5) && near(arc[19], Vec3::Y, 1e-5));
    assert!(arc.iter().all(|p| (p.length() - 1.0).abs() < 1e-5));
    let mut frame = Frame::default();
    let note = shape.draw(&mut frame, 2.0).unwrap();
    assert!(note.contains("R·t = (0.000, 1.000, 0.000)"), "{note}");
}

#[test]
fn the_direction_never_leaves_the_origin() {
    let mut shape = SingleShape::new();
    shape
        .set_transform(Vec3::new(5.0, -3.0, 2.0), Vec3::new(10.0, 20.0, 30.0))
        .unwrap();
    let mut frame = Frame::default();
    shape.draw(&mut frame, 2.0).unwrap();
    let from_origin = frame
        .segments_of(palette::PINK)
        .any(|(a, _)| a == Vec3::ZERO);
    assert!(from_origin, "the pink direction arrow starts at the origin");
}

/// The Try this of Figure 1: with t = 0 the boxes coincide; with t back at (1, 0.5, 0) and the
/// angle z at 180°, R·T ends 2|t| = 2.236 m from T·R.
#[test]
fn the_try_this_of_figure_1_holds() {
    let mut shape = SingleShape::new();
    shape
        .set_transform(Vec3::ZERO, Vec3::new(0.0, 0.0, 30.0))
        .unwrap();
    let centre = |s: &SingleShape, o: Order| s.matrix(o).w_axis.truncate();
    assert!(near(
        centre(&shape, Order::RotateFirst),
        centre(&shape, Order::TranslateFirst),
        1e-6
    ));
    assert!(shape
        .matrix(Order::RotateFirst)
        .abs_diff_eq(shape.matrix(Order::TranslateFirst), 1e-6));
    // During the steps both centres stay at the origin.
    for stage in [0.3, 0.8, 1.2, 1.7] {
        for o in [Order::RotateFirst, Order::TranslateFirst] {
            assert!(near(
                shape.matrix_at(o, stage).w_axis.truncate(),
                Vec3::ZERO,
                1e-6
            ));
        }
    }
    shape
        .set_transform(Vec3::new(1.0, 0.5, 0.0), Vec3::new(0.0, 0.0, 180.0))
        .unwrap();
    let gap = centre(&shape, Order::RotateFirst).distance(centre(&shape, Order::TranslateFirst));
    assert!((gap - 2.0 * 1.25f32.sqrt()).abs() < 1e-5, "{gap}");
    let mut frame = Frame::default();
    let note = shape.draw(&mut frame, 2.0).unwrap();
    assert!(note.contains("R·t = (-1.000, -0.500, 0.000)"), "{note}");
    assert!(note.contains("the centres are 2.236 m apart"), "{note}");
}

/// The two orders step by step: T·R turns in place and then slides; R·T slides and then swings.
#[test]
fn the_steps_apply_the_right_hand_factor_first() {
    let shape = SingleShape::new();
    let t = Vec3::new(1.0, 0.5, 0.0);
    let centre = |o: Order, stage: f32| shape.matrix_at(o, stage).w_axis.truncate();
    let turned = |o: Order, stage: f32| {
        let x = shape.matrix_at(o, stage).x_axis.truncate();
        x.y.atan2(x.x).to_degrees()
    };
    // Nothing applied at 0; the full products at 2.
    for o in [Order::RotateFirst, Order::TranslateFirst] {
        assert!(shape.matrix_at(o, 0.0).abs_diff_eq(Mat4::IDENTITY, 1e-6));
        assert!(shape.matrix_at(o, 2.0).abs_diff_eq(shape.matrix(o), 1e-6));
    }
    // Half-way through step 1: T·R has turned 15° at the origin, R·T has slid half-way unturned.
    assert!(near(centre(Order::RotateFirst, 0.5), Vec3::ZERO, 1e-6));
    assert!((turned(Order::RotateFirst, 0.5) - 15.0).abs() < 1e-3);
    assert!(near(centre(Order::TranslateFirst, 0.5), t * 0.5, 1e-6));
    assert!(turned(Order::TranslateFirst, 0.5).abs() < 1e-3);
    // Half-way through step 2: T·R is half-way to t, turned 30°; R·T is on the arc, |t| from
    // the origin, turned 15°.
    assert!(near(centre(Order::RotateFirst, 1.5), t * 0.5, 1e-6));
    assert!((turned(Order::RotateFirst, 1.5) - 30.0).abs() < 1e-3);
    assert!((centre(Order::TranslateFirst, 1.5).length() - t.length()).abs() < 1e-5);
    assert!((turned(Order::TranslateFirst, 1.5) - 15.0).abs() < 1e-3);
    let mut frame = Frame::default();
    assert!(shape
        .draw(&mut frame, 0.5)
        .unwrap()
        .starts_with("Step 1 of 2"));
    assert!(shape
        .draw(&mut frame, 1.5)
        .unwrap()
        .starts_with("Step 2 of 2"));
    assert!(shape.draw(&mut frame, 2.5).unwrap_err().contains("stage"));
    assert!(shape.draw(&mut frame, f32::NAN).is_err());
    // The view is the same at every stage (the camera does not jump while it plays).
    let view = |stage: f32| {
        let mut f = Frame::default();
        shape.draw(&mut f, stage).unwrap();
        f.keep_in_view
    };
    assert!(!view(0.0).is_empty());
    assert_eq!(view(0.0), view(1.3));
}

#[test]
fn single_shape_rejects_non_finite_values_by_name() {
    let mut shape = SingleShape::new();
    let e = shape
        .set_transform(Vec3::new(0.0, f32::NAN, 0.0), Vec3::ZERO)
        .unwrap_err();
    assert!(e.contains("ty"), "{e}");
    let e = shape
        .set_transform(Vec3::ZERO, Vec3::new(0.0, 0.0, f32::INFINITY))
        .unwrap_err();
    assert!(e.contains("rz"), "{e}");
}

// Figure 2.

fn joint(figure: &HierarchyFigure, name: &str) -> usize {
    figure.joint_names().iter().position(|n| n == name).unwrap()
}

#[test]
fn selecting_a_joint_keeps_its_scale() {
    let mut figure = HierarchyFigure::new();
    let arm = joint(&figure, "upper_arm.L");
    figure
        .set_joint_scale(arm, Vec3::new(1.0, 2.0, 1.0))
        .unwrap();
    figure.select(0).unwrap();
    figure.select(arm).unwrap();
    assert_eq!(figure.joint_scale(arm).unwrap(), Vec3::new(1.0, 2.0, 1.0));
}

#[test]
fn hierarchy_validation_rules() {
    let mut figure = HierarchyFigure::new();
    let e = figure
        .set_joint_angles_deg(0, Vec3::new(f32::NAN, 0.0, 0.0))
        .unwrap_err();
    assert!(e.contains("x must be a finite number"), "{e}");
    let e = figure
        .set_joint_scale(1, Vec3::new(1.0, 99.0, 1.0))
        .unwrap_err();
    assert!(e.contains("sy must lie in [0.1, 4]"), "{e}");
    let e = figure.select(99).unwrap_err();
    assert!(e.contains("out of range") && e.contains("11 joints"), "{e}");
    assert!(figure.sample_cycle(1, 1.2).is_err());
    assert!(figure.sample_cycle(50, f32::INFINITY).is_err());
    assert!(figure.pose(f32::NAN).unwrap_err().contains("time"));
}

#[test]
fn the_figure_has_a_face_and_feet_in_front() {
    let mut figure = HierarchyFigure::new();
    figure.set_animate(false);
    let mut frame = Frame::default();
    figure.draw(&mut frame, 0.0).unwrap();
    // 11 joint boxes, then the nose and two feet: all three reach further forward (+z) than back.
    let cubes: Vec<_> = frame
        .meshes
        .iter()
        .filter(|m| m.mesh == MeshId::CUBE)
        .collect();
    let details = &cubes[11..14];
    for d in details {
        let front = d.model.transform_point3(Vec3::Z).z;
        let back = d.model.transform_point3(-Vec3::Z).z;
        assert!(front > 0.1 && back > -0.1, "front {front}, back {back}");
    }
    // Feet rest on the ground in the rest pose.
    for foot in &details[1..] {
        let sole = foot.model.transform_point3(-Vec3::Y).y;
        assert!(sole.abs() < 1e-4, "sole at {sole}");
    }
}

#[test]
fn labels_name_the_selected_joint_and_the_wrist() {
    let mut figure = HierarchyFigure::new();
    let mut frame = Frame::default();
    figure.draw(&mut frame, 0.3).unwrap();
    let wrist = frame
        .labels
        .iter()
        .find(|l| l.text == "left wrist")
        .unwrap();
    // Beside the body, with a guide line from the wrist to the name.
    assert!(!on_a_box(&frame, wrist.anchor));
    assert!(frame
        .segments_of(palette::PINK)
        .any(|(a, b)| near(a, figure.wrist(), 1e-6) && near(b, wrist.anchor, 1e-6)));
    assert!(frame.labels.iter().any(|l| l.text == "upper_arm.L"));
}

/// Whether `p`, seen from the front (along z), lies on one of the frame's boxes.
fn on_a_box(frame: &Frame, p: Vec3) -> bool {
    frame
        .meshes
        .iter()
        .filter(|m| m.mesh == MeshId::CUBE)
        .any(|m| {
            let corners = (0..8).map(|k| {
                let c = Vec3::new(
                    if k & 1 == 0 { -1.0 } else { 1.0 },
                    if k & 2 == 0 { -1.0 } else { 1.0 },
                    if k & 4 == 0 { -1.0 } else { 1.0 },
                );
                m.model.transform_point3(c)
            });
            let (lo, hi) = corners.fold(
                (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
                |(lo, hi), c| (lo.min(c), hi.max(c)),
            );
            (lo.x..=hi.x).contains(&p.x) && (lo.y..=hi.y).contains(&p.y)
        })
}

#[test]
fn the_selected_joints_name_sits_beside_the_body() {
    let mut figure = HierarchyFigure::new();
    for k in 0..figure.joint_names().len() {
        figure.select(k).unwrap();
        for t in [0.0, 0.3, 0.7] {
            let mut frame = Frame::default();
            figure.draw(&mut frame, t).unwrap();
            let name = &figure.joint_names()[k];
            for text in [name.as_str(), "left thigh", "left wrist"] {
                let label = frame.labels.iter().find(|l| l.text == text).unwrap();
                assert!(
                    !on_a_box(&frame, label.anchor),
                    "{text} at t = {t}: on the body"
                );
            }
            let label = frame.labels.iter().find(|l| &l.text == name).unwrap();
            // The label reads away from the body: leftwards on the figure's right side.
            assert_eq!(label.left, label.anchor.x < 0.0, "{name}");
        }
    }
}

/// p is a corner of the solid box: its dot is drawn over everything, else the box's faces
/// that meet there hide half of it.
#[test]
fn the_points_dot_shows_over_the_box() {
    use inbetween::figures::transforms::POINT;
    let shape = SingleShape::new();
    for stage in [0.0, 1.0, 2.0] {
        let mut frame = Frame::default();
        shape.draw(&mut frame, stage).unwrap();
        let p = shape.matrix_at(shape.order(), stage).transform_point3(POINT);
        let dot = (frame.markers.iter())
            .find(|m| Vec3::from(m.center).distance(p) < 1e-5)
            .unwrap();
        assert!(dot.size_px < 0.0, "stage {stage}: p's dot is not drawn on top");
    }
}

#[test]
fn the_direction_and_its_label_leave_the_box_at_every_stage() {
    let shape = SingleShape::new();
    for stage in [0.0, 0.5, 1.0, 1.5, 2.0] {
        let mut frame = Frame::default();
        shape.draw(&mut frame, stage).unwrap();
        let label = frame.labels.iter().find(|l| l.text == "v (w = 0)").unwrap();
        assert!(label.left, "it reads leftwards, off the arrow");
        assert!(!on_a_box(&frame, label.anchor), "stage {stage}: on the box");
        let tip = frame
            .segments_of(palette::PINK)
            .filter(|(a, _)| *a == Vec3::ZERO)
            .map(|(_, b)| b)
            .next()
            .unwrap();
        assert!(
            !on_a_box(&frame, tip),
            "stage {stage}: the arrow ends inside the box"
        );
    }
}

/// The pink point's label as the page places it: the page's camera for Figure 1, fitted to what
/// the frame declares on a canvas of `size` CSS pixels, with the label's box just right of its
/// anchor (`p (w = 1)` is about 70 px wide and 16 px tall at the page's font).
fn point_label_box(frame: &Frame, size: glam::Vec2) -> (glam::Mat4, glam::Vec2, glam::Vec2) {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let mut camera = OrbitCamera::from_view([0.5, 0.3, 0.0, 5.0, 0.6, 0.45]);
    let points: Vec<Vec3> = frame.fit_points();
    assert!(camera.fit(&points, size, FIT_PAD_PX));
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let label = frame.labels.iter().find(|l| l.text == "p (w = 1)").unwrap();
    assert!(!label.left, "p's label reads rightwards");
    let anchor = project_to_canvas(view_proj, size, label.anchor).unwrap();
    let min = anchor + glam::Vec2::new(5.0, -8.0);
    (view_proj, min, min + glam::Vec2::new(70.0, 16.0))
}

#[test]
fn the_points_label_stays_off_the_paths_at_every_stage() {
    use inbetween::camera::project_to_canvas;
    let shape = SingleShape::new();
    let t = Vec3::new(1.0, 0.5, 0.0);
    // Both centres' paths: the slide from the origin to t, and R·T's swing from t to R·t.
    let mut path: Vec<Vec3> = (0..=40).map(|k| t * (k as f32 / 40.0)).collect();
    path.extend(shape.swing_arc(48));
    for size in crate::label_clearance::CANVASES {
        for k in 0..=16 {
            let stage = k as f32 / 8.0;
            let mut frame = Frame::default();
            shape.draw(&mut frame, stage).unwrap();
            let (view_proj, lo, hi) = point_label_box(&frame, size);
            for q in &path {
                let px = project_to_canvas(view_proj, size, *q).unwrap();
                let inside = px.cmpge(lo - 2.0).all() && px.cmple(hi + 2.0).all();
                assert!(
                    !inside,
                    "{size}, stage {stage}: the path's point {q} at {px} is under p's label ({lo} to {hi})"
                );
            }
        }
    }
}

/// Each order's name sits near its box, at most 48 px above its top (and the solid box's axes),
/// at the end of its leader, at the page's camera, however the box has turned: with angle z at
/// 180° the solid box's axes point down or sideways, and its name comes down to the box instead
/// of staying where an upright box's y axis would end.
#[test]
fn each_orders_name_sits_just_above_its_box() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::box_corners;
    for angle_z in [0.0, 90.0, 180.0] {
        let mut shape = SingleShape::new();
        shape
            .set_transform(Vec3::new(1.0, 0.5, 0.0), Vec3::new(0.0, 0.0, angle_z))
            .unwrap();
        for size in crate::label_clearance::CANVASES {
            for stage in [0.0, 1.0, 2.0] {
                // As the page does: the camera fitted to the last frame, then the labels placed.
                let mut camera = OrbitCamera::from_view([0.5, 0.3, 0.0, 5.0, 0.6, 0.45]);
                let mut frame = Frame::default();
                shape.draw(&mut frame, stage).unwrap();
                assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
                shape.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                shape.draw(&mut frame, stage).unwrap();
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                for order in [Order::RotateFirst, Order::TranslateFirst] {
                    // The box's corners and, on the solid T·R box, the tips of its axes.
                    let placed = shape.matrix_at(order, stage);
                    let mut drawn = box_corners(-BOX_HALF, BOX_HALF).to_vec();
                    if order == Order::RotateFirst {
                        drawn.extend([Vec3::X, Vec3::Y, Vec3::Z].map(|a| a * 0.6));
                    }
                    let top = drawn
                        .iter()
                        .map(|c| project_to_canvas(view_proj, size, placed.transform_point3(*c)).unwrap().y)
                        .fold(f32::MAX, f32::min);
                    let label = frame.labels.iter().find(|l| l.text == order.name()).unwrap();
                    let rect = label.first_place(view_proj, size).unwrap();
                    let gap = top - rect.max().y;
                    let at = format!("angle z {angle_z}, {size}, stage {stage}, {}", order.name());
                    assert!(gap < 48.0, "{at}: the name is {gap} px above its box");
                }
            }
        }
    }
}

/// Figure 2's Try this: the shoulder at 1.45 m (the last column of upper_arm.L's W), the wrist's
/// lowest plotted point 0.877 m; a scale of 2, 2, 2 on the upper arm leaves the wrist curve as it
/// is without inheritance, and with it puts the lowest point twice as far below the shoulder,
/// at 1.45 − 2 × 0.573 = 0.303 m.
#[test]
fn the_try_this_of_figure_2_doubles_the_wrists_drop_below_the_shoulder() {
    let lowest = |f: &HierarchyFigure| {
        let rows = f.sample_cycle(121, 1.2).unwrap(); // as the page samples it
        rows.chunks(3).map(|r| r[2]).fold(f32::MAX, f32::min)
    };
    let mut figure = HierarchyFigure::new();
    let arm = joint(&figure, "upper_arm.L");
    figure.pose(0.0).unwrap();
    let shoulder = figure.world_matrix(arm).unwrap().w_axis.y;
    assert!((shoulder - 1.45).abs() < 5e-4, "{shoulder}");
    let before = lowest(&figure);
    assert!((before - 0.877).abs() < 5e-4, "{before}");
    assert!((shoulder - before - 0.573).abs() < 5e-4);
    let plotted = figure.sample_cycle(121, 1.2).unwrap();
    figure.set_joint_scale(arm, Vec3::splat(2.0)).unwrap();
    assert_eq!(figure.sample_cycle(121, 1.2).unwrap(), plotted, "without inheritance");
    figure.set_inherit_scale(true);
    let after = lowest(&figure);
    assert!((after - 0.303).abs() < 5e-4, "{after}");
    assert!((after - (shoulder - 2.0 * (shoulder - before))).abs() < 1e-3);
}

/// Height of the left wrist at `t` in the drawn figure and in the plot.
fn drawn_and_plotted(figure: &mut HierarchyFigure, t_index: usize) -> (f32, f32) {
    let samples = figure.sample_cycle(13, 1.2).unwrap();
    let t = samples[3 * t_index];
    figure.pose(t).unwrap();
    (figure.wrist().y, samples[3 * t_index + 2])
}

#[test]
fn the_plots_keep_the_walks_angles_about_x_for_the_limbs_and_yours_for_the_rest() {
    // Figure 2's caption: the walk sets the thighs', shins', upper arms' and forearms' angles
    // about x, so a limb turned about x by hand leaves the plots as they were, while the same
    // limb turned about z (or any other joint) changes them.
    let mut figure = HierarchyFigure::new();
    let base = figure.sample_cycle(13, 1.2).unwrap();
    figure.set_animate(false);
    let arm = joint(&figure, "upper_arm.L");
    figure
        .set_joint_angles_deg(arm, Vec3::new(45.0, 0.0, 0.0))
        .unwrap();
    let about_x = figure.sample_cycle(13, 1.2).unwrap();
    assert_eq!(base, about_x, "about x, the walk's angle wins in the plots");
    figure
        .set_joint_angles_deg(arm, Vec3::new(45.0, 0.0, 30.0))
        .unwrap();
    let about_z = figure.sample_cycle(13, 1.2).unwrap();
    let moved = (0..13)
        .map(|k| (about_z[3 * k + 2] - base[3 * k + 2]).abs())
        .fold(0.0, f32::max);
    assert!(moved > 0.01, "about z the wrist curve moves: {moved} m");
}

#[test]
fn the_plot_follows_the_pose_the_scales_and_the_scale_mode() {
    let mut figure = HierarchyFigure::new();
    let base = figure.sample_cycle(13, 1.2).unwrap();
    let (drawn, plotted) = drawn_and_plotted(&mut figure, 4);
    assert!((drawn - plotted).abs() < 1e-5, "{drawn} vs {plotted}");

    // Bending the chest forward moves the wrist in the plot (the arm turns with the chest).
    let chest = joint(&figure, "chest");
    figure
        .set_joint_angles_deg(chest, Vec3::new(40.0, 0.0, 0.0))
        .unwrap();
    let bent = figure.sample_cycle(13, 1.2).unwrap();
    assert!(
        (bent[2] - base[2]).abs() > 0.02,
        "{} vs {}",
        bent[2],
        base[2]
    );
    let (drawn, plotted) = drawn_and_plotted(&mut figure, 7);
    assert!((drawn - plotted).abs() < 1e-5);

    // Stretching the upper arm moves the wrist only when scale is inherited... and the drawn
    // forearm's end either way follows the plot.
    figure.set_joint_angles_deg(chest, Vec3::ZERO).unwrap();
    let arm = joint(&figure, "upper_arm.L");
    figure
        .set_joint_scale(arm, Vec3::new(1.0, 2.0, 1.0))
        .unwrap();
    let not_inherited = figure.sample_cycle(13, 1.2).unwrap();
    assert!((not_inherited[2] - base[2]).abs() < 1e-5);
    figure.set_inherit_scale(true);
    let inherited = figure.sample_cycle(13, 1.2).unwrap();
    assert_eq!(
        figure.pose(0.0).unwrap(),
        "",
        "no hint once a scale is not 1"
    );
    assert!(
        inherited[2] < base[2] - 0.2,
        "{} vs {}",
        inherited[2],
        base[2]
    );
    let (drawn, plotted) = drawn_and_plotted(&mut figure, 9);
    assert!((drawn - plotted).abs() < 1e-5);
}

// The student's exercises, through runners.

fn wrong_order(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "local_matrix" {
        // R·T instead of T·R.
        let t = Vec3::new(args[0], args[1], args[2]);
        let r =
            inbetween::transform::local_matrix(Vec3::ZERO, Vec3::new(args[3], args[4], args[5]));
        return Ok((r * Mat4::from_translation(t)).to_cols_array().to_vec());
    }
    run::direct(name, args)
}

fn local_times_parent(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "world_matrices" {
        // world = local · parent: the product in the wrong order.
        let n = args[0] as usize;
        let parents = &args[1..1 + n];
        let local: Vec<Mat4> = (0..n)
            .map(|i| Mat4::from_cols_slice(&args[2 + n + 16 * i..2 + n + 16 * (i + 1)]))
            .collect();
        let mut world = local.clone();
        for i in 0..n {
            if parents[i] >= 0.0 {
                world[i] = local[i] * world[parents[i] as usize];
            }
        }
        let mut out = vec![n as f32];
        world.iter().for_each(|m| out.extend(m.to_cols_array()));
        return Ok(out);
    }
    run::direct(name, args)
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "index out of bounds at transforms.rs:40".into(),
    ))
}

fn solved(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    // The reference answers (what a correct student's code returns).
    let mut rest = args;
    use inbetween::exercises::run::Flat;
    match name {
        "local_matrix" => {
            let t = Vec3::take(&mut rest).unwrap();
            let a = Vec3::take(&mut rest).unwrap();
            Ok(inbetween::transform::local_matrix(t, a)
                .to_cols_array()
                .to_vec())
        }
        _ => {
            let parents: Vec<f32> = Vec::take(&mut rest).unwrap();
            let local: Vec<Mat4> = Vec::take(&mut rest).unwrap();
            let parents: Vec<i32> = parents.iter().map(|&p| p as i32).collect();
            let mut world = local.clone();
            inbetween::transform::world_matrices(&parents, &local, &mut world);
            let mut out = Vec::new();
            world.put(&mut out);
            Ok(out)
        }
    }
}

fn figure_with(runner: run::Runner) -> HierarchyFigure {
    let mut figure = HierarchyFigure::new();
    figure.set_runner(runner);
    figure.set_use_exercise(true);
    figure
}

#[test]
fn stubs_say_not_done_and_the_reference_is_drawn() {
    let mut figure = figure_with(run::direct);
    let note = figure.pose(0.3).unwrap();
    if cfg!(feature = "solutions") {
        return;
    }
    assert!(
        note.contains("Not done yet: exercise 1.1 local_matrix"),
        "{note}"
    );
    assert!(
        note.contains("Not done yet: exercise 1.2 world_matrices"),
        "{note}"
    );
    let mut reference = HierarchyFigure::new();
    reference.pose(0.3).unwrap();
    assert_eq!(figure.wrist(), reference.wrist());
}

#[test]
fn a_correct_answer_matches() {
    let mut figure = figure_with(solved);
    let note = figure.pose(0.3).unwrap();
    assert!(
        note.contains("Your local_matrix matches the reference at all 11 joints")
            && note.contains("Your world_matrices matches the reference at all 11 joints"),
        "{note}"
    );
}

#[test]
fn a_wrong_local_matrix_is_named_with_its_joint_and_drawn() {
    let mut figure = figure_with(wrong_order);
    let note = figure.pose(0.3).unwrap();
    // R·T equals T·R for joints that do not turn: the first difference is a turned joint.
    assert!(
        note.contains("Your local_matrix differs at joint"),
        "{note}"
    );
    assert!(
        note.contains("yours (") && note.contains("reference ("),
        "{note}"
    );
    let mut reference = HierarchyFigure::new();
    reference.pose(0.3).unwrap();
    assert!(
        figure.wrist().distance(reference.wrist()) > 1e-3,
        "the figure shows the student's answer"
    );
}

#[test]
fn a_wrong_world_matrices_is_named_with_its_joint() {
    let mut figure = figure_with(local_times_parent);
    let note = figure.pose(0.3).unwrap();
    // Pelvis and chest only translate, and translations commute: the first difference is the
    // first rotated child, the left upper arm.
    assert!(
        note.contains("Your world_matrices differs at joint 3 (upper_arm.L)"),
        "{note}"
    );
}

#[test]
fn a_panic_is_shown_and_the_reference_drawn() {
    let mut figure = figure_with(panics);
    let note = figure.pose(0.3).unwrap();
    assert!(
        note.contains("Your exercise 1.1 local_matrix panicked: index out of bounds"),
        "{note}"
    );
    assert!(
        note.contains("exercise 1.2 world_matrices panicked"),
        "{note}"
    );
    let mut reference = HierarchyFigure::new();
    reference.pose(0.3).unwrap();
    assert_eq!(figure.wrist(), reference.wrist());
}

// Figure 3.

#[test]
fn inherited_scale_stretches_and_shears_the_child() {
    use inbetween::figures::transforms::ScaleComparison;
    let mut comparison = ScaleComparison::new();
    let mut frame = Frame::default();
    let note = comparison.draw(&mut frame).unwrap();
    // The upper arm's outline is drawn in a colour that stands out on its shirt: at least 0.8
    // apart in linear RGB (a teal outline is 0.46 from the shirt's blue).
    use inbetween::figures::transforms::ARM_OUTLINE;
    let (hierarchy, _, shapes) = inbetween::transform::simple_human();
    let shirt = shapes[hierarchy.find("upper_arm.L").unwrap()].color;
    let rgb = |c: [f32; 4]| Vec3::new(c[0], c[1], c[2]);
    assert!(frame.strokes.iter().any(|s| rgb(s.color) == ARM_OUTLINE));
    let apart = ARM_OUTLINE.distance(shirt);
    assert!(apart >= 0.8, "outline {ARM_OUTLINE} on shirt {shirt}: {apart} apart");
    let (length, angle) = comparison.forearm_shape(0);
    assert!((length - 0.28).abs() < 1e-4 && (angle - 90.0).abs() < 1e-3);
    let (length, angle) = comparison.forearm_shape(1);
    assert!(length > 0.3, "the forearm grows with its parent: {length}");
    assert!((angle - 90.0).abs() > 5.0, "and is sheared: {angle}");
    assert!(
        note.contains("scale not inherited: the forearm is 0.280 m long"),
        "{note}"
    );
    // Uniform scale and a straight elbow: no shear, only growth.
    comparison.set_upper_arm_scale(Vec3::splat(2.0)).unwrap();
    comparison.draw(&mut frame).unwrap();
    assert!((comparison.forearm_shape(1).1 - 90.0).abs() < 1e-3);
    assert!(comparison
        .set_upper_arm_scale(Vec3::new(0.0, 1.0, 1.0))
        .is_err());
    assert!(comparison
        .set_forearm_angles_deg(Vec3::new(0.0, f32::NAN, 0.0))
        .is_err());
}

#[test]
fn inheriting_unit_scales_says_why_nothing_changes() {
    let mut figure = HierarchyFigure::new();
    figure.set_inherit_scale(true);
    let note = figure.pose(0.0).unwrap();
    assert!(note.contains("every scale is 1"), "{note}");
}

/// Rotations multiplied in the reverse order (R_z R_y R_x): at the walk, which turns the limbs
/// about x only, every joint matches, and only the probes can tell.
fn reversed_rotations(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "local_matrix" {
        let t = Vec3::new(args[0], args[1], args[2]);
        let m = Mat4::from_translation(t)
            * Mat4::from_rotation_z(args[5])
            * Mat4::from_rotation_y(args[4])
            * Mat4::from_rotation_x(args[3]);
        return Ok(m.to_cols_array().to_vec());
    }
    solved(name, args)
}

/// World matrices that multiply by the parent's local matrix instead of its world matrix:
/// right for a root's children, wrong deeper down.
fn parent_local(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "world_matrices" {
        let n = args[0] as usize;
        let parents = &args[1..1 + n];
        let local: Vec<Mat4> = (0..n)
            .map(|i| Mat4::from_cols_slice(&args[2 + n + 16 * i..2 + n + 16 * (i + 1)]))
            .collect();
        let world: Vec<Mat4> = (0..n)
            .map(|i| {
                if parents[i] >= 0.0 {
                    local[parents[i] as usize] * local[i]
                } else {
                    local[i]
                }
            })
            .collect();
        let mut out = vec![n as f32];
        world.iter().for_each(|m| out.extend(m.to_cols_array()));
        return Ok(out);
    }
    solved(name, args)
}

#[test]
fn probes_catch_what_the_walk_cannot() {
    let mut figure = figure_with(reversed_rotations);
    let note = figure.pose(0.3).unwrap();
    assert!(
        note.contains("Your local_matrix matches the reference at all 11 joints"),
        "{note}"
    );
    assert!(
        note.contains("Beyond this pose, your local_matrix differs at 3 of 3 more inputs"),
        "{note}"
    );
    assert!(
        note.contains(
            "Your local_matrix differs at t = (1, 2, 3), angles (30°, 40°, 50°): yours ("
        ),
        "{note}"
    );
    let mut figure = figure_with(parent_local);
    let note = figure.pose(0.3).unwrap();
    assert!(
        note.contains("your world_matrices differs at 2 of 2 more inputs")
            || note.contains(
                "your world_matrices differs at 1 of 2 more inputs (a chain of four joints)"
            ),
        "{note}"
    );
    assert!(
        note.contains("of a chain of four joints: yours ("),
        "{note}"
    );
    let mut figure = figure_with(solved);
    let note = figure.pose(0.3).unwrap();
    assert!(
        note.contains("your local_matrix also matches at 3 more inputs")
            && note.contains("your world_matrices also matches at 2 more inputs"),
        "{note}"
    );
}

/// Figure 3 from the side: the left forearm's outline is a rectangle (90°) without inherited
/// scale and a parallelogram with it, whose angle the note and the label give.
#[test]
fn the_inherited_forearm_is_a_parallelogram() {
    use inbetween::figures::transforms::ScaleComparison;
    let mut comparison = ScaleComparison::new();
    let mut frame = Frame::default();
    let note = comparison.draw(&mut frame).unwrap();
    fn corner(comparison: &ScaleComparison, k: usize) -> f32 {
        let c = comparison.forearm_outline(k);
        (c[1] - c[2]).angle_between(c[3] - c[2]).to_degrees()
    }
    assert!((corner(&comparison, 0) - 90.0).abs() < 0.01);
    let sheared = corner(&comparison, 1);
    assert!((sheared - 90.0).abs() > 10.0, "{sheared}");
    // The outline lies in a plane x = const (what a side view along x shows undistorted).
    for k in 0..2 {
        let c = comparison.forearm_outline(k);
        assert!(c.iter().all(|p| (p.x - c[0].x).abs() < 1e-5), "{c:?}");
    }
    let (_, from_note) = comparison.forearm_shape(1);
    assert!(
        (from_note - sheared).abs() < 0.01 || (from_note - (180.0 - sheared)).abs() < 0.01,
        "{from_note} {sheared}"
    );
    let label = format!("{:.0}°", sheared);
    assert_eq!(label, "64°", "the caption's angle");
    assert!(frame.labels.iter().any(|l| l.text == label), "{label}");
    assert!(frame.labels.iter().any(|l| l.text == "90°"));
    assert!(note.contains("scale inherited"), "{note}");
    // The copies stand one behind the other along z, both in view.
    assert!(!frame.keep_in_view.is_empty());
    // Uniform scale: square corners again, as the Try this says.
    comparison.set_upper_arm_scale(Vec3::splat(2.0)).unwrap();
    comparison.draw(&mut frame).unwrap();
    assert!((corner(&comparison, 1) - 90.0).abs() < 0.01);
    // An unbent forearm under the non-uniform stretch: square too.
    comparison
        .set_upper_arm_scale(Vec3::new(1.0, 2.0, 1.0))
        .unwrap();
    comparison.set_forearm_angles_deg(Vec3::ZERO).unwrap();
    comparison.draw(&mut frame).unwrap();
    assert!((corner(&comparison, 1) - 90.0).abs() < 0.01);
}

/// The label at each forearm's marked corner and the note give the same angle, whatever the
/// sliders: with the elbow turned about y and z as well as x, the box's other sides shear too,
/// and an angle measured at another corner than the marked one disagrees with the label.
#[test]
fn the_corner_label_and_the_note_give_the_same_angle() {
    use inbetween::figures::transforms::ScaleComparison;
    for (scale, angles) in [
        (Vec3::new(1.0, 2.0, 1.0), Vec3::new(-70.0, 0.0, 0.0)),
        (Vec3::new(2.42, 0.8, 2.42), Vec3::new(105.0, -109.0, -109.0)),
        (Vec3::new(0.5, 3.0, 1.5), Vec3::new(-40.0, 60.0, 30.0)),
    ] {
        let mut comparison = ScaleComparison::new();
        comparison.set_upper_arm_scale(scale).unwrap();
        comparison.set_forearm_angles_deg(angles).unwrap();
        let mut frame = Frame::default();
        let note = comparison.draw(&mut frame).unwrap();
        let shown: Vec<&str> = frame
            .labels
            .iter()
            .filter(|l| l.text.ends_with('°'))
            .map(|l| l.text.as_str())
            .collect();
        for k in 0..2 {
            let c = comparison.forearm_outline(k);
            let at_corner = (c[1] - c[2]).angle_between(c[3] - c[2]).to_degrees();
            let (_, angle) = comparison.forearm_shape(k);
            assert!((angle - at_corner).abs() < 1e-3, "{angle} {at_corner}");
            assert_eq!(shown[k], format!("{angle:.0}°"), "{scale} {angles}");
            let in_note = format!(
                "the marked corner of its outline {}°",
                run::format_number(angle)
            );
            assert!(note.contains(&in_note), "{in_note:?} in {note}");
        }
    }
}

/// Figure 3 is seen from the side, where the shear shows: a drag pans it, keeping the two
/// figures as far apart on the canvas, where an orbit would turn the forearms' outlines edge-on.
#[test]
fn the_scale_comparison_pans() {
    use inbetween::figures::transforms::ScaleComparison;
    let mut comparison = ScaleComparison::new();
    let mut frame = Frame::default();
    comparison.draw(&mut frame).unwrap();
    let apart = [0, 1].map(|k| ScaleComparison::placement(k).w_axis.truncate() + Vec3::Y);
    let view = [0.0, 1.0, 0.0, 3.6, std::f32::consts::FRAC_PI_2, 0.12];
    flat::assert_drag_pans(&frame, view, glam::Vec2::new(650.0, 420.0), apart);
}

/// Figure 2 with the page test's pose (forearm.L selected, turned -26°, -109°, -109°, scaled 2.42
/// with inherited scale off): the forearm's bone runs on top from its pivot to the marked wrist,
/// and the selected box's twelve edges are drawn on top, so both show where the body hides them.
#[test]
fn the_wrist_and_the_selected_box_show_through_the_body() {
    use inbetween::draw::ON_TOP;
    let mut figure = HierarchyFigure::new();
    let forearm = joint(&figure, "forearm.L");
    figure.select(forearm).unwrap();
    figure
        .set_joint_angles_deg(forearm, Vec3::new(-26.0, -109.0, -109.0))
        .unwrap();
    figure.set_joint_scale(forearm, Vec3::splat(2.42)).unwrap();
    let mut frame = Frame::default();
    figure.draw(&mut frame, 0.44).unwrap();
    let on_top: Vec<_> = frame.strokes.iter().filter(|s| s.depth_bias == ON_TOP).collect();
    let pivot = figure.world_matrix(forearm).unwrap().w_axis.truncate();
    let wrist = figure.wrist();
    assert!(
        on_top.iter().any(|s| {
            let (a, b) = (Vec3::from(s.a), Vec3::from(s.b));
            near(a, pivot, 1e-4) && near(b, wrist, 1e-4)
        }),
        "no bone from the forearm's pivot {pivot} to the wrist {wrist}"
    );
    // Besides the skeleton's dark bones and the selected joint's axes: the box's edges, in the
    // colour of one of the boxes.
    let rgb = |c: [f32; 4]| Vec3::new(c[0], c[1], c[2]);
    let axes = [palette::X_AXIS, palette::Y_AXIS, palette::Z_AXIS];
    let edges: Vec<Vec3> = on_top
        .iter()
        .map(|s| rgb(s.color))
        .filter(|&c| c != palette::KEY && !axes.contains(&c))
        .collect();
    let selected = edges.first().copied();
    assert!(frame.meshes.iter().any(|m| Some(m.color.truncate()) == selected));
    let edges = edges.iter().filter(|&&c| Some(c) == selected).count();
    assert_eq!(edges, 12, "the selected box's edges on top ({selected:?})");
}

/// Figure 2: the selected joint's pivot lies inside the body's boxes, so its axes' shafts are
/// drawn over them (else only their letters show).
#[test]
fn the_selected_joints_axes_show_over_the_body() {
    use inbetween::draw::ON_TOP;
    let mut figure = HierarchyFigure::new();
    let forearm = joint(&figure, "forearm.L");
    figure.select(forearm).unwrap();
    let mut frame = Frame::default();
    figure.draw(&mut frame, 0.3).unwrap();
    let pivot = figure.world_matrix(forearm).unwrap().w_axis.truncate();
    let shafts: Vec<_> = frame
        .strokes
        .iter()
        .filter(|s| Vec3::from(s.a).distance(pivot) < 1e-5)
        .filter(|s| {
            [palette::X_AXIS, palette::Y_AXIS, palette::Z_AXIS]
                .iter()
                .any(|c| s.color[..3] == c.to_array()[..])
        })
        .collect();
    assert!(shafts.len() >= 3, "{} shafts", shafts.len());
    assert!(shafts.iter().all(|s| s.depth_bias == ON_TOP));
}
