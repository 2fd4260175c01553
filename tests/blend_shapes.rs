//! Blend shapes core: one weight 1 gives that target, zero weights give the base, the two forms
//! agree when the weights sum to 1 and the full form scales the mesh when they do not, and each
//! validation rule has its own error.
// Native only: proptest and the file system are not available in the browser build.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::blend_shapes::{blend_full, BlendShapeError, BlendShapes};
use proptest::prelude::*;

fn mesh(seed: f32, n: usize) -> (Vec<Vec3>, Vec<Vec3>) {
    let p: Vec<Vec3> = (0..n)
        .map(|i| {
            Vec3::new(
                (i as f32 * 0.7 + seed).sin(),
                (i as f32 * 1.3 + seed).cos(),
                i as f32 * 0.1 + seed,
            )
        })
        .collect();
    let nn = p
        .iter()
        .map(|q| (*q + Vec3::splat(0.5)).normalize())
        .collect();
    (p, nn)
}

type Meshes = Vec<(Vec<Vec3>, Vec<Vec3>)>;

fn shapes() -> (BlendShapes, Meshes) {
    let (bp, bn) = mesh(0.0, 20);
    let targets = vec![mesh(1.0, 20), mesh(2.0, 20), mesh(3.0, 20)];
    (
        BlendShapes::from_targets(bp, bn, &targets).unwrap(),
        targets,
    )
}

#[test]
fn one_weight_one_gives_that_target_and_zero_gives_the_base() {
    let (s, targets) = shapes();
    let (mut p, mut n) = (vec![Vec3::ZERO; 20], vec![Vec3::ZERO; 20]);
    for k in 0..3 {
        let mut w = [0.0; 3];
        w[k] = 1.0;
        s.apply_differential(&w, &mut p, &mut n).unwrap();
        for v in 0..20 {
            assert!((p[v] - targets[k].0[v]).length() < 1e-5);
            assert!((n[v] - targets[k].1[v].normalize()).length() < 1e-5);
        }
        let mut full = [0.0; 4];
        full[k + 1] = 1.0;
        s.apply_full(&full, &mut p, &mut n).unwrap();
        assert!((p[5] - targets[k].0[5]).length() < 1e-5);
    }
    s.apply_differential(&[0.0; 3], &mut p, &mut n).unwrap();
    assert_eq!(p, mesh(0.0, 20).0);
}

proptest! {
    #[test]
    fn the_two_forms_agree_when_weights_sum_to_one(w in prop::array::uniform3(0.0f32..1.0)) {
        let (s, _) = shapes();
        let w0 = 1.0 - w.iter().sum::<f32>();
        let (mut a, mut an) = (vec![Vec3::ZERO; 20], vec![Vec3::ZERO; 20]);
        let (mut b, mut bn) = (vec![Vec3::ZERO; 20], vec![Vec3::ZERO; 20]);
        s.apply_differential(&w, &mut a, &mut an).unwrap();
        s.apply_full(&[w0, w[0], w[1], w[2]], &mut b, &mut bn).unwrap();
        for v in 0..20 {
            prop_assert!((a[v] - b[v]).length() < 1e-4);
        }
    }
}

#[test]
fn the_full_form_scales_the_mesh_when_weights_do_not_sum_to_one() {
    let (s, _) = shapes();
    let (mut p, mut n) = (vec![Vec3::ZERO; 20], vec![Vec3::ZERO; 20]);
    // Half the base and nothing else: the mesh shrinks to half size about the origin.
    s.apply_full(&[0.5, 0.0, 0.0, 0.0], &mut p, &mut n).unwrap();
    let base = mesh(0.0, 20).0;
    for v in 0..20 {
        assert!((p[v] - 0.5 * base[v]).length() < 1e-6);
    }
    let (a, b) = (mesh(1.0, 4).0, mesh(2.0, 4).0);
    let mut out = vec![Vec3::ZERO; 4];
    assert_eq!(
        blend_full(&[&a, &b], &[0.5, 0.3], &mut out),
        Err(BlendShapeError::WeightsDoNotSumToOne { sum: 0.8 })
    );
    blend_full(&[&a, &b], &[0.25, 0.75], &mut out).unwrap();
    assert!((out[2] - (0.25 * a[2] + 0.75 * b[2])).length() < 1e-6);
}

#[test]
fn each_validation_rule_has_its_own_error() {
    let (bp, bn) = mesh(0.0, 5);
    let short = mesh(1.0, 4);
    assert!(matches!(
        BlendShapes::from_targets(bp.clone(), bn.clone(), &[short]),
        Err(BlendShapeError::LengthMismatch {
            expected: 5,
            got: 4,
            ..
        })
    ));
    let mut nan = mesh(1.0, 5);
    nan.0[2].y = f32::NAN;
    let e = BlendShapes::from_targets(bp.clone(), bn.clone(), &[nan]).unwrap_err();
    assert!(e.to_string().contains("target 1 positions"), "{e}");
    let many = vec![mesh(1.0, 5); 300];
    assert!(matches!(
        BlendShapes::from_targets(bp.clone(), bn.clone(), &many),
        Err(BlendShapeError::TooManyTargets { got: 300 })
    ));
    let s = BlendShapes::from_targets(bp, bn, &[mesh(1.0, 5)]).unwrap();
    let (mut p, mut n) = (vec![Vec3::ZERO; 5], vec![Vec3::ZERO; 5]);
    assert!(s.apply_differential(&[1.0, 2.0], &mut p, &mut n).is_err());
    assert!(s.apply_differential(&[f32::NAN], &mut p, &mut n).is_err());
    assert!(s.apply_full(&[], &mut p, &mut n).is_err());
    assert!(s.apply_differential(&[0.5], &mut p[..4], &mut n).is_err());
}

/// Lesson 10's text: the head is a sphere squashed to an egg, 0.8 wide and 0.85 deep for 1 tall.
#[test]
fn the_head_is_an_egg_point_eight_wide_and_point_eight_five_deep_for_one_tall() {
    let face = inbetween::blend_shapes::face();
    let (lo, hi) = face.mesh.positions.iter().fold(
        (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let size = (hi - lo) / (hi.y - lo.y);
    assert!((size.x - 0.8).abs() < 0.01 && (size.z - 0.85).abs() < 0.01, "{size}");
}
