//! Axis-angle, rotation vectors and Rodrigues' formula.

use glam::{Mat3, Quat, Vec3};

use super::{quat_from_mat3, quat_log, sinc, RotationError};

/// A rotation by `angle_rad` about the unit vector `axis` (right-hand rule: with the thumb along
/// `axis`, the fingers curl in the positive direction).
///
/// Every rotation has this form (Euler's rotation theorem). `(n, θ)`, `(−n, −θ)` and
/// `(n, θ + 2π)` are the same rotation; [`AxisAngle::from_quat`] returns `θ ∈ [0, π]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisAngle {
    /// Unit axis of rotation.
    pub axis: Vec3,
    /// Angle in radians, counter-clockwise when looking down from the tip of `axis`.
    pub angle_rad: f32,
}

impl AxisAngle {
    /// Validated axis-angle: normalises `axis`.
    ///
    /// # Errors
    /// [`RotationError::NonFinite`] for NaN or infinite input, [`RotationError::ZeroAxis`] when
    /// `‖axis‖ < 1e-12`.
    pub fn new(axis: Vec3, angle_rad: f32) -> Result<Self, RotationError> {
        if !axis.is_finite() || !angle_rad.is_finite() {
            return Err(RotationError::NonFinite { what: "axis-angle" });
        }
        let length = axis.length();
        if length < 1e-12 {
            return Err(RotationError::ZeroAxis);
        }
        Ok(Self {
            axis: axis / length,
            angle_rad,
        })
    }

    /// Unit quaternion `(n sin(θ/2), cos(θ/2))`.
    pub fn to_quat(self) -> Quat {
        quat_from_axis_angle(self.axis, self.angle_rad)
    }

    /// Axis and angle of a unit quaternion, with `θ ∈ [0, π]`.
    /// ```text
    /// θ = 2 atan2(‖s‖, |w|),   n = sign(w) · s / ‖s‖      (s = (x, y, z))
    /// ```
    /// The identity has no axis; it returns `(x axis, 0)`.
    pub fn from_quat(q: Quat) -> Self {
        Self::from_rotation_vector(rotation_vector_from_quat(q))
    }

    /// Rotation matrix by Rodrigues' formula ([`rodrigues_mat3`]).
    pub fn to_mat3(self) -> Mat3 {
        rodrigues_mat3(self.axis, self.angle_rad)
    }

    /// Axis and angle of a rotation matrix, going through the quaternion so that angles near π
    /// stay accurate.
    pub fn from_mat3(r: Mat3) -> Self {
        Self::from_quat(quat_from_mat3(r))
    }

    /// The rotation vector `θ n`.
    pub fn to_rotation_vector(self) -> Vec3 {
        self.axis * self.angle_rad
    }

    /// Splits a rotation vector into `n = v/‖v‖`, `θ = ‖v‖`; the zero vector gives `(x axis, 0)`.
    pub fn from_rotation_vector(v: Vec3) -> Self {
        let angle_rad = v.length();
        if angle_rad == 0.0 {
            return Self {
                axis: Vec3::X,
                angle_rad: 0.0,
            };
        }
        Self {
            axis: v / angle_rad,
            angle_rad,
        }
    }
}

/// Unit quaternion of the rotation by `angle_rad` about the unit vector `axis`.
/// ```text
/// q = (n sin(θ/2), cos(θ/2))
/// ```
/// Expects `‖axis‖ = 1` (use [`AxisAngle::new`] on caller data). `θ` and `θ + 2π` give `q` and
/// `−q`, the same rotation.
///
/// This is the reference for the "quaternion from axis-angle" exercise.
pub fn quat_from_axis_angle(axis: Vec3, angle_rad: f32) -> Quat {
    let half = 0.5 * angle_rad;
    let s = axis * half.sin();
    Quat::from_xyzw(s.x, s.y, s.z, half.cos())
}

/// Rotation matrix of the rotation by `angle_rad` about the unit vector `axis` (Rodrigues).
/// ```text
/// R = I + sin θ · K + (1 − cos θ) · K²,       K = [n]ₓ = ⎡  0  −n_z  n_y ⎤
///                                                       ⎢ n_z   0  −n_x ⎥
///                                                       ⎣−n_y  n_x   0  ⎦
/// ```
/// `K v = n × v`, so `R v = v + sin θ (n × v) + (1 − cos θ) n × (n × v)`. `1 − cos θ` is computed
/// as `2 sin²(θ/2)`, which keeps its digits for small angles. Expects `‖axis‖ = 1`.
///
/// This is the reference for the "Rodrigues' matrix" exercise.
pub fn rodrigues_mat3(axis: Vec3, angle_rad: f32) -> Mat3 {
    let n = axis;
    // K as columns: K e_x = n × e_x = (0, n_z, −n_y), etc.
    let k = Mat3::from_cols(
        Vec3::new(0.0, n.z, -n.y),
        Vec3::new(-n.z, 0.0, n.x),
        Vec3::new(n.y, -n.x, 0.0),
    );
    let half_sin = (0.5 * angle_rad).sin();
    Mat3::IDENTITY + k * angle_rad.sin() + (k * k) * (2.0 * half_sin * half_sin)
}

/// Rotates `v` by `angle_rad` about the unit vector `axis` (Rodrigues' rotation formula).
/// ```text
/// v' = v cos θ + (n × v) sin θ + n (n · v)(1 − cos θ)
/// ```
/// Splits `v` into its part along `n` (unchanged) and its part in the plane ⊥ `n` (turned by θ).
pub fn rodrigues_rotate(v: Vec3, axis: Vec3, angle_rad: f32) -> Vec3 {
    let (sin, cos) = angle_rad.sin_cos();
    let half_sin = (0.5 * angle_rad).sin();
    v * cos + axis.cross(v) * sin + axis * (axis.dot(v) * 2.0 * half_sin * half_sin)
}

/// Unit quaternion of a rotation vector `v = θ n`.
/// ```text
/// q = (sin(θ/2)/θ · v, cos(θ/2)) = (½ sinc(θ/2) · v, cos(θ/2)),     θ = ‖v‖
/// ```
/// Exact for `v = 0` (the identity) and accurate for tiny `v` (series for `sinc`). A vector of
/// length near `2π` is a small rotation the other way; it maps to a quaternion near `−1`, which
/// is the same rotation as the one near `+1`.
pub fn quat_from_rotation_vector(v: Vec3) -> Quat {
    let half = 0.5 * v.length();
    let s = v * (0.5 * sinc(half));
    Quat::from_xyzw(s.x, s.y, s.z, half.cos())
}

/// Rotation vector `θ n` of a unit quaternion, with `θ ∈ [0, π]`.
/// ```text
/// v = 2 log(±q),   sign chosen so that w ≥ 0
/// ```
/// The inverse of [`quat_from_rotation_vector`] up to `2π` turns: a rotation vector of length
/// `2π − ε` comes back as length `ε` about the opposite axis. Accurate near the identity.
pub fn rotation_vector_from_quat(q: Quat) -> Vec3 {
    let q = if q.w < 0.0 { -q } else { q };
    2.0 * quat_log(q)
}

/// Rotation vector of a rotation matrix (through [`quat_from_mat3`], robust near π).
pub fn rotation_vector_from_mat3(r: Mat3) -> Vec3 {
    rotation_vector_from_quat(quat_from_mat3(r))
}
