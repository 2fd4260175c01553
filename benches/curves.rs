//! Sampling a 100-key `Vec3` track 10⁶ times: in increasing time order with a cursor, and at
//! random times with a binary search per sample; linear and Catmull-Rom.
//!
//! `cargo bench --features native-bench --bench curves -- --warm-up-time 1 --measurement-time 2`
//! Criterion reports the throughput in samples (elements) per second.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::Vec3;
use inbetween::curves::Interpolation;
use inbetween::fixtures::{sampling_benchmark, Rng};

const KEYS: usize = 100;
const SAMPLES: usize = 1_000_000;

fn sampling(c: &mut Criterion) {
    // The same input as the browser bench page (`src/web/bench_curves.rs`).
    let (base, increasing, random) = sampling_benchmark(KEYS, SAMPLES, &mut Rng::new(0x2545_f491));
    let mut out = vec![Vec3::ZERO; SAMPLES];

    for (name, scheme) in [
        ("linear", Interpolation::Linear),
        ("catmull_rom", Interpolation::CATMULL_ROM),
    ] {
        let track = base
            .clone()
            .with_interpolation(scheme)
            .expect("valid scheme");
        let mut group = c.benchmark_group(format!("curves/{name}"));
        group.throughput(Throughput::Elements(SAMPLES as u64));
        group.sample_size(10);
        group.bench_function("cursor_increasing", |b| {
            b.iter(|| track.positions(black_box(&increasing), &mut out));
        });
        group.bench_function("binary_search_random", |b| {
            b.iter(|| {
                for (slot, &t) in out.iter_mut().zip(black_box(&random)) {
                    *slot = track.position(t);
                }
            });
        });
        group.bench_function("binary_search_increasing", |b| {
            b.iter(|| {
                for (slot, &t) in out.iter_mut().zip(black_box(&increasing)) {
                    *slot = track.position(t);
                }
            });
        });
        group.finish();
        black_box(&out);
    }
}

criterion_group!(benches, sampling);
criterion_main!(benches);
