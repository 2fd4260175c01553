//! Figure logic for lesson 10, "Blend shapes" (see [`crate::figures`]).
//!
//! [`FaceFigure`]: the procedural face with four targets, a weight per target, the full or the
//! differential form (the full form also weights the base, `1 − Σ wₖ` unless "base weight" is
//! set by hand, so a wrong sum shows), a weight animation over time, and the check of the
//! student's exercise 10.1.

use super::{
    compare_note, failure_note, finite, format_number, in_range, palette, Frame, MeshId, Runner,
    DEFAULT_RUNNER,
};
use crate::blend_shapes::{face, Face};
use crate::exercises::run;
use crate::figures::skinning::SkinnedMesh;
use glam::{Mat4, Vec3, Vec4};

const EXERCISE_FILE: &str = "src/exercises/blend_shapes.rs";
const TOLERANCE: f32 = 1e-4;

/// The face figure.
pub struct FaceFigure {
    face: Face,
    weights: [f32; 4],
    /// The full form's base weight; `None`: `1 − Σ wₖ` (so the weights sum to 1).
    base_weight: Option<f32>,
    full: bool,
    animate: bool,
    use_exercise: bool,
    runner: Runner,
    pub mesh: SkinnedMesh,
    exercise_note: String,
}

impl Default for FaceFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl FaceFigure {
    /// Differential form, the weights animated.
    pub fn new() -> Self {
        let face = face();
        let n = face.mesh.positions.len();
        let mut mesh = SkinnedMesh::default();
        mesh.positions = vec![Vec3::ZERO; n];
        mesh.normals = vec![Vec3::ZERO; n];
        mesh.colors = vec![Vec4::new(0.85, 0.62, 0.48, 1.0); n];
        Self {
            face,
            weights: [1.0, 0.6, 0.8, 0.7],
            base_weight: None,
            full: false,
            animate: true,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            mesh,
            exercise_note: String::new(),
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

    /// "full" or "differential".
    pub fn set_form(&mut self, name: &str) -> Result<(), String> {
        self.full = match name {
            "full" => true,
            "differential" => false,
            _ => {
                return Err(format!(
                    "form: expected \"full\" or \"differential\", got {name:?}"
                ))
            }
        };
        Ok(())
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
    /// slider's value over a 4 s loop.
    pub fn weights_at(&self, time_sec: f32) -> [f32; 4] {
        if !self.animate {
            return self.weights;
        }
        // Each weight pulses between 0 and its slider's value, a quarter of the loop apart.
        let wave =
            |phase: f32| 0.5 - 0.5 * (std::f32::consts::TAU * (time_sec / 4.0 - phase)).cos();
        let w = self.weights;
        [
            w[0] * wave(0.0),
            w[1] * wave(0.25),
            w[2] * wave(0.5),
            w[3] * wave(0.75),
        ]
    }

    /// Blends the face at `time_sec` and draws it (`mesh`: its GPU id); returns the note.
    pub fn draw(
        &mut self,
        frame: &mut Frame,
        mesh: MeshId,
        time_sec: f32,
    ) -> Result<String, String> {
        let t = finite("time", time_sec)?;
        let w = self.weights_at(t);
        let sum: f32 = w.iter().sum();
        let shapes = &self.face.shapes;
        // How much the full form scales the face towards its origin (1 in the differential form);
        // the eyes are separate spheres, so they are scaled by hand to stay on the face.
        let mut face_scale = 1.0;
        let mut note = if self.full {
            let w0 = self.base_weight.unwrap_or(1.0 - sum);
            let total = w0 + sum;
            face_scale = total;
            shapes
                .apply_full(
                    &[w0, w[0], w[1], w[2], w[3]],
                    &mut self.mesh.positions,
                    &mut self.mesh.normals,
                )
                .map_err(|e| e.to_string())?;
            if (total - 1.0).abs() > 1e-3 {
                format!(
                    "Full form: base weight {} + targets {} = {}, not 1: every vertex's offset from the head's centre (the mesh's origin) is multiplied by {}.",
                    format_number(w0),
                    format_number(sum),
                    format_number(total),
                    format_number(total)
                )
            } else {
                format!(
                    "Full form: base weight {} + targets {} = 1.",
                    format_number(w0),
                    format_number(sum)
                )
            }
        } else {
            shapes
                .apply_differential(&w, &mut self.mesh.positions, &mut self.mesh.normals)
                .map_err(|e| e.to_string())?;
            format!(
                "Differential form: base + Σ w·delta, weights sum to {} (any sum is fine).",
                format_number(sum)
            )
        };
        if self.use_exercise {
            self.exercise_note = self.run_exercise(&w);
        } else {
            self.exercise_note.clear();
        }
        note.push_str(&format!(
            " Full form's base weight: {}.",
            match self.base_weight {
                Some(b) => format_number(b),
                None => "1 − Σw".into(),
            }
        ));
        note.push_str(&format!(
            " Weights: {}.",
            self.face
                .names
                .iter()
                .zip(w)
                .map(|(n, x)| format!("{n} {}", format_number(x)))
                .collect::<Vec<_>>()
                .join(", ")
        ));
        if !self.exercise_note.is_empty() {
            note.push(' ');
            note.push_str(&self.exercise_note);
        }
        self.mesh.mark_dirty();
        frame.grid(8, 0.5);
        // The head swings gently (±25° over the 4 s loop) so the shapes show from the side too.
        let yaw = 25f32.to_radians() * (std::f32::consts::TAU * t / 4.0).sin();
        let head = Mat4::from_translation(Vec3::new(0.0, 1.2, 0.0)) * Mat4::from_rotation_y(yaw);
        frame.mesh(mesh, head, Vec3::new(0.85, 0.62, 0.48));
        for x in [-0.27f32, 0.27] {
            let eye = head
                * Mat4::from_scale(Vec3::splat(face_scale))
                * Mat4::from_translation(Vec3::new(x, 0.22, 0.72))
                * Mat4::from_scale(Vec3::splat(0.09));
            frame.mesh(MeshId::SPHERE, eye, palette::DARK);
        }
        Ok(note)
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
                    // The face shows the student's vertices in the differential form only.
                    if !self.full {
                        self.mesh.positions[v] = if p.is_finite() { p } else { r };
                    }
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
