//! Lesson 06 figure logic: validation messages, what the controls change, the plot samples, and
//! what the note says about the student's exercises (with a correct, a wrong and a panicking
//! runner).

use glam::{Mat4, Quat, Vec3};
use inbetween::draw::{palette, Frame};
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
}

#[test]
fn plot_samples_follow_the_interpolation() {
    let mut f = SkeletonFigure::new();
    f.set_clip("arm circles").unwrap();
    f.select(f.skeleton().find("upper_arm.L").unwrap()).unwrap();
    f.set_keys_per_cycle(4.0).unwrap();
    let linear_slerp = f.sample_selected(301).unwrap();
    assert_eq!(linear_slerp.len(), 3 * 301);
    f.set_interpolation("linear (nlerp)").unwrap();
    let linear_nlerp = f.sample_selected(301).unwrap();
    assert_ne!(linear_slerp, linear_nlerp);
    // Slerp turns at constant speed inside a segment: the speed's spread within the first
    // segment (t in (0.02, 0.6), keys 120° apart) is tiny for slerp, larger for nlerp.
    let spread = |v: &[f32]| {
        let s: Vec<f32> = v
            .chunks(3)
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
