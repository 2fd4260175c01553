//! Native tests of lesson 02b's figures (src/figures/expressive.rs): what they draw, what they
//! reject, and what their notes say about the student's exercises.

use glam::Vec3;
use inbetween::draw::{Frame, MeshId};
use inbetween::exercises::run::{direct, Failure, Flat};
use inbetween::expressive;
use inbetween::figures::expressive::{FollowThrough, JumpComparison, Spacing, GHOST, PRINCIPLED};

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
    scene.draw(&mut f, 0.5).unwrap();
    let all_ghosts: Vec<Vec3> = f
        .points
        .iter()
        .filter(|p| Vec3::from_slice(&p.color[..3]) == GHOST)
        .map(|p| Vec3::from(p.center))
        .collect();
    // The arc's ghosts at z = 0, the straight twin's behind them.
    let (ghosts, twin): (Vec<Vec3>, Vec<Vec3>) = all_ghosts.iter().partition(|p| p.z > -0.5);
    assert_eq!(ghosts.len(), 11);
    assert_eq!(twin.len(), 11);
    for (k, b) in twin.iter().enumerate() {
        let covered = (b.x - twin[0].x) / (twin[10].x - twin[0].x);
        let spacing = scene.spacing(k as f32 / 10.0);
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
    scene.draw(&mut g, 0.5).unwrap();
    assert_eq!(
        g.points.len() + 11,
        f.points.len(),
        "no twin when it is off"
    );
    scene.set_twin(true);
    // Slow in and out: ghosts bunch at the ends and spread in the middle.
    let gap = |i: usize| (ghosts[i + 1] - ghosts[i]).length();
    assert!(gap(5) > 3.0 * gap(0), "{} vs {}", gap(5), gap(0));
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
    assert!(scene.set_arc_height(f32::NAN).is_err());
    // The ball's volume is kept.
    scene.set_squash(true);
    f.clear();
    scene.draw(&mut f, 0.5).unwrap();
    let ball = f.meshes.iter().find(|m| m.mesh == MeshId::SPHERE).unwrap();
    let det = glam::Mat3::from_mat4(ball.model).determinant() / 0.3f32.powi(3);
    assert!((det - 1.0).abs() < 1e-3, "{det}");
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
    let note = scene.draw(&mut f, 0.25).unwrap();
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
    assert_eq!(a.lines, b.lines);
    // Continuing forward from an earlier time gives the same picture as starting again.
    let mut fresh = FollowThrough::new();
    fresh.set(150.0, 60.0, 6.0).unwrap();
    let mut c = Frame::default();
    scene.draw(&mut Frame::default(), 3.5).unwrap();
    scene.draw(&mut Frame::default(), 0.7).unwrap();
    scene.draw(&mut c, 1.3).unwrap();
    let mut d = Frame::default();
    fresh.draw(&mut d, 1.3).unwrap();
    assert_eq!(c.lines, d.lines);
    scene.set_use_exercise(true);
    scene.set_runner(reference);
    assert!(scene
        .draw(&mut a, 0.5)
        .unwrap()
        .contains("matches the reference"));
    // Every joint is stepped by the student's code: explicit Euler drifts from the reference
    // over the loop, the shown antenna differs from the reference ghost drawn beside it.
    scene.set(150.0, 4.0, 6.0).unwrap();
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
    assert!(scene.set(100.0, 4.0, 500.0).unwrap_err().contains("joints"));
}
