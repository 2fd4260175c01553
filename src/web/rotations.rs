//! Bindings for lesson 03, "Rotations": thin wrappers around [`crate::figures::rotations`], which
//! holds the scenes' state, validation and drawing (tested natively).

use super::{js, Viewer};
use crate::figures::rotations::{Gimbal, Interpolation, Rodrigues};
use glam::{Mat3, Quat, Vec3};
use wasm_bindgen::prelude::*;

pub(crate) fn mat3_cols(values: &[f32]) -> Result<Mat3, JsError> {
    if values.len() != 9 {
        return Err(JsError::new(&format!(
            "a 3×3 matrix needs 9 numbers (column-major), got {}",
            values.len()
        )));
    }
    Ok(Mat3::from_cols_slice(values))
}

/// Figure 1: one aeroplane interpolated by matrix lerp, Euler lerp, nlerp and slerp.
#[wasm_bindgen]
pub struct InterpolationScene {
    scene: Interpolation,
}

#[wasm_bindgen]
impl InterpolationScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> InterpolationScene {
        let mut scene = Interpolation::new();
        scene.set_runner(super::sandbox::run);
        InterpolationScene { scene }
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
        let (a, b) = (Vec3::new(ax, ay, az), Vec3::new(bx, by, bz));
        self.scene.set_keys_euler_deg(a, b).map_err(js)
    }

    /// Sets the end key as a quaternion `(x, y, z, w)`; it is normalised; zero or NaN is rejected.
    #[wasm_bindgen(js_name = setEndQuat)]
    pub fn set_end_quat(&mut self, x: f32, y: f32, z: f32, w: f32) -> Result<(), JsError> {
        self.scene
            .set_end_quat(Quat::from_xyzw(x, y, z, w))
            .map_err(js)
    }

    /// Sets the end key as a rotation matrix (9 numbers, column-major).
    #[wasm_bindgen(js_name = setEndMatrix)]
    pub fn set_end_matrix(&mut self, cols: Vec<f32>) -> Result<(), JsError> {
        self.scene.set_end_matrix(mat3_cols(&cols)?).map_err(js)
    }

    /// `true`: nlerp and slerp take the long arc.
    #[wasm_bindgen(js_name = setLongArc)]
    pub fn set_long_arc(&mut self, long: JsValue) -> Result<(), JsError> {
        let long = super::boolean("long", &long)?;
        self.scene.set_long_arc(long);
        Ok(())
    }

    /// Uses the student's `slerp` (exercise 3.2) for the slerp object and checks it.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// The end key's quaternion `(x, y, z, w)` as used on the current arc.
    #[wasm_bindgen(js_name = endQuatUsed)]
    pub fn end_quat_used(&self) -> Vec<f32> {
        self.scene.end_quat_used().to_array().to_vec()
    }

    /// `[short, long]`: how far the object turns on each arc, in degrees.
    #[wasm_bindgen(js_name = arcAnglesDeg)]
    pub fn arc_angles_deg(&self) -> Vec<f32> {
        let (short, long) = self.scene.arc_angles_deg();
        vec![short, long]
    }

    /// Draws the four objects at `t ∈ [0, 1]`; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, t: f32) -> Result<String, JsError> {
        let note = self.scene.draw(&mut viewer.renderer.frame, t).map_err(js)?;
        viewer.present()?;
        Ok(note)
    }

    /// Draws Figure 2, the keys' circle of unit quaternions, at `t ∈ [0, 1]`; returns its note.
    #[wasm_bindgen(js_name = drawCircle)]
    pub fn draw_circle(&mut self, viewer: &mut Viewer, t: f32) -> Result<String, JsError> {
        // The view the keys' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_circle_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw_circle(&mut viewer.renderer.frame, t)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }

    /// Matrix lerp, sampled: `[t₀, det₀, e₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleDeterminant)]
    pub fn sample_determinant(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        let rows = self.scene.sample_determinant(samples).map_err(js)?;
        Ok(rows.concat())
    }

    /// Angular speed (° per unit of t): `[t₀, euler₀, nlerp₀, slerp₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleAngularSpeed)]
    pub fn sample_angular_speed(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        let rows = self.scene.sample_angular_speed(samples).map_err(js)?;
        Ok(rows.concat())
    }
}

impl Default for InterpolationScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 3: a three-ring gimbal (yaw, pitch, roll).
#[wasm_bindgen]
pub struct GimbalScene {
    scene: Gimbal,
}

#[wasm_bindgen]
impl GimbalScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> GimbalScene {
        GimbalScene {
            scene: Gimbal::new(),
        }
    }

    /// Sets (yaw about y, pitch about x′, roll about z″), in degrees.
    #[wasm_bindgen(js_name = setAnglesDeg)]
    pub fn set_angles_deg(&mut self, yaw: f32, pitch: f32, roll: f32) -> Result<(), JsError> {
        self.scene.set_angles_deg(yaw, pitch, roll).map_err(js)
    }

    /// Angle between the outer (yaw) and inner (roll) axles, in degrees: 0 at gimbal lock.
    #[wasm_bindgen(js_name = axesAngleDeg)]
    pub fn axes_angle_deg(&self) -> f32 {
        self.scene.axles_angle_deg()
    }

    /// The orientation read back as Y-X′-Z″ angles (degrees) and 1 at gimbal lock:
    /// `[yaw, pitch, roll, lock]`.
    #[wasm_bindgen(js_name = decomposedDeg)]
    pub fn decomposed_deg(&self) -> Vec<f32> {
        let (a, lock) = self.scene.decomposed_deg();
        vec![a.x, a.y, a.z, if lock { 1.0 } else { 0.0 }]
    }

    /// Sets how far (degrees, 0 to 45) the steady turn passes from the pole.
    #[wasm_bindgen(js_name = setPoleMissDeg)]
    pub fn set_pole_miss_deg(&mut self, miss: f32) -> Result<(), JsError> {
        self.scene.set_pole_miss_deg(miss).map_err(js)
    }

    /// Puts the rings on the steady turn at `t ∈ [0, 1]`; returns `[yaw, pitch, roll]` (°).
    #[wasm_bindgen(js_name = flyAt)]
    pub fn fly_at(&mut self, t: f32) -> Result<Vec<f32>, JsError> {
        Ok(self.scene.fly_at(t).map_err(js)?.to_array().to_vec())
    }

    /// The steady turn's yaw, pitch and roll (°), unwrapped: `[t₀, yaw₀, pitch₀, roll₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = samplePoleTurn)]
    pub fn sample_pole_turn(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_pole_turn(samples).map_err(js)?.concat())
    }

    /// What the page says under the gimbal (the read-back, and at lock which sum is determined).
    pub fn note(&self) -> String {
        self.scene.note()
    }

    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<(), JsError> {
        // The view the axles' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()
    }
}

impl Default for GimbalScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 4: Rodrigues' formula.
#[wasm_bindgen]
pub struct RodriguesScene {
    scene: Rodrigues,
}

#[wasm_bindgen]
impl RodriguesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> RodriguesScene {
        let mut scene = Rodrigues::new();
        scene.set_runner(super::sandbox::run);
        RodriguesScene { scene }
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
        self.scene
            .set_axis_angle(Vec3::new(x, y, z), angle_deg)
            .map_err(js)
    }

    /// Sets the vector `v` that turns (metres).
    #[wasm_bindgen(js_name = setVector)]
    pub fn set_vector(&mut self, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        self.scene.set_vector(Vec3::new(x, y, z)).map_err(js)
    }

    /// Uses the student's `rodrigues_matrix` (3.3) and `quat_from_axis_angle` (3.1).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// `R(θ)` as a 3×3 column-major matrix (9 numbers), for the page's matrix table.
    pub fn matrix(&self) -> Vec<f32> {
        self.scene.matrix().to_cols_array().to_vec()
    }

    /// The quaternion `(x, y, z, w)` of the full rotation.
    pub fn quaternion(&self) -> Vec<f32> {
        self.scene.quaternion().to_array().to_vec()
    }

    /// Draws the rotation swept up to `s · θ`, `s ∈ [0, 1]`; returns the note about the exercises.
    pub fn draw(&mut self, viewer: &mut Viewer, s: f32) -> Result<String, JsError> {
        // The view the terms' labels are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame, s).map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for RodriguesScene {
    fn default() -> Self {
        Self::new()
    }
}
