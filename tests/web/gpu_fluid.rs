//! Browser-only test of the GPU fluid (WebGPU): SPH and PBF stepped by compute shaders on the
//! GPU grid against the CPU core, from the same start, compared statistically after k steps
//! (the GPU sums in another order, so particles differ one by one; the density error, kinetic
//! energy and mean speed must not). On WebGL2 there is no compute: asking for it is a clear
//! error, not a panic.
#![cfg(target_arch = "wasm32")]

use glam::Vec3;
use inbetween::figures::gpu::MAX_GPU_FLUID_PARTICLES;
use inbetween::fluid::{Fluid, FluidParams, Method, Scene, Stats};
use inbetween::particles::Sphere;
use inbetween::render::FluidCompute;
use wasm_bindgen_test::*;

/// A fluid of about `count` particles with `h` at 2 spacings (3D) or 2.7 (2D), a sphere
/// obstacle where the water falls or flows (outside the water at the start): in the drop's path
/// above the pool, or in the dam break's way.
fn start(params: FluidParams, scene: Scene, count: usize) -> Fluid {
    let mut params = params;
    let spacings = if params.dim == inbetween::fluid::Dim::Two {
        2.7
    } else {
        2.0
    };
    params.h = spacings * inbetween::fluid::spacing_for(params.dim, scene, count);
    let mut f = Fluid::new(params, scene, count, 3).unwrap();
    let size = inbetween::fluid::box_size(f.params.dim);
    let (center, radius) = match scene {
        Scene::Drop => (Vec3::new(0.8, 0.45, 0.5 * size.z), 0.08),
        _ => (Vec3::new(0.9, 0.15, 0.5 * size.z), 0.12),
    };
    f.set_obstacle(Some(Sphere { center, radius })).unwrap();
    f
}

fn mean_speed(v: &[Vec3]) -> f32 {
    v.iter().map(|v| v.length()).sum::<f32>() / v.len().max(1) as f32
}

fn close(what: &str, cpu: f32, gpu: f32, rel: f32, abs: f32) {
    assert!(
        (cpu - gpu).abs() <= rel * cpu.abs().max(gpu.abs()) + abs,
        "{what}: CPU {cpu}, GPU {gpu}"
    );
}

/// Steps `fluid` `steps` times on the CPU and on the GPU from the same start and compares:
/// mean density error within 0.005 (a share of ρ₀), largest within 0.02, kinetic energy and
/// mean speed within 5 %. The fluid must have moved (a mean speed over 0.3 m/s), so that agreeing is
/// not agreeing on the start.
async fn compare(gpu: &inbetween::render::Gpu, what: &str, fluid: Fluid, steps: usize) {
    let mut cpu = fluid.clone();
    let mut on_gpu = FluidCompute::new(gpu, &fluid).unwrap();
    for _ in 0..steps {
        cpu.step();
    }
    // In a few submissions, as a page queues them frame by frame.
    for _ in 0..steps / 8 {
        on_gpu.step(gpu, 8);
    }
    on_gpu.step(gpu, steps % 8);
    assert!(cpu.exploded().is_none(), "{what}: {:?}", cpu.exploded());
    assert!((on_gpu.time() - cpu.time).abs() < 1e-4, "{what}: clocks");
    let c: Stats = cpu.stats();
    let (p, v, rho) = on_gpu.read_back(gpu).await.unwrap();
    let mut g = fluid.clone();
    (g.positions, g.velocities, g.densities) = (p, v, rho);
    let g_stats = g.stats();
    let (cs, gs) = (mean_speed(&cpu.velocities), mean_speed(&g.velocities));
    web_sys::console::log_1(
        &format!("{what}: CPU {c:?} mean speed {cs}\nGPU {g_stats:?} mean speed {gs}").into(),
    );
    assert!(cs > 0.3, "{what}: the CPU fluid barely moved ({cs} m/s)");
    close(
        &format!("{what}: mean density error"),
        c.density_error_mean,
        g_stats.density_error_mean,
        0.0,
        0.005,
    );
    close(
        &format!("{what}: largest density error"),
        c.density_error_max,
        g_stats.density_error_max,
        0.0,
        0.02,
    );
    close(
        &format!("{what}: kinetic energy (J)"),
        c.kinetic,
        g_stats.kinetic,
        0.05,
        0.0,
    );
    close(&format!("{what}: mean speed (m/s)"), cs, gs, 0.05, 0.0);
    // Every particle inside the box and outside the obstacle (to float noise).
    let size = inbetween::fluid::box_size(g.params.dim);
    let s = g.obstacle.unwrap();
    for (i, x) in g.positions.iter().enumerate() {
        assert!(
            x.cmpge(Vec3::splat(-1e-4)).all() && x.cmple(size + 1e-4).all(),
            "{what}: particle {i} at {x} left the box"
        );
        let mut q = *x - s.center;
        if g.params.dim == inbetween::fluid::Dim::Two {
            q.z = 0.0;
        }
        assert!(
            q.length() > s.radius - 1e-3,
            "{what}: particle {i} at {x} in the obstacle"
        );
    }
}

#[wasm_bindgen_test]
async fn the_gpu_fluid_matches_the_cpu_statistically() {
    let gpu = super::gpu().await;
    let sph = start(FluidParams::default_3d(Method::Sph), Scene::DamBreak, 2000);
    if !gpu.compute {
        let e = FluidCompute::new(&gpu, &sph).err().unwrap();
        assert!(e.contains("needs WebGPU"), "{e}");
        return;
    }
    // SPH, Tait, Δt = 1/1200 s: 0.12 s of the dam break's fall around the obstacle.
    compare(&gpu, "SPH 3D", sph, 144).await;
    // SPH with the ideal gas in 2D.
    let mut params = FluidParams::default_2d(Method::Sph);
    params.eos = inbetween::fluid::Eos::IdealGas;
    params.stiffness = 100.0;
    compare(
        &gpu,
        "SPH 2D ideal gas",
        start(params, Scene::DamBreak, 1500),
        144,
    )
    .await;
    // PBF, 4 Jacobi iterations with s_corr, XSPH and vorticity confinement: the drop's fall
    // into the pool, 0.25 s.
    let mut params = FluidParams::default_3d(Method::Pbf);
    params.vorticity = 0.2;
    compare(&gpu, "PBF 3D", start(params, Scene::Drop, 2000), 60).await;
    compare(
        &gpu,
        "PBF 2D",
        start(FluidParams::default_2d(Method::Pbf), Scene::DamBreak, 1500),
        60,
    )
    .await;
}

/// The cap: a fluid over [`MAX_GPU_FLUID_PARTICLES`] is refused with a message naming it (the
/// fluid is never uploaded).
#[wasm_bindgen_test]
async fn the_gpu_fluid_refuses_more_than_its_cap() {
    let gpu = super::gpu().await;
    if !gpu.compute {
        return; // the error for WebGL2 is checked above
    }
    let mut params = FluidParams::default_3d(Method::Sph);
    let n = MAX_GPU_FLUID_PARTICLES + 50_000;
    params.h = 2.0 * inbetween::fluid::spacing_for(params.dim, Scene::Pool, n);
    let big = Fluid::with_cap(params, Scene::Pool, n, 1, 2 * n).unwrap();
    assert!(big.len() > MAX_GPU_FLUID_PARTICLES, "{}", big.len());
    let e = FluidCompute::new(&gpu, &big).err().unwrap();
    assert!(e.contains("1048576"), "{e}");
}

/// The readback of the fastest particle the GPU keeps after each step, waiting for it (a page
/// asks on later frames instead).
async fn fastest(gpu: &inbetween::render::Gpu, fluid: &mut FluidCompute) -> (f32, f32) {
    for _ in 0..1000 {
        if let Some(read) = fluid.fastest(gpu) {
            return read.unwrap();
        }
        fluid.finish(gpu).await.unwrap();
    }
    panic!("the fastest particle's speed never came back");
}

/// The GPU's explosion verdict: the speed it reads back after a batch of steps is the fastest
/// particle's (at least the last step's, whose velocities are read back whole), and a step past
/// the CFL limit reads back a speed past the CPU's limit within the time the CPU's step
/// explodes in (the 2D dam break at 1/120 s, as the CPU test in tests/fluid.rs).
#[wasm_bindgen_test]
async fn the_gpu_fluid_reads_back_its_fastest_particle_and_explodes_as_the_cpu_does() {
    use inbetween::fluid::{explosion_speed, explosion_verdict};
    let gpu = super::gpu().await;
    if !gpu.compute {
        return; // the error for WebGL2 is checked above
    }
    let calm = start(FluidParams::default_2d(Method::Pbf), Scene::DamBreak, 1500);
    let mut on_gpu = FluidCompute::new(&gpu, &calm).unwrap();
    on_gpu.step(&gpu, 30);
    let (time, speed) = fastest(&gpu, &mut on_gpu).await;
    assert!(
        (time - on_gpu.time()).abs() < 1e-5,
        "{time} {}",
        on_gpu.time()
    );
    let (_, v, _) = on_gpu.read_back(&gpu).await.unwrap();
    let last = v.iter().map(|v| v.length()).fold(0.0f32, f32::max);
    assert!(last > 0.3, "the water barely moved ({last} m/s)");
    assert!(
        speed >= 0.999 * last && speed < 2.0 * last,
        "read back {speed} m/s, fastest of the last step {last} m/s"
    );
    assert_eq!(explosion_verdict(&calm.params, speed), None);
    // Once taken, a readback comes once; the next steps get their own.
    assert!(on_gpu.fastest(&gpu).is_none());

    let mut params = FluidParams::default_2d(Method::Sph);
    params.dt = 1.0 / 120.0;
    let wild = Fluid::new(params, Scene::DamBreak, 2000, 7).unwrap();
    let mut cpu = wild.clone();
    while cpu.exploded().is_none() && cpu.time < 2.0 {
        cpu.step();
    }
    let (cpu_t, _) = cpu.exploded().expect("the CPU's step explodes");
    let limit = explosion_speed(&wild.params);
    let mut on_gpu = FluidCompute::new(&gpu, &wild).unwrap();
    let mut verdict = None;
    while verdict.is_none() && on_gpu.time() < 2.0 {
        on_gpu.step(&gpu, 8);
        let (t, speed) = fastest(&gpu, &mut on_gpu).await;
        verdict = explosion_verdict(&wild.params, speed).map(|why| (t, speed, why));
    }
    let (t, speed, why) = verdict.expect("the GPU's step explodes too");
    web_sys::console::log_1(
        &format!("GPU exploded by t = {t} s ({speed} m/s, limit {limit}); CPU at {cpu_t} s: {why}")
            .into(),
    );
    assert!(speed > limit || !speed.is_finite());
    // The GPU sums in another order: the same blow-up, not the same step.
    assert!((t - cpu_t).abs() < 0.5, "GPU by {t} s, CPU at {cpu_t} s");
}
