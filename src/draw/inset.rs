//! A second view of the same frame: a small square in the canvas's bottom-right corner that shows
//! a box of the scene from above, from the side or from the front, with an orthographic camera.
//!
//! One perspective view hides depth: a 15 cm gap along the view direction, or how a flock spreads
//! towards the viewer, cannot be judged from it. The inset draws the frame's meshes, lines,
//! points, wide lines and markers again (not its textured squares and sprites, nor its labels)
//! looking along one axis, so a distance along the main view's depth reads as a distance across
//! the inset. A figure asks for it with [`super::Frame::inset`], naming the box to show; the
//! renderer draws it after the main view, and the label layout keeps the main view's labels off
//! it ([`inset_rect`]).

use super::layout::Rect;
use crate::camera::OrbitCamera;
use glam::{Mat4, Vec2, Vec3};

/// Which way the inset looks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InsetView {
    /// From above, looking down −y; +x to the right, −z up the inset.
    Top,
    /// From +x, looking along −x; −z to the right, +y up.
    Side,
    /// From +z, looking along −z; +x to the right, +y up.
    Front,
}

impl InsetView {
    /// The unit vector from the box's centre towards the inset's eye, and the inset's up.
    fn axes(self) -> (Vec3, Vec3) {
        match self {
            InsetView::Top => (Vec3::Y, Vec3::NEG_Z),
            InsetView::Side => (Vec3::X, Vec3::Y),
            InsetView::Front => (Vec3::Z, Vec3::Y),
        }
    }
}

/// What a frame's inset shows: the view, its title and the box that fills it.
#[derive(Clone, Debug, PartialEq)]
pub struct Inset {
    pub view: InsetView,
    pub title: String,
    pub min: Vec3,
    pub max: Vec3,
    /// The main view fits above the inset (the canvas's whole width) instead of left of it
    /// ([`fit_beside`]): for a wide, low figure ([`super::Frame::fit_above_inset`]).
    pub fit_above: bool,
    /// Only these strokes and markers of the frame, by index, and nothing else: a path close up
    /// without the body that carries it, which at the inset's zoom would fill it. `None`: all.
    pub only: Option<[std::ops::Range<usize>; 2]>,
}

/// Fits `camera` to `points` (see [`OrbitCamera::fit`]) beside `inset` on a canvas of `size`
/// CSS pixels: above the inset's square or left of it, as the inset asks, so the inset hides
/// nothing the figure declared. False (nothing changed) when that fit is impossible.
pub fn fit_beside(
    camera: &mut OrbitCamera,
    inset: &Inset,
    points: &[Vec3],
    size: Vec2,
    pad_px: f32,
) -> bool {
    let square = inset_rect(size);
    if inset.fit_above {
        camera.fit_above(points, size, square.min.y, pad_px)
    } else {
        camera.fit_left_of(points, size, square.min.x, pad_px)
    }
}

/// The inset's side as a fraction of the canvas's shorter side.
pub const INSET_FRACTION: f32 = 0.36;
/// The inset's side at least (CSS pixels), unless the canvas is smaller.
pub const INSET_MIN_PX: f32 = 110.0;
/// Space between the inset and the canvas's edges (CSS pixels).
pub const INSET_MARGIN_PX: f32 = 8.0;
/// The inset's border width (CSS pixels).
pub const INSET_BORDER_PX: f32 = 1.5;
/// The share of the inset the box leaves empty around it (on each side, as a fraction of the
/// box's larger extent).
const INSET_PAD: f32 = 0.08;

/// The inset's square on a canvas of `canvas` CSS pixels: in the bottom-right corner, with its
/// border inside the rectangle.
pub fn inset_rect(canvas: Vec2) -> Rect {
    let shorter = canvas.min_element().max(0.0);
    let room = (shorter - 2.0 * INSET_MARGIN_PX).max(0.0);
    let side = (INSET_FRACTION * shorter).max(INSET_MIN_PX).min(room);
    Rect {
        min: canvas - Vec2::splat(INSET_MARGIN_PX + side),
        size: Vec2::splat(side),
    }
}

/// Where the inset's title goes: the top-left corner of its box, just inside the inset.
pub fn title_top_left(canvas: Vec2) -> Vec2 {
    inset_rect(canvas).min + Vec2::new(6.0, 4.0)
}

/// The inset's camera: view and orthographic projection (depth in [0, 1], as wgpu's) that fit
/// the box into a square viewport looking along the inset's direction, and the eye (for the
/// lighting and for what is drawn on top). `None` when the box is not finite or is empty.
pub fn inset_camera(inset: &Inset) -> Option<(Mat4, Mat4, Vec3)> {
    let (lo, hi) = (inset.min.min(inset.max), inset.min.max(inset.max));
    if !lo.is_finite() || !hi.is_finite() {
        return None;
    }
    let centre = 0.5 * (lo + hi);
    let radius = 0.5 * (hi - lo).length();
    if radius <= 1e-6 {
        return None;
    }
    let (towards_eye, up) = inset.view.axes();
    let eye = centre + towards_eye * (2.0 * radius + 1.0);
    let view = glam::camera::rh::view::look_at_mat4(eye, centre, up);
    let corners = super::box_corners(lo, hi).map(|c| view.transform_point3(c));
    let (mut a, mut b) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for c in corners {
        a = a.min(c);
        b = b.max(c);
    }
    // A square viewport: the larger extent sets the scale, the smaller one is centred.
    let half = 0.5 * (b.x - a.x).max(b.y - a.y) * (1.0 + 2.0 * INSET_PAD);
    let mid = 0.5 * (a + b);
    // View space looks down −z: the box lies between −b.z and −a.z in front of the eye.
    let depth_pad = 0.05 * radius + 0.01;
    let near = (-b.z - depth_pad).max(1e-3);
    let far = -a.z + depth_pad;
    let proj = glam::camera::rh::proj::directx::orthographic(
        mid.x - half,
        mid.x + half,
        mid.y - half,
        mid.y + half,
        near,
        far,
    );
    Some((view, proj, eye))
}
