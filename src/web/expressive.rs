//! Bindings for lesson 02b, "Expressive animation": thin wrappers around
//! [`crate::figures::expressive`], which holds the scenes' state, validation and drawing.

use super::{js, Viewer};
use crate::figures::expressive::{FollowThrough, JumpComparison, Spacing};
use wasm_bindgen::prelude::*;

/// Figure 1: timing and spacing on one path.
#[wasm_bindgen]
pub struct SpacingScene {
    scene: Spacing,
}

#[wasm_bindgen]
impl SpacingScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SpacingScene {
        let mut scene = Spacing::new();
        scene.set_runner(super::sandbox::run);
        SpacingScene { scene }
    }

    /// "linear", "slow in and out", "ease in" or "ease out".
    #[wasm_bindgen(js_name = setEase)]
    pub fn set_ease(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_ease(name).map_err(js)
    }

    /// The arc's height above the straight line, 0 to 3 m.
    #[wasm_bindgen(js_name = setArcHeight)]
    pub fn set_arc_height(&mut self, h: f32) -> Result<(), JsError> {
        self.scene.set_arc_height(h).map_err(js)
    }

    /// Shows the straight-line twin behind the ball.
    #[wasm_bindgen(js_name = setTwin)]
    pub fn set_twin(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_twin(on);
        Ok(())
    }

    /// Ghosts at equal time steps, 2 to 60.
    #[wasm_bindgen(js_name = setGhosts)]
    pub fn set_ghosts(&mut self, n: f32) -> Result<(), JsError> {
        self.scene.set_ghosts(n).map_err(js)
    }

    #[wasm_bindgen(js_name = setSquash)]
    pub fn set_squash(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_squash(on);
        Ok(())
    }

    /// Uses the student's `squash_stretch_scale` (exercise 2b.1).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// Seconds from key to key.
    #[wasm_bindgen(getter)]
    pub fn duration(&self) -> f32 {
        self.scene.duration
    }

    /// Seconds of one loop: there and back, each trip with the same spacing.
    #[wasm_bindgen(getter, js_name = loopSec)]
    pub fn loop_sec(&self) -> f32 {
        self.scene.loop_sec()
    }

    /// `[t₀ (s), fraction₀, linear₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleSpacing)]
    pub fn sample_spacing(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_spacing(samples).map_err(js)?.concat())
    }

    /// Draws the figure at `time_sec` into the loop; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        // The view the paths' names are placed for (the last frame's camera).
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

impl Default for SpacingScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 2: a jump, plain and with the principles.
#[wasm_bindgen]
pub struct JumpScene {
    scene: JumpComparison,
}

#[wasm_bindgen]
impl JumpScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> JumpScene {
        let mut scene = JumpComparison::new();
        scene.set_runner(super::sandbox::run);
        JumpScene { scene }
    }

    /// Crouch depth (0 to 0.6) and stretch per m/s (0 to 0.2).
    #[wasm_bindgen(js_name = setPrinciples)]
    pub fn set_principles(&mut self, anticipation: f32, stretch: f32) -> Result<(), JsError> {
        self.scene.set_principles(anticipation, stretch).map_err(js)
    }

    /// Uses the student's `squash_stretch_scale` (exercise 2b.1).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// The loop's length, seconds.
    #[wasm_bindgen(getter)]
    pub fn duration(&self) -> f32 {
        self.scene.duration()
    }

    /// `[t₀, plain₀, principled₀, stretch₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleHeights)]
    pub fn sample_heights(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_heights(samples).map_err(js)?.concat())
    }

    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for JumpScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 3: follow-through on an antenna.
#[wasm_bindgen]
pub struct FollowThroughScene {
    scene: FollowThrough,
}

#[wasm_bindgen]
impl FollowThroughScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> FollowThroughScene {
        let mut scene = FollowThrough::new();
        scene.set_runner(super::sandbox::run);
        FollowThroughScene { scene }
    }

    /// Stiffness (50 to 600 1/s²), damping (8 to 60 1/s), joints (2 to 6).
    pub fn set(&mut self, stiffness: f32, damping: f32, joints: f32) -> Result<(), JsError> {
        self.scene.set(stiffness, damping, joints).map_err(js)
    }

    /// Compares the student's `spring_step` (exercise 2b.2) with the reference.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// `[t₀, base x₀, tip x₀, t₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleTip)]
    pub fn sample_tip(&mut self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_tip(samples).map_err(js)?.concat())
    }

    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for FollowThroughScene {
    fn default() -> Self {
        Self::new()
    }
}

/// The stretch figure: volume kept (left) against stretched along the motion only (right).
#[wasm_bindgen]
pub struct StretchScene {
    scene: crate::figures::expressive::StretchComparison,
}

#[wasm_bindgen]
impl StretchScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> StretchScene {
        StretchScene {
            scene: crate::figures::expressive::StretchComparison::new(),
        }
    }

    /// The stretch `s` (0.4 to 2.5) and the direction's angle from the x axis (−90° to 90°).
    pub fn set(&mut self, stretch: f32, angle_deg: f32) -> Result<(), JsError> {
        self.scene.set(stretch, angle_deg).map_err(js)
    }

    /// Draws both balls; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for StretchScene {
    fn default() -> Self {
        Self::new()
    }
}
