//! Transforms and hierarchies: homogeneous coordinates, local matrices, world = parent · local.
//!
//! A 4×4 affine matrix acts on homogeneous coordinates. A **point** `(x, y, z, 1)` is moved by the
//! translation column; a **direction** `(x, y, z, 0)` is not:
//! ```text
//! ⎡ A  t ⎤ ⎡ p ⎤   ⎡ A·p + t ⎤        ⎡ A  t ⎤ ⎡ v ⎤   ⎡ A·v ⎤
//! ⎣ 0  1 ⎦ ⎣ 1 ⎦ = ⎣    1    ⎦        ⎣ 0  1 ⎦ ⎣ 0 ⎦ = ⎣  0  ⎦
//! ```
//! A joint hierarchy stores, for each joint, the index of its parent (root: `-1`), parents first.
//! Its world matrices come from one forward loop: `world[i] = world[parent[i]] · local[i]`.
//!
//! Lesson: `lessons/01-transforms`.

use glam::{Mat4, Vec3, Vec4};
use std::fmt;

/// Lifts a point to homogeneous coordinates (`w = 1`): translations move it.
pub fn point(p: Vec3) -> Vec4 {
    p.extend(1.0)
}

/// Lifts a direction to homogeneous coordinates (`w = 0`): translations leave it alone.
pub fn direction(v: Vec3) -> Vec4 {
    v.extend(0.0)
}

/// Local matrix of a joint from its translation and Euler angles.
/// ```text
/// L = T(translation) · Rx(θx) · Ry(θy) · Rz(θz)
/// ```
/// Angles in radians. Applied to a point, `Rz` acts first, then `Ry`, then `Rx`, then the
/// translation: the rotations turn the shape about its own pivot, which the translation then
/// places in the parent's frame. This is the intrinsic X-Y'-Z'' order (equivalently the extrinsic
/// z-y-x order). Scale is deliberately absent: see [`ScaleMode`].
pub fn local_matrix(translation: Vec3, euler_xyz_rad: Vec3) -> Mat4 {
    Mat4::from_translation(translation)
        * Mat4::from_rotation_x(euler_xyz_rad.x)
        * Mat4::from_rotation_y(euler_xyz_rad.y)
        * Mat4::from_rotation_z(euler_xyz_rad.z)
}

/// World matrices of a hierarchy whose parents come before their children.
/// ```text
/// world[i] = local[i]                    if parents[i] = −1 (a root)
/// world[i] = world[parents[i]] · local[i] otherwise
/// ```
/// One forward loop suffices because `parents[i] < i`: a parent's world matrix is final before any
/// child reads it. Writes into the caller's `world` buffer; allocates nothing.
///
/// The inputs must satisfy what [`Hierarchy::new`] checks; this hot function only
/// `debug_assert`s them.
pub fn world_matrices(parents: &[i32], local: &[Mat4], world: &mut [Mat4]) {
    debug_assert_eq!(parents.len(), local.len());
    debug_assert_eq!(parents.len(), world.len());
    for i in 0..parents.len() {
        let parent = parents[i];
        world[i] = if parent < 0 {
            local[i]
        } else {
            debug_assert!(
                (parent as usize) < i,
                "parent {parent} of joint {i} comes after it"
            );
            world[parent as usize] * local[i]
        };
    }
}

/// Whether a joint's scale reaches its children.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ScaleMode {
    /// Scale only sizes the joint's own shape, at draw time: `draw[i] = world[i] · S[i]`, and
    /// children see an unscaled frame. Lengthening the upper arm does not squash the hand.
    /// This is the choice of most animation rigs (and of the course material).
    NotInherited,
    /// Scale is part of the local matrix, `local[i] = T · R · S`, so every descendant inherits it,
    /// and a non-uniform scale followed by a child's rotation shears the child.
    Inherited,
}

/// Translation, Euler angles (radians, order of [`local_matrix`]) and scale of one joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalTransform {
    /// Position of the joint's pivot in its parent's frame, in metres.
    pub translation: Vec3,
    /// Rotation about the pivot, radians, applied z first (see [`local_matrix`]).
    pub euler_xyz_rad: Vec3,
    /// Scale along the joint's own axes.
    pub scale: Vec3,
}

impl LocalTransform {
    /// A transform with the given translation, no rotation and unit scale.
    pub fn from_translation(translation: Vec3) -> Self {
        Self {
            translation,
            euler_xyz_rad: Vec3::ZERO,
            scale: Vec3::ONE,
        }
    }
}

/// Why a list of parents is not a valid hierarchy.
#[derive(Clone, Debug, PartialEq)]
pub enum HierarchyError {
    /// No joints at all.
    Empty,
    /// `parents[joint]` is neither −1 nor an earlier joint's index.
    ParentNotBefore { joint: usize, parent: i32 },
    /// Two per-joint arrays have different lengths.
    LengthMismatch {
        what: &'static str,
        expected: usize,
        actual: usize,
    },
    /// A transform contains NaN or an infinity.
    NonFinite { joint: usize },
}

impl fmt::Display for HierarchyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Empty => write!(f, "the hierarchy has no joints"),
            Self::ParentNotBefore { joint, parent } => write!(
                f,
                "joint {joint} has parent {parent}, but a parent must be -1 (root) or a joint listed \
                 before its child (0..{joint})"
            ),
            Self::LengthMismatch { what, expected, actual } => {
                write!(f, "expected {expected} {what} (one per joint), got {actual}")
            }
            Self::NonFinite { joint } => {
                write!(f, "the transform of joint {joint} contains NaN or an infinite value")
            }
        }
    }
}

impl std::error::Error for HierarchyError {}

/// A validated joint hierarchy: names and parent indices, parents first.
#[derive(Clone, Debug, PartialEq)]
pub struct Hierarchy {
    names: Vec<String>,
    parents: Vec<i32>,
}

impl Hierarchy {
    /// Checks that every parent is −1 or an earlier index and that there is one name per joint.
    pub fn new(names: Vec<String>, parents: Vec<i32>) -> Result<Self, HierarchyError> {
        if parents.is_empty() {
            return Err(HierarchyError::Empty);
        }
        if names.len() != parents.len() {
            return Err(HierarchyError::LengthMismatch {
                what: "names",
                expected: parents.len(),
                actual: names.len(),
            });
        }
        for (joint, &parent) in parents.iter().enumerate() {
            if parent < -1 || parent >= joint as i32 {
                return Err(HierarchyError::ParentNotBefore { joint, parent });
            }
        }
        Ok(Self { names, parents })
    }

    pub fn len(&self) -> usize {
        self.parents.len()
    }

    pub fn is_empty(&self) -> bool {
        self.parents.is_empty()
    }

    pub fn parents(&self) -> &[i32] {
        &self.parents
    }

    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Index of the joint with this name.
    pub fn find(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    /// Local and world matrices of a pose, and the matrices to draw each joint's shape with.
    ///
    /// `local` and `world` receive `T · R` (or `T · R · S` with [`ScaleMode::Inherited`]) and its
    /// accumulation; `draw` receives `world · S` (or `world` when scale is inherited). All three
    /// buffers are the caller's, one entry per joint.
    ///
    /// # Errors
    /// A length mismatch or a non-finite transform.
    pub fn pose(
        &self,
        transforms: &[LocalTransform],
        mode: ScaleMode,
        local: &mut [Mat4],
        world: &mut [Mat4],
        draw: &mut [Mat4],
    ) -> Result<(), HierarchyError> {
        let n = self.len();
        for (what, actual) in [
            ("transforms", transforms.len()),
            ("local matrices", local.len()),
            ("world matrices", world.len()),
            ("draw matrices", draw.len()),
        ] {
            if actual != n {
                return Err(HierarchyError::LengthMismatch {
                    what,
                    expected: n,
                    actual,
                });
            }
        }
        for (joint, x) in transforms.iter().enumerate() {
            let finite =
                x.translation.is_finite() && x.euler_xyz_rad.is_finite() && x.scale.is_finite();
            if !finite {
                return Err(HierarchyError::NonFinite { joint });
            }
        }
        for (l, x) in local.iter_mut().zip(transforms) {
            *l = local_matrix(x.translation, x.euler_xyz_rad);
            if mode == ScaleMode::Inherited {
                *l *= Mat4::from_scale(x.scale);
            }
        }
        world_matrices(&self.parents, local, world);
        for ((d, w), x) in draw.iter_mut().zip(world.iter()).zip(transforms) {
            *d = match mode {
                ScaleMode::NotInherited => *w * Mat4::from_scale(x.scale),
                ScaleMode::Inherited => *w,
            };
        }
        Ok(())
    }
}

/// One box of the lesson's figure: the joint it belongs to and where it sits in that joint's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointShape {
    /// Half-size of the box along the joint's axes, metres.
    pub half_extents: Vec3,
    /// Centre of the box in the joint's frame (limbs hang below their pivot).
    pub center: Vec3,
    /// Linear RGB colour.
    pub color: Vec3,
}

/// A simple human made of boxes: the hierarchy, its rest pose, and one box per joint.
///
/// Joints pivot where a real joint would (shoulder, elbow, hip, knee), and limbs hang along −Y
/// from their pivot, so rotating `x` swings a limb forwards and backwards.
pub fn simple_human() -> (Hierarchy, Vec<LocalTransform>, Vec<JointShape>) {
    let skin = Vec3::new(0.85, 0.62, 0.48);
    let shirt = Vec3::new(0.20, 0.45, 0.80);
    let trousers = Vec3::new(0.25, 0.25, 0.35);
    // (name, parent, pivot in parent frame, box half-extents, box centre, colour)
    let joints: [(&str, i32, Vec3, Vec3, Vec3, Vec3); 11] = [
        (
            "pelvis",
            -1,
            Vec3::new(0.0, 0.9, 0.0),
            Vec3::new(0.17, 0.1, 0.1),
            Vec3::ZERO,
            trousers,
        ),
        (
            "chest",
            0,
            Vec3::new(0.0, 0.1, 0.0),
            Vec3::new(0.2, 0.25, 0.11),
            Vec3::new(0.0, 0.25, 0.0),
            shirt,
        ),
        (
            "head",
            1,
            Vec3::new(0.0, 0.52, 0.0),
            Vec3::new(0.1, 0.12, 0.1),
            Vec3::new(0.0, 0.14, 0.0),
            skin,
        ),
        (
            "upper_arm.L",
            1,
            Vec3::new(0.26, 0.45, 0.0),
            Vec3::new(0.05, 0.15, 0.05),
            Vec3::new(0.0, -0.15, 0.0),
            shirt,
        ),
        (
            "forearm.L",
            3,
            Vec3::new(0.0, -0.3, 0.0),
            Vec3::new(0.045, 0.14, 0.045),
            Vec3::new(0.0, -0.14, 0.0),
            skin,
        ),
        (
            "upper_arm.R",
            1,
            Vec3::new(-0.26, 0.45, 0.0),
            Vec3::new(0.05, 0.15, 0.05),
            Vec3::new(0.0, -0.15, 0.0),
            shirt,
        ),
        (
            "forearm.R",
            5,
            Vec3::new(0.0, -0.3, 0.0),
            Vec3::new(0.045, 0.14, 0.045),
            Vec3::new(0.0, -0.14, 0.0),
            skin,
        ),
        (
            "thigh.L",
            0,
            Vec3::new(0.1, -0.08, 0.0),
            Vec3::new(0.07, 0.21, 0.07),
            Vec3::new(0.0, -0.21, 0.0),
            trousers,
        ),
        (
            "shin.L",
            7,
            Vec3::new(0.0, -0.42, 0.0),
            Vec3::new(0.06, 0.2, 0.06),
            Vec3::new(0.0, -0.2, 0.0),
            trousers,
        ),
        (
            "thigh.R",
            0,
            Vec3::new(-0.1, -0.08, 0.0),
            Vec3::new(0.07, 0.21, 0.07),
            Vec3::new(0.0, -0.21, 0.0),
            trousers,
        ),
        (
            "shin.R",
            9,
            Vec3::new(0.0, -0.42, 0.0),
            Vec3::new(0.06, 0.2, 0.06),
            Vec3::new(0.0, -0.2, 0.0),
            trousers,
        ),
    ];
    let names = joints.iter().map(|j| j.0.to_string()).collect();
    let parents = joints.iter().map(|j| j.1).collect();
    let hierarchy =
        Hierarchy::new(names, parents).expect("the built-in figure is a valid hierarchy");
    let rest = joints
        .iter()
        .map(|j| LocalTransform::from_translation(j.2))
        .collect();
    let shapes = joints
        .iter()
        .map(|j| JointShape {
            half_extents: j.3,
            center: j.4,
            color: j.5,
        })
        .collect();
    (hierarchy, rest, shapes)
}

/// Joint angles of a procedural walk for [`simple_human`], `time_sec` into a cycle of `period_sec`.
///
/// Legs swing opposite each other, arms opposite the legs; a knee bends only while its leg swings
/// forward. Writes the Euler angles (radians) into `euler_xyz_rad`, one per joint of the figure;
/// joints it does not animate keep their value.
pub fn walk_cycle(
    hierarchy: &Hierarchy,
    time_sec: f32,
    period_sec: f32,
    euler_xyz_rad: &mut [Vec3],
) {
    let phase = std::f32::consts::TAU * time_sec / period_sec.max(1e-3);
    let swing = phase.sin();
    let mut set = |name: &str, x: f32| {
        if let Some(i) = hierarchy.find(name) {
            if let Some(angles) = euler_xyz_rad.get_mut(i) {
                angles.x = x;
            }
        }
    };
    set("thigh.L", 0.5 * swing);
    set("thigh.R", -0.5 * swing);
    // Knees bend backwards (positive x) during the forward half of their leg's swing.
    set("shin.L", 0.7 * (phase + 0.6).cos().max(0.0));
    set(
        "shin.R",
        0.7 * (phase + 0.6 + std::f32::consts::PI).cos().max(0.0),
    );
    set("upper_arm.L", -0.4 * swing);
    set("upper_arm.R", 0.4 * swing);
    set("forearm.L", -0.3 - 0.2 * swing.max(0.0));
    set("forearm.R", -0.3 - 0.2 * (-swing).max(0.0));
}
