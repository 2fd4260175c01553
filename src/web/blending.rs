//! Bindings for lesson 08, "Blending": thin wrappers around [`crate::figures::blending`], which
//! holds the figures' logic and is tested natively.

use super::{js, Viewer};
use crate::figures::blending::{
    BlendFigure, LocomotionFigure, LOCOMOTION_LOOP_SEC, LOCOMOTION_PLOT_RANGES,
};
use wasm_bindgen::prelude::*;

/// Crossfade, mask and additive layer on the simple human.
#[wasm_bindgen]
pub struct BlendScene {
    scene: BlendFigure,
}

#[wasm_bindgen]
impl BlendScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> BlendScene {
        let mut scene = BlendFigure::new();
        scene.set_runner(super::sandbox::run);
        BlendScene { scene }
    }

    #[wasm_bindgen(js_name = clipNames)]
    pub fn clip_names(&self) -> Vec<String> {
        self.scene.clip_names()
    }

    /// Clip A (the timeline's) and clip B (at the same phase).
    #[wasm_bindgen(js_name = setClips)]
    pub fn set_clips(&mut self, a: JsValue, b: JsValue) -> Result<(), JsError> {
        let a: &str = &super::string("a", &a)?;
        let b: &str = &super::string("b", &b)?;
        self.scene.set_clips(a, b).map_err(js)
    }

    /// Weight of clip B, in [0, 1].
    #[wasm_bindgen(js_name = setWeight)]
    pub fn set_weight(&mut self, w: f32) -> Result<(), JsError> {
        self.scene.set_weight(w).map_err(js)
    }

    /// "whole body", "upper body from B" or "lower body from B".
    #[wasm_bindgen(js_name = setMask)]
    pub fn set_mask(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_mask(name).map_err(js)
    }

    /// "none", "lean forward (a pose)" or "wave (a clip)", with a weight in [0, 1].
    #[wasm_bindgen(js_name = setAdditive)]
    pub fn set_additive(&mut self, name: JsValue, weight: f32) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_additive(name, weight).map_err(js)
    }

    /// Blends with the student's exercise 6.3 (in the sandbox).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// `[time (s), right arm raised (°) in clip A, clip B, the mix, the mix with the additive
    /// layer, the additive layer alone]` per sample over one cycle of clip A; `samples` in
    /// [2, 10000].
    #[wasm_bindgen(js_name = armSamples)]
    pub fn arm_samples(&mut self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        self.scene.arm_samples(samples).map_err(js)
    }

    /// Clip A's duration, seconds.
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }

    /// Poses at `time_sec` and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for BlendScene {
    fn default() -> Self {
        Self::new()
    }
}

/// The travelling walk and run blended for a speed.
#[wasm_bindgen]
pub struct LocomotionScene {
    scene: LocomotionFigure,
}

#[wasm_bindgen]
impl LocomotionScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> LocomotionScene {
        let mut scene = LocomotionFigure::new();
        scene.set_runner(super::sandbox::run);
        LocomotionScene { scene }
    }

    /// Blends with the weight from the student's exercise 8.1 (in the sandbox).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// Both settings side by side (`true`, the default) or the one `setSynchronised` names.
    #[wasm_bindgen(js_name = setCompare)]
    pub fn set_compare(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_compare(on);
        Ok(())
    }

    /// `[walking speed, running speed]`, m/s.
    #[wasm_bindgen(js_name = speedRange)]
    pub fn speed_range(&self) -> Vec<f32> {
        let (lo, hi) = self.scene.speed_range();
        vec![lo, hi]
    }

    /// Speed in m/s, within `speedRange()`.
    #[wasm_bindgen(js_name = setSpeed)]
    pub fn set_speed(&mut self, speed: f32) -> Result<(), JsError> {
        self.scene.set_speed(speed).map_err(js)
    }

    #[wasm_bindgen(js_name = setSynchronised)]
    pub fn set_synchronised(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_synchronised(on);
        Ok(())
    }

    #[wasm_bindgen(js_name = setRootMotion)]
    pub fn set_root_motion(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_root_motion(on);
        Ok(())
    }

    /// The timeline's length, seconds.
    #[wasm_bindgen(js_name = loopSec)]
    pub fn loop_sec(&self) -> f32 {
        LOCOMOTION_LOOP_SEC
    }

    /// The plots' fixed y ranges: `[gap from, to (cycles), slide from, to (cm)]`.
    #[wasm_bindgen(js_name = plotRanges)]
    pub fn plot_ranges(&self) -> Vec<f32> {
        LOCOMOTION_PLOT_RANGES.to_vec()
    }

    /// `[time (s), phase gap synchronised, not (cycles), slide synchronised, not (cm), …]`
    /// every 25 ms over the timeline, at the current speed.
    #[wasm_bindgen(js_name = plotSamples)]
    pub fn plot_samples(&mut self) -> Vec<f32> {
        self.scene.plot_samples()
    }

    /// Poses at `time_sec` and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for LocomotionScene {
    fn default() -> Self {
        Self::new()
    }
}
