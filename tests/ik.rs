//! Inverse kinematics: every reachable target is reached within tolerance, unreachable ones are
//! reported with the remaining distance, segment lengths are kept, the pole picks the bend side,
//! and each bad input has its own error.

use glam::Vec3;
use inbetween::fixtures::Rng;
use inbetween::ik::{
    aim, apply_limits, ccd, ccd_limited, fabrik, fabrik_limited, max_violation_rad, rotation_arc,
    two_joint, IkError, JointLimit, MAX_LIMITED_JOINTS,
};
use std::f32::consts::PI;

fn lengths(chain: &[Vec3]) -> Vec<f32> {
    chain.windows(2).map(|w| w[0].distance(w[1])).collect()
}

/// A random chain of `n` joints, segment lengths in [0.3, 1].
fn chain(rng: &mut Rng, n: usize) -> Vec<Vec3> {
    let mut p = vec![Vec3::ZERO];
    for _ in 1..n {
        let dir = rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y);
        let last = *p.last().unwrap();
        p.push(last + dir * rng.range(0.3, 1.0));
    }
    p
}

/// A reachable target: the end of the same chain (same segment lengths) bent at random.
fn target(rng: &mut Rng, chain: &[Vec3]) -> Vec3 {
    let mut p = chain[0];
    for l in lengths(chain) {
        p += rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y) * l;
    }
    p
}

#[test]
fn two_joint_reaches_every_reachable_target_and_keeps_lengths() {
    let mut rng = Rng::new(21);
    for _ in 0..500 {
        let c = chain(&mut rng, 3);
        let l = lengths(&c);
        let (lo, hi) = ((l[0] - l[1]).abs(), l[0] + l[1]);
        let d = rng.range(lo + 0.01, hi - 0.01);
        let t = c[0] + rng.vec3(-1.0, 1.0).normalize_or(Vec3::X) * d;
        let pole = rng.vec3(-3.0, 3.0);
        let s = two_joint(c[0], c[1], c[2], t, pole, 1e-4).unwrap();
        assert!(s.result.reached, "error {}", s.result.error);
        assert!((s.middle.distance(c[0]) - l[0]).abs() < 1e-4);
        assert!((s.end.distance(s.middle) - l[1]).abs() < 1e-4);
        // The rotations take the old segments onto the new ones.
        let upper = s.root_rotation * (c[1] - c[0]);
        assert!(upper.abs_diff_eq(s.middle - c[0], 1e-4));
        let lower = s.middle_rotation * (s.root_rotation * (c[2] - c[1]));
        assert!(lower.abs_diff_eq(s.end - s.middle, 1e-4));
        // The middle joint bends towards the pole's side of the root→target line.
        let u = (t - c[0]).normalize();
        let side = |p: Vec3| (p - c[0]) - u * (p - c[0]).dot(u);
        if side(pole).length() > 0.1 {
            assert!(side(s.middle).dot(side(pole)) > 0.0);
        }
    }
}

#[test]
fn unreachable_targets_are_reported_with_the_remaining_distance() {
    let c = [Vec3::ZERO, Vec3::Y, Vec3::new(0.0, 2.0, 0.0)];
    let far = Vec3::new(5.0, 0.0, 0.0);
    let s = two_joint(c[0], c[1], c[2], far, Vec3::Z, 1e-3).unwrap();
    assert!(!s.result.reached);
    assert!((s.result.error - 3.0).abs() < 1e-3, "{}", s.result.error);
    // Too close: |a − b| = 0.5 is the nearest the end can get to the root.
    let short = [Vec3::ZERO, Vec3::Y, Vec3::new(0.0, 1.5, 0.0)];
    let s = two_joint(
        short[0],
        short[1],
        short[2],
        Vec3::new(0.1, 0.0, 0.0),
        Vec3::Z,
        1e-3,
    )
    .unwrap();
    assert!(!s.result.reached && (s.result.error - 0.4).abs() < 1e-3);
    for solver in [ccd, fabrik] {
        let mut c = c.to_vec();
        let r = solver(&mut c, far, 50, 1e-3, None).unwrap();
        assert!(!r.reached && (r.error - 3.0).abs() < 1e-2, "{r:?}");
        assert!((lengths(&c)[0] - 1.0).abs() < 1e-4 && (lengths(&c)[1] - 1.0).abs() < 1e-4);
    }
}

#[test]
fn ccd_and_fabrik_reach_reachable_targets_and_keep_lengths() {
    let mut rng = Rng::new(5);
    // Both must reach every reachable target. CCD needs more iterations: its last corrections
    // are tiny rotations (which glam's `from_rotation_arc` drops, stalling it millimetres short;
    // `ik::rotation_arc` keeps them).
    for (solver, iterations, tolerance, share) in
        [(fabrik as Solver, 200, 1e-3, 1.0), (ccd, 2000, 1e-3, 1.0)]
    {
        let mut reached = 0;
        for _ in 0..300 {
            let joints = 2 + rng.below(6);
            let start = chain(&mut rng, joints);
            let t = target(&mut rng, &start);
            let mut c = start.clone();
            let mut errors = vec![0.0f32; iterations];
            let r = solver(&mut c, t, iterations, tolerance, Some(&mut errors)).unwrap();
            assert!(
                r.reached || (share < 1.0 && r.error < 0.02),
                "{r:?} for {joints} joints"
            );
            reached += r.reached as usize;
            assert_eq!(c[0], start[0], "the root stays put");
            for (a, b) in lengths(&c).iter().zip(lengths(&start)) {
                assert!((a - b).abs() < 1e-3, "lengths kept");
            }
            assert!((c.last().unwrap().distance(t) - r.error).abs() < 1e-5);
            if r.iterations > 0 {
                assert_eq!(
                    errors[r.iterations - 1],
                    r.error,
                    "the error log ends at the result"
                );
            }
        }
        assert!(reached as f32 >= share * 300.0, "{reached} of 300");
    }
}

type Solver = fn(
    &mut [Vec3],
    Vec3,
    usize,
    f32,
    Option<&mut [f32]>,
) -> Result<inbetween::ik::IkResult, IkError>;

#[test]
fn each_bad_input_has_its_own_error() {
    let c = [Vec3::ZERO, Vec3::Y, Vec3::new(0.0, 2.0, 0.0)];
    let t = Vec3::X;
    assert!(matches!(
        ccd(&mut [Vec3::ZERO], t, 10, 1e-3, None),
        Err(IkError::ChainLength { joints: 1 })
    ));
    assert!(matches!(
        fabrik(&mut [Vec3::ZERO, Vec3::ZERO], t, 10, 1e-3, None),
        Err(IkError::ZeroSegment { segment: 0 })
    ));
    assert!(matches!(
        ccd(&mut c.clone(), Vec3::NAN, 10, 1e-3, None),
        Err(IkError::NonFinite { what: "target" })
    ));
    assert!(matches!(
        ccd(&mut c.clone(), t, 0, 1e-3, None),
        Err(IkError::BadIterations { iterations: 0 })
    ));
    assert!(matches!(
        fabrik(&mut c.clone(), t, 10, -1.0, None),
        Err(IkError::BadTolerance { .. })
    ));
    assert!(matches!(
        two_joint(c[0], c[1], c[2], t, Vec3::NAN, 1e-3),
        Err(IkError::NonFinite { what: "pole" })
    ));
    let message = IkError::ZeroSegment { segment: 2 }.to_string();
    assert!(message.contains("segment 2"));
}

#[test]
fn rotation_arc_keeps_tiny_angles() {
    // glam's from_rotation_arc returns the identity below about 7e-4 rad: CCD then stalls.
    let from = Vec3::X;
    let to = Vec3::new(1.0, 1e-4, 0.0);
    let q = rotation_arc(from, to).unwrap();
    assert!((q * from).abs_diff_eq(to.normalize(), 1e-7));
    assert!(q.to_axis_angle().1 > 0.9e-4);
    // Half a turn, and nothing for a zero vector.
    let q = rotation_arc(Vec3::X, -Vec3::X).unwrap();
    assert!((q * Vec3::X).abs_diff_eq(-Vec3::X, 1e-6));
    assert!(rotation_arc(Vec3::ZERO, Vec3::X).is_none());
}

/// Random limits for a chain of `n` joints: free, hinges about z with random ranges, cones.
fn limits(rng: &mut Rng, n: usize) -> Vec<JointLimit> {
    (0..n - 1)
        .map(|_| match rng.below(3) {
            0 => JointLimit::Free,
            1 => {
                let a = rng.range(-PI, PI);
                let b = rng.range(-PI, PI);
                JointLimit::Hinge {
                    axis: Vec3::Z,
                    min_rad: a.min(b),
                    max_rad: a.max(b),
                }
            }
            _ => JointLimit::Cone {
                max_rad: rng.range(0.0, PI),
            },
        })
        .collect()
}

#[test]
fn constrain_returns_allowed_directions_and_keeps_allowed_ones() {
    let mut rng = Rng::new(77);
    for _ in 0..2000 {
        let limit = limits(&mut rng, 2)[0];
        let incoming = rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y);
        let dir = rng.vec3(-1.0, 1.0).normalize_or(Vec3::X);
        let allowed = limit.constrain(incoming, dir);
        assert!((allowed.length() - 1.0).abs() < 1e-4);
        assert!(limit.violation_rad(incoming, allowed) < 1e-3, "{limit:?}");
        // An allowed direction is kept as it is.
        assert!(limit
            .constrain(incoming, allowed)
            .abs_diff_eq(allowed, 1e-3));
        match limit {
            JointLimit::Cone { max_rad } => {
                assert!(incoming.angle_between(allowed) <= max_rad + 1e-3)
            }
            JointLimit::Hinge { axis, .. } => assert!(allowed.dot(axis).abs() < 1e-4),
            JointLimit::Free => assert_eq!(allowed, dir),
        }
    }
    // A knee: bends only one way. 90° the wrong way is clamped onto the straight leg.
    let knee = JointLimit::Hinge {
        axis: Vec3::X,
        min_rad: 0.0,
        max_rad: 2.5,
    };
    let down = -Vec3::Y;
    assert!(knee.constrain(down, Vec3::Z).abs_diff_eq(down, 1e-5));
    assert!(knee.constrain(down, -Vec3::Z).abs_diff_eq(-Vec3::Z, 1e-5));
}

#[test]
fn limited_solvers_respect_every_limit_and_keep_lengths() {
    let mut rng = Rng::new(9);
    for solver in [ccd_limited as LimitedSolver, fabrik_limited] {
        for _ in 0..200 {
            let n = 2 + rng.below(6);
            let start = chain(&mut rng, n);
            let l = limits(&mut rng, n);
            let root_direction = rng.vec3(-1.0, 1.0).normalize_or(Vec3::Y);
            let t = rng.vec3(-3.0, 3.0);
            let mut c = start.clone();
            let r = solver(&mut c, &l, root_direction, t, 50, 1e-3, None).unwrap();
            assert_eq!(c[0], start[0]);
            for (a, b) in lengths(&c).iter().zip(lengths(&start)) {
                assert!((a - b).abs() < 1e-3);
            }
            let v = max_violation_rad(&c, &l, root_direction);
            assert!(v < 2e-3, "violation {v} rad with {l:?}");
            assert!((c[n - 1].distance(t) - r.error).abs() < 1e-5);
            assert_eq!(r.reached, r.error <= 1e-3);
        }
    }
}

#[test]
fn limited_solvers_reach_targets_the_limits_allow() {
    // A planar three-segment finger with hinges that bend one way; targets are ends of random
    // allowed poses, so each is reachable within the limits.
    let mut rng = Rng::new(3);
    let hinge = JointLimit::Hinge {
        axis: Vec3::Z,
        min_rad: -0.1,
        max_rad: 1.8,
    };
    let l = [hinge; 3];
    let down = -Vec3::Y;
    let straight = [Vec3::ZERO, down, 2.0 * down, 3.0 * down];
    for (solver, share) in [(ccd_limited as LimitedSolver, 0.9), (fabrik_limited, 0.9)] {
        let mut reached = 0;
        for _ in 0..200 {
            let mut pose = straight;
            let mut dir = down;
            for i in 0..3 {
                dir = glam::Quat::from_rotation_z(rng.range(-0.1, 1.8)) * dir;
                pose[i + 1] = pose[i] + dir;
            }
            let t = pose[3];
            let mut c = straight;
            let r = solver(&mut c, &l, down, t, 500, 1e-3, None).unwrap();
            reached += r.reached as usize;
            assert!(max_violation_rad(&c, &l, down) < 2e-3);
        }
        assert!(reached as f32 >= share * 200.0, "{reached} of 200");
    }
    // Out of the limits' reach: the finger cannot bend backwards.
    let mut c = straight;
    let r = ccd_limited(
        &mut c,
        &l,
        down,
        Vec3::new(-2.5, -1.0, 0.0),
        200,
        1e-3,
        None,
    )
    .unwrap();
    assert!(!r.reached && r.error > 0.5, "{r:?}");
    assert!(max_violation_rad(&c, &l, down) < 2e-3);
}

type LimitedSolver = fn(
    &mut [Vec3],
    &[JointLimit],
    Vec3,
    Vec3,
    usize,
    f32,
    Option<&mut [f32]>,
) -> Result<inbetween::ik::IkResult, IkError>;

#[test]
fn apply_limits_fixes_a_chain_from_the_root_out() {
    let l = [JointLimit::Cone { max_rad: 0.3 }; 3];
    let mut c = [
        Vec3::ZERO,
        Vec3::X,
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
    ];
    assert!(max_violation_rad(&c, &l, Vec3::X) > 1.0);
    apply_limits(&mut c, &l, Vec3::X, 0);
    assert!(max_violation_rad(&c, &l, Vec3::X) < 1e-4);
}

#[test]
fn aim_points_at_the_target_without_roll_and_within_its_cone() {
    let mut rng = Rng::new(12);
    for _ in 0..500 {
        let position = rng.vec3(-1.0, 1.0);
        let forward = rng.vec3(-1.0, 1.0).normalize_or(Vec3::Z);
        let up = (Vec3::Y - forward * forward.dot(Vec3::Y)).normalize_or(Vec3::X);
        let target = rng.vec3(-3.0, 3.0);
        let a = (target - position).normalize();
        // Without a limit: exactly at the target.
        let s = aim(position, forward, up, target, PI, 1e-3).unwrap();
        assert!(s.result.reached && s.result.error < 1e-3, "{:?}", s.result);
        assert!((s.rotation * forward).abs_diff_eq(a, 1e-3));
        assert!((s.rotation * up).abs_diff_eq(s.up, 1e-3));
        // No roll: the new up lies in the plane of the new forward and the old up.
        let normal = s.forward.cross(up);
        if normal.length() > 0.1 {
            assert!(s.up.dot(normal.normalize()).abs() < 1e-3);
        }
        // With a cone: never further than the limit, and the error is what is left.
        let max = rng.range(0.0, PI);
        let s = aim(position, forward, up, target, max, 1e-3).unwrap();
        assert!(forward.angle_between(s.forward) <= max + 1e-3);
        let left = (forward.angle_between(a) - max).max(0.0);
        assert!(
            (s.result.error - left).abs() < 2e-3,
            "{} vs {left}",
            s.result.error
        );
        assert_eq!(s.result.reached, s.result.error <= 1e-3);
    }
}

#[test]
fn limits_and_aim_reject_bad_input() {
    let c = [Vec3::ZERO, Vec3::Y, Vec3::new(0.0, 2.0, 0.0)];
    let t = Vec3::X;
    let free = [JointLimit::Free; 2];
    assert!(matches!(
        ccd_limited(&mut c.clone(), &free[..1], Vec3::Y, t, 10, 1e-3, None),
        Err(IkError::LimitCount {
            limits: 1,
            joints: 3
        })
    ));
    let bad = [
        JointLimit::Free,
        JointLimit::Hinge {
            axis: Vec3::ZERO,
            min_rad: 0.0,
            max_rad: 1.0,
        },
    ];
    assert!(matches!(
        fabrik_limited(&mut c.clone(), &bad, Vec3::Y, t, 10, 1e-3, None),
        Err(IkError::BadLimit { joint: 1, .. })
    ));
    let reversed = [JointLimit::Hinge {
        axis: Vec3::Z,
        min_rad: 1.0,
        max_rad: 0.0,
    }; 2];
    assert!(matches!(
        ccd_limited(&mut c.clone(), &reversed, Vec3::Y, t, 10, 1e-3, None),
        Err(IkError::BadLimit { joint: 0, .. })
    ));
    let cone = [JointLimit::Cone { max_rad: -0.1 }; 2];
    assert!(ccd_limited(&mut c.clone(), &cone, Vec3::Y, t, 10, 1e-3, None).is_err());
    assert!(matches!(
        ccd_limited(&mut c.clone(), &free, Vec3::ZERO, t, 10, 1e-3, None),
        Err(IkError::NonFinite { .. })
    ));
    let long: Vec<Vec3> = (0..=MAX_LIMITED_JOINTS)
        .map(|i| Vec3::Y * i as f32)
        .collect();
    let many = vec![JointLimit::Free; MAX_LIMITED_JOINTS];
    assert!(matches!(
        ccd_limited(&mut long.clone(), &many, Vec3::Y, t, 10, 1e-3, None),
        Err(IkError::ChainLength { .. })
    ));
    assert!(matches!(
        aim(Vec3::ZERO, Vec3::Z, Vec3::Z, t, PI, 1e-3),
        Err(IkError::BadAim)
    ));
    assert!(matches!(
        aim(Vec3::ZERO, Vec3::Z, Vec3::Y, Vec3::ZERO, PI, 1e-3),
        Err(IkError::ZeroSegment { .. })
    ));
    assert!(matches!(
        aim(Vec3::ZERO, Vec3::Z, Vec3::Y, Vec3::NAN, PI, 1e-3),
        Err(IkError::NonFinite { what: "target" })
    ));
    assert!(IkError::BadLimit { joint: 3, why: "x" }
        .to_string()
        .contains("joint 3"));
}
