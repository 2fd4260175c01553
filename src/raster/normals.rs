//! Normals: per face, averaged per vertex, and how they transform.
//!
//! A face's normal is the cross product of two of its edges. A smooth surface approximated by
//! triangles wants one normal per *vertex*: the average of the normals of the triangles around
//! it. As in the course, each neighbouring triangle counts once, whatever its size: sum their
//! *unit* normals, then normalise the sum.
//! ```text
//! n̂_face = normalize((b − a) × (c − a))
//! n_v    = normalize( Σ n̂_face  over the triangles that use v )
//! ```
//! (Summing the un-normalised cross products instead would weight each triangle by its area, a
//! common variant.)
//! Under a model matrix `M` a tangent `t` becomes `M t`; a normal must stay perpendicular to every
//! tangent, `n'·(M t) = 0`, which holds for `n' = (M⁻¹)ᵀ n`: the **normal matrix**. For rotations
//! and uniform scales it is `M` itself (up to length); under a non-uniform scale it is not.

use super::storage::check_indices;
use super::RasterError;
use glam::{Mat3, Mat4, Vec3};

/// The un-normalised normal of the counter-clockwise triangle `a, b, c`: `(b − a) × (c − a)`, of
/// length twice its area.
pub fn face_normal(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    (b - a).cross(c - a)
}

/// Averaged vertex normals of an indexed mesh (the sum of the unit normals of the triangles
/// around each vertex, normalised), written into `out`, one per position. A vertex that no
/// triangle uses, or whose triangles cancel out, gets `Vec3::ZERO`; so does a degenerate
/// (zero-area) triangle's contribution.
pub fn vertex_normals(
    positions: &[Vec3],
    indices: &[u32],
    out: &mut [Vec3],
) -> Result<(), RasterError> {
    check_indices(indices, positions.len())?;
    if out.len() != positions.len() {
        return Err(RasterError::OutputLength {
            expected: positions.len(),
            got: out.len(),
        });
    }
    out.fill(Vec3::ZERO);
    for tri in indices.chunks_exact(3) {
        let [a, b, c] = [tri[0], tri[1], tri[2]].map(|i| i as usize);
        let n = face_normal(positions[a], positions[b], positions[c]).normalize_or_zero();
        out[a] += n;
        out[b] += n;
        out[c] += n;
    }
    for n in out.iter_mut() {
        *n = n.normalize_or_zero();
    }
    Ok(())
}

/// The flat-shaded version of an indexed mesh: every triangle gets its own three corners, each
/// with the triangle's unit normal (a soup with face normals). Returns positions and normals.
pub fn flat_shaded(
    positions: &[Vec3],
    indices: &[u32],
) -> Result<(Vec<Vec3>, Vec<Vec3>), RasterError> {
    check_indices(indices, positions.len())?;
    let mut p = Vec::with_capacity(indices.len());
    let mut n = Vec::with_capacity(indices.len());
    for tri in indices.chunks_exact(3) {
        let [a, b, c] = [tri[0], tri[1], tri[2]].map(|i| positions[i as usize]);
        let normal = face_normal(a, b, c).normalize_or_zero();
        p.extend([a, b, c]);
        n.extend([normal; 3]);
    }
    Ok((p, n))
}

/// The normal matrix of `model`: the inverse transpose of its upper-left 3×3. A singular model
/// (a zero scale) has none: the result is then not finite.
pub fn normal_matrix(model: Mat4) -> Mat3 {
    Mat3::from_mat4(model).inverse().transpose()
}
