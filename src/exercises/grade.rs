//! The grader: runs each exercise on many inputs and compares it with the reference core.
//!
//! It is plain Rust, so the same code grades natively (`tests/grader.rs`) and in headless Chromium
//! (`tests/web_grader.rs`). Inputs come from a fixed-seed generator, so a failure reproduces.

use super::Answer;
pub use crate::fixtures::Rng;
use glam::Mat4;
use std::fmt::{self, Debug};

/// The outcome of grading one exercise.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    /// Every case matched the reference.
    Passed { cases: usize },
    /// The exercise still returns `Err(NotDone)`.
    NotDone,
    /// The first case whose answer differs from the reference.
    Wrong {
        /// The case's number, counting from 1 (as a student counts them).
        case: usize,
        /// What the case is meant to test ("keys with a·b < 0: the short arc").
        what: String,
        input: String,
        expected: String,
        actual: String,
    },
    /// The exercise panicked (caught natively only: a wasm panic aborts the module).
    Panicked {
        /// The case's number, counting from 1.
        case: usize,
        what: String,
        input: String,
        message: String,
        /// Where it panicked, `file:line:column` (as the browser's report gives it).
        location: Option<String>,
    },
}

/// One row of the grade table.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    pub lesson: &'static str,
    pub exercise: &'static str,
    pub status: Status,
}

impl Report {
    pub fn passed(&self) -> bool {
        matches!(self.status, Status::Passed { .. })
    }
    pub fn not_done(&self) -> bool {
        self.status == Status::NotDone
    }
}

/// Grades every exercise of every lesson.
pub fn grade_all() -> Vec<Report> {
    let mut rng = Rng::new(0x1b_e7_7e_e2);
    let mut reports = Vec::new();
    reports.extend(super::raster::grade(&mut rng));
    reports.extend(super::transforms::grade(&mut rng));
    reports.extend(super::curves::grade(&mut rng));
    reports.extend(super::expressive::grade(&mut rng));
    reports.extend(super::rotations::grade(&mut rng));
    reports.extend(super::noise::grade(&mut rng));
    reports.extend(super::skeleton::grade(&mut rng));
    reports.extend(super::ik::grade(&mut rng));
    reports.extend(super::skinning::grade(&mut rng));
    reports.extend(super::blend_shapes::grade(&mut rng));
    reports.extend(super::particles::grade(&mut rng));
    reports.extend(super::boids::grade(&mut rng));
    reports.extend(super::cloth::grade(&mut rng));
    reports
}

/// What a case of random inputs is said to test.
pub const RANDOM: &str = "random input";

/// Runs `student` and `reference` on each input; the first disagreement (by `close`) fails.
/// Every case counts as [`RANDOM`]; [`check_cases`] says what each edge case tests.
pub fn check<I: Debug, O: Debug>(
    lesson: &'static str,
    exercise: &'static str,
    inputs: &[I],
    student: impl Fn(&I) -> Answer<O>,
    reference: impl Fn(&I) -> O,
    close: impl Fn(&O, &O) -> bool,
) -> Report {
    let cases: Vec<(&str, &I)> = inputs.iter().map(|i| (RANDOM, i)).collect();
    check_cases(
        lesson,
        exercise,
        &cases,
        |i| student(i),
        |i| reference(i),
        close,
    )
}

/// Like [`check`], with each input paired with what it tests, e.g.
/// `("keys with a·b < 0: the short arc", input)`, so that a wrong answer says what it got wrong.
pub fn check_cases<I: Debug, O: Debug>(
    lesson: &'static str,
    exercise: &'static str,
    cases: &[(&str, I)],
    student: impl Fn(&I) -> Answer<O>,
    reference: impl Fn(&I) -> O,
    close: impl Fn(&O, &O) -> bool,
) -> Report {
    let status = (|| {
        // Numbered from 1: "WRONG at case 1" is the first case a student would count.
        for (case, (what, input)) in (1..).zip(cases) {
            let context = || format!("exercise {exercise} ({lesson}), case {case} ({what})");
            let answer = match run_caught(context, || student(input)) {
                Ok(answer) => answer,
                Err(Caught { message, location }) => {
                    return Status::Panicked {
                        case,
                        what: what.to_string(),
                        input: format!("{input:?}"),
                        message,
                        location,
                    };
                }
            };
            let Ok(actual) = answer else {
                return Status::NotDone;
            };
            let expected = reference(input);
            if !close(&expected, &actual) {
                return Status::Wrong {
                    case,
                    what: what.to_string(),
                    input: format!("{input:?}"),
                    expected: format!("{expected:?}"),
                    actual: format!("{actual:?}"),
                };
            }
        }
        Status::Passed { cases: cases.len() }
    })();
    Report {
        lesson,
        exercise,
        status,
    }
}

/// A caught panic: its message and where it happened.
struct Caught {
    message: String,
    location: Option<String>,
}

/// Runs `f`, catching a panic. `catch_unwind` gives only the payload (the message); the location
/// is known only to the panic hook, so while `f` runs a hook records it for this thread (and
/// prints nothing: the report says it all), handing other threads' panics to the hook that was
/// there. That very hook is put back afterwards (not wrapped, so grading many cases does not
/// chain hooks). Hooks are global: one grading call at a time swaps them, so parallel tests put
/// the right one back.
#[cfg(not(target_arch = "wasm32"))]
fn run_caught<T>(_context: impl Fn() -> String, f: impl FnOnce() -> T) -> Result<T, Caught> {
    use std::panic::{self, PanicHookInfo};
    use std::sync::{Arc, Mutex};
    type Hook = Box<dyn Fn(&PanicHookInfo<'_>) + Send + Sync + 'static>;
    static SWAPPING: Mutex<()> = Mutex::new(());
    let _one_at_a_time = SWAPPING.lock().unwrap_or_else(|e| e.into_inner());
    let previous: Arc<Mutex<Option<Hook>>> = Arc::new(Mutex::new(Some(panic::take_hook())));
    let location = Arc::new(Mutex::new(None::<String>));
    let (seen, chained) = (location.clone(), previous.clone());
    let grading = std::thread::current().id();
    panic::set_hook(Box::new(move |info| {
        if std::thread::current().id() == grading {
            let at = info
                .location()
                .map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()));
            *seen.lock().unwrap_or_else(|e| e.into_inner()) = at;
        } else if let Some(hook) = chained.lock().unwrap_or_else(|e| e.into_inner()).as_ref() {
            hook(info);
        }
    }));
    let result = panic::catch_unwind(panic::AssertUnwindSafe(f));
    // Dropping the grading hook drops its handle on `previous`.
    drop(panic::take_hook());
    let hook = previous.lock().unwrap_or_else(|e| e.into_inner()).take();
    if let Some(hook) = hook {
        panic::set_hook(hook);
    }
    result.map_err(|payload| Caught {
        message: payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "panic".to_string()),
        location: location.lock().unwrap_or_else(|e| e.into_inner()).take(),
    })
}

/// In wasm a panic cannot be caught: it ends the module. While the student's code runs, a panic
/// hook first says, in one line, which exercise and case panicked and what to do, then hands over
/// to the hook that was there (the test runner's).
#[cfg(target_arch = "wasm32")]
fn run_caught<T>(context: impl Fn() -> String, f: impl FnOnce() -> T) -> Result<T, Caught> {
    use std::panic::PanicHookInfo;
    use std::sync::{Arc, Mutex};
    type Hook = Box<dyn Fn(&PanicHookInfo<'_>) + Send + Sync + 'static>;
    let previous: Arc<Mutex<Option<Hook>>> = Arc::new(Mutex::new(Some(std::panic::take_hook())));
    let context = context();
    let chained = previous.clone();
    std::panic::set_hook(Box::new(move |info| {
        let message = format!(
            "Your {context} panicked: {info}\nThe browser grader stops at the first panic (a \
             WebAssembly module cannot continue after one); `scripts/grade` (native) reports it as \
             PANICKED and grades the other exercises."
        );
        web_sys::console::error_1(&message.into());
        if let Some(hook) = chained.lock().unwrap_or_else(|e| e.into_inner()).as_ref() {
            hook(info);
        }
    }));
    let answer = f();
    // Put back the very hook that was there (see the native `run_caught`).
    drop(std::panic::take_hook());
    let hook = previous.lock().unwrap_or_else(|e| e.into_inner()).take();
    if let Some(hook) = hook {
        std::panic::set_hook(hook);
    }
    Ok(answer)
}

/// Element-wise comparison with a tolerance scaled by the larger magnitude.
pub fn mat4_close(a: &Mat4, b: &Mat4, eps: f32) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array().iter())
        .all(|(x, y)| (x - y).abs() <= eps * (1.0 + x.abs().max(y.abs())))
}

/// The grade table, one row per exercise, then a summary line.
pub fn table(reports: &[Report]) -> String {
    let mut out = String::new();
    let w_lesson = reports
        .iter()
        .map(|r| r.lesson.len())
        .max()
        .unwrap_or(0)
        .max(6);
    let w_ex = reports
        .iter()
        .map(|r| r.exercise.len())
        .max()
        .unwrap_or(0)
        .max(8);
    out += &format!("{:<w_lesson$}  {:<w_ex$}  status\n", "lesson", "exercise");
    out += &format!("{}\n", "-".repeat(w_lesson + w_ex + 30));
    for r in reports {
        out += &format!(
            "{:<w_lesson$}  {:<w_ex$}  {}\n",
            r.lesson, r.exercise, r.status
        );
    }
    let passed = reports.iter().filter(|r| r.passed()).count();
    let todo = reports.iter().filter(|r| r.not_done()).count();
    out += &format!(
        "\n{passed} passed, {todo} not yet implemented, {} wrong, of {}\n",
        reports.len() - passed - todo,
        reports.len()
    );
    out
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Status::Passed { cases } => write!(f, "passed ({cases} cases)"),
            Status::NotDone => write!(f, "not yet implemented"),
            Status::Wrong { case, what, input, expected, actual } => write!(
                f,
                "WRONG at case {case} ({what})\n      input:    {input}\n      expected: {expected}\n      actual:   {actual}"
            ),
            Status::Panicked { case, what, input, message, location } => write!(
                f,
                "PANICKED at case {case} ({what}): {message}{}\n      input: {input}",
                location.as_ref().map_or(String::new(), |at| format!(" ({at})"))
            ),
        }
    }
}
