//! Dual quaternion skinning (Kavan, Collins, Žára and O'Sullivan, "Skinning with dual
//! quaternions", I3D 2007).

use super::{check_len, SkinWeights, SkinningError};
use crate::rigid::DualQuat;
use glam::{Affine3A, Quat, Vec3, Vec3A, Vec4};

/// How far from 1 a skinning matrix's axis lengths (and determinant) may be and still count as
/// rigid.
pub const RIGID_TOLERANCE: f32 = 1e-3;

/// The dual quaternion of each skinning matrix `K_j` (from [`super::skinning_palette`]).
///
/// Dual quaternions hold rotations and translations only, so a scaled joint is rejected, not
/// silently squashed into a rotation. (Kavan et al. handle scale by applying it first, in bind
/// space, and blending the scale matrices linearly; this course leaves scaled rigs to LBS.)
///
/// # Errors
/// [`SkinningError::LengthMismatch`], [`SkinningError::NonFiniteMatrix`],
/// [`SkinningError::ScaledJoint`] when an axis length or the determinant differs from 1 by more
/// than [`RIGID_TOLERANCE`].
pub fn dual_quat_palette(palette: &[Affine3A], out: &mut [DualQuat]) -> Result<(), SkinningError> {
    check_len("dual quaternion palette", palette.len(), out.len())?;
    for (joint, (k, q)) in palette.iter().zip(out.iter_mut()).enumerate() {
        if !k.is_finite() {
            return Err(SkinningError::NonFiniteMatrix { joint });
        }
        let m = k.matrix3;
        let scale = [m.x_axis.length(), m.y_axis.length(), m.z_axis.length()];
        let det = m.determinant();
        if scale.iter().any(|s| (s - 1.0).abs() > RIGID_TOLERANCE)
            || (det - 1.0).abs() > 3.0 * RIGID_TOLERANCE
        {
            return Err(SkinningError::ScaledJoint { joint, scale });
        }
        let r = Quat::from_mat3a(&m).normalize();
        *q = DualQuat::from_rotation_translation(r, Vec3::from(k.translation));
    }
    Ok(())
}

/// Blends unit dual quaternions with the antipodality fix, then normalises.
/// ```text
/// sᵢ = +1 if r₀ · rᵢ ≥ 0, else −1        (q and −q are the same motion: take the one near q₀)
/// b  = Σᵢ wᵢ sᵢ qᵢ,        q = b / ‖b.r‖   (and the dual part made orthogonal to the real one)
/// ```
/// The first entry is the pivot. Without the sign fix, two joints whose quaternions landed on
/// opposite hemispheres cancel and the vertex flies off through the long way round. Returns
/// [`DualQuat::IDENTITY`] when the blend cancels out (`‖b.r‖ < 1e-6`) or the slices are empty.
/// The reference for exercise 9.2.
pub fn blend_dual_quats(dual_quats: &[DualQuat], weights: &[f32]) -> DualQuat {
    let Some(pivot) = dual_quats.first() else {
        return DualQuat::IDENTITY;
    };
    let mut real = Vec4::ZERO;
    let mut dual = Vec4::ZERO;
    for (q, &w) in dual_quats.iter().zip(weights) {
        let s = if pivot.real.dot(q.real) < 0.0 { -w } else { w };
        real += Vec4::from(q.real) * s;
        dual += Vec4::from(q.dual) * s;
    }
    if real.length() < 1e-6 {
        return DualQuat::IDENTITY;
    }
    DualQuat {
        real: Quat::from_vec4(real),
        dual: Quat::from_vec4(dual),
    }
    .normalized()
}

/// DQS of one vertex: [`blend_dual_quats`], then apply the rigid motion to the point.
pub fn dqs_vertex(dual_quats: &[DualQuat], weights: &[f32], position: Vec3) -> Vec3 {
    blend_dual_quats(dual_quats, weights).transform_point(position)
}

/// Dual quaternion skinning of positions and normals.
/// ```text
/// b  = Σ_j w_j s_j q_j   (s_j: sign that aligns q_j with the vertex's first joint, the pivot)
/// r  = b.r / ‖b.r‖,  d = b.d / ‖b.r‖
/// p' = R(r) p + t,   t = 2 (r_w d⃗ − d_w r⃗ + r⃗ × d⃗)   (the vector part of 2 d r*)
/// n' = R(r) n,       R(r) v = v + 2 r⃗ × (r⃗ × v + r_w v)
/// ```
/// Computed without a square root: with the unnormalised `b.r`, both `R` and `t` take a factor
/// `1 / ‖b.r‖²` (the form Kavan et al. use in their shader). The dual part's component along `r` is dropped by
/// the formula for `t`, so no explicit
/// orthogonalisation is needed. `palette` comes from [`dual_quat_palette`]. Allocates nothing.
///
/// # Errors
/// As [`super::skin_lbs`].
pub fn skin_dqs(
    palette: &[DualQuat],
    skin: &SkinWeights,
    positions: &[Vec3],
    normals: &[Vec3],
    out_positions: &mut [Vec3],
    out_normals: &mut [Vec3],
) -> Result<(), SkinningError> {
    skin_dqs_with(
        super::LbsKernel::best(),
        palette,
        skin,
        positions,
        normals,
        out_positions,
        out_normals,
    )
}

/// [`skin_dqs`] with a chosen kernel, as [`super::skin_lbs_with`]: `Portable` is the loop wasm
/// runs (glam's SSE2 natively), so the browser's path can be timed and tested natively; a kernel
/// this CPU cannot run falls back to the portable one.
///
/// # Errors
/// As [`skin_dqs`].
pub fn skin_dqs_with(
    kernel: super::LbsKernel,
    palette: &[DualQuat],
    skin: &SkinWeights,
    positions: &[Vec3],
    normals: &[Vec3],
    out_positions: &mut [Vec3],
    out_normals: &mut [Vec3],
) -> Result<(), SkinningError> {
    super::lbs::check_skin(
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
    #[cfg(target_arch = "x86_64")]
    if kernel == super::LbsKernel::X86Fma && super::LbsKernel::best() == super::LbsKernel::X86Fma {
        // SAFETY: the CPU has AVX2 (checked by `best`).
        unsafe {
            dqs_loop_avx2(
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
    dqs_loop(
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

/// [`skin_dqs`] on an x86-64 CPU with AVX2 and FMA: eight vertices at a time
/// ([`x86::dqs_8`]), the last ones (at least one) by [`dqs_loop`].
///
/// # Safety
/// The CPU must have AVX2 and FMA; slices of one length, joints checked against the palette.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn dqs_loop_avx2(
    palette: &[DualQuat],
    joints: &[[u16; 4]],
    weights: &[[f32; 4]],
    positions: &[Vec3],
    normals: &[Vec3],
    out_positions: &mut [Vec3],
    out_normals: &mut [Vec3],
) {
    let n = joints.len();
    let mut v = 0;
    // `v + 8 < n`: the block's 16-byte loads and stores of vertex v + 7 reach into vertex v + 8.
    while v + 8 < n {
        x86::dqs_8(
            palette,
            &joints[v..v + 8],
            &weights[v..v + 8],
            positions.as_ptr().add(v) as *const f32,
            normals.as_ptr().add(v) as *const f32,
            out_positions.as_mut_ptr().add(v) as *mut f32,
            out_normals.as_mut_ptr().add(v) as *mut f32,
        );
        v += 8;
    }
    dqs_loop(
        palette,
        &joints[v..],
        &weights[v..],
        &positions[v..],
        &normals[v..],
        &mut out_positions[v..],
        &mut out_normals[v..],
    )
}

/// The AVX2 + FMA kernel of [`skin_dqs`].
#[cfg(target_arch = "x86_64")]
mod x86 {
    use crate::rigid::DualQuat;
    use core::arch::x86_64::*;

    /// Each 128-bit half of `(a, b, c, d)` transposed as a 4 × 4 matrix: output `c` holds
    /// component `c` of a, b, c, d in the low half, and the same of their high halves.
    #[inline(always)]
    unsafe fn transpose4(a: __m256, b: __m256, c: __m256, d: __m256) -> [__m256; 4] {
        let (t0, t1) = (_mm256_unpacklo_ps(a, b), _mm256_unpackhi_ps(a, b));
        let (t2, t3) = (_mm256_unpacklo_ps(c, d), _mm256_unpackhi_ps(c, d));
        [
            _mm256_shuffle_ps::<0x44>(t0, t2),
            _mm256_shuffle_ps::<0xEE>(t0, t2),
            _mm256_shuffle_ps::<0x44>(t1, t3),
            _mm256_shuffle_ps::<0xEE>(t1, t3),
        ]
    }

    /// Four floats at `lo` in the low half, four at `hi` in the high half.
    #[inline(always)]
    unsafe fn pair(lo: *const f32, hi: *const f32) -> __m256 {
        _mm256_loadu2_m128(hi, lo)
    }

    /// Eight rows of four floats, `row(i)` for vertex i, as four vectors of eight lanes (lane
    /// i: vertex i).
    #[inline(always)]
    unsafe fn lanes4(row: impl Fn(usize) -> *const f32) -> [__m256; 4] {
        transpose4(
            pair(row(0), row(4)),
            pair(row(1), row(5)),
            pair(row(2), row(6)),
            pair(row(3), row(7)),
        )
    }

    /// Writes lane i of `(x, y, z)` to the three floats at `out + 3i`, for i = 0..8, with
    /// 16-byte stores in increasing order (each writes the next vertex's x, rewritten next).
    #[inline(always)]
    unsafe fn store_lanes(out: *mut f32, x: __m256, y: __m256, z: __m256) {
        let r = transpose4(x, y, z, _mm256_setzero_ps());
        for (i, row) in r.iter().enumerate() {
            _mm_storeu_ps(out.add(3 * i), _mm256_castps256_ps128(*row));
        }
        for (i, row) in r.iter().enumerate() {
            _mm_storeu_ps(out.add(3 * (i + 4)), _mm256_extractf128_ps::<1>(*row));
        }
    }

    /// Eight vertices of `skin_dqs`, one per lane: the four-lane path's formulas with fused
    /// multiply-adds. Each joint slot's eight dual quaternions (eight floats each) are loaded
    /// and transposed so that each register holds one component of all eight.
    ///
    /// # Safety
    /// AVX2 and FMA; `joints` and `weights` have 8 entries whose joints are in the palette;
    /// `positions` and `normals` can be read and `out_*` written for 25 floats (the 8 vertices'
    /// 24 and the next vertex's x).
    #[target_feature(enable = "avx2,fma")]
    pub(super) unsafe fn dqs_8(
        palette: &[DualQuat],
        joints: &[[u16; 4]],
        weights: &[[f32; 4]],
        positions: *const f32,
        normals: *const f32,
        out_positions: *mut f32,
        out_normals: *mut f32,
    ) {
        let pal = palette.as_ptr() as *const f32;
        let slot = |k: usize| -> ([__m256; 4], [__m256; 4]) {
            let q = |i: usize| _mm256_loadu_ps(pal.add(8 * joints[i][k] as usize));
            let a = transpose4(q(0), q(1), q(2), q(3));
            let b = transpose4(q(4), q(5), q(6), q(7));
            (
                std::array::from_fn(|c| _mm256_permute2f128_ps::<0x20>(a[c], b[c])),
                std::array::from_fn(|c| _mm256_permute2f128_ps::<0x31>(a[c], b[c])),
            )
        };
        let w = lanes4(|i| weights[i].as_ptr());
        let fma = |a: __m256, b: __m256, c: __m256| _mm256_fmadd_ps(a, b, c);
        let mul = |a: __m256, b: __m256| _mm256_mul_ps(a, b);
        let (r0, d0) = slot(0);
        let mut real = r0.map(|c| mul(c, w[0]));
        let mut dual = d0.map(|c| mul(c, w[0]));
        let sign_bit = _mm256_set1_ps(-0.0);
        for (k, &wk) in w.iter().enumerate().skip(1) {
            let (r, d) = slot(k);
            let dot = fma(
                r0[0],
                r[0],
                fma(r0[1], r[1], fma(r0[2], r[2], mul(r0[3], r[3]))),
            );
            // copysign(w, dot + 0): +w for a dot of exactly 0, as the other paths.
            let sign = _mm256_and_ps(_mm256_add_ps(dot, _mm256_setzero_ps()), sign_bit);
            let s = _mm256_or_ps(_mm256_andnot_ps(sign_bit, wk), sign);
            for c in 0..4 {
                real[c] = fma(r[c], s, real[c]);
                dual[c] = fma(d[c], s, dual[c]);
            }
        }
        let [rx, ry, rz, rw] = real;
        let [dx, dy, dz, dw] = dual;
        let len2 = fma(rx, rx, fma(ry, ry, fma(rz, rz, mul(rw, rw))));
        let k = _mm256_div_ps(
            _mm256_set1_ps(2.0),
            _mm256_max_ps(len2, _mm256_set1_ps(1e-24)),
        );
        // a × b, with a = r⃗.
        let cross = |bx: __m256, by: __m256, bz: __m256| {
            (
                _mm256_fmsub_ps(ry, bz, mul(rz, by)),
                _mm256_fmsub_ps(rz, bx, mul(rx, bz)),
                _mm256_fmsub_ps(rx, by, mul(ry, bx)),
            )
        };
        // t = k (w d⃗ − d_w r⃗ + r⃗ × d⃗)
        let (cx, cy, cz) = cross(dx, dy, dz);
        let t = |d: __m256, r: __m256, c: __m256| mul(k, fma(rw, d, _mm256_fnmadd_ps(dw, r, c)));
        let (tx, ty, tz) = (t(dx, rx, cx), t(dy, ry, cy), t(dz, rz, cz));
        // R v = v + k r⃗ × (r⃗ × v + w v)
        let rotate = |vx: __m256, vy: __m256, vz: __m256| {
            let (ax, ay, az) = cross(vx, vy, vz);
            let (bx, by, bz) = cross(fma(rw, vx, ax), fma(rw, vy, ay), fma(rw, vz, az));
            (fma(k, bx, vx), fma(k, by, vy), fma(k, bz, vz))
        };
        let [px, py, pz, _] = lanes4(|i| positions.add(3 * i));
        let (px, py, pz) = rotate(px, py, pz);
        store_lanes(
            out_positions,
            _mm256_add_ps(px, tx),
            _mm256_add_ps(py, ty),
            _mm256_add_ps(pz, tz),
        );
        let [nx, ny, nz, _] = lanes4(|i| normals.add(3 * i));
        let (nx, ny, nz) = rotate(nx, ny, nz);
        store_lanes(out_normals, nx, ny, nz);
    }
}

/// The DQS loop over slices of one length, joints checked against the palette.
#[inline(always)]
fn dqs_loop(
    palette: &[DualQuat],
    joints: &[[u16; 4]],
    weights: &[[f32; 4]],
    positions: &[Vec3],
    normals: &[Vec3],
    out_positions: &mut [Vec3],
    out_normals: &mut [Vec3],
) {
    let n = joints.len();
    // Four vertices at a time, one per SIMD lane; the last `n % 4` one by one.
    let lanes = n - n % 4;
    for v in (0..lanes).step_by(4) {
        let (p, q) = dqs_4(
            palette,
            &joints[v..v + 4],
            &weights[v..v + 4],
            &positions[v..v + 4],
            &normals[v..v + 4],
        );
        out_positions[v..v + 4].copy_from_slice(&p);
        out_normals[v..v + 4].copy_from_slice(&q);
    }
    for v in lanes..n {
        let (j, w, p, n) = (&joints[v], &weights[v], &positions[v], &normals[v]);
        let (op, on) = (&mut out_positions[v], &mut out_normals[v]);
        let q0 = &palette[j[0] as usize];
        let q1 = &palette[j[1] as usize];
        let q2 = &palette[j[2] as usize];
        let q3 = &palette[j[3] as usize];
        let r0 = Vec4::from(q0.real);
        // Branch-free sign: the signs are as good as random across vertices, and a mispredicted
        // branch per joint cost more than the rest of the blend. (A dot of exactly 0 keeps +w.)
        let sign = |q: &DualQuat, w: f32| w.copysign(r0.dot(Vec4::from(q.real)) + 0.0);
        let (s1, s2, s3) = (sign(q1, w[1]), sign(q2, w[2]), sign(q3, w[3]));
        let real = r0 * w[0]
            + Vec4::from(q1.real) * s1
            + Vec4::from(q2.real) * s2
            + Vec4::from(q3.real) * s3;
        let dual = Vec4::from(q0.dual) * w[0]
            + Vec4::from(q1.dual) * s1
            + Vec4::from(q2.dual) * s2
            + Vec4::from(q3.dual) * s3;
        // A blend that cancels out (opposite joints, no weight on the pivot) cannot happen with
        // the sign fix unless the pivot's weight is 0; the guard keeps it finite.
        // Unnormalised blend b = (r, w): rotating by b / ‖b‖ is
        //   R v = v + (2 / ‖b‖²) r × (r × v + w v),
        // so one reciprocal of the squared length replaces the square root (as in Kavan et
        // al.'s shader), and the cross products run on SIMD vectors without building a matrix.
        let k = 2.0 / real.length_squared().max(1e-24);
        let rv = Vec3A::new(real.x, real.y, real.z);
        let w0 = real.w;
        let dv = Vec3A::new(dual.x, dual.y, dual.z);
        let t = k * (w0 * dv - dual.w * rv + rv.cross(dv));
        let rotate = |v: Vec3A| v + k * rv.cross(rv.cross(v) + w0 * v);
        let p2 = rotate(Vec3A::from(*p)) + t;
        let n2 = rotate(Vec3A::from(*n));
        *op = p2.into();
        *on = n2.into();
    }
}

/// Four vertices of [`skin_dqs`] at once, structure of arrays: lane `l` of every `Vec4` is
/// vertex `l`. The palette entries are gathered and transposed once (so each lane holds its
/// vertex's joint), then the blend, the sign fix, the normalisation and the rigid motion are
/// the scalar path's formulas written lane-wise: no horizontal sums and no shuffles for the
/// dot and cross products, which were most of the one-vertex path's work. Same results up to
/// rounding.
#[inline(always)]
fn dqs_4(
    palette: &[DualQuat],
    joints: &[[u16; 4]],
    weights: &[[f32; 4]],
    positions: &[Vec3],
    normals: &[Vec3],
) -> ([Vec3; 4], [Vec3; 4]) {
    use glam::Mat4;
    let (joints, weights) = (&joints[..4], &weights[..4]);
    // Rows of a transposed matrix: component c of the four lanes.
    let lanes = |m: Mat4| {
        let t = m.transpose();
        [t.x_axis, t.y_axis, t.z_axis, t.w_axis]
    };
    let w = lanes(Mat4::from_cols_array_2d(&[
        weights[0], weights[1], weights[2], weights[3],
    ]));
    // Joint slot k of the four vertices: real and dual parts, by component.
    let slot = |k: usize| {
        let q = |l: usize| &palette[joints[l][k] as usize];
        let (q0, q1, q2, q3) = (q(0), q(1), q(2), q(3));
        let r = lanes(Mat4::from_cols(
            Vec4::from(q0.real),
            Vec4::from(q1.real),
            Vec4::from(q2.real),
            Vec4::from(q3.real),
        ));
        let d = lanes(Mat4::from_cols(
            Vec4::from(q0.dual),
            Vec4::from(q1.dual),
            Vec4::from(q2.dual),
            Vec4::from(q3.dual),
        ));
        (r, d)
    };
    let dot4 = |a: &[Vec4; 4], b: &[Vec4; 4]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    let (r0, d0) = slot(0);
    let mut real = r0.map(|c| c * w[0]);
    let mut dual = d0.map(|c| c * w[0]);
    for (k, &wk) in w.iter().enumerate().skip(1) {
        let (r, d) = slot(k);
        // The sign fix, as the one-vertex path: +w when the dot is ≥ 0 (or exactly 0).
        let s = wk.copysign(dot4(&r0, &r) + Vec4::ZERO);
        for c in 0..4 {
            real[c] += r[c] * s;
            dual[c] += d[c] * s;
        }
    }
    let k = Vec4::splat(2.0) / dot4(&real, &real).max(Vec4::splat(1e-24));
    let [rx, ry, rz, rw] = real;
    let [dx, dy, dz, dw] = dual;
    let cross = |ax: Vec4, ay: Vec4, az: Vec4, bx: Vec4, by: Vec4, bz: Vec4| {
        (ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx)
    };
    // t = k (w d⃗ − d_w r⃗ + r⃗ × d⃗)
    let (cx, cy, cz) = cross(rx, ry, rz, dx, dy, dz);
    let t = (
        k * (rw * dx - dw * rx + cx),
        k * (rw * dy - dw * ry + cy),
        k * (rw * dz - dw * rz + cz),
    );
    // R v = v + k r⃗ × (r⃗ × v + w v)
    let rotate = |vx: Vec4, vy: Vec4, vz: Vec4| {
        let (ax, ay, az) = cross(rx, ry, rz, vx, vy, vz);
        let (bx, by, bz) = cross(rx, ry, rz, ax + rw * vx, ay + rw * vy, az + rw * vz);
        (vx + k * bx, vy + k * by, vz + k * bz)
    };
    let by_lane = |v: &[Vec3]| {
        (
            Vec4::new(v[0].x, v[1].x, v[2].x, v[3].x),
            Vec4::new(v[0].y, v[1].y, v[2].y, v[3].y),
            Vec4::new(v[0].z, v[1].z, v[2].z, v[3].z),
        )
    };
    let (px, py, pz) = by_lane(positions);
    let (px, py, pz) = rotate(px, py, pz);
    let (px, py, pz) = (
        (px + t.0).to_array(),
        (py + t.1).to_array(),
        (pz + t.2).to_array(),
    );
    let (nx, ny, nz) = by_lane(normals);
    let (nx, ny, nz) = rotate(nx, ny, nz);
    let (nx, ny, nz) = (nx.to_array(), ny.to_array(), nz.to_array());
    (
        std::array::from_fn(|l| Vec3::new(px[l], py[l], pz[l])),
        std::array::from_fn(|l| Vec3::new(nx[l], ny[l], nz[l])),
    )
}
