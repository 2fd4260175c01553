//! Figure logic for lesson 10, "Blend shapes" (see [`crate::figures`]).
//!
//! [`FaceFigure`]: the procedural face with four targets and a weight per target, blended in the
//! differential form and in the full form side by side (or one of them alone). The full form also
//! weights the base, `1 − Σ wₖ` unless "base weight" is set by hand, so a wrong sum shows. The
//! weights can be animated over time; [`FaceFigure::weight_curves`] gives their plot. Exercise
//! 10.1 (the student's differential form) drives the differential head.

use super::{
    check_samples, compare_note, failure_note, finite, format_number, in_range, palette, Frame,
    MeshId, Runner, DEFAULT_RUNNER,
};
use crate::blend_shapes::{face, Face};
use crate::exercises::run;
use crate::figures::skinning::SkinnedMesh;
use glam::{Mat4, Vec3, Vec4};

const EXERCISE_FILE: &str = "src/exercises/blend_shapes.rs";
const TOLERANCE: f32 = 1e-4;
/// Length of the weight animation's loop (the lesson's timeline).
pub const LOOP_SECONDS: f32 = 4.0;
/// Where the head's centre is (the centre of a head shown alone).
const HEAD_CENTRE: Vec3 = Vec3::new(0.0, 1.2, 0.0);
/// How far any vertex of the head lies from its vertical axis, metres, at any weights the sliders
/// allow (a test checks it). Side by side the heads' centres stand this far apart, each radius
/// times its scale, so neither reaches into the other however they turn about y.
pub const HEAD_RADIUS: f32 = 1.1;
/// The camera's distance when the heads are at their rest size (the framing the figure starts
/// with); larger heads are framed farther away in proportion.
const VIEW_DISTANCE: f32 = 4.8;
/// The camera looks a little above the heads' centres.
const VIEW_LIFT: f32 = 0.1;

/// Which blend the figure shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Show {
    /// The differential form on the left, the full form on the right.
    Both,
    Differential,
    Full,
}

/// The face figure.
pub struct FaceFigure {
    face: Face,
    weights: [f32; 4],
    /// The full form's base weight; `None`: `1 − Σ wₖ` (so the weights sum to 1).
    base_weight: Option<f32>,
    show: Show,
    animate: bool,
    use_exercise: bool,
    runner: Runner,
    /// The face blended in the differential form (the student's, with the exercise on).
    pub differential: SkinnedMesh,
    /// The face blended in the full form.
    pub full: SkinnedMesh,
    exercise_note: String,
    /// The base and target weights the two heads' vertices were last blended with: a frame
    /// with the same weights (a paused timeline) reuses them, so nothing is uploaded and the
    /// renderer can keep the canvas's last image.
    blended: Option<[f32; 5]>,
}

impl Default for FaceFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl FaceFigure {
    /// Both forms side by side, the weights animated.
    pub fn new() -> Self {
        let face = face();
        let n = face.mesh.positions.len();
        let blank = || {
            let mut mesh = SkinnedMesh::default();
            mesh.positions = vec![Vec3::ZERO; n];
            mesh.normals = vec![Vec3::ZERO; n];
            mesh.colors = vec![Vec4::new(0.85, 0.62, 0.48, 1.0); n];
            mesh
        };
        Self {
            differential: blank(),
            full: blank(),
            face,
            weights: [1.0, 0.6, 0.8, 0.7],
            base_weight: None,
            show: Show::Both,
            animate: true,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            exercise_note: String::new(),
            blended: None,
        }
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    pub fn target_names(&self) -> Vec<String> {
        self.face.names.iter().map(|s| s.to_string()).collect()
    }

    pub fn indices(&self) -> &[u32] {
        &self.face.mesh.indices
    }

    /// Weight of target `k`, in [−0.5, 1.5] (beyond 1 exaggerates; below 0 inverts).
    pub fn set_weight(&mut self, k: usize, w: f32) -> Result<(), String> {
        let w = in_range("weight", w, -0.5, 1.5)?;
        let slot = self
            .weights
            .get_mut(k)
            .ok_or_else(|| format!("target index {k} is out of range (0 to 3)"))?;
        *slot = w;
        Ok(())
    }

    /// What to show: "both" (differential left, full right), "differential" or "full".
    pub fn set_show(&mut self, name: &str) -> Result<(), String> {
        self.show = match name {
            "both" => Show::Both,
            "full" => Show::Full,
            "differential" => Show::Differential,
            _ => {
                return Err(format!(
                    "show: expected \"both\", \"differential\" or \"full\", got {name:?}"
                ))
            }
        };
        Ok(())
    }

    pub fn show(&self) -> Show {
        self.show
    }

    /// The full form's base weight in [0, 1], or a negative number for "1 − Σ wₖ".
    pub fn set_base_weight(&mut self, w: f32) -> Result<(), String> {
        let w = finite("base weight", w)?;
        self.base_weight = if w < 0.0 {
            None
        } else {
            Some(in_range("base weight", w, 0.0, 1.0)?)
        };
        Ok(())
    }

    pub fn set_animate(&mut self, on: bool) {
        self.animate = on;
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// The weights at `time_sec`: the sliders', or (animating) each pulsing between 0 and its
    /// slider's value over the 4 s loop, a quarter of the loop apart.
    pub fn weights_at(&self, time_sec: f32) -> [f32; 4] {
        if !self.animate {
            return self.weights;
        }
        let wave = |phase: f32| {
            0.5 - 0.5 * (std::f32::consts::TAU * (time_sec / LOOP_SECONDS - phase)).cos()
        };
        let w = self.weights;
        [
            w[0] * wave(0.0),
            w[1] * wave(0.25),
            w[2] * wave(0.5),
            w[3] * wave(0.75),
        ]
    }

    /// The full form's base weight for target weights `w`: the one set by hand, or `1 − Σ w`.
    pub fn base_weight_for(&self, w: &[f32; 4]) -> f32 {
        self.base_weight.unwrap_or(1.0 - w.iter().sum::<f32>())
    }

    /// The plot of the weights over one loop: `[time (s), smile, jaw open, brows up, puff cheeks,
    /// Σ w (the targets), base + Σ w (the full form's total)]` per sample, `samples` in [2, 10000].
    /// The last column is the factor the full form multiplies the head by.
    pub fn weight_curves(&self, samples: usize) -> Result<Vec<f32>, String> {
        check_samples(samples)?;
        let mut out = Vec::with_capacity(samples * 7);
        for i in 0..samples {
            let t = LOOP_SECONDS * i as f32 / (samples - 1) as f32;
            let w = self.weights_at(t);
            let sum: f32 = w.iter().sum();
            out.push(t);
            out.extend_from_slice(&w);
            out.push(sum);
            out.push(self.base_weight_for(&w) + sum);
        }
        Ok(out)
    }

    /// The largest factor the full form multiplies the head by over the loop (or now, with the
    /// weights still): `max |base + Σ w|`, the size the layout and the framing make room for.
    pub fn largest_full_scale(&self) -> f32 {
        let total = |w: [f32; 4]| (self.base_weight_for(&w) + w.iter().sum::<f32>()).abs();
        if !self.animate {
            return total(self.weights);
        }
        // Each weight is a raised cosine over the loop: 96 steps find the peak to 0.1%.
        (0..=96)
            .map(|i| total(self.weights_at(LOOP_SECONDS * i as f32 / 96.0)))
            .fold(0.0, f32::max)
    }

    /// Where each shown head stands: `(differential, full)`, `None` when hidden. Side by side,
    /// the full head stands far enough to the right that, at its largest over the loop
    /// ([`FaceFigure::largest_full_scale`]), it does not reach into the differential head, and
    /// the differential head stays where it is, however large the other grows.
    pub fn head_positions(&self) -> (Option<Vec3>, Option<Vec3>) {
        let s = self.largest_full_scale().max(1.0);
        match self.show {
            Show::Both => (
                Some(HEAD_CENTRE - Vec3::X * HEAD_RADIUS),
                Some(HEAD_CENTRE + Vec3::X * (HEAD_RADIUS * s)),
            ),
            Show::Differential => (Some(HEAD_CENTRE), None),
            Show::Full => (None, Some(HEAD_CENTRE)),
        }
    }

    /// Where to aim the camera so the shown heads fit: `[x, y, z, distance]`, the heads'
    /// bounding box at their largest over the loop, at the distance that frames it as the
    /// figure's start frames the heads at rest size. Changes only when a control does.
    pub fn view_fit(&self) -> [f32; 4] {
        let s = self.largest_full_scale().max(1.0);
        let r = HEAD_RADIUS;
        let (lo, hi, height) = match self.show {
            Show::Both => (-2.0 * r, 2.0 * r * s, 2.0 * r * s),
            Show::Differential => (-r, r, 2.0 * r),
            Show::Full => (-r * s, r * s, 2.0 * r * s),
        };
        // At rest size both heads side by side are 4r wide and 2r tall.
        let grow = ((hi - lo) / (4.0 * r)).max(height / (2.0 * r)).max(1.0);
        [
            0.5 * (lo + hi),
            HEAD_CENTRE.y + VIEW_LIFT,
            HEAD_CENTRE.z,
            VIEW_DISTANCE * grow,
        ]
    }

    /// Blends the faces at `time_sec` and draws them (`meshes`: the GPU ids of the differential
    /// and the full head); returns the note.
    pub fn draw(
        &mut self,
        frame: &mut Frame,
        meshes: [MeshId; 2],
        time_sec: f32,
    ) -> Result<String, String> {
        let t = finite("time", time_sec)?;
        let w = self.weights_at(t);
        let sum: f32 = w.iter().sum();
        let w0 = self.base_weight_for(&w);
        let total = w0 + sum;
        let weights = [w0, w[0], w[1], w[2], w[3]];
        if self.blended != Some(weights) {
            let shapes = &self.face.shapes;
            shapes
                .apply_differential(
                    &w,
                    &mut self.differential.positions,
                    &mut self.differential.normals,
                )
                .map_err(|e| e.to_string())?;
            shapes
                .apply_full(&weights, &mut self.full.positions, &mut self.full.normals)
                .map_err(|e| e.to_string())?;
            self.differential.mark_dirty();
            self.full.mark_dirty();
            self.blended = Some(weights);
        }
        if self.use_exercise {
            self.exercise_note = self.run_exercise(&w);
        } else {
            self.exercise_note.clear();
        }

        let (left, right) = self.head_positions();
        let both = self.show == Show::Both;
        let mut parts = Vec::new();
        if left.is_some() {
            parts.push(format!(
                "Differential{}: base + Σ w·delta; the weights sum to {} (any sum is fine).",
                if both { " (left)" } else { "" },
                format_number(sum)
            ));
        }
        if right.is_some() {
            let verdict = if (total - 1.0).abs() > 1e-3 {
                format!(
                    ", not 1: every vertex's offset from the head's centre (the mesh's origin) is multiplied by {}",
                    format_number(total)
                )
            } else if self.base_weight.is_none() {
                " (the base weight is 1 − Σw): the same face as the differential form, by design; set the full form's base weight by hand to see it go wrong".into()
            } else {
                String::new()
            };
            parts.push(format!(
                "Full{}: base weight {} + targets {} = {}{}.",
                if both { " (right)" } else { "" },
                format_number(w0),
                format_number(sum),
                format_number(total),
                verdict
            ));
        }
        parts.push(format!(
            "Weights: {}.",
            self.face
                .names
                .iter()
                .zip(w)
                .map(|(n, x)| format!("{n} {}", format_number(x)))
                .collect::<Vec<_>>()
                .join(", ")
        ));
        if !self.exercise_note.is_empty() {
            parts.push(self.exercise_note.clone());
        }

        frame.grid(8, 0.5);
        // The heads swing gently (±25° over the loop) so the shapes show from the side too.
        let yaw = 25f32.to_radians() * (std::f32::consts::TAU * t / LOOP_SECONDS).sin();
        // The full form scales the face about its origin by `total`; the eyes are separate
        // spheres, so they are scaled by hand to stay on the face.
        for (at, mesh, scale, name, differential) in [
            (left, meshes[0], 1.0, "differential".to_string(), true),
            (
                right,
                meshes[1],
                total,
                format!("full (sum {})", format_number(total)),
                false,
            ),
        ] {
            let Some(at) = at else { continue };
            let head = Mat4::from_translation(at) * Mat4::from_rotation_y(yaw);
            frame.mesh(mesh, head, Vec3::new(0.85, 0.62, 0.48));
            for x in [-0.27f32, 0.27] {
                let eye = head
                    * Mat4::from_scale(Vec3::splat(scale))
                    * Mat4::from_translation(Vec3::new(x, 0.22, 0.72))
                    * Mat4::from_scale(Vec3::splat(0.09));
                frame.mesh(MeshId::SPHERE, eye, palette::DARK);
            }
            if both {
                let above = 1.3 * scale.abs().max(1.0);
                if differential {
                    // The differential head, on the left: its label reads leftwards from above
                    // the head's centre, away from the full head, which may be many times larger.
                    frame.label_left(at + Vec3::new(0.3, above, 0.0), name, palette::DARK);
                } else {
                    frame.label(at + Vec3::new(-0.3, above, 0.0), name, palette::DARK);
                }
            }
        }
        Ok(parts.join(" "))
    }

    fn run_exercise(&mut self, w: &[f32; 4]) -> String {
        let mut worst: Option<(usize, Vec3, Vec3)> = None;
        for v in 0..self.face.mesh.positions.len() {
            let base = self.face.mesh.positions[v];
            let targets: Vec<Vec3> = self.face.targets.iter().map(|t| t[v]).collect();
            match run::differential_vertex(self.runner, base, targets, w.to_vec()) {
                Ok(p) => {
                    let r = crate::blend_shapes::differential_vertex(
                        base,
                        &targets_of(&self.face, v),
                        w,
                    );
                    let e = (p - r).length();
                    if (e > TOLERANCE || e.is_nan()) && worst.is_none() {
                        worst = Some((v, p, r));
                    }
                    // The differential head shows the student's vertices.
                    self.differential.positions[v] = if p.is_finite() { p } else { r };
                }
                Err(f) => {
                    return failure_note("exercise 10.1 differential_vertex", EXERCISE_FILE, &f)
                }
            }
        }
        match worst {
            None => format!(
                "Your differential_vertex (10.1) matches the reference (differential form) at all {} vertices.",
                self.face.mesh.positions.len()
            ),
            Some((v, s, r)) => {
                compare_note(
                    "differential_vertex (10.1)",
                    &format!("vertex {v}"),
                    &s.to_array(),
                    &r.to_array(),
                    TOLERANCE,
                )
                .1
            }
        }
    }
}

fn targets_of(face: &Face, v: usize) -> Vec<Vec3> {
    face.targets.iter().map(|t| t[v]).collect()
}
