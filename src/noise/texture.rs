//! Procedural textures from noise: marble, wood and clouds, written into RGBA8 buffers.
//!
//! ```text
//! marble:  m = sin(ω_m x + τ r(x, y)),   r = Σ αᵏ |f(2ᵏ p)|     veins where m ≈ ±1 … 0
//! wood:    w = frac(ρ ‖p‖ + τ g(p))                             rings, disturbed by the noise
//! clouds:  c = ½ + ½ g(x + t, y)                               fractal sum, drifting with t
//! ```
//! `p = scale · (x, y)` with `(x, y) ∈ [0, 1]²` over the image. Lesson: lessons/05-noise.

use super::{Fractal, Permutation, Shape};
use glam::{Vec2, Vec3};

/// The largest side of a texture: 2048² texels is 16 MB of RGBA.
pub const MAX_TEXTURE_SIZE: usize = 2048;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureKind {
    Marble,
    Wood,
    Clouds,
}

/// What a procedural texture looks like.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextureParams {
    pub kind: TextureKind,
    /// Noise cells across the image, in `(0, 64]`.
    pub scale: f32,
    /// How strongly the noise bends the stripes or rings (τ), in `[0, 20]`.
    pub turbulence: f32,
    /// Octaves: the sums run over k = 0..=n, `n ≤ 8`.
    pub n: u32,
    /// Time (clouds drift, marble and wood flow through 3D noise), in `[−1e4, 1e4]`.
    pub t: f32,
}

impl TextureParams {
    pub fn validate(&self) -> Result<(), String> {
        let check = |name: &str, x: f32, lo: f32, hi: f32| {
            if x.is_finite() && (lo..=hi).contains(&x) {
                Ok(())
            } else {
                Err(format!("{name} must lie in [{lo}, {hi}], got {x}"))
            }
        };
        check("scale", self.scale, 1e-3, 64.0)?;
        check("turbulence", self.turbulence, 0.0, 20.0)?;
        check("t", self.t, -1e4, 1e4)?;
        if self.n > 8 {
            return Err(format!("octaves N must be at most 8, got {}", self.n));
        }
        Ok(())
    }

    /// The colour (linear RGB) at `uv ∈ [0, 1]²` of the image.
    pub fn color(&self, perm: &Permutation, uv: Vec2) -> Vec3 {
        let p = uv * self.scale;
        let f = Fractal {
            n: self.n,
            alpha: 0.5,
            omega: 2.0,
        };
        match self.kind {
            TextureKind::Marble => {
                let (r, _) = f.shaped2_with_derivative(perm, Shape::Ridge, p.x, p.y + 0.3 * self.t);
                let m = (3.0 * p.x + self.turbulence * r).sin();
                // Thin dark veins where m crosses 0, milky stone elsewhere.
                let vein = (1.0 - m.abs()).powi(6);
                Vec3::new(0.85, 0.83, 0.78).lerp(Vec3::new(0.08, 0.09, 0.14), vein)
            }
            TextureKind::Wood => {
                let c = p - Vec2::splat(0.5 * self.scale);
                let g = f.sum3(perm, Vec3::new(p.x, p.y, 0.2 * self.t));
                let w = (2.0 * c.length() + 0.3 * self.turbulence * g).rem_euclid(1.0);
                let ring = (w * std::f32::consts::TAU).sin() * 0.5 + 0.5;
                Vec3::new(0.36, 0.17, 0.06).lerp(Vec3::new(0.7, 0.43, 0.18), ring)
            }
            TextureKind::Clouds => {
                let g = f.sum2(perm, p.x + self.t, p.y);
                let c = (0.5 + (0.5 + 0.1 * self.turbulence) * g).clamp(0.0, 1.0);
                Vec3::new(0.13, 0.3, 0.75).lerp(Vec3::ONE, c.powf(1.5))
            }
        }
    }
}

/// Writes a `width × height` image of `params` into `rgba` (sRGB bytes, row by row from the top),
/// which must hold `4 · width · height` bytes.
pub fn fill_rgba(
    perm: &Permutation,
    params: &TextureParams,
    width: usize,
    height: usize,
    rgba: &mut [u8],
) -> Result<(), String> {
    params.validate()?;
    if !(1..=MAX_TEXTURE_SIZE).contains(&width) || !(1..=MAX_TEXTURE_SIZE).contains(&height) {
        return Err(format!(
            "texture size must be between 1 and {MAX_TEXTURE_SIZE} on a side, got {width}×{height}"
        ));
    }
    if rgba.len() != 4 * width * height {
        return Err(format!(
            "the buffer holds {} bytes, a {width}×{height} RGBA image needs {}",
            rgba.len(),
            4 * width * height
        ));
    }
    for j in 0..height {
        for i in 0..width {
            let uv = Vec2::new(
                (i as f32 + 0.5) / width as f32,
                (j as f32 + 0.5) / height as f32,
            );
            let c = params.color(perm, uv);
            let k = 4 * (j * width + i);
            rgba[k] = to_srgb8(c.x);
            rgba[k + 1] = to_srgb8(c.y);
            rgba[k + 2] = to_srgb8(c.z);
            rgba[k + 3] = 255;
        }
    }
    Ok(())
}

/// A linear channel in `[0, 1]` as an sRGB byte.
pub fn to_srgb8(c: f32) -> u8 {
    let c = c.clamp(0.0, 1.0);
    let s = if c <= 0.0031308 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round() as u8
}

/// An sRGB byte as a linear channel.
pub fn from_srgb8(b: u8) -> f32 {
    let s = b as f32 / 255.0;
    if s <= 0.04045 {
        s / 12.92
    } else {
        ((s + 0.055) / 1.055).powf(2.4)
    }
}
