use inbetween::exercises::*;

#[test]
fn the_reference_switch_is_off_again_after_a_return_or_a_panic() {
    assert!(!reference_answers_on());
    let inner = with_reference_answers(|| {
        // Nested: the inner call leaves it on for the rest of the outer one.
        with_reference_answers(|| ());
        reference_answers_on()
    });
    assert!(inner);
    assert!(!reference_answers_on());
    let caught = std::panic::catch_unwind(|| with_reference_answers(|| panic!("in f")));
    assert!(caught.is_err());
    assert!(!reference_answers_on());
    // Inside the switch an exercise answers with its reference, whatever its body holds.
    assert_eq!(
        with_reference_answers(|| transforms::local_matrix(glam::Vec3::X, glam::Vec3::ZERO)),
        Ok(glam::Mat4::from_translation(glam::Vec3::X))
    );
}
