//! One frame (10 substeps of 1/600 s) of a 100 × 100 cloth (10,000 particles, about 59,000
//! springs, 19,602 triangles) hanging from its top edge in the wind over a sphere and the ground,
//! with mass-spring and with XPBD ([`inbetween::cloth::benchmark_cloth`], the same cloth as the
//! browser bench page). Each iteration steps a copy of the same state (the copy is not timed).
//!
//! `cargo bench --features native-bench --bench cloth -- --warm-up-time 1 --measurement-time 2`
//! Criterion reports frames per second (one element = one frame of 10 substeps).

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use inbetween::cloth::{benchmark_cloth, Method};

fn cloth(c: &mut Criterion) {
    for side in [32i64, 100] {
        let mut group = c.benchmark_group(format!("cloth/frame_{side}x{side}_10_substeps"));
        group.throughput(Throughput::Elements(1));
        group.sample_size(10);
        for (name, method) in [("mass_spring", Method::MassSpring), ("xpbd", Method::Xpbd)] {
            let (mut start, params, colliders) = benchmark_cloth(side, method).expect("valid");
            // Let it fall into the wind a little first, so that collisions and stretch are live.
            for _ in 0..30 {
                start.step(&params, &colliders, 1.0 / 60.0).expect("valid");
            }
            assert!(start.exploded().is_none(), "{name} exploded");
            group.bench_function(name, |b| {
                b.iter_batched_ref(
                    || start.clone(),
                    |cloth| cloth.step(&params, &colliders, 1.0 / 60.0).expect("valid"),
                    BatchSize::LargeInput,
                )
            });
        }
        group.finish();
    }
}

criterion_group!(benches, cloth);
criterion_main!(benches);
