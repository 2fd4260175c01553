//! Lesson 00, "From triangles to pixels": a mesh stored two ways, the perspective frustum, depth
//! precision and z-fighting, flat and smooth normals, and Phong vs Blinn-Phong shading. Native and
//! tested natively (tests/figures_raster.rs); `web::raster` only wraps these for JavaScript.

use super::{check_samples, compare_note, failure_note, finite, format_number, in_range, palette};
use super::{Frame, MeshId, Runner, DEFAULT_RUNNER};
use crate::draw::Label;
use crate::exercises::raster::material;
use crate::exercises::run;
use crate::mesh::MeshData;
use crate::raster::shading::{light_from_image, sphere_image, Term};
use crate::raster::storage::{tetrahedron, uv_sphere_indexed};
use crate::raster::{self, Material, MeshSizes, ShadingModel};
use crate::Valid;
use glam::{Mat3, Mat4, Vec2, Vec3};

const DEG: f32 = std::f32::consts::PI / 180.0;
const FILE: &str = "src/exercises/raster.rs";
const TOLERANCE: f32 = 1e-4;

/// Thousands separated by thin spaces, for byte counts in notes.
fn bytes(n: usize) -> String {
    let s = n.to_string();
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if i > 0 && (s.len() - i).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(c);
    }
    out + " B"
}

// ---------------------------------------------------------------------------------------------
// Figure 1: one mesh, two storages.

/// Colours of Figure 1, as the page's words name them.
pub const SOUP_COLOR: Vec3 = palette::ORANGE;
pub const INDEXED_COLOR: Vec3 = palette::TEAL;

/// The most segments around the sphere of Figure 1 (its cost grows with their square).
pub const MAX_SEGMENTS: u32 = 64;

/// Above this many segments, Figure 1 marks the corners and positions only on a patch of the
/// sphere that faces the page's camera, with smaller dots, the soup's triangles pulled further
/// apart, and elsewhere pale 1 px edges along every few rings and meridians (the soup's as
/// dashes, each its own triangle's edge): drawn everywhere, thousands of dots and edges merge
/// into one blot.
pub const DENSE_SEGMENTS: u32 = 16;
/// The centre of that patch before the first frame's camera is known (towards the page's
/// camera; then [`MeshStorage::set_eye`] turns it to the eye) and the cosine of its angular
/// radius (25°).
const PATCH_FACING: Vec3 = Vec3::new(0.0, 0.296, 0.955);
/// The point between Figure 1's two spheres: the patch faces the eye from there.
const MESH_MIDDLE: Vec3 = Vec3::new(0.0, 1.2, 0.0);
const PATCH_COS: f32 = 0.906;

/// A pale `color` (mixed with white) for the 1 px edges outside a dense sphere's patch: seen
/// through the patch's dots, thousands of full-colour edges would fill the disc.
fn faint(color: Vec3) -> Vec3 {
    color.lerp(Vec3::ONE, 0.65)
}

/// Figure 1: the same mesh as a triangle soup (left, every triangle pulled apart so that
/// its own three copies of the corners show) and as indexed geometry (right, each position once).
pub struct MeshStorage {
    sphere: bool,
    segments: u32,
    positions: Vec<Vec3>,
    indices: Vec<u32>,
    /// The direction the dense sphere's marked patch faces (unit).
    facing: Vec3,
    /// The last frame's camera and canvas size (CSS pixels), which the labels are placed for.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

impl Default for MeshStorage {
    fn default() -> Self {
        Self::new()
    }
}

impl MeshStorage {
    pub fn new() -> Self {
        let mut s = MeshStorage {
            sphere: true,
            segments: 8,
            positions: Vec::new(),
            indices: Vec::new(),
            facing: PATCH_FACING,
            view: None,
        };
        s.rebuild();
        s
    }

    /// The camera's eye (world space), so that a dense sphere's patch of dots faces the reader
    /// after an orbit too (one direction for both spheres, from the point between them, so the
    /// two patches hold the same part of the mesh and the note's counts compare). An eye at that
    /// point or not finite keeps the last direction.
    pub fn set_eye(&mut self, eye: Vec3) {
        let to_eye = eye - MESH_MIDDLE;
        if to_eye.is_finite() && to_eye.length() > 1e-3 {
            self.facing = to_eye.normalize();
        }
    }

    /// The last frame's camera and canvas size (CSS pixels): the patch faces its eye
    /// ([`Self::set_eye`]) and the labels take places clear of the lines, dots and the other
    /// sphere on it. A size that is not positive and finite is ignored.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        self.set_eye(camera.eye());
        if width_px > 0.0 && height_px > 0.0 && (width_px * height_px).is_finite() {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    fn rebuild(&mut self) {
        (self.positions, self.indices) = if self.sphere {
            uv_sphere_indexed(self.segments, (self.segments / 2).max(2))
        } else {
            tetrahedron()
        };
    }

    /// "tetrahedron" or "sphere".
    pub fn set_shape(&mut self, shape: &str) -> Result<(), String> {
        self.sphere = match shape {
            "sphere" => true,
            "tetrahedron" => false,
            _ => {
                return Err(format!(
                    "shape must be \"tetrahedron\" or \"sphere\", got {shape:?}"
                ))
            }
        };
        self.rebuild();
        Ok(())
    }

    /// Segments around the sphere, a whole number from 3 to [`MAX_SEGMENTS`] (rings: half as
    /// many; a fraction is an error, not rounded).
    pub fn set_segments(&mut self, segments: f32) -> Result<(), String> {
        self.segments = super::whole_number("segments", segments, 3, MAX_SEGMENTS as usize)? as u32;
        self.rebuild();
        Ok(())
    }

    /// Whether the sphere has more than [`DENSE_SEGMENTS`] segments (dots on a patch only).
    pub fn is_dense(&self) -> bool {
        self.sphere && self.segments > DENSE_SEGMENTS
    }

    /// Whether a dot goes at `p` (a position, or a triangle's centre, on the mesh at the origin):
    /// everywhere, or on a dense sphere only on the patch facing the camera.
    fn marked(&self, p: Vec3) -> bool {
        !self.is_dense() || p.normalize_or_zero().dot(self.facing) > PATCH_COS
    }

    /// Ring and segment of position `i` of the sphere, each counted in steps of m, and whether
    /// both fall on a step: outside a dense sphere's patch only every m-th ring and meridian is
    /// drawn (m keeps about 12 of them round the sphere), where every edge would merge into a
    /// pale disc. `None` at the poles.
    fn coarse_cell(&self, i: u32) -> Option<(u32, u32)> {
        let (n, m) = (self.segments, self.segments.div_ceil(12));
        (i >= 1 && (i as usize) < self.positions.len() - 1)
            .then(|| (((i - 1) / n + 1) % m, (i - 1) % n % m))
    }

    /// Whether the edge from position `a` to `b` runs along a ring or meridian that is drawn
    /// outside a dense sphere's patch ([`Self::coarse_cell`]): both ends on the same drawn ring
    /// next to each other, or on the same drawn meridian.
    fn on_grid(&self, a: u32, b: u32) -> bool {
        let n = self.segments;
        let (a, b) = (a.min(b), a.max(b));
        match (self.coarse_cell(a), self.coarse_cell(b)) {
            (Some(p), Some(_)) => {
                (a - 1) / n == (b - 1) / n && p.0 == 0 || (b - a) % n == 0 && p.1 == 0
            }
            _ => false,
        }
    }

    /// How many corners of the soup get a dot.
    fn marked_corners(&self) -> usize {
        self.indices
            .chunks_exact(3)
            .filter(|tri| {
                let centre = tri
                    .iter()
                    .map(|&i| self.positions[i as usize])
                    .sum::<Vec3>()
                    / 3.0;
                self.marked(centre)
            })
            .count()
            * 3
    }

    pub fn sizes(&self) -> MeshSizes {
        raster::mesh_sizes(self.positions.len(), self.indices.len() / 3)
    }

    /// The two storages written out, for a mesh of at most 12 positions (the tetrahedron):
    /// the soup's corners triangle by triangle, then the indexed positions and each triangle's
    /// three indices. Empty for bigger meshes, whose lists would not fit beside the figure.
    pub fn listing(&self) -> String {
        if self.positions.len() > 12 {
            return String::new();
        }
        let xyz = |p: Vec3| {
            let n = |x: f32| format!("{:6.3}", if x.abs() < 5e-4 { 0.0 } else { x });
            format!("({}, {}, {})", n(p.x), n(p.y), n(p.z))
        };
        let mut out = String::from("triangle soup: 3 corners per triangle\n");
        for (t, tri) in self.indices.chunks_exact(3).enumerate() {
            let corners: Vec<String> = tri
                .iter()
                .map(|&i| xyz(self.positions[i as usize]))
                .collect();
            out += &format!("  t{t}: {}\n", corners.join(" "));
        }
        out += "\nindexed: positions (geometry)\n";
        for (i, p) in self.positions.iter().enumerate() {
            out += &format!("  {i}: {}\n", xyz(*p));
        }
        out += "indexed: triangles (connectivity)\n";
        for (t, tri) in self.indices.chunks_exact(3).enumerate() {
            out += &format!("  t{t}: {} {} {}\n", tri[0], tri[1], tri[2]);
        }
        out
    }

    /// Left: the soup; right: the indexed mesh. Returns the note with both sizes.
    pub fn draw(&self, frame: &mut Frame) -> String {
        let s = self.sizes();
        let (left, right) = (Vec3::new(-1.4, 1.2, 0.0), Vec3::new(1.4, 1.2, 0.0));
        frame.grid(12, 0.5);
        let small = self.positions.len() <= 12;
        let dense = self.is_dense();
        // A marker's outline takes 2.5 px of its radius: 8 px shows a disc of colour, which the
        // soup's triangles, pulled to half their size, leave room for round each position up to
        // 10 segments. Beyond, the dots must stay apart more than show their colour (a dense
        // sphere's are shaded discs instead, below).
        let dot = match (small, self.segments <= 10) {
            (true, _) => 12.0,
            (false, true) => 8.0,
            (false, false) => 6.0,
        };
        let keep = if dense { 0.6 } else { 0.5 };
        // Where each soup triangle's centre is drawn, from the soup's centre. The tetrahedron's
        // four go 0.9 m out across the last frame's view, a quarter turn apart in the order of
        // their own centres round the soup's: any face (shrunk in place, or pushed out in 3D)
        // lies across another on the canvas from some side, and these never do.
        let centres: Vec<Vec3> = self
            .indices
            .chunks_exact(3)
            .map(|tri| tri.iter().map(|&i| self.positions[i as usize]).sum::<Vec3>() / 3.0)
            .collect();
        let mut shown = centres.clone();
        if small {
            let (across, up) = self.view.map_or((Vec3::X, Vec3::Y), |(camera, _)| {
                let v = camera.view();
                (v.row(0).truncate(), v.row(1).truncate())
            });
            let angle: Vec<f32> = (centres.iter())
                .map(|c| c.dot(up).atan2(c.dot(across)))
                .collect();
            let order = crate::order::order_by(angle.iter().copied(), false);
            for (k, &t) in order.iter().enumerate() {
                let a = angle[order[0]] + k as f32 * std::f32::consts::FRAC_PI_2;
                shown[t] = (across * a.cos() + up * a.sin()) * 0.9;
            }
        }
        // On a dense sphere the dots are shaded discs a fixed fraction of an edge across (an
        // edge of the unit sphere is about 2π / segments long), without a marker's rim: a marker
        // under 8 px is all rim, and hundreds of them merge into one grey mat.
        let edge = std::f32::consts::TAU / self.segments as f32;
        // Soup: each triangle shrunk towards its centre, its own three corners. Outside a dense
        // sphere's patch, each triangle's edges along the drawn rings and meridians, shrunk with
        // it: the rings read as dashed lines, one dash per triangle, round the whole sphere.
        for (tri, (&centre, &at)) in self.indices.chunks_exact(3).zip(centres.iter().zip(&shown)) {
            let corners = [tri[0], tri[1], tri[2]].map(|i| left + at + (self.positions[i as usize] - centre) * keep);
            if !self.marked(centre) {
                for k in 0..3 {
                    if self.on_grid(tri[k], tri[(k + 1) % 3]) {
                        frame.line(corners[k], corners[(k + 1) % 3], faint(SOUP_COLOR));
                    }
                }
                continue;
            }
            let [pa, pb, pc] = corners;
            if dense {
                frame.polyline(&[pa, pb, pc, pa], SOUP_COLOR);
            } else {
                frame.wide_polyline(&[pa, pb, pc, pa], SOUP_COLOR, 1.5);
            }
            for p in corners {
                if dense {
                    frame.point(p, 0.16 * edge, SOUP_COLOR);
                } else {
                    frame.marker(p, dot, SOUP_COLOR);
                }
            }
        }
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // The least gap between a label and a line or dot: one that touches a line reads as
        // part of it. Wide, as the search samples each line at 17 points: a line that crosses
        // a label's corner between two of them is still kept off.
        const LINE_MARGIN_PX: f32 = 4.0;
        // Indexed: each edge drawn once (from the triangle where a < b, or from both if the mesh
        // is open, which ours is not), each position once.
        for tri in self.indices.chunks_exact(3) {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                if a < b {
                    // Outside the patch: an edge along a drawn ring or meridian.
                    let on_grid = self.on_grid(a, b);
                    let (a, b) = (self.positions[a as usize], self.positions[b as usize]);
                    if self.marked((a + b) * 0.5) {
                        frame.wide_line(right + a, right + b, INDEXED_COLOR, 1.5);
                    } else if on_grid {
                        frame.line(right + a, right + b, faint(INDEXED_COLOR));
                    }
                }
            }
        }
        for p in self.positions.iter().filter(|p| self.marked(**p)) {
            if dense {
                frame.point(right + *p, 0.2 * edge, INDEXED_COLOR);
            } else {
                frame.marker(right + *p, dot * 1.2, INDEXED_COLOR);
            }
        }
        frame.keep_box_in_view(
            left - Vec3::splat(if small { 1.4 } else { 1.1 }),
            right + Vec3::splat(1.1) + Vec3::Y * 0.3,
        );
        // Each sphere's disc on the last frame's view (centre and radius, CSS pixels, the radius
        // from points 1.2 m off the centre along the axes: a sphere's outline in perspective is
        // a little wider than its axes' ends): the names keep off both, so that neither name
        // reads as the other sphere's.
        let disc = |c: Vec3| {
            let (view_proj, size) = view?;
            let at = |p| crate::camera::project_to_canvas(view_proj, size, p);
            let centre = at(c)?;
            let r = [Vec3::X, Vec3::Y, Vec3::Z]
                .iter()
                .filter_map(|&a| Some(at(c + a * 1.2)?.distance(centre)))
                .fold(0.0, f32::max);
            Some((centre, r))
        };
        let discs = [disc(left), disc(right)];
        let off_discs = |rect: crate::draw::layout::Rect| {
            discs
                .iter()
                .flatten()
                .all(|&(c, r)| rect.nearest(c).distance(c) > r)
        };
        // The names above their spheres at the page's camera; once orbited, the first place round
        // the sphere's disc (as a dot as wide) that covers neither sphere.
        for (centre, disc, text, color) in [
            (
                left,
                discs[0],
                format!("triangle soup: {}", bytes(s.soup_bytes)),
                SOUP_COLOR,
            ),
            (
                right,
                discs[1],
                format!("indexed: {}", bytes(s.indexed_bytes)),
                INDEXED_COLOR,
            ),
        ] {
            let width = disc.map_or(0.0, |d| 2.0 * d.1);
            let mut around = Label::around_dot(centre, width, -Vec2::Y, &text, color, 2, 6, 12.0);
            around.insert(
                0,
                Label {
                    anchor: centre + Vec3::Y * 1.35,
                    text,
                    color,
                    left: false,
                    priority: 2,
                    offset_px: Vec2::ZERO,
                    large: false,
                },
            );
            // The tetrahedron's triangles sit round an empty centre, a name among them reads as
            // one triangle's: the name keeps the numbers' margin off their lines and dots.
            frame.first_clear_label_by(view, if small { LINE_MARGIN_PX } else { 0.0 }, around, &off_discs);
        }
        if small {
            // Number the soup's triangles as the listing beside the figure does, each at the
            // first place clear of the lines, dots and other names: on its face's centre, else
            // round it, else round a point out from the face (a face turned away from the eye
            // has its centre among the near faces' lines); the indexed positions likewise round
            // their dots.
            for (t, at) in shown.iter().enumerate() {
                let centre = left + *at;
                let text = format!("t{t}");
                let out = left + (centre - left).normalize_or_zero() * 1.6;
                let mut around =
                    Label::around_dot(centre, 0.0, Vec2::ZERO, &text, SOUP_COLOR, 1, 6, 6.0);
                around.extend(Label::around_dot(
                    out,
                    0.0,
                    Vec2::ZERO,
                    &text,
                    SOUP_COLOR,
                    1,
                    6,
                    8.0,
                ));
                let on = Label::off_dot(centre, 0.0, Vec2::ZERO, text, SOUP_COLOR, 1);
                around.insert(0, on);
                frame.first_clear_label_by(view, LINE_MARGIN_PX, around, |_| true);
            }
            for (i, p) in self.positions.iter().enumerate() {
                let around = Label::around_dot(
                    right + *p,
                    dot * 1.2,
                    Vec2::ZERO,
                    &i.to_string(),
                    palette::DARK,
                    1,
                    8,
                    6.0,
                );
                frame.first_clear_label_by(view, LINE_MARGIN_PX, around, |_| true);
            }
        }
        let patch = if dense {
            format!(
                " Dots only on the patch facing you: {} corners of the soup, {} positions indexed.",
                self.marked_corners(),
                self.positions.iter().filter(|p| self.marked(**p)).count()
            )
        } else {
            String::new()
        };
        format!(
            "{} triangles. Triangle soup: 3 × {} = {} positions × 12 B = {}. Indexed: {} positions × 12 B + \
             {} indices × 4 B = {}. The soup is {:.2}× larger; every position is stored {:.1} times on average.{patch}",
            s.triangles,
            s.triangles,
            s.soup_positions,
            bytes(s.soup_bytes),
            s.vertices,
            s.indices,
            bytes(s.indexed_bytes),
            s.soup_bytes as f32 / s.indexed_bytes as f32,
            s.soup_positions as f32 / s.vertices as f32,
        )
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 2: the frustum.

/// Colours of Figure 2.
pub mod frustum_colors {
    use super::palette;
    use glam::Vec3;
    pub const NEAR: Vec3 = palette::Z_AXIS;
    pub const FAR: Vec3 = palette::PURPLE;
    pub const POINT: Vec3 = palette::ORANGE;
    pub const OUTSIDE: Vec3 = palette::X_AXIS;
    pub const ON_NEAR: Vec3 = palette::PINK;
    pub const NDC_BOX: Vec3 = palette::TEAL;
}

/// Where the camera of Figure 2 stands in the world: view space moved up by 1.2 m.
const EYE: Vec3 = Vec3::new(0.0, 1.2, 0.0);
/// Figure 2's dots: the point (and its place in the NDC box) and its image on the near plane,
/// CSS pixels across.
const POINT_PX: f32 = 14.0;
/// Figure 5's lamp, CSS pixels across.
const LAMP_PX: f32 = 16.0;
const IMAGE_PX: f32 = 10.0;
/// Where the NDC box of Figure 2 stands: the x and y of its near face's centre, whose z is a
/// quarter of the way from the eye to the far plane as drawn (2 m at the page's defaults), so
/// the box stays beside the frustum's middle when a wide field of view draws the frustum short:
/// level with its far plane instead, it sits behind that plane's tall edge from the side.
const NDC_ORIGIN: Vec2 = Vec2::new(9.5, 1.2);
/// The far plane's half-width at the page's defaults (50°, z_far 8 m, aspect 1.5), beside which
/// the NDC box is drawn at its own size.
const NDC_FAR_HALF_WIDTH: f32 = 5.6;

/// Figure 2: a camera's frustum (field of view, z_near, z_far), a point that travels along the
/// view direction through it, and the same point in normalised device coordinates (the box on
/// the right: x, y ∈ [−1, 1], depth ∈ [0, 1]).
pub struct Frustum {
    fov_y_rad: f32,
    near: f32,
    far: f32,
    /// The point's view-space x and y, metres.
    offset: Vec2,
    use_exercise: bool,
    runner: Runner,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the NDC box's
    /// labels take places that cover none of its lines.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

impl Default for Frustum {
    fn default() -> Self {
        Self::new()
    }
}

impl Frustum {
    /// Width / height of the figure's imaginary screen.
    pub const ASPECT: f32 = 1.5;
    /// The farthest z_far the figure draws, metres.
    pub const MAX_FAR: f32 = 20.0;

    pub fn new() -> Self {
        Frustum {
            fov_y_rad: 50.0 * DEG,
            near: 1.0,
            far: 8.0,
            offset: Vec2::new(0.6, 0.3),
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the NDC box's labels are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// Field of view in degrees (10 to 150), z_near (0.05 to 5 m) and z_far (above z_near, at
    /// most [`Self::MAX_FAR`]).
    pub fn set_frustum(&mut self, fov_deg: f32, near: f32, far: f32) -> Result<(), String> {
        let fov = in_range("field of view", fov_deg, 10.0, 150.0)?;
        let near = in_range("z_near", near, 0.05, 5.0)?;
        let far = in_range("z_far", far, 0.1, Self::MAX_FAR)?;
        if far <= near {
            return Err(format!(
                "z_far ({far}) must be greater than z_near ({near})"
            ));
        }
        (self.fov_y_rad, self.near, self.far) = (fov * DEG, near, far);
        Ok(())
    }

    /// The point's view-space x and y (metres, each within ±10).
    pub fn set_offset(&mut self, x: f32, y: f32) -> Result<(), String> {
        self.offset = Vec2::new(
            in_range("point x", x, -10.0, 10.0)?,
            in_range("point y", y, -10.0, 10.0)?,
        );
        Ok(())
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// The point's distance in front of the camera at `s ∈ [0, 1]`: from half of z_near to 15 %
    /// past z_far, so it enters and leaves the frustum.
    pub fn distance_at(&self, s: f32) -> f32 {
        let (a, b) = (0.5 * self.near, 1.15 * self.far);
        a + (b - a) * s
    }

    /// The reference matrix: wgpu's (`gl = false`) or OpenGL's.
    pub fn matrix(&self, gl: bool) -> Mat4 {
        let f = if gl {
            raster::perspective_gl
        } else {
            raster::perspective_wgpu
        };
        f(self.fov_y_rad, Self::ASPECT, self.near, self.far).valid("validated by the setters")
    }

    /// The wgpu matrix the figure uses: the student's with "use my exercise" when it gives one.
    fn used_matrix(&self) -> Mat4 {
        self.use_exercise
            .then(|| {
                run::perspective_matrix(
                    self.runner,
                    self.fov_y_rad,
                    Self::ASPECT,
                    self.near,
                    self.far,
                )
                .ok()
            })
            .flatten()
            .filter(|m| m.is_finite())
            .unwrap_or_else(|| self.matrix(false))
    }

    /// The point in view space at `s`.
    pub fn point_at(&self, s: f32) -> Vec3 {
        self.offset.extend(-self.distance_at(s))
    }

    /// `[clip x, y, z, w, ndc x, y, z]` with wgpu's matrix (the student's when used), then the same
    /// seven with OpenGL's, for the page's table.
    pub fn readout(&self, s: f32) -> Result<[f32; 14], String> {
        let s = in_range("s", s, 0.0, 1.0)?;
        let p = self.point_at(s);
        let a = raster::project(self.used_matrix(), p, 0.0);
        let b = raster::project(self.matrix(true), p, -1.0);
        let mut out = [0.0; 14];
        out[..4].copy_from_slice(&a.clip.to_array());
        out[4..7].copy_from_slice(&a.ndc.to_array());
        out[7..11].copy_from_slice(&b.clip.to_array());
        out[11..].copy_from_slice(&b.ndc.to_array());
        Ok(out)
    }

    /// Depth against distance: `(d, depth wgpu, depth OpenGL)` over the point's whole trip
    /// ([`Frustum::distance_at`], half of z_near to 15 % past z_far), so the plot's playhead never
    /// leaves it; outside z_near..z_far the depths leave their range (the point is clipped there).
    pub fn sample_depth(&self, samples: usize) -> Result<Vec<[f32; 3]>, String> {
        check_samples(samples)?;
        Ok((0..samples)
            .map(|k| {
                let d = self.distance_at(k as f32 / (samples - 1) as f32);
                [
                    d,
                    raster::ndc_depth_wgpu(d, self.near, self.far),
                    raster::ndc_depth_gl(d, self.near, self.far),
                ]
            })
            .collect())
    }

    /// Draws the frustum, the point at `s`, and the NDC box; returns the note.
    pub fn draw(&self, frame: &mut Frame, s: f32) -> Result<String, String> {
        use frustum_colors::*;
        let s = in_range("s", s, 0.0, 1.0)?;
        frame.grid(24, 1.0);
        let half_h = |d: f32| d * (0.5 * self.fov_y_rad).tan();
        // k: how much wider the far plane is than at the page's defaults. A wider frustum is
        // drawn scaled down about the eye by 1/k (its shape kept), and the NDC box beside it at
        // its own size, so both fit the canvas together at any field of view and z_far.
        let k = (half_h(self.far) * Self::ASPECT / NDC_FAR_HALF_WIDTH).max(1.0);
        let at = |v: Vec3| EYE + v / k;
        let corners = |d: f32| {
            let (h, w) = (half_h(d), half_h(d) * Self::ASPECT);
            [(-w, -h), (w, -h), (w, h), (-w, h)].map(|(x, y)| at(Vec3::new(x, y, -d)))
        };
        let (near, far) = (corners(self.near), corners(self.far));
        let w = crate::draw::CURVE_PX;
        frame.wide_polyline(&[near[0], near[1], near[2], near[3], near[0]], NEAR, w);
        frame.wide_polyline(&[far[0], far[1], far[2], far[3], far[0]], FAR, w);
        for (n, f) in near.iter().zip(&far) {
            frame.wide_line(EYE, *n, palette::GREY, 1.5);
            frame.wide_line(*n, *f, palette::GREY, 1.5);
        }
        frame.marker(EYE, 12.0, palette::DARK);
        // The eye, the near plane, the point and its image crowd at the apex (the point starts at
        // half of z_near), so each label there reads away from the others: the eye's left of the
        // apex (the first place round its dot, left first, that keeps LINE_MARGIN_PX off the
        // frustum's edges on the last frame's view: orbited, the near plane's lower edge passes
        // beside the eye), z_near's to the left of the near plane's top-left corner (the point
        // and its image stay to the right of the view axis, where x > 0 puts them), the point's
        // above it and the image's below it, off the ray from the eye. The point's label wins,
        // then the eye's.
        // The point, the ray from the eye, and where the ray crosses the near plane (the image).
        let p = self.point_at(s);
        let m = self.used_matrix();
        let q = raster::project(m, p, 0.0);
        let color = if q.inside { POINT } else { OUTSIDE };
        frame.stroke(
            &[EYE, at(p)],
            palette::GREY,
            crate::draw::StrokeStyle::dashed(1.5, 0.15, 0.1),
        );
        // The point's label straight above its dot and the image's below and right of its
        // own, off the ray (which rises to the right towards the point), each a few pixels
        // from its dot at any zoom: where the point crosses the near plane the two dots meet.
        // At a small z_near the image sits by the eye and the near plane's corner, so its name
        // goes to the first place round its dot, below and right first, clear of the names
        // placed before (the eye's, z_near's, the point's), the dots and the lines.
        frame.marker(at(p), POINT_PX, color);
        frame.label_off_dot(at(p), POINT_PX, Vec2::new(0.0, -1.0), "p", color, 3);
        let on_near = p * (self.near / -p.z);
        frame.marker_on_top(at(on_near), IMAGE_PX, ON_NEAR);
        // The eye's and z_near's names keep off the point's and the image's dots.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let around_eye = Label::around_dot(EYE, 12.0, -Vec2::X, "eye", palette::DARK, 2, 8, 8.0);
        frame.first_clear_label_by(view, LINE_MARGIN_PX, around_eye, |_| true);
        // At a small z_near the near plane's corner sits a few pixels from the eye, and a name
        // ending at it would butt against the eye's: then z_near's goes to the first place round
        // the corner, up and to the left first, clear of the eye's name, the dots and the lines
        // (on the last frame's view).
        let at_corner = crate::draw::Label {
            anchor: near[3],
            text: "z_near".to_string(),
            color: NEAR,
            left: true,
            priority: 1,
            offset_px: Vec2::ZERO,
            large: false,
        };
        let round_corner = Label::around_dot(
            near[3],
            0.0,
            Vec2::new(-1.0, -1.0),
            "z_near",
            NEAR,
            1,
            6,
            8.0,
        );
        frame.first_clear_label(view, std::iter::once(at_corner).chain(round_corner));
        let dot_px = POINT_PX.max(IMAGE_PX);
        let candidates =
            Label::around_dot(at(on_near), dot_px, Vec2::ONE, "image", ON_NEAR, 0, 8, 8.0);
        frame.first_clear_label_by(view, LINE_MARGIN_PX, candidates, |_| true);
        // The NDC box: x, y ∈ [−1, 1] drawn as is, depth ∈ [0, 1] drawn 2 m deep along −z, right
        // of the eye.
        let origin = NDC_ORIGIN.extend(-0.25 * self.far / k);
        let ndc_to_world = |v: Vec3| origin + Vec3::new(v.x, v.y, -2.0 * v.z);
        let box_corners: Vec<Vec3> = [0.0, 1.0]
            .iter()
            .flat_map(|&z| {
                [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                    .map(move |(x, y)| Vec3::new(x, y, z))
            })
            .map(ndc_to_world)
            .collect();
        for i in 0..4 {
            frame.wide_line(box_corners[i], box_corners[(i + 1) % 4], NEAR, w);
            frame.wide_line(box_corners[4 + i], box_corners[4 + (i + 1) % 4], FAR, w);
            frame.wide_line(box_corners[i], box_corners[4 + i], NDC_BOX, 1.5);
        }
        // The far plane's top-right corner sits beside the box when a wide field of view draws
        // the frustum short: its name goes round the corner, up and to the right first, clear
        // of both.
        let around_far = Label::around_dot(far[2], 0.0, Vec2::new(1.0, -1.0), "z_far", FAR, 1, 4, 6.0);
        frame.first_clear_label_by(view, LINE_MARGIN_PX, around_far, |_| true);
        // The box's labels go where they cover none of its lines (three meet at each corner,
        // and the point's dot moves among them) on the last frame's view, each clear of those
        // placed before it: the point's name first, preferably above its dot, then the box's
        // name, preferably below it, then each face's depth beside its top-right corner,
        // preferably away from the box's centre.
        let away_from_box = |corner: Vec3| {
            let centre = ndc_to_world(Vec3::new(0.0, 0.0, 0.5));
            view.and_then(|(view_proj, size)| {
                let at = |p| crate::camera::project_to_canvas(view_proj, size, p);
                Some(at(corner)? - at(centre)?)
            })
            .unwrap_or(Vec2::X)
        };
        if q.clip.w > 0.0 && q.ndc.abs().max_element() < 3.0 {
            let at = ndc_to_world(q.ndc);
            frame.marker(at, POINT_PX, color);
            let candidates = Label::around_dot(at, POINT_PX, -Vec2::Y, "p", color, 3, 4, 6.0);
            frame.first_clear_label_by(view, LINE_MARGIN_PX, candidates, |_| true);
        }
        // A corner as a dot this wide: the label keeps LABEL_DOT_GAP_PX off its lines.
        const CORNER_PX: f32 = 4.0 * crate::draw::CURVE_PX;
        // The least gap between a label and a line: one that touches a line reads as part of it.
        const LINE_MARGIN_PX: f32 = 3.0;
        let bottom = ndc_to_world(Vec3::new(0.0, -1.0, 0.5));
        let candidates =
            Label::around_dot(bottom, CORNER_PX, Vec2::Y, "NDC (wgpu)", NDC_BOX, 2, 6, 8.0);
        frame.first_clear_label_by(view, LINE_MARGIN_PX, candidates, |_| true);
        for (corner, text, color) in [
            (box_corners[2], "depth 0", NEAR),
            (box_corners[6], "depth 1", FAR),
        ] {
            let toward = away_from_box(corner);
            let candidates = Label::around_dot(corner, CORNER_PX, toward, text, color, 1, 6, 6.0);
            frame.first_clear_label_by(view, LINE_MARGIN_PX, candidates, |_| true);
        }
        // The whole frustum, the point's path and the NDC box stay in view at any canvas size.
        frame.keep_in_view.push(EYE);
        frame.keep_in_view.extend(far);
        frame.keep_in_view.extend(near);
        frame.keep_in_view.push(at(self.point_at(1.0)));
        frame.keep_in_view.extend(box_corners.iter().copied());
        // Room for the depth labels right of the box's right-hand corners, the box being the
        // rightmost thing in the page's view.
        frame
            .keep_in_view
            .extend([2, 6].map(|i| box_corners[i] + Vec3::X * 1.4));
        // And for the eye's and z_near's names left of the apex and the near plane's corner.
        frame
            .keep_in_view
            .extend([EYE, near[3]].map(|p| p - Vec3::X * 1.4));
        let d = self.distance_at(s);
        let mut note = format!(
            "Distance d = {} m: depth {} (wgpu), {} (OpenGL); the wgpu depth passes 0.5 at d = {} m. {}",
            format_number(d),
            format_number(raster::ndc_depth_wgpu(d, self.near, self.far)),
            format_number(raster::ndc_depth_gl(d, self.near, self.far)),
            format!("{:.3}", self.half_depth_distance()),
            if q.inside {
                "Inside the frustum: drawn."
            } else if d < self.near {
                "Nearer than z_near: clipped."
            } else if d > self.far {
                "Beyond z_far: clipped."
            } else {
                "Outside the field of view: clipped."
            }
        );
        if self.use_exercise {
            note += " ";
            note += &self.exercise_note();
        }
        Ok(note)
    }

    /// The distance at which the wgpu depth f/(f − n)·(1 − n/d) is 0.5: d = 2nf/(n + f), metres
    /// (the crossing Figure 2's Try this asks for, printed because a linear axis squeezes it into a
    /// few pixels when z_near is small).
    pub fn half_depth_distance(&self) -> f32 {
        2.0 * self.near * self.far / (self.near + self.far)
    }

    /// Compares the student's matrix (exercise 0.1) with the reference at the current frustum and
    /// at [`PERSPECTIVE_PROBES`] (a wide and a narrow view, a short range, a square screen),
    /// naming every input where they differ.
    pub fn exercise_note(&self) -> String {
        let here = (self.fov_y_rad / DEG, Self::ASPECT, self.near, self.far);
        let mut probes = Vec::new();
        for (fov_deg, aspect, near, far) in std::iter::once(here).chain(PERSPECTIVE_PROBES) {
            let at = format!(
                "field of view {}°, aspect {}, z_near {}, z_far {}",
                format_number(fov_deg),
                format_number(aspect),
                format_number(near),
                format_number(far)
            );
            let reference =
                raster::perspective_wgpu(fov_deg * DEG, aspect, near, far).valid("valid probe");
            let yours = match run::perspective_matrix(self.runner, fov_deg * DEG, aspect, near, far)
            {
                Ok(m) => m,
                Err(f) => return failure_note("exercise 0.1 perspective_matrix", FILE, &f),
            };
            probes.push(super::curves::Probe {
                at,
                yours: yours.to_cols_array().to_vec(),
                reference: reference.to_cols_array().to_vec(),
            });
        }
        let mut note = super::curves::probe_note("perspective_matrix", &probes, TOLERANCE * 10.0).1;
        let yours = Mat4::from_cols_slice(&probes[0].yours);
        if !yours.abs_diff_eq(self.matrix(false), TOLERANCE * 10.0) {
            // Where the student's matrix sends the two planes says more than 16 numbers.
            let z = |d: f32| raster::project(yours, Vec3::new(0.0, 0.0, -d), 0.0).ndc.z;
            note += &format!(
                " At the figure's frustum yours maps z_near to depth {} and z_far to {} (should be 0 and 1).",
                format_number(z(self.near)),
                format_number(z(self.far))
            );
        }
        note
    }
}

/// Where exercise 0.1 is checked besides the figure's frustum: (field of view °, aspect,
/// z_near, z_far).
pub const PERSPECTIVE_PROBES: [(f32, f32, f32, f32); 3] = [
    (90.0, 1.0, 0.1, 100.0),
    (20.0, 2.0, 2.0, 3.0),
    (120.0, 0.5, 0.5, 50.0),
];

// ---------------------------------------------------------------------------------------------
// Figure 3: depth precision and z-fighting.

/// Colours of Figure 3: the upper (nearer) plane and the lower one just beneath it.
pub const UPPER_PLANE: Vec3 = palette::X_AXIS;
pub const LOWER_PLANE: Vec3 = palette::Z_AXIS;

/// Figure 3: two horizontal planes `gap` metres apart, below a camera 3 m up that looks 10° down,
/// drawn through a depth buffer of 16 or 24 bits. The upper plane should hide the lower one
/// everywhere; where one depth step is worth more than the planes' separation along the line of
/// sight, the two fight.
pub struct DepthPrecision {
    near: f32,
    far: f32,
    gap: f32,
    bits: u32,
    /// The camera and canvas size (CSS pixels) of the last frame, which the eye's and the
    /// fighting line's names are placed for.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

impl Default for DepthPrecision {
    fn default() -> Self {
        Self::new()
    }
}

/// Eye height above the upper plane, metres.
pub const EYE_HEIGHT: f32 = 3.0;
/// How far the camera looks down, radians.
const PITCH: f32 = 10.0 * DEG;
/// Vertical field of view of the image, radians.
const IMAGE_FOV: f32 = 40.0 * DEG;
/// The largest image side, pixels.
pub const MAX_IMAGE: usize = 512;

impl DepthPrecision {
    pub fn new() -> Self {
        DepthPrecision {
            near: 0.1,
            far: 1000.0,
            gap: 0.01,
            bits: 16,
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the eye's and the fighting line's names are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// Whether a label's box (CSS pixels) on the last frame's view covers none of the upper
    /// floor (sampled every half metre across and along it, out to `reach`), which the frame
    /// draws as a mesh.
    fn off_the_floor(&self, reach: f32, rect: crate::draw::layout::Rect) -> bool {
        let Some((camera, size)) = self.view else {
            return true;
        };
        let view_proj = camera.projection(size.x / size.y) * camera.view();
        let along = (2.0 * reach).ceil() as usize;
        (0..=4).all(|i| {
            (0..=along).all(|k| {
                let p = Vec3::new(-1.0 + 0.5 * i as f32, 0.0, -reach * k as f32 / along as f32);
                crate::camera::project_to_canvas(view_proj, size, p)
                    .is_none_or(|c| !(c.cmpgt(rect.min).all() && c.cmplt(rect.max()).all()))
            })
        })
    }

    /// z_near in [0.01, 10] m, z_far in (z_near, 10⁵] m, the gap in [10⁻⁴, 1] m, 16 or 24 bits.
    pub fn set(&mut self, near: f32, far: f32, gap: f32, bits: f32) -> Result<(), String> {
        let near = in_range("z_near", near, 0.01, 10.0)?;
        let far = in_range("z_far", far, 0.02, 1e5)?;
        if far <= near {
            return Err(format!(
                "z_far ({far}) must be greater than z_near ({near})"
            ));
        }
        let gap = in_range("gap", gap, 1e-4, 1.0)?;
        let bits = finite("depth bits", bits)?;
        if bits != 16.0 && bits != 24.0 {
            return Err(format!("depth bits must be 16 or 24, got {bits}"));
        }
        (self.near, self.far, self.gap, self.bits) = (near, far, gap, bits as u32);
        Ok(())
    }

    /// How far apart the two planes are along a line of sight that meets the upper one at view
    /// depth `d`: `d · gap / h` (a grazing ray crosses the gap over a long stretch).
    pub fn separation(&self, d: f32) -> f32 {
        d * self.gap / EYE_HEIGHT
    }

    /// The view depth beyond which one depth step is worth more than the separation:
    /// `d² (f − n) / (f n (2ᵇ − 1)) = d · gap / h`, so `d = gap f n (2ᵇ − 1) / (h (f − n))`.
    pub fn fighting_from(&self) -> f32 {
        self.fighting_from_bits(self.bits)
    }

    /// `(d, step 16 bits, step 24 bits, separation)` in metres, for d from z_near to z_far spaced
    /// evenly on a log scale (the page plots them on log-log axes, where both steps are straight
    /// lines of slope 2 and the separation one of slope 1, so the crossing is easy to read).
    pub fn sample_step(&self, samples: usize) -> Result<Vec<[f32; 4]>, String> {
        check_samples(samples)?;
        let ratio = self.far / self.near;
        Ok((0..samples)
            .map(|k| {
                let d = self.near * ratio.powf(k as f32 / (samples - 1) as f32);
                [
                    d,
                    raster::depth_step(d, self.near, self.far, 16),
                    raster::depth_step(d, self.near, self.far, 24),
                    self.separation(d),
                ]
            })
            .collect())
    }

    /// The fighting distance for `bits` (16 or 24) at the current z_near, z_far and gap.
    pub fn fighting_from_bits(&self, bits: u32) -> f32 {
        let steps = ((1u64 << bits.min(32)) - 1) as f32;
        self.gap * self.far * self.near * steps / (EYE_HEIGHT * (self.far - self.near))
    }

    /// Which plane a depth buffer keeps at a pixel where the planes lie at distances `d_upper`
    /// and `d_lower`: the lower plane is drawn first, the upper one passes the test only if its
    /// stored depth is strictly smaller. `jitter` in `[−½, ½]²` stands for the rasteriser's
    /// rounding of the interpolated depth, a fraction of one step for each plane.
    pub fn upper_wins(&self, d_upper: f32, d_lower: f32, jitter: Vec2) -> bool {
        let steps = ((1u64 << self.bits) - 1) as f64;
        let store = |d: f32, j: f32| {
            let z = raster::ndc_depth_wgpu(d, self.near, self.far) as f64;
            (z * steps + j as f64).round()
        };
        store(d_upper, jitter.x) < store(d_lower, jitter.y)
    }

    /// The camera's view (RGBA bytes, sRGB, row 0 on top), `width × height` pixels, each side at
    /// most [`MAX_IMAGE`]: sky, then the upper plane in red squares where it wins and the lower
    /// plane in blue where the depth buffer lets it through.
    pub fn image(&self, width: usize, height: usize) -> Result<Vec<u8>, String> {
        if !(1..=MAX_IMAGE).contains(&width) || !(1..=MAX_IMAGE).contains(&height) {
            return Err(format!(
                "image sides must be 1 to {MAX_IMAGE} pixels, got {width} × {height}"
            ));
        }
        let tan = (0.5 * IMAGE_FOV).tan();
        let aspect = width as f32 / height as f32;
        let (sin_p, cos_p) = PITCH.sin_cos();
        let mut out = Vec::with_capacity(width * height * 4);
        let srgb = |c: Vec3| {
            let c = palette::css(c);
            let h = |k: usize| u8::from_str_radix(&c[k..k + 2], 16).unwrap_or(0);
            [h(1), h(3), h(5), 255]
        };
        let (sky, clipped) = (srgb(Vec3::new(0.6, 0.75, 0.9)), srgb(Vec3::splat(0.5)));
        let shades = [
            srgb(UPPER_PLANE),
            srgb(UPPER_PLANE * 0.55),
            srgb(LOWER_PLANE),
            srgb(LOWER_PLANE * 0.55),
        ];
        for j in 0..height {
            for i in 0..width {
                let x = (2.0 * (i as f32 + 0.5) / width as f32 - 1.0) * tan * aspect;
                let y = (1.0 - 2.0 * (j as f32 + 0.5) / height as f32) * tan;
                // The view ray (x, y, −1), pitched down: its world height changes by
                // `down` per unit of view depth, so it meets the plane h below the eye at view
                // depth d = h / down.
                let down = sin_p - y * cos_p;
                let forward = cos_p + y * sin_p;
                let px = if down <= 1e-6 {
                    sky
                } else {
                    let d_upper = EYE_HEIGHT / down;
                    let d_lower = (EYE_HEIGHT + self.gap) / down;
                    if d_upper > self.far {
                        clipped
                    } else {
                        let jitter = Vec2::new(hash(i, j, 1), hash(i, j, 2)) - 0.5;
                        let upper = d_lower > self.far || self.upper_wins(d_upper, d_lower, jitter);
                        let d = if upper { d_upper } else { d_lower };
                        let (wx, wz) = (x * d, forward * d);
                        let checker = ((wx.floor() + wz.floor()) as i64).rem_euclid(2) as usize;
                        shades[if upper { 0 } else { 2 } + checker]
                    }
                };
                out.extend(px);
            }
        }
        Ok(out)
    }

    /// How much taller than life the bars of the 3D view are drawn.
    pub const BAR_SCALE: f32 = 40.0;

    /// A side view: the camera, the two planes out to 40 m (or z_far), and every 2 m a bar as tall
    /// as one depth step there ([`Self::BAR_SCALE`] times taller than life, capped at 6 m), orange
    /// where it exceeds the planes' separation along the line of sight, whose height (same scale)
    /// the grey line follows. Returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        let reach = self.far.min(40.0);
        let eye = Vec3::new(0.0, EYE_HEIGHT, 0.0);
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // The least gap between a label and a line or dot: one that touches a line reads as
        // part of it.
        const LINE_MARGIN_PX: f32 = 3.0;
        let slab = |y: f32, color: Vec3, frame: &mut Frame| {
            let model = Mat4::from_translation(Vec3::new(0.0, y - 0.005, -reach / 2.0))
                * Mat4::from_scale(Vec3::new(1.0, 0.005, reach / 2.0));
            frame.mesh(MeshId::CUBE, model, color);
        };
        slab(0.0, UPPER_PLANE, frame);
        slab(-self.gap, LOWER_PLANE, frame);
        frame.marker(eye, 14.0, palette::DARK);
        let (sin_p, cos_p) = PITCH.sin_cos();
        let axis = Vec3::new(0.0, -sin_p, -cos_p);
        let to_ground = EYE_HEIGHT / sin_p;
        frame.stroke(
            &[eye, eye + axis * to_ground.min(reach)],
            palette::GREY,
            crate::draw::StrokeStyle::dashed(1.5, 0.4, 0.3),
        );
        // The top of the tallest green bar (the farthest of equals), which the bars' name sits
        // beside in green; without a green bar, the tallest orange one's, in orange: a green name
        // over orange bars reads as theirs.
        let mut tallest = (Vec3::new(1.1, 0.0, 0.0), palette::ORANGE);
        for k in 1..=(reach / 2.0) as usize {
            let d = 2.0 * k as f32;
            let step = raster::depth_step(d, self.near, self.far, self.bits);
            let color = if step > self.separation(d) {
                palette::ORANGE
            } else {
                palette::GREEN
            };
            let top = Vec3::new(1.1, (step * Self::BAR_SCALE).min(6.0), -d);
            frame.wide_line(Vec3::new(1.1, 0.0, -d), top, color, 4.0);
            frame.marker(top, 9.0, color);
            let (green, was_green) = (color == palette::GREEN, tallest.1 == palette::GREEN);
            if green && !was_green || green == was_green && top.y >= tallest.0.y {
                tallest = (top, color);
            }
        }
        let sep = |d: f32| Vec3::new(1.1, (self.separation(d) * Self::BAR_SCALE).min(6.0), -d);
        frame.wide_line(sep(0.0), sep(reach), palette::GREY, 2.5);
        // Whether a name's box covers none of the floor: one closure for all four names, so
        // that Frame::first_clear_label_by is compiled once for them.
        let off_floor = |rect| self.off_the_floor(reach, rect);
        let from = self.fighting_from();
        if from < reach {
            frame.stroke(
                &[Vec3::new(1.1, 0.0, -from), Vec3::new(1.1, 6.8, -from)],
                palette::ORANGE,
                crate::draw::StrokeStyle::dashed(2.5, 0.3, 0.2),
            );
            // Leftwards of the dashed line's top (to its right the orange bars rise to their
            // dots) at the page's camera; where that is taken (other settings, a slid or zoomed
            // view), the first place round the top that covers no dot, line or floor.
            let top = Vec3::new(1.1, 6.8, -from);
            let first = crate::draw::Label {
                anchor: Vec3::new(1.1, 7.1, -from),
                text: "fighting from here".to_string(),
                color: palette::ORANGE,
                left: true,
                priority: 3,
                offset_px: Vec2::ZERO,
                large: false,
            };
            let mut around =
                Label::around_dot(top, 0.0, -Vec2::Y, &first.text, first.color, 3, 6, 10.0);
            around.insert(0, first);
            frame.first_clear_label_by(view, LINE_MARGIN_PX, around, &off_floor);
        }
        // The eye's name above its dot at the page's camera; where that is taken, the first
        // place round the dot that covers no dot, line, floor or the fighting line's name.
        let first = crate::draw::Label {
            anchor: eye + Vec3::Y * 1.0,
            text: "eye".to_string(),
            color: palette::DARK,
            left: false,
            priority: 2,
            offset_px: Vec2::ZERO,
            large: false,
        };
        let mut around = Label::around_dot(eye, 14.0, -Vec2::Y, "eye", palette::DARK, 2, 6, 10.0);
        around.insert(0, first);
        frame.first_clear_label_by(view, LINE_MARGIN_PX, around, &off_floor);
        // The bars' name at the first place round the tallest bar's top, above first, that covers
        // no dot, line, floor or name placed before; the grey line's likewise round its far
        // (highest) end, else round a point further down the line: the end sits among the
        // tallest bars, and at the canvas's edge when the view is slid or zoomed.
        let text = "one depth step (×40)";
        let around = Label::around_dot(tallest.0, 9.0, -Vec2::Y, text, tallest.1, 1, 6, 10.0);
        frame.first_clear_label_by(view, LINE_MARGIN_PX, around, &off_floor);
        let text = "separation d·gap/h (×40)";
        let mut along = Vec::new();
        for t in [1.0, 0.75, 0.5, 0.25, 0.0] {
            let at = sep(t * reach);
            along.extend(Label::around_dot(at, 2.5, -Vec2::Y, text, palette::GREY, 1, 4, 10.0));
        }
        frame.first_clear_label_by(view, LINE_MARGIN_PX, along, &off_floor);
        frame.keep_box_in_view(Vec3::new(-1.0, -0.1, -reach), Vec3::new(1.6, 7.2, 0.5));
        // A diagram seen from the side: a drag slides it, where an orbit would turn it end-on
        // and stack the bars into one column.
        frame.flat = true;
        // The steps in one notation, three digits each (they span many decades: 1.53e-4 m,
        // 1.53e-2 m, 1.53e2 m), and the ratio to a tenth, as a whole number when it is one.
        let step = |d: f32| format!("{:.2e}", raster::depth_step(d, self.near, self.far, self.bits));
        format!(
            "z_far / z_near = {}. With {} bits, one depth step is worth {} m at 1 m, {} m at 10 m and {} m at \
             z_far. Along a line of sight the floors are d · gap / h apart; the step exceeds that beyond {} m{}.",
            (self.far / self.near * 10.0).round() / 10.0,
            self.bits,
            step(1.0),
            step(10.0),
            step(self.far),
            format_number(from),
            if from > self.far { ", past z_far: no fighting" } else { ": there the floors fight" },
        )
    }
}

/// A fixed pseudo-random number in [0, 1) per pixel and channel (the same every frame).
fn hash(i: usize, j: usize, k: u32) -> f32 {
    let mut h = (i as u32).wrapping_mul(0x9e37_79b1)
        ^ (j as u32).wrapping_mul(0x85eb_ca6b)
        ^ k.wrapping_mul(0xc2b2_ae35);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2c1b_3c6d);
    h ^= h >> 12;
    h = h.wrapping_mul(0x297a_2d39);
    h ^= h >> 15;
    (h >> 8) as f32 / (1u32 << 24) as f32
}

// ---------------------------------------------------------------------------------------------
// Figure 4: normals.

/// Colours of Figure 4.
pub const TRUE_NORMAL: Vec3 = palette::Y_AXIS;
pub const WRONG_NORMAL: Vec3 = palette::X_AXIS;

/// Figure 4: a low-poly sphere, flat-shaded (one normal per face) or smooth (averaged normals
/// per vertex), stretched along x; its normals as arrows, transformed by the normal matrix
/// (green) and, wrongly, by the model matrix (red).
pub struct Normals {
    flat: bool,
    scale_x: f32,
    show_wrong: bool,
    use_exercise: bool,
    runner: Runner,
    positions: Vec<Vec3>,
    indices: Vec<u32>,
    smooth: Vec<Vec3>,
    exercise_note: String,
    /// The vertex the note names where the student's normals differ most, marked in the view.
    wrong_vertex: Option<usize>,
}

impl Default for Normals {
    fn default() -> Self {
        Self::new()
    }
}

impl Normals {
    pub fn new() -> Self {
        let (positions, indices) = uv_sphere_indexed(10, 6);
        let mut smooth = vec![Vec3::ZERO; positions.len()];
        raster::vertex_normals(&positions, &indices, &mut smooth).valid("a valid sphere");
        Normals {
            flat: false,
            scale_x: 3.0,
            show_wrong: true,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            positions,
            indices,
            smooth,
            exercise_note: String::new(),
            wrong_vertex: None,
        }
    }

    pub fn set_flat(&mut self, flat: bool) {
        self.flat = flat;
    }

    /// Stretch along x, 0.2 to 4.
    pub fn set_scale_x(&mut self, s: f32) -> Result<(), String> {
        self.scale_x = in_range("scale x", s, 0.2, 4.0)?;
        Ok(())
    }

    pub fn set_show_wrong(&mut self, on: bool) {
        self.show_wrong = on;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// Uses the student's `vertex_normals` (exercise 0.2) for the smooth mesh; recomputes the
    /// smooth normals and the note. The caller re-uploads [`Self::smooth_mesh`]'s normals.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        let mut reference = vec![Vec3::ZERO; self.positions.len()];
        raster::vertex_normals(&self.positions, &self.indices, &mut reference)
            .valid("a valid sphere");
        self.smooth = reference.clone();
        self.exercise_note.clear();
        self.wrong_vertex = None;
        if !on {
            return;
        }
        let idx: Vec<f32> = self.indices.iter().map(|&i| i as f32).collect();
        match run::vertex_normals(self.runner, self.positions.clone(), idx) {
            Err(f) => self.exercise_note = failure_note("exercise 0.2 vertex_normals", FILE, &f),
            Ok(yours) => {
                let flat_ref: Vec<f32> = reference.iter().flat_map(|v| v.to_array()).collect();
                let flat_yours: Vec<f32> = yours.iter().flat_map(|v| v.to_array()).collect();
                let (ok, note) = compare_note(
                    "vertex_normals",
                    "this sphere",
                    &flat_yours,
                    &flat_ref,
                    1e-3,
                );
                self.exercise_note = if ok {
                    note
                } else {
                    // Say which vertex, not 100 numbers.
                    let worst = (0..reference.len())
                        .max_by(|&a, &b| {
                            let e = |k: usize| {
                                yours
                                    .get(k)
                                    .map_or(f32::INFINITY, |y| (*y - reference[k]).length())
                            };
                            e(a).partial_cmp(&e(b)).unwrap_or(std::cmp::Ordering::Equal)
                        })
                        .unwrap_or(0);
                    self.wrong_vertex = Some(worst);
                    let show = |v: Option<&Vec3>| {
                        v.map_or("missing".to_string(), |v| {
                            format!(
                                "({}, {}, {})",
                                format_number(v.x),
                                format_number(v.y),
                                format_number(v.z)
                            )
                        })
                    };
                    format!(
                        "Your vertex_normals differs on this sphere ({} normals for {} vertices): at vertex {worst} (the orange \
                         dot), yours {}, reference {}.",
                        yours.len(),
                        reference.len(),
                        show(yours.get(worst)),
                        show(reference.get(worst)),
                    )
                };
                if yours.len() == self.smooth.len() && yours.iter().all(|v| v.is_finite()) {
                    self.smooth = yours;
                }
                self.exercise_note += &self.probe_note();
            }
        }
    }

    /// Exercise 0.2 on [`vertex_normal_probes`], beyond the figure's sphere: " It also matches
    /// on …" or " It differs on …" with the first vertex that differs.
    fn probe_note(&self) -> String {
        let mut matching = Vec::new();
        let mut differing = Vec::new();
        for (what, positions, indices) in vertex_normal_probes() {
            let mut reference = vec![Vec3::ZERO; positions.len()];
            raster::vertex_normals(&positions, &indices, &mut reference).valid("a valid mesh");
            let idx: Vec<f32> = indices.iter().map(|&i| i as f32).collect();
            match run::vertex_normals(self.runner, positions, idx) {
                Err(f) => {
                    return format!(" {}", failure_note("exercise 0.2 vertex_normals", FILE, &f))
                }
                Ok(yours) => {
                    let wrong = (0..reference.len()).find(|&k| {
                        yours
                            .get(k)
                            .is_none_or(|y| !y.abs_diff_eq(reference[k], 1e-3))
                    });
                    match wrong {
                        None => matching.push(what),
                        Some(k) => {
                            let show = |v: Option<&Vec3>| {
                                v.map_or("missing".to_string(), |v| {
                                    format!(
                                        "({}, {}, {})",
                                        format_number(v.x),
                                        format_number(v.y),
                                        format_number(v.z)
                                    )
                                })
                            };
                            differing.push(format!(
                                "{what} (vertex {k}: yours {}, reference {})",
                                show(yours.get(k)),
                                show(reference.get(k))
                            ))
                        }
                    }
                }
            }
        }
        if differing.is_empty() {
            format!(" It also matches on {}.", matching.join(", "))
        } else {
            format!(" It differs on {}.", differing.join("; "))
        }
    }

    /// The smooth mesh: shared positions with averaged normals (the student's when used).
    pub fn smooth_mesh(&self) -> MeshData {
        MeshData {
            positions: self.positions.clone(),
            normals: self.smooth.clone(),
            indices: self.indices.clone(),
        }
    }

    /// The flat mesh: every triangle with its own corners and its face normal.
    pub fn flat_mesh(&self) -> MeshData {
        let (positions, normals) =
            raster::flat_shaded(&self.positions, &self.indices).valid("a valid sphere");
        let indices = (0..positions.len() as u32).collect();
        MeshData {
            positions,
            normals,
            indices,
        }
    }

    fn model(&self) -> Mat4 {
        Mat4::from_translation(Vec3::new(0.0, 1.3, 0.0))
            * Mat4::from_scale(Vec3::new(self.scale_x, 1.0, 1.0))
    }

    /// Where each normal starts (object space) and the normal: per face centre when flat, per
    /// vertex when smooth.
    pub fn normals(&self) -> Vec<(Vec3, Vec3)> {
        if self.flat {
            self.indices
                .chunks_exact(3)
                .map(|t| {
                    let [a, b, c] = [t[0], t[1], t[2]].map(|i| self.positions[i as usize]);
                    (
                        (a + b + c) / 3.0,
                        raster::face_normal(a, b, c).normalize_or_zero(),
                    )
                })
                .collect()
        } else {
            self.positions
                .iter()
                .copied()
                .zip(self.smooth.iter().copied())
                .collect()
        }
    }

    /// The largest angle, in degrees, between a normal transformed by the model matrix itself and
    /// the true one (by the normal matrix).
    pub fn worst_wrong_angle_deg(&self) -> f32 {
        let m = self.model();
        let (linear, nm) = (Mat3::from_mat4(m), raster::normal_matrix(m));
        self.normals()
            .iter()
            .map(|&(_, n)| {
                let (a, b) = (
                    (linear * n).normalize_or_zero(),
                    (nm * n).normalize_or_zero(),
                );
                a.dot(b).clamp(-1.0, 1.0).acos() / DEG
            })
            .fold(0.0, f32::max)
    }

    /// Draws the mesh (`flat_id` or `smooth_id`, uploaded by the caller) and the normals.
    pub fn draw(&self, frame: &mut Frame, flat_id: MeshId, smooth_id: MeshId) -> String {
        let m = self.model();
        let (linear, nm) = (Mat3::from_mat4(m), raster::normal_matrix(m));
        frame.grid(12, 0.5);
        frame.mesh(
            if self.flat { flat_id } else { smooth_id },
            m,
            Vec3::splat(0.7),
        );
        let len = 0.5;
        for (p, n) in self.normals() {
            let base = m.transform_point3(p);
            frame.arrow(
                base,
                base + (nm * n).normalize_or_zero() * len,
                TRUE_NORMAL,
                0.1,
            );
            if self.show_wrong && (self.scale_x - 1.0).abs() > 1e-3 {
                frame.arrow(
                    base,
                    base + (linear * n).normalize_or_zero() * len,
                    WRONG_NORMAL,
                    0.1,
                );
            }
        }
        // The stretched sphere with its arrows stays in view at every scale, and no more: its
        // vertices and the tips of both arrows at each (a unit sphere's vertex is its own
        // normal), whichever arrows are shown, so the camera stays put as they change.
        for p in &self.positions {
            let base = m.transform_point3(*p);
            frame.keep_in_view.extend(
                [base, base + (nm * *p).normalize() * len, base + (linear * *p).normalize() * len],
            );
        }
        let mut note = format!(
            "{} shading: {}. Stretched {}× along x. Transformed by M itself, a normal leans up to {}° away \
             from the true one (M⁻¹)ᵀ n.",
            if self.flat { "Flat" } else { "Smooth" },
            if self.flat { "one normal per face" } else { "one averaged normal per vertex" },
            format_number(self.scale_x),
            format_number(self.worst_wrong_angle_deg()),
        );
        if self.use_exercise {
            note += " ";
            note += &self.exercise_note;
        }
        // Over the mesh: a reversed normal points into the sphere, and the vertex may face away.
        if let Some(k) = self.wrong_vertex {
            frame.marker_on_top(m.transform_point3(self.positions[k]), 14.0, palette::ORANGE);
        }
        note
    }
}

/// Meshes on which exercise 0.2 is checked besides the figure's sphere, each chosen where a
/// common mistake shows: `(what it tests, positions, indices)`.
pub fn vertex_normal_probes() -> [(&'static str, Vec<Vec3>, Vec<u32>); 3] {
    let (tetra_positions, tetra_indices) = tetrahedron();
    [
        ("a tetrahedron", tetra_positions, tetra_indices),
        (
            // Two slopes at the same angle, one four times as wide: with each triangle counting
            // once the ridge's normal points straight up; weighted by area it leans.
            "a ridge of one large and one small triangle (each counts once)",
            vec![
                Vec3::ZERO,
                Vec3::Z,
                Vec3::new(2.0, -1.0, 0.5),
                Vec3::new(-0.5, -0.25, 0.5),
            ],
            vec![0, 1, 2, 0, 3, 1],
        ),
        (
            "a vertex no triangle uses and a zero-area triangle",
            vec![
                Vec3::ZERO,
                Vec3::X,
                Vec3::Y,
                Vec3::new(5.0, 5.0, 5.0),
                Vec3::new(2.0, 0.0, 0.0),
            ],
            vec![0, 1, 2, 0, 1, 4],
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// Figure 5: shading.

/// Colours of Figure 5's vectors.
pub mod shading_colors {
    use super::palette;
    use glam::Vec3;
    pub const N: Vec3 = palette::Z_AXIS;
    pub const L: Vec3 = palette::ORANGE;
    pub const V: Vec3 = palette::DARK;
    pub const R: Vec3 = palette::PURPLE;
    pub const H: Vec3 = palette::TEAL;
}

/// Figure 5: a sphere lit by one light; at one fragment the vectors n, l, v and r (Phong) or h
/// (Blinn-Phong); beside it, CPU images of each term and of both models' totals.
///
/// The 3D sphere is shaded on the CPU by the lesson's own model (or, with "use my exercise" and
/// Blinn-Phong, by the student's `blinn_phong` at every vertex) and drawn unlit, so what it shows
/// is exactly the formula on the page, for the same eye as the images: far along +z, where `v`
/// points.
pub struct Shading {
    light: Vec3,
    material: Material,
    model: ShadingModel,
    fragment: Vec3,
    use_exercise: bool,
    runner: Runner,
    sphere: MeshData,
    /// One linear RGBA colour per vertex of `sphere`.
    colors: Vec<glam::Vec4>,
    /// Whether `colors` must be computed again.
    stale: bool,
    /// Why the student's code could not shade the sphere, if it could not.
    sphere_problem: Option<String>,
}

impl Default for Shading {
    fn default() -> Self {
        Self::new()
    }
}

/// A unit direction from an azimuth about +y (0 = towards +z, the images' eye) and an elevation.
fn direction(azimuth_deg: f32, elevation_deg: f32) -> Vec3 {
    let (a, e) = (azimuth_deg * DEG, elevation_deg * DEG);
    Vec3::new(e.cos() * a.sin(), e.sin(), e.cos() * a.cos())
}

/// Where the sphere of Figure 5 stands.
const SPHERE_CENTRE: Vec3 = Vec3::new(0.0, 1.3, 0.0);
/// The tessellation of Figure 5's sphere, 11.25° between vertices: per-vertex shading shows a
/// round highlight at low shininess and a blotch at 128, which the page explains.
pub const SPHERE_SEGMENTS: u32 = 32;
pub const SPHERE_RINGS: u32 = 16;

impl Shading {
    pub fn new() -> Self {
        Shading {
            light: direction(40.0, 35.0),
            material: Material::default(),
            model: ShadingModel::BlinnPhong,
            fragment: direction(30.0, 10.0),
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            sphere: crate::mesh::uv_sphere(1.0, SPHERE_SEGMENTS, SPHERE_RINGS),
            colors: Vec::new(),
            stale: true,
            sphere_problem: None,
        }
    }

    /// The light's direction from azimuth and elevation in degrees (each finite).
    pub fn set_light_deg(&mut self, azimuth: f32, elevation: f32) -> Result<(), String> {
        self.light = direction(
            finite("light azimuth", azimuth)?,
            in_range("light elevation", elevation, -90.0, 90.0)?,
        );
        self.stale = true;
        Ok(())
    }

    /// The light where the reader points on an image, `(u, v) ∈ [0, 1]²`.
    pub fn set_light_from_image(&mut self, u: f32, v: f32) -> Result<(), String> {
        self.light = light_from_image(in_range("u", u, 0.0, 1.0)?, in_range("v", v, 0.0, 1.0)?);
        self.stale = true;
        Ok(())
    }

    /// The light's azimuth and elevation in degrees (to put the sliders where a drag left it).
    pub fn light_deg(&self) -> (f32, f32) {
        let l = self.light;
        (l.x.atan2(l.z) / DEG, l.y.clamp(-1.0, 1.0).asin() / DEG)
    }

    /// The light direction (unit, from the surface to the light).
    pub fn light(&self) -> Vec3 {
        self.light
    }

    /// `k_a, k_d, k_s` in [0, 1] and the exponent in [1, 256].
    pub fn set_material(
        &mut self,
        ka: f32,
        kd: f32,
        ks: f32,
        shininess: f32,
    ) -> Result<(), String> {
        let ambient = in_range("ambient k_a", ka, 0.0, 1.0)?;
        let diffuse = in_range("diffuse k_d", kd, 0.0, 1.0)?;
        let specular = in_range("specular k_s", ks, 0.0, 1.0)?;
        let shininess = in_range("shininess", shininess, 1.0, 256.0)?;
        self.material.ambient = ambient;
        self.material.diffuse = diffuse;
        self.material.specular = specular;
        self.material.shininess = shininess;
        self.stale = true;
        Ok(())
    }

    /// "phong" or "blinn-phong".
    pub fn set_model(&mut self, model: &str) -> Result<(), String> {
        self.model = match model {
            "phong" => ShadingModel::Phong,
            "blinn-phong" => ShadingModel::BlinnPhong,
            _ => {
                return Err(format!(
                    "model must be \"phong\" or \"blinn-phong\", got {model:?}"
                ))
            }
        };
        self.stale = true;
        Ok(())
    }

    /// The fragment whose vectors are drawn: azimuth and elevation on the sphere, in degrees.
    pub fn set_fragment_deg(&mut self, azimuth: f32, elevation: f32) -> Result<(), String> {
        self.fragment = direction(
            finite("fragment azimuth", azimuth)?,
            in_range("fragment elevation", elevation, -90.0, 90.0)?,
        );
        Ok(())
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.stale = true;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.stale = true;
    }

    /// The unit sphere the 3D figure draws (create its GPU mesh from this once).
    pub fn sphere(&self) -> &MeshData {
        &self.sphere
    }

    /// Makes the next [`Shading::shade_sphere`] shade and return the sphere (its GPU copy was
    /// lost).
    pub fn reshade(&mut self) {
        self.stale = true;
    }

    /// Shades every vertex of [`Shading::sphere`] if anything changed since the last call;
    /// returns the sphere and its colours when they changed (to upload), `None` when they did
    /// not.
    pub fn shade_sphere(&mut self) -> Option<(&MeshData, &[glam::Vec4])> {
        if !self.stale {
            return None;
        }
        self.stale = false;
        self.sphere_problem = None;
        let (l, v, m) = (self.light, Self::VIEW, self.material);
        let students = self.use_exercise && self.model == ShadingModel::BlinnPhong;
        let weights = [m.ambient, m.diffuse, m.specular];
        self.colors.clear();
        for &n in &self.sphere.normals {
            let mut color = raster::shade(n, l, v, &m, self.model).total();
            if students && self.sphere_problem.is_none() {
                match run::blinn_phong(self.runner, n, l, v, m.color, weights, m.shininess) {
                    Ok(c) if c.is_finite() => color = c,
                    Ok(c) => {
                        self.sphere_problem = Some(format!(
                            "Your blinn_phong returned a non-finite colour ({c}) at n = {n}; the \
                             sphere uses the reference."
                        ))
                    }
                    Err(f) => {
                        self.sphere_problem =
                            Some(failure_note("exercise 0.3 blinn_phong", FILE, &f))
                    }
                }
            }
            self.colors.push(color.extend(1.0));
        }
        if self.sphere_problem.is_some() {
            // Start again with the reference everywhere: no patchwork of both.
            self.colors.clear();
            self.colors.extend(
                self.sphere
                    .normals
                    .iter()
                    .map(|&n| raster::shade(n, l, v, &m, self.model).total().extend(1.0)),
            );
        }
        Some((&self.sphere, &self.colors))
    }

    /// An image of one term: "ambient", "diffuse", "specular" (of the chosen model), "phong" or
    /// "blinn-phong" (the totals, shaded per pixel), or "gouraud" (the chosen model's total
    /// shaded per vertex of the 3D sphere's grid and interpolated, as the 3D view shows it).
    /// RGBA bytes, `size × size`, size 8 to 512.
    pub fn image(&self, which: &str, size: usize) -> Result<Vec<u8>, String> {
        if !(8..=raster::shading::MAX_IMAGE_SIZE).contains(&size) {
            return Err(format!(
                "image size must be 8 to {}, got {size}",
                raster::shading::MAX_IMAGE_SIZE
            ));
        }
        let (model, term) = match which {
            "ambient" => (self.model, Term::Ambient),
            "diffuse" => (self.model, Term::Diffuse),
            "specular" => (self.model, Term::Specular),
            "phong" => (ShadingModel::Phong, Term::Total),
            "blinn-phong" => (ShadingModel::BlinnPhong, Term::Total),
            "gouraud" => {
                return Ok(raster::shading::gouraud_sphere_image(
                    size,
                    self.light,
                    &self.material,
                    self.model,
                    SPHERE_SEGMENTS,
                    SPHERE_RINGS,
                ))
            }
            _ => return Err(format!("no image named {which:?}")),
        };
        Ok(sphere_image(size, self.light, &self.material, model, term))
    }

    /// The view direction of the fragment: the images' eye is far along +z.
    const VIEW: Vec3 = Vec3::Z;

    /// Draws the sphere (`sphere`: the GPU mesh made from [`Shading::sphere`], coloured by
    /// [`Shading::shade_sphere`]), the light and the vectors at the fragment; returns the note.
    pub fn draw(&self, frame: &mut Frame, sphere: MeshId) -> String {
        use shading_colors::*;
        let (n, l, v) = (self.fragment, self.light, Self::VIEW);
        frame.grid(12, 0.5);
        frame.mesh_unlit_vertex_colors(sphere, Mat4::from_translation(SPHERE_CENTRE));
        let p = SPHERE_CENTRE + n;
        let len = 1.3;
        let head = 0.16;
        // Labels just past each tip; where tips crowd, n and the model's own vector (r or h) keep
        // their place and the light's marker label gives way.
        let tip = |d: Vec3| p + d * (len + 0.12);
        frame.arrow(p, p + n * len, N, head);
        frame.label_with_priority(tip(n), "n", N, 3);
        frame.arrow(p, p + l * len, L, head);
        frame.label_with_priority(tip(l), "l", L, 2);
        frame.arrow(p, p + v * len, V, head);
        frame.label_with_priority(tip(v), "v", V, 2);
        frame.marker(p, 10.0, palette::DARK);
        let lamp = SPHERE_CENTRE + l * 2.6;
        frame.marker(lamp, LAMP_PX, Vec3::new(1.0, 0.8, 0.2));
        // Just above the lamp's dot, a few pixels off it at any zoom.
        frame.label_off_dot(lamp, LAMP_PX, Vec2::new(0.0, -1.0), "light", L, 0);
        let model_vector = match self.model {
            ShadingModel::Phong => (2.0 * n.dot(l) * n - l, R, "r"),
            ShadingModel::BlinnPhong => ((l + v).normalize_or_zero(), H, "h"),
        };
        let (d, color, name) = model_vector;
        frame.arrow(p, p + d * len, color, head);
        frame.label_with_priority(tip(d), name, color, 3);
        // The sphere, the vectors and the light stay in view at any canvas size.
        frame.keep_box_in_view(SPHERE_CENTRE - Vec3::ONE, SPHERE_CENTRE + Vec3::ONE);
        frame
            .keep_in_view
            .extend([p + n * len, p + l * len, p + v * len, p + d * len, lamp]);
        let t = raster::shade(n, l, v, &self.material, self.model);
        let rgb = |c: Vec3| {
            format!(
                "({}, {}, {})",
                format_number(c.x),
                format_number(c.y),
                format_number(c.z)
            )
        };
        let mut note = format!(
            "At the fragment: n·l = {}; ambient {} + diffuse {} + specular {} = {} (linear RGB).",
            format_number(n.dot(l)),
            rgb(t.ambient),
            rgb(t.diffuse),
            format_number(t.specular.x),
            rgb(t.total()),
        );
        if self.use_exercise {
            let verdict = self.exercise_note();
            note += " ";
            note += &verdict;
            note += match (&self.sphere_problem, self.model) {
                // A stub or a panic is reported once, by the verdict.
                (Some(problem), _) if *problem == verdict => String::new(),
                (Some(problem), _) => format!(" {problem}"),
                (None, ShadingModel::BlinnPhong) => {
                    " The sphere is shaded by your blinn_phong at every vertex.".to_string()
                }
                (None, ShadingModel::Phong) => {
                    " The sphere shows the reference Phong (your exercise is Blinn-Phong)."
                        .to_string()
                }
            }
            .as_str();
        }
        note
    }

    /// Compares the student's Blinn-Phong colour (exercise 0.3) with the reference at the marked
    /// fragment and at [`BLINN_PHONG_PROBES`] (the light behind the surface, grazing, in line
    /// with the eye, a low exponent), naming every input where they differ.
    pub fn exercise_note(&self) -> String {
        let m = self.material;
        let weights = [m.ambient, m.diffuse, m.specular];
        let shown = (
            "the marked fragment",
            self.fragment,
            self.light,
            m.shininess,
        );
        let mut probes = Vec::new();
        for (at, n, l, shininess) in std::iter::once(shown).chain(BLINN_PHONG_PROBES) {
            let (n, l) = (n.normalize(), l.normalize());
            let v = Self::VIEW;
            let yours = match run::blinn_phong(self.runner, n, l, v, m.color, weights, shininess) {
                Ok(c) => c,
                Err(f) => return failure_note("exercise 0.3 blinn_phong", FILE, &f),
            };
            let reference = raster::blinn_phong(n, l, v, &material(m.color, weights, shininess));
            probes.push(super::curves::Probe {
                at: at.to_string(),
                yours: yours.to_array().to_vec(),
                reference: reference.to_array().to_vec(),
            });
        }
        super::curves::probe_note("blinn_phong", &probes, TOLERANCE).1
    }
}

/// Where exercise 0.3 is checked besides the marked fragment (the eye along +z, the figure's
/// material): `(what it tests, n, l, shininess)`.
pub const BLINN_PHONG_PROBES: [(&str, Vec3, Vec3, f32); 4] = [
    (
        "a light just behind the surface (n·l < 0), shininess 2",
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(0.9, 0.0, -0.2),
        2.0,
    ),
    (
        "a grazing light",
        Vec3::new(0.0, 0.6, 0.8),
        Vec3::new(0.0, 1.0, -0.7),
        32.0,
    ),
    (
        "the light in line with the eye (h = n)",
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(0.0, 0.0, 1.0),
        64.0,
    ),
    (
        "shininess 1, an oblique light",
        Vec3::new(0.6, 0.0, 0.8),
        Vec3::new(-0.5, 0.5, 0.7),
        1.0,
    ),
];
