//! # inbetween: the computational cores of an in-browser course on 3D computer animation
//!
//! Each lesson in `lessons/` has a core module here (pure Rust + glam, tested natively), its figure
//! logic in [`figures`] (scene state, validation, plot samples, what is drawn into a [`draw::Frame`];
//! also native and tested natively), a thin binding in `web/` (wasm only: `#[wasm_bindgen]`
//! wrappers and `JsError`s) and graded exercises in `exercises/`.
//!
//! | lesson | core | scene | binding | exercises |
//! |---|---|---|---|---|
//! | `00-triangles-to-pixels`: from triangles to pixels | [`raster`] | [`figures::raster`] | `web::raster` | [`exercises::raster`] (0.x) |
//! | `01-transforms`: transforms and hierarchies | [`transform`], [`mesh`], [`camera`] | [`figures::transforms`] | `web::transforms` | [`exercises::transforms`] |
//! | `02-keyframes`: keyframes and splines | [`curves`] | [`figures::curves`] | `web::curves` (bench: `web::bench_curves`) | [`exercises::curves`] |
//! | `02b-expressive-animation`: expressive animation | [`expressive`], [`curves`] (easing) | [`figures::expressive`] | `web::expressive` | [`exercises::expressive`] (2b.x) |
//! | `03-rotations`: rotations | [`rotation`] | [`figures::rotations`] | `web::rotations` (bench: `web::bench_rotation`) | [`exercises::rotations`] (3.x) |
//! | `04-rigid-motions`: rigid motions | [`rigid`], [`rotation`] (polar, affine keys) | [`figures::rigid`] | `web::rigid` | [`exercises::rotations`] (4.x) |
//! | `05-noise`: noise and terrain | [`noise`], [`terrain`] | [`figures::noise`] | `web::noise` (bench: `web::bench_noise`) | [`exercises::noise`] |
//! | `06-skeletons`: skeletons and forward kinematics | [`skeleton`], [`gltf_import`] | [`figures::skeleton`], [`figures::gltf`] | `web::skeleton`, `web::gltf`, `web::gltf_module` (bench: `web::bench_skeleton`) | [`exercises::skeleton`] (6.x) |
//! | `07-inverse-kinematics`: inverse kinematics | [`ik`] | [`figures::ik`] | `web::ik` | [`exercises::ik`] (7.x) |
//! | `08-blending`: blending | [`skeleton`] (blend, locomotion) | [`figures::blending`] | `web::blending` | [`exercises::blending`] (8.1), [`exercises::skeleton`] (6.3) |
//! | `09-skinning`: skinning (LBS, DQS, automatic weights) | [`skinning`] | [`figures::skinning`] | `web::skinning` (bench: `web::bench_skinning`) | [`exercises::skinning`] (9.x) |
//! | `10-blend-shapes`: blend shapes | [`blend_shapes`] | [`figures::blend_shapes`] | `web::blend_shapes` | [`exercises::blend_shapes`] (10.x) |
//! | `11-particles`: particles | [`particles`] (integrators, time of impact, emitters) | [`figures::particles`] | `web::particles` | [`exercises::particles`] (11.x) |
//! | `12-boids`: boids | [`boids`] (rules, force laws, grid) | [`figures::boids`] | `web::boids` (bench: `web::bench_boids`) | [`exercises::boids`] (12.x) |
//! | `13-cloth`: cloth | [`cloth`] (mass-spring, XPBD, collisions; uses [`particles`]' step) | [`figures::cloth`] | `web::cloth` (bench: `web::bench_cloth`) | [`exercises::cloth`] (13.x) |
//! | `14-rigid-bodies`: rigid bodies | [`rigid_body`] (inertia tensors, orientation and angular-velocity steps, impulses, contacts by sequential impulses) | [`figures::rigid_body`] (the throw, quaternion drift, the tennis racket, the impulse at a contact, the stack and dominoes) | `web::rigid_body` (bench: `web::bench_rigid_body`) | [`exercises::rigid_body`] (14.x) |
//! | `15-fluids`: fluids | [`fluid`] (kernels, SPH and PBF in 2D and 3D on the boids' grid, the particles' collisions) | [`figures::fluid`] (the kernels, the density of a dragged particle, SPH beside PBF on one dam break, a 3D splash on the CPU or the GPU grid and its step-time sweep) | `web::fluid` | [`exercises::fluid`] (15.x) |
//!
//! Shared by every lesson: [`draw`] (the draw list: meshes, lines, points, arrows, labels, the
//! palette), [`texture`] (textured quads, sprites and atlases in the draw list), [`order`]
//! (orderings by a float key through one sort),
//! [`exercises::run`] with `web::sandbox` (figures run student code in a separate wasm
//! instance, so a panic there cannot stop the page), `render/` (wgpu, wasm only).
//! The crate builds four wasm modules (`scripts/build`): the *figures module* (every binding but
//! the grader's, the CPU bench kernels' and the glTF importer's, and the renderer); with the
//! feature `course-module`, the *course module* (the cores, the exercises, `web::sandbox`'s
//! `runExercise` and `web::course`: the page's grader and the quizzes' answers; no renderer);
//! with the feature `bench-module`, the *bench module* (the bench page's CPU kernels,
//! `web::bench*` but `web::bench_gpu`, and the cores they time; no renderer); and with the
//! feature `gltf-module`, the *glTF module* (`web::gltf_module`: [`gltf_import::import`], its
//! result handed to the figures module as bytes by [`gltf_import::wire`]). Student code runs only
//! in the course module.
//! GPU paths (lessons 09, 11, 12, 15): skinning in the vertex shader (`render/skin.rs`, both
//! backends) and compute shaders for particles and boids (`render/compute.rs`, WebGPU only) and
//! for the fluid's SPH and PBF steps (`render/fluid.rs`) on a uniform grid built on the GPU
//! (`render/grid.rs`), with their logic (packing, grid layouts, caps, the statistics compared
//! with the CPU) in [`figures::gpu`].
//!
//! ## Conventions, stated once
//! - Right-handed coordinates, **Y up**, the camera looks down −Z in view space.
//! - Column vectors: a point transforms as `p' = M · p`, so `A · B` applies `B` first, then `A`.
//!   A world matrix is `world = parent_world · local`.
//! - Homogeneous coordinates: a point has `w = 1`, a direction (vector) has `w = 0`.
//! - Quaternions use glam's storage order `(x, y, z, w)`; `w` is the scalar part.
//! - Units: seconds, radians, metres. Names carry units where they could be mistaken
//!   (`time_sec`, `angle_rad`); an interpolation parameter `t` is in `[0, 1]`.
//! - Depth range of projection matrices is `[0, 1]` (WebGPU / wgpu), not OpenGL's `[-1, 1]`.
//! - Joint hierarchies are flat arrays of parent indices in depth-first order: the root has
//!   parent `-1` and every other joint's parent comes before it (`parents[i] < i`).

pub mod blend_shapes;
pub mod boids;
pub mod camera;
pub mod cloth;
pub mod curves;
pub mod draw;
pub mod exercises;
pub mod expressive;
pub mod figures;
pub mod fixtures;
pub mod fluid;
pub mod gltf_import;
pub mod ik;
pub mod mesh;
pub mod noise;
pub mod order;
pub mod particles;
pub mod raster;
pub mod rigid;
pub mod rigid_body;
pub mod rotation;
pub mod skeleton;
pub mod skinning;
pub mod terrain;
pub mod texture;
pub mod transform;

#[cfg(all(
    target_arch = "wasm32",
    not(any(
        feature = "course-module",
        feature = "bench-module",
        feature = "gltf-module"
    ))
))]
pub mod render;
#[cfg(target_arch = "wasm32")]
pub mod web;

/// `.valid("what was expected")` on a `Result` whose inputs are built into the course (a rig, a
/// clip, a preset, a validated setting): the value, else a panic naming what was expected and the
/// error's message. `expect` would print the error with `Debug`; this prints its `Display` (the
/// message the pages show), so the error types' derived `Debug` stays out of the wasm.
pub(crate) trait Valid<T> {
    fn valid(self, what: &str) -> T;
}

impl<T, E: core::fmt::Display> Valid<T> for Result<T, E> {
    #[track_caller]
    fn valid(self, what: &str) -> T {
        match self {
            Ok(value) => value,
            Err(error) => invalid(what, &error),
        }
    }
}

/// [`Valid::valid`]'s panic, out of line: one copy of the formatting for every caller.
#[cold]
#[inline(never)]
#[track_caller]
fn invalid(what: &str, error: &dyn core::fmt::Display) -> ! {
    panic!("{what}: {error}")
}
