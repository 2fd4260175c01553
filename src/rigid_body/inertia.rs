//! Mass properties: the inertia tensors of a box, a sphere and a cylinder about their centres of
//! mass, the parallel-axis theorem, and bodies made of several boxes.
//!
//! The inertia tensor `I` maps an angular velocity to the angular momentum it carries, `L = I ω`.
//! For a solid it is `∫ ρ (|r|² E − r rᵀ) dV` over the body, `r` measured from the point the
//! tensor is taken about. Its diagonal holds the moments about the three axes (the larger, the
//! harder the body is to spin about that axis); a shape symmetric in each axis has no products
//! of inertia, so its tensor about its centre is diagonal in its own frame.

use glam::{Mat3, Vec3};

/// The tensor of a solid box of `mass` (kg) with half-extents `half` (metres, along its own x,
/// y, z), about its centre: `m/3 · diag(hy² + hz², hx² + hz², hx² + hy²)` (the familiar
/// `m/12 (b² + c²)` with full sides `b = 2 hy`, `c = 2 hz`).
pub fn solid_box(mass: f32, half: Vec3) -> Mat3 {
    let h = half * half;
    Mat3::from_diagonal(mass / 3.0 * Vec3::new(h.y + h.z, h.x + h.z, h.x + h.y))
}

/// The tensor of a solid sphere of `mass` and `radius` about its centre: `2/5 m r²` on every axis.
pub fn solid_sphere(mass: f32, radius: f32) -> Mat3 {
    Mat3::from_diagonal(Vec3::splat(0.4 * mass * radius * radius))
}

/// The tensor of a solid cylinder of `mass`, `radius` and `height` whose axis is its own y, about
/// its centre: `½ m r²` about the axis, `m/12 (3 r² + h²)` about the two others.
pub fn solid_cylinder(mass: f32, radius: f32, height: f32) -> Mat3 {
    let across = mass / 12.0 * (3.0 * radius * radius + height * height);
    Mat3::from_diagonal(Vec3::new(across, 0.5 * mass * radius * radius, across))
}

/// The parallel-axis theorem: the tensor about a point `offset` away from the centre of mass,
/// from the tensor `about_centre` about the centre: `I + m (|d|² E − d dᵀ)`. It is never smaller
/// than the tensor about the centre: the centre of mass is where a body is easiest to spin.
pub fn shifted(about_centre: Mat3, mass: f32, offset: Vec3) -> Mat3 {
    let d = offset;
    let outer = Mat3::from_cols(d * d.x, d * d.y, d * d.z);
    about_centre + mass * (Mat3::from_diagonal(Vec3::splat(d.length_squared())) - outer)
}

/// One box of a body made of boxes: its mass, half-extents, and centre in the body's frame
/// (the boxes are axis-aligned in that frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxPart {
    pub mass: f32,
    pub half: Vec3,
    pub centre: Vec3,
}

/// The mass properties of a body made of boxes: its total mass, its centre of mass (in the
/// frame the parts are given in) and its tensor about that centre, each part's tensor shifted by
/// the parallel-axis theorem. An error for no parts, or a mass, half-extent or centre that is not
/// finite, or a mass or half-extent that is not positive.
pub fn boxes(parts: &[BoxPart]) -> Result<(f32, Vec3, Mat3), String> {
    if parts.is_empty() {
        return Err("a body needs at least one box".into());
    }
    for (i, p) in parts.iter().enumerate() {
        if !(p.mass.is_finite() && p.mass > 0.0) {
            return Err(format!(
                "box {i}: mass must be a positive number, got {}",
                p.mass
            ));
        }
        if !(p.half.is_finite() && p.half.min_element() > 0.0) {
            return Err(format!(
                "box {i}: half-extents must be positive, got {}",
                p.half
            ));
        }
        if !p.centre.is_finite() {
            return Err(format!("box {i}: centre must be finite, got {}", p.centre));
        }
    }
    let mass: f32 = parts.iter().map(|p| p.mass).sum();
    let centre = parts.iter().map(|p| p.mass * p.centre).sum::<Vec3>() / mass;
    let tensor = parts.iter().fold(Mat3::ZERO, |sum, p| {
        sum + shifted(solid_box(p.mass, p.half), p.mass, p.centre - centre)
    });
    Ok((mass, centre, tensor))
}
