//! Lesson 06 figure logic: validation messages, what the controls change, the plot samples, and
//! what the note says about the student's exercises (with a correct, a wrong and a panicking
//! runner).

use glam::{Mat4, Quat, Vec3};
use inbetween::draw::{palette, Frame, MARKER_TICK, ON_TOP};
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::skeleton::SkeletonFigure;

fn positions(f: &SkeletonFigure) -> Vec<Vec3> {
    (0..f.skeleton().len())
        .map(|j| f.joint_position(j).unwrap())
        .collect()
}

#[test]
fn bad_input_is_an_error_naming_the_parameter() {
    let mut f = SkeletonFigure::new();
    assert!(f.select(99).unwrap_err().contains("joint index 99"));
    let e = f
        .set_joint_angles_deg(0, Vec3::new(f32::NAN, 0.0, 0.0))
        .unwrap_err();
    assert!(e.contains("angle x"), "{e}");
    assert!(f
        .set_joint_angles_deg(0, Vec3::new(0.0, 500.0, 0.0))
        .unwrap_err()
        .contains("angle y"));
    assert!(f
        .set_keys_per_cycle(1.0)
        .unwrap_err()
        .contains("keys per cycle"));
    assert!(f.set_keys_per_cycle(f32::INFINITY).is_err());
    assert!(f
        .set_interpolation("bezier")
        .unwrap_err()
        .contains("interpolation"));
    assert!(f
        .set_rotation_interpolation("squad")
        .unwrap_err()
        .contains("rotation"));
    assert!(f.set_clip("dance").unwrap_err().contains("clip"));
    assert!(f.pose(f32::NAN).unwrap_err().contains("time"));
    assert!(f.sample_selected(1).is_err());
    assert!(f.sample_selected(100_000).is_err());
}

#[test]
fn the_clip_moves_the_skeleton_and_offsets_move_a_group() {
    let mut f = SkeletonFigure::new();
    f.pose(0.0).unwrap();
    let at0 = positions(&f);
    f.pose(0.3).unwrap();
    let at03 = positions(&f);
    let knee = f.skeleton().find("shin.L").unwrap();
    assert!(
        at0[knee].distance(at03[knee]) > 0.02,
        "the walk moves the knee"
    );
    // An offset on the left thigh moves exactly the thigh's group (not the thigh's own pivot).
    // Only the names the dropdown lists are clips: a name that merely starts like one is refused
    // and leaves the clip as it was.
    let e = f.set_clip("none-of-these").unwrap_err();
    assert!(e.contains("no clip named \"none-of-these\""), "{e}");
    assert_ne!(f.clip_name(), "none (rest pose)");
    f.set_clip("none (rest pose)").unwrap();
    f.pose(0.0).unwrap();
    let rest = positions(&f);
    let thigh = f.skeleton().find("thigh.L").unwrap();
    f.set_joint_angles_deg(thigh, Vec3::new(-40.0, 0.0, 0.0))
        .unwrap();
    f.pose(0.0).unwrap();
    let bent = positions(&f);
    for j in 0..rest.len() {
        let moved = rest[j].distance(bent[j]) > 1e-4;
        let below = f.skeleton().in_group(thigh, j) && j != thigh;
        assert_eq!(moved, below, "joint {j}");
    }
    f.reset_pose();
    f.pose(0.0).unwrap();
    assert_eq!(positions(&f), rest);
}

#[test]
fn interpolation_choices_change_the_pose_between_keys_only() {
    let mut f = SkeletonFigure::new();
    f.set_clip("arm circles").unwrap();
    f.set_keys_per_cycle(4.0).unwrap();
    let times = f.key_times();
    assert_eq!(times.len(), 4);
    let thigh = f.skeleton().find("upper_arm.L").unwrap();
    let angle = |f: &mut SkeletonFigure, t: f32| {
        f.pose(t).unwrap();
        let m = f.local_matrix(thigh).unwrap();
        Quat::from_mat4(&m)
    };
    let mut results = Vec::new();
    for (interp, rot) in [
        ("step", "slerp"),
        ("linear", "nlerp"),
        ("linear", "slerp"),
        ("cubic", "slerp"),
    ] {
        f.set_interpolation(interp).unwrap();
        f.set_rotation_interpolation(rot).unwrap();
        results.push((angle(&mut f, times[1]), angle(&mut f, 0.3 * times[1])));
    }
    for r in &results[1..] {
        assert!(r.0.abs_diff_eq(results[0].0, 1e-5), "all agree at a key");
    }
    for a in 0..results.len() {
        for b in a + 1..results.len() {
            assert!(
                results[a].1.angle_between(results[b].1) > 1e-4,
                "{a} vs {b} differ between keys"
            );
        }
    }
}

#[test]
fn the_note_gives_the_time_and_the_fraction_in_fixed_decimals() {
    // A timeline back at its start passes times such as 4.4e-16 s.
    let mut f = SkeletonFigure::new();
    let note = f.draw(&mut Frame::default(), 4.441e-16).unwrap();
    assert!(
        note.contains("at 0.000 s: between keys 0 and 1 (s = 0.000)"),
        "{note}"
    );
}

#[test]
fn the_drawing_highlights_the_selected_joint_and_its_group() {
    let mut f = SkeletonFigure::new();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, 0.2).unwrap();
    assert!(
        note.contains("Joint 13 (thigh.L)") && note.contains("group of 4 joints"),
        "{note}"
    );
    let orange = frame
        .meshes
        .iter()
        .filter(|m| m.color.truncate() == palette::ORANGE)
        .count();
    let teal = frame
        .meshes
        .iter()
        .filter(|m| m.color.truncate() == palette::TEAL)
        .count();
    assert_eq!(orange, 1, "one selected joint");
    assert_eq!(teal, 6, "three group joints and their three bones");
    assert_eq!(f.trail().len(), 61, "a dot per time step over one cycle");
    f.select(0).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, 0.2).unwrap();
    assert!(
        note.contains("parent none (the root)") && note.contains("group of 21"),
        "{note}"
    );
    // With body boxes (which hide the balls and bones inside them), the run's spine and its
    // group are dots drawn over everything, orange and teal, and the group's bones lines on top.
    f.set_clip("run").unwrap();
    f.set_show_boxes(true);
    let spine = f.skeleton().find("spine").unwrap();
    f.select(spine).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, 0.2).unwrap();
    let at = positions(&f);
    for (j, &p) in at.iter().enumerate() {
        let color = if j == spine {
            palette::ORANGE
        } else if f.skeleton().in_group(spine, j) {
            palette::TEAL
        } else {
            continue;
        };
        let on_top = frame.markers.iter().any(|m| {
            m.size_px < 0.0
                && Vec3::from(m.center).distance(p) < 1e-5
                && glam::Vec4::from(m.color).truncate() == color
        });
        assert!(on_top, "joint {j} has no dot over the boxes");
    }
    let bones = frame
        .strokes
        .iter()
        .filter(|s| s.depth_bias == ON_TOP && glam::Vec4::from(s.color).truncate() == palette::TEAL)
        .count();
    assert!(bones >= 10, "{bones} teal bones over the boxes");
}

#[test]
fn plot_samples_follow_the_interpolation() {
    let mut f = SkeletonFigure::new();
    f.set_clip("arm circles").unwrap();
    f.select(f.skeleton().find("upper_arm.L").unwrap()).unwrap();
    f.set_keys_per_cycle(4.0).unwrap();
    let linear_slerp = f.sample_selected(301).unwrap();
    assert_eq!(linear_slerp.len(), 7 * 301);
    f.set_interpolation("linear (nlerp)").unwrap();
    let linear_nlerp = f.sample_selected(301).unwrap();
    assert_ne!(linear_slerp, linear_nlerp);
    // Slerp turns at constant speed inside a segment: the speed's spread within the first
    // segment (t in (0.02, 0.6), keys 120° apart) is tiny for slerp, larger for nlerp.
    let spread = |v: &[f32]| {
        let s: Vec<f32> = v
            .chunks(7)
            .filter(|c| c[0] > 0.02 && c[0] < 0.6)
            .map(|c| c[2])
            .collect();
        s.iter().cloned().fold(f32::MIN, f32::max) - s.iter().cloned().fold(f32::MAX, f32::min)
    };
    assert!(spread(&linear_slerp) < 0.5, "{}", spread(&linear_slerp));
    assert!(spread(&linear_nlerp) > 10.0, "{}", spread(&linear_nlerp));
}

#[test]
fn the_note_reports_the_students_exercises() {
    let mut f = SkeletonFigure::new();
    f.set_use_exercise(true);
    let note = f.pose(0.3).unwrap();
    if cfg!(feature = "solutions") {
        assert!(
            note.contains("Your sample_rotation_slerp matches the reference"),
            "{note}"
        );
        assert!(
            note.contains("Your local_to_model matches the reference at all 21 joints"),
            "{note}"
        );
    } else {
        assert!(note.contains("Not done yet: exercise 6.2"), "{note}");
        assert!(note.contains("Not done yet: exercise 6.1"), "{note}");
    }
    // A wrong local_to_model: every matrix the identity.
    fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        match name {
            "local_to_model" => {
                let n = args[0] as usize;
                let mut out = vec![n as f32];
                for _ in 0..n {
                    out.extend_from_slice(&Mat4::IDENTITY.to_cols_array());
                }
                Ok(out)
            }
            "sample_rotation_slerp" => Ok(vec![0.0, 0.0, 0.0, 1.0]),
            _ => direct(name, args),
        }
    }
    f.set_runner(wrong);
    let note = f.pose(0.3).unwrap();
    assert!(
        note.contains("Your local_to_model differs at joint 0 (pelvis)"),
        "{note}"
    );
    assert!(
        note.contains("Your sample_rotation_slerp differs at t = 0.300 s (thigh.L)"),
        "{note}"
    );
    fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
        Err(Failure::Panicked(
            "panicked at src/exercises/skeleton.rs:60:5:\nboom".into(),
        ))
    }
    f.set_runner(panics);
    let note = f.pose(0.3).unwrap();
    assert!(
        note.contains(
            "Your exercise 6.1 local_to_model panicked at src/exercises/skeleton.rs:60:5: boom"
        ),
        "{note}"
    );
    // Outside linear + slerp, 6.2 is not run and the note says how to run it.
    f.set_interpolation("step").unwrap();
    assert!(f.pose(0.3).unwrap().contains("Switch to linear with slerp"));
}

#[test]
fn crossfading_a_second_clip() {
    let mut f = SkeletonFigure::new();
    f.pose(0.25).unwrap();
    let walk = positions(&f);
    f.set_blend("run", 0.0).unwrap();
    f.pose(0.25).unwrap();
    assert_eq!(positions(&f), walk, "weight 0: the main clip");
    f.set_blend("run", 1.0).unwrap();
    let note = f.pose(0.25).unwrap();
    assert!(
        note.contains("Crossfaded with run at weight 1.000"),
        "{note}"
    );
    let run_at_phase = positions(&f);
    // Weight 1 is the run alone, at the same phase (0.25 s of a 1 s walk = 0.175 s of a 0.7 s run).
    let mut g = SkeletonFigure::new();
    g.set_clip("run").unwrap();
    g.pose(0.175).unwrap();
    for (a, b) in run_at_phase.iter().zip(positions(&g)) {
        assert!(a.distance(b) < 1e-5);
    }
    f.set_blend("run", 0.5).unwrap();
    f.pose(0.25).unwrap();
    let half = positions(&f);
    let knee = f.skeleton().find("shin.L").unwrap();
    assert!(
        half[knee].distance(walk[knee]) > 1e-3 && half[knee].distance(run_at_phase[knee]) > 1e-3
    );
    assert!(f
        .set_blend("run", 1.5)
        .unwrap_err()
        .contains("blend weight"));
    assert!(f
        .set_blend("tango", 0.5)
        .unwrap_err()
        .contains("blend clip"));
    // "use my exercise" runs 6.3 on every joint.
    f.set_use_exercise(true);
    let note = f.pose(0.25).unwrap();
    if cfg!(feature = "solutions") {
        assert!(
            note.contains("Your crossfade_joint matches the reference at all 21 joints"),
            "{note}"
        );
    } else {
        assert!(note.contains("Not done yet: exercise 6.3"), "{note}");
    }
}

/// The speeds (°/s) of the plot's purple and blue series inside segment `k` of a clip with
/// `keys` keys per cycle and duration `d`, away from the keys' finite-difference samples.
fn speeds_in_segment(samples: &[f32], d: f32, keys: usize, k: usize) -> Vec<(f32, f32, f32)> {
    let segment = d / (keys - 1) as f32;
    samples
        .chunks(7)
        .map(|c| (c[0], c[2], c[4]))
        .filter(|&(t, ..)| t > k as f32 * segment + 0.01 && t < (k + 1) as f32 * segment - 0.02)
        .map(|(t, a, b)| ((t - k as f32 * segment) / segment, a, b))
        .collect()
}

/// Figure 2's start: arm circles, 4 keys, upper_arm.L, slerp (purple) against nlerp (blue).
fn interpolation_figure() -> SkeletonFigure {
    let mut f = SkeletonFigure::new();
    f.set_clip("arm circles").unwrap();
    f.set_keys_per_cycle(4.0).unwrap();
    f.select(f.skeleton().find("upper_arm.L").unwrap()).unwrap();
    f.set_interpolation("linear (slerp)").unwrap();
    f.set_compare("linear (nlerp)").unwrap();
    f
}

#[test]
fn the_compared_paths_and_speeds_show_what_the_try_this_says() {
    let mut f = interpolation_figure();
    assert_eq!(f.compare_name(), "linear (nlerp)");
    assert!(f
        .set_compare("squad")
        .unwrap_err()
        .contains("interpolation"));
    let d = f.duration_sec();
    // The keys are 120° apart: the upper arm turns a third of a circle per segment.
    let samples = f.sample_selected(241).unwrap();
    let arm = f.skeleton().find("upper_arm.L").unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, 0.1).unwrap();
    assert!(
        note.contains("purple linear (slerp), blue linear (nlerp)"),
        "{note}"
    );
    let times = f.key_times();
    assert_eq!(times.len(), 4);
    let rotation_at = |f: &mut SkeletonFigure, t: f32| {
        f.pose(t).unwrap();
        Quat::from_mat4(&f.local_matrix(arm).unwrap())
    };
    let q0 = rotation_at(&mut f, times[0]);
    let q1 = rotation_at(&mut f, times[1]);
    let apart = q0.angle_between(q1).to_degrees();
    assert!((apart - 120.0).abs() < 3.0, "keys {apart}° apart");
    // Slerp: flat within a segment. Nlerp: slowest at the keys, fastest midway, by about a third.
    let seg = speeds_in_segment(&samples, d, 4, 1);
    let slerp: Vec<f32> = seg.iter().map(|s| s.1).collect();
    let spread = slerp.iter().cloned().fold(f32::MIN, f32::max)
        - slerp.iter().cloned().fold(f32::MAX, f32::min);
    assert!(spread < 0.01 * slerp[0], "slerp's speed spread {spread}");
    let near_key = seg
        .iter()
        .filter(|s| s.0 < 0.1 || s.0 > 0.9)
        .map(|s| s.2)
        .fold(f32::MAX, f32::min);
    let midway = seg
        .iter()
        .filter(|s| (s.0 - 0.5).abs() < 0.05)
        .map(|s| s.2)
        .fold(0.0, f32::max);
    assert!(
        midway > 1.25 * near_key,
        "nlerp midway {midway} against near a key {near_key}"
    );
    // On the blue path the ticks are closer near the keys than midway.
    let path = f.compare_trail().to_vec();
    assert_eq!(path.len(), 61);
    let gap = |i: usize| path[i].distance(path[i + 1]);
    assert!(
        gap(30) > 1.2 * gap(20),
        "ticks near key 1 ({}) against midway ({})",
        gap(20),
        gap(30)
    );
    // With 25 keys per cycle the two speeds nearly agree (within 2 %).
    f.set_keys_per_cycle(25.0).unwrap();
    let samples = f.sample_selected(961).unwrap();
    for (_, a, b) in speeds_in_segment(&samples, d, 25, 3) {
        assert!(
            (a - b).abs() < 0.02 * a,
            "slerp {a} against nlerp {b} at 25 keys"
        );
    }
    // Step: the dots pile up on the three distinct key poses; the speed is zero between keys.
    f.set_keys_per_cycle(4.0).unwrap();
    f.set_compare("step").unwrap();
    f.draw(&mut Frame::default(), 0.1).unwrap();
    let mut distinct: Vec<Vec3> = Vec::new();
    for &p in &f.compare_trail()[..60] {
        if !distinct.iter().any(|q| q.distance(p) < 1e-4) {
            distinct.push(p);
        }
    }
    assert_eq!(distinct.len(), 3, "the step path's dots");
    let samples = f.sample_selected(241).unwrap();
    assert!(speeds_in_segment(&samples, d, 4, 1)
        .iter()
        .all(|s| s.2 == 0.0));
    // Its speed spikes at the two keys inside the cycle and nowhere else (the jump back to the
    // first key comes as the cycle wraps, past the plot's end).
    let step = f.key_times()[1] - f.key_times()[0];
    let spikes: Vec<f32> = samples
        .chunks(7)
        .filter(|row| row[4] > 0.0)
        .map(|row| row[0])
        .collect();
    assert!(!spikes.is_empty());
    for t in &spikes {
        let near = [1.0, 2.0].iter().any(|k| (t - k * step).abs() < 0.02 * d);
        assert!(near, "a step speed spike at {t} s, away from the inner keys");
    }
    for k in [1.0, 2.0] {
        assert!(
            spikes.iter().any(|t| (t - k * step).abs() < 0.02 * d),
            "no spike at key {k}: {spikes:?}"
        );
    }
    // On the walk's thigh, still at 4 keys per cycle, linear keys turn at a constant speed
    // between keys that jumps at the keys; cubic keys change speed smoothly through a key.
    let mut f = SkeletonFigure::new();
    f.set_keys_per_cycle(4.0).unwrap();
    assert_eq!(f.skeleton().names()[f.selected()], "thigh.L");
    f.set_interpolation("linear (slerp)").unwrap();
    f.set_compare("cubic").unwrap();
    let times = f.key_times();
    let samples = f.sample_selected(961).unwrap();
    // The change of speed across a key, against the fastest speed of the cycle (at 4 keys the
    // cubic thigh slows almost to rest at a key, so a ratio to the speed there says nothing).
    let jump = |column: usize, key_t: f32| {
        let rows: Vec<&[f32]> = samples.chunks(7).collect();
        let i = rows.iter().position(|c| c[0] >= key_t).unwrap();
        let fastest = rows.iter().map(|r| r[column]).fold(0.0, f32::max);
        (rows[i + 2][column] - rows[i - 3][column]).abs() / fastest
    };
    for k in [1, 2] {
        assert!(
            jump(2, times[k]) > 0.2,
            "linear jumps by {} at key {k}",
            jump(2, times[k])
        );
        assert!(
            jump(4, times[k]) < 0.05,
            "cubic jumps by {} at key {k}",
            jump(4, times[k])
        );
    }
}

#[test]
fn the_crossfade_shows_both_clips_beside_the_blend() {
    let mut f = SkeletonFigure::new();
    assert!(f.sources()[0].is_empty());
    f.set_blend("wave", 0.5).unwrap();
    let arm = f.skeleton().find("upper_arm.R").unwrap();
    let thigh = f.skeleton().find("thigh.L").unwrap();
    f.select(arm).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, 0.25).unwrap();
    assert!(
        note.contains("left, in blue: walk alone; right, in brown: wave alone"),
        "{note}"
    );
    let [a, b] = f.sources();
    assert_eq!((a.len(), b.len()), (21, 21));
    let blend_root = f.joint_position(0).unwrap();
    let beside = inbetween::figures::skeleton::SOURCE_OFFSET_X;
    assert!(
        (a[0].translation.x - blend_root.x + beside).abs() < 0.1,
        "A stands {beside} m to the left"
    );
    assert!(
        (b[0].translation.x - blend_root.x - beside).abs() < 0.1,
        "B stands {beside} m to the right"
    );
    // Over the whole cycle the three skeletons keep apart: the blend's arm, half way up, points
    // sideways and must not reach into clip A's figure (nor clip B's into the blend).
    let d = f.duration_sec();
    for k in 0..=24 {
        f.draw(&mut Frame::default(), d * k as f32 / 24.0 * 0.9999).unwrap();
        let xs = |model: &[glam::Affine3A]| {
            model
                .iter()
                .map(|m| m.translation.x)
                .fold((f32::MAX, f32::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)))
        };
        let blend: Vec<glam::Affine3A> = (0..21)
            .map(|j| {
                glam::Affine3A::from_translation(f.joint_position(j).unwrap())
            })
            .collect();
        let (blend_lo, blend_hi) = xs(&blend);
        let [a, b] = f.sources();
        assert!(xs(a).1 + 0.1 < blend_lo, "clip A reaches the blend at step {k}");
        assert!(blend_hi + 0.1 < xs(b).0, "the blend reaches clip B at step {k}");
    }
    assert!(frame
        .labels
        .iter()
        .any(|l| l.text == "wave alone" && l.color == palette::BROWN));
    // At weight 0.5 the right arm goes about half way up, and the thigh swings about half as far.
    let samples = f.sample_selected(101).unwrap();
    let mut wave = SkeletonFigure::new();
    wave.set_clip("wave").unwrap();
    wave.select(arm).unwrap();
    let wave_arm = wave.sample_selected(101).unwrap();
    let arm_blend = samples.chunks(7).map(|c| c[1]).fold(0.0, f32::max);
    // The plot's clip B column is the wave alone, its clip A column the walk alone.
    let b_column = samples.chunks(7).map(|c| c[6]).fold(0.0, f32::max);
    let wave_own = wave_arm.chunks(7).map(|c| c[1]).fold(0.0, f32::max);
    assert!((b_column - wave_own).abs() < 0.5, "{b_column} against {wave_own}");
    let mut walk_arm = SkeletonFigure::new();
    walk_arm.select(arm).unwrap();
    let walk_own: Vec<f32> = walk_arm.sample_selected(101).unwrap().chunks(7).map(|c| c[1]).collect();
    let a_column: Vec<f32> = samples.chunks(7).map(|c| c[5]).collect();
    for (a, b) in a_column.iter().zip(&walk_own) {
        assert!((a - b).abs() < 1e-3);
    }
    // The blend's line runs about midway between A's and B's (the Try this).
    for c in samples.chunks(7) {
        let (blend, a, b) = (c[1], c[5], c[6]);
        assert!((blend - 0.5 * (a + b)).abs() < 0.15 * (b - a).abs(), "blend {blend}, A {a}, B {b}");
    }
    let arm_wave = wave_arm.chunks(7).map(|c| c[1]).fold(0.0, f32::max);
    let ratio = arm_blend / arm_wave;
    assert!(
        (0.4..0.6).contains(&ratio),
        "the arm goes {ratio} of the way up"
    );
    f.select(thigh).unwrap();
    let mut walk = SkeletonFigure::new();
    walk.select(thigh).unwrap();
    let swing = |s: Vec<f32>| s.chunks(7).map(|c| c[1]).fold(0.0, f32::max);
    let ratio = swing(f.sample_selected(101).unwrap()) / swing(walk.sample_selected(101).unwrap());
    assert!(
        (0.4..0.6).contains(&ratio),
        "the stride is {ratio} of the walk's"
    );
}

#[test]
fn everything_drawn_stays_inside_the_declared_view() {
    use inbetween::draw::MeshId;
    let corners = |m: Mat4| {
        (0..8).map(move |i| {
            let c = Vec3::new(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            );
            m.transform_point3(c)
        })
    };
    // The walk with body boxes, the step keys with the arm raised by an offset, the crossfade.
    let mut cases = Vec::new();
    let mut f = SkeletonFigure::new();
    f.set_show_boxes(true);
    cases.push(f);
    let mut f = SkeletonFigure::new();
    f.set_show_boxes(true);
    f.set_clip("arm circles").unwrap();
    f.set_interpolation("step").unwrap();
    let arm = f.skeleton().find("upper_arm.L").unwrap();
    f.set_joint_angles_deg(arm, Vec3::new(0.0, 0.0, 170.0))
        .unwrap();
    cases.push(f);
    let mut f = SkeletonFigure::new();
    f.set_blend("wave", 0.5).unwrap();
    cases.push(f);
    for (n, f) in cases.iter_mut().enumerate() {
        for k in 0..20 {
            let mut frame = Frame::default();
            f.draw(&mut frame, k as f32 * 0.1).unwrap();
            let (lo, hi) = frame.keep_in_view.iter().fold(
                (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
                |(lo, hi), p| (lo.min(*p), hi.max(*p)),
            );
            let inside = |p: Vec3| p.cmpge(lo - 1e-4).all() && p.cmple(hi + 1e-4).all();
            for m in frame
                .meshes
                .iter()
                .filter(|m| m.mesh == MeshId::CUBE || m.mesh == MeshId::SPHERE)
            {
                for c in corners(m.model) {
                    assert!(
                        inside(c),
                        "case {n}, t = {}: {c} outside {lo}..{hi}",
                        k as f32 * 0.1
                    );
                }
            }
            for l in &frame.labels {
                assert!(
                    inside(l.anchor),
                    "case {n}: label {} at {}",
                    l.text,
                    l.anchor
                );
            }
        }
    }
    // Comparing paths (Figure 2 at its start, and the page test's idle forearm with 21 keys,
    // whose paths are a few centimetres long), the view keeps the whole body down to the floor
    // (a close view would cut the legs off), and the inset shows the two paths close up: they
    // reach across most of its box, along at least one of the two axes it shows.
    use inbetween::draw::inset::InsetView;
    for (clip, keys, joint, compare) in [
        ("arm circles", 4.0, "upper_arm.L", "linear (nlerp)"),
        ("idle", 21.0, "forearm.L", "linear (slerp)"),
    ] {
        let mut f = interpolation_figure();
        f.set_clip(clip).unwrap();
        f.set_keys_per_cycle(keys).unwrap();
        f.set_interpolation("cubic").unwrap();
        f.set_compare(compare).unwrap();
        f.select(f.skeleton().find(joint).unwrap()).unwrap();
        let mut frame = Frame::default();
        f.draw(&mut frame, 0.0).unwrap();
        let (lo, hi) = f.view_bounds();
        assert!(lo.y <= 0.0, "{clip}: the floor in view: {lo}..{hi}");
        let head = f.joint_position(f.skeleton().find("head").unwrap()).unwrap();
        assert!(head.cmpge(lo).all() && head.cmple(hi).all(), "{clip}: head {head}");
        let inset = frame.inset.as_ref().expect("an inset of the paths");
        let paths: Vec<Vec3> = f.trail().iter().chain(f.compare_trail()).copied().collect();
        let (mut a, mut b) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
        for &p in &paths {
            assert!(
                p.cmpge(inset.min).all() && p.cmple(inset.max).all(),
                "{clip}: {p} outside the inset's box"
            );
            (a, b) = (a.min(p), b.max(p));
        }
        let shown = match inset.view {
            InsetView::Top => [0, 2],
            InsetView::Side => [1, 2],
            InsetView::Front => [0, 1],
        };
        let fill = shown
            .map(|i| (b[i] - a[i]) / (inset.max[i] - inset.min[i]))
            .into_iter()
            .fold(0.0, f32::max);
        assert!(fill > 0.5, "{clip}: the paths fill {fill} of the inset");
        // The paths and their ticks are drawn over everything: the tip's ball (4.4 cm across)
        // otherwise hides much of a path a few centimetres long, in the inset above all.
        let on_top = frame.strokes.iter().filter(|s| s.depth_bias == ON_TOP).count();
        assert!(on_top >= paths.len() - 2, "{clip}: {on_top} path segments on top");
        let ticks = frame.markers.iter().filter(|m| m.shape == MARKER_TICK);
        assert!(ticks.clone().count() > 20 && ticks.clone().all(|m| m.size_px < 0.0), "{clip}");
        // Seen in the inset, on either page canvas, no tick lies under the inset's title (in
        // its top-left corner, where the page puts it).
        use inbetween::draw::inset::{inset_camera, inset_rect, title_top_left};
        let (view, projection, _) = inset_camera(inset).unwrap();
        for size in crate::label_clearance::CANVASES {
            let r = inset_rect(size);
            let title_end = title_top_left(size) + inbetween::draw::label_size_px(&inset.title);
            for m in ticks.clone() {
                let ndc = (projection * view).project_point3(Vec3::from(m.center));
                let c = r.min + glam::Vec2::new(ndc.x + 1.0, 1.0 - ndc.y) * 0.5 * r.size;
                let half = 0.5 * m.size_px.abs();
                assert!(
                    c.y - half > title_end.y || c.x - half > title_end.x,
                    "{clip} on {size}: a tick at {c} under the inset's title (to {title_end})"
                );
            }
        }
        // The inset draws the paths and their ticks alone: at its zoom the tip's ball and bar
        // would fill it and run through its title.
        let [strokes, markers] = inset.only.clone().expect("the inset draws the paths alone");
        assert!(strokes.len() >= paths.len() - 2, "{clip}: {strokes:?}");
        assert!(frame.strokes[strokes].iter().all(|s| s.depth_bias == ON_TOP));
        assert_eq!(markers.len(), ticks.count(), "{clip}");
        assert!(frame.markers[markers].iter().all(|m| m.shape == MARKER_TICK));
    }
    // Without compared paths, no inset.
    let mut frame = Frame::default();
    SkeletonFigure::new().draw(&mut frame, 0.0).unwrap();
    assert!(frame.inset.is_none());
}

#[test]
fn a_click_picks_the_joint_under_the_pointer() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera};
    let mut f = SkeletonFigure::new();
    f.draw(&mut Frame::default(), 0.2).unwrap();
    let camera = OrbitCamera::from_view([0.0, 0.85, 0.0, 2.5, 0.5, 0.2]);
    for size in [Vec2::new(800.0, 600.0), Vec2::new(690.0, 420.0)] {
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        for name in ["pelvis", "head", "hand.R", "foot.L", "shin.L"] {
            let j = f.skeleton().find(name).unwrap();
            let px = project_to_canvas(view_proj, size, f.joint_position(j).unwrap()).unwrap();
            assert_eq!(
                f.pick_joint(view_proj, size, px),
                Some(j),
                "{name} at its centre"
            );
            // A few pixels off still picks it (small joints are hard to hit exactly).
            assert_eq!(
                f.pick_joint(view_proj, size, px + Vec2::new(4.0, -3.0)),
                Some(j),
                "{name} off centre"
            );
        }
        assert_eq!(
            f.pick_joint(view_proj, size, Vec2::new(5.0, 5.0)),
            None,
            "empty space"
        );
        assert_eq!(f.pick_joint(view_proj, size, Vec2::NAN), None);
    }
}

#[test]
fn use_my_exercise_checks_probe_inputs_beyond_the_shown_one() {
    let mut f = interpolation_figure();
    f.set_use_exercise(true);
    // A slerp that forgets the short arc: right wherever q_k·q_k+1 > 0, as on this clip.
    fn long_arc(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        if name == "sample_rotation_slerp" {
            let n = args[0] as usize;
            let times = &args[1..1 + n];
            // Flattened as [n, times…, n, keys (x, y, z, w)…, time].
            let keys: Vec<Quat> = args[2 + n..2 + 5 * n]
                .chunks(4)
                .map(|c| Quat::from_xyzw(c[0], c[1], c[2], c[3]))
                .collect();
            let t = args[2 + 5 * n];
            let i = times.iter().rposition(|&k| k <= t).unwrap_or(0).min(n - 2);
            let s = ((t - times[i]) / (times[i + 1] - times[i])).clamp(0.0, 1.0);
            let (a, b) = (keys[i], keys[i + 1]);
            let theta = a.dot(b).clamp(-1.0, 1.0).acos();
            let q = if theta < 1e-4 {
                a
            } else {
                a * ((1.0 - s) * theta).sin() / theta.sin() + b * (s * theta).sin() / theta.sin()
            };
            return Ok(q.to_array().to_vec());
        }
        direct(name, args)
    }
    f.set_runner(long_arc);
    let note = f.pose(0.3).unwrap();
    assert!(
        note.contains("Your sample_rotation_slerp matches the reference"),
        "{note}"
    );
    assert!(
        note.contains("Of 4 probe inputs beyond the shown one, your sample_rotation_slerp differs at 1: key 1 negated"),
        "{note}"
    );
    if cfg!(feature = "solutions") {
        f.set_runner(direct);
        let note = f.pose(0.3).unwrap();
        assert!(note.contains("It also matches at 4 probe inputs"), "{note}");
        assert!(note.contains("It also matches at 3 probe inputs"), "{note}");
    }
    // A crossfade without the sign test, and a local_to_model that ignores scale.
    fn sloppy(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        match name {
            "crossfade_joint" => {
                let w = args[14];
                let mut out: Vec<f32> = (0..3)
                    .map(|i| (1.0 - w) * args[i] + w * args[7 + i])
                    .collect();
                let q = Quat::from_xyzw(
                    (1.0 - w) * args[3] + w * args[10],
                    (1.0 - w) * args[4] + w * args[11],
                    (1.0 - w) * args[5] + w * args[12],
                    (1.0 - w) * args[6] + w * args[13],
                )
                .normalize();
                out.extend(q.to_array());
                Ok(out)
            }
            _ => direct(name, args),
        }
    }
    let mut g = SkeletonFigure::new();
    g.set_use_exercise(true);
    g.set_blend("wave", 0.5).unwrap();
    g.set_runner(sloppy);
    let note = g.pose(0.3).unwrap();
    assert!(
        note.contains("your crossfade_joint differs at 1: q_b negated"),
        "{note}"
    );
}

/// At the selected joint: its name and its axes' x, y and z (placed after the name, clear of
/// it: tests/label_clearance/lesson_06.rs), in the default figure and in the one comparing two
/// interpolations, whichever joint is selected; the world's axes at the feet have their letters
/// too.
#[test]
fn the_selected_joints_name_and_axis_letters_are_at_the_joint() {
    let mut figures = vec![SkeletonFigure::new(), interpolation_figure()];
    let thigh = figures[0].skeleton().find("thigh.L").unwrap();
    figures[0].select(thigh).unwrap();
    for (n, f) in figures.iter_mut().enumerate() {
        let mut frame = Frame::default();
        f.draw(&mut frame, 0.4).unwrap();
        let at = f.joint_position(f.selected()).unwrap();
        let name = &f.skeleton().names()[f.selected()];
        let near: Vec<&str> = frame
            .labels
            .iter()
            .filter(|l| (l.anchor - at).length() < 0.3)
            .map(|l| l.text.as_str())
            .collect();
        assert_eq!(near, vec![name.as_str(), "x", "y", "z"], "figure {n}");
        if n == 0 {
            let letters = frame.labels.iter().filter(|l| l.text.len() == 1).count();
            assert_eq!(letters, 6, "the joint's and the world's x, y and z");
        }
    }
}

#[test]
fn path_ticks_are_sized_to_their_spacing_on_the_canvas() {
    // Figures 1 and 2 at their page cameras (lessons/06-skeletons/lesson.js: fitted to what the
    // figure keeps in view), on the canvases the page gives them at 800 × 600 and 1600 × 1000:
    // Figure 1 at its start (the thigh's path, a few tens of pixels long), with the page test's
    // settings (the run, the shin, body boxes) at its camera and orbited, and Figure 2's two
    // compared paths. As on the page, the figure sizes its ticks for the view of the frame
    // before. Each path's ticks are at most 1.5 times as long across it as they are apart on
    // average (4 px at the least, the smallest marker; 14 px at the most): on a short path, 14 px
    // ticks a pixel apart merge into a hatched smudge, and Figure 2's close view keeps long ones.
    // A lone path with room for none of 7 px (the thigh's) has none.
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::MARKER_TICK;
    let fitted = |view: [f32; 6], frame: &Frame, size: Vec2| {
        let mut camera = OrbitCamera::from_view(view);
        camera.fit(&frame.fit_points(), size, FIT_PAD_PX);
        camera
    };
    for (clip, joint, boxes, yaw, pitch) in [
        ("walk", "thigh.L", false, 0.5, 0.2),
        ("run", "shin.L", true, 0.5, 0.2),
        ("run", "shin.L", true, 1.0, 0.5),
        ("arm circles", "upper_arm.L", false, 1.2, 0.15),
    ] {
        for size in crate::label_clearance::CANVASES {
            let mut f = SkeletonFigure::new();
            f.set_clip(clip).unwrap();
            f.set_show_boxes(boxes);
            if clip == "arm circles" {
                f.set_keys_per_cycle(4.0).unwrap();
                f.set_compare("linear (nlerp)").unwrap();
            }
            f.select(f.skeleton().find(joint).unwrap()).unwrap();
            let view = [0.0, 0.85, 0.0, 2.5, yaw, pitch];
            let mut frame = Frame::default();
            f.draw(&mut frame, 0.3).unwrap();
            let camera = fitted(view, &frame, size);
            f.set_view(camera, size.x, size.y);
            let mut frame = Frame::default();
            f.draw(&mut frame, 0.3).unwrap();
            let camera = fitted(view, &frame, size);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let name = format!("{clip}, {joint}, orbit ({yaw}, {pitch}) on {size}");
            let mut paths = 0;
            for color in [palette::PURPLE, palette::BLUE] {
                let ticks: Vec<_> = frame
                    .markers
                    .iter()
                    .filter(|m| m.shape == MARKER_TICK && m.color[..3] == color.to_array())
                    .collect();
                if ticks.is_empty() {
                    continue;
                }
                paths += 1;
                let at: Vec<Vec2> = ticks
                    .iter()
                    .map(|m| project_to_canvas(view_proj, size, Vec3::from(m.center)).unwrap())
                    .collect();
                let apart = at.windows(2).map(|w| w[0].distance(w[1])).sum::<f32>()
                    / (at.len() - 1) as f32;
                let longest = (1.5 * apart).clamp(4.0, 14.0);
                for m in &ticks {
                    assert!(
                        (m.size_px.abs() - longest).abs() < 0.01,
                        "{name}: a {} px tick, {apart} px apart on average",
                        m.size_px
                    );
                }
                if clip == "arm circles" {
                    assert!(longest > 8.0, "{name}: the arm's circle has room: {longest}");
                }
            }
            // The thigh's path alone, a few tens of pixels long, has no room for ticks that
            // show their purple (7 px): it is a plain line 4 px wide.
            let expected = match clip {
                "arm circles" => 2,
                "walk" => 0,
                _ => 1,
            };
            assert_eq!(paths, expected, "{name}: paths drawn with ticks");
            if clip == "walk" {
                let widths: Vec<f32> = frame
                    .strokes
                    .iter()
                    .filter(|s| s.color[..3] == palette::PURPLE.to_array())
                    .map(|s| s.width_px)
                    .collect();
                assert!(!widths.is_empty() && widths.iter().all(|&w| w == 4.0), "{name}: {widths:?}");
            }
        }
    }
}

#[test]
fn the_crossfade_draws_the_world_axes_without_their_letters() {
    // Figure 3's blend stands on the world's origin: the x, y and z of the axes at its feet
    // would lie on its legs and the selected joint's path. Figure 1 keeps them; both letter
    // the selected joint's axes.
    let letters = |f: &mut SkeletonFigure| {
        let mut frame = Frame::default();
        f.draw(&mut frame, 0.3).unwrap();
        let axis = |l: &&inbetween::draw::Label| ["x", "y", "z"].contains(&l.text.as_str());
        frame.labels.iter().filter(axis).count()
    };
    let mut f = SkeletonFigure::new();
    assert_eq!(letters(&mut f), 6);
    for (clip, joint) in [("wave", "upper_arm.R"), ("arm circles", "shin.L")] {
        f.set_blend(clip, 0.2).unwrap();
        f.select(f.skeleton().find(joint).unwrap()).unwrap();
        assert_eq!(letters(&mut f), 3, "{clip}");
    }
}

/// Figure 1 at its page camera (yaw 0.5, pitch 0.2, fitted to the declared box) on the canvases
/// the page gives it at 1600 × 1000 (650 × 420) and 800 × 600 (760 × 420): the skeleton's joints
/// span at least 55 % of the canvas's height over the walk. The declared box stops at the floor
/// (nothing is drawn below it but the lowest joints' balls, 3.3 cm across), so no margin under
/// the feet shrinks the skeleton.
#[test]
fn the_skeleton_fills_most_of_figure_1s_height() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    for size in crate::label_clearance::CANVASES {
        let mut f = SkeletonFigure::new();
        f.select(f.skeleton().find("thigh.L").unwrap()).unwrap();
        for t in [0.0, 0.3, 0.6] {
            let mut frame = Frame::default();
            f.draw(&mut frame, t).unwrap();
            assert!(f.view_bounds().0.y > -0.04, "{:?}", f.view_bounds());
            let mut camera = OrbitCamera::from_view([0.0, 0.85, 0.0, 2.5, 0.5, 0.2]);
            assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let ys = (0..f.skeleton().len())
                .map(|j| project_to_canvas(view_proj, size, f.joint_position(j).unwrap()).unwrap().y);
            let (top, bottom) = ys.fold((f32::MAX, f32::MIN), |(a, b), y| (a.min(y), b.max(y)));
            assert!(
                bottom - top >= 0.55 * size.y,
                "{size} at {t} s: the joints span {} px",
                bottom - top
            );
        }
    }
}

#[test]
fn the_thighs_two_paths_come_apart_in_the_inset() {
    // The Try this's walk, thigh.L, slerp (purple) against cubic (blue), at the page's camera
    // on either canvas: in the main view the two paths lie within 5 px of each other (one band),
    // in the inset they come more than 8 px apart between the keys.
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::inset::{inset_camera, inset_rect};
    for size in crate::label_clearance::CANVASES {
        let mut f = interpolation_figure();
        f.set_clip("walk").unwrap();
        f.select(f.skeleton().find("thigh.L").unwrap()).unwrap();
        f.set_compare("cubic").unwrap();
        let mut frame = Frame::default();
        f.draw(&mut frame, 0.3).unwrap();
        let mut camera = OrbitCamera::from_view([0.0, 0.85, 0.0, 2.5, 0.5, 0.2]);
        camera.fit(&frame.fit_points(), size, FIT_PAD_PX);
        let main = camera.projection(size.x / size.y) * camera.view();
        let (view, projection, _) = inset_camera(frame.inset.as_ref().unwrap()).unwrap();
        let side = inset_rect(size).size.x;
        let inset = |q: Vec3| (projection * view).project_point3(q).truncate() * 0.5 * side;
        let (mut in_main, mut in_inset) = (0f32, 0f32);
        for (&a, &b) in f.trail().iter().zip(f.compare_trail()) {
            let on_canvas = |q| project_to_canvas(main, size, q).unwrap();
            in_main = in_main.max(on_canvas(a).distance(on_canvas(b)));
            in_inset = in_inset.max(inset(a).distance(inset(b)));
        }
        assert!(
            in_main < 5.0 && in_inset > 8.0,
            "{size}: {in_main} px, inset {in_inset} px"
        );
    }
}
