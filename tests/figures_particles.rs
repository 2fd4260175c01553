//! Native tests of lesson 11's figures (src/figures/particles.rs): what they draw, what they
//! reject, and what their notes say about the student's exercises.

#[path = "support/canvas.rs"]
mod canvas;
use canvas::on_canvas;
use glam::Vec3;
use inbetween::draw::Frame;
use inbetween::exercises::run::{direct, Failure, Flat};
use inbetween::figures::particles::*;
use inbetween::particles;

fn reference(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
    let mut out = Vec::new();
    match name {
        "time_of_impact" => inbetween::exercises::particles::reference_time_of_impact(
            args[0], args[1], args[2], args[3],
        )
        .put(&mut out),
        "semi_implicit_euler_step" => {
            inbetween::exercises::particles::reference_semi_implicit(v(0), v(3), v(6), args[9])
                .put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

/// Typical mistakes: the earlier (negative) root; explicit Euler instead of semi-implicit.
fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
    let mut out = Vec::new();
    match name {
        "time_of_impact" => {
            let (y, vy, g, f) = (args[0], args[1], args[2], args[3]);
            ((-vy + (vy * vy - 2.0 * g * (y - f)).sqrt()) / g).put(&mut out)
        }
        "semi_implicit_euler_step" => {
            let (p, vel, a, dt) = (v(0), v(3), v(6), args[9]);
            (p + vel * dt, vel + a * dt).put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

fn stub(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::NotDone)
}

fn panics(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::Panicked(
        "panicked at src/exercises/particles.rs:40:9:\nattempt to divide by zero".into(),
    ))
}

/// How many of the live particles came from emitter `index`, and how many of those were born in
/// the last step.
fn from_emitter(scene: &EmitterFigure, index: u16) -> (usize, usize) {
    let sys = scene.system();
    let n = sys.len();
    let mine = (0..n).filter(|&i| sys.emitter_of[i] == index);
    let all = mine.clone().count();
    let newborn = mine.filter(|&i| sys.ages[i] <= SIM_DT * 1.01).count();
    (all, newborn)
}

#[test]
fn a_fast_fountain_keeps_flowing_beside_the_explosions() {
    // At 1000 particles/s in "both" mode, with particles living 10 s: every step of the fountain
    // emits its 1000 / 60 particles, each emitter stays inside its share, the system is never
    // full, and an explosion is the burst size it asks for. (A burst of 2 × the rate would take
    // all 2000 slots and stop the fountain until the sparks die; a fountain allowed to fill every
    // slot would then spurt only as particles die.)
    let mut scene = EmitterFigure::new();
    scene.set_mode("both").unwrap();
    scene.set_rate(1000.0).unwrap();
    scene.set_lifetime(10.0).unwrap();
    let eye = Vec3::new(0.0, 2.0, 6.0);
    scene.advance_to(SIM_DT).unwrap();
    assert_eq!(
        from_emitter(&scene, 1).0,
        400,
        "one explosion: its burst size"
    );
    for k in 1..=480 {
        scene.advance_to(k as f32 * SIM_DT).unwrap();
        let (fountain, born) = from_emitter(&scene, 0);
        let (sparks, _) = from_emitter(&scene, 1);
        assert!(
            (16..=17).contains(&born),
            "step {k}: the fountain emitted {born} (1000/s is 16.7 a step)"
        );
        assert!(
            fountain <= FOUNTAIN_SLOTS && sparks <= EXPLOSION_SLOTS,
            "step {k}: {fountain} + {sparks}"
        );
        assert!(scene.len() < PAGE_MAX_PARTICLES, "step {k}: full");
    }
    // The shortened lifetime is rate × 1.2 l + a step within the fountain's slots, and said.
    let l = scene.lifetime_sec();
    assert!(
        l < 1.0 && 1000.0 * (1.2 * l + SIM_DT) + 1.0 <= FOUNTAIN_SLOTS as f32,
        "{l}"
    );
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, eye, Vec3::ZERO, 8.0).unwrap();
    assert!(
        note.contains("Of the 2,000 slots here (the core allows 100,000), 1,200 are the fountain's and 800 the explosions'"),
        "{note}"
    );
    assert!(
        note.contains("A stream of 1,000 particles/s living 10.00 s would need about 10,000 slots"),
        "{note}"
    );
    assert!(
        note.contains(&format!("its particles live {l:.2} s")),
        "{note}"
    );
    // The note's numbers check out: the span the fountain's slots hold is 1.2 × the lifetime,
    // within those slots at the rate, and no more than a step and two slots short of them.
    let hold = format!("{:.2}", 1.2 * l);
    assert!(
        note.contains(&format!("The fountain's 1,200 hold {hold} s of it")),
        "{note}"
    );
    let hold: f32 = hold.parse().unwrap();
    let span = FOUNTAIN_SLOTS as f32 / 1000.0;
    assert!(hold <= span && hold >= span - SIM_DT - 0.002 - 0.005, "{hold}");
    // The dashed guide the note names is the plot's: rate × the lifetime the particles live.
    let guide = scene.count_samples()[3];
    assert!(
        note.contains(&format!("rate × lifetime (the plot's dashed guide) is {}", (1000.0 * l).round() as usize)),
        "{note}"
    );
    assert!((guide - 1000.0 * l).abs() < 0.5, "guide {guide}, lifetime {l}");
    assert!(!note.contains("by hand"), "{note}");
    for p in &frame.points {
        assert!(p.center[1] >= 0.0, "nothing below the floor");
    }
    // Stepped on the GPU the figure has the same shares and says the same.
    let gpu_note = scene.draw_gpu(&mut Frame::default());
    assert!(gpu_note.contains(&scene.budget_note()), "{gpu_note}");
    assert!(gpu_note.contains("its particles live"), "{gpu_note}");
    // A slow fountain keeps the slider's lifetime and says nothing about it.
    scene.set_rate(200.0).unwrap();
    scene.set_lifetime(2.5).unwrap();
    assert_eq!(scene.lifetime_sec(), 2.5);
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.0)
        .unwrap();
    assert!(!note.contains("would need"), "{note}");
    // In "explosion" mode the explosions have every slot.
    scene.set_mode("explosion").unwrap();
    assert_eq!(scene.slots(), (0, PAGE_MAX_PARTICLES));
    assert!(scene
        .set_burst(MAX_BURST as f32 + 1.0)
        .unwrap_err()
        .contains("per explosion"));
}

#[test]
fn an_explosion_gets_what_is_left_of_its_slots_and_a_press_spawns_once() {
    let eye = Vec3::new(0.0, 2.0, 6.0);
    // "both": the automatic explosion at t = 0 takes 400 of the explosions' 800 slots; a press
    // at 1 s (its sparks live up to 3 s) gets the other 400, one at 1.5 s none, and the note
    // says why.
    let mut scene = EmitterFigure::new();
    scene.set_mode("both").unwrap();
    scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.0)
        .unwrap();
    scene.explode();
    assert_eq!(from_emitter(&scene, 1).0, 800);
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.5)
        .unwrap();
    assert!(!note.contains("The last explosion got"), "{note}");
    scene.explode();
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.5)
        .unwrap();
    assert!(
        note.contains("The last explosion got 0 of its 400 particles")
            && note.contains("Explosions set off by hand: 2."),
        "{note}"
    );
    // A press while paused spawns at once, and only once: playing on from there gives what a
    // replay from the start gives (the step it was pressed before does not spawn it again).
    let mut live = EmitterFigure::new();
    live.draw(&mut Frame::default(), eye, Vec3::ZERO, 1.0)
        .unwrap();
    live.explode();
    assert_eq!(from_emitter(&live, 1).0, 400);
    let mut f1 = Frame::default();
    live.draw(&mut f1, eye, Vec3::ZERO, 1.2).unwrap();
    assert_eq!(from_emitter(&live, 1).0, 400, "spawned once");
    let mut f2 = Frame::default();
    live.draw(&mut Frame::default(), eye, Vec3::ZERO, 0.0)
        .unwrap();
    live.draw(&mut f2, eye, Vec3::ZERO, 1.2).unwrap();
    assert_eq!(
        f1.fingerprint(),
        f2.fingerprint(),
        "a replay shows the same"
    );
}

#[test]
fn sorted_sprites_are_drawn_back_to_front() {
    let mut scene = EmitterFigure::new();
    let eye = Vec3::new(0.0, 2.0, 5.0);
    let mut frame = Frame::default();
    scene.draw(&mut frame, eye, Vec3::ZERO, 1.0).unwrap();
    // Depth along the view direction (the camera looks at the origin), deepest first.
    let forward = (-eye).normalize();
    let d: Vec<f32> = frame
        .points
        .iter()
        .map(|p| (Vec3::from(p.center) - eye).dot(forward))
        .collect();
    assert!(d.len() > 50);
    assert!(d.windows(2).all(|w| w[0] >= w[1]), "deepest first");
    scene.set_sort(false);
    let mut frame = Frame::default();
    scene.draw(&mut frame, eye, Vec3::ZERO, 1.0).unwrap();
    let d: Vec<f32> = frame
        .points
        .iter()
        .map(|p| (Vec3::from(p.center) - eye).dot(forward))
        .collect();
    assert!(
        !d.windows(2).all(|w| w[0] >= w[1]),
        "storage order is not depth order"
    );
    // Fading: alpha below 1 for old particles unless fading is off.
    assert!(frame.points.iter().any(|p| p.color[3] < 0.9));
    scene.set_fade(false);
    let mut frame = Frame::default();
    scene.draw(&mut frame, eye, Vec3::ZERO, 1.0).unwrap();
    assert!(frame.points.iter().all(|p| p.color[3] == 1.0));
}

#[test]
fn the_emitter_figure_rejects_bad_input() {
    let mut scene = EmitterFigure::new();
    assert!(scene.set_rate(-1.0).unwrap_err().contains("rate"));
    assert!(scene.set_rate(f32::NAN).unwrap_err().contains("rate"));
    assert!(scene.set_lifetime(0.0).unwrap_err().contains("lifetime"));
    assert!(scene.set_mode("volcano").unwrap_err().contains("volcano"));
    assert!(scene.set_gravity(f32::INFINITY).is_err());
    // A time that is NaN, negative or past the limit is refused (no endless replay).
    let mut frame = Frame::default();
    for t in [f32::NAN, -1.0, MAX_SIM_TIME + 1.0] {
        assert!(scene
            .draw(&mut frame, Vec3::Z, Vec3::ZERO, t)
            .unwrap_err()
            .contains("time"));
    }
}

#[test]
fn a_paused_figure_stands_still_and_a_scrub_replays_exactly() {
    let mut a = EmitterFigure::new();
    a.set_mode("both").unwrap();
    let eye = Vec3::new(0.0, 2.0, 5.0);
    let mut f1 = Frame::default();
    a.draw(&mut f1, eye, Vec3::ZERO, 3.0).unwrap();
    let mut f2 = Frame::default();
    a.draw(&mut f2, eye, Vec3::ZERO, 3.0).unwrap();
    assert_eq!(
        f1.fingerprint(),
        f2.fingerprint(),
        "the same time draws the same frame"
    );
    // Going forward in small steps or jumping, or back and forward again: the same state.
    let mut b = EmitterFigure::new();
    b.set_mode("both").unwrap();
    for k in 0..=30 {
        b.draw(&mut Frame::default(), eye, Vec3::ZERO, 0.1 * k as f32)
            .unwrap();
    }
    b.draw(&mut Frame::default(), eye, Vec3::ZERO, 0.5).unwrap();
    let mut f3 = Frame::default();
    b.draw(&mut f3, eye, Vec3::ZERO, 3.0).unwrap();
    assert_eq!(f1.fingerprint(), f3.fingerprint());
    // A changed parameter replays with the new value: the frame at the same time changes.
    a.set_restitution(0.1).unwrap();
    let mut f4 = Frame::default();
    a.draw(&mut f4, eye, Vec3::ZERO, 3.0).unwrap();
    assert_ne!(f1.fingerprint(), f4.fingerprint());
}

#[test]
fn free_fall_errors_grow_linearly_for_euler_and_stay_zero_for_verlet() {
    let mut scene = FreeFallFigure::new();
    scene.set_dt(0.1).unwrap();
    let s = scene.error_samples();
    let rows: Vec<&[f32]> = s.chunks(4).collect();
    let last = rows[rows.len() - 1];
    let t = last[0];
    // Both Euler variants are off by g t dt / 2, Verlet by rounding only. The samples are signed
    // heights above the parabola: explicit Euler (the old velocity) is above it, semi-implicit
    // Euler (the new one) as far below, so the plot's two lines do not lie on each other.
    let expected = 9.81 * t * 0.1 / 2.0;
    assert!((last[1] - expected).abs() < 1e-3, "{last:?}");
    assert!((last[2] + expected).abs() < 1e-3, "{last:?}");
    assert!(last[3].abs() < 1e-4);
    for row in &rows[1..] {
        assert!(
            row[1] > 0.0 && row[2] < 0.0,
            "explicit above, semi-implicit below: {row:?}"
        );
    }
    // Halving dt halves the Euler error at the same time.
    let e1 = scene.final_errors();
    scene.set_dt(0.05).unwrap();
    let e2 = scene.final_errors();
    let r = e1.error_m[0] / e2.error_m[0] * (e2.time_sec / e1.time_sec);
    assert!((r - 2.0).abs() < 0.2, "{r}");
    assert!(scene.set_dt(0.0).is_err() && scene.set_dt(f32::NAN).is_err());
}

#[test]
fn free_fall_draws_each_integrator_and_the_exact_path() {
    let scene = FreeFallFigure::new();
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, 0.65).unwrap();
    for c in INTEGRATOR_COLORS.iter().chain([&EXACT_COLOR]) {
        assert!(frame.segments_of(*c).count() > 0, "a path in {c}");
    }
    assert!(
        note.contains("explicit Euler") && note.contains("velocity Verlet"),
        "{note}"
    );
    assert!(scene.draw(&mut frame, f32::NAN).is_err());
}

#[test]
fn free_fall_shows_the_exact_ball_at_the_latest_step() {
    // Between two steps (t = 0.95 s with dt = 0.1 s: the latest step is at 0.9 s) the exact ball
    // is drawn where the parabola is at 0.9 s, so Verlet's dot (exact for gravity) sits on it
    // instead of 5 cm behind it; the note says which side of the parabola each Euler is on.
    let scene = FreeFallFigure::new();
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, 0.95).unwrap();
    let big = |c: glam::Vec3, r: f32| {
        frame
            .points
            .iter()
            .find(|p| p.color[..3] == c.to_array() && (p.radius - r).abs() < 1e-6)
            .map(|p| glam::Vec3::from_array(p.center))
            .unwrap()
    };
    // The exact ball is the larger one and the integrators' balls are drawn over everything:
    // where Verlet's sits on it, the exact ball shows as a dark ring around it.
    assert!(EXACT_BALL_M > 1.5 * STEP_BALL_M);
    let exact = big(EXACT_COLOR, EXACT_BALL_M);
    let verlet = big(INTEGRATOR_COLORS[2], -STEP_BALL_M);
    let expected = particles::free_fall(scene.p0, scene.v0, scene.g, 0.9).0;
    assert!((exact - expected).length() < 1e-4, "{exact} {expected}");
    assert!((exact - verlet).length() < 1e-4, "{exact} {verlet}");
    assert!(note.contains("t = 0.900 s"), "{note}");
    assert!(
        note.contains("explicit Euler is 0.441 m above")
            && note.contains("semi-implicit Euler 0.441 m below")
            && note.contains("velocity Verlet on the parabola"),
        "{note}"
    );
}

#[test]
fn free_fall_says_what_the_students_step_does() {
    let mut scene = FreeFallFigure::new();
    scene.set_use_exercise(true);
    for (runner, expect) in [
        (reference as fn(&str, &[f32]) -> _, "matches the reference"),
        (wrong, "differs at the first step"),
        (stub, "Not done yet: exercise 11.2"),
        (panics, "divide by zero"),
    ] {
        scene.set_runner(runner);
        let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
        assert!(note.contains(expect), "{expect}: {note}");
    }
    // With the wrong (explicit) step, the semi-implicit path is the explicit one.
    scene.set_runner(wrong);
    let s = scene.error_samples();
    let last = &s[s.len() - 4..];
    assert!((last[1] - last[2]).abs() < 1e-5);
}

#[test]
fn bouncing_balls_never_go_through_the_floor_and_predict_their_impact() {
    let mut scene = BounceFigure::new();
    scene.set_runner(reference);
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, 0.0).unwrap();
    assert!(note.contains("reaches the floor in t = "), "{note}");
    let label = frame.labels.iter().find(|l| l.text.starts_with("floor in"));
    let label = label.expect("the impact mark's label");
    // It reads leftwards and ends clear of the ball (radius 0.08 m) that lands on the mark.
    let mark = frame.markers.iter().find(|m| m.center[1] < 0.01).expect("the impact mark");
    assert!(label.left && label.anchor.x < mark.center[0] - 0.1, "{label:?}");
    for k in 0..400 {
        scene.advance_to(k as f32 / 60.0).unwrap();
        for p in scene.positions() {
            assert!(p.y >= 0.08 - 1e-5, "{p}");
        }
    }
    scene.set_use_exercise(true);
    scene.drop_balls();
    for (runner, expect) in [
        (reference as fn(&str, &[f32]) -> _, "matches the reference"),
        (wrong, "differs at y0 = "),
        (stub, "Not done yet: exercise 11.1"),
    ] {
        scene.set_runner(runner);
        let note = scene.draw(&mut Frame::default(), 0.0).unwrap();
        assert!(note.contains(expect), "{expect}: {note}");
    }
    assert!(scene.set_restitution(1.5).is_err() && scene.set_friction(f32::NAN).is_err());
}

#[test]
fn dropped_from_rest_the_prediction_is_the_formula() {
    let mut scene = BounceFigure::new();
    scene.set_runner(reference);
    let note = scene.draw(&mut Frame::default(), 0.0).unwrap();
    // Ball 0 starts at y = 2.2 with radius 0.08: t = √(2 (2.2 − 0.08) / 9.81).
    let t = (2.0f32 * 2.12 / 9.81).sqrt();
    let t2 = particles::floor_time_of_impact(2.2, 0.0, -9.81, 0.08, 10.0).unwrap();
    assert!((t - t2).abs() < 1e-5);
    assert!(note.contains(&format!("{t:.3}")), "{note}");
}

#[test]
fn the_squash_ball_keeps_its_volume() {
    let mut scene = SquashFigure::new();
    let mut squashed = false;
    for k in 0..200 {
        let note = scene.draw(&mut Frame::default(), k as f32 / 60.0).unwrap();
        assert!(note.contains("volume stays 1.000"), "{note}");
        squashed |= scene.stretch().1 < 0.9;
    }
    assert!(squashed);
    assert!(scene.set_squash(0.9).is_err() && scene.set_stretch(-0.1).is_err());
}

#[test]
fn the_bounce_camera_starts_with_every_ball_and_the_sphere_in_view() {
    // The page's bounce canvas at 800 x 600 and 1600 x 1000 (760 x 420 and 650 x 420 CSS px).
    // Every ball is dropped from up to 3.1 m; a camera aimed 0.9 m up from 4.5 m away would cut
    // the highest ones off.
    let mut scene = BounceFigure::new();
    scene.advance_to(0.0).unwrap();
    let view = scene.view();
    for (w, h) in crate::label_clearance::CANVASES.map(|s| (s.x, s.y)) {
        let mut points: Vec<Vec3> = Vec::new();
        for p in scene.positions() {
            points.push(*p + Vec3::Y * 0.08);
            points.push(*p - Vec3::Y * 0.08);
        }
        // The sphere (centre 0.6 m up, radius 0.6 m), and the floor under the drop.
        points.extend([
            Vec3::new(0.0, 1.2, 0.0),
            Vec3::new(-0.6, 0.6, 0.0),
            Vec3::new(0.6, 0.6, 0.0),
        ]);
        points.extend([Vec3::new(-1.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0)]);
        for p in points {
            let s = on_canvas(view, w, h, p);
            assert!(
                s.x > 5.0 && s.x < w - 5.0 && s.y > 5.0 && s.y < h - 5.0,
                "{p} lands at {s} on a {w} x {h} canvas"
            );
        }
    }
}

#[test]
fn the_squash_figures_labels_never_overlap() {
    // Labels are HTML over the canvas, running rightwards from 0.35em right of their anchor
    // (www/style.css: 600 0.8rem, so about 7.7 px a character and 15 px high). At the page's
    // camera, both canvas sizes (760 x 420 at 800 x 600, 650 x 420 at 1600 x 1000), every frame
    // of the 4 s timeline and the sliders' extremes, the two boxes stay apart and on the canvas
    // (the balls drift +x by 2.4 m over the timeline: with the camera's target at x = −0.6 m
    // the long label would run off the 650 px canvas's right edge); with "squash and stretch"
    // on the left ball it would run into "rigid".
    let boxes = |frame: &Frame, view: [f32; 6], w: f32, h: f32| {
        frame
            .labels
            .iter()
            .map(|l| {
                let s = on_canvas(view, w, h, l.anchor);
                let x0 = s.x + 4.5;
                (
                    x0,
                    s.y - 9.0,
                    x0 + 7.7 * l.text.chars().count() as f32,
                    s.y + 6.0,
                )
            })
            .collect::<Vec<_>>()
    };
    for (k, squash, contact) in [
        (0.06f32, 0.45f32, 0.09f32),
        (0.3, 0.8, 0.3),
        (0.0, 0.0, 0.02),
    ] {
        let mut scene = SquashFigure::new();
        scene.set_stretch(k).unwrap();
        scene.set_squash(squash).unwrap();
        scene.set_contact(contact).unwrap();
        let view = scene.view();
        for step in 0..=240 {
            let mut frame = Frame::default();
            scene.draw(&mut frame, step as f32 / 60.0).unwrap();
            assert_eq!(frame.labels.len(), 2);
            for (w, h) in crate::label_clearance::CANVASES.map(|s| (s.x, s.y)) {
                let b = boxes(&frame, view, w, h);
                let apart =
                    b[0].2 < b[1].0 || b[1].2 < b[0].0 || b[0].3 < b[1].1 || b[1].3 < b[0].1;
                assert!(apart, "t = {} s, {w} x {h}: {b:?}", step as f32 / 60.0);
                for r in &b {
                    assert!(
                        r.0 > 10.0 && r.2 < w - 10.0 && r.1 > 0.0 && r.3 < h,
                        "on the canvas, 10 px from its sides: {r:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_squash_plot_follows_the_figure() {
    // The plot's samples are the figure's own stretch factor at each step of the timeline: a
    // stretch (s > 1) in flight, a squash (s < 1) after each impact, and the change of a slider
    // shows in them.
    let mut scene = SquashFigure::new();
    let samples = scene.plot_samples();
    let rows: Vec<&[f32]> = samples.chunks(2).collect();
    assert_eq!(rows.len(), (SQUASH_DURATION * 60.0).round() as usize + 1);
    for k in [0usize, 30, 61, 62, 100, 170, 240] {
        scene.advance_to(k as f32 / 60.0).unwrap();
        assert!((rows[k][0] - k as f32 / 60.0).abs() < 1e-5);
        assert!(
            (rows[k][1] - scene.stretch().1).abs() < 1e-6,
            "step {k}: {:?} vs {:?}",
            rows[k],
            scene.stretch()
        );
    }
    assert!(
        rows.iter().any(|r| r[1] > 1.05) && rows.iter().any(|r| r[1] < 0.7),
        "stretches and squashes"
    );
    scene.set_squash(0.0).unwrap();
    assert!(
        scene.plot_samples().chunks(2).all(|r| r[1] >= 1.0),
        "no squash at 0"
    );
}

#[test]
fn at_e_1_and_mu_0_the_balls_stay_in_their_box_and_in_view() {
    // Without walls nothing slows a ball that the sphere sent sideways at e = 1, μ = 0: it would
    // leave the canvas within the 6 s timeline. The glass box's walls bounce it back, exactly (no
    // energy is gained or lost at e = 1), so every ball and the box stay in view at both canvas
    // sizes for as long as the figure simulates.
    let mut scene = BounceFigure::new();
    scene.set_restitution(1.0).unwrap();
    scene.set_friction(0.0).unwrap();
    let view = scene.view();
    let energy = |p: Vec3, v: Vec3| 0.5 * v.length_squared() + 9.81 * p.y;
    scene.advance_to(0.0).unwrap();
    let e0: Vec<f32> = scene
        .positions()
        .iter()
        .map(|&p| energy(p, Vec3::ZERO))
        .collect();
    let mut went_sideways = false;
    let inner = BOX_HALF_M - 0.08;
    for k in 0..=(20 * 60) {
        scene.advance_to(k as f32 / 60.0).unwrap();
        for (i, p) in scene.positions().iter().enumerate() {
            assert!(
                p.x.abs() <= inner + 1e-4 && p.z.abs() <= inner + 1e-4 && p.y >= 0.08 - 1e-4,
                "step {k}, ball {i} at {p}"
            );
            went_sideways |= p.x.abs() > 1.0;
            for (w, h) in crate::label_clearance::CANVASES.map(|s| (s.x, s.y)) {
                let s = on_canvas(view, w, h, *p);
                assert!(
                    s.x > 5.0 && s.x < w - 5.0 && s.y > 5.0 && s.y < h - 5.0,
                    "step {k}: ball {i} at {p} lands at {s} on a {w} x {h} canvas"
                );
            }
        }
        if k % 60 == 0 {
            // Energy per unit mass: kept by every bounce (the velocities are not public, so the
            // ball's height at rest is checked instead: it never rises above where it started).
            for (i, p) in scene.positions().iter().enumerate() {
                assert!(
                    9.81 * p.y <= e0[i] + 1e-2,
                    "ball {i} above its drop height: {p}"
                );
            }
        }
    }
    assert!(went_sideways, "some ball is thrown towards the walls");
    // The box is in view too.
    for x in [-BOX_HALF_M, BOX_HALF_M] {
        for z in [-BOX_HALF_M, BOX_HALF_M] {
            for y in [0.0, BOX_DRAWN_HEIGHT_M] {
                for (w, h) in crate::label_clearance::CANVASES.map(|s| (s.x, s.y)) {
                    let s = on_canvas(view, w, h, Vec3::new(x, y, z));
                    assert!(
                        s.x > 0.0 && s.x < w && s.y > 0.0 && s.y < h,
                        "box corner ({x}, {y}, {z}) lands at {s} on a {w} x {h} canvas"
                    );
                }
            }
        }
    }
}

/// What the page's `apply()` does after every control, the "explode now" button included
/// (lil-gui calls the panel's onChange for a button too): every setter with the values it has.
fn apply_unchanged(scene: &mut EmitterFigure, mode: &str) {
    scene.set_mode(mode).unwrap();
    scene.set_rate(200.0).unwrap();
    scene.set_burst(400.0).unwrap();
    scene.set_spread_deg(11.0).unwrap();
    scene.set_lifetime(2.5).unwrap();
    scene.set_restitution(0.7).unwrap();
    scene.set_gravity(9.81).unwrap();
    scene.set_sort(true);
    scene.set_fade(true);
}

#[test]
fn explode_now_while_paused_shows_its_sparks_at_once() {
    // "Explode now" on a paused figure shows its sparks at once, although the button's onChange
    // re-applies every control: setting a value it already has is no change (no replay), and a
    // replay spawns the presses of the step it stops at (it does not stop short of them).
    let eye = Vec3::new(0.0, 2.0, 6.0);
    let mut scene = EmitterFigure::new();
    scene.set_spread_deg(11.0).unwrap();
    scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.8)
        .unwrap();
    assert_eq!(from_emitter(&scene, 1).0, 0);
    scene.explode();
    apply_unchanged(&mut scene, "fountain");
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.8)
        .unwrap();
    assert_eq!(from_emitter(&scene, 1).0, 400, "{note}");
    // A real change replays from the start and still shows the press, once.
    scene.set_restitution(0.5).unwrap();
    scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.8)
        .unwrap();
    assert_eq!(from_emitter(&scene, 1).0, 400);
    scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.9)
        .unwrap();
    assert_eq!(from_emitter(&scene, 1).0, 400, "spawned once");
}

#[test]
fn the_free_fall_plot_ends_where_the_timeline_does() {
    // The last sample is the figure's state at the end of the timeline: at dt = 0.3 s a fifth
    // step, at 1.5 s, lies past the timeline's 1.3 s and is never drawn, so it is not plotted.
    for dt in [0.01, 0.05, 0.07, 0.1, 0.25, 0.3] {
        let mut scene = FreeFallFigure::new();
        scene.set_dt(dt).unwrap();
        let s = scene.error_samples();
        let last = &s[s.len() - 4..];
        assert!(last[0] <= FREE_FALL_DURATION + 1e-4, "dt {dt}: {last:?}");
        let steps = s.len() / 4 - 1;
        let note = scene
            .draw(&mut Frame::default(), FREE_FALL_DURATION)
            .unwrap();
        let named = if steps == 1 { "step" } else { "steps" };
        assert!(
            note.starts_with(&format!("After {steps} {named} ")),
            "dt {dt}: {note}"
        );
        let explicit = format!("explicit Euler is {:.3} m above", last[1]);
        assert!(note.contains(&explicit), "dt {dt}: {note} / {explicit}");
    }
    // One step is one step.
    let mut scene = FreeFallFigure::new();
    scene.set_dt(0.3).unwrap();
    let note = scene.draw(&mut Frame::default(), 0.3).unwrap();
    assert!(note.starts_with("After 1 step of dt"), "{note}");
}

#[test]
fn the_stretch_is_capped_and_its_peaks_shrink_below_the_cap() {
    // The text: s = 1 + k |v| up to 1.6; the plot's peaks shrink with the bounces, except where
    // the cap flattens them (k = 0.3 reaches it before the first impact).
    let peaks = |k: f32| {
        let mut scene = SquashFigure::new();
        scene.set_stretch(k).unwrap();
        let s: Vec<f32> = scene.plot_samples().chunks(2).map(|r| r[1]).collect();
        let peaks: Vec<f32> = s
            .windows(3)
            .filter(|w| w[0] > 1.0 && w[1] > w[0] && w[1] >= w[2])
            .map(|w| w[1])
            .collect();
        (s.iter().cloned().fold(0.0, f32::max), peaks)
    };
    let (top, p) = peaks(0.06);
    assert!(top < 1.6 && p.len() >= 4, "{top} {p:?}");
    assert!(p.windows(2).all(|w| w[1] < w[0]), "shrinking peaks {p:?}");
    let (top, p) = peaks(0.3);
    assert!((top - 1.6).abs() < 1e-6, "capped at 1.6: {top} {p:?}");
}

#[test]
fn at_e_0_the_orange_ball_stops_dead_and_floor_balls_slide_until_friction_stops_them() {
    let mut scene = BounceFigure::new();
    scene.set_restitution(0.0).unwrap();
    scene.set_friction(0.1).unwrap();
    scene.advance_to(0.7).unwrap();
    let at_rest = scene.positions()[0];
    assert!((at_rest.y - 0.08).abs() < 1e-5, "{at_rest}");
    scene.advance_to(5.5).unwrap();
    let before = scene.positions().to_vec();
    scene.advance_to(6.0).unwrap();
    assert_eq!(
        scene.positions()[0],
        at_rest,
        "the orange ball never moves again"
    );
    for (a, b) in before.iter().zip(scene.positions()) {
        if (a.y - 0.08).abs() < 1e-5 {
            assert_eq!(a, b, "a ball on the floor has stopped sliding");
        }
    }
    // Without friction a ball on the floor slides on (until a wall stops it, e = 0).
    scene.set_friction(0.0).unwrap();
    scene.advance_to(1.5).unwrap();
    let a = scene.positions().to_vec();
    scene.advance_to(1.6).unwrap();
    let sliding = a
        .iter()
        .zip(scene.positions())
        .any(|(a, b)| (a.y - 0.08).abs() < 1e-5 && (b.y - 0.08).abs() < 1e-5 && a != b);
    assert!(sliding, "{a:?}");
}

#[test]
fn the_try_this_explosions_fill_their_share_and_the_note_says_so() {
    // The Try this: "both", 1,000/s, 6 s. The automatic explosion at 0 s and a press at 0.5 s
    // fill the explosions' 800 slots; a press at 0.6 s gets none of its 400, and the note says so.
    let eye = Vec3::new(0.0, 2.0, 6.0);
    let mut scene = EmitterFigure::new();
    scene.set_mode("both").unwrap();
    scene.set_rate(1000.0).unwrap();
    scene.set_lifetime(6.0).unwrap();
    assert!((scene.lifetime_sec() - 0.98).abs() < 0.01);
    scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 0.5)
        .unwrap();
    scene.explode();
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 0.6)
        .unwrap();
    assert!(!note.contains("The last explosion got"), "{note}");
    scene.explode();
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 0.6)
        .unwrap();
    assert!(
        note.contains("The last explosion got 0 of its 400 particles"),
        "{note}"
    );
    // Away from the automatic ones (0 s and 2.5 s; sparks live under 1.2 s): three presses give
    // 400, 400 and nothing.
    let mut scene = EmitterFigure::new();
    scene.set_mode("both").unwrap();
    scene.set_rate(1000.0).unwrap();
    scene.set_lifetime(6.0).unwrap();
    let mut got = Vec::new();
    for t in [1.5, 1.6, 1.7] {
        scene
            .draw(&mut Frame::default(), eye, Vec3::ZERO, t)
            .unwrap();
        let alive = from_emitter(&scene, 1).0;
        scene.explode();
        got.push(from_emitter(&scene, 1).0 - alive);
    }
    assert_eq!(got, [400, 400, 0]);
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.7)
        .unwrap();
    assert!(
        note.contains("The last explosion got 0 of its 400 particles"),
        "{note}"
    );
}

#[test]
fn the_bounce_plot_follows_the_orange_ball_and_its_energy_never_grows() {
    // [t, h, E / (m g)] per step over the timeline; the energy height is flat in flight, drops
    // by about e² at each bounce of the straight drop, and stays flat at e = 1, μ = 0.
    let energies = |e: f32, mu: f32| {
        let mut f = BounceFigure::new();
        f.set_restitution(e).unwrap();
        f.set_friction(mu).unwrap();
        let s = f.plot_samples();
        assert_eq!(s.len() % 3, 0);
        let rows: Vec<[f32; 3]> = s.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
        assert_eq!(rows.len(), (BOUNCE_DURATION / SIM_DT).round() as usize + 1);
        assert!((rows.last().unwrap()[0] - BOUNCE_DURATION).abs() < 1e-3);
        // The samples are the figure's own states.
        f.advance_to(1.0).unwrap();
        let p = f.positions()[0];
        assert!(
            (rows[60][1] - (p.y - 0.08)).abs() < 1e-6,
            "{:?} {p}",
            rows[60]
        );
        rows
    };
    for (e, mu) in [(0.75, 0.1), (0.3, 0.5), (1.0, 0.0), (0.0, 0.0)] {
        let rows = energies(e, mu);
        let start = rows[0][2];
        assert!((start - rows[0][1]).abs() < 1e-6, "dropped at rest");
        for w in rows.windows(2) {
            assert!(w[1][2] <= w[0][2] + 1e-4, "e {e} μ {mu}: energy grew {w:?}");
            assert!(w[1][1] >= -1e-4, "below the floor {w:?}");
        }
        if e == 1.0 {
            let last = rows.last().unwrap()[2];
            assert!((last - start).abs() < 1e-3 * start, "{start} -> {last}");
            // It bounces back to its drop height.
            let late_top = rows[200..].iter().map(|r| r[1]).fold(0.0, f32::max);
            assert!((late_top - start).abs() < 0.01, "{late_top} vs {start}");
        }
    }
    // The first bounce keeps e² of the energy (measured just before and after it).
    let rows = energies(0.75, 0.1);
    let k = rows.iter().position(|r| r[2] < 0.99 * rows[0][2]).unwrap();
    let ratio = rows[k][2] / rows[k - 1][2];
    assert!((ratio - 0.5625).abs() < 0.01, "kept {ratio}");
}

#[test]
fn emitter_sprites_stay_visible_until_the_second_half_of_their_life() {
    // The fountain and the sparks show clearly at the defaults: the atlas thins each puff out
    // with age, so sprites do not take the colour's alpha, falling over the whole life, on top as
    // it is (puffs past mid-life would be faint), but its square root, which falls later; and
    // they are 2.6 times the disc (at 1.8 they are specks).
    let eye = Vec3::new(0.0, 2.0, 6.0);
    let mut scene = EmitterFigure::new();
    scene.set_mode("both").unwrap();
    scene.set_sprite_texture(Some(inbetween::draw::TextureId(0)));
    let mut frame = Frame::default();
    scene.draw(&mut frame, eye, Vec3::ZERO, 1.5).unwrap();
    let sys = scene.system();
    assert_eq!(frame.sprites.len(), sys.len());
    let mut young = 0;
    for (k, s) in frame.sprites.iter().enumerate() {
        // Sorted back to front: find the particle by its centre.
        let i = (0..sys.len())
            .find(|&i| sys.positions[i].to_array() == s.center)
            .unwrap_or_else(|| panic!("sprite {k} has no particle"));
        let life = sys.ages[i] / sys.lifetimes[i];
        assert!((s.half_size - SPRITE_SCALE * sys.sizes[i]).abs() < 1e-6);
        let core_alpha = sys.colors[i].w;
        assert!((s.color[3] - core_alpha.sqrt()).abs() < 1e-6);
        if life < 0.5 {
            young += 1;
            assert!(s.color[3] > 0.7, "life {life}: alpha {}", s.color[3]);
        }
        assert!(s.color[3] >= core_alpha);
    }
    assert!(young > 100, "{young}");
    assert!(
        frame.sprites.iter().any(|s| s.color[3] < 0.7),
        "the old ones fade"
    );
}

#[test]
fn presses_at_two_moments_of_one_step_both_explode_and_replay() {
    // The page's timeline moves 6 ms a notch (1,000 notches over 6 s), a step is 1/60 s: a
    // press after a move of one notch lands in the step of the press before. It is a press
    // of its own (its own explosion at that step), not "an explosion was set off at this
    // moment already".
    let eye = Vec3::new(0.0, 2.0, 6.0);
    let (t1, t2) = (1.5, 1.506);
    assert_eq!(steps_to(t1).unwrap(), steps_to(t2).unwrap(), "one step");
    let mut live = EmitterFigure::new();
    live.draw(&mut Frame::default(), eye, Vec3::ZERO, t1).unwrap();
    live.explode();
    live.draw(&mut Frame::default(), eye, Vec3::ZERO, t2).unwrap();
    live.explode();
    let note = live
        .draw(&mut Frame::default(), eye, Vec3::ZERO, t2)
        .unwrap();
    assert!(
        note.contains("set off by hand: 2.") && !note.contains("did nothing"),
        "{note}"
    );
    assert_eq!(from_emitter(&live, 1).0, 800, "two explosions of 400");
    // Played on, and replayed from the start: the same particles.
    let mut f1 = Frame::default();
    live.draw(&mut f1, eye, Vec3::ZERO, 2.0).unwrap();
    live.draw(&mut Frame::default(), eye, Vec3::ZERO, 0.5)
        .unwrap();
    let mut f2 = Frame::default();
    live.draw(&mut f2, eye, Vec3::ZERO, 2.0).unwrap();
    assert_eq!(from_emitter(&live, 1).0, 800);
    assert_eq!(f1.fingerprint(), f2.fingerprint(), "a replay shows the same");
    // A replay that stops at their step spawns both.
    live.draw(&mut Frame::default(), eye, Vec3::ZERO, 0.5)
        .unwrap();
    live.draw(&mut Frame::default(), eye, Vec3::ZERO, t1).unwrap();
    assert_eq!(from_emitter(&live, 1).0, 800);
}

#[test]
fn a_second_press_at_the_same_moment_says_why_it_did_nothing() {
    // "Explode now" twice on a paused figure: the note says why the second press did nothing,
    // not only "Explosions set off by hand: 1.".
    let eye = Vec3::new(0.0, 2.0, 6.0);
    let mut scene = EmitterFigure::new();
    scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.5)
        .unwrap();
    scene.explode();
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.5)
        .unwrap();
    assert!(
        note.contains("set off by hand: 1.") && !note.contains("did nothing"),
        "{note}"
    );
    scene.explode();
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.5)
        .unwrap();
    assert!(note.contains("set off by hand: 1."), "{note}");
    assert!(
        note.contains(
            "The last press did nothing: an explosion was set off at this moment already"
        ),
        "{note}"
    );
    assert!(scene
        .draw_gpu(&mut Frame::default())
        .contains("did nothing"));
    // Once the timeline moves the explanation goes, and a press there counts.
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.6)
        .unwrap();
    assert!(!note.contains("did nothing"), "{note}");
    scene.explode();
    let note = scene
        .draw(&mut Frame::default(), eye, Vec3::ZERO, 1.6)
        .unwrap();
    assert!(
        note.contains("set off by hand: 2.") && !note.contains("did nothing"),
        "{note}"
    );
    // The GPU note writes its slot count as the others do.
    assert!(scene
        .draw_gpu(&mut Frame::default())
        .contains("2,000 slots refilled"));
}

/// Ignores the vertical velocity: right for a ball dropped from rest, wrong for any throw.
fn forgets_vy(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let mut out = Vec::new();
    match name {
        "time_of_impact" => {
            let (y, g, f) = (args[0], args[2], args[3]);
            (2.0 * (y - f) / -g).sqrt().put(&mut out)
        }
        // Only y gets the acceleration: right under gravity alone.
        "semi_implicit_euler_step" => {
            let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
            let (p, vel, a, dt) = (v(0), v(3), v(6), args[9]);
            let w = vel + Vec3::new(0.0, a.y, 0.0) * dt;
            (p + w * dt, w).put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

#[test]
fn the_exercise_notes_check_probe_inputs_beyond_the_figure() {
    // Dropped from rest, the orange ball cannot tell a formula that forgets vy: the note says it
    // matches there and names the throws where it differs.
    let mut bounce = BounceFigure::new();
    bounce.set_use_exercise(true);
    bounce.set_runner(forgets_vy);
    let note = bounce.exercise_note();
    assert!(
        note.contains("matches the reference at y0 = 2.200 m, vy = 0.000 m/s (the figure's input)"),
        "{note}"
    );
    assert!(
        note.contains("a ball thrown up") && note.contains("a ball thrown down"),
        "{note}"
    );
    assert!(
        !note.contains("a floor at 1 m"),
        "a drop from rest is right: {note}"
    );
    bounce.set_runner(reference);
    let note = bounce.exercise_note();
    assert!(note.contains("and at 4 more inputs"), "{note}");
    bounce.set_runner(panics);
    assert!(bounce.exercise_note().contains("divide by zero"));

    // Gravity is vertical in the throw: a step that only accelerates y matches there and
    // differs under the sideways probe.
    let mut fall = FreeFallFigure::new();
    fall.set_runner(forgets_vy);
    let note = fall.exercise_note();
    assert!(note.contains("(the figure's input)"), "{note}");
    assert!(note.contains("sideways parts"), "{note}");
    fall.set_runner(reference);
    assert!(fall.exercise_note().contains("and at 3 more inputs"));
    fall.set_runner(wrong);
    assert!(fall
        .exercise_note()
        .starts_with("Your semi_implicit_euler_step differs at the first step"));
}

#[test]
fn on_a_spring_explicit_euler_gains_energy_and_semi_implicit_euler_does_not() {
    let mut scene = SpringFigure::new();
    let w2 = SPRING_OMEGA * SPRING_OMEGA;
    let dt = SPRING_DEFAULT_DT;
    // Explicit Euler multiplies the energy by exactly 1 + ω² Δt² every step.
    for k in 0..50 {
        let (x0, v0) = scene.state(0, k);
        let (x1, v1) = scene.state(0, k + 1);
        let r = SpringFigure::energy_ratio(x1, v1) / SpringFigure::energy_ratio(x0, v0);
        assert!((r - (1.0 + w2 * dt * dt)).abs() < 1e-5, "step {k}: {r}");
    }
    // The page: "about 7 times its starting energy after 10 s" at Δt = 0.02 s.
    let s = scene.energy_samples();
    let last = &s[s.len() - 4..];
    assert!((last[0] - 10.0).abs() < 1e-3, "{last:?}");
    assert!((6.8..7.6).contains(&last[1]), "explicit Euler {}", last[1]);
    // The caption: it leaves the plot (4 × its energy, the plot's top) after about 7 s.
    let past_top = s.chunks_exact(4).find(|r| r[1] > 4.0).unwrap()[0];
    assert!((6.8..7.3).contains(&past_top), "{past_top}");
    // Semi-implicit Euler stays within 7 % of the start at every step (the page: "within a
    // few per cent"), velocity Verlet within 0.1 %.
    for row in s.chunks_exact(4) {
        assert!((row[2] - 1.0).abs() < 0.07, "semi-implicit {row:?}");
        assert!((row[3] - 1.0).abs() < 1e-3, "Verlet {row:?}");
    }
    // The caption's Δt = 0.1 s: explicit Euler passes 4 × its energy (the plot's top) within
    // 2 s and ends near 12,000 ×; semi-implicit Euler swings by at most a fifth.
    scene.set_dt(0.1).unwrap();
    let s = scene.energy_samples();
    let past_top = s.chunks_exact(4).find(|r| r[1] > 4.0).unwrap()[0];
    assert!(past_top < 2.0, "{past_top}");
    assert!(
        (11_000.0..13_500.0).contains(&s[s.len() - 3]),
        "{}",
        s[s.len() - 3]
    );
    for row in s.chunks_exact(4) {
        assert!((row[2] - 1.0).abs() < 0.2, "semi-implicit at 0.1 s {row:?}");
    }
    // At the largest step the page allows semi-implicit Euler is still bounded (ω Δt < 2), and
    // explicit Euler is far gone.
    scene.set_dt(0.2).unwrap();
    let s = scene.energy_samples();
    for row in s.chunks_exact(4) {
        assert!(row[2] < 1.6, "semi-implicit at 0.2 s {row:?}");
    }
    assert!(s[s.len() - 3] > 1e6);
    // The note gives the ratios and says when explicit Euler's mass is drawn cut.
    let note = scene.draw(&mut Frame::default(), 10.0).unwrap();
    assert!(note.contains("Explicit Euler now swings"), "{note}");
    scene.set_dt(dt).unwrap();
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame, 10.0).unwrap();
    assert!(
        note.contains("After 500 steps") && note.contains("explicit Euler ×7.1"),
        "{note}"
    );
    assert!(!frame.keep_in_view.is_empty());
    assert!(
        scene.set_dt(0.0).is_err() && scene.set_dt(0.3).is_err() && scene.set_dt(f32::NAN).is_err()
    );
    assert!(scene.draw(&mut frame, f32::NAN).is_err());
}

#[test]
fn the_fountain_settles_at_rate_times_lifetime() {
    // At the defaults (200 particles/s, lifetimes uniform around 2.5 s) the fountain's count
    // climbs for about 2.5 s, then holds near 200 × 2.5 = 500, under its 1,200 slots.
    let mut scene = EmitterFigure::new();
    scene.advance_to(5.0).unwrap();
    let s = scene.count_samples();
    assert_eq!(s.len(), 5 * 301);
    let at = |t: f32| &s[5 * (t / SIM_DT).round() as usize..][..5];
    assert!((at(5.0)[0] - 5.0).abs() < 1e-3);
    assert!((at(5.0)[3] - 500.0).abs() < 1.0, "{:?}", at(5.0));
    assert_eq!(at(5.0)[4], FOUNTAIN_SLOTS as f32);
    for t in [3.5, 4.0, 4.5, 5.0] {
        let n = at(t)[1];
        assert!((n - 500.0).abs() < 50.0, "t = {t}: {n}");
    }
    assert!(at(1.0)[1] > 150.0 && at(1.0)[1] < 230.0, "{:?}", at(1.0));
    assert_eq!(at(1.0)[2], 0.0, "no explosion in fountain mode");
    // A press of "explode now" counts at once; a scrub back starts the samples again.
    scene.explode();
    let s = scene.count_samples();
    assert_eq!(s.len(), 5 * 301);
    assert_eq!(s[s.len() - 3], 400.0);
    scene.advance_to(1.0).unwrap();
    assert_eq!(scene.count_samples().len(), 5 * 61);
}

/// The squash figure's balls cast shadows on the floor, one each, once they are low enough
/// (`Frame::shadow_reach`: 1.5 m for these 25 cm balls; they drop from 2 m).
#[test]
fn the_squash_balls_cast_shadows() {
    use inbetween::draw::{Frame, MARKER_SHADOW};
    let mut f = inbetween::figures::particles::SquashFigure::new();
    let mut frame = Frame::default();
    f.draw(&mut frame, 0.6).unwrap();
    let n = frame
        .markers
        .iter()
        .filter(|m| m.shape == MARKER_SHADOW)
        .count();
    assert_eq!(n, 2);
}

/// Figure 6's text: the ball keeps its sideways speed, so at the top of each bounce (where its
/// stretch axis, the velocity, turns from up to down) its stretch stays over 1.
#[test]
fn the_squash_ball_stays_stretched_at_the_top_of_a_bounce() {
    let mut scene = SquashFigure::new();
    for k in [0.06, 0.3] {
        scene.set_stretch(k).unwrap();
        let mut ball = scene.clone();
        let mut tops = 0;
        let mut was_rising = false;
        for i in 0..=(SQUASH_DURATION * 60.0) as usize {
            ball.advance_to(i as f32 / 60.0).unwrap();
            let (axis, s) = ball.stretch();
            if was_rising && axis.y < 0.0 && s >= 1.0 {
                tops += 1;
                assert!(s > 1.0 + 0.5 * k, "k = {k}: s = {s} at a top");
            }
            was_rising = axis.y > 0.0 && s > 1.0;
        }
        assert!(tops >= 2, "k = {k}: {tops} bounce tops");
    }
}

/// The squash figure's balls start 1.75 m above the floor, above `Frame::shadow_reach`, where
/// they cast no shadow: a line drops from each ball's bottom straight down to the floor, so
/// their height reads from t = 0 on.
#[test]
fn the_squash_balls_have_drop_lines_from_the_start() {
    use inbetween::draw::Frame;
    let mut f = inbetween::figures::particles::SquashFigure::new();
    for t in [0.0, 0.3] {
        let mut frame = Frame::default();
        f.draw(&mut frame, t).unwrap();
        let spheres: Vec<glam::Vec3> = frame
            .meshes
            .iter()
            .filter(|m| m.mesh == inbetween::draw::MeshId::SPHERE)
            .map(|m| m.model.w_axis.truncate())
            .collect();
        assert_eq!(spheres.len(), 2, "t {t}: two balls");
        for c in spheres {
            assert!(c.y > 1.0, "t {t}: the ball at {c} is in flight");
            let drop = frame.strokes.iter().find(|s| {
                let (a, b) = (glam::Vec3::from(s.a), glam::Vec3::from(s.b));
                (a.x - c.x).abs() < 1e-4
                    && (a.z - c.z).abs() < 1e-4
                    && (a.y - (c.y - 0.25)).abs() < 0.06
                    && (b - a * glam::Vec3::new(1.0, 0.0, 1.0)).length() < 1e-4
            });
            assert!(
                drop.is_some(),
                "t {t}: no line from the ball at {c} to the floor"
            );
        }
    }
}

#[test]
fn the_emitter_note_says_when_the_fountain_rises_out_of_the_view() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera};
    // The emitter figure's page camera (lessons/11-particles/lesson.js; it fits nothing), on
    // both canvases: a particle FOUNTAIN_VIEW_TOP_M above the floor, anywhere a fountain
    // reaching that high can be (x from -3 to 3 m, z from -2 to 2 m), is off the canvas.
    let camera = OrbitCamera::from_view([0.2, 1.0, 0.0, 6.5, 0.35, 0.3]);
    for size in [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0)] {
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        for i in 0..=24 {
            for j in 0..=16 {
                let p = Vec3::new(
                    -3.0 + 0.25 * i as f32,
                    FOUNTAIN_VIEW_TOP_M,
                    -2.0 + 0.25 * j as f32,
                );
                let on = project_to_canvas(view_proj, size, p)
                    .filter(|c| c.cmpge(Vec2::ZERO).all() && c.cmple(size).all());
                assert!(on.is_none(), "{size}: {p} is on the canvas at {on:?}");
            }
        }
    }
    // The defaults' fountain stays well below (its top is under 2 m) and the note says nothing
    // of it; under weaker gravity it rises past, and the note gives its top. The simulated
    // particles come near that top and never pass it.
    for (g, leaves) in [(9.81, false), (4.0, true), (0.0, true)] {
        let mut scene = EmitterFigure::new();
        scene.set_gravity(g).unwrap();
        let top = scene.fountain_top_m();
        let mut highest = 0.0f32;
        for k in 1..=240 {
            scene.advance_to(k as f32 * SIM_DT).unwrap();
            let sys = scene.system();
            highest = sys.positions[..sys.len()]
                .iter()
                .fold(highest, |h, p| h.max(p.y));
        }
        assert!(
            highest <= top + 1e-3 && highest >= 0.8 * top,
            "g {g}: particles up to {highest} m, top {top} m"
        );
        assert_eq!(top > FOUNTAIN_VIEW_TOP_M, leaves, "g {g}: top {top} m");
        let mut frame = Frame::default();
        let eye = Vec3::new(0.0, 2.0, 6.0);
        let note = scene.draw(&mut frame, eye, Vec3::ZERO, 4.0).unwrap();
        let said = format!(
            "At g = {} m/s² the fountain's highest particles rise up to {} m before they die, \
             out of the top of the view.",
            inbetween::exercises::run::format_number(g),
            inbetween::exercises::run::format_number(top)
        );
        assert_eq!(note.contains(&said), leaves, "g {g}: {note}");
    }
}
