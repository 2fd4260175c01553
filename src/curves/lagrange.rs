//! Lagrange interpolation: one polynomial of degree N − 1 through all N keys.

use super::Value;

/// Position, velocity and acceleration of the Lagrange polynomial through all keys at time `t`.
/// ```text
/// p(t) = Σ_i α_i(t) p_i,     α_i(t) = Π_{k≠i} (t − t_k) / (t_i − t_k)
/// ```
/// By construction `α_i(t_i) = 1` and `α_i(t_k) = 0` for `k ≠ i`, so the polynomial passes
/// through every key, and a polynomial of degree at most `N − 1` is reproduced exactly. Every key
/// moves the whole curve, and with many keys the curve oscillates wildly near the ends (Runge's
/// phenomenon): adding two keys to ten can change it everywhere. This is why animation tools use
/// piecewise cubics instead. Shown for comparison only.
///
/// The basis and its derivatives are built in `f64`, one factor `(t − t_k)` at a time with the
/// product rule (`O(N²)` per call, no allocation), then applied to the `f32` values. Keys must
/// have distinct times. Returns `[p, p′, p″]`; a single key gives a constant.
pub fn lagrange<T: Value>(times: &[f32], values: &[T], t: f32) -> [T; 3] {
    debug_assert_eq!(times.len(), values.len());
    let t = f64::from(t);
    let mut result = [T::ZERO; 3];
    for (i, (&t_i, &p_i)) in times.iter().zip(values).enumerate() {
        // (f, f′, f″) of α_i, multiplied in one factor at a time.
        let (mut f, mut df, mut ddf) = (1.0_f64, 0.0_f64, 0.0_f64);
        for (k, &t_k) in times.iter().enumerate() {
            if k == i {
                continue;
            }
            let denominator = f64::from(t_i) - f64::from(t_k);
            let g = (t - f64::from(t_k)) / denominator; // this factor; its derivative is 1/denominator
            let dg = 1.0 / denominator;
            ddf = ddf * g + 2.0 * df * dg;
            df = df * g + f * dg;
            f *= g;
        }
        result[0] = result[0] + p_i * f as f32;
        result[1] = result[1] + p_i * df as f32;
        result[2] = result[2] + p_i * ddf as f32;
    }
    result
}
