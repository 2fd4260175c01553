//! Interpolation of general affine keys (rotation, scale, shear, translation) through polar
//! decomposition.

use glam::{Mat3, Mat4, Quat, Vec3, Vec4};

use super::{polar_decompose, quat_from_mat3, slerp, RotationError};

/// A 4x4 affine key split into the parts that interpolate well.
/// ```text
/// M = ⎡ R D  p ⎤      p: translation,  R: rotation (as a quaternion),
///     ⎣  0   1 ⎦      D: symmetric positive definite stretch (scale and shear)
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AffineKey {
    /// Translation `p`, in the parent space.
    pub translation: Vec3,
    /// Rotation `R` as a unit quaternion with `w ≥ 0`.
    pub rotation: Quat,
    /// Stretch `D` (symmetric positive definite), applied before the rotation.
    pub stretch: Mat3,
}

impl AffineKey {
    /// Splits an affine matrix by polar decomposition of its upper-left 3x3 block.
    ///
    /// # Errors
    /// [`RotationError::NonFinite`]; [`RotationError::NotAffine`] when the bottom row is not
    /// `(0, 0, 0, 1)` (to 1e-6); and the errors of [`polar_decompose`], notably
    /// [`RotationError::SingularMatrix`] for a key that flattens space.
    pub fn from_mat4(m: Mat4) -> Result<Self, RotationError> {
        if !m.is_finite() {
            return Err(RotationError::NonFinite { what: "matrix" });
        }
        let bottom_row = m.row(3);
        if (bottom_row - Vec4::W).abs().max_element() > 1e-6 {
            return Err(RotationError::NotAffine {
                bottom_row: bottom_row.to_array(),
            });
        }
        let polar = polar_decompose(Mat3::from_mat4(m))?;
        Ok(Self {
            translation: m.w_axis.truncate(),
            rotation: quat_from_mat3(polar.rotation),
            stretch: polar.stretch,
        })
    }

    /// The affine matrix `[R D | p]`.
    pub fn to_mat4(&self) -> Mat4 {
        let linear = Mat3::from_quat(self.rotation) * self.stretch;
        Mat4::from_cols(
            linear.x_axis.extend(0.0),
            linear.y_axis.extend(0.0),
            linear.z_axis.extend(0.0),
            self.translation.extend(1.0),
        )
    }

    /// Interpolates two keys part by part (Shoemake & Duff).
    /// ```text
    /// p(t) = (1 − t) p₀ + t p₁
    /// q(t) = slerp(q₀, q₁; t)          (short arc)
    /// D(t) = (1 − t) D₀ + t D₁
    /// M(t) = [R(q(t)) D(t) | p(t)]
    /// ```
    /// `t = 0` gives `self`, `t = 1` gives `other`. `D(t)` stays symmetric positive definite (a
    /// convex combination of such matrices), so the key never flattens or mirrors on the way.
    pub fn interpolate(&self, other: &AffineKey, t: f32) -> AffineKey {
        AffineKey {
            translation: self.translation.lerp(other.translation, t),
            rotation: slerp(self.rotation, other.rotation, t),
            stretch: self.stretch * (1.0 - t) + other.stretch * t,
        }
    }
}

/// Element-wise lerp of two 4x4 matrices, for comparison with [`AffineKey::interpolate`].
/// ```text
/// M(t) = (1 − t) M₀ + t M₁
/// ```
pub fn affine_lerp_naive(a: Mat4, b: Mat4, t: f32) -> Mat4 {
    a * (1.0 - t) + b * t
}
