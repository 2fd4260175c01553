//! Lesson 12 core, "Boids": Reynolds' flocking rules (cohesion, alignment, separation) with
//! weights, radii and a field of view, the course's distance force laws, a bounding box, sphere
//! obstacles, a leader and a predator; neighbours found by the naive O(N²) loop or by a uniform
//! grid ([`grid`]) that gives the same neighbour sets in O(N) at bounded density.
//!
//! The update is the course's semi-implicit Euler step
//! ```text
//! v ← clamp_speed(v + clamp_force(F) dt),   p ← p + v dt
//! ```
//! (see [`crate::particles::semi_implicit_euler_step`]). At most [`MAX_BOIDS`] boids.
//! Lesson: lessons/12-boids.

pub mod grid;

use grid::CellSearch;
pub use grid::{cell_index, for_each_neighbour_naive, Grid, MAX_GRID_CELLS};

use crate::particles::{semi_implicit_euler_step, Rng, Sphere};
use glam::{BVec4A, Vec3, Vec4};

/// The most boids a flock may hold (the naive search is quadratic: keep it well below this).
pub const MAX_BOIDS: usize = 200_000;

/// A rule's weight (dimensionless gain) and radius (metres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rule {
    pub weight: f32,
    pub radius: f32,
}

/// The distance force law `f(x)` of the course: `F_i = Σ_j f(|p_j − p_i|) (p_j − p_i)/|p_j − p_i|`
/// (positive `f` attracts).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceLaw {
    None,
    /// `f(x) = a1 / x² − a2 / x⁴`: attraction at long range, repulsion at short range; zero at
    /// `x = √(a2/a1)`.
    InversePower {
        a1: f32,
        a2: f32,
    },
    /// `f(x) = a1 exp(−k ((x − x0)/x0)²) − a2 exp(−x/x0)`: an attraction term peaking at `x0`
    /// and a repulsion strongest at contact (the sum peaks beyond `x0`, by how much depends on
    /// `a2`; with `k = 2` and `a1 = a2` it changes sign at `x0 / 2`). (The course writes the
    /// repulsion as `a2 exp(x/x0)`; with a minus sign in the exponent it fades with distance
    /// instead of growing.)
    Gaussian {
        a1: f32,
        a2: f32,
        k: f32,
        x0: f32,
    },
}

impl ForceLaw {
    /// `f(x)` at distance `x > 0` metres.
    pub fn f(self, x: f32) -> f32 {
        match self {
            ForceLaw::None => 0.0,
            ForceLaw::InversePower { a1, a2 } => {
                let x2 = x * x;
                a1 / x2 - a2 / (x2 * x2)
            }
            ForceLaw::Gaussian { a1, a2, k, x0 } => {
                let u = (x - x0) / x0;
                a1 * (-k * u * u).exp() - a2 * (-x / x0).exp()
            }
        }
    }
}

/// Everything that steers a boid.
#[derive(Clone, Debug, PartialEq)]
pub struct BoidParams {
    pub cohesion: Rule,
    pub alignment: Rule,
    pub separation: Rule,
    /// The distance law, applied within `law_radius`.
    pub law: ForceLaw,
    pub law_radius: f32,
    /// Full field of view, degrees in `[0, 360]`: a boid ignores neighbours behind it.
    pub fov_deg: f32,
    pub max_speed: f32,
    /// The slowest a boid flies, m/s: a moving boid slower than this is sped up along its
    /// heading after each step (a value above `max_speed` acts as `max_speed`). Without it the rules only ever pull speeds
    /// towards the neighbours' mean velocity, and the mean of random headings is small: a flock
    /// slows down until it hovers instead of flying.
    pub min_speed: f32,
    /// Largest steering acceleration, m/s².
    pub max_force: f32,
    /// Boids are pushed back into the box `[-bounds, bounds]`.
    pub bounds: Vec3,
    pub bounds_weight: f32,
    pub obstacles: Vec<Sphere>,
    pub avoid_weight: f32,
    /// Boid 0 is a leader that follows [`leader_path`]; the others seek it with this weight.
    pub leader: Option<f32>,
    /// Boid 0 (or 1 with a leader) is a predator that chases the nearest boid; the others flee
    /// it within `flee_radius` with weight `flee_weight`.
    pub predator: Option<(f32, f32)>,
}

impl Default for BoidParams {
    fn default() -> Self {
        Self {
            cohesion: Rule {
                weight: 1.0,
                radius: 1.5,
            },
            alignment: Rule {
                weight: 2.0,
                radius: 1.5,
            },
            separation: Rule {
                weight: 1.5,
                radius: 0.5,
            },
            law: ForceLaw::None,
            law_radius: 1.5,
            fov_deg: 270.0,
            max_speed: 2.5,
            min_speed: 1.25,
            max_force: 6.0,
            bounds: Vec3::new(6.0, 3.0, 6.0),
            bounds_weight: 4.0,
            obstacles: Vec::new(),
            avoid_weight: 10.0,
            leader: None,
            predator: None,
        }
    }
}

impl BoidParams {
    /// Every rule the parameters must satisfy, each with its own message.
    pub fn validate(&self) -> Result<(), String> {
        for (name, r) in [
            ("cohesion", self.cohesion),
            ("alignment", self.alignment),
            ("separation", self.separation),
        ] {
            if !(r.weight.is_finite() && r.radius.is_finite() && r.radius > 0.0) {
                return Err(format!("{name}: weight must be finite and radius > 0"));
            }
        }
        let numbers = [
            self.law_radius,
            self.fov_deg,
            self.max_speed,
            self.min_speed,
            self.max_force,
            self.bounds_weight,
            self.avoid_weight,
        ];
        if numbers.iter().any(|x| !x.is_finite() || *x < 0.0) || !self.bounds.is_finite() {
            return Err("boid parameters must be finite and non-negative".into());
        }
        if !(0.0..=360.0).contains(&self.fov_deg) {
            return Err(format!(
                "field of view must lie in [0, 360] degrees, got {}",
                self.fov_deg
            ));
        }
        Ok(())
    }

    /// The largest radius any neighbour rule looks at (the grid's cell size).
    pub fn search_radius(&self) -> f32 {
        let law = if self.law == ForceLaw::None {
            0.0
        } else {
            self.law_radius
        };
        self.cohesion
            .radius
            .max(self.alignment.radius)
            .max(self.separation.radius)
            .max(law)
    }
}

/// `v` with its length clamped into `[min, max]` (`max` as glam's `clamp_length_max`, to the
/// bit); a boid at rest stays at rest (it has no heading to speed up along).
#[inline]
pub fn clamp_speed(v: Vec3, min: f32, max: f32) -> Vec3 {
    let s2 = v.length_squared();
    if s2 > max * max {
        max * (v / s2.sqrt())
    } else if s2 < min * min && s2 > 0.0 {
        min * (v / s2.sqrt())
    } else {
        v
    }
}

/// The three rules of Reynolds for boid `(p, v)` given its neighbours (already chosen: within
/// the radius and field of view), unweighted:
/// ```text
/// cohesion   = (1/n) Σ p_j − p                 towards the neighbours' centre
/// alignment  = (1/n) Σ v_j − v                 towards their mean velocity
/// separation = Σ (p − p_j) / |p − p_j|²        away from each, harder when closer
/// ```
/// Each is zero without neighbours; a neighbour at the same point adds nothing to separation.
/// Exercise 12.1.
pub fn three_rules(p: Vec3, v: Vec3, positions: &[Vec3], velocities: &[Vec3]) -> [Vec3; 3] {
    let n = positions.len().min(velocities.len());
    if n == 0 {
        return [Vec3::ZERO; 3];
    }
    let mut centre = Vec3::ZERO;
    let mut mean_v = Vec3::ZERO;
    let mut separation = Vec3::ZERO;
    for (&q, &w) in positions.iter().zip(velocities) {
        centre += q;
        mean_v += w;
        let d = p - q;
        let d2 = d.length_squared();
        if d2 > 0.0 {
            separation += d / d2;
        }
    }
    let inv = 1.0 / n as f32;
    [centre * inv - p, mean_v * inv - v, separation]
}

/// Where the leader is at `time_sec`: a slow figure-of-eight inside `bounds`.
pub fn leader_path(time_sec: f32, bounds: Vec3) -> Vec3 {
    let w = 0.35;
    Vec3::new(
        0.7 * bounds.x * (w * time_sec).sin(),
        0.4 * bounds.y * (2.0 * w * time_sec).sin(),
        0.7 * bounds.z * (2.0 * w * time_sec).sin() * 0.8,
    )
}

/// [`Flock::new`]'s start without its cap (the GPU steps larger flocks): `count` boids at seeded
/// random places inside `params.bounds`, moving in random directions at half the maximum speed
/// clamped into the speed limits (so at the min speed where that is higher).
pub fn seeded_start(count: usize, params: &BoidParams, seed: u64) -> (Vec<Vec3>, Vec<Vec3>) {
    let mut rng = Rng::new(seed);
    let b = params.bounds;
    let positions = (0..count)
        .map(|_| {
            Vec3::new(
                rng.range(-b.x, b.x),
                rng.range(-b.y, b.y),
                rng.range(-b.z, b.z),
            )
        })
        .collect();
    let velocities = (0..count)
        .map(|_| {
            let (min, max) = speed_limits(params, false);
            clamp_speed(rng.on_unit_sphere() * 0.5 * params.max_speed, min, max)
        })
        .collect();
    (positions, velocities)
}

/// The speeds a step keeps a boid between, `(min, max)` in m/s: the predator's top is 1.3 times
/// the max speed; a min speed above the top acts as the top.
fn speed_limits(params: &BoidParams, predator: bool) -> (f32, f32) {
    let top = params.max_speed * if predator { 1.3 } else { 1.0 };
    (params.min_speed.min(top), top)
}

/// How the flock finds neighbours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// Every pair: O(N²).
    Naive,
    /// A uniform grid with cells as wide as the largest radius in y and z (a quarter of it in x,
    /// see [`grid::X_SPLIT`]): O(N) at bounded density.
    Grid,
}

/// A flock in structure-of-arrays form.
#[derive(Clone, Debug)]
pub struct Flock {
    pub positions: Vec<Vec3>,
    pub velocities: Vec<Vec3>,
    /// The steering acceleration of the last step (m/s²), after clamping.
    pub forces: Vec<Vec3>,
    pub grid: Grid,
    /// Seconds since the start (drives the leader).
    pub time_sec: f32,
}

impl Flock {
    /// `count ≤` [`MAX_BOIDS`] boids at seeded random places inside `bounds`, moving in random
    /// directions as [`seeded_start`] says.
    pub fn new(count: usize, params: &BoidParams, seed: u64) -> Result<Self, String> {
        if count > MAX_BOIDS {
            return Err(format!("{count} boids is too many (at most {MAX_BOIDS})"));
        }
        params.validate()?;
        let (positions, velocities) = seeded_start(count, params, seed);
        Ok(Self {
            positions,
            velocities,
            forces: vec![Vec3::ZERO; count],
            grid: Grid::default(),
            time_sec: 0.0,
        })
    }

    pub fn len(&self) -> usize {
        self.positions.len()
    }

    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Index of the leader and of the predator, if any.
    pub fn roles(&self, params: &BoidParams) -> (Option<usize>, Option<usize>) {
        let leader = params.leader.filter(|_| !self.is_empty()).map(|_| 0);
        let first_free = leader.map_or(0, |_| 1);
        let predator = params
            .predator
            .filter(|_| self.len() > first_free)
            .map(|_| first_free);
        (leader, predator)
    }

    /// Calls `f(j)` for every neighbour of boid `i` within `radius` (any search gives the same
    /// set; the grid must be rebuilt first for [`Search::Grid`]).
    pub fn for_each_neighbour(&self, search: Search, i: usize, radius: f32, f: impl FnMut(usize)) {
        match search {
            Search::Naive => for_each_neighbour_naive(&self.positions, i, radius, f),
            Search::Grid => self.grid.for_each_neighbour(&self.positions, i, radius, f),
        }
    }

    /// Whether boid `i` sees the point `q` (within half the field of view of its velocity).
    pub fn sees(&self, i: usize, q: Vec3, fov_deg: f32) -> bool {
        if fov_deg >= 360.0 {
            return true;
        }
        let d = q - self.positions[i];
        let v = self.velocities[i];
        let (dl, vl) = (d.length(), v.length());
        if dl == 0.0 || vl == 0.0 {
            return true;
        }
        d.dot(v) >= (0.5 * fov_deg).to_radians().cos() * dl * vl
    }

    /// One step of `dt` seconds: neighbours by `search`, steering, semi-implicit Euler.
    /// Allocates nothing once the grid has been built for this many boids.
    pub fn step(&mut self, params: &BoidParams, search: Search, dt: f32) {
        let n = self.len();
        let radius = params.search_radius();
        let margin = Vec3::splat(radius);
        let (min, max) = (-params.bounds - margin, params.bounds + margin);
        // The naive search is the grid's loop over one single cell: every boid tests every
        // other, with the same SIMD kernel, so naive against grid measures the search alone.
        match search {
            Search::Grid => self.grid.configure(min, max, radius),
            Search::Naive => self.grid.configure_single_cell(min, max),
        }
        self.grid
            .rebuild_with_velocities(&self.positions, &self.velocities);
        let (leader, predator) = self.roles(params);
        self.steer_all_with_grid(params, leader, predator);
        self.time_sec += dt;
        for i in 0..n {
            let (p, v) = (&mut self.positions[i], &mut self.velocities[i]);
            if Some(i) == leader {
                // The leader is driven along its path (its velocity is the path's tangent).
                let target = leader_path(self.time_sec, params.bounds);
                *v = (target - *p) / dt.max(1e-6);
                *v = v.clamp_length_max(params.max_speed * 1.5);
                *p += *v * dt;
                continue;
            }
            semi_implicit_euler_step(p, v, self.forces[i], dt);
            // Clamp the speed after the velocity update, then redo the position with it.
            let (min, top) = speed_limits(params, Some(i) == predator);
            let clamped = clamp_speed(*v, min, top);
            *p += (clamped - *v) * dt;
            *v = clamped;
        }
    }

    /// Clamps every velocity into the speed limits a step keeps ([`clamp_speed`]) now, the
    /// leader's (set from its path by each step) left as it is: after a change of the min or
    /// max speed the flock's speeds lie within the new limits before the next step.
    pub fn clamp_speeds(&mut self, params: &BoidParams) {
        let (leader, predator) = self.roles(params);
        for (i, v) in self.velocities.iter_mut().enumerate() {
            if Some(i) != leader {
                let (min, max) = speed_limits(params, Some(i) == predator);
                *v = clamp_speed(*v, min, max);
            }
        }
    }

    /// The steering acceleration boid `i` would get now (after clamping), by the naive search:
    /// what the figure draws for its highlighted boid.
    pub fn steering_of(&self, params: &BoidParams, i: usize) -> Vec3 {
        let (leader, predator) = self.roles(params);
        self.steering(params, Search::Naive, i, leader, predator)
    }

    fn steering(
        &self,
        params: &BoidParams,
        search: Search,
        i: usize,
        leader: Option<usize>,
        predator: Option<usize>,
    ) -> Vec3 {
        let p = self.positions[i];
        let v = self.velocities[i];
        if Some(i) == predator {
            return self.predator_steering(params, i, leader);
        }
        let rules = NeighbourRules::new(params, v);
        let mut acc = Neighbours::default();
        self.for_each_neighbour(search, i, params.search_radius(), |j| {
            if Some(j) == predator {
                return;
            }
            let q = self.positions[j];
            let d = p - q;
            rules.add(&mut acc, d, d.length_squared(), v, self.velocities[j]);
        });
        self.finish_steering(params, p, v, &acc, leader, predator)
    }

    /// The predator chases the nearest boid within four search radii, else patrols.
    fn predator_steering(&self, params: &BoidParams, i: usize, leader: Option<usize>) -> Vec3 {
        let p = self.positions[i];
        let mut force = Vec3::ZERO;
        let mut best = (f32::INFINITY, p);
        // One boid scanning all others is O(N), whatever the search.
        for (j, &q) in self.positions.iter().enumerate() {
            let d = (q - p).length_squared();
            if j != i
                && Some(j) != leader
                && d < best.0
                && d < 16.0 * params.search_radius().powi(2)
            {
                best = (d, q);
            }
        }
        if best.0.is_finite() {
            force += 3.0 * (best.1 - p);
        } else {
            force += -p * 0.5; // patrol towards the middle
        }
        self.environment_steering(params, p, force)
    }

    /// The rules' sums turned into a force, plus leader, predator, obstacles and box; clamped.
    fn finish_steering(
        &self,
        params: &BoidParams,
        p: Vec3,
        v: Vec3,
        acc: &Neighbours,
        leader: Option<usize>,
        predator: Option<usize>,
    ) -> Vec3 {
        let mut force = Vec3::ZERO;
        if acc.n_c > 0.0 {
            force += params.cohesion.weight * (acc.offset / acc.n_c);
        }
        if acc.n_a > 0.0 {
            force += params.alignment.weight * (acc.mean_v / acc.n_a - v);
        }
        force += params.separation.weight * acc.sep + acc.law;
        if let (Some(l), Some(w)) = (leader, params.leader) {
            force += w * (self.positions[l] - p).clamp_length_max(2.0);
        }
        if let (Some(k), Some((flee_radius, flee_weight))) = (predator, params.predator) {
            let d = p - self.positions[k];
            let d2 = d.length_squared();
            if d2 < flee_radius * flee_radius && d2 > 0.0 {
                force += flee_weight * d / d2;
            }
        }
        self.environment_steering(params, p, force)
    }

    /// Obstacles and the bounding box added to `force`, then the force clamp.
    fn environment_steering(&self, params: &BoidParams, p: Vec3, mut force: Vec3) -> Vec3 {
        // Obstacles: push out along the normal when inside the obstacle's margin.
        for o in &params.obstacles {
            let d = p - o.center;
            let dist = d.length();
            let margin = o.radius + 0.6;
            if dist < margin && dist > 0.0 {
                force += params.avoid_weight * (margin - dist) / 0.6 * (d / dist);
            }
        }
        // The bounding box: a spring back in on each axis once outside.
        let b = params.bounds;
        let outside = p - p.clamp(-b, b);
        force -= params.bounds_weight * outside;
        force.clamp_length_max(params.max_force)
    }

    /// Every boid's steering with the grid, written into `self.forces`, walking the boids in
    /// cell order over the grid's sorted copies of positions and velocities: a boid and its
    /// neighbours then sit close together in memory (in flock order every neighbour was a jump
    /// across the arrays; at 100k boids, a cache miss each). Only the cells the search ball
    /// reaches are scanned ([`Grid::for_each_run_near`]). Without a distance law the
    /// candidates are tested and summed four at a time ([`Flock::steer_simd`]); with one, one at
    /// a time, in the order of [`Flock::steering`] (so the same bits).
    fn steer_all_with_grid(
        &mut self,
        params: &BoidParams,
        leader: Option<usize>,
        predator: Option<usize>,
    ) {
        let mut forces = std::mem::take(&mut self.forces);
        let base_rules = NeighbourRules::new(params, Vec3::ZERO);
        let pred_slot =
            predator.and_then(|k| self.grid.sorted().iter().position(|&i| i as usize == k));
        // The SIMD path skips the predator by a NaN x (restored below).
        if let Some(k) = pred_slot {
            self.grid.soa_mut()[0][k] = f32::NAN;
        }
        let sorted = self.grid.sorted();
        let columns = Columns::new(self.grid.soa());
        let [dx, dy, dz] = self.grid.dims.map(|d| d as usize);
        // Cell by cell, so each boid's cell coordinates come without a division or a lookup.
        for ck in 0..dz {
            for cj in 0..dy {
                for ci in 0..dx {
                    let cell = (ci, cj, ck);
                    let run = self
                        .grid
                        .run(ci + dx * (cj + dy * ck), ci + dx * (cj + dy * ck));
                    if run.is_empty() {
                        continue;
                    }
                    let search = self.grid.cell_search(cell);
                    for s in run {
                        let i = sorted[s] as usize;
                        if Some(i) == predator {
                            forces[i] = self.predator_steering(params, i, leader);
                            continue;
                        }
                        let acc = if params.law == ForceLaw::None {
                            self.steer_simd(params, &base_rules, &columns, s, &search)
                        } else {
                            self.steer_scalar(params, &base_rules, s, cell, pred_slot)
                        };
                        let (p, v) = (self.grid.sorted_position(s), self.grid.sorted_velocity(s));
                        forces[i] = self.finish_steering(params, p, v, &acc, leader, predator);
                    }
                }
            }
        }
        if let Some(k) = pred_slot {
            self.grid.soa_mut()[0][k] = self.positions[self.grid.sorted()[k] as usize].x;
        }
        self.forces = forces;
    }

    /// The neighbour sums of the boid in slot `s` of cell `cell`, one candidate at a time.
    fn steer_scalar(
        &self,
        params: &BoidParams,
        base_rules: &NeighbourRules,
        s: usize,
        cell: (usize, usize, usize),
        pred_slot: Option<usize>,
    ) -> Neighbours {
        let grid = &self.grid;
        let r2 = params.search_radius().powi(2);
        let (p, v) = (grid.sorted_position(s), grid.sorted_velocity(s));
        let rules = NeighbourRules {
            v_len: v.length(),
            ..*base_rules
        };
        let pred = pred_slot.unwrap_or(usize::MAX);
        let mut acc = Neighbours::default();
        grid.for_each_run_near(p, cell, r2, |run| {
            for t in run {
                let q = grid.sorted_position(t);
                if (q - p).length_squared() <= r2 && t != s && t != pred {
                    let d = p - q;
                    rules.add(&mut acc, d, d.length_squared(), v, grid.sorted_velocity(t));
                }
            }
        });
        acc
    }

    /// The neighbour sums of the boid in slot `s` of cell `cell` without a distance law,
    /// four candidates at a time (SSE2 natively, simd128 in wasm, through glam's `Vec4`): every
    /// test becomes a lane mask (in the ball, in view) and every sum a masked add, so there is
    /// no branch per candidate. The tests are the scalar ones, lane by lane, so the neighbour
    /// sets are the same; the sums run in another order (four partial sums), so they differ
    /// from the scalar path's by rounding.
    ///
    /// What keeps the loop short (it is most of the step): the six arrays are read through
    /// pointers checked once per step, four lanes at a time with no lane mask (a run's last
    /// chunk reads past its end, see `simd_sums`); the counts are integer lane counters; the
    /// field of view is one comparison of signed squares; cohesion sums `p − q`, which the
    /// distance test computed anyway; when cohesion and alignment share a radius (the
    /// default), one mask and one count serve both.
    fn steer_simd(
        &self,
        params: &BoidParams,
        base_rules: &NeighbourRules,
        columns: &Columns,
        s: usize,
        search: &CellSearch,
    ) -> Neighbours {
        let (p, v) = (self.grid.sorted_position(s), self.grid.sorted_velocity(s));
        let rules = NeighbourRules {
            v_len: v.length(),
            ..*base_rules
        };
        let kernel = SimdKernel::new(&rules, p, v);
        let r2 = params.search_radius().powi(2);
        let same_radii = rules.rc2 == rules.ra2;
        // One loop per case, so that the loop has no branch but separation's (whether the view
        // is tested depends on the boid's speed; the radii are the flock's).
        let (c, g) = (columns, search);
        let [cohesion, alignment, sep] = match (same_radii, kernel.view) {
            (true, View::All) => self.simd_sums::<true, VIEW_ALL>(&kernel, c, p, g, r2),
            (true, View::Cone) => self.simd_sums::<true, VIEW_CONE>(&kernel, c, p, g, r2),
            (false, View::All) => self.simd_sums::<false, VIEW_ALL>(&kernel, c, p, g, r2),
            (false, View::Cone) => self.simd_sums::<false, VIEW_CONE>(&kernel, c, p, g, r2),
        };
        // Take the boid itself off (see `simd_sums`): 1 from each count, v from the velocities.
        Neighbours {
            n_c: cohesion.w - 1.0,
            n_a: alignment.w - 1.0,
            offset: -cohesion.truncate(),
            mean_v: alignment.truncate() - v,
            sep: sep.truncate(),
            law: Vec3::ZERO,
        }
    }

    /// The sums of [`Flock::steer_simd`] for the boid at `p` in `search`'s cell, over the runs
    /// a ball of squared radius `r2` reaches: `(Σ (p − q), n_c)`, `(Σ w, n_a)` and separation's
    /// sum. The boid itself is not masked out: it is always in
    /// its own run, at d2 = 0, so it adds exactly its v to the alignment sum and 1 to both
    /// counts (and nothing to cohesion's p − q or to separation); the caller takes that off.
    /// The predator's x is NaN in these arrays for the step (see `steer_all_with_grid`), which
    /// fails every comparison.
    // Not inlined: six copies of the loop inlined into one step made the wasm engine's code
    // slower (one function per case keeps each small enough to compile well).
    #[inline(never)]
    fn simd_sums<const SAME_RADII: bool, const VIEW: u8>(
        &self,
        kernel: &SimdKernel,
        columns: &Columns,
        p: Vec3,
        search: &CellSearch,
        r2: f32,
    ) -> [Vec4; 3] {
        let len = columns.len;
        // The four lanes from slot `at` of all six arrays.
        let chunk = |at: usize| {
            debug_assert!(at + 4 <= len);
            // SAFETY: called below only with `at < end` where `end + 3 <= len` (asserted per
            // run), so slots at..at + 4 lie within every array (`Columns::new`).
            columns
                .ptrs
                .map(|c| unsafe { lanes::load(c.add(at).cast::<[f32; 4]>().read_unaligned()) })
        };
        let mut sums = SimdSums::default();
        let mut runs = [(0u32, 0u32); 9];
        self.grid.runs_near(search, p, r2, &mut runs);
        // Whole chunks only: a run's last chunk reads up to three slots past its end, which
        // hold other cells' boids (outside the ball: every boid within it is in some run, so
        // they fail the distance test) or, past the last boid, padding with a NaN x that
        // fails every test. No slot is read twice: the runs come in increasing order, and
        // each starts at the first slot not read yet.
        let mut done = 0usize;
        for &(start, end) in &runs {
            let (mut at, end) = ((start as usize).max(done), end as usize);
            // A run ends at most at the last boid, so its last chunk ends within the padding.
            assert!(end + 3 <= len);
            while at < end {
                kernel.add::<SAME_RADII, VIEW>(&mut sums, chunk(at));
                at += 4;
            }
            done = done.max(at);
        }
        let na = if SAME_RADII { sums.nc } else { sums.na };
        [
            lanes::sum4(sums.dx, sums.dy, sums.dz, sums.nc.as_floats()),
            lanes::sum4(sums.wx, sums.wy, sums.wz, na.as_floats()),
            sums.sep.extend(0.0),
        ]
    }
}

/// The grid's six sorted arrays (see `Grid::soa`) as pointers, checked once per step to have one
/// length: the boids, then 3 padding entries.
struct Columns<'a> {
    ptrs: [*const f32; 6],
    len: usize,
    _soa: std::marker::PhantomData<&'a [Vec<f32>; 6]>,
}

impl<'a> Columns<'a> {
    fn new(soa: &'a [Vec<f32>; 6]) -> Self {
        let len = soa[0].len();
        assert!(soa.iter().all(|a| a.len() == len) && len >= grid::PADDING);
        Self {
            ptrs: soa.each_ref().map(|a| a.as_ptr()),
            len,
            _soa: std::marker::PhantomData,
        }
    }
}

/// The few lane operations [`SimdKernel`] needs beyond glam's `Vec4`: a load of four floats, a
/// lane mask applied with one `and` or `andnot` (`Vec4::select(m, x, 0)` is a three-instruction
/// bit-select in wasm), and lane counters.
mod lanes {
    use glam::{BVec4A, Vec4};

    #[inline(always)]
    pub fn load(a: [f32; 4]) -> Vec4 {
        Vec4::from_array(a)
    }

    #[inline(always)]
    pub fn and(m: BVec4A, x: Vec4) -> Vec4 {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            use core::arch::wasm32::{v128, v128_and};
            Vec4::from(v128_and(v128::from(m), v128::from(x)))
        }
        #[cfg(target_arch = "x86_64")]
        {
            use core::arch::x86_64::{__m128, _mm_and_ps};
            // SAFETY: SSE2 is part of every x86-64 CPU (glam's Vec4 is built on it there).
            Vec4::from(unsafe { _mm_and_ps(__m128::from(m), __m128::from(x)) })
        }
        #[cfg(not(any(
            all(target_arch = "wasm32", target_feature = "simd128"),
            target_arch = "x86_64"
        )))]
        {
            Vec4::select(m, x, Vec4::ZERO)
        }
    }

    /// `x` in the lanes where `m` is false, 0 elsewhere (`x & !m`: one instruction).
    #[inline(always)]
    pub fn and_not(m: BVec4A, x: BVec4A) -> BVec4A {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            use core::arch::wasm32::{v128, v128_andnot};
            // SAFETY: BVec4A is a v128 of all-ones or all-zeros lanes, as the result is.
            unsafe {
                core::mem::transmute::<v128, BVec4A>(v128_andnot(v128::from(x), v128::from(m)))
            }
        }
        #[cfg(target_arch = "x86_64")]
        {
            use core::arch::x86_64::{__m128, _mm_andnot_ps};
            // SAFETY: SSE2; BVec4A is an __m128 of all-ones or all-zeros lanes, as the result is.
            unsafe {
                core::mem::transmute::<__m128, BVec4A>(_mm_andnot_ps(
                    __m128::from(m),
                    __m128::from(x),
                ))
            }
        }
        #[cfg(not(any(
            all(target_arch = "wasm32", target_feature = "simd128"),
            target_arch = "x86_64"
        )))]
        {
            x & !m
        }
    }

    /// Four lane counters: adding a mask is one integer subtraction (a true lane is −1).
    #[derive(Clone, Copy, Default)]
    pub struct Count([i32; 4]);

    impl Count {
        #[inline(always)]
        pub fn add(&mut self, m: BVec4A) {
            #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
            {
                use core::arch::wasm32::{i32x4_sub, v128};
                // SAFETY: [i32; 4] and v128 have the same size, and every bit pattern is valid.
                unsafe {
                    let c = core::mem::transmute::<[i32; 4], v128>(self.0);
                    self.0 = core::mem::transmute::<v128, [i32; 4]>(i32x4_sub(c, v128::from(m)));
                }
            }
            #[cfg(target_arch = "x86_64")]
            {
                use core::arch::x86_64::{__m128, __m128i, _mm_castps_si128, _mm_sub_epi32};
                // SAFETY: SSE2; [i32; 4] and __m128i have the same size, every bit pattern is
                // valid.
                unsafe {
                    let c = core::mem::transmute::<[i32; 4], __m128i>(self.0);
                    let m = _mm_castps_si128(__m128::from(m));
                    self.0 = core::mem::transmute::<__m128i, [i32; 4]>(_mm_sub_epi32(c, m));
                }
            }
            #[cfg(not(any(
                all(target_arch = "wasm32", target_feature = "simd128"),
                target_arch = "x86_64"
            )))]
            {
                let b = m.bitmask();
                for (l, c) in self.0.iter_mut().enumerate() {
                    *c += ((b >> l) & 1) as i32;
                }
            }
        }

        /// The counts as floats (exact below 2²⁴).
        #[inline(always)]
        pub fn as_floats(&self) -> Vec4 {
            Vec4::from_array(self.0.map(|c| c as f32))
        }
    }

    /// `(Σ a, Σ b, Σ c, Σ d)`, each the sum of its four lanes, by a transposition (six
    /// shuffles and four adds instead of four separate sums of lanes; the same order of
    /// additions in every lane: `(l0 + l2) + (l1 + l3)`).
    #[inline(always)]
    pub fn sum4(a: Vec4, b: Vec4, c: Vec4, d: Vec4) -> Vec4 {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            use core::arch::wasm32::{f32x4_add, i32x4_shuffle, v128};
            let (a, b, c, d) = (v128::from(a), v128::from(b), v128::from(c), v128::from(d));
            // (a0 + a2, b0 + b2, a1 + a3, b1 + b3) and the same for c, d.
            let ab = f32x4_add(
                i32x4_shuffle::<0, 4, 1, 5>(a, b),
                i32x4_shuffle::<2, 6, 3, 7>(a, b),
            );
            let cd = f32x4_add(
                i32x4_shuffle::<0, 4, 1, 5>(c, d),
                i32x4_shuffle::<2, 6, 3, 7>(c, d),
            );
            Vec4::from(f32x4_add(
                i32x4_shuffle::<0, 1, 4, 5>(ab, cd),
                i32x4_shuffle::<2, 3, 6, 7>(ab, cd),
            ))
        }
        #[cfg(target_arch = "x86_64")]
        {
            use core::arch::x86_64::{
                __m128, _mm_add_ps, _mm_movehl_ps, _mm_movelh_ps, _mm_unpackhi_ps, _mm_unpacklo_ps,
            };
            let (a, b, c, d) = (
                __m128::from(a),
                __m128::from(b),
                __m128::from(c),
                __m128::from(d),
            );
            // SAFETY: SSE, part of every x86-64 CPU.
            unsafe {
                let ab = _mm_add_ps(_mm_unpacklo_ps(a, b), _mm_unpackhi_ps(a, b));
                let cd = _mm_add_ps(_mm_unpacklo_ps(c, d), _mm_unpackhi_ps(c, d));
                Vec4::from(_mm_add_ps(_mm_movelh_ps(ab, cd), _mm_movehl_ps(cd, ab)))
            }
        }
        #[cfg(not(any(
            all(target_arch = "wasm32", target_feature = "simd128"),
            target_arch = "x86_64"
        )))]
        {
            let s = |v: Vec4| (v.x + v.z) + (v.y + v.w);
            Vec4::new(s(a), s(b), s(c), s(d))
        }
    }
}

/// The lane sums of [`Flock::steer_simd`]: cohesion's `Σ (p − q)` and count, alignment's
/// `Σ w` and count, separation.
#[derive(Default)]
struct SimdSums {
    dx: Vec4,
    dy: Vec4,
    dz: Vec4,
    nc: lanes::Count,
    wx: Vec4,
    wy: Vec4,
    wz: Vec4,
    na: lanes::Count,
    sep: Vec3,
}

/// Whether a boid's neighbours get the field-of-view test ([`NeighbourRules::behind`]): not
/// with a full circle, nor for a boid that stands still (it has no heading).
#[derive(Clone, Copy, PartialEq, Eq)]
enum View {
    All,
    Cone,
}

/// [`View`] as const generic parameters of [`SimdKernel::add`].
const VIEW_ALL: u8 = 0;
const VIEW_CONE: u8 = 1;

/// One boid's tests, splatted to four lanes, for [`Flock::steer_simd`].
struct SimdKernel {
    p: [Vec4; 3],
    v: [Vec4; 3],
    rc2: Vec4,
    ra2: Vec4,
    rs2: Vec4,
    /// `−b|b|` with `b = cos(fov/2)|v|` (see [`NeighbourRules::behind`]).
    cone: Vec4,
    view: View,
}

impl SimdKernel {
    fn new(rules: &NeighbourRules, p: Vec3, v: Vec3) -> Self {
        let b = rules.cos_half * rules.v_len;
        Self {
            p: [Vec4::splat(p.x), Vec4::splat(p.y), Vec4::splat(p.z)],
            v: [Vec4::splat(v.x), Vec4::splat(v.y), Vec4::splat(v.z)],
            rc2: Vec4::splat(rules.rc2),
            ra2: Vec4::splat(rules.ra2),
            rs2: Vec4::splat(rules.rs2),
            cone: Vec4::splat(-(b * b.abs())),
            view: if rules.all_round || rules.v_len <= 0.0 {
                View::All
            } else {
                View::Cone
            },
        }
    }

    /// Adds the candidates `q` (velocities `w`) that pass the tests; with `SAME_RADII`
    /// (cohesion and alignment share their radius) one mask and one count serve both, and
    /// `sums.na` is left to the caller.
    #[inline(always)]
    fn add<const SAME_RADII: bool, const VIEW: u8>(
        &self,
        sums: &mut SimdSums,
        [qx, qy, qz, wx, wy, wz]: [Vec4; 6],
    ) {
        let zero = Vec4::ZERO;
        // d = p − q, d2 = |d|² (the order of glam's length_squared).
        let (dx, dy, dz) = (self.p[0] - qx, self.p[1] - qy, self.p[2] - qz);
        let d2 = dx * dx + dy * dy + dz * dz;
        let away = d2.cmpgt(zero);
        // The lanes a test keeps: within its radius and, with a field of view, not hidden.
        let keep = |within: BVec4A, hidden: BVec4A| {
            if VIEW == VIEW_ALL {
                within
            } else {
                lanes::and_not(hidden, within)
            }
        };
        let hidden = if VIEW == VIEW_ALL {
            BVec4A::splat(false)
        } else {
            // With a = (q − p)·v = −e, e = d·v: behind is a|a| < b|b| d2, that is
            // e|e| > −b|b| d2, exactly (negation is exact); d2 > 0 is never behind.
            let e = dx * self.v[0] + dy * self.v[1] + dz * self.v[2];
            (e * e.abs()).cmpgt(self.cone * d2) & away
        };
        let mc = keep(d2.cmple(self.rc2), hidden);
        let ma = if SAME_RADII {
            mc
        } else {
            keep(d2.cmple(self.ra2), hidden)
        };
        sums.dx += lanes::and(mc, dx);
        sums.dy += lanes::and(mc, dy);
        sums.dz += lanes::and(mc, dz);
        sums.nc.add(mc);
        sums.wx += lanes::and(ma, wx);
        sums.wy += lanes::and(ma, wy);
        sums.wz += lanes::and(ma, wz);
        if !SAME_RADII {
            sums.na.add(ma);
        }
        let ms = keep(d2.cmple(self.rs2) & away, hidden);
        if ms.any() {
            // Rare: the separation radius is small.
            sums.sep += Vec3::new(
                lanes::and(ms, dx / d2).element_sum(),
                lanes::and(ms, dy / d2).element_sum(),
                lanes::and(ms, dz / d2).element_sum(),
            );
        }
    }
}

/// What the three rules and the distance law sum over a boid's neighbours.
#[derive(Default)]
struct Neighbours {
    /// The numbers of cohesion and alignment neighbours (whole numbers, as floats: the step
    /// divides by them).
    n_c: f32,
    n_a: f32,
    /// `Σ (q − p)` over the cohesion neighbours: their centre is `p + offset / n_c`.
    offset: Vec3,
    mean_v: Vec3,
    sep: Vec3,
    law: Vec3,
}

/// One boid's view of its neighbours: squared radii and the field-of-view test, with the cosine
/// and `|v|` computed once per boid (a cosine per neighbour pair was most of the step's time in
/// wasm).
#[derive(Clone, Copy)]
struct NeighbourRules {
    rc2: f32,
    ra2: f32,
    rs2: f32,
    rl2: f32,
    law: ForceLaw,
    all_round: bool,
    cos_half: f32,
    v_len: f32,
}

impl NeighbourRules {
    /// Whether a neighbour at squared distance `d2 > 0` with `(q − p)·v = a` lies outside the
    /// field of view, `a < cos(fov/2) |q − p| |v|`, without the square root: with
    /// `b = cos(fov/2) |v|`, both sides squared with their signs kept (`x ↦ x|x|` is
    /// increasing), that is `a|a| < b|b| d2`. The SIMD step ([`Flock::steer_all_with_grid`])
    /// evaluates the same products lane by lane, so both decide every pair alike.
    #[inline(always)]
    fn behind(&self, a: f32, d2: f32) -> bool {
        let b = self.cos_half * self.v_len;
        a * a.abs() < b * b.abs() * d2
    }

    fn new(params: &BoidParams, v: Vec3) -> Self {
        Self {
            rc2: params.cohesion.radius.powi(2),
            ra2: params.alignment.radius.powi(2),
            rs2: params.separation.radius.powi(2),
            rl2: params.law_radius.powi(2),
            law: params.law,
            all_round: params.fov_deg >= 360.0,
            cos_half: (0.5 * params.fov_deg).to_radians().cos(),
            v_len: v.length(),
        }
    }

    /// Adds neighbour `q` (velocity `w`) of the boid at `p` with velocity `v`, where
    /// `d = p − q` and `d2 = |d|²`, unless it is outside the field of view.
    #[inline(always)]
    fn add(&self, acc: &mut Neighbours, d: Vec3, d2: f32, v: Vec3, w: Vec3) {
        if !self.all_round && self.v_len > 0.0 && d2 > 0.0 && self.behind((-d).dot(v), d2) {
            return;
        }
        if d2 <= self.rc2 {
            acc.offset -= d;
            acc.n_c += 1.0;
        }
        if d2 <= self.ra2 {
            acc.mean_v += w;
            acc.n_a += 1.0;
        }
        if d2 <= self.rs2 && d2 > 0.0 {
            acc.sep += d / d2;
        }
        if d2 <= self.rl2 && d2 > 0.0 && self.law != ForceLaw::None {
            let x = d2.sqrt();
            acc.law += self.law.f(x) * (-d / x);
        }
    }
}

/// The flock the benchmarks step (native criterion and the browser bench page, so both measure
/// the same work): `n` boids at one boid per cubic metre in a cube (about 14 within the default
/// 1.5 m radius), default rules with a 270° field of view, seeded.
pub fn benchmark_flock(n: usize) -> Result<(BoidParams, Flock), String> {
    let params = benchmark_params(n);
    let flock = Flock::new(n, &params, BENCHMARK_SEED)?;
    Ok((params, flock))
}

/// [`benchmark_flock`]'s parameters for `n` boids: its box grows with `n`, so the density stays.
pub fn benchmark_params(n: usize) -> BoidParams {
    let half = 0.5 * (n.max(1) as f32).cbrt();
    BoidParams {
        bounds: Vec3::splat(half),
        ..Default::default()
    }
}

/// [`benchmark_flock`]'s seed: with [`seeded_start`], its start at any count (the GPU benchmarks
/// step more boids than a [`Flock`] takes).
pub const BENCHMARK_SEED: u64 = 0x5eed_b01d;

/// A white-box check of the grid step's cell-order path against the per-boid search: it reads
/// the step's private stages, so it lives beside them. The native tests call it
/// (tests/internals/boids.rs); only a build with debug assertions (the test profile) has it.
#[cfg(debug_assertions)]
#[doc(hidden)]
pub mod white_box {
    use super::*;

    /// The cell-order grid step gives every boid the force that the per-boid
    /// [`Flock::steering`] finds through [`Grid::for_each_neighbour`], with a leader, a predator,
    /// a field of view on and off: the same bits with a distance law (one candidate at a time,
    /// in the same order), and the same up to rounding without one (four lanes of partial sums).
    pub fn cell_order_steering_matches_the_per_boid_path() {
        for (fov_deg, law) in [
            (270.0, ForceLaw::None),
            (360.0, ForceLaw::None),
            (120.0, ForceLaw::None),
            (360.0, ForceLaw::InversePower { a1: 0.2, a2: 0.01 }),
            (200.0, ForceLaw::InversePower { a1: 0.2, a2: 0.01 }),
        ] {
            // Cohesion and alignment with one radius (the default, one mask for both in the
            // SIMD step) and with two.
            let alignment_radius = if fov_deg == 270.0 { 1.5 } else { 1.1 };
            let params = BoidParams {
                fov_deg,
                law,
                leader: Some(1.0),
                predator: Some((2.0, 3.0)),
                alignment: Rule {
                    weight: 2.0,
                    radius: alignment_radius,
                },
                ..Default::default()
            };
            let mut flock = Flock::new(2000, &params, 9).unwrap();
            for _ in 0..5 {
                flock.step(&params, Search::Grid, 1.0 / 60.0);
            }
            // A few boids outside the box (clamped into the border cells) and two at one point.
            flock.positions[10] = params.bounds * 1.7;
            flock.positions[11] = -params.bounds * 1.2;
            flock.positions[12] = flock.positions[13];
            let radius = params.search_radius();
            let margin = Vec3::splat(radius);
            flock
                .grid
                .configure(-params.bounds - margin, params.bounds + margin, radius);
            flock
                .grid
                .rebuild_with_velocities(&flock.positions, &flock.velocities);
            let (leader, predator) = flock.roles(&params);
            flock.steer_all_with_grid(&params, leader, predator);
            for i in 0..flock.len() {
                let simple = flock.steering(&params, Search::Grid, i, leader, predator);
                let fast = flock.forces[i];
                if law == ForceLaw::None {
                    assert!(
                        (simple - fast).length() <= 1e-4 * (1.0 + simple.length()),
                        "boid {i}, fov {fov_deg}: {simple} vs {fast}"
                    );
                } else {
                    assert_eq!(
                        simple.to_array().map(f32::to_bits),
                        fast.to_array().map(f32::to_bits),
                        "boid {i}, fov {fov_deg}"
                    );
                }
            }
        }
    }
}
