//! Figure logic for lesson 14, "Rigid bodies" (see [`crate::rigid_body`]):
//!
//! - [`ThrowFigure`] (figure 1): a box thrown up with spin; `L` stays fixed in the world while ω
//!   wobbles around it (the space cone), and the centre of mass flies its parabola.
//! - [`DriftFigure`] (figure 2): quaternion drift, the additive orientation step with and without
//!   normalising beside the exponential one.
//! - [`RacketFigure`] (figure 3): the tennis racket (the intermediate-axis instability), spun
//!   about its middle axis and stepped by three angular integrators side by side, with the
//!   energy and the angular momentum each keeps.
//! - [`ImpulseFigure`] (figure 4): a box dropped tilted meets the ground with one corner; the one
//!   impulse [`crate::rigid_body::normal_impulse`] that resolves it, with v and ω before and after.
//! - [`StackFigure`] (figure 5): a stack of boxes or a row of dominoes on the contact solver
//!   (sequential impulses), with its passes, friction and restitution.
//!
//! Each is deterministic: the state at timeline time `t` is the state after `⌊t / Δt⌋` steps from
//! the start, replayed when the time goes back or a setting changes.

use super::particles::{steps_to, MAX_SIM_TIME, SIM_DT};
use super::{
    compare_note, failure_note, format_number, in_range, palette, whole_number, Frame, Runner,
    DEFAULT_RUNNER,
};
use crate::camera::{project_to_canvas, OrbitCamera};
use crate::draw::inset::InsetView;
use crate::draw::{Label, MeshId, StrokeStyle, ARROW_PX, DOT_PX};
use crate::exercises::run;
use crate::rigid_body::contact::{corners, BroadPhase, Shape, World};
use crate::rigid_body::inertia::solid_box;
use crate::rigid_body::{
    normal_impulse, orientation_step, AngularStep, OrientationStep, RigidBody,
};
use glam::{Mat4, Quat, Vec2, Vec3};

/// The racket's half-extents (m): long along x, middle along y, thin along z, so its moments
/// are smallest about x, in between about y, largest about z.
pub const RACKET_HALF: Vec3 = Vec3::new(0.3, 0.15, 0.05);
/// The three integrators, left to right, and their names.
pub const INTEGRATORS: [(AngularStep, &str); 3] = [
    (AngularStep::Momentum, "L held"),
    (AngularStep::Explicit, "explicit"),
    (AngularStep::Implicit, "implicit"),
];
/// Where the three rackets stand, along x (m), and their height.
const SPACING_M: f32 = 1.0;
const HEIGHT_M: f32 = 0.8;
/// The most samples a figure keeps for its plots (one per step, 60 s at 60 steps a second).
pub const MAX_SAMPLES: usize = 3600;
/// The racket figure's timeline (s): several flips at the default spin.
pub const RACKET_DURATION_SEC: f32 = 12.0;
/// The rackets' colours, in the order of [`INTEGRATORS`] (the page's plots use the same).
const RACKET_COLORS: [Vec3; 3] = [palette::PURPLE, palette::ORANGE, palette::TEAL];
/// A racket whose energy passes this multiple of its start has exploded: it stops there.
pub const RACKET_EXPLODED_ENERGY: f32 = 100.0;
/// The racket plots' y axes reach at most this multiple of the start: an explicit racket's
/// energy climbs towards [`RACKET_EXPLODED_ENERGY`] times its start, and an axis that follows it
/// flattens the curves the text compares onto its floor.
pub const RACKET_PLOT_TOP: f32 = 3.0;
/// Where the page's exercises live, for the notes.
const FILE: &str = "src/exercises/rigid_body.rs";

/// Three copies of the same racket, spun at `spin` rad/s about its middle axis with a small
/// wobble, each stepped by one of [`INTEGRATORS`] at [`SIM_DT`].
#[derive(Clone, Debug)]
pub struct RacketFigure {
    spin: f32,
    wobble: f32,
    /// With "use my exercise", the moments come from the student's 14.1 `box_inertia`.
    use_exercise: bool,
    runner: Runner,
    /// What the student's 14.1 gave at the last restart (a comparison or a failure).
    exercise_note: String,
    start: RigidBody,
    bodies: [RigidBody; 3],
    /// When each racket exploded (its energy past [`RACKET_EXPLODED_ENERGY`] times the start,
    /// or a number that is not finite); it is no longer stepped from then on.
    exploded: [Option<f32>; 3],
    steps_done: usize,
    /// The timeline's time of the last [`Self::advance_to`] (s), which the note names as the
    /// page's clock shows it; the bodies are at the last whole step at or before it.
    time_sec: f32,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: each name is
    /// placed just off its racket on screen, over none of the rackets.
    view: Option<(OrbitCamera, Vec2)>,
    /// Per step: time, then energy / start energy and |L| / start |L| for each integrator
    /// (NaN for a racket that has exploded: a gap in the plots).
    history: Vec<[f32; 7]>,
}

impl Default for RacketFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl RacketFigure {
    /// Spun at 6 rad/s about the middle axis, with a wobble of 0.05 rad/s about the others.
    pub fn new() -> Self {
        let i = solid_box(1.0, RACKET_HALF);
        let start = RigidBody::new(1.0, Vec3::new(i.x_axis.x, i.y_axis.y, i.z_axis.z))
            .expect("a box's moments");
        let mut f = Self {
            spin: 6.0,
            wobble: 0.05,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            exercise_note: String::new(),
            start,
            bodies: [start; 3],
            exploded: [None; 3],
            steps_done: 0,
            time_sec: 0.0,
            view: None,
            history: Vec::new(),
        };
        f.restart();
        f
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the rackets' names are placed for.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// When racket `k` exploded (s since the start), if it did.
    pub fn exploded_at(&self, k: usize) -> Option<f32> {
        self.exploded.get(k).copied().flatten()
    }

    /// The spin about the middle axis (rad/s, 0.5 to 20) and the wobble about the two others
    /// (rad/s, 0 to 1); the run starts again.
    pub fn set_spin(&mut self, spin: f32, wobble: f32) -> Result<(), String> {
        let spin = in_range("spin", spin, 0.5, 20.0)?;
        let wobble = in_range("wobble", wobble, 0.0, 1.0)?;
        self.spin = spin;
        self.wobble = wobble;
        self.restart();
        Ok(())
    }

    /// How the page runs the student's code (see [`crate::exercises::run`]).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.restart();
    }

    /// Gives the rackets the moments of the student's 14.1 `box_inertia` (the reference where
    /// it fails or answers moments no body has); the run starts again.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.restart();
    }

    /// The timeline's length (s).
    pub fn duration_sec(&self) -> f32 {
        RACKET_DURATION_SEC
    }

    /// The racket's principal moments: the reference's, or the student's, with the note to show.
    fn moments(&self) -> (Vec3, String) {
        let reference = box_moments(RACKET_HALF);
        if !self.use_exercise {
            return (reference, String::new());
        }
        match run::box_inertia(self.runner, 1.0, RACKET_HALF) {
            Err(f) => (
                reference,
                failure_note("exercise 14.1 box_inertia", FILE, &f),
            ),
            Ok(m) => {
                let at = "the racket (1 kg, half-extents 0.3 × 0.15 × 0.05 m)";
                let (_, note) = compare_note(
                    "box_inertia",
                    at,
                    &m.to_array(),
                    &reference.to_array(),
                    1e-4 * reference.max_element(),
                );
                match RigidBody::new(1.0, m) {
                    Ok(_) => (m, format!("{note} The rackets spin with your moments.")),
                    Err(e) => (
                        reference,
                        format!("{note} They are no body's moments ({e}): the figure uses the reference."),
                    ),
                }
            }
        }
    }

    /// The racket at the start of a run: spun about its middle axis, with the wobble.
    fn first(&self) -> RigidBody {
        let mut body = self.start;
        body.omega_body = Vec3::new(self.wobble, self.spin, self.wobble);
        body
    }

    fn restart(&mut self) {
        let (moments, note) = self.moments();
        self.start.inertia = moments;
        self.exercise_note = note;
        self.bodies = [self.first(); 3];
        self.exploded = [None; 3];
        self.steps_done = 0;
        self.time_sec = 0.0;
        self.history.clear();
        self.record();
    }

    fn record(&mut self) {
        if self.history.len() >= MAX_SAMPLES {
            return;
        }
        let mut row = [
            self.steps_done as f32 * SIM_DT,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ];
        let first = self.first();
        let (e0, l0) = (first.kinetic_energy(), first.angular_momentum().length());
        for (k, b) in self.bodies.iter().enumerate() {
            if self.exploded[k].is_some() {
                row[1 + k] = f32::NAN;
                row[4 + k] = f32::NAN;
            } else {
                row[1 + k] = b.kinetic_energy() / e0;
                row[4 + k] = b.angular_momentum().length() / l0;
            }
        }
        self.history.push(row);
    }

    /// Steps the three rackets to `time_sec` (0 to 60 s); an earlier time starts again.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        let target = steps_to(time_sec)?;
        if target < self.steps_done {
            self.restart();
        }
        self.time_sec = time_sec;
        let e0 = self.first().kinetic_energy();
        while self.steps_done < target {
            let t = (self.steps_done + 1) as f32 * SIM_DT;
            for (k, (body, (how, _))) in self.bodies.iter_mut().zip(INTEGRATORS).enumerate() {
                if self.exploded[k].is_some() {
                    continue;
                }
                let mut next = *body;
                next.step(SIM_DT, Vec3::ZERO, how, OrientationStep::Exponential);
                let energy = next.kinetic_energy();
                if next.is_finite() && energy.is_finite() && energy <= RACKET_EXPLODED_ENERGY * e0 {
                    *body = next;
                } else {
                    // Kept as it was before the step that blew up, and drawn red.
                    self.exploded[k] = Some(t);
                }
            }
            self.steps_done += 1;
            self.record();
        }
        Ok(())
    }

    /// The plot samples so far, one row per step: time (s), then the energy over the start
    /// energy for each integrator, then |L| over the start |L| for each.
    pub fn samples(&self) -> &[[f32; 7]] {
        &self.history
    }

    /// The y ranges of the two plots, `[energy lo, energy hi, |L| lo, |L| hi]` (shares of the
    /// start): over every racket's samples, the top cut at [`RACKET_PLOT_TOP`], so that a curve
    /// past it runs off the top of its plot.
    pub fn plot_ranges(&self) -> [f32; 4] {
        let mut out = [1.0f32; 4];
        for (first, range) in [1, 4].into_iter().zip(out.chunks_mut(2)) {
            for row in &self.history {
                for x in row[first..first + 3].iter().filter(|x| x.is_finite()) {
                    range[0] = range[0].min(*x);
                    range[1] = range[1].max(*x);
                }
            }
            range[1] = range[1].min(RACKET_PLOT_TOP);
        }
        out
    }

    /// The three rackets.
    pub fn bodies(&self) -> &[RigidBody; 3] {
        &self.bodies
    }

    /// Where racket `k` stands.
    pub fn place(k: usize) -> Vec3 {
        Vec3::new((k as f32 - 1.0) * SPACING_M, HEIGHT_M, 0.0)
    }

    /// Draws the three rackets (boxes turned by their orientations, the middle axis drawn
    /// through each in green), the angular momentum of each as a purple arrow; returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        frame.grid(12, 0.25);
        let reach = RACKET_HALF.length();
        frame.keep_box_in_view(
            Self::place(0) - Vec3::splat(reach + 0.1),
            Self::place(2) + Vec3::new(reach + 0.1, reach + 0.35, reach + 0.1),
        );
        let l0 = self.first().angular_momentum().length();
        let mut parts = Vec::new();
        let mut names = Vec::new();
        let mut solid = Vec::new();
        for (k, (body, (_, name))) in self.bodies.iter().zip(INTEGRATORS).enumerate() {
            let at = Self::place(k);
            let r = Mat4::from_mat3(body.rotation());
            let model = Mat4::from_translation(at) * r * Mat4::from_scale(RACKET_HALF);
            // Each racket in the colour of its curves on the page's plots.
            let color = match self.exploded[k] {
                Some(_) => palette::RED,
                None => RACKET_COLORS[k],
            };
            frame.mesh(MeshId::CUBE, model, color);
            let points: Vec<Vec3> = box_samples(model).collect();
            solid.extend_from_slice(&points);
            let above = at + Vec3::Y * (reach + 0.2);
            // The name in its racket's colour, as the caption and the plots' legends colour it.
            let first = Label::off_dot(above, 0.0, Vec2::NEG_Y, name.into(), color, 0);
            names.push((points, first));
            let middle = body.rotation() * Vec3::Y * (RACKET_HALF.y + 0.12);
            frame.wide_line(at - middle, at + middle, palette::Y_AXIS, ARROW_PX);
            // L at 0.3 m for the start's |L|, at most twice that (an explicit racket's grows
            // without bound before it is stopped); none for a racket that exploded. Over
            // everything: it starts inside the box, and one that has lost half its |L| would
            // end inside it too.
            if self.exploded[k].is_none() {
                let l = (body.angular_momentum() / l0 * 0.3).clamp_length_max(0.6);
                frame.arrow_on_top(at, at + l, palette::DARK, 0.05);
            }
            let row = self.history.last().copied().unwrap_or([0.0; 7]);
            parts.push(match self.exploded[k] {
                Some(t) => format!(
                    "{name}: exploded at t = {} s (its energy passed {} times the start; stopped \
                     there, in red)",
                    format_number(t),
                    RACKET_EXPLODED_ENERGY
                ),
                None => format!(
                    "{name}: energy {:.0} %, |L| {:.1} %",
                    100.0 * row[1 + k],
                    100.0 * row[4 + k]
                ),
            });
        }
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let off_boxes = super::clear_of(view, &solid);
        for (points, first) in names {
            box_label(frame, view, &points, first, &off_boxes);
        }
        let mut note = format!(
            "At t = {:.2} s, of their values at the start: {}.",
            self.time_sec,
            parts.join("; ")
        );
        if self.use_exercise {
            note.push(' ');
            note.push_str(&self.exercise_note);
        }
        note
    }
}

/// Gravity of the figures that have it (m/s²).
pub const GRAVITY: Vec3 = Vec3::new(0.0, -9.81, 0.0);
/// The thrown box's half-extents (m): long along its x, middle along y, thin along z; 1 kg. Its
/// moments are smallest about x, in between about y, largest about z (the shortest axis).
pub const THROW_HALF: Vec3 = Vec3::new(0.45, 0.22, 0.12);
/// Where the throw starts (the centre of mass, m) and the velocity it is thrown with (m/s).
pub const THROW_START: Vec3 = Vec3::new(-0.9, 1.0, 0.0);
pub const THROW_VELOCITY: Vec3 = Vec3::new(1.0, 6.0, 0.0);
/// Substeps of the throw per [`SIM_DT`] (and of the dropped box's free flight): the centre's
/// semi-implicit Euler step then lands within a millimetre of the exact parabola, and the
/// rotation's energy stays within 3 % at the top spin (measured in the tests).
pub const THROW_SUBSTEPS: usize = 50;
/// ω is drawn at the scale that makes its component along `L` this long (m), so ω's tip moves on
/// the plane across `L` this far from the centre.
pub const THROW_ARROW_M: f32 = 0.9;
/// Length of the drawn `L` (m): half as long again as ω's reach along it, so that L's last third
/// and its head stand clear past ω's tip, where ω lies a few degrees off L and hides the rest.
pub const THROW_L_M: f32 = 1.35;

/// The world direction of the thrown box's angular momentum: mostly up, leaning towards the
/// default camera so the arrow and the cone around it are seen from the side.
fn throw_l_direction() -> Vec3 {
    Vec3::new(0.35, 1.0, 0.25).normalize()
}

/// The moments of a 1 kg solid box of half-extents `half`.
fn box_moments(half: Vec3) -> Vec3 {
    let i = solid_box(1.0, half);
    Vec3::new(i.x_axis.x, i.y_axis.y, i.z_axis.z)
}

/// Figure 1: a box thrown up with spin. Gravity pulls on the centre of mass only, so it exerts no
/// torque: the centre flies the parabola `x₀ + v₀ t + ½ g t²` while the angular momentum `L`
/// stays fixed in the world. The angular velocity ω is not fixed: unless the box spins about a
/// principal axis, ω wobbles around `L` (its tip runs round the *space cone*), since `ω = I⁻¹ L`
/// in the body's turning frame.
///
/// The spin axis starts in the box's x–z plane, `tilt` degrees from its shortest axis z (the
/// axis of the largest moment) towards its longest axis x: tilt 0 spins the box about a
/// principal axis, and ω stays along `L`. The box is turned at the start so that `L` points
/// along a fixed world direction, mostly up.
///
/// The box is stepped [`THROW_SUBSTEPS`] times per [`SIM_DT`]: the rotation with
/// [`AngularStep::Momentum`] and [`OrientationStep::Exponential`], with ω read off the `L` of
/// the throw after each substep; the centre with semi-implicit Euler, started with the velocity
/// half a substep of gravity back (`v₀ − ½ g h`, leapfrog's start), which puts every step's
/// centre exactly on the parabola. The flight lasts until the centre is back at its start height,
/// `2 v₀ᵧ / g` ([`ThrowFigure::duration_sec`]); later times hold that moment (the box is caught).
#[derive(Clone, Debug)]
pub struct ThrowFigure {
    spin: f32,
    tilt_deg: f32,
    body: RigidBody,
    /// The angular momentum of the throw (world), held through the flight.
    l_world: Vec3,
    steps_done: usize,
    /// The timeline's time of the last [`Self::advance_to`] (s), which the note names as the
    /// page's clock shows it; the bodies are at the last whole step at or before it.
    time_sec: f32,
    /// Per step: `[t, |ω|, |L|, angle between ω and L (deg), rotational energy]`.
    history: Vec<[f32; 5]>,
    /// Per step: ω in the world (rad/s), for the trail of its tip.
    omegas: Vec<Vec3>,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the labels of L
    /// and ω take the sides of their tips that keep them apart and off the lines.
    view: Option<(OrbitCamera, Vec2)>,
}

impl Default for ThrowFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl ThrowFigure {
    /// Spun at 10 rad/s, 20° from the shortest axis.
    pub fn new() -> Self {
        let mut f = Self {
            spin: 10.0,
            tilt_deg: 20.0,
            body: RigidBody::new(1.0, box_moments(THROW_HALF)).expect("a box's moments"),
            l_world: Vec3::ZERO,
            steps_done: 0,
            time_sec: 0.0,
            history: Vec::new(),
            omegas: Vec::new(),
            view: None,
        };
        f.restart();
        f
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the labels of L and ω are placed for.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// The spin (rad/s, 0 to 15) and the spin axis's angle from the box's shortest axis towards
    /// its longest (degrees, 0 to 80); the throw starts again.
    pub fn set_throw(&mut self, spin: f32, tilt_deg: f32) -> Result<(), String> {
        let spin = in_range("spin", spin, 0.0, 15.0)?;
        let tilt_deg = in_range("tilt", tilt_deg, 0.0, 80.0)?;
        self.spin = spin;
        self.tilt_deg = tilt_deg;
        self.restart();
        Ok(())
    }

    /// The flight's length (s): until the centre of mass is back at its start height.
    pub fn duration_sec(&self) -> f32 {
        2.0 * THROW_VELOCITY.y / -GRAVITY.y
    }

    /// Steps in the flight.
    fn flight_steps(&self) -> usize {
        (self.duration_sec() / SIM_DT).floor() as usize
    }

    /// The box as thrown.
    pub fn first(&self) -> RigidBody {
        let mut body = RigidBody::new(1.0, box_moments(THROW_HALF)).expect("a box's moments");
        let (s, c) = self.tilt_deg.to_radians().sin_cos();
        let axis = Vec3::new(s, 0.0, c);
        // L's direction in the body depends on the tilt only, so the box starts in the same
        // attitude at any spin, 0 included.
        let l_body = (body.inertia * axis).normalize();
        body.orientation = Quat::from_rotation_arc(l_body, throw_l_direction());
        body.omega_body = self.spin * axis;
        body.position = THROW_START;
        body.velocity = THROW_VELOCITY - 0.5 * GRAVITY * (SIM_DT / THROW_SUBSTEPS as f32);
        body
    }

    /// The centre of mass on the parabola at `time_sec`.
    pub fn parabola(time_sec: f32) -> Vec3 {
        THROW_START + THROW_VELOCITY * time_sec + 0.5 * GRAVITY * time_sec * time_sec
    }

    fn restart(&mut self) {
        self.body = self.first();
        self.l_world = self.body.angular_momentum();
        self.steps_done = 0;
        self.time_sec = 0.0;
        self.history.clear();
        self.omegas.clear();
        self.record();
    }

    fn record(&mut self) {
        let b = &self.body;
        let (omega, l) = (b.omega_world(), b.angular_momentum());
        let rotational = 0.5 * b.omega_body.dot(b.inertia * b.omega_body);
        self.history.push([
            self.steps_done as f32 * SIM_DT,
            omega.length(),
            l.length(),
            angle_deg(omega, l),
            rotational,
        ]);
        self.omegas.push(omega);
    }

    /// The plots' rows: `[t (s), |ω| over its value at the throw, |L| over its value at the
    /// throw, angle between ω and L (°)]`, one per step so far (the sizes as shares, so the two
    /// fit one axis: |L| stays at 1 while |ω| moves).
    pub fn plot_rows(&self) -> Vec<[f32; 4]> {
        let Some(first) = self.history.first() else {
            return Vec::new();
        };
        let share = |x: f32, x0: f32| if x0 > 0.0 { x / x0 } else { 1.0 };
        self.history
            .iter()
            .map(|r| [r[0], share(r[1], first[1]), share(r[2], first[2]), r[3]])
            .collect()
    }

    /// Steps the throw to `time_sec` (0 to 60 s; past [`ThrowFigure::duration_sec`] the box
    /// holds where the flight ends); an earlier time starts again.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        let target = steps_to(time_sec)?.min(self.flight_steps());
        if target < self.steps_done {
            self.restart();
        }
        self.time_sec = time_sec;
        let dt = SIM_DT / THROW_SUBSTEPS as f32;
        let l = self.l_world;
        while self.steps_done < target {
            for _ in 0..THROW_SUBSTEPS {
                let b = &mut self.body;
                b.step(
                    dt,
                    GRAVITY,
                    AngularStep::Momentum,
                    OrientationStep::Exponential,
                );
                // ω read off the L of the throw, not the L read back from the body: the
                // rounding of that round trip adds up over the flight's substeps.
                b.omega_body = (b.orientation.normalize().inverse() * l) / b.inertia;
            }
            self.steps_done += 1;
            self.record();
        }
        Ok(())
    }

    /// One row per step so far: `[t (s), |ω| (rad/s), |L| (kg m²/s), angle between ω and L
    /// (degrees; 0 without spin), rotational energy ½ ω · I ω (J)]`.
    pub fn samples(&self) -> &[[f32; 5]] {
        &self.history
    }

    /// The box now.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }

    /// How far ω's drawn tip gets from L's axis over the flight (m, on the plane across L at
    /// [`THROW_ARROW_M`]). In the body, `L` keeps its length and `2E = Σ Lᵢ²/Iᵢ`; with
    /// `uᵢ = Lᵢ²` both are linear in u, and so is `|ω|² = Σ uᵢ/Iᵢ²`: its largest value lies at an
    /// end of that segment of u, where one `uₖ` is 0. ω's part along L is `2E/|L|` throughout.
    pub fn omega_tip_reach(&self) -> f32 {
        let b = self.first();
        let (m, u) = (b.inertia, (b.inertia * b.omega_body).powf(2.0));
        let (l2, e2) = (u.element_sum(), (u / m).element_sum());
        let mut w2 = (u / (m * m)).element_sum();
        for k in 0..3 {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            let ui = (e2 - l2 / m[j]) / (1.0 / m[i] - 1.0 / m[j]);
            if (0.0..=l2).contains(&ui) {
                w2 = w2.max(ui / (m[i] * m[i]) + (l2 - ui) / (m[j] * m[j]));
            }
        }
        let along = e2 / l2.sqrt();
        if along > 0.0 {
            THROW_ARROW_M * (w2 - along * along).max(0.0).sqrt() / along
        } else {
            0.0
        }
    }

    /// ω in the world at every step so far (rad/s).
    pub fn omegas(&self) -> &[Vec3] {
        &self.omegas
    }

    /// Draws the box, the parabola of its centre (dashed), `L` (purple, fixed) and ω (teal) from
    /// the centre of mass, and the trail of ω's tip; returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        frame.grid(16, 0.25);
        let t_end = self.duration_sec();
        let apex = Self::parabola(0.5 * t_end);
        // The flight only, not the floor: the parabola with round each centre the box (its half
        // diagonal), L's tip, and ω's trail (its reach round L's axis on the plane across L).
        let l_dir = throw_l_direction();
        let (d, r) = (THROW_HALF.length(), self.omega_tip_reach());
        let (c, l_off) = (THROW_ARROW_M * l_dir, THROW_L_M * l_dir);
        let (off_lo, off_hi) = (
            (c - r).min(l_off).min(Vec3::splat(-d)),
            (c + r).max(l_off).max(Vec3::splat(d)),
        );
        frame.keep_box_in_view(
            THROW_START.min(Self::parabola(t_end)) + off_lo,
            THROW_START.max(Self::parabola(t_end)).max(apex) + off_hi,
        );
        let path: Vec<Vec3> = (0..=48)
            .map(|k| Self::parabola(t_end * k as f32 / 48.0))
            .collect();
        frame.stroke(&path, palette::GREY, StrokeStyle::dashed(2.0, 0.08, 0.06));
        let b = &self.body;
        let at = b.position;
        let model = Mat4::from_translation(at)
            * Mat4::from_mat3(b.rotation())
            * Mat4::from_scale(THROW_HALF);
        frame.mesh(MeshId::CUBE, model, palette::ORANGE);
        let lowest = corners(b, THROW_HALF)
            .into_iter()
            .fold(at, |low, c| if c.y < low.y { c } else { low });
        frame.contact_shadow(Vec3::new(at.x, lowest.y, at.z), THROW_HALF.x);
        frame.marker(at, DOT_PX, palette::DARK);
        let t = self.time_sec;
        let l = b.angular_momentum();
        let omega = b.omega_world();
        let along = self.omegas[0].dot(l_dir);
        if self.spin == 0.0 || along <= 0.0 {
            return format!(
                "t = {t:.2} s. No spin: ω and L are zero, and the box flies its parabola \
                 without turning."
            );
        }
        let l_tip = at + THROW_L_M * l_dir;
        frame.arrow(at, l_tip, palette::PURPLE, 0.08);
        // L and ω wider than other arrows (up to their heads): they are what the figure shows,
        // often a few degrees apart on screen.
        frame.wide_line(at, l_tip - 0.08 * l_dir, palette::PURPLE, THROW_SHAFT_PX);
        // ω at the scale that puts its tip on the plane across L at THROW_ARROW_M.
        let scale = THROW_ARROW_M / along;
        let trail: Vec<Vec3> = self.omegas.iter().map(|w| at + scale * *w).collect();
        let light = palette::TEAL.lerp(Vec3::ONE, 0.45);
        frame.wide_polyline(&trail, light, 3.0);
        let w_tip = at + scale * omega;
        frame.arrow(at, w_tip, palette::TEAL, 0.08);
        let w_head = (0.4 * (w_tip - at).length()).min(0.08);
        frame.wide_line(at, w_tip - w_head * (w_tip - at).normalize_or_zero(), palette::TEAL, THROW_SHAFT_PX);
        self.label_tips(frame, l_tip, w_tip);
        // From above, nearly along L: L's tip stands still while ω's runs round it.
        frame.inset(
            InsetView::Top,
            "from above",
            (at + c - r).min(at - 0.3),
            (at + c + r).max(l_tip),
        );
        let row = self.history.last().copied().unwrap_or([0.0; 5]);
        let turned = angle_deg(omega, self.omegas[0]);
        let l0 = self.history[0][2];
        format!(
            "t = {t:.2} s. L stays fixed in the world: |L| = {} kg m²/s ({} at the throw), its \
             direction unchanged. ω moves: |ω| = {:.2} rad/s, {:.1}° from L, {:.1}° from where it \
             started; its tip stays on the plane across L (ω · L = 2 E_rot = {} J).",
            format_number(l.length()),
            format_number(l0),
            row[1],
            row[3],
            turned,
            format_number(omega.dot(l)),
        )
    }
}

impl ThrowFigure {
    /// Names L and ω at their tips, which can lie close on screen: each on the side of its tip
    /// away from the other's (on screen, for the last frame's view), else the first side round
    /// its tip that covers no line, dot or the other's name. The names are spelt out: a lone
    /// letter reads as a speck beside an arrow head.
    fn label_tips(&self, frame: &mut Frame, l_tip: Vec3, w_tip: Vec3) {
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // +1: ω's tip lies right of L's on screen (from the page's default view, before the
        // first frame is drawn).
        let apart = view
            .and_then(|(view_proj, size)| {
                let l = project_to_canvas(view_proj, size, l_tip)?;
                let w = project_to_canvas(view_proj, size, w_tip)?;
                Some(if w.x >= l.x { 1.0 } else { -1.0 })
            })
            .unwrap_or(1.0);
        // Sideways away from the other first, then up and down that side, then over the top,
        // then the other side.
        let sides = |x: f32| {
            [
                (x, 0.0),
                (x, -1.0),
                (x, 1.0),
                (0.0, -1.0),
                (0.0, 1.0),
                (-x, -1.0),
                (-x, 1.0),
                (-x, 0.0),
            ]
            .map(|(x, y)| Vec2::new(x, y))
        };
        let names = [
            (l_tip, -apart, "L (angular momentum)", palette::PURPLE, 1),
            (w_tip, apart, "ω (angular velocity)", palette::TEAL, 0),
        ];
        for (tip, x, text, color, priority) in names {
            // Every side just off the tip, then further out: the trail circles L's tip and the
            // path passes the arrows.
            let candidates = [0.0, 16.0, 32.0].into_iter().flat_map(|out_px| {
                sides(x).map(|side| {
                    let clear_px = TIP_PX + 2.0 * out_px;
                    Label::off_dot(tip, clear_px, side, text.into(), color, priority)
                })
            });
            frame.first_clear_label(view, candidates);
        }
    }
}

/// The width of L's and ω's shafts in Figure 1, CSS pixels.
const THROW_SHAFT_PX: f32 = 4.5;

/// How wide an arrow's head is taken to be on screen, CSS pixels, for the labels at the tips.
const TIP_PX: f32 = 10.0;

/// The stack figure's name of its tracked body sits this far above the body's highest corner,
/// taken as a dot this wide (CSS pixels): the top face seen from above rises about 10 px above
/// that corner's height at the page's camera.
const NAME_CLEAR_PX: f32 = 24.0;

/// The angle between two vectors in degrees; 0 when either is (nearly) zero.
fn angle_deg(a: Vec3, b: Vec3) -> f32 {
    let d = (a.length() * b.length()).max(0.0);
    if d < 1e-12 {
        return 0.0;
    }
    (a.dot(b) / d).clamp(-1.0, 1.0).acos().to_degrees()
}

/// The dropped box's half-extents (m), 1 kg: it lies on its largest face (x–z) when level.
pub const DROP_HALF: Vec3 = Vec3::new(0.3, 0.1, 0.2);
/// The dropped box's turn about the vertical before it is tilted (degrees): with it, a tilt about
/// the world z axis lowers one corner below all the others.
pub const DROP_YAW_DEG: f32 = 25.0;
/// The impulse figure's timeline (s).
pub const DROP_DURATION_SEC: f32 = 2.0;
/// Corners within this height of the lowest one touch together (m): the impulse acts at their
/// mean (a level box lands on the middle of its face).
pub const TIE_M: f32 = 1e-4;
/// Drawn lengths: metres per m/s (v, and the impulse as the velocity change `j / m` it gives)
/// and per rad/s (ω).
pub const VELOCITY_SCALE: f32 = 0.1;
pub const OMEGA_SCALE: f32 = 0.05;
/// How far to the side of the centre on screen the drop figure's ω arrows start, metres.
pub const OMEGA_SIDE_M: f32 = 0.4;
/// How far either side of the centre on screen the drop figure's v arrows start when the box
/// bounces back the way it came (v after against v before), metres: from the centre itself the
/// two would lie on one line, after over before.
pub const V_SIDE_M: f32 = 0.08;
/// Room the drop figure keeps in view past each arrow's outer end for its name, metres.
pub const NAME_ROOM_M: f32 = 0.2;
/// The impulse's arrow's shortest length, metres.
pub const IMPULSE_MIN_M: f32 = 0.3;
/// Halvings of a step in the search for the moment of contact.
const BISECTIONS: usize = 16;
/// Substeps of the contact solver per [`SIM_DT`] after the first impact.
pub const AFTER_SUBSTEPS: usize = 10;

/// The first impact of the dropped box: what the page reports.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact {
    /// When (s, between two steps: the moment of contact found by bisection).
    pub time_sec: f32,
    /// The contact point (world) and the centre of mass then.
    pub point: Vec3,
    pub centre: Vec3,
    /// The impulse's size (N s); it acts along the ground's normal +y.
    pub j: f32,
    pub velocity_before: Vec3,
    pub velocity_after: Vec3,
    /// Angular velocity in the world (rad/s).
    pub omega_before: Vec3,
    pub omega_after: Vec3,
    /// The contact point's velocity along the normal (m/s): negative approaching.
    pub normal_before: f32,
    pub normal_after: f32,
    /// Kinetic energy (J).
    pub energy_before: f32,
    pub energy_after: f32,
    /// The box's attitude then.
    pub orientation: Quat,
}

/// Figure 4: a box dropped tilted, so that one corner meets the ground first, and the one impulse
/// that resolves the impact ([`crate::rigid_body::normal_impulse`], frictionless: it acts along
/// the ground's normal only). The box falls without spin; at the moment of contact (found by
/// bisection within the step, so the box never sinks into the ground) the corner gets `j n`,
/// which sets the corner's normal velocity to `−e` times what it was, and gives the box the spin
/// `I⁻¹ (r × j n)`; [`ImpulseFigure::impact`] reports it. Then the box flies on under the
/// contact solver of [`crate::rigid_body::contact`] (frictionless, the same `e`,
/// [`AFTER_SUBSTEPS`] substeps a step) until the timeline's end ([`DROP_DURATION_SEC`]): one
/// impulse at a time cannot bring a box to rest on several corners (it rattles between them),
/// the sequential impulses of the stack figure can. No force ever pushes the box sideways, so
/// its centre of mass moves only up and down.
#[derive(Clone, Debug)]
pub struct ImpulseFigure {
    tilt_deg: f32,
    restitution: f32,
    height_m: f32,
    /// With "use my exercise", the impact's inverse inertia and impulse come from the student's
    /// 14.3 and 14.4.
    use_exercise: bool,
    runner: Runner,
    /// What the student's 14.3 and 14.4 gave at the impact (comparisons or failures).
    exercise_note: String,
    body: RigidBody,
    steps_done: usize,
    first_impact: Option<Impact>,
    /// The contact solver that takes the box over after the first impact.
    after: Option<World>,
    /// When the contact solver's step failed (the figure stops there).
    stopped: Option<f32>,
    /// Per step: `[t, centre height, lowest point's normal velocity, kinetic energy]`.
    history: Vec<[f32; 4]>,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the names of the
    /// arrows take the sides of their heads that keep them off the lines and the boxes.
    view: Option<(OrbitCamera, Vec2)>,
}

impl Default for ImpulseFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl ImpulseFigure {
    /// Tilted 20°, restitution 0.5, dropped from 1 m.
    pub fn new() -> Self {
        let mut f = Self {
            tilt_deg: 20.0,
            restitution: 0.5,
            height_m: 1.0,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            exercise_note: String::new(),
            body: RigidBody::new(1.0, box_moments(DROP_HALF)).expect("a box's moments"),
            steps_done: 0,
            first_impact: None,
            after: None,
            stopped: None,
            history: Vec::new(),
            view: None,
        };
        f.restart();
        f
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the names of the arrows are placed for.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// The tilt about the world z axis (degrees, 0 to 45), the coefficient of restitution (0 to
    /// 1) and the height of the lowest corner at release (m, 0.2 to 2); the drop starts again.
    pub fn set_drop(
        &mut self,
        tilt_deg: f32,
        restitution: f32,
        height_m: f32,
    ) -> Result<(), String> {
        let tilt_deg = in_range("tilt", tilt_deg, 0.0, 45.0)?;
        let restitution = in_range("restitution", restitution, 0.0, 1.0)?;
        let height_m = in_range("height", height_m, 0.2, 2.0)?;
        self.tilt_deg = tilt_deg;
        self.restitution = restitution;
        self.height_m = height_m;
        self.restart();
        Ok(())
    }

    /// The timeline's length (s).
    pub fn duration_sec(&self) -> f32 {
        DROP_DURATION_SEC
    }

    /// How the page runs the student's code (see [`crate::exercises::run`]).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.restart();
    }

    /// Takes the impact's world inverse inertia from the student's 14.3 and its impulse from
    /// the student's 14.4 (each the reference where it fails); the drop starts again.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.restart();
    }

    /// The impulse of the first impact and the world inverse inertia it used: the reference's,
    /// or with "use my exercise" the student's where they answer, with the note to show.
    fn impact_impulse(&self, b: &RigidBody, v: Vec3, r: Vec3) -> (f32, String) {
        let reference_inv = b.world_inverse_inertia();
        let e = self.restitution;
        let reference_j = |inv| normal_impulse(v, Vec3::Y, r, 1.0 / b.mass, inv, e);
        if !self.use_exercise {
            return (reference_j(reference_inv), String::new());
        }
        let at = "the impact";
        let mut notes = Vec::new();
        let inv = match run::world_inverse_inertia(self.runner, b.orientation, b.inertia) {
            Err(f) => {
                notes.push(failure_note(
                    "exercise 14.3 world_inverse_inertia",
                    FILE,
                    &f,
                ));
                reference_inv
            }
            Ok(mine) => {
                let (same, note) = compare_note(
                    "world_inverse_inertia",
                    at,
                    &mine.to_cols_array(),
                    &reference_inv.to_cols_array(),
                    1e-3 * reference_inv
                        .abs()
                        .to_cols_array()
                        .into_iter()
                        .fold(0.0, f32::max),
                );
                notes.push(note);
                if mine.is_finite() {
                    mine
                } else {
                    debug_assert!(!same);
                    reference_inv
                }
            }
        };
        let j = match run::normal_impulse(self.runner, v, Vec3::Y, r, 1.0 / b.mass, inv, e) {
            Err(f) => {
                notes.push(failure_note("exercise 14.4 normal_impulse", FILE, &f));
                reference_j(inv)
            }
            Ok(mine) => {
                let reference = reference_j(inv);
                let (_, mut note) = compare_note(
                    "normal_impulse",
                    "the impact (with the inverse inertia above)",
                    &[mine],
                    &[reference],
                    1e-3 * (1.0 + reference.abs()),
                );
                let usable = mine.is_finite() && mine >= 0.0;
                if !usable {
                    note += &format!(
                        " An impulse of {} N s cannot be applied: the figure uses the reference.",
                        format_number(mine)
                    );
                }
                notes.push(note);
                if usable {
                    mine
                } else {
                    reference
                }
            }
        };
        // One line an exercise (the page keeps the note's line breaks).
        (j, notes.join("\n"))
    }

    /// The box at release: turned by [`DROP_YAW_DEG`] about the vertical, then tilted about z,
    /// its lowest corner `height_m` above the ground, at rest.
    pub fn first(&self) -> RigidBody {
        let mut body = RigidBody::new(1.0, box_moments(DROP_HALF)).expect("a box's moments");
        body.orientation = Quat::from_rotation_z(-self.tilt_deg.to_radians())
            * Quat::from_rotation_y(DROP_YAW_DEG.to_radians());
        let (_, low) = touching(&body);
        body.position.y = self.height_m - low;
        body
    }

    fn restart(&mut self) {
        self.body = self.first();
        self.steps_done = 0;
        self.first_impact = None;
        self.after = None;
        self.stopped = None;
        self.exercise_note.clear();
        self.history.clear();
        self.record();
    }

    fn record(&mut self) {
        let b = &self.body;
        // The lowest point until the first hit, then the body's point that hit, wherever it
        // goes: the plot shows that point's velocity jump to −e times itself.
        let point = match &self.first_impact {
            Some(hit) => {
                let local = hit.orientation.normalize().inverse() * (hit.point - hit.centre);
                b.position + b.orientation.normalize() * local
            }
            None => touching(b).0,
        };
        self.history.push([
            self.steps_done as f32 * SIM_DT,
            b.position.y,
            b.point_velocity(point).y,
            b.kinetic_energy(),
        ]);
    }

    /// One step of [`SIM_DT`]: before the first impact, free flight up to the moment of
    /// contact and the impulse there; after it, the contact solver's substeps.
    fn step(&mut self) {
        let mut left = SIM_DT;
        if self.after.is_none() {
            let mut trial = self.body;
            fly_free(&mut trial, left);
            if touching(&trial).1 >= 0.0 {
                self.body = trial;
                return;
            }
            // The largest share of the step that keeps every corner above the ground.
            let (mut lo, mut hi) = (0.0f32, 1.0f32);
            for _ in 0..BISECTIONS {
                let mid = 0.5 * (lo + hi);
                let mut b = self.body;
                fly_free(&mut b, mid * left);
                if touching(&b).1 >= 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            fly_free(&mut self.body, lo * left);
            left -= lo * left;
            let (point, _) = touching(&self.body);
            let v = self.body.point_velocity(point);
            let r = point - self.body.position;
            let (j, note) = self.impact_impulse(&self.body, v, r);
            self.exercise_note = note;
            let b = &mut self.body;
            let before = *b;
            b.apply_impulse(j * Vec3::Y, point);
            self.first_impact = Some(Impact {
                time_sec: (self.steps_done as f32 + lo) * SIM_DT,
                point,
                centre: before.position,
                j,
                velocity_before: before.velocity,
                velocity_after: b.velocity,
                omega_before: before.omega_world(),
                omega_after: b.omega_world(),
                normal_before: v.y,
                normal_after: b.point_velocity(point).y,
                energy_before: before.kinetic_energy(),
                energy_after: b.kinetic_energy(),
                orientation: before.orientation,
            });
            // The moment of the hit, twice: the plot jumps there from the approach to the
            // bounce.
            if let Some(hit) = self.first_impact {
                for (normal, energy) in [
                    (hit.normal_before, hit.energy_before),
                    (hit.normal_after, hit.energy_after),
                ] {
                    self.history
                        .push([hit.time_sec, hit.centre.y, normal, energy]);
                }
            }
            let mut world = World::default();
            world.restitution = self.restitution;
            world.friction = 0.0;
            world.broad_phase = BroadPhase::AllPairs;
            if world.add(*b, Shape::Cuboid { half: DROP_HALF }).is_err() {
                self.stopped = Some(self.steps_done as f32 * SIM_DT);
                return;
            }
            self.after = Some(world);
        }
        if self.stopped.is_some() {
            return;
        }
        let Some(world) = self.after.as_mut() else {
            return;
        };
        let n = (left * AFTER_SUBSTEPS as f32 / SIM_DT).ceil().max(1.0);
        for _ in 0..n as usize {
            if world.step(left / n).is_err() {
                self.stopped = Some(self.steps_done as f32 * SIM_DT);
                break;
            }
        }
        self.body = world.bodies[0].0;
    }

    /// Steps the drop to `time_sec` (0 to 60 s; past [`DROP_DURATION_SEC`] it holds the end); an
    /// earlier time starts again.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        let end = (DROP_DURATION_SEC / SIM_DT + 1e-3).floor() as usize;
        let target = steps_to(time_sec)?.min(end);
        if target < self.steps_done {
            self.restart();
        }
        while self.steps_done < target {
            self.step();
            self.steps_done += 1;
            self.record();
        }
        Ok(())
    }

    /// One row per step so far, and two at the moment of the first hit (before and after the
    /// impulse): `[t (s), height of the centre of mass (m), normal velocity (m/s) of the lowest
    /// point until the hit (the lowest corner, or the mean of those level with it) and of the
    /// point that hit from then on, kinetic energy (J)]`.
    pub fn samples(&self) -> &[[f32; 4]] {
        &self.history
    }

    /// The first impact so far: its time (s) and the impulse's size `j` (N s).
    pub fn impact(&self) -> Option<(f32, f32)> {
        self.first_impact.map(|i| (i.time_sec, i.j))
    }

    /// Everything about the first impact so far.
    pub fn impact_details(&self) -> Option<&Impact> {
        self.first_impact.as_ref()
    }

    /// When the contact solver failed after the impact (the figure stopped there), if it did.
    pub fn stopped(&self) -> Option<f32> {
        self.stopped
    }

    /// The box now.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }

    /// Draws the box and, from the first impact on, the box as it was then (outlined), the
    /// contact point, the impulse `j n` (red, drawn as the velocity change `j / m`, at least
    /// [`IMPULSE_MIN_M`] long), and v (blue)
    /// and ω (teal) before (faded, arriving at the centre of mass then) and after (solid, leaving
    /// it); returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        frame.grid(12, 0.25);
        let b = &self.body;
        // Until the first hit the whole fall; from then on the box near the ground and the
        // hit's arrows (their tips below), drawn larger.
        let top = match &self.first_impact {
            None => self.first().position.y.max(1.2 - DROP_HALF.length()),
            Some(hit) => hit.centre.y.max(b.position.y),
        } + DROP_HALF.length();
        frame.keep_box_in_view(Vec3::new(-0.8, 0.0, -0.6), Vec3::new(0.8, top, 0.6));
        let model = Mat4::from_translation(b.position)
            * Mat4::from_mat3(b.rotation())
            * Mat4::from_scale(DROP_HALF);
        frame.mesh(MeshId::CUBE, model, palette::ORANGE);
        let (low_point, low) = touching(b);
        frame.contact_shadow(Vec3::new(b.position.x, low, b.position.z), DROP_HALF.x);
        let e = self.restitution;
        let Some(hit) = self.first_impact else {
            frame.marker(low_point, DOT_PX, palette::DARK);
            let mut note = format!(
                "Falling: the lowest corner is {} m above the ground, moving at {} m/s. \
                 Restitution e = {}.",
                format_number(low.max(0.0)),
                format_number(b.point_velocity(low_point).y),
                format_number(e),
            );
            if self.use_exercise {
                note.push_str(" Your 14.3 and 14.4 act at the impact.");
            }
            return note;
        };
        // The box at the impact, outlined.
        let then = {
            let mut t = *b;
            t.position = hit.centre;
            t.orientation = hit.orientation;
            t
        };
        let c = corners(&then, DROP_HALF);
        for (i, k) in BOX_EDGES {
            frame.wide_line(c[i], c[k], palette::GREY, 1.5);
        }
        let faded = |c: Vec3| c.lerp(Vec3::ONE, 0.55);
        let o = hit.centre;
        frame.marker(o, DOT_PX, palette::DARK);
        // Each arrow with its name, the name always in the full colour: "before" says which
        // one it is, and faded text does not read on the grid. ω first, so that v, drawn after
        // it, shows where the two lie on one line on screen (v is straight down, ω after a
        // corner hit often points down the screen too, and reaches further).
        let arrows = [
            (
                hit.omega_before * OMEGA_SCALE,
                faded(palette::TEAL),
                palette::TEAL,
                "ω before",
            ),
            (
                hit.omega_after * OMEGA_SCALE,
                palette::TEAL,
                palette::TEAL,
                "ω after",
            ),
            (
                hit.velocity_before * VELOCITY_SCALE,
                faded(palette::BLUE),
                palette::BLUE,
                "v before",
            ),
            (
                hit.velocity_after * VELOCITY_SCALE,
                palette::BLUE,
                palette::BLUE,
                "v after",
            ),
        ];
        // The impulse pushes the box up at the corner: drawn from below the ground up to the
        // contact point (from the corner up it would be hidden inside the box).
        // The hit's arrows are drawn over everything: they start inside the box at the hit and
        // run through the box now and below the ground, which would hide most of them.
        // At least IMPULSE_MIN_M long: a corner hit needs little impulse (1.41 N s at the
        // defaults, 14 cm as a velocity change), and a shorter arrow is a stub under the
        // contact's dot with its name against the box.
        let j_tail = hit.point - Vec3::Y * (hit.j / b.mass * VELOCITY_SCALE).max(IMPULSE_MIN_M);
        frame.arrow_on_top(j_tail, hit.point, palette::RED, 0.06);
        frame.keep_in_view.push(j_tail);
        frame.marker_on_top(hit.point, 12.0, palette::DARK);
        let mut names = vec![(j_tail.lerp(hit.point, 0.5), Vec3::X, "j n", palette::RED)];
        // ω is the same at every point of the body: its arrows start OMEGA_SIDE_M to the side of
        // the centre on screen, the side ω after leans to, tied to the centre by a grey line, so
        // that they never lie along v (straight down through the centre) on screen.
        // The camera's right, level: the eye lies at (sin yaw, ·, cos yaw) from its target.
        let yaw = self.view.map_or(0.0, |(camera, _)| camera.yaw_rad);
        let right = Vec3::new(yaw.cos(), 0.0, -yaw.sin());
        let side = right * OMEGA_SIDE_M * hit.omega_after.dot(right).signum();
        if ties_omega_arrows(hit.omega_before, hit.omega_after) {
            frame.wide_line_on_top(o, o + side, palette::GREY, 1.5);
        }
        // Before arrives at its start and after leaves it: while v after points down, as v
        // before does, the two run one after the other along one line. A box that bounces back
        // up (a level drop) sends v after back along v before's shaft: then they stand
        // V_SIDE_M either side of the centre.
        let v_side = if hit.velocity_before.dot(hit.velocity_after) < 0.0 {
            right * V_SIDE_M
        } else {
            Vec3::ZERO
        };
        for (d, color, text_color, name) in arrows {
            if d.length() > 1e-3 {
                let o = if text_color == palette::TEAL {
                    o + side
                } else if color == text_color {
                    o + v_side
                } else {
                    o - v_side
                };
                let (from, out) = if color == text_color {
                    (o, d)
                } else {
                    (o - d, -d)
                };
                frame.arrow_on_top(from, from + d, color, 0.06);
                // The outer end and NAME_ROOM_M past it: the name beside the end has room on
                // the canvas on the side away from the arrow (at the end itself the camera keeps
                // only FIT_PAD_PX, and a name there is pushed back against the canvas's edge).
                frame.keep_in_view.push(o + out + out.normalize() * NAME_ROOM_M);
                names.push((o + out, out, name, text_color));
            }
        }
        // Each name beside its arrow's outer end (the head after, the tail before; the
        // impulse's beside its shaft), on the side away from the centre first, then round it, keeping off every line, dot and name and off
        // both boxes (the box now and the box at the hit), for the last frame's view.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let solid: Vec<Vec3> = [*b, then]
            .iter()
            .flat_map(|body| {
                box_samples(
                    Mat4::from_translation(body.position)
                        * Mat4::from_mat3(body.rotation())
                        * Mat4::from_scale(DROP_HALF),
                )
            })
            .collect();
        let off_boxes = super::clear_of(view, &solid);
        for (at, d, name, color) in names {
            let toward = view
                .and_then(|(view_proj, size)| {
                    let a = project_to_canvas(view_proj, size, at - d)?;
                    Some(project_to_canvas(view_proj, size, at)? - a)
                })
                // Before the first frame: the page's camera looks along −z, y up.
                .unwrap_or(Vec2::new(d.x, -d.y));
            let candidates = Label::around_dot(at, TIP_PX, toward, name, color, 0, 6, 10.0);
            frame.first_clear_label_by(view, 2.0, candidates, &off_boxes);
        }
        // Rounding leftovers (a spin of 1e-6 rad/s after a level drop, a normal velocity and an
        // energy of 1e-15 after a drop at e = 0) read as the 0 they are.
        let clean = |x: f32| if x.abs() < 1e-4 { 0.0 } else { x };
        let v3 = |v: Vec3| {
            format!(
                "({}, {}, {})",
                format_number(clean(v.x)),
                format_number(clean(v.y)),
                format_number(clean(v.z))
            )
        };
        let stopped = match self.stopped {
            Some(t) => format!(
                " The contact solver's step failed at t = {} s (a state that is not finite): the \
                 figure stopped there.",
                format_number(t)
            ),
            None => String::new(),
        };
        // A student's 14.4 can give another impulse: the note then says what e asks for
        // instead of calling the result −e times the approach.
        let asked = -e * hit.normal_before;
        let bounce = if (hit.normal_after - asked).abs() <= 1e-3 * asked.abs().max(1e-2) {
            format!("−e times it, e = {}", format_number(e))
        } else {
            format!(
                "e = {} asks for −e times it, {} m/s: this impulse does not give that",
                format_number(e),
                format_number(asked)
            )
        };
        format!(
            "Impact at t = {} s: j = {} N s along n = +y at the contact. The contact point's \
             normal velocity {} → {} m/s ({bounce}). v {} → {} m/s; ω {} → {} rad/s \
             (|ω| = {}). Kinetic energy {} → {} J. After the impact the contact solver of the \
             stack figure takes the box over.{stopped}",
            format_number(hit.time_sec),
            format_number(hit.j),
            format_number(clean(hit.normal_before)),
            format_number(clean(hit.normal_after)),
            v3(hit.velocity_before),
            v3(hit.velocity_after),
            v3(hit.omega_before),
            v3(hit.omega_after),
            format_number(clean(hit.omega_after.length())),
            format_number(clean(hit.energy_before)),
            format_number(clean(hit.energy_after)),
        ) + &if self.use_exercise {
            format!("\n{}", self.exercise_note)
        } else {
            String::new()
        }
    }
}

/// Whether Figure 4 ties its ω arrows to the centre of mass with a grey line: when either ω
/// arrow is drawn (one longer than 1 mm at [`OMEGA_SCALE`]), whatever the signs of ω's components.
pub fn ties_omega_arrows(omega_before: Vec3, omega_after: Vec3) -> bool {
    omega_before.length().max(omega_after.length()) * OMEGA_SCALE > 1e-3
}

/// Free flight under gravity for `dt` seconds, in substeps of at most [`SIM_DT`] /
/// [`THROW_SUBSTEPS`] (a box spinning at 40 rad/s after an impact turns 0.7 rad in a whole
/// `SIM_DT`, where the first-order rotation step gains energy fast).
fn fly_free(body: &mut RigidBody, dt: f32) {
    if dt <= 0.0 {
        return;
    }
    let n = (dt * THROW_SUBSTEPS as f32 / SIM_DT).ceil().max(1.0);
    let h = dt / n;
    for _ in 0..n as usize {
        body.step(
            h,
            GRAVITY,
            AngularStep::Momentum,
            OrientationStep::Exponential,
        );
    }
}

/// The dropped box's touching point and its height: the lowest corner, or the mean of the
/// corners within [`TIE_M`] of the lowest.
fn touching(body: &RigidBody) -> (Vec3, f32) {
    let c = corners(body, DROP_HALF);
    let low = c.iter().map(|p| p.y).fold(f32::INFINITY, f32::min);
    let (sum, n) = c
        .iter()
        .filter(|p| p.y <= low + TIE_M)
        .fold((Vec3::ZERO, 0.0), |(s, n), p| (s + *p, n + 1.0));
    (sum / n, low)
}

/// What the stack figure shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StackPreset {
    /// Three boxes on the ground, one on another, each [`STACK_OFFSET_M`] further along x.
    Stack,
    /// A row of [`DOMINOES`] thin upright boxes, the first tipped by [`DOMINO_TIP_DEG`].
    Dominoes,
}

/// The stacked boxes' half-extents (m), 1 kg each.
pub const STACK_HALF: Vec3 = Vec3::new(0.25, 0.15, 0.25);
/// How far each box of the stack sits along x from the one under it (m).
pub const STACK_OFFSET_M: f32 = 0.01;
/// The dominoes' half-extents (m: 5 cm thick, 40 cm tall, 20 cm wide), 1 kg each.
pub const DOMINO_HALF: Vec3 = Vec3::new(0.025, 0.2, 0.1);
pub const DOMINOES: usize = 10;
/// How much energy (J) the contact figure lets the solver's position corrections add before it
/// calls the run exploded.
pub const STACK_ENERGY_SLACK_J: f32 = 0.2;
/// The distance between neighbouring dominoes' centres (m): less than their height, so each
/// falling one reaches the next.
pub const DOMINO_SPACING_M: f32 = 0.25;
/// The first domino's tilt towards the row at the start (degrees): it falls by itself.
pub const DOMINO_TIP_DEG: f32 = 15.0;
/// A domino counts as fallen past this tilt from upright (degrees).
pub const FALLEN_DEG: f32 = 45.0;
/// The contact solver's substeps per [`SIM_DT`] (the core's tests step at 1/120 s).
pub const STACK_SUBSTEPS: usize = 2;
/// The impulse of [`StackFigure::push`] (N s, along +x): on the top box's centre, or on the
/// first domino's top.
pub const STACK_PUSH: f32 = 2.0;
pub const DOMINO_PUSH: f32 = 0.3;
/// The most pushes a run remembers.
pub const MAX_PUSHES: usize = 64;
/// Size of a contact point's dot (CSS pixels).
pub const CONTACT_PX: f32 = 9.0;
/// The boxes' colours, in turn.
const BOX_COLORS: [Vec3; 7] = [
    palette::ORANGE,
    palette::TEAL,
    palette::PURPLE,
    palette::BLUE,
    palette::PINK,
    palette::GREEN,
    palette::BROWN,
];

/// Figure 5: a stack of three boxes, or a row of dominoes, on the contact solver of
/// [`crate::rigid_body::contact`] (sequential impulses). The reader sets the solver's passes
/// per step, friction and restitution (the run starts again) and pushes: the top box of the
/// stack gets a sideways shove, the first domino a push at its top. Pushes are recorded with the
/// frame they happened at and replayed, so the state at a time is always the same. With too few
/// passes the contacts are not resolved before the step ends and the stack creeps. A step that
/// fails ([`World::step`] returns an error: a state that is not finite), or one after which the
/// bodies hold more energy (kinetic and gravity's) than the run had plus what the pushes gave
/// and [`STACK_ENERGY_SLACK_J`], stops the figure there ([`StackFigure::exploded`]): no contact
/// may add energy, so a solver that does has blown up.
#[derive(Clone, Debug)]
pub struct StackFigure {
    preset: StackPreset,
    iterations: usize,
    friction: f32,
    restitution: f32,
    world: World,
    /// Where each body starts.
    start: Vec<Vec3>,
    steps_done: usize,
    /// The timeline's time of the last [`Self::advance_to`] (s), which the note names as the
    /// page's clock shows it; the bodies are at the last whole step at or before it.
    time_sec: f32,
    /// The frames at which pushes happened, in order.
    pushes: Vec<usize>,
    exploded: Option<f32>,
    /// Why it stopped: the step failed (false) or the solver added energy (true).
    gained_energy: bool,
    /// The most energy (J, kinetic and gravity's) the bodies may hold: the start's, what the
    /// pushes gave, and [`STACK_ENERGY_SLACK_J`].
    energy_budget: f32,
    /// The contact points at the present state (what the next step resolves).
    contact_points: Vec<Vec3>,
    /// Per step: `[t, total kinetic energy, distance the tracked body has moved]`.
    history: Vec<[f32; 3]>,
}

impl StackFigure {
    /// The figure of `preset` with the core's solver defaults: 20 passes, friction 0.5,
    /// restitution 0.
    pub fn new(preset: StackPreset) -> Self {
        let mut f = Self {
            preset,
            iterations: 20,
            friction: 0.5,
            restitution: 0.0,
            world: World::default(),
            start: Vec::new(),
            steps_done: 0,
            time_sec: 0.0,
            pushes: Vec::new(),
            exploded: None,
            gained_energy: false,
            energy_budget: 0.0,
            contact_points: Vec::new(),
            history: Vec::new(),
        };
        f.restart();
        f
    }

    /// The solver's passes over the contacts per step (a whole number, 1 to 50), the friction
    /// coefficient μ (0 to 1) and the restitution e (0 to 1); the run starts again, with the
    /// pushes made so far.
    pub fn set_solver(
        &mut self,
        iterations: f32,
        friction: f32,
        restitution: f32,
    ) -> Result<(), String> {
        let iterations = whole_number("iterations", iterations, 1, 50)?;
        let friction = in_range("friction", friction, 0.0, 1.0)?;
        let restitution = in_range("restitution", restitution, 0.0, 1.0)?;
        self.iterations = iterations;
        self.friction = friction;
        self.restitution = restitution;
        self.restart();
        Ok(())
    }

    /// The preset shown.
    pub fn preset(&self) -> StackPreset {
        self.preset
    }

    /// The timeline's length (s): 10 for the stack, 4 for the dominoes (they are all down by 2).
    pub fn duration_sec(&self) -> f32 {
        match self.preset {
            StackPreset::Stack => 10.0,
            StackPreset::Dominoes => 4.0,
        }
    }

    /// The body whose travel the samples follow: the top box, or the last domino.
    pub fn tracked(&self) -> usize {
        self.world.bodies.len() - 1
    }

    /// The bodies at the start of a run.
    fn bodies_at_start(&self) -> Vec<(RigidBody, Shape)> {
        let make = |half: Vec3, at: Vec3| {
            let mut b = RigidBody::new(1.0, box_moments(half)).expect("a box's moments");
            b.position = at;
            (b, Shape::Cuboid { half })
        };
        match self.preset {
            StackPreset::Stack => (0..3)
                .map(|k| {
                    let at = Vec3::new(
                        STACK_OFFSET_M * k as f32,
                        STACK_HALF.y * (2 * k + 1) as f32,
                        0.0,
                    );
                    make(STACK_HALF, at)
                })
                .collect(),
            StackPreset::Dominoes => (0..DOMINOES)
                .map(|k| {
                    let x = DOMINO_SPACING_M * (k as f32 - 0.5 * (DOMINOES - 1) as f32);
                    let (mut b, s) = make(DOMINO_HALF, Vec3::new(x, DOMINO_HALF.y, 0.0));
                    if k == 0 {
                        // Tipped towards the row about its front bottom edge, which stays on
                        // the ground.
                        b.orientation = Quat::from_rotation_z(-DOMINO_TIP_DEG.to_radians());
                        let low = corners(&b, DOMINO_HALF)
                            .iter()
                            .map(|c| c.y)
                            .fold(f32::INFINITY, f32::min);
                        b.position.y -= low;
                    }
                    (b, s)
                })
                .collect(),
        }
    }

    fn restart(&mut self) {
        let mut world = World::default();
        world.iterations = self.iterations;
        world.friction = self.friction;
        world.restitution = self.restitution;
        world.broad_phase = BroadPhase::AllPairs;
        for (b, s) in self.bodies_at_start() {
            world.add(b, s).expect("the preset's bodies are valid");
        }
        self.start = world.bodies.iter().map(|(b, _)| b.position).collect();
        self.world = world;
        self.steps_done = 0;
        self.time_sec = 0.0;
        self.exploded = None;
        self.gained_energy = false;
        self.energy_budget = self.total_energy() + STACK_ENERGY_SLACK_J;
        self.history.clear();
        self.record();
        self.apply_pushes_at(0);
        self.find_contacts();
    }

    fn record(&mut self) {
        let k = self.tracked();
        self.history.push([
            self.steps_done as f32 * SIM_DT,
            self.world.kinetic_energy(),
            self.world.bodies[k].0.position.distance(self.start[k]),
        ]);
    }

    fn find_contacts(&mut self) {
        self.contact_points = self.world.contacts().iter().map(|c| c.point).collect();
    }

    /// The push's impulse on the world as it is now.
    /// The bodies' kinetic energy plus gravity's (`m g y`, from the ground), in J.
    fn total_energy(&self) -> f32 {
        let g = -self.world.gravity.y;
        self.world
            .bodies
            .iter()
            .map(|(b, _)| b.kinetic_energy() + b.mass * g * b.position.y)
            .sum()
    }

    fn apply_push(&mut self) {
        let before = self.total_energy();
        self.shove();
        self.energy_budget += self.total_energy() - before;
    }

    fn shove(&mut self) {
        let (b, _) = &mut self.world.bodies[match self.preset {
            StackPreset::Stack => 2,
            StackPreset::Dominoes => 0,
        }];
        match self.preset {
            StackPreset::Stack => b.apply_impulse(STACK_PUSH * Vec3::X, b.position),
            StackPreset::Dominoes => {
                let top = b.position + b.orientation * Vec3::new(0.0, DOMINO_HALF.y, 0.0);
                b.apply_impulse(DOMINO_PUSH * Vec3::X, top);
            }
        }
    }

    fn apply_pushes_at(&mut self, step: usize) {
        let n = self.pushes.iter().filter(|&&s| s == step).count();
        for _ in 0..n {
            self.apply_push();
        }
    }

    /// Pushes now: the top box of the stack sideways ([`STACK_PUSH`] along +x through its
    /// centre), or the first domino at its top ([`DOMINO_PUSH`]). Remembered for the replays; an
    /// error past [`MAX_PUSHES`] or after an explosion.
    pub fn push(&mut self) -> Result<(), String> {
        if self.pushes.len() >= MAX_PUSHES {
            return Err(format!(
                "a run remembers at most {MAX_PUSHES} pushes: press reset"
            ));
        }
        if self.exploded.is_some() {
            return Err("the run has stopped (the step failed): press reset".into());
        }
        self.pushes.push(self.steps_done);
        self.apply_push();
        self.find_contacts();
        Ok(())
    }

    /// Forgets the pushes and starts again (the solver's settings stay).
    pub fn reset(&mut self) {
        self.pushes.clear();
        self.restart();
    }

    /// Steps to `time_sec` (0 to 60 s; past [`StackFigure::duration_sec`] it holds the end); an
    /// earlier time starts again.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        let end = (self.duration_sec() / SIM_DT + 1e-3).floor() as usize;
        let target = steps_to(time_sec)?.min(end);
        if target < self.steps_done {
            self.restart();
        }
        self.time_sec = time_sec;
        let moved = self.steps_done < target;
        while self.steps_done < target {
            if self.exploded.is_none() {
                for _ in 0..STACK_SUBSTEPS {
                    if self.world.step(SIM_DT / STACK_SUBSTEPS as f32).is_err() {
                        self.exploded = Some(self.steps_done as f32 * SIM_DT);
                        break;
                    }
                }
                if self.exploded.is_none() && self.total_energy() > self.energy_budget {
                    self.exploded = Some((self.steps_done + 1) as f32 * SIM_DT);
                    self.gained_energy = true;
                }
            }
            self.steps_done += 1;
            // Recorded before the pushes of this frame, as when the push happened live.
            if self.exploded.is_none() {
                self.record();
                self.apply_pushes_at(self.steps_done);
            }
        }
        if moved {
            self.find_contacts();
        }
        Ok(())
    }

    /// One row per step so far (none after an explosion): `[t (s), total kinetic energy (J),
    /// how far the top box (stack) or the last domino has moved from where it started (m)]`.
    pub fn samples(&self) -> &[[f32; 3]] {
        &self.history
    }

    /// When the solver's step failed (s), if it did; the figure stops there.
    pub fn exploded(&self) -> Option<f32> {
        self.exploded
    }

    /// The bodies now.
    pub fn bodies(&self) -> &[(RigidBody, Shape)] {
        &self.world.bodies
    }

    /// The contact points of the present state (world), which the next step resolves.
    pub fn contact_points(&self) -> &[Vec3] {
        &self.contact_points
    }

    /// Body `k`'s tilt: the angle of its own y axis from the vertical (degrees).
    pub fn tilt_deg(&self, k: usize) -> f32 {
        self.world.bodies.get(k).map_or(0.0, |(b, _)| {
            let up = b.orientation.normalize() * Vec3::Y;
            up.y.clamp(-1.0, 1.0).acos().to_degrees()
        })
    }

    /// Dominoes tilted past [`FALLEN_DEG`] (for the stack: boxes, likewise).
    pub fn fallen(&self) -> usize {
        (0..self.world.bodies.len())
            .filter(|&k| self.tilt_deg(k) > FALLEN_DEG)
            .count()
    }

    /// Draws the boxes in turns of the palette's colours, the present contact points as red
    /// dots and a label on the tracked body; returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        frame.grid(16, 0.25);
        let (lo, hi) = match self.preset {
            StackPreset::Stack => (Vec3::new(-1.0, 0.0, -0.6), Vec3::new(1.0, 1.2, 0.6)),
            StackPreset::Dominoes => (Vec3::new(-1.5, 0.0, -0.5), Vec3::new(1.7, 0.7, 0.5)),
        };
        frame.keep_box_in_view(lo, hi);
        for (k, (b, shape)) in self.world.bodies.iter().enumerate() {
            let half = match shape {
                Shape::Cuboid { half } => *half,
                Shape::Sphere { radius } => Vec3::splat(*radius),
            };
            let model = Mat4::from_translation(b.position)
                * Mat4::from_mat3(b.rotation())
                * Mat4::from_scale(half);
            frame.mesh(MeshId::CUBE, model, BOX_COLORS[k % BOX_COLORS.len()]);
        }
        for p in &self.contact_points {
            frame.marker_on_top(*p, CONTACT_PX, palette::RED);
        }
        let k = self.tracked();
        let (b, shape) = &self.world.bodies[k];
        let name = match self.preset {
            StackPreset::Stack => "top box",
            StackPreset::Dominoes => "last domino",
        };
        // Over the body's middle, at its highest corner's height, a fixed few pixels up at any
        // zoom (NAME_CLEAR_PX: the top face seen from above rises above that point).
        let half = match shape {
            Shape::Cuboid { half } => *half,
            Shape::Sphere { radius } => Vec3::splat(*radius),
        };
        let top = corners(b, half)
            .into_iter()
            .fold(f32::MIN, |top, c| top.max(c.y));
        let anchor = Vec3::new(b.position.x, top, b.position.z);
        frame.label_off_dot(
            anchor,
            NAME_CLEAR_PX,
            Vec2::new(0.0, -1.0),
            name,
            palette::DARK,
            0,
        );
        let row = self.history.last().copied().unwrap_or([0.0; 3]);
        let t = self.time_sec;
        let solver = format!(
            "{} solver pass{} per step ({} steps a frame), friction μ = {}, restitution e = {}.",
            self.iterations,
            if self.iterations == 1 { "" } else { "es" },
            STACK_SUBSTEPS,
            format_number(self.friction),
            format_number(self.restitution),
        );
        let state = match self.preset {
            StackPreset::Stack => format!(
                "The top box has moved {} cm from where it started; kinetic energy {} J; {} \
                 contact points.",
                format_number(100.0 * row[2]),
                format_number(row[1]),
                self.contact_points.len(),
            ),
            StackPreset::Dominoes => format!(
                "{} of {DOMINOES} dominoes are down (tilted past {FALLEN_DEG}°); the last one has \
                 moved {} cm; kinetic energy {} J; {} contact points.",
                self.fallen(),
                format_number(100.0 * row[2]),
                format_number(row[1]),
                self.contact_points.len(),
            ),
        };
        // A push shows from the step after it (the plots record each step before its pushes).
        let done = self.pushes.iter().filter(|&&s| s < self.steps_done).count();
        let mut pushes = match done {
            0 => String::new(),
            1 => " Pushed once.".to_string(),
            n => format!(" Pushed {n} times."),
        };
        if let Some(s) = self.pushes.iter().filter(|&&s| s >= self.steps_done).min() {
            pushes += &format!(" A push comes at t = {:.2} s.", *s as f32 * SIM_DT);
        }
        let exploded = match self.exploded {
            Some(at) if self.gained_energy => format!(
                " At t = {} s the bodies held more energy than the run ever had: the solver \
                 added some (a restitution near 1 given to several contacts of a body at once, \
                 or, without friction, boxes sliding into each other and pushed out hard). The \
                 figure stopped there: press reset, lower the restitution or raise the \
                 friction.",
                format_number(at)
            ),
            Some(at) => format!(
                " The solver's step failed at t = {} s (a body's state left the finite \
                 numbers): the figure stopped there. Raise the passes or press reset.",
                format_number(at)
            ),
            None => String::new(),
        };
        format!("t = {t:.2} s. {solver} {state}{pushes}{exploded}")
    }
}

/// The drift figure's boxes: how each steps its orientation, and its name.
/// The names are the plot's (the caption names the steps in full, in the boxes' colours): three
/// long names do not fit round three boxes on screen.
pub const DRIFT_STEPS: [(OrientationStep, &str); 3] = [
    (OrientationStep::Additive, "normalised"),
    (OrientationStep::AdditiveUnnormalised, "unnormalised"),
    (OrientationStep::Exponential, "exponential"),
];
/// The drift figure's boxes' half-extents (m), 1 kg; they spin about their shortest axis z (the
/// largest moment: a stable spin), tipped by [`DRIFT_TIP_RAD`] from the world's z (the viewer's
/// direction).
pub const DRIFT_HALF: Vec3 = Vec3::new(0.3, 0.15, 0.075);
/// How far the boxes are tipped about x before they spin about their own z (rad).
pub const DRIFT_TIP_RAD: f32 = 0.6;
/// The drift figure's timeline (s).
pub const DRIFT_DURATION_SEC: f32 = 10.0;
/// A box's name (`points`: its box sampled, [`box_samples`]): for the last frame's view, the
/// first clear side round the box (above first), just off its extent on screen, keeping off
/// every box (`off_boxes`), line and name; before the first frame, `first`. In Figure 2 that is
/// centred 0.6 m over the box (the outer two would run past the canvas's sides reading
/// outwards), the middle one a row higher, since each is wider than the boxes' spacing on screen.
fn box_label(
    frame: &mut Frame,
    view: Option<(Mat4, Vec2)>,
    points: &[Vec3],
    first: Label,
    off_boxes: &dyn Fn(crate::draw::layout::Rect) -> bool,
) {
    let candidates = match view {
        Some((view_proj, size)) => {
            labels_round(points, view_proj, size, &first.text, first.color, 9, 8.0)
        }
        None => vec![first],
    };
    frame.first_clear_label_by(view, 2.0, candidates, off_boxes);
}

/// Candidates for [`Frame::first_clear_label_by`] naming a shape drawn through `points`, seen
/// through `view_proj` on a `size` canvas (CSS pixels): on each side (above first, then below,
/// right, left and the corners), anchored at the shape's outermost point that way on screen,
/// just off it and then `step_px` further out each time, `rings` places per side. Anchored at
/// the edge, a name placed just off the shape lies within the page's leader distance of its
/// anchor (a name far from its anchor gets a leader line on the page).
pub(crate) fn labels_round(
    points: &[Vec3],
    view_proj: Mat4,
    size: Vec2,
    text: &str,
    color: Vec3,
    rings: usize,
    step_px: f32,
) -> Vec<Label> {
    let n = points.len().max(1) as f32;
    let centre = points.iter().copied().sum::<Vec3>() / n;
    let on_screen: Vec<(Vec3, Vec2)> = points
        .iter()
        .filter_map(|&p| Some((p, project_to_canvas(view_proj, size, p)?)))
        .collect();
    let sides = [(0.0, -1.0), (0.0, 1.0), (1.0, 0.0), (-1.0, 0.0), (1.0, -1.0), (-1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .map(|(x, y)| Vec2::new(x, y));
    (0..rings)
        .flat_map(|k| {
            let on_screen = &on_screen;
            sides.into_iter().map(move |side| {
                let far = on_screen
                    .iter()
                    .max_by(|a, b| a.1.dot(side).total_cmp(&b.1.dot(side)))
                    .map_or(centre, |p| p.0);
                Label::off_dot(far, 2.0 + 2.0 * step_px * k as f32, side, text.into(), color, 0)
            })
        })
        .collect()
}

/// Points through a box of the cube mesh placed by `model` (5 a side, its faces and inside):
/// a name's box that holds none of them keeps off the box.
fn box_samples(model: Mat4) -> impl Iterator<Item = Vec3> {
    (0..125).map(move |i| {
        let at = |k: i32| (k % 5) as f32 * 0.5 - 1.0;
        model.transform_point3(Vec3::new(at(i), at(i / 5), at(i / 25)))
    })
}

/// How much higher the middle label of Figure 2 sits, CSS pixels: a label's height and a gap.
const DRIFT_ROW_PX: f32 = 22.0;

/// The unnormalised box is drawn while `|q|` is at most this: its matrix then stretches it by
/// at most `2|q|² − 1 = 4`.
pub const DRIFT_DRAWN_MAX_NORM: f32 = 1.581_138_8; // √2.5
/// The unnormalised box stops being stepped past this `|q|` (its numbers would overflow).
pub const DRIFT_MAX_NORM: f32 = 1e6;
/// Where the boxes stand (x, m) and their height.
const DRIFT_SPACING_M: f32 = 1.5;
const DRIFT_HEIGHT_M: f32 = 1.0;

/// Figure 2: quaternion drift. Three boxes spun at the same ω, stepped at the same `Δt` by the
/// three orientation steps of [`DRIFT_STEPS`]. The additive step `q + ½ Δt ω q = (1 + ½ Δt ω) q`
/// multiplies `|q|` by `|1 + ½ Δt ω| = √(1 + (|ω| Δt / 2)²)` every step, exactly (the norm of a
/// product of quaternions is the product of the norms): left unnormalised, `|q|` grows
/// geometrically, and the matrix built from it by the unit-quaternion formula
/// ([`RigidBody::rotation`]), `(1 − s²) E + s² R` for `q = s u` with `u` unit, stretches the box
/// by up to `2 s² − 1` and, since the spin axis is no axis of the world, skews its edges: the
/// drawn box swells, shrinks and shears as it spins.
/// Normalised, the additive step turns by `2 atan(|ω| Δt / 2)` per step instead of `|ω| Δt`, so
/// it falls behind the exponential step, which is exact for a constant ω.
#[derive(Clone, Debug)]
pub struct DriftFigure {
    spin: f32,
    step_ms: f32,
    /// With "use my exercise", the normalised box is stepped by the student's 14.2.
    use_exercise: bool,
    runner: Runner,
    /// Why the student's step stopped being used this run (it failed or left the numbers).
    exercise_failure: Option<String>,
    bodies: [RigidBody; 3],
    steps_done: usize,
    /// Set when the unnormalised box passed [`DRIFT_MAX_NORM`] and stopped.
    overflowed_at: Option<f32>,
    /// `[t, |q| of each box]`, one row per step or per frame's worth of steps.
    history: Vec<[f32; 4]>,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: each box's name
    /// takes a side of its box that keeps it off the other boxes, the outline and the names.
    view: Option<(OrbitCamera, Vec2)>,
}

impl Default for DriftFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl DriftFigure {
    /// Spun at 5 rad/s, stepped every 10 ms.
    pub fn new() -> Self {
        let body = RigidBody::new(1.0, box_moments(DRIFT_HALF)).expect("a box's moments");
        let mut f = Self {
            spin: 5.0,
            step_ms: 10.0,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            exercise_failure: None,
            bodies: [body; 3],
            steps_done: 0,
            overflowed_at: None,
            history: Vec::new(),
            view: None,
        };
        f.restart();
        f
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the boxes' names are placed for.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// The spin (rad/s, 1 to 30) and the time step (ms, 1 to 50); the run starts again.
    pub fn set_drift(&mut self, spin: f32, step_ms: f32) -> Result<(), String> {
        let spin = in_range("spin", spin, 1.0, 30.0)?;
        let step_ms = in_range("step", step_ms, 1.0, 50.0)?;
        self.spin = spin;
        self.step_ms = step_ms;
        self.restart();
        Ok(())
    }

    /// The timeline's length (s).
    pub fn duration_sec(&self) -> f32 {
        DRIFT_DURATION_SEC
    }

    /// How the page runs the student's code (see [`crate::exercises::run`]).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.restart();
    }

    /// Steps the normalised box with the student's 14.2 `orientation_step` (the reference from
    /// the first step where it fails); the run starts again.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.restart();
    }

    /// The normalised additive step of box 0: the student's while it answers, else the
    /// reference's.
    fn normalised_step(&mut self, q: Quat, omega: Vec3, dt: f32) -> Quat {
        let reference = orientation_step(q, omega, dt, OrientationStep::Additive);
        if !self.use_exercise || self.exercise_failure.is_some() {
            return reference;
        }
        match run::orientation_step(self.runner, q, omega, dt) {
            Ok(mine) if mine.is_finite() => mine,
            Ok(mine) => {
                self.exercise_failure = Some(format!(
                    "Your orientation_step returned {mine}, not a number: the figure uses the \
                     reference from step {}.",
                    self.steps_done + 1
                ));
                reference
            }
            Err(f) => {
                self.exercise_failure =
                    Some(failure_note("exercise 14.2 orientation_step", FILE, &f));
                reference
            }
        }
    }

    /// The note on the student's 14.2: its answer at the first step compared with the
    /// reference's, and why it stopped being used, if it did.
    fn exercise_note(&self) -> String {
        let (q, omega, dt) = (
            Quat::from_rotation_x(DRIFT_TIP_RAD),
            self.omega_world(),
            self.dt_sec(),
        );
        let at = format!(
            "the first step (Δt = {} ms, |ω| = {} rad/s)",
            format_number(self.step_ms),
            format_number(self.spin)
        );
        let compared = match run::orientation_step(self.runner, q, omega, dt) {
            Err(f) => failure_note("exercise 14.2 orientation_step", FILE, &f),
            Ok(mine) => {
                let reference = orientation_step(q, omega, dt, OrientationStep::Additive);
                compare_note(
                    "orientation_step",
                    &at,
                    &mine.to_array(),
                    &reference.to_array(),
                    1e-5,
                )
                .1
            }
        };
        match &self.exercise_failure {
            Some(why) if !compared.contains(why.as_str()) => format!("{compared} {why}"),
            _ => compared,
        }
    }

    /// The time step (s).
    pub fn dt_sec(&self) -> f32 {
        self.step_ms / 1000.0
    }

    /// The angular velocity every box spins with, in the world's frame (rad/s): `spin` about the
    /// box's own z axis, tipped with it.
    pub fn omega_world(&self) -> Vec3 {
        Quat::from_rotation_x(DRIFT_TIP_RAD) * Vec3::new(0.0, 0.0, self.spin)
    }

    /// What each step multiplies the additive step's `|q|` by: `√(1 + (|ω| Δt / 2)²)`.
    pub fn growth_per_step(&self) -> f32 {
        let half = 0.5 * self.spin * self.dt_sec();
        (1.0 + half * half).sqrt()
    }

    fn restart(&mut self) {
        let mut body = RigidBody::new(1.0, box_moments(DRIFT_HALF)).expect("a box's moments");
        // Tipped towards the viewer first: the spin axis is then no axis of the world, and the
        // raw matrix of a long quaternion shears the box as well as stretching it (about a world
        // axis it would only stretch it across that axis).
        body.orientation = Quat::from_rotation_x(DRIFT_TIP_RAD);
        body.omega_body = Vec3::new(0.0, 0.0, self.spin);
        self.bodies = [body; 3];
        self.steps_done = 0;
        self.overflowed_at = None;
        self.exercise_failure = None;
        self.history.clear();
        self.record();
    }

    fn record(&mut self) {
        let b = &self.bodies;
        self.history.push([
            self.steps_done as f32 * self.dt_sec(),
            b[0].orientation.length(),
            b[1].orientation.length(),
            b[2].orientation.length(),
        ]);
    }

    /// Steps the three boxes to `time_sec` (0 to 60 s; past [`DRIFT_DURATION_SEC`] they hold
    /// the end); an earlier time starts again.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        let t = in_range("time", time_sec, 0.0, MAX_SIM_TIME)?;
        let dt = self.dt_sec();
        let target = ((t.min(DRIFT_DURATION_SEC) / dt + 1e-3).floor()) as usize;
        if target < self.steps_done {
            self.restart();
        }
        // A row per step, or per frame when steps are shorter than a frame: at the first step
        // of each frame, so the rows do not depend on how the time was reached.
        let frame_of = |n: usize| (n as f32 * dt / SIM_DT + 1e-3).floor() as usize;
        let omega = self.omega_world();
        while self.steps_done < target {
            let student = self.normalised_step(self.bodies[0].orientation, omega, dt);
            for (k, (body, (how, _))) in self.bodies.iter_mut().zip(DRIFT_STEPS).enumerate() {
                if k == 1 && self.overflowed_at.is_some() {
                    continue;
                }
                if k == 0 {
                    body.orientation = student;
                    continue;
                }
                // Only the orientation steps: the angular velocity is held (a spin about the
                // body's axis of largest moment needs no torque to stay as it is), so the three
                // boxes differ by their orientation step alone.
                body.orientation = orientation_step(body.orientation, omega, dt, how);
            }
            self.steps_done += 1;
            if self.overflowed_at.is_none() && self.bodies[1].orientation.length() > DRIFT_MAX_NORM
            {
                self.overflowed_at = Some(self.steps_done as f32 * dt);
            }
            if dt >= SIM_DT || frame_of(self.steps_done) > frame_of(self.steps_done - 1) {
                self.record();
            }
        }
        Ok(())
    }

    /// The rows so far: `[t (s), |q| of the normalised additive box, of the unnormalised one,
    /// of the exponential one]`, one per step, or one per frame ([`SIM_DT`]) when steps are
    /// shorter than a frame.
    pub fn samples(&self) -> &[[f32; 4]] {
        &self.history
    }

    /// The three boxes, in the order of [`DRIFT_STEPS`].
    pub fn bodies(&self) -> &[RigidBody; 3] {
        &self.bodies
    }

    /// Steps taken so far.
    pub fn steps_done(&self) -> usize {
        self.steps_done
    }

    /// When the unnormalised box passed [`DRIFT_MAX_NORM`] and stopped (s), if it did.
    pub fn overflowed_at(&self) -> Option<f32> {
        self.overflowed_at
    }

    /// How far the normalised additive box has fallen behind the exponential one (degrees, 0 to
    /// 180): the angle of the rotation between them.
    pub fn lag_deg(&self) -> f32 {
        let (a, b) = (self.bodies[0].orientation, self.bodies[2].orientation);
        let between = a.normalize() * b.normalize().conjugate();
        // atan2 rather than acos: exact for small angles too.
        (2.0 * between.xyz().length().atan2(between.w.abs())).to_degrees()
    }

    /// How far the normalised additive box has fallen behind the exponential one over the steps
    /// so far, counting whole turns (degrees): `n (|ω| Δt − 2 atan(|ω| Δt / 2))`, which
    /// [`DriftFigure::lag_deg`] measures modulo a turn.
    pub fn total_lag_deg(&self) -> f32 {
        let turn = self.spin * self.dt_sec();
        (self.steps_done as f32 * (turn - 2.0 * (0.5 * turn).atan())).to_degrees()
    }

    /// Where box `k` stands.
    pub fn place(k: usize) -> Vec3 {
        Vec3::new((k as f32 - 1.0) * DRIFT_SPACING_M, DRIFT_HEIGHT_M, 0.0)
    }

    /// Draws each box with the matrix of its raw quaternion (the unnormalised one stretched,
    /// with the unit-quaternion box it should be outlined in grey), each labelled with its step
    /// and `|q|`; returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        frame.grid(16, 0.25);
        // Room for the unnormalised box at its largest drawn stretch.
        let reach = DRIFT_HALF.x * (2.0 * DRIFT_DRAWN_MAX_NORM.powi(2) - 1.0);
        frame.keep_box_in_view(
            Self::place(0) - Vec3::new(0.6, DRIFT_HEIGHT_M, 0.3),
            Self::place(2) + Vec3::new(0.6, reach.max(0.7), 0.3),
        );
        let mut names = Vec::new();
        let mut solid = Vec::new();
        for (k, (body, (_, name))) in self.bodies.iter().zip(DRIFT_STEPS).enumerate() {
            let at = Self::place(k);
            let norm = body.orientation.length();
            let color = BOX_COLORS[k];
            // The box it should be: the matrix of the normalised quaternion.
            let mut unit = *body;
            unit.orientation = unit.orientation.normalize();
            unit.position = at;
            let unit_model = Mat4::from_translation(at)
                * Mat4::from_mat3(unit.rotation())
                * Mat4::from_scale(DRIFT_HALF);
            let mut box_points: Vec<Vec3> = box_samples(unit_model).collect();
            if k == 1 {
                // Outlined.
                let c = corners(&unit, DRIFT_HALF);
                for (i, j) in BOX_EDGES {
                    frame.wide_line(c[i], c[j], palette::GREY, 1.5);
                }
            }
            if norm.is_finite() && norm <= DRIFT_DRAWN_MAX_NORM {
                let model = Mat4::from_translation(at)
                    * Mat4::from_mat3(body.rotation())
                    * Mat4::from_scale(DRIFT_HALF);
                frame.mesh(MeshId::CUBE, model, color);
                box_points.extend(box_samples(model));
            }
            // Past DRIFT_DRAWN_MAX_NORM its matrix would stretch it past the canvas: only the
            // outline is drawn, and its name, in the box's colour as the caption gives it, says so.
            let hidden = if norm.is_finite() && norm <= DRIFT_DRAWN_MAX_NORM {
                ""
            } else {
                " (not drawn)"
            };
            let text = format!("{name}: |q| = {}{hidden}", format_number(norm));
            names.push((k, text, color, box_points.clone()));
            solid.extend(box_points);
        }
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let off_boxes = super::clear_of(view, &solid);
        for (k, text, color, points) in names {
            let at = Self::place(k) + Vec3::new(0.0, 0.6, 0.0);
            let mut first = Label::off_dot(at, 0.0, Vec2::new(0.0, -1.0), text, color, 0);
            if k == 1 {
                first.offset_px.y -= DRIFT_ROW_PX;
            }
            box_label(frame, view, &points, first, &off_boxes);
        }
        let n = self.steps_done;
        let s = self.bodies[1].orientation.length();
        let stopped = match self.overflowed_at {
            Some(t) => format!(
                " It passed {} at t = {} s and was stopped there (its numbers would overflow).",
                format_number(DRIFT_MAX_NORM),
                format_number(t)
            ),
            None => String::new(),
        };
        format!(
            "After {n} steps of Δt = {} ms at |ω| = {} rad/s: the unnormalised |q| = {} (each \
             step multiplies it by √(1 + (|ω|Δt/2)²) = {:.6}), and its matrix (1 − |q|²)E + |q|²R \
             stretches the box by up to 2|q|² − 1 = {} and skews its edges.{stopped} The \
             normalised and \
             exponential |q| stay 1 ({} and {}). The normalised additive box has fallen {}° \
             behind the exponential one: it turns by 2 atan(|ω|Δt/2) a step, not |ω|Δt.",
            format_number(self.step_ms),
            format_number(self.spin),
            format_number(s),
            self.growth_per_step(),
            format_number(2.0 * s * s - 1.0),
            format_number(self.bodies[0].orientation.length()),
            format_number(self.bodies[2].orientation.length()),
            format_number(self.total_lag_deg()),
        ) + &if self.use_exercise {
            format!(" {}", self.exercise_note())
        } else {
            String::new()
        }
    }
}

/// The twelve edges of a box, as pairs of indices into [`corners`].
const BOX_EDGES: [(usize, usize); 12] = [
    (0, 1),
    (2, 3),
    (4, 5),
    (6, 7),
    (0, 2),
    (1, 3),
    (4, 6),
    (5, 7),
    (0, 4),
    (1, 5),
    (2, 6),
    (3, 7),
];
