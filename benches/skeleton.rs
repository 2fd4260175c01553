//! Sample + local-to-model of a 60-joint humanoid (30 keys on every translation, rotation and
//! scale channel), played at 60 fps: the runtime [`Clip`] (shared key times, key-major values)
//! against the straightforward per-channel `Track` sampling of the editable [`RawClip`], in the
//! same run. Also each half alone, and slerp instead of nlerp.
//!
//! `cargo bench --features native-bench --bench skeleton -- --warm-up-time 1 --measurement-time 3`
//! Criterion reports joints per second (elements = joints × frames).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::Affine3A;
use inbetween::fixtures::Rng;
use inbetween::skeleton::{human, local_to_model, Clip, ClipCursor, QuatInterpolation};

/// Frames per measured iteration: ten seconds at 60 fps (the one-second clip loops ten times).
const FRAMES: usize = 600;
const DT_SEC: f32 = 1.0 / 60.0;

fn skeleton(c: &mut Criterion) {
    // The same input as the browser bench page (`src/web/bench_skeleton.rs`).
    let (skeleton, raw) = human::benchmark_humanoid(&mut Rng::new(0x5eed_0060));
    let clip = Clip::from_raw(&raw, &skeleton).expect("valid clip");
    let mut slerp_clip = clip.clone();
    slerp_clip.set_rotation_interpolation(QuatInterpolation::Slerp);
    let n = skeleton.len();
    let parents = skeleton.parents();
    let mode = skeleton.scale_mode();
    let mut pose = skeleton.rest_pose();
    let mut model = vec![Affine3A::IDENTITY; n];

    let mut group = c.benchmark_group(format!("skeleton/{n}_joints_30_keys"));
    group.throughput(Throughput::Elements((n * FRAMES) as u64));
    group.sample_size(20);
    group.bench_function("runtime_clip_sample_and_local_to_model", |b| {
        let mut cursor = ClipCursor::new();
        b.iter(|| {
            for f in 0..FRAMES {
                clip.sample(black_box(f as f32 * DT_SEC), &mut cursor, &mut pose);
                local_to_model(parents, &pose.local, mode, &mut model);
            }
            black_box(&model);
        });
    });
    group.bench_function("track_baseline_sample_and_local_to_model", |b| {
        let mut cursors = raw.cursors();
        b.iter(|| {
            for f in 0..FRAMES {
                raw.sample(
                    black_box(f as f32 * DT_SEC),
                    skeleton.rest(),
                    &mut cursors,
                    &mut pose,
                );
                local_to_model(parents, &pose.local, mode, &mut model);
            }
            black_box(&model);
        });
    });
    group.bench_function("runtime_clip_sample_only", |b| {
        let mut cursor = ClipCursor::new();
        b.iter(|| {
            for f in 0..FRAMES {
                clip.sample(black_box(f as f32 * DT_SEC), &mut cursor, &mut pose);
            }
            black_box(&pose);
        });
    });
    group.bench_function("local_to_model_only", |b| {
        b.iter(|| {
            for _ in 0..FRAMES {
                local_to_model(parents, black_box(&pose.local), mode, &mut model);
            }
            black_box(&model);
        });
    });
    group.bench_function("runtime_clip_slerp_sample_and_local_to_model", |b| {
        let mut cursor = ClipCursor::new();
        b.iter(|| {
            for f in 0..FRAMES {
                slerp_clip.sample(black_box(f as f32 * DT_SEC), &mut cursor, &mut pose);
                local_to_model(parents, &pose.local, mode, &mut model);
            }
            black_box(&model);
        });
    });
    group.finish();
}

criterion_group!(benches, skeleton);
criterion_main!(benches);
