//! The unit dual quaternion `q = r + ε d` of a rigid motion.

use core::ops::Mul;

use glam::{Mat4, Quat, Vec3, Vec4};

use crate::rotation::{
    check_quat, check_rotation_mat3, mat3_from_quat, quat_from_mat3, RotationError,
};

/// A rigid motion as a unit dual quaternion `q = r + ε d` (`ε² = 0`).
/// ```text
/// r = rotation (unit quaternion),    d = ½ t r    (t = (t, 0), the translation)
/// p' = r p r* + t                    rotate first, then translate
/// ```
/// Unit means `‖r‖ = 1` and `r · d = 0`. `q` and `−q` are the same motion. `a * b` applies `b`
/// first, then `a`, like matrices. (Named `DualQuat` because glam's `DQuat` is the `f64`
/// quaternion.)
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)] // eight floats, real then dual: the AVX2 skinning kernel loads them so
pub struct DualQuat {
    /// Real part `r`: the rotation.
    pub real: Quat,
    /// Dual part `d = ½ t r`: encodes the translation.
    pub dual: Quat,
}

const ZERO_QUAT: Quat = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);

fn pure(v: Vec3) -> Quat {
    Quat::from_xyzw(v.x, v.y, v.z, 0.0)
}

fn vector_part(q: Quat) -> Vec3 {
    Vec3::new(q.x, q.y, q.z)
}

impl Default for DualQuat {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl DualQuat {
    /// The motion that moves nothing: `1 + ε 0`.
    pub const IDENTITY: DualQuat = DualQuat {
        real: Quat::IDENTITY,
        dual: ZERO_QUAT,
    };

    /// Rotate by `rotation` (about the origin), then translate by `translation`.
    /// ```text
    /// q = r + ε ½ (t, 0) r
    /// ```
    /// Expects a unit `rotation` (use [`check_quat`] on caller data).
    pub fn from_rotation_translation(rotation: Quat, translation: Vec3) -> Self {
        Self {
            real: rotation,
            dual: pure(translation) * rotation * 0.5,
        }
    }

    /// A pure rotation about the origin: `r + ε 0`.
    pub fn from_rotation(rotation: Quat) -> Self {
        Self {
            real: rotation,
            dual: ZERO_QUAT,
        }
    }

    /// A pure translation: `1 + ε ½ (t, 0)`.
    pub fn from_translation(translation: Vec3) -> Self {
        Self {
            real: Quat::IDENTITY,
            dual: pure(translation * 0.5),
        }
    }

    /// The rotation `r`.
    pub fn rotation(&self) -> Quat {
        self.real
    }

    /// The translation, applied after the rotation.
    /// ```text
    /// t = 2 d r*
    /// ```
    pub fn translation(&self) -> Vec3 {
        vector_part(self.dual * self.real.conjugate()) * 2.0
    }

    /// `(rotation, translation)`, the inverse of [`DualQuat::from_rotation_translation`].
    pub fn to_rotation_translation(&self) -> (Quat, Vec3) {
        (self.real, self.translation())
    }

    /// The 4x4 matrix `[R | t]` of the motion (for a unit dual quaternion).
    pub fn to_mat4(&self) -> Mat4 {
        let r = mat3_from_quat(self.real);
        Mat4::from_cols(
            r.x_axis.extend(0.0),
            r.y_axis.extend(0.0),
            r.z_axis.extend(0.0),
            self.translation().extend(1.0),
        )
    }

    /// The dual quaternion of a rigid 4x4 matrix `[R | t]`.
    ///
    /// # Errors
    /// [`RotationError::NonFinite`]; [`RotationError::NotAffine`] for a bottom row other than
    /// `(0, 0, 0, 1)`; [`RotationError::NotOrthonormal`] or [`RotationError::Reflection`] when the
    /// 3x3 block is not a rotation (a scaled matrix is not a rigid motion).
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
        let r = check_rotation_mat3(glam::Mat3::from_mat4(m))?;
        Ok(Self::from_rotation_translation(
            quat_from_mat3(r),
            m.w_axis.truncate(),
        ))
    }

    /// Quaternion conjugate of both parts: the inverse motion, for a unit dual quaternion.
    /// ```text
    /// q* = r* + ε d*,      q q* = 1
    /// ```
    /// (Of the three conjugates of a dual quaternion, this is the one that inverts.)
    pub fn conjugate(&self) -> Self {
        Self {
            real: self.real.conjugate(),
            dual: self.dual.conjugate(),
        }
    }

    /// Inverse motion. For a unit dual quaternion this is [`DualQuat::conjugate`]; for a
    /// non-unit one the general formula is used.
    /// ```text
    /// q⁻¹ = r⁻¹ − ε r⁻¹ d r⁻¹
    /// ```
    pub fn inverse(&self) -> Self {
        let r_inv = self.real.inverse();
        Self {
            real: r_inv,
            dual: -(r_inv * self.dual * r_inv),
        }
    }

    /// Validates a caller's dual quaternion and returns it normalised.
    ///
    /// # Errors
    /// [`RotationError::NonFinite`] for NaN or infinities, [`RotationError::ZeroQuat`] when the
    /// real part has zero length.
    pub fn check(self) -> Result<Self, RotationError> {
        if !self.dual.is_finite() {
            return Err(RotationError::NonFinite {
                what: "dual quaternion",
            });
        }
        check_quat(self.real).map_err(|e| match e {
            RotationError::NonFinite { .. } => RotationError::NonFinite {
                what: "dual quaternion",
            },
            other => other,
        })?;
        Ok(self.normalized())
    }

    /// Normalised copy: unit real part and dual part orthogonal to it.
    /// ```text
    /// r' = r/‖r‖,   d' = d/‖r‖ − r' (r' · d/‖r‖)
    /// ```
    /// Removes the drift that products and blends accumulate. Expects `r ≠ 0`.
    pub fn normalized(&self) -> Self {
        let inv = 1.0 / self.real.length();
        let real = self.real * inv;
        let dual = self.dual * inv;
        let dual = dual - real * real.dot(dual);
        Self { real, dual }
    }

    /// Normalises in place; see [`DualQuat::normalized`].
    pub fn normalize(&mut self) {
        *self = self.normalized();
    }

    /// Applies the motion to a point: rotate, then translate.
    /// ```text
    /// p' = r p r* + t,     t = 2 d r*
    /// ```
    pub fn transform_point(&self, p: Vec3) -> Vec3 {
        self.real * p + self.translation()
    }

    /// Applies the motion to a direction: directions are not translated.
    /// ```text
    /// v' = r v r*
    /// ```
    pub fn transform_direction(&self, v: Vec3) -> Vec3 {
        self.real * v
    }

    /// Applies the motion to a point with the full dual quaternion sandwich, the textbook way.
    /// ```text
    /// 1 + ε p'  =  q (1 + ε p) q̄,     q̄ = r* − ε d*
    /// ```
    /// Same result as [`DualQuat::transform_point`], with two dual quaternion products (six
    /// quaternion products) per point.
    pub fn transform_point_sandwich(&self, p: Vec3) -> Vec3 {
        let point = DualQuat {
            real: Quat::IDENTITY,
            dual: pure(p),
        };
        let bar = DualQuat {
            real: self.real.conjugate(),
            dual: -self.dual.conjugate(),
        };
        vector_part((*self * point * bar).dual)
    }

    /// Applies the motion to many points, with the per-motion work factored out.
    /// ```text
    /// once:       R = matrix(r),  t = 2 d r*
    /// per point:  p'ᵢ = R pᵢ + t
    /// ```
    /// Writes `out[i]` for each `points[i]`; allocates nothing.
    ///
    /// # Errors
    /// [`RotationError::LengthMismatch`] when `out.len() != points.len()`.
    pub fn transform_points(&self, points: &[Vec3], out: &mut [Vec3]) -> Result<(), RotationError> {
        check_lengths(points, out)?;
        let r = mat3_from_quat(self.real);
        let t = self.translation();
        for (p, o) in points.iter().zip(out.iter_mut()) {
            *o = r * *p + t;
        }
        Ok(())
    }

    /// The naive baseline for [`DualQuat::transform_points`]: the full sandwich
    /// ([`DualQuat::transform_point_sandwich`]) redone for every point.
    ///
    /// # Errors
    /// [`RotationError::LengthMismatch`] when `out.len() != points.len()`.
    pub fn transform_points_sandwich(
        &self,
        points: &[Vec3],
        out: &mut [Vec3],
    ) -> Result<(), RotationError> {
        check_lengths(points, out)?;
        for (p, o) in points.iter().zip(out.iter_mut()) {
            *o = self.transform_point_sandwich(*p);
        }
        Ok(())
    }

    /// Dual quaternion linear blending of two motions (DLB): nlerp in the 8D space.
    /// ```text
    /// q(t) = ((1 − t) a + t b) / ‖(1 − t) a.r + t b.r‖       (b negated when a.r · b.r < 0)
    /// ```
    /// `t = 0` gives `a`, `t = 1` gives `b`; always a rigid motion, but not at constant speed and
    /// not exactly along the screw. Expects unit dual quaternions.
    pub fn nlerp(a: DualQuat, b: DualQuat, t: f32) -> DualQuat {
        let b = if a.real.dot(b.real) < 0.0 {
            b * -1.0
        } else {
            b
        };
        (a * (1.0 - t) + b * t).normalized()
    }

    /// Screw linear interpolation (ScLERP): constant-speed motion along the screw from `a` to
    /// `b`.
    /// ```text
    /// q(t) = exp(t · log(b a*)) a
    /// ```
    /// `t = 0` gives `a`, `t = 1` gives `b` (up to sign); the relative motion `b a*` turns by at
    /// most π (short way). Two transcendental evaluations per call: for many samples between the
    /// same pair, use [`super::ScrewInterpolator`], which caches the logarithm.
    pub fn sclerp(a: DualQuat, b: DualQuat, t: f32) -> DualQuat {
        ((b * a.conjugate()).log() * t).exp() * a
    }
}

fn check_lengths(points: &[Vec3], out: &[Vec3]) -> Result<(), RotationError> {
    if points.len() != out.len() {
        return Err(RotationError::LengthMismatch {
            expected: points.len(),
            got: out.len(),
        });
    }
    Ok(())
}

/// Composition: `a * b` applies `b` first, then `a`.
/// ```text
/// (a.r + ε a.d)(b.r + ε b.d) = a.r b.r + ε (a.r b.d + a.d b.r)
/// ```
impl Mul for DualQuat {
    type Output = DualQuat;
    fn mul(self, rhs: DualQuat) -> DualQuat {
        DualQuat {
            real: self.real * rhs.real,
            dual: self.real * rhs.dual + self.dual * rhs.real,
        }
    }
}

/// Scales all eight components (used by blending; the result is not unit).
impl Mul<f32> for DualQuat {
    type Output = DualQuat;
    fn mul(self, s: f32) -> DualQuat {
        DualQuat {
            real: self.real * s,
            dual: self.dual * s,
        }
    }
}

/// Component-wise sum (used by blending; the result is not unit).
impl core::ops::Add for DualQuat {
    type Output = DualQuat;
    fn add(self, rhs: DualQuat) -> DualQuat {
        DualQuat {
            real: self.real + rhs.real,
            dual: self.dual + rhs.dual,
        }
    }
}

/// Dual quaternion of "rotate by `rotation`, then translate by `translation`".
/// ```text
/// q = r + ε ½ (t, 0) r
/// ```
/// Same as [`DualQuat::from_rotation_translation`]; expects a unit `rotation`.
///
/// This is the reference for the "dual quaternion from rotation + translation" exercise.
pub fn dual_quat_from_rotation_translation(rotation: Quat, translation: Vec3) -> DualQuat {
    DualQuat::from_rotation_translation(rotation, translation)
}

/// Applies a unit dual quaternion to a point.
/// ```text
/// p' = r p r* + 2 d r*
/// ```
/// Same as [`DualQuat::transform_point`].
///
/// This is the reference for the "apply the dual quaternion to a point" exercise.
pub fn dual_quat_transform_point(dq: DualQuat, point: Vec3) -> Vec3 {
    dq.transform_point(point)
}

/// Dual quaternion linear blending of several motions, as in skinning (Kavan et al. 2007).
/// ```text
/// q = Σ wᵢ sᵢ qᵢ / ‖Σ wᵢ sᵢ rᵢ‖,     sᵢ = ±1 so that r₀ · rᵢ ≥ 0
/// ```
/// # Errors
/// [`RotationError::LengthMismatch`] when the slices differ in length,
/// [`RotationError::TooFewKeys`] when they are empty, [`RotationError::BadWeights`] for a
/// negative weight or a zero sum, [`RotationError::ZeroQuat`] when the blend cancels out.
pub fn dual_quat_blend(motions: &[DualQuat], weights: &[f32]) -> Result<DualQuat, RotationError> {
    if motions.len() != weights.len() {
        return Err(RotationError::LengthMismatch {
            expected: motions.len(),
            got: weights.len(),
        });
    }
    let Some(first) = motions.first() else {
        return Err(RotationError::TooFewKeys { needed: 1, got: 0 });
    };
    let sum: f32 = weights.iter().sum();
    let valid = |w: f32| w.is_finite() && w >= 0.0;
    if !weights.iter().all(|&w| valid(w)) || !valid(sum) || sum == 0.0 {
        return Err(RotationError::BadWeights { sum });
    }
    let mut acc = DualQuat {
        real: ZERO_QUAT,
        dual: ZERO_QUAT,
    };
    for (q, &w) in motions.iter().zip(weights) {
        let sign = if first.real.dot(q.real) < 0.0 { -w } else { w };
        acc = acc + *q * sign;
    }
    if acc.real.length() < 1e-6 {
        return Err(RotationError::ZeroQuat);
    }
    Ok(acc.normalized())
}
