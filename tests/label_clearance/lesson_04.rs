//! Lesson 04: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_04_key_names_sit_at_their_keys_and_off_the_paths() {
    // Figure 1 at its page camera (lessons/04-rigid-motions/lesson.js), both canvases, at the
    // keys, the page's start (t = 0.5 at 1 s of the 4 s ping-pong), a third and the end, for
    // the page's key B and a turn of 0°: "A" and "B" each end within the reach of their key's
    // axes (0.5 m) and 10 px on screen from its origin (they lay 1 m out to the side), clear
    // of every path, tick and dot and of the aeroplanes.
    use inbetween::figures::rigid::{RigidMotion, KEY_LABEL_M};
    for angle in [150.0, 0.0] {
        let mut scene = RigidMotion::new();
        scene
            .set_end(Vec3::new(0.2, 1.0, 0.3), angle, Vec3::new(1.5, 1.4, 0.3))
            .unwrap();
        for t in [0.0, 0.33, 0.5, 1.0] {
            let mut frame = Frame::default();
            scene.draw(&mut frame, t).unwrap();
            for size in CANVASES {
                let camera = page_camera([0.0, 1.0, 0.0, 6.5, 0.35, 0.4], &frame, size);
                let name = format!("04 keys, angle {angle}°, t {t}");
                let mut keys = frame.clone();
                keys.labels.retain(|l| l.text == "A" || l.text == "B");
                assert_eq!(keys.labels.len(), 2);
                assert_clear(&name, &keys, &camera, size);
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                for (text, rect) in label_boxes(&keys, &camera, size) {
                    // The key's origin, KEY_LABEL_M below the name's anchor.
                    let anchor = keys.labels.iter().find(|l| l.text == text).unwrap().anchor;
                    let key = anchor - Vec3::Y * KEY_LABEL_M;
                    let origin = project_to_canvas(view_proj, size, key).unwrap();
                    let gap = rect.nearest(origin).distance(origin);
                    // The key's axes are 0.5 m long; the name ends no more than 10 px past
                    // their tips' reach.
                    let axis = project_to_canvas(view_proj, size, key + Vec3::Y * 0.5)
                        .unwrap()
                        .distance(origin);
                    assert!(
                        gap <= axis + 10.0,
                        "{name} on {size}: {text:?} {gap} px from its key (axes {axis} px)"
                    );
                    // Nor over the aeroplanes' parts (boxes: their corners and centres).
                    for m in &frame.meshes {
                        for c in 0..9 {
                            let s = |bit: i32| if c & bit == 0 { -1.0 } else { 1.0 };
                            let local = if c == 8 {
                                Vec3::ZERO
                            } else {
                                Vec3::new(s(1), s(2), s(4))
                            };
                            let Some(p) =
                                project_to_canvas(view_proj, size, m.model.transform_point3(local))
                            else {
                                continue;
                            };
                            assert!(
                                !(p.cmpgt(rect.min).all() && p.cmplt(rect.max()).all()),
                                "{name} on {size}: {text:?} covers a plane's part at {p}"
                            );
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn lesson_04_thirds_names_sit_at_their_aeroplanes_and_off_the_paths() {
    // Figure 1 with "a third, three times" on, at its page camera (lessons/04-rigid-motions/
    // lesson.js) and orbited round it, both canvases, for the page's key B, a turn of 90° and one
    // of 0° (where the two methods' thirds coincide), all three methods shown and each of the two
    // with thirds alone, at the keys and half-way: each "k/3" (the screw's third lands on B,
    // which "B" names) is shown where the figure put it, keeps 2 px off every dot, tick and line
    // (the paths, the axes, the screw axis), covers no aeroplane's part (its boxes' corners,
    // edge and face middles and centres), and ends within three label heights (48 px) of its
    // own aeroplane (the method's first third applied k times to A). As on the page, the figure
    // places them for the view of the frame before.
    use inbetween::figures::palette;
    use inbetween::figures::rigid::{Method, RigidMotion};
    let mut failures = Vec::new();
    for (angle, show) in [(150.0, 0), (150.0, 1), (150.0, 3), (90.0, 0), (0.0, 0)] {
        for t in [0.0, 0.5, 1.0] {
            for (yaw, pitch) in [
                (0.35, 0.4),
                (0.0, 0.2),
                (1.0, 0.4),
                (-0.5, 0.6),
                (0.35, 1.1),
                (2.5, 0.3),
            ] {
                for size in CANVASES {
                    let mut scene = RigidMotion::new();
                    scene
                        .set_end(Vec3::new(0.2, 1.0, 0.3), angle, Vec3::new(1.5, 1.4, 0.3))
                        .unwrap();
                    scene.set_show(show).unwrap();
                    scene.set_thirds(true);
                    let view = [0.0, 1.0, 0.0, 6.5, yaw, pitch];
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        view,
                        size,
                        |fig, out| {
                            fig.draw(out, t).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!(
                        "04 thirds, angle {angle}°, show {show}, t {t}, orbit ({yaw}, {pitch})"
                    );
                    // The screw's 3/3 is B, which "B" names.
                    let thirds: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| frame.labels[i].text.ends_with("/3"))
                        .collect();
                    assert_eq!(thirds.len(), [5, 3, 0, 2][show as usize], "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &thirds, 2.0)
                    }));
                    let points = |m: &inbetween::draw::MeshDraw| part_points(m, &camera, size);
                    let parts: Vec<Vec2> = frame.meshes.iter().flat_map(points).collect();
                    let placed = layout(&frame, &camera, size);
                    let a = scene.motion(Method::LerpSlerp, 0.0);
                    for &i in &thirds {
                        let label = &frame.labels[i];
                        let (_, b, p) = &placed[i];
                        let rect = Rect {
                            min: p.top_left,
                            size: b.size,
                        };
                        let method = if label.color == palette::Z_AXIS {
                            Method::Screw
                        } else {
                            Method::LerpSlerp
                        };
                        let step = scene.motion(method, 1.0 / 3.0) * a.conjugate();
                        let k: usize = label.text[..1].parse().unwrap();
                        // The gap to its aeroplane: to the points of the four boxes from the one
                        // centred there.
                        let gap = || {
                            let centre = (0..k).fold(a, |f, _| step * f).translation();
                            let first = frame
                                .meshes
                                .iter()
                                .position(|m| m.model.w_axis.truncate().distance(centre) < 1e-4)
                                .unwrap();
                            frame.meshes[first..first + 4]
                                .iter()
                                .flat_map(points)
                                .map(|q| rect.nearest(q).distance(q))
                                .fold(f32::MAX, f32::min)
                        };
                        let text = &label.text;
                        failures.extend(failure_of(|| {
                            let own = gap();
                            assert!(
                                own <= 48.0,
                                "{name} on {size}: {text:?} {own} px from its aeroplane"
                            );
                            for q in &parts {
                                assert!(
                                    !(q.cmpgt(rect.min).all() && q.cmplt(rect.max()).all()),
                                    "{name} on {size}: {text:?} at {:?} covers an aeroplane's part at {q}",
                                    rect.min
                                );
                            }
                        }));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_04_method_names_sit_on_their_moving_aeroplanes() {
    // Figure 1 with all three methods shown and with each alone, at its page camera (lessons/04-rigid-motions/
    // lesson.js) and orbited round it, both canvases, for the page's key B, a turn of 90° and one
    // of 0° (where the three planes travel together), at the keys, the page's start (t = 0.5),
    // a third and 0.58 (where the page's screenshots catch it), with and without the thirds:
    // "lerp + slerp", "blend" and "screw" (and "screw axis") are each shown where the figure put
    // it, 2 px off every dot, tick and line; the three names cover no aeroplane's part and sit and within four label heights (64 px) of its
    // own moving aeroplane (the paths through it keep a name from sitting closer), so that a
    // student tells the overlapping planes apart. At most 1 % of the names may miss: orbited far
    // round on the small canvas, with the thirds on, the paths and thirds can leave no clear place
    // within 64 px of the screw's plane (its name then gets a leader line).
    use inbetween::figures::rigid::{Method, RigidMotion, METHODS, METHOD_NAMES};
    use inbetween::figures::rotations::plane_parts;
    let mut failures = Vec::new();
    let mut names_checked = 0;
    let cases = [
        (150.0, false, 0),
        (150.0, true, 0),
        (90.0, false, 0),
        (0.0, false, 0),
        (150.0, false, 1),
        (150.0, true, 3),
    ];
    for (angle, thirds, show) in cases {
        for t in [0.0, 0.33, 0.5, 0.58, 1.0] {
            for (yaw, pitch) in [(0.35, 0.4), (0.0, 0.2), (1.0, 0.4), (-0.5, 0.6), (2.5, 0.3)] {
                for size in CANVASES {
                    let mut scene = RigidMotion::new();
                    scene
                        .set_end(Vec3::new(0.2, 1.0, 0.3), angle, Vec3::new(1.5, 1.4, 0.3))
                        .unwrap();
                    scene.set_thirds(thirds);
                    scene.set_show(show).unwrap();
                    let view = [0.0, 1.0, 0.0, 6.5, yaw, pitch];
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        view,
                        size,
                        |fig, out| {
                            fig.draw(out, t).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!(
                        "04 method names, angle {angle}°, thirds {thirds}, show {show}, t {t}, \
                         orbit ({yaw}, {pitch})"
                    );
                    // All three, or the one shown alone.
                    let shown: Vec<Method> = (0..3)
                        .filter(|&k| show == 0 || show == k + 1)
                        .map(|k| METHODS[k as usize].0)
                        .collect();
                    let named: Vec<usize> = shown
                        .iter()
                        .map(|&method| {
                            let text = METHOD_NAMES[method as usize];
                            let found = frame.labels.iter().position(|l| l.text == text);
                            found.unwrap_or_else(|| panic!("{name}: no {text:?}"))
                        })
                        .collect();
                    let names = frame.labels.iter();
                    let all = names.filter(|l| METHOD_NAMES.contains(&l.text.as_str()));
                    assert_eq!(all.count(), shown.len(), "{name}: a name per shown plane");
                    // With "screw axis", which keeps off its own axis too.
                    let axis = frame.labels.iter().position(|l| l.text == "screw axis");
                    let checked: Vec<usize> = named.iter().copied().chain(axis).collect();
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &checked, 2.0)
                    }));
                    let points = |m: &inbetween::draw::MeshDraw| part_points(m, &camera, size);
                    // Each shown method's moving aeroplane's boxes (the screw's is an outline,
                    // not meshes, when the blend's is shown too).
                    let own_boxes = |method: Method| {
                        let (r, p) = scene.motion(method, t).to_rotation_translation();
                        plane_parts(p, glam::Mat3::from_quat(r), Vec3::ONE, 1.0).map(|(m, _)| {
                            inbetween::draw::MeshDraw {
                                mesh: inbetween::draw::MeshId::CUBE,
                                model: m,
                                color: glam::Vec4::ONE,
                                vertex_colors: false,
                                unlit: false,
                            }
                        })
                    };
                    let parts: Vec<Vec2> = (frame.meshes.iter().flat_map(points))
                        .chain(shown.iter().flat_map(|&m| own_boxes(m)).flat_map(|m| points(&m)))
                        .collect();
                    let placed = layout(&frame, &camera, size);
                    for (&i, &method) in named.iter().zip(&shown) {
                        let (_, b, p) = &placed[i];
                        let rect = Rect {
                            min: p.top_left,
                            size: b.size,
                        };
                        let text = &frame.labels[i].text;
                        // Its own aeroplane: the four boxes at the method's pose.
                        let own: Vec<Vec2> = own_boxes(method).iter().flat_map(points).collect();
                        names_checked += 1;
                        failures.extend(failure_of(|| {
                            let gap = own
                                .iter()
                                .map(|q| rect.nearest(*q).distance(*q))
                                .fold(f32::MAX, f32::min);
                            assert!(
                                gap <= 64.0,
                                "{name} on {size}: {text:?} {gap} px from its aeroplane"
                            );
                            for q in &parts {
                                assert!(
                                    !(q.cmpgt(rect.min).all() && q.cmplt(rect.max()).all()),
                                    "{name} on {size}: {text:?} at {:?} covers an aeroplane's part at {q}",
                                    rect.min
                                );
                            }
                        }));
                    }
                }
            }
        }
    }
    assert!(
        failures.len() * 100 <= names_checked,
        "{} of {names_checked} names fail (at most 1 % may), e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

/// An aeroplane part's points on the canvas: its box's corners, edge and face middles and centre.
fn part_points(m: &inbetween::draw::MeshDraw, camera: &OrbitCamera, size: Vec2) -> Vec<Vec2> {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    (0..27)
        .filter_map(|i| {
            let c = |k: i32| (k % 3 - 1) as f32;
            let corner = Vec3::new(c(i), c(i / 3), c(i / 9));
            project_to_canvas(view_proj, size, m.model.transform_point3(corner))
        })
        .collect()
}

#[test]
fn lesson_04_key_names_keep_off_the_thirds() {
    // Figure 1 with "a third, three times" on, at its page camera and orbited, both canvases,
    // for the page's key B at angle 180° and 150°, the pivot at either end and in the middle:
    // "A" and "B" are shown where the figure put them, 2 px off every dot, tick and line, and
    // cover no aeroplane's part (the thirds' aeroplanes stand near the keys, and a name over
    // one reads as its name).
    use inbetween::figures::rigid::RigidMotion;
    let mut failures = Vec::new();
    for (angle, pivot) in [(180.0, 1.5), (180.0, -1.5), (150.0, 1.5), (150.0, 0.0)] {
        for t in [0.0, 0.5, 1.0] {
            for (yaw, pitch) in [(0.35, 0.4), (1.0, 0.4), (-0.5, 0.6)] {
                for size in CANVASES {
                    let mut scene = RigidMotion::new();
                    scene
                        .set_end(Vec3::new(0.2, 1.0, 0.3), angle, Vec3::new(1.5, 1.4, 0.3))
                        .unwrap();
                    scene.set_pivot(Vec3::X * pivot).unwrap();
                    scene.set_thirds(true);
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        [0.0, 1.0, 0.0, 6.5, yaw, pitch],
                        size,
                        |fig, out| {
                            fig.draw(out, t).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!(
                        "04 keys with thirds, angle {angle}°, pivot {pivot}, t {t}, orbit ({yaw}, {pitch})"
                    );
                    let keys: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| ["A", "B"].contains(&&*frame.labels[i].text))
                        .collect();
                    assert_eq!(keys.len(), 2, "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &keys, 2.0)
                    }));
                    let parts: Vec<Vec2> = (frame.meshes.iter())
                        .flat_map(|m| part_points(m, &camera, size))
                        .collect();
                    let placed = layout(&frame, &camera, size);
                    for &i in &keys {
                        let (_, b, p) = &placed[i];
                        let (lo, hi) = (p.top_left, p.top_left + b.size);
                        failures.extend(failure_of(|| {
                            for q in &parts {
                                assert!(
                                    !(q.cmpgt(lo).all() && q.cmplt(hi).all()),
                                    "{name} on {size}: {:?} covers an aeroplane's part at {q}",
                                    frame.labels[i].text
                                );
                            }
                        }));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_04_method_names_part_at_the_default() {
    // Figure 1 with all three methods, at its page camera and key B, both canvases, where the page
    // opens (t = 0.3) and while it plays on (to 0.45): the three aeroplanes travel close together,
    // so the names must not stack under them as one block. Each name's box, as the page lays it
    // out, is nearer its own aeroplane's dot than any other aeroplane's (within 2 px, where the
    // blend's and the screw's dots meet), and the three boxes stand at least 8 px apart (more
    // than the 6 px of names packed together).
    use inbetween::figures::rigid::{RigidMotion, METHODS, METHOD_NAMES};
    let mut failures = Vec::new();
    for t in [0.3, 0.35, 0.4, 0.45] {
        for size in CANVASES {
            let mut scene = RigidMotion::new();
            let (frame, camera) = drawn_for_view(
                &mut scene,
                [0.0, 1.0, 0.0, 6.5, 0.35, 0.4],
                size,
                |fig, out| {
                    fig.draw(out, t).unwrap();
                },
                |fig, cam, px| fig.set_view(cam, px.x, px.y),
            );
            let name = format!("04 method names at t {t} on {size}");
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let dots: Vec<Vec2> = METHODS
                .iter()
                .map(|&(m, _)| {
                    let p = scene.motion(m, t).transform_point(Vec3::ZERO);
                    project_to_canvas(view_proj, size, p).unwrap()
                })
                .collect();
            let boxes = label_boxes(&frame, &camera, size);
            let rects: Vec<Rect> = METHODS
                .iter()
                .map(|&(m, _)| {
                    let text = METHOD_NAMES[m as usize];
                    boxes.iter().find(|(t, _)| t == text).unwrap().1
                })
                .collect();
            let texts = METHODS.map(|(m, _)| METHOD_NAMES[m as usize]);
            for (k, rect) in rects.iter().enumerate() {
                let gap = |d: Vec2| rect.nearest(d).distance(d);
                for (j, d) in dots.iter().enumerate() {
                    if j != k && gap(*d) + 2.0 < gap(dots[k]) {
                        failures.push(format!(
                            "{name}: {:?} nearer {:?}'s dot ({} px) than its own ({} px)",
                            METHOD_NAMES[METHODS[k].0 as usize],
                            METHOD_NAMES[METHODS[j].0 as usize],
                            gap(*d),
                            gap(dots[k])
                        ));
                    }
                }
                for (j, other) in rects.iter().enumerate().skip(k + 1) {
                    if rect.overlaps(other, 8.0) {
                        failures.push(format!(
                            "{name}: {:?} at {} and {:?} at {} within 8 px",
                            texts[k], rect.min, texts[j], other.min
                        ));
                    }
                }
            }
        }
    }
    assert_none_failed(&failures);
}
