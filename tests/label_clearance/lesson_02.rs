//! Lesson 02: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_02_keys_time_axis_labels_keep_off_the_curves() {
    let mut scene = inbetween::figures::curves::KeyframesScene::new();
    for tau in [0.0, 1.7, 3.6] {
        let mut frame = Frame::default();
        scene.draw(&mut frame, tau).unwrap();
        for size in [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)] {
            let camera = page_camera([0.3, 0.8, -1.3, 6.5, 0.75, 0.4], &frame, size);
            assert_clear("02 keys", &frame, &camera, size);
        }
    }
}
