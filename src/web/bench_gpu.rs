//! Browser bench kernels for the GPU compute paths (WebGPU only; `www/bench.js` runs them when
//! the browser offers a WebGPU adapter): the time of one GPU step of the particle system and of
//! the flock. Each call makes its own device on `canvas`; building the buffers and pipelines and a
//! first step are not timed; then `steps` steps are queued and the time runs until the GPU has
//! finished them (a read-back of a few bytes waits for it).

#[cfg(doc)]
use crate::boids::benchmark_flock;
use crate::boids::{benchmark_params, seeded_start, Search, BENCHMARK_SEED};
use crate::figures::gpu::{check_gpu_boids, MAX_GPU_PARTICLES};
use crate::particles::{Emitter, Sphere, Surfaces};
use crate::render::{BackendChoice, BoidsCompute, Gpu, ParticlesCompute};
use glam::Vec3;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

async fn webgpu(canvas: HtmlCanvasElement) -> Result<Gpu, JsError> {
    Gpu::new(canvas, BackendChoice::WebGpu)
        .await
        .map_err(|e| JsError::new(&e))
}

fn check_steps(steps: usize) -> Result<(), JsError> {
    if (1..=1000).contains(&steps) {
        Ok(())
    } else {
        Err(JsError::new(&format!(
            "steps must lie in [1, 1000], got {steps}"
        )))
    }
}

/// Milliseconds per GPU step of `count ∈ [1, 2^20]` particles, all alive (a fountain burst with
/// lifetimes longer than the run), falling and bouncing on the floor and one sphere.
/// Caps (the work grows with both): `steps` in [1, 1000] and `count × steps` at most 2²⁸.
#[wasm_bindgen(js_name = benchGpuParticles)]
pub async fn bench_gpu_particles(canvas: JsValue, count: f64, steps: f64) -> Result<f64, JsError> {
    let canvas = super::canvas("canvas", canvas)?;
    let count = super::whole("count", count)?;
    let steps = super::whole("steps", steps)?;
    super::check_work("count", count as u64, steps, 1 << 28)?;
    check_steps(steps)?;
    if !(1..=MAX_GPU_PARTICLES).contains(&count) {
        return Err(JsError::new(&format!(
            "count must lie in [1, {MAX_GPU_PARTICLES}], got {count}"
        )));
    }
    let gpu = webgpu(canvas).await?;
    let mut system = ParticlesCompute::new(&gpu, count, 3).map_err(|e| JsError::new(&e))?;
    let mut emitter = Emitter::fountain(Vec3::ZERO);
    emitter.rate_per_sec = 0.0;
    emitter.lifetime_sec = (1e4, 1e4);
    let mut emitters = [emitter];
    let surfaces = Surfaces {
        spheres: vec![Sphere {
            center: Vec3::new(0.3, 1.0, 0.0),
            radius: 0.5,
        }],
        ..Default::default()
    };
    let dt = 1.0 / 60.0;
    system.burst(0, count);
    let err = |e: String| JsError::new(&e);
    system
        .step(&gpu, &mut emitters, &surfaces, dt)
        .map_err(err)?;
    system.finish(&gpu).await.map_err(err)?;
    let start = now_ms();
    for _ in 0..steps {
        system
            .step(&gpu, &mut emitters, &surfaces, dt)
            .map_err(err)?;
    }
    system.finish(&gpu).await.map_err(err)?;
    Ok((now_ms() - start) / steps as f64)
}

/// Milliseconds per GPU step of the benchmark flock ([`benchmark_flock`]'s start at any count,
/// as the CPU kernel `benchBoids`: the box grows with the count), neighbours by `search`:
/// "naive" tests every pair (tiled; `boids ∈ [1, 65536]`, `boids × steps` at most 2²⁴),
/// "grid" builds the GPU grid each step (`boids ∈ [1, 2²⁰]`, `boids × steps` at most 2²⁸).
/// `steps` in [1, 1000].
#[wasm_bindgen(js_name = benchGpuBoids)]
pub async fn bench_gpu_boids(
    canvas: JsValue,
    boids: f64,
    steps: f64,
    search: JsValue,
) -> Result<f64, JsError> {
    let canvas = super::canvas("canvas", canvas)?;
    let search = super::string("search", &search)?;
    let search = crate::figures::boids::parse_search(&search).map_err(|e| JsError::new(&e))?;
    let boids = super::whole("boids", boids)?;
    let steps = super::whole("steps", steps)?;
    let work = match search {
        Search::Naive => 1 << 24,
        Search::Grid => 1 << 28,
    };
    super::check_work("boids", boids as u64, steps, work)?;
    check_steps(steps)?;
    check_gpu_boids(boids, search).map_err(|e| JsError::new(&e))?;
    let gpu = webgpu(canvas).await?;
    let params = benchmark_params(boids);
    let (positions, velocities) = seeded_start(boids, &params, BENCHMARK_SEED);
    let err = |e: String| JsError::new(&e);
    let mut on_gpu = BoidsCompute::new(&gpu, &positions, &velocities, 0.0).map_err(err)?;
    let dt = 1.0 / 60.0;
    on_gpu.step(&gpu, &params, dt, search).map_err(err)?;
    on_gpu.finish(&gpu).await.map_err(err)?;
    let start = now_ms();
    for _ in 0..steps {
        on_gpu.step(&gpu, &params, dt, search).map_err(err)?;
    }
    on_gpu.finish(&gpu).await.map_err(err)?;
    Ok((now_ms() - start) / steps as f64)
}

/// Milliseconds per GPU step of a 3D dam break of `count ∈ [1000, 2^20]` particles at rest
/// (`method` "sph" or "pbf" with 4 iterations; `h` at 2 spacings, about 33 neighbours; SPH's time
/// step for a speed of sound of 20 m/s, as the CPU's [`crate::fluid::benchmark_fluid`], which
/// starts after 0.1 s of fall: here the water is let go, since the CPU cannot run a million
/// particles first). The GPU grid is built every step. `steps` in [1, 1000], `count × steps` at
/// most 2²⁶.
#[wasm_bindgen(js_name = benchGpuFluid)]
pub async fn bench_gpu_fluid(
    canvas: JsValue,
    method: JsValue,
    count: f64,
    steps: f64,
) -> Result<f64, JsError> {
    use crate::figures::gpu::MAX_GPU_FLUID_PARTICLES;
    use crate::fluid::{spacing_for, Dim, Fluid, FluidParams, Method, Scene};
    let canvas = super::canvas("canvas", canvas)?;
    let method = match super::string("method", &method)?.as_str() {
        "sph" => Method::Sph,
        "pbf" => Method::Pbf,
        other => {
            return Err(JsError::new(&format!(
                "method must be \"sph\" or \"pbf\", got {other:?}"
            )))
        }
    };
    let count = super::whole_in("count", count, 1000, MAX_GPU_FLUID_PARTICLES)?;
    let steps = super::whole("steps", steps)?;
    super::check_work("count", count as u64, steps, 1 << 26)?;
    check_steps(steps)?;
    let err = |e: String| JsError::new(&e);
    let mut params = FluidParams::default_3d(method);
    params.h = 2.0 * spacing_for(Dim::Three, Scene::DamBreak, count);
    if method == Method::Sph {
        params.dt = 0.4 * params.h / 20.0;
    }
    let fluid =
        Fluid::with_cap(params, Scene::DamBreak, count, 1, MAX_GPU_FLUID_PARTICLES).map_err(err)?;
    let gpu = webgpu(canvas).await?;
    let mut on_gpu = crate::render::FluidCompute::new(&gpu, &fluid).map_err(err)?;
    on_gpu.step(&gpu, 1);
    on_gpu.finish(&gpu).await.map_err(err)?;
    let start = now_ms();
    on_gpu.step(&gpu, steps);
    on_gpu.finish(&gpu).await.map_err(err)?;
    Ok((now_ms() - start) / steps as f64)
}
