//! Bindings for lesson 11's sprite figure: a thin wrapper around
//! [`crate::figures::particles_sprites`]. The atlas is uploaded once, on the first draw.

use super::{js, Viewer};
use crate::figures::particles_sprites::{SmokeFigure, ATLAS_SIDE};
use crate::texture::TextureId;
use wasm_bindgen::prelude::*;

/// A column of smoke drawn with textured, alpha-blended sprites.
#[wasm_bindgen]
pub struct SmokeScene {
    scene: SmokeFigure,
    atlas: Option<TextureId>,
    /// The viewer's generation the atlas was made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

impl Default for SmokeScene {
    fn default() -> Self {
        Self::new()
    }
}

#[wasm_bindgen]
impl SmokeScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SmokeScene {
        SmokeScene {
            scene: SmokeFigure::new(),
            atlas: None,
            gpu_seen: 0,
        }
    }
    /// Puffs (1 to 200) and their lifetime (0.5 to 10 s).
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(&mut self, puffs: f32, lifetime_sec: f32) -> Result<(), JsError> {
        self.scene.set_params(puffs, lifetime_sec).map_err(js)
    }
    #[wasm_bindgen(js_name = setAnimateFrames)]
    pub fn set_animate_frames(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_animate_frames(on);
        Ok(())
    }
    #[wasm_bindgen(js_name = setShowAtlas)]
    pub fn set_show_atlas(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_atlas(on);
        Ok(())
    }
    /// The note `draw` returns at `time_sec`, from the default camera and without a canvas (the
    /// column is computed from the time alone: nothing is stepped).
    #[wasm_bindgen(js_name = noteAt)]
    pub fn note_at(&mut self, time_sec: f32) -> Result<String, JsError> {
        let mut scratch = crate::draw::Frame::default();
        let camera = crate::camera::OrbitCamera::default();
        let (eye, target) = (camera.eye(), camera.target);
        self.scene
            .draw(&mut scratch, TextureId(0), eye, target, time_sec)
            .map_err(js)
    }
    /// Draws the column at `time_sec`; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        if viewer.renewed(&mut self.gpu_seen) {
            self.atlas = None;
        }
        let atlas = match self.atlas {
            Some(id) => id,
            None => {
                let side = ATLAS_SIDE as u32;
                let id = viewer
                    .renderer
                    .create_texture(&viewer.gpu, side, side, self.scene.atlas())
                    .map_err(js)?;
                self.atlas = Some(id);
                id
            }
        };
        let (eye, target) = (viewer.camera.eye(), viewer.camera.target);
        // The view the names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, atlas, eye, target, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}
