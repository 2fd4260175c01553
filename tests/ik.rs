//! Inverse kinematics: every reachable target is reached within tolerance, unreachable ones are
//! reported with the remaining distance, segment lengths are kept, the pole picks the bend side,
//! and each bad input has its own error.

use glam::Vec3;
use inbetween::fixtures::Rng;
use inbetween::ik::{ccd, fabrik, two_joint, IkError};

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
    // FABRIK converges fast and must reach every reachable target. CCD crawls when the target
    // is near the edge of the reachable region (the chain nearly straight): it gets more
    // iterations and a looser tolerance, must reach 95% of the targets, and must at least come
    // within 2 cm of the rest.
    for (solver, iterations, tolerance, share) in
        [(fabrik as Solver, 200, 1e-3, 1.0), (ccd, 2000, 5e-3, 0.95)]
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
