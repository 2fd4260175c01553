//! Browser-only tests of the lesson 03 and 04 bindings: bad input (zero or NaN quaternion,
//! non-orthonormal matrix given as a rotation, singular affine key, zero axis) is an `Err` with
//! the core's message, never a panic; valid input is `Ok`.
#![cfg(target_arch = "wasm32")]

use inbetween::web::{AffineScene, InterpolationScene, RigidScene, RodriguesScene};
use wasm_bindgen_test::*;

use super::message;

#[wasm_bindgen_test]
fn a_zero_or_nan_quaternion_is_rejected() {
    let mut scene = InterpolationScene::new();
    let e = scene.set_end_quat(0.0, 0.0, 0.0, 0.0).unwrap_err();
    assert!(message(e).contains("zero length"));
    let e = scene.set_end_quat(f32::NAN, 0.0, 0.0, 1.0).unwrap_err();
    assert!(message(e).contains("NaN"));
    assert!(
        scene.set_end_quat(0.0, 0.0, 0.0, 2.0).is_ok(),
        "a non-unit quaternion is normalised"
    );
    let mut rigid = RigidScene::new();
    assert!(rigid
        .set_end_quat(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
        .is_err());
    assert!(rigid
        .set_end_quat(0.0, 0.0, 0.0, 1.0, f32::NAN, 0.0, 0.0)
        .is_err());
    assert!(rigid
        .set_end_quat(0.0, 0.6, 0.0, 0.8, 1.0, 0.0, 0.0)
        .is_ok());
}

#[wasm_bindgen_test]
fn a_non_orthonormal_matrix_is_not_a_rotation() {
    let mut scene = InterpolationScene::new();
    let scaled = vec![2.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    assert!(message(scene.set_end_matrix(scaled).unwrap_err()).contains("not orthonormal"));
    let mirror = vec![-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    assert!(message(scene.set_end_matrix(mirror).unwrap_err()).contains("mirrors"));
    assert!(scene.set_end_matrix(vec![1.0; 4]).is_err(), "wrong length");
    let (s, c) = 0.5f32.sin_cos();
    assert!(scene
        .set_end_matrix(vec![c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0])
        .is_ok());
    let mut rigid = RigidScene::new();
    let mut sheared = glam::Mat4::IDENTITY.to_cols_array();
    sheared[4] = 0.5;
    assert!(
        message(rigid.set_end_matrix(sheared.to_vec()).unwrap_err()).contains("not orthonormal")
    );
    assert!(rigid
        .set_end_matrix(
            glam::Mat4::from_translation(glam::Vec3::X)
                .to_cols_array()
                .to_vec()
        )
        .is_ok());
}

#[wasm_bindgen_test]
fn a_singular_affine_key_is_rejected() {
    let mut scene = AffineScene::new();
    assert!(message(scene.set_key_b(30.0, 1.0, 0.0, 1.0, 0.2).unwrap_err()).contains("singular"));
    let flat = glam::Mat4::from_scale(glam::Vec3::new(1.0, 1.0, 0.0))
        .to_cols_array()
        .to_vec();
    assert!(message(scene.set_key_matrix(0.0, flat).unwrap_err()).contains("singular"));
    let mut nan = glam::Mat4::IDENTITY.to_cols_array();
    nan[0] = f32::NAN;
    assert!(scene.set_key_matrix(1.0, nan.to_vec()).is_err());
    let mut projective = glam::Mat4::IDENTITY.to_cols_array();
    projective[3] = 0.5;
    assert!(
        message(scene.set_key_matrix(1.0, projective.to_vec()).unwrap_err()).contains("not affine")
    );
    assert!(
        scene
            .set_key_matrix(2.0, glam::Mat4::IDENTITY.to_cols_array().to_vec())
            .is_err(),
        "no key 2"
    );
    assert!(scene.set_key_b(-120.0, 0.5, 2.0, 1.0, -0.4).is_ok());
    assert!(scene
        .set_key_matrix(
            0.0,
            glam::Mat4::from_scale(glam::Vec3::splat(2.0))
                .to_cols_array()
                .to_vec()
        )
        .is_ok());
}

#[wasm_bindgen_test]
fn a_zero_axis_is_rejected() {
    let mut scene = RodriguesScene::new();
    assert!(
        message(scene.set_axis_angle(0.0, 0.0, 0.0, 30.0).unwrap_err())
            .contains("axis has zero length")
    );
    assert!(scene.set_axis_angle(0.0, 1.0, 0.0, f32::INFINITY).is_err());
    assert!(scene.set_axis_angle(0.0, 2.0, 0.0, 30.0).is_ok());
    let mut rigid = RigidScene::new();
    assert!(rigid.set_end(0.0, 0.0, 0.0, 90.0, 0.0, 0.0, 0.0).is_err());
    assert!(rigid.set_end(1.0, 0.0, 0.0, 90.0, 0.0, 1.0, 0.0).is_ok());
}

#[wasm_bindgen_test]
fn sampled_plots_have_the_promised_shape() {
    let scene = InterpolationScene::new();
    let d = scene.sample_determinant(11.0).map_err(message).unwrap();
    assert_eq!(d.len(), 33);
    assert!(
        (d[1] - 1.0).abs() < 1e-4 && (d[31] - 1.0).abs() < 1e-4,
        "keys are rotations"
    );
    let s = scene.sample_angular_speed(11.0).map_err(message).unwrap();
    let slerp: Vec<f32> = s.chunks(4).map(|c| c[3]).collect();
    let spread = slerp.iter().cloned().fold(f32::MIN, f32::max)
        - slerp.iter().cloned().fold(f32::MAX, f32::min);
    assert!(
        spread < 0.02 * slerp[0],
        "slerp's angular speed is constant: {slerp:?}"
    );
    assert!(scene.sample_determinant(1.0).is_err());
    let rigid = RigidScene::new();
    assert_eq!(rigid.sample_speed(5.0).map_err(message).unwrap().len(), 20);
}

#[wasm_bindgen_test]
fn new_controls_validate_and_report() {
    let scene = InterpolationScene::new();
    let arcs = scene.arc_angles_deg();
    assert!((arcs[0] + arcs[1] - 360.0).abs() < 1e-3);
    assert_eq!(RodriguesScene::new().matrix().len(), 9, "R is shown 3×3");
    let mut rigid = RigidScene::new();
    assert!(message(rigid.set_show(4.0).unwrap_err()).contains("show must be"));
    assert!(rigid.set_show(3.0).is_ok());
    rigid.set_thirds(true.into()).unwrap();
    let mut affine = AffineScene::new();
    // Large but in range (entries within ±1e4) and not singular; 1e38 is outside the range.
    let large = glam::Mat4::from_scale(glam::Vec3::new(1e4, 1.0, 1.0));
    assert!(affine
        .set_key_matrix(0.0, large.to_cols_array().to_vec())
        .is_ok());
    let huge = glam::Mat4::from_scale(glam::Vec3::new(1e38, 1.0, 1.0));
    assert!(message(
        affine
            .set_key_matrix(0.0, huge.to_cols_array().to_vec())
            .unwrap_err()
    )
    .contains("[-10000, 10000]"));
}
