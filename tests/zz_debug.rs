use glam::{Vec2, Vec3};
use inbetween::camera::{OrbitCamera, FIT_PAD_PX, project_to_canvas};
use inbetween::draw::{Frame, project_labels, label_size_px};
use inbetween::draw::layout::{place, LabelBox};
#[test]
fn dbg() {
    let scene = inbetween::figures::raster::Frustum::new();
    for size in [Vec2::new(760.0, 380.0), Vec2::new(650.0, 420.0)] {
    for s in [0.0f32, 0.03, 0.067, 0.1, 0.15] {
        let mut frame = Frame::default();
        scene.draw(&mut frame, s).unwrap();
        let mut camera = OrbitCamera::from_view([4.5, 1.2, -4.0, 17.0, 0.45, 0.45]);
        camera.fit(&frame.fit_points(), size, FIT_PAD_PX);
        let vp = camera.projection(size.x / size.y) * camera.view();
        let labels = project_labels(&frame.labels, vp, size.x, size.y);
        let boxes: Vec<LabelBox> = labels.iter().map(|l| LabelBox { anchor: Vec2::new(l.x_px, l.y_px), size: label_size_px(&l.text), left: l.left, visible: l.visible, priority: l.priority }).collect();
        let placed = place(&boxes, size);
        print!("{size} s {s}: ");
        for (l, p) in labels.iter().zip(&placed) { if l.text == "p" || l.text == "image" || l.text=="eye" || l.text=="z_near" { print!("{:?} anchor ({:.0},{:.0}) at ({:.0},{:.0}) {} lead {:?}; ", l.text, l.x_px, l.y_px, p.top_left.x, p.top_left.y, p.shown, p.leader_to.map(|v| (v.x as i32, v.y as i32))); } }
        for m in &frame.markers { let c = project_to_canvas(vp, size, m.center.into()).unwrap(); print!("m({:.0},{:.0} {}) ", c.x, c.y, m.size_px); }
        println!();
    }}
}
