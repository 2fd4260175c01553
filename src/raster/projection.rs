//! The perspective projection: from view space to clip space and normalised device coordinates.
//!
//! The camera sits at the origin and looks down −z. Its **frustum** is the truncated pyramid of
//! what it sees: a vertical field of view `θ`, a width / height ratio `a`, and everything between
//! the near plane `z = −n` and the far plane `z = −f`. With `F = 1 / tan(θ/2)`:
//! ```text
//! OpenGL (gluPerspective, depth in [−1, 1])      wgpu / WebGPU / Direct3D (depth in [0, 1])
//! ⎡F/a  0      0            0      ⎤              ⎡F/a  0      0           0      ⎤
//! ⎢ 0   F      0            0      ⎥              ⎢ 0   F      0           0      ⎥
//! ⎢ 0   0  (f+n)/(n−f)  2fn/(n−f)  ⎥              ⎢ 0   0   f/(n−f)    fn/(n−f)   ⎥
//! ⎣ 0   0     −1            0      ⎦              ⎣ 0   0     −1           0      ⎦
//! ```
//! A point `p` goes to clip space `c = P p` (with `w_c = −z = its distance in front of the camera`),
//! then to normalised device coordinates `ndc = c.xyz / c.w`. Inside the frustum
//! `x, y ∈ [−1, 1]`; depth is `[−1, 1]` in OpenGL and `[0, 1]` here: `z = −n` maps to −1 (or 0) and
//! `z = −f` to +1. Depth is not linear in distance `d = −z`:
//! ```text
//! depth_wgpu(d) = f (d − n) / (d (f − n))       depth_gl(d) = 2 depth_wgpu(d) − 1
//! ```
//! so half of all depth values are spent between `n` and `2n f/(f + n) ≈ 2n`. A depth buffer of
//! `b` bits stores `2ᵇ` steps; near distance `d` one step is worth about
//! `d² (f − n) / (f n 2ᵇ)` metres: keep `f / n` small.

use super::RasterError;
use glam::{Mat4, Vec3, Vec4};

fn check(fov_y_rad: f32, aspect: f32, near: f32, far: f32) -> Result<(), RasterError> {
    let bad = |m: String| Err(RasterError::Parameter(m));
    if !(fov_y_rad.is_finite() && fov_y_rad > 0.0 && fov_y_rad < std::f32::consts::PI) {
        return bad(format!(
            "the field of view must lie strictly between 0 and π radians, got {fov_y_rad}"
        ));
    }
    if !(aspect.is_finite() && aspect > 0.0) {
        return bad(format!("the aspect ratio must be positive, got {aspect}"));
    }
    if !(near.is_finite() && near > 0.0) {
        return bad(format!("z_near must be positive, got {near}"));
    }
    if !(far.is_finite() && far > near) {
        return bad(format!(
            "z_far must be greater than z_near = {near}, got {far}"
        ));
    }
    Ok(())
}

/// The OpenGL perspective matrix (gluPerspective): view space to clip space with depth in
/// `[−1, 1]`. `fov_y_rad` is the vertical field of view; `near` and `far` are positive distances.
pub fn perspective_gl(
    fov_y_rad: f32,
    aspect: f32,
    near: f32,
    far: f32,
) -> Result<Mat4, RasterError> {
    check(fov_y_rad, aspect, near, far)?;
    let f = 1.0 / (0.5 * fov_y_rad).tan();
    let (n, fa) = (near, far);
    Ok(Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, (fa + n) / (n - fa), -1.0),
        Vec4::new(0.0, 0.0, 2.0 * fa * n / (n - fa), 0.0),
    ))
}

/// The perspective matrix this project renders with (wgpu, WebGPU, Direct3D): view space to
/// clip space with depth in `[0, 1]`; `z = −near` maps to depth 0 and `z = −far` to depth 1.
pub fn perspective_wgpu(
    fov_y_rad: f32,
    aspect: f32,
    near: f32,
    far: f32,
) -> Result<Mat4, RasterError> {
    check(fov_y_rad, aspect, near, far)?;
    let f = 1.0 / (0.5 * fov_y_rad).tan();
    let (n, fa) = (near, far);
    Ok(Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, fa / (n - fa), -1.0),
        Vec4::new(0.0, 0.0, fa * n / (n - fa), 0.0),
    ))
}

/// Depth in `[0, 1]` (wgpu) of a point at distance `d` in front of the camera.
pub fn ndc_depth_wgpu(d: f32, near: f32, far: f32) -> f32 {
    far * (d - near) / (d * (far - near))
}

/// Depth in `[−1, 1]` (OpenGL) of a point at distance `d` in front of the camera.
pub fn ndc_depth_gl(d: f32, near: f32, far: f32) -> f32 {
    2.0 * ndc_depth_wgpu(d, near, far) - 1.0
}

/// How many metres of distance one step of a `bits`-bit depth buffer spans at distance `d`
/// (wgpu depth, fixed point, first order): `d² (f − n) / (f n (2ᵇ − 1))`.
pub fn depth_step(d: f32, near: f32, far: f32, bits: u32) -> f32 {
    let steps = ((1u64 << bits.min(32)) - 1) as f32;
    d * d * (far - near) / (far * near * steps)
}

/// A view-space point after the projection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projected {
    pub clip: Vec4,
    /// `clip.xyz / clip.w`; meaningless when `clip.w ≤ 0` (behind the camera).
    pub ndc: Vec3,
    /// In front of the camera and inside the frustum (depth range `[0, 1]` or `[−1, 1]` as given).
    pub inside: bool,
}

/// Projects the view-space point `p` with `projection`; `depth_lo` is the near end of the depth
/// range (0 for wgpu, −1 for OpenGL).
pub fn project(projection: Mat4, p: Vec3, depth_lo: f32) -> Projected {
    let clip = projection * p.extend(1.0);
    let ndc = clip.truncate() / clip.w;
    let eps = 1e-5;
    let inside = clip.w > 0.0
        && ndc.x.abs() <= 1.0 + eps
        && ndc.y.abs() <= 1.0 + eps
        && ndc.z >= depth_lo - eps
        && ndc.z <= 1.0 + eps;
    Projected { clip, ndc, inside }
}
