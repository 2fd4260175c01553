//! The rigid-body core: inertia tensors against their closed forms and the parallel-axis theorem,
//! conservation in free flight, the orientation steps, the gyroscopic term, impulses.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Mat3, Quat, Vec3};
use inbetween::rigid_body::inertia::{
    boxes, shifted, solid_box, solid_cylinder, solid_sphere, BoxPart,
};
use inbetween::rigid_body::{
    normal_impulse, orientation_step, AngularStep, OrientationStep, RigidBody,
};

fn close(a: Mat3, b: Mat3, tol: f32) -> bool {
    (a - b).to_cols_array().iter().all(|x| x.abs() <= tol)
}

/// The tensor of a solid box by summing small cubes (midpoint rule), for an independent check.
fn box_by_cubes(mass: f32, half: Vec3, n: usize) -> Mat3 {
    let dm = mass / (n * n * n) as f32;
    let mut sum = Mat3::ZERO;
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                let f = |a: usize, h: f32| -h + (a as f32 + 0.5) * 2.0 * h / n as f32;
                let r = Vec3::new(f(i, half.x), f(j, half.y), f(k, half.z));
                let outer = Mat3::from_cols(r * r.x, r * r.y, r * r.z);
                sum += dm * (Mat3::from_diagonal(Vec3::splat(r.length_squared())) - outer);
            }
        }
    }
    sum
}

#[test]
fn inertia_tensors_match_their_closed_forms() {
    // A 2 kg box of sides 1 × 2 × 3 m: m/12 (b² + c²) and so on.
    let b = solid_box(2.0, Vec3::new(0.5, 1.0, 1.5));
    let expected = Vec3::new(
        2.0 / 12.0 * (4.0 + 9.0),
        2.0 / 12.0 * (1.0 + 9.0),
        2.0 / 12.0 * (1.0 + 4.0),
    );
    assert!(close(b, Mat3::from_diagonal(expected), 1e-5), "{b}");
    // The same box summed from 40³ little cubes.
    assert!(close(
        b,
        box_by_cubes(2.0, Vec3::new(0.5, 1.0, 1.5), 40),
        2e-3
    ));
    assert!(close(
        solid_sphere(5.0, 0.2),
        Mat3::from_diagonal(Vec3::splat(0.4 * 5.0 * 0.04)),
        1e-6
    ));
    let c = solid_cylinder(3.0, 0.5, 2.0);
    let across = 3.0 / 12.0 * (3.0 * 0.25 + 4.0);
    assert!(close(
        c,
        Mat3::from_diagonal(Vec3::new(across, 0.5 * 3.0 * 0.25, across)),
        1e-6
    ));
}

#[test]
fn the_parallel_axis_theorem_adds_m_d_squared_off_the_axis() {
    // A ball about a point on its surface: 2/5 m r² + m r² = 7/5 m r² about the two axes across
    // the offset, and nothing added about the axis along it.
    let (m, r) = (2.0, 0.3);
    let s = shifted(solid_sphere(m, r), m, Vec3::new(r, 0.0, 0.0));
    assert!(
        close(
            s,
            Mat3::from_diagonal(Vec3::new(0.4 * m * r * r, 1.4 * m * r * r, 1.4 * m * r * r)),
            1e-6
        ),
        "{s}"
    );
    // An offset along a diagonal brings products of inertia: −m dx dy.
    let d = Vec3::new(1.0, 2.0, 0.0);
    let s = shifted(Mat3::ZERO, 1.5, d);
    assert!((s.col(1).x - (-1.5 * 2.0)).abs() < 1e-6 && (s.col(2).z - 1.5 * 5.0).abs() < 1e-6);
    // Never smaller than about the centre: every moment grows or stays.
    let base = solid_box(1.0, Vec3::new(0.2, 0.3, 0.4));
    for k in 0..20 {
        let d = Vec3::new(
            (k as f32).sin(),
            (k as f32 * 1.3).cos(),
            k as f32 * 0.1 - 1.0,
        );
        let s = shifted(base, 1.0, d);
        for axis in 0..3 {
            assert!(s.col(axis)[axis] >= base.col(axis)[axis] - 1e-6);
        }
    }
}

#[test]
fn two_boxes_side_by_side_are_one_box_twice_as_long() {
    let half = Vec3::new(0.5, 0.25, 0.1);
    let parts = [
        BoxPart {
            mass: 1.0,
            half,
            centre: Vec3::new(3.0 - 0.5, 1.0, 0.0),
        },
        BoxPart {
            mass: 1.0,
            half,
            centre: Vec3::new(3.0 + 0.5, 1.0, 0.0),
        },
    ];
    let (mass, centre, tensor) = boxes(&parts).unwrap();
    assert_eq!(mass, 2.0);
    assert!((centre - Vec3::new(3.0, 1.0, 0.0)).length() < 1e-6);
    assert!(
        close(tensor, solid_box(2.0, Vec3::new(1.0, 0.25, 0.1)), 1e-5),
        "{tensor}"
    );
    assert!(boxes(&[]).is_err());
    let bad = BoxPart {
        mass: f32::NAN,
        ..parts[0]
    };
    assert!(boxes(&[bad]).unwrap_err().contains("box 0: mass"));
    let flat = BoxPart {
        half: Vec3::new(1.0, 0.0, 1.0),
        ..parts[0]
    };
    assert!(boxes(&[parts[0], flat]).unwrap_err().contains("box 1"));
}

#[test]
fn a_body_needs_a_positive_mass_and_moments_a_body_can_have() {
    assert!(RigidBody::new(1.0, Vec3::new(1.0, 2.0, 2.5)).is_ok());
    assert!(RigidBody::new(0.0, Vec3::ONE).unwrap_err().contains("mass"));
    assert!(RigidBody::new(1.0, Vec3::new(1.0, f32::INFINITY, 1.0)).is_err());
    assert!(RigidBody::new(1.0, Vec3::new(1.0, 1.0, 3.0))
        .unwrap_err()
        .contains("sum of the other two"));
}

/// A 1 kg box of sides 0.6 × 0.3 × 0.1 m along x, y, z (a racket-like body): three distinct
/// moments, smallest about its long axis x, in between about y, largest about its short axis z.
fn racket() -> RigidBody {
    let i = solid_box(1.0, Vec3::new(0.3, 0.15, 0.05));
    RigidBody::new(1.0, Vec3::new(i.x_axis.x, i.y_axis.y, i.z_axis.z)).unwrap()
}

#[test]
fn free_flight_conserves_linear_and_angular_momentum() {
    let mut body = racket();
    body.velocity = Vec3::new(1.0, 2.0, -0.5);
    body.omega_body = Vec3::new(3.0, 0.2, 5.0);
    let p0 = body.linear_momentum();
    let l0 = body.angular_momentum();
    let mut worst = 0.0f32;
    let mut implicit = body;
    let mut implicit_worst = 0.0f32;
    for _ in 0..600 {
        body.step(
            1.0 / 60.0,
            Vec3::ZERO,
            AngularStep::Momentum,
            OrientationStep::Exponential,
        );
        worst = worst.max((body.angular_momentum() - l0).length() / l0.length());
        implicit.step(
            1.0 / 60.0,
            Vec3::ZERO,
            AngularStep::Implicit,
            OrientationStep::Exponential,
        );
        implicit_worst =
            implicit_worst.max((implicit.angular_momentum() - l0).length() / l0.length());
    }
    assert!((body.linear_momentum() - p0).length() < 1e-5);
    assert!((body.position - 10.0 * Vec3::new(1.0, 2.0, -0.5)).length() < 1e-3);
    // Holding L conserves it up to float rounding (a few 1e-5 after 600 steps); the implicit
    // gyroscopic step, which stores ω, lets it drift by several per cent (its damping).
    assert!(
        worst < 1e-4,
        "angular momentum drifted by {worst:e} of itself"
    );
    assert!(
        implicit_worst > 100.0 * worst && implicit_worst > 0.01,
        "{implicit_worst}"
    );
    // Under gravity, momentum changes by exactly m g t.
    let mut falling = racket();
    for _ in 0..60 {
        falling.step(
            1.0 / 60.0,
            Vec3::new(0.0, -9.81, 0.0),
            AngularStep::Implicit,
            OrientationStep::Exponential,
        );
    }
    assert!((falling.velocity.y + 9.81).abs() < 1e-4);
}

#[test]
fn the_exponential_step_keeps_the_quaternion_unit_and_the_unnormalised_one_drifts() {
    let omega = Vec3::new(2.0, -1.0, 4.0);
    let dt = 1.0 / 60.0;
    let (mut exact, mut additive, mut raw) = (Quat::IDENTITY, Quat::IDENTITY, Quat::IDENTITY);
    for _ in 0..6000 {
        exact = orientation_step(exact, omega, dt, OrientationStep::Exponential);
        additive = orientation_step(additive, omega, dt, OrientationStep::Additive);
        raw = orientation_step(raw, omega, dt, OrientationStep::AdditiveUnnormalised);
    }
    assert!(
        (exact.length() - 1.0).abs() < 1e-4,
        "|q| = {}",
        exact.length()
    );
    assert!((additive.length() - 1.0).abs() < 1e-6);
    // Each unnormalised step multiplies |q| by sqrt(1 + (|ω| dt / 2)²): after 100 s, by e^1.6.
    let growth = (1.0 + (omega.length() * dt / 2.0).powi(2)).powf(3000.0);
    assert!(
        (raw.length() / growth - 1.0).abs() < 1e-2,
        "{} against {growth}",
        raw.length()
    );
    assert!(raw.length() > 4.0);
    // The exact step turns by |ω| t about ω: after 6000 steps, 100 s at 4.58 rad/s.
    let expected = Quat::from_axis_angle(omega.normalize(), omega.length() * 100.0);
    assert!(exact.dot(expected).abs() > 1.0 - 1e-4);
    // The additive step lags behind the exact rotation (it takes chords of the unit sphere).
    assert!(additive.dot(expected).abs() < exact.dot(expected).abs());
}

#[test]
fn the_unnormalised_quaternion_stretches_and_shears_the_body() {
    // A tumbling racket: its axes through the rotation matrix built from the drifting q.
    let shape = |r: Mat3| {
        let axes = [r.x_axis, r.y_axis, r.z_axis];
        let lengths = axes.map(|a| a.length());
        let stretch = lengths.iter().fold(0.0f32, |m, l| m.max(*l))
            / lengths.iter().fold(f32::INFINITY, |m, l| m.min(*l));
        let skew = (0..3)
            .map(|i| axes[i].normalize().dot(axes[(i + 1) % 3].normalize()).abs())
            .fold(0.0, f32::max);
        (stretch, skew)
    };
    let run = |how| {
        let mut body = racket();
        body.omega_body = Vec3::new(3.0, 5.0, 2.0);
        let (mut stretch, mut skew) = (1.0f32, 0.0f32);
        for _ in 0..600 {
            body.step(1.0 / 60.0, Vec3::ZERO, AngularStep::Momentum, how);
            let (s, k) = shape(body.rotation());
            stretch = stretch.max(s);
            skew = skew.max(k);
        }
        (body.orientation.length(), stretch, skew)
    };
    let (length, stretch, skew) = run(OrientationStep::AdditiveUnnormalised);
    assert!(length > 1.1, "|q| = {length}");
    assert!(
        stretch > 1.2 && skew > 0.1,
        "stretch {stretch}, skew {skew}"
    );
    // With the normalisation the same matrix stays a rotation.
    let (length, stretch, skew) = run(OrientationStep::Additive);
    assert!((length - 1.0).abs() < 1e-5 && stretch < 1.0 + 1e-4 && skew < 1e-4);
}

#[test]
fn only_holding_l_keeps_both_invariants_of_a_spin_about_the_middle_axis() {
    // 10 s of the racket spun at 8 rad/s about its middle axis, the energy relative to the start.
    let energy = |how, hz: usize| {
        let mut body = racket();
        body.omega_body = Vec3::new(0.5, 8.0, 0.5);
        let e0 = body.kinetic_energy();
        let mut most = e0;
        for _ in 0..10 * hz {
            body.step(
                1.0 / hz as f32,
                Vec3::ZERO,
                how,
                OrientationStep::Exponential,
            );
            most = most.max(body.kinetic_energy());
        }
        (e0, most, body.kinetic_energy())
    };
    let (e0, explicit_most, _) = energy(AngularStep::Explicit, 60);
    let (_, implicit_most, implicit_end) = energy(AngularStep::Implicit, 60);
    let (_, held_most, _) = energy(AngularStep::Momentum, 60);
    let (_, _, held_fine) = energy(AngularStep::Momentum, 960);
    assert!(
        explicit_most > 1.5 * e0,
        "explicit: {e0} -> at most {explicit_most}"
    );
    // The implicit step never gains, and at 60 steps a second it loses a good part in 10 s.
    assert!(
        implicit_most <= e0 * (1.0 + 1e-5),
        "implicit: {e0} -> at most {implicit_most}"
    );
    assert!(implicit_end < 0.9 * e0, "implicit: {e0} -> {implicit_end}");
    // Holding L keeps the momentum (test above) and, turning the body by the symmetric
    // splitting, the energy too: within 0.1 % at 60 steps a second (the splitting's error is
    // bounded); at 960 steps a second float rounding over the 9,600 steps is what is left.
    assert!(
        (held_most / e0 - 1.0).abs() < 1e-3,
        "held L at 60 Hz: {e0} -> at most {held_most}"
    );
    assert!(
        (held_fine / e0 - 1.0).abs() < 2e-3,
        "held L at 960 Hz: {e0} -> {held_fine}"
    );
}

#[test]
fn a_spin_about_the_middle_axis_flips_and_spins_about_the_others_do_not() {
    // The tennis racket: spun about its intermediate axis (y) with a small wobble, the body
    // turns over again and again; about the smallest (x) or largest (z) axis it stays put.
    let flips = |axis: Vec3| {
        let mut body = racket();
        body.omega_body = 10.0 * axis + Vec3::splat(0.01);
        let start = axis;
        let mut lowest = 1.0f32;
        for _ in 0..1200 {
            body.step(
                1.0 / 240.0,
                Vec3::ZERO,
                AngularStep::Momentum,
                OrientationStep::Exponential,
            );
            lowest = lowest.min((body.orientation * axis).dot(start));
        }
        lowest
    };
    assert!(
        flips(Vec3::Y) < -0.9,
        "the middle axis turns over: {}",
        flips(Vec3::Y)
    );
    assert!(flips(Vec3::X) > 0.99 && flips(Vec3::Z) > 0.99);
}

#[test]
fn an_impulse_changes_the_velocity_by_j_over_m_and_the_spin_by_the_inverse_inertia_of_r_cross_j() {
    let mut body = racket();
    body.position = Vec3::new(1.0, 2.0, 3.0);
    body.orientation = Quat::from_rotation_y(0.7) * Quat::from_rotation_x(0.3);
    let j = Vec3::new(0.0, 2.0, 0.5);
    let r = Vec3::new(0.25, 0.0, -0.1);
    let expected_omega = body.world_inverse_inertia() * r.cross(j);
    body.apply_impulse(j, body.position + r);
    assert!((body.velocity - j / body.mass).length() < 1e-6);
    assert!((body.omega_world() - expected_omega).length() < 1e-4);
    // World inverse inertia is R I⁻¹ Rᵀ: symmetric, with the body's inverse moments as eigenvalues.
    let w = body.world_inverse_inertia();
    assert!(close(w, w.transpose(), 1e-5));
    assert!(
        (w.determinant() - body.inertia.recip().element_product()).abs() < 1e-3 * w.determinant()
    );
    // An impulse through the centre of mass does not spin the body.
    let spin = body.omega_world();
    body.apply_impulse(Vec3::new(5.0, 0.0, 0.0), body.position);
    assert!((body.omega_world() - spin).length() < 1e-6);
    // The contact point's velocity is v + ω × r.
    let p = body.position + r;
    assert!(
        (body.point_velocity(p) - (body.velocity + body.omega_world().cross(r))).length() < 1e-6
    );
}

#[test]
fn the_normal_impulse_turns_the_contact_points_normal_velocity_into_minus_e_times_itself() {
    // A tumbling racket meets the ground with a corner, in several attitudes and spins.
    let n = Vec3::Y;
    let mut approaching = 0;
    for k in 0..12 {
        let mut body = racket();
        body.position = Vec3::new(0.0, 0.4, 0.0);
        body.orientation = Quat::from_rotation_z(0.3 * k as f32) * Quat::from_rotation_x(0.7);
        body.velocity = Vec3::new(0.5, -3.0, 0.2 * k as f32 - 1.0);
        body.omega_body = Vec3::new(2.0 - 0.3 * k as f32, 1.0, 4.0);
        let corner = body.position + body.orientation * Vec3::new(0.3, -0.15, 0.05);
        let v = body.point_velocity(corner);
        if v.dot(n) >= 0.0 {
            continue;
        }
        approaching += 1;
        for e in [0.0, 0.5, 1.0] {
            let mut hit = body;
            let r = corner - hit.position;
            let j = normal_impulse(v, n, r, 1.0 / hit.mass, hit.world_inverse_inertia(), e);
            assert!(j > 0.0);
            hit.apply_impulse(j * n, corner);
            let after = hit.point_velocity(corner).dot(n);
            assert!(
                (after + e * v.dot(n)).abs() < 1e-4 * v.dot(n).abs(),
                "attitude {k}, e = {e}: {} became {after}",
                v.dot(n)
            );
            let (e0, e1) = (body.kinetic_energy(), hit.kinetic_energy());
            assert!(e1 <= e0 * (1.0 + 1e-5), "e = {e}: energy {e0} became {e1}");
            if e == 1.0 {
                assert!((e1 - e0).abs() < 1e-5 * e0, "e = 1 keeps {e0}, got {e1}");
            }
        }
    }
    assert!(approaching >= 8, "only {approaching} attitudes approach");
}

#[test]
fn a_separating_point_gets_no_impulse_and_one_under_the_centre_gets_no_spin() {
    let body = racket();
    let inv_i = body.world_inverse_inertia();
    let r = Vec3::new(0.2, -0.1, 0.0);
    assert_eq!(
        normal_impulse(Vec3::new(0.0, 1.0, 0.0), Vec3::Y, r, 1.0, inv_i, 0.5),
        0.0
    );
    assert_eq!(
        normal_impulse(Vec3::new(3.0, 0.0, 0.0), Vec3::Y, r, 1.0, inv_i, 0.5),
        0.0
    );
    // Straight under the centre of mass the body responds as a particle: j = (1 + e) m |v|.
    let j = normal_impulse(
        Vec3::new(0.0, -2.0, 0.0),
        Vec3::Y,
        -0.15 * Vec3::Y,
        1.0,
        inv_i,
        0.5,
    );
    assert!((j - 3.0).abs() < 1e-6, "{j}");
}
