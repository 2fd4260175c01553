#![allow(clippy::approx_constant)] // 3.14 is Perlin's own test point, not π.
#![allow(clippy::needless_range_loop)]
//! Tests of the lesson 05 cores: src/noise and src/terrain.

use glam::{Vec2, Vec3};
use inbetween::noise::fractals::{koch_snowflake, sierpinski, MAX_DEPTH};
use inbetween::noise::*;
use inbetween::terrain::*;

/// Rows `x, y, z, noise` written by scripts/reference/perlin_reference.py (Perlin's 2002
/// reference algorithm in Python doubles).
fn reference_rows() -> Vec<[f64; 4]> {
    include_str!("data/perlin_reference.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

#[test]
fn double_precision_transcription_matches_the_reference_bit_for_bit() {
    assert_eq!(noise3_f64(3.14, 42.0, 7.0), 0.13691995878400012);
    let rows = reference_rows();
    assert!(rows.len() > 900);
    for [x, y, z, n] in rows {
        assert_eq!(noise3_f64(x, y, z), n, "at ({x}, {y}, {z})");
    }
}

#[test]
fn f32_noise_agrees_with_the_reference_to_f32_rounding() {
    let perm = Permutation::perlin();
    let mut worst = 0.0f64;
    for [x, y, z, n] in reference_rows() {
        let (xf, yf, zf) = (x as f32, y as f32, z as f32);
        // Compare at the f32 point itself, so that only the arithmetic differs.
        let exact = noise3_f64(xf as f64, yf as f64, zf as f64);
        let got = perm.noise3(xf, yf, zf) as f64;
        // Fractions of coordinates near 300 keep about 15 bits in f32: scale the tolerance.
        let scale = 1.0 + x.abs().max(y.abs()).max(z.abs());
        let err = (got - exact).abs() / scale;
        worst = worst.max(err);
        assert!(err < 2e-6, "at ({x}, {y}, {z}): f32 {got}, f64 {exact}");
        if z == 0.0 {
            assert_eq!(
                perm.noise2(xf, yf),
                perm.noise3(xf, yf, 0.0),
                "2D = z=0 slice"
            );
            let _ = n;
        }
    }
    assert!(
        worst > 0.0,
        "the comparison must see f32 rounding somewhere"
    );
    let got = perm.noise3(3.14, 42.0, 7.0) as f64;
    assert!((got - 0.13691995878400012).abs() < 1e-6, "{got}");
}

#[test]
fn gradient_table_is_the_references_grad() {
    // grad(h, x, y, z) of the reference, written out, against the table's dot product.
    let grad = |h: usize, x: f32, y: f32, z: f32| {
        let h = h & 15;
        let u = if h < 8 { x } else { y };
        let v = if h < 4 {
            y
        } else if h == 12 || h == 14 {
            x
        } else {
            z
        };
        (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
    };
    for h in 0..16 {
        let g = GRAD3[h];
        let p = Vec3::new(0.3, -0.7, 0.45);
        assert_eq!(g[0] * p.x + g[1] * p.y + g[2] * p.z, grad(h, p.x, p.y, p.z));
        let nonzero = g.iter().filter(|c| **c != 0.0).count();
        assert_eq!(nonzero, 2, "an edge direction of the cube");
    }
}

#[test]
fn zero_at_every_lattice_point() {
    let perm = Permutation::perlin();
    let seeded = Permutation::seeded(7);
    for i in -5..6 {
        assert_eq!(perm.noise1(i as f32), 0.0);
        for j in -5..6 {
            assert_eq!(perm.noise2(i as f32, j as f32), 0.0);
            assert_eq!(seeded.noise2(i as f32, j as f32), 0.0);
            for k in -2..3 {
                assert_eq!(perm.noise3(i as f32, j as f32, k as f32), 0.0);
                assert_eq!(noise3_f64(i as f64, j as f64, k as f64), 0.0);
            }
        }
    }
}

#[test]
fn values_stay_within_bounds_and_use_the_range() {
    let perm = Permutation::perlin();
    let (mut lo, mut hi) = (0.0f32, 0.0f32);
    let mut rng = inbetween::fixtures::Rng::new(3);
    for _ in 0..200_000 {
        let p = rng.vec3(-40.0, 40.0);
        let (n1, n2, n3) = (
            perm.noise1(p.x),
            perm.noise2(p.x, p.y),
            perm.noise3(p.x, p.y, p.z),
        );
        assert!(n1.abs() <= 0.5 + 1e-6, "1D {n1}");
        assert!(n2.abs() <= 1.0 + 1e-6, "2D {n2}");
        assert!(n3.abs() <= 1.0 + 1e-6, "3D {n3}");
        lo = lo.min(n2);
        hi = hi.max(n2);
    }
    assert!(lo < -0.6 && hi > 0.6, "2D range seen: [{lo}, {hi}]");
}

#[test]
fn fade_has_the_right_ends_and_derivative() {
    assert_eq!(fade(0.0), 0.0);
    assert_eq!(fade(1.0), 1.0);
    assert_eq!(fade(0.5), 0.5);
    assert_eq!(fade_derivative(0.0), 0.0);
    assert_eq!(fade_derivative(1.0), 0.0);
    for i in 1..100 {
        let t = i as f32 / 100.0;
        let fd = (fade(t + 1e-3) - fade(t - 1e-3)) / 2e-3;
        assert!((fd - fade_derivative(t)).abs() < 1e-3, "t = {t}");
    }
}

#[test]
fn analytic_derivatives_match_finite_differences() {
    let perm = Permutation::seeded(11);
    let mut rng = inbetween::fixtures::Rng::new(5);
    let e = 1e-3f32;
    for _ in 0..2000 {
        let p = rng.vec3(-8.0, 8.0);
        let (_, d1) = perm.noise1_with_derivative(p.x);
        let fd1 = (perm.noise1(p.x + e) - perm.noise1(p.x - e)) / (2.0 * e);
        assert!((d1 - fd1).abs() < 5e-3, "1D at {p}: {d1} vs {fd1}");
        let (v2, d2) = perm.noise2_with_derivative(p.x, p.y);
        assert_eq!(v2, perm.noise2(p.x, p.y));
        let fd2 = Vec2::new(
            perm.noise2(p.x + e, p.y) - perm.noise2(p.x - e, p.y),
            perm.noise2(p.x, p.y + e) - perm.noise2(p.x, p.y - e),
        ) / (2.0 * e);
        assert!((d2 - fd2).length() < 1e-2, "2D at {p}: {d2} vs {fd2}");
        let (v3, d3) = perm.noise3_with_derivative(p);
        assert_eq!(v3, perm.noise3(p.x, p.y, p.z));
        let f = |q: Vec3| perm.noise3(q.x, q.y, q.z);
        let fd3 = Vec3::new(
            f(p + Vec3::X * e) - f(p - Vec3::X * e),
            f(p + Vec3::Y * e) - f(p - Vec3::Y * e),
            f(p + Vec3::Z * e) - f(p - Vec3::Z * e),
        ) / (2.0 * e);
        assert!((d3 - fd3).length() < 1e-2, "3D at {p}: {d3} vs {fd3}");
    }
}

#[test]
fn cell_evaluation_is_the_step_inside_noise2() {
    let perm = Permutation::perlin();
    let mut rng = inbetween::fixtures::Rng::new(8);
    for _ in 0..1000 {
        let p = Vec2::new(rng.range(-20.0, 20.0), rng.range(-20.0, 20.0));
        let c = p.floor();
        let (i, j) = (c.x as i32, c.y as i32);
        let g = [
            grad2(perm.hash2(i, j)),
            grad2(perm.hash2(i + 1, j)),
            grad2(perm.hash2(i, j + 1)),
            grad2(perm.hash2(i + 1, j + 1)),
        ];
        let n = cell2(p - c, g);
        assert!((n - perm.noise2(p.x, p.y)).abs() < 1e-6);
    }
    // A single ramp: only g00 = (1, 0) set, at p = (0.25, 0.5): (1 − u)(1 − v) · 0.25 ... blended.
    let g = [Vec2::X, Vec2::ZERO, Vec2::ZERO, Vec2::ZERO];
    let p = Vec2::new(0.25, 0.5);
    let expected = (1.0 - fade(0.25)) * (1.0 - fade(0.5)) * 0.25;
    assert!((cell2(p, g) - expected).abs() < 1e-7);
}

#[test]
fn seeded_permutations_are_reproducible_permutations() {
    let a = Permutation::seeded(42);
    let b = Permutation::seeded(42);
    let c = Permutation::seeded(43);
    assert_eq!(a, b);
    assert_ne!(a, c);
    let mut seen = [false; 256];
    for &x in a.table() {
        seen[x as usize] = true;
    }
    assert!(seen.iter().all(|s| *s), "every byte once");
    assert_ne!(a.noise2(0.3, 0.7), c.noise2(0.3, 0.7));
    assert_eq!(Permutation::perlin().table(), &PERLIN_PERMUTATION[..]);
}

#[test]
fn noise_repeats_every_256_cells() {
    let perm = Permutation::perlin();
    for &(x, y) in &[(0.3f32, 0.6f32), (5.5, -2.25), (-7.75, 3.125)] {
        // Equal up to f32 rounding of the coordinate near 256 (about 3e-5).
        assert!((perm.noise2(x, y) - perm.noise2(x + 256.0, y)).abs() < 2e-4);
        assert!((perm.noise2(x, y) - perm.noise2(x, y - 256.0)).abs() < 2e-4);
        assert_eq!(
            noise3_f64(x as f64, y as f64, 0.5),
            noise3_f64(x as f64 + 256.0, y as f64, 0.5)
        );
    }
}

#[test]
fn fractal_sum_is_the_sum_of_its_octaves() {
    let perm = Permutation::perlin();
    let f = Fractal {
        n: 5,
        alpha: 0.5,
        omega: 2.0,
    };
    for &(x, y) in &[(0.3f32, 0.7f32), (-1.2, 2.5), (3.3, -0.1)] {
        let by_octave: f32 = (0..=5).map(|k| f.octave2(&perm, k, x, y)).sum();
        assert!((f.sum2(&perm, x, y) - by_octave).abs() < 1e-6);
        let (g, _) = f.shaped2_with_derivative(&perm, Shape::Sum, x, y);
        assert!((g - by_octave).abs() < 1e-6);
    }
    // N = 0 is plain noise; α = 0 keeps only octave 0.
    let one = Fractal {
        n: 0,
        alpha: 0.5,
        omega: 2.0,
    };
    assert_eq!(one.sum2(&perm, 0.3, 0.4), perm.noise2(0.3, 0.4));
    let flat = Fractal {
        n: 6,
        alpha: 0.0,
        omega: 2.0,
    };
    assert_eq!(flat.sum2(&perm, 0.3, 0.4), perm.noise2(0.3, 0.4));
    assert!((Fractal::COURSE.amplitude_sum() - (1.0 - 0.4f32.powi(10)) / 0.6).abs() < 1e-5);
    assert!(Fractal { n: 17, ..f }.validate().unwrap_err().contains("N"));
    assert!(Fractal { alpha: 1.5, ..f }
        .validate()
        .unwrap_err()
        .contains("alpha"));
    assert!(Fractal {
        omega: f32::NAN,
        ..f
    }
    .validate()
    .unwrap_err()
    .contains("omega"));
}

#[test]
fn ridge_turbulence_and_marble() {
    let perm = Permutation::perlin();
    let f = Fractal {
        n: 4,
        alpha: 0.5,
        omega: 2.0,
    };
    let mut rng = inbetween::fixtures::Rng::new(9);
    for _ in 0..500 {
        let (x, y) = (rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let (r, _) = f.shaped2_with_derivative(&perm, Shape::Ridge, x, y);
        let expected: f32 = (0..=4).map(|k| f.octave2(&perm, k, x, y).abs()).sum();
        assert!((r - expected).abs() < 1e-5);
        assert!(r >= 0.0);
        assert!((turbulence2(&perm, 4, x, y) - r).abs() < 1e-6);
        let (q, _) = f.shaped2_with_derivative(&perm, Shape::InvertedRidge, x, y);
        assert!((q - (f.amplitude_sum() - r)).abs() < 1e-5);
        let m = marble2(&perm, &f, 3.0, x, y);
        assert!((m - (3.0 * x + r).sin()).abs() < 1e-5);
    }
}

#[test]
fn fractal_derivatives_match_finite_differences() {
    let perm = Permutation::perlin();
    let f = Fractal {
        n: 3,
        alpha: 0.5,
        omega: 2.0,
    };
    let e = 2e-4;
    for &(x, y) in &[(0.31f32, 0.77f32), (-1.23, 2.51), (3.37, -0.13)] {
        let (_, d) = f.shaped2_with_derivative(&perm, Shape::Sum, x, y);
        let fd = Vec2::new(
            f.sum2(&perm, x + e, y) - f.sum2(&perm, x - e, y),
            f.sum2(&perm, x, y + e) - f.sum2(&perm, x, y - e),
        ) / (2.0 * e);
        assert!((d - fd).length() < 3e-2, "{d} vs {fd}");
        let p = Vec3::new(x, y, 0.4);
        let (g3, d3) = f.sum3_with_derivative(&perm, p);
        assert!((g3 - f.sum3(&perm, p)).abs() < 1e-6);
        let fdx = (f.sum3(&perm, p + Vec3::X * e) - f.sum3(&perm, p - Vec3::X * e)) / (2.0 * e);
        assert!((d3.x - fdx).abs() < 3e-2);
    }
}

#[test]
fn terrain_normals_match_finite_differences_of_the_mesh() {
    let perm = Permutation::perlin();
    let mut t = Terrain::new(257).unwrap();
    let p = TerrainParams::default();
    t.regenerate(&perm, &p).unwrap();
    let r = t.resolution();
    let mut worst = 0.0f32;
    for j in (8..r - 8).step_by(31) {
        for i in (8..r - 8).step_by(29) {
            let k = j * r + i;
            let du = t.positions[k + 1] - t.positions[k - 1];
            let dv = t.positions[k + r] - t.positions[k - r];
            let fd = dv.cross(du).normalize();
            let n = t.normals[k];
            assert!((n.length() - 1.0).abs() < 1e-5);
            worst = worst.max(n.angle_between(fd));
        }
    }
    // The mesh spacing (2/256) is coarse next to octave 9's wavelength (1/512): compare loosely.
    assert!(worst < 0.6, "largest angle to the mesh normal {worst} rad");
    // With N = 0 the mesh resolves the noise well and the two agree closely.
    let smooth = TerrainParams {
        fractal: Fractal {
            n: 0,
            ..Fractal::COURSE
        },
        ..p
    };
    t.regenerate(&perm, &smooth).unwrap();
    let k = 100 * r + 130;
    let fd = (t.positions[k + r] - t.positions[k - r])
        .cross(t.positions[k + 1] - t.positions[k - 1])
        .normalize();
    assert!(t.normals[k].angle_between(fd) < 2e-3);
}

#[test]
fn terrain_follows_the_course_formula() {
    let perm = Permutation::perlin();
    let mut t = Terrain::new(33).unwrap();
    let p = TerrainParams {
        h: 0.5,
        s: 2.0,
        o: 0.25,
        ..TerrainParams::default()
    };
    t.regenerate(&perm, &p).unwrap();
    let (u, v) = t.uv(5, 9);
    let expected = 0.5 * Fractal::COURSE.sum2(&perm, 2.0 * (u + 0.25), 2.0 * (v + 0.25));
    let got = t.positions[9 * 33 + 5];
    assert!((got.y - expected).abs() < 1e-6);
    assert_eq!((got.x, got.z), (u, v));
    // h = 0 is flat with upward normals.
    t.regenerate(&perm, &TerrainParams { h: 0.0, ..p }).unwrap();
    assert!(t.positions.iter().all(|q| q.y == 0.0));
    assert!(t.normals.iter().all(|n| *n == Vec3::Y));
}

#[test]
fn regenerating_never_reallocates() {
    let perm = Permutation::perlin();
    let mut t = Terrain::new(64).unwrap();
    let ptrs = (t.positions.as_ptr(), t.normals.as_ptr(), t.colors.as_ptr());
    let caps = (
        t.positions.capacity(),
        t.normals.capacity(),
        t.colors.capacity(),
    );
    for variant in [
        Variant::Sum,
        Variant::Ridge,
        Variant::InvertedRidge,
        Variant::Marble,
        Variant::Sliding { t: 0.5 },
        Variant::Evolving { t: 0.5 },
    ] {
        let before = t.positions[1000];
        t.regenerate(
            &perm,
            &TerrainParams {
                variant,
                ..TerrainParams::default()
            },
        )
        .unwrap();
        assert_ne!(t.positions[1000], before, "{variant:?} changed the heights");
        assert!(t.normals.iter().all(|n| n.is_finite() && n.y > 0.0));
    }
    assert_eq!(
        ptrs,
        (t.positions.as_ptr(), t.normals.as_ptr(), t.colors.as_ptr())
    );
    assert_eq!(
        caps,
        (
            t.positions.capacity(),
            t.normals.capacity(),
            t.colors.capacity()
        )
    );
}

#[test]
fn terrain_rejects_bad_parameters_by_name() {
    assert!(Terrain::new(1).unwrap_err().contains("resolution"));
    assert!(Terrain::new(MAX_RESOLUTION + 1)
        .unwrap_err()
        .contains("resolution"));
    let perm = Permutation::perlin();
    let mut t = Terrain::new(4).unwrap();
    let d = TerrainParams::default();
    for (p, name) in [
        (TerrainParams { h: f32::NAN, ..d }, "h"),
        (TerrainParams { s: 0.0, ..d }, "s"),
        (TerrainParams { o: 1e9, ..d }, "o"),
        (
            TerrainParams {
                variant: Variant::Evolving { t: f32::INFINITY },
                ..d
            },
            "t",
        ),
    ] {
        let e = t.regenerate(&perm, &p).unwrap_err();
        assert!(e.starts_with(name), "{e}");
    }
}

#[test]
fn triangles_face_up() {
    let t = Terrain::new(5).unwrap();
    for tri in t.indices.chunks(3) {
        let [a, b, c] = [0, 1, 2].map(|i| t.positions[tri[i] as usize]);
        assert!((b - a).cross(c - a).y > 0.0);
    }
    assert_eq!(t.indices.len(), 4 * 4 * 6);
}

#[test]
fn colours_follow_height_and_slope() {
    let flat_low = terrain_color(-0.5, Vec3::Y, 1.0);
    let flat_high = terrain_color(0.9, Vec3::Y, 1.0);
    let steep = terrain_color(0.9, Vec3::new(1.0, 1.0, 0.0).normalize(), 1.0);
    assert!(flat_low.z > flat_low.x, "water is blue");
    assert!(flat_high.x > 0.8, "snow is white");
    assert!(steep.x < 0.4, "steep ground is rock, even high up");
}

#[test]
fn koch_and_sierpinski_counts_and_shapes() {
    let mut pts = Vec::new();
    for d in 0..=4 {
        koch_snowflake(d, 1.0, &mut pts).unwrap();
        assert_eq!(pts.len(), 3 * 4usize.pow(d) + 1);
        assert!((pts[0] - *pts.last().unwrap()).length() < 1e-5, "closed");
        // Every segment has the same length, (side) / 3^d.
        let side = 3f32.sqrt();
        for w in pts.windows(2) {
            assert!(((w[1] - w[0]).length() - side / 3f32.powi(d as i32)).abs() < 1e-4);
        }
        // The bumps point outwards: no point comes closer to the centre than the triangle's inradius.
        assert!(pts.iter().all(|p| p.length() >= 0.5 - 1e-4));
    }
    let mut tris = Vec::new();
    let corners = [
        Vec2::new(-1.0, 0.0),
        Vec2::new(1.0, 0.0),
        Vec2::new(0.0, 1.7),
    ];
    sierpinski(3, corners, &mut tris).unwrap();
    assert_eq!(tris.len(), 27);
    let area = |t: &[Vec2; 3]| 0.5 * (t[1] - t[0]).perp_dot(t[2] - t[0]).abs();
    let total: f32 = tris.iter().map(area).sum();
    assert!((total - area(&corners) * 0.75f32.powi(3)).abs() < 1e-4);
    assert!(koch_snowflake(MAX_DEPTH + 1, 1.0, &mut pts)
        .unwrap_err()
        .contains("depth"));
    assert!(sierpinski(MAX_DEPTH + 1, corners, &mut tris).is_err());
}

/// Rows of points for the row fast paths: increasing with small and large steps (many points per
/// cell, cells skipped), decreasing, scattered, negative and far from the origin.
fn row_cases() -> Vec<(Vec<f32>, f32, f32)> {
    let mut rng = inbetween::fixtures::Rng::new(5);
    let mut cases = vec![];
    for (x0, step, n) in [
        (0.0, 0.0371, 200),
        (-7.3, 0.61, 60),
        (251.2, 0.013, 400),
        (12.0, -0.37, 50),
    ] {
        let xs = (0..n).map(|i| x0 + i as f32 * step).collect();
        cases.push((xs, rng.range(-300.0, 300.0), rng.range(-300.0, 300.0)));
    }
    let scattered = (0..300).map(|_| rng.range(-50.0, 50.0)).collect();
    cases.push((scattered, 0.5, -2.25));
    // Lattice lines: y, z on integers.
    cases.push(((0..100).map(|i| i as f32 * 0.25).collect(), 3.0, -4.0));
    cases
}

#[test]
fn noise2_row_matches_noise2_and_its_derivative() {
    for seed in [None, Some(11)] {
        let perm = seed.map_or_else(Permutation::perlin, Permutation::seeded);
        for (xs, y, _) in row_cases() {
            let n = xs.len();
            let (mut out, mut dx, mut dy) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            perm.noise2_row(&xs, y, &mut out);
            let mut out2 = vec![0.0; n];
            perm.noise2_row_with_derivative(&xs, y, &mut out2, &mut dx, &mut dy);
            for k in 0..n {
                let v = perm.noise2(xs[k], y);
                let (v2, d) = perm.noise2_with_derivative(xs[k], y);
                assert!(
                    (out[k] - v).abs() < 2e-6,
                    "x {} y {y}: {} vs {v}",
                    xs[k],
                    out[k]
                );
                assert!((out2[k] - v2).abs() < 2e-6);
                assert!(
                    (dx[k] - d.x).abs() < 1e-5,
                    "dx at {}: {} vs {}",
                    xs[k],
                    dx[k],
                    d.x
                );
                assert!(
                    (dy[k] - d.y).abs() < 1e-5,
                    "dy at {}: {} vs {}",
                    xs[k],
                    dy[k],
                    d.y
                );
            }
        }
    }
}

#[test]
fn noise3_row_matches_noise3() {
    let perm = Permutation::perlin();
    for (xs, y, z) in row_cases() {
        let mut out = vec![0.0; xs.len()];
        perm.noise3_row(&xs, y, z, &mut out);
        for (k, &x) in xs.iter().enumerate() {
            let v = perm.noise3(x, y, z);
            assert!(
                (out[k] - v).abs() < 2e-6,
                "({x}, {y}, {z}): {} vs {v}",
                out[k]
            );
        }
    }
    // And against Perlin's reference in doubles, through the row path.
    let xs = [3.14f32, 0.5, -1.25];
    let mut out = [0.0; 3];
    perm.noise3_row(&xs, 42.0, 7.0, &mut out);
    for (k, &x) in xs.iter().enumerate() {
        assert!((out[k] as f64 - noise3_f64(x as f64, 42.0, 7.0)).abs() < 2e-6);
    }
}

/// The row-by-row regeneration gives, at every vertex, the height and normal of the point by
/// point formula (`TerrainParams::g` and `terrain_normal`), for every variant.
#[test]
fn regenerate_matches_the_point_by_point_terrain() {
    let perm = Permutation::seeded(3);
    let mut terrain = Terrain::new(97).unwrap();
    for variant in [
        Variant::Sum,
        Variant::Ridge,
        Variant::InvertedRidge,
        Variant::Marble,
        Variant::Sliding { t: 2.7 },
        Variant::Evolving { t: 0.4 },
    ] {
        let params = TerrainParams {
            fractal: Fractal {
                n: 8,
                alpha: 0.5,
                omega: 2.1,
            },
            h: 0.7,
            s: 2.3,
            o: -13.4,
            variant,
        };
        terrain.regenerate(&perm, &params).unwrap();
        let r = terrain.resolution();
        for j in 0..r {
            for i in 0..r {
                let (u, v) = terrain.uv(i, j);
                let (g, dg) = params.g(&perm, params.s * (u + params.o), params.s * (v + params.o));
                let k = j * r + i;
                let p = terrain.positions[k];
                assert!(
                    (p.y - params.h * g).abs() < 1e-5,
                    "{variant:?} at ({i}, {j}): {} vs {}",
                    p.y,
                    params.h * g
                );
                assert_eq!((p.x, p.z), (u, v));
                let n = terrain_normal(params.h, params.s, dg);
                assert!(
                    (terrain.normals[k] - n).length() < 1e-4,
                    "{variant:?} normal at ({i}, {j})"
                );
            }
        }
    }
}

#[test]
fn fade_second_derivative_is_zero_at_the_ends_unlike_the_1985_curve() {
    assert_eq!(fade_second_derivative(0.0), 0.0);
    assert_eq!(fade_second_derivative(1.0), 0.0);
    let h = 1e-3f64;
    for i in 1..20 {
        let t = i as f32 / 20.0;
        let fd = (fade_derivative(t + h as f32) - fade_derivative(t - h as f32)) / (2.0 * h as f32);
        assert!((fd - fade_second_derivative(t)).abs() < 2e-2, "t = {t}");
    }
    // The 1985 curve 3t² − 2t³: its second derivative 6 − 12t is 6 at t = 0 and −6 at t = 1, so
    // where one cell's t = 1 meets the next cell's t = 0 the curvature of the blend jumps.
    let cubic = |t: f64| 3.0 * t * t - 2.0 * t * t * t;
    let second = |t: f64| (cubic(t + h) - 2.0 * cubic(t) + cubic(t - h)) / (h * h);
    assert!((second(h) - 6.0).abs() < 0.05 && (second(1.0 - h) + 6.0).abs() < 0.05);
}

#[test]
fn the_3d_hash_and_gradient_extend_the_2d_ones() {
    let perm = Permutation::perlin();
    for (i, j) in [(0, 0), (3, -2), (-7, 5), (200, 13)] {
        assert_eq!(
            perm.hash3(i, j, 0),
            perm.hash2(i, j),
            "the 2D noise is the slice z = 0"
        );
        let g = perm.gradient3(i, j, 0);
        assert_eq!(g.truncate(), grad2(perm.hash2(i, j)));
    }
    // Near a lattice point (i, j, k) the noise is the ramp g·(p − corner).
    let g = perm.gradient3(2, 1, 3);
    let d = Vec3::new(1e-3, -2e-3, 1.5e-3);
    let n = perm.noise3(2.0 + d.x, 1.0 + d.y, 3.0 + d.z);
    assert!((n - g.dot(d)).abs() < 1e-6, "{n} vs {}", g.dot(d));
}

#[test]
fn last_resolved_octave_is_the_nyquist_limit_of_the_mesh() {
    // Octave k is kept while s ωᵏ < (resolution − 1)/4: a cell spans more than two spacings.
    assert_eq!(last_resolved_octave(128, 1.0, 2.0), Some(4)); // 31.75 cells per metre at most
    assert_eq!(last_resolved_octave(129, 1.0, 2.0), Some(4)); // exactly 32: the limit itself is past it
    assert_eq!(last_resolved_octave(193, 1.0, 2.0), Some(5));
    assert_eq!(last_resolved_octave(512, 1.0, 2.0), Some(6));
    assert_eq!(last_resolved_octave(97, 1.0, 2.0), Some(4));
    assert_eq!(last_resolved_octave(97, 3.0, 2.0), Some(2)); // octave 3: 24 cells per metre, the limit itself
    assert_eq!(last_resolved_octave(64, 16.0, 2.0), None);
    assert_eq!(last_resolved_octave(64, 1.0, 1.0), Some(MAX_N));
    assert_eq!(last_resolved_octave(512, 1.0, 4.0), Some(3));
    // Past the limit the mesh's samples stop following the octave: neighbouring vertices of
    // a resolved octave are strongly correlated, those of an octave past the limit are not.
    let perm = Permutation::perlin();
    let step = 2.0 / 127.0;
    let neighbour_correlation = |k: i32| {
        let w = 2f32.powi(k);
        let (mut sab, mut saa, mut sbb) = (0.0f64, 0.0f64, 0.0f64);
        for j in 0..40 {
            for i in 0..126 {
                let (u, v) = (-1.0 + i as f32 * step, -1.0 + j as f32 * 0.05);
                let a = perm.noise2(w * u, w * v) as f64;
                let b = perm.noise2(w * (u + step), w * v) as f64;
                (sab, saa, sbb) = (sab + a * b, saa + a * a, sbb + b * b);
            }
        }
        sab / (saa * sbb).sqrt()
    };
    // The last kept octave (4) and the first past the limit (5).
    assert!(neighbour_correlation(4) > 0.7);
    assert!(neighbour_correlation(5) < 0.4);
    assert!(neighbour_correlation(7).abs() < 0.1);
}

#[test]
fn inverted_ridge_and_marble_terrains_follow_the_lessons_formulas() {
    // q = Σ αᵏ (1 − |f|) − 0.7 Σ αᵏ and m = ½ sin(4x + Σ αᵏ |f|), as the lesson writes them.
    let perm = Permutation::perlin();
    let f = Fractal::COURSE;
    let params = |variant| TerrainParams {
        variant,
        ..TerrainParams::default()
    };
    let mut rng = inbetween::fixtures::Rng::new(3);
    for _ in 0..200 {
        let (x, y) = (rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
        let r: f32 = (0..=f.n).map(|k| f.octave2(&perm, k, x, y).abs()).sum();
        let q: f32 = (0..=f.n)
            .map(|k| {
                f.alpha.powi(k as i32)
                    * (1.0
                        - perm
                            .noise2(f.omega.powi(k as i32) * x, f.omega.powi(k as i32) * y)
                            .abs())
            })
            .sum();
        let (got_q, _) = params(Variant::InvertedRidge).g(&perm, x, y);
        assert!((got_q - (q - 0.7 * f.amplitude_sum())).abs() < 1e-5);
        let (got_m, _) = params(Variant::Marble).g(&perm, x, y);
        assert!((got_m - 0.5 * (4.0 * x + r).sin()).abs() < 1e-5);
    }
    // The shift keeps the inverted ridge around 0 like the other variants: on the course's
    // window its mean height lies within 0.1 Σ αᵏ of 0, and it goes below 0 (the water).
    let mut t = Terrain::new(128).unwrap();
    t.regenerate(&perm, &params(Variant::InvertedRidge))
        .unwrap();
    let heights: Vec<f32> = t.positions.iter().map(|p| p.y / 0.3).collect();
    let mean = heights.iter().sum::<f32>() / heights.len() as f32;
    assert!(mean.abs() < 0.1 * f.amplitude_sum(), "mean {mean}");
    assert!(heights.iter().any(|&y| y < 0.0));
    assert!(
        t.colors.iter().any(|c| c.z > 2.0 * c.x),
        "water in the lowest parts"
    );
}

/// Scattered points for the batch kernels: negative, large, on lattice lines and cell borders,
/// at lengths that are not multiples of the batch width, and one longer than a sum's chunk.
fn scattered_cases() -> Vec<Vec<[f32; 3]>> {
    let mut rng = inbetween::fixtures::Rng::new(5);
    let mut cases: Vec<Vec<[f32; 3]>> = [0usize, 1, 7, 8, 9, 31, 600]
        .iter()
        .map(|&n| {
            (0..n)
                .map(|_| std::array::from_fn(|_| rng.range(-300.0, 300.0)))
                .collect()
        })
        .collect();
    cases.push(
        (0..40)
            .map(|i| {
                let t = i as f32 * 0.5 - 10.0;
                [t, t.floor(), -t]
            })
            .collect(),
    );
    cases.push(vec![
        [1e6, -1e6, 0.25],
        [-0.0, 255.999, 256.0],
        [1e-30, -1e-30, 3.5],
    ]);
    cases
}

#[test]
fn the_batch_kernels_equal_the_per_point_noise() {
    for seed in [None, Some(3)] {
        let perm = seed.map_or_else(Permutation::perlin, Permutation::seeded);
        for points in scattered_cases() {
            let [xs, ys, zs]: [Vec<f32>; 3] =
                std::array::from_fn(|c| points.iter().map(|p| p[c]).collect());
            let n = points.len();
            // One slot more than the points: the shortest length wins, the extra is untouched.
            let (mut out2, mut out3) = (vec![7.0; n + 1], vec![7.0; n + 1]);
            perm.noise2_batch(&xs, &ys, &mut out2);
            perm.noise3_batch(&xs, &ys, &zs, &mut out3);
            assert_eq!((out2[n], out3[n]), (7.0, 7.0));
            for k in 0..n {
                let ([x, y, z], at) = (points[k], k);
                assert_eq!(
                    out2[at].to_bits(),
                    perm.noise2(x, y).to_bits(),
                    "2D at {x} {y}"
                );
                // 3D: equal as numbers (the batch may give -0 for 0 at a lattice point).
                assert_eq!(out3[at], perm.noise3(x, y, z), "3D at {x} {y} {z}");
            }
        }
    }
    // A NaN gives what the per-point noise gives there (NaN), and no panic.
    let perm = Permutation::perlin();
    let mut out = [0.0; 3];
    let (xs, ys, zs) = ([f32::NAN, 0.5, 0.5], [0.5, f32::NAN, 0.5], [0.5, 0.5, 0.25]);
    perm.noise3_batch(&xs, &ys, &zs, &mut out);
    for k in 0..3 {
        assert_eq!(
            out[k].is_nan(),
            perm.noise3(xs[k], ys[k], zs[k]).is_nan(),
            "{k}"
        );
    }
    assert!(out[0].is_nan() && !out[2].is_nan());
}

#[test]
fn the_batch_fractal_sums_equal_sum2_and_sum3() {
    let perm = Permutation::seeded(9);
    for fractal in [
        Fractal::COURSE,
        Fractal {
            n: 7,
            alpha: 0.5,
            omega: 2.0,
        },
        Fractal {
            n: 0,
            alpha: 1.0,
            omega: 1.0,
        },
    ] {
        for points in scattered_cases() {
            let points: Vec<[f32; 3]> = points.iter().map(|p| p.map(|v| v * 0.01)).collect();
            let [xs, ys, zs]: [Vec<f32>; 3] =
                std::array::from_fn(|c| points.iter().map(|p| p[c]).collect());
            let n = points.len();
            let (mut g2, mut g3) = (vec![0.0; n], vec![0.0; n]);
            fractal.sum2_batch(&perm, &xs, &ys, &mut g2);
            fractal.sum3_batch(&perm, &xs, &ys, &zs, &mut g3);
            for (k, &[x, y, z]) in points.iter().enumerate() {
                assert_eq!(g2[k].to_bits(), fractal.sum2(&perm, x, y).to_bits());
                let p = Vec3::new(x, y, z);
                assert_eq!(g3[k], fractal.sum3(&perm, p));
            }
        }
    }
}

#[test]
fn the_row_fractal_sums_match_sum2_and_sum3() {
    let perm = Permutation::perlin();
    let fractal = Fractal {
        n: 7,
        alpha: 0.5,
        omega: 2.0,
    };
    // A sorted row longer than a chunk, an unsorted one, and a row on lattice lines.
    let mut rng = inbetween::fixtures::Rng::new(8);
    let sorted: Vec<f32> = (0..700).map(|i| i as f32 * 0.0173 - 3.0).collect();
    let unsorted: Vec<f32> = (0..300).map(|_| rng.range(-40.0, 40.0)).collect();
    let lattice: Vec<f32> = (0..64).map(|i| i as f32 * 0.25).collect();
    for (xs, y, z) in [
        (sorted, 0.37, -1.2),
        (unsorted, -5.5, 2.0),
        (lattice, 2.0, 3.0),
    ] {
        let n = xs.len();
        let (mut g2, mut g3) = (vec![0.0; n], vec![0.0; n]);
        fractal.sum2_row(&perm, &xs, y, &mut g2);
        fractal.sum3_row(&perm, &xs, y, z, &mut g3);
        for (k, &x) in xs.iter().enumerate() {
            // Each octave's row agrees with the point's noise to about 2e-6; the weights sum to 2.
            let e2 = fractal.sum2(&perm, x, y);
            let e3 = fractal.sum3(&perm, Vec3::new(x, y, z));
            assert!((g2[k] - e2).abs() < 1e-5, "2D at {x}: {} vs {e2}", g2[k]);
            assert!((g3[k] - e3).abs() < 1e-5, "3D at {x}: {} vs {e3}", g3[k]);
        }
    }
}
