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

use glam::{Vec3, Vec4};
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

/// The kernels of one support radius `h` and dimension, their constants computed once (a step
/// evaluates them millions of times). The free functions below are the same kernels for one
/// call each.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kernels {
    pub h: f32,
    h2: f32,
    poly6: f32,
    spiky: f32,
    spiky_gradient: f32,
    viscosity_laplacian: f32,
}

impl Kernels {
    pub fn new(h: f32, dim: Dim) -> Self {
        let (poly6, spiky, spiky_gradient, viscosity_laplacian) = match dim {
            Dim::Three => (
                315.0 / (64.0 * PI * h.powi(9)),
                15.0 / (PI * h.powi(6)),
                45.0 / (PI * h.powi(6)),
                45.0 / (PI * h.powi(6)),
            ),
            Dim::Two => (
                4.0 / (PI * h.powi(8)),
                10.0 / (PI * h.powi(5)),
                30.0 / (PI * h.powi(5)),
                40.0 / (PI * h.powi(5)),
            ),
        };
        Self {
            h,
            h2: h * h,
            poly6,
            spiky,
            spiky_gradient,
            viscosity_laplacian,
        }
    }

    /// The constants of poly6, spiky's gradient and the viscosity Laplacian, in that order (the
    /// numbers in front of the table's formulas, without their sign): what a GPU step uploads,
    /// so that its kernels are these.
    pub fn constants(&self) -> [f32; 3] {
        [self.poly6, self.spiky_gradient, self.viscosity_laplacian]
    }

    /// poly6 at squared distance `r2` (zero from `h²` on).
    #[inline]
    pub fn poly6(&self, r2: f32) -> f32 {
        if !(r2 < self.h2) {
            return 0.0;
        }
        let d = self.h2 - r2;
        self.poly6 * d * d * d
    }

    /// spiky at distance `r`.
    #[inline]
    pub fn spiky(&self, r: f32) -> f32 {
        if !(r < self.h) {
            return 0.0;
        }
        let q = self.h - r;
        self.spiky * q * q * q
    }

    /// The spiky kernel's gradient with respect to `x_i` at `rij = x_i − x_j`: `−c (h − r)² r̂`.
    /// Odd: `∇W(−r) = −∇W(r)` exactly (only the sign changes), which is what makes the
    /// pressure force symmetric. Zero at `r = 0` (no direction) and from `h` on.
    #[inline]
    pub fn spiky_gradient(&self, rij: Vec3) -> Vec3 {
        let r2 = rij.length_squared();
        if !(r2 < self.h2) || r2 <= 1e-24 * self.h2 {
            return Vec3::ZERO;
        }
        let r = r2.sqrt();
        let q = self.h - r;
        rij * (-self.spiky_gradient * q * q / r)
    }

    /// [`Kernels::poly6`] of four squared distances at once, lane by lane: the same float
    /// operations in the same order, so each lane equals the scalar kernel bit for bit.
    #[inline(always)]
    pub fn poly6_x4(&self, r2: Vec4) -> Vec4 {
        let h2 = Vec4::splat(self.h2);
        let d = h2 - r2;
        let w = Vec4::splat(self.poly6) * d * d * d;
        Vec4::select(r2.cmplt(h2), w, Vec4::ZERO)
    }

    /// The factor `s` of [`Kernels::spiky_gradient`] (`∇W = rij s`) for four squared distances
    /// at once: `−c (h − r)² / r` inside `(0, h)`, zero elsewhere, each lane equal to the scalar
    /// kernel's bit for bit (the same operations in the same order; a NaN lane gives zero).
    #[inline(always)]
    pub fn spiky_gradient_factor_x4(&self, r2: Vec4) -> Vec4 {
        let inside = r2.cmplt(Vec4::splat(self.h2)) & r2.cmpgt(Vec4::splat(1e-24 * self.h2));
        let r = r2.sqrt();
        let q = Vec4::splat(self.h) - r;
        let s = Vec4::splat(-self.spiky_gradient) * q * q / r;
        Vec4::select(inside, s, Vec4::ZERO)
    }

    /// The viscosity kernel's Laplacian at distance `r`: positive inside the support.
    #[inline]
    pub fn viscosity_laplacian(&self, r: f32) -> f32 {
        if !(r < self.h) {
            return 0.0;
        }
        self.viscosity_laplacian * (self.h - r)
    }
}

/// The poly6 kernel at squared distance `r2` (zero from `h²` on). Exercise 15.1.
pub fn poly6(r2: f32, h: f32, dim: Dim) -> f32 {
    Kernels::new(h, dim).poly6(r2)
}

/// The spiky kernel at distance `r`.
pub fn spiky(r: f32, h: f32, dim: Dim) -> f32 {
    Kernels::new(h, dim).spiky(r)
}

/// The gradient of the spiky kernel with respect to `x_i`, at `rij = x_i − x_j` (see
/// [`Kernels::spiky_gradient`]).
pub fn spiky_gradient(rij: Vec3, h: f32, dim: Dim) -> Vec3 {
    Kernels::new(h, dim).spiky_gradient(rij)
}

/// The Laplacian of the viscosity kernel at distance `r`: positive inside the support.
pub fn viscosity_laplacian(r: f32, h: f32, dim: Dim) -> f32 {
    Kernels::new(h, dim).viscosity_laplacian(r)
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
