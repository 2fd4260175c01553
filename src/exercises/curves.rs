//! Exercises for lesson 02, "Keyframes and splines".
//!
//! Reference solutions: [`crate::curves::hermite_basis`], [`crate::curves::cardinal_tangents`],
//! [`crate::curves::find_segment`] and [`crate::curves::arc_length_invert`]. Tick "use my
//! exercise" in the lesson's first figure to see your versions move the ball: the page then finds
//! segments, computes tangents, evaluates the cubic and walks at constant speed with your code.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;

/// **Exercise 2.1: the cubic Hermite basis.**
///
/// Return the four weights `[h00, h10, h01, h11]` at `s` (the parameter inside one segment,
/// normally in `[0, 1]`):
/// ```text
/// h00(s) =  2s³ − 3s² + 1      weight of p_i     (start point)
/// h10(s) =   s³ − 2s² + s      weight of h·d_i   (start tangent)
/// h01(s) = −2s³ + 3s²          weight of p_{i+1} (end point)
/// h11(s) =   s³ −  s²          weight of h·d_{i+1} (end tangent)
/// p(t) = h00(s) p_i + h10(s) h d_i + h01(s) p_{i+1} + h11(s) h d_{i+1}
/// ```
/// as on the lesson page: `h = t_{i+1} − t_i` is the segment's duration and `s = (t − t_i)/h`;
/// the tangents `d` are in units per second, so `h·d` is the change per unit of `s`. Your
/// function returns only the four weights; the figure multiplies the tangents by `h`.
/// Hints: compute `s²` and `s³` once. Check yourself: at `s = 0` the weights are `[1, 0, 0, 0]`,
/// at `s = 1` they are `[0, 0, 1, 0]`, and `h00 + h01 = 1` for every `s`. Do not clamp `s`: values
/// outside `[0, 1]` extrapolate the cubic, and the grader tries a few.
pub fn hermite_basis(s: f32) -> Answer<[f32; 4]> {
    solution!(crate::curves::hermite_basis(s));
    let _ = s;
    Err(NotDone)
}

/// **Exercise 2.2: cardinal tangents for non-uniform key times.**
///
/// Keys `(times[i], values[i])` of one channel (say the x coordinate), times strictly
/// increasing. Write into `out[i]` the tangent (units per second) of a cardinal spline with
/// tension `mu`:
/// ```text
/// interior keys:  d_i     = μ (p_{i+1} − p_{i−1}) / (t_{i+1} − t_{i−1})
/// first key:      d_0     = μ (p_1 − p_0) / (t_1 − t_0)
/// last key:       d_{N−1} = μ (p_{N−1} − p_{N−2}) / (t_{N−1} − t_{N−2})
/// ```
/// A single key gets a zero tangent. `mu = 1` is Catmull-Rom, `mu = 0` gives all zeros.
///
/// Hints: `out`, `times` and `values` have the same length. Divide by the *time* between the
/// neighbours, not by 2: with uneven key times, "half the difference" gives a tangent in the
/// wrong units and the curve bulges. An end key is the formula with the missing neighbour
/// replaced by the key itself.
pub fn cardinal_tangents(times: &[f32], values: &[f32], mu: f32, out: &mut [f32]) -> Answer<()> {
    solution!(crate::curves::cardinal_tangents(times, values, mu, out));
    let _ = (times, values, mu, out);
    Err(NotDone)
}

/// **Exercise 2.3: find the segment that contains `t`.**
///
/// `times` is strictly increasing. Return the index `i` of the segment `[times[i], times[i+1])`
/// containing `t`:
/// ```text
/// i = (number of keys with t_k ≤ t) − 1,   clamped to [0, N − 2]
/// ```
/// So a time before the first key gives 0, a time at or after the last key gives `N − 2` (the
/// last segment), and at a key time exactly `t = t_k` the segment that *starts* at `t_k` (except
/// at the last key). With fewer than two keys, return 0.
///
/// Hints: a linear scan works but costs `O(N)`; a binary search over the sorted times costs
/// `O(log N)` (look at `slice::partition_point`, or write the loop with `lo` and `hi`).
pub fn find_segment(times: &[f32], t: f32) -> Answer<usize> {
    solution!(crate::curves::find_segment(times, t));
    let _ = (times, t);
    Err(NotDone)
}

/// **Exercise 2.4: invert an arc-length table.**
///
/// `params[k]` are times `u_k` (increasing) and `lengths[k]` the arc length `L_k` of the curve from
/// its start to `u_k` (non-decreasing, `L_0 = 0`, same length as `params`). Return the time `u` at
/// which the length reaches `s`, by linear interpolation inside the table interval:
/// ```text
/// j = first index with L_j ≥ s
/// u = u_{j−1} + (s − L_{j−1}) / (L_j − L_{j−1}) · (u_j − u_{j−1})
/// ```
/// `s ≤ 0` gives `params[0]`, `s ≥ L_last` gives the last parameter. Where the curve stops
/// (equal lengths, `L_{j−1} = L_j`), return the first parameter that reaches `s`; never divide
/// by zero.
///
/// Hints: the lengths are sorted, so `j` can be found by binary search (`partition_point`). Handle
/// the two ends first. This is the lookup that makes the lesson's ball move at constant speed.
pub fn arc_length_invert(params: &[f32], lengths: &[f32], s: f32) -> Answer<f32> {
    solution!(crate::curves::arc_length_invert(params, lengths, s));
    let _ = (params, lengths, s);
    Err(NotDone)
}

/// Grades this file's exercises against the reference on edge cases (each saying what it
/// tests) and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, check_list_cases, RANDOM};
    const LESSON: &str = "02-keyframes";
    let close = |a: f32, b: f32, eps: f32| (a - b).abs() <= eps * (1.0 + a.abs().max(b.abs()));

    // 2.1: the ends, the middle, extrapolation, then random s.
    let mut params: Vec<(&str, f32)> = vec![
        ("s = 0: all weight on p0, [1, 0, 0, 0]", 0.0),
        ("s = 1: all weight on p1, [0, 0, 1, 0]", 1.0),
        ("s = 0.5: the middle of the segment", 0.5),
        ("s = 0.25", 0.25),
        ("s = 0.75", 0.75),
        ("s = -0.5: before the segment (do not clamp s)", -0.5),
        ("s = 1.5: past the segment (do not clamp s)", 1.5),
        ("s = 2: far past the segment (do not clamp s)", 2.0),
    ];
    params.extend((0..200).map(|_| (RANDOM, rng.range(-0.2, 1.2))));
    let basis = check_cases(
        LESSON,
        "hermite_basis",
        ["s"],
        &params,
        |&s| hermite_basis(s),
        |&s| crate::curves::hermite_basis(s),
        |a, b| a.iter().zip(b).all(|(x, y)| close(*x, *y, 1e-5)),
    );

    // Random strictly increasing, non-uniform key times (steps 0.05 to 2 s).
    let random_times = |rng: &mut super::grade::Rng, n: usize| {
        let mut t = rng.range(-3.0, 3.0);
        (0..n)
            .map(|_| {
                let now = t;
                t += rng.range(0.05, 2.0);
                now
            })
            .collect::<Vec<f32>>()
    };

    // 2.2: one key, two keys, very uneven times (the halving mistake fails these), μ = 0, 1, 2.
    type Channel = (Vec<f32>, Vec<f32>, f32);
    let mut cases: Vec<(&str, Channel)> = vec![
        ("a single key: zero tangent", (vec![0.0], vec![3.0], 1.0)),
        (
            "two keys: both ends use the one segment's slope",
            (vec![0.0, 1.0], vec![0.0, 2.0], 1.0),
        ),
        (
            "three evenly spaced keys, μ = 1 (Catmull-Rom)",
            (vec![0.0, 1.0, 2.0], vec![0.0, 1.0, 0.0], 1.0),
        ),
        (
            "very uneven times: divide by t_{i+1} − t_{i−1}, not by 2",
            (vec![0.0, 0.1, 3.0, 3.2], vec![1.0, -1.0, 2.0, 0.5], 1.0),
        ),
        (
            "μ = 0: every tangent is zero",
            (vec![0.0, 0.1, 3.0, 3.2], vec![1.0, -1.0, 2.0, 0.5], 0.0),
        ),
        (
            "μ = 2, negative times: the tension scales every tangent",
            (
                vec![-2.0, 0.5, 0.7, 5.0, 6.0],
                vec![0.0, 4.0, -3.0, 1.0, 1.0],
                2.0,
            ),
        ),
    ];
    for _ in 0..100 {
        let n = 1 + rng.below(12);
        let times = random_times(rng, n);
        let values = (0..n).map(|_| rng.range(-5.0, 5.0)).collect();
        cases.push((RANDOM, (times, values, rng.range(0.0, 2.0))));
    }
    let tangents = check_list_cases(
        LESSON,
        "cardinal_tangents",
        ["times", "values", "mu"],
        &cases,
        |(times, values, mu)| {
            let mut out = vec![f32::NAN; times.len()];
            cardinal_tangents(times, values, *mu, &mut out).map(|()| out)
        },
        |(times, values, mu)| {
            let mut out = vec![0.0; times.len()];
            crate::curves::cardinal_tangents(times, values, *mu, &mut out);
            out
        },
        |x, y| close(*x, *y, 1e-4),
    );

    // 2.3: every key time exactly, just before and after keys, outside on both sides, few keys.
    let keys = vec![0.0, 0.5, 1.25, 2.0, 4.0];
    let mut lookups: Vec<(&str, (Vec<f32>, f32))> = vec![
        ("a single key: 0", (vec![1.0], 5.0)),
        ("two keys, inside: segment 0", (vec![0.0, 1.0], 0.5)),
        (
            "two keys, at the last key: the last segment",
            (vec![0.0, 1.0], 1.0),
        ),
        (
            "two keys, before the first: clamped to 0",
            (vec![0.0, 1.0], -1.0),
        ),
    ];
    let at_keys: [(&str, f32); 12] = [
        ("before the first key: clamped to 0", -1.0),
        ("exactly at the first key", 0.0),
        (
            "exactly at an inner key: the segment that starts there",
            0.5,
        ),
        ("exactly at an inner key (1.25)", 1.25),
        ("exactly at an inner key (2.0)", 2.0),
        ("exactly at the last key: the last segment, N − 2", 4.0),
        ("after the last key: clamped to N − 2", 5.0),
        ("just before a key", 0.49),
        ("just after a key", 0.51),
        ("just before an inner key (1.999)", 1.999),
        ("just before the last key", 3.999),
        ("just after the last key", 4.0001),
    ];
    for (what, t) in at_keys {
        lookups.push((what, (keys.clone(), t)));
    }
    for _ in 0..200 {
        let n = 2 + rng.below(40);
        let times = random_times(rng, n);
        let (first, last) = (times[0], times[times.len() - 1]);
        // Half the cases land exactly on a key.
        let t = if rng.below(2) == 0 {
            times[rng.below(times.len())]
        } else {
            rng.range(first - 1.0, last + 1.0)
        };
        lookups.push((RANDOM, (times, t)));
    }
    let segment = check_cases(
        LESSON,
        "find_segment",
        ["times", "t"],
        &lookups,
        |(times, t)| find_segment(times, *t),
        |(times, t)| crate::curves::find_segment(times, *t),
        |a, b| a == b,
    );

    // 2.4: the ends, table entries, a stop in the middle (equal lengths), then random tables.
    let params_a = vec![0.0, 0.5, 1.0, 1.5, 2.0];
    let lengths_a = vec![0.0, 1.0, 1.0, 1.0, 3.0];
    let mut tables: Vec<(&str, Channel)> = Vec::new();
    let lookups_a: [(&str, f32); 7] = [
        ("s < 0: the first parameter", -1.0),
        ("s = 0: the first parameter", 0.0),
        ("s inside the first interval", 0.5),
        (
            "s where the curve stops (equal lengths): the first parameter reaching s",
            1.0,
        ),
        ("s inside the interval after the stop", 2.0),
        ("s = total length: the last parameter", 3.0),
        ("s past the total length: the last parameter", 4.0),
    ];
    for (what, s) in lookups_a {
        tables.push((what, (params_a.clone(), lengths_a.clone(), s)));
    }
    tables.push(("a one-entry table", (vec![2.0], vec![0.0], 1.0)));
    tables.push((
        "a curve of zero length: never divide by zero",
        (vec![0.0, 1.0], vec![0.0, 0.0], 0.0),
    ));
    for _ in 0..200 {
        let n = 2 + rng.below(30);
        let params = random_times(rng, n);
        let mut length = 0.0;
        let lengths: Vec<f32> = (0..n)
            .map(|k| {
                // A few zero-length intervals: the curve holds still there.
                if k > 0 && rng.below(5) != 0 {
                    length += rng.range(0.01, 2.0);
                }
                length
            })
            .collect();
        let total = length;
        let s = if rng.below(4) == 0 {
            lengths[rng.below(n)]
        } else {
            rng.range(-0.1 * total, 1.1 * total)
        };
        tables.push((RANDOM, (params, lengths, s)));
    }
    let invert = check_cases(
        LESSON,
        "arc_length_invert",
        ["params", "lengths", "s"],
        &tables,
        |(params, lengths, s)| arc_length_invert(params, lengths, *s),
        |(params, lengths, s)| crate::curves::arc_length_invert(params, lengths, *s),
        |a, b| close(*a, *b, 1e-4),
    );

    vec![basis, tangents, segment, invert]
}
