//! Projection onto the page's canvas, for the figure tests that check what the reader sees
//! (`#[path = "support/canvas.rs"] mod canvas;`).

/// Where `world` lands on a `w × h` canvas seen by the page's camera `view` (a figure's six
/// `setCamera` numbers), in CSS pixels from the top-left. Panics behind the camera.
pub fn on_canvas(view: [f32; 6], w: f32, h: f32, world: glam::Vec3) -> glam::Vec2 {
    let camera = inbetween::camera::OrbitCamera::from_view(view);
    let view_proj = camera.projection(w / h) * camera.view();
    inbetween::camera::project_to_canvas(view_proj, glam::Vec2::new(w, h), world).unwrap()
}
