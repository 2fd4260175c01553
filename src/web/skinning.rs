//! Bindings for lesson 09, "Skinning": thin wrappers around [`crate::figures::skinning`]. Each
//! skinned mesh is created once on the GPU (`Renderer::create_mesh`) and rewritten in place
//! (`Renderer::update_mesh_with_colors`) when its vertices changed.

use super::{js, Viewer};
use crate::draw::MeshId;
use crate::figures::skinning::{CylinderFigure, HumanFigure, SignFigure, SkinnedMesh};
use crate::mesh::MeshData;
use wasm_bindgen::prelude::*;

/// The heat map's colours as a CSS gradient, 0 on the left to 1 on the right (the legends).
#[wasm_bindgen(js_name = heatRampCss)]
pub fn heat_ramp_css() -> String {
    crate::figures::skinning::heat_ramp_css()
}

/// Uploads `skinned` into `id` (creating the mesh on first use) if it changed.
fn sync(
    viewer: &mut Viewer,
    id: &mut Option<MeshId>,
    skinned: &mut SkinnedMesh,
    indices: &[u32],
) -> Result<MeshId, JsError> {
    match *id {
        Some(mesh) => {
            if skinned.take_dirty() {
                viewer
                    .renderer
                    .update_mesh_with_colors(
                        &viewer.gpu,
                        mesh,
                        &skinned.positions,
                        &skinned.normals,
                        &skinned.colors,
                    )
                    .map_err(|e| JsError::new(&e))?;
            }
            Ok(mesh)
        }
        None => {
            skinned.take_dirty();
            let data = MeshData {
                positions: skinned.positions.clone(),
                normals: skinned.normals.clone(),
                indices: indices.to_vec(),
            };
            let mesh = viewer
                .renderer
                .create_mesh(&viewer.gpu, &data, Some(&skinned.colors));
            *id = Some(mesh);
            Ok(mesh)
        }
    }
}

/// Figure 1: the bend-and-twist cylinder, LBS beside DQS.
#[wasm_bindgen]
pub struct SkinningCylinderScene {
    scene: CylinderFigure,
    meshes: [Option<MeshId>; 2],
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl SkinningCylinderScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SkinningCylinderScene {
        let mut scene = CylinderFigure::new();
        scene.set_runner(super::sandbox::run);
        SkinningCylinderScene {
            scene,
            meshes: [None, None],
            gpu_seen: 0,
        }
    }

    /// Elbow bend, degrees in [0, 180].
    #[wasm_bindgen(js_name = setBendDeg)]
    pub fn set_bend_deg(&mut self, deg: f32) -> Result<(), JsError> {
        self.scene.set_bend_deg(deg).map_err(js)
    }

    /// Elbow twist, degrees in [−180, 180].
    #[wasm_bindgen(js_name = setTwistDeg)]
    pub fn set_twist_deg(&mut self, deg: f32) -> Result<(), JsError> {
        self.scene.set_twist_deg(deg).map_err(js)
    }

    /// Falloff of the automatic weights, metres in [0.01, 1].
    #[wasm_bindgen(js_name = setFalloff)]
    pub fn set_falloff(&mut self, falloff: f32) -> Result<(), JsError> {
        self.scene.set_falloff(falloff).map_err(js)
    }

    /// "none", "shoulder" or "elbow".
    #[wasm_bindgen(js_name = setHeatJoint)]
    pub fn set_heat_joint(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_heat_joint(name).map_err(js)
    }

    /// The ring (0 at the shoulder end to 40 at the wrist end) whose top vertex the figure
    /// follows.
    #[wasm_bindgen(js_name = setProbeRing)]
    pub fn set_probe_ring(&mut self, ring: f64) -> Result<(), JsError> {
        let ring = super::whole("ring", ring)?;
        self.scene.set_probe_ring(ring).map_err(js)
    }

    /// Runs the student's exercises 9.1 and 9.2 (in the sandbox) instead of the reference.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// `[angle (°), LBS bend, DQS bend, LBS twist, DQS twist]` per sample (areas as fractions of
    /// the rest area); `samples` in [2, 10000].
    #[wasm_bindgen(js_name = areaCurves)]
    pub fn area_curves(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        self.scene.area_curves(samples).map_err(js)
    }

    /// `[area plot, volume plot]`: where the current pose lies on each plot's x axis, degrees
    /// (their dashed lines), `null` where it is on none of the plot's curves (a plot's
    /// `setCursor(null)` hides its line).
    #[wasm_bindgen(js_name = plotCursors)]
    pub fn plot_cursors(&self) -> js_sys::Array {
        let c = self.scene.plot_cursors();
        let cursor = |x: Option<f32>| x.map_or(JsValue::NULL, JsValue::from);
        [cursor(c.area), cursor(c.volume)].into_iter().collect()
    }

    /// `[distance along the tube (m), shoulder's weight, elbow's weight]` per ring, at this
    /// falloff.
    #[wasm_bindgen(js_name = weightCurves)]
    pub fn weight_curves(&self) -> Vec<f32> {
        self.scene.weight_curves()
    }

    /// `[angle (°), LBS, DQS]` per sample: the tube's volume (fraction of rest) against the bend.
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = volumeCurves)]
    pub fn volume_curves(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        self.scene.volume_curves(samples).map_err(js)
    }

    /// Skins (if a control changed), uploads and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the labels are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        self.scene.update().map_err(js)?;
        if viewer.renewed(&mut self.gpu_seen) {
            self.meshes = [None, None];
        }
        let indices = self.scene.rig().mesh.indices.clone();
        let a = sync(viewer, &mut self.meshes[0], &mut self.scene.lbs, &indices)?;
        let b = sync(viewer, &mut self.meshes[1], &mut self.scene.dqs, &indices)?;
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, [a, b])
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for SkinningCylinderScene {
    fn default() -> Self {
        Self::new()
    }
}

/// The antipodality fix: the tube twisted 0 to 360° by DQS, with or without the sign flip.
#[wasm_bindgen]
pub struct SkinningSignScene {
    scene: SignFigure,
    mesh: Option<MeshId>,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl SkinningSignScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SkinningSignScene {
        SkinningSignScene {
            scene: SignFigure::new(),
            mesh: None,
            gpu_seen: 0,
        }
    }

    /// Elbow twist, degrees in [0, 360].
    #[wasm_bindgen(js_name = setTwistDeg)]
    pub fn set_twist_deg(&mut self, deg: f32) -> Result<(), JsError> {
        self.scene.set_twist_deg(deg).map_err(js)
    }

    /// The antipodality fix on or off.
    #[wasm_bindgen(js_name = setFix)]
    pub fn set_fix(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_fix(on);
        Ok(())
    }

    /// Skins (if a control changed), uploads and draws. Returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the circle faces and its labels are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        self.scene.update().map_err(js)?;
        if viewer.renewed(&mut self.gpu_seen) {
            self.mesh = None;
        }
        let indices = self.scene.rig().mesh.indices.clone();
        let id = sync(viewer, &mut self.mesh, &mut self.scene.mesh, &indices)?;
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, id)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for SkinningSignScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Figure 3: the built-in human, skinned, playing a clip.
#[wasm_bindgen]
pub struct SkinnedHumanScene {
    scene: HumanFigure,
    mesh: Option<MeshId>,
    /// The DQS body beside the LBS one.
    mesh_dqs: Option<MeshId>,
    /// The same body for skinning in the vertex shader (made on first use).
    gpu_mesh: Option<crate::draw::SkinMeshId>,
    /// The viewer's generation the meshes were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl SkinnedHumanScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SkinnedHumanScene {
        let mut scene = HumanFigure::new();
        scene.set_compare(true);
        SkinnedHumanScene {
            scene,
            mesh: None,
            mesh_dqs: None,
            gpu_mesh: None,
            gpu_seen: 0,
        }
    }

    #[wasm_bindgen(js_name = clipNames)]
    pub fn clip_names(&self) -> Vec<String> {
        self.scene.clip_names()
    }

    #[wasm_bindgen(js_name = setClip)]
    pub fn set_clip(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_clip(name).map_err(js)
    }

    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.duration_sec()
    }

    /// "LBS" or "DQS".
    #[wasm_bindgen(js_name = setMethod)]
    pub fn set_method(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_method(name).map_err(js)
    }

    /// "whole body" or "left legs": what the camera keeps in view.
    #[wasm_bindgen(js_name = setView)]
    pub fn set_view(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_view(name).map_err(js)
    }

    /// `[time (s), LBS, DQS]` per sample: the left leg's volume (fraction of rest) over the
    /// clip; `samples` in [2, 10000].
    #[wasm_bindgen(js_name = legVolumeCurves)]
    pub fn leg_volume_curves(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        self.scene.leg_volume_curves(samples).map_err(js)
    }

    /// Falloff of the automatic weights, metres in [`falloffRange`](Self::falloff_range).
    #[wasm_bindgen(js_name = setFalloff)]
    pub fn set_falloff(&mut self, falloff: f32) -> Result<(), JsError> {
        self.scene.set_falloff(falloff).map_err(js)
    }

    /// `[lowest, highest]` falloff, metres: the slider's range. As the f32s' shortest decimals
    /// (0.005, not 0.004999999888), so the slider's steps land on round numbers.
    #[wasm_bindgen(js_name = falloffRange)]
    pub fn falloff_range(&self) -> Vec<f64> {
        crate::figures::skinning::HUMAN_FALLOFF_RANGE
            .iter()
            .map(|x| x.to_string().parse().unwrap_or(f64::from(*x)))
            .collect()
    }

    #[wasm_bindgen(js_name = jointNames)]
    pub fn joint_names(&self) -> Vec<String> {
        self.scene.joint_names()
    }

    /// "none" or a joint's name.
    #[wasm_bindgen(js_name = setHeatJoint)]
    pub fn set_heat_joint(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_heat_joint(name).map_err(js)
    }

    #[wasm_bindgen(js_name = setShowSkeleton)]
    pub fn set_show_skeleton(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_skeleton(on);
        Ok(())
    }

    /// Samples the clip at `time_sec`, skins the body on the CPU; returns the milliseconds the
    /// skinning took (sampling, palette and LBS or DQS), or `undefined` when the body was
    /// already skinned at this time with these settings (a paused page) and nothing was done.
    pub fn skin(&mut self, time_sec: f32) -> Result<Option<f64>, JsError> {
        let start = now_ms();
        let skinned = self.scene.skin(time_sec).map_err(js)?;
        Ok(skinned.then(|| now_ms() - start))
    }

    /// Skins in the vertex shader (`true`) or on the CPU (`false`, the default).
    #[wasm_bindgen(js_name = setGpu)]
    pub fn set_gpu(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_gpu(on);
        Ok(())
    }

    /// Uploads the skinned body (or, skinning on the GPU, only its palette) and draws. Returns
    /// the note.
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the heat map's joint name is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_canvas_view(viewer.camera, w, h);
        if viewer.renewed(&mut self.gpu_seen) {
            (self.mesh, self.mesh_dqs, self.gpu_mesh) = (None, None, None);
        }
        if self.scene.gpu() {
            let dirty = self.scene.take_gpu_dirty();
            let skins = &mut viewer.renderer.skin;
            let c = self.scene.character();
            let id = match self.gpu_mesh {
                Some(id) => {
                    if dirty {
                        skins
                            .update_colors(&viewer.gpu, id, &self.scene.mesh.colors)
                            .and_then(|()| skins.update_weights(&viewer.gpu, id, &c.skin))
                            .map_err(|e| JsError::new(&e))?;
                    }
                    id
                }
                None => {
                    let id = skins
                        .create(&viewer.gpu, &c.mesh, Some(&self.scene.mesh.colors), &c.skin)
                        .map_err(|e| JsError::new(&e))?;
                    self.gpu_mesh = Some(id);
                    id
                }
            };
            let note = self
                .scene
                .draw_gpu(&mut viewer.renderer.frame, id)
                .map_err(js)?;
            viewer.present()?;
            return Ok(note);
        }
        let indices = self.scene.character().mesh.indices.clone();
        let id = sync(viewer, &mut self.mesh, &mut self.scene.mesh, &indices)?;
        let other = sync(
            viewer,
            &mut self.mesh_dqs,
            &mut self.scene.mesh_dqs,
            &indices,
        )?;
        let note = self
            .scene
            .draw_pair(&mut viewer.renderer.frame, [id, other]);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for SkinnedHumanScene {
    fn default() -> Self {
        Self::new()
    }
}

fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map(|p| p.now())
        .unwrap_or(0.0)
}

/// Validates skinning data from JavaScript and says what is wrong, or `"ok"`: the wasm-boundary
/// check of every rule. `joints` and `weights` hold four numbers per vertex. Cap (the check's
/// work grows with the vertices): at most 2²⁰ vertices (`skinning::MAX_SKIN_VERTICES`), checked
/// before the lists are read.
#[wasm_bindgen(js_name = checkSkinWeights)]
pub fn check_skin_weights(
    joints: Vec<f64>,
    weights: Vec<f32>,
    joint_count: f64,
) -> Result<String, JsError> {
    use crate::skinning::{SkinWeights, MAX_SKIN_VERTICES};
    let joint_count = super::whole("joint_count", joint_count)?;
    if !joints.len().is_multiple_of(4) || weights.len() != joints.len() {
        return Err(JsError::new(&format!(
            "joints and weights: four numbers per vertex each, got {} and {}",
            joints.len(),
            weights.len()
        )));
    }
    if joints.len() / 4 > MAX_SKIN_VERTICES {
        return Err(JsError::new(&format!(
            "{} vertices is too many (at most {MAX_SKIN_VERTICES})",
            joints.len() / 4
        )));
    }
    // Whole numbers only: a Uint32Array would turn NaN into joint 0 and -1 into 4294967295.
    let joints: Vec<u32> = super::wholes("joints", &joints, 0.0, f64::from(u32::MAX))?
        .into_iter()
        .map(|j| j as u32)
        .collect();
    if let Some(&j) = joints.iter().find(|&&j| j > u16::MAX as u32) {
        return Err(JsError::new(&format!("joint index {j} is over 65535")));
    }
    let j4 = joints
        .chunks_exact(4)
        .map(|c| [c[0] as u16, c[1] as u16, c[2] as u16, c[3] as u16])
        .collect();
    let w4 = weights
        .chunks_exact(4)
        .map(|c| [c[0], c[1], c[2], c[3]])
        .collect();
    SkinWeights::new(j4, w4, joint_count)
        .map(|_| "ok".to_string())
        .map_err(|e| JsError::new(&e.to_string()))
}
