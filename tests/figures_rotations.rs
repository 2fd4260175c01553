//! Native tests of lesson 03's figures (src/figures/rotations.rs): what they draw, what they
//! reject, and what their notes say about the student's exercises.

use glam::{Mat3, Quat, Vec3};
use inbetween::draw::{Frame, MeshId};
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::rotations::{
    rodrigues_colors as rc, Gimbal, Interpolation, Method, Rodrigues,
};
use inbetween::rotation::{self, slerp_arc, Arc};

/// The reference for every exercise: a correct student.
fn reference(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let q = |i: usize| Quat::from_slice(&args[i..i + 4]);
    let v = |i: usize| Vec3::from_slice(&args[i..i + 3]);
    Ok(match name {
        "slerp" => rotation::slerp(q(0), q(4), args[8]).to_array().to_vec(),
        "rodrigues_matrix" => rotation::rodrigues_mat3(v(0), args[3])
            .to_cols_array()
            .to_vec(),
        "quat_from_axis_angle" => rotation::quat_from_axis_angle(v(0), args[3])
            .to_array()
            .to_vec(),
        _ => return direct(name, args),
    })
}

/// A slerp that forgets to negate b when a·b < 0; a Rodrigues matrix that is transposed; a
/// quaternion twice too long.
fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let q = |i: usize| Quat::from_slice(&args[i..i + 4]);
    let v = |i: usize| Vec3::from_slice(&args[i..i + 3]);
    Ok(match name {
        "slerp" => {
            let (a, b) = (q(0), q(4));
            let arc = if a.dot(b) < 0.0 {
                Arc::Long
            } else {
                Arc::Short
            };
            slerp_arc(a, b, args[8], arc).to_array().to_vec()
        }
        "rodrigues_matrix" => rotation::rodrigues_mat3(v(0), args[3])
            .transpose()
            .to_cols_array()
            .to_vec(),
        "quat_from_axis_angle" => (rotation::quat_from_axis_angle(v(0), args[3]) * 2.0)
            .to_array()
            .to_vec(),
        _ => return direct(name, args),
    })
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "not yet implemented (src/exercises/rotations.rs:42:5)".into(),
    ))
}

/// Keys whose quaternions have a·b < 0, so the short arc needs −b.
fn opposite_keys() -> Interpolation {
    let mut scene = Interpolation::new();
    let end = Interpolation::new().end_quat_used();
    let start = Quat::IDENTITY;
    assert!(start.dot(end) > 0.0);
    scene.set_keys_euler_deg(Vec3::ZERO, Vec3::ZERO).unwrap();
    scene.set_end_quat(-end).unwrap();
    scene
}

/// The length of the path drawn in `color` (all its segments).
fn path_length(frame: &Frame, color: Vec3) -> f32 {
    frame.segments_of(color).map(|(a, b)| a.distance(b)).sum()
}

#[test]
fn a_turn_about_the_nose_axis_still_draws_a_path() {
    // Keys 170° and −170° about x: every nose stays put, the wing tips sweep arcs.
    let mut scene = Interpolation::new();
    scene
        .set_keys_euler_deg(Vec3::new(170.0, 0.0, 0.0), Vec3::new(-170.0, 0.0, 0.0))
        .unwrap();
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.5).unwrap();
    for (method, _, color) in inbetween::figures::rotations::METHODS {
        let drawn = path_length(&frame, color * 0.8);
        // The short arc (20°) at a wing tip 0.5 m out is 0.17 m; Euler lerp's 340° is 3 m; matrix
        // lerp's chord is 0.17 m.
        assert!(drawn > 0.15, "{method:?}: {drawn} m of path");
    }
}

#[test]
fn default_keys_make_euler_lerp_wobble() {
    let mut scene = Interpolation::new();
    let mut deviation: f32 = 0.0;
    for k in 0..=20 {
        let t = k as f32 / 20.0;
        let euler = Quat::from_mat3(&scene.orientation(Method::EulerLerp, t, false));
        let slerp = Quat::from_mat3(&scene.orientation(Method::Slerp, t, false));
        deviation = deviation.max(euler.angle_between(slerp).to_degrees());
    }
    // The page: "strays up to 39° from slerp", and the note under the figure reads the same.
    assert!(
        (38.5..39.5).contains(&deviation),
        "Euler lerp strays {deviation}° from slerp"
    );
    let (t_max, max) = scene.max_euler_deviation_deg();
    assert!((max - deviation).abs() < 0.5, "{max} against {deviation}");
    assert!((0.0..=1.0).contains(&t_max));
    let note = scene.draw(&mut Frame::default(), t_max).unwrap();
    assert!(
        note.contains(&format!(
            "Euler lerp is 39° from slerp at t = {t_max:.2}; at most 39° (at t = {t_max:.2})."
        )),
        "{note}"
    );
    let note = scene.draw(&mut Frame::default(), 0.0).unwrap();
    assert!(
        note.contains("Euler lerp is 0° from slerp at t = 0.00"),
        "{note}"
    );
    let speeds: Vec<[f32; 4]> = scene.sample_angular_speed(41).unwrap();
    let euler: Vec<f32> = speeds.iter().map(|r| r[1]).collect();
    let (lo, hi) = euler
        .iter()
        .fold((f32::MAX, 0.0f32), |(lo, hi), &s| (lo.min(s), hi.max(s)));
    assert!(hi > 2.0 * lo, "Euler lerp speed {lo}..{hi}");
    let slerp: Vec<f32> = speeds.iter().map(|r| r[3]).collect();
    let spread =
        slerp.iter().cloned().fold(0.0, f32::max) - slerp.iter().cloned().fold(f32::MAX, f32::min);
    assert!(
        spread < 0.02 * slerp[0],
        "slerp speed is constant: {slerp:?}"
    );
}

#[test]
fn keys_about_one_axis_say_euler_lerp_follows_slerp() {
    // The caption's Try this: end key (0, 90, 0), a turn about y alone.
    let mut scene = Interpolation::new();
    scene
        .set_keys_euler_deg(Vec3::ZERO, Vec3::new(0.0, 90.0, 0.0))
        .unwrap();
    let (_, max) = scene.max_euler_deviation_deg();
    assert!(max < 0.5, "{max}°");
    let note = scene.draw(&mut Frame::default(), 0.3).unwrap();
    assert!(
        note.contains("Euler lerp follows slerp here: they are under 0.5° apart at every t."),
        "{note}"
    );
    assert!(!note.contains("at most"), "no largest to point at: {note}");
}

#[test]
fn each_wing_tip_carries_a_dot_where_its_dashed_path_is_now() {
    let mut scene = Interpolation::new();
    for t in [0.0, 0.4, 1.0] {
        let mut frame = Frame::default();
        scene.draw(&mut frame, t).unwrap();
        for (method, x, color) in inbetween::figures::rotations::METHODS {
            let tip = Vec3::new(x, 1.2, 0.0)
                + scene.orientation(method, t, false) * Vec3::new(0.05, 0.0, 0.5);
            assert!(
                frame
                    .markers
                    .iter()
                    .any(|m| Vec3::from(m.center).distance(tip) < 1e-4
                        && glam::Vec4::from(m.color).truncate().distance(color * 0.8) < 1e-4),
                "{method:?} at t = {t}: no dot on the wing tip {tip}"
            );
        }
    }
}

#[test]
fn long_arc_note_gives_both_angles_adding_to_a_turn() {
    let mut scene = Interpolation::new();
    let (short, long) = scene.arc_angles_deg();
    assert!((short + long - 360.0).abs() < 1e-3 && short < 180.0);
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, 0.5).unwrap();
    assert!(note.starts_with("Euler lerp is "), "{note}");
    scene.set_long_arc(true);
    let note = scene.draw(&mut frame, 0.5).unwrap();
    assert!(note.contains("the other way round"), "{note}");
    assert!(
        note.contains(&format!("{long:.3}°")) && note.contains(&format!("{short:.3}°")),
        "{note}"
    );
    // The long-arc slerp really turns by the long angle at the midpoint: half of it.
    let mid = Quat::from_mat3(&scene.orientation(Method::Slerp, 0.5, false));
    let turned = mid.angle_between(Quat::IDENTITY).to_degrees();
    assert!(
        (turned - (360.0 - long / 2.0).min(long / 2.0)).abs() < 0.1,
        "{turned}"
    );
}

#[test]
fn slerp_feedback_checks_the_answer_and_the_arc() {
    let mut scene = opposite_keys();
    scene.set_use_exercise(true);
    let mut frame = Frame::default();

    scene.set_runner(reference);
    let note = scene.draw(&mut frame, 0.25).unwrap();
    assert!(
        note.starts_with("Your slerp matches the reference at t = 0.250 and at 5 more inputs"),
        "{note}"
    );
    assert!(note.contains("takes the short arc"), "{note}");

    scene.set_runner(wrong);
    let note = scene.draw(&mut frame, 0.25).unwrap();
    assert!(
        note.starts_with("Your slerp differs at t = 0.250: yours ("),
        "{note}"
    );
    assert!(note.contains("reference ("), "{note}");
    assert!(
        note.contains("your slerp takes the long arc: negate b"),
        "{note}"
    );
    // The figure shows what the student's code does: the slerp plane follows the long arc.
    let shown = Quat::from_mat3(&scene.orientation(Method::Slerp, 0.5, true));
    let (a, b) = (Quat::IDENTITY, scene.end_quat_used());
    assert!(shown.angle_between(slerp_arc(a, b, 0.5, Arc::Long)) < 1e-3);

    // With long arc ticked the note still checks the student's code, not a fixed sentence.
    scene.set_long_arc(true);
    let note = scene.draw(&mut frame, 0.25).unwrap();
    assert!(
        note.contains("differs") && note.contains("takes the long arc:"),
        "{note}"
    );
    scene.set_runner(reference);
    let note = scene.draw(&mut frame, 0.25).unwrap();
    assert!(
        note.contains("matches") && note.contains("takes the short arc"),
        "{note}"
    );
}

#[test]
fn slerp_feedback_reports_a_panic_and_draws_the_reference() {
    let mut scene = opposite_keys();
    scene.set_use_exercise(true);
    scene.set_runner(panics);
    let note = scene.draw(&mut Frame::default(), 0.3).unwrap();
    assert!(
        note.starts_with("Your exercise 3.2 slerp panicked: not yet implemented"),
        "{note}"
    );
    let shown = scene.orientation(Method::Slerp, 0.3, true);
    let expected = scene.orientation(Method::Slerp, 0.3, false);
    assert!(shown.abs_diff_eq(expected, 1e-6));
}

#[test]
fn stubs_say_not_done_yet() {
    if cfg!(feature = "solutions") {
        return;
    }
    let mut scene = Interpolation::new();
    scene.set_use_exercise(true);
    let note = scene.draw(&mut Frame::default(), 0.3).unwrap();
    assert!(
        note.starts_with("Not done yet: exercise 3.2 slerp"),
        "{note}"
    );
    let mut rod = Rodrigues::new();
    rod.set_use_exercise(true);
    let note = rod.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("Not done yet: exercise 3.3 rodrigues_matrix"),
        "{note}"
    );
    assert!(
        note.contains("Not done yet: exercise 3.1 quat_from_axis_angle"),
        "{note}"
    );
}

#[test]
fn interpolation_rejects_bad_input() {
    let mut scene = Interpolation::new();
    assert!(scene
        .set_keys_euler_deg(Vec3::new(f32::NAN, 0.0, 0.0), Vec3::ZERO)
        .unwrap_err()
        .contains("start x"));
    assert!(scene
        .set_end_quat(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0))
        .unwrap_err()
        .contains("zero length"));
    assert!(scene
        .set_end_matrix(Mat3::from_diagonal(Vec3::new(2.0, 1.0, 1.0)))
        .unwrap_err()
        .contains("not orthonormal"));
    assert!(scene
        .draw(&mut Frame::default(), 1.5)
        .unwrap_err()
        .contains("t must lie in [0, 1]"));
    assert!(scene.sample_determinant(1).is_err());
}

#[test]
fn gimbal_lock_note_names_the_sum_the_matrix_keeps() {
    let mut g = Gimbal::new();
    // At pitch +90° the read-back is yaw − roll (R_x(90°) takes z to −y): 30 − 20 = 10.
    g.set_angles_deg(30.0, 90.0, 20.0).unwrap();
    let (back, locked) = g.decomposed_deg();
    assert!(locked);
    assert!(
        (back.x - 10.0).abs() < 1e-3 && back.z.abs() < 1e-3,
        "{back:?}"
    );
    assert_eq!(g.lock_sign(), -1.0);
    let note = g.note();
    assert!(
        note.contains("only yaw − roll = 10.000° is determined"),
        "{note}"
    );
    assert!(
        note.contains("yaw 10.000°, pitch 90.000°, roll 0.000°"),
        "{note}"
    );
    // At −90° it is yaw + roll: 30 + 20 = 50.
    g.set_angles_deg(30.0, -90.0, 20.0).unwrap();
    let (back, _) = g.decomposed_deg();
    assert!((back.x - 50.0).abs() < 1e-3, "{back:?}");
    assert!(
        g.note().contains("only yaw + roll = 50.000° is determined"),
        "{}",
        g.note()
    );
    // Away from the lock the angles read back as set.
    g.set_angles_deg(30.0, 40.0, 20.0).unwrap();
    let (back, locked) = g.decomposed_deg();
    assert!(!locked && (back - Vec3::new(30.0, 40.0, 20.0)).abs().max_element() < 1e-3);
    assert!(
        g.note()
            .starts_with("Angle between the yaw and roll axles: 50.000°."),
        "{}",
        g.note()
    );
    assert!(g
        .set_angles_deg(0.0, f32::INFINITY, 0.0)
        .unwrap_err()
        .contains("pitch"));
}

#[test]
fn gimbal_rings_turn_red_at_lock_and_axles_are_labelled() {
    let mut g = Gimbal::new();
    let mut frame = Frame::default();
    g.draw(&mut frame);
    let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(texts, ["yaw axle", "pitch axle", "roll axle"]);
    let red = |f: &Frame| {
        f.meshes
            .iter()
            .filter(|m| m.color.truncate() == inbetween::figures::rotations::LOCK_WARNING)
            .count()
    };
    let before = red(&frame);
    g.set_angles_deg(30.0, 90.0, 20.0).unwrap();
    let mut frame = Frame::default();
    g.draw(&mut frame);
    assert_eq!(red(&frame), before + 80, "outer and middle rings warn");
}

#[test]
fn the_gimbal_axles_show_over_the_rings_at_lock() {
    // At gimbal lock the pitch axle lies in the plane of the two locked rings and the roll axle
    // along the yaw axle: depth-tested, each hides inside a ring's edge on screen, and its name
    // names nothing visible. Each axle and its line on to its name are drawn over everything.
    let mut g = Gimbal::new();
    g.set_angles_deg(30.0, 90.0, 20.0).unwrap();
    let mut frame = Frame::default();
    g.draw(&mut frame);
    for color in inbetween::figures::rotations::GIMBAL_COLORS {
        let axle: Vec<_> = (frame.strokes.iter())
            .filter(|s| s.color[..3] == color.to_array())
            .collect();
        assert_eq!(axle.len(), 2, "{color}: the axle and the line to its name");
        assert!(axle.iter().all(|s| s.depth_bias == inbetween::draw::ON_TOP), "{color}");
    }
}

#[test]
fn the_key_circle_stays_face_on() {
    // The circle of unit quaternions is a plane diagram: a drag pans it instead of orbiting (an
    // orbit turned the circle into a thin ellipse, and a and −b, 10° apart at the 170° preset,
    // ran together).
    let mut scene = Interpolation::new();
    let mut frame = Frame::default();
    scene.draw_circle(&mut frame, 0.3).unwrap();
    assert!(frame.flat);
}

#[test]
fn gimbal_rings_show_the_colours_the_page_names() {
    // The page calls the rings green, orange and blue: each ring's boxes are drawn unlit in
    // that colour (the light would turn the thin, side-lit boxes a darker shade, orange to
    // brown).
    let mut frame = Frame::default();
    Gimbal::new().draw(&mut frame);
    for color in inbetween::figures::rotations::GIMBAL_COLORS {
        let ring: Vec<_> = (frame.meshes.iter())
            .filter(|m| m.color.truncate() == color)
            .collect();
        assert_eq!(ring.len(), 40, "{color}");
        assert!(ring.iter().all(|m| m.unlit), "{color}: lit");
    }
}

#[test]
fn nlerp_is_slower_than_slerp_at_the_ends_and_crosses_it_near_a_fifth() {
    // The page: nlerp is slower than slerp at both ends, faster in the middle, and the two
    // speed curves cross near t = 0.2 and 0.8 (at the default keys, one axis, a half turn and
    // the 170° / −170° preset, all on the short arc).
    let keys = [
        (Vec3::ZERO, Interpolation::END_DEG),
        (Vec3::ZERO, Vec3::new(0.0, 90.0, 0.0)),
        (Vec3::ZERO, Vec3::new(180.0, 0.0, 0.0)),
        (Vec3::new(170.0, 0.0, 0.0), Vec3::new(-170.0, 0.0, 0.0)),
    ];
    for (start, end) in keys {
        let mut scene = Interpolation::new();
        scene.set_keys_euler_deg(start, end).unwrap();
        let speeds = scene.sample_angular_speed(401).unwrap();
        let gap: Vec<(f32, f32)> = speeds.iter().map(|r| (r[0], r[2] - r[3])).collect();
        let (first, last) = (gap[0].1, gap[gap.len() - 1].1);
        assert!(first < 0.0 && last < 0.0, "{end}: nlerp not slower at the ends");
        let crossings: Vec<f32> = (gap.windows(2))
            .filter(|w| (w[0].1 < 0.0) != (w[1].1 < 0.0))
            .map(|w| 0.5 * (w[0].0 + w[1].0))
            .collect();
        assert_eq!(crossings.len(), 2, "{start} to {end}: {crossings:?}");
        assert!(
            (0.19..0.25).contains(&crossings[0]) && (0.75..0.81).contains(&crossings[1]),
            "{start} to {end}: {crossings:?}"
        );
    }
}

fn cone_tip(frame: &Frame, color: Vec3) -> Vec3 {
    let cone = frame
        .meshes
        .iter()
        .find(|m| m.mesh == MeshId::CONE && m.color.truncate() == color)
        .expect("an arrow of that colour");
    cone.model.transform_point3(Vec3::Y)
}

#[test]
fn rodrigues_draws_labelled_terms_that_add_up_to_the_rotated_vector() {
    let mut scene = Rodrigues::new();
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.5).unwrap();
    let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    for t in [
        "n",
        "v",
        "v cos θ",
        "(n × v) sin θ",
        "n (n·v)(1 − cos θ)",
        "v′ = R v",
    ] {
        assert!(texts.contains(&t), "{t} in {texts:?}");
    }
    let colors = [
        rc::AXIS,
        rc::V,
        rc::ROTATED,
        rc::COS_PART,
        rc::SIN_PART,
        rc::AXIAL_PART,
    ];
    for (i, a) in colors.iter().enumerate() {
        for b in &colors[i + 1..] {
            assert_ne!(a, b, "distinct colours");
        }
    }
    let n = Vec3::new(0.3, 1.0, 0.2).normalize();
    let v = Vec3::new(1.2, 0.4, 0.3);
    let expected = rotation::rodrigues_rotate(v, n, 60f32.to_radians());
    assert!((cone_tip(&frame, rc::ROTATED) - expected).length() < 1e-4);
    assert!(
        (cone_tip(&frame, rc::AXIAL_PART) - expected).length() < 1e-4,
        "the terms end at v′"
    );
    // The page shows R as 3×3.
    let r: Mat3 = scene.matrix();
    assert!(r.abs_diff_eq(rotation::rodrigues_mat3(n, 120f32.to_radians()), 1e-5));
    // With v along the axis, v, v′ and the terms lie on the axis: its line is drawn before them
    // and wider, so its purple shows either side of them.
    scene.set_vector(n * 1.5).unwrap();
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.5).unwrap();
    let first = |c: Vec3| frame.strokes.iter().position(|s| s.color[..3] == c.to_array());
    let axis = &frame.strokes[first(rc::AXIS).unwrap()];
    for c in [rc::V, rc::ROTATED, rc::COS_PART, rc::AXIAL_PART] {
        let term = &frame.strokes[first(c).unwrap()];
        assert!(first(c) > first(rc::AXIS) && term.width_px < axis.width_px - 2.0);
    }
}

/// v cos θ runs along v from the origin: v's arrow is drawn after it (over it), so that v shows
/// whole and not only past the term's head.
#[test]
fn rodrigues_draws_v_over_its_cos_term() {
    let mut scene = Rodrigues::new();
    for s in [0.12, 0.25, 0.5] {
        let mut frame = Frame::default();
        scene.draw(&mut frame, s).unwrap();
        let from_origin = |c: Vec3| -> Vec<usize> {
            (0..frame.strokes.len())
                .filter(|&i| {
                    let st = &frame.strokes[i];
                    st.color[..3] == c.to_array() && Vec3::from(st.a).length() < 1e-6
                })
                .collect()
        };
        let (v, cos) = (from_origin(rc::V), from_origin(rc::COS_PART));
        assert!(!v.is_empty() && !cos.is_empty(), "s {s}");
        assert!(
            v.iter().min() > cos.iter().max(),
            "s {s}: v's shaft {v:?} is drawn before v cos θ's {cos:?}"
        );
    }
}

#[test]
fn rodrigues_feedback_compares_and_checks_validity() {
    let mut scene = Rodrigues::new();
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("Your rodrigues_matrix matches the reference at θ = 120.000° and at 4 more"),
        "{note}"
    );
    assert!(
        note.contains(
            "Your quat_from_axis_angle matches the reference at θ = 120.000° and at 4 more"
        ),
        "{note}"
    );
    scene.set_runner(wrong);
    let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("Your rodrigues_matrix differs at θ = 120.000°: yours ("),
        "{note}"
    );
    // Nine numbers in a row next to a table of rows: the note says they are columns.
    assert!(
        note.contains("Both matrices are listed column by column (glam's order); the table under"),
        "{note}"
    );
    assert!(
        note.contains("it is not a unit quaternion: its length is 2.000"),
        "{note}"
    );
    scene.set_runner(panics);
    let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("Your exercise 3.3 rodrigues_matrix panicked"),
        "{note}"
    );
    assert!(scene.matrix().abs_diff_eq(
        rotation::rodrigues_mat3(Vec3::new(0.3, 1.0, 0.2).normalize(), 120f32.to_radians()),
        1e-5
    ));
}

#[test]
fn rodrigues_rejects_bad_input() {
    let mut scene = Rodrigues::new();
    assert!(scene
        .set_axis_angle(Vec3::ZERO, 30.0)
        .unwrap_err()
        .contains("axis has zero length"));
    assert!(scene
        .set_axis_angle(Vec3::Y, f32::NAN)
        .unwrap_err()
        .contains("angle"));
    assert!(scene
        .set_vector(Vec3::new(0.0, f32::NAN, 0.0))
        .unwrap_err()
        .contains("v.y"));
    assert!(scene.draw(&mut Frame::default(), -0.1).is_err());
}

#[test]
fn a_slerp_without_the_flip_is_caught_at_the_default_keys() {
    // At the default keys a·b > 0, so a slerp that never negates b agrees with the reference at
    // every t there: the probes with a·b < 0 must still say it differs, and the arc check must
    // judge it where a·b < 0.
    let mut scene = Interpolation::new();
    assert!(Quat::IDENTITY.dot(scene.end_quat_used()) > 0.0);
    scene.set_use_exercise(true);
    scene.set_runner(wrong);
    let note = scene.draw(&mut Frame::default(), 0.25).unwrap();
    assert!(
        note.starts_with("Your slerp matches the reference at t = 0.250 (the figure's input), but"),
        "{note}"
    );
    assert!(
        note.contains("the figure's keys with −b (a·b = -0.635), t = 0.25")
            && note.contains("keys 170° and −170° about x (a·b < 0), t = 0.5"),
        "{note}"
    );
    assert!(
        note.contains(
            "(the figure's start and −(end key)), your slerp takes the long arc: negate b"
        ),
        "{note}"
    );
    // A slerp that divides by sin Ω with no fallback fails only at nearly equal keys.
    fn no_fallback(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        if name != "slerp" {
            return direct(name, args);
        }
        let (a, mut b, t) = (
            Quat::from_slice(&args[0..4]),
            Quat::from_slice(&args[4..8]),
            args[8],
        );
        if a.dot(b) < 0.0 {
            b = -b;
        }
        let omega = a.dot(b).clamp(-1.0, 1.0).acos();
        let q =
            a * (((1.0 - t) * omega).sin() / omega.sin()) + b * ((t * omega).sin() / omega.sin());
        Ok(q.to_array().to_vec())
    }
    scene.set_runner(no_fallback);
    let note = scene.draw(&mut Frame::default(), 0.25).unwrap();
    assert!(
        note.contains("but") && note.contains("keys 0.01° apart, t = 0.5"),
        "{note}"
    );
    assert!(
        !note.contains("about x (a·b < 0)"),
        "only the near keys differ: {note}"
    );
}

#[test]
fn the_key_circle_holds_both_arcs_and_the_steps_of_nlerp_and_slerp() {
    use inbetween::figures::rotations::{CIRCLE_CENTRE, CIRCLE_RADIUS, SLERP_TICKS_OUT};
    let mut scene = Interpolation::new();
    let mut frame = Frame::default();
    let note = scene.draw_circle(&mut frame, 0.3).unwrap();
    // The default keys: a·b = 0.635, the short arc ends at b, Ω = 50.6°, a turn of 101.2°.
    assert!(note.starts_with("a·b = 0.635: a·b ≥ 0"), "{note}");
    assert!(
        note.contains("from a to b,") && note.contains("2Ω = 101.164°"),
        "{note}"
    );
    let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    for name in [
        "a",
        "−a",
        "b",
        "−b",
        "short arc: Ω = 51°",
        "long arc: Ω = 129°",
    ] {
        assert!(texts.contains(&name), "{name} in {texts:?}");
    }
    // Slerp and nlerp stay in the plane of the keys: the drawn points lie on the circle at the
    // angle of the real quaternions.
    let (e1, e2) = scene.key_plane();
    for t in [0.0, 0.3, 0.7, 1.0] {
        let q = Quat::from_mat3(&scene.orientation(Method::Slerp, t, false));
        let q = if q.dot(e1) < 0.0 && t == 0.0 { -q } else { q };
        let in_plane = Vec3::new(q.dot(e1), q.dot(e2), 0.0).length();
        assert!(
            (in_plane - 1.0).abs() < 1e-3,
            "slerp leaves the plane at t = {t}"
        );
    }
    // The equal steps: slerp's ticks are equally spaced on the arc, nlerp's (on the circle) are
    // closer at the ends than in the middle.
    let nlerp_dots: Vec<Vec3> = frame
        .markers
        .iter()
        .filter(|m| m.size_px == 7.0 && m.color[..3] == inbetween::figures::palette::Y_AXIS.to_array())
        .map(|m| Vec3::from(m.center))
        .collect();
    // Steps 1 to 7 of 8: the first and last are the keys' own dots.
    assert_eq!(nlerp_dots.len(), 7);
    for p in &nlerp_dots {
        assert!(((*p - CIRCLE_CENTRE).length() - CIRCLE_RADIUS).abs() < 1e-4);
    }
    // slerp's ticks stand apart from nlerp's dots (by 0.1 radii, about 15 px at the page's
    // camera), so a dot and a tick on the short arc do not read as one mark.
    let ticks: Vec<Vec3> = (frame.markers.iter())
        .filter(|m| m.shape == inbetween::draw::MARKER_TICK)
        .map(|m| Vec3::from(m.center))
        .collect();
    assert_eq!(ticks.len(), 9);
    for p in &ticks {
        assert!(((*p - CIRCLE_CENTRE).length() - SLERP_TICKS_OUT * CIRCLE_RADIUS).abs() < 1e-4);
        for d in &nlerp_dots {
            assert!(p.distance(*d) > 0.1 * CIRCLE_RADIUS, "tick {p} by dot {d}");
        }
    }
    let first = nlerp_dots[0].distance(nlerp_dots[1]);
    let middle = nlerp_dots[3].distance(nlerp_dots[4]);
    assert!(
        middle > 1.05 * first,
        "nlerp is faster in the middle: {first} vs {middle}"
    );
    // With a·b < 0 the short arc ends at −b; with long arc ticked, at the farther one.
    scene
        .set_keys_euler_deg(Vec3::new(170.0, 0.0, 0.0), Vec3::new(-170.0, 0.0, 0.0))
        .unwrap();
    let note = scene.draw_circle(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("a·b < 0, so −b is the nearer") && note.contains("2Ω = 20.000°"),
        "{note}"
    );
    scene.set_long_arc(true);
    let note = scene.draw_circle(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("from a to b,") && note.contains("2Ω = 340.000°"),
        "{note}"
    );
    assert!(scene.draw_circle(&mut Frame::default(), f32::NAN).is_err());
}

#[test]
fn a_steady_turn_near_the_pole_swings_yaw_and_roll() {
    let mut g = Gimbal::new();
    assert_eq!(Gimbal::POLE_MISS_DEG, 5.0);
    let rows = g.sample_pole_turn(2001).unwrap();
    // The aeroplane turns 120° per unit of t, steadily; over the 10° of turn around the pole
    // (t from 0.5 − 5/120 to 0.5 + 5/120) yaw and roll each swing by about 90°.
    let at = |t: f32| rows[(t * 2000.0).round() as usize];
    let (before, after) = (at(0.5 - 5.0 / 120.0), at(0.5 + 5.0 / 120.0));
    for (i, name) in [(1, "yaw"), (3, "roll")] {
        let swing = (after[i] - before[i]).abs();
        assert!((85.0..95.0).contains(&swing), "{name} swings {swing}°");
    }
    // Up to 11 times faster than the aeroplane turns.
    let fastest = rows
        .windows(2)
        .map(|w| ((w[1][1] - w[0][1]) / (w[1][0] - w[0][0])).abs())
        .fold(0.0f32, f32::max);
    assert!(fastest > 11.0 * Gimbal::POLE_TURN_DEG, "{fastest}");
    // The curves are continuous (unwrapped) away from the pole.
    assert!(rows.windows(2).all(|w| (w[1][1] - w[0][1]).abs() < 5.0));
    // Straight through the pole, yaw and roll jump by 180° at once.
    g.set_pole_miss_deg(0.0).unwrap();
    let rows = g.sample_pole_turn(2001).unwrap();
    let jump = rows
        .windows(2)
        .map(|w| (w[1][1] - w[0][1]).abs())
        .fold(0.0f32, f32::max);
    assert!((jump - 180.0).abs() < 1.0, "{jump}");
    // At 20° from the pole the swing spreads out: under 35° over the same 10° of turn.
    g.set_pole_miss_deg(20.0).unwrap();
    let rows = g.sample_pole_turn(2001).unwrap();
    let at = |t: f32| rows[(t * 2000.0).round() as usize];
    let swing = (at(0.5 + 5.0 / 120.0)[1] - at(0.5 - 5.0 / 120.0)[1]).abs();
    assert!(swing < 35.0, "{swing}");
    // The rings follow the turn: the gimbal's rotation is R(t).
    g.set_pole_miss_deg(5.0).unwrap();
    let angles = g.fly_at(0.3).unwrap();
    let (back, _) = g.decomposed_deg();
    assert!(
        (back - angles).abs().max_element() < 1e-2,
        "{back} {angles}"
    );
    assert!(g
        .set_pole_miss_deg(-1.0)
        .unwrap_err()
        .contains("distance from the pole"));
    assert!(g.fly_at(1.5).is_err());
}

#[test]
fn rodrigues_probes_catch_a_transposed_matrix_at_a_half_turn() {
    // At θ = 180° a transposed matrix is right: the figure's input alone cannot tell.
    let mut scene = Rodrigues::new();
    scene
        .set_axis_angle(Vec3::new(0.3, 1.0, 0.2), 180.0)
        .unwrap();
    scene.set_use_exercise(true);
    scene.set_runner(wrong);
    let note = scene.exercise_note();
    assert!(
        note.contains(
            "Your rodrigues_matrix matches the reference at θ = 180.000° (the figure's input), but"
        ),
        "{note}"
    );
    assert!(note.contains("θ = 90° about x"), "{note}");
    scene.set_runner(reference);
    let note = scene.exercise_note();
    assert!(
        note.contains(
            "Your rodrigues_matrix matches the reference at θ = 180.000° and at 4 more inputs"
        ),
        "{note}"
    );
}

#[test]
fn figure_1_paths_are_over_everything_with_a_tick_per_eighth() {
    let mut scene = Interpolation::new();
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.4).unwrap();
    // Four solid nose paths and four dashed wing-tip paths of 64 segments each, drawn over the
    // aeroplanes.
    let on_top = |dashed: bool| {
        frame
            .strokes
            .iter()
            .filter(|s| s.depth_bias == inbetween::draw::ON_TOP && (s.dash[3] > 0.0) == dashed)
            .count()
    };
    assert_eq!((on_top(false), on_top(true)), (4 * 64, 4 * 64));
    let ticks = frame
        .markers
        .iter()
        .filter(|m| m.shape == inbetween::draw::MARKER_TICK)
        .count();
    assert_eq!(ticks, 4 * 9);
    // The caption's Try this: with the end key (0, 90, 0), Euler lerp follows slerp.
    scene
        .set_keys_euler_deg(Vec3::ZERO, Vec3::new(0.0, 90.0, 0.0))
        .unwrap();
    for k in 0..=10 {
        let t = k as f32 / 10.0;
        let euler = Quat::from_mat3(&scene.orientation(Method::EulerLerp, t, false));
        let slerp = Quat::from_mat3(&scene.orientation(Method::Slerp, t, false));
        assert!(euler.angle_between(slerp) < 1e-3, "t = {t}");
    }
    // The 170° and −170° keys: Euler lerp alone goes the long way (through 0°), 340°.
    scene
        .set_keys_euler_deg(Vec3::new(170.0, 0.0, 0.0), Vec3::new(-170.0, 0.0, 0.0))
        .unwrap();
    let mid = Quat::from_mat3(&scene.orientation(Method::EulerLerp, 0.5, false));
    assert!(
        mid.angle_between(Quat::IDENTITY) < 1e-3,
        "Euler lerp passes 0°"
    );
    let slerp_mid = Quat::from_mat3(&scene.orientation(Method::Slerp, 0.5, false));
    assert!((slerp_mid.angle_between(Quat::IDENTITY).to_degrees() - 180.0).abs() < 0.1);
}

/// Figure 2's labels keep their places beside their anchors, inside the canvas and off the four
/// keys' dots, at the page's camera fitted to a 760 × 420 canvas (the 800 × 600 page) and a
/// 650 × 420 one (1600 × 1000): with the default keys, the keys 170° and −170° about x, and the
/// long arc.
#[test]
fn circle_labels_stay_beside_their_anchors_and_off_the_dots() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::layout::{place, LabelBox, Rect};
    let mut scenes = vec![Interpolation::new()];
    let mut across = Interpolation::new();
    across
        .set_keys_euler_deg(Vec3::new(170.0, 0.0, 0.0), Vec3::new(-170.0, 0.0, 0.0))
        .unwrap();
    scenes.push(across);
    let mut long = Interpolation::new();
    long.set_keys_euler_deg(Vec3::new(170.0, 0.0, 0.0), Vec3::new(-170.0, 0.0, 0.0))
        .unwrap();
    long.set_long_arc(true);
    scenes.push(long);
    let mut long_default = Interpolation::new();
    long_default.set_long_arc(true);
    scenes.push(long_default);
    for (n, scene) in scenes.iter_mut().enumerate() {
        for size in crate::label_clearance::CANVASES {
            let mut f = Frame::default();
            scene.draw_circle(&mut f, 0.3).unwrap();
            let mut camera = OrbitCamera::from_view([0.0, 1.3, 0.0, 5.0, 0.0, 0.0]);
            let fit: Vec<Vec3> = f.fit_points();
            camera.fit(&fit, size, FIT_PAD_PX);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let on = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
            let boxes: Vec<LabelBox> = f
                .labels
                .iter()
                .map(|l| LabelBox {
                    anchor: on(l.anchor),
                    size: Vec2::new(7.7 * l.text.chars().count() as f32, 17.0),
                    left: l.left,
                    visible: true,
                    priority: l.priority,
                })
                .collect();
            let keys: Vec<Vec2> = f
                .markers
                .iter()
                .filter(|m| m.size_px == inbetween::figures::rotations::KEY_DOT_PX)
                .map(|m| on(Vec3::from(m.center)))
                .collect();
            assert_eq!(keys.len(), 4);
            for ((label, b), p) in f.labels.iter().zip(&boxes).zip(place(&boxes, size)) {
                let at = format!("scene {n}, {} on {size}", label.text);
                assert!(p.shown, "{at}: hidden");
                let rect = Rect {
                    min: p.top_left,
                    size: b.size,
                };
                for d in &keys {
                    assert!(
                        !rect.overlaps(
                            &Rect {
                                min: *d - 5.0,
                                size: Vec2::splat(10.0)
                            },
                            0.0
                        ),
                        "{at}: over a key's dot at {d}"
                    );
                }
                // Only a key's name may give way to a neighbour's (a and −b 10° apart).
                if label.text.contains("arc") {
                    assert!(p.leader_to.is_none(), "{at}: moved off its anchor");
                }
            }
        }
    }
}

#[test]
fn with_a_panicking_slerp_the_key_circle_names_the_dots_it_draws() {
    // The student's slerp panics while "use my exercise" is on and the keys change (the page's
    // slider): Figure 1 falls back to the reference and says so, and Figure 2 draws one state,
    // the new keys': each name of a, −a, b and −b stands at one of the four key dots, which
    // are where the new keys lie on the circle, and the note's a·b is theirs.
    let mut scene = Interpolation::new();
    scene.set_runner(panics);
    scene.set_use_exercise(true);
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, 0.3).unwrap();
    assert!(note.contains("panicked"), "{note}");
    scene
        .set_keys_euler_deg(Vec3::ZERO, Vec3::new(-126.0, 70.0, -120.0))
        .unwrap();
    let note = scene.draw(&mut Frame::default(), 0.3).unwrap();
    assert!(note.contains("panicked"), "{note}");
    let mut frame = Frame::default();
    let said = scene.draw_circle(&mut frame, 0.3).unwrap();
    let start = Quat::IDENTITY;
    let end = inbetween::rotation::EulerAngles::new(
        inbetween::rotation::EulerOrder::IntrinsicXYZ,
        Vec3::new(-126.0, 70.0, -120.0) * std::f32::consts::PI / 180.0,
    )
    .to_quat();
    let dot = start.dot(end);
    assert!(dot < 0.0, "keys with a·b < 0: {dot}");
    assert!(
        said.starts_with(&format!("a·b = {}", inbetween::figures::format_number(dot))),
        "{said}"
    );
    let (e1, e2) = scene.key_plane();
    let keys: Vec<Vec3> = frame
        .markers
        .iter()
        .filter(|m| m.size_px == inbetween::figures::rotations::KEY_DOT_PX)
        .map(|m| Vec3::from(m.center))
        .collect();
    assert_eq!(keys.len(), 4);
    for (q, name) in [(start, "a"), (-start, "−a"), (end, "b"), (-end, "−b")] {
        let on_circle = Vec3::new(0.0, 1.3, 0.0) + 1.2 * Vec3::new(q.dot(e1), q.dot(e2), 0.0);
        assert!(
            keys.iter().any(|k| k.distance(on_circle) < 1e-4),
            "{name}: no dot at {on_circle}"
        );
        let label = frame.labels.iter().find(|l| l.text == name).unwrap();
        assert!(
            label.anchor.distance(on_circle) < 1e-4,
            "{name} named at {}, its dot at {on_circle}",
            label.anchor
        );
    }
}

/// The camera lessons/03-rotations/lesson.js places for `viewer` (its `setCamera` arguments).
fn page_view(viewer: &str) -> [f32; 6] {
    crate::page_camera(include_str!("../lessons/03-rotations/lesson.js"), viewer)
}

#[test]
fn the_four_planes_fill_their_canvas_matrix_lerp_nearest() {
    // Figure 1 at its page camera, fitted as the viewer fits it, on the canvases the page gives
    // it at 1600 × 1000 (650 × 420) and at 800 × 600 (760 × 420, measured in Chromium): the
    // spheres that hold each plane and its paths span at least 75 % of the canvas both ways,
    // and each plane's is at least 110 px across, the matrix lerp's (left, whose shrink the
    // text is about) the largest.
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::figures::rotations::METHODS;
    let mut scene = Interpolation::new();
    let mut frame = Frame::default();
    scene.draw(&mut frame, 0.5).unwrap();
    for size in [Vec2::new(650.0, 420.0), Vec2::new(760.0, 420.0)] {
        let mut camera = OrbitCamera::from_view(page_view("interpViewer"));
        assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let (mut lo, mut hi) = (Vec2::splat(f32::MAX), Vec2::splat(f32::MIN));
        for p in &frame.keep_in_view {
            let c = project_to_canvas(view_proj, size, *p).unwrap();
            (lo, hi) = (lo.min(c), hi.max(c));
        }
        let fill = (hi - lo) / size;
        assert!(fill.min_element() >= 0.75, "on {size}: {fill}");
        // Each lane's sphere (radius 0.95 m) across, in pixels, at its centre's depth.
        let across: Vec<f32> = (METHODS.iter())
            .map(|&(_, x, _)| {
                let depth = -camera.view().transform_point3(Vec3::new(x, 1.2, 0.0)).z;
                1.9 / depth / (0.5 * camera.fov_y_rad).tan() * 0.5 * size.y
            })
            .collect();
        let at = format!("on {size}: {across:?} px");
        assert!(across.iter().all(|&d| d >= 110.0), "{at}");
        assert!(across.iter().skip(1).all(|&d| d < across[0]), "{at}");
    }
}

#[test]
fn keys_half_a_turn_apart_say_both_ways_round_are_right() {
    // End key (180, 0, 0): Euler lerp and slerp turn about x in opposite senses, 180° apart at
    // t = 0.5, and both reach the end key: the note says so, rather than reading as a failure.
    let mut scene = Interpolation::new();
    scene
        .set_keys_euler_deg(Vec3::ZERO, Vec3::new(180.0, 0.0, 0.0))
        .unwrap();
    let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(note.contains("180° from slerp at t = 0.50"), "{note}");
    assert!(note.contains("half a turn apart"), "{note}");
    // Not at the default keys.
    let mut scene = Interpolation::new();
    let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(!note.contains("half a turn"), "{note}");
}
