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
    // Just short of the end: a looping clip wraps its duration to 0.
    let at = |clip: &Clip| (phase * clip.duration_sec()).min(clip.duration_sec() * 0.999_999);
    a.sample(at(a), &mut cursors[0], out);
    b.sample(at(b), &mut cursors[1], scratch);
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
