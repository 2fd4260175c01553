//! Bindings for lesson 06's glTF figure: thin wrappers around [`crate::figures::gltf`].

use super::{js, Viewer};
use crate::figures::gltf::GltfFigure;
use wasm_bindgen::prelude::*;

/// A character imported from a glTF file, drawn as its skeleton.
#[wasm_bindgen]
pub struct GltfScene {
    scene: GltfFigure,
}

#[wasm_bindgen]
impl GltfScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> GltfScene {
        GltfScene {
            scene: GltfFigure::new(),
        }
    }

    /// Imports a `.gltf` (embedded buffers) or `.glb` file's bytes; returns a summary, or an
    /// error that says what is wrong with the file (what was loaded before stays).
    pub fn load(&mut self, name: &str, bytes: &[u8]) -> Result<String, JsError> {
        self.scene.load(name, bytes).map_err(js)
    }

    #[wasm_bindgen(getter, js_name = isLoaded)]
    pub fn is_loaded(&self) -> bool {
        self.scene.is_loaded()
    }

    #[wasm_bindgen(js_name = clipNames)]
    pub fn clip_names(&self) -> Vec<String> {
        self.scene.clip_names()
    }

    #[wasm_bindgen(js_name = setClip)]
    pub fn set_clip(&mut self, index: usize) -> Result<(), JsError> {
        self.scene.set_clip(index).map_err(js)
    }

    /// The current clip's duration, seconds.
    #[wasm_bindgen(getter)]
    pub fn duration(&self) -> f32 {
        self.scene.duration_sec()
    }

    #[wasm_bindgen(js_name = setShowMesh)]
    pub fn set_show_mesh(&mut self, on: bool) {
        self.scene.set_show_mesh(on);
    }

    /// `[x, y, z, distance]` that frame the character.
    pub fn fit(&self) -> Vec<f32> {
        self.scene.fit().to_vec()
    }

    /// Draws at `time_sec`; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for GltfScene {
    fn default() -> Self {
        Self::new()
    }
}
