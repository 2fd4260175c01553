//! Exercises for lesson 07, "Inverse kinematics".
//!
//! Reference solutions: [`crate::ik::two_joint`] and [`crate::ik::ccd_iteration`]. Tick "use my
//! exercise" in the lesson's first figure to see your versions move the chains.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use glam::Vec3;

/// The reference for 7.1: the core's new middle and end positions.
pub fn reference_two_joint(
    root: Vec3,
    middle: Vec3,
    end: Vec3,
    target: Vec3,
    pole: Vec3,
) -> (Vec3, Vec3) {
    match crate::ik::two_joint(root, middle, end, target, pole, 1e-4) {
        Ok(s) => (s.middle, s.end),
        // Bad input (coinciding joints, NaN): the chain stays as it is.
        Err(_) => (middle, end),
    }
}

/// **Exercise 7.1: two-joint IK by the law of cosines.**
///
/// A chain `root → middle → end` (a hip, a knee, an ankle) has segment lengths
/// `a = |middle − root|` and `b = |end − middle|`. Move the middle and the end so that the end
/// reaches `target`, keeping both lengths, with the middle joint bending towards `pole`. Return
/// `Ok((new_middle, new_end))`.
/// ```text
/// d = clamp(|target − root|, |a − b| + 1e-6, a + b − 1e-6)   (what the chain can reach)
/// cos α = (a² + d² − b²) / (2 a d)                          (law of cosines: angle at the root)
/// u = (target − root) / |target − root|                      (towards the target)
/// v = unit(w − u (w · u)),  w = pole − root                  (towards the pole, ⊥ u)
/// new_middle = root + a (cos α u + sin α v)
/// new_end    = root + d u
/// ```
/// Inputs in the graded cases: `target ≠ root`, and the pole is not on the root→target line.
///
/// Hints: draw the triangle root, middle, target with sides `a`, `b`, `d`; `α` is the angle at
/// the root. Clamp `cos α` to [−1, 1] before taking `sin α = √(1 − cos² α)`. A target out of
/// reach (`d` clamped) straightens the chain towards it.
pub fn two_joint(
    root: Vec3,
    middle: Vec3,
    end: Vec3,
    target: Vec3,
    pole: Vec3,
) -> Answer<(Vec3, Vec3)> {
    solution!(reference_two_joint(root, middle, end, target, pole));
    let _ = (root, middle, end, target, pole);
    Err(NotDone)
}

/// **Exercise 7.2: one iteration of CCD (Cyclic Coordinate Descent).**
///
/// `chain[0]` is the root, `chain[n − 1]` the end effector. Visit the joints from `n − 2` down to
/// `0`; at joint `i`, turn every joint after it about `chain[i]` by the shortest rotation that
/// takes the direction `end − chain[i]` onto the direction `target − chain[i]`:
/// ```text
/// for i = n−2, n−3, …, 0:
///     R = rotation_arc(chain[n−1] − chain[i], target − chain[i])
///     chain[j] ← chain[i] + R (chain[j] − chain[i])      for every j > i
/// ```
/// Read the end's position afresh at each joint (the previous joint moved it). Skip a joint
/// when either direction is zero. Return `Ok(())`.
///
/// Hints: `Quat::from_rotation_arc(from, to)` wants unit vectors and returns the identity for
/// angles below about 7·10⁻⁴ rad (fine for one iteration; the core's `ik::rotation_arc` keeps them,
/// which matters after many). The root never moves.
pub fn ccd_iteration(chain: &mut [Vec3], target: Vec3) -> Answer<()> {
    solution!(crate::ik::ccd_iteration(chain, target));
    let _ = (chain, target);
    Err(NotDone)
}

/// Grades this file's exercises against the reference on edge cases (each saying what it tests)
/// and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, check_list_cases, RANDOM};
    const LESSON: &str = "07-inverse-kinematics";
    let close = |a: &Vec3, b: &Vec3| a.abs_diff_eq(*b, 1e-3);

    // 7.1: (root, middle, end, target, pole)
    type TwoJoint = (Vec3, Vec3, Vec3, Vec3, Vec3);
    let (r, m, e) = (
        Vec3::ZERO,
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(0.0, 2.0, 0.0),
    );
    let mut cases: Vec<(&str, TwoJoint)> = vec![
        (
            "a target in reach, in the plane of the chain",
            (r, m, e, Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.0, 1.0, 1.0)),
        ),
        (
            "the pole on the other side: the middle joint bends the other way",
            (r, m, e, Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.0, 1.0, -1.0)),
        ),
        (
            "a target out of reach: the chain straightens towards it",
            (r, m, e, Vec3::new(3.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 1.0)),
        ),
        (
            "segments of different lengths (a = 1, b = 0.5) and a target too close: d clamps to |a − b|",
            (
                r,
                m,
                Vec3::new(0.0, 1.5, 0.0),
                Vec3::new(0.1, 0.1, 0.0),
                Vec3::new(0.0, 0.0, 1.0),
            ),
        ),
        (
            "a root away from the origin: everything is relative to the root",
            (
                Vec3::new(2.0, 1.0, -1.0),
                Vec3::new(2.0, 2.0, -1.0),
                Vec3::new(2.0, 3.0, -1.0),
                Vec3::new(3.0, 2.0, -0.5),
                Vec3::new(2.0, 2.0, 1.0),
            ),
        ),
    ];
    for _ in 0..200 {
        let root = rng.vec3(-1.0, 1.0);
        let middle = root + rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y) * rng.range(0.3, 1.0);
        let end = middle + rng.vec3(-1.0, 1.0).normalize_or(Vec3::X) * rng.range(0.3, 1.0);
        let target = root + rng.vec3(-2.0, 2.0);
        let pole = root + rng.vec3(-2.0, 2.0);
        // Skip degenerate inputs the task rules out (pole on the root→target line).
        let u = (target - root).normalize_or(Vec3::Y);
        let w = pole - root;
        if (w - u * w.dot(u)).length() < 0.05 || target.distance(root) < 0.05 {
            continue;
        }
        cases.push((RANDOM, (root, middle, end, target, pole)));
    }
    let two = check_cases(
        LESSON,
        "two_joint",
        ["root", "middle", "end", "target", "pole"],
        &cases,
        |&(r, m, e, t, p)| two_joint(r, m, e, t, p),
        |&(r, m, e, t, p)| reference_two_joint(r, m, e, t, p),
        // The middle joint is ill-conditioned at full reach (sin α ≈ 0): a student who clamps to
        // exactly a + b lands a millimetre or two from the reference there.
        |a, b| a.0.abs_diff_eq(b.0, 5e-3) && close(&a.1, &b.1),
    );

    // 7.2: (chain, target)
    type Sweep = (Vec<Vec3>, Vec3);
    let straight = vec![Vec3::ZERO, Vec3::Y, 2.0 * Vec3::Y, 3.0 * Vec3::Y];
    let mut cases: Vec<(&str, Sweep)> = vec![
        (
            "two joints (one segment): the segment turns to point at the target",
            (vec![Vec3::ZERO, Vec3::X], Vec3::new(0.0, 3.0, 0.0)),
        ),
        (
            "a straight chain, target to the side: joints visited from the end back to the root",
            (straight.clone(), Vec3::new(2.0, 1.0, 0.0)),
        ),
        (
            "a target behind the chain: half-turns are allowed",
            (straight.clone(), Vec3::new(0.0, -2.0, 0.0)),
        ),
        (
            "a target out of reach: the chain points at it",
            (straight.clone(), Vec3::new(5.0, 5.0, 1.0)),
        ),
        (
            "the target already reached: nothing moves",
            (straight.clone(), 3.0 * Vec3::Y),
        ),
    ];
    for _ in 0..150 {
        let n = 2 + rng.below(6);
        let mut chain = vec![rng.vec3(-1.0, 1.0)];
        for _ in 1..n {
            let last = *chain.last().unwrap();
            chain.push(last + rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y) * rng.range(0.3, 1.0));
        }
        cases.push((RANDOM, (chain, rng.vec3(-2.5, 2.5))));
    }
    let sweep = check_list_cases(
        LESSON,
        "ccd_iteration",
        ["chain", "target"],
        &cases,
        |(chain, target)| {
            let mut c = chain.clone();
            ccd_iteration(&mut c, *target).map(|()| c)
        },
        |(chain, target)| {
            let mut c = chain.clone();
            crate::ik::ccd_iteration(&mut c, *target);
            c
        },
        |x, y| x.abs_diff_eq(*y, 2e-3),
    );
    vec![two, sweep]
}
