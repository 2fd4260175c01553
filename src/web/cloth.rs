//! Bindings for lesson 13, "Cloth": thin wrappers around [`crate::figures::cloth`]. Each cloth's
//! mesh is created once per resolution (`Renderer::create_mesh`) and rewritten in place every
//! frame (`Renderer::update_mesh_with_colors`).

use super::{js, Viewer};
use crate::camera::OrbitCamera;
use crate::draw::MeshId;
use crate::figures::cloth::{ClothFigure, Preset, SpringFigure};
use std::collections::HashMap;
use wasm_bindgen::prelude::*;

/// A flag pair in the wind or a cloth draped on a sphere.
#[wasm_bindgen]
pub struct ClothScene {
    scene: ClothFigure,
    /// GPU meshes by (cloth, vertex count), created once each.
    meshes: HashMap<(usize, usize), MeshId>,
    current: Vec<MeshId>,
    camera: Option<OrbitCamera>,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl ClothScene {
    /// `preset`: "flag" or "drape".
    #[wasm_bindgen(constructor)]
    pub fn new(preset: JsValue) -> Result<ClothScene, JsError> {
        let preset: &str = &super::string("preset", &preset)?;
        let preset = match preset {
            "flag" => Preset::Flag,
            "drape" => Preset::Drape,
            other => return Err(JsError::new(&format!("no cloth preset named {other:?}"))),
        };
        Ok(ClothScene {
            scene: ClothFigure::new(preset),
            meshes: HashMap::new(),
            current: Vec::new(),
            camera: None,
            gpu_seen: 0,
        })
    }
    /// "structural", "shear" or "bending"; N/m in [0, 5000].
    #[wasm_bindgen(js_name = setStiffness)]
    pub fn set_stiffness(&mut self, kind: JsValue, k: f32) -> Result<(), JsError> {
        let kind: &str = &super::string("kind", &kind)?;
        self.scene.set_stiffness(kind, k).map_err(js)
    }
    /// N·s/m in [0, 1].
    #[wasm_bindgen(js_name = setDamping)]
    pub fn set_damping(&mut self, c: f32) -> Result<(), JsError> {
        self.scene.set_damping(c).map_err(js)
    }
    /// Frame step, ms in [5, 50].
    #[wasm_bindgen(js_name = setStepMs)]
    pub fn set_step_ms(&mut self, ms: f32) -> Result<(), JsError> {
        self.scene.set_step_ms(ms).map_err(js)
    }
    /// In [1, 40].
    #[wasm_bindgen(js_name = setSubsteps)]
    pub fn set_substeps(&mut self, n: f32) -> Result<(), JsError> {
        self.scene.set_substeps(n).map_err(js)
    }
    /// m/s in [0, 20].
    #[wasm_bindgen(js_name = setWind)]
    pub fn set_wind(&mut self, speed: f32) -> Result<(), JsError> {
        self.scene.set_wind(speed).map_err(js)
    }
    /// "none", "two corners" or "whole edge".
    #[wasm_bindgen(js_name = setPins)]
    pub fn set_pins(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_pins(name).map_err(js)
    }
    /// "mass-spring" or "XPBD".
    #[wasm_bindgen(js_name = setMethod)]
    pub fn set_method(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_method(name).map_err(js)
    }
    /// Particles per side, in [4, 100].
    #[wasm_bindgen(js_name = setResolution)]
    pub fn set_resolution(&mut self, side: f32) -> Result<(), JsError> {
        self.scene.set_resolution(side).map_err(js)
    }
    /// Metres, each in [−1.5, 1.5].
    #[wasm_bindgen(js_name = setObstacles)]
    pub fn set_obstacles(&mut self, sphere_x: f32, box_x: f32, box_z: f32) -> Result<(), JsError> {
        self.scene.set_obstacles(sphere_x, box_x, box_z).map_err(js)
    }
    /// μ in [0, 2].
    #[wasm_bindgen(js_name = setFriction)]
    pub fn set_friction(&mut self, mu: f32) -> Result<(), JsError> {
        self.scene.set_friction(mu).map_err(js)
    }
    /// Back to the start, forgetting the drags.
    pub fn reset(&mut self) {
        self.scene.reset();
    }
    /// `[t, energy per cloth (J)…, max stretch per cloth (%)…]` per frame.
    pub fn samples(&self) -> Vec<f32> {
        self.scene.samples()
    }
    /// Changes whenever `samples` or `plotRanges` may have: the page's cheap check before it
    /// copies the samples.
    #[wasm_bindgen(js_name = sampleGeneration)]
    pub fn sample_generation(&self) -> u32 {
        self.scene.sample_generation()
    }
    /// `[energy lo, hi, stretch lo, hi]`: the flag plots' data ranges over the cloths that held
    /// (NaN before the first sample).
    #[wasm_bindgen(js_name = plotRanges)]
    pub fn plot_ranges(&self) -> Vec<f32> {
        self.scene.plot_ranges().to_vec()
    }
    /// Starts measuring the substeps the mass-spring cloth needs against its structural
    /// stiffness, at this figure's other settings (see `SubstepSearch`).
    #[wasm_bindgen(js_name = substepSearch)]
    pub fn substep_search(&self) -> Result<SubstepSearch, JsError> {
        Ok(SubstepSearch {
            search: self.scene.substep_search().map_err(js)?,
        })
    }
    /// When cloth `k` exploded (seconds since the start), or `undefined` while it holds.
    #[wasm_bindgen(js_name = explodedAt)]
    pub fn exploded_at(&self, k: f64) -> Result<Option<f32>, JsError> {
        let k = super::whole("k", k)?;
        Ok(self.scene.exploded(k))
    }

    /// Frames the last `draw` simulated going on from the previous one (0 after a replay from
    /// the start): the page times one simulated frame with it.
    #[wasm_bindgen(js_name = lastStepFrames)]
    pub fn last_step_frames(&self) -> usize {
        self.scene.last_step_frames()
    }

    /// How many cloths are drawn (1 or 2).
    #[wasm_bindgen(js_name = clothCount)]
    pub fn cloth_count(&self) -> usize {
        self.scene.cloth_count()
    }
    /// Seconds the timeline covers.
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        crate::figures::cloth::DURATION
    }
    /// Grabs the free particle under the pointer at `(x, y)` CSS pixels (canvas `width` ×
    /// `height`); returns whether there was one.
    pub fn grab(&mut self, x: f32, y: f32, width: f32, height: f32) -> Result<bool, JsError> {
        self.use_view(x, y, width, height)?;
        self.scene.grab(x, y).map_err(js)
    }
    /// Moves the grabbed particle's target under the pointer.
    pub fn drag(&mut self, x: f32, y: f32, width: f32, height: f32) -> Result<(), JsError> {
        self.use_view(x, y, width, height)?;
        self.scene.drag(x, y).map_err(js)
    }
    pub fn release(&mut self) {
        self.scene.release();
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
    /// Simulates to `time_sec` without drawing; returns the frames simulated. `draw` does the
    /// same, then draws.
    #[wasm_bindgen(js_name = advanceTo)]
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, JsError> {
        self.scene.advance_to(time_sec).map_err(js)
    }
    /// Simulates to `time_sec` and draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.camera = Some(viewer.camera);
        // The view the drape's name is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        if viewer.renewed(&mut self.gpu_seen) {
            self.meshes.clear();
            self.current.clear();
        }
        if self.scene.take_structure_changed() || self.current.len() != self.scene.cloth_count() {
            self.current.clear();
            for k in 0..self.scene.cloth_count() {
                let (data, colors) = self.scene.mesh_data(k);
                let key = (k, data.positions.len());
                let id = *self.meshes.entry(key).or_insert_with(|| {
                    viewer
                        .renderer
                        .create_mesh(&viewer.gpu, &data, Some(&colors))
                });
                self.current.push(id);
            }
        }
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, &self.current, time_sec)
            .map_err(js)?;
        for (k, &id) in self.current.iter().enumerate() {
            let (p, n, c) = self.scene.render_buffers(k);
            viewer
                .renderer
                .update_mesh_with_colors(&viewer.gpu, id, p, n, c)
                .map_err(|e| JsError::new(&e))?;
        }
        viewer.present()?;
        Ok(note)
    }
}

/// One particle on a spring beside one on a distance constraint.
#[wasm_bindgen]
pub struct SpringScene {
    scene: SpringFigure,
}

#[wasm_bindgen]
impl SpringScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SpringScene {
        let mut scene = SpringFigure::new();
        scene.set_runner(super::sandbox::run);
        SpringScene { scene }
    }
    /// N/m in [1, 400].
    #[wasm_bindgen(js_name = setStiffness)]
    pub fn set_stiffness(&mut self, k: f32) -> Result<(), JsError> {
        self.scene.set_stiffness(k).map_err(js)
    }
    /// N·s/m in [0, 1].
    #[wasm_bindgen(js_name = setDamping)]
    pub fn set_damping(&mut self, c: f32) -> Result<(), JsError> {
        self.scene.set_damping(c).map_err(js)
    }
    /// ms in [2, 80].
    #[wasm_bindgen(js_name = setStepMs)]
    pub fn set_step_ms(&mut self, ms: f32) -> Result<(), JsError> {
        self.scene.set_step_ms(ms).map_err(js)
    }
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        crate::figures::cloth::SPRING_DURATION
    }
    /// `[t, length mass-spring (m), length XPBD (m)]` per step.
    #[wasm_bindgen(js_name = lengthSamples)]
    pub fn length_samples(&self) -> Vec<f32> {
        self.scene.length_samples()
    }
    /// The note `draw` returns at `time_sec`, without a canvas (the figure is a function of the
    /// time: nothing is stepped).
    #[wasm_bindgen(js_name = noteAt)]
    pub fn note_at(&self, time_sec: f32) -> Result<String, JsError> {
        let mut scratch = crate::draw::Frame::default();
        self.scene.draw(&mut scratch, time_sec).map_err(js)
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

impl Default for SpringScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Builds a cloth of `columns × rows` particles (2 m square, 0.5 kg) and says what is wrong, or
/// "ok": the wasm-boundary check of the core's validation and its cap. Cap (the build's work
/// grows with columns × rows): each side at most 256 particles (`cloth::MAX_SIDE`), checked
/// before anything is built.
#[wasm_bindgen(js_name = checkCloth)]
pub fn check_cloth(columns: f64, rows: f64, mass_kg: f32) -> Result<String, JsError> {
    use crate::cloth::{Cloth, ClothSpec};
    let count = |name: &str, x: f64| {
        if x.is_finite() && x.fract() == 0.0 && x.abs() < 1e9 {
            Ok(x as i64)
        } else {
            Err(JsError::new(&format!(
                "{name} must be a whole number, got {x}"
            )))
        }
    };
    let spec = ClothSpec {
        columns: count("columns", columns)?,
        rows: count("rows", rows)?,
        mass_kg,
        ..ClothSpec::level(2, 1.0)
    };
    let cloth = Cloth::new(&spec).map_err(|e| JsError::new(&e.to_string()))?;
    Ok(format!(
        "ok: {} particles, {} springs, {} triangles",
        cloth.len(),
        cloth.springs.len(),
        cloth.triangles.len()
    ))
}

/// A measurement of the substeps a mass-spring cloth needs, run a few frames at a time.
#[wasm_bindgen]
pub struct SubstepSearch {
    search: crate::figures::cloth::SubstepSearch,
}

#[wasm_bindgen]
impl SubstepSearch {
    /// Simulates at most `frames` frames (a whole number from 1 to 10,000: about a second) of the runs the
    /// search needs; true when it is finished.
    pub fn work(&mut self, frames: f64) -> Result<bool, JsError> {
        let frames = super::whole_in("frames", frames, 1, 10_000)?;
        self.search.work(frames).map_err(js)
    }
    /// How many of the stiffnesses have their answer.
    pub fn done(&self) -> usize {
        self.search.done()
    }
    /// Rows of `[k, fewest substeps, c·√k fit, conservative limit]` (NaN: past 40 or not yet).
    pub fn rows(&self) -> Vec<f32> {
        self.search.rows()
    }
}
