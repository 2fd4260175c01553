//! Exercises for lesson 10, "Blend shapes".
//!
//! Reference solution: [`crate::blend_shapes::differential_vertex`]. Tick "use my exercise" in
//! the lesson's face figure (differential form) to see your version move the face.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use glam::Vec3;

/// **Exercise 10.1: one vertex by differential blend shapes.**
///
/// `base` is the vertex in the base mesh, `targets[k]` the same vertex in target `k`, and
/// `weights[k]` that target's weight (any real numbers: they need not sum to 1). Return
/// ```text
/// p = base + Σₖ weights[k] · (targets[k] − base)
/// ```
/// using as many pairs as the shorter slice has.
///
/// Hints: all weights 0 give the base; weight 1 on one target alone gives that target. Why does
/// this form not care whether the weights sum to 1, when `Σₖ wₖ targets[k]` does?
pub fn differential_vertex(base: Vec3, targets: &[Vec3], weights: &[f32]) -> Answer<Vec3> {
    solution!(crate::blend_shapes::differential_vertex(
        base, targets, weights
    ));
    let _ = (base, targets, weights);
    Err(NotDone)
}

/// Grades this file's exercise against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    type Case = (Vec3, Vec<Vec3>, Vec<f32>);
    let b = Vec3::new(0.3, -0.2, 0.9);
    let t = vec![Vec3::new(0.5, 0.1, 0.8), Vec3::new(0.0, -0.6, 1.0)];
    let mut cases: Vec<(&str, Case)> = vec![
        ("all weights zero: the base", (b, t.clone(), vec![0.0, 0.0])),
        ("one weight 1: that target", (b, t.clone(), vec![0.0, 1.0])),
        (
            "weights summing to 0.5: still no shrinking (deltas, not whole meshes)",
            (b, t.clone(), vec![0.25, 0.25]),
        ),
        (
            "weights summing to more than 1: both deltas add",
            (b, t.clone(), vec![1.0, 1.0]),
        ),
        (
            "a negative weight: the delta reversed",
            (b, t.clone(), vec![-0.5, 0.0]),
        ),
        ("no targets: the base", (b, vec![], vec![])),
    ];
    for _ in 0..60 {
        let n = rng.below(6);
        let base = rng.vec3(-1.0, 1.0);
        let targets = (0..n).map(|_| rng.vec3(-1.0, 1.0)).collect();
        let weights = (0..n).map(|_| rng.range(-0.5, 1.5)).collect();
        cases.push((RANDOM, (base, targets, weights)));
    }
    vec![check_cases(
        "10-blend-shapes",
        "differential_vertex",
        ["base", "targets", "weights"],
        &cases,
        |(b, t, w)| differential_vertex(*b, t, w),
        |(b, t, w)| crate::blend_shapes::differential_vertex(*b, t, w),
        |a, b| (*a - *b).length() <= 1e-4 * (1.0 + a.length()),
    )]
}
