//! The fluids lesson's figure logic (src/figures/fluid.rs).
#![cfg(not(target_arch = "wasm32"))]

use inbetween::draw::Frame;
use inbetween::figures::fluid::{DensityFigure, KernelsFigure};

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
        note.starts_with("SPH: compressed at most") && note.contains("PBF: compressed"),
        "{note}"
    );
    assert_eq!(frame.labels.len(), 2);
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
