//! The coming rigid-body lesson's first figure: the tennis racket (the intermediate-axis
//! instability), spun about its middle axis and stepped by three angular integrators side by
//! side, with the energy and the angular momentum each keeps (see [`crate::rigid_body`]).

use super::particles::{steps_to, SIM_DT};
use super::{format_number, in_range, palette, Frame};
use crate::draw::{MeshId, StrokeStyle, ARROW_PX, DOT_PX};
use crate::rigid_body::contact::corners;
use crate::rigid_body::inertia::solid_box;
use crate::rigid_body::{AngularStep, OrientationStep, RigidBody};
use glam::{Mat4, Quat, Vec3};

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

/// Three copies of the same racket, spun at `spin` rad/s about its middle axis with a small
/// wobble, each stepped by one of [`INTEGRATORS`] at [`SIM_DT`].
#[derive(Clone, Debug)]
pub struct RacketFigure {
    spin: f32,
    wobble: f32,
    start: RigidBody,
    bodies: [RigidBody; 3],
    steps_done: usize,
    /// Per step: time, then energy / start energy and |L| / start |L| for each integrator.
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
            start,
            bodies: [start; 3],
            steps_done: 0,
            history: Vec::new(),
        };
        f.restart();
        f
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

    /// The racket at the start of a run: spun about its middle axis, with the wobble.
    fn first(&self) -> RigidBody {
        let mut body = self.start;
        body.omega_body = Vec3::new(self.wobble, self.spin, self.wobble);
        body
    }

    fn restart(&mut self) {
        self.bodies = [self.first(); 3];
        self.steps_done = 0;
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
            row[1 + k] = b.kinetic_energy() / e0;
            row[4 + k] = b.angular_momentum().length() / l0;
        }
        self.history.push(row);
    }

    /// Steps the three rackets to `time_sec` (0 to 60 s); an earlier time starts again.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        let target = steps_to(time_sec)?;
        if target < self.steps_done {
            self.restart();
        }
        while self.steps_done < target {
            for (body, (how, _)) in self.bodies.iter_mut().zip(INTEGRATORS) {
                body.step(SIM_DT, Vec3::ZERO, how, OrientationStep::Exponential);
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
        for (k, (body, (_, name))) in self.bodies.iter().zip(INTEGRATORS).enumerate() {
            let at = Self::place(k);
            let r = Mat4::from_mat3(body.rotation());
            let model = Mat4::from_translation(at) * r * Mat4::from_scale(RACKET_HALF);
            frame.mesh(MeshId::CUBE, model, palette::ORANGE);
            let middle = body.rotation() * Vec3::Y * (RACKET_HALF.y + 0.12);
            frame.wide_line(at - middle, at + middle, palette::Y_AXIS, ARROW_PX);
            let l = body.angular_momentum() / l0 * 0.3;
            frame.arrow(at, at + l, palette::PURPLE, 0.05);
            frame.label(at + Vec3::new(-0.25, reach + 0.3, 0.0), name, palette::DARK);
            let row = self.history.last().copied().unwrap_or([0.0; 7]);
            parts.push(format!(
                "{name}: energy {:.0} %, |L| {:.1} %",
                100.0 * row[1 + k],
                100.0 * row[4 + k]
            ));
        }
        format!(
            "At t = {:.2} s, of their values at the start: {}.",
            self.steps_done as f32 * SIM_DT,
            parts.join("; ")
        )
    }
}

/// Gravity of the figures that have it (m/s²).
pub const GRAVITY: Vec3 = Vec3::new(0.0, -9.81, 0.0);
/// The thrown box's half-extents (m): long along its x, middle along y, thin along z; 1 kg. Its
/// moments are smallest about x, in between about y, largest about z (the shortest axis).
pub const THROW_HALF: Vec3 = Vec3::new(0.3, 0.15, 0.08);
/// Where the throw starts (the centre of mass, m) and the velocity it is thrown with (m/s).
pub const THROW_START: Vec3 = Vec3::new(-0.9, 1.0, 0.0);
pub const THROW_VELOCITY: Vec3 = Vec3::new(1.2, 7.5, 0.0);
/// Substeps of the throw per [`SIM_DT`]. The rotation is stepped at first order: at a whole
/// `SIM_DT` a box spun at 10 rad/s gains more than double its rotational energy within the
/// flight; at 1/50 of it, at most 3 % at the top spin (measured in the tests).
pub const THROW_SUBSTEPS: usize = 50;
/// Length of the drawn `L` (m); ω is drawn at the scale that makes its component along `L` as
/// long, so ω's tip moves on the plane across `L` through `L`'s tip.
pub const THROW_ARROW_M: f32 = 0.8;

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
/// [`AngularStep::Momentum`] and [`OrientationStep::Exponential`], the centre with semi-implicit
/// Euler, started with the velocity half a substep of gravity back (`v₀ − ½ g Δt`, leapfrog's start), which puts every
/// step's centre exactly on the parabola. The flight lasts until the centre is back at its start
/// height, `2 v₀ᵧ / g` ([`ThrowFigure::duration_sec`]); later times hold that moment (the box is
/// caught).
#[derive(Clone, Debug)]
pub struct ThrowFigure {
    spin: f32,
    tilt_deg: f32,
    body: RigidBody,
    /// The angular momentum of the throw (world), held through the flight.
    l_world: Vec3,
    steps_done: usize,
    /// Per step: `[t, |ω|, |L|, angle between ω and L (deg), rotational energy]`.
    history: Vec<[f32; 5]>,
    /// Per step: ω in the world (rad/s), for the trail of its tip.
    omegas: Vec<Vec3>,
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
            history: Vec::new(),
            omegas: Vec::new(),
        };
        f.restart();
        f
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

    /// Steps the throw to `time_sec` (0 to 60 s; past [`ThrowFigure::duration_sec`] the box
    /// holds where the flight ends); an earlier time starts again.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        let target = steps_to(time_sec)?.min(self.flight_steps());
        if target < self.steps_done {
            self.restart();
        }
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
        let reach = THROW_HALF.length().max(THROW_ARROW_M + 0.2);
        frame.keep_box_in_view(
            THROW_START.min(Self::parabola(t_end)) - Vec3::new(reach, THROW_START.y, reach),
            THROW_START.max(Self::parabola(t_end)).max(apex) + Vec3::splat(reach),
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
        let t = self.steps_done as f32 * SIM_DT;
        let l = b.angular_momentum();
        let omega = b.omega_world();
        let l_dir = throw_l_direction();
        let along = self.omegas[0].dot(l_dir);
        if self.spin == 0.0 || along <= 0.0 {
            return format!(
                "t = {t:.2} s. No spin: ω and L are zero, and the box flies its parabola \
                 without turning."
            );
        }
        let l_tip = at + THROW_ARROW_M * l_dir;
        frame.arrow(at, l_tip, palette::PURPLE, 0.08);
        frame.label(l_tip + Vec3::new(-0.12, 0.05, 0.0), "L", palette::PURPLE);
        // ω at the scale that puts its tip on the plane across L through L's tip.
        let scale = THROW_ARROW_M / along;
        let trail: Vec<Vec3> = self.omegas.iter().map(|w| at + scale * *w).collect();
        let light = palette::TEAL.lerp(Vec3::ONE, 0.45);
        frame.wide_polyline(&trail, light, 3.0);
        let w_tip = at + scale * omega;
        frame.arrow(at, w_tip, palette::TEAL, 0.08);
        frame.label(w_tip + Vec3::new(0.05, 0.05, 0.0), "ω", palette::TEAL);
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

/// The angle between two vectors in degrees; 0 when either is (nearly) zero.
fn angle_deg(a: Vec3, b: Vec3) -> f32 {
    let d = (a.length() * b.length()).max(0.0);
    if d < 1e-12 {
        return 0.0;
    }
    (a.dot(b) / d).clamp(-1.0, 1.0).acos().to_degrees()
}
