//! wasm-bindgen bindings (wasm only). Thin by design: each function checks what JavaScript
//! passed (lengths, finiteness, ranges), calls a core, and returns `Result<_, JsError>` whose
//! message the page shows in its error banner. No HTML is built here, no math re-implemented.

mod bench;
mod bench_curves;
mod bench_rotation;
mod curves;
mod rigid;
mod rotations;
mod transforms;
mod viewer;

pub use curves::{KeyframesScene, LagrangeScene};
pub use rigid::{AffineScene, RigidScene};
pub use rotations::{GimbalScene, InterpolationScene, RodriguesScene};
pub use transforms::{HierarchyScene, SingleShapeScene};
pub use viewer::Viewer;

use wasm_bindgen::prelude::*;

/// Runs once when the module loads: panics (bugs, never bad input) reach the console and the page.
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

/// The crate version and whether this build grades with the reference solutions.
#[wasm_bindgen(js_name = buildInfo)]
pub fn build_info() -> String {
    format!(
        "inbetween {}{}",
        env!("CARGO_PKG_VERSION"),
        if cfg!(feature = "solutions") {
            " (solutions build)"
        } else {
            ""
        }
    )
}

/// An error for JavaScript when `value` is NaN or infinite.
pub(crate) fn finite(name: &str, value: f32) -> Result<f32, JsError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(JsError::new(&format!(
            "{name} must be a finite number, got {value}"
        )))
    }
}

/// An error for JavaScript unless a plot asks for between 2 and 10 000 samples.
pub(crate) fn check_samples(samples: usize) -> Result<(), JsError> {
    if (2..=10_000).contains(&samples) {
        Ok(())
    } else {
        Err(JsError::new(&format!(
            "samples must be between 2 and 10000, got {samples}"
        )))
    }
}

/// An error for JavaScript when `value` lies outside `[lo, hi]` (or is not finite).
pub(crate) fn in_range(name: &str, value: f32, lo: f32, hi: f32) -> Result<f32, JsError> {
    finite(name, value)?;
    if (lo..=hi).contains(&value) {
        Ok(value)
    } else {
        Err(JsError::new(&format!(
            "{name} must lie in [{lo}, {hi}], got {value}"
        )))
    }
}
