//! The draw list: what a figure shows in one frame, as plain data.
//!
//! A lesson's scene (in [`crate::figures`]) fills a [`Frame`] with meshes placed by model
//! matrices, world-space lines, point sprites, arrows and text labels; the wgpu renderer
//! (`render/`, wasm only) draws it and the page places the labels. Because the list is plain Rust,
//! native tests can check what a figure draws ("the path passes through every key") without a GPU.
//!
//! Colours are linear RGB in `[0, 1]`; the named colours of the course are in [`palette`], and
//! `www/palette.css` gives the same colours to the words of the text.

pub use crate::texture::{SpriteInstance, TextureId, TexturedQuad, UvRect};

pub mod inset;
pub mod layout;
use glam::{Mat4, Quat, Vec3, Vec4};

/// A mesh known to a renderer. The first three are created by every renderer, in this order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshId(pub usize);

impl MeshId {
    /// A cube with half-extent 1 (so 2 m on a side) centred at the origin.
    pub const CUBE: MeshId = MeshId(0);
    /// A sphere of radius 1 centred at the origin.
    pub const SPHERE: MeshId = MeshId(1);
    /// A cone of radius 1 and height 1: base on y = 0, tip at (0, 1, 0). Arrow heads use it.
    pub const CONE: MeshId = MeshId(2);
}

/// One mesh to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshDraw {
    pub mesh: MeshId,
    /// Model matrix: mesh space to world space.
    pub model: Mat4,
    /// Linear RGBA; ignored when `vertex_colors` is set.
    pub color: Vec4,
    /// Use the colours stored in the mesh's vertices.
    pub vertex_colors: bool,
    /// Show the colour as it is, without the renderer's lighting (colours already shaded on the
    /// CPU, as lesson 00's shading figure does).
    pub unlit: bool,
}

/// One end of a line segment, laid out as the GPU reads it.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineVertex {
    /// World space.
    pub position: [f32; 3],
    /// Pulls the line towards the camera by this much normalised depth, so that an axis drawn
    /// over a grid line at the same place wins instead of flickering (0 for ordinary lines,
    /// [`ON_TOP`] for a line drawn over everything). Never past the near plane.
    pub depth_bias: f32,
    /// Linear RGBA.
    pub color: [f32; 4],
}

/// A camera-facing disc, laid out as the GPU reads it.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointInstance {
    /// World space.
    pub center: [f32; 3],
    /// World units; negative: the disc is drawn over everything ([`Frame::point_on_top`]).
    pub radius: f32,
    /// Linear RGBA.
    pub color: [f32; 4],
}

/// One segment of a wide line, laid out as the GPU reads it: the vertex shader turns it into a
/// screen-space quad `width_px` CSS pixels wide with round ends, so consecutive segments of a
/// polyline join without gaps at any angle (see [`Frame::stroke`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrokeSegment {
    /// World space.
    pub a: [f32; 3],
    /// Width in CSS pixels, in [`MIN_WIDTH_PX`, `MAX_WIDTH_PX`].
    pub width_px: f32,
    /// World space.
    pub b: [f32; 3],
    /// As [`LineVertex::depth_bias`].
    pub depth_bias: f32,
    /// Linear RGBA.
    pub color: [f32; 4],
    /// Dashes: distance along the whole line at `a` and at `b`, dash length, gap length, all in
    /// metres (world units). A gap of 0 is a solid line.
    pub dash: [f32; 4],
}

/// A marker drawn at a fixed size on screen (it stays visible however far the camera zooms out),
/// with a white-and-dark outline that shows on light and dark backgrounds alike. Laid out as the
/// GPU reads it.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MarkerInstance {
    /// World space.
    pub center: [f32; 3],
    /// Diameter (a dot) or length across the path (a tick), in CSS pixels, outline included;
    /// negative: drawn over everything.
    pub size_px: f32,
    /// Linear RGBA.
    pub color: [f32; 4],
    /// A tick's path direction here (world space); unused by dots.
    pub tangent: [f32; 3],
    /// [`MARKER_DOT`] or [`MARKER_TICK`].
    pub shape: f32,
}

/// [`MarkerInstance::shape`]: a filled disc.
pub const MARKER_DOT: f32 = 0.0;
/// [`MarkerInstance::shape`]: a short bar across a path (equal-time ticks).
pub const MARKER_TICK: f32 = 1.0;
/// [`MarkerInstance::shape`]: a soft dark disc lying on the ground (y = 0) under an object, its
/// radius in metres in `size_px` and its darkness in the colour's alpha ([`Frame::contact_shadow`]).
pub const MARKER_SHADOW: f32 = 2.0;
/// Height of a contact shadow above the ground: over the grid's lines, under anything standing.
pub const SHADOW_LIFT_M: f32 = 0.002;
/// The narrowest and widest stroke, in CSS pixels.
pub const MIN_WIDTH_PX: f32 = 1.0;
pub const MAX_WIDTH_PX: f32 = 6.0;
/// The smallest and largest marker, in CSS pixels.
pub const MIN_MARKER_PX: f32 = 4.0;
pub const MAX_MARKER_PX: f32 = 32.0;
/// Default widths: a curve or path, a bone or arrow shaft, a dot, a tick.
pub const CURVE_PX: f32 = 2.5;
pub const ARROW_PX: f32 = 2.5;
/// The axes of a frame ([`Frame::axes`]): a little thinner than a bone, so a joint's axes do not
/// hide its bones.
pub const AXIS_PX: f32 = 2.0;
pub const DOT_PX: f32 = 10.0;
pub const TICK_PX: f32 = 10.0;

/// How a wide line looks ([`Frame::stroke`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrokeStyle {
    /// CSS pixels; clamped to [`MIN_WIDTH_PX`, `MAX_WIDTH_PX`] (NaN draws 1 px).
    pub width_px: f32,
    /// Dash and gap lengths in metres along the line; `None`: solid.
    pub dash_m: Option<(f32, f32)>,
    /// Drawn over everything (bones inside a body), as [`Frame::line_on_top`].
    pub on_top: bool,
}

impl StrokeStyle {
    /// A solid line `width_px` CSS pixels wide.
    pub fn solid(width_px: f32) -> Self {
        Self {
            width_px,
            dash_m: None,
            on_top: false,
        }
    }

    /// A dashed line: `dash_m` metres drawn, `gap_m` metres left out, in turn.
    pub fn dashed(width_px: f32, dash_m: f32, gap_m: f32) -> Self {
        Self {
            width_px,
            dash_m: Some((dash_m, gap_m)),
            on_top: false,
        }
    }
}

/// A text label anchored at a 3D point; the page draws it as HTML over the canvas.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// World space.
    pub anchor: Vec3,
    pub text: String,
    /// Linear RGB.
    pub color: Vec3,
    /// The text ends at the anchor instead of starting there ([`Frame::label_left`]).
    pub left: bool,
    /// Where labels crowd, a higher priority keeps its place and a lower one moves or hides
    /// (see [`layout`]); equal priorities go in the order they were added.
    pub priority: i32,
    /// CSS pixels from the anchor's projection to where the label is placed (x right, y down):
    /// keeps a label a fixed distance on screen from the dot it names whatever the camera's
    /// distance, where an offset in metres would shrink onto the dot ([`Frame::label_off_dot`]).
    pub offset_px: glam::Vec2,
    /// Drawn [`LARGE_LABEL_SCALE`] times the usual size ([`Frame::label_large`]): for a short
    /// name with subscripts (K₁p), whose subscript digits are too small to read at 0.8 rem.
    pub large: bool,
}

/// The box the page gives a label's text (bold, 0.8 rem), CSS pixels: about 7.5 px a character
/// and 16 px tall.
pub fn label_size_px(text: &str) -> glam::Vec2 {
    glam::Vec2::new(7.5 * text.chars().count() as f32, 16.0)
}

/// How much bigger a large label's text is than a plain one's (1.05 rem against 0.8 rem, in
/// `www/style.css`).
pub const LARGE_LABEL_SCALE: f32 = 1.3125;

impl Label {
    /// The box the page gives this label's text, CSS pixels ([`label_size_px`], scaled for a
    /// large label).
    pub fn size_px(&self) -> glam::Vec2 {
        let size = label_size_px(&self.text);
        if self.large {
            LARGE_LABEL_SCALE * size
        } else {
            size
        }
    }
}

/// The gap between a dot and a label placed off it ([`Frame::label_off_dot`]), CSS pixels.
pub const LABEL_DOT_GAP_PX: f32 = 4.0;

/// The space [`Frame::label_is_clear`] keeps between a label and the others, CSS pixels: more
/// than the layout's least ([`layout::PAD_PX`]), so that two labels placed near each other read
/// as two, not as one label of two lines.
pub const LABELS_APART_PX: f32 = 6.0;

/// Depth bias of axes and arrows (see [`LineVertex::depth_bias`]).
pub const OVERLAY_BIAS: f32 = 2e-5;
/// Depth bias of a line drawn over everything ([`Frame::line_on_top`]).
pub const ON_TOP: f32 = 1.0;

/// What to draw this frame. Scenes fill it; the renderer draws it and then calls [`Frame::clear`].
#[derive(Clone, Debug, Default)]
pub struct Frame {
    pub meshes: Vec<MeshDraw>,
    /// Two vertices per segment.
    pub lines: Vec<LineVertex>,
    pub points: Vec<PointInstance>,
    pub labels: Vec<Label>,
    /// Meshes skinned on the GPU (see [`SkinnedDraw`]).
    pub skinned: Vec<SkinnedDraw>,
    /// Their joints' skinning transforms, three `Vec4` per joint (see [`SkinnedDraw::joints`]).
    pub skin_palette: Vec<[Vec4; 3]>,
    /// Textured squares (unlit), drawn after the meshes (see [`crate::texture`]).
    pub quads: Vec<TexturedQuad>,
    /// Camera-facing textured squares, all showing parts of `sprite_texture`, alpha-blended last
    /// in this order (list them back to front).
    pub sprites: Vec<SpriteInstance>,
    pub sprite_texture: Option<TextureId>,
    /// Wide lines, one instance per segment (see [`StrokeSegment`]).
    pub strokes: Vec<StrokeSegment>,
    /// Dots and ticks of a fixed size on screen (see [`MarkerInstance`]).
    pub markers: Vec<MarkerInstance>,
    /// Points that must stay in view: the viewer fits its camera to them (with the label
    /// anchors) at any canvas size, keeping the reader's orbit. Empty: the figure places its
    /// camera itself.
    pub keep_in_view: Vec<Vec3>,
    /// A second, small view of this frame from above or the side ([`inset::Inset`]).
    pub inset: Option<inset::Inset>,
    /// A flat figure (a graph facing the camera): a drag slides it instead of orbiting round it,
    /// which would squeeze it into a line ([`crate::camera::OrbitCamera::drag`]).
    pub flat: bool,
    /// The highest the camera may look down from, radians above the horizon: a figure whose
    /// subject reads only from the side (an antenna's sideways lag) keeps the orbit below it
    /// ([`crate::camera::OrbitCamera::limit_pitch`]). `None`: up to the pole.
    pub max_pitch_rad: Option<f32>,
    /// The farthest the camera may turn from the front (yaw 0), radians either way: a figure
    /// drawn in one plane (a 2D simulation's tanks) turned edge-on shows slivers
    /// ([`crate::camera::OrbitCamera::limit_yaw`]). `None`: all the way round.
    pub max_yaw_rad: Option<f32>,
}

/// A mesh made with the renderer's GPU-skinning path (`Renderer::skin`), by creation order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SkinMeshId(pub usize);

/// One mesh skinned in the vertex shader: its bind-pose vertices, joints and weights live on the
/// GPU; the frame carries only the palette (built by `crate::figures::gpu`).
#[derive(Clone, Debug, PartialEq)]
pub struct SkinnedDraw {
    pub mesh: SkinMeshId,
    pub model: Mat4,
    /// Linear RGBA; ignored when `vertex_colors` is set.
    pub color: Vec4,
    pub vertex_colors: bool,
    /// Dual quaternion skinning (palette rows: real part, dual part, unused) instead of linear
    /// blend skinning (palette rows: the three rows of `K_j`'s 3 × 4 matrix).
    pub dqs: bool,
    /// The range of [`Frame::skin_palette`] that holds this mesh's joints.
    pub joints: std::ops::Range<usize>,
}

impl Frame {
    /// Draws `mesh` transformed by `model`, lit, in a uniform colour.
    #[inline(never)]
    pub fn mesh(&mut self, mesh: MeshId, model: Mat4, color: Vec3) {
        self.meshes.push(MeshDraw {
            mesh,
            model,
            color: color.extend(1.0),
            vertex_colors: false,
            unlit: false,
        });
    }

    /// Draws `mesh` lit, with the colours stored in its vertices.
    #[inline(never)]
    pub fn mesh_vertex_colors(&mut self, mesh: MeshId, model: Mat4) {
        self.meshes.push(MeshDraw {
            mesh,
            model,
            color: Vec4::ONE,
            vertex_colors: true,
            unlit: false,
        });
    }

    /// Draws `mesh` with the colours stored in its vertices, unlit: the colours are the final
    /// (linear RGB) colours, already shaded by the caller.
    #[inline(never)]
    pub fn mesh_unlit_vertex_colors(&mut self, mesh: MeshId, model: Mat4) {
        self.meshes.push(MeshDraw {
            mesh,
            model,
            color: Vec4::ONE,
            vertex_colors: true,
            unlit: true,
        });
    }

    /// A line segment from `a` to `b`.
    #[inline(never)]
    pub fn line(&mut self, a: Vec3, b: Vec3, color: Vec3) {
        self.biased_line(a, b, color, 0.0);
    }

    #[inline(never)]
    fn biased_line(&mut self, a: Vec3, b: Vec3, color: Vec3, depth_bias: f32) {
        let color = color.extend(1.0).to_array();
        for p in [a, b] {
            self.lines.push(LineVertex {
                position: p.to_array(),
                depth_bias,
                color,
            });
        }
    }

    /// Consecutive points joined by segments (a curve, a trajectory).
    #[inline(never)]
    pub fn polyline(&mut self, points: &[Vec3], color: Vec3) {
        for pair in points.windows(2) {
            self.line(pair[0], pair[1], color);
        }
    }

    /// A shaded disc of `radius` (world units) always facing the camera.
    #[inline(never)]
    pub fn point(&mut self, center: Vec3, radius: f32, color: Vec3) {
        self.points.push(PointInstance {
            center: center.to_array(),
            radius: radius.abs(),
            color: color.extend(1.0).to_array(),
        });
    }

    /// A [`Frame::point`] drawn over everything, seen through any surface in front of it (the
    /// joints of a skeleton inside a body).
    #[inline(never)]
    pub fn point_on_top(&mut self, center: Vec3, radius: f32, color: Vec3) {
        self.points.push(PointInstance {
            center: center.to_array(),
            radius: -radius.abs(),
            color: color.extend(1.0).to_array(),
        });
    }

    /// A wide line through `points` in `style`: one [`StrokeSegment`] per consecutive pair, with
    /// the distance along the line carried from segment to segment so dashes run on across the
    /// joins. Segments with a non-finite end are left out (the line breaks there).
    #[inline(never)]
    pub fn stroke(&mut self, points: &[Vec3], color: Vec3, style: StrokeStyle) {
        let width_px = if style.width_px.is_nan() {
            MIN_WIDTH_PX
        } else {
            style.width_px.clamp(MIN_WIDTH_PX, MAX_WIDTH_PX)
        };
        let (dash, gap) = match style.dash_m {
            Some((d, g)) if d.is_finite() && g.is_finite() && d > 0.0 && g > 0.0 => (d, g),
            _ => (1.0, 0.0),
        };
        let depth_bias = if style.on_top { ON_TOP } else { OVERLAY_BIAS };
        let color = color.extend(1.0).to_array();
        let mut along = 0.0;
        for pair in points.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            if !a.is_finite() || !b.is_finite() {
                continue;
            }
            let next = along + a.distance(b);
            self.strokes.push(StrokeSegment {
                a: a.to_array(),
                width_px,
                b: b.to_array(),
                depth_bias,
                color,
                dash: [along, next, dash, gap],
            });
            along = next;
        }
    }

    /// A solid wide line from `a` to `b`, `width_px` CSS pixels wide.
    #[inline(never)]
    pub fn wide_line(&mut self, a: Vec3, b: Vec3, color: Vec3, width_px: f32) {
        self.stroke(&[a, b], color, StrokeStyle::solid(width_px));
    }

    /// A solid wide line through `points` (a curve, a path, a trajectory).
    #[inline(never)]
    pub fn wide_polyline(&mut self, points: &[Vec3], color: Vec3, width_px: f32) {
        self.stroke(points, color, StrokeStyle::solid(width_px));
    }

    /// A [`Frame::wide_line`] drawn over everything (a bone inside a body).
    #[inline(never)]
    pub fn wide_line_on_top(&mut self, a: Vec3, b: Vec3, color: Vec3, width_px: f32) {
        let style = StrokeStyle {
            on_top: true,
            ..StrokeStyle::solid(width_px)
        };
        self.stroke(&[a, b], color, style);
    }

    /// A dot `size_px` CSS pixels across at `center`, outlined, the same size at any distance.
    #[inline(never)]
    pub fn marker(&mut self, center: Vec3, size_px: f32, color: Vec3) {
        self.push_marker(center, size_px, color, Vec3::ZERO, MARKER_DOT, false);
    }

    /// A [`Frame::marker`] drawn over everything (a joint inside a body).
    #[inline(never)]
    pub fn marker_on_top(&mut self, center: Vec3, size_px: f32, color: Vec3) {
        self.push_marker(center, size_px, color, Vec3::ZERO, MARKER_DOT, true);
    }

    /// Equal-time ticks: `samples` are the positions of something at equal time steps; each gets
    /// a short bar across the path (`size_px` long on screen), so close ticks read as slow and
    /// spread ones as fast. The path's direction at a tick comes from its neighbours.
    #[inline(never)]
    pub fn ticks(&mut self, samples: &[Vec3], size_px: f32, color: Vec3) {
        let n = samples.len();
        for (i, p) in samples.iter().enumerate() {
            let before = samples[i.saturating_sub(1)];
            let after = samples[(i + 1).min(n - 1)];
            let tangent = (after - before).try_normalize().unwrap_or(Vec3::ZERO);
            self.push_marker(*p, size_px, color, tangent, MARKER_TICK, false);
        }
    }

    fn push_marker(
        &mut self,
        center: Vec3,
        size_px: f32,
        color: Vec3,
        tangent: Vec3,
        shape: f32,
        on_top: bool,
    ) {
        if !center.is_finite() {
            return;
        }
        let size = if size_px.is_nan() {
            DOT_PX
        } else {
            size_px.clamp(MIN_MARKER_PX, MAX_MARKER_PX)
        };
        self.markers.push(MarkerInstance {
            center: center.to_array(),
            size_px: if on_top { -size } else { size },
            color: color.extend(1.0).to_array(),
            tangent: tangent.to_array(),
            shape,
        });
    }

    /// A soft contact shadow on the ground (y = 0) under an object of about `radius` metres whose
    /// lowest point is at `bottom`: darkest (alpha 0.45) and as wide as the object when it
    /// touches the ground, wider (by 0.35 of the height) and fainter as it rises, gone at
    /// [`Frame::shadow_reach`] metres up. It lets a reader judge from one view how high
    /// something is and whether it touches the ground. Nothing is drawn for a non-finite or
    /// non-positive radius or for an object below the ground.
    #[inline(never)]
    pub fn contact_shadow(&mut self, bottom: Vec3, radius: f32) {
        if !bottom.is_finite() || !radius.is_finite() || radius <= 0.0 || bottom.y < -1e-3 {
            return;
        }
        let height = bottom.y.max(0.0);
        let darkness = 0.45 * (1.0 - height / Self::shadow_reach(radius));
        if darkness <= 0.0 {
            return;
        }
        self.markers.push(MarkerInstance {
            center: [bottom.x, SHADOW_LIFT_M, bottom.z],
            size_px: radius + 0.35 * height,
            color: [0.0, 0.0, 0.0, darkness],
            tangent: [0.0; 3],
            shape: MARKER_SHADOW,
        });
    }

    /// The height (metres) at which an object of `radius` metres no longer casts a
    /// [`Frame::contact_shadow`]: four radii, and at least 1.5 m so small balls keep theirs
    /// through a bounce.
    pub fn shadow_reach(radius: f32) -> f32 {
        (4.0 * radius).max(1.5)
    }

    /// The points the viewer fits its camera to: the declared ones ([`Frame::keep_in_view`]) and
    /// every label's anchor.
    pub fn fit_points(&self) -> Vec<Vec3> {
        self.keep_in_view
            .iter()
            .copied()
            .chain(self.labels.iter().map(|l| l.anchor))
            .collect()
    }

    /// Declares that the box from `min` to `max` must stay in view (see [`Frame::keep_in_view`]):
    /// its eight corners join the points the camera fits.
    #[inline(never)]
    pub fn keep_box_in_view(&mut self, min: Vec3, max: Vec3) {
        let finite = box_corners(min, max).into_iter().filter(|c| c.is_finite());
        self.keep_in_view.extend(finite);
    }

    /// A [`Frame::line`] drawn over everything (the bones of a skeleton inside a body).
    #[inline(never)]
    pub fn line_on_top(&mut self, a: Vec3, b: Vec3, color: Vec3) {
        self.biased_line(a, b, color, ON_TOP);
    }

    /// An arrow from `from` to `to`: a shaft line and a cone head whose length is `head` world
    /// units (shortened for short arrows so the head never overshoots the tail). A zero-length
    /// arrow draws nothing.
    #[inline(never)]
    pub fn arrow(&mut self, from: Vec3, to: Vec3, color: Vec3, head: f32) {
        self.arrow_with(from, to, color, head, false);
    }

    /// A [`Frame::arrow`] whose shaft, and three strokes from its tip along its cone, are drawn
    /// over everything: an offset that starts inside a surface (a vertex's move under the skin
    /// it moved) still shows its whole length and its direction.
    #[inline(never)]
    pub fn arrow_on_top(&mut self, from: Vec3, to: Vec3, color: Vec3, head: f32) {
        self.arrow_with(from, to, color, head, true);
    }

    fn arrow_with(&mut self, from: Vec3, to: Vec3, color: Vec3, head: f32, on_top: bool) {
        let v = to - from;
        let length = v.length();
        if length.is_nan() || length <= 1e-6 || length.is_infinite() {
            return;
        }
        let dir = v / length;
        let head = head.min(0.4 * length).max(0.0);
        let base = to - dir * head;
        let style = StrokeStyle {
            on_top,
            ..StrokeStyle::solid(ARROW_PX)
        };
        self.stroke(&[from, base], color, style);
        if on_top {
            // Three, a third of a turn apart, so at least two open a V from any side.
            let (a, b) = dir.any_orthonormal_pair();
            for k in 0..3 {
                let (sin, cos) = (k as f32 * std::f32::consts::TAU / 3.0).sin_cos();
                let rim = base + 0.35 * head * (a * cos + b * sin);
                self.stroke(&[rim, to], color, style);
            }
        }
        let model = Mat4::from_scale_rotation_translation(
            Vec3::new(head * 0.35, head, head * 0.35),
            Quat::from_rotation_arc(Vec3::Y, dir),
            base,
        );
        self.mesh(MeshId::CONE, model, color);
    }

    /// A text label at `anchor` (world space), drawn over the canvas by the page.
    #[inline(never)]
    pub fn label(&mut self, anchor: Vec3, text: impl Into<String>, color: Vec3) {
        self.labels.push(Label {
            anchor,
            text: text.into(),
            color,
            left: false,
            priority: 0,
            offset_px: glam::Vec2::ZERO,
            large: false,
        });
    }

    /// Whether `label` (not yet added), in the box the page's layout first tries for it
    /// ([`layout::preferred`] at its anchor's projection plus its offset, moved inside the
    /// canvas) on a `size` canvas (CSS pixels) seen through `view_proj`, stays clear of the
    /// frame's markers (their whole dot), its strokes (every point of each segment), the first
    /// places of the labels the layout places before it (those of at least its priority, by
    /// [`LABELS_APART_PX`]; a lower one moves out of its way) and the frame's inset. The box is
    /// measured as [`Label::size_px`] does. For figures that choose among places for a label
    /// near crowded lines; an anchor behind the camera is not clear.
    pub fn label_is_clear(&self, view_proj: Mat4, size: glam::Vec2, label: &Label) -> bool {
        self.label_is_clear_by(view_proj, size, label, 0.0)
    }

    /// [`Frame::label_is_clear`] with `margin_px` more between the label's box and the frame's
    /// markers and strokes: for a label that must not touch the lines it sits among.
    pub fn label_is_clear_by(
        &self,
        view_proj: Mat4,
        size: glam::Vec2,
        label: &Label,
        margin_px: f32,
    ) -> bool {
        let priority = label.priority;
        use crate::camera::project_to_canvas;
        let place = |l: &Label| l.first_place(view_proj, size);
        let Some(rect) = place(label) else {
            return false;
        };
        let at = |p: [f32; 3]| project_to_canvas(view_proj, size, Vec3::from(p));
        let markers_clear = self.markers.iter().all(|m| {
            at(m.center).is_none_or(|c| {
                let r = 0.5 * m.size_px.abs() + margin_px;
                !(c.cmpge(rect.min - r).all() && c.cmple(rect.max() + r).all())
            })
        });
        let strokes_clear = || {
            self.strokes.iter().all(|s| {
                let (Some(a), Some(b)) = (at(s.a), at(s.b)) else {
                    return true;
                };
                let r = 0.5 * s.width_px + margin_px;
                !segment_enters(a, b, rect.min - r, rect.max() + r)
            })
        };
        let labels_clear = || {
            self.labels
                .iter()
                .filter(|l| l.priority >= priority)
                .all(|l| place(l).is_none_or(|other| !other.overlaps(&rect, LABELS_APART_PX)))
        };
        // The page's layout keeps labels off the inset's square (and its title).
        let inset_clear = self
            .inset
            .as_ref()
            .is_none_or(|_| !inset::inset_rect(size).overlaps(&rect, layout::PAD_PX));
        inset_clear && markers_clear && strokes_clear() && labels_clear()
    }

    /// A [`Frame::label`] with a `priority`: where labels crowd, the higher one keeps its place.
    #[inline(never)]
    pub fn label_with_priority(
        &mut self,
        anchor: Vec3,
        text: impl Into<String>,
        color: Vec3,
        priority: i32,
    ) {
        self.label(anchor, text, color);
        if let Some(last) = self.labels.last_mut() {
            last.priority = priority;
        }
    }

    /// A [`Frame::label_with_priority`] whose text is [`LARGE_LABEL_SCALE`] times the usual
    /// size: for a short name with subscripts (K₁p) that must read at 800 × 600.
    #[inline(never)]
    pub fn label_large(
        &mut self,
        anchor: Vec3,
        text: impl Into<String>,
        color: Vec3,
        priority: i32,
    ) {
        self.label_with_priority(anchor, text, color, priority);
        if let Some(last) = self.labels.last_mut() {
            last.large = true;
        }
    }

    /// A text label that ends at `anchor` (it reads leftwards from there): for a label that
    /// would otherwise run into something drawn to the anchor's right.
    #[inline(never)]
    pub fn label_left(&mut self, anchor: Vec3, text: impl Into<String>, color: Vec3) {
        self.labels.push(Label {
            anchor,
            text: text.into(),
            color,
            left: true,
            priority: 0,
            offset_px: glam::Vec2::ZERO,
            large: false,
        });
    }

    /// A label beside a dot `dot_px` CSS pixels across at `anchor`, towards `side` on screen (x
    /// right, y down: each component −1, 0 or 1, so eight places round the dot), with a gap of
    /// [`LABEL_DOT_GAP_PX`] between the dot's edge and the label's box at any camera distance,
    /// where an offset in metres would shrink onto the dot as the camera backs away. A label to
    /// the left reads leftwards; one straight above or below is centred on the dot (its width
    /// from [`label_size_px`]).
    #[inline(never)]
    pub fn label_off_dot(
        &mut self,
        anchor: Vec3,
        dot_px: f32,
        side: glam::Vec2,
        text: impl Into<String>,
        color: Vec3,
        priority: i32,
    ) {
        let label = Label::off_dot(anchor, dot_px, side, text.into(), color, priority);
        self.labels.push(label);
    }

    /// Adds the first of `candidates` that [`Frame::label_is_clear`] finds clear on a canvas of
    /// `view`'s size (CSS pixels) seen through its matrix, else the first: for a label that has
    /// several good places (the sides of a dot, [`Label::off_dot`]) and must keep off lines that
    /// move. Without a view (the figure not drawn yet) or candidates, adds the first or nothing.
    pub fn first_clear_label(
        &mut self,
        view: Option<(Mat4, glam::Vec2)>,
        candidates: impl IntoIterator<Item = Label>,
    ) {
        self.first_clear_label_by(view, 0.0, candidates, |_| true);
    }

    /// [`Frame::first_clear_label`] with `margin_px` kept from the markers and strokes
    /// ([`Frame::label_is_clear_by`]) and a further test `also_clear` of each candidate's box
    /// (its first place on the canvas, [`Label::first_place`]): for a figure that knows of
    /// things under the label that the frame does not list (a mesh).
    pub fn first_clear_label_by(
        &mut self,
        view: Option<(Mat4, glam::Vec2)>,
        margin_px: f32,
        candidates: impl IntoIterator<Item = Label>,
        also_clear: impl Fn(layout::Rect) -> bool,
    ) {
        // One compiled body serves every figure's candidates and test (the wasm's size: each
        // caller's iterator and closure types would otherwise copy the whole search).
        self.first_clear_label_dyn(
            view,
            margin_px,
            candidates.into_iter().collect(),
            &also_clear,
        );
    }

    #[inline(never)]
    fn first_clear_label_dyn(
        &mut self,
        view: Option<(Mat4, glam::Vec2)>,
        margin_px: f32,
        candidates: Vec<Label>,
        also_clear: &dyn Fn(layout::Rect) -> bool,
    ) {
        let mut candidates = candidates.into_iter();
        let Some(first) = candidates.next() else {
            return;
        };
        let chosen = view
            .and_then(|(view_proj, size)| {
                std::iter::once(first.clone()).chain(candidates).find(|l| {
                    self.label_is_clear_by(view_proj, size, l, margin_px)
                        && l.first_place(view_proj, size).is_some_and(also_clear)
                })
            })
            .unwrap_or(first);
        self.labels.push(chosen);
    }
}

/// Whether the segment `a`–`b` passes inside the open box from `lo` to `hi` (a touch along an
/// edge or at a corner does not count): the segment clipped to each axis's slab in turn
/// (Liang–Barsky), so a box that lies between any two points of a long line still meets it.
/// Public for the label tests, which check placed labels against lines the same way.
#[inline(never)]
pub fn segment_enters(a: glam::Vec2, b: glam::Vec2, lo: glam::Vec2, hi: glam::Vec2) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for i in 0..2 {
        if d[i] == 0.0 {
            if a[i] <= lo[i] || a[i] >= hi[i] {
                return false;
            }
        } else {
            let (u, v) = ((lo[i] - a[i]) / d[i], (hi[i] - a[i]) / d[i]);
            t0 = t0.max(u.min(v));
            t1 = t1.min(u.max(v));
        }
    }
    t0 < t1
}

impl Label {
    /// The box the page's layout first tries for this label on a `size` canvas (CSS pixels)
    /// seen through `view_proj`: [`layout::preferred`] at its anchor's projection plus its
    /// offset, moved inside the canvas, measured as [`Label::size_px`] does. `None` when the
    /// anchor is behind the camera.
    #[inline(never)]
    pub fn first_place(&self, view_proj: Mat4, size: glam::Vec2) -> Option<layout::Rect> {
        let anchor =
            crate::camera::project_to_canvas(view_proj, size, self.anchor)? + self.offset_px;
        let label = layout::LabelBox {
            anchor,
            size: self.size_px(),
            left: self.left,
            visible: true,
            priority: 0,
        };
        Some(layout::Rect {
            min: layout::inside(layout::preferred(&label), label.size, size),
            size: label.size,
        })
    }

    /// Candidates for [`Frame::first_clear_label`]: [`Label::off_dot`] on the eight sides of a
    /// dot `dot_px` across at `anchor`, the sides that point most along `toward` (a screen
    /// direction, x right, y down) first, at the dot's gap and then `step_px` further out each
    /// time, `steps` places in all per side. A zero `toward` keeps the order right, left, above,
    /// below, then the diagonals.
    pub fn around_dot(
        anchor: Vec3,
        dot_px: f32,
        toward: glam::Vec2,
        text: &str,
        color: Vec3,
        priority: i32,
        steps: usize,
        step_px: f32,
    ) -> Vec<Label> {
        let sides = [
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (0.0, 1.0),
            (1.0, -1.0),
            (-1.0, -1.0),
            (1.0, 1.0),
            (-1.0, 1.0),
        ]
        .map(|(x, y)| glam::Vec2::new(x, y));
        let toward = toward.normalize_or_zero();
        // Most towards `toward` first; a stable sort: equal scores keep the order above.
        let order = crate::order::order_by(sides.iter().map(|s| s.normalize().dot(toward)), true);
        let sides: [glam::Vec2; 8] = std::array::from_fn(|k| sides[order[k]]);
        (0..steps.max(1))
            .flat_map(|k| {
                let out_px = k as f32 * step_px;
                sides.map(|side| {
                    Label::off_dot(
                        anchor,
                        dot_px + 2.0 * out_px,
                        side,
                        text.into(),
                        color,
                        priority,
                    )
                })
            })
            .collect()
    }

    /// The label [`Frame::label_off_dot`] adds: beside a dot `dot_px` CSS pixels across at
    /// `anchor`, towards `side` on screen, [`LABEL_DOT_GAP_PX`] from the dot's edge.
    pub fn off_dot(
        anchor: Vec3,
        dot_px: f32,
        side: glam::Vec2,
        text: String,
        color: Vec3,
        priority: i32,
    ) -> Label {
        let size = label_size_px(&text);
        let mut clear = 0.5 * dot_px.abs() + LABEL_DOT_GAP_PX;
        if side.x != 0.0 && side.y != 0.0 {
            // The box's corner nearest the dot, on the diagonal.
            clear *= std::f32::consts::FRAC_1_SQRT_2;
        }
        // The box's top-left corner relative to the dot's centre.
        let x = match side.x {
            x if x > 0.0 => clear,
            x if x < 0.0 => -clear - size.x,
            _ => -0.5 * size.x,
        };
        let y = match side.y {
            y if y > 0.0 => clear,
            y if y < 0.0 => -clear - size.y,
            _ => -0.5 * size.y,
        };
        // The anchor that puts the layout's first place there (see layout::preferred).
        let left = side.x < 0.0;
        let offset_px = glam::Vec2::new(
            if left {
                x + size.x + layout::GAP_PX
            } else {
                x - layout::GAP_PX
            },
            y + 0.5 * size.y,
        );
        Label {
            anchor,
            text,
            color,
            left,
            priority,
            offset_px,
            large: false,
        }
    }
}

impl Frame {

    /// The x, y and z axes of the frame `m` as wide lines ([`AXIS_PX`]) in the palette's axis
    /// colours, each `length` long, drawn over anything at the same depth (the grid's centre
    /// lines).
    pub fn axes(&mut self, m: Mat4, length: f32) {
        self.axes_with(m, length, false);
    }

    /// [`Frame::axes`] drawn over everything: the axes of a solid box, which would hide them.
    pub fn axes_on_top(&mut self, m: Mat4, length: f32) {
        self.axes_with(m, length, true);
    }

    #[inline(never)]
    fn axes_with(&mut self, m: Mat4, length: f32, on_top: bool) {
        let style = StrokeStyle {
            on_top,
            ..StrokeStyle::solid(AXIS_PX)
        };
        let o = m.transform_point3(Vec3::ZERO);
        for (axis, color) in [
            (Vec3::X, palette::X_AXIS),
            (Vec3::Y, palette::Y_AXIS),
            (Vec3::Z, palette::Z_AXIS),
        ] {
            let tip = o + m.transform_vector3(axis) * length;
            self.stroke(&[o, tip], color, style);
        }
    }

    /// The axes of `m` as arrows with heads and x, y, z labels at their tips.
    pub fn labelled_axes(&mut self, m: Mat4, length: f32) {
        self.labelled_axes_with(m, length, false);
    }

    /// [`Frame::labelled_axes`] whose shafts and heads' strokes are drawn over everything
    /// ([`Frame::arrow_on_top`]): a joint's axes inside the body.
    pub fn labelled_axes_on_top(&mut self, m: Mat4, length: f32) {
        self.labelled_axes_with(m, length, true);
    }

    #[inline(never)]
    fn labelled_axes_with(&mut self, m: Mat4, length: f32, on_top: bool) {
        let o = m.transform_point3(Vec3::ZERO);
        for (axis, color, name) in [
            (Vec3::X, palette::X_AXIS, "x"),
            (Vec3::Y, palette::Y_AXIS, "y"),
            (Vec3::Z, palette::Z_AXIS, "z"),
        ] {
            let tip = o + m.transform_vector3(axis) * length;
            self.arrow_with(o, tip, color, 0.15 * length, on_top);
            self.label(tip, name, color);
        }
    }

    /// A ground grid on y = 0 with `cells` cells of `spacing` metres on a side; the lines through
    /// the origin are darker. The lines fade out towards the grid's rim ([`grid_fade`]), so the
    /// ground recedes instead of ending at a hard edge: a depth cue in a single view.
    #[inline(never)]
    pub fn grid(&mut self, cells: u32, spacing: f32) {
        let half = cells as f32 * spacing * 0.5;
        for [a, b] in crate::mesh::grid_lines(cells, spacing) {
            let on_axis =
                a.x.abs() < 1e-6 && b.x.abs() < 1e-6 || a.z.abs() < 1e-6 && b.z.abs() < 1e-6;
            let color = if on_axis {
                palette::GRID_AXIS
            } else {
                palette::GRID
            };
            // One segment per cell, so the fade follows the distance from the centre.
            let fade = |p: Vec3| grid_fade(p.length() / half.max(1e-6));
            let pieces = cells.max(1);
            for k in 0..pieces {
                let p = a.lerp(b, k as f32 / pieces as f32);
                let q = a.lerp(b, (k + 1) as f32 / pieces as f32);
                for (v, alpha) in [(p, fade(p)), (q, fade(q))] {
                    self.lines.push(LineVertex {
                        position: v.to_array(),
                        depth_bias: 0.0,
                        color: color.extend(alpha).to_array(),
                    });
                }
            }
        }
    }

    /// Empties the list, keeping its capacity (no allocation next frame).
    pub fn clear(&mut self) {
        self.meshes.clear();
        self.lines.clear();
        self.points.clear();
        self.labels.clear();
        self.skinned.clear();
        self.skin_palette.clear();
        self.quads.clear();
        self.sprites.clear();
        self.sprite_texture = None;
        self.strokes.clear();
        self.markers.clear();
        self.keep_in_view.clear();
        self.inset = None;
        self.flat = false;
        self.max_yaw_rad = None;
        self.max_pitch_rad = None;
    }

    /// Runs `draw` on this frame and moves everything it added by `offset`: meshes, GPU-skinned
    /// meshes and textured squares (their models), lines, points, sprites, wide lines, markers,
    /// labels and the points kept in view. A figure draws a copy of its scene in its own
    /// coordinates and places it with this, instead of offsetting every item itself.
    pub fn translated<R>(&mut self, offset: Vec3, draw: impl FnOnce(&mut Frame) -> R) -> R {
        let start = (
            self.meshes.len(),
            self.lines.len(),
            self.points.len(),
            self.labels.len(),
            self.skinned.len(),
            self.quads.len(),
            self.sprites.len(),
            self.strokes.len(),
            self.markers.len(),
            self.keep_in_view.len(),
        );
        let out = draw(self);
        let shift = Mat4::from_translation(offset);
        let moved = |p: &mut [f32; 3]| *p = (Vec3::from(*p) + offset).to_array();
        self.meshes[start.0..]
            .iter_mut()
            .for_each(|m| m.model = shift * m.model);
        self.lines[start.1..]
            .iter_mut()
            .for_each(|v| moved(&mut v.position));
        self.points[start.2..]
            .iter_mut()
            .for_each(|p| moved(&mut p.center));
        self.labels[start.3..]
            .iter_mut()
            .for_each(|l| l.anchor += offset);
        self.skinned[start.4..]
            .iter_mut()
            .for_each(|s| s.model = shift * s.model);
        self.quads[start.5..]
            .iter_mut()
            .for_each(|q| q.model = shift * q.model);
        self.sprites[start.6..]
            .iter_mut()
            .for_each(|s| moved(&mut s.center));
        for s in &mut self.strokes[start.7..] {
            moved(&mut s.a);
            moved(&mut s.b);
        }
        self.markers[start.8..]
            .iter_mut()
            .for_each(|m| moved(&mut m.center));
        self.keep_in_view[start.9..]
            .iter_mut()
            .for_each(|p| *p += offset);
        out
    }

    /// Draws `titles.len()` copies of a scene side by side along `step` (the copies centred on
    /// the origin), each by `draw(frame, k)` in its own coordinates, with its title (text and
    /// colour) over it at height `title_y`; the titles are kept in view and placed before other
    /// labels. The comparisons of the course (two methods on the same input) use it.
    pub fn side_by_side(
        &mut self,
        step: Vec3,
        titles: &[(&str, Vec3)],
        title_y: f32,
        mut draw: impl FnMut(&mut Frame, usize),
    ) {
        let n = titles.len();
        for (k, &(title, color)) in titles.iter().enumerate() {
            let offset = step * (k as f32 - 0.5 * (n as f32 - 1.0));
            self.translated(offset, |f| {
                draw(f, k);
                let anchor = Vec3::new(0.0, title_y, 0.0);
                f.label_with_priority(anchor, title, color, 1);
                f.keep_in_view.push(anchor);
            });
        }
    }

    /// Adds an inset: the box `min`–`max` seen along `view` (orthographic) in a small square in
    /// the canvas's bottom-right corner, titled `title` (see [`inset`]). A later call replaces
    /// an earlier one.
    pub fn inset(
        &mut self,
        view: inset::InsetView,
        title: impl Into<String>,
        min: Vec3,
        max: Vec3,
    ) {
        self.inset = Some(inset::Inset {
            view,
            title: title.into(),
            min,
            max,
            fit_above: false,
            only: None,
        });
    }

    /// Has the camera fit what the frame declares above its inset, across the canvas's whole
    /// width, instead of left of it (see [`inset::fit_beside`]). Call it after [`Frame::inset`].
    pub fn fit_above_inset(&mut self) {
        if let Some(inset) = &mut self.inset {
            inset.fit_above = true;
        }
    }

    /// Draws `uv` of `texture` on the square `[−1, 1]²` of the xz plane placed by `model`.
    #[inline(never)]
    pub fn textured_quad(&mut self, texture: TextureId, model: Mat4, uv: UvRect) {
        self.quads.push(TexturedQuad {
            texture,
            model,
            tint: Vec4::ONE,
            uv,
        });
    }

    /// A fingerprint of everything in the list (FNV-1a over the numbers and texts): two frames
    /// that draw the same thing have the same fingerprint. The page tests use it to see that a
    /// control changed what a figure draws without reading pixels back.
    pub fn fingerprint(&self) -> u64 {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        let mut eat = |bits: u32| {
            for byte in bits.to_le_bytes() {
                h = (h ^ byte as u64).wrapping_mul(0x0100_0000_01b3);
            }
        };
        for m in &self.meshes {
            eat(m.mesh.0 as u32);
            m.model
                .to_cols_array()
                .iter()
                .for_each(|x| eat(x.to_bits()));
            m.color.to_array().iter().for_each(|x| eat(x.to_bits()));
            eat(m.vertex_colors as u32);
            eat(m.unlit as u32);
        }
        for v in &self.lines {
            v.position
                .iter()
                .chain(&v.color)
                .for_each(|x| eat(x.to_bits()));
        }
        for p in &self.points {
            p.center
                .iter()
                .chain(&p.color)
                .for_each(|x| eat(x.to_bits()));
            eat(p.radius.to_bits());
        }
        for q in &self.quads {
            eat(q.texture.0 as u32);
            q.model
                .to_cols_array()
                .iter()
                .for_each(|x| eat(x.to_bits()));
            q.tint
                .to_array()
                .iter()
                .chain(&q.uv.to_array())
                .for_each(|x| eat(x.to_bits()));
        }
        for s in &self.sprites {
            s.center
                .iter()
                .chain(&s.uv)
                .chain(&s.color)
                .for_each(|x| eat(x.to_bits()));
            eat(s.half_size.to_bits());
        }
        eat(self.sprite_texture.map_or(u32::MAX, |t| t.0 as u32));
        for s in &self.strokes {
            s.a.iter()
                .chain(&s.b)
                .chain(&s.color)
                .chain(&s.dash)
                .chain(&[s.width_px, s.depth_bias])
                .for_each(|x| eat(x.to_bits()));
        }
        for m in &self.markers {
            m.center
                .iter()
                .chain(&m.color)
                .chain(&m.tangent)
                .chain(&[m.size_px, m.shape])
                .for_each(|x| eat(x.to_bits()));
        }
        for p in &self.keep_in_view {
            p.to_array().iter().for_each(|x| eat(x.to_bits()));
        }
        for l in &self.labels {
            l.anchor.to_array().iter().for_each(|x| eat(x.to_bits()));
            l.text.bytes().for_each(|b| eat(b as u32));
            eat(l.left as u32);
            eat(l.priority as u32);
            eat(l.offset_px.x.to_bits());
            eat(l.offset_px.y.to_bits());
        }
        for s in &self.skinned {
            eat(s.mesh.0 as u32 | (s.dqs as u32) << 31);
            s.model
                .to_cols_array()
                .iter()
                .for_each(|x| eat(x.to_bits()));
            s.color.to_array().iter().for_each(|x| eat(x.to_bits()));
        }
        for row in self.skin_palette.iter().flatten() {
            row.to_array().iter().for_each(|x| eat(x.to_bits()));
        }
        if let Some(inset) = &self.inset {
            eat(inset.view as u32);
            inset
                .min
                .to_array()
                .iter()
                .chain(&inset.max.to_array())
                .for_each(|x| eat(x.to_bits()));
            inset.title.bytes().for_each(|b| eat(b as u32));
        } else {
            eat(u32::MAX);
        }
        h
    }

    /// The segments as `(a, b, colour)`, thin lines first, then wide ones: for tests and for
    /// scenes that inspect what they drew.
    pub fn segments(&self) -> impl Iterator<Item = (Vec3, Vec3, Vec3)> + '_ {
        let thin = self.lines.chunks_exact(2).map(|pair| {
            let c = pair[0].color;
            (
                Vec3::from(pair[0].position),
                Vec3::from(pair[1].position),
                Vec3::new(c[0], c[1], c[2]),
            )
        });
        let wide = self.strokes.iter().map(|s| {
            let c = s.color;
            (
                Vec3::from(s.a),
                Vec3::from(s.b),
                Vec3::new(c[0], c[1], c[2]),
            )
        });
        thin.chain(wide)
    }

    /// The segments drawn in exactly `color` (tests: "the path passes through every key").
    pub fn segments_of(&self, color: Vec3) -> impl Iterator<Item = (Vec3, Vec3)> + '_ {
        self.segments()
            .filter(move |(_, _, c)| *c == color)
            .map(|(a, b, _)| (a, b))
    }
}

/// The eight corners of the box from `min` to `max` (corner `i` takes max's x when bit 0 of `i`
/// is set, its y for bit 1, its z for bit 2).
pub fn box_corners(min: Vec3, max: Vec3) -> [Vec3; 8] {
    std::array::from_fn(|i| {
        let pick = |bit: usize, lo: f32, hi: f32| if i & bit == 0 { lo } else { hi };
        Vec3::new(
            pick(1, min.x, max.x),
            pick(2, min.y, max.y),
            pick(4, min.z, max.z),
        )
    })
}

/// The ground grid's opacity at `r`, the distance from its centre over its half-width: opaque
/// out to half the way, then easing down to 0.15 at the rim (and beyond, in the corners).
pub fn grid_fade(r: f32) -> f32 {
    let t = ((r - 0.5) / 0.5).clamp(0.0, 1.0);
    1.0 - 0.85 * t * t * (3.0 - 2.0 * t)
}

/// A label placed on screen: CSS pixels from the canvas's top-left corner.
#[derive(Clone, Debug, PartialEq)]
pub struct ScreenLabel {
    /// Where the layout starts from: the anchor's projection plus the label's offset.
    pub x_px: f32,
    pub y_px: f32,
    /// The anchor's own projection (CSS pixels): the point the label names, where a leader line
    /// starts ([`layout::leader`]).
    pub dot_px: glam::Vec2,
    /// False when the anchor is behind the camera or outside the view.
    pub visible: bool,
    pub text: String,
    /// sRGB hex, `#rrggbb`, ready for CSS.
    pub css_color: String,
    /// The text ends at `(x_px, y_px)` instead of starting there.
    pub left: bool,
    /// As [`Label::priority`].
    pub priority: i32,
    /// As [`Label::large`].
    pub large: bool,
}

/// Projects labels with `view_proj` (world to clip space, depth in [0, 1]) onto a canvas of
/// `width_px × height_px` CSS pixels.
pub fn project_labels(
    labels: &[Label],
    view_proj: Mat4,
    width_px: f32,
    height_px: f32,
) -> Vec<ScreenLabel> {
    labels
        .iter()
        .map(|label| {
            let clip = view_proj * label.anchor.extend(1.0);
            let ndc = clip.truncate() / clip.w;
            let visible = clip.w > 1e-6
                && ndc.x.abs() <= 1.05
                && ndc.y.abs() <= 1.05
                && (0.0..=1.0).contains(&ndc.z);
            let dot_px = glam::Vec2::new(
                (ndc.x * 0.5 + 0.5) * width_px,
                (0.5 - ndc.y * 0.5) * height_px,
            );
            ScreenLabel {
                x_px: dot_px.x + label.offset_px.x,
                y_px: dot_px.y + label.offset_px.y,
                dot_px,
                visible,
                text: label.text.clone(),
                css_color: palette::css(label.color),
                left: label.left,
                priority: label.priority,
                large: label.large,
            }
        })
        .collect()
}

/// Where the stroke shader (`render/shaders/stroke.wgsl`) puts the corners of `segment`'s quad,
/// in device pixels from the top-left of a `viewport_px` target with `px_per_css` device pixels
/// per CSS pixel: `[a − side, b − side, b + side, a + side]` (each end pushed out along the
/// segment by the same reach, for the round caps), and the half width that is drawn solid. The
/// quad reaches one pixel past the half width for the antialiased edge. `None` when the segment
/// lies wholly in front of the near plane.
pub fn stroke_corners(
    segment: &StrokeSegment,
    view_proj: Mat4,
    viewport_px: glam::Vec2,
    px_per_css: f32,
) -> Option<([glam::Vec2; 4], f32)> {
    use glam::Vec2;
    let ca0 = view_proj * Vec3::from(segment.a).extend(1.0);
    let cb0 = view_proj * Vec3::from(segment.b).extend(1.0);
    if ca0.z < 0.0 && cb0.z < 0.0 {
        return None;
    }
    let near = |p: Vec4, q: Vec4| {
        if p.z >= 0.0 {
            p
        } else {
            p.lerp(q, p.z / (p.z - q.z))
        }
    };
    let (ca, cb) = (near(ca0, cb0), near(cb0, ca0));
    let half_viewport = 0.5 * viewport_px;
    let sa = ca.truncate().truncate() / ca.w * half_viewport;
    let sb = cb.truncate().truncate() / cb.w * half_viewport;
    let length = sa.distance(sb);
    let dir = if length > 1e-4 {
        (sb - sa) / length
    } else {
        Vec2::X
    };
    let normal = dir.perp();
    let half_width = 0.5 * segment.width_px * px_per_css;
    let reach = half_width + 1.0;
    // From the shader's y-up pixels about the centre to the canvas's y-down pixels.
    let to_canvas = |p: Vec2| Vec2::new(p.x + half_viewport.x, half_viewport.y - p.y);
    let corner =
        |s: Vec2, end: f32, side: f32| to_canvas(s + dir * end * reach + normal * side * reach);
    Some((
        [
            corner(sa, -1.0, -1.0),
            corner(sb, 1.0, -1.0),
            corner(sb, 1.0, 1.0),
            corner(sa, -1.0, 1.0),
        ],
        half_width,
    ))
}

/// The course's named colours (linear RGB). `www/palette.css` defines the same colours as CSS
/// classes, so a word in the text can wear the colour of the object it names.
pub mod palette {
    use glam::Vec3;

    /// Linear RGB to `#rrggbb` (sRGB), for CSS.
    pub fn css(color: Vec3) -> String {
        let enc = |c: f32| {
            let c = c.clamp(0.0, 1.0);
            let s = if c <= 0.0031308 {
                12.92 * c
            } else {
                1.055 * c.powf(1.0 / 2.4) - 0.055
            };
            (s * 255.0).round() as u8
        };
        format!(
            "#{:02x}{:02x}{:02x}",
            enc(color.x),
            enc(color.y),
            enc(color.z)
        )
    }

    /// x axis.
    pub const X_AXIS: Vec3 = Vec3::new(0.672443, 0.0202886, 0.021219); // #d62728
    /// y axis.
    pub const Y_AXIS: Vec3 = Vec3::new(0.0251869, 0.351533, 0.0251869); // #2ca02c
    /// z axis.
    pub const Z_AXIS: Vec3 = Vec3::new(0.0137021, 0.158961, 0.672443); // #1f6fd6
    pub const RED: Vec3 = X_AXIS;
    pub const GREEN: Vec3 = Y_AXIS;
    pub const BLUE: Vec3 = Z_AXIS;
    pub const ORANGE: Vec3 = Vec3::new(0.791298, 0.254152, 0.0); // #e68a00
    pub const PURPLE: Vec3 = Vec3::new(0.296138, 0.0781874, 0.584078); // #944fc9
    pub const TEAL: Vec3 = Vec3::new(0.00856813, 0.361307, 0.391572); // #17a2a8
    pub const PINK: Vec3 = Vec3::new(0.768151, 0.109462, 0.332452); // #e35d9c
    pub const BROWN: Vec3 = Vec3::new(0.262251, 0.093059, 0.0703601); // #8c564b
    pub const GREY: Vec3 = Vec3::new(0.212231, 0.212231, 0.212231); // #7f7f7f
    pub const DARK: Vec3 = Vec3::new(0.0331048, 0.0331048, 0.0331048); // #333333
    pub const GRID: Vec3 = Vec3::new(0.57758, 0.57758, 0.57758); // #c8c8c8
    pub const GRID_AXIS: Vec3 = Vec3::new(0.323143, 0.323143, 0.323143); // #9a9a9a
    /// A key (keyframe, control point).
    pub const KEY: Vec3 = Vec3::new(0.0159963, 0.0159963, 0.0159963); // #222222
    /// The student's result, when it is drawn beside the reference.
    pub const STUDENT: Vec3 = PINK;
    /// The reference result.
    pub const REFERENCE: Vec3 = GREY;

    /// Every named colour with its CSS name (`var(--x-axis)` in `www/palette.css`).
    pub const NAMED: &[(&str, Vec3)] = &[
        ("x-axis", X_AXIS),
        ("y-axis", Y_AXIS),
        ("z-axis", Z_AXIS),
        ("orange", ORANGE),
        ("purple", PURPLE),
        ("teal", TEAL),
        ("pink", PINK),
        ("brown", BROWN),
        ("grey", GREY),
        ("pale-grey", GRID),
        ("dark", DARK),
        ("key", KEY),
    ];
}
