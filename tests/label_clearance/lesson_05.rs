//! Lesson 05: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_05_probe_value_keeps_off_the_cell_square_and_the_arrows() {
    // Figure 2 at its page camera (lessons/05-noise/lesson.js), both canvases, for the
    // page's probe (0.4, 0.7) and others across the grid, on the 2D noise and on slices of 3D
    // noise (z = 0.5, whose sticks join the dots to the surface, and 1.3): the probe's "n = …"
    // is shown where the figure put it and keeps 2 px off every dot and line (the purple
    // square of the probe's cell, the sticks, the arrows, the probe's stem). As on the page,
    // the figure places it for the view of the frame before.
    use inbetween::figures::noise::{Noise2d, TerrainFigure};
    let view = [0.0, 0.0, 0.0, 2.9, 0.35, 0.75];
    let mut failures = Vec::new();
    for (x, y) in [
        (0.4, 0.7),
        (0.1, 0.1),
        (-0.5, 0.5),
        (0.9, -0.9),
        (-1.5, -1.2),
        (1.5, 1.5),
    ] {
        for z in [0.0, 0.5, 1.3] {
            for size in CANVASES {
                let mut scene = Noise2d::new();
                scene.set_probe(x, y).unwrap();
                scene.set_z(z).unwrap();
                scene.take_dirty();
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    view,
                    size,
                    |fig, out| {
                        fig.draw(out, inbetween::draw::MeshId(1));
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let name = format!("05 noise 2D, probe ({x}, {y}), z {z}");
                let value: Vec<usize> = (0..frame.labels.len())
                    .filter(|&i| frame.labels[i].text.starts_with("n = "))
                    .collect();
                assert_eq!(value.len(), 1, "{name}");
                failures.extend(failure_of(|| {
                    assert_shown_clear_by(&name, &frame, &camera, size, &value, 2.0)
                }));
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_05_noise_1d_probe_name_keeps_off_the_curve() {
    // Figure 1 at its page camera (lessons/05-noise/lesson.js) and orbited round it (the page
    // sweep's drag turns it by −1.2 rad and tilts it by 0.3 rad), both canvases, at the page's
    // probe and the page test's (6.32, seed 16), either side of an integer and near the ends,
    // with the ramps and without: the probe's "n(x)" is shown where the figure put it and keeps
    // 2 px off every dot and line (the curve climbs steeply through the probe). As on the page,
    // the figure places it for the view of the frame before.
    use inbetween::figures::noise::Noise1d;
    let mut failures = Vec::new();
    for (yaw, pitch) in [(0.0, 0.0), (-1.216, 0.304), (0.6, 0.3)] {
        let view = [0.0, 0.0, 0.0, 7.5, yaw, pitch];
        for (x, seed) in [(2.35, 0.0), (6.32, 16.0), (3.02, 0.0), (2.98, 16.0), (0.3, 0.0), (7.9, 16.0)] {
            for ramps in [true, false] {
                for size in CANVASES {
                    let mut scene = Noise1d::new();
                    scene.set_probe(x).unwrap();
                    scene.set_seed(seed).unwrap();
                    scene.set_show_ramps(ramps);
                    let (frame, camera) = drawn!(&mut scene, view, size);
                    let name =
                        format!("05 noise 1D, orbit ({yaw}, {pitch}), x {x}, seed {seed}, ramps {ramps}");
                    let probe: Vec<usize> = (0..frame.labels.len())
                        .filter(|&i| frame.labels[i].text == "n(x)")
                        .collect();
                    assert_eq!(probe.len(), 1, "{name}");
                    failures.extend(failure_of(|| {
                        assert_shown_clear_by(&name, &frame, &camera, size, &probe, 2.0)
                    }));
                }
            }
        }
    }
    assert_none_failed(&failures);
}

#[test]
fn lesson_05_variant_names_keep_off_the_terrains() {
    // Figure 6 at its page camera (lessons/05-noise/lesson.js) and orbited round it (the page
    // sweep's drag turns it by −1.2 rad and tilts it by 0.3 rad), both canvases, at the
    // course's parameters, the page test's (N 2, α 0.79, h 0.79) and the slider's tallest h: each
    // variant's name is shown and covers no point of any terrain (every 4th vertex of each,
    // sampled finer than the figure does). As on the page, the figure places them for the view
    // of the frame before.
    use inbetween::draw::MeshId;
    use inbetween::figures::noise::{TerrainFigure, Variants};
    let mut failures = Vec::new();
    for (yaw, pitch) in [(0.0, 0.8), (-1.216, 1.104), (1.216, 1.104), (-0.6, 0.5)] {
        let view = [0.0, -0.1, 0.1, 6.0, yaw, pitch];
        for (n, alpha, h) in [(9.0, 0.4, 0.3), (2.0, 0.79, 0.79), (9.0, 0.6, 1.0)] {
            for size in CANVASES {
                let mut scene = Variants::new();
                scene.set_params(n, alpha, h).unwrap();
                let meshes = [MeshId(1), MeshId(2), MeshId(3), MeshId(4)];
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    view,
                    size,
                    |fig, out| {
                        fig.draw(out, &meshes);
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let name = format!("05 variants, orbit ({yaw}, {pitch}), N {n}, α {alpha}, h {h}");
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let points: Vec<Vec2> = (scene.terrains().iter().enumerate())
                    .flat_map(|(i, t)| {
                        let r = t.resolution();
                        (0..r * r)
                            .filter(move |k| (k % r) % 4 == 0 && (k / r) % 4 == 0)
                            .map(move |k| t.positions[k] + Variants::placement(i))
                    })
                    .filter_map(|p| project_to_canvas(view_proj, size, p))
                    .collect();
                let boxes = label_boxes(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    assert_eq!(boxes.len(), 4, "{name} on {size}: four names shown");
                    for (text, rect) in &boxes {
                        for c in &points {
                            assert!(
                                !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                                "{name} on {size}: {text:?} at {:?} covers a terrain at {c}",
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

#[test]
fn lesson_05_profile_name_keeps_off_the_fractal_surface() {
    // Figure 3 at its page camera (lessons/05-noise/lesson.js) and orbited as the page sweep's
    // drag turns it, both canvases, at the page's start, the Try this's spiky α = 0.8, N = 7,
    // and the sliders' ends: "v = 0.25" is shown and covers no vertex of the surface (the figure
    // samples every 2nd). As on the page, the figure places it for the view of the frame before.
    use inbetween::draw::MeshId;
    use inbetween::figures::noise::{Octaves, TerrainFigure, OCTAVES_RESOLUTION};
    let mut failures = Vec::new();
    for (yaw, pitch) in [(0.3, 0.6), (0.3 - 1.216, 0.6 + 0.336)] {
        for (n, alpha, omega) in [(3.0, 0.5, 2.0), (7.0, 0.8, 2.0), (9.0, 1.0, 4.0)] {
            for size in CANVASES {
                let mut scene = Octaves::new();
                scene.set_params(n, alpha, omega).unwrap();
                scene.rebuild().unwrap();
                let (frame, camera) = drawn_for_view(
                    &mut scene,
                    [0.0, 0.0, 0.0, 3.0, yaw, pitch],
                    size,
                    |fig, out| {
                        fig.draw(out, MeshId(1));
                    },
                    |fig, cam, px| fig.set_view(cam, px.x, px.y),
                );
                let name = format!("05 octaves, orbit ({yaw}, {pitch}), N {n}, α {alpha}, ω {omega}");
                let view_proj = camera.projection(size.x / size.y) * camera.view();
                let r = OCTAVES_RESOLUTION;
                let points: Vec<Vec2> = (0..r * r)
                    .filter_map(|k| project_to_canvas(view_proj, size, scene.terrains()[0].positions[k]))
                    .collect();
                let boxes = label_boxes(&frame, &camera, size);
                failures.extend(failure_of(|| {
                    assert!(boxes.iter().any(|(t, _)| t == "v = 0.25"), "{name} on {size}: no name");
                    assert_names_cover_none(&name, size, &boxes, &["v = 0.25"], &points, "the surface");
                }));
            }
        }
    }
    assert_none_failed(&failures);
}
