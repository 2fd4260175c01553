//! Rotation and rigid-motion benchmarks (native):
//! - slerp vs nlerp throughput (`quat_interp`),
//! - one rigid motion applied to 1e6 points, factored (rotation matrix + translation computed
//!   once) vs the naive per-point dual quaternion sandwich (`rigid_1e6_points`).
//!
//! Run: `cargo bench --features native-bench --bench rotation -- --warm-up-time 1 --measurement-time 2`.
//! After criterion's report, the ratios are printed from a short separate timing.

use std::hint::black_box;
use std::time::Instant;

use criterion::{Criterion, Throughput};
use glam::{Quat, Vec3};
use inbetween::rigid::DualQuat;
use inbetween::rotation::{nlerp, quat_from_axis_angle, slerp};

const PAIRS: usize = 4096;
const POINTS: usize = 1_000_000;

fn quat_pairs() -> Vec<(Quat, Quat)> {
    (0..PAIRS)
        .map(|i| {
            let f = i as f32;
            let a = quat_from_axis_angle(Vec3::new(f.sin(), f.cos(), 0.5).normalize(), f * 0.37);
            let b = quat_from_axis_angle(
                Vec3::new(0.3, (f * 1.7).sin(), f.cos()).normalize(),
                f * 0.11,
            );
            (a, b)
        })
        .collect()
}

fn points() -> Vec<Vec3> {
    (0..POINTS)
        .map(|i| {
            let f = i as f32 * 1e-3;
            Vec3::new(f.sin(), f.cos(), f * 0.5)
        })
        .collect()
}

fn motion() -> DualQuat {
    DualQuat::from_rotation_translation(
        quat_from_axis_angle(Vec3::new(1.0, 2.0, 3.0).normalize(), 1.2),
        Vec3::new(0.5, -1.0, 2.0),
    )
}

fn interp_all(pairs: &[(Quat, Quat)], f: fn(Quat, Quat, f32) -> Quat) -> Quat {
    let mut acc = Quat::IDENTITY;
    for (i, (a, b)) in pairs.iter().enumerate() {
        let t = (i % 17) as f32 / 16.0;
        let q = f(black_box(*a), black_box(*b), t);
        acc = Quat::from_vec4(glam::Vec4::from(acc) + glam::Vec4::from(q));
    }
    acc
}

fn bench_interp(c: &mut Criterion) {
    let pairs = quat_pairs();
    let mut group = c.benchmark_group("quat_interp");
    group.throughput(Throughput::Elements(PAIRS as u64));
    group.bench_function("slerp", |bencher| {
        bencher.iter(|| interp_all(&pairs, slerp))
    });
    group.bench_function("nlerp", |bencher| {
        bencher.iter(|| interp_all(&pairs, nlerp))
    });
    group.finish();
}

fn bench_points(c: &mut Criterion) {
    let input = points();
    let mut out = vec![Vec3::ZERO; POINTS];
    let q = motion();
    let mut group = c.benchmark_group("rigid_1e6_points");
    group.throughput(Throughput::Elements(POINTS as u64));
    group.sample_size(10);
    group.bench_function("factored", |bencher| {
        bencher.iter(|| {
            black_box(q)
                .transform_points(black_box(&input), &mut out)
                .unwrap();
            black_box(&mut out);
        })
    });
    group.bench_function("sandwich", |bencher| {
        bencher.iter(|| {
            black_box(q)
                .transform_points_sandwich(black_box(&input), &mut out)
                .unwrap();
            black_box(&mut out);
        })
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

fn print_ratios() {
    let pairs = quat_pairs();
    let slerp_s = best_time(200, || {
        black_box(interp_all(&pairs, slerp));
    });
    let nlerp_s = best_time(200, || {
        black_box(interp_all(&pairs, nlerp));
    });
    let input = points();
    let mut out = vec![Vec3::ZERO; POINTS];
    let q = motion();
    let factored_s = best_time(10, || {
        black_box(q)
            .transform_points(black_box(&input), &mut out)
            .unwrap();
        black_box(&mut out);
    });
    let sandwich_s = best_time(10, || {
        black_box(q)
            .transform_points_sandwich(black_box(&input), &mut out)
            .unwrap();
        black_box(&mut out);
    });
    println!(
        "ratio slerp / nlerp time: {:.2} ({:.1} vs {:.1} ns per pair)",
        slerp_s / nlerp_s,
        slerp_s * 1e9 / PAIRS as f64,
        nlerp_s * 1e9 / PAIRS as f64
    );
    println!(
        "ratio sandwich / factored time, 1e6 points: {:.2} ({:.2} ms vs {:.2} ms)",
        sandwich_s / factored_s,
        sandwich_s * 1e3,
        factored_s * 1e3
    );
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    bench_interp(&mut c);
    bench_points(&mut c);
    c.final_summary();
    print_ratios();
}
