//! Figure logic for the glTF characters: a character imported from a glTF file (a Khronos sample
//! served with the site, or the reader's own file), drawn as its skeleton and playing its clips.
//! The import itself is [`crate::gltf_import`]. Lesson 06 shows the joints, the bones and, faintly,
//! the mesh's vertices in the bind pose; lesson 09 skins the mesh ([`SkinMode`]) with the file's
//! inverse bind matrices, by linear blend or dual quaternion skinning ([`crate::skinning`]).

use super::{format_number, in_range, palette, Frame, MeshId};
use crate::gltf_import::{import, ImportError, Imported};
use crate::rigid::DualQuat;
use crate::skeleton::{Clip, ClipCursor, Pose};
use crate::skinning::{dual_quat_palette, skin_dqs, skin_lbs, skinning_palette, SkinWeights};
use glam::{Affine3A, Mat4, Vec2, Vec3};

/// How the figure shows the mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SkinMode {
    /// The bind-pose vertices as dots (lesson 06).
    #[default]
    Dots,
    /// Linear blend skinning.
    Lbs,
    /// Dual quaternion skinning (falls back to LBS, and says so, for scaled joints).
    Dqs,
}

/// The colour of the skinned mesh.
pub const SKIN: Vec3 = Vec3::new(0.75, 0.62, 0.5);

/// One skinned mesh's weights and its skinned vertices.
struct Skinned {
    weights: SkinWeights,
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
}

/// The most mesh vertices drawn as dots (every k-th vertex beyond it).
const MAX_DOTS: usize = 2_000;
/// Width of a bone on screen, CSS pixels.
const BONE_PX: f32 = 3.0;
/// The radius of a bind-pose dot, as a fraction of the character's size: a plain grey disc (up to
/// two thousand of them lie close together, where outlined markers would read as black rings),
/// about 6 px across when the character fills a 420 px canvas, large enough to find the
/// caption's "grey dots" by.
const DOT_RADIUS: f32 = 0.009;
/// The radius of a joint's ball, as a fraction of the character's size.
const JOINT_RADIUS: f32 = 0.012;

/// What is loaded.
struct Character {
    imported: Imported,
    clips: Vec<Clip>,
    /// Joint world positions in the rest pose, for the fit and the joint size.
    size: f32,
    centre: Vec3,
    /// Half the size of that box along each axis.
    half_extent: Vec3,
    /// A thinned set of the mesh's vertices (bind pose, world space).
    dots: Vec<Vec3>,
    /// Every how many vertices (across the meshes) `dots` takes one.
    dot_step: usize,
    /// Per mesh, or why the mesh cannot be skinned.
    skinned: Result<Vec<Skinned>, String>,
    /// The file's inverse bind matrices.
    inverse_bind: Vec<Affine3A>,
}

/// The figure: nothing until a file is loaded.
#[derive(Default)]
pub struct GltfFigure {
    character: Option<Character>,
    clip: usize,
    cursor: ClipCursor,
    pose: Option<Pose>,
    model: Vec<Affine3A>,
    show_mesh: bool,
    mode: SkinMode,
    /// Skinning: the bind-pose vertices drawn too, over the skinned mesh (lesson 09).
    bind_dots: bool,
    /// Counts loads, so the page knows when to make new GPU meshes.
    generation: u32,
    /// Scratch: the joints' world matrices this frame.
    world: Vec<Affine3A>,
    /// Scratch: the bind-pose dots on the canvas (CSS pixels), on the last frame's view.
    dots_px: Vec<Vec2>,
    /// Scratch: the skinned mesh's vertices on the canvas (CSS pixels), on the last frame's view,
    /// and its triangles there, while the CPU skins it.
    skin_px: Vec<Option<Vec2>>,
    skin_triangles: Vec<[Vec2; 3]>,
    palette: Vec<Affine3A>,
    dual_quats: Vec<DualQuat>,
    /// Why DQS fell back to LBS this frame, if it did.
    fallback: Option<String>,
    /// Skin in the vertex shader when the page gives GPU meshes (see [`GltfFigure::draw_with`]).
    gpu: bool,
    /// Why this frame was skinned on the CPU although the GPU was asked for, if it was.
    gpu_fallback: Option<String>,
    /// The file shown and its one-line summary (see [`GltfFigure::load`]).
    shown: Option<(String, String)>,
    /// Why the last file was rejected, when the last load failed (cleared by a good load).
    rejected: Option<String>,
    /// The camera and canvas size (CSS pixels) of the last frame, which the root's name is
    /// placed for.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

impl GltfFigure {
    pub fn new() -> Self {
        GltfFigure {
            show_mesh: true,
            mode: SkinMode::Dots,
            generation: 0,
            ..Default::default()
        }
    }

    /// Imports `bytes` (a `.gltf` with embedded buffers or a `.glb`) named `name`; on success
    /// returns a one-line summary, on failure the reason (and keeps what was loaded before).
    /// The note of [`GltfFigure::draw`] starts with the outcome: the summary, or that the file
    /// was rejected, why, and which character is still shown.
    pub fn load(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        self.show_import(name, import(bytes))
    }

    /// [`GltfFigure::load`] for a file imported elsewhere and handed over as
    /// [`crate::gltf_import::wire`] bytes: the page imports in the glTF module and draws here.
    pub fn load_imported(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        self.show_import(name, crate::gltf_import::wire::decode(bytes))
    }

    fn show_import(
        &mut self,
        name: &str,
        imported: Result<Imported, ImportError>,
    ) -> Result<String, String> {
        let result = imported
            .map_err(|e| format!("{name}: {e}"))
            .and_then(|imported| self.show(name, imported));
        match &result {
            Ok(summary) => {
                self.shown = Some((name.to_string(), summary.clone()));
                self.rejected = None;
            }
            Err(e) => self.rejected = Some(e.clone()),
        }
        result
    }

    /// Records a file rejected before it was read (the web layer checks its size before copying
    /// it): the note says so, as for any rejected file, and what was loaded before stays.
    /// Returns the error message, `"{name}: {why}"` as [`GltfFigure::load`] words it.
    pub fn reject(&mut self, name: &str, why: &str) -> String {
        let e = format!("{name}: {why}");
        self.rejected = Some(e.clone());
        e
    }

    /// The outcome of the last load, for the start of the note.
    fn load_note(&self) -> String {
        let rejected = self.rejected.as_deref().map(|e| e.trim_end_matches('.'));
        match (rejected, &self.shown) {
            (None, Some((_, summary))) => summary.clone(),
            (None, None) => String::new(),
            (Some(why), Some((name, _))) => format!(
                "Could not load {why}. The file was rejected: the figure still shows {name}, \
                 loaded before."
            ),
            (Some(why), None) => format!("Could not load {why}."),
        }
    }

    fn show(&mut self, name: &str, imported: Imported) -> Result<String, String> {
        let clips = imported
            .clips
            .iter()
            .map(|raw| Clip::from_raw(raw, &imported.skeleton))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| format!("{name}: {e}"))?;
        let rest = imported.skeleton.rest_pose();
        let mut model = vec![Affine3A::IDENTITY; imported.skeleton.len()];
        imported
            .skeleton
            .model_matrices(&rest, &mut model)
            .map_err(|e| format!("{name}: {e}"))?;
        let points: Vec<Vec3> = model
            .iter()
            .map(|m| {
                imported
                    .root_transform
                    .transform_point3(m.translation.into())
            })
            .collect();
        let vertices: usize = imported.meshes.iter().map(|m| m.positions.len()).sum();
        let step = vertices.div_ceil(MAX_DOTS).max(1);
        let dots: Vec<Vec3> = imported
            .meshes
            .iter()
            .flat_map(|m| {
                m.positions
                    .iter()
                    .map(move |&p| m.node_transform.transform_point3(p))
            })
            .step_by(step)
            .collect();
        // The box around the joints and the mesh (a head reaches above its last joint).
        let (lo, hi) = points.iter().chain(&dots).fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        );
        let size = (hi - lo).max_element().max(1e-3);
        let summary = format!(
            "{name}: {} joints, {} clip{} ({}), {} skinned vertices{}.",
            imported.skeleton.len(),
            clips.len(),
            if clips.len() == 1 { "" } else { "s" },
            if clips.is_empty() {
                "none: it shows the rest pose".to_string()
            } else {
                imported
                    .clips
                    .iter()
                    .map(|c| format!("{} {} s", c.name(), format_number(c.duration_sec())))
                    .collect::<Vec<_>>()
                    .join(", ")
            },
            vertices,
            if imported.notes.is_empty() {
                String::new()
            } else {
                format!("; skipped: {}", imported.notes.join("; "))
            },
        );
        let skinned = imported
            .meshes
            .iter()
            .map(|m| {
                let n = m.positions.len();
                Ok(Skinned {
                    weights: SkinWeights::new(
                        m.joints.clone(),
                        m.weights.clone(),
                        imported.skeleton.len(),
                    )
                    .map_err(|e| format!("its skin weights: {e}"))?,
                    positions: vec![Vec3::ZERO; n],
                    normals: vec![Vec3::ZERO; n],
                })
            })
            .collect::<Result<Vec<_>, String>>();
        let inverse_bind = imported
            .inverse_bind
            .iter()
            .map(|m| Affine3A::from_mat4(*m))
            .collect();
        self.palette = vec![Affine3A::IDENTITY; imported.skeleton.len()];
        self.dual_quats = vec![DualQuat::IDENTITY; imported.skeleton.len()];
        self.generation += 1;
        self.pose = Some(rest);
        self.model = model;
        self.cursor = ClipCursor::new();
        self.clip = 0;
        self.character = Some(Character {
            clips,
            size,
            centre: 0.5 * (lo + hi),
            half_extent: 0.5 * (hi - lo),
            dots,
            dot_step: step,
            skinned,
            inverse_bind,
            imported,
        });
        Ok(summary)
    }

    pub fn is_loaded(&self) -> bool {
        self.character.is_some()
    }

    /// The loaded clips' names.
    pub fn clip_names(&self) -> Vec<String> {
        self.character.as_ref().map_or_else(Vec::new, |c| {
            c.clips.iter().map(|clip| clip.name().to_string()).collect()
        })
    }

    pub fn set_clip(&mut self, index: usize) -> Result<(), String> {
        let count = self.character.as_ref().map_or(0, |c| c.clips.len());
        if index >= count {
            return Err(format!("clip {index} does not exist ({count} loaded)"));
        }
        self.clip = index;
        self.cursor = ClipCursor::new();
        Ok(())
    }

    /// The current clip's duration (1 s when there is none, so a timeline still works).
    pub fn duration_sec(&self) -> f32 {
        self.character
            .as_ref()
            .and_then(|c| c.clips.get(self.clip))
            .map_or(1.0, |c| c.duration_sec())
    }

    pub fn set_show_mesh(&mut self, on: bool) {
        self.show_mesh = on;
    }

    /// While skinning: the bind-pose vertices as dots too, over the skinned mesh, so what
    /// skinning moved stands out from them.
    pub fn set_show_bind_pose(&mut self, on: bool) {
        self.bind_dots = on;
    }

    /// "dots" (bind-pose vertices), "lbs" or "dqs".
    pub fn set_skinning(&mut self, mode: &str) -> Result<(), String> {
        self.mode = match mode {
            "dots" => SkinMode::Dots,
            "lbs" => SkinMode::Lbs,
            "dqs" => SkinMode::Dqs,
            _ => return Err(format!("skinning must be dots, lbs or dqs, got {mode:?}")),
        };
        Ok(())
    }

    /// Whether [`GltfFigure::draw`] skins the meshes (and draws the GPU meshes).
    pub fn skinning_on(&self) -> bool {
        self.mode != SkinMode::Dots && self.show_mesh && self.character.is_some()
    }

    /// Skin in the vertex shader (with the meshes the page made from [`GltfFigure::skin_weights`]).
    pub fn set_gpu(&mut self, on: bool) {
        self.gpu = on;
    }

    /// Whether the GPU path is asked for and possible for this character (at most
    /// [`super::gpu::MAX_GPU_JOINTS`] joints, weights that validated).
    pub fn gpu_on(&self) -> bool {
        self.gpu && self.skinning_on() && self.gpu_problem().is_none()
    }

    fn gpu_problem(&self) -> Option<String> {
        let c = self.character.as_ref()?;
        let meshes = c.skinned.as_ref().ok()?;
        meshes.iter().find_map(|s| {
            super::gpu::gpu_skinnable(s.weights.joint_bound(), c.imported.skeleton.len()).err()
        })
    }

    /// Mesh `k`'s validated, normalised weights (for the GPU copy).
    pub fn skin_weights(&self, k: usize) -> Option<&SkinWeights> {
        let c = self.character.as_ref()?;
        Some(&c.skinned.as_ref().ok()?.get(k)?.weights)
    }

    /// Changes at every load: the page makes new GPU meshes then.
    pub fn generation(&self) -> u32 {
        self.generation
    }

    /// The loaded meshes in the bind pose (positions, normals, triangles), for the GPU.
    pub fn bind_meshes(&self) -> Vec<crate::mesh::MeshData> {
        self.character.as_ref().map_or_else(Vec::new, |c| {
            c.imported
                .meshes
                .iter()
                .map(|m| crate::mesh::MeshData {
                    positions: m.positions.clone(),
                    normals: m.normals.clone(),
                    indices: m.indices.clone(),
                })
                .collect()
        })
    }

    /// The skinned positions and normals of mesh `k`, as of the last [`GltfFigure::draw`] with
    /// skinning on.
    pub fn skinned(&self, k: usize) -> Option<(&[Vec3], &[Vec3])> {
        let c = self.character.as_ref()?;
        let s = c.skinned.as_ref().ok()?.get(k)?;
        Some((&s.positions, &s.normals))
    }

    /// Skins every mesh with the current model matrices.
    fn skin(&mut self, gpu: bool) -> Result<(), String> {
        let Some(c) = self.character.as_mut() else {
            return Ok(());
        };
        let meshes = c.skinned.as_mut().map_err(|e| e.clone())?;
        let root = Affine3A::from_mat4(c.imported.root_transform);
        // World matrices of the joints (the nodes above the root included), then K = M · B⁻¹.
        self.world.clear();
        self.world.extend(self.model.iter().map(|m| root * *m));
        skinning_palette(&self.world, &c.inverse_bind, &mut self.palette)
            .map_err(|e| e.to_string())?;
        self.fallback = None;
        let mut dqs = self.mode == SkinMode::Dqs;
        if dqs {
            if let Err(e) = dual_quat_palette(&self.palette, &mut self.dual_quats) {
                self.fallback = Some(format!("DQS cannot skin it ({e}); shown with LBS"));
                dqs = false;
            }
        }
        if gpu {
            return Ok(()); // the vertex shader skins: the palettes are all it needs
        }
        for (m, s) in c.imported.meshes.iter().zip(meshes.iter_mut()) {
            let result = if dqs {
                skin_dqs(
                    &self.dual_quats,
                    &s.weights,
                    &m.positions,
                    &m.normals,
                    &mut s.positions,
                    &mut s.normals,
                )
            } else {
                skin_lbs(
                    &self.palette,
                    &s.weights,
                    &m.positions,
                    &m.normals,
                    &mut s.positions,
                    &mut s.normals,
                )
            };
            result.map_err(|e| e.to_string())?;
        }
        Ok(())
    }

    /// Where to aim the camera: `[x, y, z, distance]`, framing the rest pose.
    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the root's name is placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    pub fn fit(&self) -> [f32; 4] {
        match &self.character {
            Some(c) => [c.centre.x, c.centre.y, c.centre.z, 2.0 * c.size],
            None => [0.0, 1.0, 0.0, 4.0],
        }
    }

    /// Draws the character at `time_sec`; returns the note. `meshes`: the GPU meshes made from
    /// [`GltfFigure::bind_meshes`] (drawn when skinning is on; upload [`GltfFigure::skinned`]
    /// to them after this call).
    pub fn draw(
        &mut self,
        frame: &mut Frame,
        time_sec: f32,
        meshes: &[MeshId],
    ) -> Result<String, String> {
        self.draw_with(frame, time_sec, meshes, &[])
    }

    /// As [`GltfFigure::draw`]; with GPU skinning on ([`GltfFigure::gpu_on`]) draws
    /// `skin_meshes` (one per loaded mesh, made from [`GltfFigure::bind_meshes`] and
    /// [`GltfFigure::skin_weights`]) skinned in the vertex shader instead of `meshes`.
    pub fn draw_with(
        &mut self,
        frame: &mut Frame,
        time_sec: f32,
        meshes: &[MeshId],
        skin_meshes: &[crate::draw::SkinMeshId],
    ) -> Result<String, String> {
        let time_sec = in_range("time", time_sec, 0.0, 1e6)?;
        let drawn = self.draw_character(frame, time_sec, meshes, skin_meshes)?;
        let loaded = self.load_note();
        Ok(if loaded.is_empty() {
            drawn
        } else {
            format!("{loaded} {drawn}")
        })
    }

    /// Draws what is loaded; returns the note about it (what [`GltfFigure::draw_with`] says after
    /// the outcome of the last load).
    fn draw_character(
        &mut self,
        frame: &mut Frame,
        time_sec: f32,
        meshes: &[MeshId],
        skin_meshes: &[crate::draw::SkinMeshId],
    ) -> Result<String, String> {
        let Some(c) = &self.character else {
            frame.grid(10, 0.5);
            return Ok(
                "No character loaded: pick a sample or drop a .gltf / .glb file on the figure."
                    .into(),
            );
        };
        let pose = self.pose.as_mut().expect("set with the character");
        if let Some(clip) = c.clips.get(self.clip) {
            clip.sample(time_sec, &mut self.cursor, pose);
        }
        c.imported
            .skeleton
            .model_matrices(pose, &mut self.model)
            .map_err(|e| e.to_string())?;
        let skinning = self.mode != SkinMode::Dots && self.show_mesh;
        let mesh_count = c.imported.meshes.len();
        self.gpu_fallback = match (self.gpu && skinning, self.gpu_problem()) {
            (true, Some(p)) => Some(format!("GPU skinning is off for it ({p})")),
            (true, None) if skin_meshes.len() < mesh_count => {
                Some("GPU skinning is off: no GPU meshes were given".into())
            }
            _ => None,
        };
        let gpu = self.gpu && skinning && self.gpu_fallback.is_none();
        let mut problem = None;
        if skinning {
            if let Err(e) = self.skin(gpu) {
                problem = Some(format!("Cannot skin this mesh: {e}."));
            }
        }
        let c = self.character.as_ref().expect("checked above");
        let skeleton = &c.imported.skeleton;
        if skinning && problem.is_none() {
            if gpu {
                let dqs = self.mode == SkinMode::Dqs && self.fallback.is_none();
                for &id in skin_meshes.iter().take(mesh_count) {
                    if dqs {
                        super::gpu::draw_skinned_dqs(
                            frame,
                            id,
                            Mat4::IDENTITY,
                            Some(SKIN),
                            &self.dual_quats,
                        )?;
                    } else {
                        super::gpu::draw_skinned_lbs(
                            frame,
                            id,
                            Mat4::IDENTITY,
                            Some(SKIN),
                            &self.palette,
                        )?;
                    }
                }
            } else {
                for &id in meshes.iter().take(mesh_count) {
                    frame.mesh(id, Mat4::IDENTITY, SKIN);
                }
            }
        }
        let world = |m: &Affine3A| {
            c.imported
                .root_transform
                .transform_point3(m.translation.into())
        };
        // The floor under the rest pose's lowest point (joints and mesh), not through a model
        // whose origin is at its middle (RiggedSimple's tube).
        let start = frame.lines.len();
        frame.grid(12, (c.size / 6.0).max(0.05));
        for v in &mut frame.lines[start..] {
            v.position[1] = c.centre.y - c.half_extent.y;
        }
        let radius = JOINT_RADIUS * c.size;
        for (i, &parent) in skeleton.parents().iter().enumerate() {
            let p = world(&self.model[i]);
            let color = if parent < 0 {
                palette::ORANGE
            } else {
                palette::DARK
            };
            frame.mesh(
                MeshId::SPHERE,
                Mat4::from_translation(p) * Mat4::from_scale(Vec3::splat(radius)),
                color,
            );
            if parent >= 0 {
                frame.wide_line(
                    world(&self.model[parent as usize]),
                    p,
                    palette::BLUE,
                    BONE_PX,
                );
            }
        }
        let root = skeleton
            .parents()
            .iter()
            .position(|&p| p < 0)
            .expect("a skeleton has a root");
        // The root's name above its ball; where a bone or the mesh's dots lie there (CesiumMan's
        // spine rises straight up from its root, and its hips surround it), the first place
        // round the ball clear of the bones and the dots by a few pixels, and of the other
        // joints by more, on the last frame's view, to the side first.
        let at = world(&self.model[root]);
        let dots = self.show_mesh && (!skinning || self.bind_dots);
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // Orange as its ball, but dark over a skin: RiggedSimple's beige tube lies round the
        // root, and orange text on it does not read.
        let name_color = if skinning {
            palette::DARK
        } else {
            palette::ORANGE
        };
        let first = crate::draw::Label {
            anchor: at + Vec3::Y * 2.0 * radius,
            text: "root".to_string(),
            color: name_color,
            left: false,
            priority: 0,
            offset_px: Vec2::ZERO,
            large: false,
        };
        // The ball's width on screen.
        let ball_px = view.map_or(0.0, |(view_proj, size)| {
            let px = |p| crate::camera::project_to_canvas(view_proj, size, p);
            [Vec3::X, Vec3::Y, Vec3::Z]
                .iter()
                .filter_map(|&axis| Some(px(at + axis * radius)?.distance(px(at)?)))
                .fold(0.0, f32::max)
                * 2.0
        });
        let around = crate::draw::Label::around_dot(
            at,
            ball_px,
            Vec2::new(1.0, 0.0),
            "root",
            name_color,
            0,
            12,
            8.0,
        );
        // A dot's radius on screen (the ball's in proportion) and a gap of a few pixels.
        let dot_clear_px = 0.5 * ball_px * DOT_RADIUS / JOINT_RADIUS + 3.0;
        self.dots_px.clear();
        if let (true, Some((view_proj, size))) = (dots, view) {
            let px = |&p| crate::camera::project_to_canvas(view_proj, size, p);
            self.dots_px.extend(c.dots.iter().filter_map(px));
        }
        let dots_px = &self.dots_px;
        // Over a skin, off the body too (the root lies inside it): off every skinned triangle
        // on screen. The vertex shader's skin is not known here: skinned on the GPU, the
        // palette's LBS stands for it (DQS parts from it by millimetres in a blend zone).
        self.skin_triangles.clear();
        if let (true, None, Some((view_proj, size)), Ok(skinned)) =
            (skinning, &problem, view, &c.skinned)
        {
            for (m, s) in c.imported.meshes.iter().zip(skinned) {
                let px = |p| crate::camera::project_to_canvas(view_proj, size, p);
                self.skin_px.clear();
                if gpu {
                    let vertices = m.positions.iter().zip(&m.joints).zip(&m.weights);
                    self.skin_px.extend(
                        vertices.map(|((&p, j), w)| px(lbs_point(&self.palette, p, j, w))),
                    );
                } else {
                    self.skin_px.extend(s.positions.iter().map(|&p| px(p)));
                }
                for t in m.indices.chunks_exact(3) {
                    let corner = |k: usize| self.skin_px.get(t[k] as usize).copied().flatten();
                    if let (Some(a), Some(b), Some(d)) = (corner(0), corner(1), corner(2)) {
                        self.skin_triangles.push([a, b, d]);
                    }
                }
            }
        }
        let skin = &self.skin_triangles;
        // Nor beside another joint's ball, which it would seem to name.
        let joints_px: Vec<Vec2> = match view {
            Some((view_proj, size)) => self
                .model
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != root)
                .filter_map(|(_, m)| crate::camera::project_to_canvas(view_proj, size, world(m)))
                .collect(),
            None => Vec::new(),
        };
        let joint_clear_px = 0.5 * ball_px + 12.0;
        frame.first_clear_label_by(view, 2.0, std::iter::once(first).chain(around), |rect| {
            let clear = |points: &[Vec2], gap: f32| {
                points.iter().all(|&d| rect.nearest(d).distance(d) > gap)
            };
            clear(dots_px, dot_clear_px)
                && clear(&joints_px, joint_clear_px)
                && !skin.iter().any(|&t| touches_triangle(rect, t))
        });
        if dots {
            let radius = DOT_RADIUS * c.size;
            for &d in &c.dots {
                frame.point(d, radius, palette::GREY);
            }
        }
        // The rest pose's box (joints and mesh) and the joints where they are now stay in view,
        // so the character fills the canvas at any size.
        let margin = 0.05 * c.size;
        frame.keep_box_in_view(
            c.centre - c.half_extent - Vec3::splat(margin),
            c.centre + c.half_extent + Vec3::splat(margin),
        );
        for m in &self.model {
            frame.keep_in_view.push(world(m));
        }
        // The skinned mesh wherever the pose takes it (the rest pose's box cuts a raised arm or
        // a bent tip): every k-th vertex skinned by the palette (LBS, on the CPU whichever
        // skins the mesh), the same thinned set as the dots.
        if skinning && problem.is_none() {
            let step = c.dot_step;
            let palette = &self.palette;
            let skinned = c.imported.meshes.iter().flat_map(|m| {
                let vertices = m.positions.iter().zip(&m.joints).zip(&m.weights);
                vertices.map(|((&p, j), w)| lbs_point(palette, p, j, w))
            });
            frame
                .keep_in_view
                .extend(skinned.step_by(step).filter(|p| p.is_finite()));
        }
        let clip = c.clips.get(self.clip);
        Ok(format!(
            "{}{}",
            match clip {
                Some(clip) => format!(
                    "Clip \"{}\" at {} s of {} s (looping)",
                    clip.name(),
                    format_number(time_sec % clip.duration_sec().max(1e-6)),
                    format_number(clip.duration_sec())
                ),
                None => "No clip: the rest pose".into(),
            },
            match (skinning, &problem, &self.fallback) {
                (true, Some(p), _) => format!(". {p}"),
                (true, None, Some(f)) => format!(". {f}."),
                (true, None, None) => format!(
                    ". Skinned by {} {} with the file's inverse bind matrices{}.{}",
                    if self.mode == SkinMode::Dqs {
                        "DQS"
                    } else {
                        "LBS"
                    },
                    if gpu {
                        "on the GPU (vertex shader)"
                    } else {
                        "on the CPU"
                    },
                    self.gpu_fallback
                        .as_ref()
                        .map_or(String::new(), |f| format!("; {f}")),
                    if dots && !c.dots.is_empty() {
                        " Grey dots: the mesh's vertices in the bind pose; where the skinned mesh has left them, skinning moved it."
                    } else {
                        ""
                    },
                ),
                (false, ..) if self.show_mesh && !c.dots.is_empty() => {
                    ". Grey dots: the mesh's vertices in the bind pose (where the mesh sits before skinning moves it)."
                        .to_string()
                }
                _ => ".".to_string(),
            }
        ))
    }
}

/// A bind-pose point skinned by linear blend skinning with `palette` (a joint outside it adds
/// nothing).
fn lbs_point(palette: &[Affine3A], p: Vec3, joints: &[u16; 4], weights: &[f32; 4]) -> Vec3 {
    joints.iter().zip(weights).fold(Vec3::ZERO, |sum, (&j, &w)| {
        palette.get(j as usize).map_or(sum, |k| sum + w * k.transform_point3(p))
    })
}

/// Whether the label box `rect` (grown by 2 px) and the triangle `[a, b, c]` on the canvas
/// overlap: an edge of the triangle enters the box, or the box lies inside the triangle.
fn touches_triangle(rect: crate::draw::layout::Rect, [a, b, c]: [Vec2; 3]) -> bool {
    let (lo, hi) = (
        rect.min - Vec2::splat(2.0),
        rect.min + rect.size + Vec2::splat(2.0),
    );
    if a.min(b).min(c).cmpgt(hi).any() || a.max(b).max(c).cmplt(lo).any() {
        return false;
    }
    let enters = |p, q| crate::draw::segment_enters(p, q, lo, hi);
    if enters(a, b) || enters(b, c) || enters(c, a) {
        return true;
    }
    // The box's centre on the same side of all three edges: inside.
    let m = 0.5 * (lo + hi);
    let side = |p: Vec2, q: Vec2| (q - p).perp_dot(m - p);
    let (x, y, z) = (side(a, b), side(b, c), side(c, a));
    (x >= 0.0 && y >= 0.0 && z >= 0.0) || (x <= 0.0 && y <= 0.0 && z <= 0.0)
}
