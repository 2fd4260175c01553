//! [`Skeleton`] (the validated hierarchy), [`Transform`] and [`Pose`] (local transforms), and the
//! local-to-model pass.

use core::fmt;

use crate::transform::ScaleMode;
use glam::{Affine3A, Mat3A, Mat4, Quat, Vec3, Vec3A};

/// The most joints a skeleton may have (joint indices fit in a `u16`, as skinning stores them).
pub const MAX_JOINTS: usize = 1 << 16;

/// One joint's local transform: where it sits in its parent's frame.
/// ```text
/// local = T(translation) · R(rotation) · S(scale)
/// ```
/// so a point in the joint's frame is scaled first, then rotated, then moved to the pivot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Position of the joint's pivot in its parent's frame, metres.
    pub translation: Vec3,
    /// Rotation about the pivot, a unit quaternion.
    pub rotation: Quat,
    /// Scale along the joint's own axes.
    pub scale: Vec3,
}

impl Transform {
    /// No translation, no rotation, unit scale.
    pub const IDENTITY: Self = Self {
        translation: Vec3::ZERO,
        rotation: Quat::IDENTITY,
        scale: Vec3::ONE,
    };

    /// A pure translation.
    pub fn from_translation(translation: Vec3) -> Self {
        Self {
            translation,
            ..Self::IDENTITY
        }
    }

    /// `T · R · S` as an affine matrix (see [`trs_to_affine`]).
    pub fn to_affine(&self) -> Affine3A {
        trs_to_affine(self.translation, self.rotation, self.scale)
    }

    /// `T · R · S` as a 4×4 matrix.
    pub fn to_mat4(&self) -> Mat4 {
        Mat4::from(self.to_affine())
    }

    /// `true` when every number is finite.
    pub fn is_finite(&self) -> bool {
        self.translation.is_finite() && self.rotation.is_finite() && self.scale.is_finite()
    }
}

impl Default for Transform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

/// `T · R · S` as a 3×4 affine matrix, built straight from the quaternion's components.
/// ```text
///        ⎡ 1−2(y²+z²)   2(xy−wz)    2(xz+wy)  ⎤
/// R(q) = ⎢  2(xy+wz)   1−2(x²+z²)   2(yz−wx)  ⎥,   M = [ R(q)·diag(s) | t ]
///        ⎣  2(xz−wy)    2(yz+wx)   1−2(x²+y²) ⎦
/// ```
/// The scale multiplies the columns, the translation is the last column; no 4×4 product is
/// formed, and the bottom row `(0 0 0 1)` is implicit (an affine matrix stores 12 numbers, not
/// 16). Expects a unit quaternion. This is what the sampling loop calls once per joint per frame.
#[inline]
pub fn trs_to_affine(translation: Vec3, rotation: Quat, scale: Vec3) -> Affine3A {
    let [x, y, z, w] = rotation.to_array();
    let (x2, y2, z2) = (x + x, y + y, z + z);
    let (xx, yy, zz) = (x * x2, y * y2, z * z2);
    let (xy, xz, yz) = (x * y2, x * z2, y * z2);
    let (wx, wy, wz) = (w * x2, w * y2, w * z2);
    Affine3A {
        matrix3: Mat3A::from_cols(
            Vec3A::new(1.0 - (yy + zz), xy + wz, xz - wy) * scale.x,
            Vec3A::new(xy - wz, 1.0 - (xx + zz), yz + wx) * scale.y,
            Vec3A::new(xz + wy, yz - wx, 1.0 - (xx + yy)) * scale.z,
        ),
        translation: Vec3A::from(translation),
    }
}

/// Model-space matrices of a pose, in one forward pass over the joints.
/// ```text
/// ScaleMode::Inherited:     model[i] = model[p] · T_i R_i S_i
/// ScaleMode::NotInherited:  frame[i] = frame[p] · T_i R_i,   model[i] = frame[i] · S_i
/// ```
/// (`p = parents[i]`; a root uses the identity for its parent.) One loop suffices because
/// `parents[i] < i`: a parent's matrix is final before any child reads it. With scale not
/// inherited, the loop first writes the unscaled frames (children read those), then a second,
/// parent-free pass scales each joint's own columns. Writes into `model`; allocates nothing.
///
/// The inputs must satisfy what [`Skeleton::new`] checks and have one entry per joint; this hot
/// function only `debug_assert`s that. [`Skeleton::model_matrices`] is the checked front door.
pub fn local_to_model(
    parents: &[i32],
    local: &[Transform],
    mode: ScaleMode,
    model: &mut [Affine3A],
) {
    debug_assert!(parents.len() == local.len() && local.len() == model.len());
    let n = parents.len().min(local.len()).min(model.len());
    match mode {
        ScaleMode::Inherited => {
            for i in 0..n {
                let x = &local[i];
                let m = trs_to_affine(x.translation, x.rotation, x.scale);
                let parent = parents[i];
                model[i] = if parent < 0 {
                    m
                } else {
                    debug_assert!((parent as usize) < i, "parent {parent} of joint {i}");
                    model[parent as usize] * m
                };
            }
        }
        ScaleMode::NotInherited => {
            for i in 0..n {
                let x = &local[i];
                let m = trs_to_affine(x.translation, x.rotation, Vec3::ONE);
                let parent = parents[i];
                model[i] = if parent < 0 {
                    m
                } else {
                    debug_assert!((parent as usize) < i, "parent {parent} of joint {i}");
                    model[parent as usize] * m
                };
            }
            for (m, x) in model[..n].iter_mut().zip(local) {
                m.matrix3 = Mat3A::from_cols(
                    m.matrix3.x_axis * x.scale.x,
                    m.matrix3.y_axis * x.scale.y,
                    m.matrix3.z_axis * x.scale.z,
                );
            }
        }
    }
}

/// Why joints given to [`Skeleton::new`] do not make a skeleton. Each rule has its own variant;
/// messages are written for students.
#[derive(Clone, Debug, PartialEq)]
pub enum SkeletonError {
    /// No joints at all.
    Empty,
    /// More than [`MAX_JOINTS`] joints.
    TooManyJoints { count: usize },
    /// Two per-joint lists have different lengths.
    LengthMismatch {
        what: &'static str,
        expected: usize,
        actual: usize,
    },
    /// `parents[joint]` is neither −1 nor the index of a joint (`< -1` or `≥ count`).
    ParentOutOfRange {
        joint: usize,
        parent: i32,
        count: usize,
    },
    /// Following parents from `joint` comes back to `joint` (a joint that is its own ancestor).
    Cycle { joint: usize },
    /// `parents[joint]` is a valid joint, but listed at or after its child.
    ParentNotBefore { joint: usize, parent: i32 },
    /// Two joints share a name.
    DuplicateName {
        name: String,
        first: usize,
        second: usize,
    },
    /// A rest transform contains NaN or an infinity.
    NonFinite { joint: usize },
    /// A rest rotation is not a unit quaternion (its length is given).
    NotUnitRotation { joint: usize, length: f32 },
    /// The rest pose's model matrix of a joint cannot be inverted (a zero scale).
    SingularBind { joint: usize },
}

impl fmt::Display for SkeletonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Empty => write!(f, "the skeleton has no joints"),
            Self::TooManyJoints { count } => {
                write!(f, "{count} joints is too many: a skeleton has at most {MAX_JOINTS}")
            }
            Self::LengthMismatch { what, expected, actual } => {
                write!(f, "expected {expected} {what} (one per joint), got {actual}")
            }
            Self::ParentOutOfRange { joint, parent, count } => write!(
                f,
                "joint {joint} has parent {parent}, which is out of range: a parent is -1 (root) or \
                 a joint index in 0..{count}"
            ),
            Self::Cycle { joint } => write!(
                f,
                "joint {joint} is its own ancestor: following its parents leads back to it (a cycle)"
            ),
            Self::ParentNotBefore { joint, parent } => write!(
                f,
                "joint {joint} has parent {parent}, listed at or after it: every parent must come \
                 before its children (parent < {joint})"
            ),
            Self::DuplicateName { name, first, second } => {
                write!(f, "joints {first} and {second} are both named {name:?}: names must be unique")
            }
            Self::NonFinite { joint } => {
                write!(f, "the rest transform of joint {joint} contains NaN or an infinite value")
            }
            Self::NotUnitRotation { joint, length } => write!(
                f,
                "the rest rotation of joint {joint} has length {length}: it must be a unit quaternion"
            ),
            Self::SingularBind { joint } => write!(
                f,
                "the rest pose of joint {joint} cannot be inverted (a scale of zero?)"
            ),
        }
    }
}

impl std::error::Error for SkeletonError {}

/// A validated joint hierarchy: one flat array, parents before children.
///
/// Per joint: a name, the parent index (`-1` for a root), the rest (bind) transform, the inverse
/// of the rest pose's model matrix (used by skinning to take a vertex from model space into the
/// joint's frame), and the **group size**: the joint plus all its descendants. When the joints are
/// listed depth-first (as [`human`](super::human) lists them), a joint's group is the contiguous
/// range `i .. i + group_size[i]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Skeleton {
    names: Vec<String>,
    parents: Vec<i32>,
    rest: Vec<Transform>,
    inverse_bind: Vec<Affine3A>,
    group_sizes: Vec<usize>,
    scale_mode: ScaleMode,
}

impl Skeleton {
    /// Checks every rule of [`SkeletonError`] and computes the group sizes and the inverse bind
    /// matrices (with scale inherited, as glTF and most runtimes do; see
    /// [`Skeleton::with_scale_mode`]).
    pub fn new(
        names: Vec<String>,
        parents: Vec<i32>,
        rest: Vec<Transform>,
    ) -> Result<Self, SkeletonError> {
        let n = parents.len();
        if n == 0 {
            return Err(SkeletonError::Empty);
        }
        if n > MAX_JOINTS {
            return Err(SkeletonError::TooManyJoints { count: n });
        }
        for (what, actual) in [("names", names.len()), ("rest transforms", rest.len())] {
            if actual != n {
                return Err(SkeletonError::LengthMismatch {
                    what,
                    expected: n,
                    actual,
                });
            }
        }
        for (joint, &parent) in parents.iter().enumerate() {
            if parent < -1 || parent >= n as i32 {
                return Err(SkeletonError::ParentOutOfRange {
                    joint,
                    parent,
                    count: n,
                });
            }
        }
        for (joint, &parent) in parents.iter().enumerate() {
            if parent < joint as i32 {
                continue;
            }
            // Listed at or after its child: say "cycle" when the ancestry really loops.
            let mut k = parent;
            for _ in 0..=n {
                if k == joint as i32 {
                    return Err(SkeletonError::Cycle { joint });
                }
                if k < 0 {
                    break;
                }
                k = parents[k as usize];
            }
            return Err(SkeletonError::ParentNotBefore { joint, parent });
        }
        let mut seen = std::collections::HashMap::with_capacity(n);
        for (second, name) in names.iter().enumerate() {
            if let Some(&first) = seen.get(name.as_str()) {
                return Err(SkeletonError::DuplicateName {
                    name: name.clone(),
                    first,
                    second,
                });
            }
            seen.insert(name.as_str(), second);
        }
        for (joint, x) in rest.iter().enumerate() {
            if !x.is_finite() {
                return Err(SkeletonError::NonFinite { joint });
            }
            let length = x.rotation.length();
            if (length - 1.0).abs() > 1e-3 {
                return Err(SkeletonError::NotUnitRotation { joint, length });
            }
        }
        // Group sizes: every joint adds its group to its parent's, children last to first.
        let mut group_sizes = vec![1usize; n];
        for i in (1..n).rev() {
            if parents[i] >= 0 {
                group_sizes[parents[i] as usize] += group_sizes[i];
            }
        }
        let mut skeleton = Self {
            names,
            parents,
            rest,
            inverse_bind: Vec::new(),
            group_sizes,
            scale_mode: ScaleMode::Inherited,
        };
        skeleton.compute_inverse_bind()?;
        Ok(skeleton)
    }

    /// The same skeleton with another scale mode (the inverse bind matrices are recomputed).
    pub fn with_scale_mode(mut self, mode: ScaleMode) -> Result<Self, SkeletonError> {
        self.scale_mode = mode;
        self.compute_inverse_bind()?;
        Ok(self)
    }

    fn compute_inverse_bind(&mut self) -> Result<(), SkeletonError> {
        let mut model = vec![Affine3A::IDENTITY; self.len()];
        local_to_model(&self.parents, &self.rest, self.scale_mode, &mut model);
        self.inverse_bind = Vec::with_capacity(model.len());
        for (joint, m) in model.iter().enumerate() {
            let det = m.matrix3.determinant();
            if !det.is_finite() || det.abs() < 1e-12 {
                return Err(SkeletonError::SingularBind { joint });
            }
            self.inverse_bind.push(m.inverse());
        }
        Ok(())
    }

    /// Number of joints (at least 1).
    pub fn len(&self) -> usize {
        self.parents.len()
    }

    /// Always `false`: a skeleton has at least one joint.
    pub fn is_empty(&self) -> bool {
        self.parents.is_empty()
    }

    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Parent of each joint, `-1` for a root; `parents[i] < i`.
    pub fn parents(&self) -> &[i32] {
        &self.parents
    }

    /// The rest (bind) pose's local transforms.
    pub fn rest(&self) -> &[Transform] {
        &self.rest
    }

    /// Inverse of each joint's model matrix in the rest pose.
    pub fn inverse_bind(&self) -> &[Affine3A] {
        &self.inverse_bind
    }

    /// Each joint's group size: itself plus all its descendants (a leaf has 1).
    pub fn group_sizes(&self) -> &[usize] {
        &self.group_sizes
    }

    pub fn scale_mode(&self) -> ScaleMode {
        self.scale_mode
    }

    /// Index of the joint with this name.
    pub fn find(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    /// `true` when `joint` is `ancestor` or one of its descendants (walks up the parents).
    pub fn in_group(&self, ancestor: usize, joint: usize) -> bool {
        let mut k = joint as i32;
        while k >= ancestor as i32 {
            if k == ancestor as i32 {
                return true;
            }
            k = self.parents[k as usize];
        }
        false
    }

    /// A pose holding the rest transforms.
    pub fn rest_pose(&self) -> Pose {
        Pose {
            local: self.rest.clone(),
        }
    }

    /// Model matrices of `pose` (with this skeleton's scale mode) into `model`, after checking
    /// the lengths and that the pose is finite.
    pub fn model_matrices(&self, pose: &Pose, model: &mut [Affine3A]) -> Result<(), SkeletonError> {
        for (what, actual) in [
            ("pose transforms", pose.len()),
            ("model matrices", model.len()),
        ] {
            if actual != self.len() {
                return Err(SkeletonError::LengthMismatch {
                    what,
                    expected: self.len(),
                    actual,
                });
            }
        }
        if let Some(joint) = pose.local.iter().position(|x| !x.is_finite()) {
            return Err(SkeletonError::NonFinite { joint });
        }
        local_to_model(&self.parents, &pose.local, self.scale_mode, model);
        Ok(())
    }
}

/// Local transforms, one per joint of a skeleton: what sampling and blending write, and what
/// [`local_to_model`] reads.
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    /// Joint `i`'s transform relative to its parent.
    pub local: Vec<Transform>,
}

impl Pose {
    /// `joints` identity transforms.
    pub fn identity(joints: usize) -> Self {
        Self {
            local: vec![Transform::IDENTITY; joints],
        }
    }

    pub fn len(&self) -> usize {
        self.local.len()
    }

    pub fn is_empty(&self) -> bool {
        self.local.is_empty()
    }
}
