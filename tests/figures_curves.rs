//! Lesson 02's figures, natively: what they draw, what they refuse, what they say about the
//! student's exercises.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Vec2, Vec3};
use inbetween::curves::{hermite_basis, Interpolation};
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::curves::*;
use inbetween::figures::Frame;

fn scene(scheme: &str) -> KeyframesScene {
    let mut s = KeyframesScene::new();
    s.set_scheme(scheme).unwrap();
    s
}

fn path_of(s: &KeyframesScene) -> Vec<Vec2> {
    let mut out = Vec::new();
    s.path(&mut out);
    out
}

#[test]
fn the_drawn_path_passes_through_every_key() {
    for scheme in [
        "linear",
        "lagrange",
        "hermite",
        "cardinal",
        "natural",
        "centripetal",
    ] {
        for preset_name in ["default", "loop", "uneven", "centripetal"] {
            let mut s = scene(scheme);
            let (times, values) = preset(preset_name).unwrap();
            s.set_keys(times, values.clone()).unwrap();
            let mut frame = Frame::default();
            s.draw(&mut frame, 0.3).unwrap();
            let drawn: Vec<Vec3> = frame.segments_of(PATH_COLOR).map(|(a, _)| a).collect();
            assert!(!drawn.is_empty(), "{scheme}: a path is drawn");
            let ends: Vec<Vec3> = frame.segments_of(PATH_COLOR).map(|(_, b)| b).collect();
            for (i, key) in values.iter().enumerate() {
                let hit = drawn
                    .iter()
                    .chain(&ends)
                    .any(|p| (p.truncate() - *key).length() < 1e-5);
                assert!(
                    hit,
                    "{scheme} / {preset_name}: key {i} at {key} is on the path"
                );
            }
        }
    }
}

#[test]
fn a_key_between_even_samples_is_still_on_the_path() {
    // A key 1 ms after its neighbour falls between any evenly spaced samples.
    let mut s = scene("linear");
    let times = vec![0.0, 1.0, 1.001, 3.0];
    let keys = vec![
        Vec2::ZERO,
        Vec2::new(1.0, 0.0),
        Vec2::new(1.0, 2.0),
        Vec2::new(2.0, 0.0),
    ];
    s.set_keys(times, keys.clone()).unwrap();
    let path = path_of(&s);
    for key in keys {
        assert!(path.iter().any(|p| (*p - key).length() < 1e-5), "{key}");
    }
}

#[test]
fn step_is_drawn_as_held_values_and_reaches_the_last_key() {
    let mut s = scene("step");
    let keys = s.track().values().to_vec();
    assert_eq!(path_of(&s), keys, "the held values are the keys");
    let mut frame = Frame::default();
    s.draw(&mut frame, 0.0).unwrap();
    assert_eq!(
        frame.segments_of(PATH_COLOR).count(),
        0,
        "no curve between held values"
    );
    assert_eq!(frame.segments_of(JUMP_COLOR).count(), keys.len() - 1);
    // Half-way through the first segment the ball still holds key 0…
    let t1 = s.track().times()[1];
    assert_eq!(s.position(0.5 * t1).unwrap(), keys[0]);
    // …and during the hold at the end it rests on the last key.
    let end = s.track().duration_sec() + 0.5 * HOLD_SEC;
    assert_eq!(s.position(s.wrap(end)).unwrap(), *keys.last().unwrap());
    assert!(s.loop_sec() > s.track().duration_sec());
}

#[test]
fn constant_speed_is_constant_at_the_corners_of_a_linear_path() {
    let mut s = scene("linear");
    s.set_arc_length(true);
    let rows = s.sample_motion(401).unwrap();
    let speeds: Vec<f32> = rows.iter().map(|r| r[2]).collect();
    let (lo, hi) = speeds
        .iter()
        .fold((f32::MAX, 0.0f32), |(a, b), &v| (a.min(v), b.max(v)));
    assert!(hi - lo < 1e-3 * hi, "speed from {lo} to {hi}");
    // The expected speed: path length over duration.
    let keys = s.track().values();
    let length: f32 = keys.windows(2).map(|w| (w[1] - w[0]).length()).sum();
    assert!((hi - length / s.track().duration_sec()).abs() < 1e-3);
}

#[test]
fn motion_rows_use_the_keys_own_seconds() {
    let mut s = scene("cardinal");
    let (mut times, values) = preset("default").unwrap();
    times.iter_mut().for_each(|t| *t += 0.75);
    s.set_keys(times, values).unwrap();
    let rows = s.sample_motion(11).unwrap();
    assert_eq!(rows[0][0], 0.75);
    assert!((rows[10][0] - (0.75 + s.track().duration_sec())).abs() < 1e-5);
}

#[test]
fn every_setter_rejects_bad_input_and_leaves_the_scene_unchanged() {
    let mut s = KeyframesScene::new();
    let before = s.track().clone();
    let e = s
        .set_keys(vec![0.0, 1.0], vec![Vec2::new(f32::NAN, 0.0), Vec2::ONE])
        .unwrap_err();
    assert!(e.contains("key 0") && e.contains("NaN"), "{e}");
    let e = s
        .set_keys(vec![0.0, 2.0, 1.0], vec![Vec2::ZERO; 3])
        .unwrap_err();
    assert!(e.contains("strictly increase"), "{e}");
    let e = s.set_keys(vec![0.0], vec![Vec2::ZERO; 2]).unwrap_err();
    assert!(e.contains("1 key times but 2"), "{e}");
    let e = s
        .set_keys(
            (0..1001).map(|i| i as f32).collect(),
            vec![Vec2::ZERO; 1001],
        )
        .unwrap_err();
    assert!(e.contains("at most 1000 keys"), "{e}");
    assert!(s
        .set_scheme("bezier")
        .unwrap_err()
        .contains("unknown scheme"));
    assert!(s.set_tension(2.5).unwrap_err().contains("between 0 and 2"));
    assert!(s
        .set_tension(f32::NAN)
        .unwrap_err()
        .contains("between 0 and 2"));
    assert!(s.set_ease("bounce").unwrap_err().contains("unknown ease"));
    assert!(s
        .set_ghost_count(1)
        .unwrap_err()
        .contains("between 2 and 200"));
    assert!(s.sample_motion(1).unwrap_err().contains("samples"));
    assert!(s.position(f32::NAN).unwrap_err().contains("finite"));
    let e = s.set_key_tangent(99, Vec2::ZERO, Vec2::ZERO).unwrap_err();
    assert!(e.contains("99"), "{e}");
    assert!(preset("nope").unwrap_err().contains("unknown preset"));
    assert_eq!(s.track(), &before);
}

#[test]
fn ten_thousand_lagrange_keys_give_a_clear_error_at_once() {
    let start = std::time::Instant::now();
    let mut s = scene("lagrange");
    let times: Vec<f32> = (0..10_000).map(|i| i as f32).collect();
    let e = s.set_keys(times, vec![Vec2::ZERO; 10_000]).unwrap_err();
    assert!(e.contains("at most"), "{e}");
    let times: Vec<f32> = (0..65).map(|i| i as f32).collect();
    let mut s = scene("linear");
    s.set_keys(times, vec![Vec2::ZERO; 65]).unwrap();
    let e = s.set_scheme("lagrange").unwrap_err();
    assert!(e.contains("at most 64 keys"), "{e}");
    assert!(start.elapsed().as_secs_f32() < 1.0);
}

#[test]
fn presets_show_what_they_promise() {
    // "centripetal": the two schemes' paths differ visibly (by more than 5 cm somewhere).
    let path = |scheme: &str| {
        let mut s = scene(scheme);
        let (t, v) = preset("centripetal").unwrap();
        s.set_keys(t, v).unwrap();
        path_of(&s)
    };
    let (a, b) = (path("cardinal"), path("centripetal"));
    let gap = a
        .iter()
        .zip(&b)
        .map(|(p, q)| (*p - *q).length())
        .fold(0.0, f32::max);
    assert!(gap > 0.05, "largest gap {gap}");
}

// ---- Exercise feedback ----

fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "hermite_basis" => Ok(vec![1.0, 0.0, 0.0, 0.0]),
        "find_segment" => Ok(vec![0.0]),
        "cardinal_tangents" => {
            let n = args[0] as usize;
            let mut out = vec![n as f32];
            out.extend(std::iter::repeat_n(0.5, n));
            Ok(out)
        }
        "arc_length_invert" => Ok(vec![0.0]),
        _ => direct(name, args),
    }
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "attempt to divide by zero (src/exercises/curves.rs:7:5)".into(),
    ))
}

fn right(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    use inbetween::curves as c;
    let mut a = args;
    let list = |a: &mut &[f32]| {
        let n = a[0] as usize;
        let v = a[1..=n].to_vec();
        *a = &a[n + 1..];
        v
    };
    Ok(match name {
        "hermite_basis" => hermite_basis(args[0]).to_vec(),
        "find_segment" => {
            let times = list(&mut a);
            vec![c::find_segment(&times, a[0]) as f32]
        }
        "cardinal_tangents" => {
            let (times, values) = (list(&mut a), list(&mut a));
            let mut out = vec![0.0; times.len()];
            c::cardinal_tangents(&times, &values, a[0], &mut out);
            let mut r = vec![out.len() as f32];
            r.extend(out);
            r
        }
        "arc_length_invert" => {
            let (p, l) = (list(&mut a), list(&mut a));
            vec![c::arc_length_invert(&p, &l, a[0])]
        }
        _ => return direct(name, args),
    })
}

fn note_with(runner: inbetween::exercises::run::Runner, arc_length: bool) -> (String, Frame) {
    let mut s = scene("cardinal");
    s.set_runner(runner);
    s.set_use_exercise(true);
    s.set_arc_length(arc_length);
    let mut frame = Frame::default();
    let note = s.draw(&mut frame, 1.1).unwrap();
    (note, frame)
}

#[test]
fn a_correct_exercise_matches_at_the_current_time() {
    let (note, _) = note_with(right, true);
    for what in [
        "Your hermite_basis matches the reference at s = ",
        "Your cardinal_tangents matches the reference at all 5 keys (μ = 1.000)",
        "Your find_segment matches the reference at t = ",
        "Your arc_length_invert matches the reference at s = ",
    ] {
        assert!(note.contains(what), "{what}\n{note}");
    }
}

#[test]
fn a_wrong_exercise_differs_with_both_values() {
    let (note, frame) = note_with(wrong, true);
    assert!(
        note.contains("Your hermite_basis differs at s = "),
        "{note}"
    );
    assert!(
        note.contains("yours (1.000, 0.000, 0.000, 0.000), reference ("),
        "{note}"
    );
    assert!(
        note.contains("Your cardinal_tangents differs at key 0 (μ = 1.000)"),
        "{note}"
    );
    assert!(note.contains("Your find_segment differs at t = "), "{note}");
    assert!(
        note.contains("Your arc_length_invert differs at s = "),
        "{note}"
    );
    // The figure draws what the student computed: not the reference path.
    let reference = note_with(right, true).1;
    let (a, b): (Vec<_>, Vec<_>) = (
        frame.segments_of(PATH_COLOR).collect(),
        reference.segments_of(PATH_COLOR).collect(),
    );
    assert_ne!(a, b);
}

#[test]
fn a_panicking_exercise_is_reported_and_the_reference_is_drawn() {
    let (note, frame) = note_with(panics, true);
    assert!(
        note.contains("Your exercise 2.1 hermite_basis panicked: attempt to divide by zero"),
        "{note}"
    );
    assert!(
        note.contains("exercise 2.4 arc_length_invert panicked"),
        "{note}"
    );
    let reference = note_with(right, true).1;
    let close = frame
        .segments_of(PATH_COLOR)
        .zip(reference.segments_of(PATH_COLOR))
        .all(|((a, _), (b, _))| (a - b).length() < 1e-4);
    assert!(close, "the reference path is drawn");
}

#[test]
fn stubs_say_not_done_yet() {
    if cfg!(feature = "solutions") {
        return;
    }
    let (note, _) = note_with(direct, true);
    for n in [
        "2.1 hermite_basis",
        "2.2 cardinal_tangents",
        "2.3 find_segment",
        "2.4 arc_length_invert",
    ] {
        assert!(
            note.contains(&format!("Not done yet: exercise {n}")),
            "{n}\n{note}"
        );
    }
    let (note, _) = note_with(direct, false);
    assert!(
        !note.contains("2.4"),
        "2.4 is only used at constant speed: {note}"
    );
}

#[test]
fn the_basis_note_compares_exercise_2_1() {
    let n = hermite_basis_note(right, 0.25, true).unwrap();
    assert_eq!(n, "Your hermite_basis matches the reference at s = 0.250.");
    let n = hermite_basis_note(wrong, 0.5, true).unwrap();
    assert!(n.starts_with("Your hermite_basis differs at s = 0.500: yours (1.000, 0.000, 0.000, 0.000), reference (0.500, 0.125, 0.500, -0.125)"), "{n}");
    let n = hermite_basis_note(panics, 0.5, true).unwrap();
    assert!(n.contains("panicked"), "{n}");
    let n = hermite_basis_note(wrong, 0.0, false).unwrap();
    assert_eq!(
        n,
        "At s = 0.000: h00 = 1.000, h10 = 0.000, h01 = 0.000, h11 = 0.000."
    );
    assert!(hermite_basis_note(right, 1.5, true)
        .unwrap_err()
        .contains("s must lie"));
    let rows = hermite_basis_samples(3).unwrap();
    assert_eq!(rows[2], [1.0, 0.0, 0.0, 1.0, 0.0]);
}

// ---- Lagrange ----

#[test]
fn the_lagrange_graph_has_labelled_axes_and_passes_through_its_keys() {
    let mut s = LagrangeScene::new();
    s.set_key_count(6.0).unwrap();
    let mut frame = Frame::default();
    s.draw(&mut frame);
    let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert!(
        texts.contains(&"time t (s)") && texts.contains(&"value y (m)"),
        "{texts:?}"
    );
    assert!(texts.contains(&"0") && texts.contains(&"5"), "{texts:?}");
    let ((times, values), _) = s.key_sets();
    let curve: Vec<Vec3> = frame.segments_of(LAGRANGE_BASE).map(|(a, _)| a).collect();
    for (t, y) in times.iter().zip(&values) {
        let key = s.place(*t, *y);
        let nearest = curve
            .iter()
            .map(|p| (*p - key).length())
            .fold(f32::MAX, f32::min);
        assert!(nearest < 0.03, "key at t = {t}: {nearest}");
    }
    assert!(s.set_key_count(f32::NAN).unwrap_err().contains("key count"));
    assert!(s.set_key_count(40.0).unwrap_err().contains("key count"));
    assert_eq!(s.key_count(), 6);
    let _ = Interpolation::Lagrange;
}
