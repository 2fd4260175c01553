//! Browser bench kernels for lesson 09 (same work as `benches/skinning.rs`): 100,000 vertices with
//! four influences over the 60-joint benchmark humanoid's palette, positions and normals, by the
//! plain scalar loop, LBS (separate arrays, interleaved) and DQS. The bench page times the same
//! plain loop written in JavaScript on [`skinning_bench_input`]'s arrays, in the same page.

use crate::rigid::DualQuat;
use crate::skinning::rigs::{benchmark_input, BenchmarkSkin};
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

/// One pass of a kernel, never inlined: V8 compiles a wasm function first with its baseline
/// compiler and swaps in the optimised code only for later *calls* (there is no on-stack
/// replacement in wasm), so the bench warms this function up with many small calls before timing.
#[inline(never)]
fn pass(
    kernel: &str,
    input: &BenchmarkSkin,
    flat: &Flat,
    interleaved: &[SkinVertex],
    dq: &mut [DualQuat],
    out: &mut Out,
) -> Result<(), JsError> {
    let err = |e: crate::skinning::SkinningError| JsError::new(&e.to_string());

    match kernel {
        "wasm_plain_loop" => {
            let (pal, j, w, pos, nrm) = flat;
            skin_lbs_plain_loop(
                std::hint::black_box(pal),
                j,
                w,
                pos,
                nrm,
                &mut out.flat_p,
                &mut out.flat_n,
            );
        }
        "lbs" => skin_lbs(
            std::hint::black_box(&input.palette),
            &input.skin,
            &input.positions,
            &input.normals,
            &mut out.p,
            &mut out.n,
        )
        .map_err(err)?,
        "lbs_interleaved" => skin_lbs_interleaved(
            std::hint::black_box(&input.palette),
            interleaved,
            &mut out.p,
            &mut out.n,
        )
        .map_err(err)?,
        "dqs" => {
            dual_quat_palette(std::hint::black_box(&input.palette), dq).map_err(err)?;
            skin_dqs(
                dq,
                &input.skin,
                &input.positions,
                &input.normals,
                &mut out.p,
                &mut out.n,
            )
            .map_err(err)?;
        }
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    }
    std::hint::black_box(&out.p);
    std::hint::black_box(&out.flat_p);
    Ok(())
}

type Flat = (Vec<f32>, Vec<u16>, Vec<f32>, Vec<f32>, Vec<f32>);

struct Out {
    p: Vec<Vec3>,
    n: Vec<Vec3>,
    flat_p: Vec<f32>,
    flat_n: Vec<f32>,
}

struct Prepared {
    input: BenchmarkSkin,
    flat: Flat,
    interleaved: Vec<SkinVertex>,
    dq: Vec<DualQuat>,
    out: Out,
}

fn prepare(vertices: usize) -> Result<Prepared, JsError> {
    let input = benchmark_input(vertices, SEED);
    let flat = input.flat();
    let interleaved = SkinVertex::interleave(&input.skin, &input.positions, &input.normals)
        .map_err(|e| JsError::new(&e.to_string()))?;
    let dq = vec![DualQuat::IDENTITY; input.palette.len()];
    let out = Out {
        p: vec![Vec3::ZERO; vertices],
        n: vec![Vec3::ZERO; vertices],
        flat_p: vec![0.0; 3 * vertices],
        flat_n: vec![0.0; 3 * vertices],
    };
    Ok(Prepared {
        input,
        flat,
        interleaved,
        dq,
        out,
    })
}

/// Times `iterations` passes of a skinning kernel over `vertices` vertices and returns
/// milliseconds. `kernel` is "wasm_plain_loop", "lbs", "lbs_interleaved" or "dqs" (DQS includes
/// turning the palette into dual quaternions, once per pass). Before timing, 200 calls on 512
/// vertices let the engine optimise the kernel (see [`pass`]).
/// Caps (the work grows with both): `vertices` and `iterations` each in [1, 2²⁰] and
/// `vertices × iterations` at most 2³⁰.
#[wasm_bindgen(js_name = benchSkinning)]
pub fn bench_skinning(kernel: JsValue, vertices: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let vertices = super::whole("vertices", vertices)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("vertices", vertices as u64, iterations, 1 << 30)?;
    check(vertices, iterations)?;
    let mut warm = prepare(512)?;
    for _ in 0..200 {
        let w = &mut warm;
        pass(
            kernel,
            &w.input,
            &w.flat,
            &w.interleaved,
            &mut w.dq,
            &mut w.out,
        )?;
    }
    let mut x = prepare(vertices)?;
    let start = now_ms();
    for _ in 0..iterations {
        pass(
            kernel,
            &x.input,
            &x.flat,
            &x.interleaved,
            &mut x.dq,
            &mut x.out,
        )?;
    }
    Ok(now_ms() - start)
}

/// The benchmark's input as flat arrays for the JavaScript loop, concatenated:
/// `[palette (12 per joint, 60 joints), joints (4 per vertex, as numbers), weights (4 per vertex),
/// positions (3 per vertex), normals (3 per vertex)]`.
/// Cap: `vertices` in [1, 2²⁰] (the arrays grow with it).
#[wasm_bindgen(js_name = skinningBenchInput)]
pub fn skinning_bench_input(vertices: f64) -> Result<Vec<f32>, JsError> {
    let vertices = super::whole("vertices", vertices)?;
    check(vertices, 1)?;
    let (pal, j, w, pos, nrm) = benchmark_input(vertices, SEED).flat();
    let mut out = pal;
    out.extend(j.iter().map(|&x| x as f32));
    out.extend(w);
    out.extend(pos);
    out.extend(nrm);
    Ok(out)
}
