//! Lesson 04, "Rigid motions": one frame moved three ways between two keys (with a "third, three
//! times" check of the screw motion), and an affine key pair (scale and shear) interpolated
//! naively vs through polar decomposition. Natively testable; `web::rigid` wraps these.

use super::curves::{probe_note, Probe};
use super::rotations::{draw_plane, plane_parts};
use super::{
    failure_note, format_number, in_range, palette, rotation_problem, unit_quat_problem, Frame,
    MeshId, Runner, DEFAULT_RUNNER,
};
use crate::exercises::run;
use crate::rigid::{DualQuat, ScrewInterpolator};
use crate::rotation::{self, check_quat, quat_from_mat3, slerp, AffineKey, AxisAngle};
use crate::Valid;
use glam::{Mat3, Mat4, Quat, Vec3};

const DEG: f32 = std::f32::consts::PI / 180.0;
const FILE: &str = "src/exercises/rotations.rs";
const TOLERANCE: f32 = 1e-4;
/// The nose of the aeroplane, in its own frame.
pub const TIP: Vec3 = Vec3::new(0.55, 0.0, 0.0);
/// A speed sample's round-off, in `ε |p| / h` ([`RigidMotion::sample_speed`]): the screw's,
/// the noisiest, reaches about 6 (over 2,000 random keys).
pub const SPEED_ROUND_OFF: f32 = 16.0;
/// Equal steps of t marked on each nose path.
const TICKS: usize = 12;
/// How far above a key its name is put, metres: past the aeroplane drawn there.
pub const KEY_LABEL_M: f32 = 0.55;

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Method {
    LerpSlerp,
    DualQuatNlerp,
    Screw,
}

/// Each method with its colour; the page's words use `c-orange`, `c-y-axis`, `c-z-axis`.
pub const METHODS: [(Method, Vec3); 3] = [
    (Method::LerpSlerp, palette::ORANGE),
    (Method::DualQuatNlerp, palette::Y_AXIS),
    (Method::Screw, palette::Z_AXIS),
];
/// A name for [`RigidMotion::place_names`]: the point it names (an aeroplane's centre, the
/// screw axis's end), its text, its colour and the side of the point it prefers, on screen.
type Name = (Vec3, String, Vec3, glam::Vec2);

/// Each method's name on its moving aeroplane, in the order of [`Method`].
pub const METHOD_NAMES: [&str; 3] = ["lerp + slerp", "blend", "screw"];
pub const SCREW_AXIS: Vec3 = palette::PURPLE;
/// Width of the screw's aeroplane's outline (CSS pixels), drawn instead of its boxes when the
/// blend's aeroplane is shown too: the two stay within 0.18 m and 4.5° of each other at the
/// defaults and meet at the keys and half-way ([`RigidMotion::coincides_with_screw`]), so one
/// solid aeroplane would hide the other; the blend's solid green shows inside the blue edges.
pub const SCREW_OUTLINE_PX: f32 = 2.5;
/// The thirds' aeroplanes' size, of a moving one's: the screw's thirds stand where its moving
/// aeroplane passes at t = 1/3 and 2/3, and the lerp + slerp ones close together, so a smaller
/// ghost shows inside or beside the full-size aeroplane, not as one knot with it.
pub const THIRD_SIZE: f32 = 0.5;

/// The figures' physical range: key translations within ±`MAX_TRANSLATION_M` metres on each axis,
/// angles within ±`MAX_ANGLE_DEG`, axis, quaternion and matrix entries, scales and shears within
/// ±`MAX_COMPONENT`. Squares and products of these stay far from `f32`'s overflow, so every
/// normalisation, determinant and speed derived from a key is finite.
pub const MAX_TRANSLATION_M: f32 = 100.0;
/// See [`MAX_TRANSLATION_M`].
pub const MAX_ANGLE_DEG: f32 = 3600.0;
/// See [`MAX_TRANSLATION_M`].
pub const MAX_COMPONENT: f32 = 1e4;

/// Each of `v`'s components in `[-limit, limit]`, else an error naming `name`'s range.
fn check_vec(name: &str, v: Vec3, limit: f32) -> Result<Vec3, String> {
    Ok(Vec3::new(
        in_range(&format!("{name} x"), v.x, -limit, limit)?,
        in_range(&format!("{name} y"), v.y, -limit, limit)?,
        in_range(&format!("{name} z"), v.z, -limit, limit)?,
    ))
}

/// Figure 1: a frame moving from key A to key B by translation lerp + slerp, by dual quaternion
/// linear blending and by screw interpolation, with the paths of its origin and nose and the
/// screw axis of the motion from A to B. One method can be shown alone (`show`), and the screw
/// motion's "a third, three times" can be drawn (`thirds`).
pub struct RigidMotion {
    /// Key A and key B: the aeroplane's poses (its own origin at the middle of its body).
    start: DualQuat,
    end: DualQuat,
    /// The point of the aeroplane (its own coordinates) whose frame is interpolated: the keys
    /// become `A T(pivot)` and `B T(pivot)`, and the result is moved back by `T(−pivot)`.
    pivot: Vec3,
    /// The screw interpolation of the pivot's keys.
    screw: ScrewInterpolator,
    /// `None`: all three; `Some(m)`: only `m`.
    solo: Option<Method>,
    thirds: bool,
    use_exercise: bool,
    runner: Runner,
    path: Vec<Vec3>,
    /// The camera and canvas size (CSS pixels) of the last frame, which the thirds' names are
    /// placed for.
    view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
    /// Scratch: points of the aeroplanes' parts on the canvas (CSS pixels), on that view.
    parts_px: Vec<glam::Vec2>,
    /// Scratch: the boxes of the aeroplane drawn as an outline this frame, which names keep off
    /// as they keep off the solid ones.
    outlined: Vec<Mat4>,
}

impl Default for RigidMotion {
    fn default() -> Self {
        Self::new()
    }
}

impl RigidMotion {
    pub fn new() -> Self {
        let start = DualQuat::from_rotation_translation(Quat::IDENTITY, Vec3::new(-1.5, 0.6, 0.0));
        let end = DualQuat::from_rotation_translation(
            Quat::from_axis_angle(Vec3::new(0.2, 1.0, 0.3).normalize(), 150.0 * DEG),
            Vec3::new(1.5, 1.4, 0.3),
        );
        RigidMotion {
            start,
            end,
            pivot: Vec3::ZERO,
            screw: ScrewInterpolator::new(start, end),
            solo: None,
            thirds: false,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            path: Vec::with_capacity(65),
            view: None,
            parts_px: Vec::new(),
            outlined: Vec::new(),
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the thirds' names are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    /// The last frame's view matrix and canvas size (CSS pixels), once drawn.
    fn view_proj(&self) -> Option<(Mat4, glam::Vec2)> {
        let (camera, size) = self.view?;
        Some((camera.projection(size.x / size.y) * camera.view(), size))
    }

    fn set_end_dq(&mut self, end: DualQuat) {
        self.end = end;
        self.refresh_screw();
    }

    fn refresh_screw(&mut self) {
        let (a, b) = self.pivot_keys();
        self.screw = ScrewInterpolator::new(a, b);
    }

    /// The keys of the pivot's frame: `A T(pivot)` and `B T(pivot)`.
    fn pivot_keys(&self) -> (DualQuat, DualQuat) {
        let shift = DualQuat::from_translation(self.pivot);
        (self.start * shift, self.end * shift)
    }

    /// The farthest the pivot may sit from the aeroplane's middle, in metres on each axis.
    pub const MAX_PIVOT_M: f32 = 3.0;

    /// Sets the point of the aeroplane (in its own coordinates, metres) whose frame is
    /// interpolated. lerp + slerp moves that point on a straight line, so its in-betweens
    /// depend on it; the two dual quaternion methods do not.
    pub fn set_pivot(&mut self, pivot: Vec3) -> Result<(), String> {
        self.pivot = check_vec("pivot", pivot, Self::MAX_PIVOT_M)?;
        self.refresh_screw();
        Ok(())
    }

    /// Key B: rotation by `angle_deg` about `axis` (any non-zero direction), then `translation`.
    pub fn set_end(&mut self, axis: Vec3, angle_deg: f32, translation: Vec3) -> Result<(), String> {
        let angle = in_range("angle", angle_deg, -MAX_ANGLE_DEG, MAX_ANGLE_DEG)? * DEG;
        let axis = check_vec("axis", axis, MAX_COMPONENT)?;
        let r = AxisAngle::new(axis, angle).map_err(|e| e.to_string())?;
        let t = check_translation(translation)?;
        self.set_end_dq(DualQuat::from_rotation_translation(r.to_quat(), t));
        Ok(())
    }

    /// Key B from a quaternion (normalised; zero or NaN rejected) and a translation.
    pub fn set_end_quat(&mut self, q: Quat, translation: Vec3) -> Result<(), String> {
        let limit = MAX_COMPONENT;
        if !q.is_finite() || glam::Vec4::from(q).abs().max_element() > limit {
            return Err(format!(
                "the quaternion's components must lie in [-{limit}, {limit}], got ({}, {}, {}, {})",
                q.x, q.y, q.z, q.w
            ));
        }
        let q = check_quat(q).map_err(|e| e.to_string())?;
        let t = check_translation(translation)?;
        self.set_end_dq(DualQuat::from_rotation_translation(q, t));
        Ok(())
    }

    /// Key B from a rigid 4×4 matrix; a scaled, sheared or mirroring one is rejected.
    pub fn set_end_matrix(&mut self, m: Mat4) -> Result<(), String> {
        self.set_end_dq(DualQuat::from_mat4(m).map_err(|e| e.to_string())?);
        Ok(())
    }

    /// What to show: 0 = all three, 1 = lerp + slerp, 2 = dual quaternion blend, 3 = screw.
    pub fn set_show(&mut self, which: u32) -> Result<(), String> {
        self.solo = match which {
            0 => None,
            1..=3 => Some(METHODS[which as usize - 1].0),
            _ => return Err(format!("show must be 0 (all), 1, 2 or 3, got {which}")),
        };
        Ok(())
    }

    /// Draws the screw motion's third `S = q(1/3) A⁻¹` applied to A once, twice and three times
    /// (and the same for lerp + slerp, which misses B).
    pub fn set_thirds(&mut self, on: bool) {
        self.thirds = on;
    }

    /// The green frame's nose is moved by the student's `dual_quat_apply` (exercise 4.1).
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// The screw axis of the motion from A to B, with its point moved to where the axis passes
    /// closest to the middle of the keys' origins (the core gives the point closest to the world
    /// origin, which may lie far from both keys). With no turn the motion is a pure slide, and
    /// every line along it is an axis: the one through that middle point. A half turn about `n`
    /// is the same motion as a half turn about `−n`; of the two, the one that slides forwards
    /// (a positive slide) is given.
    pub fn screw_axis(&self) -> crate::rigid::ScrewAxis {
        let mut axis = (self.end * self.start.conjugate()).screw_axis();
        let middle = (self.start.translation() + self.end.translation()) * 0.5;
        if axis.angle_rad < 1e-4 {
            let slide = self.end.translation() - self.start.translation();
            if let Some(direction) = slide.try_normalize() {
                axis.direction = direction;
                axis.displacement = slide.length();
            }
            axis.point = middle;
        } else {
            axis.point += axis.direction * axis.direction.dot(middle - axis.point);
            if (axis.angle_rad - std::f32::consts::PI).abs() < 1e-3 && axis.displacement < 0.0 {
                axis.direction = -axis.direction;
                axis.displacement = -axis.displacement;
            }
        }
        axis
    }

    fn shown(&self, method: Method) -> bool {
        self.solo.is_none_or(|m| m == method)
    }

    /// Draws the frames at `t ∈ [0, 1]`; returns the note (the thirds check, the exercise check).
    pub fn draw(&mut self, frame: &mut Frame, t: f32) -> Result<String, String> {
        let t = in_range("t", t, 0.0, 1.0)?;
        frame.grid(12, 0.5);
        // The screw axis: the line the relative motion B A⁻¹ turns about and slides along.
        let axis = self.screw_axis();
        let (a, b) = (
            axis.point - axis.direction * 2.0,
            axis.point + axis.direction * 2.0,
        );
        // In pieces, so that a label placed clear of the frame's strokes (sampled along each
        // piece) is clear of the whole axis.
        let pieces: [Vec3; 9] = std::array::from_fn(|k| a.lerp(b, k as f32 / 8.0));
        frame.wide_polyline(&pieces, SCREW_AXIS, 3.0);
        // Its name goes past its end on the last frame's view (placed with the other names).
        let toward = self.view_proj().map_or(glam::Vec2::X, |(vp, size)| {
            let at = |p| crate::camera::project_to_canvas(vp, size, p).unwrap_or_default();
            at(b) - at(a)
        });
        let axis_name = (b, "screw axis".to_string(), SCREW_AXIS, toward);
        frame.keep_box_in_view(Vec3::new(-2.6, 0.0, -1.2), Vec3::new(2.6, 2.4, 1.2));
        // Each key's name just above its axes' origin, past the plane there (its parts reach
        // 0.56 m from its centre), a few pixels over that point at any zoom, so the name sits
        // on the key it names; placed first with the other names, so that it moves off a third's
        // aeroplane drawn there.
        let mut names = Vec::new();
        for (key, name) in [(self.start, "A"), (self.end, "B")] {
            // Over the aeroplanes, which start and end on the keys and would hide them.
            frame.axes_on_top(key.to_mat4(), 0.5);
            let anchor = key.translation() + Vec3::Y * KEY_LABEL_M;
            names.push((anchor, name.to_string(), palette::KEY, -glam::Vec2::Y));
        }
        // Each moving plane's own axes only when it is shown alone: with all three shown they
        // would pile up on the keys' axes where the planes start and end together.
        let own_axes = self.solo.is_some();
        let below = glam::Vec2::Y;
        let student = self.use_exercise;
        let mut planes = Vec::new();
        for (method, color) in METHODS {
            if !self.shown(method) {
                continue;
            }
            // The screw's paths are drawn wide and the blend's narrow on top, in that order: the
            // two methods travel the same helix, and both stay visible where they coincide.
            let width = match method {
                Method::Screw => 6.0,
                Method::DualQuatNlerp => 2.5,
                Method::LerpSlerp => 3.0,
            };
            for (local, shade) in [(self.pivot, 0.6), (TIP, 1.0)] {
                self.path.clear();
                for k in 0..=64 {
                    let s = k as f32 / 64.0;
                    self.path.push(self.point(method, s, local, student));
                }
                frame.wide_polyline(&self.path, color * shade, width);
            }
            // Equal steps of t on the nose's path of the two methods that share the helix:
            // spread where the method is fast.
            if method != Method::LerpSlerp {
                self.path.clear();
                for k in 0..=TICKS {
                    let s = k as f32 / TICKS as f32;
                    self.path.push(self.point(method, s, TIP, student));
                }
                frame.ticks(&self.path, 10.0, color);
            }
            let m = self.motion(method, t);
            let (r, p) = m.to_rotation_translation();
            // With the blend's shown too, the screw's plane is an outline (SCREW_OUTLINE_PX).
            if method == Method::Screw && self.shown(Method::DualQuatNlerp) {
                let edges = crate::draw::StrokeStyle::solid(SCREW_OUTLINE_PX);
                for (part, _) in plane_parts(p, Mat3::from_quat(r), color, 1.0) {
                    wire_cube(frame, part, color, edges);
                    self.outlined.push(part);
                }
            } else {
                draw_plane(frame, p, Mat3::from_quat(r), color, 1.0);
            }
            if own_axes {
                frame.axes(m.to_mat4() * Mat4::from_translation(self.pivot), 0.45);
            }
            frame.marker(m.transform_point(self.pivot), crate::draw::DOT_PX, color);
            // Each moving plane is named: the planes travel close together, and the blend's and
            // the screw's meet at the keys and half-way.
            // With all three shown, each name leaves the clump its own way (lerp + slerp above,
            // the blend to the right, the screw to the left), so that the three do not stack
            // under it; the page's leader runs from each name to its own plane's dot.
            let toward = match (self.solo, method) {
                (Some(_), _) => below,
                (None, Method::LerpSlerp) => -below,
                (None, Method::DualQuatNlerp) => glam::Vec2::X,
                (None, Method::Screw) => -glam::Vec2::X,
            };
            planes.push((p, METHOD_NAMES[method as usize].to_string(), color, toward));
        }
        let mut notes = Vec::new();
        // The thirds' names are placed after the keys', then the axis's, and the moving planes'
        // keep off them.
        if self.thirds {
            notes.push(self.draw_thirds(frame, &mut names));
        }
        names.push(axis_name);
        names.extend(planes);
        self.place_names(frame, names);
        if self.use_exercise {
            notes.push(self.exercise_note(t));
        }
        Ok(notes.join(" "))
    }

    /// Whether dual quaternion blending and the screw place the plane at `t` within 2 cm and
    /// 2° of each other (as at the keys and half-way), so that one plane would hide the other.
    pub fn coincides_with_screw(&self, t: f32) -> bool {
        let blend = self.motion(Method::DualQuatNlerp, t);
        let screw = self.motion(Method::Screw, t);
        let (rb, pb) = blend.to_rotation_translation();
        let (rs, ps) = screw.to_rotation_translation();
        pb.distance(ps) < 0.02 && rotation::angle_between(rb, rs) < 2.0 * DEG
    }

    /// The screw parameter `s` at which the screw motion is where dual quaternion blending is at
    /// `t`: the share of the whole turn the blend has made (of the whole slide, with no turn).
    /// The blend of two keys stays on the screw's helix, so `screw(s(t)) = blend(t)`; only the
    /// timing differs.
    pub fn screw_time_of_blend(&self, t: f32) -> f32 {
        let (a, b) = self.pivot_keys();
        let blend = DualQuat::nlerp(a, b, t);
        let total = rotation::angle_between(a.real, b.real);
        if total > 1e-3 {
            rotation::angle_between(a.real, blend.real) / total
        } else {
            let (pa, pb) = (a.translation(), b.translation());
            let slide = pb - pa;
            if slide.length_squared() > 1e-12 {
                (blend.translation() - pa).dot(slide) / slide.length_squared()
            } else {
                t
            }
        }
    }

    /// How far dual quaternion blending is along the screw axis past the screw at the same turn,
    /// metres, at `t`, positive in the direction of the whole slide. The blend's motion from A,
    /// `blend(t) A⁻¹`, turns about the screw axis and slides along it (the two share the helix's
    /// line, not its pitch), so it moves a point of the axis by its slide; the screw at the same
    /// turn, `s(t)` ([`RigidMotion::screw_time_of_blend`]), slides `s(t)` of the whole way.
    pub fn blend_lead_m(&self, t: f32) -> f32 {
        let axis = self.screw_axis();
        let (a, b) = self.pivot_keys();
        let moved = (DualQuat::nlerp(a, b, t) * a.conjugate()).transform_point(axis.point);
        let slide = (moved - axis.point).dot(axis.direction);
        (slide - self.screw_time_of_blend(t) * axis.displacement) * axis.displacement.signum()
    }

    /// The largest [`RigidMotion::blend_lead_m`] over `t`, either way (metres), sampled at 64
    /// steps.
    pub fn largest_blend_lead_m(&self) -> f32 {
        (0..=64).fold(0.0, |m, k| m.max(self.blend_lead_m(k as f32 / 64.0).abs()))
    }

    /// Distance travelled by the nose since t = 0 (metres), sampled: `(t, lerp + slerp, blend,
    /// screw)`. The blend and the screw end at the same distance (one helix); lerp + slerp
    /// takes another path.
    pub fn sample_distance(&self, samples: usize) -> Result<Vec<[f32; 4]>, String> {
        super::check_samples(samples)?;
        // Each interval is cut into `FINE` steps so the distance is the length of the curve.
        const FINE: usize = 16;
        let mut rows = Vec::with_capacity(samples);
        let mut travelled = [0.0f32; 3];
        let mut last = METHODS.map(|(m, _)| self.point(m, 0.0, TIP, false));
        rows.push([0.0, 0.0, 0.0, 0.0]);
        let steps = (samples - 1) * FINE;
        for k in 1..=steps {
            let t = k as f32 / steps as f32;
            for (i, (method, _)) in METHODS.iter().enumerate() {
                let p = self.point(*method, t, TIP, false);
                travelled[i] += p.distance(last[i]);
                last[i] = p;
            }
            if k % FINE == 0 {
                rows.push([t, travelled[0], travelled[1], travelled[2]]);
            }
        }
        Ok(rows)
    }

    /// `step³ A` vs `B`, where `step = q(1/3) A⁻¹` is the method's first third as a motion.
    pub fn third_three_times(&self, method: Method) -> (DualQuat, f32) {
        let step = self.motion(method, 1.0 / 3.0) * self.start.conjugate();
        let landed = step * step * step * self.start;
        let miss = (landed.transform_point(Vec3::ZERO) - self.end.transform_point(Vec3::ZERO))
            .length()
            .max((landed.transform_point(TIP) - self.end.transform_point(TIP)).length());
        (landed, miss)
    }

    /// Draws the thirds (see [`RigidMotion::set_thirds`]) after the rest of the figure, adds
    /// their names to `names` (placed by [`RigidMotion::place_names`]); returns the note.
    fn draw_thirds(&mut self, frame: &mut Frame, names: &mut Vec<Name>) -> String {
        let mut said = Vec::new();
        for (method, color, name) in [
            (Method::Screw, palette::Z_AXIS, "screw"),
            (Method::LerpSlerp, palette::ORANGE, "lerp + slerp"),
        ] {
            if !self.shown(method) {
                continue;
            }
            let step = self.motion(method, 1.0 / 3.0) * self.start.conjugate();
            let mut f = self.start;
            for k in 1..=3 {
                f = step * f;
                let (r, p) = f.to_rotation_translation();
                draw_plane(
                    frame,
                    p,
                    Mat3::from_quat(r),
                    color * 0.5 + Vec3::splat(0.4),
                    THIRD_SIZE,
                );
                // The screw's third lands on B, which "B" names.
                if method == Method::LerpSlerp || k < 3 {
                    names.push((p, format!("{k}/3"), color, glam::Vec2::Y));
                }
            }
            let (_, miss) = self.third_three_times(method);
            let result = if miss < 1e-3 {
                format!("lands on B (off by {} m, round-off)", format_number(miss))
            } else {
                format!("misses B by {} m", format_number(miss))
            };
            said.push(format!(
                "{name}: its first third, applied three times to A, {result}"
            ));
        }
        if said.is_empty() {
            return "A third, three times: show the screw or lerp + slerp to see it.".into();
        }
        format!("{}.", said.join("; "))
    }

    /// Adds each of `names` at the first place round its point, on the side it prefers first,
    /// on the last frame's view, clear by a few pixels of every path, tick, axis and name and of
    /// every aeroplane: of the points of a 5 × 5 × 5 lattice through each of their boxes.
    fn place_names(&mut self, frame: &mut Frame, names: Vec<Name>) {
        let view = self.view_proj();
        self.parts_px.clear();
        if let Some((view_proj, size)) = view {
            let models = frame.meshes.iter().map(|m| m.model);
            for model in models.chain(self.outlined.drain(..)) {
                self.parts_px.extend((0..125).filter_map(|i| {
                    let c = |k: i32| (k % 5) as f32 * 0.5 - 1.0;
                    let p = model.transform_point3(Vec3::new(c(i), c(i / 5), c(i / 25)));
                    crate::camera::project_to_canvas(view_proj, size, p)
                }));
            }
        }
        self.outlined.clear();
        for (p, text, color, toward) in names {
            let around = crate::draw::Label::around_dot(p, 0.0, toward, &text, color, 0, 16, 6.0);
            let parts = &self.parts_px;
            frame.first_clear_label_by(view, 3.0, around, |rect| {
                parts.iter().all(|&q| rect.nearest(q).distance(q) > 3.0)
            });
        }
    }

    /// Compares the student's `dual_quat_apply` with the reference on the green frame's motion
    /// at `t` and its nose, and at probe inputs ([`dual_quat_probes`]); checks that the rotation
    /// part is a unit quaternion.
    pub fn exercise_note(&self, t: f32) -> String {
        let (r, p) = self
            .motion(Method::DualQuatNlerp, t)
            .to_rotation_translation();
        let shown = (
            format!("t = {} (the green frame's nose)", format_number(t)),
            (r, p, TIP),
        );
        let mut probes = Vec::new();
        let mut shown_real = Quat::IDENTITY;
        for (at, (r, p, point)) in
            std::iter::once(shown).chain(dual_quat_probes(self.start, self.end))
        {
            let (dq, moved) = match run::dual_quat_apply(self.runner, r, p, point) {
                Ok(answer) => answer,
                Err(f) => return failure_note("exercise 4.1 dual_quat_apply", FILE, &f),
            };
            if probes.is_empty() {
                shown_real = dq.real;
            }
            let ref_dq = DualQuat::from_rotation_translation(r, p);
            // q and −q are one motion: compare with the closer sign.
            let s = if dq.real.dot(ref_dq.real) < 0.0 {
                -1.0
            } else {
                1.0
            };
            let flat = |q: DualQuat, v: Vec3| {
                let mut out = q.real.to_array().to_vec();
                out.extend(q.dual.to_array());
                out.extend(v.to_array());
                out
            };
            probes.push(Probe {
                at,
                yours: flat(
                    DualQuat {
                        real: dq.real * s,
                        dual: dq.dual * s,
                    },
                    moved,
                ),
                reference: flat(ref_dq, ref_dq.transform_point(point)),
            });
        }
        let (_, mut note) = probe_note("dual_quat_apply", &probes, TOLERANCE);
        // Eleven numbers per answer say little by themselves: name the part that differs at the
        // first input where the answer is wrong.
        let close = |a: &[f32], b: &[f32]| {
            a.iter()
                .zip(b)
                .all(|(x, y)| (x - y).abs() <= TOLERANCE * (1.0 + y.abs()))
        };
        if let Some(p) = probes.iter().find(|p| !close(&p.yours, &p.reference)) {
            let (q_yours, point_yours) = p.yours.split_at(8);
            let (q_reference, point_reference) = p.reference.split_at(8);
            note += if !close(q_yours, q_reference) {
                " Each answer is q's real part (x, y, z, w), its dual part (x, y, z, w), then the \
                 moved point: your q itself differs (d = ½ (t, 0) r)."
            } else if !close(point_yours, point_reference) {
                " Each answer is q's real part (x, y, z, w), its dual part (x, y, z, w), then the \
                 moved point: your q is right and the moved point is not (p' = r p r* + t, with \
                 t = 2 d r*)."
            } else {
                ""
            };
        }
        if let Some(problem) = unit_quat_problem(shown_real, 1e-3) {
            note += &format!(" Its real part: {problem}.");
        }
        note
    }

    /// The aeroplane's pose by `method` at `t`, always the reference: the pivot's frame is
    /// interpolated between `A T(pivot)` and `B T(pivot)`, then moved back by `T(−pivot)`.
    pub fn motion(&self, method: Method, t: f32) -> DualQuat {
        let (a, b) = self.pivot_keys();
        let pivot_frame = match method {
            Method::LerpSlerp => {
                let (ra, pa) = a.to_rotation_translation();
                let (rb, pb) = b.to_rotation_translation();
                DualQuat::from_rotation_translation(slerp(ra, rb, t), pa.lerp(pb, t))
            }
            Method::DualQuatNlerp => DualQuat::nlerp(a, b, t),
            Method::Screw => self.screw.sample(t),
        };
        pivot_frame * DualQuat::from_translation(-self.pivot)
    }

    /// Where `local` (a point of the frame) is at `t`. With `student`, the green frame's points
    /// are moved by the student's `dual_quat_apply`, falling back to the reference.
    pub fn point(&self, method: Method, t: f32, local: Vec3, student: bool) -> Vec3 {
        let m = self.motion(method, t);
        if student && method == Method::DualQuatNlerp {
            let (r, p) = m.to_rotation_translation();
            if let Ok((_, moved)) = run::dual_quat_apply(self.runner, r, p, local) {
                if moved.is_finite() {
                    return moved;
                }
            }
        }
        m.transform_point(local)
    }

    /// Speed of the frame's nose (metres per unit of t): `(t, lerp+slerp, dlb, screw)`, each the
    /// chord over `[t − h, t + h]`, `h = 10⁻²` (the window slid inside `[0, 1]` at the ends), so
    /// a constant speed gives the same chord everywhere. Each chord carries the round-off of two
    /// `f32` positions, a few `ε |p| / h`: a method whose samples spread by less than
    /// [`SPEED_ROUND_OFF`] of those moves at constant speed, and every sample is given as their
    /// mean, since an autoscaled plot would draw the round-off as one-pixel steps.
    pub fn sample_speed(&self, samples: usize) -> Result<Vec<[f32; 4]>, String> {
        super::check_samples(samples)?;
        let h = 1e-2;
        let mut largest_p: f32 = 0.0;
        let mut rows: Vec<[f32; 4]> = (0..samples)
            .map(|k| {
                let t = k as f32 / (samples - 1) as f32;
                let t0 = (t - h).clamp(0.0, 1.0 - 2.0 * h);
                let mut row = [t; 4];
                for (i, (method, _)) in METHODS.iter().enumerate() {
                    let (p0, p1) = (
                        self.point(*method, t0, TIP, false),
                        self.point(*method, t0 + 2.0 * h, TIP, false),
                    );
                    largest_p = largest_p.max(p0.length()).max(p1.length());
                    row[i + 1] = (p1 - p0).length() / (2.0 * h);
                }
                row
            })
            .collect();
        let round_off = SPEED_ROUND_OFF * f32::EPSILON * largest_p / h;
        for i in 1..4 {
            let (lo, hi, sum) = rows
                .iter()
                .fold((f32::MAX, f32::MIN, 0.0), |(lo, hi, sum), r| {
                    (lo.min(r[i]), hi.max(r[i]), sum + r[i])
                });
            if hi - lo <= round_off {
                let mean = sum / samples as f32;
                rows.iter_mut().for_each(|r| r[i] = mean);
            }
        }
        Ok(rows)
    }
}

/// Where the student's 4.1 is checked besides the figure's input: `(what the note calls it,
/// (rotation, translation, point))`. A pure slide (the dual part alone), a quarter turn about z
/// with no slide (the rotation of the point alone), a half turn (w = 0), and both keys.
pub fn dual_quat_probes(a: DualQuat, b: DualQuat) -> Vec<(String, (Quat, Vec3, Vec3))> {
    let (ra, pa) = a.to_rotation_translation();
    let (rb, pb) = b.to_rotation_translation();
    vec![
        (
            "a slide by (1, 2, 3) m, no turn".into(),
            (
                Quat::IDENTITY,
                Vec3::new(1.0, 2.0, 3.0),
                Vec3::new(0.5, 0.0, 0.0),
            ),
        ),
        (
            "a quarter turn about z, no slide".into(),
            (
                Quat::from_rotation_z(90.0 * DEG),
                Vec3::ZERO,
                Vec3::new(1.0, 0.0, 0.0),
            ),
        ),
        (
            "a half turn about y and a slide".into(),
            (
                Quat::from_rotation_y(180.0 * DEG),
                Vec3::new(0.0, 1.0, 0.0),
                Vec3::new(0.3, 0.2, 0.1),
            ),
        ),
        ("key A's nose".into(), (ra, pa, TIP)),
        ("key B's nose".into(), (rb, pb, TIP)),
    ]
}

fn check_translation(t: Vec3) -> Result<Vec3, String> {
    let m = MAX_TRANSLATION_M;
    Ok(Vec3::new(
        in_range("tx", t.x, -m, m)?,
        in_range("ty", t.y, -m, m)?,
        in_range("tz", t.z, -m, m)?,
    ))
}

/// The 12 edges of the cube `[-1, 1]³` transformed by `m`, in `style`.
fn wire_cube(frame: &mut Frame, m: Mat4, color: Vec3, style: crate::draw::StrokeStyle) {
    let c = |i: u32| {
        let s = |bit: u32| if i & bit == 0 { -1.0 } else { 1.0 };
        m.transform_point3(Vec3::new(s(1), s(2), s(4)))
    };
    for i in 0..8u32 {
        for bit in [1, 2, 4] {
            if i & bit == 0 {
                frame.stroke(&[c(i), c(i | bit)], color, style);
            }
        }
    }
}

/// Half the size of the box the affine keys move.
const HALF: f32 = 0.35;
/// Colours of the naive (left) and polar (right) boxes: `c-x-axis` and `c-z-axis` in the page.
pub const NAIVE: Vec3 = palette::X_AXIS;
pub const POLAR: Vec3 = palette::Z_AXIS;

/// Figure 2: two affine keys with rotation, scale and shear. Left: element-wise lerp of the 4×4
/// matrices. Right: translation lerp + rotation slerp + stretch lerp, after polar decomposition.
pub struct AffineKeys {
    a: Mat4,
    b: Mat4,
    key_a: AffineKey,
    key_b: AffineKey,
    use_exercise: bool,
    runner: Runner,
    note: String,
    path: Vec<Vec3>,
}

impl Default for AffineKeys {
    fn default() -> Self {
        Self::new()
    }
}

impl AffineKeys {
    pub fn new() -> Self {
        let a = Mat4::from_translation(Vec3::new(-0.6, 0.7, 0.0));
        let key = AffineKey::from_mat4(a).valid("a translation is a valid key");
        let mut scene = AffineKeys {
            a,
            b: a,
            key_a: key,
            key_b: key,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            note: String::new(),
            path: Vec::with_capacity(65),
        };
        scene
            .set_key_b(160.0, Vec3::new(1.6, 0.6, 1.0), 0.6)
            .expect("the default key is invertible");
        scene
    }

    /// Key B: rotation by `angle_deg` about y, after a shear of x by y and a `scale`. A zero
    /// scale flattens the key (singular), a negative one mirrors it: both are rejected.
    pub fn set_key_b(&mut self, angle_deg: f32, scale: Vec3, shear: f32) -> Result<(), String> {
        let angle = in_range("angle", angle_deg, -MAX_ANGLE_DEG, MAX_ANGLE_DEG)? * DEG;
        let c = MAX_COMPONENT;
        let scale = Vec3::new(
            in_range("sx", scale.x, -c, c)?,
            in_range("sy", scale.y, -c, c)?,
            in_range("sz", scale.z, -c, c)?,
        );
        let shear = Mat3::from_cols(
            Vec3::X,
            Vec3::new(in_range("shear", shear, -c, c)?, 1.0, 0.0),
            Vec3::Z,
        );
        let linear = Mat3::from_rotation_y(angle) * shear * Mat3::from_diagonal(scale);
        let at = Mat4::from_translation(Vec3::new(0.6, 1.1, 0.0));
        self.set_key(1, at * Mat4::from_mat3(linear))
    }

    /// Sets key `which` (0 = A, 1 = B) from an affine matrix. Rejects NaN, a bottom row other
    /// than (0, 0, 0, 1), a singular or a mirroring key (the core's messages).
    pub fn set_key(&mut self, which: u32, m: Mat4) -> Result<(), String> {
        if which > 1 {
            return Err(format!("key must be 0 (A) or 1 (B), got {which}"));
        }
        let c = MAX_COMPONENT;
        if let Some(v) = m.to_cols_array().iter().find(|v| v.abs() > c) {
            return Err(format!(
                "the matrix's entries must lie in [-{c}, {c}], got {v}"
            ));
        }
        let key = AffineKey::from_mat4(m).map_err(|e| e.to_string())?;
        if which == 0 {
            (self.a, self.key_a) = (m, key);
        } else {
            (self.b, self.key_b) = (m, key);
        }
        self.refresh_student();
        Ok(())
    }

    /// Splits the keys with the student's `polar_step` (exercise 4.2) iterated to convergence.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.refresh_student();
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.refresh_student();
    }

    /// The note, computed when the keys or the exercise switch change (not per frame).
    pub fn note(&self) -> &str {
        &self.note
    }

    /// Re-splits both keys (the reference, or the student's iteration) and rewrites the note:
    /// one step of the student's `polar_step` on key B compared with the reference, then whether
    /// the iteration converges to a rotation.
    fn refresh_student(&mut self) {
        self.note.clear();
        for which in 0..2 {
            let m = if which == 0 { self.a } else { self.b };
            let mut key = AffineKey::from_mat4(m).valid("validated when set");
            if self.use_exercise {
                if let Ok(Some((r, _))) = student_polar(self.runner, Mat3::from_mat4(m)) {
                    key.rotation = quat_from_mat3(r);
                    key.stretch = r.transpose() * Mat3::from_mat4(m);
                }
            }
            if which == 0 {
                self.key_a = key;
            } else {
                self.key_b = key;
            }
        }
        if self.use_exercise {
            self.note = self.exercise_note();
        }
    }

    fn exercise_note(&self) -> String {
        let m = Mat3::from_mat4(self.b);
        let yours = match run::polar_step(self.runner, m) {
            Ok(step) => step,
            Err(f) => return failure_note("exercise 4.2 polar_step", FILE, &f),
        };
        let mut probes = vec![Probe {
            at: "key B's matrix (one step from R₀ = M)".into(),
            yours: yours.to_cols_array().to_vec(),
            reference: rotation::polar_step(m).to_cols_array().to_vec(),
        }];
        for (at, probe) in polar_probes() {
            match run::polar_step(self.runner, probe) {
                Ok(step) => probes.push(Probe {
                    at: at.into(),
                    yours: step.to_cols_array().to_vec(),
                    reference: rotation::polar_step(probe).to_cols_array().to_vec(),
                }),
                Err(f) => return failure_note("exercise 4.2 polar_step", FILE, &f),
            }
        }
        let (_, mut note) = probe_note("polar_step", &probes, 1e-3);
        match student_polar(self.runner, m) {
            Ok(Some((r, n))) => match rotation_problem(r, 1e-3) {
                None => note += &format!(" Iterated, it converges in {n} steps to a rotation; the figure uses your split."),
                Some(problem) => note += &format!(" Iterated, it converges in {n} steps, but {problem}; the figure uses your split."),
            },
            _ => note += " Iterated, it does not converge (or gives NaN): the figure uses the reference.",
        }
        note
    }

    fn at(&self, naive: bool, t: f32) -> Mat4 {
        if naive {
            rotation::affine_lerp_naive(self.a, self.b, t)
        } else {
            self.key_a.interpolate(&self.key_b, t).to_mat4()
        }
    }

    /// Determinant of the linear part over t: `(t, naive, polar)`.
    pub fn sample_determinant(&self, samples: usize) -> Result<Vec<[f32; 3]>, String> {
        super::check_samples(samples)?;
        let det = |m: Mat4| Mat3::from_mat4(m).determinant();
        Ok((0..samples)
            .map(|k| {
                let t = k as f32 / (samples - 1) as f32;
                [t, det(self.at(true, t)), det(self.at(false, t))]
            })
            .collect())
    }

    /// Draws both interpolations at `t ∈ [0, 1]`; returns the note about the exercise.
    pub fn draw(&mut self, frame: &mut Frame, t: f32) -> Result<String, String> {
        let t = in_range("t", t, 0.0, 1.0)?;
        frame.grid(12, 0.5);
        let corner = Vec3::splat(1.0);
        let size = Mat4::from_scale(Vec3::splat(HALF));
        for (offset, color, naive) in [(-1.8, NAIVE, true), (1.8, POLAR, false)] {
            let shift = Mat4::from_translation(Vec3::new(offset, 0.0, 0.0));
            // Key A dashed and key B solid: at these widths grey and dark grey look alike.
            let dashed = crate::draw::StrokeStyle::dashed(1.5, 0.06, 0.05);
            wire_cube(frame, shift * self.a * size, palette::GREY, dashed);
            let solid = crate::draw::StrokeStyle::solid(2.0);
            wire_cube(frame, shift * self.b * size, palette::DARK, solid);
            self.path.clear();
            for k in 0..=64 {
                let m = shift * self.at(naive, k as f32 / 64.0) * size;
                self.path.push(m.transform_point3(corner));
            }
            // Over everything: the path runs through and behind the boxes.
            let over = crate::draw::StrokeStyle {
                on_top: true,
                ..crate::draw::StrokeStyle::solid(4.0)
            };
            frame.stroke(&self.path, color * 0.8, over);
            frame.keep_in_view.extend(self.path.iter().step_by(4));
            let m = shift * self.at(naive, t);
            frame.mesh(MeshId::CUBE, m * size, color);
            // The corner whose path the line is, where it is now.
            frame.marker_on_top(
                (m * size).transform_point3(corner),
                14.0,
                Vec3::new(0.95, 0.85, 0.2),
            );
            frame.axes(m, 0.6);
            for key in [self.a, self.b] {
                let box_m = shift * key * size;
                for i in 0..8u32 {
                    let s = |bit: u32| if i & bit == 0 { -1.0 } else { 1.0 };
                    frame
                        .keep_in_view
                        .push(box_m.transform_point3(Vec3::new(s(1), s(2), s(4))));
                }
            }
        }
        Ok(self.note.clone())
    }
}

/// Where the student's 4.2 is checked besides key B: the identity and a rotation (a step must
/// leave a rotation alone; a step with the inverse instead of the inverse transpose does not),
/// a stretch along the axes, and a shear.
pub fn polar_probes() -> [(&'static str, Mat3); 4] {
    [
        ("the identity", Mat3::IDENTITY),
        ("a 40° turn about y", Mat3::from_rotation_y(40.0 * DEG)),
        (
            "a stretch diag(2, 0.5, 1)",
            Mat3::from_diagonal(Vec3::new(2.0, 0.5, 1.0)),
        ),
        (
            "a shear of x by 0.8 y",
            Mat3::from_cols(Vec3::X, Vec3::new(0.8, 1.0, 0.0), Vec3::Z),
        ),
    ]
}

/// Iterates the student's step from `R₀ = M` until it stops moving (at most 64 steps):
/// `Ok(Some((R, steps)))`, `Ok(None)` when it does not converge or gives NaN.
fn student_polar(runner: Runner, m: Mat3) -> Result<Option<(Mat3, u32)>, run::Failure> {
    let mut r = m;
    for iteration in 1..=64 {
        let next = run::polar_step(runner, r)?;
        if !next.is_finite() {
            return Ok(None);
        }
        let change = (next - r)
            .to_cols_array()
            .iter()
            .map(|x| x * x)
            .sum::<f32>()
            .sqrt();
        r = next;
        if change <= 1e-5 * (1.0 + r.x_axis.length()) {
            return Ok(Some((r, iteration)));
        }
    }
    Ok(None)
}
