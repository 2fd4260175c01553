//! Student exercises, one file per lesson, and the grader that checks them.
//!
//! Each exercise is a function whose doc comment states the task. Its body starts as a stub that
//! returns `Err(NotDone)`. Replace the stub with your code and return `Ok(answer)`. A panic in your
//! code (a `todo!()`, an index out of bounds) is caught: the native grader reports it as
//! `PANICKED`, and the lesson pages run your code in a separate module instance ([`run`]), so the
//! figure shows the message and falls back to the reference while the rest of the page goes on.
//!
//! The first line of each body, `solution!(...)`, calls the reference core function when the crate
//! is built with the `solutions` feature, or while the grader's own test checks that a correct
//! answer passes ([`with_reference_answers`]); otherwise it does nothing. Leave it where it is.
//!
//! Grade with `./scripts/grade` (natively) or `./scripts/grade --browser` (headless Chromium).

pub mod blend_shapes;
pub mod blending;
pub mod boids;
pub mod cloth;
pub mod curves;
pub mod expressive;
pub mod fluid;
pub mod grade;
pub mod ik;
pub mod noise;
pub mod particles;
pub mod raster;
pub mod rigid_body;
pub mod rotations;
pub mod run;
pub mod skeleton;
pub mod skinning;
pub mod transforms;

/// An exercise's answer: `Ok(value)` once implemented, `Err(NotDone)` while it is still a stub.
pub type Answer<T> = Result<T, NotDone>;

/// The marker a stub returns: "not implemented yet".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NotDone;

impl std::fmt::Display for NotDone {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("not yet implemented")
    }
}

/// With the `solutions` feature, or on a thread inside [`with_reference_answers`], returns the
/// reference answer from the enclosing exercise.
macro_rules! solution {
    ($reference:expr) => {
        if cfg!(feature = "solutions") || $crate::exercises::reference_answers_on() {
            return Ok($reference);
        }
    };
}
pub(crate) use solution;

thread_local! {
    static REFERENCE_ANSWERS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    static STUDENT_BUGS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Sets `switch` for the time of `f` on this thread (back to what it was when `f` returns or
/// unwinds). Only builds with debug assertions have the switches (see [`with_reference_answers`]).
fn switched_on<T>(
    switch: &'static std::thread::LocalKey<std::cell::Cell<bool>>,
    f: impl FnOnce() -> T,
) -> T {
    assert!(
        cfg!(debug_assertions),
        "the exercises' test switches need a build with debug assertions"
    );
    struct Restore(&'static std::thread::LocalKey<std::cell::Cell<bool>>, bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            self.0.set(self.1);
        }
    }
    let _restore = Restore(switch, switch.replace(true));
    f()
}

/// Whether the exercises on this thread answer with their reference solutions (see
/// [`with_reference_answers`]). Always false in a build without debug assertions (a release
/// build), where the check compiles away.
#[doc(hidden)]
#[inline]
pub fn reference_answers_on() -> bool {
    cfg!(debug_assertions) && REFERENCE_ANSWERS.get()
}

/// Runs `f` with every exercise on this thread answering with its reference solution, as a build
/// with the feature `solutions` does. The grader's tests use it to check that a right answer
/// passes in the same build that checks the untouched stubs, instead of compiling the crate a
/// second time with the feature. Only builds with debug assertions (the test profile) have the
/// switch: elsewhere it panics instead of running `f`.
#[doc(hidden)]
pub fn with_reference_answers<T>(f: impl FnOnce() -> T) -> T {
    switched_on(&REFERENCE_ANSWERS, f)
}

/// Whether the exercises on this thread make the three planted mistakes of the isolation test
/// (`run::student_bugs`): in a build with the feature `student-bugs`, or inside
/// [`with_student_bugs`] in a build with debug assertions.
#[doc(hidden)]
#[inline]
pub fn student_bugs_on() -> bool {
    cfg!(feature = "student-bugs") || (cfg!(debug_assertions) && STUDENT_BUGS.get())
}

/// Runs `f` with the exercises making the planted mistakes of the feature `student-bugs` (see
/// [`student_bugs_on`]): the native grader's table for the isolation test's page, from the build
/// the native tests use. Panics in a build without debug assertions.
#[doc(hidden)]
pub fn with_student_bugs<T>(f: impl FnOnce() -> T) -> T {
    switched_on(&STUDENT_BUGS, f)
}
