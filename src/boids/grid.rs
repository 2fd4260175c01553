//! Neighbour search: the naive O(N²) loop and a uniform grid filled by counting sort.

use glam::Vec3;

/// The most cells a grid may have; a grid that would need more uses larger cells (still correct:
/// a cell is never smaller than the search radius).
pub const MAX_GRID_CELLS: usize = 1 << 18;

/// The cell of `p` in a grid whose cell `(0, 0, 0)` starts at `origin`, with cubic cells of side
/// `cell_size` and `dims` cells along x, y, z; positions outside are clamped to the border cells
/// (clamping keeps neighbouring cells neighbours, so the search stays exact):
/// ```text
/// (i, j, k) = clamp(⌊(p − origin) / cell_size⌋, 0, dims − 1)
/// index     = i + dims.x · (j + dims.y · k)
/// ```
/// Exercise 12.2; lesson: lessons/12-boids.
pub fn cell_index(p: Vec3, origin: Vec3, cell_size: f32, dims: [u32; 3]) -> usize {
    let c = ((p - origin) / cell_size).floor();
    let clamp = |x: f32, n: u32| (x.max(0.0) as u32).min(n.saturating_sub(1)) as usize;
    let (i, j, k) = (
        clamp(c.x, dims[0]),
        clamp(c.y, dims[1]),
        clamp(c.z, dims[2]),
    );
    i + dims[0] as usize * (j + dims[1] as usize * k)
}

/// A uniform grid over a box, rebuilt every step by counting sort: count the boids per cell,
/// prefix-sum the counts into each cell's start, then write each boid's index into its cell's
/// run. The arrays keep their size between rebuilds, so a rebuild allocates nothing (unless the
/// number of boids grows).
#[derive(Clone, Debug, Default)]
pub struct Grid {
    pub origin: Vec3,
    pub cell_size: f32,
    pub dims: [u32; 3],
    /// `cell_start[c]..cell_start[c + 1]` is cell `c`'s run in `sorted`.
    cell_start: Vec<u32>,
    /// Boid indices, sorted by cell.
    sorted: Vec<u32>,
    /// Each boid's cell.
    cell_of: Vec<u32>,
    /// `positions[sorted[k]]`: the positions in cell order, so the distance tests of a cell's
    /// run read memory front to back instead of jumping around the flock.
    sorted_positions: Vec<Vec3>,
    /// `velocities[sorted[k]]`, filled by [`Grid::rebuild_with_velocities`] (the flock's step
    /// reads every neighbour's velocity; in cell order those reads are coherent too).
    sorted_velocities: Vec<Vec3>,
    /// The same, one array per coordinate (positions x, y, z, then velocities), padded with 3
    /// zeros so that four lanes can always be loaded: the flock's SIMD step reads these.
    soa: [Vec<f32>; 6],
}

impl Grid {
    /// Sets the grid over the box `[min, max]` with cells at least `radius` wide.
    pub fn configure(&mut self, min: Vec3, max: Vec3, radius: f32) {
        let extent = (max - min).max(Vec3::splat(1e-3));
        let mut size = radius.max(1e-3);
        let dims = |size: f32| {
            let d = (extent / size).ceil().max(Vec3::ONE);
            [d.x as u32, d.y as u32, d.z as u32]
        };
        let mut d = dims(size);
        while d.iter().map(|&n| n as usize).product::<usize>() > MAX_GRID_CELLS {
            size *= 1.25;
            d = dims(size);
        }
        self.origin = min;
        self.cell_size = size;
        self.dims = d;
        let cells = d.iter().map(|&n| n as usize).product::<usize>();
        self.cell_start.resize(cells + 1, 0);
    }

    /// Sets the grid over the box `[min, max]` as one single cell: every boid's run is the
    /// whole flock, so a search through the grid tests every pair (the naive O(N²) search,
    /// with the same loop as the grid's).
    pub fn configure_single_cell(&mut self, min: Vec3, max: Vec3) {
        self.origin = min;
        self.cell_size = (max - min).max_element().max(1e-3);
        self.dims = [1, 1, 1];
        self.cell_start.resize(2, 0);
    }

    pub fn cell_count(&self) -> usize {
        self.cell_start.len().saturating_sub(1)
    }

    /// Sorts `positions` into the cells (counting sort).
    pub fn rebuild(&mut self, positions: &[Vec3]) {
        let n = positions.len();
        self.sorted.resize(n, 0);
        self.cell_of.resize(n, 0);
        self.sorted_positions.resize(n, Vec3::ZERO);
        self.cell_start.fill(0);
        for (i, &p) in positions.iter().enumerate() {
            let c = cell_index(p, self.origin, self.cell_size, self.dims);
            self.cell_of[i] = c as u32;
            self.cell_start[c + 1] += 1;
        }
        for c in 1..self.cell_start.len() {
            self.cell_start[c] += self.cell_start[c - 1];
        }
        // Fill each run from its end, walking the boids backwards, so each cell lists its boids
        // in increasing index (a stable sort).
        for i in (0..n).rev() {
            let c = self.cell_of[i] as usize + 1;
            self.cell_start[c] -= 1;
            self.sorted[self.cell_start[c] as usize] = i as u32;
        }
        // Now cell_start[c + 1] holds the start of cell c; shift back by one.
        self.cell_start.rotate_left(1);
        let last = self.cell_start.len() - 1;
        self.cell_start[last] = n as u32;
        for (q, &i) in self.sorted_positions.iter_mut().zip(&self.sorted) {
            *q = positions[i as usize];
        }
    }

    /// [`Grid::rebuild`], and the velocities copied into cell order beside the positions (what
    /// the flock's grid step reads).
    pub fn rebuild_with_velocities(&mut self, positions: &[Vec3], velocities: &[Vec3]) {
        self.rebuild(positions);
        self.sorted_velocities.resize(self.sorted.len(), Vec3::ZERO);
        for (w, &i) in self.sorted_velocities.iter_mut().zip(&self.sorted) {
            *w = velocities[i as usize];
        }
        let n = self.sorted.len();
        for a in &mut self.soa {
            a.resize(n + 3, 0.0);
        }
        let [x, y, z, vx, vy, vz] = &mut self.soa;
        for k in 0..n {
            let (p, v) = (self.sorted_positions[k], self.sorted_velocities[k]);
            (x[k], y[k], z[k]) = (p.x, p.y, p.z);
            (vx[k], vy[k], vz[k]) = (v.x, v.y, v.z);
        }
    }

    /// Calls `f(run)` for the slot runs (ranges of [`Grid::sorted`], in increasing order) of the
    /// cells that a ball of squared radius `radius2 ≤ cell_size²` around `p`, which lies in
    /// the cell `(ci, cj, ck)`, can reach: per row of the 3 × 3 × 3 block around `cell`, only the cells that the
    /// ball's chord through the row's slab crosses, and no row the ball misses. Every point of
    /// the grid within the ball is in one of the runs (and, as the full block scan visits them,
    /// in the same order).
    #[inline(always)]
    pub(super) fn for_each_run_near(
        &self,
        p: Vec3,
        (ci, cj, ck): (usize, usize, usize),
        radius2: f32,
        mut f: impl FnMut(std::ops::Range<usize>),
    ) {
        let (dx, dy, dz) = (
            self.dims[0] as usize,
            self.dims[1] as usize,
            self.dims[2] as usize,
        );
        let (origin, size) = (self.origin, self.cell_size);
        let range = |x: usize, n: usize| x.saturating_sub(1)..=(x + 1).min(n - 1);
        // Slightly widened, so rounding never drops a cell that holds a neighbour (a cell too
        // many only costs its distance tests).
        let reach2 = radius2 * (1.0 + 1e-4) + 1e-12;
        // The distance from x to cell c's extent along one axis; the border cells reach to
        // infinity outwards (positions outside the box are clamped into them).
        let gap = |x: f32, o: f32, c: usize, n: usize| {
            let lo = if c == 0 {
                f32::NEG_INFINITY
            } else {
                o + c as f32 * size
            };
            let hi = if c + 1 == n {
                f32::INFINITY
            } else {
                o + (c + 1) as f32 * size
            };
            (lo - x).max(x - hi).max(0.0)
        };
        // ⌊(x − o) / size⌋ clamped to the grid; `as` truncates, which is ⌊·⌋ once clamped at 0
        // (and needs no libm call for floor on x86-64 without SSE4.1).
        let inv_size = 1.0 / size;
        let x_cell = |x: f32| (((x - origin.x) * inv_size).max(0.0) as usize).min(dx - 1);
        for k in range(ck, dz) {
            let gz = gap(p.z, origin.z, k, dz);
            for j in range(cj, dy) {
                let gy = gap(p.y, origin.y, j, dy);
                let rest = reach2 - gz * gz - gy * gy;
                if rest < 0.0 {
                    continue;
                }
                let half = rest.sqrt();
                let lo = x_cell(p.x - half).max(ci.saturating_sub(1));
                let hi = x_cell(p.x + half).min(ci + 1);
                let row = dx * (j + dy * k);
                f(self.run(row + lo, row + hi));
            }
        }
    }

    /// Sorted positions and velocities by coordinate (see `soa`).
    pub(super) fn soa(&self) -> &[Vec<f32>; 6] {
        &self.soa
    }

    pub(super) fn soa_mut(&mut self) -> &mut [Vec<f32>; 6] {
        &mut self.soa
    }

    /// Boid indices in cell order (cell `c`'s boids, in increasing index, then cell `c + 1`'s).
    pub fn sorted(&self) -> &[u32] {
        &self.sorted
    }

    /// The run of slots (indices into [`Grid::sorted`]) of cells `lo..=hi`.
    #[inline]
    pub(super) fn run(&self, lo: usize, hi: usize) -> std::ops::Range<usize> {
        self.cell_start[lo] as usize..self.cell_start[hi + 1] as usize
    }

    /// The cell of boid `i` at the last rebuild.
    #[inline]
    #[allow(dead_code)]
    pub(super) fn cell_of(&self, i: usize) -> usize {
        self.cell_of[i] as usize
    }

    pub(super) fn sorted_positions(&self) -> &[Vec3] {
        &self.sorted_positions
    }

    pub(super) fn sorted_velocities(&self) -> &[Vec3] {
        &self.sorted_velocities
    }

    /// Calls `f(j)` for every boid `j ≠ i` within `radius ≤ cell_size` of `positions[i]`
    /// (the 27 cells around `i`'s cell), in increasing cell order.
    pub fn for_each_neighbour(
        &self,
        positions: &[Vec3],
        i: usize,
        radius: f32,
        mut f: impl FnMut(usize),
    ) {
        let p = positions[i];
        let r2 = radius * radius;
        let c = self.cell_of[i] as usize;
        let (dx, dy) = (self.dims[0] as usize, self.dims[1] as usize);
        let (ci, cj, ck) = (c % dx, (c / dx) % dy, c / (dx * dy));
        let range = |x: usize, n: u32| x.saturating_sub(1)..=(x + 1).min(n as usize - 1);
        for k in range(ck, self.dims[2]) {
            for j in range(cj, self.dims[1]) {
                let row = dx * (j + dy * k);
                let (lo, hi) = (row + ci.saturating_sub(1), row + (ci + 1).min(dx - 1));
                // Cells lo..=hi are contiguous in memory, and so are their runs in `sorted`.
                let (a, b) = (
                    self.cell_start[lo] as usize,
                    self.cell_start[hi + 1] as usize,
                );
                for (&jb, q) in self.sorted[a..b].iter().zip(&self.sorted_positions[a..b]) {
                    let jb = jb as usize;
                    if jb != i && (*q - p).length_squared() <= r2 {
                        f(jb);
                    }
                }
            }
        }
    }
}

/// Calls `f(j)` for every boid `j ≠ i` within `radius` of `positions[i]`, by testing them all.
pub fn for_each_neighbour_naive(
    positions: &[Vec3],
    i: usize,
    radius: f32,
    mut f: impl FnMut(usize),
) {
    let p = positions[i];
    let r2 = radius * radius;
    for (j, q) in positions.iter().enumerate() {
        if j != i && (*q - p).length_squared() <= r2 {
            f(j);
        }
    }
}
