//! Lesson 08 figure logic: validation, what the mask and the additive layer do, the student's
//! 6.3 in the blend figure, and feet that slide only when the blend is not synchronised.

use glam::Vec3;
use inbetween::draw::Frame;
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::blending::{BlendFigure, LocomotionFigure, LOCOMOTION_PLOT_RANGES};
use inbetween::skeleton::{human, Clip, ClipCursor};

#[test]
fn bad_input_is_an_error_naming_the_parameter() {
    let mut f = BlendFigure::new();
    assert!(f.set_weight(1.5).unwrap_err().contains("weight of B"));
    assert!(f.set_weight(f32::NAN).is_err());
    assert!(f.set_clips("walk", "tango").unwrap_err().contains("clip B"));
    assert!(f.set_mask("left arm").unwrap_err().contains("mask"));
    assert!(f
        .set_additive("jump", 1.0)
        .unwrap_err()
        .contains("additive layer"));
    assert!(f
        .set_additive("none", -1.0)
        .unwrap_err()
        .contains("layer weight"));
    assert!(f.pose(f32::INFINITY).unwrap_err().contains("time"));
    let mut l = LocomotionFigure::new();
    let e = l.set_speed(100.0).unwrap_err();
    assert!(
        e.contains("speed must lie between the walk's 0.57 and the run's 1.37 m/s, got 100"),
        "{e}"
    );
    assert!(l.draw(&mut Frame::default(), f32::NAN).is_err());
}

fn clip_pose(name: &str, time: f32) -> Vec<glam::Quat> {
    let (skeleton, _) = human::simple_human();
    let i = human::CLIP_NAMES.iter().position(|&c| c == name).unwrap();
    let clip = Clip::from_raw(&human::clip(&skeleton, i).unwrap(), &skeleton).unwrap();
    let mut pose = skeleton.rest_pose();
    clip.sample(time, &mut ClipCursor::new(), &mut pose);
    pose.local.iter().map(|x| x.rotation).collect()
}

fn rotations(f: &BlendFigure) -> Vec<glam::Quat> {
    f.local_pose().local.iter().map(|x| x.rotation).collect()
}

fn close(a: &[glam::Quat], b: &[glam::Quat]) -> bool {
    a.iter().zip(b).all(|(x, y)| x.dot(*y).abs() > 1.0 - 1e-6)
}

#[test]
fn weights_0_and_1_and_the_masks() {
    let mut f = BlendFigure::new();
    f.set_clips("walk", "wave").unwrap();
    f.set_weight(0.0).unwrap();
    f.pose(0.3).unwrap();
    assert!(
        close(&rotations(&f), &clip_pose("walk", 0.3)),
        "weight 0: clip A"
    );
    f.set_weight(1.0).unwrap();
    f.pose(0.3).unwrap();
    // The 2 s wave at the walk's phase 0.3 (of a 1 s cycle): 0.6 s.
    assert!(
        close(&rotations(&f), &clip_pose("wave", 0.6)),
        "weight 1: clip B at the same phase"
    );
    // Upper body from B: the legs keep the walk, the arms wave.
    f.set_mask("upper body from B").unwrap();
    f.pose(0.3).unwrap();
    let (skeleton, _) = human::simple_human();
    let r = rotations(&f);
    let (walk, wave) = (clip_pose("walk", 0.3), clip_pose("wave", 0.6));
    for name in ["thigh.L", "shin.R", "pelvis"] {
        let j = skeleton.find(name).unwrap();
        assert!(
            r[j].dot(walk[j]).abs() > 1.0 - 1e-6,
            "{name} keeps the walk"
        );
    }
    let arm = skeleton.find("upper_arm.R").unwrap();
    assert!(r[arm].dot(wave[arm]).abs() > 1.0 - 1e-6, "the arm waves");
    assert_eq!(f.joint_weights()[skeleton.find("pelvis").unwrap()], 0.0);
    f.set_mask("lower body from B").unwrap();
    assert_eq!(f.joint_weights()[skeleton.find("head").unwrap()], 0.0);
    assert_eq!(f.joint_weights()[skeleton.find("thigh.L").unwrap()], 1.0);
}

#[test]
fn the_additive_layer_adds_on_top() {
    let mut f = BlendFigure::new();
    f.set_weight(0.0).unwrap();
    f.pose(0.3).unwrap();
    let base = rotations(&f);
    f.set_additive("lean forward (a pose)", 0.0).unwrap();
    f.pose(0.3).unwrap();
    assert!(close(&rotations(&f), &base), "weight 0 changes nothing");
    f.set_additive("lean forward (a pose)", 1.0).unwrap();
    let note = f.pose(0.3).unwrap();
    assert!(note.contains("Additive layer: lean forward"), "{note}");
    // Figure 2's note names its own controls (base clip, layer weight): it has no clip B.
    assert!(
        note.starts_with("Base clip: walk, played alone") && note.contains("layer weight 1"),
        "{note}"
    );
    assert!(!note.contains("weight of B"), "{note}");
    let (skeleton, _) = human::simple_human();
    let spine = skeleton.find("spine").unwrap();
    let thigh = skeleton.find("thigh.L").unwrap();
    let leaned = rotations(&f);
    assert!(
        leaned[spine].angle_between(base[spine]) > 0.3,
        "the spine leans"
    );
    assert!(
        leaned[thigh].dot(base[thigh]).abs() > 1.0 - 1e-6,
        "the legs still walk"
    );
    f.set_additive("wave (a clip)", 1.0).unwrap();
    f.pose(0.3).unwrap();
    let arm = skeleton.find("upper_arm.R").unwrap();
    assert!(
        rotations(&f)[arm].angle_between(base[arm]) > 1.0,
        "the arm goes up while walking"
    );
    assert!(rotations(&f)[thigh].dot(base[thigh]).abs() > 1.0 - 1e-6);
}

#[test]
fn the_note_reports_the_students_crossfade() {
    let mut f = BlendFigure::new();
    f.set_use_exercise(true);
    let note = f.pose(0.3).unwrap();
    if cfg!(feature = "solutions") {
        assert!(
            note.contains("Your crossfade_joint matches the reference at all 21 joints"),
            "{note}"
        );
    } else {
        assert!(note.contains("Not done yet: exercise 6.3"), "{note}");
    }
    fn correct(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        if name != "crossfade_joint" {
            return direct(name, args);
        }
        let (ta, qa) = (
            Vec3::from_slice(&args[0..3]),
            glam::Quat::from_slice(&args[3..7]),
        );
        let (tb, qb) = (
            Vec3::from_slice(&args[7..10]),
            glam::Quat::from_slice(&args[10..14]),
        );
        let (t, q) =
            inbetween::exercises::skeleton::reference_crossfade_joint(ta, qa, tb, qb, args[14]);
        Ok([t.to_array().as_slice(), q.to_array().as_slice()].concat())
    }
    f.set_runner(correct);
    let note = f.pose(0.3).unwrap();
    assert!(
        note.contains("Your crossfade_joint matches the reference at all 21 joints"),
        "{note}"
    );
    // Forgetting the sign test: wrong where the two rotations are in opposite hemispheres, or
    // simply a plain lerp without normalising.
    fn unnormalised(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        let mut out = correct(name, args)?;
        if name == "crossfade_joint" {
            for x in &mut out[3..7] {
                *x *= 0.9;
            }
        }
        Ok(out)
    }
    f.set_runner(unnormalised);
    let note = f.pose(0.3).unwrap();
    assert!(
        note.contains("Your crossfade_joint differs at joint 0 (pelvis)"),
        "{note}"
    );
}

#[test]
fn feet_slide_only_without_synchronisation_and_root_motion_moves_the_character() {
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    let (lo, hi) = l.speed_range();
    assert!(hi > lo && lo > 0.3);
    let mut slides = Vec::new();
    for synchronised in [true, false] {
        l.set_synchronised(synchronised);
        let mut worst = 0.0f32;
        for k in 0..8 {
            l.draw(&mut frame, 2.0 + 0.37 * k as f32).unwrap();
            worst = worst.max(l.slide_m());
        }
        slides.push(worst);
    }
    // Synchronised, what is left is the in-betweens and the blend itself (a blended foot is not
    // the blend of the two clips' feet): about 7 cm in 1.5 s over the whole stance. Not
    // synchronised, the feet slide metres.
    assert!(slides[0] < 0.09, "synchronised: {} m", slides[0]);
    assert!(slides[1] > 10.0 * slides[0], "{slides:?}");
    l.set_synchronised(true);
    l.draw(&mut frame, 3.0).unwrap();
    let at3 = l.origin();
    l.draw(&mut frame, 13.0).unwrap();
    // Within a cycle the root surges and drops back; over ten seconds it averages out.
    let speed = 0.5 * (lo + hi);
    let went = (l.origin() - at3).length();
    assert!(
        (went - 10.0 * speed).abs() < 0.05 * 10.0 * speed,
        "{went} m in 10 s at {speed} m/s"
    );
    assert!(!l.footprints().is_empty());
    l.set_root_motion(false);
    let note = l.draw(&mut frame, 4.0).unwrap();
    assert_eq!(l.origin(), Vec3::ZERO);
    assert!(note.contains("snaps back"), "{note}");
}

#[test]
fn unsynchronised_travel_never_jumps_a_cycle_at_a_loop() {
    // Each clip's cycle count and clip-local time come from one division: a clip's own wrap
    // (rem_euclid) and the cycle count (floor of t / d) can disagree in f32 at some loop times,
    // which would make the character jump a whole cycle (about 1 m) for that instant and the
    // footprints' slide count the jump (97 cm for the run alone, not synchronised).
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    let (lo, hi) = l.speed_range();
    l.set_synchronised(false);
    for speed in [lo, 0.5 * (lo + hi), hi] {
        l.set_speed(speed).unwrap();
        let mut last: Option<Vec3> = None;
        for k in 0..=2400 {
            let t = k as f32 / 240.0;
            l.draw(&mut frame, t).unwrap();
            if let Some(p) = last {
                let step = l.origin().z - p.z;
                assert!(
                    step.abs() < 0.05,
                    "speed {speed}: the character moved {step} m between {} s and {t} s",
                    t - 1.0 / 240.0
                );
            }
            last = Some(l.origin());
        }
    }
    // The run alone slides as little unsynchronised as synchronised.
    l.set_speed(hi).unwrap();
    for t in [2.0, 3.3, 5.0, 6.1] {
        l.set_synchronised(true);
        l.draw(&mut frame, t).unwrap();
        let synced = l.slide_m();
        l.set_synchronised(false);
        l.draw(&mut frame, t).unwrap();
        assert!(
            (l.slide_m() - synced).abs() < 0.02,
            "at {t} s the run alone slid {} m unsynchronised, {synced} m synchronised",
            l.slide_m()
        );
    }
}

#[test]
fn body_parts_are_coloured_by_the_weight_of_b_alone() {
    // The figure's colours say which parts take clip B and how much: every part with the same
    // weight has the same colour, grey for A only and teal for B only. A 70 % teal tint over
    // each part's own colour would not do: the blue shirt and trousers hide it (the legs taking
    // B would look like the shirt taking nothing).
    use inbetween::draw::palette;
    let mut f = BlendFigure::new();
    f.set_clips("walk", "wave").unwrap();
    f.set_mask("upper body from B").unwrap();
    f.set_weight(1.0).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, 0.3).unwrap();
    let n = f.skeleton().len();
    let weights = f.joint_weights().to_vec();
    // The first n meshes are the body parts, one per joint, in joint order.
    let colors: Vec<Vec3> = frame.meshes[..n]
        .iter()
        .map(|m| m.color.truncate())
        .collect();
    for j in 0..n {
        let want = BlendFigure::weight_color(weights[j]);
        assert!(
            colors[j].distance(want) < 1e-4,
            "{}: {:?}, want {want:?} (weight {})",
            f.skeleton().names()[j],
            colors[j],
            weights[j]
        );
    }
    let chest = f.skeleton().find("chest").unwrap();
    let thigh = f.skeleton().find("thigh.L").unwrap();
    assert_eq!((weights[chest], weights[thigh]), (1.0, 0.0));
    assert!(colors[chest].distance(palette::TEAL) < 1e-4);
    assert!(colors[thigh].distance(palette::GREY) < 1e-4);
}

#[test]
fn the_synchronised_try_this_is_what_the_note_says() {
    // Lesson 08's "Try this" under Figure 2: at the default speed the note's slide is a few
    // centimetres synchronised and most of a metre (at times over a metre) not synchronised.
    // (The clips' contacts plant a foot for its whole stance; counting only the lowest 5 mm of
    // each stance as planted, about a seventh of the samples, it would read a few millimetres.)
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    let times: Vec<f32> = (0..12).map(|k| 1.5 + 0.53 * k as f32).collect();
    let mut worst = [0.0f32; 2];
    let mut least = [f32::INFINITY; 2];
    for (i, synchronised) in [true, false].into_iter().enumerate() {
        l.set_synchronised(synchronised);
        for &t in &times {
            let note = l.draw(&mut frame, t).unwrap();
            assert!(
                note.contains(&format!(
                    "slid {:.1} cm in the last 1.5 s.",
                    l.slide_m() * 100.0
                )),
                "{note}"
            );
            worst[i] = worst[i].max(l.slide_m());
            least[i] = least[i].min(l.slide_m());
        }
    }
    assert!(
        least[0] > 0.01 && worst[0] < 0.09,
        "synchronised: {} to {} m",
        least[0],
        worst[0]
    );
    assert!(
        least[1] > 0.5 && worst[1] > 1.0 && worst[1] < 1.5,
        "not synchronised: {} to {} m",
        least[1],
        worst[1]
    );
}

#[test]
fn each_clip_alone_leaves_its_planted_feet_in_place() {
    // At the ends of the speed range one clip plays alone, synchronised or not: the root keys
    // cancel the planted foot's step at every key, and what is left is the in-betweens (the
    // root moves in a line between keys, the foot along an arc): about 1.7 cm in 1.5 s for the
    // walk and 5 to 7 cm for the faster run, counted over the whole stance. (Counting only
    // the lowest 5 mm of each stance, the walk would read 0.3 cm.) Root keys that cancelled only
    // the stance foot's forward step, not its sideways one, would let the walk slide 28 cm and
    // the run 70 cm in 1.5 s.
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    let (lo, hi) = l.speed_range();
    for speed in [lo, hi] {
        l.set_speed(speed).unwrap();
        for synchronised in [true, false] {
            l.set_synchronised(synchronised);
            for t in [2.0, 3.3, 5.0, 6.1] {
                l.draw(&mut frame, t).unwrap();
                let bound = if speed == lo { 0.025 } else { 0.08 };
                assert!(
                    l.slide_m() < bound,
                    "{speed} m/s, synchronised {synchronised}, at {t} s: {} m",
                    l.slide_m()
                );
            }
        }
    }
}

#[test]
fn the_snap_back_at_a_loop_is_not_counted_as_sliding() {
    // With root motion left in the pose the character jumps back a cycle's travel at every loop.
    // The note's slide does not count that jump as the planted foot sliding (it would add about
    // 77 cm at the default speed, synchronised): it is measured where the travel has taken the
    // feet, so it is the same with root motion on or off, and the note gives the jump on its own.
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    for synchronised in [true, false] {
        l.set_synchronised(synchronised);
        // Every 1.5 s window holds at least one loop of each clip.
        for t in [1.6, 2.0, 3.3, 5.05, 6.1, 7.9] {
            l.set_root_motion(true);
            l.draw(&mut frame, t).unwrap();
            let on = l.slide_m();
            l.set_root_motion(false);
            let note = l.draw(&mut frame, t).unwrap();
            assert!(
                (l.slide_m() - on).abs() < 1e-3,
                "synchronised {synchronised}, {t} s: {} m with root motion off, {on} m on",
                l.slide_m()
            );
            assert!(note.contains("(a jump, not counted as sliding)"), "{note}");
        }
    }
    // Nor is it drawn as a trail: synchronised, a planted foot's trail is as long with root
    // motion off as on (the snap leaves two dots, not a line as long as the jump).
    l.set_synchronised(true);
    for t in [1.6, 2.0, 3.3, 5.05, 6.1, 7.9] {
        l.set_root_motion(true);
        l.draw(&mut frame, t).unwrap();
        let on = longest_trail(&l);
        l.set_root_motion(false);
        l.draw(&mut frame, t).unwrap();
        let off = longest_trail(&l);
        assert!(
            on < 0.1 && (off - on).abs() < 0.01,
            "{t} s: trail {off} m off, {on} m on"
        );
    }
    l.set_synchronised(true);
    let note = l.draw(&mut frame, 2.0).unwrap();
    let snap = l.snap_back_m()[0];
    assert!(snap > 0.5 && snap < 1.0, "{snap} m");
    assert!(
        note.contains(&format!("snaps back {:.0} cm (a jump", snap * 100.0)),
        "{note}"
    );
    l.set_synchronised(false);
    let note = l.draw(&mut frame, 2.0).unwrap();
    let [walk, run] = l.snap_back_m();
    // Each clip's share of the blended cycle's travel, at its own loop.
    assert!(walk > 0.1 && run > 0.1 && (walk + run - snap).abs() < 1e-5);
    assert!(
        note.contains(&format!(
            "snaps back {:.0} cm at each loop of the walk and {:.0} cm at each loop of the run",
            walk * 100.0,
            run * 100.0
        )),
        "{note}"
    );
}

#[test]
fn the_plot_shows_the_notes_slide_and_how_far_out_of_step_the_clips_are() {
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    l.set_synchronised(false);
    let rows: Vec<[f32; 5]> = l
        .plot_samples()
        .chunks(5)
        .map(|r| r.try_into().unwrap())
        .collect();
    // Every 25 ms over the 8 s timeline; the figure's own setting is left alone.
    assert_eq!(rows.len(), 321);
    assert_eq!(rows[0][0], 0.0);
    assert!((rows[320][0] - 8.0).abs() < 1e-4);
    let note = l.draw(&mut frame, 2.0).unwrap();
    assert!(
        note.contains("At the same clock time (right, red footprints), they slid"),
        "{note}"
    );
    l.set_compare(false);
    assert!(l
        .draw(&mut frame, 2.0)
        .unwrap()
        .contains("not synchronised"));
    l.set_compare(true);
    for (k, row) in rows.iter().enumerate() {
        let [t, gap_on, gap_off, slide_on, slide_off] = *row;
        assert_eq!(gap_on, 0.0, "synchronised clips are always in step");
        assert!((0.0..=0.5).contains(&gap_off), "{gap_off} at {t} s");
        assert!(slide_on < 9.0, "synchronised: {slide_on} cm at {t} s");
        // The playhead's value is the note's, in both settings.
        if k % 16 == 3 {
            for (synchronised, want) in [(true, slide_on), (false, slide_off)] {
                l.set_synchronised(synchronised);
                l.draw(&mut frame, t).unwrap();
                assert!(
                    (l.slide_m() * 100.0 - want).abs() < 0.05,
                    "at {t} s synchronised {synchronised}: note {} cm, plot {want} cm",
                    l.slide_m() * 100.0
                );
                assert_eq!(l.phase_gap(t), if synchronised { 0.0 } else { gap_off });
                // Side by side, each lane's slide is its plot line's.
                let [on, off] = l.slides_m().map(|m| m * 100.0);
                assert!((on - slide_on).abs() < 0.05 && (off - slide_off).abs() < 0.05);
            }
        }
    }
    // Not synchronised, the clips drift in and out of step (a 1 s and a 0.7 s cycle meet
    // every 2.33 s) and the slide rises and falls with them.
    let off: Vec<f32> = rows.iter().map(|r| r[4]).collect();
    let (lo, hi) = off[60..]
        .iter()
        .fold((f32::INFINITY, 0.0f32), |(a, b), &x| (a.min(x), b.max(x)));
    // The caption: "between about 70 cm and 1.4 m" at the default speed, never near the
    // synchronised 7 cm ("about 7 cm").
    assert!(hi > 1.8 * lo && lo > 30.0, "{lo} to {hi} cm");
    assert!(
        (65.0..75.0).contains(&lo) && (135.0..145.0).contains(&hi),
        "{lo} to {hi} cm"
    );
    let on: Vec<f32> = rows[60..].iter().map(|r| r[3]).collect();
    assert!(on.iter().all(|&x| (6.0..8.0).contains(&x)), "{on:?}");
    let gaps: Vec<f32> = rows.iter().map(|r| r[2]).collect();
    assert!(gaps.iter().any(|&g| g < 0.02) && gaps.iter().any(|&g| g > 0.48));
    // The Try this: the slide peaks half a second to a second after the gap reaches half a
    // cycle (the note sums the last 1.5 s). Gap peaks at 1.17, 3.5 and 5.83 s.
    let mut peaks = 0;
    for k in 1..rows.len() - 1 {
        if gaps[k] > 0.45 && gaps[k] >= gaps[k - 1] && gaps[k] >= gaps[k + 1] {
            peaks += 1;
            let (at, best) = (k + 1..(k + 49).min(rows.len()))
                .map(|i| (i, off[i]))
                .fold((k, off[k]), |a, b| if b.1 > a.1 { b } else { a });
            let lag = rows[at][0] - rows[k][0];
            assert!(
                (0.4..=1.2).contains(&lag) && best > 1.25 * off[k],
                "gap peak at {} s: slide {} cm there, {best} cm {lag} s later",
                rows[k][0],
                off[k]
            );
        }
    }
    assert_eq!(peaks, 3);
}

#[test]
fn the_plots_fixed_ranges_hold_every_speed() {
    // The plots' y ranges are fixed (so the Try this's "both slide lines lie flat" at the walk's
    // speed is what the reader sees; autoscaled, a 2 cm slide would fill the plot). They must hold
    // the samples at every speed, and not be so large that the largest slide looks small.
    let [gap_lo, gap_hi, slide_lo, slide_hi] = LOCOMOTION_PLOT_RANGES;
    let mut l = LocomotionFigure::new();
    let (lo, hi) = l.speed_range();
    let mut largest = 0.0f32;
    for k in 0..=20 {
        let speed = lo + (hi - lo) * k as f32 / 20.0;
        l.set_speed(speed).unwrap();
        for row in l.plot_samples().chunks(5) {
            assert!(row[1..3].iter().all(|g| (gap_lo..=gap_hi).contains(g)));
            assert!(row[3..5].iter().all(|x| (slide_lo..=slide_hi).contains(x)));
            largest = largest.max(row[4]);
            // The caption: synchronised, the slide is a few centimetres at every speed.
            assert!(row[3] < 9.0, "synchronised at {speed} m/s: {} cm", row[3]);
        }
    }
    assert!(largest > 0.85 * slide_hi, "largest slide {largest} cm");
    assert!(gap_lo < 0.0 && slide_lo < 0.0 && gap_hi > 0.5);
    // At the slider's left end (0.58 m/s, run weight 0.01) both lines lie low on that scale.
    l.set_speed(0.58).unwrap();
    let flat = l
        .plot_samples()
        .chunks(5)
        .map(|r| r[3].max(r[4]))
        .fold(0.0f32, f32::max);
    assert!(flat < 0.03 * slide_hi, "{flat} cm at 0.58 m/s");
}

#[test]
fn footprints_and_slide_follow_the_clips_contacts() {
    // Which foot is planted comes from the travelling clips' contacts, blended as the poses
    // are, not from the ankle's height: a rule such as "within 5 mm of 6 cm" would lose a stance
    // ankle that rises to 8.7 cm, and plant a foot for only about a seventh of the samples at
    // mid speeds.
    use inbetween::skeleton::{blend_contacts, synchronised_cycle, RootMotion};
    let (skeleton, _) = human::simple_human();
    let clip = |i| {
        Clip::from_raw(
            &human::travelling_clip(&skeleton, i, 25).unwrap(),
            &skeleton,
        )
    };
    let (walk, run) = (clip(1).unwrap(), clip(2).unwrap());
    let motion = [RootMotion::from_clip(&walk), RootMotion::from_clip(&run)];
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    let (lo, hi) = l.speed_range();
    for speed in [lo, 0.5 * (lo + hi), hi] {
        l.set_speed(speed).unwrap();
        let w = l.weight();
        let (cycle, _, _) = synchronised_cycle(&motion[0], &motion[1], w);
        for synchronised in [true, false] {
            l.set_synchronised(synchronised);
            let t = 3.1;
            l.draw(&mut frame, t).unwrap();
            let drawn = l.footprint_feet().to_vec();
            assert_eq!(drawn.len(), l.footprints().len());
            // The draw's samples: 61 over the last 1.5 s.
            let mut want = Vec::new();
            for k in 0..=60 {
                let s = t - 1.5 * (1.0 - k as f32 / 60.0);
                let planted = l.planted_at(s);
                // The clips' own contacts: at the same phase, or at each clip's own time.
                let (ta, tb) = if synchronised {
                    let phase = (s / cycle).rem_euclid(1.0);
                    (phase * walk.duration_sec(), phase * run.duration_sec())
                } else {
                    (s, s)
                };
                let mut expected = [false; 2];
                blend_contacts(&walk, ta, &run, tb, w, &mut expected);
                assert_eq!(
                    planted, expected,
                    "{speed} m/s, synchronised {synchronised}, {s} s"
                );
                want.extend((0..2).filter(|&f| planted[f]));
            }
            assert_eq!(drawn, want, "{speed} m/s, synchronised {synchronised}");
            // One foot is down at every sample (each clip plants one foot at a time; where the
            // two disagree at w = 1/2 both would count).
            if synchronised || w == 0.0 || w == 1.0 {
                assert_eq!(drawn.len(), 61);
            }
            // The footprints lie on the ground, wherever the ankle was.
            assert!(l.footprints().iter().all(|p| p.y.abs() < 0.01));
        }
    }
    // The slide counts the whole stance: the walk alone, at a speed where a height rule would
    // plant few samples, has a footprint for every sample and a slide of a centimetre or two
    // (the in-betweens), not the few millimetres a height rule would see.
    l.set_speed(lo).unwrap();
    l.set_synchronised(true);
    l.draw(&mut frame, 3.1).unwrap();
    assert!(
        (0.005..0.025).contains(&l.slide_m()),
        "walk alone: {} m",
        l.slide_m()
    );
}

#[test]
fn the_speed_sliders_rounded_ends_are_the_clips_own_speeds() {
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    let (lo, hi) = l.speed_range();
    // The slider's ends are the speeds rounded to 0.01 m/s (what the page's slider offers).
    let round = |v: f32| (v * 100.0).round() / 100.0;
    l.set_speed(round(lo)).unwrap();
    assert_eq!((l.speed(), l.weight()), (lo, 0.0));
    assert!(l
        .draw(&mut frame, 1.0)
        .unwrap()
        .contains("run weight 0.000 (the walk alone)"));
    l.set_speed(round(hi)).unwrap();
    assert_eq!((l.speed(), l.weight()), (hi, 1.0));
    assert!(l.draw(&mut frame, 1.0).unwrap().contains("(the run alone)"));
    // Past half a step from an end is still rejected.
    assert!(l.set_speed(lo - 0.006).is_err() && l.set_speed(hi + 0.006).is_err());
    l.set_speed(0.5 * (lo + hi)).unwrap();
    assert!(l.weight() > 0.0 && l.weight() < 1.0);
}

/// 8.1 with the classic slip: the weight linear in the speed (right at the two ends only).
fn linear_in_speed(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "weight_for_speed" => {
            let [da, ta, db, tb, v] = args.try_into().unwrap();
            let (va, vb) = (ta / da, tb / db);
            Ok(vec![((v - va) / (vb - va)).clamp(0.0, 1.0)])
        }
        _ => direct(name, args),
    }
}

/// 8.1 right inside the range but never clamped.
fn unclamped(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "weight_for_speed" => {
            let [da, ta, db, tb, v] = args.try_into().unwrap();
            Ok(vec![(v * da - ta) / ((tb - ta) - v * (db - da))])
        }
        _ => direct(name, args),
    }
}

fn reference_8_1(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "weight_for_speed" => {
            use inbetween::skeleton::{weight_for_speed, RootMotion};
            let [da, ta, db, tb, v] = args.try_into().unwrap();
            let m = |d: f32, t: f32| RootMotion {
                start: Vec3::ZERO,
                cycle_travel: Vec3::new(0.0, 0.0, t),
                duration_sec: d,
            };
            Ok(vec![weight_for_speed(&m(da, ta), &m(db, tb), v)])
        }
        _ => direct(name, args),
    }
}

fn panicking(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "attempt to divide by zero (src/exercises/blending.rs:40:9)".into(),
    ))
}

#[test]
fn the_note_checks_the_students_weight_at_this_speed_and_the_probes() {
    let mut l = LocomotionFigure::new();
    let mut frame = Frame::default();
    let reference = l.weight();
    l.set_runner(reference_8_1);
    l.set_use_exercise(true);
    let note = l.draw(&mut frame, 1.0).unwrap();
    assert!(
        note.contains("Your weight_for_speed (8.1) matches the reference at v = "),
        "{note}"
    );
    assert!(
        note.contains("It also matches at the probe speeds"),
        "{note}"
    );
    assert_eq!(l.weight(), reference);

    // Linear in the speed: wrong at the default (middle) speed, and the figure blends with it.
    l.set_runner(linear_in_speed);
    let note = l.draw(&mut frame, 1.0).unwrap();
    assert!(note.contains("differs at v = "), "{note}");
    assert!(
        note.contains("The figure blends with your weight"),
        "{note}"
    );
    assert!(
        (l.weight() - reference).abs() > 0.02,
        "{} {reference}",
        l.weight()
    );

    // Unclamped: right at this speed, wrong below the walk and above the run, and says so.
    l.set_runner(unclamped);
    let note = l.draw(&mut frame, 1.0).unwrap();
    assert!(note.contains("matches the reference at v = "), "{note}");
    assert!(
        note.contains("it differs at v = 0.300") && note.contains("v = 2.500"),
        "{note}"
    );
    assert!(
        !note.contains("v = 1.") || !note.contains("differs at v = 1."),
        "{note}"
    );

    // A panic: the reference blends, and the note says where.
    l.set_runner(panicking);
    let note = l.draw(&mut frame, 1.0).unwrap();
    assert!(
        note.contains("panicked") && note.contains("blending.rs:40:9"),
        "{note}"
    );
    assert_eq!(l.weight(), reference);

    // The stub (the plain direct runner in a build without solutions) is "not done yet".
    l.set_runner(direct);
    let note = l.draw(&mut frame, 1.0).unwrap();
    if !cfg!(feature = "solutions") {
        assert!(
            note.contains("Not done yet: exercise 8.1 weight_for_speed"),
            "{note}"
        );
    }
    l.set_use_exercise(false);
    assert!(!l.draw(&mut frame, 1.0).unwrap().contains("8.1"));
}

fn crossfade_args(args: &[f32]) -> (Vec3, glam::Quat, Vec3, glam::Quat, f32) {
    (
        Vec3::from_slice(&args[0..3]),
        glam::Quat::from_slice(&args[3..7]),
        Vec3::from_slice(&args[7..10]),
        glam::Quat::from_slice(&args[10..14]),
        args[14],
    )
}

/// 6.3 without the short-arc flip: right wherever a·b ≥ 0.
fn no_flip(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name != "crossfade_joint" {
        return direct(name, args);
    }
    let (ta, qa, tb, qb, w) = crossfade_args(args);
    let t = ta.lerp(tb, w);
    let q = glam::Quat::from_vec4(glam::Vec4::from(qa).lerp(glam::Vec4::from(qb), w)).normalize();
    Ok([t.to_array().as_slice(), q.to_array().as_slice()].concat())
}

#[test]
fn the_crossfade_probes_catch_a_missing_short_arc_flip() {
    let mut f = BlendFigure::new();
    f.set_runner(no_flip);
    f.set_use_exercise(true);
    let note = f.pose(0.3).unwrap();
    // The clips' own rotations all lie on one hemisphere: the joints alone cannot tell.
    assert!(
        note.contains("matches the reference at all 21 joints"),
        "{note}"
    );
    assert!(
        note.contains(
            "On the upper arm's probes it differs at w = 0.5 with B's rotation negated (a·b < 0)."
        ),
        "{note}"
    );
    assert!(!note.contains("w = 0.25,"), "{note}");
}

/// Rows of the arm plot as `[t, a, b, mix, with additive, additive alone]`.
fn arm_rows(f: &mut BlendFigure) -> Vec<[f32; 6]> {
    f.arm_samples(61)
        .unwrap()
        .chunks(6)
        .map(|r| r.try_into().unwrap())
        .collect()
}

/// Figure 1's caption: the mix's arm can hang lower than both clips' (the turn between arms
/// raised in different directions swings it nearer hanging): with run and arm circles, upper body from B,
/// at weight 0.2 and 0.5, part of the cycle has the mix at least 3° below both clips.
#[test]
fn the_mix_can_hang_lower_than_both_clips() {
    let mut f = BlendFigure::new();
    f.set_clips("run", "arm circles").unwrap();
    f.set_mask("upper body from B").unwrap();
    for w in [0.2, 0.5] {
        f.set_weight(w).unwrap();
        let below = arm_rows(&mut f)
            .iter()
            .filter(|r| r[3] < r[1].min(r[2]) - 3.0)
            .count();
        assert!(below >= 5, "weight {w}: the mix is below both clips in {below} of 61 rows");
    }
}

#[test]
fn the_arm_plot_follows_the_weights_the_mask_and_the_additive_layer() {
    let mut f = BlendFigure::new();
    f.set_clips("walk", "wave").unwrap();
    let max = |rows: &[[f32; 6]], i: usize| rows.iter().map(|r| r[i]).fold(f32::MIN, f32::max);
    let min = |rows: &[[f32; 6]], i: usize| rows.iter().map(|r| r[i]).fold(f32::MAX, f32::min);
    // One cycle of clip A, the last row at its end, which repeats the first.
    f.set_weight(0.0).unwrap();
    let rows = arm_rows(&mut f);
    assert_eq!(rows.len(), 61);
    assert!((rows[60][0] - f.duration_sec()).abs() < 1e-5);
    assert_eq!(rows[60][1..], rows[0][1..]);
    for r in &rows {
        assert!(
            (r[3] - r[1]).abs() < 0.01 && r[4] == r[3],
            "weight 0 is clip A: {r:?}"
        );
    }
    // The walk swings the arm a little; the wave holds it high.
    assert!(max(&rows, 1) < 45.0 && min(&rows, 2) > 120.0, "{rows:?}");
    f.set_weight(1.0).unwrap();
    for r in &arm_rows(&mut f) {
        assert!((r[3] - r[2]).abs() < 0.01, "weight 1 is clip B: {r:?}");
    }
    // The Try this: the upper body from B at 0.5 raises the arm only part of the way.
    f.set_mask("upper body from B").unwrap();
    f.set_weight(0.5).unwrap();
    let rows = arm_rows(&mut f);
    for r in &rows {
        assert!(r[3] > r[1] + 20.0 && r[3] < r[2] - 20.0, "half way: {r:?}");
    }
    // The lower body from B leaves the arm to A.
    f.set_mask("lower body from B").unwrap();
    for r in &arm_rows(&mut f) {
        assert!((r[3] - r[1]).abs() < 0.01, "{r:?}");
    }
    // The additive Try this: weight of B 0, the wave added: the arm is up and still swings a
    // little with the walk (it moves more over the cycle than the wave alone).
    f.set_mask("whole body").unwrap();
    f.set_weight(0.0).unwrap();
    f.set_additive("wave (a clip)", 1.0).unwrap();
    let rows = arm_rows(&mut f);
    assert!(min(&rows, 4) > 135.0, "{rows:?}");
    let swing = |i: usize| max(&rows, i) - min(&rows, i);
    // The plot's "layer alone" is the wave played on the rest pose: clip B, the wave itself.
    for r in &rows {
        assert!((r[5] - r[2]).abs() < 0.01, "the wave alone: {r:?}");
    }
    assert!(
        swing(4) > swing(5) + 2.0,
        "{} against {}",
        swing(4),
        swing(5)
    );
    // With the lean chosen, the plot's third line is the lean alone, not the wave: the rest
    // pose's hanging arm tilted with the chest, the same all cycle long.
    f.set_additive("lean forward (a pose)", 1.0).unwrap();
    let rows = arm_rows(&mut f);
    assert!(swing_of(&rows, 5) < 0.01, "{rows:?}");
    assert!(rows[0][5] > 10.0 && rows[0][5] < 90.0, "{rows:?}");
    for r in &rows {
        assert!((r[5] - r[2]).abs() > 30.0, "not the wave: {r:?}");
    }
    // At layer weight 0 the layer is nothing: alone it is the rest pose, on the base the base.
    f.set_additive("lean forward (a pose)", 0.0).unwrap();
    for r in &arm_rows(&mut f) {
        assert!(r[5] < 1.0 && (r[4] - r[3]).abs() < 0.01, "{r:?}");
    }
}

fn swing_of(rows: &[[f32; 6]], i: usize) -> f32 {
    let (lo, hi) = rows
        .iter()
        .fold((f32::MAX, f32::MIN), |(a, b), r| (a.min(r[i]), b.max(r[i])));
    hi - lo
}

#[test]
fn the_ghost_is_the_pose_before_the_additive_layer() {
    let mut f = BlendFigure::new();
    let mut frame = Frame::default();
    f.set_weight(0.0).unwrap();
    f.draw(&mut frame, 0.4).unwrap();
    let plain = frame.strokes.len();
    assert!(!frame.keep_in_view.is_empty());
    // Every joint stays in the box the camera keeps in view.
    let (lo, hi) = (frame.keep_in_view[0], frame.keep_in_view[7]);
    for clip in human::CLIP_NAMES {
        f.set_clips("walk", clip).unwrap();
        f.set_weight(1.0).unwrap();
        f.set_additive("lean forward (a pose)", 1.0).unwrap();
        for k in 0..20 {
            f.pose(0.05 * k as f32).unwrap();
            for p in f.model() {
                let p = Vec3::from(p.translation);
                assert!(
                    p.cmpge(lo).all() && p.cmple(hi).all(),
                    "{clip}: {p} outside {lo}..{hi}"
                );
            }
        }
    }
    f.set_clips("walk", "wave").unwrap();
    f.set_weight(0.0).unwrap();
    f.set_additive("wave (a clip)", 1.0).unwrap();
    frame = Frame::default();
    f.draw(&mut frame, 0.4).unwrap();
    assert_eq!(
        frame.strokes.len(),
        plain + 20,
        "one ghost bone per joint with a parent"
    );
    // The ghost lies mostly inside the body: it is drawn over it, or only the arm would show.
    assert!(frame.strokes[plain..]
        .iter()
        .all(|s| s.depth_bias == inbetween::draw::ON_TOP));
    let base = Vec3::from(f.base_model()[5].translation);
    assert!(
        f.base_model()
            .iter()
            .zip(f.model())
            .any(|(a, b)| { Vec3::from(a.translation).distance(Vec3::from(b.translation)) > 0.2 }),
        "{base}"
    );
}

/// The longest trail among the footprints of the last draw: the farthest apart two footprints
/// of one stance (linked from one to the next) lie, metres.
fn longest_trail(l: &LocomotionFigure) -> f32 {
    let prints = l.footprints();
    let mut stance: Vec<usize> = (0..prints.len()).collect();
    for &[a, b] in l.footprint_links() {
        assert!(
            a < b && l.footprint_feet()[a] == l.footprint_feet()[b],
            "one foot, in order"
        );
        stance[b] = stance[a];
    }
    let mut longest = 0.0f32;
    for i in 0..prints.len() {
        for j in 0..i {
            if stance[i] == stance[j] {
                longest = longest.max(prints[i].distance(prints[j]));
            }
        }
    }
    longest
}

#[test]
fn a_planted_foot_leaves_a_dot_and_a_sliding_foot_a_trail() {
    // The text: each step leaves one dot synchronised, and trails 20 to 40 cm long at the same
    // clock time (the default speed). The trail is drawn between the footprints of one stance,
    // over the legs (which stand on it).
    let mut l = LocomotionFigure::new();
    l.set_compare(false);
    let (mut dot, mut shortest, mut longest) = (0.0f32, f32::INFINITY, 0.0f32);
    for k in 6..=32 {
        let t = 0.25 * k as f32;
        l.set_synchronised(true);
        l.draw(&mut Frame::default(), t).unwrap();
        dot = dot.max(longest_trail(&l));
        l.set_synchronised(false);
        let mut frame = Frame::default();
        l.draw(&mut frame, t).unwrap();
        let trail = longest_trail(&l);
        (shortest, longest) = (shortest.min(trail), longest.max(trail));
        let links = l.footprint_links().len();
        assert!(links > 0);
        // One line over the legs per link, in a white outline 1 px wider each side: all the
        // outlines first, so that no outline covers a join of the trail it outlines. Seen along
        // the walk, a trail lies over the legs, and the white keeps it a line of its own.
        let on_top: Vec<_> = (frame.strokes.iter())
            .filter(|s| s.depth_bias == inbetween::draw::ON_TOP)
            .collect();
        assert_eq!(on_top.len(), 2 * links, "an outline and a line per link");
        let (outlines, lines) = on_top.split_at(links);
        for (o, line) in outlines.iter().zip(lines) {
            assert_eq!((o.a, o.b), (line.a, line.b));
            assert_eq!(o.color, [1.0; 4], "a white outline");
            assert_eq!(line.color[..3], inbetween::figures::palette::PURPLE.to_array());
            assert_eq!(o.width_px, line.width_px + 2.0);
        }
        let dots = frame
            .markers
            .iter()
            .filter(|m| m.shape == inbetween::draw::MARKER_DOT)
            .count();
        // A dot at each end of a stance: where it has one sample, one dot.
        let links = l.footprint_links();
        let ends = (0..l.footprints().len())
            .filter(|&i| !(links.iter().any(|k| k[0] == i) && links.iter().any(|k| k[1] == i)))
            .count();
        assert_eq!(dots, ends);
        assert!(dots < l.footprints().len() / 4);
    }
    assert!(dot < 0.015, "a step synchronised: {dot} m");
    assert!(
        shortest > 0.2 && longest < 0.45,
        "{shortest} to {longest} m"
    );
}

/// A panic as the page reports it: Rust's "panicked at file:line:col:" then the message.
fn rust_panic(message: String) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(format!(
        "panicked at src/exercises/blending.rs:37:5:\n{message}"
    )))
}

/// 8.1 right at and above the walk's speed, panicking below it (an `assert!` on `v`).
fn panics_below_the_walk(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "weight_for_speed" && args[4] < args[1] / args[0] - 1e-3 {
        return rust_panic(format!("v is below the walk's speed: {}", args[4]));
    }
    reference_8_1(name, args)
}

thread_local! {
    /// The first panic of the page-like runner below.
    static STUCK: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// [`panics_below_the_walk`] as the page runs it: after a panic, every later call of the
/// exercise gets that same panic back.
fn stuck_after_a_panic(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if let Some(message) = STUCK.with(|s| s.borrow().clone()) {
        return Err(Failure::Panicked(message));
    }
    let answer = panics_below_the_walk(name, args);
    if let Err(Failure::Panicked(message)) = &answer {
        STUCK.with(|s| *s.borrow_mut() = Some(message.clone()));
    }
    answer
}

#[test]
fn a_panic_of_8_1_is_reported_once_against_the_speed_that_caused_it() {
    let mut frame = Frame::default();
    for runner in [
        panics_below_the_walk as fn(&str, &[f32]) -> Result<Vec<f32>, Failure>,
        stuck_after_a_panic,
    ] {
        STUCK.with(|s| *s.borrow_mut() = None);
        let mut l = LocomotionFigure::new();
        let reference = l.weight();
        l.set_runner(runner);
        l.set_use_exercise(true);
        let note = l.draw(&mut frame, 1.0).unwrap();
        // The default speed and the range's are fine; the probe at 0.3 m/s panics.
        assert!(
            note.contains(
                "Your exercise 8.1 weight_for_speed, called with v = 0.300 m/s, panicked at \
                 src/exercises/blending.rs:37:5: v is below the walk's speed: 0.3."
            ),
            "{note}"
        );
        assert_eq!(note.matches("panicked").count(), 1, "{note}");
        assert!(!note.contains("2.500"), "{note}");
        assert!(note.contains("uses the reference"), "{note}");
        assert_eq!(l.weight(), reference);
        // Another speed, where the page answers with the same panic: still the speed that
        // caused it, and the reference's weight.
        let (lo, hi) = l.speed_range();
        let v = 0.25 * lo + 0.75 * hi;
        l.set_speed(v).unwrap();
        let mut plain = LocomotionFigure::new();
        plain.set_speed(v).unwrap();
        let reference = plain.weight();
        assert!(reference > 0.5);
        let note = l.draw(&mut frame, 1.0).unwrap();
        assert!(
            note.contains("called with v = 0.300 m/s, panicked at"),
            "{note}"
        );
        assert_eq!(l.weight(), reference);
    }
    // A panic at the figure's own speed names that speed.
    let mut l = LocomotionFigure::new();
    l.set_runner(|_, args| rust_panic(format!("no: {}", args[4])));
    l.set_use_exercise(true);
    let v = format!("{:.3}", 0.5 * (l.speed_range().0 + l.speed_range().1));
    let note = l.draw(&mut frame, 1.0).unwrap();
    assert!(
        note.contains(&format!(
            "Your exercise 8.1 weight_for_speed, called with v = {v} m/s, panicked at"
        )),
        "{note}"
    );
    // A rebuilt exercise (a new runner) is tried afresh.
    l.set_runner(reference_8_1);
    let note = l.draw(&mut frame, 1.0).unwrap();
    assert!(note.contains("matches the reference"), "{note}");
}

/// 6.3 right (the reference), panicking at weight 1 (as an `assert!(w < 1.0)` would).
fn crossfade_panics_at_1(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name != "crossfade_joint" {
        return direct(name, args);
    }
    let w = args[14];
    if w >= 1.0 {
        return rust_panic(format!("w must be below 1, got {w}"));
    }
    crossfade_reference(args)
}

/// 6.3 as the reference computes it.
fn crossfade_reference(args: &[f32]) -> Result<Vec<f32>, Failure> {
    let (ta, qa, tb, qb, w) = crossfade_args(args);
    use inbetween::skeleton::{crossfade_transform, Transform};
    let joint = |translation, rotation| Transform {
        translation,
        rotation,
        scale: Vec3::ONE,
    };
    let x = crossfade_transform(&joint(ta, qa), &joint(tb, qb), w);
    Ok([
        x.translation.to_array().as_slice(),
        x.rotation.to_array().as_slice(),
    ]
    .concat())
}

#[test]
fn a_panic_of_6_3_names_the_input_and_leaves_the_reference_pose() {
    let mut reference = BlendFigure::new();
    reference.pose(0.3).unwrap();
    let mut f = BlendFigure::new();
    f.set_runner(crossfade_panics_at_1);
    f.set_use_exercise(true);
    let note = f.pose(0.3).unwrap();
    assert!(
        note.contains(
            "Your exercise 6.3 crossfade_joint, called for the upper arm's probe (upper_arm.R) at \
             w = 1, panicked at src/exercises/blending.rs:37:5: w must be below 1, got 1."
        ),
        "{note}"
    );
    assert_eq!(note.matches("panicked").count(), 1, "{note}");
    assert!(close(&rotations(&f), &rotations(&reference)));
    // Kept, as the page keeps it, at any later time.
    assert!(f.pose(0.6).unwrap().contains("at w = 1, panicked"));
    // A panic at a joint (at a weight no probe uses) names the joint and its weight.
    f.set_runner(|name, args| match name {
        "crossfade_joint" if args[14] == 0.7 => rust_panic(format!("no: {}", args[14])),
        "crossfade_joint" => crossfade_reference(args),
        _ => direct(name, args),
    });
    f.set_weight(0.7).unwrap();
    let note = f.pose(0.3).unwrap();
    assert!(
        note.contains("crossfade_joint, called for joint 0 (")
            && note
                .contains("with w = 0.700, panicked at src/exercises/blending.rs:37:5: no: 0.7."),
        "{note}"
    );
}

/// Figures 3 and 4 fill their canvases: the footprints are dots of at least 10 px, the
/// single character's figure declares only its own lane, and with the camera fitted on the
/// page's 760 × 420 canvas from the page's orbits the characters' body parts span on average
/// at least 200 px (side by side) and 225 px (alone) from top to bottom over four times of the
/// walk.
#[test]
fn the_locomotion_figures_fill_their_canvases() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::figures::blending::LANE_X;
    let size = glam::Vec2::new(760.0, 420.0);
    for (compare, orbit, least) in [
        (true, LOCOMOTION_VIEW, 200.0),
        (false, [0.0, 0.8, 0.0, 4.5, 1.3, 0.3], 225.0),
    ] {
        let mut l = LocomotionFigure::new();
        l.set_compare(compare);
        let (lo, hi) = l.speed_range();
        l.set_speed(0.5 * (lo + hi)).unwrap();
        let mut spans = Vec::new();
        for t in [0.2, 1.0, 2.0, 3.0] {
            let mut f = Frame::default();
            l.draw(&mut f, t).unwrap();
            let widest = f.keep_in_view.iter().map(|p| p.x.abs()).fold(0.0, f32::max);
            if !compare {
                assert!(widest < LANE_X, "one lane: {widest} m either side");
            }
            let dots: Vec<f32> = f
                .markers
                .iter()
                .filter(|m| m.shape == inbetween::draw::MARKER_DOT)
                .map(|m| m.size_px.abs())
                .collect();
            assert!(
                !dots.is_empty() && dots.iter().all(|&s| s >= 10.0),
                "{dots:?}"
            );
            let mut camera = OrbitCamera::from_view(orbit);
            assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let ys: Vec<f32> = f
                .meshes
                .iter()
                .map(|m| {
                    project_to_canvas(view_proj, size, m.model.w_axis.truncate())
                        .unwrap()
                        .y
                })
                .collect();
            let (top, bottom) = ys
                .iter()
                .fold((f32::MAX, f32::MIN), |(a, b), y| (a.min(*y), b.max(*y)));
            spans.push(bottom - top);
        }
        let mean = spans.iter().sum::<f32>() / spans.len() as f32;
        assert!(mean >= least, "compare {compare}: {spans:?} px");
    }
}

#[test]
fn the_compared_characters_walk_abreast() {
    // Blended at the same clock time, the root drifts most of a metre ahead of or behind the
    // synchronised one's (and wraps round the loop at another moment): drawn where each root
    // is, one character stands behind the other from the page's three-quarter view. Both are
    // drawn level, each in its own lane; each name stands centred just over its character's
    // head (the highest box of its lane), wherever the lean takes the head: anchored at the
    // lane's root 2 m up and reading rightwards from there, a name floated off its head.
    let mut l = LocomotionFigure::new();
    let (lo, hi) = l.speed_range();
    for speed in [lo, 0.97, 0.5 * (lo + hi), hi] {
        l.set_speed(speed).unwrap();
        for k in 0..32 {
            let t = k as f32 * 0.25;
            let mut f = Frame::default();
            l.draw(&mut f, t).unwrap();
            let at = |name: &str| f.labels.iter().find(|x| x.text == name).unwrap().anchor;
            let (sync, clock) = (at("synchronised"), at("same clock time"));
            assert!(
                (sync.z - clock.z).abs() < 0.3,
                "speed {speed}, t {t}: synchronised at {sync}, same clock time at {clock}"
            );
            for label in &f.labels {
                let head = f
                    .meshes
                    .iter()
                    .map(|m| m.model.w_axis.truncate())
                    .filter(|c| c.x * label.anchor.x > 0.0)
                    .max_by(|a, b| a.y.total_cmp(&b.y))
                    .unwrap();
                let off = (label.anchor - head) * Vec3::new(1.0, 0.0, 1.0);
                assert!(
                    off.length() < 0.05 && label.anchor.y > head.y + 0.1,
                    "speed {speed}, t {t}: {} at {}, its head at {head}",
                    label.text,
                    label.anchor
                );
                // Centred over the anchor and above it on screen.
                let half = 0.5 * inbetween::draw::label_size_px(&label.text).x;
                assert!(!label.left && label.offset_px.x < -half + 1.0 && label.offset_px.y < 0.0);
            }
            assert!(clock.x - sync.x > 1.0, "speed {speed}, t {t}: lanes apart");
        }
    }
}

/// Figure 3 at the page's default camera ([`LOCOMOTION_VIEW`]), fitted on the page's 760 × 420
/// canvas: the same-clock-time character's footprint trails do not run along the line of
/// sight, so where its feet slide a trail's two ends lie at least 18 px apart on screen, well
/// clear of its 11 px end dots (20 px at 0.97 m/s, 21 px at 0.73 m/s).
#[test]
fn the_compared_footprint_trails_read_at_the_default_view() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let size = glam::Vec2::new(760.0, 420.0);
    let mut l = LocomotionFigure::new();
    for speed in [0.73, 0.97] {
        l.set_speed(speed).unwrap();
        let mut longest = 0.0f32;
        for t in [1.0, 2.0, 2.94, 4.0] {
            let mut f = Frame::default();
            l.draw(&mut f, t).unwrap();
            let mut camera = OrbitCamera::from_view(LOCOMOTION_VIEW);
            assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
            // A trail is a chain of short links, one per sample of a stance: its two ends are
            // the first link's start and the last link's end.
            let mut start: Option<(Vec3, Vec3)> = None;
            for (a, b) in f.segments_of(inbetween::draw::palette::RED) {
                let from = match start {
                    Some((first, end)) if end == a => first,
                    _ => a,
                };
                start = Some((from, b));
                longest = longest.max(at(from).distance(at(b)));
            }
        }
        assert!(longest >= 18.0, "speed {speed}: the longest red trail is {longest} px");
    }
}

/// The weight colours of Figure 1 read apart at 0, 0.5 and 1: in OKLab (Björn Ottosson's
/// perceptual colour space, where distance follows how different two colours look), 0.5 lies
/// nearer grey than teal, since a little colour already reads as teal, and each step is at
/// least a third of the way from grey to teal.
#[test]
fn the_weight_colours_at_one_half_and_one_read_apart() {
    fn oklab(c: Vec3) -> Vec3 {
        let lms = glam::Mat3::from_cols(
            Vec3::new(0.4122214708, 0.2119034982, 0.0883024619),
            Vec3::new(0.5363325363, 0.6806995451, 0.2817188376),
            Vec3::new(0.0514459929, 0.1073969566, 0.6299787005),
        ) * c;
        glam::Mat3::from_cols(
            Vec3::new(0.2104542553, 1.9779984951, 0.0259040371),
            Vec3::new(0.7936177850, -2.4285922050, 0.7827717662),
            Vec3::new(-0.0040720468, 0.4505937099, -0.8086757660),
        ) * lms.map(f32::cbrt)
    }
    let at = |w: f32| oklab(BlendFigure::weight_color(w));
    let whole = at(0.0).distance(at(1.0));
    let (from_grey, from_teal) = (at(0.0).distance(at(0.5)), at(0.5).distance(at(1.0)));
    assert!(
        from_grey < from_teal && from_grey > whole / 3.0,
        "0.5 is {from_grey} from grey, {from_teal} from teal (grey to teal {whole})"
    );
}

/// Figure 4's Try this: with root motion left in the pose, the body (the mean of its boxes, on
/// the ground plane) moves forwards through each cycle and jumps back by one cycle's travel,
/// the note's jump, as the next cycle begins; between the jumps it moves a frame's walk.
#[test]
fn without_root_motion_the_body_jumps_back_a_cycles_travel_as_each_cycle_begins() {
    use inbetween::draw::MeshId;
    // As the page's Figure 4: one character, synchronised.
    let mut l = LocomotionFigure::new();
    l.set_compare(false);
    l.set_root_motion(false);
    let body = |l: &mut LocomotionFigure, t: f32| {
        let mut frame = Frame::default();
        let note = l.draw(&mut frame, t).unwrap();
        let boxes: Vec<Vec3> = frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CUBE)
            .map(|m| m.model.w_axis.truncate())
            .collect();
        let mean = boxes.iter().sum::<Vec3>() / boxes.len() as f32;
        (mean * Vec3::new(1.0, 0.0, 1.0), note)
    };
    let (mut before, note) = body(&mut l, 2.0);
    let snap = l.snap_back_m()[0];
    assert!(note.contains(&format!("snaps back {:.0} cm", snap * 100.0)), "{note}");
    let cycle: f32 = note
        .split("one cycle takes ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .expect("the cycle's length in the note");
    let (mut jumps, mut walked) = (Vec::new(), 0.0f32);
    for k in 1..=240 {
        let (now, _) = body(&mut l, 2.0 + k as f32 / 60.0);
        let step = now - before;
        if step.length() > 0.5 * snap {
            jumps.push(step.length());
        } else {
            walked = walked.max(step.length());
        }
        before = now;
    }
    let loops = (4.0 / cycle).floor() as usize;
    assert!(
        (loops..=loops + 1).contains(&jumps.len()),
        "{} jumps in 4 s of {cycle} s cycles",
        jumps.len()
    );
    for jump in jumps {
        assert!((jump - snap).abs() < 0.15 * snap, "a jump of {jump} m, the note's {snap} m");
    }
    assert!(walked < 0.1 * snap, "{walked} m in one frame");
}


/// Figure 3's default camera, as lessons/08-blending/lesson.js places it: target, distance,
/// yaw and pitch (radians), from the front of the walk and a little to the same-clock-time
/// character's side.
const LOCOMOTION_VIEW: [f32; 6] = [0.0, 0.8, 0.0, 5.0, 0.5, 0.35];

/// Figure 3 at the page's default camera, fitted on its canvas at 800 px (760 × 420) and at
/// 1600 px (650 × 420): at every speed and all through the loop the synchronised character
/// (body boxes and footprints) stands left of the same-clock-time one with at least 20 px
/// between them on screen, as the caption's "side by side" and the note's "left" and "right"
/// say, and each name lies over its own character, clear of the other.
#[test]
fn the_compared_characters_stand_left_and_right_at_the_default_view() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::{box_corners, label_size_px, MARKER_DOT};
    let mut l = LocomotionFigure::new();
    let (lo, hi) = l.speed_range();
    for size in [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0)] {
        for speed in [lo, 0.73, 0.97, 0.5 * (lo + hi), hi] {
            l.set_speed(speed).unwrap();
            for k in 0..32 {
                let t = k as f32 * 0.25;
                let mut f = Frame::default();
                l.draw(&mut f, t).unwrap();
                let mut camera = OrbitCamera::from_view(LOCOMOTION_VIEW);
                assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                // Screen boxes, [synchronised (lane −x), same clock time (lane +x)].
                let mut bounds = [(Vec2::MAX, Vec2::MIN); 2];
                let mut grow = |world: Vec3, radius_px: f32| {
                    let (p, side) = (at(world), usize::from(world.x > 0.0));
                    bounds[side].0 = bounds[side].0.min(p - radius_px);
                    bounds[side].1 = bounds[side].1.max(p + radius_px);
                };
                for m in &f.meshes {
                    for c in box_corners(Vec3::NEG_ONE, Vec3::ONE) {
                        grow(m.model.transform_point3(c), 0.0);
                    }
                }
                for m in f.markers.iter().filter(|m| m.shape == MARKER_DOT) {
                    grow(Vec3::from(m.center), 0.5 * m.size_px.abs());
                }
                let gap = bounds[1].0.x - bounds[0].1.x;
                assert!(gap >= 20.0, "{size}, speed {speed}, t {t}: {gap} px apart");
                for label in &f.labels {
                    let own = usize::from(label.anchor.x > 0.0);
                    let (other_lo, other_hi) = bounds[1 - own];
                    let top_left = at(label.anchor) + label.offset_px;
                    let bottom_right = top_left + label_size_px(&label.text);
                    let over_other = top_left.x < other_hi.x
                        && bottom_right.x > other_lo.x
                        && top_left.y < other_hi.y
                        && bottom_right.y > other_lo.y;
                    let centre = 0.5 * (top_left.x + bottom_right.x);
                    assert!(
                        !over_other && (bounds[own].0.x..bounds[own].1.x).contains(&centre),
                        "{size}, speed {speed}, t {t}: {} at {top_left}",
                        label.text
                    );
                }
            }
        }
    }
}

