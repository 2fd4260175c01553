//! Blending poses: crossfade, N-way weights, additive layers, per-joint masks.
//!
//! All blends work on local transforms, joint by joint: translations and scales are mixed
//! linearly, rotations by a weighted sum of quaternions put in one hemisphere and normalised (an
//! nlerp generalised to many inputs). Outputs go into the caller's pose; nothing is allocated.

use core::fmt;

use super::hierarchy::{Pose, Skeleton, Transform};
use glam::{Quat, Vec3, Vec4};

/// What is wrong with a blend's inputs.
#[derive(Clone, Debug, PartialEq)]
pub enum BlendError {
    /// A pose, weight list or mask has the wrong length.
    LengthMismatch {
        what: &'static str,
        expected: usize,
        actual: usize,
    },
    /// A weight is negative, above 1 where a fraction is expected, or not a number.
    BadWeight { index: usize, weight: f32 },
    /// Every weight is zero: nothing to blend.
    ZeroTotalWeight,
    /// No poses given.
    NoPoses,
}

impl fmt::Display for BlendError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::LengthMismatch {
                what,
                expected,
                actual,
            } => {
                write!(f, "expected {expected} {what}, got {actual}")
            }
            Self::BadWeight { index, weight } => {
                write!(
                    f,
                    "weight {index} is {weight}: blend weights must be finite and in [0, 1]"
                )
            }
            Self::ZeroTotalWeight => write!(f, "the blend weights add up to zero"),
            Self::NoPoses => write!(f, "no poses to blend"),
        }
    }
}

impl std::error::Error for BlendError {}

fn check_len(what: &'static str, expected: usize, actual: usize) -> Result<(), BlendError> {
    if expected == actual {
        Ok(())
    } else {
        Err(BlendError::LengthMismatch {
            what,
            expected,
            actual,
        })
    }
}

fn check_fraction(index: usize, weight: f32) -> Result<f32, BlendError> {
    if (0.0..=1.0).contains(&weight) {
        Ok(weight)
    } else {
        Err(BlendError::BadWeight { index, weight })
    }
}

/// One joint's crossfade: lerp, short-arc nlerp, lerp. `w = 0` gives `a`, `w = 1` gives `b`
/// exactly.
/// ```text
/// t = (1−w) t_a + w t_b,   s = (1−w) s_a + w s_b,   q = nlerp(q_a, ±q_b; w)  (short arc)
/// ```
/// Reference solution of exercise 6.3. Lesson: `lessons/06-skeletons`.
#[inline]
pub fn crossfade_transform(a: &Transform, b: &Transform, w: f32) -> Transform {
    if w <= 0.0 {
        return *a;
    }
    if w >= 1.0 {
        return *b;
    }
    let qb = if a.rotation.dot(b.rotation) < 0.0 {
        -b.rotation
    } else {
        b.rotation
    };
    let q = Vec4::from(a.rotation) * (1.0 - w) + Vec4::from(qb) * w;
    Transform {
        translation: a.translation.lerp(b.translation, w),
        rotation: Quat::from_vec4(q.normalize()),
        scale: a.scale.lerp(b.scale, w),
    }
}

/// Crossfade of two poses with weight `w ∈ [0, 1]`, joint by joint.
/// ```text
/// t = (1−w) t_a + w t_b,   s = (1−w) s_a + w s_b,   q = nlerp(q_a, ±q_b; w)  (short arc)
/// ```
/// `w = 0` gives `a` and `w = 1` gives `b`, exactly.
pub fn crossfade(a: &Pose, b: &Pose, w: f32, out: &mut Pose) -> Result<(), BlendError> {
    check_len("transforms in pose b", a.len(), b.len())?;
    check_len("transforms in the output pose", a.len(), out.len())?;
    let w = check_fraction(0, w)?;
    for ((o, x), y) in out.local.iter_mut().zip(&a.local).zip(&b.local) {
        *o = crossfade_transform(x, y, w);
    }
    Ok(())
}

/// Crossfade with one weight per joint: `mask[j] = 0` keeps `a`'s joint, `1` takes `b`'s. With a
/// [`subtree_mask`] this puts one clip's upper body on another clip's legs.
pub fn crossfade_masked(
    a: &Pose,
    b: &Pose,
    mask: &[f32],
    out: &mut Pose,
) -> Result<(), BlendError> {
    check_len("transforms in pose b", a.len(), b.len())?;
    check_len("transforms in the output pose", a.len(), out.len())?;
    check_len("mask weights (one per joint)", a.len(), mask.len())?;
    for (j, &w) in mask.iter().enumerate() {
        check_fraction(j, w)?;
    }
    for (((o, x), y), &w) in out.local.iter_mut().zip(&a.local).zip(&b.local).zip(mask) {
        *o = crossfade_transform(x, y, w);
    }
    Ok(())
}

/// Per-joint weights: `inside` for `root` and its descendants, `outside` for every other joint.
/// (Allocates: build masks once, not per frame.)
pub fn subtree_mask(skeleton: &Skeleton, root: usize, inside: f32, outside: f32) -> Vec<f32> {
    (0..skeleton.len())
        .map(|j| {
            if root < skeleton.len() && skeleton.in_group(root, j) {
                inside
            } else {
                outside
            }
        })
        .collect()
}

/// Weighted blend of any number of poses. Weights must be ≥ 0 and are divided by their sum.
/// ```text
/// t = Σ w_k t_k,   s = Σ w_k s_k,   q = normalise(Σ w_k σ_k q_k),   σ_k = sign(q_k · q_ref)
/// ```
/// Every rotation is first put in the hemisphere of the first pose with a non-zero weight
/// (`q_ref`): `q` and `−q` are the same rotation, but summing them would cancel.
pub fn blend_weighted(poses: &[&Pose], weights: &[f32], out: &mut Pose) -> Result<(), BlendError> {
    let first = poses.first().ok_or(BlendError::NoPoses)?;
    check_len("weights (one per pose)", poses.len(), weights.len())?;
    for p in poses {
        check_len("transforms in every pose", first.len(), p.len())?;
    }
    check_len("transforms in the output pose", first.len(), out.len())?;
    let mut total = 0.0;
    for (index, &w) in weights.iter().enumerate() {
        if !(w.is_finite() && w >= 0.0) {
            return Err(BlendError::BadWeight { index, weight: w });
        }
        total += w;
    }
    if total <= 0.0 {
        return Err(BlendError::ZeroTotalWeight);
    }
    let reference = weights.iter().position(|&w| w > 0.0).unwrap_or(0);
    for j in 0..first.len() {
        let q_ref = poses[reference].local[j].rotation;
        let (mut t, mut s, mut q) = (Vec3::ZERO, Vec3::ZERO, Vec4::ZERO);
        for (p, &w) in poses.iter().zip(weights) {
            let x = &p.local[j];
            let w = w / total;
            let sign = if x.rotation.dot(q_ref) < 0.0 { -w } else { w };
            t += x.translation * w;
            s += x.scale * w;
            q += Vec4::from(x.rotation) * sign;
        }
        out.local[j] = Transform {
            translation: t,
            rotation: Quat::from_vec4(q.normalize()),
            scale: s,
        };
    }
    Ok(())
}

/// The difference of `pose` from `reference`, joint by joint: what an additive layer stores.
/// ```text
/// Δt = t − t_ref,   Δq = q_ref⁻¹ · q,   Δs = s / s_ref
/// ```
/// so that [`add_additive`] with weight 1 on `reference` gives back `pose`. A reference scale of
/// zero gives `Δs = 1` on that axis.
pub fn make_additive(pose: &Pose, reference: &Pose, out: &mut Pose) -> Result<(), BlendError> {
    check_len(
        "transforms in the reference pose",
        pose.len(),
        reference.len(),
    )?;
    check_len("transforms in the output pose", pose.len(), out.len())?;
    for ((o, x), r) in out.local.iter_mut().zip(&pose.local).zip(&reference.local) {
        let ratio = |a: f32, b: f32| if b == 0.0 { 1.0 } else { a / b };
        *o = Transform {
            translation: x.translation - r.translation,
            rotation: (r.rotation.conjugate() * x.rotation).normalize(),
            scale: Vec3::new(
                ratio(x.scale.x, r.scale.x),
                ratio(x.scale.y, r.scale.y),
                ratio(x.scale.z, r.scale.z),
            ),
        };
    }
    Ok(())
}

/// Adds an additive layer (from [`make_additive`]) on top of `base` with weight `w ∈ [0, 1]`.
/// ```text
/// t = t_base + w Δt,   q = q_base · nlerp(1, Δq; w),   s = s_base ⊙ (1 + w (Δs − 1))
/// ```
/// `w = 0` gives `base`; `w = 1` applies the whole difference.
pub fn add_additive(
    base: &Pose,
    additive: &Pose,
    w: f32,
    out: &mut Pose,
) -> Result<(), BlendError> {
    check_len(
        "transforms in the additive pose",
        base.len(),
        additive.len(),
    )?;
    check_len("transforms in the output pose", base.len(), out.len())?;
    let w = check_fraction(0, w)?;
    for ((o, b), d) in out.local.iter_mut().zip(&base.local).zip(&additive.local) {
        let delta = if w >= 1.0 {
            d.rotation
        } else {
            crate::rotation::nlerp(Quat::IDENTITY, d.rotation, w)
        };
        *o = Transform {
            translation: b.translation + d.translation * w,
            rotation: (b.rotation * delta).normalize(),
            scale: b.scale * (Vec3::ONE + (d.scale - Vec3::ONE) * w),
        };
    }
    Ok(())
}
