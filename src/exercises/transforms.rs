//! Exercises for lesson 01, "Transforms and hierarchies".
//!
//! Reference solutions: [`crate::transform::local_matrix`] and [`crate::transform::world_matrices`].
//! Switch the lesson page's "use my exercise" toggle to see your version drive the figure.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use glam::{Mat4, Vec3};

/// **Exercise 1.1: a joint's local matrix.**
///
/// Build the 4×4 matrix that rotates a shape about its pivot by Euler angles, then moves the pivot
/// to `translation` (in the parent's frame):
/// ```text
/// L = T(translation) · Rx(θx) · Ry(θy) · Rz(θz)
/// ```
/// with column vectors, so `Rz` acts first on a point. Angles are in radians.
///
/// Hints: glam has `Mat4::from_translation` and `Mat4::from_rotation_x` (and y, z); `*` multiplies
/// matrices. The order of the product is the whole exercise: try the wrong one in the lesson page
/// and watch the arm swing about the wrong point.
pub fn local_matrix(translation: Vec3, euler_xyz_rad: Vec3) -> Answer<Mat4> {
    solution!(crate::transform::local_matrix(translation, euler_xyz_rad));
    let _ = (translation, euler_xyz_rad);
    Err(NotDone)
}

/// **Exercise 1.2: world matrices of a hierarchy.**
///
/// `parents[i]` is the index of joint `i`'s parent, or `-1` for a root; every parent comes before
/// its children (`parents[i] < i`). Fill `world` (same length as `local`) with
/// ```text
/// world[i] = local[i]                     if parents[i] = −1
/// world[i] = world[parents[i]] · local[i]  otherwise
/// ```
/// Hints: a single loop over `i` in increasing order is enough; why? Do not allocate: write into
/// `world`, then return `Ok(())`.
pub fn world_matrices(parents: &[i32], local: &[Mat4], world: &mut [Mat4]) -> Answer<()> {
    solution!(crate::transform::world_matrices(parents, local, world));
    let _ = (parents, local, world);
    Err(NotDone)
}

/// Grades this file's exercises against the reference on edge cases (each saying what it tests)
/// and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, check_list_cases, mat4_close, RANDOM};
    use std::f32::consts::{FRAC_PI_2, PI};
    const LESSON: &str = "01-transforms";

    let mut inputs = vec![
        (
            "no translation, no rotation: the identity",
            (Vec3::ZERO, Vec3::ZERO),
        ),
        (
            "translation only: t lands in the last column",
            (Vec3::new(1.0, 2.0, 3.0), Vec3::ZERO),
        ),
        (
            "a quarter turn about x only",
            (Vec3::ZERO, Vec3::new(FRAC_PI_2, 0.0, 0.0)),
        ),
        (
            "rotation and translation: T must be applied after R (T·R, not R·T)",
            (Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 0.0, FRAC_PI_2)),
        ),
        (
            "three angles that do not commute: the order Rx·Ry·Rz",
            (Vec3::new(0.0, 0.5, 0.0), Vec3::new(0.3, -1.1, 2.0)),
        ),
        (
            "half turns about every axis",
            (Vec3::ZERO, Vec3::new(PI, PI, -PI)),
        ),
    ];
    for _ in 0..200 {
        inputs.push((RANDOM, (rng.vec3(-5.0, 5.0), rng.vec3(-6.3, 6.3))));
    }
    let local = check_cases(
        LESSON,
        "local_matrix",
        ["translation", "euler_xyz_rad"],
        &inputs,
        |&(t, a)| local_matrix(t, a),
        |&(t, a)| crate::transform::local_matrix(t, a),
        |a, b| mat4_close(a, b, 1e-4),
    );

    let mut hierarchies: Vec<(&str, Vec<i32>)> = vec![
        ("a single root: world = local", vec![-1]),
        ("a parent and a child: world = parent · local", vec![-1, 0]),
        (
            "a chain of four: products accumulate down the chain",
            vec![-1, 0, 1, 2],
        ),
        (
            "two roots and siblings: a second root starts afresh",
            vec![-1, 0, 0, 1, -1, 4],
        ),
    ];
    for _ in 0..50 {
        let n = 1 + rng.below(20);
        // A random valid hierarchy: each joint's parent is a root marker or any earlier joint.
        let parents = (0..n)
            .map(|i| {
                if i == 0 {
                    -1
                } else {
                    rng.below(i + 1) as i32 - 1
                }
            })
            .collect();
        hierarchies.push((RANDOM, parents));
    }
    type Hierarchy = (Vec<i32>, Vec<Mat4>); // parents, local matrices
    let cases: Vec<(&str, Hierarchy)> = hierarchies
        .into_iter()
        .map(|(what, parents)| {
            let local = parents
                .iter()
                .map(|_| crate::transform::local_matrix(rng.vec3(-1.0, 1.0), rng.vec3(-3.0, 3.0)))
                .collect();
            (what, (parents, local))
        })
        .collect();
    let world = check_list_cases(
        LESSON,
        "world_matrices",
        ["parents", "local"],
        &cases,
        |(parents, local)| {
            let mut world = vec![Mat4::ZERO; local.len()];
            world_matrices(parents, local, &mut world).map(|()| world)
        },
        |(parents, local)| {
            let mut world = vec![Mat4::ZERO; local.len()];
            crate::transform::world_matrices(parents, local, &mut world);
            world
        },
        |a, b| mat4_close(a, b, 1e-3),
    );
    vec![local, world]
}
