//! Tests of `inbetween::rotation`: conversions, interpolation, spline, polar decomposition,
//! affine keys, errors, and reference values from scipy (tests/data/rotation_reference.txt).
// Native only (proptest); the browser runs tests/transform.rs and tests/web*.rs.
#![cfg(not(target_arch = "wasm32"))]

use std::f32::consts::{FRAC_PI_2, PI};

use glam::{Mat3, Mat4, Quat, Vec3};
use inbetween::rotation::*;
use proptest::prelude::*;

macro_rules! assert_near {
    ($a:expr, $b:expr, $eps:expr) => {{
        let (a, b, eps) = ($a, $b, $eps);
        assert!(
            (a - b).abs() <= eps,
            "{} = {a} vs {} = {b} (eps {eps})",
            stringify!($a),
            stringify!($b)
        );
    }};
}

/// `a` and `b` are the same rotation (`q` and `−q` allowed).
fn same_rotation(a: Quat, b: Quat, eps: f32) -> bool {
    (a - b).length() <= eps || (a + b).length() <= eps
}

fn mat_near(a: Mat3, b: Mat3, eps: f32) -> bool {
    a.abs_diff_eq(b, eps)
}

fn quat_from_seed(v: [f32; 4]) -> Quat {
    Quat::from_xyzw(v[0], v[1], v[2], v[3]).normalize()
}

fn arb_quat() -> impl Strategy<Value = Quat> {
    prop::array::uniform4(-1.0f32..1.0)
        .prop_filter("not tiny", |v| v.iter().map(|x| x * x).sum::<f32>() > 0.01)
        .prop_map(quat_from_seed)
}

// ---------------------------------------------------------------------------------------------
// Quaternion and matrix
// ---------------------------------------------------------------------------------------------

#[test]
fn mat3_from_quat_matches_glam() {
    let q = Quat::from_xyzw(0.3, -0.5, 0.1, 0.8).normalize();
    assert!(mat_near(mat3_from_quat(q), Mat3::from_quat(q), 1e-6));
}

#[test]
fn quat_from_mat3_half_turns_about_axes() {
    for axis in [
        Vec3::X,
        Vec3::Y,
        Vec3::Z,
        Vec3::new(1.0, 1.0, 0.0).normalize(),
    ] {
        let q = quat_from_axis_angle(axis, PI);
        let back = quat_from_mat3(mat3_from_quat(q));
        assert!(same_rotation(back, q, 1e-6), "{axis}: {back} vs {q}");
        assert!(back.w >= 0.0);
    }
}

#[test]
fn quaternion_and_matrix_compose_the_same_way() {
    let a = quat_from_axis_angle(Vec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
    let b = quat_from_axis_angle(Vec3::new(-1.0, 0.5, 0.0).normalize(), 2.1);
    let from_quat = mat3_from_quat(a * b);
    let from_mats = mat3_from_quat(a) * mat3_from_quat(b);
    assert!(mat_near(from_quat, from_mats, 1e-6));
    let v = Vec3::new(0.2, -1.0, 3.0);
    assert!((a * (b * v)).abs_diff_eq(from_mats * v, 1e-5));
}

#[test]
fn angle_between_is_accurate_for_tiny_and_half_turn_angles() {
    let a = quat_from_axis_angle(Vec3::Y, 0.3);
    assert_near!(
        angle_between(a, a * quat_from_axis_angle(Vec3::X, 1e-4)),
        1e-4,
        1e-8
    );
    assert_near!(
        angle_between(a, a * quat_from_axis_angle(Vec3::X, PI - 1e-3)),
        PI - 1e-3,
        1e-5
    );
    assert_near!(angle_between(a, -a), 0.0, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Axis-angle, rotation vectors, Rodrigues
// ---------------------------------------------------------------------------------------------

#[test]
fn rodrigues_matches_quaternion_and_vector_forms() {
    let axis = Vec3::new(0.2, -0.7, 0.4).normalize();
    for angle in [0.0, 1e-4, 0.5, 2.0, PI, 5.0] {
        let r = rodrigues_mat3(axis, angle);
        assert!(mat_near(
            r,
            mat3_from_quat(quat_from_axis_angle(axis, angle)),
            1e-6
        ));
        let v = Vec3::new(1.0, 2.0, -0.5);
        assert!((r * v).abs_diff_eq(rodrigues_rotate(v, axis, angle), 1e-5));
        assert!(orthogonality_error(r) < 1e-6);
        assert_near!(r.determinant(), 1.0, 1e-6);
    }
}

#[test]
fn rodrigues_quarter_turn_about_z_sends_x_to_y() {
    let r = rodrigues_mat3(Vec3::Z, FRAC_PI_2);
    assert!((r * Vec3::X).abs_diff_eq(Vec3::Y, 1e-7));
}

#[test]
fn rotation_vector_near_zero_keeps_its_digits() {
    let v = Vec3::new(3e-7, -1e-7, 2e-7);
    let q = quat_from_rotation_vector(v);
    assert!(q.w == 1.0 || q.w > 1.0 - 1e-7);
    let back = rotation_vector_from_quat(q);
    assert!((back - v).length() <= 1e-6 * v.length(), "{back} vs {v}");
    assert_eq!(rotation_vector_from_quat(Quat::IDENTITY), Vec3::ZERO);
}

#[test]
fn rotation_vector_near_two_pi_is_a_small_turn_the_other_way() {
    let n = Vec3::new(1.0, 2.0, 2.0) / 3.0;
    let eps = 1e-3;
    let q = quat_from_rotation_vector(n * (2.0 * PI - eps));
    let back = rotation_vector_from_quat(q);
    assert!((back + n * eps).length() < 1e-6, "{back}");
}

#[test]
fn axis_angle_round_trips() {
    let aa = AxisAngle::new(Vec3::new(0.0, 3.0, 4.0), 2.5).unwrap();
    assert!(aa.axis.abs_diff_eq(Vec3::new(0.0, 0.6, 0.8), 1e-7));
    let from_q = AxisAngle::from_quat(aa.to_quat());
    assert!(from_q.axis.abs_diff_eq(aa.axis, 1e-6) && (from_q.angle_rad - 2.5).abs() < 1e-6);
    let from_m = AxisAngle::from_mat3(aa.to_mat3());
    assert!(from_m.axis.abs_diff_eq(aa.axis, 1e-5) && (from_m.angle_rad - 2.5).abs() < 1e-5);
    let v = aa.to_rotation_vector();
    assert_eq!(AxisAngle::from_rotation_vector(v).angle_rad, v.length());
    assert!(rotation_vector_from_mat3(aa.to_mat3()).abs_diff_eq(v, 1e-5));
}

// ---------------------------------------------------------------------------------------------
// Euler angles
// ---------------------------------------------------------------------------------------------

#[test]
fn euler_orders_are_named_as_documented() {
    let (a, b, c) = (0.3, -0.4, 1.1);
    let intrinsic = EulerAngles::new(EulerOrder::IntrinsicXYZ, Vec3::new(a, b, c)).to_mat3();
    let expected = Mat3::from_rotation_x(a) * Mat3::from_rotation_y(b) * Mat3::from_rotation_z(c);
    assert!(mat_near(intrinsic, expected, 1e-6));
    let extrinsic = EulerAngles::new(EulerOrder::ExtrinsicXYZ, Vec3::new(a, b, c)).to_mat3();
    let expected = Mat3::from_rotation_z(c) * Mat3::from_rotation_y(b) * Mat3::from_rotation_x(a);
    assert!(mat_near(extrinsic, expected, 1e-6));
    // intrinsic X-Y'-Z'' by (a, b, c) is extrinsic z-y-x by (c, b, a)
    let zyx = EulerAngles::new(EulerOrder::ExtrinsicZYX, Vec3::new(c, b, a)).to_mat3();
    assert!(mat_near(intrinsic, zyx, 1e-6));
    // glam's own decomposition agrees for the intrinsic order
    let (x, y, z) = Mat3::from_quat(Quat::from_mat3(&intrinsic)).to_euler(glam::EulerRot::XYZ);
    assert!(Vec3::new(x, y, z).abs_diff_eq(Vec3::new(a, b, c), 1e-5));
}

#[test]
fn euler_round_trips_in_every_order() {
    let angles = Vec3::new(0.7, -0.9, 2.4);
    for order in EulerOrder::ALL {
        let e = EulerAngles::new(order, angles);
        let r = e.to_mat3();
        assert!(
            same_rotation(e.to_quat(), quat_from_mat3(r), 1e-6),
            "{}",
            order.name()
        );
        let back = EulerAngles::from_mat3(r, order);
        assert!(!back.gimbal_lock);
        assert!(
            back.angles_rad.abs_diff_eq(angles, 1e-5),
            "{}: {}",
            order.name(),
            back.angles_rad
        );
        let back_q = EulerAngles::from_quat(e.to_quat(), order);
        assert!(back_q.angles_rad.abs_diff_eq(angles, 1e-5));
    }
}

#[test]
fn euler_gimbal_lock_is_detected_and_the_rotation_kept() {
    for order in EulerOrder::ALL {
        for beta in [FRAC_PI_2, -FRAC_PI_2] {
            let e = EulerAngles::new(order, Vec3::new(0.4, beta, -0.3));
            let back = EulerAngles::from_mat3(e.to_mat3(), order);
            assert!(back.gimbal_lock, "{}", order.name());
            let zeroed = if order.is_intrinsic() {
                back.angles_rad.z
            } else {
                back.angles_rad.x
            };
            assert_eq!(zeroed, 0.0);
            assert!(
                mat_near(back.to_mat3(), e.to_mat3(), 1e-5),
                "{} {beta}",
                order.name()
            );
        }
    }
}

#[test]
fn euler_lerp_endpoints_and_naive_path() {
    let a = EulerAngles::new(EulerOrder::IntrinsicXYZ, Vec3::new(0.0, 0.0, 0.0));
    let b = EulerAngles::new(EulerOrder::IntrinsicXYZ, Vec3::new(PI / 2.0, 0.5, PI / 2.0));
    assert_eq!(euler_lerp(a, b, 0.0).angles_rad, a.angles_rad);
    assert_eq!(euler_lerp(a, b, 1.0).angles_rad, b.angles_rad);
    // Every Euler sample is a rotation, but its speed is not constant (unlike slerp).
    let qa = a.to_quat();
    let qb = b.to_quat();
    let mut speeds = vec![];
    for i in 0..10 {
        let t0 = i as f32 / 10.0;
        let t1 = (i + 1) as f32 / 10.0;
        let e0 = euler_lerp(a, b, t0).to_quat();
        let e1 = euler_lerp(a, b, t1).to_quat();
        assert!(orthogonality_error(euler_lerp(a, b, t0).to_mat3()) < 1e-5);
        speeds.push(angle_between(e0, e1));
    }
    let spread = speeds.iter().cloned().fold(0.0f32, f32::max)
        - speeds.iter().cloned().fold(9.0f32, f32::min);
    assert!(spread > 1e-3, "{speeds:?}");
    let _ = (qa, qb);
}

// ---------------------------------------------------------------------------------------------
// Interpolation
// ---------------------------------------------------------------------------------------------

#[test]
fn slerp_and_nlerp_endpoints() {
    let a = quat_from_axis_angle(Vec3::X, 0.4);
    let b = quat_from_axis_angle(Vec3::new(0.0, 1.0, 1.0).normalize(), 2.9);
    for f in [slerp, nlerp] {
        assert!(same_rotation(f(a, b, 0.0), a, 1e-6));
        assert!(same_rotation(f(a, b, 1.0), b, 1e-6));
        assert!(same_rotation(f(a, -b, 1.0), b, 1e-6));
    }
    assert!(same_rotation(slerp_arc(a, b, 1.0, Arc::Long), b, 1e-6));
    assert!(same_rotation(nlerp_arc(a, b, 1.0, Arc::Long), b, 1e-6));
}

#[test]
fn slerp_has_constant_angular_speed_and_nlerp_does_not() {
    let a = quat_from_axis_angle(Vec3::Y, -1.0);
    let b = quat_from_axis_angle(Vec3::new(1.0, 0.2, 0.0).normalize(), 2.0);
    let total = angle_between(a, b);
    let n = 16;
    let mut nlerp_steps = vec![];
    for i in 0..n {
        let (t0, t1) = (i as f32 / n as f32, (i + 1) as f32 / n as f32);
        assert_near!(
            angle_between(slerp(a, b, t0), slerp(a, b, t1)),
            total / n as f32,
            1e-5
        );
        nlerp_steps.push(angle_between(nlerp(a, b, t0), nlerp(a, b, t1)));
    }
    assert!(nlerp_steps[n / 2] > nlerp_steps[0] * 1.1, "{nlerp_steps:?}");
}

#[test]
fn slerp_short_and_long_arcs_turn_by_complementary_angles() {
    let a = Quat::IDENTITY;
    let b = quat_from_axis_angle(Vec3::Z, 1.0);
    let short_mid = slerp_arc(a, b, 0.5, Arc::Short);
    let long_mid = slerp_arc(a, b, 0.5, Arc::Long);
    assert_near!(angle_between(a, short_mid), 0.5, 1e-6);
    assert_near!(angle_between(a, long_mid), PI - 0.5, 1e-5);
    // Long arc between equal keys: one full turn, through the half turn at t = 1/2.
    let full = slerp_arc(b, b, 0.5, Arc::Long);
    assert_near!(angle_between(b, full), PI, 1e-5);
    assert!((full.length() - 1.0).abs() < 1e-6);
}

#[test]
fn slerp_nearly_equal_and_nearly_opposite_rotations() {
    let a = quat_from_axis_angle(Vec3::new(1.0, 1.0, 1.0).normalize(), 0.5);
    let axis = Vec3::new(0.0, 0.6, 0.8);
    for delta in [1e-7, 1e-5, 1e-3] {
        let b = a * quat_from_axis_angle(axis, delta);
        let mid = slerp(a, b, 0.5);
        let expected = a * quat_from_axis_angle(axis, 0.5 * delta);
        let err = (mid - expected).length().min((mid + expected).length());
        assert!(err < 2e-7, "{delta}: {err}");
    }
    for delta in [PI - 1e-3, PI - 1e-5] {
        let b = a * quat_from_axis_angle(axis, delta);
        for t in [0.25, 0.5, 0.9] {
            let got = slerp(a, b, t);
            let expected = a * quat_from_axis_angle(axis, t * delta);
            assert!(
                same_rotation(got, expected, 1e-6),
                "{delta} {t}: {got} vs {expected}"
            );
        }
    }
    // An exact half turn: both ways round are shortest; either must run at constant speed.
    let b = a * quat_from_axis_angle(axis, PI);
    for t in [0.25, 0.5, 0.9] {
        assert_near!(angle_between(a, slerp(a, b, t)), t * PI, 1e-5);
    }
}

#[test]
fn log_exp_and_pow() {
    let q = quat_from_axis_angle(Vec3::new(0.3, 0.4, 0.5).normalize(), 1.3);
    assert!(same_rotation(quat_exp(quat_log(q)), q, 1e-6));
    assert_eq!(quat_exp(Vec3::ZERO), Quat::IDENTITY);
    assert_eq!(quat_log(Quat::IDENTITY), Vec3::ZERO);
    assert!(same_rotation(quat_pow(q, 0.5) * quat_pow(q, 0.5), q, 1e-6));
    assert!(same_rotation(quat_pow(q, 0.0), Quat::IDENTITY, 1e-7));
    let tiny = quat_from_axis_angle(Vec3::Y, 2e-6);
    assert!(quat_log(tiny).abs_diff_eq(Vec3::new(0.0, 1e-6, 0.0), 1e-12));
}

// ---------------------------------------------------------------------------------------------
// Spline
// ---------------------------------------------------------------------------------------------

fn spline_keys() -> Vec<Quat> {
    vec![
        Quat::IDENTITY,
        quat_from_axis_angle(Vec3::Y, 1.2),
        -quat_from_axis_angle(Vec3::new(1.0, 1.0, 0.0).normalize(), 2.0), // sign must not matter
        quat_from_axis_angle(Vec3::Z, 0.5),
        quat_from_axis_angle(Vec3::X, -1.0),
    ]
}

#[test]
fn spline_passes_through_keys_with_unit_norm() {
    let keys = spline_keys();
    let spline = QuatSpline::new(&keys).unwrap();
    assert_eq!(spline.segment_count(), 4);
    for (i, key) in keys.iter().enumerate() {
        assert!(
            same_rotation(spline.sample(i as f32), *key, 1e-6),
            "key {i}"
        );
    }
    for i in 0..=80 {
        let q = spline.sample(i as f32 * 0.05);
        assert_near!(q.length(), 1.0, 1e-6);
    }
}

#[test]
fn spline_angular_velocity_is_continuous_at_interior_keys() {
    let spline = QuatSpline::new(&spline_keys()).unwrap();
    let h = 1e-3;
    for i in 1..4 {
        let u = i as f32;
        let q = spline.sample(u);
        // body angular velocity from one-sided differences: log(q⁻¹ q(u ± h)) / h
        let before = quat_log(q.conjugate() * spline.sample(u - h)) * (-2.0 / h);
        let after = quat_log(q.conjugate() * spline.sample(u + h)) * (2.0 / h);
        assert!(
            (before - after).length() < 0.02 * after.length().max(1.0),
            "key {i}: {before} vs {after}"
        );
    }
}

#[test]
fn spline_errors() {
    assert_eq!(
        QuatSpline::new(&[Quat::IDENTITY]),
        Err(RotationError::TooFewKeys { needed: 2, got: 1 })
    );
    let zero = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    assert_eq!(
        QuatSpline::new(&[Quat::IDENTITY, zero]),
        Err(RotationError::ZeroQuat)
    );
}

// ---------------------------------------------------------------------------------------------
// Naive matrix lerp
// ---------------------------------------------------------------------------------------------

#[test]
fn matrix_lerp_shrinks_and_loses_orthogonality() {
    let a = Mat3::IDENTITY;
    let b = Mat3::from_rotation_z(PI);
    let start = mat3_lerp_report(a, b, 0.0);
    assert_eq!(start.matrix, a);
    assert_near!(start.determinant, 1.0, 1e-6);
    let mid = mat3_lerp_report(a, b, 0.5);
    assert_near!(mid.determinant, 0.0, 1e-6); // a half turn apart: passes through a flat matrix
    let quarter = mat3_lerp_report(a, Mat3::from_rotation_z(FRAC_PI_2), 0.5);
    assert_near!(quarter.determinant, 0.5, 1e-6);
    assert!(quarter.orthogonality_error > 0.5);
    assert!(mat_near(mat3_lerp(a, b, 1.0), b, 1e-7));
}

#[test]
fn rotation_matrix_checks() {
    let r = Mat3::from_rotation_y(0.3);
    assert_eq!(check_rotation_mat3(r), Ok(r));
    let scaled = r * 1.1;
    match check_rotation_mat3(scaled) {
        Err(RotationError::NotOrthonormal { error, .. }) => assert!(error > 0.3),
        other => panic!("{other:?}"),
    }
    let mirror = Mat3::from_diagonal(Vec3::new(1.0, 1.0, -1.0));
    assert!(matches!(
        check_rotation_mat3(mirror),
        Err(RotationError::Reflection { .. })
    ));
    let nan = Mat3::from_cols(Vec3::NAN, Vec3::Y, Vec3::Z);
    assert_eq!(
        check_rotation_mat3(nan),
        Err(RotationError::NonFinite { what: "matrix" })
    );
}

#[test]
fn quaternion_checks() {
    assert_eq!(
        check_quat(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)),
        Err(RotationError::ZeroQuat)
    );
    assert!(matches!(
        check_quat(Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0)),
        Err(RotationError::NonFinite { .. })
    ));
    let q = check_quat(Quat::from_xyzw(0.0, 0.0, 0.0, 2.0)).unwrap();
    assert_eq!(q, Quat::IDENTITY);
    assert_eq!(
        AxisAngle::new(Vec3::ZERO, 1.0),
        Err(RotationError::ZeroAxis)
    );
}

#[test]
fn error_messages_are_readable() {
    let messages = [
        RotationError::ZeroQuat.to_string(),
        RotationError::NotOrthonormal {
            error: 0.25,
            tolerance: ROTATION_TOLERANCE,
        }
        .to_string(),
        RotationError::SingularMatrix { determinant: 0.0 }.to_string(),
    ];
    assert!(messages[0].contains("zero length"));
    assert!(messages[1].contains("2.500e-1") && messages[1].contains("not orthonormal"));
    assert!(messages[2].contains("singular"));
    let boxed: Box<dyn std::error::Error> = Box::new(RotationError::ZeroAxis);
    assert!(boxed.to_string().contains("axis"));
}

// ---------------------------------------------------------------------------------------------
// Polar decomposition and affine keys
// ---------------------------------------------------------------------------------------------

fn shear_scale_rotate() -> Mat3 {
    let r = Mat3::from_quat(quat_from_axis_angle(
        Vec3::new(1.0, -2.0, 0.5).normalize(),
        2.2,
    ));
    let s = Mat3::from_cols(
        Vec3::new(2.0, 0.3, 0.0),
        Vec3::new(0.3, 0.5, 0.1),
        Vec3::new(0.0, 0.1, 1.5),
    );
    r * s
}

fn assert_polar_factors(m: Mat3, p: &PolarDecomposition) {
    assert!(orthogonality_error(p.rotation) < 1e-5);
    assert_near!(p.rotation.determinant(), 1.0, 1e-5);
    assert!(mat_near(p.stretch, p.stretch.transpose(), 1e-6));
    let (lambda, _) = symmetric_eigen(p.stretch);
    assert!(
        lambda.min_element() > 0.0,
        "stretch not positive definite: {lambda}"
    );
    assert!(mat_near(
        p.rotation * p.stretch,
        m,
        1e-5 * (1.0 + m.abs().to_cols_array().iter().cloned().fold(0.0, f32::max))
    ));
}

#[test]
fn polar_factors_are_rotation_and_spd_with_product_m() {
    let m = shear_scale_rotate();
    let p = polar_decompose(m).unwrap();
    assert_polar_factors(m, &p);
    assert!(p.iterations > 1 && p.iterations < 20, "{}", p.iterations);
    let check = polar_decompose_eigen(m).unwrap();
    assert!(mat_near(p.rotation, check.rotation, 1e-5));
    assert!(mat_near(p.stretch, check.stretch, 1e-5));
}

#[test]
fn polar_of_a_rotation_is_itself_and_step_fixes_rotations() {
    let r = Mat3::from_rotation_x(0.9);
    let p = polar_decompose(r).unwrap();
    assert!(mat_near(p.rotation, r, 1e-6));
    assert!(mat_near(p.stretch, Mat3::IDENTITY, 1e-6));
    assert!(mat_near(polar_step(r), r, 1e-6));
    // one step moves a scale s to (s + 1/s)/2
    let step = polar_step(Mat3::from_diagonal(Vec3::new(2.0, 0.5, 1.0)));
    assert!(mat_near(
        step,
        Mat3::from_diagonal(Vec3::new(1.25, 1.25, 1.0)),
        1e-6
    ));
}

#[test]
fn polar_errors() {
    let singular = Mat3::from_cols(Vec3::X, Vec3::X, Vec3::Z);
    assert!(matches!(
        polar_decompose(singular),
        Err(RotationError::SingularMatrix { .. })
    ));
    assert!(matches!(
        polar_decompose(Mat3::ZERO),
        Err(RotationError::SingularMatrix { .. })
    ));
    let mirror = Mat3::from_diagonal(Vec3::new(-1.0, 2.0, 1.0));
    assert!(matches!(
        polar_decompose(mirror),
        Err(RotationError::Reflection { .. })
    ));
    assert!(matches!(
        polar_decompose_with(Mat3::from_diagonal(Vec3::new(1e4, 1.0, 1.0)), 1e-7, 3),
        Err(RotationError::NotConverged { iterations: 3, .. })
    ));
    let nan = Mat3::from_cols(Vec3::new(f32::NAN, 0.0, 0.0), Vec3::Y, Vec3::Z);
    assert!(matches!(
        polar_decompose(nan),
        Err(RotationError::NonFinite { .. })
    ));
}

#[test]
fn symmetric_eigen_reconstructs() {
    let s = Mat3::from_cols(
        Vec3::new(4.0, 1.0, -2.0),
        Vec3::new(1.0, 2.0, 0.5),
        Vec3::new(-2.0, 0.5, 3.0),
    );
    let (lambda, v) = symmetric_eigen(s);
    assert!(orthogonality_error(v) < 1e-5);
    assert!(mat_near(
        v * Mat3::from_diagonal(lambda) * v.transpose(),
        s,
        1e-5
    ));
}

#[test]
fn affine_keys_interpolate_through_polar_factors() {
    let m0 =
        Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0)) * Mat4::from_mat3(shear_scale_rotate());
    let m1 = Mat4::from_scale_rotation_translation(
        Vec3::new(1.0, 3.0, 0.5),
        Quat::from_rotation_y(1.0),
        Vec3::ZERO,
    );
    let k0 = AffineKey::from_mat4(m0).unwrap();
    let k1 = AffineKey::from_mat4(m1).unwrap();
    assert!(k0.to_mat4().abs_diff_eq(m0, 1e-5));
    assert!(k0.interpolate(&k1, 0.0).to_mat4().abs_diff_eq(m0, 1e-5));
    assert!(k0.interpolate(&k1, 1.0).to_mat4().abs_diff_eq(m1, 1e-5));
    for i in 0..=10 {
        let t = i as f32 / 10.0;
        let k = k0.interpolate(&k1, t);
        assert!(k
            .translation
            .abs_diff_eq(Vec3::new(1.0, 2.0, 3.0) * (1.0 - t), 1e-5));
        assert!(
            Mat3::from_mat4(k.to_mat4()).determinant() > 0.1,
            "key flattened at {t}"
        );
        assert!(same_rotation(
            k.rotation,
            slerp(k0.rotation, k1.rotation, t),
            1e-6
        ));
    }
    // The naive lerp of the same keys can flatten.
    let flip = Mat4::from_rotation_z(PI);
    assert_near!(
        Mat3::from_mat4(affine_lerp_naive(Mat4::IDENTITY, flip, 0.5)).determinant(),
        0.0,
        1e-6
    );
}

#[test]
fn affine_key_errors() {
    let singular = Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0));
    assert!(matches!(
        AffineKey::from_mat4(singular),
        Err(RotationError::SingularMatrix { .. })
    ));
    let mut projective = Mat4::IDENTITY;
    projective.x_axis.w = 0.5;
    assert!(matches!(
        AffineKey::from_mat4(projective),
        Err(RotationError::NotAffine { .. })
    ));
    let msg = AffineKey::from_mat4(singular).unwrap_err().to_string();
    assert!(msg.contains("singular"), "{msg}");
}

// ---------------------------------------------------------------------------------------------
// Property tests
// ---------------------------------------------------------------------------------------------

proptest! {
    #[test]
    fn prop_quat_matrix_round_trip(q in arb_quat()) {
        let back = quat_from_mat3(mat3_from_quat(q));
        prop_assert!(same_rotation(back, q, 2e-6), "{} vs {}", back, q);
        prop_assert!(orthogonality_error(mat3_from_quat(q)) < 2e-6);
    }

    #[test]
    fn prop_rotation_vector_round_trip(q in arb_quat()) {
        let back = quat_from_rotation_vector(rotation_vector_from_quat(q));
        prop_assert!(same_rotation(back, q, 2e-6));
        let aa = AxisAngle::from_quat(q);
        prop_assert!(aa.angle_rad <= PI + 1e-6);
        prop_assert!(same_rotation(aa.to_quat(), q, 2e-6));
        prop_assert!(mat_near(aa.to_mat3(), mat3_from_quat(q), 2e-6));
    }

    #[test]
    fn prop_euler_round_trip(q in arb_quat(), which in 0usize..12) {
        let order = EulerOrder::ALL[which];
        let e = EulerAngles::from_quat(q, order);
        // Near gimbal lock the angles lose digits, but the rotation must survive.
        let eps = if e.gimbal_lock { 1e-3 } else { 2e-5 };
        prop_assert!(same_rotation(e.to_quat(), q, eps));
        prop_assert!(mat_near(e.to_mat3(), mat3_from_quat(q), eps));
    }

    #[test]
    fn prop_slerp_unit_norm_and_on_the_arc(a in arb_quat(), b in arb_quat(), t in 0.0f32..1.0) {
        let q = slerp(a, b, t);
        prop_assert!((q.length() - 1.0).abs() < 1e-6);
        let n = nlerp(a, b, t);
        prop_assert!((n.length() - 1.0).abs() < 1e-6);
        let total = angle_between(a, b);
        prop_assert!((angle_between(a, q) - t * total).abs() < 1e-4 + 1e-4 * total);
        prop_assert!((angle_between(q, b) - (1.0 - t) * total).abs() < 1e-4 + 1e-4 * total);
    }

    #[test]
    fn prop_log_exp_inverse(q in arb_quat()) {
        prop_assert!(same_rotation(quat_exp(quat_log(q)), q, 2e-6));
    }

    #[test]
    fn prop_polar_factors(
        q in arb_quat(),
        diag in prop::array::uniform3(0.2f32..5.0),
        off in prop::array::uniform3(-0.5f32..0.5),
    ) {
        let s = Mat3::from_cols(
            Vec3::new(diag[0], off[0], off[1]),
            Vec3::new(off[0], diag[1], off[2]),
            Vec3::new(off[1], off[2], diag[2]),
        );
        let m = mat3_from_quat(q) * s;
        prop_assume!(m.determinant() > 1e-2);
        let p = polar_decompose(m).unwrap();
        assert_polar_factors(m, &p);
    }
}

// ---------------------------------------------------------------------------------------------
// Reference values (scipy)
// ---------------------------------------------------------------------------------------------

const REFERENCE: &str = include_str!("data/rotation_reference.txt");

/// Records named `kind`: the first word after the name (kept as text) and the numbers.
fn records(kind: &str) -> Vec<(String, Vec<f32>)> {
    REFERENCE
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| {
            let mut words = l.split_whitespace();
            (words.next() == Some(kind)).then(|| {
                let rest: Vec<&str> = words.collect();
                let label = rest.first().map(|s| s.to_string()).unwrap_or_default();
                let numbers = rest.iter().filter_map(|w| w.parse::<f32>().ok()).collect();
                (label, numbers)
            })
        })
        .collect()
}

fn quat_at(v: &[f32], i: usize) -> Quat {
    Quat::from_xyzw(v[i], v[i + 1], v[i + 2], v[i + 3])
}

#[test]
fn reference_slerp_scipy() {
    let rows = records("slerp");
    assert!(rows.len() >= 10);
    for (_, v) in rows {
        let (a, b, t, expected) = (quat_at(&v, 0), quat_at(&v, 4), v[8], quat_at(&v, 9));
        let got = slerp(a, b, t);
        assert!(
            same_rotation(got, expected, 1e-5),
            "t = {t}: {got} vs {expected}"
        );
    }
}

#[test]
fn reference_euler_scipy() {
    let rows = records("euler");
    assert!(rows.len() >= 12);
    for (name, v) in rows {
        let order = EulerOrder::ALL
            .into_iter()
            .find(|o| o.name() == name)
            .expect("order");
        let angles = Vec3::new(v[0], v[1], v[2]);
        let expected = quat_at(&v, 3);
        let e = EulerAngles::new(order, angles);
        assert!(same_rotation(e.to_quat(), expected, 1e-5), "{name}");
        assert!(
            same_rotation(quat_from_mat3(e.to_mat3()), expected, 1e-5),
            "{name}"
        );
        let back = EulerAngles::from_quat(expected, order);
        assert!(
            back.angles_rad.abs_diff_eq(angles, 1e-5),
            "{name}: {} vs {angles}",
            back.angles_rad
        );
    }
}

#[test]
fn reference_rotation_vectors_scipy() {
    let rows = records("rotvec");
    assert!(rows.len() >= 8);
    for (_, v) in rows {
        let rotvec = Vec3::new(v[0], v[1], v[2]);
        let expected = quat_at(&v, 3);
        let canonical = Vec3::new(v[7], v[8], v[9]);
        let q = quat_from_rotation_vector(rotvec);
        assert!(
            same_rotation(q, expected, 1e-6),
            "{rotvec}: {q} vs {expected}"
        );
        let back = rotation_vector_from_quat(expected);
        assert!(
            (back - canonical).length() <= 1e-5 * canonical.length().max(1e-2),
            "{back} vs {canonical}"
        );
    }
}

#[test]
fn reference_matrix_to_quaternion_near_pi_scipy() {
    let rows = records("matquat");
    assert!(rows.len() >= 8);
    for (_, v) in rows {
        let m = Mat3::from_cols_array(&[v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]])
            .transpose();
        let expected = quat_at(&v, 9);
        let got = quat_from_mat3(m);
        assert!(same_rotation(got, expected, 1e-6), "{got} vs {expected}");
    }
}

/// A case from the property test: near a half-turn (w ≈ −1) a quaternion whose norm is off by
/// rounding comes back from exp(log q) within 2e-6 (a log that divided by sinc φ would amplify
/// the norm error by 1 / sin φ and miss by 4e-6).
#[test]
fn log_exp_near_a_half_turn_with_rounding_in_the_norm() {
    let q = Quat::from_xyzw(-0.099_271_34, 0.0, 0.0, -0.995_060_4);
    assert!(same_rotation(quat_exp(quat_log(q)), q, 2e-6));
    assert_eq!(quat_log(Quat::IDENTITY), Vec3::ZERO);
    assert!((quat_log(-Quat::IDENTITY).length() - PI).abs() < 1e-6);
}
