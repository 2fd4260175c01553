//! Lesson 10 figure logic: validation, the two forms side by side, the full form's warning, the
//! animation and its plot, and the note about the student's exercise.

use glam::Vec3;
use inbetween::draw::{Frame, MeshId};
use inbetween::figures::blend_shapes::{FaceFigure, Show, LOOP_SECONDS};

const IDS: [MeshId; 2] = [MeshId(3), MeshId(4)];

#[test]
fn controls_validate_and_the_full_form_reports_a_bad_sum() {
    let mut f = FaceFigure::new();
    assert!(f.set_weight(7, 0.5).unwrap_err().contains("target index 7"));
    assert!(f.set_weight(0, f32::NAN).unwrap_err().contains("weight"));
    assert!(f.set_show("half").unwrap_err().contains("show"));
    assert!(f.set_base_weight(2.0).unwrap_err().contains("base weight"));
    assert!(f.weight_curves(1).is_err());
    assert!(f.weight_curves(1_000_000).is_err());
    f.set_animate(false);
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, IDS, 0.0).unwrap();
    assert_eq!(f.show(), Show::Both);
    assert!(note.contains("Differential (left)"), "{note}");
    assert!(
        note.contains("the same face as the differential form"),
        "{note}"
    );
    f.set_show("differential").unwrap();
    let note = f.draw(&mut frame, IDS, 0.0).unwrap();
    assert!(
        note.starts_with("Differential:") && !note.contains("Full"),
        "{note}"
    );
    f.set_show("full").unwrap();
    f.set_base_weight(0.5).unwrap();
    let note = f.draw(&mut frame, IDS, 0.0).unwrap();
    assert!(
        note.starts_with("Full:") && note.contains("not 1"),
        "{note}"
    );
    assert!(f.draw(&mut frame, IDS, f32::NAN).is_err());
    assert!(f.differential.take_dirty() && f.full.take_dirty());
}

/// A frame at the same weights (the timeline paused) blends and uploads nothing, so the renderer
/// can keep the canvas's last image; a new time or a moved slider blends again.
#[test]
fn a_paused_face_is_blended_once() {
    let mut f = FaceFigure::new();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 1.3).unwrap();
    assert!(f.differential.take_dirty() && f.full.take_dirty());
    let before = f.full.positions.clone();
    f.draw(&mut frame, IDS, 1.3).unwrap();
    assert!(!f.differential.take_dirty() && !f.full.take_dirty());
    assert_eq!(f.full.positions, before);
    f.draw(&mut frame, IDS, 1.4).unwrap();
    assert!(
        f.differential.take_dirty() && f.full.take_dirty(),
        "a new time"
    );
    f.draw(&mut frame, IDS, 1.4).unwrap();
    f.set_weight(0, 0.2).unwrap();
    f.draw(&mut frame, IDS, 1.4).unwrap();
    assert!(f.full.take_dirty(), "a moved slider");
    assert_ne!(f.full.positions, before);
}

/// The mesh ids drawn in `frame` and where each stands.
fn heads(frame: &Frame) -> Vec<(MeshId, Vec3)> {
    frame
        .meshes
        .iter()
        .filter(|m| IDS.contains(&m.mesh))
        .map(|m| (m.mesh, m.model.w_axis.truncate()))
        .collect()
}

#[test]
fn both_forms_stand_side_by_side_and_agree_when_the_base_weight_is_one_minus_the_sum() {
    let mut f = FaceFigure::new();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 1.3).unwrap();
    let h = heads(&frame);
    assert_eq!(h.len(), 2);
    assert_eq!((h[0].0, h[1].0), (IDS[0], IDS[1]));
    assert!(
        h[0].1.x < -0.5 && h[1].1.x > 0.5,
        "differential left, full right: {h:?}"
    );
    assert_eq!(frame.labels.len(), 2);
    // The differential head's label reads leftwards from above it, away from the full head
    // (which grows with the total); the full head's reads rightwards.
    let (l, r) = (&frame.labels[0], &frame.labels[1]);
    assert!(l.text == "differential" && l.left && l.anchor.x < h[1].1.x - 1.0);
    assert!(r.text.starts_with("full") && !r.left);
    // Base weight 1 − Σw: the full form is the differential form.
    for (a, b) in f.differential.positions.iter().zip(&f.full.positions) {
        assert!(a.distance(*b) < 1e-5, "{a} vs {b}");
    }
    // A base weight by hand: full − differential = (s − 1) b₀ (s = base + Σw, b₀ the base).
    f.set_animate(false);
    for k in 0..4 {
        f.set_weight(k, 0.0).unwrap();
    }
    f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    let base = f.differential.positions.clone();
    for (k, w) in [0.5, 0.25, 0.75, 0.3].into_iter().enumerate() {
        f.set_weight(k, w).unwrap();
    }
    f.set_base_weight(0.8).unwrap();
    f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    let s = 0.8 + 1.8;
    for ((d, full), b) in f
        .differential
        .positions
        .iter()
        .zip(&f.full.positions)
        .zip(&base)
    {
        assert!(
            (*full - *d - (s - 1.0) * *b).length() < 1e-4,
            "{full} vs {d}"
        );
    }
    // One head alone stands in the middle, without labels.
    f.set_show("full").unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 0.0).unwrap();
    let h = heads(&frame);
    assert_eq!(h.len(), 1);
    assert_eq!(h[0].0, IDS[1]);
    assert!(h[0].1.x.abs() < 1e-6);
    assert!(frame.labels.is_empty());
}

#[test]
fn the_weight_plot_follows_the_animation_and_the_full_forms_total() {
    let mut f = FaceFigure::new();
    let samples = 41;
    let flat = f.weight_curves(samples).unwrap();
    assert_eq!(flat.len(), samples * 7);
    for row in flat.chunks(7) {
        let (t, w) = (row[0], &row[1..5]);
        assert_eq!(w, f.weights_at(t));
        assert!((row[5] - w.iter().sum::<f32>()).abs() < 1e-6);
        assert!((row[6] - 1.0).abs() < 1e-6, "base 1 − Σw: the total is 1");
    }
    assert_eq!(flat[0], 0.0);
    assert!((flat[(samples - 1) * 7] - LOOP_SECONDS).abs() < 1e-6);
    // Each weight reaches its slider's value during the loop.
    for k in 0..4 {
        let peak = flat.chunks(7).map(|r| r[1 + k]).fold(0f32, f32::max);
        assert!(
            (peak - [1.0, 0.6, 0.8, 0.7][k]).abs() < 0.01,
            "weight {k} peaks at {peak}"
        );
    }
    f.set_base_weight(0.25).unwrap();
    for row in f.weight_curves(samples).unwrap().chunks(7) {
        assert!((row[6] - (0.25 + row[5])).abs() < 1e-6);
    }
    f.set_animate(false);
    let flat = f.weight_curves(samples).unwrap();
    assert!(
        flat.chunks(7).all(|r| r[1..5] == flat[1..5]),
        "still weights: flat lines"
    );
}

#[test]
fn the_animation_moves_the_weights_and_the_exercise_note_shows() {
    let mut f = FaceFigure::new();
    assert_ne!(f.weights_at(0.0), f.weights_at(1.0));
    assert_eq!(f.weights_at(0.0)[0], 0.0);
    f.set_animate(false);
    assert_eq!(f.weights_at(0.0), f.weights_at(1.0));
    f.set_use_exercise(true);
    let note = f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    if cfg!(feature = "solutions") {
        assert!(note.contains("matches the reference"), "{note}");
    } else {
        assert!(note.contains("Not done yet: exercise 10.1"), "{note}");
    }
}

#[test]
fn the_eyes_shrink_with_the_face_when_the_full_form_sum_is_not_one() {
    // The eyes are separate spheres: in the full form with weights summing to s, every face
    // vertex is scaled by s towards the head's origin, and the eyes must follow or they float off.
    let eye_positions = |f: &mut FaceFigure| -> Vec<Vec3> {
        let mut frame = Frame::default();
        f.draw(&mut frame, IDS, 0.0).unwrap();
        frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::SPHERE)
            .map(|m| m.model.w_axis.truncate())
            .collect()
    };
    let mut f = FaceFigure::new();
    f.set_animate(false);
    f.set_show("full").unwrap();
    let whole = eye_positions(&mut f);
    f.set_base_weight(0.5).unwrap();
    let w: f32 = f.weights_at(0.0).iter().sum();
    let scaled = eye_positions(&mut f);
    assert_eq!(whole.len(), 2);
    let head = Vec3::new(0.0, 1.2, 0.0);
    for (a, b) in whole.iter().zip(&scaled) {
        let expected = head + (*a - head) * (0.5 + w);
        assert!((*b - expected).length() < 1e-5, "{b} vs {expected}");
    }
}

/// The largest distance of a head's vertex from its vertical axis (metres).
fn horizontal_radius(positions: &[Vec3]) -> f32 {
    positions
        .iter()
        .map(|p| (p.x * p.x + p.z * p.z).sqrt())
        .fold(0.0, f32::max)
}

#[test]
fn the_head_stays_within_its_radius_at_any_weights() {
    use inbetween::figures::blend_shapes::HEAD_RADIUS;
    let mut f = FaceFigure::new();
    f.set_animate(false);
    for combo in 0..81 {
        // Every weight at -0.5, 0.5 or 1.5 (the sliders' ends and middle).
        for k in 0..4 {
            let w = [-0.5, 0.5, 1.5][(combo / 3usize.pow(k as u32)) % 3];
            f.set_weight(k, w).unwrap();
        }
        f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
        let r = horizontal_radius(&f.differential.positions);
        assert!(r <= HEAD_RADIUS, "combination {combo}: radius {r}");
    }
}

#[test]
fn side_by_side_neither_head_reaches_into_the_other_and_the_view_frames_both() {
    use inbetween::camera::{project_to_canvas, OrbitCamera};
    let size = glam::Vec2::new(650.0, 420.0);
    let mut f = FaceFigure::new();
    // At the defaults (base 1 − Σw) the heads keep the figure's opening framing.
    let start = f.view_fit();
    assert!(
        start[0].abs() < 1e-6 && (start[3] - 4.8).abs() < 1e-6,
        "{start:?}"
    );
    for (animate, base, w) in [
        (false, 1.0, 1.5),  // the largest total: 1 + 4 × 1.5 = 7
        (true, 1.0, 1.5),   // pulsing up to about 4.5
        (false, 0.5, 0.5),  // the lesson's "Try this": 2.5
        (false, 0.0, -0.5), // negative: the head is turned inside out, twice as large
        (false, 0.2, 0.1),  // smaller than at rest
    ] {
        f.set_animate(animate);
        f.set_base_weight(base).unwrap();
        for k in 0..4 {
            f.set_weight(k, w).unwrap();
        }
        let s_max = f.largest_full_scale();
        let [x, y, z, distance] = f.view_fit();
        let mut camera = OrbitCamera {
            target: Vec3::new(x, y, z),
            distance,
            ..Default::default()
        };
        camera.orbit(0.15, 0.1);
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        for i in 0..16 {
            let t = LOOP_SECONDS * i as f32 / 16.0;
            let mut frame = Frame::default();
            f.draw(&mut frame, IDS, t).unwrap();
            let h = heads(&frame);
            let (left, right) = (h[0].1, h[1].1);
            let (r_left, r_right) = (
                horizontal_radius(&f.differential.positions),
                horizontal_radius(&f.full.positions),
            );
            assert!(
                r_right <= HEAD_RADIUS_FOR_TEST * s_max.max(1.0) + 1e-4,
                "{r_right} {s_max}"
            );
            let gap = (right - left).length() - r_left - r_right;
            assert!(
                gap > 0.0,
                "base {base}, w {w}, t {t}: the heads overlap by {}",
                -gap
            );
            // Both heads, with their full width and height, project inside the canvas.
            for (centre, r) in [
                (left, HEAD_RADIUS_FOR_TEST),
                (right, HEAD_RADIUS_FOR_TEST * s_max.max(1.0)),
            ] {
                for corner in [
                    Vec3::new(-r, -r, 0.0),
                    Vec3::new(r, -r, 0.0),
                    Vec3::new(-r, r, 0.0),
                    Vec3::new(r, r, 0.0),
                ] {
                    let p = project_to_canvas(view_proj, size, centre + corner).unwrap();
                    assert!(
                        p.x > 0.0 && p.x < size.x && p.y > 0.0 && p.y < size.y,
                        "base {base}, w {w}: {corner} of the head at {centre} is off the canvas at {p}"
                    );
                }
            }
        }
    }
}

const HEAD_RADIUS_FOR_TEST: f32 = inbetween::figures::blend_shapes::HEAD_RADIUS;
