//! One boids step (neighbour search, steering, semi-implicit Euler) at N = 1k, 10k and 100k
//! boids, with the uniform grid and with the naive O(N²) search (1k and 10k only: at 100k the
//! naive step is 10¹⁰ distance tests; the naive search runs the grid's SIMD loop over a single
//! cell, so the ratio measures the search structure alone). Same flock as the browser bench page
//! ([`inbetween::boids::benchmark_flock`]: one boid per m³, about 14 neighbours each).
//!
//! Each iteration steps a copy of the same flock (the copy is not timed).
//!
//! `cargo bench --features native-bench --bench boids -- --warm-up-time 1 --measurement-time 2`
//! Criterion reports boids per second; compare grid and naive at the same N.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use inbetween::boids::{benchmark_flock, Search};

fn boids(c: &mut Criterion) {
    for n in [1_000usize, 10_000, 100_000] {
        let mut group = c.benchmark_group(format!("boids/step_{n}"));
        group.throughput(Throughput::Elements(n as u64));
        group.sample_size(10);
        let (params, flock) = benchmark_flock(n).expect("under the cap");
        let mut searches = vec![("grid", Search::Grid)];
        if n <= 10_000 {
            searches.push(("naive", Search::Naive));
        }
        for (name, search) in searches {
            let mut start = flock.clone();
            start.step(&params, search, 1.0 / 60.0); // size the grid outside the timing
                                                     // Every iteration steps the same state: a flock stepped hundreds of times clusters,
                                                     // and the cost per step would drift with the number of iterations.
            group.bench_function(name, |b| {
                b.iter_batched_ref(
                    || start.clone(),
                    |f| f.step(&params, search, 1.0 / 60.0),
                    BatchSize::LargeInput,
                )
            });
        }
        group.finish();
    }
}

criterion_group!(benches, boids);
criterion_main!(benches);
