//! Exercises for lesson 08, "Blending".
//!
//! Reference solution: [`crate::skeleton::weight_for_speed`]. Tick "use my exercise" in the
//! lesson's walk-to-run figure to see your weight drive the blend.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;

/// The reference for 8.1 on plain numbers (the core reads them from two clips' root motion).
fn reference_weight_for_speed(d_a: f32, travel_a: f32, d_b: f32, travel_b: f32, v: f32) -> f32 {
    use crate::skeleton::{weight_for_speed, RootMotion};
    let motion = |d: f32, travel: f32| RootMotion {
        start: glam::Vec3::ZERO,
        cycle_travel: glam::Vec3::new(0.0, 0.0, travel),
        duration_sec: d,
    };
    weight_for_speed(&motion(d_a, travel_a), &motion(d_b, travel_b), v)
}

/// **Exercise 8.1: the run's weight for a speed.**
///
/// Clip A (the walk) lasts `d_a` seconds per cycle and travels `travel_a` metres in it; clip B
/// (the run) lasts `d_b` seconds and travels `travel_b` metres. Blended at the same phase with
/// the run's weight `w`, one cycle lasts `d` and travels `T`, so the blend moves at `T / d`:
/// ```text
/// d(w) = (1 − w) d_a + w d_b,     T(w) = (1 − w) travel_a + w travel_b,     v(w) = T(w) / d(w)
/// ```
/// Return the weight that makes the blend move at `v` metres per second, by solving
/// `v(w) = v` for `w`, clamped to `[0, 1]` (a speed below the walk's gives 0, above the run's
/// gives 1). When the equation has no single solution (the denominator within 1e-9 of 0, as
/// for two clips with the same cycle and travel) or `v` is not finite, return 0.
///
/// Hints: multiply `v(w) = v` out by `d(w)`; it is linear in `w`. Check your formula at the walk's
/// own speed `travel_a / d_a` (it must give 0) and at the run's (it must give 1).
pub fn weight_for_speed(d_a: f32, travel_a: f32, d_b: f32, travel_b: f32, v: f32) -> Answer<f32> {
    solution!(reference_weight_for_speed(d_a, travel_a, d_b, travel_b, v));
    let _ = (d_a, travel_a, d_b, travel_b, v);
    Err(NotDone)
}

/// Grades this file's exercise against the reference on edge cases (each saying what it tests)
/// and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    const LESSON: &str = "08-blending";

    // (d_a, travel_a, d_b, travel_b, v): a walk of 1 s and 1.4 m, a run of 0.7 s and 2.1 m.
    type Speed = (f32, f32, f32, f32, f32);
    let (da, ta, db, tb) = (1.0, 1.4, 0.7, 2.1);
    let mut cases: Vec<(&str, Speed)> = vec![
        ("the walk's own speed: weight 0", (da, ta, db, tb, ta / da)),
        ("the run's own speed: weight 1", (da, ta, db, tb, tb / db)),
        (
            "halfway between the speeds: not halfway in weight (the cycle shortens too)",
            (da, ta, db, tb, 0.5 * (ta / da + tb / db)),
        ),
        ("slower than the walk: clamped to 0", (da, ta, db, tb, 0.5)),
        ("faster than the run: clamped to 1", (da, ta, db, tb, 5.0)),
        (
            "clips of equal duration: the weight is linear in the speed",
            (1.0, 1.0, 1.0, 3.0, 2.5),
        ),
        (
            "the walk given as clip B and the run as clip A: the weight of the walk",
            (db, tb, da, ta, 2.0),
        ),
        (
            "two identical clips: no single answer, 0",
            (1.0, 1.4, 1.0, 1.4, 1.4),
        ),
        (
            "a speed that is not a number: 0",
            (da, ta, db, tb, f32::NAN),
        ),
    ];
    for _ in 0..60 {
        let d_a = rng.range(0.5, 1.5);
        let d_b = rng.range(0.4, 1.2);
        let travel_a = rng.range(0.5, 2.0);
        let travel_b = travel_a + rng.range(0.3, 2.0);
        let (lo, hi) = (travel_a / d_a, travel_b / d_b);
        let v = rng.range(lo.min(hi) - 0.2, lo.max(hi) + 0.2);
        cases.push((RANDOM, (d_a, travel_a, d_b, travel_b, v)));
    }
    let report = check_cases(
        LESSON,
        "weight_for_speed",
        ["d_a", "travel_a", "d_b", "travel_b", "v"],
        &cases,
        |&(a, b, c, d, v)| weight_for_speed(a, b, c, d, v),
        |&(a, b, c, d, v)| reference_weight_for_speed(a, b, c, d, v),
        |x: &f32, y: &f32| (x - y).abs() <= 1e-4,
    );
    vec![report]
}
