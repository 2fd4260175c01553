//! Exercises for lesson 12, "Boids".
//!
//! Reference solutions: [`crate::boids::three_rules`] and [`crate::boids::cell_index`]. Tick
//! "use my exercise" in the lesson's figures to see yours at work.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::boids;
use glam::Vec3;

/// **Exercise 12.1: the three rules of Reynolds for one boid.**
///
/// A boid at `p` with velocity `v` has `n` neighbours (already chosen for you: within its radius
/// and field of view) at `positions[j]` with velocities `velocities[j]`. Return the three
/// unweighted steering vectors `[cohesion, alignment, separation]`:
/// ```text
/// cohesion   = (1/n) Σ_j positions[j] − p              towards the neighbours' centre
/// alignment  = (1/n) Σ_j velocities[j] − v             towards their mean velocity
/// separation = Σ_j (p − positions[j]) / |p − positions[j]|²   away from each, harder when closer
/// ```
/// With no neighbours all three are zero. Skip a neighbour at exactly `p` in the separation sum
/// (its direction is undefined).
///
/// Hints: one loop accumulating three sums; `Vec3::length_squared`. The lesson's flock weights
/// these three vectors and adds them.
pub fn three_rules(p: Vec3, v: Vec3, positions: &[Vec3], velocities: &[Vec3]) -> Answer<[Vec3; 3]> {
    solution!(boids::three_rules(p, v, positions, velocities));
    let _ = (p, v, positions, velocities);
    Err(NotDone)
}

/// **Exercise 12.2: the grid cell of a position.**
///
/// A uniform grid starts at `origin` (the corner of cell `(0, 0, 0)`), has cubic cells of side
/// `cell_size` metres and `dims = [nx, ny, nz]` cells along x, y and z. Return the index of the
/// cell holding `p`, counting x fastest, then y, then z; a position outside the grid goes to the
/// nearest border cell:
/// ```text
/// (i, j, k) = clamp(⌊(p − origin) / cell_size⌋, 0, dims − 1)     per axis
/// index     = i + nx (j + ny k)
/// ```
/// Hints: `Vec3::floor`. Rust's `as u32` saturates (a negative float gives 0), so the lower
/// clamp comes for free, the upper one does not: each of i, j, k must stay below its count, and
/// a grid may be a single cell thick (`ny = 1`: every position has j = 0).
pub fn cell_index(p: Vec3, origin: Vec3, cell_size: f32, dims: [u32; 3]) -> Answer<usize> {
    solution!(boids::cell_index(p, origin, cell_size, dims));
    let _ = (p, origin, cell_size, dims);
    Err(NotDone)
}

/// Grades this file's exercises against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    const L: &str = "12-boids";
    type Case = (Vec3, Vec3, Vec<Vec3>, Vec<Vec3>);
    let mut cases: Vec<(&str, Case)> = vec![
        (
            "no neighbours: three zeros",
            (Vec3::ONE, Vec3::X, vec![], vec![]),
        ),
        (
            "one neighbour ahead: cohesion towards it, separation away",
            (
                Vec3::ZERO,
                Vec3::X,
                vec![Vec3::new(2.0, 0.0, 0.0)],
                vec![Vec3::Y],
            ),
        ),
        (
            "two neighbours: the centre is their mean; separation by 1/distance",
            (
                Vec3::ZERO,
                Vec3::X,
                vec![Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0)],
                vec![Vec3::Y, Vec3::Y],
            ),
        ),
        (
            "a neighbour at the same point: skipped in separation",
            (
                Vec3::ONE,
                Vec3::Z,
                vec![Vec3::ONE, Vec3::new(2.0, 1.0, 1.0)],
                vec![Vec3::X, Vec3::X],
            ),
        ),
    ];
    for _ in 0..150 {
        let n = rng.below(8);
        let p = rng.vec3(-3.0, 3.0);
        let positions = (0..n).map(|_| p + rng.vec3(-1.5, 1.5)).collect();
        let velocities = (0..n).map(|_| rng.vec3(-2.0, 2.0)).collect();
        cases.push((RANDOM, (p, rng.vec3(-2.0, 2.0), positions, velocities)));
    }
    let rules = check_cases(
        L,
        "three_rules",
        ["p", "v", "positions", "velocities"],
        &cases,
        |(p, v, ps, vs)| three_rules(*p, *v, ps, vs),
        |(p, v, ps, vs)| boids::three_rules(*p, *v, ps, vs),
        |a, b| {
            a.iter()
                .zip(b)
                .all(|(a, b)| (*a - *b).abs().max_element() <= 1e-4 * (1.0 + a.abs().max_element()))
        },
    );
    type Cell = (Vec3, Vec3, f32, [u32; 3]);
    let dims = [4, 5, 6];
    let mut cells: Vec<(&str, Cell)> = vec![
        ("the first cell", (Vec3::splat(0.1), Vec3::ZERO, 1.0, dims)),
        (
            "one cell along x: index 1",
            (Vec3::new(1.5, 0.1, 0.1), Vec3::ZERO, 1.0, dims),
        ),
        (
            "one cell along y: index nx",
            (Vec3::new(0.1, 1.5, 0.1), Vec3::ZERO, 1.0, dims),
        ),
        (
            "one cell along z: index nx·ny",
            (Vec3::new(0.1, 0.1, 1.5), Vec3::ZERO, 1.0, dims),
        ),
        (
            "a negative origin and half-metre cells",
            (Vec3::ZERO, Vec3::splat(-1.0), 0.5, dims),
        ),
        (
            "left of the grid: clamped to i = 0",
            (Vec3::new(-3.0, 1.5, 0.5), Vec3::ZERO, 1.0, dims),
        ),
        (
            "beyond the far corner: the last cell",
            (Vec3::splat(50.0), Vec3::ZERO, 1.0, dims),
        ),
        (
            "exactly on a cell boundary: the upper cell",
            (Vec3::new(2.0, 0.0, 0.0), Vec3::ZERO, 1.0, dims),
        ),
    ];
    for _ in 0..200 {
        let d = [
            1 + rng.below(10) as u32,
            1 + rng.below(10) as u32,
            1 + rng.below(10) as u32,
        ];
        cells.push((
            RANDOM,
            (
                rng.vec3(-6.0, 6.0),
                rng.vec3(-3.0, 0.0),
                rng.range(0.2, 2.0),
                d,
            ),
        ));
    }
    let cell = check_cases(
        L,
        "cell_index",
        ["p", "origin", "cell_size", "dims"],
        &cells,
        |&(p, o, s, d)| cell_index(p, o, s, d),
        |&(p, o, s, d)| boids::cell_index(p, o, s, d),
        |a, b| a == b,
    );
    vec![rules, cell]
}
