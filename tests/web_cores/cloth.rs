//! Browser-only tests of the lesson 13 bindings: bad input (zero, negative or too many particles
//! per side, NaN, unknown names) is an `Err` with a readable message at the wasm boundary, never a
//! panic, and valid input is `Ok`.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{check_cloth, ClothScene, SpringScene};
use wasm_bindgen_test::*;

use super::message;

#[wasm_bindgen_test]
fn cloth_sizes_fail_with_their_own_message() {
    assert!(check_cloth(100.0, 100.0, 0.5)
        .unwrap()
        .starts_with("ok: 10000 particles"));
    for (c, r) in [(0.0, 5.0), (-3.0, 5.0), (257.0, 2.0), (1.0, 10.0)] {
        assert!(message(check_cloth(c, r, 0.5).unwrap_err()).contains("between 2 and 256"));
    }
    assert!(message(check_cloth(f64::NAN, 5.0, 0.5).unwrap_err()).contains("whole number"));
    assert!(message(check_cloth(2.5, 5.0, 0.5).unwrap_err()).contains("whole number"));
    assert!(message(check_cloth(5.0, 5.0, f32::NAN).unwrap_err()).contains("mass"));
}

#[wasm_bindgen_test]
fn figure_setters_reject_bad_input() {
    assert!(message(ClothScene::new("curtain".into()).err().unwrap()).contains("no cloth preset"));
    let mut f = ClothScene::new("flag".into()).unwrap();
    assert!(
        message(f.set_stiffness("structural".into(), f32::NAN).unwrap_err())
            .contains("structural stiffness")
    );
    assert!(message(f.set_stiffness("wobbly".into(), 1.0).unwrap_err()).contains("spring kind"));
    assert!(message(f.set_substeps(0.0).unwrap_err()).contains("substeps"));
    assert!(message(f.set_wind(-1.0).unwrap_err()).contains("wind"));
    assert!(message(f.set_pins("all".into()).unwrap_err()).contains("pins"));
    let mut d = ClothScene::new("drape".into()).unwrap();
    assert!(message(d.set_resolution(0.0).unwrap_err()).contains("resolution"));
    assert!(message(d.set_resolution(1e6).unwrap_err()).contains("resolution"));
    assert!(message(d.set_method("implicit".into()).unwrap_err()).contains("method"));
    assert!(message(d.set_obstacles(f32::NAN, 0.0, 0.0).unwrap_err()).contains("sphere x"));
    assert!(message(d.grab(0.0, 0.0, 0.0, 10.0).unwrap_err()).contains("width"));
    assert!(d.set_resolution(40.0).is_ok());
    let mut s = SpringScene::new();
    assert!(message(s.set_stiffness(0.0).unwrap_err()).contains("stiffness"));
    assert!(message(s.set_step_ms(f32::INFINITY).unwrap_err()).contains("step"));
}
