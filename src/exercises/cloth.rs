//! Exercises for lesson 13, "Cloth".
//!
//! Reference solutions: [`crate::cloth::spring_force`], [`crate::cloth::particle_step`] and
//! [`crate::cloth::project_distance`]. Tick "use my exercise" in the lesson's spring figure to see
//! yours at work.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::cloth;
use glam::Vec3;

/// **Exercise 13.1: the force of a damped spring.**
///
/// Particles `a` and `b` at `pa`, `pb` (metres) move with velocities `va`, `vb` (m/s). A spring of
/// stiffness `k` (N/m), damping `c` (N·s/m) and rest length `rest` (m) joins them. Return the
/// force (newtons) the spring puts on `a` (the force on `b` is its opposite):
/// ```text
/// d = pb − pa,   l = |d|,   n = d / l
/// f_a = (k (l − rest) + c (vb − va)·n) n
/// ```
/// A stretched spring (`l > rest`) pulls `a` towards `b`; the damping term resists the two ends
/// moving apart or together along the spring, not sideways. When `l = 0` there is no direction:
/// return zero.
///
/// Hints: `Vec3::length`, `Vec3::dot`. Check the sign with `c = 0`: `pb` to the right of `pa` and
/// a stretched spring must give a force pointing right.
pub fn spring_force(
    pa: Vec3,
    pb: Vec3,
    va: Vec3,
    vb: Vec3,
    k: f32,
    c: f32,
    rest: f32,
) -> Answer<Vec3> {
    solution!(cloth::spring_force(pa, pb, va, vb, k, c, rest));
    let _ = (pa, pb, va, vb, k, c, rest);
    Err(NotDone)
}

/// **Exercise 13.2: one semi-implicit Euler step of a cloth particle.**
///
/// A particle at `p` (m) with velocity `v` (m/s) and inverse mass `w = 1/m` (1/kg; `w = 0` for a
/// pinned particle, which forces cannot move) feels the total force `f` (N). Advance it by `dt`
/// seconds and return `(p', v')`:
/// ```text
/// v' = v + w f dt
/// p' = p + v' dt
/// ```
/// Hints: the acceleration is `w f` (Newton: `a = f / m`). Velocity first, then move with the new
/// velocity, as in exercise 11.2.
pub fn cloth_euler_step(p: Vec3, v: Vec3, f: Vec3, w: f32, dt: f32) -> Answer<(Vec3, Vec3)> {
    solution!({
        let (mut p, mut v) = (p, v);
        cloth::particle_step(&mut p, &mut v, f, w, dt);
        (p, v)
    });
    let _ = (p, v, f, w, dt);
    Err(NotDone)
}

/// **Exercise 13.3: projecting one distance constraint (XPBD).**
///
/// Particles at `pa`, `pb` with inverse masses `wa`, `wb` should stay `rest` metres apart: the
/// constraint is `C = |pb − pa| − rest`. With compliance `α` (m/N, the inverse of a stiffness;
/// 0 is rigid) over a substep `dt`, move both and return `(pa', pb')`:
/// ```text
/// n = (pb − pa) / |pb − pa|,   α̃ = α / dt²
/// Δλ = −C / (wa + wb + α̃)
/// pa' = pa − wa Δλ n,   pb' = pb + wb Δλ n
/// ```
/// Return the points unchanged when `wa + wb + α̃` is 0 (both pinned and rigid) or when the points
/// coincide. With `α = 0` and `wa = wb` each end moves half of `C`; a pinned end (`w = 0`) does not
/// move at all.
///
/// Hints: the lighter particle (larger `w`) moves more; the centre of mass stays put, so mass times
/// displacement sums to zero: `Δpa/wa + Δpb/wb = 0`, or `wb·Δpa + wa·Δpb = 0` with a pinned end.
/// Check that `|pb' − pa'| = rest` when `α = 0`.
pub fn project_distance(
    pa: Vec3,
    pb: Vec3,
    wa: f32,
    wb: f32,
    rest: f32,
    alpha: f32,
    dt: f32,
) -> Answer<(Vec3, Vec3)> {
    solution!(reference_project(pa, pb, wa, wb, rest, alpha, dt));
    let _ = (pa, pb, wa, wb, rest, alpha, dt);
    Err(NotDone)
}

/// The reference for 13.2 as a pure function.
pub fn reference_step(p: Vec3, v: Vec3, f: Vec3, w: f32, dt: f32) -> (Vec3, Vec3) {
    let (mut p, mut v) = (p, v);
    cloth::particle_step(&mut p, &mut v, f, w, dt);
    (p, v)
}

/// The reference for 13.3 as a pure function.
pub fn reference_project(
    pa: Vec3,
    pb: Vec3,
    wa: f32,
    wb: f32,
    rest: f32,
    alpha: f32,
    dt: f32,
) -> (Vec3, Vec3) {
    let (mut pa, mut pb) = (pa, pb);
    cloth::project_distance(&mut pa, &mut pb, wa, wb, rest, alpha, dt);
    (pa, pb)
}

fn close(a: Vec3, b: Vec3, eps: f32) -> bool {
    (a - b).abs().max_element() <= eps * (1.0 + a.abs().max_element().max(b.abs().max_element()))
}

/// Grades this file's exercises against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    const L: &str = "13-cloth";
    type Spring = (Vec3, Vec3, Vec3, Vec3, f32, f32, f32);
    let z = Vec3::ZERO;
    let mut springs: Vec<(&str, Spring)> = vec![
        (
            "at rest length: no force",
            (z, Vec3::X, z, z, 50.0, 0.0, 1.0),
        ),
        (
            "stretched along x: pulls a towards b (+x)",
            (z, Vec3::new(2.0, 0.0, 0.0), z, z, 10.0, 0.0, 1.0),
        ),
        (
            "compressed: pushes a away from b",
            (z, Vec3::new(0.0, 0.5, 0.0), z, z, 10.0, 0.0, 1.0),
        ),
        (
            "ends separating: damping pulls a along",
            (z, Vec3::X, z, Vec3::new(3.0, 0.0, 0.0), 0.0, 2.0, 1.0),
        ),
        (
            "sideways velocity: no damping force",
            (z, Vec3::X, z, Vec3::new(0.0, 5.0, 0.0), 0.0, 2.0, 1.0),
        ),
        (
            "coincident particles: zero, not NaN",
            (Vec3::ONE, Vec3::ONE, z, Vec3::X, 10.0, 1.0, 1.0),
        ),
    ];
    for _ in 0..200 {
        springs.push((
            RANDOM,
            (
                rng.vec3(-2.0, 2.0),
                rng.vec3(-2.0, 2.0),
                rng.vec3(-3.0, 3.0),
                rng.vec3(-3.0, 3.0),
                rng.range(0.0, 500.0),
                rng.range(0.0, 5.0),
                rng.range(0.1, 2.0),
            ),
        ));
    }
    let force = check_cases(
        L,
        "spring_force",
        ["pa", "pb", "va", "vb", "k", "c", "rest"],
        &springs,
        |&(pa, pb, va, vb, k, c, r)| spring_force(pa, pb, va, vb, k, c, r),
        |&(pa, pb, va, vb, k, c, r)| cloth::spring_force(pa, pb, va, vb, k, c, r),
        |a, b| close(*a, *b, 1e-4),
    );
    let g = Vec3::new(0.0, -9.81, 0.0);
    type Step = (Vec3, Vec3, Vec3, f32, f32);
    let mut steps: Vec<(&str, Step)> = vec![
        ("dt = 0: nothing changes", (Vec3::ONE, Vec3::X, g, 2.0, 0.0)),
        (
            "pinned (w = 0) at rest: stays put",
            (Vec3::ONE, z, Vec3::new(5.0, 5.0, 5.0), 0.0, 0.1),
        ),
        (
            "from rest: moves by w f dt², with the new velocity",
            (z, z, g, 1.0, 0.1),
        ),
        (
            "a heavier particle (w = 0.25) accelerates less",
            (z, Vec3::X, Vec3::new(4.0, 0.0, 0.0), 0.25, 0.5),
        ),
    ];
    for _ in 0..200 {
        steps.push((
            RANDOM,
            (
                rng.vec3(-3.0, 3.0),
                rng.vec3(-5.0, 5.0),
                rng.vec3(-10.0, 10.0),
                rng.range(0.0, 1000.0),
                rng.range(0.0, 0.02),
            ),
        ));
    }
    let step = check_cases(
        L,
        "cloth_euler_step",
        ["p", "v", "f", "w", "dt"],
        &steps,
        |&(p, v, f, w, dt)| cloth_euler_step(p, v, f, w, dt),
        |&(p, v, f, w, dt)| reference_step(p, v, f, w, dt),
        |a, b| close(a.0, b.0, 1e-5) && close(a.1, b.1, 1e-5),
    );
    type Project = (Vec3, Vec3, f32, f32, f32, f32, f32);
    let mut projects: Vec<(&str, Project)> = vec![
        (
            "rigid, equal masses: each end moves half of C",
            (z, Vec3::new(2.0, 0.0, 0.0), 1.0, 1.0, 1.0, 0.0, 0.01),
        ),
        (
            "rigid, a pinned: only b moves, by all of C",
            (z, Vec3::new(0.0, 3.0, 0.0), 0.0, 1.0, 1.0, 0.0, 0.01),
        ),
        (
            "compressed: pushed apart",
            (z, Vec3::new(0.0, 0.0, 0.5), 1.0, 1.0, 1.0, 0.0, 0.01),
        ),
        (
            "compliant: α̃ = α/dt² makes the correction smaller",
            (z, Vec3::new(2.0, 0.0, 0.0), 1.0, 1.0, 1.0, 1e-4, 0.01),
        ),
        (
            "both pinned and rigid: nothing moves",
            (z, Vec3::new(2.0, 0.0, 0.0), 0.0, 0.0, 1.0, 0.0, 0.01),
        ),
        (
            "coincident points: unchanged, not NaN",
            (Vec3::ONE, Vec3::ONE, 1.0, 1.0, 1.0, 0.0, 0.01),
        ),
    ];
    for _ in 0..200 {
        projects.push((
            RANDOM,
            (
                rng.vec3(-2.0, 2.0),
                rng.vec3(-2.0, 2.0),
                rng.range(0.0, 100.0),
                rng.range(0.1, 100.0),
                rng.range(0.1, 2.0),
                rng.range(0.0, 1e-3),
                rng.range(1e-3, 0.02),
            ),
        ));
    }
    let project = check_cases(
        L,
        "project_distance",
        ["pa", "pb", "wa", "wb", "rest", "alpha", "dt"],
        &projects,
        |&(pa, pb, wa, wb, r, a, dt)| project_distance(pa, pb, wa, wb, r, a, dt),
        |&(pa, pb, wa, wb, r, a, dt)| reference_project(pa, pb, wa, wb, r, a, dt),
        |a, b| close(a.0, b.0, 1e-4) && close(a.1, b.1, 1e-4),
    );
    vec![force, step, project]
}
