//! The fluids lesson's figure logic (src/figures/fluid.rs).
#![cfg(not(target_arch = "wasm32"))]

use inbetween::draw::Frame;
use inbetween::figures::fluid::{DensityFigure, KernelsFigure};
#[path = "support/flat.rs"]
mod flat;

#[test]
fn the_kernel_plots_start_at_one_and_reach_zero_at_h() {
    let mut fig = KernelsFigure::new();
    for (h, dim) in [(0.1, 2), (0.05, 3)] {
        fig.set(h, dim).unwrap();
        let rows = fig.plot_rows(201).unwrap();
        assert_eq!(rows.len(), 201);
        assert_eq!(rows[0][0], 0.0);
        assert!((rows[200][0] - 1.25 * h).abs() < 1e-6);
        for c in 1..5 {
            assert!(
                (rows[0][c] - 1.0).abs() < 1e-3,
                "column {c} starts at {}",
                rows[0][c]
            );
        }
        for row in &rows {
            // Every curve decreases from 1 at r = 0 to 0 at h, and stays 0 beyond.
            for c in 1..5 {
                assert!((0.0..=1.0 + 1e-3).contains(&row[c]), "{row:?}");
                if row[0] >= h {
                    assert_eq!(row[c], 0.0, "{row:?}");
                }
            }
        }
        for w in rows.windows(2) {
            for c in 1..5 {
                assert!(w[1][c] <= w[0][c] + 1e-6, "column {c} rises: {w:?}");
            }
        }
        // Half-way to h: poly6 keeps (3/4)³ = 42 % of its peak, spiky (1/2)³ = 12.5 %.
        let mid = rows.iter().find(|r| (r[0] - 0.5 * h).abs() < 1e-4).unwrap();
        assert!(
            (mid[1] - 0.421875).abs() < 1e-3 && (mid[2] - 0.125).abs() < 1e-3,
            "{mid:?}"
        );
    }
    assert!(fig.set(-1.0, 2).is_err() && fig.set(0.1, 4).is_err() && fig.plot_rows(1).is_err());
}

#[test]
fn a_particle_inside_the_pool_has_the_rest_density_and_one_above_it_only_its_own() {
    let mut fig = DensityFigure::new();
    let rho0 = fig.fluid().params.rest_density;
    // The default: in the middle of the pool, about 23 neighbours, within 3 % of ρ₀.
    let (rho, n) = fig.probe();
    assert!((rho / rho0 - 1.0).abs() < 0.03, "ρ = {rho}");
    assert!((18..=30).contains(&n), "{n} neighbours");
    // At the surface (0.4 m), about half the neighbourhood is air.
    fig.set_probe(0.8, 0.4).unwrap();
    let (surface, _) = fig.probe();
    assert!(
        (0.4..0.75).contains(&(surface / rho0)),
        "surface ρ/ρ₀ = {}",
        surface / rho0
    );
    // Above the water: no neighbours, only its own term m W(0).
    fig.set_probe(0.8, 0.9).unwrap();
    let (alone, n) = fig.probe();
    assert_eq!(n, 0);
    let terms = fig.terms();
    assert_eq!(terms.len(), 1);
    assert_eq!(alone, terms[0][1]);
    // The terms add up to the density, nearest first, each within h.
    fig.set_probe(0.5, 0.2).unwrap();
    let terms = fig.terms();
    let sum: f32 = terms.iter().map(|t| t[1]).sum();
    assert!((sum / fig.probe().0 - 1.0).abs() < 1e-5);
    assert!(terms.windows(2).all(|w| w[0][0] <= w[1][0]) && terms.iter().all(|t| t[0] < 1.0));
}

#[test]
fn a_rejected_probe_changes_nothing_and_the_note_says_the_density() {
    let mut fig = DensityFigure::new();
    let before = fig.probe();
    for (x, y) in [(f32::NAN, 0.2), (0.5, 1e38), (-0.1, 0.2), (0.5, 1.5)] {
        assert!(fig.set_probe(x, y).is_err());
        assert_eq!(fig.probe(), before);
    }
    let mut frame = Frame::default();
    let note = fig.draw(&mut frame);
    assert!(
        note.starts_with("ρ = ") && note.contains("neighbours within h"),
        "{note}"
    );
    assert_eq!(frame.labels.len(), 1);
    assert!(!frame.keep_in_view.is_empty());
    assert!(
        note.contains("SPH: pressure") && note.contains("PBF: λ"),
        "{note}"
    );
}

use inbetween::figures::fluid::{DamBreakFigure, DAM_FRAME_SEC};

#[test]
fn the_dam_break_replays_the_same_run_and_pbf_keeps_the_density_closer() {
    let mut fig = DamBreakFigure::new();
    fig.advance_to(1.5).unwrap();
    let first = fig.fluids()[0].positions.clone();
    let rows = fig.plot_rows().to_vec();
    assert_eq!(rows.len(), (1.5 / DAM_FRAME_SEC).round() as usize);
    // Back in time and forward again: the same state, bit for bit.
    fig.advance_to(0.2).unwrap();
    fig.advance_to(1.5).unwrap();
    assert_eq!(fig.fluids()[0].positions, first);
    assert_eq!(fig.plot_rows(), &rows[..]);
    // Neither explodes at the defaults; over the fall and the splash PBF's largest compression
    // stays under SPH's (its constraints hold the density, SPH's pressure only pushes back).
    assert!(fig.fluids().iter().all(|f| f.exploded().is_none()));
    let peak = |c: usize| rows.iter().map(|r| r[c]).fold(0.0f32, f32::max);
    assert!(peak(2) < peak(1), "PBF {} vs SPH {}", peak(2), peak(1));
    let mut frame = Frame::default();
    let note = fig.draw(&mut frame);
    assert!(
        note.starts_with("SPH: densest particle +") && note.contains("PBF: densest particle"),
        "{note}"
    );
    assert_eq!(frame.labels.len(), 2);
}

#[test]
fn the_dam_break_note_at_the_start_gives_the_starting_densities() {
    // Before the first step: the block at rest, its densest particle near ρ₀ (not −100 %, as
    // densities never computed would give).
    let fig = DamBreakFigure::new();
    let note = fig.draw(&mut Frame::default());
    assert!(!note.contains("-100"), "{note}");
    for f in fig.fluids() {
        let max = f.stats().density_error_max;
        assert!(max.abs() < 0.05, "{max}");
    }
}

/// The particles are shaded discs nearly a spacing wide, one per particle of both fluids, and
/// the two boxes fill the width of the page's canvas (the figure's controls sit under it), so
/// each particle is at least 5 px across at 800 and 1600 px wide windows (outlined 7 px dots,
/// mostly white ring and dark rim, and boxes in 60 % of a canvas beside the controls read as
/// grey specks).
#[test]
fn the_dam_break_draws_its_water_across_the_canvas_in_particles_5_px_wide() {
    use glam::{Vec2, Vec3};
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::figures::fluid::DAM_POINT_SPACINGS;
    let fig = DamBreakFigure::new();
    let mut frame = Frame::default();
    fig.draw(&mut frame);
    let n: usize = fig.fluids().iter().map(|f| f.len()).sum();
    assert!(frame.markers.is_empty());
    assert_eq!(frame.points.len(), n);
    let radius = DAM_POINT_SPACINGS * fig.fluids()[0].spacing;
    assert!(frame.points.iter().all(|p| p.radius == radius));
    assert!((0.4..=0.5).contains(&DAM_POINT_SPACINGS));
    // The page's canvas: the figure's width by 420 px, at windows 800 and 1600 px wide; the page
    // places the camera square-on to the slab and the viewer fits what the figure keeps in view.
    for size in [Vec2::new(760.0, 420.0), Vec2::new(920.0, 420.0)] {
        let mut camera = OrbitCamera::from_view([0.0, 0.55, 0.0, 4.0, 0.0, 0.0]);
        assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
        let p = Vec3::from(frame.points[0].center);
        let across = 2.0 * (at(p + radius * Vec3::X) - at(p)).x;
        assert!(across >= 5.0, "{size}: {across} px");
        let xs: Vec<f32> = frame.fit_points().iter().map(|&q| at(q).x).collect();
        let span =
            xs.iter().fold(f32::MIN, |a, &b| a.max(b)) - xs.iter().fold(f32::MAX, |a, &b| a.min(b));
        assert!(span > 0.85 * size.x, "{size}: the boxes span {span} px");
    }
}

#[test]
fn sph_past_its_time_step_limit_stops_and_the_note_says_why() {
    let mut fig = DamBreakFigure::new();
    // A speed of sound of 20 m/s crosses 2.4 kernel radii in a 1/60 s step.
    fig.set_sph(400.0, 1.0 / 60.0).unwrap();
    fig.advance_to(2.0).unwrap();
    assert!(fig.fluids()[0].exploded().is_some());
    assert!(fig.fluids()[1].exploded().is_none());
    let note = fig.draw(&mut Frame::default());
    assert!(
        note.starts_with("SPH stopped at t = ") && note.contains("lower the time step"),
        "{note}"
    );
    // The plot's SPH curves end where it stopped (NaN), PBF's go on.
    let last = fig.plot_rows().last().unwrap();
    assert!(last[1].is_nan() && last[2].is_finite());
    // Bad settings change nothing.
    let before = fig.fluids()[0].params.clone();
    assert!(fig.set_sph(f32::NAN, 0.001).is_err() && fig.set_sph(400.0, 0.0).is_err());
    assert_eq!(fig.fluids()[0].params, before);
    assert!(fig.advance_to(-1.0).is_err() && fig.advance_to(1e38).is_err());
}

/// The numbers lesson 15's text gives for Figure 2 (its "Try this" callouts).
#[test]
fn the_density_figure_shows_what_the_lesson_says() {
    let mut fig = DensityFigure::new();
    let rho0 = fig.fluid().params.rest_density;
    // The caption: h = 9.7 cm, 2.7 spacings.
    assert!((fig.h() - 0.097).abs() < 0.0005 && (fig.h() / fig.fluid().spacing - 2.7).abs() < 1e-4);
    // The start: 21 neighbours, ρ₀ to within 0.1 %, a pressure of about 120 Pa.
    let (rho, n) = fig.probe();
    assert_eq!(n, 21);
    assert!((rho / rho0 - 1.0).abs() < 0.001, "{rho}");
    let p = fig.forces().pressure;
    assert!((100.0..140.0).contains(&p), "{p}");
    // At the surface: about 10 neighbours, about 60 % of ρ₀.
    fig.set_probe(0.8, 0.4).unwrap();
    let (rho, n) = fig.probe();
    assert!(
        (9..=11).contains(&n) && (0.57..0.63).contains(&(rho / rho0)),
        "{n} {rho}"
    );
    // Out of the water: its own term alone, 17 % of ρ₀.
    fig.set_probe(0.8, 0.9).unwrap();
    let (rho, n) = fig.probe();
    assert!(n == 0 && (0.165..0.18).contains(&(rho / rho0)), "{rho}");
    // Half a spacing sideways: one particle more, 0.9 % denser, about 3,700 Pa, pushed back
    // towards where it came from (−x), and PBF's move of about 0.3 mm.
    fig.set_probe(0.818, 0.2).unwrap();
    let (rho, n) = fig.probe();
    let f = fig.forces();
    assert!(
        n == 23 && (0.0085..0.0095).contains(&(rho / rho0 - 1.0)),
        "{n} {rho}"
    );
    assert!((3500.0..3900.0).contains(&f.pressure), "{}", f.pressure);
    assert!(
        f.force.x < 0.0 && f.force.x.abs() > f.force.y.abs(),
        "{}",
        f.force
    );
    let mm = 1000.0 * f.correction.length();
    assert!((0.25..0.35).contains(&mm), "{mm} mm");
    assert!(f.lambda < 0.0 && f.correction.x < 0.0, "{f:?}");
}

/// PBF's move is a fraction of a millimetre: its arrow grows with it and levels off at 30 cm
/// (the caption), 13 cm at x = 0.818 m (the "Try this").
#[test]
fn the_pbf_arrow_grows_with_the_move_and_levels_off_at_30_cm() {
    use inbetween::figures::fluid::pbf_arrow_length;
    let mut fig = DensityFigure::new();
    fig.set_probe(0.818, 0.2).unwrap();
    let drawn = pbf_arrow_length(fig.forces().correction.length());
    assert!((0.12..0.14).contains(&drawn), "{drawn} m");
    assert!(pbf_arrow_length(0.01) <= 0.3 && pbf_arrow_length(0.01) > 0.299);
    assert!(pbf_arrow_length(2e-4) < pbf_arrow_length(4e-4));
}

/// The support circle shows on the water's dark blue: its dashes are drawn over the particles,
/// each purple one over a wider white one (purple alone was lost on the blue).
#[test]
fn the_support_circle_is_purple_on_white_over_the_particles() {
    use glam::Vec3;
    use inbetween::draw::{palette, ON_TOP};
    let f = DensityFigure::new();
    let mut frame = Frame::default();
    f.draw(&mut frame);
    let dashed = |color: Vec3| {
        frame
            .strokes
            .iter()
            .filter(move |s| Vec3::from_slice(&s.color) == color && s.dash[3] > 0.0)
            .collect::<Vec<_>>()
    };
    let (purple, white) = (dashed(palette::PURPLE), dashed(Vec3::ONE));
    assert!(purple.len() >= 64 && purple.len() == white.len(), "{} and {}", purple.len(), white.len());
    for (p, w) in purple.iter().zip(&white) {
        assert!(p.depth_bias >= ON_TOP && w.depth_bias >= ON_TOP);
        assert!(w.width_px >= p.width_px + 2.0 && p.a == w.a, "{} over {}", p.width_px, w.width_px);
    }
}

/// Exercises 15.2 to 15.4 in the density figure: the reference passes, a wrong answer is named.
#[test]
fn the_density_figure_checks_the_students_exercises() {
    use inbetween::exercises::run::{direct, Failure};
    let mut fig = DensityFigure::new();
    fig.set_probe(0.818, 0.2).unwrap();
    let reference = fig.forces();
    fig.set_runner(|name, args| match name {
        "sph_density" | "pressure_force" | "pbf_lambda" => {
            let mut out = direct(name, args);
            if let Ok(v) = &mut out {
                for x in v.iter_mut() {
                    *x *= 1.1;
                }
            }
            if name == "pbf_lambda" {
                return Err(Failure::NotDone);
            }
            out.or_else(|_| {
                // The stubs: answer with the reference, scaled, so that the note says "differs".
                let mut f = DensityFigure::new();
                f.set_probe(0.818, 0.2).unwrap();
                let r = f.forces();
                Ok(match name {
                    "sph_density" => vec![1.1 * r.density],
                    _ => vec![1.1 * r.force.x / 23.0, 1.1 * r.force.y / 23.0],
                })
            })
        }
        _ => direct(name, args),
    });
    fig.set_use_exercise(true);
    let note = fig.draw(&mut Frame::default());
    assert!(note.contains("Your sph_density differs"), "{note}");
    assert!(
        note.contains("Not done yet: exercise 15.4 pbf_lambda"),
        "{note}"
    );
    // What is drawn is the student's density; λ falls back to the reference.
    assert!((fig.probe().0 / reference.density - 1.1).abs() < 1e-3);
    assert_eq!(fig.forces().lambda, reference.lambda);
    fig.set_use_exercise(false);
    assert_eq!(fig.forces(), reference);
}

#[test]
fn the_density_note_gives_each_exercise_a_line_of_its_own() {
    // The stubs of a plain build: 15.2 to 15.4 not done. The note's first line is the probe's
    // numbers, then one line an exercise (the page keeps the note's line breaks), not one
    // paragraph that runs the three together.
    use inbetween::exercises::run::{direct, Failure};
    let mut fig = DensityFigure::new();
    fig.set_runner(|name, args| match name {
        "sph_density" | "pressure_force" | "pbf_lambda" => Err(Failure::NotDone),
        _ => direct(name, args),
    });
    fig.set_use_exercise(true);
    let note = fig.draw(&mut Frame::default());
    let lines: Vec<&str> = note.lines().collect();
    assert_eq!(lines.len(), 4, "{note}");
    assert!(lines[0].starts_with("ρ = ") && !lines[0].contains("Not done"), "{note}");
    for (line, exercise) in lines[1..].iter().zip(["15.2 sph_density", "15.3 pressure_force", "15.4 pbf_lambda"]) {
        assert!(line.starts_with(&format!("Not done yet: exercise {exercise} (")), "{note}");
        assert!(line.ends_with("The figure uses the reference."), "{note}");
    }
    // Out of the water, 15.3's sum has no pairs: the note says it was not called (a sum of no
    // pairs is zero whatever the exercise does, and would "match the reference").
    fig.set_probe(0.8, 0.9).unwrap();
    assert_eq!(fig.probe().1, 0);
    let note = fig.draw(&mut Frame::default());
    assert_eq!(
        note.lines().nth(2),
        Some("Exercise 15.3 pressure_force is not called: the dragged particle has no neighbours."),
        "{note}"
    );
    // Off: the probe's line alone.
    fig.set_use_exercise(false);
    assert_eq!(fig.draw(&mut Frame::default()).lines().count(), 1);
}

#[test]
fn the_kernel_figure_draws_the_students_poly6_and_says_where_it_differs() {
    use inbetween::exercises::run::direct;
    let mut fig = KernelsFigure::new();
    // Off: no curve, no note.
    let (yours, note) = fig.exercise(101).unwrap();
    assert!(yours.is_none() && note.is_empty());
    // A kernel that goes negative beyond h (no clamp): the note names where.
    fig.set_runner(|name, args| match name {
        "poly6" => {
            let (r2, h) = (args[0], args[1]);
            let d = h * h - r2;
            Ok(vec![4.0 / (std::f32::consts::PI * h.powi(8)) * d * d * d])
        }
        _ => direct(name, args),
    });
    fig.set_use_exercise(true);
    let (yours, note) = fig.exercise(101).unwrap();
    let yours = yours.unwrap();
    assert!(
        note.starts_with("Your poly6 differs at r = 0.125"),
        "{note}"
    );
    assert!((yours[0] - 1.0).abs() < 1e-5 && yours[100] < 0.0);
    // The right kernel matches at every sample; 3D says the exercise is 2D.
    fig.set_runner(|name, args| match name {
        "poly6" => Ok(vec![inbetween::fluid::kernels::poly6(
            args[0],
            args[1],
            inbetween::fluid::Dim::Two,
        )]),
        _ => direct(name, args),
    });
    let (_, note) = fig.exercise(101).unwrap();
    assert!(
        note.starts_with("Your poly6 matches the reference at all 101"),
        "{note}"
    );
    fig.set(0.1, 3).unwrap();
    let (yours, note) = fig.exercise(101).unwrap();
    assert!(yours.is_none() && note.contains("2D"), "{note}");
}

/// Figure 3's numbers in lesson 15's text: the squeeze at the defaults, where SPH's step stops
/// being stable, what stiffness does, and which fluid settles.
#[test]
fn the_dam_break_figure_shows_what_the_lesson_says() {
    // Per column of the plot rows: the peak over the run, and the 10th and 90th percentiles and
    // the largest value once the water has landed (after 0.5 s).
    struct Run {
        rows: Vec<[f32; 5]>,
        exploded: Option<f32>,
    }
    impl Run {
        fn landed(&self, c: usize) -> Vec<f32> {
            let mut v: Vec<f32> = self
                .rows
                .iter()
                .filter(|r| r[0] > 0.5 && r[c].is_finite())
                .map(|r| r[c])
                .collect();
            v.sort_by(f32::total_cmp);
            v
        }
        fn peak(&self, c: usize) -> f32 {
            self.rows
                .iter()
                .map(|r| r[c])
                .filter(|v| v.is_finite())
                .fold(f32::MIN, f32::max)
        }
        fn p10_p90(&self, c: usize) -> (f32, f32) {
            let v = self.landed(c);
            (v[v.len() / 10], v[v.len() * 9 / 10])
        }
    }
    let run = |k: f32, dt: f32, until: f32| {
        let mut fig = DamBreakFigure::new();
        fig.set_sph(k, dt).unwrap();
        fig.advance_to(until).unwrap();
        Run {
            rows: fig.plot_rows().to_vec(),
            exploded: fig.fluids()[0].exploded().map(|e| e.0),
        }
    };
    // The text's rule of thumb: Δt ≤ 0.4 h / c with h = 7 cm and c = √400 = 20 m/s, 1.4 ms.
    let fig = DamBreakFigure::new();
    let h = fig.fluids()[0].params.h;
    assert!((h - 0.070).abs() < 0.0005, "{h}");
    assert!((0.4 * h / 400f32.sqrt() * 1000.0 - 1.4).abs() < 0.05);
    // The five runs below are independent: each on its own thread, so the test takes about as
    // long as its longest run where a second core is free.
    let [defaults, double, fast, stiff, soft] = std::thread::scope(|s| {
        [
            (400.0, 1.0 / 1200.0, 4.0),
            (400.0, 1.0 / 600.0, 2.5),
            (400.0, 1.0 / 400.0, 2.5),
            (1600.0, 1.0 / 1200.0, 2.5),
            (100.0, 1.0 / 1200.0, 4.0),
        ]
        .map(|(k, dt, until)| s.spawn(move || run(k, dt, until)))
        .map(|h| h.join().unwrap())
    });
    // Defaults (k = 400, 0.83 ms): once landed, SPH's densest particle 10 to 15 % over ρ₀ with
    // spikes near 19 %; PBF's within about 2 %, about 5 % at most (at the impact).
    assert!(defaults.exploded.is_none());
    let (lo, hi) = defaults.p10_p90(1);
    assert!(
        (0.085..0.11).contains(&lo) && (0.13..0.16).contains(&hi),
        "SPH {lo} {hi}"
    );
    let sph = defaults.peak(1);
    assert!((0.17..0.21).contains(&sph), "{sph}");
    let (_, pbf_hi) = defaults.p10_p90(2);
    assert!(pbf_hi < 0.022, "PBF {pbf_hi}");
    let pbf = defaults.peak(2);
    assert!((0.045..0.06).contains(&pbf), "{pbf}");
    // From 2 s on SPH keeps over 100 J per metre of depth; PBF less than a third of SPH's.
    let late: Vec<_> = defaults.rows.iter().filter(|r| r[0] >= 2.0).collect();
    let sph_least = late.iter().map(|r| r[3]).fold(f32::MAX, f32::min);
    let ratio = late.iter().map(|r| r[4] / r[3]).fold(0.0f32, f32::max);
    assert!(
        sph_least > 100.0 && ratio < 0.33,
        "{sph_least} J, PBF/SPH up to {ratio}"
    );
    // 1.67 ms runs with about the same squeeze; 2.5 ms explodes within about half a second.
    assert!(double.exploded.is_none() && (double.peak(1) - sph).abs() < 0.03);
    let (lo2, hi2) = double.p10_p90(1);
    assert!(
        (lo2 - lo).abs() < 0.02 && (hi2 - hi).abs() < 0.02,
        "{lo2} {hi2}"
    );
    let gone = fast.exploded;
    assert!(gone.is_some_and(|t| (0.3..0.8).contains(&t)), "{gone:?}");
    // Stiffer at the default step explodes; softer calms down (its energy after 2 s stays under
    // a quarter of the default's least), a third squeezed at the impact and about 15 % after.
    assert!(stiff.exploded.is_some());
    assert!(soft.exploded.is_none() && (0.29..0.37).contains(&soft.peak(1)));
    let (slo, shi) = soft.p10_p90(1);
    assert!(slo > 0.11 && shi < 0.19, "{slo} {shi}");
    let soft_most = soft
        .rows
        .iter()
        .filter(|r| r[0] >= 2.0)
        .map(|r| r[3])
        .fold(0.0f32, f32::max);
    assert!(soft_most < 0.25 * sph_least, "{soft_most} J");
}

/// Figure 1's note gives the peaks the plot's shares are shares of: doubling h divides W(0) by
/// 4 in 2D and by 8 in 3D (the lesson's "Try this").
#[test]
fn the_kernel_figure_says_its_peaks_and_how_they_scale_with_h() {
    let mut fig = KernelsFigure::new();
    assert_eq!(fig.peaks()[0].round(), 127.0);
    assert!(
        fig.peaks_note()
            == "Peaks at h = 10.0 cm in 2D: poly6 W(0) = 127 1/m², spiky W(0) = 318 1/m².",
        "{}",
        fig.peaks_note()
    );
    fig.set(0.2, 2).unwrap();
    assert!((fig.peaks()[0] - 31.83).abs() < 0.01);
    assert!(
        fig.peaks_note().contains("poly6 W(0) = 31.8 1/m²"),
        "{}",
        fig.peaks_note()
    );
    fig.set(0.1, 3).unwrap();
    let p3 = fig.peaks();
    fig.set(0.2, 3).unwrap();
    assert!(
        (p3[0] / fig.peaks()[0] - 8.0).abs() < 1e-3 && (p3[1] / fig.peaks()[1] - 8.0).abs() < 1e-3
    );
    assert!(
        fig.peaks_note().contains("in 3D") && fig.peaks_note().contains("1/m³, spiky"),
        "{}",
        fig.peaks_note()
    );
}

use inbetween::figures::fluid::{
    SplashFigure, SPLASH_DURATION_SEC, SPLASH_STEPS_PER_CALL, SPLASH_STEP_BUDGET,
};

#[test]
fn the_splash_steps_a_few_steps_a_call_and_replays_when_the_time_goes_back() {
    let mut fig = SplashFigure::new();
    // Far ahead: at most a few steps a call, and the fluid catches up over the calls.
    let per_call = (SPLASH_STEP_BUDGET / fig.fluid().len()).min(SPLASH_STEPS_PER_CALL);
    assert_eq!(fig.advance_to(0.5).unwrap(), per_call);
    let mut calls = 1;
    while fig.advance_to(0.5).unwrap() > 0 {
        calls += 1;
    }
    let per_call = (SPLASH_STEP_BUDGET / fig.fluid().len()).min(SPLASH_STEPS_PER_CALL);
    assert_eq!(calls, 120usize.div_ceil(per_call));
    // Many particles: fewer steps a call; all pairs: one.
    fig.set("PBF", 10_000.0, "grid", 0.0).unwrap();
    assert_eq!(fig.advance_to(0.5).unwrap(), 1);
    fig.set("PBF", 4000.0, "all pairs", 0.0).unwrap();
    assert_eq!(fig.advance_to(0.5).unwrap(), 1);
    // The lesson's "Try this": 4,000 asked for, 3,771 in the lattice, 14 million tests a step.
    assert_eq!(fig.fluid().len(), 3771);
    assert_eq!((fig.fluid().len().pow(2) as f32 / 1e6).round(), 14.0);
    fig.set("PBF", 3000.0, "grid", 0.0).unwrap();
    while fig.advance_to(0.5).unwrap() > 0 {}
    // The same time again takes no step (the fluid may be up to half a step past it).
    assert_eq!(fig.advance_to(0.5).unwrap(), 0);
    let there = fig.fluid().positions.clone();
    // Back in time: the run starts over, and reaches the same state bit for bit.
    fig.advance_to(0.1).unwrap();
    while fig.advance_to(0.5).unwrap() > 0 {}
    assert_eq!(fig.fluid().positions, there);
    assert!(fig.advance_to(SPLASH_DURATION_SEC + 1.0).is_err());
    // Bad settings change nothing.
    let before = fig.fluid().len();
    for bad in [
        fig.set("FLIP", 3000.0, "grid", 0.0),
        fig.set("PBF", 3000.5, "grid", 0.0),
        fig.set("PBF", 1e9, "grid", 0.0),
        fig.set("PBF", 3000.0, "octree", 0.0),
        fig.set("PBF", 3000.0, "grid", f32::NAN),
        fig.set("PBF", 8000.0, "all pairs", 0.0),
    ] {
        assert!(bad.is_err());
    }
    assert_eq!(fig.fluid().len(), before);
    let note = fig.draw(&mut Frame::default());
    assert!(
        note.starts_with("PBF, 2584 particles, neighbours from the grid"),
        "{note}"
    );
}

/// The splash's lattice holds up to about a quarter fewer particles than the slider asks for (the
/// caption; the note gives the count).
#[test]
fn the_splash_holds_up_to_about_a_quarter_fewer_particles_than_asked_for() {
    let mut fig = SplashFigure::new();
    let mut fewest = 1.0f32;
    for asked in (500..=10_000).step_by(500) {
        fig.set("PBF", asked as f32, "grid", 0.0).unwrap();
        let share = fig.fluid().len() as f32 / asked as f32;
        assert!(share <= 1.0, "{asked}: {}", fig.fluid().len());
        fewest = fewest.min(share);
    }
    assert!((0.74..0.8).contains(&fewest), "{fewest}");
}

/// Vorticity confinement gives back motion that PBF's damping takes: the splash keeps more
/// kinetic energy with it than without (a sign error in the curl makes it damp instead).
#[test]
fn vorticity_confinement_keeps_the_splash_moving() {
    let energy = |eps: f32| {
        let mut fig = SplashFigure::new();
        fig.set("PBF", 1000.0, "grid", eps).unwrap();
        while fig.advance_to(1.5).unwrap() > 0 {}
        assert!(fig.fluid().exploded().is_none());
        fig.fluid().stats().kinetic
    };
    let (without, with) = (energy(0.0), energy(0.2));
    assert!(with > 1.03 * without, "{with} J with, {without} J without");
}

#[test]
fn the_step_time_sweep_times_the_grid_and_all_pairs_in_turn() {
    let mut fig = SplashFigure::new();
    let mut seen = Vec::new();
    while let Some(search) = fig.next_sweep_timing().unwrap() {
        fig.timing_step(search).unwrap();
        // Synthetic timings: N / 1000 ms for the grid, N² / 10⁶ ms for all pairs.
        seen.push(search);
        let size = [250.0f32, 500.0, 1000.0, 2000.0, 4000.0, 8000.0][seen.len().div_ceil(10) - 1];
        let ms = if search == "grid" {
            size / 1000.0
        } else {
            size * size / 1e6
        };
        fig.record_sweep(ms).unwrap();
    }
    // The all-pairs search stops once a median passed the limit (60 ms at N = 8000 is 64).
    assert!(seen.iter().filter(|s| **s == "grid").count() == 30);
    let note = fig.sweep().note();
    assert!(
        note.contains("all-pairs slope 2.0") && note.contains("grid slope 1.0"),
        "{note}"
    );
}

/// How far the splash has got, which the page's timeline keeps at most a quarter of a second
/// ahead of: the CPU fluid's time while it runs, the GPU's clock in GPU mode, and the timeline's
/// end once the fluid has stopped (an exploded fluid must not hold the timeline back for ever).
#[test]
fn the_splash_says_how_far_it_has_got_and_the_end_once_it_has_stopped() {
    let mut fig = SplashFigure::new();
    assert_eq!(fig.ready_sec(), 0.0);
    fig.set("PBF", 8000.0, "grid", 0.0).unwrap();
    // One step a call at 8,000 particles: far behind a timeline at 1 s.
    fig.advance_to(1.0).unwrap();
    fig.advance_to(1.0).unwrap();
    let dt = fig.fluid().params.dt;
    assert!((fig.ready_sec() - 2.0 * dt).abs() < 1e-6, "{}", fig.ready_sec());
    assert_eq!(fig.ready_sec(), fig.fluid().time);
    // GPU mode: the GPU's clock, whatever the CPU fluid did.
    fig.set_gpu(3000.0).unwrap();
    assert_eq!(fig.ready_sec(), 0.0);
    fig.plan_gpu_steps(0.5, true).unwrap();
    assert!(fig.gpu_time() > 0.0);
    assert_eq!(fig.ready_sec(), fig.gpu_time());
    // Stopped: the end of the timeline.
    let t = fig.gpu_time();
    fig.record_gpu_fastest(t, f32::INFINITY).unwrap();
    assert!(fig.gpu_exploded().is_some());
    assert_eq!(fig.ready_sec(), SPLASH_DURATION_SEC);
}

mod splash_on_the_gpu {
    use inbetween::draw::Frame;
    use inbetween::figures::fluid::{
        SplashFigure, SPLASH_GPU_REPEATS, SPLASH_GPU_STEPS_PER_CALL, SPLASH_GPU_TIMING_STEPS,
        SPLASH_SWEEP_SIZES,
    };
    use inbetween::figures::gpu::MAX_GPU_FLUID_PARTICLES;

    #[test]
    fn a_gpu_count_out_of_range_changes_nothing() {
        let mut fig = SplashFigure::new();
        fig.set_gpu(2000.0).unwrap();
        let n = fig.gpu_start().unwrap().len();
        for bad in [
            f32::NAN,
            1e38,
            -500.0,
            499.0,
            1500.5,
            (MAX_GPU_FLUID_PARTICLES + 1) as f32,
        ] {
            let e = fig.set_gpu(bad).unwrap_err();
            assert!(e.contains("1048576"), "{bad}: {e}");
            assert!(fig.gpu_mode());
            assert_eq!(fig.gpu_start().unwrap().len(), n, "{bad}");
        }
        // 0 goes back to the CPU.
        fig.set_gpu(0.0).unwrap();
        assert!(!fig.gpu_mode() && fig.gpu_start().is_none());
        assert!(fig.plan_gpu_steps(0.1, true).is_err());
    }

    #[test]
    fn the_gpu_start_follows_the_solver_and_holds_a_million() {
        let mut fig = SplashFigure::new();
        fig.set_gpu(1_000_000.0).unwrap();
        let f = fig.gpu_start().unwrap();
        assert!(
            f.len() > 700_000 && f.len() <= MAX_GPU_FLUID_PARTICLES,
            "{}",
            f.len()
        );
        assert_eq!(f.params.method, inbetween::fluid::Method::Pbf);
        fig.set("SPH", 3000.0, "grid", 0.0).unwrap();
        let f = fig.gpu_start().unwrap();
        assert_eq!(f.params.method, inbetween::fluid::Method::Sph);
        assert!(f.len() > 700_000);
        // The CPU fluid keeps the slider's count.
        assert!(fig.fluid().len() <= 3000);
    }

    #[test]
    fn gpu_steps_wait_for_the_gpu_and_a_jump_back_starts_over() {
        let mut fig = SplashFigure::new();
        fig.set_gpu(3000.0).unwrap();
        let dt = fig.gpu_start().unwrap().params.dt;
        // A busy GPU gets no more steps; an idle one a few, towards the time.
        assert_eq!(fig.plan_gpu_steps(0.5, false).unwrap(), (false, 0));
        assert_eq!(
            fig.plan_gpu_steps(0.5, true).unwrap(),
            (false, SPLASH_GPU_STEPS_PER_CALL)
        );
        assert!((fig.gpu_time() - SPLASH_GPU_STEPS_PER_CALL as f32 * dt).abs() < 1e-6);
        assert_eq!(fig.plan_gpu_steps(2.0 * dt, true).unwrap(), (true, 2));
        assert!(fig.plan_gpu_steps(f32::NAN, true).is_err());
        // A million particles: one step a call.
        fig.set_gpu(1_000_000.0).unwrap();
        assert_eq!(fig.plan_gpu_steps(0.5, true).unwrap(), (false, 1));
        let mut frame = Frame::default();
        let note = fig.draw_gpu(&mut frame);
        assert!(
            note.contains("on the GPU") && note.contains("GPU grid"),
            "{note}"
        );
        assert!(
            frame.points.is_empty(),
            "the particles are the GPU's sprites"
        );
    }

    /// The GPU's fluid gets the CPU's explosion verdict from the readback of its fastest
    /// particle: past the limit it stops queueing steps and the note says why, in the CPU's
    /// words; below it the note gives the speed; a restart clears the verdict.
    #[test]
    fn a_gpu_fluid_whose_fastest_particle_is_too_fast_stops_as_the_cpus_does() {
        use inbetween::fluid::{explosion_speed, explosion_verdict};
        let mut fig = SplashFigure::new();
        fig.set("SPH", 3000.0, "grid", 0.0).unwrap();
        assert!(fig.record_gpu_fastest(0.0, 1.0).is_err(), "GPU mode is off");
        fig.set_gpu(3000.0).unwrap();
        let params = fig.gpu_start().unwrap().params.clone();
        let limit = explosion_speed(&params);
        let (_, steps) = fig.plan_gpu_steps(0.5, true).unwrap();
        assert!(steps > 0);
        let t = fig.gpu_time();
        // Below the limit: the note gives the speed, and the steps go on.
        fig.record_gpu_fastest(t, 1.25).unwrap();
        let note = fig.draw_gpu(&mut Frame::default());
        assert!(note.contains("Fastest particle 1.250 m/s"), "{note}");
        assert!(fig.gpu_exploded().is_none());
        assert!(fig.plan_gpu_steps(0.5, true).unwrap().1 > 0);
        // A readback from later than the clock (before a restart) is ignored; bad times are
        // rejected.
        fig.record_gpu_fastest(fig.gpu_time() + 1.0, 2.0 * limit)
            .unwrap();
        assert!(fig.gpu_exploded().is_none());
        assert!(fig.record_gpu_fastest(f32::NAN, 1.0).is_err());
        // Past the limit: stopped, in the CPU's words, and no more steps.
        let t = fig.gpu_time();
        fig.record_gpu_fastest(t, 2.0 * limit).unwrap();
        let why = explosion_verdict(&params, 2.0 * limit).unwrap();
        assert_eq!(fig.gpu_exploded(), Some((t, why.as_str())));
        let note = fig.draw_gpu(&mut Frame::default());
        assert!(
            note.starts_with("SPH on the GPU stopped at t = ") && note.contains(&why),
            "{note}"
        );
        assert_eq!(fig.plan_gpu_steps(1.0, true).unwrap(), (false, 0));
        assert_eq!(fig.gpu_time(), t, "its clock stays where it stopped");
        // A later readback changes nothing; a NaN is "not a number".
        fig.record_gpu_fastest(t, 0.5).unwrap();
        assert!(fig.gpu_exploded().is_some());
        // Back in time starts over, without the verdict.
        assert!(fig.plan_gpu_steps(0.0, true).unwrap().0);
        assert!(fig.gpu_exploded().is_none());
        fig.record_gpu_fastest(0.0, f32::INFINITY).unwrap();
        let (_, why) = fig.gpu_exploded().unwrap();
        assert!(why.contains("stopped being a number"), "{why}");
        // A new count, solver or ε starts over too.
        fig.set_gpu(2000.0).unwrap();
        assert!(fig.gpu_exploded().is_none());
    }

    #[test]
    fn the_sweep_times_the_gpu_grid_after_the_cpu() {
        let mut fig = SplashFigure::new();
        assert_eq!(fig.next_gpu_timing(), None, "not asked for");
        fig.set_gpu_sweep(true);
        assert_eq!(fig.next_gpu_timing(), None, "the CPU's timings first");
        assert!(fig.record_gpu_sweep(1.0).is_err());
        while let Some(search) = fig.next_sweep_timing().unwrap() {
            fig.timing_step(search).unwrap();
            fig.record_sweep(if search == "grid" { 1.0 } else { 4.0 })
                .unwrap();
        }
        let mut sizes = Vec::new();
        while let Some(n) = fig.next_gpu_timing() {
            sizes.push(n);
            fig.record_gpu_sweep(n as f32 / 8000.0).unwrap();
        }
        assert_eq!(sizes.len(), SPLASH_SWEEP_SIZES.len() * SPLASH_GPU_REPEATS);
        let rows = fig.sweep_samples();
        assert_eq!(rows.len(), 12 * SPLASH_SWEEP_SIZES.len());
        for (row, n) in rows.chunks_exact(12).zip(SPLASH_SWEEP_SIZES) {
            assert_eq!(row[0], n as f32);
            assert_eq!(row[9..12], [n as f32 / 8000.0; 3]);
        }
        let note = fig.sweep_note();
        assert!(
            note.contains("GPU grid") && note.contains("1.00 ms"),
            "{note}"
        );
        // A GPU grid slower than the CPU's reads as the GPU being slow: the note says the
        // times depend on the adapter, and that a software one can be slower than the CPU.
        assert!(
            note.contains("depend on the adapter") && note.contains("slower than the CPU grid"),
            "{note}"
        );
        // Figure 5's caption: the median of three timings of four steps queued at once.
        assert_eq!((SPLASH_GPU_REPEATS, SPLASH_GPU_TIMING_STEPS), (3, 4));
    }
}

/// Figures 2 and 3 colour a particle by its density as their captions say: water blue at ρ₀,
/// paler below (pale blue at half of ρ₀), red above (full red at 25 % over); at rest the
/// particles stand out from the canvas's light background (a light grey at ρ₀ did not).
#[test]
fn particles_at_rest_are_water_blue_paler_below_and_red_above() {
    use inbetween::draw::palette;
    use inbetween::figures::fluid::{density_color, THIN_WATER, WATER};
    assert_eq!(density_color(1.0), palette::BLUE);
    assert_eq!(WATER, palette::BLUE);
    assert_eq!(density_color(0.5), THIN_WATER);
    assert_eq!(density_color(0.0), THIN_WATER);
    assert_eq!(density_color(1.25), palette::RED);
    assert_eq!(density_color(2.0), palette::RED);
    assert_eq!(density_color(f32::NAN), palette::RED);
    // Relative luminance (linear light): the background's light grey against water at rest and
    // at half its density. WCAG's contrast ratio, (L1 + 0.05) / (L2 + 0.05).
    let lum = |c: glam::Vec3| 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
    let contrast =
        |a: glam::Vec3, b: glam::Vec3| (lum(a).max(lum(b)) + 0.05) / (lum(a).min(lum(b)) + 0.05);
    let background = glam::Vec3::splat(0.91); // #f5f5f5, lighter than the canvas's clear colour
    assert!(
        contrast(background, WATER) > 3.0,
        "{}",
        contrast(background, WATER)
    );
    assert!(
        contrast(background, THIN_WATER) > 1.4,
        "{}",
        contrast(background, THIN_WATER)
    );
    // Blue stays blue: more blue than red or green from half of ρ₀ up to 10 % over (PBF's
    // densest particles), and redder than blue from 15 % over (SPH's squeeze).
    for ratio in [0.5, 0.8, 1.0, 1.05, 1.1] {
        let c = density_color(ratio);
        assert!(c.z > c.x && c.z > c.y, "{ratio}: {c}");
    }
    let c = density_color(1.15);
    assert!(c.x > c.z, "{c}");
    // Denser is redder, thinner is paler, without a jump.
    let mut last = density_color(0.4);
    for k in 1..=100 {
        let c = density_color(0.4 + 0.9 * k as f32 / 100.0);
        assert!((c - last).abs().max_element() < 0.05, "{c} after {last}");
        last = c;
    }
}

/// Figure 4's "Try this": on the grid, a particle of the 3,771-particle splash tests "the couple
/// of hundred" particles of its 27 cells (cells one kernel radius wide, 2 spacings: 8 particles
/// a cell in the water), against 3,771 with all pairs.
#[test]
fn a_splash_particle_on_the_grid_tests_a_couple_of_hundred_candidates() {
    let mut fig = SplashFigure::new();
    fig.set("PBF", 4000.0, "grid", 0.0).unwrap();
    let f = fig.fluid();
    assert_eq!(f.len(), 3771);
    let h = f.params.h;
    let cell = |p: glam::Vec3| (p / h).floor().as_ivec3();
    let cells: Vec<_> = f.positions.iter().map(|&p| cell(p)).collect();
    // The pool's particles away from its walls and surface: a full block of 27 cells.
    let size = inbetween::fluid::box_size(inbetween::fluid::Dim::Three);
    let inner: Vec<usize> = (0..f.len())
        .filter(|&i| {
            let p = f.positions[i];
            p.cmpgt(glam::Vec3::splat(1.5 * h)).all()
                && p.x < size.x - 1.5 * h
                && p.z < size.z - 1.5 * h
                && p.y < 0.3 * size.y - 1.5 * h
        })
        .collect();
    assert!(inner.len() > 100, "{}", inner.len());
    let mean = inner
        .iter()
        .map(|&i| {
            cells
                .iter()
                .filter(|c| (**c - cells[i]).abs().max_element() <= 1)
                .count()
        })
        .sum::<usize>() as f32
        / inner.len() as f32;
    assert!((150.0..300.0).contains(&mean), "{mean} candidates");
}

/// Figure 3's caption: once the water has landed, a few of SPH's particles, the most squeezed
/// (8 % over ρ₀ and more: half-way from blue to red at 12.5 %), show purple; none of PBF's.
#[test]
fn sph_squeezed_particles_turn_purple_and_pbf_stays_blue() {
    use inbetween::figures::fluid::density_color;
    let mut fig = DamBreakFigure::new();
    let mut counts = Vec::new();
    for t in [1.0, 1.5, 2.0, 3.0] {
        fig.advance_to(t).unwrap();
        let purple = |f: &inbetween::fluid::Fluid| {
            let rho0 = f.params.rest_density;
            let colors: Vec<_> = f
                .densities
                .iter()
                .map(|&rho| density_color(rho / rho0))
                .collect();
            (
                colors.iter().filter(|c| c.x > 0.5 * c.z).count(),
                colors.iter().all(|c| c.z > c.x),
            )
        };
        let [sph, pbf] = fig.fluids();
        counts.push((t, purple(sph), purple(pbf)));
    }
    for (t, (sph_purple, _), (pbf_purple, pbf_blue)) in counts {
        assert!(sph_purple >= 3, "{t} s: {sph_purple} SPH particles purple");
        assert!(
            pbf_purple == 0 && pbf_blue,
            "{t} s: {pbf_purple} PBF particles purple"
        );
    }
}

#[test]
fn the_dragged_particles_lines_and_arrows_lie_over_the_water() {
    // In the pool the particles surround the dragged one: its lines to its neighbours and its
    // two arrows are drawn over them (else they are lost among the dots), the lines at least
    // 1.5 px wide.
    use glam::Vec3;
    use inbetween::draw::{palette, ON_TOP};
    let f = DensityFigure::new();
    let mut frame = Frame::default();
    f.draw(&mut frame);
    let of = |color: Vec3| {
        frame
            .strokes
            .iter()
            .filter(move |s| Vec3::from_slice(&s.color) == color)
            .collect::<Vec<_>>()
    };
    let lines: Vec<_> = of(palette::PURPLE)
        .into_iter()
        .filter(|s| s.dash[3] == 0.0)
        .collect();
    assert!(lines.len() > 5, "{} lines to neighbours", lines.len());
    assert!(lines.iter().all(|s| s.depth_bias >= ON_TOP && s.width_px >= 1.5));
    for color in [palette::TEAL, palette::ORANGE] {
        let arrow = of(color);
        assert!(!arrow.is_empty() && arrow.iter().all(|s| s.depth_bias >= ON_TOP), "{color}");
    }
}

#[test]
fn the_dam_break_seen_from_the_side_adds_a_view_from_the_front() {
    // The two tanks are slabs facing +z: orbited to the side or over the top they are seen
    // edge-on, one behind the other. Then (more than 60° from face-on) the frame has an inset
    // from the front that holds both tanks; at the page's camera it has none.
    use inbetween::camera::OrbitCamera;
    use inbetween::draw::inset::{inset_camera, InsetView};
    use inbetween::fluid::box_size;
    use inbetween::fluid::kernels::Dim;
    let mut fig = DamBreakFigure::new();
    fig.advance_to(0.5).unwrap();
    let mut drawn = |view: [f32; 6]| {
        fig.set_view(OrbitCamera::from_view(view));
        let mut frame = Frame::default();
        fig.draw(&mut frame);
        frame
    };
    assert!(drawn([0.0, 0.55, 0.0, 4.0, 0.0, 0.0]).inset.is_none());
    assert!(drawn([0.0, 0.55, 0.0, 4.0, 0.7, 0.3]).inset.is_none());
    for view in [[0.0, 0.55, 0.0, 4.0, 1.4, 0.2], [0.0, 0.55, 0.0, 4.0, 0.0, 1.3]] {
        let frame = drawn(view);
        let inset = frame.inset.clone().expect("an inset from the front");
        assert_eq!(inset.view, InsetView::Front);
        let (v, p, _) = inset_camera(&inset).unwrap();
        let size = box_size(Dim::Two);
        // Every tank's corner (the points kept in view) and every particle lie inside it.
        for q in frame.keep_in_view.iter().copied().chain(frame.points.iter().map(|q| glam::Vec3::from(q.center))) {
            let ndc = (p * v).project_point3(q);
            assert!(ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0, "{q} at {ndc}, box {size}");
        }
    }
}

#[test]
fn the_pool_is_flat_and_pans_on_a_drag() {
    // Figure 2's 2D pool is seen square-on (lessons/15-fluids/lesson.js): a drag off the dragged
    // particle pans it, keeping the box's floor as wide on the canvas, where an orbit would
    // squeeze the slab. Figure 3's tanks turn (it adds a view from the front when seen edge-on).
    use glam::{Vec2, Vec3};
    use inbetween::fluid::box_size;
    use inbetween::fluid::kernels::Dim;
    let mut frame = Frame::default();
    DensityFigure::new().draw(&mut frame);
    let mut dam = Frame::default();
    DamBreakFigure::new().draw(&mut dam);
    assert!(!dam.flat, "Figure 3 turns");
    // The page's camera (lessons/15-fluids/lesson.js); the box's floor.
    let floor = [Vec3::ZERO, Vec3::new(box_size(Dim::Two).x, 0.0, 0.0)];
    flat::assert_drag_pans(&frame, [0.8, 0.5, 0.0, 2.6, 0.0, 0.0], Vec2::new(650.0, 420.0), floor);
}

/// At the dam's release PBF's water falls: its artificial pressure `s_corr`, which pushes the
/// surface layer up at every iteration with nothing pulling it back, stays too weak to lift the
/// top of the column above where it started (within a quarter of a spacing) over the first
/// quarter second.
#[test]
fn the_dam_breaks_pbf_water_falls_instead_of_rising_at_the_release() {
    let mut fig = DamBreakFigure::new();
    let top = |fig: &DamBreakFigure| fig.fluids()[1].positions.iter().map(|p| p.y).fold(f32::MIN, f32::max);
    let (top0, spacing) = (top(&fig), fig.fluids()[1].spacing);
    let mut highest = top0;
    for k in 1..=15 {
        fig.advance_to(k as f32 * DAM_FRAME_SEC).unwrap();
        highest = highest.max(top(&fig));
    }
    assert!(highest - top0 < 0.25 * spacing, "PBF's top rose {} spacings", (highest - top0) / spacing);
    assert!(top(&fig) < top0 - spacing, "PBF's top at 0.25 s: {} m, from {top0} m", top(&fig));
}

/// At the surface (y = 0.4 m) the dragged particle is below ρ₀, so its own pressure is 0, yet
/// SPH pushes it: each pair pushes with (p_i + p_j)/2, and the note says the force is all its
/// neighbours' pressures'. In the middle of the pool, with a pressure of its own, it does not.
#[test]
fn a_surface_particle_with_no_pressure_of_its_own_is_pushed_by_its_neighbours() {
    let mut fig = DensityFigure::new();
    fig.set_probe(0.8, 0.4).unwrap();
    let f = fig.forces();
    assert!(f.pressure == 0.0 && f.force.length() > 1.0, "{} Pa, {} N", f.pressure, f.force.length());
    let note = fig.draw(&mut Frame::default());
    assert!(
        note.contains("SPH: pressure 0") && note.contains("on the particle), all of it from its neighbours' pressures."),
        "{note}"
    );
    let note = DensityFigure::new().draw(&mut Frame::default());
    assert!(!note.contains("neighbours' pressures"), "{note}");
}

/// Figure 3's caption: for the first tenth of a second PBF's column keeps its height (its top
/// within half a spacing of the start), while SPH's sinks by about two spacings, falling
/// almost freely (its top's speed at 0.1 s within 15 % of g t). PBF holds each particle at ρ₀:
/// its column can only come down as it spreads; SPH's pushes back only once squeezed past ρ₀.
/// PBF's top rows (the top two spacings) turn paler: their mean density falls by a fifth.
#[test]
fn for_a_tenth_of_a_second_pbfs_column_keeps_its_height_and_sphs_sinks() {
    let mut fig = DamBreakFigure::new();
    let spacing = fig.fluids()[0].spacing;
    let top = |f: &inbetween::fluid::Fluid| f.positions.iter().map(|p| p.y).fold(f32::MIN, f32::max);
    let top0 = [top(&fig.fluids()[0]), top(&fig.fluids()[1])];
    let top_rows = |f: &inbetween::fluid::Fluid| {
        let (t, rho0) = (top(f), f.params.rest_density);
        let rows: Vec<f32> = f.positions.iter().zip(&f.densities).filter(|(p, _)| p.y > t - 2.0 * spacing).map(|(_, r)| r / rho0).collect();
        rows.iter().sum::<f32>() / rows.len() as f32
    };
    let pale0 = top_rows(&fig.fluids()[1]);
    for k in 1..=6 {
        fig.advance_to(k as f32 * DAM_FRAME_SEC).unwrap();
        let pbf = top(&fig.fluids()[1]) - top0[1];
        assert!(pbf.abs() < 0.5 * spacing, "PBF's top moved {} spacings by frame {k}", pbf / spacing);
    }
    let pale = top_rows(&fig.fluids()[1]);
    assert!(pale < 0.8 * pale0, "PBF's top rows at {pale} of ρ₀, from {pale0}");
    let sph = &fig.fluids()[0];
    let sunk = (top0[0] - top(sph)) / spacing;
    assert!((1.5..2.5).contains(&sunk), "SPH's top sank {sunk} spacings in 0.1 s");
    let highest = sph
        .positions
        .iter()
        .zip(&sph.velocities)
        .max_by(|a, b| a.0.y.total_cmp(&b.0.y))
        .unwrap();
    let free = 9.81 * 6.0 * DAM_FRAME_SEC;
    assert!((-highest.1.y / free - 1.0).abs() < 0.15, "SPH's top falls at {} m/s", highest.1.y);
}

#[test]
fn the_dam_break_orbit_stops_short_of_edge_on() {
    // The tanks are slabs in one plane. From the page's front view (lessons/15-fluids/lesson.js)
    // dragged sideways as the page sweep drags (a fifth of the canvas's width to the left and a
    // tenth of its height down, on its 760 and 920 px canvases) or all the way to the side, the figure's
    // yaw limit keeps each tank at least 0.7 of its front-view width against its height on
    // screen (in clip space: the canvas's aspect is the same for both and cancels).
    use glam::Vec3;
    use inbetween::camera::OrbitCamera;
    use inbetween::figures::fluid::DAM_MAX_YAW_RAD;
    let fig = DamBreakFigure::new();
    let mut frame = Frame::default();
    fig.draw(&mut frame);
    assert_eq!(frame.max_yaw_rad, Some(DAM_MAX_YAW_RAD));
    let size = inbetween::fluid::box_size(inbetween::fluid::Dim::Two);
    // The SPH tank's corners, as the figure places it: left of the middle by half the gap.
    let left = -(size.x + 0.2) * 0.5 - 0.5 * size.x;
    let corners = [
        Vec3::new(left, 0.0, 0.0),
        Vec3::new(left + size.x, 0.0, 0.0),
        Vec3::new(left, size.y, 0.0),
    ];
    let aspect = |camera: &OrbitCamera| {
        let view_proj = camera.projection(760.0 / 420.0) * camera.view();
        let c = corners.map(|p| view_proj.project_point3(p).truncate());
        (c[1] - c[0]).length() / (c[2] - c[0]).length()
    };
    let front = OrbitCamera::from_view([0.0, 0.55, 0.0, 4.0, 0.0, 0.0]);
    for (d_yaw, d_pitch) in [
        (-0.2 * 760.0 * 0.008, 0.1 * 420.0 * 0.008),
        (-0.2 * 920.0 * 0.008, 0.1 * 420.0 * 0.008),
        (std::f32::consts::FRAC_PI_2, 0.0),
        (-std::f32::consts::FRAC_PI_2, 0.0),
        (std::f32::consts::TAU - 0.3, 0.0),
    ] {
        let mut camera = front;
        camera.orbit(d_yaw, d_pitch);
        camera.limit_yaw(frame.max_yaw_rad);
        assert!(
            camera.yaw_rad.abs() <= DAM_MAX_YAW_RAD + 1e-6,
            "{d_yaw}: yaw {}",
            camera.yaw_rad
        );
        let ratio = aspect(&camera) / aspect(&front);
        assert!(
            ratio >= 0.7,
            "orbited by {d_yaw}, {d_pitch}: {ratio} of the front width"
        );
    }
    // A turn of nearly a whole circle is a small turn the other way: it stays as it is.
    let mut camera = front;
    camera.orbit(std::f32::consts::TAU - 0.3, 0.0);
    camera.limit_yaw(frame.max_yaw_rad);
    assert!((camera.yaw_rad + 0.3).abs() < 1e-4, "{}", camera.yaw_rad);
}
