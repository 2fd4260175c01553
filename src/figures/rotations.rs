//! Lesson 03, "Rotations": one aeroplane interpolated four ways, a three-ring gimbal, and
//! Rodrigues' formula. Natively testable; `web::rotations` only wraps these for JavaScript.

use super::{
    compare_note, failure_note, finite, format_number, in_range, palette, rotation_problem,
    unit_quat_problem, Frame, MeshId, Runner, DEFAULT_RUNNER,
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
    let place =
        Mat4::from_translation(at) * Mat4::from_mat3(linear) * Mat4::from_scale(Vec3::splat(size));
    let parts = [
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
    ];
    for (center, half, c) in parts {
        let part = Mat4::from_translation(center) * Mat4::from_scale(half);
        frame.mesh(MeshId::CUBE, place * part, c);
    }
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

/// The nose of the aeroplane, in its own frame.
const NOSE: Vec3 = Vec3::new(0.55, 0.0, 0.0);

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

    /// Draws the four objects at `t ∈ [0, 1]`; returns the note (the arc taken, and the check of
    /// the student's slerp when "use my exercise" is on).
    pub fn draw(&mut self, frame: &mut Frame, t: f32) -> Result<String, String> {
        let t = in_range("t", t, 0.0, 1.0)?;
        let student = self.use_exercise && self.arc == Arc::Short;
        frame.grid(16, 0.5);
        // The four objects, their axes and paths stay in view at any canvas size.
        frame.keep_box_in_view(Vec3::new(-3.9, 0.5, -0.7), Vec3::new(3.9, 1.9, 0.7));
        for (method, x, color) in METHODS {
            let at = Vec3::new(x, 1.2, 0.0);
            self.path.clear();
            for k in 0..=64 {
                let m = self.orientation(method, k as f32 / 64.0, student);
                self.path.push(at + m * NOSE);
            }
            frame.wide_polyline(&self.path, color * 0.8, crate::draw::CURVE_PX);
            frame.point(self.path[0], 0.04, palette::GREY);
            frame.point(self.path[64], 0.04, palette::KEY);
            let m = self.orientation(method, t, student);
            draw_plane(frame, at, m, color, 1.0);
            frame.axes(Mat4::from_translation(at) * Mat4::from_mat3(m), 0.6);
        }
        let mut note = self.arc_note();
        if self.use_exercise {
            note = [note, self.exercise_note(t)].join(" ").trim().to_string();
        }
        Ok(note)
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

    /// Compares the student's slerp with the reference (short arc) at `t`, checks it returns a
    /// unit quaternion, and says which arc it took.
    pub fn exercise_note(&self, t: f32) -> String {
        let (a, b) = (self.start_quat, self.end_quat);
        let yours = match run::slerp(self.runner, a, b, t) {
            Ok(q) => q,
            Err(f) => return failure_note("exercise 3.2 slerp", FILE, &f),
        };
        let reference = rotation::slerp(a, b, t);
        // q and −q are one rotation: compare with the sign that is closer.
        let aligned = if yours.dot(reference) < 0.0 {
            -yours
        } else {
            yours
        };
        let at = format!("t = {}", format_number(t));
        let (_, mut note) = compare_note(
            "slerp",
            &at,
            &aligned.to_array(),
            &reference.to_array(),
            TOLERANCE,
        );
        if let Some(problem) = unit_quat_problem(yours, 1e-3) {
            note += &format!(" Your answer at {at}: {problem}.");
        }
        note += " ";
        note += &self.arc_check();
        if self.arc == Arc::Long {
            note += " (The long-arc figure uses the reference.)";
        }
        note
    }

    /// Whether the student's slerp takes the short arc, judged at the midpoint.
    fn arc_check(&self) -> String {
        let (a, b) = (self.start_quat, self.end_quat);
        let Ok(mid) = run::slerp(self.runner, a, b, 0.5) else {
            return String::new();
        };
        let short = slerp_arc(a, b, 0.5, Arc::Short);
        let long = slerp_arc(a, b, 0.5, Arc::Long);
        let (to_short, to_long) = (angle_between(mid, short), angle_between(mid, long));
        let dot = format_number(a.dot(b));
        if to_short <= 1e-2 {
            format!("Your slerp takes the short arc (a·b = {dot}).")
        } else if to_long <= 1e-2 {
            format!("Your slerp takes the long arc here (a·b = {dot} < 0): negate b when a·b < 0.")
        } else {
            "At t = 0.5 your slerp is on neither arc between the keys.".into()
        }
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

/// Points on a circle of `radius` in the plane spanned by `u` and `v`, as thin boxes.
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
        frame.mesh(MeshId::CUBE, m * model, color);
    }
}

/// Ring colours (outer/yaw, middle/pitch, inner/roll), as the page names them, and the warning
/// colour near gimbal lock.
pub const GIMBAL_COLORS: [Vec3; 3] = [palette::Y_AXIS, palette::ORANGE, palette::Z_AXIS];
pub const LOCK_WARNING: Vec3 = palette::X_AXIS;

/// Figure 2: a three-ring gimbal for intrinsic Y-X′-Z″ angles (yaw, pitch, roll),
/// `R = R_y(yaw) R_x(pitch) R_z(roll)`. At pitch ±90° the inner axle lines up with the outer one.
pub struct Gimbal {
    angles_rad: Vec3,
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
        }
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
        frame.line(Vec3::ZERO, center - Vec3::Y * 1.35, palette::GREY);
        frame.line(
            center + Vec3::Y * 1.35,
            center + Vec3::Y * 1.6,
            palette::GREY,
        );
        let warn = |c: Vec3| if locked { LOCK_WARNING } else { c };
        ring(frame, outer, Vec3::X, Vec3::Y, 1.3, warn(c_outer));
        ring(frame, middle, Vec3::X, Vec3::Z, 1.1, warn(c_middle));
        ring(frame, inner, Vec3::Y, Vec3::Z, 0.9, c_inner);
        // Each ring's axle, in the colour of the ring it turns, labelled at its tip.
        for (m, axis, len, color, name) in [
            (base, Vec3::Y, 1.3, c_outer, "yaw axle"),
            (outer, Vec3::X, 1.1, c_middle, "pitch axle"),
            (middle, Vec3::Z, 0.9, c_inner, "roll axle"),
        ] {
            let a = m.transform_point3(-axis * len);
            let b = m.transform_point3(axis * len);
            frame.line(a, b, color);
            frame.point(a, 0.05, color);
            frame.point(b, 0.05, color);
            frame.label(b, name, color);
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

/// Colours of Figure 3, as the page's words name them.
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

/// Figure 3: Rodrigues' formula. A vector `v` turns about the unit axis `n` by `θ`:
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

    /// Draws the rotation swept up to `s · θ`, `s ∈ [0, 1]`. Returns the note about the exercises.
    pub fn draw(&mut self, frame: &mut Frame, s: f32) -> Result<String, String> {
        use rodrigues_colors::*;
        let s = in_range("s", s, 0.0, 1.0)?;
        let (n, v) = (self.axis.axis, self.v);
        let phi = s * self.axis.angle_rad;
        frame.grid(8, 0.5);
        // The axis n, both ways through the origin, and v.
        frame.line(-n * 2.0, Vec3::ZERO, AXIS);
        frame.arrow(Vec3::ZERO, n * 2.0, AXIS, 0.15);
        // Beside the shaft, below the tip: at the tip the label leaves the top of the canvas.
        frame.label(n * 1.7, "n", AXIS);
        frame.arrow(Vec3::ZERO, v, V, 0.12);
        frame.label(v, "v", V);
        // The circle the tip sweeps, about its centre n (n·v).
        let centre = n * n.dot(v);
        self.arc.clear();
        self.arc.extend(
            (0..=128).map(|k| {
                rotation::rodrigues_rotate(v, n, std::f32::consts::TAU * k as f32 / 128.0)
            }),
        );
        frame.wide_polyline(&self.arc, CIRCLE, crate::draw::CURVE_PX);
        frame.point(centre, 0.035, AXIS);
        // The three terms of the formula, tip to tail: they end at v′.
        let cos_part = v * phi.cos();
        let sin_part = n.cross(v) * phi.sin();
        let axial_part = n * n.dot(v) * (1.0 - phi.cos());
        let (p1, p2) = (cos_part, cos_part + sin_part);
        frame.arrow(Vec3::ZERO, p1, COS_PART, 0.1);
        // A term's label only when the term is long enough to carry it (labels of short terms
        // all land on the same spot near the tip of v′).
        const LABELLED: f32 = 0.25;
        if cos_part.length() > LABELLED {
            frame.label(p1 * 0.5, "v cos θ", COS_PART);
        }
        frame.arrow(p1, p2, SIN_PART, 0.1);
        if sin_part.length() > LABELLED {
            frame.label((p1 + p2) * 0.5, "(n × v) sin θ", SIN_PART);
        }
        frame.arrow(p2, p2 + axial_part, AXIAL_PART, 0.1);
        if axial_part.length() > LABELLED {
            frame.label(p2 + axial_part * 0.5, "n (n·v)(1 − cos θ)", AXIAL_PART);
        }
        // v′ = R(sθ) v, from the matrix (the student's when used).
        let turned = self.matrix_at(phi) * v;
        frame.arrow(Vec3::ZERO, turned, ROTATED, 0.14);
        // Just past the tip: the last term's label sits near the tip when that term is short.
        frame.label(turned * 1.15, "v′ = R v", ROTATED);
        // A small box turned by the quaternion of the same rotation.
        let q = self.quat_at(phi);
        let box_model = Mat4::from_quat(q) * Mat4::from_scale(Vec3::new(0.22, 0.12, 0.08));
        frame.mesh(MeshId::CUBE, box_model, palette::GREY);
        frame.axes(Mat4::from_quat(q), 0.4);
        Ok(if self.use_exercise {
            self.exercise_note()
        } else {
            String::new()
        })
    }

    /// Compares the student's 3.3 matrix and 3.1 quaternion with the reference at the current
    /// axis and angle θ, and checks that they are a rotation and a unit quaternion.
    pub fn exercise_note(&self) -> String {
        let (n, theta) = (self.axis.axis, self.axis.angle_rad);
        let at = format!("θ = {}°", format_number(theta / DEG));
        let matrix = match run::rodrigues_matrix(self.runner, n, theta) {
            Err(f) => failure_note("exercise 3.3 rodrigues_matrix", FILE, &f),
            Ok(m) => {
                let reference = rotation::rodrigues_mat3(n, theta);
                let (_, mut note) = compare_note(
                    "rodrigues_matrix",
                    &at,
                    &m.to_cols_array(),
                    &reference.to_cols_array(),
                    TOLERANCE,
                );
                if let Some(problem) = rotation_problem(m, 1e-3) {
                    note += &format!(" Your matrix: {problem}.");
                }
                note
            }
        };
        let quat = match run::quat_from_axis_angle(self.runner, n, theta) {
            Err(f) => failure_note("exercise 3.1 quat_from_axis_angle", FILE, &f),
            Ok(q) => {
                let reference = rotation::quat_from_axis_angle(n, theta);
                // θ and θ + 2π give q and −q, one rotation: compare with the closer sign.
                let aligned = if q.dot(reference) < 0.0 { -q } else { q };
                let (_, mut note) = compare_note(
                    "quat_from_axis_angle",
                    &at,
                    &aligned.to_array(),
                    &reference.to_array(),
                    TOLERANCE,
                );
                if let Some(problem) = unit_quat_problem(q, 1e-3) {
                    note += &format!(" Your quaternion: {problem}.");
                }
                note
            }
        };
        format!("{matrix} {quat}")
    }
}
