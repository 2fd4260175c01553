//! Kernels for the browser bench page, lesson 05: the 512 × 512 terrain of `benches/perlin.rs`,
//! timed inside wasm with `performance.now()`.

use crate::noise::{Fractal, Permutation};
use crate::terrain::{Terrain, TerrainParams};
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// 8 octaves: N = 7, α = ½, ω = 2.
const FBM8: Fractal = Fractal {
    n: 7,
    alpha: 0.5,
    omega: 2.0,
};

/// Times `iterations` regenerations of a square terrain of `size` vertices (a perfect square, at
/// most 1024²); milliseconds. `kernel` is "fbm8_values" (the baseline: the 8-octave sum at every
/// vertex, values only) or "terrain_with_normals" (heights, exact normals and colours in place).
/// Caps (the work grows with both): `iterations` at least 1 and `size × iterations` at most
/// 2²⁹.
#[wasm_bindgen(js_name = benchTerrain)]
pub fn bench_terrain(kernel: JsValue, size: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let size = super::whole("size", size)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("size", size as u64, iterations, 1 << 29)?;
    let side = (size as f64).sqrt().round() as usize;
    if side * side != size || !(2..=crate::terrain::MAX_RESOLUTION).contains(&side) {
        return Err(JsError::new(&format!(
            "size must be a square of 2 to {} vertices per side, got {size}",
            crate::terrain::MAX_RESOLUTION
        )));
    }
    if !(1..=1 << 20).contains(&iterations) {
        return Err(JsError::new("iterations must be in [1, 2^20]"));
    }
    let perm = Permutation::perlin();
    let params = TerrainParams {
        fractal: FBM8,
        ..TerrainParams::default()
    };
    let mut terrain = Terrain::new(side).map_err(|e| JsError::new(&e))?;
    let mut heights = vec![0.0f32; size];
    let step = 2.0 / (side - 1) as f32;
    let start = now_ms();
    for _ in 0..iterations {
        match kernel {
            "fbm8_values" => {
                for (k, h) in heights.iter_mut().enumerate() {
                    let (u, v) = (
                        -1.0 + (k % side) as f32 * step,
                        -1.0 + (k / side) as f32 * step,
                    );
                    *h = FBM8.sum2(&perm, u, v);
                }
                std::hint::black_box(&heights);
            }
            "terrain_with_normals" => {
                terrain
                    .regenerate(&perm, std::hint::black_box(&params))
                    .map_err(|e| JsError::new(&e))?;
                std::hint::black_box(&terrain.normals);
            }
            other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
        }
    }
    Ok(now_ms() - start)
}
