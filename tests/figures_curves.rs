//! Lesson 02's figures, natively: what they draw, what they refuse, what they say about the
//! student's exercises.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Vec2, Vec3};
use inbetween::curves::{hermite_basis, Interpolation};
use inbetween::exercises::run::{direct, Failure};
use inbetween::figures::curves::*;
use inbetween::figures::Frame;
#[path = "support/flat.rs"]
mod flat;

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
fn step_with_constant_speed_keeps_the_keyed_timing_and_says_why() {
    let mut s = scene("step");
    s.set_arc_length(true);
    assert!(!s.constant_speed());
    assert!(
        s.timing_note().contains("step motion"),
        "{}",
        s.timing_note()
    );
    // Default keys at 0, 0.8, 1.6, 2.2, 3.2 s: at 1.85 s the ball holds key 2.
    let keys = s.track().values().to_vec();
    assert_eq!(s.position(1.85).unwrap(), keys[2]);
    assert_eq!(s.position(3.0).unwrap(), keys[3]);
    // The in-betweens are the held keys, not all key 0.
    let mut ghosts = Vec::new();
    s.ghosts(&mut ghosts);
    for (i, key) in keys.iter().enumerate() {
        assert!(ghosts.contains(key), "key {i} is among the in-betweens");
    }
    // Any other scheme travels at constant speed and the note is empty.
    s.set_scheme("linear").unwrap();
    assert!(s.constant_speed());
    assert_eq!(s.timing_note(), "");
    s.set_arc_length(false);
    s.set_scheme("step").unwrap();
    assert_eq!(s.timing_note(), "", "no note when constant speed is off");
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

fn not_done(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::NotDone)
}

#[test]
fn the_basis_note_compares_exercise_2_1() {
    let n = hermite_basis_note(right, 0.25, true).unwrap();
    assert_eq!(
        n,
        "Your hermite_basis matches the reference at s = 0.250 and at 4 more inputs \
         (s = 0.000; s = 0.500; s = 0.750; s = 1.000).\n\
         At s = 0.250: h00 = 0.844, h10 = 0.141, h01 = 0.156, h11 = -0.047."
    );
    // Not done (or failing), the figure uses the reference: its weights stay in the note, so
    // the Try this's sum can still be read (0.784 + 0.216 at the default s = 0.3).
    let n = hermite_basis_note(not_done, 0.3, true).unwrap();
    let lines: Vec<&str> = n.lines().collect();
    assert!(lines[0].starts_with("Not done yet: exercise 2.1"), "{n}");
    assert_eq!(lines[1], hermite_basis_note(not_done, 0.3, false).unwrap());
    assert!(lines[1].contains("h00 = 0.784") && lines[1].contains("h01 = 0.216"), "{n}");
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

/// The Lagrange graph strokes its axes after its curves: a later stroke covers an earlier one at
/// the same depth, so the polynomial that runs up along the value axis (10 keys, between 1 and
/// 3.4 m) does not hide the axis and its ticks.
#[test]
fn the_lagrange_axes_are_stroked_over_the_curves() {
    let mut frame = Frame::default();
    LagrangeScene::new().draw(&mut frame);
    let rgb = |c: [f32; 4]| Vec3::new(c[0], c[1], c[2]);
    let dark = inbetween::draw::palette::DARK;
    let curves = [LAGRANGE_BASE, LAGRANGE_MORE, LAGRANGE_SPLINE];
    let last_curve = frame.strokes.iter().rposition(|s| curves.contains(&rgb(s.color)));
    let first_axis = frame.strokes.iter().position(|s| rgb(s.color) == dark);
    assert!(
        matches!((last_curve, first_axis), (Some(c), Some(a)) if a > c),
        "last curve stroke {last_curve:?}, first axis stroke {first_axis:?}"
    );
}

/// The Lagrange graph declares its axes and their labels for the camera's fit, so that after an
/// orbit (lessons/02-keyframes/lesson.js: target (0.15, 1.4, 0), distance 6.5, yaw 0, pitch 0)
/// the value axis's foot stays on the canvas: every label's anchor and both axes' ends lie on
/// a 650 × 420 canvas, at 3, 6 and 16 keys, seen straight on and orbited.
#[test]
fn the_lagrange_graph_stays_on_the_canvas_when_orbited() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    for keys in [3.0, 6.0, 16.0] {
        let mut s = LagrangeScene::new();
        s.set_key_count(keys).unwrap();
        let mut frame = Frame::default();
        s.draw(&mut frame);
        assert!(
            !frame.keep_in_view.is_empty(),
            "nothing declared for the fit"
        );
        let last = keys - 1.0;
        let ends = [s.place(0.0, -0.8), s.place(0.0, 3.4), s.place(last, 0.0)];
        for (yaw, pitch) in [(0.0, 0.0), (-1.04, 0.34), (0.8, -0.3), (1.4, 0.6)] {
            let size = Vec2::new(650.0, 420.0);
            let mut camera = OrbitCamera::from_view([0.15, 1.4, 0.0, 6.5, yaw, pitch]);
            camera.fit(&frame.fit_points(), size, FIT_PAD_PX);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let anchors = frame.labels.iter().map(|l| l.anchor);
            for p in ends.into_iter().chain(anchors) {
                let c = project_to_canvas(view_proj, size, p).unwrap();
                assert!(
                    c.cmpge(Vec2::ZERO).all() && c.cmple(size).all(),
                    "{keys} keys, yaw {yaw}, pitch {pitch}: {p} at {c}, off the canvas"
                );
            }
        }
    }
}

/// Figure 3 is a graph seen straight on (its caption): a drag on it pans, keeping it facing the
/// camera and its time axis as wide on the canvas, where an orbit would squeeze it.
#[test]
fn the_lagrange_graph_pans_on_a_drag_and_keeps_its_width() {
    let s = LagrangeScene::new();
    let mut frame = Frame::default();
    s.draw(&mut frame);
    // The page's camera (lessons/02-keyframes/lesson.js); the time axis from the first key to
    // the last (10 keys at the start).
    let axis = [s.place(0.0, 0.0), s.place(9.0, 0.0)];
    flat::assert_drag_pans(&frame, [0.15, 1.4, 0.0, 6.5, 0.0, 0.0], Vec2::new(650.0, 420.0), axis);
}

#[test]
fn clip_graph_cuts_at_the_edge_instead_of_running_along_it() {
    // Up through the top edge, back down, and once through the bottom edge.
    let graph: Vec<(f32, f32)> = [0.0, 1.0, 3.0, 1.0, -0.5, -3.0, 0.5]
        .iter()
        .enumerate()
        .map(|(k, &y)| (k as f32, y))
        .collect();
    let pieces = clip_graph(&graph, (-1.0, 2.0));
    assert_eq!(pieces.len(), 3, "{pieces:?}");
    // The first piece ends where the graph crosses y = 2 between t = 1 and t = 2.
    assert_eq!(*pieces[0].last().unwrap(), (1.5, 2.0));
    // The second comes back in at y = 2 (t = 2.5) and leaves at y = -1 (t = 4.2).
    assert_eq!(pieces[1][0], (2.5, 2.0));
    let (t, y) = *pieces[1].last().unwrap();
    assert!((t - 4.2).abs() < 1e-5 && y == -1.0, "({t}, {y})");
    // The third re-enters at y = -1 between t = 5 and t = 6.
    assert!((pieces[2][0].0 - 5.571_428_5).abs() < 1e-5 && pieces[2][0].1 == -1.0);
    assert!(pieces
        .iter()
        .flatten()
        .all(|&(_, y)| (-1.0..=2.0).contains(&y)));
}

#[test]
fn the_lagrange_curve_through_more_keys_is_cut_not_flattened_at_the_edge() {
    // With 14 keys the red polynomial leaves the graph near both ends (Runge).
    let mut s = LagrangeScene::new();
    s.set_key_count(14.0).unwrap();
    let mut frame = Frame::default();
    s.draw(&mut frame);
    let red: Vec<(Vec3, Vec3)> = frame.segments_of(LAGRANGE_MORE).collect();
    assert!(!red.is_empty());
    let top = s.place(0.0, 3.4).y;
    let bottom = s.place(0.0, -0.8).y;
    // No drawn segment runs along an edge: that would be a flat line the polynomial never draws.
    for (a, b) in &red {
        let on_edge = |p: &Vec3| (p.y - top).abs() < 1e-4 || (p.y - bottom).abs() < 1e-4;
        assert!(
            !(on_edge(a) && on_edge(b)),
            "segment {a} to {b} runs along the edge"
        );
        assert!(a.y <= top + 1e-4 && a.y >= bottom - 1e-4);
    }
    // The curve is cut: it has more than one piece (one polyline per piece).
    let pieces = red
        .windows(2)
        .filter(|w| (w[0].1 - w[1].0).length() > 1e-6)
        .count()
        + 1;
    assert!(pieces >= 2, "{pieces} pieces");
}

/// Right except where a typical mistake shows: `find_segment` without the upper clamp (returns
/// N − 1 at the last key), `cardinal_tangents` that ignores μ, `hermite_basis` that swaps the
/// tangent weights' signs only past s = 0.6.
fn almost(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    match name {
        "find_segment" => {
            let n = args[0] as usize;
            let (times, t) = (&args[1..=n], args[n + 1]);
            let count = times.iter().filter(|&&k| k <= t).count();
            Ok(vec![count.max(1) as f32 - 1.0])
        }
        "cardinal_tangents" => {
            let n = args[0] as usize;
            let mut fixed = args.to_vec();
            *fixed.last_mut().unwrap() = 1.0;
            let _ = n;
            right(name, &fixed)
        }
        "hermite_basis" if args[0] > 0.6 => {
            let [a, b, c, d] = hermite_basis(args[0]);
            Ok(vec![a, -b, c, -d])
        }
        _ => right(name, args),
    }
}

#[test]
fn a_verdict_checks_probe_inputs_beyond_the_one_shown() {
    let (note, _) = note_with(almost, true);
    // At the ball's time (1.1 s, s ≈ 0.4 in segment 1, μ = 1) all three look right…
    assert!(
        note.contains("Your find_segment matches the reference at t = 1.100 s (the figure's input), but differs at t = 3.200 s: yours (4.000), reference (3.000)"),
        "{note}"
    );
    assert!(
        note.contains("Your cardinal_tangents matches the reference at all 5 keys (μ = 1.000) (the figure's input), but differs at the figure's keys' x at μ = 0.5"),
        "{note}"
    );
    assert!(
        note.contains("Your hermite_basis matches the reference at s = ")
            && note.contains("but differs at s = 0.750"),
        "{note}"
    );
    // At s = 1 both tangent weights are 0, so a sign error cannot show there.
    assert!(!note.contains("differs at s = 1.000"), "{note}");
    // The basis figure says the same at its own s.
    let n = hermite_basis_note(almost, 0.3, true).unwrap();
    assert!(n.contains("but differs at s = 0.750"), "{n}");
    assert!(note.contains("It also differs at t = 3.700 s"), "{note}");
    // A right answer is checked at the probes too, and the note lists them.
    let (note, _) = note_with(right, true);
    assert!(note.contains("and at 5 more inputs (t = -0.500 s; t = 0.000 s; t = 1.600 s; t = 3.200 s; t = 3.700 s)"), "{note}");
    assert!(
        note.contains("Your arc_length_invert matches the reference at s = "),
        "{note}"
    );
}

/// True when two non-neighbouring segments of the polyline cross.
fn self_intersects(path: &[Vec2]) -> bool {
    let cross = |o: Vec2, a: Vec2, b: Vec2| (a - o).perp_dot(b - o);
    for i in 0..path.len().saturating_sub(1) {
        for j in i + 2..path.len() - 1 {
            let (p, q, r, s) = (path[i], path[i + 1], path[j], path[j + 1]);
            let d1 = cross(r, s, p);
            let d2 = cross(r, s, q);
            let d3 = cross(p, q, r);
            let d4 = cross(p, q, s);
            if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
                return true;
            }
        }
    }
    false
}

#[test]
fn the_captions_preset_claims_hold() {
    let path = |scheme: &str, name: &str| {
        let mut s = scene(scheme);
        let (t, v) = preset(name).unwrap();
        s.set_keys(t, v).unwrap();
        path_of(&s)
    };
    // Figure 7: "loop-prone makes A (Catmull-Rom) loop while B (centripetal) passes straight".
    assert!(self_intersects(&path("cardinal", "loop")));
    assert!(!self_intersects(&path("centripetal", "loop")));
    // "zig-zag: the paths differ by up to 7.5 cm, and B's speed jumps at every key by 0.3 to
    // 0.5 m/s while A's is continuous".
    let (a, b) = (
        path("cardinal", "centripetal"),
        path("centripetal", "centripetal"),
    );
    let gap = a
        .iter()
        .zip(&b)
        .map(|(p, q)| (*p - *q).length())
        .fold(0.0f32, f32::max);
    assert!((gap - 0.075).abs() < 0.005, "largest gap {gap}");
    // Figure 7's note gives that gap, from the two motions at the same moment.
    let on = |scheme: &str| {
        let mut s = scene(scheme);
        let (t, v) = preset("centripetal").unwrap();
        s.set_keys(t, v).unwrap();
        s
    };
    let note = on("cardinal").gap_note(&on("centripetal"));
    let noted: f32 = note
        .split("at most ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next()?.parse().ok())
        .unwrap_or_else(|| panic!("{note}"));
    assert!((noted / 100.0 - gap).abs() < 0.001, "{note} against {gap} m");
    assert!(on("cardinal").gap_note(&on("cardinal")).contains("at most 0.000 cm"));
    for (scheme, lo, hi) in [("cardinal", 0.0, 0.05), ("centripetal", 0.3, 0.55)] {
        let mut s = scene(scheme);
        let (times, values) = preset("centripetal").unwrap();
        s.set_keys(times.clone(), values).unwrap();
        for &k in &times[1..times.len() - 1] {
            let before = s.track().evaluate(k - 1e-3).velocity.length();
            let after = s.track().evaluate(k + 1e-3).velocity.length();
            let jump = (after - before).abs();
            assert!(
                (lo..=hi).contains(&jump),
                "{scheme} at {k} s: {before} to {after}"
            );
        }
    }
    // Figure 2: the uneven preset's linear speeds are 5.09, 1.20 and 9.01 m/s.
    let mut s = scene("linear");
    let (t, v) = preset("uneven").unwrap();
    s.set_keys(t, v).unwrap();
    let rows = s.sample_motion(601).unwrap();
    let speed_at = |time: f32| {
        rows.iter()
            .min_by(|a, b| (a[0] - time).abs().total_cmp(&(b[0] - time).abs()))
            .unwrap()[1]
    };
    for (time, expected) in [(0.15, 5.09), (1.5, 1.20), (2.9, 9.01)] {
        assert!(
            (speed_at(time) - expected).abs() < 0.01,
            "at {time} s: {}",
            speed_at(time)
        );
    }
    // Figure 8, same keys: at constant speed the red curve is flat at 2.1 m/s (6.34 m in 3 s),
    // and the keyed in-betweens sit mostly on the middle segment (2.5 of the 3 seconds).
    s.set_arc_length(true);
    let rows = s.sample_motion(601).unwrap();
    for r in &rows {
        assert!((r[2] - 2.11).abs() < 0.01, "constant speed at {} s: {}", r[0], r[2]);
    }
    s.set_arc_length(false);
    s.set_ghost_count(24).unwrap();
    let mut ghosts = Vec::new();
    s.ghosts(&mut ghosts);
    let on_middle = ghosts.iter().filter(|g| g.y > 1.75 && g.x > -1.6 && g.x < 1.4).count();
    assert!(on_middle * 2 > ghosts.len(), "{on_middle} of {} ghosts on the middle segment", ghosts.len());
}

#[test]
fn the_lagrange_captions_numbers_hold() {
    use inbetween::curves::Track;
    // (largest |blue − green|, largest gap between any two of blue, red and green, largest |red|,
    // where red is farthest from green as a fraction of the time range)
    let measure = |n: f32| {
        let mut s = LagrangeScene::new();
        s.set_key_count(n).unwrap();
        let ((ta, ya), (tb, yb)) = s.key_sets();
        let with =
            |t: Vec<f32>, y: Vec<f32>, i| Track::new(t, y).unwrap().with_interpolation(i).unwrap();
        let blue = with(ta, ya, Interpolation::Lagrange);
        let red = with(tb.clone(), yb.clone(), Interpolation::Lagrange);
        let green = with(tb, yb, Interpolation::CATMULL_ROM);
        let (mut bg, mut all, mut rmax, mut worst) = (0.0f32, 0.0f32, 0.0f32, (0.0f32, 0.0f32));
        for k in 0..=2000 {
            let u = k as f32 / 2000.0;
            let t = (n - 1.0) * u;
            // The largest gap between any two of the three curves.
            let (b, r, g) = (blue.position(t), red.position(t), green.position(t));
            bg = bg.max((b - g).abs());
            all = all.max(bg).max((r - g).abs()).max((r - b).abs());
            rmax = rmax.max(red.position(t).abs());
            let d = (red.position(t) - green.position(t)).abs();
            if d > worst.0 {
                worst = (d, u);
            }
        }
        (bg, all, rmax, worst.1)
    };
    // The figure's note gives the two numbers the Try this reads, as measured here.
    let noted = |n: f32| {
        let mut s = LagrangeScene::new();
        s.set_key_count(n).unwrap();
        let note = s.note().to_string();
        let after = |words: &str| -> f32 {
            let rest = &note[note.find(words).unwrap_or_else(|| panic!("{note}")) + words.len()..];
            rest.split(' ').next().unwrap().parse().unwrap_or_else(|_| panic!("{note}"))
        };
        (after("at most "), after("|y| = "), note)
    };
    for n in [3.0, 10.0, 16.0] {
        let ((_, all, rmax, _), (gap, red, note)) = (measure(n), noted(n));
        assert!((gap - all).abs() < 0.01 * all && (red - rmax).abs() < 0.01 * rmax, "{n}: {note}");
    }
    // 3 keys: all three nearly agree (within 12 cm: red and blue differ by up to 11.9 cm).
    let (_, all, _, _) = measure(3.0);
    assert!((0.10..0.12).contains(&all), "{all}");
    // 10 keys (the default): blue within 9 cm of green, red already off the 3.4 m graph.
    let (bg, _, rmax, _) = measure(10.0);
    assert!(bg < 0.09 && rmax > 3.4, "{bg} {rmax}");
    // 16 keys: red swings out past 100 m, worst near an end.
    let (_, _, rmax, at) = measure(16.0);
    assert!(
        rmax > 100.0 && !(0.15..=0.85).contains(&at),
        "{rmax} at {at}"
    );
}

#[test]
fn figure_5s_acceleration_jumps_for_catmull_rom_and_not_for_natural() {
    let (times, _) = preset("default").unwrap();
    for (scheme, jumps) in [("cardinal", true), ("natural", false)] {
        let s = scene(scheme);
        for &k in &times[1..times.len() - 1] {
            // The plot shows |p″|: its magnitude must jump, not only its direction.
            let before = s.track().evaluate(k - 1e-3).acceleration.length();
            let after = s.track().evaluate(k + 1e-3).acceleration.length();
            let jump = (after - before).abs();
            assert_eq!(
                jump > 1.0,
                jumps,
                "{scheme} at {k} s: a jump of {jump} m/s²"
            );
            if !jumps {
                assert!(jump < 0.1, "{scheme} at {k} s: {jump}");
            }
        }
    }
}

#[test]
fn the_space_time_view_puts_the_clock_along_the_depth() {
    let mut s = KeyframesScene::new();
    let mut frame = Frame::default();
    s.draw(&mut frame, 1.0).unwrap();
    let curve: Vec<Vec3> = frame.segments_of(SPACETIME_COLOR).map(|(a, _)| a).collect();
    assert!(!curve.is_empty(), "drawn by default");
    // Every point is (x(τ), y(τ), −0.8 τ): the depth is the clock, the position the ball's.
    for p in &curve {
        let tau = -p.z / TIME_DEPTH_M_PER_SEC;
        let q = s.position(tau).unwrap();
        assert!(
            (p.truncate() - q).length() < 1e-4,
            "{p} against {q} at {tau} s"
        );
    }
    let deepest = curve.iter().fold(0.0f32, |m, p| m.min(p.z));
    assert!((deepest + TIME_DEPTH_M_PER_SEC * s.track().duration_sec()).abs() < 0.02);
    // The in-betweens lie on it at equal steps of depth (equal time).
    let ghosts: Vec<f32> = frame
        .points
        .iter()
        .filter(|p| Vec3::from_slice(&p.color[..3]) == GHOST_COLOR)
        .map(|p| p.center[2])
        .collect();
    assert_eq!(ghosts.len(), 24);
    let step = ghosts[1] - ghosts[0];
    assert!(ghosts.windows(2).all(|w| (w[1] - w[0] - step).abs() < 1e-4));
    // The ball rides the curve at the clock's depth.
    let ball = frame
        .meshes
        .iter()
        .find(|m| m.color.truncate() == BALL_COLOR)
        .unwrap();
    let centre = ball.model.w_axis.truncate();
    assert!(
        (centre.z + TIME_DEPTH_M_PER_SEC * 1.0).abs() < 1e-5,
        "{centre}"
    );
    assert!((centre.truncate() - s.position(1.0).unwrap()).length() < 1e-5);
    // Off: no space-time curve, the in-betweens back on the path in the plane z = 0.
    s.set_time_depth(false);
    let mut flat = Frame::default();
    s.draw(&mut flat, 1.0).unwrap();
    assert_eq!(flat.segments_of(SPACETIME_COLOR).count(), 0);
    assert!(flat
        .points
        .iter()
        .filter(|p| Vec3::from_slice(&p.color[..3]) == GHOST_COLOR)
        .all(|p| p.center[2] == 0.0));
    // With the student's functions the curve is theirs: a wrong find_segment moves it.
    s.set_time_depth(true);
    s.set_use_exercise(true);
    s.set_runner(wrong);
    let mut theirs = Frame::default();
    s.draw(&mut theirs, 1.0).unwrap();
    let a: Vec<(Vec3, Vec3)> = theirs.segments_of(SPACETIME_COLOR).collect();
    assert_eq!(a.len(), frame.segments_of(SPACETIME_COLOR).count());
    assert!(a
        .iter()
        .zip(frame.segments_of(SPACETIME_COLOR))
        .any(|(x, y)| (x.0 - y.0).length() > 0.05));
}

#[test]
fn the_space_time_axis_counts_the_clocks_seconds() {
    // The clock reads the keys' own seconds, so the time axis does too: each tick's label names
    // the clock's whole second and sits at its depth after key 0, not counted from key 0.
    for (times, labels) in [
        (vec![2.2, 3.2], vec!["3 s"]),
        (vec![0.5, 1.5, 2.7], vec!["1 s", "2 s"]),
        (vec![0.0, 1.0, 2.0], vec!["0 s", "1 s", "2 s"]),
    ] {
        let mut s = KeyframesScene::new();
        let values = (0..times.len()).map(|k| Vec2::new(k as f32, 1.0)).collect();
        s.set_keys(times.clone(), values).unwrap();
        // The page's camera (lessons/02-keyframes/lesson.js), which sets how many ticks are labelled.
        let camera = inbetween::camera::OrbitCamera::from_view([0.3, 0.8, -1.3, 6.5, 0.75, 0.4]);
        s.set_view(camera, 760.0, 300.0);
        let mut frame = Frame::default();
        s.draw(&mut frame, 0.0).unwrap();
        let ticks: Vec<_> = frame.labels.iter().filter(|l| l.text.ends_with(" s")).collect();
        let texts: Vec<&str> = ticks.iter().map(|l| l.text.as_str()).collect();
        assert_eq!(texts, labels, "keys at {times:?}");
        for l in ticks {
            let second: f32 = l.text.trim_end_matches(" s").parse().unwrap();
            let depth = -TIME_DEPTH_M_PER_SEC * (second - times[0]);
            assert!((l.anchor.z - depth).abs() < 1e-4, "{} at z = {}", l.text, l.anchor.z);
        }
    }
}

#[test]
fn cardinal_figure_compares_the_time_rule_with_the_halved_chord() {
    let mut s = CardinalScene::new();
    // Uneven preset at μ = 1: key 0's tangent is the first segment's slope, 1.53 m in 0.3 s.
    let by_time = s.tangents(ChordRule::ByTime);
    let halved = s.tangents(ChordRule::Halved);
    assert!((by_time[0].length() - 5.09).abs() < 0.01, "{}", by_time[0].length());
    assert!((halved[0].length() - 1.53).abs() < 0.01, "{}", halved[0].length());
    // The caption's top speeds: 11.6 m/s by the time rule, 12.6 m/s halved.
    let rows = s.sample_speeds(401).unwrap();
    let top = |c: usize| rows.iter().map(|r| r[c]).fold(0.0f32, f32::max);
    assert!((top(1) - 11.6).abs() < 0.05, "{}", top(1));
    assert!((top(2) - 12.6).abs() < 0.05, "{}", top(2));
    assert!(s.note().contains("11.605") && s.note().contains("12.646"), "{}", s.note());
    // With keys one second apart (the loop preset) both rules agree.
    s.set_preset("loop").unwrap();
    assert_eq!(s.tangents(ChordRule::ByTime), s.tangents(ChordRule::Halved));
    // μ = 0: every tangent is zero, so the ball stops at every key.
    s.set_preset("uneven").unwrap();
    s.set_tension(0.0).unwrap();
    let (times, _) = s.keys();
    let times = times.to_vec();
    for rule in [ChordRule::ByTime, ChordRule::Halved] {
        let track = s.track(rule);
        for &t in &times {
            assert!(track.velocity(t).length() < 1e-5, "speed at key {t} s");
        }
    }
    // Rejected input changes nothing.
    assert!(s.set_tension(2.5).is_err());
    assert!(s.set_tension(f32::NAN).is_err());
    assert!(s.set_preset("nope").is_err());
    assert!(ChordRule::from_name("third").is_err());
    assert_eq!(s.tangents(ChordRule::ByTime), vec![Vec2::ZERO; 4]);
    assert!(s.path(ChordRule::ByTime, 1).is_err());
}

#[test]
fn spacing_charts_of_the_eases() {
    // Linear spaces the frames evenly; smoothstep's first of 7 frames covers 0.074 of the way,
    // under half of linear's 0.167; ease in starts slower still (0.028) and ease out faster (0.306).
    let first = |name: &str| spacing_ticks(name, 7).unwrap()[1];
    assert!((first("none") - 1.0 / 6.0).abs() < 1e-6);
    assert!((first("smoothstep") - 0.074).abs() < 1e-3);
    assert!((first("in") - 0.028).abs() < 1e-3);
    assert!((first("out") - 0.306).abs() < 1e-3);
    for name in EASE_NAMES {
        let ticks = spacing_ticks(name, 13).unwrap();
        assert_eq!((ticks[0], ticks[12]), (0.0, 1.0), "{name} goes from key to key");
        assert!(ticks.windows(2).all(|w| w[1] >= w[0]), "{name} never goes back");
        let rows = ease_samples(name, 101).unwrap();
        assert_eq!(rows.len(), 101);
        // Slow in and out start and end at rest: e′ is 0 at both ends.
        if ["smoothstep", "smootherstep", "sine", "inout"].contains(&name) {
            assert!(rows[0][2].abs() < 1e-5 && rows[100][2].abs() < 1e-4, "{name}");
        }
    }
    // Figure 4's Try: at s = 0.3 the note reads h00 = 0.784 and h01 = 0.216, which sum to 1.
    let note = hermite_basis_note(direct, 0.3, false).unwrap();
    assert!(note.contains("h00 = 0.784") && note.contains("h01 = 0.216"), "{note}");
    // Figure 8 with smoothstep: both speeds start and end at zero.
    let mut s = KeyframesScene::new();
    s.set_ease("smoothstep").unwrap();
    s.set_arc_length(true);
    let rows = s.sample_motion(201).unwrap();
    for r in [rows[0], rows[200]] {
        assert!(r[1].abs() < 1e-4 && r[2].abs() < 1e-4, "{r:?}");
    }
    assert!(spacing_ticks("bounce", 7).is_err());
    assert!(spacing_ticks("none", 1).is_err());
    assert!(spacing_ticks("none", 61).is_err());
    assert!(ease_samples("none", 1).is_err());
}

/// The number written after `words` in `text` (the first run of digits).
fn number_after(text: &str, words: &str) -> usize {
    let at = text
        .find(words)
        .unwrap_or_else(|| panic!("the text names no '{words} N': {text}"));
    let rest = &text[at + words.len()..];
    let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
    digits
        .parse()
        .unwrap_or_else(|_| panic!("no number after '{words}': {rest}"))
}

#[test]
fn figure_6s_try_this_names_a_key_that_moves_all_of_b_and_only_part_of_a() {
    // The caption's claim, read from the page: "drag key K … B change all the way to the last
    // key, A only up to key M".
    let page = include_str!("../lessons/02-keyframes/index.html");
    let figure = &page[page.find("id=\"fig-natural\"").unwrap()..];
    let caption = &figure[..figure.find("</figcaption>").unwrap()];
    let caption = caption.split_whitespace().collect::<Vec<_>>().join(" ");
    let (dragged, reach) = (
        number_after(&caption, "drag key "),
        number_after(&caption, "A only up to key "),
    );
    let (times, values) = preset("default").unwrap();
    let last = times.len() - 1;
    // Figure 6 draws A (Catmull-Rom) and B (natural) on Figure 1's keys, its path and ball at
    // `position` and its plot from `sample_motion`'s acceleration: what changes there when key
    // `k` moves 0.5 m up, at 400 times over the motion.
    let changed = |scheme: &str, k: usize| -> Vec<(f32, bool)> {
        let mut moved = values.clone();
        moved[k].y += 0.5;
        let before = scene(scheme);
        let mut after = scene(scheme);
        after.set_keys(times.clone(), moved).unwrap();
        let (rows_before, rows_after) = (
            before.sample_motion(400).unwrap(),
            after.sample_motion(400).unwrap(),
        );
        rows_before
            .iter()
            .zip(&rows_after)
            .map(|(a, b)| {
                let tau = a[0] - times[0];
                let path = before.position(tau).unwrap() - after.position(tau).unwrap();
                (a[0], path.length() > 1e-4 || (a[3] - b[3]).abs() > 1e-3)
            })
            .collect()
    };
    // Which of the keys' segments change anywhere inside them.
    let segments_changed = |samples: &[(f32, bool)]| -> Vec<bool> {
        times
            .windows(2)
            .map(|w| samples.iter().any(|&(t, c)| c && t > w[0] && t < w[1]))
            .collect()
    };
    let b = changed("natural", dragged);
    assert_eq!(
        segments_changed(&b),
        vec![true; last],
        "B changes on every segment when key {dragged} moves"
    );
    let a = changed("cardinal", dragged);
    let expected: Vec<bool> = (0..last).map(|i| i < reach).collect();
    assert_eq!(
        segments_changed(&a),
        expected,
        "A changes up to key {reach} only when key {dragged} moves"
    );
    assert!(
        a.iter().all(|&(t, c)| !c || t <= times[reach]),
        "A changes past key {reach}"
    );
    assert!(reach < last, "the caption promises a part of A that stays");
    // "key 2 … changes all four of A's segments".
    assert_eq!(segments_changed(&changed("cardinal", 2)), vec![true; last]);
}

/// The box round the first loop of a polyline: the points between the first two segments that
/// cross (the page's `loopBox`, lessons/02-keyframes/lesson.js, adds the crossing point).
fn loop_box(path: &[Vec2]) -> Option<[Vec2; 2]> {
    let side = |p: Vec2, q: Vec2, r: Vec2| (q - p).perp_dot(r - p);
    for j in 2..path.len().saturating_sub(1) {
        for i in 0..j - 1 {
            let (a, b, c, d) = (path[i], path[i + 1], path[j], path[j + 1]);
            if side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0 {
                let inside = &path[i + 1..=j];
                return Some(inside.iter().fold([inside[0]; 2], |[lo, hi], &p| [lo.min(p), hi.max(p)]));
            }
        }
    }
    None
}

#[test]
fn figure_7s_loop_is_about_3_cm_across_and_only_catmull_rom_loops() {
    let path_on = |scheme: &str, name: &str| {
        let mut s = scene(scheme);
        let (t, v) = preset(name).unwrap();
        s.set_keys(t, v).unwrap();
        path_of(&s)
    };
    // Loop-prone: Catmull-Rom loops between keys 1 and 2, "about 3 cm across" (Figure 7's
    // caption; a few pixels in its view, which the page's inset magnifies).
    let (_, keys) = preset("loop").unwrap();
    let [lo, hi] = loop_box(&path_on("cardinal", "loop")).expect("A loops");
    let size = hi - lo;
    assert!(
        (0.025..0.04).contains(&size.max_element()),
        "the loop is {size} m"
    );
    let middle = (lo + hi) / 2.0;
    assert!((middle - (keys[1] + keys[2]) / 2.0).length() < 0.2, "{lo} {hi}");
    // Centripetal passes straight; on the default keys no scheme with a path loops, so the
    // page shows no inset there.
    assert_eq!(loop_box(&path_on("centripetal", "loop")), None);
    for scheme in ["linear", "lagrange", "hermite", "cardinal", "natural", "centripetal"] {
        assert_eq!(loop_box(&path_of(&scene(scheme))), None, "{scheme}");
    }
}
