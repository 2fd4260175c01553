//! Student exercises, one file per lesson, and the grader that checks them.
//!
//! Each exercise is a function whose doc comment states the task. Its body starts as a stub that
//! returns `Err(NotDone)`. Replace the stub with your code and return `Ok(answer)`. A panic in your
//! code (a `todo!()`, an index out of bounds) is caught: the native grader reports it as
//! `PANICKED`, and the lesson pages run your code in a separate module instance ([`run`]), so the
//! figure shows the message and falls back to the reference while the rest of the page goes on.
//!
//! The first line of each body, `solution!(...)`, calls the reference core function when the crate
//! is built with the `solutions` feature (used by CI to prove the grader passes a correct answer);
//! in a normal build it does nothing. Leave it where it is.
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

/// With the `solutions` feature, returns the reference answer from the enclosing exercise.
macro_rules! solution {
    ($reference:expr) => {
        if cfg!(feature = "solutions") {
            return Ok($reference);
        }
    };
}
pub(crate) use solution;
