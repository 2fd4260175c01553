//! Exercises for lesson 11, "Particles".
//!
//! Reference solutions: [`crate::particles::floor_time_of_impact`] and
//! [`crate::particles::semi_implicit_euler_step`]. Tick "use my exercise" in the lesson's figures
//! to see yours at work.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::particles;
use glam::Vec3;

/// The reference for 11.1 (the core, with no limit on the time).
pub fn reference_time_of_impact(y0: f32, vy: f32, gy: f32, floor_y: f32) -> f32 {
    particles::floor_time_of_impact(y0, vy, gy, floor_y, f32::INFINITY).unwrap_or(f32::INFINITY)
}

/// **Exercise 11.1: the exact time of impact with the floor.**
///
/// A particle at height `y0` (metres, above the floor: `y0 > floor_y`) moves up or down with
/// vertical velocity `vy` (m/s) under gravity `gy < 0` (m/s², e.g. −9.81). Its height is
/// ```text
/// y(t) = y0 + vy t + ½ gy t²
/// ```
/// Return the time `t > 0` (seconds) at which it reaches `y = floor_y`: the positive root of
/// `½ gy t² + vy t + (y0 − floor_y) = 0`, which is
/// ```text
/// h = y0 − floor_y,   t = (−vy − √(vy² − 2 gy h)) / gy
/// ```
/// Hints: check the sign: with `gy < 0` and `h > 0` the square root is larger than `|vy|`, so the
/// numerator and `gy` are both negative. Which of the two roots is the past?
pub fn time_of_impact(y0: f32, vy: f32, gy: f32, floor_y: f32) -> Answer<f32> {
    solution!(reference_time_of_impact(y0, vy, gy, floor_y));
    let _ = (y0, vy, gy, floor_y);
    Err(NotDone)
}

/// **Exercise 11.2: one semi-implicit Euler step.**
///
/// A particle at `p` (metres) with velocity `v` (m/s) feels the acceleration `a` (m/s²). Advance
/// it by `dt` seconds, updating the velocity *first* and moving with the *new* velocity, and
/// return `(p', v')`:
/// ```text
/// v' = v + a dt
/// p' = p + v' dt
/// ```
/// Hints: two lines. Swap them (move with the old velocity) and you have explicit Euler: the
/// lesson's error plot shows the difference.
pub fn semi_implicit_euler_step(p: Vec3, v: Vec3, a: Vec3, dt: f32) -> Answer<(Vec3, Vec3)> {
    solution!({
        let (mut p, mut v) = (p, v);
        particles::semi_implicit_euler_step(&mut p, &mut v, a, dt);
        (p, v)
    });
    let _ = (p, v, a, dt);
    Err(NotDone)
}

/// The reference for 11.2 as a pure function.
pub fn reference_semi_implicit(p: Vec3, v: Vec3, a: Vec3, dt: f32) -> (Vec3, Vec3) {
    let (mut p, mut v) = (p, v);
    particles::semi_implicit_euler_step(&mut p, &mut v, a, dt);
    (p, v)
}

fn close(a: Vec3, b: Vec3, eps: f32) -> bool {
    (a - b).abs().max_element() <= eps * (1.0 + a.abs().max_element().max(b.abs().max_element()))
}

/// Grades this file's exercises against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    const L: &str = "11-particles";
    let mut drops = vec![
        ("dropped from 4.905 m: 1 s", (4.905, 0.0, -9.81, 0.0)),
        (
            "thrown up: the later root, after the way up and down",
            (1.0, 5.0, -9.81, 0.0),
        ),
        ("thrown down: sooner than dropped", (1.0, -5.0, -9.81, 0.0)),
        ("a floor that is not at 0", (3.0, 0.0, -9.81, 1.0)),
        ("weaker gravity (the Moon)", (2.0, 1.0, -1.62, 0.0)),
        (
            "just above the floor, falling fast",
            (1e-3, -20.0, -9.81, 0.0),
        ),
    ];
    for _ in 0..200 {
        let floor = rng.range(-2.0, 2.0);
        drops.push((
            RANDOM,
            (
                floor + rng.range(0.01, 5.0),
                rng.range(-6.0, 6.0),
                rng.range(-20.0, -1.0),
                floor,
            ),
        ));
    }
    let toi = check_cases(
        L,
        "time_of_impact",
        ["y0", "vy", "gy", "floor_y"],
        &drops,
        |&(y, v, g, f)| time_of_impact(y, v, g, f),
        |&(y, v, g, f)| reference_time_of_impact(y, v, g, f),
        |a, b| (a - b).abs() <= 1e-4 * (1.0 + a.abs()),
    );
    let mut steps = vec![
        (
            "dt = 0: nothing changes",
            (Vec3::ONE, Vec3::X, Vec3::new(0.0, -9.81, 0.0), 0.0),
        ),
        (
            "no acceleration: a straight line",
            (Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0), Vec3::ZERO, 0.5),
        ),
        (
            "from rest: p moves with the new velocity, by a dt²",
            (Vec3::ZERO, Vec3::ZERO, Vec3::new(0.0, -10.0, 0.0), 0.1),
        ),
        (
            "thrown sideways under gravity",
            (
                Vec3::new(0.0, 1.0, 0.0),
                Vec3::new(3.0, 0.0, 0.0),
                Vec3::new(0.0, -9.81, 0.0),
                0.02,
            ),
        ),
    ];
    for _ in 0..200 {
        steps.push((
            RANDOM,
            (
                rng.vec3(-3.0, 3.0),
                rng.vec3(-5.0, 5.0),
                rng.vec3(-10.0, 10.0),
                rng.range(0.0, 0.1),
            ),
        ));
    }
    let step = check_cases(
        L,
        "semi_implicit_euler_step",
        ["p", "v", "a", "dt"],
        &steps,
        |&(p, v, a, dt)| semi_implicit_euler_step(p, v, a, dt),
        |&(p, v, a, dt)| reference_semi_implicit(p, v, a, dt),
        |a, b| close(a.0, b.0, 1e-5) && close(a.1, b.1, 1e-5),
    );
    vec![toi, step]
}
