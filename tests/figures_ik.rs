//! Lesson 07 figure logic: validation messages, what the controls change, the error samples,
//! dragging the target, and what the note says about the student's exercises (with a correct, a
//! wrong and a panicking runner).

use glam::Vec3;
use inbetween::camera::OrbitCamera;
use inbetween::draw::{palette, Frame};
use inbetween::exercises::run::{direct, Failure, Flat};
use inbetween::figures::ik::{AimFigure, IkFigure, MAX_ITERATIONS, TOLERANCE_M};
use inbetween::ik::{ccd_iteration, max_violation_rad, JointLimit};

fn lengths(chain: &[Vec3]) -> Vec<f32> {
    chain.windows(2).map(|w| w[0].distance(w[1])).collect()
}

#[test]
fn bad_input_is_an_error_naming_the_parameter() {
    let mut f = IkFigure::new();
    assert!(f.set_segments(9.0).unwrap_err().contains("segments"));
    assert!(f.set_segments(f32::NAN).unwrap_err().contains("segments"));
    assert!(f
        .set_target(Vec3::new(0.0, f32::INFINITY, 0.0))
        .unwrap_err()
        .contains("target y"));
    assert!(f
        .set_target(Vec3::new(2.0, 0.0, 0.0))
        .unwrap_err()
        .contains("target x"));
    assert!(f.set_iterations(0.0).unwrap_err().contains("iterations"));
    assert!(f.set_iterations(1e6).unwrap_err().contains("iterations"));
    assert!(f
        .set_pole_angle_deg(f32::NAN)
        .unwrap_err()
        .contains("pole angle"));
    assert!(f
        .set_limits("springs")
        .unwrap_err()
        .contains("joint limits"));
    assert!(f.hits_target(f32::NAN, 0.0).is_err());
    assert!(f.drag_target(0.0, f32::NAN).is_err());
    let mut a = AimFigure::new();
    assert!(a
        .set_max_angle_deg(-1.0)
        .unwrap_err()
        .contains("largest turn"));
    assert!(a.set_target(Vec3::NAN).is_err());
    assert!(a.draw(&mut Frame::default(), f32::NAN).is_err());
}

#[test]
fn all_three_solvers_reach_a_reachable_target_and_keep_the_chain() {
    let mut f = IkFigure::new();
    f.set_iterations(MAX_ITERATIONS as f32).unwrap();
    let note = f.draw(&mut Frame::default()).unwrap();
    assert!(note.contains("Two-joint: reached in one step"), "{note}");
    // Side d's length, which the figure's label may shorten to "d": |(0.55, 0.65, 0.15)|.
    assert!(note.contains("side d = 0.865 m."), "{note}");
    assert!(note.contains("FABRIK: reached after"), "{note}");
    assert!(note.contains("CCD: reached after"), "{note}");
    let results = f.results().unwrap();
    assert!(results.iter().all(|r| r.unwrap().reached));
    let rest = f.chain(1).unwrap();
    for k in 0..3 {
        let c = f.chain(k).unwrap();
        assert_eq!(c.len(), 3);
        assert!((c[2] - c[0]).distance(f.target()) <= TOLERANCE_M + 1e-5);
        for (a, b) in lengths(&c).iter().zip(lengths(&rest)) {
            assert!((a - b).abs() < 1e-4);
        }
    }
    // More segments: no analytic answer, the others still reach.
    f.set_segments(6.0).unwrap();
    let note = f.draw(&mut Frame::default()).unwrap();
    assert!(
        note.contains("Two-joint IK needs exactly 2 segments"),
        "{note}"
    );
    assert!(f.chain(0).unwrap().is_empty());
    assert_eq!(f.chain(2).unwrap().len(), 7);
    // Out of reach: reported, not reached.
    f.set_target(Vec3::new(1.2, 1.2, 0.0)).unwrap();
    let results = f.results().unwrap();
    assert!(!results[1].unwrap().reached && !results[2].unwrap().reached);
    assert!(results[2].unwrap().error > 0.6);
}

#[test]
fn the_iteration_slider_and_the_error_samples() {
    let mut f = IkFigure::new();
    f.set_segments(5.0).unwrap();
    f.set_iterations(1.0).unwrap();
    let one = f.results().unwrap()[1].unwrap();
    assert_eq!(one.iterations, 1);
    f.set_iterations(30.0).unwrap();
    let thirty = f.results().unwrap()[1].unwrap();
    assert!(thirty.error < one.error);
    let samples = f.error_samples().unwrap();
    assert_eq!(samples.len(), 3 * MAX_ITERATIONS);
    assert_eq!(samples[0], 1.0);
    // The plotted error after iteration 1 is the log of the slider's error at 1 iteration.
    assert!((samples[1] - one.error.log10()).abs() < 1e-4);
    // FABRIK ends within the tolerance.
    assert!(samples[3 * MAX_ITERATIONS - 1] <= TOLERANCE_M.log10() + 1e-4);
}

#[test]
fn limits_hold_in_the_drawn_chains() {
    let mut f = IkFigure::new();
    f.set_segments(4.0).unwrap();
    f.set_target(Vec3::new(-0.6, 0.4, 0.3)).unwrap();
    let free = f.results().unwrap()[2].unwrap();
    for (mode, limit, root) in [
        (
            "hinges (bend one way)",
            JointLimit::Hinge {
                axis: Vec3::Z,
                min_rad: -120f32.to_radians(),
                max_rad: 0.0,
            },
            JointLimit::Hinge {
                axis: Vec3::Z,
                min_rad: -90f32.to_radians(),
                max_rad: 90f32.to_radians(),
            },
        ),
        (
            "cones (40°)",
            JointLimit::Cone {
                max_rad: 40f32.to_radians(),
            },
            JointLimit::Cone {
                max_rad: 60f32.to_radians(),
            },
        ),
    ] {
        f.set_limits(mode).unwrap();
        let note = f.draw(&mut Frame::default()).unwrap();
        assert!(note.contains("Limits apply"), "{note}");
        let mut limits = vec![limit; 4];
        limits[0] = root;
        for k in 1..3 {
            let c = f.chain(k).unwrap();
            let local: Vec<Vec3> = c.iter().map(|&p| p - c[0]).collect();
            assert!(max_violation_rad(&local, &limits, Vec3::Y) < 2e-3, "{mode}");
        }
    }
    // Hinges about z keep the chain in the z = 0 plane: a target at z = 0.3 is out of reach.
    f.set_limits("hinges (bend one way)").unwrap();
    let limited = f.results().unwrap()[2].unwrap();
    assert!(free.reached && !limited.reached && limited.error >= 0.3 - 1e-3);
}

#[test]
fn dragging_moves_the_target_under_the_pointer() {
    let mut f = IkFigure::new();
    let camera = OrbitCamera {
        target: Vec3::new(0.0, 0.5, 0.0),
        distance: 4.0,
        yaw_rad: 0.0,
        pitch_rad: 0.0,
        ..OrbitCamera::default()
    };
    assert!(!f.hits_target(100.0, 100.0).unwrap(), "no view yet");
    f.set_view(camera, 800.0, 400.0);
    // Looking along −z from the front, the CCD chain's target (root at x = 0) at (0.45, 0.55, 0.15).
    let view_proj = camera.projection(2.0) * camera.view();
    let clip = view_proj * (f.target()).extend(1.0);
    let (x, y) = (
        (clip.x / clip.w * 0.5 + 0.5) * 800.0,
        (0.5 - clip.y / clip.w * 0.5) * 400.0,
    );
    assert!(f.hits_target(x, y).unwrap());
    assert!(!f.hits_target(x + 60.0, y).unwrap());
    let before = f.target();
    f.drag_target(x + 40.0, y - 20.0).unwrap();
    let after = f.target();
    assert!(
        after.x > before.x + 0.05 && after.y > before.y + 0.02,
        "{before} → {after}"
    );
    // On the plane through the old target that faces the camera (the CCD chain's root is at 0).
    let sight = (before - camera.eye()).normalize();
    assert!(
        (after - before).dot(sight).abs() < 1e-3,
        "the plane faces the camera"
    );
    // Dragging far away clamps to the target's range.
    f.drag_target(1e5, -1e5).unwrap();
    assert!(f.target().abs().max_element() <= 1.5);
}

/// Answers 7.1 and 7.2 with the reference, through the same flattening as the sandbox.
fn correct(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut rest = args;
    let mut out = Vec::new();
    match name {
        "two_joint" => {
            let v: Vec<Vec3> = (0..5).map(|_| Vec3::take(&mut rest).unwrap()).collect();
            inbetween::exercises::ik::reference_two_joint(v[0], v[1], v[2], v[3], v[4])
                .put(&mut out);
        }
        "ccd_iteration" => {
            let mut chain = Vec::<Vec3>::take(&mut rest).unwrap();
            let target = Vec3::take(&mut rest).unwrap();
            ccd_iteration(&mut chain, target);
            chain.put(&mut out);
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

#[test]
fn the_note_reports_the_students_exercises() {
    let mut f = IkFigure::new();
    f.set_use_exercise(true);
    let note = f.draw(&mut Frame::default()).unwrap();
    if cfg!(feature = "solutions") {
        assert!(
            note.contains("Your two_joint matches the reference"),
            "{note}"
        );
    } else {
        assert!(note.contains("Not done yet: exercise 7.1"), "{note}");
        assert!(note.contains("Not done yet: exercise 7.2"), "{note}");
    }
    f.set_runner(correct);
    let note = f.draw(&mut Frame::default()).unwrap();
    assert!(
        note.contains("Your two_joint matches the reference"),
        "{note}"
    );
    assert!(
        note.contains("Your ccd_iteration matches the reference in every iteration"),
        "{note}"
    );
    // Wrong: the middle joint on the other side (pole ignored); a CCD sweep from the root out.
    fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        let mut rest = args;
        let mut out = Vec::new();
        match name {
            "two_joint" => {
                let v: Vec<Vec3> = (0..5).map(|_| Vec3::take(&mut rest).unwrap()).collect();
                let (m, e) =
                    inbetween::exercises::ik::reference_two_joint(v[0], v[1], v[2], v[3], v[4]);
                let u = (v[3] - v[0]).normalize();
                let w = m - v[0];
                let mirrored = v[0] + 2.0 * u * w.dot(u) - w;
                (mirrored, e).put(&mut out);
            }
            "ccd_iteration" => {
                let mut chain = Vec::<Vec3>::take(&mut rest).unwrap();
                let target = Vec3::take(&mut rest).unwrap();
                let n = chain.len();
                for i in 0..n - 1 {
                    let pivot = chain[i];
                    let r =
                        inbetween::ik::rotation_arc(chain[n - 1] - pivot, target - pivot).unwrap();
                    for p in &mut chain[i + 1..] {
                        *p = pivot + r * (*p - pivot);
                    }
                }
                chain.put(&mut out);
            }
            _ => return direct(name, args),
        }
        Ok(out)
    }
    f.set_runner(wrong);
    let note = f.draw(&mut Frame::default()).unwrap();
    assert!(note.contains("Your two_joint differs at target"), "{note}");
    assert!(
        note.contains("Your ccd_iteration differs at iteration 1, joint"),
        "{note}"
    );
    fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
        Err(Failure::Panicked(
            "panicked at src/exercises/ik.rs:70:5:\nboom".into(),
        ))
    }
    f.set_runner(panics);
    let note = f.draw(&mut Frame::default()).unwrap();
    assert!(
        note.contains("Your exercise 7.1 two_joint panicked at src/exercises/ik.rs:70:5: boom"),
        "{note}"
    );
    // With limits, 7.2 says how to run it; with more segments, 7.1 does.
    f.set_runner(correct);
    f.set_limits("cones (40°)").unwrap();
    f.set_segments(3.0).unwrap();
    let note = f.draw(&mut Frame::default()).unwrap();
    assert!(note.contains("Set segments to 2"), "{note}");
    assert!(note.contains("Set joint limits to none"), "{note}");
    assert!(!note.contains("Not done yet"), "{note}");
    // A stub is reported whatever the settings.
    f.set_runner(direct);
    let note = f.draw(&mut Frame::default()).unwrap();
    if !cfg!(feature = "solutions") {
        assert!(note.contains("Not done yet: exercise 7.1"), "{note}");
        assert!(note.contains("Not done yet: exercise 7.2"), "{note}");
    }
}

#[test]
fn the_head_looks_at_the_target_within_its_cone() {
    let mut a = AimFigure::new();
    a.set_target(Vec3::new(1.2, 1.9, 1.0)).unwrap();
    let note = a.draw(&mut Frame::default(), 0.0).unwrap();
    assert!(note.contains("Looking straight at the target"), "{note}");
    a.set_target(Vec3::new(0.0, 1.6, -1.2)).unwrap();
    let note = a.draw(&mut Frame::default(), 0.0).unwrap();
    assert!(
        note.contains("outside the 70° cone") && note.contains("reached: no"),
        "{note}"
    );
}

#[test]
fn the_pole_steers_the_analytic_solver_only() {
    let mut f = IkFigure::new();
    let before: Vec<Vec<Vec3>> = (0..3).map(|k| f.chain(k).unwrap()).collect();
    f.set_pole_angle_deg(180.0).unwrap();
    let after: Vec<Vec<Vec3>> = (0..3).map(|k| f.chain(k).unwrap()).collect();
    assert!(
        before[0][1].distance(after[0][1]) > 0.2,
        "the middle joint swings round"
    );
    assert!(
        before[0][2].distance(after[0][2]) < 1e-4,
        "the end stays on the target"
    );
    assert_eq!(before[1], after[1]);
    assert_eq!(before[2], after[2]);
}

#[test]
fn the_aim_target_circles_once_per_timeline_loop() {
    // The caption says the target circles once every 8 s, the timeline's length, so it does
    // not jump when the timeline loops from 8 s back to 0 (as a target turning once every 7 s
    // would).
    let a = AimFigure::new();
    let period = inbetween::figures::ik::AIM_PERIOD_SEC;
    assert_eq!(period, 8.0);
    assert!(a.target_at(0.0).distance(a.target_at(period)) < 1e-5);
    // Half a period later it is on the far side of its circle (0.5 m across).
    let across = a.target_at(0.0) - a.target_at(0.5 * period);
    assert!((Vec3::new(across.x, 0.0, across.z).length() - 0.5).abs() < 1e-4);
    // No frame of the loop moves it further than the frames around it (60 frames a second).
    let steps: Vec<f32> = (0..480)
        .map(|k| {
            let t = k as f32 / 60.0;
            a.target_at(t).distance(a.target_at(t + 1.0 / 60.0))
        })
        .collect();
    let wrap = a.target_at(period - 1.0 / 60.0).distance(a.target_at(0.0));
    assert!(
        wrap <= 1.01 * steps.iter().cloned().fold(0.0, f32::max),
        "{wrap} {steps:?}"
    );
}

#[test]
fn the_aim_targets_range_is_what_the_page_frames() {
    let reach = inbetween::figures::ik::AIM_REACH_M;
    let mut a = AimFigure::new();
    let (low, high) = inbetween::figures::ik::AIM_HEIGHT_M;
    assert!(a.set_target(Vec3::new(-reach, low, reach)).is_ok());
    assert!(a.set_target(Vec3::new(reach, high, -reach)).is_ok());
    assert!(a
        .set_target(Vec3::new(0.0, low - 0.1, 0.0))
        .unwrap_err()
        .contains("target y"));
    assert!(a
        .set_target(Vec3::new(reach + 0.5, 1.0, 0.0))
        .unwrap_err()
        .contains("target x"));
    // The cone is labelled with its angle.
    a.set_max_angle_deg(45.0).unwrap();
    let mut frame = Frame::default();
    a.draw(&mut frame, 0.0).unwrap();
    assert!(frame.labels.iter().any(|l| l.text == "45° cone"));
}

#[test]
fn the_hinges_try_this_is_what_the_figure_shows() {
    // Lesson 07's "Try this" under Joint limits, step by step, at the figure's default 10
    // iterations and then at 50.
    let hinges = |segments: f32, target: Vec3, iterations: f32| {
        let mut f = IkFigure::new();
        f.set_segments(segments).unwrap();
        f.set_limits("hinges (bend one way)").unwrap();
        f.set_target(target).unwrap();
        f.set_iterations(iterations).unwrap();
        let r = f.results().unwrap();
        (r[1].unwrap(), r[2].unwrap())
    };
    // The default target (z = 0.15): both stop at least 15 cm short.
    let (ccd, fabrik) = hinges(2.0, Vec3::new(0.55, 0.65, 0.15), 10.0);
    assert!(ccd.error >= 0.15 - 1e-3 && fabrik.error >= 0.15 - 1e-3);
    // z = 0: FABRIK reaches it in a few iterations, CCD is millimetres short after 10 and
    // reaches it with more.
    let (ccd, fabrik) = hinges(2.0, Vec3::new(0.55, 0.65, 0.0), 10.0);
    assert!(fabrik.reached && fabrik.iterations <= 5, "{fabrik:?}");
    assert!(!ccd.reached && ccd.error < 5e-3, "{ccd:?}");
    let (ccd, _) = hinges(2.0, Vec3::new(0.55, 0.65, 0.0), 50.0);
    assert!(ccd.reached, "{ccd:?}");
    // To the left with 2 segments: neither, even with 50 iterations.
    let left = Vec3::new(-0.5, 0.65, 0.0);
    let (ccd, fabrik) = hinges(2.0, left, 50.0);
    assert!(!ccd.reached && !fabrik.reached);
    // With 5 segments CCD gets there; FABRIK stays more than 30 cm short.
    let (ccd, fabrik) = hinges(5.0, left, 50.0);
    assert!(ccd.reached, "{ccd:?}");
    assert!(!fabrik.reached && fabrik.error > 0.3, "{fabrik:?}");
}

#[test]
fn the_aim_plot_follows_the_target_until_the_cone_stops_the_head() {
    let mut a = AimFigure::new();
    a.set_target(Vec3::new(1.2, 1.6, 0.45)).unwrap();
    let rows = a.plot_samples(80).unwrap();
    assert_eq!(rows.len(), 3 * 81);
    assert_eq!(rows[0], 0.0);
    assert_eq!(rows[3 * 80], inbetween::figures::ik::AIM_PERIOD_SEC);
    let (mut inside, mut outside) = (0, 0);
    for row in rows.chunks(3) {
        let (to_target, head) = (row[1], row[2]);
        assert!(head <= 70.0 + 0.1, "{row:?}");
        if to_target <= 70.0 {
            inside += 1;
            assert!(
                (head - to_target).abs() < 0.2,
                "inside the cone the head follows: {row:?}"
            );
        } else {
            outside += 1;
            assert!(
                (head - 70.0).abs() < 0.2,
                "outside it stops at the rim: {row:?}"
            );
        }
    }
    // This target's circle crosses the cone's rim: both cases show in the plot.
    assert!(
        inside > 5 && outside > 5,
        "{inside} inside, {outside} outside"
    );
}

#[test]
fn fabrik_stalls_near_the_root_where_ccd_reaches() {
    // A target 7 cm from the root: the two-segment chain must fold almost double. FABRIK's
    // passes pull the joints along the chain and barely open the fold; CCD turns it.
    let mut f = IkFigure::new();
    f.set_target(Vec3::new(0.05, 0.05, 0.0)).unwrap();
    let [_, ccd, fabrik] = f.results().unwrap();
    let (ccd, fabrik) = (ccd.unwrap(), fabrik.unwrap());
    println!("CCD {ccd:?}, FABRIK {fabrik:?}");
    assert!(ccd.reached && ccd.iterations == 2, "{ccd:?}");
    assert!(!fabrik.reached && fabrik.iterations == 10, "{fabrik:?}");
    assert!(
        (fabrik.error * 1000.0 - 41.8).abs() < 0.1,
        "FABRIK {} mm short",
        fabrik.error * 1000.0
    );
    // The figure marks the gap with its length.
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    assert!(
        frame.labels.iter().any(|l| l.text == "41.8 mm short"),
        "{:?}",
        frame.labels.iter().map(|l| &l.text).collect::<Vec<_>>()
    );
}

#[test]
fn each_target_has_its_chains_colour_and_stays_in_view() {
    use inbetween::draw::palette;
    let mut f = IkFigure::new();
    f.set_target(Vec3::new(-1.2, 1.4, 0.5)).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    let colors = [palette::BLUE, palette::ORANGE, palette::TEAL];
    for (k, name) in ["two-joint", "CCD", "FABRIK"].iter().enumerate() {
        let label = frame
            .labels
            .iter()
            .find(|l| l.text == format!("{name} target"))
            .unwrap();
        assert_eq!(label.color, colors[k], "{name}");
        let target = f.target() + Vec3::new([-1.1, 0.0, 1.1][k], 0.0, 0.0);
        assert!(frame
            .markers
            .iter()
            .any(|m| Vec3::from(m.center) == target
                && glam::Vec4::from(m.color).truncate() == colors[k]));
        assert!(
            frame.keep_in_view.contains(&target),
            "{name}'s target is kept in view"
        );
    }
    // With 3 segments the two-joint chain, its pole and its labels are not drawn.
    f.set_segments(3.0).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    assert!(frame
        .labels
        .iter()
        .all(|l| !l.text.contains("two-joint") && l.text != "pole" && !l.text.contains("needs")));
    assert!(frame
        .meshes
        .iter()
        .all(|m| m.color.truncate() != palette::BLUE));
}

#[test]
fn the_law_of_cosines_triangle_is_drawn_on_the_two_joint_chain() {
    let mut f = IkFigure::new();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert!(texts.contains(&"a") && texts.contains(&"b"), "{texts:?}");
    let d = f.target().length();
    assert!(
        texts.contains(&format!("d = {:.3} m", d).as_str()),
        "{texts:?}"
    );
    // α as drawn is the angle of the law of cosines: cos α = (a² + d² − b²) / (2ad).
    let (a, b) = (0.5f32, 0.5f32);
    let alpha = ((a * a + d * d - b * b) / (2.0 * a * d))
        .acos()
        .to_degrees();
    assert!(
        texts.contains(&format!("α = {alpha:.0}°").as_str()),
        "{texts:?}"
    );
    // Every middle joint the pole angle can choose lies on the dashed circle: turning the pole
    // keeps the middle joint at the same distance from the root→target line.
    let chain = f.chain(0).unwrap();
    let root = chain[0];
    let u = f.target().normalize();
    let off_line = |p: Vec3| {
        let v = p - root;
        (v - u * v.dot(u)).length()
    };
    let r0 = off_line(chain[1]);
    for deg in [-150.0, -60.0, 45.0, 120.0] {
        f.set_pole_angle_deg(deg).unwrap();
        let c = f.chain(0).unwrap();
        assert!((off_line(c[1]) - r0).abs() < 1e-4);
        assert!(
            c[2].distance(chain[2]) < 1e-4,
            "the end stays on the target"
        );
    }
}

#[test]
fn every_miss_the_note_reports_is_labelled_at_its_chain() {
    // The defaults: CCD stops 3.8 mm short after 10 iterations, FABRIK and two-joint reach.
    let mut f = IkFigure::new();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame).unwrap();
    let results = f.results().unwrap();
    let ccd = results[1].unwrap();
    assert!(
        !ccd.reached && ccd.error > 0.003 && ccd.error < 0.005,
        "{ccd:?}"
    );
    assert!(
        note.contains(&format!(
            "CCD: after 10 iterations, {:.3} mm",
            ccd.error * 1000.0
        )),
        "{note}"
    );
    let shorts: Vec<&str> = frame
        .labels
        .iter()
        .filter(|l| l.text.ends_with("mm short"))
        .map(|l| l.text.as_str())
        .collect();
    assert_eq!(shorts, [format!("{:.1} mm short", ccd.error * 1000.0)]);
}

#[test]
fn the_hinges_gap_is_marked_with_its_length() {
    let mut f = IkFigure::new();
    f.set_limits("hinges (bend one way)").unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    let results = f.results().unwrap();
    for r in &results[1..3] {
        let r = r.unwrap();
        assert!(r.error >= 0.15 - 1e-4, "{r:?}");
        let text = format!("{:.1} mm short", r.error * 1000.0);
        assert!(frame.labels.iter().any(|l| l.text == text), "{text}");
    }
}

#[test]
fn the_hinges_plane_and_the_targets_drop_to_it_are_drawn() {
    use inbetween::figures::ik::HINGE_PATCH_M;
    let mut f = IkFigure::new();
    f.set_limits("hinges (bend one way)").unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame).unwrap();
    assert!(
        note.contains("the target is 15 cm off it (the grey dashed drop to the grey square)"),
        "{note}"
    );
    let grey: Vec<(Vec3, Vec3)> = frame.segments_of(palette::GREY).collect();
    let target = f.target();
    for root_x in [0.0, 1.1] {
        let root = Vec3::new(root_x, 0.0, 0.0);
        let (top, foot) = (root + target, root + Vec3::new(target.x, target.y, 0.0));
        // The square of the plane around the foot: its lower edge, at z = 0.
        let h = HINGE_PATCH_M;
        let lower = (foot + Vec3::new(-h, -h, 0.0), foot + Vec3::new(h, -h, 0.0));
        assert!(
            grey.iter()
                .any(|(a, b)| a.distance(lower.0) < 1e-4 && b.distance(lower.1) < 1e-4),
            "the square at the chain at x = {root_x}"
        );
        // The drop from the target to the plane, 15 cm along z.
        assert!(
            grey.iter()
                .any(|(a, b)| a.distance(foot) < 1e-4 && b.distance(top) < 1e-4),
            "the drop at the chain at x = {root_x}"
        );
        assert!((top - foot).length() > 0.15 - 1e-4);
    }
    // None without hinges, nor for a target on the plane.
    f.set_limits("cones (40°)").unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame).unwrap();
    assert!(!note.contains("grey dashed drop"), "{note}");
    f.set_limits("hinges (bend one way)").unwrap();
    f.set_target(Vec3::new(0.55, 0.65, 0.0)).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame).unwrap();
    assert!(!note.contains("grey dashed drop"), "{note}");
    // Every grey line (hinge ranges, the side d) lies in the plane: no drop along z.
    assert!(frame
        .segments_of(palette::GREY)
        .all(|(a, b)| (a.z - b.z).abs() < 1e-6));
}

#[test]
fn the_aim_figure_shows_what_the_head_misses() {
    let mut f = AimFigure::new();
    f.set_target(Vec3::new(0.0, 1.6, -1.2)).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, 0.0).unwrap();
    assert!(note.contains("outside the 70° cone"), "{note}");
    let missed = frame
        .labels
        .iter()
        .find(|l| l.text.starts_with("misses"))
        .expect("the missed angle");
    let deg: f32 = missed
        .text
        .trim_start_matches("misses ")
        .trim_end_matches('°')
        .parse()
        .unwrap();
    assert!(deg > 90.0, "{deg}");
    assert!(
        frame
            .strokes
            .iter()
            .any(|s| s.dash[3] > 0.0 && s.width_px >= 2.0),
        "a wide dashed line to the target"
    );
    // Every target position of the loop stays inside the declared view.
    let (lo, hi) = frame.keep_in_view.iter().fold(
        (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    for k in 0..32 {
        let p = f.target_at(8.0 * k as f32 / 32.0);
        assert!(p.cmpge(lo).all() && p.cmple(hi).all(), "{p}");
    }
    // At 180° the head turns all the way: nothing is missed.
    f.set_max_angle_deg(180.0).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, 0.0).unwrap();
    assert!(frame.labels.iter().all(|l| !l.text.starts_with("misses")));
}

#[test]
fn use_my_exercise_checks_probe_inputs_beyond_the_target() {
    let mut f = IkFigure::new();
    f.set_use_exercise(true);
    // A two_joint that ignores the out-of-reach clamp: right wherever the target is in reach.
    fn no_clamp(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        if name == "two_joint" {
            let mut input = args;
            let [r, m, e, g, pole] = [(); 5].map(|_| Vec3::take(&mut input).unwrap());
            let (a, b) = (m.distance(r), e.distance(m));
            let d = g.distance(r);
            let u = (g - r) / d;
            let w = pole - r;
            let v = (w - u * w.dot(u)).normalize();
            let cos = ((a * a + d * d - b * b) / (2.0 * a * d)).clamp(-1.0, 1.0);
            let middle = r + a * (cos * u + (1.0 - cos * cos).sqrt() * v);
            let mut out = Vec::new();
            middle.put(&mut out);
            g.put(&mut out);
            return Ok(out);
        }
        direct(name, args)
    }
    f.set_runner(no_clamp);
    let note = f
        .results()
        .map(|_| ())
        .and_then(|_| {
            let mut frame = Frame::default();
            f.draw(&mut frame)
        })
        .unwrap();
    assert!(
        note.contains("Your two_joint matches the reference"),
        "{note}"
    );
    assert!(
        note.contains(
            "your two_joint differs at 2: a target out of reach; a target closer than |a − b|"
        ),
        "{note}"
    );
    if cfg!(feature = "solutions") {
        f.set_runner(direct);
        f.set_target(Vec3::new(0.3, 0.6, 0.1)).unwrap();
        let mut frame = Frame::default();
        let note = f.draw(&mut frame).unwrap();
        assert!(note.contains("It also matches at 4 probe inputs"), "{note}");
        assert!(note.contains("It also matches at 3 probe inputs"), "{note}");
    }
}

#[test]
fn the_aim_cone_is_drawn_in_wide_lines() {
    // The cone's rim and its eight rays from the head read at a glance: wide strokes, none of
    // them a 1 px line (the floor grid keeps its 1 px lines).
    use inbetween::draw::palette;
    use inbetween::figures::ik::CONE_PX;
    let mut a = AimFigure::new();
    let mut frame = Frame::default();
    a.draw(&mut frame, 0.0).unwrap();
    let purple = palette::PURPLE.extend(1.0).to_array();
    assert!(
        frame.lines.chunks(2).all(|v| v[0].color != purple),
        "no 1 px purple line"
    );
    let head = Vec3::new(0.0, 1.6, 0.0);
    let rays = frame
        .strokes
        .iter()
        .filter(|s| s.color == purple && Vec3::from(s.a).distance(head) < 1e-5)
        .collect::<Vec<_>>();
    assert_eq!(rays.len(), 8, "a ray to every third of the rim's 24 points");
    assert!(rays.iter().all(|s| s.width_px == CONE_PX && CONE_PX >= 2.0));
}

/// At 180° every direction is allowed: no rim shrunk to a short bar behind the head (the rays
/// from the head to a rim 1° from straight back) but the name alone, saying there is no limit;
/// at 170° the cone's rim is still drawn, all of it behind the head.
#[test]
fn the_aim_cone_at_180_degrees_draws_no_rim() {
    use inbetween::draw::palette;
    let purple = palette::PURPLE.extend(1.0).to_array();
    let mut a = AimFigure::new();
    a.set_target(Vec3::new(0.0, 1.6, -1.2)).unwrap();
    let mut purple_strokes = |deg: f32| {
        a.set_max_angle_deg(deg).unwrap();
        let mut frame = Frame::default();
        a.draw(&mut frame, 0.0).unwrap();
        let name = frame.labels.iter().find(|l| l.color == palette::PURPLE);
        let name = name.map(|l| l.text.clone()).unwrap_or_default();
        let n = frame.strokes.iter().filter(|s| s.color == purple).count();
        (n, name)
    };
    let (n, name) = purple_strokes(170.0);
    assert!(n > 8 && name == "170° cone", "{n} strokes, {name:?}");
    let (n, name) = purple_strokes(180.0);
    assert_eq!((n, name.as_str()), (0, "180°: no limit"));
}

/// With hinges and a target off the chains' plane, a corner view from the side shows the gap
/// across (the main view sees it nearly end on): the target and the foot of its drop lie in the
/// inset's box. Without the gap there is no inset.
#[test]
fn the_hinges_gap_gets_a_side_view() {
    use inbetween::draw::inset::InsetView;
    let mut f = IkFigure::new();
    f.set_limits("hinges (bend one way)").unwrap();
    f.set_target(Vec3::new(0.55, 0.65, 0.15)).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    let inset = frame.inset.clone().expect("a side view");
    assert_eq!(inset.view, InsetView::Side);
    assert_eq!(inset.title, "from the side");
    // FABRIK's chain stands at x = 1.1 (the last one drawn).
    let target = Vec3::new(1.1 + 0.55, 0.65, 0.15);
    for p in [target, Vec3::new(target.x, target.y, 0.0)] {
        assert!(p.cmpge(inset.min).all() && p.cmple(inset.max).all(), "{p}");
    }
    f.set_target(Vec3::new(0.55, 0.65, 0.0)).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    assert!(frame.inset.is_none());
    f.set_target(Vec3::new(0.55, 0.65, 0.15)).unwrap();
    f.set_limits("none").unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    assert!(frame.inset.is_none());
}

#[test]
fn the_students_chains_are_drawn_last_and_over_the_reference() {
    // With "use my exercise" and a correct answer, the student's chains lie exactly inside the
    // reference's bars and joints: they must come after every reference chain's lines and be
    // drawn over everything, thinner than the reference's joints, or a right answer is hidden.
    use inbetween::draw::ON_TOP;
    let mut f = IkFigure::new();
    f.set_runner(correct);
    f.set_use_exercise(true);
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    let pink = |c: [f32; 4]| glam::Vec4::from(c).truncate() == palette::STUDENT;
    let student: Vec<usize> = (0..frame.strokes.len())
        .filter(|&i| pink(frame.strokes[i].color))
        .collect();
    // Two chains of two segments: 7.1 on the two-joint chain, 7.2 on CCD's.
    assert_eq!(student.len(), 4, "the student's segments");
    let last_chain = (0..frame.strokes.len())
        .filter(|&i| {
            let c = glam::Vec4::from(frame.strokes[i].color).truncate();
            c == palette::BLUE || c == palette::ORANGE
        })
        .max()
        .unwrap();
    assert!(student[0] > last_chain, "drawn after the reference chains");
    for &i in &student {
        assert_eq!(frame.strokes[i].depth_bias, ON_TOP, "stroke {i} on top");
        assert!(frame.strokes[i].width_px < 4.0, "thinner than the bars");
    }
    let dots: Vec<_> = frame.markers.iter().filter(|m| pink(m.color)).collect();
    assert_eq!(dots.len(), 6, "the student's joints");
    // A negative size: drawn over everything; smaller than a joint's sphere on the canvas.
    assert!(dots.iter().all(|m| m.size_px < 0.0 && m.size_px > -9.0));
}

#[test]
fn two_segments_stall_on_the_straight_line_to_a_target_above_the_root() {
    // Figure 2's Try this with segments at 2 (lessons/07-inverse-kinematics/index.html): at
    // (0, 0.97, 0) the root, the rest pose's middle joint (straight above the root) and the
    // target start on one line, so CCD and FABRIK lay the chain straight along it and stay
    // exactly 30 mm short (1 m of chain, 0.97 m to the target) however many iterations run.
    // At x = 0.01 the start is just off that line: both errors fall, slowly; FABRIK needs
    // nearly all 50 iterations and CCD is still about 29 mm short after them.
    let mut f = IkFigure::new();
    f.set_segments(2.0).unwrap();
    f.set_target(Vec3::new(0.0, 0.97, 0.0)).unwrap();
    for iterations in [1.0, 10.0, MAX_ITERATIONS as f32] {
        f.set_iterations(iterations).unwrap();
        let results = f.results().unwrap();
        assert!(results[0].unwrap().reached, "two-joint IK reaches it");
        for k in 1..3 {
            let r = results[k].unwrap();
            assert!(!r.reached, "solver {k}, {iterations} iterations");
            assert!((r.error - 0.03).abs() < 1e-5, "solver {k}: {}", r.error);
            // On the line x = z = 0 through the root (the figure's chains sit at their roots).
            let chain = f.chain(k).unwrap();
            let root = chain[0];
            assert!(
                chain.iter().all(|p| (*p - root).x.abs() < 1e-4 && p.z.abs() < 1e-4),
                "{chain:?}"
            );
        }
    }
    f.set_target(Vec3::new(0.01, 0.97, 0.0)).unwrap();
    f.set_iterations(MAX_ITERATIONS as f32).unwrap();
    let samples = f.error_samples().unwrap();
    let (first, last) = (&samples[..3], &samples[samples.len() - 3..]);
    assert!(last[1] < first[1] && last[2] < first[2], "{first:?} {last:?}");
    let results = f.results().unwrap();
    let (ccd, fabrik) = (results[1].unwrap(), results[2].unwrap());
    assert!(fabrik.reached && fabrik.iterations >= 40, "{fabrik:?}");
    assert!(!ccd.reached && (ccd.error - 0.029).abs() < 5e-4, "{ccd:?}");
}

#[test]
fn behind_the_head_the_turn_stays_at_the_cone_all_round_the_loop() {
    // Figure 4's Try this: the page's target (x = 1.2, y = 1.9) moved behind the head
    // (z = −1.2). With the 70° cone the target is outside the cone all round its loop and the
    // plot's head turn is flat at 70°; with 180° the head follows it all round.
    let mut a = AimFigure::new();
    a.set_target(Vec3::new(1.2, 1.9, -1.2)).unwrap();
    for row in a.plot_samples(80).unwrap().chunks(3) {
        assert!(row[1] > 70.0 + 1.0, "outside the cone: {row:?}");
        assert!((row[2] - 70.0).abs() < 0.2, "flat at the rim: {row:?}");
    }
    a.set_max_angle_deg(180.0).unwrap();
    for row in a.plot_samples(80).unwrap().chunks(3) {
        assert!((row[2] - row[1]).abs() < 0.2, "follows: {row:?}");
    }
}

#[test]
fn the_hinges_drop_is_drawn_wide_on_top_with_its_length() {
    // Figure 3's start: each limited chain's drop from its target to the chains' plane, 15 cm
    // along z, which the main view sees nearly end on, is grey, at least 5 px wide, over
    // everything, with "15 cm" on it.
    let mut f = IkFigure::new();
    f.set_limits("hinges (bend one way)").unwrap();
    f.set_target(Vec3::new(0.55, 0.65, 0.15)).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame).unwrap();
    let drops: Vec<_> = frame
        .strokes
        .iter()
        .filter(|s| s.color[..3] == palette::GREY.to_array() && s.a[..2] == s.b[..2])
        .collect();
    assert_eq!(drops.len(), 2, "{drops:?}");
    for s in drops {
        assert!(s.width_px >= 5.0 && s.depth_bias == inbetween::draw::ON_TOP, "{s:?}");
        assert!(((s.a[2] - s.b[2]).abs() - 0.15).abs() < 1e-4, "{s:?}");
    }
    assert_eq!(frame.labels.iter().filter(|l| l.text == "15 cm").count(), 2);
}

#[test]
fn at_the_page_start_the_aim_plot_shows_the_head_follow_and_stop() {
    // Figure 4 at its start (the page's target and 70° cone): over the loop the target goes
    // in and out of the cone, so the plot shows what the caption says at first sight: the
    // head's turn on the target's angle for part of the loop, and flat at the rim while the
    // target's angle runs at least 10° above it.
    let a = AimFigure::new();
    let (mut follows, mut flat, mut widest) = (0, 0, 0.0f32);
    for row in a.plot_samples(80).unwrap().chunks(3) {
        let (to_target, head) = (row[1], row[2]);
        if to_target < 70.0 {
            assert!((head - to_target).abs() < 0.2, "inside, the head follows: {row:?}");
            follows += 1;
        } else {
            assert!((head - 70.0).abs() < 0.2, "outside, flat at the rim: {row:?}");
            flat += 1;
            widest = widest.max(to_target - head);
        }
    }
    assert!(follows >= 16 && flat >= 16, "{follows} rows follow, {flat} flat");
    assert!(widest >= 10.0, "the lines part by {widest}° at most");
}

#[test]
fn inside_the_cone_a_dashed_line_carries_the_forward_arrow_to_the_target() {
    // The page sweep's corner target (1.2, 2.6, 1.2) at 6 s: the head looks straight at the
    // target, well past the arrow's tip. A dashed blue line runs from the tip on to the target,
    // along the arrow (from the head at (0, 1.6, 0)), so the figure shows the head looking at it.
    let head = Vec3::new(0.0, 1.6, 0.0);
    let mut a = AimFigure::new();
    a.set_target(Vec3::new(1.2, 2.6, 1.2)).unwrap();
    for t in [0.0, 2.0, 6.0] {
        let mut frame = Frame::default();
        let note = a.draw(&mut frame, t).unwrap();
        assert!(note.starts_with("Looking straight at the target"), "{note}");
        let target = a.target_at(t);
        let on = frame
            .strokes
            .iter()
            .filter(|s| s.color[..3] == palette::BLUE.to_array() && s.dash[3] > 0.0)
            .map(|s| (Vec3::from_slice(&s.a[..3]), Vec3::from_slice(&s.b[..3])))
            .collect::<Vec<_>>();
        let (first, last) = (on.first().expect("a dashed blue line").0, on.last().unwrap().1);
        assert!(last.distance(target) < 1e-4, "{t} s: it ends at {last}, not {target}");
        let along = (first - head).normalize().dot((target - head).normalize());
        assert!(along > 0.9999, "{t} s: it starts off the line to the target ({along})");
        assert!((first - head).length() > 0.75, "{t} s: it starts before the arrow's tip");
    }
    // Outside the cone the red dashed line goes from the head, and no blue one.
    a.set_target(Vec3::new(0.0, 1.6, -1.2)).unwrap();
    let mut frame = Frame::default();
    a.draw(&mut frame, 0.0).unwrap();
    assert!(!frame
        .strokes
        .iter()
        .any(|s| s.color[..3] == palette::BLUE.to_array() && s.dash[3] > 0.0));
}
