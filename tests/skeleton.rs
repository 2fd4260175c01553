//! Skeleton core (lesson 06): validation (one failing input per rule), group sizes, the
//! local-to-model pass against the inverse bind matrices, clip sampling (keys, loops, both
//! forms), and blending identities.

use glam::{Affine3A, EulerRot, Mat4, Quat, Vec3, Vec4};
use inbetween::curves::Track;
use inbetween::fixtures::Rng;
use inbetween::skeleton::{
    add_additive, blend_weighted, crossfade, crossfade_masked, human, local_to_model,
    make_additive, sample_rotation_channel, subtree_mask, trs_to_affine, BlendError, Clip,
    ClipCursor, ClipError, JointTracks, KeyInterpolation, Pose, QuatInterpolation, RawClip,
    ScaleMode, Skeleton, SkeletonError, Transform,
};

fn names(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("j{i}")).collect()
}

fn rest(n: usize) -> Vec<Transform> {
    (0..n)
        .map(|i| Transform::from_translation(Vec3::new(0.0, 0.5, 0.1 * i as f32)))
        .collect()
}

fn build(parents: Vec<i32>) -> Result<Skeleton, SkeletonError> {
    let n = parents.len();
    Skeleton::new(names(n), parents, rest(n))
}

#[test]
fn each_validation_rule_has_its_own_error() {
    assert_eq!(
        Skeleton::new(vec![], vec![], vec![]),
        Err(SkeletonError::Empty)
    );
    assert!(matches!(
        Skeleton::new(names(2), vec![-1, 0], rest(3)),
        Err(SkeletonError::LengthMismatch {
            what: "rest transforms",
            expected: 2,
            actual: 3
        })
    ));
    assert_eq!(
        build(vec![-1, 5]),
        Err(SkeletonError::ParentOutOfRange {
            joint: 1,
            parent: 5,
            count: 2
        })
    );
    assert_eq!(
        build(vec![-1, -2]),
        Err(SkeletonError::ParentOutOfRange {
            joint: 1,
            parent: -2,
            count: 2
        })
    );
    assert_eq!(
        build(vec![-1, 2, 1]),
        Err(SkeletonError::Cycle { joint: 1 })
    );
    assert_eq!(
        build(vec![-1, 1]),
        Err(SkeletonError::Cycle { joint: 1 }),
        "its own parent"
    );
    assert_eq!(
        build(vec![-1, 2, 0]),
        Err(SkeletonError::ParentNotBefore {
            joint: 1,
            parent: 2
        })
    );
    let mut dup = names(3);
    dup[2] = "j0".into();
    assert_eq!(
        Skeleton::new(dup, vec![-1, 0, 1], rest(3)),
        Err(SkeletonError::DuplicateName {
            name: "j0".into(),
            first: 0,
            second: 2
        })
    );
    let mut bad = rest(3);
    bad[1].translation.y = f32::NAN;
    assert_eq!(
        Skeleton::new(names(3), vec![-1, 0, 1], bad),
        Err(SkeletonError::NonFinite { joint: 1 })
    );
    let mut bad = rest(3);
    bad[2].scale = Vec3::new(1.0, f32::INFINITY, 1.0);
    assert_eq!(
        Skeleton::new(names(3), vec![-1, 0, 1], bad),
        Err(SkeletonError::NonFinite { joint: 2 })
    );
    let mut bad = rest(2);
    bad[1].rotation = Quat::from_xyzw(0.0, 0.0, 0.0, 2.0);
    assert!(matches!(
        Skeleton::new(names(2), vec![-1, 0], bad),
        Err(SkeletonError::NotUnitRotation { joint: 1, .. })
    ));
    let mut bad = rest(2);
    bad[0].scale = Vec3::new(1.0, 0.0, 1.0);
    assert_eq!(
        Skeleton::new(names(2), vec![-1, 0], bad),
        Err(SkeletonError::SingularBind { joint: 0 })
    );
    // Every message names the joint or the rule.
    let message = build(vec![-1, 2, 0]).unwrap_err().to_string();
    assert!(
        message.contains("joint 1") && message.contains("before"),
        "{message}"
    );
    assert!(
        build(vec![-1, 0, 0, 1, -1, 4]).is_ok(),
        "two roots and siblings"
    );
}

#[test]
fn group_sizes_count_a_joint_and_its_descendants() {
    let s = build(vec![-1, 0, 1, 1, 0, -1]).unwrap();
    assert_eq!(s.group_sizes(), &[5, 3, 1, 1, 1, 1]);
    let (human, _) = human::simple_human();
    assert_eq!(human.len(), 21);
    assert_eq!(human.group_sizes()[0], 21, "the pelvis carries everyone");
    // Depth-first: each group is the contiguous range i .. i + size.
    for i in 0..human.len() {
        for j in 0..human.len() {
            let contiguous = (i..i + human.group_sizes()[i]).contains(&j);
            assert_eq!(
                human.in_group(i, j),
                contiguous,
                "joint {j} in group of {i}"
            );
        }
    }
    let arm = human.find("upper_arm.L").unwrap();
    assert_eq!(human.group_sizes()[arm], 3, "upper arm, forearm, hand");
}

fn affine_close(a: Affine3A, b: Affine3A, eps: f32) -> bool {
    Mat4::from(a).abs_diff_eq(Mat4::from(b), eps)
}

#[test]
fn trs_to_affine_agrees_with_glam() {
    let mut rng = Rng::new(7);
    for _ in 0..200 {
        let t = rng.vec3(-3.0, 3.0);
        let e = rng.vec3(-3.0, 3.0);
        let r = Quat::from_euler(EulerRot::XYZ, e.x, e.y, e.z);
        let s = rng.vec3(0.2, 2.0);
        let expected = Affine3A::from_scale_rotation_translation(s, r, t);
        assert!(affine_close(trs_to_affine(t, r, s), expected, 1e-5));
    }
}

#[test]
fn rest_pose_times_inverse_bind_is_the_identity() {
    let mut rng = Rng::new(11);
    let (human, _) = human::simple_human();
    let (bench, _) = human::benchmark_humanoid(&mut rng);
    // A skeleton with rotated and scaled rest transforms, in both scale modes.
    let mut twisted = rest(6);
    for x in &mut twisted {
        let e = rng.vec3(-2.0, 2.0);
        x.rotation = Quat::from_euler(EulerRot::XYZ, e.x, e.y, e.z);
        x.scale = rng.vec3(0.5, 1.5);
    }
    let twisted = Skeleton::new(names(6), vec![-1, 0, 1, 1, 3, 0], twisted).unwrap();
    let not_inherited = twisted
        .clone()
        .with_scale_mode(ScaleMode::NotInherited)
        .unwrap();
    for s in [human, bench, twisted, not_inherited] {
        let mut model = vec![Affine3A::IDENTITY; s.len()];
        s.model_matrices(&s.rest_pose(), &mut model).unwrap();
        for (m, inv) in model.iter().zip(s.inverse_bind()) {
            assert!(affine_close(*m * *inv, Affine3A::IDENTITY, 1e-4));
        }
    }
}

#[test]
fn local_to_model_is_parent_times_local() {
    let parents = [-1, 0, 1, 0];
    let local: Vec<Transform> = (0..4)
        .map(|i| Transform {
            translation: Vec3::new(0.0, 1.0, 0.0),
            rotation: Quat::from_rotation_z(0.3 * i as f32),
            scale: Vec3::new(1.0, 2.0, 1.0),
        })
        .collect();
    let mut model = vec![Affine3A::IDENTITY; 4];
    local_to_model(&parents, &local, ScaleMode::Inherited, &mut model);
    let m: Vec<Mat4> = local.iter().map(|x| x.to_mat4()).collect();
    assert!(Mat4::from(model[2]).abs_diff_eq(m[0] * m[1] * m[2], 1e-5));
    assert!(Mat4::from(model[3]).abs_diff_eq(m[0] * m[3], 1e-5));
    // Not inherited: children see the parent's unscaled frame.
    local_to_model(&parents, &local, ScaleMode::NotInherited, &mut model);
    let tr = |x: &Transform| Mat4::from_rotation_translation(x.rotation, x.translation);
    let s = Mat4::from_scale(local[2].scale);
    assert!(
        Mat4::from(model[2]).abs_diff_eq(tr(&local[0]) * tr(&local[1]) * tr(&local[2]) * s, 1e-5)
    );
}

fn small_clip(looping: bool) -> (Skeleton, RawClip) {
    let s = build(vec![-1, 0, 1]).unwrap();
    let times = vec![0.0, 0.5, 1.0, 2.0];
    let rot = [
        Quat::IDENTITY,
        Quat::from_rotation_x(1.2),
        Quat::from_rotation_y(-2.0),
        Quat::IDENTITY,
    ];
    let tracks = vec![
        JointTracks {
            translation: Track::new(
                times.clone(),
                vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::ZERO],
            )
            .ok(),
            ..Default::default()
        },
        JointTracks {
            // Different key times on another channel: the runtime form merges them.
            rotation: JointTracks::rotation_track(vec![0.0, 0.7, 2.0], &[rot[0], rot[1], rot[0]])
                .ok(),
            scale: Track::new(vec![0.0, 2.0], vec![Vec3::ONE, Vec3::splat(2.0)]).ok(),
            ..Default::default()
        },
        JointTracks {
            rotation: JointTracks::rotation_track(times.clone(), &rot).ok(),
            ..Default::default()
        },
    ];
    (s, RawClip::new("test", 2.0, looping, tracks).unwrap())
}

fn pose_close(a: &Pose, b: &Pose, eps: f32) -> bool {
    a.local.iter().zip(&b.local).all(|(x, y)| {
        x.translation.abs_diff_eq(y.translation, eps)
            && x.scale.abs_diff_eq(y.scale, eps)
            && (x.rotation.dot(y.rotation).abs() - 1.0).abs() < eps
    })
}

#[test]
fn sampling_at_key_times_returns_the_keys() {
    let (s, mut raw) = small_clip(false);
    for interpolation in [
        KeyInterpolation::Step,
        KeyInterpolation::Linear,
        KeyInterpolation::Cubic,
    ] {
        for q in [QuatInterpolation::Nlerp, QuatInterpolation::Slerp] {
            raw.set_interpolation(interpolation);
            raw.set_rotation_interpolation(q);
            let clip = Clip::from_raw(&raw, &s).unwrap();
            assert_eq!(clip.key_times(), &[0.0, 0.5, 0.7, 1.0, 2.0]);
            let mut pose = s.rest_pose();
            let mut cursor = ClipCursor::new();
            for (k, &t) in clip.key_times().iter().enumerate() {
                clip.sample(t, &mut cursor, &mut pose);
                for j in 0..s.len() {
                    let key = clip.key(k, j);
                    assert!(pose.local[j].translation.abs_diff_eq(key.translation, 1e-6));
                    assert!(
                        pose.local[j].rotation.abs_diff_eq(key.rotation, 1e-6),
                        "{interpolation:?} {q:?} key {k} joint {j}"
                    );
                }
            }
            // And the editable form passes through its own keys.
            let track = raw.joints()[2].rotation.as_ref().unwrap();
            let mut cursors = raw.cursors();
            for (k, &t) in track.times().iter().enumerate() {
                raw.sample(t, s.rest(), &mut cursors, &mut pose);
                let key = Quat::from_vec4(track.values()[k]);
                assert!((pose.local[2].rotation.dot(key).abs() - 1.0).abs() < 1e-6);
            }
        }
    }
}

#[test]
fn runtime_and_editable_forms_agree_between_keys() {
    let (s, mut raw) = small_clip(true);
    for q in [QuatInterpolation::Nlerp, QuatInterpolation::Slerp] {
        for interpolation in [KeyInterpolation::Step, KeyInterpolation::Linear] {
            raw.set_interpolation(interpolation);
            raw.set_rotation_interpolation(q);
            let clip = Clip::from_raw(&raw, &s).unwrap();
            let (mut a, mut b) = (s.rest_pose(), s.rest_pose());
            let mut cursor = ClipCursor::new();
            let mut cursors = raw.cursors();
            for k in 0..400 {
                let t = k as f32 * 0.01;
                clip.sample(t, &mut cursor, &mut a);
                raw.sample(t, s.rest(), &mut cursors, &mut b);
                // Joint 1's rotation gained a key at 0.5 and 1.0: exact for slerp and step,
                // within a small nlerp resampling error otherwise.
                let eps =
                    if q == QuatInterpolation::Nlerp && interpolation == KeyInterpolation::Linear {
                        2e-2
                    } else {
                        1e-5
                    };
                assert!(pose_close(&a, &b, eps), "{interpolation:?} {q:?} t = {t}");
            }
        }
    }
    // The built-in clips key every channel at the same times: the forms agree for cubic too.
    let (human, _) = human::simple_human();
    for index in 0..human::CLIP_NAMES.len() {
        let mut raw = human::clip(&human, index).unwrap();
        raw.set_interpolation(KeyInterpolation::Cubic);
        let clip = Clip::from_raw(&raw, &human).unwrap();
        let (mut a, mut b) = (human.rest_pose(), human.rest_pose());
        let (mut cursor, mut cursors) = (ClipCursor::new(), raw.cursors());
        for k in 0..100 {
            let t = k as f32 * 0.037;
            clip.sample(t, &mut cursor, &mut a);
            raw.sample(t, human.rest(), &mut cursors, &mut b);
            assert!(pose_close(&a, &b, 1e-4), "clip {index} t = {t}");
        }
    }
}

#[test]
fn looping_clips_are_seamless_and_wrap() {
    let (human, _) = human::simple_human();
    for index in 0..human::CLIP_NAMES.len() {
        let raw = human::clip(&human, index).unwrap();
        for interpolation in [KeyInterpolation::Linear, KeyInterpolation::Cubic] {
            let mut clip = Clip::from_raw(&raw, &human).unwrap();
            clip.set_interpolation(interpolation);
            let d = clip.duration_sec();
            let (mut start, mut end, mut later) =
                (human.rest_pose(), human.rest_pose(), human.rest_pose());
            let mut cursor = ClipCursor::new();
            clip.sample(0.0, &mut cursor, &mut start);
            clip.sample(d - 1e-4, &mut cursor, &mut end);
            assert!(
                pose_close(&start, &end, 2e-3),
                "clip {index}: end meets start"
            );
            clip.sample(0.3, &mut cursor, &mut start);
            clip.sample(0.3 + 3.0 * d, &mut cursor, &mut later);
            assert!(pose_close(&start, &later, 1e-4), "clip {index}: periodic");
        }
    }
    // A non-looping clip clamps.
    let (s, raw) = small_clip(false);
    let clip = Clip::from_raw(&raw, &s).unwrap();
    let (mut a, mut b) = (s.rest_pose(), s.rest_pose());
    let mut cursor = ClipCursor::new();
    clip.sample(2.0, &mut cursor, &mut a);
    clip.sample(7.0, &mut cursor, &mut b);
    assert!(pose_close(&a, &b, 1e-6));
    clip.sample(f32::NAN, &mut cursor, &mut b);
    assert!(b.local.iter().all(|x| x.is_finite()), "NaN time reads as 0");
}

#[test]
fn rotation_channel_sampling_with_slerp() {
    let times = [0.0, 1.0, 3.0];
    let keys = [
        Quat::IDENTITY,
        Quat::from_rotation_z(1.0),
        -Quat::from_rotation_z(2.0),
    ];
    let at = |t| sample_rotation_channel(&times, &keys, t, QuatInterpolation::Slerp);
    assert_eq!(at(-1.0), keys[0]);
    assert_eq!(at(5.0), keys[2]);
    assert!(at(0.5).abs_diff_eq(Quat::from_rotation_z(0.5), 1e-6));
    // Across the sign flip of the last key: the short arc, at constant speed.
    assert!((at(2.0).dot(Quat::from_rotation_z(1.5)).abs() - 1.0).abs() < 1e-6);
    let nl = sample_rotation_channel(&times, &keys, 0.25, QuatInterpolation::Nlerp);
    let angle = nl.angle_between(Quat::IDENTITY);
    assert!(
        angle < 0.25 && angle > 0.2,
        "nlerp lags near the ends of a segment: {angle}"
    );
}

#[test]
fn clip_validation() {
    let (s, raw) = small_clip(false);
    assert!(matches!(
        RawClip::new("x", 0.0, false, vec![]),
        Err(ClipError::BadDuration { .. })
    ));
    assert!(matches!(
        RawClip::new("x", f32::NAN, false, vec![]),
        Err(ClipError::BadDuration { .. })
    ));
    let late = JointTracks {
        translation: Track::new(vec![0.0, 3.0], vec![Vec3::ZERO, Vec3::X]).ok(),
        ..Default::default()
    };
    assert!(matches!(
        RawClip::new("x", 2.0, false, vec![late]),
        Err(ClipError::KeyOutsideDuration {
            joint: 0,
            channel: "translation",
            ..
        })
    ));
    let zero = JointTracks {
        rotation: Track::new(vec![0.0], vec![Vec4::ZERO]).ok(),
        ..Default::default()
    };
    assert!(matches!(
        RawClip::new("x", 2.0, false, vec![zero]),
        Err(ClipError::ZeroRotation { joint: 0, key: 0 })
    ));
    let other = build(vec![-1, 0]).unwrap();
    assert!(matches!(
        Clip::from_raw(&raw, &other),
        Err(ClipError::JointCount {
            expected: 2,
            actual: 3
        })
    ));
    assert!(Clip::from_raw(&raw, &s).is_ok());
}

fn random_pose(rng: &mut Rng, n: usize) -> Pose {
    Pose {
        local: (0..n)
            .map(|_| {
                let e = rng.vec3(-3.0, 3.0);
                Transform {
                    translation: rng.vec3(-1.0, 1.0),
                    rotation: Quat::from_euler(EulerRot::XYZ, e.x, e.y, e.z),
                    scale: rng.vec3(0.5, 2.0),
                }
            })
            .collect(),
    }
}

#[test]
fn blend_weights_zero_and_one_return_an_input() {
    let mut rng = Rng::new(3);
    let (a, b) = (random_pose(&mut rng, 8), random_pose(&mut rng, 8));
    let mut out = Pose::identity(8);
    crossfade(&a, &b, 0.0, &mut out).unwrap();
    assert_eq!(out, a);
    crossfade(&a, &b, 1.0, &mut out).unwrap();
    assert_eq!(out, b);
    blend_weighted(&[&a, &b], &[0.0, 3.0], &mut out).unwrap();
    assert!(pose_close(&out, &b, 1e-5));
    blend_weighted(&[&a, &b, &a], &[1.0, 0.0, 0.0], &mut out).unwrap();
    assert!(pose_close(&out, &a, 1e-5));
    // Hemisphere alignment: -q is the same rotation and must not cancel.
    let mut flipped = a.clone();
    for x in &mut flipped.local {
        x.rotation = -x.rotation;
    }
    blend_weighted(&[&a, &flipped], &[0.5, 0.5], &mut out).unwrap();
    assert!(pose_close(&out, &a, 1e-5));
    // Masks: 0 keeps a, 1 takes b, joint by joint.
    let (human, _) = human::simple_human();
    let (c, d) = (random_pose(&mut rng, 21), random_pose(&mut rng, 21));
    let mask = subtree_mask(&human, human.find("spine").unwrap(), 1.0, 0.0);
    let mut out = Pose::identity(21);
    crossfade_masked(&c, &d, &mask, &mut out).unwrap();
    for (j, &w) in mask.iter().enumerate() {
        let expected = if w == 1.0 { d.local[j] } else { c.local[j] };
        assert_eq!(out.local[j], expected);
    }
    assert_eq!(
        mask.iter().filter(|&&w| w == 1.0).count(),
        12,
        "spine, chest, neck, head, arms"
    );
    // Additive: difference then add back gives the pose; weight 0 gives the base.
    let mut delta = Pose::identity(8);
    make_additive(&b, &a, &mut delta).unwrap();
    let mut out8 = Pose::identity(8);
    add_additive(&a, &delta, 1.0, &mut out8).unwrap();
    assert!(pose_close(&out8, &b, 1e-4));
    add_additive(&a, &delta, 0.0, &mut out8).unwrap();
    assert!(pose_close(&out8, &a, 1e-5));
}

#[test]
fn blend_errors_name_the_problem() {
    let (a, b) = (Pose::identity(3), Pose::identity(4));
    let mut out = Pose::identity(3);
    assert!(matches!(
        crossfade(&a, &b, 0.5, &mut out),
        Err(BlendError::LengthMismatch { .. })
    ));
    assert_eq!(
        crossfade(&a, &a, 1.5, &mut out),
        Err(BlendError::BadWeight {
            index: 0,
            weight: 1.5
        })
    );
    assert!(matches!(
        crossfade(&a, &a, f32::NAN, &mut out),
        Err(BlendError::BadWeight { .. })
    ));
    assert_eq!(blend_weighted(&[], &[], &mut out), Err(BlendError::NoPoses));
    assert_eq!(
        blend_weighted(&[&a, &a], &[0.0, 0.0], &mut out),
        Err(BlendError::ZeroTotalWeight)
    );
    assert!(matches!(
        blend_weighted(&[&a, &a], &[-1.0, 2.0], &mut out),
        Err(BlendError::BadWeight { index: 0, .. })
    ));
    assert!(matches!(
        crossfade_masked(&a, &a, &[0.5; 2], &mut out),
        Err(BlendError::LengthMismatch { .. })
    ));
}
