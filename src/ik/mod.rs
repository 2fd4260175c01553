//! # Inverse kinematics: where should the joints go so that the end reaches a target?
//!
//! Forward kinematics turns joint rotations into positions; inverse kinematics (IK) goes the other
//! way. Three solvers work on a chain of joint positions `p_0 (root) … p_n (end effector)` in one
//! space (model or world), keep every segment length `|p_{i+1} − p_i|`, and report whether the end
//! reached the target and how far it is left:
//!
//! | solver | chain | idea |
//! |---|---|---|
//! | [`two_joint`] | root, middle, end | law of cosines for the middle angle; a pole vector picks the bend plane; analytic, one step |
//! | [`ccd`] | any length | Cyclic Coordinate Descent: from the last joint to the root, turn each joint so the end points at the target |
//! | [`fabrik`] | any length | Forward And Backward Reaching IK: drag the chain end to the target, then the root back home, repeat |
//!
//! Joint limits ([`JointLimit`]: hinge and cone) constrain [`ccd_limited`] and [`fabrik_limited`];
//! [`aim`] turns a joint (a head, an eye) to look at a target, within a cone.
//!
//! Unreachable targets are clamped: the chain stretches straight towards the target and the result
//! says `reached: false` with the remaining distance. Positions are written into the caller's
//! slice; nothing is allocated.

use core::fmt;

mod limits;
pub use limits::{
    aim, apply_limits, ccd_limited, fabrik_limited, max_violation_rad, AimSolution, JointLimit,
    MAX_LIMITED_JOINTS,
};

use glam::{Quat, Vec3};

/// The most iterations [`ccd`] and [`fabrik`] accept.
pub const MAX_IK_ITERATIONS: usize = 10_000;

/// The most joints a chain may have.
pub const MAX_CHAIN_JOINTS: usize = 1024;

/// What a solver achieved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkResult {
    /// `true` when the end effector ended within the tolerance of the target.
    pub reached: bool,
    /// Distance from the end effector to the target after solving, in the chain's units.
    pub error: f32,
    /// Iterations used (1 for the analytic solver).
    pub iterations: usize,
}

/// What is wrong with a solver's input. Messages name the parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum IkError {
    /// Fewer than two joints, or more than [`MAX_CHAIN_JOINTS`].
    ChainLength { joints: usize },
    /// A joint position, the target or the pole is NaN or infinite.
    NonFinite { what: &'static str },
    /// Two consecutive joints coincide: that segment has no direction.
    ZeroSegment { segment: usize },
    /// The tolerance is not a finite number > 0.
    BadTolerance { tolerance: f32 },
    /// Zero iterations or more than [`MAX_IK_ITERATIONS`].
    BadIterations { iterations: usize },
    /// Not one limit per joint before the end effector (`joints − 1`).
    LimitCount { limits: usize, joints: usize },
    /// A joint limit with impossible numbers.
    BadLimit { joint: usize, why: &'static str },
    /// Aim: the forward or up direction is zero, or they are parallel.
    BadAim,
}

impl fmt::Display for IkError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::ChainLength { joints } => write!(
                f,
                "a chain needs 2 to {MAX_CHAIN_JOINTS} joints (3 for two-joint IK), got {joints}"
            ),
            Self::NonFinite { what } => write!(f, "the {what} contains NaN or an infinite value"),
            Self::ZeroSegment { segment } => {
                write!(f, "segment {segment} has zero length: two joints coincide")
            }
            Self::BadTolerance { tolerance } => {
                write!(f, "tolerance must be a finite number > 0, got {tolerance}")
            }
            Self::BadIterations { iterations } => write!(
                f,
                "iterations must be between 1 and {MAX_IK_ITERATIONS}, got {iterations}"
            ),
            Self::LimitCount { limits, joints } => write!(
                f,
                "a chain of {joints} joints needs {} limits (one per joint before the end), got {limits}",
                joints.saturating_sub(1)
            ),
            Self::BadLimit { joint, why } => write!(f, "limit of joint {joint}: {why}"),
            Self::BadAim => f.write_str(
                "aim: the forward and up directions must be nonzero and not parallel",
            ),
        }
    }
}

impl std::error::Error for IkError {}

fn check_chain(chain: &[Vec3], target: Vec3) -> Result<(), IkError> {
    if !(2..=MAX_CHAIN_JOINTS).contains(&chain.len()) {
        return Err(IkError::ChainLength {
            joints: chain.len(),
        });
    }
    if !chain.iter().all(|p| p.is_finite()) {
        return Err(IkError::NonFinite {
            what: "chain of joint positions",
        });
    }
    if !target.is_finite() {
        return Err(IkError::NonFinite { what: "target" });
    }
    for (segment, pair) in chain.windows(2).enumerate() {
        if pair[0].distance_squared(pair[1]) <= 1e-12 {
            return Err(IkError::ZeroSegment { segment });
        }
    }
    Ok(())
}

fn check_solver(iterations: usize, tolerance: f32) -> Result<(), IkError> {
    if !(1..=MAX_IK_ITERATIONS).contains(&iterations) {
        return Err(IkError::BadIterations { iterations });
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(IkError::BadTolerance { tolerance });
    }
    Ok(())
}

/// The analytic two-joint answer: new middle and end positions, and the world-space rotations
/// that take the old segments onto the new ones (apply `root_rotation` to the root joint, then
/// `middle_rotation` to the middle joint).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoJointSolution {
    pub middle: Vec3,
    pub end: Vec3,
    /// World-space rotation of the root joint: old `middle − root` onto new.
    pub root_rotation: Quat,
    /// World-space rotation of the middle joint, after the root's: the rotated old
    /// `end − middle` onto the new one.
    pub middle_rotation: Quat,
    pub result: IkResult,
}

/// Two-joint IK (shoulder–elbow–wrist, hip–knee–ankle) by the law of cosines.
/// ```text
/// a = |middle − root|,  b = |end − middle|,  d = clamp(|target − root|, |a − b|, a + b)
/// cos α = (a² + d² − b²) / (2 a d)                 (angle at the root, between the
///                                                   root→target line and the first segment)
/// u = (target − root) / |target − root|,  v = the pole direction made perpendicular to u
/// middle' = root + a (cos α u + sin α v),   end' = root + d u
/// ```
/// The pole (a point in the same space, e.g. in front of the knee) picks the plane the chain bends
/// in: the middle joint goes to the pole's side. Without a usable pole (on the root→target line)
/// the current middle joint's side is kept. A target closer than `|a − b|` or further than `a + b`
/// is unreachable: the chain goes as near as it can and `reached` is `false`.
pub fn two_joint(
    root: Vec3,
    middle: Vec3,
    end: Vec3,
    target: Vec3,
    pole: Vec3,
    tolerance: f32,
) -> Result<TwoJointSolution, IkError> {
    check_chain(&[root, middle, end], target)?;
    check_solver(1, tolerance)?;
    if !pole.is_finite() {
        return Err(IkError::NonFinite { what: "pole" });
    }
    let a = root.distance(middle);
    let b = middle.distance(end);
    let to_target = target - root;
    let distance = to_target.length();
    let u = if distance > 1e-9 {
        to_target / distance
    } else {
        (end - root).normalize_or(Vec3::Y)
    };
    // A hair inside the limits keeps sin α away from 0 (no flip of the bend direction).
    let d = distance.clamp((a - b).abs() + 1e-6, a + b - 1e-6);
    let cos_alpha = ((a * a + d * d - b * b) / (2.0 * a * d)).clamp(-1.0, 1.0);
    let sin_alpha = (1.0 - cos_alpha * cos_alpha).max(0.0).sqrt();
    let perpendicular = |w: Vec3| w - u * w.dot(u);
    let v = perpendicular(pole - root)
        .try_normalize()
        .or_else(|| perpendicular(middle - root).try_normalize())
        .unwrap_or_else(|| u.any_orthonormal_vector());
    let new_middle = root + a * (cos_alpha * u + sin_alpha * v);
    let new_end = root + d * u;
    let root_rotation = Quat::from_rotation_arc((middle - root) / a, (new_middle - root) / a);
    let turned_lower = root_rotation * (end - middle) / b;
    let middle_rotation = Quat::from_rotation_arc(turned_lower, (new_end - new_middle) / b);
    let error = new_end.distance(target);
    Ok(TwoJointSolution {
        middle: new_middle,
        end: new_end,
        root_rotation,
        middle_rotation,
        result: IkResult {
            reached: error <= tolerance,
            error,
            iterations: 1,
        },
    })
}

/// The shortest rotation turning the direction of `from` onto the direction of `to` (neither
/// needs unit length), or `None` when either is (nearly) zero.
/// ```text
/// q = normalize(from × to,  |from| |to| + from · to)      (x, y, z, w)
/// ```
/// Unlike `Quat::from_rotation_arc`, tiny angles are kept: glam returns the identity below about
/// 7·10⁻⁴ rad (its `dot > 1 − 2ε` test), which stalled CCD a few millimetres short of the target,
/// since near convergence every joint's correction is that small. Opposite directions turn half a
/// turn about any perpendicular axis.
pub fn rotation_arc(from: Vec3, to: Vec3) -> Option<Quat> {
    let scale = from.length() * to.length();
    if scale.is_nan() || scale <= 1e-12 {
        return None;
    }
    let w = scale + from.dot(to);
    if w <= 1e-6 * scale {
        let axis = from.any_orthonormal_vector();
        return Some(Quat::from_axis_angle(axis, std::f32::consts::PI));
    }
    let c = from.cross(to);
    Some(Quat::from_xyzw(c.x, c.y, c.z, w).normalize())
}

/// One CCD iteration (sweep): for each joint from the one before the end back to the root, turn
/// everything after it about it so that the end points at the target.
/// ```text
/// for i = n−1 … 0:   R = rotation_arc(end − p_i, target − p_i);   p_j ← p_i + R (p_j − p_i)  for j > i
/// ```
/// A joint where the end or the target sits on the pivot is skipped. The caller validates the
/// chain ([`ccd`] does).
pub fn ccd_iteration(chain: &mut [Vec3], target: Vec3) {
    ccd_iteration_then(chain, target, |_, _| {});
}

/// [`ccd_iteration`], calling `after_joint(chain, i)` once joint `i` has turned (or been
/// skipped): [`limits::ccd_limited`] applies the joint limits there.
pub(crate) fn ccd_iteration_then(
    chain: &mut [Vec3],
    target: Vec3,
    mut after_joint: impl FnMut(&mut [Vec3], usize),
) {
    let n = chain.len();
    for i in (0..n.saturating_sub(1)).rev() {
        let pivot = chain[i];
        if let Some(r) = rotation_arc(chain[n - 1] - pivot, target - pivot) {
            for p in &mut chain[i + 1..] {
                *p = pivot + r * (*p - pivot);
            }
        }
        after_joint(chain, i);
    }
}

/// The loop the iterative solvers share: runs `iteration` until the end effector is within
/// `tolerance` of `target` or `max_iterations` have run, writing the error after each iteration
/// into `errors` (as many as fit).
pub(crate) fn iterate(
    chain: &mut [Vec3],
    target: Vec3,
    max_iterations: usize,
    tolerance: f32,
    mut errors: Option<&mut [f32]>,
    mut iteration: impl FnMut(&mut [Vec3]),
) -> IkResult {
    let end = chain.len() - 1;
    let mut error = chain[end].distance(target);
    let mut iterations = 0;
    while error > tolerance && iterations < max_iterations {
        iteration(chain);
        error = chain[end].distance(target);
        if let Some(slot) = errors.as_deref_mut().and_then(|e| e.get_mut(iterations)) {
            *slot = error;
        }
        iterations += 1;
    }
    IkResult {
        reached: error <= tolerance,
        error,
        iterations,
    }
}

/// FABRIK's backward pass: the end on the target, then each joint at its segment's length from
/// the next one, towards where it was.
pub(crate) fn fabrik_backward(chain: &mut [Vec3], target: Vec3, lengths: &[f32]) {
    let n = chain.len();
    chain[n - 1] = target;
    for i in (0..n - 1).rev() {
        let dir = (chain[i] - chain[i + 1]).normalize_or(Vec3::Y);
        chain[i] = chain[i + 1] + dir * lengths[i];
    }
}

/// Cyclic Coordinate Descent on a chain of positions (`chain[0]` the root, the last the end
/// effector). One iteration visits the joints from the one before the end back to the root and
/// turns everything after joint `i` about it by the rotation taking `end − p_i` onto
/// `target − p_i`:
/// ```text
/// for i = n−1 … 0:   R = rotation_arc(end − p_i, target − p_i);   p_j ← p_i + R (p_j − p_i)  for j > i
/// ```
/// Stops when the end is within `tolerance` of the target or after `max_iterations`. Segment
/// lengths are kept exactly (up to rounding). `errors`, if given, receives the error after each
/// iteration (as many as fit).
pub fn ccd(
    chain: &mut [Vec3],
    target: Vec3,
    max_iterations: usize,
    tolerance: f32,
    errors: Option<&mut [f32]>,
) -> Result<IkResult, IkError> {
    check_chain(chain, target)?;
    check_solver(max_iterations, tolerance)?;
    Ok(iterate(
        chain,
        target,
        max_iterations,
        tolerance,
        errors,
        |c| ccd_iteration(c, target),
    ))
}

/// FABRIK on a chain of positions (`chain[0]` the root, which stays put).
/// ```text
/// backward: p_n ← target;  for i = n−1 … 0:  p_i ← p_{i+1} + ℓ_i (p_i − p_{i+1}) / |p_i − p_{i+1}|
/// forward:  p_0 ← root;    for i = 1 … n:    p_i ← p_{i−1} + ℓ_{i−1} (p_i − p_{i−1}) / |p_i − p_{i−1}|
/// ```
/// with `ℓ_i = |p_{i+1} − p_i|` the segment lengths. An unreachable target (further than the sum of
/// the lengths) straightens the chain towards it in one step. Stops within `tolerance` or after
/// `max_iterations`; `errors` as in [`ccd`].
pub fn fabrik(
    chain: &mut [Vec3],
    target: Vec3,
    max_iterations: usize,
    tolerance: f32,
    errors: Option<&mut [f32]>,
) -> Result<IkResult, IkError> {
    check_chain(chain, target)?;
    check_solver(max_iterations, tolerance)?;
    let n = chain.len();
    let root = chain[0];
    // The segment lengths ℓ_i, kept on the stack (a chain has at most MAX_CHAIN_JOINTS joints).
    let mut buffer = [0.0f32; MAX_CHAIN_JOINTS];
    let lens = &mut buffer[..n - 1];
    for (i, l) in lens.iter_mut().enumerate() {
        *l = chain[i].distance(chain[i + 1]);
    }
    let total: f32 = lens.iter().sum();
    if root.distance(target) >= total {
        let u = (target - root).normalize_or(Vec3::Y);
        let mut along = 0.0;
        for i in 1..n {
            along += lens[i - 1];
            chain[i] = root + u * along;
        }
        let error = chain[n - 1].distance(target);
        if let Some(slot) = errors.and_then(|e| e.get_mut(0)) {
            *slot = error;
        }
        return Ok(IkResult {
            reached: error <= tolerance,
            error,
            iterations: 1,
        });
    }
    let lens = &*lens;
    Ok(iterate(
        chain,
        target,
        max_iterations,
        tolerance,
        errors,
        |chain| {
            fabrik_backward(chain, target, lens);
            chain[0] = root;
            for i in 1..n {
                let dir = (chain[i] - chain[i - 1]).normalize_or(Vec3::Y);
                chain[i] = chain[i - 1] + dir * lens[i - 1];
            }
        },
    ))
}
