//! Lesson 00: its figures' labels keep clear of what they name (see main.rs).

use super::*;

/// Figure 3's canvases: 300 px tall (lessons/00-triangles-to-pixels/index.html), as wide as
/// [`CANVASES`].
const DEPTH_CANVASES: [Vec2; 2] = [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)];

#[test]
fn lesson_00_depth_side_view_labels_keep_off_the_bars_and_the_line() {
    // The page's defaults (lessons/00-triangles-to-pixels/lesson.js): 16 bits, 0.1 m to 1 km.
    // As on the page, the figure places its labels for the view of the frame before.
    let view = [0.0, 3.0, -20.0, 30.0, 1.2, 0.45];
    for size in DEPTH_CANVASES {
        let mut scene = inbetween::figures::raster::DepthPrecision::new();
        scene.set(0.1, 1000.0, 0.01, 16.0).unwrap();
        let (frame, camera) = drawn!(&mut scene, view, size);
        assert_clear("00 depth", &frame, &camera, size);
    }
}

#[test]
fn lesson_00_point_and_image_labels_stay_apart_where_the_point_crosses_the_near_plane() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js), both canvases,
    // through the first third of the point's path (t = 0.2 s of the 6 s timeline is s ≈ 0.07,
    // where the point crosses z_near and its dot meets its image's), for the page's point and
    // two others: "p" and "image" stay where the figure put them (no leader line), keep a few
    // pixels from each other, and cover neither dot nor the dashed ray from the eye.
    use inbetween::draw::palette;
    use inbetween::figures::raster::Frustum;
    for (x, y) in [(0.6, 0.3), (0.9, 0.2), (1.0, -0.2)] {
        let mut scene = Frustum::new();
        scene.set_offset(x, y).unwrap();
        for k in 0..=30 {
            let s = k as f32 * 0.01;
            let mut frame = Frame::default();
            scene.draw(&mut frame, s).unwrap();
            for size in CANVASES {
                let camera = page_camera([4.5, 1.2, -4.0, 17.0, 0.45, 0.45], &frame, size);
                let name = format!("00 frustum, point ({x}, {y}), s {s}");
                let mut pair = frame.clone();
                // The point's label in the frustum (the NDC box's comes later) and the image's.
                let p = pair.labels.iter().position(|l| l.text == "p").unwrap();
                let image = pair.labels.iter().position(|l| l.text == "image").unwrap();
                pair.labels = vec![pair.labels[p].clone(), pair.labels[image].clone()];
                // The ray from the eye (grey, dashed); the frustum's edges pass the point and
                // its image near the apex.
                pair.strokes
                    .retain(|s| s.color[..3] == palette::GREY.to_array() && s.dash[3] > 0.0);
                assert_clear(&name, &pair, &camera, size);
                let placed = layout(&frame, &camera, size);
                let boxes: Vec<Rect> = [p, image]
                    .map(|i| {
                        let (l, b, at) = &placed[i];
                        assert!(at.shown, "{name} on {size}: {:?} hidden", l.text);
                        assert!(
                            at.leader_to.is_none(),
                            "{name} on {size}: {:?} moved",
                            l.text
                        );
                        Rect {
                            min: at.top_left,
                            size: b.size,
                        }
                    })
                    .into();
                assert!(
                    !boxes[0].overlaps(&boxes[1], 4.0),
                    "{name} on {size}: \"p\" at {:?} and \"image\" at {:?} crowd",
                    boxes[0].min,
                    boxes[1].min
                );
            }
        }
    }
}

#[test]
fn lesson_00_light_label_sits_on_its_lamp() {
    // Figure 5 at its page camera (lessons/00-triangles-to-pixels/lesson.js), both canvases,
    // the page's light and two others: "light" is shown beside the lamp's dot (its box within
    // 12 px of the dot's edge; 0.25 m up left a 20 px gap), covering no dot or line.
    use inbetween::draw::MeshId;
    use inbetween::figures::raster::Shading;
    for (azimuth, elevation) in [(40.0, 35.0), (-60.0, 10.0), (120.0, 70.0)] {
        let mut scene = Shading::new();
        scene.set_light_deg(azimuth, elevation).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame, MeshId(1));
        for size in CANVASES {
            let camera = page_camera([0.0, 1.5, 0.0, 7.5, -0.5, 0.55], &frame, size);
            let name = format!("00 shading, light at {azimuth}°, {elevation}°");
            let mut light = frame.clone();
            light.labels.retain(|l| l.text == "light");
            assert_clear(&name, &light, &camera, size);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let lamp = frame.markers.iter().find(|m| m.size_px == 16.0).unwrap();
            let dot = project_to_canvas(view_proj, size, Vec3::from(lamp.center)).unwrap();
            let (_, rect) = label_boxes(&light, &camera, size).pop().unwrap();
            let gap = rect.nearest(dot).distance(dot) - 8.0;
            assert!(
                gap <= 12.0,
                "{name} on {size}: \"light\" {gap} px from its lamp"
            );
        }
    }
}

#[test]
fn lesson_00_ndc_box_labels_keep_off_its_lines() {
    // Figure 2's NDC box at its page camera (lessons/00-triangles-to-pixels/lesson.js), both
    // canvases, along the point's path, for the page's point and two others: "depth 0",
    // "depth 1", "NDC (wgpu)" and the box's "p" stay where the figure put them and keep 2 px
    // off every line and dot (three lines meet at each corner the depth labels name, and the
    // point's dot moves among them). As on the page, the figure places them for the view of
    // the frame before.
    use inbetween::figures::raster::Frustum;
    let mut failures = Vec::new();
    for (x, y) in [(0.6, 0.3), (0.9, 0.2), (-1.0, -0.4)] {
        for k in 0..=10 {
            let s = k as f32 * 0.1;
            for size in CANVASES {
                let mut scene = Frustum::new();
                scene.set_offset(x, y).unwrap();
                let mut frame = Frame::default();
                scene.draw(&mut frame, s).unwrap();
                let camera = page_camera([4.5, 1.2, -4.0, 17.0, 0.45, 0.45], &frame, size);
                scene.set_view(camera, size.x, size.y);
                let mut frame = Frame::default();
                scene.draw(&mut frame, s).unwrap();
                let camera = page_camera([4.5, 1.2, -4.0, 17.0, 0.45, 0.45], &frame, size);
                let texts: Vec<&str> = frame.labels.iter().map(|l| l.text.as_str()).collect();
                let mut checked: Vec<usize> = ["depth 0", "depth 1", "NDC (wgpu)"]
                    .iter()
                    .map(|t| texts.iter().position(|l| l == t).unwrap())
                    .collect();
                // The box's p (drawn while the point is in front of the eye) comes after the
                // frustum's p and image.
                let image = texts.iter().position(|l| *l == "image").unwrap();
                checked.extend(texts.iter().rposition(|l| *l == "p").filter(|&i| i > image));
                let name = format!("00 NDC box, point ({x}, {y}), s {s}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &checked, 2.0)
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_eye_and_z_near_labels_stay_apart_at_a_small_z_near() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js), both canvases,
    // across the z_near slider's low end (0.05 m, the lesson's 0.1 m and 0.2 m) and at the
    // page's 1 m, along the point's path: near the eye the near plane's corner, which "z_near"
    // names, is a few pixels from the eye's dot and from the point's image, so "eye", "z_near"
    // and "image" sit at least LABELS_APART_PX apart, each where the figure put it (no leader
    // line), and "z_near" and "image" cover no dot. As on the page, the figure places them for
    // the view of the frame before.
    use inbetween::draw::LABELS_APART_PX;
    use inbetween::figures::raster::Frustum;
    let view = [4.5, 1.2, -4.0, 17.0, 0.45, 0.45];
    let mut failures = Vec::new();
    for near in [0.05, 0.1, 0.15, 0.2, 0.5, 1.0] {
        for s in [0.0, 0.03, 0.07, 0.15, 0.5, 1.0] {
            for size in CANVASES {
                let mut scene = Frustum::new();
                scene.set_frustum(50.0, near, 8.0).unwrap();
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    view,
                    size,
                    |fig, out| {
                        fig.draw(out, s).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let name = format!("00 frustum, z_near {near}, s {s}");
                let index = |t: &str| frame.labels.iter().position(|l| l.text == t).unwrap();
                let (eye, z_near, image) = (index("eye"), index("z_near"), index("image"));
                let placed = layout(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    let boxes = [eye, z_near, image].map(|i| {
                        let (l, b, at) = &placed[i];
                        assert!(
                            at.shown && at.leader_to.is_none(),
                            "{name} on {size}: {:?} moved",
                            l.text
                        );
                        Rect {
                            min: at.top_left,
                            size: b.size,
                        }
                    });
                    for (a, b) in [(0, 1), (1, 2), (0, 2)] {
                        assert!(
                            !boxes[a].overlaps(&boxes[b], LABELS_APART_PX - 0.5),
                            "{name} on {size}: {:?} at {:?} and {:?} at {:?} butt",
                            frame.labels[[eye, z_near, image][a]].text,
                            boxes[a].min,
                            frame.labels[[eye, z_near, image][b]].text,
                            boxes[b].min
                        );
                    }
                    let mut only = frame.clone();
                    only.labels = vec![frame.labels[z_near].clone(), frame.labels[image].clone()];
                    only.strokes.clear();
                    assert_clear(&name, &only, &camera, size);
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_depth_eye_and_fighting_labels_keep_off_the_floor_and_bars_when_orbited() {
    // Figure 3 at its page camera (lessons/00-triangles-to-pixels/lesson.js) and orbited round
    // it (azimuths round the side view, from low to steep), both canvases, at the page's
    // settings and with half the gap (the fighting line nearer, at 10.9 m): "eye", "fighting
    // from here" and the bars' and the grey line's names are shown where the figure put them
    // (so none sits on another), keep 2 px off every dot and line, and cover no point of the
    // upper floor (a mesh, sampled here every half metre). As on the page, the figure places
    // them for the view of the frame before.
    use inbetween::figures::raster::DepthPrecision;
    const NAMES: [&str; 4] = [
        "eye",
        "fighting from here",
        "one depth step (×40)",
        "separation d·gap/h (×40)",
    ];
    let mut failures = Vec::new();
    for gap in [0.01, 0.005] {
        for (yaw, pitch) in [
            (1.2, 0.45),
            (0.6, 0.45),
            (0.0, 0.3),
            (-0.6, 0.45),
            (1.8, 0.3),
            (2.6, 0.45),
            (1.2, 0.9),
            (0.3, 1.1),
            (1.2, 0.1),
        ] {
            let view = [0.0, 3.0, -20.0, 30.0, yaw, pitch];
            for size in DEPTH_CANVASES {
                let mut scene = DepthPrecision::new();
                scene.set(0.1, 1000.0, gap, 16.0).unwrap();
                let (frame, camera) = drawn!(&mut scene, view, size);
                let name = format!("00 depth, gap {gap}, orbit ({yaw}, {pitch})");
                let named: Vec<usize> = (0..frame.labels.len())
                    .filter(|&i| NAMES.contains(&&*frame.labels[i].text))
                    .collect();
                assert_eq!(named.len(), NAMES.len(), "{name}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
                }));
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let floor: Vec<Vec2> = (0..=4)
                    .flat_map(|i| {
                        (0..=80)
                            .map(move |k| Vec3::new(-1.0 + 0.5 * i as f32, 0.0, -0.5 * k as f32))
                    })
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                let boxes = label_boxes(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    for (text, rect) in boxes.iter().filter(|(t, _)| NAMES.contains(&&**t)) {
                        for c in &floor {
                            assert!(
                                !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                                "{name} on {size}: {text:?} at {:?} covers the floor at {c}",
                                rect.min
                            );
                        }
                    }
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

/// The canvas disc (centre, radius) of a unit sphere at `centre` on `camera`'s view: the
/// farthest of 26 points round it from its centre's projection.
fn sphere_disc(centre: Vec3, camera: &OrbitCamera, size: Vec2) -> (Vec2, f32) {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let at = |p| project_to_canvas(view_proj, size, p).unwrap();
    let c = at(centre);
    let mut r: f32 = 0.0;
    for x in -1..=1 {
        for y in -1..=1 {
            for z in -1..=1 {
                let d = Vec3::new(x as f32, y as f32, z as f32).normalize_or_zero();
                r = r.max(at(centre + d).distance(c));
            }
        }
    }
    (c, r)
}

#[test]
fn lesson_00_mesh_names_keep_off_both_spheres_when_orbited() {
    // Figure 1 (lessons/00-triangles-to-pixels/lesson.js: target (0, 1.2, 0), distance 5.6,
    // yaw 0, pitch 0.3), orbited round (a drag across the canvas turns it by up to 1.6 rad), at
    // 8 and 51 segments: each sphere's name covers neither sphere's disc (a name over the other
    // sphere reads as its name) nor a dot or line, where the figure put it.
    use inbetween::figures::raster::MeshStorage;
    let mut failures = Vec::new();
    for segments in [8.0, 51.0] {
        for yaw in [-1.6, -1.04, -0.5, 0.0, 0.5, 1.04, 1.6] {
            for pitch in [0.1, 0.3, 0.64] {
                for size in CANVASES {
                    failures.extend(failure_of(|| {
                        let mut scene = MeshStorage::new();
                        scene.set_segments(segments).unwrap();
                        let view = [0.0, 1.2, 0.0, 5.6, yaw, pitch];
                        let (frame, camera) = drawn!(&mut scene, view, size);
                        let name =
                            format!("00 mesh, {segments} segments, yaw {yaw}, pitch {pitch}");
                        let discs =
                            [-1.4, 1.4].map(|x| sphere_disc(Vec3::new(x, 1.2, 0.0), &camera, size));
                        let placed = layout(&frame, &camera, size);
                        for (i, (l, b, p)) in placed.iter().enumerate() {
                            if !(l.text.starts_with("triangle soup")
                                || l.text.starts_with("indexed"))
                            {
                                continue;
                            }
                            let rect = Rect {
                                min: p.top_left,
                                size: b.size,
                            };
                            for (c, r) in discs {
                                assert!(
                                    rect.nearest(c).distance(c) > r,
                                    "{name} on {size}: {:?} at {:?} over the sphere at {c}",
                                    l.text,
                                    rect.min
                                );
                            }
                            assert_shown_clear_by(&name, &frame, &camera, size, &[i], 0.0);
                        }
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_tetrahedron_numbers_keep_off_its_lines_and_apart() {
    // Figure 1 with the tetrahedron, at its page camera and orbited: the triangles' names (t0
    // to t3) and the positions' numbers (0 to 3) cover no dot or line (keeping 2 px off them:
    // a number on an edge reads as the edge's) and keep 2 px from each other.
    use inbetween::figures::raster::MeshStorage;
    let mut failures = Vec::new();
    for yaw in [-1.04, -0.5, 0.0, 0.5, 1.04] {
        for pitch in [0.1, 0.3, 0.64] {
            for size in CANVASES {
                failures.extend(failure_of(|| {
                    let mut scene = MeshStorage::new();
                    scene.set_shape("tetrahedron").unwrap();
                    let view = [0.0, 1.2, 0.0, 5.6, yaw, pitch];
                    let (frame, camera) = drawn!(&mut scene, view, size);
                    let name = format!("00 tetrahedron, yaw {yaw}, pitch {pitch}");
                    let small: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| frame.labels[i].text.len() <= 2)
                        .collect();
                    assert_eq!(small.len(), 8, "{name}: four t-names and four numbers");
                    assert_shown_clear_by(&name, &frame, &camera, size, &small, 2.0);
                    let placed = layout(&frame, &camera, size);
                    let boxes: Vec<(String, Rect)> = small
                        .iter()
                        .map(|&i| {
                            let (l, b, p) = &placed[i];
                            (
                                l.text.clone(),
                                Rect {
                                    min: p.top_left,
                                    size: b.size,
                                },
                            )
                        })
                        .collect();
                    for (i, (a, ra)) in boxes.iter().enumerate() {
                        for (b, rb) in &boxes[i + 1..] {
                            assert!(
                                !ra.overlaps(rb, 2.0),
                                "{name} on {size}: {a:?} at {:?} touches {b:?} at {:?}",
                                ra.min,
                                rb.min
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
fn lesson_00_ndc_box_keeps_its_size_beside_a_wide_frustum() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js) with the field of
    // view and z_far at the top of their sliders: the far plane is many times wider than at the
    // defaults, and the NDC box beside it must still span at least an eighth of the canvas's
    // width, as it does at the defaults, rather than shrink to a few pixels.
    use inbetween::figures::raster::Frustum;
    for (fov, near, far) in [
        (50.0, 1.0, 8.0),
        (121.0, 3.95, 15.9),
        (150.0, 1.0, 20.0),
        (90.0, 0.1, 20.0),
    ] {
        let mut scene = Frustum::new();
        scene.set_frustum(fov, near, far).unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame, 0.5).unwrap();
        for size in CANVASES {
            let camera = page_camera([4.5, 1.2, -4.0, 17.0, 0.45, 0.45], &frame, size);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            // The box's edges are its teal lines (near face to far face).
            let teal = inbetween::figures::raster::frustum_colors::NDC_BOX.to_array();
            let xs: Vec<f32> = frame
                .strokes
                .iter()
                .filter(|s| s.color[..3] == teal)
                .flat_map(|s| [s.a, s.b])
                .map(|p| project_to_canvas(view_proj, size, Vec3::from(p)).unwrap().x)
                .collect();
            assert_eq!(xs.len(), 8, "four teal edges");
            // The whole frustum and the box fit the canvas (the camera's distance is capped,
            // so a frustum drawn at its full width would run off the edges).
            for p in &frame.keep_in_view {
                let c = project_to_canvas(view_proj, size, *p).unwrap();
                assert!(
                    c.cmpge(Vec2::ZERO).all() && c.cmple(size).all(),
                    "fov {fov}, z_near {near}, z_far {far} on {size}: {p} off the canvas at {c}"
                );
            }
            let width = xs.iter().fold(f32::MIN, |m, &x| m.max(x))
                - xs.iter().fold(f32::MAX, |m, &x| m.min(x));
            assert!(
                width > size.x / 8.0,
                "fov {fov}, z_near {near}, z_far {far} on {size}: the NDC box {width} px wide"
            );
        }
    }
}

#[test]
fn lesson_00_frustum_names_keep_off_the_lines_at_a_wide_field_of_view_when_orbited() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js) and orbited as a
    // drag across the canvas does (yaw down by up to 1 rad, pitch up), both canvases, at the
    // page's settings and at a wide field of view with a far z_far (the frustum drawn short, its
    // far plane's corner beside the NDC box) and the point below and left: "eye", "image",
    // "z_far", "depth 0" and "depth 1" stay where the figure put them and keep 2 px off every
    // line and dot. As on the page, the figure places them for the view of the frame before.
    use inbetween::figures::raster::Frustum;
    const NAMES: [&str; 5] = ["eye", "image", "z_far", "depth 0", "depth 1"];
    let mut failures = Vec::new();
    for (fov, near, far, x, y) in [
        (50.0, 1.0, 8.0, 0.6, 0.3),
        (121.0, 3.95, 15.9, -1.8, -1.8),
        (100.0, 2.0, 12.0, 0.6, 0.3),
    ] {
        for (yaw, pitch) in [(0.45, 0.45), (-0.1, 0.6), (-0.59, 0.79)] {
            for s in [0.2, 0.37, 0.6] {
                for size in CANVASES {
                    let mut scene = Frustum::new();
                    scene.set_frustum(fov, near, far).unwrap();
                    scene.set_offset(x, y).unwrap();
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        [4.5, 1.2, -4.0, 17.0, yaw, pitch],
                        size,
                        |fig, out| {
                            fig.draw(out, s).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let named: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| NAMES.contains(&&*frame.labels[i].text))
                        .collect();
                    let name = format!("00 frustum {fov}° {near}-{far} m, orbit ({yaw}, {pitch}), s {s}");
                    assert_eq!(named.len(), NAMES.len(), "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_tetrahedron_soup_triangles_stay_apart_on_the_canvas() {
    // Figure 1 with the tetrahedron at its page camera (lessons/00-triangles-to-pixels/lesson.js:
    // yaw 0, pitch 0.3) and orbited as the page test's drag turns it (yaw by -1.04 or -1.22 rad,
    // pitch by 0.3 or 0.34) and the other way, both canvases: the soup's four triangles (orange,
    // three strokes each) are pulled apart so far that no two cross or touch on the canvas (at
    // least 3 px between them), and can be counted.
    use inbetween::figures::raster::{MeshStorage, SOUP_COLOR};
    let inside = |p: Vec2, t: &[Vec2; 3]| {
        let side = |a: Vec2, b: Vec2| (b - a).perp_dot(p - a);
        let s = [side(t[0], t[1]), side(t[1], t[2]), side(t[2], t[0])];
        s.iter().all(|&x| x >= 0.0) || s.iter().all(|&x| x <= 0.0)
    };
    let seg_dist = |p: Vec2, a: Vec2, b: Vec2| {
        let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        p.distance(a + (b - a) * t)
    };
    let mut failures = Vec::new();
    for (yaw, pitch) in [(0.0, 0.3), (-1.04, 0.6), (-1.22, 0.64), (1.04, 0.6), (-0.5, 0.1)] {
        for size in CANVASES {
            failures.extend(failure_of(|| {
                let mut scene = MeshStorage::new();
                scene.set_shape("tetrahedron").unwrap();
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    [0.0, 1.2, 0.0, 5.6, yaw, pitch],
                    size,
                    |fig, out| {
                        fig.draw(out);
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let at = |p: [f32; 3]| project_to_canvas(view_proj, size, Vec3::from(p)).unwrap();
                let soup: Vec<[Vec2; 3]> = frame
                    .strokes
                    .iter()
                    .filter(|s| s.color[..3] == SOUP_COLOR.to_array())
                    .collect::<Vec<_>>()
                    .chunks_exact(3)
                    .map(|t| [at(t[0].a), at(t[1].a), at(t[2].a)])
                    .collect();
                assert_eq!(soup.len(), 4, "four triangles");
                for (i, a) in soup.iter().enumerate() {
                    for (j, b) in soup.iter().enumerate().skip(i + 1) {
                        let mut gap = f32::MAX;
                        for (s, t) in [(a, b), (b, a)] {
                            for p in s {
                                assert!(
                                    !inside(*p, t),
                                    "yaw {yaw}, pitch {pitch} on {size}: t{i} and t{j} overlap"
                                );
                                for k in 0..3 {
                                    gap = gap.min(seg_dist(*p, t[k], t[(k + 1) % 3]));
                                }
                            }
                        }
                        assert!(
                            gap >= 3.0,
                            "yaw {yaw}, pitch {pitch} on {size}: t{i} and t{j} {gap} px apart"
                        );
                    }
                }
            }));
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_frustum_keeps_clear_of_the_ndc_box_at_every_field_of_view() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js) and orbited as the
    // page test's drag turns it (yaw down by about 1 rad, pitch up by 0.34), both canvases, the
    // field of view over its whole slider (10° to 150°) with a short, the page's and a far
    // z_far: no line of the frustum (its planes, edges and the ray to the point) comes within
    // 6 px of the NDC box's outline on the canvas, so the two never read as one drawing.
    use inbetween::figures::raster::{frustum_colors::NDC_BOX, Frustum};
    // The convex hull of `points` (counter-clockwise on the canvas, y down: clockwise as seen).
    let hull = |mut p: Vec<Vec2>| {
        p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        let cross = |o: Vec2, a: Vec2, b: Vec2| (a - o).perp_dot(b - o);
        let mut h: Vec<Vec2> = Vec::new();
        for pass in [p.clone(), p.into_iter().rev().collect()] {
            let start = h.len();
            for q in pass {
                while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                    h.pop();
                }
                h.push(q);
            }
            h.pop();
        }
        h
    };
    let seg_dist = |q: Vec2, a: Vec2, b: Vec2| {
        let t = ((q - a).dot(b - a) / (b - a).length_squared().max(1e-12)).clamp(0.0, 1.0);
        q.distance(a + (b - a) * t)
    };
    let mut failures = Vec::new();
    let fovs = (10..=150).step_by(10).chain([121, 145]);
    for fov in fovs {
        for (near, far) in [(1.0, 8.0), (3.95, 15.9), (0.1, 20.0), (1.0, 2.0)] {
            for (size, (yaw, pitch)) in CANVASES.into_iter().flat_map(|size| {
                [(0.45, 0.45), (-0.59, 0.79), (-0.77, 0.79)].map(|orbit| (size, orbit))
            }) {
                failures.extend(failure_of(|| {
                    let mut scene = Frustum::new();
                    scene.set_frustum(fov as f32, near, far).unwrap();
                    scene.set_offset(-1.8, -1.8).unwrap();
                    let mut frame = Frame::default();
                    scene.draw(&mut frame, 0.5).unwrap();
                    let camera = page_camera([4.5, 1.2, -4.0, 17.0, yaw, pitch], &frame, size);
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let at = |p: [f32; 3]| project_to_canvas(view_proj, size, Vec3::from(p)).unwrap();
                    // The box's corners: the ends of its four teal edges.
                    let corners: Vec<[f32; 3]> = (frame.strokes.iter())
                        .filter(|s| s.color[..3] == NDC_BOX.to_array())
                        .flat_map(|s| [s.a, s.b])
                        .collect();
                    assert_eq!(corners.len(), 8, "four teal edges");
                    let outline = hull(corners.iter().map(|&c| at(c)).collect());
                    let n = outline.len();
                    let inside = |q: Vec2| {
                        (0..n).all(|i| (outline[(i + 1) % n] - outline[i]).perp_dot(q - outline[i]) >= 0.0)
                    };
                    let gap = |q: Vec2| {
                        if inside(q) {
                            return 0.0;
                        }
                        (0..n).map(|i| seg_dist(q, outline[i], outline[(i + 1) % n])).fold(f32::MAX, f32::min)
                    };
                    for s in &frame.strokes {
                        if corners.contains(&s.a) && corners.contains(&s.b) {
                            continue;
                        }
                        let (a, b) = (at(s.a), at(s.b));
                        for k in 0..=64 {
                            let q = a.lerp(b, k as f32 / 64.0);
                            let d = gap(q) - 0.5 * s.width_px;
                            assert!(
                                d >= 6.0,
                                "fov {fov}, z_near {near}, z_far {far}, orbit ({yaw}, {pitch}) on \
                                 {size}: a line from {a} to {b} (colour {:?}) {d} px from the NDC box",
                                s.color
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
fn lesson_00_tetrahedron_storage_names_keep_off_its_triangles() {
    // Figure 1 with the tetrahedron, at its page camera (lessons/00-triangles-to-pixels/lesson.js)
    // and orbited: "triangle soup: 144 B" and "indexed: 96 B" stay where the figure put them (no
    // leader line, which from the soup's empty centre would cross a triangle), keep 2 px off every
    // dot and line, and 2 px from the triangles' names and the positions' numbers.
    use inbetween::figures::raster::MeshStorage;
    let mut failures = Vec::new();
    let orbits = [-1.04, -0.5, 0.0, 0.5, 1.04].into_iter().flat_map(|yaw| [0.1, 0.3, 0.64].map(|pitch| (yaw, pitch)));
    // And as the page test's drag turns it (yaw by -1.04 or -1.22 rad, pitch by 0.3 or 0.34).
    for (yaw, pitch) in orbits.chain([(-1.04, 0.6), (-1.22, 0.64)]) {
        {
            for size in CANVASES {
                failures.extend(failure_of(|| {
                    let mut scene = MeshStorage::new();
                    scene.set_shape("tetrahedron").unwrap();
                    let view = [0.0, 1.2, 0.0, 5.6, yaw, pitch];
                    let (frame, camera) = drawn!(&mut scene, view, size);
                    let name = format!("00 tetrahedron, yaw {yaw}, pitch {pitch}");
                    let names: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| frame.labels[i].text.contains(" B"))
                        .collect();
                    assert_eq!(names.len(), 2, "{name}: both storages named");
                    assert_shown_clear_by(&name, &frame, &camera, size, &names, 2.0);
                    let placed = layout(&frame, &camera, size);
                    let rect = |i: usize| Rect {
                        min: placed[i].2.top_left,
                        size: placed[i].1.size,
                    };
                    for &i in &names {
                        for j in (0..placed.len()).filter(|j| !names.contains(j)) {
                            assert!(
                                !rect(i).overlaps(&rect(j), 2.0),
                                "{name} on {size}: {:?} touches {:?}",
                                placed[i].0.text,
                                placed[j].0.text
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
fn lesson_00_depth_side_view_fills_its_canvas() {
    // Figure 3 at its page camera (lessons/00-triangles-to-pixels/lesson.js) on its canvases, at
    // the page's settings, with z_near 1 m (short bars) and with 24 bits: what it draws (the
    // floors' ends, the bars, the lines and the names) spans at least 80 % of the canvas's width
    // and half its height, rather than a strip with an empty band under it.
    use inbetween::figures::raster::DepthPrecision;
    for (near, bits) in [(0.1, 16.0), (1.0, 16.0), (0.1, 24.0)] {
        for size in DEPTH_CANVASES {
            let mut scene = DepthPrecision::new();
            scene.set(near, 1000.0, 0.01, bits).unwrap();
            let (frame, camera) = drawn!(&mut scene, [0.0, 3.0, -20.0, 30.0, 1.2, 0.45], size);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let floor_ends = [-1.0, 1.0].map(|x| [Vec3::new(x, 0.0, 0.0), Vec3::new(x, 0.0, -40.0)]);
            let mut points: Vec<Vec2> = (frame.strokes.iter())
                .flat_map(|s| [s.a, s.b])
                .chain(frame.markers.iter().map(|m| m.center))
                .map(Vec3::from)
                .chain(floor_ends.into_iter().flatten())
                .filter_map(|p| project_to_canvas(view_proj, size, p))
                .collect();
            for (_, rect) in label_boxes(&frame, &camera, size) {
                points.extend([rect.min, rect.max()]);
            }
            let (lo, hi) = points.iter().fold((Vec2::MAX, Vec2::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
            let span = (hi - lo) / size;
            assert!(
                span.x >= 0.8 && span.y >= 0.5,
                "z_near {near}, {bits} bits on {size}: the drawing spans {span} of the canvas"
            );
        }
    }
}

#[test]
fn lesson_00_depth_side_view_keeps_the_eye_and_its_name_on_the_canvas_after_a_slide_or_zoom() {
    // Figure 3 at its page camera on its canvases, at the page's settings and the page sweep's
    // (z_near 1.58 m, z_far 3960 m, gap 0.079 m, 24 bits), then zoomed (in ×0.6 and ×0.1, out ×3)
    // and slid ten canvases each way, as the viewer does it (the zoom and the drag, then the
    // clamp on the frame's declared points at each frame; the figure places its names for the
    // frame before): the eye's dot lies whole on the canvas, and its name is shown inside it.
    use inbetween::figures::raster::{DepthPrecision, EYE_HEIGHT};
    let eye = Vec3::new(0.0, EYE_HEIGHT, 0.0);
    let mut failures = Vec::new();
    for (near, far, gap, bits) in [(0.1, 1000.0, 0.01, 16.0), (1.58, 3960.0, 0.079, 24.0)] {
        for size in DEPTH_CANVASES {
            for zoom in [1.0, 0.6, 0.1, 3.0] {
                for (dx, dy) in [(10.0, 0.0), (-10.0, 0.0), (0.0, 10.0), (0.0, -10.0), (10.0, -10.0)] {
                    let mut scene = DepthPrecision::new();
                    scene.set(near, far, gap, bits).unwrap();
                    let view = [0.0, 3.0, -20.0, 30.0, 1.2, 0.45];
                    let (frame, mut camera) = drawn!(&mut scene, view, size);
                    camera.zoom(zoom);
                    camera.drag(dx * size.x, dy * size.y, size.y, true);
                    camera.clamp_pan(&frame.fit_points(), size);
                    let mut frame = Frame::default();
                    for _ in 0..2 {
                        scene.set_view(camera, size.x, size.y);
                        frame = Frame::default();
                        scene.draw(&mut frame);
                        camera.clamp_pan(&frame.fit_points(), size);
                    }
                    let name = format!("z_near {near}, {bits} bits, zoom {zoom}, slid ({dx}, {dy})");
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let c = project_to_canvas(view_proj, size, eye).unwrap();
                    let placed = layout(&frame, &camera, size);
                    failures.extend(failure_of(|| {
                        assert!(
                            c.min(size - c).min_element() >= 7.0,
                            "{name} on {size}: the eye's dot at {c}"
                        );
                        let (_, b, p) = placed.iter().find(|(l, _, _)| l.text == "eye").unwrap();
                        let (lo, hi) = (p.top_left, p.top_left + b.size);
                        assert!(
                            p.shown && lo.min_element() >= 0.0 && hi.cmple(size).all(),
                            "{name} on {size}: \"eye\" from {lo} to {hi}"
                        );
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_00_frustum_names_keep_off_the_canvas_edges() {
    // Figure 2 at its page camera (lessons/00-triangles-to-pixels/lesson.js), both canvases, at
    // the page's start (s = 0.05: the point near z_near) and further along, at the page's
    // frustum and at a wide and a narrow one: every name is shown at least 16 px inside the
    // canvas, so the eye's and z_near's names left of the apex do not end against its edge.
    use inbetween::figures::raster::Frustum;
    let mut failures = Vec::new();
    for (fov, near, far) in [(50.0, 1.0, 8.0), (100.0, 0.5, 12.0), (25.0, 2.0, 6.0)] {
        for s in [0.05, 0.5] {
            for size in CANVASES {
                let mut scene = Frustum::new();
                scene.set_frustum(fov, near, far).unwrap();
                let (frame, camera) = crate::label_clearance::drawn_for_view(
                    &mut scene,
                    [4.5, 1.2, -4.0, 17.0, 0.45, 0.45],
                    size,
                    |fig, out| {
                        fig.draw(out, s).unwrap();
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let boxes = label_boxes(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    assert_eq!(boxes.len(), frame.labels.len(), "fov {fov}, s {s} on {size}: a name hidden");
                    for (text, rect) in &boxes {
                        let margin = rect.min.min(size - rect.max()).min_element();
                        assert!(
                            margin >= 16.0,
                            "fov {fov}, z_near {near}, s {s} on {size}: {text:?} {margin} px from the edge"
                        );
                    }
                }));
            }
        }
    }
    assert_none_failed(&failures);
}
