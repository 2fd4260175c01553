//! wasm-bindgen bindings (wasm only). Thin by design: each function checks what JavaScript
//! passed (lengths, finiteness, ranges), calls a core, and returns `Result<_, JsError>` whose
//! message the page shows in its error banner. No HTML is built here, no math re-implemented.

mod bench;
mod bench_boids;
mod bench_cloth;
mod bench_curves;
mod bench_gpu;
mod bench_noise;
mod bench_rotation;
mod bench_skeleton;
mod bench_skinning;
mod blend_shapes;
mod blending;
mod boids;
mod cloth;
mod curves;
mod expressive;
mod gltf;
mod ik;
mod noise;
mod noise_images;
mod particles;
mod particles_sprites;
mod raster;
mod rigid;
mod rotations;
pub mod sandbox;
mod skeleton;
mod skinning;
mod transforms;
mod viewer;

pub use blend_shapes::BlendShapeFaceScene;
pub use blending::{BlendScene, LocomotionScene};
pub use boids::{BoidRulesScene, FlockScene};
pub use cloth::{check_cloth, ClothScene, SpringScene};
pub use curves::{KeyframesScene, LagrangeScene};
pub use expressive::{FollowThroughScene, JumpScene, SpacingScene};
pub use ik::{AimScene, IkScene};
pub use noise::{
    FractalsScene, Noise1dScene, Noise2dScene, OctavesScene, QuizScene, TerrainFigureScene,
    TexturesScene,
};
pub use particles::{check_emitter, BounceScene, EmitterScene, FreeFallScene, SquashScene};
pub use raster::{DepthPrecisionScene, FrustumScene, MeshStorageScene, NormalsScene, ShadingScene};
pub use rigid::{AffineScene, RigidScene};
pub use rotations::{GimbalScene, InterpolationScene, RodriguesScene};
pub use skeleton::{check_skeleton, SkeletonScene};
pub use skinning::{check_skin_weights, SkinnedHumanScene, SkinningCylinderScene};
pub use transforms::{HierarchyScene, ScaleComparisonScene, SingleShapeScene};
pub use viewer::Viewer;

use wasm_bindgen::prelude::*;

/// Runs once when the module loads: panics reach the page (and the console); see [`sandbox`].
#[wasm_bindgen(start)]
pub fn start() {
    sandbox::install_panic_hook();
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

/// A native figure's error message as a JavaScript error.
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
