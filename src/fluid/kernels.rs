//! The smoothing kernels of Müller, Charypar and Gross (2003), in two and three dimensions.
//!
//! A kernel `W(r, h)` weighs a neighbour at distance `r` and is zero from the *support radius*
//! `h` on; each kernel here integrates to 1 over its support (a disc in 2D, a ball in 3D), so a sum
//! `Σ m W` over neighbours estimates a density. With `q = h − r`:
//! ```text
//!                      3D                          2D
//! poly6  W(r)     315 / (64 π h⁹) (h² − r²)³      4 / (π h⁸) (h² − r²)³
//! spiky  W(r)     15 / (π h⁶) q³                  10 / (π h⁵) q³
//! spiky  ∇W(r)   −45 / (π h⁶) q² r̂               −30 / (π h⁵) q² r̂
//! viscosity ∇²W   45 / (π h⁶) q                   40 / (π h⁵) q
//! ```
//! poly6 is smooth and cheap (it needs r² only) but its gradient vanishes at r = 0, so two
//! particles on top of each other would not push apart: pressure uses the spiky kernel's gradient,
//! which is largest there. The viscosity kernel's Laplacian is positive everywhere inside the
//! support, so viscosity only ever damps relative motion. The 3D viscosity kernel itself is
//! `15 / (2 π h³) (−r³/2h³ + r²/h² + h/2r − 1)`; the 2D Laplacian is the standard constant of
//! 2D SPH codes (the same `(h − r)` shape, normalised over the disc).

// `!(r < h)` on purpose: a NaN distance gives a zero weight, never a NaN one.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use glam::Vec3;
use std::f32::consts::PI;

/// Whether the fluid lives in a vertical slab (`z = 0`, 2D kernels) or in space.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dim {
    Two,
    Three,
}

impl Dim {
    /// 2 or 3.
    pub fn count(self) -> i32 {
        match self {
            Dim::Two => 2,
            Dim::Three => 3,
        }
    }
}

/// The poly6 kernel at squared distance `r2` (zero from `h²` on). Exercise 15.1.
pub fn poly6(r2: f32, h: f32, dim: Dim) -> f32 {
    let h2 = h * h;
    if !(r2 < h2) {
        return 0.0;
    }
    let d = h2 - r2;
    let c = match dim {
        Dim::Three => 315.0 / (64.0 * PI * h.powi(9)),
        Dim::Two => 4.0 / (PI * h.powi(8)),
    };
    c * d * d * d
}

/// The spiky kernel at distance `r`.
pub fn spiky(r: f32, h: f32, dim: Dim) -> f32 {
    if !(r < h) {
        return 0.0;
    }
    let q = h - r;
    let c = match dim {
        Dim::Three => 15.0 / (PI * h.powi(6)),
        Dim::Two => 10.0 / (PI * h.powi(5)),
    };
    c * q * q * q
}

/// The gradient of the spiky kernel with respect to `x_i`, at `rij = x_i − x_j`: it points from
/// `j` to `i` with a negative slope, `−c (h − r)² r̂`. Odd: `∇W(−r) = −∇W(r)` exactly (the
/// sign is the only thing that changes), which is what makes the pressure force symmetric.
/// Zero at `r = 0` (no direction) and from `h` on.
pub fn spiky_gradient(rij: Vec3, h: f32, dim: Dim) -> Vec3 {
    let r = rij.length();
    if !(r < h) || r <= 1e-12 * h {
        return Vec3::ZERO;
    }
    let q = h - r;
    let c = match dim {
        Dim::Three => 45.0 / (PI * h.powi(6)),
        Dim::Two => 30.0 / (PI * h.powi(5)),
    };
    rij * (-c * q * q / r)
}

/// The Laplacian of the viscosity kernel at distance `r`: positive inside the support.
pub fn viscosity_laplacian(r: f32, h: f32, dim: Dim) -> f32 {
    if !(r < h) {
        return 0.0;
    }
    let c = match dim {
        Dim::Three => 45.0 / (PI * h.powi(6)),
        Dim::Two => 40.0 / (PI * h.powi(5)),
    };
    c * (h - r)
}

/// The 3D viscosity kernel itself (for its plot and its normalisation test); it grows without
/// bound as `r → 0`, but its integral over the ball is 1.
pub fn viscosity_3d(r: f32, h: f32) -> f32 {
    if !(r < h) || r <= 0.0 {
        return 0.0;
    }
    let q = r / h;
    15.0 / (2.0 * PI * h.powi(3)) * (-0.5 * q * q * q + q * q + 0.5 / q - 1.0)
}
