//! The check every flat figure's test makes (lessons 02, 05 and 15): a drag pans it instead of
//! orbiting round it. Included with `#[path = "support/flat.rs"] mod flat;`.

use glam::{Vec2, Vec3};
use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
use inbetween::draw::Frame;

/// Fits the page's camera `view` to `frame` on a `size` canvas, then drags it as the page test
/// does (a fifth of the canvas right, a tenth down): the frame is flat, so the drag pans, keeping
/// the camera's angles, moving the view, and keeping the segment `a`–`b` as long on the canvas
/// (within half a pixel); the same drag as an orbit shortens it below 90 %.
pub fn assert_drag_pans(frame: &Frame, view: [f32; 6], size: Vec2, [a, b]: [Vec3; 2]) {
    assert!(frame.flat, "the figure is flat");
    let mut camera = OrbitCamera::from_view(view);
    camera.fit(&frame.fit_points(), size, FIT_PAD_PX);
    let length = |c: &OrbitCamera| {
        let vp = c.projection(size.x / size.y) * c.view();
        let at = |p: Vec3| project_to_canvas(vp, size, p).unwrap();
        at(b).distance(at(a))
    };
    let before = length(&camera);
    let (dx, dy) = (0.2 * size.x, 0.1 * size.y);
    let mut panned = camera;
    assert!(panned.drag(dx, dy, size.y, frame.flat), "a drag pans a flat figure");
    assert_eq!(
        (panned.yaw_rad, panned.pitch_rad),
        (camera.yaw_rad, camera.pitch_rad)
    );
    assert_ne!(panned.target, camera.target, "the drag moves the view");
    assert!((length(&panned) - before).abs() < 0.5, "{before} → {}", length(&panned));
    let mut orbited = camera;
    assert!(!orbited.drag(dx, dy, size.y, false));
    assert!(
        length(&orbited) < 0.9 * before,
        "an orbit narrows it: {before} → {}",
        length(&orbited)
    );
}
