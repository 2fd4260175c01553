//! Browser bench kernel for the rigid-body core (same work as `benches/rigid_body.rs`): one step
//! of a heap of balls and boxes in contact ([`crate::rigid_body::contact::heap`]), with the grid
//! broad phase or with every pair tested.

use crate::rigid_body::contact::{heap, BroadPhase, World, MAX_BODIES};
use std::cell::RefCell;
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

thread_local! {
    /// The heap after a second of falling, by body count: made once, not on every timed call.
    static FALLEN: RefCell<Option<(usize, World)>> = const { RefCell::new(None) };
}

/// Times `iterations` steps of 1/120 s of a heap of `bodies` balls and boxes that has fallen for
/// one second (made once per body count, not timed), each step from that same state (the copy
/// is timed too, and is small next to a step), and returns milliseconds. `kernel` is "grid" or
/// "all_pairs". Caps (the work grows with both): `bodies` in [1, 4096], `iterations` in
/// [1, 2²⁰] and `bodies × iterations` at most 2²².
#[wasm_bindgen(js_name = benchRigidBodies)]
pub fn bench_rigid_bodies(kernel: JsValue, bodies: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let bodies = super::whole("bodies", bodies)?;
    let iterations = super::whole("iterations", iterations)?;
    super::check_work("bodies", bodies as u64, iterations, 1 << 22)?;
    if !(1..=MAX_BODIES).contains(&bodies) || !(1..=1 << 20).contains(&iterations) {
        return Err(JsError::new(&format!(
            "bodies must be in [1, {MAX_BODIES}] and iterations in [1, 2^20]"
        )));
    }
    let broad = match kernel {
        "grid" => BroadPhase::Grid,
        "all_pairs" => BroadPhase::AllPairs,
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    };
    let mut start = FALLEN.with(|cell| -> Result<World, JsError> {
        let mut cell = cell.borrow_mut();
        if cell.as_ref().map(|(n, _)| *n) != Some(bodies) {
            let mut world = heap(bodies).map_err(|e| JsError::new(&e))?;
            for _ in 0..120 {
                world.step(1.0 / 120.0).map_err(|e| JsError::new(&e))?;
            }
            *cell = Some((bodies, world));
        }
        Ok(cell.as_ref().expect("made above").1.clone())
    })?;
    start.broad_phase = broad;
    let began = now_ms();
    for _ in 0..iterations {
        let mut world = start.clone();
        world.step(1.0 / 120.0).map_err(|e| JsError::new(&e))?;
        std::hint::black_box(&world.bodies);
    }
    Ok(now_ms() - began)
}
