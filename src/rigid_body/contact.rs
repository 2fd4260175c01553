//! Contacts between spheres, boxes and the ground plane `y = 0`, resolved by sequential impulses.
//!
//! **Detection** finds contact points with a normal and a depth (positive when the shapes
//! overlap): a sphere against the ground, a sphere or a box's corners against the ground, two
//! spheres, a sphere against a box (its closest point), and two boxes by their corners: every
//! corner of one box that lies inside the other touches the face it is least deep behind. That
//! corner test misses edge-on-edge crossings; it is what resting boxes, stacks and dominoes need.
//! Contacts are also kept a little before the shapes touch (within [`MARGIN_M`]), so that a body
//! at rest keeps its contacts from one step to the next.
//!
//! **Resolution** (after Catto's sequential impulses): each step, gravity changes the velocities,
//! then every contact in turn gets the impulse along its normal that stops the bodies from
//! approaching there, clamped so that the total impulse of the step only pushes, never pulls
//! (`λ ≥ 0`); two friction impulses in the contact plane oppose the sliding, clamped to
//! Coulomb's cone `|λ_t| ≤ μ λ`. The loop over all contacts runs a fixed number of times, each
//! pass correcting what the others changed. A small depth correction (Baumgarte's term,
//! `β (depth − slop) / dt`) pushes overlapping bodies apart over a few steps, and a contact still
//! apart lets the bodies approach by the gap (a speculative contact). After the loop, a contact
//! that pushed and was approaching faster than [`BOUNCE_THRESHOLD`] before gravity acted this
//! step gets the separating speed `e` times that approach speed (restitution, as Box2D applies
//! it). Then the positions and orientations move with the new velocities. The broad phase tries
//! every pair: a world of a few dozen bodies.

use super::{gyroscopic_step, orientation_step, OrientationStep, RigidBody};
use crate::boids::grid::Grid;
use glam::{Mat3, Vec3};

/// What a body is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Sphere {
        radius: f32,
    },
    /// A box with these half-extents along its own axes.
    Cuboid {
        half: Vec3,
    },
}

/// Contacts are kept while the shapes are closer than this (metres), before they touch.
pub const MARGIN_M: f32 = 0.01;
/// Overlap left alone by the depth correction (metres): correcting it all would make resting
/// contacts come and go.
pub const SLOP_M: f32 = 0.002;
/// The share of the overlap beyond the slop corrected per step.
pub const BAUMGARTE: f32 = 0.2;
/// Below this approach speed (m/s) a contact does not bounce: resting contacts stay at rest.
pub const BOUNCE_THRESHOLD: f32 = 0.2;
/// Largest number of bodies a world holds, and of solver passes a step makes.
pub const MAX_BODIES: usize = 4096;
pub const MAX_ITERATIONS: usize = 100;

/// One contact: bodies `a` and `b` (`None`: the ground), the world point, the normal pointing
/// from `b` towards `a` (the direction that pushes `a` out), and the depth of overlap (negative
/// when the shapes are still apart, within the margin).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    pub a: usize,
    pub b: Option<usize>,
    pub point: Vec3,
    pub normal: Vec3,
    pub depth: f32,
}

/// The corners of a box.
pub fn corners(body: &RigidBody, half: Vec3) -> [Vec3; 8] {
    let r = Mat3::from_quat(body.orientation.normalize());
    std::array::from_fn(|i| {
        let s = Vec3::new(
            if i & 1 == 0 { -1.0 } else { 1.0 },
            if i & 2 == 0 { -1.0 } else { 1.0 },
            if i & 4 == 0 { -1.0 } else { 1.0 },
        );
        body.position + r * (s * half)
    })
}

/// The contacts of body `i` with the ground plane.
fn ground_contacts(i: usize, body: &RigidBody, shape: Shape, out: &mut Vec<Contact>) {
    match shape {
        Shape::Sphere { radius } => {
            let depth = radius - body.position.y;
            if depth > -MARGIN_M {
                out.push(Contact {
                    a: i,
                    b: None,
                    point: body.position - radius * Vec3::Y,
                    normal: Vec3::Y,
                    depth,
                });
            }
        }
        Shape::Cuboid { half } => {
            for c in corners(body, half) {
                if c.y < MARGIN_M {
                    out.push(Contact {
                        a: i,
                        b: None,
                        point: c,
                        normal: Vec3::Y,
                        depth: -c.y,
                    });
                }
            }
        }
    }
}

/// Where `p` lies against the box `body` of half-extents `half`: the closest point of the box
/// (world), and, when `p` is inside, the outward normal of the face it is least deep behind and
/// that depth.
fn against_box(body: &RigidBody, half: Vec3, p: Vec3) -> (Vec3, Option<(Vec3, f32)>) {
    let q = body.orientation.normalize();
    let local = q.inverse() * (p - body.position);
    let clamped = local.clamp(-half, half);
    let closest = body.position + q * clamped;
    if clamped != local {
        return (closest, None);
    }
    let room = half - local.abs();
    let axis = if room.x <= room.y && room.x <= room.z {
        0
    } else if room.y <= room.z {
        1
    } else {
        2
    };
    let mut n = Vec3::ZERO;
    n[axis] = if local[axis] >= 0.0 { 1.0 } else { -1.0 };
    (closest, Some((q * n, room[axis])))
}

/// The contacts between bodies `i` and `j`.
fn pair_contacts(i: usize, j: usize, bodies: &[(RigidBody, Shape)], out: &mut Vec<Contact>) {
    let (a, sa) = bodies[i];
    let (b, sb) = bodies[j];
    match (sa, sb) {
        (Shape::Sphere { radius: ra }, Shape::Sphere { radius: rb }) => {
            let d = a.position - b.position;
            let dist = d.length();
            let depth = ra + rb - dist;
            if depth > -MARGIN_M && dist > 1e-9 {
                let n = d / dist;
                out.push(Contact {
                    a: i,
                    b: Some(j),
                    point: b.position + n * (rb - 0.5 * depth),
                    normal: n,
                    depth,
                });
            }
        }
        (Shape::Sphere { radius }, Shape::Cuboid { half }) => {
            sphere_box(i, &a, radius, j, &b, half, out)
        }
        (Shape::Cuboid { half }, Shape::Sphere { radius }) => {
            sphere_box(j, &b, radius, i, &a, half, out)
        }
        (Shape::Cuboid { half: ha }, Shape::Cuboid { half: hb }) => {
            // Corners of each box inside (or just outside) the other, against the face of the
            // other that faces the first box's centre most (as SAT picks a reference face): a
            // box resting on another touches its top face, even at corners that lie as deep
            // behind a side face.
            for (x, hx, y, hy, ix, iy) in [(&a, ha, &b, hb, i, j), (&b, hb, &a, ha, j, i)] {
                let q = y.orientation.normalize();
                let towards = (q.inverse() * (x.position - y.position)) / hy;
                let axis = towards.abs().max_position();
                let mut face = Vec3::ZERO;
                face[axis] = if towards[axis] >= 0.0 { 1.0 } else { -1.0 };
                let grown = hy + Vec3::splat(MARGIN_M);
                for c in corners(x, hx) {
                    let local = q.inverse() * (c - y.position);
                    if local.abs().cmple(grown).all() {
                        out.push(Contact {
                            a: ix,
                            b: Some(iy),
                            point: c,
                            normal: q * face,
                            depth: hy[axis] - face[axis] * local[axis],
                        });
                    }
                }
            }
        }
    }
}

fn sphere_box(
    s: usize,
    sphere: &RigidBody,
    radius: f32,
    k: usize,
    cuboid: &RigidBody,
    half: Vec3,
    out: &mut Vec<Contact>,
) {
    let (closest, inside) = against_box(cuboid, half, sphere.position);
    let (normal, depth) = match inside {
        // The centre inside the box: out through the nearest face.
        Some((n, room)) => (n, radius + room),
        None => {
            let d = sphere.position - closest;
            let dist = d.length();
            if dist < 1e-9 {
                return;
            }
            (d / dist, radius - dist)
        }
    };
    if depth > -MARGIN_M {
        out.push(Contact {
            a: s,
            b: Some(k),
            point: closest,
            normal,
            depth,
        });
    }
}

/// How a world finds the pairs of bodies that may touch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BroadPhase {
    /// Every pair: N (N − 1) / 2 tests.
    AllPairs,
    /// The boids' uniform grid (counting sort), with cells as wide as the largest reach of two
    /// bodies: each body is tested against the bodies of the cells around its own.
    Grid,
}

/// A world of spheres and boxes above the ground plane `y = 0`.
#[derive(Clone, Debug)]
pub struct World {
    pub bodies: Vec<(RigidBody, Shape)>,
    pub gravity: Vec3,
    /// Coefficient of restitution `e` in [0, 1], for every contact.
    pub restitution: f32,
    /// Coulomb friction coefficient `μ` (≥ 0), for every contact.
    pub friction: f32,
    /// Solver passes over the contacts per step.
    pub iterations: usize,
    pub broad_phase: BroadPhase,
    /// The grid's storage, kept between steps (a rebuild allocates nothing once it has grown).
    grid: Grid,
}

impl Default for World {
    fn default() -> Self {
        Self {
            bodies: Vec::new(),
            gravity: Vec3::new(0.0, -9.81, 0.0),
            restitution: 0.0,
            friction: 0.5,
            iterations: 20,
            broad_phase: BroadPhase::Grid,
            grid: Grid::default(),
        }
    }
}

/// One direction of a contact for the solver: the direction, its angular parts for each body
/// (`r × d`) and what a unit impulse along it does to each body's angular velocity
/// (`I⁻¹ (r × d)`), and the effective mass along it. Precomputed once per step, so a pass reads
/// only dot products.
#[derive(Clone, Copy)]
struct Axis {
    dir: Vec3,
    ang_a: Vec3,
    ang_b: Vec3,
    push_a: Vec3,
    push_b: Vec3,
    mass: f32,
}

/// A contact's state during the solver's passes: its bodies, its normal and two tangents, the
/// velocity asked for along the normal, the approach speed before the step, and the impulses
/// accumulated this step (normal, then the two tangents).
struct Row {
    a: usize,
    b: Option<usize>,
    axes: [Axis; 3],
    target: f32,
    /// The normal velocity before the solver (negative: approaching), for the bounce.
    approach: f32,
    lambda: [f32; 3],
}

impl World {
    /// Adds a body; returns its index. An error for a shape whose sizes are not positive and
    /// finite, or past [`MAX_BODIES`].
    pub fn add(&mut self, body: RigidBody, shape: Shape) -> Result<usize, String> {
        if self.bodies.len() >= MAX_BODIES {
            return Err(format!("a world holds at most {MAX_BODIES} bodies"));
        }
        let ok = match shape {
            Shape::Sphere { radius } => radius.is_finite() && radius > 0.0,
            Shape::Cuboid { half } => half.is_finite() && half.min_element() > 0.0,
        };
        if !ok {
            return Err(format!("shape sizes must be positive, got {shape:?}"));
        }
        if !body.is_finite() {
            return Err("the body's state must be finite".into());
        }
        self.bodies.push((body, shape));
        Ok(self.bodies.len() - 1)
    }

    /// Every contact at the present positions: with the ground, then between the pairs whose
    /// bounding spheres come within the margin, found by the [`BroadPhase`].
    pub fn contacts(&mut self) -> Vec<Contact> {
        let mut out = Vec::new();
        let reach = |s: Shape| match s {
            Shape::Sphere { radius } => radius,
            Shape::Cuboid { half } => half.length(),
        };
        for (i, &(body, shape)) in self.bodies.iter().enumerate() {
            ground_contacts(i, &body, shape, &mut out);
        }
        let near = |bodies: &[(RigidBody, Shape)], i: usize, j: usize| {
            let (a, sa) = bodies[i];
            let (b, sb) = bodies[j];
            a.position.distance(b.position) < reach(sa) + reach(sb) + MARGIN_M
        };
        let n = self.bodies.len();
        match self.broad_phase {
            BroadPhase::AllPairs => {
                for i in 0..n {
                    for j in i + 1..n {
                        if near(&self.bodies, i, j) {
                            pair_contacts(i, j, &self.bodies, &mut out);
                        }
                    }
                }
            }
            BroadPhase::Grid if n > 1 => {
                let positions: Vec<Vec3> = self.bodies.iter().map(|(b, _)| b.position).collect();
                let widest = self
                    .bodies
                    .iter()
                    .map(|&(_, s)| reach(s))
                    .fold(0.0, f32::max);
                let radius = 2.0 * widest + MARGIN_M;
                let (lo, hi) = positions.iter().fold(
                    (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
                    |(lo, hi), p| (lo.min(*p), hi.max(*p)),
                );
                self.grid.configure(lo, hi, radius);
                self.grid.rebuild(&positions);
                // In increasing pair order, as the all-pairs loop finds them: the solver's
                // result does not depend on the broad phase. Each body's later neighbours,
                // smallest index first, through the crate's one float sort (an index below
                // [`MAX_BODIES`] is exact as an `f32`).
                let mut later: Vec<(f32, u32)> = Vec::new();
                for i in 0..n {
                    later.clear();
                    self.grid.for_each_neighbour(&positions, i, radius, |j| {
                        if j > i {
                            later.push((-(j as f32), j as u32));
                        }
                    });
                    crate::order::sort_desc(&mut later);
                    for &(_, j) in &later {
                        let j = j as usize;
                        if near(&self.bodies, i, j) {
                            pair_contacts(i, j, &self.bodies, &mut out);
                        }
                    }
                }
            }
            BroadPhase::Grid => {}
        }
        out
    }

    /// One step of `dt` seconds (see the module's description). An error, leaving the world as
    /// it was, for a `dt` that is not in (0, 0.1] s, parameters out of range, or a step that
    /// leaves a state that is not finite.
    pub fn step(&mut self, dt: f32) -> Result<(), String> {
        if !(dt.is_finite() && dt > 0.0 && dt <= 0.1) {
            return Err(format!("time step must be in (0, 0.1] s, got {dt}"));
        }
        if !(0.0..=1.0).contains(&self.restitution) {
            return Err(format!(
                "restitution must be in [0, 1], got {}",
                self.restitution
            ));
        }
        if !(self.friction.is_finite() && self.friction >= 0.0) {
            return Err(format!("friction must be 0 or more, got {}", self.friction));
        }
        if !(1..=MAX_ITERATIONS).contains(&self.iterations) {
            return Err(format!(
                "iterations must be 1 to {MAX_ITERATIONS}, got {}",
                self.iterations
            ));
        }
        if !self.gravity.is_finite() {
            return Err("gravity must be finite".into());
        }
        let before = self.bodies.clone();
        // World angular velocities and inverse inertias for the solver; the contacts' approach
        // speeds are read before gravity acts this step (a bounce returns the speed the body
        // arrived with, not that plus one step of gravity).
        let omega: Vec<Vec3> = self.bodies.iter().map(|(b, _)| b.omega_world()).collect();
        let inv_inertia: Vec<Mat3> = self
            .bodies
            .iter()
            .map(|(b, _)| b.world_inverse_inertia())
            .collect();
        let inv_mass: Vec<f32> = self.bodies.iter().map(|(b, _)| 1.0 / b.mass).collect();
        let contacts = self.contacts();
        let mut rows: Vec<Row> = contacts
            .iter()
            .map(|c| {
                let (a, _) = &self.bodies[c.a];
                let ra = c.point - a.position;
                let rb =
                    c.b.map_or(Vec3::ZERO, |b| c.point - self.bodies[b].0.position);
                let axis = |d: Vec3| {
                    let (ang_a, ang_b) = (ra.cross(d), rb.cross(d));
                    let push_a = inv_inertia[c.a] * ang_a;
                    let mut k = inv_mass[c.a] + ang_a.dot(push_a);
                    let push_b = match c.b {
                        Some(b) => {
                            let push = inv_inertia[b] * ang_b;
                            k += inv_mass[b] + ang_b.dot(push);
                            push
                        }
                        None => Vec3::ZERO,
                    };
                    Axis {
                        dir: d,
                        ang_a,
                        ang_b,
                        push_a,
                        push_b,
                        mass: 1.0 / k,
                    }
                };
                let t1 = c.normal.any_orthonormal_vector();
                let t2 = c.normal.cross(t1);
                let relative = self.bodies[c.a].0.velocity + omega[c.a].cross(ra)
                    - c.b.map_or(Vec3::ZERO, |b| {
                        self.bodies[b].0.velocity + omega[b].cross(rb)
                    });
                let approach = relative.dot(c.normal);
                let target = if c.depth > SLOP_M {
                    BAUMGARTE * (c.depth - SLOP_M) / dt
                } else if c.depth < 0.0 {
                    // Still apart: the bodies may approach by what closes the gap this step.
                    c.depth / dt
                } else {
                    0.0
                };
                Row {
                    a: c.a,
                    b: c.b,
                    axes: [axis(c.normal), axis(t1), axis(t2)],
                    target,
                    approach,
                    lambda: [0.0; 3],
                }
            })
            .collect();
        // Velocities: gravity, and the gyroscopic term (implicit, so it cannot add energy).
        for (body, _) in &mut self.bodies {
            body.velocity += self.gravity * dt;
            body.omega_body = gyroscopic_step(body.inertia, body.omega_body, dt, true);
        }
        let mut omega: Vec<Vec3> = self.bodies.iter().map(|(b, _)| b.omega_world()).collect();
        let mut velocity: Vec<Vec3> = self.bodies.iter().map(|(b, _)| b.velocity).collect();
        // The relative speed along axis `k` of a row, and an impulse `l` along it.
        let speed = |velocity: &[Vec3], omega: &[Vec3], row: &Row, k: usize| {
            let x = &row.axes[k];
            let mut v = x.dir.dot(velocity[row.a]) + x.ang_a.dot(omega[row.a]);
            if let Some(b) = row.b {
                v -= x.dir.dot(velocity[b]) + x.ang_b.dot(omega[b]);
            }
            v
        };
        let push = |velocity: &mut [Vec3], omega: &mut [Vec3], row: &Row, k: usize, l: f32| {
            let x = &row.axes[k];
            velocity[row.a] += (inv_mass[row.a] * l) * x.dir;
            omega[row.a] += l * x.push_a;
            if let Some(b) = row.b {
                velocity[b] -= (inv_mass[b] * l) * x.dir;
                omega[b] -= l * x.push_b;
            }
        };
        for _ in 0..self.iterations {
            for row in &mut rows {
                // The normal impulse first, then friction bounded by it: the impulses start at
                // zero every step (no warm start), so friction solved first would have no bound
                // to work with in the first pass, and none at all with one pass.
                let vn = speed(&velocity, &omega, row, 0);
                let new = (row.lambda[0] - (vn - row.target) * row.axes[0].mass).max(0.0);
                let d = new - row.lambda[0];
                row.lambda[0] = new;
                push(&mut velocity, &mut omega, row, 0, d);
                let limit = self.friction * row.lambda[0];
                for k in 1..3 {
                    let vt = speed(&velocity, &omega, row, k);
                    let new = (row.lambda[k] - vt * row.axes[k].mass).clamp(-limit, limit);
                    let d = new - row.lambda[k];
                    row.lambda[k] = new;
                    push(&mut velocity, &mut omega, row, k, d);
                }
            }
        }
        // Restitution, once the contacts hold: a contact that was approaching faster than the
        // threshold and pushed this step separates at e times its approach speed.
        for row in &mut rows {
            if row.approach < -BOUNCE_THRESHOLD && row.lambda[0] > 0.0 {
                let vn = speed(&velocity, &omega, row, 0);
                let wanted = -self.restitution * row.approach;
                let new = (row.lambda[0] - (vn - wanted) * row.axes[0].mass).max(0.0);
                let d = new - row.lambda[0];
                row.lambda[0] = new;
                push(&mut velocity, &mut omega, row, 0, d);
            }
        }
        // Positions and orientations with the solved velocities.
        for (i, (body, _)) in self.bodies.iter_mut().enumerate() {
            body.velocity = velocity[i];
            body.position += velocity[i] * dt;
            body.orientation =
                orientation_step(body.orientation, omega[i], dt, OrientationStep::Exponential);
            body.omega_body = body.orientation.inverse() * omega[i];
        }
        if let Some(i) = self.bodies.iter().position(|(b, _)| !b.is_finite()) {
            self.bodies = before;
            return Err(format!(
                "body {i} left the finite numbers: the step exploded"
            ));
        }
        Ok(())
    }

    /// The total kinetic energy (J).
    pub fn kinetic_energy(&self) -> f32 {
        self.bodies.iter().map(|(b, _)| b.kinetic_energy()).sum()
    }
}

/// The scene the benchmarks and tests step: `n` bodies (`1 ≤ n ≤` [`MAX_BODIES`]), balls of
/// radius 0.2 m and boxes of 0.4 × 0.3 × 0.36 m in turn, 1 kg each, dropped in four layers 0.5 m
/// apart over a square of 0.5 m cells (a few centimetres off the grid, so they topple).
pub fn heap(n: usize) -> Result<World, String> {
    if !(1..=MAX_BODIES).contains(&n) {
        return Err(format!("a heap has 1 to {MAX_BODIES} bodies, got {n}"));
    }
    let per_row = ((n as f32 / 4.0).sqrt().ceil() as usize).max(1);
    let side = 0.5 * per_row as f32;
    let mut world = World::default();
    for k in 0..n {
        let (i, j, layer) = (
            k % per_row,
            (k / per_row) % per_row,
            k / (per_row * per_row),
        );
        let at = Vec3::new(
            -0.5 * side + 0.25 + 0.5 * i as f32 + 0.03 * (k % 7) as f32,
            0.3 + 0.5 * layer as f32,
            -0.5 * side + 0.25 + 0.5 * j as f32,
        );
        let (inertia, shape) = if k % 2 == 0 {
            (
                super::inertia::solid_sphere(1.0, 0.2),
                Shape::Sphere { radius: 0.2 },
            )
        } else {
            let half = Vec3::new(0.2, 0.15, 0.18);
            (super::inertia::solid_box(1.0, half), Shape::Cuboid { half })
        };
        let mut body = RigidBody::new(
            1.0,
            Vec3::new(inertia.x_axis.x, inertia.y_axis.y, inertia.z_axis.z),
        )?;
        body.position = at;
        world.add(body, shape)?;
    }
    Ok(world)
}
