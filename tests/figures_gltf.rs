//! Native tests of lesson 06's glTF figure (src/figures/gltf.rs).

use glam::Vec3;
use inbetween::draw::{palette, Frame, MeshId};
use inbetween::figures::gltf::GltfFigure;
use inbetween::fixtures::tiny_skinned_gltf;

#[test]
fn an_imported_character_is_drawn_as_its_skeleton_and_plays() {
    let mut figure = GltfFigure::new();
    let mut f = Frame::default();
    assert!(figure
        .draw(&mut f, 0.0, &[])
        .unwrap()
        .contains("No character loaded"));
    let summary = figure
        .load("tiny.gltf", tiny_skinned_gltf().as_bytes())
        .unwrap();
    assert!(
        summary.contains("2 joints") && summary.contains("bend 1.000 s"),
        "{summary}"
    );
    assert_eq!(figure.clip_names(), ["bend"]);
    assert_eq!(figure.duration_sec(), 1.0);
    let joints = |f: &Frame| -> Vec<Vec3> {
        f.meshes
            .iter()
            .filter(|m| m.mesh == MeshId::SPHERE)
            .map(|m| m.model.w_axis.truncate())
            .collect()
    };
    f.clear();
    figure.draw(&mut f, 0.0, &[]).unwrap();
    let rest = joints(&f);
    assert_eq!(rest.len(), 2);
    assert!(
        (rest[1] - Vec3::Y).length() < 1e-5,
        "the knee 1 m above the hip: {}",
        rest[1]
    );
    // The clip turns the knee's joint by 90° about z at t = 1; halfway, 45°. The knee is the
    // child, so its own position does not move; the mesh dots are plain grey discs (outlined
    // markers, close together, would read as black rings), and the view keeps the whole
    // character (box and joints) in.
    f.clear();
    let note = figure.draw(&mut f, 0.5, &[]).unwrap();
    assert!(note.contains("Clip \"bend\" at 0.500 s"), "{note}");
    assert_eq!(f.points.len(), 3, "the three vertices as dots");
    assert!(f.markers.is_empty());
    assert!(f
        .points
        .iter()
        .all(|p| p.radius > 0.0 && p.color[..3] == palette::GREY.to_array()));
    let (lo, hi) = f.keep_in_view.iter().fold(
        (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    for p in joints(&f)
        .into_iter()
        .chain(f.points.iter().map(|p| Vec3::from(p.center)))
    {
        assert!(
            p.cmpge(lo).all() && p.cmple(hi).all(),
            "{p} outside {lo}..{hi}"
        );
    }
    assert!(f.strokes.len() == 1, "the bone as a wide line");
    figure.set_show_mesh(false);
    f.clear();
    figure.draw(&mut f, 0.5, &[]).unwrap();
    assert!(f.points.is_empty());
    // A bad file: a clear message, and the character loaded before stays.
    let err = figure.load("broken.gltf", b"{ not json").unwrap_err();
    assert!(err.starts_with("broken.gltf: not a valid glTF"), "{err}");
    assert_eq!(figure.clip_names(), ["bend"]);
    assert!(figure.set_clip(3).is_err());
    assert!(figure.draw(&mut f, f32::NAN, &[]).is_err());
    let [_, _, _, distance] = figure.fit();
    assert!(distance > 1.0 && distance < 10.0, "{distance}");
    // Skinned: the first vertex is bound to the knee alone (weight 1), whose inverse bind is the
    // identity in this file, so it sits at the knee's world position; LBS and DQS agree there.
    figure.set_show_mesh(true);
    figure.set_skinning("lbs").unwrap();
    assert!(figure.skinning_on());
    f.clear();
    let note = figure.draw(&mut f, 0.0, &[MeshId(9)]).unwrap();
    assert!(note.contains("Skinned by LBS"), "{note}");
    assert!(f.meshes.iter().any(|m| m.mesh == MeshId(9)));
    assert!(f.points.is_empty(), "no dots while skinned");
    let knee = joints(&f)[1];
    let (p, _) = figure.skinned(0).unwrap();
    assert!((p[0] - knee).length() < 1e-5, "{} vs {knee}", p[0]);
    let lbs = p.to_vec();
    figure.set_skinning("dqs").unwrap();
    f.clear();
    figure.draw(&mut f, 0.0, &[MeshId(9)]).unwrap();
    let (p, _) = figure.skinned(0).unwrap();
    assert!((p[0] - lbs[0]).length() < 1e-5);
    // Over the skin the root's name is dark (orange text on RiggedSimple's beige tube does not
    // read); on the skeleton and dots alone, orange as the root's ball.
    let root_color = |f: &Frame| f.labels.iter().find(|l| l.text == "root").unwrap().color;
    assert_eq!(root_color(&f), palette::DARK);
    figure.set_skinning("dots").unwrap();
    f.clear();
    figure.draw(&mut f, 0.0, &[MeshId(9)]).unwrap();
    assert_eq!(root_color(&f), palette::ORANGE);
    figure.set_skinning("dqs").unwrap();
    // Lesson 09's bind-pose vertices: the dots over the skinned mesh, which stays.
    figure.set_show_bind_pose(true);
    f.clear();
    let note = figure.draw(&mut f, 0.0, &[MeshId(9)]).unwrap();
    assert!(
        f.meshes.iter().any(|m| m.mesh == MeshId(9)),
        "the mesh stays"
    );
    assert_eq!(f.points.len(), 3);
    assert!(
        note.contains("Grey dots: the mesh's vertices in the bind pose"),
        "{note}"
    );
    figure.set_show_bind_pose(false);
    assert!(figure.set_skinning("gpu").is_err());
}

#[test]
fn after_a_rejected_file_the_note_says_what_is_still_shown() {
    let mut figure = GltfFigure::new();
    let mut f = Frame::default();
    // Nothing loaded yet, then a bad file: the reason, and that nothing is shown.
    figure.load("broken.gltf", b"{ not json").unwrap_err();
    let note = figure.draw(&mut f, 0.0, &[]).unwrap();
    assert!(
        note.starts_with("Could not load broken.gltf: not a valid glTF")
            && note.contains("No character loaded"),
        "{note}"
    );
    // A good file: its summary, then what is drawn.
    figure
        .load("tiny.gltf", tiny_skinned_gltf().as_bytes())
        .unwrap();
    let note = figure.draw(&mut f, 0.5, &[]).unwrap();
    assert!(
        note.starts_with("tiny.gltf: 2 joints") && note.contains("Clip \"bend\" at 0.500 s"),
        "{note}"
    );
    assert!(!note.contains("Could not load"), "{note}");
    // A bad file after it: the note says the file was rejected and why, and that the character
    // still drawn is the one loaded before (not the rejected file).
    figure.load("broken.gltf", b"{ not json").unwrap_err();
    let note = figure.draw(&mut f, 0.5, &[]).unwrap();
    assert!(
        note.starts_with("Could not load broken.gltf: not a valid glTF"),
        "{note}"
    );
    assert!(
        note.contains("The file was rejected: the figure still shows tiny.gltf, loaded before."),
        "{note}"
    );
    assert!(!note.contains(".."), "{note}");
    assert!(
        !note.contains("tiny.gltf: 2 joints"),
        "the old summary is gone: {note}"
    );
    // The next good load clears the message.
    figure
        .load("tiny.gltf", tiny_skinned_gltf().as_bytes())
        .unwrap();
    let note = figure.draw(&mut f, 0.5, &[]).unwrap();
    assert!(note.starts_with("tiny.gltf: 2 joints"), "{note}");
}

#[test]
fn a_file_too_big_to_copy_is_rejected_like_any_other() {
    // The web layer checks a file's size before copying it into wasm memory and hands the
    // rejection to the figure: the note and the character shown are as for a file the importer
    // rejected.
    let mut figure = GltfFigure::new();
    figure
        .load("tiny.gltf", tiny_skinned_gltf().as_bytes())
        .unwrap();
    let clips = figure.clip_names();
    let e = figure.reject(
        "huge.glb",
        "the file has 99999999999 bytes; the importer reads at most 67108864",
    );
    assert_eq!(
        e,
        "huge.glb: the file has 99999999999 bytes; the importer reads at most 67108864"
    );
    assert!(figure.is_loaded());
    assert_eq!(figure.clip_names(), clips);
    let note = figure.draw(&mut Frame::default(), 0.0, &[]).unwrap();
    assert!(
        note.starts_with("Could not load huge.glb: the file has 99999999999 bytes")
            && note.contains("the figure still shows tiny.gltf, loaded before."),
        "{note}"
    );
}

/// Lesson 09 Figure 5 frames the skinned mesh wherever the clip takes it: at the page's camera
/// (the scene's fit, yaw 0.6, pitch 0.15) fitted as the viewer does, on the canvases the page
/// gives it at 800 × 600 and 1600 × 1000, every skinned vertex, every joint and every
/// bind-pose dot lies inside the canvas, through the clip, with LBS and DQS, the bind-pose dots
/// on and off. The tiny file's triangle is given a vertex 2 m out along the knee's x axis, which
/// the clip's quarter turn raises above everything in the rest pose: the rest pose's box and the
/// joints alone let it leave the canvas at the top.
#[test]
fn the_skinned_mesh_stays_in_view_through_the_clip() {
    use glam::Vec2;
    use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
    use inbetween::gltf_import::{import, wire};
    let mut imported = import(tiny_skinned_gltf().as_bytes()).unwrap();
    let knee = imported.skeleton.find("knee (node 2)").unwrap();
    let mesh = &mut imported.meshes[0];
    // The rest pose puts the knee's origin at (0, 1, 0): a vertex at the knee's (2, 0, 0).
    let bind = imported.inverse_bind[knee].inverse();
    mesh.positions[1] = bind.transform_point3(Vec3::new(2.0, 0.0, 0.0));
    mesh.joints[1] = [knee as u16, 0, 0, 0];
    mesh.weights[1] = [1.0, 0.0, 0.0, 0.0];
    let bytes = wire::encode(&imported).unwrap();
    for mode in ["lbs", "dqs"] {
        for dots in [false, true] {
            let mut figure = GltfFigure::new();
            figure.load_imported("long.gltf", &bytes).unwrap();
            figure.set_skinning(mode).unwrap();
            figure.set_show_bind_pose(dots);
            let [x, y, z, distance] = figure.fit();
            for k in 0..=20 {
                let time_sec = k as f32 * 0.05;
                let mut f = Frame::default();
                figure.draw(&mut f, time_sec, &[MeshId(100)]).unwrap();
                let (skinned, _) = figure.skinned(0).unwrap();
                let dots_drawn: Vec<Vec3> = f.points.iter().map(|p| Vec3::from(p.center)).collect();
                let joints: Vec<Vec3> = f
                    .meshes
                    .iter()
                    .filter(|m| m.mesh == MeshId::SPHERE)
                    .map(|m| m.model.w_axis.truncate())
                    .collect();
                for size in crate::label_clearance::CANVASES {
                    let mut camera = OrbitCamera::from_view([x, y, z, distance, 0.6, 0.15]);
                    camera.fit(&f.fit_points(), size, FIT_PAD_PX);
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    for p in skinned.iter().chain(&dots_drawn).chain(&joints) {
                        let s = project_to_canvas(view_proj, size, *p).unwrap();
                        assert!(
                            s.cmpge(Vec2::ZERO).all() && s.cmple(size).all(),
                            "{mode}, dots {dots}, t {time_sec} on {size}: {p} lands at {s}"
                        );
                    }
                }
            }
        }
    }
}

/// The floor lies under the model: a file whose mesh reaches below its origin (RiggedSimple's
/// tube is centred on it) has the grid at its lowest point, not through its middle. The tiny
/// file's triangle is given a vertex half a metre below the origin.
#[test]
fn the_floor_lies_under_the_lowest_point_of_the_model() {
    use inbetween::gltf_import::{import, wire};
    let mut imported = import(tiny_skinned_gltf().as_bytes()).unwrap();
    let tiny = wire::encode(&imported).unwrap();
    imported.meshes[0].positions[1] = Vec3::new(0.0, -0.5, 0.0);
    let low = wire::encode(&imported).unwrap();
    for (name, bytes) in [("tiny.gltf", tiny), ("low.gltf", low)] {
        let mut figure = GltfFigure::new();
        figure.load_imported(name, &bytes).unwrap();
        let mut f = Frame::default();
        figure.draw(&mut f, 0.0, &[]).unwrap();
        let lowest = f.points.iter().map(|p| p.center[1]).fold(f32::MAX, f32::min);
        let grid: Vec<f32> = f
            .lines
            .iter()
            .filter(|v| [palette::GRID, palette::GRID_AXIS].contains(&Vec3::from_slice(&v.color[..3])))
            .map(|v| v.position[1])
            .collect();
        assert!(!grid.is_empty(), "{name}: a floor");
        for y in grid {
            assert!(y <= lowest + 1e-4, "{name}: the floor at {y}, the model down to {lowest}");
        }
        if name == "low.gltf" {
            assert!((lowest + 0.5).abs() < 1e-4, "the moved vertex is drawn: {lowest}");
        }
    }
}
