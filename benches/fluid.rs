//! One step of the 3D dam break (src/fluid, `benchmark_fluid`: after a tenth of a second of
//! fall), SPH and PBF, at 10,000 and 50,000 particles (kernel radius 2 spacings, about 33
//! neighbours), one step of the 2D one at 10,000 particles (2.7 spacings, about 23), and the
//! neighbour search alone at 10,000 particles with the grid and with every pair tested. Each
//! iteration steps a copy of the same state (the copy is not timed).
//!
//! `cargo bench --features native-bench --bench fluid -- --warm-up-time 1 --measurement-time 3`
//! Criterion reports steps per second (one element = one step).

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use inbetween::fluid::{benchmark_fluid, Dim, Fluid, Method, Search};

fn fluid(method: Method, count: usize) -> Fluid {
    benchmark_fluid(Dim::Three, method, count).expect("valid")
}

fn steps(c: &mut Criterion) {
    for count in [10_000, 50_000] {
        let mut group = c.benchmark_group(format!("fluid/step_3d_{count}"));
        group.throughput(Throughput::Elements(1));
        group.sample_size(10);
        for (name, method) in [("sph", Method::Sph), ("pbf_4_iterations", Method::Pbf)] {
            let start = fluid(method, count);
            group.bench_function(name, |b| {
                b.iter_batched_ref(|| start.clone(), |f| f.step(), BatchSize::LargeInput)
            });
        }
        group.finish();
    }
    let mut group = c.benchmark_group("fluid/step_2d_10000");
    group.throughput(Throughput::Elements(1));
    group.sample_size(10);
    for (name, method) in [("sph", Method::Sph), ("pbf_4_iterations", Method::Pbf)] {
        let start = benchmark_fluid(Dim::Two, method, 10_000).expect("valid");
        group.bench_function(name, |b| {
            b.iter_batched_ref(|| start.clone(), |f| f.step(), BatchSize::LargeInput)
        });
    }
    group.finish();
    let mut group = c.benchmark_group("fluid/search_3d_10000");
    group.throughput(Throughput::Elements(1));
    group.sample_size(10);
    let start = fluid(Method::Sph, 10_000);
    for (name, search) in [("grid", Search::Grid), ("all_pairs", Search::AllPairs)] {
        let mut f = start.clone();
        f.set_search(search);
        group.bench_function(name, |b| b.iter(|| f.search()));
    }
    group.finish();
}

criterion_group!(benches, steps);
criterion_main!(benches);
