//! Skinning core (lesson 09): one failing input per validation rule, the properties every skinning
//! method must have (rest pose gives the bind mesh, one joint at weight 1 is rigid), the ones that
//! tell LBS and DQS apart (DQS keeps distances under twist, LBS collapses more at a bend), and the
//! automatic weights.
// Native only: proptest and the file system are not available in the browser build.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Affine3A, Mat4, Quat, Vec3};
use inbetween::rigid::DualQuat;
use inbetween::skinning::rigs::{cylinder_rig, skinned_human, CylinderRig};
use inbetween::skinning::{
    auto_weights, blend_dual_quats, dqs_vertex, dual_quat_palette, lbs_vertex, mesh_volume,
    ring_area, skin_dqs, skin_dqs_with, skin_lbs, skin_lbs_interleaved, skin_lbs_positions,
    skin_lbs_with, skinning_palette, LbsKernel, SkinVertex, SkinWeights, SkinningError,
};
use proptest::prelude::*;
use std::f32::consts::PI;

fn rig() -> CylinderRig {
    cylinder_rig(1.0, 0.25, 41, 24).unwrap()
}

struct Skinned {
    lbs: Vec<Vec3>,
    dqs: Vec<Vec3>,
    lbs_normals: Vec<Vec3>,
    dqs_normals: Vec<Vec3>,
}

fn skin_both(rig: &CylinderRig, skin: &SkinWeights, bend: f32, twist: f32) -> Skinned {
    let n = rig.skeleton.len();
    let mut model = vec![Affine3A::IDENTITY; n];
    let mut palette = vec![Affine3A::IDENTITY; n];
    rig.palette(bend, twist, &mut model, &mut palette).unwrap();
    let mut dq = vec![DualQuat::IDENTITY; n];
    dual_quat_palette(&palette, &mut dq).unwrap();
    let v = rig.mesh.positions.len();
    let mut out = Skinned {
        lbs: vec![Vec3::ZERO; v],
        dqs: vec![Vec3::ZERO; v],
        lbs_normals: vec![Vec3::ZERO; v],
        dqs_normals: vec![Vec3::ZERO; v],
    };
    let m = &rig.mesh;
    skin_lbs(
        &palette,
        skin,
        &m.positions,
        &m.normals,
        &mut out.lbs,
        &mut out.lbs_normals,
    )
    .unwrap();
    skin_dqs(
        &dq,
        skin,
        &m.positions,
        &m.normals,
        &mut out.dqs,
        &mut out.dqs_normals,
    )
    .unwrap();
    out
}

fn elbow_area(rig: &CylinderRig, positions: &[Vec3]) -> f32 {
    let s = rig.ring_start(rig.elbow_ring());
    ring_area(&positions[s..s + rig.around]) / rig.rest_ring_area()
}

#[test]
fn each_validation_rule_has_its_own_error() {
    let ok_j = vec![[0u16, 1, 0, 0]];
    let ok_w = vec![[0.5f32, 0.5, 0.0, 0.0]];
    assert!(SkinWeights::new(ok_j.clone(), ok_w.clone(), 2).is_ok());
    assert!(matches!(
        SkinWeights::new(ok_j.clone(), vec![], 2),
        Err(SkinningError::LengthMismatch {
            expected: 1,
            got: 0,
            ..
        })
    ));
    assert_eq!(
        SkinWeights::new(vec![[0, 2, 0, 0]], ok_w.clone(), 2),
        Err(SkinningError::JointOutOfRange {
            vertex: 0,
            joint: 2,
            joints: 2
        })
    );
    assert_eq!(
        SkinWeights::new(ok_j.clone(), vec![[f32::NAN, 0.5, 0.0, 0.0]], 2),
        Err(SkinningError::NonFiniteWeight { vertex: 0 })
    );
    assert_eq!(
        SkinWeights::new(ok_j.clone(), vec![[f32::INFINITY, 0.5, 0.0, 0.0]], 2),
        Err(SkinningError::NonFiniteWeight { vertex: 0 })
    );
    assert_eq!(
        SkinWeights::new(ok_j.clone(), vec![[1.0, -0.5, 0.0, 0.0]], 2),
        Err(SkinningError::NegativeWeight {
            vertex: 0,
            weight: -0.5
        })
    );
    assert_eq!(
        SkinWeights::new(
            vec![[0; 4], [0; 4]],
            vec![[1.0, 0.0, 0.0, 0.0], [0.0; 4]],
            2
        ),
        Err(SkinningError::ZeroWeights { vertex: 1 })
    );
    // The messages name the vertex and the rule.
    let e = SkinWeights::new(vec![[0, 7, 0, 0]], ok_w, 3).unwrap_err();
    assert!(e.to_string().contains("vertex 0 names joint 7"), "{e}");
}

#[test]
fn weights_are_normalised_by_their_sum() {
    let s = SkinWeights::new(vec![[0, 1, 2, 0]], vec![[2.0, 1.0, 1.0, 0.0]], 3).unwrap();
    assert_eq!(s.weights()[0], [0.5, 0.25, 0.25, 0.0]);
    assert_eq!(s.weight_of(0, 0), 0.5);
    assert_eq!(s.weight_of(0, 2), 0.25);
}

#[test]
fn eight_influences_keep_the_four_largest() {
    let j = [[0u16, 1, 2, 3, 4, 5, 6, 7]];
    let w = [[0.05f32, 0.3, 0.05, 0.2, 0.1, 0.05, 0.2, 0.05]];
    let s = SkinWeights::from_eight(&j, &w, 8).unwrap();
    assert_eq!(s.joints()[0][..2], [1, 3]);
    let kept: f32 = 0.3 + 0.2 + 0.2 + 0.1;
    assert!((s.weight_of(0, 1) - 0.3 / kept).abs() < 1e-6);
    assert_eq!(s.weight_of(0, 0), 0.0);
    assert!(matches!(
        SkinWeights::from_eight(&[[0, 1, 2, 3, 4, 5, 6, 9]], &w, 8),
        Err(SkinningError::JointOutOfRange { joint: 9, .. })
    ));
}

#[test]
fn skinning_checks_lengths_and_the_palette() {
    let rig = rig();
    let skin = rig.weights(0.1).unwrap();
    let n = rig.mesh.positions.len();
    let palette = vec![Affine3A::IDENTITY; 3];
    let mut out = vec![Vec3::ZERO; n];
    let mut out_n = vec![Vec3::ZERO; n - 1];
    assert!(matches!(
        skin_lbs(
            &palette,
            &skin,
            &rig.mesh.positions,
            &rig.mesh.normals,
            &mut out,
            &mut out_n
        ),
        Err(SkinningError::LengthMismatch {
            what: "output normals",
            ..
        })
    ));
    let mut out_n = vec![Vec3::ZERO; n];
    // A palette shorter than the joints the vertices name.
    assert!(matches!(
        skin_lbs(
            &palette[..1],
            &skin,
            &rig.mesh.positions,
            &rig.mesh.normals,
            &mut out,
            &mut out_n
        ),
        Err(SkinningError::JointOutOfRange { joints: 1, .. })
    ));
    let dq = vec![DualQuat::IDENTITY; 1];
    assert!(matches!(
        skin_dqs(
            &dq,
            &skin,
            &rig.mesh.positions,
            &rig.mesh.normals,
            &mut out,
            &mut out_n
        ),
        Err(SkinningError::JointOutOfRange { joints: 1, .. })
    ));
    // Non-finite matrices and scaled joints.
    let mut bad = vec![Affine3A::IDENTITY; 3];
    let mut k = vec![Affine3A::IDENTITY; 3];
    bad[2].translation.x = f32::NAN;
    assert_eq!(
        skinning_palette(&bad, rig.skeleton.inverse_bind(), &mut k),
        Err(SkinningError::NonFiniteMatrix { joint: 2 })
    );
    let scaled = vec![
        Affine3A::IDENTITY,
        Affine3A::from_scale(Vec3::new(1.0, 2.0, 1.0)),
    ];
    let mut dq = vec![DualQuat::IDENTITY; 2];
    let e = dual_quat_palette(&scaled, &mut dq).unwrap_err();
    assert!(matches!(e, SkinningError::ScaledJoint { joint: 1, .. }));
    assert!(e.to_string().contains("not rigid"));
    let mirrored = vec![Affine3A::from_scale(Vec3::new(-1.0, 1.0, 1.0))];
    assert!(dual_quat_palette(&mirrored, &mut dq[..1]).is_err());
}

#[test]
fn rest_pose_skins_to_the_bind_mesh() {
    let rig = rig();
    let skin = rig.weights(0.15).unwrap();
    let s = skin_both(&rig, &skin, 0.0, 0.0);
    for (v, p) in rig.mesh.positions.iter().enumerate() {
        assert!((s.lbs[v] - *p).length() < 1e-5, "LBS vertex {v}");
        assert!((s.dqs[v] - *p).length() < 1e-5, "DQS vertex {v}");
        assert!((s.lbs_normals[v] - rig.mesh.normals[v]).length() < 1e-5);
        assert!((s.dqs_normals[v] - rig.mesh.normals[v]).length() < 1e-5);
    }
    // The human too, with its 21 joints.
    let human = skinned_human(0.03).unwrap();
    let n = human.skeleton.len();
    let mut model = vec![Affine3A::IDENTITY; n];
    let mut palette = vec![Affine3A::IDENTITY; n];
    human
        .skeleton
        .model_matrices(&human.skeleton.rest_pose(), &mut model)
        .unwrap();
    skinning_palette(&model, human.skeleton.inverse_bind(), &mut palette).unwrap();
    let v = human.mesh.positions.len();
    let (mut p, mut nn) = (vec![Vec3::ZERO; v], vec![Vec3::ZERO; v]);
    skin_lbs(
        &palette,
        &human.skin,
        &human.mesh.positions,
        &human.mesh.normals,
        &mut p,
        &mut nn,
    )
    .unwrap();
    for (a, b) in p.iter().zip(&human.mesh.positions) {
        assert!((*a - *b).length() < 1e-5);
    }
}

fn random_rigid(rng: &mut impl FnMut() -> f32) -> Affine3A {
    let axis = Vec3::new(rng() - 0.5, rng() - 0.5, rng() - 0.5).normalize_or(Vec3::Y);
    Affine3A::from_rotation_translation(
        Quat::from_axis_angle(axis, 6.0 * rng()),
        Vec3::new(rng(), rng(), rng()) * 4.0 - 2.0,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A vertex bound to one joint with weight 1 moves rigidly with it: p' = K_j p, and the
    /// distance between two such vertices is kept, in LBS and in DQS.
    #[test]
    fn one_joint_at_weight_one_moves_rigidly(seed in 0u32..10_000, a in prop::array::uniform3(-2.0f32..2.0), b in prop::array::uniform3(-2.0f32..2.0)) {
        let mut state = seed.wrapping_mul(2654435761).wrapping_add(1);
        let mut rng = move || { state ^= state << 13; state ^= state >> 17; state ^= state << 5; (state % 10_000) as f32 / 10_000.0 };
        let palette: Vec<Affine3A> = (0..4).map(|_| random_rigid(&mut rng)).collect();
        let skin = SkinWeights::new(vec![[2, 0, 0, 0], [2, 1, 3, 0]], vec![[1.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]], 4).unwrap();
        let (pa, pb) = (Vec3::from_array(a), Vec3::from_array(b));
        let pos = [pa, pb];
        let nrm = [Vec3::X, Vec3::Y];
        let (mut o, mut on) = ([Vec3::ZERO; 2], [Vec3::ZERO; 2]);
        skin_lbs(&palette, &skin, &pos, &nrm, &mut o, &mut on).unwrap();
        prop_assert!((o[0] - palette[2].transform_point3(pa)).length() < 1e-4);
        prop_assert!(((o[0] - o[1]).length() - (pa - pb).length()).abs() < 1e-4);
        prop_assert!((on[1] - palette[2].transform_vector3(Vec3::Y)).length() < 1e-5);
        let mut dq = vec![DualQuat::IDENTITY; 4];
        dual_quat_palette(&palette, &mut dq).unwrap();
        skin_dqs(&dq, &skin, &pos, &nrm, &mut o, &mut on).unwrap();
        prop_assert!((o[0] - palette[2].transform_point3(pa)).length() < 1e-4);
        prop_assert!(((o[0] - o[1]).length() - (pa - pb).length()).abs() < 1e-4);
        prop_assert!((on[1] - palette[2].transform_vector3(Vec3::Y)).length() < 1e-4);
    }

    /// With pure translations every blend of matrices is itself a translation, and DQS gives
    /// exactly what LBS gives: p + Σ w_j t_j.
    #[test]
    fn dqs_equals_lbs_for_pure_translations(t in prop::array::uniform12(-3.0f32..3.0), w in prop::array::uniform4(0.01f32..1.0), p in prop::array::uniform3(-2.0f32..2.0)) {
        let palette: Vec<Affine3A> = t.chunks(3).map(|c| Affine3A::from_translation(Vec3::new(c[0], c[1], c[2]))).collect();
        let skin = SkinWeights::new(vec![[0, 1, 2, 3]], vec![w], 4).unwrap();
        let pos = [Vec3::from_array(p)];
        let nrm = [Vec3::Z];
        let (mut a, mut an, mut b, mut bn) = ([Vec3::ZERO], [Vec3::ZERO], [Vec3::ZERO], [Vec3::ZERO]);
        skin_lbs(&palette, &skin, &pos, &nrm, &mut a, &mut an).unwrap();
        let mut dq = vec![DualQuat::IDENTITY; 4];
        dual_quat_palette(&palette, &mut dq).unwrap();
        skin_dqs(&dq, &skin, &pos, &nrm, &mut b, &mut bn).unwrap();
        prop_assert!((a[0] - b[0]).length() < 1e-4, "{:?} vs {:?}", a, b);
        prop_assert!((an[0] - bn[0]).length() < 1e-5);
    }

    /// Twisting the elbow about its own bone moves every vertex by a rotation about the x axis
    /// through the elbow in DQS, so its distance to the elbow joint is kept at any angle.
    #[test]
    fn dqs_keeps_distances_to_the_joint_under_twist(twist in -PI..PI) {
        let rig = rig();
        let skin = rig.weights(0.2).unwrap();
        let s = skin_both(&rig, &skin, 0.0, twist);
        let elbow = Vec3::new(rig.segment_length, 0.0, 0.0);
        for (v, p) in rig.mesh.positions.iter().enumerate() {
            let d0 = (*p - elbow).length();
            prop_assert!(((s.dqs[v] - elbow).length() - d0).abs() < 1e-4, "vertex {}", v);
        }
    }

    /// The interleaved layout computes the same thing as separate arrays.
    #[test]
    fn interleaved_lbs_equals_separate_arrays(bend in -2.5f32..2.5, twist in -PI..PI) {
        let rig = rig();
        let skin = rig.weights(0.1).unwrap();
        let s = skin_both(&rig, &skin, bend, twist);
        let mut model = vec![Affine3A::IDENTITY; 3];
        let mut palette = vec![Affine3A::IDENTITY; 3];
        rig.palette(bend, twist, &mut model, &mut palette).unwrap();
        let verts = SkinVertex::interleave(&skin, &rig.mesh.positions, &rig.mesh.normals).unwrap();
        let n = verts.len();
        let (mut p, mut nn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        skin_lbs_interleaved(&palette, &verts, &mut p, &mut nn).unwrap();
        // Bit for bit against the same (portable) kernel; to rounding against the CPU's best.
        let (mut q, mut qn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        skin_lbs_with(LbsKernel::Portable, &palette, &skin, &rig.mesh.positions, &rig.mesh.normals, &mut q, &mut qn).unwrap();
        prop_assert_eq!(&p, &q);
        prop_assert_eq!(&nn, &qn);
        for v in 0..n {
            prop_assert!((p[v] - s.lbs[v]).length() < 1e-5 * (1.0 + p[v].length()), "vertex {}", v);
            prop_assert!((nn[v] - s.lbs_normals[v]).length() < 1e-5, "normal {}", v);
        }
    }
}

/// Whichever kernel `skin_lbs` picks on this CPU (AVX2 + FMA where there is one) agrees with the
/// portable kernel to rounding, on the benchmark's humanoid with a vertex count that is not a
/// multiple of anything, so the last vertex's exact-size store runs too.
#[test]
fn the_best_lbs_kernel_matches_the_portable_one() {
    let input = inbetween::skinning::rigs::benchmark_input(1003, 11);
    let n = input.positions.len();
    let (mut a, mut an, mut b, mut bn) = (
        vec![Vec3::ZERO; n],
        vec![Vec3::ZERO; n],
        vec![Vec3::ZERO; n],
        vec![Vec3::ZERO; n],
    );
    skin_lbs(
        &input.palette,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut a,
        &mut an,
    )
    .unwrap();
    skin_lbs_with(
        LbsKernel::Portable,
        &input.palette,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut b,
        &mut bn,
    )
    .unwrap();
    for v in 0..n {
        assert!(
            (a[v] - b[v]).length() < 1e-5 * (1.0 + b[v].length()),
            "vertex {v} ({:?}): {} vs {}",
            LbsKernel::best(),
            a[v],
            b[v]
        );
        assert!(
            (an[v] - bn[v]).length() < 1e-5 * (1.0 + bn[v].length()),
            "normal {v}"
        );
    }
    // The output has exactly n entries and the last one is whole (not clobbered by a wide store).
    assert!(a[n - 1].is_finite() && (a[n - 1] - b[n - 1]).length() < 1e-4);
}

/// The DQS kernel switch: the portable loop (what wasm runs) agrees with the best one (AVX2 here
/// when the CPU has it) to rounding, and with `dqs_vertex`, the formula written out.
#[test]
fn the_best_dqs_kernel_matches_the_portable_one() {
    let input = inbetween::skinning::rigs::benchmark_input(1003, 11);
    let n = input.positions.len();
    let mut dq = vec![DualQuat::IDENTITY; input.palette.len()];
    dual_quat_palette(&input.palette, &mut dq).unwrap();
    let mut out = [0, 1, 2, 3].map(|_| vec![Vec3::ZERO; n]);
    let [a, an, b, bn] = &mut out;
    skin_dqs(&dq, &input.skin, &input.positions, &input.normals, a, an).unwrap();
    skin_dqs_with(
        LbsKernel::Portable,
        &dq,
        &input.skin,
        &input.positions,
        &input.normals,
        b,
        bn,
    )
    .unwrap();
    for v in 0..n {
        let tol = 1e-5 * (1.0 + b[v].length());
        assert!(
            (a[v] - b[v]).length() < tol,
            "vertex {v}: {} vs {}",
            a[v],
            b[v]
        );
        assert!(
            (an[v] - bn[v]).length() < 1e-5 * (1.0 + bn[v].length()),
            "normal {v}"
        );
        let w = &input.skin.weights()[v];
        let js = input.skin.joints()[v].map(|j| dq[j as usize]);
        let r = dqs_vertex(&js, w, input.positions[v]);
        assert!(
            (b[v] - r).length() < tol,
            "vertex {v}: {} vs dqs_vertex {r}",
            b[v]
        );
    }
    // A bad input is refused by the switch as by skin_dqs.
    let mut short = vec![Vec3::ZERO; n - 1];
    let e = skin_dqs_with(
        LbsKernel::Portable,
        &dq,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut short,
        bn,
    );
    assert!(
        matches!(e, Err(SkinningError::LengthMismatch { .. })),
        "{e:?}"
    );
}

/// Positions-only LBS gives the positions of the portable LBS kernel bit for bit, and checks its
/// input as `skin_lbs` does.
#[test]
fn positions_only_lbs_matches_the_full_kernel() {
    let input = inbetween::skinning::rigs::benchmark_input(1003, 11);
    let n = input.positions.len();
    let (mut p, mut pn, mut q) = (
        vec![Vec3::ZERO; n],
        vec![Vec3::ZERO; n],
        vec![Vec3::ZERO; n],
    );
    skin_lbs_with(
        LbsKernel::Portable,
        &input.palette,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut p,
        &mut pn,
    )
    .unwrap();
    skin_lbs_positions(&input.palette, &input.skin, &input.positions, &mut q).unwrap();
    for v in 0..n {
        assert_eq!(
            p[v].to_array().map(f32::to_bits),
            q[v].to_array().map(f32::to_bits),
            "{v}"
        );
    }
    let e = skin_lbs_positions(&input.palette[..3], &input.skin, &input.positions, &mut q);
    assert!(
        matches!(e, Err(SkinningError::JointOutOfRange { .. })),
        "{e:?}"
    );
    let e = skin_lbs_positions(&input.palette, &input.skin, &input.positions[1..], &mut q);
    assert!(
        matches!(e, Err(SkinningError::LengthMismatch { .. })),
        "{e:?}"
    );
}

#[test]
fn lbs_candy_wrapper_at_a_half_turn_and_dqs_keeps_the_ring() {
    let rig = rig();
    let skin = rig.weights(0.2).unwrap();
    let s = skin_both(&rig, &skin, 0.0, PI);
    let lbs = elbow_area(&rig, &s.lbs);
    let dqs = elbow_area(&rig, &s.dqs);
    assert!(
        lbs < 0.01,
        "LBS elbow ring at 180° twist keeps {lbs} of its area"
    );
    assert!(
        (dqs - 1.0).abs() < 1e-3,
        "DQS elbow ring keeps {dqs} of its area"
    );
    // And the LBS distance to the elbow shrinks to zero there.
    let elbow = Vec3::new(1.0, 0.0, 0.0);
    let start = rig.ring_start(rig.elbow_ring());
    assert!((s.lbs[start] - elbow).length() < 1e-3);
}

#[test]
fn lbs_collapses_more_than_dqs_at_a_bend() {
    let rig = rig();
    let skin = rig.weights(0.2).unwrap();
    let rest_volume = mesh_volume(&rig.mesh.positions, &rig.mesh.indices);
    let exact = PI * 0.25 * 0.25 * 2.0;
    assert!(
        (rest_volume - exact).abs() / exact < 0.02,
        "{rest_volume} vs {exact}"
    );
    let mut last_lbs = f32::INFINITY;
    for deg in [30.0f32, 60.0, 90.0, 120.0, 150.0] {
        let s = skin_both(&rig, &skin, deg.to_radians(), 0.0);
        let (a_lbs, a_dqs) = (elbow_area(&rig, &s.lbs), elbow_area(&rig, &s.dqs));
        let v_lbs = mesh_volume(&s.lbs, &rig.mesh.indices) / rest_volume;
        let v_dqs = mesh_volume(&s.dqs, &rig.mesh.indices) / rest_volume;
        assert!(
            a_lbs < a_dqs,
            "{deg}°: elbow area LBS {a_lbs} vs DQS {a_dqs}"
        );
        assert!(v_lbs < v_dqs, "{deg}°: volume LBS {v_lbs} vs DQS {v_dqs}");
        assert!(a_lbs < last_lbs, "LBS area shrinks as the bend grows");
        last_lbs = a_lbs;
        // LBS at a bend of θ scales the elbow ring's in-plane axis by cos(θ/2).
        let expected = (deg.to_radians() / 2.0).cos();
        assert!(
            (a_lbs - expected).abs() < 0.02,
            "{deg}°: {a_lbs} vs cos(θ/2) = {expected}"
        );
    }
}

#[test]
fn automatic_weights_blend_at_the_elbow_and_stay_rigid_far_from_it() {
    let rig = rig();
    for falloff in [0.02f32, 0.1, 0.5] {
        let skin = rig.weights(falloff).unwrap();
        for (v, w) in skin.weights().iter().enumerate() {
            let sum: f32 = w.iter().sum();
            assert!(
                (sum - 1.0).abs() < 1e-5 && w.iter().all(|&x| x >= 0.0),
                "vertex {v}"
            );
        }
        let e = rig.ring_start(rig.elbow_ring());
        assert!((skin.weight_of(e, 0) - 0.5).abs() < 1e-5);
        if falloff <= 0.1 {
            assert!(
                skin.weight_of(0, 0) > 0.999,
                "the shoulder end follows the shoulder"
            );
        }
    }
    // A wider falloff spreads the blend: a vertex a little past the elbow keeps more shoulder.
    let near = rig.ring_start(rig.elbow_ring() + 2);
    let narrow = rig.weights(0.02).unwrap().weight_of(near, 0);
    let wide = rig.weights(0.5).unwrap().weight_of(near, 0);
    assert!(narrow < wide && wide < 0.5, "{narrow} < {wide} < 0.5");
    assert!(matches!(
        rig.weights(0.0),
        Err(SkinningError::BadParameter(_))
    ));
    assert!(matches!(
        rig.weights(f32::NAN),
        Err(SkinningError::BadParameter(_))
    ));
    // At most four influences even with many candidates.
    let segs: Vec<(Vec3, Vec3)> = (0..10)
        .map(|i| (Vec3::X * i as f32, Vec3::X * i as f32))
        .collect();
    let s = auto_weights(&[Vec3::new(4.5, 0.0, 0.0)], &segs, 10.0, |_| 0..10).unwrap();
    let mut j = s.joints()[0];
    j.sort();
    assert_eq!(j, [3, 4, 5, 6]);
}

#[test]
fn human_body_weights_follow_parts_and_neighbours() {
    let human = skinned_human(0.03).unwrap();
    assert_eq!(human.skin.len(), human.mesh.positions.len());
    assert_eq!(human.colors.len(), human.mesh.positions.len());
    let parents = human.skeleton.parents();
    // Two joints one vertex follows are at most two steps apart in the tree (a part, its parent
    // and its children), so the side of the chest never follows the upper arm.
    let near = |a: usize, b: usize| {
        let up = |j: usize| parents[j];
        a == b
            || up(a) == b as i32
            || up(b) == a as i32
            || (up(a) >= 0 && up(a) == up(b))
            || (up(a) >= 0 && up(up(a) as usize) == b as i32)
            || (up(b) >= 0 && up(up(b) as usize) == a as i32)
    };
    let spine = human.skeleton.find("spine").unwrap();
    let arm = human.skeleton.find("upper_arm.L").unwrap();
    for (v, (j, w)) in human
        .skin
        .joints()
        .iter()
        .zip(human.skin.weights())
        .enumerate()
    {
        let used: Vec<usize> = (0..4)
            .filter(|&k| w[k] > 1e-4)
            .map(|k| j[k] as usize)
            .collect();
        for &a in &used {
            for &b in &used {
                assert!(near(a, b), "vertex {v} follows joints {a} and {b}");
            }
        }
        assert!(!(used.contains(&spine) && used.contains(&arm)));
    }
    // Somewhere the parts blend: some vertices follow two joints.
    let blended = human.skin.weights().iter().filter(|w| w[1] > 0.1).count();
    assert!(blended > 50, "{blended} blended vertices");
    assert!(matches!(
        skinned_human(-1.0),
        Err(SkinningError::BadParameter(_))
    ));
}

#[test]
fn dual_quat_blend_takes_the_short_way() {
    let q =
        DualQuat::from_rotation_translation(Quat::from_rotation_y(0.3), Vec3::new(1.0, 2.0, 0.0));
    let neg = q * -1.0;
    // q and −q are one motion; without the sign fix they would cancel.
    let b = blend_dual_quats(&[q, neg], &[0.5, 0.5]);
    let p = Vec3::new(0.3, -0.2, 1.0);
    assert!((b.transform_point(p) - q.transform_point(p)).length() < 1e-5);
    // Blending the identity with a quarter turn gives an eighth turn.
    let quarter = DualQuat::from_rotation(Quat::from_rotation_z(PI / 2.0));
    let half = blend_dual_quats(&[DualQuat::IDENTITY, quarter * -1.0], &[0.5, 0.5]);
    let x = half.transform_point(Vec3::X);
    assert!(
        (x - Vec3::new((PI / 4.0).cos(), (PI / 4.0).sin(), 0.0)).length() < 1e-5,
        "{x}"
    );
    // dqs_vertex and lbs_vertex on one joint agree with the matrix.
    let m = Mat4::from_rotation_translation(Quat::from_rotation_x(1.0), Vec3::ONE);
    let dq = DualQuat::from_rotation_translation(Quat::from_rotation_x(1.0), Vec3::ONE);
    assert!((lbs_vertex(&[m], &[1.0], p) - m.transform_point3(p)).length() < 1e-5);
    assert!((dqs_vertex(&[dq], &[1.0], p) - m.transform_point3(p)).length() < 1e-5);
}

#[test]
fn lbs_vertex_matches_the_fast_kernel() {
    let rig = rig();
    let skin = rig.weights(0.2).unwrap();
    let s = skin_both(&rig, &skin, 1.2, 0.7);
    let mut model = vec![Affine3A::IDENTITY; 3];
    let mut palette = vec![Affine3A::IDENTITY; 3];
    rig.palette(1.2, 0.7, &mut model, &mut palette).unwrap();
    for v in (0..rig.mesh.positions.len()).step_by(17) {
        let mats: Vec<Mat4> = skin.joints()[v]
            .iter()
            .map(|&j| Mat4::from(palette[j as usize]))
            .collect();
        let p = lbs_vertex(&mats, &skin.weights()[v], rig.mesh.positions[v]);
        assert!((p - s.lbs[v]).length() < 1e-5);
    }
}

#[test]
fn cylinder_rig_rejects_bad_sizes() {
    assert!(cylinder_rig(1.0, 0.2, 40, 16).is_err());
    assert!(cylinder_rig(1.0, 0.2, 41, 2).is_err());
    assert!(cylinder_rig(-1.0, 0.2, 41, 16).is_err());
    assert!(cylinder_rig(1.0, f32::NAN, 41, 16).is_err());
    assert!(cylinder_rig(1.0, 0.2, 1001, 16).is_err());
}

#[test]
fn the_benchmark_kernels_agree() {
    use inbetween::skinning::rigs::benchmark_input;
    use inbetween::skinning::skin_lbs_plain_loop;
    let input = benchmark_input(500, 9);
    let n = input.positions.len();
    let (mut p, mut nn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    skin_lbs(
        &input.palette,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut p,
        &mut nn,
    )
    .unwrap();
    let (pal, j, w, pos, nrm) = input.flat();
    let (mut fp, mut fn_) = (vec![0.0; 3 * n], vec![0.0; 3 * n]);
    skin_lbs_plain_loop(&pal, &j, &w, &pos, &nrm, &mut fp, &mut fn_);
    for v in 0..n {
        assert!(
            (Vec3::from_slice(&fp[3 * v..]) - p[v]).length() < 1e-4,
            "vertex {v}"
        );
        assert!(
            (Vec3::from_slice(&fn_[3 * v..]) - nn[v]).length() < 1e-4,
            "normal {v}"
        );
    }
    let mut dq = vec![DualQuat::IDENTITY; input.palette.len()];
    dual_quat_palette(&input.palette, &mut dq).expect("the benchmark pose is rigid");
    skin_dqs(
        &dq,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut p,
        &mut nn,
    )
    .unwrap();
    assert!(p.iter().all(|x| x.is_finite()));
}
