//! Rotation matrices: validation, and the naive element-wise lerp shown for comparison.

use glam::Mat3;

use super::RotationError;

/// Largest `‖RᵀR − I‖` (Frobenius) accepted from a caller for a matrix given as a rotation.
///
/// Loose enough for matrices typed with 4 to 5 significant digits or built in `f32`, tight
/// enough to reject any visible scale or shear.
pub const ROTATION_TOLERANCE: f32 = 1e-3;

/// How far a matrix is from orthonormal.
/// ```text
/// e(M) = ‖MᵀM − I‖_F = √(Σᵢⱼ ((MᵀM)ᵢⱼ − δᵢⱼ)²)
/// ```
/// Zero exactly for rotations and reflections; grows with any scale or shear.
pub fn orthogonality_error(m: Mat3) -> f32 {
    let e = m.transpose() * m - Mat3::IDENTITY;
    (e.x_axis.length_squared() + e.y_axis.length_squared() + e.z_axis.length_squared()).sqrt()
}

/// Checks that a caller's matrix is a rotation: finite, orthonormal to
/// [`ROTATION_TOLERANCE`], determinant `+1` (not a mirror).
///
/// # Errors
/// [`RotationError::NonFinite`], [`RotationError::NotOrthonormal`] (with the measured error),
/// [`RotationError::Reflection`] (with the determinant).
pub fn check_rotation_mat3(m: Mat3) -> Result<Mat3, RotationError> {
    if !m.is_finite() {
        return Err(RotationError::NonFinite { what: "matrix" });
    }
    let error = orthogonality_error(m);
    if error > ROTATION_TOLERANCE || error.is_nan() {
        return Err(RotationError::NotOrthonormal {
            error,
            tolerance: ROTATION_TOLERANCE,
        });
    }
    let determinant = m.determinant();
    if determinant < 0.0 {
        return Err(RotationError::Reflection { determinant });
    }
    Ok(m)
}

/// Element-wise linear interpolation of two matrices: the naive method the lesson warns about.
/// ```text
/// M(t) = (1 − t) A + t B
/// ```
/// `t = 0` gives `A`, `t = 1` gives `B`. Between two rotations `M(t)` is in general not a
/// rotation: it shrinks (between rotations half a turn apart it passes through a singular
/// matrix) and shears. See [`mat3_lerp_report`].
pub fn mat3_lerp(a: Mat3, b: Mat3, t: f32) -> Mat3 {
    a * (1.0 - t) + b * t
}

/// One sample of [`mat3_lerp`] with the two numbers the lesson plots.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MatLerpSample {
    /// `M(t) = (1 − t) A + t B`.
    pub matrix: Mat3,
    /// `det M(t)`: 1 for a rotation, less when the object shrinks.
    pub determinant: f32,
    /// `‖M(t)ᵀM(t) − I‖_F`: 0 for a rotation.
    pub orthogonality_error: f32,
}

/// [`mat3_lerp`] with its determinant and orthogonality error.
pub fn mat3_lerp_report(a: Mat3, b: Mat3, t: f32) -> MatLerpSample {
    let matrix = mat3_lerp(a, b, t);
    MatLerpSample {
        matrix,
        determinant: matrix.determinant(),
        orthogonality_error: orthogonality_error(matrix),
    }
}
