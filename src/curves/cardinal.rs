//! Automatic tangents: cardinal splines (Catmull-Rom at tension 1) and centripetal Catmull-Rom.

use super::Value;

/// Tangents (time derivatives, units per second) of a cardinal spline with tension `mu`.
/// ```text
/// interior keys:  d_i     = μ (p_{i+1} − p_{i−1}) / (t_{i+1} − t_{i−1})
/// first key:      d_0     = μ (p_1 − p_0) / (t_1 − t_0)
/// last key:       d_{N−1} = μ (p_{N−1} − p_{N−2}) / (t_{N−1} − t_{N−2})
/// ```
/// The slope of the chord between the two neighbours, scaled by the tension `μ ∈ [0, 2]`:
/// `μ = 0` gives zero tangents (the curve stops at every key), `μ = 1` is Catmull-Rom, larger
/// values overshoot more. Dividing by the time between the neighbours (not by 2) keeps the
/// formula right for non-uniform key times. An end key has one neighbour only, so its tangent is
/// the formula with the missing neighbour replaced by the key itself: `μ` times the slope of
/// the end segment. A single key gets a zero tangent.
///
/// `times` must be strictly increasing, as in a [`Track`](super::Track). Works for `f32` keys
/// (one curve-editor channel) as well as for vectors; writes one tangent per key into `out`.
///
/// # Panics
/// If `values` or `out` do not have the length of `times`.
///
/// Reference solution of the "cardinal tangents" exercise. Lesson: keyframes and splines.
pub fn cardinal_tangents<T: Value>(times: &[f32], values: &[T], mu: f32, out: &mut [T]) {
    let n = times.len();
    assert_eq!(values.len(), n, "cardinal_tangents: one value per key time");
    assert_eq!(
        out.len(),
        n,
        "cardinal_tangents: one output tangent per key"
    );
    for (i, d_i) in out.iter_mut().enumerate() {
        // Neighbours, with the key itself standing in for a missing one at the ends.
        let before = i.saturating_sub(1);
        let after = (i + 1).min(n - 1);
        *d_i = if before == after {
            T::ZERO
        } else {
            (values[after] - values[before]) * (mu / (times[after] - times[before]))
        };
    }
}

/// The exponent of the knot spacing for centripetal Catmull-Rom: `Δτ = |Δp|^α` with `α = ½`.
pub const CENTRIPETAL_ALPHA: f32 = 0.5;

/// Smallest knot spacing, so that two equal consecutive keys do not divide by zero.
const MIN_KNOT_SPACING: f32 = 1e-6;

/// Knot spacing `Δτ = |p1 − p0|^α`, floored away from zero.
fn knot_spacing<T: Value>(p0: T, p1: T, alpha: f32) -> f32 {
    (p1 - p0).length().powf(alpha).max(MIN_KNOT_SPACING)
}

/// Catmull-Rom curve of Barry and Goldman at knot parameter `tau ∈ [τ1, τ2]`, by repeated
/// linear interpolation (a pyramid of lerps).
/// ```text
/// lerp(a, b; τa, τb) = ((τb − τ) a + (τ − τa) b) / (τb − τa)
/// A1 = lerp(P0, P1; τ0, τ1)   A2 = lerp(P1, P2; τ1, τ2)   A3 = lerp(P2, P3; τ2, τ3)
/// B1 = lerp(A1, A2; τ0, τ2)   B2 = lerp(A2, A3; τ1, τ3)
/// C  = lerp(B1, B2; τ1, τ2)
/// ```
/// The curve runs from `P1` (at `τ1`) to `P2` (at `τ2`); `P0` and `P3` only shape it. With knot
/// spacings `τ_{k+1} − τ_k = |P_{k+1} − P_k|^α`, `α = 0` is uniform Catmull-Rom, `α = ½`
/// centripetal (no cusps nor self-intersections within a segment), `α = 1` chordal. The knots
/// must be strictly increasing. [`Track`](super::Track) evaluates the same cubic in Hermite
/// form (see [`centripetal_tangents`]); this function is the definition it is tested against.
pub fn barry_goldman<T: Value>(points: [T; 4], knots: [f32; 4], tau: f32) -> T {
    let [p0, p1, p2, p3] = points;
    let [t0, t1, t2, t3] = knots;
    let lerp = |a: T, b: T, ta: f32, tb: f32| (a * (tb - tau) + b * (tau - ta)) * (1.0 / (tb - ta));
    let a1 = lerp(p0, p1, t0, t1);
    let a2 = lerp(p1, p2, t1, t2);
    let a3 = lerp(p2, p3, t2, t3);
    let b1 = lerp(a1, a2, t0, t2);
    let b2 = lerp(a2, a3, t1, t3);
    lerp(b1, b2, t1, t2)
}

/// In and out tangents (time derivatives, units per second) that make each segment of a Hermite
/// track equal to the centripetal Catmull-Rom curve ([`barry_goldman`] with `α = ½`).
/// ```text
/// Δτ_i = |p_{i+1} − p_i|^½                         knot spacing
/// m_i  = (p_i − p_{i−1}) / Δτ_{i−1} − (p_{i+1} − p_{i−1}) / (Δτ_{i−1} + Δτ_i)
///        + (p_{i+1} − p_i) / Δτ_i                   derivative d/dτ at key i
/// out_i = m_i Δτ_i / h_i,   in_{i+1} = m_{i+1} Δτ_i / h_i,   h_i = t_{i+1} − t_i
/// end keys: phantom neighbours p_{−1} = 2p_0 − p_1 and p_N = 2p_{N−1} − p_{N−2}
/// ```
/// The Barry–Goldman segment between `p_i` and `p_{i+1}` is a cubic in `τ` whose end
/// derivatives are `m_i` and `m_{i+1}`. The track runs through the segment at a uniform rate of
/// `τ` per second, so the time derivative is `m · Δτ_i / h_i`: the *path* is smooth (the
/// direction of motion is continuous at keys), but the *speed* may jump at a key where
/// `Δτ / h` changes. The phantom end points make the end tangents the slope of the end
/// segment. Equal consecutive keys are allowed (their knot spacing is floored at `1e-6`).
///
/// # Panics
/// If `values`, `tangents_in` or `tangents_out` do not have the length of `times`.
pub fn centripetal_tangents<T: Value>(
    times: &[f32],
    values: &[T],
    tangents_in: &mut [T],
    tangents_out: &mut [T],
) {
    let n = times.len();
    assert_eq!(
        values.len(),
        n,
        "centripetal_tangents: one value per key time"
    );
    assert_eq!(
        tangents_in.len(),
        n,
        "centripetal_tangents: one in tangent per key"
    );
    assert_eq!(
        tangents_out.len(),
        n,
        "centripetal_tangents: one out tangent per key"
    );
    if n < 2 {
        tangents_in.fill(T::ZERO);
        tangents_out.fill(T::ZERO);
        return;
    }
    let point = |k: isize| -> T {
        if k < 0 {
            values[0] * 2.0 - values[1]
        } else if k as usize >= n {
            values[n - 1] * 2.0 - values[n - 2]
        } else {
            values[k as usize]
        }
    };
    for i in 0..n {
        let k = i as isize;
        let (p_prev, p, p_next) = (point(k - 1), point(k), point(k + 1));
        let dtau_before = knot_spacing(p_prev, p, CENTRIPETAL_ALPHA);
        let dtau_after = knot_spacing(p, p_next, CENTRIPETAL_ALPHA);
        let m = (p - p_prev) * (1.0 / dtau_before)
            - (p_next - p_prev) * (1.0 / (dtau_before + dtau_after))
            + (p_next - p) * (1.0 / dtau_after);
        tangents_in[i] = if i > 0 {
            m * (dtau_before / (times[i] - times[i - 1]))
        } else {
            T::ZERO
        };
        tangents_out[i] = if i + 1 < n {
            m * (dtau_after / (times[i + 1] - times[i]))
        } else {
            T::ZERO
        };
    }
    // The first in tangent and the last out tangent lie outside the keyed range; give them the
    // value of their other side so that extrapolation continues the end slope.
    tangents_in[0] = tangents_out[0];
    tangents_out[n - 1] = tangents_in[n - 1];
}

/// Centripetal knots `τ_0 = 0, τ_{i+1} = τ_i + |p_{i+1} − p_i|^½` for the keys `i − 1 … i + 2`
/// around segment `i` (phantom end points as in [`centripetal_tangents`]); used by tests and
/// lessons to call [`barry_goldman`] on a track's segment. Returns `(points, knots)`.
///
/// # Panics
/// If `values.len() < 2` or `i + 1 >= values.len()`.
pub fn centripetal_segment_points<T: Value>(values: &[T], i: usize) -> ([T; 4], [f32; 4]) {
    let n = values.len();
    assert!(
        n >= 2 && i + 1 < n,
        "centripetal_segment_points: segment {i} does not exist"
    );
    let p0 = if i == 0 {
        values[0] * 2.0 - values[1]
    } else {
        values[i - 1]
    };
    let p3 = if i + 2 >= n {
        values[n - 1] * 2.0 - values[n - 2]
    } else {
        values[i + 2]
    };
    let points = [p0, values[i], values[i + 1], p3];
    let mut knots = [0.0; 4];
    for k in 1..4 {
        knots[k] = knots[k - 1] + knot_spacing(points[k - 1], points[k], CENTRIPETAL_ALPHA);
    }
    (points, knots)
}
