//! Locomotion: synchronised blends of looping clips (normalised time) and root motion.
//!
//! A walk cycle of 1 s and a run cycle of 0.7 s cannot be crossfaded at the same clock time: the
//! legs would be at different points of their cycles and fight. Blending at the same **phase**
//! `φ = t / duration ∈ [0, 1)` of each cycle keeps them in step; the blended cycle lasts
//! `(1 − w) d_a + w d_b`.
//!
//! **Root motion**: a travelling clip moves its root joint forwards. Played as it is, the
//! character walks off and jumps back at every loop. Extracting the root's horizontal offset from
//! the pose each frame (the pose then walks on the spot) and moving the character by it instead
//! makes the travel continue across loops, and lets a game steer it.
//!
//! **Foot contacts**: which foot is planted is part of a locomotion clip ([`super::Contact`],
//! stance intervals in clip time). A blend's contacts follow its clips the way its pose does: at
//! the same phase when synchronised ([`synchronised_contacts`]), at each clip's own time
//! otherwise ([`blend_contacts`]), weighted like the poses.

use super::blend::crossfade_transform;
use super::clip::{Clip, ClipCursor};
use super::hierarchy::Pose;
use glam::Vec3;

/// The root joint's travel in a looping clip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RootMotion {
    /// The root's translation at the first key (model space).
    pub start: Vec3,
    /// The root's horizontal travel over one cycle (last key − first key, with y = 0).
    pub cycle_travel: Vec3,
    /// The clip's duration, seconds.
    pub duration_sec: f32,
}

fn horizontal(v: Vec3) -> Vec3 {
    Vec3::new(v.x, 0.0, v.z)
}

impl RootMotion {
    /// Reads the root joint's (joint 0) first and last keys of `clip`.
    pub fn from_clip(clip: &Clip) -> Self {
        let last = clip.key_times().len() - 1;
        let start = clip.key(0, 0).translation;
        let end = clip.key(last, 0).translation;
        Self {
            start,
            cycle_travel: horizontal(end - start),
            duration_sec: clip.duration_sec(),
        }
    }

    /// Average speed over a cycle, metres per second.
    pub fn speed(&self) -> f32 {
        self.cycle_travel.length() / self.duration_sec
    }

    /// Moves the root's horizontal offset from `start` out of `pose` (which then stays on the
    /// spot) and returns it:
    /// ```text
    /// d = (t_root − start) with y = 0,     t_root ← t_root − d
    /// ```
    pub fn extract(&self, pose: &mut Pose) -> Vec3 {
        let d = horizontal(pose.local[0].translation - self.start);
        pose.local[0].translation -= d;
        d
    }

    /// Where the character is after playing for `time_sec` from 0 (not wrapped), given the
    /// offset [`RootMotion::extract`] returned at that time:
    /// ```text
    /// position = ⌊time / duration⌋ · cycle_travel + d
    /// ```
    pub fn position(&self, time_sec: f32, d: Vec3) -> Vec3 {
        (time_sec / self.duration_sec).floor() * self.cycle_travel + d
    }
}

/// Samples two looping clips at the same normalised time and crossfades them with weight `w`
/// (0: all `a`, 1: all `b`):
/// ```text
/// t_a = φ · d_a,   t_b = φ · d_b,   pose = crossfade(a(t_a), b(t_b); w)
/// ```
/// `phase` is taken modulo 1. `scratch` receives clip `b`'s pose. Returns the blended horizontal
/// root offset of the two clips (each extracted from its own [`RootMotion`]) when `root_motion`
/// is given, leaving the pose on the spot; otherwise `Vec3::ZERO` and the pose keeps its root.
/// [`synchronised_contacts`] with the same `w` and `phase` says which feet are planted.
#[allow(clippy::too_many_arguments)]
pub fn sample_synchronised(
    a: &Clip,
    b: &Clip,
    w: f32,
    phase: f32,
    cursors: &mut [ClipCursor; 2],
    scratch: &mut Pose,
    root_motion: Option<[&RootMotion; 2]>,
    out: &mut Pose,
) -> Vec3 {
    let phase = phase.rem_euclid(1.0);
    let w = w.clamp(0.0, 1.0);
    a.sample(phase_time(a, phase), &mut cursors[0], out);
    b.sample(phase_time(b, phase), &mut cursors[1], scratch);
    let offset = match root_motion {
        Some([ra, rb]) => {
            let da = ra.extract(out);
            let db = rb.extract(scratch);
            da.lerp(db, w)
        }
        None => Vec3::ZERO,
    };
    for (x, y) in out.local.iter_mut().zip(&scratch.local) {
        *x = crossfade_transform(x, y, w);
    }
    offset
}

/// Clip time at `phase` ∈ [0, 1): just short of the end, since a looping clip wraps its duration
/// to 0.
fn phase_time(clip: &Clip, phase: f32) -> f32 {
    (phase * clip.duration_sec()).min(clip.duration_sec() * 0.999_999)
}

/// The ground contacts of a blend of clip `a` at `time_a` and clip `b` at `time_b` (seconds,
/// wrapped as sampling wraps them) with weight `w` of `b`: `out[i]` for clip `a`'s contact `i`,
/// matched in `b` by its joint (a joint `b` has no contact for counts as lifted there). The
/// clips' flags vote with the blend's weights:
/// ```text
/// planted_i = (1 − w) · [a: in contact at t_a] + w · [b: in contact at t_b] ≥ ½
/// ```
/// so the clip with more weight decides, and at `w = ½` a foot either clip plants is planted.
/// Fills `out[..a.contacts().len()]` (at most `out.len()`).
pub fn blend_contacts(a: &Clip, time_a: f32, b: &Clip, time_b: f32, w: f32, out: &mut [bool]) {
    let w = w.clamp(0.0, 1.0);
    for (i, slot) in out.iter_mut().enumerate().take(a.contacts().len()) {
        let joint = a.contacts()[i].joint();
        let in_a = if a.in_contact(i, time_a) {
            1.0 - w
        } else {
            0.0
        };
        let in_b = match b.contact_of(joint) {
            Some(k) if b.in_contact(k, time_b) => w,
            _ => 0.0,
        };
        *slot = in_a + in_b >= 0.5;
    }
}

/// The ground contacts of [`sample_synchronised`]'s blend at `phase`: [`blend_contacts`] with
/// both clips at the same normalised time,
/// ```text
/// t_a = φ · d_a,   t_b = φ · d_b
/// ```
/// so a walk and a run whose feet are planted over the same part of their cycles stay planted
/// together, whatever their durations.
pub fn synchronised_contacts(a: &Clip, b: &Clip, w: f32, phase: f32, out: &mut [bool]) {
    let phase = phase.rem_euclid(1.0);
    blend_contacts(a, phase_time(a, phase), b, phase_time(b, phase), w, out);
}

/// The blended cycle of two locomotion clips at weight `w`: duration (s), travel per cycle (m)
/// and speed (m/s).
/// ```text
/// d = (1 − w) d_a + w d_b,   T = (1 − w) T_a + w T_b,   v = T / d
/// ```
pub fn synchronised_cycle(a: &RootMotion, b: &RootMotion, w: f32) -> (f32, f32, f32) {
    let d = a.duration_sec + (b.duration_sec - a.duration_sec) * w;
    let travel = a.cycle_travel.length() + (b.cycle_travel.length() - a.cycle_travel.length()) * w;
    (d, travel, travel / d)
}

/// The weight that makes the synchronised blend move at `speed` m/s (clamped to the speeds of
/// the two clips): solves `v(w) = speed` for the formula of [`synchronised_cycle`],
/// ```text
/// w = (v d_a − T_a) / ((T_b − T_a) − v (d_b − d_a))
/// ```
pub fn weight_for_speed(a: &RootMotion, b: &RootMotion, speed: f32) -> f32 {
    let (ta, tb) = (a.cycle_travel.length(), b.cycle_travel.length());
    let (da, db) = (a.duration_sec, b.duration_sec);
    let denominator = (tb - ta) - speed * (db - da);
    if denominator.abs() < 1e-9 || !speed.is_finite() {
        return 0.0;
    }
    ((speed * da - ta) / denominator).clamp(0.0, 1.0)
}
