//! Browser-only tests of the lesson 11 and 12 bindings: bad input (negative rates or lifetimes,
//! NaN, counts over the caps) is an `Err` with a readable message at the wasm boundary, never a
//! panic, and valid input is `Ok`.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{check_emitter, BoidRulesScene, EmitterScene, FlockScene};
use wasm_bindgen_test::*;

use super::message;

#[wasm_bindgen_test]
fn emitter_rules_fail_with_their_own_message() {
    assert_eq!(check_emitter(1000.0, 100.0, 1.0, 2.0).unwrap(), "ok");
    assert!(message(check_emitter(100_001.0, 100.0, 1.0, 2.0).unwrap_err()).contains("too many"));
    assert!(message(check_emitter(10.0, -1.0, 1.0, 2.0).unwrap_err()).contains("rate"));
    assert!(message(check_emitter(10.0, f32::NAN, 1.0, 2.0).unwrap_err()).contains("rate"));
    assert!(message(check_emitter(10.0, 1.0, -1.0, 2.0).unwrap_err()).contains("lifetime"));
    assert!(message(check_emitter(10.0, 1.0, 3.0, 2.0).unwrap_err()).contains("lifetime"));
}

#[wasm_bindgen_test]
fn figure_setters_reject_bad_input() {
    let mut e = EmitterScene::new();
    assert!(message(e.set_rate(-5.0).unwrap_err()).contains("rate"));
    assert!(message(e.set_lifetime(f32::NAN).unwrap_err()).contains("lifetime"));
    assert!(e.set_rate(100.0).is_ok());
    let mut f = FlockScene::new();
    assert!(message(f.set_count(1e9).unwrap_err()).contains("count"));
    assert!(
        message(f.set_rule("cohesion".into(), 1.0, f32::NAN).unwrap_err())
            .contains("cohesion radius")
    );
    assert!(message(f.prepare_timing(1e9).unwrap_err()).contains("boids to time"));
    assert!(message(f.advance_to(f32::NAN).unwrap_err()).contains("time"));
    assert_eq!(f.advance_to(1.0 / 60.0).unwrap(), 1);
    let mut r = BoidRulesScene::new();
    assert!(message(r.set_fov_deg(400.0).unwrap_err()).contains("field of view"));
}
