//! Exercises for lesson 09, "Skinning".
//!
//! Reference solutions: [`crate::skinning::lbs_vertex`] and [`crate::skinning::blend_dual_quats`].
//! Tick "use my exercise" in the lesson's cylinder figure to see your version skin the tube.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::rigid::DualQuat;
use glam::{Mat4, Vec3};

/// **Exercise 9.1: skin one vertex by linear blend skinning.**
///
/// `matrices[k]` is the skinning matrix `K = M · B⁻¹` of the vertex's `k`-th joint (where the
/// joint is now, times the inverse of where it was in the bind pose) and `weights[k]` its weight;
/// the weights are non-negative and sum to 1. Return the skinned position
/// ```text
/// p' = Σₖ weights[k] · (matrices[k] · p)        (p a point: w = 1)
/// ```
/// Use as many pairs as the shorter slice has.
///
/// Hints: `Mat4::transform_point3(p)` applies a matrix to a point (with `w = 1`). A weight of 0
/// must contribute nothing, and one joint with weight 1 must move the point rigidly.
pub fn lbs_vertex(matrices: &[Mat4], weights: &[f32], position: Vec3) -> Answer<Vec3> {
    solution!(crate::skinning::lbs_vertex(matrices, weights, position));
    let _ = (matrices, weights, position);
    Err(NotDone)
}

/// **Exercise 9.2: blend dual quaternions with the antipodality fix.**
///
/// Each `dual_quats[k]` is a unit dual quaternion (a joint's rigid motion) with weight
/// `weights[k]` (non-negative, summing to 1). `q` and `−q` are the same motion, so before summing,
/// flip every `q_k` whose real part points away from the first one's (the pivot):
/// ```text
/// s_k = +1 if r₀ · r_k ≥ 0, else −1
/// b   = Σₖ weights[k] · s_k · q_k
/// q   = b / ‖b.real‖        then make the dual part orthogonal to the real part
/// ```
/// Return the normalised blend. An empty input, or a blend whose real part (nearly) cancels
/// (`‖b.real‖ < 1e-6`, e.g. all weights zero), gives [`DualQuat::IDENTITY`].
///
/// Hints: `q.real.dot(p.real)` is the 4D dot product; `DualQuat` supports `+` and `* f32`, and
/// [`DualQuat::normalized`] does the last step. Without the sign flip, blending a motion with its
/// own negative cancels to zero.
pub fn blend_dual_quats(dual_quats: &[DualQuat], weights: &[f32]) -> Answer<DualQuat> {
    solution!(crate::skinning::blend_dual_quats(dual_quats, weights));
    let _ = (dual_quats, weights);
    Err(NotDone)
}

/// Grades this file's exercises against the reference on edge cases (each saying what it tests)
/// and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    use glam::{EulerRot, Quat};
    const LESSON: &str = "09-skinning";

    let random_quat = |rng: &mut super::grade::Rng| {
        let e = rng.vec3(-3.0, 3.0);
        Quat::from_euler(EulerRot::XYZ, e.x, e.y, e.z)
    };
    let random_weights = |rng: &mut super::grade::Rng, n: usize| {
        let w: Vec<f32> = (0..n).map(|_| rng.range(0.0, 1.0) + 0.01).collect();
        let sum: f32 = w.iter().sum();
        w.into_iter().map(|x| x / sum).collect::<Vec<f32>>()
    };

    // 9.1: (matrices, weights, position)
    type Vertex = (Vec<Mat4>, Vec<f32>, Vec3);
    let turn =
        Mat4::from_rotation_translation(Quat::from_rotation_z(1.0), Vec3::new(1.0, 0.0, 0.0));
    let p = Vec3::new(0.5, 0.2, -0.3);
    let mut cases: Vec<(&str, Vertex)> = vec![
        ("one joint, weight 1: the point moves rigidly", (vec![turn], vec![1.0], p)),
        (
            "identity matrices: the bind pose gives the bind position",
            (vec![Mat4::IDENTITY; 4], vec![0.25; 4], p),
        ),
        (
            "a point, not a direction: the translations count (w = 1)",
            (
                vec![Mat4::from_translation(Vec3::X), Mat4::from_translation(Vec3::Y)],
                vec![0.5, 0.5],
                p,
            ),
        ),
        (
            "a zero weight contributes nothing",
            (vec![turn, Mat4::from_translation(Vec3::splat(9.0))], vec![1.0, 0.0], p),
        ),
        (
            "a half turn against the identity at ½ and ½: the candy wrapper (the point falls to the axis)",
            (
                vec![Mat4::IDENTITY, Mat4::from_rotation_x(std::f32::consts::PI)],
                vec![0.5, 0.5],
                Vec3::new(1.0, 0.25, 0.0),
            ),
        ),
    ];
    for _ in 0..60 {
        let n = 1 + rng.below(4);
        let m = (0..n)
            .map(|_| Mat4::from_rotation_translation(random_quat(rng), rng.vec3(-2.0, 2.0)))
            .collect();
        cases.push((RANDOM, (m, random_weights(rng, n), rng.vec3(-1.0, 1.0))));
    }
    let lbs = check_cases(
        LESSON,
        "lbs_vertex",
        ["matrices", "weights", "position"],
        &cases,
        |(m, w, p)| lbs_vertex(m, w, *p),
        |(m, w, p)| crate::skinning::lbs_vertex(m, w, *p),
        |a, b| (*a - *b).length() <= 1e-4 * (1.0 + a.length()),
    );

    // 9.2: (dual quaternions, weights). Compared as the motions they are (q and −q agree).
    type Blend = (Vec<DualQuat>, Vec<f32>);
    let dq = |q: Quat, t: Vec3| DualQuat::from_rotation_translation(q, t);
    let a = dq(Quat::from_rotation_y(0.4), Vec3::new(1.0, 0.0, 0.5));
    let b = dq(Quat::from_rotation_x(2.5), Vec3::new(0.0, 1.0, 0.0));
    let mut cases: Vec<(&str, Blend)> = vec![
        ("one motion, weight 1: itself", (vec![a], vec![1.0])),
        (
            "a motion and its own negative at ½ and ½: the same motion, not zero (the sign fix)",
            (vec![a, a * -1.0], vec![0.5, 0.5]),
        ),
        (
            "the second quaternion on the far hemisphere: flip it before summing",
            (vec![a, b * -1.0], vec![0.6, 0.4]),
        ),
        (
            "pure translations: the translations average",
            (
                vec![dq(Quat::IDENTITY, Vec3::X), dq(Quat::IDENTITY, Vec3::Z)],
                vec![0.5, 0.5],
            ),
        ),
        (
            "weights that do not make a unit blend: normalise (the real part must have length 1)",
            (vec![a, b], vec![0.5, 0.5]),
        ),
        ("no motions: the identity", (vec![], vec![])),
    ];
    for _ in 0..60 {
        let n = 1 + rng.below(4);
        let q = (0..n)
            .map(|_| {
                let s = if rng.below(2) == 0 { 1.0 } else { -1.0 };
                dq(random_quat(rng), rng.vec3(-2.0, 2.0)) * s
            })
            .collect();
        cases.push((RANDOM, (q, random_weights(rng, n))));
    }
    let same_motion = |x: &DualQuat, y: &DualQuat| {
        let s = if x.real.dot(y.real) < 0.0 { -1.0 } else { 1.0 };
        let d = |p: Quat, q: Quat| (glam::Vec4::from(p) - glam::Vec4::from(q) * s).length();
        d(x.real, y.real) <= 1e-4 && d(x.dual, y.dual) <= 1e-4 * (1.0 + x.dual.length())
    };
    let blend = check_cases(
        LESSON,
        "blend_dual_quats",
        ["dual_quats", "weights"],
        &cases,
        |(q, w)| blend_dual_quats(q, w),
        |(q, w)| crate::skinning::blend_dual_quats(q, w),
        same_motion,
    );
    vec![lbs, blend]
}
