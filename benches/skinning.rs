//! Skinning 100,000 vertices with 4 influences each over a 60-joint palette, positions and
//! normals: the plain scalar loop (the baseline, the same loop the bench page runs in JavaScript)
//! against linear blend skinning with separate arrays and with interleaved vertices, and dual
//! quaternion skinning (with and without turning the palette into dual quaternions), each also
//! with the portable kernel (the one wasm runs), and LBS of positions only, in the same run.
//!
//! `cargo bench --features native-bench --bench skinning -- --warm-up-time 1 --measurement-time 2`
//! Criterion reports vertices per second.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::Vec3;
use inbetween::rigid::DualQuat;
use inbetween::skinning::rigs::benchmark_input;
use inbetween::skinning::{
    dual_quat_palette, skin_dqs, skin_dqs_with, skin_lbs, skin_lbs_interleaved,
    skin_lbs_plain_loop, skin_lbs_positions, skin_lbs_with, LbsKernel, SkinVertex,
};

const VERTICES: usize = 100_000;

fn skinning(c: &mut Criterion) {
    // The same input as the browser bench page (`src/web/bench_skinning.rs`).
    let input = benchmark_input(VERTICES, 0x5eed_0009);
    let (palette_flat, joints_flat, weights_flat, positions_flat, normals_flat) = input.flat();
    let interleaved = SkinVertex::interleave(&input.skin, &input.positions, &input.normals)
        .expect("matching lengths");
    let mut out_p = vec![Vec3::ZERO; VERTICES];
    let mut out_n = vec![Vec3::ZERO; VERTICES];
    let mut flat_p = vec![0.0f32; 3 * VERTICES];
    let mut flat_n = vec![0.0f32; 3 * VERTICES];
    let mut dq = vec![DualQuat::IDENTITY; input.palette.len()];

    let mut group = c.benchmark_group("skinning/100k_vertices_4_influences_60_joints");
    group.throughput(Throughput::Elements(VERTICES as u64));
    group.sample_size(20);
    group.bench_function("plain_scalar_loop_baseline", |b| {
        b.iter(|| {
            skin_lbs_plain_loop(
                black_box(&palette_flat),
                &joints_flat,
                &weights_flat,
                &positions_flat,
                &normals_flat,
                &mut flat_p,
                &mut flat_n,
            );
            black_box(&flat_p);
        });
    });
    group.bench_function("lbs_separate_arrays", |b| {
        b.iter(|| {
            skin_lbs(
                black_box(&input.palette),
                &input.skin,
                &input.positions,
                &input.normals,
                &mut out_p,
                &mut out_n,
            )
            .unwrap();
            black_box(&out_p);
        });
    });
    // `skin_lbs` runs the AVX2 + FMA kernel where the CPU has it; this is the portable SSE2 one
    // (the same code the wasm build runs, through simd128), measured in the same run.
    eprintln!("skin_lbs runs {:?}", LbsKernel::best());
    group.bench_function("lbs_separate_arrays_portable_kernel", |b| {
        b.iter(|| {
            skin_lbs_with(
                LbsKernel::Portable,
                black_box(&input.palette),
                &input.skin,
                &input.positions,
                &input.normals,
                &mut out_p,
                &mut out_n,
            )
            .unwrap();
            black_box(&out_p);
        });
    });
    group.bench_function("lbs_positions_only_portable_kernel", |b| {
        b.iter(|| {
            skin_lbs_positions(
                black_box(&input.palette),
                &input.skin,
                &input.positions,
                &mut out_p,
            )
            .unwrap();
            black_box(&out_p);
        });
    });
    group.bench_function("lbs_interleaved", |b| {
        b.iter(|| {
            skin_lbs_interleaved(
                black_box(&input.palette),
                &interleaved,
                &mut out_p,
                &mut out_n,
            )
            .unwrap();
            black_box(&out_p);
        });
    });
    dual_quat_palette(&input.palette, &mut dq).unwrap();
    group.bench_function("dqs", |b| {
        b.iter(|| {
            skin_dqs(
                black_box(&dq),
                &input.skin,
                &input.positions,
                &input.normals,
                &mut out_p,
                &mut out_n,
            )
            .unwrap();
            black_box(&out_p);
        });
    });
    group.bench_function("dqs_portable_kernel", |b| {
        b.iter(|| {
            skin_dqs_with(
                LbsKernel::Portable,
                black_box(&dq),
                &input.skin,
                &input.positions,
                &input.normals,
                &mut out_p,
                &mut out_n,
            )
            .unwrap();
            black_box(&out_p);
        });
    });
    group.bench_function("dqs_with_palette_conversion", |b| {
        b.iter(|| {
            dual_quat_palette(black_box(&input.palette), &mut dq).unwrap();
            skin_dqs(
                &dq,
                &input.skin,
                &input.positions,
                &input.normals,
                &mut out_p,
                &mut out_n,
            )
            .unwrap();
            black_box(&out_p);
        });
    });
    group.finish();
}

criterion_group!(benches, skinning);
criterion_main!(benches);
