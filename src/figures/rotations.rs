//! Lesson 03, "Rotations": one aeroplane interpolated four ways, the two keys' circle of unit
//! quaternions, a three-ring gimbal (with a steady turn through its pole), and Rodrigues' formula. Natively testable; `web::rotations` only wraps these for JavaScript.

use super::curves::{probe_note, Probe};
use super::{
    failure_note, finite, format_number, in_range, palette, rotation_problem, unit_quat_problem,
    Frame, MeshId, Runner, DEFAULT_RUNNER,
};
use crate::exercises::run;
use crate::rotation::{
    self, angle_between, check_quat, check_rotation_mat3, euler_lerp, mat3_from_quat,
    mat3_lerp_report, nlerp_arc, slerp_arc, Arc, AxisAngle, EulerAngles, EulerOrder,
};
use glam::{Mat3, Mat4, Quat, Vec3};

const DEG: f32 = std::f32::consts::PI / 180.0;
const FILE: &str = "src/exercises/rotations.rs";
/// How close a student's answer must be to the reference for the note to say "matches".
const TOLERANCE: f32 = 1e-4;

/// The little aeroplane every figure turns: body, wings, a tail fin and a yellow nose, so that any
/// orientation (and any shear) is easy to read. Drawn with `linear` (any 3×3, not only rotations)
/// at `at`; the nose points along local +x.
pub fn draw_plane(frame: &mut Frame, at: Vec3, linear: Mat3, color: Vec3, size: f32) {
    for (part, c) in plane_parts(at, linear, color, size) {
        frame.mesh(MeshId::CUBE, part, c);
    }
}

/// The aeroplane's four boxes ([`draw_plane`]): each one's model of the cube `[-1, 1]³` (body,
/// wings, tail fin, nose) and its colour.
pub fn plane_parts(at: Vec3, linear: Mat3, color: Vec3, size: f32) -> [(Mat4, Vec3); 4] {
    let place =
        Mat4::from_translation(at) * Mat4::from_mat3(linear) * Mat4::from_scale(Vec3::splat(size));
    [
        (Vec3::ZERO, Vec3::new(0.5, 0.09, 0.11), color),
        (
            Vec3::new(0.05, 0.0, 0.0),
            Vec3::new(0.13, 0.025, 0.5),
            color * 0.8,
        ),
        (
            Vec3::new(-0.42, 0.14, 0.0),
            Vec3::new(0.07, 0.14, 0.02),
            palette::X_AXIS,
        ),
        (
            Vec3::new(0.5, 0.0, 0.0),
            Vec3::splat(0.06),
            Vec3::new(0.95, 0.85, 0.2),
        ),
    ]
    .map(|(center, half, c)| (place * Mat4::from_translation(center) * Mat4::from_scale(half), c))
}

/// The four ways of getting from one orientation to another, side by side.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Method {
    MatrixLerp,
    EulerLerp,
    Nlerp,
    Slerp,
}

/// Each method's lane (x in metres) and colour, left to right. The page's words use the same
/// colours: `c-x-axis` (red), `c-orange`, `c-y-axis` (green), `c-z-axis` (blue).
pub const METHODS: [(Method, f32, Vec3); 4] = [
    (Method::MatrixLerp, -3.3, palette::X_AXIS),
    (Method::EulerLerp, -1.1, palette::ORANGE),
    (Method::Nlerp, 1.1, palette::Y_AXIS),
    (Method::Slerp, 3.3, palette::Z_AXIS),
];

/// The tip of the yellow pointer on the aeroplane's nose, in its own frame: past the wings, so
/// that its path is not hidden under the aeroplane.
const NOSE: Vec3 = Vec3::new(0.9, 0.0, 0.0);
/// The tip of the aeroplane's right wing, in its own frame: a second tracer, at right angles to
/// the nose, so a turn about the nose's own axis (x), which leaves the nose in place, still draws
/// a path.
const WING_TIP: Vec3 = Vec3::new(0.05, 0.0, 0.5);
/// The dot on the wing tip that draws the dashed path, CSS pixels.
const WING_TIP_PX: f32 = 8.0;
/// Equal steps of t marked on each path.
const PATH_TICKS: usize = 8;
/// Samples of t over which Figure 1's note finds how far Euler lerp strays from slerp.
const DEVIATION_SAMPLES: usize = 64;

/// Figure 1: one aeroplane, two key orientations, interpolated by matrix lerp, Euler-angle lerp,
/// nlerp and slerp (left to right), with the path of the nose over the whole interpolation.
pub struct Interpolation {
    start: EulerAngles,
    end: EulerAngles,
    start_quat: Quat,
    end_quat: Quat,
    arc: Arc,
    use_exercise: bool,
    runner: Runner,
    path: Vec<Vec3>,
    /// The camera and canvas size (CSS pixels) Figure 2's last frame was drawn with: the names
    /// of a, b, −a and −b take places beside their dots that cover no dot or line.
    circle_view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
}

impl Default for Interpolation {
    fn default() -> Self {
        Self::new()
    }
}

impl Interpolation {
    /// Default keys (intrinsic X-Y′-Z″, degrees) chosen so that Euler lerp wobbles visibly: the
    /// keys are 101° apart, yet Euler lerp strays up to 39° from slerp's orientation and its
    /// angular speed varies by a factor of more than 2 (tests/figures_rotations.rs checks this).
    pub const START_DEG: Vec3 = Vec3::new(0.0, 0.0, 0.0);
    pub const END_DEG: Vec3 = Vec3::new(120.0, 70.0, -120.0);

    pub fn new() -> Self {
        let mut scene = Interpolation {
            start: EulerAngles::new(EulerOrder::IntrinsicXYZ, Vec3::ZERO),
            end: EulerAngles::new(EulerOrder::IntrinsicXYZ, Vec3::ZERO),
            start_quat: Quat::IDENTITY,
            end_quat: Quat::IDENTITY,
            arc: Arc::Short,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            path: Vec::with_capacity(65),
            circle_view: None,
        };
        scene.set_keys(Self::START_DEG * DEG, Self::END_DEG * DEG);
        scene
    }

    fn set_keys(&mut self, start_rad: Vec3, end_rad: Vec3) {
        self.start = EulerAngles::new(EulerOrder::IntrinsicXYZ, start_rad);
        self.end = EulerAngles::new(EulerOrder::IntrinsicXYZ, end_rad);
        self.start_quat = self.start.to_quat();
        self.end_quat = self.end.to_quat();
    }

    /// Sets both keys as intrinsic X-Y′-Z″ Euler angles, in degrees.
    pub fn set_keys_euler_deg(&mut self, start_deg: Vec3, end_deg: Vec3) -> Result<(), String> {
        for (name, v) in [("start", start_deg), ("end", end_deg)] {
            for (axis, x) in ["x", "y", "z"].iter().zip(v.to_array()) {
                finite(&format!("{name} {axis}"), x)?;
            }
        }
        self.set_keys(start_deg * DEG, end_deg * DEG);
        Ok(())
    }

    /// Sets the end key as a quaternion; it is normalised. Zero or NaN is rejected.
    pub fn set_end_quat(&mut self, q: Quat) -> Result<(), String> {
        let q = check_quat(q).map_err(|e| e.to_string())?;
        self.end_quat = q;
        self.end = EulerAngles::from_quat(q, EulerOrder::IntrinsicXYZ);
        Ok(())
    }

    /// Sets the end key as a rotation matrix; one that is not orthonormal, or mirrors, is rejected.
    pub fn set_end_matrix(&mut self, r: Mat3) -> Result<(), String> {
        let r = check_rotation_mat3(r).map_err(|e| e.to_string())?;
        self.end_quat = rotation::quat_from_mat3(r);
        self.end = EulerAngles::from_mat3(r, EulerOrder::IntrinsicXYZ);
        Ok(())
    }

    /// `true`: nlerp and slerp take the long arc (they use `−q` for the end key).
    pub fn set_long_arc(&mut self, long: bool) {
        self.arc = if long { Arc::Long } else { Arc::Short };
    }

    /// Uses the student's `slerp` (exercise 3.2) for the slerp object.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// How the student's exercise is called (natively: in-process; in the page: the sandbox).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// The camera and canvas size (CSS pixels) Figure 2 is drawn for (its last frame's), which
    /// the names of its keys are placed for.
    pub fn set_circle_view(
        &mut self,
        camera: crate::camera::OrbitCamera,
        width_px: f32,
        height_px: f32,
    ) {
        if width_px > 0.0 && height_px > 0.0 {
            self.circle_view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    /// The end key's quaternion as used on the current arc (negated when needed).
    pub fn end_quat_used(&self) -> Quat {
        let d = self.start_quat.dot(self.end_quat);
        let flip = match self.arc {
            Arc::Short => d < 0.0,
            Arc::Long => d > 0.0,
        };
        if flip {
            -self.end_quat
        } else {
            self.end_quat
        }
    }

    /// How far the object turns between the keys, in degrees: `(short arc, long arc)`. They add up
    /// to 360°: the long arc turns the other way round, it is not an extra loop.
    pub fn arc_angles_deg(&self) -> (f32, f32) {
        let short = angle_between(self.start_quat, self.end_quat) / DEG;
        (short, 360.0 - short)
    }

    /// Draws the four objects at `t ∈ [0, 1]` with the paths of their noses and wing tips; returns
    /// the note (the arc taken, the check of the student's slerp when "use my exercise" is on, and
    /// how far Euler lerp is from slerp at `t` and at most).
    pub fn draw(&mut self, frame: &mut Frame, t: f32) -> Result<String, String> {
        let t = in_range("t", t, 0.0, 1.0)?;
        let student = self.use_exercise && self.arc == Arc::Short;
        frame.grid(16, 0.5);
        for (method, x, color) in METHODS {
            let at = Vec3::new(x, 1.2, 0.0);
            // Whatever the keys, the object, its axes and its paths stay within 0.9 m of its
            // centre (the nose's pointer reaches furthest): 26 points on a sphere of 0.95 m
            // stay in view at any canvas size. A box's corners would reach √3 times as far, and
            // leave the objects small.
            for d in [-1.0f32, 0.0, 1.0]
                .into_iter()
                .flat_map(|x| [-1.0f32, 0.0, 1.0].map(move |y| (x, y)))
                .flat_map(|(x, y)| [-1.0f32, 0.0, 1.0].map(move |z| Vec3::new(x, y, z)))
                .filter(|d| *d != Vec3::ZERO)
            {
                frame.keep_in_view.push(at + 0.95 * d.normalize());
            }
            self.path.clear();
            for k in 0..=64 {
                let m = self.orientation(method, k as f32 / 64.0, student);
                self.path.push(at + m * NOSE);
            }
            // Over everything: the path is seen through the aeroplane that turns about it.
            let over = crate::draw::StrokeStyle {
                on_top: true,
                ..crate::draw::StrokeStyle::solid(3.0)
            };
            frame.stroke(&self.path, color * 0.8, over);
            let ticks: Vec<Vec3> = (0..=PATH_TICKS)
                .map(|k| self.path[k * 64 / PATH_TICKS])
                .collect();
            frame.ticks(&ticks, 12.0, color * 0.8);
            frame.marker_on_top(self.path[0], crate::draw::DOT_PX, palette::GREY);
            frame.marker_on_top(self.path[64], crate::draw::DOT_PX, palette::KEY);
            // The wing tip's path, dashed and thinner: it moves where the nose's stays put.
            self.path.clear();
            for k in 0..=64 {
                let m = self.orientation(method, k as f32 / 64.0, student);
                self.path.push(at + m * WING_TIP);
            }
            let wing = crate::draw::StrokeStyle {
                on_top: true,
                ..crate::draw::StrokeStyle::dashed(2.5, 0.08, 0.05)
            };
            frame.stroke(&self.path, color * 0.8, wing);
            let m = self.orientation(method, t, student);
            // The wing tip that draws the dashed path, where it is now.
            frame.marker_on_top(at + m * WING_TIP, WING_TIP_PX, color * 0.8);
            draw_plane(frame, at, m, color, 1.0);
            // The pointer whose tip draws the path.
            let pointer = Mat4::from_translation(at)
                * Mat4::from_mat3(m)
                * Mat4::from_translation(Vec3::new(0.72, 0.0, 0.0))
                * Mat4::from_scale(Vec3::new(0.18, 0.015, 0.015));
            frame.mesh(MeshId::CUBE, pointer, Vec3::new(0.95, 0.85, 0.2));
            frame.axes(Mat4::from_translation(at) * Mat4::from_mat3(m), 0.6);
        }
        let exercise = if self.use_exercise {
            self.exercise_note(t)
        } else {
            String::new()
        };
        let parts = [self.arc_note(), exercise, self.deviation_note(t)];
        Ok(parts
            .iter()
            .filter(|p| !p.is_empty())
            .cloned()
            .collect::<Vec<_>>()
            .join(" "))
    }

    /// The angle (degrees) between Euler lerp's orientation and slerp's at `t` (the reference
    /// slerp, on the arc in use).
    pub fn euler_deviation_deg(&self, t: f32) -> f32 {
        let euler = rotation::quat_from_mat3(self.orientation(Method::EulerLerp, t, false));
        let slerp = rotation::quat_from_mat3(self.orientation(Method::Slerp, t, false));
        angle_between(euler, slerp) / DEG
    }

    /// The largest [`Interpolation::euler_deviation_deg`] over t at
    /// [`DEVIATION_SAMPLES`] + 1 equal steps: `(t, degrees)`.
    pub fn max_euler_deviation_deg(&self) -> (f32, f32) {
        (0..=DEVIATION_SAMPLES)
            .map(|k| k as f32 / DEVIATION_SAMPLES as f32)
            .map(|t| (t, self.euler_deviation_deg(t)))
            .fold((0.0, 0.0), |best, x| if x.1 > best.1 { x } else { best })
    }

    /// How far Euler lerp is from slerp now, and at most.
    fn deviation_note(&self, t: f32) -> String {
        let (t_max, max) = self.max_euler_deviation_deg();
        if max < 0.5 {
            // No largest to point at: the two agree everywhere (keys about one axis).
            return "Euler lerp follows slerp here: they are under 0.5° apart at every t.".into();
        }
        let mut note = format!(
            "Euler lerp is {:.0}° from slerp at t = {:.2}; at most {:.0}° (at t = {:.2}).",
            self.euler_deviation_deg(t),
            t,
            max,
            t_max
        );
        if self.start_quat.dot(self.end_quat).abs() < 1e-3 {
            // a·b = 0: both arcs are 180°, and neither method is wrong to take its own.
            note += " The keys are half a turn apart: either way round reaches the end key, so \
                     two correct in-betweens can be up to 180° apart.";
        }
        note
    }

    fn arc_note(&self) -> String {
        if self.arc == Arc::Short {
            return String::new();
        }
        let (short, long) = self.arc_angles_deg();
        format!(
            "Long arc: nlerp and slerp turn {}° the other way round, instead of {}° the short way.",
            format_number(long),
            format_number(short)
        )
    }

    /// Compares the student's slerp with the reference (short arc) at `t` and at probe inputs
    /// where a slerp often goes wrong (keys with a·b < 0, the ends, nearly equal keys), checks that
    /// it returns a unit quaternion, and says which arc it takes when a·b < 0.
    pub fn exercise_note(&self, t: f32) -> String {
        let (a, b) = (self.start_quat, self.end_quat);
        let yours = match run::slerp(self.runner, a, b, t) {
            Ok(q) => q,
            Err(f) => return failure_note("exercise 3.2 slerp", FILE, &f),
        };
        let mut probes = Vec::new();
        for (at, (pa, pb, pt)) in std::iter::once((format!("t = {}", format_number(t)), (a, b, t)))
            .chain(slerp_probes(a, b))
        {
            let mine = match run::slerp(self.runner, pa, pb, pt) {
                Ok(q) => q,
                Err(f) => return failure_note("exercise 3.2 slerp", FILE, &f),
            };
            let reference = rotation::slerp(pa, pb, pt);
            // q and −q are one rotation: compare with the sign that is closer.
            let aligned = if mine.dot(reference) < 0.0 {
                -mine
            } else {
                mine
            };
            probes.push(Probe {
                at,
                yours: aligned.to_array().to_vec(),
                reference: reference.to_array().to_vec(),
            });
        }
        let (_, mut note) = probe_note("slerp", &probes, TOLERANCE);
        if let Some(problem) = unit_quat_problem(yours, 1e-3) {
            note += &format!(" Your answer at t = {}: {problem}.", format_number(t));
        }
        note += " ";
        note += &self.arc_check();
        if self.arc == Arc::Long {
            note += " (The long-arc figure uses the reference.)";
        }
        note
    }

    /// Whether the student's slerp takes the short arc when a·b < 0, judged at the midpoint of
    /// the figure's keys, or of the figure's start and −(end key) when the keys have a·b ≥ 0 (a
    /// slerp without the flip takes the short arc there by chance).
    fn arc_check(&self) -> String {
        let a = self.start_quat;
        let (b, which) = if a.dot(self.end_quat) < 0.0 {
            (self.end_quat, "the figure's keys")
        } else {
            (-self.end_quat, "the figure's start and −(end key)")
        };
        let Ok(mid) = run::slerp(self.runner, a, b, 0.5) else {
            return String::new();
        };
        let short = slerp_arc(a, b, 0.5, Arc::Short);
        let long = slerp_arc(a, b, 0.5, Arc::Long);
        let (to_short, to_long) = (angle_between(mid, short), angle_between(mid, long));
        let dot = format_number(a.dot(b));
        if a.dot(b) > -1e-4 {
            // The keys are a quarter turn apart on the sphere: both arcs are as long.
            String::new()
        } else if to_short <= 1e-2 {
            format!("With a·b = {dot} < 0 ({which}), your slerp takes the short arc.")
        } else if to_long <= 1e-2 {
            format!(
                "With a·b = {dot} < 0 ({which}), your slerp takes the long arc: negate b when a·b < 0."
            )
        } else {
            format!("With a·b = {dot} < 0 ({which}), at t = 0.5 your slerp is on neither arc.")
        }
    }

    /// The plane of the two keys in quaternion space, as coordinates `(along a, across)`: slerp
    /// and nlerp between a and ±b never leave the plane through 0, a and b, so its circle of unit
    /// quaternions shows both arcs exactly. The second axis is the part of b orthogonal to a
    /// (any unit quaternion orthogonal to a when b = ±a).
    pub fn key_plane(&self) -> (Quat, Quat) {
        let (a, b) = (self.start_quat, self.end_quat);
        let across = b - a * a.dot(b);
        let e2 = if across.length() > 1e-4 {
            across.normalize()
        } else {
            Quat::from_xyzw(-a.y, a.x, -a.w, a.z)
        };
        (a, e2)
    }

    /// Figure 2: the circle of unit quaternions in the plane of the two keys, with a, b, −b and
    /// −a, the short arc (solid) and the long arc (dashed), the chord that lerp follows, equal
    /// steps of t for slerp (blue, just outside the circle) and nlerp (green rays from the chord), and
    /// both at `t`. Returns the note: which of b and −b the arc in use ends at, and why.
    pub fn draw_circle(&mut self, frame: &mut Frame, t: f32) -> Result<String, String> {
        let t = in_range("t", t, 0.0, 1.0)?;
        // A plane diagram seen face-on: a drag pans it, and the circle stays a circle.
        frame.flat = true;
        let (e1, e2) = self.key_plane();
        let to_world =
            |q: Quat| CIRCLE_CENTRE + CIRCLE_RADIUS * Vec3::new(q.dot(e1), q.dot(e2), 0.0);
        let at_angle = |phi: f32, r: f32| CIRCLE_CENTRE + r * Vec3::new(phi.cos(), phi.sin(), 0.0);
        frame.keep_box_in_view(
            CIRCLE_CENTRE - Vec3::new(1.25, 1.2, 0.0) * CIRCLE_RADIUS,
            CIRCLE_CENTRE + Vec3::new(1.25, 1.2, 0.0) * CIRCLE_RADIUS,
        );
        self.path.clear();
        self.path.extend(
            (0..=128).map(|k| at_angle(k as f32 / 128.0 * std::f32::consts::TAU, CIRCLE_RADIUS)),
        );
        frame.wide_polyline(&self.path, palette::GRID_AXIS, 1.5);
        let (a, b) = (self.start_quat, self.end_quat);
        // b sits at angle φ_b in [0, π] (its coordinate across is ≥ 0), −b at φ_b − π.
        let phi_b = b.dot(e2).atan2(b.dot(e1));
        let used = self.end_quat_used();
        let phi_used = if used.dot(b) >= 0.0 {
            phi_b
        } else {
            phi_b - std::f32::consts::PI
        };
        let phi_other = if used.dot(b) >= 0.0 {
            phi_b - std::f32::consts::PI
        } else {
            phi_b
        };
        let (short_phi, long_phi) = if phi_used.abs() <= phi_other.abs() {
            (phi_used, phi_other)
        } else {
            (phi_other, phi_used)
        };
        let arc_points = |end: f32| -> Vec<Vec3> {
            (0..=64)
                .map(|k| at_angle(end * k as f32 / 64.0, CIRCLE_RADIUS))
                .collect()
        };
        let slerp_color = palette::Z_AXIS;
        let nlerp_color = palette::Y_AXIS;
        frame.wide_polyline(&arc_points(short_phi), slerp_color, 5.0);
        frame.stroke(
            &arc_points(long_phi),
            palette::PURPLE,
            crate::draw::StrokeStyle::dashed(3.0, 0.12, 0.08),
        );
        // The arcs' labels read away from the circle: rightwards on its right half, leftwards on
        // its left half, so neither covers the circle or its dots. They are short (the note
        // gives the turn, 2Ω) so they fit beside the circle.
        let outward = |frame: &mut Frame, at: Vec3, text: String, color: Vec3, priority: i32| {
            frame.label_with_priority(at, text, color, priority);
            if let Some(label) = frame.labels.last_mut() {
                label.left = at.x < CIRCLE_CENTRE.x;
            }
        };
        let (short_deg, long_deg) = (short_phi.abs() / DEG, long_phi.abs() / DEG);
        // The label of the arc in use stands past slerp's ticks; a short arc's farther out,
        // past the names of its two ends.
        let out = |phi: f32| if phi == phi_used { 1.27 } else { 1.15 };
        outward(
            frame,
            at_angle(
                short_phi * 0.5,
                CIRCLE_RADIUS * if short_deg < 40.0 { 1.45 } else { out(short_phi) },
            ),
            format!("short arc: Ω = {short_deg:.0}°"),
            slerp_color,
            2,
        );
        outward(
            frame,
            at_angle(long_phi * 0.5, CIRCLE_RADIUS * out(long_phi)),
            format!("long arc: Ω = {long_deg:.0}°"),
            palette::PURPLE,
            2,
        );
        // The four quaternions of the two rotations: a and −a, b and −b.
        let keys = [
            (a, "a", palette::GREY),
            (-a, "−a", palette::GREY),
            (b, "b", palette::KEY),
            (-b, "−b", palette::KEY),
        ];
        // lerp walks the chord at equal steps of t; nlerp pushes each step out onto the circle
        // (a ray from the centre); slerp walks the arc at equal angles.
        let end = at_angle(phi_used, CIRCLE_RADIUS);
        let start = at_angle(0.0, CIRCLE_RADIUS);
        for (q, _, color) in keys {
            frame.marker(to_world(q), KEY_DOT_PX, color);
        }
        frame.wide_line(start, end, palette::DARK, 1.5);
        const STEPS: usize = 8;
        let mut slerp_ticks = Vec::with_capacity(STEPS + 1);
        for k in 0..=STEPS {
            let s = k as f32 / STEPS as f32;
            let step = start.lerp(end, s);
            let out = CIRCLE_CENTRE + (step - CIRCLE_CENTRE).normalize_or_zero() * CIRCLE_RADIUS;
            frame.wide_line(step, out, nlerp_color, 1.5);
            // The first and last steps are the keys' dots.
            if k % STEPS != 0 {
                frame.marker(out, 7.0, nlerp_color);
            }
            slerp_ticks.push(at_angle(phi_used * s, CIRCLE_RADIUS * SLERP_TICKS_OUT));
        }
        frame.ticks(&slerp_ticks, 10.0, slerp_color);
        // The dots at t, each smaller than the one it lies on: near t = 0 (and 1) nlerp's and
        // lerp's lie on a key's (all three methods start at a), and a ring of each shows round
        // the next.
        let on_chord = start.lerp(end, t);
        frame.marker(
            CIRCLE_CENTRE + (on_chord - CIRCLE_CENTRE).normalize_or_zero() * CIRCLE_RADIUS,
            NOW_DOT_PX,
            nlerp_color,
        );
        frame.marker(
            at_angle(phi_used * t, CIRCLE_RADIUS * SLERP_TICKS_OUT),
            NOW_DOT_PX,
            slerp_color,
        );
        frame.marker(on_chord, LERP_NOW_PX, palette::DARK);
        // The keys' names, once every dot and line is down: each at the first place round its
        // dot, outward first (then further out), on the last frame's view, that keeps
        // KEY_NAME_CLEAR_PX off every dot, line and name placed before it (near t = 0 or 1,
        // slerp's and nlerp's dots sit on a key's; a name touching nlerp's rays or the chord
        // reads as theirs) and lies nearer its own key's dot than any other's (a and −b, or b
        // and −a, can be 10° apart).
        let view = self
            .circle_view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // The arcs' labels' boxes: a name 6 px before one reads as its first word ("a short
        // arc"), so the names keep ARC_LABEL_GAP_PX off them.
        let arc_labels: Vec<_> = view.map_or(Vec::new(), |(view_proj, size)| {
            (frame.labels.iter())
                .filter_map(|l| l.first_place(view_proj, size))
                .collect()
        });
        let dots: Vec<Option<glam::Vec2>> = (keys.iter())
            .map(|(q, _, _)| {
                let (view_proj, size) = view?;
                crate::camera::project_to_canvas(view_proj, size, to_world(*q))
            })
            .collect();
        for (i, (q, name, color)) in keys.into_iter().enumerate() {
            let p = to_world(q);
            let out = p - CIRCLE_CENTRE;
            let toward = view
                .and_then(|(view_proj, size)| {
                    let at = |x| crate::camera::project_to_canvas(view_proj, size, x);
                    Some(at(p + out)? - at(p)?)
                })
                .unwrap_or(glam::Vec2::new(out.x, -out.y));
            let candidates =
                crate::draw::Label::around_dot(p, KEY_DOT_PX, toward, name, color, 3, 8, 8.0);
            let clear = super::clear_of(view, &[]);
            let from = |c: glam::Vec2, r: &crate::draw::layout::Rect| r.nearest(c).distance(c);
            frame.first_clear_label_by(view, KEY_NAME_CLEAR_PX, candidates, |r| {
                clear(r)
                    && arc_labels.iter().all(|a| !a.overlaps(&r, ARC_LABEL_GAP_PX))
                    && dots[i].is_none_or(|own| {
                        let d = from(own, &r);
                        dots.iter().flatten().all(|&o| o == own || from(o, &r) > d)
                    })
            });
        }
        let dot = format_number(a.dot(b));
        let target = if used.dot(b) >= 0.0 { "b" } else { "−b" };
        let why = match (self.arc, a.dot(b) < 0.0) {
            (Arc::Short, false) => {
                "a·b ≥ 0, so b is the nearer of b and −b: the short arc ends at b"
            }
            (Arc::Short, true) => {
                "a·b < 0, so −b is the nearer of b and −b: the short arc ends at −b"
            }
            (Arc::Long, _) => "long arc is ticked, so the arc ends at the farther of b and −b",
        };
        Ok(format!(
            "a·b = {dot}: {why}. nlerp and slerp go from a to {target}, through angle Ω = {}° on the \
             circle: the aeroplane turns by 2Ω = {}°.",
            format_number(phi_used.abs() / DEG),
            format_number(2.0 * phi_used.abs() / DEG)
        ))
    }

    /// Matrix lerp, sampled: `(t, det, ‖MᵀM − I‖)`.
    pub fn sample_determinant(&self, samples: usize) -> Result<Vec<[f32; 3]>, String> {
        super::check_samples(samples)?;
        let (a, b) = (
            mat3_from_quat(self.start_quat),
            mat3_from_quat(self.end_quat),
        );
        Ok((0..samples)
            .map(|k| {
                let t = k as f32 / (samples - 1) as f32;
                let s = mat3_lerp_report(a, b, t);
                [t, s.determinant, s.orthogonality_error]
            })
            .collect())
    }

    /// Angular speed (degrees per unit of t) of Euler lerp, nlerp and slerp, by finite
    /// differences: `(t, euler, nlerp, slerp)`.
    pub fn sample_angular_speed(&self, samples: usize) -> Result<Vec<[f32; 4]>, String> {
        super::check_samples(samples)?;
        let student = self.use_exercise && self.arc == Arc::Short;
        let h = 1e-3;
        Ok((0..samples)
            .map(|k| {
                let t = k as f32 / (samples - 1) as f32;
                let (t0, t1) = ((t - h).max(0.0), (t + h).min(1.0));
                let speed = |method| {
                    let q0 = rotation::quat_from_mat3(self.orientation(method, t0, student));
                    let q1 = rotation::quat_from_mat3(self.orientation(method, t1, student));
                    angle_between(q0, q1) / (t1 - t0) / DEG
                };
                [
                    t,
                    speed(Method::EulerLerp),
                    speed(Method::Nlerp),
                    speed(Method::Slerp),
                ]
            })
            .collect())
    }

    /// The orientation (any 3×3 for matrix lerp) of `method` at `t`. With `student`, slerp runs
    /// the student's code, falling back to the reference when it gives no usable answer.
    pub fn orientation(&self, method: Method, t: f32, student: bool) -> Mat3 {
        let (a, b) = (self.start_quat, self.end_quat);
        match method {
            Method::MatrixLerp => rotation::mat3_lerp(mat3_from_quat(a), mat3_from_quat(b), t),
            Method::EulerLerp => euler_lerp(self.start, self.end, t).to_mat3(),
            Method::Nlerp => mat3_from_quat(nlerp_arc(a, b, t, self.arc)),
            Method::Slerp => {
                let mine = student
                    .then(|| run::slerp(self.runner, a, b, t).ok())
                    .flatten()
                    .filter(|q| q.is_finite() && q.length() > 1e-6);
                mat3_from_quat(match mine {
                    Some(q) => q.normalize(),
                    None => slerp_arc(a, b, t, self.arc),
                })
            }
        }
    }
}

/// Figure 2's dots, CSS pixels across: a, −a, b and −b; nlerp's and slerp's at t; lerp's at t.
/// Each is 7 px smaller than the one before, so that where lerp's lies on nlerp's and nlerp's on
/// a key's (at t = 0 and 1) a ring of each shows round the next (a dot's outline takes 1.75 px
/// of its radius).
pub const KEY_DOT_PX: f32 = 21.0;
pub const NOW_DOT_PX: f32 = 14.0;
pub const LERP_NOW_PX: f32 = 7.0;
/// How far Figure 2's key names keep from its arcs' labels, CSS pixels: a word's gap and more.
pub const ARC_LABEL_GAP_PX: f32 = 14.0;
/// Figure 2: the names a, −a, b and −b keep this far off every dot and line (CSS pixels).
pub const KEY_NAME_CLEAR_PX: f32 = 2.0;

/// Figure 2's circle of unit quaternions: its centre and radius (metres).
pub const CIRCLE_CENTRE: Vec3 = Vec3::new(0.0, 1.3, 0.0);
pub const CIRCLE_RADIUS: f32 = 1.2;
/// Figure 2: slerp's ticks stand this many radii from the centre, apart from nlerp's dots on
/// the circle (nearer it, a dot and a tick on a short arc read as one mark).
pub const SLERP_TICKS_OUT: f32 = 1.13;

/// Where a student's slerp is checked besides the figure's input: `(what the note calls it,
/// (a, b, t))`. Keys with a·b < 0 (a slerp without the short-arc flip goes the long way), both
/// ends, and keys 0.01° apart (sin Ω ≈ 0: a slerp without a fallback divides by zero).
pub fn slerp_probes(a: Quat, b: Quat) -> Vec<(String, (Quat, Quat, f32))> {
    let x170 = Quat::from_rotation_x(170.0 * DEG);
    let near = Quat::from_axis_angle(Vec3::new(0.6, 0.0, 0.8), 0.01 * DEG) * a;
    vec![
        (
            format!(
                "the figure's keys with −b (a·b = {}), t = 0.25",
                format_number(-a.dot(b))
            ),
            (a, -b, 0.25),
        ),
        (
            "keys 170° and −170° about x (a·b < 0), t = 0.5".into(),
            (x170, x170.inverse(), 0.5),
        ),
        ("t = 0".into(), (a, b, 0.0)),
        ("t = 1".into(), (a, b, 1.0)),
        ("keys 0.01° apart, t = 0.5".into(), (a, near, 0.5)),
    ]
}

/// Points on a circle of `radius` in the plane spanned by `u` and `v`, as thin boxes, unlit:
/// the page names each ring by its colour (the middle one orange), and the light would turn
/// these thin, mostly side-lit boxes a darker shade (orange to brown).
fn ring(frame: &mut Frame, m: Mat4, u: Vec3, v: Vec3, radius: f32, color: Vec3) {
    const SEGMENTS: usize = 40;
    let half = std::f32::consts::PI * radius / SEGMENTS as f32 * 1.05;
    let normal = u.cross(v);
    for k in 0..SEGMENTS {
        let phi = (k as f32 + 0.5) / SEGMENTS as f32 * std::f32::consts::TAU;
        let radial = u * phi.cos() + v * phi.sin();
        let tangent = normal.cross(radial);
        let model = Mat4::from_cols(
            (tangent * half).extend(0.0),
            (radial * 0.035).extend(0.0),
            (normal * 0.035).extend(0.0),
            (radial * radius).extend(1.0),
        );
        frame.meshes.push(crate::draw::MeshDraw {
            mesh: MeshId::CUBE,
            model: m * model,
            color: color.extend(1.0),
            vertex_colors: false,
            unlit: true,
        });
    }
}

/// Ring colours (outer/yaw, middle/pitch, inner/roll), as the page names them, and the warning
/// colour near gimbal lock.
pub const GIMBAL_COLORS: [Vec3; 3] = [palette::Y_AXIS, palette::ORANGE, palette::Z_AXIS];
pub const LOCK_WARNING: Vec3 = palette::X_AXIS;

/// Figure 3: a three-ring gimbal for intrinsic Y-X′-Z″ angles (yaw, pitch, roll),
/// `R = R_y(yaw) R_x(pitch) R_z(roll)`. At pitch ±90° the inner axle lines up with the outer one.
pub struct Gimbal {
    angles_rad: Vec3,
    /// How far the steady turn of [`Gimbal::pole_turn`] passes from gimbal lock.
    pole_miss_rad: f32,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the axles' names
    /// take places that cover no line.
    view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
}

impl Default for Gimbal {
    fn default() -> Self {
        Self::new()
    }
}

impl Gimbal {
    pub fn new() -> Self {
        Gimbal {
            angles_rad: Vec3::new(30.0, 0.0, 20.0) * DEG,
            pole_miss_rad: Self::POLE_MISS_DEG * DEG,
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the axles' names are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    /// How far from the gimbal's centre each axle's name sits, metres: past the outer ring
    /// (1.3 m), where no ring runs under it, at the top of the stand for the yaw axle.
    pub const AXLE_NAME_R: f32 = 1.6;

    /// The default distance (degrees) by which the steady turn passes the pole.
    pub const POLE_MISS_DEG: f32 = 5.0;
    /// How far the steady turn turns over t in [0, 1] (degrees): pitch 30° to 150° when it
    /// passes straight through the pole.
    pub const POLE_TURN_DEG: f32 = 120.0;

    /// Sets how far (degrees, 0 to 45) the steady turn passes from the pole.
    pub fn set_pole_miss_deg(&mut self, miss: f32) -> Result<(), String> {
        self.pole_miss_rad = in_range("distance from the pole", miss, 0.0, 45.0)? * DEG;
        Ok(())
    }

    /// A steady turn through the pole: `R(t) = R_z(miss) R_x(30° + 120° t)`, one fixed axis at
    /// constant angular speed. Its roll axle `R z` comes within `miss` of the yaw axle's
    /// direction (−y) at t = 0.5.
    pub fn pole_turn(&self, t: f32) -> Mat3 {
        Mat3::from_rotation_z(self.pole_miss_rad)
            * Mat3::from_rotation_x((30.0 + Self::POLE_TURN_DEG * t) * DEG)
    }

    /// Puts the gimbal on the steady turn at `t ∈ [0, 1]`: the rings take the yaw, pitch and
    /// roll read back from `R(t)`. Returns them in degrees.
    pub fn fly_at(&mut self, t: f32) -> Result<Vec3, String> {
        let t = in_range("t", t, 0.0, 1.0)?;
        let e = EulerAngles::from_mat3(self.pole_turn(t), EulerOrder::IntrinsicYXZ);
        self.angles_rad = e.angles_rad;
        Ok(e.angles_rad / DEG)
    }

    /// Yaw, pitch and roll (degrees) that the rings need to follow the steady turn, sampled:
    /// `(t, yaw, pitch, roll)`, each unwrapped (a step of 360° removed) so that the curves are
    /// continuous wherever the turn misses the pole.
    pub fn sample_pole_turn(&self, samples: usize) -> Result<Vec<[f32; 4]>, String> {
        super::check_samples(samples)?;
        let mut rows: Vec<[f32; 4]> = Vec::with_capacity(samples);
        for k in 0..samples {
            let t = k as f32 / (samples - 1) as f32;
            let e = EulerAngles::from_mat3(self.pole_turn(t), EulerOrder::IntrinsicYXZ);
            let mut a = e.angles_rad / DEG;
            if let Some(last) = rows.last() {
                for (i, x) in [(0, &mut a.x), (2, &mut a.z)] {
                    *x += 360.0 * ((last[i + 1] - *x) / 360.0).round();
                }
            }
            rows.push([t, a.x, a.y, a.z]);
        }
        Ok(rows)
    }

    /// Sets (yaw about y, pitch about x′, roll about z″), in degrees.
    pub fn set_angles_deg(&mut self, yaw: f32, pitch: f32, roll: f32) -> Result<(), String> {
        self.angles_rad = Vec3::new(
            finite("yaw", yaw)?,
            finite("pitch", pitch)?,
            finite("roll", roll)?,
        ) * DEG;
        Ok(())
    }

    fn rotation(&self) -> Mat3 {
        EulerAngles::new(EulerOrder::IntrinsicYXZ, self.angles_rad).to_mat3()
    }

    /// World directions of the outer (yaw) and inner (roll) axles.
    pub fn axles(&self) -> (Vec3, Vec3) {
        let [yaw, pitch, _] = self.angles_rad.to_array();
        (
            Vec3::Y,
            Mat3::from_rotation_y(yaw) * Mat3::from_rotation_x(pitch) * Vec3::Z,
        )
    }

    /// Angle between the outer and inner axles, in degrees: 0 at gimbal lock.
    pub fn axles_angle_deg(&self) -> f32 {
        let (outer, inner) = self.axles();
        outer.dot(inner).abs().min(1.0).acos() / DEG
    }

    /// The orientation read back as Y-X′-Z″ angles by the core, in degrees, and whether the core
    /// flags gimbal lock there.
    pub fn decomposed_deg(&self) -> (Vec3, bool) {
        let e = EulerAngles::from_mat3(self.rotation(), EulerOrder::IntrinsicYXZ);
        (e.angles_rad / DEG, e.gimbal_lock)
    }

    /// At gimbal lock the roll axle is the yaw axle, turned the same way (`+1`) or the opposite
    /// way (`−1`): then only `yaw + sign · roll` is determined. At pitch +90°, `R_x(90°)` takes z
    /// to −y, so the sign is −1 (yaw − roll); at −90° it is +1.
    pub fn lock_sign(&self) -> f32 {
        let (outer, inner) = self.axles();
        if outer.dot(inner) < 0.0 {
            -1.0
        } else {
            1.0
        }
    }

    /// What the page says under the gimbal: the axle angle and the angles read back.
    pub fn note(&self) -> String {
        let (back, locked) = self.decomposed_deg();
        let angle = format_number(self.axles_angle_deg());
        let read = format!(
            "yaw {}°, pitch {}°, roll {}°",
            format_number(back.x),
            format_number(back.y),
            format_number(back.z)
        );
        if !locked {
            return format!(
                "Angle between the yaw and roll axles: {angle}°. Read back from the matrix: {read}."
            );
        }
        let [yaw, pitch, roll] = (self.angles_rad / DEG).to_array();
        let sign = self.lock_sign();
        let (op, combined) = if sign < 0.0 {
            ("−", yaw - roll)
        } else {
            ("+", yaw + roll)
        };
        format!(
            "Gimbal lock at pitch {}°: yaw and roll turn about the same line, {}, so only \
             yaw {op} roll = {}° is determined. Read back from the matrix, with roll set to 0: {read}.",
            format_number(pitch),
            if sign < 0.0 { "in opposite senses" } else { "in the same sense" },
            format_number(wrap_deg(combined)),
        )
    }

    pub fn draw(&self, frame: &mut Frame) {
        let [yaw, pitch, roll] = self.angles_rad.to_array();
        let center = Vec3::new(0.0, 1.5, 0.0);
        let base = Mat4::from_translation(center);
        let outer = base * Mat4::from_rotation_y(yaw);
        let middle = outer * Mat4::from_rotation_x(pitch);
        let inner = middle * Mat4::from_rotation_z(roll);
        let locked = self.axles_angle_deg() < 5.0;
        let [c_outer, c_middle, c_inner] = GIMBAL_COLORS;
        frame.grid(8, 0.5);
        // The stand holds the outer ring's bearings on the world's y axis.
        frame.wide_line(Vec3::ZERO, center - Vec3::Y * 1.35, palette::GREY, 4.0);
        frame.wide_line(
            center + Vec3::Y * 1.35,
            center + Vec3::Y * 1.6,
            palette::GREY,
            4.0,
        );
        let warn = |c: Vec3| if locked { LOCK_WARNING } else { c };
        let rings = [
            (outer, Vec3::X, Vec3::Y, 1.3, warn(c_outer)),
            (middle, Vec3::X, Vec3::Z, 1.1, warn(c_middle)),
            (inner, Vec3::Y, Vec3::Z, 0.9, c_inner),
        ];
        for (m, u, v, radius, color) in rings {
            ring(frame, m, u, v, radius, color);
        }
        // Each ring's axle, in the colour of the ring it turns, with its bearings on the ring,
        // and a thin line on to its name past the outer ring: the axle's tips lie on the rings,
        // where a name would cover them. Over the rings and the aeroplane: at gimbal lock an axle
        // lies in a ring's plane, inside its edge on screen.
        let axles = [
            (base, Vec3::Y, 1.3, c_outer, "yaw axle"),
            (outer, Vec3::X, 1.1, c_middle, "pitch axle"),
            (middle, Vec3::Z, 0.9, c_inner, "roll axle"),
        ];
        for (m, axis, len, color, _) in axles {
            let a = m.transform_point3(-axis * len);
            let b = m.transform_point3(axis * len);
            let over = |width_px| crate::draw::StrokeStyle {
                on_top: true,
                ..crate::draw::StrokeStyle::solid(width_px)
            };
            frame.stroke(&[a, b], color, over(3.0));
            let name_at = m.transform_point3(axis * Self::AXLE_NAME_R);
            frame.stroke(&[b, name_at], color, over(1.5));
            frame.marker(a, crate::draw::DOT_PX, color);
            frame.marker(b, crate::draw::DOT_PX, color);
        }
        // Each name beside its line's end, on the side away from the centre on the last
        // frame's view when that covers no line, dot, name or ring (first the side facing
        // away). The rings are meshes, which the frame's own test does not see: their centre
        // lines are sampled here, every 4.5°, and kept 4 px (about their half thickness) off.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let ring_points: Vec<glam::Vec2> = view
            .map(|(view_proj, size)| {
                rings
                    .iter()
                    .flat_map(|&(m, u, v, radius, _)| {
                        (0..80).filter_map(move |k| {
                            let phi = k as f32 / 80.0 * std::f32::consts::TAU;
                            let p = m.transform_point3((u * phi.cos() + v * phi.sin()) * radius);
                            crate::camera::project_to_canvas(view_proj, size, p)
                        })
                    })
                    .collect()
            })
            .unwrap_or_default();
        let off_the_rings = |rect: crate::draw::layout::Rect| {
            let (lo, hi) = (rect.min - 4.0, rect.max() + 4.0);
            ring_points
                .iter()
                .all(|c| !(c.cmpgt(lo).all() && c.cmplt(hi).all()))
        };
        for (m, axis, _, color, name) in axles {
            let end = m.transform_point3(axis * Self::AXLE_NAME_R);
            let toward = view
                .and_then(|(view_proj, size)| {
                    let at = |p| crate::camera::project_to_canvas(view_proj, size, p);
                    Some(at(end)? - at(center)?)
                })
                .unwrap_or(glam::Vec2::X);
            let candidates =
                crate::draw::Label::around_dot(end, 4.0, toward, name, color, 0, 10, 8.0);
            frame.first_clear_label_by(view, 2.0, candidates, off_the_rings);
        }
        draw_plane(
            frame,
            center,
            Mat3::from_mat4(inner),
            Vec3::splat(0.75),
            1.2,
        );
    }
}

/// An angle in degrees wrapped to (−180, 180].
fn wrap_deg(a: f32) -> f32 {
    let w = (a + 180.0).rem_euclid(360.0) - 180.0;
    if w == -180.0 {
        180.0
    } else {
        w
    }
}

/// Colours of Figure 4, as the page's words name them.
pub mod rodrigues_colors {
    use super::palette;
    use glam::Vec3;
    pub const AXIS: Vec3 = palette::PURPLE;
    pub const V: Vec3 = palette::DARK;
    pub const ROTATED: Vec3 = palette::PINK;
    pub const COS_PART: Vec3 = palette::ORANGE;
    pub const SIN_PART: Vec3 = palette::TEAL;
    pub const AXIAL_PART: Vec3 = palette::BROWN;
    pub const CIRCLE: Vec3 = palette::GREY;
}

/// Where Figure 4 draws the box that the quaternion of the rotation turns.
pub const QUAT_BOX_AT: Vec3 = Vec3::new(-1.6, 0.2, -0.6);

/// Figure 4: Rodrigues' formula. A vector `v` turns about the unit axis `n` by `θ`:
/// ```text
/// v′ = v cos θ + (n × v) sin θ + n (n·v)(1 − cos θ)
/// ```
/// The figure draws `n`, `v`, the three terms tip to tail (they end at `v′`), `v′ = R v` and the
/// circle the tip sweeps.
pub struct Rodrigues {
    axis: AxisAngle,
    v: Vec3,
    use_exercise: bool,
    runner: Runner,
    arc: Vec<Vec3>,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the terms' labels
    /// take places beside their arrows that cover no line.
    view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
}

impl Default for Rodrigues {
    fn default() -> Self {
        Self::new()
    }
}

impl Rodrigues {
    pub fn new() -> Self {
        Rodrigues {
            axis: AxisAngle {
                axis: Vec3::new(0.3, 1.0, 0.2).normalize(),
                angle_rad: 120.0 * DEG,
            },
            v: Vec3::new(1.2, 0.4, 0.3),
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            arc: Vec::with_capacity(129),
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the terms' labels are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    /// Sets the axis (any non-zero direction; it is normalised) and the angle in degrees.
    pub fn set_axis_angle(&mut self, axis: Vec3, angle_deg: f32) -> Result<(), String> {
        let angle = finite("angle", angle_deg)? * DEG;
        self.axis = AxisAngle::new(axis, angle).map_err(|e| e.to_string())?;
        Ok(())
    }

    /// Sets the vector `v` that turns (metres).
    pub fn set_vector(&mut self, v: Vec3) -> Result<(), String> {
        self.v = Vec3::new(
            finite("v.x", v.x)?,
            finite("v.y", v.y)?,
            finite("v.z", v.z)?,
        );
        Ok(())
    }

    /// Uses the student's `rodrigues_matrix` (3.3) and `quat_from_axis_angle` (3.1).
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// `R(θ)` (3×3) of the whole rotation, the student's when used and usable.
    pub fn matrix(&self) -> Mat3 {
        self.matrix_at(self.axis.angle_rad)
    }

    /// The quaternion of the whole rotation, the student's when used and usable.
    pub fn quaternion(&self) -> Quat {
        self.quat_at(self.axis.angle_rad)
    }

    fn matrix_at(&self, angle_rad: f32) -> Mat3 {
        self.use_exercise
            .then(|| run::rodrigues_matrix(self.runner, self.axis.axis, angle_rad).ok())
            .flatten()
            .filter(|m| m.is_finite())
            .unwrap_or_else(|| rotation::rodrigues_mat3(self.axis.axis, angle_rad))
    }

    fn quat_at(&self, angle_rad: f32) -> Quat {
        self.use_exercise
            .then(|| run::quat_from_axis_angle(self.runner, self.axis.axis, angle_rad).ok())
            .flatten()
            .filter(|q| q.is_finite() && q.length() > 1e-6)
            .map(|q| q.normalize())
            .unwrap_or_else(|| rotation::quat_from_axis_angle(self.axis.axis, angle_rad))
    }

    /// Adds a term's label beside its arrow from `from` to `to`: the first place that covers no
    /// line, dot or label already placed on the last frame's view (the middle itself, above and
    /// right, without one). Places beside its tip go across the arrow on the canvas, on the
    /// side away from `away` (the next term's tip) first, then across and back towards its
    /// tail, then round the tip, 0 to 40 px out. With `tip_first` (v cos θ, whose shaft runs
    /// along v, and the sin term, whose short shaft lies between v and v′), a place beside the
    /// middle would read as another arrow's: the places at its tip come first, then those beside
    /// its middle, nearer either end, and further out (12 to 60 px).
    /// Without, the places beside the shaft up to 12 px out come first, then those at the tip
    /// up to 8 px out, then the shaft's further out, then the tip's: a crowded shaft keeps its
    /// name at its tip rather than 60 px away. No place holds one of `box_points` (the box turned by q).
    fn label_beside_arrow(
        &self,
        frame: &mut Frame,
        (from, to): (Vec3, Vec3),
        text: &str,
        color: Vec3,
        (away, tip_first): (Vec3, bool),
        box_points: &[Vec3],
    ) {
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let mut at_tip = Vec::new();
        if let Some((view_proj, size)) = view {
            let px = |p| crate::camera::project_to_canvas(view_proj, size, p);
            if let (Some(a), Some(b), Some(c)) = (px(from), px(to), px(away)) {
                let mut across = (b - a).normalize_or_zero().perp();
                if across.dot(c - b) > 0.0 {
                    across = -across;
                }
                // The nearest of the eight sides of a dot (22.5° either side of each).
                let side = |d: glam::Vec2| {
                    let s = |x: f32| if x.abs() > 0.38 { x.signum() } else { 0.0 };
                    glam::Vec2::new(s(d.x), s(d.y))
                };
                let back = (a - b).normalize_or_zero();
                let sides = [
                    across,
                    -across,
                    across + back,
                    back - across,
                    back,
                    across - back,
                    -across - back,
                ];
                for out_px in [0.0, 8.0, 16.0, 24.0, 32.0, 40.0] {
                    for d in sides.map(|d| d.normalize_or_zero()) {
                        if d != glam::Vec2::ZERO {
                            at_tip.push(crate::draw::Label::off_dot(
                                to,
                                12.0 + 2.0 * out_px,
                                side(d),
                                text.into(),
                                color,
                                0,
                            ));
                        }
                    }
                }
            }
        }
        let sides = [
            (1.0, -1.0),
            (-1.0, 1.0),
            (-1.0, -1.0),
            (1.0, 1.0),
            (0.0, -1.0),
            (0.0, 1.0),
            (1.0, 0.0),
            (-1.0, 0.0),
        ]
        .map(|(x, y)| glam::Vec2::new(x, y));
        // The shaft as a dot this wide: the label keeps LABEL_DOT_GAP_PX off its stroke.
        const SHAFT_PX: f32 = 2.0 * crate::draw::ARROW_PX;
        let shaft = |outs: &[f32]| -> Vec<crate::draw::Label> {
            (outs.iter())
                .flat_map(|&out_px| {
                    [0.5, 0.35, 0.65, 0.2, 0.8].into_iter().flat_map(move |t| {
                        sides.map(|side| {
                            let at = from.lerp(to, t);
                            let clear_px = SHAFT_PX + 2.0 * out_px;
                            crate::draw::Label::off_dot(at, clear_px, side, text.into(), color, 0)
                        })
                    })
                })
                .collect()
        };
        // The tip's places 0 and 8 px out: 7 sides each.
        let tip_far = at_tip.split_off(at_tip.len().min(14));
        let (near, far) = (shaft(&[0.0, 12.0]), shaft(&[24.0, 36.0, 48.0, 60.0]));
        // 2 px off the lines: a label that touches an arrow reads as part of it.
        let candidates = if tip_first {
            [at_tip, tip_far, near, far]
        } else {
            [near, at_tip, far, tip_far]
        }
        .concat();
        let box_px: Vec<glam::Vec2> = view.map_or(Vec::new(), |(view_proj, size)| {
            (box_points.iter())
                .filter_map(|&p| crate::camera::project_to_canvas(view_proj, size, p))
                .collect()
        });
        frame.first_clear_label_by(view, 2.0, candidates, |r| {
            box_px.iter().all(|&c| r.nearest(c).distance(c) > 2.0)
        });
    }

    /// Draws the rotation swept up to `s · θ`, `s ∈ [0, 1]`. Returns the note about the exercises.
    pub fn draw(&mut self, frame: &mut Frame, s: f32) -> Result<String, String> {
        use rodrigues_colors::*;
        let s = in_range("s", s, 0.0, 1.0)?;
        let (n, v) = (self.axis.axis, self.v);
        let phi = s * self.axis.angle_rad;
        frame.grid(8, 0.5);
        // The axis n, both ways through the origin. Its line is twice as wide as the arrows and
        // drawn first: with v along the axis, v, v′ and the terms lie on it, and its purple
        // still shows either side of them.
        frame.wide_line(-n * 2.0, n * 2.0, AXIS, 2.0 * crate::draw::ARROW_PX);
        frame.arrow(Vec3::ZERO, n * 2.0, AXIS, 0.15);
        // The circle the tip sweeps, about its centre n (n·v).
        let centre = n * n.dot(v);
        self.arc.clear();
        self.arc.extend(
            (0..=128).map(|k| {
                rotation::rodrigues_rotate(v, n, std::f32::consts::TAU * k as f32 / 128.0)
            }),
        );
        let circle_from = frame.strokes.len();
        frame.wide_polyline(&self.arc, CIRCLE, crate::draw::CURVE_PX);
        let circle = circle_from..frame.strokes.len();
        frame.marker(centre, crate::draw::DOT_PX, AXIS);
        // The three terms of the formula, tip to tail: they end at v′.
        let cos_part = v * phi.cos();
        let sin_part = n.cross(v) * phi.sin();
        let axial_part = n * n.dot(v) * (1.0 - phi.cos());
        let (p1, p2) = (cos_part, cos_part + sin_part);
        // v cos θ lies along v: v is drawn over it, so that v shows whole and the term's orange
        // head marks where the term ends on it.
        frame.arrow(Vec3::ZERO, p1, COS_PART, 0.1);
        frame.arrow(Vec3::ZERO, v, V, 0.12);
        // A term's label only when the term is long enough to carry it (labels of short terms
        // all land on the same spot near the tip of v′).
        const LABELLED: f32 = 0.25;
        let mut terms = Vec::new();
        if cos_part.length() > LABELLED {
            terms.push((Vec3::ZERO, p1, "v cos θ", COS_PART, (p2, true)));
        }
        frame.arrow(p1, p2, SIN_PART, 0.1);
        let p3 = p2 + axial_part;
        if sin_part.length() > LABELLED {
            // At its tip first: beside its short shaft the name reads as v′'s or v cos θ's.
            terms.push((p1, p2, "(n × v) sin θ", SIN_PART, (p3, true)));
        }
        frame.arrow(p2, p3, AXIAL_PART, 0.1);
        if axial_part.length() > LABELLED {
            let text = "n (n·v)(1 − cos θ)";
            terms.push((p2, p3, text, AXIAL_PART, (Vec3::ZERO, false)));
        }
        // v′ = R(sθ) v, from the matrix (the student's when used).
        let turned = self.matrix_at(phi) * v;
        frame.arrow(Vec3::ZERO, turned, ROTATED, 0.14);
        // A small box turned by the quaternion of the same rotation, beside the arrows so that
        // it hides none of them and their labels.
        let q = self.quat_at(phi);
        let place = Mat4::from_translation(QUAT_BOX_AT) * Mat4::from_quat(q);
        frame.mesh(
            MeshId::CUBE,
            place * Mat4::from_scale(Vec3::new(0.22, 0.12, 0.08)),
            palette::GREY,
        );
        frame.axes(place, 0.4);
        // The names, once every arrow is down, each at the first place round its anchor (right
        // first, then further out) on the last frame's view that covers no line, dot or name
        // placed before it, nor the box: with v along the axis, n, v, v′ and the box all meet
        // near the origin on the screen. n beside its shaft, below the tip (at the tip the name
        // leaves the top of the canvas); v at its tip; v′ just past its tip (the last term's
        // label sits near the tip when that term is short); the box's name beside the box, left
        // first, away from the circle (the box stands left of it in the page's view; a grey
        // name on the grey circle reads as the circle's).
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // The box's points on a 3 × 3 × 3 grid: its corners, edges' and faces' middles, so that
        // a name over part of the box holds one of them.
        let box_points: Vec<Vec3> = (0..27)
            .map(|c| {
                let s = |k: i32| ((c / k) % 3 - 1) as f32;
                place.transform_point3(Vec3::new(0.22 * s(1), 0.12 * s(3), 0.08 * s(9)))
            })
            .collect();
        // The box's width on the last frame's view, as a dot's: twice its farthest corner.
        let box_px = view.map_or(0.0, |(view_proj, size)| {
            let px = |p| crate::camera::project_to_canvas(view_proj, size, p);
            box_points
                .iter()
                .filter_map(|&p| Some(px(p)?.distance(px(QUAT_BOX_AT)?)))
                .fold(0.0, f32::max)
                * 2.0
        });
        // Where v′ lies on v (v along the axis, or no turn yet) one name names both.
        let same = turned.distance(v) < 0.02;
        for (at, dot_px, toward, text, color) in [
            (n * 1.7, 0.0, glam::Vec2::X, "n", AXIS),
            (v, 12.0, glam::Vec2::X, if same { "v = v′ = R v" } else { "v" }, V),
            (turned * 1.15, 0.0, glam::Vec2::X, if same { "" } else { "v′ = R v" }, ROTATED),
            (QUAT_BOX_AT, box_px, -glam::Vec2::X, "turned by q", palette::GREY),
        ] {
            if text.is_empty() {
                continue;
            }
            let mut candidates =
                crate::draw::Label::around_dot(at, dot_px, toward, text, color, 0, 10, 8.0);
            if let (Some((view_proj, size)), true) = (view, text == "turned by q") {
                // Places outside the circle first, each part in its order round the box.
                let ring: Vec<glam::Vec2> = (self.arc.iter())
                    .filter_map(|&p| crate::camera::project_to_canvas(view_proj, size, p))
                    .collect();
                let in_ring = |c: glam::Vec2| {
                    // Crossings of a ray to the right of c with the circle's edges: odd inside.
                    let edges = ring.iter().zip(ring.iter().cycle().skip(1));
                    edges
                        .filter(|(a, b)| {
                            (a.y > c.y) != (b.y > c.y)
                                && c.x < a.x + (c.y - a.y) / (b.y - a.y) * (b.x - a.x)
                        })
                        .count()
                        % 2
                        == 1
                };
                let (outside, inside): (Vec<_>, Vec<_>) =
                    candidates.into_iter().partition(|l| {
                        l.first_place(view_proj, size).is_some_and(|r| {
                            ![r.min, r.max(), r.min + 0.5 * r.size].into_iter().any(in_ring)
                        })
                    });
                candidates = outside;
                candidates.extend(inside);
            }
            frame.first_clear_label_by(view, 2.0, candidates, super::clear_of(view, &box_points));
        }
        // Last, once every arrow and the other labels are down: the terms run tip to tail
        // beside v, v′ and the circle, so a label at a term's middle lies on some arrow. The
        // names of the sin and axial terms may cross the thin grey circle (set aside while they
        // are placed): inside it the arrows leave no room beside those terms for a name that
        // keeps off the circle too. v cos θ's name (the first term) keeps off it.
        let mut set_aside = Vec::new();
        for (from, to, text, color, away) in terms {
            if text != "v cos θ" && set_aside.is_empty() {
                set_aside = frame.strokes.drain(circle.clone()).collect();
            }
            self.label_beside_arrow(frame, (from, to), text, color, away, &box_points);
        }
        frame.strokes.extend(set_aside);
        // The axis, the circle (which holds v and v′) and the box stay in view.
        frame.keep_in_view.extend(self.arc.iter().step_by(8));
        frame.keep_in_view.extend([
            n * 2.0,
            -n * 2.0,
            QUAT_BOX_AT + Vec3::splat(0.4),
            QUAT_BOX_AT - Vec3::splat(0.4),
        ]);
        Ok(if self.use_exercise {
            self.exercise_note()
        } else {
            String::new()
        })
    }

    /// Compares the student's 3.3 matrix and 3.1 quaternion with the reference at the current
    /// axis and angle θ and at a few probe inputs ([`rodrigues_probes`]), and checks that they are
    /// a rotation and a unit quaternion.
    pub fn exercise_note(&self) -> String {
        let (n, theta) = (self.axis.axis, self.axis.angle_rad);
        let at = format!("θ = {}°", format_number(theta / DEG));
        let inputs: Vec<(String, Vec3, f32)> = std::iter::once((at.clone(), n, theta))
            .chain(rodrigues_probes(n))
            .collect();
        let matrix = (|| {
            let mut probes = Vec::new();
            for (at, axis, angle) in &inputs {
                let m = run::rodrigues_matrix(self.runner, *axis, *angle)?;
                probes.push(Probe {
                    at: at.clone(),
                    yours: m.to_cols_array().to_vec(),
                    reference: rotation::rodrigues_mat3(*axis, *angle)
                        .to_cols_array()
                        .to_vec(),
                });
            }
            Ok(probes)
        })();
        let matrix = match matrix {
            Err(f) => failure_note("exercise 3.3 rodrigues_matrix", FILE, &f),
            Ok(probes) => {
                let (all_match, mut note) = probe_note("rodrigues_matrix", &probes, TOLERANCE);
                if !all_match {
                    // The table under the figure shows rows: say which order these are in.
                    note += " Both matrices are listed column by column (glam's order); the \
                             table under the figure shows rows.";
                }
                let shown = Mat3::from_cols_slice(&probes[0].yours);
                if let Some(problem) = rotation_problem(shown, 1e-3) {
                    note += &format!(" Your matrix at {at}: {problem}.");
                }
                note
            }
        };
        let quat = (|| {
            let mut probes = Vec::new();
            for (at, axis, angle) in &inputs {
                let q = run::quat_from_axis_angle(self.runner, *axis, *angle)?;
                let reference = rotation::quat_from_axis_angle(*axis, *angle);
                // θ and θ + 2π give q and −q, one rotation: compare with the closer sign.
                let aligned = if q.dot(reference) < 0.0 { -q } else { q };
                probes.push(Probe {
                    at: at.clone(),
                    yours: aligned.to_array().to_vec(),
                    reference: reference.to_array().to_vec(),
                });
            }
            Ok(probes)
        })();
        let quat = match quat {
            Err(f) => failure_note("exercise 3.1 quat_from_axis_angle", FILE, &f),
            Ok(probes) => {
                let (_, mut note) = probe_note("quat_from_axis_angle", &probes, TOLERANCE);
                let shown = Quat::from_slice(&probes[0].yours);
                if let Some(problem) = unit_quat_problem(shown, 1e-3) {
                    note += &format!(" Your quaternion at {at}: {problem}.");
                }
                note
            }
        };
        format!("{matrix} {quat}")
    }
}

/// Where the student's 3.1 and 3.3 are checked besides the figure's axis and angle: no turn, a
/// half turn, a quarter turn about x (a transposed matrix or a full-angle quaternion shows
/// there, while a half turn hides a transposition), and −90° about the figure's axis.
pub fn rodrigues_probes(n: Vec3) -> Vec<(String, Vec3, f32)> {
    vec![
        ("θ = 0°".into(), n, 0.0),
        ("θ = 180°".into(), n, 180.0 * DEG),
        ("θ = 90° about x".into(), Vec3::X, 90.0 * DEG),
        ("θ = −90°".into(), n, -90.0 * DEG),
    ]
}
