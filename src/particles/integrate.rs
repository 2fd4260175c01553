//! Integrators for `d²p/dt² = a(p)`: explicit Euler, semi-implicit (symplectic) Euler and velocity
//! Verlet, next to the exact solution of free fall. One particle at a time, so that a particle
//! system, a flock or a cloth (issue 12) can call them in its own loop over flat arrays.

use glam::Vec3;

/// The exact free fall under a constant acceleration `g` (m/s²), from `p0` with velocity `v0`:
/// ```text
/// p(t) = ½ g t² + v0 t + p0
/// v(t) = g t + v0
/// ```
/// `t` in seconds; `t = 0` gives `(p0, v0)`. Lesson: lessons/11-particles.
pub fn free_fall(p0: Vec3, v0: Vec3, g: Vec3, t: f32) -> (Vec3, Vec3) {
    (0.5 * g * t * t + v0 * t + p0, g * t + v0)
}

/// How a particle's position and velocity are advanced by one step `dt`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// `p' = p + v dt`, `v' = v + a(p) dt`: both from the old state. First order; gains energy
    /// on an oscillator.
    ExplicitEuler,
    /// `v' = v + a(p) dt`, `p' = p + v' dt`: the new velocity moves the point. First order, but
    /// symplectic: an oscillator's energy stays bounded.
    SemiImplicitEuler,
    /// `p' = p + v dt + ½ a(p) dt²`, `v' = v + ½ (a(p) + a(p')) dt`. Second order, symplectic,
    /// and exact when `a` is constant (free fall).
    VelocityVerlet,
}

impl Integrator {
    /// Every integrator, in the order the lesson shows them.
    pub const ALL: [Integrator; 3] = [
        Integrator::ExplicitEuler,
        Integrator::SemiImplicitEuler,
        Integrator::VelocityVerlet,
    ];

    /// The name the page shows ("explicit Euler", "semi-implicit Euler", "velocity Verlet").
    pub fn name(self) -> &'static str {
        match self {
            Integrator::ExplicitEuler => "explicit Euler",
            Integrator::SemiImplicitEuler => "semi-implicit Euler",
            Integrator::VelocityVerlet => "velocity Verlet",
        }
    }

    /// The order of convergence: halving `dt` divides the error at a fixed time by `2^order`.
    pub fn order(self) -> u32 {
        match self {
            Integrator::VelocityVerlet => 2,
            _ => 1,
        }
    }

    /// Advances `(p, v)` by `dt` seconds under the acceleration field `a(p)` (m/s²).
    /// `dt = 0` changes nothing. Velocity Verlet evaluates `a` twice per step; a caller that
    /// keeps the last acceleration can use [`verlet_step`] and evaluate it once.
    pub fn step(self, p: &mut Vec3, v: &mut Vec3, dt: f32, a: impl Fn(Vec3) -> Vec3) {
        match self {
            Integrator::ExplicitEuler => explicit_euler_step(p, v, a(*p), dt),
            Integrator::SemiImplicitEuler => semi_implicit_euler_step(p, v, a(*p), dt),
            Integrator::VelocityVerlet => {
                let a0 = a(*p);
                verlet_step(p, v, a0, dt, a);
            }
        }
    }
}

/// One explicit (forward) Euler step with acceleration `a` taken at the start of the step:
/// ```text
/// p' = p + v dt
/// v' = v + a dt
/// ```
pub fn explicit_euler_step(p: &mut Vec3, v: &mut Vec3, a: Vec3, dt: f32) {
    *p += *v * dt;
    *v += a * dt;
}

/// One semi-implicit (symplectic) Euler step: the velocity first, then the position with the
/// *new* velocity:
/// ```text
/// v' = v + a dt
/// p' = p + v' dt
/// ```
/// The course's boids update; exercise 11.2.
pub fn semi_implicit_euler_step(p: &mut Vec3, v: &mut Vec3, a: Vec3, dt: f32) {
    *v += a * dt;
    *p += *v * dt;
}

/// One velocity Verlet step, given the acceleration `a0 = a(p)` at the start; returns the
/// acceleration at the new position (the next step's `a0`):
/// ```text
/// p' = p + v dt + ½ a0 dt²
/// v' = v + ½ (a0 + a(p')) dt
/// ```
pub fn verlet_step(
    p: &mut Vec3,
    v: &mut Vec3,
    a0: Vec3,
    dt: f32,
    a: impl Fn(Vec3) -> Vec3,
) -> Vec3 {
    *p += *v * dt + 0.5 * a0 * dt * dt;
    let a1 = a(*p);
    *v += 0.5 * (a0 + a1) * dt;
    a1
}

/// One sample of the free-fall comparison: time and each integrator's position error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FreeFallError {
    /// Seconds since the start.
    pub time_sec: f32,
    /// `|p_integrated − p_exact|` in metres, per integrator in [`Integrator::ALL`] order.
    pub error_m: [f32; 3],
}

/// Integrates free fall from `(p0, v0)` under `g` with step `dt` for `steps` steps with every
/// integrator, and writes the position error against [`free_fall`] after each step into `out`
/// (one sample per step, `out.len()` at least `steps`). Returns how many samples were written.
/// Uses f64 for the exact solution so the error shown is the integrator's, not rounding's.
pub fn free_fall_errors(p0: Vec3, v0: Vec3, g: Vec3, dt: f32, out: &mut [FreeFallError]) -> usize {
    let mut states = [(p0, v0); 3];
    for (k, sample) in out.iter_mut().enumerate() {
        let t = (k + 1) as f64 * dt as f64;
        let exact = p0.as_dvec3() + v0.as_dvec3() * t + 0.5 * g.as_dvec3() * t * t;
        let mut error_m = [0.0; 3];
        for (i, integrator) in Integrator::ALL.iter().enumerate() {
            let (p, v) = &mut states[i];
            integrator.step(p, v, dt, |_| g);
            error_m[i] = (p.as_dvec3() - exact).length() as f32;
        }
        *sample = FreeFallError {
            time_sec: t as f32,
            error_m,
        };
    }
    out.len()
}
