//! Browser-only tests of the lesson 06 bindings: every skeleton validation rule is an `Err` with
//! the core's message at the wasm boundary (never a panic), bad figure input names the parameter,
//! and valid input is `Ok`.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{check_skeleton, SkeletonScene};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

use super::message;

fn names(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("j{i}")).collect()
}

/// Rest transforms: translation (0, 1, 0), identity rotation, unit scale.
fn rest(n: usize) -> Vec<f32> {
    (0..n)
        .flat_map(|_| [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0])
        .collect()
}

/// `check_skeleton` with Rust values: the names as a JavaScript array, the parents as numbers.
fn check(
    names: Vec<String>,
    parents: Vec<i32>,
    rest: Vec<f32>,
) -> Result<String, wasm_bindgen::JsError> {
    let names: js_sys::Array = names.iter().map(|n| JsValue::from(n.as_str())).collect();
    check_skeleton(
        names.into(),
        parents.iter().map(|&p| f64::from(p)).collect(),
        rest,
    )
}

fn fails(names: Vec<String>, parents: Vec<i32>, rest: Vec<f32>) -> String {
    message(check(names, parents, rest).unwrap_err())
}

#[wasm_bindgen_test]
fn each_skeleton_rule_fails_with_its_own_message() {
    assert_eq!(check(names(3), vec![-1, 0, 1], rest(3)).unwrap(), "ok");
    assert!(fails(vec![], vec![], vec![]).contains("no joints"));
    assert!(fails(names(2), vec![-1, 0], rest(3)).contains("10 numbers per joint"));
    assert!(fails(names(1), vec![-1, 0], rest(2)).contains("names"));
    assert!(fails(names(2), vec![-1, 7], rest(2)).contains("out of range"));
    assert!(fails(names(3), vec![-1, 2, 1], rest(3)).contains("cycle"));
    assert!(fails(names(3), vec![-1, 2, 0], rest(3)).contains("before its children"));
    let mut dup = names(2);
    dup[1] = "j0".into();
    assert!(fails(dup, vec![-1, 0], rest(2)).contains("both named"));
    let mut nan = rest(2);
    nan[10] = f32::NAN;
    assert!(fails(names(2), vec![-1, 0], nan).contains("NaN"));
    let mut long = rest(2);
    long[16] = 3.0; // joint 1's w
    assert!(fails(names(2), vec![-1, 0], long).contains("unit quaternion"));
    let mut flat = rest(2);
    flat[8] = 0.0; // joint 0's scale y
    assert!(fails(names(2), vec![-1, 0], flat).contains("cannot be inverted"));
}

#[wasm_bindgen_test]
fn bad_figure_input_names_the_parameter() {
    let mut scene = SkeletonScene::new();
    assert!(message(scene.select(99.0).unwrap_err()).contains("joint index 99"));
    let e = scene
        .set_joint_angles_deg(0.0, f32::NAN, 0.0, 0.0)
        .unwrap_err();
    assert!(message(e).contains("angle x"));
    assert!(message(scene.set_keys_per_cycle(0.0).unwrap_err()).contains("keys per cycle"));
    assert!(
        message(scene.set_interpolation("bezier".into()).unwrap_err()).contains("interpolation")
    );
    assert!(message(scene.set_clip("dance".into()).unwrap_err()).contains("clip"));
    assert!(scene.sample_selected(1.0).is_err());
    assert!(scene.set_clip("run".into()).is_ok());
    // Ten rows of [t, angle, speed, angle₂, speed₂, angle_A, angle_B].
    assert_eq!(scene.sample_selected(10.0).unwrap().len(), 70);
}
