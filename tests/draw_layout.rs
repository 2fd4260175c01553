//! Native tests of the label layout (src/draw/layout.rs): no two shown labels overlap, every
//! shown label lies inside the canvas, and priorities decide who keeps its place.

use glam::Vec2;
use inbetween::draw::layout::{
    place, preferred, priority_order, LabelBox, Placement, Rect, EDGE_PX, PAD_PX,
};
use proptest::prelude::*;

fn rect(label: &LabelBox, p: &Placement) -> Rect {
    Rect {
        min: p.top_left,
        size: label.size,
    }
}

/// Asserts what every layout must hold: shown boxes inside the canvas, `EDGE_PX` from its
/// edges (text touching the edge reads as cut), apart from each other.
fn check_layout(labels: &[LabelBox], placed: &[Placement], canvas: Vec2) {
    assert_eq!(labels.len(), placed.len());
    let shown: Vec<(usize, Rect)> = placed
        .iter()
        .enumerate()
        .filter(|(_, p)| p.shown)
        .map(|(i, p)| (i, rect(&labels[i], p)))
        .collect();
    for (i, r) in &shown {
        assert!(
            labels[*i].visible,
            "label {i} shown with its anchor out of view"
        );
        assert!(
            r.min.x >= EDGE_PX - 1e-3
                && r.min.y >= EDGE_PX - 1e-3
                && r.max().x <= canvas.x - EDGE_PX + 1e-3
                && r.max().y <= canvas.y - EDGE_PX + 1e-3,
            "label {i} at {r:?} leaves the {canvas} canvas or touches its edge"
        );
    }
    for (k, (i, a)) in shown.iter().enumerate() {
        for (j, b) in &shown[k + 1..] {
            assert!(
                !a.overlaps(b, PAD_PX - 1e-3),
                "labels {i} {a:?} and {j} {b:?} overlap"
            );
        }
    }
}

fn label(x: f32, y: f32, w: f32, priority: i32) -> LabelBox {
    LabelBox {
        anchor: Vec2::new(x, y),
        size: Vec2::new(w, 16.0),
        left: false,
        visible: true,
        priority,
    }
}

#[test]
fn a_lone_label_sits_right_of_its_anchor() {
    let canvas = Vec2::new(800.0, 600.0);
    let l = label(100.0, 200.0, 40.0, 0);
    let p = place(&[l], canvas)[0];
    assert!(p.shown && p.leader_to.is_none());
    assert_eq!(p.top_left, preferred(&l));
    assert!(p.top_left.x > 100.0 && (p.top_left.y + 8.0 - 200.0).abs() < 1e-4);
}

#[test]
fn two_labels_on_one_anchor_both_show_apart() {
    let canvas = Vec2::new(800.0, 600.0);
    let labels = [label(300.0, 300.0, 60.0, 0), label(300.0, 300.0, 60.0, 0)];
    let placed = place(&labels, canvas);
    check_layout(&labels, &placed, canvas);
    assert!(placed.iter().all(|p| p.shown));
    // The first keeps its preferred place; the second goes to the anchor's other side.
    assert_eq!(placed[0].top_left, preferred(&labels[0]));
    assert!(placed[1].top_left.x + 60.0 <= 300.0, "{:?}", placed[1]);
}

#[test]
fn the_higher_priority_label_keeps_its_place_whatever_the_order() {
    let canvas = Vec2::new(800.0, 600.0);
    let low = label(300.0, 300.0, 60.0, 0);
    let high = label(305.0, 302.0, 60.0, 5);
    let placed = place(&[low, high], canvas);
    assert_eq!(placed[1].top_left, preferred(&high));
    assert_ne!(placed[0].top_left, preferred(&low));
    check_layout(&[low, high], &placed, canvas);
}

#[test]
fn a_label_at_the_edge_is_pulled_inside_the_canvas() {
    let canvas = Vec2::new(400.0, 300.0);
    let labels = [label(395.0, 2.0, 80.0, 0), label(-3.0, 299.0, 50.0, 0)];
    let placed = place(&labels, canvas);
    check_layout(&labels, &placed, canvas);
    assert!(placed.iter().all(|p| p.shown));
}

#[test]
fn a_moved_label_gets_a_leader_line_to_its_box() {
    let canvas = Vec2::new(800.0, 600.0);
    // Eight labels on one anchor: the first two sit beside it, the rest are nudged away.
    let labels: Vec<LabelBox> = (0..8).map(|_| label(400.0, 300.0, 50.0, 0)).collect();
    let placed = place(&labels, canvas);
    check_layout(&labels, &placed, canvas);
    assert!(placed.iter().all(|p| p.shown));
    assert!(placed[0].leader_to.is_none());
    let far: Vec<&Placement> = placed.iter().filter(|p| p.leader_to.is_some()).collect();
    assert!(!far.is_empty());
    for p in far {
        let r = Rect {
            min: p.top_left,
            size: Vec2::new(50.0, 16.0),
        };
        let end = p.leader_to.unwrap();
        assert!(end.distance(r.nearest(Vec2::new(400.0, 300.0))) < 1e-4);
    }
}

#[test]
fn with_no_room_the_lowest_priorities_hide() {
    // A canvas with room for a handful of labels, and forty of them on one spot.
    let canvas = Vec2::new(120.0, 60.0);
    let labels: Vec<LabelBox> = (0..40).map(|i| label(60.0, 30.0, 50.0, i)).collect();
    let placed = place(&labels, canvas);
    check_layout(&labels, &placed, canvas);
    let shown: Vec<i32> = placed
        .iter()
        .zip(&labels)
        .filter(|(p, _)| p.shown)
        .map(|(_, l)| l.priority)
        .collect();
    assert!(shown.len() >= 2 && shown.len() < 40, "{shown:?}");
    // Everything shown outranks everything hidden.
    let lowest_shown = *shown.iter().min().unwrap();
    let hidden_max = placed
        .iter()
        .zip(&labels)
        .filter(|(p, _)| !p.shown)
        .map(|(_, l)| l.priority)
        .max()
        .unwrap();
    assert!(
        hidden_max < lowest_shown,
        "hidden {hidden_max} outranks shown {lowest_shown}"
    );
}

#[test]
fn labels_out_of_view_are_not_shown_and_take_no_room() {
    let canvas = Vec2::new(800.0, 600.0);
    let mut hidden = label(300.0, 300.0, 60.0, 9);
    hidden.visible = false;
    let seen = label(300.0, 300.0, 60.0, 0);
    let placed = place(&[hidden, seen], canvas);
    assert!(!placed[0].shown);
    assert_eq!(placed[1].top_left, preferred(&seen));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// N labels anywhere in a box: the shown ones never overlap and stay inside; removing every
    /// label below some priority moves none of those left (a label never gives way to a lower one).
    #[test]
    fn no_overlaps_and_priorities_respected(
        raw in prop::collection::vec((-20f32..820.0, -20f32..620.0, 10f32..140.0, 0i32..4, any::<bool>()), 1..40),
        cut in 0i32..4,
        big in any::<bool>(),
    ) {
        let canvas = if big { Vec2::new(1600.0, 1000.0) } else { Vec2::new(800.0, 600.0) };
        let labels: Vec<LabelBox> = raw.iter().map(|&(x, y, w, p, left)| LabelBox {
            anchor: Vec2::new(x, y), size: Vec2::new(w, 16.0), left, visible: true, priority: p,
        }).collect();
        let placed = place(&labels, canvas);
        check_layout(&labels, &placed, canvas);
        let kept: Vec<usize> = (0..labels.len()).filter(|&i| labels[i].priority >= cut).collect();
        let fewer: Vec<LabelBox> = kept.iter().map(|&i| labels[i]).collect();
        let again = place(&fewer, canvas);
        for (k, &i) in kept.iter().enumerate() {
            prop_assert_eq!(again[k], placed[i], "label {} moved when lower priorities left", i);
        }
    }

    /// The layout's order is the standard library's stable sort by descending priority: highest
    /// first, equal priorities in the order given (a tie taken out of order, or ascending).
    #[test]
    fn priority_order_is_a_stable_descending_sort(priorities in prop::collection::vec(-3i32..4, 0..60)) {
        let mut expected: Vec<usize> = (0..priorities.len()).collect();
        expected.sort_by_key(|&i| std::cmp::Reverse(priorities[i]));
        prop_assert_eq!(priority_order(&priorities), expected);
    }
}

/// The canvas and view the leader-line tests use: the project's orbit camera, 5 m from the origin.
fn leader_view() -> (glam::Mat4, Vec2) {
    let canvas = Vec2::new(800.0, 600.0);
    let camera = inbetween::camera::OrbitCamera::from_view([0.0, 0.0, 0.0, 5.0, 0.3, 0.2]);
    (camera.projection(canvas.x / canvas.y) * camera.view(), canvas)
}

#[test]
fn a_name_just_off_its_dot_gets_no_leader_line_and_one_moved_out_gets_one_to_its_box() {
    use inbetween::draw::{layout::leader, project_labels, Label};
    let (view_proj, canvas) = leader_view();
    let anchor = glam::Vec3::new(0.3, -0.2, 0.5);
    for dot_px in [0.0, 4.0, 8.0, 14.0, 16.0] {
        // Eight sides at the dot's gap, then six places further out by 10 px each.
        let candidates = Label::around_dot(anchor, dot_px, Vec2::ZERO, "name", glam::Vec3::ONE, 0, 7, 10.0);
        let screen = project_labels(&candidates, view_proj, canvas.x, canvas.y);
        let dot = screen[0].dot_px;
        for (k, (label, s)) in candidates.iter().zip(&screen).enumerate() {
            assert_eq!(s.dot_px, dot, "every candidate names the same point");
            let rect = label.first_place(view_proj, canvas).unwrap();
            let gap = rect.nearest(dot).distance(dot);
            let line = leader(rect, dot, false);
            if k < 8 {
                // The first ring: just off the dot, as the figures place a name first.
                assert!(line.is_none(), "dot {dot_px} px, side {k}: {gap} px away, leader {line:?}");
            }
            match line {
                Some(end) => {
                    assert!(gap > inbetween::draw::layout::LEADER_PX);
                    assert!(end.distance(rect.nearest(dot)) < 1e-4, "the line ends on the box");
                }
                None => assert!(gap <= inbetween::draw::layout::LEADER_PX),
            }
        }
        // The outermost ring is 60 px further out: every one of its places is led back.
        assert!(candidates[48..]
            .iter()
            .all(|l| leader(l.first_place(view_proj, canvas).unwrap(), dot, false).is_some()));
    }
}

#[test]
fn a_label_the_layout_moved_off_its_dot_gets_a_leader_line_unless_it_still_touches_the_dot() {
    use inbetween::draw::layout::{leader, GAP_PX};
    let dot = Vec2::new(100.0, 100.0);
    let size = Vec2::new(40.0, 16.0);
    // Moved to just below the dot, touching it: no line; moved 12 px off: a line.
    let touching = Rect { min: Vec2::new(80.0, 100.0 + GAP_PX), size };
    assert!(leader(touching, dot, true).is_none());
    assert!(leader(touching, dot, false).is_none());
    let off = Rect { min: Vec2::new(80.0, 112.0), size };
    assert_eq!(leader(off, dot, true), Some(Vec2::new(100.0, 112.0)));
    assert!(leader(off, dot, false).is_none(), "12 px, where the figure put it: no line");
}

#[test]
fn a_line_that_only_clips_a_labels_corner_is_not_clear_of_it() {
    use inbetween::draw::{Frame, StrokeStyle};
    use glam::{Mat4, Vec3};
    // World x, y are canvas pixels (y down): the label's first place is its box's top-left at
    // (105, 92), 5 px right of its anchor and centred on it.
    let canvas = Vec2::new(800.0, 600.0);
    let view_proj = Mat4::from_translation(Vec3::new(-1.0, 1.0, 0.0))
        * Mat4::from_scale(Vec3::new(2.0 / canvas.x, -2.0 / canvas.y, 1.0));
    let mut frame = Frame::default();
    frame.label(Vec3::new(100.0, 100.0, 0.0), "name", Vec3::ONE);
    let label = frame.labels.pop().unwrap();
    let rect = label.first_place(view_proj, canvas).unwrap();
    assert!(rect.min.distance(Vec2::new(105.0, 92.0)) < 1e-3, "{:?}", rect.min);
    // Long lines x + y = c, 4,000 px long: their points 1/16 of the way apart lie hundreds of
    // pixels from the box, and the box's top-left corner lies on x + y = 197.
    let line = |c: f32| {
        let mut frame = Frame::default();
        frame.stroke(
            &[Vec3::new(-2000.0, c + 2000.0, 0.0), Vec3::new(2000.0, c - 2000.0, 0.0)],
            Vec3::ONE,
            StrokeStyle::solid(2.0),
        );
        frame
    };
    // Through the corner, 2 px in along each axis.
    assert!(!line(199.0).label_is_clear(view_proj, canvas, &label));
    // 7 px out along each axis: clear, but not by 7 px (the box grown by the margin and the
    // line's half width reaches past it).
    assert!(line(190.0).label_is_clear(view_proj, canvas, &label));
    assert!(line(190.0).label_is_clear_by(view_proj, canvas, &label, 2.0));
    assert!(!line(190.0).label_is_clear_by(view_proj, canvas, &label, 7.0));
    // A point-long stroke inside the box is not clear either; one on its edge is.
    let dot = |p: Vec3| {
        let mut frame = Frame::default();
        frame.stroke(&[p, p], Vec3::ONE, StrokeStyle::solid(1.0));
        frame
    };
    assert!(!dot(Vec3::new(110.0, 100.0, 0.0)).label_is_clear(view_proj, canvas, &label));
    assert!(dot(Vec3::new(110.0, 80.0, 0.0)).label_is_clear(view_proj, canvas, &label));
}

/// The orderings by a float key (src/order.rs), which the label sides, the arrows and the
/// sprites use: largest or smallest first, equal keys in index order, a NaN key as `total_cmp`
/// places it, and the smallest-first order the exact reverse of the largest-first one where no
/// keys tie.
#[test]
fn orderings_by_a_float_key_are_stable_and_exact() {
    use inbetween::order::{order_by, sort_desc};
    let keys = [2.0, -1.0, 3.0, 2.0, 0.0, -0.0, 3.0];
    assert_eq!(order_by(keys, true), vec![2, 6, 0, 3, 4, 5, 1]);
    assert_eq!(order_by(keys, false), vec![1, 5, 4, 0, 3, 2, 6]);
    let distinct = [0.5, -2.0, 7.0, 1e-30, -0.0];
    let mut up = order_by(distinct, false);
    up.reverse();
    assert_eq!(up, order_by(distinct, true));
    let mut pairs = [(1.0, 0), (f32::NAN, 1), (f32::INFINITY, 2), (1.0, 3)];
    sort_desc(&mut pairs);
    assert_eq!(pairs.map(|p| p.1), [1, 2, 0, 3]);
}

/// `sort_ascending` orders exactly as `sort_by(f32::total_cmp)`: -0 before +0, a NaN with the
/// sign bit set first and one without last, every value's bits kept.
#[test]
fn sort_ascending_matches_total_cmp() {
    let values = [2.5, -0.0, f32::NAN, 0.0, -f32::NAN, -7.0, f32::INFINITY, 1e-30, 2.5, -1e-30];
    let mut expected = values;
    expected.sort_by(f32::total_cmp);
    let mut sorted = values;
    inbetween::order::sort_ascending(&mut sorted);
    assert_eq!(sorted.map(f32::to_bits), expected.map(f32::to_bits));
    assert!(sorted[0].is_nan() && sorted[0].is_sign_negative());
    assert_eq!(sorted[1], -7.0);
}
