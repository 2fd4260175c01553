//! Fluids as particles: smoothed-particle hydrodynamics (SPH, after Müller, Charypar and Gross
//! 2003, "Particle-based fluid simulation for interactive applications") and position-based
//! fluids (PBF, after Macklin and Müller 2013, "Position based fluids"), in a vertical slab (2D,
//! `z = 0`) or in space (3D), with one code path for both: the dimension only changes the
//! kernels' constants ([`kernels`]) and which walls the box has.
//!
//! Neighbours come from the boids' uniform grid ([`crate::boids::grid::Grid`], counting sort),
//! rebuilt every step; the box's walls and the sphere obstacle are the particles core's
//! ([`crate::particles::collide`]): `Plane`, `Sphere` and `bounce_velocity`.
//!
//! Every particle carries the fluid of one lattice cell at rest, `m = ρ₀ sᵈ` (`s` the spacing
//! the scene fills its blocks with), so a particle inside a block at rest has about the rest
//! density.

pub mod kernels;

use crate::boids::grid::Grid;
use crate::particles::collide::{bounce_velocity, Plane, Sphere};
use glam::{Vec3, Vec4};
pub use kernels::{Dim, Kernels};

/// The most particles a fluid may have: the CPU step's cost grows with the count (and the
/// neighbour lists with it, about 30 per particle in 3D).
pub const MAX_PARTICLES: usize = 200_000;

/// A step is declared exploded when a particle moves faster than this many times the speed of
/// a fall from the top of the box (`√(2 |g| H)`), or a value stops being finite.
pub const EXPLOSION_SPEED_FACTOR: f32 = 4.0;

/// How pressure follows density in SPH.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Eos {
    /// `p = k (ρ − ρ₀)` (Müller et al.'s ideal gas with a rest density): soft, negative below
    /// rest density (particles pull together).
    IdealGas,
    /// `p = max(0, k ρ₀ ((ρ/ρ₀)⁷ − 1) / 7)` (Tait's equation, scaled so its slope at rest density
    /// is the ideal gas's `k`): much stiffer against compression than against expansion, and no
    /// pull below rest density (a free surface would otherwise pull itself into clumps, the
    /// tensile instability).
    Tait,
}

/// Which solver steps the fluid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Sph,
    Pbf,
}

/// The fluid's parameters; [`FluidParams::validate`] says which one is wrong and why.
#[derive(Clone, Debug, PartialEq)]
pub struct FluidParams {
    pub dim: Dim,
    pub method: Method,
    /// Kernel support radius `h`, metres.
    pub h: f32,
    /// Rest density `ρ₀`, kg/m³ in 3D (kg/m² in 2D).
    pub rest_density: f32,
    /// SPH: the equation of state's stiffness `k`.
    pub stiffness: f32,
    pub eos: Eos,
    /// SPH: the dynamic viscosity `μ`.
    pub viscosity: f32,
    /// Time step, seconds.
    pub dt: f32,
    pub gravity: Vec3,
    /// Restitution and friction of the walls and the obstacle (`particles::collide`'s bounce).
    pub restitution: f32,
    pub friction: f32,
    /// PBF: density-constraint iterations per step.
    pub iterations: u32,
    /// PBF: the relaxation `ε` added to each constraint's denominator. It plays the role of
    /// XPBD's `α / Δt²` (lesson 13): a small compliance that keeps `λ` finite where a particle
    /// has few neighbours.
    pub relaxation: f32,
    /// PBF: the artificial pressure `s_corr = −k (W(r) / W(Δq))ⁿ` against clumping (tensile
    /// instability): `k`, with `n = 4` and `Δq = 0.2 h`; 0 turns it off.
    pub s_corr: f32,
    /// PBF: XSPH viscosity `c` (`v_i += c Σ (m/ρ_j)(v_j − v_i) W_ij`).
    pub xsph: f32,
    /// PBF: vorticity confinement `ε` (m/s² per unit of vorticity); 0 turns it off.
    pub vorticity: f32,
}

impl FluidParams {
    /// Parameters that run the 2D dam break stably: the kernel radius is about 2.7 particle
    /// spacings at 2,000 particles (about 23 neighbours). SPH: Tait with `k = 400` (a speed of
    /// sound `√k = 20` m/s, six times the fastest fall in the box) needs `Δt ≤ 0.4 h / 20` m/s,
    /// so `Δt = 1/1200` s (20 steps per 60 Hz frame); PBF takes 1/240 s with 4 iterations.
    pub fn default_2d(method: Method) -> Self {
        Self {
            dim: Dim::Two,
            method,
            h: 0.045,
            rest_density: 1000.0,
            stiffness: 400.0,
            eos: Eos::Tait,
            viscosity: 8.0,
            dt: match method {
                Method::Sph => 1.0 / 1200.0,
                Method::Pbf => 1.0 / 240.0,
            },
            gravity: Vec3::new(0.0, -9.81, 0.0),
            restitution: 0.0,
            friction: 0.0,
            iterations: 4,
            relaxation: 1e-4,
            s_corr: 0.1,
            xsph: 0.01,
            vorticity: 0.0,
        }
    }

    /// As [`FluidParams::default_2d`], in 3D: `h = 0.07` m is about 2 spacings at 8,000
    /// particles (about 33 neighbours).
    pub fn default_3d(method: Method) -> Self {
        Self {
            dim: Dim::Three,
            h: 0.07,
            ..Self::default_2d(method)
        }
    }

    /// An error naming the first parameter out of its range.
    pub fn validate(&self) -> Result<(), String> {
        let positive = |name: &str, v: f32, hi: f32| {
            if v.is_finite() && v > 0.0 && v <= hi {
                Ok(())
            } else {
                Err(format!(
                    "{name} must be a number above 0 and at most {hi}, got {v}"
                ))
            }
        };
        let at_least_0 = |name: &str, v: f32, hi: f32| {
            if v.is_finite() && (0.0..=hi).contains(&v) {
                Ok(())
            } else {
                Err(format!("{name} must be a number from 0 to {hi}, got {v}"))
            }
        };
        positive("kernel radius h (m)", self.h, 1.0)?;
        positive("rest density", self.rest_density, 1e5)?;
        positive("stiffness", self.stiffness, 1e7)?;
        at_least_0("viscosity", self.viscosity, 1e4)?;
        positive("time step (s)", self.dt, 0.05)?;
        if !self.gravity.is_finite() || self.gravity.length() > 1000.0 {
            return Err(format!(
                "gravity must be finite and at most 1000 m/s², got {}",
                self.gravity
            ));
        }
        if self.dim == Dim::Two && self.gravity.z != 0.0 {
            return Err("a 2D fluid's gravity must have z = 0".into());
        }
        at_least_0("restitution", self.restitution, 1.0)?;
        at_least_0("friction", self.friction, 10.0)?;
        if !(1..=100).contains(&self.iterations) {
            return Err(format!(
                "iterations must be from 1 to 100, got {}",
                self.iterations
            ));
        }
        positive("relaxation", self.relaxation, 1.0)?;
        at_least_0("s_corr", self.s_corr, 1.0)?;
        at_least_0("XSPH viscosity", self.xsph, 1.0)?;
        at_least_0("vorticity", self.vorticity, 100.0)?;
        Ok(())
    }
}

/// How a run starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scene {
    /// A block of water against the left wall, 0.45 of the box wide and 0.75 of it high, let go.
    DamBreak,
    /// A pool 0.4 of the box deep, at rest.
    Pool,
    /// A pool 0.3 of the box deep and a drop (a disc in 2D, a ball in 3D) above it.
    Drop,
}

/// The box: 1.6 m wide, 1 m high (and 0.6 m deep in 3D), its corner at the origin.
pub fn box_size(dim: Dim) -> Vec3 {
    match dim {
        Dim::Two => Vec3::new(1.6, 1.0, 0.0),
        Dim::Three => Vec3::new(1.6, 1.0, 0.6),
    }
}

/// How a step finds each particle's neighbours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// The uniform grid: cells one kernel radius wide, the 27 (2D: 9) around a particle.
    Grid,
    /// Every pair tested: the same loop over one cell that holds the whole fluid, O(N²).
    AllPairs,
}

/// What a step measures.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Mean and largest `ρ/ρ₀ − 1` over the particles (compression; negative at the surface).
    pub density_error_mean: f32,
    pub density_error_max: f32,
    /// Kinetic energy `½ Σ m |v|²` and potential energy `Σ m (−g)·x` (the box's corner is the
    /// origin, so heights are measured from its floor), joules.
    pub kinetic: f32,
    pub potential: f32,
    /// The largest `|v| Δt / h`: the share of a kernel radius a particle crosses in one step.
    pub cfl: f32,
    pub max_speed: f32,
}

/// A fluid: particles, their neighbours and the box they live in.
#[derive(Clone, Debug)]
pub struct Fluid {
    pub params: FluidParams,
    /// Lattice spacing the scene was filled with, metres, and each particle's mass.
    pub spacing: f32,
    pub mass: f32,
    pub positions: Vec<Vec3>,
    pub velocities: Vec<Vec3>,
    pub densities: Vec<f32>,
    /// SPH: pressures. PBF: the last iteration's `λ`.
    pub pressures: Vec<f32>,
    pub walls: Vec<Plane>,
    pub obstacle: Option<Sphere>,
    pub time: f32,
    /// Why and when the run stopped, once a step exploded.
    exploded: Option<(f32, String)>,
    grid: Grid,
    /// Neighbour lists in one array: particle `i`'s are `nbr[start[i]..start[i + 1]]`.
    start: Vec<u32>,
    nbr: Vec<u32>,
    predicted: Vec<Vec3>,
    scratch: Vec<Vec3>,
    /// PBF: `1 / Σ_k |∇_k C|²` for a particle inside a lattice at rest, the `|λ|` a constraint
    /// violated by `C = 1` gets: the artificial pressure `s_corr` is measured in it, so that
    /// `k = 0.1` means "as if compressed by 10 %" whatever the units.
    lambda_unit: f32,
}

/// The scene's water: axis-aligned blocks (`min, max`) and an optional round drop (centre,
/// radius; in 2D its z is ignored).
#[allow(clippy::type_complexity)]
fn scene_water(dim: Dim, scene: Scene) -> (Vec<(Vec3, Vec3)>, Option<(Vec3, f32)>) {
    let size = box_size(dim);
    match scene {
        Scene::DamBreak => (vec![(Vec3::ZERO, size * Vec3::new(0.45, 0.75, 1.0))], None),
        Scene::Pool => (vec![(Vec3::ZERO, size * Vec3::new(1.0, 0.4, 1.0))], None),
        Scene::Drop => (
            vec![(Vec3::ZERO, size * Vec3::new(1.0, 0.3, 1.0))],
            Some((size * Vec3::new(0.5, 0.72, 0.5), 0.14)),
        ),
    }
}

/// The lattice spacing that fills `scene` with about `count` particles: `(V / count)^(1/d)`,
/// `V` the water's area (2D) or volume (3D). A caller picks the kernel radius from it (about 2
/// to 3 spacings).
pub fn spacing_for(dim: Dim, scene: Scene, count: usize) -> f32 {
    let (blocks, drop) = scene_water(dim, scene);
    let volume_of = |min: Vec3, max: Vec3| {
        let e = max - min;
        if dim == Dim::Two {
            e.x * e.y
        } else {
            e.x * e.y * e.z
        }
    };
    let mut volume: f32 = blocks.iter().map(|&(a, b)| volume_of(a, b)).sum();
    if let Some((_, r)) = drop {
        volume += if dim == Dim::Two {
            std::f32::consts::PI * r * r
        } else {
            4.0 / 3.0 * std::f32::consts::PI * r * r * r
        };
    }
    (volume / count.max(1) as f32).powf(1.0 / dim.count() as f32)
}

/// The benchmarks' fluid (`benches/fluid.rs` and the bench page's `benchFluid`): the dam break
/// of `count` particles with `h` at 2 spacings in 3D (about 33 neighbours) and 2.7 in 2D (about
/// 23), SPH's time step for a speed of sound of 20 m/s at that `h`, after 0.1 s of fall (so the
/// step timed is one of water in motion). An error when the count is out of range or the fall
/// already exploded.
pub fn benchmark_fluid(dim: Dim, method: Method, count: usize) -> Result<Fluid, String> {
    let mut params = match dim {
        Dim::Two => FluidParams::default_2d(method),
        Dim::Three => FluidParams::default_3d(method),
    };
    let spacings = match dim {
        Dim::Two => 2.7,
        Dim::Three => 2.0,
    };
    params.h = spacings * spacing_for(dim, Scene::DamBreak, count.max(1));
    if method == Method::Sph {
        params.dt = 0.4 * params.h / 20.0;
    }
    let mut f = Fluid::new(params, Scene::DamBreak, count, 1)?;
    for _ in 0..(0.1 / f.params.dt).round() as usize {
        f.step();
    }
    match f.exploded() {
        Some((t, why)) => Err(format!("the benchmark fluid exploded at {t} s: {why}")),
        None => Ok(f),
    }
}

/// A small deterministic generator (xorshift32) for the start's jitter: a seeded run is the
/// same bit for bit.
fn jitter(state: &mut u32) -> f32 {
    *state ^= *state << 13;
    *state ^= *state >> 17;
    *state ^= *state << 5;
    (*state >> 8) as f32 / (1u32 << 24) as f32 - 0.5
}

impl Fluid {
    /// Fills `scene` with about `count` particles (the lattice's exact count may differ by a few
    /// percent), at rest. The spacing follows from the scene's water volume and the count.
    pub fn new(params: FluidParams, scene: Scene, count: usize, seed: u32) -> Result<Self, String> {
        Self::with_cap(params, scene, count, seed, MAX_PARTICLES)
    }

    /// As [`Fluid::new`], with `max_particles` in place of [`MAX_PARTICLES`]: the GPU step's
    /// start ([`crate::figures::gpu::MAX_GPU_FLUID_PARTICLES`]), which the CPU only fills and
    /// uploads.
    pub fn with_cap(
        params: FluidParams,
        scene: Scene,
        count: usize,
        seed: u32,
        max_particles: usize,
    ) -> Result<Self, String> {
        params.validate()?;
        if !(1..=max_particles).contains(&count) {
            return Err(format!(
                "particle count must be from 1 to {max_particles}, got {count}"
            ));
        }
        let dim = params.dim;
        let size = box_size(dim);
        let (blocks, drop) = scene_water(dim, scene);
        let spacing = spacing_for(dim, scene, count);
        if params.h < spacing {
            return Err(format!(
                "kernel radius h = {} m is below the particle spacing {spacing:.4} m: a particle would have no neighbours (use more particles or a larger h)",
                params.h
            ));
        }
        if params.h > 8.0 * spacing {
            return Err(format!(
                "kernel radius h = {} m is more than 8 particle spacings ({spacing:.4} m): each particle would have hundreds of neighbours (use fewer particles or a smaller h)",
                params.h
            ));
        }
        let mut positions = Vec::new();
        // A bijection of the seed (odd multiplier), never 0, which xorshift cannot leave.
        let mut seed = seed
            .wrapping_mul(747_796_405)
            .wrapping_add(2_891_336_453)
            .max(1);
        let mut lattice = |min: Vec3, max: Vec3, keep: &dyn Fn(Vec3) -> bool| {
            let n = ((max - min) / spacing).floor().max(Vec3::ONE);
            let nz = if dim == Dim::Two { 1 } else { n.z as usize };
            for k in 0..nz {
                for j in 0..n.y as usize {
                    for i in 0..n.x as usize {
                        let mut p = min + spacing * (Vec3::new(i as f32, j as f32, k as f32) + 0.5);
                        // A jitter of 1 % of the spacing breaks the lattice's symmetry.
                        p += 0.01
                            * spacing
                            * Vec3::new(jitter(&mut seed), jitter(&mut seed), jitter(&mut seed));
                        if dim == Dim::Two {
                            p.z = 0.0;
                        }
                        if keep(p) {
                            positions.push(p);
                        }
                    }
                }
            }
        };
        for &(a, b) in &blocks {
            lattice(a, b, &|_| true);
        }
        if let Some((c, r)) = drop {
            let c = if dim == Dim::Two {
                Vec3::new(c.x, c.y, 0.0)
            } else {
                c
            };
            lattice(c - Vec3::splat(r), c + Vec3::splat(r), &|p| {
                let mut q = p - c;
                if dim == Dim::Two {
                    q.z = 0.0;
                }
                q.length() <= r
            });
        }
        if positions.len() > max_particles {
            return Err(format!(
                "the scene would hold {} particles, more than {max_particles}",
                positions.len()
            ));
        }
        let n = positions.len();
        let mut walls = vec![
            Plane::through(Vec3::ZERO, Vec3::X),
            Plane::through(size, -Vec3::X),
            Plane::through(Vec3::ZERO, Vec3::Y),
            Plane::through(size, -Vec3::Y),
        ];
        if dim == Dim::Three {
            walls.push(Plane::through(Vec3::ZERO, Vec3::Z));
            walls.push(Plane::through(size, -Vec3::Z));
        }
        let mut grid = Grid::default();
        let pad = Vec3::splat(params.h);
        grid.configure(-pad, size + pad, params.h);
        let mass = params.rest_density * spacing.powi(dim.count());
        let lambda_unit = lattice_lambda_unit(params.h, spacing, mass, params.rest_density, dim);
        Ok(Self {
            params,
            spacing,
            mass,
            velocities: vec![Vec3::ZERO; n],
            densities: vec![0.0; n],
            pressures: vec![0.0; n],
            predicted: positions.clone(),
            scratch: vec![Vec3::ZERO; n],
            positions,
            walls,
            obstacle: None,
            time: 0.0,
            exploded: None,
            grid,
            start: Vec::new(),
            nbr: Vec::new(),
            lambda_unit,
        })
    }

    pub fn len(&self) -> usize {
        self.positions.len()
    }

    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Sets (or removes) the sphere obstacle; it must lie inside the box.
    pub fn set_obstacle(&mut self, obstacle: Option<Sphere>) -> Result<(), String> {
        if let Some(s) = obstacle {
            let size = box_size(self.params.dim);
            let inside = s.center.is_finite()
                && s.radius.is_finite()
                && s.radius > 0.0
                && s.center.cmpge(Vec3::ZERO).all()
                && s.center.cmple(size).all()
                && s.radius <= 0.5 * size.y;
            if !inside {
                return Err(format!(
                    "the obstacle must have its centre inside the box and a radius from 0 to {} m, got centre {} and radius {}",
                    0.5 * size.y,
                    s.center,
                    s.radius
                ));
            }
        }
        self.obstacle = obstacle;
        Ok(())
    }

    /// PBF's `1 / Σ_k |∇_k C|²` of a particle in the lattice at rest, the unit `s_corr` is
    /// measured in (see [`FluidParams::s_corr`]).
    pub fn lambda_unit(&self) -> f32 {
        self.lambda_unit
    }

    /// When and why the run stopped, once a step exploded.
    pub fn exploded(&self) -> Option<(f32, &str)> {
        self.exploded.as_ref().map(|(t, why)| (*t, why.as_str()))
    }

    /// Rebuilds the grid on `points` and the neighbour lists (every other particle within `h`).
    fn find_neighbours(&mut self, use_predicted: bool) {
        let points = if use_predicted {
            &self.predicted
        } else {
            &self.positions
        };
        self.grid.rebuild(points);
        self.start.clear();
        self.nbr.clear();
        self.start.push(0);
        for i in 0..points.len() {
            self.grid
                .append_neighbours(points, i, self.params.h, &mut self.nbr);
            self.start.push(self.nbr.len() as u32);
        }
    }

    /// The neighbours of particle `i` (after a search).
    pub fn neighbours(&self, i: usize) -> &[u32] {
        &self.nbr[self.start[i] as usize..self.start[i + 1] as usize]
    }

    /// Chooses the neighbour search; both find the same neighbours (`tests/fluid.rs`).
    pub fn set_search(&mut self, search: Search) {
        let size = box_size(self.params.dim);
        let pad = Vec3::splat(self.params.h);
        match search {
            Search::Grid => self.grid.configure(-pad, size + pad, self.params.h),
            Search::AllPairs => self.grid.configure_single_cell(-pad, size + pad),
        }
    }

    /// Finds every particle's neighbours among the current positions (the figures' and tests'
    /// entry; a step searches by itself).
    pub fn search(&mut self) {
        self.find_neighbours(false);
    }

    /// `ρ_i = m W(0) + Σ_j m W(|x_i − x_j|)` over the neighbour lists, for `points`.
    fn compute_densities(&mut self, use_predicted: bool) {
        let (h, dim, m) = (self.params.h, self.params.dim, self.mass);
        let points = if use_predicted {
            &self.predicted
        } else {
            &self.positions
        };
        let kern = Kernels::new(h, dim);
        for i in 0..points.len() {
            let p = points[i];
            // Σ W first, one multiplication by m at the end.
            let mut w = kern.poly6(0.0);
            let nbr = &self.nbr[self.start[i] as usize..self.start[i + 1] as usize];
            for_each_four(points, p, nbr, |_, n, o| {
                let v = kern.poly6_x4(o.r2).to_array();
                for &v in &v[..n] {
                    w += v;
                }
            });
            self.densities[i] = m * w;
        }
    }

    /// PBF's `λ_i` for particle `i` at the predicted positions: [`pbf_lambda`] over its
    /// neighbour list, four neighbours at a time with the terms added in list order (the same
    /// value bit for bit; this module's test compares the two).
    fn lambda(&self, kern: &Kernels, i: usize) -> f32 {
        let (m, rho0) = (self.mass, self.params.rest_density);
        let c = (self.densities[i] / rho0 - 1.0).max(0.0);
        if c == 0.0 {
            return 0.0;
        }
        let k = Vec4::splat(m / rho0);
        let (mut grad_i, mut sum) = (Vec3::ZERO, 0.0);
        let nbr = &self.nbr[self.start[i] as usize..self.start[i + 1] as usize];
        for_each_four(&self.predicted, self.predicted[i], nbr, |_, n, o| {
            let s = kern.spiky_gradient_factor_x4(o.r2);
            let (gx, gy, gz) = (k * (o.x * s), k * (o.y * s), k * (o.z * s));
            let len2 = (gx * gx + gy * gy + gz * gz).to_array();
            let (gx, gy, gz) = (gx.to_array(), gy.to_array(), gz.to_array());
            for l in 0..n {
                grad_i += Vec3::new(gx[l], gy[l], gz[l]);
                sum += len2[l];
            }
        });
        sum += grad_i.length_squared();
        -c / (sum + self.params.relaxation)
    }

    /// The pressure of the equation of state at density `rho`.
    pub fn pressure(&self, rho: f32) -> f32 {
        let (k, rho0) = (self.params.stiffness, self.params.rest_density);
        match self.params.eos {
            Eos::IdealGas => k * (rho - rho0),
            Eos::Tait => (k * rho0 / 7.0 * ((rho / rho0).powi(7) - 1.0)).max(0.0),
        }
    }

    /// One step of the chosen solver; does nothing once the run has exploded.
    pub fn step(&mut self) {
        if self.exploded.is_some() {
            return;
        }
        match self.params.method {
            Method::Sph => self.step_sph(),
            Method::Pbf => self.step_pbf(),
        }
        self.time += self.params.dt;
        self.check_explosion();
    }

    /// SPH: densities, pressures, the symmetric pressure and viscosity forces, gravity, then a
    /// semi-implicit Euler step (velocity first) and the collisions.
    fn step_sph(&mut self) {
        self.find_neighbours(false);
        self.compute_densities(false);
        for i in 0..self.len() {
            self.pressures[i] = self.pressure(self.densities[i]);
        }
        let (h, dim, m, mu) = (
            self.params.h,
            self.params.dim,
            self.mass,
            self.params.viscosity,
        );
        let dt = self.params.dt;
        let kern = Kernels::new(h, dim);
        for i in 0..self.len() {
            let mut f = Vec3::ZERO;
            for &j in self.neighbours(i) {
                let j = j as usize;
                f += pair_force_with(
                    &kern,
                    [self.positions[i], self.positions[j]],
                    [self.velocities[i], self.velocities[j]],
                    [self.densities[i], self.densities[j]],
                    [self.pressures[i], self.pressures[j]],
                    m,
                    mu,
                );
            }
            self.scratch[i] = f / m + self.params.gravity;
        }
        for i in 0..self.len() {
            self.velocities[i] += dt * self.scratch[i];
            self.positions[i] += dt * self.velocities[i];
        }
        for i in 0..self.len() {
            let (mut p, mut v) = (self.positions[i], self.velocities[i]);
            self.collide(&mut p, Some(&mut v));
            (self.positions[i], self.velocities[i]) = (p, v);
        }
    }

    /// PBF: predict under gravity, then `iterations` rounds of density constraints
    /// (`C_i = ρ_i/ρ₀ − 1`, pushing apart only: `C_i ≥ 0`), each a Jacobi pass of `λ_i` and
    /// position corrections with `s_corr`; the velocity is the position change over the step, then
    /// vorticity confinement and XSPH viscosity.
    fn step_pbf(&mut self) {
        let p = &self.params;
        let (dt, h, dim, iterations) = (p.dt, p.h, p.dim, p.iterations);
        for i in 0..self.len() {
            self.velocities[i] += dt * self.params.gravity;
            let mut x = self.positions[i] + dt * self.velocities[i];
            self.collide(&mut x, None);
            self.predicted[i] = x;
        }
        self.find_neighbours(true);
        let kern = Kernels::new(h, dim);
        let w_dq = kern.poly6((0.2 * h) * (0.2 * h));
        for _ in 0..iterations {
            self.compute_densities(true);
            for i in 0..self.len() {
                self.pressures[i] = self.lambda(&kern, i);
            }
            self.position_corrections(&kern, w_dq);
            for i in 0..self.len() {
                let mut x = self.predicted[i] + self.scratch[i];
                self.collide(&mut x, None);
                self.predicted[i] = x;
            }
        }
        for i in 0..self.len() {
            self.velocities[i] = (self.predicted[i] - self.positions[i]) / dt;
        }
        self.compute_densities(true);
        if self.params.vorticity > 0.0 {
            self.confine_vorticity();
        }
        if self.params.xsph > 0.0 {
            self.xsph();
        }
        std::mem::swap(&mut self.positions, &mut self.predicted);
    }

    /// PBF's position corrections into `scratch`: `Δx_i = (m/ρ₀) Σ_j (λ_i + λ_j + s_corr)
    /// ∇W(x_i − x_j)` at the predicted positions, with the `λ`s in `pressures` and `w_dq` the
    /// poly6 value `s_corr` is measured against.
    fn position_corrections(&mut self, kern: &Kernels, w_dq: f32) {
        let (m, rho0, k_corr) = (self.mass, self.params.rest_density, self.params.s_corr);
        // Four neighbours at a time: the lanes hold each term's factors, and the terms are
        // added in list order.
        let (k_lanes, w_dq_lanes, unit_lanes) = (
            Vec4::splat(-k_corr),
            Vec4::splat(w_dq),
            Vec4::splat(self.lambda_unit),
        );
        for i in 0..self.len() {
            let xi = self.predicted[i];
            let lambda_i = Vec4::splat(self.pressures[i]);
            let mut dx = Vec3::ZERO;
            let nbr = &self.nbr[self.start[i] as usize..self.start[i + 1] as usize];
            for_each_four(&self.predicted, xi, nbr, |js, n, o| {
                let s_corr = if k_corr > 0.0 {
                    let ratio = kern.poly6_x4(o.r2) / w_dq_lanes;
                    k_lanes * ratio * ratio * ratio * ratio * unit_lanes
                } else {
                    Vec4::ZERO
                };
                let s = kern.spiky_gradient_factor_x4(o.r2);
                let c = lambda_i + gather(&self.pressures, js) + s_corr;
                let (gx, gy, gz) = (
                    (c * (o.x * s)).to_array(),
                    (c * (o.y * s)).to_array(),
                    (c * (o.z * s)).to_array(),
                );
                for l in 0..n {
                    dx += Vec3::new(gx[l], gy[l], gz[l]);
                }
            });
            self.scratch[i] = m / rho0 * dx;
        }
    }

    /// Vorticity confinement (PBF): `ω_i = Σ (m/ρ_j)(v_j − v_i) × ∇_j W_ij`, `N = η/|η|` with
    /// `η = ∇|ω|`, and `v_i += Δt ε (N × ω_i)`: it gives back the swirls that damping takes.
    fn confine_vorticity(&mut self) {
        let (h, dim, m, dt, eps) = (
            self.params.h,
            self.params.dim,
            self.mass,
            self.params.dt,
            self.params.vorticity,
        );
        let x = &self.predicted;
        let kern = Kernels::new(h, dim);
        let omega: Vec<Vec3> = (0..x.len())
            .map(|i| {
                let mut w = Vec3::ZERO;
                for &j in self.neighbours(i) {
                    let j = j as usize;
                    // ∇_j W_ij (the paper's form): the gradient with respect to x_j, the
                    // opposite of `spiky_gradient(x_i − x_j)`. With ∇_i W the curl's sign
                    // flips and the "confinement" damps the swirls instead.
                    let g = kern.spiky_gradient(x[j] - x[i]);
                    w += m / self.densities[j] * (self.velocities[j] - self.velocities[i]).cross(g);
                }
                w
            })
            .collect();
        for i in 0..x.len() {
            let mut eta = Vec3::ZERO;
            for &j in self.neighbours(i) {
                let j = j as usize;
                eta += m / self.densities[j] * omega[j].length() * kern.spiky_gradient(x[i] - x[j]);
            }
            let len = eta.length();
            if len > 1e-9 {
                self.scratch[i] = dt * eps * (eta / len).cross(omega[i]);
            } else {
                self.scratch[i] = Vec3::ZERO;
            }
        }
        for i in 0..x.len() {
            self.velocities[i] += self.scratch[i];
        }
    }

    /// XSPH viscosity: `v_i += c Σ (m/ρ_j)(v_j − v_i) W_ij`, a blend towards the neighbours'
    /// mean velocity.
    fn xsph(&mut self) {
        let (h, dim, m, c) = (self.params.h, self.params.dim, self.mass, self.params.xsph);
        let x = &self.predicted;
        let kern = Kernels::new(h, dim);
        let m_lanes = Vec4::splat(m);
        for i in 0..x.len() {
            let vi = self.velocities[i];
            let mut dv = Vec3::ZERO;
            let nbr = &self.nbr[self.start[i] as usize..self.start[i + 1] as usize];
            // Four neighbours at a time, the terms added in list order.
            for_each_four(x, x[i], nbr, |js, n, o| {
                let share = m_lanes / gather(&self.densities, js);
                let w = kern.poly6_x4(o.r2);
                let (mut vx, mut vy, mut vz) = ([vi.x; 4], [vi.y; 4], [vi.z; 4]);
                for (l, &j) in js.iter().enumerate() {
                    let v = self.velocities[j as usize];
                    (vx[l], vy[l], vz[l]) = (v.x, v.y, v.z);
                }
                let (tx, ty, tz) = (
                    (share * (Vec4::from_array(vx) - Vec4::splat(vi.x)) * w).to_array(),
                    (share * (Vec4::from_array(vy) - Vec4::splat(vi.y)) * w).to_array(),
                    (share * (Vec4::from_array(vz) - Vec4::splat(vi.z)) * w).to_array(),
                );
                for l in 0..n {
                    dv += Vec3::new(tx[l], ty[l], tz[l]);
                }
            });
            self.scratch[i] = c * dv;
        }
        for i in 0..x.len() {
            self.velocities[i] += self.scratch[i];
        }
    }

    /// Keeps `p` inside the box and outside the obstacle (projected to the surface); with a
    /// velocity, its part into the surface bounces with the particles core's rule.
    fn collide(&self, p: &mut Vec3, mut v: Option<&mut Vec3>) {
        let (e, mu) = (self.params.restitution, self.params.friction);
        for wall in &self.walls {
            let d = wall.distance(*p);
            if d < 0.0 {
                *p -= d * wall.normal;
                if let Some(v) = v.as_deref_mut() {
                    if v.dot(wall.normal) < 0.0 {
                        *v = bounce_velocity(*v, wall.normal, e, mu);
                    }
                }
            }
        }
        if let Some(s) = self.obstacle {
            let mut q = *p - s.center;
            if self.params.dim == Dim::Two {
                q.z = 0.0;
            }
            let r = q.length();
            if r < s.radius && r > 0.0 {
                let n = q / r;
                *p += (s.radius - r) * n;
                if let Some(v) = v {
                    if v.dot(n) < 0.0 {
                        *v = bounce_velocity(*v, n, e, mu);
                    }
                }
            }
        }
    }

    /// Density errors, energies and the CFL number of the current state (densities from the
    /// last step; call [`Fluid::search`] and [`Fluid::refresh_densities`] first on a fresh fluid).
    pub fn stats(&self) -> Stats {
        let rho0 = self.params.rest_density;
        let n = self.len().max(1) as f32;
        let mut s = Stats {
            density_error_max: f32::MIN,
            ..Stats::default()
        };
        for i in 0..self.len() {
            let err = self.densities[i] / rho0 - 1.0;
            s.density_error_mean += err / n;
            s.density_error_max = s.density_error_max.max(err);
            let v2 = self.velocities[i].length_squared();
            s.kinetic += 0.5 * self.mass * v2;
            s.potential -= self.mass * self.params.gravity.dot(self.positions[i]);
            s.max_speed = s.max_speed.max(v2.sqrt());
        }
        if self.is_empty() {
            s.density_error_max = 0.0;
        }
        s.cfl = s.max_speed * self.params.dt / self.params.h;
        s
    }

    /// Recomputes the densities at the current positions (neighbours from [`Fluid::search`]).
    pub fn refresh_densities(&mut self) {
        self.compute_densities(false);
    }

    fn check_explosion(&mut self) {
        let mut worst = 0.0f32;
        for (p, v) in self.positions.iter().zip(&self.velocities) {
            if !p.is_finite() || !v.is_finite() {
                worst = f32::INFINITY;
                break;
            }
            worst = worst.max(v.length());
        }
        if let Some(why) = explosion_verdict(&self.params, worst) {
            self.exploded = Some((self.time, why));
        }
    }
}

/// The offsets `x_i − x_j` from `p = x_i` to four of its neighbours, lane by lane, and their
/// squared lengths (`(x² + y²) + z²`, the order of `Vec3::length_squared`, so each lane equals
/// the scalar computation bit for bit). `js` holds one to four indices; lanes past its end are
/// `p − p` (a step reads only the first `js.len()` lanes).
#[derive(Clone, Copy)]
struct Offsets {
    x: Vec4,
    y: Vec4,
    z: Vec4,
    r2: Vec4,
}

#[inline(always)]
fn offsets(points: &[Vec3], p: Vec3, js: &[u32]) -> Offsets {
    let (mut xs, mut ys, mut zs) = ([p.x; 4], [p.y; 4], [p.z; 4]);
    for (l, &j) in js.iter().enumerate() {
        let q = points[j as usize];
        (xs[l], ys[l], zs[l]) = (q.x, q.y, q.z);
    }
    let x = Vec4::splat(p.x) - Vec4::from_array(xs);
    let y = Vec4::splat(p.y) - Vec4::from_array(ys);
    let z = Vec4::splat(p.z) - Vec4::from_array(zs);
    Offsets {
        x,
        y,
        z,
        r2: x * x + y * y + z * z,
    }
}

/// Four of `values` gathered by index (lanes past `js` are 1, a value no sum reads).
#[inline(always)]
fn gather(values: &[f32], js: &[u32]) -> Vec4 {
    let mut v = [1.0; 4];
    for (l, &j) in js.iter().enumerate() {
        v[l] = values[j as usize];
    }
    Vec4::from_array(v)
}

/// Calls `f(js, n, offsets)` for the neighbour list `nbr` of the particle at `p`, four
/// neighbours at a time in list order (`n = js.len()`, 4 but for the last call). The step's
/// sums evaluate their kernels four lanes at a time and add the lanes in list order, so every
/// sum is the one a loop over the list, one neighbour at a time, computes, bit for bit (this
/// module's test compares them).
#[inline(always)]
fn for_each_four(points: &[Vec3], p: Vec3, nbr: &[u32], mut f: impl FnMut(&[u32], usize, Offsets)) {
    let mut chunks = nbr.chunks_exact(4);
    for js in &mut chunks {
        f(js, 4, offsets(points, p, js));
    }
    let rest = chunks.remainder();
    if !rest.is_empty() {
        f(rest, rest.len(), offsets(points, p, rest));
    }
}

/// The speed past which a step counts as exploded, m/s: [`EXPLOSION_SPEED_FACTOR`] times the
/// speed of a fall from the top of the box, `√(2 |g| H)` (`|g|` at least 1 m/s²).
pub fn explosion_speed(params: &FluidParams) -> f32 {
    let height = box_size(params.dim).y;
    EXPLOSION_SPEED_FACTOR * (2.0 * params.gravity.length().max(1.0) * height).sqrt()
}

/// Why a step whose fastest particle moves at `fastest` m/s has exploded, or `None` when it has
/// not (at most [`explosion_speed`]). An infinite or NaN `fastest` stands for a position or
/// velocity that stopped being a number. The CPU's step and the GPU's readback of its fastest
/// particle give the same verdict through it.
pub fn explosion_verdict(params: &FluidParams, fastest: f32) -> Option<String> {
    let limit = explosion_speed(params);
    if fastest.is_finite() {
        (fastest > limit).then(|| format!(
            "a particle reached {fastest:.1} m/s, {:.1} kernel radii per step (more than {limit:.1} m/s): the step is unstable; lower the time step or the stiffness",
            fastest * params.dt / params.h
        ))
    } else {
        Some("a position or velocity stopped being a number: the step is unstable; lower the time step or the stiffness".to_string())
    }
}

/// `1 / Σ_k |∇_k C|²` for a particle in a square (2D) or cubic (3D) lattice of `spacing`, with
/// `∇_j C = −(m/ρ₀) ∇W(x_i − x_j)` (the sum over the neighbours of `∇_i C` is zero by symmetry).
fn lattice_lambda_unit(h: f32, spacing: f32, m: f32, rho0: f32, dim: Dim) -> f32 {
    let n = (h / spacing).ceil() as i32;
    let nz = if dim == Dim::Two { 0 } else { n };
    let mut sum = 0.0;
    for k in -nz..=nz {
        for j in -n..=n {
            for i in -n..=n {
                let o = spacing * Vec3::new(i as f32, j as f32, k as f32);
                sum += (m / rho0 * kernels::spiky_gradient(o, h, dim)).length_squared();
            }
        }
    }
    if sum > 0.0 {
        1.0 / sum
    } else {
        0.0
    }
}

/// The SPH force on particle `i` from particle `j` (pressure and viscosity), in newtons:
/// ```text
/// F_ij = −m² (p_i + p_j) / (2 ρ_i ρ_j) ∇W_spiky(x_i − x_j)  +  μ m² (v_j − v_i) / (ρ_i ρ_j) ∇²W_visc(r)
/// ```
/// Swapping `i` and `j` gives exactly `−F_ij` (the gradient is odd; sums and products are the
/// same in either order), so the pair conserves momentum. Arrays hold `[i, j]`. Exercise 15.3.
#[allow(clippy::too_many_arguments)]
pub fn pair_force(
    x: [Vec3; 2],
    v: [Vec3; 2],
    rho: [f32; 2],
    p: [f32; 2],
    m: f32,
    mu: f32,
    h: f32,
    dim: Dim,
) -> Vec3 {
    pair_force_with(&Kernels::new(h, dim), x, v, rho, p, m, mu)
}

/// [`pair_force`] with the kernels' constants already computed (the step's loop).
#[inline]
fn pair_force_with(
    kern: &Kernels,
    x: [Vec3; 2],
    v: [Vec3; 2],
    rho: [f32; 2],
    p: [f32; 2],
    m: f32,
    mu: f32,
) -> Vec3 {
    let rij = x[0] - x[1];
    let rr = rho[0] * rho[1];
    let pressure = -(m * m) * (p[0] + p[1]) / (2.0 * rr) * kern.spiky_gradient(rij);
    let viscosity = mu * (m * m) / rr * kern.viscosity_laplacian(rij.length()) * (v[1] - v[0]);
    pressure + viscosity
}

/// Particle `i`'s density `ρ_i = m W(0) + Σ_j m W_poly6(|x_i − x_j|)` from its neighbours'
/// positions. Exercise 15.2.
pub fn density(
    x: Vec3,
    neighbours: impl IntoIterator<Item = Vec3>,
    m: f32,
    h: f32,
    dim: Dim,
) -> f32 {
    let kern = Kernels::new(h, dim);
    let mut w = kern.poly6(0.0);
    for y in neighbours {
        w += kern.poly6((x - y).length_squared());
    }
    m * w
}

/// PBF's `λ_i` for the density constraint `C_i = ρ_i/ρ₀ − 1` (only when compressed: `C_i < 0`
/// gives 0), with the relaxation `ε`:
/// ```text
/// ∇_i C_i = (m/ρ₀) Σ_j ∇W(x_i − x_j),   ∇_j C_i = −(m/ρ₀) ∇W(x_i − x_j)
/// λ_i = −C_i / (Σ_k |∇_k C_i|² + ε)
/// ```
/// Exercise 15.4.
#[allow(clippy::too_many_arguments)]
pub fn pbf_lambda(
    x: Vec3,
    neighbours: impl IntoIterator<Item = Vec3>,
    rho: f32,
    m: f32,
    rho0: f32,
    eps: f32,
    h: f32,
    dim: Dim,
) -> f32 {
    pbf_lambda_with(&Kernels::new(h, dim), x, neighbours, rho, m, rho0, eps)
}

/// [`pbf_lambda`] with the kernels' constants already computed (the step's loop).
#[inline]
fn pbf_lambda_with(
    kern: &Kernels,
    x: Vec3,
    neighbours: impl IntoIterator<Item = Vec3>,
    rho: f32,
    m: f32,
    rho0: f32,
    eps: f32,
) -> f32 {
    let c = (rho / rho0 - 1.0).max(0.0);
    if c == 0.0 {
        return 0.0;
    }
    let mut grad_i = Vec3::ZERO;
    let mut sum = 0.0;
    for y in neighbours {
        let g = m / rho0 * kern.spiky_gradient(x - y);
        grad_i += g;
        sum += g.length_squared();
    }
    sum += grad_i.length_squared();
    -c / (sum + eps)
}

/// White-box checks of the step's fast paths against their one-at-a-time definitions: they read
/// the step's private stages, so they live beside them. The native tests call them
/// (tests/internals/fluid.rs); only a build with debug assertions (the test profile) has them.
#[cfg(debug_assertions)]
#[doc(hidden)]
pub mod white_box {
    use super::*;

    /// The step's sums, which evaluate four neighbours at a time, against a loop over each list
    /// one neighbour at a time with the scalar kernels: equal bit for bit (the lanes add their
    /// terms in list order), on a splashing 3D and 2D dam break.
    pub fn the_four_lane_sums_are_the_scalar_loops_bit_for_bit() {
        for dim in [Dim::Three, Dim::Two] {
            let params = match dim {
                Dim::Three => FluidParams::default_3d(Method::Pbf),
                Dim::Two => FluidParams::default_2d(Method::Pbf),
            };
            let mut f = Fluid::new(params, Scene::DamBreak, 3000, 7).unwrap();
            for _ in 0..40 {
                f.step();
            }
            assert!(f.exploded().is_none());
            let (m, rho0) = (f.mass, f.params.rest_density);
            let kern = Kernels::new(f.params.h, dim);
            f.predicted.clone_from(&f.positions);
            f.find_neighbours(true);
            f.compute_densities(true);
            let x = f.predicted.clone();
            let nbrs = |f: &Fluid, i: usize| f.neighbours(i).to_vec();
            let mut compressed = 0;
            for i in 0..f.len() {
                let mut w = kern.poly6(0.0);
                for j in nbrs(&f, i) {
                    w += kern.poly6((x[i] - x[j as usize]).length_squared());
                }
                assert_eq!(
                    f.densities[i].to_bits(),
                    (m * w).to_bits(),
                    "density of {i}"
                );
                let lambda = pbf_lambda_with(
                    &kern,
                    x[i],
                    nbrs(&f, i).iter().map(|&j| x[j as usize]),
                    f.densities[i],
                    m,
                    rho0,
                    f.params.relaxation,
                );
                f.pressures[i] = lambda;
                compressed += usize::from(lambda != 0.0);
            }
            assert!(
                compressed > 100,
                "{compressed} particles compressed: too few to test λ"
            );
            for i in 0..f.len() {
                let lambda = f.lambda(&kern, i);
                assert_eq!(lambda.to_bits(), f.pressures[i].to_bits(), "λ of {i}");
            }
            let w_dq = kern.poly6((0.2 * f.params.h) * (0.2 * f.params.h));
            f.position_corrections(&kern, w_dq);
            for i in 0..f.len() {
                let mut dx = Vec3::ZERO;
                for j in nbrs(&f, i) {
                    let j = j as usize;
                    let rij = x[i] - x[j];
                    let ratio = kern.poly6(rij.length_squared()) / w_dq;
                    let s_corr = -f.params.s_corr * ratio * ratio * ratio * ratio * f.lambda_unit;
                    dx += (f.pressures[i] + f.pressures[j] + s_corr) * kern.spiky_gradient(rij);
                }
                assert_eq!(f.scratch[i], m / rho0 * dx, "correction of {i}");
            }
            let v = f.velocities.clone();
            f.xsph();
            for i in 0..f.len() {
                let mut dv = Vec3::ZERO;
                for j in nbrs(&f, i) {
                    let j = j as usize;
                    dv += m / f.densities[j]
                        * (v[j] - v[i])
                        * kern.poly6((x[i] - x[j]).length_squared());
                }
                assert_eq!(f.velocities[i], v[i] + f.params.xsph * dv, "XSPH of {i}");
            }
        }
    }
}
