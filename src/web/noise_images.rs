//! Bindings for lesson 05's "Perlin, simplex, and the GPU" figure: thin wrappers around
//! [`crate::figures::noise_images`]. The CPU images are uploaded once and rewritten in place;
//! the GPU image is drawn by `shaders/noise.wgsl` into a texture, and a second, packed 16-bit
//! copy is read back (without blocking: the page polls) and compared with the CPU.

use super::{js, Viewer};
use crate::figures::noise_images::{NoiseImages, NoiseKind, IMAGE_SIZE};
use crate::render::{NoiseImage, PendingRead};
use crate::texture::TextureId;
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
pub struct NoiseImagesScene {
    scene: NoiseImages,
    /// CPU Perlin, CPU simplex, GPU (grey), GPU (packed, read back).
    textures: Option<[TextureId; 4]>,
    pending: Option<PendingRead>,
    check: String,
    /// The viewer's generation the textures were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

impl Default for NoiseImagesScene {
    fn default() -> Self {
        Self::new()
    }
}

#[wasm_bindgen]
impl NoiseImagesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> NoiseImagesScene {
        NoiseImagesScene {
            scene: NoiseImages::new(),
            textures: None,
            pending: None,
            check: String::new(),
            gpu_seen: 0,
        }
    }
    /// Cells across an image (1 to 32) and the seed (0: Perlin's table).
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(&mut self, cells: f32, seed: f32) -> Result<(), JsError> {
        self.scene.set_params(cells, seed).map_err(js)
    }
    /// What the GPU computes: simplex (2D) or Perlin.
    #[wasm_bindgen(js_name = setGpuSimplex)]
    pub fn set_gpu_simplex(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_gpu_kind(if on {
            NoiseKind::Simplex
        } else {
            NoiseKind::Perlin
        });
        Ok(())
    }
    #[wasm_bindgen(js_name = setLattice)]
    pub fn set_lattice(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_lattice(on);
        Ok(())
    }
    /// The last GPU check's sentence ('' until one finished).
    #[wasm_bindgen(getter, js_name = gpuCheck)]
    pub fn gpu_check(&self) -> String {
        self.check.clone()
    }
    /// Draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let side = IMAGE_SIZE as u32;
        let renewed = viewer.renewed(&mut self.gpu_seen);
        if renewed {
            (self.textures, self.pending) = (None, None);
        }
        let renderer = &mut viewer.renderer;
        let gpu = &viewer.gpu;
        let ids = match self.textures {
            Some(ids) => {
                if self.scene.take_dirty() {
                    for (&id, rgba) in ids.iter().zip(self.scene.images()) {
                        renderer
                            .update_texture(gpu, id, side, side, rgba)
                            .map_err(js)?;
                    }
                }
                ids
            }
            None => {
                self.scene.take_dirty();
                let [perlin, simplex] = self.scene.images();
                let ids = [
                    renderer
                        .create_texture(gpu, side, side, perlin)
                        .map_err(js)?,
                    renderer
                        .create_texture(gpu, side, side, simplex)
                        .map_err(js)?,
                    renderer.create_noise_texture(gpu, side, side).map_err(js)?,
                    renderer.create_noise_texture(gpu, side, side).map_err(js)?,
                ];
                self.textures = Some(ids);
                ids
            }
        };
        if self.scene.take_gpu_dirty() || renewed {
            let s = self.scene.spec();
            let mut image = NoiseImage {
                origin: s.origin,
                step: s.step,
                z: s.z,
                simplex: s.simplex,
                packed: false,
            };
            let table = self.scene.table();
            renderer
                .render_noise(gpu, ids[2], table, &image)
                .map_err(js)?;
            image.packed = true;
            renderer
                .render_noise(gpu, ids[3], table, &image)
                .map_err(js)?;
            self.pending = Some(renderer.start_read_texture(gpu, ids[3]).map_err(js)?);
            self.check.clear();
        }
        if let Some(result) = self.pending.as_ref().and_then(|p| p.poll(gpu)) {
            self.pending = None;
            let pixels = result.map_err(js)?;
            let cmp = self.scene.compare_gpu(&pixels).map_err(js)?;
            self.check = cmp.note(gpu.backend_name);
        }
        let note = self
            .scene
            .draw(&mut renderer.frame, [ids[0], ids[1], ids[2]]);
        viewer.present()?;
        Ok(note)
    }
}
