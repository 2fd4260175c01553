//! Label layout: where each label's box goes on the canvas so that no two overlap.
//!
//! The viewer projects the labels' anchors ([`super::project_labels`]); the page measures each
//! label's text and asks for a layout. Labels are placed one at a time, highest priority first
//! (equal priorities in the order the scene added them). Each tries its preferred place beside
//! its anchor, then the other side, above and below, then places nudged further away along the
//! screen; every candidate is first moved inside the canvas, [`EDGE_PX`] from its edges. The
//! first candidate that overlaps no label already placed wins. A label placed away from its
//! anchor gets a leader line back to it; a label with no free candidate is hidden. So a label
//! never moves or hides because of a label of lower priority.

use glam::Vec2;

/// Space between an anchor and its label's box, CSS pixels.
pub const GAP_PX: f32 = 5.0;
/// Space kept between two labels' boxes, CSS pixels.
pub const PAD_PX: f32 = 2.0;
/// Space kept between a label's box and the canvas's edges, CSS pixels: text that touches the
/// edge reads as cut.
pub const EDGE_PX: f32 = 4.0;
/// How far from its anchor a label may be nudged, in label heights.
const MAX_RINGS: usize = 5;
/// A label whose box ends further than this from the point it names (CSS pixels) gets a leader
/// line back to it, even where the figure put it there on purpose: beyond about a label's height
/// the eye no longer pairs a name with its dot. A name just off a dot (half the dot's size plus a
/// few pixels, at most 12 px for the largest dots the figures draw) gets none.
pub const LEADER_PX: f32 = 20.0;

/// One label to place: its anchor on the canvas (CSS pixels from the top-left), its box's size,
/// whether it reads leftwards from the anchor, whether its anchor is in view, and its priority.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LabelBox {
    pub anchor: Vec2,
    pub size: Vec2,
    pub left: bool,
    pub visible: bool,
    pub priority: i32,
}

/// Where a label went: its box's top-left corner (CSS pixels), whether it is shown, and, when it
/// sits away from its anchor, the point of its box nearest the anchor (where the leader line
/// ends).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub top_left: Vec2,
    pub shown: bool,
    pub leader_to: Option<Vec2>,
}

/// An axis-aligned box: top-left corner and size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    pub min: Vec2,
    pub size: Vec2,
}

impl Rect {
    pub fn max(&self) -> Vec2 {
        self.min + self.size
    }

    /// Whether the two boxes come closer than `pad` to each other (or overlap).
    pub fn overlaps(&self, other: &Rect, pad: f32) -> bool {
        self.min.x < other.max().x + pad
            && other.min.x < self.max().x + pad
            && self.min.y < other.max().y + pad
            && other.min.y < self.max().y + pad
    }

    /// The point of the box nearest `p`.
    pub fn nearest(&self, p: Vec2) -> Vec2 {
        p.clamp(self.min, self.max())
    }
}

/// The box a label takes where it prefers to be: just right of its anchor (left of it for a
/// left label), centred on it vertically.
pub fn preferred(label: &LabelBox) -> Vec2 {
    let y = label.anchor.y - 0.5 * label.size.y;
    if label.left {
        Vec2::new(label.anchor.x - GAP_PX - label.size.x, y)
    } else {
        Vec2::new(label.anchor.x + GAP_PX, y)
    }
}

/// The places a label tries, in order (top-left corners, before they are moved into the canvas).
fn candidates(label: &LabelBox) -> Vec<Vec2> {
    let a = label.anchor;
    let s = label.size;
    let first = preferred(label);
    let mirrored = LabelBox {
        left: !label.left,
        ..*label
    };
    let other = preferred(&mirrored);
    let above = Vec2::new(a.x - 0.5 * s.x, a.y - GAP_PX - s.y);
    let below = Vec2::new(a.x - 0.5 * s.x, a.y + GAP_PX);
    let mut out = vec![first, other, above, below];
    let step = s.y + PAD_PX + 1.0;
    for ring in 1..=MAX_RINGS {
        let dy = ring as f32 * step;
        for base in [first, other] {
            out.push(base + Vec2::new(0.0, -dy));
            out.push(base + Vec2::new(0.0, dy));
        }
        let dx = ring as f32 * (0.5 * s.x + GAP_PX);
        out.push(above + Vec2::new(dx, -dy + step));
        out.push(above + Vec2::new(-dx, -dy + step));
        out.push(below + Vec2::new(dx, dy - step));
        out.push(below + Vec2::new(-dx, dy - step));
    }
    out
}

/// Moves a box's corner so the box lies inside a `canvas`-sized area, [`EDGE_PX`] from its
/// edges (a box too large for that keeps its top-left corner `EDGE_PX` from the canvas's).
pub fn inside(top_left: Vec2, size: Vec2, canvas: Vec2) -> Vec2 {
    top_left
        .min(canvas - size - Vec2::splat(EDGE_PX))
        .max(Vec2::splat(EDGE_PX))
}

/// Where a leader line from `dot` (the projection of the point a label names) ends on the
/// label's placed box `rect`, if it needs one: when the box ends more than [`LEADER_PX`] from the
/// dot, or when the layout `moved` the label from its first place and the box is not touching
/// the dot. The line ends at the box's point nearest the dot.
pub fn leader(rect: Rect, dot: Vec2, moved: bool) -> Option<Vec2> {
    let near = rect.nearest(dot);
    let d = near.distance(dot);
    (d > LEADER_PX || (moved && d > GAP_PX + 2.0)).then_some(near)
}

/// Places `labels` on a canvas of `canvas` CSS pixels (see the module's description). Labels
/// whose anchor is out of view are not shown.
pub fn place(labels: &[LabelBox], canvas: Vec2) -> Vec<Placement> {
    place_avoiding(labels, canvas, &[])
}

/// The indices of `priorities`, highest first, equal priorities in their given order (a
/// stable sort): the order in which [`place_avoiding`], and a figure that places its own labels,
/// take them. A binary insertion sort: a figure has tens of labels, and every caller shares this
/// one small body (each `sort_by_key` closure would compile a whole sort of its own).
pub fn priority_order(priorities: &[i32]) -> Vec<usize> {
    let mut order: Vec<usize> = Vec::with_capacity(priorities.len());
    for (i, &p) in priorities.iter().enumerate() {
        // After every index of a priority ≥ p: equal priorities keep their order.
        let at = order.partition_point(|&j| priorities[j] >= p);
        order.insert(at, i);
    }
    order
}

/// [`place`], keeping every label off the `obstacles` too (a figure's inset).
pub fn place_avoiding(labels: &[LabelBox], canvas: Vec2, obstacles: &[Rect]) -> Vec<Placement> {
    let priorities: Vec<i32> = labels.iter().map(|l| l.priority).collect();
    let order = priority_order(&priorities);
    let hidden = Placement {
        top_left: Vec2::ZERO,
        shown: false,
        leader_to: None,
    };
    let mut out = vec![hidden; labels.len()];
    let mut taken: Vec<Rect> = Vec::with_capacity(labels.len() + obstacles.len());
    taken.extend_from_slice(obstacles);
    for i in order {
        let label = &labels[i];
        if !label.visible || !label.anchor.is_finite() || !label.size.is_finite() {
            continue;
        }
        let size = label.size.max(Vec2::ZERO);
        let free = candidates(label).into_iter().find_map(|c| {
            let rect = Rect {
                min: inside(c, size, canvas),
                size,
            };
            (!taken.iter().any(|t| t.overlaps(&rect, PAD_PX))).then_some(rect)
        });
        let Some(rect) = free else { continue };
        taken.push(rect);
        let near = rect.nearest(label.anchor);
        out[i] = Placement {
            top_left: rect.min,
            shown: true,
            leader_to: (near.distance(label.anchor) > GAP_PX + 2.0).then_some(near),
        };
    }
    out
}
