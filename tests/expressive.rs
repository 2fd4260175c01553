//! Lesson 02b core (src/expressive): squash and stretch, springs, arcs, the jump, the antenna.

use glam::{Mat3, Vec3};
use inbetween::expressive::*;

#[test]
fn squash_and_stretch_keeps_the_volume() {
    for s in [0.3, 0.5, 1.0, 1.3, 2.0, 4.0] {
        let k = squash_stretch_scale(s);
        assert!((k.x * k.y * k.z - 1.0).abs() < 1e-5, "s = {s}");
        assert_eq!(k.x, s);
        assert_eq!(k.y, k.z);
        for axis in [Vec3::X, Vec3::new(1.0, 2.0, -0.5), Vec3::NEG_Y] {
            let m = squash_stretch_matrix(axis, s);
            assert!((m.determinant() - 1.0).abs() < 1e-4, "det at s = {s}");
            let a = axis.normalize();
            assert!((m * a - a * s).length() < 1e-4, "stretches along the axis");
            let across = a.any_orthonormal_vector();
            assert!(
                (m * across - across / s.sqrt()).length() < 1e-4,
                "thins across it"
            );
            assert!(
                (m - m.transpose()).abs_diff_eq(Mat3::ZERO, 1e-5),
                "no rotation: symmetric"
            );
        }
    }
    assert_eq!(squash_stretch_matrix(Vec3::ZERO, 2.0), Mat3::IDENTITY);
    assert_eq!(stretch_from_speed(-10.0, 0.1, 1.5), 1.5);
    assert_eq!(stretch_from_speed(0.0, 0.1, 1.5), 1.0);
}

#[test]
fn a_damped_follower_settles_on_its_target() {
    let target = Vec3::new(1.0, 2.0, -1.0);
    for (k, c) in [(40.0, 4.0), (40.0, 12.65), (10.0, 20.0)] {
        let (mut x, mut v) = (Vec3::ZERO, Vec3::ZERO);
        for _ in 0..2000 {
            (x, v) = spring_step(x, v, target, k, c, 1.0 / 120.0);
        }
        assert!(
            (x - target).length() < 1e-3 && v.length() < 1e-3,
            "k = {k}, c = {c}: {x}"
        );
    }
    // Under-damped overshoots, critically damped (c = 2√k) does not.
    let overshoot = |k: f32, c: f32| {
        let (mut x, mut v, mut most) = (Vec3::ZERO, Vec3::ZERO, 0.0f32);
        for _ in 0..600 {
            (x, v) = spring_step(x, v, Vec3::X, k, c, 1.0 / 240.0);
            most = most.max(x.x);
        }
        most - 1.0
    };
    assert!(overshoot(40.0, 2.0) > 0.3);
    assert!(overshoot(40.0, 2.0 * 40f32.sqrt()) < 1e-3);
    // dt = 0 changes nothing; at rest on the target it stays.
    let (x, v) = spring_step(Vec3::ONE, Vec3::X, Vec3::ZERO, 5.0, 1.0, 0.0);
    assert_eq!((x, v), (Vec3::ONE, Vec3::X));
    assert_eq!(
        spring_step(target, Vec3::ZERO, target, 5.0, 1.0, 0.1),
        (target, Vec3::ZERO)
    );
}

#[test]
fn arcs_pass_through_their_ends_and_bulge_by_the_sagitta() {
    let (a, b) = (Vec3::new(-2.0, 0.0, 0.0), Vec3::new(2.0, 0.0, 0.0));
    for h in [0.0, 0.5, 1.5, -0.7] {
        assert!((arc_point(a, b, Vec3::Y, h, 0.0) - a).length() < 1e-5);
        assert!((arc_point(a, b, Vec3::Y, h, 1.0) - b).length() < 1e-4);
        let mid = arc_point(a, b, Vec3::Y, h, 0.5);
        assert!(
            (mid - Vec3::new(0.0, h, 0.0)).length() < 1e-4,
            "h = {h}: {mid}"
        );
    }
    // Equal steps of t are equal steps of arc length.
    let p: Vec<Vec3> = (0..=10)
        .map(|k| arc_point(a, b, Vec3::Y, 1.0, k as f32 / 10.0))
        .collect();
    let d: Vec<f32> = p.windows(2).map(|w| (w[1] - w[0]).length()).collect();
    assert!(d.iter().all(|x| (x - d[0]).abs() < 1e-4));
}

#[test]
fn jumps_reach_the_apex_and_land_where_they_started() {
    let j = Jump::default();
    let mid = j.wind_up + 0.5 * j.flight;
    for sample in [j.principled(mid), j.plain(mid)] {
        assert!((sample.height - j.apex).abs() < 1e-4);
    }
    for t in [0.0, j.wind_up, j.wind_up + j.flight, j.duration()] {
        assert!(j.principled(t).height.abs() < 1e-4, "on the ground at {t}");
        assert!(j.plain(t).height.abs() < 1e-4);
    }
    // Anticipation: the body squashes (crouches) before take-off only when asked to.
    assert!(j.principled(0.5 * j.wind_up).stretch < 0.8);
    let none = Jump {
        anticipation: 0.0,
        ..j
    };
    assert_eq!(none.principled(0.5 * j.wind_up).stretch, 1.0);
    // Stretch in flight grows with speed; at the apex the body is round.
    assert!(j.principled(j.wind_up + 0.05).stretch > 1.1);
    assert!((j.principled(mid).stretch - 1.0).abs() < 1e-3);
    // The plain jump never deforms.
    assert!((0..100).all(|k| j.plain(k as f32 * 0.02).stretch == 1.0));
}

#[test]
fn the_antenna_keeps_its_length_lags_and_straightens_again() {
    let mut a = Antenna::new(Vec3::ZERO, 6, 0.2);
    let dt = 1.0 / 120.0;
    // Move the base sideways for half a second: the tip lags behind.
    for k in 0..60 {
        a.step(Vec3::new(k as f32 * 0.02, 0.0, 0.0), 120.0, 6.0, dt);
        for w in a.positions.windows(2) {
            assert!(((w[1] - w[0]).length() - 0.2).abs() < 1e-4);
        }
    }
    assert!(
        a.tip().x < a.positions[0].x - 0.05,
        "the tip lags: {}",
        a.tip()
    );
    // Stop: it swings past (follow-through), then settles straight above the base.
    let base = a.positions[0];
    let mut passed = false;
    for _ in 0..2400 {
        a.step(base, 120.0, 6.0, dt);
        passed |= a.tip().x > base.x + 0.01;
    }
    assert!(passed, "overshoot after the stop");
    assert!(
        (a.tip() - (base + Vec3::Y * 1.0)).length() < 1e-3,
        "{}",
        a.tip()
    );
}
