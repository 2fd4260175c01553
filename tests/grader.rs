//! Grades the exercises natively and prints the table.
//!
//! `./scripts/grade` runs `grade_exercises`, whose expectation depends on the build:
//! - with `--features solutions`, every exercise passes (the grader accepts a right answer);
//! - with `INBETWEEN_GRADER_EXPECT=stubs` (CI, on the untouched stubs; read when the test runs, so
//!   one build serves both runs), every exercise reports "not yet implemented" (the grader tells
//!   a stub from an answer);
//! - otherwise (a student's build), no exercise may be wrong or panic.
//!
//!
//! `the_reference_answers_all_pass` checks in every build that the grader accepts a right answer:
//! it grades with the exercises answering by their reference solutions
//! (`exercises::with_reference_answers`), as the feature `solutions` makes them do.
//!
//! `INBETWEEN_GRADE_LESSON` (read when the test runs; `scripts/grade LESSON` sets it) grades the
//! lessons it names only (see `select_lessons`); one that names none fails with a line starting
//! `grade: ` that lists the lessons.
// Native only (tests/web_grader.rs is the browser twin); the browser runs tests/transform.rs and tests/web*.rs.
#![cfg(not(target_arch = "wasm32"))]

use inbetween::exercises::grade::{grade_selected, table};
use inbetween::exercises::with_reference_answers;

#[test]
fn the_reference_answers_all_pass() {
    let reports = with_reference_answers(|| grade_selected(""))
        .unwrap_or_else(|e| panic!("grading every lesson: {e}"));
    println!("\nWith the reference answers:\n{}", table(&reports));
    assert!(!reports.is_empty());
    let failed: Vec<_> = reports
        .iter()
        .filter(|r| !r.passed())
        .map(|r| r.exercise)
        .collect();
    assert_eq!(
        failed,
        Vec::<&str>::new(),
        "reference answers the grader refused"
    );
    assert!(
        !inbetween::exercises::reference_answers_on(),
        "the switch is off again"
    );
}

/// The native grader's table for the isolation test's page (tests/e2e-variant/), whose course
/// module is built with the features `solutions` and `student-bugs`: here the same answers come
/// from the switches that stand for those features, in the build the other tests use. The three
/// planted mistakes that natively come back (slerp panics, the Rodrigues matrix is transposed,
/// the middle vertex normal reversed) fail; every other exercise passes.
#[test]
fn grade_with_student_bugs() {
    use inbetween::exercises::with_student_bugs;
    let selector = std::env::var("INBETWEEN_GRADE_LESSON").unwrap_or_default();
    let reports = with_reference_answers(|| with_student_bugs(|| grade_selected(&selector)))
        .unwrap_or_else(|e| panic!("{e}"));
    println!("\n{}", table(&reports));
    assert!(!reports.is_empty());
    for r in &reports {
        let planted = ["slerp", "rodrigues_matrix", "vertex_normals"].contains(&r.exercise);
        assert_eq!(!r.passed(), planted, "{}: {:?}", r.exercise, r.status);
    }
}

#[test]
fn grade_exercises() {
    let selector = std::env::var("INBETWEEN_GRADE_LESSON").unwrap_or_default();
    let reports = match grade_selected(&selector) {
        Ok(reports) => reports,
        Err(message) => {
            // scripts/grade shows the lines that start with "grade: " and nothing else.
            println!(
                "\n{}",
                message
                    .lines()
                    .map(|l| format!("grade: {l}\n"))
                    .collect::<String>()
            );
            panic!("{message}");
        }
    };
    println!("\n{}", table(&reports));
    assert!(!reports.is_empty());
    if cfg!(feature = "solutions") {
        assert!(
            reports.iter().all(|r| r.passed()),
            "with solutions every exercise must pass"
        );
    } else if std::env::var("INBETWEEN_GRADER_EXPECT").as_deref() == Ok("stubs") {
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

mod lessons {
    use inbetween::exercises::grade::{grade_all, select_lessons, LESSONS};

    fn ids(selector: &str) -> Vec<&'static str> {
        select_lessons(selector)
            .unwrap_or_else(|e| panic!("{selector:?}: {e}"))
            .iter()
            .map(|l| l.id)
            .collect()
    }

    #[test]
    fn a_lesson_is_named_by_its_number_name_or_file() {
        assert_eq!(ids("03"), ["03-rotations"]);
        assert_eq!(ids("3"), ["03-rotations"]);
        assert_eq!(ids(" 03-rotations "), ["03-rotations"]);
        // rotations.rs holds lessons 03 and 04: the lesson's own name wins over the file's.
        assert_eq!(ids("rotations"), ["03-rotations"]);
        // A name two lessons start with selects both.
        assert_eq!(ids("Rigid"), ["04-rigid-motions", "14-rigid-bodies"]);
        assert_eq!(ids("rigid-motions"), ["04-rigid-motions"]);
        assert_eq!(ids("rigid-bodies"), ["14-rigid-bodies"]);
        assert_eq!(ids("rigid_body"), ["14-rigid-bodies"]);
        assert_eq!(ids("14"), ["14-rigid-bodies"]);
        assert_eq!(ids("15"), ["15-fluids"]);
        assert_eq!(ids("fluid"), ["15-fluids"]);
        assert_eq!(ids("curves"), ["02-keyframes"]);
        assert_eq!(ids("02"), ["02-keyframes"]);
        assert_eq!(ids("2b"), ["02b-expressive-animation"]);
        assert_eq!(ids("expressive"), ["02b-expressive-animation"]);
        assert_eq!(ids("ik"), ["07-inverse-kinematics"]);
        assert_eq!(ids("blend_shapes"), ["10-blend-shapes"]);
        assert_eq!(ids("skeleton"), ["06-skeletons"]);
        assert_eq!(ids("08"), ["08-blending"]);
        assert_eq!(ids("blending"), ["08-blending"]);
        assert_eq!(ids("").len(), LESSONS.len());
    }

    #[test]
    fn an_unknown_lesson_gets_the_list_of_lessons() {
        for selector in ["16", "walking", "99", "xx", "r"] {
            let Err(message) = select_lessons(selector) else {
                panic!("{selector:?} selected something");
            };
            assert!(message.contains(&format!("\"{selector}\"")), "{message}");
            for lesson in LESSONS {
                assert!(
                    message.contains(lesson.id) && message.contains(&format!("{}.rs", lesson.file)),
                    "{message}"
                );
            }
        }
    }

    /// Every lesson draws its inputs from a generator of its own, so grading one lesson alone
    /// gives exactly the rows (cases, verdicts) of the whole table; and each row names the lesson
    /// it is registered under.
    #[test]
    fn a_lesson_graded_alone_gives_its_rows_of_the_whole_table() {
        let all = grade_all();
        let mut seen = 0;
        for lesson in LESSONS {
            let alone = lesson.grade();
            assert!(!alone.is_empty(), "{} grades nothing", lesson.id);
            assert!(alone.iter().all(|r| r.lesson == lesson.id), "{}", lesson.id);
            let rows: Vec<_> = all
                .iter()
                .filter(|r| r.lesson == lesson.id)
                .cloned()
                .collect();
            assert_eq!(alone, rows, "{}", lesson.id);
            seen += rows.len();
        }
        assert_eq!(seen, all.len(), "a row whose lesson is not registered");
    }

    /// The names a report gives the inputs are the exercise's own parameter names, in order,
    /// leaving out only output slices (`&mut`) that the grader fills.
    #[test]
    fn inputs_are_named_as_in_the_exercise_signature() {
        for lesson in LESSONS {
            let path = format!(
                "{}/src/exercises/{}.rs",
                env!("CARGO_MANIFEST_DIR"),
                lesson.file
            );
            let source = std::fs::read_to_string(&path).unwrap();
            for report in lesson.grade() {
                let start = format!("pub fn {}(", report.exercise);
                let at = source
                    .find(&start)
                    .unwrap_or_else(|| panic!("{path}: no `{start}`"))
                    + start.len();
                let end = at
                    + source[at..]
                        .find(") -> Answer")
                        .expect("an exercise returns Answer");
                let params: Vec<(&str, &str)> = source[at..end]
                    .split(',')
                    .filter(|p| !p.trim().is_empty())
                    .map(|p| {
                        let (name, ty) = p.split_once(':').expect("name: type");
                        (name.trim(), ty.trim())
                    })
                    .collect();
                let mut args = report.args.iter().peekable();
                for (name, ty) in &params {
                    if args.peek() == Some(&name) {
                        args.next();
                    } else {
                        assert!(
                            ty.starts_with("&mut"),
                            "{}: input `{name}` is not named in the grader ({:?})",
                            report.exercise,
                            report.args
                        );
                    }
                }
                assert!(
                    args.next().is_none(),
                    "{}: the grader names {:?}, the signature has {params:?}",
                    report.exercise,
                    report.args
                );
            }
        }
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
            ["x"],
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
                input: vec![("x", "2".into())],
                list: None,
                expected: "2".into(),
                actual: "0".into()
            }
        );
    }

    #[test]
    fn names_each_input() {
        let report = check(
            "l",
            "e",
            ["root", "k"],
            &[(glam::Vec3::new(1.0, 2.0, 3.0), 0.5f32)],
            |_| Ok(0),
            |_| 1,
            |a, b| a == b,
        );
        let shown = report.status.to_string();
        assert!(
            shown.contains("\n      input:    root = Vec3(1.0, 2.0, 3.0), k = 0.5\n"),
            "{shown}"
        );
        // Inputs too long for one line go one per line, each under the first.
        let long = vec![0.25f32; 12];
        let report = check(
            "l",
            "e",
            ["times", "t"],
            &[(long.clone(), 2.0f32)],
            |_| Ok(0),
            |_| 1,
            |a, b| a == b,
        );
        let shown = report.status.to_string();
        let expected = format!(
            "\n      input:    times = {long:?}\n                t = 2.0\n      expected: 1\n"
        );
        assert!(shown.contains(&expected), "{shown}");
    }

    /// The lists `0.0, 1.0, …` of `n` elements: the reference of the list tests below.
    fn count_to(&n: &usize) -> Vec<f32> {
        (0..n).map(|i| i as f32).collect()
    }

    fn within_1e4(a: &f32, b: &f32) -> bool {
        (a - b).abs() <= 1e-4
    }

    #[test]
    fn names_the_first_wrong_element_of_a_long_list_with_both_values() {
        use inbetween::exercises::grade::check_list_cases;
        let report = check_list_cases(
            "l",
            "e",
            ["n"],
            &[("short", 3usize), ("long", 40)],
            |&n| {
                let mut list = count_to(&n);
                if n == 40 {
                    list[17] = -1.0;
                    list[30] += 0.5;
                    // Within the tolerance: not wrong.
                    list[35] += 5e-5;
                }
                Ok(list)
            },
            count_to,
            within_1e4,
        );
        let Status::Wrong {
            case,
            list,
            expected,
            actual,
            ..
        } = &report.status
        else {
            panic!("{:?}", report.status);
        };
        assert_eq!(*case, 2, "the short list is right");
        assert_eq!(
            list.as_deref(),
            Some("index 17 first, 2 of 40 elements in all: expected 17.0, actual -1.0")
        );
        // The long lists show the elements round index 17 and how many are left out.
        assert_eq!(
            expected,
            "[… 15 before, 15.0, 16.0, 17.0, 18.0, 19.0, … 20 after]"
        );
        assert_eq!(
            actual,
            "[… 15 before, 15.0, 16.0, -1.0, 18.0, 19.0, … 20 after]"
        );
        let shown = report.status.to_string();
        let lines = "\n      wrong:    index 17 first, 2 of 40 elements in all: expected 17.0, \
                     actual -1.0\n      expected: [… 15 before, 15.0,";
        assert!(shown.contains(lines), "{shown}");
    }

    #[test]
    fn a_short_list_shows_whole_and_a_length_is_wrong_even_when_every_element_matches() {
        use inbetween::exercises::grade::check_list_cases;
        let short = check_list_cases(
            "l",
            "e",
            ["n"],
            &[4usize].map(|n| ("short", n)),
            |&n| Ok(count_to(&n).into_iter().map(|x| x * x).collect()),
            count_to,
            within_1e4,
        );
        let Status::Wrong {
            list,
            expected,
            actual,
            ..
        } = &short.status
        else {
            panic!("{:?}", short.status);
        };
        assert_eq!(
            list.as_deref(),
            Some("index 2 first, 2 of 4 elements in all: expected 2.0, actual 4.0")
        );
        assert_eq!(
            (expected.as_str(), actual.as_str()),
            ("[0.0, 1.0, 2.0, 3.0]", "[0.0, 1.0, 4.0, 9.0]")
        );
        // One element short: the list says so, and the lists show their ends.
        let shorter = check_list_cases(
            "l",
            "e",
            ["n"],
            &[("long", 20usize)],
            |&n| Ok(count_to(&(n - 1))),
            count_to,
            within_1e4,
        );
        let Status::Wrong {
            list,
            expected,
            actual,
            ..
        } = &shorter.status
        else {
            panic!("{:?}", shorter.status);
        };
        assert_eq!(
            list.as_deref(),
            Some("the length: expected 20 elements, actual 19")
        );
        assert_eq!(expected, "[… 15 before, 15.0, 16.0, 17.0, 18.0, 19.0]");
        assert_eq!(actual, "[… 14 before, 14.0, 15.0, 16.0, 17.0, 18.0]");
        // An answer that is no list says nothing of elements.
        let plain = check("l", "e", ["x"], &[1], |_| Ok(2), |&x| x, |a, b| a == b);
        assert!(!plain.status.to_string().contains("wrong:"));
    }

    #[test]
    fn says_what_the_failing_case_tests() {
        use inbetween::exercises::grade::check_cases;
        let report = check_cases(
            "l",
            "e",
            ["x"],
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
            ["x"],
            &[1],
            |_| Err::<i32, _>(NotDone),
            |&x| x,
            |a, b| a == b,
        );
        assert_eq!(report.status, Status::NotDone);
        let report = check("l", "e", ["x"], &[1, 5], |&x| Ok(x), |&x| x, |a, b| a == b);
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
            ["i"],
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
                ["i"],
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
