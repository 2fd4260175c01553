//! Lesson 13 core, "Cloth": a rectangular grid of particles joined by springs (mass-spring) or by
//! distance constraints (XPBD), with gravity, wind, pins, a dragged particle and collisions with
//! the ground, a sphere and a box.
//!
//! - [`Cloth`]: the particles in structure-of-arrays form (positions, velocities, inverse masses),
//!   the springs (structural, shear, bending), the triangles and per-vertex normals (recomputed in
//!   place, no allocation after [`Cloth::new`]). At most [`MAX_SIDE`] particles per side.
//! - [`Cloth::step`]: one frame of `dt` seconds split into [`ClothParams::substeps`] substeps,
//!   with [`Method::MassSpring`] (forces, then the particles core's semi-implicit Euler step,
//!   [`crate::particles::semi_implicit_euler_step`]) or [`Method::Xpbd`] (predict, project the
//!   constraints with compliance, derive the velocities).
//! - The stability limit of the mass-spring step: [`Cloth::stable_substep_estimate`]; a step past
//!   it makes the cloth explode, which [`Cloth::step`] detects ([`Cloth::exploded`]) and after
//!   which it stops moving until [`Cloth::reset`].
//! - No self-collision: the cloth passes through itself (the lesson says so).
//!
//! Conventions as in the crate root: Y up, metres, seconds, kilograms; gravity `(0, −9.81, 0)`.
//! Lesson: lessons/13-cloth.

use crate::particles::semi_implicit_euler_step;
use glam::Vec3;

/// The most particles per side of a cloth (65,536 particles, about 390,000 springs). The cost of a
/// step and the memory grow with columns × rows.
pub const MAX_SIDE: usize = 256;
/// The most substeps per frame.
pub const MAX_SUBSTEPS: u32 = 200;
/// A cloth whose structural springs are longer than this many times their rest length (or whose
/// positions are no longer finite) has exploded.
pub const EXPLODED_STRETCH: f32 = 3.0;
/// The fastest a grabbed particle follows the pointer, m/s.
pub const GRAB_SPEED: f32 = 8.0;

/// What a caller can get wrong.
#[derive(Clone, Debug, PartialEq)]
pub enum ClothError {
    /// Columns or rows outside `[2, MAX_SIDE]`.
    Resolution { columns: i64, rows: i64 },
    /// A parameter out of its range or not finite; the message names it.
    Invalid(String),
}

impl std::fmt::Display for ClothError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ClothError::Resolution { columns, rows } => write!(
                f,
                "a cloth needs between 2 and {MAX_SIDE} particles per side, got {columns} × {rows}"
            ),
            ClothError::Invalid(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for ClothError {}

fn check(name: &str, value: f32, lo: f32, hi: f32) -> Result<f32, ClothError> {
    if value.is_finite() && value >= lo && value <= hi {
        Ok(value)
    } else {
        Err(ClothError::Invalid(format!(
            "{name} must be a finite number in [{lo}, {hi}], got {value}"
        )))
    }
}

fn check_vec(name: &str, v: Vec3, limit: f32) -> Result<Vec3, ClothError> {
    if v.is_finite() && v.abs().max_element() <= limit {
        Ok(v)
    } else {
        Err(ClothError::Invalid(format!(
            "{name} must be finite with components in [−{limit}, {limit}], got {v}"
        )))
    }
}

/// The three kinds of spring of a grid cloth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpringKind {
    /// Between neighbours along a row or a column: resists stretching.
    Structural = 0,
    /// Along both diagonals of each cell: resists shearing.
    Shear = 1,
    /// Between particles two apart along a row or a column: resists bending (folding).
    Bending = 2,
}

impl SpringKind {
    pub const ALL: [SpringKind; 3] = [
        SpringKind::Structural,
        SpringKind::Shear,
        SpringKind::Bending,
    ];

    pub fn name(self) -> &'static str {
        match self {
            SpringKind::Structural => "structural",
            SpringKind::Shear => "shear",
            SpringKind::Bending => "bending",
        }
    }
}

/// A spring (mass-spring) or distance constraint (XPBD) between particles `a` and `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spring {
    pub a: u32,
    pub b: u32,
    /// Rest length, metres.
    pub rest: f32,
    pub kind: SpringKind,
}

/// How [`Cloth::step`] advances the cloth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Spring forces and semi-implicit Euler: stable only for substeps below a limit.
    MassSpring,
    /// Extended position-based dynamics: stable for any step; stiffness as compliance.
    Xpbd,
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Method::MassSpring => "mass-spring",
            Method::Xpbd => "XPBD",
        }
    }
}

/// The material and the forces. Stiffness and damping are per spring, by [`SpringKind`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClothParams {
    /// Spring stiffness `k`, N/m, per kind (mass-spring).
    pub stiffness: [f32; 3],
    /// Spring damping `c`, N·s/m, per kind: resists the two ends' relative speed along the spring.
    pub damping: [f32; 3],
    /// XPBD compliance `α`, m/N, per kind (the inverse of a stiffness; 0 is rigid).
    pub compliance: [f32; 3],
    /// m/s².
    pub gravity: Vec3,
    /// The air's velocity, m/s.
    pub wind: Vec3,
    /// Aerodynamic coefficient `½ ρ C`, kg/m³ (air: about 0.6).
    pub drag: f32,
    pub substeps: u32,
    pub method: Method,
}

impl Default for ClothParams {
    fn default() -> Self {
        Self {
            stiffness: [100.0, 50.0, 20.0],
            damping: [0.02, 0.02, 0.01],
            compliance: [0.01, 0.02, 0.05],
            gravity: Vec3::new(0.0, -9.81, 0.0),
            wind: Vec3::ZERO,
            drag: 0.6,
            substeps: 10,
            method: Method::MassSpring,
        }
    }
}

impl ClothParams {
    /// XPBD compliances equal to the inverse stiffnesses (`α = 1/k`; 0 where `k` is 0 is not
    /// rigid but absent: the constraint is skipped, see [`Cloth::step`]).
    pub fn compliance_from_stiffness(&mut self) {
        for k in 0..3 {
            self.compliance[k] = if self.stiffness[k] > 0.0 {
                1.0 / self.stiffness[k]
            } else {
                f32::INFINITY
            };
        }
    }

    /// Every rule, each with its own message.
    pub fn validate(&self) -> Result<(), ClothError> {
        for (k, kind) in SpringKind::ALL.iter().enumerate() {
            check(
                &format!("{} stiffness", kind.name()),
                self.stiffness[k],
                0.0,
                1e7,
            )?;
            check(
                &format!("{} damping", kind.name()),
                self.damping[k],
                0.0,
                1e4,
            )?;
            let a = self.compliance[k];
            if !(a == f32::INFINITY || (a.is_finite() && a >= 0.0)) {
                return Err(ClothError::Invalid(format!(
                    "{} compliance must be ≥ 0 (or infinite: no constraint), got {a}",
                    kind.name()
                )));
            }
        }
        check_vec("gravity", self.gravity, 1000.0)?;
        check_vec("wind", self.wind, 1000.0)?;
        check("drag", self.drag, 0.0, 100.0)?;
        if !(1..=MAX_SUBSTEPS).contains(&self.substeps) {
            return Err(ClothError::Invalid(format!(
                "substeps must be between 1 and {MAX_SUBSTEPS}, got {}",
                self.substeps
            )));
        }
        Ok(())
    }
}

/// What the cloth collides with. Particles are kept `thickness` away from every surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Colliders {
    /// The ground plane's height, metres.
    pub ground_y: Option<f32>,
    /// Centre and radius.
    pub sphere: Option<(Vec3, f32)>,
    /// An axis-aligned box: centre and half extents.
    pub cuboid: Option<(Vec3, Vec3)>,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub friction: f32,
    /// Metres.
    pub thickness: f32,
}

impl Default for Colliders {
    fn default() -> Self {
        Self {
            ground_y: Some(0.0),
            sphere: None,
            cuboid: None,
            friction: 0.3,
            thickness: 0.01,
        }
    }
}

impl Colliders {
    pub fn validate(&self) -> Result<(), ClothError> {
        if let Some(y) = self.ground_y {
            check("ground height", y, -1e4, 1e4)?;
        }
        if let Some((c, r)) = self.sphere {
            check_vec("sphere centre", c, 1e4)?;
            check("sphere radius", r, 0.0, 1e4)?;
        }
        if let Some((c, h)) = self.cuboid {
            check_vec("box centre", c, 1e4)?;
            check_vec("box half extents", h, 1e4)?;
            if h.min_element() < 0.0 {
                return Err(ClothError::Invalid("box half extents must be ≥ 0".into()));
            }
        }
        check("friction", self.friction, 0.0, 10.0)?;
        check("thickness", self.thickness, 0.0, 1.0)?;
        Ok(())
    }

    /// The deepest contact of a point: `(outward unit normal, penetration depth > 0)`, or `None`
    /// when the point is outside every collider (grown by the thickness).
    pub fn contact(&self, p: Vec3) -> Option<(Vec3, f32)> {
        let mut best: Option<(Vec3, f32)> = None;
        let mut consider = |n: Vec3, d: f32| {
            if d > 0.0 && best.is_none_or(|(_, b)| d > b) {
                best = Some((n, d));
            }
        };
        let t = self.thickness;
        if let Some(y) = self.ground_y {
            consider(Vec3::Y, y + t - p.y);
        }
        if let Some((c, r)) = self.sphere {
            let d = p - c;
            let l = d.length();
            let n = if l > 1e-9 { d / l } else { Vec3::Y };
            consider(n, r + t - l);
        }
        if let Some((c, h)) = self.cuboid {
            let d = p - c;
            let inside = h + Vec3::splat(t) - d.abs();
            if inside.min_element() > 0.0 {
                // Out through the nearest face.
                let axis = if inside.x <= inside.y && inside.x <= inside.z {
                    0
                } else if inside.y <= inside.z {
                    1
                } else {
                    2
                };
                let mut n = Vec3::ZERO;
                n[axis] = if d[axis] >= 0.0 { 1.0 } else { -1.0 };
                consider(n, inside[axis]);
            }
        }
        best
    }
}

/// The force spring `(a, b)` puts on particle `a` (the opposite acts on `b`): Hooke's law plus
/// damping of the relative speed along the spring,
/// ```text
/// d = pb − pa,  l = |d|,  n = d / l
/// f_a = (k (l − rest) + c (vb − va)·n) n
/// ```
/// Zero when the two particles coincide (no direction). Exercise 13.1.
#[inline]
pub fn spring_force(pa: Vec3, pb: Vec3, va: Vec3, vb: Vec3, k: f32, c: f32, rest: f32) -> Vec3 {
    let d = pb - pa;
    let l = d.length();
    if l <= 1e-12 {
        return Vec3::ZERO;
    }
    let n = d / l;
    (k * (l - rest) + c * (vb - va).dot(n)) * n
}

/// One semi-implicit Euler step of a particle with inverse mass `w` (0: pinned, unmoved by
/// forces) under the force `f`: `v' = v + w f dt`, `p' = p + v' dt`. The particles core's step
/// with `a = w f`. Exercise 13.2.
#[inline]
pub fn particle_step(p: &mut Vec3, v: &mut Vec3, f: Vec3, w: f32, dt: f32) {
    semi_implicit_euler_step(p, v, f * w, dt);
}

/// Projects one XPBD distance constraint `C = |pb − pa| − rest` with compliance `α` (m/N) over a
/// substep `dt`, starting from `λ = 0` (one iteration per substep):
/// ```text
/// α̃ = α / dt²,  Δλ = −C / (wa + wb + α̃)
/// pa' = pa − wa Δλ n,   pb' = pb + wb Δλ n,   n = (pb − pa) / |pb − pa|
/// ```
/// `α = 0` makes the constraint exact (rigid). Unchanged when both ends are pinned, when `α` is
/// infinite, or when the particles coincide. Exercise 13.3.
#[inline]
pub fn project_distance(
    pa: &mut Vec3,
    pb: &mut Vec3,
    wa: f32,
    wb: f32,
    rest: f32,
    compliance: f32,
    dt: f32,
) {
    let d = *pb - *pa;
    let l = d.length();
    let alpha = if dt > 0.0 {
        compliance / (dt * dt)
    } else {
        f32::INFINITY
    };
    let denominator = wa + wb + alpha;
    // Not finite covers NaN as well as an infinite compliance.
    if l <= 1e-12 || denominator <= 0.0 || !denominator.is_finite() {
        return;
    }
    let n = d / l;
    let dlambda = -(l - rest) / denominator;
    *pa -= wa * dlambda * n;
    *pb += wb * dlambda * n;
}

/// Where the cloth starts: `columns × rows` particles on the rectangle from `origin`, `width_m`
/// along `across` and `height_m` along `down` (both unit vectors, perpendicular), `mass_kg` spread
/// evenly over the particles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClothSpec {
    /// Particles per row; signed so that a negative request can be reported.
    pub columns: i64,
    /// Particles per column.
    pub rows: i64,
    pub width_m: f32,
    pub height_m: f32,
    pub mass_kg: f32,
    pub origin: Vec3,
    pub across: Vec3,
    pub down: Vec3,
}

impl ClothSpec {
    /// A square cloth of `side` × `side` particles, 2 m wide, lying level at height `y`, centred
    /// above the origin.
    pub fn level(side: i64, y: f32) -> Self {
        Self {
            columns: side,
            rows: side,
            width_m: 2.0,
            height_m: 2.0,
            mass_kg: 0.5,
            origin: Vec3::new(-1.0, y, -1.0),
            across: Vec3::X,
            down: Vec3::Z,
        }
    }

    pub fn validate(&self) -> Result<(usize, usize), ClothError> {
        let side = 2..=MAX_SIDE as i64;
        if !side.contains(&self.columns) || !side.contains(&self.rows) {
            return Err(ClothError::Resolution {
                columns: self.columns,
                rows: self.rows,
            });
        }
        check("width", self.width_m, 1e-3, 1e3)?;
        check("height", self.height_m, 1e-3, 1e3)?;
        check("mass", self.mass_kg, 1e-6, 1e6)?;
        check_vec("origin", self.origin, 1e4)?;
        for (name, v) in [("across", self.across), ("down", self.down)] {
            check_vec(name, v, 2.0)?;
            if (v.length() - 1.0).abs() > 1e-3 {
                return Err(ClothError::Invalid(format!(
                    "{name} must be a unit vector, got {v}"
                )));
            }
        }
        if self.across.dot(self.down).abs() > 1e-3 {
            return Err(ClothError::Invalid(
                "across and down must be perpendicular".into(),
            ));
        }
        Ok((self.columns as usize, self.rows as usize))
    }
}

/// A grid cloth. Particle `(c, r)` (column, row) has index `r · columns + c`.
#[derive(Clone, Debug)]
pub struct Cloth {
    pub columns: usize,
    pub rows: usize,
    /// Metres.
    pub positions: Vec<Vec3>,
    /// m/s.
    pub velocities: Vec<Vec3>,
    /// 1 / mass, 1/kg; 0 for a pinned particle.
    pub inv_mass: Vec<f32>,
    /// Unit normals, one per particle (area-weighted average of the triangles around it).
    pub normals: Vec<Vec3>,
    pub springs: Vec<Spring>,
    /// Counter-clockwise seen from the side `across × down` points to.
    pub triangles: Vec<[u32; 3]>,
    /// Mass of one particle, kg.
    pub particle_mass: f32,
    /// Seconds simulated since the start (or the last reset).
    pub time_sec: f32,
    /// A particle held at a point (dragged with the mouse): `(index, target)`.
    pub grab: Option<(usize, Vec3)>,
    exploded_at: Option<f32>,
    start: Vec<Vec3>,
    pinned: Vec<bool>,
    forces: Vec<Vec3>,
    previous: Vec<Vec3>,
}

impl Cloth {
    /// The particles of `spec` at rest, with springs of every kind at their rest lengths; nothing
    /// pinned.
    pub fn new(spec: &ClothSpec) -> Result<Self, ClothError> {
        let (nc, nr) = spec.validate()?;
        let n = nc * nr;
        let dx = spec.width_m / (nc - 1) as f32;
        let dy = spec.height_m / (nr - 1) as f32;
        let positions: Vec<Vec3> = (0..n)
            .map(|i| {
                let (c, r) = (i % nc, i / nc);
                spec.origin + spec.across * (c as f32 * dx) + spec.down * (r as f32 * dy)
            })
            .collect();
        let index = |c: usize, r: usize| (r * nc + c) as u32;
        let mut springs = Vec::with_capacity(6 * n);
        let mut add = |a: u32, b: u32, kind: SpringKind| {
            let rest = (positions[b as usize] - positions[a as usize]).length();
            springs.push(Spring { a, b, rest, kind });
        };
        for r in 0..nr {
            for c in 0..nc {
                if c + 1 < nc {
                    add(index(c, r), index(c + 1, r), SpringKind::Structural);
                }
                if r + 1 < nr {
                    add(index(c, r), index(c, r + 1), SpringKind::Structural);
                }
            }
        }
        for r in 0..nr - 1 {
            for c in 0..nc - 1 {
                add(index(c, r), index(c + 1, r + 1), SpringKind::Shear);
                add(index(c + 1, r), index(c, r + 1), SpringKind::Shear);
            }
        }
        for r in 0..nr {
            for c in 0..nc {
                if c + 2 < nc {
                    add(index(c, r), index(c + 2, r), SpringKind::Bending);
                }
                if r + 2 < nr {
                    add(index(c, r), index(c, r + 2), SpringKind::Bending);
                }
            }
        }
        let mut triangles = Vec::with_capacity(2 * (nc - 1) * (nr - 1));
        for r in 0..nr - 1 {
            for c in 0..nc - 1 {
                let (a, b, d, e) = (
                    index(c, r),
                    index(c + 1, r),
                    index(c, r + 1),
                    index(c + 1, r + 1),
                );
                // Alternate the diagonal so the mesh has no preferred direction.
                if (c + r) % 2 == 0 {
                    triangles.push([a, b, d]);
                    triangles.push([b, e, d]);
                } else {
                    triangles.push([a, e, d]);
                    triangles.push([a, b, e]);
                }
            }
        }
        let particle_mass = spec.mass_kg / n as f32;
        let mut cloth = Self {
            columns: nc,
            rows: nr,
            velocities: vec![Vec3::ZERO; n],
            inv_mass: vec![1.0 / particle_mass; n],
            normals: vec![Vec3::ZERO; n],
            springs,
            triangles,
            particle_mass,
            time_sec: 0.0,
            grab: None,
            exploded_at: None,
            start: positions.clone(),
            pinned: vec![false; n],
            forces: vec![Vec3::ZERO; n],
            previous: positions.clone(),
            positions,
        };
        cloth.update_normals();
        Ok(cloth)
    }

    pub fn len(&self) -> usize {
        self.positions.len()
    }

    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// The index of particle `(column, row)`.
    pub fn index(&self, column: usize, row: usize) -> usize {
        row * self.columns + column
    }

    /// Pins (or frees) particle `i`: a pinned particle has inverse mass 0 and never moves.
    pub fn set_pinned(&mut self, i: usize, pinned: bool) {
        if i < self.len() {
            self.pinned[i] = pinned;
            self.inv_mass[i] = if pinned {
                0.0
            } else {
                1.0 / self.particle_mass
            };
            if pinned {
                self.velocities[i] = Vec3::ZERO;
            }
        }
    }

    pub fn is_pinned(&self, i: usize) -> bool {
        self.pinned[i]
    }

    /// Frees every particle.
    pub fn unpin_all(&mut self) {
        for i in 0..self.len() {
            self.set_pinned(i, false);
        }
    }

    /// Back to the starting positions at rest (pins kept), time 0, not exploded, nothing grabbed.
    pub fn reset(&mut self) {
        self.positions.copy_from_slice(&self.start);
        self.velocities.fill(Vec3::ZERO);
        self.time_sec = 0.0;
        self.exploded_at = None;
        self.grab = None;
        self.update_normals();
    }

    /// When the cloth exploded (seconds), if it did: a position stopped being finite or a
    /// structural spring grew past [`EXPLODED_STRETCH`] times its rest length. An exploded cloth
    /// no longer moves until [`Cloth::reset`].
    pub fn exploded(&self) -> Option<f32> {
        self.exploded_at
    }

    /// The largest relative stretch `l / rest − 1` over the structural springs (0 at rest).
    pub fn max_stretch(&self) -> f32 {
        self.springs
            .iter()
            .filter(|s| s.kind == SpringKind::Structural)
            .map(|s| {
                (self.positions[s.b as usize] - self.positions[s.a as usize]).length() / s.rest
                    - 1.0
            })
            .fold(
                0.0,
                |m, x| if x.is_nan() { f32::INFINITY } else { m.max(x) },
            )
    }

    /// Total energy, joules: kinetic `Σ ½ m v²`, gravitational `Σ −m g·p` and elastic
    /// (mass-spring: `Σ ½ k (l − rest)²`; XPBD: `Σ ½ C² / α` over constraints with `α > 0`).
    /// Pinned particles count for nothing.
    pub fn energy(&self, params: &ClothParams) -> f32 {
        let m = self.particle_mass;
        let mut e = 0.0f64;
        for i in 0..self.len() {
            if !self.pinned[i] {
                let (p, v) = (self.positions[i], self.velocities[i]);
                e += (0.5 * m * v.length_squared() - m * params.gravity.dot(p)) as f64;
            }
        }
        for s in &self.springs {
            let k = match params.method {
                Method::MassSpring => params.stiffness[s.kind as usize],
                Method::Xpbd => {
                    let a = params.compliance[s.kind as usize];
                    if a > 0.0 {
                        1.0 / a
                    } else {
                        0.0
                    }
                }
            };
            let c = (self.positions[s.b as usize] - self.positions[s.a as usize]).length() - s.rest;
            e += (0.5 * k * c * c) as f64;
        }
        e as f32
    }

    /// A conservative estimate of the largest stable mass-spring substep, seconds (damping
    /// ignored): the stiffest particle's `√(2 m / Σk)`, where `Σk` sums the stiffness of the
    /// springs attached to it. From Gershgorin's bound `ω² ≤ 2 Σk / m` on the highest frequency of
    /// the spring network and semi-implicit Euler's limit `ω h < 2`.
    pub fn stable_substep_estimate(&self, params: &ClothParams) -> f32 {
        // Σk of an interior particle: 4 springs of each kind.
        let total: f32 = params.stiffness.iter().map(|k| 4.0 * k).sum();
        let total = total.max(1e-12);
        (2.0 * self.particle_mass / total).sqrt()
    }

    /// Recomputes [`Cloth::normals`] from the positions, in place.
    pub fn update_normals(&mut self) {
        self.normals.fill(Vec3::ZERO);
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| i as usize);
            let n = (self.positions[b] - self.positions[a])
                .cross(self.positions[c] - self.positions[a]);
            self.normals[a] += n;
            self.normals[b] += n;
            self.normals[c] += n;
        }
        for n in &mut self.normals {
            *n = n.normalize_or(Vec3::Y);
        }
    }

    /// Advances by one frame of `dt` seconds in `params.substeps` substeps. `dt = 0` changes
    /// nothing. An exploded cloth is left as it is. Allocates nothing.
    pub fn step(
        &mut self,
        params: &ClothParams,
        colliders: &Colliders,
        dt: f32,
    ) -> Result<(), ClothError> {
        check("dt", dt, 0.0, 1.0)?;
        params.validate()?;
        colliders.validate()?;
        if let Some((i, target)) = self.grab {
            if i >= self.len() {
                return Err(ClothError::Invalid(format!(
                    "grabbed particle {i} does not exist (the cloth has {})",
                    self.len()
                )));
            }
            check_vec("grab target", target, 1e4)?;
        }
        if dt == 0.0 || self.exploded_at.is_some() {
            return Ok(());
        }
        let h = dt / params.substeps as f32;
        for _ in 0..params.substeps {
            match params.method {
                Method::MassSpring => self.substep_mass_spring(params, colliders, h),
                Method::Xpbd => self.substep_xpbd(params, colliders, h),
            }
            self.time_sec += h;
        }
        if params.method == Method::Xpbd {
            self.damp_constraints(params, dt);
        }
        // Checked once per frame: an exploding cloth only gets worse within a frame.
        self.check_explosion();
        self.update_normals();
        Ok(())
    }

    fn check_explosion(&mut self) -> bool {
        let finite = self.positions.iter().all(|p| p.is_finite());
        if !finite || self.max_stretch() > EXPLODED_STRETCH - 1.0 {
            self.exploded_at = Some(self.time_sec);
            return true;
        }
        false
    }

    /// Gravity and wind into `forces` (newtons). Wind acts per triangle: with `v_rel` the air's
    /// velocity relative to the triangle, `n` its unit normal and `A` its area, the force
    /// `drag · A · (n·v_rel) |v_rel| n` is shared equally by its three corners.
    fn external_forces(&mut self, params: &ClothParams) {
        let weight = params.gravity * self.particle_mass;
        self.forces.fill(weight);
        if params.drag == 0.0 {
            return;
        }
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| i as usize);
            let (pa, pb, pc) = (self.positions[a], self.positions[b], self.positions[c]);
            let v = (self.velocities[a] + self.velocities[b] + self.velocities[c]) / 3.0;
            let relative = params.wind - v;
            let cross = (pb - pa).cross(pc - pa); // |cross| = 2 A
            let length = cross.length();
            if length <= 1e-12 {
                continue;
            }
            let n = cross / length;
            let f = params.drag * 0.5 * length * n.dot(relative) * relative.length() * n;
            let share = f / 3.0;
            self.forces[a] += share;
            self.forces[b] += share;
            self.forces[c] += share;
        }
    }

    /// Moves the grabbed particle towards its target, at most [`GRAB_SPEED`] m/s (a pointer can
    /// jump; a particle thrown across the cloth in one substep would tear it), and gives it the
    /// velocity of that move.
    fn hold_grab(&mut self, start: Vec3, h: f32) {
        if let Some((i, target)) = self.grab {
            let step = (target - start).clamp_length_max(GRAB_SPEED * h);
            self.positions[i] = start + step;
            self.velocities[i] = if h > 0.0 { step / h } else { Vec3::ZERO };
        }
    }

    fn substep_mass_spring(&mut self, params: &ClothParams, colliders: &Colliders, h: f32) {
        let grab_start = self.grab.map(|(i, _)| self.positions[i]);
        self.external_forces(params);
        for s in &self.springs {
            let (a, b) = (s.a as usize, s.b as usize);
            let k = s.kind as usize;
            let f = spring_force(
                self.positions[a],
                self.positions[b],
                self.velocities[a],
                self.velocities[b],
                params.stiffness[k],
                params.damping[k],
                s.rest,
            );
            self.forces[a] += f;
            self.forces[b] -= f;
        }
        for i in 0..self.positions.len() {
            if self.pinned[i] {
                continue;
            }
            particle_step(
                &mut self.positions[i],
                &mut self.velocities[i],
                self.forces[i],
                self.inv_mass[i],
                h,
            );
            if let Some((n, depth)) = colliders.contact(self.positions[i]) {
                self.positions[i] += depth * n;
                let vn = self.velocities[i].dot(n);
                if vn < 0.0 {
                    // Stop the motion into the surface; friction takes up to μ |vn| off the
                    // sliding speed.
                    let tangential = self.velocities[i] - vn * n;
                    let speed = tangential.length();
                    let keep = if speed > 0.0 {
                        (1.0 - colliders.friction * -vn / speed).max(0.0)
                    } else {
                        0.0
                    };
                    self.velocities[i] = tangential * keep;
                }
            }
        }
        if let Some(start) = grab_start {
            self.hold_grab(start, h);
        }
    }

    /// XPBD damping along each constraint, once per frame of `dt` seconds (a pass over the
    /// springs per substep would cost as much as the projection itself), implicit so that it is
    /// stable for any `c`: the two ends' relative speed along the constraint is divided by
    /// `1 + c dt (wa + wb)`. The grabbed particle keeps the speed of the pointer.
    fn damp_constraints(&mut self, params: &ClothParams, dt: f32) {
        let h = dt;
        let grabbed = self.grab.map(|(i, _)| (i, self.velocities[i]));
        for s in &self.springs {
            let c = params.damping[s.kind as usize];
            if c == 0.0 {
                continue;
            }
            let (a, b) = (s.a as usize, s.b as usize);
            let (wa, wb) = (self.inv_mass[a], self.inv_mass[b]);
            let w = wa + wb;
            if w == 0.0 {
                continue;
            }
            let d = self.positions[b] - self.positions[a];
            let l = d.length();
            if l <= 1e-12 {
                continue;
            }
            let n = d / l;
            let dv = (self.velocities[b] - self.velocities[a]).dot(n);
            let p = dv * c * h / (1.0 + c * h * w);
            self.velocities[a] += wa * p * n;
            self.velocities[b] -= wb * p * n;
        }
        if let Some((i, v)) = grabbed {
            self.velocities[i] = v;
        }
    }

    fn substep_xpbd(&mut self, params: &ClothParams, colliders: &Colliders, h: f32) {
        self.external_forces(params);
        for i in 0..self.positions.len() {
            self.previous[i] = self.positions[i];
            if self.pinned[i] {
                continue;
            }
            let w = self.inv_mass[i];
            self.velocities[i] += self.forces[i] * w * h;
            self.positions[i] += self.velocities[i] * h;
        }
        if let Some((i, _)) = self.grab {
            self.hold_grab(self.previous[i], h);
        }
        for s in &self.springs {
            let (a, b) = (s.a as usize, s.b as usize);
            let alpha = params.compliance[s.kind as usize];
            if alpha == f32::INFINITY {
                continue;
            }
            let (wa, wb) = (self.inv_mass[a], self.inv_mass[b]);
            let (wa, wb) = match self.grab {
                Some((g, _)) if g == a => (0.0, wb),
                Some((g, _)) if g == b => (wa, 0.0),
                _ => (wa, wb),
            };
            let (mut pa, mut pb) = (self.positions[a], self.positions[b]);
            project_distance(&mut pa, &mut pb, wa, wb, s.rest, alpha, h);
            self.positions[a] = pa;
            self.positions[b] = pb;
        }
        for i in 0..self.positions.len() {
            if self.pinned[i] {
                continue;
            }
            if let Some((n, depth)) = colliders.contact(self.positions[i]) {
                self.positions[i] += depth * n;
                // Position-based friction: the sliding displacement shrinks by up to μ · depth.
                let moved = self.positions[i] - self.previous[i];
                let tangential = moved - moved.dot(n) * n;
                let slide = tangential.length();
                if slide > 0.0 {
                    let take = (colliders.friction * depth / slide).min(1.0);
                    self.positions[i] -= tangential * take;
                }
            }
            self.velocities[i] = (self.positions[i] - self.previous[i]) / h;
        }
        if let Some((i, _)) = self.grab {
            self.velocities[i] = (self.positions[i] - self.previous[i]) / h;
        }
    }
}

/// The benchmark cloth (criterion and the browser bench page): `side × side` particles, 2 m
/// square, a curtain hanging from its whole top edge over a sphere and the ground in a steady
/// wind, 10 substeps per frame, with stiffnesses low enough (`[5, 2.5, 1]` N/m) that mass-spring
/// stays stable at 100 × 100 with 10 substeps of 1/60 s (XPBD uses `α = 1/k`). So soft a cloth
/// sags and stretches by tens of percent: the benchmark measures cost, not looks.
pub fn benchmark_cloth(
    side: i64,
    method: Method,
) -> Result<(Cloth, ClothParams, Colliders), ClothError> {
    let spec = ClothSpec {
        columns: side,
        rows: side,
        width_m: 2.0,
        height_m: 2.0,
        mass_kg: 0.5,
        origin: Vec3::new(-1.0, 2.2, 0.0),
        across: Vec3::X,
        down: Vec3::NEG_Y,
    };
    let mut cloth = Cloth::new(&spec)?;
    for c in 0..cloth.columns {
        cloth.set_pinned(c, true);
    }
    let mut params = ClothParams {
        stiffness: [5.0, 2.5, 1.0],
        damping: [0.001, 0.001, 0.0005],
        wind: Vec3::new(0.0, 0.0, 3.0),
        substeps: 10,
        method,
        ..Default::default()
    };
    params.compliance_from_stiffness();
    let colliders = Colliders {
        sphere: Some((Vec3::new(0.0, 0.8, 0.5), 0.4)),
        ..Default::default()
    };
    Ok((cloth, params, colliders))
}
