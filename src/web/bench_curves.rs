//! Browser bench kernels for lesson 02 (same work as `benches/curves.rs`): sampling a 100-key
//! `Vec3` track, in increasing time order with a [`Cursor`](crate::curves::Cursor) and at random
//! times with a binary search per sample, for linear and Catmull-Rom interpolation.

use crate::curves::Interpolation;
use glam::Vec3;
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// Times `iterations` passes of a sampling kernel over `samples` times on a 100-key `Vec3` track
/// (non-uniform key times) and returns milliseconds. `kernel` is one of
/// "copy_baseline" (copying precomputed positions: the memory traffic alone),
/// "linear_cursor", "linear_binary_search", "catmull_rom_cursor", "catmull_rom_binary_search".
/// Cursor kernels sample in increasing time order; binary-search kernels at random times.
/// Caps (the work grows with both): `samples` in [1, 2²²], `iterations` in [1, 2²⁰] and
/// `samples × iterations` at most 2²⁹.
#[wasm_bindgen(js_name = benchCurves)]
pub fn bench_curves(kernel: JsValue, samples: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let samples = super::whole("samples", samples)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("samples", samples as u64, iterations, 1 << 29)?;
    if !(1..=1 << 22).contains(&samples) || !(1..=1 << 20).contains(&iterations) {
        return Err(JsError::new(
            "samples must be in [1, 2^22] and iterations in [1, 2^20]",
        ));
    }
    // The same input as `benches/curves.rs`.
    let (base, increasing, random) = crate::fixtures::sampling_benchmark(
        100,
        samples,
        &mut crate::fixtures::Rng::new(0x2545_f491),
    );
    let (scheme, by_cursor) = match kernel {
        "copy_baseline" | "linear_cursor" => (Interpolation::Linear, true),
        "linear_binary_search" => (Interpolation::Linear, false),
        "catmull_rom_cursor" => (Interpolation::CATMULL_ROM, true),
        "catmull_rom_binary_search" => (Interpolation::CATMULL_ROM, false),
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    };
    let track = base
        .with_interpolation(scheme)
        .map_err(|e| JsError::new(&e.to_string()))?;
    let mut out = vec![Vec3::ZERO; samples];
    let precomputed = {
        let mut p = vec![Vec3::ZERO; samples];
        track.positions(&increasing, &mut p);
        p
    };
    let start_ms = now_ms();
    for _ in 0..iterations {
        if kernel == "copy_baseline" {
            out.copy_from_slice(std::hint::black_box(&precomputed));
        } else if by_cursor {
            track.positions(std::hint::black_box(&increasing), &mut out);
        } else {
            for (slot, &t) in out.iter_mut().zip(std::hint::black_box(&random)) {
                *slot = track.position(t);
            }
        }
        std::hint::black_box(&mut out);
    }
    let elapsed = now_ms() - start_ms;
    std::hint::black_box(&out);
    Ok(elapsed)
}
