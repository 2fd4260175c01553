//! Native tests of wide lines and markers in the draw list (src/draw.rs): the quads the stroke
//! shader draws are as wide as asked, in CSS pixels, at any canvas size, distance and pixel ratio;
//! polylines join without gaps; dashes run on across segments; bad numbers never reach the GPU.

use glam::{Vec2, Vec3};
use inbetween::camera::OrbitCamera;
use inbetween::draw::*;

/// The distance between a quad's two long edges, device pixels.
fn quad_width(corners: &[Vec2; 4]) -> f32 {
    let along = (corners[1] - corners[0]).normalize();
    let across = corners[3] - corners[0];
    (across - along * across.dot(along)).length()
}

#[test]
fn wide_lines_are_their_width_in_css_pixels_at_two_canvas_sizes() {
    let camera = OrbitCamera::default();
    for (size, dpr) in [
        (Vec2::new(800.0, 600.0), 1.0),
        (Vec2::new(1600.0, 1000.0), 2.0),
    ] {
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        for width in [1.0, 2.5, 4.0, 6.0] {
            // One segment near the camera and one far off: the same width on screen.
            for (a, b) in [
                (Vec3::new(-0.5, 1.0, 1.0), Vec3::new(0.5, 1.3, 1.0)),
                (Vec3::new(-3.0, 0.0, -20.0), Vec3::new(3.0, 2.0, -25.0)),
            ] {
                let mut f = Frame::default();
                f.wide_line(a, b, palette::ORANGE, width);
                let (corners, half) =
                    stroke_corners(&f.strokes[0], view_proj, size * dpr, dpr).unwrap();
                assert!((2.0 * half - width * dpr).abs() < 1e-4);
                // The quad reaches one device pixel past the solid width on each side.
                let w = quad_width(&corners);
                assert!(
                    (w - (width * dpr + 2.0)).abs() < 0.05,
                    "{size} x{dpr}: {width} px drawn {w}"
                );
                // And its middle runs through both ends' projections.
                let mid_a = 0.5 * (corners[0] + corners[3]);
                let seen = inbetween::camera::project_to_canvas(view_proj, size * dpr, a).unwrap();
                assert!(mid_a.distance(seen) > 0.0);
                let along = (corners[1] - corners[0]).normalize();
                assert!(((mid_a - seen) - along * (mid_a - seen).dot(along)).length() < 0.05);
            }
        }
    }
}

#[test]
fn a_segment_crossing_the_near_plane_is_cut_there_and_one_behind_it_is_dropped() {
    let camera = OrbitCamera::default();
    let size = Vec2::new(800.0, 600.0);
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let eye = camera.eye();
    let behind = eye + (eye - camera.target);
    let mut f = Frame::default();
    f.wide_line(behind, camera.target, palette::RED, 3.0);
    f.wide_line(behind, behind + Vec3::X, palette::RED, 3.0);
    let (corners, _) = stroke_corners(&f.strokes[0], view_proj, size, 1.0).unwrap();
    assert!(corners.iter().all(|c| c.is_finite()), "{corners:?}");
    assert!(stroke_corners(&f.strokes[1], view_proj, size, 1.0).is_none());
}

#[test]
fn polylines_carry_the_distance_along_for_dashes_and_round_every_join() {
    let mut f = Frame::default();
    let pts = [
        Vec3::ZERO,
        Vec3::X,
        Vec3::new(1.0, 2.0, 0.0),
        Vec3::new(1.0, 2.0, 2.0),
    ];
    f.stroke(&pts, palette::BLUE, StrokeStyle::dashed(3.0, 0.1, 0.05));
    assert_eq!(f.strokes.len(), 3);
    let starts: Vec<[f32; 4]> = f.strokes.iter().map(|s| s.dash).collect();
    assert_eq!(starts[0], [0.0, 1.0, 0.1, 0.05]);
    assert_eq!(starts[1], [1.0, 3.0, 0.1, 0.05]);
    assert_eq!(starts[2], [3.0, 5.0, 0.1, 0.05]);
    // Each segment starts where the last ended, so the round ends overlap at every join.
    for pair in f.strokes.windows(2) {
        assert_eq!(pair[0].b, pair[1].a);
    }
    assert_eq!(f.segments_of(palette::BLUE).count(), 3);
}

#[test]
fn bad_widths_sizes_and_points_never_reach_the_gpu() {
    let mut f = Frame::default();
    f.wide_line(Vec3::ZERO, Vec3::X, palette::RED, 40.0);
    f.wide_line(Vec3::ZERO, Vec3::X, palette::RED, 0.0);
    f.wide_line(Vec3::ZERO, Vec3::X, palette::RED, f32::NAN);
    f.wide_polyline(
        &[Vec3::ZERO, Vec3::NAN, Vec3::X, Vec3::Y],
        palette::RED,
        2.0,
    );
    f.stroke(
        &[Vec3::ZERO, Vec3::X],
        palette::RED,
        StrokeStyle::dashed(2.0, -1.0, f32::NAN),
    );
    let widths: Vec<f32> = f.strokes.iter().map(|s| s.width_px).collect();
    assert_eq!(&widths[..3], &[MAX_WIDTH_PX, MIN_WIDTH_PX, MIN_WIDTH_PX]);
    // The NaN point drops its two segments; the last pair stays.
    assert_eq!(f.strokes.len(), 3 + 1 + 1);
    assert_eq!(
        f.strokes.last().unwrap().dash[3],
        0.0,
        "a bad dash draws solid"
    );
    f.marker(Vec3::NAN, 8.0, palette::RED);
    f.marker(Vec3::ZERO, 1000.0, palette::RED);
    f.marker(Vec3::ZERO, f32::NAN, palette::RED);
    f.marker_on_top(Vec3::ZERO, 1.0, palette::RED);
    let sizes: Vec<f32> = f.markers.iter().map(|m| m.size_px).collect();
    assert_eq!(sizes, vec![MAX_MARKER_PX, DOT_PX, -MIN_MARKER_PX]);
    assert!(f
        .strokes
        .iter()
        .all(|s| s.a.iter().chain(&s.b).chain(&s.dash).all(|x| x.is_finite())));
}

#[test]
fn ticks_mark_each_sample_across_its_path() {
    let mut f = Frame::default();
    let samples: Vec<Vec3> = (0..5)
        .map(|i| Vec3::new(i as f32 * i as f32, 0.0, 0.0))
        .collect();
    f.ticks(&samples, TICK_PX, palette::KEY);
    assert_eq!(f.markers.len(), 5);
    for (m, p) in f.markers.iter().zip(&samples) {
        assert_eq!(m.center, p.to_array());
        assert_eq!(m.shape, MARKER_TICK);
        assert_eq!(m.tangent, [1.0, 0.0, 0.0]);
    }
    // A single sample has no direction: its tick faces the screen's x axis.
    f.clear();
    f.ticks(&[Vec3::ONE], TICK_PX, palette::KEY);
    assert_eq!(f.markers[0].tangent, [0.0; 3]);
}

#[test]
fn wide_lines_and_markers_change_the_fingerprint() {
    let base = || {
        let mut f = Frame::default();
        f.wide_line(Vec3::ZERO, Vec3::X, palette::RED, 2.0);
        f.marker(Vec3::Y, 8.0, palette::BLUE);
        f
    };
    assert_eq!(base().fingerprint(), base().fingerprint());
    let mut wider = base();
    wider.strokes[0].width_px = 3.0;
    assert_ne!(wider.fingerprint(), base().fingerprint());
    let mut bigger = base();
    bigger.markers[0].size_px = 9.0;
    assert_ne!(bigger.fingerprint(), base().fingerprint());
    let mut framed = base();
    framed.keep_box_in_view(Vec3::ZERO, Vec3::ONE);
    assert_ne!(framed.fingerprint(), base().fingerprint());
}

#[test]
fn a_contact_shadow_widens_and_fades_as_its_object_rises() {
    let mut f = Frame::default();
    for h in [0.0, 0.1, 0.3, 0.6, 1.49] {
        f.contact_shadow(Vec3::new(1.0, h, -2.0), 0.2);
    }
    // At the reach (1.5 m for a small object, four radii for a big one) and above, below the
    // ground, or a bad radius: no shadow.
    assert_eq!(Frame::shadow_reach(0.2), 1.5);
    assert_eq!(Frame::shadow_reach(1.0), 4.0);
    f.contact_shadow(Vec3::new(0.0, 1.5, 0.0), 0.2);
    f.contact_shadow(Vec3::new(0.0, 4.0, 0.0), 1.0);
    f.contact_shadow(Vec3::new(0.0, -0.5, 0.0), 0.2);
    f.contact_shadow(Vec3::ZERO, 0.0);
    f.contact_shadow(Vec3::ZERO, f32::NAN);
    f.contact_shadow(Vec3::NAN, 0.2);
    assert_eq!(f.markers.len(), 5);
    for m in &f.markers {
        assert_eq!(m.shape, MARKER_SHADOW);
        assert_eq!(
            m.center,
            [1.0, SHADOW_LIFT_M, -2.0],
            "on the ground under the object"
        );
    }
    assert!(
        (f.markers[0].color[3] - 0.45).abs() < 1e-6 && (f.markers[0].size_px - 0.2).abs() < 1e-6
    );
    for pair in f.markers.windows(2) {
        assert!(pair[1].color[3] < pair[0].color[3], "fainter higher up");
        assert!(pair[1].size_px > pair[0].size_px, "wider higher up");
    }
}

#[test]
fn axes_are_wide_strokes_in_the_axis_colours() {
    let mut f = Frame::default();
    f.axes(glam::Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0)), 0.5);
    assert!(f.lines.is_empty(), "no 1-pixel axis lines");
    assert_eq!(f.strokes.len(), 3);
    for (s, color) in f
        .strokes
        .iter()
        .zip([palette::X_AXIS, palette::Y_AXIS, palette::Z_AXIS])
    {
        assert_eq!(s.width_px, AXIS_PX);
        assert!(AXIS_PX >= 2.0, "wide enough to see at 800 x 600");
        assert_eq!(s.color[..3], color.to_array());
        assert_eq!(s.a, [1.0, 2.0, 3.0]);
        assert!((Vec3::from(s.b).distance(Vec3::from(s.a)) - 0.5).abs() < 1e-6);
        // Drawn over the grid's centre lines, which lie at the same depth (the overlay bias).
        assert_eq!(s.depth_bias, OVERLAY_BIAS);
    }
    // Their quads are AXIS_PX CSS pixels wide on screen, at both page sizes.
    let camera = OrbitCamera::default();
    for size in [Vec2::new(800.0, 600.0), Vec2::new(1600.0, 1000.0)] {
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        for s in &f.strokes {
            let (corners, half) = stroke_corners(s, view_proj, size, 1.0).expect("in view");
            assert!((2.0 * half - AXIS_PX).abs() < 1e-4);
            // Plus the antialiased pixel on each side.
            assert!((quad_width(&corners) - (AXIS_PX + 2.0)).abs() < 0.05);
        }
    }
}
