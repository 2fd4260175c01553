//! Grades the exercises natively and prints the table.
//!
//! `./scripts/grade` runs this. What must hold depends on the build:
//! - with `--features solutions`, every exercise passes (the grader accepts a right answer);
//! - with `INBETWEEN_GRADER_EXPECT=stubs` (CI, on the untouched stubs), every exercise reports
//!   "not yet implemented" (the grader tells a stub from an answer);
//! - otherwise (a student's build), no exercise may be wrong or panic.
// Native only (tests/web_grader.rs is the browser twin); the browser runs tests/transform.rs and tests/web*.rs.
#![cfg(not(target_arch = "wasm32"))]

use inbetween::exercises::grade::{grade_all, table};

#[test]
fn grade_exercises() {
    let reports = grade_all();
    println!("\n{}", table(&reports));
    assert!(!reports.is_empty());
    if cfg!(feature = "solutions") {
        assert!(
            reports.iter().all(|r| r.passed()),
            "with solutions every exercise must pass"
        );
    } else if option_env!("INBETWEEN_GRADER_EXPECT") == Some("stubs") {
        assert!(
            reports.iter().all(|r| r.not_done()),
            "every stub must report 'not yet implemented'"
        );
    } else {
        assert!(
            reports.iter().all(|r| r.passed() || r.not_done()),
            "some exercises are wrong"
        );
    }
}

mod the_grader_itself {
    use inbetween::exercises::grade::{check, Status};
    use inbetween::exercises::NotDone;

    #[test]
    fn reports_the_first_wrong_case_with_input_expected_and_actual() {
        let report = check(
            "l",
            "e",
            &[1, 2, 3],
            |&x| Ok(if x == 2 { 0 } else { x }),
            |&x| x,
            |a, b| a == b,
        );
        assert_eq!(
            report.status,
            Status::Wrong {
                case: 1,
                what: "random input".into(),
                input: "2".into(),
                expected: "2".into(),
                actual: "0".into()
            }
        );
    }

    #[test]
    fn says_what_the_failing_case_tests() {
        use inbetween::exercises::grade::check_cases;
        let report = check_cases(
            "l",
            "e",
            &[("positive", 1), ("zero: the edge", 0)],
            |&x| Ok(x.max(1)),
            |&x| x,
            |a, b| a == b,
        );
        let shown = report.status.to_string();
        assert!(
            shown.starts_with("WRONG at case 1 (zero: the edge)"),
            "{shown}"
        );
    }

    #[test]
    fn tells_a_stub_from_an_answer() {
        let report = check(
            "l",
            "e",
            &[1],
            |_| Err::<i32, _>(NotDone),
            |&x| x,
            |a, b| a == b,
        );
        assert_eq!(report.status, Status::NotDone);
        let report = check("l", "e", &[1, 5], |&x| Ok(x), |&x| x, |a, b| a == b);
        assert_eq!(report.status, Status::Passed { cases: 2 });
    }

    #[test]
    fn catches_a_panicking_exercise_natively() {
        let report = check(
            "l",
            "e",
            &[0usize],
            |&i| Ok([1][i + 1]),
            |_| 1,
            |a, b| a == b,
        );
        assert!(
            matches!(report.status, Status::Panicked { case: 0, .. }),
            "{:?}",
            report.status
        );
    }
}
