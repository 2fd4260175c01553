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
                case: 2,
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
            shown.starts_with("WRONG at case 2 (zero: the edge)"),
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

    /// The line of the panic in [`out_of_range`], for the reports' `file:line`.
    const PANIC_LINE: u32 = line!() + 3;
    /// An exercise with a bug: reads past the end of `v`.
    fn out_of_range(v: &[i32], i: usize) -> i32 {
        v[i + 1]
    }

    #[test]
    fn catches_a_panicking_exercise_natively_and_says_where() {
        let report = check(
            "l",
            "e",
            &[0usize],
            |&i| Ok(out_of_range(&[1], i)),
            |_| 1,
            |a, b| a == b,
        );
        let Status::Panicked {
            case,
            message,
            location,
            ..
        } = &report.status
        else {
            panic!("{:?}", report.status);
        };
        assert_eq!(*case, 1, "counted from 1");
        assert!(message.contains("index out of bounds"), "{message}");
        let at = format!("tests/grader.rs:{PANIC_LINE}:");
        assert!(
            location.as_ref().is_some_and(|l| l.starts_with(&at)),
            "{location:?}, expected {at}…"
        );
        let shown = report.status.to_string();
        assert!(
            shown.starts_with("PANICKED at case 1 (random input): index out of bounds")
                && shown.contains(&format!("({at}")),
            "{shown}"
        );
    }

    /// Set by [`puts_the_previous_panic_hook_back`] for the process it starts.
    const CHILD: &str = "INBETWEEN_GRADER_HOOK_CHILD";

    /// Panic hooks are global: a test that sets one must not share its process with the other
    /// tests, which grade (and swap hooks) in parallel. So this starts the test binary again,
    /// running only [`hook_child`].
    #[test]
    fn puts_the_previous_panic_hook_back() {
        let out = std::process::Command::new(std::env::current_exe().unwrap())
            .args([
                "the_grader_itself::hook_child",
                "--exact",
                "--test-threads=1",
                "--nocapture",
            ])
            .env(CHILD, "1")
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout).to_string()
            + &String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{text}");
        assert!(
            text.contains("hook_child ... ok"),
            "the child ran no test: {text}"
        );
    }

    /// In a process of its own (see above; elsewhere it does nothing): the grader's own hook
    /// takes the student's panic quietly, and afterwards the hook that was there before gets the
    /// next panic.
    #[test]
    fn hook_child() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        if std::env::var_os(CHILD).is_none() {
            return;
        }
        static SEEN: AtomicUsize = AtomicUsize::new(0);
        // A hook with state, so that its box has an address of its own.
        let step = 1usize;
        let hook: Box<dyn Fn(&std::panic::PanicHookInfo<'_>) + Send + Sync> = Box::new(move |_| {
            SEEN.fetch_add(step, Ordering::SeqCst);
        });
        let address = |h: &(dyn Fn(&std::panic::PanicHookInfo<'_>) + Send + Sync)| {
            h as *const _ as *const u8 as usize
        };
        let original = address(&*hook);
        std::panic::set_hook(hook);
        for _ in 0..3 {
            let report = check(
                "l",
                "e",
                &[0usize],
                |&i| Ok(out_of_range(&[1], i)),
                |_| 1,
                |a, b| a == b,
            );
            assert!(matches!(report.status, Status::Panicked { .. }));
        }
        // The very hook that was there is back, not a wrapper around it (a wrapper per graded
        // case would chain one closure per case).
        let back = std::panic::take_hook();
        assert_eq!(address(&*back), original, "the grader put back a wrapper");
        std::panic::set_hook(back);
        assert_eq!(
            SEEN.load(Ordering::SeqCst),
            0,
            "the grader's hook took the student's panic"
        );
        assert!(std::panic::catch_unwind(|| out_of_range(&[1], 0)).is_err());
        assert_eq!(SEEN.load(Ordering::SeqCst), 1, "the previous hook is back");
        drop(std::panic::take_hook());
    }
}
