//! The coming rigid-body lesson's first figure: the tennis racket (the intermediate-axis
//! instability), spun about its middle axis and stepped by three angular integrators side by
//! side, with the energy and the angular momentum each keeps (see [`crate::rigid_body`]).

use super::particles::{steps_to, SIM_DT};
use super::{in_range, palette, Frame};
use crate::draw::{MeshId, ARROW_PX};
use crate::rigid_body::inertia::solid_box;
use crate::rigid_body::{AngularStep, OrientationStep, RigidBody};
use glam::{Mat4, Vec3};

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
