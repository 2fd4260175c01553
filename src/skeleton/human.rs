//! A built-in character that needs no asset file: a procedural simple human (21 joints, one box
//! per joint) and five clips defined in code: idle, walk, run, wave and arm circles. Also the 60-joint
//! benchmark humanoid.
//!
//! The figure faces +z with its left side at +x; limbs hang along −y from their pivots, so a
//! positive angle about x swings a limb backwards and bends a knee. Joints are listed depth-first,
//! so each joint's group (itself and its descendants) is a contiguous range of the array.

use super::clip::{JointTracks, RawClip};
use super::hierarchy::{Skeleton, Transform};
use crate::fixtures::Rng;
use crate::transform::JointShape;
use crate::Valid;
use glam::{EulerRot, Quat, Vec3};
use std::f32::consts::TAU;

const SKIN: Vec3 = Vec3::new(0.85, 0.62, 0.48);
const SHIRT: Vec3 = Vec3::new(0.20, 0.45, 0.80);
const TROUSERS: Vec3 = Vec3::new(0.25, 0.25, 0.35);
const SHOES: Vec3 = Vec3::new(0.12, 0.10, 0.10);

/// `(name, parent, pivot in the parent's frame, box centre, box half-extents, colour)`.
type JointRow = (&'static str, i32, [f32; 3], [f32; 3], [f32; 3], Vec3);

const JOINTS: [JointRow; 21] = [
    (
        "pelvis",
        -1,
        [0.0, 0.95, 0.0],
        [0.0, 0.0, 0.0],
        [0.15, 0.07, 0.09],
        TROUSERS,
    ),
    (
        "spine",
        0,
        [0.0, 0.08, 0.0],
        [0.0, 0.1, 0.0],
        [0.13, 0.1, 0.08],
        SHIRT,
    ),
    (
        "chest",
        1,
        [0.0, 0.2, 0.0],
        [0.0, 0.14, 0.0],
        [0.17, 0.14, 0.1],
        SHIRT,
    ),
    (
        "neck",
        2,
        [0.0, 0.3, 0.0],
        [0.0, 0.05, 0.0],
        [0.04, 0.05, 0.04],
        SKIN,
    ),
    (
        "head",
        3,
        [0.0, 0.1, 0.0],
        [0.0, 0.11, 0.01],
        [0.09, 0.11, 0.1],
        SKIN,
    ),
    (
        "clavicle.L",
        2,
        [0.04, 0.25, 0.0],
        [0.07, 0.0, 0.0],
        [0.07, 0.03, 0.03],
        SHIRT,
    ),
    (
        "upper_arm.L",
        5,
        [0.15, 0.0, 0.0],
        [0.0, -0.14, 0.0],
        [0.045, 0.14, 0.045],
        SHIRT,
    ),
    (
        "forearm.L",
        6,
        [0.0, -0.28, 0.0],
        [0.0, -0.13, 0.0],
        [0.04, 0.13, 0.04],
        SKIN,
    ),
    (
        "hand.L",
        7,
        [0.0, -0.26, 0.0],
        [0.0, -0.07, 0.0],
        [0.035, 0.07, 0.02],
        SKIN,
    ),
    (
        "clavicle.R",
        2,
        [-0.04, 0.25, 0.0],
        [-0.07, 0.0, 0.0],
        [0.07, 0.03, 0.03],
        SHIRT,
    ),
    (
        "upper_arm.R",
        9,
        [-0.15, 0.0, 0.0],
        [0.0, -0.14, 0.0],
        [0.045, 0.14, 0.045],
        SHIRT,
    ),
    (
        "forearm.R",
        10,
        [0.0, -0.28, 0.0],
        [0.0, -0.13, 0.0],
        [0.04, 0.13, 0.04],
        SKIN,
    ),
    (
        "hand.R",
        11,
        [0.0, -0.26, 0.0],
        [0.0, -0.07, 0.0],
        [0.035, 0.07, 0.02],
        SKIN,
    ),
    (
        "thigh.L",
        0,
        [0.1, -0.05, 0.0],
        [0.0, -0.21, 0.0],
        [0.065, 0.21, 0.065],
        TROUSERS,
    ),
    (
        "shin.L",
        13,
        [0.0, -0.42, 0.0],
        [0.0, -0.21, 0.0],
        [0.055, 0.21, 0.055],
        TROUSERS,
    ),
    (
        "foot.L",
        14,
        [0.0, -0.42, 0.0],
        [0.0, -0.03, 0.04],
        [0.05, 0.03, 0.08],
        SHOES,
    ),
    (
        "toe.L",
        15,
        [0.0, -0.06, 0.12],
        [0.0, 0.0, 0.03],
        [0.05, 0.02, 0.03],
        SHOES,
    ),
    (
        "thigh.R",
        0,
        [-0.1, -0.05, 0.0],
        [0.0, -0.21, 0.0],
        [0.065, 0.21, 0.065],
        TROUSERS,
    ),
    (
        "shin.R",
        17,
        [0.0, -0.42, 0.0],
        [0.0, -0.21, 0.0],
        [0.055, 0.21, 0.055],
        TROUSERS,
    ),
    (
        "foot.R",
        18,
        [0.0, -0.42, 0.0],
        [0.0, -0.03, 0.04],
        [0.05, 0.03, 0.08],
        SHOES,
    ),
    (
        "toe.R",
        19,
        [0.0, -0.06, 0.12],
        [0.0, 0.0, 0.03],
        [0.05, 0.02, 0.03],
        SHOES,
    ),
];

/// The simple human's skeleton (rest pose: standing, arms down) and one box per joint.
pub fn simple_human() -> (Skeleton, Vec<JointShape>) {
    let names = JOINTS.iter().map(|j| j.0.to_string()).collect();
    let parents = JOINTS.iter().map(|j| j.1).collect();
    let rest = JOINTS
        .iter()
        .map(|j| Transform::from_translation(Vec3::from_array(j.2)))
        .collect();
    let skeleton =
        Skeleton::new(names, parents, rest).valid("the built-in human is a valid skeleton");
    let shapes = JOINTS
        .iter()
        .map(|j| JointShape {
            center: Vec3::from_array(j.3),
            half_extents: Vec3::from_array(j.4),
            color: j.5,
        })
        .collect();
    (skeleton, shapes)
}

/// The built-in clips' names, in the order of [`clip`].
pub const CLIP_NAMES: [&str; 5] = ["idle", "walk", "run", "wave", "arm circles"];

/// What one clip does at a phase `φ ∈ [0, 2π]`: Euler angles (x, y, z, radians, applied as in
/// lesson 01) per joint name, and the pelvis's offset from its rest position.
struct Motion<'a> {
    angles: Vec<(&'a str, Vec3)>,
    pelvis_offset: Vec3,
}

fn idle(phi: f32) -> Motion<'static> {
    let (s, c) = phi.sin_cos();
    Motion {
        angles: vec![
            ("spine", Vec3::new(0.03 * s, 0.0, 0.0)),
            ("chest", Vec3::new(0.04 * s, 0.05 * c, 0.0)),
            ("head", Vec3::new(-0.05 * c, 0.35 * s, 0.0)),
            ("upper_arm.L", Vec3::new(0.05 * c, 0.0, 0.12)),
            ("upper_arm.R", Vec3::new(-0.05 * c, 0.0, -0.12)),
            ("forearm.L", Vec3::new(-0.25 - 0.05 * s, 0.0, 0.0)),
            ("forearm.R", Vec3::new(-0.25 + 0.05 * s, 0.0, 0.0)),
            ("thigh.L", Vec3::new(0.0, 0.0, 0.04)),
            ("thigh.R", Vec3::new(0.0, 0.0, -0.04)),
        ],
        pelvis_offset: Vec3::new(0.01 * s, -0.01 + 0.005 * c, 0.0),
    }
}

/// A gait: `stride` (thigh swing, rad), `knee` (bend in swing), `arm` (swing), `lean` (spine
/// forward), `bob` (pelvis height), `elbow` (forearm bend).
fn gait(
    phi: f32,
    stride: f32,
    knee: f32,
    arm: f32,
    lean: f32,
    bob: f32,
    elbow: f32,
) -> Motion<'static> {
    let (s, c) = phi.sin_cos();
    // The left leg moves forwards while cos φ > 0; its knee bends then.
    let knee_l = 0.1 + knee * c.max(0.0);
    let knee_r = 0.1 + knee * (-c).max(0.0);
    let thigh_l = -stride * s;
    let thigh_r = stride * s;
    Motion {
        angles: vec![
            ("pelvis", Vec3::new(0.0, 0.12 * s, 0.0)),
            ("spine", Vec3::new(lean, -0.08 * s, 0.0)),
            ("chest", Vec3::new(0.5 * lean, -0.1 * s, 0.0)),
            ("head", Vec3::new(-1.2 * lean, 0.05 * s, 0.0)),
            ("upper_arm.L", Vec3::new(arm * s, 0.0, 0.08)),
            ("upper_arm.R", Vec3::new(-arm * s, 0.0, -0.08)),
            (
                "forearm.L",
                Vec3::new(-elbow - 0.2 * (-s).max(0.0), 0.0, 0.0),
            ),
            ("forearm.R", Vec3::new(-elbow - 0.2 * s.max(0.0), 0.0, 0.0)),
            ("thigh.L", Vec3::new(thigh_l, 0.0, 0.0)),
            ("thigh.R", Vec3::new(thigh_r, 0.0, 0.0)),
            ("shin.L", Vec3::new(knee_l, 0.0, 0.0)),
            ("shin.R", Vec3::new(knee_r, 0.0, 0.0)),
            // Keep the soles roughly level: undo most of the leg's swing at the ankle.
            ("foot.L", Vec3::new(-0.7 * (thigh_l + knee_l), 0.0, 0.0)),
            ("foot.R", Vec3::new(-0.7 * (thigh_r + knee_r), 0.0, 0.0)),
        ],
        pelvis_offset: Vec3::new(0.0, -bob + bob * (2.0 * phi).cos(), 0.0),
    }
}

fn wave(phi: f32) -> Motion<'static> {
    let (s, c) = phi.sin_cos();
    let side = (2.0 * phi).sin();
    Motion {
        angles: vec![
            ("chest", Vec3::new(0.0, -0.08, 0.04)),
            ("head", Vec3::new(0.0, -0.25, -0.1 + 0.05 * c)),
            ("clavicle.R", Vec3::new(0.0, 0.0, -0.25)),
            ("upper_arm.R", Vec3::new(0.0, 0.0, -2.3 - 0.1 * s)),
            ("forearm.R", Vec3::new(0.0, 0.0, -0.6 + 0.55 * side)),
            ("hand.R", Vec3::new(0.0, 0.0, 0.25 * side)),
            ("upper_arm.L", Vec3::new(0.05 * s, 0.0, 0.1)),
            ("forearm.L", Vec3::new(-0.2, 0.0, 0.0)),
        ],
        pelvis_offset: Vec3::ZERO,
    }
}

/// Both arms turn full circles about x, half a turn apart (a windmill): large angles between keys,
/// where nlerp and slerp visibly differ.
fn arm_circles(phi: f32) -> Motion<'static> {
    Motion {
        angles: vec![
            ("upper_arm.L", Vec3::new(-phi, 0.0, 0.15)),
            (
                "upper_arm.R",
                Vec3::new(-phi - std::f32::consts::PI, 0.0, -0.15),
            ),
            ("chest", Vec3::new(0.0, 0.1 * phi.sin(), 0.0)),
        ],
        pelvis_offset: Vec3::ZERO,
    }
}

/// `(duration in seconds, number of keys)` of each built-in clip.
const CLIP_TIMING: [(f32, usize); 5] = [(3.0, 7), (1.0, 9), (0.7, 9), (2.0, 9), (2.0, 9)];

/// Built-in clip number `index` ([`CLIP_NAMES`]) for [`simple_human`]'s skeleton, or `None`.
///
/// Each is one looping cycle keyed at evenly spaced times; the last key (at the duration) equals
/// the first, so the loop is seamless. Only the joints that move get a rotation channel; the
/// pelvis also gets a translation channel.
pub fn clip(skeleton: &Skeleton, index: usize) -> Option<RawClip> {
    let (_, keys) = *CLIP_TIMING.get(index)?;
    clip_with_keys(skeleton, index, keys)
}

/// The most keys per cycle [`clip_with_keys`] accepts.
pub const MAX_KEYS_PER_CYCLE: usize = 1000;

/// Built-in clip `index` keyed `keys` times per cycle (at least 2, at most
/// [`MAX_KEYS_PER_CYCLE`]), to see what fewer or more keys do. `None` outside those ranges.
pub fn clip_with_keys(skeleton: &Skeleton, index: usize, keys: usize) -> Option<RawClip> {
    let (duration, _) = *CLIP_TIMING.get(index)?;
    if !(2..=MAX_KEYS_PER_CYCLE).contains(&keys) {
        return None;
    }
    let motion = |phi: f32| match index {
        0 => idle(phi),
        1 => gait(phi, 0.45, 0.75, 0.35, 0.05, 0.02, 0.3),
        2 => gait(phi, 0.8, 1.4, 0.6, 0.22, 0.04, 1.3),
        3 => wave(phi),
        _ => arm_circles(phi),
    };
    let times: Vec<f32> = (0..keys)
        .map(|k| duration * k as f32 / (keys - 1) as f32)
        .collect();
    let motions: Vec<Motion> = (0..keys)
        .map(|k| motion(TAU * k as f32 / (keys - 1) as f32))
        .collect();
    let mut tracks = vec![JointTracks::default(); skeleton.len()];
    for (name, _) in &motions[0].angles {
        let Some(j) = skeleton.find(name) else {
            continue;
        };
        let rest = skeleton.rest()[j].rotation;
        let keys: Vec<Quat> = motions
            .iter()
            .map(|m| {
                let e = m
                    .angles
                    .iter()
                    .find(|a| a.0 == *name)
                    .map_or(Vec3::ZERO, |a| a.1);
                rest * Quat::from_euler(EulerRot::XYZ, e.x, e.y, e.z)
            })
            .collect();
        tracks[j].rotation = JointTracks::rotation_track(times.clone(), &keys).ok();
    }
    let pelvis = skeleton.rest()[0].translation;
    let offsets: Vec<Vec3> = motions.iter().map(|m| pelvis + m.pelvis_offset).collect();
    tracks[0].translation = crate::curves::Track::new(times.clone(), offsets).ok();
    RawClip::new(CLIP_NAMES[index], duration, true, tracks).ok()
}

/// The benchmark input: a 60-joint humanoid (the simple human plus three-joint fingers, a jaw,
/// eyes and twist joints; parents before children, not depth-first) and a one-second looping clip
/// with 30 keys on every translation, rotation and scale channel (smooth random motion).
pub fn benchmark_humanoid(rng: &mut Rng) -> (Skeleton, RawClip) {
    let (base, _) = simple_human();
    let mut names: Vec<String> = base.names().to_vec();
    let mut parents: Vec<i32> = base.parents().to_vec();
    let mut rest: Vec<Transform> = base.rest().to_vec();
    let mut add = |name: String, parent: usize, offset: Vec3| {
        names.push(name);
        parents.push(parent as i32);
        rest.push(Transform::from_translation(offset));
        names.len() - 1
    };
    for (hand, side) in [(8usize, "L"), (12, "R")] {
        for finger in 0..5 {
            let x = (finger as f32 - 2.0) * 0.015;
            let mut parent = hand;
            for segment in 0..3 {
                let drop = if segment == 0 { -0.12 } else { -0.03 };
                parent = add(
                    format!("finger{finger}_{segment}.{side}"),
                    parent,
                    Vec3::new(x, drop, 0.0),
                );
            }
        }
    }
    add("jaw".into(), 4, Vec3::new(0.0, 0.03, 0.04));
    add("eye.L".into(), 4, Vec3::new(0.035, 0.12, 0.08));
    add("eye.R".into(), 4, Vec3::new(-0.035, 0.12, 0.08));
    for (limb, name) in [
        (6usize, "upper_arm_twist.L"),
        (10, "upper_arm_twist.R"),
        (7, "forearm_twist.L"),
        (11, "forearm_twist.R"),
        (13, "thigh_twist.L"),
        (17, "thigh_twist.R"),
    ] {
        add(name.into(), limb, Vec3::new(0.0, -0.12, 0.0));
    }
    let skeleton = Skeleton::new(names, parents, rest).valid("a valid benchmark skeleton");
    const KEYS: usize = 30;
    let times: Vec<f32> = (0..KEYS).map(|k| k as f32 / (KEYS - 1) as f32).collect();
    let tracks = skeleton
        .rest()
        .iter()
        .map(|x| {
            let (a, f) = (rng.vec3(-0.5, 0.5), rng.vec3(1.0, 3.0));
            let at = |k: usize| (f * TAU * times[k]).to_array().map(f32::sin);
            let rotations: Vec<Quat> = (0..KEYS)
                .map(|k| {
                    let s = Vec3::from_array(at(k)) * a;
                    Quat::from_euler(EulerRot::XYZ, s.x, s.y, s.z)
                })
                .collect();
            let translations = (0..KEYS)
                .map(|k| x.translation + Vec3::from_array(at(k)) * 0.01)
                .collect();
            let scales = (0..KEYS)
                .map(|k| Vec3::ONE + Vec3::from_array(at(k)) * 0.05)
                .collect();
            JointTracks {
                translation: crate::curves::Track::new(times.clone(), translations).ok(),
                rotation: JointTracks::rotation_track(times.clone(), &rotations).ok(),
                scale: crate::curves::Track::new(times.clone(), scales).ok(),
            }
        })
        .collect();
    let clip = RawClip::new("benchmark", 1.0, true, tracks).valid("a valid benchmark clip");
    (skeleton, clip)
}

/// The walk (`index` 1) or the run (2) travelling forwards, keyed `keys` times per cycle: the
/// pelvis's translation gets a horizontal offset that keeps the stance foot still.
/// ```text
/// between keys k and k+1, with the stance foot the lower ankle at the segment's middle:
/// root[k+1] = root[k] − (foot[k+1] − foot[k])     (x and z; the height is the clip's)
/// ```
/// Both x and z: the pelvis's yaw swings the planted foot sideways as well as back, so the
/// character travels exactly as far as its planted foot pushes it back (no sliding at the keys).
/// The clip records that stance foot as its [`super::Contact`]s (left foot first, then right):
/// each foot is planted over the segments where it is the lower one, about half the cycle, one
/// foot at a time. The last key's root is one cycle's travel ahead of the first: the clip no
/// longer loops seamlessly by itself; [`super::RootMotion`] makes it. `None` for other clips or
/// a bad key count.
pub fn travelling_clip(skeleton: &Skeleton, index: usize, keys: usize) -> Option<RawClip> {
    if !(1..=2).contains(&index) {
        return None;
    }
    let raw = clip_with_keys(skeleton, index, keys)?;
    let clip = super::clip::Clip::from_raw(&raw, skeleton).ok()?;
    let feet = [skeleton.find("foot.L")?, skeleton.find("foot.R")?];
    let n = skeleton.len();
    let mut pose = skeleton.rest_pose();
    let mut model = vec![glam::Affine3A::IDENTITY; n];
    let mut ankles = Vec::with_capacity(keys);
    for k in 0..keys {
        for j in 0..n {
            pose.local[j] = clip.key(k, j);
        }
        super::hierarchy::local_to_model(
            skeleton.parents(),
            &pose.local,
            skeleton.scale_mode(),
            &mut model,
        );
        ankles.push(feet.map(|f| Vec3::from(model[f].translation)));
    }
    // Compensating z alone left the walk's planted foot sliding 5 cm in 1.5 s, sideways.
    let mut offset = vec![Vec3::ZERO; keys];
    // stance[k]: the foot planted from key k to key k + 1 (0 left, 1 right).
    let mut stance = Vec::with_capacity(keys - 1);
    for k in 0..keys - 1 {
        let height = |f: usize| ankles[k][f].y + ankles[k + 1][f].y;
        let foot = if height(0) <= height(1) { 0 } else { 1 };
        let step = ankles[k + 1][foot] - ankles[k][foot];
        offset[k + 1] = offset[k] - Vec3::new(step.x, 0.0, step.z);
        stance.push(foot);
    }
    let mut tracks = raw.joints().to_vec();
    let root = tracks[0].translation.as_ref()?;
    let values: Vec<Vec3> = root
        .values()
        .iter()
        .zip(&offset)
        .map(|(v, d)| *v + *d)
        .collect();
    tracks[0].translation = crate::curves::Track::new(root.times().to_vec(), values).ok();
    let name = if index == 1 {
        "walk (travelling)"
    } else {
        "run (travelling)"
    };
    // The foot whose step the root cancels is the planted one: record it with the clip, as
    // stance intervals (runs of segments) per foot, so no one has to guess it from heights.
    let times = clip.key_times();
    let contacts = [0, 1]
        .into_iter()
        .map(|foot| {
            let mut intervals: Vec<[f32; 2]> = Vec::new();
            for (k, &planted) in stance.iter().enumerate() {
                if planted != foot {
                    continue;
                }
                match intervals.last_mut() {
                    Some(last) if last[1] == times[k] => last[1] = times[k + 1],
                    _ => intervals.push([times[k], times[k + 1]]),
                }
            }
            super::clip::Contact::new(feet[foot], intervals)
        })
        .collect::<Result<Vec<_>, _>>()
        .ok()?;
    RawClip::new(name, raw.duration_sec(), true, tracks)
        .ok()?
        .with_contacts(contacts)
        .ok()
}
