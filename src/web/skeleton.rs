//! Bindings for lesson 06, "Skeletons and forward kinematics": thin wrappers around
//! [`crate::figures::skeleton`], which holds the figure's logic and is tested natively.

use super::{js, Viewer};
use crate::camera::OrbitCamera;
use crate::figures::skeleton::SkeletonFigure;
use glam::{Vec2, Vec3};
use wasm_bindgen::prelude::*;

/// The skeleton figure: the built-in human playing a clip.
#[wasm_bindgen]
pub struct SkeletonScene {
    scene: SkeletonFigure,
    /// The camera of the last drawn frame, for picking a joint.
    camera: Option<OrbitCamera>,
}

#[wasm_bindgen]
impl SkeletonScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SkeletonScene {
        let mut scene = SkeletonFigure::new();
        scene.set_runner(super::sandbox::run);
        SkeletonScene {
            scene,
            camera: None,
        }
    }

    #[wasm_bindgen(js_name = jointNames)]
    pub fn joint_names(&self) -> Vec<String> {
        self.scene.skeleton().names().to_vec()
    }

    /// Each joint's parent index (−1 for the root).
    pub fn parents(&self) -> Vec<i32> {
        self.scene.skeleton().parents().to_vec()
    }

    /// Each joint's group size (itself plus its descendants).
    #[wasm_bindgen(js_name = groupSizes)]
    pub fn group_sizes(&self) -> Vec<u32> {
        let sizes = self.scene.skeleton().group_sizes();
        sizes.iter().map(|&s| s as u32).collect()
    }

    #[wasm_bindgen(js_name = clipNames)]
    pub fn clip_names(&self) -> Vec<String> {
        self.scene.clip_names()
    }

    /// Plays the clip with this name (one of `clipNames()`).
    #[wasm_bindgen(js_name = setClip)]
    pub fn set_clip(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_clip(name).map_err(js)
    }

    /// Keys per cycle of every clip, in [4, 25].
    #[wasm_bindgen(js_name = setKeysPerCycle)]
    pub fn set_keys_per_cycle(&mut self, keys: f32) -> Result<(), JsError> {
        self.scene.set_keys_per_cycle(keys).map_err(js)
    }

    /// "step", "linear (nlerp)", "linear (slerp)" or "cubic".
    #[wasm_bindgen(js_name = setInterpolation)]
    pub fn set_interpolation(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_interpolation(name).map_err(js)
    }

    /// "nlerp" or "slerp".
    #[wasm_bindgen(js_name = setRotationInterpolation)]
    pub fn set_rotation_interpolation(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_rotation_interpolation(name).map_err(js)
    }

    /// A second path of the selected bone's tip under another interpolation (one of those
    /// `setInterpolation` takes), or "none".
    #[wasm_bindgen(js_name = setCompare)]
    pub fn set_compare(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_compare(name).map_err(js)
    }

    /// The joint under the pointer at `(x, y)` CSS pixels on a canvas `width` × `height`, or −1.
    #[wasm_bindgen(js_name = pickJoint)]
    pub fn pick_joint(&self, x: f32, y: f32, width: f32, height: f32) -> Result<f64, JsError> {
        let pointer = Vec2::new(super::finite("x", x)?, super::finite("y", y)?);
        let w = super::in_range("width", width, 1.0, 1e5)?;
        let h = super::in_range("height", height, 1.0, 1e5)?;
        let Some(camera) = self.camera else {
            return Ok(-1.0);
        };
        let view_proj = camera.projection(w / h) * camera.view();
        Ok(self
            .scene
            .pick_joint(view_proj, Vec2::new(w, h), pointer)
            .map_or(-1.0, |j| j as f64))
    }

    /// Crossfades clip `name` (or "none") in with weight `weight ∈ [0, 1]`, at the same phase.
    #[wasm_bindgen(js_name = setBlend)]
    pub fn set_blend(&mut self, name: JsValue, weight: f32) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_blend(name, weight).map_err(js)
    }

    /// Selects the joint drawn in orange (its group in teal).
    pub fn select(&mut self, joint: f64) -> Result<(), JsError> {
        let joint = super::whole("joint", joint)?;
        self.scene.select(joint).map_err(js)
    }

    /// A joint's angle offsets on top of the clip, degrees (x, y, z).
    #[wasm_bindgen(js_name = jointAnglesDeg)]
    pub fn joint_angles_deg(&self, joint: f64) -> Result<Vec<f32>, JsError> {
        let joint = super::whole("joint", joint)?;
        let a = self.scene.joint_angles_deg(joint).map_err(js)?;
        Ok(a.to_array().to_vec())
    }

    /// Sets a joint's angle offsets, each in [−180, 180] degrees.
    #[wasm_bindgen(js_name = setJointAnglesDeg)]
    pub fn set_joint_angles_deg(
        &mut self,
        joint: f64,
        x_deg: f32,
        y_deg: f32,
        z_deg: f32,
    ) -> Result<(), JsError> {
        let joint = super::whole("joint", joint)?;
        let deg = Vec3::new(x_deg, y_deg, z_deg);
        self.scene.set_joint_angles_deg(joint, deg).map_err(js)
    }

    /// Clears every joint's angle offsets.
    #[wasm_bindgen(js_name = resetPose)]
    pub fn reset_pose(&mut self) {
        self.scene.reset_pose();
    }

    #[wasm_bindgen(js_name = setShowBoxes)]
    pub fn set_show_boxes(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_boxes(on);
        Ok(())
    }

    #[wasm_bindgen(js_name = setShowAxes)]
    pub fn set_show_axes(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_axes(on);
        Ok(())
    }

    /// Runs the student's exercises 6.1 and 6.2 (in the sandbox) instead of the reference.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// The playing clip's duration, seconds.
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }

    /// The playing clip's key times, seconds.
    #[wasm_bindgen(js_name = keyTimes)]
    pub fn key_times(&self) -> Vec<f32> {
        self.scene.key_times()
    }

    /// Poses at `time_sec` and draws. Returns the note for the page.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.camera = Some(viewer.camera);
        // The view the selected joint's name is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }

    /// Local matrix of a joint at the last pose, column-major.
    #[wasm_bindgen(js_name = localMatrix)]
    pub fn local_matrix(&self, joint: f64) -> Result<Vec<f32>, JsError> {
        let joint = super::whole("joint", joint)?;
        let m = self.scene.local_matrix(joint).map_err(js)?;
        Ok(m.to_cols_array().to_vec())
    }

    /// Model matrix of a joint at the last pose, column-major.
    #[wasm_bindgen(js_name = modelMatrix)]
    pub fn model_matrix(&self, joint: f64) -> Result<Vec<f32>, JsError> {
        let joint = super::whole("joint", joint)?;
        let m = self.scene.model_matrix(joint).map_err(js)?;
        Ok(m.to_cols_array().to_vec())
    }

    /// One cycle of the selected joint for the plots: rows of `[t, angle (°), speed (°/s), angle
    /// and speed under the compared interpolation, angle under clip A alone, under clip B alone]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleSelected)]
    pub fn sample_selected(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        self.scene.sample_selected(samples).map_err(js)
    }
}

impl Default for SkeletonScene {
    fn default() -> Self {
        Self::new()
    }
}

/// The longest joint name [`check_skeleton`] takes, in UTF-16 code units (the page's names are
/// a few words; the cap bounds the copy and the comparisons of a hostile list).
pub const MAX_NAME_CHARS: usize = 256;

/// Builds a skeleton from JavaScript arrays and says what is wrong, or `"ok"`: the page's check
/// of a typed-in hierarchy, and the wasm-boundary test of every validation rule. `rest` holds 10
/// numbers per joint: translation (3), rotation quaternion x, y, z, w (4), scale (3).
///
/// Caps (the check's work grows with them): at most 65,536 joints (`skeleton::MAX_JOINTS`, for
/// `names` and `parents` alike) and names of at most [`MAX_NAME_CHARS`] characters, both
/// checked before the lists are converted.
#[wasm_bindgen(js_name = checkSkeleton)]
pub fn check_skeleton(
    names: JsValue,
    parents: Vec<f64>,
    rest: Vec<f32>,
) -> Result<String, JsError> {
    use crate::skeleton::{Skeleton, Transform, MAX_JOINTS};
    let names = super::strings("names", &names, MAX_JOINTS, MAX_NAME_CHARS)?;
    if parents.len() > MAX_JOINTS {
        return Err(JsError::new(&format!(
            "parents: {} joints is too many (at most {MAX_JOINTS})",
            parents.len()
        )));
    }
    // Whole numbers from -1 (the root) up; an Int32Array would wrap 4294967295 to -1.
    let parents: Vec<i32> = super::wholes("parents", &parents, -1.0, f64::from(i32::MAX))?
        .into_iter()
        .map(|p| p as i32)
        .collect();
    if rest.len() != 10 * parents.len() {
        return Err(JsError::new(&format!(
            "rest: expected 10 numbers per joint ({}), got {}",
            10 * parents.len(),
            rest.len()
        )));
    }
    let rest = rest
        .chunks_exact(10)
        .map(|c| Transform {
            translation: Vec3::new(c[0], c[1], c[2]),
            rotation: glam::Quat::from_xyzw(c[3], c[4], c[5], c[6]),
            scale: Vec3::new(c[7], c[8], c[9]),
        })
        .collect();
    Skeleton::new(names, parents, rest)
        .map(|_| "ok".to_string())
        .map_err(|e| JsError::new(&e.to_string()))
}
