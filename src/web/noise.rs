//! Bindings for lesson 05, "Noise and terrain": thin wrappers around [`crate::figures::noise`].
//! The terrains' meshes are created once per resolution with `Renderer::create_mesh` and then
//! rewritten in place with `Renderer::update_mesh_with_colors` whenever the scene changes them.

use super::{js, Viewer};
use crate::draw::MeshId;
use crate::figures::noise::{
    Fractals, Noise1d, Noise2d, Normals, Octaves, Quiz, TerrainFigure, TerrainScene, Textures,
    Variants,
};
use std::collections::HashMap;
use wasm_bindgen::prelude::*;

/// The GPU meshes of a figure's terrains: one per (slot, resolution), created on first use.
#[derive(Default)]
struct GpuTerrains {
    meshes: HashMap<(usize, usize), MeshId>,
    current: Vec<MeshId>,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

impl GpuTerrains {
    /// Uploads what changed; returns the mesh ids in the scene's order.
    fn sync(
        &mut self,
        viewer: &mut Viewer,
        scene: &mut dyn TerrainFigure,
    ) -> Result<&[MeshId], JsError> {
        if viewer.renewed(&mut self.gpu_seen) {
            self.meshes.clear();
        }
        let dirty = scene.take_dirty();
        let terrains = scene.terrains();
        self.current.clear();
        for (slot, t) in terrains.iter().enumerate() {
            let key = (slot, t.resolution());
            let id = match self.meshes.get(&key) {
                Some(&id) => {
                    if dirty {
                        viewer
                            .renderer
                            .update_mesh_with_colors(
                                &viewer.gpu,
                                id,
                                &t.positions,
                                &t.normals,
                                &t.colors,
                            )
                            .map_err(|e| JsError::new(&e))?;
                    }
                    id
                }
                None => {
                    let id =
                        viewer
                            .renderer
                            .create_mesh(&viewer.gpu, &t.mesh_data(), Some(&t.colors));
                    self.meshes.insert(key, id);
                    id
                }
            };
            self.current.push(id);
        }
        Ok(&self.current)
    }
}

/// Figure 1: 1D gradient noise.
#[wasm_bindgen]
pub struct Noise1dScene {
    scene: Noise1d,
}

#[wasm_bindgen]
impl Noise1dScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> Noise1dScene {
        let mut scene = Noise1d::new();
        scene.set_runner(super::sandbox::run);
        Noise1dScene { scene }
    }
    /// 0: Perlin's permutation; any other whole number: a shuffled one.
    #[wasm_bindgen(js_name = setSeed)]
    pub fn set_seed(&mut self, seed: f32) -> Result<(), JsError> {
        self.scene.set_seed(seed).map_err(js)
    }
    /// The probe, `x ∈ [0, 8)`.
    #[wasm_bindgen(js_name = setProbe)]
    pub fn set_probe(&mut self, x: f32) -> Result<(), JsError> {
        self.scene.set_probe(x).map_err(js)
    }
    #[wasm_bindgen(js_name = setShowRamps)]
    pub fn set_show_ramps(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_ramps(on);
        Ok(())
    }
    /// Uses the student's `fade` (exercise 5.1) for the probe and the plot.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    /// `[t₀, fade₀, fade′₀, smoothstep₀, fade″₀, smoothstep″₀, t₁, …]` (six numbers per row).
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleFade)]
    pub fn sample_fade(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_fade(samples).map_err(js)?.concat())
    }
    #[wasm_bindgen(js_name = probeT)]
    pub fn probe_t(&self) -> f32 {
        self.scene.probe_t()
    }
    /// Draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the probe's name is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for Noise1dScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 2: 2D noise with its lattice gradients and slices of 3D noise.
#[wasm_bindgen]
pub struct Noise2dScene {
    scene: Noise2d,
    gpu: GpuTerrains,
}

#[wasm_bindgen]
impl Noise2dScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> Noise2dScene {
        let mut scene = Noise2d::new();
        scene.set_runner(super::sandbox::run);
        Noise2dScene {
            scene,
            gpu: GpuTerrains::default(),
        }
    }
    #[wasm_bindgen(js_name = setSeed)]
    pub fn set_seed(&mut self, seed: f32) -> Result<(), JsError> {
        self.scene.set_seed(seed).map_err(js)
    }
    /// The slice `z ∈ [0, 2]` of 3D noise (0: the 2D noise).
    #[wasm_bindgen(js_name = setZ)]
    pub fn set_z(&mut self, z: f32) -> Result<(), JsError> {
        self.scene.set_z(z).map_err(js)
    }
    /// The probe in noise coordinates, each in `[−2, 2)`.
    #[wasm_bindgen(js_name = setProbe)]
    pub fn set_probe(&mut self, x: f32, y: f32) -> Result<(), JsError> {
        self.scene.set_probe(x, y).map_err(js)
    }
    /// Draws the student's `perlin_cell` (exercise 5.2) over the probe's cell and compares it.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let mesh = self.gpu.sync(viewer, &mut self.scene)?[0];
        // The view the probe's value is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame, mesh);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for Noise2dScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 3: octaves added one by one.
#[wasm_bindgen]
pub struct OctavesScene {
    scene: Octaves,
    gpu: GpuTerrains,
}

#[wasm_bindgen]
impl OctavesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> OctavesScene {
        let mut scene = Octaves::new();
        scene.set_runner(super::sandbox::run);
        OctavesScene {
            scene,
            gpu: GpuTerrains::default(),
        }
    }
    /// N ∈ 0..=9, α ∈ [0, 1], ω ∈ [1, 4].
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(&mut self, n: f32, alpha: f32, omega: f32) -> Result<(), JsError> {
        self.scene.set_params(n, alpha, omega).map_err(js)
    }
    /// Draws the student's `fractal_sum` (exercise 5.3) along the profile and compares it there.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    /// Leaves the octaves finer than the mesh out of the surface.
    #[wasm_bindgen(js_name = setBandLimit)]
    pub fn set_band_limit(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_band_limit(on);
        Ok(())
    }
    /// The last octave the mesh shows faithfully at the current ω (−1: not even octave 0).
    #[wasm_bindgen(js_name = lastResolvedOctave)]
    pub fn last_resolved_octave(&self) -> i32 {
        self.scene.last_resolved_octave().map_or(-1, |k| k as i32)
    }
    /// `[u₀, octave 0, …, octave 9, sum, u₁, …]` (12 values per row): numbers, and `null` for the
    /// octaves above N, which are not in the sum (a plot's gap marker, as uPlot takes it).
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleOctaves)]
    pub fn sample_octaves(&self, samples: f64) -> Result<js_sys::Array, JsError> {
        let samples = super::whole("samples", samples)?;
        let rows = self.scene.sample_octaves(samples).map_err(js)?;
        let value = |v: f32| {
            if v.is_finite() {
                JsValue::from(v)
            } else {
                JsValue::NULL
            }
        };
        Ok(rows.iter().flatten().map(|&v| value(v)).collect())
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the profile's name is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let mesh = self.gpu.sync(viewer, &mut self.scene)?[0];
        let note = self.scene.draw(&mut viewer.renderer.frame, mesh);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for OctavesScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 4: the course's terrain.
#[wasm_bindgen]
pub struct TerrainFigureScene {
    scene: TerrainScene,
    gpu: GpuTerrains,
    last_regenerate_ms: f64,
}

#[wasm_bindgen]
impl TerrainFigureScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> TerrainFigureScene {
        let mut scene = TerrainScene::new();
        scene.set_runner(super::sandbox::run);
        TerrainFigureScene {
            scene,
            gpu: GpuTerrains::default(),
            last_regenerate_ms: 0.0,
        }
    }
    /// N, α, ω, h, s, o; each checked by name.
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(
        &mut self,
        n: f32,
        alpha: f32,
        omega: f32,
        h: f32,
        s: f32,
        o: f32,
    ) -> Result<(), JsError> {
        self.scene.set_params(n, alpha, omega, h, s, o).map_err(js)
    }
    /// 0 sum, 1 ridge, 2 inverted ridge, 3 marble, 4 sliding, 5 evolving.
    #[wasm_bindgen(js_name = setVariant)]
    pub fn set_variant(&mut self, index: f64) -> Result<(), JsError> {
        let index = super::whole("index", index)?;
        self.scene.set_variant(index).map_err(js)
    }
    /// Vertices per side (2 to 1024).
    #[wasm_bindgen(js_name = setResolution)]
    pub fn set_resolution(&mut self, resolution: f64) -> Result<(), JsError> {
        let resolution = super::whole("resolution", resolution)?;
        self.scene.set_resolution(resolution).map_err(js)
    }
    #[wasm_bindgen(js_name = setSeed)]
    pub fn set_seed(&mut self, seed: f32) -> Result<(), JsError> {
        self.scene.set_seed(seed).map_err(js)
    }
    /// Advances the animated variants by `dt` seconds (0 to 1).
    pub fn advance(&mut self, dt_sec: f32) -> Result<(), JsError> {
        self.scene.advance(dt_sec).map_err(js)
    }
    /// Compares the student's `terrain_normal` (exercise 5.4) at the probe vertex and others.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    /// Leaves the octaves finer than the mesh out of the surface.
    #[wasm_bindgen(js_name = setBandLimit)]
    pub fn set_band_limit(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_band_limit(on);
        Ok(())
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let start = now_ms();
        let stale = self.scene.is_stale();
        let mesh = self.gpu.sync(viewer, &mut self.scene)?[0];
        if stale {
            self.last_regenerate_ms = now_ms() - start;
        }
        let note = self.scene.draw(&mut viewer.renderer.frame, mesh);
        viewer.present()?;
        Ok(note)
    }

    /// Milliseconds the last regeneration took (heights, normals, colours and the upload).
    #[wasm_bindgen(getter, js_name = lastRegenerateMs)]
    pub fn last_regenerate_ms(&self) -> f64 {
        self.last_regenerate_ms
    }
}

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

impl Default for TerrainFigureScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 8: procedural textures.
#[wasm_bindgen]
pub struct TexturesScene {
    scene: Textures,
    textures: Vec<crate::texture::TextureId>,
    /// The viewer's generation the textures were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl TexturesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> TexturesScene {
        TexturesScene {
            scene: Textures::new(),
            textures: Vec::new(),
            gpu_seen: 0,
        }
    }
    /// scale (0.5 to 16), turbulence (0 to 20), N (0 to 8).
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(&mut self, scale: f32, turbulence: f32, n: f32) -> Result<(), JsError> {
        self.scene.set_params(scale, turbulence, n).map_err(js)
    }
    #[wasm_bindgen(js_name = setAnimate)]
    pub fn set_animate(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_animate(on).map_err(js)
    }
    pub fn advance(&mut self, dt_sec: f32) -> Result<(), JsError> {
        self.scene.advance(dt_sec).map_err(js)
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let side = crate::figures::noise::TEXTURE_SIZE as u32;
        if viewer.renewed(&mut self.gpu_seen) {
            self.textures.clear();
        }
        if self.scene.take_dirty() || self.textures.is_empty() {
            for (i, rgba) in self.scene.images().into_iter().enumerate() {
                match self.textures.get(i) {
                    Some(&id) => viewer
                        .renderer
                        .update_texture(&viewer.gpu, id, side, side, rgba)
                        .map_err(js)?,
                    None => {
                        let id = viewer
                            .renderer
                            .create_texture(&viewer.gpu, side, side, rgba)
                            .map_err(js)?;
                        self.textures.push(id);
                    }
                }
            }
        }
        let note = self.scene.draw(&mut viewer.renderer.frame, &self.textures);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for TexturesScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 7: the terrain quiz.
#[wasm_bindgen]
pub struct QuizScene {
    scene: Quiz,
    gpu: GpuTerrains,
}

#[wasm_bindgen]
impl QuizScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> QuizScene {
        QuizScene {
            scene: Quiz::new(),
            gpu: GpuTerrains::default(),
        }
    }
    /// Terrain 0 (a) to 5 (f) gets set 1 to 6, or 0 for no answer.
    #[wasm_bindgen(js_name = setAnswer)]
    pub fn set_answer(&mut self, terrain: f64, set: f64) -> Result<(), JsError> {
        let terrain = super::whole("terrain", terrain)?;
        let set = super::whole("set", set)?;
        self.scene.set_answer(terrain, set).map_err(js)
    }
    pub fn check(&mut self) {
        self.scene.check();
    }
    #[wasm_bindgen(js_name = newRound)]
    pub fn new_round(&mut self) {
        self.scene.new_round();
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let meshes = self.gpu.sync(viewer, &mut self.scene)?.to_vec();
        let note = self.scene.draw(&mut viewer.renderer.frame, &meshes);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for QuizScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 5: exact normals against the average of the faces around each vertex.
#[wasm_bindgen]
pub struct TerrainNormalsScene {
    scene: Normals,
    gpu: GpuTerrains,
}

#[wasm_bindgen]
impl TerrainNormalsScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> TerrainNormalsScene {
        TerrainNormalsScene {
            scene: Normals::new(),
            gpu: GpuTerrains::default(),
        }
    }
    /// `[vertices per side, mean angle (°), largest angle (°)]` per resolution offered, at the
    /// current h, flattened.
    #[wasm_bindgen(js_name = anglesByResolution)]
    pub fn angles_by_resolution(&self) -> Vec<f32> {
        self.scene.angles_by_resolution().concat()
    }
    /// Vertices per side (9, 17, 33, 65 or 129) and h in [0, 1]; nothing changes on an error.
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(&mut self, resolution: f32, h: f32) -> Result<(), JsError> {
        self.scene.set_params(resolution, h).map_err(js)
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let meshes = self.gpu.sync(viewer, &mut self.scene)?.to_vec();
        let note = self.scene.draw(&mut viewer.renderer.frame, meshes[0]);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for TerrainNormalsScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 6: the variants side by side: sum, ridge, inverted ridge, marble from the same noise.
#[wasm_bindgen]
pub struct VariantsScene {
    scene: Variants,
    gpu: GpuTerrains,
}

#[wasm_bindgen]
impl VariantsScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> VariantsScene {
        VariantsScene {
            scene: Variants::new(),
            gpu: GpuTerrains::default(),
        }
    }
    /// N (whole, 0 to 9), α in [0, 1], h in [0, 2]; nothing changes on an error.
    #[wasm_bindgen(js_name = setParams)]
    pub fn set_params(&mut self, n: f32, alpha: f32, h: f32) -> Result<(), JsError> {
        self.scene.set_params(n, alpha, h).map_err(js)
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let meshes = self.gpu.sync(viewer, &mut self.scene)?.to_vec();
        // The view the names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame, &meshes);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for VariantsScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 10: Koch snowflake and Sierpinski triangle.
#[wasm_bindgen]
pub struct FractalsScene {
    scene: Fractals,
}

#[wasm_bindgen]
impl FractalsScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> FractalsScene {
        FractalsScene {
            scene: Fractals::new(),
        }
    }
    /// 0 to 7.
    #[wasm_bindgen(js_name = setDepth)]
    pub fn set_depth(&mut self, depth: f32) -> Result<(), JsError> {
        self.scene.set_depth(depth).map_err(js)
    }
    #[wasm_bindgen(js_name = setShowPrevious)]
    pub fn set_show_previous(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_previous(on);
        Ok(())
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for FractalsScene {
    fn default() -> Self {
        Self::new()
    }
}
