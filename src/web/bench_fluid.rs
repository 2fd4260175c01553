//! Browser bench kernel for lesson 15 (the same work as `benches/fluid.rs`): one step of the dam
//! break ([`crate::fluid::benchmark_fluid`]) with SPH or PBF in 2D or 3D, or the neighbour
//! search alone, with the grid or with every pair tested.

use crate::fluid::{benchmark_fluid, Dim, Fluid, Method, Search};
use std::cell::RefCell;
use wasm_bindgen::prelude::*;

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// The most particles the bench accepts (the splash figure stops at 10,000).
const MAX_BENCH_PARTICLES: usize = 50_000;
/// The most particles the every-pair search accepts: its work grows with their square.
const MAX_ALL_PAIRS: usize = 20_000;

thread_local! {
    /// The last start state made, with what it was made for: making it steps 0.1 s of fall,
    /// which costs more than the steps timed.
    static START: RefCell<Option<((Dim, Method, usize), Fluid)>> = const { RefCell::new(None) };
}

/// Times `iterations` steps (or searches) of the benchmark fluid of `count` particles in `dim`
/// dimensions (2 or 3) and returns milliseconds. `kernel` is "sph", "pbf" (4 iterations),
/// "search_grid" or "search_all_pairs" (the neighbour search alone, on the SPH fluid). Each step
/// starts from the same state, copied from the one made once (the copy is timed too, and is
/// small next to a step). Caps (the work grows with both): `count` in [100, 50,000] (every pair:
/// 20,000), `iterations` in [1, 2²⁰], `count × iterations` at most 2²² (every pair:
/// `count² × iterations` at most 2³²).
#[wasm_bindgen(js_name = benchFluid)]
pub fn bench_fluid(kernel: JsValue, dim: f64, count: f64, iterations: f64) -> Result<f64, JsError> {
    let kernel: &str = &super::string("kernel", &kernel)?;
    let dim = match super::whole_in("dim", dim, 2, 3)? {
        2 => Dim::Two,
        _ => Dim::Three,
    };
    let count = super::whole_in("count", count, 100, MAX_BENCH_PARTICLES)?;
    let iterations = super::whole_in("iterations", iterations, 1, 1 << 20)?;
    let (method, search) = match kernel {
        "sph" => (Method::Sph, None),
        "pbf" => (Method::Pbf, None),
        "search_grid" => (Method::Sph, Some(Search::Grid)),
        "search_all_pairs" => (Method::Sph, Some(Search::AllPairs)),
        other => return Err(JsError::new(&format!("unknown kernel '{other}'"))),
    };
    if search == Some(Search::AllPairs) {
        if count > MAX_ALL_PAIRS {
            return Err(JsError::new(&format!(
                "the every-pair search takes at most {MAX_ALL_PAIRS} particles, got {count}"
            )));
        }
        super::check_work("count²", (count as u64).pow(2), iterations, 1 << 32)?;
    } else {
        super::check_work("count", count as u64, iterations, 1 << 22)?;
    }
    let key = (dim, method, count);
    let start = START.with(|cell| -> Result<Fluid, JsError> {
        let mut cell = cell.borrow_mut();
        if cell.as_ref().map(|(k, _)| *k) != Some(key) {
            let fluid = benchmark_fluid(dim, method, count).map_err(|e| JsError::new(&e))?;
            *cell = Some((key, fluid));
        }
        Ok(cell.as_ref().expect("made above").1.clone())
    })?;
    let began = now_ms();
    match search {
        Some(search) => {
            let mut fluid = start;
            fluid.set_search(search);
            for _ in 0..iterations {
                fluid.search();
            }
            std::hint::black_box(fluid.neighbours(0).len());
        }
        None => {
            for _ in 0..iterations {
                let mut fluid = start.clone();
                fluid.step();
                std::hint::black_box(&fluid.positions);
            }
        }
    }
    Ok(now_ms() - began)
}
