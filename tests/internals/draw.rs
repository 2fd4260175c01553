use glam::{Mat4, Vec3};
use inbetween::draw::*;

#[test]
fn translated_moves_everything_the_closure_added_and_nothing_else() {
    let mut f = Frame::default();
    f.line(Vec3::ZERO, Vec3::X, palette::DARK);
    let offset = Vec3::new(2.0, 0.5, -1.0);
    f.translated(offset, |f| {
        f.mesh(MeshId::CUBE, Mat4::IDENTITY, palette::ORANGE);
        f.line(Vec3::ZERO, Vec3::Y, palette::TEAL);
        f.wide_line(Vec3::ZERO, Vec3::Z, palette::TEAL, 2.0);
        f.marker(Vec3::ONE, 10.0, palette::TEAL);
        f.label(Vec3::Y, "copy", palette::DARK);
        f.keep_in_view.push(Vec3::ZERO);
    });
    // The line drawn before stays; everything drawn inside moved by the offset.
    assert_eq!(
        f.segments_of(palette::DARK).next(),
        Some((Vec3::ZERO, Vec3::X))
    );
    let teal: Vec<_> = f.segments_of(palette::TEAL).collect();
    assert_eq!(
        teal,
        vec![(offset, offset + Vec3::Y), (offset, offset + Vec3::Z)]
    );
    assert_eq!(f.meshes[0].model.w_axis.truncate(), offset);
    assert_eq!(Vec3::from(f.markers[0].center), Vec3::ONE + offset);
    assert_eq!(f.labels[0].anchor, Vec3::Y + offset);
    assert_eq!(f.keep_in_view, vec![offset]);
}

#[test]
fn side_by_side_centres_the_copies_and_titles_each() {
    let mut f = Frame::default();
    let titles = [("LBS", palette::ORANGE), ("DQS", palette::TEAL)];
    f.side_by_side(Vec3::new(1.5, 0.0, 0.0), &titles, 2.0, |f, k| {
        f.mesh(
            MeshId::SPHERE,
            Mat4::from_scale(Vec3::splat(0.1 + k as f32)),
            palette::GREY,
        );
    });
    let centres: Vec<Vec3> = f.meshes.iter().map(|m| m.model.w_axis.truncate()).collect();
    assert_eq!(
        centres,
        vec![Vec3::new(-0.75, 0.0, 0.0), Vec3::new(0.75, 0.0, 0.0)]
    );
    // Each copy got its own draw call (k), and its title over it, kept in view, placed first.
    assert!((f.meshes[1].model.x_axis.x - 1.1).abs() < 1e-6);
    let l: Vec<_> = f
        .labels
        .iter()
        .map(|l| (l.text.as_str(), l.anchor, l.priority))
        .collect();
    assert_eq!(
        l,
        vec![
            ("LBS", Vec3::new(-0.75, 2.0, 0.0), 1),
            ("DQS", Vec3::new(0.75, 2.0, 0.0), 1)
        ]
    );
    assert_eq!(f.keep_in_view.len(), 2);
}

#[test]
fn the_grid_fades_towards_its_rim() {
    let mut f = Frame::default();
    f.grid(12, 0.25);
    let half = 1.5;
    let mut inner = 0;
    for v in &f.lines {
        let p = Vec3::from(v.position);
        let rgb = Vec3::from_slice(&v.color[..3]);
        assert!(rgb == palette::GRID || rgb == palette::GRID_AXIS);
        let r = p.length() / half;
        if r <= 0.5 {
            inner += 1;
            assert_eq!(v.color[3], 1.0, "{p}");
        }
        if r >= 1.0 {
            assert!(v.color[3] <= 0.15 + 1e-6, "{p}: {}", v.color[3]);
        }
    }
    assert!(inner > 20);
    // Opacity never grows outwards.
    assert!((0..=20).all(|i| grid_fade(i as f32 * 0.1) >= grid_fade((i + 1) as f32 * 0.1)));
    // The lines still span the whole grid.
    let far = f
        .lines
        .iter()
        .map(|v| Vec3::from(v.position).x.abs())
        .fold(0.0, f32::max);
    assert!((far - half).abs() < 1e-5);
}

#[test]
fn arrow_is_a_shaft_and_a_cone_ending_at_the_tip() {
    let mut f = Frame::default();
    f.arrow(Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0), palette::BLUE, 0.3);
    assert_eq!(f.strokes.len(), 1);
    assert_eq!(f.strokes[0].width_px, ARROW_PX);
    assert_eq!(f.meshes.len(), 1);
    let tip = f.meshes[0].model.transform_point3(Vec3::Y);
    assert!((tip - Vec3::new(0.0, 0.0, 2.0)).length() < 1e-5, "{tip}");
    f.clear();
    f.arrow(Vec3::ONE, Vec3::ONE, palette::BLUE, 0.3);
    assert!(f.strokes.is_empty() && f.meshes.is_empty());
    // On top: the shaft and three head strokes from the cone's rim to the tip, all over
    // everything (a cone inside a surface is hidden, and the arrow would read as a line).
    f.arrow_on_top(Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0), palette::BLUE, 0.3);
    assert_eq!(f.strokes.len(), 4);
    assert!(f.strokes.iter().all(|s| s.depth_bias == ON_TOP));
    for s in &f.strokes[1..] {
        let (rim, tip) = (Vec3::from(s.a), Vec3::from(s.b));
        assert!(tip.distance(Vec3::new(0.0, 0.0, 2.0)) < 1e-5, "{tip}");
        assert!((rim.z - 1.7).abs() < 1e-5 && (rim.truncate().length() - 0.105).abs() < 1e-5);
    }
}

#[test]
fn palette_matches_its_css_twin() {
    // www/palette.css must give the words of the text these very colours.
    let css = include_str!("../../www/palette.css");
    for (name, color) in palette::NAMED {
        let hex = palette::css(*color);
        let rule = format!("--{name}: {hex};");
        assert!(css.contains(&rule), "www/palette.css lacks `{rule}`");
    }
}

#[test]
fn labels_project_to_the_centre_and_hide_behind_the_camera() {
    let cam = inbetween::camera::OrbitCamera::default();
    let vp = cam.projection(2.0) * cam.view();
    let out = project_labels(
        &[
            Label {
                anchor: cam.target,
                text: "c".into(),
                color: Vec3::ONE,
                left: false,
                priority: 0,
                offset_px: glam::Vec2::ZERO,
                large: false,
            },
            Label {
                anchor: cam.eye() + (cam.eye() - cam.target),
                text: "b".into(),
                color: Vec3::ONE,
                left: true,
                priority: 0,
                offset_px: glam::Vec2::ZERO,
                large: false,
            },
        ],
        vp,
        200.0,
        100.0,
    );
    assert!((out[0].x_px - 100.0).abs() < 1e-3 && (out[0].y_px - 50.0).abs() < 1e-3);
    assert!(out[0].visible);
    assert!(!out[1].visible);
}

#[test]
fn fingerprint_sees_any_change() {
    let draw = |x: f32| {
        let mut f = Frame::default();
        f.grid(2, 1.0);
        f.arrow(Vec3::ZERO, Vec3::new(x, 1.0, 0.0), palette::ORANGE, 0.2);
        f.label(Vec3::ONE, "p", palette::PINK);
        f
    };
    assert_eq!(draw(1.0).fingerprint(), draw(1.0).fingerprint());
    assert_ne!(draw(1.0).fingerprint(), draw(1.0001).fingerprint());
    let mut relabelled = draw(1.0);
    relabelled.labels[0].text = "q".into();
    assert_ne!(relabelled.fingerprint(), draw(1.0).fingerprint());
}

#[test]
fn axes_win_over_the_grid_lines_beneath_them() {
    let mut f = Frame::default();
    f.grid(4, 1.0);
    f.axes(Mat4::IDENTITY, 1.0);
    // The grid: thin lines at their depth; the axes: wide strokes biased towards the eye.
    assert!(!f.lines.is_empty());
    assert!(f.lines.iter().all(|v| v.depth_bias == 0.0));
    assert_eq!(f.strokes.len(), 3);
    assert!(f.strokes.iter().all(|s| s.depth_bias == OVERLAY_BIAS));
}
