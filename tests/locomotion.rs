//! Locomotion: synchronised blends at normalised time, root motion, and feet that do not slide.

use glam::{Affine3A, Vec3};
use inbetween::skeleton::{
    blend_contacts, human, local_to_model, sample_synchronised, synchronised_contacts,
    synchronised_cycle, weight_for_speed, Clip, ClipCursor, ClipError, Contact, JointTracks, Pose,
    RawClip, RootMotion, Skeleton,
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

/// How far the planted foot slides over one blended cycle with root motion applied, metres,
/// sampled at 400 steps; `synchronised: false` samples both clips at the same clock time instead
/// of the same phase. The planted foot is the clips' contact, blended as the poses are
/// ([`synchronised_contacts`], [`blend_contacts`]).
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
    let mut planted = [false; 2];
    for k in 0..=steps {
        let time = cycle * k as f32 / steps as f32;
        let offset = if synchronised {
            let phase = time / cycle;
            let offset = sample_synchronised(
                &walk,
                &run,
                w,
                phase,
                &mut cursors,
                &mut scratch,
                Some([&ra, &rb]),
                &mut out,
            );
            synchronised_contacts(&walk, &run, w, phase, &mut planted);
            offset
        } else {
            // The naive blend: each clip at the same clock time.
            walk.sample(time, &mut cursors[0], &mut out);
            run.sample(time, &mut cursors[1], &mut scratch);
            blend_contacts(&walk, time, &run, time, w, &mut planted);
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
        // The travelling clips plant one foot at a time. The slide of one planted run is how
        // far the foot drifted from where it was put down.
        let stance = if planted[0] { 0 } else { 1 };
        let planted = planted[stance];
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
    // Each stance begins and ends at a key, where the root keys cancel the planted foot's step
    // exactly: a clip alone drifts a fraction of a millimetre per cycle (0.14 mm the walk, 0.4
    // the run; 5 cm the walk with its sideways step left in). The synchronised half blend
    // drifts 6.5 mm (a blended foot is not the blend of the two feet), the naive one 28 cm.
    assert!(walk < 0.002 && run < 0.002, "walk {walk}, run {run}");
    assert!(half < 0.015, "half {half}");
    assert!(naive > 10.0 * half, "naive {naive} vs synchronised {half}");
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
/// applied, metres: every horizontal step of an ankle while the clip's contact plants it,
/// sampled at 400 steps (so a foot that drifts sideways and back counts twice, as the figure's
/// footprints do).
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
            if clip.in_contact(clip.contact_of(joint).unwrap(), t) {
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
    // The travelling clips' root keys cancel the stance foot's whole horizontal step. Root keys
    // that cancelled its forward (z) step only would leave the pelvis's yaw swinging the planted
    // foot sideways: the walk alone would slide 5.5 cm per cycle (5 cm in the figure's 1.5 s),
    // out and back, which a test of where a stance ends against where it began does not see.
    let (skeleton, walk, run) = clips();
    for (name, clip) in [("walk", &walk), ("run", &run)] {
        let path = planted_path(&skeleton, clip);
        // What is left is the in-betweens: the root moves linearly between keys, the foot along
        // an arc. Over the whole stance (the clip's contacts) that is 2.3 cm per cycle for the
        // walk and 7.1 cm for the run, whose foot moves faster; with the sideways step left in,
        // the walk's would be 20 cm. (Counting only the lowest 5 mm of each stance, about 1 cm.)
        let bound = if name == "walk" { 0.03 } else { 0.09 };
        assert!(
            path < bound,
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

#[test]
fn each_foot_is_planted_for_half_the_cycle_one_at_a_time() {
    // The travelling clips record which foot is planted (the one whose step the root keys
    // cancel): the left foot, then the right, each over the segments where its ankle is the
    // lower one. The gait is symmetric, so each foot stands for half the cycle, and one foot
    // is always down (the built-in gaits have no flight phase in their keys).
    let (skeleton, walk, run) = clips();
    let feet = [
        skeleton.find("foot.L").unwrap(),
        skeleton.find("foot.R").unwrap(),
    ];
    for (name, clip) in [("walk", &walk), ("run", &run)] {
        let contacts = clip.contacts();
        assert_eq!(contacts.len(), 2, "{name}");
        for (c, &foot) in contacts.iter().zip(&feet) {
            assert_eq!(c.joint(), foot, "{name}");
            let fraction = c.stance_sec() / clip.duration_sec();
            assert!(
                (0.45..=0.55).contains(&fraction),
                "{name}: {} planted {fraction} of the cycle",
                skeleton.names()[foot]
            );
            // Stances begin and end at keys.
            for iv in c.intervals() {
                for end in iv {
                    assert!(
                        clip.key_times().iter().any(|k| (k - end).abs() < 1e-6),
                        "{name}: a stance ends at {end} s, not at a key"
                    );
                }
            }
        }
        let samples = 1000;
        let mut counts = [0usize; 2];
        let mut heights = [f32::INFINITY, 0.0f32];
        let mut pose = skeleton.rest_pose();
        let mut model = vec![Affine3A::IDENTITY; skeleton.len()];
        for k in 0..samples {
            let t = clip.duration_sec() * (k as f32 + 0.5) / samples as f32;
            let planted = [0, 1].map(|i| clip.in_contact(i, t));
            assert!(
                planted[0] != planted[1],
                "{name} at {t} s: planted {planted:?}"
            );
            // The same one cycle later and earlier: the contacts loop with the clip.
            for shift in [-1.0, 1.0, 3.0] {
                let later = t + shift * clip.duration_sec();
                assert_eq!([0, 1].map(|i| clip.in_contact(i, later)), planted);
            }
            clip.sample(t, &mut ClipCursor::new(), &mut pose);
            local_to_model(
                skeleton.parents(),
                &pose.local,
                skeleton.scale_mode(),
                &mut model,
            );
            let f = if planted[0] { 0 } else { 1 };
            counts[f] += 1;
            let y = model[feet[f]].translation.y;
            heights = [heights[0].min(y), heights[1].max(y)];
        }
        for count in counts {
            let fraction = count as f32 / samples as f32;
            assert!((0.45..=0.55).contains(&fraction), "{name}: {counts:?}");
        }
        // Why contacts, not a height: the planted ankle does not stay at one height. It sits
        // 6 cm up with the foot flat and rises by about 3 cm as the pelvis bobs and the leg
        // swings under it, so "within 5 mm of 6 cm" would plant the walk's feet for a seventh
        // of the samples at mid speeds.
        assert!(
            (0.05..0.065).contains(&heights[0]) && heights[1] > 0.08,
            "{name}: planted ankle between {heights:?} m"
        );
    }
}

#[test]
fn contacts_follow_the_phase_in_a_synchronised_blend() {
    let (_, walk, run) = clips();
    let mut planted = [false; 2];
    let mut blended = [false; 2];
    for k in 0..200 {
        let phase = (k as f32 + 0.25) / 200.0;
        let own = |clip: &Clip| [0, 1].map(|i| clip.in_contact(i, phase * clip.duration_sec()));
        // The walk and the run plant the same foot at the same phase (not at the same time).
        assert_eq!(own(&walk), own(&run), "phase {phase}");
        for (w, want) in [(0.0, own(&walk)), (0.4, own(&walk)), (1.0, own(&run))] {
            synchronised_contacts(&walk, &run, w, phase, &mut planted);
            assert_eq!(planted, want, "w = {w}, phase {phase}");
        }
        // A phase is the same one cycle on.
        synchronised_contacts(&walk, &run, 0.6, phase + 2.0, &mut blended);
        synchronised_contacts(&walk, &run, 0.6, phase, &mut planted);
        assert_eq!(blended, planted);
    }
}

#[test]
fn blended_contacts_are_a_weighted_vote() {
    // Two one-joint clips that plant their joint at different times: the heavier clip decides,
    // and at w = 1/2 either one plants it.
    let (skeleton, _) = human::simple_human();
    let tracks = vec![JointTracks::default(); skeleton.len()];
    let clip = |intervals: Vec<[f32; 2]>| {
        let raw = RawClip::new("c", 1.0, true, tracks.clone())
            .unwrap()
            .with_contacts(vec![Contact::new(15, intervals).unwrap()])
            .unwrap();
        Clip::from_raw(&raw, &skeleton).unwrap()
    };
    let a = clip(vec![[0.0, 0.5]]);
    let b = clip(vec![[0.5, 1.0]]);
    let mut out = [false];
    for (w, t, want) in [
        (0.0, 0.25, true),
        (0.3, 0.25, true),
        (0.7, 0.25, false),
        (0.5, 0.25, true),
        (0.3, 0.75, false),
        (0.7, 0.75, true),
        (1.0, 0.75, true),
        (0.5, 0.75, true),
    ] {
        blend_contacts(&a, t, &b, t, w, &mut out);
        assert_eq!(out[0], want, "w = {w}, t = {t}");
    }
    // Each clip at its own time: a at 0.25 (planted), b at 0.25 (not).
    blend_contacts(&a, 0.25, &b, 0.75, 1.0, &mut out);
    assert!(out[0]);
    // A joint clip b has no contact for is lifted in b.
    let none = Clip::from_raw(
        &RawClip::new("n", 1.0, true, tracks.clone()).unwrap(),
        &skeleton,
    )
    .unwrap();
    blend_contacts(&a, 0.25, &none, 0.25, 0.6, &mut out);
    assert!(!out[0]);
    // A looping clip's duration is its time 0; [start, end) excludes the end.
    assert!(a.in_contact(0, 1.0) && a.in_contact(0, 0.0) && !a.in_contact(0, 0.5));
}

#[test]
fn bad_contacts_are_errors() {
    let bad = |r: Result<Contact, ClipError>| matches!(r, Err(ClipError::BadContact { .. }));
    assert!(bad(Contact::new(0, vec![[0.5, 0.2]])));
    assert!(bad(Contact::new(0, vec![[0.0, f32::NAN]])));
    assert!(bad(Contact::new(0, vec![[0.0, 0.5], [0.4, 0.8]])));
    assert!(Contact::new(0, vec![[0.0, 0.5], [0.5, 0.8]]).is_ok());
    let (skeleton, _) = human::simple_human();
    let raw = RawClip::new("c", 1.0, true, vec![JointTracks::default(); skeleton.len()]).unwrap();
    let late = raw
        .clone()
        .with_contacts(vec![Contact::new(3, vec![[0.5, 1.5]]).unwrap()]);
    let message = late.unwrap_err().to_string();
    assert!(
        message.contains("joint 3") && message.contains("outside the clip [0, 1] s"),
        "{message}"
    );
    let missing = raw.with_contacts(vec![Contact::new(99, vec![[0.0, 0.5]]).unwrap()]);
    assert!(missing.unwrap_err().to_string().contains("21 joints"));
}
