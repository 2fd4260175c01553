//! The skinning palette and linear blend skinning.

use super::{check_len, SkinWeights, SkinningError};
use glam::{Affine3A, Mat4, Vec3, Vec3A};

/// The skinning matrices of one frame, one per joint:
/// ```text
/// K_j = M_j · B_j⁻¹        M_j: model matrix now,  B_j⁻¹: inverse bind matrix
/// ```
/// `K_j` takes a bind-pose point to where joint `j` carries it; in the bind pose every `K_j` is the
/// identity. Computed once per frame, shared by every vertex. Writes `out`; allocates nothing.
///
/// # Errors
/// [`SkinningError::LengthMismatch`] unless the three slices have one entry per joint,
/// [`SkinningError::NonFiniteMatrix`] for a matrix with NaN or infinity.
pub fn skinning_palette(
    model: &[Affine3A],
    inverse_bind: &[Affine3A],
    out: &mut [Affine3A],
) -> Result<(), SkinningError> {
    check_len("inverse bind matrices", model.len(), inverse_bind.len())?;
    check_len("palette", model.len(), out.len())?;
    for (j, ((m, b), k)) in model
        .iter()
        .zip(inverse_bind)
        .zip(out.iter_mut())
        .enumerate()
    {
        *k = *m * *b;
        if !k.is_finite() {
            return Err(SkinningError::NonFiniteMatrix { joint: j });
        }
    }
    Ok(())
}

fn check_skin(
    palette_len: usize,
    skin: &SkinWeights,
    positions: usize,
    normals: usize,
    out_positions: usize,
    out_normals: usize,
) -> Result<(), SkinningError> {
    let n = skin.len();
    check_len("positions", n, positions)?;
    check_len("normals", n, normals)?;
    check_len("output positions", n, out_positions)?;
    check_len("output normals", n, out_normals)?;
    // O(1) per frame: the scan that names the vertex runs only when something is wrong.
    if skin.joint_bound() > palette_len {
        if let Some((vertex, j)) = skin.joints().iter().enumerate().find_map(|(v, j)| {
            j.iter()
                .find(|&&j| j as usize >= palette_len)
                .map(|&j| (v, j))
        }) {
            return Err(SkinningError::JointOutOfRange {
                vertex,
                joint: j as usize,
                joints: palette_len,
            });
        }
    }
    Ok(())
}

/// Linear blend skinning of positions and normals, one output per vertex.
/// ```text
/// K  = Σ_j w_j K_j                  (the four skinning matrices, blended once per vertex)
/// p' = K p,      n' = A n           (A: linear part of K; not renormalised, shaders do that)
/// ```
/// Blending the matrices first costs 4 × 12 multiply-adds, then one matrix applies to the
/// position and the normal; transforming the point by each matrix and blending the results would
/// cost 4 × 21. For rigid or uniformly scaled joints the linear part turns normals correctly; a
/// non-uniform scale would need the inverse transpose (not handled). Allocates nothing.
///
/// # Errors
/// [`SkinningError::LengthMismatch`] unless every slice has one entry per vertex,
/// [`SkinningError::JointOutOfRange`] when a vertex names a joint past the palette.
pub fn skin_lbs(
    palette: &[Affine3A],
    skin: &SkinWeights,
    positions: &[Vec3],
    normals: &[Vec3],
    out_positions: &mut [Vec3],
    out_normals: &mut [Vec3],
) -> Result<(), SkinningError> {
    check_skin(
        palette.len(),
        skin,
        positions.len(),
        normals.len(),
        out_positions.len(),
        out_normals.len(),
    )?;
    // An index loop over slices cut to one length (the checks above made them equal): the
    // compiler drops the bounds checks, and measured faster than a six-way zip, most of all in wasm.
    let n = skin.len();
    let (joints, weights) = (&skin.joints()[..n], &skin.weights()[..n]);
    let (positions, normals) = (&positions[..n], &normals[..n]);
    let (out_positions, out_normals) = (&mut out_positions[..n], &mut out_normals[..n]);
    for v in 0..n {
        let (j, w, p, n) = (&joints[v], &weights[v], &positions[v], &normals[v]);
        let (op, on) = (&mut out_positions[v], &mut out_normals[v]);
        let k = blend4(palette, j, w);
        *op = k.transform_point3(*p);
        *on = k.transform_vector3(*n);
    }
    Ok(())
}

#[inline(always)]
fn blend4(palette: &[Affine3A], j: &[u16; 4], w: &[f32; 4]) -> Affine3A {
    let k0 = &palette[j[0] as usize];
    let k1 = &palette[j[1] as usize];
    let k2 = &palette[j[2] as usize];
    let k3 = &palette[j[3] as usize];
    let (w0, w1, w2, w3) = (
        Vec3A::splat(w[0]),
        Vec3A::splat(w[1]),
        Vec3A::splat(w[2]),
        Vec3A::splat(w[3]),
    );
    let col = |a: Vec3A, b: Vec3A, c: Vec3A, d: Vec3A| a * w0 + b * w1 + c * w2 + d * w3;
    Affine3A {
        matrix3: glam::Mat3A::from_cols(
            col(
                k0.matrix3.x_axis,
                k1.matrix3.x_axis,
                k2.matrix3.x_axis,
                k3.matrix3.x_axis,
            ),
            col(
                k0.matrix3.y_axis,
                k1.matrix3.y_axis,
                k2.matrix3.y_axis,
                k3.matrix3.y_axis,
            ),
            col(
                k0.matrix3.z_axis,
                k1.matrix3.z_axis,
                k2.matrix3.z_axis,
                k3.matrix3.z_axis,
            ),
        ),
        translation: col(
            k0.translation,
            k1.translation,
            k2.translation,
            k3.translation,
        ),
    }
}

/// One vertex with everything skinning reads, interleaved (48 bytes): the other memory layout,
/// measured against [`skin_lbs`]'s separate arrays in `benches/skinning.rs`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SkinVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub joints: [u16; 4],
    pub weights: [f32; 4],
}

impl SkinVertex {
    /// Interleaves validated data: vertex `v` of `skin` with its position and normal.
    pub fn interleave(
        skin: &SkinWeights,
        positions: &[Vec3],
        normals: &[Vec3],
    ) -> Result<Vec<SkinVertex>, SkinningError> {
        check_len("positions", skin.len(), positions.len())?;
        check_len("normals", skin.len(), normals.len())?;
        Ok((0..skin.len())
            .map(|v| SkinVertex {
                position: positions[v].to_array(),
                normal: normals[v].to_array(),
                joints: skin.joints()[v],
                weights: skin.weights()[v],
            })
            .collect())
    }
}

/// [`skin_lbs`] on interleaved vertices (made by [`SkinVertex::interleave`], so already
/// validated against a skeleton). Same formula, same output.
///
/// # Errors
/// As [`skin_lbs`].
pub fn skin_lbs_interleaved(
    palette: &[Affine3A],
    vertices: &[SkinVertex],
    out_positions: &mut [Vec3],
    out_normals: &mut [Vec3],
) -> Result<(), SkinningError> {
    check_len("output positions", vertices.len(), out_positions.len())?;
    check_len("output normals", vertices.len(), out_normals.len())?;
    if let Some((vertex, j)) = vertices.iter().enumerate().find_map(|(v, x)| {
        x.joints
            .iter()
            .find(|&&j| j as usize >= palette.len())
            .map(|&j| (v, j))
    }) {
        return Err(SkinningError::JointOutOfRange {
            vertex,
            joint: j as usize,
            joints: palette.len(),
        });
    }
    for (x, (op, on)) in vertices
        .iter()
        .zip(out_positions.iter_mut().zip(out_normals.iter_mut()))
    {
        let k = blend4(palette, &x.joints, &x.weights);
        *op = k.transform_point3(Vec3::from_array(x.position));
        *on = k.transform_vector3(Vec3::from_array(x.normal));
    }
    Ok(())
}

/// LBS of one vertex, the plain way: transform the point by each skinning matrix and average.
/// ```text
/// p' = Σ_j w_j (K_j p)
/// ```
/// `matrices[k]` is the skinning matrix `K_j = M_j B_j⁻¹` of the vertex's `k`-th joint and
/// `weights[k]` its weight (extra entries of the longer slice are ignored). The reference for
/// exercise 9.1 and the scalar baseline of the benchmark.
pub fn lbs_vertex(matrices: &[Mat4], weights: &[f32], position: Vec3) -> Vec3 {
    matrices
        .iter()
        .zip(weights)
        .map(|(k, &w)| w * k.transform_point3(position))
        .sum()
}

/// The benchmarks' baseline: LBS written as a plain scalar loop over flat `f32` arrays, the way
/// one would write it in JavaScript (the bench page runs the same loop in JS). `palette` holds
/// 12 numbers per joint (the 3 × 4 matrix, column by column); `joints` and `weights` 4 per vertex,
/// positions and normals 3. Transforms the point by each joint's matrix and sums; no validation
/// beyond slice indexing (a bad index panics).
pub fn skin_lbs_plain_loop(
    palette: &[f32],
    joints: &[u16],
    weights: &[f32],
    positions: &[f32],
    normals: &[f32],
    out_positions: &mut [f32],
    out_normals: &mut [f32],
) {
    let n = positions.len() / 3;
    for v in 0..n {
        let (px, py, pz) = (positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
        let (nx, ny, nz) = (normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
        let (mut ox, mut oy, mut oz) = (0.0, 0.0, 0.0);
        let (mut mx, mut my, mut mz) = (0.0, 0.0, 0.0);
        for k in 0..4 {
            let w = weights[4 * v + k];
            let m = &palette[12 * joints[4 * v + k] as usize..][..12];
            ox += w * (m[0] * px + m[3] * py + m[6] * pz + m[9]);
            oy += w * (m[1] * px + m[4] * py + m[7] * pz + m[10]);
            oz += w * (m[2] * px + m[5] * py + m[8] * pz + m[11]);
            mx += w * (m[0] * nx + m[3] * ny + m[6] * nz);
            my += w * (m[1] * nx + m[4] * ny + m[7] * nz);
            mz += w * (m[2] * nx + m[5] * ny + m[8] * nz);
        }
        out_positions[3 * v] = ox;
        out_positions[3 * v + 1] = oy;
        out_positions[3 * v + 2] = oz;
        out_normals[3 * v] = mx;
        out_normals[3 * v + 1] = my;
        out_normals[3 * v + 2] = mz;
    }
}
