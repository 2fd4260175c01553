//! Simplex noise (Perlin 2001), in 2D and 3D: Stefan Gustavson's public-domain
//! `simplexnoise1234` (2003–2011), transcribed with the same gradients, skew factors and scale
//! factors, on any [`Permutation`] (Perlin's table gives Gustavson's values).
//!
//! Perlin noise blends the ramps of the `2ⁿ` corners of a square (cube, hypercube) cell. Simplex
//! noise splits space into simplices instead (triangles in 2D, tetrahedra in 3D: `n + 1` corners)
//! and adds up radially fading bumps, one per corner, with no interpolation:
//!
//! ```text
//! skew:    s = (x + y) F₂,  (i, j) = (⌊x + s⌋, ⌊y + s⌋),  F₂ = (√3 − 1)/2,  G₂ = (3 − √3)/6
//! corner:  dₖ = p − cornerₖ  (unskewed with G₂)
//! n(p) = 45.23 Σₖ max(0, ½ − |dₖ|²)⁴ (gₖ · dₖ)           (3D: 0.6 − |dₖ|², scale 32.74)
//! ```
//!
//! Cost: `n + 1` corners instead of `2ⁿ` (3 vs 4 in 2D, 4 vs 8 in 3D, 5 vs 16 in 4D), and the
//! triangles' mixed orientations hide the axis-aligned streaks of a square lattice. Lesson:
//! lessons/05-noise.

use super::Permutation;

// Gustavson's skew factors are `double` literals: the expressions that use them are computed in
// double precision and stored to `float`, which is what keeps large coordinates accurate.
const F2: f64 = 0.366025403; // (√3 − 1) / 2
const G2: f64 = 0.211324865; // (3 − √3) / 6
const F3: f64 = 0.333333333; // 1/3
const G3: f64 = 0.166666667; // 1/6

/// Gustavson's 2D gradients: eight directions `(±1, ±2)` and `(±2, ±1)`, picked by `hash & 7`.
#[inline]
fn grad2(hash: u8, x: f32, y: f32) -> f32 {
    let h = hash & 7;
    let (u, v) = if h < 4 { (x, y) } else { (y, x) };
    (if h & 1 != 0 { -u } else { u }) + (if h & 2 != 0 { -2.0 * v } else { 2.0 * v })
}

/// The twelve cube-edge gradients of Perlin's improved noise, picked by `hash & 15`.
#[inline]
fn grad3(hash: u8, x: f32, y: f32, z: f32) -> f32 {
    let h = hash & 15;
    let u = if h < 8 { x } else { y };
    let v = if h < 4 {
        y
    } else if h == 12 || h == 14 {
        x
    } else {
        z
    };
    (if h & 1 != 0 { -u } else { u }) + (if h & 2 != 0 { -v } else { v })
}

/// One corner's bump: `max(0, r² − |d|²)⁴ · (g · d)` with the dot product already taken.
#[inline]
fn bump(r2: f32, d2: f32, dot: impl FnOnce() -> f32) -> f32 {
    let t = r2 - d2;
    if t < 0.0 {
        0.0
    } else {
        let t2 = t * t;
        t2 * t2 * dot()
    }
}

impl Permutation {
    #[inline(always)]
    fn p(&self, i: i32) -> i32 {
        self.table()[(i & 255) as usize] as i32
    }

    /// 2D simplex noise, in about `[−1, 1]`; continuous with continuous first derivatives.
    pub fn simplex2(&self, x: f32, y: f32) -> f32 {
        let s = ((x + y) as f64 * F2) as f32;
        let (i, j) = ((x + s).floor() as i32, (y + s).floor() as i32);
        let t = ((i + j) as f64 * G2) as f32;
        let (x0, y0) = (x - (i as f32 - t), y - (j as f32 - t));
        // Lower triangle (x0 > y0): corners (0,0), (1,0), (1,1); upper: (0,0), (0,1), (1,1).
        let (i1, j1) = if x0 > y0 { (1, 0) } else { (0, 1) };
        let offset = |d: f32, di: i32, g: f64| (d as f64 - di as f64 + g) as f32;
        let (x1, y1) = (offset(x0, i1, G2), offset(y0, j1, G2));
        let (x2, y2) = (offset(x0, 1, 2.0 * G2), offset(y0, 1, 2.0 * G2));
        let h = |di: i32, dj: i32| self.p(i + di + self.p(j + dj)) as u8;
        let n0 = bump(0.5, x0 * x0 + y0 * y0, || grad2(h(0, 0), x0, y0));
        let n1 = bump(0.5, x1 * x1 + y1 * y1, || grad2(h(i1, j1), x1, y1));
        let n2 = bump(0.5, x2 * x2 + y2 * y2, || grad2(h(1, 1), x2, y2));
        45.23 * (n0 + n1 + n2)
    }

    /// 3D simplex noise, in about `[−1, 1]`.
    pub fn simplex3(&self, x: f32, y: f32, z: f32) -> f32 {
        let s = ((x + y + z) as f64 * F3) as f32;
        let (i, j, k) = (
            (x + s).floor() as i32,
            (y + s).floor() as i32,
            (z + s).floor() as i32,
        );
        let t = ((i + j + k) as f64 * G3) as f32;
        let (x0, y0, z0) = (x - (i as f32 - t), y - (j as f32 - t), z - (k as f32 - t));
        // The tetrahedron: walk from (0,0,0) to (1,1,1) along the axes in decreasing order of
        // the offsets; (i1, j1, k1) is the second corner, (i2, j2, k2) the third.
        let ((i1, j1, k1), (i2, j2, k2)) = if x0 >= y0 {
            if y0 >= z0 {
                ((1, 0, 0), (1, 1, 0))
            } else if x0 >= z0 {
                ((1, 0, 0), (1, 0, 1))
            } else {
                ((0, 0, 1), (1, 0, 1))
            }
        } else if y0 < z0 {
            ((0, 0, 1), (0, 1, 1))
        } else if x0 < z0 {
            ((0, 1, 0), (0, 1, 1))
        } else {
            ((0, 1, 0), (1, 1, 0))
        };
        let h = |di: i32, dj: i32, dk: i32| self.p(i + di + self.p(j + dj + self.p(k + dk))) as u8;
        let offset = |d: f32, di: i32, g: f64| (d as f64 - di as f64 + g) as f32;
        let corner = |di: i32, dj: i32, dk: i32, g: f64| {
            let (dx, dy, dz) = (offset(x0, di, g), offset(y0, dj, g), offset(z0, dk, g));
            bump(0.6, dx * dx + dy * dy + dz * dz, || {
                grad3(h(di, dj, dk), dx, dy, dz)
            })
        };
        let n = corner(0, 0, 0, 0.0)
            + corner(i1, j1, k1, G3)
            + corner(i2, j2, k2, 2.0 * G3)
            + corner(1, 1, 1, 3.0 * G3);
        32.74 * n
    }
}

/// Corners a simplex cell has in `n` dimensions (`n + 1`) and a Perlin cell has (`2ⁿ`): the work
/// per sample grows linearly for simplex noise, exponentially for Perlin's.
pub fn corners_per_sample(n: u32) -> (u64, u64) {
    (n as u64 + 1, 1u64 << n.min(63))
}
