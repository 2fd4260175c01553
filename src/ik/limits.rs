//! Joint limits for the iterative solvers, and aiming a joint at a target.
//!
//! A chain of positions has no joint frames, so a limit is stated about directions: joint `i`
//! limits the direction of the segment that leaves it, `d_i = (p_{i+1} − p_i) / ℓ_i`, relative to
//! the segment that enters it, `d_{i−1}` (for the root: a fixed `root_direction`, e.g. the rest
//! direction of the first segment, or "down" for a leg hanging from the hip).

use super::{
    ccd_iteration_then, check_chain, check_solver, fabrik_backward, iterate, rotation_arc, IkError,
    IkResult,
};
use glam::{Quat, Vec3};
use std::f32::consts::PI;

/// The most joints [`ccd_limited`] and [`fabrik_limited`] accept: applying the limits after each
/// joint's CCD step costs a pass over the rest of the chain (`O(n²)` per iteration).
pub const MAX_LIMITED_JOINTS: usize = 64;

/// What directions a joint allows for the segment leaving it, relative to the incoming one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JointLimit {
    /// Any direction.
    Free,
    /// A hinge (knee, elbow, finger): the segment stays in the plane perpendicular to `axis`
    /// (chain space, any length), turned from the incoming direction by a signed angle
    /// `θ ∈ [min_rad, max_rad]` about `axis` (right-hand rule). `axis` is fixed in the chain's
    /// space, so a hinge chain bends in one plane (a finger, a leg seen from the side).
    Hinge {
        axis: Vec3,
        min_rad: f32,
        max_rad: f32,
    },
    /// A ball joint (shoulder, hip): the segment stays within `max_rad` of the incoming direction.
    Cone { max_rad: f32 },
}

impl JointLimit {
    /// Checks the limit's numbers: a hinge axis finite and nonzero, `−π ≤ min ≤ max ≤ π`; a cone
    /// angle in `[0, π]`.
    pub fn validate(&self) -> Result<(), &'static str> {
        match *self {
            JointLimit::Free => Ok(()),
            JointLimit::Hinge {
                axis,
                min_rad,
                max_rad,
            } => {
                if !axis.is_finite() || axis.length_squared() < 1e-12 {
                    Err("the hinge axis must be a finite nonzero vector")
                } else if !(min_rad.is_finite() && max_rad.is_finite()) {
                    Err("the hinge angles must be finite")
                } else if !(-PI - 1e-6 <= min_rad && min_rad <= max_rad && max_rad <= PI + 1e-6) {
                    Err("the hinge angles need −π ≤ min ≤ max ≤ π")
                } else {
                    Ok(())
                }
            }
            JointLimit::Cone { max_rad } => {
                if (0.0..=PI + 1e-6).contains(&max_rad) {
                    Ok(())
                } else {
                    Err("the cone angle must be in [0, π]")
                }
            }
        }
    }

    /// The allowed direction nearest to `dir`, given the incoming direction (both unit vectors).
    /// ```text
    /// cone:  if ∠(incoming, dir) > max:  dir' = rotate incoming by max about (incoming × dir)
    /// hinge: project dir and incoming onto the plane ⊥ axis;  θ = signed angle between them
    ///        about axis;  dir' = rotate incoming_plane by clamp(θ, min, max) about axis
    /// ```
    pub fn constrain(&self, incoming: Vec3, dir: Vec3) -> Vec3 {
        match *self {
            JointLimit::Free => dir,
            JointLimit::Cone { max_rad } => {
                let angle = incoming.dot(dir).clamp(-1.0, 1.0).acos();
                if angle <= max_rad {
                    return dir;
                }
                let axis = incoming
                    .cross(dir)
                    .try_normalize()
                    .unwrap_or_else(|| incoming.any_orthonormal_vector());
                Quat::from_axis_angle(axis, max_rad) * incoming
            }
            JointLimit::Hinge {
                axis,
                min_rad,
                max_rad,
            } => {
                let axis = axis.normalize();
                let (zero, theta) = hinge_angle(axis, incoming, dir);
                Quat::from_axis_angle(axis, theta.clamp(min_rad, max_rad)) * zero
            }
        }
    }

    /// How far (radians) `dir` is outside the limit; 0 inside it.
    pub fn violation_rad(&self, incoming: Vec3, dir: Vec3) -> f32 {
        let allowed = self.constrain(incoming, dir);
        // atan2 of sine and cosine: precise for small angles, where acos of a dot is not.
        allowed.cross(dir).length().atan2(allowed.dot(dir))
    }
}

/// The hinge's zero direction (incoming projected onto the plane ⊥ `axis`) and the signed angle
/// of `dir`'s projection from it about `axis`.
fn hinge_angle(axis: Vec3, incoming: Vec3, dir: Vec3) -> (Vec3, f32) {
    let flat = |v: Vec3| v - axis * v.dot(axis);
    // An incoming direction along the axis has no projection: any perpendicular will do.
    let zero = flat(incoming)
        .try_normalize()
        .unwrap_or_else(|| axis.any_orthonormal_vector());
    let d = flat(dir);
    let theta = zero.cross(d).dot(axis).atan2(zero.dot(d));
    (zero, theta)
}

fn check_limits(
    chain: &[Vec3],
    limits: &[JointLimit],
    root_direction: Vec3,
) -> Result<(), IkError> {
    if chain.len() > MAX_LIMITED_JOINTS {
        return Err(IkError::ChainLength {
            joints: chain.len(),
        });
    }
    if limits.len() + 1 != chain.len() {
        return Err(IkError::LimitCount {
            limits: limits.len(),
            joints: chain.len(),
        });
    }
    for (joint, limit) in limits.iter().enumerate() {
        limit
            .validate()
            .map_err(|why| IkError::BadLimit { joint, why })?;
    }
    if !root_direction.is_finite() || root_direction.length_squared() < 1e-12 {
        return Err(IkError::NonFinite {
            what: "root direction (it must also be nonzero)",
        });
    }
    Ok(())
}

/// The direction entering joint `i`: the previous segment's, or the root direction.
fn incoming(chain: &[Vec3], root_direction: Vec3, i: usize) -> Vec3 {
    if i == 0 {
        root_direction
    } else {
        (chain[i] - chain[i - 1]).normalize_or(root_direction)
    }
}

/// Applies the limits of joints `from..` in order, each by turning everything after the joint
/// about it (so the earlier joints are untouched and each joint is final once visited).
pub fn apply_limits(chain: &mut [Vec3], limits: &[JointLimit], root_direction: Vec3, from: usize) {
    let root_direction = root_direction.normalize_or(Vec3::Y);
    for i in from..chain.len() - 1 {
        let dir = chain[i + 1] - chain[i];
        let Some(unit) = dir.try_normalize() else {
            continue;
        };
        let allowed = limits[i].constrain(incoming(chain, root_direction, i), unit);
        if allowed.dot(unit) < 1.0 - 1e-7 {
            if let Some(r) = rotation_arc(unit, allowed) {
                let pivot = chain[i];
                for p in &mut chain[i + 1..] {
                    *p = pivot + r * (*p - pivot);
                }
            }
        }
    }
}

/// Largest violation (radians) of any joint's limit in the chain; 0 when all hold.
pub fn max_violation_rad(chain: &[Vec3], limits: &[JointLimit], root_direction: Vec3) -> f32 {
    let root_direction = root_direction.normalize_or(Vec3::Y);
    (0..chain.len() - 1)
        .map(|i| {
            let dir = (chain[i + 1] - chain[i]).normalize_or(Vec3::Y);
            limits[i].violation_rad(incoming(chain, root_direction, i), dir)
        })
        .fold(0.0, f32::max)
}

/// [`super::ccd`] with a limit per joint (`limits[i]` for joint `i`, one per segment):
/// ```text
/// for i = n−1 … 0:   turn the chain after p_i so the end points at the target (as in ccd),
///                    then apply the limits of joints i, i+1, …, n−1 in order
/// ```
/// The limits hold after every step. A limited chain may not reach a target inside its reach
/// (the limits can forbid every pose that touches it): the result says `reached: false` and the
/// distance left. `chain.len() ≤` [`MAX_LIMITED_JOINTS`]. The starting chain need not satisfy the
/// limits; it does after the first step.
#[allow(clippy::too_many_arguments)]
pub fn ccd_limited(
    chain: &mut [Vec3],
    limits: &[JointLimit],
    root_direction: Vec3,
    target: Vec3,
    max_iterations: usize,
    tolerance: f32,
    errors: Option<&mut [f32]>,
) -> Result<IkResult, IkError> {
    check_chain(chain, target)?;
    check_solver(max_iterations, tolerance)?;
    check_limits(chain, limits, root_direction)?;
    apply_limits(chain, limits, root_direction, 0);
    Ok(iterate(
        chain,
        target,
        max_iterations,
        tolerance,
        errors,
        |chain| {
            ccd_iteration_then(chain, target, |chain, i| {
                apply_limits(chain, limits, root_direction, i)
            })
        },
    ))
}

/// [`super::fabrik`] with a limit per joint: the backward pass is unchanged, and the forward pass
/// (root to end, which ends each iteration) places each joint in the allowed direction nearest
/// to where the backward pass put it:
/// ```text
/// forward:  p_0 ← root;  for i = 1 … n:  d = limit_{i−1}.constrain(d_{i−2}, unit(p_i − p_{i−1}));
///                                        p_i ← p_{i−1} + ℓ_{i−1} d
/// ```
/// so the limits hold after every iteration. As with [`ccd_limited`], a reachable target may be
/// out of the limits' reach (`reached: false`). `chain.len() ≤` [`MAX_LIMITED_JOINTS`].
#[allow(clippy::too_many_arguments)]
pub fn fabrik_limited(
    chain: &mut [Vec3],
    limits: &[JointLimit],
    root_direction: Vec3,
    target: Vec3,
    max_iterations: usize,
    tolerance: f32,
    errors: Option<&mut [f32]>,
) -> Result<IkResult, IkError> {
    check_chain(chain, target)?;
    check_solver(max_iterations, tolerance)?;
    check_limits(chain, limits, root_direction)?;
    let root_direction = root_direction.normalize();
    let n = chain.len();
    let root = chain[0];
    let mut lens = [0.0f32; MAX_LIMITED_JOINTS];
    for (i, l) in lens[..n - 1].iter_mut().enumerate() {
        *l = chain[i].distance(chain[i + 1]);
    }
    apply_limits(chain, limits, root_direction, 0);
    Ok(iterate(
        chain,
        target,
        max_iterations,
        tolerance,
        errors,
        |chain| {
            fabrik_backward(chain, target, &lens[..n - 1]);
            chain[0] = root;
            for i in 1..n {
                let incoming = incoming(chain, root_direction, i - 1);
                let dir = (chain[i] - chain[i - 1]).normalize_or(incoming);
                chain[i] = chain[i - 1] + limits[i - 1].constrain(incoming, dir) * lens[i - 1];
            }
        },
    ))
}

/// An aim (look-at) answer: the rotation to apply to the joint (in the same space as its
/// `forward` and `up`), the new forward direction, and the result, whose `error` is an angle in
/// radians (between the new forward and the direction to the target).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AimSolution {
    pub rotation: Quat,
    pub forward: Vec3,
    pub up: Vec3,
    pub result: IkResult,
}

/// Aims a joint (a head, an eye, a turret) at a target, without roll.
/// ```text
/// a  = unit(target − position)                       the wanted forward
/// f' = a, or, if ∠(f, a) > max_angle_rad, f turned towards a by max_angle_rad   (cone limit)
/// u' = unit(u − f' (u · f'))                          up, kept as upright as the new forward allows
/// rotation R: R f = f',  R (f × u) = f' × u'          error = ∠(f', a)
/// ```
/// `forward` (f) and `up` (u) are the joint's current aim and up directions (any length, not
/// parallel). `max_angle_rad ∈ [0, π]` limits how far the joint turns from `forward`; π for no
/// limit. `reached` is `error ≤ tolerance_rad`.
pub fn aim(
    position: Vec3,
    forward: Vec3,
    up: Vec3,
    target: Vec3,
    max_angle_rad: f32,
    tolerance_rad: f32,
) -> Result<AimSolution, IkError> {
    for (what, v) in [
        ("joint position", position),
        ("forward direction", forward),
        ("up direction", up),
        ("target", target),
    ] {
        if !v.is_finite() {
            return Err(IkError::NonFinite { what });
        }
    }
    check_solver(1, tolerance_rad)?;
    JointLimit::Cone {
        max_rad: max_angle_rad,
    }
    .validate()
    .map_err(|why| IkError::BadLimit { joint: 0, why })?;
    let (Some(f), Some(u)) = (forward.try_normalize(), up.try_normalize()) else {
        return Err(IkError::BadAim);
    };
    let Some(side) = f.cross(u).try_normalize() else {
        return Err(IkError::BadAim);
    };
    let Some(a) = (target - position).try_normalize() else {
        return Err(IkError::ZeroSegment { segment: 0 });
    };
    let new_forward = JointLimit::Cone {
        max_rad: max_angle_rad,
    }
    .constrain(f, a);
    // Upright: up projected off the new forward; when the new forward is along up, turn the
    // old frame along instead.
    let turn = rotation_arc(f, new_forward).unwrap_or(Quat::IDENTITY);
    let new_up = (u - new_forward * u.dot(new_forward))
        .try_normalize()
        .unwrap_or_else(|| (turn * u).normalize());
    let new_side = new_forward.cross(new_up);
    let from = glam::Mat3::from_cols(f, f.cross(side), side);
    let to = glam::Mat3::from_cols(new_forward, new_forward.cross(new_side), new_side);
    let rotation = Quat::from_mat3(&(to * from.transpose())).normalize();
    let error = new_forward.dot(a).clamp(-1.0, 1.0).acos();
    Ok(AimSolution {
        rotation,
        forward: new_forward,
        up: new_up,
        result: IkResult {
            reached: error <= tolerance_rad,
            error,
            iterations: 1,
        },
    })
}
