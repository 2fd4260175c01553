//! Native tests that a figure's labels, placed by the shell's layout (src/draw/layout.rs) on the
//! canvas the page gives the figure at 800 × 600 and 1600 × 1000, keep off the dots (markers) and
//! wide lines (strokes) of the figure, so that no label hides what it names. Text is measured as
//! the page sets it (bold, 0.8 rem): about 7.5 px a character and 16 px tall.
#![cfg(not(target_arch = "wasm32"))]

use glam::{Vec2, Vec3};
use inbetween::camera::{project_to_canvas, OrbitCamera, FIT_PAD_PX};
use inbetween::draw::inset::{fit_beside, inset_rect};
use inbetween::draw::layout::{place_avoiding, LabelBox, Placement, Rect};
use inbetween::draw::{project_labels, Frame, ScreenLabel};

/// [`drawn_for_view`] for a figure whose `draw(&mut Frame)` draws it and whose
/// `set_view(camera, width_px, height_px)` tells it the page's view, as most figures do.
macro_rules! drawn {
    ($scene:expr, $view:expr, $size:expr) => {
        crate::label_clearance::drawn_for_view(
            $scene,
            $view,
            $size,
            |fig, out| {
                fig.draw(out);
            },
            |fig, cam, px| fig.set_view(cam, px.x, px.y),
        )
    };
}

mod lesson_00;
mod lesson_01;
mod lesson_02;
mod lesson_02b;
mod lesson_03;
mod lesson_04;
mod lesson_05;
mod lesson_06;
mod lesson_07;
mod lesson_09;
mod lesson_10;
mod lesson_11;
mod lesson_12;
mod lesson_13;
mod lesson_14;
mod lesson_15;

/// The canvases a 3D figure gets at the two page sizes, CSS px, as measured in Chromium: at
/// 800 × 600 under its panel (760 × 420), at 1600 × 1000 beside its 270 px panel (650 × 420).
pub(crate) const CANVASES: [Vec2; 2] = [Vec2::new(760.0, 420.0), Vec2::new(650.0, 420.0)];

/// Lesson 02b's canvases (its figures are lower at 800 × 600), as [`CANVASES`].
const CANVASES_02B: [Vec2; 2] = [Vec2::new(760.0, 340.0), Vec2::new(650.0, 420.0)];

/// Every label of the frame as the page lays it out: its projection, its box as measured, and
/// where the layout put it.
fn layout(
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
) -> Vec<(ScreenLabel, LabelBox, Placement)> {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let labels = project_labels(&frame.labels, view_proj, size.x, size.y);
    let boxes: Vec<LabelBox> = labels
        .iter()
        .map(|l| LabelBox {
            anchor: Vec2::new(l.x_px, l.y_px),
            size: Vec2::new(7.5 * l.text.chars().count() as f32, 16.0),
            left: l.left,
            visible: l.visible,
            priority: l.priority,
        })
        .collect();
    // As the page: with an inset, the labels keep off its square.
    let obstacles: Vec<Rect> = frame.inset.iter().map(|_| inset_rect(size)).collect();
    let placed = place_avoiding(&boxes, size, &obstacles);
    labels
        .into_iter()
        .zip(boxes)
        .zip(placed)
        .map(|((l, b), p)| (l, b, p))
        .collect()
}

/// The shown labels' boxes, as the page lays them out.
fn label_boxes(frame: &Frame, camera: &OrbitCamera, size: Vec2) -> Vec<(String, Rect)> {
    layout(frame, camera, size)
        .into_iter()
        .filter(|(_, _, p)| p.shown)
        .map(|(l, b, p)| {
            let rect = Rect {
                min: p.top_left,
                size: b.size,
            };
            (l.text, rect)
        })
        .collect()
}

/// Asserts that no shown label's box covers a marker (its whole dot) or a point of a stroke.
fn assert_clear(name: &str, frame: &Frame, camera: &OrbitCamera, size: Vec2) {
    assert_clear_of(name, frame, camera, size, |_| true);
}

/// [`assert_clear`] for the labels whose text passes `checked`, laid out among all the frame's.
fn assert_clear_of(
    name: &str,
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
    checked: impl Fn(&str) -> bool,
) {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let at = |p: [f32; 3]| project_to_canvas(view_proj, size, Vec3::from(p));
    for (text, rect) in label_boxes(frame, camera, size) {
        if !checked(&text) {
            continue;
        }
        for m in &frame.markers {
            let Some(c) = at(m.center) else { continue };
            let r = 0.5 * m.size_px.abs();
            let grown = Rect {
                min: rect.min - r,
                size: rect.size + 2.0 * r,
            };
            let inside = c.cmpge(grown.min).all() && c.cmple(grown.max()).all();
            assert!(
                !inside,
                "{name} on {size}: label {text:?} at {:?} covers a dot at {c}",
                rect.min
            );
        }
        for s in &frame.strokes {
            let (Some(a), Some(b)) = (at(s.a), at(s.b)) else {
                continue;
            };
            assert!(
                !enters(a, b, rect),
                "{name} on {size}: label {text:?} at {:?} crosses a line from {a} to {b} (colour {:?})",
                rect.min,
                s.color
            );
        }
    }
}

/// Whether the segment `a`–`b` on the canvas passes inside the open box `rect`: every point of
/// it, not samples, so a box between two samples of a long line is still caught.
fn enters(a: Vec2, b: Vec2, rect: Rect) -> bool {
    inbetween::draw::segment_enters(a, b, rect.min, rect.max())
}

/// The camera a page's `setCamera` places, fitted to what the frame declares (as the viewer does:
/// beside the inset when the frame has one).
fn page_camera(view: [f32; 6], frame: &Frame, size: Vec2) -> OrbitCamera {
    let mut camera = OrbitCamera::from_view(view);
    camera.limit_pitch(frame.max_pitch_rad);
    camera.limit_yaw(frame.max_yaw_rad);
    if !frame.keep_in_view.is_empty() {
        let points = frame.fit_points();
        let beside = frame
            .inset
            .as_ref()
            .is_some_and(|inset| fit_beside(&mut camera, inset, &points, size, FIT_PAD_PX));
        if !beside {
            camera.fit(&points, size, FIT_PAD_PX);
        }
    }
    camera
}

/// The frame a figure shows at a page camera, drawn as the page draws it: a first frame fixes the
/// fitted camera, the figure is told that view (it places its labels for the view of the frame
/// before), and the second frame is the one checked; returns it with its fitted camera.
pub(crate) fn drawn_for_view<S>(
    scene: &mut S,
    view: [f32; 6],
    size: Vec2,
    mut draw: impl FnMut(&mut S, &mut Frame),
    mut set_view: impl FnMut(&mut S, OrbitCamera, Vec2),
) -> (Frame, OrbitCamera) {
    let mut frame = Frame::default();
    draw(scene, &mut frame);
    set_view(scene, page_camera(view, &frame, size), size);
    let mut frame = Frame::default();
    draw(scene, &mut frame);
    let camera = page_camera(view, &frame, size);
    (frame, camera)
}

/// Asserts that no box of `boxes` whose text is one of `names` covers any of `points` (canvas
/// px): a name would hide `what` the points sample.
fn assert_names_cover_none(
    at: &str,
    size: Vec2,
    boxes: &[(String, Rect)],
    names: &[&str],
    points: &[Vec2],
    what: &str,
) {
    for (text, rect) in boxes.iter().filter(|(t, _)| names.contains(&t.as_str())) {
        for c in points {
            assert!(
                !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                "{at} on {size}: {text:?} at {:?} covers {what} at {c}",
                rect.min
            );
        }
    }
}

/// Runs one case's checks and returns its assertion's message, if it failed: a sweep keeps going
/// and reports how many cases fail, with a few of them.
fn failure_of(check: impl FnOnce() + std::panic::UnwindSafe) -> Option<String> {
    std::panic::catch_unwind(check)
        .err()
        .map(|e| e.downcast_ref::<String>().cloned().unwrap_or_default())
}

/// Fails with the number of failed cases and the first twelve messages.
fn assert_none_failed(failures: &[String]) {
    assert!(
        failures.is_empty(),
        "{} failures, e.g.\n{}",
        failures.len(),
        failures[..failures.len().min(12)].join("\n")
    );
}

/// A name just above what it names: its box's bottom from `gap` px above the topmost of
/// `points` (on the canvas) to 2 px into it, and its middle over them.
fn assert_just_above(at: &str, bottom: f32, middle: f32, points: &[Vec2], gap: f32, what: &str) {
    let top = points.iter().map(|c| c.y).fold(f32::MAX, f32::min);
    let (left, right) = points.iter().fold((f32::MAX, f32::MIN), |(lo, hi), c| {
        (lo.min(c.x), hi.max(c.x))
    });
    assert!(
        (top - gap..=top + 2.0).contains(&bottom),
        "{at}'s bottom at {bottom}, the {what}'s top at {top}"
    );
    assert!(
        (left..=right).contains(&middle),
        "{at}'s middle at {middle}, the {what} from {left} to {right}"
    );
}

/// Asserts that the labels of `frame` at `indices` are shown where the figure put them (no
/// leader line) and keep `margin_px` off every marker's dot and every stroke's edge: a label
/// that touches a line reads as part of it.
fn assert_shown_clear_by(
    name: &str,
    frame: &Frame,
    camera: &OrbitCamera,
    size: Vec2,
    indices: &[usize],
    margin_px: f32,
) {
    let view_proj = camera.projection(size.x / size.y) * camera.view();
    let at = |p: [f32; 3]| project_to_canvas(view_proj, size, Vec3::from(p));
    let placed = layout(frame, camera, size);
    for &i in indices {
        let (l, b, p) = &placed[i];
        assert!(
            p.shown && p.leader_to.is_none(),
            "{name} on {size}: {:?} moved",
            l.text
        );
        let grown = |r: f32| Rect {
            min: p.top_left - (r + margin_px),
            size: b.size + 2.0 * (r + margin_px),
        };
        for m in &frame.markers {
            let Some(c) = at(m.center) else { continue };
            let rect = grown(0.5 * m.size_px.abs());
            assert!(
                !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()),
                "{name} on {size}: {:?} at {:?} within {margin_px} px of a dot at {c}",
                l.text,
                p.top_left
            );
        }
        for s in &frame.strokes {
            let (Some(a), Some(e)) = (at(s.a), at(s.b)) else {
                continue;
            };
            assert!(
                !enters(a, e, grown(0.5 * s.width_px)),
                "{name} on {size}: {:?} at {:?} within {margin_px} px of a line from {a} to {e} \
                 (colour {:?})",
                l.text,
                p.top_left,
                s.color
            );
        }
    }
}
