//! Phong and Blinn-Phong shading of one fragment.
//!
//! A fragment on a surface with unit normal `n`, seen along the unit vector `v` (from the surface
//! to the eye) and lit from the unit direction `l` (from the surface to the light), gets the sum
//! of three terms (a white light of intensity 1, surface colour `C`):
//! ```text
//! ambient  = k_a C                                   light that arrives from everywhere
//! diffuse  = k_d C max(n·l, 0)                       Lambert: light per area ∝ cos(angle)
//! specular = k_s max(r·v, 0)^s      r = 2(n·l) n − l (Phong: the mirror direction of l)
//! specular = k_s max(n·h, 0)^s      h = (l + v)/|l + v|  (Blinn-Phong: the halfway vector)
//! ```
//! The specular term is 0 where the light is behind the surface (`n·l ≤ 0`). Blinn-Phong's
//! highlight is wider for the same exponent `s` (the angle between `n` and `h` is about half
//! the angle between `r` and `v`); an exponent about 4 times larger gives a similar highlight.

use glam::Vec3;

/// The surface: its colour (linear RGB) and the weights of the three terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub color: Vec3,
    pub ambient: f32,
    pub diffuse: f32,
    pub specular: f32,
    /// The specular exponent `s` (≥ 0): larger is a smaller, sharper highlight.
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            color: Vec3::new(0.8, 0.25, 0.05),
            ambient: 0.15,
            diffuse: 0.7,
            specular: 0.5,
            shininess: 32.0,
        }
    }
}

/// Which specular term.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadingModel {
    Phong,
    BlinnPhong,
}

/// The three terms of one fragment's colour (linear RGB); their sum is the colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadingTerms {
    pub ambient: Vec3,
    pub diffuse: Vec3,
    pub specular: Vec3,
}

impl ShadingTerms {
    pub fn total(&self) -> Vec3 {
        self.ambient + self.diffuse + self.specular
    }
}

/// The three terms at a fragment with unit normal `n`, unit light direction `l` and unit view
/// direction `v` (both pointing away from the surface).
pub fn shade(n: Vec3, l: Vec3, v: Vec3, m: &Material, model: ShadingModel) -> ShadingTerms {
    let n_dot_l = n.dot(l);
    let lit = n_dot_l > 0.0;
    let specular = if !lit {
        0.0
    } else {
        let cos = match model {
            ShadingModel::Phong => (2.0 * n_dot_l * n - l).dot(v),
            ShadingModel::BlinnPhong => n.dot((l + v).normalize_or_zero()),
        };
        m.specular * cos.max(0.0).powf(m.shininess)
    };
    ShadingTerms {
        ambient: m.ambient * m.color,
        diffuse: m.diffuse * n_dot_l.max(0.0) * m.color,
        specular: Vec3::splat(specular),
    }
}

/// Phong's colour of one fragment (the sum of [`shade`]'s terms).
pub fn phong(n: Vec3, l: Vec3, v: Vec3, m: &Material) -> Vec3 {
    shade(n, l, v, m, ShadingModel::Phong).total()
}

/// Blinn-Phong's colour of one fragment (the sum of [`shade`]'s terms).
pub fn blinn_phong(n: Vec3, l: Vec3, v: Vec3, m: &Material) -> Vec3 {
    shade(n, l, v, m, ShadingModel::BlinnPhong).total()
}

/// Which part of the colour an image shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Term {
    Ambient,
    Diffuse,
    Specular,
    Total,
}

/// Half the width of the square of view space an image of the unit sphere covers.
const IMAGE_HALF_WIDTH: f32 = 1.1;

/// The unit sphere's normal under the pixel centre `(i, j)` of a `size × size` image seen from +z
/// (orthographic, y up, row 0 at the top), or `None` off the sphere.
pub fn sphere_normal_at(i: usize, j: usize, size: usize) -> Option<Vec3> {
    let to = |k: usize| (2.0 * (k as f32 + 0.5) / size as f32 - 1.0) * IMAGE_HALF_WIDTH;
    let (x, y) = (to(i), -to(j));
    let r2 = x * x + y * y;
    (r2 < 1.0).then(|| Vec3::new(x, y, (1.0 - r2).sqrt()))
}

/// The direction from the sphere's centre to the point under `(u, v) ∈ [0, 1]²` of an image
/// (u to the right, v down): where a reader points the light. Off the sphere, the rim.
pub fn light_from_image(u: f32, v: f32) -> Vec3 {
    let x = (2.0 * u - 1.0) * IMAGE_HALF_WIDTH;
    let y = -(2.0 * v - 1.0) * IMAGE_HALF_WIDTH;
    let r2 = x * x + y * y;
    if r2 < 0.999 {
        Vec3::new(x, y, (1.0 - r2).sqrt())
    } else {
        Vec3::new(x, y, 0.045 * r2.sqrt()).normalize()
    }
}

/// Linear to sRGB-encoded byte.
fn srgb_byte(c: f32) -> u8 {
    let c = c.clamp(0.0, 1.0);
    let s = if c <= 0.0031308 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round() as u8
}

/// The largest image side [`sphere_image`] draws (its cost grows with the square of the side).
pub const MAX_IMAGE_SIZE: usize = 512;

/// An RGBA (sRGB bytes, row 0 at the top) image of the unit sphere seen from +z (`v = +z`
/// everywhere: an orthographic view), showing one `term` of the shading with the light from `l`.
/// `size` is clamped to [`MAX_IMAGE_SIZE`]. The background is light grey.
pub fn sphere_image(
    size: usize,
    l: Vec3,
    m: &Material,
    model: ShadingModel,
    term: Term,
) -> Vec<u8> {
    let size = size.min(MAX_IMAGE_SIZE);
    let mut out = Vec::with_capacity(size * size * 4);
    for j in 0..size {
        for i in 0..size {
            let rgb = match sphere_normal_at(i, j, size) {
                None => Vec3::splat(0.87),
                Some(n) => {
                    let t = shade(n, l, Vec3::Z, m, model);
                    match term {
                        Term::Ambient => t.ambient,
                        Term::Diffuse => t.diffuse,
                        Term::Specular => t.specular,
                        Term::Total => t.total(),
                    }
                }
            };
            out.extend([srgb_byte(rgb.x), srgb_byte(rgb.y), srgb_byte(rgb.z), 255]);
        }
    }
    out
}

/// Like [`sphere_image`] with `Term::Total`, but shaded the way a vertex-lit mesh is (Gouraud
/// shading): the colour is computed only at the vertices of a UV sphere of `segments × rings`
/// (as [`crate::mesh::uv_sphere`] lays them out) and interpolated linearly across each triangle
/// of the grid. A highlight narrower than a triangle falls between the vertices and comes out as
/// a blotch with corners, where [`sphere_image`], shading every pixel, keeps it round.
/// `segments ≥ 3` and `rings ≥ 2` (smaller values are raised to these).
pub fn gouraud_sphere_image(
    size: usize,
    l: Vec3,
    m: &Material,
    model: ShadingModel,
    segments: u32,
    rings: u32,
) -> Vec<u8> {
    use std::f32::consts::{PI, TAU};
    let size = size.min(MAX_IMAGE_SIZE);
    let (segments, rings) = (segments.max(3), rings.max(2));
    let vertex = |ring: u32, segment: u32| {
        let polar = PI * ring as f32 / rings as f32;
        let azimuth = TAU * segment as f32 / segments as f32;
        let n = Vec3::new(
            polar.sin() * azimuth.sin(),
            polar.cos(),
            polar.sin() * azimuth.cos(),
        );
        shade(n, l, Vec3::Z, m, model).total()
    };
    let mut out = Vec::with_capacity(size * size * 4);
    for j in 0..size {
        for i in 0..size {
            let rgb = match sphere_normal_at(i, j, size) {
                None => Vec3::splat(0.87),
                Some(n) => {
                    // Where the pixel lies on the grid: ring and segment, and the fractions
                    // (s across the segment, r down the ring) inside that cell.
                    let polar = n.y.clamp(-1.0, 1.0).acos() / PI * rings as f32;
                    let azimuth = n.x.atan2(n.z).rem_euclid(TAU) / TAU * segments as f32;
                    let ring = (polar.floor() as u32).min(rings - 1);
                    let segment = (azimuth.floor() as u32).min(segments - 1);
                    let (r, s) = (polar - ring as f32, azimuth - segment as f32);
                    let a = vertex(ring, segment);
                    let a1 = vertex(ring, segment + 1);
                    let b = vertex(ring + 1, segment);
                    let b1 = vertex(ring + 1, segment + 1);
                    // The cell's two triangles (a, b, a+1) and (a+1, b, b+1), as the mesh's.
                    if s + r <= 1.0 {
                        a * (1.0 - s - r) + a1 * s + b * r
                    } else {
                        b1 * (s + r - 1.0) + b * (1.0 - s) + a1 * (1.0 - r)
                    }
                }
            };
            out.extend([srgb_byte(rgb.x), srgb_byte(rgb.y), srgb_byte(rgb.z), 255]);
        }
    }
    out
}
