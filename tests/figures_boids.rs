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
    // STEER_ARROW_MAX_M): at the defaults the boid steers at a few tenths of a m/s², which the
    // old quarter-metre scale drew a few centimetres long, hidden under the neighbour lines.
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
    // A narrower field of view sees fewer neighbours.
    let (all, _) = scene.neighbours();
    scene.set_fov_deg(60.0).unwrap();
    let (ahead, _) = scene.neighbours();
    assert!(ahead.len() < all.len());
    assert!(scene.set_position(5.0, 0.0).is_err() && scene.set_radius(f32::NAN).is_err());
}

#[test]
fn the_rules_figure_says_what_the_students_code_does() {
    let mut scene = RulesFigure::new();
    scene.set_use_exercise(true);
    for (runner, expect) in [
        (
            reference as fn(&str, &[f32]) -> _,
            "Your three_rules matches the reference at this boid. Your cell_index matches",
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
    assert!(note.contains("Your cell_index differs"), "{note}");
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
    // the note says "1 neighbour" (it said "1 neighbours"); every count agrees with its noun.
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
