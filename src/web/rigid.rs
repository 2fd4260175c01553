//! Bindings for lesson 04, "Rigid motions": thin wrappers around [`crate::figures::rigid`], which
//! holds the scenes' state, validation and drawing (tested natively).

use super::{js, Viewer};
use crate::figures::rigid::{AffineKeys, RigidMotion};
use glam::{Mat4, Quat, Vec3};
use wasm_bindgen::prelude::*;

const DEG: f32 = std::f32::consts::PI / 180.0;

fn mat4_cols(values: &[f32]) -> Result<Mat4, JsError> {
    if values.len() != 16 {
        return Err(JsError::new(&format!(
            "a 4×4 matrix needs 16 numbers (column-major), got {}",
            values.len()
        )));
    }
    Ok(Mat4::from_cols_slice(values))
}

/// Figure 1: a frame moved from key A to key B by lerp + slerp, dual quaternion blending and
/// screw interpolation.
#[wasm_bindgen]
pub struct RigidScene {
    scene: RigidMotion,
}

#[wasm_bindgen]
impl RigidScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> RigidScene {
        let mut scene = RigidMotion::new();
        scene.set_runner(super::sandbox::run);
        RigidScene { scene }
    }

    /// Sets key B: rotation by `angle_deg` about `(ax, ay, az)`, then translation `(tx, ty, tz)`.
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
        let (axis, t) = (Vec3::new(ax, ay, az), Vec3::new(tx, ty, tz));
        self.scene.set_end(axis, angle_deg, t).map_err(js)
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
        let q = Quat::from_xyzw(x, y, z, w);
        self.scene
            .set_end_quat(q, Vec3::new(tx, ty, tz))
            .map_err(js)
    }

    /// Sets key B from a rigid 4×4 matrix (16 numbers, column-major).
    #[wasm_bindgen(js_name = setEndMatrix)]
    pub fn set_end_matrix(&mut self, cols: Vec<f32>) -> Result<(), JsError> {
        self.scene.set_end_matrix(mat4_cols(&cols)?).map_err(js)
    }

    /// 0 = all three methods, 1 = lerp + slerp only, 2 = dual quaternion blend, 3 = screw.
    #[wasm_bindgen(js_name = setShow)]
    pub fn set_show(&mut self, which: f64) -> Result<(), JsError> {
        let which = super::whole("which", which)? as u32;
        self.scene.set_show(which).map_err(js)
    }

    /// Draws a third of the motion applied three times (screw: lands on B; lerp + slerp: misses).
    #[wasm_bindgen(js_name = setThirds)]
    pub fn set_thirds(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_thirds(on);
        Ok(())
    }

    /// Moves the green frame with the student's `dual_quat_apply` (exercise 4.1) and checks it.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// The screw axis of the motion from A to B: `[dx, dy, dz, px, py, pz, angle_deg, slide]`.
    #[wasm_bindgen(js_name = screwAxis)]
    pub fn screw_axis(&self) -> Vec<f32> {
        let s = self.scene.screw_axis();
        let mut out = s.direction.to_array().to_vec();
        out.extend_from_slice(&s.point.to_array());
        out.extend_from_slice(&[s.angle_rad / DEG, s.displacement]);
        out
    }

    /// Draws the frames at `t ∈ [0, 1]`; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, t: f32) -> Result<String, JsError> {
        // The view the thirds' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame, t).map_err(js)?;
        viewer.present()?;
        Ok(note)
    }

    /// Sets the point of the aeroplane (its own coordinates, metres) whose frame is interpolated.
    #[wasm_bindgen(js_name = setPivot)]
    pub fn set_pivot(&mut self, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        self.scene.set_pivot(Vec3::new(x, y, z)).map_err(js)
    }

    /// Distance travelled by the nose (m): `[t₀, lerp+slerp₀, dlb₀, screw₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleDistance)]
    pub fn sample_distance(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_distance(samples).map_err(js)?.concat())
    }

    /// Speed of the nose (m per unit of t): `[t₀, lerp+slerp₀, dlb₀, screw₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleSpeed)]
    pub fn sample_speed(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_speed(samples).map_err(js)?.concat())
    }
}

impl Default for RigidScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 2: two affine keys, naive lerp vs polar decomposition.
#[wasm_bindgen]
pub struct AffineScene {
    scene: AffineKeys,
}

#[wasm_bindgen]
impl AffineScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> AffineScene {
        let mut scene = AffineKeys::new();
        scene.set_runner(super::sandbox::run);
        AffineScene { scene }
    }

    /// Key B: rotation by `angle_deg` about y, after a scale `(sx, sy, sz)` and a shear of x by y.
    #[wasm_bindgen(js_name = setKeyB)]
    pub fn set_key_b(
        &mut self,
        angle_deg: f32,
        sx: f32,
        sy: f32,
        sz: f32,
        shear: f32,
    ) -> Result<(), JsError> {
        let scale = Vec3::new(sx, sy, sz);
        self.scene.set_key_b(angle_deg, scale, shear).map_err(js)
    }

    /// Sets key `which` (0 = A, 1 = B) from a 4×4 affine matrix (16 numbers, column-major).
    #[wasm_bindgen(js_name = setKeyMatrix)]
    pub fn set_key_matrix(&mut self, which: f64, cols: Vec<f32>) -> Result<(), JsError> {
        let which = super::whole("which", which)? as u32;
        self.scene.set_key(which, mat4_cols(&cols)?).map_err(js)
    }

    /// Splits the keys with the student's `polar_step` (exercise 4.2) and checks it.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// Determinant of the linear part over t: `[t₀, naive₀, polar₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleDeterminant)]
    pub fn sample_determinant(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_determinant(samples).map_err(js)?.concat())
    }

    /// Draws both interpolations at `t ∈ [0, 1]`; returns the note about the exercise.
    pub fn draw(&mut self, viewer: &mut Viewer, t: f32) -> Result<String, JsError> {
        let note = self.scene.draw(&mut viewer.renderer.frame, t).map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for AffineScene {
    fn default() -> Self {
        Self::new()
    }
}
