//! # Skinning: a mesh that follows a skeleton
//!
//! Every vertex of a skinned mesh names up to four joints and a weight for each. In the bind pose
//! (the pose the mesh was modelled in) a joint's model matrix is `B_j`; in the current pose it is
//! `M_j`. The **skinning matrix** `K_j = M_j · B_j⁻¹` carries a point from the bind pose to where
//! joint `j` takes it; one palette of them is computed per frame, then every vertex mixes its
//! joints' motions.
//!
//! **Linear blend skinning (LBS)** averages the transformed points:
//! ```text
//! p' = Σ_j w_j K_j p,        n' = normalize(Σ_j w_j A_j n)       (A_j: linear part of K_j)
//! ```
//! Averaging matrices is not a rotation: at a bend the elbow's cross-section shrinks (the
//! "collapsing elbow"), and at a twist of 180° it shrinks to a point (the "candy wrapper").
//!
//! **Dual quaternion skinning (DQS)** (Kavan, Collins, Žára, O'Sullivan 2007) averages unit dual
//! quaternions instead, then normalises, which always gives a rigid motion:
//! ```text
//! q = Σ_j w_j s_j q_j,   s_j = ±1 so that r_pivot · r_j ≥ 0,   p' = (q/‖q.r‖)(p)
//! ```
//! Volume is kept at twists; at bends the joint bulges slightly instead of collapsing.
//!
//! | topic | items |
//! |---|---|
//! | per-vertex joints and weights, validation, normalisation | [`SkinWeights`], [`SkinningError`], [`MAX_INFLUENCES`], [`MAX_SKIN_VERTICES`] |
//! | the palette `K_j = M_j B_j⁻¹`, once per frame | [`skinning_palette`], [`dual_quat_palette`] |
//! | LBS, two layouts | [`skin_lbs`], [`skin_lbs_interleaved`], [`SkinVertex`], [`lbs_vertex`] |
//! | DQS | [`skin_dqs`], [`blend_dual_quats`], [`dqs_vertex`] |
//! | kernels: portable (glam: SSE2, wasm simd128) or AVX2 + FMA picked at run time on x86-64 | [`LbsKernel`], [`skin_lbs_with`] (`skin_dqs` dispatches the same way) |
//! | automatic weights | [`auto_weights`], [`segment_distance`] |
//! | test rigs and measures | [`rigs`]: the bend-and-twist cylinder, the skinned simple human; [`ring_area`], [`mesh_volume`] |
//!
//! Nothing in the per-frame functions allocates: outputs go into the caller's slices.
//! Characters from files: an importer (glTF's `JOINTS_0`/`WEIGHTS_0`, and `JOINTS_1`/`WEIGHTS_1`
//! through [`SkinWeights::from_eight`]) only has to build a [`SkinWeights`] and a
//! [`crate::skeleton::Skeleton`] whose inverse bind matrices are the file's; everything below
//! works unchanged. Lesson: `lessons/09-skinning`.

mod dqs;
mod lbs;
pub mod rigs;
mod weights;

pub use dqs::{
    blend_dual_quats, dqs_vertex, dual_quat_palette, skin_dqs, skin_dqs_with, RIGID_TOLERANCE,
};
pub use lbs::{
    lbs_vertex, skin_lbs, skin_lbs_interleaved, skin_lbs_plain_loop, skin_lbs_positions,
    skin_lbs_with, skinning_palette, LbsKernel, SkinVertex,
};
pub use rigs::{mesh_volume, ring_area};
pub use weights::{auto_weights, segment_distance, SkinWeights};

use std::fmt;

/// Joints per vertex in one set (glTF's `JOINTS_0` / `WEIGHTS_0`).
pub const MAX_INFLUENCES: usize = 4;

/// The most vertices one skinned mesh may have (about a million; the cost of every per-frame
/// function grows with it).
pub const MAX_SKIN_VERTICES: usize = 1 << 20;

/// What is wrong with skinning input. Messages name the vertex or joint, for students.
#[derive(Clone, Debug, PartialEq)]
pub enum SkinningError {
    /// Two arrays that must have one entry per vertex (or per joint) differ in length.
    LengthMismatch {
        what: &'static str,
        expected: usize,
        got: usize,
    },
    /// More vertices than [`MAX_SKIN_VERTICES`].
    TooManyVertices { got: usize },
    /// A vertex names a joint the skeleton does not have.
    JointOutOfRange {
        vertex: usize,
        joint: usize,
        joints: usize,
    },
    /// A weight is NaN or infinite.
    NonFiniteWeight { vertex: usize },
    /// A weight is below zero.
    NegativeWeight { vertex: usize, weight: f32 },
    /// All of a vertex's weights are zero: it would follow no joint.
    ZeroWeights { vertex: usize },
    /// A joint's matrix (model, inverse bind or skinning) holds NaN or infinity.
    NonFiniteMatrix { joint: usize },
    /// Dual quaternion skinning needs rigid skinning matrices; this one scales (or mirrors).
    ScaledJoint { joint: usize, scale: [f32; 3] },
    /// Automatic weights: a parameter out of its range.
    BadParameter(String),
}

impl fmt::Display for SkinningError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::LengthMismatch { what, expected, got } => {
                write!(f, "{what}: expected {expected} entries, got {got}")
            }
            Self::TooManyVertices { got } => write!(
                f,
                "{got} vertices is too many for one skinned mesh (at most {MAX_SKIN_VERTICES})"
            ),
            Self::JointOutOfRange {
                vertex,
                joint,
                joints,
            } => write!(
                f,
                "vertex {vertex} names joint {joint}, but the skeleton has {joints} joints (0 to {})",
                joints.saturating_sub(1)
            ),
            Self::NonFiniteWeight { vertex } => {
                write!(f, "vertex {vertex} has a weight that is NaN or infinite")
            }
            Self::NegativeWeight { vertex, weight } => {
                write!(f, "vertex {vertex} has a negative weight ({weight})")
            }
            Self::ZeroWeights { vertex } => write!(
                f,
                "vertex {vertex} has all weights zero: it would follow no joint"
            ),
            Self::NonFiniteMatrix { joint } => {
                write!(f, "joint {joint}'s matrix holds NaN or infinity")
            }
            Self::ScaledJoint { joint, scale } => write!(
                f,
                "joint {joint}'s skinning matrix is not rigid (axis lengths {:.3}, {:.3}, {:.3}): \
                 dual quaternion skinning takes rotations and translations only; use linear blend \
                 skinning, or remove the scale from the pose",
                scale[0], scale[1], scale[2]
            ),
            Self::BadParameter(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for SkinningError {}

pub(crate) fn check_len(
    what: &'static str,
    expected: usize,
    got: usize,
) -> Result<(), SkinningError> {
    if expected == got {
        Ok(())
    } else {
        Err(SkinningError::LengthMismatch {
            what,
            expected,
            got,
        })
    }
}
