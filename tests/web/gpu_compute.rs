//! Browser-only test of GPU compute (WebGPU): the particle system and the flock stepped by
//! compute shaders against the CPU cores, from the same start, compared statistically (the GPU
//! draws other random numbers and sums in another order, so particles and boids differ one by
//! one; their statistics must not). On WebGL2 there is no compute: the test checks that asking
//! for it is a clear error, not a panic.
#![cfg(target_arch = "wasm32")]

use glam::Vec3;
use inbetween::boids::{BoidParams, Flock, Search};
use inbetween::figures::gpu::{flock_stats, particle_stats};
use inbetween::particles::{Emitter, ParticleSystem, Sphere, Surfaces};
use inbetween::render::{BackendChoice, BoidsCompute, Gpu, ParticlesCompute};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;

async fn gpu() -> Gpu {
    let document = web_sys::window().unwrap().document().unwrap();
    let canvas: web_sys::HtmlCanvasElement = document
        .create_element("canvas")
        .unwrap()
        .dyn_into()
        .unwrap();
    canvas.set_width(16);
    canvas.set_height(16);
    document.body().unwrap().append_child(&canvas).unwrap();
    let gpu = Gpu::new(canvas, BackendChoice::Auto)
        .await
        .expect("an adapter (WebGPU or WebGL2)");
    if let Some(expected) = crate::EXPECTED_BACKEND {
        assert_eq!(gpu.backend_name, expected, "adapter: {}", gpu.adapter_name);
    }
    assert_eq!(gpu.compute, gpu.backend_name == "WebGPU");
    gpu
}

fn close(what: &str, cpu: f32, gpu: f32, rel: f32, abs: f32) {
    assert!(
        (cpu - gpu).abs() <= rel * cpu.abs().max(gpu.abs()) + abs,
        "{what}: CPU {cpu}, GPU {gpu}"
    );
}

#[wasm_bindgen_test]
async fn gpu_particles_match_the_cpu_statistically() {
    let gpu = gpu().await;
    if !gpu.compute {
        let e = ParticlesCompute::new(&gpu, 1000, 1).err().unwrap();
        assert!(e.contains("needs WebGPU"), "{e}");
        return;
    }
    let surfaces = Surfaces {
        spheres: vec![Sphere {
            center: Vec3::new(0.3, 0.8, 0.0),
            radius: 0.4,
        }],
        ..Default::default()
    };
    let fountain = Emitter::fountain(Vec3::ZERO);
    let dt = 1.0 / 60.0;
    let capacity = 2048; // ≥ rate × longest lifetime (200 × 3 = 600): the ring never laps
    let mut cpu = ParticleSystem::new(capacity, 11).unwrap();
    let mut cpu_emitters = [fountain];
    let mut on_gpu = ParticlesCompute::new(&gpu, capacity, 11).unwrap();
    let mut gpu_emitters = [fountain];
    // 3.3 s: particles have risen, hit the sphere and the floor, and the first ones have died.
    for _ in 0..200 {
        cpu.step(&mut cpu_emitters, &surfaces, dt);
        on_gpu.step(&gpu, &mut gpu_emitters, &surfaces, dt).unwrap();
    }
    let n = cpu.len();
    let c = particle_stats(&cpu.positions[..n], &cpu.velocities[..n], &vec![true; n]);
    let (p, v, alive) = on_gpu.read_back(&gpu).await.unwrap();
    let g = particle_stats(&p, &v, &alive);
    // Same spawn counts; deaths depend on random lifetimes in [2, 3] s.
    assert!(c.alive > 300, "CPU alive {}", c.alive);
    close("alive", c.alive as f32, g.alive as f32, 0.08, 5.0);
    close("mean speed (m/s)", c.mean_speed, g.mean_speed, 0.08, 0.05);
    close("mean height (m)", c.mean_height, g.mean_height, 0.1, 0.05);
    // Nobody below the floor (exact time of impact, on both).
    assert!(c.lowest >= -1e-4 && g.lowest >= -1e-4, "{c:?} {g:?}");
    // A burst of the explosion emitter spawns exactly that many more next step.
    let mut boom = [fountain, Emitter::explosion(Vec3::new(0.0, 2.0, 0.0))];
    boom[0].rate_per_sec = 0.0;
    let before = g.alive;
    on_gpu.burst(1, 100);
    on_gpu.step(&gpu, &mut boom, &surfaces, 1e-4).unwrap();
    let (_, _, alive) = on_gpu.read_back(&gpu).await.unwrap();
    let after = alive.iter().filter(|a| **a).count();
    assert!(
        after >= before + 100 - 2 && after <= before + 100,
        "{before} then {after}"
    );
}

#[wasm_bindgen_test]
async fn gpu_boids_match_the_cpu_statistically() {
    let gpu = gpu().await;
    if !gpu.compute {
        let e = BoidsCompute::new(&gpu, &[Vec3::ZERO], &[Vec3::X], 0.0)
            .err()
            .unwrap();
        assert!(e.contains("needs WebGPU"), "{e}");
        return;
    }
    let plain = BoidParams {
        obstacles: vec![Sphere {
            center: Vec3::ZERO,
            radius: 0.8,
        }],
        bounds: Vec3::new(3.0, 1.5, 3.0),
        ..Default::default()
    };
    // Every rule at once: a force law, a narrower field of view, a leader and a predator.
    let busy = BoidParams {
        law: inbetween::boids::ForceLaw::Gaussian {
            a1: 1.0,
            a2: 2.0,
            k: 2.0,
            x0: 0.6,
        },
        fov_deg: 240.0,
        leader: Some(1.5),
        predator: Some((1.2, 3.0)),
        ..plain.clone()
    };
    // No minimum speed: the flock slows into a hovering swarm (the other two keep their speed).
    let hovering = BoidParams {
        min_speed: 0.0,
        ..plain.clone()
    };
    for params in [plain, hovering, busy] {
        compare_flocks(&gpu, &params).await;
    }
    // Bad input at the boundary: a clear error.
    let mut on_gpu = BoidsCompute::new(&gpu, &[Vec3::ZERO], &[Vec3::X], 0.0).unwrap();
    assert!(on_gpu
        .step(&gpu, &BoidParams::default(), f32::NAN)
        .unwrap_err()
        .contains("dt"));
}

async fn compare_flocks(gpu: &Gpu, params: &BoidParams) {
    let gpu = gpu;
    let params = params.clone();
    let mut cpu = Flock::new(300, &params, 5).unwrap();
    let start = flock_stats(&cpu.positions, &cpu.velocities);
    let mut on_gpu = BoidsCompute::new(gpu, &cpu.positions, &cpu.velocities, 0.0).unwrap();
    let dt = 1.0 / 30.0;
    for _ in 0..90 {
        cpu.step(&params, Search::Naive, dt);
        on_gpu.step(gpu, &params, dt).unwrap();
    }
    let c = flock_stats(&cpu.positions, &cpu.velocities);
    let (p, v) = on_gpu.read_back(gpu).await.unwrap();
    let g = flock_stats(&p, &v);
    // The flock changed (it aligns, or slows into a swarm), so agreeing is not agreeing on the
    // start.
    assert!(
        (c.mean_speed - start.mean_speed).abs() > 0.3
            || (c.polarisation - start.polarisation).abs() > 0.1,
        "start {start:?}, CPU after {c:?}"
    );
    web_sys::console::log_1(&format!("start {start:?}\nCPU {c:?}\nGPU {g:?}").into());
    close("mean speed (m/s)", c.mean_speed, g.mean_speed, 0.1, 0.05);
    close("polarisation", c.polarisation, g.polarisation, 0.0, 0.15);
    close(
        "mean nearest-neighbour distance (m)",
        c.mean_nearest_m,
        g.mean_nearest_m,
        0.15,
        0.02,
    );
}

/// Two figures of one page step their particles and their flocks with the page's kernels (each
/// compute shader compiled once per page), and both figures' systems run.
#[wasm_bindgen_test]
async fn two_figures_share_the_compute_kernels_and_both_run() {
    let figures = [gpu().await, gpu().await];
    if !figures[0].compute {
        return;
    }
    let surfaces = Surfaces::default();
    let mut emitters = [[Emitter::fountain(Vec3::ZERO)]; 2];
    let mut systems =
        [1, 2].map(|seed| ParticlesCompute::new(&figures[seed - 1], 512, seed as u32).unwrap());
    assert!(systems[0].shares_kernels(&systems[1]));
    let start = Flock::new(64, &BoidParams::default(), 3).unwrap();
    let mut flocks = figures
        .each_ref()
        .map(|g| BoidsCompute::new(g, &start.positions, &start.velocities, 0.0).unwrap());
    assert!(flocks[0].shares_kernels(&flocks[1]));
    for _ in 0..30 {
        for k in 0..2 {
            let g = &figures[k];
            systems[k]
                .step(g, &mut emitters[k], &surfaces, 1.0 / 60.0)
                .unwrap();
            flocks[k]
                .step(g, &BoidParams::default(), 1.0 / 60.0)
                .unwrap();
        }
    }
    for k in 0..2 {
        let (p, _, alive) = systems[k].read_back(&figures[k]).await.unwrap();
        // The fountain spawns 200 a second: about 100 in 0.5 s, risen off the ground.
        let risen = p
            .iter()
            .zip(&alive)
            .filter(|(p, a)| **a && p.y > 0.05)
            .count();
        assert!(risen > 50, "figure {k}: {risen} particles alive and risen");
        let (p, _) = flocks[k].read_back(&figures[k]).await.unwrap();
        let moved = p
            .iter()
            .zip(&start.positions)
            .filter(|(a, b)| a.distance(**b) > 0.01)
            .count();
        assert_eq!(moved, 64, "figure {k}: every boid moved");
    }
}
