use glam::{Mat3, Quat};
use inbetween::figures::*;

#[test]
fn validity_checks_name_the_problem() {
    assert_eq!(rotation_problem(Mat3::from_rotation_y(0.7), 1e-4), None);
    let scaled = Mat3::from_diagonal(glam::Vec3::new(1.0, 2.0, 1.0));
    assert!(rotation_problem(scaled, 1e-4)
        .unwrap()
        .contains("orthonormal"));
    let mirror = Mat3::from_diagonal(glam::Vec3::new(1.0, 1.0, -1.0));
    assert!(rotation_problem(mirror, 1e-4)
        .unwrap()
        .contains("determinant is -1.000"));
    assert!(rotation_problem(Mat3::NAN, 1e-4).is_some());
    assert_eq!(unit_quat_problem(Quat::from_rotation_x(1.0), 1e-4), None);
    assert!(unit_quat_problem(Quat::from_xyzw(0.0, 0.0, 0.0, 2.0), 1e-4).is_some());
    assert!(unit_quat_problem(Quat::NAN, 1e-4).is_some());
}

#[test]
fn failure_notes_say_what_happened() {
    let n = failure_note(
        "exercise 3.2 slerp",
        "src/exercises/rotations.rs",
        &Failure::NotDone,
    );
    assert!(n.starts_with("Not done yet: exercise 3.2 slerp"));
    let file = "src/exercises/cloth.rs";
    assert_eq!(not_done_note(&[], file), "");
    assert_eq!(
        not_done_note(&["exercise 13.1 spring_force"], file),
        failure_note("exercise 13.1 spring_force", file, &Failure::NotDone)
    );
    assert_eq!(
        not_done_note(
            &["exercise 13.1 a", "exercise 13.2 b", "exercise 13.3 c"],
            file
        ),
        "Not done yet: exercises 13.1 a, 13.2 b and 13.3 c (src/exercises/cloth.rs). \
         The figure uses the reference."
    );
    let n = failure_note("exercise 3.2 slerp", "f", &Failure::Panicked("boom".into()));
    assert!(n.contains("panicked: boom") && n.contains("reference"));
    let rust = "panicked at src/exercises/rotations.rs:45:9:\nindex out of bounds";
    let n = failure_note("exercise 3.2 slerp", "f", &Failure::Panicked(rust.into()));
    assert!(
        n.starts_with("Your exercise 3.2 slerp panicked at src/exercises/rotations.rs:45:9: index"),
        "{n}"
    );
}
