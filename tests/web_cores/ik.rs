//! Browser-only tests of the lesson 07 and 08 bindings: bad input is an `Err` naming the
//! parameter at the wasm boundary (never a panic), and valid input is `Ok`.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{AimScene, BlendScene, IkScene, LocomotionScene};
use wasm_bindgen_test::*;

use super::message;

#[wasm_bindgen_test]
fn ik_scene_rejects_bad_input_with_a_message() {
    let mut s = IkScene::new();
    assert!(message(s.set_target(f32::NAN, 0.0, 0.0).unwrap_err()).contains("target x"));
    assert!(message(s.set_target(0.0, 9.0, 0.0).unwrap_err()).contains("target y"));
    assert!(message(s.set_segments(1.0).unwrap_err()).contains("segments"));
    assert!(message(s.set_iterations(f32::INFINITY).unwrap_err()).contains("iterations"));
    assert!(message(s.set_pole_angle_deg(500.0).unwrap_err()).contains("pole angle"));
    assert!(message(s.set_limits("rubber".into()).unwrap_err()).contains("joint limits"));
    assert!(message(s.hits_target(0.0, 0.0, 0.0, 100.0).unwrap_err()).contains("width"));
    assert!(message(s.drag_target(f32::NAN, 0.0, 100.0, 100.0).unwrap_err()).contains("x"));
    s.set_target(0.3, 0.6, 0.0).unwrap();
    s.set_limits("cones (40°)".into()).unwrap();
    assert_eq!(s.error_samples().unwrap().len(), 150);
    assert_eq!(s.target(), vec![0.3, 0.6, 0.0]);
    let mut a = AimScene::new();
    assert!(message(a.set_max_angle_deg(-5.0).unwrap_err()).contains("largest turn"));
    assert!(message(a.set_target(0.0, -1.0, 0.0).unwrap_err()).contains("target y"));
}

#[wasm_bindgen_test]
fn blending_scenes_reject_bad_input_with_a_message() {
    let mut b = BlendScene::new();
    assert!(message(b.set_weight(2.0).unwrap_err()).contains("weight of B"));
    assert!(message(b.set_clips("walk".into(), "moonwalk".into()).unwrap_err()).contains("clip B"));
    assert!(message(b.set_mask("tail".into()).unwrap_err()).contains("mask"));
    assert!(
        message(b.set_additive("none".into(), f32::NAN).unwrap_err()).contains("layer weight")
    );
    b.set_clips("run".into(), "idle".into()).unwrap();
    assert!(b.duration_sec() > 0.5);
    let mut l = LocomotionScene::new();
    let range = l.speed_range();
    assert!(range[1] > range[0]);
    assert!(message(l.set_speed(range[1] + 1.0).unwrap_err()).contains("speed"));
    l.set_speed(range[0]).unwrap();
}
