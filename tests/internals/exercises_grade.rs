use inbetween::exercises::grade::*;
use inbetween::exercises::Answer;

thread_local! {
    /// How often the fake lesson's first exercise ran on this test's thread.
    static FIRST_RAN: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

fn first(x: &f32) -> Answer<f32> {
    FIRST_RAN.set(FIRST_RAN.get() + 1);
    if *x > 1.5 {
        panic!("x is too big: {x}");
    }
    Ok(*x)
}

/// Two exercises with inputs from the generator: the first panics at its second case.
fn fake(rng: &mut Rng) -> Vec<Report> {
    let a = [
        ("one", 1.0_f32),
        ("two", 2.0),
        (RANDOM, rng.range(0.0, 1.0)),
    ];
    let b = [("small", rng.range(0.0, 1.0)), ("smaller", 0.25)];
    vec![
        check_cases("99-fake", "first", ["x"], &a, first, |x| *x, |p, q| p == q),
        check_cases(
            "99-fake",
            "second",
            ["y"],
            &b,
            |y| Ok(*y * 2.0),
            |y| *y * 2.0,
            |p, q| p == q,
        ),
    ]
}

const FAKE: Lesson = lesson("99-fake", "fake", fake);

#[test]
fn a_known_panic_is_replayed_with_the_same_row_and_not_run_again() {
    let native = FAKE.grade();
    let Status::Panicked {
        case,
        message,
        location,
        ..
    } = &native[0].status
    else {
        panic!("expected a panic: {:?}", native[0].status);
    };
    assert_eq!((*case, message.as_str()), (2, "x is too big: 2"));
    let location = location.clone().expect("the panic's location");
    assert!(
        location.starts_with("tests/internals/exercises_grade.rs:"),
        "{location}"
    );
    let known = vec![Known {
        exercise: "first".into(),
        case: 2,
        failure: KnownFailure::Panicked {
            message: message.clone(),
            location: Some(location),
        },
    }];
    let before = FIRST_RAN.get();
    let replayed = grade_lesson_with(&FAKE, known, None);
    assert_eq!(
        FIRST_RAN.get(),
        before,
        "a known failure does not run again"
    );
    assert_eq!(replayed, native);
    assert_eq!(table(&replayed), table(&native));
}

#[test]
fn a_stopped_exercise_gets_its_case_and_the_time_limit() {
    let known = vec![Known {
        exercise: "second".into(),
        case: 1,
        failure: KnownFailure::Stopped { seconds: 5.0 },
    }];
    let reports = grade_lesson_with(&FAKE, known, None);
    let Status::Stopped {
        case,
        what,
        input,
        seconds,
    } = &reports[1].status
    else {
        panic!("expected a stop: {:?}", reports[1].status);
    };
    assert_eq!((*case, what.as_str(), *seconds), (1, "small", 5.0));
    assert_eq!(input[0].0, "y");
    let line = reports[1].status.to_string();
    assert!(
        line.starts_with("STOPPED at case 1 (small): no answer within 5 s"),
        "{line}"
    );
    assert!(table(&reports)
        .contains("0 passed, 0 not yet implemented, 0 wrong, 1 panicked, 1 stopped, of 2"));
    // Nothing stays known for the next grading.
    assert!(matches!(
        FAKE.grade()[1].status,
        Status::Passed { cases: 2 }
    ));
}

#[test]
fn the_watchdog_hears_of_every_case_before_it_runs() {
    static SEEN: std::sync::Mutex<Vec<(String, usize)>> = std::sync::Mutex::new(Vec::new());
    fn heard(exercise: &str, case: usize) {
        SEEN.lock().unwrap().push((exercise.to_string(), case));
    }
    grade_lesson_with(&FAKE, Vec::new(), Some(heard));
    let seen = SEEN.lock().unwrap().clone();
    let expected: Vec<(String, usize)> = [("first", 1), ("first", 2), ("second", 1), ("second", 2)]
        .map(|(e, c)| (e.to_string(), c))
        .to_vec();
    assert_eq!(seen, expected, "the first exercise stops at its panic");
}

/// The isolation test's build (features `solutions` and `student-bugs`), here by the
/// switches that stand for them in a build with debug assertions.
#[cfg(debug_assertions)]
#[test]
fn the_student_bugs_build_grades_wrong_and_panicking_exercises() {
    use inbetween::exercises::{with_reference_answers, with_student_bugs};
    let grade_selected =
        |l: &str| with_reference_answers(|| with_student_bugs(|| grade_selected(l)));
    let rows = grade_selected("03").unwrap();
    let status = |name: &str| &rows.iter().find(|r| r.exercise == name).unwrap().status;
    assert!(matches!(
        status("quat_from_axis_angle"),
        Status::Passed { .. }
    ));
    let Status::Panicked { location, .. } = status("slerp") else {
        panic!("slerp: {:?}", status("slerp"));
    };
    assert!(location
        .as_deref()
        .unwrap_or("")
        .starts_with("src/exercises/run.rs:"));
    assert!(matches!(status("rodrigues_matrix"), Status::Wrong { .. }));
    // Lesson 00's vertex normals: the middle one of the first mesh (the tetrahedron's four)
    // is reversed, and the report says which.
    let rows = grade_selected("00").unwrap();
    let normals = rows
        .iter()
        .find(|r| r.exercise == "vertex_normals")
        .unwrap();
    let Status::Wrong { case, list, .. } = &normals.status else {
        panic!("vertex_normals: {:?}", normals.status);
    };
    assert_eq!(*case, 1);
    let list = list.as_deref().unwrap_or("");
    assert!(
        list.starts_with("index 2 first, 1 of 4 elements in all: expected Vec3("),
        "{list}"
    );
}
