//! Bindings for lesson 10, "Blend shapes": thin wrappers around [`crate::figures::blend_shapes`].
//! The two heads' meshes (differential, full) are created once and rewritten in place each frame.

use super::{js, Viewer};
use crate::draw::MeshId;
use crate::figures::blend_shapes::{FaceFigure, TargetsFigure};
use crate::mesh::MeshData;
use wasm_bindgen::prelude::*;

/// The face with four blend shapes.
#[wasm_bindgen]
pub struct BlendShapeFaceScene {
    scene: FaceFigure,
    meshes: Option<[MeshId; 2]>,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl BlendShapeFaceScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> BlendShapeFaceScene {
        let mut scene = FaceFigure::new();
        scene.set_runner(super::sandbox::run);
        BlendShapeFaceScene {
            scene,
            meshes: None,
            gpu_seen: 0,
        }
    }

    #[wasm_bindgen(js_name = targetNames)]
    pub fn target_names(&self) -> Vec<String> {
        self.scene.target_names()
    }

    /// The sliders' target weights, in the order of `targetNames`.
    pub fn weights(&self) -> Vec<f32> {
        self.scene.weights().to_vec()
    }

    /// Weight of target `k`, in [−0.5, 1.5].
    #[wasm_bindgen(js_name = setWeight)]
    pub fn set_weight(&mut self, k: f64, w: f32) -> Result<(), JsError> {
        let k = super::whole("k", k)?;
        self.scene.set_weight(k, w).map_err(js)
    }

    /// "both" (differential left, full right), "differential" or "full".
    #[wasm_bindgen(js_name = setShow)]
    pub fn set_show(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_show(name).map_err(js)
    }

    /// `[time (s), four weights, Σ w, base + Σ w]` per sample over the 4 s loop; `samples` in
    /// [2, 10000].
    #[wasm_bindgen(js_name = weightCurves)]
    pub fn weight_curves(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        self.scene.weight_curves(samples).map_err(js)
    }

    /// The full form's base weight by hand, in [0, 1].
    #[wasm_bindgen(js_name = setBaseWeight)]
    pub fn set_base_weight(&mut self, w: f32) -> Result<(), JsError> {
        self.scene.set_base_weight(w).map_err(js)
    }

    /// `[x, y, z, distance]`: where to aim the camera so both heads fit at their largest over
    /// the loop (changes only when a control does).
    #[wasm_bindgen(js_name = viewFit)]
    pub fn view_fit(&self) -> Vec<f32> {
        self.scene.view_fit().to_vec()
    }

    /// `true`: the full form's base weight is 1 − Σ wₖ; `false`: the one set by hand.
    #[wasm_bindgen(js_name = setBaseAuto)]
    pub fn set_base_auto(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_base_auto(on);
        Ok(())
    }

    /// Arrows from each sampled vertex's base position to its blended one.
    #[wasm_bindgen(js_name = setShowDeltas)]
    pub fn set_show_deltas(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_deltas(on);
        Ok(())
    }

    #[wasm_bindgen(js_name = setAnimate)]
    pub fn set_animate(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_animate(on);
        Ok(())
    }

    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// Blends at `time_sec`, uploads and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let renewed = viewer.renewed(&mut self.gpu_seen);
        if renewed {
            self.meshes = None;
        }
        let ids = match self.meshes {
            Some(ids) => ids,
            None => {
                let indices = self.scene.indices().to_vec();
                // Both heads carry the face's paint (lips, mouth, brows, cheeks) per vertex.
                let colors = self.scene.differential.colors.clone();
                let mut create = |positions: &[glam::Vec3]| {
                    let data = MeshData {
                        positions: positions.to_vec(),
                        normals: vec![glam::Vec3::Y; positions.len()],
                        indices: indices.clone(),
                    };
                    viewer
                        .renderer
                        .create_mesh(&viewer.gpu, &data, Some(&colors))
                };
                let ids = [
                    create(&self.scene.differential.positions),
                    create(&self.scene.full.positions),
                ];
                self.meshes = Some(ids);
                ids
            }
        };
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, ids, time_sec)
            .map_err(js)?;
        for (id, mesh) in ids
            .into_iter()
            .zip([&mut self.scene.differential, &mut self.scene.full])
        {
            if mesh.take_dirty() || renewed {
                viewer
                    .renderer
                    .update_mesh(&viewer.gpu, id, &mesh.positions, &mesh.normals)
                    .map_err(|e| JsError::new(&e))?;
            }
        }
        viewer.present()?;
        Ok(note)
    }
}

impl Default for BlendShapeFaceScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 1: the base head and each target on its own.
#[wasm_bindgen]
pub struct BlendShapeTargetsScene {
    scene: TargetsFigure,
    meshes: Vec<MeshId>,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl BlendShapeTargetsScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> BlendShapeTargetsScene {
        BlendShapeTargetsScene {
            scene: TargetsFigure::new(),
            meshes: Vec::new(),
            gpu_seen: 0,
        }
    }

    #[wasm_bindgen(js_name = targetNames)]
    pub fn target_names(&self) -> Vec<String> {
        self.scene.target_names()
    }

    /// The weight every target head is shown at, in [0, 1.5].
    #[wasm_bindgen(js_name = setWeight)]
    pub fn set_weight(&mut self, w: f32) -> Result<(), JsError> {
        self.scene.set_weight(w).map_err(js)
    }

    /// Arrows along w·dₖ on each target head.
    #[wasm_bindgen(js_name = setShowDeltas)]
    pub fn set_show_deltas(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_deltas(on);
        Ok(())
    }

    /// Blends what changed, uploads and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        if viewer.renewed(&mut self.gpu_seen) {
            self.meshes.clear();
        }
        if self.meshes.is_empty() {
            let indices = self.scene.indices().to_vec();
            for head in &self.scene.heads {
                let data = MeshData {
                    positions: head.positions.clone(),
                    normals: head.normals.clone(),
                    indices: indices.clone(),
                };
                let id = viewer
                    .renderer
                    .create_mesh(&viewer.gpu, &data, Some(&head.colors));
                self.meshes.push(id);
            }
        }
        // The rows of heads run across the last frame's view.
        self.scene.set_view(viewer.camera);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, &self.meshes)
            .map_err(js)?;
        for (&id, head) in self.meshes.iter().zip(&mut self.scene.heads) {
            if head.take_dirty() {
                viewer
                    .renderer
                    .update_mesh(&viewer.gpu, id, &head.positions, &head.normals)
                    .map_err(|e| JsError::new(&e))?;
            }
        }
        viewer.present()?;
        Ok(note)
    }
}

impl Default for BlendShapeTargetsScene {
    fn default() -> Self {
        Self::new()
    }
}
