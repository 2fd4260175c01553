//! The grader in headless Chromium, with the same expectations as `tests/grader.rs`: the reference
//! answers all pass, and `grade_exercises_in_the_browser` holds what the build's answers must.
//!
//! `INBETWEEN_GRADE_LESSON` picks the lessons as in `tests/grader.rs`, but it is read when the
//! test compiles (a page has no environment): cargo rebuilds the test when it changes.
#![cfg(target_arch = "wasm32")]

use inbetween::exercises::grade::{grade_selected, table};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

/// The grader accepts a right answer under wasm too: every exercise answering with its reference
/// solution passes (the switch that stands for the feature `solutions`; see tests/grader.rs).
#[wasm_bindgen_test]
fn the_reference_answers_all_pass_in_the_browser() {
    let reports = inbetween::exercises::with_reference_answers(|| grade_selected(""))
        .unwrap_or_else(|e| panic!("grading every lesson: {e}"));
    let failed: Vec<_> = reports
        .iter()
        .filter(|r| !r.passed())
        .map(|r| r.exercise)
        .collect();
    if !failed.is_empty() {
        web_sys::console::log_1(&table(&reports).into());
    }
    assert!(!reports.is_empty());
    assert_eq!(
        failed,
        Vec::<&str>::new(),
        "reference answers the grader refused (see the table above)"
    );
    assert!(
        !inbetween::exercises::reference_answers_on(),
        "the switch is off again"
    );
}

#[wasm_bindgen_test]
fn grade_exercises_in_the_browser() {
    let reports = match grade_selected(option_env!("INBETWEEN_GRADE_LESSON").unwrap_or("")) {
        Ok(reports) => reports,
        Err(message) => {
            // scripts/grade shows the lines that start with "grade: " and nothing else.
            let lines: String = message.lines().map(|l| format!("grade: {l}\n")).collect();
            web_sys::console::log_1(&lines.into());
            panic!("no such lesson (see the message above)");
        }
    };
    // The table is printed once; a failure below names the rule, not the table again.
    web_sys::console::log_1(&table(&reports).into());
    assert!(!reports.is_empty());
    let (ok, rule) = if cfg!(feature = "solutions") {
        (
            reports.iter().all(|r| r.passed()),
            "with solutions every exercise must pass",
        )
    } else if option_env!("INBETWEEN_GRADER_EXPECT") == Some("stubs") {
        (
            reports.iter().all(|r| r.not_done()),
            "every stub must report 'not yet implemented'",
        )
    } else {
        (
            reports.iter().all(|r| r.passed() || r.not_done()),
            "some exercises are wrong",
        )
    };
    assert!(ok, "{rule} (see the table above)");
}
