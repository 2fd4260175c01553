//! Figure logic for lesson 10, "Blend shapes" (see [`crate::figures`]).
//!
//! [`FaceFigure`]: the procedural face with four targets and a weight per target, blended in the
//! differential form and in the full form side by side (or one of them alone). The full form also
//! weights the base: by hand (0 at the start, as when only the targets get weights), or
//! automatically `1 − Σ wₖ`, which makes the two forms agree. Arrows on the differential head show
//! each vertex's offset `Σ wₖ dₖ`. The weights can be animated over time;
//! [`FaceFigure::weight_curves`] gives their plot. Exercise 10.1 (the student's differential form)
//! drives the differential head.

use super::{
    check_samples, compare_note, failure_note, finite, format_number, in_range, palette, Frame,
    MeshId, Runner, DEFAULT_RUNNER,
};
use crate::blend_shapes::{face, Face};
use crate::exercises::run;
use crate::figures::skinning::SkinnedMesh;
use crate::Valid;
use glam::{Mat4, Vec3};

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
/// The layout and the framing make room for the full head at least this many times its rest
/// size: the defaults' largest total (1.67) and every total of the page's Try this (at most
/// 1.5) stay within it, so neither head moves or changes size on the canvas while the right one
/// grows up to it; only a larger total moves the camera back.
pub const FRAMED_SCALE: f32 = 1.7;

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
    /// The full form's base weight when set by hand.
    base_weight: f32,
    /// The full form's base weight is `1 − Σ wₖ` (so the weights sum to 1), not `base_weight`.
    base_auto: bool,
    show: Show,
    animate: bool,
    show_deltas: bool,
    use_exercise: bool,
    /// Every `DELTA_STRIDE`-th vertex with a visible offset: where the delta arrows start.
    arrow_vertices: Vec<usize>,
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
    /// Both forms side by side, the weights animated, the full form's base weight 0 by hand (so
    /// the two heads differ from the start).
    pub fn new() -> Self {
        let face = face();
        let n = face.mesh.positions.len();
        let blank = || {
            let mut mesh = SkinnedMesh::default();
            mesh.positions = vec![Vec3::ZERO; n];
            mesh.normals = vec![Vec3::ZERO; n];
            mesh.colors = face.colors.clone();
            mesh
        };
        let arrow_vertices = arrow_vertices(&face, DELTA_STRIDE);
        Self {
            differential: blank(),
            full: blank(),
            weights: DEFAULT_WEIGHTS,
            base_weight: 0.0,
            base_auto: false,
            show: Show::Both,
            animate: true,
            show_deltas: true,
            use_exercise: false,
            arrow_vertices,
            face,
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

    /// The sliders' target weights (smile, jaw open, brows up, puff cheeks).
    pub fn weights(&self) -> [f32; 4] {
        self.weights
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

    /// The full form's base weight by hand, in [0, 1] (used while the base weight is not
    /// automatic).
    pub fn set_base_weight(&mut self, w: f32) -> Result<(), String> {
        self.base_weight = in_range("base weight", w, 0.0, 1.0)?;
        Ok(())
    }

    /// `true`: the full form's base weight is `1 − Σ wₖ` (the weights sum to 1 and the two forms
    /// agree); `false`: the one set by hand.
    pub fn set_base_auto(&mut self, on: bool) {
        self.base_auto = on;
    }

    pub fn set_animate(&mut self, on: bool) {
        self.animate = on;
    }

    /// Arrows on the differential head from each sampled vertex's base position to its blended
    /// one (its offset `Σ wₖ dₖ`).
    pub fn set_show_deltas(&mut self, on: bool) {
        self.show_deltas = on;
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        // Blend again at the next frame: the differential head switches to (or from) the
        // student's vertices.
        self.blended = None;
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

    /// The full form's base weight for target weights `w`: `1 − Σ w` when automatic, else the
    /// one set by hand.
    pub fn base_weight_for(&self, w: &[f32; 4]) -> f32 {
        if self.base_auto {
            1.0 - w.iter().sum::<f32>()
        } else {
            self.base_weight
        }
    }

    /// The smallest and the largest full-form total `base + Σ w` over the loop (sampled at 97
    /// times; both equal when the weights are still).
    pub fn total_range(&self) -> (f32, f32) {
        let total = |w: [f32; 4]| self.base_weight_for(&w) + w.iter().sum::<f32>();
        (0..=96)
            .map(|i| total(self.weights_at(LOOP_SECONDS * i as f32 / 96.0)))
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            })
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

    /// The full head's size the layout and the framing make room for: its largest over the loop
    /// ([`FaceFigure::largest_full_scale`]), at least [`FRAMED_SCALE`].
    pub fn framed_scale(&self) -> f32 {
        self.largest_full_scale().max(FRAMED_SCALE)
    }

    /// Where each shown head stands: `(differential, full)`, `None` when hidden. Side by side,
    /// the full head stands far enough to the right that, at its largest over the loop
    /// ([`FaceFigure::framed_scale`]), it does not reach into the differential head, and
    /// the differential head stays where it is, however large the other grows.
    pub fn head_positions(&self) -> (Option<Vec3>, Option<Vec3>) {
        let s = self.framed_scale();
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
    /// bounding box at their largest over the loop (at least [`FRAMED_SCALE`]), at the distance
    /// that frames two heads at rest size at [`VIEW_DISTANCE`]. Changes only when a control
    /// takes the full head past [`FRAMED_SCALE`].
    pub fn view_fit(&self) -> [f32; 4] {
        let s = self.framed_scale();
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
    /// and the full head, both with the face's vertex colours); returns the note.
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
            // The student's vertices replace the reference's on the differential head; checked
            // once per set of weights, like the blend.
            self.exercise_note = if self.use_exercise {
                self.run_exercise(&w)
            } else {
                String::new()
            };
            self.differential.mark_dirty();
            self.full.mark_dirty();
            self.blended = Some(weights);
        }

        let (left, right) = self.head_positions();
        let both = self.show == Show::Both;
        let mut parts = Vec::new();
        if left.is_some() {
            parts.push(format!(
                "Differential{}: base + Σ w·delta; the weights sum to {} (any sum is fine).",
                if both { " (left)" } else { "" },
                fixed3(sum)
            ));
        }
        if right.is_some() {
            parts.push(format!(
                "Full{}: base weight {}{} + targets {} = {}{}.",
                if both { " (right)" } else { "" },
                fixed3(w0),
                if self.base_auto { " (1 − Σw)" } else { "" },
                fixed3(sum),
                fixed3(total),
                full_verdict(total)
            ));
        }
        let largest = self.framed_scale();
        // Side by side the view zooms out in proportion to the framed scale: past
        // ARROWS_HIDDEN_ABOVE the differential head is drawn at under half its size at the
        // start, and its arrows (in proportion to the offsets, not the head) would cover it.
        let small = both && largest > ARROWS_HIDDEN_ABOVE;
        if both && largest > FRAMED_SCALE {
            parts.push(format!(
                "The view is zoomed out to fit the full head at its largest ({} times the base), \
                 so the differential head is drawn smaller{}.",
                fixed3(largest),
                if small && self.show_deltas {
                    ", too small for its arrows (hidden: they would cover it)"
                } else {
                    ""
                }
            ));
        }
        parts.push(format!(
            "Weights: {}.",
            self.face
                .names
                .iter()
                .zip(w)
                .map(|(n, x)| format!("{n} {}", fixed3(x)))
                .collect::<Vec<_>>()
                .join(", ")
        ));
        if !self.exercise_note.is_empty() {
            parts.push(self.exercise_note.clone());
        }

        frame.grid(8, 0.5);
        // The heads swing gently (±25° over the loop) so the shapes show from the side too.
        let yaw = 25f32.to_radians() * (std::f32::consts::TAU * t / LOOP_SECONDS).sin();
        // The full form scales the base about its origin by `total`; the eyes are separate
        // spheres, so they are scaled by hand to stay on the face.
        for (at, mesh, scale, name, differential) in [
            (left, meshes[0], 1.0, "differential".to_string(), true),
            (
                right,
                meshes[1],
                total,
                format!("full (total {})", fixed3(total)),
                false,
            ),
        ] {
            let Some(at) = at else { continue };
            let head = Mat4::from_translation(at) * Mat4::from_rotation_y(yaw);
            frame.mesh_vertex_colors(mesh, head);
            for x in [-0.27f32, 0.27] {
                let eye = head
                    * Mat4::from_scale(Vec3::splat(scale))
                    * Mat4::from_translation(Vec3::new(x, 0.22, 0.72))
                    * Mat4::from_scale(Vec3::splat(0.09));
                frame.mesh(MeshId::SPHERE, eye, palette::DARK);
            }
            if differential && self.show_deltas && !small {
                // Each arrow runs from the vertex on the base head along its offset Σ wₖ dₖ,
                // drawn FACE_ARROW_SCALE times as long, in the head's frame, lifted 3 cm off the
                // base surface along its normal, its shaft drawn over the skin (which hides where
                // it starts when the blend moves the skin outwards). A vertex that moves less
                // than FACE_ARROW_MIN carries none: its arrow would be a dot on this small head.
                let base = &self.face.mesh.positions;
                let normals = &self.face.mesh.normals;
                for &v in &self.arrow_vertices {
                    let offset = self.differential.positions[v] - base[v];
                    if offset.length() < FACE_ARROW_MIN {
                        continue;
                    }
                    let lift = ARROW_LIFT * normals[v];
                    let from = head.transform_point3(base[v] + lift);
                    let to = head.transform_point3(base[v] + lift + FACE_ARROW_SCALE * offset);
                    frame.arrow_on_top(from, to, palette::BLUE, FACE_ARROW_HEAD_M);
                }
            }
            // Each shown head is named, alone too (the full head's name gives its total).
            let above = 1.3 * scale.abs().max(1.0);
            if differential {
                // The differential head, on the left: its label reads leftwards from above the
                // head's centre, away from the full head, which may be many times larger.
                frame.label_left(at + Vec3::new(0.3, above, 0.0), name, palette::DARK);
            } else {
                frame.label(at + Vec3::new(-0.3, above, 0.0), name, palette::DARK);
            }
        }
        // The camera fits each shown head at its largest over the loop (at least FRAMED_SCALE),
        // with its title's anchor (1.3 k above its centre): it holds still while the heads
        // breathe and moves only when a control takes the full head past FRAMED_SCALE.
        for (at, k) in [(left, 1.0), (right, largest)] {
            if let Some(at) = at {
                let (r, top) = (HEAD_RADIUS * k, 1.3 * k);
                frame.keep_box_in_view(at - Vec3::splat(r), at + Vec3::new(r, top, r));
            }
        }
        Ok(parts.join(" "))
    }

    /// The vertices the delta arrows start from (see [`arrow_vertices`]).
    pub fn arrow_vertices(&self) -> &[usize] {
        &self.arrow_vertices
    }

    /// Runs the student's 10.1 on every vertex at weights `w` (their vertices go to the
    /// differential head) and at [`PROBES`] on the vertex that the targets move most, and says
    /// where it differs from the reference.
    fn run_exercise(&mut self, w: &[f32; 4]) -> String {
        let n = self.face.mesh.positions.len();
        let mut worst: Option<(usize, Vec3, Vec3)> = None;
        for v in 0..n {
            let base = self.face.mesh.positions[v];
            let targets = targets_of(&self.face, v);
            match run::differential_vertex(self.runner, base, targets.clone(), w.to_vec()) {
                Ok(p) => {
                    let r = crate::blend_shapes::differential_vertex(base, &targets, w);
                    let e = (p - r).length();
                    if (e > TOLERANCE || e.is_nan()) && worst.is_none() {
                        worst = Some((v, p, r));
                    }
                    self.differential.positions[v] = if p.is_finite() { p } else { r };
                }
                Err(f) => {
                    return failure_note("exercise 10.1 differential_vertex", EXERCISE_FILE, &f)
                }
            }
        }
        let here = match worst {
            None => format!(
                "Your differential_vertex (10.1) matches the reference at all {n} vertices at the current weights."
            ),
            Some((v, s, r)) => {
                compare_note(
                    "differential_vertex (10.1)",
                    &format!("vertex {v} at the current weights"),
                    &s.to_array(),
                    &r.to_array(),
                    TOLERANCE,
                )
                .1
            }
        };
        // Probes: weights the sliders may not be at now, each a classic mistake's trap.
        let v = self.probe_vertex();
        let base = self.face.mesh.positions[v];
        let all_targets = targets_of(&self.face, v);
        let mut differing = Vec::new();
        for (name, weights) in PROBES {
            let targets = all_targets[..weights.len()].to_vec();
            let r = crate::blend_shapes::differential_vertex(base, &targets, weights);
            match run::differential_vertex(self.runner, base, targets, weights.to_vec()) {
                Ok(p) if (p - r).length() <= TOLERANCE => {}
                Ok(p) => differing.push((name, p, r)),
                Err(f) => {
                    return failure_note("exercise 10.1 differential_vertex", EXERCISE_FILE, &f)
                }
            }
        }
        if differing.is_empty() {
            format!(
                "{here} It also matches at the {} probe weights at vertex {v} ({}).",
                PROBES.len(),
                PROBES.map(|(name, _)| name).join(", ")
            )
        } else {
            let (first, p, r) = differing[0];
            format!(
                "{here} At vertex {v} it differs for {} of the {} probe weights: {}; with {first}: yours ({}), reference ({}).",
                differing.len(),
                PROBES.len(),
                differing.iter().map(|d| d.0).collect::<Vec<_>>().join(", "),
                fmt_vec(p),
                fmt_vec(r)
            )
        }
    }

    /// The vertex whose four deltas are longest together: where a wrong blend shows most.
    pub fn probe_vertex(&self) -> usize {
        (0..self.face.mesh.positions.len())
            .max_by(|&a, &b| {
                let size = |v: usize| -> f32 {
                    self.face
                        .targets
                        .iter()
                        .map(|t| (t[v] - self.face.mesh.positions[v]).length())
                        .sum()
                };
                size(a).total_cmp(&size(b))
            })
            .unwrap_or(0)
    }
}

/// The weights the figure starts with: smile, jaw open, brows up, puff cheeks.
pub const DEFAULT_WEIGHTS: [f32; 4] = [1.0, 0.8, 0.6, 0.3];

/// The probe weights exercise 10.1 is checked at besides the sliders' (each with as many targets
/// as weights): the traps of the usual mistakes (the full form, a forgotten base, clamped
/// weights, a loop over the wrong slice).
pub const PROBES: [(&str, &[f32]); 6] = [
    ("all weights 0", &[0.0, 0.0, 0.0, 0.0]),
    ("weights summing to 0.5", &[0.2, 0.1, 0.1, 0.1]),
    ("weights summing to 2", &[0.5, 0.5, 0.5, 0.5]),
    ("a negative weight", &[-0.5, 0.0, 0.0, 0.0]),
    ("a weight above 1", &[0.0, 1.5, 0.0, 0.0]),
    ("no targets", &[]),
];

/// One in this many vertices (along each ring and across rings) carries a delta arrow.
const DELTA_STRIDE: usize = 4;
/// How far the delta arrows float above the base surface, metres.
const ARROW_LIFT: f32 = 0.03;
/// The length of a delta arrow's head, metres (at most 0.4 of the arrow): most arrows are
/// 5 to 25 cm long on heads 2 m tall, and a shorter head does not show their direction.
const ARROW_HEAD_M: f32 = 0.08;
/// A target moves a vertex at least this far (metres) for it to carry an arrow.
const DELTA_MIN: f32 = 0.02;

/// Figure 1 samples one in this many vertices, along each ring and across rings, for its arrows.
const TARGET_STRIDE: usize = 3;
/// A target's arrows in Figure 1 sit on the sampled vertices it moves at least this share of its
/// farthest move: where it acts most, each arrow long enough on the canvas to show its direction
/// (the vertices it barely moves would give dots).
pub const TARGET_ARROW_SHARE: f32 = 0.5;
/// Figure 1 draws each delta arrow this many times as long as the offset it shows: its heads
/// share a canvas, where a 10 cm offset drawn to scale is a dot a few pixels long.
pub const TARGET_ARROW_SCALE: f32 = 2.0;
/// Figure 2 draws each delta arrow this many times as long as the offset it shows: its
/// differential head is about 120 px tall on the page's canvas (the view makes room for the full
/// head at [`FRAMED_SCALE`] times its size), and the animated weights are mostly well below 1.
pub const FACE_ARROW_SCALE: f32 = 5.0;
/// Figure 2's vertices that move less than this (metres) at the current weights carry no arrow:
/// drawn [`FACE_ARROW_SCALE`] times as long, a shorter offset gives a blue dot a few pixels long.
pub const FACE_ARROW_MIN: f32 = 0.025;
/// Side by side, Figure 2 hides the delta arrows once the full head's framed scale passes this
/// ([`FaceFigure::framed_scale`]): the view then shows the left head at under half its size
/// at the start ([`FRAMED_SCALE`]).
pub const ARROWS_HIDDEN_ABOVE: f32 = 2.0 * FRAMED_SCALE;
/// The length of Figure 2's arrow heads, metres (at most 0.4 of the arrow).
const FACE_ARROW_HEAD_M: f32 = 0.12;

/// The vertices that carry delta arrows: every `stride`-th one along and across the sphere's
/// rings that some target moves at least [`DELTA_MIN`].
fn arrow_vertices(face: &Face, stride: usize) -> Vec<usize> {
    let segments = crate::blend_shapes::FACE_SEGMENTS as usize;
    (1..face.mesh.positions.len().saturating_sub(1))
        .filter(|&v| {
            let (ring, segment) = ((v - 1) / segments, (v - 1) % segments);
            ring % stride == 0 && segment % stride == 0
        })
        .filter(|&v| {
            face.targets
                .iter()
                .any(|t| (t[v] - face.mesh.positions[v]).length() >= DELTA_MIN)
        })
        .collect()
}

/// What the note says about the full form's total `base + Σ w`.
fn full_verdict(total: f32) -> String {
    let s = format_number(total);
    if (total - 1.0).abs() <= 1e-3 {
        ": the weights sum to 1, so the full form is the differential form".into()
    } else if total.abs() <= 1e-3 {
        ", so the base vanishes: p = Σ wₖ dₖ, only the deltas are left, crumpled at the head's centre".into()
    } else if total < 0.0 {
        format!(
            ", negative: p = ({s})·b₀ + Σ wₖ dₖ mirrors the base through the head's centre, so the head is turned inside out (its faces point inwards)"
        )
    } else {
        format!(
            ", not 1: p = {s}·b₀ + Σ wₖ dₖ, so the base head is scaled by {s} about its centre while the deltas keep their size"
        )
    }
}

fn fmt_vec(v: Vec3) -> String {
    v.to_array().map(format_number).join(", ")
}

fn targets_of(face: &Face, v: usize) -> Vec<Vec3> {
    face.targets.iter().map(|t| t[v]).collect()
}

// ---------------------------------------------------------------------------------------------
// Figure 1: the base and its targets.

/// How far apart (metres, along x) [`TargetsFigure`] stands its five heads: more than twice
/// the widest any head gets at the largest weight (a test checks it).
pub const TARGETS_SPACING: f32 = 2.1;
/// Half the height between [`TargetsFigure`]'s two rows of heads, metres (a head is 2 m tall,
/// plus its label).
pub const TARGETS_ROW: f32 = 1.35;
/// A vertex that a target moves less than this (metres) does not count as moved in the note.
pub const MOVED_MIN: f32 = 0.001;

/// Figure 1: the base head `b₀` and each target `bₖ = b₀ + dₖ` on its own, five heads in a row,
/// every target shown at one weight `w` (1: the target as sculpted), with arrows along `w dₖ`
/// (drawn [`TARGET_ARROW_SCALE`] times as long) on the vertices it moves most.
pub struct TargetsFigure {
    face: Face,
    weight: f32,
    show_deltas: bool,
    /// The base, then each target at `weight`, with the face's paint.
    pub heads: Vec<SkinnedMesh>,
    /// Per target: the vertices that carry an arrow (every [`TARGET_STRIDE`]-th that it moves at
    /// least [`TARGET_ARROW_SHARE`] of its farthest).
    arrows: Vec<Vec<usize>>,
    /// The weight the target heads were last blended at.
    blended: Option<f32>,
    /// The directions the rows of heads run along and stack up: the last frame's camera's
    /// right and up ([`TargetsFigure::set_view`]).
    axes: (Vec3, Vec3),
}

impl Default for TargetsFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl TargetsFigure {
    /// Every target at weight 1 (as sculpted), with arrows.
    pub fn new() -> Self {
        let face = face();
        let n = face.mesh.positions.len();
        let heads = (0..=face.targets.len())
            .map(|_| {
                let mut mesh = SkinnedMesh::default();
                mesh.positions = vec![Vec3::ZERO; n];
                mesh.normals = vec![Vec3::ZERO; n];
                mesh.colors = face.colors.clone();
                mesh
            })
            .collect();
        let sampled = arrow_vertices(&face, TARGET_STRIDE);
        let arrows = face
            .targets
            .iter()
            .map(|t| {
                let moved = |v: usize| (t[v] - face.mesh.positions[v]).length();
                let farthest = (0..n).map(moved).fold(0.0, f32::max);
                sampled
                    .iter()
                    .copied()
                    .filter(|&v| moved(v) >= TARGET_ARROW_SHARE * farthest)
                    .collect()
            })
            .collect();
        let mut f = Self {
            face,
            weight: 1.0,
            show_deltas: true,
            heads,
            arrows,
            blended: None,
            axes: (Vec3::X, Vec3::Y),
        };
        f.blend();
        f
    }

    /// The camera the frame is drawn for (the last frame's): the heads stand in rows across its
    /// view, so an orbit turns each head in its place instead of lining them up behind each
    /// other.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera) {
        self.axes = super::skinning::screen_axes(&camera);
    }

    pub fn indices(&self) -> &[u32] {
        &self.face.mesh.indices
    }

    /// The targets' names, in order.
    pub fn target_names(&self) -> Vec<String> {
        self.face.names.iter().map(|s| s.to_string()).collect()
    }

    /// The weight every target head is shown at, in [0, 1.5] (1: as sculpted).
    pub fn set_weight(&mut self, w: f32) -> Result<(), String> {
        self.weight = in_range("weight", w, 0.0, 1.5)?;
        Ok(())
    }

    pub fn weight(&self) -> f32 {
        self.weight
    }

    /// Arrows along `w dₖ` on each target head.
    pub fn set_show_deltas(&mut self, on: bool) {
        self.show_deltas = on;
    }

    /// Where head `i` stands (0: the base, k: target k), its centre: the base, the smile and
    /// the open jaw in the top row, the brows and the cheeks centred below them (two rows fill a
    /// canvas's width better than one row of five), the rows across the camera's view.
    pub fn head_position(&self, i: usize) -> Vec3 {
        let (x, y) = if i < 3 {
            ((i as f32 - 1.0) * TARGETS_SPACING, TARGETS_ROW)
        } else {
            ((i as f32 - 3.5) * TARGETS_SPACING, -TARGETS_ROW)
        };
        self.on_view_plane(x, y)
    }

    /// The point `x` along the camera's right and `y` along its up from the origin.
    fn on_view_plane(&self, x: f32, y: f32) -> Vec3 {
        self.axes.0 * x + self.axes.1 * y
    }

    /// Rewrites the target heads at the current weight (the base head once); nothing when the
    /// weight has not changed since.
    fn blend(&mut self) {
        if self.blended == Some(self.weight) {
            return;
        }
        let k_count = self.face.targets.len();
        for i in 0..=k_count {
            let mut w = vec![0.0; k_count];
            if i > 0 {
                w[i - 1] = self.weight;
            }
            let head = &mut self.heads[i];
            self.face
                .shapes
                .apply_differential(&w, &mut head.positions, &mut head.normals)
                .valid("one weight per target, finite");
            head.mark_dirty();
        }
        self.blended = Some(self.weight);
    }

    /// How target `k` (0-based) moves the head: the number of vertices its delta moves by at
    /// least [`MOVED_MIN`] (a property of the target, the same at every weight), and the
    /// largest distance any vertex moves at the current weight (metres).
    pub fn target_reach(&self, k: usize) -> (usize, f32) {
        let base = &self.face.mesh.positions;
        let target = &self.face.targets[k];
        let mut moved = 0;
        let mut largest = 0.0f32;
        for (b, t) in base.iter().zip(target) {
            let d = (*t - *b).length();
            if d >= MOVED_MIN {
                moved += 1;
            }
            largest = largest.max(self.weight.abs() * d);
        }
        (moved, largest)
    }

    /// Blends what changed and draws the five heads (`meshes`: the GPU ids of the base and of
    /// each target head, in order); returns the note.
    pub fn draw(&mut self, frame: &mut Frame, meshes: &[MeshId]) -> Result<String, String> {
        if meshes.len() != self.heads.len() {
            return Err(format!(
                "meshes: expected {} (the base and each target), got {}",
                self.heads.len(),
                meshes.len()
            ));
        }
        self.blend();
        let n = self.face.mesh.positions.len();
        let base = &self.face.mesh.positions;
        let normals = &self.face.mesh.normals;
        for (i, &mesh) in meshes.iter().enumerate() {
            let at = self.head_position(i);
            let model = Mat4::from_translation(at);
            frame.mesh_vertex_colors(mesh, model);
            for x in [-0.27f32, 0.27] {
                let eye = model
                    * Mat4::from_translation(Vec3::new(x, 0.22, 0.72))
                    * Mat4::from_scale(Vec3::splat(0.09));
                frame.mesh(MeshId::SPHERE, eye, palette::DARK);
            }
            let name = if i == 0 {
                "b₀ base".to_string()
            } else {
                format!("b{} {}", subscript(i), self.face.names[i - 1])
            };
            // The top row's names stand above its heads, clear of the open jaw's arrows; the
            // bottom row's below.
            let under = if i < 3 { -1.2 } else { 1.25 };
            frame.label(at - self.on_view_plane(0.55, under), name, palette::DARK);
            if i > 0 && self.show_deltas {
                for &v in &self.arrows[i - 1] {
                    let lift = ARROW_LIFT * normals[v];
                    let from = model.transform_point3(base[v] + lift);
                    let offset = self.heads[i].positions[v] - base[v];
                    let to = model.transform_point3(base[v] + lift + TARGET_ARROW_SCALE * offset);
                    frame.arrow_on_top(from, to, palette::BLUE, ARROW_HEAD_M);
                }
            }
        }
        // Every head with its label, the rows' outer heads at their widest.
        let (x, bottom, top) = (
            TARGETS_SPACING + HEAD_RADIUS,
            -TARGETS_ROW - 1.45,
            TARGETS_ROW + 1.4,
        );
        for (x, y) in [(-x, bottom), (x, bottom), (-x, top), (x, top)] {
            frame.keep_in_view.push(self.on_view_plane(x, y));
        }
        let parts: Vec<String> = (0..self.face.targets.len())
            .map(|k| {
                let (moved, largest) = self.target_reach(k);
                format!(
                    "{}: its delta moves {moved} of the {n} vertices, the farthest by {} cm at this weight",
                    self.face.names[k],
                    format_number_digits(100.0 * largest, 1)
                )
            })
            .collect();
        Ok(format!(
            "Each target alone at weight {}: b₀ + {}·dₖ. {}. The other vertices stay where the base has them: a target stores one position per vertex, but only its delta dₖ matters.",
            format_number(self.weight),
            format_number(self.weight),
            parts.join("; ")
        ))
    }
}

/// `k` as a subscript digit (k < 10).
fn subscript(k: usize) -> char {
    char::from_u32(0x2080 + (k % 10) as u32).unwrap_or('?')
}

/// A weight or a total in the note and the label: three decimals, however small (no "8.335e-4"
/// among "0.230"s), and no "-0.000".
fn fixed3(x: f32) -> String {
    format_number_digits(if x.abs() < 5e-4 { 0.0 } else { x }, 3)
}

/// `x` with `digits` decimals.
fn format_number_digits(x: f32, digits: usize) -> String {
    format!("{x:.digits$}")
}
