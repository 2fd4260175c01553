//! Bindings for lesson 04, "Rigid motions": one frame moved three ways between two keys, and an
//! affine key pair (scale and shear) interpolated naively vs through polar decomposition.

use super::rotations::{draw_plane, js_error};
use super::{finite, in_range, Viewer};
use crate::exercises::{self, NotDone};
use crate::rigid::{DualQuat, ScrewInterpolator};
use crate::rotation::{self, check_quat, quat_from_mat3, slerp, AffineKey, AxisAngle};
use glam::{Mat3, Mat4, Quat, Vec3};
use wasm_bindgen::prelude::*;

const DEG: f32 = std::f32::consts::PI / 180.0;
const TIP: Vec3 = Vec3::new(0.55, 0.0, 0.0);

#[derive(Clone, Copy, PartialEq, Eq)]
enum Method {
    LerpSlerp,
    DualQuatNlerp,
    Screw,
}

const METHODS: [(Method, [f32; 3]); 3] = [
    (Method::LerpSlerp, [0.9, 0.55, 0.1]),
    (Method::DualQuatNlerp, [0.2, 0.65, 0.35]),
    (Method::Screw, [0.2, 0.45, 0.9]),
];

/// Figure 1: a frame moving from key A to key B by translation lerp + slerp (orange), by dual
/// quaternion linear blending (green) and by screw interpolation (blue), with the paths of its
/// origin and of its nose, and the screw axis of the motion from A to B (purple).
#[wasm_bindgen]
pub struct RigidScene {
    start: DualQuat,
    end: DualQuat,
    screw: ScrewInterpolator,
    use_exercise: bool,
    path: Vec<Vec3>,
}

#[wasm_bindgen]
impl RigidScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> RigidScene {
        let start = DualQuat::from_rotation_translation(Quat::IDENTITY, Vec3::new(-1.5, 0.6, 0.0));
        let end = DualQuat::from_rotation_translation(
            Quat::from_axis_angle(Vec3::new(0.2, 1.0, 0.3).normalize(), 150.0 * DEG),
            Vec3::new(1.5, 1.4, 0.3),
        );
        RigidScene {
            start,
            end,
            screw: ScrewInterpolator::new(start, end),
            use_exercise: false,
            path: Vec::with_capacity(65),
        }
    }

    fn set_end_dq(&mut self, end: DualQuat) {
        self.end = end;
        self.screw = ScrewInterpolator::new(self.start, self.end);
    }

    /// Sets key B: rotation by `angle_deg` about the axis `(ax, ay, az)` (any non-zero
    /// direction), then translation `(tx, ty, tz)`.
    #[wasm_bindgen(js_name = setEnd)]
    #[allow(clippy::too_many_arguments)] // scalars from JavaScript: no tuple types cross the boundary
    pub fn set_end(
        &mut self,
        ax: f32,
        ay: f32,
        az: f32,
        angle_deg: f32,
        tx: f32,
        ty: f32,
        tz: f32,
    ) -> Result<(), JsError> {
        let r = AxisAngle::new(Vec3::new(ax, ay, az), finite("angle", angle_deg)? * DEG)
            .map_err(js_error)?;
        let t = Vec3::new(finite("tx", tx)?, finite("ty", ty)?, finite("tz", tz)?);
        self.set_end_dq(DualQuat::from_rotation_translation(r.to_quat(), t));
        Ok(())
    }

    /// Sets key B from a quaternion `(x, y, z, w)` (normalised; zero or NaN rejected) and a
    /// translation.
    #[wasm_bindgen(js_name = setEndQuat)]
    #[allow(clippy::too_many_arguments)] // scalars from JavaScript: no tuple types cross the boundary
    pub fn set_end_quat(
        &mut self,
        x: f32,
        y: f32,
        z: f32,
        w: f32,
        tx: f32,
        ty: f32,
        tz: f32,
    ) -> Result<(), JsError> {
        let q = check_quat(Quat::from_xyzw(x, y, z, w)).map_err(js_error)?;
        let t = Vec3::new(finite("tx", tx)?, finite("ty", ty)?, finite("tz", tz)?);
        self.set_end_dq(DualQuat::from_rotation_translation(q, t));
        Ok(())
    }

    /// Sets key B from a rigid 4×4 matrix (16 numbers, column-major). A scaled, sheared or
    /// mirroring 3×3 block is rejected: that is not a rigid motion.
    #[wasm_bindgen(js_name = setEndMatrix)]
    pub fn set_end_matrix(&mut self, cols: Vec<f32>) -> Result<(), JsError> {
        let m = mat4_cols(&cols)?;
        self.set_end_dq(DualQuat::from_mat4(m).map_err(js_error)?);
        Ok(())
    }

    /// Builds the dual quaternion keys and moves the green frame's nose with the student's
    /// `dual_quat_apply` (exercise 4.1).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// The screw axis of the motion from A to B: `[dx, dy, dz, px, py, pz, angle_deg, slide]`.
    #[wasm_bindgen(js_name = screwAxis)]
    pub fn screw_axis(&self) -> Vec<f32> {
        let s = (self.end * self.start.conjugate()).screw_axis();
        let mut out = s.direction.to_array().to_vec();
        out.extend_from_slice(&s.point.to_array());
        out.extend_from_slice(&[s.angle_rad / DEG, s.displacement]);
        out
    }

    /// Draws the three frames at `t ∈ [0, 1]`. Returns a note about the exercise.
    pub fn draw(&mut self, viewer: &mut Viewer, t: f32) -> Result<String, JsError> {
        let t = in_range("t", t, 0.0, 1.0)?;
        let (note, student) = self.student_ok();
        let frame = &mut viewer.renderer.frame;
        frame.grid(12, 0.5);
        // The screw axis: the line the relative motion B A⁻¹ turns about and slides along.
        let axis = (self.end * self.start.conjugate()).screw_axis();
        let purple = Vec3::new(0.55, 0.2, 0.75);
        frame.line(
            axis.point - axis.direction * 3.0,
            axis.point + axis.direction * 3.0,
            purple,
        );
        frame.point(axis.point, 0.05, purple);
        // The keys, as thin axes.
        frame.axes(self.start.to_mat4(), 0.5);
        frame.axes(self.end.to_mat4(), 0.5);
        for (method, color) in METHODS {
            let color = Vec3::from_array(color);
            for local in [Vec3::ZERO, TIP] {
                self.path.clear();
                for k in 0..=64 {
                    self.path
                        .push(self.point(method, k as f32 / 64.0, local, student));
                }
                frame.polyline(
                    &self.path,
                    if local == Vec3::ZERO {
                        color * 0.6
                    } else {
                        color
                    },
                );
            }
            let m = self.motion(method, t, student);
            let (r, p) = m.to_rotation_translation();
            draw_plane(
                frame,
                viewer.renderer.cube,
                p,
                Mat3::from_quat(r),
                color,
                1.0,
            );
            frame.axes(m.to_mat4(), 0.45);
        }
        viewer.present()?;
        Ok(note)
    }

    /// Speed of the frame's nose (metres per unit of t), sampled: `[t₀, lerp+slerp₀, dlb₀,
    /// screw₀, t₁, …]`. Only the screw motion keeps it constant.
    #[wasm_bindgen(js_name = sampleSpeed)]
    pub fn sample_speed(&self, samples: usize) -> Result<Vec<f32>, JsError> {
        super::check_samples(samples)?;
        let h = 1e-3;
        let mut out = Vec::with_capacity(samples * 4);
        for k in 0..samples {
            let t = k as f32 / (samples - 1) as f32;
            let (t0, t1) = ((t - h).max(0.0), (t + h).min(1.0));
            out.push(t);
            for (method, _) in METHODS {
                let d = self.point(method, t1, TIP, false) - self.point(method, t0, TIP, false);
                out.push(d.length() / (t1 - t0));
            }
        }
        Ok(out)
    }
}

impl Default for RigidScene {
    fn default() -> Self {
        Self::new()
    }
}

impl RigidScene {
    fn student_ok(&self) -> (String, bool) {
        if !self.use_exercise {
            return (String::new(), false);
        }
        let (r, t) = self.start.to_rotation_translation();
        match exercises::rotations::dual_quat_apply(r, t, TIP) {
            Err(NotDone) => (
                "Not done yet: exercise 4.1 dual_quat_apply (src/exercises/rotations.rs). The figure uses the reference.".into(),
                false,
            ),
            Ok(_) => ("Showing your dual_quat_apply: it builds the green frame's keys and moves its nose.".into(), true),
        }
    }

    fn keys(&self, student: bool) -> (DualQuat, DualQuat) {
        if student {
            let mine = |dq: DualQuat| {
                let (r, t) = dq.to_rotation_translation();
                exercises::rotations::dual_quat_apply(r, t, Vec3::ZERO)
                    .ok()
                    .map(|(q, _)| q)
                    .filter(|q| q.real.is_finite() && q.dual.is_finite() && q.real.length() > 1e-6)
            };
            if let (Some(a), Some(b)) = (mine(self.start), mine(self.end)) {
                return (a, b);
            }
        }
        (self.start, self.end)
    }

    fn motion(&self, method: Method, t: f32, student: bool) -> DualQuat {
        match method {
            Method::LerpSlerp => {
                let (ra, pa) = self.start.to_rotation_translation();
                let (rb, pb) = self.end.to_rotation_translation();
                DualQuat::from_rotation_translation(slerp(ra, rb, t), pa.lerp(pb, t))
            }
            Method::DualQuatNlerp => {
                let (a, b) = self.keys(student);
                DualQuat::nlerp(a, b, t)
            }
            Method::Screw => self.screw.sample(t),
        }
    }

    fn point(&self, method: Method, t: f32, local: Vec3, student: bool) -> Vec3 {
        let m = self.motion(method, t, student);
        if student && method == Method::DualQuatNlerp {
            let (r, p) = m.to_rotation_translation();
            if let Ok((_, moved)) = exercises::rotations::dual_quat_apply(r, p, local) {
                if moved.is_finite() {
                    return moved;
                }
            }
        }
        m.transform_point(local)
    }
}

fn mat4_cols(values: &[f32]) -> Result<Mat4, JsError> {
    if values.len() != 16 {
        return Err(JsError::new(&format!(
            "a 4×4 matrix needs 16 numbers (column-major), got {}",
            values.len()
        )));
    }
    Ok(Mat4::from_cols_slice(values))
}

/// The 12 edges of the cube `[-1, 1]³` transformed by `m`.
fn wire_cube(frame: &mut crate::render::Frame, m: Mat4, color: Vec3) {
    let c = |i: u32| {
        m.transform_point3(Vec3::new(
            if i & 1 == 0 { -1.0 } else { 1.0 },
            if i & 2 == 0 { -1.0 } else { 1.0 },
            if i & 4 == 0 { -1.0 } else { 1.0 },
        ))
    };
    for i in 0..8u32 {
        for bit in [1, 2, 4] {
            if i & bit == 0 {
                frame.line(c(i), c(i | bit), color);
            }
        }
    }
}

/// Figure 2: two affine keys with rotation, scale and shear. Left: element-wise lerp of the 4×4
/// matrices. Right: translation lerp + rotation slerp + stretch lerp, after polar decomposition.
#[wasm_bindgen]
pub struct AffineScene {
    a: Mat4,
    b: Mat4,
    key_a: AffineKey,
    key_b: AffineKey,
    use_exercise: bool,
    note: String,
    path: Vec<Vec3>,
}

const HALF: f32 = 0.35;

#[wasm_bindgen]
impl AffineScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> AffineScene {
        let a = Mat4::from_translation(Vec3::new(-0.6, 0.7, 0.0));
        let mut scene = AffineScene {
            a,
            b: a,
            key_a: AffineKey::from_mat4(a).expect("identity key"),
            key_b: AffineKey::from_mat4(a).expect("identity key"),
            use_exercise: false,
            note: String::new(),
            path: Vec::with_capacity(65),
        };
        scene
            .set_key_b(160.0, 1.6, 0.6, 1.0, 0.6)
            .expect("the default key is invertible");
        scene
    }

    /// Key B: rotation by `angle_deg` about y, after a scale `(sx, sy, sz)` and a shear of x by y.
    /// A zero scale flattens the key (singular): that is rejected.
    #[wasm_bindgen(js_name = setKeyB)]
    pub fn set_key_b(
        &mut self,
        angle_deg: f32,
        sx: f32,
        sy: f32,
        sz: f32,
        shear: f32,
    ) -> Result<(), JsError> {
        let angle = finite("angle", angle_deg)? * DEG;
        let scale = Vec3::new(finite("sx", sx)?, finite("sy", sy)?, finite("sz", sz)?);
        let shear = Mat3::from_cols(
            Vec3::X,
            Vec3::new(finite("shear", shear)?, 1.0, 0.0),
            Vec3::Z,
        );
        let linear = Mat3::from_rotation_y(angle) * shear * Mat3::from_diagonal(scale);
        self.set_key(
            1,
            Mat4::from_translation(Vec3::new(0.6, 1.1, 0.0)) * Mat4::from_mat3(linear),
        )
    }

    /// Sets key `which` (0 = A, 1 = B) from a 4×4 affine matrix (16 numbers, column-major).
    /// Rejects NaN, a bottom row other than (0, 0, 0, 1), a singular or a mirroring key.
    #[wasm_bindgen(js_name = setKeyMatrix)]
    pub fn set_key_matrix(&mut self, which: u32, cols: Vec<f32>) -> Result<(), JsError> {
        let m = mat4_cols(&cols)?;
        self.set_key(which, m)
    }

    /// Splits the keys with the student's `polar_step` (exercise 4.2) iterated to convergence.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: bool) -> Result<(), JsError> {
        self.use_exercise = on;
        self.set_key(0, self.a)?;
        self.set_key(1, self.b)
    }

    /// Determinant of the linear part over t, sampled: `[t₀, naive₀, polar₀, t₁, …]`.
    #[wasm_bindgen(js_name = sampleDeterminant)]
    pub fn sample_determinant(&self, samples: usize) -> Result<Vec<f32>, JsError> {
        super::check_samples(samples)?;
        let mut out = Vec::with_capacity(samples * 3);
        for k in 0..samples {
            let t = k as f32 / (samples - 1) as f32;
            let naive =
                Mat3::from_mat4(rotation::affine_lerp_naive(self.a, self.b, t)).determinant();
            let polar =
                Mat3::from_mat4(self.key_a.interpolate(&self.key_b, t).to_mat4()).determinant();
            out.extend_from_slice(&[t, naive, polar]);
        }
        Ok(out)
    }

    /// Draws both interpolations at `t ∈ [0, 1]`. Returns a note about the exercise.
    pub fn draw(&mut self, viewer: &mut Viewer, t: f32) -> Result<String, JsError> {
        let t = in_range("t", t, 0.0, 1.0)?;
        let frame = &mut viewer.renderer.frame;
        frame.grid(12, 0.5);
        let corner = Vec3::splat(1.0);
        let size = Mat4::from_scale(Vec3::splat(HALF));
        for (offset, color, naive) in [
            (-1.8, Vec3::new(0.85, 0.3, 0.25), true),
            (1.8, Vec3::new(0.2, 0.45, 0.9), false),
        ] {
            let shift = Mat4::from_translation(Vec3::new(offset, 0.0, 0.0));
            let at = |s: f32| {
                if naive {
                    rotation::affine_lerp_naive(self.a, self.b, s)
                } else {
                    self.key_a.interpolate(&self.key_b, s).to_mat4()
                }
            };
            wire_cube(frame, shift * self.a * size, Vec3::splat(0.55));
            wire_cube(frame, shift * self.b * size, Vec3::splat(0.25));
            self.path.clear();
            for k in 0..=64 {
                self.path
                    .push((shift * at(k as f32 / 64.0) * size).transform_point3(corner));
            }
            frame.polyline(&self.path, color * 0.8);
            let m = shift * at(t);
            frame.mesh(viewer.renderer.cube, m * size, color);
            frame.point(
                (m * size).transform_point3(corner),
                0.045,
                Vec3::new(0.95, 0.85, 0.2),
            );
            frame.axes(m, 0.6);
        }
        viewer.present()?;
        Ok(self.note.clone())
    }
}

impl Default for AffineScene {
    fn default() -> Self {
        Self::new()
    }
}

impl AffineScene {
    fn set_key(&mut self, which: u32, m: Mat4) -> Result<(), JsError> {
        if which > 1 {
            return Err(JsError::new(&format!(
                "key must be 0 (A) or 1 (B), got {which}"
            )));
        }
        // The core validates (finite, affine, invertible, no mirror) and splits M = R D.
        let mut key = AffineKey::from_mat4(m).map_err(js_error)?;
        self.note.clear();
        if self.use_exercise {
            match student_polar(Mat3::from_mat4(m)) {
                Ok(Some((r, iterations))) => {
                    key.rotation = quat_from_mat3(r);
                    key.stretch = r.transpose() * Mat3::from_mat4(m);
                    self.note = format!("Showing your polar_step: it converged in {iterations} iterations for the last key set.");
                }
                Ok(None) => self.note = "Your polar_step did not converge (or gave NaN): the figure uses the reference.".into(),
                Err(NotDone) => {
                    self.note = "Not done yet: exercise 4.2 polar_step (src/exercises/rotations.rs). The figure uses the reference.".into()
                }
            }
        }
        if which == 0 {
            self.a = m;
            self.key_a = key;
        } else {
            self.b = m;
            self.key_b = key;
        }
        Ok(())
    }
}

/// Iterates the student's step from `R₀ = M` until it stops moving (at most 64 steps).
fn student_polar(m: Mat3) -> Result<Option<(Mat3, u32)>, NotDone> {
    let mut r = m;
    for iteration in 1..=64 {
        let next = exercises::rotations::polar_step(r)?;
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
        if change <= 1e-5 {
            return Ok(Some((r, iteration)));
        }
    }
    Ok(None)
}
