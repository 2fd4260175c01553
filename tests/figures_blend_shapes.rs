//! Lesson 10 figure logic: validation, the full form's warning, the animation, and the note about
//! the student's exercise.

use inbetween::draw::{Frame, MeshId};
use inbetween::figures::blend_shapes::FaceFigure;

#[test]
fn controls_validate_and_the_full_form_reports_a_bad_sum() {
    let mut f = FaceFigure::new();
    assert!(f.set_weight(7, 0.5).unwrap_err().contains("target index 7"));
    assert!(f.set_weight(0, f32::NAN).unwrap_err().contains("weight"));
    assert!(f.set_form("half").unwrap_err().contains("form"));
    assert!(f.set_base_weight(2.0).unwrap_err().contains("base weight"));
    f.set_animate(false);
    let mut frame = Frame::default();
    let note = f.draw(&mut frame, MeshId(3), 0.0).unwrap();
    assert!(note.contains("Differential form"), "{note}");
    f.set_form("full").unwrap();
    let note = f.draw(&mut frame, MeshId(3), 0.0).unwrap();
    assert!(note.contains("= 1."), "{note}");
    f.set_base_weight(0.5).unwrap();
    let note = f.draw(&mut frame, MeshId(3), 0.0).unwrap();
    assert!(note.contains("not 1"), "{note}");
    assert!(f.draw(&mut frame, MeshId(3), f32::NAN).is_err());
    assert!(f.mesh.take_dirty());
}

#[test]
fn the_animation_moves_the_weights_and_the_exercise_note_shows() {
    let mut f = FaceFigure::new();
    assert_ne!(f.weights_at(0.0), f.weights_at(1.0));
    assert_eq!(f.weights_at(0.0)[0], 0.0);
    f.set_animate(false);
    assert_eq!(f.weights_at(0.0), f.weights_at(1.0));
    f.set_use_exercise(true);
    let note = f.draw(&mut Frame::default(), MeshId(3), 0.0).unwrap();
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
    let eye_positions = |f: &mut FaceFigure| -> Vec<glam::Vec3> {
        let mut frame = Frame::default();
        f.draw(&mut frame, MeshId(3), 0.0).unwrap();
        frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::SPHERE)
            .map(|m| m.model.w_axis.truncate())
            .collect()
    };
    let mut f = FaceFigure::new();
    f.set_animate(false);
    f.set_form("full").unwrap();
    let whole = eye_positions(&mut f);
    f.set_base_weight(0.5).unwrap();
    let w: f32 = f.weights_at(0.0).iter().sum();
    let scaled = eye_positions(&mut f);
    assert_eq!(whole.len(), 2);
    let head = glam::Vec3::new(0.0, 1.2, 0.0);
    for (a, b) in whole.iter().zip(&scaled) {
        let expected = head + (*a - head) * (0.5 + w);
        assert!((*b - expected).length() < 1e-5, "{b} vs {expected}");
    }
}
