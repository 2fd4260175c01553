//! Euler (Tait–Bryan) angles: three turns about coordinate axes.

use glam::{Mat3, Quat, Vec3};

use super::mat3_from_quat;

/// Below this value of `cos β` (β = the middle angle) a decomposition reports gimbal lock.
pub const GIMBAL_LOCK_COS_EPS: f32 = 1e-4;

/// The order and kind of three Euler (Tait–Bryan) turns, named without ambiguity.
///
/// Angles `(α, β, γ)` are always given in the order the variant names the axes.
///
/// - **Intrinsic** (upper-case, body axes, `X-Y'-Z''`): turn by α about X, then by β about the
///   *turned* Y', then by γ about the twice-turned Z''. With column vectors
///   `R = Rx(α) · Ry(β) · Rz(γ)`.
/// - **Extrinsic** (lower-case, fixed world axes, `x-y-z`): turn by α about the world x, then by
///   β about the world y, then by γ about the world z: `R = Rz(γ) · Ry(β) · Rx(α)`.
///
/// So intrinsic `X-Y'-Z''` by `(α, β, γ)` is the same rotation as extrinsic `z-y-x` by
/// `(γ, β, α)`: the same product of matrices read from the other end. The names match
/// scipy's `Rotation.from_euler("XYZ", …)` (intrinsic) and `("xyz", …)` (extrinsic).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EulerOrder {
    /// Intrinsic `X-Y'-Z''`: `R = Rx(α) Ry(β) Rz(γ)` (= extrinsic `z-y-x`).
    IntrinsicXYZ,
    /// Intrinsic `X-Z'-Y''`: `R = Rx(α) Rz(β) Ry(γ)`.
    IntrinsicXZY,
    /// Intrinsic `Y-X'-Z''`: `R = Ry(α) Rx(β) Rz(γ)`.
    IntrinsicYXZ,
    /// Intrinsic `Y-Z'-X''`: `R = Ry(α) Rz(β) Rx(γ)`.
    IntrinsicYZX,
    /// Intrinsic `Z-X'-Y''`: `R = Rz(α) Rx(β) Ry(γ)`.
    IntrinsicZXY,
    /// Intrinsic `Z-Y'-X''` (yaw, pitch, roll about Z up): `R = Rz(α) Ry(β) Rx(γ)`.
    IntrinsicZYX,
    /// Extrinsic `x-y-z`: `R = Rz(γ) Ry(β) Rx(α)` (= intrinsic `Z-Y'-X''` by `(γ, β, α)`).
    ExtrinsicXYZ,
    /// Extrinsic `x-z-y`: `R = Ry(γ) Rz(β) Rx(α)`.
    ExtrinsicXZY,
    /// Extrinsic `y-x-z`: `R = Rz(γ) Rx(β) Ry(α)`.
    ExtrinsicYXZ,
    /// Extrinsic `y-z-x`: `R = Rx(γ) Rz(β) Ry(α)`.
    ExtrinsicYZX,
    /// Extrinsic `z-x-y`: `R = Ry(γ) Rx(β) Rz(α)`.
    ExtrinsicZXY,
    /// Extrinsic `z-y-x`: `R = Rx(γ) Ry(β) Rz(α)`.
    ExtrinsicZYX,
}

impl EulerOrder {
    /// All twelve orders, for tests and lesson menus.
    pub const ALL: [EulerOrder; 12] = [
        EulerOrder::IntrinsicXYZ,
        EulerOrder::IntrinsicXZY,
        EulerOrder::IntrinsicYXZ,
        EulerOrder::IntrinsicYZX,
        EulerOrder::IntrinsicZXY,
        EulerOrder::IntrinsicZYX,
        EulerOrder::ExtrinsicXYZ,
        EulerOrder::ExtrinsicXZY,
        EulerOrder::ExtrinsicYXZ,
        EulerOrder::ExtrinsicYZX,
        EulerOrder::ExtrinsicZXY,
        EulerOrder::ExtrinsicZYX,
    ];

    /// The axes (0 = x, 1 = y, 2 = z) in the order the name lists them.
    pub fn axes(self) -> [usize; 3] {
        use EulerOrder::*;
        match self {
            IntrinsicXYZ | ExtrinsicXYZ => [0, 1, 2],
            IntrinsicXZY | ExtrinsicXZY => [0, 2, 1],
            IntrinsicYXZ | ExtrinsicYXZ => [1, 0, 2],
            IntrinsicYZX | ExtrinsicYZX => [1, 2, 0],
            IntrinsicZXY | ExtrinsicZXY => [2, 0, 1],
            IntrinsicZYX | ExtrinsicZYX => [2, 1, 0],
        }
    }

    /// True for the body-axes (intrinsic) orders.
    pub fn is_intrinsic(self) -> bool {
        use EulerOrder::*;
        matches!(
            self,
            IntrinsicXYZ | IntrinsicXZY | IntrinsicYXZ | IntrinsicYZX | IntrinsicZXY | IntrinsicZYX
        )
    }

    /// The scipy name of the order: upper-case for intrinsic, lower-case for extrinsic.
    pub fn name(self) -> &'static str {
        use EulerOrder::*;
        match self {
            IntrinsicXYZ => "XYZ",
            IntrinsicXZY => "XZY",
            IntrinsicYXZ => "YXZ",
            IntrinsicYZX => "YZX",
            IntrinsicZXY => "ZXY",
            IntrinsicZYX => "ZYX",
            ExtrinsicXYZ => "xyz",
            ExtrinsicXZY => "xzy",
            ExtrinsicYXZ => "yxz",
            ExtrinsicYZX => "yzx",
            ExtrinsicZXY => "zxy",
            ExtrinsicZYX => "zyx",
        }
    }
}

/// Three Euler angles with their order, and whether they sit at gimbal lock.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EulerAngles {
    /// Convention the angles are read in.
    pub order: EulerOrder,
    /// `(α, β, γ)` in radians, in the order `order` names the axes. From a decomposition:
    /// `α, γ ∈ (−π, π]`, `β ∈ [−π/2, π/2]`.
    pub angles_rad: Vec3,
    /// Set by [`EulerAngles::from_mat3`] when `|cos β| <` [`GIMBAL_LOCK_COS_EPS`]: the first
    /// and last axes line up, only `α ± γ` is determined, and the angle of the factor applied
    /// first to a vector (the rightmost matrix: `γ` for intrinsic, `α` for extrinsic) is set
    /// to 0.
    pub gimbal_lock: bool,
}

fn axis_rotation(axis: usize, angle_rad: f32) -> Mat3 {
    match axis {
        0 => Mat3::from_rotation_x(angle_rad),
        1 => Mat3::from_rotation_y(angle_rad),
        _ => Mat3::from_rotation_z(angle_rad),
    }
}

fn axis_quat(axis: usize, angle_rad: f32) -> Quat {
    match axis {
        0 => Quat::from_rotation_x(angle_rad),
        1 => Quat::from_rotation_y(angle_rad),
        _ => Quat::from_rotation_z(angle_rad),
    }
}

impl EulerAngles {
    /// Angles in the given order, not at gimbal lock.
    pub fn new(order: EulerOrder, angles_rad: Vec3) -> Self {
        Self {
            order,
            angles_rad,
            gimbal_lock: false,
        }
    }

    /// The three factors `(axis, angle)` of the matrix product, left to right.
    fn factors(self) -> [(usize, f32); 3] {
        let [i, j, k] = self.order.axes();
        let [a, b, c] = self.angles_rad.to_array();
        if self.order.is_intrinsic() {
            [(i, a), (j, b), (k, c)]
        } else {
            [(k, c), (j, b), (i, a)]
        }
    }

    /// Rotation matrix: the product of the three axis rotations.
    /// ```text
    /// intrinsic I-J'-K'':  R = R_I(α) R_J(β) R_K(γ)
    /// extrinsic i-j-k:     R = R_k(γ) R_j(β) R_i(α)
    /// ```
    pub fn to_mat3(self) -> Mat3 {
        let [f0, f1, f2] = self.factors();
        axis_rotation(f0.0, f0.1) * axis_rotation(f1.0, f1.1) * axis_rotation(f2.0, f2.1)
    }

    /// Unit quaternion: the product of the three axis quaternions, in the same order as
    /// [`EulerAngles::to_mat3`].
    pub fn to_quat(self) -> Quat {
        let [f0, f1, f2] = self.factors();
        axis_quat(f0.0, f0.1) * axis_quat(f1.0, f1.1) * axis_quat(f2.0, f2.1)
    }

    /// Euler angles of a unit quaternion (through its matrix).
    pub fn from_quat(q: Quat, order: EulerOrder) -> Self {
        Self::from_mat3(mat3_from_quat(q), order)
    }

    /// Euler angles of a rotation matrix, with gimbal-lock detection.
    /// ```text
    /// intrinsic I-J'-K'' (I, J, K a cyclic order, sign σ = +1; otherwise σ = −1):
    ///   sin β = σ R_IK
    ///   α = atan2(−σ R_JK, R_KK)        γ = atan2(−σ R_IJ, R_II)
    /// gimbal lock (cos β ≈ 0):  γ = 0,  α = atan2(σ R_KJ, R_JJ)
    /// ```
    /// (`R_IK` = row I, column K.) An extrinsic order `i-j-k` is decomposed as the intrinsic
    /// `K-J'-I''` and its angles reversed. Returns `α, γ ∈ (−π, π]`, `β ∈ [−π/2, π/2]`.
    /// Expects a rotation matrix (see [`super::check_rotation_mat3`]).
    pub fn from_mat3(r: Mat3, order: EulerOrder) -> Self {
        let m = |row: usize, col: usize| r.col(col)[row];
        let [oi, oj, ok] = order.axes();
        // The matrix product R = R_I R_J R_K of the intrinsic chain (reversed for extrinsic).
        let (i, j, k) = if order.is_intrinsic() {
            (oi, oj, ok)
        } else {
            (ok, oj, oi)
        };
        let sigma = if (j + 3 - i) % 3 == 1 { 1.0 } else { -1.0 };
        let sin_beta = (sigma * m(i, k)).clamp(-1.0, 1.0);
        let cos_beta = m(i, i).hypot(m(i, j));
        let beta = sin_beta.atan2(cos_beta);
        let gimbal_lock = cos_beta < GIMBAL_LOCK_COS_EPS;
        let (first, last) = if gimbal_lock {
            ((sigma * m(k, j)).atan2(m(j, j)), 0.0)
        } else {
            (
                (-sigma * m(j, k)).atan2(m(k, k)),
                (-sigma * m(i, j)).atan2(m(i, i)),
            )
        };
        let angles_rad = if order.is_intrinsic() {
            Vec3::new(first, beta, last)
        } else {
            Vec3::new(last, beta, first)
        };
        Self {
            order,
            angles_rad,
            gimbal_lock,
        }
    }
}

/// Element-wise interpolation of Euler angles: the naive method shown in the lesson.
/// ```text
/// (α, β, γ)(t) = (1 − t)(α₀, β₀, γ₀) + t (α₁, β₁, γ₁)
/// ```
/// Every sample is a rotation (unlike [`super::mat3_lerp`]), but the path depends on the order
/// and the angle wrap-around, and its angular speed is not constant.
pub fn euler_lerp(a: EulerAngles, b: EulerAngles, t: f32) -> EulerAngles {
    debug_assert_eq!(
        a.order, b.order,
        "euler_lerp: both keys need the same order"
    );
    EulerAngles::new(a.order, a.angles_rad.lerp(b.angles_rad, t))
}
