//! The logic of the GPU paths (native, tested natively): what the skinning shader receives and
//! how it mixes it, the caps, and the statistics that compare a GPU simulation with the CPU one.
//!
//! **Skinning in the vertex shader** (`src/render/skin.rs`, `shaders/skin.wgsl`). The bind-pose
//! vertices, joints and weights are uploaded once; per frame only the palette travels, as a
//! uniform array, because WebGL2 has no storage buffers in vertex shaders. Each joint takes three
//! `vec4`s: for LBS the three rows of `K_j`'s 3 × 4 matrix, for DQS the real and the dual part
//! (and an unused row). A uniform block is at least 16 KiB everywhere, which bounds the palette:
//! [`MAX_GPU_JOINTS`] joints (6 KiB). A character with more joints stays on the CPU.
//! [`lbs_like_shader`] and [`dqs_like_shader`] are the shader's formulas in Rust, so a native
//! test checks the packing against [`crate::skinning`]'s skinning.

use super::{palette, Frame};
use crate::draw::{SkinMeshId, SkinnedDraw};
use crate::rigid::DualQuat;
use glam::{Affine3A, Mat4, Vec3, Vec4};

/// The most joints one GPU-skinned mesh may use (the uniform palette's size; see the module).
pub const MAX_GPU_JOINTS: usize = 128;

/// `vec4`s per joint in the palette.
pub const ROWS_PER_JOINT: usize = 3;

fn check_joints(n: usize) -> Result<(), String> {
    if n > MAX_GPU_JOINTS {
        Err(format!(
            "{n} joints is too many for GPU skinning (at most {MAX_GPU_JOINTS}, the size of the \
             shader's uniform palette): skinned on the CPU instead"
        ))
    } else {
        Ok(())
    }
}

/// The LBS palette as the shader reads it: per joint the three rows of `K_j` (3 × 4).
pub fn pack_lbs(palette: &[Affine3A]) -> impl Iterator<Item = [Vec4; 3]> + '_ {
    palette.iter().map(|k| {
        let m = Mat4::from(*k).transpose();
        [m.x_axis, m.y_axis, m.z_axis]
    })
}

/// The DQS palette as the shader reads it: per joint `[real (x, y, z, w), dual, unused]`.
pub fn pack_dqs(palette: &[DualQuat]) -> impl Iterator<Item = [Vec4; 3]> + '_ {
    palette
        .iter()
        .map(|q| [Vec4::from(q.real), Vec4::from(q.dual), Vec4::ZERO])
}

/// Adds a GPU-skinned draw of `mesh` by LBS with `palette` (`K_j = M_j B_j⁻¹`, from
/// [`crate::skinning::skinning_palette`]). `color`: `None` uses the mesh's vertex colours.
///
/// # Errors
/// More than [`MAX_GPU_JOINTS`] joints.
pub fn draw_skinned_lbs(
    frame: &mut Frame,
    mesh: SkinMeshId,
    model: Mat4,
    color: Option<Vec3>,
    palette: &[Affine3A],
) -> Result<(), String> {
    check_joints(palette.len())?;
    let start = frame.skin_palette.len();
    frame.skin_palette.extend(pack_lbs(palette));
    push(frame, mesh, model, color, false, start);
    Ok(())
}

/// As [`draw_skinned_lbs`], by DQS with the dual quaternions of
/// [`crate::skinning::dual_quat_palette`].
///
/// # Errors
/// More than [`MAX_GPU_JOINTS`] joints.
pub fn draw_skinned_dqs(
    frame: &mut Frame,
    mesh: SkinMeshId,
    model: Mat4,
    color: Option<Vec3>,
    palette: &[DualQuat],
) -> Result<(), String> {
    check_joints(palette.len())?;
    let start = frame.skin_palette.len();
    frame.skin_palette.extend(pack_dqs(palette));
    push(frame, mesh, model, color, true, start);
    Ok(())
}

fn push(
    frame: &mut Frame,
    mesh: SkinMeshId,
    model: Mat4,
    color: Option<Vec3>,
    dqs: bool,
    start: usize,
) {
    frame.skinned.push(SkinnedDraw {
        mesh,
        model,
        color: color.unwrap_or(Vec3::ONE).extend(1.0),
        vertex_colors: color.is_none(),
        dqs,
        joints: start..frame.skin_palette.len(),
    });
}

/// Whether a mesh whose weights name joints below `joint_bound` can be skinned on the GPU with a
/// palette of `joints` joints; the reason if not.
pub fn gpu_skinnable(joint_bound: usize, joints: usize) -> Result<(), String> {
    check_joints(joints)?;
    if joint_bound > joints {
        return Err(format!(
            "the weights name joint {} but the palette has {joints}",
            joint_bound - 1
        ));
    }
    Ok(())
}

/// `skin.wgsl`'s LBS for one vertex, in Rust: blend the rows, then apply them.
pub fn lbs_like_shader(
    rows: &[[Vec4; 3]],
    joints: [u16; 4],
    weights: [f32; 4],
    p: Vec3,
    n: Vec3,
) -> (Vec3, Vec3) {
    let mut r = [Vec4::ZERO; 3];
    for (j, w) in joints.iter().zip(weights) {
        for (acc, row) in r.iter_mut().zip(rows[*j as usize]) {
            *acc += w * row;
        }
    }
    let p4 = p.extend(1.0);
    (
        Vec3::new(r[0].dot(p4), r[1].dot(p4), r[2].dot(p4)),
        Vec3::new(
            r[0].truncate().dot(n),
            r[1].truncate().dot(n),
            r[2].truncate().dot(n),
        ),
    )
}

/// `skin.wgsl`'s DQS for one vertex, in Rust: signs against the first joint (the pivot), blend,
/// rotate by the unnormalised blend with the factor `2 / ‖r‖²`, translate.
pub fn dqs_like_shader(
    rows: &[[Vec4; 3]],
    joints: [u16; 4],
    weights: [f32; 4],
    p: Vec3,
    n: Vec3,
) -> (Vec3, Vec3) {
    let pivot = rows[joints[0] as usize][0];
    let (mut real, mut dual) = (Vec4::ZERO, Vec4::ZERO);
    for (j, w) in joints.iter().zip(weights) {
        let [r, d, _] = rows[*j as usize];
        let s = if pivot.dot(r) >= 0.0 { w } else { -w };
        real += s * r;
        dual += s * d;
    }
    let k = 2.0 / real.length_squared().max(1e-24);
    let (rv, w0, dv) = (real.truncate(), real.w, dual.truncate());
    let t = k * (w0 * dv - dual.w * rv + rv.cross(dv));
    let rotate = |v: Vec3| v + k * rv.cross(rv.cross(v) + w0 * v);
    (rotate(p) + t, rotate(n))
}

// ---------------------------------------------------------------------------------------------
// Compute (WebGPU only): particles and boids.
//
// The compute shaders (`src/render/shaders/particles.wgsl`, `boids.wgsl`) run the models of
// `crate::particles` and `crate::boids` one thread per particle or boid. What they receive is
// packed here, as rows of four 32-bit words (floats by their bits), with every cap checked.

use crate::boids::{leader_path, BoidParams, ForceLaw, Search};
use crate::particles::{Emitter, PositionDist, Surfaces, VelocityDist};

/// The most particle slots the GPU path allocates: about a million (48 bytes of state and 48 of
/// sprite per slot, 96 MiB in all; WebGPU guarantees 128 MiB per storage binding).
pub const MAX_GPU_PARTICLES: usize = 1 << 20;
/// Emitters and spheres one GPU particle system takes (uniform arrays in the shader).
pub const MAX_GPU_EMITTERS: usize = 4;
pub const MAX_GPU_SPHERES: usize = 8;
/// The most boids the GPU path steps with every pair tested (the O(N²) loop, tiled through
/// workgroup memory): N = 65,536 is 4·10⁹ pair tests per step.
pub const MAX_GPU_BOIDS: usize = 1 << 16;
/// The most boids the GPU path steps with the GPU uniform grid (`src/render/grid.rs`): 2²⁰,
/// 32 MiB for each of the two state buffers and the sprites (WebGPU guarantees 128 MiB per
/// storage binding), 4,096 workgroups of 256 for the grid's passes (at most 65,535 per
/// dispatch).
pub const MAX_GPU_GRID_BOIDS: usize = 1 << 20;
/// The most cells a GPU grid has: 2²¹ (8 MiB of counts). A layout that would need more gets
/// larger cells ([`GridLayout::cubic`]). The prefix sum scans blocks of [`GRID_SCAN_BLOCK`]
/// cells, then the 4,096 block sums in one workgroup, [`GRID_SCAN_BLOCK`] at a time.
pub const MAX_GPU_GRID_CELLS: usize = 1 << 21;
/// Cells one workgroup of the grid's prefix sum scans (256 threads, two cells each).
pub const GRID_SCAN_BLOCK: usize = 512;

/// Where a GPU uniform grid lies: cell `(i, j, k)` spans `origin + (i, j, k) · cell_size` to the
/// next corner and is number `i + dims.x · (j + dims.y · k)`, so a row of cells along x is one
/// run of the sorted points. Points outside are clamped into the border cells, as
/// [`crate::boids::cell_index`] does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridLayout {
    /// The corner of cell (0, 0, 0), metres.
    pub origin: Vec3,
    /// The cells' size along x, y, z, metres.
    pub cell_size: Vec3,
    pub dims: [u32; 3],
}

impl GridLayout {
    /// Cubic cells at least `radius` wide over the box `[min, max]`: the points within `radius`
    /// of a point lie in the 3 × 3 × 3 cells around its own. Cells grow by a quarter at a time
    /// while there would be more than [`MAX_GPU_GRID_CELLS`].
    ///
    /// # Errors
    /// A corner or the radius not finite, or a radius that is not positive.
    pub fn cubic(min: Vec3, max: Vec3, radius: f32) -> Result<Self, String> {
        if !(min.is_finite() && max.is_finite() && radius.is_finite() && radius > 0.0) {
            return Err(format!(
                "GPU grid: the box must be finite and the radius finite and > 0, got radius \
                 {radius}"
            ));
        }
        let extent = (max - min).max(Vec3::splat(1e-3));
        let mut size = radius;
        loop {
            let d = (extent / size).ceil().max(Vec3::ONE);
            let dims = [d.x as u32, d.y as u32, d.z as u32];
            let layout = Self {
                origin: min,
                cell_size: Vec3::splat(size),
                dims,
            };
            if layout.cells() <= MAX_GPU_GRID_CELLS {
                return Ok(layout);
            }
            size *= 1.25;
        }
    }

    /// The layout of the CPU grid `grid` (its cells a quarter as wide along x), so that the GPU
    /// grid sorts points into the very same cells (the browser test compares the two).
    pub fn of_cpu_grid(grid: &crate::boids::grid::Grid) -> Self {
        Self {
            origin: grid.origin,
            cell_size: Vec3::new(grid.x_size, grid.cell_size, grid.cell_size),
            dims: grid.dims,
        }
    }

    pub fn cells(&self) -> usize {
        self.dims.iter().map(|&d| d as usize).product()
    }

    /// How many cells along each axis a search of `radius` reaches from a point's cell (at
    /// least 1).
    pub fn reach(&self, radius: f32) -> u32 {
        ((radius / self.cell_size.min_element()).ceil() as u32).max(1)
    }

    /// The cell of `p`, as `shaders/grid_common.wgsl` computes it:
    /// ```text
    /// (i, j, k) = clamp(⌊(p − origin) · (1 / cell_size)⌋, 0, dims − 1)   (a NaN gives 0)
    /// ```
    pub fn cell_of(&self, p: Vec3) -> usize {
        let f = (p - self.origin) * self.cell_size.recip();
        let c = |x: f32, d: u32| (if x >= 0.0 { x } else { 0.0 }).min(d as f32 - 1.0) as usize;
        let [dx, dy, dz] = self.dims;
        c(f.x, dx) + dx as usize * (c(f.y, dy) + dy as usize * c(f.z, dz))
    }
}

/// The uniform block of a GPU grid of `layout` over `n` points, each `stride` `vec4`s long
/// (its position the first `vec4`'s xyz).
///
/// # Errors
/// More than [`MAX_GPU_GRID_CELLS`] cells, no points or more than [`MAX_GPU_GRID_BOIDS`], a
/// stride of 0.
pub fn grid_rows(layout: &GridLayout, n: usize, stride: u32) -> Result<Vec<Row>, String> {
    let cells = layout.cells();
    if cells == 0 || cells > MAX_GPU_GRID_CELLS {
        return Err(format!(
            "GPU grid: the cell count must lie in [1, {MAX_GPU_GRID_CELLS}], got {cells}"
        ));
    }
    if n == 0 || n > MAX_GPU_GRID_BOIDS || stride == 0 {
        return Err(format!(
            "GPU grid: 1 to {MAX_GPU_GRID_BOIDS} points of at least one vec4 each, got {n} of \
             {stride}"
        ));
    }
    let (o, inv, [dx, dy, dz]) = (layout.origin, layout.cell_size.recip(), layout.dims);
    Ok(vec![
        frow(o.x, o.y, o.z, 0.0),
        frow(inv.x, inv.y, inv.z, 0.0),
        [dx, dy, dz, cells as u32],
        [n as u32, stride, cells.div_ceil(GRID_SCAN_BLOCK) as u32, 0],
    ])
}
/// Obstacles one GPU flock takes.
pub const MAX_GPU_OBSTACLES: usize = 8;

/// One row of a compute shader's uniform block.
pub type Row = [u32; 4];

fn f(x: f32) -> u32 {
    x.to_bits()
}

fn frow(a: f32, b: f32, c: f32, d: f32) -> Row {
    [f(a), f(b), f(c), f(d)]
}

/// The CPU's share of the GPU particle system: how many particles each emitter spawns this step
/// (rate × dt with the fraction carried, as [`crate::particles::ParticleSystem::step`]) and where
/// they go. The GPU cannot swap dead particles to the end cheaply, so new particles fill the slots
/// in ring order, overwriting the oldest: with `capacity ≥ rate × longest lifetime` (the pages
/// ensure it) the ring never reaches a live particle and the model is the CPU's.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuParticleClock {
    capacity: u32,
    ring: u32,
    step: u32,
    seed: u32,
}

impl GpuParticleClock {
    /// # Errors
    /// `capacity` of 0 or over [`MAX_GPU_PARTICLES`].
    pub fn new(capacity: usize, seed: u32) -> Result<Self, String> {
        if capacity == 0 || capacity > MAX_GPU_PARTICLES {
            return Err(format!(
                "GPU particles: capacity must lie in [1, {MAX_GPU_PARTICLES}], got {capacity}"
            ));
        }
        Ok(Self {
            capacity: capacity as u32,
            ring: 0,
            step: 0,
            seed,
        })
    }

    pub fn capacity(&self) -> usize {
        self.capacity as usize
    }

    /// Spawns `count` particles from emitter `index` at the next step (an explosion's burst).
    pub fn burst(&mut self, counts: &mut [u32; 4], index: usize, count: usize) {
        if let Some(c) = counts.get_mut(index) {
            *c = c.saturating_add(count.min(self.capacity as usize) as u32);
        }
    }

    /// The uniform block of one step of `dt` seconds: advances the emitters' carries and the
    /// ring. `extra` adds burst counts per emitter.
    ///
    /// # Errors
    /// More than [`MAX_GPU_EMITTERS`] emitters or [`MAX_GPU_SPHERES`] spheres, an invalid emitter,
    /// a non-finite or negative `dt`, non-finite surfaces.
    pub fn step(
        &mut self,
        emitters: &mut [Emitter],
        surfaces: &Surfaces,
        dt: f32,
        extra: [u32; 4],
    ) -> Result<Vec<Row>, String> {
        if emitters.len() > MAX_GPU_EMITTERS {
            return Err(format!(
                "GPU particles take at most {MAX_GPU_EMITTERS} emitters, got {}",
                emitters.len()
            ));
        }
        if surfaces.spheres.len() > MAX_GPU_SPHERES {
            return Err(format!(
                "GPU particles take at most {MAX_GPU_SPHERES} spheres, got {}",
                surfaces.spheres.len()
            ));
        }
        if !surfaces.walls.is_empty() {
            return Err("GPU particles bounce on the floor and spheres only, not on walls".into());
        }
        if !(dt.is_finite() && dt >= 0.0) {
            return Err(format!("dt must be finite and ≥ 0, got {dt}"));
        }
        let finite = surfaces.gravity.is_finite()
            && surfaces.floor_y.is_none_or(f32::is_finite)
            && surfaces.restitution.is_finite()
            && surfaces.friction.is_finite()
            && surfaces
                .spheres
                .iter()
                .all(|s| s.center.is_finite() && s.radius.is_finite());
        if !finite {
            return Err("surfaces must be finite".into());
        }
        let mut spawn = extra;
        for (k, e) in emitters.iter_mut().enumerate() {
            e.validate().map_err(|e| e.to_string())?;
            e.carry += e.rate_per_sec * dt;
            let whole = e.carry.floor();
            e.carry -= whole;
            spawn[k] = spawn[k].saturating_add(whole as u32);
        }
        // Never more in one step than there are slots (the ring would lap itself).
        let mut left = self.capacity;
        for s in spawn.iter_mut() {
            *s = (*s).min(left);
            left -= *s;
        }
        let g = surfaces.gravity;
        let mut rows = vec![
            frow(g.x, g.y, g.z, dt),
            frow(
                if surfaces.floor_y.is_some() { 1.0 } else { 0.0 },
                surfaces.floor_y.unwrap_or(0.0),
                surfaces.restitution,
                surfaces.friction,
            ),
            [
                self.capacity,
                self.ring,
                surfaces.spheres.len() as u32,
                self.seed ^ self.step.wrapping_mul(0x9e37_79b9),
            ],
            spawn,
        ];
        for k in 0..MAX_GPU_SPHERES {
            rows.push(match surfaces.spheres.get(k) {
                Some(s) => frow(s.center.x, s.center.y, s.center.z, s.radius),
                None => [0; 4],
            });
        }
        for k in 0..MAX_GPU_EMITTERS {
            match emitters.get(k) {
                Some(e) => rows.extend(emitter_rows(e)),
                None => rows.extend([[0; 4]; 6]),
            }
        }
        let total: u32 = spawn.iter().sum();
        self.ring = (self.ring + total) % self.capacity;
        self.step = self.step.wrapping_add(1);
        Ok(rows)
    }
}

fn emitter_rows(e: &Emitter) -> [Row; 6] {
    let (c, r) = match e.position {
        PositionDist::Point(p) => (p, 0.0),
        PositionDist::Ball(c, r) => (c, r),
    };
    let (axis, half, lo, hi, kind) = match e.velocity {
        VelocityDist::Cone {
            axis,
            half_angle_rad,
            speed_min,
            speed_max,
        } => (axis.normalize(), half_angle_rad, speed_min, speed_max, 0.0),
        VelocityDist::Sphere {
            speed_min,
            speed_max,
        } => (Vec3::Y, 0.0, speed_min, speed_max, 1.0),
    };
    let (b, d) = (e.color_birth, e.color_death);
    [
        frow(c.x, c.y, c.z, r),
        frow(axis.x, axis.y, axis.z, half),
        frow(lo, hi, kind, 0.0),
        frow(e.lifetime_sec.0, e.lifetime_sec.1, e.size.0, e.size.1),
        frow(b.x, b.y, b.z, b.w),
        frow(d.x, d.y, d.z, d.w),
    ]
}

/// The most boids the GPU steps with `search`: [`MAX_GPU_BOIDS`] for every pair,
/// [`MAX_GPU_GRID_BOIDS`] on the grid.
pub fn max_gpu_boids(search: Search) -> usize {
    match search {
        Search::Naive => MAX_GPU_BOIDS,
        Search::Grid => MAX_GPU_GRID_BOIDS,
    }
}

/// Whether the GPU steps `n` boids with `search`.
///
/// # Errors
/// `n` of 0 or over [`max_gpu_boids`], with a message that names the search and its cap.
pub fn check_gpu_boids(n: usize, search: Search) -> Result<(), String> {
    let cap = max_gpu_boids(search);
    if n == 0 || n > cap {
        let how = match search {
            Search::Naive => "with every pair tested (the grid takes more)",
            Search::Grid => "on the grid",
        };
        return Err(format!(
            "GPU boids: the count must lie in [1, {cap}] {how}, got {n}"
        ));
    }
    Ok(())
}

/// The uniform block of one GPU flock step of `dt` seconds for `n` boids whose clock reads
/// `time_after_sec` after the step (the leader's target is [`leader_path`] then, as on the CPU),
/// neighbours found by `search`. Colours of the drawn boids are the shader's.
///
/// # Errors
/// Invalid parameters, what [`check_gpu_boids`] rejects, more than [`MAX_GPU_OBSTACLES`]
/// obstacles, a non-finite or negative `dt`.
pub fn boid_rows(
    params: &BoidParams,
    n: usize,
    search: Search,
    time_after_sec: f32,
    dt: f32,
) -> Result<Vec<Row>, String> {
    params.validate()?;
    check_gpu_boids(n, search)?;
    if params.obstacles.len() > MAX_GPU_OBSTACLES {
        return Err(format!(
            "GPU boids take at most {MAX_GPU_OBSTACLES} obstacles, got {}",
            params.obstacles.len()
        ));
    }
    if !(dt.is_finite() && dt >= 0.0 && time_after_sec.is_finite()) {
        return Err(format!("dt must be finite and ≥ 0, got {dt}"));
    }
    let (kind, [a1, a2, k, x0]) = match params.law {
        ForceLaw::None => (0.0, [0.0; 4]),
        ForceLaw::InversePower { a1, a2 } => (1.0, [a1, a2, 0.0, 1.0]),
        ForceLaw::Gaussian { a1, a2, k, x0 } => (2.0, [a1, a2, k, x0]),
    };
    let cos_half = if params.fov_deg >= 360.0 {
        -2.0
    } else {
        (0.5 * params.fov_deg).to_radians().cos()
    };
    let sq = |r: f32| r * r;
    let target = leader_path(time_after_sec, params.bounds);
    let (flee_r, flee_w, predator) = match params.predator {
        Some((r, w)) => (r, w, 1.0),
        None => (0.0, 0.0, 0.0),
    };
    let b = params.bounds;
    let mut rows = vec![
        frow(
            params.cohesion.weight,
            params.alignment.weight,
            params.separation.weight,
            dt,
        ),
        frow(
            sq(params.cohesion.radius),
            sq(params.alignment.radius),
            sq(params.separation.radius),
            sq(params.law_radius),
        ),
        frow(a1, a2, k, x0),
        frow(kind, cos_half, params.max_speed, params.max_force),
        frow(b.x, b.y, b.z, params.bounds_weight),
        frow(
            target.x,
            target.y,
            target.z,
            params.leader.unwrap_or(0.0).max(0.0),
        ),
        frow(
            sq(flee_r),
            flee_w,
            predator,
            16.0 * sq(params.search_radius()),
        ),
        [n as u32, params.obstacles.len() as u32, 0, 0],
        frow(params.avoid_weight, params.min_speed, 0.0, 0.0),
    ];
    // Colours as the CPU figure draws them (src/figures/boids.rs). A boid is a dot of a size in
    // metres: 6 cm keeps a figure-sized flock (a few hundred) visible from the page's camera,
    // where the CPU flock's tailed markers are about 8 px; a flock of thousands keeps 3.5 cm, or
    // its dots would merge into one blue mass.
    let boid_r = if n <= 5_000 { 0.06 } else { 0.035 };
    for (c, r) in [
        (palette::BLUE, boid_r),
        (palette::GREEN, 0.09),
        (palette::RED, 0.11),
    ] {
        rows.push(frow(c.x, c.y, c.z, r));
    }
    for k in 0..MAX_GPU_OBSTACLES {
        rows.push(match params.obstacles.get(k) {
            Some(o) => frow(o.center.x, o.center.y, o.center.z, o.radius),
            None => [0; 4],
        });
    }
    Ok(rows)
}

/// What the CPU and GPU particle systems are compared by (their random numbers differ, so their
/// particles do; their distributions must not).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParticleStats {
    pub alive: usize,
    /// Metres per second.
    pub mean_speed: f32,
    /// Metres.
    pub mean_height: f32,
    /// Metres, over the alive particles.
    pub lowest: f32,
}

/// Statistics of the particles whose `alive` flag is set.
pub fn particle_stats(positions: &[Vec3], velocities: &[Vec3], alive: &[bool]) -> ParticleStats {
    let (mut n, mut speed, mut height, mut lowest) = (0usize, 0.0f64, 0.0f64, f32::INFINITY);
    for ((p, v), &a) in positions.iter().zip(velocities).zip(alive) {
        if a {
            n += 1;
            speed += v.length() as f64;
            height += p.y as f64;
            lowest = lowest.min(p.y);
        }
    }
    let k = n.max(1) as f64;
    ParticleStats {
        alive: n,
        mean_speed: (speed / k) as f32,
        mean_height: (height / k) as f32,
        lowest,
    }
}

/// What the CPU and GPU flocks are compared by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlockStats {
    /// Metres per second.
    pub mean_speed: f32,
    /// `|Σ v̂| / N` in `[0, 1]`: 1 when every boid heads the same way.
    pub polarisation: f32,
    /// Mean distance to the nearest other boid, metres (O(N²): for tests and small flocks).
    pub mean_nearest_m: f32,
}

/// Statistics of a flock.
pub fn flock_stats(positions: &[Vec3], velocities: &[Vec3]) -> FlockStats {
    let n = positions.len().min(velocities.len());
    let k = n.max(1) as f32;
    let mean_speed = velocities[..n].iter().map(|v| v.length()).sum::<f32>() / k;
    let heading: Vec3 = velocities[..n].iter().map(|v| v.normalize_or_zero()).sum();
    let nearest: f32 = (0..n)
        .map(|i| {
            (0..n)
                .filter(|&j| j != i)
                .map(|j| positions[i].distance_squared(positions[j]))
                .fold(f32::INFINITY, f32::min)
                .sqrt()
        })
        .filter(|d| d.is_finite())
        .sum();
    FlockStats {
        mean_speed,
        polarisation: heading.length() / k,
        mean_nearest_m: nearest / k,
    }
}

// ---------------------------------------------------------------------------------------------
// Fluids (WebGPU only): SPH and PBF on the GPU grid.
//
// `src/render/fluid.rs` and `shaders/fluid.wgsl` step a `crate::fluid::Fluid` one thread per
// particle, its neighbours found in the GPU grid of `src/render/grid.rs` (cells one kernel radius
// wide over the box). What the shader receives is packed here, with its caps.

use crate::fluid::{Dim, Eos, Fluid, Kernels as FluidKernels, Method};

/// The most particles the GPU fluid steps: 2²⁰ = 1,048,576, the GPU grid's cap
/// ([`MAX_GPU_GRID_BOIDS`]). Five state buffers of 16 bytes a particle (16 MiB each at the cap)
/// and the sprites (32 MiB) stay under the 128 MiB WebGPU guarantees per storage binding, and a
/// pass is 16,384 workgroups of 64 (at most 65,535 per dispatch).
pub const MAX_GPU_FLUID_PARTICLES: usize = MAX_GPU_GRID_BOIDS;
/// The most walls a GPU fluid takes: the 3D box's six.
pub const MAX_GPU_FLUID_WALLS: usize = 6;
/// `vec4` rows of [`fluid_rows`]: eight of parameters, two colours, then the walls.
pub const GPU_FLUID_ROWS: usize = 10 + MAX_GPU_FLUID_WALLS;
/// The speed the GPU fluid's sprites are coloured red at (blue at rest, through grey), m/s: as
/// the CPU splash draws it.
pub const GPU_FLUID_RED_SPEED: f32 = 3.0;

/// Whether the GPU steps a fluid of `n` particles.
///
/// # Errors
/// `n` of 0 or over [`MAX_GPU_FLUID_PARTICLES`].
pub fn check_gpu_fluid(n: usize) -> Result<(), String> {
    if n == 0 || n > MAX_GPU_FLUID_PARTICLES {
        return Err(format!(
            "GPU fluid: the particle count must lie in [1, {MAX_GPU_FLUID_PARTICLES}], got {n}"
        ));
    }
    Ok(())
}

/// The GPU grid of `fluid`: cubic cells one kernel radius `h` wide over its box enlarged by `h`
/// (as the CPU fluid's grid), so the neighbours within `h` lie in the 3 × 3 × 3 cells around a
/// particle's own (3 × 3 in 2D, where the slab is one cell deep).
///
/// # Errors
/// What [`GridLayout::cubic`] rejects.
pub fn fluid_layout(fluid: &Fluid) -> Result<GridLayout, String> {
    let h = fluid.params.h;
    let size = crate::fluid::box_size(fluid.params.dim);
    GridLayout::cubic(Vec3::splat(-h), size + Vec3::splat(h), h)
}

/// The uniform block of `fluid`'s GPU step (`Params` in `shaders/fluid.wgsl`): the kernels'
/// constants of [`FluidKernels::constants`], the equation of state, the collisions' box walls
/// and obstacle, PBF's relaxation, `s_corr` (already times [`Fluid::lambda_unit`]), XSPH and
/// vorticity confinement.
///
/// # Errors
/// Invalid parameters, what [`check_gpu_fluid`] rejects, more than [`MAX_GPU_FLUID_WALLS`]
/// walls.
pub fn fluid_rows(fluid: &Fluid) -> Result<Vec<Row>, String> {
    let p = &fluid.params;
    p.validate()?;
    check_gpu_fluid(fluid.len())?;
    if fluid.walls.len() > MAX_GPU_FLUID_WALLS {
        return Err(format!(
            "GPU fluid: at most {MAX_GPU_FLUID_WALLS} walls, got {}",
            fluid.walls.len()
        ));
    }
    let kern = FluidKernels::new(p.h, p.dim);
    let [poly6, spiky_gradient, viscosity_laplacian] = kern.constants();
    let eos = match p.eos {
        Eos::IdealGas => 0.0,
        Eos::Tait => 1.0,
    };
    let two_d = if p.dim == Dim::Two { 1.0 } else { 0.0 };
    let (g, o) = (p.gravity, fluid.obstacle);
    let mut rows = vec![
        frow(p.h, p.h * p.h, fluid.mass, p.dt),
        frow(
            poly6,
            spiky_gradient,
            viscosity_laplacian,
            kern.poly6((0.2 * p.h) * (0.2 * p.h)),
        ),
        frow(p.rest_density, p.stiffness, p.viscosity, eos),
        frow(g.x, g.y, g.z, p.restitution),
        frow(
            p.friction,
            p.relaxation,
            p.s_corr * fluid.lambda_unit(),
            p.xsph,
        ),
        frow(
            p.vorticity,
            two_d,
            0.45 * fluid.spacing,
            GPU_FLUID_RED_SPEED,
        ),
        match o {
            Some(s) => frow(s.center.x, s.center.y, s.center.z, s.radius),
            None => [0; 4],
        },
        [
            fluid.len() as u32,
            fluid.walls.len() as u32,
            matches!(p.method, Method::Pbf) as u32,
            0,
        ],
    ];
    // The sprites' colours at rest and at GPU_FLUID_RED_SPEED, as `noise::diverging_color`.
    for c in [palette::BLUE, palette::RED] {
        rows.push(frow(c.x, c.y, c.z, 0.85));
    }
    for k in 0..MAX_GPU_FLUID_WALLS {
        rows.push(match fluid.walls.get(k) {
            Some(w) => frow(w.normal.x, w.normal.y, w.normal.z, w.offset),
            None => [0; 4],
        });
    }
    Ok(rows)
}
