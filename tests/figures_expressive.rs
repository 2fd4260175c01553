//! Native tests of lesson 02b's figures (src/figures/expressive.rs): what they draw, what they
//! reject, and what their notes say about the student's exercises.

use glam::Vec3;
#[path = "support/flat.rs"]
mod flat;
use inbetween::draw::{Frame, MeshId};
use inbetween::exercises::run::{direct, Failure, Flat};
use inbetween::expressive;
use inbetween::figures::expressive::{
    damping_regime, FollowThrough, JumpComparison, Spacing, DT, GHOST, MAX_STRETCH, PRINCIPLED, TWIN,
    TWIN_GHOST,
};

fn reference(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
    let mut out = Vec::new();
    match name {
        "squash_stretch_scale" => expressive::squash_stretch_scale(args[0]).put(&mut out),
        "spring_step" => {
            expressive::spring_step(v(0), v(3), v(6), args[9], args[10], args[11]).put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

/// Typical mistakes: `1/s` across instead of `1/√s` (volume not kept); explicit Euler.
fn wrong(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
    let v = |k: usize| Vec3::from_slice(&args[k..k + 3]);
    let mut out = Vec::new();
    match name {
        "squash_stretch_scale" => Vec3::new(args[0], 1.0 / args[0], 1.0 / args[0]).put(&mut out),
        "spring_step" => {
            let (x, vel, t, k, c, dt) = (v(0), v(3), v(6), args[9], args[10], args[11]);
            let a = k * (t - x) - c * vel;
            (x + vel * dt, vel + a * dt).put(&mut out)
        }
        _ => return direct(name, args),
    }
    Ok(out)
}

fn stub(_: &str, _: &[f32]) -> Result<Vec<f32>, Failure> {
    Err(Failure::NotDone)
}

#[test]
fn spacing_draws_ghosts_at_equal_time_steps_along_the_path() {
    let mut scene = Spacing::new();
    scene.set_ghosts(10.0).unwrap();
    let mut f = Frame::default();
    // Half-way through the trip from key 1 to key 2.
    let note = scene.draw(&mut f, 0.5 * scene.duration).unwrap();
    assert!(
        note.contains("10 ghosts"),
        "the note counts what is drawn: {note}"
    );
    let of = |color: Vec3| -> Vec<Vec3> {
        f.points
            .iter()
            .filter(|p| Vec3::from_slice(&p.color[..3]) == color)
            .map(|p| Vec3::from(p.center))
            .collect()
    };
    // The arc's ghosts at z = 0 in pale grey, the straight twin's behind them in pale purple.
    let (ghosts, twin) = (of(GHOST), of(TWIN_GHOST));
    assert!(ghosts.iter().all(|p| p.z > -0.5) && twin.iter().all(|p| p.z < -0.5));
    assert_eq!(ghosts.len(), 10, "as many ghosts as the slider says");
    assert_eq!(twin.len(), 10);
    for (k, b) in twin.iter().enumerate() {
        let covered = (b.x - twin[0].x) / (twin[9].x - twin[0].x);
        let spacing = scene.spacing(k as f32 / 9.0);
        assert!(
            (covered - spacing).abs() < 1e-4,
            "the same spacing: {covered} vs {spacing}"
        );
        assert!(
            (b.y - twin[0].y).abs() < 1e-5,
            "the twin's path is straight"
        );
    }
    assert!(
        ghosts[5].y > twin[5].y + 1.0,
        "the arc rises above the straight line"
    );
    scene.set_twin(false);
    let mut g = Frame::default();
    scene.draw(&mut g, 0.5 * scene.duration).unwrap();
    assert_eq!(
        g.points.len() + 10,
        f.points.len(),
        "no twin when it is off"
    );
    scene.set_twin(true);
    // Slow in and out: ghosts bunch at the ends and spread in the middle.
    let gap = |i: usize| (ghosts[i + 1] - ghosts[i]).length();
    assert!(gap(4) > 3.0 * gap(0), "{} vs {}", gap(4), gap(0));
    scene.set_ease("linear").unwrap();
    let p: Vec<Vec3> = (0..=10).map(|k| scene.position(k as f32 / 10.0)).collect();
    let d: Vec<f32> = p.windows(2).map(|w| (w[1] - w[0]).length()).collect();
    assert!(
        d.iter().all(|x| (x - d[0]).abs() < 1e-3),
        "linear: even spacing on the arc"
    );
    // A straight path at arc height 0.
    scene.set_arc_height(0.0).unwrap();
    assert!((scene.position(0.5).y - scene.position(0.0).y).abs() < 1e-5);
    assert!(scene.set_ease("bouncy").is_err());
    assert!(scene.set_ghosts(1000.0).is_err());
    // A fraction is refused, not rounded: the count stays as it was.
    let e = scene.set_ghosts(7.5).unwrap_err();
    assert!(e.contains("ghosts"), "{e}");
    assert!(scene.set_arc_height(f32::NAN).is_err());
    // The ball's volume is kept.
    scene.set_squash(true);
    f.clear();
    scene.draw(&mut f, 0.5 * scene.duration).unwrap();
    let ball = f.meshes.iter().find(|m| m.mesh == MeshId::SPHERE).unwrap();
    let det = glam::Mat3::from_mat4(ball.model).determinant() / 0.3f32.powi(3);
    assert!((det - 1.0).abs() < 1e-3, "{det}");
}

#[test]
fn the_caption_colours_the_ghosts_as_they_are_drawn() {
    // Figure 1's caption names the ghosts in a class of www/palette.css; its colour is GHOST.
    let page = include_str!("../lessons/02b-expressive-animation/index.html");
    let end = page.find(">ghosts</span>").expect("the caption names the ghosts");
    let class = &page[page[..end].rfind("class=\"c-").unwrap() + 9..end - 1];
    let named = inbetween::draw::palette::NAMED
        .iter()
        .find(|(name, _)| *name == class)
        .unwrap_or_else(|| panic!("no palette colour for c-{class}"));
    assert_eq!(named.1, GHOST, "the word is c-{class}");
    // And the twin in the colour its ball, line and name are drawn in.
    let end = page.find(" twin</span>").expect("the caption names the twin");
    let class = &page[page[..end].rfind("class=\"c-").unwrap() + 9..];
    let class = &class[..class.find('"').unwrap()];
    let named = inbetween::draw::palette::NAMED.iter().find(|(name, _)| *name == class);
    assert_eq!(named.map(|n| n.1), Some(TWIN), "the twin is c-{class}");
    assert!(
        page[..end].ends_with(&format!(">{class}")),
        "the word names its colour: c-{class}"
    );
}

#[test]
fn spacing_reports_the_students_scale() {
    let mut scene = Spacing::new();
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    assert!(scene
        .draw(&mut Frame::default(), 0.5)
        .unwrap()
        .contains("matches the reference"));
    scene.set_runner(wrong);
    let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("differs") && !note.contains("keeps 1.000 of the volume"),
        "{note}"
    );
    scene.set_runner(stub);
    assert!(scene
        .draw(&mut Frame::default(), 0.5)
        .unwrap()
        .contains("Not done yet: exercise 2b.1"));
}

#[test]
fn jump_side_by_side() {
    let mut scene = JumpComparison::new();
    let rows = scene.sample_heights(200).unwrap();
    let apex = rows.iter().map(|r| r[2]).fold(0.0f32, f32::max);
    let plain_apex = rows.iter().map(|r| r[1]).fold(0.0f32, f32::max);
    assert!((apex - plain_apex).abs() < 0.05, "both reach the same apex");
    assert!(rows.iter().any(|r| r[3] < 0.8), "the crouch squashes");
    let mut f = Frame::default();
    let note = scene.draw(&mut f, 0.2).unwrap();
    assert!(note.contains("anticipation"), "{note}");
    let right = f
        .meshes
        .iter()
        .find(|m| m.color.truncate() == PRINCIPLED)
        .unwrap();
    let det = glam::Mat3::from_mat4(right.model).determinant() / 0.3f32.powi(3);
    assert!(
        (det - 1.0).abs() < 1e-3,
        "volume kept while crouching: {det}"
    );
    scene.set_principles(0.0, 0.0).unwrap();
    assert!(scene
        .sample_heights(50)
        .unwrap()
        .iter()
        .all(|r| (r[3] - 1.0).abs() < 0.2));
    assert!(scene
        .set_principles(2.0, 0.0)
        .unwrap_err()
        .contains("anticipation"));
    assert!(scene.draw(&mut f, 100.0).is_err());
}

#[test]
fn follow_through_lags_and_is_checked_against_the_reference() {
    let mut scene = FollowThrough::new();
    let rows = scene.sample_tip(401).unwrap();
    // While the base moves right (t in (0.2, 0.8)) the tip is behind it.
    let moving: Vec<&[f32; 3]> = rows.iter().filter(|r| r[0] > 0.3 && r[0] < 0.6).collect();
    assert!(moving.iter().all(|r| r[2] < r[1]), "the tip lags");
    // After the stop (t in (1, 2)) the tip swings past the base.
    assert!(rows
        .iter()
        .filter(|r| r[0] > 1.0 && r[0] < 2.0)
        .any(|r| r[2] > r[1] + 0.05));
    // Over-damped: no swinging past.
    scene.set(150.0, 60.0, 6.0).unwrap();
    let rows = scene.sample_tip(401).unwrap();
    assert!(rows
        .iter()
        .filter(|r| r[0] > 1.0 && r[0] < 2.0)
        .all(|r| r[2] <= r[1] + 1e-3));
    // Drawing twice at the same time gives the same picture (deterministic).
    let (mut a, mut b) = (Frame::default(), Frame::default());
    scene.draw(&mut a, 1.3).unwrap();
    scene.draw(&mut b, 1.3).unwrap();
    assert_eq!(a.strokes, b.strokes);
    assert_eq!(a.markers, b.markers);
    // Continuing forward from an earlier time gives the same picture as starting again.
    let mut fresh = FollowThrough::new();
    fresh.set(150.0, 60.0, 6.0).unwrap();
    let mut c = Frame::default();
    scene.draw(&mut Frame::default(), 3.5).unwrap();
    scene.draw(&mut Frame::default(), 0.7).unwrap();
    scene.draw(&mut c, 1.3).unwrap();
    let mut d = Frame::default();
    fresh.draw(&mut d, 1.3).unwrap();
    assert_eq!(c.strokes, d.strokes);
    assert_eq!(c.markers, d.markers);
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    assert!(scene
        .draw(&mut a, 0.5)
        .unwrap()
        .contains("matches the reference"));
    // Every joint is stepped by the student's code: explicit Euler drifts from the reference
    // over the loop, the shown antenna differs from the reference ghost drawn beside it.
    scene.set(150.0, 10.0, 6.0).unwrap();
    scene.set_runner(wrong);
    let mut e = Frame::default();
    let note = scene.draw(&mut e, 1.5).unwrap();
    assert!(
        note.contains("differs") && note.contains("t = 1.5"),
        "{note}"
    );
    assert!(e.labels.iter().any(|l| l.text == "reference"));
    scene.set_runner(|name: &str, args: &[f32]| {
        if name == "spring_step" {
            Err(Failure::Panicked(
                "panicked at src/exercises/expressive.rs:9:5:\nboom".into(),
            ))
        } else {
            direct(name, args)
        }
    });
    let note = scene.draw(&mut e, 1.0).unwrap();
    assert!(
        note.contains("panicked at src/exercises/expressive.rs:9:5: boom"),
        "{note}"
    );
    scene.set_runner(stub);
    assert!(scene
        .draw(&mut a, 0.5)
        .unwrap()
        .contains("Not done yet: exercise 2b.2"));
    assert!(scene.set(1.0, 4.0, 6.0).unwrap_err().contains("stiffness"));
    assert!(scene
        .set(100.0, 10.0, 500.0)
        .unwrap_err()
        .contains("joints"));
}

#[test]
fn spacing_loops_there_and_back_with_the_same_spacing_and_the_clock_runs_forward() {
    let mut scene = Spacing::new();
    let d = scene.duration;
    assert_eq!(scene.loop_sec(), 2.0 * d);
    // "ease in" starts slowly on both trips: after a tenth of each trip the ball has covered 1 %.
    scene.set_ease("ease in").unwrap();
    assert!((scene.along(0.1 * d) - 0.01).abs() < 1e-5);
    assert!((scene.along(1.1 * d) - 0.99).abs() < 1e-5);
    // The loop is continuous: at the turn and at the end the ball is on a key.
    assert!((scene.along(d) - 1.0).abs() < 1e-6);
    assert!(scene.along(2.0 * d).abs() < 1e-6);
    // The plot's rows run forward in time over the whole loop (the playhead follows the clock).
    let rows = scene.sample_spacing(61).unwrap();
    assert_eq!(rows[0][0], 0.0);
    assert!((rows[60][0] - 2.0 * d).abs() < 1e-5);
    assert!(rows.windows(2).all(|w| w[1][0] > w[0][0]));
    assert!((rows[30][1] - 1.0).abs() < 1e-5 && (rows[30][2] - 1.0).abs() < 1e-5);
    // On the way back the note names the trip and counts from key 1, as the plot does, in
    // fixed notation even just after the turn, where the ball is a hair's breadth from key 2.
    scene.set_ease("slow in and out").unwrap();
    for time in [1.5 * d, d + 0.006, 2.0 * d - 0.006] {
        let note = scene.draw(&mut Frame::default(), time).unwrap();
        let said = number_after(&note, "the ball is ");
        let plotted = 100.0 * scene.along(time);
        assert!((said - plotted).abs() < 1e-3, "{plotted} % on the plot: {note}");
        assert!(note.contains("% of the way along the path from key 1 (on the way back)"), "{note}");
        let percent = note.split("the ball is ").nth(1).unwrap().split(' ').next().unwrap();
        assert!(!percent.contains('e'), "{note}");
    }
    assert!(scene.draw(&mut Frame::default(), 2.0 * d + 0.1).is_err());
}

#[test]
fn the_jump_stretch_is_continuous_and_capped_at_1_6() {
    let mut scene = JumpComparison::new();
    // Take-off at 4 · 1.6 m / 1 s = 6.4 m/s: with 0.06 per m/s, s = 1 + 0.06 · 6.4 = 1.384.
    let jump = inbetween::expressive::Jump::default();
    assert!((jump.take_off_speed() - 6.4).abs() < 1e-5);
    assert!((jump.take_off_stretch() - 1.384).abs() < 1e-4);
    // Every slider corner: the stretch changes by less than 0.12 in 10 ms (a stretch that
    // switches on at take-off jumps by 0.38 in one sample, a squash that starts at landing 0.7).
    for (a, k) in [(0.0, 0.0), (0.3, 0.06), (0.6, 0.2), (0.0, 0.2), (0.6, 0.0)] {
        scene.set_principles(a, k).unwrap();
        let rows = scene.sample_heights(241).unwrap(); // a 2.4 s loop: 10 ms apart
        let worst = rows
            .windows(2)
            .map(|w| (w[1][3] - w[0][3]).abs())
            .fold(0.0f32, f32::max);
        assert!(
            worst < 0.12,
            "anticipation {a}, stretch {k}: a step of {worst}"
        );
        assert!(rows
            .iter()
            .all(|r| r[3] <= MAX_STRETCH + 1e-6 && r[3] > 0.3));
    }
    // At 0.2 per m/s, 1 + 0.2 · 6.4 = 2.28 is capped at 1.6, and the note says so.
    scene.set_principles(0.3, 0.2).unwrap();
    let note = scene.draw(&mut Frame::default(), 0.55).unwrap();
    assert!(note.contains("capped at 1.600"), "{note}");
    // Scrubbing through take-off: the end of the push-off is capped too, at the take-off speed.
    let note = scene.draw(&mut Frame::default(), 0.499).unwrap();
    assert!(note.contains("capped at 1.600") && note.contains("would be 2.280"), "{note}");
    // At the apex (1 s) the ball is not moving: not stretched.
    let rows = scene.sample_heights(241).unwrap();
    let apex = rows.iter().find(|r| (r[0] - 1.0).abs() < 1e-4).unwrap();
    assert!((apex[3] - 1.0).abs() < 1e-3, "{apex:?}");
}

#[test]
fn the_damping_note_names_the_four_regimes() {
    assert!(damping_regime(4.0, 150.0).starts_with("under-damped"));
    assert!(damping_regime(20.0, 100.0).starts_with("critically damped"));
    assert!(damping_regime(30.0, 100.0).starts_with("over-damped"));
    let mut scene = FollowThrough::new();
    let note = scene.draw(&mut Frame::default(), 1.0).unwrap();
    assert!(
        note.contains("under-damped") && note.contains("2√k = 24.495"),
        "{note}"
    );
    scene.set(100.0, 20.0, 6.0).unwrap();
    let note = scene.draw(&mut Frame::default(), 1.0).unwrap();
    assert!(note.contains("critically damped"), "{note}");
}

#[test]
fn the_antenna_keeps_its_length_and_stays_finite_over_every_slider_corner() {
    let mut scene = FollowThrough::new();
    for k in [FollowThrough::MIN_STIFFNESS, 600.0] {
        for c in [FollowThrough::MIN_DAMPING, 60.0] {
            for n in [2.0, FollowThrough::MAX_JOINTS as f32] {
                scene.set(k, c, n).unwrap();
                for row in scene.sample_tip(401).unwrap() {
                    assert!(row.iter().all(|v| v.is_finite()));
                    assert!(
                        (row[2] - row[1]).abs() <= FollowThrough::LENGTH + 1e-4,
                        "k {k}, c {c}, {n} joints: tip {} m from the base",
                        row[2] - row[1]
                    );
                }
            }
        }
    }
    assert!(scene
        .set(10.0, 10.0, 6.0)
        .unwrap_err()
        .contains("stiffness"));
    assert!(scene.set(150.0, 4.0, 6.0).unwrap_err().contains("damping"));
    assert!(scene.set(150.0, 10.0, 20.0).unwrap_err().contains("joints"));
    assert!(scene.set(150.0, 10.0, 5.5).unwrap_err().contains("joints"));
}

/// Figure 4's page camera, as lessons/02b-expressive-animation/lesson.js sets it.
fn follow_view() -> [f32; 6] {
    crate::page_camera(
        include_str!("../lessons/02b-expressive-animation/lesson.js"),
        "followViewer",
    )
}

#[test]
fn the_antenna_figure_keeps_all_in_view_with_a_still_camera() {
    // Figure 4 at its page camera (fitted to what the figure declares), on the canvases the page
    // gives it at 1600 × 1000 (650 × 420, beside its panel) and 800 × 600 (760 × 340, above its
    // panel), over the loop at the page's sliders and at their
    // corners: the declared box, every joint of the antenna, the body's corners and the names
    // lie inside the canvas; at the page's sliders the camera stays put over the loop (the
    // tip's name, anchored at the tip, stays inside the declared box and never pulls the fit);
    // and the declared box (the body's bottom to the antenna's top along the slide) spans at
    // least 65 % of the canvas's height.
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::draw::box_corners;
    let view = follow_view();
    let mut settings = vec![(150.0, 10.0, 6.0)];
    for k in [FollowThrough::MIN_STIFFNESS, 600.0] {
        for c in [FollowThrough::MIN_DAMPING, 60.0] {
            for n in [2.0, FollowThrough::MAX_JOINTS as f32] {
                settings.push((k, c, n));
            }
        }
    }
    for size in [Vec2::new(650.0, 420.0), Vec2::new(760.0, 340.0)] {
        for &(k, c, n) in &settings {
            let mut scene = FollowThrough::new();
            scene.set(k, c, n).unwrap();
            let mut first: Option<OrbitCamera> = None;
            for step in 0..=80 {
                let t = step as f32 * 0.05;
                let mut frame = Frame::default();
                scene.draw(&mut frame, t).unwrap();
                let mut camera = OrbitCamera::from_view(view);
                assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
                let at = format!("k {k}, c {c}, {n} joints, t {t} on {size}");
                let fixed = *first.get_or_insert(camera);
                let moved = fixed.target.distance(camera.target) > 1e-4
                    || (fixed.distance - camera.distance).abs() > 1e-4;
                assert!(!(moved && (k, c, n) == settings[0]), "{at}: the camera moved");
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let on = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                let inside = |c: Vec2| c.cmpge(Vec2::ZERO).all() && c.cmple(size).all();
                let body = &frame.meshes[0];
                assert_eq!(body.mesh, MeshId::CUBE, "{at}: the body");
                let drawn = (frame.keep_in_view.iter().copied())
                    .chain(scene.shown().positions.iter().copied())
                    .chain(
                        box_corners(-Vec3::ONE, Vec3::ONE).map(|p| body.model.transform_point3(p)),
                    );
                for p in drawn {
                    assert!(inside(on(p)), "{at}: {p} at {} is off the canvas", on(p));
                }
                for label in &frame.labels {
                    let rect = label.first_place(view_proj, size).unwrap();
                    assert!(
                        inside(rect.min) && inside(rect.max()),
                        "{at}: {:?} at {rect:?} is off the canvas",
                        label.text
                    );
                }
                let ys = frame.keep_in_view.iter().map(|p| on(*p).y);
                let (top, bottom) = ys.fold((f32::MAX, f32::MIN), |(lo, hi), y| (lo.min(y), hi.max(y)));
                assert!(
                    bottom - top >= 0.65 * size.y,
                    "{at}: the figure spans {} of {} px of the canvas's height",
                    bottom - top,
                    size.y
                );
            }
        }
    }
}

/// The largest angle (degrees) between neighbouring segments over two loops.
fn worst_bend(k: f32, c: f32, joints: usize) -> f32 {
    let segment = FollowThrough::LENGTH / (joints - 1) as f32;
    let mut antenna = expressive::Antenna::new(FollowThrough::base(0.0), joints, segment);
    let mut worst = 0.0f32;
    for step in 1..=(2.0 * FollowThrough::DURATION / DT) as usize {
        antenna.step(FollowThrough::base(step as f32 * DT), k, c, DT);
        let p = &antenna.positions;
        for i in 1..joints - 1 {
            worst = worst.max(
                (p[i] - p[i - 1])
                    .angle_between(p[i + 1] - p[i])
                    .to_degrees(),
            );
        }
    }
    worst
}

#[test]
fn inside_the_slider_limits_the_antenna_bends_but_never_folds_over() {
    for k in [FollowThrough::MIN_STIFFNESS, 100.0, 150.0, 300.0, 600.0] {
        for c in [FollowThrough::MIN_DAMPING, 10.0, 20.0, 60.0] {
            for joints in 3..=FollowThrough::MAX_JOINTS {
                let bend = worst_bend(k, c, joints);
                assert!(
                    bend < 110.0,
                    "k {k}, c {c}, {joints} joints: a bend of {bend}°"
                );
            }
        }
    }
    // What the limits keep out: with c = 4 six joints fold over (a bend near 180°).
    assert!(worst_bend(150.0, 4.0, 6) > 170.0);
}

#[test]
fn the_jump_captions_numbers_hold() {
    let mut scene = JumpComparison::new();
    let jump = inbetween::expressive::Jump::default();
    let crouch_min = |rows: &[[f32; 4]]| {
        rows.iter()
            .filter(|r| r[0] < jump.wind_up)
            .map(|r| r[3])
            .fold(f32::MAX, f32::min)
    };
    // Anticipation 0: no crouch at all; 0.6: the stretch dips to 0.4.
    scene.set_principles(0.0, 0.06).unwrap();
    assert!((crouch_min(&scene.sample_heights(481).unwrap()) - 1.0).abs() < 1e-6);
    scene.set_principles(0.6, 0.06).unwrap();
    assert!((crouch_min(&scene.sample_heights(481).unwrap()) - 0.4).abs() < 1e-3);
    // At 0.2 per m/s the stretch sits on the 1.6 cap just after take-off and before landing.
    scene.set_principles(0.3, 0.2).unwrap();
    let at = |t: f32| jump.principled(t);
    let capped = inbetween::expressive::Jump {
        stretch_per_speed: 0.2,
        ..jump
    };
    for t in [jump.wind_up + 0.1, jump.wind_up + jump.flight - 0.1] {
        assert_eq!(capped.principled(t).stretch, MAX_STRETCH, "at {t} s");
    }
    assert!(
        at(jump.wind_up + 0.1).stretch < MAX_STRETCH,
        "at 0.06 per m/s it is not capped"
    );
}

#[test]
fn a_soft_spring_trails_and_takes_the_whole_hold_to_come_back() {
    // Rows every 0.01 s: (t, base x, tip x). The body stops at t = 1 s and holds until 2 s.
    let offsets = |k: f32| -> Vec<(f32, f32)> {
        let mut scene = FollowThrough::new();
        scene.set(k, 10.0, 6.0).unwrap();
        let rows = scene.sample_tip(401).unwrap();
        rows.iter().map(|r| (r[0], r[2] - r[1])).collect()
    };
    let at = |o: &[(f32, f32)], t: f32| o.iter().find(|r| (r.0 - t).abs() < 5e-3).unwrap().1;
    let soft = offsets(50.0);
    // k = 50: still 0.3 m behind half-way through the hold, and never swings past.
    assert!(at(&soft, 1.5) < -0.3, "{}", at(&soft, 1.5));
    assert!(soft
        .iter()
        .filter(|r| r.0 > 1.0 && r.0 < 2.0)
        .all(|r| r.1 < 0.05));
    // k = 150 (the default): it swings past the base during the hold.
    let default = offsets(150.0);
    assert!(default
        .iter()
        .filter(|r| r.0 > 1.0 && r.0 < 2.0)
        .any(|r| r.1 > 0.2));
}

#[test]
fn the_scale_verdict_checks_a_squash_too() {
    // Right for stretches, wrong for squashes (s < 1 left round across).
    fn only_stretch(name: &str, args: &[f32]) -> Result<Vec<f32>, Failure> {
        if name == "squash_stretch_scale" && args[0] < 1.0 {
            let mut out = Vec::new();
            Vec3::new(args[0], 1.0, 1.0).put(&mut out);
            return Ok(out);
        }
        reference(name, args)
    }
    let mut scene = JumpComparison::new();
    scene.set_use_exercise(true);
    scene.set_runner(only_stretch);
    // In flight (0.6 s) the ball is stretched: that input matches, the probe s = 0.6 does not.
    let note = scene.draw(&mut Frame::default(), 0.6).unwrap();
    assert!(
        note.contains(
            "(the figure's input), but differs at s = 0.600: yours (0.600, 1.000, 1.000)"
        ),
        "{note}"
    );
    scene.set_runner(reference);
    let note = scene.draw(&mut Frame::default(), 0.6).unwrap();
    assert!(
        note.contains("and at 3 more inputs (s = 0.600; s = 1.000; s = 1.600)"),
        "{note}"
    );
    // spring_step: one step on inputs where each term shows, after the whole antenna matched.
    let mut follow = FollowThrough::new();
    follow.set_use_exercise(true);
    follow.set_runner(reference);
    let note = follow.draw(&mut Frame::default(), 0.5).unwrap();
    assert!(
        note.contains("and at 3 more inputs (one step from x = (0, 0, 0)"),
        "{note}"
    );
}

#[test]
fn just_past_critical_damping_the_tip_no_longer_swings_past() {
    // "raise the damping past critical (24.5 at k = 150) and the wobble after each stop
    // disappears": during the hold after the move right the tip stays behind the base.
    for c in [25.0, 30.0, 60.0] {
        let mut scene = FollowThrough::new();
        scene.set(150.0, c, 6.0).unwrap();
        let rows = scene.sample_tip(401).unwrap();
        let past = rows
            .iter()
            .filter(|r| r[0] > 1.0 && r[0] < 2.0)
            .map(|r| r[2] - r[1])
            .fold(f32::MIN, f32::max);
        assert!(
            past < 0.01,
            "c = {c}: the tip swings {past} m past the base"
        );
    }
}

#[test]
fn the_stretch_figure_keeps_the_volume_on_the_left_only() {
    let mut scene = inbetween::figures::expressive::StretchComparison::new();
    let mut frame = Frame::default();
    let note = scene.draw(&mut frame);
    // s = 1.6, the lesson's cap: about twice as long as wide, volume kept; stretched only, × 1.6.
    assert!((scene.kept().determinant() - 1.0).abs() < 1e-5);
    assert!((scene.grown().determinant() - 1.6).abs() < 1e-5);
    assert!((scene.kept_aspect() - 2.02).abs() < 0.01);
    assert!(
        note.contains("volume × 1.000") && note.contains("volume × 1.600"),
        "{note}"
    );
    // Along a, the left ball is s times as long; across it, 1/√s as wide.
    let a = scene.axis();
    assert!(((scene.kept() * a).length() - 1.6).abs() < 1e-5);
    let across = Vec3::new(-a.y, a.x, 0.0);
    assert!(((scene.kept() * across).length() - 1.0 / 1.6f32.sqrt()).abs() < 1e-5);
    assert!(((scene.grown() * across).length() - 1.0).abs() < 1e-5);
    // A squash keeps the volume too.
    scene.set(0.5, -40.0).unwrap();
    assert!((scene.kept().determinant() - 1.0).abs() < 1e-5);
    // Rejected input changes nothing, whichever argument is wrong.
    assert!(scene.set(3.0, 0.0).is_err());
    assert!(scene.set(1.0, f32::NAN).is_err());
    assert!(scene.set(f32::INFINITY, 0.0).is_err());
    assert!((scene.grown().determinant() - 0.5).abs() < 1e-5);
}

/// Figure 4's Try this: at the default damping 10 and a stiffness of 50 the antenna trails almost
/// flat (1.1 m long) when the body stops, takes the whole one-second hold to stand up again, and
/// never swings past the base.
#[test]
fn a_soft_antenna_trails_and_stands_up_over_the_hold_without_swinging_past() {
    let mut scene = FollowThrough::new();
    scene.set(50.0, 10.0, 6.0).unwrap();
    let rows = scene.sample_tip(401).unwrap();
    let lag_at = |t: f32| {
        let r = rows
            .iter()
            .min_by(|a, b| (a[0] - t).abs().total_cmp(&(b[0] - t).abs()))
            .unwrap();
        r[1] - r[2]
    };
    assert!(lag_at(1.0) > 0.8, "trails almost flat at the stop: {}", lag_at(1.0));
    assert!(lag_at(1.5) > 0.3, "still standing up half way through the hold: {}", lag_at(1.5));
    assert!(lag_at(1.95) < 0.1, "up by the end of the hold: {}", lag_at(1.95));
    let hold = rows.iter().filter(|r| r[0] > 1.0 && r[0] < 2.0);
    assert!(hold.map(|r| r[1] - r[2]).all(|lag| lag > 0.0), "never swings past");
    // The same stiffness with the damping raised past critical (24.5) does not stand up in time.
    scene.set(50.0, 24.5, 6.0).unwrap();
    let rows = scene.sample_tip(401).unwrap();
    let end = rows.iter().filter(|r| r[0] < 1.95).last().unwrap();
    assert!(end[1] - end[2] > 0.5);
}

/// Both balls of the jump cast a shadow on the ground: darkest when a ball touches it, fainter
/// at the apex, so the heights compare from one view.
#[test]
fn the_jumping_balls_cast_shadows_that_fade_with_height() {
    use inbetween::draw::MARKER_SHADOW;
    let f = JumpComparison::new();
    let shadows = |t: f32| -> Vec<f32> {
        let mut frame = Frame::default();
        f.draw(&mut frame, t).unwrap();
        frame
            .markers
            .iter()
            .filter(|m| m.shape == MARKER_SHADOW)
            .map(|m| m.color[3])
            .collect()
    };
    let rest = shadows(0.0);
    assert_eq!(rest.len(), 2);
    assert!(rest.iter().all(|&a| a > 0.4), "{rest:?}");
    // Somewhere in the flight both balls are up: their shadows are fainter.
    let duration = (1..100)
        .map(|k| k as f32 * 0.05)
        .find(|&t| shadows(t).iter().all(|&a| a < 0.4));
    assert!(duration.is_some(), "the shadows never fade");
}

/// The ghosts read as copies of the ball: each at least half the ball's size, and, with the
/// camera fitted on the page's 760 × 420 canvas from its orbit, at least 20 px across.
#[test]
fn spacing_ghosts_are_copies_of_the_ball_not_dots() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    let scene = Spacing::new();
    let mut f = Frame::default();
    scene.draw(&mut f, 0.4).unwrap();
    let ball = f
        .meshes
        .iter()
        .find(|m| m.mesh == MeshId::SPHERE)
        .map(|m| {
            m.model
                .x_axis
                .truncate()
                .length()
                .min(m.model.y_axis.truncate().length())
        })
        .unwrap();
    let ghosts: Vec<_> = f
        .points
        .iter()
        .filter(|p| [GHOST, TWIN_GHOST].contains(&Vec3::from_slice(&p.color[..3])))
        .collect();
    assert!(ghosts.len() >= 2 * 12, "the arc's and the twin's");
    let size = glam::Vec2::new(760.0, 420.0);
    let mut camera = OrbitCamera::from_view([0.0, 0.9, 0.0, 7.5, 0.0, 0.35]);
    assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    for g in ghosts {
        assert!(
            g.radius >= 0.5 * ball,
            "a ghost of {} m by a ball of {ball} m",
            g.radius
        );
        let c = Vec3::from(g.center);
        let [a, b] = [c - Vec3::Y * g.radius, c + Vec3::Y * g.radius]
            .map(|p| project_to_canvas(view_proj, size, p).unwrap());
        assert!((a - b).length() >= 20.0, "{} px across", (a - b).length());
    }
}

/// The stretch figure's names sit just under their balls (within 0.5 m of the lowest point at
/// any stretch and direction, not a fixed distance that leaves a gap of a ball's height), and
/// the dark dashed outline at rest shows on both balls: each ball's surface is lighter than
/// mid-grey or coloured, never a dark grey under dark dashes.
#[test]
fn stretch_names_sit_under_their_balls_and_the_outline_shows_on_both() {
    use inbetween::figures::expressive::StretchComparison;
    for s in [0.4, 1.0, 1.6, 2.5] {
        for angle in [-90.0, -30.0, 0.0, 30.0, 90.0] {
            let mut scene = StretchComparison::new();
            scene.set(s, angle).unwrap();
            let mut f = Frame::default();
            scene.draw(&mut f);
            let balls: Vec<_> = f
                .meshes
                .iter()
                .filter(|m| m.mesh == MeshId::SPHERE)
                .collect();
            assert_eq!(balls.len(), 2);
            for (ball, title) in balls.iter().zip(["volume kept", "stretched only"]) {
                let m = ball.model;
                let lowest = m.w_axis.y - Vec3::new(m.x_axis.y, m.y_axis.y, m.z_axis.y).length();
                let label = f.labels.iter().find(|l| l.text == title).unwrap();
                let below = lowest - label.anchor.y;
                assert!(
                    (0.0..0.5).contains(&below),
                    "s {s}, {angle}°: {title:?} {below} m under its ball"
                );
                assert!(
                    (label.anchor.x - m.w_axis.x).abs() < 1e-3,
                    "s {s}, {angle}°: {title:?} not under its ball"
                );
                let c = ball.color.truncate();
                let grey = (c.max_element() - c.min_element()) < 0.05;
                assert!(
                    !grey || c.x > 0.4,
                    "s {s}, {angle}°: the {title:?} ball's grey {c} hides the dark outline"
                );
            }
        }
    }
}

/// The stretch figure is a picture in the x-y plane: a drag pans it (the balls stay apart and
/// each name under its own ball), and "a" is anchored at the head of the left ball's arrow at
/// any direction.
#[test]
fn the_stretch_figure_pans_and_names_the_arrow_at_its_head() {
    use inbetween::figures::expressive::StretchComparison;
    let mut scene = StretchComparison::new();
    for angle in [-90.0, -54.0, 0.0, 30.0, 90.0] {
        scene.set(0.82, angle).unwrap();
        let mut f = Frame::default();
        scene.draw(&mut f);
        let label = f.labels.iter().find(|l| l.text == "a").unwrap();
        let (tip, a) = (label.anchor, scene.axis());
        let centre = Vec3::new(-1.5, 1.3, 0.0);
        let along = (tip - centre).dot(a);
        assert!(
            (tip - centre).cross(a).length() < 1e-4 && (0.8..0.9).contains(&along),
            "{angle}°: \"a\" at {tip}, {along} m along the arrow"
        );
        let (l, r) = (Vec3::new(-1.5, 1.3, 0.0), Vec3::new(1.5, 1.3, 0.0));
        flat::assert_drag_pans(&f, [0.0, 1.3, 0.0, 7.0, 0.0, 0.0], glam::Vec2::new(650.0, 420.0), [l, r]);
    }
}

/// Figure 3's names follow their balls up: each stays within 0.3 m under its ball's lowest
/// point through the jump (on the floor they would sit a ball's flight below it).
#[test]
fn jump_names_follow_their_balls() {
    let scene = JumpComparison::new();
    for t in [0.0, 0.6, 0.88, 1.0, 1.3, 2.0] {
        let mut f = Frame::default();
        scene.draw(&mut f, t).unwrap();
        let balls: Vec<_> = f.meshes.iter().filter(|m| m.mesh == MeshId::SPHERE).collect();
        for (ball, name) in balls.iter().zip(["plain", "principles"]) {
            let m = ball.model;
            let lowest = m.w_axis.y - Vec3::new(m.x_axis.y, m.y_axis.y, m.z_axis.y).length();
            let label = f.labels.iter().find(|l| l.text == name).unwrap();
            let below = lowest - label.anchor.y;
            assert!(
                (-1e-3..0.3).contains(&below) && (label.anchor.x - m.w_axis.x).abs() < 1e-3,
                "t {t}: {name:?} {below} m under its ball"
            );
        }
    }
}

/// Figure 1's twin ghosts are paler than the straight twin's purple ball, so the ball stands
/// out among them as the blue one does on the arc; and the twin's ghosts are not the arc's grey,
/// so the two rows stay apart where they cross on the canvas.
#[test]
fn ghosts_are_paler_than_the_twin_ball() {
    let mut scene = Spacing::new();
    scene.set_twin(true);
    let mut f = Frame::default();
    scene.draw(&mut f, 0.5).unwrap();
    let twin = f
        .meshes
        .iter()
        .find(|m| m.color.truncate() == TWIN)
        .expect("the twin's ball");
    assert!(
        (TWIN_GHOST - twin.color.truncate()).min_element() > 0.15,
        "ghosts {TWIN_GHOST} against the twin ball's {}",
        twin.color
    );
    // Hue apart from the arc's grey ghosts: blue over green by a tenth or more.
    assert!(TWIN_GHOST.z - TWIN_GHOST.y > 0.1 && (GHOST.z - GHOST.y).abs() < 1e-3);
    assert_eq!(f.segments_of(TWIN).count(), 1, "the twin's line");
}

/// Figure 4 at its page camera (lessons/02b-expressive-animation/lesson.js), fitted on both
/// canvases: the body's slide and the antenna over the loop fill the canvas (their box on the
/// canvas at least 78 % of its width and, as tall as a 3.6 m slide lets them, 55 % of its
/// height), not a strip in its upper middle.
#[test]
fn the_antenna_figure_fills_its_canvas() {
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::figures::expressive::FollowThrough;
    let view = follow_view();
    for size in [glam::Vec2::new(650.0, 420.0), glam::Vec2::new(760.0, 340.0)] {
        let mut scene = FollowThrough::new();
        let (mut lo, mut hi) = (glam::Vec2::splat(f32::MAX), glam::Vec2::splat(f32::MIN));
        for k in 0..40 {
            let mut f = Frame::default();
            scene.draw(&mut f, k as f32 * 0.1).unwrap();
            let mut camera = OrbitCamera::from_view(view);
            assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let body = f.meshes.iter().find(|m| m.mesh == MeshId::CUBE).unwrap().model;
            let corners = inbetween::draw::box_corners(-Vec3::ONE, Vec3::ONE)
                .map(|c| body.transform_point3(c));
            let joints = f.markers.iter().map(|m| Vec3::from(m.center));
            for p in corners.into_iter().chain(joints) {
                let c = project_to_canvas(view_proj, size, p).unwrap();
                (lo, hi) = (lo.min(c), hi.max(c));
            }
        }
        // Seen from the front left and above, the slide and the antenna span at least 65 % of
        // the canvas both ways on the canvases of both page sizes (from the front, the 3.7 m
        // slide on the 650 × 420 canvas left its lower third empty: 57 % of its height).
        let fill = (hi - lo) / size;
        assert!(
            fill.x >= 0.65 && fill.y >= 0.65,
            "on {size}: {fill} of the canvas"
        );
    }
}

/// The furthest the tip swings past the base while the body holds still after a move, over the
/// plotted loop (rows of `(t, base x, tip x)`).
fn plotted_swing_past(rows: &[[f32; 3]]) -> f32 {
    rows.iter()
        .map(|r| match r[0] {
            t if (1.0..=2.0).contains(&t) => r[2] - r[1],
            t if t >= 3.0 => r[1] - r[2],
            _ => 0.0,
        })
        .fold(0.0, f32::max)
}

/// The number after `key` in `note`.
fn number_after(note: &str, key: &str) -> f32 {
    let rest = note.split(key).nth(1).unwrap_or_else(|| panic!("{key:?} in {note}"));
    rest.split(' ').next().unwrap().parse().unwrap()
}

/// Figure 4's note says what one joint alone would do (from c against 2√k) and, apart from it,
/// what the chain's tip does in the simulated loop: at k = 50, c = 10 each joint is under-damped
/// but the tip never swings past the base; at the default and at k = 600, c = 8 it does, by the
/// amount the plot shows; at k = 150, c = 30 each joint is over-damped and the tip stays behind.
#[test]
fn the_antenna_note_says_what_the_tip_does_apart_from_one_joint() {
    let mut scene = FollowThrough::new();
    scene.set(50.0, 10.0, 6.0).unwrap();
    let note = scene.draw(&mut Frame::default(), 1.5).unwrap();
    assert!(note.contains("2√k = 14.142): under-damped (one joint alone would swing past)"), "{note}");
    assert!(note.contains("the tip never gets 1 mm past the base"), "{note}");
    assert!(plotted_swing_past(&scene.sample_tip(401).unwrap()) < 1e-3);
    scene.set(150.0, 30.0, 6.0).unwrap();
    let note = scene.draw(&mut Frame::default(), 1.5).unwrap();
    assert!(note.contains("over-damped") && note.contains("never gets 1 mm past"), "{note}");
    for (k, c) in [(150.0, 10.0), (600.0, 8.0)] {
        scene.set(k, c, 6.0).unwrap();
        let note = scene.draw(&mut Frame::default(), 1.5).unwrap();
        assert!(note.contains("under-damped"), "k {k}, c {c}: {note}");
        let said = number_after(&note, "the tip swings up to ");
        let plotted = plotted_swing_past(&scene.sample_tip(401).unwrap());
        assert!(plotted > 0.02, "k {k}, c {c}: the plot shows {plotted} m");
        assert!((said - plotted).abs() < 5e-3, "k {k}, c {c}: {note}; the plot shows {plotted} m");
    }
}

/// Figure 4 loops without a jump: the antenna at the end of the loop (4 s) is the one at its
/// start (0 s), joint by joint, positions and velocities, so the motion runs on across the wrap,
/// at the page's sliders and at their corners; the plot starts where it ends.
#[test]
fn the_antenna_runs_on_across_the_loop_wrap() {
    let mut settings = vec![(150.0, 10.0, 6.0), (600.0, 8.0, 6.0)];
    for k in [FollowThrough::MIN_STIFFNESS, 600.0] {
        for c in [FollowThrough::MIN_DAMPING, 60.0] {
            for n in [2.0, FollowThrough::MAX_JOINTS as f32] {
                settings.push((k, c, n));
            }
        }
    }
    let end = FollowThrough::DURATION;
    for (k, c, n) in settings {
        let mut scene = FollowThrough::new();
        scene.set(k, c, n).unwrap();
        let mut at = |t: f32| {
            scene.draw(&mut Frame::default(), t).unwrap();
            scene.shown().clone()
        };
        let (at_end, at_start) = (at(end), at(0.0));
        let joints = at_end.positions.iter().zip(&at_start.positions);
        for (a, b) in joints {
            assert!(a.distance(*b) < 1e-3, "k {k}, c {c}, {n} joints: {a} at 4 s, {b} at 0 s");
        }
        let speeds = at_end.velocities.iter().zip(&at_start.velocities);
        for (a, b) in speeds.skip(1) {
            assert!(a.distance(*b) < 1e-2, "k {k}, c {c}, {n} joints: {a} m/s at 4 s, {b} at 0 s");
        }
        let rows = scene.sample_tip(201).unwrap();
        assert!((rows[0][2] - rows[200][2]).abs() < 1e-3, "k {k}, c {c}, {n} joints: {rows:?}");
    }
}

/// Figure 4's note says how far the tip still is to the side of the base in the last 0.25 s of
/// each 1 s hold, as the plot shows it, or that it is within 1 cm, at the default and at every
/// corner of the panel. At k = 600, c = 8 and six joints each joint's wobble is passed up the
/// chain, and the tip is still swinging by decimetres when the body moves again: the note must
/// not let the student expect it to settle there.
#[test]
fn the_antenna_note_says_whether_the_tip_settles_within_the_hold() {
    let mut settings = vec![(150.0, 10.0, 6.0)];
    for k in [FollowThrough::MIN_STIFFNESS, 600.0] {
        for c in [FollowThrough::MIN_DAMPING, 60.0] {
            for n in [2.0, FollowThrough::MAX_JOINTS as f32] {
                settings.push((k, c, n));
            }
        }
    }
    let mut scene = FollowThrough::new();
    for (k, c, n) in settings {
        scene.set(k, c, n).unwrap();
        let note = scene.draw(&mut Frame::default(), 0.5).unwrap();
        let rows = scene.sample_tip(481).unwrap();
        let in_last = |t: f32| [2.0f32, 4.0].iter().any(|e| (e - 0.2501..=e + 1e-4).contains(&t));
        let late = rows
            .iter()
            .filter(|r| in_last(r[0]))
            .map(|r| (r[2] - r[1]).abs())
            .fold(0.0, f32::max);
        if (k, c, n) == (600.0, 8.0, 6.0) {
            assert!(late > 0.2, "the tip is still swinging: {late} m");
        }
        let setting = format!("k {k}, c {c}, {n} joints, {late} m on the plot");
        if late < 0.01 {
            let settled = "in the last 0.25 s of each hold it is within 1 cm of the base";
            assert!(note.contains(settled), "{setting}: {note}");
        } else {
            let said = number_after(&note, "in the last 0.25 s of each hold it is still up to ");
            assert!((said - late).abs() < 2e-3, "{setting}: {note}");
        }
    }
}

/// Figure 3's slider for the stretch per unit speed is named by the symbol of the formula the
/// text gives, s = min(1 + k_s |v|, 1.6), so the reader can match the two.
#[test]
fn the_jump_panel_names_the_stretch_slider_by_the_formulas_symbol() {
    let text = include_str!("../lessons/02b-expressive-animation/index.html");
    let page = include_str!("../lessons/02b-expressive-animation/lesson.js");
    assert!(text.contains(r"with \(k_s\) the stretch per m/s"));
    assert!(page.contains(".name('stretch k_s (per m/s)')"));
}
