//! Kernels for the browser bench page, lessons 03 and 04: the same work as `benches/rotation.rs`,
//! timed inside wasm with `performance.now()`.

use crate::rigid::DualQuat;
use crate::rotation::{nlerp, slerp};
use glam::{Quat, Vec3};
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

fn check(size: usize, iterations: usize) -> Result<(), JsError> {
    if !(1..=1 << 22).contains(&size) || !(1..=1 << 24).contains(&iterations) {
        return Err(JsError::new(
            "size must be in [1, 2^22] and iterations in [1, 2^24]",
        ));
    }
    Ok(())
}

/// Times `iterations` passes of quaternion interpolation over `size` key pairs; milliseconds.
/// `kernel` is "nlerp" (the baseline) or "slerp".
/// Caps (the work grows with both): `size` in [1, 2²²], `iterations` in [1, 2²⁴] and
/// `size × iterations` at most 2³⁰.
#[wasm_bindgen(js_name = benchQuatInterpolation)]
pub fn bench_quat_interpolation(
    kernel: JsValue,
    size: f64,
    iterations: f64,
) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let size = super::whole("size", size)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("size", size as u64, iterations, 1 << 30)?;
    check(size, iterations)?;
    let keys: Vec<(Quat, Quat)> = (0..size)
        .map(|i| {
            let x = i as f32 * 0.001;
            (
                Quat::from_euler(glam::EulerRot::XYZ, x, 0.3, -x),
                Quat::from_euler(glam::EulerRot::XYZ, 1.0 - x, x, 2.0),
            )
        })
        .collect();
    let mut out = vec![Quat::IDENTITY; size];
    let f: fn(Quat, Quat, f32) -> Quat = match kernel {
        "nlerp" => nlerp,
        "slerp" => slerp,
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    };
    let start = now_ms();
    for it in 0..iterations {
        let t = std::hint::black_box((it % 7) as f32 / 7.0 + 0.05);
        for ((a, b), o) in keys.iter().zip(out.iter_mut()) {
            *o = f(*a, *b, t);
        }
        std::hint::black_box(&out);
    }
    Ok(now_ms() - start)
}

/// Times `iterations` applications of one rigid motion to `size` points; milliseconds.
/// `kernel` is "factored" (the baseline: matrix and translation once, then `R p + t` per point)
/// or "sandwich" (the full dual quaternion product per point).
/// Caps (the work grows with both): `size` in [1, 2²²], `iterations` in [1, 2²⁴] and
/// `size × iterations` at most 2³⁰.
#[wasm_bindgen(js_name = benchRigidPoints)]
pub fn bench_rigid_points(kernel: JsValue, size: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let size = super::whole("size", size)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("size", size as u64, iterations, 1 << 30)?;
    check(size, iterations)?;
    let motion = DualQuat::from_rotation_translation(
        Quat::from_axis_angle(Vec3::new(0.3, 1.0, 0.2).normalize(), 1.1),
        Vec3::new(0.5, -1.0, 2.0),
    );
    let points: Vec<Vec3> = (0..size)
        .map(|i| Vec3::new(i as f32 * 1e-3, (i % 97) as f32, -(i as f32).sqrt()))
        .collect();
    let mut out = vec![Vec3::ZERO; size];
    let start = now_ms();
    for _ in 0..iterations {
        let m = std::hint::black_box(motion);
        let result = match kernel {
            "factored" => m.transform_points(&points, &mut out),
            "sandwich" => m.transform_points_sandwich(&points, &mut out),
            other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
        };
        result.map_err(|e| JsError::new(&e.to_string()))?;
        std::hint::black_box(&out);
    }
    Ok(now_ms() - start)
}
