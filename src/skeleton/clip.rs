//! Clips: keys for each joint's translation, rotation and scale, in an editable form
//! ([`RawClip`], one [`Track`] per channel) and a compact runtime form ([`Clip`]).
//!
//! # Which form, and why two
//! The **editable** form is what an animator or an importer produces: each channel has its own
//! key times, and a channel without keys keeps the rest value. It reuses lesson 02's [`Track`]
//! (validation, segment cursor, Catmull-Rom tangents), so it is easy to read and to edit; but
//! sampling a 60-joint character walks 180 separate tracks, each with its own cursor and its own
//! small arrays scattered through memory.
//!
//! The **runtime** form ([`Clip::from_raw`]) is what the sampler reads every frame:
//! - one list of key times shared by every channel (the union of all the channels' times), so one
//!   cursor lookup per frame finds the segment for all joints at once;
//! - values stored **key-major**: key `k` of joint `j` is at `k · joints + j`, so the two keys a
//!   frame interpolates between are two contiguous runs of memory, read front to back;
//! - rotations hemisphere-aligned along time at build (`q_k · q_{k−1} ≥ 0`), so nlerp needs no
//!   sign test per sample; Catmull-Rom tangents precomputed for cubic interpolation.
//!
//! The price is memory when channels have different key times (every channel gets a key at every
//! time of the union). Building evaluates the editable clip at those times, so the runtime clip
//! passes through every key of every channel; between keys it is identical for step and linear
//! translation/scale and slerp rotation, and very close for nlerp and cubic when a channel gained
//! extra keys (the built-in clips key all channels at the same times, so for them the two forms
//! agree everywhere).

use core::fmt;

use super::hierarchy::{Pose, Skeleton, Transform};
use crate::curves::{cardinal_tangents, Cursor, Interpolation, Track, TrackError};
use crate::rotation::slerp;
use crate::Valid;
use glam::{Quat, Vec3, Vec4};

/// The most key times a runtime clip may have (after merging every channel's times).
pub const MAX_CLIP_KEYS: usize = 1 << 16;

/// How a clip fills the time between keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyInterpolation {
    /// Hold each key until the next one: the pose jumps at keys.
    Step,
    /// Straight lines for translation and scale; rotation by [`QuatInterpolation`].
    Linear,
    /// Catmull-Rom cubic segments (tangent = slope between the neighbouring keys); rotations are
    /// interpolated component-wise, then normalised.
    Cubic,
}

/// How linear interpolation moves between two rotation keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuatInterpolation {
    /// Normalised lerp: cheap (one square root), same path as slerp, but faster in the middle
    /// of a segment and slower at its ends.
    Nlerp,
    /// Spherical lerp: constant angular speed, costs trigonometry.
    Slerp,
}

/// What is wrong with a clip. Messages name the joint and channel.
#[derive(Clone, Debug, PartialEq)]
pub enum ClipError {
    /// The duration is not a finite number > 0.
    BadDuration { duration_sec: f32 },
    /// The clip has tracks for a different number of joints than the skeleton.
    JointCount { expected: usize, actual: usize },
    /// A channel's keys are invalid (see [`TrackError`]).
    Track {
        joint: usize,
        channel: &'static str,
        error: TrackError,
    },
    /// A key time lies outside `[0, duration]`.
    KeyOutsideDuration {
        joint: usize,
        channel: &'static str,
        time_sec: f32,
        duration_sec: f32,
    },
    /// A rotation key has zero length (it cannot be normalised).
    ZeroRotation { joint: usize, key: usize },
    /// More merged key times than [`MAX_CLIP_KEYS`].
    TooManyKeys { count: usize },
    /// A [`Contact`] is invalid: its joint is not in the clip, or an interval is empty, not
    /// finite, out of order or outside `[0, duration]`.
    BadContact { joint: usize, reason: String },
}

impl fmt::Display for ClipError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadDuration { duration_sec } => {
                write!(f, "the clip's duration must be a finite number > 0 s, got {duration_sec}")
            }
            Self::JointCount { expected, actual } => write!(
                f,
                "the clip has tracks for {actual} joints but the skeleton has {expected}"
            ),
            Self::Track { joint, channel, error } => {
                write!(f, "joint {joint}, {channel} keys: {error}")
            }
            Self::KeyOutsideDuration { joint, channel, time_sec, duration_sec } => write!(
                f,
                "joint {joint}, {channel}: a key at {time_sec} s lies outside the clip [0, {duration_sec}] s"
            ),
            Self::ZeroRotation { joint, key } => {
                write!(f, "joint {joint}, rotation key {key} has zero length: not a rotation")
            }
            Self::TooManyKeys { count } => {
                write!(f, "the clip has {count} key times; at most {MAX_CLIP_KEYS} are allowed")
            }
            Self::BadContact { joint, reason } => write!(f, "contact of joint {joint}: {reason}"),
        }
    }
}

impl std::error::Error for ClipError {}

/// The editable channels of one joint. A missing channel keeps the skeleton's rest value.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JointTracks {
    /// Translation keys, metres in the parent's frame.
    pub translation: Option<Track<Vec3>>,
    /// Rotation keys, unit quaternions stored as `(x, y, z, w)`.
    pub rotation: Option<Track<Vec4>>,
    /// Scale keys.
    pub scale: Option<Track<Vec3>>,
}

impl JointTracks {
    /// Rotation keys as a track (quaternions as `(x, y, z, w)`); normalised and aligned later by
    /// [`RawClip::new`].
    pub fn rotation_track(times: Vec<f32>, keys: &[Quat]) -> Result<Track<Vec4>, TrackError> {
        Track::new(times, keys.iter().map(|&q| Vec4::from(q)).collect())
    }
}

/// When one joint (a foot) is on the ground: its stance intervals in clip time, part of the clip
/// like its keys. Locomotion reads which foot is planted from here (the animator's, or the clip
/// maker's, decision) rather than guessing it from the foot's height, which a stance foot does
/// not keep exactly.
/// ```text
/// in contact at clip time t  ⇔  start_i ≤ t < end_i  for some interval i
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Contact {
    joint: usize,
    intervals: Vec<[f32; 2]>,
}

impl Contact {
    /// Joint `joint` is in contact during each `[start, end)` of `intervals` (seconds): finite,
    /// `start < end`, in order and not overlapping (one may start where the previous ends). The
    /// clip checks the joint and the duration ([`RawClip::with_contacts`]).
    pub fn new(joint: usize, intervals: Vec<[f32; 2]>) -> Result<Self, ClipError> {
        let bad = |reason: String| Err(ClipError::BadContact { joint, reason });
        let mut previous_end = f32::NEG_INFINITY;
        for &[start, end] in &intervals {
            if !(start.is_finite() && end.is_finite() && start < end) {
                return bad(format!(
                    "the interval [{start}, {end}) s is empty or not finite"
                ));
            }
            if start < previous_end {
                return bad(format!(
                    "the interval [{start}, {end}) s starts before the previous one ends ({previous_end} s)"
                ));
            }
            previous_end = end;
        }
        Ok(Self { joint, intervals })
    }

    /// The joint that touches the ground.
    pub fn joint(&self) -> usize {
        self.joint
    }

    /// The stance intervals, `[start, end)` in clip seconds, in order.
    pub fn intervals(&self) -> &[[f32; 2]] {
        &self.intervals
    }

    /// Whether the joint is in contact at clip-local time `t` (not wrapped here).
    pub fn at(&self, t: f32) -> bool {
        let i = self.intervals.partition_point(|iv| iv[1] <= t);
        self.intervals.get(i).is_some_and(|iv| iv[0] <= t)
    }

    /// Seconds in contact per cycle: the intervals' total length.
    pub fn stance_sec(&self) -> f32 {
        self.intervals.iter().map(|iv| iv[1] - iv[0]).sum()
    }
}

/// The editable clip: one [`Track`] per animated channel, each with its own key times, and the
/// joints' ground [`Contact`]s (none unless given).
#[derive(Clone, Debug, PartialEq)]
pub struct RawClip {
    name: String,
    duration_sec: f32,
    looping: bool,
    interpolation: KeyInterpolation,
    rotation_interpolation: QuatInterpolation,
    joints: Vec<JointTracks>,
    contacts: Vec<Contact>,
}

fn track_interpolation(k: KeyInterpolation) -> Interpolation {
    match k {
        KeyInterpolation::Step => Interpolation::Step,
        KeyInterpolation::Linear => Interpolation::Linear,
        KeyInterpolation::Cubic => Interpolation::CATMULL_ROM,
    }
}

impl RawClip {
    /// Checks the duration and that every key lies in `[0, duration]`; normalises the rotation
    /// keys and flips signs so that consecutive keys lie in one hemisphere (`q_k · q_{k−1} ≥ 0`,
    /// the short way round). Starts with linear interpolation and nlerp.
    pub fn new(
        name: impl Into<String>,
        duration_sec: f32,
        looping: bool,
        mut joints: Vec<JointTracks>,
    ) -> Result<Self, ClipError> {
        if !duration_sec.is_finite() || duration_sec <= 0.0 {
            return Err(ClipError::BadDuration { duration_sec });
        }
        for (joint, tracks) in joints.iter_mut().enumerate() {
            let channels = [
                (
                    "translation",
                    tracks.translation.as_ref().map(|t| t.times()),
                ),
                ("rotation", tracks.rotation.as_ref().map(|t| t.times())),
                ("scale", tracks.scale.as_ref().map(|t| t.times())),
            ];
            for (channel, times) in channels {
                for &time_sec in times.unwrap_or(&[]) {
                    if !(0.0..=duration_sec).contains(&time_sec) {
                        return Err(ClipError::KeyOutsideDuration {
                            joint,
                            channel,
                            time_sec,
                            duration_sec,
                        });
                    }
                }
            }
            if let Some(track) = &tracks.rotation {
                let mut values = Vec::with_capacity(track.key_count());
                for (key, &v) in track.values().iter().enumerate() {
                    let length = v.length();
                    if length < 1e-6 {
                        return Err(ClipError::ZeroRotation { joint, key });
                    }
                    let mut q = v / length;
                    if let Some(&previous) = values.last() {
                        if q.dot(previous) < 0.0 {
                            q = -q;
                        }
                    }
                    values.push(q);
                }
                let rebuilt = Track::new(track.times().to_vec(), values).map_err(|error| {
                    ClipError::Track {
                        joint,
                        channel: "rotation",
                        error,
                    }
                })?;
                tracks.rotation = Some(rebuilt);
            }
        }
        let mut clip = Self {
            name: name.into(),
            duration_sec,
            looping,
            interpolation: KeyInterpolation::Linear,
            rotation_interpolation: QuatInterpolation::Nlerp,
            joints,
            contacts: Vec::new(),
        };
        clip.set_interpolation(KeyInterpolation::Linear);
        Ok(clip)
    }

    /// The clip with these ground contacts (replacing any it had). Each contact's joint must be
    /// one of the clip's and its intervals must lie in `[0, duration]`.
    pub fn with_contacts(mut self, contacts: Vec<Contact>) -> Result<Self, ClipError> {
        for c in &contacts {
            let bad = |reason: String| ClipError::BadContact {
                joint: c.joint,
                reason,
            };
            if c.joint >= self.joints.len() {
                return Err(bad(format!("the clip has {} joints", self.joints.len())));
            }
            if let Some(iv) = c
                .intervals
                .iter()
                .find(|iv| iv[0] < 0.0 || iv[1] > self.duration_sec)
            {
                return Err(bad(format!(
                    "the interval [{}, {}) s lies outside the clip [0, {}] s",
                    iv[0], iv[1], self.duration_sec
                )));
            }
        }
        self.contacts = contacts;
        Ok(self)
    }

    /// The joints' ground contacts.
    pub fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    pub fn name(&self) -> &str {
        &self.name
    }

    pub fn duration_sec(&self) -> f32 {
        self.duration_sec
    }

    pub fn looping(&self) -> bool {
        self.looping
    }

    pub fn joints(&self) -> &[JointTracks] {
        &self.joints
    }

    pub fn interpolation(&self) -> KeyInterpolation {
        self.interpolation
    }

    pub fn rotation_interpolation(&self) -> QuatInterpolation {
        self.rotation_interpolation
    }

    /// Sets the interpolation of every channel.
    pub fn set_interpolation(&mut self, interpolation: KeyInterpolation) {
        self.interpolation = interpolation;
        let scheme = track_interpolation(interpolation);
        for tracks in &mut self.joints {
            for track in [&mut tracks.translation, &mut tracks.scale]
                .into_iter()
                .flatten()
            {
                track.set_interpolation(scheme).valid("tension 1 is valid");
            }
            if let Some(track) = &mut tracks.rotation {
                track.set_interpolation(scheme).valid("tension 1 is valid");
            }
        }
    }

    pub fn set_rotation_interpolation(&mut self, q: QuatInterpolation) {
        self.rotation_interpolation = q;
    }

    /// Clip-local time: wrapped into `[0, duration)` when looping, clamped to `[0, duration]`
    /// otherwise; NaN reads as 0.
    pub fn local_time(&self, time_sec: f32) -> f32 {
        local_time(time_sec, self.duration_sec, self.looping)
    }

    /// One cursor per channel (3 per joint), for [`RawClip::sample`].
    pub fn cursors(&self) -> Vec<Cursor> {
        vec![Cursor::new(); 3 * self.joints.len()]
    }

    /// Samples every channel at `time_sec` (wrapped or clamped) into `pose`; channels without
    /// keys take `rest`'s value. The straightforward way: each track finds its own segment with
    /// its own cursor. Allocates nothing.
    ///
    /// # Panics
    /// If `rest`, `cursors` (3 per joint) or `pose` do not match the clip's joint count.
    pub fn sample(
        &self,
        time_sec: f32,
        rest: &[Transform],
        cursors: &mut [Cursor],
        pose: &mut Pose,
    ) {
        let t = self.local_time(time_sec);
        self.sample_at(t, rest, cursors, pose);
    }

    /// As [`RawClip::sample`], at a clip-local time used as given (clamped by the tracks).
    fn sample_at(&self, t: f32, rest: &[Transform], cursors: &mut [Cursor], pose: &mut Pose) {
        let n = self.joints.len();
        assert!(
            rest.len() == n && pose.len() == n && cursors.len() == 3 * n,
            "one per joint"
        );
        for (j, tracks) in self.joints.iter().enumerate() {
            let out = &mut pose.local[j];
            let c = &mut cursors[3 * j..3 * j + 3];
            out.translation = match &tracks.translation {
                Some(track) => track.position_with(&mut c[0], t),
                None => rest[j].translation,
            };
            out.rotation = match &tracks.rotation {
                Some(track) => self.rotation_at(track, &mut c[1], t),
                None => rest[j].rotation,
            };
            out.scale = match &tracks.scale {
                Some(track) => track.position_with(&mut c[2], t),
                None => rest[j].scale,
            };
        }
    }

    fn rotation_at(&self, track: &Track<Vec4>, cursor: &mut Cursor, t: f32) -> Quat {
        match (self.interpolation, self.rotation_interpolation) {
            (KeyInterpolation::Linear, QuatInterpolation::Slerp) => {
                // Keys are aligned, so slerp's own short-arc test never flips here.
                let keys = track.values();
                rotation_segment(
                    track.times(),
                    cursor,
                    t,
                    |i, s| slerp(Quat::from_vec4(keys[i]), Quat::from_vec4(keys[i + 1]), s),
                    |i| Quat::from_vec4(keys[i]),
                )
            }
            // Step holds a key; linear on aligned keys plus a normalisation is nlerp; cubic is
            // Catmull-Rom on the components, normalised.
            _ => Quat::from_vec4(track.position_with(cursor, t).normalize()),
        }
    }
}

/// Finds the segment of `t` in `times` (clamping outside) and calls `between(i, s)`, or `at(k)` at
/// or beyond an end key.
fn rotation_segment(
    times: &[f32],
    cursor: &mut Cursor,
    t: f32,
    between: impl Fn(usize, f32) -> Quat,
    at: impl Fn(usize) -> Quat,
) -> Quat {
    let n = times.len();
    if n == 1 || t <= times[0] || t.is_nan() {
        return at(0);
    }
    if t >= times[n - 1] {
        return at(n - 1);
    }
    let i = cursor.find(times, t);
    let s = (t - times[i]) / (times[i + 1] - times[i]);
    between(i, s)
}

/// One rotation channel sampled at `time_sec`, with nlerp or slerp between the two keys around it.
/// ```text
/// t ≤ t_0: q_0      t ≥ t_{N−1}: q_{N−1}
/// otherwise, with t_i ≤ t < t_{i+1}:   s = (t − t_i) / (t_{i+1} − t_i),   q = slerp(q_i, q_{i+1}; s)
/// ```
/// (or nlerp), always along the short arc. `times` strictly increasing, one unit quaternion per
/// time. Reference solution of exercise 6.2. Lesson: `lessons/06-skeletons`.
///
/// # Panics
/// If `keys` is empty or its length differs from `times`.
pub fn sample_rotation_channel(
    times: &[f32],
    keys: &[Quat],
    time_sec: f32,
    interpolation: QuatInterpolation,
) -> Quat {
    assert!(
        !keys.is_empty() && keys.len() == times.len(),
        "one key per time"
    );
    let mut cursor = Cursor::new();
    rotation_segment(
        times,
        &mut cursor,
        time_sec,
        |i, s| match interpolation {
            QuatInterpolation::Slerp => slerp(keys[i], keys[i + 1], s),
            QuatInterpolation::Nlerp => crate::rotation::nlerp(keys[i], keys[i + 1], s),
        },
        |k| keys[k],
    )
}

fn local_time(time_sec: f32, duration_sec: f32, looping: bool) -> f32 {
    if time_sec.is_nan() {
        0.0
    } else if looping {
        time_sec.rem_euclid(duration_sec).min(duration_sec)
    } else {
        time_sec.clamp(0.0, duration_sec)
    }
}

/// Where a [`Clip`] was last sampled: keep one per playing clip, so that sampling at increasing
/// times finds the segment in `O(1)`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClipCursor {
    segment: Cursor,
}

impl ClipCursor {
    pub const fn new() -> Self {
        Self {
            segment: Cursor::new(),
        }
    }

    /// The key segment found last.
    pub fn segment(&self) -> usize {
        self.segment.segment()
    }
}

/// The runtime clip: key times shared by all channels, values stored key-major (see the module
/// docs for why). Built from a [`RawClip`] with [`Clip::from_raw`].
#[derive(Clone, Debug, PartialEq)]
pub struct Clip {
    name: String,
    duration_sec: f32,
    looping: bool,
    interpolation: KeyInterpolation,
    rotation_interpolation: QuatInterpolation,
    joints: usize,
    times: Vec<f32>,
    translations: Vec<Vec3>,
    rotations: Vec<Quat>,
    scales: Vec<Vec3>,
    translation_tangents: Vec<Vec3>,
    rotation_tangents: Vec<Vec4>,
    scale_tangents: Vec<Vec3>,
    contacts: Vec<Contact>,
}

impl Clip {
    /// Builds the runtime form of `raw` for `skeleton`: merges all key times (plus 0 and the
    /// duration), evaluates every channel there (channels without keys: the rest value), aligns
    /// rotations along time, and precomputes Catmull-Rom tangents.
    pub fn from_raw(raw: &RawClip, skeleton: &Skeleton) -> Result<Self, ClipError> {
        let n = skeleton.len();
        if raw.joints.len() != n {
            return Err(ClipError::JointCount {
                expected: n,
                actual: raw.joints.len(),
            });
        }
        let mut times = vec![0.0, raw.duration_sec];
        for tracks in &raw.joints {
            let all = [
                tracks.translation.as_ref().map(|t| t.times()),
                tracks.rotation.as_ref().map(|t| t.times()),
                tracks.scale.as_ref().map(|t| t.times()),
            ];
            times.extend(all.into_iter().flatten().flatten().copied());
            if times.len() > 4 * MAX_CLIP_KEYS {
                return Err(ClipError::TooManyKeys { count: times.len() });
            }
        }
        crate::order::sort_ascending(&mut times);
        // Keys closer than a microsecond are one key.
        times.dedup_by(|b, a| *b - *a <= 1e-6);
        if let Some(last) = times.last_mut() {
            *last = raw.duration_sec;
        }
        if times.len() > MAX_CLIP_KEYS {
            return Err(ClipError::TooManyKeys { count: times.len() });
        }
        let keys = times.len();
        let mut clip = Self {
            name: raw.name.clone(),
            duration_sec: raw.duration_sec,
            looping: raw.looping,
            interpolation: raw.interpolation,
            rotation_interpolation: raw.rotation_interpolation,
            joints: n,
            translations: Vec::with_capacity(keys * n),
            rotations: Vec::with_capacity(keys * n),
            scales: Vec::with_capacity(keys * n),
            translation_tangents: vec![Vec3::ZERO; keys * n],
            rotation_tangents: vec![Vec4::ZERO; keys * n],
            scale_tangents: vec![Vec3::ZERO; keys * n],
            times,
            contacts: raw.contacts.clone(),
        };
        // Evaluate the editable clip at each key time, linearly (exact at each channel's keys).
        let mut linear = raw.clone();
        linear.set_interpolation(match raw.interpolation {
            KeyInterpolation::Step => KeyInterpolation::Step,
            _ => KeyInterpolation::Linear,
        });
        let mut cursors = linear.cursors();
        let mut pose = skeleton.rest_pose();
        for k in 0..keys {
            linear.sample_at(clip.times[k], skeleton.rest(), &mut cursors, &mut pose);
            for (j, x) in pose.local.iter().enumerate() {
                let mut q = x.rotation;
                if k > 0 && q.dot(clip.rotations[(k - 1) * n + j]) < 0.0 {
                    q = -q;
                }
                clip.translations.push(x.translation);
                clip.rotations.push(q);
                clip.scales.push(x.scale);
            }
        }
        clip.compute_tangents();
        Ok(clip)
    }

    /// Catmull-Rom tangents of every channel along the shared key times.
    fn compute_tangents(&mut self) {
        let (n, keys) = (self.joints, self.times.len());
        let mut t3 = vec![Vec3::ZERO; keys];
        let mut s3 = vec![Vec3::ZERO; keys];
        let mut r4 = vec![Vec4::ZERO; keys];
        let (mut dt, mut ds, mut dr) = (t3.clone(), s3.clone(), r4.clone());
        for j in 0..n {
            for k in 0..keys {
                t3[k] = self.translations[k * n + j];
                s3[k] = self.scales[k * n + j];
                r4[k] = Vec4::from(self.rotations[k * n + j]);
            }
            cardinal_tangents(&self.times, &t3, 1.0, &mut dt);
            cardinal_tangents(&self.times, &s3, 1.0, &mut ds);
            cardinal_tangents(&self.times, &r4, 1.0, &mut dr);
            for k in 0..keys {
                self.translation_tangents[k * n + j] = dt[k];
                self.scale_tangents[k * n + j] = ds[k];
                self.rotation_tangents[k * n + j] = dr[k];
            }
        }
    }

    pub fn name(&self) -> &str {
        &self.name
    }

    pub fn duration_sec(&self) -> f32 {
        self.duration_sec
    }

    pub fn looping(&self) -> bool {
        self.looping
    }

    pub fn set_looping(&mut self, looping: bool) {
        self.looping = looping;
    }

    /// Number of joints each key holds.
    pub fn joint_count(&self) -> usize {
        self.joints
    }

    /// The shared key times, seconds, from 0 to the duration.
    pub fn key_times(&self) -> &[f32] {
        &self.times
    }

    /// Joint `joint`'s transform at key `key`.
    pub fn key(&self, key: usize, joint: usize) -> Transform {
        let i = key * self.joints + joint;
        Transform {
            translation: self.translations[i],
            rotation: self.rotations[i],
            scale: self.scales[i],
        }
    }

    pub fn interpolation(&self) -> KeyInterpolation {
        self.interpolation
    }

    pub fn set_interpolation(&mut self, interpolation: KeyInterpolation) {
        self.interpolation = interpolation;
    }

    pub fn rotation_interpolation(&self) -> QuatInterpolation {
        self.rotation_interpolation
    }

    pub fn set_rotation_interpolation(&mut self, q: QuatInterpolation) {
        self.rotation_interpolation = q;
    }

    /// Clip-local time (wrapped when looping, clamped otherwise; NaN reads as 0).
    pub fn local_time(&self, time_sec: f32) -> f32 {
        local_time(time_sec, self.duration_sec, self.looping)
    }

    /// The joints' ground contacts, as the [`RawClip`] gave them.
    pub fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    /// Whether contact `index` (of [`Clip::contacts`]) holds at `time_sec`, wrapped or clamped
    /// as [`Clip::sample`] does (a looping clip's duration is its time 0). `false` for a
    /// contact the clip does not have.
    pub fn in_contact(&self, index: usize, time_sec: f32) -> bool {
        let mut t = self.local_time(time_sec);
        if self.looping && t >= self.duration_sec {
            t = 0.0;
        }
        self.contacts.get(index).is_some_and(|c| c.at(t))
    }

    /// The index in [`Clip::contacts`] of `joint`'s contact, if it has one.
    pub fn contact_of(&self, joint: usize) -> Option<usize> {
        self.contacts.iter().position(|c| c.joint == joint)
    }

    /// Samples every joint at `time_sec` into `pose`: one segment lookup for all joints, then
    /// one pass over two contiguous runs of keys. Allocates nothing. Looping clips wrap the time
    /// (the last key, at the duration, equals the first for a seamless loop); others clamp.
    ///
    /// # Panics
    /// If `pose` does not have one transform per joint of the clip.
    pub fn sample(&self, time_sec: f32, cursor: &mut ClipCursor, pose: &mut Pose) {
        let n = self.joints;
        assert_eq!(
            pose.len(),
            n,
            "Clip::sample: the pose needs one transform per joint"
        );
        let t = self.local_time(time_sec);
        let keys = self.times.len();
        if keys == 1 {
            self.copy_key(0, pose);
            return;
        }
        let i = cursor.segment.find(&self.times, t);
        let (t0, t1) = (self.times[i], self.times[i + 1]);
        let h = t1 - t0;
        let s = ((t - t0) / h).clamp(0.0, 1.0);
        let (a, b) = (i * n, (i + 1) * n);
        let out = &mut pose.local[..n];
        match (self.interpolation, self.rotation_interpolation) {
            (KeyInterpolation::Step, _) => self.copy_key(if s >= 1.0 { i + 1 } else { i }, pose),
            (KeyInterpolation::Linear, rotation) => {
                let (ta, tb) = (&self.translations[a..a + n], &self.translations[b..b + n]);
                let (ra, rb) = (&self.rotations[a..a + n], &self.rotations[b..b + n]);
                let (sa, sb) = (&self.scales[a..a + n], &self.scales[b..b + n]);
                let u = 1.0 - s;
                match rotation {
                    QuatInterpolation::Nlerp => {
                        for j in 0..n {
                            // Keys are hemisphere-aligned at build: no sign test needed.
                            let q = Vec4::from(ra[j]) * u + Vec4::from(rb[j]) * s;
                            out[j] = Transform {
                                translation: ta[j] * u + tb[j] * s,
                                rotation: Quat::from_vec4(q * q.length_recip()),
                                scale: sa[j] * u + sb[j] * s,
                            };
                        }
                    }
                    QuatInterpolation::Slerp => {
                        for j in 0..n {
                            out[j] = Transform {
                                translation: ta[j] * u + tb[j] * s,
                                rotation: slerp(ra[j], rb[j], s),
                                scale: sa[j] * u + sb[j] * s,
                            };
                        }
                    }
                }
            }
            (KeyInterpolation::Cubic, _) => {
                let [h00, h10, h01, h11] = crate::curves::hermite_basis(s);
                let (m10, m11) = (h10 * h, h11 * h);
                for (j, slot) in out.iter_mut().enumerate() {
                    let (ka, kb) = (a + j, b + j);
                    let q = Vec4::from(self.rotations[ka]) * h00
                        + self.rotation_tangents[ka] * m10
                        + Vec4::from(self.rotations[kb]) * h01
                        + self.rotation_tangents[kb] * m11;
                    *slot = Transform {
                        translation: self.translations[ka] * h00
                            + self.translation_tangents[ka] * m10
                            + self.translations[kb] * h01
                            + self.translation_tangents[kb] * m11,
                        rotation: Quat::from_vec4(q.normalize()),
                        scale: self.scales[ka] * h00
                            + self.scale_tangents[ka] * m10
                            + self.scales[kb] * h01
                            + self.scale_tangents[kb] * m11,
                    };
                }
            }
        }
    }

    fn copy_key(&self, key: usize, pose: &mut Pose) {
        let n = self.joints;
        let base = key * n;
        for (j, slot) in pose.local[..n].iter_mut().enumerate() {
            *slot = Transform {
                translation: self.translations[base + j],
                rotation: self.rotations[base + j],
                scale: self.scales[base + j],
            };
        }
    }
}
