//! Bindings for lesson 07, "Inverse kinematics": thin wrappers around [`crate::figures::ik`],
//! which holds the figures' logic and is tested natively.

use super::{js, Viewer};
use crate::camera::OrbitCamera;
use crate::figures::ik::{AimFigure, IkFigure};
use glam::Vec3;
use wasm_bindgen::prelude::*;

/// One chain, three solvers (two-joint analytic, CCD, FABRIK) side by side.
#[wasm_bindgen]
pub struct IkScene {
    scene: IkFigure,
    /// The camera of the last drawn frame, for picking the target.
    camera: Option<OrbitCamera>,
}

#[wasm_bindgen]
impl IkScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> IkScene {
        let mut scene = IkFigure::new();
        scene.set_runner(super::sandbox::run);
        IkScene {
            scene,
            camera: None,
        }
    }

    /// Segments per chain, in [2, 8].
    #[wasm_bindgen(js_name = setSegments)]
    pub fn set_segments(&mut self, segments: f32) -> Result<(), JsError> {
        self.scene.set_segments(segments).map_err(js)
    }

    /// The target relative to each chain's root, metres, each in [−1.5, 1.5].
    #[wasm_bindgen(js_name = setTarget)]
    pub fn set_target(&mut self, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        self.scene.set_target(Vec3::new(x, y, z)).map_err(js)
    }

    /// The target, `[x, y, z]` metres (after a drag).
    pub fn target(&self) -> Vec<f32> {
        self.scene.target().to_array().to_vec()
    }

    /// Pole angle about the root→target line, degrees in [−180, 180].
    #[wasm_bindgen(js_name = setPoleAngleDeg)]
    pub fn set_pole_angle_deg(&mut self, deg: f32) -> Result<(), JsError> {
        self.scene.set_pole_angle_deg(deg).map_err(js)
    }

    /// Most iterations for CCD and FABRIK, in [1, 50].
    #[wasm_bindgen(js_name = setIterations)]
    pub fn set_iterations(&mut self, iterations: f32) -> Result<(), JsError> {
        self.scene.set_iterations(iterations).map_err(js)
    }

    /// "none", "hinges (bend one way)" or "cones (40°)".
    #[wasm_bindgen(js_name = setLimits)]
    pub fn set_limits(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_limits(name).map_err(js)
    }

    /// Runs the student's exercises 7.1 and 7.2 (in the sandbox) instead of the reference.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// `[iteration, log₁₀ CCD error (m), log₁₀ FABRIK error (m), …]` for the plot.
    #[wasm_bindgen(js_name = errorSamples)]
    pub fn error_samples(&mut self) -> Result<Vec<f32>, JsError> {
        self.scene.error_samples().map_err(js)
    }

    /// Whether the pointer at `(x, y)` (CSS pixels in a canvas `width` × `height`) is on a target.
    #[wasm_bindgen(js_name = hitsTarget)]
    pub fn hits_target(
        &mut self,
        x: f32,
        y: f32,
        width: f32,
        height: f32,
    ) -> Result<bool, JsError> {
        self.use_view(x, y, width, height)?;
        self.scene.hits_target(x, y).map_err(js)
    }

    /// Moves the target under the pointer at `(x, y)` CSS pixels.
    #[wasm_bindgen(js_name = dragTarget)]
    pub fn drag_target(&mut self, x: f32, y: f32, width: f32, height: f32) -> Result<(), JsError> {
        self.use_view(x, y, width, height)?;
        self.scene.drag_target(x, y).map_err(js)
    }

    /// Checks the pointer and the canvas size, then hands the scene the view to pick in: a
    /// rejected call changes nothing.
    fn use_view(&mut self, x: f32, y: f32, width: f32, height: f32) -> Result<(), JsError> {
        super::finite("x", x)?;
        super::finite("y", y)?;
        let w = super::in_range("width", width, 1.0, 1e5)?;
        let h = super::in_range("height", height, 1.0, 1e5)?;
        if let Some(camera) = self.camera {
            self.scene.set_view(camera, w, h);
        }
        Ok(())
    }

    /// Solves (when something changed) and draws. Returns the note for the page.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        self.camera = Some(viewer.camera);
        // The view the labels at the roots are placed for (the last frame's fitted camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame).map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for IkScene {
    fn default() -> Self {
        Self::new()
    }
}

/// A head that looks at a target within a cone.
#[wasm_bindgen]
pub struct AimScene {
    scene: AimFigure,
}

#[wasm_bindgen]
impl AimScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> AimScene {
        AimScene {
            scene: AimFigure::new(),
        }
    }

    /// The target, metres (x, z in [−1.2, 1.2], y in [0.6, 2.6]).
    #[wasm_bindgen(js_name = setTarget)]
    pub fn set_target(&mut self, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        self.scene.set_target(Vec3::new(x, y, z)).map_err(js)
    }

    /// How far the head may turn from straight ahead, degrees in [0, 180].
    #[wasm_bindgen(js_name = setMaxAngleDeg)]
    pub fn set_max_angle_deg(&mut self, deg: f32) -> Result<(), JsError> {
        self.scene.set_max_angle_deg(deg).map_err(js)
    }

    /// `[time (s), angle to the target (°), angle the head turns (°), …]` over one loop.
    #[wasm_bindgen(js_name = plotSamples)]
    pub fn plot_samples(&self) -> Result<Vec<f32>, JsError> {
        self.scene.plot_samples(160).map_err(js)
    }

    /// Aims at `time_sec` (the target circles slowly) and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        // The view its labels keep clear on (the last frame's fitted camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for AimScene {
    fn default() -> Self {
        Self::new()
    }
}
