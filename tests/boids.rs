//! Lesson 12 core: the boid rules, the force laws, grid vs naive neighbour search.
// Native only (proptest); the browser runs tests/web_cores/particles.rs.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::boids::*;
use proptest::prelude::*;

fn neighbour_sets(positions: &[Vec3], radius: f32, search: Search) -> Vec<Vec<usize>> {
    let mut flock = Flock {
        positions: positions.to_vec(),
        velocities: vec![Vec3::X; positions.len()],
        forces: vec![Vec3::ZERO; positions.len()],
        grid: Grid::default(),
        time_sec: 0.0,
    };
    if search == Search::Grid {
        flock
            .grid
            .configure(Vec3::splat(-4.0), Vec3::splat(4.0), radius);
        flock.grid.rebuild(&flock.positions);
    }
    (0..positions.len())
        .map(|i| {
            let mut set = Vec::new();
            flock.for_each_neighbour(search, i, radius, |j| set.push(j));
            set.sort_unstable();
            set
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::default() })]
    #[test]
    fn grid_and_naive_give_the_same_neighbour_sets(
        // Some positions lie outside the grid's box: the border cells must still be exact.
        positions in prop::collection::vec(prop::array::uniform3(-6.0f32..6.0), 0..150),
        radius in 0.1f32..3.0,
    ) {
        let positions: Vec<Vec3> = positions.into_iter().map(Vec3::from_array).collect();
        prop_assert_eq!(
            neighbour_sets(&positions, radius, Search::Naive),
            neighbour_sets(&positions, radius, Search::Grid)
        );
    }

    /// The grid lists a point's neighbours in cell order, and by index within a cell (the
    /// order the fluid's sums take, so a faster search must keep it).
    #[test]
    fn the_grid_lists_neighbours_in_cell_then_index_order(
        positions in prop::collection::vec(prop::array::uniform3(-6.0f32..6.0), 0..150),
        radius in 0.1f32..3.0,
    ) {
        let positions: Vec<Vec3> = positions.into_iter().map(Vec3::from_array).collect();
        let mut grid = Grid::default();
        grid.configure(Vec3::splat(-4.0), Vec3::splat(4.0), radius);
        grid.rebuild(&positions);
        for i in 0..positions.len() {
            let mut keys = Vec::new();
            grid.for_each_neighbour(&positions, i, radius, |j| {
                keys.push((grid.cell_of_point(positions[j]), j))
            });
            prop_assert!(keys.windows(2).all(|w| w[0] < w[1]), "{:?}", keys);
        }
    }

    /// `append_neighbours` (the fluid's lists) writes the neighbours `for_each_neighbour`
    /// visits, in the same order, after what the list already holds.
    #[test]
    fn append_neighbours_lists_what_for_each_neighbour_visits(
        positions in prop::collection::vec(prop::array::uniform3(-6.0f32..6.0), 0..150),
        radius in 0.1f32..3.0,
    ) {
        let positions: Vec<Vec3> = positions.into_iter().map(Vec3::from_array).collect();
        let mut grid = Grid::default();
        grid.configure(Vec3::splat(-4.0), Vec3::splat(4.0), radius);
        grid.rebuild(&positions);
        let mut appended = vec![7u32];
        let mut visited = vec![7u32];
        for i in 0..positions.len() {
            grid.append_neighbours(&positions, i, radius, &mut appended);
            grid.for_each_neighbour(&positions, i, radius, |j| visited.push(j as u32));
            prop_assert_eq!(&appended, &visited);
        }
    }

    #[test]
    fn cell_index_is_within_the_grid(p in prop::array::uniform3(-100.0f32..100.0)) {
        let dims = [4, 5, 6];
        let c = cell_index(Vec3::from_array(p), Vec3::splat(-2.0), 0.5, dims);
        prop_assert!(c < 4 * 5 * 6);
    }
}

#[test]
fn cell_index_counts_x_first() {
    let dims = [4, 5, 6];
    let o = Vec3::ZERO;
    assert_eq!(cell_index(Vec3::new(0.1, 0.1, 0.1), o, 1.0, dims), 0);
    assert_eq!(cell_index(Vec3::new(1.5, 0.1, 0.1), o, 1.0, dims), 1);
    assert_eq!(cell_index(Vec3::new(0.1, 1.5, 0.1), o, 1.0, dims), 4);
    assert_eq!(cell_index(Vec3::new(0.1, 0.1, 1.5), o, 1.0, dims), 20);
    assert_eq!(
        cell_index(Vec3::new(-5.0, 99.0, 2.5), o, 1.0, dims),
        4 * 4 + 20 * 2
    );
}

#[test]
fn grid_and_naive_steps_agree() {
    let params = BoidParams {
        fov_deg: 240.0,
        ..Default::default()
    };
    let mut a = Flock::new(400, &params, 5).unwrap();
    let mut b = a.clone();
    for _ in 0..30 {
        a.step(&params, Search::Naive, 1.0 / 60.0);
        b.step(&params, Search::Grid, 1.0 / 60.0);
    }
    // Same sets, visited in another order: the sums differ only by rounding.
    let max = a
        .positions
        .iter()
        .zip(&b.positions)
        .map(|(p, q)| (*p - *q).length())
        .fold(0.0, f32::max);
    assert!(max < 1e-3, "{max}");
}

#[test]
fn the_three_rules_for_one_boid() {
    let p = Vec3::ZERO;
    let v = Vec3::X;
    let positions = [Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0)];
    let velocities = [Vec3::Y, Vec3::Y];
    let [c, a, s] = three_rules(p, v, &positions, &velocities);
    assert!((c - Vec3::new(0.5, 1.0, 0.0)).length() < 1e-6);
    assert!((a - Vec3::new(-1.0, 1.0, 0.0)).length() < 1e-6);
    assert!((s - Vec3::new(-1.0, -0.5, 0.0)).length() < 1e-6);
    assert_eq!(three_rules(p, v, &[], &[]), [Vec3::ZERO; 3]);
}

#[test]
fn force_laws_attract_far_and_repel_near() {
    let law = ForceLaw::InversePower { a1: 1.0, a2: 0.25 };
    assert!((law.f(0.5)).abs() < 1e-6, "zero at √(a2/a1)");
    assert!(law.f(0.3) < 0.0 && law.f(1.0) > 0.0);
    let g = ForceLaw::Gaussian {
        a1: 1.0,
        a2: 2.0,
        k: 2.0,
        x0: 1.0,
    };
    assert!(g.f(0.05) < 0.0 && g.f(1.0) > 0.0);
    assert!(g.f(1.0) > g.f(3.0));
}

/// Every boid flies between the minimum and the maximum speed after each step (the flock starts
/// at half the top speed, not above the default minimum), and `clamp_speed` leaves a boid at rest at
/// rest and a speed inside the range untouched.
#[test]
fn speed_stays_between_the_minimum_and_the_maximum() {
    let params = BoidParams::default();
    assert!(
        params.min_speed >= 0.5 * params.max_speed,
        "the start is not above the minimum"
    );
    let mut flock = Flock::new(300, &params, 4).unwrap();
    for _ in 0..120 {
        flock.step(&params, Search::Grid, 1.0 / 60.0);
        for v in &flock.velocities {
            let s = v.length();
            assert!(
                s >= params.min_speed * 0.9999 && s <= params.max_speed * 1.0001,
                "{s}"
            );
        }
    }
    use inbetween::boids::clamp_speed;
    assert_eq!(clamp_speed(Vec3::ZERO, 1.0, 2.0), Vec3::ZERO);
    assert_eq!(clamp_speed(Vec3::X * 1.5, 1.0, 2.0), Vec3::X * 1.5);
    assert!((clamp_speed(Vec3::Y * 0.1, 1.0, 2.0) - Vec3::Y).length() < 1e-6);
    assert!((clamp_speed(Vec3::Z * 5.0, 1.0, 2.0) - Vec3::Z * 2.0).length() < 1e-6);
}

#[test]
fn speed_stays_below_the_maximum_and_boids_stay_near_the_box() {
    let params = BoidParams {
        obstacles: vec![inbetween::particles::Sphere {
            center: Vec3::ZERO,
            radius: 1.0,
        }],
        ..Default::default()
    };
    let mut flock = Flock::new(300, &params, 9).unwrap();
    for _ in 0..600 {
        flock.step(&params, Search::Grid, 1.0 / 60.0);
        for v in &flock.velocities {
            assert!(v.length() <= params.max_speed * 1.0001);
        }
    }
    for p in &flock.positions {
        assert!((p.abs() - params.bounds).max_element() < 2.0, "{p}");
        assert!(p.length() > 0.8, "kept out of the obstacle: {p}");
    }
}

#[test]
fn field_of_view_hides_boids_behind() {
    let params = BoidParams::default();
    let mut flock = Flock::new(2, &params, 1).unwrap();
    flock.positions = vec![Vec3::ZERO, Vec3::new(-1.0, 0.0, 0.0)];
    flock.velocities = vec![Vec3::X, Vec3::X];
    assert!(!flock.sees(0, flock.positions[1], 90.0));
    assert!(flock.sees(0, flock.positions[1], 360.0));
    assert!(flock.sees(1, flock.positions[0], 90.0));
}

#[test]
fn a_predator_scatters_and_a_leader_gathers() {
    let base = BoidParams::default();
    let lead = BoidParams {
        leader: Some(3.0),
        ..base.clone()
    };
    let mut flock = Flock::new(200, &lead, 2).unwrap();
    for _ in 0..600 {
        flock.step(&lead, Search::Grid, 1.0 / 60.0);
    }
    let leader = flock.positions[0];
    let mean = flock.positions[1..]
        .iter()
        .map(|p| (*p - leader).length())
        .sum::<f32>()
        / 199.0;
    assert!(
        mean < 3.0,
        "the flock follows its leader: mean distance {mean}"
    );
    let chase = BoidParams {
        predator: Some((2.0, 8.0)),
        ..base
    };
    let mut flock = Flock::new(200, &chase, 2).unwrap();
    for _ in 0..300 {
        flock.step(&chase, Search::Grid, 1.0 / 60.0);
    }
    let predator = flock.positions[0];
    let near = flock.positions[1..]
        .iter()
        .filter(|p| (**p - predator).length() < 0.5)
        .count();
    assert!(near < 10, "few boids stay near the predator: {near}");
}

#[test]
fn a_seeded_flock_is_reproducible_bit_for_bit() {
    let params = BoidParams::default();
    let run = || {
        let mut f = Flock::new(300, &params, 4).unwrap();
        for _ in 0..60 {
            f.step(&params, Search::Grid, 1.0 / 60.0);
        }
        f.positions
            .iter()
            .flat_map(|p| p.to_array())
            .map(f32::to_bits)
            .collect::<Vec<_>>()
    };
    assert_eq!(run(), run());
}

#[test]
fn bad_input_is_an_error() {
    let params = BoidParams::default();
    assert!(Flock::new(MAX_BOIDS + 1, &params, 0)
        .unwrap_err()
        .contains("too many"));
    let bad = BoidParams {
        fov_deg: 400.0,
        ..params.clone()
    };
    assert!(bad.validate().unwrap_err().contains("field of view"));
    let bad = BoidParams {
        cohesion: Rule {
            weight: f32::NAN,
            radius: 1.0,
        },
        ..params.clone()
    };
    assert!(bad.validate().unwrap_err().contains("cohesion"));
    let bad = BoidParams {
        max_speed: -1.0,
        ..params
    };
    assert!(bad.validate().is_err());
}

/// Lesson 12's numbers for the grid search on the benchmark flock at 100,000 boids (one per m³,
/// radius 1.5 m): about 14 neighbours per boid, about 47 candidates tested (the cells the
/// ball's chords cross), where the full 3 × 3 block of rows, X_SPLIT cells either side of the
/// boid's cell, holds about 65.
#[test]
fn the_grid_tests_about_47_candidates_for_14_neighbours() {
    use inbetween::boids::grid::X_SPLIT;
    let n = 100_000;
    let (params, mut flock) = benchmark_flock(n).unwrap();
    let radius = params.search_radius();
    let (min, max) = (-params.bounds - radius, params.bounds + radius);
    let grid = &mut flock.grid;
    grid.configure(min, max, radius);
    grid.rebuild(&flock.positions);
    let d = ((max - min) / Vec3::new(radius / X_SPLIT as f32, radius, radius)).ceil();
    let [dx, dy, dz] = [d.x as usize, d.y as usize, d.z as usize];
    assert_eq!(grid.cell_count(), dx * dy * dz);
    let (mut neighbours, mut candidates, mut block) = (0, 0, 0);
    for (i, &p) in flock.positions.iter().enumerate() {
        grid.for_each_neighbour(&flock.positions, i, radius, |_| neighbours += 1);
        candidates += grid.candidates(&flock.positions, i, radius);
        let c = grid.cell_of_point(p);
        let (ci, cj, ck) = (c % dx, c / dx % dy, c / (dx * dy));
        let starts = grid.cell_starts();
        for k in ck.saturating_sub(1)..=(ck + 1).min(dz - 1) {
            for j in cj.saturating_sub(1)..=(cj + 1).min(dy - 1) {
                let row = dx * (j + dy * k);
                let (lo, hi) = (ci.saturating_sub(X_SPLIT), (ci + X_SPLIT).min(dx - 1));
                block += (starts[row + hi + 1] - starts[row + lo]) as usize;
            }
        }
    }
    let per_boid = |total: usize| (total as f32 / n as f32).round();
    let seen = [per_boid(neighbours), per_boid(candidates), per_boid(block)];
    assert!(
        (seen[0] - 14.0).abs() <= 0.5 && (seen[1] - 47.0).abs() <= 1.0 && (seen[2] - 65.0).abs() <= 2.0,
        "neighbours, candidates, full block per boid: {seen:?}"
    );
}
