//! One step (1/120 s, 20 solver passes) of a heap of 1,000 balls and boxes that has fallen for
//! one second ([`inbetween::rigid_body::contact::heap`]), with the grid broad phase and with
//! every pair tested. Each iteration steps a copy of the same state (the copy is not timed).
//!
//! `cargo bench --features native-bench --bench rigid_body -- --warm-up-time 1 --measurement-time 3`
//! Criterion reports steps per second (one element = one step).

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use inbetween::rigid_body::contact::{heap, BroadPhase};

fn rigid_bodies(c: &mut Criterion) {
    let mut start = heap(1000).expect("valid");
    for _ in 0..120 {
        start.step(1.0 / 120.0).expect("valid");
    }
    let mut group = c.benchmark_group("rigid_body/step_1000_bodies");
    group.throughput(Throughput::Elements(1));
    group.sample_size(10);
    for (name, broad) in [
        ("grid", BroadPhase::Grid),
        ("all_pairs", BroadPhase::AllPairs),
    ] {
        let mut world = start.clone();
        world.broad_phase = broad;
        group.bench_function(name, |b| {
            b.iter_batched_ref(
                || world.clone(),
                |w| w.step(1.0 / 120.0).expect("valid"),
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

criterion_group!(benches, rigid_bodies);
criterion_main!(benches);
