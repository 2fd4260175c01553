use glam::{Mat4, Quat, Vec3};
use inbetween::exercises::run::*;
use inbetween::rigid::DualQuat;

fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "slerp" => Ok(vec![0.0, 0.0, 0.0, 1.0]),
        _ => direct(name, args),
    }
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "index out of bounds (src/exercises/rotations.rs:42:5)".into(),
    ))
}

#[test]
fn values_round_trip_through_the_flat_form() {
    let dq = DualQuat {
        real: Quat::from_rotation_y(0.3),
        dual: Quat::from_xyzw(0.1, 0.2, 0.3, 0.0),
    };
    let v = (dq, Vec3::new(1.0, 2.0, 3.0));
    let mut out = Vec::new();
    v.put(&mut out);
    let mut rest = &out[..];
    assert_eq!(<(DualQuat, Vec3)>::take(&mut rest), Some(v));
    assert!(rest.is_empty());
    let list = vec![Mat4::IDENTITY, Mat4::from_translation(Vec3::X)];
    let mut out = Vec::new();
    list.put(&mut out);
    assert_eq!(Vec::<Mat4>::take(&mut &out[..]), Some(list));
    assert_eq!(
        Vec::<f32>::take(&mut &[1e9_f32][..]),
        None,
        "a length past the data"
    );
    assert_eq!(usize::take(&mut &[-1.0_f32][..]), None);
}

#[test]
fn an_answer_too_short_or_too_long_is_malformed() {
    fn short(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
        Ok(vec![0.0, 0.0, 0.0])
    }
    fn long(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
        Ok(vec![0.0, 0.0, 0.0, 1.0, 5.0])
    }
    let malformed = Err(Failure::Call("slerp: malformed answer".into()));
    assert_eq!(slerp(short, Quat::IDENTITY, Quat::IDENTITY, 0.5), malformed);
    assert_eq!(slerp(long, Quat::IDENTITY, Quat::IDENTITY, 0.5), malformed);
    assert_eq!(
        slerp(long, Quat::IDENTITY, Quat::IDENTITY, 0.5)
            .unwrap_err()
            .to_string(),
        "could not be called: slerp: malformed answer"
    );
}

#[test]
fn direct_runs_each_exercise_and_reports_stubs() {
    let call = || slerp(direct, Quat::IDENTITY, Quat::from_rotation_z(1.0), 0.5);
    if cfg!(feature = "student-bugs") {
        assert!(
            std::panic::catch_unwind(call).is_err(),
            "the bug variant's slerp panics"
        );
        return;
    }
    let got = call();
    if cfg!(feature = "solutions") {
        let q = got.unwrap();
        assert!(q.angle_between(Quat::from_rotation_z(0.5)) < 1e-5);
    } else {
        assert_eq!(got, Err(Failure::NotDone));
    }
    assert!(matches!(direct("nope", &[]), Err(Failure::Call(_))));
    assert!(matches!(direct("slerp", &[1.0]), Err(Failure::Call(_))));
    assert_eq!(NAMES.len(), 44);
}

#[test]
fn other_runners_reach_the_figure() {
    let q = slerp(wrong, Quat::IDENTITY, Quat::from_rotation_z(1.0), 0.5).unwrap();
    assert_eq!(q, Quat::IDENTITY);
    assert!(matches!(
        slerp(panics, Quat::IDENTITY, Quat::IDENTITY, 0.5),
        Err(Failure::Panicked(m)) if m.contains("rotations.rs:42")
    ));
}

#[test]
fn notes_say_match_or_differ_with_both_values() {
    let (ok, note) = compare_note("slerp", "t = 0.25", &[0.0, 1.0], &[0.0, 1.0000001], 1e-4);
    assert!(ok, "{note}");
    assert!(note.contains("matches the reference"));
    let (ok, note) = compare_note("slerp", "t = 0.25", &[0.0, -0.0], &[0.5, 1.0], 1e-4);
    assert!(!ok);
    assert_eq!(
        note,
        "Your slerp differs at t = 0.25: yours (0.000, 0.000), reference (0.500, 1.000)."
    );
    let (ok, _) = compare_note("x", "y", &[f32::NAN], &[0.0], 1e-4);
    assert!(!ok, "NaN never matches");
    assert_eq!(format_number(-1e-9), "-1.000e-9");
    assert_eq!(format_number(-0.0001), "-1.000e-4");
    assert_eq!(format_number(-0.0), "0.000");
    assert_eq!(format_number(1e38), "1.000e38");
}
