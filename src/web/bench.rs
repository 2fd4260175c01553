//! Kernels for the browser bench page (`www/bench.html`): the same work as the criterion benches,
//! timed inside wasm with `performance.now()` so that JavaScript call overhead is not measured.

use crate::transform::{local_matrix, world_matrices};
use glam::{Mat4, Vec3};
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// Times `iterations` runs of a hierarchy kernel over `joints` joints and returns milliseconds.
/// `kernel` is "copy_baseline", "world_matrices" or "local_matrix_from_euler".
/// Caps (the work grows with both): `joints` in [1, 2²⁰], `iterations` in [1, 2²⁴] and
/// `joints × iterations` at most 2³⁰.
#[wasm_bindgen(js_name = benchHierarchy)]
pub fn bench_hierarchy(kernel: JsValue, joints: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let joints = super::whole("joints", joints)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("joints", joints as u64, iterations, 1 << 30)?;
    if !(1..=1 << 20).contains(&joints) || !(1..=1 << 24).contains(&iterations) {
        return Err(JsError::new(
            "joints must be in [1, 2^20] and iterations in [1, 2^24]",
        ));
    }
    let (parents, local) = crate::fixtures::binary_tree_hierarchy(joints);
    let mut world = vec![Mat4::IDENTITY; joints];
    let start = now_ms();
    match kernel {
        "copy_baseline" => {
            (0..iterations).for_each(|_| world.copy_from_slice(std::hint::black_box(&local)))
        }
        "world_matrices" => (0..iterations)
            .for_each(|_| world_matrices(std::hint::black_box(&parents), &local, &mut world)),
        "local_matrix_from_euler" => (0..iterations).for_each(|_| {
            for (i, l) in world.iter_mut().enumerate() {
                *l = local_matrix(std::hint::black_box(Vec3::Y), Vec3::splat(i as f32));
            }
        }),
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    }
    let elapsed = now_ms() - start;
    std::hint::black_box(&world);
    Ok(elapsed)
}
