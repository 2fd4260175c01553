//! Neighbour search: the naive O(N²) loop and a uniform grid filled by counting sort.

use glam::{Vec3, Vec4};

/// The most cells a grid may have; a grid that would need more uses larger cells (still correct:
/// a cell is never narrower in y and z than the search radius). 2¹⁹ cells hold 2 MB of run starts.
pub const MAX_GRID_CELLS: usize = 1 << 19;

/// A [`Grid`]'s cells are this many times thinner along x than along y and z: a search ball then
/// reads, per row of cells along x, only the slots its chord crosses to within a quarter radius:
/// on the benchmark flock at 100,000 boids, about 47 candidates for 14 neighbours instead of the
/// 65 in the whole 3 × 3 block of rows (tests/boids.rs; the SIMD step's cost is the candidates
/// it tests, four at a time).
pub const X_SPLIT: usize = 4;

/// The slots after the boids in the grid's sorted arrays (see `Grid::soa`): a SIMD load of four
/// lanes from any boid's slot stays within the arrays.
pub const PADDING: usize = 3;

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
/// number of boids grows). Cells are `cell_size` wide along y and z and `x_size =
/// cell_size / X_SPLIT` along x (see [`X_SPLIT`]); cell `(i, j, k)` is number
/// `i + dims.x · (j + dims.y · k)`, so a row of cells along x is one run of slots.
#[derive(Clone, Debug, Default)]
pub struct Grid {
    pub origin: Vec3,
    /// The cells' size along y and z, at least the search radius.
    pub cell_size: f32,
    /// The cells' size along x.
    pub x_size: f32,
    pub dims: [u32; 3],
    /// `cell_start[c]..cell_start[c + 1]` is cell `c`'s run in `sorted`.
    cell_start: Vec<u32>,
    /// Boid indices, sorted by cell.
    sorted: Vec<u32>,
    /// Each boid's cell.
    cell_of: Vec<u32>,
    /// `positions[sorted[k]]` and `velocities[sorted[k]]`, one array per coordinate (x, y, z,
    /// then the velocities'): the positions and velocities in cell order, so the distance
    /// tests of a cell's run read memory front to back instead of jumping around the flock.
    /// After the boids come [`PADDING`] slots with a NaN x and zero velocities, so that four
    /// lanes can always be loaded: the flock's SIMD step reads these.
    soa: [Vec<f32>; 6],
}

impl Grid {
    /// Sets the grid over the box `[min, max]` with cells at least `radius` wide.
    pub fn configure(&mut self, min: Vec3, max: Vec3, radius: f32) {
        let extent = (max - min).max(Vec3::splat(1e-3));
        let mut size = radius.max(1e-3);
        let dims = |size: f32| {
            let d = (extent / Vec3::new(size / X_SPLIT as f32, size, size))
                .ceil()
                .max(Vec3::ONE);
            [d.x as u32, d.y as u32, d.z as u32]
        };
        let mut d = dims(size);
        while d.iter().map(|&n| n as usize).product::<usize>() > MAX_GRID_CELLS {
            size *= 1.25;
            d = dims(size);
        }
        self.origin = min;
        self.cell_size = size;
        self.x_size = size / X_SPLIT as f32;
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
        self.x_size = self.cell_size;
        self.dims = [1, 1, 1];
        self.cell_start.resize(2, 0);
    }

    /// The reciprocals of the cells' sizes along x, y, z.
    #[inline(always)]
    fn inv_sizes(&self) -> Vec3 {
        Vec3::new(
            1.0 / self.x_size,
            1.0 / self.cell_size,
            1.0 / self.cell_size,
        )
    }

    /// The number of the cell that holds `p` (positions outside the box are clamped into the
    /// border cells): [`cell_index`]'s clamp(⌊(p − origin) / size⌋, 0, dims − 1) per axis, as
    /// multiplications by the sizes' reciprocals (the search computes a chord's cells the same
    /// way, so a boid's cell and the search's ranges agree to the bit), the three axes in the
    /// lanes of one vector. A NaN coordinate gives cell 0 on its axis.
    #[inline(always)]
    pub fn cell_of_point(&self, p: Vec3) -> usize {
        let inv = self.inv_sizes();
        let c = (Vec4::from((p - self.origin, 0.0))) * Vec4::from((inv, 0.0));
        let top = Vec4::new(
            self.dims[0] as f32 - 1.0,
            self.dims[1] as f32 - 1.0,
            self.dims[2] as f32 - 1.0,
            0.0,
        );
        // Clamped as floats, so truncation is ⌊·⌋ and needs none of `as`'s checks.
        let [i, j, k, _] = lanes::truncate(lanes::clamp(c, Vec4::ZERO, top));
        let [dx, dy] = [self.dims[0] as usize, self.dims[1] as usize];
        i as usize + dx * (j as usize + dy * k as usize)
    }

    pub fn cell_count(&self) -> usize {
        self.cell_start.len().saturating_sub(1)
    }

    /// Sorts `positions` into the cells (counting sort); the velocities in the sorted arrays
    /// are zero.
    pub fn rebuild(&mut self, positions: &[Vec3]) {
        self.sort(positions);
        self.gather(positions, None);
    }

    /// [`Grid::rebuild`], with the velocities copied into cell order beside the positions
    /// (what the flock's grid step reads).
    pub fn rebuild_with_velocities(&mut self, positions: &[Vec3], velocities: &[Vec3]) {
        self.sort(positions);
        self.gather(positions, Some(velocities));
    }

    /// The counting sort: `cell_of`, `cell_start` and `sorted`.
    fn sort(&mut self, positions: &[Vec3]) {
        let n = positions.len();
        self.sorted.resize(n, 0);
        self.cell_of.resize(n, 0);
        self.cell_start.fill(0);
        for (i, &p) in positions.iter().enumerate() {
            let c = self.cell_of_point(p);
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
    }

    /// Fills the sorted arrays (`soa`) in cell order, in one pass, and their padding.
    fn gather(&mut self, positions: &[Vec3], velocities: Option<&[Vec3]>) {
        let n = self.sorted.len();
        for a in &mut self.soa {
            a.resize(n + PADDING, 0.0);
        }
        let [x, y, z, vx, vy, vz] = &mut self.soa;
        match velocities {
            Some(velocities) => {
                for (k, &i) in self.sorted.iter().enumerate() {
                    let (p, v) = (positions[i as usize], velocities[i as usize]);
                    (x[k], y[k], z[k]) = (p.x, p.y, p.z);
                    (vx[k], vy[k], vz[k]) = (v.x, v.y, v.z);
                }
            }
            None => {
                for (k, &i) in self.sorted.iter().enumerate() {
                    let p = positions[i as usize];
                    (x[k], y[k], z[k]) = (p.x, p.y, p.z);
                }
                for a in [&mut *vx, &mut *vy, &mut *vz] {
                    a[..n].fill(0.0);
                }
            }
        }
        // The padding: a NaN x fails every distance test, zero velocities add nothing.
        for (a, pad) in self.soa.iter_mut().zip([f32::NAN, 0.0, 0.0, 0.0, 0.0, 0.0]) {
            a[n..].fill(pad);
        }
    }

    /// What a search from cell `(ci, cj, ck)` needs of the grid, computed once for all the boids
    /// in the cell (see [`Grid::runs_near`]).
    #[inline(always)]
    pub(super) fn cell_search(&self, (ci, cj, ck): (usize, usize, usize)) -> CellSearch {
        let [dx, dy, dz] = self.dims.map(|d| d as usize);
        let (o, size) = (self.origin, self.cell_size);
        // The cell's faces in y and z. A missing neighbour row (past the border) gets a face at
        // infinity, hence an infinite gap; so does the outer side of a border cell, whose
        // clamped positions may lie anywhere beyond it.
        let faces = |o: f32, c: usize, n: usize| {
            let lo = o + c as f32 * size;
            let hi = lo + size;
            (
                if c > 0 { lo } else { f32::NEG_INFINITY },
                if c + 1 < n { hi } else { f32::INFINITY },
            )
        };
        let ((y0, y1), (z0, z1)) = (faces(o.y, cj, dy), faces(o.z, ck, dz));
        // Which of the 3 × 3 rows around the cell's exist (bit 3 k + j for row (cj − 1 + j,
        // ck − 1 + k)).
        let exists = |c: usize, n: usize| (c > 0) as u32 | 2 | ((c + 1 < n) as u32) << 2;
        let (ey, ez) = (exists(cj, dy), exists(ck, dz));
        let rows = (0..3)
            .filter(|kk| ez & (1 << kk) != 0)
            .fold(0, |m, kk| m | ey << (3 * kk));
        CellSearch {
            rows,
            faces: Vec4::new(y0, -y1, z0, -z1),
            ox: o.x,
            inv_x: self.inv_sizes().x,
            // A ball of radius ≤ cell_size reaches no further than X_SPLIT cells along x.
            lo_min: ci.saturating_sub(X_SPLIT) as f32,
            hi_max: (ci + X_SPLIT).min(dx - 1) as f32,
            // The first slot of row (cj − 1, ck − 1); wrapping, as cj or ck may be 0 (those rows
            // have an infinite gap and are never read).
            first_row: cj
                .wrapping_sub(1)
                .wrapping_add(dy.wrapping_mul(ck.wrapping_sub(1)))
                .wrapping_mul(dx),
            row_stride: dx,
            plane_stride: dx * dy,
        }
    }

    /// Calls `f(run)` for the slot runs (ranges of [`Grid::sorted`], in increasing order) of the
    /// cells that a ball of squared radius `radius2 ≤ cell_size²` around `p`, which lies in
    /// the cell `cell`, can reach (see [`Grid::runs_near`]; empty runs are skipped).
    #[inline(always)]
    pub(super) fn for_each_run_near(
        &self,
        p: Vec3,
        cell: (usize, usize, usize),
        radius2: f32,
        mut f: impl FnMut(std::ops::Range<usize>),
    ) {
        let mut runs = [(0u32, 0u32); 9];
        self.runs_near(&self.cell_search(cell), p, radius2, &mut runs);
        for &(a, b) in &runs {
            if a < b {
                f(a as usize..b as usize);
            }
        }
    }

    /// Writes into `runs` the slot runs (`start..end` in [`Grid::sorted`], `start ≤ end`, in
    /// increasing order) of the cells that a ball of squared radius `radius2 ≤ cell_size²`
    /// around `p`, which lies in the cell of `search` ([`Grid::cell_search`]), can reach: per
    /// row along x of the 3 × 3 rows around the cell's (entry `3 k + j` for the row at
    /// `(cj − 1 + j, ck − 1 + k)`), only the cells that the ball's chord through the row's slab
    /// crosses; a row the ball misses, or that lies past the grid's border, gets an empty run.
    /// Every point of the grid within the ball is in one of the runs (and, as the full block
    /// scan visits them, in the same order).
    #[inline(always)]
    pub(super) fn runs_near(
        &self,
        search: &CellSearch,
        p: Vec3,
        radius2: f32,
        runs: &mut [(u32, u32); 9],
    ) {
        // Slightly widened, so rounding never drops a cell that holds a neighbour (a cell too
        // many only costs its distance tests).
        let reach2 = radius2 * (1.0 + 1e-4) + 1e-12;
        // The squared distances from p to the rows below and above its own, in y and in z (its
        // own row is at distance 0): p − lower face and upper face − p, at least 0.
        let gaps = (Vec4::new(p.y, -p.y, p.z, -p.z) - search.faces).max(Vec4::ZERO);
        let g2 = gaps * gaps;
        // The three rows of one plane (k fixed, j = cj − 1, cj, cj + 1) are the first three
        // lanes of a Vec4 (the fourth is never reached): their chords and cells are computed
        // together.
        let gy2 = Vec4::new(g2.x, 0.0, g2.y, f32::INFINITY);
        let gz2 = [g2.z, 0.0, g2.w];
        // ⌊(x − o) / x_size⌋ as in `cell_of_point`, clamped to the cells the ball can reach;
        // truncation is ⌊·⌋ once clamped at 0 (no libm floor on x86-64 without SSE4.1).
        let (px, ox, inv_x) = (
            Vec4::splat(p.x),
            Vec4::splat(search.ox),
            Vec4::splat(search.inv_x),
        );
        let (lo_min, hi_max) = (Vec4::splat(search.lo_min), Vec4::splat(search.hi_max));
        // Clamped as floats (a NaN becomes lo_min), so every lane is finite and within
        // [lo_min, hi_max] ⊂ [0, dims.x − 1]: its truncation to an integer needs none of
        // `as`'s checks.
        let x_cells = |x: Vec4| lanes::truncate(lanes::clamp((x - ox) * inv_x, lo_min, hi_max));
        for (kk, &g2z) in gz2.iter().enumerate() {
            let out = &mut runs[3 * kk..3 * kk + 3];
            // A missing row's −∞ and a NaN fail; so does any row past the border (`rows`: a
            // NaN p would otherwise reach them).
            let rest = Vec4::splat(reach2 - g2z) - gy2;
            let reached = rest.cmpge(Vec4::ZERO).bitmask() & (search.rows >> (3 * kk));
            if reached & 7 == 0 {
                out.fill((0, 0));
                continue;
            }
            let half = rest.sqrt();
            let (lo, hi) = (x_cells(px - half), x_cells(px + half));
            let plane = search.first_row.wrapping_add(kk * search.plane_stride);
            for (jj, run) in out.iter_mut().enumerate() {
                *run = if reached & (1 << jj) != 0 {
                    let row = plane.wrapping_add(jj * search.row_stride);
                    let (a, b) = (row + lo[jj] as usize, row + hi[jj] as usize + 1);
                    debug_assert!(a < b && b < self.cell_start.len());
                    // SAFETY: the row exists (its bit is set in `search.rows`), so `row` is the
                    // first of its dims.x cells, and lo, hi ≤ dims.x − 1 (`x_cells`): a and b
                    // are at most the number of cells, the last index of `cell_start`.
                    unsafe {
                        (
                            *self.cell_start.get_unchecked(a),
                            *self.cell_start.get_unchecked(b),
                        )
                    }
                } else {
                    (0, 0)
                };
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

    /// Where each cell's run starts in [`Grid::sorted`], one more entry for the boid count:
    /// `cell_starts()[c]..cell_starts()[c + 1]` is cell `c`'s run.
    pub fn cell_starts(&self) -> &[u32] {
        &self.cell_start
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

    /// The position of the boid in slot `k` (`positions[sorted[k]]` at the last rebuild).
    #[inline(always)]
    pub fn sorted_position(&self, k: usize) -> Vec3 {
        Vec3::new(self.soa[0][k], self.soa[1][k], self.soa[2][k])
    }

    /// The velocity of the boid in slot `k` (zero after [`Grid::rebuild`]).
    #[inline(always)]
    pub fn sorted_velocity(&self, k: usize) -> Vec3 {
        Vec3::new(self.soa[3][k], self.soa[4][k], self.soa[5][k])
    }

    /// Calls `f(j)` for every boid `j ≠ i` within `radius ≤ cell_size` of `positions[i]`, in
    /// increasing cell order (within a cell, increasing index). It reads only the cells that the
    /// ball's chords cross ([`Grid::for_each_run_near`]), and tests four sorted positions at a
    /// time: the same tests, in the same order and with the same float operations, as a scan of
    /// the whole 3 × 3 block of rows, so the neighbours and their order are the same.
    pub fn for_each_neighbour(
        &self,
        positions: &[Vec3],
        i: usize,
        radius: f32,
        mut f: impl FnMut(usize),
    ) {
        let p = positions[i];
        let r2 = radius * radius;
        let cell = self.cell_coords(i);
        let [x, y, z, ..] = &self.soa;
        let (px, py, pz, r2v) = (
            Vec4::splat(p.x),
            Vec4::splat(p.y),
            Vec4::splat(p.z),
            Vec4::splat(r2),
        );
        self.for_each_run_near(p, cell, r2, |run| {
            let mut t = run.start;
            while t < run.end {
                // Four lanes from slot t: the padding after the last boid (`PADDING`) keeps
                // the loads in the arrays; lanes past the run are masked off.
                let lane = |a: &[f32]| Vec4::from_slice(&a[t..t + 4]);
                let (ex, ey, ez) = (lane(x) - px, lane(y) - py, lane(z) - pz);
                let d2 = ex * ex + ey * ey + ez * ez;
                let left = run.end - t;
                let mut hits =
                    d2.cmple(r2v).bitmask() & if left < 4 { (1 << left) - 1 } else { 15 };
                while hits != 0 {
                    let jb = self.sorted[t + hits.trailing_zeros() as usize] as usize;
                    if jb != i {
                        f(jb);
                    }
                    hits &= hits - 1;
                }
                t += 4;
            }
        });
    }
}

impl Grid {
    /// The cell (x, y, z) that boid `i` was sorted into by the last rebuild.
    #[inline(always)]
    fn cell_coords(&self, i: usize) -> (usize, usize, usize) {
        let c = self.cell_of[i] as usize;
        let (dx, dy) = (self.dims[0] as usize, self.dims[1] as usize);
        (c % dx, (c / dx) % dy, c / (dx * dy))
    }

    /// How many slots the search around boid `i` tests (its candidates, `i` among them): the
    /// length of the runs [`Grid::for_each_neighbour`] reads for `radius ≤ cell_size`.
    pub fn candidates(&self, positions: &[Vec3], i: usize, radius: f32) -> usize {
        let mut n = 0;
        let cell = self.cell_coords(i);
        self.for_each_run_near(positions[i], cell, radius * radius, |run| n += run.len());
        n
    }

    /// Appends to `out` the neighbours of `i` that [`Grid::for_each_neighbour`] finds, in the
    /// same order, without a branch per neighbour: each group of four tested slots writes its
    /// four indices at the end of the list and keeps as many as are within `radius` (the
    /// fluid's neighbour lists, where a mispredicted branch per group cost more than the
    /// distance tests).
    pub fn append_neighbours(&self, positions: &[Vec3], i: usize, radius: f32, out: &mut Vec<u32>) {
        let p = positions[i];
        let r2 = radius * radius;
        let cell = self.cell_coords(i);
        let mut runs = [(0u32, 0u32); 9];
        self.runs_near(&self.cell_search(cell), p, r2, &mut runs);
        let slots: usize = runs.iter().map(|&(a, b)| (b - a) as usize).sum();
        out.reserve(slots + 4);
        let spare = out.spare_capacity_mut();
        let [x, y, z, ..] = &self.soa;
        let (px, py, pz, r2v) = (
            Vec4::splat(p.x),
            Vec4::splat(p.y),
            Vec4::splat(p.z),
            Vec4::splat(r2),
        );
        let me = i as u32;
        let mut kept = 0;
        for &(a, b) in &runs {
            let (mut t, end) = (a as usize, b as usize);
            while t < end {
                // As in `for_each_neighbour`: four lanes from slot t, those past the run masked.
                let lane = |a: &[f32]| Vec4::from_slice(&a[t..t + 4]);
                let (ex, ey, ez) = (lane(x) - px, lane(y) - py, lane(z) - pz);
                let d2 = ex * ex + ey * ey + ez * ez;
                let left = end - t;
                let hits = d2.cmple(r2v).bitmask() & if left < 4 { (1 << left) - 1 } else { 15 };
                for l in 0..4 {
                    // Slots past the last boid hold no index: u32::MAX there, never kept.
                    let j = self.sorted.get(t + l).copied().unwrap_or(u32::MAX);
                    spare[kept].write(j);
                    kept += ((hits >> l) & 1) as usize & usize::from(j != me);
                }
                t += 4;
            }
        }
        // SAFETY: `kept` counts tested slots within the radius, at most `slots`, and the first
        // `kept` entries of the spare capacity (of at least `slots + 4`) were written above:
        // every write lands at the current `kept`, which only grows.
        unsafe { out.set_len(out.len() + kept) };
    }
}

mod lanes {
    use glam::Vec4;

    /// The lanes of `v`, each finite and in `[0, 2³¹)`, truncated to integers (one instruction
    /// for the four on x86-64 and in wasm, where a per-lane `as` also checks for NaN and range).
    /// `v` clamped into `[lo, hi]` lane by lane (`lo ≤ hi`), a NaN lane becoming `lo`: two
    /// instructions (SSE's max returns its second operand when either is NaN; wasm's pmax
    /// returns its first unless it is less than the second).
    #[inline(always)]
    pub fn clamp(v: Vec4, lo: Vec4, hi: Vec4) -> Vec4 {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            use core::arch::wasm32::{f32x4_pmax, f32x4_pmin, v128};
            let above = f32x4_pmax(v128::from(lo), v128::from(v));
            Vec4::from(f32x4_pmin(v128::from(hi), above))
        }
        #[cfg(target_arch = "x86_64")]
        {
            use core::arch::x86_64::{__m128, _mm_max_ps, _mm_min_ps};
            // SAFETY: SSE, part of every x86-64 CPU.
            unsafe {
                let above = _mm_max_ps(__m128::from(v), __m128::from(lo));
                Vec4::from(_mm_min_ps(above, __m128::from(hi)))
            }
        }
        #[cfg(not(any(
            all(target_arch = "wasm32", target_feature = "simd128"),
            target_arch = "x86_64"
        )))]
        {
            Vec4::select(v.cmpgt(lo), v, lo).min(hi)
        }
    }

    #[inline(always)]
    pub fn truncate(v: Vec4) -> [u32; 4] {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            use core::arch::wasm32::{i32x4_trunc_sat_f32x4, v128};
            // SAFETY: v128 and [u32; 4] have the same size, and every bit pattern is valid.
            unsafe { core::mem::transmute::<v128, [u32; 4]>(i32x4_trunc_sat_f32x4(v128::from(v))) }
        }
        #[cfg(target_arch = "x86_64")]
        {
            use core::arch::x86_64::{__m128, __m128i, _mm_cvttps_epi32};
            // SAFETY: SSE2 is part of every x86-64 CPU; __m128i and [u32; 4] have the same size
            // and every bit pattern is valid.
            unsafe { core::mem::transmute::<__m128i, [u32; 4]>(_mm_cvttps_epi32(__m128::from(v))) }
        }
        #[cfg(not(any(
            all(target_arch = "wasm32", target_feature = "simd128"),
            target_arch = "x86_64"
        )))]
        {
            v.to_array().map(|c| c as u32)
        }
    }
}

/// What [`Grid::runs_near`] needs of a boid's cell, the same for every boid in it.
pub(super) struct CellSearch {
    /// The cell's lower and upper faces in y and z as `(y0, −y1, z0, −z1)` (±∞ where the
    /// neighbour row is missing).
    faces: Vec4,
    /// Bit `3 k + j` is set when the row `(cj − 1 + j, ck − 1 + k)` exists.
    rows: u32,
    ox: f32,
    inv_x: f32,
    /// The x cells a ball from this cell can reach: `lo_min..=hi_max`.
    lo_min: f32,
    hi_max: f32,
    first_row: usize,
    row_stride: usize,
    plane_stride: usize,
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
