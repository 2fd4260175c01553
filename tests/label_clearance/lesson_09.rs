//! Lesson 09: its figures' labels keep clear of what they name (see main.rs).

use super::*;

/// The orbits Figure 4 of lesson 09 is checked from: the page's (lessons/09-skinning/lesson.js)
/// and the page's after the page test's drag (a fifth of a 650 px canvas across, a tenth of its
/// 420 px down, at 0.008 rad a pixel).
const HUMAN_ORBITS: [[f32; 6]; 2] = [
    [0.0, 0.9, 0.0, 3.2, 1.45, 0.15],
    [
        0.0,
        0.9,
        0.0,
        3.2,
        1.45 - 0.008 * 130.0,
        0.15 + 0.008 * 42.0,
    ],
];

#[test]
fn lesson_09_human_pair_names_keep_off_the_bodies_and_the_skeletons() {
    // Both bodies side by side with the skeleton X-rayed and a heat map's joint named, in both
    // views, through the run and the walk, from both orbits: the titles and the joint's names
    // cover no vertex of either body (as skinned, on the CPU, and placed across the view), no
    // joint dot or bone, and no other name. As on the page, the joint's names are placed for
    // the view of the frame before (set_canvas_view).
    use inbetween::draw::MeshId;
    use inbetween::figures::skinning::HumanFigure;
    use inbetween::figures::skinning::{screen_axes, HUMAN_OFFSET_Z};
    let mut failures = Vec::new();
    for clip in ["walk", "run"] {
        for view in ["whole body", "left legs"] {
            for joint in ["pelvis", "thigh.L", "chest"] {
                let mut h = HumanFigure::new();
                h.set_compare(true);
                h.set_clip(clip).unwrap();
                h.set_view(view).unwrap();
                h.set_heat_joint(joint).unwrap();
                h.set_show_skeleton(true);
                for t in [0.0, 0.21, 0.42] {
                    h.skin(t).unwrap();
                    for size in CANVASES {
                        for orbit in HUMAN_ORBITS {
                            // The page's frames before at this orbit: the bodies stand across
                            // its view (they follow the camera's yaw), and the fit holds them.
                            h.set_canvas_view(OrbitCamera::from_view(orbit), size.x, size.y);
                            let (frame, camera) = drawn_for_view(
                                &mut h,
                                orbit,
                                size,
                                |fig, out| {
                                    fig.draw_pair(out, [MeshId(3), MeshId(4)]);
                                },
                                |fig, cam, px| fig.set_canvas_view(cam, px.x, px.y),
                            );
                            let name = format!(
                                "09 pair, {clip} at {t} s, {view}, {joint}, orbit {orbit:?}"
                            );
                            let view_proj = camera.projection(size.x / size.y) * camera.view();
                            // The bodies stand along the camera's right: LBS left, DQS right.
                            let right = HUMAN_OFFSET_Z * screen_axes(&camera).0;
                            let places = [-right, right];
                            let body: Vec<Vec2> = [&h.mesh, &h.mesh_dqs]
                                .into_iter()
                                .zip(places)
                                .flat_map(|(m, place)| m.positions.iter().map(move |p| *p + place))
                                .filter_map(|p| project_to_canvas(view_proj, size, p))
                                .collect();
                            let labels = label_boxes(&frame, &camera, size);
                            failures.extend(failure_of(|| {
                                assert_eq!(labels.len(), 4, "{name} on {size}: all shown");
                                assert_clear(&name, &frame, &camera, size);
                                for (text, rect) in &labels {
                                    let on = body
                                        .iter()
                                        .find(|p| p.cmpgt(rect.min).all() && p.cmplt(rect.max()).all());
                                    assert!(on.is_none(), "{name} on {size}: {text:?} at {:?} covers a body at {on:?}", rect.min);
                                }
                            }));
                        }
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_09_cylinder_names_keep_off_the_tubes_and_each_other() {
    // Figure 1 at its defaults, at the page test's settings (bend 36°, twist −109°, falloff
    // 0.79 m, ring 8) and at a straight and a fully bent elbow, from the page's orbit and the
    // page test's drag: each elbow's name is anchored at the elbow joint and covers neither
    // tube (placed off it, the page draws a leader line); no name covers a dot or line; K₁p's
    // and K₂p's boxes (large text) stay apart. As on the page, the labels are placed for the
    // view of the frame before (set_view).
    use inbetween::draw::layout::{leader, LEADER_PX};
    use inbetween::draw::{MeshId, LABELS_APART_PX};
    use inbetween::figures::skinning::{CylinderFigure, DQS_OFFSET, LBS_OFFSET};
    let orbits = [
        [0.3, 0.7, 0.0, 5.0, 0.0, 0.2],
        [0.3, 0.7, 0.0, 5.0, -0.008 * 130.0, 0.2 + 0.008 * 42.0],
    ];
    let mut failures = Vec::new();
    for (bend, twist, falloff, ring) in [
        (90.0, 0.0, 0.15, 20),
        (36.0, -109.0, 0.79, 8),
        (0.0, 0.0, 0.15, 20),
        (180.0, 45.0, 0.05, 23),
    ] {
        let mut f = CylinderFigure::new();
        f.set_bend_deg(bend).unwrap();
        f.set_twist_deg(twist).unwrap();
        f.set_falloff(falloff).unwrap();
        f.set_probe_ring(ring).unwrap();
        let elbow = f.rig().segments[1].0;
        for size in CANVASES {
            for orbit in orbits {
                let (frame, camera) = drawn_for_view(
                    &mut f,
                    orbit,
                    size,
                    |fig, out| {
                        fig.draw(out, [MeshId(1), MeshId(2)]).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let name = format!("09 cylinder, bend {bend}, twist {twist}, orbit {orbit:?}");
                let tubes: Vec<Vec2> = [(LBS_OFFSET, &f.lbs), (DQS_OFFSET, &f.dqs)]
                    .into_iter()
                    .flat_map(|(o, m)| m.positions.iter().map(move |p| o + *p))
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                let placed = layout(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    assert_clear(&name, &frame, &camera, size);
                    let elbows: Vec<_> = placed
                        .iter()
                        .filter(|(l, _, _)| l.text == "elbow")
                        .collect();
                    assert_eq!(elbows.len(), 2, "{name}");
                    for ((l, b, p), offset) in elbows.into_iter().zip([LBS_OFFSET, DQS_OFFSET]) {
                        let at = project_to_canvas(view_proj, size, offset + elbow).unwrap();
                        assert!(
                            l.dot_px.distance(at) < 0.01,
                            "{name}: anchored at the elbow"
                        );
                        assert!(p.shown, "{name} on {size}: elbow shown");
                        let rect = Rect {
                            min: p.top_left,
                            size: b.size,
                        };
                        let on = tubes
                            .iter()
                            .find(|q| q.cmpgt(rect.min).all() && q.cmplt(rect.max()).all());
                        assert!(
                            on.is_none(),
                            "{name} on {size}: elbow at {:?} covers a tube at {on:?}",
                            rect.min
                        );
                        // Further than a label's height from the joint, it gets a leader line.
                        if rect.nearest(at).distance(at) > LEADER_PX {
                            assert!(leader(rect, at, false).is_some());
                        }
                    }
                    let k: Vec<Rect> = frame
                        .labels
                        .iter()
                        .filter(|l| l.text.starts_with('K'))
                        .map(|l| l.first_place(view_proj, size).unwrap())
                        .collect();
                    if let [a, b] = k[..] {
                        assert!(
                            !a.overlaps(&b, LABELS_APART_PX - 0.5),
                            "{name} on {size}: K₁p and K₂p at {a:?} and {b:?}"
                        );
                    }
                    // Each K name nearer its own grey dot than any other dot of the followed
                    // vertex (teal, orange, the other grey; but one drawn on its own), so that
                    // it names its own.
                    let dots: Vec<Vec2> = frame
                        .markers
                        .iter()
                        .filter_map(|m| project_to_canvas(view_proj, size, Vec3::from(m.center)))
                        .collect();
                    for l in frame.labels.iter().filter(|l| l.text.starts_with('K')) {
                        let rect = l.first_place(view_proj, size).unwrap();
                        let own = project_to_canvas(view_proj, size, l.anchor).unwrap();
                        let gap = |d: Vec2| rect.nearest(d).distance(d);
                        for &d in dots.iter().filter(|d| d.distance(own) > 3.0) {
                            assert!(
                                gap(d) > gap(own),
                                "{name} on {size}: {} {} px from a dot at {d}, {} px from its own",
                                l.text,
                                gap(d),
                                gap(own)
                            );
                        }
                    }
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_09_sign_circle_faces_the_camera_and_its_labels_keep_clear() {
    // Over the whole twist slider, with the fix on and off, from the page's orbit and the page
    // test's (a fifth of a 650 px canvas across, a tenth of its 420 px down, at 0.008 rad a
    // pixel): the circle is seen face-on (as wide as tall on the canvas, never edge-on), and
    // every label is shown, clear of every dot and line. As on the page, the circle and its
    // labels follow the view of the frame before (set_view).
    use inbetween::draw::MeshId;
    use inbetween::figures::skinning::{SignFigure, SIGN_CIRCLE_CENTER, SIGN_CIRCLE_RADIUS};
    let orbits = [
        [0.8, 1.0, 0.0, 5.5, 0.0, 0.1],
        [0.8, 1.0, 0.0, 5.5, -0.008 * 130.0, 0.1 + 0.008 * 42.0],
    ];
    let mut failures = Vec::new();
    for fix in [true, false] {
        for deg in (0..=360).step_by(5) {
            for size in CANVASES {
                for orbit in orbits {
                    let mut scene = SignFigure::new();
                    scene.set_fix(fix);
                    scene.set_twist_deg(deg as f32).unwrap();
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        orbit,
                        size,
                        |fig, out| {
                            fig.draw(out, MeshId(1)).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!("09 sign at {deg}°, fix {fix}, orbit {orbit:?}");
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let (right, up) = scene.circle_axes();
                    let px = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                    let c = SIGN_CIRCLE_CENTER;
                    let wide = px(c + right * SIGN_CIRCLE_RADIUS)
                        .distance(px(c - right * SIGN_CIRCLE_RADIUS));
                    let tall =
                        px(c + up * SIGN_CIRCLE_RADIUS).distance(px(c - up * SIGN_CIRCLE_RADIUS));
                    failures.extend(failure_of(|| {
                        // At 360° −r is 1 (one name for both), and without the fix the
                        // blend cancels (no dot, no name).
                        let full = usize::from(deg == 360);
                        assert_eq!(frame.labels.len(), 6 - full - full * usize::from(!fix));
                        assert!(
                            (wide / tall - 1.0).abs() < 0.1 && tall > 80.0,
                            "{name} on {size}: the circle {wide} px wide, {tall} px tall"
                        );
                        for (l, _, p) in layout(&frame, &camera, size) {
                            assert!(p.shown, "{name} on {size}: {:?} hidden", l.text);
                        }
                        assert_clear(&name, &frame, &camera, size);
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_09_gltf_root_name_keeps_off_the_skin() {
    // Lesson 09's Figure 5 (www/gltf-figure.js: skinned by LBS or DQS on the CPU, the figure's
    // fit, yaw 0.6, pitch 0.15, and orbited round it), both canvases, across the first clip:
    // "root" is shown where the figure put it, covers no triangle of the skinned mesh on the
    // canvas (the root lies inside the body, and a name over the skin hides it) and ends within
    // 128 px of the root's ball, so that it still names it (its leader line runs to the ball).
    // As on the page, the figure places it for the view of the frame before. Without the
    // sample characters (../shared/assets/gltf or INBETWEEN_GLTF_ASSETS) it is not run.
    use inbetween::figures::gltf::GltfFigure;
    let dir = std::env::var_os("INBETWEEN_GLTF_ASSETS")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| {
            std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/assets/gltf")
        });
    if !dir.join("RiggedFigure.gltf").exists() {
        assert!(
            std::env::var_os("INBETWEEN_REQUIRE_ASSETS").is_none(),
            "the glTF sample characters are not in {}",
            dir.display()
        );
        eprintln!("glTF sample characters not found: root label check not run");
        return;
    }
    // Skinned on the GPU (skin on: GPU) too, where the skin the name keeps off is the vertex
    // shader's: the test takes it from a twin figure skinned on the CPU.
    let mut failures = Vec::new();
    for (character, mode, gpu) in [
        ("RiggedFigure", "lbs", false),
        ("RiggedFigure", "dqs", false),
        ("CesiumMan", "lbs", false),
        ("RiggedSimple", "dqs", true),
        ("RiggedFigure", "dqs", true),
        ("CesiumMan", "lbs", true),
    ] {
        let bytes = std::fs::read(dir.join(format!("{character}.gltf"))).unwrap();
        for (yaw, pitch) in [(0.6, 0.15), (-0.6, 0.15), (1.6, 0.3)] {
            for k in 0..4 {
                for size in CANVASES {
                    let mut scene = GltfFigure::new();
                    scene.load(character, &bytes).unwrap();
                    scene.set_skinning(mode).unwrap();
                    scene.set_gpu(gpu);
                    let t = k as f32 / 4.0 * scene.duration_sec();
                    let skin_meshes: Vec<inbetween::draw::SkinMeshId> =
                        (0..scene.bind_meshes().len()).map(inbetween::draw::SkinMeshId).collect();
                    let [x, y, z, distance] = scene.fit();
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        [x, y, z, distance, yaw, pitch],
                        size,
                        |fig, out| {
                            fig.draw_with(out, t, &[], &skin_meshes).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    assert_eq!(scene.gpu_on(), gpu);
                    if gpu {
                        scene.set_gpu(false);
                        scene.draw(&mut Frame::default(), t, &[]).unwrap();
                    }
                    let name = format!(
                        "09 glTF {character} {mode}, gpu {gpu}, t {t}, \
                         orbit ({yaw}, {pitch}) on {size}"
                    );
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let at = |p: Vec3| project_to_canvas(view_proj, size, p);
                    let boxes = label_boxes(&frame, &camera, size);
                    let Some((_, rect)) = boxes.iter().find(|(t, _)| t == "root") else {
                        failures.push(format!("{name}: \"root\" not shown"));
                        continue;
                    };
                    let ball = frame
                        .meshes
                        .iter()
                        .find(|m| m.color.truncate() == inbetween::figures::palette::ORANGE)
                        .unwrap();
                    let ball = at(ball.model.w_axis.truncate()).unwrap();
                    failures.extend(failure_of(|| {
                        let gap = rect.nearest(ball).distance(ball);
                        assert!(
                            gap <= 128.0,
                            "{name}: \"root\" {gap} px from the root's ball"
                        );
                        // Sample the box's inside on a 5 × 3 grid: none inside a triangle.
                        let inside = |p: Vec2, [a, b, c]: [Vec2; 3]| {
                            let s = |u: Vec2, v: Vec2| (v - u).perp_dot(p - u);
                            let (x, y, z) = (s(a, b), s(b, c), s(c, a));
                            (x > 0.0 && y > 0.0 && z > 0.0) || (x < 0.0 && y < 0.0 && z < 0.0)
                        };
                        for m in 0..scene.bind_meshes().len() {
                            let (positions, _) = scene.skinned(m).unwrap();
                            let indices = &scene.bind_meshes()[m].indices;
                            for tri in indices.chunks_exact(3) {
                                let Some(tri) = (|| {
                                    Some([
                                        at(positions[tri[0] as usize])?,
                                        at(positions[tri[1] as usize])?,
                                        at(positions[tri[2] as usize])?,
                                    ])
                                })() else {
                                    continue;
                                };
                                for edge in 0..3 {
                                    assert!(
                                        !enters(tri[edge], tri[(edge + 1) % 3], *rect),
                                        "{name}: \"root\" at {:?} over the skin",
                                        rect.min
                                    );
                                }
                                for i in 0..5 {
                                    for j in 0..3 {
                                        let p = rect.min
                                            + rect.size * Vec2::new(i as f32 / 4.0, j as f32 / 2.0);
                                        assert!(
                                            !inside(p, tri),
                                            "{name}: \"root\" at {:?} over the skin",
                                            rect.min
                                        );
                                    }
                                }
                            }
                        }
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}
