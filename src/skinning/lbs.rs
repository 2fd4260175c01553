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

pub(super) fn check_skin(
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
    let kernel = LbsKernel::best();
    skin_lbs_with(
        kernel,
        palette,
        skin,
        positions,
        normals,
        out_positions,
        out_normals,
    )
}

/// Which implementation [`skin_lbs`] runs: the portable one (SSE2 on x86-64, simd128 in wasm,
/// through glam), or on an x86-64 CPU with AVX2 and FMA (detected at run time, as skinning
/// libraries dispatch) the same formula with fused multiply-adds and 256-bit loads of two matrix
/// columns at once. The two agree to rounding (a fused multiply-add rounds once). [`super::skin_dqs`]
/// (super::skin_dqs) picks its kernel the same way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LbsKernel {
    Portable,
    X86Fma,
}

impl LbsKernel {
    /// The fastest kernel this CPU runs.
    pub fn best() -> Self {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
        {
            return LbsKernel::X86Fma;
        }
        LbsKernel::Portable
    }
}

/// [`skin_lbs`] with a chosen kernel: the benchmark and the tests compare them. A kernel this CPU
/// cannot run ([`LbsKernel::X86Fma`] without AVX2 and FMA) falls back to the portable one.
///
/// # Errors
/// As [`skin_lbs`].
pub fn skin_lbs_with(
    kernel: LbsKernel,
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
    let n = skin.len();
    let (joints, weights) = (&skin.joints()[..n], &skin.weights()[..n]);
    let (positions, normals) = (&positions[..n], &normals[..n]);
    let (out_positions, out_normals) = (&mut out_positions[..n], &mut out_normals[..n]);
    #[cfg(target_arch = "x86_64")]
    if kernel == LbsKernel::X86Fma && LbsKernel::best() == LbsKernel::X86Fma {
        // SAFETY: the CPU has AVX2 and FMA (checked by `best`); every slice has `n` entries and
        // every joint index is below `palette.len()` (checked above).
        unsafe {
            x86::skin_lbs_fma(
                palette,
                joints,
                weights,
                positions,
                normals,
                out_positions,
                out_normals,
            )
        };
        return Ok(());
    }
    let _ = kernel; // only x86-64 has another kernel
    skin_lbs_portable(
        palette,
        joints,
        weights,
        positions,
        normals,
        out_positions,
        out_normals,
    );
    Ok(())
}

/// Linear blend skinning of positions only (`p' = Σ_j w_j K_j p`, as [`skin_lbs`] without the
/// normals): for meshes whose normals are recomputed or not needed (shadow passes, picking,
/// collision proxies). The portable loop on every target (the one wasm runs); the same
/// positions as `skin_lbs_with(LbsKernel::Portable, …)`, bit for bit. Allocates nothing.
///
/// # Errors
/// [`SkinningError::LengthMismatch`] unless `positions` and `out_positions` have one entry per
/// vertex, [`SkinningError::JointOutOfRange`] when a vertex names a joint past the palette.
pub fn skin_lbs_positions(
    palette: &[Affine3A],
    skin: &SkinWeights,
    positions: &[Vec3],
    out_positions: &mut [Vec3],
) -> Result<(), SkinningError> {
    let n = skin.len();
    // No normals: their lengths are checked as the vertex count.
    check_skin(
        palette.len(),
        skin,
        positions.len(),
        n,
        out_positions.len(),
        n,
    )?;
    let (joints, weights) = (&skin.joints()[..n], &skin.weights()[..n]);
    let (positions, out_positions) = (&positions[..n], &mut out_positions[..n]);
    for v in 0..n {
        let k = blend4(palette, &joints[v], &weights[v]);
        out_positions[v] = k.transform_point3(positions[v]);
    }
    Ok(())
}

/// The portable LBS loop over validated slices of one length.
#[inline(always)]
fn skin_lbs_portable(
    palette: &[Affine3A],
    joints: &[[u16; 4]],
    weights: &[[f32; 4]],
    positions: &[Vec3],
    normals: &[Vec3],
    out_positions: &mut [Vec3],
    out_normals: &mut [Vec3],
) {
    // An index loop over slices cut to one length (the callers made them equal): the compiler
    // drops the bounds checks, and measured faster than a six-way zip, most of all in wasm.
    let n = joints.len();
    let (joints, weights) = (&joints[..n], &weights[..n]);
    let (positions, normals) = (&positions[..n], &normals[..n]);
    let (out_positions, out_normals) = (&mut out_positions[..n], &mut out_normals[..n]);
    for v in 0..n {
        let (j, w, p, n) = (&joints[v], &weights[v], &positions[v], &normals[v]);
        let (op, on) = (&mut out_positions[v], &mut out_normals[v]);
        let k = blend4(palette, j, w);
        *op = k.transform_point3(*p);
        *on = k.transform_vector3(*n);
    }
}

/// The AVX2 + FMA kernel of [`skin_lbs`].
#[cfg(target_arch = "x86_64")]
mod x86 {
    use core::arch::x86_64::*;
    use glam::{Affine3A, Vec3};

    /// Per vertex: the four matrices are blended two columns per 256-bit register (columns
    /// x, y in one, z and the translation in the other: an `Affine3A` is four 16-byte columns),
    /// with one multiply and three fused multiply-adds each; then
    /// `p' = c0 px + c1 py + c2 pz + c3` and `n' = c0 nx + c1 ny + c2 nz` in 128-bit
    /// registers with the coordinates broadcast from memory. Results are stored 16 bytes at a
    /// time, which writes the next vertex's x too (rewritten at the next step); the last vertex
    /// is stored 12 bytes exactly.
    ///
    /// # Safety
    /// The CPU must have AVX2 and FMA; `joints`, `weights`, `positions`, `normals` and both
    /// outputs must have the same length, and every joint index must be below `palette.len()`.
    #[target_feature(enable = "avx2,fma")]
    pub(super) unsafe fn skin_lbs_fma(
        palette: &[Affine3A],
        joints: &[[u16; 4]],
        weights: &[[f32; 4]],
        positions: &[Vec3],
        normals: &[Vec3],
        out_positions: &mut [Vec3],
        out_normals: &mut [Vec3],
    ) {
        let n = joints.len();
        debug_assert!(
            weights.len() == n
                && positions.len() == n
                && normals.len() == n
                && out_positions.len() == n
                && out_normals.len() == n
        );
        let pal = palette.as_ptr() as *const f32;
        let (op, on) = (
            out_positions.as_mut_ptr() as *mut f32,
            out_normals.as_mut_ptr() as *mut f32,
        );
        // One vertex: the blended columns applied to its position and normal, given a way to
        // get their coordinates broadcast to four lanes.
        let skin = |v: usize, coords: &dyn Fn(*const f32) -> [__m128; 3]| {
            // The four joint indices in one load.
            let jj = (joints.as_ptr().add(v) as *const u64).read_unaligned();
            let m = |k: u32| pal.add(16 * ((jj >> (16 * k)) & 0xffff) as usize);
            let (m0, m1, m2, m3) = (m(0), m(1), m(2), m(3));
            // The four weights in one load, each broadcast by an in-lane permute.
            let w4 = _mm256_broadcast_ps(&*(weights.as_ptr().add(v) as *const __m128));
            let (w0, w1, w2, w3) = (
                _mm256_permute_ps::<0x00>(w4),
                _mm256_permute_ps::<0x55>(w4),
                _mm256_permute_ps::<0xAA>(w4),
                _mm256_permute_ps::<0xFF>(w4),
            );
            let blend = |o: usize| {
                let c = _mm256_mul_ps(w0, _mm256_loadu_ps(m0.add(o)));
                let c = _mm256_fmadd_ps(w1, _mm256_loadu_ps(m1.add(o)), c);
                let c = _mm256_fmadd_ps(w2, _mm256_loadu_ps(m2.add(o)), c);
                _mm256_fmadd_ps(w3, _mm256_loadu_ps(m3.add(o)), c)
            };
            let (c01, c23) = (blend(0), blend(8));
            let (c0, c1) = (_mm256_castps256_ps128(c01), _mm256_extractf128_ps::<1>(c01));
            let (c2, c3) = (_mm256_castps256_ps128(c23), _mm256_extractf128_ps::<1>(c23));
            let [px, py, pz] = coords(positions.as_ptr().add(v) as *const f32);
            let [nx, ny, nz] = coords(normals.as_ptr().add(v) as *const f32);
            (
                _mm_fmadd_ps(c0, px, _mm_fmadd_ps(c1, py, _mm_fmadd_ps(c2, pz, c3))),
                _mm_fmadd_ps(c0, nx, _mm_fmadd_ps(c1, ny, _mm_mul_ps(c2, nz))),
            )
        };
        // Every vertex but the last: one 16-byte load for the three coordinates (the fourth
        // float is the next vertex's x) and 16-byte stores.
        let wide = |x: *const f32| {
            let l = _mm_loadu_ps(x);
            [
                _mm_permute_ps::<0x00>(l),
                _mm_permute_ps::<0x55>(l),
                _mm_permute_ps::<0xAA>(l),
            ]
        };
        for v in 0..n.saturating_sub(1) {
            let (pv, nv) = skin(v, &wide);
            _mm_storeu_ps(op.add(3 * v), pv);
            _mm_storeu_ps(on.add(3 * v), nv);
        }
        // The last vertex: exact-size loads and stores.
        if n > 0 {
            let exact = |x: *const f32| {
                [
                    _mm_broadcast_ss(&*x),
                    _mm_broadcast_ss(&*x.add(1)),
                    _mm_broadcast_ss(&*x.add(2)),
                ]
            };
            let (pv, nv) = skin(n - 1, &exact);
            let store3 = |dst: *mut f32, x: __m128| {
                _mm_storel_epi64(dst as *mut __m128i, _mm_castps_si128(x));
                _mm_store_ss(dst.add(2), _mm_movehl_ps(x, x));
            };
            store3(op.add(3 * (n - 1)), pv);
            store3(on.add(3 * (n - 1)), nv);
        }
    }
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
