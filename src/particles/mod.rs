//! Lesson 11 core, "Particles": free fall and its integrators, bouncing with the exact time of
//! impact, a particle system with emitters, and the squash-and-stretch ball.
//!
//! - [`integrate`]: the exact free fall `p(t) = ½ g t² + v0 t + p0` next to explicit Euler,
//!   semi-implicit Euler and velocity Verlet, one particle at a time (cloth reuses them).
//! - [`collide`]: ballistic flight stopped at the exact time of impact with a floor or a sphere,
//!   restitution, friction, resting contact.
//! - [`system`]: [`ParticleSystem`] in structure-of-arrays form and its [`Emitter`]s, seeded and
//!   reproducible; dead particles are recycled in place; at most [`MAX_PARTICLES`].
//! - [`sprites`]: the smoke atlas particles are drawn with, and the back-to-front order of
//!   transparent sprites.
//! - [`SquashBall`]: a ball that stretches along its velocity and squashes on impact, keeping
//!   its volume (built on [`crate::expressive::squash_stretch_matrix`]).
//!
//! Conventions as in the crate root: Y up, metres, seconds; gravity is `(0, −9.81, 0)` m/s².
//! Lesson: lessons/11-particles.

pub mod collide;
pub mod integrate;
pub mod sprites;
pub mod system;

pub use collide::{
    ballistic_step, bounce_velocity, floor_time_of_impact, sphere_contact_force,
    sphere_time_of_impact, Plane, Sphere, Surfaces,
};
pub use integrate::{
    explicit_euler_step, free_fall, free_fall_errors, semi_implicit_euler_step, verlet_step,
    FreeFallError, Integrator,
};
pub use system::{Emitter, ParticleSystem, PositionDist, VelocityDist, MAX_PARTICLES};

use glam::{Mat3, Vec3};

/// What a caller can get wrong.
#[derive(Clone, Debug, PartialEq)]
pub enum ParticleError {
    /// More particles than the documented cap.
    TooMany { asked: usize, max: usize },
    /// A parameter out of its range or not finite; the message names it.
    Invalid(String),
}

impl std::fmt::Display for ParticleError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParticleError::TooMany { asked, max } => {
                write!(f, "{asked} particles is too many (at most {max})")
            }
            ParticleError::Invalid(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for ParticleError {}

/// A small seeded generator (SplitMix64): the same sequence on every machine and in wasm, so a
/// seeded particle run is reproducible bit for bit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`, 24 bits.
    pub fn unit(&mut self) -> f32 {
        (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32
    }

    /// Uniform in `[lo, hi)` (`lo` when they are equal).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform on the unit sphere (Archimedes: uniform height, uniform angle).
    pub fn on_unit_sphere(&mut self) -> Vec3 {
        let z = self.range(-1.0, 1.0);
        let phi = self.range(0.0, std::f32::consts::TAU);
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), z, r * phi.sin())
    }

    /// Uniform in the unit ball (a direction times the cube root of a uniform number).
    pub fn in_unit_ball(&mut self) -> Vec3 {
        self.on_unit_sphere() * self.unit().cbrt()
    }

    /// Uniform over the directions within `half_angle_rad` of the unit `axis`.
    pub fn in_cone(&mut self, axis: Vec3, half_angle_rad: f32) -> Vec3 {
        let cos_max = half_angle_rad.clamp(0.0, std::f32::consts::PI).cos();
        let z = self.range(cos_max, 1.0);
        let phi = self.range(0.0, std::f32::consts::TAU);
        let r = (1.0 - z * z).max(0.0).sqrt();
        let local = Vec3::new(r * phi.cos(), r * phi.sin(), z);
        glam::Quat::from_rotation_arc(Vec3::Z, axis) * local
    }
}

/// A ball bouncing on the floor `y = 0` that squashes and stretches, keeping its volume: in the
/// air it stretches along its velocity (`s = 1 + k |v|`, at most `max_stretch`); for
/// `contact_sec` after each impact it squashes along the floor normal (`s` down to
/// `1 − squash`, a half sine). Flight and impacts are exact ([`ballistic_step`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SquashBall {
    pub position: Vec3,
    pub velocity: Vec3,
    /// Radius at rest, metres.
    pub radius: f32,
    /// Stretch per m/s of speed.
    pub stretch_per_speed: f32,
    pub max_stretch: f32,
    /// Deepest squash on impact, in `[0, 0.8]`.
    pub squash: f32,
    pub contact_sec: f32,
    /// Seconds since the last impact (large when none).
    pub since_impact_sec: f32,
    resting: bool,
}

impl SquashBall {
    /// A ball of `radius` dropped from height `height` (of its centre), moving sideways at
    /// `vx` m/s.
    pub fn new(radius: f32, height: f32, vx: f32) -> Self {
        Self {
            position: Vec3::new(0.0, height, 0.0),
            velocity: Vec3::new(vx, 0.0, 0.0),
            radius,
            stretch_per_speed: 0.06,
            max_stretch: 1.6,
            squash: 0.45,
            contact_sec: 0.09,
            since_impact_sec: f32::INFINITY,
            resting: false,
        }
    }

    /// Advances by `dt`: the ball's centre moves as a particle on the floor `y = radius`.
    pub fn step(&mut self, surfaces: &Surfaces, dt: f32) {
        let s = Surfaces {
            floor_y: surfaces.floor_y.map(|f| f + self.radius),
            spheres: Vec::new(),
            ..surfaces.clone()
        };
        let vy_before = self.velocity.y;
        ballistic_step(
            &mut self.position,
            &mut self.velocity,
            &mut self.resting,
            dt,
            &s,
        );
        // A bounce flips the vertical velocity from downwards to upwards (or stops it).
        if vy_before < -REST_IMPACT && self.velocity.y >= 0.0 {
            self.since_impact_sec = 0.0;
        } else {
            self.since_impact_sec += dt;
        }
    }

    /// The deformation now: `(axis, s)` with `s > 1` stretching along `axis`, `s < 1` squashing.
    pub fn stretch(&self) -> (Vec3, f32) {
        if self.since_impact_sec < self.contact_sec {
            let phase = self.since_impact_sec / self.contact_sec;
            let s = 1.0 - self.squash.clamp(0.0, 0.8) * (std::f32::consts::PI * phase).sin();
            return (Vec3::Y, s);
        }
        let speed = self.velocity.length();
        let s =
            crate::expressive::stretch_from_speed(speed, self.stretch_per_speed, self.max_stretch);
        (self.velocity.normalize_or(Vec3::Y), s)
    }

    /// The ball's linear part: radius times the volume-preserving squash/stretch (det = r³).
    pub fn shape_matrix(&self) -> Mat3 {
        let (axis, s) = self.stretch();
        crate::expressive::squash_stretch_matrix(axis, s) * self.radius
    }
}

/// Vertical speed (m/s) an impact needs for the ball to squash visibly.
const REST_IMPACT: f32 = 0.3;
