//! Browser bench kernels for lesson 06 (same work as `benches/skeleton.rs`): sample + local-to-
//! model of the 60-joint benchmark humanoid (30 keys per channel) at 60 fps, with the runtime
//! [`Clip`] and with the per-channel `Track` baseline of the editable clip; and a crowd of
//! characters, each with its own time offset.

use crate::fixtures::Rng;
use crate::skeleton::{human, local_to_model, Clip, ClipCursor};
use glam::Affine3A;
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// The most frames (or characters) one call may ask for.
const MAX_FRAMES: usize = 1 << 20;

/// Times `iterations` passes of `frames` frames (1/60 s apart) of a skeleton kernel on the
/// 60-joint humanoid and returns milliseconds. `kernel` is "track_baseline" (the editable clip,
/// one cursor per channel, then local-to-model), "runtime_clip" (shared key times, key-major
/// values, then local-to-model), "runtime_sample_only" or "local_to_model_only". Per-item cost is
/// per frame; divide by 60 for joints.
/// Caps (the work grows with both): `frames` and `iterations` each in [1, 2²⁰] and
/// `frames × iterations` at most 2²⁴.
#[wasm_bindgen(js_name = benchSkeleton)]
pub fn bench_skeleton(kernel: JsValue, frames: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let frames = super::whole("frames", frames)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("frames", frames as u64, iterations, 1 << 24)?;
    if !(1..=MAX_FRAMES).contains(&frames) || !(1..=MAX_FRAMES).contains(&iterations) {
        return Err(JsError::new(
            "frames must be in [1, 2^20] and iterations in [1, 2^20]",
        ));
    }
    let (skeleton, raw) = human::benchmark_humanoid(&mut Rng::new(0x5eed_0060));
    let clip = Clip::from_raw(&raw, &skeleton).map_err(|e| JsError::new(&e.to_string()))?;
    let (parents, mode) = (skeleton.parents(), skeleton.scale_mode());
    let mut pose = skeleton.rest_pose();
    let mut model = vec![Affine3A::IDENTITY; skeleton.len()];
    let mut cursor = ClipCursor::new();
    let mut cursors = raw.cursors();
    let dt = 1.0 / 60.0;
    let start = now_ms();
    for _ in 0..iterations {
        for f in 0..frames {
            let t = std::hint::black_box(f as f32 * dt);
            match kernel {
                "track_baseline" => {
                    raw.sample(t, skeleton.rest(), &mut cursors, &mut pose);
                    local_to_model(parents, &pose.local, mode, &mut model);
                }
                "runtime_clip" => {
                    clip.sample(t, &mut cursor, &mut pose);
                    local_to_model(parents, &pose.local, mode, &mut model);
                }
                "runtime_sample_only" => clip.sample(t, &mut cursor, &mut pose),
                "local_to_model_only" => local_to_model(parents, &pose.local, mode, &mut model),
                other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
            }
        }
        std::hint::black_box(&model);
    }
    Ok(now_ms() - start)
}

/// Times `iterations` frames of a crowd of `characters` 60-joint humanoids (each sampled at its
/// own time offset with its own cursor, then local-to-model) and returns milliseconds.
/// `kernel` is "runtime_clip" or "track_baseline".
/// Caps (the work grows with both): `characters` in [1, 100000], `iterations` in [1, 2²⁰]
/// and `characters × iterations` at most 2²¹.
#[wasm_bindgen(js_name = benchCrowd)]
pub fn bench_crowd(kernel: JsValue, characters: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let characters = super::whole("characters", characters)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("characters", characters as u64, iterations, 1 << 21)?;
    if !(1..=100_000).contains(&characters) || !(1..=MAX_FRAMES).contains(&iterations) {
        return Err(JsError::new(
            "characters must be in [1, 100000] and iterations in [1, 2^20]",
        ));
    }
    let (skeleton, raw) = human::benchmark_humanoid(&mut Rng::new(0x5eed_0060));
    let clip = Clip::from_raw(&raw, &skeleton).map_err(|e| JsError::new(&e.to_string()))?;
    let (parents, mode) = (skeleton.parents(), skeleton.scale_mode());
    let mut pose = skeleton.rest_pose();
    let n = skeleton.len();
    let mut model = vec![Affine3A::IDENTITY; n * characters];
    let mut cursors = vec![ClipCursor::new(); characters];
    let mut track_cursors: Vec<_> = (0..characters).map(|_| raw.cursors()).collect();
    let baseline = match kernel {
        "runtime_clip" => false,
        "track_baseline" => true,
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    };
    let start = now_ms();
    for frame in 0..iterations {
        for c in 0..characters {
            let t = std::hint::black_box(frame as f32 / 60.0 + c as f32 * 0.137);
            if baseline {
                raw.sample(t, skeleton.rest(), &mut track_cursors[c], &mut pose);
            } else {
                clip.sample(t, &mut cursors[c], &mut pose);
            }
            local_to_model(parents, &pose.local, mode, &mut model[c * n..(c + 1) * n]);
        }
        std::hint::black_box(&model);
    }
    Ok(now_ms() - start)
}
