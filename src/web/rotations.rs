//! Bindings for lesson 03, "Rotations": one object interpolated four ways, a three-ring gimbal,
//! and Rodrigues' formula. Validation errors carry the core's [`RotationError`] message.

use super::{finite, in_range, Viewer};
use crate::exercises::{self, NotDone};
use crate::render::MeshId;
use crate::rotation::{
    self, check_quat, check_rotation_mat3, euler_lerp, mat3_from_quat, mat3_lerp_report, nlerp_arc,
    slerp_arc, Arc, AxisAngle, EulerAngles, EulerOrder, RotationError,
};
use glam::{Mat3, Mat4, Quat, Vec3};
use wasm_bindgen::prelude::*;

const DEG: f32 = std::f32::consts::PI / 180.0;

pub(crate) fn js_error(e: RotationError) -> JsError {
    JsError::new(&e.to_string())
}

/// The little aeroplane every figure turns: body, wings and a tail fin, so that any orientation
/// (and any shear) is easy to read. Drawn with `linear` (any 3×3, not only rotations) at `at`.
pub(crate) fn draw_plane(
    frame: &mut crate::render::Frame,
    cube: MeshId,
    at: Vec3,
    linear: Mat3,
    color: Vec3,
    size: f32,
) {
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
            Vec3::new(0.85, 0.2, 0.2),
        ),
        (
            Vec3::new(0.5, 0.0, 0.0),
            Vec3::new(0.06, 0.06, 0.06),
            Vec3::new(0.95, 0.85, 0.2),
        ),
    ];
    for (center, half, c) in parts {
        frame.mesh(
            cube,
            place * Mat4::from_translation(center) * Mat4::from_scale(half),
            c,
        );
    }
}

fn mat3_cols(values: &[f32]) -> Result<Mat3, JsError> {
    if values.len() != 9 {
        return Err(JsError::new(&format!(
            "a 3×3 matrix needs 9 numbers (column-major), got {}",
            values.len()
        )));
    }
    Ok(Mat3::from_cols_slice(values))
}

/// The four ways of getting from one orientation to another, side by side.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Method {
    MatrixLerp,
    EulerLerp,
    Nlerp,
    Slerp,
}

const METHODS: [(Method, f32, [f32; 3]); 4] = [
    (Method::MatrixLerp, -3.3, [0.85, 0.3, 0.25]),
    (Method::EulerLerp, -1.1, [0.9, 0.6, 0.1]),
    (Method::Nlerp, 1.1, [0.2, 0.65, 0.35]),
    (Method::Slerp, 3.3, [0.2, 0.45, 0.9]),
];

/// Figure 1: one aeroplane, two key orientations, interpolated by matrix lerp, Euler-angle lerp,
/// nlerp and slerp (left to right), with the path of the nose over the whole interpolation.
#[wasm_bindgen]
pub struct InterpolationScene {
    start: EulerAngles,
    end: EulerAngles,
    start_quat: Quat,
    end_quat: Quat,
    arc: Arc,
    use_exercise: bool,
    path: Vec<Vec3>,
}

#[wasm_bindgen]
impl InterpolationScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> InterpolationScene {
        let mut scene = InterpolationScene {
            start: EulerAngles::new(EulerOrder::IntrinsicXYZ, Vec3::ZERO),
            end: EulerAngles::new(EulerOrder::IntrinsicXYZ, Vec3::ZERO),
            start_quat: Quat::IDENTITY,
            end_quat: Quat::IDENTITY,
            arc: Arc::Short,
            use_exercise: false,
            path: Vec::with_capacity(65),
        };
        scene.set_keys(
            Vec3::new(-20.0, 10.0, 0.0) * DEG,
            Vec3::new(150.0, 20.0, 120.0) * DEG,
        );
        scene
    }

    fn set_keys(&mut self, start_rad: Vec3, end_rad: Vec3) {
        self.start = EulerAngles::new(EulerOrder::IntrinsicXYZ, start_rad);
        self.end = EulerAngles::new(EulerOrder::IntrinsicXYZ, end_rad);
        self.start_quat = self.start.to_quat();
        self.end_quat = self.end.to_quat();
    }

    /// Sets both keys as intrinsic X-Y′-Z″ Euler angles, in degrees.
    #[wasm_bindgen(js_name = setKeysEulerDeg)]
    pub fn set_keys_euler_deg(
        &mut self,
        ax: f32,
        ay: f32,
        az: f32,
        bx: f32,
        by: f32,
        bz: f32,
    ) -> Result<(), JsError> {
        let a = Vec3::new(
            finite("start x", ax)?,
            finite("start y", ay)?,
            finite("start z", az)?,
        );
        let b = Vec3::new(
            finite("end x", bx)?,
            finite("end y", by)?,
            finite("end z", bz)?,
        );
        self.set_keys(a * DEG, b * DEG);
        Ok(())
    }

    /// Sets the end key as a quaternion `(x, y, z, w)`; it is normalised. A zero or NaN quaternion
    /// is rejected. The Euler-lerp key becomes its Euler decomposition.
    #[wasm_bindgen(js_name = setEndQuat)]
    pub fn set_end_quat(&mut self, x: f32, y: f32, z: f32, w: f32) -> Result<(), JsError> {
        let q = check_quat(Quat::from_xyzw(x, y, z, w)).map_err(js_error)?;
        self.end_quat = q;
        self.end = EulerAngles::from_quat(q, EulerOrder::IntrinsicXYZ);
        Ok(())
    }

    /// Sets the end key as a rotation matrix (9 numbers, column-major); a matrix that is not
    /// orthonormal, or that mirrors, is rejected.
    #[wasm_bindgen(js_name = setEndMatrix)]
    pub fn set_end_matrix(&mut self, cols: Vec<f32>) -> Result<(), JsError> {
        let r = check_rotation_mat3(mat3_cols(&cols)?).map_err(js_error)?;
        self.end_quat = rotation::quat_from_mat3(r);
        self.end = EulerAngles::from_mat3(r, EulerOrder::IntrinsicXYZ);
        Ok(())
    }

    /// `true`: nlerp and slerp take the long arc (they use `−q` for the end key).
    #[wasm_bindgen(js_name = setLongArc)]
    pub fn set_long_arc(&mut self, long: bool) {
        self.arc = if long { Arc::Long } else { Arc::Short };
    }

    /// Uses the student's `slerp` (exercise 3.2) for the slerp object.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// The end key's quaternion `(x, y, z, w)` as used on the current arc (negated on the long arc
    /// when needed), for the page to show q vs −q.
    #[wasm_bindgen(js_name = endQuatUsed)]
    pub fn end_quat_used(&self) -> Vec<f32> {
        let d = self.start_quat.dot(self.end_quat);
        let flip = match self.arc {
            Arc::Short => d < 0.0,
            Arc::Long => d > 0.0,
        };
        let q = if flip { -self.end_quat } else { self.end_quat };
        q.to_array().to_vec()
    }

    /// Draws the four objects at `t ∈ [0, 1]`. Returns a note: empty, or about the exercise.
    pub fn draw(&mut self, viewer: &mut Viewer, t: f32) -> Result<String, JsError> {
        let t = in_range("t", t, 0.0, 1.0)?;
        let (note, student) = self.student_ok();
        let frame = &mut viewer.renderer.frame;
        frame.grid(16, 0.5);
        for (method, x, color) in METHODS {
            let at = Vec3::new(x, 1.2, 0.0);
            let color = Vec3::from_array(color);
            // The nose's path over the whole interpolation, and the keys' noses.
            self.path.clear();
            for k in 0..=64 {
                let m = self.orientation(method, k as f32 / 64.0, student);
                self.path.push(at + m * Vec3::new(0.55, 0.0, 0.0));
            }
            frame.polyline(&self.path, color * 0.8);
            frame.point(self.path[0], 0.04, Vec3::splat(0.3));
            frame.point(self.path[64], 0.04, Vec3::splat(0.05));
            let m = self.orientation(method, t, student);
            draw_plane(frame, viewer.renderer.cube, at, m, color, 1.0);
            frame.axes(Mat4::from_translation(at) * Mat4::from_mat3(m), 0.6);
        }
        viewer.present()?;
        Ok(note)
    }

    /// Matrix lerp, sampled: `[t₀, det₀, e₀, t₁, …]` with the determinant and the orthogonality
    /// error ‖MᵀM − I‖.
    #[wasm_bindgen(js_name = sampleDeterminant)]
    pub fn sample_determinant(&self, samples: usize) -> Result<Vec<f32>, JsError> {
        super::check_samples(samples)?;
        let (a, b) = (
            mat3_from_quat(self.start_quat),
            mat3_from_quat(self.end_quat),
        );
        let mut out = Vec::with_capacity(samples * 3);
        for k in 0..samples {
            let t = k as f32 / (samples - 1) as f32;
            let s = mat3_lerp_report(a, b, t);
            out.extend_from_slice(&[t, s.determinant, s.orthogonality_error]);
        }
        Ok(out)
    }

    /// Angular speed (degrees per unit of t) of Euler lerp, nlerp and slerp, sampled:
    /// `[t₀, euler₀, nlerp₀, slerp₀, t₁, …]`, by finite differences.
    #[wasm_bindgen(js_name = sampleAngularSpeed)]
    pub fn sample_angular_speed(&self, samples: usize) -> Result<Vec<f32>, JsError> {
        super::check_samples(samples)?;
        let (_, student) = self.student_ok();
        let h = 1e-3;
        let mut out = Vec::with_capacity(samples * 4);
        for k in 0..samples {
            let t = k as f32 / (samples - 1) as f32;
            let (t0, t1) = ((t - h).max(0.0), (t + h).min(1.0));
            out.push(t);
            for method in [Method::EulerLerp, Method::Nlerp, Method::Slerp] {
                let q0 = rotation::quat_from_mat3(self.orientation(method, t0, student));
                let q1 = rotation::quat_from_mat3(self.orientation(method, t1, student));
                out.push(rotation::angle_between(q0, q1) / (t1 - t0) / DEG);
            }
        }
        Ok(out)
    }
}

impl Default for InterpolationScene {
    fn default() -> Self {
        Self::new()
    }
}

impl InterpolationScene {
    /// Whether the student's slerp can drive the figure, and the note that says so.
    fn student_ok(&self) -> (String, bool) {
        if !self.use_exercise {
            return (String::new(), false);
        }
        match exercises::rotations::slerp(self.start_quat, self.end_quat, 0.5) {
            Err(NotDone) => (
                "Not done yet: exercise 3.2 slerp (src/exercises/rotations.rs). The figure uses the reference.".into(),
                false,
            ),
            Ok(_) if self.arc == Arc::Long => {
                ("Your slerp takes the short arc, as it should: the long-arc object uses the reference.".into(), false)
            }
            Ok(_) => ("Showing your slerp (blue, right).".into(), true),
        }
    }

    fn orientation(&self, method: Method, t: f32, student: bool) -> Mat3 {
        let (a, b) = (self.start_quat, self.end_quat);
        match method {
            Method::MatrixLerp => rotation::mat3_lerp(mat3_from_quat(a), mat3_from_quat(b), t),
            Method::EulerLerp => euler_lerp(self.start, self.end, t).to_mat3(),
            Method::Nlerp => mat3_from_quat(nlerp_arc(a, b, t, self.arc)),
            Method::Slerp => {
                let q = if student {
                    exercises::rotations::slerp(a, b, t)
                        .ok()
                        .filter(|q| q.is_finite() && q.length() > 1e-6)
                } else {
                    None
                };
                mat3_from_quat(
                    q.map(|q| q.normalize())
                        .unwrap_or_else(|| slerp_arc(a, b, t, self.arc)),
                )
            }
        }
    }
}

/// Points on a circle of `radius` in the plane spanned by `u` and `v`, as thin boxes.
fn ring(
    frame: &mut crate::render::Frame,
    cube: MeshId,
    m: Mat4,
    u: Vec3,
    v: Vec3,
    radius: f32,
    color: Vec3,
) {
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
        frame.mesh(cube, m * model, color);
    }
}

/// Figure 2: a three-ring gimbal for intrinsic Y-X′-Z″ angles (yaw, pitch, roll). The outer ring
/// turns about the world's y axis, the middle one about the outer ring's x axis, the inner one
/// about the middle ring's z axis and carries the aeroplane. At pitch ±90° the inner axis lines up
/// with the outer one: gimbal lock.
#[wasm_bindgen]
pub struct GimbalScene {
    angles_rad: Vec3,
}

#[wasm_bindgen]
impl GimbalScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> GimbalScene {
        GimbalScene {
            angles_rad: Vec3::new(30.0, 0.0, 20.0) * DEG,
        }
    }

    /// Sets (yaw about y, pitch about x′, roll about z″), in degrees.
    #[wasm_bindgen(js_name = setAnglesDeg)]
    pub fn set_angles_deg(&mut self, yaw: f32, pitch: f32, roll: f32) -> Result<(), JsError> {
        self.angles_rad = Vec3::new(
            finite("yaw", yaw)?,
            finite("pitch", pitch)?,
            finite("roll", roll)?,
        ) * DEG;
        Ok(())
    }

    /// Angle between the outer (yaw) and inner (roll) axes, in degrees: 0 at gimbal lock.
    #[wasm_bindgen(js_name = axesAngleDeg)]
    pub fn axes_angle_deg(&self) -> f32 {
        let (outer, inner) = self.axes();
        outer.dot(inner).abs().min(1.0).acos() / DEG
    }

    /// The same orientation read back as Y-X′-Z″ angles by the core (degrees), and 1 if the core
    /// flags gimbal lock there: `[yaw, pitch, roll, lock]`.
    #[wasm_bindgen(js_name = decomposedDeg)]
    pub fn decomposed_deg(&self) -> Vec<f32> {
        let e = EulerAngles::from_mat3(self.rotation(), EulerOrder::IntrinsicYXZ);
        let a = e.angles_rad / DEG;
        vec![a.x, a.y, a.z, if e.gimbal_lock { 1.0 } else { 0.0 }]
    }

    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<(), JsError> {
        let [yaw, pitch, roll] = self.angles_rad.to_array();
        let center = Vec3::new(0.0, 1.5, 0.0);
        let base = Mat4::from_translation(center);
        let outer = base * Mat4::from_rotation_y(yaw);
        let middle = outer * Mat4::from_rotation_x(pitch);
        let inner = middle * Mat4::from_rotation_z(roll);
        let locked = self.axes_angle_deg() < 5.0;
        let warn = Vec3::new(0.9, 0.15, 0.1);
        let (c_outer, c_middle, c_inner) = (
            Vec3::new(0.25, 0.65, 0.3),
            Vec3::new(0.8, 0.25, 0.25),
            Vec3::new(0.25, 0.4, 0.9),
        );
        let cube = viewer.renderer.cube;
        let frame = &mut viewer.renderer.frame;
        frame.grid(8, 0.5);
        // The stand holds the outer ring's bearings on the world's y axis.
        frame.line(Vec3::ZERO, center - Vec3::Y * 1.35, Vec3::splat(0.3));
        frame.line(
            center + Vec3::Y * 1.35,
            center + Vec3::Y * 1.6,
            Vec3::splat(0.3),
        );
        ring(
            frame,
            cube,
            outer,
            Vec3::X,
            Vec3::Y,
            1.3,
            if locked { warn } else { c_outer },
        );
        ring(
            frame,
            cube,
            middle,
            Vec3::X,
            Vec3::Z,
            1.1,
            if locked { warn * 0.8 } else { c_middle },
        );
        ring(frame, cube, inner, Vec3::Y, Vec3::Z, 0.9, c_inner);
        // Each ring's axle, in the colour of the ring it turns.
        for (m, axis, len, color) in [
            (base, Vec3::Y, 1.3, c_outer),
            (outer, Vec3::X, 1.1, c_middle),
            (middle, Vec3::Z, 0.9, c_inner),
        ] {
            let a = m.transform_point3(-axis * len);
            let b = m.transform_point3(axis * len);
            frame.line(a, b, color);
            frame.point(a, 0.05, color);
            frame.point(b, 0.05, color);
        }
        let plane = Mat3::from_mat4(inner);
        draw_plane(frame, cube, center, plane, Vec3::new(0.75, 0.75, 0.78), 1.2);
        viewer.present()
    }
}

impl Default for GimbalScene {
    fn default() -> Self {
        Self::new()
    }
}

impl GimbalScene {
    fn rotation(&self) -> Mat3 {
        EulerAngles::new(EulerOrder::IntrinsicYXZ, self.angles_rad).to_mat3()
    }

    /// World directions of the outer and inner axles.
    fn axes(&self) -> (Vec3, Vec3) {
        let [yaw, pitch, _] = self.angles_rad.to_array();
        (
            Vec3::Y,
            Mat3::from_rotation_y(yaw) * Mat3::from_rotation_x(pitch) * Vec3::Z,
        )
    }
}

/// Figure 3: Rodrigues' formula. A vector `v` turns about the unit axis `n` by `θ`; the figure
/// draws the axis, the part of `v` along it, the circle its tip sweeps, and `n × v`.
#[wasm_bindgen]
pub struct RodriguesScene {
    axis: AxisAngle,
    v: Vec3,
    use_exercise: bool,
    arc: Vec<Vec3>,
}

#[wasm_bindgen]
impl RodriguesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> RodriguesScene {
        RodriguesScene {
            axis: AxisAngle {
                axis: Vec3::new(0.3, 1.0, 0.2).normalize(),
                angle_rad: 120.0 * DEG,
            },
            v: Vec3::new(1.2, 0.4, 0.3),
            use_exercise: false,
            arc: Vec::with_capacity(129),
        }
    }

    /// Sets the axis (any non-zero direction; it is normalised) and the angle in degrees.
    #[wasm_bindgen(js_name = setAxisAngle)]
    pub fn set_axis_angle(
        &mut self,
        x: f32,
        y: f32,
        z: f32,
        angle_deg: f32,
    ) -> Result<(), JsError> {
        self.axis = AxisAngle::new(Vec3::new(x, y, z), finite("angle", angle_deg)? * DEG)
            .map_err(js_error)?;
        Ok(())
    }

    /// Sets the vector `v` that turns (metres).
    #[wasm_bindgen(js_name = setVector)]
    pub fn set_vector(&mut self, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        self.v = Vec3::new(finite("v.x", x)?, finite("v.y", y)?, finite("v.z", z)?);
        Ok(())
    }

    /// Uses the student's `rodrigues_matrix` (3.3) and `quat_from_axis_angle` (3.1).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// `R(θ)` as a 4×4 column-major matrix, for the page's matrix table.
    pub fn matrix(&self) -> Vec<f32> {
        Mat4::from_mat3(self.matrix_at(self.axis.angle_rad).0)
            .to_cols_array()
            .to_vec()
    }

    /// The quaternion `(x, y, z, w)` of the full rotation.
    pub fn quaternion(&self) -> Vec<f32> {
        self.quat_at(self.axis.angle_rad).0.to_array().to_vec()
    }

    /// Draws the rotation swept up to `s · θ`, `s ∈ [0, 1]`. Returns a note about the exercises.
    pub fn draw(&mut self, viewer: &mut Viewer, s: f32) -> Result<String, JsError> {
        let s = in_range("s", s, 0.0, 1.0)?;
        let n = self.axis.axis;
        let theta = self.axis.angle_rad;
        let (r, r_mine) = self.matrix_at(s * theta);
        let (q, q_mine) = self.quat_at(s * theta);
        let v = self.v;
        let along = n * n.dot(v);
        let frame = &mut viewer.renderer.frame;
        frame.grid(8, 0.5);
        // The axis, through the origin, both ways.
        let purple = Vec3::new(0.55, 0.2, 0.75);
        frame.line(-n * 2.0, n * 2.0, purple);
        frame.point(n * 2.0, 0.06, purple);
        // v (grey), its part along n, the circle its tip sweeps (full in light orange, swept in orange).
        frame.line(Vec3::ZERO, v, Vec3::splat(0.35));
        frame.point(v, 0.045, Vec3::splat(0.35));
        frame.line(along, v, Vec3::splat(0.55));
        frame.point(along, 0.04, purple);
        self.arc.clear();
        for k in 0..=128 {
            self.arc.push(rotation::rodrigues_rotate(
                v,
                n,
                std::f32::consts::TAU * k as f32 / 128.0,
            ));
        }
        frame.polyline(&self.arc, Vec3::new(0.95, 0.8, 0.6));
        self.arc.clear();
        for k in 0..=64 {
            self.arc.push(rotation::rodrigues_rotate(
                v,
                n,
                s * theta * k as f32 / 64.0,
            ));
        }
        frame.polyline(&self.arc, Vec3::new(0.95, 0.5, 0.05));
        // Where the tip ends after the full angle θ.
        frame.point(
            rotation::rodrigues_rotate(v, n, theta),
            0.04,
            Vec3::new(0.95, 0.5, 0.05),
        );
        // n × v: the direction the tip starts moving in, drawn from the circle's centre.
        let cross = n.cross(v);
        frame.line(along, along + cross, Vec3::new(0.1, 0.65, 0.75));
        frame.point(along + cross, 0.035, Vec3::new(0.1, 0.65, 0.75));
        // The rotated vector, from R(sθ) v.
        let turned = r * v;
        frame.line(Vec3::ZERO, turned, Vec3::new(0.85, 0.1, 0.55));
        frame.line(along, turned, Vec3::new(0.85, 0.5, 0.7));
        frame.point(turned, 0.06, Vec3::new(0.85, 0.1, 0.55));
        // A box turned by the quaternion of the same rotation.
        let box_model = Mat4::from_quat(q) * Mat4::from_scale(Vec3::new(0.22, 0.12, 0.08));
        frame.mesh(viewer.renderer.cube, box_model, Vec3::new(0.95, 0.6, 0.2));
        frame.axes(Mat4::from_quat(q), 0.4);
        viewer.present()?;
        if !self.use_exercise {
            return Ok(String::new());
        }
        let mut missing = Vec::new();
        if !r_mine {
            missing.push("exercise 3.3 rodrigues_matrix");
        }
        if !q_mine {
            missing.push("exercise 3.1 quat_from_axis_angle");
        }
        Ok(if missing.is_empty() {
            "Showing your exercises: the pink vector uses your matrix, the box your quaternion."
                .into()
        } else {
            format!("Not done yet: {} (src/exercises/rotations.rs). The figure uses the reference for those.", missing.join(", "))
        })
    }
}

impl Default for RodriguesScene {
    fn default() -> Self {
        Self::new()
    }
}

impl RodriguesScene {
    /// `R` for `angle`, from the student when asked and done; and whether it was the student's.
    fn matrix_at(&self, angle_rad: f32) -> (Mat3, bool) {
        if self.use_exercise {
            if let Ok(m) = exercises::rotations::rodrigues_matrix(self.axis.axis, angle_rad) {
                if m.is_finite() {
                    return (m, true);
                }
            }
        }
        (rotation::rodrigues_mat3(self.axis.axis, angle_rad), false)
    }

    fn quat_at(&self, angle_rad: f32) -> (Quat, bool) {
        if self.use_exercise {
            if let Ok(q) = exercises::rotations::quat_from_axis_angle(self.axis.axis, angle_rad) {
                if q.is_finite() && q.length() > 1e-6 {
                    return (q.normalize(), true);
                }
            }
        }
        (
            rotation::quat_from_axis_angle(self.axis.axis, angle_rad),
            false,
        )
    }
}
