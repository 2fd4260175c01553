//! Arc-length reparametrisation: moving along a track's path at constant speed.

use super::segment::Cursor;
use super::{Track, Value};

/// Time `u` at which the cumulative arc length reaches `s`, read from a table by binary search
/// and linear interpolation.
/// ```text
/// table: (u_0, L_0 = 0), (u_1, L_1), …, (u_M, L_M = L),   u increasing, L non-decreasing
/// j = first index with L_j ≥ s                              (binary search)
/// u = u_{j−1} + (s − L_{j−1}) / (L_j − L_{j−1}) · (u_j − u_{j−1})
/// ```
/// `params` holds the curve parameter (here a time in seconds) and `lengths` the arc length from
/// the start of the curve to that parameter. Inside one table interval the length is taken as
/// linear in `u`, which is exact where the speed is constant and close to it when intervals are
/// short. `s ≤ 0` gives `params[0]`, `s ≥ L` the last parameter; where the curve stops (equal
/// lengths), the first parameter reaching `s` is returned. Cost: `O(log M)`.
///
/// Reference solution of the "arc-length inversion" exercise. Lesson: keyframes and splines.
///
/// # Panics
/// If the slices are empty or of different lengths.
pub fn arc_length_invert(params: &[f32], lengths: &[f32], s: f32) -> f32 {
    assert_eq!(
        params.len(),
        lengths.len(),
        "arc_length_invert: one length per parameter"
    );
    assert!(!params.is_empty(), "arc_length_invert: empty table");
    let j = lengths.partition_point(|&length| length < s);
    if j == 0 {
        return params[0];
    }
    if j == lengths.len() {
        return params[j - 1];
    }
    // L_{j−1} < s ≤ L_j, so the denominator is positive.
    let fraction = (s - lengths[j - 1]) / (lengths[j] - lengths[j - 1]);
    params[j - 1] + fraction * (params[j] - params[j - 1])
}

/// Nodes and weights of 5-point Gauss–Legendre quadrature on `[−1, 1]` (exact for polynomials of
/// degree ≤ 9).
const GAUSS_LEGENDRE_5: [(f32, f32); 5] = [
    (0.0, 0.568_888_9),
    (-0.538_469_3, 0.478_628_67),
    (0.538_469_3, 0.478_628_67),
    (-0.906_179_8, 0.236_926_88),
    (0.906_179_8, 0.236_926_88),
];

/// Newton steps after the table lookup in [`ArcLengthTable::time_at_length`].
const NEWTON_STEPS: usize = 3;

/// Arc length of `track` between times `a` and `b` (within one segment), by Gauss–Legendre.
/// ```text
/// ∫_a^b |p′(u)| du ≈ (b − a)/2 · Σ_k w_k |p′((a + b)/2 + (b − a)/2 · x_k)|
/// ```
fn length_between<T: Value>(track: &Track<T>, cursor: &mut Cursor, a: f32, b: f32) -> f32 {
    let (middle, half) = ((a + b) * 0.5, (b - a) * 0.5);
    let sum: f32 = GAUSS_LEGENDRE_5
        .iter()
        .map(|&(x, w)| {
            w * track
                .evaluate_keyed::<true>(cursor, middle + half * x)
                .velocity
                .length()
        })
        .sum();
    half * sum
}

/// Table of cumulative arc length against time for a [`Track`], and its inversion, to move
/// along the track's path at constant speed.
/// ```text
/// L(u) = ∫_{t_0}^{u} |p′(τ)| dτ                    arc length from the first key to time u
/// table: u_k evenly spaced inside each key segment, L_k = L(u_k)
/// constant speed: s(τ) = L τ / T  (τ ∈ [0, T]),   position p(L⁻¹(s(τ)))
/// ```
/// Each key segment `[t_i, t_{i+1}]` is cut into `subdivisions` equal intervals (so key times
/// are table entries, and speed jumps at keys never fall inside an interval), and the length of
/// each interval is integrated with 5-point Gauss–Legendre quadrature of the speed `|p′|`. The
/// table covers the keyed range `[t_0, t_{N−1}]` only; the end behaviour is ignored. A `Step`
/// track has zero length: its jumps are not motion along a path.
///
/// Inversion ([`ArcLengthTable::time_at_length`]) first reads the table
/// ([`arc_length_invert`]), then refines with a few Newton steps on `L(u) − s = 0`, whose
/// derivative is the speed `|p′(u)|`, staying inside the table interval. The table alone gives
/// a speed error of the order of the variation of `|p′|` across one interval; Newton's steps
/// remove most of it.
///
/// The table is built from one track; use it with that same track only.
#[derive(Clone, Debug, PartialEq)]
pub struct ArcLengthTable {
    times_sec: Vec<f32>,
    lengths: Vec<f32>,
}

impl ArcLengthTable {
    /// Builds the table of `track` with `subdivisions` intervals per key segment (at least 1;
    /// 8 to 32 is typical). Allocates `(N − 1) · subdivisions + 1` entries.
    pub fn new<T: Value>(track: &Track<T>, subdivisions: usize) -> Self {
        let subdivisions = subdivisions.max(1);
        let times = track.times();
        let entries = (times.len() - 1) * subdivisions + 1;
        let mut times_sec = Vec::with_capacity(entries);
        let mut lengths = Vec::with_capacity(entries);
        times_sec.push(times[0]);
        lengths.push(0.0);
        let mut cursor = Cursor::new();
        let mut total = 0.0_f32;
        for pair in times.windows(2) {
            let (t0, t1) = (pair[0], pair[1]);
            let step = (t1 - t0) / subdivisions as f32;
            let mut a = t0;
            for j in 1..=subdivisions {
                // The last node is the key time itself, not an accumulation of rounded steps.
                let b = if j == subdivisions {
                    t1
                } else {
                    t0 + step * j as f32
                };
                total += length_between(track, &mut cursor, a, b);
                times_sec.push(b);
                lengths.push(total);
                a = b;
            }
        }
        Self { times_sec, lengths }
    }

    /// Table parameters `u_k` (times in seconds, increasing).
    pub fn times_sec(&self) -> &[f32] {
        &self.times_sec
    }

    /// Cumulative lengths `L_k = L(u_k)` (non-decreasing, `L_0 = 0`).
    pub fn lengths(&self) -> &[f32] {
        &self.lengths
    }

    /// Total length `L` of the path from the first key to the last, in value units.
    pub fn total_length(&self) -> f32 {
        self.lengths[self.lengths.len() - 1]
    }

    /// Time at which `track` has travelled the arc length `s` (clamped to `[0, L]`): table
    /// lookup, then Newton refinement (see [`ArcLengthTable`]). `track` must be the track the
    /// table was built from. Never panics: a NaN `s` counts as 0, and a NaN length (keys so
    /// close that the path's length overflows) leaves `s` unclamped above.
    pub fn time_at_length<T: Value>(&self, track: &Track<T>, s: f32) -> f32 {
        // `f32::clamp` panics on a NaN bound; `max` and `min` skip a NaN operand.
        let s = s.max(0.0).min(self.total_length());
        let mut u = arc_length_invert(&self.times_sec, &self.lengths, s);
        let j = self.lengths.partition_point(|&length| length < s);
        if j == 0 || j == self.lengths.len() {
            return u;
        }
        let (u_low, u_high) = (self.times_sec[j - 1], self.times_sec[j]);
        let tolerance = 1e-6 * self.total_length();
        let mut cursor = Cursor::new();
        for _ in 0..NEWTON_STEPS {
            let error = self.lengths[j - 1] + length_between(track, &mut cursor, u_low, u) - s;
            let speed = track
                .evaluate_keyed::<true>(&mut cursor, u)
                .velocity
                .length();
            if error.abs() <= tolerance || speed <= f32::EPSILON {
                break;
            }
            u = (u - error / speed).clamp(u_low, u_high);
        }
        u
    }

    /// Position of `track` after travelling the arc length `s` along its path.
    pub fn position_at_length<T: Value>(&self, track: &Track<T>, s: f32) -> T {
        let u = self.time_at_length(track, s);
        track
            .evaluate_keyed::<false>(&mut Cursor::new(), u)
            .position
    }

    /// Fills `out` with points evenly spaced along the path, from the first key to the last
    /// (both included): the in-betweens of a motion at constant speed.
    /// ```text
    /// out[k] = p(L⁻¹(k L / (len − 1)))
    /// ```
    pub fn positions_at_constant_speed<T: Value>(&self, track: &Track<T>, out: &mut [T]) {
        let step = if out.len() > 1 {
            self.total_length() / (out.len() - 1) as f32
        } else {
            0.0
        };
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = self.position_at_length(track, step * k as f32);
        }
    }
}
