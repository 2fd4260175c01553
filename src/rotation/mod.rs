//! # Rotations: representations, conversions and interpolation
//!
//! A rotation of 3D space has three degrees of freedom, but no single way of writing it down is
//! best at everything, so this module converts freely between five of them:
//!
//! | representation | type here | good at | weak at |
//! |---|---|---|---|
//! | rotation matrix `R` (3x3, `RᵀR = I`, `det R = 1`) | `glam::Mat3` | applying to many vectors, composing (`R₁R₂`) | 9 numbers for 3 degrees of freedom; lerp leaves the set of rotations |
//! | Euler angles (three turns about coordinate axes) | [`EulerAngles`], [`EulerOrder`] | animator-friendly curves | gimbal lock, odd interpolation paths |
//! | axis-angle `(n, θ)` | [`AxisAngle`] | meaning; Rodrigues' formula | composition |
//! | rotation vector `v = θ n` | `glam::Vec3` | 3 numbers, no constraint | composition |
//! | unit quaternion `q = (n sin(θ/2), cos(θ/2))` | `glam::Quat` | composition, slerp, splines | `q` and `−q` are the same rotation |
//!
//! On top of these: quaternion [`slerp`] / [`nlerp`] (short arc by default, [`Arc::Long`] for the
//! lesson), [`quat_log`] / [`quat_exp`], a smooth spline through several orientations
//! ([`QuatSpline`], SQUAD), naive comparisons ([`mat3_lerp`], [`euler_lerp`]), polar decomposition
//! of a general 3x3 matrix ([`polar_decompose`]) and interpolation of 4x4 affine keys
//! ([`AffineKey`]).
//!
//! ## Conventions (see the crate root)
//! Right-handed, column vectors (`v' = R v`, so `R₁ R₂` applies `R₂` first, and likewise
//! `q₁ q₂`), glam's quaternion storage order `(x, y, z, w)` with `w` the scalar part, angles in
//! radians, `t ∈ [0, 1]`. Functions taking a quaternion "as a rotation" expect unit length; the
//! `check_*` functions turn caller data into validated values or a [`RotationError`].
//!
//! Lesson: `lessons/03-rotations` (matrix lerp vs Euler lerp vs nlerp vs slerp, gimbal, Rodrigues).

mod affine;
mod axis_angle;
mod error;
mod euler;
mod matrix;
mod polar;
mod quat;
mod spline;

pub use affine::{affine_lerp_naive, AffineKey};
pub use axis_angle::{
    quat_from_axis_angle, quat_from_rotation_vector, rodrigues_mat3, rodrigues_rotate,
    rotation_vector_from_mat3, rotation_vector_from_quat, AxisAngle,
};
pub use error::RotationError;
pub use euler::{euler_lerp, EulerAngles, EulerOrder, GIMBAL_LOCK_COS_EPS};
pub use matrix::{
    check_rotation_mat3, mat3_lerp, mat3_lerp_report, orthogonality_error, MatLerpSample,
    ROTATION_TOLERANCE,
};
pub use polar::{
    polar_decompose, polar_decompose_eigen, polar_decompose_with, polar_step, symmetric_eigen,
    PolarDecomposition, POLAR_MAX_ITERATIONS, POLAR_TOLERANCE,
};
pub use quat::{
    angle_between, check_quat, mat3_from_quat, nlerp, nlerp_arc, quat_exp, quat_from_mat3,
    quat_log, quat_pow, slerp, slerp_arc, Arc,
};
pub use spline::QuatSpline;

/// `sin(x) / x`, accurate near 0 (Taylor series) where the quotient would lose digits.
/// ```text
/// sinc(x) = 1 − x²/6 + x⁴/120 − …   for |x| small
/// ```
pub(crate) fn sinc(x: f32) -> f32 {
    if x.abs() < 1e-2 {
        let x2 = x * x;
        1.0 - x2 / 6.0 * (1.0 - x2 / 20.0)
    } else {
        x.sin() / x
    }
}
