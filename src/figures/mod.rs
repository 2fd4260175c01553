//! Figure logic, one module per lesson: scene state, validation of what the page passes, the
//! samples behind the plots, and what each figure draws (into a [`Frame`]). Plain Rust, so
//! `cargo test` checks it natively ("the drawn path passes through every key"); `web/` only wraps
//! these types for JavaScript and turns their `Err(String)` into `JsError`.
//!
//! Figures that can run a student's exercise hold a [`Runner`] (see [`crate::exercises::run`]) and
//! say, next to the figure, whether the student's answer matches the reference at the current
//! inputs (helpers below).

pub mod blend_shapes;
pub mod blending;
pub mod boids;
pub mod cloth;
pub mod curves;
pub mod expressive;
pub mod fluid;
pub mod gltf;
pub mod gpu;
pub mod ik;
pub mod noise;
pub mod noise_images;
pub mod particles;
pub mod particles_sprites;
pub mod raster;
pub mod rigid;
pub mod rigid_body;
pub mod rotations;
pub mod skeleton;
pub mod skinning;
pub mod transforms;

pub use crate::draw::{palette, Frame, MeshId};
pub use crate::exercises::run::{compare_note, format_number, Failure, Runner};
use glam::{Mat3, Quat};

/// The runner figures start with: natively (and in debug and course-module builds) the exercise
/// runs in-process; the web layer swaps in `web::sandbox::run`.
#[cfg(not(all(
    target_arch = "wasm32",
    not(debug_assertions),
    not(feature = "course-module"),
    not(feature = "bench-module")
)))]
pub const DEFAULT_RUNNER: Runner = crate::exercises::run::direct;

/// The release figures module never runs student code itself (the page's sandbox, an instance of
/// the course module, does), so it starts with a runner that says so and carries none of the
/// exercises' argument decoding.
#[cfg(all(
    target_arch = "wasm32",
    not(debug_assertions),
    not(feature = "course-module"),
    not(feature = "bench-module")
))]
pub const DEFAULT_RUNNER: Runner = |name, _| {
    Err(Failure::Call(format!(
        "{name}: this page has no exercise sandbox"
    )))
};

/// An error unless `value` is finite. Messages name the parameter, for the page.
pub fn finite(name: &str, value: f32) -> Result<f32, String> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(not_finite(name, value))
    }
}

/// [`finite`]'s message, out of line: every validated argument shares one copy of the formatting.
#[cold]
#[inline(never)]
fn not_finite(name: &str, value: f32) -> String {
    format!("{name} must be a finite number, got {value}")
}

/// An error unless `value` lies in `[lo, hi]` (and is finite).
pub fn in_range(name: &str, value: f32, lo: f32, hi: f32) -> Result<f32, String> {
    finite(name, value)?;
    if (lo..=hi).contains(&value) {
        Ok(value)
    } else {
        Err(out_of_range(name, value, lo, hi))
    }
}

/// [`in_range`]'s message, out of line (see [`not_finite`]).
#[cold]
#[inline(never)]
fn out_of_range(name: &str, value: f32, lo: f32, hi: f32) -> String {
    format!("{name} must lie in [{lo}, {hi}], got {value}")
}

/// `value` as a whole number in `[lo, hi]`: the one rule for every count a page passes (a
/// fraction, NaN or a number outside the range is an error, never rounded or truncated).
pub fn whole_number(name: &str, value: f32, lo: usize, hi: usize) -> Result<usize, String> {
    if value.is_finite() && value.fract() == 0.0 && value >= lo as f32 && value <= hi as f32 {
        Ok(value as usize)
    } else {
        Err(not_whole(name, value, lo, hi))
    }
}

/// [`whole_number`]'s message, out of line (see [`not_finite`]).
#[cold]
#[inline(never)]
fn not_whole(name: &str, value: f32, lo: usize, hi: usize) -> String {
    format!("{name} must be a whole number from {lo} to {hi}, got {value}")
}

/// The most samples a plot may ask for.
pub const MAX_SAMPLES: usize = 10_000;

/// An error unless a plot asks for between 2 and [`MAX_SAMPLES`] samples.
pub fn check_samples(samples: usize) -> Result<(), String> {
    if (2..=MAX_SAMPLES).contains(&samples) {
        Ok(())
    } else {
        Err(format!(
            "samples must be between 2 and {MAX_SAMPLES}, got {samples}"
        ))
    }
}

/// The first panic of a student's exercise in a figure: the input it was called with and the
/// panic's message. The page answers every later call of a panicked exercise with that same
/// message, whatever its input, so the figure names the input that caused it, not the one it
/// happened to try next. A new runner (a rebuilt exercise) starts afresh ([`FirstPanic::clear`]).
#[derive(Clone, Debug, Default)]
pub struct FirstPanic(std::cell::RefCell<Option<(String, String)>>);

impl FirstPanic {
    /// Keeps a panic met at `input` unless one is kept already.
    pub fn record(&self, input: &str, failure: &Failure) {
        if let Failure::Panicked(message) = failure {
            self.0
                .borrow_mut()
                .get_or_insert_with(|| (input.to_string(), message.clone()));
        }
    }

    /// What the figure says about `failure` met at `input` (exercise file `file`):
    /// [`failure_note`], with a panic named once, against the input of the first panic.
    pub fn note(&self, exercise: &str, file: &str, input: &str, failure: &Failure) -> String {
        self.record(input, failure);
        match (&*self.0.borrow(), failure) {
            (Some((at, message)), Failure::Panicked(_)) => failure_note(
                &format!("{exercise}, called with {at},"),
                file,
                &Failure::Panicked(message.clone()),
            ),
            _ => failure_note(exercise, file, failure),
        }
    }

    /// Forgets the panic (the runner changed).
    pub fn clear(&self) {
        self.0.borrow_mut().take();
    }
}

/// One sentence for the exercises of a figure that are all still stubs, instead of a
/// [`failure_note`] each: "Not done yet: exercises 13.1 spring_force, 13.2 cloth_euler_step and
/// 13.3 project_distance (src/exercises/cloth.rs). The figure uses the reference." Each of
/// `exercises` reads like "exercise 13.1 spring_force"; one alone reads as its `failure_note`;
/// none gives an empty string.
pub fn not_done_note(exercises: &[&str], file: &str) -> String {
    let names: Vec<&str> = exercises
        .iter()
        .map(|e| e.strip_prefix("exercise ").unwrap_or(e))
        .collect();
    match names.as_slice() {
        [] => String::new(),
        [_] => failure_note(exercises[0], file, &Failure::NotDone),
        [first @ .., last] => format!(
            "Not done yet: exercises {} and {last} ({file}). The figure uses the reference.",
            first.join(", ")
        ),
    }
}

/// What a figure says when the student's exercise gave no answer; the figure then uses the
/// reference. `exercise` reads like "exercise 3.2 slerp", `file` like "src/exercises/rotations.rs".
pub fn failure_note(exercise: &str, file: &str, failure: &Failure) -> String {
    match failure {
        Failure::NotDone => {
            format!("Not done yet: {exercise} ({file}). The figure uses the reference.")
        }
        Failure::Panicked(message) => {
            // Rust's own wording starts "panicked at file:line:col:\nmessage".
            let what = match message.strip_prefix("panicked at ") {
                Some(rest) => format!("panicked at {}", rest.replacen(":\n", ": ", 1)),
                None => format!("panicked: {message}"),
            };
            format!(
                "Your {exercise} {what}. The figure uses the reference until the page reloads: \
                 fix the code and save (under scripts/serve the page reloads itself after the \
                 rebuild; otherwise run scripts/build --dev and reload)."
            )
        }
        Failure::Call(message) => {
            format!("Could not run your {exercise}: {message}. The figure uses the reference.")
        }
    }
}

/// What is wrong with a matrix that should be a rotation: `None` when it is orthonormal with
/// determinant 1 (to `tolerance`), else a sentence with the numbers.
pub fn rotation_problem(m: Mat3, tolerance: f32) -> Option<String> {
    let off = (m.transpose() * m - Mat3::IDENTITY)
        .to_cols_array()
        .iter()
        .fold(0.0f32, |a, x| a.max(x.abs()));
    let det = m.determinant();
    if off.is_nan() || off > tolerance {
        Some(format!(
            "it is not a rotation: its columns are not orthonormal (largest entry of MᵀM − I is {})",
            format_number(off)
        ))
    } else if det.is_nan() || (det - 1.0).abs() > tolerance {
        Some(format!(
            "it is not a rotation: its determinant is {}, not 1",
            format_number(det)
        ))
    } else {
        None
    }
}

/// What is wrong with a quaternion that should be a unit quaternion, or `None`.
pub fn unit_quat_problem(q: Quat, tolerance: f32) -> Option<String> {
    let len = q.length();
    if len.is_nan() || (len - 1.0).abs() > tolerance {
        Some(format!(
            "it is not a unit quaternion: its length is {}",
            format_number(len)
        ))
    } else {
        None
    }
}

/// A test for [`Frame::first_clear_label_by`] on `view` (a view-projection and the canvas size,
/// CSS pixels): the label's box lies inside the canvas where the layout first puts it (not pushed
/// in from an edge, which the layout marks with a leader line), and it and 2 px round it hold
/// none of `points` (things the frame does not list: a wall, a mass, a board).
pub fn clear_of(
    view: Option<(glam::Mat4, glam::Vec2)>,
    points: &[glam::Vec3],
) -> impl Fn(crate::draw::layout::Rect) -> bool {
    let (view_proj, size) = view.unwrap_or((glam::Mat4::IDENTITY, glam::Vec2::ZERO));
    let on_canvas: Vec<glam::Vec2> = points
        .iter()
        .filter_map(|&p| crate::camera::project_to_canvas(view_proj, size, p))
        .collect();
    move |rect| {
        let edge = crate::draw::layout::EDGE_PX;
        let inside =
            rect.min.cmpgt(glam::Vec2::splat(edge)).all() && rect.max().cmplt(size - edge).all();
        let (lo, hi) = (rect.min - 2.0, rect.max() + 2.0);
        inside
            && on_canvas
                .iter()
                .all(|c| !(c.cmpgt(lo).all() && c.cmplt(hi).all()))
    }
}
