//! Exercises for lesson 14, "Rigid bodies".
//!
//! Reference solutions: [`crate::rigid_body::inertia::solid_box`],
//! [`crate::rigid_body::orientation_step`] (the normalised additive step),
//! [`crate::rigid_body::world_inverse_inertia`] and [`crate::rigid_body::normal_impulse`].
//! Tick "use my exercise" in the lesson's figures to see yours at work.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::rigid_body::{self, OrientationStep};
use glam::{Mat3, Quat, Vec3, Vec4};

/// **Exercise 14.1: the principal moments of inertia of a solid box.**
///
/// A box of `mass` kilograms, uniform density, has half-extents `half` (metres) along its own x,
/// y and z axes: it runs from `−half.x` to `half.x` along x, and so on. Return its moments of
/// inertia about its own three axes through its centre (kg m²), as a `Vec3`:
/// ```text
/// I_x = m/3 (hy² + hz²),   I_y = m/3 (hx² + hz²),   I_z = m/3 (hx² + hy²)
/// ```
/// (The textbook writes `m/12 (b² + c²)` with the full side lengths `b = 2 hy`, `c = 2 hz`.)
///
/// Hints: spinning about x moves the material in y and z only, so `hx` is not in `I_x`. A cube
/// has three equal moments; the longest box's smallest moment is about its long axis.
pub fn box_inertia(mass: f32, half: Vec3) -> Answer<Vec3> {
    solution!(diagonal(rigid_body::inertia::solid_box(mass, half)));
    let _ = (mass, half);
    Err(NotDone)
}

/// **Exercise 14.2: one step of the orientation quaternion.**
///
/// A body turned by the unit quaternion `q` spins with the angular velocity `omega` (rad/s, in
/// the world's frame). The quaternion changes as `q̇ = ½ ω q`, where `ω` is written as the pure
/// quaternion `(ωx, ωy, ωz, 0)` (glam's order: `w` last). Take one step of `dt` seconds and
/// return the new orientation, normalised:
/// ```text
/// w = Quat(ωx, ωy, ωz, 0)
/// q' = normalize(q + ½ dt (w q))
/// ```
/// The product is `w * q` in that order: ω is a world-frame velocity, so it acts on the left.
///
/// Hints: `Quat::from_xyzw`, quaternion `*` and `+`, and `Quat * f32`. Without the normalisation
/// `|q'|` grows by `√(1 + (|ω| dt / 2)²)` every step (the lesson's drift figure shows what that does
/// to the body).
pub fn orientation_step(q: Quat, omega: Vec3, dt: f32) -> Answer<Quat> {
    solution!(rigid_body::orientation_step(
        q,
        omega,
        dt,
        OrientationStep::Additive
    ));
    let _ = (q, omega, dt);
    Err(NotDone)
}

/// **Exercise 14.3: the inverse inertia tensor in the world's frame.**
///
/// A body with principal moments `inertia` (kg m², about its own axes) is turned by the unit
/// quaternion `orientation`. Its inverse inertia tensor is diagonal in its own frame,
/// `diag(1/Ix, 1/Iy, 1/Iz)`; in the world's frame it is
/// ```text
/// R = the rotation matrix of the orientation
/// I⁻¹_world = R · diag(1/Ix, 1/Iy, 1/Iz) · Rᵀ
/// ```
/// Return that matrix. It turns a world torque impulse into a change of world angular velocity:
/// the contact solver needs it at every step, because the body turns.
///
/// Hints: `Mat3::from_quat`, `Mat3::from_diagonal`, `Vec3::recip`, `Mat3::transpose`. Check: the
/// result is symmetric, and with `orientation` the identity it is the diagonal itself.
pub fn world_inverse_inertia(orientation: Quat, inertia: Vec3) -> Answer<Mat3> {
    solution!(rigid_body::world_inverse_inertia(orientation, inertia));
    let _ = (orientation, inertia);
    Err(NotDone)
}

/// **Exercise 14.4: the impulse that makes a contact bounce.**
///
/// A point of a body touches an immovable surface whose outward normal is the unit vector
/// `normal`. The point lies `r` from the body's centre of mass (world frame) and moves with the
/// velocity `v_rel` (m/s; the body's `v + ω × r`). The body's inverse mass is `inv_mass` (1/kg)
/// and its world inverse inertia tensor `inv_inertia` (exercise 14.3). With the coefficient of
/// restitution `e` (0: the point stops along the normal, 1: it bounces back as fast), the
/// impulse along the normal has the magnitude
/// ```text
/// j = −(1 + e) (v_rel · n) / (1/m + n · ((I⁻¹ (r × n)) × r))
/// ```
/// Return `j` (N s). When the point already separates (`v_rel · n ≥ 0`) no impulse is needed:
/// return 0.
///
/// Hints: the denominator is how fast the point moves along `n` per unit of impulse: the whole
/// body's share `1/m` plus the turning share. Check: after the impulse `j n` at the point, its
/// normal speed is `−e` times what it was.
pub fn normal_impulse(
    v_rel: Vec3,
    normal: Vec3,
    r: Vec3,
    inv_mass: f32,
    inv_inertia: Mat3,
    e: f32,
) -> Answer<f32> {
    solution!(rigid_body::normal_impulse(
        v_rel,
        normal,
        r,
        inv_mass,
        inv_inertia,
        e
    ));
    let _ = (v_rel, normal, r, inv_mass, inv_inertia, e);
    Err(NotDone)
}

/// The diagonal of a matrix.
fn diagonal(m: Mat3) -> Vec3 {
    Vec3::new(m.x_axis.x, m.y_axis.y, m.z_axis.z)
}

fn close(a: Vec3, b: Vec3, eps: f32) -> bool {
    (a - b).abs().max_element() <= eps * (1.0 + a.abs().max_element().max(b.abs().max_element()))
}

fn mat3_close(a: &Mat3, b: &Mat3, eps: f32) -> bool {
    let scale = a.abs().to_cols_array().into_iter().fold(0.0, f32::max);
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array().iter())
        .all(|(x, y)| (x - y).abs() <= eps * (1.0 + scale))
}

/// Principal moments a real body can have (each at most the sum of the other two): a box's.
fn moments(rng: &mut super::grade::Rng) -> Vec3 {
    diagonal(rigid_body::inertia::solid_box(
        rng.range(0.2, 5.0),
        rng.vec3(0.05, 1.0),
    ))
}

/// Grades this file's exercises against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    use super::rotations::unit_quat;
    const L: &str = "14-rigid-bodies";

    let mut boxes = vec![
        (
            "a unit cube of 6 kg: 1 kg m² about every axis",
            (6.0, Vec3::splat(0.5)),
        ),
        (
            "a long thin box: the smallest moment is about its long axis (x)",
            (2.0, Vec3::new(1.0, 0.1, 0.05)),
        ),
        (
            "half-extents, not full sides: 1 kg, half 1 × 2 × 3",
            (1.0, Vec3::new(1.0, 2.0, 3.0)),
        ),
        (
            "twice the mass: twice the moments",
            (12.0, Vec3::splat(0.5)),
        ),
    ];
    for _ in 0..200 {
        boxes.push((RANDOM, (rng.range(0.01, 50.0), rng.vec3(0.01, 3.0))));
    }
    let inertia = check_cases(
        L,
        "box_inertia",
        ["mass", "half"],
        &boxes,
        |&(m, h)| box_inertia(m, h),
        |&(m, h)| diagonal(rigid_body::inertia::solid_box(m, h)),
        |a, b| close(*a, *b, 1e-5),
    );

    let mut steps = vec![
        (
            "no spin: q stays",
            (Quat::from_rotation_x(0.7), Vec3::ZERO, 0.1),
        ),
        (
            "dt = 0: q stays",
            (Quat::from_rotation_y(-1.2), Vec3::new(1.0, 2.0, 3.0), 0.0),
        ),
        (
            "from the identity, spinning about z: a small turn about z",
            (Quat::IDENTITY, Vec3::new(0.0, 0.0, 2.0), 0.05),
        ),
        (
            "ω on the left (w q, not q w): spin about x of a body turned about y",
            (
                Quat::from_rotation_y(std::f32::consts::FRAC_PI_2),
                Vec3::new(3.0, 0.0, 0.0),
                0.1,
            ),
        ),
        (
            "a large step: the normalisation matters",
            (Quat::from_rotation_z(0.3), Vec3::new(0.0, 20.0, 0.0), 0.1),
        ),
    ];
    for _ in 0..200 {
        steps.push((
            RANDOM,
            (unit_quat(rng), rng.vec3(-10.0, 10.0), rng.range(0.0, 0.05)),
        ));
    }
    let step = check_cases(
        L,
        "orientation_step",
        ["q", "omega", "dt"],
        &steps,
        |&(q, w, dt)| orientation_step(q, w, dt),
        |&(q, w, dt)| rigid_body::orientation_step(q, w, dt, OrientationStep::Additive),
        // The same quaternion, not just the same rotation: the step has one answer.
        |a, b| (Vec4::from(*a) - Vec4::from(*b)).abs().max_element() <= 1e-5,
    );

    let mut turned = vec![
        (
            "the identity: the diagonal of reciprocals",
            (Quat::IDENTITY, Vec3::new(1.0, 2.0, 4.0)),
        ),
        (
            "a quarter turn about z swaps the x and y moments",
            (
                Quat::from_rotation_z(std::f32::consts::FRAC_PI_2),
                Vec3::new(1.0, 2.0, 2.5),
            ),
        ),
        (
            "equal moments (a sphere): every orientation gives the same tensor",
            (Quat::from_rotation_x(1.0), Vec3::splat(0.4)),
        ),
        (
            "R I⁻¹ Rᵀ, not Rᵀ I⁻¹ R: a turn about an oblique axis",
            (
                Quat::from_axis_angle(Vec3::new(1.0, 2.0, 0.5).normalize(), 0.9),
                Vec3::new(0.5, 1.0, 1.2),
            ),
        ),
    ];
    for _ in 0..200 {
        turned.push((RANDOM, (unit_quat(rng), moments(rng))));
    }
    let world = check_cases(
        L,
        "world_inverse_inertia",
        ["orientation", "inertia"],
        &turned,
        |&(q, i)| world_inverse_inertia(q, i),
        |&(q, i)| rigid_body::world_inverse_inertia(q, i),
        |a, b| mat3_close(a, b, 1e-4),
    );

    let tensor = |q: Quat, i: Vec3| rigid_body::world_inverse_inertia(q, i);
    let cube = Vec3::splat(1.0 / 6.0);
    let mut hits = vec![
        (
            "a point at the centre's level below it, falling at 1 m/s, e = 0: j = m",
            (
                Vec3::new(0.0, -1.0, 0.0),
                Vec3::Y,
                Vec3::new(0.0, -0.5, 0.0),
                1.0,
                tensor(Quat::IDENTITY, cube),
                0.0,
            ),
        ),
        (
            "the same with e = 1: twice the impulse",
            (
                Vec3::new(0.0, -1.0, 0.0),
                Vec3::Y,
                Vec3::new(0.0, -0.5, 0.0),
                1.0,
                tensor(Quat::IDENTITY, cube),
                1.0,
            ),
        ),
        (
            "a corner off to the side: the body turns, so less impulse is needed",
            (
                Vec3::new(0.0, -2.0, 0.0),
                Vec3::Y,
                Vec3::new(0.5, -0.5, 0.5),
                1.0,
                tensor(Quat::IDENTITY, cube),
                0.5,
            ),
        ),
        (
            "separating already: no impulse",
            (
                Vec3::new(0.3, 1.0, 0.0),
                Vec3::Y,
                Vec3::new(0.2, -0.5, 0.0),
                2.0,
                tensor(Quat::IDENTITY, cube),
                0.5,
            ),
        ),
        (
            "a wall (normal along x), a turned body",
            (
                Vec3::new(-3.0, 0.5, 0.2),
                Vec3::X,
                Vec3::new(-0.4, 0.3, 0.1),
                0.5,
                tensor(Quat::from_rotation_y(0.6), Vec3::new(0.3, 0.5, 0.6)),
                0.8,
            ),
        ),
    ];
    for _ in 0..200 {
        let normal = rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y);
        hits.push((
            RANDOM,
            (
                rng.vec3(-5.0, 5.0),
                normal,
                rng.vec3(-1.0, 1.0),
                1.0 / rng.range(0.2, 10.0),
                tensor(unit_quat(rng), moments(rng)),
                rng.range(0.0, 1.0),
            ),
        ));
    }
    let impulse = check_cases(
        L,
        "normal_impulse",
        ["v_rel", "normal", "r", "inv_mass", "inv_inertia", "e"],
        &hits,
        |&(v, n, r, m, i, e)| normal_impulse(v, n, r, m, i, e),
        |&(v, n, r, m, i, e)| rigid_body::normal_impulse(v, n, r, m, i, e),
        |a, b| (a - b).abs() <= 1e-4 * (1.0 + a.abs().max(b.abs())),
    );
    vec![inertia, step, world, impulse]
}
