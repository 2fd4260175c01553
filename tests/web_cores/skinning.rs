//! Browser-only tests of the lesson 09 bindings: every skinning-weight rule is an `Err` with the
//! core's message at the wasm boundary (never a panic), bad figure input names the parameter, and
//! valid input is `Ok`.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{check_skin_weights, SkinnedHumanScene, SkinningCylinderScene};
use wasm_bindgen_test::*;

use super::message;

/// `check_skin_weights` with Rust values (the joint indices and count as JavaScript numbers).
fn check(
    joints: Vec<u32>,
    weights: Vec<f32>,
    joint_count: usize,
) -> Result<String, wasm_bindgen::JsError> {
    let joints = joints.iter().map(|&j| f64::from(j)).collect();
    check_skin_weights(joints, weights, joint_count as f64)
}

fn fails(joints: Vec<u32>, weights: Vec<f32>, joint_count: usize) -> String {
    message(check(joints, weights, joint_count).unwrap_err())
}

#[wasm_bindgen_test]
fn each_weight_rule_fails_with_its_own_message() {
    let ok = check(vec![0, 1, 0, 0], vec![0.5, 0.5, 0.0, 0.0], 2).unwrap();
    assert_eq!(ok, "ok");
    assert!(fails(vec![0, 1, 0], vec![0.5, 0.5, 0.0], 2).contains("four numbers per vertex"));
    assert!(fails(vec![0, 1, 0, 0], vec![0.5, 0.5], 2).contains("four numbers per vertex"));
    assert!(fails(vec![0, 5, 0, 0], vec![0.5, 0.5, 0.0, 0.0], 2).contains("names joint 5"));
    assert!(fails(vec![0, 70000, 0, 0], vec![1.0, 0.0, 0.0, 0.0], 2).contains("over 65535"));
    assert!(fails(vec![0, 1, 0, 0], vec![f32::NAN, 0.5, 0.0, 0.0], 2).contains("NaN"));
    assert!(fails(vec![0, 1, 0, 0], vec![1.0, -0.5, 0.0, 0.0], 2).contains("negative"));
    assert!(fails(vec![0, 1, 0, 0], vec![0.0; 4], 2).contains("all weights zero"));
}

#[wasm_bindgen_test]
fn bad_figure_input_names_the_parameter() {
    let mut cylinder = SkinningCylinderScene::new();
    assert!(message(cylinder.set_bend_deg(f32::NAN).unwrap_err()).contains("bend"));
    assert!(message(cylinder.set_twist_deg(400.0).unwrap_err()).contains("twist"));
    assert!(message(cylinder.set_falloff(0.0).unwrap_err()).contains("falloff"));
    assert!(message(cylinder.set_heat_joint("knee".into()).unwrap_err()).contains("knee"));
    assert!(cylinder.area_curves(1.0).is_err());
    assert_eq!(cylinder.area_curves(3.0).unwrap().len(), 15);
    let mut human = SkinnedHumanScene::new();
    assert!(message(human.set_method("GPU".into()).unwrap_err()).contains("method"));
    assert!(message(human.skin(f32::INFINITY).unwrap_err()).contains("time"));
    assert!(human.skin(0.5).is_ok());
}
