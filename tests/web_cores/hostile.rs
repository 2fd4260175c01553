//! Browser-only tests of the wasm boundary's argument checks: a value of the wrong JavaScript
//! type is an error that names the parameter (never a panic in the glue, never a silent
//! coercion), a count or index is a whole number in range, and a rejected call changes nothing.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{
    check_emitter, check_skeleton, check_skin_weights, BounceScene, ClothScene, EmitterScene,
    HierarchyScene, KeyframesScene, SkeletonScene, SpringScene, SquashScene,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

use super::message;

#[wasm_bindgen_test]
fn a_non_string_name_is_an_error_not_a_read_past_the_buffer() {
    let mut scene = KeyframesScene::new();
    let m = message(scene.set_scheme(JsValue::from(42)).unwrap_err());
    assert_eq!(m, "name must be a string, got number 42");
    assert!(message(scene.set_ease(JsValue::NULL).unwrap_err()).contains("must be a string"));
    assert!(message(ClothScene::new(JsValue::from(7)).err().unwrap()).contains("preset"));
    assert_eq!(
        scene.scheme(),
        "cardinal",
        "the rejected scheme changed nothing"
    );
    scene.set_scheme("natural".into()).unwrap();
}

#[wasm_bindgen_test]
fn a_flag_must_be_a_boolean() {
    let mut scene = KeyframesScene::new();
    for bad in [JsValue::from("true"), JsValue::from(1), JsValue::UNDEFINED] {
        let m = message(scene.set_arc_length(bad).unwrap_err());
        assert!(m.starts_with("on must be true or false"), "{m}");
    }
    scene.set_arc_length(JsValue::TRUE).unwrap();
}

#[wasm_bindgen_test]
fn counts_and_indices_are_whole_numbers_never_wrapped() {
    let scene = KeyframesScene::new();
    for bad in [f64::NAN, f64::INFINITY, -1.0, 1.5, 4_294_967_299.0] {
        let m = message(scene.sample_motion(bad).unwrap_err());
        assert!(m.contains("whole number"), "{bad}: {m}");
    }
    assert_eq!(scene.sample_motion(3.0).unwrap().len(), 12);
    // 2^32 is not joint 0 (a conversion that wraps would make it so).
    let mut h = HierarchyScene::new();
    let before = h.joint_angles_deg(0.0).unwrap();
    assert!(h
        .set_joint_angles_deg(4_294_967_296.0, 45.0, 0.0, 0.0)
        .is_err());
    assert_eq!(h.joint_angles_deg(0.0).unwrap(), before);
    // 2^32 + 5 is not a capacity of 5.
    assert!(
        message(check_emitter(4_294_967_301.0, 10.0, 1.0, 2.0).unwrap_err())
            .contains("whole number")
    );
    let s = SkeletonScene::new();
    assert!(s.joint_angles_deg(0.5).is_err());
}

#[wasm_bindgen_test]
fn lists_of_names_and_indices_are_checked_element_by_element() {
    let rest: Vec<f32> = [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0].repeat(2);
    // A string is not an array of its characters.
    let m = message(check_skeleton("ab".into(), vec![-1.0, 0.0], rest.clone()).unwrap_err());
    assert!(m.contains("names must be an array of strings"), "{m}");
    let names: js_sys::Array = ["a", "b"].iter().map(|&n| JsValue::from(n)).collect();
    // 4294967295 is not -1 (a second root).
    let m = message(
        check_skeleton(
            names.clone().into(),
            vec![4_294_967_295.0, 0.0],
            rest.clone(),
        )
        .unwrap_err(),
    );
    assert!(m.contains("parents[0] must be a whole number"), "{m}");
    assert_eq!(
        check_skeleton(names.into(), vec![-1.0, 0.0], rest).unwrap(),
        "ok"
    );
    // NaN is not joint 0.
    let m = message(
        check_skin_weights(vec![f64::NAN, 0.0, 0.0, 0.0], vec![1.0, 0.0, 0.0, 0.0], 2.0)
            .unwrap_err(),
    );
    assert!(m.contains("joints[0] must be a whole number"), "{m}");
}

#[wasm_bindgen_test]
fn list_caps_are_checked_before_the_lists_are_read() {
    let rest: Vec<f32> = [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0].repeat(2);
    // More names than a skeleton may have joints: refused before any is converted.
    let many: js_sys::Array = (0..70_000).map(|_| JsValue::from(0.5)).collect();
    let m = message(check_skeleton(many.into(), vec![-1.0, 0.0], rest.clone()).unwrap_err());
    assert!(m.contains("names may hold at most 65536 strings"), "{m}");
    // A name past the length cap.
    let long = "x".repeat(300);
    let names: js_sys::Array = [long.as_str(), "b"]
        .iter()
        .map(|&n| JsValue::from(n))
        .collect();
    let m = message(check_skeleton(names.into(), vec![-1.0, 0.0], rest).unwrap_err());
    assert!(
        m.contains("names[0] may be at most 256 characters long, got 300"),
        "{m}"
    );
}

#[wasm_bindgen_test]
fn simulations_advance_without_a_canvas_and_reject_bad_times() {
    let mut emitter = EmitterScene::new();
    for bad in [f32::NAN, f32::INFINITY, -1.0, 1e30] {
        let m = message(emitter.advance_to(bad).unwrap_err());
        assert!(m.contains("time"), "{bad}: {m}");
    }
    // 1/60 s steps: half a second is 30 of them, and going on to 1 s 30 more.
    assert_eq!(emitter.advance_to(0.5).unwrap(), 30);
    assert_eq!(emitter.advance_to(1.0).unwrap(), 30);
    let mut bounce = BounceScene::new();
    assert!(bounce.advance_to(f32::NAN).is_err());
    assert!(bounce.advance_to(0.5).unwrap() > 0);
    let mut squash = SquashScene::new();
    assert!(squash.advance_to(-1.0).is_err());
    assert!(squash.advance_to(0.5).unwrap() > 0);
    let mut cloth = ClothScene::new("flag".into()).unwrap();
    assert!(cloth.advance_to(f32::NAN).is_err());
    assert!(cloth.advance_to(0.1).unwrap() > 0);
    let spring = SpringScene::new();
    assert!(spring.note_at(f32::NAN).is_err());
    assert!(!spring.note_at(0.5).unwrap().is_empty());
}
