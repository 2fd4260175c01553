//! Lesson 05 core: a height-field terrain from fractal noise.
//!
//! The course's surface, with y up (its z is our y, its v our z):
//! ```text
//! S(u, v) = (u, h · g(s(u + o), s(v + o)), v),      (u, v) ∈ [−1, 1]²
//! g(x, y) = Σ_{k=0}^{N} αᵏ f(ωᵏ x, ωᵏ y)            (or a ridge, marble or animated variant)
//! ```
//! h scales the height, s the horizontal frequency (zoom), o shifts the window. The normal comes
//! from the exact derivative of g (chain rule), not from finite differences or averaged faces:
//! ```text
//! ∂y/∂u = h s ∂g/∂x,  ∂y/∂v = h s ∂g/∂y,   n = (−∂y/∂u, 1, −∂y/∂v) / ‖·‖
//! ```
//! [`Terrain::regenerate`] rewrites positions, normals and colours in place: changing a
//! parameter never reallocates. Lesson: lessons/05-noise.

use crate::noise::{Fractal, Permutation, Shape};
use glam::{Vec2, Vec3, Vec4};

/// The most vertices along a side: 1024² ≈ 1 M vertices (about 40 MB of vertex data on the
/// GPU). Regeneration costs grow with resolution² × (N + 1).
pub const MAX_RESOLUTION: usize = 1024;

/// Which function of the noise gives the height.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Variant {
    /// The fractal sum `g`.
    Sum,
    /// `Σ αᵏ |f|`: creases in the valleys.
    Ridge,
    /// `Σ αᵏ (1 − |f|)`, shifted down by its mean so it sits near 0: sharp mountain crests.
    InvertedRidge,
    /// `sin(4x + Σ αᵏ |f|)`: marble veins as a relief.
    Marble,
    /// `g(x, y + t)`: the whole pattern slides.
    Sliding { t: f32 },
    /// `g(x, y, t)` with 3D noise: the pattern evolves in place.
    Evolving { t: f32 },
}

/// Everything that shapes a terrain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TerrainParams {
    pub fractal: Fractal,
    /// Height scale h (metres per unit of g), in `[0, 2]`.
    pub h: f32,
    /// Horizontal scale s (noise cells per metre), in `(0, 16]`.
    pub s: f32,
    /// Offset o, in `[−1000, 1000]`.
    pub o: f32,
    pub variant: Variant,
}

impl Default for TerrainParams {
    /// The course's example: N = 9, α = 0.4, ω = 2, h = 0.3, s = 1, o = 0.
    fn default() -> Self {
        Self {
            fractal: Fractal::COURSE,
            h: 0.3,
            s: 1.0,
            o: 0.0,
            variant: Variant::Sum,
        }
    }
}

impl TerrainParams {
    /// An error naming the parameter when one is out of range or not finite.
    pub fn validate(&self) -> Result<(), String> {
        self.fractal.validate()?;
        let check = |name: &str, x: f32, lo: f32, hi: f32| {
            if x.is_finite() && (lo..=hi).contains(&x) {
                Ok(())
            } else {
                Err(format!("{name} must lie in [{lo}, {hi}], got {x}"))
            }
        };
        check("h", self.h, 0.0, 2.0)?;
        check("s", self.s, 1e-3, 16.0)?;
        check("o", self.o, -1000.0, 1000.0)?;
        if let Variant::Sliding { t } | Variant::Evolving { t } = self.variant {
            check("t", t, -1e4, 1e4)?;
        }
        Ok(())
    }

    /// The height function of the noise domain and its gradient there: `(g, ∂g/∂x, ∂g/∂y)`.
    #[inline]
    pub fn g(&self, perm: &Permutation, x: f32, y: f32) -> (f32, Vec2) {
        let f = &self.fractal;
        match self.variant {
            Variant::Sum => f.shaped2_with_derivative(perm, Shape::Sum, x, y),
            Variant::Ridge => f.shaped2_with_derivative(perm, Shape::Ridge, x, y),
            Variant::InvertedRidge => {
                let (q, dq) = f.shaped2_with_derivative(perm, Shape::InvertedRidge, x, y);
                (q - 0.7 * f.amplitude_sum(), dq)
            }
            Variant::Marble => {
                let (r, dr) = f.shaped2_with_derivative(perm, Shape::Ridge, x, y);
                let phase = 4.0 * x + r;
                (
                    0.5 * phase.sin(),
                    0.5 * phase.cos() * (Vec2::new(4.0, 0.0) + dr),
                )
            }
            Variant::Sliding { t } => f.shaped2_with_derivative(perm, Shape::Sum, x, y + t),
            Variant::Evolving { t } => {
                let (g, d) = f.sum3_with_derivative(perm, Vec3::new(x, y, t));
                (g, d.truncate())
            }
        }
    }
}

/// The unit normal of a height field `y(u, v)` from its two partial derivatives:
/// `n = (−∂y/∂u, 1, −∂y/∂v) / ‖(−∂y/∂u, 1, −∂y/∂v)‖` (the cross product of the tangents
/// `(0, ∂y/∂v, 1) × (1, ∂y/∂u, 0)`).
#[inline]
pub fn height_field_normal(dy_du: f32, dy_dv: f32) -> Vec3 {
    Vec3::new(-dy_du, 1.0, -dy_dv).normalize()
}

/// The normal of the course's terrain `y = h g(s(u + o), s(v + o))` from the gradient of `g` at
/// `(s(u + o), s(v + o))`: by the chain rule `∂y/∂u = h s ∂g/∂x` and `∂y/∂v = h s ∂g/∂y`.
#[inline]
pub fn terrain_normal(h: f32, s: f32, grad_g: Vec2) -> Vec3 {
    height_field_normal(h * s * grad_g.x, h * s * grad_g.y)
}

/// The last octave a mesh of `resolution` vertices per side over `[−1, 1]` can show, for a
/// terrain of scale `s` and frequency gain `omega`. Octave k has noise cells `1/(s ωᵏ)` metres
/// wide and the vertices are `Δ = 2/(resolution − 1)` apart; a cell of `2Δ` or less gets at most
/// two vertices (at or past the Nyquist limit of the mesh), so its bumps fall between vertices
/// and come back as one-vertex spikes of the wrong size (aliasing). Octave k is kept while
/// `s ωᵏ < 1/(2Δ) = (resolution − 1)/4`. `None` when even octave 0 is too fine; with `ω = 1`
/// every octave has octave 0's cells, so all of them are kept ([`crate::noise::MAX_N`]).
pub fn last_resolved_octave(resolution: usize, s: f32, omega: f32) -> Option<u32> {
    let limit = resolution.saturating_sub(1) as f32 / 4.0;
    // A relative slack so that a cell of exactly 2Δ (s ωᵏ = limit, 129 vertices at ω = 2)
    // counts as past the limit in spite of round-off.
    let fits = |freq: f32| freq < limit * (1.0 - 1e-6);
    if !fits(s) {
        return None;
    }
    let mut k = 0;
    let mut freq = s;
    while k < crate::noise::MAX_N && fits(freq * omega) {
        freq *= omega;
        k += 1;
    }
    Some(k)
}

/// A colour for a terrain vertex from its height (metres) and its normal: water-blue in the lowest
/// parts (below `−0.3 · h_max`), sand, then grass, rock on slopes steeper than about 35°, snow
/// above `0.45 · h_max` on flat ground. Linear RGBA.
pub fn terrain_color(height: f32, normal: Vec3, h_max: f32) -> Vec4 {
    let h_max = h_max.max(1e-6);
    // Multiplications by reciprocals (constant, or hoisted out of a loop over vertices) instead
    // of five divisions per vertex.
    let rel = height * h_max.recip(); // roughly −1 … 1
    let water = Vec3::new(0.05, 0.18, 0.45);
    let sand = Vec3::new(0.65, 0.55, 0.3);
    let grass = Vec3::new(0.12, 0.35, 0.06);
    let rock = Vec3::new(0.28, 0.24, 0.21);
    let snow = Vec3::new(0.9, 0.92, 0.95);
    let smooth = |a: f32, b: f32, x: f32| ((x - a) * (1.0 / (b - a))).clamp(0.0, 1.0);
    let mut c = water.lerp(sand, smooth(-0.32, -0.26, rel));
    c = c.lerp(grass, smooth(-0.24, -0.14, rel));
    let steep = smooth(0.12, 0.25, 1.0 - normal.y); // 1 − cos(slope)
    c = c.lerp(rock, steep);
    let high = smooth(0.4, 0.5, rel) * (1.0 - steep);
    c = c.lerp(snow, high);
    c.extend(1.0)
}

/// A square height-field mesh over `[−1, 1]²` with `resolution` vertices per side, and the
/// buffers it is regenerated into.
#[derive(Clone, Debug)]
pub struct Terrain {
    resolution: usize,
    /// World space, row by row (v major): vertex `(i, j)` is at index `j · resolution + i`.
    pub positions: Vec<Vec3>,
    /// Unit normals, from the analytic derivative.
    pub normals: Vec<Vec3>,
    /// Linear RGBA by height and slope ([`terrain_color`]).
    pub colors: Vec<Vec4>,
    /// Three per triangle, counter-clockwise seen from above.
    pub indices: Vec<u32>,
    /// One row of work for [`Terrain::regenerate`], kept so regenerating allocates nothing.
    scratch: RowScratch,
}

/// Per-row buffers of [`Terrain::regenerate`] (one entry per vertex of a row).
#[derive(Clone, Debug, Default)]
struct RowScratch {
    /// `s (u + o)` of each column: the noise domain's x before an octave's frequency.
    base_x: Vec<f32>,
    /// This octave's x coordinates, `ωᵏ s (u + o)`.
    xs: Vec<f32>,
    /// This octave's noise and its gradient.
    f: Vec<f32>,
    fx: Vec<f32>,
    fy: Vec<f32>,
    /// The sum so far and its gradient.
    g: Vec<f32>,
    gx: Vec<f32>,
    gy: Vec<f32>,
}

impl RowScratch {
    /// Adds one octave (amplitude `a`, `aw = αᵏ ωᵏ`) of the row's noise, shaped by `shape`, to
    /// the sum and its gradient: `g += a s(f)`, `∇g += αᵏ ωᵏ s′(f) ∇f`.
    #[inline(always)]
    fn accumulate(&mut self, n: usize, a: f32, aw: f32, shape: impl Fn(f32) -> (f32, f32)) {
        let (f, fx, fy) = (&self.f[..n], &self.fx[..n], &self.fy[..n]);
        let (g, gx, gy) = (&mut self.g[..n], &mut self.gx[..n], &mut self.gy[..n]);
        for i in 0..n {
            let (sv, ds) = shape(f[i]);
            g[i] += a * sv;
            gx[i] += (aw * ds) * fx[i];
            gy[i] += (aw * ds) * fy[i];
        }
    }

    fn new(n: usize) -> Self {
        let v = || vec![0.0; n];
        Self {
            base_x: v(),
            xs: v(),
            f: v(),
            fx: v(),
            fy: v(),
            g: v(),
            gx: v(),
            gy: v(),
        }
    }
}

impl Terrain {
    /// Allocates a flat terrain; errors unless `2 ≤ resolution ≤ MAX_RESOLUTION`.
    pub fn new(resolution: usize) -> Result<Self, String> {
        if !(2..=MAX_RESOLUTION).contains(&resolution) {
            return Err(format!(
                "resolution must be between 2 and {MAX_RESOLUTION}, got {resolution}"
            ));
        }
        let n = resolution * resolution;
        let mut indices = Vec::with_capacity((resolution - 1) * (resolution - 1) * 6);
        for j in 0..resolution - 1 {
            for i in 0..resolution - 1 {
                let a = (j * resolution + i) as u32;
                let b = a + 1;
                let c = a + resolution as u32;
                let d = c + 1;
                // Seen from +y, +x to the right and +z towards the viewer: a c b, b c d are CCW.
                indices.extend_from_slice(&[a, c, b, b, c, d]);
            }
        }
        let mut t = Self {
            resolution,
            positions: vec![Vec3::ZERO; n],
            normals: vec![Vec3::Y; n],
            colors: vec![Vec4::ONE; n],
            indices,
            scratch: RowScratch::new(resolution),
        };
        for j in 0..resolution {
            for i in 0..resolution {
                let (u, v) = t.uv(i, j);
                t.positions[j * resolution + i] = Vec3::new(u, 0.0, v);
            }
        }
        Ok(t)
    }

    pub fn resolution(&self) -> usize {
        self.resolution
    }

    /// The parameters `(u, v)` of vertex `(i, j)`.
    #[inline]
    pub fn uv(&self, i: usize, j: usize) -> (f32, f32) {
        let step = 2.0 / (self.resolution - 1) as f32;
        (-1.0 + i as f32 * step, -1.0 + j as f32 * step)
    }

    /// Rewrites heights, normals and colours for `params` in place (no allocation).
    ///
    /// Row by row, octave by octave: every vertex of a row shares the noise's y, so each octave
    /// of a row is one [`Permutation::noise2_row_with_derivative`] call (the y part of the
    /// lattice work once per row, the hashes once per cell), and the fractal sum runs over the
    /// row's arrays. The result is [`TerrainParams::g`] at every vertex to a few `f32`
    /// roundings. The evolving variant (3D noise) is evaluated point by point.
    pub fn regenerate(&mut self, perm: &Permutation, params: &TerrainParams) -> Result<(), String> {
        params.validate()?;
        let TerrainParams { h, s, o, .. } = *params;
        let h_max = (h * params.fractal.amplitude_sum() * 0.5).max(1e-6);
        let r = self.resolution;
        let step = 2.0 / (r - 1) as f32;
        let shape = match params.variant {
            Variant::Sum | Variant::Sliding { .. } => Some(Shape::Sum),
            Variant::Ridge | Variant::Marble => Some(Shape::Ridge),
            Variant::InvertedRidge => Some(Shape::InvertedRidge),
            Variant::Evolving { .. } => None,
        };
        let f = params.fractal;
        let inverted_mean = 0.7 * f.amplitude_sum();
        let sc = &mut self.scratch;
        for i in 0..r {
            sc.base_x[i] = s * (-1.0 + i as f32 * step + o);
        }
        for j in 0..r {
            let v = -1.0 + j as f32 * step;
            let row = j * r;
            let y = s * (v + o);
            if let Some(shape) = shape {
                let y = match params.variant {
                    Variant::Sliding { t } => y + t,
                    _ => y,
                };
                sc.g.fill(0.0);
                sc.gx.fill(0.0);
                sc.gy.fill(0.0);
                let (mut a, mut w) = (1.0f32, 1.0f32);
                for _ in 0..=f.n {
                    for (x, &b) in sc.xs.iter_mut().zip(&sc.base_x) {
                        *x = w * b;
                    }
                    perm.noise2_row_with_derivative(
                        &sc.xs,
                        w * y,
                        &mut sc.f,
                        &mut sc.fx,
                        &mut sc.fy,
                    );
                    let aw = a * w;
                    match shape {
                        Shape::Sum => sc.accumulate(r, a, aw, |f| Shape::Sum.apply(f)),
                        Shape::Ridge => sc.accumulate(r, a, aw, |f| Shape::Ridge.apply(f)),
                        Shape::InvertedRidge => {
                            sc.accumulate(r, a, aw, |f| Shape::InvertedRidge.apply(f))
                        }
                    }
                    a *= f.alpha;
                    w *= f.omega;
                }
                if let Variant::InvertedRidge = params.variant {
                    for g in &mut sc.g[..r] {
                        *g -= inverted_mean;
                    }
                }
                if let Variant::Marble = params.variant {
                    for i in 0..r {
                        let phase = 4.0 * sc.base_x[i] + sc.g[i];
                        let (sin, cos) = phase.sin_cos();
                        sc.g[i] = 0.5 * sin;
                        sc.gx[i] = 0.5 * cos * (4.0 + sc.gx[i]);
                        sc.gy[i] *= 0.5 * cos;
                    }
                }
            } else {
                for i in 0..r {
                    let (g, dg) = params.g(perm, sc.base_x[i], y);
                    (sc.g[i], sc.gx[i], sc.gy[i]) = (g, dg.x, dg.y);
                }
            }
            for i in 0..r {
                let u = -1.0 + i as f32 * step;
                let y = h * sc.g[i];
                let n = terrain_normal(h, s, Vec2::new(sc.gx[i], sc.gy[i]));
                let k = row + i;
                self.positions[k] = Vec3::new(u, y, v);
                self.normals[k] = n;
                self.colors[k] = terrain_color(y, n, h_max);
            }
        }
        Ok(())
    }

    /// The mesh as [`crate::mesh::MeshData`] (copies; for creating the GPU mesh once).
    pub fn mesh_data(&self) -> crate::mesh::MeshData {
        crate::mesh::MeshData {
            positions: self.positions.clone(),
            normals: self.normals.clone(),
            indices: self.indices.clone(),
        }
    }
}
