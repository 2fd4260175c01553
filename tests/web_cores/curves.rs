//! Lesson 02's binding at the wasm boundary (headless Chromium): every validation rule of the
//! keyframe scene turns bad input into an `Err` with the core's message, and valid input is `Ok`.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{KeyframesScene, LagrangeScene};
use wasm_bindgen::{JsError, JsValue};
use wasm_bindgen_test::*;

fn message<T>(result: Result<T, JsError>) -> String {
    match result {
        Ok(_) => panic!("expected an error"),
        Err(e) => js_sys::Error::from(JsValue::from(e)).message().into(),
    }
}

#[wasm_bindgen_test]
fn valid_keys_are_accepted_and_read_back() {
    let mut scene = KeyframesScene::new();
    scene
        .set_keys(vec![0.0, 1.0, 2.5], vec![0.0, 0.0, 1.0, 2.0, 3.0, 0.5])
        .expect("valid keys");
    assert_eq!(
        scene.keys(),
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.5, 3.0, 0.5]
    );
    for scheme in [
        "step",
        "linear",
        "lagrange",
        "hermite",
        "cardinal",
        "natural",
        "centripetal",
    ] {
        scene.set_scheme(scheme.into()).expect(scheme);
        assert!(
            scene.sample_path().len() >= 6,
            "{scheme}: a path through the keys"
        );
    }
    scene.set_tension(0.5).expect("tension in range");
    scene
        .set_key_tangent(1.0, 1.0, 0.0, 0.0, 1.0)
        .expect("a broken tangent");
    assert_eq!(scene.scheme(), "hermite");
    scene
        .set_tangents(vec![0.0; 6], vec![1.0; 6])
        .expect("one tangent pair per key");
    scene.set_arc_length(true.into()).unwrap();
    scene.set_ease("smoothstep".into()).expect("known ease");
    assert_eq!(scene.sample_motion(11.0).expect("motion").len(), 44);
}

#[wasm_bindgen_test]
fn a_nan_key_value_is_rejected() {
    let mut scene = KeyframesScene::new();
    let before = scene.keys();
    let m = message(scene.set_keys(vec![0.0, 1.0], vec![0.0, f32::NAN, 1.0, 1.0]));
    assert!(m.contains("key 0") && m.contains("NaN"), "{m}");
    assert_eq!(
        scene.keys(),
        before,
        "a rejected edit leaves the scene unchanged"
    );
}

#[wasm_bindgen_test]
fn a_nan_or_infinite_key_time_is_rejected() {
    let mut scene = KeyframesScene::new();
    let m = message(scene.set_keys(vec![0.0, f32::NAN], vec![0.0, 0.0, 1.0, 1.0]));
    assert!(m.contains("key 1") && m.contains("not a finite"), "{m}");
    let m = message(scene.set_keys(vec![0.0, f32::INFINITY], vec![0.0, 0.0, 1.0, 1.0]));
    assert!(m.contains("not a finite"), "{m}");
}

#[wasm_bindgen_test]
fn unsorted_or_repeated_times_are_rejected() {
    let mut scene = KeyframesScene::new();
    let m = message(scene.set_keys(vec![0.0, 2.0, 1.0], vec![0.0; 6]));
    assert!(
        m.contains("strictly increase") && m.contains("key 2"),
        "{m}"
    );
    let m = message(scene.set_keys(vec![0.0, 1.0, 1.0], vec![0.0; 6]));
    assert!(m.contains("strictly increase"), "{m}");
}

#[wasm_bindgen_test]
fn mismatched_lengths_are_rejected() {
    let mut scene = KeyframesScene::new();
    let m = message(scene.set_keys(vec![0.0, 1.0, 2.0], vec![0.0, 0.0, 1.0, 1.0]));
    assert!(m.contains("3 key times but 2 key values"), "{m}");
    let m = message(scene.set_keys(vec![0.0, 1.0], vec![0.0, 0.0, 1.0]));
    assert!(m.contains("pairs"), "{m}");
    let m = message(scene.set_keys(vec![], vec![]));
    assert!(m.contains("at least one key"), "{m}");
    let m = message(scene.set_tangents(vec![0.0; 4], vec![0.0; 10]));
    assert!(m.contains("in tangents"), "{m}");
}

#[wasm_bindgen_test]
fn bad_tangents_tension_and_names_are_rejected() {
    let mut scene = KeyframesScene::new();
    assert!(message(scene.set_key_tangent(0.0, f32::NAN, 0.0, 0.0, 0.0)).contains("NaN"));
    assert!(message(scene.set_key_tangent(99.0, 0.0, 0.0, 0.0, 0.0)).contains("99"));
    assert!(message(scene.set_tension(2.5)).contains("between 0 and 2"));
    assert!(message(scene.set_tension(f32::NAN)).contains("between 0 and 2"));
    assert!(message(scene.set_scheme("bezier".into())).contains("unknown scheme"));
    assert!(message(scene.set_ease("bounce".into())).contains("unknown ease"));
    assert!(message(scene.sample_motion(1.0)).contains("samples"));
    assert!(message(scene.position(f32::NAN)).contains("finite"));
}

#[wasm_bindgen_test]
fn the_lagrange_demo_checks_its_key_count() {
    let mut scene = LagrangeScene::new();
    scene.set_key_count(12.0).expect("in range");
    assert!(message(scene.set_key_count(-10.0)).contains("key count"));
    assert!(message(scene.set_key_count(f32::NAN)).contains("key count"));
}

#[wasm_bindgen_test]
fn ten_thousand_lagrange_keys_give_an_error_not_a_freeze() {
    let mut scene = KeyframesScene::new();
    scene.set_scheme("lagrange".into()).expect("five keys");
    let times: Vec<f32> = (0..10_000).map(|i| i as f32).collect();
    let m = message(scene.set_keys(times.clone(), vec![0.0; 20_000]));
    assert!(m.contains("at most"), "{m}");
    scene.set_scheme("linear".into()).expect("linear");
    let m = message(scene.set_keys(times[..1001].to_vec(), vec![0.0; 2002]));
    assert!(m.contains("at most 1000 keys"), "{m}");
    let times: Vec<f32> = (0..65).map(|i| i as f32).collect();
    scene
        .set_keys(times, vec![0.0; 130])
        .expect("65 linear keys");
    assert!(message(scene.set_scheme("lagrange".into())).contains("at most 64 keys"));
    assert!(message(scene.load_preset("nope".into())).contains("unknown preset"));
    scene.load_preset("loop".into()).expect("a preset");
}
