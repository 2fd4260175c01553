//! Simplex noise (src/noise/simplex.rs): Gustavson's reference values, bounds, continuity,
//! seeded reproducibility.
#![cfg(not(target_arch = "wasm32"))]

use inbetween::noise::simplex::corners_per_sample;
use inbetween::noise::Permutation;
use proptest::prelude::*;

/// Rows of tests/data/simplex_reference.csv: (x, y, z or None for 2D, value).
fn reference() -> Vec<(f32, f32, Option<f32>, f32)> {
    include_str!("data/simplex_reference.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            let z = if c[2] == "-" {
                None
            } else {
                Some(c[2].parse().unwrap())
            };
            (
                c[0].parse().unwrap(),
                c[1].parse().unwrap(),
                z,
                c[3].parse().unwrap(),
            )
        })
        .collect()
}

#[test]
fn matches_gustavsons_simplexnoise1234() {
    let perm = Permutation::perlin();
    let rows = reference();
    assert_eq!(rows.len(), 400);
    let (mut n2, mut n3) = (0, 0);
    for (x, y, z, want) in rows {
        let got = match z {
            None => {
                n2 += 1;
                perm.simplex2(x, y)
            }
            Some(z) => {
                n3 += 1;
                perm.simplex3(x, y, z)
            }
        };
        // The reference computes in float32 too; only the order of a few roundings differs.
        assert!(
            (got - want).abs() < 2e-5,
            "({x}, {y}, {z:?}): {got} vs {want}"
        );
    }
    assert_eq!((n2, n3), (200, 200));
}

#[test]
fn corners_grow_linearly_not_exponentially() {
    assert_eq!(corners_per_sample(2), (3, 4));
    assert_eq!(corners_per_sample(3), (4, 8));
    assert_eq!(corners_per_sample(10), (11, 1024));
}

#[test]
fn zero_at_the_simplex_lattice_points() {
    // At a lattice corner the corner's own ramp is 0 and the other corners are too far away.
    let perm = Permutation::perlin();
    for (i, j) in [(0, 0), (3, -2), (-7, 5)] {
        let g2 = (3.0 - 3f32.sqrt()) / 6.0;
        let t = (i + j) as f32 * g2;
        let (x, y) = (i as f32 - t, j as f32 - t);
        assert!(perm.simplex2(x, y).abs() < 1e-5, "({x}, {y})");
    }
    assert!(perm.simplex3(0.0, 0.0, 0.0).abs() < 1e-6);
}

proptest! {
    #[test]
    fn stays_within_minus_one_one(x in -300f32..300.0, y in -300f32..300.0, z in -300f32..300.0) {
        let perm = Permutation::perlin();
        prop_assert!(perm.simplex2(x, y).abs() <= 1.0);
        prop_assert!(perm.simplex3(x, y, z).abs() <= 1.0);
    }

    #[test]
    fn is_continuous(x in -50f32..50.0, y in -50f32..50.0, z in -50f32..50.0,
                     dx in -1f32..1.0, dy in -1f32..1.0, dz in -1f32..1.0) {
        // Lipschitz: a step of h changes the value by at most L h (L from the gradients' size
        // and the bump's slope; measured about 2.5 in 2D and 3 in 3D, 8 leaves room).
        let perm = Permutation::perlin();
        let h = 1e-3;
        let d2 = (perm.simplex2(x + h * dx, y + h * dy) - perm.simplex2(x, y)).abs();
        let d3 = (perm.simplex3(x + h * dx, y + h * dy, z + h * dz) - perm.simplex3(x, y, z)).abs();
        prop_assert!(d2 <= 8.0 * h * 1.5, "2D jump {d2}");
        prop_assert!(d3 <= 8.0 * h * 1.8, "3D jump {d3}");
    }

    #[test]
    fn seeded_permutations_are_reproducible(seed in 1u64..1000, x in -20f32..20.0, y in -20f32..20.0) {
        let (a, b) = (Permutation::seeded(seed), Permutation::seeded(seed));
        prop_assert_eq!(a.simplex2(x, y).to_bits(), b.simplex2(x, y).to_bits());
        prop_assert_eq!(a.simplex3(x, y, 0.5).to_bits(), b.simplex3(x, y, 0.5).to_bits());
    }
}

#[test]
fn different_seeds_give_different_noise() {
    let (a, b) = (Permutation::seeded(1), Permutation::seeded(2));
    let differ = (0..100)
        .filter(|&k| {
            let x = k as f32 * 0.37 + 0.1;
            (a.simplex2(x, 1.3) - b.simplex2(x, 1.3)).abs() > 1e-3
        })
        .count();
    assert!(differ > 80, "{differ}");
}

#[test]
fn uses_the_whole_range() {
    // The scale factors bring the extremes close to ±1 (Gustavson's "just inside").
    let perm = Permutation::perlin();
    let (mut lo, mut hi) = (0f32, 0f32);
    for j in 0..400 {
        for i in 0..400 {
            let (x, y) = (i as f32 * 0.05, j as f32 * 0.05);
            let v = perm.simplex2(x, y);
            lo = lo.min(v);
            hi = hi.max(v);
        }
    }
    assert!(lo < -0.8 && hi > 0.8, "{lo} .. {hi}");
}
