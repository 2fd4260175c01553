//! Figure logic for lesson 08, "Blending" (see [`crate::figures`]).
//!
//! [`BlendFigure`]: the simple human crossfading two clips (clip B at the same phase as clip A),
//! with a mask (whole body, upper or lower body from B) and an additive layer (a lean pose or the
//! wave clip, each made relative to the rest pose) on top; with "use my exercise" every joint is
//! blended by the student's 6.3 `crossfade_joint` and compared with the reference.
//!
//! [`LocomotionFigure`]: the travelling walk and run blended for a speed, synchronised (normalised
//! time) or not, with root motion extracted and applied to the character or left in the pose; the
//! footprints of the last second and a half show whether the feet slide. Which foot is planted
//! comes from the clips' own contacts ([`crate::skeleton::Contact`]), blended as the poses are.

use super::{
    compare_note, failure_note, finite, format_number, in_range, palette, Failure, Frame, MeshId,
    Runner, DEFAULT_RUNNER,
};
use crate::exercises::run;
use crate::skeleton::{
    add_additive, blend_contacts, crossfade_transform, human, local_to_model, make_additive,
    sample_synchronised, subtree_mask, synchronised_contacts, synchronised_cycle, weight_for_speed,
    Clip, ClipCursor, Pose, RootMotion, Skeleton,
};
use crate::transform::JointShape;
use crate::Valid;
use glam::{Affine3A, EulerRot, Mat4, Quat, Vec3};

const EXERCISE_FILE: &str = "src/exercises/skeleton.rs";
/// Where the lesson's own exercise, 8.1, lives.
const BLENDING_FILE: &str = "src/exercises/blending.rs";
/// How close the student's blend must be to the reference's.
const TOLERANCE: f32 = 1e-4;
const JOINT_RADIUS: f32 = 0.02;
/// The width of the lines between joints, CSS pixels.
const BONE_PX: f32 = 2.0;
/// The width of the ghost of the pose before the additive layer, CSS pixels.
const GHOST_PX: f32 = 3.0;

/// What the mask dropdown offers, in order.
pub const MASKS: [&str; 3] = ["whole body", "upper body from B", "lower body from B"];
/// What the additive dropdown offers, in order.
pub const ADDITIVES: [&str; 3] = ["none", "lean forward (a pose)", "wave (a clip)"];

/// The lesson's first figure: crossfade, mask, additive layer.
#[derive(Clone, Debug)]
pub struct BlendFigure {
    skeleton: Skeleton,
    shapes: Vec<JointShape>,
    clips: Vec<Clip>,
    a: usize,
    b: usize,
    weight: f32,
    mask: usize,
    additive: usize,
    additive_weight: f32,
    use_exercise: bool,
    runner: Runner,
    /// Where the student's 6.3 panicked (a joint and its weight, or a probe) and the panic's
    /// message. The page answers every later call of a panicked exercise with that message, so
    /// the figure keeps the input that caused it and uses the reference until the page reloads.
    exercise_panic: Option<(String, String)>,
    /// Per-joint weight of clip B for the current mask and weight.
    joint_weights: Vec<f32>,
    lean: Pose,
    pose_a: Pose,
    pose_b: Pose,
    pose: Pose,
    scratch: Pose,
    model: Vec<Affine3A>,
    /// The model matrices before the additive layer (drawn as a ghost when one is on).
    base_model: Vec<Affine3A>,
    /// The right upper arm and its child (the elbow): the joints the plot measures.
    arm: [usize; 2],
}

impl Default for BlendFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl BlendFigure {
    /// Walk (A) and wave (B) at weight 0.5, whole body, no additive layer.
    pub fn new() -> Self {
        let (skeleton, shapes) = human::simple_human();
        let clips = (0..human::CLIP_NAMES.len())
            .map(|i| {
                let raw = human::clip(&skeleton, i).expect("a built-in clip");
                Clip::from_raw(&raw, &skeleton).valid("the built-in clips build")
            })
            .collect();
        // The lean: spine and chest forward, head turned, as a difference from the rest pose.
        let mut lean_pose = skeleton.rest_pose();
        for (name, e) in [
            ("spine", Vec3::new(0.35, 0.0, 0.0)),
            ("chest", Vec3::new(0.25, 0.2, 0.0)),
            ("head", Vec3::new(-0.2, 0.5, 0.0)),
        ] {
            let j = skeleton.find(name).expect("a joint of the human");
            lean_pose.local[j].rotation *= Quat::from_euler(EulerRot::XYZ, e.x, e.y, e.z);
        }
        let mut lean = skeleton.rest_pose();
        make_additive(&lean_pose, &skeleton.rest_pose(), &mut lean).expect("same skeleton");
        let n = skeleton.len();
        let shoulder = skeleton.find("upper_arm.R").expect("a joint of the human");
        let elbow = (0..n)
            .find(|&j| skeleton.parents()[j] == shoulder as i32)
            .expect("the upper arm has a child");
        let mut figure = Self {
            arm: [shoulder, elbow],
            base_model: vec![Affine3A::IDENTITY; n],
            clips,
            a: 1,
            b: 3,
            weight: 0.5,
            mask: 0,
            additive: 0,
            additive_weight: 1.0,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            exercise_panic: None,
            joint_weights: vec![0.5; n],
            lean,
            pose_a: skeleton.rest_pose(),
            pose_b: skeleton.rest_pose(),
            pose: skeleton.rest_pose(),
            scratch: skeleton.rest_pose(),
            model: vec![Affine3A::IDENTITY; n],
            skeleton,
            shapes,
        };
        figure.update_weights();
        figure
    }

    pub fn clip_names(&self) -> Vec<String> {
        human::CLIP_NAMES.iter().map(|s| s.to_string()).collect()
    }

    fn clip_index(what: &str, name: &str) -> Result<usize, String> {
        human::CLIP_NAMES
            .iter()
            .position(|&c| c == name)
            .ok_or_else(|| format!("{what}: no clip named {name:?}"))
    }

    /// Clip A (the timeline follows it) and clip B (played at the same phase).
    pub fn set_clips(&mut self, a: &str, b: &str) -> Result<(), String> {
        let (a, b) = (
            Self::clip_index("clip A", a)?,
            Self::clip_index("clip B", b)?,
        );
        self.a = a;
        self.b = b;
        Ok(())
    }

    /// Weight of clip B in [0, 1] (0: all A).
    pub fn set_weight(&mut self, w: f32) -> Result<(), String> {
        self.weight = in_range("weight of B", w, 0.0, 1.0)?;
        self.update_weights();
        Ok(())
    }

    /// One of [`MASKS`].
    pub fn set_mask(&mut self, name: &str) -> Result<(), String> {
        self.mask = MASKS
            .iter()
            .position(|&m| m == name)
            .ok_or_else(|| format!("mask must be one of {}, got {name:?}", MASKS.join(", ")))?;
        self.update_weights();
        Ok(())
    }

    /// One of [`ADDITIVES`], with its weight in [0, 1].
    pub fn set_additive(&mut self, name: &str, weight: f32) -> Result<(), String> {
        // Both are checked before either changes: a rejected weight keeps the layer too.
        let additive = ADDITIVES.iter().position(|&m| m == name).ok_or_else(|| {
            format!(
                "additive layer must be one of {}, got {name:?}",
                ADDITIVES.join(", ")
            )
        })?;
        let weight = in_range("layer weight", weight, 0.0, 1.0)?;
        (self.additive, self.additive_weight) = (additive, weight);
        Ok(())
    }

    /// Blends every joint with the student's exercise 6.3 (through the runner).
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// A new runner (a rebuilt exercise) forgets an earlier panic.
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.exercise_panic = None;
    }

    fn update_weights(&mut self) {
        let spine = self.skeleton.find("spine").expect("a joint of the human");
        self.joint_weights = match self.mask {
            0 => vec![self.weight; self.skeleton.len()],
            1 => subtree_mask(&self.skeleton, spine, self.weight, 0.0),
            _ => subtree_mask(&self.skeleton, spine, 0.0, self.weight),
        };
    }

    /// Clip B's weight at each joint (for the tests and the colours).
    pub fn joint_weights(&self) -> &[f32] {
        &self.joint_weights
    }

    /// Clip A's duration, seconds (the timeline's).
    pub fn duration_sec(&self) -> f32 {
        self.clips[self.a].duration_sec()
    }

    pub fn skeleton(&self) -> &Skeleton {
        &self.skeleton
    }

    /// The blended local pose after the last [`BlendFigure::pose`].
    pub fn local_pose(&self) -> &Pose {
        &self.pose
    }

    /// Model-space position of a joint after the last pose.
    pub fn joint_position(&self, joint: usize) -> Option<Vec3> {
        self.model.get(joint).map(|m| m.translation.into())
    }

    /// Poses at `time_sec`: A and B at the same phase, crossfaded with the per-joint weights, the
    /// additive layer on top. Returns the note.
    pub fn pose(&mut self, time_sec: f32) -> Result<String, String> {
        let t = finite("time", time_sec)?;
        let (a, b) = (&self.clips[self.a], &self.clips[self.b]);
        let phase = (t / a.duration_sec()).rem_euclid(1.0);
        a.sample(t, &mut ClipCursor::new(), &mut self.pose_a);
        let tb = (phase * b.duration_sec()).min(b.duration_sec() * 0.999_999);
        b.sample(tb, &mut ClipCursor::new(), &mut self.pose_b);
        for (j, o) in self.pose.local.iter_mut().enumerate() {
            *o = crossfade_transform(
                &self.pose_a.local[j],
                &self.pose_b.local[j],
                self.joint_weights[j],
            );
        }
        let mut notes = vec![self.describe()];
        if self.use_exercise {
            notes.push(self.student_blend());
        }
        local_to_model(
            self.skeleton.parents(),
            &self.pose.local,
            self.skeleton.scale_mode(),
            &mut self.base_model,
        );
        if self.additive != 0 {
            let mut layered = Pose {
                local: std::mem::take(&mut self.scratch.local),
            };
            let added = self.add_layer(&self.pose, phase, &mut layered);
            self.scratch = std::mem::replace(&mut self.pose, layered);
            added?;
        }
        local_to_model(
            self.skeleton.parents(),
            &self.pose.local,
            self.skeleton.scale_mode(),
            &mut self.model,
        );
        Ok(notes.join(" "))
    }

    /// The additive layer at its weight on top of `base` (the wave at `phase` of its cycle),
    /// into `out`. Both layers are made relative to the rest pose; the wave's pelvis translation
    /// is the rest one, so no travel is added.
    fn add_layer(&self, base: &Pose, phase: f32, out: &mut Pose) -> Result<(), String> {
        match self.additive {
            1 => {
                add_additive(base, &self.lean, self.additive_weight, out).map_err(|e| e.to_string())
            }
            2 => {
                let wave = &self.clips[3];
                let tw = (phase * wave.duration_sec()).min(wave.duration_sec() * 0.999_999);
                let rest = self.skeleton.rest_pose();
                let mut sampled = rest.clone();
                wave.sample(tw, &mut ClipCursor::new(), &mut sampled);
                let mut delta = rest.clone();
                make_additive(&sampled, &rest, &mut delta).map_err(|e| e.to_string())?;
                add_additive(base, &delta, self.additive_weight, out).map_err(|e| e.to_string())
            }
            _ => {
                out.local.clone_from(&base.local);
                Ok(())
            }
        }
    }

    /// How far the right upper arm is raised in `model`: its angle from hanging straight down,
    /// degrees (0 hanging, 90 level with the shoulder, 180 straight up).
    pub fn arm_raise_deg(&self, model: &[Affine3A]) -> f32 {
        let [shoulder, elbow] = self.arm;
        let d = Vec3::from(model[elbow].translation - model[shoulder].translation);
        d.normalize_or_zero()
            .dot(Vec3::NEG_Y)
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees()
    }

    /// The model matrices of the last pose (after the additive layer).
    pub fn model(&self) -> &[Affine3A] {
        &self.model
    }

    /// The model matrices of the last pose before the additive layer.
    pub fn base_model(&self) -> &[Affine3A] {
        &self.base_model
    }

    /// The plot over one cycle of clip A (`samples` rows, the last at its end): rows of
    /// ```text
    /// [time (s), right arm raised (°): clip A alone, clip B alone (same phase),
    ///            the mix (this mask and weight), the mix with the additive layer,
    ///            the additive layer alone (on the rest pose, at its weight)]
    /// ```
    /// computed with the reference blend (the student's is checked in the note).
    pub fn arm_samples(&mut self, samples: usize) -> Result<Vec<f32>, String> {
        super::check_samples(samples)?;
        let use_exercise = std::mem::replace(&mut self.use_exercise, false);
        let d = self.duration_sec();
        let mut out = Vec::with_capacity(6 * samples);
        let mut alone = vec![Affine3A::IDENTITY; self.skeleton.len()];
        let rest = self.skeleton.rest_pose();
        let mut layer_alone = rest.clone();
        for k in 0..samples {
            let t = d * k as f32 / (samples - 1) as f32;
            // The last row is the cycle's end, which loops back to its start.
            let t_pose = if k + 1 == samples { 0.0 } else { t };
            if let Err(e) = self.pose(t_pose) {
                self.use_exercise = use_exercise;
                return Err(e);
            }
            out.push(t);
            for pose in [&self.pose_a, &self.pose_b] {
                local_to_model(
                    self.skeleton.parents(),
                    &pose.local,
                    self.skeleton.scale_mode(),
                    &mut alone,
                );
                out.push(self.arm_raise_deg(&alone));
            }
            out.push(self.arm_raise_deg(&self.base_model));
            out.push(self.arm_raise_deg(&self.model));
            let phase = (t_pose / d).rem_euclid(1.0);
            let layered = self.add_layer(&rest, phase, &mut layer_alone);
            if let Err(e) = layered {
                self.use_exercise = use_exercise;
                return Err(e);
            }
            local_to_model(
                self.skeleton.parents(),
                &layer_alone.local,
                self.skeleton.scale_mode(),
                &mut alone,
            );
            out.push(self.arm_raise_deg(&alone));
        }
        self.use_exercise = use_exercise;
        Ok(out)
    }

    /// The note's first sentences, naming the quantities as the figures' controls do: "weight
    /// of B" for the crossfade (Figure 1), "base clip" and "layer weight" for the additive
    /// layer on a base playing alone (Figure 2).
    fn describe(&self) -> String {
        let names = human::CLIP_NAMES;
        let w = format_number(self.weight);
        let (a, b) = (names[self.a], names[self.b]);
        let mix = match self.mask {
            0 if self.weight == 0.0 && self.additive != 0 => {
                format!("Base clip: {a}, played alone (no crossfade).")
            }
            0 if self.weight == 0.0 => format!("{a} plays alone (weight of B 0)."),
            0 if self.weight == 1.0 => format!("{b} plays alone (weight of B 1)."),
            0 => format!("{a} crossfaded with {b}, weight of B {w}."),
            1 => format!(
                "Upper body (spine and up): {b} mixed into {a}, weight of B {w}; legs and pelvis: {a} only."
            ),
            _ => format!(
                "Legs and pelvis: {b} mixed into {a}, weight of B {w}; upper body: {a} only."
            ),
        };
        let additive = match self.additive {
            0 => String::new(),
            k => format!(
                " Additive layer: {}, layer weight {}, added on top (orange: the base without it).",
                ADDITIVES[k],
                format_number(self.additive_weight)
            ),
        };
        mix + &additive
    }

    /// Exercise 6.3 on every joint (before the additive layer); poses the figure with the
    /// student's blend. Returns the note.
    fn student_blend(&mut self) -> String {
        let exercise = "exercise 6.3 crossfade_joint";
        if let Some((at, message)) = &self.exercise_panic {
            return crossfade_panic_note(at, message);
        }
        // The probes first, and every joint's answer before any is used: a panic leaves the
        // reference's pose whole.
        let probes = match self.probe_crossfade() {
            Ok(text) => text,
            Err(panic) => return self.remember_panic(panic),
        };
        let mut answers = Vec::with_capacity(self.skeleton.len());
        for j in 0..self.skeleton.len() {
            let (x, y, w) = (
                self.pose_a.local[j],
                self.pose_b.local[j],
                self.joint_weights[j],
            );
            match run::crossfade_joint(
                self.runner,
                x.translation,
                x.rotation,
                y.translation,
                y.rotation,
                w,
            ) {
                Ok(answer) => answers.push(answer),
                Err(Failure::Panicked(message)) => {
                    let at = format!(
                        "joint {j} ({}) with w = {}",
                        self.skeleton.names()[j],
                        format_number(w)
                    );
                    return self.remember_panic((at, message));
                }
                Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
            }
        }
        let mut first_wrong = None;
        for (j, yours) in answers.into_iter().enumerate() {
            let w = self.joint_weights[j];
            let reference = self.pose.local[j];
            let q = if yours.1.dot(reference.rotation) < 0.0 {
                -yours.1
            } else {
                yours.1
            };
            let flat_yours: Vec<f32> = yours.0.to_array().into_iter().chain(q.to_array()).collect();
            let flat_reference: Vec<f32> = reference
                .translation
                .to_array()
                .into_iter()
                .chain(reference.rotation.to_array())
                .collect();
            let close = flat_yours
                .iter()
                .zip(&flat_reference)
                .all(|(u, v)| (u - v).abs() <= TOLERANCE);
            if first_wrong.is_none() && !close {
                first_wrong = Some((j, w, flat_yours, flat_reference));
            }
            if yours.0.is_finite() && yours.1.is_finite() && yours.1.length() > 0.5 {
                self.pose.local[j].translation = yours.0;
                self.pose.local[j].rotation = yours.1.normalize();
            }
        }
        let here = match first_wrong {
            None => format!(
                "Your crossfade_joint matches the reference at all {} joints.",
                self.skeleton.len()
            ),
            Some((j, w, yours, reference)) => {
                let at = format!(
                    "joint {j} ({}), w = {}",
                    self.skeleton.names()[j],
                    format_number(w)
                );
                compare_note("crossfade_joint", &at, &yours, &reference, TOLERANCE).1
            }
        };
        format!("{here} {probes}")
    }

    /// Keeps a panic of 6.3 (where it happened, its message) and returns the note about it.
    fn remember_panic(&mut self, panic: (String, String)) -> String {
        let note = crossfade_panic_note(&panic.0, &panic.1);
        self.exercise_panic = Some(panic);
        note
    }

    /// Exercise 6.3 on inputs the current settings may not reach: the right upper arm's A and B
    /// at w = 0, 0.25 and 1, and with B's rotation negated (a·b < 0, the short-arc flip) at
    /// w = 0.5. Says which differ; a panic comes back as where it happened and its message.
    fn probe_crossfade(&self) -> Result<String, (String, String)> {
        let j = self.arm[0];
        let (x, y) = (self.pose_a.local[j], self.pose_b.local[j]);
        let mut flipped = y;
        flipped.rotation = -y.rotation;
        let probes = [
            ("w = 0", y, 0.0),
            ("w = 0.25", y, 0.25),
            ("w = 1", y, 1.0),
            ("w = 0.5 with B's rotation negated (a·b < 0)", flipped, 0.5),
        ];
        let mut differ = Vec::new();
        for (what, b, w) in probes {
            let reference = crossfade_transform(&x, &b, w);
            match run::crossfade_joint(
                self.runner,
                x.translation,
                x.rotation,
                b.translation,
                b.rotation,
                w,
            ) {
                Ok((t, q)) => {
                    let close_t = (t - reference.translation).abs().max_element() <= TOLERANCE;
                    // q and −q are the same rotation: compare up to sign.
                    let close_q = q.dot(reference.rotation).abs() >= 1.0 - TOLERANCE
                        && (q.length() - 1.0).abs() <= TOLERANCE;
                    if !(close_t && close_q) {
                        differ.push(what);
                    }
                }
                Err(Failure::Panicked(message)) => {
                    let name = &self.skeleton.names()[j];
                    return Err((format!("the upper arm's probe ({name}) at {what}"), message));
                }
                Err(_) => differ.push(what),
            }
        }
        Ok(if differ.is_empty() {
            "It also matches on the upper arm's probes (w = 0, 0.25, 1, and a·b < 0).".into()
        } else {
            format!(
                "On the upper arm's probes it differs at {}.",
                differ.join(", ")
            )
        })
    }

    /// The colour of a body part whose joint takes clip B at weight `w`: grey (A only) to teal
    /// (B only), mixed by `w^1.5`. A little colour already reads as teal, most of all on a
    /// shaded box: mixed by `w`, 0.5 looks nearly as teal as 1; by `w^1.5` it lies nearer grey
    /// than teal (in OKLab, a perceptual colour space), and 0, 0.5 and 1 read apart.
    pub fn weight_color(w: f32) -> Vec3 {
        let w = w.clamp(0.0, 1.0);
        palette::GREY.lerp(palette::TEAL, w * w.sqrt())
    }

    /// Poses at `time_sec` and draws. Returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let note = self.pose(time_sec)?;
        frame.grid(12, 0.25);
        draw_character(
            frame,
            &self.skeleton,
            &self.shapes,
            &self.model,
            Mat4::IDENTITY,
            |j| Self::weight_color(self.joint_weights[j]),
            // Coloured by the weight alone (not over the clothes' colours, which would hide a
            // teal tint on the blue shirt and trousers): the same weight, the same colour.
            |_| 1.0,
        );
        if self.additive != 0 && self.additive_weight > 0.0 {
            // The pose before the additive layer, as a ghost drawn over the body (most of it
            // lies inside the body): where it differs from the body, the difference is the
            // layer's part.
            for (j, &parent) in self.skeleton.parents().iter().enumerate() {
                let p = Vec3::from(self.base_model[j].translation);
                if parent >= 0 {
                    let a = Vec3::from(self.base_model[parent as usize].translation);
                    frame.wide_line_on_top(a, p, palette::ORANGE, GHOST_PX);
                }
            }
            let hand = Vec3::from(self.base_model[self.arm[1]].translation);
            frame.marker_on_top(hand, crate::draw::DOT_PX, palette::ORANGE);
        }
        frame.contact_shadow(Vec3::ZERO, 0.3);
        // The body with a hand raised over the head, or leaning forwards: kept in view.
        frame.keep_box_in_view(Vec3::new(-0.75, -0.05, -0.85), Vec3::new(0.75, 2.2, 0.85));
        Ok(note)
    }
}

/// Body boxes (each tinted towards `color(j)` by `tint(j)` ∈ [0, 1]), joints coloured by
/// `color(j)`, lines between joints, all placed by `world`.
fn draw_character(
    frame: &mut Frame,
    skeleton: &Skeleton,
    shapes: &[JointShape],
    model: &[Affine3A],
    world: Mat4,
    color: impl Fn(usize) -> Vec3,
    tint: impl Fn(usize) -> f32,
) {
    for (j, (shape, m)) in shapes.iter().zip(model).enumerate() {
        let box_model = world
            * Mat4::from(*m)
            * Mat4::from_translation(shape.center)
            * Mat4::from_scale(shape.half_extents);
        frame.mesh(MeshId::CUBE, box_model, shape.color.lerp(color(j), tint(j)));
    }
    for (j, &parent) in skeleton.parents().iter().enumerate() {
        let p = world.transform_point3(model[j].translation.into());
        frame.mesh(
            MeshId::SPHERE,
            Mat4::from_scale_rotation_translation(Vec3::splat(JOINT_RADIUS), Quat::IDENTITY, p),
            color(j),
        );
        if parent >= 0 {
            let a = world.transform_point3(model[parent as usize].translation.into());
            frame.wide_line(a, p, color(j), BONE_PX);
        }
    }
}

/// What the locomotion figure shows.
#[derive(Clone, Debug)]
pub struct LocomotionFigure {
    skeleton: Skeleton,
    shapes: Vec<JointShape>,
    walk: Clip,
    run: Clip,
    motion: [RootMotion; 2],
    speed: f32,
    synchronised: bool,
    root_motion: bool,
    pose: Pose,
    scratch: Pose,
    model: Vec<Affine3A>,
    footprints: Vec<Vec3>,
    /// The ankles' joints (left, right).
    feet: [usize; 2],
    /// Each foot's contact in the walk's [`Clip::contacts`] (left, right).
    foot_contacts: [usize; 2],
    /// The walk's contacts blended with the run's at the last pose, one per contact of the walk.
    planted: Vec<bool>,
    /// Which foot (0 left, 1 right) left each footprint of the last draw.
    footprint_feet: Vec<usize>,
    /// Footprints of the last draw left by one foot at consecutive samples of one stance, as
    /// pairs of indices into `footprints`: the trail a sliding foot draws.
    footprint_links: Vec<[usize; 2]>,
    /// How far the planted feet slid over the footprint window, metres, at the last draw.
    slide_m: f32,
    /// Where the character's origin was at the last draw (before wrapping onto the track).
    origin: Vec3,
    /// Both settings side by side (synchronised on the left, same clock time on the right)
    /// instead of the one `synchronised` names.
    compare: bool,
    /// The planted feet's slide at the last draw, metres: `[synchronised, same clock time]`
    /// (only the current setting's when not comparing).
    slides_m: [f32; 2],
    /// The run's weight in use: the reference's, or the student's 8.1 with "use my exercise".
    w: f32,
    use_exercise: bool,
    runner: Runner,
    /// What the note says about the student's 8.1 (empty when not in use).
    exercise_note: String,
    /// The speed (m/s) at which the student's 8.1 panicked, and the panic's message. The page
    /// answers every later call of a panicked exercise with that same message, so the figure
    /// keeps the speed that caused it and uses the reference until the page reloads.
    exercise_panic: Option<(f32, String)>,
}

impl Default for LocomotionFigure {
    fn default() -> Self {
        Self::new()
    }
}

/// How big a footprint is drawn, and how wide the trail between one foot's footprints, CSS
/// pixels (the same at any distance); the trail's white outline is 1 px wider each side (a
/// stroke is at most [`crate::draw::MAX_WIDTH_PX`] wide).
const FOOTPRINT_PX: f32 = 11.0;
pub const TRAIL_PX: f32 = 4.0;
/// How far (metres) a drawn footprint may move from one sample to the next beyond the foot's
/// own move before it counts as the drawing's snap-back at a loop rather than a slide: well
/// below a synchronised snap (a blended cycle's travel, 57 to 96 cm) and far above rounding.
const SNAP_TOLERANCE_M: f32 = 0.05;
/// How high above the ground the footprints are drawn, metres (just clear of the grid).
const FOOTPRINT_HEIGHT: f32 = 0.005;
/// The character walks along z on a loop this long (metres), so it stays in view.
const TRACK_LENGTH: f32 = 3.0;
/// Where the two characters walk when compared: synchronised at −x, same clock time at +x, far
/// enough apart that from in front of the walk they stand left and right, footprints included.
pub const LANE_X: f32 = 0.95;
/// A speed within this of an end of the range (half the slider's 0.01 m/s step) is that end:
/// the slider's rounded ends stand for the walk's and the run's own speeds.
pub const SPEED_SNAP: f32 = 0.005;
/// The speeds (m/s) at which the note checks the student's 8.1 besides the current one: below
/// the walk's, above the run's (both clamp), and the figure's range ends and middle are added.
const PROBE_SPEEDS: [f32; 2] = [0.3, 2.5];
/// How far back in time the footprints go, seconds, and how many samples.
const FOOTPRINT_SEC: f32 = 1.5;
const FOOTPRINT_SAMPLES: usize = 60;
/// The locomotion figure's timeline, seconds: then the walk starts again from the start.
pub const LOCOMOTION_LOOP_SEC: f32 = 8.0;
/// The y ranges of the locomotion figure's plots, fixed so that lines at different speeds
/// compare and a small slide reads as small (autoscaled, 2 cm would look like a metre):
/// `[phase gap from, to (cycles), slide from, to (cm)]`. The gap lies in [0, 0.5]; the largest
/// slide at any speed is 395 cm (not synchronised, just below run weight ½, where the walk still
/// decides which foot is planted while the run's half of the pose swings it). A little below 0,
/// so a line at 0 is not cut by the plot's edge.
pub const LOCOMOTION_PLOT_RANGES: [f32; 4] = [-0.02, 0.52, -10.0, 410.0];

/// What the blend figure says when the student's 6.3 panicked when called `at` (a joint and its
/// weight, or a probe): that input once, then the panic's own words.
fn crossfade_panic_note(at: &str, message: &str) -> String {
    let exercise = format!("exercise 6.3 crossfade_joint, called for {at},");
    failure_note(
        &exercise,
        EXERCISE_FILE,
        &Failure::Panicked(message.to_string()),
    )
}

/// What the locomotion figure says when the student's 8.1 panicked when called with the speed
/// `v`: that speed once, then the panic's own words (its place and message).
fn speed_panic_note(v: f32, message: &str) -> String {
    let exercise = format!(
        "exercise 8.1 weight_for_speed, called with v = {} m/s,",
        format_number(v)
    );
    failure_note(
        &exercise,
        BLENDING_FILE,
        &Failure::Panicked(message.to_string()),
    )
}

impl LocomotionFigure {
    /// Halfway between walking and running speed, synchronised, root motion on.
    pub fn new() -> Self {
        let (skeleton, shapes) = human::simple_human();
        let clip = |i| {
            let raw = human::travelling_clip(&skeleton, i, 25).expect("the travelling clips");
            Clip::from_raw(&raw, &skeleton).valid("the travelling clips build")
        };
        let (walk, run) = (clip(1), clip(2));
        let motion = [RootMotion::from_clip(&walk), RootMotion::from_clip(&run)];
        let speed = 0.5 * (motion[0].speed() + motion[1].speed());
        let n = skeleton.len();
        let feet = ["foot.L", "foot.R"].map(|name| skeleton.find(name).expect("a foot"));
        let foot_contacts = feet.map(|f| walk.contact_of(f).expect("the walk plants each foot"));
        Self {
            planted: vec![false; walk.contacts().len()],
            foot_contacts,
            footprint_feet: Vec::with_capacity(2 * FOOTPRINT_SAMPLES),
            footprint_links: Vec::with_capacity(2 * FOOTPRINT_SAMPLES),
            feet,
            walk,
            run,
            motion,
            speed,
            synchronised: true,
            root_motion: true,
            pose: skeleton.rest_pose(),
            scratch: skeleton.rest_pose(),
            model: vec![Affine3A::IDENTITY; n],
            footprints: Vec::with_capacity(2 * FOOTPRINT_SAMPLES),
            slide_m: 0.0,
            origin: Vec3::ZERO,
            compare: true,
            slides_m: [0.0; 2],
            w: 0.0,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            exercise_note: String::new(),
            exercise_panic: None,
            skeleton,
            shapes,
        }
        .with_weight()
    }

    fn with_weight(mut self) -> Self {
        self.update_weight();
        self
    }

    /// The run's weight for the current speed: the reference's, or with "use my exercise" the
    /// student's 8.1 (clamped to [0, 1] for the pose; the reference where it gives no answer).
    /// Also writes the note's verdict on the student's 8.1 at this speed and the probe speeds.
    fn update_weight(&mut self) {
        let reference = weight_for_speed(&self.motion[0], &self.motion[1], self.speed);
        self.w = reference;
        self.exercise_note.clear();
        if !self.use_exercise {
            return;
        }
        let [(da, ta), (db, tb)] = self
            .motion
            .map(|m| (m.duration_sec, m.cycle_travel.length()));
        if let Some((v, message)) = &self.exercise_panic {
            self.exercise_note = speed_panic_note(*v, message);
            return;
        }
        let runner = self.runner;
        let student = move |v: f32| run::weight_for_speed(runner, da, ta, db, tb, v);
        let yours = match student(self.speed) {
            Ok(w) => w,
            Err(Failure::Panicked(message)) => {
                self.exercise_note = speed_panic_note(self.speed, &message);
                self.exercise_panic = Some((self.speed, message));
                return;
            }
            Err(failure) => {
                self.exercise_note =
                    failure_note("exercise 8.1 weight_for_speed", BLENDING_FILE, &failure);
                return;
            }
        };
        if yours.is_finite() {
            self.w = yours.clamp(0.0, 1.0);
        }
        let (lo, hi) = self.speed_range();
        let probes = [lo, 0.5 * (lo + hi), hi, PROBE_SPEEDS[0], PROBE_SPEEDS[1]];
        let at = format!("v = {} m/s", format_number(self.speed));
        let (ok, mut note) = compare_note(
            "weight_for_speed (8.1)",
            &at,
            &[yours],
            &[reference],
            TOLERANCE,
        );
        let mut differ = Vec::new();
        for &v in &probes {
            let r = weight_for_speed(&self.motion[0], &self.motion[1], v);
            match student(v) {
                Ok(y) if (y - r).abs() <= TOLERANCE => {}
                Ok(y) => differ.push(format!(
                    "v = {} (yours {}, reference {})",
                    format_number(v),
                    format_number(y),
                    format_number(r)
                )),
                // After a panic the page answers every call with it: the probes stop here, and
                // the figure names this speed and uses the reference.
                Err(Failure::Panicked(message)) => {
                    self.w = reference;
                    self.exercise_note = speed_panic_note(v, &message);
                    self.exercise_panic = Some((v, message));
                    return;
                }
                Err(f) => differ.push(format!("v = {} ({f})", format_number(v))),
            }
        }
        let probes_text = probes
            .iter()
            .map(|v| format_number(*v))
            .collect::<Vec<_>>()
            .join(", ");
        note += &if differ.is_empty() {
            format!(" It also matches at the probe speeds {probes_text} m/s.")
        } else {
            format!(
                " Of the probe speeds {probes_text} m/s it differs at {}.",
                differ.join("; ")
            )
        };
        if ok && yours.is_finite() && !(0.0..=1.0).contains(&yours) {
            note += " (Its weight lies outside [0, 1]: the figure clamps it.)";
        }
        if !yours.is_finite() {
            note += " It is not a number: the figure uses the reference.";
        } else if !ok {
            note += " The figure blends with your weight: watch the note's speed.";
        }
        self.exercise_note = note;
    }

    /// Blends with the student's exercise 8.1 (through the runner) instead of the reference.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.update_weight();
    }

    /// A new runner (a rebuilt exercise) forgets an earlier panic.
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.exercise_panic = None;
        self.update_weight();
    }

    /// Both settings side by side (the default), or only the one `synchronised` names.
    pub fn set_compare(&mut self, on: bool) {
        self.compare = on;
    }

    /// The planted feet's slide over the last 1.5 s at the last draw, metres, `[synchronised,
    /// same clock time]`; when not comparing, the other setting's entry is 0.
    pub fn slides_m(&self) -> [f32; 2] {
        self.slides_m
    }

    /// Walking and running speeds, m/s (the slider's range).
    pub fn speed_range(&self) -> (f32, f32) {
        (self.motion[0].speed(), self.motion[1].speed())
    }

    /// Speed in m/s, within [`LocomotionFigure::speed_range`]; within [`SPEED_SNAP`] of an end
    /// it is that end (the walk alone or the run alone).
    pub fn set_speed(&mut self, speed: f32) -> Result<(), String> {
        let (lo, hi) = self.speed_range();
        let speed = finite("speed", speed)?;
        let speed = if (speed - lo).abs() <= SPEED_SNAP {
            lo
        } else if (speed - hi).abs() <= SPEED_SNAP {
            hi
        } else {
            speed
        };
        if !(lo..=hi).contains(&speed) {
            // The range's ends are measured from the clips: two decimals say it (the slider's).
            return Err(format!(
                "speed must lie between the walk's {lo:.2} and the run's {hi:.2} m/s, got {speed}"
            ));
        }
        self.speed = speed;
        self.update_weight();
        Ok(())
    }

    /// The speed in use, m/s.
    pub fn speed(&self) -> f32 {
        self.speed
    }

    pub fn set_synchronised(&mut self, on: bool) {
        self.synchronised = on;
    }

    pub fn set_root_motion(&mut self, on: bool) {
        self.root_motion = on;
    }

    /// How far the planted feet slid over the last 1.5 s, metres (at the last draw).
    pub fn slide_m(&self) -> f32 {
        self.slide_m
    }

    /// The character's position at the last draw (root motion; zero when it stays in the pose).
    pub fn origin(&self) -> Vec3 {
        self.origin
    }

    /// The footprints of the last draw, relative to the character (on the ground, at the
    /// ankle's x and z).
    pub fn footprints(&self) -> &[Vec3] {
        &self.footprints
    }

    /// Which foot (0 left, 1 right) left each of [`LocomotionFigure::footprints`].
    pub fn footprint_feet(&self) -> &[usize] {
        &self.footprint_feet
    }

    /// The trails of the last draw: pairs of [`LocomotionFigure::footprints`] left by one foot
    /// at consecutive samples of one stance (drawn as a line between them).
    pub fn footprint_links(&self) -> &[[usize; 2]] {
        &self.footprint_links
    }

    /// Whether each foot (left, right) is planted at `time_sec`, as the figure decides it for
    /// its footprints and its slide: the travelling clips' contacts blended like their poses
    /// (at the same phase synchronised, at each clip's own time otherwise). Poses the figure.
    pub fn planted_at(&mut self, time_sec: f32) -> [bool; 2] {
        self.pose_at(time_sec);
        self.planted_feet()
    }

    fn planted_feet(&self) -> [bool; 2] {
        self.foot_contacts.map(|c| self.planted[c])
    }

    /// How far the drawn character jumps back at a loop with root motion left in the pose,
    /// metres: synchronised, `[blended cycle's travel, 0]` (both clips loop together); not
    /// synchronised, `[(1 − w) T_walk, w T_run]`, each at its own clip's loop.
    pub fn snap_back_m(&self) -> [f32; 2] {
        let w = self.weight();
        let [ta, tb] = self.motion.map(|m| m.cycle_travel.length());
        if self.synchronised {
            [
                synchronised_cycle(&self.motion[0], &self.motion[1], w).1,
                0.0,
            ]
        } else {
            [(1.0 - w) * ta, w * tb]
        }
    }

    /// The run's weight for the current speed (the student's with "use my exercise").
    pub fn weight(&self) -> f32 {
        self.w
    }

    /// Poses at `time_sec` into `self.pose` and returns where the character's origin is drawn
    /// (model space of the scene) and `ground`: what to add to a model-space position of the
    /// pose to put it where the travel has taken it. With root motion that is the origin; with
    /// root motion left in the pose it is the cycles already played (the pose holds the travel
    /// within the current one), so a planted foot stays put in it across the snap-back at a
    /// loop, which is a jump of the drawing, not a slide of the foot.
    fn pose_at(&mut self, time_sec: f32) -> (Vec3, Vec3) {
        let w = self.weight();
        let (cycle, _, _) = synchronised_cycle(&self.motion[0], &self.motion[1], w);
        let mut cursors = [ClipCursor::new(); 2];
        // `within`: the root's travel inside the current cycle; `total`: since time 0.
        let (within, total) = if self.synchronised {
            let phase = time_sec / cycle;
            let rm = [&self.motion[0], &self.motion[1]];
            let d = sample_synchronised(
                &self.walk,
                &self.run,
                w,
                phase,
                &mut cursors,
                &mut self.scratch,
                Some(rm),
                &mut self.pose,
            );
            synchronised_contacts(&self.walk, &self.run, w, phase, &mut self.planted);
            let travel = self.motion[0]
                .cycle_travel
                .lerp(self.motion[1].cycle_travel, w);
            (d, phase.floor() * travel + d)
        } else {
            // The naive blend: both clips at the same clock time, each looping on its own. Each
            // clip's cycle count and clip-local time come from one division, so they agree at
            // a loop (the clip's own wrap and ⌊t / d⌋ can differ in f32 there, which would put
            // the character a whole cycle ahead for that instant).
            let [ka, kb] = [0, 1].map(|i| (time_sec / self.motion[i].duration_sec).floor());
            let local = |k: f32, d: f32| (time_sec - k * d).clamp(0.0, d * 0.999_999);
            let (ta, tb) = (
                local(ka, self.motion[0].duration_sec),
                local(kb, self.motion[1].duration_sec),
            );
            self.walk.sample(ta, &mut cursors[0], &mut self.pose);
            self.run.sample(tb, &mut cursors[1], &mut self.scratch);
            blend_contacts(&self.walk, ta, &self.run, tb, w, &mut self.planted);
            let da = self.motion[0].extract(&mut self.pose);
            let db = self.motion[1].extract(&mut self.scratch);
            let pa = ka * self.motion[0].cycle_travel + da;
            let pb = kb * self.motion[1].cycle_travel + db;
            for (x, y) in self.pose.local.iter_mut().zip(&self.scratch.local) {
                *x = crossfade_transform(x, y, w);
            }
            (da.lerp(db, w), pa.lerp(pb, w))
        };
        if self.root_motion {
            (total, total)
        } else {
            // Root motion left in the pose: the root travels within a cycle, then snaps back.
            self.pose.local[0].translation += within;
            (Vec3::ZERO, total - within)
        }
    }

    /// Poses at `time_sec` and returns each foot's ankle (left, right) where the travel has
    /// taken it (see [`LocomotionFigure::pose_at`]'s `ground`), where it is drawn, relative to
    /// the character's drawn origin at `now`, and whether it is planted.
    fn feet_at(&mut self, time_sec: f32, now: Vec3) -> [(Vec3, Vec3, bool); 2] {
        let (origin, ground) = self.pose_at(time_sec);
        local_to_model(
            self.skeleton.parents(),
            &self.pose.local,
            self.skeleton.scale_mode(),
            &mut self.model,
        );
        let planted = self.planted_feet();
        [0, 1].map(|f| {
            let p = Vec3::from(self.model[self.feet[f]].translation);
            (p + ground, p + origin - now, planted[f])
        })
    }

    /// How far out of step the two clips are at `time_sec`, in cycles: the distance from the
    /// walk's phase to the run's, around the cycle, in [0, 0.5] (0: in step; 0.5: one clip's
    /// left foot where the other's right foot is). Always 0 synchronised.
    pub fn phase_gap(&self, time_sec: f32) -> f32 {
        if self.synchronised {
            return 0.0;
        }
        let [walk, run] = self.motion.map(|m| time_sec / m.duration_sec);
        let gap = (run - walk).rem_euclid(1.0);
        gap.min(1.0 - gap)
    }

    /// The note's slide at every footprint sample time over the timeline: entry `k` is the
    /// slide (metres) over the 1.5 s before `k` · 25 ms, measured as
    /// [`LocomotionFigure::draw`] does (from the same samples, each computed once).
    fn slide_series(&mut self) -> Vec<f32> {
        let dt = FOOTPRINT_SEC / FOOTPRINT_SAMPLES as f32;
        let steps = (LOCOMOTION_LOOP_SEC / dt).round() as usize;
        // step[i]: how far the planted feet moved from sample i − 1 to sample i, where sample i
        // is at (i − FOOTPRINT_SAMPLES) · dt.
        let mut step = vec![0.0f32; steps + FOOTPRINT_SAMPLES + 1];
        let mut last: [Option<Vec3>; 2] = [None, None];
        for (i, moved) in step.iter_mut().enumerate() {
            let t = (i as f32 - FOOTPRINT_SAMPLES as f32) * dt;
            for (f, (ground, _, planted)) in self.feet_at(t, Vec3::ZERO).into_iter().enumerate() {
                if planted {
                    if let Some(q) = last[f] {
                        *moved += Vec3::new(ground.x - q.x, 0.0, ground.z - q.z).length();
                    }
                    last[f] = Some(ground);
                } else {
                    last[f] = None;
                }
            }
        }
        (0..=steps)
            .map(|k| step[k + 1..=k + FOOTPRINT_SAMPLES].iter().sum())
            .collect()
    }

    /// The figure's plots over the timeline's [`LOCOMOTION_LOOP_SEC`], at the current speed,
    /// synchronised and not (the figure's own setting is left as it was): rows of
    /// ```text
    /// [time (s), phase gap synchronised (cycles), not synchronised (cycles),
    ///            slide synchronised (cm),         not synchronised (cm)]
    /// ```
    /// one per footprint sample (every 25 ms). The phase gap is [`LocomotionFigure::phase_gap`],
    /// the slide the note's. Root motion does not change either: the slide is measured where the
    /// travel has taken the feet.
    pub fn plot_samples(&mut self) -> Vec<f32> {
        let synchronised = self.synchronised;
        let dt = FOOTPRINT_SEC / FOOTPRINT_SAMPLES as f32;
        let mut columns = Vec::with_capacity(2);
        for on in [true, false] {
            self.synchronised = on;
            columns.push(self.slide_series());
        }
        let mut out = Vec::with_capacity(5 * columns[0].len());
        for k in 0..columns[0].len() {
            let t = k as f32 * dt;
            out.push(t);
            for on in [true, false] {
                self.synchronised = on;
                out.push(self.phase_gap(t));
            }
            out.extend(columns.iter().map(|c| c[k] * 100.0));
        }
        self.synchronised = synchronised;
        out
    }

    /// The footprints and the slide over the last [`FOOTPRINT_SEC`] before `t` at the current
    /// setting (into `self.footprints`, relative to the character); returns the slide, metres.
    /// The slide is measured where the travel has taken each foot, so the snap-back at a loop
    /// (root motion left in the pose) is not counted as sliding.
    fn footprints_at(&mut self, t: f32) -> f32 {
        self.footprints.clear();
        self.footprint_feet.clear();
        self.footprint_links.clear();
        let (now, _) = self.pose_at(t);
        let mut slide = 0.0f32;
        // Per foot, while planted: where the travel had taken it at the last sample, where it
        // was drawn, and that sample's footprint.
        let mut last: [Option<(Vec3, Vec3, usize)>; 2] = [None, None];
        for k in 0..=FOOTPRINT_SAMPLES {
            let s = t - FOOTPRINT_SEC * (1.0 - k as f32 / FOOTPRINT_SAMPLES as f32);
            for (f, (ground, drawn, planted)) in self.feet_at(s, now).into_iter().enumerate() {
                if planted {
                    let here = self.footprints.len();
                    self.footprints
                        .push(Vec3::new(drawn.x, FOOTPRINT_HEIGHT, drawn.z));
                    self.footprint_feet.push(f);
                    if let Some((q, q_drawn, before)) = last[f] {
                        let step = Vec3::new(ground.x - q.x, 0.0, ground.z - q.z);
                        slide += step.length();
                        // The drawing's snap-back at a loop (root motion left in the pose)
                        // moves the drawn foot but not the foot: two dots, no trail.
                        let drawn_step = Vec3::new(drawn.x - q_drawn.x, 0.0, drawn.z - q_drawn.z);
                        if (drawn_step - step).length() <= SNAP_TOLERANCE_M {
                            self.footprint_links.push([before, here]);
                        }
                    }
                    last[f] = Some((ground, drawn, here));
                } else {
                    last[f] = None;
                }
            }
        }
        slide
    }

    /// Poses at `t` at the current setting and draws the character, its contact shadow, its
    /// footprints (each stance's trail, with a marker of a fixed size on screen at its two ends,
    /// drawn over the legs) and its label in lane `x`, at `along` on the loop (metres before
    /// wrapping; `None`: where its own travel has taken it). Returns the slide, metres.
    fn draw_lane(
        &mut self,
        frame: &mut Frame,
        t: f32,
        x: f32,
        color: Vec3,
        name: &str,
        along: Option<f32>,
    ) -> f32 {
        let slide = self.footprints_at(t);
        let (origin, _) = self.pose_at(t);
        self.origin = origin;
        local_to_model(
            self.skeleton.parents(),
            &self.pose.local,
            self.skeleton.scale_mode(),
            &mut self.model,
        );
        // The character walks along z on a loop of TRACK_LENGTH, so it stays in view.
        let z = along.unwrap_or(origin.z);
        let z = (z + 0.5 * TRACK_LENGTH).rem_euclid(TRACK_LENGTH) - 0.5 * TRACK_LENGTH;
        let place = Vec3::new(origin.x + x, 0.0, z);
        // Over everything: a foot slides along the way it walks, under its own leg, which
        // would hide the trail from most views. Each trail in a white outline (all the outlines
        // first, so none covers a join): seen along the walk, a trail lies over the legs, and
        // the white keeps it a line of its own there. Beside the feet instead, it would no
        // longer mark where they were.
        for (width, colour) in [(TRAIL_PX + 2.0, Vec3::ONE), (TRAIL_PX, color)] {
            for &[a, b] in &self.footprint_links {
                let (a, b) = (self.footprints[a] + place, self.footprints[b] + place);
                frame.wide_line_on_top(a, b, colour, width);
            }
        }
        // A dot where each stance begins and ends: one dot for a foot that held still, the two
        // ends of its trail for one that slid.
        for (i, p) in self.footprints.iter().enumerate() {
            let linked = |end: usize| self.footprint_links.iter().any(|l| l[end] == i);
            if !(linked(0) && linked(1)) {
                frame.marker_on_top(*p + place, FOOTPRINT_PX, color);
            }
        }
        let pelvis = place + Vec3::from(self.model[0].translation);
        frame.contact_shadow(Vec3::new(pelvis.x, 0.0, pelvis.z), 0.25);
        draw_character(
            frame,
            &self.skeleton,
            &self.shapes,
            &self.model,
            Mat4::from_translation(place),
            |_| palette::DARK,
            |_| 0.0,
        );
        if !name.is_empty() {
            // Centred just over the head's box, wherever the lean or the root's drift within
            // the cycle has taken the head: it names this character.
            let head = self.skeleton.find("head").unwrap_or(0);
            let shape = &self.shapes[head];
            let top = place
                + self.model[head].transform_point3(shape.center)
                + (shape.half_extents.y + 0.04) * Vec3::Y;
            frame.label_off_dot(top, 0.0, glam::Vec2::NEG_Y, name, color, 0);
        }
        slide
    }

    /// Poses at `time_sec` and draws: comparing, the synchronised blend on the left and the
    /// same-clock-time blend on the right, each with its footprints; otherwise the one
    /// `synchronised` names, in the middle. Returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let t = finite("time", time_sec)?;
        frame.grid(16, 0.25);
        let own = self.synchronised;
        self.slides_m = [0.0; 2];
        if self.compare {
            // Both abreast, at the synchronised character's place on the loop: blended at the
            // same clock time, the root drifts ahead or behind (most of a metre), and from the
            // page's view one character then walks ahead of the other.
            self.synchronised = true;
            let along = Some(self.pose_at(t).0.z);
            // The figure's own setting last, so footprints(), slide_m() and origin() are its.
            for on in [!own, own] {
                self.synchronised = on;
                let (x, color, name) = if on {
                    (-LANE_X, palette::BLUE, "synchronised")
                } else {
                    (LANE_X, palette::RED, "same clock time")
                };
                self.slides_m[usize::from(!on)] = self.draw_lane(frame, t, x, color, name, along);
            }
            self.synchronised = own;
        } else {
            self.slides_m[usize::from(!own)] =
                self.draw_lane(frame, t, 0.0, palette::PURPLE, "", None);
        }
        self.slide_m = self.slides_m[usize::from(!own)];
        // The lanes drawn, the whole track and a raised head: what the camera must keep in view.
        let half = 0.5 * TRACK_LENGTH;
        let side = if self.compare { LANE_X } else { 0.0 } + 0.4;
        frame.keep_box_in_view(
            Vec3::new(-side, 0.0, -half - 0.3),
            Vec3::new(side, 2.0, half + 0.3),
        );
        let w = self.weight();
        let (cycle, _, speed) = synchronised_cycle(&self.motion[0], &self.motion[1], w);
        let (lo, hi) = self.speed_range();
        let alone = if self.speed == lo {
            " (the walk alone)"
        } else if self.speed == hi {
            " (the run alone)"
        } else {
            ""
        };
        let mut note = format!(
            "{} m/s: run weight {}{alone}, one cycle takes {} s.",
            format_number(speed),
            format_number(w),
            format_number(cycle)
        );
        let slid = |m: f32| format!("slid {:.1} cm in the last {FOOTPRINT_SEC} s.", m * 100.0);
        if self.compare {
            note += &format!(
                " Synchronised (left, blue footprints), the planted feet {} At the same clock time (right, red footprints), they {}",
                slid(self.slides_m[0]),
                slid(self.slides_m[1])
            );
        } else {
            note += if self.synchronised {
                " Walk and run sampled at the same phase of their cycles."
            } else {
                " Walk and run sampled at the same clock time (not synchronised)."
            };
            note += &format!(" Planted feet {}", slid(self.slide_m));
        }
        if !self.root_motion {
            let snap = if self.synchronised {
                format!("{:.0} cm", self.snap_back_m()[0] * 100.0)
            } else {
                let [walk, run] = self.snap_back_m();
                format!(
                    "{:.0} cm at each loop of the walk and {:.0} cm at each loop of the run",
                    walk * 100.0,
                    run * 100.0
                )
            };
            note += &format!(
                " Root motion left in the pose: the character steps forwards within each cycle and snaps back {snap} (a jump, not counted as sliding)."
            );
        }
        if !self.exercise_note.is_empty() {
            note.push(' ');
            note += &self.exercise_note;
        }
        Ok(note)
    }
}
