//! The error type shared by [`crate::rotation`] and [`crate::rigid`].

use crate::exercises::run::format_number;
use std::fmt;

/// What a caller can get wrong when handing data to the rotation and rigid-motion cores.
///
/// Every message is a full sentence that a lesson page can show as is, with the measured value
/// that failed the check.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RotationError {
    /// A quaternion (or the rotation part of a dual quaternion) has zero length, so it does not
    /// name any rotation.
    ZeroQuat,
    /// An input contains NaN or an infinity; `what` names the input.
    NonFinite {
        /// Which input, in words ("quaternion", "matrix", ...).
        what: &'static str,
    },
    /// An axis of rotation has zero length.
    ZeroAxis,
    /// A matrix given as a rotation is not orthonormal: `error = ‖RᵀR − I‖` (Frobenius norm).
    NotOrthonormal {
        /// The measured `‖RᵀR − I‖`.
        error: f32,
        /// The largest error accepted.
        tolerance: f32,
    },
    /// A matrix given as a rotation (or an affine key) mirrors space: its determinant is negative.
    Reflection {
        /// The measured determinant.
        determinant: f32,
    },
    /// A matrix that must be invertible (an affine key, a polar decomposition input) is singular.
    SingularMatrix {
        /// The measured determinant.
        determinant: f32,
    },
    /// The bottom row of a 4x4 matrix is not `(0, 0, 0, 1)`, so it is not an affine transform.
    NotAffine {
        /// The bottom row that was found.
        bottom_row: [f32; 4],
    },
    /// An iteration did not reach its tolerance within its iteration cap.
    NotConverged {
        /// Iterations run.
        iterations: u32,
        /// Change between the last two iterates (Frobenius norm).
        change: f32,
    },
    /// Too few keys were given to build a curve.
    TooFewKeys {
        /// Smallest number of keys accepted.
        needed: usize,
        /// Number of keys given.
        got: usize,
    },
    /// Two slices that must have the same length do not.
    LengthMismatch {
        /// Length of the first slice (the input).
        expected: usize,
        /// Length of the second slice.
        got: usize,
    },
    /// Blend weights sum to zero (or are negative), so no average can be formed.
    BadWeights {
        /// Sum of the weights.
        sum: f32,
    },
}

impl fmt::Display for RotationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            RotationError::ZeroQuat => write!(
                f,
                "the quaternion has zero length, so it does not describe any rotation"
            ),
            RotationError::NonFinite { what } => {
                write!(f, "the {what} contains NaN or an infinite value")
            }
            RotationError::ZeroAxis => write!(
                f,
                "the rotation axis has zero length; give a non-zero direction"
            ),
            RotationError::NotOrthonormal { error, tolerance } => write!(
                f,
                "the matrix is not a rotation: its columns are not orthonormal \
                 (‖RᵀR − I‖ = {error:.3e}, more than the tolerance {tolerance:.1e})"
            ),
            RotationError::Reflection { determinant } => write!(
                f,
                "the matrix mirrors space (determinant {} < 0), \
                 so it has no rotation part with a positive stretch",
                format_number(determinant)
            ),
            RotationError::SingularMatrix { determinant } => write!(
                f,
                "the matrix is singular (determinant {}, tiny for the size of its columns): it \
                 flattens space, so it cannot be split into rotation and stretch",
                format_number(determinant)
            ),
            RotationError::NotAffine { bottom_row } => write!(
                f,
                "the 4x4 matrix is not affine: its bottom row is {bottom_row:?}, \
                 expected [0, 0, 0, 1]"
            ),
            RotationError::NotConverged { iterations, change } => write!(
                f,
                "the iteration did not converge after {iterations} steps \
                 (last change {change:.3e})"
            ),
            RotationError::TooFewKeys { needed, got } => {
                write!(f, "at least {needed} keys are needed, got {got}")
            }
            RotationError::LengthMismatch { expected, got } => write!(
                f,
                "the slices have different lengths: {expected} inputs but {got} outputs"
            ),
            RotationError::BadWeights { sum } => write!(
                f,
                "the blend weights must be non-negative with a positive sum (sum is {sum})"
            ),
        }
    }
}

impl std::error::Error for RotationError {}
