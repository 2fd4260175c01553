//! Perlin noise benchmarks (native): our `f32` improved noise against the `noise` crate 0.9
//! (`Perlin`, `f64`), the usual choice of a Rust user, on the same points:
//! - 2D and 3D, on a regular grid and at scattered points (`perlin2_*`, `perlin3_*`); on the
//!   grids also our row fast path (`inbetween_f32_rows`: `noise2_row` / `noise3_row` over the
//!   same points, one call per row),
//! - an 8-octave fractal sum on a 512 × 512 grid (`fbm8_512`: our `Fractal::sum2` with N = 7,
//!   α = ½, ω = 2 against `noise::Fbm<Perlin>` with 8 octaves, persistence ½, lacunarity 2),
//! - our 512 × 512 terrain regenerated with 8 octaves, exact normals and colours (no baseline:
//!   the absolute time is the figure of merit, against a 16 ms frame).
//!
//! The two libraries' 2D noises are different functions (ours is Perlin's 3D reference on z = 0,
//! theirs a 2D variant); both cost one hash and four gradient ramps per sample.
//! Run: `cargo bench --features native-bench --bench perlin -- --warm-up-time 1 --measurement-time 2`.
//! After criterion's report, the ratios are printed from a short separate timing, then the
//! scattered-point batches and the fast fractal sums against simdnoise's SSE2 functions and
//! FastNoise Lite, interleaved (`cargo bench --features native-bench --bench perlin -- --batch-only`: those alone).

use std::hint::black_box;
use std::time::Instant;

use criterion::{Criterion, Throughput};
use inbetween::noise::{Fractal, Permutation};
use inbetween::terrain::{Terrain, TerrainParams};
use noise::{Fbm, MultiFractal, NoiseFn, Perlin};

/// A benchmark group: its name, the points in `f64` (theirs) and the same points in `f32` (ours).
type Case<'a, const D: usize> = (&'a str, &'a [[f64; D]], &'a [[f32; D]]);

const GRID2: usize = 256; // 65 536 samples
const GRID3: usize = 40; // 64 000 samples
const SCATTERED: usize = 65_536;
const FBM_SIDE: usize = 512;

fn grid2() -> Vec<[f64; 2]> {
    let step = 0.0371;
    (0..GRID2 * GRID2)
        .map(|k| [(k % GRID2) as f64 * step, (k / GRID2) as f64 * step])
        .collect()
}

fn grid3() -> Vec<[f64; 3]> {
    let step = 0.0371;
    (0..GRID3 * GRID3 * GRID3)
        .map(|k| {
            [
                (k % GRID3) as f64 * step,
                (k / GRID3 % GRID3) as f64 * step,
                (k / (GRID3 * GRID3)) as f64 * step,
            ]
        })
        .collect()
}

fn scattered<const D: usize>() -> Vec<[f64; D]> {
    let mut rng = inbetween::fixtures::Rng::new(77);
    (0..SCATTERED)
        .map(|_| std::array::from_fn(|_| rng.range(-100.0, 100.0) as f64))
        .collect()
}

/// The same points in `f32` (every coordinate above is an `f32` value or a short decimal).
fn to_f32<const D: usize>(points: &[[f64; D]]) -> Vec<[f32; D]> {
    points.iter().map(|p| p.map(|x| x as f32)).collect()
}

fn ours2(perm: &Permutation, points: &[[f32; 2]]) -> f32 {
    points.iter().map(|p| perm.noise2(p[0], p[1])).sum()
}
fn theirs2(perlin: &Perlin, points: &[[f64; 2]]) -> f64 {
    points.iter().map(|p| perlin.get(*p)).sum()
}
fn ours3(perm: &Permutation, points: &[[f32; 3]]) -> f32 {
    points.iter().map(|p| perm.noise3(p[0], p[1], p[2])).sum()
}
fn theirs3(perlin: &Perlin, points: &[[f64; 3]]) -> f64 {
    points.iter().map(|p| perlin.get(*p)).sum()
}

/// A regular grid's points as rows for the row fast paths ([`Permutation::noise2_row`],
/// [`Permutation::noise3_row`]): every point's x, row after row, and each row's other
/// coordinates (the same `f32` points as the per-point kernels, laid out by row).
struct Rows<const D: usize> {
    xs: Vec<f32>,
    rest: Vec<[f32; D]>,
    len: usize,
}

fn rows<const D: usize>(points: &[[f32; D]], len: usize) -> Rows<D> {
    for row in points.chunks(len) {
        assert!(row.iter().all(|p| p[1..] == row[0][1..]), "not a row");
    }
    Rows {
        xs: points.iter().map(|p| p[0]).collect(),
        rest: points.chunks(len).map(|row| row[0]).collect(),
        len,
    }
}

fn ours2_rows(perm: &Permutation, rows: &Rows<2>, out: &mut [f32]) -> f32 {
    for ((xs, p), o) in rows
        .xs
        .chunks(rows.len)
        .zip(&rows.rest)
        .zip(out.chunks_mut(rows.len))
    {
        perm.noise2_row(xs, p[1], o);
    }
    out.iter().sum()
}

fn ours3_rows(perm: &Permutation, rows: &Rows<3>, out: &mut [f32]) -> f32 {
    for ((xs, p), o) in rows
        .xs
        .chunks(rows.len)
        .zip(&rows.rest)
        .zip(out.chunks_mut(rows.len))
    {
        perm.noise3_row(xs, p[1], p[2], o);
    }
    out.iter().sum()
}

const OURS_FBM: Fractal = Fractal {
    n: 7,
    alpha: 0.5,
    omega: 2.0,
};

fn ours_fbm(perm: &Permutation, out: &mut [f32]) {
    let step = 4.0 / FBM_SIDE as f32;
    for (k, o) in out.iter_mut().enumerate() {
        let (i, j) = (k % FBM_SIDE, k / FBM_SIDE);
        *o = OURS_FBM.sum2(perm, i as f32 * step, j as f32 * step);
    }
}

fn theirs_fbm(fbm: &Fbm<Perlin>, out: &mut [f64]) {
    let step = 4.0 / FBM_SIDE as f64;
    for (k, o) in out.iter_mut().enumerate() {
        let (i, j) = (k % FBM_SIDE, k / FBM_SIDE);
        *o = fbm.get([i as f64 * step, j as f64 * step]);
    }
}

fn their_fbm() -> Fbm<Perlin> {
    Fbm::<Perlin>::new(0)
        .set_octaves(8)
        .set_persistence(0.5)
        .set_lacunarity(2.0)
}

fn terrain_params() -> TerrainParams {
    TerrainParams {
        fractal: OURS_FBM,
        ..TerrainParams::default()
    }
}

struct Inputs {
    perm: Permutation,
    perlin: Perlin,
    g2: Vec<[f64; 2]>,
    g2f: Vec<[f32; 2]>,
    s2: Vec<[f64; 2]>,
    s2f: Vec<[f32; 2]>,
    g3: Vec<[f64; 3]>,
    g3f: Vec<[f32; 3]>,
    s3: Vec<[f64; 3]>,
    s3f: Vec<[f32; 3]>,
    r2: Rows<2>,
    r3: Rows<3>,
}

fn inputs() -> Inputs {
    let (g2, s2, g3, s3) = (grid2(), scattered::<2>(), grid3(), scattered::<3>());
    let (g2f, g3f) = (to_f32(&g2), to_f32(&g3));
    Inputs {
        r2: rows(&g2f, GRID2),
        r3: rows(&g3f, GRID3),
        g2f,
        g3f,
        perm: Permutation::perlin(),
        perlin: Perlin::new(0),
        s2f: to_f32(&s2),
        s3f: to_f32(&s3),
        g2,
        s2,
        g3,
        s3,
    }
}

fn bench_samples(c: &mut Criterion, x: &Inputs) {
    let cases2: [Case<2>; 2] = [
        ("perlin2_grid", &x.g2, &x.g2f),
        ("perlin2_scattered", &x.s2, &x.s2f),
    ];
    for (name, pts, ptsf) in cases2 {
        let mut group = c.benchmark_group(name);
        group.throughput(Throughput::Elements(pts.len() as u64));
        group.bench_function("inbetween_f32", |b| {
            b.iter(|| ours2(&x.perm, black_box(ptsf)))
        });
        group.bench_function("noise_crate_f64", |b| {
            b.iter(|| theirs2(&x.perlin, black_box(pts)))
        });
        if name == "perlin2_grid" {
            let mut out = vec![0.0f32; pts.len()];
            group.bench_function("inbetween_f32_rows", |b| {
                b.iter(|| ours2_rows(&x.perm, black_box(&x.r2), &mut out))
            });
        }
        group.finish();
    }
    let cases3: [Case<3>; 2] = [
        ("perlin3_grid", &x.g3, &x.g3f),
        ("perlin3_scattered", &x.s3, &x.s3f),
    ];
    for (name, pts, ptsf) in cases3 {
        let mut group = c.benchmark_group(name);
        group.throughput(Throughput::Elements(pts.len() as u64));
        group.bench_function("inbetween_f32", |b| {
            b.iter(|| ours3(&x.perm, black_box(ptsf)))
        });
        group.bench_function("noise_crate_f64", |b| {
            b.iter(|| theirs3(&x.perlin, black_box(pts)))
        });
        if name == "perlin3_grid" {
            let mut out = vec![0.0f32; pts.len()];
            group.bench_function("inbetween_f32_rows", |b| {
                b.iter(|| ours3_rows(&x.perm, black_box(&x.r3), &mut out))
            });
        }
        group.finish();
    }
}

fn bench_fbm(c: &mut Criterion, x: &Inputs) {
    let mut ours = vec![0.0f32; FBM_SIDE * FBM_SIDE];
    let mut theirs = vec![0.0f64; FBM_SIDE * FBM_SIDE];
    let fbm = their_fbm();
    let mut terrain = Terrain::new(FBM_SIDE).unwrap();
    let params = terrain_params();
    let mut group = c.benchmark_group("fbm8_512");
    group.sample_size(10);
    group.throughput(Throughput::Elements((FBM_SIDE * FBM_SIDE) as u64));
    group.bench_function("inbetween_f32", |b| {
        b.iter(|| ours_fbm(&x.perm, black_box(&mut ours)))
    });
    group.bench_function("noise_crate_f64", |b| {
        b.iter(|| theirs_fbm(&fbm, black_box(&mut theirs)))
    });
    group.bench_function("inbetween_terrain_with_normals", |b| {
        b.iter(|| terrain.regenerate(&x.perm, black_box(&params)).unwrap())
    });
    group.finish();
}

/// Best of `reps` runs, in seconds.
fn best_time(reps: usize, mut f: impl FnMut()) -> f64 {
    (0..reps)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn print_ratios(x: &Inputs) {
    let line = |name: &str, n: usize, ours: f64, theirs: f64| {
        println!(
            "{name}: noise crate / inbetween time = {:.2} ({:.1} vs {:.1} M samples/s)",
            theirs / ours,
            n as f64 / ours / 1e6,
            n as f64 / theirs / 1e6
        )
    };
    let r = 30;
    line(
        "perlin2 grid",
        x.g2.len(),
        best_time(r, || {
            black_box(ours2(&x.perm, &x.g2f));
        }),
        best_time(r, || {
            black_box(theirs2(&x.perlin, &x.g2));
        }),
    );
    let mut out2 = vec![0.0f32; x.g2.len()];
    line(
        "perlin2 grid, row API",
        x.g2.len(),
        best_time(r, || {
            black_box(ours2_rows(&x.perm, &x.r2, &mut out2));
        }),
        best_time(r, || {
            black_box(theirs2(&x.perlin, &x.g2));
        }),
    );
    line(
        "perlin2 scattered",
        x.s2.len(),
        best_time(r, || {
            black_box(ours2(&x.perm, &x.s2f));
        }),
        best_time(r, || {
            black_box(theirs2(&x.perlin, &x.s2));
        }),
    );
    line(
        "perlin3 grid",
        x.g3.len(),
        best_time(r, || {
            black_box(ours3(&x.perm, &x.g3f));
        }),
        best_time(r, || {
            black_box(theirs3(&x.perlin, &x.g3));
        }),
    );
    let mut out3 = vec![0.0f32; x.g3.len()];
    line(
        "perlin3 grid, row API",
        x.g3.len(),
        best_time(r, || {
            black_box(ours3_rows(&x.perm, &x.r3, &mut out3));
        }),
        best_time(r, || {
            black_box(theirs3(&x.perlin, &x.g3));
        }),
    );
    line(
        "perlin3 scattered",
        x.s3.len(),
        best_time(r, || {
            black_box(ours3(&x.perm, &x.s3f));
        }),
        best_time(r, || {
            black_box(theirs3(&x.perlin, &x.s3));
        }),
    );
    let mut ours = vec![0.0f32; FBM_SIDE * FBM_SIDE];
    let mut theirs = vec![0.0f64; FBM_SIDE * FBM_SIDE];
    let fbm = their_fbm();
    let o = best_time(5, || ours_fbm(&x.perm, &mut ours));
    let t = best_time(5, || theirs_fbm(&fbm, &mut theirs));
    println!(
        "fbm 8 octaves 512x512: noise crate / inbetween time = {:.2} ({:.1} ms vs {:.1} ms)",
        t / o,
        o * 1e3,
        t * 1e3
    );
    let mut terrain = Terrain::new(FBM_SIDE).unwrap();
    let params = terrain_params();
    let tt = best_time(5, || terrain.regenerate(&x.perm, &params).unwrap());
    println!(
        "terrain 512x512, 8 octaves, exact normals and colours: {:.1} ms",
        tt * 1e3
    );
}

/// Each kernel's median time over `rounds` rounds, the kernels interleaved within a round (so a
/// change of the machine's load falls on all of them alike), in seconds.
fn interleaved(rounds: usize, kernels: &mut [(&str, &mut dyn FnMut())]) -> Vec<f64> {
    let mut times = vec![Vec::with_capacity(rounds); kernels.len()];
    for _ in 0..rounds {
        for (k, (_, f)) in kernels.iter_mut().enumerate() {
            let start = Instant::now();
            f();
            times[k].push(start.elapsed().as_secs_f64());
        }
    }
    times
        .into_iter()
        .map(|mut t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2]
        })
        .collect()
}

/// Prints a group of kernels timed by [`interleaved`]: each one's rate and its time relative to
/// the first (the group's reference).
fn print_group(title: &str, points: usize, kernels: &mut [(&str, &mut dyn FnMut())]) {
    let t = interleaved(11, kernels);
    println!("{title} ({points} points, median of 11 interleaved rounds):");
    for ((name, _), &tk) in kernels.iter().zip(&t) {
        println!(
            "  {name:<58} {:>7.1} M points/s  {:>5.2}x the first's speed",
            points as f64 / tk / 1e6,
            t[0] / tk
        );
    }
}

/// The scattered-point batches and the fast fractal sums against simdnoise (its SSE2 functions:
/// four points a call, the width our kernels have natively at the x86-64 baseline and in wasm)
/// and FastNoise Lite (one point a call, as its users call it). simdnoise computes simplex noise
/// and FastNoise Lite here Perlin noise, each with its own tables: the same work per point in
/// kind, not the same function.
fn print_batch_ratios(x: &Inputs) {
    let split = |pts: &[[f32; 3]], c: usize| pts.iter().map(|p| p[c]).collect::<Vec<f32>>();
    let (xs, ys, zs) = (split(&x.s3f, 0), split(&x.s3f, 1), split(&x.s3f, 2));
    let (xs2, ys2): (Vec<f32>, Vec<f32>) = x.s2f.iter().map(|p| (p[0], p[1])).unzip();
    let n = xs.len();
    let out = std::cell::RefCell::new(vec![0.0f32; n]);
    let sink = std::cell::Cell::new(0.0f32);
    let keep = |v: f32| sink.set(sink.get() + v);
    let fast = {
        let mut f = fastnoise_lite::FastNoiseLite::new();
        f.set_noise_type(Some(fastnoise_lite::NoiseType::Perlin));
        f.set_frequency(Some(1.0));
        f
    };
    print_group(
        "Perlin 3D at scattered points",
        n,
        &mut [
            (
                "inbetween Permutation::noise3, one point a call",
                &mut || keep(ours3(&x.perm, black_box(&x.s3f))),
            ),
            ("inbetween Permutation::noise3_batch", &mut || {
                let mut out = out.borrow_mut();
                x.perm.noise3_batch(black_box(&xs), &ys, &zs, &mut out);
                keep(out[n / 2]);
            }),
            (
                "FastNoise Lite 1.1 Perlin 3D, one point a call",
                &mut || {
                    keep(
                        x.s3f
                            .iter()
                            .map(|p| fast.get_noise_3d(p[0], p[1], p[2]))
                            .sum::<f32>(),
                    )
                },
            ),
            #[cfg(target_arch = "x86_64")]
            (
                "simdnoise 3.1 sse2::simplex_3d, 4 points a call",
                &mut || keep(simd3(black_box(&xs), &ys, &zs, &mut out.borrow_mut())),
            ),
        ],
    );
    print_group(
        "Perlin 2D at scattered points",
        n,
        &mut [
            (
                "inbetween Permutation::noise2, one point a call",
                &mut || keep(ours2(&x.perm, black_box(&x.s2f))),
            ),
            ("inbetween Permutation::noise2_batch", &mut || {
                let mut out = out.borrow_mut();
                x.perm.noise2_batch(black_box(&xs2), &ys2, &mut out);
                keep(out[n / 2]);
            }),
            (
                "FastNoise Lite 1.1 Perlin 2D, one point a call",
                &mut || {
                    keep(
                        x.s2f
                            .iter()
                            .map(|p| fast.get_noise_2d(p[0], p[1]))
                            .sum::<f32>(),
                    )
                },
            ),
            #[cfg(target_arch = "x86_64")]
            (
                "simdnoise 3.1 sse2::simplex_2d, 4 points a call",
                &mut || keep(simd2(black_box(&xs2), &ys2, &mut out.borrow_mut())),
            ),
        ],
    );
    // 8-octave fBm (α = ½, ω = 2) on the 512² grid, row by row.
    let side = FBM_SIDE;
    let step = 4.0 / side as f32;
    let row: Vec<f32> = (0..side).map(|i| i as f32 * step).collect();
    let (gx, gy): (Vec<f32>, Vec<f32>) = (0..side * side)
        .map(|k| ((k % side) as f32 * step, (k / side) as f32 * step))
        .unzip();
    let grid = std::cell::RefCell::new(vec![0.0f32; side * side]);
    let fbm = {
        let mut f = fastnoise_lite::FastNoiseLite::new();
        f.set_noise_type(Some(fastnoise_lite::NoiseType::Perlin));
        f.set_frequency(Some(1.0));
        f.set_fractal_type(Some(fastnoise_lite::FractalType::FBm));
        f.set_fractal_octaves(Some(8));
        f.set_fractal_lacunarity(Some(2.0));
        f.set_fractal_gain(Some(0.5));
        f
    };
    print_group(
        "fBm, 8 octaves of 2D noise, 512 x 512 grid",
        side * side,
        &mut [
            (
                "FastNoise Lite 1.1 FBm (Perlin), one point a call",
                &mut || {
                    let mut grid = grid.borrow_mut();
                    for (k, g) in grid.iter_mut().enumerate() {
                        *g = fbm.get_noise_2d(gx[k], gy[k]);
                    }
                    keep(grid[side]);
                },
            ),
            ("inbetween Fractal::sum2, one point a call", &mut || {
                let mut grid = grid.borrow_mut();
                ours_fbm(&x.perm, &mut grid);
                keep(grid[side]);
            }),
            ("inbetween Fractal::sum2_row, one row a call", &mut || {
                let mut grid = grid.borrow_mut();
                for (j, g) in grid.chunks_mut(side).enumerate() {
                    OURS_FBM.sum2_row(&x.perm, black_box(&row), j as f32 * step, g);
                }
                keep(grid[side]);
            }),
            (
                "inbetween Fractal::sum2_batch, the grid as scattered points",
                &mut || {
                    let mut grid = grid.borrow_mut();
                    OURS_FBM.sum2_batch(&x.perm, black_box(&gx), &gy, &mut grid);
                    keep(grid[side]);
                },
            ),
            #[cfg(target_arch = "x86_64")]
            ("simdnoise 3.1 sse2::fbm_2d, 4 points a call", &mut || {
                keep(simd_fbm2(black_box(&gx), &gy, &mut grid.borrow_mut()))
            }),
        ],
    );
    black_box(sink.get());
}

/// simdnoise's SSE2 simplex noise at the points, four at a time; returns one value (kept).
#[cfg(target_arch = "x86_64")]
fn simd3(xs: &[f32], ys: &[f32], zs: &[f32], out: &mut [f32]) -> f32 {
    use std::arch::x86_64::{_mm_loadu_ps, _mm_storeu_ps};
    for k in (0..xs.len() / 4 * 4).step_by(4) {
        // SAFETY: SSE2 is part of the x86-64 baseline; each load and store reads or writes four
        // f32s at k..k + 4, inside the slices.
        unsafe {
            let (x, y, z) = (
                _mm_loadu_ps(xs.as_ptr().add(k)),
                _mm_loadu_ps(ys.as_ptr().add(k)),
                _mm_loadu_ps(zs.as_ptr().add(k)),
            );
            _mm_storeu_ps(
                out.as_mut_ptr().add(k),
                simdnoise::sse2::simplex_3d(x, y, z, 0),
            );
        }
    }
    out[xs.len() / 2]
}

/// As [`simd3`], in 2D.
#[cfg(target_arch = "x86_64")]
fn simd2(xs: &[f32], ys: &[f32], out: &mut [f32]) -> f32 {
    use std::arch::x86_64::{_mm_loadu_ps, _mm_storeu_ps};
    for k in (0..xs.len() / 4 * 4).step_by(4) {
        // SAFETY: as in `simd3`.
        unsafe {
            let (x, y) = (
                _mm_loadu_ps(xs.as_ptr().add(k)),
                _mm_loadu_ps(ys.as_ptr().add(k)),
            );
            _mm_storeu_ps(
                out.as_mut_ptr().add(k),
                simdnoise::sse2::simplex_2d(x, y, 0),
            );
        }
    }
    out[xs.len() / 2]
}

/// simdnoise's SSE2 fBm (8 octaves, gain ½, lacunarity 2) at the points, four at a time.
#[cfg(target_arch = "x86_64")]
fn simd_fbm2(xs: &[f32], ys: &[f32], out: &mut [f32]) -> f32 {
    use std::arch::x86_64::{_mm_loadu_ps, _mm_set1_ps, _mm_storeu_ps};
    for k in (0..xs.len() / 4 * 4).step_by(4) {
        // SAFETY: as in `simd3`.
        unsafe {
            let (x, y) = (
                _mm_loadu_ps(xs.as_ptr().add(k)),
                _mm_loadu_ps(ys.as_ptr().add(k)),
            );
            let v = simdnoise::sse2::fbm_2d(x, y, _mm_set1_ps(2.0), _mm_set1_ps(0.5), 8, 0);
            _mm_storeu_ps(out.as_mut_ptr().add(k), v);
        }
    }
    out[xs.len() / 2]
}

fn main() {
    let x = inputs();
    if std::env::args().any(|a| a == "--batch-only") {
        print_batch_ratios(&x);
        return;
    }
    let mut c = Criterion::default().configure_from_args();
    bench_samples(&mut c, &x);
    bench_fbm(&mut c, &x);
    c.final_summary();
    print_ratios(&x);
    print_batch_ratios(&x);
}
