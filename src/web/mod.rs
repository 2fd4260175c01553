//! wasm-bindgen bindings (wasm only). Thin by design: each function checks what JavaScript
//! passed (lengths, finiteness, ranges), calls a core, and returns `Result<_, JsError>` whose
//! message the page shows in its error banner. No HTML is built here, no math re-implemented.
//!
//! Arguments are checked at this boundary before anything changes (see [`string`], [`whole`]):
//! a wrong type, a fraction where a count is expected or a value outside its range is an error
//! that names the parameter. `scripts/probe-bindings.mjs` calls every export with hostile
//! arguments and fails on a panic, a hang, a non-finite output or a half-applied call.
//!
//! One case is not guarded: a method called on an object of another class
//! (`KeyframesScene.prototype.position.call(new LagrangeScene(), 0.5)`). The generated glue
//! passes the receiver's `__wbg_ptr` without checking its class, so the method reads the other
//! object's memory as its own, or traps. Guarding it would take a class tag in every object and a
//! check in every method of generated code; neither the pages nor the shell make such a call, and
//! a receiver that is no binding object at all (pointer 0) is already an error.

// The course and bench modules use a few of the argument checks below, not all.
#![cfg_attr(
    any(
        feature = "course-module",
        feature = "bench-module",
        feature = "gltf-module"
    ),
    allow(dead_code)
)]

// One crate, four modules (see the crate's doc and `scripts/build`): the figures module (no
// feature), the course module (feature `course-module`: the grader and quiz bindings, see
// `course`), the bench module (feature `bench-module`: the bench page's CPU kernels) and the
// glTF module (feature `gltf-module`: the importer, see `gltf_module`). Each holds `start` and
// `buildInfo` below; the figures and course modules hold the sandbox's `runExercise`.
#[cfg(any(
    all(feature = "course-module", feature = "bench-module"),
    all(feature = "course-module", feature = "gltf-module"),
    all(feature = "bench-module", feature = "gltf-module")
))]
compile_error!(
    "the features `course-module`, `bench-module` and `gltf-module` each build a module of their own: enable one"
);
#[cfg(all(
    feature = "bench-full",
    any(
        feature = "course-module",
        feature = "bench-module",
        feature = "gltf-module"
    )
))]
compile_error!("`bench-full` is the figures module with the bench kernels: no other module feature");
#[cfg(all(feature = "bench-alone", not(feature = "bench-module")))]
compile_error!("`bench-alone-X` narrows the bench module: enable `bench-module` too");

mod alloc;
#[cfg(feature = "course-module")]
mod course;
#[cfg(feature = "gltf-module")]
mod gltf_module;
#[cfg(not(any(feature = "bench-module", feature = "gltf-module")))]
pub mod sandbox;

/// Items of the figures module only: the figures' bindings, the GPU benchmarks' and the renderer's
/// users.
macro_rules! figures_module {
    ($($item:item)*) => {
        $( #[cfg(not(any(feature = "course-module", feature = "bench-module", feature = "gltf-module")))] $item )*
    };
}

/// Items of the bench module only: the bench page's CPU kernels (`www/bench.js`), each timed
/// inside wasm. The GPU kernels (`bench_gpu`) need the renderer and stay in the figures module.
/// A benchmark build adds them to the figures module (`bench-full`) or keeps one family
/// (`bench-alone-X`, see Cargo.toml).
macro_rules! bench_module {
    ($($item:item)*) => {
        $( #[cfg(any(feature = "bench-module", feature = "bench-full"))] $item )*
    };
}

bench_module! {
    #[cfg(not(feature = "bench-alone"))]
    mod bench;
    #[cfg(any(not(feature = "bench-alone"), feature = "bench-alone-boids"))]
    mod bench_boids;
    #[cfg(not(feature = "bench-alone"))]
    mod bench_cloth;
    #[cfg(not(feature = "bench-alone"))]
    mod bench_curves;
    #[cfg(not(feature = "bench-alone"))]
    mod bench_fluid;
    #[cfg(any(not(feature = "bench-alone"), feature = "bench-alone-noise"))]
    mod bench_noise;
    #[cfg(not(feature = "bench-alone"))]
    mod bench_rigid_body;
    #[cfg(not(feature = "bench-alone"))]
    mod bench_rotation;
    #[cfg(any(not(feature = "bench-alone"), feature = "bench-alone-skeleton"))]
    mod bench_skeleton;
    #[cfg(any(not(feature = "bench-alone"), feature = "bench-alone-skinning"))]
    mod bench_skinning;
}

figures_module! {
    mod bench_gpu;
    mod blend_shapes;
    mod blending;
    mod boids;
    mod cloth;
    mod curves;
    mod expressive;
    mod fluid;
    mod gltf;
    mod ik;
    mod noise;
    mod noise_images;
    mod particles;
    mod particles_sprites;
    mod raster;
    mod rigid;
    mod rigid_body;
    mod rotations;
    mod skeleton;
    mod skinning;
    mod transforms;
    mod viewer;

    pub use blend_shapes::{BlendShapeFaceScene, BlendShapeTargetsScene};
    pub use blending::{BlendScene, LocomotionScene};
    pub use boids::{BoidRulesScene, FlockScene};
    pub use cloth::{check_cloth, ClothScene, SpringScene};
    pub use curves::{CardinalScene, KeyframesScene, LagrangeScene};
    pub use expressive::{FollowThroughScene, JumpScene, SpacingScene, StretchScene};
    pub use fluid::{DamBreakScene, DensityScene, KernelsScene, SplashScene};
    pub use ik::{AimScene, IkScene};
    pub use noise::{
        FractalsScene, Noise1dScene, Noise2dScene, OctavesScene, QuizScene, TerrainFigureScene,
        TexturesScene, TerrainNormalsScene, VariantsScene,
    };
    pub use particles::{check_emitter, BounceScene, EmitterScene, FreeFallScene, SquashScene};
    pub use raster::{DepthPrecisionScene, FrustumScene, MeshStorageScene, NormalsScene, ShadingScene};
    pub use rigid::{AffineScene, RigidScene};
    pub use rigid_body::{DriftScene, ImpulseScene, RacketScene, StackScene, ThrowScene};
    pub use rotations::{GimbalScene, InterpolationScene, RodriguesScene};
    pub use skeleton::{check_skeleton, SkeletonScene};
    pub use skinning::{check_skin_weights, SkinnedHumanScene, SkinningCylinderScene};
    pub use transforms::{HierarchyScene, ScaleComparisonScene, SingleShapeScene};
    pub use viewer::Viewer;
}

use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    /// `__inbetweenPanic(message)`: true when the shell took care of the panic (a sandbox call).
    #[wasm_bindgen(catch, js_name = __inbetweenPanic)]
    fn report_panic(message: &str) -> Result<JsValue, JsValue>;
}

/// Runs once when the module loads: panics reach the page (and the console); see [`sandbox`].
#[wasm_bindgen(start)]
pub fn start() {
    install_panic_hook();
}

/// Panics go to the page first (which shows the message where it belongs), then to the console
/// unless the page took care of them.
pub fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        let handled = report_panic(&info.to_string())
            .map(|v| v.as_bool() == Some(true))
            .unwrap_or(false);
        if !handled {
            console_error_panic_hook::hook(info);
        }
    }));
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

/// A native figure's error message as a JavaScript error (out of line: every binding's error
/// path shares it).
#[cold]
#[inline(never)]
pub(crate) fn js(message: String) -> JsError {
    JsError::new(&message)
}

/// An error for JavaScript when `value` is NaN or infinite ([`crate::figures::finite`]).
pub(crate) fn finite(name: &str, value: f32) -> Result<f32, JsError> {
    crate::figures::finite(name, value).map_err(js)
}

/// An error for JavaScript when `value` lies outside `[lo, hi]` (or is not finite).
pub(crate) fn in_range(name: &str, value: f32, lo: f32, hi: f32) -> Result<f32, JsError> {
    crate::figures::in_range(name, value, lo, hi).map_err(js)
}

// Argument checks at the boundary. wasm-bindgen converts a JavaScript argument to the Rust
// parameter's type without asking: a number for a `u32` or `usize` wraps (NaN and ±Infinity become
// 0, -1 becomes 4294967295, 1.5 becomes 1, 2^32 + 3 becomes 3), a `bool` takes any value's
// truthiness, and a non-string for a `&str` makes the glue read past its buffer. Exported functions
// therefore take counts and indices as `f64` and names, flags and lists of names as `JsValue`, and
// check them here before any state changes. One rule for every count and index: a whole number in
// the stated range, else an error that names the parameter, the range and the value.

/// The largest whole number a count or index may be when no narrower range is known: a `u32`.
pub(crate) const MAX_WHOLE: usize = u32::MAX as usize;

/// `value` as a whole number in `[lo, hi]`, or an error such as "count must be a whole number
/// from 1 to 1000, got 1.5". NaN, ±Infinity, fractions and numbers outside the range are errors.
pub(crate) fn whole_in(name: &str, value: f64, lo: usize, hi: usize) -> Result<usize, JsError> {
    if value.is_finite() && value.fract() == 0.0 && value >= lo as f64 && value <= hi as f64 {
        Ok(value as usize)
    } else {
        Err(not_whole(name, value, lo, hi))
    }
}

/// [`whole_in`]'s error, out of line: every count a binding checks shares one copy.
#[cold]
#[inline(never)]
fn not_whole(name: &str, value: f64, lo: usize, hi: usize) -> JsError {
    JsError::new(&format!(
        "{name} must be a whole number from {lo} to {hi}, got {value}"
    ))
}

/// `value` as a whole number from 0 to [`MAX_WHOLE`]; the figure checks the narrower range it
/// knows (a joint index against the joint count, a sample count against its cap).
pub(crate) fn whole(name: &str, value: f64) -> Result<usize, JsError> {
    whole_in(name, value, 0, MAX_WHOLE)
}

/// Every element of `values` as a whole number from `lo` to `hi` (a list of joint indices).
pub(crate) fn wholes(name: &str, values: &[f64], lo: f64, hi: f64) -> Result<Vec<f64>, JsError> {
    match values
        .iter()
        .position(|&v| !(v.is_finite() && v.fract() == 0.0 && v >= lo && v <= hi))
    {
        None => Ok(values.to_vec()),
        Some(i) => Err(JsError::new(&format!(
            "{name}[{i}] must be a whole number from {lo} to {hi}, got {}",
            values[i]
        ))),
    }
}

/// The type of a JavaScript value, for error messages: "number 42", "object", "undefined".
fn describe(value: &JsValue) -> String {
    if let Some(n) = value.as_f64() {
        format!("number {n}")
    } else if let Some(b) = value.as_bool() {
        format!("boolean {b}")
    } else {
        value.js_typeof().as_string().unwrap_or_default()
    }
}

/// `value` as a string, or a TypeError-like error "name must be a string, got number 42".
#[inline(never)]
pub(crate) fn string(name: &str, value: &JsValue) -> Result<String, JsError> {
    value
        .as_string()
        .ok_or_else(|| JsError::new(&format!("{name} must be a string, got {}", describe(value))))
}

/// `value` as a boolean: `true` or `false` only ("true", 1 and undefined are errors, not coerced).
#[inline(never)]
pub(crate) fn boolean(name: &str, value: &JsValue) -> Result<bool, JsError> {
    value.as_bool().ok_or_else(|| {
        JsError::new(&format!(
            "{name} must be true or false, got {}",
            describe(value)
        ))
    })
}

/// `value` as an array of at most `max_items` strings, each at most `max_chars` UTF-16 code
/// units long (a plain string is not split into its characters). Both caps are checked before
/// anything is copied, so the work never grows past them.
pub(crate) fn strings(
    name: &str,
    value: &JsValue,
    max_items: usize,
    max_chars: usize,
) -> Result<Vec<String>, JsError> {
    if !js_sys::Array::is_array(value) {
        return Err(JsError::new(&format!(
            "{name} must be an array of strings, got {}",
            describe(value)
        )));
    }
    let array = js_sys::Array::from(value);
    let len = array.length() as usize;
    if len > max_items {
        return Err(JsError::new(&format!(
            "{name} may hold at most {max_items} strings, got {len}"
        )));
    }
    let mut out = Vec::with_capacity(len);
    for (i, item) in array.iter().enumerate() {
        let what = format!("{name}[{i}]");
        if let Some(s) = item.dyn_ref::<js_sys::JsString>() {
            if s.length() as usize > max_chars {
                return Err(JsError::new(&format!(
                    "{what} may be at most {max_chars} characters long, got {}",
                    s.length()
                )));
            }
        }
        out.push(string(&what, &item)?);
    }
    Ok(out)
}

/// `value` as a `Uint8Array` (an array of numbers would be wrapped modulo 256), not yet copied
/// into wasm memory: the caller checks its `length()` against its cap before `to_vec()`.
pub(crate) fn bytes(name: &str, value: &JsValue) -> Result<js_sys::Uint8Array, JsError> {
    value
        .dyn_ref::<js_sys::Uint8Array>()
        .cloned()
        .ok_or_else(|| {
            JsError::new(&format!(
                "{name} must be a Uint8Array, got {}",
                describe(value)
            ))
        })
}

/// An error unless a bench call's work, `size × iterations` items, is at most `max_work`. Each
/// kernel's cap is set so that a call at the cap runs for seconds, not hours (a size and an
/// iteration count each in its own range can multiply to days of work), and well above what the
/// bench page's 100 ms batches ask for.
pub(crate) fn check_work(
    size_name: &str,
    size: u64,
    iterations: usize,
    max_work: u64,
) -> Result<(), JsError> {
    let work = size.saturating_mul(iterations as u64);
    if work <= max_work {
        Ok(())
    } else {
        Err(JsError::new(&format!(
            "{size_name} × iterations must be at most {max_work} (the kernel's work cap), got \
             {size} × {iterations} = {work}"
        )))
    }
}

/// `value` as a `<canvas>` element (a figure's or a bench's drawing surface).
pub(crate) fn canvas(name: &str, value: JsValue) -> Result<web_sys::HtmlCanvasElement, JsError> {
    value.dyn_into::<web_sys::HtmlCanvasElement>().map_err(|v| {
        JsError::new(&format!(
            "{name} must be a canvas element, got {}",
            describe(&v)
        ))
    })
}
