//! Exercises for lessons 03, "Rotations", and 04, "Rigid motions".
//!
//! Reference solutions: [`crate::rotation::quat_from_axis_angle`], [`crate::rotation::slerp`],
//! [`crate::rotation::rodrigues_mat3`], [`crate::rigid::dual_quat_from_rotation_translation`] with
//! [`crate::rigid::dual_quat_transform_point`], and [`crate::rotation::polar_step`].
//! Tick "use my exercise" in the lesson pages to see your version drive the figures.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::rigid::DualQuat;
use glam::{Mat3, Quat, Vec3, Vec4};

/// **Exercise 3.1: a quaternion from an axis and an angle.**
///
/// Return the unit quaternion that rotates by `angle_rad` about the unit vector `axis`:
/// ```text
/// q = (n sin(θ/2), cos(θ/2))        glam order: (x, y, z, w), w is the scalar part
/// ```
/// Hints: `Quat::from_xyzw(x, y, z, w)`. Mind the *half* angle: a quaternion turns a vector by
/// twice the angle it stores, because `q v q*` applies it twice. `θ` and `θ + 2π` give `q` and
/// `−q`, which are the same rotation (the grader accepts either sign).
pub fn quat_from_axis_angle(axis: Vec3, angle_rad: f32) -> Answer<Quat> {
    solution!(crate::rotation::quat_from_axis_angle(axis, angle_rad));
    let _ = (axis, angle_rad);
    Err(NotDone)
}

/// **Exercise 3.2: slerp along the short arc.**
///
/// Interpolate between the unit quaternions `a` (`t = 0`) and `b` (`t = 1`) at constant angular
/// speed:
/// ```text
/// slerp(a, b; t) = sin((1−t)Ω)/sin Ω · a + sin(tΩ)/sin Ω · b,      cos Ω = a·b
/// ```
/// Hints: `a` and `−a` are the same rotation, so when `a·b < 0` replace `b` by `−b` first;
/// otherwise the object turns the long way round (more than half a turn). When `Ω` is tiny,
/// `sin Ω` is nearly 0 and the quotients lose all their digits: fall back to a normalised lerp
/// (`(a·(1−t) + b·t).normalize()`) below, say, `Ω < 1e-3`. `Quat` supports `+`, `*` by an
/// `f32`, `dot` and `normalize`. The grader compares rotations, so either sign is accepted.
pub fn slerp(a: Quat, b: Quat, t: f32) -> Answer<Quat> {
    solution!(crate::rotation::slerp(a, b, t));
    let _ = (a, b, t);
    Err(NotDone)
}

/// **Exercise 3.3: Rodrigues' rotation matrix.**
///
/// Return the 3×3 matrix that rotates by `angle_rad` about the unit vector `axis = n`:
/// ```text
/// R = I + sin θ · K + (1 − cos θ) · K²,      K = ⎡  0  −n_z  n_y ⎤     (K v = n × v)
///                                               ⎢ n_z   0  −n_x ⎥
///                                               ⎣−n_y  n_x   0  ⎦
/// ```
/// Hints: glam's `Mat3::from_cols` takes *columns*; the first column of `K` is `K e_x = n × e_x =
/// (0, n_z, −n_y)`. `Mat3` supports `+`, `*` (matrix product) and `*` by an `f32`. For small angles
/// `1 − cos θ` loses digits; `2 sin²(θ/2)` is the same number computed accurately.
pub fn rodrigues_matrix(axis: Vec3, angle_rad: f32) -> Answer<Mat3> {
    solution!(crate::rotation::rodrigues_mat3(axis, angle_rad));
    let _ = (axis, angle_rad);
    Err(NotDone)
}

/// **Exercise 4.1: a rigid motion as a dual quaternion, applied to a point.**
///
/// Build the unit dual quaternion of "rotate by the unit quaternion `rotation` about the origin,
/// then translate by `translation`", and apply it to `point`. Return both.
/// ```text
/// q = r + ε d,        d = ½ (t, 0) r                     (t as a pure quaternion)
/// p' = r p r* + t,    with t recovered as t = 2 d r*     (vector part)
/// ```
/// Hints: `DualQuat { real, dual }` has public fields. A pure quaternion is
/// `Quat::from_xyzw(t.x, t.y, t.z, 0.0)`; `r * v` rotates a `Vec3`; `r.conjugate()` is `r*`.
/// Recover the translation from `q` (do not just reuse `translation`): that is the point of the
/// exercise, and the lesson page feeds your function interpolated dual quaternions that way.
/// Both `q` and `−q` are accepted.
pub fn dual_quat_apply(rotation: Quat, translation: Vec3, point: Vec3) -> Answer<(DualQuat, Vec3)> {
    solution!({
        let dq = crate::rigid::dual_quat_from_rotation_translation(rotation, translation);
        (dq, crate::rigid::dual_quat_transform_point(dq, point))
    });
    let _ = (rotation, translation, point);
    Err(NotDone)
}

/// **Exercise 4.2: one step of the polar decomposition iteration.**
///
/// Given an invertible 3×3 matrix `R_k`, return the average of it and its inverse transpose:
/// ```text
/// R_{k+1} = ½ (R_k + R_k^{−T})
/// ```
/// Repeated from `R₀ = M`, this converges to the rotation `R` of `M = R D` (rotations are fixed
/// points: for them `R^{−T} = R`). Hints: `Mat3::inverse`, `Mat3::transpose`; the order of those
/// two does not matter, why? The lesson page runs your step in a loop to split its affine keys.
pub fn polar_step(r: Mat3) -> Answer<Mat3> {
    solution!(crate::rotation::polar_step(r));
    let _ = r;
    Err(NotDone)
}

/// Same rotation: `q ≈ p` or `q ≈ −p`.
fn same_rotation(a: &Quat, b: &Quat, eps: f32) -> bool {
    a.is_finite()
        && b.is_finite()
        && (1.0 - a.dot(*b).abs()) <= eps
        && (a.length() - 1.0).abs() <= 1e-3
        && (b.length() - 1.0).abs() <= 1e-3
}

fn mat3_close(a: &Mat3, b: &Mat3, eps: f32) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array().iter())
        .all(|(x, y)| (x - y).abs() <= eps * (1.0 + x.abs().max(y.abs())))
}

pub(super) fn unit_quat(rng: &mut super::grade::Rng) -> Quat {
    loop {
        let v = Vec4::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        );
        if v.length() > 0.1 {
            return Quat::from_vec4(v.normalize());
        }
    }
}

fn unit_axis(rng: &mut super::grade::Rng) -> Vec3 {
    loop {
        let v = rng.vec3(-1.0, 1.0);
        if v.length() > 0.1 {
            return v.normalize();
        }
    }
}

/// Grades lesson 03's exercises (3.1 to 3.3) against the reference on random and edge-case
/// inputs.
pub(super) fn grade_rotations(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    use std::f32::consts::{FRAC_PI_2, PI};
    const L03: &str = "03-rotations";

    // 3.1: angle 0, π, 2π (gives −q: accepted), negative angles, tiny angles, random.
    let mut axis_angles = vec![
        ("angle 0: the identity (0, 0, 0, 1)", (Vec3::X, 0.0)),
        ("half a turn: w = 0", (Vec3::Y, PI)),
        ("a quarter turn: the half angle", (Vec3::Z, FRAC_PI_2)),
        ("a negative angle", (Vec3::X, -FRAC_PI_2)),
        (
            "a full turn: gives −identity, accepted",
            (Vec3::Y, 2.0 * PI),
        ),
        (
            "a diagonal axis: every component",
            (Vec3::new(1.0, 1.0, 1.0).normalize(), 2.0 * PI / 3.0),
        ),
        ("a tiny angle", (Vec3::new(0.0, 0.6, 0.8), 1e-6)),
    ];
    for _ in 0..200 {
        axis_angles.push((RANDOM, (unit_axis(rng), rng.range(-7.0, 7.0))));
    }
    let from_axis_angle = check_cases(
        L03,
        "quat_from_axis_angle",
        ["axis", "angle_rad"],
        &axis_angles,
        |&(n, a)| quat_from_axis_angle(n, a),
        |&(n, a)| crate::rotation::quat_from_axis_angle(n, a),
        |a, b| same_rotation(a, b, 1e-5),
    );

    // 3.2: endpoints, equal keys, nearly equal keys, opposite signs of one rotation (q vs −q:
    // no turn at all), half a turn apart, keys on opposite hemispheres (short arc needs −b).
    let q0 = Quat::from_rotation_y(0.3);
    let q1 = Quat::from_rotation_y(0.3 + 1e-4);
    let far = Quat::from_rotation_x(2.5) * Quat::from_rotation_z(0.7);
    let mut slerps = vec![
        ("t = 0 gives a", (q0, far, 0.0)),
        ("t = 1 gives b", (q0, far, 1.0)),
        ("the midpoint of keys far apart", (q0, far, 0.5)),
        (
            "equal keys: sin Ω = 0, needs the nlerp fallback",
            (q0, q0, 0.3),
        ),
        ("nearly equal keys: the nlerp fallback", (q0, q1, 0.5)),
        (
            "nearly equal keys with a·b < 0: flip, then the fallback",
            (q0, -q1, 0.25),
        ),
        ("b = −a: the same rotation, no turn at all", (q0, -q0, 0.5)),
        (
            "keys half a turn apart",
            (Quat::IDENTITY, Quat::from_rotation_z(PI), 0.5),
        ),
        (
            "keys just under half a turn apart",
            (Quat::IDENTITY, Quat::from_rotation_z(PI - 1e-3), 0.5),
        ),
        (
            "keys with a·b < 0: the short arc",
            (Quat::IDENTITY, Quat::from_rotation_z(PI + 0.4), 0.5),
        ),
        (
            "b given as −b (a·b < 0): the short arc",
            (Quat::IDENTITY, -Quat::from_rotation_x(1.0), 0.75),
        ),
    ];
    for _ in 0..200 {
        let a = unit_quat(rng);
        let b = unit_quat(rng);
        slerps.push((RANDOM, (a, b, rng.range(0.0, 1.0))));
    }
    let slerp_report = check_cases(
        L03,
        "slerp",
        ["a", "b", "t"],
        &slerps,
        |&(a, b, t)| slerp(a, b, t),
        |&(a, b, t)| crate::rotation::slerp(a, b, t),
        |a, b| same_rotation(a, b, 2e-5),
    );

    // 3.3: angle 0, π, tiny, full turn, random.
    let mut rodrigues = vec![
        ("angle 0: the identity", (Vec3::X, 0.0)),
        (
            "a quarter turn about z: the sign of K (columns, not rows)",
            (Vec3::Z, FRAC_PI_2),
        ),
        ("half a turn: sin θ = 0, only the K² term", (Vec3::Y, PI)),
        (
            "half a turn about a diagonal axis",
            (Vec3::new(1.0, 1.0, 1.0).normalize(), PI),
        ),
        (
            "a tiny angle: 1 − cos θ loses digits",
            (Vec3::new(0.0, 0.6, 0.8), 1e-5),
        ),
        (
            "a full turn: the identity again",
            (Vec3::new(0.48, 0.6, 0.64), 2.0 * PI),
        ),
        ("a negative angle", (Vec3::new(0.48, -0.6, 0.64), -2.0)),
    ];
    for _ in 0..200 {
        rodrigues.push((RANDOM, (unit_axis(rng), rng.range(-7.0, 7.0))));
    }
    let rodrigues_report = check_cases(
        L03,
        "rodrigues_matrix",
        ["axis", "angle_rad"],
        &rodrigues,
        |&(n, a)| rodrigues_matrix(n, a),
        |&(n, a)| crate::rotation::rodrigues_mat3(n, a),
        |a, b| mat3_close(a, b, 1e-5),
    );

    vec![from_axis_angle, slerp_report, rodrigues_report]
}

/// Grades lesson 04's exercises (4.1 and 4.2) against the reference on random and edge-case
/// inputs.
pub(super) fn grade_rigid_motions(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, RANDOM};
    use std::f32::consts::{FRAC_PI_2, PI};
    const L04: &str = "04-rigid-motions";

    // 4.1: identity, pure translation, pure rotation by π, −r (same motion), random.
    let mut motions = vec![
        (
            "the identity motion: the point stays",
            (Quat::IDENTITY, Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0)),
        ),
        (
            "a pure translation: d = ½ t, the origin moves by t",
            (Quat::IDENTITY, Vec3::new(1.0, -2.0, 0.5), Vec3::ZERO),
        ),
        (
            "a pure rotation by π: d = 0",
            (Quat::from_rotation_y(PI), Vec3::ZERO, Vec3::X),
        ),
        (
            "rotate, then translate (not the other order)",
            // t across the axis: a translation along it commutes with the turn and would hide
            // the wrong order (and d = ½ r t in place of ½ t r).
            (
                Quat::from_rotation_z(FRAC_PI_2),
                Vec3::new(2.0, 0.0, 1.0),
                Vec3::X,
            ),
        ),
        (
            "r given as −r: the same motion",
            (
                -Quat::from_rotation_x(0.8),
                Vec3::new(0.3, 0.2, -0.1),
                Vec3::new(0.0, 1.0, 1.0),
            ),
        ),
    ];
    for _ in 0..200 {
        motions.push((
            RANDOM,
            (unit_quat(rng), rng.vec3(-5.0, 5.0), rng.vec3(-3.0, 3.0)),
        ));
    }
    let dual_quat_report = check_cases(
        L04,
        "dual_quat_apply",
        ["rotation", "translation", "point"],
        &motions,
        |&(r, t, p)| dual_quat_apply(r, t, p),
        |&(r, t, p)| {
            let dq = crate::rigid::dual_quat_from_rotation_translation(r, t);
            (dq, crate::rigid::dual_quat_transform_point(dq, p))
        },
        |(a, pa), (b, pb)| {
            // q and −q are the same motion: compare both parts with one common sign.
            let s = if a.real.dot(b.real) < 0.0 { -1.0 } else { 1.0 };
            let close = |x: Quat, y: Quat| {
                (Vec4::from(x) - Vec4::from(y * s)).abs().max_element()
                    <= 1e-4 * (1.0 + Vec4::from(x).abs().max_element())
            };
            close(a.real, b.real)
                && close(a.dual, b.dual)
                && (*pa - *pb).abs().max_element() <= 1e-4 * (1.0 + pa.abs().max_element())
        },
    );

    // 4.2: the identity and a rotation (fixed points), a scale, a shear, a rotated uneven
    // scale, then random invertible matrices (|det| > 0.05; mirroring ones included).
    let mut steps = vec![
        ("the identity: a fixed point", Mat3::IDENTITY),
        (
            "a rotation: a fixed point (R⁻ᵀ = R)",
            Mat3::from_rotation_y(1.2),
        ),
        (
            "a scale: σ → ½(σ + 1/σ)",
            Mat3::from_diagonal(Vec3::new(2.0, 0.5, 1.0)),
        ),
        (
            "a shear: the transpose matters",
            Mat3::from_cols(Vec3::X, Vec3::new(0.8, 1.0, 0.0), Vec3::Z),
        ),
        (
            "a rotated, very uneven scale",
            Mat3::from_rotation_x(0.4) * Mat3::from_diagonal(Vec3::new(1e-2, 1.0, 50.0)),
        ),
    ];
    while steps.len() < 200 {
        let m = Mat3::from_cols(
            rng.vec3(-2.0, 2.0),
            rng.vec3(-2.0, 2.0),
            rng.vec3(-2.0, 2.0),
        );
        if m.determinant().abs() > 0.05 {
            steps.push((RANDOM, m));
        }
    }
    let polar_report = check_cases(
        L04,
        "polar_step",
        ["r"],
        &steps,
        |&m| polar_step(m),
        |&m| crate::rotation::polar_step(m),
        |a, b| mat3_close(a, b, 1e-3),
    );

    vec![dual_quat_report, polar_report]
}
