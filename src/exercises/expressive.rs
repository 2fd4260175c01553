//! Exercises for lesson 02b, "Expressive animation".
//!
//! Reference solutions: [`crate::expressive::squash_stretch_scale`] and
//! [`crate::expressive::spring_step`]. Tick "use my exercise" in the lesson's figures to see yours
//! at work.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::expressive;
use glam::Vec3;

/// **Exercise 2b.1: the volume-preserving squash and stretch scale.**
///
/// Return the scale factors `(along, across, across)` that stretch a body by `s` along its axis of
/// motion (local x) and thin it equally along the two other axes so that its volume does not
/// change: the product of the three factors must be 1.
/// ```text
/// scale = (s, 1/√s, 1/√s)          s > 1: stretch (fast motion), s < 1: squash (impact)
/// ```
/// Hints: `f32::sqrt`, `Vec3::new`. `s` is positive.
pub fn squash_stretch_scale(s: f32) -> Answer<Vec3> {
    solution!(expressive::squash_stretch_scale(s));
    let _ = s;
    Err(NotDone)
}

/// **Exercise 2b.2: one step of a damped spring follower.**
///
/// A point at `x` with velocity `v` is pulled towards `target` by a spring of stiffness `k` and
/// slowed by damping `c`. Advance it by `dt` seconds with semi-implicit Euler (update the velocity
/// first, then move with the *new* velocity) and return `(x', v')`.
/// ```text
/// a  = k (target − x) − c v
/// v' = v + a dt
/// x' = x + v' dt
/// ```
/// Hints: `Vec3` supports `+`, `-` and `*` by an `f32`. Moving with the old velocity instead
/// (explicit Euler) gains energy and the antenna in the lesson's figure would never settle.
pub fn spring_step(
    x: Vec3,
    v: Vec3,
    target: Vec3,
    k: f32,
    c: f32,
    dt: f32,
) -> Answer<(Vec3, Vec3)> {
    solution!(expressive::spring_step(x, v, target, k, c, dt));
    let _ = (x, v, target, k, c, dt);
    Err(NotDone)
}

fn close(a: Vec3, b: Vec3, eps: f32) -> bool {
    (a - b).abs().max_element() <= eps * (1.0 + a.abs().max_element().max(b.abs().max_element()))
}

/// Grades this file's exercises against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    const L: &str = "02b-expressive-animation";

    let mut scales = vec![
        ("s = 1: the body at rest, (1, 1, 1)", 1.0),
        ("s = 4: stretched, thinned to 1/2", 4.0),
        ("s = 0.25: squashed, widened to 2", 0.25),
        ("a slight stretch", 1.1),
    ];
    for _ in 0..100 {
        scales.push((RANDOM, rng.range(0.1, 5.0)));
    }
    let scale = check_cases(
        L,
        "squash_stretch_scale",
        ["s"],
        &scales,
        |&s| squash_stretch_scale(s),
        |&s| expressive::squash_stretch_scale(s),
        |a, b| close(*a, *b, 1e-5),
    );

    let t = Vec3::new(1.0, 0.5, -0.2);
    let mut springs = vec![
        (
            "at rest on the target: nothing moves",
            (t, Vec3::ZERO, t, 50.0, 5.0, 0.01),
        ),
        (
            "dt = 0: nothing changes",
            (Vec3::ZERO, Vec3::X, t, 50.0, 5.0, 0.0),
        ),
        (
            "no damping: a pure spring",
            (Vec3::ZERO, Vec3::ZERO, t, 50.0, 0.0, 0.01),
        ),
        (
            "moving, no spring: damping alone slows it",
            (
                Vec3::ZERO,
                Vec3::new(2.0, 0.0, 0.0),
                Vec3::ZERO,
                0.0,
                3.0,
                0.02,
            ),
        ),
        (
            "semi-implicit: x moves with the new velocity",
            (Vec3::ZERO, Vec3::ZERO, Vec3::X, 100.0, 0.0, 0.1),
        ),
    ];
    for _ in 0..200 {
        springs.push((
            RANDOM,
            (
                rng.vec3(-2.0, 2.0),
                rng.vec3(-3.0, 3.0),
                rng.vec3(-2.0, 2.0),
                rng.range(0.0, 400.0),
                rng.range(0.0, 40.0),
                rng.range(0.0, 0.05),
            ),
        ));
    }
    let spring = check_cases(
        L,
        "spring_step",
        ["x", "v", "target", "k", "c", "dt"],
        &springs,
        |&(x, v, t, k, c, dt)| spring_step(x, v, t, k, c, dt),
        |&(x, v, t, k, c, dt)| expressive::spring_step(x, v, t, k, c, dt),
        |a, b| close(a.0, b.0, 1e-5) && close(a.1, b.1, 1e-5),
    );
    vec![scale, spring]
}
