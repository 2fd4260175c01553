//! Ken Perlin's improved gradient noise (2002) in one, two and three dimensions.
//!
//! Source: K. Perlin, "Improving Noise", SIGGRAPH 2002, and his Java reference implementation
//! `ImprovedNoise` (<https://mrl.cs.nyu.edu/~perlin/noise/>). [`noise3_f64`] follows that code
//! operation by operation in doubles and reproduces it to the last bit
//! (`noise3_f64(3.14, 42.0, 7.0) = 0.13691995878400012`); [`Permutation::noise3`] is the same
//! algorithm in `f32`, with analytic derivatives beside it.

use glam::{Vec2, Vec3};

/// Perlin's permutation of 0..=255, copied from his reference implementation.
pub const PERLIN_PERMUTATION: [u8; 256] = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
];

/// Perlin's quintic fade curve and its derivative:
/// ```text
/// fade(t)  = 6t⁵ − 15t⁴ + 10t³        fade(0) = 0, fade(1) = 1
/// fade′(t) = 30t⁴ − 60t³ + 30t² = 30 t² (t − 1)²      fade′ = fade″ = 0 at t = 0 and 1
/// ```
/// Zero first and second derivatives at both ends make the noise C² across cell borders (the 1985
/// noise used `3t² − 2t³`, whose second derivative jumps). Lesson: lessons/05-noise.
#[inline]
pub fn fade(t: f32) -> f32 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// The derivative of [`fade`]: `30 t² (t − 1)²`.
#[inline]
pub fn fade_derivative(t: f32) -> f32 {
    30.0 * t * t * (t - 1.0) * (t - 1.0)
}

/// The second derivative of [`fade`]: `120t³ − 180t² + 60t = 60 t (2t − 1)(t − 1)`, zero at
/// both ends (the 1985 curve `3t² − 2t³` has `6 − 12t`: 6 at t = 0, −6 at t = 1).
#[inline]
pub fn fade_second_derivative(t: f32) -> f32 {
    60.0 * t * (2.0 * t - 1.0) * (t - 1.0)
}

/// `a + t (b − a)`, as in the reference (`t = 0` gives `a`, `t = 1` gives `b`).
#[inline]
fn lerp(t: f32, a: f32, b: f32) -> f32 {
    a + t * (b - a)
}

/// The reference's `grad(hash, x, y, z)` as a vector: the hash's low four bits pick one of twelve
/// edge directions of a cube (four of them twice), `(±1, ±1, 0)`, `(±1, 0, ±1)`, `(0, ±1, ±1)`.
const fn grad3_vector(hash: usize) -> [f32; 3] {
    let h = hash & 15;
    // u is x or y, v is y, x or z; bit 0 negates u, bit 1 negates v.
    let mut g = [0.0f32; 3];
    let su = if h & 1 == 0 { 1.0 } else { -1.0 };
    let sv = if h & 2 == 0 { 1.0 } else { -1.0 };
    if h < 8 {
        g[0] = su;
    } else {
        g[1] = su;
    }
    if h < 4 {
        g[1] = sv;
    } else if h == 12 || h == 14 {
        g[0] = sv;
    } else {
        g[2] = sv;
    }
    g
}

const fn grad3_table() -> [[f32; 3]; 16] {
    let mut t = [[0.0; 3]; 16];
    let mut h = 0;
    while h < 16 {
        t[h] = grad3_vector(h);
        h += 1;
    }
    t
}

/// The sixteen gradients of the reference, indexed by `hash & 15`.
pub const GRAD3: [[f32; 3]; 16] = grad3_table();

/// Lattice gradient of the 1D noise (not in Perlin's reference, which is 3D): a slope in
/// `±{1/8, 2/8, …, 1}` picked by `hash & 15`.
#[inline]
pub fn grad1(hash: usize) -> f32 {
    let h = hash & 15;
    let slope = ((h >> 1) + 1) as f32 / 8.0;
    if h & 1 == 0 {
        slope
    } else {
        -slope
    }
}

/// The gradient of the 2D noise at a lattice point with this hash: the `(x, y)` part of the 3D
/// reference's gradient (the 2D noise is the reference's slice `z = 0`).
#[inline]
pub fn grad2(hash: usize) -> Vec2 {
    let g = GRAD3[hash & 15];
    Vec2::new(g[0], g[1])
}

/// `floor` for `|x| < 2³¹` as an integer, without a libm call on targets lacking SSE4.1.
#[inline]
fn floor_i32(x: f32) -> i32 {
    let i = x as i32;
    if x < i as f32 {
        i - 1
    } else {
        i
    }
}

/// A doubled permutation table: `p[i] = p[i + 256]`, so hashes of neighbouring lattice points
/// need no wrap-around. Lattice coordinates repeat every 256 cells.
#[derive(Clone, Debug, PartialEq)]
pub struct Permutation {
    p: [u8; 512],
}

impl Default for Permutation {
    fn default() -> Self {
        Self::perlin()
    }
}

impl Permutation {
    /// Perlin's own table ([`PERLIN_PERMUTATION`]).
    pub fn perlin() -> Self {
        Self::from_table(&PERLIN_PERMUTATION)
    }

    /// Any table of 256 entries. It should be a permutation of 0..=255 for the noise to look
    /// uniform, but any bytes are safe.
    pub fn from_table(table: &[u8; 256]) -> Self {
        let mut p = [0u8; 512];
        p[..256].copy_from_slice(table);
        p[256..].copy_from_slice(table);
        Self { p }
    }

    /// A random permutation drawn from `seed` (Fisher–Yates with SplitMix64): the same seed gives
    /// the same table on every machine. Seed 0 is not special; use [`Permutation::perlin`] for
    /// Perlin's table.
    pub fn seeded(seed: u64) -> Self {
        let mut table = [0u8; 256];
        for (i, t) in table.iter_mut().enumerate() {
            *t = i as u8;
        }
        let mut rng = crate::fixtures::Rng::new(seed);
        for i in (1..256).rev() {
            let j = (rng.next_u64() % (i as u64 + 1)) as usize;
            table.swap(i, j);
        }
        Self::from_table(&table)
    }

    /// The first 256 entries.
    pub fn table(&self) -> &[u8] {
        &self.p[..256]
    }

    #[inline(always)]
    fn at(&self, i: usize) -> usize {
        self.p[i & 511] as usize
    }

    /// The hash of lattice point `(i, j)` of the 2D noise (as the reference hashes `(i, j, 0)`).
    #[inline]
    pub fn hash2(&self, i: i32, j: i32) -> usize {
        let (x, y) = ((i & 255) as usize, (j & 255) as usize);
        self.at(self.at(self.at(x) + y))
    }

    /// The reference's hash chain for the 3D cell whose low corner is `(xx, yy, zz)` (each
    /// coordinate `& 255`): the table indices `[aa, ba, ab, bb]`, whose entries hash the cell's
    /// corners 000, 100, 010, 110 and whose next entries (`aa + 1`, …) the corners 001, 101, 011,
    /// 111. Shared by the per-point, row and batch noises.
    #[inline(always)]
    fn cell_hashes3(&self, xx: usize, yy: usize, zz: usize) -> [usize; 4] {
        let (a, b) = (self.at(xx) + yy, self.at(xx + 1) + yy);
        [
            self.at(a) + zz,
            self.at(b) + zz,
            self.at(a + 1) + zz,
            self.at(b + 1) + zz,
        ]
    }

    /// The hash of lattice point `(i, j, k)` of the 3D noise, as the reference computes it.
    pub fn hash3(&self, i: i32, j: i32, k: i32) -> usize {
        let (x, y, z) = ((i & 255) as usize, (j & 255) as usize, (k & 255) as usize);
        self.at(self.at(self.at(x) + y) + z)
    }

    /// The gradient of the 3D noise at lattice point `(i, j, k)` (one of [`GRAD3`]).
    pub fn gradient3(&self, i: i32, j: i32, k: i32) -> Vec3 {
        Vec3::from(GRAD3[self.hash3(i, j, k) & 15])
    }

    /// The hash of lattice point `i` of the 1D noise.
    #[inline]
    pub fn hash1(&self, i: i32) -> usize {
        self.at((i & 255) as usize)
    }

    /// One-dimensional gradient noise: slopes [`grad1`] at the integers, blended by [`fade`].
    /// ```text
    /// n(x) = lerp(fade(t), g₀ t, g₁ (t − 1)),     t = x − ⌊x⌋
    /// ```
    /// Zero at every integer; `|n| ≤ 0.5`. Returns the value and `dn/dx`.
    pub fn noise1_with_derivative(&self, x: f32) -> (f32, f32) {
        let xi = floor_i32(x);
        let t = x - xi as f32;
        let (g0, g1) = (grad1(self.hash1(xi)), grad1(self.hash1(xi + 1)));
        let (a, b) = (g0 * t, g1 * (t - 1.0));
        let u = fade(t);
        let value = lerp(u, a, b);
        let slope = lerp(u, g0, g1) + fade_derivative(t) * (b - a);
        (value, slope)
    }

    /// [`Permutation::noise1_with_derivative`] without the derivative.
    #[inline]
    pub fn noise1(&self, x: f32) -> f32 {
        self.noise1_with_derivative(x).0
    }

    /// Two-dimensional improved noise: the reference's `noise(x, y, 0)`, computed from the four
    /// corners of the square cell only.
    /// ```text
    /// n(x, y) = lerp(v, lerp(u, g₀₀·d₀₀, g₁₀·d₁₀), lerp(u, g₀₁·d₀₁, g₁₁·d₁₁))
    /// d_ij = (x, y) − corner_ij,   u = fade(x − ⌊x⌋),  v = fade(y − ⌊y⌋)
    /// ```
    /// Zero at every lattice point; `|n| ≤ 1` (in practice about ±0.9).
    #[inline]
    pub fn noise2(&self, x: f32, y: f32) -> f32 {
        let (xi, yi) = (floor_i32(x), floor_i32(y));
        let (x, y) = (x - xi as f32, y - yi as f32);
        let (xx, yy) = ((xi & 255) as usize, (yi & 255) as usize);
        let a = self.at(xx) + yy;
        let b = self.at(xx + 1) + yy;
        let (aa, ab, ba, bb) = (self.at(a), self.at(a + 1), self.at(b), self.at(b + 1));
        let dot = |h: usize, dx: f32, dy: f32| {
            let g = GRAD3[self.at(h) & 15];
            g[0] * dx + g[1] * dy
        };
        let (u, v) = (fade(x), fade(y));
        lerp(
            v,
            lerp(u, dot(aa, x, y), dot(ba, x - 1.0, y)),
            lerp(u, dot(ab, x, y - 1.0), dot(bb, x - 1.0, y - 1.0)),
        )
    }

    /// [`Permutation::noise2`] and its gradient `(∂n/∂x, ∂n/∂y)`, exact (no finite differences):
    /// ```text
    /// n = k₀ + k₁u + k₂v + k₃uv,   k₀ = n₀₀, k₁ = n₁₀ − n₀₀, k₂ = n₀₁ − n₀₀, k₃ = n₀₀ − n₁₀ − n₀₁ + n₁₁
    /// ∇n = bilerp(u, v; g₀₀, g₁₀, g₀₁, g₁₁) + (fade′(x)(k₁ + k₃v), fade′(y)(k₂ + k₃u))
    /// ```
    #[inline]
    pub fn noise2_with_derivative(&self, x: f32, y: f32) -> (f32, Vec2) {
        let (xi, yi) = (floor_i32(x), floor_i32(y));
        // The same hashes as noise2 (six table lookups for the four corners).
        let (xx, yy) = ((xi & 255) as usize, (yi & 255) as usize);
        let a = self.at(xx) + yy;
        let b = self.at(xx + 1) + yy;
        let g = |h: usize| grad2(self.at(h));
        let g = [
            g(self.at(a)),
            g(self.at(b)),
            g(self.at(a + 1)),
            g(self.at(b + 1)),
        ];
        cell2_with_derivative(Vec2::new(x - xi as f32, y - yi as f32), g)
    }

    /// Perlin's improved noise in 3D, in `f32`: the reference algorithm (see [`noise3_f64`]) with
    /// the same permutation and gradients. Agrees with the double-precision reference to `f32`
    /// rounding (about 1e-6 near the origin).
    #[inline]
    pub fn noise3(&self, x: f32, y: f32, z: f32) -> f32 {
        self.noise3_with_derivative_impl::<false>(Vec3::new(x, y, z))
            .0
    }

    /// [`Permutation::noise3`] and its exact gradient.
    pub fn noise3_with_derivative(&self, p: Vec3) -> (f32, Vec3) {
        self.noise3_with_derivative_impl::<true>(p)
    }

    #[inline(always)]
    fn noise3_with_derivative_impl<const DERIV: bool>(&self, p: Vec3) -> (f32, Vec3) {
        let (xi, yi, zi) = (floor_i32(p.x), floor_i32(p.y), floor_i32(p.z));
        let (x, y, z) = (p.x - xi as f32, p.y - yi as f32, p.z - zi as f32);
        let (xx, yy, zz) = (
            (xi & 255) as usize,
            (yi & 255) as usize,
            (zi & 255) as usize,
        );
        let [aa, ba, ab, bb] = self.cell_hashes3(xx, yy, zz);
        let g = |h: usize| GRAD3[self.at(h) & 15];
        let dot = |g: [f32; 3], dx: f32, dy: f32, dz: f32| g[0] * dx + g[1] * dy + g[2] * dz;
        let (g000, g100, g010, g110) = (g(aa), g(ba), g(ab), g(bb));
        let (g001, g101, g011, g111) = (g(aa + 1), g(ba + 1), g(ab + 1), g(bb + 1));
        let n000 = dot(g000, x, y, z);
        let n100 = dot(g100, x - 1.0, y, z);
        let n010 = dot(g010, x, y - 1.0, z);
        let n110 = dot(g110, x - 1.0, y - 1.0, z);
        let n001 = dot(g001, x, y, z - 1.0);
        let n101 = dot(g101, x - 1.0, y, z - 1.0);
        let n011 = dot(g011, x, y - 1.0, z - 1.0);
        let n111 = dot(g111, x - 1.0, y - 1.0, z - 1.0);
        let (u, v, w) = (fade(x), fade(y), fade(z));
        let value = lerp(
            w,
            lerp(v, lerp(u, n000, n100), lerp(u, n010, n110)),
            lerp(v, lerp(u, n001, n101), lerp(u, n011, n111)),
        );
        if !DERIV {
            return (value, Vec3::ZERO);
        }
        // value = k0 + k1 u + k2 v + k3 w + k4 uv + k5 vw + k6 wu + k7 uvw
        let k1 = n100 - n000;
        let k2 = n010 - n000;
        let k3 = n001 - n000;
        let k4 = n000 - n100 - n010 + n110;
        let k5 = n000 - n010 - n001 + n011;
        let k6 = n000 - n100 - n001 + n101;
        let k7 = -n000 + n100 + n010 - n110 + n001 - n101 - n011 + n111;
        let gv = |g: [f32; 3]| Vec3::from_array(g);
        let tri = Vec3::lerp(
            Vec3::lerp(
                Vec3::lerp(gv(g000), gv(g100), u),
                Vec3::lerp(gv(g010), gv(g110), u),
                v,
            ),
            Vec3::lerp(
                Vec3::lerp(gv(g001), gv(g101), u),
                Vec3::lerp(gv(g011), gv(g111), u),
                v,
            ),
            w,
        );
        let d = Vec3::new(
            fade_derivative(x) * (k1 + k4 * v + k6 * w + k7 * v * w),
            fade_derivative(y) * (k2 + k4 * u + k5 * w + k7 * u * w),
            fade_derivative(z) * (k3 + k5 * v + k6 * u + k7 * u * v),
        );
        (value, tri + d)
    }
}

/// A 2D cell of a row (fixed `y`) reduced to what changes along x: with the corner gradients
/// fixed and `fy`, `v = fade(fy)` known, the values on the cell's two vertical edges, blended
/// over y, are linear in `fx`: `A = a0 + a1 fx` on the edge x = 0, `B = b0 + b1 fx` on the edge
/// x = 1 (each corner's ramp continued across the cell), and `n = A + fade(fx) (B − A)`. The
/// y-derivative needs `∂n/∂y = c0 + fade(fx) c1 + fade′(fy) (Q − P)` with
/// `Q − P = e0 + e1 fx + fade(fx) (f0 + f1 fx)` (the top edge minus the bottom edge).
#[derive(Clone, Copy, Default)]
struct RowCell2 {
    a0: f32,
    a1: f32,
    b0: f32,
    b1: f32,
    c0: f32,
    c1: f32,
    e0: f32,
    e1: f32,
    f0: f32,
    f1: f32,
}

impl RowCell2 {
    /// Corner gradients `g = [g₀₀, g₁₀, g₀₁, g₁₁]`, `fy ∈ [0, 1)`, `v = fade(fy)`.
    #[inline(always)]
    fn new(g: [[f32; 3]; 4], fy: f32, v: f32) -> Self {
        let [g00, g10, g01, g11] = g;
        // n_ij(fx) = gx (fx − i) + gy (fy − j): slope gx, intercept at fx = 0.
        let i00 = g00[1] * fy;
        let i10 = -g10[0] + g10[1] * fy;
        let i01 = g01[1] * (fy - 1.0);
        let i11 = -g11[0] + g11[1] * (fy - 1.0);
        let (e0, e1) = (i01 - i00, g01[0] - g00[0]);
        let (h0, h1) = (i11 - i10, g11[0] - g10[0]);
        let c0 = g00[1] + v * (g01[1] - g00[1]);
        Self {
            a0: i00 + v * e0,
            a1: g00[0] + v * e1,
            b0: i10 + v * h0,
            b1: g10[0] + v * h1,
            c0,
            c1: g10[1] + v * (g11[1] - g10[1]) - c0,
            e0,
            e1,
            f0: h0 - e0,
            f1: h1 - e1,
        }
    }
}

impl Permutation {
    /// The gradients at lattice points `(x, j)` and `(x, j + 1)` of the 2D noise, `yy = j & 255`.
    #[inline(always)]
    fn column2(&self, x: i32, yy: usize) -> ([f32; 3], [f32; 3]) {
        let a = self.at((x & 255) as usize) + yy;
        // The hash of (i, j, 0), as noise2: p[p[p[i] + j] + 0].
        let g = |h: usize| GRAD3[self.at(self.at(h)) & 15];
        (g(a), g(a + 1))
    }

    /// The gradients of the four corners of the 2D cells along a row, `[g₀₀, g₁₀, g₀₁, g₁₁]` of
    /// cell `xi`: a cell's right column is the next cell's left one, so a row walked left to
    /// right hashes each column once (`right` keeps the last cell's right column).
    #[inline(always)]
    fn corners2(&self, xi: i32, yy: usize, right: &mut (i32, [f32; 3], [f32; 3])) -> [[f32; 3]; 4] {
        let (g00, g01) = if right.0 == xi {
            (right.1, right.2)
        } else {
            self.column2(xi, yy)
        };
        let (g10, g11) = self.column2(xi.wrapping_add(1), yy);
        *right = (xi.wrapping_add(1), g10, g11);
        [g00, g10, g01, g11]
    }

    /// [`Permutation::noise2`] at `(xs[k], y)` for every `k`, into `out[k]` (the shorter length
    /// wins). The fast path for rows of a grid: the y part of the lattice work (the row's
    /// `⌊y⌋`, `fade(y)`) is done once, each cell's hashes and gradients once per run of
    /// consecutive points in that cell, and the points of a run go through a loop without
    /// branches, which the compiler vectorises (SSE2 natively, simd128 in wasm). `xs` may come
    /// in any order; sorted rows make the longest runs. Agrees with `noise2` to a few `f32`
    /// roundings (the same function, summed in another order).
    ///
    /// Never inlined: a function of its own, it is compiled the same way whatever else is in
    /// the build (inlined into `Fractal::sum2_row`'s octave loop in the full release module, the
    /// fBm rows ran 18 to 27 % slower than built alone; `scripts/bench-alone.mjs`). It is
    /// called once per row of up to 256 points, so the call costs nothing measurable.
    #[inline(never)]
    pub fn noise2_row(&self, xs: &[f32], y: f32, out: &mut [f32]) {
        let n = xs.len().min(out.len());
        let (xs, out) = (&xs[..n], &mut out[..n]);
        let yi = floor_i32(y);
        let fy = y - yi as f32;
        let yy = (yi & 255) as usize;
        let v = fade(fy);
        let mut right = (i32::MIN, [0.0; 3], [0.0; 3]);
        for_each_cell_run(xs, |xi, run| {
            let c = RowCell2::new(self.corners2(xi, yy, &mut right), fy, v);
            let xf = xi as f32;
            let (xs, out) = (&xs[run.clone()], &mut out[run]);
            for (o, &x) in out.iter_mut().zip(xs) {
                let fx = x - xf;
                let a = c.a0 + c.a1 * fx;
                let b = c.b0 + c.b1 * fx;
                *o = a + fade(fx) * (b - a);
            }
        });
    }

    /// [`Permutation::noise2_row`] with the exact gradient: `out[k]`, `dx[k]`, `dy[k]` are
    /// [`Permutation::noise2_with_derivative`] at `(xs[k], y)`, to a few `f32` roundings.
    pub fn noise2_row_with_derivative(
        &self,
        xs: &[f32],
        y: f32,
        out: &mut [f32],
        dx: &mut [f32],
        dy: &mut [f32],
    ) {
        let n = xs.len().min(out.len()).min(dx.len()).min(dy.len());
        let (xs, out, dx, dy) = (&xs[..n], &mut out[..n], &mut dx[..n], &mut dy[..n]);
        let yi = floor_i32(y);
        let fy = y - yi as f32;
        let yy = (yi & 255) as usize;
        let (v, dv) = (fade(fy), fade_derivative(fy));
        let mut right = (i32::MIN, [0.0; 3], [0.0; 3]);
        for_each_cell_run(xs, |xi, run| {
            let c = RowCell2::new(self.corners2(xi, yy, &mut right), fy, v);
            let xf = xi as f32;
            let m = run.len();
            let xs = &xs[run.clone()];
            let out = &mut out[run.clone()][..m];
            let dx = &mut dx[run.clone()][..m];
            let dy = &mut dy[run][..m];
            for k in 0..m {
                let fx = xs[k] - xf;
                let (u, du) = (fade(fx), fade_derivative(fx));
                let a = c.a0 + c.a1 * fx;
                let b = c.b0 + c.b1 * fx;
                out[k] = a + u * (b - a);
                dx[k] = c.a1 + u * (c.b1 - c.a1) + du * (b - a);
                let q_minus_p = c.e0 + c.e1 * fx + u * (c.f0 + c.f1 * fx);
                dy[k] = c.c0 + u * c.c1 + dv * q_minus_p;
            }
        });
    }

    /// [`Permutation::noise3`] at `(xs[k], y, z)` for every `k`, into `out[k]`: the 3D row fast
    /// path, as [`Permutation::noise2_row`] (per cell along x, the eight corner ramps blended
    /// over y and z collapse to one line on each of the cell's two x faces).
    pub fn noise3_row(&self, xs: &[f32], y: f32, z: f32, out: &mut [f32]) {
        let n = xs.len().min(out.len());
        let (xs, out) = (&xs[..n], &mut out[..n]);
        let (yi, zi) = (floor_i32(y), floor_i32(z));
        let (fy, fz) = (y - yi as f32, z - zi as f32);
        let (yy, zz) = ((yi & 255) as usize, (zi & 255) as usize);
        let (v, w) = (fade(fy), fade(fz));
        for_each_cell_run(xs, |xi, run| {
            let xx = (xi & 255) as usize;
            let [aa, ba, ab, bb] = self.cell_hashes3(xx, yy, zz);
            let g = |h: usize| GRAD3[self.at(h) & 15];
            // A corner's ramp along x at this row: slope gx, plus its y, z part.
            let yz = |g: [f32; 3], dy: f32, dz: f32| g[1] * dy + g[2] * dz;
            let blend = |c00: f32, c10: f32, c01: f32, c11: f32| {
                lerp(w, lerp(v, c00, c10), lerp(v, c01, c11))
            };
            let (g000, g010, g001, g011) = (g(aa), g(ab), g(aa + 1), g(ab + 1));
            let (g100, g110, g101, g111) = (g(ba), g(bb), g(ba + 1), g(bb + 1));
            let a1 = blend(g000[0], g010[0], g001[0], g011[0]);
            let a0 = blend(
                yz(g000, fy, fz),
                yz(g010, fy - 1.0, fz),
                yz(g001, fy, fz - 1.0),
                yz(g011, fy - 1.0, fz - 1.0),
            );
            let b1 = blend(g100[0], g110[0], g101[0], g111[0]);
            let b0 = blend(
                yz(g100, fy, fz),
                yz(g110, fy - 1.0, fz),
                yz(g101, fy, fz - 1.0),
                yz(g111, fy - 1.0, fz - 1.0),
            ) - b1;
            let xf = xi as f32;
            let (xs, out) = (&xs[run.clone()], &mut out[run]);
            for (o, &x) in out.iter_mut().zip(xs) {
                let fx = x - xf;
                let a = a0 + a1 * fx;
                let b = b0 + b1 * fx;
                *o = a + fade(fx) * (b - a);
            }
        });
    }
}

/// How many scattered points the batch kernels ([`Permutation::noise2_batch`],
/// [`Permutation::noise3_batch`]) take at a time: the lattice work of a block is done point by
/// point (hashes and gradient lookups do not vectorise), then the blend of every point of the
/// block in one loop without branches over arrays of this length, which the compiler turns into
/// SIMD (two SSE2 or simd128 vectors of four).
pub const BATCH_LANES: usize = 8;

impl Permutation {
    /// [`Permutation::noise2`] at `(xs[k], ys[k])` for every `k`, into `out[k]` (the shortest
    /// length wins): the fast path for scattered points, [`BATCH_LANES`] points at a time (in
    /// wasm, point by point: see the body). Equal to `noise2` bit for bit: the same operations in
    /// the same order.
    pub fn noise2_batch(&self, xs: &[f32], ys: &[f32], out: &mut [f32]) {
        let n = xs.len().min(ys.len()).min(out.len());
        // In wasm the blocks cost more than they save in 2D (V8: 1.6 ms against 0.67 ms point
        // by point for 65,536 points; in 3D the blocks win): there the points go one by one.
        if cfg!(target_arch = "wasm32") {
            for k in 0..n {
                out[k] = self.noise2(xs[k], ys[k]);
            }
            return;
        }
        const L: usize = BATCH_LANES;
        for start in (0..n).step_by(L) {
            let m = (n - start).min(L);
            // Per lane: the position in its cell and the x, y of the four corner gradients
            // (order 00, 10, 01, 11). Unused lanes stay zero and are not copied out.
            let mut f = [[0.0f32; L]; 2];
            let mut g = [[[0.0f32; L]; 2]; 4];
            for l in 0..m {
                let (x, y) = (xs[start + l], ys[start + l]);
                let (xi, yi) = (floor_i32(x), floor_i32(y));
                f[0][l] = x - xi as f32;
                f[1][l] = y - yi as f32;
                let (xx, yy) = ((xi & 255) as usize, (yi & 255) as usize);
                let a = self.at(xx) + yy;
                let b = self.at(xx + 1) + yy;
                // The hash of (i, j, 0), as noise2: p[p[p[i] + j] + 0].
                let hashes = [self.at(a), self.at(b), self.at(a + 1), self.at(b + 1)];
                for (c, h) in hashes.into_iter().enumerate() {
                    let v = GRAD3[self.at(h) & 15];
                    g[c][0][l] = v[0];
                    g[c][1][l] = v[1];
                }
            }
            let mut o = [0.0f32; L];
            for l in 0..L {
                let (x, y) = (f[0][l], f[1][l]);
                let dot = |c: usize, dx: f32, dy: f32| g[c][0][l] * dx + g[c][1][l] * dy;
                let (u, v) = (fade(x), fade(y));
                o[l] = lerp(
                    v,
                    lerp(u, dot(0, x, y), dot(1, x - 1.0, y)),
                    lerp(u, dot(2, x, y - 1.0), dot(3, x - 1.0, y - 1.0)),
                );
            }
            out[start..start + m].copy_from_slice(&o[..m]);
        }
    }

    /// [`Permutation::noise3`] at `(xs[k], ys[k], zs[k])` for every `k`, into `out[k]` (the
    /// shortest length wins), as [`Permutation::noise2_batch`]: equal to `noise3` (as numbers:
    /// where the noise is zero, at lattice points, the zero's sign may differ).
    pub fn noise3_batch(&self, xs: &[f32], ys: &[f32], zs: &[f32], out: &mut [f32]) {
        let n = xs.len().min(ys.len()).min(zs.len()).min(out.len());
        const L: usize = BATCH_LANES;
        for start in (0..n).step_by(L) {
            let m = (n - start).min(L);
            // The block's points (unused lanes zero), their cells and positions in them: loops
            // without branches over whole arrays, which vectorise.
            let mut p = [[0.0f32; L]; 3];
            for (c, src) in [xs, ys, zs].into_iter().enumerate() {
                p[c][..m].copy_from_slice(&src[start..start + m]);
            }
            let mut cell = [[0i32; L]; 3];
            let mut f = [[0.0f32; L]; 3];
            for c in 0..3 {
                for l in 0..L {
                    cell[c][l] = floor_i32(p[c][l]);
                    f[c][l] = p[c][l] - cell[c][l] as f32;
                }
            }
            // Per lane, the hashes of the eight corners, in the order 000, 100, 010, 110, 001,
            // 101, 011, 111 (corner xyz): table lookups, one lane at a time. The gradients are
            // picked from the hashes in the blend loop (selects, which vectorise; a table lookup
            // per component would not).
            let mut h = [[0u32; L]; 8];
            for l in 0..m {
                let (xx, yy, zz) = (
                    (cell[0][l] & 255) as usize,
                    (cell[1][l] & 255) as usize,
                    (cell[2][l] & 255) as usize,
                );
                let [aa, ba, ab, bb] = self.cell_hashes3(xx, yy, zz);
                let hashes = [aa, ba, ab, bb, aa + 1, ba + 1, ab + 1, bb + 1];
                for (c, hc) in hashes.into_iter().enumerate() {
                    h[c][l] = self.at(hc) as u32;
                }
            }
            let mut o = [0.0f32; L];
            for l in 0..L {
                let (x, y, z) = (f[0][l], f[1][l], f[2][l]);
                let dot = |c: usize, dx: f32, dy: f32, dz: f32| grad3_dot(h[c][l], dx, dy, dz);
                let n000 = dot(0, x, y, z);
                let n100 = dot(1, x - 1.0, y, z);
                let n010 = dot(2, x, y - 1.0, z);
                let n110 = dot(3, x - 1.0, y - 1.0, z);
                let n001 = dot(4, x, y, z - 1.0);
                let n101 = dot(5, x - 1.0, y, z - 1.0);
                let n011 = dot(6, x, y - 1.0, z - 1.0);
                let n111 = dot(7, x - 1.0, y - 1.0, z - 1.0);
                let (u, v, w) = (fade(x), fade(y), fade(z));
                o[l] = lerp(
                    w,
                    lerp(v, lerp(u, n000, n100), lerp(u, n010, n110)),
                    lerp(v, lerp(u, n001, n101), lerp(u, n011, n111)),
                );
            }
            out[start..start + m].copy_from_slice(&o[..m]);
        }
    }
}

/// `GRAD3[hash & 15] · (dx, dy, dz)` as the reference's `grad` computes it, with selects instead
/// of a table (selects vectorise across points; see [`grad3_vector`] for the rule): `±u ± v`,
/// u = dx or dy, v = dy, dx or dz. The same number as the table's dot product, which also adds
/// the zero component's `0 · d`: only the sign of a zero result can differ.
#[inline(always)]
fn grad3_dot(hash: u32, dx: f32, dy: f32, dz: f32) -> f32 {
    let h = hash & 15;
    let u = if h < 8 { dx } else { dy };
    let v = if h < 4 {
        dy
    } else if h == 12 || h == 14 {
        dx
    } else {
        dz
    };
    (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
}

/// Splits `xs` into runs of consecutive entries in one lattice cell `[xi, xi + 1)` and calls
/// `f(xi, run)` for each, in order (a NaN makes a run of its own).
#[inline(always)]
fn for_each_cell_run(xs: &[f32], mut f: impl FnMut(i32, std::ops::Range<usize>)) {
    let n = xs.len();
    let mut k = 0;
    while k < n {
        let xi = floor_i32(xs[k]);
        let (lo, hi) = (xi as f32, (xi + 1) as f32);
        let mut end = k + 1;
        while end < n && xs[end] >= lo && xs[end] < hi {
            end += 1;
        }
        f(xi, k..end);
        k = end;
    }
}

/// One 2D noise evaluation inside a unit cell from its four corner gradients, `g = [g₀₀, g₁₀,
/// g₀₁, g₁₁]` (corner `(i, j)` at `(i, j)`), at `p = (x, y) ∈ [0, 1]²`:
/// ```text
/// n = lerp(fade(y), lerp(fade(x), g₀₀·p, g₁₀·(p − (1,0))), lerp(fade(x), g₀₁·(p − (0,1)), g₁₁·(p − (1,1))))
/// ```
/// This is the step inside [`Permutation::noise2`] once the hash has chosen the gradients.
pub fn cell2(p: Vec2, g: [Vec2; 4]) -> f32 {
    cell2_with_derivative(p, g).0
}

/// [`cell2`] and its gradient with respect to `p`. Written out in scalars: this is the inner
/// loop of every terrain (one call per octave per vertex).
#[inline]
pub fn cell2_with_derivative(p: Vec2, g: [Vec2; 4]) -> (f32, Vec2) {
    let (x, y) = (p.x, p.y);
    let n00 = g[0].x * x + g[0].y * y;
    let n10 = g[1].x * (x - 1.0) + g[1].y * y;
    let n01 = g[2].x * x + g[2].y * (y - 1.0);
    let n11 = g[3].x * (x - 1.0) + g[3].y * (y - 1.0);
    let (u, v) = (fade(x), fade(y));
    let value = lerp(v, lerp(u, n00, n10), lerp(u, n01, n11));
    let (k1, k2, k3) = (n10 - n00, n01 - n00, n00 - n10 - n01 + n11);
    // The gradients blended like the values, plus the fade curves' slopes times the differences.
    let bx = lerp(v, lerp(u, g[0].x, g[1].x), lerp(u, g[2].x, g[3].x));
    let by = lerp(v, lerp(u, g[0].y, g[1].y), lerp(u, g[2].y, g[3].y));
    let dx = bx + fade_derivative(x) * (k1 + k3 * v);
    let dy = by + fade_derivative(y) * (k2 + k3 * u);
    (value, Vec2::new(dx, dy))
}

/// Perlin's reference `noise(x, y, z)` in doubles, operation for operation, with his table.
/// Kept for checking [`Permutation::noise3`] and as a faithful transcription to read.
pub fn noise3_f64(x: f64, y: f64, z: f64) -> f64 {
    let p = |i: usize| PERLIN_PERMUTATION[i & 255] as usize;
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let lerp = |t: f64, a: f64, b: f64| a + t * (b - a);
    let grad = |hash: usize, x: f64, y: f64, z: f64| {
        let h = hash & 15;
        let u = if h < 8 { x } else { y };
        let v = if h < 4 {
            y
        } else if h == 12 || h == 14 {
            x
        } else {
            z
        };
        (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
    };
    let (fx, fy, fz) = (x.floor(), y.floor(), z.floor());
    let (xx, yy, zz) = (
        (fx as i64 & 255) as usize,
        (fy as i64 & 255) as usize,
        (fz as i64 & 255) as usize,
    );
    let (x, y, z) = (x - fx, y - fy, z - fz);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let a = p(xx) + yy;
    let aa = p(a) + zz;
    let ab = p(a + 1) + zz;
    let b = p(xx + 1) + yy;
    let ba = p(b) + zz;
    let bb = p(b + 1) + zz;
    lerp(
        w,
        lerp(
            v,
            lerp(u, grad(p(aa), x, y, z), grad(p(ba), x - 1.0, y, z)),
            lerp(
                u,
                grad(p(ab), x, y - 1.0, z),
                grad(p(bb), x - 1.0, y - 1.0, z),
            ),
        ),
        lerp(
            v,
            lerp(
                u,
                grad(p(aa + 1), x, y, z - 1.0),
                grad(p(ba + 1), x - 1.0, y, z - 1.0),
            ),
            lerp(
                u,
                grad(p(ab + 1), x, y - 1.0, z - 1.0),
                grad(p(bb + 1), x - 1.0, y - 1.0, z - 1.0),
            ),
        ),
    )
}
