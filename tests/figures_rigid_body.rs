//! The tennis-racket figure of the coming rigid-body lesson.
#![cfg(not(target_arch = "wasm32"))]

use glam::Vec3;
use inbetween::draw::{palette, Frame, MeshId};
use inbetween::figures::rigid_body::{RacketFigure, INTEGRATORS};

#[test]
fn the_figure_draws_three_rackets_with_their_momentum_and_names() {
    let f = RacketFigure::new();
    let mut frame = Frame::default();
    let note = f.draw(&mut frame);
    let cubes = frame
        .meshes
        .iter()
        .filter(|m| m.mesh == MeshId::CUBE)
        .count();
    assert_eq!(cubes, 3);
    for (_, name) in INTEGRATORS {
        assert!(frame.labels.iter().any(|l| l.text == name), "{name}");
        assert!(
            note.contains(&format!("{name}: energy 100 %, |L| 100.0 %")),
            "{note}"
        );
    }
    assert!(frame.segments_of(palette::Y_AXIS).count() >= 3);
    assert!(!frame.keep_in_view.is_empty());
}

#[test]
fn over_ten_seconds_each_integrator_shows_its_character() {
    let mut f = RacketFigure::new();
    let start_axis = Vec3::Y;
    let mut lowest = [1.0f32; 3];
    for k in 1..=600 {
        f.advance_to(k as f32 / 60.0).unwrap();
        for (i, b) in f.bodies().iter().enumerate() {
            lowest[i] = lowest[i].min((b.orientation * Vec3::Y).dot(start_axis));
        }
    }
    let last = *f.samples().last().unwrap();
    assert_eq!(
        f.samples().len(),
        601,
        "one sample per step, the start included"
    );
    // L held: |L| kept to float rounding; the racket turns over.
    assert!((last[4] - 1.0).abs() < 1e-4, "{last:?}");
    assert!(lowest[0] < -0.9, "the held-L racket flips: {lowest:?}");
    // Explicit: the energy grows; implicit: it never grows and falls.
    let explicit_most = f.samples().iter().map(|r| r[2]).fold(0.0, f32::max);
    let implicit_most = f.samples().iter().map(|r| r[3]).fold(0.0, f32::max);
    assert!(
        explicit_most > 1.2,
        "explicit energy at most {explicit_most}"
    );
    assert!(
        implicit_most <= 1.0 + 1e-5 && last[3] < 0.99,
        "implicit: {implicit_most}, {}",
        last[3]
    );
}

#[test]
fn the_run_starts_again_when_time_goes_back_or_the_spin_changes() {
    let mut f = RacketFigure::new();
    f.advance_to(2.0).unwrap();
    let at_two = f.bodies()[0];
    f.advance_to(1.0).unwrap();
    f.advance_to(2.0).unwrap();
    assert_eq!(f.bodies()[0], at_two, "the replay is the same run");
    assert!(f.set_spin(f32::NAN, 0.1).is_err());
    assert!(f.set_spin(6.0, 2.0).unwrap_err().contains("wobble"));
    assert_eq!(f.bodies()[0], at_two, "a rejected setting changes nothing");
    f.set_spin(10.0, 0.0).unwrap();
    assert_eq!(f.samples().len(), 1);
    assert!(f.advance_to(61.0).is_err());
    // Without a wobble the spin about the middle axis stays (an unstable balance, held exactly).
    f.advance_to(5.0).unwrap();
    assert!((f.bodies()[0].orientation * Vec3::Y).dot(Vec3::Y) > 0.999);
}
