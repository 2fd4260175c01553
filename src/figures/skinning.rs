//! Figure logic for lesson 09, "Skinning" (see [`crate::figures`]).
//!
//! - [`CylinderFigure`]: the bend-and-twist cylinder skinned twice on one rig, LBS (orange) beside
//!   DQS (teal); the elbow ring whose area the plot measures; weights as a heat map for a chosen
//!   joint; the falloff of the automatic weights; the check of the student's exercises 9.1 and 9.2.
//! - [`area_curves`]: the elbow cross-section's area against the bend and the twist angle.
//! - [`HumanFigure`]: the built-in human with a skinned body, playing a clip, by LBS or DQS.
//!
//! The meshes' vertices change when a control moves (the cylinder) or every frame (the human);
//! the web layer creates each GPU mesh once and rewrites it in place when
//! [`SkinnedMesh::take_dirty`] says so.

use super::{
    compare_note, failure_note, format_number, in_range, palette, Frame, MeshId, Runner,
    DEFAULT_RUNNER,
};
use crate::camera::{project_to_canvas, OrbitCamera};
use crate::draw::layout::Rect;
use crate::draw::Label;
use crate::exercises::run;
use crate::rigid::DualQuat;
use crate::skeleton::{human, Clip, ClipCursor, Pose};
use crate::skinning::rigs::{cylinder_rig, skinned_human, CylinderRig, SkinnedCharacter};
use crate::skinning::{
    dual_quat_palette, mesh_volume, ring_area, skin_dqs, skin_lbs, skinning_palette, SkinWeights,
};
use crate::Valid;
use glam::{Affine3A, Mat4, Vec2, Vec3, Vec4};

const EXERCISE_FILE: &str = "src/exercises/skinning.rs";
/// How close the student's skinned positions must be to the reference's, metres.
const TOLERANCE: f32 = 1e-4;
/// Where the two cylinders stand: LBS on the left, DQS on the right.
pub const LBS_OFFSET: Vec3 = Vec3::new(-2.4, 0.3, 0.0);
pub const DQS_OFFSET: Vec3 = Vec3::new(0.4, 0.3, 0.0);

/// Whether a label's box (CSS pixels) covers none of `points` (on the canvas), with `margin_px`
/// round each: the further test of [`Frame::first_clear_label_by`] for a label that must keep off
/// a surface the frame does not list (a body, a tube), given as points on it. Lessons 01 and 09
/// share it, so that the placement is compiled once for them.
pub fn off_points(points: &[Vec2], margin_px: f32) -> impl Fn(Rect) -> bool + '_ {
    move |rect| {
        let (lo, hi) = (rect.min - margin_px, rect.max() + margin_px);
        points
            .iter()
            .all(|p| !(p.cmpgt(lo).all() && p.cmplt(hi).all()))
    }
}

/// The matrix and canvas size (CSS pixels) a figure places its labels for: the last frame's
/// camera, as the page passes it (`set_*view`).
pub fn view_of(view: Option<(OrbitCamera, Vec2)>) -> Option<(Mat4, Vec2)> {
    view.map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size))
}

/// The camera's right and up in world space, from its yaw and pitch alone: for a diagram that
/// faces the camera. Not its view matrix's rows, which move in their last bits as the fit moves
/// the target, so that a figure following them would change every frame and never rest.
/// Lessons 09 and 10 share it.
pub fn screen_axes(camera: &OrbitCamera) -> (Vec3, Vec3) {
    let (sy, cy) = camera.yaw_rad.sin_cos();
    let (sp, cp) = camera.pitch_rad.sin_cos();
    (Vec3::new(cy, 0.0, -sy), Vec3::new(-sy * sp, cp, -cy * sp))
}

/// Heat-map colour of a weight in `[0, 1]`: blue (0) through pale yellow (½) to red (1).
pub fn heat(w: f32) -> Vec4 {
    let w = w.clamp(0.0, 1.0);
    let mid = Vec3::new(0.9, 0.85, 0.35);
    let c = if w < 0.5 {
        palette::BLUE.lerp(mid, 2.0 * w)
    } else {
        mid.lerp(palette::RED, 2.0 * w - 1.0)
    };
    c.extend(1.0)
}

/// The heat map's colour ramp as a CSS gradient (left 0, right 1), for the legends beside the
/// figures: eleven stops of [`heat`], converted to sRGB like the mesh colours, so the legend
/// shows exactly the colours on the meshes.
pub fn heat_ramp_css() -> String {
    let stops: Vec<String> = (0..=10)
        .map(|k| {
            let w = k as f32 / 10.0;
            format!("{} {}%", palette::css(heat(w).truncate()), 10 * k)
        })
        .collect();
    format!("linear-gradient(to right, {})", stops.join(", "))
}

/// A skinned mesh's current vertices and colours, and whether the GPU copy is stale.
#[derive(Clone, Debug, Default)]
pub struct SkinnedMesh {
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    pub colors: Vec<Vec4>,
    dirty: bool,
}

impl SkinnedMesh {
    fn new(n: usize) -> Self {
        Self {
            positions: vec![Vec3::ZERO; n],
            normals: vec![Vec3::ZERO; n],
            colors: vec![Vec4::ONE; n],
            dirty: true,
        }
    }

    /// Says the vertices changed (a figure that rewrote them in place).
    pub fn mark_dirty(&mut self) {
        self.dirty = true;
    }

    /// True once after the vertices changed: upload them.
    pub fn take_dirty(&mut self) -> bool {
        std::mem::take(&mut self.dirty)
    }
}

/// Colours: the heat map of `joint`'s weights, or `plain` everywhere.
fn paint(colors: &mut [Vec4], skin: &SkinWeights, joint: Option<usize>, plain: &[Vec4]) {
    for (v, c) in colors.iter_mut().enumerate() {
        *c = match joint {
            Some(j) => heat(skin.weight_of(v, j)),
            None => plain[v.min(plain.len() - 1)],
        };
    }
}

/// How many vertices have a second weight above 1%.
fn blended(skin: &SkinWeights) -> usize {
    skin.weights().iter().filter(|w| w[1] > 0.01).count()
}

/// Which joint the heat map shows: "none" or a joint's name.
fn parse_heat(names: &[String], name: &str) -> Result<Option<usize>, String> {
    if name == "none" {
        return Ok(None);
    }
    names
        .iter()
        .position(|n| n == name)
        .map(Some)
        .ok_or_else(|| format!("weights of: no joint named {name:?}"))
}

/// Where the current pose lies on the cylinder figure's two plots ([`CylinderFigure::plot_cursors`]):
/// an angle in degrees on each x axis, or `None` when the pose is on none of the plot's curves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlotCursors {
    /// On the area plot (bend curves with no twist, twist curves with no bend).
    pub area: Option<f32>,
    /// On the volume plot (against the bend, with no twist).
    pub volume: Option<f32>,
}

/// The lesson's first figure: one rig, skinned by LBS and by DQS side by side.
#[derive(Clone, Debug)]
pub struct CylinderFigure {
    rig: CylinderRig,
    skin: SkinWeights,
    falloff: f32,
    bend_rad: f32,
    twist_rad: f32,
    heat_joint: Option<usize>,
    use_exercise: bool,
    runner: Runner,
    model: Vec<Affine3A>,
    palette: Vec<Affine3A>,
    dual_quats: Vec<DualQuat>,
    pub lbs: SkinnedMesh,
    pub dqs: SkinnedMesh,
    exercise_note: String,
    stale: bool,
    /// The ring whose top vertex the figure follows ([`CylinderFigure::set_probe_ring`]).
    probe_ring: usize,
    /// The last frame's camera and canvas size (CSS pixels), which the labels are placed for
    /// ([`CylinderFigure::set_view`]).
    view: Option<(OrbitCamera, Vec2)>,
}

/// Widths of the elbow ring and of the lines along the tubes, CSS pixels.
const RING_PX: f32 = 3.0;
const STRIPE_PX: f32 = 2.0;
/// Figure 1's LBS point (orange, on the orange tube), the dark ring under it that sets it off
/// from the tube in the close-up, and DQS's point beside the LBS tube, under both and wider, so
/// that it rings them where they meet: CSS pixels.
pub const LBS_DOT_PX: f32 = 11.0;
pub const LBS_RING_PX: f32 = 16.0;
pub const DQS_BESIDE_LBS_PX: f32 = 21.0;
/// The X-rayed skeleton of the skinned character: bone width and joint dot size, CSS pixels (a
/// bone must read through the body at 800 x 600).
pub const BONE_PX: f32 = 3.0;
pub const JOINT_PX: f32 = 9.0;

impl Default for CylinderFigure {
    fn default() -> Self {
        Self::new()
    }
}

/// What the cylinder figure keeps in view around each tube (before its offset): the box that
/// holds the tube bent 0 to 180° (the forearm swings up through +y) and twisted either way,
/// with a few centimetres to spare, and the tube's name below it (at y = −0.45).
pub const CYLINDER_VIEW: [Vec3; 2] = [Vec3::new(-0.05, -0.46, -0.42), Vec3::new(2.05, 1.06, 0.42)];

/// The smallest weight the followed vertex's note shows as more than 0.000: below it a joint
/// counts as having none (no dot, name or chord; the other joint has it all, to well under a
/// millimetre).
pub const PROBE_MIN_WEIGHT: f32 = 0.0005;

/// The cylinder's resolution: rings along it (odd: one at the elbow) and vertices around.
pub const CYLINDER_RINGS: usize = 41;
pub const CYLINDER_AROUND: usize = 24;

impl CylinderFigure {
    /// The vertices (index around each ring) the grey lines along the tube run through: on top
    /// (+y) and in front (+z) in the bind pose.
    pub const STRIPES: [usize; 2] = [0, CYLINDER_AROUND / 4];

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the elbows' and the followed vertex's names are placed for.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// Bent 90°, not twisted, falloff 0.15 m, no heat map.
    pub fn new() -> Self {
        let rig = cylinder_rig(1.0, 0.25, CYLINDER_RINGS, CYLINDER_AROUND)
            .valid("the lesson's cylinder is valid");
        let falloff = 0.15;
        let skin = rig.weights(falloff).valid("a valid falloff");
        let n = rig.mesh.positions.len();
        let j = rig.skeleton.len();
        let mut figure = Self {
            skin,
            falloff,
            bend_rad: 90f32.to_radians(),
            twist_rad: 0.0,
            heat_joint: None,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            model: vec![Affine3A::IDENTITY; j],
            palette: vec![Affine3A::IDENTITY; j],
            dual_quats: vec![DualQuat::IDENTITY; j],
            lbs: SkinnedMesh::new(n),
            dqs: SkinnedMesh::new(n),
            exercise_note: String::new(),
            stale: true,
            probe_ring: CYLINDER_RINGS / 2,
            view: None,
            rig,
        };
        figure.repaint();
        figure
    }

    pub fn rig(&self) -> &CylinderRig {
        &self.rig
    }

    pub fn skin(&self) -> &SkinWeights {
        &self.skin
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.stale = true;
    }

    /// Elbow bend about z, degrees in [0, 180].
    pub fn set_bend_deg(&mut self, deg: f32) -> Result<(), String> {
        self.bend_rad = in_range("bend", deg, 0.0, 180.0)?.to_radians();
        self.stale = true;
        Ok(())
    }

    /// Elbow twist about its bone, degrees in [−180, 180].
    pub fn set_twist_deg(&mut self, deg: f32) -> Result<(), String> {
        self.twist_rad = in_range("twist", deg, -180.0, 180.0)?.to_radians();
        self.stale = true;
        Ok(())
    }

    /// Falloff of the automatic weights, metres in [0.01, 1].
    pub fn set_falloff(&mut self, falloff: f32) -> Result<(), String> {
        let f = in_range("falloff", falloff, 0.01, 1.0)?;
        self.skin = self.rig.weights(f).map_err(|e| e.to_string())?;
        self.falloff = f;
        self.repaint();
        self.stale = true;
        Ok(())
    }

    /// The joint whose weights colour the meshes: "none", "shoulder" or "elbow".
    pub fn set_heat_joint(&mut self, name: &str) -> Result<(), String> {
        let joint = parse_heat(&self.rig.skeleton.names()[..2], name)?;
        self.heat_joint = joint;
        self.repaint();
        Ok(())
    }

    /// Skins with the student's exercises 9.1 (LBS) and 9.2 (the DQS blend), in the sandbox.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.stale = true;
    }

    fn repaint(&mut self) {
        let lbs = [palette::ORANGE.extend(1.0)];
        let dqs = [palette::TEAL.extend(1.0)];
        paint(&mut self.lbs.colors, &self.skin, self.heat_joint, &lbs);
        paint(&mut self.dqs.colors, &self.skin, self.heat_joint, &dqs);
        self.lbs.dirty = true;
        self.dqs.dirty = true;
    }

    /// Skins both meshes if a control changed since the last call.
    pub fn update(&mut self) -> Result<(), String> {
        if !self.stale {
            return Ok(());
        }
        self.stale = false;
        self.rig
            .palette(
                self.bend_rad,
                self.twist_rad,
                &mut self.model,
                &mut self.palette,
            )
            .map_err(|e| e.to_string())?;
        dual_quat_palette(&self.palette, &mut self.dual_quats).map_err(|e| e.to_string())?;
        let m = &self.rig.mesh;
        skin_lbs(
            &self.palette,
            &self.skin,
            &m.positions,
            &m.normals,
            &mut self.lbs.positions,
            &mut self.lbs.normals,
        )
        .map_err(|e| e.to_string())?;
        skin_dqs(
            &self.dual_quats,
            &self.skin,
            &m.positions,
            &m.normals,
            &mut self.dqs.positions,
            &mut self.dqs.normals,
        )
        .map_err(|e| e.to_string())?;
        self.exercise_note = if self.use_exercise {
            self.run_exercises()
        } else {
            String::new()
        };
        self.lbs.dirty = true;
        self.dqs.dirty = true;
        Ok(())
    }

    /// Replaces the reference positions by the student's where they answered; says how they
    /// compare (the largest difference over all vertices, and where).
    fn run_exercises(&mut self) -> String {
        let at = format!(
            "bend {}°, twist {}°",
            format_number(self.bend_rad.to_degrees()),
            format_number(self.twist_rad.to_degrees())
        );
        let mut notes = Vec::new();
        // 9.1: LBS, vertex by vertex.
        let mut failure = None;
        let positions = &self.rig.mesh.positions;
        let mut student = Vec::with_capacity(positions.len());
        for (v, &p) in positions.iter().enumerate() {
            let j = self.skin.joints()[v];
            let w = self.skin.weights()[v];
            let mats: Vec<Mat4> = j
                .iter()
                .map(|&j| Mat4::from(self.palette[j as usize]))
                .collect();
            match run::lbs_vertex(self.runner, mats, w.to_vec(), p) {
                Ok(q) => student.push(q),
                Err(f) => {
                    failure = Some(f);
                    break;
                }
            }
        }
        let lbs_not_done = matches!(failure, Some(run::Failure::NotDone));
        match failure {
            Some(f) => notes.push(failure_note("exercise 9.1 lbs_vertex", EXERCISE_FILE, &f)),
            None => {
                notes.push(vertices_note(
                    "lbs_vertex (9.1)",
                    &at,
                    &student,
                    &self.lbs.positions,
                ));
                self.lbs.positions.copy_from_slice(&student);
            }
        }
        // 9.2: the DQS blend, vertex by vertex; the reference applies the blended motion.
        let mut failure = None;
        student.clear();
        for (v, &p) in positions.iter().enumerate() {
            let j = self.skin.joints()[v];
            let w = self.skin.weights()[v];
            // q and −q are the same motion, and a palette may give either: the elbow's is
            // passed negated, so a blend without the antipodality fix shows (this rig's joints
            // otherwise all sit on one hemisphere, where a missing fix changes nothing).
            let dqs: Vec<DualQuat> = j
                .iter()
                .map(|&j| {
                    let q = self.dual_quats[j as usize];
                    if j == 1 {
                        q * -1.0
                    } else {
                        q
                    }
                })
                .collect();
            match run::blend_dual_quats(self.runner, dqs, w.to_vec()) {
                Ok(q) => student.push(q.transform_point(p)),
                Err(f) => {
                    failure = Some(f);
                    break;
                }
            }
        }
        match failure {
            // Neither done: one sentence for both.
            Some(f @ run::Failure::NotDone) if lbs_not_done => {
                notes[0] = failure_note(
                    "exercises 9.1 lbs_vertex and 9.2 blend_dual_quats",
                    EXERCISE_FILE,
                    &f,
                );
            }
            Some(f) => notes.push(failure_note(
                "exercise 9.2 blend_dual_quats",
                EXERCISE_FILE,
                &f,
            )),
            None => {
                notes.push(vertices_note(
                    "blend_dual_quats (9.2), applied to the vertex,",
                    &at,
                    &student,
                    &self.dqs.positions,
                ));
                for (dst, s) in self.dqs.positions.iter_mut().zip(&student) {
                    *dst = if s.is_finite() { *s } else { Vec3::ZERO };
                }
            }
        }
        let probes = self.probe_exercises();
        if !probes.is_empty() {
            notes.push(probes);
        }
        notes.join(" ")
    }

    /// Exercises 9.1 and 9.2 on the elbow ring at poses the sliders may not be at: a half
    /// twist (the candy wrapper), a deep bend, and a bend with a twist. Says which differ.
    fn probe_exercises(&self) -> String {
        const POSES: [(f32, f32); 3] = [(0.0, 180.0), (150.0, 0.0), (90.0, 90.0)];
        let n = self.rig.skeleton.len();
        let (mut model, mut k, mut dq) = (
            vec![Affine3A::IDENTITY; n],
            vec![Affine3A::IDENTITY; n],
            vec![DualQuat::IDENTITY; n],
        );
        let s = self.rig.ring_start(self.rig.elbow_ring());
        let mut differ = [Vec::new(), Vec::new()];
        let mut answered = [true, true];
        for (bend, twist) in POSES {
            if self
                .rig
                .palette(bend.to_radians(), twist.to_radians(), &mut model, &mut k)
                .is_err()
                || dual_quat_palette(&k, &mut dq).is_err()
            {
                continue;
            }
            let at = format!("bend {bend:.0}° twist {twist:.0}°");
            let (mut lbs_ok, mut dqs_ok) = (true, true);
            for v in s..s + self.rig.around {
                let p = self.rig.mesh.positions[v];
                let (j, w) = (self.skin.joints()[v], self.skin.weights()[v]);
                let mats: Vec<Mat4> = j.iter().map(|&j| Mat4::from(k[j as usize])).collect();
                let reference = crate::skinning::lbs_vertex(&mats, &w, p);
                // An exercise that gives no answer (a stub, a panic) is reported above, not here.
                lbs_ok &= match run::lbs_vertex(self.runner, mats, w.to_vec(), p) {
                    Ok(q) => (q - reference).length() <= TOLERANCE,
                    Err(_) => {
                        answered[0] = false;
                        true
                    }
                };
                // The elbow's dual quaternion negated, as in the figure.
                let qs: Vec<DualQuat> = j
                    .iter()
                    .map(|&j| if j == 1 { dq[1] * -1.0 } else { dq[j as usize] })
                    .collect();
                let reference = crate::skinning::blend_dual_quats(&qs, &w).transform_point(p);
                dqs_ok &= match run::blend_dual_quats(self.runner, qs, w.to_vec()) {
                    Ok(q) => (q.transform_point(p) - reference).length() <= TOLERANCE,
                    Err(_) => {
                        answered[1] = false;
                        true
                    }
                };
            }
            if !lbs_ok {
                differ[0].push(at.clone());
            }
            if !dqs_ok {
                differ[1].push(at);
            }
        }
        let poses = "bend 0° twist 180°, bend 150° twist 0°, bend 90° twist 90°";
        let said: Vec<String> = ["9.1", "9.2"]
            .iter()
            .zip(&differ)
            .zip(answered)
            .filter(|(_, answered)| *answered)
            .map(|((name, d), _)| {
                if d.is_empty() {
                    format!("{name} matches there")
                } else {
                    format!("{name} differs at {}", d.join(", "))
                }
            })
            .collect();
        match (said.len(), differ.iter().all(Vec::is_empty)) {
            (0, _) => String::new(),
            (2, true) => format!("Both also match on the elbow ring at {poses}."),
            _ => format!("Probed on the elbow ring at {poses}: {}.", said.join("; ")),
        }
    }

    /// The elbow ring's area now, as a fraction of its rest area: (LBS, DQS).
    pub fn elbow_areas(&self) -> (f32, f32) {
        let s = self.rig.ring_start(self.rig.elbow_ring());
        let e = s + self.rig.around;
        let rest = self.rig.rest_ring_area();
        (
            ring_area(&self.lbs.positions[s..e]) / rest,
            ring_area(&self.dqs.positions[s..e]) / rest,
        )
    }

    /// Fills the draw list (`meshes`: the LBS and the DQS mesh's ids) and returns the note.
    pub fn draw(&mut self, frame: &mut Frame, meshes: [MeshId; 2]) -> Result<String, String> {
        self.update()?;
        frame.grid(12, 0.5);
        let s = self.rig.ring_start(self.rig.elbow_ring());
        let e = s + self.rig.around;
        for (mesh, offset, skinned) in [
            (meshes[0], LBS_OFFSET, &self.lbs),
            (meshes[1], DQS_OFFSET, &self.dqs),
        ] {
            let model = Mat4::from_translation(offset);
            frame.mesh_vertex_colors(mesh, model);
            // The measured cross-section, slightly outside the surface so it shows.
            let ring = &skinned.positions[s..e];
            let c = ring.iter().sum::<Vec3>() / ring.len() as f32;
            let lifted: Vec<Vec3> = ring
                .iter()
                .chain(std::iter::once(&ring[0]))
                .map(|p| offset + c + (*p - c) * 1.03)
                .collect();
            frame.wide_polyline(&lifted, palette::DARK, RING_PX);
            // Two rows of vertices along the tube (on top and facing the camera in the bind
            // pose): a twist shows as these lines turning round the tube (DQS), or running
            // into the pinch (LBS); a plain tube looks the same however far it is twisted.
            for k in Self::STRIPES {
                let stripe: Vec<Vec3> = (0..self.rig.rings)
                    .map(|r| {
                        let s = self.rig.ring_start(r);
                        let ring = &skinned.positions[s..s + self.rig.around];
                        let c = ring.iter().sum::<Vec3>() / ring.len() as f32;
                        offset + c + (ring[k] - c) * 1.03
                    })
                    .collect();
                frame.wide_polyline(&stripe, palette::GREY, STRIPE_PX);
            }
        }
        let probe = self.draw_probe(frame);
        // Each tube's name below it, and its elbow's name anchored at the elbow joint: each at
        // the first place round its anchor, below first, that covers neither tube nor any dot,
        // line or name (on the last frame's view); the page draws a leader line to a name
        // placed away from its anchor.
        let view = view_of(self.view);
        let tubes_px: Vec<Vec2> = view.map_or(Vec::new(), |(view_proj, size)| {
            [(LBS_OFFSET, &self.lbs), (DQS_OFFSET, &self.dqs)]
                .into_iter()
                .flat_map(|(o, m)| m.positions.iter().map(move |p| o + *p))
                .filter_map(|p| project_to_canvas(view_proj, size, p))
                .collect()
        });
        let elbow = Vec3::from(self.model[1].translation);
        for (offset, color, name) in [
            (LBS_OFFSET, palette::ORANGE, "LBS"),
            (DQS_OFFSET, palette::TEAL, "DQS"),
        ] {
            for (anchor, color, name) in [
                (offset + Vec3::new(0.2, -0.45, 0.0), color, name),
                (offset + elbow, palette::DARK, "elbow"),
            ] {
                let candidates = Label::around_dot(anchor, 0.0, Vec2::Y, name, color, 0, 16, 10.0);
                frame.first_clear_label_by(view, 2.0, candidates, off_points(&tubes_px, 3.0));
            }
        }
        // Both tubes at every bend and twist the sliders reach, with their labels: the camera
        // stays put while the sliders move.
        for offset in [LBS_OFFSET, DQS_OFFSET] {
            frame.keep_box_in_view(offset + CYLINDER_VIEW[0], offset + CYLINDER_VIEW[1]);
        }
        let (a_lbs, a_dqs) = self.elbow_areas();
        let mut note = format!(
            "Elbow ring: LBS keeps {:.0}% of its rest area, DQS {:.0}%.",
            100.0 * a_lbs,
            100.0 * a_dqs
        );
        note.push_str(&format!(
            " Falloff {} m: {} of {} vertices blend shoulder and elbow.",
            format_number(self.falloff),
            blended(&self.skin),
            self.skin.len()
        ));
        note.push(' ');
        note.push_str(match self.plot_cursors() {
            PlotCursors { area: Some(_), volume: Some(_) } => {
                "The plots' dashed lines mark this bend (no twist)."
            }
            PlotCursors { area: Some(_), volume: None } => {
                "The area plot's dashed line marks this twist (no bend)."
            }
            _ => {
                "Bent and twisted, the tube is on none of the plots' curves."
            }
        });
        if let Some(j) = self.heat_joint {
            note.push_str(&format!(
                " Colours: the {}'s weights, blue 0 to red 1.",
                self.rig.skeleton.names()[j]
            ));
        }
        note.push(' ');
        note.push_str(&probe);
        if !self.exercise_note.is_empty() {
            note.push(' ');
            note.push_str(&self.exercise_note);
        }
        Ok(note)
    }

    /// The vertex the figure follows: the top one (+y in the bind pose) of ring `ring`, from 0
    /// at the shoulder end to [`CYLINDER_RINGS`] − 1 at the wrist end.
    pub fn set_probe_ring(&mut self, ring: usize) -> Result<(), String> {
        if ring >= self.rig.rings {
            return Err(format!(
                "vertex ring must be between 0 and {}, got {ring}",
                self.rig.rings - 1
            ));
        }
        self.probe_ring = ring;
        Ok(())
    }

    /// The followed vertex's index, and where the shoulder alone and the elbow alone would take
    /// it, `[K₁p, K₂p]` with their weights (model space, before the tubes' offsets): always in
    /// that order, as the caption names them, whichever joint is heavier. A joint not among the
    /// vertex's influences has weight 0.
    pub fn probe(&self) -> (usize, [(Vec3, f32); 2]) {
        let v = self.rig.ring_start(self.probe_ring);
        let p = self.rig.mesh.positions[v];
        let (j, w) = (self.skin.joints()[v], self.skin.weights()[v]);
        let k = |joint: u16| {
            let weight = j.iter().zip(w).filter(|(&i, _)| i == joint).map(|(_, w)| w).sum();
            (self.palette[usize::from(joint)].transform_point3(p), weight)
        };
        (v, [k(0), k(1)])
    }

    /// Draws the followed vertex on the LBS tube: where each joint alone would take it (K₁p,
    /// K₂p), the chord between them, LBS's point on that chord and DQS's point; DQS's point on
    /// the DQS tube too. The two names are large and dark: they sit on the orange tube, where
    /// grey text and 0.8 rem subscripts do not read. Returns the note's sentence.
    fn draw_probe(&self, frame: &mut Frame) -> String {
        let (v, [(k1, w1), (k2, w2)]) = self.probe();
        let (lbs, dqs) = (self.lbs.positions[v], self.dqs.positions[v]);
        let o = LBS_OFFSET;
        let both = w1 >= PROBE_MIN_WEIGHT && w2 >= PROBE_MIN_WEIGHT;
        if both {
            frame.stroke(
                &[o + k1, o + k2],
                palette::DARK,
                crate::draw::StrokeStyle::dashed(2.0, 0.04, 0.03),
            );
        }
        // A joint with no weight (to the note's three decimals) moves the vertex nowhere: its dot
        // and name are left out.
        let named = [(k2, w2, k1, "K₂p"), (k1, w1, k2, "K₁p")];
        let named: Vec<_> = named.into_iter().filter(|n| n.1 >= PROBE_MIN_WEIGHT).collect();
        for &(k, ..) in &named {
            frame.marker_on_top(o + k, 10.0, palette::GREY);
        }
        // LBS's orange point lies on the orange tube: a dark ring sets it off. DQS's point is
        // wider than that ring, which goes over it: where the two lie a few pixels apart (a small
        // bend) the teal still rings the dark.
        frame.marker_on_top(o + dqs, DQS_BESIDE_LBS_PX, palette::TEAL);
        frame.marker_on_top(o + lbs, LBS_RING_PX, palette::DARK);
        frame.marker_on_top(o + lbs, LBS_DOT_PX, palette::ORANGE);
        frame.marker_on_top(DQS_OFFSET + dqs, 12.0, palette::TEAL);
        // The four dots close up, seen from the front (across the bend's plane), with the whole
        // tube's depth: in the main view LBS's dot lies a few pixels from DQS's.
        let dots = named.iter().map(|n| n.0).chain([lbs]);
        let (lo, hi) = dots.fold((dqs, dqs), |(a, b), p| (a.min(p), b.max(p)));
        let pad = Vec3::new(0.08, 0.08, 0.3);
        frame.inset(
            crate::draw::inset::InsetView::Front,
            "close up",
            o + lo - pad,
            o + hi + pad,
        );
        // The tubes lie low and wide (a straight one is 2 m long): above the inset's square
        // they get the canvas's whole width.
        frame.fit_above_inset();
        // Each name at the first place round its dot, away from the other dot first, clear of
        // the dots, lines and the other name (on the last frame's view), and nearer its own dot
        // than any other dot (but one drawn on it): where the dots crowd, a name beside the
        // teal or orange dot would seem to name that one.
        let view = view_of(self.view);
        let at = |p: Vec3| view.and_then(|(m, size)| project_to_canvas(m, size, o + p));
        for &(k, _, other, text) in &named {
            let toward = at(k).zip(at(other)).map_or(Vec2::X, |(a, b)| a - b);
            let mut candidates =
                Label::around_dot(o + k, 10.0, toward, text, palette::DARK, 1, 6, 8.0);
            for l in &mut candidates {
                l.large = true;
            }
            // Off the canvas (NaN), a dot is left out of the comparison.
            let px = |p: Vec3| at(p).unwrap_or(Vec2::NAN);
            let own = px(k);
            let others = [if both { px(other) } else { Vec2::NAN }, px(lbs), px(dqs)];
            frame.first_clear_label_by(view, 2.0, candidates, |rect| {
                let gap = |d: Vec2| rect.nearest(d).distance(d);
                others
                    .iter()
                    .all(|&q| !(q.distance(own) > 3.0) || gap(q) > gap(own))
            });
        }
        let elbow = Vec3::from(self.model[1].translation);
        let rest = self.rig.mesh.positions[v].distance(self.rig.segments[1].0);
        // With one joint at weight 1 there is no chord (none is drawn): both methods move the
        // vertex rigidly with that joint, to its K p.
        let place = match (w1 >= PROBE_MIN_WEIGHT, w2 >= PROBE_MIN_WEIGHT) {
            (true, true) => "on the dashed chord between K₁p and K₂p",
            (true, false) => "at K₁p, as DQS (the shoulder has it all)",
            _ => "at K₂p, as DQS (the elbow has it all)",
        };
        // Fixed decimals: a weight or distance that is zero up to float noise reads 0.000, not
        // 1.7e-12.
        format!(
            "Followed vertex (ring {}, shoulder {w1:.3}, elbow {w2:.3}): LBS {place}, {:.3} m from the elbow joint; DQS {:.3} m (bind pose {rest:.3} m).",
            self.probe_ring,
            lbs.distance(elbow),
            dqs.distance(elbow),
        )
    }

    /// Where the current pose lies on the plots' x axes (their dashed lines), degrees. The area
    /// plot's curves each vary one angle with the other at 0: with no twist the pose is on the
    /// bend curves at the bend, with no bend on the twist curves at |twist| (a twist either way
    /// shrinks the ring alike); bent and twisted at once it is on none. The volume plot is
    /// against the bend with no twist.
    pub fn plot_cursors(&self) -> PlotCursors {
        let (bend, twist) = (self.bend_rad.to_degrees(), self.twist_rad.to_degrees());
        PlotCursors {
            area: if twist == 0.0 {
                Some(bend)
            } else if bend == 0.0 {
                Some(twist.abs())
            } else {
                None
            },
            volume: (twist == 0.0).then_some(bend),
        }
    }

    /// The elbow ring's area (fraction of rest) against the angle: `[angle (°), LBS bend, DQS
    /// bend, LBS twist, DQS twist]` per sample, angles from 0 to 180°, at this falloff.
    pub fn area_curves(&self, samples: usize) -> Result<Vec<f32>, String> {
        area_curves(&self.rig, &self.skin, samples)
    }

    /// The weights along the tube at this falloff, ring by ring (each ring's top vertex, in the
    /// bind pose): `[distance from the shoulder end (m), shoulder's weight, elbow's weight]`
    /// per ring.
    pub fn weight_curves(&self) -> Vec<f32> {
        let start = self.rig.mesh.positions[0].x;
        (0..self.rig.rings)
            .flat_map(|r| {
                let v = self.rig.ring_start(r);
                [
                    self.rig.mesh.positions[v].x - start,
                    self.skin.weight_of(v, 0),
                    self.skin.weight_of(v, 1),
                ]
            })
            .collect()
    }

    /// See [`volume_curves`].
    pub fn volume_curves(&self, samples: usize) -> Result<Vec<f32>, String> {
        volume_curves(&self.rig, &self.skin, samples)
    }
}

/// See [`CylinderFigure::area_curves`]. Skins only the elbow ring.
pub fn area_curves(
    rig: &CylinderRig,
    skin: &SkinWeights,
    samples: usize,
) -> Result<Vec<f32>, String> {
    super::check_samples(samples)?;
    let s = rig.ring_start(rig.elbow_ring());
    let e = s + rig.around;
    let ring_skin = SkinWeights::new(
        skin.joints()[s..e].to_vec(),
        skin.weights()[s..e].to_vec(),
        rig.skeleton.len(),
    )
    .map_err(|e| e.to_string())?;
    let positions = &rig.mesh.positions[s..e];
    let normals = &rig.mesh.normals[s..e];
    let n = rig.skeleton.len();
    let (mut model, mut k, mut dq) = (
        vec![Affine3A::IDENTITY; n],
        vec![Affine3A::IDENTITY; n],
        vec![DualQuat::IDENTITY; n],
    );
    let (mut p, mut nn) = (vec![Vec3::ZERO; rig.around], vec![Vec3::ZERO; rig.around]);
    let rest = rig.rest_ring_area();
    let mut out = Vec::with_capacity(samples * 5);
    for i in 0..samples {
        let deg = 180.0 * i as f32 / (samples - 1) as f32;
        out.push(deg);
        for (bend, twist) in [(deg, 0.0), (0.0, deg)] {
            rig.palette(
                bend.to_radians(),
                f32::to_radians(twist),
                &mut model,
                &mut k,
            )
            .map_err(|e| e.to_string())?;
            dual_quat_palette(&k, &mut dq).map_err(|e| e.to_string())?;
            skin_lbs(&k, &ring_skin, positions, normals, &mut p, &mut nn)
                .map_err(|e| e.to_string())?;
            let a_lbs = ring_area(&p) / rest;
            skin_dqs(&dq, &ring_skin, positions, normals, &mut p, &mut nn)
                .map_err(|e| e.to_string())?;
            let a_dqs = ring_area(&p) / rest;
            out.push(a_lbs);
            out.push(a_dqs);
        }
    }
    // Each row: [deg, lbs bend, dqs bend, lbs twist, dqs twist].
    Ok(out)
}

/// The whole tube's volume (fraction of rest) against the bend angle, 0 to 180°: `[angle (°),
/// LBS, DQS]` per sample, at these weights. Unlike the elbow ring, the volume depends on the
/// falloff: a wide blend zone spreads LBS's loss along the arm.
pub fn volume_curves(
    rig: &CylinderRig,
    skin: &SkinWeights,
    samples: usize,
) -> Result<Vec<f32>, String> {
    super::check_samples(samples)?;
    let m = &rig.mesh;
    let n = rig.skeleton.len();
    let v = m.positions.len();
    let (mut model, mut k, mut dq) = (
        vec![Affine3A::IDENTITY; n],
        vec![Affine3A::IDENTITY; n],
        vec![DualQuat::IDENTITY; n],
    );
    let (mut p, mut nn) = (vec![Vec3::ZERO; v], vec![Vec3::ZERO; v]);
    let rest = mesh_volume(&m.positions, &m.indices);
    let mut out = Vec::with_capacity(samples * 3);
    for i in 0..samples {
        let deg = 180.0 * i as f32 / (samples - 1) as f32;
        rig.palette(deg.to_radians(), 0.0, &mut model, &mut k)
            .map_err(|e| e.to_string())?;
        dual_quat_palette(&k, &mut dq).map_err(|e| e.to_string())?;
        out.push(deg);
        skin_lbs(&k, skin, &m.positions, &m.normals, &mut p, &mut nn).map_err(|e| e.to_string())?;
        out.push(mesh_volume(&p, &m.indices) / rest);
        skin_dqs(&dq, skin, &m.positions, &m.normals, &mut p, &mut nn)
            .map_err(|e| e.to_string())?;
        out.push(mesh_volume(&p, &m.indices) / rest);
    }
    Ok(out)
}

/// Which skinning method the character figure uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Lbs,
    Dqs,
}

/// The character's falloff slider, metres: from nearly rigid parts (a crease at each joint) to
/// blend zones that reach along the whole part. Past about 0.06 m every vertex already mixes its
/// part's joints nearly evenly, so a longer range would only add slider travel that changes
/// little (up to 0.2 m, the last three quarters of its travel would barely show).
pub const HUMAN_FALLOFF_RANGE: [f32; 2] = [0.005, 0.06];

/// The built-in human with a skinned body, playing one of its clips.
#[derive(Clone, Debug)]
pub struct HumanFigure {
    character: SkinnedCharacter,
    clips: Vec<Clip>,
    clip: usize,
    method: Method,
    falloff: f32,
    heat_joint: Option<usize>,
    show_skeleton: bool,
    cursor: ClipCursor,
    pose: Pose,
    model: Vec<Affine3A>,
    palette: Vec<Affine3A>,
    dual_quats: Vec<DualQuat>,
    pub mesh: SkinnedMesh,
    /// Skin in the vertex shader ([`HumanFigure::draw_gpu`]) instead of on the CPU.
    gpu: bool,
    /// The weights or colours changed since the GPU copy was made.
    gpu_dirty: bool,
    /// LBS and DQS side by side ([`HumanFigure::draw_pair`]) instead of `method` alone: then
    /// `mesh` holds the LBS body and `mesh_dqs` the DQS one.
    compare: bool,
    pub mesh_dqs: SkinnedMesh,
    /// The camera keeps the whole bodies in view, or only the left legs ([`HumanView`]).
    view: HumanView,
    /// [`HumanFigure::view_box`] for the current clip, weights and view (`None`: not made yet).
    view_box: Option<(Vec3, Vec3)>,
    /// The left thigh's and shin's parts (their closed ellipsoids): the leg whose volume the
    /// note and the plot give.
    leg: [usize; 2],
    /// The clip time the bodies were last skinned at, `None` after a change of anything the
    /// skinning depends on: [`HumanFigure::skin`] at that same time again has nothing to do (a
    /// paused page would otherwise skin both bodies and upload them every frame).
    skinned_at: Option<f32>,
    /// The last frame's camera and canvas size (CSS pixels), which the heat map's joint name is
    /// placed for ([`HumanFigure::set_canvas_view`]).
    canvas_view: Option<(OrbitCamera, Vec2)>,
}

/// What the character figure keeps in view ([`HumanFigure::view_box`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HumanView {
    /// Both whole bodies.
    Body,
    /// Both left legs: the thigh and shin parts, the leg whose volume the plot gives.
    Legs,
}

/// How many times over the clip [`HumanFigure::view_box`] skins the bodies, and how far it
/// widens the box they fill (metres): the box holds them between those times too.
const VIEW_SAMPLES: usize = 33;
const VIEW_MARGIN_M: f32 = 0.03;

/// How far each of the two bodies stands from the middle, metres: along the camera's right
/// (LBS on the left, DQS on the right), so that they stand apart across the view from any
/// orbit; without a view along z (seen from the side, +x, both knees show in profile): LBS at
/// +z, DQS at −z.
pub const HUMAN_OFFSET_Z: f32 = 0.5;

impl Default for HumanFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl HumanFigure {
    /// The walk, by DQS, falloff 0.03 m.
    pub fn new() -> Self {
        let falloff = 0.03;
        let character = skinned_human(falloff).valid("the built-in human skins");
        let skeleton = &character.skeleton;
        let clips = (0..human::CLIP_NAMES.len())
            .map(|i| {
                let raw = human::clip(skeleton, i).expect("a built-in clip");
                Clip::from_raw(&raw, skeleton).valid("the built-in clips build")
            })
            .collect();
        let n = skeleton.len();
        let v = character.mesh.positions.len();
        let mut figure = Self {
            clips,
            clip: 1,
            method: Method::Dqs,
            falloff,
            heat_joint: None,
            show_skeleton: false,
            cursor: ClipCursor::new(),
            pose: skeleton.rest_pose(),
            model: vec![Affine3A::IDENTITY; n],
            palette: vec![Affine3A::IDENTITY; n],
            dual_quats: vec![DualQuat::IDENTITY; n],
            mesh: SkinnedMesh::new(v),
            mesh_dqs: SkinnedMesh::new(v),
            leg: ["thigh.L", "shin.L"]
                .map(|name| skeleton.find(name).expect("a joint of the human")),
            character,
            gpu: false,
            gpu_dirty: true,
            compare: false,
            view: HumanView::Body,
            view_box: None,
            skinned_at: None,
            canvas_view: None,
        };
        figure.repaint();
        figure
    }

    /// LBS and DQS side by side (`true`) or the one `method` names.
    pub fn set_compare(&mut self, on: bool) {
        self.compare = on;
        self.skinned_at = None;
        self.mesh.dirty = true;
        self.mesh_dqs.dirty = true;
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the heat map's joint name is placed for.
    pub fn set_canvas_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.canvas_view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// "whole body" or "left legs": what the camera keeps in view ([`HumanFigure::view_box`]).
    pub fn set_view(&mut self, name: &str) -> Result<(), String> {
        self.view = match name {
            "whole body" => HumanView::Body,
            "left legs" => HumanView::Legs,
            _ => {
                return Err(format!(
                    "view: expected \"whole body\" or \"left legs\", got {name:?}"
                ))
            }
        };
        self.view_box = None;
        Ok(())
    }

    /// The box the side-by-side figure keeps in view round each body (in the body's own
    /// coordinates, before its place): every vertex of the body (whole body), or of the left
    /// leg's thigh and shin parts and of the heat map's joint's part (left legs), skinned by LBS
    /// and by DQS at [`VIEW_SAMPLES`] times over the clip, widened by [`VIEW_MARGIN_M`]. It
    /// holds either body wherever the clip takes it, so the camera stays put while the clip
    /// plays.
    pub fn view_box(&mut self) -> Result<(Vec3, Vec3), String> {
        if let Some(b) = self.view_box {
            return Ok(b);
        }
        let c = &self.character;
        let m = &c.mesh;
        let vertices: Vec<usize> = match self.view {
            HumanView::Body => (0..m.positions.len()).collect(),
            // The legs, and the part of the joint whose weights the heat map shows (the pelvis
            // or the spine above them would otherwise run off the canvas's top).
            HumanView::Legs => {
                let per_part = m.indices.len() / c.skeleton.len();
                self.leg
                    .iter()
                    .chain(self.heat_joint.as_ref())
                    .flat_map(|&j| m.indices[j * per_part..(j + 1) * per_part].iter())
                    .map(|&i| i as usize)
                    .collect()
            }
        };
        let clip = &self.clips[self.clip];
        let n = c.skeleton.len();
        let mut pose = c.skeleton.rest_pose();
        let (mut model, mut k, mut dq) = (
            vec![Affine3A::IDENTITY; n],
            vec![Affine3A::IDENTITY; n],
            vec![DualQuat::IDENTITY; n],
        );
        let v = m.positions.len();
        let (mut p, mut nn) = (vec![Vec3::ZERO; v], vec![Vec3::ZERO; v]);
        let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
        for i in 0..VIEW_SAMPLES {
            let t = clip.duration_sec() * i as f32 / (VIEW_SAMPLES - 1) as f32;
            clip.sample(t, &mut ClipCursor::new(), &mut pose);
            c.skeleton
                .model_matrices(&pose, &mut model)
                .map_err(|e| e.to_string())?;
            skinning_palette(&model, c.skeleton.inverse_bind(), &mut k)
                .map_err(|e| e.to_string())?;
            dual_quat_palette(&k, &mut dq).map_err(|e| e.to_string())?;
            for method in 0..2 {
                if method == 0 {
                    skin_lbs(&k, &c.skin, &m.positions, &m.normals, &mut p, &mut nn)
                } else {
                    skin_dqs(&dq, &c.skin, &m.positions, &m.normals, &mut p, &mut nn)
                }
                .map_err(|e| e.to_string())?;
                for &i in &vertices {
                    lo = lo.min(p[i]);
                    hi = hi.max(p[i]);
                }
            }
        }
        let b = (
            lo - Vec3::splat(VIEW_MARGIN_M),
            hi + Vec3::splat(VIEW_MARGIN_M),
        );
        self.view_box = Some(b);
        Ok(b)
    }

    /// The left leg's volume (thigh and shin parts) in `positions`, as a fraction of its rest
    /// volume.
    pub fn leg_volume(&self, positions: &[Vec3]) -> f32 {
        let c = &self.character;
        let per_part = c.mesh.indices.len() / c.skeleton.len();
        let volume = |p: &[Vec3]| -> f32 {
            self.leg
                .iter()
                .map(|&j| {
                    c.mesh
                        .indices
                        .get(j * per_part..(j + 1) * per_part)
                        .map_or(f32::NAN, |part| mesh_volume(p, part))
                })
                .sum()
        };
        volume(positions) / volume(&c.mesh.positions)
    }

    /// The left leg's volume (fraction of rest) over one cycle of the clip, both methods:
    /// `[time (s), LBS, DQS]` per sample, the last at the clip's end.
    pub fn leg_volume_curves(&self, samples: usize) -> Result<Vec<f32>, String> {
        super::check_samples(samples)?;
        let c = &self.character;
        let clip = &self.clips[self.clip];
        let n = c.skeleton.len();
        let v = c.mesh.positions.len();
        let mut pose = c.skeleton.rest_pose();
        let (mut model, mut k, mut dq) = (
            vec![Affine3A::IDENTITY; n],
            vec![Affine3A::IDENTITY; n],
            vec![DualQuat::IDENTITY; n],
        );
        let (mut p, mut nn) = (vec![Vec3::ZERO; v], vec![Vec3::ZERO; v]);
        let m = &c.mesh;
        let mut out = Vec::with_capacity(3 * samples);
        for i in 0..samples {
            let t = clip.duration_sec() * i as f32 / (samples - 1) as f32;
            clip.sample(t, &mut ClipCursor::new(), &mut pose);
            c.skeleton
                .model_matrices(&pose, &mut model)
                .map_err(|e| e.to_string())?;
            skinning_palette(&model, c.skeleton.inverse_bind(), &mut k)
                .map_err(|e| e.to_string())?;
            dual_quat_palette(&k, &mut dq).map_err(|e| e.to_string())?;
            out.push(t);
            skin_lbs(&k, &c.skin, &m.positions, &m.normals, &mut p, &mut nn)
                .map_err(|e| e.to_string())?;
            out.push(self.leg_volume(&p));
            skin_dqs(&dq, &c.skin, &m.positions, &m.normals, &mut p, &mut nn)
                .map_err(|e| e.to_string())?;
            out.push(self.leg_volume(&p));
        }
        Ok(out)
    }

    /// The step from the LBS body to the DQS body: [`HUMAN_OFFSET_Z`] twice along the last
    /// frame's camera's right (its yaw alone), or along −z without a view.
    fn pair_step(&self) -> Vec3 {
        let right = self.canvas_view.map_or(Vec3::NEG_Z, |(c, _)| screen_axes(&c).0);
        2.0 * HUMAN_OFFSET_Z * right
    }

    /// Draws the LBS and the DQS body side by side (`meshes`: their GPU ids) after
    /// [`HumanFigure::skin`] in compare mode; returns the note.
    pub fn draw_pair(&mut self, frame: &mut Frame, meshes: [MeshId; 2]) -> String {
        frame.grid(12, 0.25);
        let view_box = self.view_box().ok();
        let drawn = self.draw_both(frame, view_box, |f, k| {
            f.mesh_vertex_colors(meshes[k], Mat4::IDENTITY);
            Ok(())
        });
        debug_assert!(drawn.is_ok(), "drawing a CPU mesh cannot fail");
        self.overlay(frame, "on the CPU")
    }

    /// The character, built in code here; any other [`SkinnedCharacter`] can be shown through
    /// [`HumanFigure::with_character`].
    pub fn character(&self) -> &SkinnedCharacter {
        &self.character
    }

    /// The hook for characters loaded from files: same figure, another skeleton and mesh. The
    /// clips must animate this skeleton (same joint count).
    pub fn with_character(character: SkinnedCharacter, clips: Vec<Clip>) -> Result<Self, String> {
        if clips.is_empty()
            || clips
                .iter()
                .any(|c| c.joint_count() != character.skeleton.len())
        {
            return Err("clips: at least one, each animating every joint of the character".into());
        }
        let mut f = Self::new();
        let n = character.skeleton.len();
        f.pose = character.skeleton.rest_pose();
        f.model = vec![Affine3A::IDENTITY; n];
        f.palette = vec![Affine3A::IDENTITY; n];
        f.dual_quats = vec![DualQuat::IDENTITY; n];
        f.mesh = SkinnedMesh::new(character.mesh.positions.len());
        f.mesh_dqs = SkinnedMesh::new(character.mesh.positions.len());
        f.compare = false;
        f.character = character;
        f.clips = clips;
        f.clip = 0;
        f.heat_joint = None;
        f.skinned_at = None;
        f.repaint();
        Ok(f)
    }

    pub fn clip_names(&self) -> Vec<String> {
        self.clips.iter().map(|c| c.name().to_string()).collect()
    }

    pub fn set_clip(&mut self, name: &str) -> Result<(), String> {
        self.clip = self
            .clips
            .iter()
            .position(|c| c.name() == name)
            .ok_or_else(|| format!("clip: no clip named {name:?}"))?;
        self.cursor = ClipCursor::new();
        self.view_box = None;
        self.skinned_at = None;
        Ok(())
    }

    pub fn duration_sec(&self) -> f32 {
        self.clips[self.clip].duration_sec()
    }

    /// "LBS" or "DQS".
    pub fn set_method(&mut self, name: &str) -> Result<(), String> {
        self.method = match name {
            "LBS" => Method::Lbs,
            "DQS" => Method::Dqs,
            _ => return Err(format!("method: expected \"LBS\" or \"DQS\", got {name:?}")),
        };
        self.skinned_at = None;
        Ok(())
    }

    /// Falloff of the automatic weights, metres in [`HUMAN_FALLOFF_RANGE`].
    pub fn set_falloff(&mut self, falloff: f32) -> Result<(), String> {
        let [lo, hi] = HUMAN_FALLOFF_RANGE;
        let f = in_range("falloff", falloff, lo, hi)?;
        let c = skinned_human(f).map_err(|e| e.to_string())?;
        self.character.skin = c.skin;
        self.falloff = f;
        self.view_box = None;
        self.skinned_at = None;
        self.repaint();
        Ok(())
    }

    pub fn joint_names(&self) -> Vec<String> {
        self.character.skeleton.names().to_vec()
    }

    /// "none" or a joint's name: colour the body by that joint's weights.
    /// In the legs view the camera keeps that joint's part in view too
    /// ([`HumanFigure::view_box`]).
    pub fn set_heat_joint(&mut self, name: &str) -> Result<(), String> {
        self.heat_joint = parse_heat(self.character.skeleton.names(), name)?;
        self.repaint();
        self.view_box = None;
        Ok(())
    }

    pub fn set_show_skeleton(&mut self, on: bool) {
        self.show_skeleton = on;
    }

    fn repaint(&mut self) {
        let c = &self.character;
        paint(&mut self.mesh.colors, &c.skin, self.heat_joint, &c.colors);
        self.mesh_dqs.colors.clone_from(&self.mesh.colors);
        self.mesh.dirty = true;
        self.mesh_dqs.dirty = true;
        self.gpu_dirty = true;
    }

    /// Skin on the GPU (in the vertex shader) or on the CPU.
    pub fn set_gpu(&mut self, on: bool) {
        self.gpu = on;
        self.skinned_at = None;
        self.mesh.dirty = true;
    }

    pub fn gpu(&self) -> bool {
        self.gpu
    }

    /// True once after the weights or the colours changed: upload them to the GPU-skinned mesh.
    pub fn take_gpu_dirty(&mut self) -> bool {
        std::mem::take(&mut self.gpu_dirty)
    }

    /// Samples the clip at `time_sec` and skins the body. Returns false, doing nothing, when
    /// the body is already skinned at this time with these settings.
    pub fn skin(&mut self, time_sec: f32) -> Result<bool, String> {
        let t = super::finite("time", time_sec)?;
        if self.skinned_at == Some(t) {
            return Ok(false);
        }
        self.skin_now(t)?;
        self.skinned_at = Some(t);
        Ok(true)
    }

    fn skin_now(&mut self, t: f32) -> Result<(), String> {
        let c = &self.character;
        self.clips[self.clip].sample(t, &mut self.cursor, &mut self.pose);
        c.skeleton
            .model_matrices(&self.pose, &mut self.model)
            .map_err(|e| e.to_string())?;
        skinning_palette(&self.model, c.skeleton.inverse_bind(), &mut self.palette)
            .map_err(|e| e.to_string())?;
        if self.gpu {
            // The vertex shader skins: only the palette is computed here.
            if self.method == Method::Dqs || self.compare {
                dual_quat_palette(&self.palette, &mut self.dual_quats)
                    .map_err(|e| e.to_string())?;
            }
            return Ok(());
        }
        let m = &c.mesh;
        if self.compare {
            skin_lbs(
                &self.palette,
                &c.skin,
                &m.positions,
                &m.normals,
                &mut self.mesh.positions,
                &mut self.mesh.normals,
            )
            .and_then(|()| dual_quat_palette(&self.palette, &mut self.dual_quats))
            .and_then(|()| {
                skin_dqs(
                    &self.dual_quats,
                    &c.skin,
                    &m.positions,
                    &m.normals,
                    &mut self.mesh_dqs.positions,
                    &mut self.mesh_dqs.normals,
                )
            })
            .map_err(|e| e.to_string())?;
            self.mesh.dirty = true;
            self.mesh_dqs.dirty = true;
            return Ok(());
        }
        match self.method {
            Method::Lbs => skin_lbs(
                &self.palette,
                &c.skin,
                &m.positions,
                &m.normals,
                &mut self.mesh.positions,
                &mut self.mesh.normals,
            ),
            Method::Dqs => dual_quat_palette(&self.palette, &mut self.dual_quats).and_then(|()| {
                skin_dqs(
                    &self.dual_quats,
                    &c.skin,
                    &m.positions,
                    &m.normals,
                    &mut self.mesh.positions,
                    &mut self.mesh.normals,
                )
            }),
        }
        .map_err(|e| e.to_string())?;
        self.mesh.dirty = true;
        Ok(())
    }

    /// Draws the skinned body (`mesh`: its GPU id) after [`HumanFigure::skin`]; returns the note.
    pub fn draw(&mut self, frame: &mut Frame, mesh: MeshId) -> String {
        frame.grid(12, 0.25);
        frame.mesh_vertex_colors(mesh, Mat4::IDENTITY);
        self.overlay(frame, "on the CPU")
    }

    /// Draws the body skinned in the vertex shader (`mesh`: made from [`HumanFigure::character`]'s
    /// mesh, weights and [`HumanFigure::mesh`]'s colours) after [`HumanFigure::skin`] with GPU
    /// skinning on; returns the note.
    pub fn draw_gpu(
        &mut self,
        frame: &mut Frame,
        mesh: crate::draw::SkinMeshId,
    ) -> Result<String, String> {
        frame.grid(12, 0.25);
        if self.compare {
            let view_box = self.view_box().ok();
            self.draw_both(frame, view_box, |f, k| match k {
                0 => super::gpu::draw_skinned_lbs(f, mesh, Mat4::IDENTITY, None, &self.palette),
                _ => super::gpu::draw_skinned_dqs(f, mesh, Mat4::IDENTITY, None, &self.dual_quats),
            })?;
            return Ok(self.overlay(frame, "on the GPU (vertex shader)"));
        }
        match self.method {
            Method::Lbs => {
                super::gpu::draw_skinned_lbs(frame, mesh, Mat4::IDENTITY, None, &self.palette)
            }
            Method::Dqs => {
                super::gpu::draw_skinned_dqs(frame, mesh, Mat4::IDENTITY, None, &self.dual_quats)
            }
        }?;
        Ok(self.overlay(frame, "on the GPU (vertex shader)"))
    }

    /// What goes with each body, in its own coordinates: the X-rayed skeleton.
    fn decorate(&self, frame: &mut Frame) {
        let at = |m: &Affine3A| Vec3::from(m.translation);
        if self.show_skeleton {
            // The skeleton is inside the body: drawn over it, as an X-ray.
            let parents = self.character.skeleton.parents();
            for (i, m) in self.model.iter().enumerate() {
                let p = at(m);
                frame.marker_on_top(p, JOINT_PX, palette::DARK);
                if parents[i] >= 0 {
                    let q = at(&self.model[parents[i] as usize]);
                    frame.wide_line_on_top(q, p, palette::DARK, BONE_PX);
                }
            }
        }
    }

    /// Points on the canvas (the last frame's view) that stand for the bodies placed at
    /// `places`: every vertex, moved rigidly with its part's joint (the palette; the
    /// blend zones move a few centimetres more), so that skinning on the GPU has them too.
    fn body_points_px(&self, places: &[Vec3]) -> Vec<Vec2> {
        let Some((view_proj, size)) = view_of(self.canvas_view) else {
            return Vec::new();
        };
        let bind = &self.character.mesh.positions;
        let per_part = bind.len() / self.palette.len();
        let mut out = Vec::new();
        for place in places {
            for v in 0..bind.len() {
                let p = *place + self.palette[v / per_part].transform_point3(bind[v]);
                out.extend(project_to_canvas(view_proj, size, p));
            }
        }
        out
    }

    /// Adds the first of `candidates` that covers none of `body_px` ([`HumanFigure::body_points_px`])
    /// and no dot, bone or name placed before, on the last frame's view. A name keeps 6 px off
    /// those points: they move rigidly with their parts, and a blend zone's skinned vertices lie
    /// a few pixels beside them on the 760 x 420 canvas.
    fn label_off_bodies(&self, frame: &mut Frame, body_px: &[Vec2], candidates: Vec<Label>) {
        let view = view_of(self.canvas_view);
        frame.first_clear_label_by(view, 2.0, candidates, off_points(body_px, 6.0));
    }

    /// The labels of the bodies placed at `places` (after they are drawn): each title (the
    /// labels from `titles_from` on) where it was put, else at the first place round it clear
    /// of the bodies; then the heat map's joint name, anchored at the joint of each body, at the
    /// first place round it, away from the other body first. The page draws a leader line to
    /// a name placed away from its joint.
    fn place_labels(&self, frame: &mut Frame, places: &[Vec3], titles_from: usize) {
        let body_px = self.body_points_px(places);
        let view = view_of(self.canvas_view);
        let at = |p: Vec3| view.and_then(|(m, size)| project_to_canvas(m, size, p));
        let toward = |k: usize| {
            let other = places[places.len() - 1 - k];
            at(places[k]).zip(at(other)).map_or(Vec2::X, |(a, b)| a - b)
        };
        let titles: Vec<Label> = frame.labels.drain(titles_from..).collect();
        for (k, title) in titles.into_iter().enumerate() {
            let mut candidates = Label::around_dot(
                title.anchor,
                0.0,
                toward(k),
                &title.text,
                title.color,
                1,
                8,
                10.0,
            );
            candidates.insert(0, title);
            self.label_off_bodies(frame, &body_px, candidates);
        }
        let Some(j) = self.heat_joint else { return };
        let name = &self.character.skeleton.names()[j];
        for (k, place) in places.iter().enumerate() {
            let anchor = *place + Vec3::from(self.model[j].translation);
            let candidates =
                Label::around_dot(anchor, JOINT_PX, toward(k), name, palette::RED, 0, 20, 10.0);
            self.label_off_bodies(frame, &body_px, candidates);
        }
    }

    /// Compare mode: the LBS body (`k = 0`) and the DQS body (`k = 1`) side by side across the view
    /// ([`HumanFigure::pair_step`]), each
    /// drawn by `body(frame, k)` in its own coordinates with its decorations, title and contact
    /// shadow; the camera keeps `view_box` (see [`HumanFigure::view_box`]) in view.
    fn draw_both(
        &self,
        frame: &mut Frame,
        view_box: Option<(Vec3, Vec3)>,
        mut body: impl FnMut(&mut Frame, usize) -> Result<(), String>,
    ) -> Result<(), String> {
        // Titles over the heads, or under the feet in the legs view (over the hips they would
        // sit on the bodies); the camera fits them too.
        let title_y = match (self.view, view_box) {
            (HumanView::Legs, Some((lo, _))) => lo.y - 0.15,
            _ => 2.0,
        };
        let titles = [("LBS", palette::ORANGE), ("DQS", palette::TEAL)];
        let step = self.pair_step();
        let mut failed = Ok(());
        let titles_from = frame.labels.len();
        frame.side_by_side(step, &titles, title_y, |f, k| {
            if let Err(e) = body(f, k) {
                failed = Err(e);
            }
            self.decorate(f);
            f.contact_shadow(Vec3::ZERO, 0.3);
        });
        let places = [-0.5 * step, 0.5 * step];
        self.place_labels(frame, &places, titles_from);
        // The box round each body, or one that holds a body standing (only if skinning the
        // clip failed).
        let (lo, hi) = view_box.unwrap_or((Vec3::new(-0.5, 0.0, -0.5), Vec3::new(0.5, 2.0, 0.5)));
        for place in places {
            frame.keep_box_in_view(place + lo, place + hi);
        }
        failed
    }

    /// The note (and, for one body alone, its decorations).
    fn overlay(&mut self, frame: &mut Frame, where_: &str) -> String {
        let names = self.character.skeleton.names();
        if !self.compare {
            self.decorate(frame);
            self.place_labels(frame, &[Vec3::ZERO], frame.labels.len());
        }
        let colours = match self.heat_joint {
            Some(j) => format!(" Colours: the weights of {}, blue 0 to red 1.", names[j]),
            // The falloff changes the weights; the shapes move only a few centimetres, mostly
            // inside the neighbouring parts, so the heat map is where it shows.
            None => {
                " Pick a joint under weights of to see the blend zones the falloff sets.".into()
            }
        };
        let method = if self.compare {
            "linear blend skinning (LBS, left) and dual quaternion skinning (DQS, right)"
        } else {
            match self.method {
                Method::Lbs => "linear blend skinning",
                Method::Dqs => "dual quaternion skinning",
            }
        };
        let mut note = format!(
            "{} vertices, {} joints ({} vertices follow two or more at falloff {} m), skinned by {method} {where_} ({} clip).{colours}",
            self.character.mesh.positions.len(),
            self.character.skeleton.len(),
            blended(&self.character.skin),
            format_number(self.falloff),
            self.clips[self.clip].name()
        );
        if self.compare && !self.gpu {
            note += &format!(
                " Left leg (thigh and shin) now: LBS keeps {:.1}% of its volume, DQS {:.1}%.",
                100.0 * self.leg_volume(&self.mesh.positions),
                100.0 * self.leg_volume(&self.mesh_dqs.positions)
            );
        }
        note
    }
}

/// The note comparing the student's skinned vertices with the reference's: all match, or the
/// vertex that differs most (a NaN counts as the worst).
fn vertices_note(what: &str, at: &str, student: &[Vec3], reference: &[Vec3]) -> String {
    let mut worst: Option<(usize, f32)> = None;
    for (v, (s, r)) in student.iter().zip(reference).enumerate() {
        let e = (*s - *r).length();
        let e = if e.is_nan() { f32::INFINITY } else { e };
        if e > TOLERANCE && worst.is_none_or(|(_, w)| e > w) {
            worst = Some((v, e));
        }
    }
    match worst {
        None => format!(
            "Your {what} matches the reference at all {} vertices ({at}).",
            student.len()
        ),
        Some((v, _)) => {
            compare_note(
                what,
                &format!("vertex {v} ({at})"),
                &student[v].to_array(),
                &reference[v].to_array(),
                TOLERANCE,
            )
            .1
        }
    }
}

/// Where the sign figure draws the quaternion circle: its centre and radius (metres).
pub const SIGN_CIRCLE_CENTER: Vec3 = Vec3::new(2.3, 0.9, 0.0);
pub const SIGN_CIRCLE_RADIUS: f32 = 0.75;

/// The antipodality fix on its own: the cylinder twisted at the elbow by 0 to 360° and skinned
/// by DQS with or without the sign flip, beside the circle on which the shoulder's and the
/// elbow's rotation quaternions lie.
///
/// A twist by θ about the bone's axis `x` is the quaternion `r = cos(θ/2) + sin(θ/2) i`, and
/// the shoulder's is `1`: both lie on the unit circle of the plane spanned by `1` and `i`, a
/// great circle of the 4D sphere, where `r` sits at the angle θ/2 from `1`. Past θ = 180° that
/// angle passes 90°, `r · 1 = cos(θ/2)` turns negative, and the unflipped blend at ½ and ½ sits
/// at θ/4 (half of θ: the long way round) while the flipped one sits at θ/4 − 90° (half of
/// θ − 360°: the short way).
#[derive(Clone, Debug)]
pub struct SignFigure {
    rig: CylinderRig,
    skin: SkinWeights,
    twist_rad: f32,
    fix: bool,
    model: Vec<Affine3A>,
    palette: Vec<Affine3A>,
    dual_quats: Vec<DualQuat>,
    pub mesh: SkinnedMesh,
    stale: bool,
    /// Whether some vertex's unflipped blend cancelled (real part under 1e-6) and fell back to
    /// the identity: at 360° the elbow's `r = −1` and the shoulder's `1` cancel at ½ and ½.
    cancelled: bool,
    /// The last frame's camera and canvas size (CSS pixels): the circle faces that camera and
    /// its labels are placed for it ([`SignFigure::set_view`]).
    view: Option<(OrbitCamera, Vec2)>,
}

impl Default for SignFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl SignFigure {
    /// Twisted 300°, fix on.
    pub fn new() -> Self {
        let rig = cylinder_rig(1.0, 0.25, CYLINDER_RINGS, CYLINDER_AROUND)
            .valid("the lesson's cylinder is valid");
        let skin = rig.weights(0.15).valid("a valid falloff");
        let n = rig.mesh.positions.len();
        let j = rig.skeleton.len();
        let mut mesh = SkinnedMesh::new(n);
        mesh.colors.fill(palette::TEAL.extend(1.0));
        Self {
            skin,
            twist_rad: 300f32.to_radians(),
            fix: true,
            model: vec![Affine3A::IDENTITY; j],
            palette: vec![Affine3A::IDENTITY; j],
            dual_quats: vec![DualQuat::IDENTITY; j],
            mesh,
            stale: true,
            cancelled: false,
            view: None,
            rig,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the circle turns to face and its labels are placed for.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    pub fn rig(&self) -> &CylinderRig {
        &self.rig
    }

    /// Elbow twist about its bone, degrees in [0, 360].
    pub fn set_twist_deg(&mut self, deg: f32) -> Result<(), String> {
        self.twist_rad = in_range("twist", deg, 0.0, 360.0)?.to_radians();
        self.stale = true;
        Ok(())
    }

    /// The antipodality fix on (flip each quaternion onto the pivot's hemisphere) or off.
    pub fn set_fix(&mut self, on: bool) {
        self.fix = on;
        self.stale = true;
    }

    /// The elbow's rotation quaternion as the twist gives it, `cos(θ/2) + sin(θ/2) i`: past
    /// 180° on the far hemisphere from the shoulder's `1`.
    pub fn elbow_rotation(&self) -> glam::Quat {
        glam::Quat::from_rotation_x(self.twist_rad)
    }

    /// Skins the tube if a control changed.
    pub fn update(&mut self) -> Result<(), String> {
        if !self.stale {
            return Ok(());
        }
        self.stale = false;
        self.rig
            .palette(0.0, self.twist_rad, &mut self.model, &mut self.palette)
            .map_err(|e| e.to_string())?;
        dual_quat_palette(&self.palette, &mut self.dual_quats).map_err(|e| e.to_string())?;
        // A palette's dual quaternions may come with either sign; this figure gives each joint
        // the sign of its rotation cos(θ/2) + sin(θ/2) i, as an animation's keys might.
        let r = self.elbow_rotation();
        for q in &mut self.dual_quats[1..] {
            if q.real.dot(r) < 0.0 {
                *q = *q * -1.0;
            }
        }
        let m = &self.rig.mesh;
        self.cancelled = false;
        for (v, out) in self.mesh.positions.iter_mut().enumerate() {
            let joints = self.skin.joints()[v];
            let weights = self.skin.weights()[v];
            let qs: Vec<DualQuat> = joints
                .iter()
                .map(|&j| self.dual_quats[j as usize])
                .collect();
            let blend = if self.fix {
                crate::skinning::blend_dual_quats(&qs, &weights)
            } else {
                blend_without_fix(&qs, &weights).unwrap_or_else(|| {
                    self.cancelled = true;
                    DualQuat::IDENTITY
                })
            };
            *out = blend.transform_point(m.positions[v]);
            self.mesh.normals[v] = blend.transform_direction(m.normals[v]);
        }
        self.mesh.dirty = true;
        Ok(())
    }

    /// How far the elbow ring has turned about the bone, degrees in (−180, 180]: half the twist
    /// the short way with the fix, the long way round without it (past 180°).
    pub fn elbow_ring_turn_deg(&self) -> f32 {
        let s = self.rig.ring_start(self.rig.elbow_ring());
        let ring = &self.mesh.positions[s..s + self.rig.around];
        let c = ring.iter().sum::<Vec3>() / ring.len() as f32;
        let rest = self.rig.mesh.positions[s] - c;
        let now = ring[0] - c;
        // About +x: y turns towards z.
        let angle = now.z.atan2(now.y) - rest.z.atan2(rest.y);
        let deg = angle.to_degrees();
        if deg <= -180.0 {
            deg + 360.0
        } else if deg > 180.0 {
            deg - 360.0
        } else {
            deg
        }
    }

    /// The directions on screen of the circle's `1` and `i` axes, in world space: the last
    /// frame's camera's right and up (x and y before the first frame). The circle is a diagram
    /// of the 4D sphere, not an object in the scene: it faces the camera, so no orbit sees it
    /// edge-on.
    pub fn circle_axes(&self) -> (Vec3, Vec3) {
        self.view
            .map_or((Vec3::X, Vec3::Y), |(camera, _)| screen_axes(&camera))
    }

    /// Fills the draw list (`mesh`: the tube's GPU id) and returns the note.
    pub fn draw(&mut self, frame: &mut Frame, mesh: MeshId) -> Result<String, String> {
        self.update()?;
        frame.grid(12, 0.5);
        let offset = Vec3::new(-1.6, 0.9, 0.0);
        frame.mesh_vertex_colors(mesh, Mat4::from_translation(offset));
        // The two rows of vertices along the tube (on top and in front before skinning).
        for k in CylinderFigure::STRIPES {
            let stripe: Vec<Vec3> = (0..self.rig.rings)
                .map(|r| {
                    let s = self.rig.ring_start(r);
                    let ring = &self.mesh.positions[s..s + self.rig.around];
                    let c = ring.iter().sum::<Vec3>() / ring.len() as f32;
                    offset + c + (ring[k] - c) * 1.03
                })
                .collect();
            frame.wide_polyline(&stripe, palette::DARK, 2.0);
        }
        // The circle through 1 and i, the two joints' quaternions on it, −r, and the blend.
        let c = SIGN_CIRCLE_CENTER;
        let rr = SIGN_CIRCLE_RADIUS;
        let (right, up) = self.circle_axes();
        let on_circle = |a: f32| c + rr * (right * a.cos() + up * a.sin());
        let circle: Vec<Vec3> = (0..=96)
            .map(|k| on_circle(std::f32::consts::TAU * k as f32 / 96.0))
            .collect();
        frame.wide_polyline(&circle, palette::GREY, 2.0);
        // The w and x axes end at the circle, so the labels of the points on it read outwards
        // into empty space; the axes' own labels sit inside the circle, beside them (below).
        frame.wide_line(c - right * rr, c + right * rr, palette::GRID_AXIS, 1.5);
        frame.wide_line(c - up * rr, c + up * rr, palette::GRID_AXIS, 1.5);
        let half = 0.5 * self.twist_rad;
        let r = self.elbow_rotation();
        let far = r.w < 0.0;
        let blend_angle = if self.fix && far {
            0.5 * (half - std::f32::consts::PI)
        } else {
            0.5 * half
        };
        // The blend's arc from 1, under the points; a cancelled blend has no point and no arc.
        let blend_label = if self.cancelled { "" } else { "blend at ½, ½" };
        if !self.cancelled {
            let arc: Vec<Vec3> = (0..=24)
                .map(|k| on_circle(blend_angle * k as f32 / 24.0))
                .collect();
            frame.wide_polyline(&arc, palette::TEAL, 5.0);
        }
        // At a full turn −r is 1: one dot, named for both.
        let full = r.w < -0.999_999;
        let points = [
            (0.0, if full { "1 = −r (shoulder)" } else { "1 (shoulder)" }, palette::DARK, 12.0),
            (half, "r (elbow)", palette::ORANGE, 12.0),
            (blend_angle, blend_label, palette::TEAL, 12.0),
            (half + std::f32::consts::PI, if full { "" } else { "−r" }, palette::GREY, 9.0),
        ];
        for &(angle, _, color, size) in points.iter().rev().filter(|p| !p.1.is_empty()) {
            frame.marker(on_circle(angle), size, color);
        }
        // Each point's label outside the circle along its radius, at the first place round its
        // dot (on the last frame's view) that covers no dot, line or label placed before it:
        // where points meet (1, r and the blend near 0°; 1, −r and the blend near 360° with the
        // fix) the later ones step out of the way, most important first.
        let view = view_of(self.view);
        for &(angle, text, color, size) in points.iter().filter(|p| !p.1.is_empty()) {
            let toward = Vec2::new(angle.cos(), -angle.sin());
            let candidates =
                Label::around_dot(on_circle(angle), size, toward, text, color, 0, 8, 8.0);
            frame.first_clear_label_by(view, 2.0, candidates, |_| true);
        }
        for (at, toward, text) in [
            (c + right * (0.5 * rr), Vec2::Y, "w"),
            (c + up * (0.5 * rr), Vec2::X, "x (i)"),
        ] {
            let candidates = Label::around_dot(at, 0.0, toward, text, palette::GREY, 0, 3, 8.0);
            frame.first_clear_label_by(view, 2.0, candidates, |_| true);
        }
        // The tube, and room round the circle for the labels that read outwards from its sides.
        frame.keep_box_in_view(Vec3::new(-1.7, 0.5, -0.4), Vec3::new(0.5, 1.3, 0.4));
        frame.keep_in_view.extend([
            c - right * (rr + 1.15),
            c + right * (rr + 1.15),
            c - up * (rr + 0.15),
            c + up * (rr + 0.15),
        ]);
        let deg = self.twist_rad.to_degrees();
        let turn = self.elbow_ring_turn_deg();
        // A unit quaternion's component under 1e-6 is the rounding of sin or cos in f32 (sin 180°
        // is -8.7e-8): the note gives it as 0.
        let component = |v: f32| format_number(if v.abs() < 1e-6 { 0.0 } else { v });
        let mut note = format!(
            "Elbow twisted by {deg:.0}°: its quaternion r = ({}, {}, 0, 0) in (w, x, y, z), r · 1 = {}.",
            component(r.w),
            component(r.x),
            component(r.w)
        );
        note += &match (far, self.fix) {
            (false, _) => " Both on one hemisphere: the fix changes nothing.".to_string(),
            (true, true) => {
                " On the far hemisphere: the fix blends −r instead, the short way.".to_string()
            }
            (true, false) if self.cancelled => " Opposite 1, and not flipped: at ½ and ½ the two \
                cancel, the blend is zero and has nothing to normalise, so the code falls back to \
                no turn (no blend on the circle). Every other ring blends to ±1, no turn either: the \
                tube is untwisted, where a degree less turns the elbow ring almost half a turn."
                .to_string(),
            (true, false) => {
                " On the far hemisphere, and not flipped: the blend goes the long way round."
                    .to_string()
            }
        };
        note += &format!(" The elbow ring has turned {turn:.1}° about the bone.");
        Ok(note)
    }
}

/// The DQS blend without the antipodality fix: `Σ wₖ qₖ`, normalised; `None` when the real
/// part cancels (length under 1e-6), which leaves nothing to normalise.
fn blend_without_fix(dual_quats: &[DualQuat], weights: &[f32]) -> Option<DualQuat> {
    let (mut real, mut dual) = (Vec4::ZERO, Vec4::ZERO);
    for (q, &w) in dual_quats.iter().zip(weights) {
        real += Vec4::from(q.real) * w;
        dual += Vec4::from(q.dual) * w;
    }
    (real.length() >= 1e-6).then(|| {
        DualQuat {
            real: glam::Quat::from_vec4(real),
            dual: glam::Quat::from_vec4(dual),
        }
        .normalized()
    })
}
