//! Lesson 10 figure logic: validation, the two forms side by side, the full form's warning, the
//! animation and its plot, and the note about the student's exercise.

use glam::Vec3;
use inbetween::draw::{Frame, MeshId};
use inbetween::figures::blend_shapes::{
    FaceFigure, Show, TargetsFigure, DEFAULT_WEIGHTS, FRAMED_SCALE, LOOP_SECONDS, PROBES,
    TARGETS_SPACING,
};

const IDS: [MeshId; 2] = [MeshId(3), MeshId(4)];

#[test]
fn controls_validate_and_the_full_form_reports_a_bad_sum() {
    let mut f = FaceFigure::new();
    assert!(f.set_weight(7, 0.5).unwrap_err().contains("target index 7"));
    assert!(f.set_weight(0, f32::NAN).unwrap_err().contains("weight"));
    assert!(f.set_show("half").unwrap_err().contains("show"));
    assert!(f.set_base_weight(2.0).unwrap_err().contains("base weight"));
    assert!(f
        .set_base_weight(-0.05)
        .unwrap_err()
        .contains("base weight"));
    assert!(f
        .set_base_weight(f32::NAN)
        .unwrap_err()
        .contains("base weight"));
    assert!(f.weight_curves(1).is_err());
    assert!(f.weight_curves(1_000_000).is_err());
    f.set_animate(false);
    let mut frame = Frame::default();
    // The defaults: base weight 0 by hand, so the full form's total is the targets' sum.
    let note = f.draw(&mut frame, IDS, 0.0).unwrap();
    assert_eq!(f.show(), Show::Both);
    assert!(note.contains("Differential (left)"), "{note}");
    assert!(
        note.contains("Full (right): base weight 0.000 + targets 2.700 = 2.700, not 1: p = 2.700·b₀ + Σ wₖ dₖ"),
        "{note}"
    );
    f.set_base_auto(true);
    let note = f.draw(&mut frame, IDS, 0.0).unwrap();
    assert!(
        note.contains("base weight -1.700 (1 − Σw) + targets 2.700 = 1.000: the weights sum to 1"),
        "{note}"
    );
    f.set_base_auto(false);
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
    // At the defaults (base weight 0 by hand) the heads differ; with the automatic base weight
    // 1 − Σw the full form is the differential form.
    let apart = f
        .differential
        .positions
        .iter()
        .zip(&f.full.positions)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f32::max);
    assert!(
        apart > 0.1,
        "the defaults show the two forms differ: {apart}"
    );
    f.set_base_auto(true);
    f.draw(&mut Frame::default(), IDS, 1.3).unwrap();
    for (a, b) in f.differential.positions.iter().zip(&f.full.positions) {
        assert!(a.distance(*b) < 1e-5, "{a} vs {b}");
    }
    f.set_base_auto(false);
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
    // One head alone stands in the middle, with its name; the full head's gives its total.
    f.set_show("full").unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 0.0).unwrap();
    let h = heads(&frame);
    assert_eq!(h.len(), 1);
    assert_eq!(h[0].0, IDS[1]);
    assert!(h[0].1.x.abs() < 1e-6);
    let names: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(names, ["full (total 2.600)"]);
    f.set_show("differential").unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 0.0).unwrap();
    let names: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(names, ["differential"]);
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
        assert!(
            (row[6] - row[5]).abs() < 1e-6,
            "base 0 by hand: the total is Σw"
        );
    }
    f.set_base_auto(true);
    for row in f.weight_curves(samples).unwrap().chunks(7) {
        assert!((row[6] - 1.0).abs() < 1e-6, "base 1 − Σw: the total is 1");
    }
    f.set_base_auto(false);
    assert_eq!(flat[0], 0.0);
    assert!((flat[(samples - 1) * 7] - LOOP_SECONDS).abs() < 1e-6);
    // Each weight reaches its slider's value during the loop.
    for k in 0..4 {
        let peak = flat.chunks(7).map(|r| r[1 + k]).fold(0f32, f32::max);
        assert!(
            (peak - DEFAULT_WEIGHTS[k]).abs() < 0.01,
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
    f.set_base_auto(true);
    let whole = eye_positions(&mut f);
    f.set_base_auto(false);
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
    // With the automatic base weight (total 1) the view makes room for the full head at
    // FRAMED_SCALE: 4.8 m (two heads at rest size) times 1.7, aimed at the middle of the
    // heads' box (from −2r to 2r·1.7).
    f.set_base_auto(true);
    let rest = f.view_fit();
    assert!(
        (rest[0] - 0.7 * HEAD_RADIUS_FOR_TEST).abs() < 1e-5
            && (rest[3] - 4.8 * FRAMED_SCALE).abs() < 1e-5,
        "{rest:?}"
    );
    f.set_base_auto(false);
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

/// The largest distance between the two heads' matching vertices (each in its head's frame).
fn largest_gap(f: &FaceFigure) -> f32 {
    f.differential
        .positions
        .iter()
        .zip(&f.full.positions)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f32::max)
}

/// The page's numbers: at the defaults the full form's total (base 0 by hand, so Σw) swings
/// between 1.03 and 1.67 over the loop.
#[test]
fn the_defaults_total_swings_as_the_page_says() {
    let f = FaceFigure::new();
    assert_eq!(f.weights(), DEFAULT_WEIGHTS);
    let (lo, hi) = f.total_range();
    assert!(
        (lo - 1.03).abs() < 0.006 && (hi - 1.67).abs() < 0.006,
        "{lo} {hi}"
    );
    // The samples of the plot agree with the range.
    let flat = f.weight_curves(401).unwrap();
    let totals: Vec<f32> = flat.chunks(7).map(|r| r[6]).collect();
    let (plo, phi) = totals
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    assert!((plo - lo).abs() < 0.005 && (phi - hi).abs() < 0.005);
}

/// The page's "Try this", step by step, with the settings it names.
#[test]
fn the_try_this_steps_do_what_the_page_says() {
    let mut f = FaceFigure::new();
    let mut frame = Frame::default();
    // Untick animate; smile 0.5, the others 0; base weight 0.5 by hand: the sum is 1 and the
    // heads are the same.
    f.set_animate(false);
    for (k, w) in [0.5, 0.0, 0.0, 0.0].into_iter().enumerate() {
        f.set_weight(k, w).unwrap();
    }
    f.set_base_weight(0.5).unwrap();
    let note = f.draw(&mut frame, IDS, 0.0).unwrap();
    assert!(largest_gap(&f) < 1e-5);
    assert!(note.contains("= 1.000: the weights sum to 1"), "{note}");
    // Brows up 0.5 too: the total is 1.5 and the right head is the left one plus 0.5·b₀.
    f.set_weight(2, 0.5).unwrap();
    let note = f.draw(&mut frame, IDS, 0.0).unwrap();
    assert!(note.contains("= 1.500, not 1"), "{note}");
    assert!(note.contains("scaled by 1.500 about its centre"), "{note}");
    let base = inbetween::blend_shapes::face().mesh.positions;
    for ((d, full), b) in f
        .differential
        .positions
        .iter()
        .zip(&f.full.positions)
        .zip(&base)
    {
        assert!((*full - *d - 0.5 * *b).length() < 1e-5);
    }
    // The brows rise on the left head: the brow vertices move up by 0.5 × 12 cm at their middle.
    let brow = base
        .iter()
        .enumerate()
        .filter(|(_, p)| (p.y - 0.4495).abs() < 0.03 && p.z > 0.3)
        .map(|(v, p)| f.differential.positions[v].y - p.y)
        .fold(0.0, f32::max);
    assert!(brow > 0.055, "brows rise {brow}");
    // Animate: smile and brows pulse half a loop apart, so the total stays 1.0 all along.
    f.set_animate(true);
    let (lo, hi) = f.total_range();
    assert!(
        (lo - 1.0).abs() < 1e-5 && (hi - 1.0).abs() < 1e-5,
        "{lo} {hi}"
    );
    // Brows to 0 and jaw open to 0.5: a quarter of a loop apart, the total swings from 0.65
    // to 1.35 and the right head breathes.
    f.set_weight(2, 0.0).unwrap();
    f.set_weight(1, 0.5).unwrap();
    let (lo, hi) = f.total_range();
    assert!(
        (lo - 0.65).abs() < 0.005 && (hi - 1.35).abs() < 0.005,
        "{lo} {hi}"
    );
    // Tick "automatic": both heads the same again, whatever the time.
    f.set_base_auto(true);
    for t in [0.0, 0.7, 2.2] {
        f.draw(&mut frame, IDS, t).unwrap();
        assert!(largest_gap(&f) < 1e-5);
    }
}

#[test]
fn the_note_names_a_vanished_and_an_inside_out_base() {
    let mut f = FaceFigure::new();
    f.set_animate(false);
    f.set_show("full").unwrap();
    for k in 0..4 {
        f.set_weight(k, 0.0).unwrap();
    }
    let note = f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    assert!(note.contains("= 0.000, so the base vanishes"), "{note}");
    for k in 0..4 {
        f.set_weight(k, -0.25).unwrap();
    }
    let note = f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    assert!(note.contains("= -1.000, negative"), "{note}");
    assert!(note.contains("inside out"), "{note}");
    // The base is mirrored through the centre: a point at the back of the head ends up in front.
    let base = inbetween::blend_shapes::face().mesh.positions;
    let back = (0..base.len())
        .min_by(|&a, &b| base[a].z.total_cmp(&base[b].z))
        .unwrap();
    assert!(base[back].z < -0.8 && f.full.positions[back].z > 0.8);
    // The page's way there (lesson text): both heads, base weight 0 by hand, smile at −0.5
    // (the slider's least) and the other weights 0.
    f.set_show("both").unwrap();
    f.set_weight(0, -0.5).unwrap();
    for k in 1..4 {
        f.set_weight(k, 0.0).unwrap();
    }
    let note = f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    assert!(note.contains("= -0.500, negative"), "{note}");
    assert!(note.contains("inside out"), "{note}");
    // The weights read with three decimals, like the totals, however small (no "8.335e-4")
    // and with no "-0.000".
    f.set_weight(0, 0.0008335).unwrap();
    f.set_weight(1, -0.0001).unwrap();
    let note = f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    assert!(
        note.contains("Weights: smile 0.001, jaw open 0.000, brows up 0.000, puff cheeks 0.000."),
        "{note}"
    );
    assert!(note.contains("the weights sum to 0.001"), "{note}");
}

#[test]
fn the_delta_arrows_run_from_the_base_to_the_blend() {
    let mut f = FaceFigure::new();
    f.set_animate(false);
    f.set_show("differential").unwrap();
    let count = |f: &mut FaceFigure| {
        let mut frame = Frame::default();
        f.draw(&mut frame, IDS, 0.0).unwrap();
        frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CONE)
            .count()
    };
    let arrows = f.arrow_vertices().len();
    assert!((40..400).contains(&arrows), "{arrows} arrows");
    // At the defaults every sampled vertex that moves more than the arrow's smallest length
    // carries a cone; with every weight 0 nothing moves and no arrow is drawn.
    assert!(count(&mut f) > arrows / 2);
    for k in 0..4 {
        f.set_weight(k, 0.0).unwrap();
    }
    assert_eq!(count(&mut f), 0);
    f.set_weight(1, 1.0).unwrap();
    let jaw = count(&mut f);
    assert!(jaw > 5);
    f.set_show_deltas(false);
    assert_eq!(count(&mut f), 0);
}

/// The face's features move with their targets: the jaw opens the mouth (the two dark rings of
/// the opening part by about 20 cm in the middle), the smile lifts the corners above the middle.
#[test]
fn each_target_moves_its_painted_feature() {
    let face = inbetween::blend_shapes::face();
    let mouth: Vec<usize> = (0..face.mesh.positions.len())
        .filter(|&v| face.colors[v].x < 0.2 && face.mesh.positions[v].y < 0.0)
        .collect();
    assert!(mouth.len() >= 10, "{} mouth vertices", mouth.len());
    let middle = |t: &[Vec3], v: usize| t[v] - face.mesh.positions[v];
    // Jaw open: the lower dark ring drops, the upper stays.
    let (mut upper, mut lower) = (0.0f32, 0.0f32);
    for &v in &mouth {
        let p = face.mesh.positions[v];
        if p.x.abs() < 0.05 {
            let dy = middle(&face.targets[1], v).y;
            if p.y > -0.4495 {
                upper = upper.min(dy)
            } else {
                lower = lower.min(dy)
            }
        }
    }
    assert!(
        upper > -0.01 && lower < -0.2,
        "upper {upper}, lower {lower}"
    );
    // Smile: the corners rise more than the middle.
    let rise = |x_lo: f32, x_hi: f32| {
        mouth
            .iter()
            .filter(|&&v| (x_lo..x_hi).contains(&face.mesh.positions[v].x.abs()))
            .map(|&v| middle(&face.targets[0], v).y)
            .fold(0.0, f32::max)
    };
    assert!(rise(0.18, 0.25) > 0.1 && rise(0.0, 0.03) < 0.01);
}

/// A student's differential_vertex that is the full form without the base (Σ wₖ tₖ): right
/// when the weights sum to 1, wrong elsewhere. The probes catch it even where the sliders sum to 1.
fn full_form_runner(name: &str, args: &[f32]) -> Result<Vec<f32>, inbetween::figures::Failure> {
    assert_eq!(name, "differential_vertex");
    // base (3), targets (count, then 3 each), weights (count, then each).
    let n = args[3] as usize;
    let targets = &args[4..4 + 3 * n];
    let weights = &args[5 + 3 * n..];
    let mut p = Vec3::ZERO;
    for k in 0..n {
        p += weights[k] * Vec3::from_slice(&targets[3 * k..3 * k + 3]);
    }
    Ok(p.to_array().to_vec())
}

#[test]
fn use_my_exercise_checks_probe_weights_beyond_the_sliders() {
    let mut f = FaceFigure::new();
    f.set_runner(full_form_runner);
    f.set_use_exercise(true);
    f.set_animate(false);
    // Smile 1 alone: weights sum to 1, so at the sliders the wrong answer matches.
    for (k, w) in [1.0, 0.0, 0.0, 0.0].into_iter().enumerate() {
        f.set_weight(k, w).unwrap();
    }
    let note = f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    assert!(note.contains("matches the reference at all"), "{note}");
    assert!(
        note.contains(&format!(
            "it differs for {0} of the {0} probe weights: all weights 0, weights summing to 0.5,",
            PROBES.len()
        )),
        "{note}"
    );
    assert!(
        note.contains("with all weights 0: yours (0.000, 0.000, 0.000), reference ("),
        "{note}"
    );
    // At the defaults (sum 2.7) it differs on the head itself, and the head shows its vertices.
    for (k, w) in DEFAULT_WEIGHTS.into_iter().enumerate() {
        f.set_weight(k, w).unwrap();
    }
    let note = f.draw(&mut Frame::default(), IDS, 0.0).unwrap();
    assert!(note.contains("differs at vertex"), "{note}");
    assert!(
        largest_gap(&f) < 1e-4,
        "the full form's total is 2.7 as is the student's"
    );
}

const HEADS: [MeshId; 5] = [MeshId(3), MeshId(4), MeshId(5), MeshId(6), MeshId(7)];

#[test]
fn the_targets_figure_shows_the_base_and_each_target_as_sculpted() {
    let mut f = TargetsFigure::new();
    let face = inbetween::blend_shapes::face();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, &HEADS).unwrap();
    // Five heads, base first, in a row along x, each at its own place.
    let h: Vec<(MeshId, Vec3)> = frame
        .meshes
        .iter()
        .filter(|m| HEADS.contains(&m.mesh))
        .map(|m| (m.mesh, m.model.w_axis.truncate()))
        .collect();
    assert_eq!(h.iter().map(|x| x.0).collect::<Vec<_>>(), HEADS.to_vec());
    for (i, (_, at)) in h.iter().enumerate() {
        assert!(at.distance(f.head_position(i)) < 1e-6);
    }
    // At weight 1 the base head is b₀ and head k is target k, vertex for vertex.
    for (a, b) in f.heads[0].positions.iter().zip(&face.mesh.positions) {
        assert!(a.distance(*b) < 1e-6);
    }
    for k in 0..4 {
        for (a, b) in f.heads[k + 1].positions.iter().zip(&face.targets[k]) {
            assert!(a.distance(*b) < 1e-5, "target {k}: {a} vs {b}");
        }
    }
    let labels: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(
        labels,
        [
            "b₀ base",
            "b₁ smile",
            "b₂ jaw open",
            "b₃ brows up",
            "b₄ puff cheeks"
        ]
    );
    assert!(
        note.starts_with("Each target alone at weight 1.000"),
        "{note}"
    );
    // Every head stays in the declared view.
    for i in 0..5 {
        let c = f.head_position(i);
        let (lo, hi) = frame.keep_in_view.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        assert!(c.cmpge(lo).all() && c.cmple(hi).all());
    }
    // The wrong number of meshes is refused.
    assert!(f
        .draw(&mut Frame::default(), &HEADS[..2])
        .unwrap_err()
        .contains("meshes"));
}

/// The page says what each target moves, and by how much: the smile's corners by about 17 cm,
/// the jaw by 25, the brows by 12, the cheeks by 16, each target fewer than one vertex in ten.
#[test]
fn each_target_moves_a_few_vertices_by_what_the_page_says() {
    let mut f = TargetsFigure::new();
    let n = inbetween::blend_shapes::face().mesh.positions.len();
    let expected_cm = [17.0, 25.0, 12.0, 16.0];
    for (k, cm) in expected_cm.into_iter().enumerate() {
        let (moved, largest) = f.target_reach(k);
        assert!(
            (100.0 * largest - cm).abs() < 0.5,
            "target {k}: {largest} m"
        );
        assert!(moved > 100 && moved * 10 < n, "target {k}: {moved} of {n}");
    }
    assert_eq!(
        f.target_reach(1).0,
        (0..4).map(|k| f.target_reach(k).0).max().unwrap()
    );
    // The Try this reads the jaw's longest offset in the note: 25.2 cm at weight 1.
    let note = f.draw(&mut Frame::default(), &HEADS).unwrap();
    assert!(
        note.contains(
            "jaw open: its delta moves 603 of the 6050 vertices, the farthest by 25.2 cm"
        ),
        "{note}"
    );
    // At half weight every offset halves, and the count stays: which vertices a target moves
    // is a property of its delta, not of the weight (a count of offsets above a threshold at
    // the weight would drop from 603 to fewer as the weight falls).
    let counts: Vec<usize> = (0..4).map(|k| f.target_reach(k).0).collect();
    f.set_weight(0.5).unwrap();
    let (moved, half) = f.target_reach(1);
    assert!((100.0 * half - 12.6).abs() < 0.1, "{half}");
    for w in [0.5, 0.01, 1.5] {
        f.set_weight(w).unwrap();
        assert_eq!(
            (0..4).map(|k| f.target_reach(k).0).collect::<Vec<_>>(),
            counts,
            "weight {w}"
        );
    }
    f.set_weight(0.5).unwrap();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, &HEADS).unwrap();
    let jaw = note
        .split("; ")
        .find(|p| p.starts_with("jaw open"))
        .unwrap();
    assert!(
        jaw == format!("jaw open: its delta moves {moved} of the 6050 vertices, the farthest by 12.6 cm at this weight"),
        "{note}"
    );
    // The head at half weight lies halfway between the base and the target.
    let face = inbetween::blend_shapes::face();
    for ((a, b), t) in f.heads[2]
        .positions
        .iter()
        .zip(&face.mesh.positions)
        .zip(&face.targets[1])
    {
        assert!(a.distance(b.lerp(*t, 0.5)) < 1e-5);
    }
}

#[test]
fn the_targets_figure_validates_and_draws_its_arrows_on_request() {
    let mut f = TargetsFigure::new();
    assert!(f.set_weight(f32::NAN).unwrap_err().contains("weight"));
    assert!(f.set_weight(2.0).unwrap_err().contains("weight"));
    assert!(f.set_weight(-0.1).unwrap_err().contains("weight"));
    assert_eq!(f.weight(), 1.0, "a rejected weight changes nothing");
    let cones = |f: &mut TargetsFigure| {
        let mut frame = Frame::default();
        f.draw(&mut frame, &HEADS).unwrap();
        frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CONE)
            .count()
    };
    let with = cones(&mut f);
    assert!(with >= 30, "{with} arrows");
    // The shafts are drawn over the skin: a target that moves the skin outwards (the jaw, the
    // cheeks) would otherwise hide where each arrow starts, and it would read as a dot.
    let mut frame = Frame::default();
    f.draw(&mut frame, &HEADS).unwrap();
    let blue = inbetween::draw::palette::BLUE;
    let shafts: Vec<_> = frame
        .strokes
        .iter()
        .filter(|s| glam::Vec3::from_slice(&s.color[..3]).abs_diff_eq(blue, 1e-3))
        .collect();
    assert!(shafts.len() >= with, "{} shafts", shafts.len());
    assert!(shafts
        .iter()
        .all(|s| s.depth_bias == inbetween::draw::ON_TOP));
    // Drawn again at the same weight: nothing to upload.
    for head in &mut f.heads {
        head.take_dirty();
    }
    assert_eq!(cones(&mut f), with);
    assert!(f.heads.iter_mut().all(|h| !h.take_dirty()));
    f.set_show_deltas(false);
    assert_eq!(cones(&mut f), 0);
    // A new weight rewrites the target heads.
    f.set_weight(0.25).unwrap();
    cones(&mut f);
    assert!(f.heads.iter_mut().all(|h| h.take_dirty()));
}

/// Side by side, no head reaches into its neighbour, even puffed at the largest weight.
#[test]
fn the_target_heads_never_touch() {
    let mut f = TargetsFigure::new();
    f.set_weight(1.5).unwrap();
    f.draw(&mut Frame::default(), &HEADS).unwrap();
    for head in &f.heads {
        let half_width = head.positions.iter().map(|p| p.x.abs()).fold(0.0, f32::max);
        assert!(2.0 * half_width < TARGETS_SPACING, "{half_width}");
    }
}

/// From any orbit (the page's, the page test's drag, from the side and from above) the five
/// heads stand apart on the canvas, at the largest weight: their rows run across the last
/// frame's view, so no head hides behind another.
#[test]
fn the_target_heads_stand_apart_from_any_orbit() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let size = glam::Vec2::new(650.0, 420.0);
    for [yaw, pitch] in [
        [0.2, 0.05],
        [0.2 - 1.04, 0.05 + 0.336],
        [1.6, 0.0],
        [0.0, 1.4],
    ] {
        let mut f = TargetsFigure::new();
        f.set_weight(1.5).unwrap();
        let mut camera = OrbitCamera::from_view([0.0, 0.0, 0.0, 9.0, yaw, pitch]);
        f.set_view(camera);
        let mut frame = Frame::default();
        f.draw(&mut frame, &HEADS).unwrap();
        assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
        // Told the fitted camera, the figure draws the same frame again and again (a paused
        // page draws nothing new): the rows follow the camera's yaw and pitch, not its target.
        let mut prints = Vec::new();
        for _ in 0..3 {
            f.set_view(camera);
            let mut again = Frame::default();
            f.draw(&mut again, &HEADS).unwrap();
            assert!(camera.fit(&again.fit_points(), size, FIT_PAD_PX));
            prints.push(again.fingerprint());
        }
        assert!(prints.windows(2).all(|p| p[0] == p[1]), "{prints:?}");
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let boxes: Vec<(glam::Vec2, glam::Vec2)> = (0..5)
            .map(|i| {
                let at = f.head_position(i);
                f.heads[i]
                    .positions
                    .iter()
                    .map(|p| project_to_canvas(view_proj, size, *p + at).unwrap())
                    .fold((size, glam::Vec2::ZERO), |(lo, hi), p| {
                        (lo.min(p), hi.max(p))
                    })
            })
            .collect();
        for (i, a) in boxes.iter().enumerate() {
            assert!(a.0.cmpge(glam::Vec2::ZERO).all() && a.1.cmple(size).all());
            for (j, b) in boxes.iter().enumerate().skip(i + 1) {
                let apart = a.1.x < b.0.x || b.1.x < a.0.x || a.1.y < b.0.y || b.1.y < a.0.y;
                assert!(
                    apart,
                    "yaw {yaw}, pitch {pitch}: heads {i} {a:?} and {j} {b:?} overlap"
                );
            }
        }
    }
}

/// The face figure declares its heads at their largest (with their titles), so the camera fits
/// them at every canvas size: on the canvases the page gives it at 800 × 600 and 1600 × 1000,
/// from the page's orbit, each head lies inside the canvas over the whole loop and the two heads
/// fill most of the canvas's height (the full head at its largest, more than half of it).
#[test]
fn the_face_figure_fits_its_heads_large_at_both_page_sizes() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let mut f = FaceFigure::new();
    let s_max = f.largest_full_scale();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 0.0).unwrap();
    let points = frame.fit_points();
    for size in [glam::Vec2::new(760.0, 420.0), glam::Vec2::new(650.0, 420.0)] {
        let [x, y, z, distance] = f.view_fit();
        let mut camera = OrbitCamera::from_view([x, y, z, distance, 0.15, 0.1]);
        assert!(camera.fit(&points, size, FIT_PAD_PX));
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        for i in 0..16 {
            let mut frame = Frame::default();
            f.draw(&mut frame, IDS, LOOP_SECONDS * i as f32 / 16.0)
                .unwrap();
            let mut now = OrbitCamera::from_view([x, y, z, distance, 0.15, 0.1]);
            now.fit(&frame.fit_points(), size, FIT_PAD_PX);
            assert_eq!(now, camera, "the camera holds still over the loop");
        }
        let (_, right) = f.head_positions();
        let r = HEAD_RADIUS_FOR_TEST * s_max;
        let top = project_to_canvas(view_proj, size, right.unwrap() + Vec3::Y * r).unwrap();
        let bottom = project_to_canvas(view_proj, size, right.unwrap() - Vec3::Y * r).unwrap();
        let share = (bottom.y - top.y) / size.y;
        assert!(
            share > 0.5,
            "on {size} the full head at its largest takes {share} of the height"
        );
    }
}

/// At the page's camera (lessons/10-blend-shapes/lesson.js: distance 9, yaw 0.2, pitch 0.05,
/// fitted to the heads) on the canvases the page gives Figure 1 at 800 × 600 and 1600 × 1000,
/// each target's delta arrows read as arrows: at weight 1 the median one is at least 9 px long
/// on the canvas, each is `TARGET_ARROW_SCALE` times its vertex's offset `w dₖ`, and none runs
/// through a head's name (at its place right of its anchor, 7.5 px a character, 16 px tall),
/// up to the largest weight.
#[test]
fn the_target_arrows_read_at_the_page_camera() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::figures::blend_shapes::TARGET_ARROW_SCALE;
    let face = inbetween::blend_shapes::face();
    let blue = inbetween::draw::palette::BLUE;
    for (size, w) in crate::label_clearance::CANVASES
        .into_iter()
        .flat_map(|size| [(size, 1.0), (size, 1.5)])
    {
        let mut f = TargetsFigure::new();
        f.set_weight(w).unwrap();
        let page = |frame: &Frame| {
            let mut camera = OrbitCamera::from_view([0.0, 0.0, 0.0, 9.0, 0.2, 0.05]);
            assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
            camera
        };
        // As the page: the figure lays its heads out for the view of the frame before.
        let mut frame = Frame::default();
        f.draw(&mut frame, &HEADS).unwrap();
        f.set_view(page(&frame));
        let mut frame = Frame::default();
        f.draw(&mut frame, &HEADS).unwrap();
        let camera = page(&frame);
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
        // Each on-top arrow is its shaft and three strokes from its cone's rim to its tip.
        let blue: Vec<_> = frame
            .strokes
            .iter()
            .filter(|s| Vec3::from_slice(&s.color[..3]).abs_diff_eq(blue, 1e-3))
            .collect();
        assert_eq!(blue.len() % 4, 0);
        let arrows: Vec<(Vec3, Vec3)> = blue
            .chunks(4)
            .map(|c| (Vec3::from(c[0].a), Vec3::from(c[1].b)))
            .collect();
        for k in 1..5 {
            let centre = f.head_position(k);
            let mut lengths = Vec::new();
            for &(from, to) in arrows.iter().filter(|a| a.0.distance(centre) < 1.2) {
                // The arrow's vertex: the base's nearest to where it starts (3 cm off it).
                let v = (0..face.mesh.positions.len())
                    .min_by(|&a, &b| {
                        let d = |i: usize| (face.mesh.positions[i] + centre).distance(from);
                        d(a).total_cmp(&d(b))
                    })
                    .unwrap();
                let offset = face.targets[k - 1][v] - face.mesh.positions[v];
                assert!(
                    (to - from).distance(TARGET_ARROW_SCALE * w * offset) < 1e-4,
                    "target {k}, vertex {v}: arrow {} for offset {offset}",
                    to - from
                );
                lengths.push(at(from).distance(at(to)));
            }
            assert!(lengths.len() >= 4, "target {k}: {} arrows", lengths.len());
            lengths.sort_by(f32::total_cmp);
            let median = lengths[lengths.len() / 2];
            assert!(median >= 9.0 * w, "on {size}, w {w}, target {k}: median {median} px");
        }
        for label in &frame.labels {
            let anchor = at(label.anchor);
            let w = 7.5 * label.text.chars().count() as f32;
            let (lo, hi) = (
                anchor + glam::Vec2::new(0.0, -8.0),
                anchor + glam::Vec2::new(4.0 + w, 8.0),
            );
            for &(from, to) in &arrows {
                let (a, b) = (at(from), at(to));
                for i in 0..=16 {
                    let p = a.lerp(b, i as f32 / 16.0);
                    assert!(
                        !(p.cmpgt(lo).all() && p.cmplt(hi).all()),
                        "on {size}: an arrow at {p} runs through {:?}",
                        label.text
                    );
                }
            }
        }
    }
}

/// The page's Try this, step by step, at the page's canvas sizes (800 × 600 and 1600 × 1000):
/// the camera the page fits to the declared heads is the same at every step and every time of
/// the loop, so the left (differential) head keeps its place and size on the canvas while the
/// right one grows to 1.5 and breathes between 0.65 and 1.35. Past FRAMED_SCALE (all four
/// weights at 1.5) the view does move back.
#[test]
fn the_left_head_keeps_its_size_on_screen_through_the_try_this() {
    use inbetween::camera::{OrbitCamera, FIT_PAD_PX};
    let camera_for = |f: &mut FaceFigure, t: f32, size: glam::Vec2| {
        let mut frame = Frame::default();
        f.draw(&mut frame, IDS, t).unwrap();
        let mut camera = OrbitCamera::from_view({
            let [x, y, z, d] = f.view_fit();
            [x, y, z, d, 0.15, 0.1]
        });
        assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
        (camera, heads(&frame)[0].1)
    };
    for size in [glam::Vec2::new(760.0, 420.0), glam::Vec2::new(650.0, 420.0)] {
        let mut f = FaceFigure::new();
        let (first, left) = camera_for(&mut f, 0.0, size);
        let check = |f: &mut FaceFigure, step: &str| {
            for i in 0..8 {
                let (camera, at) = camera_for(f, LOOP_SECONDS * i as f32 / 8.0, size);
                assert_eq!(camera, first, "on {size}, {step}: the camera moved");
                assert_eq!(at, left, "on {size}, {step}: the left head moved");
            }
        };
        check(&mut f, "the defaults");
        f.set_animate(false);
        for (k, w) in [0.5, 0.0, 0.0, 0.0].into_iter().enumerate() {
            f.set_weight(k, w).unwrap();
        }
        f.set_base_weight(0.5).unwrap();
        check(&mut f, "smile 0.5, base 0.5");
        f.set_weight(2, 0.5).unwrap();
        assert_eq!(f.largest_full_scale(), 1.5);
        check(&mut f, "brows 0.5 too: total 1.5");
        f.set_animate(true);
        check(&mut f, "animated");
        f.set_weight(2, 0.0).unwrap();
        f.set_weight(1, 0.5).unwrap();
        check(&mut f, "jaw 0.5 instead of brows");
        f.set_base_auto(true);
        check(&mut f, "automatic");
        f.set_base_auto(false);
        f.set_animate(false);
        for k in 0..4 {
            f.set_weight(k, 1.5).unwrap();
        }
        let (camera, _) = camera_for(&mut f, 0.0, size);
        assert!(camera.distance > first.distance, "on {size}: total 7 does not move back");
    }
}

/// Figure 2's delta arrows are `FACE_ARROW_SCALE` times the offset Σ wₖ dₖ, on the sampled
/// vertices that move at least `FACE_ARROW_MIN`, so at the Try this's "brows up 0.5 too" (the
/// brows rise 6 cm) the brows' arrows read at the page's camera: each at least 12 px long on
/// the 650 × 420 canvas (1600 × 1000 page).
#[test]
fn the_face_figures_arrows_are_the_scaled_offset_and_read_at_the_try_this() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::figures::blend_shapes::{FACE_ARROW_MIN, FACE_ARROW_SCALE};
    let size = glam::Vec2::new(650.0, 420.0);
    let mut f = FaceFigure::new();
    f.set_animate(false);
    for (k, w) in [0.5, 0.0, 0.5, 0.0].into_iter().enumerate() {
        f.set_weight(k, w).unwrap();
    }
    f.set_base_weight(0.5).unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 0.0).unwrap();
    let [x, y, z, d] = f.view_fit();
    let mut camera = OrbitCamera::from_view([x, y, z, d, 0.15, 0.1]);
    assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let shafts = arrow_shafts(&frame);
    let base = inbetween::blend_shapes::face().mesh.positions;
    let left = heads(&frame)[0].1;
    let (mut brows, mut drawn) = (0, 0);
    for &v in f.arrow_vertices() {
        let offset = f.differential.positions[v] - base[v];
        // At t = 0 the heads face the camera (no swing), so the head's frame is a translation.
        let from = left + base[v] + 0.03 * inbetween::blend_shapes::face().mesh.normals[v];
        let nearest = shafts
            .iter()
            .min_by(|p, q| p.0.distance(from).total_cmp(&q.0.distance(from)))
            .filter(|s| s.0.distance(from) < 1e-4);
        if offset.length() < FACE_ARROW_MIN {
            assert!(nearest.is_none(), "vertex {v} moves {offset} but has an arrow");
            continue;
        }
        let &(a, b) = nearest.unwrap_or_else(|| panic!("vertex {v}: no arrow starts at {from}"));
        drawn += 1;
        assert!(
            (b - a).distance(FACE_ARROW_SCALE * offset) < 1e-4,
            "vertex {v}: arrow {} for offset {offset}",
            b - a
        );
        // The brows' vertices: moved up by at least 5 cm.
        if offset.y > 0.05 {
            brows += 1;
            let px = project_to_canvas(view_proj, size, a)
                .unwrap()
                .distance(project_to_canvas(view_proj, size, b).unwrap());
            assert!(px >= 12.0, "vertex {v}: the brow's arrow is {px} px");
        }
    }
    assert_eq!(drawn, shafts.len(), "an arrow without its vertex");
    assert!(brows >= 4, "{brows} brow arrows");
    // The caption gives the scale and the smallest offset drawn.
    let page = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/lessons/10-blend-shapes/index.html"
    ))
    .unwrap();
    let page = page.split_whitespace().collect::<Vec<_>>().join(" ");
    assert_eq!(FACE_ARROW_SCALE, 5.0);
    assert!(page.contains("(drawn five times as long, on the vertices that move at least 2.5 cm;"));
    assert_eq!(FACE_ARROW_MIN, 0.025);
}

/// Each on-top arrow of `frame`: its shaft's start and its tip (an arrow is its shaft and three
/// strokes from its cone's rim to its tip).
fn arrow_shafts(frame: &Frame) -> Vec<(Vec3, Vec3)> {
    let blue = inbetween::draw::palette::BLUE;
    frame
        .strokes
        .iter()
        .filter(|s| Vec3::from_slice(&s.color[..3]).abs_diff_eq(blue, 1e-3))
        .collect::<Vec<_>>()
        .chunks(4)
        .map(|c| (Vec3::from(c[0].a), Vec3::from(c[1].b)))
        .collect()
}

/// At the defaults (the weights animated, the view making room for the full head at 1.7 times
/// its size, so the differential head is about 120 px tall on the 650 × 420 canvas), the delta
/// arrows read as arrows over the whole loop at the page's camera: on the canvases the page
/// gives Figure 2 at 1600 × 1000 and 800 × 600, at each of 16 times (12 or more of which draw
/// arrows), every drawn arrow is at least 6 px long on the canvas, three quarters of them at
/// least 7.5 px and half at least 9.5 px.
#[test]
fn the_face_figures_arrows_read_at_the_defaults_over_the_loop() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    for size in [glam::Vec2::new(650.0, 420.0), glam::Vec2::new(760.0, 420.0)] {
        let mut f = FaceFigure::new();
        let mut frame = Frame::default();
        f.draw(&mut frame, IDS, 0.0).unwrap();
        let [x, y, z, d] = f.view_fit();
        let mut camera = OrbitCamera::from_view([x, y, z, d, 0.15, 0.1]);
        assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let px = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
        let mut times = 0;
        for i in 0..16 {
            let t = LOOP_SECONDS * i as f32 / 16.0;
            let mut frame = Frame::default();
            f.draw(&mut frame, IDS, t).unwrap();
            let mut lengths: Vec<f32> = arrow_shafts(&frame)
                .into_iter()
                .map(|(a, b)| px(a).distance(px(b)))
                .collect();
            if lengths.is_empty() {
                continue;
            }
            times += 1;
            lengths.sort_by(f32::total_cmp);
            let (quarter, median) = (lengths[lengths.len() / 4], lengths[lengths.len() / 2]);
            assert!(
                lengths[0] >= 6.0 && quarter >= 7.5 && median >= 9.5,
                "on {size} at {t} s: of the {} arrows the shortest is {} px, a quarter are under \
                 {quarter} px, half under {median} px",
                lengths.len(),
                lengths[0]
            );
        }
        assert!(times >= 12, "on {size}: arrows at {times} of 16 times");
    }
}

/// Past FRAMED_SCALE the camera backs away to fit the full head, and the differential head
/// shrinks on screen: the note says why. At the defaults (a total up to 1.67) it stays silent.
#[test]
fn the_note_says_when_the_view_zooms_out_for_a_large_total() {
    let mut f = FaceFigure::new();
    let note = f.draw(&mut Frame::default(), IDS, 1.3).unwrap();
    assert!(f.framed_scale() == FRAMED_SCALE && !note.contains("zoomed out"), "{note}");
    f.set_animate(false);
    for k in 0..4 {
        f.set_weight(k, 1.5).unwrap();
    }
    f.set_base_weight(1.0).unwrap();
    let note = f.draw(&mut Frame::default(), IDS, 1.3).unwrap();
    assert!(
        note.contains("zoomed out to fit the full head at its largest (7.000 times the base)"),
        "{note}"
    );
    // The full head alone: nothing else shrinks.
    f.set_show("full").unwrap();
    let note = f.draw(&mut Frame::default(), IDS, 1.3).unwrap();
    assert!(!note.contains("zoomed out"), "{note}");
}

#[test]
fn side_by_side_the_arrows_hide_once_the_left_head_is_drawn_under_half_its_size() {
    // Base weight 1 by hand, every target at w, still: the full total is 1 + 4w. The caption's
    // 3.4: past it the view frames the heads from over twice the start's distance (the left
    // head at under half its size), and the left head's arrows, drawn in proportion to the
    // offsets, would cover it, so none is drawn; at 3.3 they are.
    use inbetween::figures::blend_shapes::{ARROWS_HIDDEN_ABOVE, FRAMED_SCALE};
    assert!((ARROWS_HIDDEN_ABOVE - 3.4).abs() < 1e-6);
    let start = FaceFigure::new().view_fit()[3];
    let drawn = |total: f32| {
        let mut f = FaceFigure::new();
        f.set_animate(false);
        f.set_base_weight(1.0).unwrap();
        for k in 0..4 {
            f.set_weight(k, 0.25 * (total - 1.0)).unwrap();
        }
        let mut frame = Frame::default();
        let note = f.draw(&mut frame, IDS, 0.0).unwrap();
        let cones = frame.meshes.iter().filter(|m| m.mesh == MeshId::CONE).count();
        (cones, note, f.view_fit()[3] / start)
    };
    let (cones, note, zoom) = drawn(3.3);
    assert!(cones > 10, "{cones} arrows at 3.3");
    assert!(zoom > 1.0 && zoom < 2.0, "{zoom}");
    assert!(!note.contains("arrows"), "{note}");
    for total in [3.5, 7.0] {
        let (cones, note, zoom) = drawn(total);
        assert_eq!(cones, 0, "arrows at {total}");
        assert!(zoom > 2.0, "{total}: {zoom}");
        assert!(note.contains("too small for its arrows (hidden: they would cover it)"), "{note}");
    }
    assert!(FRAMED_SCALE < 3.3);
    // Shown alone, the differential head is not zoomed out and keeps its arrows.
    let mut f = FaceFigure::new();
    f.set_animate(false);
    f.set_base_weight(1.0).unwrap();
    for k in 0..4 {
        f.set_weight(k, 1.5).unwrap();
    }
    f.set_show("differential").unwrap();
    let mut frame = Frame::default();
    f.draw(&mut frame, IDS, 0.0).unwrap();
    assert!(frame.meshes.iter().any(|m| m.mesh == MeshId::CONE));
}
