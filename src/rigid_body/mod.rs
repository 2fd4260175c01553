//! Rigid bodies: a body's state (position, orientation quaternion, linear and angular velocity),
//! its inertia in its principal frame, and the integrators the course compares.
//!
//! - **Linear part:** semi-implicit Euler, as for particles (`v += g dt`, then `x += v dt`).
//! - **Orientation:** the quaternion follows `q̇ = ½ ω q` (ω in the world frame, as a pure
//!   quaternion). [`OrientationStep`] offers the additive step `q + ½ dt ω q` with or without
//!   normalising it afterwards, and the exact step for a constant ω over the step,
//!   `q ← exp(½ dt ω) q`, a rotation by `|ω| dt` about `ω`, which keeps `|q| = 1` by construction.
//!   Without the normalisation the additive step lets `|q|` grow every step, and the matrix built
//!   from `q` ([`RigidBody::rotation`]) stretches and shears the body.
//! - **Angular velocity:** with no torque the angular momentum `L = R I ω` is constant in the
//!   world. [`AngularStep::Momentum`] keeps it so and turns the body by a symmetric splitting of
//!   the torque-free motion into turns about its own principal axes (x and y for half a step, z
//!   for a whole one, then y and x again: McLachlan 1993, Touma and Wisdom 1994), each at the rate
//!   read off the unchanged L in the attitude of the moment (`ω_i = (Rᵀ L)_i / I_i`); `L` is
//!   conserved to float precision and the energy, which no explicit turn keeps, stays within a
//!   small bounded error (the splitting is symplectic). The other two integrate
//!   Euler's equations in the body frame, `I ω̇ = −ω × I ω` (the gyroscopic term), as solvers that
//!   store velocities must: [`AngularStep::Explicit`] evaluates the term at the start of the step
//!   and gains energy; [`AngularStep::Implicit`] solves `I (ω − ω₀) + dt ω × I ω = 0` for the end
//!   of the step by one Newton step from ω₀ (as Box2D's and Bullet's solvers do), which never
//!   gains energy but loses some.
//! - **Collisions:** an impulse `j` at a point changes `v` by `j / m` and ω by `I⁻¹ (r × j)`
//!   ([`RigidBody::apply_impulse`]); [`normal_impulse`] is the size of the one impulse that makes
//!   a contact point with an immovable object bounce with restitution `e`. [`contact`] resolves
//!   many contacts at once, between moving bodies too, by sequential impulses.
//!
//! The body's own frame is its principal frame: its inertia tensor there is the diagonal
//! [`RigidBody::inertia`]. A body made of parts whose tensor has products of inertia would first
//! be turned to its principal axes.

pub mod contact;
pub mod inertia;

use glam::{Mat3, Quat, Vec3};

/// How the orientation quaternion advances over a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OrientationStep {
    /// `q ← normalize(q + ½ dt ω q)`.
    Additive,
    /// `q ← q + ½ dt ω q`, left unnormalised: `|q|` drifts and the body shears.
    AdditiveUnnormalised,
    /// `q ← exp(½ dt ω) q`: the rotation by `|ω| dt` about `ω`, exact for a constant ω.
    Exponential,
}

/// How the angular velocity advances under no torque.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AngularStep {
    /// The world angular momentum is held; the body turns about its principal axes in a
    /// symmetric splitting, at rates read off `L` (conserves `L`, keeps the energy to a bounded
    /// error).
    Momentum,
    /// The gyroscopic term with the angular velocity at the start of the step (gains energy).
    Explicit,
    /// The gyroscopic term with the angular velocity at the end of the step, by one Newton step
    /// (never gains energy, loses some).
    Implicit,
}

/// One step of the orientation `q` under the world-frame angular velocity `omega` (rad/s).
pub fn orientation_step(q: Quat, omega: Vec3, dt: f32, how: OrientationStep) -> Quat {
    match how {
        OrientationStep::Additive | OrientationStep::AdditiveUnnormalised => {
            let w = Quat::from_xyzw(omega.x, omega.y, omega.z, 0.0);
            let next = q + (w * q) * (0.5 * dt);
            if how == OrientationStep::Additive {
                next.normalize()
            } else {
                next
            }
        }
        OrientationStep::Exponential => {
            let speed = omega.length();
            if speed * dt < 1e-12 {
                return q;
            }
            Quat::from_axis_angle(omega / speed, speed * dt) * q
        }
    }
}

/// The skew-symmetric matrix of `v`: `skew(v) u = v × u`.
fn skew(v: Vec3) -> Mat3 {
    Mat3::from_cols(
        Vec3::new(0.0, v.z, -v.y),
        Vec3::new(-v.z, 0.0, v.x),
        Vec3::new(v.y, -v.x, 0.0),
    )
}

/// The inverse inertia tensor in the world's frame, `R I⁻¹ Rᵀ`, of a body turned by
/// `orientation` (normalised first) whose principal moments are `inertia`: the body-frame inverse
/// (a diagonal of reciprocals) seen from the world. It maps a world torque impulse to the change
/// of world angular velocity it makes.
pub fn world_inverse_inertia(orientation: Quat, inertia: Vec3) -> Mat3 {
    let r = Mat3::from_quat(orientation.normalize());
    r * Mat3::from_diagonal(inertia.recip()) * r.transpose()
}

/// One step of Euler's equations for the body-frame angular velocity `omega` of a body with
/// principal moments `inertia` under no torque (`I ω̇ = −ω × I ω`), explicit or implicit in the
/// gyroscopic term. `implicit` false is the explicit step.
pub fn gyroscopic_step(inertia: Vec3, omega: Vec3, dt: f32, implicit: bool) -> Vec3 {
    let i = Mat3::from_diagonal(inertia);
    match implicit {
        false => omega - dt * (omega.cross(inertia * omega) / inertia),
        true => {
            // f(ω) = I (ω − ω₀) + dt ω × I ω, zero at the end of the step; one Newton step
            // from ω₀, where f(ω₀) = dt ω₀ × I ω₀ and f′(ω₀) = I + dt (skew(ω₀) I − skew(I ω₀)).
            let f = dt * omega.cross(inertia * omega);
            let jacobian = i + dt * (skew(omega) * i - skew(inertia * omega));
            omega - jacobian.inverse() * f
        }
    }
}

/// The impulse magnitude of a single frictionless contact of a body with an immovable object
/// (the ground, a wall): the textbook collision response.
/// ```text
///          −(1 + e) (v_rel · n)
/// j = ──────────────────────────────────
///      1/m + n · ((I⁻¹ (r × n)) × r)
/// ```
/// `v_rel` is the velocity of the body's contact point (m/s, world), `n` the unit contact normal
/// pointing out of the object into the body, `r` the vector from the centre of mass to the
/// contact point, `inv_mass` = 1/m, `inv_inertia` the world inverse inertia `R I⁻¹ Rᵀ`
/// ([`RigidBody::world_inverse_inertia`]), `e` the coefficient of restitution in [0, 1].
/// Applying `j n` at the contact point ([`RigidBody::apply_impulse`]) turns the point's normal
/// velocity `v_rel · n` into exactly `−e` times itself; for `e ≤ 1` the kinetic energy does not
/// grow (`e = 1` keeps it). 0 when the point is not approaching (`v_rel · n ≥ 0`). The
/// denominator is `1/m` plus the rotational share `|I^(−1/2) (r × n)|²`, never below `1/m`.
/// Lesson: lessons/14-rigid-bodies (exercise 14.4).
pub fn normal_impulse(
    v_rel: Vec3,
    normal: Vec3,
    r: Vec3,
    inv_mass: f32,
    inv_inertia: Mat3,
    restitution: f32,
) -> f32 {
    let approach = v_rel.dot(normal);
    if approach >= 0.0 {
        return 0.0;
    }
    let k = inv_mass + normal.dot((inv_inertia * r.cross(normal)).cross(r));
    -(1.0 + restitution) * approach / k
}

/// A rigid body. Its frame is its principal frame, centred on its centre of mass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidBody {
    /// Centre of mass, world frame (m).
    pub position: Vec3,
    /// Rotation from the body's frame to the world's.
    pub orientation: Quat,
    /// Velocity of the centre of mass (m/s).
    pub velocity: Vec3,
    /// Angular velocity in the body's frame (rad/s).
    pub omega_body: Vec3,
    /// Mass (kg).
    pub mass: f32,
    /// Principal moments of inertia (kg m²): the diagonal of the tensor in the body's frame.
    pub inertia: Vec3,
}

impl RigidBody {
    /// A body at rest at the origin. An error unless the mass and the three moments are positive
    /// and finite, and the moments satisfy the triangle inequality every real body does
    /// (`I₁ + I₂ ≥ I₃` for each order).
    pub fn new(mass: f32, inertia: Vec3) -> Result<Self, String> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(format!("mass must be a positive number of kg, got {mass}"));
        }
        if !(inertia.is_finite() && inertia.min_element() > 0.0) {
            return Err(format!(
                "moments of inertia must be positive, got {inertia}"
            ));
        }
        let sum = inertia.element_sum();
        if 2.0 * inertia.max_element() > sum * (1.0 + 1e-5) {
            return Err(format!(
                "moments of inertia {inertia} are not a body's: each must be at most the sum of the other two"
            ));
        }
        Ok(Self {
            position: Vec3::ZERO,
            orientation: Quat::IDENTITY,
            velocity: Vec3::ZERO,
            omega_body: Vec3::ZERO,
            mass,
            inertia,
        })
    }

    /// The rotation matrix of the orientation, by the formula for a unit quaternion (lesson 03's
    /// [`crate::rotation::mat3_from_quat`], as `glam::Mat3::from_quat`), applied to the
    /// quaternion as it is: a quaternion that has drifted from unit length gives a matrix whose
    /// axes are neither unit nor perpendicular, and the drawn body stretches and shears.
    pub fn rotation(&self) -> Mat3 {
        crate::rotation::mat3_from_quat(self.orientation)
    }

    /// The angular velocity in the world's frame.
    pub fn omega_world(&self) -> Vec3 {
        self.orientation.normalize() * self.omega_body
    }

    /// The inverse inertia tensor in the world's frame, `R I⁻¹ Rᵀ`.
    pub fn world_inverse_inertia(&self) -> Mat3 {
        world_inverse_inertia(self.orientation, self.inertia)
    }

    /// The linear momentum `m v`.
    pub fn linear_momentum(&self) -> Vec3 {
        self.mass * self.velocity
    }

    /// The angular momentum about the centre of mass in the world's frame, `R I ω_body`.
    pub fn angular_momentum(&self) -> Vec3 {
        self.orientation.normalize() * (self.inertia * self.omega_body)
    }

    /// Kinetic energy, translation plus rotation: `½ m |v|² + ½ ω · I ω` (J).
    pub fn kinetic_energy(&self) -> f32 {
        0.5 * self.mass * self.velocity.length_squared()
            + 0.5 * self.omega_body.dot(self.inertia * self.omega_body)
    }

    /// Applies the impulse `j` (N s) at the world point `at`: `Δv = j / m` and
    /// `Δω = I⁻¹ (r × j)` with `r` from the centre of mass to `at`.
    pub fn apply_impulse(&mut self, j: Vec3, at: Vec3) {
        self.velocity += j / self.mass;
        let r = at - self.position;
        let d_omega_world = self.world_inverse_inertia() * r.cross(j);
        self.omega_body += self.orientation.normalize().inverse() * d_omega_world;
    }

    /// The velocity of the body's material point at the world point `at`: `v + ω × r`.
    pub fn point_velocity(&self, at: Vec3) -> Vec3 {
        self.velocity + self.omega_world().cross(at - self.position)
    }

    /// One step of `dt` seconds under `gravity` and no torque: semi-implicit Euler for the
    /// centre of mass, `angular` for the angular velocity and `orientation` for the quaternion.
    pub fn step(
        &mut self,
        dt: f32,
        gravity: Vec3,
        angular: AngularStep,
        orientation: OrientationStep,
    ) {
        self.velocity += gravity * dt;
        self.position += self.velocity * dt;
        match angular {
            AngularStep::Momentum => {
                // Five turns about the body's own axes, x y z y x, each at the rate about that
                // axis that the unchanged L gives in the present attitude. A turn about a body
                // axis e_i at rate w is the world angular velocity w q e_i.
                let l = self.angular_momentum();
                for (axis, share) in [(0, 0.5), (1, 0.5), (2, 1.0), (1, 0.5), (0, 0.5)] {
                    let q = self.orientation.normalize();
                    let rate = (q.inverse() * l)[axis] / self.inertia[axis];
                    let e = Vec3::AXES[axis];
                    self.orientation =
                        orientation_step(self.orientation, q * (rate * e), share * dt, orientation);
                }
                let q = self.orientation.normalize();
                self.omega_body = (q.inverse() * l) / self.inertia;
            }
            AngularStep::Explicit | AngularStep::Implicit => {
                let implicit = angular == AngularStep::Implicit;
                self.omega_body = gyroscopic_step(self.inertia, self.omega_body, dt, implicit);
                let omega = self.omega_world();
                self.orientation = orientation_step(self.orientation, omega, dt, orientation);
            }
        }
    }

    /// Whether every number of the state is finite.
    pub fn is_finite(&self) -> bool {
        self.position.is_finite()
            && self.orientation.is_finite()
            && self.velocity.is_finite()
            && self.omega_body.is_finite()
    }
}
