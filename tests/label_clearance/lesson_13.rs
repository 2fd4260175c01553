//! Lesson 13: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_13_drape_name_sits_on_the_cloth() {
    // Figure 3 at its page camera (lessons/13-cloth/lesson.js), both canvases, each method, as
    // the cloth falls and after it has draped: the method's name sits just above the cloth's
    // topmost point on screen (its box's bottom between 12 px above it and 2 px into it), over
    // that point. As on the page, the figure places it for the view of the frame before.
    use inbetween::draw::MeshId;
    use inbetween::figures::cloth::{ClothFigure, Preset};
    let view = [0.5, 0.6, 0.0, 5.0, 0.45, 0.5];
    for method in ["mass-spring", "XPBD"] {
        for size in CANVASES {
            let mut f = ClothFigure::new(Preset::Drape);
            f.set_method(method).unwrap();
            let meshes = [MeshId(10)];
            let mut frame = Frame::default();
            f.draw(&mut frame, &meshes, 0.0).unwrap();
            let camera = page_camera(view, &frame, size);
            f.set_view(camera, size.x, size.y);
            for t in [0.0, 0.3, 0.8, 2.0] {
                let mut frame = Frame::default();
                f.draw(&mut frame, &meshes, t).unwrap();
                let camera = page_camera(view, &frame, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let name = format!("13 drape, {method}, t {t} s");
                let placed = layout(&frame, &camera, size);
                let (l, b, p) = placed
                    .iter()
                    .find(|(l, _, _)| l.text == method)
                    .unwrap_or_else(|| panic!("{name}: no name"));
                assert!(p.shown && p.leader_to.is_none(), "{name}: moved");
                let tops: Vec<Vec2> = f
                    .positions(0)
                    .iter()
                    .filter_map(|q| project_to_canvas(view_proj, size, *q))
                    .collect();
                let (bottom, middle) = (p.top_left.y + b.size.y, p.top_left.x + 0.5 * b.size.x);
                let at = format!("{name} on {size}: {:?}", l.text);
                assert_just_above(&at, bottom, middle, &tops, 12.0, "cloth");
            }
        }
    }
}

#[test]
fn lesson_13_exploded_flag_label_keeps_off_the_poles() {
    // Figure 2 pushed past the stability limit, at its page camera (lessons/13-cloth/lesson.js),
    // both canvases: what happened to the mass-spring flag is said under it, and the label's box
    // keeps 4 px off both brown poles (each a cube mesh from its foot to its top), so that it
    // does not read across the XPBD flag's pole.
    use inbetween::draw::{segment_enters, MeshId};
    use inbetween::figures::cloth::{ClothFigure, Preset};
    let view = [0.0, 1.9, 0.0, 5.0, 0.3, 0.18];
    for size in CANVASES {
        let mut f = ClothFigure::new(Preset::Flag);
        f.set_stiffness("structural", 2000.0).unwrap();
        f.set_substeps(4.0).unwrap();
        let meshes = [MeshId(10), MeshId(11)];
        let mut frame = Frame::default();
        f.draw(&mut frame, &meshes, 1.0).unwrap();
        assert!(f.exploded(0).is_some(), "the mass-spring flag exploded");
        let camera = page_camera(view, &frame, size);
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let poles: Vec<(Vec2, Vec2)> = frame
            .meshes
            .iter()
            .filter(|m| m.mesh == MeshId::CUBE)
            .filter_map(|m| {
                let end = |y: f32| {
                    project_to_canvas(
                        view_proj,
                        size,
                        m.model.transform_point3(Vec3::new(0.0, y, 0.0)),
                    )
                };
                Some((end(-1.0)?, end(1.0)?))
            })
            .collect();
        assert_eq!(poles.len(), 2, "two poles");
        let boxes = label_boxes(&frame, &camera, size);
        let (text, rect) = boxes
            .iter()
            .find(|(t, _)| t.starts_with("exploded at"))
            .unwrap_or_else(|| panic!("{size}: no explosion label among {boxes:?}"));
        for (a, b) in &poles {
            assert!(
                !segment_enters(*a, *b, rect.min - 4.0, rect.max() + 4.0),
                "{size}: {text:?} at {:?} to {:?} runs into the pole from {a} to {b}",
                rect.min,
                rect.max()
            );
        }
    }
}
