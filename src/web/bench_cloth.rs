//! Browser bench kernel for lesson 13 (same work as `benches/cloth.rs`): one frame of 10 substeps
//! of the benchmark cloth ([`crate::cloth::benchmark_cloth`]) with mass-spring or XPBD.

use crate::cloth::{benchmark_cloth, Method};
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// The largest side the bench accepts (the page's cloths go to 100).
const MAX_BENCH_SIDE: usize = 256;

/// Times `iterations` frames (10 substeps of 1/600 s each) of a `side × side` cloth and returns
/// milliseconds. `kernel` is "mass_spring" or "xpbd". The cloth falls for 30 frames first (not
/// timed); each timed frame starts from that same state (the copy back is timed too, and is small
/// next to a frame).
/// Caps (the work grows with both): `side` in [2, 256], `iterations` in [1, 2²⁰] and
/// `side² × 10 × iterations` at most 2²⁷.
#[wasm_bindgen(js_name = benchCloth)]
pub fn bench_cloth(kernel: JsValue, side: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let side = super::whole("side", side)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work(
        "side² × 10 substeps",
        (side as u64).pow(2).saturating_mul(10),
        iterations,
        1 << 27,
    )?;
    if !(2..=MAX_BENCH_SIDE).contains(&side) || !(1..=1 << 20).contains(&iterations) {
        return Err(JsError::new(&format!(
            "side must be in [2, {MAX_BENCH_SIDE}] and iterations in [1, 2^20]"
        )));
    }
    let method = match kernel {
        "mass_spring" => Method::MassSpring,
        "xpbd" => Method::Xpbd,
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    };
    let (mut cloth, params, colliders) =
        benchmark_cloth(side as i64, method).map_err(|e| JsError::new(&e.to_string()))?;
    for _ in 0..30 {
        cloth
            .step(&params, &colliders, 1.0 / 60.0)
            .map_err(|e| JsError::new(&e.to_string()))?;
    }
    let (positions, velocities) = (cloth.positions.clone(), cloth.velocities.clone());
    let start = now_ms();
    for _ in 0..iterations {
        cloth.positions.copy_from_slice(&positions);
        cloth.velocities.copy_from_slice(&velocities);
        cloth
            .step(&params, &colliders, 1.0 / 60.0)
            .map_err(|e| JsError::new(&e.to_string()))?;
    }
    std::hint::black_box(&cloth.positions);
    Ok(now_ms() - start)
}
