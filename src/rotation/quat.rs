//! Unit quaternions: conversion to and from matrices, interpolation, log and exp.

use glam::{Mat3, Quat, Vec3, Vec4};

use super::{sinc, RotationError};

/// Which of the two great-circle arcs an interpolation follows.
///
/// `q` and `−q` are the same rotation, so between two rotations there are two arcs on the unit
/// sphere of quaternions: the short one turns by the smaller angle (at most π), the long one by
/// the complementary angle `2π − θ` the other way round.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Arc {
    /// Negate the second key when `a·b < 0`: the rotation never turns by more than π.
    #[default]
    Short,
    /// Negate the second key when `a·b > 0`: the "wrong way round" path shown in the lesson.
    Long,
}

/// Validates a quaternion given as a rotation and returns it with unit length.
/// ```text
/// q / ‖q‖
/// ```
/// # Errors
/// [`RotationError::NonFinite`] for NaN or infinite components, [`RotationError::ZeroQuat`] when
/// `‖q‖ < 1e-6`.
pub fn check_quat(q: Quat) -> Result<Quat, RotationError> {
    if !q.is_finite() {
        return Err(RotationError::NonFinite { what: "quaternion" });
    }
    let length = q.length();
    if length < 1e-6 {
        return Err(RotationError::ZeroQuat);
    }
    Ok(q / length)
}

/// Rotation matrix of a unit quaternion `q = (x, y, z, w)`.
/// ```text
///     ⎡ 1 − 2(y² + z²)   2(xy − wz)       2(xz + wy)     ⎤
/// R = ⎢ 2(xy + wz)       1 − 2(x² + z²)   2(yz − wx)     ⎥
///     ⎣ 2(xz − wy)       2(yz + wx)       1 − 2(x² + y²) ⎦
/// ```
/// Comes from expanding `q (v, 0) q*` (Rodrigues' formula with half angles). `q` and `−q` give
/// the same `R`. Expects `‖q‖ = 1`; otherwise `R` is not orthonormal.
pub fn mat3_from_quat(q: Quat) -> Mat3 {
    let (x, y, z, w) = (q.x, q.y, q.z, q.w);
    // glam stores columns: each Vec3 below is one column of R.
    Mat3::from_cols(
        Vec3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y + w * z),
            2.0 * (x * z - w * y),
        ),
        Vec3::new(
            2.0 * (x * y - w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z + w * x),
        ),
        Vec3::new(
            2.0 * (x * z + w * y),
            2.0 * (y * z - w * x),
            1.0 - 2.0 * (x * x + y * y),
        ),
    )
}

/// Unit quaternion of a rotation matrix, robust for every angle (Shepperd's method).
/// ```text
/// 4w² = 1 + R₀₀ + R₁₁ + R₂₂        4x² = 1 + R₀₀ − R₁₁ − R₂₂
/// 4y² = 1 − R₀₀ + R₁₁ − R₂₂        4z² = 1 − R₀₀ − R₁₁ + R₂₂
/// 4wx = R₂₁ − R₁₂   4wy = R₀₂ − R₂₀   4wz = R₁₀ − R₀₁
/// 4xy = R₁₀ + R₀₁   4xz = R₀₂ + R₂₀   4yz = R₂₁ + R₁₂
/// ```
/// (`Rᵢⱼ` = row i, column j.) The textbook formula divides by `r = √(1 + trace)`, which vanishes
/// for angles near π; instead take the square root of the largest of the four squares (at least
/// 1/4, so the division is safe) and get the other three components from the products.
/// Returns `w ≥ 0` (rotation angle in `[0, π]`). Expects `R` orthonormal with `det R = 1`
/// (use [`super::check_rotation_mat3`] on caller data); the result is normalised anyway.
pub fn quat_from_mat3(r: Mat3) -> Quat {
    let m = |row: usize, col: usize| r.col(col)[row];
    let trace = m(0, 0) + m(1, 1) + m(2, 2);
    let q = if trace >= m(0, 0) && trace >= m(1, 1) && trace >= m(2, 2) {
        let s = 2.0 * (1.0 + trace).sqrt(); // s = 4w
        Quat::from_xyzw(
            (m(2, 1) - m(1, 2)) / s,
            (m(0, 2) - m(2, 0)) / s,
            (m(1, 0) - m(0, 1)) / s,
            0.25 * s,
        )
    } else if m(0, 0) >= m(1, 1) && m(0, 0) >= m(2, 2) {
        let s = 2.0 * (1.0 + m(0, 0) - m(1, 1) - m(2, 2)).sqrt(); // s = 4x
        Quat::from_xyzw(
            0.25 * s,
            (m(1, 0) + m(0, 1)) / s,
            (m(0, 2) + m(2, 0)) / s,
            (m(2, 1) - m(1, 2)) / s,
        )
    } else if m(1, 1) >= m(2, 2) {
        let s = 2.0 * (1.0 - m(0, 0) + m(1, 1) - m(2, 2)).sqrt(); // s = 4y
        Quat::from_xyzw(
            (m(1, 0) + m(0, 1)) / s,
            0.25 * s,
            (m(2, 1) + m(1, 2)) / s,
            (m(0, 2) - m(2, 0)) / s,
        )
    } else {
        let s = 2.0 * (1.0 - m(0, 0) - m(1, 1) + m(2, 2)).sqrt(); // s = 4z
        Quat::from_xyzw(
            (m(0, 2) + m(2, 0)) / s,
            (m(2, 1) + m(1, 2)) / s,
            0.25 * s,
            (m(1, 0) - m(0, 1)) / s,
        )
    };
    let q = q.normalize();
    if q.w < 0.0 {
        -q
    } else {
        q
    }
}

/// Angle of the rotation that takes `a` to `b`, in `[0, π]`.
/// ```text
/// θ = 2Ω = 4 · atan2(‖a − b‖, ‖a + b‖)     after negating b when a·b < 0
/// ```
/// The half-angle formula with `atan2` stays accurate for nearly equal rotations, where
/// `2 acos(|a·b|)` loses half its digits. Expects unit quaternions.
pub fn angle_between(a: Quat, b: Quat) -> f32 {
    let b = if a.dot(b) < 0.0 { -b } else { b };
    let a = Vec4::from(a);
    let b = Vec4::from(b);
    2.0 * 2.0 * (a - b).length().atan2((a + b).length())
}

/// Normalised linear interpolation along the short arc.
/// ```text
/// nlerp(a, b; t) = ((1 − t) a + t b) / ‖(1 − t) a + t b‖     (b negated when a·b < 0)
/// ```
/// `t = 0` gives `a`, `t = 1` gives `b` (up to sign). Follows the same great-circle arc as
/// [`slerp`] but not at constant speed: fastest in the middle. Expects unit quaternions.
pub fn nlerp(a: Quat, b: Quat, t: f32) -> Quat {
    nlerp_arc(a, b, t, Arc::Short)
}

/// [`nlerp`] with a choice of arc. With [`Arc::Long`] and `b = −a` exactly the sum vanishes at
/// `t = 1/2`; the result is then `a` (nlerp has no meaningful answer there, use [`slerp_arc`]).
pub fn nlerp_arc(a: Quat, b: Quat, t: f32, arc: Arc) -> Quat {
    let b = pick_arc(a, b, arc);
    let v = Vec4::from(a) * (1.0 - t) + Vec4::from(b) * t;
    let length = v.length();
    if length < 1e-12 {
        return a;
    }
    Quat::from_vec4(v / length)
}

/// Spherical linear interpolation between unit quaternions, along the short arc.
/// ```text
/// slerp(a, b; t) = sin((1−t)Ω)/sin Ω · a + sin(tΩ)/sin Ω · b,    cos Ω = a·b ≥ 0
/// ```
/// `t = 0` gives `a`, `t = 1` gives `b` (up to sign), at constant angular speed. Takes the
/// short arc (negates `b` when `a·b < 0`). The weights are computed as
/// `t · sinc(tΩ) / sinc(Ω)` so there is no separate branch for nearly equal keys, and `Ω`
/// comes from `atan2`, so keys differing by a tiny angle or by nearly π stay accurate.
/// Expects unit quaternions. Lesson: `lessons/03-rotations`.
///
/// This is the reference for the "slerp with the short arc" exercise.
pub fn slerp(a: Quat, b: Quat, t: f32) -> Quat {
    slerp_arc(a, b, t, Arc::Short)
}

/// [`slerp`] with a choice of arc. On the long arc the keys can be exactly opposite
/// (`b = −a`, a full turn): every great circle through `a` then joins them, and this one is
/// chosen: `a · cos(πt) + (a·i) · sin(πt)`, a full turn about `a`'s image of the x axis.
pub fn slerp_arc(a: Quat, b: Quat, t: f32, arc: Arc) -> Quat {
    let b = pick_arc(a, b, arc);
    let va = Vec4::from(a);
    let vb = Vec4::from(b);
    let sum = (va + vb).length();
    let diff = (va - vb).length();
    // Ω is the angle between a and b on the 4D unit sphere (half the rotation angle).
    let omega = 2.0 * diff.atan2(sum);
    if sum < 1e-6 {
        let perpendicular = Vec4::from(a * Quat::from_xyzw(1.0, 0.0, 0.0, 0.0));
        let angle = core::f32::consts::PI * t;
        return Quat::from_vec4(va * angle.cos() + perpendicular * angle.sin()).normalize();
    }
    let s = sinc(omega);
    let wa = (1.0 - t) * sinc((1.0 - t) * omega) / s;
    let wb = t * sinc(t * omega) / s;
    Quat::from_vec4(va * wa + vb * wb).normalize()
}

fn pick_arc(a: Quat, b: Quat, arc: Arc) -> Quat {
    let d = a.dot(b);
    match arc {
        Arc::Short if d < 0.0 => -b,
        Arc::Long if d > 0.0 => -b,
        _ => b,
    }
}

/// Logarithm of a unit quaternion: a pure quaternion, returned as its vector part.
/// ```text
/// q = (n sin φ, cos φ)   ⟹   log q = φ n,     φ = atan2(‖s‖, w) ∈ [0, π],  s = (x, y, z)
/// ```
/// `φ` is half the rotation angle, so the rotation vector is `2 log q` (for `w ≥ 0`). `q` and `−q`
/// have different logs (`φ` and `π − φ` about opposite axes); no sign is chosen here. Near the
/// direction `n` is `s / ‖s‖` and the length `φ` comes from `atan2`, so a `q` whose norm is off
/// by rounding still gives the log of the unit quaternion next to it (using `s / sinc φ` instead
/// would scale that error by `1 / sin φ` near `φ = π`). Expects `‖q‖ ≈ 1`.
pub fn quat_log(q: Quat) -> Vec3 {
    let s = Vec3::new(q.x, q.y, q.z);
    let sin_phi = s.length();
    let phi = sin_phi.atan2(q.w);
    if sin_phi > 0.0 {
        // φ / ‖s‖ → 1 / w near the identity: no series needed.
        s * (phi / sin_phi)
    } else {
        // q = ±1: the identity rotation (log 1 = 0; log −1 is any π n, pick the x axis).
        Vec3::new(phi, 0.0, 0.0)
    }
}

/// Exponential of a pure quaternion `(v, 0)`: the inverse of [`quat_log`].
/// ```text
/// exp(v) = (sin‖v‖ · v/‖v‖, cos‖v‖) = (sinc‖v‖ · v, cos‖v‖)
/// ```
/// Always a unit quaternion; `exp(0) = 1`. Rotates by `2‖v‖` about `v`.
pub fn quat_exp(v: Vec3) -> Quat {
    let phi = v.length();
    let s = v * sinc(phi);
    Quat::from_xyzw(s.x, s.y, s.z, phi.cos())
}

/// Power of a unit quaternion: turn `t` times as far about the same axis.
/// ```text
/// qᵗ = exp(t · log q)
/// ```
/// `q⁰ = 1`, `q¹ = q`. Takes `q` as given (call with `w ≥ 0` for the short way round).
pub fn quat_pow(q: Quat, t: f32) -> Quat {
    quat_exp(quat_log(q) * t)
}
