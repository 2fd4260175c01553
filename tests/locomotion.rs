//! Locomotion: synchronised blends at normalised time, root motion, and feet that do not slide.

use glam::{Affine3A, Vec3};
use inbetween::skeleton::{
    human, local_to_model, sample_synchronised, synchronised_cycle, weight_for_speed, Clip,
    ClipCursor, Pose, RootMotion, Skeleton,
};

fn clips() -> (Skeleton, Clip, Clip) {
    let (skeleton, _) = human::simple_human();
    let walk = Clip::from_raw(
        &human::travelling_clip(&skeleton, 1, 25).unwrap(),
        &skeleton,
    )
    .unwrap();
    let run = Clip::from_raw(
        &human::travelling_clip(&skeleton, 2, 25).unwrap(),
        &skeleton,
    )
    .unwrap();
    (skeleton, walk, run)
}

fn same(a: &Pose, b: &Pose, eps: f32) -> bool {
    a.local.iter().zip(&b.local).all(|(x, y)| {
        x.translation.abs_diff_eq(y.translation, eps)
            && x.rotation.dot(y.rotation).abs() > 1.0 - eps
    })
}

#[test]
fn weight_0_or_1_returns_one_clip_at_its_own_phase() {
    let (skeleton, walk, run) = clips();
    let mut out = skeleton.rest_pose();
    let mut scratch = skeleton.rest_pose();
    let mut expected = skeleton.rest_pose();
    for phase in [0.0, 0.1, 0.37, 0.8] {
        for (w, clip) in [(0.0, &walk), (1.0, &run)] {
            let mut cursors = [ClipCursor::new(); 2];
            sample_synchronised(
                &walk,
                &run,
                w,
                phase,
                &mut cursors,
                &mut scratch,
                None,
                &mut out,
            );
            clip.sample(
                phase * clip.duration_sec(),
                &mut ClipCursor::new(),
                &mut expected,
            );
            assert!(same(&out, &expected, 1e-6), "w = {w}, phase {phase}");
        }
    }
}

#[test]
fn root_motion_moves_the_travel_from_the_pose_to_the_character() {
    let (skeleton, walk, _) = clips();
    let motion = RootMotion::from_clip(&walk);
    assert!(
        motion.cycle_travel.z.abs() > 0.3,
        "a walk travels: {:?}",
        motion.cycle_travel
    );
    assert_eq!(motion.cycle_travel.y, 0.0);
    let mut pose = skeleton.rest_pose();
    let mut cursor = ClipCursor::new();
    for k in 0..40 {
        let t = k as f32 * 0.07;
        walk.sample(t, &mut cursor, &mut pose);
        let root = pose.local[0].translation;
        let d = motion.extract(&mut pose);
        let stay = pose.local[0].translation;
        // The pose stays on the spot horizontally, keeps its height, and pose + offset = clip.
        assert!((stay.x - motion.start.x).abs() < 1e-6 && (stay.z - motion.start.z).abs() < 1e-6);
        assert_eq!(stay.y, root.y);
        assert!((stay + d).abs_diff_eq(root, 1e-5));
        // Over several loops the character keeps going.
        let p = motion.position(t, d);
        let cycles = (t / walk.duration_sec()).floor();
        assert!(p.abs_diff_eq(cycles * motion.cycle_travel + d, 1e-5));
    }
}

#[test]
fn looping_is_seamless_once_the_root_motion_is_extracted() {
    let (skeleton, walk, run) = clips();
    for clip in [&walk, &run] {
        let motion = RootMotion::from_clip(clip);
        let d = clip.duration_sec();
        let mut before = skeleton.rest_pose();
        let mut after = skeleton.rest_pose();
        clip.sample(d - 1e-5, &mut ClipCursor::new(), &mut before);
        clip.sample(d + 1e-5, &mut ClipCursor::new(), &mut after);
        let p_before = motion.position(d - 1e-5, motion.extract(&mut before));
        let p_after = motion.position(d + 1e-5, motion.extract(&mut after));
        assert!(same(&before, &after, 1e-3), "the pose on the spot loops");
        assert!(
            p_before.distance(p_after) < 1e-3,
            "the character does not jump back"
        );
        // Without extraction the pose jumps back by a whole cycle's travel at the loop.
        let mut raw_before = skeleton.rest_pose();
        let mut raw_after = skeleton.rest_pose();
        clip.sample(d - 1e-5, &mut ClipCursor::new(), &mut raw_before);
        clip.sample(d + 1e-5, &mut ClipCursor::new(), &mut raw_after);
        let jump = raw_before.local[0]
            .translation
            .distance(raw_after.local[0].translation);
        assert!((jump - motion.cycle_travel.length()).abs() < 0.01, "{jump}");
    }
}

/// The ankle's height when the foot is flat on the ground, metres (the walk's lowest).
const CONTACT_HEIGHT: f32 = 0.06;

/// How far the planted foot (the lower ankle) slides over one blended cycle with root motion
/// applied, metres, sampled at 400 steps; `synchronised: false` samples both clips at the
/// same clock time instead of the same phase.
fn foot_slide(w: f32, synchronised: bool) -> f32 {
    let (skeleton, walk, run) = clips();
    let (ra, rb) = (RootMotion::from_clip(&walk), RootMotion::from_clip(&run));
    let feet = [
        skeleton.find("foot.L").unwrap(),
        skeleton.find("foot.R").unwrap(),
    ];
    let (cycle, _, _) = synchronised_cycle(&ra, &rb, w);
    let mut out = skeleton.rest_pose();
    let mut scratch = skeleton.rest_pose();
    let mut model = vec![Affine3A::IDENTITY; skeleton.len()];
    let mut cursors = [ClipCursor::new(); 2];
    let steps = 399; // not a divisor of the cycle's keys
    let mut last: Option<(usize, Vec3)> = None;
    let mut run_start: Option<(usize, Vec3)> = None;
    let mut slide = 0.0;
    let mut travel = Vec3::ZERO;
    let mut previous_offset = Vec3::ZERO;
    for k in 0..=steps {
        let time = cycle * k as f32 / steps as f32;
        let offset = if synchronised {
            let phase = time / cycle;
            sample_synchronised(
                &walk,
                &run,
                w,
                phase,
                &mut cursors,
                &mut scratch,
                Some([&ra, &rb]),
                &mut out,
            )
        } else {
            // The naive blend: each clip at the same clock time.
            walk.sample(time, &mut cursors[0], &mut out);
            run.sample(time, &mut cursors[1], &mut scratch);
            let d = ra.extract(&mut out).lerp(rb.extract(&mut scratch), w);
            for (x, y) in out.local.iter_mut().zip(&scratch.local) {
                *x = inbetween::skeleton::crossfade_transform(x, y, w);
            }
            d
        };
        // Continuous character travel (offsets wrap once per cycle of each clip).
        let step = offset - previous_offset;
        if k > 0 && step.length() < 0.3 {
            travel += step;
        }
        previous_offset = offset;
        local_to_model(
            skeleton.parents(),
            &out.local,
            skeleton.scale_mode(),
            &mut model,
        );
        let world = feet.map(|f| Vec3::from(model[f].translation) + travel);
        // A foot is planted while it is within 5 mm of the ground contact height (the ankle
        // sits 6 cm up); a landing or lifting foot is not counted. The slide of one planted
        // run is how far the foot drifted from where it was put down.
        let stance = if world[0].y <= world[1].y { 0 } else { 1 };
        let planted = world[stance].y < CONTACT_HEIGHT + 0.005;
        match (run_start, planted) {
            (Some((foot, _)), true) if foot == stance => {}
            _ => {
                if let (Some((_, start)), Some((_, end))) = (run_start, last) {
                    slide += Vec3::new(end.x - start.x, 0.0, end.z - start.z).length();
                }
                run_start = planted.then_some((stance, world[stance]));
            }
        }
        last = planted.then_some((stance, world[stance]));
    }
    slide
}

#[test]
fn feet_do_not_slide_in_a_synchronised_blend() {
    let walk = foot_slide(0.0, true);
    let run = foot_slide(1.0, true);
    let half = foot_slide(0.5, true);
    let naive = foot_slide(0.5, false);
    println!("slide per cycle: walk {walk}, run {run}, half {half}, naive half {naive}");
    assert!(walk < 0.05 && run < 0.05, "walk {walk}, run {run}");
    assert!(half < 0.05, "half {half}");
    assert!(naive > 3.0 * half, "naive {naive} vs synchronised {half}");
}

#[test]
fn the_speed_slider_picks_the_weight() {
    let (_, walk, run) = clips();
    let (ra, rb) = (RootMotion::from_clip(&walk), RootMotion::from_clip(&run));
    let (_, _, v_walk) = synchronised_cycle(&ra, &rb, 0.0);
    let (_, _, v_run) = synchronised_cycle(&ra, &rb, 1.0);
    assert!(
        v_run > v_walk && v_walk > 0.3,
        "walk {v_walk} m/s, run {v_run} m/s"
    );
    for k in 0..=10 {
        let w = k as f32 / 10.0;
        let (_, _, v) = synchronised_cycle(&ra, &rb, w);
        assert!((weight_for_speed(&ra, &rb, v) - w).abs() < 1e-4);
    }
    assert_eq!(weight_for_speed(&ra, &rb, 0.0), 0.0);
    assert_eq!(weight_for_speed(&ra, &rb, 100.0), 1.0);
}

/// The path length of the planted feet over one cycle of `clip` played alone with root motion
/// applied, metres: every horizontal step of an ankle that stays within 5 mm of the contact
/// height, sampled at 400 steps (so a foot that drifts sideways and back counts twice, as the
/// figure's footprints do).
fn planted_path(skeleton: &Skeleton, clip: &Clip) -> f32 {
    let motion = RootMotion::from_clip(clip);
    let feet = [
        skeleton.find("foot.L").unwrap(),
        skeleton.find("foot.R").unwrap(),
    ];
    let mut pose = skeleton.rest_pose();
    let mut model = vec![Affine3A::IDENTITY; skeleton.len()];
    let mut last: [Option<Vec3>; 2] = [None, None];
    let mut path = 0.0;
    let steps = 400;
    for k in 0..=steps {
        let t = clip.duration_sec() * (1.0 + k as f32 / steps as f32);
        clip.sample(t, &mut ClipCursor::new(), &mut pose);
        let origin = motion.position(t, motion.extract(&mut pose));
        local_to_model(
            skeleton.parents(),
            &pose.local,
            skeleton.scale_mode(),
            &mut model,
        );
        for (f, &joint) in feet.iter().enumerate() {
            let p = Vec3::from(model[joint].translation) + origin;
            if p.y < CONTACT_HEIGHT + 0.005 {
                if let Some(q) = last[f] {
                    path += Vec3::new(p.x - q.x, 0.0, p.z - q.z).length();
                }
                last[f] = Some(p);
            } else {
                last[f] = None;
            }
        }
    }
    path
}

#[test]
fn a_planted_foot_holds_still_sideways_too() {
    // The travelling clips' root keys cancel the stance foot's whole horizontal step. They used
    // to cancel its forward (z) step only, and the pelvis's yaw swung the planted foot sideways:
    // the walk alone slid 5.5 cm per cycle (5 cm in the figure's 1.5 s), out and back, so
    // a test of where a stance ends against where it began did not see it.
    let (skeleton, walk, run) = clips();
    for (name, clip) in [("walk", &walk), ("run", &run)] {
        let path = planted_path(&skeleton, clip);
        // What is left (about 1 cm) is the in-betweens: the root moves linearly between keys, the
        // foot along an arc.
        assert!(
            path < 0.015,
            "{name}: planted feet moved {path} m in one cycle"
        );
        let motion = RootMotion::from_clip(clip);
        assert!(
            motion.cycle_travel.x.abs() < 1e-4,
            "{name} goes straight: {:?}",
            motion.cycle_travel
        );
    }
}
