//! Cubic Hermite segments: a cubic fixed by its two end points and its two end derivatives.

use super::Value;

/// The four cubic Hermite basis functions at `s ∈ [0, 1]`, in the order `[h00, h10, h01, h11]`.
/// ```text
/// h00(s) =  2s³ − 3s² + 1      weight of p0 (start point)
/// h10(s) =   s³ − 2s² + s      weight of d0 (start tangent)
/// h01(s) = −2s³ + 3s²          weight of p1 (end point)
/// h11(s) =   s³ −  s²          weight of d1 (end tangent)
///
/// p(s) = h00 p0 + h10 d0 + h01 p1 + h11 d1
/// ```
/// They come from solving `p(0) = p0, p(1) = p1, p′(0) = d0, p′(1) = d1` for the coefficients of
/// `p(s) = c3 s³ + c2 s² + c1 s + c0`. At `s = 0` the weights are `[1, 0, 0, 0]`, at `s = 1`
/// they are `[0, 0, 1, 0]`, and `h00 + h01 = 1` for every `s`. Here the tangents are derivatives
/// with respect to `s`: for a segment `[t_i, t_{i+1}]` in seconds, multiply a time derivative
/// (units per second) by the duration `t_{i+1} − t_i` first (see [`hermite_segment`]). Values of
/// `s` outside `[0, 1]` extrapolate the cubic.
///
/// Reference solution of the "Hermite basis" exercise. Lesson: keyframes and splines.
pub fn hermite_basis(s: f32) -> [f32; 4] {
    let s2 = s * s;
    let s3 = s2 * s;
    [
        2.0 * s3 - 3.0 * s2 + 1.0,
        s3 - 2.0 * s2 + s,
        -2.0 * s3 + 3.0 * s2,
        s3 - s2,
    ]
}

/// First derivatives `d/ds` of the Hermite basis, same order as [`hermite_basis`].
/// ```text
/// h00′ = 6s² − 6s,   h10′ = 3s² − 4s + 1,   h01′ = −6s² + 6s,   h11′ = 3s² − 2s
/// ```
pub fn hermite_basis_derivative(s: f32) -> [f32; 4] {
    let s2 = s * s;
    [
        6.0 * s2 - 6.0 * s,
        3.0 * s2 - 4.0 * s + 1.0,
        -6.0 * s2 + 6.0 * s,
        3.0 * s2 - 2.0 * s,
    ]
}

/// Second derivatives `d²/ds²` of the Hermite basis, same order as [`hermite_basis`].
/// ```text
/// h00″ = 12s − 6,   h10″ = 6s − 4,   h01″ = −12s + 6,   h11″ = 6s − 2
/// ```
pub fn hermite_basis_second_derivative(s: f32) -> [f32; 4] {
    [
        12.0 * s - 6.0,
        6.0 * s - 4.0,
        -12.0 * s + 6.0,
        6.0 * s - 2.0,
    ]
}

/// Position, velocity and acceleration at time `t` on the Hermite segment `[t0, t1]` (seconds).
/// ```text
/// h = t1 − t0,   s = (t − t0) / h,   d̃0 = h d0,   d̃1 = h d1
/// p(t)  = h00(s) p0 + h10(s) d̃0 + h01(s) p1 + h11(s) d̃1
/// p′(t) = [h00′ p0 + h10′ d̃0 + h01′ p1 + h11′ d̃1] / h
/// p″(t) = [h00″ p0 + h10″ d̃0 + h01″ p1 + h11″ d̃1] / h²
/// ```
/// `d0` and `d1` are time derivatives (units per second) at `t0` and `t1`; the factor `h` turns
/// them into derivatives with respect to `s`, and the divisions by `h` turn the result back into
/// time derivatives. Requires `t1 > t0`. Returns `[p, p′, p″]`.
pub fn hermite_segment<T: Value>(t0: f32, t1: f32, p0: T, d0: T, p1: T, d1: T, t: f32) -> [T; 3] {
    let h = t1 - t0;
    debug_assert!(h > 0.0, "a Hermite segment needs t1 > t0");
    let s = (t - t0) / h;
    let (d0, d1) = (d0 * h, d1 * h);
    let combine = |w: [f32; 4]| p0 * w[0] + d0 * w[1] + p1 * w[2] + d1 * w[3];
    [
        combine(hermite_basis(s)),
        combine(hermite_basis_derivative(s)) * (1.0 / h),
        combine(hermite_basis_second_derivative(s)) * (1.0 / (h * h)),
    ]
}

/// Position only of [`hermite_segment`] (same formula, without the derivatives).
pub(crate) fn hermite_position<T: Value>(
    t0: f32,
    t1: f32,
    p0: T,
    d0: T,
    p1: T,
    d1: T,
    t: f32,
) -> T {
    // Same operations, in the same order, as `hermite_segment`: bit-identical positions.
    let h = t1 - t0;
    let [h00, h10, h01, h11] = hermite_basis((t - t0) / h);
    let (d0, d1) = (d0 * h, d1 * h);
    p0 * h00 + d0 * h10 + p1 * h01 + d1 * h11
}
