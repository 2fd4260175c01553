//! Tests of `inbetween::rigid`: dual quaternions, blending, screw interpolation, screw axis,
//! errors, and pytransform3d reference values (tests/data/rotation_reference.txt).
// Native only (proptest); the browser runs tests/transform.rs and tests/web*.rs.
#![cfg(not(target_arch = "wasm32"))]

use std::f32::consts::{FRAC_PI_2, PI};

use glam::{Mat3, Mat4, Quat, Vec3};
use inbetween::rigid::*;
use inbetween::rotation::{angle_between, quat_from_axis_angle, RotationError};
use proptest::prelude::*;

fn same_motion(a: DualQuat, b: DualQuat, eps: f32) -> bool {
    let close =
        |s: f32| (a.real - b.real * s).length() <= eps && (a.dual - b.dual * s).length() <= eps;
    close(1.0) || close(-1.0)
}

fn motion(axis: Vec3, angle: f32, t: Vec3) -> DualQuat {
    DualQuat::from_rotation_translation(quat_from_axis_angle(axis.normalize(), angle), t)
}

fn two_motions() -> (DualQuat, DualQuat) {
    (
        motion(Vec3::new(1.0, 2.0, 0.5), 0.8, Vec3::new(1.0, -2.0, 0.3)),
        motion(Vec3::new(-0.3, 1.0, 1.0), 2.5, Vec3::new(-1.0, 0.5, 4.0)),
    )
}

#[test]
fn rotation_translation_and_matrix_round_trips() {
    let r = quat_from_axis_angle(Vec3::new(0.0, 0.6, 0.8), 1.1);
    let t = Vec3::new(3.0, -1.0, 2.0);
    let q = dual_quat_from_rotation_translation(r, t);
    let (r2, t2) = q.to_rotation_translation();
    assert!((r2 - r).length() < 1e-7 && t2.abs_diff_eq(t, 1e-6));
    let m = Mat4::from_rotation_translation(r, t);
    assert!(q.to_mat4().abs_diff_eq(m, 1e-6));
    assert!(same_motion(DualQuat::from_mat4(m).unwrap(), q, 1e-6));
    assert!(DualQuat::IDENTITY
        .to_mat4()
        .abs_diff_eq(Mat4::IDENTITY, 0.0));
    assert_eq!(DualQuat::from_translation(t).translation(), t);
    assert_eq!(DualQuat::from_rotation(r).translation(), Vec3::ZERO);
}

#[test]
fn composition_matches_matrices_and_inverse_undoes() {
    let (a, b) = two_motions();
    assert!((a * b)
        .to_mat4()
        .abs_diff_eq(a.to_mat4() * b.to_mat4(), 1e-5));
    assert!(same_motion(a * a.conjugate(), DualQuat::IDENTITY, 1e-6));
    assert!(same_motion(a.inverse(), a.conjugate(), 1e-6));
    let p = Vec3::new(0.5, 1.0, -2.0);
    assert!(a
        .conjugate()
        .transform_point(a.transform_point(p))
        .abs_diff_eq(p, 1e-5));
}

#[test]
fn points_and_directions() {
    let (a, _) = two_motions();
    let p = Vec3::new(0.5, 1.0, -2.0);
    let expected = a.to_mat4().transform_point3(p);
    assert!(dual_quat_transform_point(a, p).abs_diff_eq(expected, 1e-5));
    assert!(a.transform_point_sandwich(p).abs_diff_eq(expected, 1e-5));
    let v = Vec3::new(0.0, 0.0, 1.0);
    assert!(a
        .transform_direction(v)
        .abs_diff_eq(a.to_mat4().transform_vector3(v), 1e-6));
}

#[test]
fn transform_points_factored_equals_sandwich() {
    let (a, _) = two_motions();
    let points: Vec<Vec3> = (0..100)
        .map(|i| Vec3::new(i as f32 * 0.1, (i as f32).sin(), -1.0))
        .collect();
    let mut fast = vec![Vec3::ZERO; points.len()];
    let mut slow = vec![Vec3::ZERO; points.len()];
    a.transform_points(&points, &mut fast).unwrap();
    a.transform_points_sandwich(&points, &mut slow).unwrap();
    for (f, s) in fast.iter().zip(&slow) {
        assert!(f.abs_diff_eq(*s, 1e-5));
    }
    let mut short = vec![Vec3::ZERO; 3];
    assert_eq!(
        a.transform_points(&points, &mut short),
        Err(RotationError::LengthMismatch {
            expected: 100,
            got: 3
        })
    );
}

#[test]
fn normalize_and_check() {
    let (a, _) = two_motions();
    let drifted = DualQuat {
        real: a.real * 1.7,
        dual: a.dual * 1.7 + a.real * 0.01,
    };
    let n = drifted.normalized();
    assert!((n.real.length() - 1.0).abs() < 1e-6);
    assert!(n.real.dot(n.dual).abs() < 1e-6);
    assert!((n.real - a.real).length() < 1e-6);
    let mut m = drifted;
    m.normalize();
    assert_eq!(m, n);
    assert!(same_motion(drifted.check().unwrap(), n, 0.0));
    let zero = DualQuat {
        real: Quat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        dual: Quat::IDENTITY,
    };
    assert_eq!(zero.check(), Err(RotationError::ZeroQuat));
    let nan = DualQuat {
        real: Quat::IDENTITY,
        dual: Quat::from_xyzw(f32::NAN, 0.0, 0.0, 0.0),
    };
    assert_eq!(
        nan.check(),
        Err(RotationError::NonFinite {
            what: "dual quaternion"
        })
    );
}

#[test]
fn from_mat4_errors() {
    let scaled = Mat4::from_scale(Vec3::splat(2.0));
    assert!(matches!(
        DualQuat::from_mat4(scaled),
        Err(RotationError::NotOrthonormal { .. })
    ));
    let mirror = Mat4::from_scale(Vec3::new(1.0, 1.0, -1.0));
    assert!(matches!(
        DualQuat::from_mat4(mirror),
        Err(RotationError::Reflection { .. })
    ));
    let mut projective = Mat4::IDENTITY;
    projective.w_axis.w = 2.0;
    assert!(matches!(
        DualQuat::from_mat4(projective),
        Err(RotationError::NotAffine { .. })
    ));
    let msg = DualQuat::from_mat4(scaled).unwrap_err().to_string();
    assert!(msg.contains("not a rotation"), "{msg}");
}

#[test]
fn nlerp_and_blend() {
    let (a, b) = two_motions();
    assert!(same_motion(DualQuat::nlerp(a, b, 0.0), a, 1e-6));
    assert!(same_motion(DualQuat::nlerp(a, b, 1.0), b, 1e-6));
    assert!(same_motion(DualQuat::nlerp(a, b * -1.0, 1.0), b, 1e-6));
    let mid = DualQuat::nlerp(a, b, 0.5);
    assert!((mid.real.length() - 1.0).abs() < 1e-6 && mid.real.dot(mid.dual).abs() < 1e-6);
    let blended = dual_quat_blend(&[a, b * -1.0], &[0.5, 0.5]).unwrap();
    assert!(same_motion(blended, mid, 1e-6));
    assert!(same_motion(
        dual_quat_blend(&[a, b], &[1.0, 0.0]).unwrap(),
        a,
        1e-6
    ));
    assert!(matches!(
        dual_quat_blend(&[a], &[1.0, 2.0]),
        Err(RotationError::LengthMismatch { .. })
    ));
    assert!(matches!(
        dual_quat_blend(&[a, b], &[0.0, 0.0]),
        Err(RotationError::BadWeights { .. })
    ));
    assert!(matches!(
        dual_quat_blend(&[a, b], &[-1.0, 2.0]),
        Err(RotationError::BadWeights { .. })
    ));
    assert!(matches!(
        dual_quat_blend(&[], &[]),
        Err(RotationError::TooFewKeys { .. })
    ));
}

#[test]
fn log_exp_round_trip_including_pure_translation() {
    let (a, b) = two_motions();
    for q in [
        a,
        b,
        DualQuat::from_translation(Vec3::new(1.0, 2.0, 3.0)),
        DualQuat::IDENTITY,
        motion(Vec3::Y, 1e-4, Vec3::new(0.0, 0.0, 5.0)),
        motion(Vec3::X, PI - 1e-3, Vec3::ONE),
    ] {
        assert!(same_motion(q.log().exp(), q, 2e-5), "{q:?}");
    }
    let log = DualQuat::from_translation(Vec3::new(2.0, 0.0, 0.0)).log();
    assert_eq!(log.real, Vec3::ZERO);
    assert!(log.dual.abs_diff_eq(Vec3::new(1.0, 0.0, 0.0), 1e-7));
}

#[test]
fn screw_thirds_recompose_the_full_motion() {
    let (a, b) = two_motions();
    let delta = b * a.conjugate();
    let third = delta.pow(1.0 / 3.0);
    assert!(same_motion(third * third * third, delta, 2e-5));
    let step = DualQuat::sclerp(a, b, 1.0 / 3.0) * a.conjugate();
    assert!(same_motion(step * step * step * a, b, 2e-5));
}

#[test]
fn sclerp_endpoints_constant_speed_and_cache() {
    let (a, b) = two_motions();
    assert!(same_motion(DualQuat::sclerp(a, b, 0.0), a, 1e-6));
    assert!(same_motion(DualQuat::sclerp(a, b, 1.0), b, 2e-5));
    let cached = ScrewInterpolator::new(a, b);
    let n = 10;
    let mut angles = vec![];
    let mut slides = vec![];
    let axis = (b * a.conjugate()).screw_axis();
    for i in 0..=n {
        let t = i as f32 / n as f32;
        let q = DualQuat::sclerp(a, b, t);
        assert!(same_motion(cached.sample(t), q, 1e-6));
        let rel = (q * a.conjugate()).screw_axis();
        angles.push(rel.angle_rad);
        slides.push(rel.displacement);
        if i > 0 {
            assert!(
                rel.direction.abs_diff_eq(axis.direction, 1e-4),
                "axis moves at {t}"
            );
            assert!(rel.point.abs_diff_eq(axis.point, 1e-3), "axis moves at {t}");
        }
    }
    for i in 0..=n {
        let t = i as f32 / n as f32;
        assert!((angles[i] - t * axis.angle_rad).abs() < 1e-5, "{angles:?}");
        assert!(
            (slides[i] - t * axis.displacement).abs() < 1e-4,
            "{slides:?}"
        );
    }
}

#[test]
fn sclerp_of_pure_translations_is_translation_lerp() {
    let a = DualQuat::from_translation(Vec3::new(1.0, 0.0, 0.0));
    let b = DualQuat::from_translation(Vec3::new(-1.0, 4.0, 2.0));
    for t in [0.0, 0.3, 0.5, 1.0] {
        let q = DualQuat::sclerp(a, b, t);
        assert!(q.translation().abs_diff_eq(
            Vec3::new(1.0, 0.0, 0.0).lerp(Vec3::new(-1.0, 4.0, 2.0), t),
            1e-6
        ));
        assert!((q.real - Quat::IDENTITY).length() < 1e-7);
    }
}

#[test]
fn screw_axis_of_a_known_screw() {
    // Turn a quarter about the z axis through (1, 2, 0), then slide 3 along z.
    let c = Vec3::new(1.0, 2.0, 0.0);
    let q = DualQuat::from_translation(c + Vec3::new(0.0, 0.0, 3.0))
        * DualQuat::from_rotation(quat_from_axis_angle(Vec3::Z, FRAC_PI_2))
        * DualQuat::from_translation(-c);
    let s = q.screw_axis();
    assert!(s.direction.abs_diff_eq(Vec3::Z, 1e-6));
    assert!(s.point.abs_diff_eq(c, 1e-5), "{}", s.point);
    assert!((s.angle_rad - FRAC_PI_2).abs() < 1e-6);
    assert!((s.displacement - 3.0).abs() < 1e-6);
    // points on the axis only slide
    assert!(q
        .transform_point(c)
        .abs_diff_eq(c + Vec3::new(0.0, 0.0, 3.0), 1e-5));
    let pure = DualQuat::from_translation(Vec3::new(0.0, -2.0, 0.0)).screw_axis();
    assert_eq!(
        (pure.direction, pure.angle_rad, pure.displacement),
        (Vec3::NEG_Y, 0.0, 2.0)
    );
}

proptest! {
    #[test]
    fn prop_motion_laws(
        axis in prop::array::uniform3(-1.0f32..1.0),
        angle in -3.1f32..3.1,
        t in prop::array::uniform3(-5.0f32..5.0),
        p in prop::array::uniform3(-5.0f32..5.0),
    ) {
        let axis = Vec3::from_array(axis);
        prop_assume!(axis.length() > 0.1);
        let q = motion(axis, angle, Vec3::from_array(t));
        let p = Vec3::from_array(p);
        let m = q.to_mat4();
        prop_assert!(q.transform_point(p).abs_diff_eq(m.transform_point3(p), 1e-4));
        prop_assert!(q.transform_point_sandwich(p).abs_diff_eq(m.transform_point3(p), 1e-4));
        prop_assert!(same_motion(q.log().exp(), q, 1e-4));
        let third = q.pow(1.0 / 3.0);
        prop_assert!(same_motion(third * third * third, q, 1e-4));
        prop_assert!(Mat3::from_mat4(m).determinant() > 0.999);
    }

    #[test]
    fn prop_sclerp_unit_and_rotation_matches_slerp(
        angle_a in -3.0f32..3.0, angle_b in -3.0f32..3.0, s in 0.0f32..1.0,
    ) {
        let a = motion(Vec3::new(1.0, 0.5, 0.0), angle_a, Vec3::new(1.0, 2.0, 3.0));
        let b = motion(Vec3::new(0.0, 0.5, 1.0), angle_b, Vec3::new(-2.0, 0.0, 1.0));
        let q = DualQuat::sclerp(a, b, s);
        prop_assert!((q.real.length() - 1.0).abs() < 1e-5);
        prop_assert!(q.real.dot(q.dual).abs() < 1e-5);
        // The rotation part of a screw interpolation is the slerp of the rotations.
        let r = inbetween::rotation::slerp(a.real, b.real, s);
        prop_assert!(angle_between(q.real, r) < 1e-3);
    }
}

const REFERENCE: &str = include_str!("data/rotation_reference.txt");

#[test]
fn reference_sclerp_pytransform3d() {
    let rows: Vec<Vec<f32>> = REFERENCE
        .lines()
        .filter(|l| l.starts_with("sclerp "))
        .map(|l| {
            l.split_whitespace()
                .skip(1)
                .map(|w| w.parse().unwrap())
                .collect()
        })
        .collect();
    assert!(rows.len() >= 10);
    for v in rows {
        let quat = |i: usize| Quat::from_xyzw(v[i], v[i + 1], v[i + 2], v[i + 3]);
        let vec = |i: usize| Vec3::new(v[i], v[i + 1], v[i + 2]);
        let a = DualQuat::from_rotation_translation(quat(0), vec(4));
        let b = DualQuat::from_rotation_translation(quat(7), vec(11));
        let t = v[14];
        let expected = DualQuat::from_rotation_translation(quat(15), vec(19));
        let got = DualQuat::sclerp(a, b, t);
        assert!(
            same_motion(got, expected, 1e-5),
            "t = {t}: {got:?} vs {expected:?}"
        );
        assert!(got.translation().abs_diff_eq(vec(19), 1e-5));
        assert!(same_motion(
            ScrewInterpolator::new(a, b).sample(t),
            expected,
            1e-5
        ));
    }
}
