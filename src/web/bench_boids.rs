//! Browser bench kernel for lesson 12 (same work as `benches/boids.rs`): one boids step on the
//! benchmark flock ([`crate::boids::benchmark_flock`]) with the grid or the naive search.

use crate::boids::{benchmark_flock, Search, MAX_BOIDS};
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// The most boids the naive kernel accepts: its step is quadratic (20k boids is 4·10⁸ tests).
const MAX_NAIVE_BOIDS: usize = 20_000;

/// Times `iterations` steps of a flock of `boids` boids and returns milliseconds (building the
/// flock and the first grid is not timed; restoring the start state before each step is). `kernel` is "grid" or "naive".
/// Caps (the work grows with both): `boids` in [1, 200000], `iterations` in [1, 2²⁰],
/// `boids × iterations` at most 2²⁵; the naive kernel at most 20000 boids and `boids² ×
/// iterations` at most 2³².
#[wasm_bindgen(js_name = benchBoids)]
pub fn bench_boids(kernel: JsValue, boids: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let boids = super::whole("boids", boids)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("boids", boids as u64, iterations, 1 << 25)?;
    if !(1..=MAX_BOIDS).contains(&boids) || !(1..=1 << 20).contains(&iterations) {
        return Err(JsError::new(&format!(
            "boids must be in [1, {MAX_BOIDS}] and iterations in [1, 2^20]"
        )));
    }
    let search = match kernel {
        "grid" => Search::Grid,
        "naive" if boids <= MAX_NAIVE_BOIDS => {
            // The naive step tests every pair: its work grows with the square of the count.
            super::check_work("boids²", (boids as u64).pow(2), iterations, 1 << 32)?;
            Search::Naive
        }
        "naive" => {
            return Err(JsError::new(&format!(
                "the naive kernel takes at most {MAX_NAIVE_BOIDS} boids"
            )))
        }
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    };
    let (params, mut flock) = benchmark_flock(boids).map_err(|e| JsError::new(&e))?;
    flock.step(&params, search, 1.0 / 60.0);
    // Every iteration steps the same state (a flock stepped many times clusters and its cost
    // drifts); restoring it is a copy of two arrays, small next to a step.
    let (positions, velocities) = (flock.positions.clone(), flock.velocities.clone());
    let start = now_ms();
    for _ in 0..iterations {
        flock.positions.copy_from_slice(&positions);
        flock.velocities.copy_from_slice(&velocities);
        flock.step(&params, search, 1.0 / 60.0);
    }
    std::hint::black_box(&flock.positions);
    Ok(now_ms() - start)
}
