//! The particle system: flat arrays (structure of arrays), emitters that spawn from seeded
//! distributions, ageing, and recycling of dead particles without allocation.

use super::collide::{ballistic_step, Surfaces};
use super::{ParticleError, Rng};
use glam::{Vec3, Vec4};

/// The most particles one system may hold. Memory and the cost of a step grow with it; the pages
/// use far fewer (a few thousand at most) so that software rendering stays smooth.
pub const MAX_PARTICLES: usize = 100_000;

/// Where an emitter places new particles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PositionDist {
    /// Always at this point.
    Point(Vec3),
    /// Uniform inside a ball (centre, radius in metres).
    Ball(Vec3, f32),
}

/// How fast, and where to, new particles move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VelocityDist {
    /// Inside a cone around the unit `axis` with half-angle `half_angle_rad`, speed uniform in
    /// `[speed_min, speed_max]` m/s (a fountain).
    Cone {
        axis: Vec3,
        half_angle_rad: f32,
        speed_min: f32,
        speed_max: f32,
    },
    /// Uniform over directions, speed in `[speed_min, speed_max]` (an explosion).
    Sphere { speed_min: f32, speed_max: f32 },
}

/// A source of particles: a rate, a lifetime, and the distributions new particles are drawn from
/// (with the system's seeded generator, so a run is reproducible bit for bit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emitter {
    /// Particles per second, `≥ 0` (0: only bursts).
    pub rate_per_sec: f32,
    /// Lifetime range, seconds, `0 < min ≤ max`.
    pub lifetime_sec: (f32, f32),
    pub position: PositionDist,
    pub velocity: VelocityDist,
    /// Radius range, metres.
    pub size: (f32, f32),
    /// Colour at birth and at death (linear RGBA), blended with age.
    pub color_birth: Vec4,
    pub color_death: Vec4,
    /// Fractional particles carried to the next step (so rate × dt need not be whole).
    pub carry: f32,
}

impl Emitter {
    /// A fountain at `origin`: a narrow upward cone.
    pub fn fountain(origin: Vec3) -> Self {
        Self {
            rate_per_sec: 200.0,
            lifetime_sec: (2.0, 3.0),
            position: PositionDist::Ball(origin, 0.03),
            velocity: VelocityDist::Cone {
                axis: Vec3::Y,
                half_angle_rad: 0.25,
                speed_min: 5.0,
                speed_max: 6.0,
            },
            size: (0.03, 0.05),
            color_birth: Vec4::new(0.1, 0.4, 1.0, 1.0),
            color_death: Vec4::new(0.8, 0.9, 1.0, 0.0),
            carry: 0.0,
        }
    }

    /// An explosion at `origin`: no steady rate; call [`ParticleSystem::burst`].
    pub fn explosion(origin: Vec3) -> Self {
        Self {
            rate_per_sec: 0.0,
            lifetime_sec: (0.8, 1.6),
            position: PositionDist::Ball(origin, 0.1),
            velocity: VelocityDist::Sphere {
                speed_min: 2.0,
                speed_max: 6.0,
            },
            size: (0.03, 0.06),
            color_birth: Vec4::new(1.0, 0.8, 0.2, 1.0),
            color_death: Vec4::new(0.6, 0.05, 0.0, 0.0),
            carry: 0.0,
        }
    }

    /// Every rule an emitter must satisfy, each with its own message.
    pub fn validate(&self) -> Result<(), ParticleError> {
        let bad = |what: &str| Err(ParticleError::Invalid(what.to_string()));
        if !self.rate_per_sec.is_finite() || self.rate_per_sec < 0.0 {
            return bad(&format!(
                "rate must be finite and ≥ 0, got {}",
                self.rate_per_sec
            ));
        }
        let (lo, hi) = self.lifetime_sec;
        if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && lo <= hi) {
            return bad(&format!(
                "lifetime must satisfy 0 < min ≤ max, got [{lo}, {hi}]"
            ));
        }
        let (lo, hi) = self.size;
        if !(lo.is_finite() && hi.is_finite() && lo >= 0.0 && lo <= hi) {
            return bad(&format!(
                "size must satisfy 0 ≤ min ≤ max, got [{lo}, {hi}]"
            ));
        }
        let finite = match self.position {
            PositionDist::Point(p) => p.is_finite(),
            PositionDist::Ball(c, r) => c.is_finite() && r.is_finite() && r >= 0.0,
        };
        if !finite {
            return bad("position distribution must be finite (radius ≥ 0)");
        }
        let ok = match self.velocity {
            VelocityDist::Cone {
                axis,
                half_angle_rad,
                speed_min,
                speed_max,
            } => {
                axis.is_finite()
                    && axis.length_squared() > 0.0
                    && half_angle_rad.is_finite()
                    && speed_min.is_finite()
                    && speed_max.is_finite()
                    && speed_min <= speed_max
            }
            VelocityDist::Sphere {
                speed_min,
                speed_max,
            } => speed_min.is_finite() && speed_max.is_finite() && speed_min <= speed_max,
        };
        if !ok {
            return bad(
                "velocity distribution must be finite, with a non-zero axis and min ≤ max speed",
            );
        }
        if !(self.color_birth.is_finite() && self.color_death.is_finite()) {
            return bad("colours must be finite");
        }
        Ok(())
    }
}

/// Particles in structure-of-arrays form. The first [`ParticleSystem::len`] entries of each
/// array are alive; a particle that dies is replaced by the last live one (swap), so the live
/// ones stay packed and the arrays never shrink or grow after [`ParticleSystem::new`].
#[derive(Clone, Debug)]
pub struct ParticleSystem {
    /// World space, metres.
    pub positions: Vec<Vec3>,
    /// m/s.
    pub velocities: Vec<Vec3>,
    /// Seconds since birth.
    pub ages: Vec<f32>,
    /// Seconds a particle lives.
    pub lifetimes: Vec<f32>,
    /// Radius, metres.
    pub sizes: Vec<f32>,
    /// Linear RGBA, blended from the emitter's birth to death colour with age.
    pub colors: Vec<Vec4>,
    /// Which emitter made it (an index into the caller's emitters).
    pub emitter_of: Vec<u16>,
    /// Lying on the floor (see [`ballistic_step`]).
    pub resting: Vec<bool>,
    alive: usize,
    rng: Rng,
}

impl ParticleSystem {
    /// Room for `capacity ≤` [`MAX_PARTICLES`] particles, all dead; `seed` seeds the generator.
    pub fn new(capacity: usize, seed: u64) -> Result<Self, ParticleError> {
        if capacity > MAX_PARTICLES {
            return Err(ParticleError::TooMany {
                asked: capacity,
                max: MAX_PARTICLES,
            });
        }
        Ok(Self {
            positions: vec![Vec3::ZERO; capacity],
            velocities: vec![Vec3::ZERO; capacity],
            ages: vec![0.0; capacity],
            lifetimes: vec![0.0; capacity],
            sizes: vec![0.0; capacity],
            colors: vec![Vec4::ZERO; capacity],
            emitter_of: vec![0; capacity],
            resting: vec![false; capacity],
            alive: 0,
            rng: Rng::new(seed),
        })
    }

    /// How many particles are alive.
    pub fn len(&self) -> usize {
        self.alive
    }

    pub fn is_empty(&self) -> bool {
        self.alive == 0
    }

    pub fn capacity(&self) -> usize {
        self.positions.len()
    }

    /// Kills every particle and reseeds the generator.
    pub fn reset(&mut self, seed: u64) {
        self.alive = 0;
        self.rng = Rng::new(seed);
    }

    /// Spawns up to `count` particles from `emitters[index]` (fewer if the system is full).
    /// Returns how many were spawned.
    pub fn burst(&mut self, emitters: &[Emitter], index: usize, count: usize) -> usize {
        let Some(e) = emitters.get(index) else {
            return 0;
        };
        let n = count.min(self.capacity() - self.alive);
        for _ in 0..n {
            self.spawn(e, index);
        }
        n
    }

    fn spawn(&mut self, e: &Emitter, index: usize) {
        let i = self.alive;
        let rng = &mut self.rng;
        let p = match e.position {
            PositionDist::Point(p) => p,
            PositionDist::Ball(c, r) => c + r * rng.in_unit_ball(),
        };
        let v = match e.velocity {
            VelocityDist::Cone {
                axis,
                half_angle_rad,
                speed_min,
                speed_max,
            } => {
                let dir = rng.in_cone(axis.normalize(), half_angle_rad);
                dir * rng.range(speed_min, speed_max)
            }
            VelocityDist::Sphere {
                speed_min,
                speed_max,
            } => rng.on_unit_sphere() * rng.range(speed_min, speed_max),
        };
        self.positions[i] = p;
        self.velocities[i] = v;
        self.ages[i] = 0.0;
        self.lifetimes[i] = rng.range(e.lifetime_sec.0, e.lifetime_sec.1);
        self.sizes[i] = rng.range(e.size.0, e.size.1);
        self.colors[i] = e.color_birth;
        self.emitter_of[i] = index as u16;
        self.resting[i] = false;
        self.alive += 1;
    }

    /// One step of `dt` seconds: emit (rate × dt, with the fraction carried over), age and kill
    /// (recycling the slots), move every live particle along its exact ballistic path with
    /// bounces on `surfaces`, and update colours. No allocation.
    pub fn step(&mut self, emitters: &mut [Emitter], surfaces: &Surfaces, dt: f32) {
        for (index, e) in emitters.iter_mut().enumerate() {
            e.carry += e.rate_per_sec * dt;
            let whole = e.carry.floor();
            e.carry -= whole;
            let n = (whole as usize).min(self.capacity() - self.alive);
            let e = *e; // a copy, so that spawning can borrow self
            for _ in 0..n {
                self.spawn(&e, index);
            }
        }
        let mut i = 0;
        while i < self.alive {
            self.ages[i] += dt;
            if self.ages[i] >= self.lifetimes[i] {
                self.kill(i); // the last live one moves into slot i: look at i again
                continue;
            }
            ballistic_step(
                &mut self.positions[i],
                &mut self.velocities[i],
                &mut self.resting[i],
                dt,
                surfaces,
            );
            if let Some(e) = emitters.get(self.emitter_of[i] as usize) {
                let t = (self.ages[i] / self.lifetimes[i]).clamp(0.0, 1.0);
                self.colors[i] = e.color_birth.lerp(e.color_death, t);
            }
            i += 1;
        }
    }

    /// Kills particle `i` by moving the last live particle into its slot.
    fn kill(&mut self, i: usize) {
        let last = self.alive - 1;
        self.positions.swap(i, last);
        self.velocities.swap(i, last);
        self.ages.swap(i, last);
        self.lifetimes.swap(i, last);
        self.sizes.swap(i, last);
        self.colors.swap(i, last);
        self.emitter_of.swap(i, last);
        self.resting.swap(i, last);
        self.alive = last;
    }
}
