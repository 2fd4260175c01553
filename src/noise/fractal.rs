//! Fractal sums of noise: octaves of growing frequency and shrinking amplitude.
//!
//! ```text
//! g(x) = Σ_{k=0}^{N} αᵏ f(ωᵏ x)          fractal sum (fBm): N + 1 octaves
//! r(x) = Σ_{k=0}^{N} αᵏ |f(ωᵏ x)|        ridge; with α = 1/2, ω = 2 this is Perlin's turbulence
//! q(x) = Σ_{k=0}^{N} αᵏ (1 − |f(ωᵏ x)|)  inverted ridge: sharp crests instead of sharp creases
//! m(x) = sin(c x + r(x))                marble: c stripes per 2π along x, bent by r
//! ```
//! α is the attenuation (1/α the persistence), ω the frequency gain. Lesson: lessons/05-noise.

use super::Permutation;
use glam::{Vec2, Vec3};

/// The most octaves a sum may have (`N ≤ 16`): at ω = 2 the 17th octave is 65 536 times finer
/// than the first, far below a pixel; the cap bounds the cost of one sample.
pub const MAX_N: u32 = 16;

/// The row and batch sums ([`Fractal::sum2_row`], [`Fractal::sum2_batch`], ...) work through
/// their points this many at a time, with their scratch on the stack (no allocation).
pub const CHUNK: usize = 256;

/// Parameters of a fractal sum. `n` is the course's N, the index of the last octave, so there
/// are `n + 1` terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal {
    /// Last octave index N, in `0..=MAX_N`.
    pub n: u32,
    /// Attenuation α: octave k has amplitude αᵏ. In `[0, 1]`.
    pub alpha: f32,
    /// Frequency gain ω: octave k has frequency ωᵏ. In `[1, 4]`.
    pub omega: f32,
}

impl Default for Fractal {
    fn default() -> Self {
        Self::COURSE
    }
}

/// What a sample of a fractal sum is made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// `Σ αᵏ f(ωᵏ x)`.
    Sum,
    /// `Σ αᵏ |f(ωᵏ x)|`.
    Ridge,
    /// `Σ αᵏ (1 − |f(ωᵏ x)|)`.
    InvertedRidge,
}

impl Shape {
    /// The shape applied to one octave's value `f`: `(s(f), s′(f))`.
    #[inline(always)]
    pub fn apply(self, f: f32) -> (f32, f32) {
        // (value, d value / d f)
        match self {
            Shape::Sum => (f, 1.0),
            Shape::Ridge => (f.abs(), if f < 0.0 { -1.0 } else { 1.0 }),
            Shape::InvertedRidge => (1.0 - f.abs(), if f < 0.0 { 1.0 } else { -1.0 }),
        }
    }
}

impl Fractal {
    /// The course's terrain: N = 9, α = 0.4, ω = 2.
    pub const COURSE: Fractal = Fractal {
        n: 9,
        alpha: 0.4,
        omega: 2.0,
    };

    /// An error naming the parameter unless `n ≤ MAX_N`, `α ∈ [0, 1]`, `ω ∈ [1, 4]`.
    pub fn validate(&self) -> Result<(), String> {
        if self.n > MAX_N {
            return Err(format!("N must be at most {MAX_N}, got {}", self.n));
        }
        if !(0.0..=1.0).contains(&self.alpha) {
            return Err(format!("alpha must lie in [0, 1], got {}", self.alpha));
        }
        if !(1.0..=4.0).contains(&self.omega) {
            return Err(format!("omega must lie in [1, 4], got {}", self.omega));
        }
        Ok(())
    }

    /// `Σ αᵏ` over the octaves: the largest a sum of terms bounded by 1 can reach.
    pub fn amplitude_sum(&self) -> f32 {
        (0..=self.n).map(|k| self.alpha.powi(k as i32)).sum()
    }

    /// Octave k alone at `(x, y)`: `αᵏ f(ωᵏ x, ωᵏ y)` (the plotted contributions).
    pub fn octave2(&self, perm: &Permutation, k: u32, x: f32, y: f32) -> f32 {
        let (a, w) = (self.alpha.powi(k as i32), self.omega.powi(k as i32));
        a * perm.noise2(w * x, w * y)
    }

    /// The fractal sum `g(x, y)` of 2D noise.
    #[inline]
    pub fn sum2(&self, perm: &Permutation, x: f32, y: f32) -> f32 {
        let (mut a, mut w, mut g) = (1.0, 1.0, 0.0);
        for _ in 0..=self.n {
            g += a * perm.noise2(w * x, w * y);
            a *= self.alpha;
            w *= self.omega;
        }
        g
    }

    /// The octave loop of the row and batch sums: `out[k] = Σ αᵏ f_k(k)` over the octaves, [`CHUNK`]
    /// points at a time. `octave(start, w, scratch)` writes octave `w`'s noise (ω to the octave's
    /// power) at points `start..start + scratch.len()` into `scratch`; the weights are added in
    /// the order `sum2` adds them, so a batch of exact per-point values gives `sum2`'s bits.
    fn octaves(&self, out: &mut [f32], mut octave: impl FnMut(usize, f32, &mut [f32])) {
        let mut scratch = [0.0f32; CHUNK];
        let n = out.len();
        for start in (0..n).step_by(CHUNK) {
            let m = (n - start).min(CHUNK);
            let out = &mut out[start..start + m];
            out.fill(0.0);
            let (mut a, mut w) = (1.0f32, 1.0f32);
            for _ in 0..=self.n {
                octave(start, w, &mut scratch[..m]);
                for (o, &v) in out.iter_mut().zip(&scratch[..m]) {
                    *o += a * v;
                }
                a *= self.alpha;
                w *= self.omega;
            }
        }
    }

    /// [`Fractal::sum2`] at `(xs[k], y)` for every `k`, into `out[k]` (the shorter length wins):
    /// the fast path for rows of a grid (terrains, textures). Each octave is one
    /// [`Permutation::noise2_row`] over the row scaled by ωᵏ (the scaled row stays sorted when
    /// `xs` is, as ω ≥ 1), added with weight αᵏ; the scratch rows are on the stack, [`CHUNK`]
    /// points at a time. Agrees with `sum2` to a few `f32` roundings per octave.
    pub fn sum2_row(&self, perm: &Permutation, xs: &[f32], y: f32, out: &mut [f32]) {
        let n = xs.len().min(out.len());
        let mut sx = [0.0f32; CHUNK];
        self.octaves(&mut out[..n], |start, w, octave| {
            let m = octave.len();
            for (s, &x) in sx[..m].iter_mut().zip(&xs[start..start + m]) {
                *s = w * x;
            }
            perm.noise2_row(&sx[..m], w * y, octave);
        });
    }

    /// [`Fractal::sum3`] at `(xs[k], y, z)` for every `k`, into `out[k]`, as
    /// [`Fractal::sum2_row`] with [`Permutation::noise3_row`].
    pub fn sum3_row(&self, perm: &Permutation, xs: &[f32], y: f32, z: f32, out: &mut [f32]) {
        let n = xs.len().min(out.len());
        let mut sx = [0.0f32; CHUNK];
        self.octaves(&mut out[..n], |start, w, octave| {
            let m = octave.len();
            for (s, &x) in sx[..m].iter_mut().zip(&xs[start..start + m]) {
                *s = w * x;
            }
            perm.noise3_row(&sx[..m], w * y, w * z, octave);
        });
    }

    /// [`Fractal::sum2`] at scattered points `(xs[k], ys[k])`, into `out[k]` (the shortest length
    /// wins): each octave is one [`Permutation::noise2_batch`] over the scaled points. Equal to
    /// `sum2` bit for bit (the same operations in the same order).
    pub fn sum2_batch(&self, perm: &Permutation, xs: &[f32], ys: &[f32], out: &mut [f32]) {
        let n = xs.len().min(ys.len()).min(out.len());
        let mut s = [[0.0f32; CHUNK]; 2];
        self.octaves(&mut out[..n], |start, w, octave| {
            let m = octave.len();
            for k in 0..m {
                s[0][k] = w * xs[start + k];
                s[1][k] = w * ys[start + k];
            }
            perm.noise2_batch(&s[0][..m], &s[1][..m], octave);
        });
    }

    /// [`Fractal::sum3`] at scattered points `(xs[k], ys[k], zs[k])`, into `out[k]`, as
    /// [`Fractal::sum2_batch`] with [`Permutation::noise3_batch`]: equal to `sum3` (as numbers; a
    /// zero's sign may differ).
    pub fn sum3_batch(
        &self,
        perm: &Permutation,
        xs: &[f32],
        ys: &[f32],
        zs: &[f32],
        out: &mut [f32],
    ) {
        let n = xs.len().min(ys.len()).min(zs.len()).min(out.len());
        let mut s = [[0.0f32; CHUNK]; 3];
        self.octaves(&mut out[..n], |start, w, octave| {
            let m = octave.len();
            for k in 0..m {
                s[0][k] = w * xs[start + k];
                s[1][k] = w * ys[start + k];
                s[2][k] = w * zs[start + k];
            }
            perm.noise3_batch(&s[0][..m], &s[1][..m], &s[2][..m], octave);
        });
    }

    /// The 1D fractal sum (the lesson's first plots).
    pub fn sum1(&self, perm: &Permutation, x: f32) -> f32 {
        let (mut a, mut w, mut g) = (1.0, 1.0, 0.0);
        for _ in 0..=self.n {
            g += a * perm.noise1(w * x);
            a *= self.alpha;
            w *= self.omega;
        }
        g
    }

    /// A sum of the given `shape` and its exact gradient: each term contributes
    /// `αᵏ ωᵏ s′(f) ∇f(ωᵏ x)` (chain rule; `s′` jumps where a ridge folds, at `f = 0`).
    #[inline]
    pub fn shaped2_with_derivative(
        &self,
        perm: &Permutation,
        shape: Shape,
        x: f32,
        y: f32,
    ) -> (f32, Vec2) {
        let (mut a, mut w) = (1.0f32, 1.0f32);
        let (mut g, mut dg) = (0.0, Vec2::ZERO);
        for _ in 0..=self.n {
            let (f, df) = perm.noise2_with_derivative(w * x, w * y);
            let (s, ds) = shape.apply(f);
            g += a * s;
            dg += (a * w * ds) * df;
            a *= self.alpha;
            w *= self.omega;
        }
        (g, dg)
    }

    /// The fractal sum of 3D noise and its gradient (animated terrain: `g(x, y, t)`).
    pub fn sum3_with_derivative(&self, perm: &Permutation, p: Vec3) -> (f32, Vec3) {
        let (mut a, mut w) = (1.0f32, 1.0f32);
        let (mut g, mut dg) = (0.0, Vec3::ZERO);
        for _ in 0..=self.n {
            let (f, df) = perm.noise3_with_derivative(w * p);
            g += a * f;
            dg += (a * w) * df;
            a *= self.alpha;
            w *= self.omega;
        }
        (g, dg)
    }

    /// The fractal sum of 3D noise.
    pub fn sum3(&self, perm: &Permutation, p: Vec3) -> f32 {
        let (mut a, mut w, mut g) = (1.0, 1.0, 0.0);
        for _ in 0..=self.n {
            g += a * perm.noise3(w * p.x, w * p.y, w * p.z);
            a *= self.alpha;
            w *= self.omega;
        }
        g
    }
}

/// Perlin's turbulence: `Σ_{k=0}^{N} |f(2ᵏ x)| / 2ᵏ`, the ridge sum with α = 1/2 and ω = 2.
pub fn turbulence2(perm: &Permutation, n: u32, x: f32, y: f32) -> f32 {
    let f = Fractal {
        n,
        alpha: 0.5,
        omega: 2.0,
    };
    f.shaped2_with_derivative(perm, Shape::Ridge, x, y).0
}

/// Marble: `sin(stripes · x + r(x, y))` with the ridge sum `r` of `fractal`, in `[−1, 1]`.
pub fn marble2(perm: &Permutation, fractal: &Fractal, stripes: f32, x: f32, y: f32) -> f32 {
    let r = fractal.shaped2_with_derivative(perm, Shape::Ridge, x, y).0;
    (stripes * x + r).sin()
}
