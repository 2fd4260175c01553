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
    let n = skin.len();
    check_len("positions", n, positions.len())?;
    check_len("normals", n, normals.len())?;
    check_len("output positions", n, out_positions.len())?;
    check_len("output normals", n, out_normals.len())?;
    // O(1) per frame: the scan that names the vertex runs only when something is wrong.
    if skin.joint_bound() > palette.len() {
        if let Some((vertex, j)) = skin.joints().iter().enumerate().find_map(|(v, j)| {
            j.iter()
                .find(|&&j| j as usize >= palette.len())
                .map(|&j| (v, j))
        }) {
            return Err(SkinningError::JointOutOfRange {
                vertex,
                joint: j as usize,
                joints: palette.len(),
            });
        }
    }
    // An index loop over slices cut to one length (the checks above made them equal): the
    // compiler drops the bounds checks, and measured faster than a six-way zip, most of all in wasm.
    let n = skin.len();
    let (joints, weights) = (&skin.joints()[..n], &skin.weights()[..n]);
    let (positions, normals) = (&positions[..n], &normals[..n]);
    let (out_positions, out_normals) = (&mut out_positions[..n], &mut out_normals[..n]);
    for v in 0..n {
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
    Ok(())
}
