//! Bindings for lesson 00, "From triangles to pixels": thin wrappers around
//! [`crate::figures::raster`], which holds the scenes' state, validation and drawing.

use super::{js, Viewer};
use crate::draw::MeshId;
use crate::figures::raster::{DepthPrecision, Frustum, MeshStorage, Normals, Shading};
use wasm_bindgen::prelude::*;

/// Figure 1: one mesh as a triangle soup and as indexed geometry.
#[wasm_bindgen]
pub struct MeshStorageScene {
    scene: MeshStorage,
}

#[wasm_bindgen]
impl MeshStorageScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> MeshStorageScene {
        MeshStorageScene {
            scene: MeshStorage::new(),
        }
    }

    /// "tetrahedron" or "sphere".
    #[wasm_bindgen(js_name = setShape)]
    pub fn set_shape(&mut self, shape: JsValue) -> Result<(), JsError> {
        let shape: &str = &super::string("shape", &shape)?;
        self.scene.set_shape(shape).map_err(js)
    }

    /// Segments around the sphere, 3 to 64.
    #[wasm_bindgen(js_name = setSegments)]
    pub fn set_segments(&mut self, segments: f32) -> Result<(), JsError> {
        self.scene.set_segments(segments).map_err(js)
    }

    /// The tetrahedron's two storages written out (empty for the sphere).
    pub fn listing(&self) -> String {
        self.scene.listing()
    }

    /// Draws both storages; returns the note with their sizes.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The dense sphere's patch of dots faces the last frame's eye; the labels are placed for
        // its view.
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for MeshStorageScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 2: the frustum, a point travelling through it, and its clip and NDC coordinates.
#[wasm_bindgen]
pub struct FrustumScene {
    scene: Frustum,
}

#[wasm_bindgen]
impl FrustumScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> FrustumScene {
        let mut scene = Frustum::new();
        scene.set_runner(super::sandbox::run);
        FrustumScene { scene }
    }

    /// Field of view (degrees, 10 to 150), z_near (0.05 to 5) and z_far (above z_near, ≤ 20).
    #[wasm_bindgen(js_name = setFrustum)]
    pub fn set_frustum(&mut self, fov_deg: f32, near: f32, far: f32) -> Result<(), JsError> {
        self.scene.set_frustum(fov_deg, near, far).map_err(js)
    }

    /// The point's view-space x and y, metres.
    #[wasm_bindgen(js_name = setOffset)]
    pub fn set_offset(&mut self, x: f32, y: f32) -> Result<(), JsError> {
        self.scene.set_offset(x, y).map_err(js)
    }

    /// Uses the student's `perspective_matrix` (exercise 0.1).
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// The point's distance at `s ∈ [0, 1]`, metres (the plot's playhead).
    #[wasm_bindgen(js_name = distanceAt)]
    pub fn distance_at(&self, s: f32) -> Result<f32, JsError> {
        Ok(self.scene.distance_at(super::in_range("s", s, 0.0, 1.0)?))
    }

    /// `[clip x, y, z, w, ndc x, y, z]` for wgpu, then the same for OpenGL.
    pub fn readout(&self, s: f32) -> Result<Vec<f32>, JsError> {
        Ok(self.scene.readout(s).map_err(js)?.to_vec())
    }

    /// The reference matrix, column-major: wgpu's (`gl = false`) or OpenGL's.
    pub fn matrix(&self, gl: JsValue) -> Result<Vec<f32>, JsError> {
        let gl = super::boolean("gl", &gl)?;
        Ok(self.scene.matrix(gl).to_cols_array().to_vec())
    }

    /// `[d₀, depth_wgpu₀, depth_gl₀, d₁, …]`.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleDepth)]
    pub fn sample_depth(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_depth(samples).map_err(js)?.concat())
    }

    pub fn draw(&mut self, viewer: &mut Viewer, s: f32) -> Result<String, JsError> {
        // The view the NDC box's labels are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame, s).map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for FrustumScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 3: depth precision and z-fighting.
#[wasm_bindgen]
pub struct DepthPrecisionScene {
    scene: DepthPrecision,
}

#[wasm_bindgen]
impl DepthPrecisionScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> DepthPrecisionScene {
        DepthPrecisionScene {
            scene: DepthPrecision::new(),
        }
    }

    /// z_near, z_far, the gap between the planes (metres) and the depth bits (16 or 24).
    pub fn set(&mut self, near: f32, far: f32, gap: f32, bits: f32) -> Result<(), JsError> {
        self.scene.set(near, far, gap, bits).map_err(js)
    }

    /// The camera's view through the depth buffer: RGBA bytes, `width × height` (each ≤ 512).
    pub fn image(&self, width: f64, height: f64) -> Result<Vec<u8>, JsError> {
        let width = super::whole("width", width)?;
        let height = super::whole("height", height)?;
        self.scene.image(width, height).map_err(js)
    }

    /// `[d₀, step16₀, step24₀, gap, d₁, …]`, metres.
    #[wasm_bindgen(js_name = sampleStep)]
    pub fn sample_step(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_step(samples).map_err(js)?.concat())
    }

    /// The distance (metres) beyond which the floors fight with the chosen bits.
    #[wasm_bindgen(js_name = fightingFrom)]
    pub fn fighting_from(&self) -> f32 {
        self.scene.fighting_from()
    }

    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the eye's and the fighting line's names are placed for (the last frame's).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for DepthPrecisionScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 4: flat and smooth normals, and the normal matrix under a non-uniform scale.
#[wasm_bindgen]
pub struct NormalsScene {
    scene: Normals,
    /// The flat and the smooth mesh, uploaded on the first draw.
    meshes: Option<(MeshId, MeshId)>,
    /// The smooth normals changed (the student's exercise): upload them on the next draw.
    dirty: bool,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl NormalsScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> NormalsScene {
        let mut scene = Normals::new();
        scene.set_runner(super::sandbox::run);
        NormalsScene {
            scene,
            meshes: None,
            dirty: false,
            gpu_seen: 0,
        }
    }

    #[wasm_bindgen(js_name = setFlat)]
    pub fn set_flat(&mut self, flat: JsValue) -> Result<(), JsError> {
        let flat = super::boolean("flat", &flat)?;
        self.scene.set_flat(flat);
        Ok(())
    }

    /// Stretch along x, 0.2 to 4.
    #[wasm_bindgen(js_name = setScaleX)]
    pub fn set_scale_x(&mut self, s: f32) -> Result<(), JsError> {
        self.scene.set_scale_x(s).map_err(js)
    }

    /// Also draw the normals transformed by the model matrix itself (wrong).
    #[wasm_bindgen(js_name = setShowWrong)]
    pub fn set_show_wrong(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_wrong(on);
        Ok(())
    }

    /// Uses the student's `vertex_normals` (exercise 0.2) for the smooth mesh.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        self.dirty = true;
        Ok(())
    }

    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        if viewer.renewed(&mut self.gpu_seen) {
            self.meshes = None;
        }
        let (flat, smooth) = match self.meshes {
            Some(ids) => ids,
            None => {
                let flat = viewer
                    .renderer
                    .create_mesh(&viewer.gpu, &self.scene.flat_mesh(), None);
                let smooth =
                    viewer
                        .renderer
                        .create_mesh(&viewer.gpu, &self.scene.smooth_mesh(), None);
                self.meshes = Some((flat, smooth));
                self.dirty = false;
                (flat, smooth)
            }
        };
        if self.dirty {
            let m = self.scene.smooth_mesh();
            viewer
                .renderer
                .update_mesh(&viewer.gpu, smooth, &m.positions, &m.normals)
                .map_err(|e| JsError::new(&e))?;
            self.dirty = false;
        }
        let note = self.scene.draw(&mut viewer.renderer.frame, flat, smooth);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for NormalsScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 5: Phong and Blinn-Phong shading, term by term.
#[wasm_bindgen]
pub struct ShadingScene {
    scene: Shading,
    /// The CPU-shaded sphere's GPU mesh, created on the first draw.
    sphere: Option<MeshId>,
    /// The viewer's generation the sphere was made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl ShadingScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> ShadingScene {
        let mut scene = Shading::new();
        scene.set_runner(super::sandbox::run);
        ShadingScene {
            scene,
            sphere: None,
            gpu_seen: 0,
        }
    }

    /// The light's azimuth and elevation, degrees.
    #[wasm_bindgen(js_name = setLightDeg)]
    pub fn set_light_deg(&mut self, azimuth: f32, elevation: f32) -> Result<(), JsError> {
        self.scene.set_light_deg(azimuth, elevation).map_err(js)
    }

    /// The light where the reader points on an image, `(u, v) ∈ [0, 1]²`.
    #[wasm_bindgen(js_name = setLightFromImage)]
    pub fn set_light_from_image(&mut self, u: f32, v: f32) -> Result<(), JsError> {
        self.scene.set_light_from_image(u, v).map_err(js)
    }

    /// `[azimuth, elevation]` of the light, degrees.
    #[wasm_bindgen(js_name = lightDeg)]
    pub fn light_deg(&self) -> Vec<f32> {
        let (a, e) = self.scene.light_deg();
        vec![a, e]
    }

    /// `k_a, k_d, k_s` in [0, 1], shininess in [1, 256].
    #[wasm_bindgen(js_name = setMaterial)]
    pub fn set_material(
        &mut self,
        ka: f32,
        kd: f32,
        ks: f32,
        shininess: f32,
    ) -> Result<(), JsError> {
        self.scene.set_material(ka, kd, ks, shininess).map_err(js)
    }

    /// "phong" or "blinn-phong".
    #[wasm_bindgen(js_name = setModel)]
    pub fn set_model(&mut self, model: JsValue) -> Result<(), JsError> {
        let model: &str = &super::string("model", &model)?;
        self.scene.set_model(model).map_err(js)
    }

    /// The marked fragment's azimuth and elevation on the sphere, degrees.
    #[wasm_bindgen(js_name = setFragmentDeg)]
    pub fn set_fragment_deg(&mut self, azimuth: f32, elevation: f32) -> Result<(), JsError> {
        self.scene.set_fragment_deg(azimuth, elevation).map_err(js)
    }

    /// Uses the student's `blinn_phong` (exercise 0.3) at the marked fragment.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// RGBA bytes of one image: "ambient", "diffuse", "specular", "phong", "blinn-phong" or
    /// "gouraud", `size × size` pixels with `size` from 8 to 512 (`raster::shading::MAX_IMAGE_SIZE`;
    /// the work grows with size²).
    pub fn image(&self, which: JsValue, size: f64) -> Result<Vec<u8>, JsError> {
        let which: &str = &super::string("which", &which)?;
        let size = super::whole("size", size)?;
        self.scene.image(which, size).map_err(js)
    }

    /// Draws the sphere (lit from the scene's light) and the vectors at the fragment.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        viewer.renderer.light_dir = self.scene.light();
        if viewer.renewed(&mut self.gpu_seen) {
            self.sphere = None;
            self.scene.reshade();
        }
        let id = *self.sphere.get_or_insert_with(|| {
            viewer
                .renderer
                .create_mesh(&viewer.gpu, self.scene.sphere(), None)
        });
        if let Some((sphere, colors)) = self.scene.shade_sphere() {
            viewer
                .renderer
                .update_mesh_with_colors(
                    &viewer.gpu,
                    id,
                    &sphere.positions,
                    &sphere.normals,
                    colors,
                )
                .map_err(|e| JsError::new(&e))?;
        }
        let note = self.scene.draw(&mut viewer.renderer.frame, id);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for ShadingScene {
    fn default() -> Self {
        Self::new()
    }
}
