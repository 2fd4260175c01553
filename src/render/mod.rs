//! The renderer (wasm only): one GPU device per page, shared by its canvases, WebGPU first,
//! WebGL2 otherwise.
//!
//! Everything here is shared by all lessons: a lesson fills a [`Frame`] (the native draw list of
//! `crate::draw`) (meshes with model
//! matrices, world-space lines, world-space point sprites) and the [`Renderer`] draws it with
//! depth testing and 4× multisampling. Limits are WebGL2's, so one build runs on both backends.

/// The text of the shader `src/render/shaders/NAME` as the build script wrote it into OUT_DIR
/// (without comments in a release build: see `scripts/build-shaders.rs`).
macro_rules! shader_source {
    ($name:literal) => {
        include_str!(concat!(env!("OUT_DIR"), "/", $name))
    };
}
pub(crate) use shader_source;

mod compute;
mod context;
mod fluid;
mod grid;
mod renderer;
mod skin;
mod texture;

pub use compute::{BoidsCompute, ParticlesCompute, ReadBack};
pub use context::{BackendChoice, Gpu};
pub use fluid::FluidCompute;
pub use grid::GpuGrid;
pub use renderer::{Frame, MeshId, Renderer};
pub use skin::SkinPass;
pub use texture::{NoiseImage, PendingRead};
