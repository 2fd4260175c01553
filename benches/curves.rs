//! Sampling a 100-key `Vec3` track 10⁶ times: in increasing time order with a cursor, and at
//! random times with a binary search per sample; linear and Catmull-Rom.
//!
//! `cargo bench --bench curves -- --warm-up-time 1 --measurement-time 2`
//! Criterion reports the throughput in samples (elements) per second.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::Vec3;
use inbetween::curves::{Interpolation, Track};

const KEYS: usize = 100;
const SAMPLES: usize = 1_000_000;

/// xorshift32: a tiny deterministic generator, enough for benchmark inputs.
struct XorShift(u32);

impl XorShift {
    /// Uniform in `[0, 1)`.
    fn next_f32(&mut self) -> f32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        (x >> 8) as f32 / (1 << 24) as f32
    }
}

/// 100 keys at non-uniform times (steps of 0.05 to 0.15 s) with random positions.
fn bench_track(rng: &mut XorShift) -> Track<Vec3> {
    let mut times = Vec::with_capacity(KEYS);
    let mut values = Vec::with_capacity(KEYS);
    let mut t = 0.0;
    for _ in 0..KEYS {
        times.push(t);
        t += 0.05 + 0.1 * rng.next_f32();
        values.push(Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) * 10.0);
    }
    Track::new(times, values).expect("valid benchmark keys")
}

fn sampling(c: &mut Criterion) {
    let mut rng = XorShift(0x2545_f491);
    let base = bench_track(&mut rng);
    let (start, duration) = (base.start_sec(), base.duration_sec());
    let increasing: Vec<f32> = (0..SAMPLES)
        .map(|k| start + duration * k as f32 / SAMPLES as f32)
        .collect();
    let random: Vec<f32> = (0..SAMPLES)
        .map(|_| start + duration * rng.next_f32())
        .collect();
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
