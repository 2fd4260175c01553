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

pub use grid::{cell_index, for_each_neighbour_naive, Grid, MAX_GRID_CELLS};

use crate::particles::{semi_implicit_euler_step, Rng, Sphere};
use glam::Vec3;

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
    /// `f(x) = a1 exp(−k ((x − x0)/x0)²) − a2 exp(−x/x0)`: attraction peaking at `x0`,
    /// repulsion strongest at contact. (The course writes the repulsion as `a2 exp(x/x0)`;
    /// with a minus sign in the exponent it fades with distance instead of growing.)
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

/// How the flock finds neighbours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// Every pair: O(N²).
    Naive,
    /// A uniform grid with cells as wide as the largest radius: O(N) at bounded density.
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
    /// `count ≤` [`MAX_BOIDS`] boids at seeded random places inside `bounds`, moving at half the
    /// maximum speed in random directions.
    pub fn new(count: usize, params: &BoidParams, seed: u64) -> Result<Self, String> {
        if count > MAX_BOIDS {
            return Err(format!("{count} boids is too many (at most {MAX_BOIDS})"));
        }
        params.validate()?;
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
            .map(|_| rng.on_unit_sphere() * 0.5 * params.max_speed)
            .collect();
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
        if search == Search::Grid {
            let margin = Vec3::splat(radius);
            self.grid
                .configure(-params.bounds - margin, params.bounds + margin, radius);
            self.grid.rebuild(&self.positions);
        }
        let (leader, predator) = self.roles(params);
        for i in 0..n {
            self.forces[i] = self.steering(params, search, i, leader, predator);
        }
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
            let clamped =
                v.clamp_length_max(params.max_speed * if Some(i) == predator { 1.3 } else { 1.0 });
            *p += (clamped - *v) * dt;
            *v = clamped;
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
        let mut force = Vec3::ZERO;
        if Some(i) == predator {
            // Chase the nearest boid within four search radii, else patrol.
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
        } else {
            let (mut n_c, mut n_a) = (0u32, 0u32);
            let (mut centre, mut mean_v, mut sep, mut law) =
                (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
            let (rc2, ra2, rs2, rl2) = (
                params.cohesion.radius.powi(2),
                params.alignment.radius.powi(2),
                params.separation.radius.powi(2),
                params.law_radius.powi(2),
            );
            // The field-of-view test of `sees`, with its cosine and |v| computed once per boid
            // (a cosine per neighbour pair was most of the step's time in wasm).
            let all_round = params.fov_deg >= 360.0;
            let cos_half = (0.5 * params.fov_deg).to_radians().cos();
            let v_len = v.length();
            self.for_each_neighbour(search, i, params.search_radius(), |j| {
                if Some(j) == predator {
                    return;
                }
                let q = self.positions[j];
                if !all_round && v_len > 0.0 {
                    let to = q - p;
                    let l = to.length();
                    if l > 0.0 && to.dot(v) < cos_half * l * v_len {
                        return;
                    }
                }
                let d = p - q;
                let d2 = d.length_squared();
                if d2 <= rc2 {
                    centre += q;
                    n_c += 1;
                }
                if d2 <= ra2 {
                    mean_v += self.velocities[j];
                    n_a += 1;
                }
                if d2 <= rs2 && d2 > 0.0 {
                    sep += d / d2;
                }
                if d2 <= rl2 && d2 > 0.0 && params.law != ForceLaw::None {
                    let x = d2.sqrt();
                    law += params.law.f(x) * (-d / x);
                }
            });
            if n_c > 0 {
                force += params.cohesion.weight * (centre / n_c as f32 - p);
            }
            if n_a > 0 {
                force += params.alignment.weight * (mean_v / n_a as f32 - v);
            }
            force += params.separation.weight * sep + law;
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
        }
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
}

/// The flock the benchmarks step (native criterion and the browser bench page, so both measure
/// the same work): `n` boids at one boid per cubic metre in a cube (about 14 within the default
/// 1.5 m radius), default rules with a 270° field of view, seeded.
pub fn benchmark_flock(n: usize) -> Result<(BoidParams, Flock), String> {
    let half = 0.5 * (n.max(1) as f32).cbrt();
    let params = BoidParams {
        bounds: Vec3::splat(half),
        ..Default::default()
    };
    let flock = Flock::new(n, &params, 0x5eed_b01d)?;
    Ok((params, flock))
}
