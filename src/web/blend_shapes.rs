//! Bindings for lesson 10, "Blend shapes": thin wrappers around [`crate::figures::blend_shapes`].
//! The face's mesh is created once and rewritten in place each frame.

use super::{js, Viewer};
use crate::draw::MeshId;
use crate::figures::blend_shapes::FaceFigure;
use crate::mesh::MeshData;
use wasm_bindgen::prelude::*;

/// The face with four blend shapes.
#[wasm_bindgen]
pub struct BlendShapeFaceScene {
    scene: FaceFigure,
    mesh: Option<MeshId>,
}

#[wasm_bindgen]
impl BlendShapeFaceScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> BlendShapeFaceScene {
        let mut scene = FaceFigure::new();
        scene.set_runner(super::sandbox::run);
        BlendShapeFaceScene { scene, mesh: None }
    }

    #[wasm_bindgen(js_name = targetNames)]
    pub fn target_names(&self) -> Vec<String> {
        self.scene.target_names()
    }

    /// Weight of target `k`, in [−0.5, 1.5].
    #[wasm_bindgen(js_name = setWeight)]
    pub fn set_weight(&mut self, k: usize, w: f32) -> Result<(), JsError> {
        self.scene.set_weight(k, w).map_err(js)
    }

    /// "full" or "differential".
    #[wasm_bindgen(js_name = setForm)]
    pub fn set_form(&mut self, name: &str) -> Result<(), JsError> {
        self.scene.set_form(name).map_err(js)
    }

    /// The full form's base weight in [0, 1], or negative for "1 − Σ wₖ".
    #[wasm_bindgen(js_name = setBaseWeight)]
    pub fn set_base_weight(&mut self, w: f32) -> Result<(), JsError> {
        self.scene.set_base_weight(w).map_err(js)
    }

    #[wasm_bindgen(js_name = setAnimate)]
    pub fn set_animate(&mut self, on: bool) {
        self.scene.set_animate(on);
    }

    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: bool) {
        self.scene.set_use_exercise(on);
    }

    /// Blends at `time_sec`, uploads and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let id = match self.mesh {
            Some(id) => id,
            None => {
                let data = MeshData {
                    positions: self.scene.mesh.positions.clone(),
                    normals: self.scene.mesh.normals.clone(),
                    indices: self.scene.indices().to_vec(),
                };
                let id = viewer.renderer.create_mesh(&viewer.gpu, &data, None);
                self.mesh = Some(id);
                id
            }
        };
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, id, time_sec)
            .map_err(js)?;
        if self.scene.mesh.take_dirty() {
            viewer
                .renderer
                .update_mesh(
                    &viewer.gpu,
                    id,
                    &self.scene.mesh.positions,
                    &self.scene.mesh.normals,
                )
                .map_err(|e| JsError::new(&e))?;
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
