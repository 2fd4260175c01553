//! Native tests of lesson 04's figures (src/figures/rigid.rs): the three motions, the "a third,
//! three times" check, solo, the affine keys' validation, and the exercise feedback.

use glam::{Mat3, Mat4, Quat, Vec3};
use inbetween::draw::{Frame, MeshId};
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::rigid::{AffineKeys, Method, RigidMotion};
use inbetween::rigid::DualQuat;
use inbetween::rotation::{self, AffineKey};

fn reference(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let m = |i: usize| Mat3::from_cols_slice(&args[i..i + 9]);
    Ok(match name {
        "dual_quat_apply" => {
            let r = Quat::from_slice(&args[0..4]);
            let (t, p) = (
                Vec3::from_slice(&args[4..7]),
                Vec3::from_slice(&args[7..10]),
            );
            let dq = DualQuat::from_rotation_translation(r, t);
            let mut out = dq.real.to_array().to_vec();
            out.extend(dq.dual.to_array());
            out.extend(dq.transform_point(p).to_array());
            out
        }
        "polar_step" => rotation::polar_step(m(0)).to_cols_array().to_vec(),
        _ => return direct(name, args),
    })
}

/// A dual_quat_apply that forgets the rotation of the point; a polar step without the transpose.
fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut out = reference(name, args)?;
    match name {
        "dual_quat_apply" => {
            let (t, p) = (
                Vec3::from_slice(&args[4..7]),
                Vec3::from_slice(&args[7..10]),
            );
            out.truncate(8);
            out.extend((p + t).to_array());
        }
        "polar_step" => {
            let r = Mat3::from_cols_slice(&args[0..9]);
            out = ((r + r.inverse()) * 0.5).to_cols_array().to_vec();
        }
        _ => {}
    }
    Ok(out)
}

/// A dual_quat_apply whose dual part is `t r / 2` with the wrong sign; its moved point is right.
fn wrong_dual_part(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut out = reference(name, args)?;
    if name == "dual_quat_apply" {
        out[4..8].iter_mut().for_each(|x| *x = -*x);
    }
    Ok(out)
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "index out of bounds (src/exercises/rotations.rs:90:9)".into(),
    ))
}

fn planes(frame: &Frame) -> usize {
    // Each aeroplane is four cubes.
    frame
        .meshes
        .iter()
        .filter(|m| m.mesh == MeshId::CUBE)
        .count()
        / 4
}

#[test]
fn a_third_of_the_screw_three_times_lands_on_b() {
    let mut scene = RigidMotion::new();
    let (_, miss) = scene.third_three_times(Method::Screw);
    assert!(miss < 1e-4, "screw misses B by {miss}");
    let (_, miss) = scene.third_three_times(Method::LerpSlerp);
    assert!(miss > 0.1, "lerp + slerp's third is not a third: {miss}");
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.5).unwrap();
    let before = planes(&frame);
    scene.set_thirds(true);
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, 0.5).unwrap();
    assert_eq!(
        planes(&frame),
        before + 6,
        "three ghosts for screw and for lerp + slerp"
    );
    assert!(
        note.starts_with("screw: its first third, applied three times to A, lands on B (off by "),
        "{note}"
    );
    assert!(
        note.contains(
            "lerp + slerp: its first third, applied three times to A, misses B by 2.160 m."
        ),
        "{note}"
    );
    let labels: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert!(labels.contains(&"3/3") && labels.contains(&"A") && labels.contains(&"B"));
}

#[test]
fn the_thirds_are_drawn_half_the_size_of_the_moving_aeroplanes() {
    // At t = 1/3 the screw's moving aeroplane stands on its first third: at the same size the
    // two (and the blend's, near them) formed one knot of boxes.
    let mut scene = RigidMotion::new();
    scene.set_thirds(true);
    let mut frame = Frame::default();
    scene.draw(&mut frame, 1.0 / 3.0).unwrap();
    // Each cube's largest half-extent (its model's longest column): the wing's.
    let span = |m: &inbetween::draw::MeshDraw| {
        let a = glam::Mat3::from_mat4(m.model);
        a.x_axis.length().max(a.y_axis.length()).max(a.z_axis.length())
    };
    let cubes: Vec<_> = frame
        .meshes
        .iter()
        .filter(|m| m.mesh == MeshId::CUBE)
        .collect();
    // Two solid moving aeroplanes (the screw's is an outline beside the blend's), then three
    // thirds for each of two methods, four cubes each.
    assert_eq!(cubes.len(), 4 * 8);
    let moving = cubes[..8].iter().map(|m| span(m)).fold(0.0, f32::max);
    for third in &cubes[8..] {
        let s = span(third);
        assert!(
            s <= 0.55 * moving,
            "a third's part spans {s} m, the moving wing {moving} m"
        );
    }
}

#[test]
fn solo_shows_one_method() {
    let mut scene = RigidMotion::new();
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.3).unwrap();
    // The screw's is an outline beside the blend's.
    assert_eq!(planes(&frame), 2);
    for which in 1..=3 {
        scene.set_show(which).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame, 0.3).unwrap();
        assert_eq!(planes(&frame), 1);
    }
    assert!(scene.set_show(4).unwrap_err().contains("show must be"));
}

#[test]
fn the_screw_is_drawn_at_constant_speed() {
    let scene = RigidMotion::new();
    let speed = scene.sample_speed(21).unwrap();
    let screw: Vec<f32> = speed.iter().map(|r| r[3]).collect();
    let spread =
        screw.iter().cloned().fold(0.0, f32::max) - screw.iter().cloned().fold(f32::MAX, f32::min);
    assert!(spread < 0.02 * screw[10], "{screw:?}");
    assert!(scene.sample_speed(1).is_err());
}

#[test]
fn rigid_rejects_bad_input() {
    let mut scene = RigidMotion::new();
    assert!(scene
        .set_end(Vec3::ZERO, 90.0, Vec3::ZERO)
        .unwrap_err()
        .contains("axis has zero length"));
    assert!(scene
        .set_end(Vec3::X, 90.0, Vec3::new(0.0, f32::NAN, 0.0))
        .unwrap_err()
        .contains("ty"));
    assert!(scene
        .set_end_quat(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0), Vec3::ZERO)
        .unwrap_err()
        .contains("zero length"));
    let mut sheared = Mat4::IDENTITY;
    sheared.y_axis.x = 0.5;
    assert!(scene
        .set_end_matrix(sheared)
        .unwrap_err()
        .contains("not orthonormal"));
    assert!(scene.draw(&mut Frame::default(), 2.0).is_err());
}

#[test]
fn dual_quat_feedback_compares_at_the_current_t() {
    let mut scene = RigidMotion::new();
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    let note = scene.draw(&mut Frame::default(), 0.25).unwrap();
    assert!(
        note.starts_with(
            "Your dual_quat_apply matches the reference at t = 0.250 (the green frame's nose) and at 5 more inputs"
        ),
        "{note}"
    );
    scene.set_runner(wrong);
    let note = scene.draw(&mut Frame::default(), 0.25).unwrap();
    assert!(
        note.starts_with(
            "Your dual_quat_apply differs at t = 0.250 (the green frame's nose): yours ("
        ),
        "{note}"
    );
    // The note names the part that is wrong: here q is right and the moved point is not.
    assert!(
        note.contains("your q is right and the moved point is not"),
        "{note}"
    );
    scene.set_runner(wrong_dual_part);
    let note = scene.draw(&mut Frame::default(), 0.25).unwrap();
    assert!(note.contains("your q itself differs"), "{note}");
    scene.set_runner(wrong);
    // The figure shows the student's (wrong) nose path.
    let mine = scene.point(
        Method::DualQuatNlerp,
        0.5,
        inbetween::figures::rigid::TIP,
        true,
    );
    let theirs = scene.point(
        Method::DualQuatNlerp,
        0.5,
        inbetween::figures::rigid::TIP,
        false,
    );
    assert!((mine - theirs).length() > 0.05);
    scene.set_runner(panics);
    let note = scene.draw(&mut Frame::default(), 0.25).unwrap();
    assert!(
        note.starts_with("Your exercise 4.1 dual_quat_apply panicked: index out of bounds"),
        "{note}"
    );
    let shown = scene.point(Method::DualQuatNlerp, 0.5, Vec3::ZERO, true);
    assert!(
        (shown
            - scene
                .motion(Method::DualQuatNlerp, 0.5)
                .transform_point(Vec3::ZERO))
        .length()
            < 1e-6
    );
}

#[test]
fn polar_feedback_checks_one_step_and_the_limit() {
    let mut scene = AffineKeys::new();
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    let note = scene.note().to_string();
    assert!(
        note.starts_with("Your polar_step matches the reference at key B's matrix"),
        "{note}"
    );
    assert!(
        note.contains("to a rotation; the figure uses your split"),
        "{note}"
    );
    scene.set_runner(wrong);
    let note = scene.note().to_string();
    assert!(
        note.starts_with(
            "Your polar_step differs at key B's matrix (one step from R₀ = M): yours ("
        ),
        "{note}"
    );
    scene.set_runner(panics);
    assert!(
        scene
            .note()
            .starts_with("Your exercise 4.2 polar_step panicked"),
        "{}",
        scene.note()
    );
    assert_eq!(
        scene.draw(&mut Frame::default(), 0.5).unwrap(),
        scene.note()
    );
    if !cfg!(feature = "solutions") {
        scene.set_runner(direct);
        assert!(
            scene
                .note()
                .starts_with("Not done yet: exercise 4.2 polar_step"),
            "{}",
            scene.note()
        );
    }
}

#[test]
fn singular_is_judged_relative_to_the_size_of_the_columns() {
    // Huge or tiny but well-shaped keys are invertible.
    let huge = Mat4::from_scale(Vec3::new(1e38, 1.0, 1.0));
    let key = AffineKey::from_mat4(huge).expect("det 1e38 is not singular");
    assert!(key.rotation.abs_diff_eq(Quat::IDENTITY, 1e-5));
    assert!(AffineKey::from_mat4(Mat4::from_scale(Vec3::splat(1e-12))).is_ok());
    let mut scene = AffineKeys::new();
    // The figure's keys have a range: a 1e38 scale would make its determinant plot NaN.
    let e = scene
        .set_key(0, Mat4::from_translation(Vec3::Y) * huge)
        .unwrap_err();
    assert!(e.contains("[-10000, 10000]"), "{e}");
    let large = Mat4::from_scale(Vec3::new(1e4, 1.0, 1.0));
    assert!(scene
        .set_key(0, Mat4::from_translation(Vec3::Y) * large)
        .is_ok());
    // Nearly parallel columns of ordinary size are singular, and the message has no "-0.000e0".
    let flat = Mat3::from_cols(Vec3::X, Vec3::new(1.0, 1e-9, 0.0), Vec3::Z);
    let e = scene.set_key(1, Mat4::from_mat3(flat)).unwrap_err();
    assert!(e.contains("singular"), "{e}");
    let e = scene
        .set_key_b(30.0, Vec3::new(1.0, -0.0, 1.0), 0.2)
        .unwrap_err();
    assert!(e.contains("singular (determinant 0.000,"), "{e}");
    assert!(!e.contains("e0"), "{e}");
    let e = scene
        .set_key_b(30.0, Vec3::new(-1.0, 1.0, 1.0), 0.0)
        .unwrap_err();
    assert!(e.contains("mirrors space (determinant -1.000 < 0)"), "{e}");
    assert!(scene
        .set_key(2, Mat4::IDENTITY)
        .unwrap_err()
        .contains("key must be 0"));
    let mut projective = Mat4::IDENTITY;
    projective.x_axis.w = 0.5;
    assert!(scene
        .set_key(1, projective)
        .unwrap_err()
        .contains("not affine"));
}

#[test]
fn polar_keeps_volume_positive_and_naive_lerp_does_not() {
    let scene = AffineKeys::new();
    let det = scene.sample_determinant(41).unwrap();
    assert!(det.iter().all(|r| r[2] > 0.0), "polar never flattens");
    let naive_min = det.iter().map(|r| r[1]).fold(f32::MAX, f32::min);
    assert!(
        naive_min < 0.5 * det[0][1].min(det[40][1]),
        "naive lerp shrinks: {naive_min}"
    );
}

use inbetween::figures::rigid::TIP;

const THREE: [Method; 3] = [Method::LerpSlerp, Method::DualQuatNlerp, Method::Screw];

#[test]
fn the_blend_turns_about_the_screw_axis_and_only_its_timing_differs() {
    let scene = RigidMotion::new();
    let axis = scene.screw_axis();
    let mut worst_slide: f32 = 0.0;
    for k in 0..=40 {
        let t = k as f32 / 40.0;
        let s = scene.screw_time_of_blend(t);
        assert!((0.0..=1.0 + 1e-4).contains(&s), "{s}");
        // At the same turn, blend and screw differ by a slide along the screw axis only.
        let gap =
            scene.motion(Method::DualQuatNlerp, t) * scene.motion(Method::Screw, s).conjugate();
        let (r, slide) = gap.to_rotation_translation();
        assert!(
            r.angle_between(Quat::IDENTITY) < 2e-3,
            "t = {t}: a turn of {}",
            r.angle_between(Quat::IDENTITY)
        );
        let across = slide - axis.direction * slide.dot(axis.direction);
        assert!(across.length() < 2e-3, "t = {t}: {across} off the axis");
        worst_slide = worst_slide.max(slide.length());
    }
    // The page: "at most 9 cm", of a slide of 1.40 m.
    assert!((0.085..0.095).contains(&worst_slide), "{worst_slide}");
    assert!((scene.largest_blend_lead_m() - worst_slide).abs() < 2e-3);
    assert!(
        (axis.displacement - 1.40).abs() < 0.005,
        "{}",
        axis.displacement
    );
    // The distance travelled by the nose: the screw's grows in a straight line, the blend's
    // slowly at the ends; they end within 1 % of each other, lerp + slerp's path is shorter.
    let d = scene.sample_distance(101).unwrap();
    let end = d[100];
    assert!((end[2] - end[3]).abs() < 0.01 * end[3], "{end:?}");
    assert!(end[1] < 0.9 * end[3], "{end:?}");
    for row in &d {
        assert!(
            (row[3] - row[0] * end[3]).abs() < 0.01 * end[3],
            "screw at constant speed: {row:?}"
        );
    }
    assert!(
        d[10][2] < 0.75 * d[10][3],
        "the blend starts slowly: {:?}",
        d[10]
    );
}

#[test]
fn at_half_a_turn_the_blend_is_2_5_times_as_fast_in_the_middle() {
    let mut scene = RigidMotion::new();
    scene
        .set_end(Vec3::new(0.2, 1.0, 0.3), 180.0, Vec3::new(1.5, 1.4, 0.3))
        .unwrap();
    let speed = scene.sample_speed(101).unwrap();
    let ratio = speed[50][2] / speed[0][2];
    // The page says "2.5 times": the ratio rounds to it.
    assert!((2.45..2.55).contains(&ratio), "{ratio}");
    let screw: Vec<f32> = speed.iter().map(|r| r[3]).collect();
    let (lo, hi) = screw
        .iter()
        .fold((f32::MAX, 0.0f32), |(l, h), &x| (l.min(x), h.max(x)));
    assert!(hi - lo < 0.01 * hi, "the screw stays flat: {lo}..{hi}");
}

#[test]
fn only_lerp_slerp_depends_on_the_pivot() {
    let mut scene = RigidMotion::new();
    let before: Vec<Vec3> = THREE
        .iter()
        .map(|m| scene.point(*m, 0.5, TIP, false))
        .collect();
    scene.set_pivot(Vec3::new(1.5, 0.0, 0.0)).unwrap();
    let after: Vec<Vec3> = THREE
        .iter()
        .map(|m| scene.point(*m, 0.5, TIP, false))
        .collect();
    assert!(before[0].distance(after[0]) > 0.5, "lerp + slerp moves");
    assert!(before[1].distance(after[1]) < 1e-4, "the blend does not");
    assert!(before[2].distance(after[2]) < 1e-4, "the screw does not");
    // The keys themselves stay where they are.
    for m in THREE {
        for t in [0.0, 1.0] {
            let moved = scene.motion(m, t).transform_point(TIP);
            let key = if t == 0.0 {
                RigidMotion::new().motion(m, 0.0)
            } else {
                RigidMotion::new().motion(m, 1.0)
            };
            assert!(moved.distance(key.transform_point(TIP)) < 1e-4);
        }
    }
    assert!(scene
        .set_pivot(Vec3::new(0.0, f32::NAN, 0.0))
        .unwrap_err()
        .contains("pivot y"));
    assert!(scene
        .set_pivot(Vec3::new(9.0, 0.0, 0.0))
        .unwrap_err()
        .contains("pivot x"));
}

#[test]
fn with_no_turn_the_screw_axis_runs_through_the_keys() {
    let mut scene = RigidMotion::new();
    // With a turn, the drawn axis passes closest to the middle of the keys' origins.
    let axis = scene.screw_axis();
    let middle = Vec3::new(0.0, 1.0, 0.15);
    let to_middle = middle - axis.point;
    assert!(to_middle.dot(axis.direction).abs() < 1e-4);
    scene
        .set_end(Vec3::Y, 0.0, Vec3::new(1.5, 1.4, 0.3))
        .unwrap();
    let axis = scene.screw_axis();
    assert!(axis.point.distance(middle) < 1e-5, "{:?}", axis.point);
    let slide = Vec3::new(3.0, 0.8, 0.3);
    assert!(axis.direction.distance(slide.normalize()) < 1e-5);
    assert!((axis.displacement - slide.length()).abs() < 1e-4);
    // The three methods make one straight line at one speed (the page's Try this).
    let speed = scene.sample_speed(51).unwrap();
    for row in &speed {
        for m in 1..4 {
            assert!((row[m] - slide.length()).abs() < 2e-3, "{row:?}");
        }
    }
}

#[test]
fn probes_catch_what_the_figure_input_hides() {
    // A polar step with the inverse instead of the inverse transpose matches on a diagonal
    // key but not on a rotation.
    let mut scene = AffineKeys::new();
    scene.set_key_b(0.0, Vec3::new(2.0, 0.5, 1.0), 0.0).unwrap();
    scene.set_runner(wrong);
    scene.set_use_exercise(true);
    let note = scene.note().to_string();
    assert!(note.contains("(the figure's input), but"), "{note}");
    assert!(note.contains("a 40° turn about y"), "{note}");
    scene.set_runner(reference);
    let note = scene.note().to_string();
    assert!(note.contains("and at 4 more inputs"), "{note}");
    // dual_quat_apply that forgets the rotation differs on the quarter turn.
    let mut rigid = RigidMotion::new();
    rigid.set_use_exercise(true);
    rigid.set_runner(wrong);
    let note = rigid.exercise_note(0.0);
    assert!(note.contains("a quarter turn about z, no slide"), "{note}");
    rigid.set_runner(reference);
    assert!(rigid.exercise_note(0.3).contains("and at 5 more inputs"));
}

#[test]
fn the_affine_try_this_does_what_it_says() {
    let mut scene = AffineKeys::new();
    // Scales 1, shear 0: B is a pure rotation (160° about y), and the naive lerp still shrinks.
    scene.set_key_b(160.0, Vec3::ONE, 0.0).unwrap();
    let det = scene.sample_determinant(101).unwrap();
    assert!(det[50][1] < 0.5, "naive shrinks: {:?}", det[50]);
    assert!(
        det.iter().all(|r| (r[2] - 1.0).abs() < 1e-3),
        "polar keeps the volume"
    );
    // Angle 0 and scale x 2: the two methods agree exactly, volume 1 to 2 in a straight line.
    scene.set_key_b(0.0, Vec3::new(2.0, 1.0, 1.0), 0.0).unwrap();
    for r in scene.sample_determinant(11).unwrap() {
        assert!((r[1] - r[2]).abs() < 1e-4, "{r:?}");
        assert!((r[1] - (1.0 + r[0])).abs() < 1e-4, "{r:?}");
    }
}

#[test]
fn a_half_turn_is_described_with_a_forward_slide() {
    // Turning 180° about n is the same motion as turning 180° about −n: the figure names the
    // direction that slides forwards, the way a turn just short of 180° is named.
    let mut scene = RigidMotion::new();
    let n = Vec3::new(0.2, 1.0, 0.3);
    let t = Vec3::new(1.5, 1.4, 0.3);
    scene.set_end(n, 179.0, t).unwrap();
    let near = scene.screw_axis();
    for angle in [180.0, -180.0] {
        scene.set_end(n, angle, t).unwrap();
        let half = scene.screw_axis();
        assert!((half.angle_rad - std::f32::consts::PI).abs() < 1e-3);
        assert!(half.displacement > 0.0, "{angle}°: slide {}", half.displacement);
        assert!(half.direction.dot(near.direction) > 0.9, "{angle}°: {:?}", half.direction);
        // The same line: the key B it describes is unchanged.
        let moved = |axis: &inbetween::rigid::ScrewAxis, p: Vec3| {
            Quat::from_axis_angle(axis.direction, axis.angle_rad) * (p - axis.point)
                + axis.point
                + axis.direction * axis.displacement
        };
        let a = Vec3::new(-1.5, 0.6, 0.0);
        assert!((moved(&half, a) - t).length() < 1e-3, "{angle}°: {:?}", moved(&half, a));
    }
}

/// Where the three aeroplanes start (key A) and end (key B) together, the figure is not a pile:
/// with all three shown only the keys' own axes are drawn (a plane shown alone has its own
/// too), and each key's name is anchored above its key, at least 0.45 m from the centre of
/// every part of the planes there and from every point of the paths (the page places it a few
/// pixels higher still: tests/label_clearance.rs checks its box on screen).
#[test]
fn the_keys_stay_readable_where_the_planes_meet_them() {
    use inbetween::draw::{palette, AXIS_PX};
    let x_axes = |f: &Frame| {
        f.strokes
            .iter()
            .filter(|s| s.color[..3] == palette::X_AXIS.to_array() && s.width_px == AXIS_PX)
            .count()
    };
    let mut scene = RigidMotion::new();
    for (t, key) in [(0.0, "A"), (1.0, "B")] {
        let mut f = Frame::default();
        scene.draw(&mut f, t).unwrap();
        assert_eq!(x_axes(&f), 2, "the keys' axes alone at t = {t}");
        let label = f.labels.iter().find(|l| l.text == key).unwrap();
        let centres = f
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CUBE)
            .map(|m| m.model.w_axis.truncate());
        // The paths (the keys' axes are left out: the name sits just past the tip of its
        // key's y axis, which leads to it; so is the screw's plane's outline, whose boxes stand
        // where the blend's solid ones do at the keys).
        let outline = inbetween::figures::rigid::SCREW_OUTLINE_PX;
        let paths = f
            .strokes
            .iter()
            .filter(|s| s.width_px != AXIS_PX)
            .filter(|s| !(s.width_px == outline && s.color[..3] == palette::Z_AXIS.to_array()))
            .flat_map(|s| [Vec3::from(s.a), Vec3::from(s.b)]);
        let nearest = centres
            .chain(paths)
            .map(|p| (p - label.anchor).length())
            .fold(f32::INFINITY, f32::min);
        assert!(nearest >= 0.45, "{key}: {nearest} m from a plane or a path");
    }
    scene.set_show(1).unwrap();
    let mut f = Frame::default();
    scene.draw(&mut f, 0.0).unwrap();
    assert_eq!(x_axes(&f), 3, "a plane shown alone has its axes");
}

#[test]
fn where_blend_and_screw_coincide_both_planes_show() {
    // The blend and the screw put the plane in the same place at the keys and half-way, and
    // up to 0.18 m apart between: with both shown, the screw's (blue) is an outline, 12 edges a
    // box, and the blend's (green) a solid inside it, at its own size.
    use inbetween::draw::palette;
    use inbetween::figures::rigid::SCREW_OUTLINE_PX;
    let solid = |frame: &Frame, color: Vec3| {
        frame
            .meshes
            .iter()
            .filter(|d| d.color.truncate().distance(color * 0.8) < 1e-5)
            // Its half span in centimetres, rounded.
            .map(|d| (d.model.z_axis.truncate().length() * 100.0).round())
            .collect::<Vec<f32>>()
    };
    let outline = |frame: &Frame| {
        frame
            .strokes
            .iter()
            .filter(|s| s.color[..3] == palette::Z_AXIS.to_array() && s.width_px == SCREW_OUTLINE_PX)
            .count()
    };
    let mut scene = RigidMotion::new();
    assert!(scene.coincides_with_screw(0.5) && !scene.coincides_with_screw(0.25));
    for t in [0.5, 0.0, 1.0, 0.25, 0.58] {
        let mut frame = Frame::default();
        scene.draw(&mut frame, t).unwrap();
        // The wing (the part in 0.8 of the plane's colour), at its own size.
        assert_eq!(solid(&frame, palette::Y_AXIS), [50.0], "t {t}: the blend's solid wing");
        assert!(solid(&frame, palette::Z_AXIS).is_empty(), "t {t}: no solid screw plane");
        assert_eq!(outline(&frame), 4 * 12, "t {t}: the screw's plane's edges");
    }
    // Shown alone, each is solid.
    for (show, color) in [(2, palette::Y_AXIS), (3, palette::Z_AXIS)] {
        scene.set_show(show).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame, 0.5).unwrap();
        assert_eq!(solid(&frame, color), [50.0], "show {show}");
        assert_eq!(outline(&frame), 0, "show {show}");
    }
}

#[test]
fn the_affine_keys_wireframes_tell_a_from_b() {
    // The caption names key A's wireframe grey and dashed, key B's dark and solid: two greys
    // alone, 1.5 px wide, read as one colour.
    use inbetween::draw::palette;
    let mut scene = AffineKeys::new();
    let mut f = Frame::default();
    scene.draw(&mut f, 0.3).unwrap();
    let color = |s: &inbetween::draw::StrokeSegment| Vec3::new(s.color[0], s.color[1], s.color[2]);
    let a: Vec<_> = f.strokes.iter().filter(|s| color(s) == palette::GREY).collect();
    let b: Vec<_> = f.strokes.iter().filter(|s| color(s) == palette::DARK).collect();
    // 12 edges a box, one box a side.
    assert_eq!((a.len(), b.len()), (24, 24));
    assert!(a.iter().all(|s| s.dash[3] > 0.0), "A dashed");
    assert!(b.iter().all(|s| s.dash[3] == 0.0), "B solid");
}


#[test]
fn a_constant_speed_is_plotted_flat_and_a_varying_one_is_not() {
    // Lesson 04's Try this: at 0° the three methods slide along one line at one constant speed,
    // and the screw keeps one speed at any angle. The plot autoscales down to half a metre per
    // unit of t and snaps to whole pixels: speeds that differ by round-off would draw as
    // one-pixel steps, so a constant speed must come out as one number.
    let flat = |scene: &RigidMotion, method: usize| {
        let speed = scene.sample_speed(101).unwrap();
        speed.iter().all(|r| r[method] == speed[0][method])
    };
    let mut scene = RigidMotion::new();
    scene
        .set_end(Vec3::new(0.2, 1.0, 0.3), 0.0, Vec3::new(1.5, 1.4, 0.3))
        .unwrap();
    for method in 1..=3 {
        assert!(flat(&scene, method), "0°, method {method}");
    }
    let slide = scene.sample_speed(2).unwrap()[0][1];
    assert!((slide - Vec3::new(3.0, 0.8, 0.3).length()).abs() < 1e-3, "{slide}");
    // The screw at the default key and at a few others.
    for (angle, axis, to) in [
        (150.0, Vec3::new(0.2, 1.0, 0.3), Vec3::new(1.5, 1.4, 0.3)),
        (180.0, Vec3::new(0.2, 1.0, 0.3), Vec3::new(0.0, 0.0, 0.0)),
        (-120.0, Vec3::new(1.0, 0.0, 0.0), Vec3::new(3.0, 0.0, -3.0)),
    ] {
        scene.set_end(axis, angle, to).unwrap();
        assert!(flat(&scene, 3), "screw at {angle}°");
    }
    // A turn of 5° changes the lerp + slerp and blend speeds by about a tenth of a percent: that
    // is motion, not round-off, and is kept.
    scene
        .set_end(Vec3::new(0.2, 1.0, 0.3), 5.0, Vec3::new(1.5, 1.4, 0.3))
        .unwrap();
    assert!(!flat(&scene, 1) && !flat(&scene, 2));
    assert!(flat(&scene, 3));
}

#[test]
fn the_blend_trails_the_screw_along_the_axis_then_leads_it_by_as_much() {
    // The page: at the same turn the blend trails the screw along the axis, by at most 9 cm with
    // the default key B, then leads it by as much; not at all at the keys and half-way, nor with
    // no turn.
    let mut scene = RigidMotion::new();
    let lead: Vec<f32> = (0..=64).map(|k| scene.blend_lead_m(k as f32 / 64.0)).collect();
    for (k, &l) in lead.iter().enumerate() {
        let mirrored = lead[64 - k];
        assert!((l + mirrored).abs() < 2e-3, "t = {k}/64: {l} vs {mirrored}");
        match k {
            0 | 32 | 64 => assert!(l.abs() < 1e-3, "t = {k}/64: {l}"),
            1..=31 => assert!(l < 0.0, "behind at t = {k}/64: {l}"),
            _ => assert!(l > 0.0, "ahead at t = {k}/64: {l}"),
        }
    }
    let largest = scene.largest_blend_lead_m();
    assert!((0.085..0.095).contains(&largest), "{largest}");
    assert_eq!(format!("{:.0}", largest * 100.0), "9");
    // Behind, then ahead, for other keys and pivots too.
    for (angle, to, pivot) in [
        (180.0, Vec3::new(1.5, 1.4, 0.3), 0.0),
        (-120.0, Vec3::new(3.0, 0.0, -3.0), 1.5),
        (60.0, Vec3::new(-2.0, 2.0, 1.0), -1.0),
    ] {
        scene.set_end(Vec3::new(0.2, 1.0, 0.3), angle, to).unwrap();
        scene.set_pivot(Vec3::new(pivot, 0.0, 0.0)).unwrap();
        assert!(scene.blend_lead_m(0.25) < 0.0 && scene.blend_lead_m(0.75) > 0.0, "{angle}°");
        assert!(scene.largest_blend_lead_m() > 0.005, "{angle}°");
    }
    scene
        .set_end(Vec3::new(0.2, 1.0, 0.3), 0.0, Vec3::new(1.5, 1.4, 0.3))
        .unwrap();
    assert!(scene.largest_blend_lead_m() < 1e-4);
}

/// Figure 1: the keys' axes are drawn over the aeroplanes, which start and end on them (else
/// "A" names axes hidden in the orange aeroplane).
#[test]
fn the_keys_axes_show_over_the_aeroplanes() {
    use inbetween::draw::{palette, ON_TOP};
    let mut scene = RigidMotion::new();
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.0).unwrap();
    let keys: Vec<_> = frame
        .strokes
        .iter()
        .filter(|s| s.color[..3] == palette::X_AXIS.to_array()[..])
        .filter(|s| (Vec3::from(s.b).distance(Vec3::from(s.a)) - 0.5).abs() < 1e-4)
        .collect();
    assert_eq!(keys.len(), 2, "each key's x axis, 0.5 m long");
    assert!(keys.iter().all(|s| s.depth_bias == ON_TOP));
}
