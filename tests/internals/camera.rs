use glam::{Vec2, Vec3};
use inbetween::camera::*;

/// A point projected to its pixel and taken back onto the view plane through itself is the
/// same point; the camera's target lands in the middle of the canvas; behind the eye, no pixel.
#[test]
fn canvas_projection_round_trips() {
    let camera = OrbitCamera::default();
    let size = Vec2::new(640.0, 480.0);
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let middle = project_to_canvas(view_proj, size, camera.target).unwrap();
    assert!((middle - 0.5 * size).length() < 1e-3, "{middle}");
    for p in [Vec3::new(0.3, -0.2, 0.1), Vec3::new(-1.0, 0.5, 0.7)] {
        let px = project_to_canvas(view_proj, size, p).unwrap();
        let back = point_on_view_plane(view_proj, size, p, px).unwrap();
        assert!((back - p).length() < 1e-3, "{p} -> {px} -> {back}");
    }
    let behind = camera.eye() + (camera.eye() - camera.target);
    assert!(project_to_canvas(view_proj, size, behind).is_none());
}
