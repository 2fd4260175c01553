//! Native tests of lesson 12's figures (src/figures/boids.rs).

use glam::Vec3;
use inbetween::boids;
use inbetween::draw::Frame;
use inbetween::exercises::run::{direct, Failure, Flat};
use inbetween::figures::boids::*;

fn reference(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut rest = args;
    let mut out = Vec::new();
    match name {
        "three_rules" => {
            let p = Vec3::take(&mut rest).unwrap();
            let v = Vec3::take(&mut rest).unwrap();
            let ps = Vec::<Vec3>::take(&mut rest).unwrap();
            let vs = Vec::<Vec3>::take(&mut rest).unwrap();
            boids::three_rules(p, v, &ps, &vs).to_vec().put(&mut out)
        }
        "cell_index" => {
            let p = Vec3::take(&mut rest).unwrap();
            let o = Vec3::take(&mut rest).unwrap();
            let s = f32::take(&mut rest).unwrap();
            let d = <[f32; 3]>::take(&mut rest).unwrap();
            boids::cell_index(p, o, s, d.map(|x| x as u32)).put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

/// Typical mistakes: separation towards the neighbours; x and z swapped in the cell index.
fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut out = reference(name, args)?;
    match name {
        "three_rules" => {
            for x in &mut out[7..10] {
                *x = -*x;
            }
        }
        "cell_index" => out[0] += 1.0,
        _ => {}
    }
    Ok(out)
}

fn stub(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::NotDone)
}

#[test]
fn the_flock_draws_every_boid_and_the_highlighted_ones_neighbours() {
    let mut scene = FlockFigure::new();
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame);
    assert_eq!(frame.points.len(), 300);
    assert!(note.contains("300 boids, grid search"), "{note}");
    // The steering cap with its unit (not a bare "the force is at most 6.000").
    assert!(note.contains("capped at 6.000 m/s²"), "{note}");
    scene.set_leader(true);
    scene.set_predator(true);
    scene.advance_to(0.5).unwrap();
    let mut frame = Frame::default();
    scene.draw(&mut frame);
    assert!(frame.labels.iter().any(|l| l.text == "leader"));
    assert!(frame.labels.iter().any(|l| l.text == "predator"));
}

#[test]
fn the_steering_arrow_is_long_enough_to_see() {
    // The purple arrow from the orange boid is STEER_ARROW_M_PER_MS2 metres per m/s² (at most
    // STEER_ARROW_MAX_M): at the defaults the boid steers at a few tenths of a m/s², which a
    // quarter-metre scale would draw a few centimetres long, hidden under the neighbour lines.
    let mut scene = FlockFigure::new();
    for t in [0.5f32, 1.0, 2.0] {
        scene.advance_to(t).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        let h = scene.highlighted();
        let steer = scene.flock().steering_of(scene.params(), h);
        let from = scene.flock().positions[h];
        let expected = (STEER_ARROW_M_PER_MS2 * steer.length()).min(STEER_ARROW_MAX_M);
        // The shaft ends where the head (a cone mesh) begins: the tip is the far end of the cone.
        let shaft: Vec<_> = frame
            .segments_of(inbetween::draw::palette::PURPLE)
            .collect();
        assert_eq!(shaft.len(), 1, "one purple shaft");
        let (a, b) = shaft[0];
        assert!((a - from).length() < 1e-5);
        let head = 0.08f32.min(0.4 * expected);
        assert!(
            ((b - a).length() + head - expected).abs() < 1e-3,
            "{} vs {expected}",
            (b - a).length() + head
        );
        assert!(
            expected > 0.2 || steer.length() < 0.2,
            "at {t} s: {} m/s²",
            steer.length()
        );
    }
}

#[test]
fn the_flock_rejects_bad_input() {
    let mut scene = FlockFigure::new();
    assert!(scene
        .set_count(PAGE_MAX_BOIDS as f32 + 1.0)
        .unwrap_err()
        .contains("count"));
    assert!(scene.set_count(f32::NAN).is_err());
    assert!(scene
        .set_rule("cohesion", f32::NAN, 1.0)
        .unwrap_err()
        .contains("cohesion weight"));
    assert!(scene
        .set_rule("gravity", 1.0, 1.0)
        .unwrap_err()
        .contains("gravity"));
    assert!(scene.set_fov_deg(361.0).is_err());
    assert!(scene.set_search("octree").is_err());
    assert!(scene.set_law("cubic").is_err());
    assert!(scene.timing_step("grid").is_err(), "prepare first");
    assert!(scene
        .prepare_timing(PAGE_MAX_TIMED_BOIDS as f32 + 1.0)
        .is_err());
    scene.prepare_timing(500.0).unwrap();
    scene.timing_step("naive").unwrap();
    scene.timing_step("grid").unwrap();
}

#[test]
fn grid_and_naive_flocks_stay_together() {
    let mut a = FlockFigure::new();
    let mut b = FlockFigure::new();
    b.set_search("naive").unwrap();
    for k in 1..=20 {
        assert_eq!(a.advance_to(k as f32 / 60.0).unwrap(), 1);
        assert_eq!(b.advance_to(k as f32 / 60.0).unwrap(), 1);
    }
    assert_eq!(
        a.advance_to(20.0 / 60.0).unwrap(),
        0,
        "the same time takes no step"
    );
    let d = a
        .flock()
        .positions
        .iter()
        .zip(&b.flock().positions)
        .map(|(p, q)| (*p - *q).length())
        .fold(0.0, f32::max);
    assert!(d < 1e-3, "{d}");
}

#[test]
fn a_jump_in_time_restarts_the_flock_without_replaying() {
    let mut scene = FlockFigure::new();
    let start = scene.flock().positions.clone();
    for k in 1..=5 {
        scene.advance_to(k as f32 / 60.0).unwrap();
    }
    assert_ne!(scene.flock().positions, start);
    assert_eq!(
        scene.advance_to(10.0).unwrap(),
        0,
        "a long jump takes no steps"
    );
    let at_10 = scene.flock().positions.clone();
    assert_ne!(at_10, start, "a fresh flock seeded by the time");
    assert_eq!(scene.advance_to(0.0).unwrap(), 0);
    assert_eq!(
        scene.flock().positions,
        start,
        "time 0 is the first flock again"
    );
    scene.advance_to(10.0).unwrap();
    assert_eq!(scene.flock().positions, at_10);
    assert!(scene.advance_to(f32::NAN).is_err());
}

#[test]
fn the_rules_figure_draws_three_arrows_and_names_the_cell() {
    let mut scene = RulesFigure::new();
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame);
    for name in ["cohesion", "alignment", "separation"] {
        assert!(frame.labels.iter().any(|l| l.text == name), "{name}");
    }
    assert!(note.contains("in cell"), "{note}");
    // At the start separation is over 6 long, drawn cut at 2 m: the note says so (and only of
    // separation), so that its arrow does not read as three times the cohesion.
    let cut = note.split("cut at 2 m: ").nth(1).unwrap_or_default();
    assert!(
        cut.starts_with("separation ") && !cut.contains("cohesion"),
        "{note}"
    );
    // A narrower field of view sees fewer neighbours.
    let (all, _) = scene.neighbours();
    scene.set_fov_deg(60.0).unwrap();
    let (ahead, _) = scene.neighbours();
    assert!(ahead.len() < all.len());
    assert!(scene.set_position(5.0, 0.0).is_err() && scene.set_radius(f32::NAN).is_err());
}

/// The radius circle tells the field of view from the blind sector: solid where the boid sees
/// (within half the field of view of its heading), dashed behind, and solid all round at 360°.
/// One full solid circle with the sector's two edges reads the same at 90° and at 270°.
#[test]
fn the_radius_circle_is_solid_over_the_field_of_view_and_dashed_behind() {
    use inbetween::draw::palette::PURPLE;
    let mut scene = RulesFigure::new();
    scene.set_position(0.4, -0.3).unwrap();
    scene.set_heading_deg(30.0).unwrap();
    scene.set_radius(1.2).unwrap();
    let boid = Vec3::new(0.4, 0.0, -0.3);
    let heading = Vec3::new(30f32.to_radians().cos(), 0.0, -30f32.to_radians().sin());
    for fov in [90.0f32, 270.0, 360.0] {
        scene.set_fov_deg(fov).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        let (mut solid, mut dashed) = (0, 0);
        let purple = frame
            .strokes
            .iter()
            .filter(|s| s.color[..3] == PURPLE.to_array());
        for s in purple {
            let (a, b) = (Vec3::from(s.a), Vec3::from(s.b));
            // The sector's edges start at the boid; the circle's pieces lie on the radius.
            let on_circle = |p: Vec3| ((p - boid).length() - 1.2).abs() < 1e-3;
            if !on_circle(a) || !on_circle(b) {
                continue;
            }
            let mid = (0.5 * (a + b) - boid).normalize();
            let angle = mid.angle_between(heading).to_degrees();
            if s.dash[3] > 0.0 {
                dashed += 1;
                assert!(angle > 0.5 * fov - 3.0, "fov {fov}: a dash {angle}° ahead");
            } else {
                solid += 1;
                assert!(angle < 0.5 * fov + 3.0, "fov {fov}: solid {angle}° behind");
            }
        }
        assert!(solid > 10, "fov {fov}: {solid} solid pieces");
        assert_eq!(dashed > 0, fov < 360.0, "fov {fov}: {dashed} dashes");
    }
}

#[test]
fn the_rules_figure_says_what_the_students_code_does() {
    let mut scene = RulesFigure::new();
    scene.set_use_exercise(true);
    for (runner, expect) in [
        (
            reference as fn(&str, &[f32]) -> _,
            "Your three_rules also matches at 3 probe inputs the figure does not show. Your \
             cell_index matches the reference at this boid.",
        ),
        (wrong, "Your three_rules differs at this boid"),
        (stub, "Not done yet: exercise 12.1"),
    ] {
        scene.set_runner(runner);
        let note = scene.draw(&mut Frame::default());
        assert!(note.contains(expect), "{expect}: {note}");
    }
    scene.set_runner(wrong);
    let note = scene.draw(&mut Frame::default());
    // An index, in whole numbers, with the reference's (i, j, k): the wrong runner adds 1.
    assert!(
        note.contains(
            "Your cell_index differs at this boid: yours 11, reference 10 (cell i = 2, j = 0, \
             k = 2 of 4 × 1 × 4)."
        ),
        "{note}"
    );
    // The wrong runner flips separation only: the note names it, gives both vectors, and says
    // the other two match.
    assert!(
        note.contains("Your three_rules differs at this boid in separation: separation yours (")
            && note.contains("(cohesion and alignment match.)"),
        "{note}"
    );
}

#[test]
fn the_flock_note_counts_neighbours_in_the_right_number() {
    // Narrow the view step by step: somewhere the orange boid sees exactly one neighbour, and
    // the note says "1 neighbour" (not "1 neighbours"); every count agrees with its noun.
    let mut scene = FlockFigure::new();
    let mut seen_one = false;
    for fov in (0..=360).rev().step_by(2) {
        scene.set_fov_deg(fov as f32).unwrap();
        let note = scene.draw(&mut Frame::default());
        let count: usize = note
            .split("sees ")
            .nth(1)
            .and_then(|r| r.split(' ').next())
            .and_then(|n| n.parse().ok())
            .unwrap();
        seen_one |= count == 1;
        let noun = if count == 1 {
            "neighbour"
        } else {
            "neighbours"
        };
        assert!(
            note.contains(&format!("sees {count} {noun} within")),
            "{note}"
        );
    }
    assert!(seen_one, "some field of view shows exactly one neighbour");
}

#[test]
fn the_rules_figures_labels_never_overlap() {
    // Labels are HTML over the canvas (www/style.css: 600 0.8rem, about 7.7 px a character and
    // 15 px high from 9 px above the anchor, 4.5 px right of it, or ending 4.5 px left of it for
    // a left label). At the page's camera and both canvas sizes (760 x 420 at 800 x 600, 650 x
    // 420 at 1600 x 1000), over the sliders' range, the three labels stay apart. At the arrows'
    // tips alone the short cohesion and alignment arrows put "alignment" on "cohesion" at the
    // defaults. The cell size sets how much the camera takes in (it fits the grid), so the
    // labels' sizes in metres.
    // The camera as the viewer places it: the page's direction, fitted to what the figure
    // declares (its grid) and its labels.
    let boxes = |frame: &Frame, view: [f32; 6], w: f32, h: f32| {
        use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
        let size = glam::Vec2::new(w, h);
        let mut camera = OrbitCamera::from_view(view);
        assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
        let view_proj = camera.projection(w / h) * camera.view();
        frame
            .labels
            .iter()
            .map(|l| {
                let s = project_to_canvas(view_proj, size, l.anchor).unwrap();
                let width = 7.7 * l.text.chars().count() as f32;
                let x0 = if l.left { s.x - 4.5 - width } else { s.x + 4.5 };
                (x0, s.y - 9.0, x0 + width, s.y + 6.0)
            })
            .collect::<Vec<_>>()
    };
    let mut checked = 0;
    for x in [-1.9f32, -1.15, 0.0, 0.8, 1.9] {
        for z in [-1.9f32, -1.15, 0.0, 0.8, 1.9] {
            for heading in (-4..=4).map(|k| 45.0 * k as f32) {
                for radius in [0.6f32, 1.2, 2.4, 3.0] {
                    for (fov, cell) in
                        [(70.0f32, 1.9f32), (270.0, 1.2), (360.0, 0.25), (270.0, 1.5)]
                    {
                        let mut scene = RulesFigure::new();
                        scene.set_cell_size(cell).unwrap();
                        scene.set_position(x, z).unwrap();
                        scene.set_heading_deg(heading).unwrap();
                        scene.set_radius(radius).unwrap();
                        scene.set_fov_deg(fov).unwrap();
                        let mut frame = Frame::default();
                        scene.draw(&mut frame);
                        let view = scene.view();
                        for (w, h) in crate::label_clearance::CANVASES.map(|s| (s.x, s.y)) {
                            let b = boxes(&frame, view, w, h);
                            for i in 0..b.len() {
                                for j in 0..i {
                                    let (p, q) = (b[i], b[j]);
                                    let apart =
                                        p.2 <= q.0 || q.2 <= p.0 || p.3 <= q.1 || q.3 <= p.1;
                                    assert!(
                                        apart,
                                        "x {x}, z {z}, heading {heading}, radius {radius}, fov {fov}, cell {cell}, {w} x {h}: {:?} and {:?} overlap: {p:?} {q:?}",
                                        frame.labels[i].text, frame.labels[j].text
                                    );
                                }
                            }
                            for r in &b {
                                assert!(
                                    r.0 > 0.0 && r.2 < w && r.1 > 0.0 && r.3 < h,
                                    "x {x}, z {z}, heading {heading}, radius {radius}, fov {fov}, cell {cell}, {w} x {h}: a label leaves the canvas: {r:?}"
                                );
                            }
                            checked += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(checked > 1000);
    // At the defaults all three are there and on the canvas.
    let scene = RulesFigure::new();
    let mut frame = Frame::default();
    scene.draw(&mut frame);
    assert_eq!(frame.labels.len(), 3);
    for (w, h) in crate::label_clearance::CANVASES.map(|s| (s.x, s.y)) {
        for r in boxes(&frame, scene.view(), w, h) {
            assert!(r.0 > 0.0 && r.2 < w && r.1 > 0.0 && r.3 < h, "{r:?}");
        }
    }
}

#[test]
fn the_order_plot_follows_the_flock_step_by_step() {
    // One sample per step since the flock started, [t, φ, mean speed / max speed], each the
    // figure's own polarisation and speed at that step; a jump in time, or a new count, starts
    // the plot again with the fresh flock. The flock has no plot of its motion otherwise.
    let mut scene = FlockFigure::new();
    let first = scene.plot_samples();
    assert_eq!(first.len(), 3, "the start: one sample");
    assert_eq!(first[0], 0.0);
    // Random headings: φ is of the order of 1/√N; every boid starts at half the top speed
    // clamped into the speed limits: the min speed, 1.2 of 1.8 m/s.
    assert!(first[1] < 0.2, "{first:?}");
    assert!((first[2] - 1.2 / 1.8).abs() < 1e-4, "{first:?}");
    for k in 1..=120 {
        scene.advance_to(k as f32 / 60.0).unwrap();
        let s = scene.plot_samples();
        assert_eq!(s.len(), 3 * (k + 1));
        let last = &s[s.len() - 3..];
        assert!((last[0] - k as f32 / 60.0).abs() < 1e-5);
        assert_eq!(last[1], scene.polarisation());
        assert_eq!(last[2], scene.speed_ratio());
        assert!((0.0..=1.0).contains(&last[1]) && (0.0..=1.0 + 1e-4).contains(&last[2]));
    }
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame);
    assert!(
        note.contains(&format!("Polarisation φ = {:.2}", scene.polarisation())),
        "{note}"
    );
    // A scrub restarts the plot at the new time; so does a new count.
    scene.advance_to(7.0).unwrap();
    let s = scene.plot_samples();
    assert_eq!(s.len(), 3);
    assert!((s[0] - 7.0).abs() < 1e-5);
    scene.advance_to(7.0 + 1.0 / 60.0).unwrap();
    scene.set_count(100.0).unwrap();
    assert_eq!(scene.plot_samples().len(), 3);
    // What the page's Try this says the plot shows. `run` returns φ and the speed ratio 4 s
    // after the start, and φ's mean over the timeline's second half (10 to 20 s).
    let run = |alignment: f32, min_speed: f32, leader: bool| {
        let mut f = FlockFigure::new();
        f.set_rule("alignment", alignment, 1.5).unwrap();
        f.set_min_speed(min_speed).unwrap();
        f.set_leader(leader);
        let (mut at_4s, mut late) = ((0.0, 0.0), 0.0);
        for k in 1..=1200 {
            f.advance_to(k as f32 / 60.0).unwrap();
            if k == 240 {
                at_4s = (f.polarisation(), f.speed_ratio());
            }
            if k > 600 {
                late += f.polarisation() / 600.0;
            }
        }
        (at_4s, late)
    };
    // The defaults (alignment 2, minimum speed 1.2 m/s): φ rises from its random start to
    // above 0.4 on average over the second half.
    let (_, late) = run(2.0, 1.2, false);
    assert!(late > 0.4, "defaults: mean φ {late}");
    // No alignment: every boid keeps its own heading, φ stays near 1/√N.
    let (_, late0) = run(0.0, 1.2, false);
    assert!(late0 < 0.15, "no alignment: mean φ {late0}");
    // No minimum speed: the boids agree by slowing down, below a tenth of the top speed in 4 s.
    let ((_, speed), late_slow) = run(2.0, 0.0, false);
    assert!(
        speed < 0.1 && late_slow < late,
        "no minimum speed: speed {speed}, mean φ {late_slow}"
    );
    // A leader pulls φ past 0.8 within 4 s.
    let ((phi_led, _), _) = run(2.0, 1.2, true);
    assert!(phi_led > 0.8, "leader: φ {phi_led}");
}

/// Steps `f` on to `time_sec` one step at a time (as the page does, frame by frame).
fn fly_to(f: &mut FlockFigure, time_sec: f32) {
    let mut k = (f.plot_samples()[f.plot_samples().len() - 3] * 60.0).round() as usize;
    while (k as f32) < time_sec * 60.0 - 0.5 {
        k += 1;
        f.advance_to(k as f32 / 60.0).unwrap();
    }
}

#[test]
fn the_flock_try_this_holds_when_done_in_mid_flight() {
    // The reader moves the controls while the flock flies, not only at its start. Minimum speed
    // to 0 at any moment: the mean speed is under a tenth of the top speed 5 s later (the text
    // says "within five seconds", not four). Then back to 1.2 with the leader: φ past 0.8
    // within five seconds.
    for t0 in [2.0f32, 5.0, 8.0] {
        let mut f = FlockFigure::new();
        fly_to(&mut f, t0);
        f.set_min_speed(0.0).unwrap();
        fly_to(&mut f, t0 + 5.0);
        assert!(
            f.speed_ratio() < 0.1,
            "min speed 0 at {t0} s: {}",
            f.speed_ratio()
        );
        f.set_min_speed(1.2).unwrap();
        f.set_leader(true);
        fly_to(&mut f, t0 + 10.0);
        assert!(
            f.polarisation() > 0.8,
            "leader at {} s: φ {}",
            t0 + 5.0,
            f.polarisation()
        );
    }
    // Alignment off in mid-flight: an ordered flock keeps much of its order for a while (which
    // is why the Try this says to start a new flock by dragging the timeline back to 0 s).
    let mut f = FlockFigure::new();
    fly_to(&mut f, 17.0);
    assert!(f.polarisation() > 0.4, "{}", f.polarisation());
    f.set_rule("alignment", 0.0, 1.5).unwrap();
    fly_to(&mut f, 19.0);
    assert!(f.polarisation() > 0.3, "{}", f.polarisation());
    // Dragged back to 0 s: a new flock, whose φ stays under 0.15 all through the loop.
    f.advance_to(0.0).unwrap();
    let mut highest: f32 = 0.0;
    for k in 1..=1200 {
        f.advance_to(k as f32 / 60.0).unwrap();
        highest = highest.max(f.polarisation());
    }
    assert!(
        highest < 0.15,
        "no alignment from the start: φ reached {highest}"
    );
}

#[test]
fn the_box_holds_the_flock_loosely() {
    // The text: a spring pulls back any boid that leaves the box, so boids overshoot the walls,
    // some by more than a metre, before they turn (so the text does not say the flock stays
    // inside the box). None escapes.
    let mut f = FlockFigure::new();
    let b = f.params().bounds;
    let mut farthest: f32 = 0.0;
    for k in 1..=1200 {
        f.advance_to(k as f32 / 60.0).unwrap();
        for p in &f.flock().positions {
            farthest = farthest.max((p.abs() - b).max(Vec3::ZERO).length());
        }
    }
    assert!(
        farthest > 1.0 && farthest < 2.5,
        "farthest outside the box: {farthest} m"
    );
}

#[test]
fn the_force_laws_do_what_the_text_says() {
    use inbetween::boids::ForceLaw;
    let mut f = FlockFigure::new();
    // The Gaussian law (a1 = a2 = 1, k = 2, x0 = 0.7 m): repels at contact, changes sign at
    // exactly x0 / 2, attracts most a little beyond x0. With a2 = 3 it would repel at x0.
    f.set_law("Gaussian").unwrap();
    let ForceLaw::Gaussian { a1, a2, k, x0 } = f.params().law else {
        panic!("{:?}", f.params().law)
    };
    assert_eq!((a1, a2, k, x0), (1.0, 1.0, 2.0, 0.7));
    let law = f.params().law;
    assert!(law.f(0.05) < 0.0 && law.f(0.45 * x0) < 0.0 && law.f(0.55 * x0) > 0.0);
    assert!(law.f(0.5 * x0).abs() < 1e-6, "{}", law.f(0.5 * x0));
    let xs = (1..=1500).map(|i| i as f32 / 1000.0);
    let peak = xs.max_by(|a, b| law.f(*a).total_cmp(&law.f(*b))).unwrap();
    assert!(peak > x0 && peak < 1.15 * x0, "peak at {peak} m");
    // The inverse-power law (a1 = 0.4, a2 = 0.04) is zero at 0.32 m, but in the flock every
    // neighbour within 1.5 m pulls, so nearest neighbours end up about 0.2 m apart.
    f.set_law("a1/x² − a2/x⁴").unwrap();
    let ForceLaw::InversePower { a1, a2 } = f.params().law else {
        panic!("{:?}", f.params().law)
    };
    let zero = (a2 / a1).sqrt();
    assert!((zero - 0.316).abs() < 1e-3 && f.params().law.f(zero).abs() < 1e-4);
    assert_eq!(f.params().law_radius, 1.5);
    let (mut sum, mut samples) = (0.0, 0);
    for k in 1..=1200 {
        f.advance_to(k as f32 / 60.0).unwrap();
        if k > 600 && k % 30 == 0 {
            let ps = &f.flock().positions;
            let nearest = |i: usize| {
                (0..ps.len())
                    .filter(|&j| j != i)
                    .map(|j| (ps[i] - ps[j]).length())
                    .fold(f32::INFINITY, f32::min)
            };
            sum += (0..ps.len()).map(nearest).sum::<f32>() / ps.len() as f32;
            samples += 1;
        }
    }
    let mean = sum / samples as f32;
    assert!(
        mean > 0.15 && mean < 0.26,
        "mean nearest-neighbour distance {mean} m"
    );
}

#[test]
fn the_rules_figures_cell_square_lies_on_the_grid_around_the_boid() {
    // The orange square (the boid's cell) and the teal block are drawn on the grid's plane
    // y = 0, and the orange one holds the boid. Drawn from the grid origin's y = −0.5, half a
    // metre below the grid lines, the orange square would look a whole cell away from the boid
    // near a corner in the page's perspective.
    let orange = Vec3::new(0.791298, 0.254152, 0.0);
    for (x, z, size) in [
        (0.0, 0.0, 1.0),
        (-1.9, -1.9, 0.25),
        (1.9, 0.0, 0.25),
        (1.2, -1.0, 0.5),
    ] {
        let mut scene = RulesFigure::new();
        scene.set_position(x, z).unwrap();
        scene.set_cell_size(size).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        for v in &frame.lines {
            assert!(v.position[1] > -0.01, "a line below the grid plane: {v:?}");
        }
        // The orange lines within 0.01 m of the plane are the cell square (the boid's velocity
        // arrow is orange too, but it starts at the boid and points along +x).
        let square: Vec<Vec3> = frame
            .strokes
            .iter()
            .filter(|v| Vec3::from_slice(&v.color[..3]).distance(orange) < 1e-3)
            .flat_map(|v| [Vec3::from(v.a), Vec3::from(v.b)])
            .filter(|p| (p.y - 0.002).abs() < 1e-4)
            .collect();
        assert_eq!(square.len(), 8, "four edges at ({x}, {z}), cell {size}");
        let (lo, hi) = square.iter().fold(
            (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
            |(a, b), p| (a.min(*p), b.max(*p)),
        );
        assert!(
            // The square is inset by 3% of a cell; a boid on a boundary belongs to the upper cell.
            (lo.x - 0.05 * size..=hi.x + 0.05 * size).contains(&x)
                && (lo.z - 0.05 * size..=hi.z + 0.05 * size).contains(&z),
            "the boid at ({x}, {z}) is outside its square {lo} .. {hi}"
        );
        assert!((hi.x - lo.x - 0.94 * size).abs() < 1e-4, "{lo} .. {hi}");
    }
}

#[test]
fn a_min_speed_above_the_max_is_rejected_and_changes_nothing() {
    let mut scene = FlockFigure::new();
    let note = scene.draw(&mut Frame::default());
    assert!(note.contains("speed between 1.200 and 1.800 m/s"), "{note}");
    let e = scene.set_min_speed(3.0).unwrap_err();
    assert!(e.contains("at most the max speed, 1.8 m/s"), "{e}");
    let e = scene.set_max_speed(1.0).unwrap_err();
    assert!(e.contains("at least the min speed, 1.2 m/s"), "{e}");
    let note = scene.draw(&mut Frame::default());
    assert!(note.contains("speed between 1.200 and 1.800 m/s"), "{note}");
    scene.set_max_speed(1.2).unwrap();
    scene.set_min_speed(1.2).unwrap();
}

#[test]
fn the_force_law_plot_shows_what_the_lesson_says_of_the_two_laws() {
    use inbetween::figures::boids::{law_plot_samples, FLOCK_LAWS, LAW_PLOT_X};
    let flat = law_plot_samples(1000.0).unwrap();
    assert_eq!(flat.len(), 3000);
    let rows: Vec<[f32; 3]> = flat.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
    assert_eq!(rows[0][0], LAW_PLOT_X.0);
    assert!((rows[999][0] - LAW_PLOT_X.1).abs() < 1e-6);
    // The samples are the laws the flock's dropdown sets.
    for r in &rows {
        assert_eq!(r[1], FLOCK_LAWS[1].f(r[0]));
        assert_eq!(r[2], FLOCK_LAWS[2].f(r[0]));
    }
    // Where each crosses zero (repulsion to attraction) and where it pulls hardest, as the text
    // says: 0.32 m and 1 m/s² at 0.45 m; 0.35 m and about 0.65 m/s² near 0.76 m.
    let crossing = |k: usize| {
        let w = rows
            .windows(2)
            .find(|w| w[0][k] < 0.0 && w[1][k] >= 0.0)
            .unwrap();
        w[0][0]
    };
    let peak = |k: usize| {
        let r = rows.iter().max_by(|a, b| a[k].total_cmp(&b[k])).unwrap();
        (r[0], r[k])
    };
    assert!(
        (crossing(1) - 0.1f32.sqrt()).abs() < 0.002,
        "{}",
        crossing(1)
    );
    let (x, f) = peak(1);
    assert!(
        (x - 0.2f32.sqrt()).abs() < 0.002 && (f - 1.0).abs() < 1e-3,
        "{x} {f}"
    );
    assert!((crossing(2) - 0.35).abs() < 0.002, "{}", crossing(2));
    let (x, f) = peak(2);
    assert!(
        (x - 0.76).abs() < 0.01 && (f - 0.65).abs() < 0.005,
        "{x} {f}"
    );
    // At contact the Gaussian law pushes with a finite a1 e^(−k) − a2; the other without bound.
    assert!((FLOCK_LAWS[2].f(0.0) - ((-2.0f32).exp() - 1.0)).abs() < 1e-6);
    assert!((FLOCK_LAWS[2].f(0.0) + 0.86).abs() < 0.01);
    assert!(rows[0][1] < -1000.0 && rows[0][1].is_finite());
    // The plot reaches contact: its first Gaussian sample is the text's -0.86 m/s².
    assert!(rows[0][0] < 0.01 && (rows[0][2] + 0.86).abs() < 0.01, "{:?}", rows[0]);
    // Bad counts are errors, not panics or huge allocations.
    for bad in [f32::NAN, 1.0, 1e9, -3.0] {
        assert!(law_plot_samples(bad).is_err(), "{bad}");
    }
}

#[test]
fn the_gaussian_law_changes_sign_twice_within_its_reach() {
    // With k = 2 and a1 = a2, f(x) = 0 where 2 (x/x0 − 1)² = x/x0: x = x0/2 and x = 2 x0. The
    // page: zero at 0.35 m and 1.4 m, attraction between, f(1.5 m) ≈ −0.044 m/s² beyond.
    use inbetween::figures::boids::FLOCK_LAWS;
    let law = FLOCK_LAWS[2];
    assert!(law.f(0.35).abs() < 1e-6 && law.f(1.4).abs() < 1e-6);
    assert!((law.f(1.5) + 0.044).abs() < 0.001, "{}", law.f(1.5));
    for i in 1..100 {
        let x = 0.35 + (1.4 - 0.35) * i as f32 / 100.0;
        assert!(law.f(x) > 0.0, "attracts at {x}");
    }
    assert!(law.f(1.45) < 0.0 && law.f(0.3) < 0.0);
}

/// Sweeps with made-up timings: `grid(N)` and `naive(N)` ms, with a repeat-dependent wobble.
fn synthetic_sweep(grid: impl Fn(f32) -> f32, naive: impl Fn(f32) -> f32) -> StepTimeSweep {
    let mut sweep = StepTimeSweep::new();
    let mut k = 0;
    while let Some((n, search)) = sweep.next_timing() {
        let wobble = 1.0 + 0.1 * (k % 3) as f32;
        let t = if search == "grid" {
            grid(n as f32)
        } else {
            naive(n as f32)
        };
        sweep.record(t * wobble).unwrap();
        k += 1;
    }
    sweep
}

#[test]
fn the_step_time_sweep_fits_slopes_on_log_log_axes_and_shows_the_spread() {
    // t = c N for the grid, c N² for the naive search: fitted slopes 1 and 2, guides through the
    // last medians, fastest ≤ median ≤ slowest.
    let mut sweep = synthetic_sweep(|n| 1e-3 * n, |n| 1e-6 * n * n);
    assert!((sweep.fitted_slope(0).unwrap() - 1.0).abs() < 1e-3);
    assert!((sweep.fitted_slope(1).unwrap() - 2.0).abs() < 1e-3);
    let s = sweep.plot_samples();
    assert_eq!(s.len(), 9 * SWEEP_SIZES.len());
    for row in s.chunks_exact(9) {
        let n = row[0];
        assert!(row[2] <= row[1] && row[1] <= row[3] && row[5] <= row[4] && row[4] <= row[6]);
        assert!(row[3] > row[2], "the spread shows");
        // The median of 1.0, 1.1, 1.2, 1.0, 1.1 times the law is 1.1 times it.
        assert!((row[7] - 1.1e-3 * n).abs() < 1e-4 * n, "{row:?}");
        assert!((row[8] - 1.1e-6 * n * n).abs() < 1e-4 * row[8], "{row:?}");
    }
    let note = sweep.note();
    assert!(
        note.contains("naive slope 2.0 (×4.0 per doubling of N), grid slope 1.0 (×2.0"),
        "{note}"
    );
    assert!(
        note.contains("At N = 3200 the naive search takes 3.2× as long as the grid."),
        "{note}"
    );
    assert!(
        note.contains("% above the fastest.") && !note.contains("busy"),
        "{note}"
    );
    // Grid and naive take turns at each size.
    let mut sweep = StepTimeSweep::new();
    let order: Vec<&str> = (0..4)
        .map(|_| {
            let (_, s) = sweep.next_timing().unwrap();
            sweep.record(1.0).unwrap();
            s
        })
        .collect();
    assert_eq!(order, ["grid", "naive", "grid", "naive"]);
    assert!(sweep.note().starts_with("Measuring one step at N = 100"));
    assert!(sweep.record(f32::NAN).is_err() && sweep.record(-1.0).is_err());
}

#[test]
fn a_slow_naive_search_is_not_timed_at_larger_sizes() {
    // A debug build: the naive step passes SWEEP_LIMIT_MS at 800 boids, so 1600 and 3200 are
    // left out (NaN in the plot) and the note says from where.
    let mut sweep = synthetic_sweep(|n| 1e-2 * n, |n| 1e-4 * n * n);
    let s = sweep.plot_samples();
    assert_eq!(s.len(), 9 * SWEEP_SIZES.len());
    let row = |n: f32| s.chunks_exact(9).find(|r| r[0] == n).unwrap();
    assert!(row(800.0)[4] > SWEEP_LIMIT_MS && row(1600.0)[4].is_nan() && row(3200.0)[4].is_nan());
    assert!(row(3200.0)[1] > 0.0, "the grid goes on");
    assert!(
        row(800.0)[8] > 0.0 && row(1600.0)[8].is_nan(),
        "the slope-2 guide stops with it"
    );
    let note = sweep.note();
    assert!(note.contains("not timed from N = 1600 on"), "{note}");
    assert!(note.contains("At N = 800 the naive search"), "{note}");
    // A loaded machine: one slow timing in five moves the median little, and the note says so.
    let mut sweep = StepTimeSweep::new();
    let mut k = 0;
    while let Some((n, search)) = sweep.next_timing() {
        let n = n as f32;
        let t = if search == "grid" {
            1e-3 * n
        } else {
            1e-6 * n * n
        };
        sweep.record(if k % 10 == 3 { 3.0 * t } else { t }).unwrap();
        k += 1;
    }
    assert!((sweep.fitted_slope(1).unwrap() - 2.0).abs() < 0.05);
    assert!(sweep.note().contains("the machine is busy"));
}

#[test]
fn cells_narrower_than_the_radius_miss_neighbours_and_the_figure_says_so() {
    let mut scene = RulesFigure::new();
    // Cells at least as wide as the radius never miss a neighbour, wherever the boid is.
    for (cell, radius) in [(1.2, 1.2), (1.5, 1.2), (2.0, 0.5), (0.5, 0.5)] {
        scene.set_cell_size(cell).unwrap();
        scene.set_radius(radius).unwrap();
        for i in 0..20 {
            for k in 0..20 {
                let (x, z) = (-1.9 + 0.2 * i as f32, -1.9 + 0.2 * k as f32);
                scene.set_position(x, z).unwrap();
                assert!(
                    scene.missed_neighbours().is_empty(),
                    "{cell} {radius} at {x} {z}"
                );
            }
        }
    }
    // At the defaults with 0.25 m cells (the page's Try this) some neighbours lie beyond the
    // 3 × 3 block.
    let mut scene = RulesFigure::new();
    scene.set_cell_size(0.25).unwrap();
    let missed = scene.missed_neighbours().len();
    assert!(missed > 0);
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame);
    assert!(
        note.contains(&format!("misses {missed} of its neighbours (ringed in red)")),
        "{note}"
    );
    // Each missed neighbour has a red ring round it (its dot shows inside), not a disc.
    let red = inbetween::draw::palette::RED.to_array();
    assert!(frame.markers.iter().all(|m| m.color[..3] != red));
    for q in scene.missed_neighbours() {
        let ring = frame
            .strokes
            .iter()
            .filter(|s| s.color[..3] == red)
            .filter(|s| {
                [s.a, s.b]
                    .iter()
                    .all(|&p| (Vec3::from(p).distance(q) - MISSED_RING_M).abs() < 1e-4)
            })
            .count();
        assert_eq!(ring, 24, "a ring round {q}");
    }
    scene.set_cell_size(1.2).unwrap();
    assert!(!scene.draw(&mut Frame::default()).contains("misses"));
}

/// Right where no clamp or empty set is needed: no upper clamp in the cell index, a mean over
/// no neighbours divides by zero.
fn careless(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut rest = args;
    let mut out = Vec::new();
    match name {
        "three_rules" => {
            let p = Vec3::take(&mut rest).unwrap();
            let v = Vec3::take(&mut rest).unwrap();
            let ps = Vec::<Vec3>::take(&mut rest).unwrap();
            let vs = Vec::<Vec3>::take(&mut rest).unwrap();
            let n = ps.len() as f32;
            let c = ps.iter().sum::<Vec3>() / n - p;
            let a = vs.iter().sum::<Vec3>() / n - v;
            let s: Vec3 = ps
                .iter()
                .map(|q| (p - *q) / (p - *q).length_squared())
                .sum();
            vec![c, a, s].put(&mut out)
        }
        "cell_index" => {
            let p = Vec3::take(&mut rest).unwrap();
            let o = Vec3::take(&mut rest).unwrap();
            let s = f32::take(&mut rest).unwrap();
            let d = <[f32; 3]>::take(&mut rest).unwrap();
            let c = ((p - o) / s).floor().max(Vec3::ZERO);
            (c.x as usize + d[0] as usize * (c.y as usize + d[1] as usize * c.z as usize))
                .put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

#[test]
fn the_rules_figure_checks_probe_inputs_beyond_its_boid() {
    let mut scene = RulesFigure::new();
    scene.set_use_exercise(true);
    scene.set_runner(careless);
    let note = scene.exercise_note();
    assert!(
        note.contains("Your three_rules matches the reference at this boid."),
        "{note}"
    );
    assert!(
        note.contains("your three_rules differs at 1: no neighbours"),
        "{note}"
    );
    assert!(
        note.contains("Your cell_index matches the reference at this boid."),
        "{note}"
    );
    assert!(
        note.contains("your cell_index differs at 1: a boid past the grid's far corner"),
        "{note}"
    );
    scene.set_runner(reference);
    let note = scene.exercise_note();
    assert!(
        note.contains("Your three_rules also matches at 3 probe inputs"),
        "{note}"
    );
    assert!(
        note.contains("Your cell_index also matches at 4 probe inputs"),
        "{note}"
    );
}

#[test]
fn without_separation_the_leaders_flock_piles_into_one_clump() {
    // The Try this: leader on, then separation 0: nothing keeps the boids apart, and their mean
    // distance to the nearest neighbour collapses (the boids pile onto one point).
    let nearest = |f: &FlockFigure| {
        let ps = &f.flock().positions;
        (0..ps.len())
            .map(|i| {
                (0..ps.len())
                    .filter(|&j| j != i)
                    .map(|j| (ps[i] - ps[j]).length())
                    .fold(f32::INFINITY, f32::min)
            })
            .sum::<f32>()
            / ps.len() as f32
    };
    let mut f = FlockFigure::new();
    f.set_leader(true);
    fly_to(&mut f, 5.0);
    let before = nearest(&f);
    f.set_rule("separation", 0.0, 0.5).unwrap();
    // The page: "within five seconds … from about a third of a metre to under 2 cm".
    fly_to(&mut f, 10.0);
    let after = nearest(&f);
    assert!(
        (0.25..0.45).contains(&before) && after < 0.02,
        "{before} → {after}"
    );
}

/// Only the ground's cell grid may be 1 pixel wide: anything a student must see is a wide stroke.
fn thin_lines_are_grid_lines_only(frame: &Frame) -> bool {
    use inbetween::draw::palette;
    frame.lines.iter().all(|v| {
        let c = Vec3::from_slice(&v.color[..3]);
        c == palette::GRID || c == palette::GRID_AXIS
    })
}

#[test]
fn every_boids_tail_is_a_wide_stroke() {
    let mut scene = FlockFigure::new();
    scene.advance_to(0.3).unwrap();
    let mut frame = Frame::default();
    scene.draw(&mut frame);
    assert!(thin_lines_are_grid_lines_only(&frame));
    let boids = frame.points.len();
    assert_eq!(boids, 300);
    // One tail per boid, 0.12 m long behind it, TAIL_PX wide.
    let tails = frame
        .strokes
        .iter()
        .filter(|s| s.width_px == TAIL_PX)
        .filter(|s| (Vec3::from(s.a).distance(Vec3::from(s.b)) - 0.12).abs() < 1e-3)
        .count();
    assert_eq!(tails, boids);
    assert!(TAIL_PX >= 2.0);
    let rules = RulesFigure::new();
    let mut frame = Frame::default();
    rules.draw(&mut frame);
    assert!(thin_lines_are_grid_lines_only(&frame));
}

#[test]
fn gpu_mode_plots_the_flock_read_back_from_the_gpu() {
    // In GPU mode the CPU never steps the flock; the order plot takes a sample every
    // GPU_SAMPLE_SEC from the flock the web layer reads back. Here a CPU flock stands in for
    // the GPU's: the samples are its φ and speed, at the tickets' times.
    let mut f = FlockFigure::new();
    let mut stand_in = f.flock().clone();
    let params = f.params().clone();
    let mut samples = 0;
    for frame in 1..=60 {
        let (restart, steps) = f.plan_gpu_steps(frame as f32 / 60.0).unwrap();
        assert!(!restart);
        for _ in 0..steps {
            stand_in.step(&params, boids::Search::Grid, 1.0 / 60.0);
        }
        if let Some(ticket) = f.gpu_sample_due() {
            assert!(f.record_gpu_sample(ticket, &stand_in.velocities).unwrap());
            samples += 1;
        }
    }
    let s = f.plot_samples();
    assert_eq!(s.len(), 3 * (1 + samples), "the start, then one sample per 0.1 s");
    assert_eq!(samples, 10);
    let times: Vec<f32> = s.chunks(3).map(|r| r[0]).collect();
    assert!(times.windows(2).all(|w| (w[1] - w[0] - GPU_SAMPLE_SEC).abs() < 1e-4), "{times:?}");
    let last = &s[s.len() - 3..];
    let mut cpu = FlockFigure::new();
    for frame in 1..=60 {
        cpu.advance_to(frame as f32 / 60.0).unwrap();
    }
    assert!((last[1] - cpu.polarisation()).abs() < 1e-4 && (last[2] - cpu.speed_ratio()).abs() < 1e-4);
    // A read-back queued before a scrub back is not plotted after it; bad read-backs are errors.
    let ticket = GpuSample { time_sec: 1.0, run: 0 };
    let stale = f.gpu_sample_due().unwrap_or(ticket);
    assert!(f.plan_gpu_steps(0.2).unwrap().0, "a scrub back restarts the flock");
    assert!(!f.record_gpu_sample(stale, &stand_in.velocities).unwrap());
    assert_eq!(f.plot_samples().len(), 3);
    assert!(f.record_gpu_sample(stale, &stand_in.velocities[1..]).unwrap_err().contains("velocities"));
    let mut nan = stand_in.velocities.clone();
    nan[7].x = f32::NAN;
    assert!(f.record_gpu_sample(stale, &nan).unwrap_err().contains("boid 7"));
    let note = f.draw_gpu(&mut Frame::default());
    assert!(note.contains("order plot reads the flock back from the GPU every 0.1 s"), "{note}");
    // The GPU's boids are the shader's sprites, dots without the CPU flock's heading tails:
    // the note says so, and the frame draws no boid of its own.
    assert!(note.contains("Each boid is a dot"), "{note}");
    let mut frame = Frame::default();
    f.draw_gpu(&mut frame);
    assert!(frame.points.is_empty(), "{} points", frame.points.len());
}

#[test]
fn the_flock_has_an_inset_from_above_that_holds_its_box_and_its_boids() {
    // The walls are a spring: boids overshoot them (the_box_holds_the_flock_loosely). Every boid
    // and every corner of the box lies inside the inset's view, seen from above, through 20 s
    // of flight at the page's settings and at the sliders' top speeds with the predator and the
    // leader, on the CPU, and the GPU mode's inset frames its box the same way.
    use inbetween::draw::inset::{inset_camera, InsetView};
    let mut farthest: f32 = 0.0;
    for fast in [false, true] {
        let mut f = FlockFigure::new();
        if fast {
            f.set_max_speed(5.0).unwrap();
            f.set_min_speed(5.0).unwrap();
            f.set_predator(true);
            f.set_leader(true);
        }
        for k in 0..=1200 {
            f.advance_to(k as f32 / 60.0).unwrap();
            let mut frame = Frame::default();
            f.draw(&mut frame);
            let inset = frame.inset.clone().expect("an inset");
            assert_eq!(inset.view, InsetView::Top);
            let (view, proj, _) = inset_camera(&inset).unwrap();
            let vp = proj * view;
            let corners = frame.keep_in_view.clone();
            assert!(!corners.is_empty());
            for p in corners.iter().chain(&f.flock().positions) {
                let ndc = vp.project_point3(*p);
                farthest = farthest.max(ndc.x.abs()).max(ndc.y.abs());
                assert!(
                    ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0 && (0.0..=1.0).contains(&ndc.z),
                    "fast {fast}, step {k}: {p} at {ndc}"
                );
            }
        }
        // GPU mode widens its inset with the flock read back from the GPU.
        f.set_gpu_mode(true).unwrap();
        let far = Vec3::new(30.0, 0.0, -40.0);
        f.widen_reach(&[far, Vec3::NAN]);
        let mut frame = Frame::default();
        f.draw_gpu(&mut frame);
        let inset = frame.inset.clone().expect("an inset in GPU mode");
        assert!(inset.max.cmpge(far.abs()).all() && inset.min.cmple(-far.abs()).all());
        assert!(inset.max.is_finite(), "{inset:?}");
    }
    // The inset is not far wider than the flock reaches: some boid comes near its edge.
    assert!(farthest > 0.75, "the boids reach {farthest} of the inset's half-width");
}

/// 12.1 right with neighbours, panicking without (a mean over no neighbours, then an `assert!`).
fn panics_without_neighbours(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "three_rules" {
        let mut rest = args;
        let _ = (Vec3::take(&mut rest), Vec3::take(&mut rest));
        if Vec::<Vec3>::take(&mut rest).unwrap().is_empty() {
            return Err(Failure::Panicked(
                "panicked at src/exercises/boids.rs:31:5:\nno neighbours: the centre is not a number"
                    .into(),
            ));
        }
    }
    reference(name, args)
}

thread_local! {
    /// The first panic of the page-like runner below.
    static STUCK: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// [`panics_without_neighbours`] as the page runs it: after a panic of 12.1, every later call
/// of 12.1 gets it back.
fn stuck_after_a_panic(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    if name == "three_rules" {
        if let Some(message) = STUCK.with(|s| s.borrow().clone()) {
            return Err(Failure::Panicked(message));
        }
    }
    let answer = panics_without_neighbours(name, args);
    if let Err(Failure::Panicked(message)) = &answer {
        STUCK.with(|s| *s.borrow_mut() = Some(message.clone()));
    }
    answer
}

#[test]
fn a_panic_of_12_1_is_named_once_against_the_input_that_caused_it() {
    for runner in [
        panics_without_neighbours as fn(&str, &[f32]) -> Result<Vec<f32>, Failure>,
        stuck_after_a_panic,
    ] {
        STUCK.with(|s| *s.borrow_mut() = None);
        let mut scene = RulesFigure::new();
        scene.set_runner(runner);
        scene.set_use_exercise(true);
        // The figure's boid has neighbours; the probe without any panics. Twice: the second
        // note is what the page shows from its next frame on.
        for _ in 0..2 {
            let note = scene.exercise_note();
            assert!(
                note.contains(
                    "Your exercise 12.1 three_rules, called with the probe input \"no neighbours \
                     (three zero vectors)\", panicked at src/exercises/boids.rs:31:5: no \
                     neighbours: the centre is not a number."
                ),
                "{note}"
            );
            assert_eq!(note.matches("panicked").count(), 1, "{note}");
            // 12.2 is not touched by 12.1's panic.
            assert!(note.contains("Your cell_index matches"), "{note}");
        }
        // A boid with no neighbours in view, from a fresh figure: the figure's own boid is named.
        let mut scene = RulesFigure::new();
        STUCK.with(|s| *s.borrow_mut() = None);
        scene.set_runner(runner);
        scene.set_use_exercise(true);
        scene.set_radius(0.2).unwrap();
        let note = scene.exercise_note();
        assert!(
            note.contains("three_rules, called with the figure's boid at (0.000, 0.000), panicked"),
            "{note}"
        );
        assert_eq!(scene.rules(), {
            let mut plain = RulesFigure::new();
            plain.set_radius(0.2).unwrap();
            plain.rules()
        });
    }
}

/// The rules figure declares its whole grid as its view: for every cell size (the last row and
/// column reach up to 2 m past the boids' square), with the camera fitted from the page's
/// direction, every grid line lies on the canvas at 800 × 600, 1600 × 1000 and the figure's
/// own canvases. The heading is drawn wider than the steering arrows, which go over it.
#[test]
fn the_rules_figure_shows_its_whole_grid_and_the_heading_under_the_arrows() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::{palette, ARROW_PX};
    for cell in [0.25f32, 0.9, 1.2, 1.5, 1.9, 2.0] {
        let mut scene = RulesFigure::new();
        scene.set_cell_size(cell).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        let (lo, hi) = scene.grid_box();
        assert!(hi.x - lo.x >= 4.0 && hi.x - lo.x < 4.0 + cell + 1e-4);
        for p in &frame.keep_in_view {
            assert!(p.cmpge(lo - 1e-5).all() && p.cmple(hi + 1e-5).all(), "{p}");
        }
        for (w, h) in [
            (800.0, 600.0),
            (1600.0, 1000.0),
            (760.0, 420.0),
            (650.0, 420.0),
        ] {
            let size = glam::Vec2::new(w, h);
            let mut camera = OrbitCamera::from_view(scene.view());
            assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
            let view_proj = camera.projection(w / h) * camera.view();
            let ends = frame.lines.iter().map(|v| Vec3::from(v.position));
            for p in ends {
                let s = project_to_canvas(view_proj, size, p).unwrap();
                assert!(
                    s.x >= 0.0 && s.y >= 0.0 && s.x <= w && s.y <= h,
                    "cell {cell}, {w} x {h}: a grid line ends at {s} ({p})"
                );
            }
        }
    }
    let mut frame = Frame::default();
    RulesFigure::new().draw(&mut frame);
    let orange: Vec<usize> = (0..frame.strokes.len())
        .filter(|&i| frame.strokes[i].color[..3] == palette::ORANGE.to_array())
        .filter(|&i| frame.strokes[i].width_px == HEADING_PX)
        .collect();
    assert_eq!(orange.len(), 1, "one wide heading");
    assert!(HEADING_PX >= 2.0 * ARROW_PX);
    let green = frame
        .strokes
        .iter()
        .position(|s| s.color[..3] == palette::GREEN.to_array())
        .unwrap();
    assert!(green > orange[0], "cohesion is drawn over the heading");
    // The boid is an outlined dot over everything, added after the arrows that start at it,
    // and its own cell's square (y = 0.002) is drawn over the teal block's edges beside it.
    let boid = frame
        .markers
        .iter()
        .position(|m| m.color[..3] == palette::ORANGE.to_array())
        .expect("the boid's dot");
    assert!(frame.markers[boid].size_px < 0.0, "over everything");
    assert_eq!(Vec3::from(frame.markers[boid].center), Vec3::ZERO);
    for s in &frame.strokes {
        if (s.a[1] - 0.002).abs() < 1e-4 && (s.b[1] - 0.002).abs() < 1e-4 {
            let own = s.color[..3] == palette::ORANGE.to_array();
            assert_eq!(s.depth_bias == inbetween::draw::ON_TOP, own, "{s:?}");
        }
    }
}

/// The three steering arrows start at the boid: the shorter of two lies above the longer (the
/// camera looks down), so a short rule pointing along a long one is not hidden under it, at the
/// defaults and at other places and headings.
#[test]
fn the_rules_figures_shorter_steering_arrows_lie_over_the_longer() {
    use inbetween::draw::palette;
    for (x, z, heading) in [(0.0, 0.0, 0.0), (0.3, 0.3, 45.0), (-0.4, 0.2, 180.0)] {
        let mut scene = RulesFigure::new();
        scene.set_position(x, z).unwrap();
        scene.set_heading_deg(heading).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        let shafts: Vec<(f32, f32)> = [palette::GREEN, palette::PINK, palette::RED]
            .iter()
            .filter_map(|c| {
                frame
                    .strokes
                    .iter()
                    .find(|s| s.color[..3] == c.to_array())
                    .map(|s| {
                        let (a, b) = (Vec3::from(s.a), Vec3::from(s.b));
                        ((b - a).length(), a.y)
                    })
            })
            .collect();
        assert_eq!(shafts.len(), 3, "at ({x}, {z}), heading {heading}");
        for a in &shafts {
            for b in &shafts {
                if a.0 < b.0 - 1e-4 {
                    assert!(a.1 > b.1, "at ({x}, {z}), heading {heading}: {shafts:?}");
                }
            }
        }
    }
}

#[test]
fn the_rules_figures_largest_radius_circle_stays_in_view() {
    // A circle of 3 m around a boid at the slider's corner reaches past the grid: every point of
    // every wide line (the circle included) lies on the canvas after the viewer's fit.
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    for (x, z) in [(0.0, 0.0), (1.9, -1.9), (-1.9, 1.9)] {
        let mut scene = RulesFigure::new();
        scene.set_position(x, z).unwrap();
        scene.set_radius(3.0).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        let circle_far = frame
            .strokes
            .iter()
            .flat_map(|s| [Vec3::from(s.a), Vec3::from(s.b)])
            .map(|p| p.x.abs().max(p.z.abs()))
            .fold(0.0f32, f32::max);
        assert!(circle_far >= 2.99, "the circle reaches {circle_far} m");
        for size in [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0)] {
            let mut camera = OrbitCamera::from_view(scene.view());
            assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            for s in &frame.strokes {
                for p in [s.a, s.b] {
                    let px = project_to_canvas(view_proj, size, Vec3::from(p)).unwrap();
                    assert!(
                        px.cmpge(Vec2::ZERO).all() && px.cmple(size).all(),
                        "boid at ({x}, {z}), {size}: {p:?} drawn at {px}, off the canvas"
                    );
                }
            }
        }
    }
}

#[test]
fn the_mean_speed_lies_within_the_speed_limits_the_note_states() {
    // The note's "speed between min and max" holds of the flock it describes: at the start
    // (a seeded flock at half the max speed would fly below the min speed), and at once after
    // the limits move (not only after the next step), also for a flock started afresh then.
    let mean = |f: &FlockFigure| f.speed_ratio() * f.params().max_speed;
    let within = |f: &FlockFigure| {
        let (lo, hi) = (f.params().min_speed, f.params().max_speed);
        let ok = f.flock().velocities.iter().all(|v| {
            let s = v.length();
            s >= lo - 1e-4 && s <= hi + 1e-4
        });
        ok && mean(f) >= lo - 1e-4 && mean(f) <= hi + 1e-4
    };
    let mut f = FlockFigure::new();
    assert!(within(&f), "at the start: mean {}", mean(&f));
    fly_to(&mut f, 0.5);
    f.set_max_speed(4.0).unwrap();
    f.set_min_speed(4.0).unwrap();
    assert!(within(&f), "after the limits moved: mean {}", mean(&f));
    let note = f.draw(&mut Frame::default());
    assert!(
        note.contains("speed between 4.000 and 4.000 m/s") && note.contains("mean speed 4.00 m/s"),
        "{note}"
    );
    f.set_min_speed(0.5).unwrap();
    f.set_max_speed(0.8).unwrap();
    assert!(within(&f), "after the max fell: mean {}", mean(&f));
    f.set_count(500.0).unwrap();
    assert!(within(&f), "a new flock: mean {}", mean(&f));
}

/// At the page's camera (lessons/12-boids/lesson.js: distance 9, yaw 0.5, pitch 0.45, fitted
/// beside the inset as the viewer does) on the canvases the page gives Figure 2 at 800 × 600 and
/// 1600 × 1000, every boid of the default flock lies on the canvas, left of the inset's square,
/// through 20 s of flight: the walls are springs and boids overshoot them, so the view frames
/// the farthest the flock has flown, not only the box. The box still spans most of the canvas's
/// height, and the camera moves only a few times (the reach grows in half metres).
#[test]
fn the_main_view_keeps_the_overshooting_flock_in_view() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::inset::inset_rect;
    for size in crate::label_clearance::CANVASES {
        let left_of = inset_rect(size).min.x;
        let mut f = FlockFigure::new();
        let b = f.params().bounds;
        let mut cameras = Vec::new();
        for k in 0..=1200 {
            f.advance_to(k as f32 / 60.0).unwrap();
            let mut frame = Frame::default();
            f.draw(&mut frame);
            let mut camera = OrbitCamera::from_view([0.0, 0.0, 0.0, 9.0, 0.5, 0.45]);
            assert!(camera.fit_left_of(&frame.fit_points(), size, left_of, FIT_PAD_PX));
            if cameras.last() != Some(&camera) {
                cameras.push(camera);
            }
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let at = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
            for &p in &f.flock().positions {
                let c = at(p);
                assert!(
                    c.cmpge(Vec2::ZERO).all() && c.x <= left_of && c.y <= size.y,
                    "on {size} at step {k}: the boid at {p} lands at {c}"
                );
            }
            // The box's corners, from its top to its bottom on the canvas.
            let ys: Vec<f32> = (0..8)
                .map(|i| {
                    let s = Vec3::new(
                        if i & 1 == 0 { -1.0 } else { 1.0 },
                        if i & 2 == 0 { -1.0 } else { 1.0 },
                        if i & 4 == 0 { -1.0 } else { 1.0 },
                    );
                    at(s * b).y
                })
                .collect();
            let span = ys.iter().copied().fold(f32::MIN, f32::max)
                - ys.iter().copied().fold(f32::MAX, f32::min);
            assert!(span > 0.35 * size.y, "on {size} at step {k}: the box spans {span} px");
        }
        // Each move frames half a metre more (the inset's reach); the flock stops reaching
        // farther within seconds.
        assert!(cameras.len() <= 12, "on {size} the camera moves {} times", cameras.len());
    }
}


/// The page's slowest frame at its fastest speed: the cap on a frame's `dt` in `tick` and the
/// largest option of the timeline's speed menu, read from `www/lesson.js`.
fn page_largest_frame_jump_sec() -> f32 {
    let js = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/www/lesson.js")).unwrap();
    let cap_at = js.find("Math.min((nowMs - lastMs) / 1000, ").expect("the frame cap in tick") + 34;
    let cap: f32 = js[cap_at..].split(')').next().unwrap().trim().parse().unwrap();
    let menu = &js[js.find("class=\"speed\"").expect("the speed menu")..];
    let menu = &menu[..menu.find("</select>").unwrap()];
    let fastest = menu
        .split("<option value=\"")
        .skip(1)
        .map(|o| o.split('"').next().unwrap().parse::<f32>().unwrap())
        .fold(0.0, f32::max);
    assert!(cap > 0.0 && fastest >= 1.0, "{cap} {fastest}");
    cap * fastest
}

#[test]
fn the_pages_slowest_frame_at_its_fastest_speed_keeps_the_flock() {
    let jump = page_largest_frame_jump_sec();
    // Several start times, so that the frame's ends fall at every rounding of the steps.
    for start_step in [180, 181, 197] {
        for offset in [0.0, 0.3, 0.7] {
            let t0 = (start_step as f32 + offset) / 60.0;
            let mut slow = FlockFigure::new();
            let mut smooth = FlockFigure::new();
            for k in 1..=start_step {
                slow.advance_to(k as f32 / 60.0).unwrap();
            }
            slow.advance_to(t0).unwrap();
            let samples_before = slow.plot_samples().len();
            let taken = slow.advance_to(t0 + jump).unwrap();
            assert!(taken >= 12, "{taken} steps for a {jump} s frame from {t0} s");
            let history = slow.plot_samples();
            assert_eq!(history[0], 0.0, "the order plot still starts at 0 s (from {t0} s)");
            assert_eq!(history.len(), samples_before + 3 * taken, "from {t0} s");
            // The same flock as one stepped a frame at a time: not a fresh start.
            let end_steps = start_step + taken;
            for k in 1..=end_steps {
                smooth.advance_to(k as f32 / 60.0).unwrap();
            }
            assert_eq!(slow.flock().positions, smooth.flock().positions, "from {t0} s");
        }
    }
}

/// The Try this under the flock: the headings begin random, with φ a few hundredths (under
/// 0.05), below the 1/√N ≈ 0.06 typical of 300 random headings.
#[test]
fn the_flock_starts_with_polarisation_a_few_hundredths() {
    let f = FlockFigure::new();
    let phi = f.polarisation();
    assert_eq!(f.flock().positions.len(), 300);
    assert!((0.005..0.05).contains(&phi), "φ at the start: {phi}");
}

/// Each steering arrow's shaft leaves the wide heading arrow (the boid's velocity, 0.5 m long):
/// a rule that points along the heading and ends inside it is hidden by it. At the defaults the
/// cohesion points ahead, and at the Try this's 90° field of view all three come from ahead.
#[test]
fn the_rules_figures_steering_arrows_reach_past_the_heading() {
    use inbetween::draw::palette;
    for fov in [270.0, 90.0] {
        let mut scene = RulesFigure::new();
        scene.set_fov_deg(fov).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame);
        let heading = frame
            .strokes
            .iter()
            .find(|s| s.width_px == HEADING_PX && s.color[..3] == palette::ORANGE.to_array())
            .expect("the heading");
        let (a, b) = (Vec3::from(heading.a), Vec3::from(heading.b));
        for (color, name) in [
            (palette::GREEN, "cohesion"),
            (palette::PINK, "alignment"),
            (palette::RED, "separation"),
        ] {
            let shaft = frame
                .strokes
                .iter()
                .find(|s| s.color[..3] == color.to_array())
                .expect(name);
            let end = Vec3::from(shaft.b) * Vec3::new(1.0, 0.0, 1.0);
            let t = ((end - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            let off = (end - a.lerp(b, t)).length();
            assert!(off > 0.1, "fov {fov}: {name}'s shaft ends {off} m from the heading");
        }
    }
}
