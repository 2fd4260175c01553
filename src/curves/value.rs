//! The value a track animates: a scalar or a glam vector.

use core::fmt::Debug;
use core::ops::{Add, Mul, Sub};

use glam::{Vec2, Vec3, Vec4};

/// A value that keyframes can hold: `f32`, [`Vec2`], [`Vec3`] or [`Vec4`].
///
/// Interpolation only needs a vector space (add, subtract, scale by an `f32`), a way to reject
/// NaN and infinities, and a length (for arc length and centripetal knots). The trait is
/// implemented for the four types above and is not meant to be implemented elsewhere.
pub trait Value:
    Copy
    + Debug
    + PartialEq
    + Default
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<f32, Output = Self>
{
    /// The zero value (additive identity).
    const ZERO: Self;

    /// `true` when every component is finite (neither NaN nor infinite).
    fn is_finite(self) -> bool;

    /// Euclidean length: `|x|` for a scalar, `√(x² + y² + …)` for a vector.
    fn length(self) -> f32;

    /// The components in a [`Vec4`], the missing ones zero: a track computes the tangents of
    /// every value type with one compiled body on `Vec4` (component by component, so the same
    /// numbers as on the type itself).
    fn to_vec4(self) -> Vec4;

    /// The value in the first components of `v`: the inverse of [`Value::to_vec4`].
    fn from_vec4(v: Vec4) -> Self;
}

impl Value for f32 {
    const ZERO: Self = 0.0;

    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }

    fn length(self) -> f32 {
        self.abs()
    }

    fn to_vec4(self) -> Vec4 {
        Vec4::new(self, 0.0, 0.0, 0.0)
    }

    fn from_vec4(v: Vec4) -> Self {
        v.x
    }
}

impl Value for Vec2 {
    const ZERO: Self = Vec2::ZERO;

    fn is_finite(self) -> bool {
        Vec2::is_finite(self)
    }

    fn length(self) -> f32 {
        Vec2::length(self)
    }

    fn to_vec4(self) -> Vec4 {
        self.extend(0.0).extend(0.0)
    }

    fn from_vec4(v: Vec4) -> Self {
        v.truncate().truncate()
    }
}

impl Value for Vec3 {
    const ZERO: Self = Vec3::ZERO;

    fn is_finite(self) -> bool {
        Vec3::is_finite(self)
    }

    fn length(self) -> f32 {
        Vec3::length(self)
    }

    fn to_vec4(self) -> Vec4 {
        self.extend(0.0)
    }

    fn from_vec4(v: Vec4) -> Self {
        v.truncate()
    }
}

impl Value for Vec4 {
    const ZERO: Self = Vec4::ZERO;

    fn is_finite(self) -> bool {
        Vec4::is_finite(self)
    }

    fn length(self) -> f32 {
        Vec4::length(self)
    }

    fn to_vec4(self) -> Vec4 {
        self
    }

    fn from_vec4(v: Vec4) -> Self {
        v
    }
}
