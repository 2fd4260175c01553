//! Lesson 07: its figures' labels keep clear of what they name (see main.rs).

use super::*;

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
            || text == "a"
            || text == "b"
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

/// Figure 4 (the aim) with `target` and a cone of `cone` degrees at time `t`, drawn at its page
/// camera (lessons/07-inverse-kinematics/lesson.js: yaw −0.95, pitch 0.15, fitted) on a canvas of
/// `size`, as the page draws it: the scene, the frame checked and its camera.
fn aim_drawn(
    target: Vec3,
    cone: f32,
    t: f32,
    size: Vec2,
) -> (inbetween::figures::ik::AimFigure, Frame, OrbitCamera) {
    aim_drawn_orbited(target, cone, t, size, Vec2::ZERO)
}

/// [`aim_drawn`] with the page camera's yaw and pitch moved by `orbit` (radians).
fn aim_drawn_orbited(
    target: Vec3,
    cone: f32,
    t: f32,
    size: Vec2,
    orbit: Vec2,
) -> (inbetween::figures::ik::AimFigure, Frame, OrbitCamera) {
    let mut scene = inbetween::figures::ik::AimFigure::new();
    scene.set_target(target).unwrap();
    scene.set_max_angle_deg(cone).unwrap();
    let (frame, camera) = drawn_for_view(
        &mut scene,
        [0.0, 1.5, 0.0, 5.2, -0.95 + orbit.x, 0.15 + orbit.y],
        size,
        |fig, out| {
            fig.draw(out, t).unwrap();
        },
        |fig, cam, px| fig.set_view(cam, px.x, px.y),
    );
    (scene, frame, camera)
}

#[test]
fn lesson_07_aim_labels_keep_off_the_body_and_the_lines() {
    // Figure 4 at its page camera (lessons/07-inverse-kinematics/lesson.js: yaw −0.95, pitch
    // 0.15, fitted), both canvases, over the target's loop: at the page's start, with the target
    // behind the body (the head stops at the cone's rim and a red arc gives the miss), and with
    // a wide cone that lets the head look down through its body. "target", "forward" and
    // "misses …°" (the target's name crossed the dashed line to it with the target behind) are
    // shown where the figure put them, off every dot and line, and off the body's and the
    // head's boxes on the canvas (a label on the body's edge reads as part of it), and the miss's
    // leader back to its arc does not cross them either (a red line over the dark body reads as
    // part of it). As on the page, the figure places them for the view of the frame before.
    use inbetween::draw::layout::leader;
    use inbetween::draw::MeshId;
    use inbetween::figures::palette;
    let mut failures = Vec::new();
    let mut misses = 0;
    for (target, cone) in [
        (Vec3::new(1.2, 1.9, 0.4), 70.0),
        (Vec3::new(1.2, 1.9, 1.0), 70.0),
        (Vec3::new(-0.7, 1.0, -1.2), 70.0),
        (Vec3::new(0.0, 1.9, -1.2), 40.0),
        (Vec3::new(-0.7, 1.0, -0.7), 142.0),
        (Vec3::new(1.2, 1.9, -1.2), 180.0),
    ] {
        for k in 0..8 {
            let t = k as f32;
            for size in CANVASES {
                let (_, frame, camera) = aim_drawn(target, cone, t, size);
                let name = format!("07 aim, target {target}, cone {cone}°, t {t}");
                let placed: Vec<usize> = (0..frame.labels.len())
                    .filter(|&i| {
                        let text = &frame.labels[i].text;
                        text == "target" || text == "forward" || text.starts_with("misses ")
                    })
                    .collect();
                misses += placed.len() - 2;
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &placed, 0.0)
                }));
                // The body (grey box) and the head (brown ball): their boxes on the canvas.
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let solids: Vec<Rect> = frame
                    .meshes
                    .iter()
                    .filter(|m| {
                        (m.mesh == MeshId::CUBE && m.color.truncate() == palette::GREY)
                            || (m.mesh == MeshId::SPHERE && m.color.truncate() == palette::BROWN)
                    })
                    .map(|m| {
                        let corners = inbetween::draw::box_corners(Vec3::splat(-1.0), Vec3::ONE)
                            .map(|c| {
                                project_to_canvas(view_proj, size, m.model.transform_point3(c))
                                    .unwrap()
                            });
                        let lo = corners.iter().copied().fold(Vec2::MAX, Vec2::min);
                        let hi = corners.iter().copied().fold(Vec2::MIN, Vec2::max);
                        Rect {
                            min: lo,
                            size: hi - lo,
                        }
                    })
                    .collect();
                assert_eq!(solids.len(), 2, "{name}: the body and the head");
                for (l, b, p) in layout(&frame, &camera, size) {
                    let text = &l.text;
                    let named = text == "target" || text == "forward" || text.starts_with("misses ");
                    if !p.shown || !named {
                        continue;
                    }
                    let rect = Rect {
                        min: p.top_left,
                        size: b.size,
                    };
                    if solids.iter().any(|b| b.overlaps(&rect, 0.0)) {
                        failures.push(format!(
                            "{name} on {size}: {text:?} at {:?} over the body or the head",
                            rect.min
                        ));
                    }
                    let Some(end) = leader(rect, l.dot_px, p.leader_to.is_some())
                        .filter(|_| text.starts_with("misses "))
                    else {
                        continue;
                    };
                    if solids.iter().any(|b| enters(l.dot_px, end, *b)) {
                        failures.push(format!(
                            "{name} on {size}: {text:?}'s leader from {} to {end} crosses the \
                             body or the head",
                            l.dot_px
                        ));
                    }
                }
            }
        }
    }
    // The targets behind the body are missed for most of the loop: their labels were checked.
    assert!(misses >= 24, "only {misses} frames show a miss");
    assert_none_failed(&failures);
}

#[test]
fn lesson_07_hinge_figure_labels_keep_off_the_arcs_at_every_segment_count() {
    // Figure 3 at its page camera and orbited round it (to the front, to the front left, from
    // above), both
    // canvases, at the page's target with every number of
    // segments the slider gives, each kind of joint limit, and 10 and 40 iterations: the
    // targets' names, the misses' lengths and the chains' names are shown where the figure put
    // them and keep 1.5 px off every dot's and line's edge, at every point of each line (with
    // hinges, one arc per joint crowds the targets as the chains reach for them; a name that
    // touches one reads as part of it). As on the page, the figure places them for the view of
    // the frame before.
    use inbetween::figures::ik::{IkFigure, SOLVERS};
    let placed = |text: &str| {
        SOLVERS.contains(&text)
            || text.ends_with(" target")
            || text.ends_with(" mm short")
            || text.starts_with("d = ")
            || text.starts_with("α")
    };
    let mut failures = Vec::new();
    for segments in 2..=8 {
        for limits in ["hinges (bend one way)", "cones (40°)", "none"] {
            for iterations in [10.0, 40.0] {
                let mut scene = IkFigure::new();
                scene.set_segments(segments as f32).unwrap();
                scene.set_limits(limits).unwrap();
                scene.set_iterations(iterations).unwrap();
                scene.set_target(Vec3::new(0.55, 0.65, 0.15)).unwrap();
                for (size, (yaw, pitch)) in CANVASES
                    .iter()
                    .flat_map(|&size| [(0.5, 0.3), (-0.54, 0.64), (0.0, 0.64)].map(|v| (size, v)))
                {
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        [0.25, 0.45, 0.0, 4.3, yaw, pitch],
                        size,
                        |fig, out| {
                            fig.draw(out).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!(
                        "07 Fig 3, {segments} segments, {limits}, {iterations} iterations, \
                         orbit ({yaw}, {pitch})"
                    );
                    let shown: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| placed(&frame.labels[i].text))
                        .collect();
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &shown, 1.5)
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}


#[test]
fn lesson_07_miss_labels_sit_by_their_line_or_lead_to_it() {
    // Figures 1 to 3 at their page cameras, both canvases, as on the page (placed for the view of
    // the frame before, then laid out with the page's leader rule, draw::layout::leader): each
    // solver's miss ("143.2 mm short") is named by a label whose box comes within
    // draw::layout::LEADER_PX of its dashed line from the chain's end to the target, or whose
    // leader line starts on that line. A label anchored off the line would lead to empty space.
    use inbetween::draw::layout::{leader, LEADER_PX};
    use inbetween::figures::ik::{IkFigure, ROOTS_X};
    use inbetween::figures::palette;
    // Each chain's colour, as the caption names them: two-joint IK, CCD and FABRIK.
    let colors = [palette::BLUE, palette::ORANGE, palette::TEAL].map(palette::css);
    let figures = [
        ([0.25, 0.45, 0.0, 4.3, 0.1, 0.25], 2.0, "none"),
        ([0.25, 0.45, 0.0, 4.3, 0.1, 0.25], 3.0, "none"),
        ([0.25, 0.45, 0.0, 4.3, 0.5, 0.3], 2.0, "hinges (bend one way)"),
        ([0.25, 0.45, 0.0, 4.3, 0.5, 0.3], 2.0, "cones (40°)"),
    ];
    let (mut failures, mut misses, mut led) = (Vec::new(), 0, 0);
    for (view, segments, limits) in figures {
        for x in [-1.5, -0.8, 0.0, 0.55, 1.5] {
            for y in [-1.5, -0.5, 0.65, 1.5] {
                for z in [-0.8, 0.15, 0.8] {
                    let target = Vec3::new(x, y, z);
                    let mut scene = IkFigure::new();
                    scene.set_segments(segments).unwrap();
                    scene.set_limits(limits).unwrap();
                    scene.set_target(target).unwrap();
                    for size in CANVASES {
                        let (frame, camera) = drawn_for_view(
                            &mut scene,
                            view,
                            size,
                            |s, f| {
                                s.draw(f).unwrap();
                            },
                            |s, c, size| s.set_view(c, size.x, size.y),
                        );
                        let view_proj = camera.projection(size.x / size.y) * camera.view();
                        let placed = layout(&frame, &camera, size);
                        let results = scene.results().unwrap();
                        for k in scene.shown_solvers() {
                            let Some(r) = results[k].filter(|r| !r.reached) else {
                                continue;
                            };
                            let end = *scene.chain(k).unwrap().last().unwrap();
                            let goal = target + Vec3::new(ROOTS_X[k], 0.0, 0.0);
                            let (Some(a), Some(b)) = (
                                project_to_canvas(view_proj, size, end),
                                project_to_canvas(view_proj, size, goal),
                            ) else {
                                continue;
                            };
                            let text = format!("{:.1} mm short", r.error * 1000.0);
                            let Some((l, bx, p)) = placed
                                .iter()
                                .find(|(l, _, p)| {
                                    l.text == text && l.css_color == colors[k] && p.shown
                                })
                            else {
                                continue;
                            };
                            misses += 1;
                            let rect = Rect {
                                min: p.top_left,
                                size: bx.size,
                            };
                            let on_line = |q: Vec2| {
                                let t = ((q - a).dot(b - a) / (b - a).length_squared().max(1e-6))
                                    .clamp(0.0, 1.0);
                                a.lerp(b, t).distance(q)
                            };
                            let gap = (0..=64)
                                .map(|i| {
                                    let q = a.lerp(b, i as f32 / 64.0);
                                    rect.nearest(q).distance(q)
                                })
                                .fold(f32::MAX, f32::min);
                            let name = format!(
                                "07 {segments} segments, {limits}, target {target} on {size}: \
                                 {text:?}"
                            );
                            match leader(rect, l.dot_px, p.leader_to.is_some()) {
                                Some(_) => {
                                    led += 1;
                                    if on_line(l.dot_px) > 1.0 {
                                        failures.push(format!(
                                            "{name}: its leader starts {} px off its line",
                                            on_line(l.dot_px)
                                        ));
                                    }
                                }
                                None if gap > LEADER_PX + 0.5 => failures.push(format!(
                                    "{name}: {gap} px from its line, with no leader"
                                )),
                                None => {}
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(misses > 100 && led > 0, "{misses} misses, {led} with a leader");
    assert_none_failed(&failures);
}

#[test]
fn lesson_07_sides_a_and_b_labels_sit_beside_their_sides() {
    // Figures 1 and 3 at their page cameras, both canvases, two segments, Figure 3 with each
    // kind of joint limit, at the page's start: the labels of the two-joint chain's sides a and
    // b each lie within 12 px of the side they name (the pole's dot and line sit near b).
    use inbetween::figures::ik::IkFigure;
    let figures = [
        ([0.25, 0.45, 0.0, 4.3, 0.1, 0.25], "none"),
        ([0.25, 0.45, 0.0, 4.3, 0.5, 0.3], "hinges (bend one way)"),
        ([0.25, 0.45, 0.0, 4.3, 0.5, 0.3], "cones (40°)"),
    ];
    let mut failures = Vec::new();
    for (view, limits) in figures {
        let mut scene = IkFigure::new();
        scene.set_limits(limits).unwrap();
        scene.set_target(Vec3::new(0.55, 0.65, 0.15)).unwrap();
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
            let chain = scene.chain(0).unwrap();
            for (text, p, q) in [("a", chain[0], chain[1]), ("b", chain[1], chain[2])] {
                let (p, q) = (at(p), at(q));
                let boxes: Vec<Rect> = label_boxes(&frame, &camera, size)
                    .into_iter()
                    .filter(|(t, _)| t == text)
                    .map(|(_, rect)| rect)
                    .collect();
                let name = format!("07 {limits}, side {text} on {size}");
                assert_eq!(boxes.len(), 1, "{name}");
                let gap = (0..=64)
                    .map(|k| {
                        let s = p.lerp(q, k as f32 / 64.0);
                        boxes[0].nearest(s).distance(s)
                    })
                    .fold(f32::MAX, f32::min);
                if gap > 12.0 {
                    failures.push(format!("{name}: {gap} px from its side"));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

/// Whether the segments `a`–`b` and `c`–`d` on the canvas cross (each one's ends on strictly
/// opposite sides of the other's line).
fn segments_cross(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> bool {
    let side = |p: Vec2, q: Vec2, r: Vec2| (q - p).perp_dot(r - p);
    side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0
}

/// The leader lines the page draws for the frame's labels whose text passes `from` (each from
/// the point its label names to its box, draw::layout::leader) that run into the box of a shown
/// label whose text passes `over`: one message each.
fn leaders_into(
    name: &str,
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
    from: impl Fn(&str) -> bool,
    over: impl Fn(&str) -> bool,
) -> Vec<String> {
    use inbetween::draw::layout::leader;
    let placed = layout(frame, camera, size);
    let rect = |b: &LabelBox, p: &Placement| Rect {
        min: p.top_left,
        size: b.size,
    };
    let mut out = Vec::new();
    for (l, b, p) in placed.iter().filter(|(l, _, p)| p.shown && from(&l.text)) {
        let Some(end) = leader(rect(b, p), l.dot_px, p.leader_to.is_some()) else {
            continue;
        };
        for (o, ob, op) in placed.iter().filter(|(o, _, op)| op.shown && over(&o.text)) {
            if o.text != l.text && enters(l.dot_px, end, rect(ob, op)) {
                out.push(format!(
                    "{name} on {size}: {:?}'s leader from {} runs into {:?} at {:?}",
                    l.text, l.dot_px, o.text, op.top_left
                ));
            }
        }
    }
    out
}

#[test]
fn lesson_07_miss_and_side_d_leaders_keep_off_each_others_labels() {
    // Figure 1 at its page camera and orbited (as the page test's drag does), both canvases,
    // two segments, pole 0° and 90°, targets all round the reach and past it: the leader line
    // of the two-joint chain's miss ("128.3 mm short") runs into no box of side d's label
    // ("d = 1.128 m"), nor side d's leader into the miss's. Both name points on the same line
    // from the root to the target; a leader across the other label reads as a strike-through.
    // As on the page, the figure places them for the view of the frame before. At the page
    // test's target (x = −0.91, y = 0.65) every case passes; over the sweep at most 5 % may
    // fail, where the miss and d crowd the canvas's edge and no place near either is clear.
    use inbetween::figures::ik::IkFigure;
    let miss = |t: &str| t.ends_with(" mm short");
    let side_d = |t: &str| t == "d" || t.starts_with("d = ");
    let (mut failures, mut at_slider, mut cases) = (Vec::new(), Vec::new(), 0);
    for x in [-1.5, -1.2, -0.91, -0.6, 0.0, 0.55, 0.9, 1.5] {
        for y in [-1.2, -0.3, 0.0, 0.3, 0.65, 1.2] {
            for z in [-0.6, 0.15, 0.6] {
                for pole in [0.0, 90.0] {
                    let mut scene = IkFigure::new();
                    scene.set_target(Vec3::new(x, y, z)).unwrap();
                    scene.set_pole_angle_deg(pole).unwrap();
                    scene.set_iterations(10.0).unwrap();
                    for (yaw, pitch) in [(0.1, 0.25), (-0.9, 0.55), (0.6, 0.6)] {
                        for size in CANVASES {
                            let (frame, camera) = drawn_for_view(
                                &mut scene,
                                [0.25, 0.45, 0.0, 4.3, yaw, pitch],
                                size,
                                |s, f| {
                                    s.draw(f).unwrap();
                                },
                                |s, c, size| s.set_view(c, size.x, size.y),
                            );
                            cases += 1;
                            let name = format!(
                                "07 Fig 1, target ({x}, {y}, {z}), pole {pole}°, orbit ({yaw}, {pitch})"
                            );
                            let mut found =
                                leaders_into(&name, &frame, &camera, size, miss, side_d);
                            found.extend(leaders_into(&name, &frame, &camera, size, side_d, miss));
                            if (x, y, z) == (-0.91, 0.65, 0.15) {
                                at_slider.extend(found.iter().cloned());
                            }
                            failures.extend(found);
                        }
                    }
                }
            }
        }
    }
    assert_none_failed(&at_slider);
    assert!(
        failures.len() * 100 <= 5 * cases,
        "{} of {cases} cases fail (at most 5 % may), e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

#[test]
fn lesson_07_aim_miss_leader_keeps_off_the_dashed_line() {
    // Figure 4 at its page camera, both canvases, over the target's loop with the target behind
    // the body and the cone at 40° and 70°: where "misses …°" has a leader line back to the
    // middle of its arc, that leader does not cross the red dashed line from the head to the
    // target (it would point at the wrong line). As on the page, the figure places it for the
    // view of the frame before.
    use inbetween::draw::layout::leader;
    // The head's centre (src/figures/ik.rs, HEAD), where the dashed line starts.
    let head = Vec3::new(0.0, 1.6, 0.0);
    let mut failures = Vec::new();
    let mut misses = 0;
    for (target, cone) in [
        (Vec3::new(-0.7, 1.0, -1.2), 70.0),
        (Vec3::new(0.0, 1.9, -1.2), 40.0),
        (Vec3::new(0.0, 1.5, -1.2), 70.0),
        (Vec3::new(0.7, 1.0, -1.2), 70.0),
        (Vec3::new(0.0, 0.6, -1.2), 70.0),
    ] {
        for k in 0..16 {
            let t = 0.5 * k as f32;
            for size in CANVASES {
                let (scene, frame, camera) = aim_drawn(target, cone, t, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                let (h, g) = (at(head), at(scene.target_at(t)));
                for (l, b, p) in layout(&frame, &camera, size) {
                    if !p.shown || !l.text.starts_with("misses ") {
                        continue;
                    }
                    misses += 1;
                    let rect = Rect {
                        min: p.top_left,
                        size: b.size,
                    };
                    let Some(end) = leader(rect, l.dot_px, p.leader_to.is_some()) else {
                        continue;
                    };
                    if segments_cross(l.dot_px, end, h, g) {
                        failures.push(format!(
                            "07 aim, target {target}, cone {cone}°, t {t} on {size}: {:?}'s \
                             leader from {} to {end} crosses the dashed line from {h} to {g}",
                            l.text, l.dot_px
                        ));
                    }
                }
            }
        }
    }
    assert!(misses >= 40, "only {misses} frames show a miss");
    assert_none_failed(&failures);
}

#[test]
fn lesson_07_target_names_sit_nearest_their_own_target() {
    // Figures 1 to 3 at their page cameras and orbited as the page test's drag orbits them (yaw
    // down by 0.2 of the canvas's width and pitch up by 0.1 of its height, at 0.008 rad a pixel:
    // (−1.04, +0.34) on the 650 px canvas, (−1.22, +0.34) on the 760 px one), on both canvases,
    // over each figure's controls (segments, joint limits, 10 and 40 iterations) and targets all round
    // the reach: each target's name ("CCD target") is shown where the figure put it, off every
    // dot and line, and its box comes nearer its own target's dot than any other target's (a name
    // nearer a neighbour's target reads as naming that one). As on the page, the figure places it
    // for the view of the frame before. At the page's start target (where the page test's reset
    // puts it back) and the targets the quiz's "show me" buttons set, every case passes; over
    // the sweep at most 1 in 1000 cases may fail, where an orbited view lines the targets up
    // beside the canvas's edge and no place by the target is both nearer it and clear.
    use inbetween::figures::ik::{IkFigure, ROOTS_X, SOLVERS};
    let figures = [
        // Each figure's view, its numbers of segments, and its joint limits with pole angles.
        (
            "Fig 1",
            (0.1, 0.25),
            &[2.0][..],
            &[("none", 0.0), ("none", 90.0)][..],
        ),
        ("Fig 2", (0.1, 0.25), &[3.0, 7.0][..], &[("none", 0.0)][..]),
        (
            "Fig 3",
            (0.5, 0.3),
            &[2.0, 7.0][..],
            &[
                ("hinges (bend one way)", 0.0),
                ("cones (40°)", 0.0),
                ("none", 0.0),
            ][..],
        ),
    ];
    // The page's start, and the targets its quiz's "show me" buttons set.
    let page_targets = [
        Vec3::new(0.55, 0.65, 0.15),
        Vec3::new(0.48, 0.64, 0.0),
        Vec3::new(0.05, 0.05, 0.0),
    ];
    let mut targets = page_targets.to_vec();
    for x in [-0.9, -0.4, 0.0, 0.4, 0.9] {
        for y in [-0.6, 0.0, 0.5, 1.0] {
            for z in [-0.5, 0.15, 0.5] {
                targets.push(Vec3::new(x, y, z));
            }
        }
    }
    let (mut failures, mut at_start, mut cases) = (Vec::new(), Vec::new(), 0);
    for (figure, (yaw, pitch), segment_counts, settings) in figures {
        for &segments in segment_counts {
            for &(limits, pole) in settings {
                for iterations in [10.0, 40.0] {
                    for &target in &targets {
                        let mut scene = IkFigure::new();
                        scene.set_pole_angle_deg(pole).unwrap();
                        scene.set_segments(segments).unwrap();
                        scene.set_limits(limits).unwrap();
                        scene.set_iterations(iterations).unwrap();
                        scene.set_target(target).unwrap();
                        for size in CANVASES {
                            let drag = 0.008 * Vec2::new(-0.2 * size.x, 0.1 * size.y);
                            for orbit in [Vec2::ZERO, drag] {
                                let view = [0.25, 0.45, 0.0, 4.3, yaw + orbit.x, pitch + orbit.y];
                                let (frame, camera) = drawn_for_view(
                                    &mut scene,
                                    view,
                                    size,
                                    |s, f| {
                                        s.draw(f).unwrap();
                                    },
                                    |s, c, size| s.set_view(c, size.x, size.y),
                                );
                                cases += 1;
                                let name = format!(
                                    "07 {figure}, {segments} segments, {limits}, pole {pole}°, \
                                     {iterations} iterations, target {target}, view ({:.2}, {:.2})",
                                    view[4], view[5]
                                );
                                let view_proj = camera.projection(size.x / size.y) * camera.view();
                                let dots: Vec<Option<Vec2>> = scene
                                    .shown_solvers()
                                    .map(|k| {
                                        let goal = target + Vec3::new(ROOTS_X[k], 0.0, 0.0);
                                        project_to_canvas(view_proj, size, goal)
                                    })
                                    .collect();
                                let names: Vec<String> = scene
                                    .shown_solvers()
                                    .map(|k| format!("{} target", SOLVERS[k]))
                                    .collect();
                                let shown: Vec<usize> = (0..frame.labels.len())
                                    .filter(|&i| names.contains(&frame.labels[i].text))
                                    .collect();
                                let mut found: Vec<String> = failure_of(|| {
                                    assert_shown_clear_by(&name, &frame, &camera, size, &shown, 0.0)
                                })
                                .into_iter()
                                .collect();
                                for (text, rect) in label_boxes(&frame, &camera, size) {
                                    let Some(own) = names.iter().position(|n| *n == text) else {
                                        continue;
                                    };
                                    let gap = |p: Vec2| rect.nearest(p).distance(p);
                                    let Some(mine) = dots[own] else { continue };
                                    for (j, dot) in dots.iter().enumerate() {
                                        match dot {
                                            Some(dot) if j != own && gap(*dot) <= gap(mine) => {
                                                found.push(format!(
                                                    "{name} on {size}: {text:?} at {:?} is {} px \
                                                     from its target, {} px from {:?}'s",
                                                    rect.min,
                                                    gap(mine),
                                                    gap(*dot),
                                                    names[j]
                                                ))
                                            }
                                            _ => {}
                                        }
                                    }
                                }
                                if page_targets.contains(&target) {
                                    at_start.extend(found.iter().cloned());
                                }
                                failures.extend(found);
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(cases > 4000, "{cases} cases");
    assert_none_failed(&at_start);
    assert!(
        failures.len() * 1000 <= cases,
        "{} failures in {cases} cases (at most 1 in 1000 may fail), e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

#[test]
fn lesson_07_labels_keep_room_between_them_far_and_near() {
    // Figure 1 at its page camera, both canvases, with the target dragged far up and out of
    // reach (0.88, 1.5, −0.52) and near the root (the quiz's (0.05, 0.05, 0)): every two shown
    // labels, as the page lays them out, keep 10 px apart, and two words (not a side's one
    // letter) 20 px where they share half a line, so that two names never read as one ("CCD
    // target FABRIK target", "d = 0.071 m CCD") where the text is set wider than measured.
    use inbetween::figures::ik::IkFigure;
    let mut failures = Vec::new();
    for target in [Vec3::new(0.88, 1.5, -0.52), Vec3::new(0.05, 0.05, 0.0)] {
        let mut scene = IkFigure::new();
        scene.set_target(target).unwrap();
        for size in CANVASES {
            let (frame, camera) = drawn_for_view(
                &mut scene,
                [0.25, 0.45, 0.0, 4.3, 0.1, 0.25],
                size,
                |s, f| {
                    s.draw(f).unwrap();
                },
                |s, c, size| s.set_view(c, size.x, size.y),
            );
            let boxes = label_boxes(&frame, &camera, size);
            for (i, (a, ra)) in boxes.iter().enumerate() {
                for (b, rb) in &boxes[i + 1..] {
                    let shared = ra.max().y.min(rb.max().y) - ra.min.y.max(rb.min.y);
                    let one_line = shared >= 8.0 && a.len() > 1 && b.len() > 1;
                    if ra.overlaps(rb, 10.0) || (one_line && ra.overlaps(rb, 20.0)) {
                        failures.push(format!(
                            "07 Fig 1, target {target} on {size}: {a:?} at {:?} and {b:?} at {:?}",
                            ra.min, rb.min
                        ));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

/// Figure 1 with `target` and `pole` drawn as on the page (placed for the view of the frame
/// before) at its page camera, or orbited as the page test's drag orbits it (yaw down by 0.2 of
/// the canvas's width and pitch up by 0.1 of its height, at 0.008 rad a pixel): the scene, the
/// frame checked and its camera.
fn fig1_drawn(
    target: Vec3,
    pole: f32,
    size: Vec2,
    orbited: bool,
) -> (inbetween::figures::ik::IkFigure, Frame, OrbitCamera) {
    let mut scene = inbetween::figures::ik::IkFigure::new();
    scene.set_target(target).unwrap();
    scene.set_pole_angle_deg(pole).unwrap();
    let drag = if orbited {
        0.008 * Vec2::new(-0.2 * size.x, 0.1 * size.y)
    } else {
        Vec2::ZERO
    };
    let view = [0.25, 0.45, 0.0, 4.3, 0.1 + drag.x, 0.25 + drag.y];
    let (frame, camera) = drawn_for_view(
        &mut scene,
        view,
        size,
        |s, f| {
            s.draw(f).unwrap();
        },
        |s, c, size| s.set_view(c, size.x, size.y),
    );
    (scene, frame, camera)
}

/// Figure 1's targets for the sweeps below: the page test's (x = −0.91), the quiz's
/// (0.05, 0.05, 0), and a grid all round the reach.
fn fig1_targets() -> Vec<Vec3> {
    let mut targets = vec![Vec3::new(-0.91, 0.65, 0.15), Vec3::new(0.05, 0.05, 0.0)];
    for x in [-1.5, -0.9, -0.4, 0.0, 0.4, 0.9, 1.5] {
        for y in [-0.6, 0.0, 0.65, 1.2] {
            for z in [-0.5, 0.15, 0.5] {
                targets.push(Vec3::new(x, y, z));
            }
        }
    }
    targets
}

#[test]
fn lesson_07_miss_leaders_keep_off_other_dots_and_labels() {
    // Figure 1 at its page camera and orbited as the page test orbits it, both canvases, pole 0°
    // and 90°, over targets all round the reach: where a miss's label ("143.2 mm short") has a
    // leader line back to its dashed line, the leader keeps 3 px off every other label's box and
    // every dot but one it starts on (CCD's ran along under "pole" and "CCD target" and past the
    // pole's dot, as if naming them). At the page test's target, orbited as the page test leaves
    // it, CCD's and FABRIK's misses pass in every case; over the sweep at most 8 % of the
    // misses may fail (7 %: 107 of 1512), where the labels crowd a chain (the two-joint chain's sides, pole and
    // names) and no place near the miss is clear.
    use inbetween::draw::layout::leader;
    use inbetween::figures::palette;
    let blue = palette::css(palette::BLUE);
    let view_of = |camera: &OrbitCamera, size: Vec2| camera.projection(size.x / size.y) * camera.view();
    let targets = fig1_targets();
    let (mut failures, mut at_page, mut cases) = (Vec::new(), Vec::new(), 0);
    for (i, &target) in targets.iter().enumerate() {
        for pole in [0.0, 90.0] {
            for size in CANVASES {
                for orbited in [false, true] {
                    let (_, frame, camera) = fig1_drawn(target, pole, size, orbited);
                    let view_proj = view_of(&camera, size);
                    let placed = layout(&frame, &camera, size);
                    let name = format!("07 Fig 1, target {target}, pole {pole}°, orbited {orbited} on {size}");
                    let mut found = Vec::new();
                    for (j, (l, b, p)) in placed.iter().enumerate() {
                        if !p.shown || !l.text.ends_with(" mm short") {
                            continue;
                        }
                        cases += 1;
                        let rect = Rect { min: p.top_left, size: b.size };
                        let Some(end) = leader(rect, l.dot_px, p.leader_to.is_some()) else {
                            continue;
                        };
                        let start = l.dot_px;
                        let grown = |c: Vec2, half: Vec2| Rect { min: c - half, size: 2.0 * half };
                        for (k, (o, ob, op)) in placed.iter().enumerate() {
                            if k == j || !op.shown {
                                continue;
                            }
                            let r = grown(op.top_left + 0.5 * ob.size, 0.5 * ob.size + 3.0);
                            if enters(start, end, r) {
                                found.push((l.css_color.clone(), format!("{name}: {:?}'s leader runs into {:?}", l.text, o.text)));
                            }
                        }
                        for m in &frame.markers {
                            let Some(c) = project_to_canvas(view_proj, size, m.center.into()) else {
                                continue;
                            };
                            let r = 0.5 * m.size_px + 3.0;
                            if c.distance(start) > r && enters(start, end, grown(c, Vec2::splat(r))) {
                                found.push((l.css_color.clone(), format!("{name}: {:?}'s leader passes the dot at {c}", l.text)));
                            }
                        }
                    }
                    if i == 0 && orbited {
                        at_page.extend(found.iter().filter(|(c, _)| *c != blue).map(|f| f.1.clone()));
                    }
                    failures.extend(found.into_iter().map(|f| f.1));
                }
            }
        }
    }
    eprintln!("{} of {cases} misses' leaders graze a label or a dot", failures.len());
    assert_none_failed(&at_page);
    assert!(
        failures.len() * 100 <= 8 * cases,
        "{} of {cases} cases fail (at most 8 % may), e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

#[test]
fn lesson_07_chain_names_sit_nearest_their_own_root() {
    // Figure 1 at its page camera and orbited as the page test orbits it, both canvases, pole 0°
    // and 90°, over targets all round the reach: each chain's name ("FABRIK") comes nearer its
    // own root's dot than any joint or target of another chain (at the quiz's target near the
    // roots, orbited, "FABRIK" sat between CCD's target and FABRIK's root, nearer the first).
    // At the page test's and the quiz's targets every case passes; over the sweep at most 1 %
    // may fail, where another chain bends down past a root and no place near it is clear.
    use inbetween::figures::ik::{ROOTS_X, SOLVERS};
    let targets = fig1_targets();
    let (mut failures, mut at_page, mut cases) = (Vec::new(), Vec::new(), 0);
    for (i, &target) in targets.iter().enumerate() {
        for pole in [0.0, 90.0] {
            for size in CANVASES {
                for orbited in [false, true] {
                    let (mut scene, frame, camera) = fig1_drawn(target, pole, size, orbited);
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let at = |p: Vec3| project_to_canvas(view_proj, size, p);
                    let chains: Vec<Vec<Vec3>> = (0..3).map(|k| scene.chain(k).unwrap()).collect();
                    let name = format!("07 Fig 1, target {target}, pole {pole}°, orbited {orbited} on {size}");
                    for (text, rect) in label_boxes(&frame, &camera, size) {
                        let Some(k) = SOLVERS.iter().position(|s| *s == text) else {
                            continue;
                        };
                        cases += 1;
                        let gap = |p: Vec2| rect.nearest(p).distance(p);
                        let Some(own) = at(Vec3::new(ROOTS_X[k], 0.0, 0.0)) else { continue };
                        for j in (0..3).filter(|&j| j != k) {
                            let goal = target + Vec3::new(ROOTS_X[j], 0.0, 0.0);
                            for p in chains[j].iter().chain([&goal]).filter_map(|&p| at(p)) {
                                if gap(p) <= gap(own) {
                                    let message = format!(
                                        "{name}: {text:?} at {:?} is {} px from its root, {} px \
                                         from {}'s point at {p}",
                                        rect.min, gap(own), gap(p), SOLVERS[j]
                                    );
                                    if i < 2 {
                                        at_page.push(message.clone());
                                    }
                                    failures.push(message);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    eprintln!("{} failures in {cases} chain names", failures.len());
    assert_none_failed(&at_page);
    assert!(
        failures.len() * 100 <= cases,
        "{} failures in {cases} cases (at most 1 % may), e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

#[test]
fn lesson_07_aim_miss_leader_keeps_off_the_body_orbited() {
    // Figure 4 at its page camera and orbited as the page test's drag leaves it (yaw down by
    // 0.2 of the canvas's width and pitch up by 0.1 of its height, at 0.008 rad a pixel), both
    // canvases, with the target behind the body where the page's controls and quiz leave it
    // (x = −0.72, y = 1, z = −1.2) and beside it, cones of 70° and 40°, over the loop: where
    // "misses …°" has a leader line back to its arc, the leader does not cross the body's or
    // the head's box on the canvas (from the arc's middle over the body, a red line over the
    // dark grey reads as part of it). As on the page, the figure places it for the view of the
    // frame before.
    use inbetween::draw::layout::leader;
    use inbetween::draw::MeshId;
    use inbetween::figures::palette;
    let (mut failures, mut led) = (Vec::new(), 0);
    for (target, cone) in [
        (Vec3::new(-0.72, 1.0, -1.2), 70.0),
        (Vec3::new(-0.72, 1.0, -1.2), 40.0),
        (Vec3::new(-1.2, 1.6, -0.7), 70.0),
    ] {
        for k in 0..8 {
            let t = k as f32;
            for size in CANVASES {
                for orbit in [Vec2::ZERO, 0.008 * Vec2::new(-0.2 * size.x, 0.1 * size.y)] {
                    let (_, frame, camera) = aim_drawn_orbited(target, cone, t, size, orbit);
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let solids: Vec<Rect> = frame
                        .meshes
                        .iter()
                        .filter(|m| {
                            (m.mesh == MeshId::CUBE && m.color.truncate() == palette::GREY)
                                || (m.mesh == MeshId::SPHERE
                                    && m.color.truncate() == palette::BROWN)
                        })
                        .map(|m| {
                            let corners =
                                inbetween::draw::box_corners(Vec3::splat(-1.0), Vec3::ONE).map(
                                    |c| {
                                        let p = m.model.transform_point3(c);
                                        project_to_canvas(view_proj, size, p).unwrap()
                                    },
                                );
                            let lo = corners.iter().copied().fold(Vec2::MAX, Vec2::min);
                            let hi = corners.iter().copied().fold(Vec2::MIN, Vec2::max);
                            Rect {
                                min: lo,
                                size: hi - lo,
                            }
                        })
                        .collect();
                    for (l, b, p) in layout(&frame, &camera, size) {
                        if !p.shown || !l.text.starts_with("misses ") {
                            continue;
                        }
                        let rect = Rect {
                            min: p.top_left,
                            size: b.size,
                        };
                        let Some(end) = leader(rect, l.dot_px, p.leader_to.is_some()) else {
                            continue;
                        };
                        led += 1;
                        if solids.iter().any(|s| enters(l.dot_px, end, *s)) {
                            failures.push(format!(
                                "07 aim, target {target}, cone {cone}°, t {t}, orbit {orbit} on \
                                 {size}: {:?}'s leader from {} to {end} crosses the body or the \
                                 head",
                                l.text, l.dot_px
                            ));
                        }
                    }
                }
            }
        }
    }
    eprintln!("{led} misses' labels with a leader");
    assert!(led >= 8, "only {led} misses' labels have a leader");
    assert_none_failed(&failures);
}
