//! Bindings for lesson 01, "Transforms and hierarchies": thin wrappers around
//! [`crate::figures::transforms`], which holds the figures' logic and is tested natively.

use super::{js, Viewer};
use crate::figures::transforms::{HierarchyFigure, Order, ScaleComparison, SingleShape};
use glam::Vec3;
use wasm_bindgen::prelude::*;

/// Figure 1: one box, its matrix, and the order of translation and rotation.
#[wasm_bindgen]
pub struct SingleShapeScene {
    scene: SingleShape,
}

fn order(translate_first: bool) -> Order {
    if translate_first {
        Order::TranslateFirst
    } else {
        Order::RotateFirst
    }
}

#[wasm_bindgen]
impl SingleShapeScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SingleShapeScene {
        SingleShapeScene {
            scene: SingleShape::new(),
        }
    }

    /// Sets the translation (metres) and Euler angles (degrees, X then Y then Z as in the lesson).
    #[wasm_bindgen(js_name = setTransform)]
    pub fn set_transform(
        &mut self,
        tx: f32,
        ty: f32,
        tz: f32,
        rx_deg: f32,
        ry_deg: f32,
        rz_deg: f32,
    ) -> Result<(), JsError> {
        let t = Vec3::new(tx, ty, tz);
        let r = Vec3::new(rx_deg, ry_deg, rz_deg);
        self.scene.set_transform(t, r).map_err(js)
    }

    /// `false`: the solid box is M = T · R and the ghost R · T; `true`: the other way round.
    #[wasm_bindgen(js_name = setTranslateFirst)]
    pub fn set_translate_first(&mut self, translate_first: JsValue) -> Result<(), JsError> {
        let translate_first = super::boolean("translate_first", &translate_first)?;
        self.scene.set_order(order(translate_first));
        Ok(())
    }

    /// The solid box's 4×4 matrix, column-major (16 numbers).
    pub fn matrix(&self) -> Vec<f32> {
        let m = self.scene.matrix(self.scene.order());
        m.to_cols_array().to_vec()
    }

    /// The matrix of one order (`true`: R · T), column-major.
    #[wasm_bindgen(js_name = matrixOf)]
    pub fn matrix_of(&self, translate_first: JsValue) -> Result<Vec<f32>, JsError> {
        let translate_first = super::boolean("translate_first", &translate_first)?;
        let m = self.scene.matrix(order(translate_first));
        Ok(m.to_cols_array().to_vec())
    }

    /// Draws the figure with both boxes `stage` into their two steps (0 to 2; 2: the full
    /// products); returns the note for the page.
    pub fn draw(&mut self, viewer: &mut Viewer, stage: f32) -> Result<String, JsError> {
        // The view p's and v's names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, stage)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for SingleShapeScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 2: a human made of boxes, posed by joint angles, with world = parent · local.
#[wasm_bindgen]
pub struct HierarchyScene {
    scene: HierarchyFigure,
}

#[wasm_bindgen]
impl HierarchyScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> HierarchyScene {
        let mut scene = HierarchyFigure::new();
        scene.set_runner(super::sandbox::run);
        HierarchyScene { scene }
    }

    #[wasm_bindgen(js_name = jointNames)]
    pub fn joint_names(&self) -> Vec<String> {
        self.scene.joint_names().to_vec()
    }

    /// Selects the joint whose axes are drawn and whose values the panel edits.
    pub fn select(&mut self, joint: f64) -> Result<(), JsError> {
        let joint = super::whole("joint", joint)?;
        self.scene.select(joint).map_err(js)
    }

    /// Euler angles of a joint in degrees (x, y, z) as last set or animated.
    #[wasm_bindgen(js_name = jointAnglesDeg)]
    pub fn joint_angles_deg(&self, joint: f64) -> Result<Vec<f32>, JsError> {
        let joint = super::whole("joint", joint)?;
        let a = self.scene.joint_angles_deg(joint).map_err(js)?;
        Ok(a.to_array().to_vec())
    }

    /// Sets a joint's Euler angles, in degrees.
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

    /// A joint's scale along its own axes (x, y, z).
    #[wasm_bindgen(js_name = jointScale)]
    pub fn joint_scale(&self, joint: f64) -> Result<Vec<f32>, JsError> {
        let joint = super::whole("joint", joint)?;
        let s = self.scene.joint_scale(joint).map_err(js)?;
        Ok(s.to_array().to_vec())
    }

    /// Sets a joint's scale along its own axes (each in [0.1, 4]).
    #[wasm_bindgen(js_name = setJointScale)]
    pub fn set_joint_scale(
        &mut self,
        joint: f64,
        sx: f32,
        sy: f32,
        sz: f32,
    ) -> Result<(), JsError> {
        let joint = super::whole("joint", joint)?;
        let s = Vec3::new(sx, sy, sz);
        self.scene.set_joint_scale(joint, s).map_err(js)
    }

    /// Whether a joint's scale is passed on to its children (see the lesson).
    #[wasm_bindgen(js_name = setInheritScale)]
    pub fn set_inherit_scale(&mut self, inherit: JsValue) -> Result<(), JsError> {
        let inherit = super::boolean("inherit", &inherit)?;
        self.scene.set_inherit_scale(inherit);
        Ok(())
    }

    /// When on, the timeline drives a walk cycle and the angle sliders follow it.
    #[wasm_bindgen(js_name = setAnimate)]
    pub fn set_animate(&mut self, animate: JsValue) -> Result<(), JsError> {
        let animate = super::boolean("animate", &animate)?;
        self.scene.set_animate(animate);
        Ok(())
    }

    /// Runs the student's exercises 1.1 and 1.2 (in the sandbox) instead of the reference.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// Poses the figure at `time_sec` and draws it. Returns the note for the page: empty, or what
    /// the student's exercises did.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        // The view the names beside the body are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }

    /// World matrix of a joint at the last drawn pose, column-major.
    #[wasm_bindgen(js_name = worldMatrix)]
    pub fn world_matrix(&self, joint: f64) -> Result<Vec<f32>, JsError> {
        let joint = super::whole("joint", joint)?;
        let m = self.scene.world_matrix(joint).map_err(js)?;
        Ok(m.to_cols_array().to_vec())
    }

    /// Local matrix of a joint at the last drawn pose, column-major.
    #[wasm_bindgen(js_name = localMatrix)]
    pub fn local_matrix(&self, joint: f64) -> Result<Vec<f32>, JsError> {
        let joint = super::whole("joint", joint)?;
        let m = self.scene.local_matrix(joint).map_err(js)?;
        Ok(m.to_cols_array().to_vec())
    }

    /// One walk cycle of the current figure (pose, scales, scale mode) for the plot:
    /// `[t₀, a₀, h₀, …]`, left thigh angle `a` (degrees), left wrist height `h` (metres).
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleCycle)]
    pub fn sample_cycle(&self, samples: f64, period_sec: f32) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        self.scene.sample_cycle(samples, period_sec).map_err(js)
    }
}

impl Default for HierarchyScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 3: the same pose with scale not inherited (left) and inherited (right).
#[wasm_bindgen]
pub struct ScaleComparisonScene {
    scene: ScaleComparison,
}

#[wasm_bindgen]
impl ScaleComparisonScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> ScaleComparisonScene {
        ScaleComparisonScene {
            scene: ScaleComparison::new(),
        }
    }

    /// The left upper arm's scale along its own axes (each in [0.1, 4]), in both copies.
    #[wasm_bindgen(js_name = setUpperArmScale)]
    pub fn set_upper_arm_scale(&mut self, sx: f32, sy: f32, sz: f32) -> Result<(), JsError> {
        let s = Vec3::new(sx, sy, sz);
        self.scene.set_upper_arm_scale(s).map_err(js)
    }

    /// The left forearm's Euler angles in degrees, in both copies.
    #[wasm_bindgen(js_name = setForearmAnglesDeg)]
    pub fn set_forearm_angles_deg(&mut self, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        let deg = Vec3::new(x, y, z);
        self.scene.set_forearm_angles_deg(deg).map_err(js)
    }

    /// Draws both copies; returns the note (forearm lengths and corner angles).
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the labels are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame).map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for ScaleComparisonScene {
    fn default() -> Self {
        Self::new()
    }
}
