//! Bindings for lesson 06's glTF figure: thin wrappers around [`crate::figures::gltf`].

use super::{js, Viewer};
use crate::draw::MeshId;
use crate::figures::gltf::GltfFigure;
use wasm_bindgen::prelude::*;

/// A character imported from a glTF file, drawn as its skeleton (and skinned, in lesson 09).
#[wasm_bindgen]
pub struct GltfScene {
    scene: GltfFigure,
    /// GPU meshes of the loaded file (bind pose, rewritten in place when skinned).
    meshes: Vec<MeshId>,
    /// The figure's load count these meshes were made for.
    generation: u32,
    /// The same meshes for skinning in the vertex shader (made on first use per file).
    skin_meshes: Vec<crate::draw::SkinMeshId>,
    skin_generation: u32,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl GltfScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> GltfScene {
        GltfScene {
            scene: GltfFigure::new(),
            meshes: Vec::new(),
            generation: 0,
            skin_meshes: Vec::new(),
            skin_generation: 0,
            gpu_seen: 0,
        }
    }

    /// Shows a file imported by the glTF module (`importGltf` there returns `bytes`, a
    /// `Uint8Array`); returns a summary, or an error that says what is wrong (what was loaded
    /// before stays). The bytes are checked as thoroughly as a file is
    /// ([`crate::gltf_import::wire::decode`]), at most `wire::MAX_WIRE_BYTES` of them (checked
    /// before they are copied out of JavaScript).
    #[wasm_bindgen(js_name = loadImported)]
    pub fn load_imported(&mut self, name: JsValue, bytes: JsValue) -> Result<String, JsError> {
        let name: &str = &super::string("name", &name)?;
        let array = super::bytes("bytes", &bytes)?;
        let (len, max) = (
            array.length() as usize,
            crate::gltf_import::wire::MAX_WIRE_BYTES,
        );
        if len > max {
            let why = format!("the imported model has {len} bytes; the figure reads at most {max}");
            return Err(js(self.scene.reject(name, &why)));
        }
        self.scene.load_imported(name, &array.to_vec()).map_err(js)
    }

    /// Records that the file `name` could not be imported, and why (the glTF module's error):
    /// the note says so, and what was loaded before stays. Returns the message it shows.
    pub fn reject(&mut self, name: JsValue, why: JsValue) -> Result<String, JsError> {
        let name = super::string("name", &name)?;
        let why = super::string("why", &why)?;
        Ok(self.scene.reject(&name, &why))
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
    pub fn set_clip(&mut self, index: f64) -> Result<(), JsError> {
        let index = super::whole("index", index)?;
        self.scene.set_clip(index).map_err(js)
    }

    /// The current clip's duration, seconds.
    #[wasm_bindgen(getter)]
    pub fn duration(&self) -> f32 {
        self.scene.duration_sec()
    }

    #[wasm_bindgen(js_name = setShowMesh)]
    pub fn set_show_mesh(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_mesh(on);
        Ok(())
    }

    /// While skinning, the bind-pose vertices as dots over the skinned mesh (`true`) or not.
    #[wasm_bindgen(js_name = setShowBindPose)]
    pub fn set_show_bind_pose(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_bind_pose(on);
        Ok(())
    }

    /// "dots" (the bind-pose vertices), "lbs" or "dqs".
    #[wasm_bindgen(js_name = setSkinning)]
    pub fn set_skinning(&mut self, mode: JsValue) -> Result<(), JsError> {
        let mode: &str = &super::string("mode", &mode)?;
        self.scene.set_skinning(mode).map_err(js)
    }

    /// Skins in the vertex shader (`true`) or on the CPU (`false`, the default).
    #[wasm_bindgen(js_name = setGpu)]
    pub fn set_gpu(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_gpu(on);
        Ok(())
    }

    /// `[x, y, z, distance]` that frame the character.
    pub fn fit(&self) -> Vec<f32> {
        self.scene.fit().to_vec()
    }

    /// Draws at `time_sec`; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        if viewer.renewed(&mut self.gpu_seen) {
            // The meshes went with the lost renderer: make them again, as for a new file.
            (self.meshes, self.skin_meshes) = (Vec::new(), Vec::new());
            self.generation = self.scene.generation().wrapping_add(1);
            self.skin_generation = self.generation;
        }
        if self.generation != self.scene.generation() {
            // A new file: the last file's GPU meshes are released, the new ones made once.
            for id in self.meshes.drain(..) {
                viewer.renderer.free_mesh(id);
            }
            for id in self.skin_meshes.drain(..) {
                viewer.renderer.skin.free(id);
            }
            self.meshes = self
                .scene
                .bind_meshes()
                .iter()
                .map(|m| viewer.renderer.create_mesh(&viewer.gpu, m, None))
                .collect();
            self.generation = self.scene.generation();
        }
        if self.scene.gpu_on() && self.skin_generation != self.scene.generation() {
            let data = self.scene.bind_meshes();
            for id in self.skin_meshes.drain(..) {
                viewer.renderer.skin.free(id);
            }
            for (k, m) in data.iter().enumerate() {
                let weights = self
                    .scene
                    .skin_weights(k)
                    .ok_or_else(|| JsError::new("no weights"))?;
                let id = viewer
                    .renderer
                    .skin
                    .create(&viewer.gpu, m, None, weights)
                    .map_err(|e| JsError::new(&e))?;
                self.skin_meshes.push(id);
            }
            self.skin_generation = self.scene.generation();
        }
        let skin_meshes: &[crate::draw::SkinMeshId] =
            if self.skin_generation == self.scene.generation() {
                &self.skin_meshes
            } else {
                &[]
            };
        // The view the root's name is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw_with(
                &mut viewer.renderer.frame,
                time_sec,
                &self.meshes,
                skin_meshes,
            )
            .map_err(js)?;
        if self.scene.skinning_on() && !self.scene.gpu_on() {
            for (k, &id) in self.meshes.iter().enumerate() {
                if let Some((positions, normals)) = self.scene.skinned(k) {
                    viewer
                        .renderer
                        .update_mesh(&viewer.gpu, id, positions, normals)
                        .map_err(|e| JsError::new(&e))?;
                }
            }
        }
        viewer.present()?;
        Ok(note)
    }
}

impl Default for GltfScene {
    fn default() -> Self {
        Self::new()
    }
}
