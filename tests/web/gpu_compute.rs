//! Browser-only test of GPU compute (WebGPU): the particle system and the flock stepped by
//! compute shaders against the CPU cores, from the same start, compared statistically (the GPU
//! draws other random numbers and sums in another order, so particles and boids differ one by
//! one; their statistics must not), the flock with every pair tested and on the GPU grid; the
//! GPU grid's cells against the CPU grid's, exactly. On WebGL2 there is no compute: the test
//! checks that asking for it is a clear error, not a panic.
#![cfg(target_arch = "wasm32")]

use glam::Vec3;
use inbetween::boids::grid::Grid;
use inbetween::boids::{
    benchmark_flock, benchmark_params, seeded_start, BoidParams, Flock, Search, BENCHMARK_SEED,
};
use inbetween::figures::gpu::{flock_stats, particle_stats, GridLayout, MAX_GPU_BOIDS};
use inbetween::particles::{Emitter, ParticleSystem, Sphere, Surfaces};
use inbetween::render::{BackendChoice, BoidsCompute, Gpu, GpuGrid, ParticlesCompute};
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
    let (plain, busy) = compared_params();
    // No minimum speed: the flock slows into a hovering swarm (the other two keep their speed).
    let hovering = BoidParams {
        min_speed: 0.0,
        ..plain.clone()
    };
    for params in [&plain, &hovering, &busy] {
        compare_flocks(&gpu, params, Search::Naive).await;
    }
    // Bad input at the boundary: a clear error.
    let mut on_gpu = BoidsCompute::new(&gpu, &[Vec3::ZERO], &[Vec3::X], 0.0).unwrap();
    assert!(on_gpu
        .step(&gpu, &BoidParams::default(), f32::NAN, Search::Naive)
        .unwrap_err()
        .contains("dt"));
}

/// The flock on the GPU grid against the CPU's, as the all-pairs kernel is compared above: the
/// grid must find the same neighbours, so the statistics must agree as well.
#[wasm_bindgen_test]
async fn gpu_boids_on_the_grid_match_the_cpu_statistically() {
    let gpu = gpu().await;
    if !gpu.compute {
        return; // the error for WebGL2 is checked above
    }
    let (plain, busy) = compared_params();
    for params in [&plain, &busy] {
        compare_flocks(&gpu, params, Search::Grid).await;
    }
    // Every pair takes at most MAX_GPU_BOIDS boids; the grid more: a clear error, not a panic.
    // Three grid steps of that flock from the same state move every boid as the CPU's grid steps
    // do (the sums' order differs, so to within float noise, not to the bit).
    let (params, mut cpu) = benchmark_flock(MAX_GPU_BOIDS + 1).unwrap();
    let mut big = BoidsCompute::new(&gpu, &cpu.positions, &cpu.velocities, 0.0).unwrap();
    let e = big
        .step(&gpu, &params, 1.0 / 60.0, Search::Naive)
        .unwrap_err();
    assert!(e.contains("65536") && e.contains("every pair"), "{e}");
    for _ in 0..3 {
        big.step(&gpu, &params, 1.0 / 60.0, Search::Grid).unwrap();
        cpu.step(&params, Search::Grid, 1.0 / 60.0);
    }
    let (p, _) = big.read_back(&gpu).await.unwrap();
    let off = p
        .iter()
        .zip(&cpu.positions)
        .filter(|(g, c)| !(g.distance(**c) < 1e-4))
        .count();
    assert!(
        off <= p.len() / 1000,
        "{off} of {} boids off by 0.1 mm or more",
        p.len()
    );
    // The cap itself: a million boids (2²⁰ is the cap) step on the grid, every one moving at
    // most the top speed (the leader and predator are off).
    let n = 1_000_000;
    let params = benchmark_params(n);
    let (p0, v0) = seeded_start(n, &params, BENCHMARK_SEED);
    let mut million = BoidsCompute::new(&gpu, &p0, &v0, 0.0).unwrap();
    million
        .step(&gpu, &params, 1.0 / 60.0, Search::Grid)
        .unwrap();
    let (p, _) = million.read_back(&gpu).await.unwrap();
    let reach = params.max_speed / 60.0 * 1.001 + 1e-5;
    let moved = p
        .iter()
        .zip(&p0)
        .filter(|(a, b)| a.distance(**b) > 0.0 && a.distance(**b) <= reach)
        .count();
    assert_eq!(moved, n, "boids that moved, by at most {reach} m");
}

/// The GPU grid sorts points into the same cells as the CPU grid (`Grid`, counting sort), given
/// the CPU grid's layout: every cell's start and its set of points agree exactly (within a
/// cell the GPU's order is its atomics', the CPU's increasing index). Points outside the box
/// (clamped into the border cells), a NaN position, several cells' worth of scan blocks (more
/// than 512 cells, so the block sums are scanned too), and empty cells.
#[wasm_bindgen_test]
async fn the_gpu_grid_has_the_cpu_grids_cells() {
    let gpu = gpu().await;
    if !gpu.compute {
        let points = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: 16,
            usage: wgpu::BufferUsages::STORAGE,
            mapped_at_creation: false,
        });
        let e = GpuGrid::new(
            &gpu,
            &[&points],
            1,
            1,
            GridLayout::cubic(Vec3::ZERO, Vec3::ONE, 1.0).unwrap(),
        )
        .err()
        .unwrap();
        assert!(e.contains("needs WebGPU"), "{e}");
        return;
    }
    let params = BoidParams {
        bounds: Vec3::new(4.0, 2.0, 3.0),
        ..Default::default()
    };
    for (count, radius) in [(3000, 0.5), (3000, 0.02), (257, 1.3), (1, 2.0)] {
        let flock = Flock::new(count, &params, 9).unwrap();
        let mut positions = flock.positions.clone();
        if count > 2 {
            positions[0] = Vec3::new(9.0, -7.0, 0.5); // outside the box
            positions[1] = Vec3::new(f32::NAN, 0.0, 0.0);
        }
        let mut cpu = Grid::default();
        cpu.configure(-params.bounds, params.bounds, radius);
        cpu.rebuild(&positions);
        let layout = GridLayout::of_cpu_grid(&cpu);
        assert_eq!(layout.cells(), cpu.cell_count());
        if count == 3000 {
            assert!(layout.cells() > 2 * 512, "{} cells", layout.cells());
        }
        // Points as the boids' state lays them out: position, then velocity (stride 2).
        let data: Vec<[f32; 8]> = positions
            .iter()
            .map(|p| [p.x, p.y, p.z, 0.0, 9.0, 9.0, 9.0, 0.0])
            .collect();
        let points = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: (count * 32) as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        gpu.queue
            .write_buffer(&points, 0, bytemuck::cast_slice(&data));
        let grid = GpuGrid::new(&gpu, &[&points], count, 2, layout).unwrap();
        // Twice: the second build must clear the first one's counts.
        grid.build(&gpu, 0);
        grid.build(&gpu, 0);
        let (starts, mut sorted) = grid.read_back(&gpu).await.unwrap();
        // The first cell whose start differs, not the whole array (up to 5 · 10⁵ cells).
        let cpu_starts = cpu.cell_starts();
        assert_eq!(starts.len(), cpu_starts.len());
        if let Some(c) = (0..starts.len()).find(|&c| starts[c] != cpu_starts[c]) {
            panic!(
                "{count} points, {} cells: cell {c} starts at {} on the GPU, {} on the CPU",
                starts.len() - 1,
                starts[c],
                cpu_starts[c]
            );
        }
        for c in 0..layout.cells() {
            let run = starts[c] as usize..starts[c + 1] as usize;
            sorted[run.clone()].sort_unstable();
            assert_eq!(
                sorted[run.clone()],
                cpu.sorted()[run],
                "{count} points: cell {c}'s points"
            );
        }
        for (i, p) in positions.iter().enumerate() {
            if p.is_finite() {
                assert_eq!(layout.cell_of(*p), cpu.cell_of_point(*p), "point {i}");
            }
        }
    }
}

/// The flocks both GPU searches are compared on: a plain one around an obstacle, and one with
/// every rule at once (a force law, a narrower field of view, a leader and a predator).
fn compared_params() -> (BoidParams, BoidParams) {
    let plain = BoidParams {
        obstacles: vec![Sphere {
            center: Vec3::ZERO,
            radius: 0.8,
        }],
        bounds: Vec3::new(3.0, 1.5, 3.0),
        ..Default::default()
    };
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
    (plain, busy)
}

async fn compare_flocks(gpu: &Gpu, params: &BoidParams, search: Search) {
    let gpu = gpu;
    let params = params.clone();
    let mut cpu = Flock::new(300, &params, 5).unwrap();
    let start = flock_stats(&cpu.positions, &cpu.velocities);
    let mut on_gpu = BoidsCompute::new(gpu, &cpu.positions, &cpu.velocities, 0.0).unwrap();
    let dt = 1.0 / 30.0;
    for _ in 0..90 {
        cpu.step(&params, Search::Naive, dt);
        on_gpu.step(gpu, &params, dt, search).unwrap();
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
    web_sys::console::log_1(&format!("{search:?}: start {start:?}\nCPU {c:?}\nGPU {g:?}").into());
    close("mean speed (m/s)", c.mean_speed, g.mean_speed, 0.1, 0.05);
    // The box is a spring, not a wall (`bounds_weight` times the distance outside, in
    // src/boids and boids.wgsl alike): on the CPU too boids overshoot it, some by more than a
    // metre (tests/figures_boids.rs, the_box_holds_the_flock_loosely), so no step keeps every
    // boid inside. Both keep every boid within 2.5 m of it, and overshoot it alike.
    let outside = |ps: &[Vec3]| {
        ps.iter()
            .map(|q| (q.abs() - params.bounds).max(Vec3::ZERO).length())
            .fold(0.0f32, f32::max)
    };
    let (c_out, g_out) = (outside(&cpu.positions), outside(&p));
    assert!(
        c_out < 2.5 && g_out < 2.5,
        "{search:?}: farthest outside the box: CPU {c_out} m, GPU {g_out} m"
    );
    close("farthest outside the box (m)", c_out, g_out, 0.5, 0.3);
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
                .step(g, &BoidParams::default(), 1.0 / 60.0, Search::Grid)
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
