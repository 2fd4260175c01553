//! Figure logic for lesson 06, "Skeletons and forward kinematics" (see [`crate::figures`]).
//!
//! [`SkeletonFigure`]: the built-in simple human drawn as its skeleton (a sphere per joint, a bar
//! per joint-to-parent segment, local axes), playing one of its clips with step, linear (nlerp or
//! slerp) or cubic interpolation and a chosen number of keys per cycle; per-joint angle offsets on
//! top of the clip; the selected joint (orange) and its group (teal), which the page's joint table
//! highlights too; the path of the selected joint's bone tip over one cycle with ticks at equal
//! time steps, and beside it the same path under a second interpolation to compare with; while a
//! second clip is crossfaded in, the two clips' own poses to the left and right of the blend;
//! picking a joint under the pointer; the box the camera keeps in view; the samples behind the
//! plots; and the check of the student's exercises 6.1, 6.2 and 6.3, at the shown inputs and at
//! probe inputs beyond them.

use super::{
    compare_note, failure_note, finite, format_number, in_range, palette, Frame, MeshId, Runner,
    DEFAULT_RUNNER,
};
use crate::camera::{point_on_view_plane, project_to_canvas};
use crate::draw::inset::InsetView;
use crate::exercises::run;
use crate::rotation::angle_between;
use crate::skeleton::{
    crossfade_transform, human, local_to_model, sample_rotation_channel, Clip, ClipCursor,
    KeyInterpolation, Pose, QuatInterpolation, RawClip, Skeleton,
};
use crate::transform::JointShape;
use glam::{Affine3A, EulerRot, Mat4, Quat, Vec2, Vec3};

const DEG: f32 = std::f32::consts::PI / 180.0;
const EXERCISE_FILE: &str = "src/exercises/skeleton.rs";
/// How close the student's matrices and quaternions must be to the reference's.
const TOLERANCE: f32 = 1e-4;
/// Dots along the bone-tip path, per cycle.
const TRAIL_DOTS: usize = 60;
/// Radius of a joint's sphere, metres.
const JOINT_RADIUS: f32 = 0.022;
/// Length of the equal-time ticks across a path, CSS pixels, and how far they sit beside it
/// when two paths are compared, metres.
const PATH_TICK_PX: f32 = 14.0;
/// The most a path's tick is long across it, in average spacings between ticks on the canvas.
const PATH_TICK_SPACINGS: f32 = 1.5;
const TICK_OFFSET_M: f32 = 0.025;
/// The shortest tick that shows its colour inside its dark rim, CSS pixels; a lone path whose
/// ticks would be shorter is drawn [`LONE_PATH_PX`] wide without them.
const READABLE_TICK_PX: f32 = 7.0;
const LONE_PATH_PX: f32 = 4.0;
/// The width round the selected joint (its ball and the root of its axes) that its name keeps
/// clear of, CSS pixels.
const NAME_CLEAR_PX: f32 = 14.0;
/// A joint can be picked this many CSS pixels from its centre, however small it is drawn.
const PICK_RADIUS_PX: f32 = 10.0;
/// Where the crossfade's two clips stand beside the blend, metres along x (A left, B right).
pub const SOURCE_OFFSET_X: f32 = 1.4;
/// The share of the paths' box's larger side added at the top of the inset, under its title.
pub const INSET_TITLE_ROOM: f32 = 0.3;
/// Room kept around the skeleton's box for the joint boxes, the head and the labels, metres.
const VIEW_MARGIN_M: f32 = 0.18;

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
    /// The interpolation the second path uses, its clip (the playing one with that mode), and
    /// the path.
    compare: Option<(KeyInterpolation, QuatInterpolation)>,
    compare_clip: Option<Clip>,
    compare_trail: Vec<Vec3>,
    /// The crossfade's clip A and clip B as they play alone (model matrices), while blending.
    sources: [Vec<Affine3A>; 2],
    /// The box every joint stays in over one cycle, with the current settings.
    bounds: (Vec3, Vec3),
    /// The box of the two compared paths, which the inset shows close up.
    paths_box: (Vec3, Vec3),
    /// The camera and canvas size (CSS pixels) of the last frame, which the selected joint's
    /// name is placed for.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

impl Default for SkeletonFigure {
    fn default() -> Self {
        Self::new()
    }
}

/// What the interpolation dropdown offers, in order.
pub const INTERPOLATIONS: [&str; 4] = ["step", "linear (nlerp)", "linear (slerp)", "cubic"];

impl SkeletonFigure {
    /// The simple human playing the walk, keyed 9 times per cycle, linear with slerp, `thigh.L`
    /// selected, every joint's axes shown; no body boxes, no offsets on the clip, no second path,
    /// no crossfade, and "use my exercise" off (the runner calls the exercises in-process).
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
            compare: None,
            compare_clip: None,
            compare_trail: Vec::with_capacity(TRAIL_DOTS + 1),
            sources: [Vec::new(), Vec::new()],
            bounds: (Vec3::ZERO, Vec3::ZERO),
            paths_box: (Vec3::ZERO, Vec3::ZERO),
            view: None,
            skeleton,
            shapes,
        };
        let keys = figure.keys_per_cycle;
        figure
            .rebuild_clips(keys)
            .expect("the built-in clips build");
        figure
    }

    /// Builds every clip at `keys` keys per cycle into new lists, then swaps them in: a clip that
    /// fails to build leaves the figure's clips (and its key count) as they were.
    fn rebuild_clips(&mut self, keys: usize) -> Result<(), String> {
        let mut raws = Vec::with_capacity(human::CLIP_NAMES.len());
        let mut clips = Vec::with_capacity(human::CLIP_NAMES.len());
        for index in 0..human::CLIP_NAMES.len() {
            let mut raw = human::clip_with_keys(&self.skeleton, index, keys)
                .ok_or_else(|| format!("keys per cycle: {keys} is out of range"))?;
            raw.set_interpolation(self.interpolation);
            raw.set_rotation_interpolation(self.rotation);
            let clip = Clip::from_raw(&raw, &self.skeleton).map_err(|e| e.to_string())?;
            raws.push(raw);
            clips.push(clip);
        }
        (self.keys_per_cycle, self.raw, self.clips) = (keys, raws, clips);
        self.refresh_compare();
        Ok(())
    }

    /// Rebuilds the second path's clip: the playing clip with the compared interpolation.
    fn refresh_compare(&mut self) {
        self.compare_clip = match (self.compare, self.clip) {
            (Some((interpolation, rotation)), Some(c)) => {
                let mut clip = self.clips[c].clone();
                clip.set_interpolation(interpolation);
                clip.set_rotation_interpolation(rotation);
                Some(clip)
            }
            _ => None,
        };
    }

    /// Draws a second path of the selected bone's tip, sampled with the interpolation `name`
    /// (one of [`INTERPOLATIONS`]), or none with "none"; the plots' last two columns follow it.
    pub fn set_compare(&mut self, name: &str) -> Result<(), String> {
        self.compare = match name {
            "none" => None,
            _ => Some(parse_interpolation(name, self.rotation)?),
        };
        self.refresh_compare();
        Ok(())
    }

    /// The compared interpolation's name, or "none".
    pub fn compare_name(&self) -> &'static str {
        match self.compare {
            None => "none",
            Some(mode) => interpolation_name(mode),
        }
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
            None if name == "none" || name == "none (rest pose)" => None,
            None => return Err(format!("clip: no clip named {name:?}")),
        };
        self.cursor = ClipCursor::new();
        self.refresh_compare();
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
            self.rebuild_clips(keys)?;
        }
        Ok(())
    }

    /// One of [`INTERPOLATIONS`]: "step", "linear (nlerp)", "linear (slerp)" or "cubic"; a bare
    /// "linear" keeps the current rotation choice.
    pub fn set_interpolation(&mut self, name: &str) -> Result<(), String> {
        let (interpolation, rotation) = parse_interpolation(name, self.rotation)?;
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
    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the selected joint's name is placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

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
        self.sample_with(self.clip.map(|c| &self.clips[c]), time_sec, cursor, pose);
    }

    /// As [`SkeletonFigure::sample_into`], with `clip` in place of the playing clip (the same
    /// clip under another interpolation, for the second path).
    fn sample_with(
        &self,
        clip: Option<&Clip>,
        time_sec: f32,
        cursor: &mut ClipCursor,
        pose: &mut Pose,
    ) {
        match clip {
            Some(clip) => clip.sample(time_sec, cursor, pose),
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

    /// Model matrices of the crossfade's clip `k` (0: A, the playing clip; 1: B) alone at
    /// `time_sec` (no offsets), shifted to its place beside the blend.
    fn source_model(&self, k: usize, time_sec: f32, pose: &mut Pose, model: &mut Vec<Affine3A>) {
        let (clip, t, dx) = match (k, self.blend_clip) {
            (0, _) => (self.clip, time_sec, -SOURCE_OFFSET_X),
            (_, Some(b)) => (Some(b), self.blend_time(b, time_sec), SOURCE_OFFSET_X),
            (_, None) => (None, time_sec, SOURCE_OFFSET_X),
        };
        match clip {
            Some(c) => self.clips[c].sample(t, &mut ClipCursor::new(), pose),
            None => pose.local.copy_from_slice(self.skeleton.rest()),
        }
        model.resize(self.skeleton.len(), Affine3A::IDENTITY);
        local_to_model(
            self.skeleton.parents(),
            &pose.local,
            self.skeleton.scale_mode(),
            model,
        );
        for m in model.iter_mut() {
            m.translation.x += dx;
        }
    }

    /// The crossfade's two clips as they play alone, left (A) and right (B) of the blend; empty
    /// without a blend.
    pub fn sources(&self) -> &[Vec<Affine3A>; 2] {
        &self.sources
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
        let mut sources = std::mem::take(&mut self.sources);
        if self.blend_clip.is_some() {
            let mut pose = std::mem::replace(&mut self.scratch_pose, Pose::identity(0));
            for (k, model) in sources.iter_mut().enumerate() {
                self.source_model(k, t, &mut pose, model);
            }
            self.scratch_pose = pose;
        } else {
            sources.iter_mut().for_each(Vec::clear);
        }
        self.sources = sources;
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
                " Crossfaded with {} at weight {} (same phase of its own cycle); left, in blue: {} \
                 alone; right, in brown: {} alone.",
                self.clips[b].name(),
                format_number(self.blend_weight),
                clip.name(),
                self.clips[b].name(),
            ),
            None => String::new(),
        };
        let compare = match self.compare {
            Some(mode) => format!(
                " Paths of the {} tip over one cycle, a tick every 1/{} of it: purple {}, \
                 blue {}.",
                names[j],
                TRAIL_DOTS / 2,
                interpolation_name((self.interpolation, self.rotation)),
                interpolation_name(mode)
            ),
            None => String::new(),
        };
        // Fixed decimals: a timeline back at its start can pass a time of a few 1e-16 s,
        // which format_number would print in scientific notation.
        format!(
            "{joint} Clip {} at {local:.3} s: between keys {i} and {} (s = {:.3}), \
             {how}.{blend}{compare}",
            clip.name(),
            i + 1,
            s.clamp(0.0, 1.0),
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
        let yours =
            match run::sample_rotation_slerp(self.runner, times.clone(), keys.clone(), local) {
                Ok(q) => q,
                Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
            };
        let aligned = if yours.dot(reference) < 0.0 {
            -yours
        } else {
            yours
        };
        let at = format!("t = {local:.3} s ({})", self.skeleton.names()[j]);
        let (ok, note) = compare_note(
            "sample_rotation_slerp",
            &at,
            &aligned.to_array(),
            &reference.to_array(),
            TOLERANCE,
        );
        let note = note + &self.probe_sample_rotation(&times, &keys);
        if ok || yours.is_finite() && (yours.length() - 1.0).abs() < 0.1 {
            // Pose with the student's answer (offsets on top, as for the reference).
            let o = self.offsets_rad[j];
            self.pose.local[j].rotation =
                (yours.normalize() * Quat::from_euler(EulerRot::XYZ, o.x, o.y, o.z)).normalize();
        }
        note
    }

    /// Exercise 6.2 on this channel at times the playing clip does not reach (on a key, before
    /// the first key, after the last) and with a key negated (the short-arc rule).
    fn probe_sample_rotation(&self, times: &[f32], keys: &[Quat]) -> String {
        let n = times.len();
        if n < 2 {
            return String::new();
        }
        let mut flipped = keys.to_vec();
        flipped[1] = -flipped[1];
        let middle = 0.5 * (times[0] + times[1]);
        let probes = [
            ("on key 1", times[1], keys),
            ("before the first key", times[0] - 0.25, keys),
            ("after the last key", times[n - 1] + 0.25, keys),
            (
                "key 1 negated (q₀·q₁ < 0: the short arc)",
                middle,
                &flipped[..],
            ),
        ];
        let mut asked = 0;
        let mut differing = Vec::new();
        for (name, t, keys) in probes {
            let reference = sample_rotation_channel(times, keys, t, QuatInterpolation::Slerp);
            let Ok(yours) =
                run::sample_rotation_slerp(self.runner, times.to_vec(), keys.to_vec(), t)
            else {
                continue;
            };
            asked += 1;
            // q and −q are the same rotation.
            let aligned = if yours.dot(reference) < 0.0 {
                -yours
            } else {
                yours
            };
            if !aligned.abs_diff_eq(reference, TOLERANCE) {
                differing.push(format!("{name} (t = {} s)", format_number(t)));
            }
        }
        probe_summary("sample_rotation_slerp", asked, &differing)
    }

    /// Exercise 6.3 at weights and rotations the slider may not show: w = 0, w = 1, and q_b on
    /// the other hemisphere (q_a·q_b < 0).
    fn probe_crossfade(&self) -> String {
        let (ta, qa) = (Vec3::new(0.1, 0.9, 0.0), Quat::from_rotation_x(0.5));
        let (tb, qb) = (Vec3::new(-0.2, 1.0, 0.3), Quat::from_rotation_y(1.0));
        let probes = [
            ("w = 0", qb, 0.0),
            ("w = 1", qb, 1.0),
            ("q_b negated (q_a·q_b < 0), w = 0.3", -qb, 0.3),
        ];
        let mut asked = 0;
        let mut differing = Vec::new();
        for (name, qb, w) in probes {
            let Ok((t, q)) = run::crossfade_joint(self.runner, ta, qa, tb, qb, w) else {
                continue;
            };
            asked += 1;
            let (rt, rq) = crate::exercises::skeleton::reference_crossfade_joint(ta, qa, tb, qb, w);
            let q = if q.dot(rq) < 0.0 { -q } else { q };
            if !(t.abs_diff_eq(rt, TOLERANCE) && q.abs_diff_eq(rq, TOLERANCE)) {
                differing.push(name.to_string());
            }
        }
        probe_summary("crossfade_joint", asked, &differing)
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
        let note = match first_wrong {
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
        };
        note + &self.probe_crossfade()
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
        note + &self.probe_local_to_model()
    }

    /// Exercise 6.1 at small skeletons the figure's human never shows: two roots, a parent
    /// listed two places back, a non-uniform scale passed on to a turned child.
    fn probe_local_to_model(&self) -> String {
        use crate::skeleton::{ScaleMode, Transform};
        let turn = Quat::from_rotation_z(0.7) * Quat::from_rotation_x(-0.4);
        let probes: [(&str, Vec<i32>, Vec<Vec3>); 3] = [
            ("two roots", vec![-1, 0, -1, 2], vec![Vec3::ONE; 4]),
            (
                "a parent listed two places back",
                vec![-1, 0, 0, 2, 1],
                vec![Vec3::ONE; 5],
            ),
            (
                "a non-uniform scale (2, 0.5, 1) on the root, passed on to its turned children",
                vec![-1, 0, 1],
                vec![Vec3::new(2.0, 0.5, 1.0), Vec3::ONE, Vec3::ONE],
            ),
        ];
        let mut asked = 0;
        let mut differing = Vec::new();
        for (name, parents, scales) in probes {
            let n = parents.len();
            let translations: Vec<Vec3> = (0..n)
                .map(|i| Vec3::new(0.1 * i as f32, 0.3, -0.05 * i as f32))
                .collect();
            let rotations: Vec<Quat> = (0..n)
                .map(|i| if i % 2 == 0 { turn } else { turn.inverse() })
                .collect();
            let local: Vec<Transform> = (0..n)
                .map(|i| Transform {
                    translation: translations[i],
                    rotation: rotations[i],
                    scale: scales[i],
                })
                .collect();
            let mut reference = vec![Affine3A::IDENTITY; n];
            local_to_model(&parents, &local, ScaleMode::Inherited, &mut reference);
            let parents_f: Vec<f32> = parents.iter().map(|&p| p as f32).collect();
            let Ok(yours) =
                run::local_to_model(self.runner, parents_f, translations, rotations, scales)
            else {
                continue;
            };
            asked += 1;
            let close = yours.len() == n
                && yours
                    .iter()
                    .zip(&reference)
                    .all(|(y, r)| y.abs_diff_eq(Mat4::from(*r), 1e-4));
            if !close {
                differing.push(name.to_string());
            }
        }
        probe_summary("local_to_model", asked, &differing)
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

    /// The selected bone tip's paths over one cycle (with the playing interpolation and, when
    /// set, the compared one), the box the camera keeps in view (every joint over the cycle, the
    /// crossfade's two clips too, and the floor) and the box of the paths, for the inset.
    fn compute_trail(&mut self) {
        self.trail.clear();
        self.compare_trail.clear();
        let mut lo = Vec3::splat(f32::INFINITY);
        let mut hi = Vec3::splat(f32::NEG_INFINITY);
        let mut grow = |p: Vec3| {
            lo = lo.min(p);
            hi = hi.max(p);
        };
        for m in &self.model {
            grow(m.translation.into());
        }
        let mut pose = std::mem::replace(&mut self.scratch_pose, Pose::identity(0));
        let mut model = std::mem::take(&mut self.scratch_model);
        if self.clip.is_some() {
            let d = self.duration_sec();
            let mut paths = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
            let main = self.clip.map(|c| &self.clips[c]);
            for (clip, path) in [(main, 0), (self.compare_clip.as_ref(), 1)] {
                let Some(clip) = clip else { continue };
                let mut cursor = ClipCursor::new();
                for k in 0..=TRAIL_DOTS {
                    let t = d * k as f32 / TRAIL_DOTS as f32 * 0.99999;
                    self.sample_with(Some(clip), t, &mut cursor, &mut pose);
                    local_to_model(
                        self.skeleton.parents(),
                        &pose.local,
                        self.skeleton.scale_mode(),
                        &mut model,
                    );
                    let tip = self.tip(&model);
                    if path == 0 {
                        self.trail.push(tip);
                    } else {
                        self.compare_trail.push(tip);
                    }
                    paths = (paths.0.min(tip), paths.1.max(tip));
                    grow(tip);
                    model.iter().for_each(|m| grow(m.translation.into()));
                    if self.show_boxes {
                        for (shape, m) in self.shapes.iter().zip(&model) {
                            for corner in box_corners(shape) {
                                grow(m.transform_point3(corner));
                            }
                        }
                    }
                }
            }
            // The paths' box, at least 8 cm across, so that a path a few centimetres long
            // fills the inset without its ticks (TICK_OFFSET_M beside it) leaving it.
            let middle = 0.5 * (paths.0 + paths.1);
            let half = (0.5 * (paths.1 - paths.0)).max(Vec3::splat(0.04));
            self.paths_box = (middle - half, middle + half);
            if self.blend_clip.is_some() {
                for k in 0..2 {
                    for step in 0..=12 {
                        let t = d * step as f32 / 12.0 * 0.99999;
                        self.source_model(k, t, &mut pose, &mut model);
                        model.iter().for_each(|m| {
                            lo = lo.min(m.translation.into());
                            hi = hi.max(m.translation.into());
                        });
                    }
                }
            }
        }
        self.scratch_pose = pose;
        self.scratch_model = model;
        // Room for the labels round the body, and the floor under the feet in view; below the
        // floor nothing is drawn but the lowest joints' balls, so the box stops there.
        let floor = lo.y.min(0.0) - 1.5 * JOINT_RADIUS;
        lo -= Vec3::splat(VIEW_MARGIN_M);
        lo.y = floor;
        self.bounds = (lo, hi + Vec3::splat(VIEW_MARGIN_M));
    }

    /// The box the camera keeps in view ([`Frame::keep_in_view`]), from the last pose.
    pub fn view_bounds(&self) -> (Vec3, Vec3) {
        self.bounds
    }

    /// The second path (the compared interpolation), empty when none is compared.
    pub fn compare_trail(&self) -> &[Vec3] {
        &self.compare_trail
    }

    /// The joint under the pointer at `pointer` (CSS pixels on a canvas of `size`, seen through
    /// `view_proj`): the nearest joint sphere the pointer's ray meets, each sphere at least
    /// [`PICK_RADIUS_PX`] across on screen; `None` when the ray misses them all.
    pub fn pick_joint(&self, view_proj: Mat4, size: Vec2, pointer: Vec2) -> Option<usize> {
        if !(pointer.is_finite() && size.x > 0.0 && size.y > 0.0) {
            return None;
        }
        let inverse = view_proj.inverse();
        let unproject = |z: f32| {
            let ndc = Vec3::new(
                2.0 * pointer.x / size.x - 1.0,
                1.0 - 2.0 * pointer.y / size.y,
                z,
            );
            inverse.project_point3(ndc)
        };
        let origin = unproject(0.0);
        let dir = (unproject(1.0) - origin).try_normalize()?;
        let mut best: Option<(f32, usize)> = None;
        for (j, m) in self.model.iter().enumerate() {
            let c: Vec3 = m.translation.into();
            // The sphere's radius, or what PICK_RADIUS_PX pixels measure at its depth.
            let radius = project_to_canvas(view_proj, size, c)
                .and_then(|px| {
                    point_on_view_plane(view_proj, size, c, px + Vec2::new(PICK_RADIUS_PX, 0.0))
                })
                .map_or(1.5 * JOINT_RADIUS, |edge| {
                    edge.distance(c).max(1.5 * JOINT_RADIUS)
                });
            // Ray against sphere: |origin + s·dir − c| = radius.
            let oc = origin - c;
            let b = oc.dot(dir);
            let disc = b * b - (oc.length_squared() - radius * radius);
            if disc < 0.0 {
                continue;
            }
            if -b + disc.sqrt() < 0.0 {
                continue; // behind the eye
            }
            // Of the spheres hit, the one whose centre the ray passes closest to (relative to
            // its size): where joints crowd, the one the pointer is on.
            let miss = (oc.length_squared() - b * b).max(0.0).sqrt() / radius;
            if best.is_none_or(|(d, _)| miss < d) {
                best = Some((miss, j));
            }
        }
        best.map(|(_, j)| j)
    }

    /// The path of the selected bone's tip over one cycle (dots at equal time steps).
    pub fn trail(&self) -> &[Vec3] {
        &self.trail
    }

    /// Poses at `time_sec` and draws. Returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let note = self.pose(time_sec)?;
        frame.grid(12, 0.25);
        if self.compare_clip.is_none() && self.blend_clip.is_none() {
            // The world's axes at the feet; their letters (where one skeleton stands alone: at
            // the crossfade's feet they would lie on its legs and paths) once the legs are drawn.
            frame.axes(Mat4::IDENTITY, 0.3);
        }
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
                // Inside the body boxes, the group's bones are drawn again over them.
                if self.show_boxes && bone_color == palette::TEAL {
                    frame.wide_line_on_top(a, p, bone_color, 3.0);
                }
            }
            // The selected joint and its group over the body boxes, which hide their balls.
            if self.show_boxes && color(i) != palette::DARK {
                frame.marker_on_top(p, if i == self.selected { 14.0 } else { 10.0 }, color(i));
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
            let lowest = self
                .model
                .iter()
                .map(|m| m.translation.y)
                .fold(f32::MAX, f32::min);
            frame.contact_shadow(Vec3::new(middle.x, lowest.max(0.0), middle.z), 0.25);
        }
        let selected = Mat4::from(self.model[self.selected]);
        // Its axes; their letters once its name is placed.
        frame.axes(selected, 0.18);
        let main_step = self.interpolation == KeyInterpolation::Step;
        let compare_step = matches!(self.compare, Some((KeyInterpolation::Step, _)));
        // While comparing, the two paths often lie on one another: the purple ticks go just
        // outside the path (away from the joint's pivot), the blue ones just inside.
        let pivot: Vec3 = self.model[self.selected].translation.into();
        let (outside, inside) = if self.compare_clip.is_some() {
            (TICK_OFFSET_M, -TICK_OFFSET_M)
        } else {
            (0.0, 0.0)
        };
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // The inset draws these strokes and markers alone: the paths and their ticks.
        let first = [frame.strokes.len(), frame.markers.len()];
        draw_path(
            frame,
            &self.trail,
            palette::PURPLE,
            main_step,
            pivot,
            outside,
            view,
        );
        draw_path(
            frame,
            &self.compare_trail,
            palette::BLUE,
            compare_step,
            pivot,
            inside,
            view,
        );
        let paths = [first[0]..frame.strokes.len(), first[1]..frame.markers.len()];
        // The crossfade's two clips alone, beside the blend.
        let source_names = [
            self.clip_name(),
            self.blend_clip
                .map_or(String::new(), |b| human::CLIP_NAMES[b].to_string()),
        ];
        for ((model, color), name) in self
            .sources
            .iter()
            .zip([palette::BLUE, palette::BROWN])
            .zip(source_names)
        {
            if model.is_empty() {
                continue;
            }
            for (i, &parent) in parents.iter().enumerate() {
                let p: Vec3 = model[i].translation.into();
                frame.mesh(
                    MeshId::SPHERE,
                    Mat4::from_scale_rotation_translation(
                        Vec3::splat(JOINT_RADIUS),
                        Quat::IDENTITY,
                        p,
                    ),
                    color,
                );
                if parent >= 0 {
                    bone(frame, model[parent as usize].translation.into(), p, color);
                }
            }
            let top = model
                .iter()
                .map(|m| Vec3::from(m.translation))
                .fold(Vec3::splat(f32::NEG_INFINITY), Vec3::max);
            let root: Vec3 = model[0].translation.into();
            frame.label(
                Vec3::new(root.x - 0.15, top.y + 0.12, root.z),
                format!("{name} alone"),
                color,
            );
            frame.contact_shadow(Vec3::new(root.x, 0.0, root.z), 0.25);
        }
        // The joint's name up and to the right of it; where the ring of path ticks, a bone or
        // the crossfade's clips alone (and their names) lie there on the last frame's view, the
        // first place round the joint clear of them by a few pixels, up and to the right first.
        let p = selected.w_axis.truncate();
        let name = self.skeleton.names()[self.selected].clone();
        let first = crate::draw::Label {
            anchor: p + Vec3::new(0.05, 0.05, 0.0),
            text: name.clone(),
            color: palette::ORANGE,
            left: false,
            priority: 0,
            offset_px: Vec2::ZERO,
            large: false,
        };
        let around = crate::draw::Label::around_dot(
            p,
            NAME_CLEAR_PX,
            Vec2::new(1.0, -1.0),
            &name,
            palette::ORANGE,
            0,
            12,
            8.0,
        );
        // Points of the body boxes on the canvas (a 7 × 7 × 7 grid through each): the name keeps
        // off them, where it would read as a box's; the bones and balls add to them for the
        // world's letters below.
        let mut body_px = Vec::new();
        if let (Some((view_proj, size)), true) = (view, self.show_boxes) {
            for (shape, m) in self.shapes.iter().zip(&self.model) {
                let model = Mat4::from(*m)
                    * Mat4::from_translation(shape.center)
                    * Mat4::from_scale(shape.half_extents);
                body_px.extend((0..343).filter_map(|i| {
                    let c = |k: i32| (k % 7) as f32 / 3.0 - 1.0;
                    let q = model.transform_point3(Vec3::new(c(i), c(i / 7), c(i / 49)));
                    project_to_canvas(view_proj, size, q)
                }));
            }
        }
        frame.first_clear_label_by(
            view,
            2.0,
            std::iter::once(first).chain(around),
            super::skinning::off_points(&body_px, 2.0),
        );
        // The letters of the joint's axes and of the world's, each beside its tip clear of the
        // bones, paths and names. The world's stand a few pixels further off the body too: its
        // y runs up between the legs, and a letter beside a leg reads as the leg's.
        letter_axes(frame, selected, 0.18, view, (&[], 4));
        if self.compare_clip.is_none() && self.blend_clip.is_none() {
            if let Some((view_proj, size)) = view {
                for (i, &parent) in parents.iter().enumerate() {
                    let b: Vec3 = self.model[i].translation.into();
                    let a: Vec3 = self.model[parent.max(0) as usize].translation.into();
                    // Every 2 px or so along the bone at the page's zoom.
                    body_px.extend((0..=32).filter_map(|k| {
                        project_to_canvas(view_proj, size, a.lerp(b, k as f32 / 32.0))
                    }));
                }
            }
            letter_axes(frame, Mat4::IDENTITY, 0.3, view, (&body_px, 12));
        }
        frame.keep_box_in_view(self.bounds.0, self.bounds.1);
        if self.compare_clip.is_some() {
            // The two paths close up, seen along the axis they extend least along (across the
            // plane they mostly lie in), whatever the main view's distance and angle.
            // The box grows at the inset's top by INSET_TITLE_ROOM of its larger side across,
            // so that the paths and their ticks lie under the inset's title, not behind it.
            let (mut lo, mut hi) = self.paths_box;
            let extent = hi - lo;
            let room = INSET_TITLE_ROOM * extent.max_element();
            let along = if extent.y <= extent.x.min(extent.z) {
                // Seen from above, −z is up the inset.
                lo.z -= room;
                InsetView::Top
            } else {
                hi.y += room;
                if extent.x <= extent.z {
                    InsetView::Side
                } else {
                    InsetView::Front
                }
            };
            frame.inset(along, "paths, close up", lo, hi);
            if let Some(inset) = &mut frame.inset {
                inset.only = Some(paths);
            }
        }
        Ok(note)
    }

    /// One cycle of the selected joint's rotation for the plots: `[t, angle, speed, angle₂,
    /// speed₂, angle_A, angle_B, …]`, the angle (degrees) of its local rotation from its rest rotation and the
    /// angular speed (degrees per second, by finite differences), `samples` times over the clip,
    /// with the current interpolation and offsets; `angle₂` and `speed₂` are the same under the
    /// compared interpolation (a copy of the first two when none is compared); then the angle
    /// under clip A alone and under clip B alone while crossfading (`[…, angle_A, angle_B]`,
    /// without offsets; both the playing clip's without a blend).
    pub fn sample_selected(&self, samples: usize) -> Result<Vec<f32>, String> {
        super::check_samples(samples)?;
        let d = self.duration_sec();
        let j = self.selected;
        let rest = self.skeleton.rest()[j].rotation;
        let mut pose = self.skeleton.rest_pose();
        let dt = d / (samples - 1) as f32;
        let main = self.clip.map(|c| &self.clips[c]);
        let second = self.compare_clip.as_ref().or(main);
        let mut series = [Vec::with_capacity(samples), Vec::with_capacity(samples)];
        for (clip, rotations) in [main, second].into_iter().zip(&mut series) {
            let mut cursor = ClipCursor::new();
            for k in 0..samples {
                let t = (k as f32 * dt).min(d * 0.99999);
                self.sample_with(clip, t, &mut cursor, &mut pose);
                rotations.push(pose.local[j].rotation);
            }
        }
        // The crossfade's clips alone (no offsets): A is the playing clip, B the blended one at
        // the same phase; without a blend both are the playing clip.
        let mut alone = [Vec::with_capacity(samples), Vec::with_capacity(samples)];
        for (k, rotations) in alone.iter_mut().enumerate() {
            let (clip, scale) = match (k, self.blend_clip) {
                (1, Some(b)) => (Some(b), self.clips[b].duration_sec() / d),
                _ => (self.clip, 1.0),
            };
            let mut cursor = ClipCursor::new();
            for i in 0..samples {
                let t = (i as f32 * dt).min(d * 0.99999) * scale;
                match clip {
                    Some(c) => self.clips[c].sample(t, &mut cursor, &mut pose),
                    None => pose.local.copy_from_slice(self.skeleton.rest()),
                }
                rotations.push(pose.local[j].rotation);
            }
        }
        let mut out = Vec::with_capacity(7 * samples);
        for k in 0..samples {
            let (a, b) = if k + 1 < samples {
                (k, k + 1)
            } else {
                (k - 1, k)
            };
            out.push(k as f32 * dt);
            for rotations in &series {
                out.push(angle_between(rest, rotations[k]) / DEG);
                out.push(angle_between(rotations[a], rotations[b]) / dt / DEG);
            }
            for rotations in &alone {
                out.push(angle_between(rest, rotations[k]) / DEG);
            }
        }
        Ok(out)
    }
}

/// The modes an entry of [`INTERPOLATIONS`] names; a bare "linear" keeps `rotation`.
fn parse_interpolation(
    name: &str,
    rotation: QuatInterpolation,
) -> Result<(KeyInterpolation, QuatInterpolation), String> {
    Ok(match name {
        "step" => (KeyInterpolation::Step, rotation),
        "linear" => (KeyInterpolation::Linear, rotation),
        "linear (nlerp)" => (KeyInterpolation::Linear, QuatInterpolation::Nlerp),
        "linear (slerp)" => (KeyInterpolation::Linear, QuatInterpolation::Slerp),
        "cubic" => (KeyInterpolation::Cubic, rotation),
        _ => {
            return Err(format!(
                "interpolation must be one of {}, got {name:?}",
                INTERPOLATIONS.join(", ")
            ))
        }
    })
}

/// The entry of [`INTERPOLATIONS`] for a pair of modes.
fn interpolation_name(
    (interpolation, rotation): (KeyInterpolation, QuatInterpolation),
) -> &'static str {
    match (interpolation, rotation) {
        (KeyInterpolation::Step, _) => INTERPOLATIONS[0],
        (KeyInterpolation::Linear, QuatInterpolation::Nlerp) => INTERPOLATIONS[1],
        (KeyInterpolation::Linear, QuatInterpolation::Slerp) => INTERPOLATIONS[2],
        (KeyInterpolation::Cubic, _) => INTERPOLATIONS[3],
    }
}

/// What a check at probe inputs found: "" when every probe the student's code answered
/// matches and none was asked, else which of the `asked` probes differ.
pub(crate) fn probe_summary(function: &str, asked: usize, differing: &[String]) -> String {
    if asked == 0 {
        String::new()
    } else if differing.is_empty() {
        format!(" It also matches at {asked} probe inputs beyond the shown one.")
    } else {
        format!(
            " Of {asked} probe inputs beyond the shown one, your {function} differs at {}: {}.",
            differing.len(),
            differing.join("; ")
        )
    }
}

/// The eight corners of a joint's body box, in the joint's frame.
fn box_corners(shape: &JointShape) -> impl Iterator<Item = Vec3> + '_ {
    (0..8).map(move |i| {
        let sign = |bit: usize| if i & bit == 0 { -1.0 } else { 1.0 };
        shape.center + shape.half_extents * Vec3::new(sign(1), sign(2), sign(4))
    })
}

/// A path of equal-time samples: a wide line with a tick at each sample, or, for step keys
/// (where the pose jumps), a dot at each sample, so the dots pile up on the keys.
/// The ticks (or dots) sit `offset` metres from the path, away from `pivot` (towards it when
/// negative). On the last frame's `view` (view-projection, canvas size in CSS pixels) the ticks
/// are [`PATH_TICK_SPACINGS`] times as long across the path as they are apart on average, from
/// [`crate::draw::MIN_MARKER_PX`] to [`PATH_TICK_PX`]; a lone path (`offset` 0) whose ticks
/// would be shorter than [`READABLE_TICK_PX`] is drawn wider, without them.
fn draw_path(
    frame: &mut Frame,
    path: &[Vec3],
    color: Vec3,
    step: bool,
    pivot: Vec3,
    offset: f32,
    view: Option<(Mat4, Vec2)>,
) {
    if path.len() < 2 {
        return;
    }
    // Every other sample: 30 ticks a cycle stay apart on a small path.
    let samples: Vec<Vec3> = path[..path.len() - 1]
        .iter()
        .step_by(2)
        .map(|&p| p + (p - pivot).normalize_or_zero() * offset)
        .collect();
    if step {
        for &p in &samples {
            frame.marker(p, crate::draw::DOT_PX, color);
        }
    } else {
        // A path a few tens of pixels long on the canvas has its ticks a pixel or two apart:
        // full-length ticks there merge into a hatched smudge wider than the path is long.
        let tick_px = view
            .and_then(|(view_proj, size)| {
                let on_canvas = samples
                    .iter()
                    .map(|&p| project_to_canvas(view_proj, size, p))
                    .collect::<Option<Vec<Vec2>>>()?;
                let length: f32 = on_canvas.windows(2).map(|w| w[0].distance(w[1])).sum();
                Some(PATH_TICK_SPACINGS * length / (on_canvas.len().max(2) - 1) as f32)
            })
            .map_or(PATH_TICK_PX, |px| {
                px.clamp(crate::draw::MIN_MARKER_PX, PATH_TICK_PX)
            });
        // Over everything (a tick's negative size too): the path runs through the tip's own
        // ball, 4.4 cm across, which would hide much of a path a few centimetres long, in the
        // inset above all. A lone path (`offset` 0: no compared path, no inset) too short for
        // readable ticks goes without them: ticks that small are all dark rim,
        // and the path read as grey.
        let lone = offset == 0.0 && tick_px < READABLE_TICK_PX;
        let style = crate::draw::StrokeStyle {
            on_top: true,
            ..crate::draw::StrokeStyle::solid(if lone { LONE_PATH_PX } else { crate::draw::CURVE_PX })
        };
        frame.stroke(path, color, style);
        if lone {
            return;
        }
        let first = frame.markers.len();
        frame.ticks(&samples, tick_px, color);
        for tick in &mut frame.markers[first..] {
            tick.size_px = -tick.size_px.abs();
        }
    }
}

/// The letters x, y and z of the axes that `m` places, `length` long: each at the first place
/// round its tip, away from the axes' origin on screen first, that keeps 1 px off the dots and
/// lines, clear of the labels and 6 px off the points `body` (canvas pixels) on the last
/// frame's view (`view`), up to `steps` places of 6 px out (past 20 px, the page draws a leader
/// from the tip).
fn letter_axes(
    frame: &mut Frame,
    m: Mat4,
    length: f32,
    view: Option<(Mat4, Vec2)>,
    (body, steps): (&[Vec2], usize),
) {
    let o = m.transform_point3(Vec3::ZERO);
    for (axis, color, name) in [
        (Vec3::X, palette::X_AXIS, "x"),
        (Vec3::Y, palette::Y_AXIS, "y"),
        (Vec3::Z, palette::Z_AXIS, "z"),
    ] {
        let tip = o + m.transform_vector3(axis) * length;
        let on_screen = |p: Vec3| view.and_then(|(vp, size)| project_to_canvas(vp, size, p));
        let toward = on_screen(tip)
            .zip(on_screen(o))
            .map_or(Vec2::ZERO, |(t, o)| t - o);
        let candidates =
            crate::draw::Label::around_dot(tip, 6.0, toward, name, color, 0, steps, 6.0);
        frame.first_clear_label_by(view, 1.0, candidates, super::skinning::off_points(body, 6.0));
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
    frame.wide_line(a, b, color, 2.0);
}
