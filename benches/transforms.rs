//! Forward kinematics throughput: world matrices of a hierarchy, as the lesson computes them.
//!
//! Run: `cargo bench --features native-bench --bench transforms`. Compare within one run: `world_matrices` against a
//! baseline that only copies the local matrices (the memory traffic with no arithmetic).
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::{Mat4, Vec3};
use inbetween::fixtures::binary_tree_hierarchy;
use inbetween::transform::{local_matrix, world_matrices};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let n = 1024;
    let (parents, local) = binary_tree_hierarchy(n);
    let mut world = vec![Mat4::IDENTITY; n];
    let mut group = c.benchmark_group("hierarchy_1024_joints");
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function("copy_baseline", |b| {
        b.iter(|| world.copy_from_slice(black_box(&local)))
    });
    group.bench_function("world_matrices", |b| {
        b.iter(|| world_matrices(black_box(&parents), black_box(&local), &mut world))
    });
    group.bench_function("local_matrix_from_euler", |b| {
        b.iter(|| {
            for (i, l) in world.iter_mut().enumerate() {
                *l = local_matrix(black_box(Vec3::Y), black_box(Vec3::splat(i as f32)));
            }
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
