//! Browser bench kernels for lesson 09 (same work as `benches/skinning.rs`): 100,000 vertices with
//! four influences over the 60-joint benchmark humanoid's palette, positions and normals, by the
//! plain scalar loop, LBS (separate arrays, interleaved) and DQS. The bench page times the same
//! plain loop written in JavaScript on [`skinning_bench_input`]'s arrays, in the same page.

use crate::rigid::DualQuat;
use crate::skinning::rigs::benchmark_input;
use crate::skinning::{
    dual_quat_palette, skin_dqs, skin_lbs, skin_lbs_interleaved, skin_lbs_plain_loop, SkinVertex,
};
use glam::Vec3;
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// The most vertices a bench call may ask for, and the most iterations.
const MAX_VERTICES: usize = 1 << 20;
const MAX_ITERATIONS: usize = 1 << 20;
const SEED: u64 = 0x5eed_0009;

fn check(vertices: usize, iterations: usize) -> Result<(), JsError> {
    if !(1..=MAX_VERTICES).contains(&vertices) || !(1..=MAX_ITERATIONS).contains(&iterations) {
        return Err(JsError::new(
            "vertices must be in [1, 2^20] and iterations in [1, 2^20]",
        ));
    }
    Ok(())
}

/// Times `iterations` passes of a skinning kernel over `vertices` vertices and returns
/// milliseconds. `kernel` is "wasm_plain_loop", "lbs", "lbs_interleaved" or "dqs" (DQS includes
/// turning the palette into dual quaternions, once per pass).
#[wasm_bindgen(js_name = benchSkinning)]
pub fn bench_skinning(kernel: &str, vertices: usize, iterations: usize) -> Result<f64, JsError> {
    check(vertices, iterations)?;
    let input = benchmark_input(vertices, SEED);
    let mut out_p = vec![Vec3::ZERO; vertices];
    let mut out_n = vec![Vec3::ZERO; vertices];
    let err = |e: crate::skinning::SkinningError| JsError::new(&e.to_string());
    let start;
    match kernel {
        "wasm_plain_loop" => {
            let (pal, j, w, pos, nrm) = input.flat();
            let (mut fp, mut fn_) = (vec![0.0f32; 3 * vertices], vec![0.0f32; 3 * vertices]);
            start = now_ms();
            for _ in 0..iterations {
                skin_lbs_plain_loop(
                    std::hint::black_box(&pal),
                    &j,
                    &w,
                    &pos,
                    &nrm,
                    &mut fp,
                    &mut fn_,
                );
                std::hint::black_box(&fp);
            }
        }
        "lbs" => {
            start = now_ms();
            for _ in 0..iterations {
                skin_lbs(
                    std::hint::black_box(&input.palette),
                    &input.skin,
                    &input.positions,
                    &input.normals,
                    &mut out_p,
                    &mut out_n,
                )
                .map_err(err)?;
                std::hint::black_box(&out_p);
            }
        }
        "lbs_interleaved" => {
            let v = SkinVertex::interleave(&input.skin, &input.positions, &input.normals)
                .map_err(err)?;
            start = now_ms();
            for _ in 0..iterations {
                skin_lbs_interleaved(
                    std::hint::black_box(&input.palette),
                    &v,
                    &mut out_p,
                    &mut out_n,
                )
                .map_err(err)?;
                std::hint::black_box(&out_p);
            }
        }
        "dqs" => {
            let mut dq = vec![DualQuat::IDENTITY; input.palette.len()];
            start = now_ms();
            for _ in 0..iterations {
                dual_quat_palette(std::hint::black_box(&input.palette), &mut dq).map_err(err)?;
                skin_dqs(
                    &dq,
                    &input.skin,
                    &input.positions,
                    &input.normals,
                    &mut out_p,
                    &mut out_n,
                )
                .map_err(err)?;
                std::hint::black_box(&out_p);
            }
        }
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    }
    Ok(now_ms() - start)
}

/// The benchmark's input as flat arrays for the JavaScript loop, concatenated:
/// `[palette (12 per joint, 60 joints), joints (4 per vertex, as numbers), weights (4 per vertex),
/// positions (3 per vertex), normals (3 per vertex)]`.
#[wasm_bindgen(js_name = skinningBenchInput)]
pub fn skinning_bench_input(vertices: usize) -> Result<Vec<f32>, JsError> {
    check(vertices, 1)?;
    let (pal, j, w, pos, nrm) = benchmark_input(vertices, SEED).flat();
    let mut out = pal;
    out.extend(j.iter().map(|&x| x as f32));
    out.extend(w);
    out.extend(pos);
    out.extend(nrm);
    Ok(out)
}
