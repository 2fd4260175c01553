use glam::{Vec2, Vec3};
use inbetween::draw::inset::*;
use inbetween::draw::layout::Rect;

#[test]
fn the_inset_sits_in_the_bottom_right_corner_inside_the_canvas() {
    for canvas in [
        Vec2::new(800.0, 600.0),
        Vec2::new(1600.0, 1000.0),
        Vec2::new(300.0, 100.0),
    ] {
        let r = inset_rect(canvas);
        assert!(r.min.cmpge(Vec2::ZERO).all(), "{canvas}: {r:?}");
        assert!((r.max() - (canvas - INSET_MARGIN_PX)).abs().max_element() < 1e-3);
        assert_eq!(r.size.x, r.size.y);
    }
    assert_eq!(inset_rect(Vec2::new(800.0, 600.0)).size.x, 0.36 * 600.0);
}

#[test]
fn the_box_fills_the_inset_from_every_side() {
    let (min, max) = (Vec3::new(-2.0, 0.0, -0.5), Vec3::new(1.0, 3.0, 0.5));
    for view in [InsetView::Top, InsetView::Side, InsetView::Front] {
        let inset = Inset {
            view,
            title: String::new(),
            min,
            max,
            fit_above: false,
            only: None,
        };
        let (v, p, _) = inset_camera(&inset).unwrap();
        let mut extent = Vec2::ZERO;
        for c in inbetween::draw::box_corners(min, max) {
            let ndc = (p * v).project_point3(c);
            assert!(
                ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0,
                "{view:?}: {c} at {ndc}"
            );
            assert!((0.0..=1.0).contains(&ndc.z), "{view:?}: depth {}", ndc.z);
            extent = extent.max(ndc.truncate().abs());
        }
        // The larger extent reaches the padding, not less.
        assert!(extent.max_element() > 0.85, "{view:?}: {extent}");
    }
}

#[test]
fn each_view_looks_along_its_axis() {
    let inset = |view| Inset {
        view,
        title: String::new(),
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
        fit_above: false,
        only: None,
    };
    let ndc = |view, p: Vec3| {
        let (v, proj, _) = inset_camera(&inset(view)).unwrap();
        (proj * v).project_point3(p)
    };
    // From above: +x to the right, −z up; height only changes depth.
    assert!(ndc(InsetView::Top, Vec3::X).x > 0.5);
    assert!(ndc(InsetView::Top, Vec3::NEG_Z).y > 0.5);
    assert!(ndc(InsetView::Top, Vec3::Y).z < ndc(InsetView::Top, Vec3::NEG_Y).z);
    // From the side (+x): −z to the right, +y up.
    assert!(ndc(InsetView::Side, Vec3::NEG_Z).x > 0.5);
    assert!(ndc(InsetView::Side, Vec3::Y).y > 0.5);
    // From the front (+z): +x right, +y up.
    assert!(ndc(InsetView::Front, Vec3::X).x > 0.5);
    assert!(ndc(InsetView::Front, Vec3::Z).z < ndc(InsetView::Front, Vec3::NEG_Z).z);
}

#[test]
fn labels_keep_off_the_inset_and_its_title_sits_inside_it() {
    use inbetween::draw::layout::{place_avoiding, LabelBox};
    let canvas = Vec2::new(800.0, 600.0);
    let inset = inset_rect(canvas);
    // Labels anchored all over the canvas, some inside the inset's square.
    let labels: Vec<LabelBox> = (0..60)
        .map(|i| LabelBox {
            anchor: Vec2::new(13.0 * i as f32 % 800.0, 37.0 * i as f32 % 600.0),
            size: Vec2::new(70.0, 16.0),
            left: i % 3 == 0,
            visible: true,
            priority: i % 4,
        })
        .collect();
    let placed = place_avoiding(&labels, canvas, &[inset]);
    let mut shown = 0;
    for (p, l) in placed.iter().zip(&labels) {
        if p.shown {
            shown += 1;
            let r = Rect {
                min: p.top_left,
                size: l.size,
            };
            assert!(!r.overlaps(&inset, 0.0), "{r:?} on the inset {inset:?}");
        }
    }
    assert!(shown > 20, "only {shown} of 60 labels placed");
    let title = title_top_left(canvas);
    assert!(title.cmpgt(inset.min).all() && title.cmplt(inset.max()).all());
}

#[test]
fn a_box_that_is_not_finite_or_empty_has_no_camera() {
    let inset = |min, max| Inset {
        view: InsetView::Top,
        title: String::new(),
        min,
        max,
        fit_above: false,
        only: None,
    };
    assert!(inset_camera(&inset(Vec3::ZERO, Vec3::splat(f32::NAN))).is_none());
    assert!(inset_camera(&inset(Vec3::ONE, Vec3::ONE)).is_none());
}
