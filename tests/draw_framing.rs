//! Native tests of the camera fit (src/camera.rs, `OrbitCamera::fit`): every declared point lands
//! inside the canvas, clear of the padding, at 800 × 600 and 1600 × 1000 and at any orbit, and the
//! fit keeps the reader's yaw and pitch.

use glam::{Vec2, Vec3};
use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX, PAN_ROOM_PX};
use proptest::prelude::*;

const SIZES: [Vec2; 3] = [
    Vec2::new(800.0, 600.0),
    Vec2::new(1600.0, 1000.0),
    Vec2::new(420.0, 700.0),
];

/// Asserts each point is on the canvas at least `pad` (less a hair) from every edge, and that
/// the view is tight: some point comes within a pixel of the padding.
fn assert_fits(camera: &OrbitCamera, size: Vec2, points: &[Vec3], pad: f32) {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let mut slack = f32::MAX;
    for p in points {
        let px = project_to_canvas(view_proj, size, *p).expect("in front of the camera");
        let margins = [px.x, px.y, size.x - px.x, size.y - px.y];
        let least = margins.iter().copied().fold(f32::MAX, f32::min);
        assert!(
            least >= pad - 0.5,
            "{p} at {px} on {size}: {least} px from the edge"
        );
        slack = slack.min(least - pad);
    }
    assert!(
        slack < 1.0,
        "the fit leaves {slack} px spare on {size}: not tight"
    );
}

fn corners(min: Vec3, max: Vec3) -> Vec<Vec3> {
    let mut f = inbetween::draw::Frame::default();
    f.keep_box_in_view(min, max);
    f.keep_in_view
}

#[test]
fn a_box_fits_at_both_canvas_sizes_from_the_default_orbit() {
    let points = corners(Vec3::new(-2.0, 0.0, -2.0), Vec3::new(2.0, 1.8, 2.0));
    for size in SIZES {
        let mut camera = OrbitCamera::default();
        let (yaw, pitch) = (camera.yaw_rad, camera.pitch_rad);
        assert!(camera.fit(&points, size, FIT_PAD_PX));
        assert_eq!(
            (camera.yaw_rad, camera.pitch_rad),
            (yaw, pitch),
            "the orbit is kept"
        );
        assert_fits(&camera, size, &points, FIT_PAD_PX);
    }
}

#[test]
fn a_tall_thin_figure_fits_a_wide_canvas_and_a_wide_one_a_tall_canvas() {
    let tall = corners(Vec3::new(-0.2, 0.0, -0.2), Vec3::new(0.2, 3.0, 0.2));
    let wide = corners(Vec3::new(-5.0, 0.0, -0.3), Vec3::new(5.0, 0.4, 0.3));
    for size in SIZES {
        for points in [&tall, &wide] {
            let mut camera = OrbitCamera {
                yaw_rad: 0.3,
                pitch_rad: 0.2,
                ..OrbitCamera::default()
            };
            assert!(camera.fit(points, size, FIT_PAD_PX));
            assert_fits(&camera, size, points, FIT_PAD_PX);
        }
    }
}

#[test]
fn nothing_to_fit_changes_nothing() {
    let mut camera = OrbitCamera::default();
    let before = camera;
    assert!(!camera.fit(&[], Vec2::new(800.0, 600.0), FIT_PAD_PX));
    assert!(!camera.fit(&[Vec3::NAN], Vec2::new(800.0, 600.0), FIT_PAD_PX));
    // A canvas too small for its padding.
    assert!(!camera.fit(&[Vec3::ZERO, Vec3::ONE], Vec2::new(40.0, 40.0), FIT_PAD_PX));
    assert_eq!(camera, before);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Any cloud of points, from any orbit, at either canvas size: all of it in view.
    #[test]
    fn any_points_fit_from_any_orbit(
        pts in prop::collection::vec((-10f32..10.0, -1f32..6.0, -10f32..10.0), 1..30),
        yaw in -3.1f32..3.1,
        pitch in -1.5f32..1.5,
        big in any::<bool>(),
    ) {
        let points: Vec<Vec3> = pts.iter().map(|&(x, y, z)| Vec3::new(x, y, z)).collect();
        let size = if big { SIZES[1] } else { SIZES[0] };
        let mut camera = OrbitCamera { yaw_rad: yaw, pitch_rad: pitch, ..OrbitCamera::default() };
        prop_assert!(camera.fit(&points, size, FIT_PAD_PX));
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        for p in &points {
            let px = project_to_canvas(view_proj, size, *p).unwrap();
            prop_assert!(px.x >= FIT_PAD_PX - 0.5 && px.y >= FIT_PAD_PX - 0.5, "{} at {}", p, px);
            prop_assert!(px.x <= size.x - FIT_PAD_PX + 0.5 && px.y <= size.y - FIT_PAD_PX + 0.5, "{} at {}", p, px);
        }
    }
}

/// The figures that declare their view, drawn at their defaults: what they declare and their
/// label anchors all land inside the canvas at 800 × 600 and 1600 × 1000, seen from the page's
/// own orbit (the yaw and pitch its lesson.js passes to setCamera) and from two others.
#[test]
fn figures_that_declare_their_view_fit_at_both_sizes() {
    use inbetween::draw::{Frame, TextureId};
    use inbetween::figures::{noise, noise_images, rotations};
    let mut frames: Vec<(&str, Frame, (f32, f32))> = Vec::new();
    let mut f = Frame::default();
    rotations::Interpolation::new().draw(&mut f, 0.5).unwrap();
    frames.push(("03 interpolation", f, (0.0, 0.25)));
    let mut f = Frame::default();
    inbetween::figures::curves::KeyframesScene::new()
        .draw(&mut f, 1.0)
        .unwrap();
    frames.push(("02 keys in space and time", f, (0.75, 0.4)));
    let mut f = Frame::default();
    noise::Textures::new().draw(&mut f, &[TextureId(3), TextureId(4), TextureId(5)]);
    frames.push(("05 textures", f, (0.0, 1.3)));
    let mut f = Frame::default();
    noise_images::NoiseImages::new().draw(&mut f, [TextureId(3), TextureId(4), TextureId(5)]);
    frames.push(("05 CPU and GPU noise", f, (0.0, 0.0)));
    {
        use inbetween::draw::MeshId;
        use inbetween::figures::cloth::{ClothFigure, Preset, SpringFigure};
        let mut f = Frame::default();
        SpringFigure::new().draw(&mut f, 1.0).unwrap();
        frames.push(("13 one spring", f, (0.1, 0.08)));
        for (name, preset, orbit) in [
            ("13 flags", Preset::Flag, (0.3, 0.18)),
            ("13 drape", Preset::Drape, (0.45, 0.5)),
        ] {
            let mut scene = ClothFigure::new(preset);
            let meshes: Vec<MeshId> = (0..scene.cloth_count()).map(|k| MeshId(10 + k)).collect();
            let mut f = Frame::default();
            scene.draw(&mut f, &meshes, 1.0).unwrap();
            frames.push((name, f, orbit));
        }
    }
    let mut f = Frame::default();
    inbetween::figures::particles::SquashFigure::new()
        .draw(&mut f, 1.0)
        .unwrap();
    frames.push(("11 squash and stretch", f, (0.9, 0.15)));
    for (name, frame, (yaw, pitch)) in frames {
        assert!(!frame.keep_in_view.is_empty(), "{name} declares its view");
        let points: Vec<Vec3> = frame.fit_points();
        // The two page sizes, and the canvases the page gives a figure at them (420 px tall,
        // beside or under the 270 px panel).
        let sizes = [
            Vec2::new(800.0, 600.0),
            Vec2::new(1600.0, 1000.0),
            Vec2::new(760.0, 420.0),
            Vec2::new(690.0, 420.0),
        ];
        for size in sizes {
            for (dy, dp) in [(0.0, 0.0), (0.8, -0.2), (-1.5, 0.3)] {
                let mut camera = OrbitCamera {
                    yaw_rad: yaw + dy,
                    pitch_rad: pitch + dp,
                    ..OrbitCamera::default()
                };
                assert!(camera.fit(&points, size, FIT_PAD_PX), "{name}");
                assert_fits(&camera, size, &points, FIT_PAD_PX);
            }
        }
    }
}

#[test]
fn a_figure_with_an_inset_fits_beside_it() {
    use inbetween::draw::inset::inset_rect;
    // A flock's box, seen from several orbits, on the canvases lesson 12 gives its flock figure
    // at the two page sizes and at 1280 px: every point lands left of the inset's square (and
    // inside the canvas), and the fit is tight against one of those edges.
    let points = corners(Vec3::new(-2.0, 0.0, -1.5), Vec3::new(2.0, 2.0, 1.5));
    for size in [
        Vec2::new(760.0, 420.0),
        Vec2::new(690.0, 420.0),
        Vec2::new(960.0, 420.0),
        Vec2::new(1600.0, 1000.0),
    ] {
        let left = inset_rect(size).min.x;
        for (yaw, pitch) in [(0.5, 0.4), (1.2, 0.2), (-0.7, 0.8)] {
            let mut camera = OrbitCamera {
                yaw_rad: yaw,
                pitch_rad: pitch,
                ..OrbitCamera::default()
            };
            assert!(camera.fit_left_of(&points, size, left, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let mut slack = f32::MAX;
            for p in &points {
                let px = project_to_canvas(view_proj, size, *p).unwrap();
                let margins = [px.x, px.y, left - px.x, size.y - px.y];
                let least = margins.iter().copied().fold(f32::MAX, f32::min);
                assert!(
                    least >= FIT_PAD_PX - 0.5,
                    "{p} at {px} on {size}, inset from x = {left}"
                );
                slack = slack.min(least - FIT_PAD_PX);
            }
            assert!(slack < 1.0, "{slack} px spare on {size}");
        }
        // An impossible part (no width) changes nothing.
        let mut camera = OrbitCamera::default();
        assert!(!camera.fit_left_of(&points, size, 0.0, FIT_PAD_PX));
        assert_eq!(camera, OrbitCamera::default());
    }
}

/// Lesson 11's squash figure fits its balls' path (every 0.1 s), not a box around it nor its
/// 4 m floor grid: in the page's canvas (760 × 420 at 800 px, from the page's orbit) a ball at
/// the top of its drop is at least 45 px across (2.45 m of drop and label must fit 420 px).
#[test]
fn the_squash_figure_frames_its_balls_closely() {
    use inbetween::draw::{Frame, MeshId};
    use inbetween::figures::particles::SquashFigure;
    let mut f = Frame::default();
    SquashFigure::new().draw(&mut f, 0.0).unwrap();
    let size = Vec2::new(760.0, 420.0);
    let mut camera = OrbitCamera {
        yaw_rad: 0.9,
        pitch_rad: 0.15,
        ..OrbitCamera::default()
    };
    assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    // The rigid ball, drawn first (the other one's model matrix carries its stretch).
    for m in f.meshes.iter().filter(|m| m.mesh == MeshId::SPHERE).take(1) {
        let centre = m.model.w_axis.truncate();
        let radius = m.model.x_axis.truncate().length();
        let [a, b] = [centre - Vec3::Y * radius, centre + Vec3::Y * radius]
            .map(|p| project_to_canvas(view_proj, size, p).unwrap());
        assert!((a - b).length() >= 45.0, "{} px across", (a - b).length());
    }
}

/// Lesson 03 Figure 1 declares a sphere of 0.95 m around each aeroplane: whatever the keys,
/// every path it draws stays within it, and from the page's orbit the nearest plane's (matrix
/// lerp's) 0.9 m reach is at least 88 px on the 760 × 420 canvas (a box around the same reach
/// gives 80 px).
#[test]
fn the_aeroplanes_fit_their_reach_and_fill_more_of_the_view() {
    use inbetween::draw::Frame;
    use inbetween::figures::rotations::{Interpolation, METHODS};
    let mut s = Interpolation::new();
    for (start, end) in [
        (Vec3::ZERO, Vec3::new(120.0, 70.0, -120.0)),
        (Vec3::new(170.0, 0.0, 0.0), Vec3::new(-170.0, 0.0, 0.0)),
        (Vec3::new(-90.0, 45.0, 30.0), Vec3::new(180.0, -89.0, 179.0)),
    ] {
        s.set_keys_euler_deg(start, end).unwrap();
        for t in [0.0, 0.3, 0.7, 1.0] {
            let mut f = Frame::default();
            s.draw(&mut f, t).unwrap();
            for st in &f.strokes {
                for p in [Vec3::from(st.a), Vec3::from(st.b)] {
                    let reach = METHODS
                        .iter()
                        .map(|&(_, x, _)| (p - Vec3::new(x, 1.2, 0.0)).length())
                        .fold(f32::INFINITY, f32::min);
                    assert!(reach <= 0.95, "{p} is {reach} m from its plane");
                }
            }
        }
    }
    let mut f = Frame::default();
    Interpolation::new().draw(&mut f, 0.2).unwrap();
    let size = Vec2::new(760.0, 420.0);
    // lessons/03-rotations/lesson.js: interpViewer.setCamera.
    let mut camera = OrbitCamera::from_view([0.0, 1.1, 0.0, 7.5, -0.6, 0.7]);
    assert!(camera.fit(&f.fit_points(), size, FIT_PAD_PX));
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    // 0.9 m up the screen from the plane's centre.
    let up = camera.view().inverse().transform_vector3(Vec3::Y);
    let centre = Vec3::new(-3.3, 1.2, 0.0);
    let [a, b] =
        [centre, centre + 0.9 * up].map(|p| project_to_canvas(view_proj, size, p).unwrap());
    assert!((a - b).length() >= 88.0, "{} px", (a - b).length());
}

/// Lesson 09 Figure 4 (LBS and DQS side by side), in both views, through the walk and the run:
/// from the page's orbit and the page test's (a drag of a fifth of the canvas across and a tenth
/// down), at both page sizes, every vertex of both bodies (whole body) or of both left legs'
/// thigh and shin parts (left legs) lands inside the canvas, clear of the padding, at any time
/// of the clip, and so do the titles, which in the legs view stand under the feet.
#[test]
fn the_skinned_pair_keeps_both_bodies_or_both_left_legs_in_view() {
    use inbetween::draw::{Frame, MeshId};
    use inbetween::figures::skinning::HumanFigure;
    let mut h = HumanFigure::new();
    h.set_compare(true);
    let leg: Vec<usize> = {
        let c = h.character();
        let per_part = c.mesh.positions.len() / c.skeleton.len();
        ["thigh.L", "shin.L"]
            .iter()
            .flat_map(|name| {
                let j = c.skeleton.find(name).unwrap();
                j * per_part..(j + 1) * per_part
            })
            .collect()
    };
    let places = [Vec3::new(0.0, 0.0, 0.5), Vec3::new(0.0, 0.0, -0.5)];
    for clip in ["walk", "run"] {
        h.set_clip(clip).unwrap();
        for view in ["whole body", "left legs"] {
            h.set_view(view).unwrap();
            h.skin(0.0).unwrap();
            let mut frame = Frame::default();
            h.draw_pair(&mut frame, [MeshId(3), MeshId(4)]);
            let titles: Vec<Vec3> = frame
                .labels
                .iter()
                .filter(|l| l.text == "LBS" || l.text == "DQS")
                .map(|l| l.anchor)
                .collect();
            assert_eq!(titles.len(), 2);
            if view == "left legs" {
                assert!(
                    titles.iter().all(|t| t.y < 0.0),
                    "under the feet: {titles:?}"
                );
            }
            for size in crate::label_clearance::CANVASES {
                for (yaw, pitch) in [(1.45, 0.15), (1.45 - 0.008 * 130.0, 0.15 + 0.008 * 42.0)] {
                    let mut camera = OrbitCamera::from_view([0.0, 0.9, 0.0, 3.2, yaw, pitch]);
                    assert!(camera.fit(&frame.fit_points(), size, FIT_PAD_PX));
                    let view_proj = camera.projection(size.x / size.y) * camera.view();
                    let inside = |p: Vec3, what: &str| {
                        let px = project_to_canvas(view_proj, size, p).expect("in front");
                        let least = [px.x, px.y, size.x - px.x, size.y - px.y]
                            .into_iter()
                            .fold(f32::MAX, f32::min);
                        assert!(
                            least >= FIT_PAD_PX - 0.5,
                            "{clip}, {view}, {size}, yaw {yaw}: {what} at {px}"
                        );
                    };
                    titles.iter().for_each(|t| inside(*t, "a title"));
                    for k in 0..=32 {
                        h.skin(h.duration_sec() * k as f32 / 32.0).unwrap();
                        for (mesh, place) in [&h.mesh, &h.mesh_dqs].into_iter().zip(places) {
                            let all: Vec<usize> = (0..mesh.positions.len()).collect();
                            let vertices = if view == "left legs" { &leg } else { &all };
                            for &v in vertices {
                                inside(mesh.positions[v] + place, "a vertex");
                            }
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn a_figure_fits_above_its_inset() {
    use inbetween::draw::inset::inset_rect;
    // A wide, low box, seen from several orbits, on the canvases of the two page sizes: every
    // point lands above the inset's square (and inside the canvas), and the fit is tight
    // against one of those edges.
    let points = corners(Vec3::new(-2.5, 0.0, -0.3), Vec3::new(2.5, 1.5, 0.3));
    for size in [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0)] {
        let top = inset_rect(size).min.y;
        for (yaw, pitch) in [(0.0, 0.2), (0.5, 0.4), (-0.7, 0.1)] {
            let mut camera = OrbitCamera {
                yaw_rad: yaw,
                pitch_rad: pitch,
                ..OrbitCamera::default()
            };
            assert!(camera.fit_above(&points, size, top, FIT_PAD_PX));
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let mut slack = f32::MAX;
            for p in &points {
                let px = project_to_canvas(view_proj, size, *p).unwrap();
                let margins = [px.x, px.y, size.x - px.x, top - px.y];
                let least = margins.iter().copied().fold(f32::MAX, f32::min);
                assert!(
                    least >= FIT_PAD_PX - 0.5,
                    "{p} at {px} on {size}, inset from y = {top}"
                );
                slack = slack.min(least - FIT_PAD_PX);
            }
            assert!(slack < 1.0, "{slack} px spare on {size}");
        }
        let mut camera = OrbitCamera::default();
        assert!(!camera.fit_above(&points, size, 0.0, FIT_PAD_PX));
        assert_eq!(camera, OrbitCamera::default());
    }
}

/// Lesson 09 Figure 1 from the page's orbit, fitted as the page fits it on both canvases: at
/// every bend and twist the sliders reach, every vertex of both tubes lands on the canvas clear
/// of the padding and above the inset (the camera stays put while the sliders move); at the
/// default bend (90°) each tube is at least 130 px tall.
#[test]
fn the_skinned_tubes_fill_the_width_above_the_inset() {
    use inbetween::draw::inset::{fit_beside, inset_rect};
    use inbetween::draw::{Frame, MeshId};
    use inbetween::figures::skinning::{CylinderFigure, DQS_OFFSET, LBS_OFFSET};
    for size in [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0)] {
        let mut f = CylinderFigure::new();
        let mut frame = Frame::default();
        f.draw(&mut frame, [MeshId(1), MeshId(2)]).unwrap();
        // lessons/09-skinning/lesson.js: cylinderViewer.setCamera.
        let mut camera = OrbitCamera::from_view([0.3, 0.7, 0.0, 5.0, 0.0, 0.2]);
        let inset = frame.inset.as_ref().unwrap();
        assert!(fit_beside(
            &mut camera,
            inset,
            &frame.fit_points(),
            size,
            FIT_PAD_PX
        ));
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let top = inset_rect(size).min.y;
        let px = |f: &CylinderFigure| -> Vec<Vec<Vec2>> {
            [(LBS_OFFSET, &f.lbs), (DQS_OFFSET, &f.dqs)]
                .map(|(o, m)| {
                    m.positions
                        .iter()
                        .map(|p| project_to_canvas(view_proj, size, o + *p).unwrap())
                        .collect()
                })
                .to_vec()
        };
        for tube in px(&f) {
            let (lo, hi) = tube
                .iter()
                .fold((Vec2::MAX, Vec2::MIN), |(a, b), p| (a.min(*p), b.max(*p)));
            eprintln!(
                "{size}: tube {lo} to {hi}, {} px tall, {} wide",
                hi.y - lo.y,
                hi.x - lo.x
            );
            assert!(
                hi.y - lo.y >= 130.0,
                "{size}: a tube {} px tall",
                hi.y - lo.y
            );
        }
        for bend in [0.0, 45.0, 90.0, 135.0, 180.0] {
            for twist in [-180.0, -90.0, 0.0, 90.0, 180.0] {
                f.set_bend_deg(bend).unwrap();
                f.set_twist_deg(twist).unwrap();
                f.draw(&mut Frame::default(), [MeshId(1), MeshId(2)])
                    .unwrap();
                for p in px(&f).concat() {
                    let margins = [p.x, p.y, size.x - p.x, top - p.y];
                    let least = margins.iter().copied().fold(f32::MAX, f32::min);
                    assert!(
                        least >= FIT_PAD_PX - 4.0,
                        "bend {bend}, twist {twist}: {p} on {size}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_panned_flat_figure_keeps_its_box_in_view() {
    // A flat figure (seen square-on) fitted to its box, then dragged ten canvases away: the box
    // stays inside the canvas. A zoom in stops at the fit (the box still whole), a zoom out is
    // kept. A drag within the room moves the view as far as it was dragged.
    let points = corners(Vec3::ZERO, Vec3::new(2.0, 1.0, 0.0));
    for size in SIZES {
        let inside = |camera: &OrbitCamera| {
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            for p in &points {
                let c = project_to_canvas(view_proj, size, *p).unwrap();
                let margin = c.min(size - c).min_element();
                assert!(margin >= FIT_PAD_PX - PAN_ROOM_PX - 0.5, "{size}: {p} at {c}");
            }
        };
        let mut camera = OrbitCamera::from_view([1.0, 0.5, 0.0, 3.0, 0.0, 0.0]);
        assert!(camera.fit(&points, size, FIT_PAD_PX));
        let fitted = camera.distance;
        for (dx, dy) in [(10.0, 10.0), (-10.0, 3.0), (0.0, -10.0)] {
            camera.drag(dx * size.x, dy * size.y, size.y, true);
            camera.clamp_pan(&points, size);
            inside(&camera);
        }
        camera.zoom(0.3);
        camera.drag(10.0 * size.x, -10.0 * size.y, size.y, true);
        camera.clamp_pan(&points, size);
        assert!((camera.distance - fitted).abs() < 1e-3 * fitted, "{size}: zoomed in to {}", camera.distance);
        inside(&camera);
        camera.zoom(2.0);
        camera.clamp_pan(&points, size);
        assert!((camera.distance - 2.0 * fitted).abs() < 1e-3 * fitted);
        let before = camera.target;
        camera.drag(-5.0, 0.0, size.y, true);
        camera.clamp_pan(&points, size);
        let moved = (camera.target - before).length() / camera.distance * size.y;
        assert!((moved - 5.0).abs() < 0.1, "{size}: moved {moved} px of 5");
    }
}

#[test]
fn a_flat_figure_fitted_on_a_wide_canvas_fits_a_narrower_one_after_a_drag() {
    // Lesson 05 Figure 9 (three images in a row, lessons/05-noise/lesson.js's camera) fitted on
    // a wide canvas, dragged (which leaves the fit) and zoomed in, then shown on narrower
    // canvases (the page made smaller) as the viewer does, clamping at each frame: the three
    // images and their names' anchors stay on the canvas, FIT_PAD_PX − PAN_ROOM_PX from its
    // edges.
    use inbetween::draw::{Frame, TextureId};
    use inbetween::figures::noise_images::{image_model, NoiseImages};
    let mut frame = Frame::default();
    NoiseImages::new().draw(&mut frame, [TextureId(1), TextureId(2), TextureId(3)]);
    let points = frame.fit_points();
    let mut shown: Vec<Vec3> = frame.labels.iter().map(|l| l.anchor).collect();
    for q in &frame.quads {
        shown.extend([(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .map(|(x, z)| q.model.transform_point3(Vec3::new(x, 0.0, z))));
    }
    assert_eq!(frame.quads[0].model, image_model(-2.2));
    for zoom in [1.0, 0.5] {
        let mut camera = OrbitCamera::from_view([0.0, -0.15, 0.0, 6.2, 0.0, 0.0]);
        assert!(camera.fit(&points, Vec2::new(920.0, 420.0), FIT_PAD_PX));
        camera.drag(100.0, 30.0, 420.0, true);
        camera.zoom(zoom);
        for size in [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0), Vec2::new(400.0, 300.0)] {
            camera.clamp_pan(&points, size);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            for p in &shown {
                let c = project_to_canvas(view_proj, size, *p).unwrap();
                let margin = c.min(size - c).min_element();
                assert!(
                    margin >= FIT_PAD_PX - PAN_ROOM_PX - 0.5,
                    "zoom {zoom} on {size}: {p} at {c}"
                );
            }
        }
    }
}

/// Lesson 07 Figure 3 (hinges, the page's start) from the page's camera, fitted as the page fits
/// it beside the "from the side" inset on both canvases: the hinges keep every chain in the
/// z = 0 plane, so the view box round each chain is flat there and the fit (limited by the
/// canvas's width) draws the three chains and their targets larger: at least 425 px across and
/// 150 px tall on the 760 x 420 canvas, 335 and 120 on the 650 x 420 one (with the box 0.4 m
/// deep, as for cones: 409 x 145 and 314 x 114).
#[test]
fn the_hinged_chains_fill_the_part_left_of_the_inset() {
    use inbetween::draw::inset::fit_beside;
    use inbetween::draw::Frame;
    use inbetween::figures::ik::IkFigure;
    for (size, least) in [
        (Vec2::new(760.0, 420.0), Vec2::new(425.0, 150.0)),
        (Vec2::new(650.0, 420.0), Vec2::new(335.0, 120.0)),
    ] {
        let mut scene = IkFigure::new();
        scene.set_limits("hinges (bend one way)").unwrap();
        let mut frame = Frame::default();
        scene.draw(&mut frame).unwrap();
        // lessons/07-inverse-kinematics/lesson.js: Figure 3's setCamera.
        let mut camera = OrbitCamera::from_view([0.25, 0.45, 0.0, 4.3, 0.5, 0.3]);
        let inset = frame.inset.as_ref().unwrap();
        assert!(fit_beside(
            &mut camera,
            inset,
            &frame.fit_points(),
            size,
            FIT_PAD_PX
        ));
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let target = scene.target();
        let mut points = Vec::new();
        for k in scene.shown_solvers() {
            points.extend(scene.chain(k).unwrap());
            let root = Vec3::new(inbetween::figures::ik::ROOTS_X[k], 0.0, 0.0);
            points.push(root + target);
        }
        let (lo, hi) = points
            .iter()
            .map(|&p| project_to_canvas(view_proj, size, p).unwrap())
            .fold((Vec2::MAX, Vec2::MIN), |(a, b), p| (a.min(p), b.max(p)));
        eprintln!("{size}: chains {lo} to {hi}, {} x {} px", hi.x - lo.x, hi.y - lo.y);
        assert!(
            (hi - lo).cmpge(least).all(),
            "{size}: the chains span {} x {} px",
            hi.x - lo.x,
            hi.y - lo.y
        );
    }
}

#[test]
fn a_panned_flat_figure_that_fits_stays_near_the_middle() {
    // A flat figure fitted to its box, dragged far each way: where the box fits inside the
    // canvas, its centre stays within PAN_ROOM_PX (8 px) of the canvas's, so a drag never leaves
    // it against one edge with the rest of the canvas empty. The box is wider (2:1) than every
    // canvas, so along y it has room to spare that a clamp to the canvas's edge would let it use.
    let points = corners(Vec3::ZERO, Vec3::new(2.0, 1.0, 0.0));
    for size in SIZES {
        let mut camera = OrbitCamera::from_view([1.0, 0.5, 0.0, 3.0, 0.0, 0.0]);
        assert!(camera.fit(&points, size, FIT_PAD_PX));
        for (dx, dy) in [(10.0, 10.0), (-10.0, -10.0), (0.3, -0.4)] {
            camera.drag(dx * size.x, dy * size.y, size.y, true);
            camera.clamp_pan(&points, size);
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let centre = project_to_canvas(view_proj, size, Vec3::new(1.0, 0.5, 0.0)).unwrap();
            let off = (centre - 0.5 * size).abs();
            assert!(
                off.cmple(Vec2::splat(PAN_ROOM_PX + 0.5)).all(),
                "{size}, dragged ({dx}, {dy}) canvases: the box's centre is {off} px off the middle"
            );
        }
    }
}
