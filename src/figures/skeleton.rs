//! Figure logic for lesson 06, "Skeletons and forward kinematics" (see [`crate::figures`]).
//!
//! [`SkeletonFigure`]: the built-in simple human drawn as its skeleton (a sphere per joint, a bar
//! per joint-to-parent segment, local axes), playing one of its clips with step, linear (nlerp or
//! slerp) or cubic interpolation and a chosen number of keys per cycle; per-joint angle offsets on
//! top of the clip; the selected joint (orange) and its group (teal), which the page's joint table
//! highlights too; the path of the selected joint's bone tip over one cycle with dots at equal time
//! steps; the samples behind the plots; and the check of the student's exercises 6.1 and 6.2.

use super::{
    compare_note, failure_note, finite, format_number, in_range, palette, Frame, MeshId, Runner,
    DEFAULT_RUNNER,
};
use crate::exercises::run;
use crate::rotation::angle_between;
use crate::skeleton::{
    crossfade_transform, human, local_to_model, sample_rotation_channel, Clip, ClipCursor,
    KeyInterpolation, Pose, QuatInterpolation, RawClip, Skeleton,
};
use crate::transform::JointShape;
use glam::{Affine3A, EulerRot, Mat4, Quat, Vec3};

const DEG: f32 = std::f32::consts::PI / 180.0;
const EXERCISE_FILE: &str = "src/exercises/skeleton.rs";
/// How close the student's matrices and quaternions must be to the reference's.
const TOLERANCE: f32 = 1e-4;
/// Dots along the bone-tip path, per cycle.
const TRAIL_DOTS: usize = 60;
/// Radius of a joint's sphere, metres.
const JOINT_RADIUS: f32 = 0.022;

/// The lesson's figure: a skeleton playing a clip.
#[derive(Clone, Debug)]
pub struct SkeletonFigure {
    skeleton: Skeleton,
    shapes: Vec<JointShape>,
    raw: Vec<RawClip>,
    clips: Vec<Clip>,
    clip: Option<usize>,
    keys_per_cycle: usize,
    interpolation: KeyInterpolation,
    rotation: QuatInterpolation,
    offsets_rad: Vec<Vec3>,
    selected: usize,
    show_boxes: bool,
    show_axes: bool,
    use_exercise: bool,
    runner: Runner,
    /// The clip crossfaded in (played at the same phase), and its weight.
    blend_clip: Option<usize>,
    blend_weight: f32,
    /// Clip B's pose and cursor while blending (a cell: sampling is `&self`).
    blend_scratch: std::cell::RefCell<(Pose, ClipCursor)>,
    cursor: ClipCursor,
    pose: Pose,
    model: Vec<Affine3A>,
    scratch_pose: Pose,
    scratch_model: Vec<Affine3A>,
    trail: Vec<Vec3>,
}

impl Default for SkeletonFigure {
    fn default() -> Self {
        Self::new()
    }
}

/// What the interpolation dropdown offers, in order.
pub const INTERPOLATIONS: [&str; 4] = ["step", "linear (nlerp)", "linear (slerp)", "cubic"];

impl SkeletonFigure {
    /// The walk, 9 keys per cycle, linear with slerp, `upper_arm.L` selected.
    pub fn new() -> Self {
        let (skeleton, shapes) = human::simple_human();
        let n = skeleton.len();
        let selected = skeleton.find("thigh.L").expect("a joint of the human");
        let mut figure = Self {
            raw: Vec::new(),
            clips: Vec::new(),
            clip: Some(1),
            keys_per_cycle: 9,
            interpolation: KeyInterpolation::Linear,
            rotation: QuatInterpolation::Slerp,
            offsets_rad: vec![Vec3::ZERO; n],
            selected,
            show_boxes: false,
            show_axes: true,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            blend_clip: None,
            blend_weight: 0.5,
            blend_scratch: std::cell::RefCell::new((skeleton.rest_pose(), ClipCursor::new())),
            cursor: ClipCursor::new(),
            pose: skeleton.rest_pose(),
            model: vec![Affine3A::IDENTITY; n],
            scratch_pose: skeleton.rest_pose(),
            scratch_model: vec![Affine3A::IDENTITY; n],
            trail: Vec::with_capacity(TRAIL_DOTS + 1),
            skeleton,
            shapes,
        };
        figure.rebuild_clips().expect("the built-in clips build");
        figure
    }

    fn rebuild_clips(&mut self) -> Result<(), String> {
        self.raw.clear();
        self.clips.clear();
        for index in 0..human::CLIP_NAMES.len() {
            let mut raw = human::clip_with_keys(&self.skeleton, index, self.keys_per_cycle)
                .ok_or_else(|| {
                    format!("keys per cycle: {} is out of range", self.keys_per_cycle)
                })?;
            raw.set_interpolation(self.interpolation);
            raw.set_rotation_interpolation(self.rotation);
            let clip = Clip::from_raw(&raw, &self.skeleton).map_err(|e| e.to_string())?;
            self.raw.push(raw);
            self.clips.push(clip);
        }
        Ok(())
    }

    pub fn skeleton(&self) -> &Skeleton {
        &self.skeleton
    }

    /// The clip names the dropdown offers: the built-in clips, then "none (rest pose)".
    pub fn clip_names(&self) -> Vec<String> {
        let mut names: Vec<String> = human::CLIP_NAMES.iter().map(|s| s.to_string()).collect();
        names.push("none (rest pose)".into());
        names
    }

    /// Plays the clip named `name` (one of [`SkeletonFigure::clip_names`]).
    pub fn set_clip(&mut self, name: &str) -> Result<(), String> {
        self.clip = match human::CLIP_NAMES.iter().position(|&c| c == name) {
            Some(i) => Some(i),
            None if name.starts_with("none") => None,
            None => return Err(format!("clip: no clip named {name:?}")),
        };
        self.cursor = ClipCursor::new();
        Ok(())
    }

    /// The playing clip's name, or "none (rest pose)".
    pub fn clip_name(&self) -> String {
        match self.clip {
            Some(i) => human::CLIP_NAMES[i].to_string(),
            None => "none (rest pose)".into(),
        }
    }

    /// Keys per cycle of every clip, in [4, 25] (counting the last key, which repeats the first).
    pub fn set_keys_per_cycle(&mut self, keys: f32) -> Result<(), String> {
        let keys = super::whole_number("keys per cycle", keys, 4, 25)?;
        if keys != self.keys_per_cycle {
            self.keys_per_cycle = keys;
            self.rebuild_clips()?;
        }
        Ok(())
    }

    /// One of [`INTERPOLATIONS`]: "step", "linear (nlerp)", "linear (slerp)" or "cubic"; a bare
    /// "linear" keeps the current rotation choice.
    pub fn set_interpolation(&mut self, name: &str) -> Result<(), String> {
        let (interpolation, rotation) = match name {
            "step" => (KeyInterpolation::Step, self.rotation),
            "linear" => (KeyInterpolation::Linear, self.rotation),
            "linear (nlerp)" => (KeyInterpolation::Linear, QuatInterpolation::Nlerp),
            "linear (slerp)" => (KeyInterpolation::Linear, QuatInterpolation::Slerp),
            "cubic" => (KeyInterpolation::Cubic, self.rotation),
            _ => {
                return Err(format!(
                    "interpolation must be one of {}, got {name:?}",
                    INTERPOLATIONS.join(", ")
                ))
            }
        };
        self.interpolation = interpolation;
        self.rotation = rotation;
        self.apply_modes();
        Ok(())
    }

    /// "nlerp" or "slerp" (used by linear interpolation).
    pub fn set_rotation_interpolation(&mut self, name: &str) -> Result<(), String> {
        self.rotation = match name {
            "nlerp" => QuatInterpolation::Nlerp,
            "slerp" => QuatInterpolation::Slerp,
            _ => return Err(format!("rotation must be nlerp or slerp, got {name:?}")),
        };
        self.apply_modes();
        Ok(())
    }

    fn apply_modes(&mut self) {
        for (raw, clip) in self.raw.iter_mut().zip(&mut self.clips) {
            raw.set_interpolation(self.interpolation);
            raw.set_rotation_interpolation(self.rotation);
            clip.set_interpolation(self.interpolation);
            clip.set_rotation_interpolation(self.rotation);
        }
    }

    fn joint(&self, joint: usize) -> Result<usize, String> {
        if joint < self.skeleton.len() {
            Ok(joint)
        } else {
            Err(format!(
                "joint index {joint} is out of range: the skeleton has {} joints",
                self.skeleton.len()
            ))
        }
    }

    /// Selects the joint drawn in orange (its group in teal) whose angles the sliders edit.
    pub fn select(&mut self, joint: usize) -> Result<(), String> {
        self.selected = self.joint(joint)?;
        Ok(())
    }

    pub fn selected(&self) -> usize {
        self.selected
    }

    /// A joint's angle offsets (degrees, about x, y, z as in lesson 01) on top of the clip.
    pub fn joint_angles_deg(&self, joint: usize) -> Result<Vec3, String> {
        Ok(self.offsets_rad[self.joint(joint)?] / DEG)
    }

    /// Sets a joint's angle offsets, each in [−180, 180] degrees.
    pub fn set_joint_angles_deg(&mut self, joint: usize, deg: Vec3) -> Result<(), String> {
        let j = self.joint(joint)?;
        self.offsets_rad[j] = Vec3::new(
            in_range("angle x", deg.x, -180.0, 180.0)?,
            in_range("angle y", deg.y, -180.0, 180.0)?,
            in_range("angle z", deg.z, -180.0, 180.0)?,
        ) * DEG;
        Ok(())
    }

    /// Clears every joint's angle offsets.
    pub fn reset_pose(&mut self) {
        self.offsets_rad.iter_mut().for_each(|o| *o = Vec3::ZERO);
    }

    pub fn set_show_boxes(&mut self, on: bool) {
        self.show_boxes = on;
    }

    pub fn set_show_axes(&mut self, on: bool) {
        self.show_axes = on;
    }

    /// Runs the student's exercises 6.1 and 6.2 (through the runner) instead of the reference.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// The playing clip's duration, seconds (1 for the rest pose).
    pub fn duration_sec(&self) -> f32 {
        self.clip.map_or(1.0, |c| self.clips[c].duration_sec())
    }

    /// The playing clip's key times, seconds (empty for the rest pose).
    pub fn key_times(&self) -> Vec<f32> {
        self.clip
            .map_or_else(Vec::new, |c| self.clips[c].key_times().to_vec())
    }

    /// Model matrix of a joint at the last pose.
    pub fn model_matrix(&self, joint: usize) -> Result<Mat4, String> {
        Ok(Mat4::from(self.model[self.joint(joint)?]))
    }

    /// Local matrix `T·R·S` of a joint at the last pose.
    pub fn local_matrix(&self, joint: usize) -> Result<Mat4, String> {
        Ok(self.pose.local[self.joint(joint)?].to_mat4())
    }

    /// Where a joint's pivot is at the last pose, model space.
    pub fn joint_position(&self, joint: usize) -> Result<Vec3, String> {
        Ok(self.model[self.joint(joint)?].translation.into())
    }

    /// Crossfades a second clip in (`None`: no blend), weight `w ∈ [0, 1]` (1: all clip B). Clip
    /// B plays at the same phase as the main clip (time normalised by each clip's duration), so
    /// a walk and a run of different lengths stay in step.
    pub fn set_blend(&mut self, name: &str, weight: f32) -> Result<(), String> {
        let weight = in_range("blend weight", weight, 0.0, 1.0)?;
        self.blend_clip = match human::CLIP_NAMES.iter().position(|&c| c == name) {
            Some(i) => Some(i),
            None if name == "none" => None,
            None => return Err(format!("blend clip: no clip named {name:?}")),
        };
        self.blend_weight = weight;
        Ok(())
    }

    /// Clip B's time for the main clip's time `time_sec`: the same phase of its own cycle.
    fn blend_time(&self, b: usize, time_sec: f32) -> f32 {
        let phase = time_sec / self.duration_sec();
        phase * self.clips[b].duration_sec()
    }

    /// Samples the clip at `time_sec` into `pose` (the rest pose without a clip), crossfades the
    /// blend clip in, and adds the angle offsets.
    fn sample_into(&self, time_sec: f32, cursor: &mut ClipCursor, pose: &mut Pose) {
        match self.clip {
            Some(c) => self.clips[c].sample(time_sec, cursor, pose),
            None => pose.local.copy_from_slice(self.skeleton.rest()),
        }
        if let Some(b) = self.blend_clip {
            let mut scratch = self.blend_scratch.borrow_mut();
            let (pose_b, cursor_b) = &mut *scratch;
            self.clips[b].sample(self.blend_time(b, time_sec), cursor_b, pose_b);
            for (x, y) in pose.local.iter_mut().zip(&pose_b.local) {
                *x = crossfade_transform(x, y, self.blend_weight);
            }
        }
        for (x, o) in pose.local.iter_mut().zip(&self.offsets_rad) {
            if *o != Vec3::ZERO {
                x.rotation =
                    (x.rotation * Quat::from_euler(EulerRot::XYZ, o.x, o.y, o.z)).normalize();
            }
        }
    }

    /// Poses the skeleton at `time_sec` (reference cores, then, with "use my exercise", the
    /// student's). Returns the note.
    pub fn pose(&mut self, time_sec: f32) -> Result<String, String> {
        let t = finite("time", time_sec)?;
        let mut cursor = self.cursor;
        let mut pose = std::mem::replace(&mut self.pose, Pose::identity(0));
        self.sample_into(t, &mut cursor, &mut pose);
        self.cursor = cursor;
        self.pose = pose;
        let mut notes = Vec::new();
        if self.use_exercise {
            notes.push(self.student_rotation(t));
            if self.blend_clip.is_some() {
                notes.push(self.student_blend(t));
            }
        }
        local_to_model(
            self.skeleton.parents(),
            &self.pose.local,
            self.skeleton.scale_mode(),
            &mut self.model,
        );
        if self.use_exercise {
            notes.push(self.student_model());
        } else {
            notes.push(self.describe(t));
        }
        self.compute_trail();
        Ok(notes.join(" "))
    }

    /// The default note: the selected joint in the array, and where the clip is.
    fn describe(&self, t: f32) -> String {
        let j = self.selected;
        let names = self.skeleton.names();
        let parent = self.skeleton.parents()[j];
        let parent = if parent < 0 {
            "none (the root)".to_string()
        } else {
            format!("{} ({})", parent, names[parent as usize])
        };
        let joint = format!(
            "Joint {j} ({}): parent {parent}, group of {} joint{}.",
            names[j],
            self.skeleton.group_sizes()[j],
            if self.skeleton.group_sizes()[j] == 1 {
                ""
            } else {
                "s"
            }
        );
        let Some(c) = self.clip else {
            return format!("{joint} Rest pose: no clip.");
        };
        let clip = &self.clips[c];
        let local = clip.local_time(t);
        let times = clip.key_times();
        let i = crate::curves::find_segment(times, local);
        let s = (local - times[i]) / (times[i + 1] - times[i]);
        let how = match self.interpolation {
            KeyInterpolation::Step => "step (holds key ".to_string() + &i.to_string() + ")",
            KeyInterpolation::Linear => match self.rotation {
                QuatInterpolation::Nlerp => "linear, rotations by nlerp".into(),
                QuatInterpolation::Slerp => "linear, rotations by slerp".into(),
            },
            KeyInterpolation::Cubic => "cubic (Catmull-Rom)".into(),
        };
        let blend = match self.blend_clip {
            Some(b) => format!(
                " Crossfaded with {} at weight {} (same phase of its own cycle).",
                self.clips[b].name(),
                format_number(self.blend_weight)
            ),
            None => String::new(),
        };
        format!(
            "{joint} Clip {} at {} s: between keys {i} and {} (s = {}), {how}.{blend}",
            clip.name(),
            format_number(local),
            i + 1,
            format_number(s.clamp(0.0, 1.0)),
        )
    }

    /// Exercise 6.2 on the selected joint's rotation channel; replaces that joint's sampled
    /// rotation by the student's (linear + slerp only). Returns the note.
    fn student_rotation(&mut self, t: f32) -> String {
        let exercise = "exercise 6.2 sample_rotation_slerp";
        let Some(c) = self.clip else {
            return "Pick a clip to run your 6.2 on the selected joint.".into();
        };
        let j = self.selected;
        let Some(track) = &self.raw[c].joints()[j].rotation else {
            return format!(
                "{} has no rotation channel in this clip: select a joint that moves (thigh.L) to run \
                 your 6.2.",
                self.skeleton.names()[j]
            );
        };
        if (self.interpolation, self.rotation)
            != (KeyInterpolation::Linear, QuatInterpolation::Slerp)
        {
            return "Switch to linear with slerp to run your 6.2 on the selected joint.".into();
        }
        let times = track.times().to_vec();
        let keys: Vec<Quat> = track.values().iter().map(|&v| Quat::from_vec4(v)).collect();
        let local = self.clips[c].local_time(t);
        let reference = sample_rotation_channel(&times, &keys, local, QuatInterpolation::Slerp);
        let yours = match run::sample_rotation_slerp(self.runner, times, keys, local) {
            Ok(q) => q,
            Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
        };
        let aligned = if yours.dot(reference) < 0.0 {
            -yours
        } else {
            yours
        };
        let at = format!(
            "t = {} s ({})",
            format_number(local),
            self.skeleton.names()[j]
        );
        let (ok, note) = compare_note(
            "sample_rotation_slerp",
            &at,
            &aligned.to_array(),
            &reference.to_array(),
            TOLERANCE,
        );
        if ok || yours.is_finite() && (yours.length() - 1.0).abs() < 0.1 {
            // Pose with the student's answer (offsets on top, as for the reference).
            let o = self.offsets_rad[j];
            self.pose.local[j].rotation =
                (yours.normalize() * Quat::from_euler(EulerRot::XYZ, o.x, o.y, o.z)).normalize();
        }
        note
    }

    /// Exercise 6.3 on every joint of the blend (clip A and clip B at time `t`, before the angle
    /// offsets); poses the figure with the student's blend. Returns the note.
    fn student_blend(&mut self, t: f32) -> String {
        let exercise = "exercise 6.3 crossfade_joint";
        let Some(b) = self.blend_clip else {
            return String::new();
        };
        let n = self.skeleton.len();
        let mut a = self.skeleton.rest_pose();
        let mut cursor = ClipCursor::new();
        if let Some(c) = self.clip {
            self.clips[c].sample(t, &mut cursor, &mut a);
        }
        let mut pose_b = self.skeleton.rest_pose();
        self.clips[b].sample(self.blend_time(b, t), &mut ClipCursor::new(), &mut pose_b);
        let w = self.blend_weight;
        let mut first_wrong = None;
        for j in 0..n {
            let (x, y) = (a.local[j], pose_b.local[j]);
            let yours = match run::crossfade_joint(
                self.runner,
                x.translation,
                x.rotation,
                y.translation,
                y.rotation,
                w,
            ) {
                Ok(answer) => answer,
                Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
            };
            let reference = crossfade_transform(&x, &y, w);
            let q = if yours.1.dot(reference.rotation) < 0.0 {
                -yours.1
            } else {
                yours.1
            };
            let flat_yours: Vec<f32> = yours.0.to_array().into_iter().chain(q.to_array()).collect();
            let flat_reference: Vec<f32> = (reference.translation.to_array().into_iter())
                .chain(reference.rotation.to_array())
                .collect();
            let close = flat_yours
                .iter()
                .zip(&flat_reference)
                .all(|(u, v)| (u - v).abs() <= TOLERANCE);
            if first_wrong.is_none() && !close {
                first_wrong = Some((j, flat_yours, flat_reference));
            }
            if yours.0.is_finite() && yours.1.is_finite() && yours.1.length() > 0.5 {
                let o = self.offsets_rad[j];
                self.pose.local[j].translation = yours.0;
                self.pose.local[j].rotation = (yours.1.normalize()
                    * Quat::from_euler(EulerRot::XYZ, o.x, o.y, o.z))
                .normalize();
            }
        }
        match first_wrong {
            None => format!(
                "Your crossfade_joint matches the reference at all {n} joints (w = {}).",
                format_number(w)
            ),
            Some((j, yours, reference)) => {
                let at = format!(
                    "joint {j} ({}), w = {}",
                    self.skeleton.names()[j],
                    format_number(w)
                );
                compare_note("crossfade_joint", &at, &yours, &reference, TOLERANCE).1
            }
        }
    }

    /// Exercise 6.1 on the current pose; draws the student's matrices when there are some.
    fn student_model(&mut self) -> String {
        let exercise = "exercise 6.1 local_to_model";
        let parents: Vec<f32> = self.skeleton.parents().iter().map(|&p| p as f32).collect();
        let local = &self.pose.local;
        let translations = local.iter().map(|x| x.translation).collect();
        let rotations = local.iter().map(|x| x.rotation).collect();
        let scales = local.iter().map(|x| x.scale).collect();
        let yours = match run::local_to_model(self.runner, parents, translations, rotations, scales) {
            Ok(m) if m.len() == self.model.len() => m,
            Ok(m) => {
                return format!(
                    "Your {exercise} returned {} matrices for {} joints. The figure uses the reference.",
                    m.len(),
                    self.model.len()
                )
            }
            Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
        };
        let wrong = (0..yours.len()).find(|&i| {
            let r = Mat4::from(self.model[i]);
            !yours[i].abs_diff_eq(
                r,
                TOLERANCE
                    * (1.0
                        + r.abs()
                            .to_cols_array()
                            .iter()
                            .fold(0.0f32, |m, x| m.max(*x))),
            )
        });
        let note = match wrong {
            None => format!(
                "Your local_to_model matches the reference at all {} joints of this pose.",
                yours.len()
            ),
            Some(i) => {
                let at = format!("joint {i} ({})", self.skeleton.names()[i]);
                compare_note(
                    "local_to_model",
                    &at,
                    &yours[i].to_cols_array(),
                    &Mat4::from(self.model[i]).to_cols_array(),
                    TOLERANCE,
                )
                .1
            }
        };
        for (m, y) in self.model.iter_mut().zip(&yours) {
            if y.is_finite() {
                *m = Affine3A::from_mat4(*y);
            }
        }
        note
    }

    /// The tip of the selected joint's bone: its first child's pivot, or a point 10 cm along its
    /// own −y for a leaf.
    fn tip(&self, model: &[Affine3A]) -> Vec3 {
        let j = self.selected;
        match self.skeleton.parents().iter().position(|&p| p == j as i32) {
            Some(child) => model[child].translation.into(),
            None => model[j].transform_point3(Vec3::new(0.0, -0.1, 0.0)),
        }
    }

    fn compute_trail(&mut self) {
        self.trail.clear();
        if self.clip.is_none() {
            return;
        }
        let d = self.duration_sec();
        let mut cursor = ClipCursor::new();
        let mut pose = std::mem::replace(&mut self.scratch_pose, Pose::identity(0));
        let mut model = std::mem::take(&mut self.scratch_model);
        for k in 0..=TRAIL_DOTS {
            let t = d * k as f32 / TRAIL_DOTS as f32 * 0.99999;
            self.sample_into(t, &mut cursor, &mut pose);
            local_to_model(
                self.skeleton.parents(),
                &pose.local,
                self.skeleton.scale_mode(),
                &mut model,
            );
            let tip = self.tip(&model);
            self.trail.push(tip);
        }
        self.scratch_pose = pose;
        self.scratch_model = model;
    }

    /// The path of the selected bone's tip over one cycle (dots at equal time steps).
    pub fn trail(&self) -> &[Vec3] {
        &self.trail
    }

    /// Poses at `time_sec` and draws. Returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let note = self.pose(time_sec)?;
        frame.grid(12, 0.25);
        frame.labelled_axes(Mat4::IDENTITY, 0.3);
        let parents = self.skeleton.parents();
        let color = |i: usize| {
            if i == self.selected {
                palette::ORANGE
            } else if self.skeleton.in_group(self.selected, i) {
                palette::TEAL
            } else {
                palette::DARK
            }
        };
        if self.show_boxes {
            for (shape, m) in self.shapes.iter().zip(&self.model) {
                let model = Mat4::from(*m)
                    * Mat4::from_translation(shape.center)
                    * Mat4::from_scale(shape.half_extents);
                frame.mesh(MeshId::CUBE, model, shape.color);
            }
        }
        for (i, &parent) in parents.iter().enumerate() {
            let p: Vec3 = self.model[i].translation.into();
            let radius = if i == self.selected {
                1.5 * JOINT_RADIUS
            } else {
                JOINT_RADIUS
            };
            frame.mesh(
                MeshId::SPHERE,
                Mat4::from_scale_rotation_translation(Vec3::splat(radius), Quat::IDENTITY, p),
                color(i),
            );
            if parent >= 0 {
                let a: Vec3 = self.model[parent as usize].translation.into();
                let bone_color = if self.skeleton.in_group(self.selected, i) && i != self.selected {
                    palette::TEAL
                } else {
                    palette::GREY
                };
                bone(frame, a, p, bone_color);
            }
            if self.show_axes && i != self.selected {
                frame.axes(Mat4::from(self.model[i]), 0.1);
            }
        }
        // A soft shadow on the floor under the character's middle: it shows how high the body
        // is and whether its lowest joint is down.
        if !self.model.is_empty() {
            let sum: Vec3 = self.model.iter().map(|m| Vec3::from(m.translation)).sum();
            let middle = sum / self.model.len() as f32;
            let lowest = self.model.iter().map(|m| m.translation.y).fold(f32::MAX, f32::min);
            frame.contact_shadow(Vec3::new(middle.x, lowest.max(0.0), middle.z), 0.25);
        }
        let selected = Mat4::from(self.model[self.selected]);
        frame.labelled_axes(selected, 0.18);
        let p = selected.w_axis.truncate();
        frame.label(
            p + Vec3::new(0.05, 0.05, 0.0),
            self.skeleton.names()[self.selected].clone(),
            palette::ORANGE,
        );
        if self.trail.len() >= 2 {
            frame.wide_polyline(&self.trail, palette::PURPLE, crate::draw::CURVE_PX);
            // A dot at each of the trail's samples, equal time steps apart.
            for &dot in &self.trail[..self.trail.len() - 1] {
                frame.point(dot, 0.008, palette::PURPLE);
            }
        }
        Ok(note)
    }

    /// One cycle of the selected joint's rotation for the plots: `[t, angle, speed, …]`, the
    /// angle (degrees) of its local rotation from its rest rotation and the angular speed
    /// (degrees per second, by finite differences), `samples` times over the clip, with the
    /// current interpolation and offsets.
    pub fn sample_selected(&self, samples: usize) -> Result<Vec<f32>, String> {
        super::check_samples(samples)?;
        let d = self.duration_sec();
        let j = self.selected;
        let rest = self.skeleton.rest()[j].rotation;
        let mut pose = self.skeleton.rest_pose();
        let mut cursor = ClipCursor::new();
        let mut rotations = Vec::with_capacity(samples);
        let dt = d / (samples - 1) as f32;
        for k in 0..samples {
            let t = (k as f32 * dt).min(d * 0.99999);
            self.sample_into(t, &mut cursor, &mut pose);
            rotations.push(pose.local[j].rotation);
        }
        let mut out = Vec::with_capacity(3 * samples);
        for k in 0..samples {
            let (a, b) = if k + 1 < samples {
                (k, k + 1)
            } else {
                (k - 1, k)
            };
            let speed = angle_between(rotations[a], rotations[b]) / dt / DEG;
            out.extend_from_slice(&[
                k as f32 * dt,
                angle_between(rest, rotations[k]) / DEG,
                speed,
            ]);
        }
        Ok(out)
    }
}

/// A joint-to-joint segment as a thin bar (plus a line, so it stays visible end-on).
fn bone(frame: &mut Frame, a: Vec3, b: Vec3, color: Vec3) {
    let v = b - a;
    let length = v.length();
    if length.is_nan() || length <= 1e-4 {
        return;
    }
    let model = Mat4::from_scale_rotation_translation(
        Vec3::new(0.008, 0.5 * length, 0.008),
        Quat::from_rotation_arc(Vec3::Y, v / length),
        a + 0.5 * v,
    );
    frame.mesh(MeshId::CUBE, model, color);
    frame.line(a, b, color);
}
