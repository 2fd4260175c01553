//! Lesson 10: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_10_head_names_keep_off_the_other_head() {
    // Figure 2 at its page camera (lessons/10-blend-shapes/lesson.js: the figure's view fit,
    // yaw 0.15, pitch 0.1), both canvases: at the defaults, at the largest total (every weight
    // 1.5 and the base 1: the full head 7 times the base beside a small differential head) and
    // at the most negative (−2), each shown head has its name, every name lies on the canvas, and
    // no name covers the other head (its vertices, 4 px round the name). `show` = one head
    // names that head too.
    use inbetween::draw::MeshId;
    use inbetween::figures::blend_shapes::FaceFigure;
    let ids = [MeshId(3), MeshId(4)];
    let mut failures = Vec::new();
    // (every weight, base weight, show)
    let states = [
        (None, 0.0, "both"),
        (Some(1.5), 1.0, "both"),
        (Some(-0.5), 0.0, "both"),
        (None, 0.0, "full"),
        (Some(1.5), 1.0, "full"),
        (None, 0.0, "differential"),
    ];
    for (weight, base, show) in states {
        for size in CANVASES {
            let mut scene = FaceFigure::new();
            if let Some(w) = weight {
                scene.set_animate(false);
                for k in 0..4 {
                    scene.set_weight(k, w).unwrap();
                }
            }
            scene.set_base_weight(base).unwrap();
            scene.set_show(show).unwrap();
            let [x, y, z, distance] = scene.view_fit();
            let view = [x, y, z, distance, 0.15, 0.1];
            let (frame, camera) = drawn_for_view(
                &mut scene,
                view,
                size,
                |fig, out| {
                    fig.draw(out, ids, 1.3).unwrap();
                },
                |_, _, _| {},
            );
            let at = format!("10 face, weights {weight:?}, base {base}, show {show}");
            failures.extend(failure_of(|| {
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let head = |id: MeshId, positions: &[Vec3]| -> Vec<Vec2> {
                    let Some(m) = frame.meshes.iter().find(|m| m.mesh == id) else {
                        return Vec::new();
                    };
                    positions
                        .iter()
                        .filter_map(|p| project_to_canvas(view_proj, size, m.model.transform_point3(*p)))
                        .collect()
                };
                let differential = head(ids[0], &scene.differential.positions);
                let full = head(ids[1], &scene.full.positions);
                let boxes: Vec<(String, Rect)> = label_boxes(&frame, &camera, size)
                    .into_iter()
                    .map(|(text, r)| {
                        (text, Rect { min: r.min - 4.0, size: r.size + 8.0 })
                    })
                    .collect();
                let named = |prefix: &str| boxes.iter().any(|(t, _)| t.starts_with(prefix));
                assert_eq!(named("differential"), show != "full", "{at}: {boxes:?}");
                assert_eq!(named("full (total "), show != "differential", "{at}: {boxes:?}");
                for (text, r) in &boxes {
                    assert!(
                        r.min.cmpge(Vec2::splat(-4.0)).all() && r.max().cmple(size + 4.0).all(),
                        "{at} on {size}: {text:?} at {r:?} leaves the canvas"
                    );
                }
                assert_names_cover_none(&at, size, &boxes, &["differential"], &full, "the full head");
                let full_name: Vec<&str> = boxes
                    .iter()
                    .map(|(t, _)| t.as_str())
                    .filter(|t| t.starts_with("full"))
                    .collect();
                assert_names_cover_none(&at, size, &boxes, &full_name, &differential, "the differential head");
            }));
        }
    }
    assert_none_failed(&failures);
}
