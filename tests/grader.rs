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
        assert!(reports.iter().all(|r| r.passed()), "with solutions every exercise must pass");
    } else if option_env!("INBETWEEN_GRADER_EXPECT") == Some("stubs") {
        assert!(reports.iter().all(|r| r.not_done()), "every stub must report 'not yet implemented'");
    } else {
        assert!(reports.iter().all(|r| r.passed() || r.not_done()), "some exercises are wrong");
    }
}
