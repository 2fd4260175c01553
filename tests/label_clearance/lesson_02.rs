//! Lesson 02: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_02_keys_time_axis_labels_keep_off_the_curves() {
    let mut scene = inbetween::figures::curves::KeyframesScene::new();
    for tau in [0.0, 1.7, 3.6] {
        let mut frame = Frame::default();
        scene.draw(&mut frame, tau).unwrap();
        for size in [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)] {
            let camera = page_camera([0.3, 0.8, -1.3, 6.5, 0.75, 0.4], &frame, size);
            assert_clear("02 keys", &frame, &camera, size);
        }
    }
}

#[test]
fn lesson_02_keys_time_axis_labels_keep_off_the_path_when_orbited() {
    // Figure 1's 3D view at its page camera (lessons/02-keyframes/lesson.js) and orbited as the
    // page sweep's drag turns it (−1.2 rad, tilted by 0.3 rad), on both canvases, with the
    // default, uneven and centripetal keys, the default keys 2.2 s later, and keys dragged right
    // (the path then runs over the axis), across the timeline: the axis's labels (at least two ticks and "time (s)") are
    // shown where the figure put them, keep 2 px off every line and dot (the path, the curve,
    // the axis), and cover no key. As on the page, the figure places them for the view of the frame before.
    use inbetween::figures::curves::{preset, KeyframesScene};
    let is_axis_label = |t: &str| t.ends_with(" s") || t == "time (s)";
    let mut failures = Vec::new();
    let mut keys = vec![];
    for name in ["default", "uneven", "centripetal"] {
        keys.push(preset(name).unwrap());
    }
    let (times, values) = preset("default").unwrap();
    // Key 0 at 2.2 s: the ticks are the clock's seconds, 3 s on, off the axis's start.
    keys.push((times.iter().map(|t| t + 2.2).collect(), values.clone()));
    keys.push((times, values.iter().map(|p| *p + Vec2::new(1.5, 0.4)).collect()));
    for view in [
        [0.3, 0.8, -1.3, 6.5, 0.75, 0.4],
        [0.3, 0.8, -1.3, 6.5, -0.45, 0.7],
    ] {
        for (k, (times, values)) in keys.iter().enumerate() {
            for tau in [0.0, 1.7, 3.1] {
                for size in [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)] {
                    let mut scene = KeyframesScene::new();
                    scene.set_keys(times.clone(), values.clone()).unwrap();
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        view,
                        size,
                        |fig, out| {
                            fig.draw(out, tau).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let name = format!("02 time axis, view {view:?}, keys {k}, τ {tau}");
                    let named: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| is_axis_label(&frame.labels[i].text))
                        .collect();
                    assert!(named.len() >= 3, "{name}: the axis is labelled");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &named, 2.0)
                    }));
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let boxes = label_boxes(&frame, &camera, size);
                    failures.extend(failure_of(|| {
                        for p in values {
                            let c = project_to_canvas(view_proj, size, p.extend(0.0)).unwrap();
                            for (text, rect) in boxes.iter().filter(|(t, _)| is_axis_label(t)) {
                                assert!(
                                    !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                                    "{name} on {size}: {text:?} covers the key at {c}"
                                );
                            }
                        }
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_02_lagrange_tick_numbers_keep_off_the_keys_and_curves() {
    // Figure 3 at its page camera (lessons/02-keyframes/lesson.js), both canvases, at 3, 6, 10,
    // 12 and 16 keys: the value axis's numbers and the time axis's (where the polynomial plunges
    // through the axis between keys, as at 10 keys near t = 8 and 9) keep off every key dot (the key at
    // t = 0 sits on the tick of 1 m) and every curve, and one "0" names the origin for both axes.
    // As on the page, the figure places the time numbers for the view of the frame before.
    use inbetween::figures::curves::LagrangeScene;
    for keys in 3..=16 {
        let mut scene = LagrangeScene::new();
        scene.set_key_count(keys as f32).unwrap();
        for size in [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)] {
            let (frame, camera) = drawn_for_view(
                &mut scene,
                [0.15, 1.4, 0.0, 6.5, 0.0, 0.0],
                size,
                |s, f| s.draw(f),
                |s, c, size| s.set_view(c, size.x, size.y),
            );
            let zeros = frame.labels.iter().filter(|l| l.text == "0").count();
            assert_eq!(zeros, 1, "{keys} keys: one 0 at the origin");
            assert!(frame.markers.len() >= keys, "the keys as dots");
            let name = format!("02 Lagrange, {keys} keys");
            let values = frame.labels.iter().filter(|l| l.left && l.anchor.y != 0.0).count();
            assert_eq!(values, 4, "{name}: -0.5, 1, 2 and 3");
            let is_number = |t: &str| t.parse::<f32>().is_ok();
            let numbers = frame.labels.iter().filter(|l| is_number(&l.text)).count();
            assert_eq!(numbers, 4 + keys.div_ceil(if keys > 10 { 2 } else { 1 }), "{name}");
            assert_clear_of(&name, &frame, &camera, size, is_number);
        }
    }
}

#[test]
fn lesson_02_keys_time_axis_labels_read_in_order_when_the_axis_is_short_on_screen() {
    // Figure 1's 3D view at its page camera after key 1 is dragged far up (to y = 7.92 m): the
    // camera backs away to fit the tall path, the axis shrinks to a few pixels a second, and its
    // labels must still read in order along it ("0 s", "1 s", ... then "time (s)"), each shown
    // label further along the axis than the one before, none overlapping another.
    use inbetween::figures::curves::{preset, KeyframesScene, TIME_DEPTH_M_PER_SEC};
    let (times, mut values) = preset("default").unwrap();
    values[1] = Vec2::new(-1.11, 7.92);
    let right = values.iter().fold(f32::MIN, |m, p| m.max(p.x)) + 0.8;
    let axis = |t: f32| Vec3::new(right, 0.0, -TIME_DEPTH_M_PER_SEC * t);
    let mut failures = Vec::new();
    for tau in [0.0, 1.7, 2.92] {
        for size in [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)] {
            let mut scene = KeyframesScene::new();
            scene.set_keys(times.clone(), values.clone()).unwrap();
            let (frame, camera) = drawn_for_view(
                &mut scene,
                [0.3, 0.8, -1.3, 6.5, 0.75, 0.4],
                size,
                |fig, out| {
                    fig.draw(out, tau).unwrap();
                },
                |fig, cam, px| fig.set_view(cam, px.x, px.y),
            );
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let px = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
            let along = (px(axis(1.0)) - px(axis(0.0))).normalize();
            // Each shown axis label's place along the axis, in its order on the axis.
            let mut placed: Vec<(f32, String, Rect)> = label_boxes(&frame, &camera, size)
                .into_iter()
                .filter_map(|(text, rect)| {
                    let rank = match text.as_str() {
                        "time (s)" => f32::INFINITY,
                        t => t.strip_suffix(" s")?.parse().ok()?,
                    };
                    Some((rank, text, rect))
                })
                .collect();
            placed.sort_by(|a, b| a.0.total_cmp(&b.0));
            let name = format!("τ {tau} on {size}");
            failures.extend(failure_of(|| {
                assert!(placed.len() >= 3, "{name}: the axis is labelled: {placed:?}");
                for w in placed.windows(2) {
                    let centre = |r: &Rect| (r.min + 0.5 * r.size).dot(along);
                    assert!(
                        centre(&w[1].2) > centre(&w[0].2),
                        "{name}: {:?} is not past {:?} along the axis",
                        w[1].1,
                        w[0].1
                    );
                    let (a, b) = (&w[0].2, &w[1].2);
                    let apart = a.max().cmple(b.min).any() || b.max().cmple(a.min).any();
                    assert!(apart, "{name}: {:?} overlaps {:?}", w[0].1, w[1].1);
                }
                // Each second's label is nearer its own tick than any other tick.
                let ticks: Vec<Vec2> = (0..=3).map(|s| px(axis(s as f32))).collect();
                for (second, text, rect) in placed.iter().filter(|p| p.0.is_finite()) {
                    let gap = |c: Vec2| c.clamp(rect.min, rect.max()).distance(c);
                    let own = gap(ticks[*second as usize]);
                    for (s, c) in ticks.iter().enumerate() {
                        let other = gap(*c);
                        assert!(
                            s == *second as usize || own < other,
                            "{name}: {text:?} is {other} px from the {s} s tick, {own} from its own"
                        );
                    }
                }
            }));
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_02_keys_time_axis_numbers_keep_to_one_side_for_any_orbit() {
    // Figure 1's 3D view orbited all round its page camera (yaw −1.5 to 1.5 rad, pitch 0.1 to
    // 1.0 rad), on both canvases, with the default, uneven and centripetal keys: every shown
    // number of the time axis lies wholly on one side of the axis's line on the canvas, the
    // side where fewer points of the curve and the path's keys lie, so that they read in order
    // along it; "time (s)" lies wholly past the last tick along the axis.
    use inbetween::figures::curves::{preset, KeyframesScene, TIME_DEPTH_M_PER_SEC};
    let mut failures = Vec::new();
    for name in ["default", "uneven", "centripetal"] {
        let (times, values) = preset(name).unwrap();
        let right = values.iter().fold(f32::MIN, |m, p| m.max(p.x)) + 0.8;
        let duration = times[times.len() - 1] - times[0];
        let axis = |t: f32| Vec3::new(right, 0.0, -TIME_DEPTH_M_PER_SEC * t);
        for yaw in (-5..=5).map(|k| 0.3 * k as f32) {
            for pitch in [0.1, 0.4, 0.7, 1.0] {
                for size in [Vec2::new(760.0, 300.0), Vec2::new(650.0, 300.0)] {
                    let mut scene = KeyframesScene::new();
                    scene.set_keys(times.clone(), values.clone()).unwrap();
                    let (frame, camera) = drawn_for_view(
                        &mut scene,
                        [0.3, 0.8, -1.3, 6.5, yaw, pitch],
                        size,
                        |fig, out| {
                            fig.draw(out, 1.7).unwrap();
                        },
                        |fig, cam, px| fig.set_view(cam, px.x, px.y),
                    );
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let px = |p: Vec3| project_to_canvas(view_proj, size, p).unwrap();
                    let (start, tip) = (px(axis(0.0)), px(axis(duration + 0.4)));
                    let along = (tip - start).normalize();
                    let last = px(axis((times[0] + duration).floor() - times[0]));
                    let side = |c: Vec2| (c - start).dot(along.perp());
                    // The curve is the figure's widest stroke; the keys, the path's dots.
                    let curve = frame.strokes.iter().map(|s| Vec3::from(s.a));
                    let keys = values.iter().map(|p| p.extend(0.0));
                    let lean: f32 = curve.chain(keys).map(|p| side(px(p)).signum()).sum();
                    let at = format!("{name} keys, yaw {yaw}, pitch {pitch}, {size}");
                    failures.extend(failure_of(|| {
                        for (text, rect) in label_boxes(&frame, &camera, size) {
                            let corners = [
                                rect.min,
                                rect.max(),
                                Vec2::new(rect.min.x, rect.max().y),
                                Vec2::new(rect.max().x, rect.min.y),
                            ];
                            if text == "time (s)" {
                                let past = corners.iter().all(|&c| (c - last).dot(along) > 0.0);
                                assert!(past, "{at}: \"time (s)\" at {rect:?}, the last tick at {last}");
                            } else if text.ends_with(" s") {
                                let away = corners.iter().all(|&c| side(c) * lean < 0.0);
                                assert!(away, "{at}: {text:?} at {rect:?} is not on the side away from the curves");
                            }
                        }
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}
