//! The GPU paths' logic, natively (`src/figures/gpu.rs`): the palette the skinning shader gets,
//! mixed by the shader's formulas written in Rust, skins like the CPU cores; caps give errors;
//! the figures put GPU draws (not CPU meshes) in the frame when GPU skinning is on.

use glam::{Affine3A, Mat4, Vec3};
use inbetween::draw::{Frame, MeshId, SkinMeshId};
use inbetween::figures::gpu::{
    dqs_like_shader, draw_skinned_dqs, draw_skinned_lbs, gpu_skinnable, lbs_like_shader, pack_dqs,
    pack_lbs, MAX_GPU_JOINTS,
};
use inbetween::figures::skinning::HumanFigure;
use inbetween::rigid::DualQuat;
use inbetween::skinning::rigs::benchmark_input;
use inbetween::skinning::{dual_quat_palette, skin_dqs, skin_lbs};

fn max_error(a: &[Vec3], b: &[Vec3]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (*x - *y).length())
        .fold(0.0, f32::max)
}

#[test]
fn shader_formulas_on_the_packed_palette_match_the_cpu_skinning() {
    // 60 joints, 4 random influences per vertex, a real pose (the benchmark's input).
    let input = benchmark_input(2_000, 7);
    let n = input.positions.len();
    let (mut p, mut nn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    skin_lbs(
        &input.palette,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut p,
        &mut nn,
    )
    .unwrap();
    let rows: Vec<_> = pack_lbs(&input.palette).collect();
    let (gp, gn): (Vec<Vec3>, Vec<Vec3>) = (0..n)
        .map(|v| {
            lbs_like_shader(
                &rows,
                input.skin.joints()[v],
                input.skin.weights()[v],
                input.positions[v],
                input.normals[v],
            )
        })
        .unzip();
    assert!(max_error(&p, &gp) < 1e-4, "LBS positions");
    assert!(max_error(&nn, &gn) < 1e-4, "LBS normals");

    let mut dq = vec![DualQuat::IDENTITY; input.palette.len()];
    dual_quat_palette(&input.palette, &mut dq).unwrap();
    skin_dqs(
        &dq,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut p,
        &mut nn,
    )
    .unwrap();
    let rows: Vec<_> = pack_dqs(&dq).collect();
    let (gp, gn): (Vec<Vec3>, Vec<Vec3>) = (0..n)
        .map(|v| {
            dqs_like_shader(
                &rows,
                input.skin.joints()[v],
                input.skin.weights()[v],
                input.positions[v],
                input.normals[v],
            )
        })
        .unzip();
    assert!(max_error(&p, &gp) < 1e-4, "DQS positions");
    assert!(max_error(&nn, &gn) < 1e-4, "DQS normals");
}

#[test]
fn dqs_shader_formula_fixes_antipodal_quaternions() {
    // Joint 1 is joint 0's rotation with the quaternion negated: the same motion. Without the
    // sign fix a 50/50 blend would cancel; with it the vertex moves rigidly with both.
    let k = Affine3A::from_rotation_translation(
        glam::Quat::from_rotation_y(0.8),
        Vec3::new(0.1, 0.2, 0.3),
    );
    let mut dq = [DualQuat::IDENTITY; 2];
    dual_quat_palette(&[k, k], &mut dq).unwrap();
    dq[1].real = -dq[1].real;
    dq[1].dual = -dq[1].dual;
    let rows: Vec<_> = pack_dqs(&dq).collect();
    let p = Vec3::new(0.5, -0.2, 0.7);
    let (q, n) = dqs_like_shader(&rows, [0, 1, 0, 0], [0.5, 0.5, 0.0, 0.0], p, Vec3::X);
    assert!((q - k.transform_point3(p)).length() < 1e-5, "{q}");
    assert!((n - k.transform_vector3(Vec3::X)).length() < 1e-5, "{n}");
}

#[test]
fn palettes_over_the_cap_are_errors_and_draws_record_their_range() {
    let mut frame = Frame::default();
    let big = vec![Affine3A::IDENTITY; MAX_GPU_JOINTS + 1];
    let e = draw_skinned_lbs(&mut frame, SkinMeshId(0), Mat4::IDENTITY, None, &big).unwrap_err();
    assert!(e.contains("too many") && e.contains("128"), "{e}");
    assert!(frame.skinned.is_empty() && frame.skin_palette.is_empty());
    let small = vec![Affine3A::IDENTITY; 5];
    draw_skinned_lbs(&mut frame, SkinMeshId(0), Mat4::IDENTITY, None, &small).unwrap();
    draw_skinned_dqs(
        &mut frame,
        SkinMeshId(1),
        Mat4::IDENTITY,
        Some(Vec3::X),
        &[DualQuat::IDENTITY; 3],
    )
    .unwrap();
    assert_eq!(frame.skinned[0].joints, 0..5);
    assert_eq!(frame.skinned[1].joints, 5..8);
    assert!(frame.skinned[1].dqs && !frame.skinned[0].dqs);
    assert!(frame.skinned[0].vertex_colors && !frame.skinned[1].vertex_colors);
    // The identity packs to the identity rows (LBS) and the unit quaternion (DQS).
    assert_eq!(frame.skin_palette[0][0].to_array(), [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(frame.skin_palette[5][0].to_array(), [0.0, 0.0, 0.0, 1.0]);
    let before = frame.fingerprint();
    frame.skin_palette[1][0].w = 0.5;
    assert_ne!(
        before,
        frame.fingerprint(),
        "the palette is part of the fingerprint"
    );
    frame.clear();
    assert!(frame.skinned.is_empty() && frame.skin_palette.is_empty());
    assert!(gpu_skinnable(10, 10).is_ok());
    assert!(gpu_skinnable(11, 10).unwrap_err().contains("joint 10"));
    assert!(gpu_skinnable(3, 200).is_err());
}

#[test]
fn the_human_figure_draws_a_gpu_skinned_body_when_asked() {
    let mut figure = HumanFigure::new();
    figure.set_gpu(true);
    figure.skin(0.3).unwrap();
    let mut frame = Frame::default();
    let note = figure.draw_gpu(&mut frame, SkinMeshId(0)).unwrap();
    assert!(note.contains("on the GPU"), "{note}");
    assert_eq!(frame.skinned.len(), 1);
    assert!(frame.skinned[0].dqs, "the figure starts with DQS");
    assert_eq!(
        frame.skinned[0].joints.len(),
        figure.character().skeleton.len()
    );
    // The palette moved: the walk at 0.3 s is not the bind pose.
    assert!(frame
        .skin_palette
        .iter()
        .any(|r| (r[0] - glam::Vec4::new(0.0, 0.0, 0.0, 1.0)).length() > 1e-3));
    // CPU mode: a plain mesh, no GPU draws.
    figure.set_gpu(false);
    figure.skin(0.3).unwrap();
    let mut frame = Frame::default();
    let note = figure.draw(&mut frame, MeshId(3));
    assert!(note.contains("on the CPU"), "{note}");
    assert!(frame.skinned.is_empty() && frame.meshes.len() == 1);
    // Heat map changes reach the GPU copy once.
    figure.take_gpu_dirty();
    figure.set_heat_joint("none").unwrap();
    assert!(figure.take_gpu_dirty() && !figure.take_gpu_dirty());
}

mod compute {
    use glam::Vec3;
    use inbetween::boids::grid::Grid;
    use inbetween::boids::{BoidParams, Flock, Search};
    use inbetween::figures::boids::FlockFigure;
    use inbetween::figures::gpu::{
        boid_rows, flock_stats, grid_rows, particle_stats, GpuParticleClock, GridLayout,
        MAX_GPU_BOIDS, MAX_GPU_GRID_BOIDS, MAX_GPU_GRID_CELLS, MAX_GPU_PARTICLES,
    };
    use inbetween::particles::{Emitter, ParticleSystem, Sphere, Surfaces};

    #[test]
    fn the_clock_spawns_what_the_cpu_system_spawns() {
        // Long lifetimes: nobody dies, so the CPU's live count is what it spawned.
        let mut e = Emitter::fountain(Vec3::ZERO);
        e.rate_per_sec = 137.0;
        e.lifetime_sec = (50.0, 60.0);
        let surfaces = Surfaces::default();
        let mut cpu = ParticleSystem::new(5000, 1).unwrap();
        let (mut ce, mut ge) = ([e], [e]);
        let mut clock = GpuParticleClock::new(5000, 1).unwrap();
        let mut spawned = 0u32;
        for k in 0..100 {
            cpu.step(&mut ce, &surfaces, 1.0 / 60.0);
            let rows = clock.step(&mut ge, &surfaces, 1.0 / 60.0, [0; 4]).unwrap();
            assert_eq!(rows[2][1], spawned % 5000, "ring start at step {k}");
            spawned += rows[3].iter().sum::<u32>();
            assert_eq!(spawned as usize, cpu.len(), "step {k}");
        }
    }

    #[test]
    fn caps_and_bad_input_are_errors() {
        assert!(GpuParticleClock::new(MAX_GPU_PARTICLES + 1, 0).is_err());
        assert!(GpuParticleClock::new(0, 0).is_err());
        let mut clock = GpuParticleClock::new(100, 0).unwrap();
        let s = Surfaces::default();
        let e = Emitter::fountain(Vec3::ZERO);
        assert!(clock
            .step(&mut [e; 5], &s, 0.01, [0; 4])
            .unwrap_err()
            .contains("emitters"));
        assert!(clock
            .step(&mut [e], &s, f32::NAN, [0; 4])
            .unwrap_err()
            .contains("dt"));
        let mut bad = e;
        bad.rate_per_sec = -1.0;
        assert!(clock
            .step(&mut [bad], &s, 0.01, [0; 4])
            .unwrap_err()
            .contains("rate"));
        let many = Surfaces {
            spheres: vec![
                Sphere {
                    center: Vec3::ZERO,
                    radius: 1.0
                };
                9
            ],
            ..Default::default()
        };
        assert!(clock
            .step(&mut [e], &many, 0.01, [0; 4])
            .unwrap_err()
            .contains("spheres"));
        // A burst bigger than the ring is cut to the ring.
        let rows = clock.step(&mut [e], &s, 0.0, [500, 0, 0, 0]).unwrap();
        assert_eq!(rows[3].iter().sum::<u32>(), 100);
        let p = BoidParams::default();
        let e = boid_rows(&p, MAX_GPU_BOIDS + 1, Search::Naive, 0.0, 0.01).unwrap_err();
        assert!(e.contains("count") && e.contains("every pair"), "{e}");
        // The grid takes a million boids and more.
        assert!(boid_rows(&p, 1_000_000, Search::Grid, 0.0, 0.01).is_ok());
        let e = boid_rows(&p, MAX_GPU_GRID_BOIDS + 1, Search::Grid, 0.0, 0.01).unwrap_err();
        assert!(e.contains("1048576"), "{e}");
        assert!(boid_rows(&p, 0, Search::Grid, 0.0, 0.01).is_err());
        assert!(boid_rows(&p, 10, Search::Grid, 0.0, -1.0)
            .unwrap_err()
            .contains("dt"));
        let nan = BoidParams {
            max_speed: f32::NAN,
            ..Default::default()
        };
        assert!(boid_rows(&nan, 10, Search::Naive, 0.0, 0.01).is_err());
        assert_eq!(
            boid_rows(&p, 10, Search::Naive, 0.0, 0.01).unwrap().len(),
            12 + 8
        );
        // A boid's dot radius (the first of the three looks rows, after nine of parameters): big
        // enough to see in a figure-sized flock, smaller in a flock of thousands.
        let dot = |n| f32::from_bits(boid_rows(&p, n, Search::Grid, 0.0, 0.01).unwrap()[9][3]);
        assert!(dot(300) >= 0.05, "{}", dot(300));
        assert!(dot(100_000) < 0.04, "{}", dot(100_000));
    }

    /// The GPU grid's cells (`GridLayout::cell_of`, the formula of `grid_common.wgsl`) are the
    /// CPU grid's for the CPU grid's layout, points outside the box included; a cubic layout
    /// keeps under its cap by growing its cells; `grid_rows` checks its caps.
    #[test]
    fn the_gpu_grid_layout_has_the_cpu_grids_cells_and_caps() {
        let params = BoidParams {
            bounds: Vec3::new(4.0, 2.0, 3.0),
            ..Default::default()
        };
        let flock = Flock::new(2000, &params, 4).unwrap();
        let mut cpu = Grid::default();
        cpu.configure(-params.bounds, params.bounds, 0.7);
        let layout = GridLayout::of_cpu_grid(&cpu);
        assert_eq!(layout.cells(), cpu.cell_count());
        let outside = [Vec3::new(50.0, -9.0, 0.1), Vec3::splat(-1e9)];
        for p in flock.positions.iter().chain(&outside) {
            assert_eq!(layout.cell_of(*p), cpu.cell_of_point(*p), "{p}");
        }
        assert_eq!(layout.cell_of(Vec3::NAN), 0);
        let cubic = GridLayout::cubic(Vec3::splat(-1.0), Vec3::new(3.0, 1.0, 1.0), 0.5).unwrap();
        assert_eq!(cubic.dims, [8, 4, 4]);
        assert_eq!(cubic.reach(2.0), 4);
        assert_eq!(cubic.reach(0.1), 1);
        let fine = GridLayout::cubic(Vec3::splat(-100.0), Vec3::splat(100.0), 0.05).unwrap();
        assert!(fine.cells() <= MAX_GPU_GRID_CELLS && fine.cell_size.x > 0.05);
        assert!(GridLayout::cubic(Vec3::ZERO, Vec3::ONE, 0.0).is_err());
        assert!(GridLayout::cubic(Vec3::ZERO, Vec3::NAN, 1.0).is_err());
        assert_eq!(grid_rows(&cubic, 10, 2).unwrap()[2], [8, 4, 4, 128]);
        assert!(grid_rows(&cubic, MAX_GPU_GRID_BOIDS + 1, 2).is_err());
        assert!(grid_rows(&cubic, 10, 0).is_err());
        assert!(grid_rows(&cubic, 0, 2).is_err());
        let huge = GridLayout {
            dims: [4096, 4096, 1],
            ..cubic
        };
        assert!(grid_rows(&huge, 10, 2).unwrap_err().contains("cell count"));
    }

    /// Lesson 12's flock in GPU mode: a flock of its own up to the grid's cap, in a box that
    /// keeps the density; every pair takes at most MAX_GPU_BOIDS, and a setter that would break
    /// that changes nothing.
    #[test]
    fn the_flock_figure_chooses_the_gpu_search_and_count() {
        let mut f = FlockFigure::new();
        for bad in [1, MAX_GPU_GRID_BOIDS + 1] {
            assert!(f.set_gpu_count(bad).unwrap_err().contains("GPU boids"));
        }
        assert_eq!(f.gpu_count(), 0);
        f.set_gpu_mode(true).unwrap();
        f.set_gpu_count(1_000_000).unwrap();
        assert_eq!(f.gpu_len(), 1_000_000);
        // A million boids queue one step a call, however far the timeline moved.
        assert_eq!(f.plan_gpu_steps(0.0).unwrap(), (false, 0));
        assert_eq!(f.plan_gpu_steps(0.1).unwrap(), (false, 1));
        let scale = f.gpu_params().bounds.x / f.params().bounds.x;
        assert!(
            (scale - (1_000_000f32 / 300.0).cbrt()).abs() < 1e-3,
            "{scale}"
        );
        let (p, v, _) = f.gpu_start();
        assert_eq!((p.len(), v.len()), (1_000_000, 1_000_000));
        let b = f.gpu_params().bounds;
        assert!(p.iter().all(|p| p.abs().cmple(b).all()));
        // Every pair at a million: refused, and the search stays the grid.
        assert!(f.set_search("naive").unwrap_err().contains("every pair"));
        assert_eq!(f.search(), Search::Grid);
        f.set_gpu_count(MAX_GPU_BOIDS as usize).unwrap();
        f.set_search("naive").unwrap();
        assert!(f.set_gpu_count(MAX_GPU_BOIDS + 1).is_err());
        assert_eq!(f.gpu_len(), MAX_GPU_BOIDS);
        // Back to the slider's flock (300 boids) in the figure's own box.
        f.set_gpu_count(0).unwrap();
        assert_eq!(f.gpu_len(), 300);
        assert_eq!(f.gpu_params().bounds, f.params().bounds);
        // GPU mode cannot start with every pair over the cap.
        f.set_gpu_mode(false).unwrap();
        f.set_gpu_count(100_000).unwrap();
        assert!(f.set_gpu_mode(true).is_err());
        assert!(!f.gpu_mode());
    }

    #[test]
    fn statistics_measure_what_they_say() {
        let s = particle_stats(
            &[Vec3::Y, Vec3::new(0.0, 3.0, 0.0), Vec3::splat(9.0)],
            &[Vec3::X, Vec3::new(0.0, 3.0, 0.0), Vec3::ZERO],
            &[true, true, false],
        );
        assert_eq!(
            (s.alive, s.mean_speed, s.mean_height, s.lowest),
            (2, 2.0, 2.0, 1.0)
        );
        // Two boids heading the same way 1 m apart; then opposite ways.
        let p = [Vec3::ZERO, Vec3::X];
        let f = flock_stats(&p, &[Vec3::Z, 2.0 * Vec3::Z]);
        assert_eq!(
            (f.mean_speed, f.polarisation, f.mean_nearest_m),
            (1.5, 1.0, 1.0)
        );
        assert_eq!(flock_stats(&p, &[Vec3::Z, -Vec3::Z]).polarisation, 0.0);
    }
}

mod figures {
    use inbetween::figures::boids::FlockFigure;
    use inbetween::figures::particles::EmitterFigure;

    /// On the GPU the live-particle plot keeps its time axis and its guides (rate × lifetime,
    /// the fountain's slots) while the counts, never read back, are NaN after step 0.
    #[test]
    fn the_emitter_figure_plots_its_guides_but_no_counts_on_the_gpu() {
        let mut f = EmitterFigure::new();
        f.restart();
        assert!(f.advance_gpu(1.0, false, |_, _, _, _| Ok(())).unwrap().0);
        f.advance_gpu(1.0, true, |_, _, _, _| Ok(())).unwrap();
        let samples = f.count_samples();
        let rows: Vec<&[f32]> = samples.chunks_exact(5).collect();
        assert_eq!(rows.len(), 61, "step 0 and 60 steps");
        assert_eq!(rows[0][..3], [0.0, 0.0, 0.0]);
        let (steady, slots) = (f.steady_count(), f.slots().0 as f32);
        assert!(steady > 0.0 && slots > 0.0);
        for (i, r) in rows.iter().enumerate().skip(1) {
            assert!((r[0] - i as f32 * inbetween::figures::particles::SIM_DT).abs() < 1e-5);
            assert!(r[1].is_nan() && r[2].is_nan(), "{r:?}");
            assert_eq!((r[3], r[4]), (steady, slots));
        }
    }

    #[test]
    fn the_emitter_figure_hands_its_steps_to_the_gpu() {
        let mut f = EmitterFigure::new();
        f.set_mode("both").unwrap();
        // A new mode restarts first, without stepping.
        let (restart, n) = f
            .advance_gpu(1.0, false, |_, _, _, _| panic!("no step yet"))
            .unwrap();
        assert!(restart && n == 0);
        let mut bursts = Vec::new();
        let (restart, n) = f
            .advance_gpu(1.0, true, |e, _, b, dt| {
                assert_eq!(e.len(), 2);
                assert_eq!(dt, inbetween::figures::particles::SIM_DT);
                bursts.push(b);
                Ok(())
            })
            .unwrap();
        assert!(!restart && n == 60 && bursts.len() == 60);
        assert_eq!(bursts[0], 400, "the explosion goes off at the start");
        assert!(bursts[1..].iter().all(|&b| b == 0));
        // Forward: more steps, no restart; back in time: a restart.
        assert_eq!(
            f.advance_gpu(1.5, false, |_, _, _, _| Ok(())).unwrap(),
            (false, 30)
        );
        assert_eq!(
            f.advance_gpu(0.5, false, |_, _, _, _| Ok(())).unwrap(),
            (true, 0)
        );
        // A failing GPU step is the caller's error, and the clock does not move past it.
        let e = f
            .advance_gpu(0.5, true, |_, _, _, _| Err("boom".into()))
            .unwrap_err();
        assert_eq!(e, "boom");
        assert!(f.advance_gpu(f32::NAN, false, |_, _, _, _| Ok(())).is_err());
        // "Explode now" reaches the GPU at once, once per step, and the note counts it.
        let mut fired = 0;
        f.explode_gpu(|_, _, n| {
            fired += n;
            Ok(())
        })
        .unwrap();
        f.explode_gpu(|_, _, _| panic!("already set off at this step"))
            .unwrap();
        assert_eq!(fired, 400);
        let mut frame = inbetween::draw::Frame::default();
        let note = f.draw_gpu(&mut frame);
        assert!(
            note.contains("GPU") && note.contains("by hand: 1"),
            "{note}"
        );
        assert!(frame.points.is_empty(), "the sprites are the GPU's");
    }

    #[test]
    fn gpu_particles_are_drawn_as_the_cpu_figures_atlas_sprites() {
        // The compute shader writes SpriteInstance rows with the figure's scale and the atlas's
        // grid, written into the WGSL as constants: they must be the Rust ones.
        use inbetween::figures::particles::SPRITE_SCALE;
        use inbetween::particles::sprites::SMOKE_ATLAS;
        let wgsl = include_str!("../src/render/shaders/particles.wgsl");
        let constant = |name: &str| {
            let at = wgsl.find(&format!("const {name}: ")).expect(name);
            let line = wgsl[at..].lines().next().unwrap();
            line.split('=')
                .nth(1)
                .unwrap()
                .trim()
                .trim_end_matches(';')
                .to_string()
        };
        assert_eq!(
            constant("SPRITE_SCALE").parse::<f32>().unwrap(),
            SPRITE_SCALE
        );
        assert_eq!(
            constant("ATLAS_COLUMNS"),
            format!("{}u", SMOKE_ATLAS.columns)
        );
        assert_eq!(constant("ATLAS_ROWS"), format!("{}u", SMOKE_ATLAS.rows));
        // The GPU frame carries the atlas for those sprites.
        let mut f = EmitterFigure::new();
        f.set_sprite_texture(Some(inbetween::draw::TextureId(3)));
        let mut frame = inbetween::draw::Frame::default();
        f.draw_gpu(&mut frame);
        assert_eq!(frame.sprite_texture, Some(inbetween::draw::TextureId(3)));
        assert!(frame.sprites.is_empty(), "the sprites are the GPU's");
    }

    #[test]
    fn a_paused_gpu_press_survives_a_parameter_change() {
        // In GPU mode, paused, "explode now" then a real change of a slider replays the run up
        // to the paused step; the press made there is handed over last, as a step of 0 s, so it
        // spawns as in the CPU run instead of being dropped.
        let mut f = EmitterFigure::new();
        let run = |f: &mut EmitterFigure, t: f32| {
            let mut calls = Vec::new();
            let (restart, _) = f
                .advance_gpu(t, false, |_, _, b, dt| {
                    calls.push((b, dt));
                    Ok(())
                })
                .unwrap();
            if restart {
                f.advance_gpu(t, true, |_, _, b, dt| {
                    calls.push((b, dt));
                    Ok(())
                })
                .unwrap();
            }
            calls
        };
        assert_eq!(run(&mut f, 1.0).len(), 60);
        let mut fired = 0;
        f.explode_gpu(|_, _, n| {
            fired += n;
            Ok(())
        })
        .unwrap();
        assert_eq!(fired, 400);
        // Paused: the same time again, nothing to do.
        assert!(run(&mut f, 1.0).is_empty());
        f.set_restitution(0.5).unwrap();
        let calls = run(&mut f, 1.0);
        assert_eq!(calls.len(), 61, "60 steps, then the press");
        assert!(calls[..60].iter().all(|&(b, dt)| b == 0 && dt > 0.0));
        assert_eq!(calls[60], (400, 0.0));
        // Played on, the press is not spawned a second time.
        let calls = run(&mut f, 1.5);
        assert_eq!(calls.len(), 30);
        assert!(calls.iter().all(|&(b, _)| b == 0));
    }

    #[test]
    fn fade_off_makes_the_gpu_sprites_opaque_as_the_cpu_ones() {
        // The compute shader colours each sprite by mixing its emitter's birth and death
        // colours; with "fade with age" off the CPU figure draws every sprite with alpha 1, so
        // the GPU must get opaque colours too, and the figure's own emitters stay as they were.
        let mut f = EmitterFigure::new();
        let alphas = |f: &mut EmitterFigure, t: f32| {
            let mut seen = Vec::new();
            let mut step = |e: &mut [inbetween::particles::Emitter]| -> Result<(), String> {
                seen.extend(e.iter().map(|e| (e.color_birth.w, e.color_death.w)));
                Ok(())
            };
            let (restart, _) = f.advance_gpu(t, false, |e, _, _, _| step(e)).unwrap();
            if restart {
                f.advance_gpu(t, true, |e, _, _, _| step(e)).unwrap();
            }
            f.explode_gpu(|e, _, _| step(e)).unwrap();
            seen
        };
        let faded = alphas(&mut f, 0.5);
        assert!(!faded.is_empty());
        assert!(faded.iter().any(|&(_, death)| death < 1.0), "{faded:?}");
        let mut frame = inbetween::draw::Frame::default();
        assert!(f.draw_gpu(&mut frame).contains("fade with age"));
        // Turning the fade off replays the run, every step with opaque colours.
        f.set_fade(false);
        let opaque = alphas(&mut f, 0.5);
        assert!(opaque.len() >= faded.len(), "a replay: {opaque:?}");
        assert!(opaque.iter().all(|&a| a == (1.0, 1.0)), "{opaque:?}");
        assert!(f.draw_gpu(&mut frame).contains("opaque"));
        // The emitters themselves keep their fade for when it is turned back on.
        f.set_fade(true);
        let again = alphas(&mut f, 0.5);
        assert!(again.iter().any(|&(_, death)| death < 1.0), "{again:?}");
        // Setting the same value again is no change: no replay.
        f.set_fade(true);
        assert!(f.advance_gpu(0.5, false, |_, _, _, _| Ok(())).unwrap() == (false, 0));
    }
    #[test]
    fn the_flock_figure_plans_its_gpu_steps() {
        let mut f = FlockFigure::new();
        // A jump of more than the catch-up limit restarts from a fresh seeded flock.
        assert_eq!(f.plan_gpu_steps(0.5).unwrap(), (true, 0));
        assert_eq!(f.plan_gpu_steps(0.55).unwrap(), (false, 3));
        assert_eq!(f.plan_gpu_steps(0.2).unwrap(), (true, 0));
        let mut frame = inbetween::draw::Frame::default();
        let note = f.draw_gpu(&mut frame);
        assert!(note.contains("300 boids") && note.contains("GPU"), "{note}");
        assert!(frame.points.is_empty());
        // The note names only the roles that are on.
        for (leader, predator) in [(false, false), (true, false), (false, true), (true, true)] {
            f.set_leader(leader);
            f.set_predator(predator);
            let note = f.draw_gpu(&mut inbetween::draw::Frame::default());
            assert_eq!(note.contains("leader green"), leader, "{note}");
            assert_eq!(note.contains("predator red"), predator, "{note}");
        }
    }
}

/// The GPU fluid's uniform block and grid (`src/render/fluid.rs` steps with them; the browser
/// test tests/web/gpu_fluid.rs compares its steps with the CPU's).
mod fluid_compute {
    use glam::Vec3;
    use inbetween::figures::gpu::{
        check_gpu_fluid, fluid_layout, fluid_rows, GPU_FLUID_ROWS, MAX_GPU_FLUID_PARTICLES,
        MAX_GPU_GRID_CELLS,
    };
    use inbetween::fluid::{spacing_for, Dim, Fluid, FluidParams, Kernels, Method, Scene};
    use inbetween::particles::Sphere;

    fn f(bits: u32) -> f32 {
        f32::from_bits(bits)
    }

    fn fluid(dim: Dim, method: Method, count: usize, cap: usize) -> Fluid {
        let mut params = match dim {
            Dim::Two => FluidParams::default_2d(method),
            Dim::Three => FluidParams::default_3d(method),
        };
        params.h = 2.0 * spacing_for(dim, Scene::DamBreak, count);
        Fluid::with_cap(params, Scene::DamBreak, count, 1, cap).unwrap()
    }

    #[test]
    fn the_rows_carry_the_cpu_fluids_kernels_walls_and_obstacle() {
        for (dim, walls) in [(Dim::Two, 4), (Dim::Three, 6)] {
            for method in [Method::Sph, Method::Pbf] {
                let mut fl = fluid(dim, method, 2000, 2000);
                let rows = fluid_rows(&fl).unwrap();
                assert_eq!(rows.len(), GPU_FLUID_ROWS);
                let p = &fl.params;
                assert_eq!(
                    [f(rows[0][0]), f(rows[0][2]), f(rows[0][3])],
                    [p.h, fl.mass, p.dt]
                );
                let k = Kernels::new(p.h, dim);
                // The shader's poly6(r²) = c (h² − r²)³ is the CPU kernel at r = h/2.
                let r2 = 0.25 * p.h * p.h;
                let d = p.h * p.h - r2;
                assert_eq!(f(rows[1][0]) * d * d * d, k.poly6(r2));
                assert_eq!(f(rows[1][3]), k.poly6(0.04 * p.h * p.h));
                assert_eq!(f(rows[4][2]), p.s_corr * fl.lambda_unit());
                assert!(fl.lambda_unit() > 0.0);
                assert_eq!(
                    rows[7],
                    [fl.len() as u32, walls, (method == Method::Pbf) as u32, 0]
                );
                assert_eq!(f(rows[5][1]), if dim == Dim::Two { 1.0 } else { 0.0 });
                // The walls as the CPU's planes; the unused slots are zero.
                for (w, row) in fl.walls.iter().zip(&rows[10..]) {
                    assert_eq!(
                        [f(row[0]), f(row[1]), f(row[2]), f(row[3])],
                        [w.normal.x, w.normal.y, w.normal.z, w.offset]
                    );
                }
                assert!(rows[10 + walls as usize..].iter().all(|r| *r == [0; 4]));
                // No obstacle: radius 0; one: its centre and radius.
                assert_eq!(rows[6], [0; 4]);
                let s = Sphere {
                    center: Vec3::new(0.8, 0.3, 0.0),
                    radius: 0.2,
                };
                fl.set_obstacle(Some(s)).unwrap();
                let rows = fluid_rows(&fl).unwrap();
                assert_eq!(f(rows[6][3]), 0.2);
                assert_eq!(f(rows[6][0]), 0.8);
            }
        }
    }

    #[test]
    fn the_cap_is_a_million_and_more_is_an_error() {
        assert!(MAX_GPU_FLUID_PARTICLES >= 1_000_000);
        assert!(check_gpu_fluid(MAX_GPU_FLUID_PARTICLES).is_ok());
        for n in [0, MAX_GPU_FLUID_PARTICLES + 1] {
            let e = check_gpu_fluid(n).unwrap_err();
            assert!(e.contains("1048576") && e.contains(&n.to_string()), "{e}");
        }
        // A fluid the CPU fills past the cap is refused as a whole.
        let big = fluid(
            Dim::Three,
            Method::Sph,
            MAX_GPU_FLUID_PARTICLES + 60_000,
            1 << 21,
        );
        assert!(big.len() > MAX_GPU_FLUID_PARTICLES, "{}", big.len());
        assert!(fluid_rows(&big).unwrap_err().contains("1048576"));
    }

    #[test]
    fn the_grid_has_cells_at_least_h_wide_up_to_the_cap() {
        for (dim, n) in [
            (Dim::Three, 1_000_000),
            (Dim::Three, 2000),
            (Dim::Two, 100_000),
        ] {
            let fl = fluid(dim, Method::Pbf, n, MAX_GPU_FLUID_PARTICLES);
            let layout = fluid_layout(&fl).unwrap();
            assert!(
                layout.cells() <= MAX_GPU_GRID_CELLS,
                "{n}: {}",
                layout.cells()
            );
            // One cell each way finds every neighbour within h (the shader's reach).
            assert_eq!(layout.reach(fl.params.h), 1, "{n}");
            let size = inbetween::fluid::box_size(dim);
            let h = Vec3::splat(fl.params.h);
            let far = layout.origin
                + layout.cell_size
                    * Vec3::new(
                        layout.dims[0] as f32,
                        layout.dims[1] as f32,
                        layout.dims[2] as f32,
                    );
            assert!(
                layout.origin.cmple(-h).all() && far.cmpge(size + h).all(),
                "{n}"
            );
        }
    }
}
