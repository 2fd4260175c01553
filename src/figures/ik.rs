//! Figure logic for lesson 07, "Inverse kinematics" (see [`crate::figures`]).
//!
//! [`IkFigure`]: three copies of one chain side by side, each solving for the same target
//! (relative to its root): two-joint analytic IK (law of cosines, with a pole), CCD and FABRIK,
//! each from the same rest pose with at most `iterations` iterations; joint limits (hinges or
//! cones) for the iterative two; the error after each iteration for the plot; dragging the
//! target in the view; and the check of the student's exercises 7.1 and 7.2.
//!
//! [`AimFigure`]: a head that looks at a target within a cone ([`crate::ik::aim`]).

use super::{
    compare_note, failure_note, finite, format_number, in_range, palette, Frame, MeshId, Runner,
    DEFAULT_RUNNER,
};
use crate::camera::{point_on_view_plane, project_to_canvas, OrbitCamera};
use crate::draw::inset::InsetView;
use crate::draw::StrokeStyle;
use crate::exercises::run;
use crate::ik::{aim, ccd, ccd_limited, fabrik, fabrik_limited, two_joint, IkResult, JointLimit};
use glam::{Mat4, Quat, Vec2, Vec3};

const DEG: f32 = std::f32::consts::PI / 180.0;
const EXERCISE_FILE: &str = "src/exercises/ik.rs";
/// The iterative solvers stop within this distance of the target, metres (0.1 mm).
pub const TOLERANCE_M: f32 = 1e-4;
/// The most iterations the slider offers; the plot always shows this many.
pub const MAX_ITERATIONS: usize = 50;
/// Segments per chain, at least and at most.
pub const MIN_SEGMENTS: usize = 2;
pub const MAX_SEGMENTS: usize = 8;
/// Total length of every chain, metres.
const CHAIN_LENGTH: f32 = 1.0;
/// Where the three chains stand: analytic, CCD, FABRIK (x of each root, metres).
pub const ROOTS_X: [f32; 3] = [-1.1, 0.0, 1.1];
/// How close (CSS pixels) a pointer must come to a target to grab it.
const GRAB_RADIUS_PX: f32 = 18.0;
/// How close the student's joints must be to the reference's, metres.
const STUDENT_TOLERANCE: f32 = 2e-3;
/// The student's chain's line and joints, CSS px: inside the reference's bars and spheres.
const STUDENT_PX: f32 = 2.5;
const STUDENT_DOT_PX: f32 = 7.0;
/// The bend of the rest pose at each joint, about −z (the chain leans towards +x).
const REST_BEND_RAD: f32 = 12.0 * DEG;

/// Each chain's colour (its bars, joints, target and labels): analytic, CCD, FABRIK.
const SOLVER_COLORS: [Vec3; 3] = [palette::BLUE, palette::ORANGE, palette::TEAL];
/// Sizes on screen, CSS pixels: a target, the pole, the dashed gap left to a target.
const TARGET_PX: f32 = 16.0;
const POLE_PX: f32 = 11.0;
const GAP_PX: f32 = 2.5;
/// Width of the aim figure's cone: its rim and the rays from the head to it, CSS pixels.
pub const CONE_PX: f32 = 2.0;

/// Half the side of the square of the hinges' plane drawn around the target's foot, metres.
pub const HINGE_PATCH_M: f32 = 0.1;

/// What the joint-limits dropdown offers, in order.
pub const LIMIT_MODES: [&str; 3] = ["none", "hinges (bend one way)", "cones (40°)"];

/// The three solvers, in the order the chains stand.
pub const SOLVERS: [&str; 3] = ["two-joint", "CCD", "FABRIK"];

#[derive(Clone, Copy, Debug, PartialEq)]
enum Limits {
    None,
    Hinges,
    Cones,
}

/// The lesson's first figure: one chain, three solvers.
#[derive(Clone, Debug)]
pub struct IkFigure {
    segments: usize,
    /// The target relative to each chain's root, metres.
    target: Vec3,
    pole_angle_rad: f32,
    iterations: usize,
    limits: Limits,
    use_exercise: bool,
    runner: Runner,
    camera: Option<(OrbitCamera, Vec2)>,
    dirty: bool,
    rest: Vec<Vec3>,
    /// Solved chains relative to the root: analytic (empty unless 2 segments), CCD, FABRIK.
    solved: [Vec<Vec3>; 3],
    results: [Option<IkResult>; 3],
    /// Error after each of [`MAX_ITERATIONS`] iterations (the last one repeated after a stop).
    errors: [Vec<f32>; 2],
    /// The student's chains (analytic, CCD) when "use my exercise" gave one.
    student: [Option<Vec<Vec3>>; 2],
    notes: Vec<String>,
}

impl Default for IkFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl IkFigure {
    /// Two segments, the target up and to the right, the pole above the root→target line, 10
    /// iterations, no limits.
    pub fn new() -> Self {
        let mut figure = Self {
            segments: 2,
            target: Vec3::new(0.55, 0.65, 0.15),
            pole_angle_rad: 0.0,
            iterations: 10,
            limits: Limits::None,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            camera: None,
            dirty: true,
            rest: Vec::new(),
            solved: Default::default(),
            results: [None; 3],
            errors: [vec![0.0; MAX_ITERATIONS], vec![0.0; MAX_ITERATIONS]],
            student: [None, None],
            notes: Vec::new(),
        };
        figure.build_rest();
        figure
    }

    /// The rest pose the iterative solvers start from: `segments` equal segments from the root
    /// straight up, each joint bent a little about −z (the chain leans towards +x, the side the
    /// hinges bend to), at most 45° in all.
    fn build_rest(&mut self) {
        let n = self.segments;
        let l = CHAIN_LENGTH / n as f32;
        let bend = REST_BEND_RAD.min(45.0 * DEG / (n - 1).max(1) as f32);
        self.rest.clear();
        self.rest.push(Vec3::ZERO);
        let mut dir = Vec3::Y;
        for i in 0..n {
            if i > 0 {
                dir = Quat::from_rotation_z(-bend) * dir;
            }
            let last = self.rest[i];
            self.rest.push(last + dir * l);
        }
        self.dirty = true;
    }

    /// Segments per chain, a whole number in [[`MIN_SEGMENTS`], [`MAX_SEGMENTS`]] (a fraction is
    /// an error, not rounded).
    pub fn set_segments(&mut self, segments: f32) -> Result<(), String> {
        self.segments = super::whole_number("segments", segments, MIN_SEGMENTS, MAX_SEGMENTS)?;
        self.build_rest();
        Ok(())
    }

    pub fn segments(&self) -> usize {
        self.segments
    }

    /// The target relative to each chain's root, each coordinate in [−1.5, 1.5] m.
    pub fn set_target(&mut self, target: Vec3) -> Result<(), String> {
        self.target = Vec3::new(
            in_range("target x", target.x, -1.5, 1.5)?,
            in_range("target y", target.y, -1.5, 1.5)?,
            in_range("target z", target.z, -1.5, 1.5)?,
        );
        self.dirty = true;
        Ok(())
    }

    pub fn target(&self) -> Vec3 {
        self.target
    }

    /// Where the pole sits around the root→target line, degrees in [−180, 180]; 0 puts it on
    /// the upper side.
    pub fn set_pole_angle_deg(&mut self, deg: f32) -> Result<(), String> {
        self.pole_angle_rad = in_range("pole angle", deg, -180.0, 180.0)? * DEG;
        self.dirty = true;
        Ok(())
    }

    /// The most iterations CCD and FABRIK may take, a whole number in [1, [`MAX_ITERATIONS`]]
    /// (a fraction is an error, not rounded).
    pub fn set_iterations(&mut self, iterations: f32) -> Result<(), String> {
        self.iterations = super::whole_number("iterations", iterations, 1, MAX_ITERATIONS)?;
        self.dirty = true;
        Ok(())
    }

    /// One of [`LIMIT_MODES`].
    pub fn set_limits(&mut self, name: &str) -> Result<(), String> {
        self.limits = match LIMIT_MODES.iter().position(|&m| m == name) {
            Some(0) => Limits::None,
            Some(1) => Limits::Hinges,
            Some(_) => Limits::Cones,
            None => {
                return Err(format!(
                    "joint limits must be one of {}, got {name:?}",
                    LIMIT_MODES.join(", ")
                ))
            }
        };
        self.dirty = true;
        Ok(())
    }

    /// Runs the student's exercises 7.1 and 7.2 (through the runner) instead of the reference.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.dirty = true;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.dirty = true;
    }

    /// Each joint's limit and the root direction, for the current mode.
    fn joint_limits(&self) -> Option<(Vec<JointLimit>, Vec3)> {
        let n = self.segments;
        match self.limits {
            Limits::None => None,
            Limits::Hinges => {
                // The root swings ±90° from straight up; the others bend one way (towards +x
                // when the chain points up), like fingers.
                let mut limits = vec![
                    JointLimit::Hinge {
                        axis: Vec3::Z,
                        min_rad: -120.0 * DEG,
                        max_rad: 0.0,
                    };
                    n
                ];
                limits[0] = JointLimit::Hinge {
                    axis: Vec3::Z,
                    min_rad: -90.0 * DEG,
                    max_rad: 90.0 * DEG,
                };
                Some((limits, Vec3::Y))
            }
            Limits::Cones => {
                let mut limits = vec![
                    JointLimit::Cone {
                        max_rad: 40.0 * DEG
                    };
                    n
                ];
                limits[0] = JointLimit::Cone {
                    max_rad: 60.0 * DEG,
                };
                Some((limits, Vec3::Y))
            }
        }
    }

    /// The pole (relative to the root): beside the middle of the root→target line, turned by the
    /// pole angle about that line from its upper side.
    pub fn pole(&self) -> Vec3 {
        let u = self.target.normalize_or(Vec3::Y);
        let up = Vec3::Y - u * u.dot(Vec3::Y);
        let v0 = up
            .try_normalize()
            .unwrap_or_else(|| u.any_orthonormal_vector());
        let v = Quat::from_axis_angle(u, self.pole_angle_rad) * v0;
        0.5 * self.target + 0.5 * v
    }

    /// Solves all three chains (reference, then the student's with "use my exercise").
    pub fn solve(&mut self) -> Result<(), String> {
        if !self.dirty {
            return Ok(());
        }
        self.dirty = false;
        self.notes.clear();
        self.student = [None, None];
        let target = self.target;
        let limits = self.joint_limits();
        // Analytic: only a two-segment chain.
        self.solved[0].clear();
        self.results[0] = None;
        if self.segments == 2 {
            let r = &self.rest;
            let s = two_joint(r[0], r[1], r[2], target, self.pole(), TOLERANCE_M)
                .map_err(|e| e.to_string())?;
            self.solved[0].extend([r[0], s.middle, s.end]);
            self.results[0] = Some(s.result);
        }
        // CCD and FABRIK: from the rest pose, at most `iterations`; the plot runs on to the end.
        for k in 0..2 {
            let mut chain = self.rest.clone();
            let mut errors = [0.0f32; MAX_ITERATIONS];
            let result = match (&limits, k) {
                (None, 0) => ccd(
                    &mut chain,
                    target,
                    MAX_ITERATIONS,
                    TOLERANCE_M,
                    Some(&mut errors),
                ),
                (None, _) => fabrik(
                    &mut chain,
                    target,
                    MAX_ITERATIONS,
                    TOLERANCE_M,
                    Some(&mut errors),
                ),
                (Some((l, d)), 0) => ccd_limited(
                    &mut chain,
                    l,
                    *d,
                    target,
                    MAX_ITERATIONS,
                    TOLERANCE_M,
                    Some(&mut errors),
                ),
                (Some((l, d)), _) => fabrik_limited(
                    &mut chain,
                    l,
                    *d,
                    target,
                    MAX_ITERATIONS,
                    TOLERANCE_M,
                    Some(&mut errors),
                ),
            }
            .map_err(|e| e.to_string())?;
            // After a stop the error stays where it was.
            let used = result.iterations.max(1);
            for i in result.iterations..MAX_ITERATIONS {
                errors[i] = if i == 0 {
                    result.error
                } else {
                    errors[used - 1]
                };
            }
            self.errors[k].copy_from_slice(&errors);
            // The pose the slider asks for: run again with that many iterations.
            let mut shown = self.rest.clone();
            let result = match (&limits, k) {
                (None, 0) => ccd(&mut shown, target, self.iterations, TOLERANCE_M, None),
                (None, _) => fabrik(&mut shown, target, self.iterations, TOLERANCE_M, None),
                (Some((l, d)), 0) => ccd_limited(
                    &mut shown,
                    l,
                    *d,
                    target,
                    self.iterations,
                    TOLERANCE_M,
                    None,
                ),
                (Some((l, d)), _) => fabrik_limited(
                    &mut shown,
                    l,
                    *d,
                    target,
                    self.iterations,
                    TOLERANCE_M,
                    None,
                ),
            }
            .map_err(|e| e.to_string())?;
            self.solved[k + 1] = shown;
            self.results[k + 1] = Some(result);
        }
        if self.use_exercise {
            let a = self.student_two_joint();
            let b = self.student_ccd();
            self.notes.extend([a, b]);
        } else {
            self.notes.push(self.describe());
        }
        Ok(())
    }

    fn describe(&self) -> String {
        let mut parts = Vec::new();
        let mm = |e: f32| format!("{} mm", format_number(e * 1000.0));
        match self.results[0] {
            Some(r) if r.reached => parts.push(format!(
                "Two-joint: reached in one step (error {}), side d = {} m.",
                mm(r.error),
                format_number(self.target.length())
            )),
            Some(r) => parts.push(format!(
                "Two-joint: out of reach, {} short (the chain points straight at the target), \
                 side d = {} m.",
                mm(r.error),
                format_number(self.target.length())
            )),
            None => {
                parts.push("Two-joint IK needs exactly 2 segments: its chain is hidden.".into())
            }
        }
        for (k, name) in [(1, "CCD"), (2, "FABRIK")] {
            let Some(r) = self.results[k] else { continue };
            parts.push(if r.reached {
                format!(
                    "{name}: reached after {} iteration{} (error {}).",
                    r.iterations,
                    if r.iterations == 1 { "" } else { "s" },
                    mm(r.error)
                )
            } else {
                format!(
                    "{name}: after {} iteration{}, {} from the target.",
                    r.iterations,
                    if r.iterations == 1 { "" } else { "s" },
                    mm(r.error)
                )
            });
        }
        if self.limits == Limits::Hinges && self.target.z.abs() >= 0.01 {
            parts.push(format!(
                "The hinges keep CCD's and FABRIK's chains in the plane z = 0 through their roots, \
                 and the target is {:.0} cm off it (the grey dashed drop to the grey square): no \
                 hinged pose comes closer than that.",
                self.target.z.abs() * 100.0
            ));
        }
        if self.limits != Limits::None {
            parts.push(if self.segments == 2 {
                "Limits apply to CCD and FABRIK; two-joint IK bends towards its pole.".into()
            } else {
                "Limits apply to CCD and FABRIK.".into()
            });
        }
        parts.join(" ")
    }

    /// Exercise 7.1 on the two-segment chain; keeps the student's chain for drawing.
    fn student_two_joint(&mut self) -> String {
        let exercise = "exercise 7.1 two_joint";
        if self.segments != 2 {
            // Still say whether it is done (or panics), on a two-segment probe.
            let (r, m, e) = (Vec3::ZERO, Vec3::Y * 0.5, Vec3::Y);
            let how = "Set segments to 2 to see your 7.1 two_joint on the blue chain.";
            return match run::two_joint(self.runner, r, m, e, self.target, self.pole()) {
                Ok(_) => how.into(),
                Err(failure) => {
                    format!("{} {how}", failure_note(exercise, EXERCISE_FILE, &failure))
                }
            };
        }
        let r = &self.rest;
        let (root, middle, end) = (r[0], r[1], r[2]);
        let yours = match run::two_joint(self.runner, root, middle, end, self.target, self.pole()) {
            Ok(answer) => answer,
            Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
        };
        let reference = (self.solved[0][1], self.solved[0][2]);
        let flat = |(m, e): (Vec3, Vec3)| -> Vec<f32> {
            m.to_array().into_iter().chain(e.to_array()).collect()
        };
        let at = format!(
            "target ({}) (middle, end)",
            self.target.to_array().map(format_number).join(", ")
        );
        let (_, note) = compare_note(
            "two_joint",
            &at,
            &flat(yours),
            &flat(reference),
            STUDENT_TOLERANCE,
        );
        if yours.0.is_finite() && yours.1.is_finite() {
            self.student[0] = Some(vec![root, yours.0, yours.1]);
        }
        let lengths = format!(
            " Your segment lengths: {} and {} m (should be {} and {}).",
            format_number(yours.0.distance(root)),
            format_number(yours.1.distance(yours.0)),
            format_number(middle.distance(root)),
            format_number(end.distance(middle)),
        );
        note + &lengths + &self.probe_two_joint()
    }

    /// Exercise 7.1 at inputs the figure may not show: a target out of reach, one closer than
    /// |a − b|, unequal segments, the pole on the other side.
    fn probe_two_joint(&self) -> String {
        let (r, m, e) = (
            Vec3::ZERO,
            Vec3::new(0.1, 0.6, 0.0),
            Vec3::new(0.0, 1.0, 0.05),
        );
        let probes = [
            (
                "a target out of reach",
                r,
                m,
                e,
                Vec3::new(1.5, 0.4, 0.2),
                Vec3::new(0.0, 1.0, 1.0),
            ),
            (
                "a target closer than |a − b|",
                r,
                m,
                e,
                Vec3::new(0.05, 0.1, 0.0),
                Vec3::new(1.0, 0.0, 0.0),
            ),
            (
                "the pole behind (−z)",
                r,
                m,
                e,
                Vec3::new(0.4, 0.6, 0.1),
                Vec3::new(0.2, 0.3, -1.0),
            ),
            (
                "a root away from the origin",
                Vec3::new(0.3, -0.2, 0.1),
                m,
                e,
                Vec3::new(0.5, 0.4, 0.3),
                Vec3::new(1.0, 1.0, 0.0),
            ),
        ];
        let mut asked = 0;
        let mut differing = Vec::new();
        for (name, root, middle, end, target, pole) in probes {
            let Ok(yours) = run::two_joint(self.runner, root, middle, end, target, pole) else {
                continue;
            };
            asked += 1;
            let Ok(reference) = two_joint(root, middle, end, target, pole, TOLERANCE_M) else {
                continue;
            };
            let close = yours.0.distance(reference.middle) <= STUDENT_TOLERANCE
                && yours.1.distance(reference.end) <= STUDENT_TOLERANCE;
            if !close {
                differing.push(name.to_string());
            }
        }
        super::skeleton::probe_summary("two_joint", asked, &differing)
    }

    /// Exercise 7.2, one sweep, at chains the figure may not show: four unequal segments, a
    /// target out of reach, a target on the chain's own line.
    fn probe_ccd(&self) -> String {
        let bent = vec![
            Vec3::ZERO,
            Vec3::new(0.0, 0.3, 0.0),
            Vec3::new(0.2, 0.5, 0.1),
            Vec3::new(0.3, 0.9, 0.0),
            Vec3::new(0.1, 1.0, -0.2),
        ];
        let probes = [
            (
                "four unequal segments",
                bent.clone(),
                Vec3::new(-0.4, 0.5, 0.3),
            ),
            (
                "a target out of reach",
                bent.clone(),
                Vec3::new(2.0, 1.0, 0.5),
            ),
            ("a target behind the root", bent, Vec3::new(0.0, -0.5, -0.3)),
        ];
        let mut asked = 0;
        let mut differing = Vec::new();
        for (name, chain, target) in probes {
            let Ok(yours) = run::ccd_iteration(self.runner, chain.clone(), target) else {
                continue;
            };
            asked += 1;
            let mut reference = chain;
            crate::ik::ccd_iteration(&mut reference, target);
            let close = yours.len() == reference.len()
                && yours
                    .iter()
                    .zip(&reference)
                    .all(|(y, r)| y.distance(*r) <= STUDENT_TOLERANCE);
            if !close {
                differing.push(name.to_string());
            }
        }
        super::skeleton::probe_summary("ccd_iteration", asked, &differing)
    }

    /// Exercise 7.2, iterated like the reference CCD (no limits); keeps the student's chain.
    fn student_ccd(&mut self) -> String {
        let exercise = "exercise 7.2 ccd_iteration";
        if self.limits != Limits::None {
            let how = "Set joint limits to none to see your 7.2 ccd_iteration on the orange chain.";
            return match run::ccd_iteration(self.runner, self.rest.clone(), self.target) {
                Ok(_) => how.into(),
                Err(failure) => {
                    format!("{} {how}", failure_note(exercise, EXERCISE_FILE, &failure))
                }
            };
        }
        let mut yours = self.rest.clone();
        let mut reference = self.rest.clone();
        for k in 1..=self.iterations {
            if reference[reference.len() - 1].distance(self.target) <= TOLERANCE_M {
                break;
            }
            let before = yours.clone();
            yours = match run::ccd_iteration(self.runner, yours, self.target) {
                Ok(c) if c.len() == reference.len() => c,
                Ok(c) => {
                    return format!(
                        "Your {exercise} returned {} joints for a chain of {}. The figure uses the reference.",
                        c.len(),
                        reference.len()
                    )
                }
                Err(failure) => return failure_note(exercise, EXERCISE_FILE, &failure),
            };
            // Compare one sweep from the same chain (so an early slip is not blamed later).
            let mut expected = before;
            crate::ik::ccd_iteration(&mut expected, self.target);
            crate::ik::ccd_iteration(&mut reference, self.target);
            if let Some(j) = (0..yours.len()).find(|&j| {
                let d = yours[j].distance(expected[j]);
                d.is_nan() || d > STUDENT_TOLERANCE
            }) {
                let at = format!("iteration {k}, joint {j}");
                let note = compare_note(
                    "ccd_iteration",
                    &at,
                    &yours[j].to_array(),
                    &expected[j].to_array(),
                    STUDENT_TOLERANCE,
                )
                .1;
                if yours.iter().all(|p| p.is_finite()) {
                    self.student[1] = Some(yours);
                }
                return note + &self.probe_ccd();
            }
        }
        let n = self.iterations;
        self.student[1] = Some(yours);
        format!(
            "Your ccd_iteration matches the reference in every iteration (up to {n}) at this target.{}",
            self.probe_ccd()
        )
    }

    /// The error after each iteration for the plot: `[iteration, log₁₀ CCD error (m), log₁₀
    /// FABRIK error (m), …]` for iterations 1 … [`MAX_ITERATIONS`] (errors below 1 µm drawn at
    /// 1 µm).
    pub fn error_samples(&mut self) -> Result<Vec<f32>, String> {
        self.solve()?;
        let mut out = Vec::with_capacity(3 * MAX_ITERATIONS);
        for i in 0..MAX_ITERATIONS {
            out.extend_from_slice(&[
                (i + 1) as f32,
                self.errors[0][i].max(1e-6).log10(),
                self.errors[1][i].max(1e-6).log10(),
            ]);
        }
        Ok(out)
    }

    /// The three results (reached, error in m, iterations) for the tests and the page.
    pub fn results(&mut self) -> Result<[Option<IkResult>; 3], String> {
        self.solve()?;
        Ok(self.results)
    }

    /// A solved chain in world space: 0 analytic, 1 CCD, 2 FABRIK (empty for the analytic one
    /// unless the chain has 2 segments).
    pub fn chain(&mut self, solver: usize) -> Result<Vec<Vec3>, String> {
        self.solve()?;
        let k = solver.min(2);
        let root = Vec3::new(ROOTS_X[k], 0.0, 0.0);
        Ok(self.solved[k].iter().map(|&p| p + root).collect())
    }

    /// The camera and canvas size (CSS pixels) the last frame was drawn with, for picking.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.camera = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    fn view_proj(&self) -> Option<(Mat4, Vec2)> {
        let (camera, size) = self.camera?;
        Some((camera.projection(size.x / size.y) * camera.view(), size))
    }

    /// Whether a pointer at `(x, y)` CSS pixels is on one of the three targets.
    pub fn hits_target(&self, x_px: f32, y_px: f32) -> Result<bool, String> {
        let p = Vec2::new(finite("x", x_px)?, finite("y", y_px)?);
        let Some((view_proj, size)) = self.view_proj() else {
            return Ok(false);
        };
        Ok(ROOTS_X[self.shown_solvers()].iter().any(|&x| {
            let world = self.target + Vec3::new(x, 0.0, 0.0);
            project_to_canvas(view_proj, size, world)
                .is_some_and(|s| s.distance(p) <= GRAB_RADIUS_PX)
        }))
    }

    /// Moves the target under a pointer at `(x, y)` CSS pixels, in the plane through the target
    /// facing the camera (the same offset for all three chains, so whichever target was grabbed
    /// follows the pointer: the one nearest to it on screen). Clamped to the target's range.
    pub fn drag_target(&mut self, x_px: f32, y_px: f32) -> Result<(), String> {
        let p = Vec2::new(finite("x", x_px)?, finite("y", y_px)?);
        let Some((view_proj, size)) = self.view_proj() else {
            return Ok(());
        };
        let Some(&root_x) = ROOTS_X[self.shown_solvers()].iter().min_by(|&&a, &&b| {
            let d = |x: f32| {
                project_to_canvas(view_proj, size, self.target + Vec3::new(x, 0.0, 0.0))
                    .map_or(f32::INFINITY, |s| s.distance(p))
            };
            d(a).total_cmp(&d(b))
        }) else {
            return Ok(());
        };
        let root = Vec3::new(root_x, 0.0, 0.0);
        if let Some(world) = point_on_view_plane(view_proj, size, self.target + root, p) {
            let t = (world - root).clamp(Vec3::splat(-1.5), Vec3::splat(1.5));
            self.set_target(t)?;
        }
        Ok(())
    }

    /// The chains drawn: all three with 2 segments, CCD and FABRIK only otherwise (two-joint
    /// IK has no answer for them).
    pub fn shown_solvers(&self) -> std::ops::Range<usize> {
        if self.segments == 2 {
            0..3
        } else {
            1..3
        }
    }

    /// Solves (if anything changed) and draws. Returns the note.
    pub fn draw(&mut self, frame: &mut Frame) -> Result<String, String> {
        self.solve()?;
        frame.grid(12, 0.25);
        let limits = self.joint_limits();
        let mut placed_labels = Vec::new();
        for k in self.shown_solvers() {
            let root = Vec3::new(ROOTS_X[k], 0.0, 0.0);
            let target = self.target + root;
            let color = SOLVER_COLORS[k];
            // Each chain's own target, in its colour, so none is taken for a neighbour's.
            frame.marker(target, TARGET_PX, color);
            // Above the target where that is clear (the grey square around its foot and the
            // hinges' arcs lie near it); the rightmost chain's reads leftwards, so that it stays
            // clear of the canvas's right edge.
            let up = Vec3::new(if k == 2 { -0.05 } else { 0.05 }, 0.12, 0.0);
            placed_labels.push(PlacedLabel {
                at: target,
                out: up.normalize(),
                first_m: up.length(),
                low_y: f32::NEG_INFINITY,
                line: None,
                short_text: None,
                own_side: true,
                text: format!("{} target", SOLVERS[k]),
                color,
                priority: 1,
            });
            placed_labels.push(PlacedLabel {
                at: root,
                out: Vec3::NEG_Y,
                first_m: ROOT_LABEL_FIRST_M,
                low_y: root.y + ROOT_LABEL_LOW_M,
                line: None,
                short_text: None,
                own_side: false,
                text: SOLVERS[k].into(),
                color,
                priority: 2,
            });
            draw_chain(frame, root, &self.solved[k], color);
            if k == 0 {
                placed_labels.extend(self.draw_law_of_cosines(frame, root));
            }
            // What is left between the end and the target: a dashed line with its length, for
            // every miss the note reports (a few millimetres show as the label alone).
            if let (Some(r), Some(&end)) = (self.results[k], self.solved[k].last()) {
                if !r.reached {
                    let end = end + root;
                    frame.stroke(
                        &[end, target],
                        color,
                        StrokeStyle::dashed(GAP_PX, 0.03, 0.02),
                    );
                    let below = Vec3::new(0.03, -0.06, 0.0);
                    placed_labels.push(PlacedLabel {
                        at: end.lerp(target, 0.5),
                        out: below.normalize(),
                        first_m: below.length(),
                        low_y: f32::NEG_INFINITY,
                        line: Some([end, target]),
                        short_text: None,
                        own_side: false,
                        text: format!("{:.1} mm short", r.error * 1000.0),
                        color,
                        priority: 0,
                    });
                }
            }
            if k > 0 {
                if let Some((l, d)) = &limits {
                    draw_limits(frame, root, &self.solved[k], l, *d);
                }
                if self.limits == Limits::Hinges {
                    placed_labels.extend(self.draw_hinge_plane(frame, root));
                }
            }
            // The chain's reach and its target stay in view; hinges (all about z) keep the chain
            // in the z = 0 plane, so the box is flat there and the chains are drawn larger.
            let depth = if self.limits == Limits::Hinges { 0.0 } else { 0.2 };
            frame.keep_box_in_view(
                root + Vec3::new(-0.6, -0.15, -depth),
                root + Vec3::new(0.6, 1.05, depth),
            );
            frame.keep_in_view.push(target);
        }
        // The student's chains (7.1 on the two-joint chain, 7.2 on CCD's) after every reference
        // chain and over everything, thinner than the bars and joints they trace: a correct
        // answer lies inside the reference chain and must still show.
        if self.use_exercise {
            for k in self.shown_solvers().filter(|&k| k < 2) {
                if let Some(student) = &self.student[k] {
                    let root = Vec3::new(ROOTS_X[k], 0.0, 0.0);
                    let shifted: Vec<Vec3> = student.iter().map(|&p| p + root).collect();
                    let on_top = StrokeStyle {
                        on_top: true,
                        ..StrokeStyle::solid(STUDENT_PX)
                    };
                    frame.stroke(&shifted, palette::STUDENT, on_top);
                    for &p in &shifted {
                        frame.marker_on_top(p, STUDENT_DOT_PX, palette::STUDENT);
                    }
                }
            }
        }
        // Last, once every chain is drawn (a chain passes another's root when the target lies
        // far to the side), highest priority first, as the page's layout places them.
        let priorities: Vec<i32> = placed_labels.iter().map(|l| l.priority).collect();
        let mut placed_labels: Vec<Option<PlacedLabel>> =
            placed_labels.into_iter().map(Some).collect();
        for i in crate::draw::layout::priority_order(&priorities) {
            if let Some(label) = placed_labels[i].take() {
                self.place_label(frame, label);
            }
        }
        Ok(self.notes.join(" "))
    }

    /// Adds a label near the point it names: a label that measures a segment just beside that
    /// segment when such a place is clear ([`beside_line_px`]); otherwise in its preferred place
    /// (`first_m` along `out`, reading away from the point) when that covers none of the frame's
    /// dots, lines and labels on the canvas the figure was last drawn on, else in the first such
    /// place around the point, nearest the preferred direction first (rings in metres, then
    /// rings on screen), and round points along the segment; a place [`LABEL_GAP_PX`] off every
    /// dot and line first, else one that only does not cover them; a target's name in a place
    /// nearer its own target than any other first. The chains, side d, the circle of
    /// middle joints, the pole's line, the hinges' arcs and the grey square of their plane sweep
    /// round the roots and the targets as the target and the pole move. Where no place is clear it keeps the preferred
    /// one. The anchor stays put (at the preferred place, or, once the figure has a view, at
    /// `at` on the segment a label measures) and every place is a screen offset from it ([`crate::draw::Label::offset_px`]), so
    /// the place chosen never moves the camera's fit.
    fn place_label(&self, frame: &mut Frame, label: PlacedLabel) {
        let anchor_at = |dir: Vec3, r: f32| {
            let a = label.at + dir * r;
            Vec3::new(a.x, a.y.max(label.low_y), a.z)
        };
        // Every label's anchor joins the points the camera fits: a place chosen for the last
        // frame's view must not move the next frame's fit.
        let first_at = anchor_at(label.out, label.first_m);
        let mut placed = crate::draw::Label {
            anchor: first_at,
            text: label.text,
            color: label.color,
            left: label.out.x < 0.0,
            priority: label.priority,
            offset_px: Vec2::ZERO,
            large: false,
        };
        let Some((view_proj, size)) = self.view_proj() else {
            frame.labels.push(placed);
            return;
        };
        // A label that measures a segment is anchored on it, so that the page's leader line to
        // a label moved off it starts on the segment; its preferred place is an offset.
        if label.line.is_some() {
            placed.anchor = label.at;
            // The preferred anchor stays among the points the camera fits, as in the first
            // frame, drawn without a view: the fit does not move once the figure has one.
            frame.keep_in_view.push(first_at);
        }
        let Some(home) = project_to_canvas(view_proj, size, placed.anchor) else {
            frame.labels.push(placed);
            return;
        };
        if let Some(first) = project_to_canvas(view_proj, size, first_at) {
            placed.offset_px = first - home;
        }
        let base = label.out.y.atan2(label.out.x);
        let mut places = vec![(first_at, placed.left)];
        // Nearest the preferred direction first, a ring at a time, each place reading away
        // from the point first; a label that reads best on its own side of the point tries
        // that side (within 45°) at every ring before it turns further.
        const RINGS_M: [f32; 8] = [0.12, 0.16, 0.2, 0.24, 0.28, 0.36, 0.44, 0.52];
        let side_steps = if label.own_side { 0..5 } else { 0..0 };
        let rings = RINGS_M.iter().map(|&r| (r, side_steps.clone()));
        for (r, steps) in rings.chain(RINGS_M.iter().map(|&r| (r, 0..16))) {
            for step in steps {
                let turn = (step as f32 * 0.5).ceil() * if step % 2 == 0 { 1.0 } else { -1.0 };
                let angle = base + turn * std::f32::consts::TAU / 16.0;
                let dir = Vec3::new(angle.cos(), angle.sin(), 0.0);
                let at = anchor_at(dir, r);
                let left = dir.x < 0.0;
                places.extend([(at, left), (at, !left)]);
            }
        }
        let line_px = label.line.and_then(|[p, q]| {
            let (a, b) = (
                project_to_canvas(view_proj, size, p)?,
                project_to_canvas(view_proj, size, q)?,
            );
            (a.distance(b) > 1.0).then_some((a, b))
        });
        // Just beside the segment it measures: in full up to 10 px from it, then shortened up
        // to 16 px, then in full at 16 px, then shortened at 22 px.
        let mut candidates = Vec::new();
        if let Some((a, b)) = line_px {
            let full = placed.text.clone();
            let tries = [
                (Some(full.clone()), &[4.0, 10.0][..]),
                (label.short_text.clone(), &[4.0, 10.0, 16.0][..]),
                (Some(full), &[16.0][..]),
                (label.short_text.clone(), &[22.0][..]),
            ];
            let out = label.out.truncate();
            for (text, gaps) in tries {
                let Some(text) = text else { continue };
                for offset_px in beside_line_px(a, b, home, &text, out, gaps) {
                    candidates.push(crate::draw::Label {
                        offset_px,
                        left: false,
                        text: text.clone(),
                        ..placed.clone()
                    });
                }
            }
        }
        let beside = candidates.len();
        let mut offsets: Vec<(Vec2, bool)> = places
            .iter()
            .filter_map(|&(at, left)| Some((project_to_canvas(view_proj, size, at)? - home, left)))
            .collect();
        // Then rings on screen round the point (and points along the line it measures), for a
        // canvas where the figure is small.
        let along = label.line.map_or(Vec::new(), |[p, q]| {
            [0.6, 0.4, 0.9].map(|t| p.lerp(q, t)).to_vec()
        });
        let centres = std::iter::once(label.at).chain(along);
        for centre in centres.filter_map(|c| project_to_canvas(view_proj, size, c)) {
            for r_px in [12.0, 18.0, 26.0, 36.0, 48.0, 64.0, 80.0, 96.0] {
                for step in 0..16 {
                    let angle = step as f32 * std::f32::consts::TAU / 16.0;
                    let p = centre + r_px * Vec2::new(angle.cos(), -angle.sin());
                    offsets.extend([(p - home, false), (p - home, true)]);
                }
            }
        }
        candidates.extend(offsets.into_iter().map(|(offset_px, left)| crate::draw::Label {
            offset_px,
            left,
            ..placed.clone()
        }));
        // The first place that keeps a visible gap from every dot and line (a name that touches
        // a hinge's arc reads as part of it), else the first that only does not cover them; side
        // d's label tries every place beside its line both ways before it turns round the point.
        let beside = if label.short_text.is_some() { beside } else { 0 };
        let (near, around) = candidates.split_at(beside);
        // A miss's label (a measured line, not its own side) takes first a place whose leader
        // line keeps LEADER_CLEAR_PX off every label placed before it and every dot but one it
        // starts on (`strict` 2: a leader grazing the pole's dot or a name reads as pointing at
        // it), then one whose leader crosses no label (`strict` 1: side d's lies on the same
        // line), then any, in each tier.
        let miss = label.line.is_some() && !label.own_side;
        let leader_crosses = |c: &crate::draw::Label, strict: u8| {
            let Some(r) = c.first_place(view_proj, size) else {
                return false;
            };
            let end = r.nearest(home);
            let room = if strict == 2 { LEADER_CLEAR_PX } else { 0.0 };
            let grazes = |c: Vec2, r: Vec2| {
                !(home - c).abs().cmplt(r).all()
                    && crate::draw::segment_enters(home, end, c - r, c + r)
            };
            strict > 0 && miss && end.distance(home) > crate::draw::layout::LEADER_PX
                && (frame.labels.iter().any(|o| {
                    o.first_place(view_proj, size).is_some_and(|o| {
                        grazes(o.min + 0.5 * o.size, 0.5 * o.size + room)
                    })
                }) || strict == 2 && frame.markers.iter().any(|m| {
                    project_to_canvas(view_proj, size, m.center.into()).is_some_and(|c| {
                        grazes(c, Vec2::splat(0.5 * m.size_px + room))
                    })
                }))
        };
        // A target's name (the only label that keeps to its own side of a point it does not
        // measure) sits nearer its own target's dot than any other's: a name nearer a
        // neighbour's target reads as naming that one. Likewise a chain's name (and α) at its
        // root sits nearer that root than any other chain's joints and target.
        let target_name = label.own_side && label.line.is_none();
        let root_name = label.low_y.is_finite() && label.line.is_none();
        let own = project_to_canvas(view_proj, size, label.at);
        let dots: Vec<Vec2> = self
            .shown_solvers()
            .flat_map(|k| {
                let root = ROOTS_X[k] * Vec3::X;
                let mine = root == label.at;
                let chain = self.solved[k].iter().filter(move |_| root_name && !mine);
                let target = (target_name || (root_name && !mine)).then_some(&self.target);
                chain.chain(target).map(move |&p| p + root)
            })
            .filter_map(|p| project_to_canvas(view_proj, size, p))
            .collect();
        let nearest_own = |c: &crate::draw::Label| {
            let gap = |r: crate::draw::layout::Rect, p: Vec2| r.nearest(p).distance(p);
            c.first_place(view_proj, size).is_some_and(|r| {
                own.is_none_or(|o| dots.iter().all(|&p| p == o || gap(r, p) > gap(r, o)))
            })
        };
        let g = LABEL_GAP_PX;
        // A target's name nearer another target only where no place nearer its own is clear; a
        // miss's label touching a line before its leader crosses side d's label.
        let tiers = [
            (near, g, 2),
            (near, 0.0, 2),
            (near, g, 1),
            (near, 0.0, 1),
            (near, g, 0),
            (near, 0.0, 0),
            (around, g, 2),
            (around, 0.0, 2),
            (around, g, 1),
            (around, 0.0, 1),
            (around, g, 0),
            (around, 0.0, 0),
        ];
        // With the gap from dots and lines, also [`LABELS_ROOMY_PX`] from every label placed
        // before, twice that between two words sharing half a line: text set wider than
        // measured makes two names 6 px apart touch, and two words on one line 12 px apart
        // read as one ("d = 0.071 m CCD"). A side's one-letter name keeps to its side.
        let roomy = |c: &crate::draw::Label| {
            c.first_place(view_proj, size).is_some_and(|r| {
                frame.labels.iter().all(|l| {
                    l.first_place(view_proj, size).is_none_or(|o| {
                        let shared = r.max().y.min(o.max().y) - r.min.y.max(o.min.y);
                        let words = c.text.len() > 1 && l.text.len() > 1;
                        let gap = if words && shared >= 8.0 { 2.0 } else { 1.0 };
                        !o.overlaps(&r, gap * LABELS_ROOMY_PX)
                    })
                })
            })
        };
        let clear = [true, false].into_iter().find_map(|nearest| {
            tiers.iter().find_map(|&(list, margin_px, strict)| {
                list.iter().find(|c| {
                    frame.label_is_clear_by(view_proj, size, c, margin_px)
                        && (margin_px == 0.0 || roomy(c))
                        && !leader_crosses(c, strict)
                        && (!nearest || nearest_own(c))
                })
            })
        });
        if let Some(candidate) = clear {
            placed = candidate.clone();
        }
        frame.labels.push(placed);
    }

    /// With hinges, where the target is off the z = 0 plane through the root that the hinges (all
    /// about z) keep the chain in: a grey square of that plane around the target's foot, a hollow
    /// dot at the foot and a grey dashed drop from the target to it. The drop is the distance no
    /// hinged pose can cover; the main view sees it nearly end on, so it is drawn wide, over
    /// everything, with its length on it, and the inset shows it from the side. Returns the
    /// length's label, which [`IkFigure::place_label`] places once everything is drawn.
    fn draw_hinge_plane(&self, frame: &mut Frame, root: Vec3) -> Option<PlacedLabel> {
        if self.target.z.abs() < 0.01 {
            return None;
        }
        let target = self.target + root;
        let foot = Vec3::new(target.x, target.y, root.z);
        let h = HINGE_PATCH_M;
        let square = [(-h, -h), (h, -h), (h, h), (-h, h), (-h, -h)]
            .map(|(x, y)| foot + Vec3::new(x, y, 0.0));
        frame.stroke(&square, palette::GREY, StrokeStyle::solid(1.5));
        let on_top = StrokeStyle {
            on_top: true,
            ..StrokeStyle::dashed(2.0 * GAP_PX, 0.03, 0.02)
        };
        frame.stroke(&[foot, target], palette::GREY, on_top);
        frame.marker(foot, POLE_PX, palette::GREY);
        // From the side (looking along −x) the chains' plane is a vertical line and the drop
        // runs across: the corner view shows the gap that the main view sees nearly end on.
        let depth = (self.target.z.abs() + 0.1).max(0.35);
        frame.inset(
            InsetView::Side,
            "from the side",
            root + Vec3::new(-0.6, -0.15, -depth),
            root + Vec3::new(0.6, 1.05, depth),
        );
        Some(PlacedLabel {
            at: foot.lerp(target, 0.5),
            out: Vec3::X,
            first_m: 0.05,
            low_y: f32::NEG_INFINITY,
            line: Some([foot, target]),
            short_text: None,
            own_side: false,
            text: format!("{:.0} cm", self.target.z.abs() * 100.0),
            color: palette::GREY,
            priority: 0,
        })
    }

    /// On the two-joint chain: the triangle of the law of cosines (sides a, b, d, the angle α at
    /// the root), the pole and its dashed line to the middle joint, and the circle of middle
    /// joints the pole chooses from (one per pole angle).
    /// Returns α's, d's, a's and b's labels, which [`IkFigure::place_label`] places once
    /// everything is drawn.
    fn draw_law_of_cosines(&self, frame: &mut Frame, root: Vec3) -> Vec<PlacedLabel> {
        let pole = self.pole() + root;
        frame.marker(pole, POLE_PX, palette::PURPLE);
        let [r, m, e] = match self.solved[0][..] {
            [r, m, e] => [r + root, m + root, e + root],
            _ => return Vec::new(),
        };
        frame.stroke(
            &[m, pole],
            palette::PURPLE,
            StrokeStyle::dashed(1.5, 0.03, 0.03),
        );
        let d = (self.target).length();
        let a = (m - r).length();
        let u = (e - r).normalize_or(Vec3::Y);
        // The circle of middle joints: centre on the root→end line at a·cos α, radius a·sin α.
        let along = (m - r).dot(u);
        let centre = r + u * along;
        let radial = m - centre;
        if radial.length() > 1e-3 {
            let circle: Vec<Vec3> = (0..=48)
                .map(|k| {
                    centre
                        + Quat::from_axis_angle(u, std::f32::consts::TAU * k as f32 / 48.0) * radial
                })
                .collect();
            frame.stroke(
                &circle,
                palette::PURPLE,
                StrokeStyle::dashed(1.5, 0.02, 0.02),
            );
        }
        // Side d along the root→target line (up to the end when the target is out of reach).
        let g = self.target + root;
        frame.stroke(&[r, g], palette::GREY, StrokeStyle::dashed(1.5, 0.04, 0.03));
        // Each label beside what it names, on the side away from the triangle, reading away
        // from it (left of its anchor when it lies to the left), so it covers no line.
        let centroid = (r + m + e) / 3.0;
        let beside = |frame: &mut Frame, at: Vec3, out: Vec3, text: String, color: Vec3| {
            let out = Vec3::new(out.x, out.y, 0.0).normalize_or(Vec3::X);
            let anchor = at + out * (0.05 + 0.07 * out.y.abs());
            frame.labels.push(crate::draw::Label {
                anchor,
                text,
                color,
                left: out.x < 0.0,
                priority: 0,
                offset_px: glam::Vec2::ZERO,
                large: false,
            });
        };
        // A side's middle and the direction across it away from the triangle, in the xy plane
        // the page's camera nearly faces (the triangle may be seen edge on).
        let away = |p: Vec3, q: Vec3| {
            let mid = p.lerp(q, 0.5);
            let across = (q - p).truncate().perp().normalize_or(glam::Vec2::X);
            let off = (mid - centroid).truncate();
            let sign = if across.dot(off) < 0.0 { -1.0 } else { 1.0 };
            (mid, (sign * across).extend(0.0))
        };
        // The pole's label beyond it, away from its dashed line to the middle joint.
        beside(frame, pole, pole - m, "pole".into(), palette::PURPLE);
        // Sides a and b are measured like d: each anchored on its side, placed just beside it
        // where that is clear (a moved label's leader then ends on the side it names).
        let side = |p: Vec3, q: Vec3, text: &str| {
            let (at, out) = away(p, q);
            PlacedLabel {
                at,
                out,
                first_m: 0.05 + 0.07 * out.y.abs(),
                low_y: f32::NEG_INFINITY,
                line: Some([p, q]),
                short_text: None,
                own_side: true,
                text: text.into(),
                color: palette::BLUE,
                priority: 0,
            }
        };
        let sides = [side(r, m, "a"), side(m, e, "b")];
        // Side d's label towards the target's end, clear of the circle of middle joints
        // (whose centre lies on d) and of α's label at the root's end.
        let (_, out) = away(r, g);
        let out = Vec3::new(out.x, out.y, 0.0).normalize_or(Vec3::X);
        let d_label = PlacedLabel {
            at: r.lerp(g, 0.8),
            out,
            first_m: 0.05 + 0.07 * out.y.abs(),
            low_y: f32::NEG_INFINITY,
            line: Some([r, g]),
            short_text: Some("d".into()),
            own_side: true,
            text: format!("d = {} m", format_number(d)),
            color: palette::GREY,
            priority: 0,
        };
        // The angle α at the root, between the line to the target and the first segment.
        let first = (m - r).normalize_or(Vec3::Y);
        let angle = u.angle_between(first);
        if angle > 1e-3 && a > 0.0 {
            let axis = u.cross(first).normalize_or(Vec3::Z);
            let arc: Vec<Vec3> = (0..=16)
                .map(|k| r + Quat::from_axis_angle(axis, angle * k as f32 / 16.0) * u * 0.18)
                .collect();
            frame.stroke(&arc, palette::DARK, StrokeStyle::solid(2.0));
            // Across the root from the arc where that is clear: the wedge is too narrow for the
            // text, and the circle of middle joints passes beside it.
            let bisector = Quat::from_axis_angle(axis, 0.5 * angle) * u;
            let out = Vec3::new(-bisector.x, -bisector.y, 0.0).normalize_or(Vec3::NEG_Y);
            return vec![
                PlacedLabel {
                    at: r,
                    out,
                    first_m: 0.05 + 0.07 * out.y.abs(),
                    low_y: r.y + ROOT_LABEL_LOW_M,
                    line: None,
                    short_text: None,
                    own_side: false,
                    text: format!("α = {:.0}°", angle / DEG),
                    color: palette::DARK,
                    priority: 0,
                },
                d_label,
            ]
            .into_iter()
            .chain(sides)
            .collect();
        }
        std::iter::once(d_label).chain(sides).collect()
    }
}

/// A label placed once the whole figure is drawn ([`IkFigure::place_label`]): a chain's name
/// and α at its root, a target's name, a miss's length, side d.
struct PlacedLabel {
    /// The point it names (or sits beside), world space.
    at: Vec3,
    /// The preferred direction from `at`, in the xy plane, unit length.
    out: Vec3,
    /// How far along `out` the preferred anchor lies, metres.
    first_m: f32,
    /// The lowest the anchor may go, world y in metres.
    low_y: f32,
    /// The segment the label measures, if any (side d, a miss), with `at` on it: the label is
    /// anchored at `at`, its first places lie just beside the segment on screen, and its last
    /// ones round points along it.
    line: Option<[Vec3; 2]>,
    /// A shorter text it takes just beside `line` where the full text fits no clear place there
    /// (side d's letter alone: the note gives its length).
    short_text: Option<String>,
    /// It tries its own side of `at` (within 45° of `out`) further out before turning round
    /// `at`: a target's name below its target reads as naming the chain beneath.
    own_side: bool,
    text: String,
    color: Vec3,
    priority: i32,
}

/// Screen offsets (from the place the page's layout first gives a label reading `text`
/// rightwards from `home`, its anchor's projection) that put the label's box just beside the
/// segment `a`–`b` on the canvas: its nearest edge each of `gaps_px` in turn from the
/// segment's line, at points from three quarters of the way to `b` out to `b` and back towards
/// `a`, on the side `out` (a direction on screen, y up) points to first, then on the other, and
/// last (for gaps up to 10 px) past `b` on the line's continuation, 8 px further out for the
/// target's dot there.
fn beside_line_px(
    a: Vec2,
    b: Vec2,
    home: Vec2,
    text: &str,
    out: Vec2,
    gaps_px: &[f32],
) -> Vec<Vec2> {
    use crate::draw::layout::{preferred, LabelBox};
    let size = crate::draw::label_size_px(text);
    let first = preferred(&LabelBox {
        anchor: home,
        size,
        left: false,
        visible: true,
        priority: 0,
    });
    // Screen y runs down: `out`'s y flips.
    let mut normal = (b - a).perp().normalize();
    if normal.dot(Vec2::new(out.x, -out.y)) < 0.0 {
        normal = -normal;
    }
    // The box's half extent along a direction on screen.
    let half = |dir: Vec2| 0.5 * (size.x * dir.x.abs() + size.y * dir.y.abs());
    let mut offsets = Vec::new();
    for &gap_px in gaps_px {
        for t in [0.75, 0.9, 0.6, 1.0, 0.45, 0.3, 0.15] {
            for side in [normal, -normal] {
                let centre = a.lerp(b, t) + side * (gap_px + half(side));
                offsets.push(centre - 0.5 * size - first);
            }
        }
        // Past the end at `b`, on the line's continuation, clear of a target's dot there (at
        // the smaller gaps only: a wide box far along a steep line ends up far from it).
        if gap_px <= 10.0 {
            let on = (b - a).normalize();
            let centre = b + on * (gap_px + 8.0 + half(on));
            offsets.push(centre - 0.5 * size - first);
        }
    }
    offsets
}

/// The gap a placed label keeps from every dot's and line's edge where it can, CSS pixels: past
/// a line's antialiased rim (1 px), with a pixel to spare.
const LABEL_GAP_PX: f32 = 2.0;
/// The room a label keeps from the others where it can, CSS px.
const LABELS_ROOMY_PX: f32 = 12.0;
/// The room a miss's leader keeps from other labels and from dots where it can, CSS px.
const LEADER_CLEAR_PX: f32 = 3.0;

/// How far below its root a chain's name sits first, metres.
const ROOT_LABEL_FIRST_M: f32 = 0.12;

/// How far below its root a root label's anchor may go, metres: the bottom of the box each chain
/// keeps in view.
const ROOT_LABEL_LOW_M: f32 = -0.15;

/// A chain: a sphere per joint, a bar per segment.
fn draw_chain(frame: &mut Frame, root: Vec3, chain: &[Vec3], color: Vec3) {
    for (i, &p) in chain.iter().enumerate() {
        let p = p + root;
        let radius = if i == 0 { 0.035 } else { 0.025 };
        frame.mesh(
            MeshId::SPHERE,
            Mat4::from_scale_rotation_translation(Vec3::splat(radius), Quat::IDENTITY, p),
            if i == 0 { palette::DARK } else { color },
        );
        if i > 0 {
            bar(frame, chain[i - 1] + root, p, color);
        }
    }
}

fn bar(frame: &mut Frame, a: Vec3, b: Vec3, color: Vec3) {
    let v = b - a;
    let length = v.length();
    if length.is_nan() || length <= 1e-4 {
        return;
    }
    let model = Mat4::from_scale_rotation_translation(
        Vec3::new(0.012, 0.5 * length, 0.012),
        Quat::from_rotation_arc(Vec3::Y, v / length),
        a + 0.5 * v,
    );
    frame.mesh(MeshId::CUBE, model, color);
    frame.wide_line(a, b, color, 2.0);
}

/// Each joint's allowed range: an arc for a hinge, a circle for a cone, 12 cm out.
fn draw_limits(
    frame: &mut Frame,
    root: Vec3,
    chain: &[Vec3],
    limits: &[JointLimit],
    root_direction: Vec3,
) {
    const R: f32 = 0.12;
    const STEPS: usize = 16;
    let mut points = [Vec3::ZERO; STEPS + 1];
    for (i, limit) in limits.iter().enumerate() {
        let pivot = chain[i] + root;
        let incoming = if i == 0 {
            root_direction
        } else {
            (chain[i] - chain[i - 1]).normalize_or(root_direction)
        };
        match *limit {
            JointLimit::Free => {}
            JointLimit::Hinge {
                axis,
                min_rad,
                max_rad,
            } => {
                let axis = axis.normalize();
                let zero = (incoming - axis * incoming.dot(axis)).normalize_or(Vec3::Y);
                for (s, p) in points.iter_mut().enumerate() {
                    let a = min_rad + (max_rad - min_rad) * s as f32 / STEPS as f32;
                    *p = pivot + Quat::from_axis_angle(axis, a) * zero * R;
                }
                frame.wide_polyline(&points, palette::GREY, 1.5);
                frame.wide_line(pivot, points[0], palette::GREY, 1.5);
                frame.wide_line(pivot, points[STEPS], palette::GREY, 1.5);
            }
            JointLimit::Cone { max_rad } => {
                let side = incoming.any_orthonormal_vector();
                let rim = Quat::from_axis_angle(side, max_rad) * incoming * R;
                for (s, p) in points.iter_mut().enumerate() {
                    let a = std::f32::consts::TAU * s as f32 / STEPS as f32;
                    *p = pivot + Quat::from_axis_angle(incoming, a) * rim;
                }
                frame.wide_polyline(&points, palette::GREY, 1.5);
                frame.wide_line(pivot, points[0], palette::GREY, 1.5);
                frame.wide_line(pivot, points[STEPS / 2], palette::GREY, 1.5);
            }
        }
    }
}

/// The lesson's aim figure: a head on a neck turns to look at a target, at most `max_angle`
/// from straight ahead.
#[derive(Clone, Debug)]
pub struct AimFigure {
    /// The target, metres (model space; the head sits at (0, 1.6, 0) looking along +z).
    target: Vec3,
    max_angle_rad: f32,
    /// The camera and canvas size (CSS pixels) of the last frame, that the labels keep clear on.
    view: Option<(OrbitCamera, Vec2)>,
}

impl Default for AimFigure {
    fn default() -> Self {
        Self::new()
    }
}

/// How long the aim figure's target takes to circle once, seconds.
pub const AIM_PERIOD_SEC: f32 = 8.0;
/// How far the aim figure's target may go along x and z, metres (the view frames it all).
pub const AIM_REACH_M: f32 = 1.2;
/// How low and how high the aim figure's target may go, metres.
pub const AIM_HEIGHT_M: (f32, f32) = (0.6, 2.6);

/// Where the aim figure's head sits, and its rest forward and up.
const HEAD: Vec3 = Vec3::new(0.0, 1.6, 0.0);

impl AimFigure {
    pub fn new() -> Self {
        Self {
            // Its loop runs from about 60° to 83° off straight ahead, across the 70° cone's
            // rim: the head follows part of the way and stops at the rim for the rest.
            target: Vec3::new(1.2, 1.9, 0.4),
            max_angle_rad: 70.0 * DEG,
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the labels of
    /// the forward arrow and of the miss keep off the body and the lines on that view.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// The target, x and z in [−[`AIM_REACH_M`], [`AIM_REACH_M`]] m, y within [`AIM_HEIGHT_M`].
    pub fn set_target(&mut self, target: Vec3) -> Result<(), String> {
        self.target = Vec3::new(
            in_range("target x", target.x, -AIM_REACH_M, AIM_REACH_M)?,
            in_range("target y", target.y, AIM_HEIGHT_M.0, AIM_HEIGHT_M.1)?,
            in_range("target z", target.z, -AIM_REACH_M, AIM_REACH_M)?,
        );
        Ok(())
    }

    /// Where the target is at `time_sec`: it circles its set position (radius 0.25 m) once every
    /// [`AIM_PERIOD_SEC`], bobbing up and down twice, so the motion loops with the timeline.
    pub fn target_at(&self, time_sec: f32) -> Vec3 {
        let a = std::f32::consts::TAU * time_sec / AIM_PERIOD_SEC;
        self.target + 0.25 * Vec3::new(a.cos(), 0.6 * (2.0 * a).sin(), a.sin())
    }

    /// How far the head may turn from straight ahead, degrees in [0, 180].
    pub fn set_max_angle_deg(&mut self, deg: f32) -> Result<(), String> {
        self.max_angle_rad = in_range("largest turn", deg, 0.0, 180.0)? * DEG;
        Ok(())
    }

    /// Samples over one loop of the timeline for the plot: `[time (s), angle from straight
    /// ahead to the target (°), angle the head turns (°), …]`, `samples` + 1 rows from 0 to
    /// [`AIM_PERIOD_SEC`]. The head's angle follows the target's until it reaches the cone.
    pub fn plot_samples(&self, samples: usize) -> Result<Vec<f32>, String> {
        super::check_samples(samples)?;
        let n = samples;
        let mut out = Vec::with_capacity(3 * (n + 1));
        for k in 0..=n {
            let t = AIM_PERIOD_SEC * k as f32 / n as f32;
            let target = self.target_at(t);
            let s = aim(HEAD, Vec3::Z, Vec3::Y, target, self.max_angle_rad, 1e-3)
                .map_err(|e| e.to_string())?;
            out.extend_from_slice(&[
                t,
                Vec3::Z.angle_between(target - HEAD) / DEG,
                Vec3::Z.angle_between(s.forward) / DEG,
            ]);
        }
        Ok(out)
    }

    /// Aims and draws. Returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let t = finite("time", time_sec)?;
        frame.grid(12, 0.25);
        // The target circles slowly around its set position, so the head keeps following.
        let target = self.target_at(t);
        let s = aim(HEAD, Vec3::Z, Vec3::Y, target, self.max_angle_rad, 1e-3)
            .map_err(|e| e.to_string())?;
        // Body, neck and head.
        frame.mesh(
            MeshId::CUBE,
            Mat4::from_scale_rotation_translation(
                Vec3::new(0.2, 0.35, 0.12),
                Quat::IDENTITY,
                Vec3::new(0.0, 1.1, 0.0),
            ),
            palette::GREY,
        );
        let head = Mat4::from_rotation_translation(s.rotation, HEAD);
        frame.mesh(
            MeshId::SPHERE,
            head * Mat4::from_scale(Vec3::splat(0.13)),
            palette::BROWN,
        );
        frame.axes(head, 0.2);
        // From the head's surface, over everything: a head turned down and back looks through
        // its own body, and the arrow stays whole.
        frame.arrow_on_top(
            HEAD + s.forward * 0.13,
            HEAD + s.forward * 0.8,
            palette::BLUE,
            0.08,
        );
        frame.marker(target, TARGET_PX, palette::RED);
        // Looking straight at it, a dashed line on from the arrow's tip to a target farther
        // off, in the arrow's colour: the forward direction runs through the target.
        let tip = HEAD + s.forward * 0.8;
        if s.result.reached && (target - HEAD).dot(s.forward) > 0.8 {
            frame.stroke(&[tip, target], palette::BLUE, StrokeStyle::dashed(GAP_PX, 0.06, 0.04));
        }
        let to_target = (target - HEAD).normalize_or(Vec3::Z);
        let missed = s.forward.angle_between(to_target);
        let axis = s
            .forward
            .cross(to_target)
            .try_normalize()
            .unwrap_or_else(|| s.forward.any_orthonormal_vector());
        if !s.result.reached {
            // What the head misses: a dashed line to the target, and the angle between where
            // it looks and where the target is, drawn as an arc with its size.
            frame.stroke(
                &[HEAD, target],
                palette::RED,
                StrokeStyle::dashed(GAP_PX, 0.06, 0.04),
            );
            let arc: Vec<Vec3> = (0..=24)
                .map(|k| {
                    HEAD + Quat::from_axis_angle(axis, missed * k as f32 / 24.0) * s.forward * 0.45
                })
                .collect();
            frame.stroke(&arc, palette::RED, StrokeStyle::solid(GAP_PX));
        }
        // The cone of allowed directions, around the rest forward (+z). At 180° it allows every
        // direction and has no rim (its rim would shrink to a point behind the head, drawn as a
        // short bar): only its name, above the head.
        const STEPS: usize = 24;
        let whole = self.max_angle_rad >= std::f32::consts::PI;
        let rim = Quat::from_rotation_x(self.max_angle_rad.min(179.0 * DEG)) * Vec3::Z * 0.55;
        let circle: Vec<Vec3> = (0..=STEPS)
            .map(|k| {
                HEAD + Quat::from_rotation_z(std::f32::consts::TAU * k as f32 / STEPS as f32) * rim
            })
            .collect();
        if !whole {
            frame.wide_polyline(&circle, palette::PURPLE, CONE_PX);
            for k in (0..STEPS).step_by(3) {
                frame.wide_line(HEAD, circle[k], palette::PURPLE, CONE_PX);
            }
        }
        // The cone's name above its rim, clear of the forward arrow's label.
        let top = circle
            .iter()
            .copied()
            .fold(circle[0], |a, b| if b.y > a.y { b } else { a });
        frame.label_with_priority(
            if whole { HEAD + Vec3::Y * 0.55 } else { top } + Vec3::new(0.0, 0.12, 0.0),
            if whole {
                "180°: no limit".to_string()
            } else {
                format!("{:.0}° cone", self.max_angle_rad / DEG)
            },
            palette::PURPLE,
            0,
        );
        // The body's and the head's boxes on the last frame's view: the labels placed below
        // keep off them (meshes are not among the frame's dots and lines).
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let solids: Vec<crate::draw::layout::Rect> =
            view.map_or(Vec::new(), |(view_proj, size)| {
                [
                    (Vec3::new(0.2, 0.35, 0.12), Vec3::new(0.0, 1.1, 0.0)),
                    (Vec3::splat(0.13), HEAD),
                ]
                .iter()
                .filter_map(|&(half, centre)| {
                    let corners = crate::draw::box_corners(centre - half, centre + half);
                    let px: Option<Vec<Vec2>> = corners
                        .iter()
                        .map(|&c| project_to_canvas(view_proj, size, c))
                        .collect();
                    let px = px?;
                    let lo = px.iter().copied().fold(Vec2::MAX, Vec2::min);
                    let hi = px.iter().copied().fold(Vec2::MIN, Vec2::max);
                    Some(crate::draw::layout::Rect {
                        min: lo,
                        size: hi - lo,
                    })
                })
                .collect()
            });
        // The target's name beside its dot, the arrow's past its tip, and the miss's size past
        // the middle of its arc; where the body, the head or a line (the dashed line to the
        // target) lies there, the first place round that point clear of them.
        // The miss's size tries points along its arc from the middle out: where the arc runs
        // over the body, a leader from its middle would cross the body to a clear place.
        let mut labels = vec![
            (vec![target - HEAD], "target".to_string(), palette::RED, 2, TARGET_PX),
            (vec![s.forward * 0.85], "forward".to_string(), palette::BLUE, 2, 4.0),
        ];
        if !s.result.reached {
            labels.push((
                [0.5, 0.3, 0.7, 0.15, 0.85]
                    .map(|t| Quat::from_axis_angle(axis, t * missed) * s.forward * 0.52)
                    .to_vec(),
                format!("misses {:.0}°", missed / DEG),
                palette::RED,
                1,
                4.0,
            ));
        }
        // The dashed line on the last frame's view: a leader from a label's point back to its
        // box must not cross it (it would point at the wrong line).
        let px = |p: Vec3| view.and_then(|(view_proj, size)| project_to_canvas(view_proj, size, p));
        let dashed = px(HEAD).zip(px(target)).filter(|_| !s.result.reached);
        let side = |p: Vec2, q: Vec2, x: Vec2| (q - p).perp_dot(x - p);
        for (outs, text, color, priority, dot_px) in labels {
            let candidates: Vec<(Option<Vec2>, crate::draw::Label)> = outs
                .iter()
                .flat_map(|&out| {
                    let at = HEAD + out;
                    let first = crate::draw::Label {
                        anchor: at,
                        text: text.clone(),
                        color,
                        left: false,
                        priority,
                        offset_px: Vec2::ZERO,
                        large: false,
                    };
                    let around = crate::draw::Label::around_dot(
                        at,
                        dot_px,
                        Vec2::ZERO,
                        &text,
                        color,
                        priority,
                        12,
                        8.0,
                    );
                    std::iter::once(first).chain(around).map(move |l| (px(at), l))
                })
                .collect();
            // The first place clear of the dots, lines and solids whose leader (from the
            // label's point to the nearest point of its box) keeps off the dashed line and the
            // solids, else one whose leader only keeps off the dashed line, else the first.
            let clear = view.and_then(|(view_proj, size)| {
                [true, false].into_iter().find_map(|strict| candidates.iter().find(|(from, c)| {
                    frame.label_is_clear_by(view_proj, size, c, 2.0)
                        && c.first_place(view_proj, size).is_some_and(|r| {
                            let lead = from
                                .map(|a| (a, r.nearest(a)))
                                .filter(|(a, b)| a.distance(*b) > crate::draw::layout::GAP_PX);
                            let crosses = lead.zip(dashed).is_some_and(|((a, b), (h, g))| {
                                side(a, b, h) * side(a, b, g) < 0.0
                                    && side(h, g, a) * side(h, g, b) < 0.0
                            });
                            !crosses
                                && solids.iter().all(|b| {
                                    !b.overlaps(&r, 2.0)
                                        && (!strict || lead.is_none_or(|(p, q)| {
                                            !crate::draw::segment_enters(p, q, b.min, b.max())
                                        }))
                                })
                        })
                }))
            });
            frame
                .labels
                .push(clear.unwrap_or(&candidates[0]).1.clone());
        }
        // The body, the head's reach and the target's whole loop stay in view.
        frame.keep_box_in_view(Vec3::new(-0.6, 0.7, -0.6), Vec3::new(0.6, 2.3, 0.6));
        frame.keep_box_in_view(
            self.target - Vec3::new(0.3, 0.2, 0.3),
            self.target + Vec3::new(0.3, 0.2, 0.3),
        );
        let deg = |r: f32| format!("{:.0}", r / DEG);
        Ok(if s.result.reached {
            format!(
                "Looking straight at the target: it is {}° from straight ahead, inside the {}° cone.",
                deg(Vec3::Z.angle_between(target - HEAD)),
                deg(self.max_angle_rad)
            )
        } else {
            format!(
                "The target is {}° from straight ahead, outside the {}° cone: the head stops at the rim, {}° short (reached: no).",
                deg(Vec3::Z.angle_between(target - HEAD)),
                deg(self.max_angle_rad),
                deg(s.result.error)
            )
        })
    }
}
