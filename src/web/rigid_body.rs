//! Bindings for lesson 14, "Rigid bodies": thin wrappers around [`crate::figures::rigid_body`].
//! Each scene keeps two copies of its figure: one stepped to the timeline's time for the drawing,
//! and one stepped to the end of the run for the plots (the curves show the whole run and the
//! cursor moves along them). The stack is pushed by the reader, so it plots what it has run.

use super::{js, Viewer};
use crate::figures::rigid_body::{
    DriftFigure, ImpulseFigure, RacketFigure, StackFigure, StackPreset, ThrowFigure,
};
use wasm_bindgen::prelude::*;

/// Flattens sample rows for JavaScript.
fn flat<const N: usize>(rows: &[[f32; N]]) -> Vec<f32> {
    rows.iter().flatten().copied().collect()
}

/// A box thrown with spin: L fixed, ω circling round it.
#[wasm_bindgen]
pub struct ThrowScene {
    scene: ThrowFigure,
    whole: ThrowFigure,
}

#[wasm_bindgen]
impl ThrowScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> Result<ThrowScene, JsError> {
        let (scene, mut whole) = (ThrowFigure::new(), ThrowFigure::new());
        whole.advance_to(whole.duration_sec()).map_err(js)?;
        Ok(ThrowScene { scene, whole })
    }
    /// Spin (rad/s, 0 to 15) and the spin axis's tilt (degrees, 0 to 80).
    #[wasm_bindgen(js_name = setThrow)]
    pub fn set_throw(&mut self, spin: f32, tilt_deg: f32) -> Result<(), JsError> {
        self.whole.set_throw(spin, tilt_deg).map_err(js)?;
        self.scene.set_throw(spin, tilt_deg).map_err(js)?;
        self.whole.advance_to(self.whole.duration_sec()).map_err(js)
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }
    /// `[t, |ω| / |ω₀|, |L| / |L₀|, angle between ω and L (°)]` per step of the whole run.
    pub fn samples(&self) -> Vec<f32> {
        flat(&self.whole.plot_rows())
    }
    /// Steps to `time_sec` and draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.scene.advance_to(time_sec).map_err(js)?;
        // The view the labels at the arrows' tips are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

/// One box spun three times, its quaternion stepped three ways.
#[wasm_bindgen]
pub struct DriftScene {
    scene: DriftFigure,
    whole: DriftFigure,
}

#[wasm_bindgen]
impl DriftScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> Result<DriftScene, JsError> {
        let mut scene = DriftFigure::new();
        scene.set_runner(super::sandbox::run);
        let mut whole = scene.clone();
        whole.advance_to(whole.duration_sec()).map_err(js)?;
        Ok(DriftScene { scene, whole })
    }
    /// Spin (rad/s, 1 to 30) and step (ms, 1 to 50).
    #[wasm_bindgen(js_name = setDrift)]
    pub fn set_drift(&mut self, spin: f32, step_ms: f32) -> Result<(), JsError> {
        self.whole.set_drift(spin, step_ms).map_err(js)?;
        self.scene.set_drift(spin, step_ms).map_err(js)?;
        self.whole.advance_to(self.whole.duration_sec()).map_err(js)
    }
    /// Steps the normalised box with the student's 14.2.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.whole.set_use_exercise(on);
        self.scene.set_use_exercise(on);
        self.whole.advance_to(self.whole.duration_sec()).map_err(js)
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }
    /// `[t, |q| normalised, |q| unnormalised, |q| exponential]` per step of the whole run.
    pub fn samples(&self) -> Vec<f32> {
        flat(self.whole.samples())
    }
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.scene.advance_to(time_sec).map_err(js)?;
        // The view the boxes' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

/// The tennis racket: three integrators of the angular velocity side by side.
#[wasm_bindgen]
pub struct RacketScene {
    scene: RacketFigure,
    whole: RacketFigure,
}

#[wasm_bindgen]
impl RacketScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> Result<RacketScene, JsError> {
        let mut scene = RacketFigure::new();
        scene.set_runner(super::sandbox::run);
        let mut whole = scene.clone();
        whole.advance_to(whole.duration_sec()).map_err(js)?;
        Ok(RacketScene { scene, whole })
    }
    /// Spin about the middle axis (rad/s, 0.5 to 20) and the wobble about the two others (rad/s,
    /// 0 to 1); both runs start again.
    #[wasm_bindgen(js_name = setSpin)]
    pub fn set_spin(&mut self, spin: f32, wobble: f32) -> Result<(), JsError> {
        self.whole.set_spin(spin, wobble).map_err(js)?;
        self.scene.set_spin(spin, wobble).map_err(js)?;
        self.whole.advance_to(self.whole.duration_sec()).map_err(js)
    }
    /// The rackets' moments from the student's 14.1.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.whole.set_use_exercise(on);
        self.scene.set_use_exercise(on);
        self.whole.advance_to(self.whole.duration_sec()).map_err(js)
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }
    /// `[t, energy × 3, |L| × 3]` per step over the whole run, each over its start value.
    pub fn samples(&self) -> Vec<f32> {
        flat(self.whole.samples())
    }
    /// The plots' y ranges over the whole run, `[energy lo, hi, |L| lo, hi]` (see
    /// `RacketFigure::plot_ranges`).
    #[wasm_bindgen(js_name = plotRanges)]
    pub fn plot_ranges(&self) -> Vec<f32> {
        self.whole.plot_ranges().to_vec()
    }
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.scene.advance_to(time_sec).map_err(js)?;
        // The view the rackets' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

/// A tilted box hitting the ground on one corner: one impulse.
#[wasm_bindgen]
pub struct ImpulseScene {
    scene: ImpulseFigure,
    whole: ImpulseFigure,
}

#[wasm_bindgen]
impl ImpulseScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> Result<ImpulseScene, JsError> {
        let mut scene = ImpulseFigure::new();
        scene.set_runner(super::sandbox::run);
        let mut whole = scene.clone();
        whole.advance_to(whole.duration_sec()).map_err(js)?;
        Ok(ImpulseScene { scene, whole })
    }
    /// Tilt (degrees, 0 to 45), restitution (0 to 1), drop height (m, 0.2 to 2).
    #[wasm_bindgen(js_name = setDrop)]
    pub fn set_drop(
        &mut self,
        tilt_deg: f32,
        restitution: f32,
        height_m: f32,
    ) -> Result<(), JsError> {
        self.whole
            .set_drop(tilt_deg, restitution, height_m)
            .map_err(js)?;
        self.scene
            .set_drop(tilt_deg, restitution, height_m)
            .map_err(js)?;
        self.whole.advance_to(self.whole.duration_sec()).map_err(js)
    }
    /// The impulse from the student's 14.3 and 14.4.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.whole.set_use_exercise(on);
        self.scene.set_use_exercise(on);
        self.whole.advance_to(self.whole.duration_sec()).map_err(js)
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }
    /// `[t, height of the centre (m), normal velocity of the lowest corner (m/s), kinetic
    /// energy (J)]` per step of the whole run.
    pub fn samples(&self) -> Vec<f32> {
        flat(self.whole.samples())
    }
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.scene.advance_to(time_sec).map_err(js)?;
        // The view the arrows' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

/// A stack of boxes or a row of dominoes on the contact solver.
#[wasm_bindgen]
pub struct StackScene {
    scene: StackFigure,
}

#[wasm_bindgen]
impl StackScene {
    /// `preset`: "stack" or "dominoes".
    #[wasm_bindgen(constructor)]
    pub fn new(preset: JsValue) -> Result<StackScene, JsError> {
        let preset: &str = &super::string("preset", &preset)?;
        let preset = match preset {
            "stack" => StackPreset::Stack,
            "dominoes" => StackPreset::Dominoes,
            other => {
                return Err(JsError::new(&format!(
                    "no scene named {other:?}: \"stack\" or \"dominoes\""
                )))
            }
        };
        Ok(StackScene {
            scene: StackFigure::new(preset),
        })
    }
    /// Solver passes (whole, 1 to 50), friction μ (0 to 1), restitution e (0 to 1).
    #[wasm_bindgen(js_name = setSolver)]
    pub fn set_solver(
        &mut self,
        iterations: f32,
        friction: f32,
        restitution: f32,
    ) -> Result<(), JsError> {
        self.scene
            .set_solver(iterations, friction, restitution)
            .map_err(js)
    }
    /// A shove on the top box (the stack) or on the first domino; an error past the figure's
    /// cap on pushes or after a failed step.
    pub fn push(&mut self) -> Result<(), JsError> {
        self.scene.push().map_err(js)
    }
    pub fn reset(&mut self) {
        self.scene.reset();
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }
    /// `[t, kinetic energy (J), distance the top box (the last domino) has moved (m)]` per step
    /// so far.
    pub fn samples(&self) -> Vec<f32> {
        flat(self.scene.samples())
    }
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.scene.advance_to(time_sec).map_err(js)?;
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}
