//! Lesson 05, "Noise and terrain": 1D noise built from lattice gradients, 2D noise and its 3D
//! slices, octaves added one by one, the course's terrain with every parameter, its exact normals
//! against averaged ones, its variants side by side, procedural textures, the terrain quiz and two
//! fractals. Natively testable;
//! `web::noise` wraps these for JavaScript and uploads the terrain meshes (created once, then
//! updated in place).

use super::{check_samples, FirstPanic, DEFAULT_RUNNER};
use super::{compare_note, format_number, in_range, palette, Frame, MeshId, Runner};
use crate::draw::StrokeStyle;
use crate::exercises::run;
use crate::noise::fractals::{koch_snowflake, sierpinski, MAX_DEPTH};
use crate::noise::texture::{fill_rgba, TextureKind, TextureParams};
use crate::noise::{
    cell2, fade, fade_derivative, fade_second_derivative, grad1, grad2, Fractal, Permutation,
};
use crate::terrain::{
    last_resolved_octave, terrain_normal, Terrain, TerrainParams, Variant, MAX_RESOLUTION,
};
use crate::texture::{TextureId, UvRect};
use crate::Valid;
use glam::{Mat4, Vec2, Vec3};

const FILE: &str = "src/exercises/noise.rs";
const TOLERANCE: f32 = 1e-4;
/// Width of a guide line (a gradient, a ramp, the probe's stalk, the cell's outline), CSS pixels.
pub const GUIDE_PX: f32 = 2.0;
/// Width of Figure 4's normal's shaft, CSS pixels; its dark outline is 2.5 px wider (6 px, the
/// widest line the renderer draws).
pub const NORMAL_PX: f32 = 3.5;

/// Perlin's table for seed 0, a seeded shuffle otherwise.
pub fn permutation_for_seed(seed: u32) -> Permutation {
    if seed == 0 {
        Permutation::perlin()
    } else {
        Permutation::seeded(seed as u64)
    }
}

fn check_seed(seed: f32) -> Result<u32, String> {
    let s = in_range("seed", seed, 0.0, 1e6)?;
    if s.fract() != 0.0 {
        return Err(format!("seed must be a whole number, got {seed}"));
    }
    Ok(s as u32)
}

fn check_n(n: f32, max: u32) -> Result<u32, String> {
    let v = in_range("N", n, 0.0, max as f32)?;
    if v.fract() != 0.0 {
        return Err(format!("N must be a whole number, got {n}"));
    }
    Ok(v as u32)
}

/// The verdict on a student's exercise over several inputs, so a bug that the displayed input
/// cannot reveal still shows. `cases` names each input (`"t = 0.250"`) with the reference's
/// answer; `yours(i)` runs the student's code on case i. Returns the note and, when every case
/// answered, the student's answers (for drawing). A missing or panicking exercise stops at its
/// first call and yields [`failure_note`] (a panic named against its input, see [`FirstPanic`]).
fn probe_verdict(
    what: &str,
    exercise: &str,
    first_panic: &FirstPanic,
    cases: &[(String, Vec<f32>)],
    mut yours: impl FnMut(usize) -> Result<Vec<f32>, crate::exercises::run::Failure>,
) -> (String, Option<Vec<Vec<f32>>>) {
    let mut answers = Vec::with_capacity(cases.len());
    let mut differ = Vec::new();
    for (i, (_, reference)) in cases.iter().enumerate() {
        match yours(i) {
            Ok(a) => {
                let bad = a.len() != reference.len()
                    || a.iter().zip(reference).any(|(x, r)| {
                        let e = (x - r).abs();
                        e.is_nan() || e > TOLERANCE
                    });
                if bad {
                    differ.push(i);
                }
                answers.push(a);
            }
            Err(f) => return (first_panic.note(exercise, FILE, &cases[i].0, &f), None),
        }
    }
    let n = cases.len();
    let note = match differ.first() {
        None => format!(
            "Your {what} matches the reference at all {n} inputs it was tried on (the first: {}).",
            cases[0].0
        ),
        Some(&i) => {
            let first = compare_note(what, &cases[i].0, &answers[i], &cases[i].1, TOLERANCE).1;
            let others: Vec<&str> = differ[1..]
                .iter()
                .take(3)
                .map(|&k| cases[k].0.as_str())
                .collect();
            let more = if others.is_empty() {
                String::new()
            } else if differ.len() > 4 {
                format!(
                    " Also at {} and {} more.",
                    others.join("; "),
                    differ.len() - 4
                )
            } else {
                format!(" Also at {}.", others.join("; "))
            };
            format!(
                "{first} It differs at {} of the {n} inputs tried.{more}",
                differ.len()
            )
        }
    };
    (note, Some(answers))
}

/// A diverging colour for a noise value (linear RGBA): red above 0, blue below, white at 0, full
/// colour at `|n| ≥ 0.6` (one octave of 2D noise seldom passes ±0.7).
pub fn diverging_color(n: f32) -> glam::Vec4 {
    let t = (n.abs() / 0.6).min(1.0);
    let end = if n >= 0.0 {
        palette::RED
    } else {
        palette::BLUE
    };
    Vec3::splat(0.85).lerp(end, t).extend(1.0)
}

/// Declares a terrain over `[−1, 1]²` as what must stay in view, between its lowest and highest
/// vertex, so no corner is cut at any canvas size.
fn keep_terrain_in_view(frame: &mut Frame, terrain: &Terrain) {
    let (lo, hi) = terrain
        .positions
        .iter()
        .fold((0.0f32, 0.0f32), |(lo, hi), p| (lo.min(p.y), hi.max(p.y)));
    frame.keep_box_in_view(Vec3::new(-1.0, lo, -1.0), Vec3::new(1.0, hi, 1.0));
}

/// Terrains a figure shows, for the web layer to upload: each with its model matrix.
///
/// A setter only raises the figure's `stale` flag, so a page that sets five parameters in a row
/// pays for one regeneration; regenerating raises `dirty`, which the web layer takes to know
/// when to upload the terrains again.
pub trait TerrainFigure {
    /// The terrains, in the order their mesh ids are passed to `draw`.
    fn terrains(&self) -> Vec<&Terrain>;
    /// Raised by a setter: the terrains no longer match the parameters.
    fn stale(&mut self) -> &mut bool;
    /// Raised by [`TerrainFigure::rebuild`]: the terrains changed since the web layer took them.
    fn dirty(&mut self) -> &mut bool;
    /// Regenerates the terrains from the parameters and raises `dirty`. The setters validated
    /// the parameters, so this fails only on a bug; then the old terrains stay.
    fn rebuild(&mut self) -> Result<(), String>;

    /// Regenerates what the setters marked stale, then returns true once after the terrains
    /// changed (the web layer then re-uploads them).
    fn take_dirty(&mut self) -> bool {
        if std::mem::take(self.stale()) && self.rebuild().is_err() {
            return false;
        }
        std::mem::take(self.dirty())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 1: 1D noise.

/// Figure 1: 1D gradient noise over `x ∈ [0, 8]`. Each integer has a slope (its gradient); in the
/// cell around the probe the two ramps `g₀ t` and `g₁ (t − 1)` are drawn and blended by `fade`.
pub struct Noise1d {
    perm: Permutation,
    probe_x: f32,
    show_ramps: bool,
    use_exercise: bool,
    runner: Runner,
    first_panic: FirstPanic,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the probe's name
    /// takes the first place round its dot there that covers no line, dot or name.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

/// Screen mapping of Figure 1: x ∈ [0, 8] to [−4, 4], values ×4.
const X0: f32 = 4.0;
const Y_SCALE: f32 = 4.0;
/// Half the length along x of the tick that shows a lattice point's gradient.
const TICK_HALF: f32 = 0.3;
/// Samples of Figure 1's curve over x ∈ [0, 8].
const CURVE_SAMPLES: usize = 800;
/// Room kept above and below what Figure 1 must show, in noise units (×[`Y_SCALE`] metres):
/// the ramps run on that far past the curve, and the pink label above the probe has space.
pub const RAMP_MARGIN: f32 = 0.1;

impl Default for Noise1d {
    fn default() -> Self {
        Self::new()
    }
}

impl Noise1d {
    pub fn new() -> Self {
        Self {
            perm: Permutation::perlin(),
            probe_x: 2.35,
            show_ramps: true,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            first_panic: FirstPanic::default(),
            view: None,
        }
    }
    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the probe's name is placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }
    pub fn set_seed(&mut self, seed: f32) -> Result<(), String> {
        self.perm = permutation_for_seed(check_seed(seed)?);
        Ok(())
    }
    pub fn set_probe(&mut self, x: f32) -> Result<(), String> {
        self.probe_x = in_range("x", x, 0.0, 7.999)?;
        Ok(())
    }
    pub fn set_show_ramps(&mut self, on: bool) {
        self.show_ramps = on;
    }
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.first_panic.clear();
    }

    fn to_world(x: f32, y: f32) -> Vec3 {
        Vec3::new(x - X0, y * Y_SCALE, 0.0)
    }

    /// `fade(t)` and `fade′(t)` from the student's exercise 5.1 (with "use my exercise", when it
    /// answers), else the reference.
    fn fade_pair(&self, t: f32) -> [f32; 2] {
        let reference = [fade(t), fade_derivative(t)];
        if !self.use_exercise {
            return reference;
        }
        match run::fade(self.runner, t) {
            Ok(yours) => yours,
            Err(failure) => {
                self.first_panic
                    .record(&format!("t = {}", format_number(t)), &failure);
                reference
            }
        }
    }

    /// The verdict on the student's 5.1 at the probe's t and at t = 0, ¼, ½, ¾, 1 (the ends are
    /// where a wrong derivative shows).
    fn fade_verdict(&self, t: f32) -> String {
        let ts = [t, 0.0, 0.25, 0.5, 0.75, 1.0];
        let cases: Vec<(String, Vec<f32>)> = ts
            .iter()
            .map(|&t| {
                (
                    format!("t = {}", format_number(t)),
                    vec![fade(t), fade_derivative(t)],
                )
            })
            .collect();
        probe_verdict(
            "fade (5.1)",
            "exercise 5.1 fade",
            &self.first_panic,
            &cases,
            |i| run::fade(self.runner, ts[i]).map(|v| v.to_vec()),
        )
        .0
    }

    /// The probe's cell, its `t`, the two gradients `(g₀, g₁)` and the two ramps' values at
    /// the probe `(g₀ t, g₁ (t − 1))`.
    fn probe_ramps(&self) -> (i32, f32, (f32, f32), (f32, f32)) {
        let cell = self.probe_x.floor() as i32;
        let t = self.probe_x - cell as f32;
        let (g0, g1) = (
            grad1(self.perm.hash1(cell)),
            grad1(self.perm.hash1(cell + 1)),
        );
        (cell, t, (g0, g1), (g0 * t, g1 * (t - 1.0)))
    }

    /// What must stay in view, `(min, max)`, in world space: the lattice from 0 to 8 with its
    /// gradient ticks, the curve, and the probe's dots on the two ramps, with [`RAMP_MARGIN`]
    /// above and below. The ramps are drawn only inside it (a steep ramp rises by up to 1 over
    /// its cell, about twice the curve's height), so the curve fills the view; the box grows
    /// only while the probe's dots on a steep ramp lie beyond the curve, and the camera
    /// re-fits then.
    pub fn view_box(&self) -> (Vec3, Vec3) {
        let (_, _, _, (a, b)) = self.probe_ramps();
        let (mut lo, mut hi) = (a.min(b).min(0.0), a.max(b).max(0.0));
        for i in 0..=8 {
            let tick = TICK_HALF * grad1(self.perm.hash1(i)).abs();
            (lo, hi) = (lo.min(-tick), hi.max(tick));
        }
        for k in 0..=CURVE_SAMPLES {
            let n = self.perm.noise1(k as f32 * 8.0 / CURVE_SAMPLES as f32);
            (lo, hi) = (lo.min(n), hi.max(n));
        }
        (
            Self::to_world(-TICK_HALF, lo - RAMP_MARGIN),
            Self::to_world(8.0 + TICK_HALF, hi + RAMP_MARGIN),
        )
    }

    /// Draws the figure; returns its note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        let (lo, hi) = self.view_box();
        frame.keep_box_in_view(lo, hi);
        // A graph in the plane z = 0: a drag pans it rather than turning it edge-on.
        frame.flat = true;
        frame.line(
            Self::to_world(0.0, 0.0),
            Self::to_world(8.0, 0.0),
            palette::GRID_AXIS,
        );
        let curve: Vec<Vec3> = (0..=CURVE_SAMPLES)
            .map(|k| {
                let x = k as f32 * 8.0 / CURVE_SAMPLES as f32;
                Self::to_world(x, self.perm.noise1(x))
            })
            .collect();
        frame.wide_polyline(&curve, palette::BLUE, crate::draw::CURVE_PX);
        let (cell, t, (g0, g1), (a, b)) = self.probe_ramps();
        for i in 0..=8 {
            let g = grad1(self.perm.hash1(i));
            let color = if i == cell {
                palette::ORANGE
            } else if i == cell + 1 {
                palette::TEAL
            } else {
                palette::GREY
            };
            let x = i as f32;
            frame.marker(Self::to_world(x, 0.0), 9.0, palette::KEY);
            // In three pieces, so that a label placed clear of the frame's strokes (sampled
            // along each piece) is clear of all of it: a steep tick is long on screen.
            let (from, to) = (
                Self::to_world(x - TICK_HALF, -TICK_HALF * g),
                Self::to_world(x + TICK_HALF, TICK_HALF * g),
            );
            let tick: [Vec3; 4] = std::array::from_fn(|k| from.lerp(to, k as f32 / 3.0));
            frame.wide_polyline(&tick, color, GUIDE_PX);
        }
        let x0 = cell as f32;
        if self.show_ramps {
            // Each ramp as far as it stays inside the view: `g₀ t` from t = 0 and `g₁ (t − 1)`
            // back from t = 1, up to where it leaves [lo, hi] (the probe's dots are inside).
            let (y_lo, y_hi) = (lo.y / Y_SCALE, hi.y / Y_SCALE);
            let reach = |g: f32| {
                if g > 0.0 {
                    (y_hi / g).min(1.0)
                } else if g < 0.0 {
                    (y_lo / g).min(1.0)
                } else {
                    1.0
                }
            };
            let (u0, u1) = (reach(g0), reach(-g1));
            frame.wide_polyline(
                &[Self::to_world(x0, 0.0), Self::to_world(x0 + u0, g0 * u0)],
                palette::ORANGE,
                GUIDE_PX,
            );
            frame.wide_polyline(
                &[
                    Self::to_world(x0 + 1.0 - u1, -g1 * u1),
                    Self::to_world(x0 + 1.0, 0.0),
                ],
                palette::TEAL,
                GUIDE_PX,
            );
            // Labels three quarters of the way out along what is drawn of each ramp, away from
            // the lattice point it starts at.
            frame.label(
                Self::to_world(x0 + 0.75 * u0, 0.75 * u0 * g0),
                "g₀·t",
                palette::ORANGE,
            );
            frame.label(
                Self::to_world(x0 + 1.0 - 0.75 * u1, -0.75 * u1 * g1),
                "g₁·(t − 1)",
                palette::TEAL,
            );
        }
        let [f, _] = self.fade_pair(t);
        let n = a + f * (b - a);
        if self.show_ramps {
            // Dots of a fixed size on screen, outlined, over the lines: the view is eight cells
            // wide, so a dot sized in metres would be a couple of pixels.
            frame.marker_on_top(Self::to_world(self.probe_x, a), 11.0, palette::ORANGE);
            frame.marker_on_top(Self::to_world(self.probe_x, b), 11.0, palette::TEAL);
            frame.wide_line(
                Self::to_world(self.probe_x, a),
                Self::to_world(self.probe_x, b),
                palette::GREY,
                GUIDE_PX,
            );
        }
        let at = Self::to_world(self.probe_x, n);
        frame.marker_on_top(at, 14.0, palette::PINK);
        // The probe's name at the first place round its dot, above first, on the last frame's
        // view, 2 px clear of the curve, the ramps, the ticks, the dots and the names: the
        // curve climbs steeply through the dot, and after an orbit it runs close beside it.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let candidates =
            crate::draw::Label::around_dot(at, 14.0, -Vec2::Y, "n(x)", palette::PINK, 0, 10, 8.0);
        frame.first_clear_label_by(view, 2.0, candidates, super::clear_of(view, &[]));
        let mut text = format!(
            "x = {}: cell [{}, {}], t = {}, fade(t) = {}; ramps g₀t = {}, g₁(t − 1) = {}; \
             n(x) = lerp(fade(t), g₀t, g₁(t − 1)) = {}.",
            format_number(self.probe_x),
            cell,
            cell + 1,
            format_number(t),
            format_number(f),
            format_number(a),
            format_number(b),
            format_number(n)
        );
        if self.use_exercise {
            text = format!("{text} {}", self.fade_verdict(t));
        }
        text
    }

    /// The fade curves for the plots: `[t, fade, fade′, 3t² − 2t³, fade″, (3t² − 2t³)″]` per
    /// row (fade and fade′ from the student's exercise when "use my exercise" is ticked and it
    /// answers). The second derivatives show the 1985 curve's jump in curvature: `6 − 12t` is 6
    /// at t = 0 and −6 at t = 1, where the quintic's `fade″` is 0.
    pub fn sample_fade(&self, samples: usize) -> Result<Vec<[f32; 6]>, String> {
        check_samples(samples)?;
        Ok((0..samples)
            .map(|i| {
                let t = i as f32 / (samples - 1) as f32;
                let [f, d] = self.fade_pair(t);
                [
                    t,
                    f,
                    d,
                    t * t * (3.0 - 2.0 * t),
                    fade_second_derivative(t),
                    6.0 - 12.0 * t,
                ]
            })
            .collect())
    }

    /// The probe's position inside its cell, `t ∈ [0, 1)` (the plot's cursor).
    pub fn probe_t(&self) -> f32 {
        self.probe_x.fract()
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 2: 2D noise, its lattice gradients, and slices of 3D noise.

/// Figure 2: one octave of 2D noise as a height field over noise coordinates `[−2, 2]²`, with the
/// gradient at every lattice point and a probe whose cell is outlined. `z` slices 3D noise.
pub struct Noise2d {
    perm: Permutation,
    terrain: Terrain,
    z: f32,
    probe: Vec2,
    use_exercise: bool,
    runner: Runner,
    first_panic: FirstPanic,
    dirty: bool,
    stale: bool,
    /// The camera and canvas size (CSS pixels) of the last frame, which the probe's value is
    /// placed for.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

/// Figure 2's terrain: `s = 2` noise cells per metre, so `u ∈ [−1, 1]` covers `x ∈ [−2, 2]`.
const FIG2_S: f32 = 2.0;
const FIG2_H: f32 = 0.6;
/// The radius of Figure 2's probe dot, metres.
const PROBE_RADIUS: f32 = 0.03;

impl Noise2d {
    pub fn new() -> Self {
        let mut s = Self {
            perm: Permutation::perlin(),
            terrain: Terrain::new(129).expect("a valid resolution"),
            z: 0.0,
            probe: Vec2::new(0.4, 0.7),
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            first_panic: FirstPanic::default(),
            dirty: true,
            stale: false,
            view: None,
        };
        s.regenerate();
        s
    }
    fn params(&self) -> TerrainParams {
        TerrainParams {
            fractal: Fractal {
                n: 0,
                alpha: 0.5,
                omega: 2.0,
            },
            h: FIG2_H,
            s: FIG2_S,
            o: 0.0,
            variant: if self.z == 0.0 {
                Variant::Sum
            } else {
                Variant::Evolving { t: self.z }
            },
        }
    }
    fn regenerate(&mut self) {
        let p = self.params();
        self.terrain
            .regenerate(&self.perm, &p)
            .expect("figure 2's parameters are valid");
        // One octave has a sign, and the sign is the lesson: a diverging palette instead of the
        // terrain's water, grass and snow.
        for (c, q) in self.terrain.colors.iter_mut().zip(&self.terrain.positions) {
            *c = diverging_color(q.y / FIG2_H);
        }
        self.dirty = true;
    }
    pub fn set_seed(&mut self, seed: f32) -> Result<(), String> {
        self.perm = permutation_for_seed(check_seed(seed)?);
        self.stale = true;
        Ok(())
    }
    /// The 3D slice `z` (0 is the 2D noise), in `[0, 2]`.
    pub fn set_z(&mut self, z: f32) -> Result<(), String> {
        self.z = in_range("z", z, 0.0, 2.0)?;
        self.stale = true;
        Ok(())
    }
    /// The probe in noise coordinates, each in `[−2, 2)`.
    pub fn set_probe(&mut self, x: f32, y: f32) -> Result<(), String> {
        self.probe = Vec2::new(
            in_range("probe x", x, -2.0, 1.999)?,
            in_range("probe y", y, -2.0, 1.999)?,
        );
        Ok(())
    }
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.first_panic.clear();
    }
    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the probe's value is placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    fn world(&self, p: Vec2, value: f32) -> Vec3 {
        Vec3::new(p.x / FIG2_S, FIG2_H * value, p.y / FIG2_S)
    }

    /// The noise value at the probe (the slice's, at z ≠ 0).
    pub fn probe_value(&self) -> f32 {
        self.perm.noise3(self.probe.x, self.probe.y, self.z)
    }

    /// The layers of 3D lattice points around the slice: `k = ⌊z⌋` and the weight
    /// `w = fade(z − k)` of layer `k + 1` (0 at an integer slice, where only layer k counts).
    pub fn layers(&self) -> (i32, f32) {
        let k = self.z.floor();
        (k as i32, fade(self.z - k))
    }

    /// The slice's value and slope `(∂n/∂x, ∂n/∂y)` right over lattice point `(i, j)`. There the
    /// x and y fades and their derivatives are 0, so only the two 3D lattice points `(i, j, k)` and
    /// `(i, j, k + 1)` count:
    /// ```text
    /// n = lerp(w, g_k.z (z − k), g_k+1.z (z − k − 1)),   ∇n = lerp(w, g_k.xy, g_k+1.xy)
    /// ```
    /// At an integer slice (w = 0, z = k) the value is 0 and the slope is layer k's gradient.
    pub fn dot_value_and_slope(&self, i: i32, j: i32) -> (f32, Vec2) {
        let (k, w) = self.layers();
        let t = self.z - k as f32;
        let (g0, g1) = (
            self.perm.gradient3(i, j, k),
            self.perm.gradient3(i, j, k + 1),
        );
        let value = g0.z * t + w * (g1.z * (t - 1.0) - g0.z * t);
        (value, g0.truncate().lerp(g1.truncate(), w))
    }

    /// The student's 5.2 over the probe's cell on a `STUDENT_GRID`² grid, compared with
    /// [`cell2`] at every grid point (and at the probe first). Returns the note and, when the
    /// exercise answered, the values row by row.
    fn student_cell(&self) -> (String, Option<Vec<f32>>) {
        let c = self.probe.floor();
        let (i, j) = (c.x as i32, c.y as i32);
        let g = [
            grad2(self.perm.hash2(i, j)),
            grad2(self.perm.hash2(i + 1, j)),
            grad2(self.perm.hash2(i, j + 1)),
            grad2(self.perm.hash2(i + 1, j + 1)),
        ];
        let last = (STUDENT_GRID - 1) as f32;
        let mut points = vec![self.probe - c];
        for b in 0..STUDENT_GRID {
            for a in 0..STUDENT_GRID {
                points.push(Vec2::new(a as f32 / last, b as f32 / last));
            }
        }
        let cases: Vec<(String, Vec<f32>)> = points
            .iter()
            .map(|&p| {
                (
                    format!(
                        "p = ({}, {}) in the cell",
                        format_number(p.x),
                        format_number(p.y)
                    ),
                    vec![cell2(p, g)],
                )
            })
            .collect();
        let (note, answers) = probe_verdict(
            "perlin_cell (5.2)",
            "exercise 5.2 perlin_cell",
            &self.first_panic,
            &cases,
            |k| run::perlin_cell(self.runner, points[k], g[0], g[1], g[2], g[3]).map(|v| vec![v]),
        );
        (note, answers.map(|a| a[1..].iter().map(|v| v[0]).collect()))
    }

    pub fn draw(&self, frame: &mut Frame, mesh: MeshId) -> String {
        frame.mesh_vertex_colors(mesh, Mat4::IDENTITY);
        keep_terrain_in_view(frame, &self.terrain);
        let lift = Vec3::Y * 0.01;
        for j in -2..=2 {
            for i in -2..=2 {
                let p = Vec2::new(i as f32, j as f32);
                let (value, slope) = self.dot_value_and_slope(i, j);
                let at = self.world(p, value) + lift;
                if value == 0.0 {
                    frame.point(at, 0.025, palette::KEY);
                } else {
                    // Between layers the dot stays at height 0 and a stick joins it to the
                    // surface; both are drawn through the surface, which hides half of them.
                    let dot = self.world(p, 0.0) + lift;
                    frame.point_on_top(dot, 0.025, palette::KEY);
                    frame.stroke(
                        &[dot, at],
                        palette::KEY,
                        StrokeStyle {
                            on_top: true,
                            ..StrokeStyle::solid(1.5)
                        },
                    );
                }
                if slope != Vec2::ZERO {
                    let tip = at + Vec3::new(slope.x, 0.0, slope.y) * 0.18;
                    frame.arrow(at, tip, palette::ORANGE, 0.05);
                }
            }
        }
        let c = self.probe.floor();
        let corners = [c, c + Vec2::X, c + Vec2::ONE, c + Vec2::Y, c];
        let outline: Vec<Vec3> = corners.iter().map(|&p| self.world(p, 0.0) + lift).collect();
        frame.wide_polyline(&outline, palette::PURPLE, GUIDE_PX);
        let value = self.probe_value();
        let at = self.world(self.probe, value);
        frame.point(at, PROBE_RADIUS, palette::PINK);
        // Through the surface, as the black sticks: it runs from height 0 to the surface, inside
        // the hill or the hollow round the probe, which hides half of it from most views.
        frame.wide_line_on_top(self.world(self.probe, 0.0), at, palette::PINK, GUIDE_PX);
        // The value above the probe's dot; where the cell's square, the sticks or the arrows
        // run there (on the last frame's view), the first place round the dot clear of them,
        // above it first.
        let text = format!("n = {}", format_number(value));
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let first = crate::draw::Label {
            anchor: at + Vec3::Y * 0.12,
            text: text.clone(),
            color: palette::PINK,
            left: false,
            priority: 0,
            offset_px: Vec2::ZERO,
            large: false,
        };
        // The dot's width on screen: the most a radius along any axis spans there.
        let dot_px = view.map_or(0.0, |(view_proj, size)| {
            let px = |p| crate::camera::project_to_canvas(view_proj, size, p);
            [Vec3::X, Vec3::Y, Vec3::Z]
                .iter()
                .filter_map(|&axis| Some(px(at + axis * PROBE_RADIUS)?.distance(px(at)?)))
                .fold(0.0, f32::max)
                * 2.0
        });
        let around =
            crate::draw::Label::around_dot(at, dot_px, -Vec2::Y, &text, palette::PINK, 0, 6, 8.0);
        frame.first_clear_label_by(view, 2.0, std::iter::once(first).chain(around), |_| true);
        let mut note = format!(
            "Probe ({}, {}) in cell [{}, {}] × [{}, {}]: n = {}.",
            format_number(self.probe.x),
            format_number(self.probe.y),
            c.x,
            c.x + 1.0,
            c.y,
            c.y + 1.0,
            format_number(value)
        );
        let (k, w) = self.layers();
        if w == 0.0 && k == 0 {
            note += " The slice z = 0 is the 2D noise: 0 at every dot, and each arrow is the \
                     gradient there.";
        } else if w == 0.0 {
            note += &format!(
                " z = {k} is an integer: the slice passes through the 3D lattice points of layer \
                 {k}, so the surface is 0 at every dot again, with that layer's gradients (other \
                 arrows than at z = 0)."
            );
        } else {
            note += &format!(
                " The slice z = {} lies between the lattice layers z = {k} and z = {}: at a dot the \
                 value and the slope (arrow) blend those two layers' gradients with weight \
                 fade({}) = {} on layer {}, so the surface is no longer 0 at the dots (each \
                 black stick joins a dot to the surface).",
                format_number(self.z),
                k + 1,
                format_number(self.z - k as f32),
                format_number(w),
                k + 1
            );
        }
        if self.use_exercise {
            let (verdict, values) = self.student_cell();
            if let Some(values) = values {
                let point = |a: usize, b: usize| {
                    let last = (STUDENT_GRID - 1) as f32;
                    let p = c + Vec2::new(a as f32 / last, b as f32 / last);
                    self.world(p, values[b * STUDENT_GRID + a]) + lift * 2.0
                };
                for b in 0..STUDENT_GRID {
                    let row: Vec<Vec3> = (0..STUDENT_GRID).map(|a| point(a, b)).collect();
                    frame.wide_polyline(&row, palette::STUDENT, 1.5);
                    let col: Vec<Vec3> = (0..STUDENT_GRID).map(|a| point(b, a)).collect();
                    frame.wide_polyline(&col, palette::STUDENT, 1.5);
                }
                frame.label(
                    point(STUDENT_GRID - 1, STUDENT_GRID - 1),
                    "yours",
                    palette::STUDENT,
                );
            }
            note += " ";
            note += &verdict;
            if self.z != 0.0 {
                note += " (Your 5.2 computes the 2D noise, the slice z = 0: set z to 0 to see \
                         your grid lie on the surface.)";
            }
        }
        note
    }
}

/// Grid points per side at which Figure 2 evaluates the student's 5.2 over the probe's cell.
pub const STUDENT_GRID: usize = 9;

impl Default for Noise2d {
    fn default() -> Self {
        Self::new()
    }
}

impl TerrainFigure for Noise2d {
    fn terrains(&self) -> Vec<&Terrain> {
        vec![&self.terrain]
    }
    fn stale(&mut self) -> &mut bool {
        &mut self.stale
    }
    fn dirty(&mut self) -> &mut bool {
        &mut self.dirty
    }
    fn rebuild(&mut self) -> Result<(), String> {
        self.regenerate();
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 3: octaves one by one.

/// The last octave Figure 3's slider reaches.
pub const OCTAVES_MAX_N: u32 = 9;

/// Figure 3: the fractal sum with octaves 0..=N; the profile along `v = V_SLICE` is drawn on the
/// terrain (orange, with the sum without the newest octave in dark grey) and plotted octave by
/// octave. Octaves finer than the mesh can show ([`last_resolved_octave`]) are named in the note,
/// greyed in the plot, and left out of the surface with "leave out octaves finer than the mesh".
pub struct Octaves {
    perm: Permutation,
    fractal: Fractal,
    band_limit: bool,
    terrain: Terrain,
    use_exercise: bool,
    runner: Runner,
    first_panic: FirstPanic,
    /// The student's 5.3 along the profile for the figure's current sum, with its verdict
    /// (computed once per change of N, α, ω or the runner: hundreds of calls).
    student: Option<(Fractal, String, Option<Vec<f32>>)>,
    dirty: bool,
    stale: bool,
    /// The camera and canvas size (CSS pixels) of the last frame, which the profile's name is
    /// placed for.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

/// Width of Figure 3's orange profile, CSS pixels: 1.5 px either side of the dark dashed
/// profile drawn over it.
pub const PROFILE_PX: f32 = 4.5;
/// The profile's v (world z).
pub const V_SLICE: f32 = 0.25;
const FIG3_H: f32 = 0.5;
/// Vertices per side of Figure 3's mesh.
pub const OCTAVES_RESOLUTION: usize = 193;
/// Points along the drawn profiles (the student's too): 0.005 m apart, fine enough for every
/// octave up to 6.
pub const PROFILE_POINTS: usize = 401;

impl Octaves {
    pub fn new() -> Self {
        let mut s = Self {
            perm: Permutation::perlin(),
            fractal: Fractal {
                n: 3,
                alpha: 0.5,
                omega: 2.0,
            },
            band_limit: false,
            terrain: Terrain::new(OCTAVES_RESOLUTION).expect("a valid resolution"),
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            first_panic: FirstPanic::default(),
            student: None,
            dirty: true,
            stale: false,
            view: None,
        };
        s.regenerate();
        s
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the profile's name is placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// The last octave the mesh shows faithfully (`None`: not even octave 0).
    pub fn last_resolved_octave(&self) -> Option<u32> {
        last_resolved_octave(OCTAVES_RESOLUTION, 1.0, self.fractal.omega)
    }

    /// The sum the surface and the orange profile show: octaves 0..=N, or only those the mesh
    /// can show when "leave out octaves finer than the mesh" is ticked.
    pub fn shown_fractal(&self) -> Fractal {
        let mut f = self.fractal;
        if self.band_limit {
            f.n = f.n.min(self.last_resolved_octave().unwrap_or(0));
        }
        f
    }

    fn params(&self) -> TerrainParams {
        TerrainParams {
            fractal: self.shown_fractal(),
            h: FIG3_H,
            s: 1.0,
            o: 0.0,
            variant: Variant::Sum,
        }
    }
    fn regenerate(&mut self) {
        let p = self.params();
        self.terrain
            .regenerate(&self.perm, &p)
            .expect("figure 3's parameters are checked");
        self.dirty = true;
    }
    /// N ∈ 0..=9, α ∈ [0, 1], ω ∈ [1, 4].
    pub fn set_params(&mut self, n: f32, alpha: f32, omega: f32) -> Result<(), String> {
        let f = Fractal {
            n: check_n(n, OCTAVES_MAX_N)?,
            alpha: in_range("alpha", alpha, 0.0, 1.0)?,
            omega: in_range("omega", omega, 1.0, 4.0)?,
        };
        f.validate()?;
        self.fractal = f;
        self.stale = true;
        Ok(())
    }
    /// Leaves the octaves finer than the mesh out of the surface and the orange profile.
    pub fn set_band_limit(&mut self, on: bool) {
        if on != self.band_limit {
            self.band_limit = on;
            self.stale = true;
        }
    }
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.first_panic.clear();
        self.student = None;
    }

    /// The profile along `v = V_SLICE`: per row `[u, octave 0, …, octave 9, sum]` where octaves
    /// above N are NaN (the plot leaves them out). The sum is the figure's (without the octaves
    /// finer than the mesh when those are left out); each octave is plotted whole.
    pub fn sample_octaves(&self, samples: usize) -> Result<Vec<[f32; 12]>, String> {
        check_samples(samples)?;
        let shown = self.shown_fractal().n;
        Ok((0..samples)
            .map(|i| {
                let u = -1.0 + 2.0 * i as f32 / (samples - 1) as f32;
                let mut row = [f32::NAN; 12];
                row[0] = u;
                let mut sum = 0.0;
                for k in 0..=self.fractal.n {
                    let o = self.fractal.octave2(&self.perm, k, u, V_SLICE);
                    row[1 + k as usize] = o;
                    if k <= shown {
                        sum += o;
                    }
                }
                row[11] = sum;
                row
            })
            .collect())
    }

    /// The u of profile point i.
    fn profile_u(i: usize) -> f32 {
        -1.0 + 2.0 * i as f32 / (PROFILE_POINTS - 1) as f32
    }

    /// Runs the student's 5.3 along the profile for the shown sum (once per change).
    fn update_student(&mut self) {
        let f = self.shown_fractal();
        if matches!(&self.student, Some((cached, _, _)) if *cached == f) {
            return;
        }
        let points: Vec<Vec2> = (0..PROFILE_POINTS)
            .map(|i| Vec2::new(Self::profile_u(i), V_SLICE))
            .collect();
        let reference = Permutation::perlin();
        let cases: Vec<(String, Vec<f32>)> = points
            .iter()
            .map(|p| {
                (
                    format!("p = ({}, {})", format_number(p.x), format_number(p.y)),
                    vec![f.sum2(&reference, p.x, p.y)],
                )
            })
            .collect();
        let runner = self.runner;
        let (note, answers) = probe_verdict(
            "fractal_sum (5.3)",
            "exercise 5.3 fractal_sum",
            &self.first_panic,
            &cases,
            |i| {
                run::fractal_sum(runner, points[i], f.n as usize, f.alpha, f.omega).map(|v| vec![v])
            },
        );
        self.student = Some((f, note, answers.map(|a| a.iter().map(|v| v[0]).collect())));
    }

    pub fn draw(&mut self, frame: &mut Frame, mesh: MeshId) -> String {
        frame.mesh_vertex_colors(mesh, Mat4::IDENTITY);
        keep_terrain_in_view(frame, &self.terrain);
        let lift = Vec3::Y * 0.004;
        let shown = self.shown_fractal();
        let previous = Fractal {
            n: shown.n.saturating_sub(1),
            ..shown
        };
        let profile = |f: &Fractal| -> Vec<Vec3> {
            (0..PROFILE_POINTS)
                .map(|i| {
                    let u = Self::profile_u(i);
                    Vec3::new(u, FIG3_H * f.sum2(&self.perm, u, V_SLICE), V_SLICE) + lift
                })
                .collect()
        };
        // Both profiles over the surface: at α = 0.8 the fine octaves' spikes stand in front of
        // the line v = 0.25 from any view, and the profile is what the plot below draws. The
        // dark one thin and dashed over the wide orange one: where the newest octave adds next
        // to nothing the two lie on one line, and both still show.
        let over = |style| StrokeStyle {
            on_top: true,
            ..style
        };
        let orange = over(StrokeStyle::solid(PROFILE_PX));
        let line = profile(&shown);
        frame.stroke(&line, palette::ORANGE, orange);
        if shown.n > 0 {
            let dashed = over(StrokeStyle::dashed(1.5, 0.03, 0.03));
            frame.stroke(&profile(&previous), palette::DARK, dashed);
        }
        // The profile's name at the first place round its end at u = 1, then round its end at
        // u = −1 (orbited, one end lies inside the surface's outline), on the last frame's
        // view, that covers no part of the surface (every 2nd vertex: an aliased spike is one
        // vertex wide): over the grey spikes the orange name does not read.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let r = OCTAVES_RESOLUTION;
        let surface: Vec<Vec3> = (0..r * r)
            .filter(|k| (k % r) % 2 == 0 && (k / r) % 2 == 0)
            .map(|k| self.terrain.positions[k])
            .collect();
        let text = format!("v = {V_SLICE}");
        let around = |end: Vec3, toward: Vec2| {
            crate::draw::Label::around_dot(
                end,
                PROFILE_PX,
                toward,
                &text,
                palette::ORANGE,
                0,
                12,
                8.0,
            )
        };
        let mut candidates = around(line[PROFILE_POINTS - 1], Vec2::X);
        candidates.extend(around(line[0], -Vec2::X));
        frame.first_clear_label_by(view, 0.0, candidates, super::clear_of(view, &surface));
        let k = self.fractal.n;
        let mut note = format!(
            "{} octave{}: the newest, k = {k}, has amplitude αᵏ = {} and frequency ωᵏ = {} \
             (wavelength {} m).",
            k + 1,
            if k == 0 { "" } else { "s" },
            format_number(self.fractal.alpha.powi(k as i32)),
            format_number(self.fractal.omega.powi(k as i32)),
            format_number(1.0 / self.fractal.omega.powi(k as i32))
        );
        let spacing = 2.0 / (OCTAVES_RESOLUTION - 1) as f32;
        match self.last_resolved_octave() {
            Some(last) if last >= k => {
                if self.band_limit {
                    note += &format!(
                        " The mesh shows octaves up to {}, so none of these is left out: \
                         raise N past it to see the difference.",
                        last.min(OCTAVES_MAX_N)
                    );
                }
            }
            last => {
                let first = last.map_or(0, |l| l + 1);
                let range = if first == k {
                    format!("Octave {k} is")
                } else if first + 1 == k {
                    format!("Octaves {first} and {k} are")
                } else {
                    format!("Octaves {first} to {k} are")
                };
                note += &format!(
                    " {range} finer than the mesh: its vertices are {} m apart, and a cell \
                     no wider than two spacings ({} m) falls between vertices and comes back as \
                     spikes (aliasing); they are grey in the plot.{}",
                    format_number(spacing),
                    format_number(2.0 * spacing),
                    if self.band_limit {
                        // The finest octave kept (octave 0 at least, as the surface keeps it) can
                        // still be a bed of narrow spikes (ω = 3.37: cells of 2.5 spacings), so
                        // the note says which octave they are.
                        let l = last.unwrap_or(0) as i32;
                        format!(
                            " They are left out of the surface: what stays rough there is octave \
                             {l}, whose cells are {} vertex spacings wide.",
                            format_number(self.fractal.omega.powi(-l) / spacing)
                        )
                    } else {
                        " Tick “leave out octaves finer than the mesh” to drop them.".into()
                    }
                );
            }
        }
        if self.use_exercise {
            self.update_student();
            if let Some((_, verdict, values)) = &self.student {
                if let Some(values) = values {
                    let line: Vec<Vec3> = values
                        .iter()
                        .enumerate()
                        .map(|(i, &g)| {
                            Vec3::new(Self::profile_u(i), FIG3_H * g, V_SLICE) + lift * 2.0
                        })
                        .collect();
                    frame.wide_polyline(&line, palette::STUDENT, crate::draw::CURVE_PX);
                    frame.label(
                        Vec3::new(-1.05, FIG3_H * values[0], V_SLICE),
                        "yours",
                        palette::STUDENT,
                    );
                }
                note += " ";
                note += verdict;
                if values.is_some() {
                    note += &format!(" Your sum is the pink line along v = {V_SLICE}.");
                }
            }
        }
        note
    }
}

impl Default for Octaves {
    fn default() -> Self {
        Self::new()
    }
}

impl TerrainFigure for Octaves {
    fn terrains(&self) -> Vec<&Terrain> {
        vec![&self.terrain]
    }
    fn stale(&mut self) -> &mut bool {
        &mut self.stale
    }
    fn dirty(&mut self) -> &mut bool {
        &mut self.dirty
    }
    fn rebuild(&mut self) -> Result<(), String> {
        self.regenerate();
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 4: the course's terrain.

/// The variants Figure 4's dropdown offers, in its order.
pub const VARIANT_NAMES: [&str; 6] = [
    "sum",
    "ridge",
    "inverted ridge",
    "marble",
    "sliding f(x, y + t)",
    "evolving f(x, y, t)",
];

/// The resolutions Figure 4 offers (vertices per side).
pub const TERRAIN_RESOLUTIONS: [usize; 4] = [64, 128, 256, 512];

/// Figure 4: `S(u, v) = (u, h g(s(u + o), s(v + o)), v)` with every parameter, five variants, and
/// the normal at a probe vertex (reference and, with "use my exercise", the student's).
pub struct TerrainScene {
    perm: Permutation,
    params: TerrainParams,
    variant: usize,
    time_sec: f32,
    terrain: Terrain,
    band_limit: bool,
    use_exercise: bool,
    runner: Runner,
    first_panic: FirstPanic,
    dirty: bool,
    stale: bool,
}

impl TerrainScene {
    pub fn new() -> Self {
        let mut s = Self {
            perm: Permutation::perlin(),
            params: TerrainParams::default(),
            variant: 0,
            time_sec: 0.0,
            terrain: Terrain::new(128).expect("a valid resolution"),
            band_limit: false,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            first_panic: FirstPanic::default(),
            dirty: true,
            stale: false,
        };
        s.regenerate().expect("the course's parameters are valid");
        s
    }

    fn regenerate(&mut self) -> Result<(), String> {
        let t = self.time_sec;
        self.params.variant = match self.variant {
            0 => Variant::Sum,
            1 => Variant::Ridge,
            2 => Variant::InvertedRidge,
            3 => Variant::Marble,
            4 => Variant::Sliding { t: 0.3 * t },
            _ => Variant::Evolving { t: 0.3 * t },
        };
        let shown = self.shown_params();
        self.terrain.regenerate(&self.perm, &shown)?;
        self.dirty = true;
        Ok(())
    }

    /// The last octave the mesh shows faithfully at the current resolution, s and ω.
    pub fn last_resolved_octave(&self) -> Option<u32> {
        last_resolved_octave(
            self.terrain.resolution(),
            self.params.s,
            self.params.fractal.omega,
        )
    }

    /// The parameters the surface is built from: N capped at the last octave the mesh can show
    /// when "leave out octaves finer than the mesh" is ticked.
    pub fn shown_params(&self) -> TerrainParams {
        let mut p = self.params;
        if self.band_limit {
            p.fractal.n = p.fractal.n.min(self.last_resolved_octave().unwrap_or(0));
        }
        p
    }

    /// Leaves the octaves finer than the mesh out of the surface.
    pub fn set_band_limit(&mut self, on: bool) {
        if on != self.band_limit {
            self.band_limit = on;
            self.stale = true;
        }
    }

    /// Sets N, α, ω, h, s, o (checked by name; nothing changes on an error).
    #[allow(clippy::too_many_arguments)]
    pub fn set_params(
        &mut self,
        n: f32,
        alpha: f32,
        omega: f32,
        h: f32,
        s: f32,
        o: f32,
    ) -> Result<(), String> {
        let fractal = Fractal {
            n: check_n(n, crate::noise::MAX_N)?,
            alpha: in_range("alpha", alpha, 0.0, 1.0)?,
            omega: in_range("omega", omega, 1.0, 4.0)?,
        };
        let p = TerrainParams {
            fractal,
            h: in_range("h", h, 0.0, 2.0)?,
            s: in_range("s", s, 0.01, 16.0)?,
            o: in_range("o", o, -1000.0, 1000.0)?,
            variant: self.params.variant,
        };
        p.validate()?;
        self.params = p;
        self.stale = true;
        Ok(())
    }

    /// One of [`VARIANT_NAMES`], by index.
    pub fn set_variant(&mut self, index: usize) -> Result<(), String> {
        if index >= VARIANT_NAMES.len() {
            return Err(format!(
                "variant must be 0 to {}, got {index}",
                VARIANT_NAMES.len() - 1
            ));
        }
        self.variant = index;
        self.stale = true;
        Ok(())
    }

    /// Vertices per side, one of [`TERRAIN_RESOLUTIONS`] (or any in 2..=MAX_RESOLUTION);
    /// reallocates only when it changes.
    pub fn set_resolution(&mut self, resolution: usize) -> Result<(), String> {
        if resolution != self.terrain.resolution() {
            if !(2..=MAX_RESOLUTION).contains(&resolution) {
                return Err(format!(
                    "resolution must be between 2 and {MAX_RESOLUTION}, got {resolution}"
                ));
            }
            self.terrain = Terrain::new(resolution)?;
            self.stale = true;
        }
        Ok(())
    }

    pub fn set_seed(&mut self, seed: f32) -> Result<(), String> {
        self.perm = permutation_for_seed(check_seed(seed)?);
        self.stale = true;
        Ok(())
    }

    /// True when a setter changed something the next upload will regenerate.
    pub fn is_stale(&self) -> bool {
        self.stale
    }

    /// True for the variants that move with time.
    pub fn animated(&self) -> bool {
        self.variant >= 4
    }

    /// Advances time by `dt_sec` and regenerates the animated variants.
    pub fn advance(&mut self, dt_sec: f32) -> Result<(), String> {
        let dt = in_range("dt", dt_sec, 0.0, 1.0)?;
        if self.animated() {
            self.time_sec = (self.time_sec + dt) % 1000.0;
            self.stale = true;
        }
        Ok(())
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.first_panic.clear();
    }

    pub fn params(&self) -> TerrainParams {
        self.params
    }

    /// The probe vertex: halfway across, a quarter of the way in from the near edge (at the
    /// defaults, a slope facing the camera's side, where the grey arrow stands out).
    fn probe_index(&self) -> usize {
        let r = self.terrain.resolution();
        (3 * r / 4) * r + r / 2
    }

    /// The inputs at which "use my exercise" checks 5.4: the probe vertex first, four more
    /// vertices and the steepest one at the current settings, then the probe's gradient at other
    /// h and s (a normal that forgets s still matches at s = 1). Each is `(name, h, s, ∇g)`.
    fn normal_cases(&self) -> Vec<(String, f32, f32, Vec2)> {
        let p = self.shown_params();
        let r = self.terrain.resolution();
        let steepest = (0..self.terrain.normals.len())
            .min_by(|&a, &b| {
                self.terrain.normals[a]
                    .y
                    .total_cmp(&self.terrain.normals[b].y)
            })
            .unwrap_or(0);
        let vertices = [
            self.probe_index(),
            (r / 4) * r + r / 4,
            (r / 4) * r + 3 * r / 4,
            (r / 2) * r + r / 2,
            (3 * r / 4) * r + 3 * r / 4,
            steepest,
        ];
        let grad_at = |k: usize| {
            let q = self.terrain.positions[k];
            p.g(&self.perm, p.s * (q.x + p.o), p.s * (q.z + p.o)).1
        };
        let mut cases: Vec<(String, f32, f32, Vec2)> = vertices
            .iter()
            .enumerate()
            .map(|(i, &k)| {
                let q = self.terrain.positions[k];
                let what = match i {
                    0 => "the probe",
                    5 => "the steepest vertex",
                    _ => "the vertex",
                };
                (
                    format!(
                        "{what} (u = {}, v = {})",
                        format_number(q.x),
                        format_number(q.z)
                    ),
                    p.h,
                    p.s,
                    grad_at(k),
                )
            })
            .collect();
        let g = cases[0].3;
        for (h, s) in [(0.5, 2.0), (1.0, 0.5)] {
            cases.push((format!("the probe's ∇g with h = {h}, s = {s}"), h, s, g));
        }
        cases
    }

    pub fn draw(&self, frame: &mut Frame, mesh: MeshId) -> String {
        frame.mesh_vertex_colors(mesh, Mat4::IDENTITY);
        keep_terrain_in_view(frame, &self.terrain);
        let k = self.probe_index();
        let at = self.terrain.positions[k];
        let reference = self.terrain.normals[k];
        // The normals' shafts over the surface: on a rough terrain (s and h high) the peaks
        // round the vertex hide a depth-tested arrow. The reference's shaft is wide and outlined
        // in dark, so that its grey reads on water, grass, rock and snow alike; its name large.
        let tip = at + reference * 0.5;
        frame.wide_line_on_top(at, tip - reference * 0.08, palette::DARK, NORMAL_PX + 2.5);
        frame.wide_line_on_top(at, tip, palette::REFERENCE, NORMAL_PX);
        frame.arrow_on_top(at, tip, palette::REFERENCE, 0.08);
        frame.label_large(at + reference * 0.58, "n", palette::REFERENCE, 0);
        let p = &self.params;
        let r = self.terrain.resolution();
        let mut note = format!(
            "{r} × {r} vertices, {}: N = {}, α = {}, ω = {}, h = {}, s = {}, o = {}.",
            VARIANT_NAMES[self.variant],
            p.fractal.n,
            format_number(p.fractal.alpha),
            format_number(p.fractal.omega),
            format_number(p.h),
            format_number(p.s),
            format_number(p.o)
        );
        let spacing = 2.0 / (r - 1) as f32;
        let last = self.last_resolved_octave();
        if self.band_limit && last.is_some_and(|l| l >= p.fractal.n) {
            note += &format!(
                " This mesh shows octaves up to {}, so none is left out.",
                last.unwrap_or(0).min(crate::noise::MAX_N)
            );
        }
        if last.is_none_or(|l| l < p.fractal.n) {
            let first = last.map_or(0, |l| l + 1);
            let one = first == p.fractal.n;
            let range = if one {
                format!("octave {first} is")
            } else if first + 1 == p.fractal.n {
                format!("octaves {first} and {} are", p.fractal.n)
            } else {
                format!("octaves {first} to {} are", p.fractal.n)
            };
            // One octave or several: the rest of the sentence agrees.
            let (they, fall, add, are, them) = if one {
                ("it", "falls", "adds", "is", "it")
            } else {
                ("they", "fall", "add", "are", "them")
            };
            note += &format!(
                " The vertices are {} m apart, so {range} finer than the mesh (cells no wider \
                 than two spacings, {} m): {they} {fall} between vertices and only {add} \
                 aliasing{}.",
                format_number(spacing),
                format_number(2.0 * spacing),
                if self.band_limit {
                    format!(", and {are} left out")
                } else {
                    format!("; “leave out octaves finer than the mesh” drops {them}")
                }
            );
        }
        if self.use_exercise {
            let cases = self.normal_cases();
            let named: Vec<(String, Vec<f32>)> = cases
                .iter()
                .map(|(name, h, s, g)| {
                    (name.clone(), terrain_normal(*h, *s, *g).to_array().to_vec())
                })
                .collect();
            let (verdict, answers) = probe_verdict(
                "terrain_normal (5.4)",
                "exercise 5.4 terrain_normal",
                &self.first_panic,
                &named,
                |i| {
                    let (_, h, s, g) = cases[i];
                    run::terrain_normal(self.runner, h, s, g).map(|v| v.to_array().to_vec())
                },
            );
            if let Some(yours) = answers.as_ref().map(|a| Vec3::from_slice(&a[0])) {
                if yours.is_finite() && yours.length() > 1e-6 {
                    frame.arrow_on_top(at, at + yours.normalize() * 0.5, palette::STUDENT, 0.08);
                    // Reading leftwards, so that it sits beside the reference's "n" (which reads
                    // rightwards) when the two arrows coincide.
                    frame.label_left(at + yours.normalize() * 0.58, "yours", palette::STUDENT);
                }
            }
            note += " ";
            note += &verdict;
        }
        note
    }
}

impl Default for TerrainScene {
    fn default() -> Self {
        Self::new()
    }
}

impl TerrainFigure for TerrainScene {
    fn terrains(&self) -> Vec<&Terrain> {
        vec![&self.terrain]
    }
    fn stale(&mut self) -> &mut bool {
        &mut self.stale
    }
    fn dirty(&mut self) -> &mut bool {
        &mut self.dirty
    }
    fn rebuild(&mut self) -> Result<(), String> {
        self.regenerate()
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 5: exact normals against averaged ones.

/// The resolutions Figure 5 offers (vertices per side).
pub const NORMALS_RESOLUTIONS: [usize; 5] = [9, 17, 33, 65, 129];
/// The noise Figure 5 samples: octaves 0 to 3 of the course's sum.
const NORMALS_FRACTAL: Fractal = Fractal {
    n: 3,
    ..Fractal::COURSE
};
/// Arrows per side of Figure 5's terrain (every vertex at 9 × 9, fewer on finer meshes).
const NORMALS_ARROWS: usize = 9;
/// Length of Figure 5's normal arrows, metres.
const NORMAL_ARROW: f32 = 0.3;

/// Figure 5: one terrain, the same noise at every resolution, with two normals at each sampled
/// vertex: the exact one from the noise's derivative (grey) and the average of the faces around
/// the vertex (orange). The note measures the angle between them.
pub struct Normals {
    perm: Permutation,
    h: f32,
    terrain: Terrain,
    averaged: Vec<Vec3>,
    stale: bool,
    dirty: bool,
}

impl Normals {
    /// 17 × 17 vertices, h = 0.3.
    pub fn new() -> Self {
        let mut f = Self {
            perm: Permutation::perlin(),
            h: 0.3,
            terrain: Terrain::new(17).expect("a valid resolution"),
            averaged: Vec::new(),
            stale: false,
            dirty: true,
        };
        f.regenerate();
        f
    }

    /// Vertices per side, one of [`NORMALS_RESOLUTIONS`], and h in [0, 1]; checked by name,
    /// nothing changes on an error.
    pub fn set_params(&mut self, resolution: f32, h: f32) -> Result<(), String> {
        let r = in_range("resolution", resolution, 0.0, 1e4)?;
        if !NORMALS_RESOLUTIONS.iter().any(|&x| x as f32 == r) {
            return Err(format!(
                "resolution must be one of {NORMALS_RESOLUTIONS:?}, got {resolution}"
            ));
        }
        let h = in_range("h", h, 0.0, 1.0)?;
        if r as usize != self.terrain.resolution() {
            self.terrain = Terrain::new(r as usize)?;
        }
        self.h = h;
        self.stale = true;
        Ok(())
    }

    fn params(&self) -> TerrainParams {
        TerrainParams {
            fractal: NORMALS_FRACTAL,
            h: self.h,
            ..TerrainParams::default()
        }
    }

    fn regenerate(&mut self) {
        let p = self.params();
        self.terrain
            .regenerate(&self.perm, &p)
            .expect("the setters checked every parameter");
        self.averaged.resize(self.terrain.positions.len(), Vec3::Y);
        crate::raster::vertex_normals(
            &self.terrain.positions,
            &self.terrain.indices,
            &mut self.averaged,
        )
        .valid("the terrain's indices are valid");
        self.dirty = true;
    }

    /// The exact and the averaged normal of every vertex, in the terrain's order.
    pub fn normals(&self) -> (&[Vec3], &[Vec3]) {
        (&self.terrain.normals, &self.averaged)
    }

    /// The mean and the largest angle (degrees) between the exact and the averaged normal, over
    /// the vertices off the border (a border vertex has fewer faces to average).
    pub fn angle_stats(&self) -> (f32, f32) {
        let r = self.terrain.resolution();
        let mut sum = 0.0;
        let mut largest = 0.0f32;
        let mut count = 0;
        for j in 1..r - 1 {
            for i in 1..r - 1 {
                let k = j * r + i;
                let cos = self.terrain.normals[k]
                    .dot(self.averaged[k])
                    .clamp(-1.0, 1.0);
                let angle = cos.acos().to_degrees();
                sum += angle;
                largest = largest.max(angle);
                count += 1;
            }
        }
        (sum / count.max(1) as f32, largest)
    }

    /// The plot of the error against the mesh: `[vertices per side, mean angle (°), largest
    /// angle (°)]` for each of [`NORMALS_RESOLUTIONS`] at the current h (the same noise; builds
    /// each mesh once, so call it when a control changes, not every frame).
    pub fn angles_by_resolution(&self) -> Vec<[f32; 3]> {
        NORMALS_RESOLUTIONS
            .iter()
            .map(|&r| {
                let mut f = Self {
                    perm: self.perm.clone(),
                    h: self.h,
                    terrain: Terrain::new(r).expect("a valid resolution"),
                    averaged: Vec::new(),
                    stale: false,
                    dirty: false,
                };
                f.regenerate();
                let (mean, largest) = f.angle_stats();
                [r as f32, mean, largest]
            })
            .collect()
    }

    pub fn draw(&mut self, frame: &mut Frame, mesh: MeshId) -> String {
        if std::mem::take(&mut self.stale) {
            self.regenerate();
        }
        frame.mesh_vertex_colors(mesh, Mat4::IDENTITY);
        keep_terrain_in_view(frame, &self.terrain);
        frame.keep_box_in_view(
            Vec3::new(-1.0, 0.0, -1.0),
            Vec3::new(1.0, NORMAL_ARROW, 1.0),
        );
        let r = self.terrain.resolution();
        let stride = (r - 1) / (NORMALS_ARROWS - 1);
        for j in (0..r).step_by(stride) {
            for i in (0..r).step_by(stride) {
                let k = j * r + i;
                let at = self.terrain.positions[k];
                frame.arrow(
                    at,
                    at + self.terrain.normals[k] * NORMAL_ARROW,
                    palette::REFERENCE,
                    0.06,
                );
                frame.arrow(
                    at,
                    at + self.averaged[k] * NORMAL_ARROW,
                    palette::ORANGE,
                    0.06,
                );
            }
        }
        let (mean, largest) = self.angle_stats();
        format!(
            "{r} × {r} vertices, {} m apart, octaves 0 to {}, h = {}: off the border, the averaged \
             normals differ from the exact ones by {}° on average and {}° at most. Arrows at {} × \
             {} of the vertices.",
            format_number(2.0 / (r - 1) as f32),
            NORMALS_FRACTAL.n,
            format_number(self.h),
            format_angle(mean),
            format_angle(largest),
            NORMALS_ARROWS,
            NORMALS_ARROWS
        )
    }
}

/// An angle in degrees with one decimal.
fn format_angle(deg: f32) -> String {
    format!("{deg:.1}")
}

impl Default for Normals {
    fn default() -> Self {
        Self::new()
    }
}

impl TerrainFigure for Normals {
    fn terrains(&self) -> Vec<&Terrain> {
        vec![&self.terrain]
    }
    fn stale(&mut self) -> &mut bool {
        &mut self.stale
    }
    fn dirty(&mut self) -> &mut bool {
        &mut self.dirty
    }
    fn rebuild(&mut self) -> Result<(), String> {
        self.regenerate();
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 6: the variants side by side.

/// The variants Figure 6 sets side by side, in its order (back row, then front row).
pub const SIDE_BY_SIDE_VARIANTS: [(Variant, &str); 4] = [
    (Variant::Sum, "sum g"),
    (Variant::Ridge, "ridge Σ αᵏ|f|"),
    (Variant::InvertedRidge, "inverted ridge"),
    (Variant::Marble, "marble"),
];

/// Vertices per side of each of Figure 6's terrains.
pub const VARIANTS_RESOLUTION: usize = 129;

/// Figure 6: the sum, the ridge, the inverted ridge and marble side by side, built from the same
/// noise with the same N, α and h (ω = 2, s = 1, o = 0), without the octaves finer than their
/// mesh, so each difference comes from the variant alone.
pub struct Variants {
    perm: Permutation,
    fractal: Fractal,
    h: f32,
    terrains: Vec<Terrain>,
    stale: bool,
    dirty: bool,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the names take
    /// the first places round their corners there that cover no terrain.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

impl Variants {
    /// The course's N = 9 and α = 0.4, with h = 0.3.
    pub fn new() -> Self {
        let mut f = Self {
            perm: Permutation::perlin(),
            fractal: Fractal::COURSE,
            h: 0.3,
            terrains: (0..SIDE_BY_SIDE_VARIANTS.len())
                .map(|_| Terrain::new(VARIANTS_RESOLUTION).expect("a valid resolution"))
                .collect(),
            stale: false,
            dirty: true,
            view: None,
        };
        f.regenerate();
        f
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the names are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// Sets N (whole, 0 to [`OCTAVES_MAX_N`]), α in [0, 1] and h in [0, 2], checked by name;
    /// nothing changes on an error.
    pub fn set_params(&mut self, n: f32, alpha: f32, h: f32) -> Result<(), String> {
        let fractal = Fractal {
            n: check_n(n, OCTAVES_MAX_N)?,
            alpha: in_range("alpha", alpha, 0.0, 1.0)?,
            omega: 2.0,
        };
        let h = in_range("h", h, 0.0, 2.0)?;
        self.fractal = fractal;
        self.h = h;
        self.stale = true;
        Ok(())
    }

    /// The parameters variant `i` is built from: the last octave capped where the mesh stops
    /// resolving them.
    pub fn shown_params(&self, i: usize) -> TerrainParams {
        let last = last_resolved_octave(VARIANTS_RESOLUTION, 1.0, 2.0).unwrap_or(0);
        TerrainParams {
            fractal: Fractal {
                n: self.fractal.n.min(last),
                ..self.fractal
            },
            h: self.h,
            s: 1.0,
            o: 0.0,
            variant: SIDE_BY_SIDE_VARIANTS[i].0,
        }
    }

    fn regenerate(&mut self) {
        for i in 0..self.terrains.len() {
            let p = self.shown_params(i);
            self.terrains[i]
                .regenerate(&self.perm, &p)
                .expect("the setters checked every parameter");
        }
        self.dirty = true;
    }

    /// The lowest and the highest height (metres) of variant `i`'s terrain.
    pub fn height_range(&self, i: usize) -> (f32, f32) {
        self.terrains[i]
            .positions
            .iter()
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.y), hi.max(p.y))
            })
    }

    /// Where terrain i sits: two across, two deep.
    pub fn placement(i: usize) -> Vec3 {
        Vec3::new((i % 2) as f32 * 2.6 - 1.3, 0.0, (i / 2) as f32 * 2.7 - 1.35)
    }

    pub fn draw(&mut self, frame: &mut Frame, meshes: &[MeshId]) -> String {
        if std::mem::take(&mut self.stale) {
            self.regenerate();
        }
        for (i, &mesh) in meshes.iter().enumerate().take(self.terrains.len()) {
            frame.mesh_vertex_colors(mesh, Mat4::from_translation(Self::placement(i)));
        }
        // Each name at the first place round the middle of its terrain's outer edge (the back
        // row's far edge, above first; the front row's near edge, below first), on the last
        // frame's view, that covers no terrain (every 4th vertex of each) nor a name placed
        // before it: a name at a corner facing the middle lands on the terrain beside it.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let surfaces: Vec<Vec3> = (self.terrains.iter().enumerate())
            .flat_map(|(i, t)| {
                let r = t.resolution();
                (0..r * r)
                    .filter(move |k| (k % r) % 4 == 0 && (k / r) % 4 == 0)
                    .map(move |k| t.positions[k] + Self::placement(i))
            })
            .collect();
        for (i, &(_, name)) in SIDE_BY_SIDE_VARIANTS.iter().enumerate() {
            let out = if i < 2 { -1.0 } else { 1.0 };
            let edge = Self::placement(i) + Vec3::Z * 1.1 * out;
            let candidates = crate::draw::Label::around_dot(
                edge,
                0.0,
                Vec2::Y * out,
                name,
                palette::DARK,
                0,
                16,
                8.0,
            );
            frame.first_clear_label_by(view, 0.0, candidates, super::clear_of(view, &surfaces));
        }
        let h_top = (0.6 * self.h).max(0.1);
        frame.keep_box_in_view(
            Self::placement(0) + Vec3::new(-1.0, -h_top, -1.0),
            Self::placement(3) + Vec3::new(1.0, h_top, 1.25),
        );
        let p = self.shown_params(0);
        let ranges: Vec<String> = (0..self.terrains.len())
            .map(|i| {
                let (lo, hi) = self.height_range(i);
                format!(
                    "{} from {} to {} m",
                    SIDE_BY_SIDE_VARIANTS[i].1,
                    format_number(lo),
                    format_number(hi)
                )
            })
            .collect();
        let mut note = format!(
            "{0} × {0} vertices each, N = {1}, α = {2}, h = {3}, ω = 2, s = 1, o = 0. Heights: {4}.",
            VARIANTS_RESOLUTION,
            self.fractal.n,
            format_number(self.fractal.alpha),
            format_number(self.h),
            ranges.join("; ")
        );
        if p.fractal.n < self.fractal.n {
            note += &format!(
                " Octaves {} to {} are finer than these meshes and left out.",
                p.fractal.n + 1,
                self.fractal.n
            );
        }
        note
    }
}

impl Default for Variants {
    fn default() -> Self {
        Self::new()
    }
}

impl TerrainFigure for Variants {
    fn terrains(&self) -> Vec<&Terrain> {
        self.terrains.iter().collect()
    }
    fn stale(&mut self) -> &mut bool {
        &mut self.stale
    }
    fn dirty(&mut self) -> &mut bool {
        &mut self.dirty
    }
    fn rebuild(&mut self) -> Result<(), String> {
        self.regenerate();
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 8: procedural textures.

/// Texels per side of each of Figure 8's textures.
pub const TEXTURE_SIZE: usize = 128;

/// Figure 8: marble, wood and clouds, each written into an RGBA buffer and shown by the renderer
/// as a texture on a square (uploaded once, then rewritten in place when a parameter changes).
pub struct Textures {
    perm: Permutation,
    scale: f32,
    turbulence: f32,
    n: u32,
    time_sec: f32,
    animate: bool,
    images: [Vec<u8>; 3],
    dirty: bool,
    stale: bool,
}

pub const TEXTURE_KINDS: [(TextureKind, &str); 3] = [
    (TextureKind::Marble, "marble"),
    (TextureKind::Wood, "wood"),
    (TextureKind::Clouds, "clouds"),
];

impl Textures {
    pub fn new() -> Self {
        let image = || vec![0; 4 * TEXTURE_SIZE * TEXTURE_SIZE];
        let mut s = Self {
            perm: Permutation::perlin(),
            scale: 4.0,
            turbulence: 5.0,
            n: 4,
            time_sec: 0.0,
            animate: false,
            images: [image(), image(), image()],
            dirty: true,
            stale: false,
        };
        s.regenerate().expect("valid defaults");
        s
    }

    fn regenerate(&mut self) -> Result<(), String> {
        for (rgba, (kind, _)) in self.images.iter_mut().zip(TEXTURE_KINDS) {
            let params = TextureParams {
                kind,
                scale: self.scale,
                turbulence: self.turbulence,
                n: self.n,
                t: self.time_sec,
            };
            fill_rgba(&self.perm, &params, TEXTURE_SIZE, TEXTURE_SIZE, rgba)?;
        }
        self.dirty = true;
        Ok(())
    }

    /// Noise cells across a texture (0.5 to 16), turbulence τ (0 to 20), octaves N (0 to 8).
    pub fn set_params(&mut self, scale: f32, turbulence: f32, n: f32) -> Result<(), String> {
        let scale = in_range("scale", scale, 0.5, 16.0)?;
        let turbulence = in_range("turbulence", turbulence, 0.0, 20.0)?;
        let n = check_n(n, 8)?;
        (self.scale, self.turbulence, self.n) = (scale, turbulence, n);
        self.stale = true;
        Ok(())
    }

    pub fn set_animate(&mut self, on: bool) -> Result<(), String> {
        self.animate = on;
        if on {
            // Step at once so that ticking the box shows a change even before the next frame.
            self.time_sec += 0.25;
            self.stale = true;
        }
        Ok(())
    }

    pub fn advance(&mut self, dt_sec: f32) -> Result<(), String> {
        let dt = in_range("dt", dt_sec, 0.0, 1.0)?;
        if self.animate {
            self.time_sec = (self.time_sec + 0.5 * dt) % 1000.0;
            self.stale = true;
        }
        Ok(())
    }

    /// The three images (marble, wood, clouds), `TEXTURE_SIZE²` RGBA texels each, sRGB bytes.
    pub fn images(&self) -> [&[u8]; 3] {
        [&self.images[0], &self.images[1], &self.images[2]]
    }

    /// Regenerates what the setters marked stale; returns true once after the images changed
    /// (the web layer then rewrites the GPU textures in place).
    pub fn take_dirty(&mut self) -> bool {
        if std::mem::take(&mut self.stale) && self.regenerate().is_err() {
            return false;
        }
        std::mem::take(&mut self.dirty)
    }

    /// Draws the textures (`textures[i]` holds `images()[i]`) on three squares; returns the note.
    pub fn draw(&self, frame: &mut Frame, textures: &[TextureId]) -> String {
        // The three squares and their labels stay whole at any canvas size.
        frame.keep_box_in_view(Vec3::new(-3.3, 0.0, -1.0), Vec3::new(3.3, 0.0, 1.3));
        for (i, (&texture, (_, name))) in textures.iter().zip(TEXTURE_KINDS).enumerate() {
            let x = (i as f32 - 1.0) * 2.3;
            frame.textured_quad(
                texture,
                Mat4::from_translation(Vec3::new(x, 0.0, 0.0)),
                UvRect::FULL,
            );
            // Labels read rightwards from their anchor: start each at its square's left edge.
            frame.label(Vec3::new(x - 1.0, 0.0, 1.2), name, palette::DARK);
        }
        format!(
            "Each texture is a {TEXTURE_SIZE} × {TEXTURE_SIZE} RGBA image computed on the CPU and \
             shown by the GPU on a square (a textured quad; the GPU interpolates between texels). \
             scale = {}, τ = {}, N = {}{}.",
            format_number(self.scale),
            format_number(self.turbulence),
            self.n,
            if self.animate {
                format!(", t = {}", format_number(self.time_sec))
            } else {
                String::new()
            }
        )
    }
}

impl Default for Textures {
    fn default() -> Self {
        Self::new()
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 7: the course's quiz.

/// One of the quiz's parameter sets and why it looks the way it does.
pub struct QuizSet {
    pub params: TerrainParams,
    /// What gives it away, for the feedback.
    pub why: &'static str,
}

impl QuizSet {
    /// What a quiz terrain is built from: the set's parameters without the octaves finer than
    /// the quiz's mesh can show ([`last_resolved_octave`]), which would only add spikes.
    pub fn shown_params(&self) -> TerrainParams {
        let mut p = self.params;
        let last = last_resolved_octave(QUIZ_RESOLUTION, p.s, p.fractal.omega).unwrap_or(0);
        p.fractal.n = p.fractal.n.min(last);
        p
    }
}

/// The six parameter sets of the quiz, numbered 1 to 6 on the page (the course's terrain and one
/// change each).
pub fn quiz_sets() -> [QuizSet; 6] {
    let base = TerrainParams::default();
    let with = |f: Fractal| TerrainParams { fractal: f, ..base };
    [
        QuizSet {
            params: base,
            why: "the course's terrain (N = 9, α = 0.4, h = 0.3, s = 1, o = 0): the same hills as \
                  Figure 4 at its defaults",
        },
        QuizSet {
            params: with(Fractal {
                n: 1,
                ..Fractal::COURSE
            }),
            why: "N = 1 keeps only two octaves: the same large hills, but smooth, with no small \
                  bumps",
        },
        QuizSet {
            params: with(Fractal {
                alpha: 0.75,
                ..Fractal::COURSE
            }),
            why: "α = 0.75 lets the fine octaves keep most of their amplitude: a rough, craggy \
                  surface",
        },
        QuizSet {
            params: TerrainParams { h: 0.8, ..base },
            why: "h = 0.8 stretches the course's terrain vertically: the same shape, much taller",
        },
        QuizSet {
            params: TerrainParams { s: 3.0, ..base },
            why: "s = 3 packs three times as many noise cells into the square: many small hills",
        },
        QuizSet {
            params: TerrainParams { o: 0.5, ..base },
            why: "o = 0.5 moves the window over the noise: the course's kind of terrain, but \
                  other hills than set 1",
        },
    ]
}

/// Figure 7: six terrains `a`–`f` from the six sets in a hidden order; the student assigns a
/// set to each and checks.
pub struct Quiz {
    perm: Permutation,
    /// `hidden[i]`: the set (0-based) behind terrain i.
    hidden: [usize; 6],
    answers: [Option<usize>; 6],
    checked: bool,
    terrains: Vec<Terrain>,
    round: u64,
    dirty: bool,
    stale: bool,
}

/// Vertices per side of each quiz terrain.
pub const QUIZ_RESOLUTION: usize = 97;
const LETTERS: [&str; 6] = ["a", "b", "c", "d", "e", "f"];

impl Quiz {
    pub fn new() -> Self {
        let mut q = Self {
            perm: Permutation::perlin(),
            hidden: [0, 1, 2, 3, 4, 5],
            answers: [None; 6],
            checked: false,
            terrains: (0..6)
                .map(|_| Terrain::new(QUIZ_RESOLUTION).expect("a valid resolution"))
                .collect(),
            round: 0,
            dirty: true,
            stale: false,
        };
        q.new_round();
        q.regenerate();
        q
    }

    /// Shuffles the sets onto the terrains (a different order each round) and clears the answers.
    pub fn new_round(&mut self) {
        self.round += 1;
        let mut rng = crate::fixtures::Rng::new(0x9e11_0000 + self.round);
        let before = self.hidden;
        loop {
            for i in (1..6).rev() {
                let j = rng.below(i + 1);
                self.hidden.swap(i, j);
            }
            if self.hidden != before {
                break;
            }
        }
        self.answers = [None; 6];
        self.checked = false;
        self.stale = true;
    }

    fn regenerate(&mut self) {
        let sets = quiz_sets();
        for (t, &set) in self.terrains.iter_mut().zip(&self.hidden) {
            t.regenerate(&self.perm, &sets[set].shown_params())
                .expect("the quiz's sets are valid");
        }
        self.dirty = true;
    }

    /// The student's answer for terrain `terrain` (0 = a): set 1..=6, or 0 for "not answered".
    pub fn set_answer(&mut self, terrain: usize, set: usize) -> Result<(), String> {
        if terrain >= 6 {
            return Err(format!("terrain must be 0 (a) to 5 (f), got {terrain}"));
        }
        if set > 6 {
            return Err(format!("set must be 1 to 6 (or 0: no answer), got {set}"));
        }
        self.answers[terrain] = set.checked_sub(1);
        self.checked = false;
        Ok(())
    }

    /// Marks the answers: the labels say right or wrong and the note says why.
    pub fn check(&mut self) {
        self.checked = true;
    }

    /// How many answers are right.
    pub fn score(&self) -> usize {
        (0..6)
            .filter(|&i| self.answers[i] == Some(self.hidden[i]))
            .count()
    }

    /// Where terrain i sits: three across, two deep.
    pub fn placement(i: usize) -> Vec3 {
        Vec3::new((i % 3) as f32 * 2.5 - 2.5, 0.0, (i / 3) as f32 * 2.7 - 1.35)
    }

    pub fn draw(&self, frame: &mut Frame, meshes: &[MeshId]) -> String {
        // The lowest ground and the highest peak among the six (set 4's h = 0.8 is the tallest).
        let (lo, hi) = self
            .terrains
            .iter()
            .flat_map(|t| &t.positions)
            .fold((0.0f32, 0.0f32), |(lo, hi), p| (lo.min(p.y), hi.max(p.y)));
        for (i, &mesh) in meshes.iter().enumerate().take(6) {
            let at = Self::placement(i);
            frame.mesh_vertex_colors(mesh, Mat4::from_translation(at));
            let mut text = LETTERS[i].to_string();
            let mut color = palette::DARK;
            if let Some(a) = self.answers[i] {
                text += &format!(" → set {}", a + 1);
                color = palette::PURPLE;
                if self.checked {
                    let right = a == self.hidden[i];
                    text += if right { " ✓" } else { " ✗" };
                    color = if right { palette::GREEN } else { palette::RED };
                }
            }
            // Off the row's outer edge, away from the tile on the canvas: above the back row's
            // far edge at the highest peak, below the front row's near edge. Between the rows a
            // name reads as the other row's tile's; over its tile's peaks it covers them.
            let (out, up, side) = if i < 3 {
                (-1.15, hi, -Vec2::Y)
            } else {
                (1.15, 0.0, Vec2::Y)
            };
            frame.label_off_dot(at + Vec3::new(0.0, up, out), 0.0, side, text, color, 0);
        }
        frame.keep_box_in_view(
            Self::placement(0) + Vec3::new(-1.0, lo, -1.15),
            Self::placement(5) + Vec3::new(1.0, hi, 1.15),
        );
        if !self.checked {
            let answered = self.answers.iter().filter(|a| a.is_some()).count();
            return format!(
                "{answered} of 6 answered. Pick a set for each terrain, then press “check my answers”."
            );
        }
        let sets = quiz_sets();
        let mut lines = vec![format!("{} of 6 right.", self.score())];
        for (i, letter) in LETTERS.iter().enumerate() {
            let truth = self.hidden[i];
            let verdict = match self.answers[i] {
                None => format!("{}: no answer; it is set {}", letter, truth + 1),
                Some(a) if a == truth => format!("{}: set {}, right", letter, a + 1),
                Some(a) => format!("{}: not set {}; it is set {}", letter, a + 1, truth + 1),
            };
            lines.push(format!("{verdict}: {}.", sets[truth].why));
        }
        lines.join(" ")
    }
}

impl Default for Quiz {
    fn default() -> Self {
        Self::new()
    }
}

impl TerrainFigure for Quiz {
    fn terrains(&self) -> Vec<&Terrain> {
        self.terrains.iter().collect()
    }
    fn stale(&mut self) -> &mut bool {
        &mut self.stale
    }
    fn dirty(&mut self) -> &mut bool {
        &mut self.dirty
    }
    fn rebuild(&mut self) -> Result<(), String> {
        self.regenerate();
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 10: fractals.

/// Figure 10: the Koch snowflake (left) and the Sierpinski triangle (right) at one depth; with
/// "show previous depth" the depth before is drawn in grey over it.
pub struct Fractals {
    depth: u32,
    show_previous: bool,
    points: Vec<Vec2>,
    triangles: Vec<[Vec2; 3]>,
}

/// Width of the fractals' outlines, CSS pixels. The previous depth's grey is as wide, so where
/// a segment survives a step the grey covers it whole.
pub const FRACTAL_PX: f32 = 2.0;

const KOCH_CENTRE: Vec2 = Vec2::new(-1.7, 0.0);
/// The snowflake's circumradius: its starting triangle's corners, which every depth keeps.
pub const KOCH_RADIUS: f32 = 1.25;
/// Height of the two names, under the shapes.
const LABEL_Y: f32 = -1.55;
const SIERPINSKI: [Vec2; 3] = [
    Vec2::new(0.4, -1.2),
    Vec2::new(3.0, -1.2),
    Vec2::new(1.7, 1.05),
];

impl Fractals {
    pub fn new() -> Self {
        Self {
            depth: 3,
            show_previous: false,
            points: Vec::new(),
            triangles: Vec::new(),
        }
    }
    pub fn set_depth(&mut self, depth: f32) -> Result<(), String> {
        let d = in_range("depth", depth, 0.0, MAX_DEPTH as f32)?;
        if d.fract() != 0.0 {
            return Err(format!("depth must be a whole number, got {depth}"));
        }
        self.depth = d as u32;
        Ok(())
    }
    pub fn set_show_previous(&mut self, on: bool) {
        self.show_previous = on;
    }

    fn draw_depth(&mut self, frame: &mut Frame, depth: u32, koch: Vec3, sier: Vec3, z: f32) {
        koch_snowflake(depth, KOCH_RADIUS, &mut self.points).expect("depth checked");
        let pts: Vec<Vec3> = self
            .points
            .iter()
            .map(|p| (*p + KOCH_CENTRE).extend(z))
            .collect();
        frame.wide_polyline(&pts, koch, FRACTAL_PX);
        sierpinski(depth, SIERPINSKI, &mut self.triangles).expect("depth checked");
        for t in &self.triangles {
            let v = t.map(|p| p.extend(z));
            frame.wide_polyline(&[v[0], v[1], v[2], v[0]], sier, FRACTAL_PX);
        }
    }

    /// What must stay in view, `(min, max)`: the snowflake (inside its circumcircle, radius
    /// [`KOCH_RADIUS`]), the Sierpinski triangle and the labels under them.
    pub fn view_box() -> (Vec3, Vec3) {
        let koch = KOCH_CENTRE - Vec2::splat(KOCH_RADIUS);
        let top = (KOCH_CENTRE.y + KOCH_RADIUS).max(SIERPINSKI[2].y);
        (
            Vec3::new(koch.x, LABEL_Y, 0.0),
            Vec3::new(SIERPINSKI[1].x, top, 0.0),
        )
    }

    pub fn draw(&mut self, frame: &mut Frame) -> String {
        let (lo, hi) = Self::view_box();
        frame.keep_box_in_view(lo, hi);
        // Drawings in the plane z = 0: a drag pans them rather than turning them edge-on.
        frame.flat = true;
        let d = self.depth;
        self.draw_depth(frame, d, palette::BLUE, palette::ORANGE, 0.0);
        if self.show_previous && d > 0 {
            // The depth before in grey, nearer the camera than the current one: where a segment
            // survives the step it shows grey.
            self.draw_depth(frame, d - 1, palette::GREY, palette::GREY, 0.01);
            // What the step adds, in colour over the grey: a step finer than a pixel would
            // otherwise leave the grey over all of it. Each old segment's bump is the middle
            // two of its four new segments; each old triangle loses the one between its
            // sides' midpoints.
            for t in &self.triangles {
                let m = [0, 1, 2, 0].map(|i| ((t[i] + t[(i + 1) % 3]) / 2.0).extend(0.02));
                frame.wide_polyline(&m, palette::ORANGE, FRACTAL_PX);
            }
            koch_snowflake(d, KOCH_RADIUS, &mut self.points).expect("depth checked");
            for bump in self.points[1..].chunks(4) {
                let pts = bump[..3].iter().map(|p| (*p + KOCH_CENTRE).extend(0.02));
                frame.wide_polyline(&pts.collect::<Vec<_>>(), palette::BLUE, FRACTAL_PX);
            }
        }
        // Each name centred under its shape (a side of zero centres the box on the anchor).
        for (x, name, color) in [
            (KOCH_CENTRE.x, "Koch snowflake", palette::BLUE),
            (SIERPINSKI[2].x, "Sierpinski triangle", palette::ORANGE),
        ] {
            let at = Vec3::new(x, LABEL_Y, 0.0);
            frame.label_off_dot(at, 0.0, Vec2::ZERO, name, color, 0);
        }
        let segments = 3 * 4usize.pow(d);
        // What the step adds, drawn in colour over the grey: the two sides of each new bump, and
        // the outline of the middle triangle cut out of each old triangle.
        let step = if self.show_previous && d > 0 {
            let before = 3 * 4usize.pow(d - 1);
            format!(
                " Over depth {} in grey, the step turns each of the snowflake's {before} segments \
                 into 4 and adds the {} coloured sides of the new bumps; it cuts the middle out of \
                 every triangle of depth {0} in the Sierpinski triangle ({} of them), whose \
                 outlines are drawn in orange.",
                d - 1,
                2 * before,
                3usize.pow(d - 1)
            )
        } else {
            String::new()
        };
        format!(
            "Depth {d}: the snowflake has {segments} segments and a perimeter (4/3)^{d} = {} times \
             the triangle's; the Sierpinski triangle has 3^{d} = {} triangles covering (3/4)^{d} = {} \
             of the area.{step}",
            format_number((4.0f32 / 3.0).powi(d as i32)),
            3usize.pow(d),
            format_number(0.75f32.powi(d as i32))
        )
    }
}

impl Default for Fractals {
    fn default() -> Self {
        Self::new()
    }
}
