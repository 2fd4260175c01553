//! Exercises for lesson 06, "Skeletons and forward kinematics".
//!
//! Reference solutions: [`crate::skeleton::local_to_model`] (with scale inherited) and
//! [`crate::skeleton::sample_rotation_channel`] (with slerp). Tick "use my exercise" in the
//! lesson's figure to see your version pose the character.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use glam::{Mat4, Quat, Vec3};

/// The reference for 6.1 as 4×4 matrices (the core writes affine 3×4 matrices).
fn reference_local_to_model(
    parents: &[i32],
    translations: &[Vec3],
    rotations: &[Quat],
    scales: &[Vec3],
    model: &mut [Mat4],
) {
    use crate::skeleton::{local_to_model, ScaleMode, Transform};
    let local: Vec<Transform> = translations
        .iter()
        .zip(rotations)
        .zip(scales)
        .map(|((&translation, &rotation), &scale)| Transform {
            translation,
            rotation,
            scale,
        })
        .collect();
    let mut affine = vec![glam::Affine3A::IDENTITY; local.len()];
    local_to_model(parents, &local, ScaleMode::Inherited, &mut affine);
    for (m, a) in model.iter_mut().zip(&affine) {
        *m = Mat4::from(*a);
    }
}

/// **Exercise 6.1: the local-to-model pass.**
///
/// Joint `i` has a local transform given as a translation, a unit quaternion and a scale, and a
/// parent `parents[i]` (`-1` for a root; every parent comes before its children). Fill `model`
/// (one matrix per joint) with
/// ```text
/// local[i] = T(translations[i]) · R(rotations[i]) · S(scales[i])
/// model[i] = local[i]                     if parents[i] = −1
/// model[i] = model[parents[i]] · local[i]  otherwise
/// ```
/// (scale is inherited here: it is part of `local`). Return `Ok(())`.
///
/// Hints: `Mat4::from_scale_rotation_translation(s, r, t)` builds `T · R · S` in one call. One
/// loop in increasing `i` suffices: why can you read `model[parents[i]]` before writing
/// `model[i]`? Do not allocate.
pub fn local_to_model(
    parents: &[i32],
    translations: &[Vec3],
    rotations: &[Quat],
    scales: &[Vec3],
    model: &mut [Mat4],
) -> Answer<()> {
    solution!(reference_local_to_model(
        parents,
        translations,
        rotations,
        scales,
        model
    ));
    let _ = (parents, translations, rotations, scales, model);
    Err(NotDone)
}

/// **Exercise 6.2: sampling one rotation channel with slerp.**
///
/// A channel has key times `times` (seconds, strictly increasing) and one unit quaternion per
/// time in `keys`. Return its rotation at `time_sec`:
/// ```text
/// time_sec ≤ times[0]        →  keys[0]
/// time_sec ≥ times[N−1]      →  keys[N−1]
/// otherwise find i with times[i] ≤ time_sec < times[i+1], then
///     s = (time_sec − times[i]) / (times[i+1] − times[i]),   q = slerp(keys[i], keys[i+1]; s)
/// ```
/// Slerp along the **short arc**: if `keys[i] · keys[i+1] < 0`, use `−keys[i+1]` (the same
/// rotation). `keys` has at least one key.
///
/// Hints: you wrote slerp in exercise 3.2 (`crate::exercises::rotations::slerp`), and glam's
/// `Quat::slerp` exists too; the work here is finding the segment and `s`. A linear scan is
/// fine; `times.partition_point(|&t| t <= time_sec)` is the binary-search way.
pub fn sample_rotation_slerp(times: &[f32], keys: &[Quat], time_sec: f32) -> Answer<Quat> {
    solution!(crate::skeleton::sample_rotation_channel(
        times,
        keys,
        time_sec,
        crate::skeleton::QuatInterpolation::Slerp
    ));
    let _ = (times, keys, time_sec);
    Err(NotDone)
}

/// **Exercise 6.3: crossfading one joint between two poses.**
///
/// Joint `a` has translation `translation_a` and rotation `rotation_a` (a unit quaternion), joint
/// `b` likewise. Return their blend with weight `w ∈ [0, 1]`:
/// ```text
/// t = (1 − w) t_a + w t_b
/// q = ((1 − w) q_a + w q_b) / ‖(1 − w) q_a + w q_b‖     (nlerp; use −q_b when q_a · q_b < 0)
/// ```
/// `w = 0` must give `a` and `w = 1` must give `b`.
///
/// Hints: why does the sign test matter? `q` and `−q` are the same rotation, but their average is
/// zero. glam's `Vec3::lerp` helps; do the quaternion sum with `Vec4::from(q)`.
pub fn crossfade_joint(
    translation_a: Vec3,
    rotation_a: Quat,
    translation_b: Vec3,
    rotation_b: Quat,
    w: f32,
) -> Answer<(Vec3, Quat)> {
    solution!(reference_crossfade_joint(
        translation_a,
        rotation_a,
        translation_b,
        rotation_b,
        w
    ));
    let _ = (translation_a, rotation_a, translation_b, rotation_b, w);
    Err(NotDone)
}

/// The reference for 6.3: the core's [`crate::skeleton::crossfade_transform`] with unit scales.
pub fn reference_crossfade_joint(
    translation_a: Vec3,
    rotation_a: Quat,
    translation_b: Vec3,
    rotation_b: Quat,
    w: f32,
) -> (Vec3, Quat) {
    use crate::skeleton::{crossfade_transform, Transform};
    let a = Transform {
        translation: translation_a,
        rotation: rotation_a,
        scale: Vec3::ONE,
    };
    let b = Transform {
        translation: translation_b,
        rotation: rotation_b,
        scale: Vec3::ONE,
    };
    let x = crossfade_transform(&a, &b, w);
    (x.translation, x.rotation)
}

/// Grades this file's exercises against the reference on edge cases (each saying what it tests)
/// and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, check_list_cases, mat4_close, RANDOM};
    use glam::EulerRot;
    const LESSON: &str = "06-skeletons";

    let random_quat = |rng: &mut super::grade::Rng| {
        let e = rng.vec3(-3.0, 3.0);
        Quat::from_euler(EulerRot::XYZ, e.x, e.y, e.z)
    };

    // 6.1: (parents, translations, rotations, scales)
    type Joints = (Vec<i32>, Vec<Vec3>, Vec<Quat>, Vec<Vec3>);
    let chain = |rotations: Vec<Quat>, scales: Vec<Vec3>| -> Joints {
        let n = rotations.len();
        let parents = (0..n as i32).map(|i| i - 1).collect();
        (
            parents,
            vec![Vec3::new(0.0, 1.0, 0.0); n],
            rotations,
            scales,
        )
    };
    let mut cases: Vec<(&str, Joints)> = vec![
        (
            "a single root: model = T·R·S",
            (
                vec![-1],
                vec![Vec3::new(1.0, 2.0, 3.0)],
                vec![Quat::from_rotation_y(0.5)],
                vec![Vec3::new(1.0, 2.0, 0.5)],
            ),
        ),
        (
            "a chain with no rotation: translations add up",
            chain(vec![Quat::IDENTITY; 4], vec![Vec3::ONE; 4]),
        ),
        (
            "a turned parent carries its child's translation round (model[p] · local, not local · model[p])",
            chain(
                vec![Quat::from_rotation_z(1.0), Quat::IDENTITY, Quat::from_rotation_x(0.4)],
                vec![Vec3::ONE; 3],
            ),
        ),
        (
            "a scaled parent: the scale is inherited by the child",
            chain(vec![Quat::IDENTITY; 3], vec![Vec3::new(1.0, 2.0, 1.0), Vec3::ONE, Vec3::ONE]),
        ),
        (
            "order inside local: T·R·S (scale first, then rotate, then move)",
            chain(
                vec![Quat::from_rotation_z(0.7), Quat::from_rotation_x(-0.9)],
                vec![Vec3::new(2.0, 1.0, 0.5), Vec3::new(0.5, 1.5, 1.0)],
            ),
        ),
        (
            "two roots and siblings: a second root starts afresh",
            (
                vec![-1, 0, 0, 1, -1, 4],
                vec![Vec3::new(0.3, 1.0, 0.0); 6],
                vec![Quat::from_rotation_y(0.6); 6],
                vec![Vec3::ONE; 6],
            ),
        ),
    ];
    for _ in 0..60 {
        let n = 1 + rng.below(24);
        let parents = (0..n)
            .map(|i| {
                if i == 0 {
                    -1
                } else {
                    rng.below(i + 1) as i32 - 1
                }
            })
            .collect();
        let translations = (0..n).map(|_| rng.vec3(-1.0, 1.0)).collect();
        let rotations = (0..n).map(|_| random_quat(rng)).collect();
        let scales = (0..n).map(|_| rng.vec3(0.5, 1.5)).collect();
        cases.push((RANDOM, (parents, translations, rotations, scales)));
    }
    let l2m = check_list_cases(
        LESSON,
        "local_to_model",
        ["parents", "translations", "rotations", "scales"],
        &cases,
        |(p, t, r, s)| {
            let mut model = vec![Mat4::ZERO; p.len()];
            local_to_model(p, t, r, s, &mut model).map(|()| model)
        },
        |(p, t, r, s)| {
            let mut model = vec![Mat4::ZERO; p.len()];
            reference_local_to_model(p, t, r, s, &mut model);
            model
        },
        |a, b| mat4_close(a, b, 1e-3),
    );

    // 6.2: (times, keys, time)
    type Channel = (Vec<f32>, Vec<Quat>, f32);
    let keys3 = vec![
        Quat::IDENTITY,
        Quat::from_rotation_z(1.2),
        Quat::from_rotation_x(-2.0),
    ];
    let times3 = vec![0.0, 0.5, 2.0];
    let mut cases: Vec<(&str, Channel)> = vec![
        (
            "before the first key: the first key",
            (times3.clone(), keys3.clone(), -1.0),
        ),
        (
            "after the last key: the last key",
            (times3.clone(), keys3.clone(), 3.5),
        ),
        (
            "exactly at a key time: that key",
            (times3.clone(), keys3.clone(), 0.5),
        ),
        (
            "a quarter into the first segment",
            (times3.clone(), keys3.clone(), 0.125),
        ),
        (
            "non-uniform key times: s uses this segment's length (2.0 − 0.5)",
            (times3.clone(), keys3.clone(), 1.25),
        ),
        (
            "keys with a·b < 0: slerp along the short arc",
            (
                vec![0.0, 1.0],
                vec![Quat::IDENTITY, -Quat::from_rotation_y(0.8)],
                0.5,
            ),
        ),
        (
            "a large angle: slerp, not nlerp (constant speed)",
            (
                vec![0.0, 1.0],
                vec![Quat::IDENTITY, Quat::from_rotation_y(2.8)],
                0.2,
            ),
        ),
        (
            "a single key: always that key",
            (vec![0.3], vec![Quat::from_rotation_x(0.4)], 0.9),
        ),
    ];
    for _ in 0..200 {
        let n = 2 + rng.below(8);
        let mut t = 0.0;
        let times: Vec<f32> = (0..n)
            .map(|_| {
                t += rng.range(0.05, 1.0);
                t
            })
            .collect();
        let keys = (0..n).map(|_| random_quat(rng)).collect();
        let at = rng.range(0.0, t + 0.5);
        cases.push((RANDOM, (times, keys, at)));
    }
    let sample = check_cases(
        LESSON,
        "sample_rotation_slerp",
        ["times", "keys", "time_sec"],
        &cases,
        |(times, keys, t)| sample_rotation_slerp(times, keys, *t),
        |(times, keys, t)| {
            crate::skeleton::sample_rotation_channel(
                times,
                keys,
                *t,
                crate::skeleton::QuatInterpolation::Slerp,
            )
        },
        |a, b| (a.dot(*b).abs() - 1.0).abs() < 1e-4 && (b.length() - 1.0).abs() < 1e-3,
    );
    // 6.3: (t_a, q_a, t_b, q_b, w)
    type Blend = (Vec3, Quat, Vec3, Quat, f32);
    let (ta, tb) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 2.0, -1.0));
    let (qa, qb) = (Quat::from_rotation_y(0.4), Quat::from_rotation_x(1.5));
    let mut cases: Vec<(&str, Blend)> = vec![
        ("w = 0: exactly a", (ta, qa, tb, qb, 0.0)),
        ("w = 1: exactly b", (ta, qa, tb, qb, 1.0)),
        ("halfway", (ta, qa, tb, qb, 0.5)),
        (
            "q_a · q_b < 0: negate q_b first (the short arc)",
            (ta, qa, tb, -qb, 0.3),
        ),
        (
            "q_b = −q_a, the same rotation: the blend must not collapse to zero",
            (ta, qa, tb, -qa, 0.5),
        ),
    ];
    for _ in 0..200 {
        let w = rng.range(0.0, 1.0);
        cases.push((
            RANDOM,
            (
                rng.vec3(-2.0, 2.0),
                random_quat(rng),
                rng.vec3(-2.0, 2.0),
                random_quat(rng),
                w,
            ),
        ));
    }
    let blend = check_cases(
        LESSON,
        "crossfade_joint",
        [
            "translation_a",
            "rotation_a",
            "translation_b",
            "rotation_b",
            "w",
        ],
        &cases,
        |&(ta, qa, tb, qb, w)| crossfade_joint(ta, qa, tb, qb, w),
        |&(ta, qa, tb, qb, w)| reference_crossfade_joint(ta, qa, tb, qb, w),
        |a, b| a.0.abs_diff_eq(b.0, 1e-4) && (a.1.dot(b.1).abs() - 1.0).abs() < 1e-4,
    );
    vec![l2m, sample, blend]
}
