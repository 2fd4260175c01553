//! Kernels for the browser bench page, lesson 05: the 512 × 512 terrain of `benches/perlin.rs`
//! and noise at scattered points, timed inside wasm with `performance.now()`.

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
/// vertex, one `Fractal::sum2` call each, values only), "fbm8_rows" (the same values, one
/// `Fractal::sum2_row` call per row), "fbm8_batch" (one `Fractal::sum2_batch` call over every
/// vertex) or "terrain_with_normals" (heights, exact normals and colours in place).
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
    let row: Vec<f32> = (0..side).map(|i| -1.0 + i as f32 * step).collect();
    let (us, vs): (Vec<f32>, Vec<f32>) = (0..size)
        .map(|k| (row[k % side], row[k / side]))
        .unzip();
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
            "fbm8_rows" => {
                for (j, h) in heights.chunks_mut(side).enumerate() {
                    FBM8.sum2_row(&perm, &row, row[j], h);
                }
                std::hint::black_box(&heights);
            }
            "fbm8_batch" => {
                FBM8.sum2_batch(&perm, &us, &vs, &mut heights);
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

/// The scattered points of [`bench_noise`]: `size` points, x, y, z in [−100, 100), the same on
/// every call (seed 77, as `benches/perlin.rs`), flattened as `[x0, y0, z0, x1, …]`, so that the
/// page's JavaScript kernels run on the wasm kernels' input. Cap: `size` from 1 to 2²⁰.
#[wasm_bindgen(js_name = noiseBenchInput)]
pub fn noise_bench_input(size: f64) -> Result<Vec<f32>, JsError> {
    let size = super::whole_in("size", size, 1, 1 << 20)?;
    Ok(scattered(size).into_iter().flatten().collect())
}

fn scattered(size: usize) -> Vec<[f32; 3]> {
    let mut rng = crate::fixtures::Rng::new(77);
    (0..size)
        .map(|_| std::array::from_fn(|_| rng.range(-100.0, 100.0)))
        .collect()
}

/// Times `iterations` passes of Perlin noise over `size` scattered points (those of
/// [`noise_bench_input`]); milliseconds. `kernel`: "noise3_per_point" (one `Permutation::noise3`
/// call a point), "noise3_batch" (one `Permutation::noise3_batch` call for all), and the same in
/// 2D ("noise2_per_point", "noise2_batch", at the points' x, y). Caps (the work grows with both):
/// `size` from 1 to 2²⁰, `iterations` from 1 to 2²⁰, `size × iterations` at most 2²⁹.
#[wasm_bindgen(js_name = benchNoise)]
pub fn bench_noise(kernel: JsValue, size: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let size = super::whole_in("size", size, 1, 1 << 20)?;
    let iterations = super::whole_in("iterations", iterations, 1, 1 << 20)?;
    super::check_work("size", size as u64, iterations, 1 << 29)?;
    if !matches!(
        kernel,
        "noise3_per_point" | "noise3_batch" | "noise2_per_point" | "noise2_batch"
    ) {
        return Err(JsError::new(&format!("unknown kernel '{kernel}'")));
    }
    let perm = Permutation::perlin();
    let points = scattered(size);
    let [xs, ys, zs]: [Vec<f32>; 3] = std::array::from_fn(|c| points.iter().map(|p| p[c]).collect());
    let mut out = vec![0.0f32; size];
    let start = now_ms();
    for _ in 0..iterations {
        match kernel {
            "noise3_per_point" => {
                for (o, p) in out.iter_mut().zip(&points) {
                    *o = perm.noise3(p[0], p[1], p[2]);
                }
            }
            "noise3_batch" => perm.noise3_batch(&xs, &ys, &zs, &mut out),
            "noise2_per_point" => {
                for (o, p) in out.iter_mut().zip(&points) {
                    *o = perm.noise2(p[0], p[1]);
                }
            }
            _ => perm.noise2_batch(&xs, &ys, &mut out),
        }
        std::hint::black_box(&out);
    }
    Ok(now_ms() - start)
}

/// Perlin's permutation table (the 256 entries of `Permutation::perlin`), for the page's
/// JavaScript noise loop (www/noise-loop.js).
#[wasm_bindgen(js_name = perlinTable)]
pub fn perlin_table() -> Vec<u8> {
    Permutation::perlin().table().to_vec()
}

/// `Permutation::perlin().noise3` at each point of `xyz` (`[x0, y0, z0, x1, …]`): the bench page
/// checks its JavaScript Perlin loop against it before timing (the two must compute the same
/// function). Cap: at most 2²⁰ points; a length that is not a multiple of 3 is an error.
#[wasm_bindgen(js_name = perlinNoise3)]
pub fn perlin_noise3(xyz: Vec<f32>) -> Result<Vec<f32>, JsError> {
    if xyz.len() % 3 != 0 || xyz.len() > 3 << 20 {
        return Err(JsError::new(&format!(
            "xyz must hold whole points (3 numbers each), at most 2^20 of them, got {} numbers",
            xyz.len()
        )));
    }
    let perm = Permutation::perlin();
    Ok(xyz.chunks(3).map(|p| perm.noise3(p[0], p[1], p[2])).collect())
}
