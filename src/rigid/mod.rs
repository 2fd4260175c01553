//! # Rigid motions: dual quaternions and screw interpolation
//!
//! A rigid motion (rotation and translation, no scale) has six degrees of freedom. Chasles'
//! theorem says every one of them is a *screw motion*: a rotation by `θ` about some line in
//! space together with a slide by `d` along that same line. A unit dual quaternion
//! ([`DualQuat`]) stores exactly that, in eight numbers that compose by multiplication, and its
//! logarithm is the screw line scaled by the motion's size, so `exp(t · log m)` moves along the
//! screw at constant speed ([`DualQuat::sclerp`]). In Klein's projective geometric algebra the
//! same object is called a *motor* and its logarithm a *line*.
//!
//! What the lesson compares, for one frame moving between two keys:
//! - translation lerp + rotation slerp (what [`crate::rotation`] gives),
//! - dual quaternion linear blending ([`DualQuat::nlerp`], [`dual_quat_blend`]: cheap, used for
//!   skinning, not constant speed),
//! - screw linear interpolation ([`DualQuat::sclerp`], [`ScrewInterpolator`] when the same pair
//!   is sampled many times), with the screw axis drawn ([`DualQuat::screw_axis`]).
//!
//! Applying one motion to many points: convert it once to a rotation matrix and a translation,
//! then each point costs one matrix-vector product and one addition
//! ([`DualQuat::transform_points`]). Redoing the full sandwich `q p q̄` per point
//! ([`DualQuat::transform_points_sandwich`]) is the naive baseline of the benchmark.
//!
//! Conventions as in the crate root: column vectors, `a * b` applies `b` first, quaternion
//! order `(x, y, z, w)`. Errors are [`crate::rotation::RotationError`].
//!
//! Lesson: `lessons/04-rigid-motions`.

mod dual_quat;
mod screw;

pub use dual_quat::{
    dual_quat_blend, dual_quat_from_rotation_translation, dual_quat_transform_point, DualQuat,
};
pub use screw::{DualQuatLog, ScrewAxis, ScrewInterpolator};
