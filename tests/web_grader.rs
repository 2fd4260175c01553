//! The grader in headless Chromium, with the same expectations as `tests/grader.rs`.
#![cfg(target_arch = "wasm32")]

use inbetween::exercises::grade::{grade_all, table};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn grade_exercises_in_the_browser() {
    let reports = grade_all();
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
