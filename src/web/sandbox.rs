//! The page side of [`crate::exercises::run`]: student code runs in a second module instance.
//!
//! `www/lesson.js` runs the figures in the figures module and student code in instances of the
//! course module (`scripts/build` builds both; see `web::course`), the *sandbox*, and
//! publishes `globalThis.__inbetweenSandbox = { call(name, args) }`. A figure's [`run`] hands
//! the flattened arguments to that object, which calls [`run_exercise`] in the sandbox. A panic
//! there traps only the sandbox: the shell records the message (from [`super::install_panic_hook`]),
//! answers this call and later calls of the same exercise with a `panic` error, and starts a fresh
//! sandbox for the other exercises. Without a sandbox (browser unit tests) the exercise runs in
//! this instance, except in the release figures module, which carries no exercise code.

use crate::exercises::run::{self, Failure};
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    /// `__inbetweenSandbox.call(name, args)`: a Float32Array, or throws `{ kind, message }`.
    #[wasm_bindgen(catch, js_namespace = __inbetweenSandbox, js_name = call)]
    fn sandbox_call(name: &str, args: &[f32]) -> Result<js_sys::Float32Array, JsValue>;
}

fn sandbox_present() -> bool {
    js_sys::Reflect::has(&js_sys::global(), &JsValue::from_str("__inbetweenSandbox"))
        .unwrap_or(false)
}

/// The [`run::Runner`] the figures use in the page.
pub fn run(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if !sandbox_present() {
        return crate::figures::DEFAULT_RUNNER(name, args);
    }
    match sandbox_call(name, args) {
        Ok(out) => Ok(out.to_vec()),
        Err(e) => {
            let field = |key: &str| {
                js_sys::Reflect::get(&e, &JsValue::from_str(key))
                    .ok()
                    .and_then(|v| v.as_string())
                    .unwrap_or_default()
            };
            let message = field("message");
            Err(match field("kind").as_str() {
                "not-done" => Failure::NotDone,
                "panic" => Failure::Panicked(message),
                _ => Failure::Call(if message.is_empty() {
                    format!("{e:?}")
                } else {
                    message
                }),
            })
        }
    }
}

/// Runs the exercise `name` in *this* instance (the sandbox). A stub throws an error whose message
/// is `not-done`; a panic traps (the shell catches it). The shell's sandboxes are course modules;
/// the release figures module has no copy of it (see `figures::DEFAULT_RUNNER`).
#[cfg(any(debug_assertions, feature = "course-module"))]
#[wasm_bindgen(js_name = runExercise)]
pub fn run_exercise(name: JsValue, args: &[f32]) -> Result<Vec<f32>, JsError> {
    let name: &str = &super::string("name", &name)?;
    match run::direct(name, args) {
        Ok(out) => Ok(out),
        Err(Failure::NotDone) => Err(JsError::new("not-done")),
        Err(other) => Err(JsError::new(&other.to_string())),
    }
}

/// The names of the exercises a figure can run (for the shell and the tests).
#[wasm_bindgen(js_name = exerciseNames)]
pub fn exercise_names() -> Vec<String> {
    run::NAMES.iter().map(|s| s.to_string()).collect()
}
