//! Figure logic for lesson 15, "Fluids" (see [`crate::fluid`]).
//!
//! - [`KernelsFigure`]: the four kernels of one support radius, as plot rows, with the student's
//!   poly6 (exercise 15.1) beside the reference.
//! - [`DensityFigure`]: a 2D pool at rest; the reader drags one particle and sees the neighbours
//!   within `h`, each one's weight, the density they add up to, the pressure force SPH puts on it
//!   and the move PBF's constraint asks of it (exercises 15.2 to 15.4).
//! - [`DamBreakFigure`]: SPH and PBF on the same 2D dam break side by side, SPH's stiffness and
//!   time step the reader's (past its limit it stops, and says why).
//! - [`SplashFigure`]: a 3D drop into a pool, either solver, on the CPU or (WebGPU) on the GPU
//!   grid, with a step-time sweep of the CPU grid against all pairs and the GPU grid.

use super::boids::StepTimeSweep;
use super::gpu::MAX_GPU_FLUID_PARTICLES;
use super::{failure_note, format_number, palette, Frame, DEFAULT_RUNNER};
use crate::camera::{point_on_view_plane, project_to_canvas, OrbitCamera};
use crate::draw::inset::InsetView;
use crate::draw::{StrokeStyle, DOT_PX};
use crate::exercises::run::{self, compare_note, Runner};
use crate::fluid::kernels::{Dim, Kernels};
use crate::fluid::{
    box_size, density, pair_force, pbf_lambda, spacing_for, Fluid, FluidParams, Method, Scene,
    Search,
};
use glam::{Mat4, Vec2, Vec3};

/// The exercises' file, as the notes name it.
const FILE: &str = "src/exercises/fluid.rs";

/// The kernels of support radius `h` in 2D or 3D, for the lesson's kernel plots.
#[derive(Clone, Debug)]
pub struct KernelsFigure {
    h: f32,
    dim: Dim,
    use_exercise: bool,
    runner: Runner,
}

impl Default for KernelsFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl KernelsFigure {
    pub fn new() -> Self {
        Self {
            h: 0.1,
            dim: Dim::Two,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
        }
    }

    /// How the student's exercise is called (the page's sandbox; tests pass their own).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// Plots the student's poly6 (exercise 15.1, 2D) beside the reference.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// The student's poly6 over the plot's rows as a share of the reference's peak (`None` when
    /// the exercise is off or gave no answer), and the note: where it differs most from the
    /// reference, or why it could not run (empty when the exercise is off).
    pub fn exercise(&self, samples: usize) -> Result<(Option<Vec<f32>>, String), String> {
        super::check_samples(samples)?;
        if !self.use_exercise {
            return Ok((None, String::new()));
        }
        if self.dim != Dim::Two {
            return Ok((
                None,
                "Exercise 15.1 is the 2D kernel: choose 2D to see yours.".into(),
            ));
        }
        let k = Kernels::new(self.h, Dim::Two);
        let peak = k.poly6(0.0);
        let mut yours = Vec::with_capacity(samples);
        let mut worst = (0.0f32, 0.0f32, 0.0f32, 0.0f32);
        for i in 0..samples {
            let r = 1.25 * self.h * i as f32 / (samples - 1) as f32;
            let reference = k.poly6(r * r);
            match run::poly6(self.runner, r * r, self.h) {
                Err(f) => {
                    let note = failure_note("exercise 15.1 poly6", FILE, &f);
                    return Ok((None, note));
                }
                Ok(w) => {
                    let error = if w.is_nan() {
                        f32::INFINITY
                    } else {
                        (w - reference).abs()
                    };
                    if error > worst.0 {
                        worst = (error, r, w, reference);
                    }
                    yours.push(w / peak);
                }
            }
        }
        let (error, r, w, reference) = worst;
        let at = format!(
            "r = {} m, h = {} m",
            format_number(r),
            format_number(self.h)
        );
        let (_, note) = compare_note("poly6", &at, &[w], &[reference], 1e-4 * peak);
        let note = if error <= 1e-4 * peak {
            format!(
                "Your poly6 matches the reference at all {samples} distances (h = {} m).",
                format_number(self.h)
            )
        } else {
            note
        };
        Ok((Some(yours), note))
    }

    /// Sets the support radius (0.01 to 1 m) and the dimension (2 or 3); nothing changes on an
    /// error.
    pub fn set(&mut self, h: f32, dim: u32) -> Result<(), String> {
        let h = super::in_range("kernel radius h (m)", h, 0.01, 1.0)?;
        let dim = match dim {
            2 => Dim::Two,
            3 => Dim::Three,
            other => return Err(format!("dimension must be 2 or 3, got {other}")),
        };
        (self.h, self.dim) = (h, dim);
        Ok(())
    }

    /// The largest values of the four kernels, in the plot's order: `W(0)` of poly6 and spiky
    /// (1/m² in 2D, 1/m³ in 3D), spiky's slope `−dW/dr` as `r → 0` and the viscosity
    /// Laplacian at 0 (each one power of 1/m more).
    pub fn peaks(&self) -> [f32; 4] {
        let k = Kernels::new(self.h, self.dim);
        [
            k.poly6(0.0),
            k.spiky(0.0),
            -k.spiky_gradient(Vec3::X * 1e-6 * self.h).x,
            k.viscosity_laplacian(0.0),
        ]
    }

    /// What the plot's shares are shares of: poly6's and spiky's peaks `W(0)`, with their unit.
    /// Doubling `h` divides them by 4 in 2D and by 8 in 3D (the same unit weight over 4 or 8
    /// times the area or volume).
    pub fn peaks_note(&self) -> String {
        let [poly6, spiky, _, _] = self.peaks();
        // Whole numbers from 100 up, one decimal below (31.8 at h = 20 cm in 2D).
        let show = |w: f32| {
            if w >= 100.0 {
                format!("{w:.0}")
            } else {
                format!("{w:.1}")
            }
        };
        let (d, unit) = match self.dim {
            Dim::Two => (2, "1/m²"),
            Dim::Three => (3, "1/m³"),
        };
        format!(
            "Peaks at h = {} cm in {d}D: poly6 W(0) = {} {unit}, spiky W(0) = {} {unit}.",
            show(100.0 * self.h),
            show(poly6),
            show(spiky)
        )
    }

    /// `samples` rows from `r = 0` to `1.25 h`: `[r, poly6, spiky, −dW/dr of spiky, ∇²W of
    /// viscosity]`, each kernel as a share of its largest value, so one axis shows all four
    /// (they differ by orders of magnitude) and where each reaches zero: at `h`, and beyond.
    pub fn plot_rows(&self, samples: usize) -> Result<Vec<[f32; 5]>, String> {
        super::check_samples(samples)?;
        let k = Kernels::new(self.h, self.dim);
        let slope = |r: f32| -k.spiky_gradient(Vec3::X * r).x;
        // The spiky slope is largest as r → 0: `peaks` takes its value at a millionth of h.
        let peaks = self.peaks();
        Ok((0..samples)
            .map(|i| {
                let r = 1.25 * self.h * i as f32 / (samples - 1) as f32;
                [
                    r,
                    k.poly6(r * r) / peaks[0],
                    k.spiky(r) / peaks[1],
                    if r > 0.0 { slope(r) / peaks[2] } else { 1.0 },
                    k.viscosity_laplacian(r) / peaks[3],
                ]
            })
            .collect())
    }
}

/// The colour of water at its rest density in Figures 2 and 3: the palette's blue.
pub const WATER: Vec3 = palette::BLUE;
/// The colour of water at half its rest density or less (a surface particle with half of its
/// disc in the air): a pale blue (#a9c9ef), still darker than the canvas's background.
pub const THIN_WATER: Vec3 = Vec3::new(0.397, 0.585, 0.863);
/// The compression `ρ/ρ₀ − 1` drawn full red: SPH's densest particles (10 to 20 % over) are
/// half-way there, PBF's (a few percent) stay blue.
pub const RED_COMPRESSION: f32 = 0.25;

/// A particle's colour for its density as a share of the rest density, `ratio = ρ/ρ₀`:
/// [`WATER`] at 1, towards [`THIN_WATER`] below (reached at 0.5), towards red above (reached at
/// `1 +` [`RED_COMPRESSION`]). Mixed in linear light; a NaN ratio is red.
pub fn density_color(ratio: f32) -> Vec3 {
    let error = ratio - 1.0;
    if error < 0.0 {
        WATER.lerp(THIN_WATER, (-error / 0.5).min(1.0))
    } else if error.is_nan() {
        palette::RED
    } else {
        WATER.lerp(palette::RED, (error / RED_COMPRESSION).min(1.0))
    }
}

/// Particles in the density figure's pool.
pub const DENSITY_PARTICLES: usize = 500;
/// The density figure's kernel radius, in particle spacings (about 23 neighbours in 2D).
pub const DENSITY_H_SPACINGS: f32 = 2.7;
/// How near the pointer must be to the dragged particle to grab it, CSS pixels.
pub const GRAB_RADIUS_PX: f32 = 20.0;
/// The pressure-force arrow's length: `ARROW_MAX_M · tanh(|F| / (m · ARROW_ACCEL))`, so that a
/// small force still shows and a large one stays inside the box.
const ARROW_MAX_M: f32 = 0.25;
const ARROW_ACCEL: f32 = 50.0;
/// PBF's move is a fraction of a millimetre: its arrow is `PBF_ARROW_MAX_M · tanh(|Δx| /
/// PBF_ARROW_MOVE_M)` long, like the force's (the note gives the move's true length).
pub const PBF_ARROW_MAX_M: f32 = 0.3;
pub const PBF_ARROW_MOVE_M: f32 = 6e-4;

/// The orange arrow's length for a PBF move of `move_m` metres.
pub fn pbf_arrow_length(move_m: f32) -> f32 {
    PBF_ARROW_MAX_M * (move_m / PBF_ARROW_MOVE_M).tanh()
}

/// What SPH and PBF make of the dragged particle's neighbourhood: its density, its pressure,
/// the pressure force of its neighbours, and its PBF `λ` with the move `λ ∇ᵢCᵢ` it asks of the
/// particle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ProbeForces {
    pub density: f32,
    pub pressure: f32,
    pub force: Vec3,
    pub lambda: f32,
    pub correction: Vec3,
}

/// A 2D pool at rest whose first particle the reader moves (the probe). Dropped into the
/// water, the probe takes the place of the particle nearest to it (within half a spacing),
/// which goes to the probe's own place in the lattice: every particle then counts once.
#[derive(Clone, Debug)]
pub struct DensityFigure {
    fluid: Fluid,
    /// The lattice at rest, before the probe moved.
    home: Vec<Vec3>,
    /// The probe's neighbours (indices) and their distances, after the last move.
    neighbours: Vec<(usize, f32)>,
    /// The reference's values at the probe, and the ones the figure shows (the student's, when
    /// "use my exercise" is on and they answered).
    reference: ProbeForces,
    shown: ProbeForces,
    use_exercise: bool,
    runner: Runner,
    exercise_note: String,
    /// The camera and canvas size (CSS pixels) of the last frame, for picking.
    view: Option<(OrbitCamera, Vec2)>,
}

impl Default for DensityFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl DensityFigure {
    pub fn new() -> Self {
        let mut params = FluidParams::default_2d(Method::Sph);
        params.h = DENSITY_H_SPACINGS * spacing_for(Dim::Two, Scene::Pool, DENSITY_PARTICLES);
        let fluid = Fluid::new(params, Scene::Pool, DENSITY_PARTICLES, 1).expect("valid defaults");
        let mut figure = Self {
            home: fluid.positions.clone(),
            fluid,
            neighbours: Vec::new(),
            reference: ProbeForces::default(),
            shown: ProbeForces::default(),
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            exercise_note: String::new(),
            view: None,
        };
        // The probe starts in the middle of the pool (0.4 m deep), half-way down.
        figure
            .set_probe(0.8, 0.2)
            .expect("the start is inside the box");
        figure
    }

    pub fn fluid(&self) -> &Fluid {
        &self.fluid
    }

    /// The kernel radius, metres.
    pub fn h(&self) -> f32 {
        self.fluid.params.h
    }

    /// How the student's exercises are called (the page's sandbox; tests pass their own).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.evaluate();
    }

    /// Computes the probe's density, force and `λ` with the student's 15.2 to 15.4.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.evaluate();
    }

    /// Moves the probe (particle 0) to `(x, y)` inside the box and recomputes every density;
    /// an error leaves the figure as it was.
    pub fn set_probe(&mut self, x: f32, y: f32) -> Result<(), String> {
        let size = box_size(Dim::Two);
        let x = super::in_range("x (m)", x, 0.0, size.x)?;
        let y = super::in_range("y (m)", y, 0.0, size.y)?;
        let p = Vec3::new(x, y, 0.0);
        self.fluid.positions.clone_from(&self.home);
        self.fluid.positions[0] = p;
        // The particle the probe lands on moves to the probe's place in the lattice.
        let nearest = (1..self.home.len())
            .map(|j| (j, (self.home[j] - p).length()))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .filter(|&(_, r)| r < 0.5 * self.fluid.spacing);
        if let Some((j, _)) = nearest {
            self.fluid.positions[j] = self.home[0];
        }
        self.fluid.search();
        self.fluid.refresh_densities();
        self.neighbours = self
            .fluid
            .neighbours(0)
            .iter()
            .map(|&j| (j as usize, (self.fluid.positions[j as usize] - p).length()))
            .collect();
        let nearest_first = crate::order::order_by(self.neighbours.iter().map(|n| n.1), false);
        self.neighbours = nearest_first.into_iter().map(|i| self.neighbours[i]).collect();
        self.evaluate();
        Ok(())
    }

    /// The probe's and its neighbours' positions, densities and pressures.
    fn neighbourhood(&self) -> (Vec3, Vec<(Vec3, f32, f32)>) {
        let f = &self.fluid;
        let nbrs = self
            .neighbours
            .iter()
            .map(|&(j, _)| {
                let rho = f.densities[j];
                (f.positions[j], rho, f.pressure(rho))
            })
            .collect();
        (f.positions[0], nbrs)
    }

    /// The reference's density, force and `λ` at the probe, then the student's when asked.
    fn evaluate(&mut self) {
        let f = &self.fluid;
        let (h, m, rho0) = (f.params.h, f.mass, f.params.rest_density);
        let eps = f.params.relaxation;
        let (p, nbrs) = self.neighbourhood();
        let rho = density(p, nbrs.iter().map(|n| n.0), m, h, Dim::Two);
        let pressure = f.pressure(rho);
        let force: Vec3 = nbrs
            .iter()
            .map(|&(x, rho_j, p_j)| {
                let v = [Vec3::ZERO; 2];
                pair_force(
                    [p, x],
                    v,
                    [rho, rho_j],
                    [pressure, p_j],
                    m,
                    0.0,
                    h,
                    Dim::Two,
                )
            })
            .sum();
        let lambda = pbf_lambda(p, nbrs.iter().map(|n| n.0), rho, m, rho0, eps, h, Dim::Two);
        let kern = Kernels::new(h, Dim::Two);
        let grad: Vec3 = nbrs
            .iter()
            .map(|n| m / rho0 * kern.spiky_gradient(p - n.0))
            .sum();
        self.reference = ProbeForces {
            density: rho,
            pressure,
            force,
            lambda,
            correction: lambda * grad,
        };
        self.shown = self.reference;
        self.exercise_note.clear();
        if self.use_exercise {
            self.run_exercises(&nbrs, grad);
        }
    }

    /// Runs 15.2 to 15.4 at the probe, compares each with the reference and shows the
    /// student's values where they answered.
    fn run_exercises(&mut self, nbrs: &[(Vec3, f32, f32)], grad: Vec3) {
        let f = &self.fluid;
        let (h, m, rho0, eps) = (
            f.params.h,
            f.mass,
            f.params.rest_density,
            f.params.relaxation,
        );
        let p = f.positions[0].truncate();
        let points: Vec<Vec2> = nbrs.iter().map(|n| n.0.truncate()).collect();
        let r = self.reference;
        let at = format!(
            "the dragged particle at ({}, {}) m with {} neighbours",
            format_number(p.x),
            format_number(p.y),
            points.len()
        );
        let mut notes = Vec::new();
        match run::sph_density(self.runner, p, points.clone(), m, h) {
            Err(e) => notes.push(failure_note("exercise 15.2 sph_density", FILE, &e)),
            Ok(rho) => {
                notes.push(
                    compare_note("sph_density", &at, &[rho], &[r.density], 1e-4 * r.density).1,
                );
                if rho.is_finite() {
                    self.shown.density = rho;
                }
            }
        }
        // The force as the sum of the student's pair forces, with the reference's densities
        // and pressures (each exercise is checked on its own).
        let mut force = Vec2::ZERO;
        let mut failed = None;
        for &(x, rho_j, p_j) in nbrs {
            let pair = [p, x.truncate()];
            match run::pressure_force(
                self.runner,
                pair,
                [r.density, rho_j],
                [r.pressure, p_j],
                m,
                h,
            ) {
                Ok(fij) => force += fij,
                Err(e) => {
                    failed = Some(e);
                    break;
                }
            }
        }
        match failed {
            Some(e) => notes.push(failure_note("exercise 15.3 pressure_force", FILE, &e)),
            // A sum of no pairs is zero whatever the exercise does: nothing to compare.
            None if nbrs.is_empty() => notes.push(
                "Exercise 15.3 pressure_force is not called: the dragged particle has no \
                 neighbours."
                    .into(),
            ),
            None => {
                let reference = r.force.truncate();
                let tol = 1e-4 * (1.0 + reference.length());
                let what = "pressure_force, summed over the neighbours,";
                notes
                    .push(compare_note(what, &at, &force.to_array(), &reference.to_array(), tol).1);
                if force.is_finite() {
                    self.shown.force = force.extend(0.0);
                }
            }
        }
        match run::pbf_lambda(self.runner, p, points, r.density, m, rho0, eps, h) {
            Err(e) => notes.push(failure_note("exercise 15.4 pbf_lambda", FILE, &e)),
            Ok(lambda) => {
                let tol = 1e-4 * (1e-6 + r.lambda.abs());
                notes.push(compare_note("pbf_lambda", &at, &[lambda], &[r.lambda], tol).1);
                if lambda.is_finite() {
                    self.shown.lambda = lambda;
                    self.shown.correction = lambda * grad;
                }
            }
        }
        // One line an exercise (the page keeps the note's line breaks).
        self.exercise_note = notes.join("\n");
    }

    /// The probe's density, kg/m² (2D), and its neighbours' count.
    pub fn probe(&self) -> (f32, usize) {
        (self.shown.density, self.neighbours.len())
    }

    /// What the figure shows at the probe (the student's values with "use my exercise").
    pub fn forces(&self) -> ProbeForces {
        self.shown
    }

    /// One row per neighbour, nearest first: `[distance / h, m W(r)]`, and the probe's own
    /// term first at distance 0 (the bars of the sum).
    pub fn terms(&self) -> Vec<[f32; 2]> {
        let k = Kernels::new(self.h(), Dim::Two);
        let m = self.fluid.mass;
        std::iter::once([0.0, m * k.poly6(0.0)])
            .chain(
                self.neighbours
                    .iter()
                    .map(|&(_, r)| [r / self.h(), m * k.poly6(r * r)]),
            )
            .collect()
    }

    /// The camera and canvas size (CSS pixels) of the last frame, for picking.
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    fn view_proj(&self) -> Option<(Mat4, Vec2)> {
        let (camera, size) = self.view?;
        Some((camera.projection(size.x / size.y) * camera.view(), size))
    }

    /// Whether a pointer at `(x, y)` CSS pixels is on the dragged particle.
    pub fn hits_probe(&self, x_px: f32, y_px: f32) -> Result<bool, String> {
        let p = Vec2::new(super::finite("x", x_px)?, super::finite("y", y_px)?);
        let Some((view_proj, size)) = self.view_proj() else {
            return Ok(false);
        };
        Ok(project_to_canvas(view_proj, size, self.fluid.positions[0])
            .is_some_and(|s| s.distance(p) <= GRAB_RADIUS_PX))
    }

    /// Moves the probe under a pointer at `(x, y)` CSS pixels: the point of the slab (z = 0)
    /// under it, kept inside the box.
    pub fn drag_probe(&mut self, x_px: f32, y_px: f32) -> Result<(), String> {
        let p = Vec2::new(super::finite("x", x_px)?, super::finite("y", y_px)?);
        let Some((view_proj, size)) = self.view_proj() else {
            return Ok(());
        };
        let anchor = self.fluid.positions[0];
        if let Some(world) = point_on_view_plane(view_proj, size, anchor, p) {
            let b = box_size(Dim::Two);
            self.set_probe(world.x.clamp(0.0, b.x), world.y.clamp(0.0, b.y))?;
        }
        Ok(())
    }

    /// The probe's position, metres.
    pub fn probe_position(&self) -> Vec3 {
        self.fluid.positions[0]
    }

    /// The pool's particles coloured by density ([`density_color`]: water blue at the rest
    /// density, paler below, red above), the probe's support circle, lines to its neighbours
    /// (thicker for larger weights),
    /// the pressure force on it and PBF's move. Returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        // A 2D pool in the plane z = 0, seen square-on: a drag pans it rather than turning it
        // edge-on (the dragged particle has its own drag).
        frame.flat = true;
        let f = &self.fluid;
        let rho0 = f.params.rest_density;
        let h = self.h();
        let size = box_size(Dim::Two);
        let radius = 0.35 * f.spacing;
        for (i, &p) in f.positions.iter().enumerate().skip(1) {
            frame.point(p, radius, density_color(f.densities[i] / rho0));
        }
        let p = f.positions[0];
        let k = Kernels::new(h, Dim::Two);
        let w0 = k.poly6(0.0);
        // The lines, the arrows and the dot over the particles, which would hide them.
        for &(j, r) in &self.neighbours {
            let share = k.poly6(r * r) / w0;
            frame.wide_line_on_top(p, f.positions[j], palette::PURPLE, 1.5 + 3.0 * share);
        }
        let circle: Vec<Vec3> = (0..=64)
            .map(|i| {
                let a = std::f32::consts::TAU * i as f32 / 64.0;
                p + h * Vec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        // Over the particles, each purple dash on a wider white one: purple alone is lost on
        // the water's dark blue.
        for (color, width) in [(Vec3::ONE, 5.0), (palette::PURPLE, 2.5)] {
            let style = StrokeStyle {
                on_top: true,
                ..StrokeStyle::dashed(width, 0.02, 0.012)
            };
            frame.stroke(&circle, color, style);
        }
        frame.marker_on_top(p, 1.6 * DOT_PX, palette::PURPLE);
        let s = self.shown;
        let accel = s.force.length() / f.mass;
        if accel > 1e-3 && accel.is_finite() {
            let length = ARROW_MAX_M * (accel / ARROW_ACCEL).tanh();
            frame.arrow_on_top(
                p,
                p + s.force / s.force.length() * length,
                palette::TEAL,
                0.04,
            );
        }
        if s.correction.length() > 1e-6 && s.correction.is_finite() {
            // A little in front of the slab (towards the default camera): the move mostly
            // points where the force does, and the teal arrow would hide it.
            let front = p + Vec3::new(0.0, 0.0, 0.03);
            let length = pbf_arrow_length(s.correction.length());
            let drawn = s.correction.normalize() * length;
            frame.arrow_on_top(front, front + drawn, palette::ORANGE, 0.02);
        }
        // The box's walls.
        let corners = [
            Vec3::ZERO,
            Vec3::new(size.x, 0.0, 0.0),
            Vec3::new(size.x, size.y, 0.0),
            Vec3::new(0.0, size.y, 0.0),
            Vec3::ZERO,
        ];
        frame.wide_polyline(&corners, palette::DARK, 2.0);
        frame.keep_box_in_view(Vec3::ZERO, size);
        // The name just off the support circle, above it first, then below, beside it and
        // further out, off the water (for the last frame's view): over the particles it does not
        // read. Each side's place is anchored at the circle's edge that way (8 % out, past the
        // white under its dashes), so a name beside the circle gets no leader line.
        let view = self.view_proj();
        let candidates = match view {
            Some((view_proj, canvas)) => {
                let rim: Vec<Vec3> = (0..16)
                    .map(|i| {
                        let a = i as f32 * std::f32::consts::TAU / 16.0;
                        p + 1.08 * h * Vec3::new(a.cos(), a.sin(), 0.0)
                    })
                    .collect();
                super::rigid_body::labels_round(&rim, view_proj, canvas, "dragged particle", palette::PURPLE, 16, 12.0)
            }
            None => vec![crate::draw::Label::off_dot(
                p + Vec3::new(0.0, h + 0.03, 0.0),
                0.0,
                Vec2::new(0.0, -1.0),
                "dragged particle".into(),
                palette::PURPLE,
                0,
            )],
        };
        let water = &f.positions[1..];
        frame.first_clear_label_by(view, 2.0, candidates, super::clear_of(view, water));
        let (rho, n) = self.probe();
        let mut note = format!(
            "ρ = {} kg/m² from {n} neighbours within h = {} m and itself: {} of the rest density {} kg/m². SPH: pressure {} Pa, force {} N ({} m/s² on the particle){}. PBF: λ = {}, a move of {} mm.",
            format_number(rho),
            format_number(h),
            format_number(rho / rho0),
            format_number(rho0),
            format_number(s.pressure),
            format_number(s.force.length()),
            format_number(accel),
            // Each pair pushes with (p_i + p_j)/2: below ρ₀ the particle's own pressure is 0,
            // and a force there is its squeezed neighbours' alone.
            if s.pressure == 0.0 && s.force.length() > 0.0 {
                ", all of it from its neighbours' pressures"
            } else {
                ""
            },
            format_number(s.lambda),
            format_number(1000.0 * s.correction.length()),
        );
        if self.use_exercise {
            note.push('\n');
            note.push_str(&self.exercise_note);
        }
        note
    }
}

/// PBF's artificial pressure `s_corr` in the figures' fluids. The core's default, 0.1, suits
/// finer fluids; in these coarse ones it holds the whole pool apart below ρ₀, since the density
/// constraint never pulls. It pushes the surface layer outwards at every iteration, so at 0.03
/// the dam's released column boils upwards by two spacings before it falls; 0.015 lifts it by
/// under a quarter of one, while 0 lets about 4 surface particles in 10 pair up.
pub const FIGURE_S_CORR: f32 = 0.015;

/// The dam-break figure's particles per fluid, and its kernel radius in spacings.
pub const DAM_PARTICLES: usize = 800;
/// The figure's frame: the fluids are stepped to the timeline's time at their own steps.
pub const DAM_FRAME_SEC: f32 = 1.0 / 60.0;
/// The longest the timeline runs, seconds (the samples of the plots cover it).
pub const DAM_DURATION_SEC: f32 = 4.0;
/// The dam break's particles on screen: shaded discs of this radius in spacings, so that
/// neighbours in the lattice touch, as water does. On the page's canvas (the figure's whole
/// width) a spacing is 5 to 6.5 px: each particle shows its colour over 5 px or more.
pub const DAM_POINT_SPACINGS: f32 = 0.5;

/// SPH and PBF on the same 2D dam break, side by side: SPH at its small step (Tait, `k` the
/// reader's stiffness), PBF at 1/240 s. The state at time `t` is the state after the steps up to
/// `t` from the start, replayed when the time goes back or a setting changes; a sample per frame
/// feeds the plots.
#[derive(Clone, Debug)]
pub struct DamBreakFigure {
    start: [Fluid; 2],
    fluids: [Fluid; 2],
    /// Per frame: `[t, SPH's largest ρ/ρ₀ − 1, PBF's, SPH's kinetic energy, PBF's]`.
    samples: Vec<[f32; 5]>,
    /// How squarely the last frame's camera faces the tanks: the cosine between its line of
    /// sight and their normal (z); 1 before the first frame.
    face_on: f32,
}

impl Default for DamBreakFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl DamBreakFigure {
    pub fn new() -> Self {
        let make = |method| {
            let mut params = FluidParams::default_2d(method);
            params.h = DENSITY_H_SPACINGS * spacing_for(Dim::Two, Scene::DamBreak, DAM_PARTICLES);
            params.s_corr = FIGURE_S_CORR;
            let mut f =
                Fluid::new(params, Scene::DamBreak, DAM_PARTICLES, 3).expect("valid defaults");
            // The start's densities, for the note and colours before the first step.
            f.search();
            f.refresh_densities();
            f
        };
        let start = [make(Method::Sph), make(Method::Pbf)];
        Self {
            fluids: start.clone(),
            start,
            samples: Vec::new(),
            face_on: 1.0,
        }
    }

    /// The camera the frame is drawn for (the last frame's): seen from the side or from above,
    /// the frame adds an inset of the tanks from the front.
    pub fn set_view(&mut self, camera: OrbitCamera) {
        self.face_on = (camera.yaw_rad.cos() * camera.pitch_rad.cos()).abs();
    }

    pub fn fluids(&self) -> &[Fluid; 2] {
        &self.fluids
    }

    /// Sets SPH's stiffness `k` (10 to 10,000) and time step (1/4000 to 1/60 s) and starts over;
    /// nothing changes on an error.
    pub fn set_sph(&mut self, stiffness: f32, dt: f32) -> Result<(), String> {
        let k = super::in_range("stiffness k", stiffness, 10.0, 10_000.0)?;
        let dt = super::in_range("SPH time step (s)", dt, 1.0 / 4000.0, 1.0 / 60.0)?;
        self.start[0].params.stiffness = k;
        self.start[0].params.dt = dt;
        self.reset();
        Ok(())
    }

    /// Back to the start.
    pub fn reset(&mut self) {
        self.fluids = self.start.clone();
        self.samples.clear();
    }

    /// Steps both fluids to `time_sec` (0 to [`DAM_DURATION_SEC`]), replaying from the start when
    /// the time goes back; records a sample per frame passed.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<(), String> {
        self.advance_toward(time_sec, usize::MAX)
    }

    /// As [`DamBreakFigure::advance_to`], at most `frames` frames of [`DAM_FRAME_SEC`] a call
    /// (the page's: a frame that cannot catch up leaves the rest to the next ones).
    pub fn advance_toward(&mut self, time_sec: f32, frames: usize) -> Result<(), String> {
        let t = super::in_range("time (s)", time_sec, 0.0, DAM_DURATION_SEC)?;
        let mut left = frames;
        // A frame is taken once less than half of it is left to `t`, so the fluids may be up to
        // half a frame past `t`: only an earlier time starts over.
        if t + 0.5 * DAM_FRAME_SEC + 1e-6 < self.fluids[1].time {
            self.reset();
        }
        while left > 0 && self.fluids[1].time + 0.5 * DAM_FRAME_SEC <= t {
            left -= 1;
            let frame_end = self.fluids[1].time + DAM_FRAME_SEC;
            for f in &mut self.fluids {
                // An exploded fluid stops; its time stays where it stopped.
                while f.exploded().is_none() && f.time + 0.5 * f.params.dt < frame_end {
                    f.step();
                }
            }
            if self.fluids[1].time + 0.5 * DAM_FRAME_SEC < frame_end {
                // PBF cannot fall behind (it never explodes at its defaults); guard anyway.
                break;
            }
            let [a, b] = [self.fluids[0].stats(), self.fluids[1].stats()];
            let gone = |f: &Fluid, v: f32| if f.exploded().is_some() { f32::NAN } else { v };
            self.samples.push([
                frame_end,
                gone(&self.fluids[0], a.density_error_max),
                b.density_error_max,
                gone(&self.fluids[0], a.kinetic),
                b.kinetic,
            ]);
        }
        Ok(())
    }

    /// The plots' rows so far.
    pub fn plot_rows(&self) -> &[[f32; 5]] {
        &self.samples
    }

    /// Both fluids side by side, particles coloured by density, and the note: each one's
    /// largest compression and CFL number, or why SPH stopped.
    pub fn draw(&self, frame: &mut Frame) -> String {
        let size = crate::fluid::box_size(Dim::Two);
        let titles = [("SPH", palette::BLUE), ("PBF", palette::ORANGE)];
        // A narrow gap between the two boxes: the pair is what the canvas's width must hold.
        frame.side_by_side(
            Vec3::new(size.x + 0.2, 0.0, 0.0),
            &titles,
            size.y + 0.12,
            |frame, k| {
                let f = &self.fluids[k];
                let offset = Vec3::new(-0.5 * size.x, 0.0, 0.0);
                let rho0 = f.params.rest_density;
                for (p, rho) in f.positions.iter().zip(&f.densities) {
                    let radius = DAM_POINT_SPACINGS * f.spacing;
                    frame.point(*p + offset, radius, density_color(rho / rho0));
                }
                let corners = [
                    Vec3::new(0.0, size.y, 0.0),
                    Vec3::ZERO,
                    Vec3::new(size.x, 0.0, 0.0),
                    Vec3::new(size.x, size.y, 0.0),
                ]
                .map(|c| c + offset);
                frame.wide_polyline(&corners, palette::DARK, 2.0);
                frame.keep_box_in_view(offset, offset + Vec3::new(size.x, size.y, 0.0));
            },
        );
        // The tanks are slabs in one plane: an orbit to the side stops at DAM_MAX_YAW_RAD, short
        // of edge-on. More than 60° from face-on (from above or below), the inset shows them
        // from the front.
        frame.max_yaw_rad = Some(DAM_MAX_YAW_RAD);
        if self.face_on < 0.5 {
            let half = Vec3::new(size.x + 0.1, 0.0, 0.05);
            frame.inset(
                InsetView::Front,
                "from the front",
                -half,
                half + Vec3::new(0.0, size.y, 0.0),
            );
        }
        let describe = |f: &Fluid, name: &str| match f.exploded() {
            Some((t, why)) => format!("{name} stopped at t = {} s: {why}.", format_number(t)),
            None => {
                let s = f.stats();
                format!(
                    "{name}: densest particle {:+.1} % from ρ₀, CFL {} ({} steps a frame).",
                    100.0 * s.density_error_max,
                    format_number(s.cfl),
                    (DAM_FRAME_SEC / f.params.dt).round()
                )
            }
        };
        // The fluids' own time: on a slow machine they fall behind the timeline.
        format!(
            "{} {} Simulated so far: {} s.",
            describe(&self.fluids[0], "SPH"),
            describe(&self.fluids[1], "PBF"),
            format_number(self.fluids[1].time)
        )
    }
}

/// The splash's particle counts: the fewest, the default and the most the page offers.
pub const SPLASH_MIN: usize = 500;
pub const SPLASH_DEFAULT: usize = 3000;
pub const SPLASH_MAX: usize = 10_000;
/// The splash's kernel radius, in particle spacings (about 33 neighbours in 3D).
pub const SPLASH_H_SPACINGS: f32 = 2.0;
/// The timeline's length, simulated seconds.
pub const SPLASH_DURATION_SEC: f32 = 3.0;
/// The farthest the dam break's camera turns from the front, radians (40°): the tanks keep
/// three quarters of their width on screen.
pub const DAM_MAX_YAW_RAD: f32 = 0.7;
/// The most steps one call of [`SplashFigure::advance_to`] takes: a frame that cannot catch up
/// leaves the rest to the next frames (the fluid falls behind the timeline) instead of holding
/// the page. With many particles fewer: [`SPLASH_STEP_BUDGET`] particle-steps a call, at least
/// one step; with all pairs, one step.
pub const SPLASH_STEPS_PER_CALL: usize = 8;
pub const SPLASH_STEP_BUDGET: usize = 12_000;
/// The most particles the all-pairs search takes: it tests N² pairs a step, 16 million at
/// 4,000, which a frame can just afford.
pub const SPLASH_ALL_PAIRS_MAX: usize = 4000;
/// The step-time sweep's sizes, particles.
pub const SPLASH_SWEEP_SIZES: [usize; 6] = [250, 500, 1000, 2000, 4000, 8000];
/// The most GPU steps one call of [`SplashFigure::plan_gpu_steps`] queues, and only when the
/// GPU has finished the ones before: a GPU slower than the timeline lets the fluid fall behind
/// instead of piling up work. With many particles fewer: [`SPLASH_GPU_STEP_BUDGET`]
/// particle-steps a call, at least one step (a million particles: one).
pub const SPLASH_GPU_STEPS_PER_CALL: usize = 4;
pub const SPLASH_GPU_STEP_BUDGET: usize = 400_000;
/// The GPU sweep: the steps one timing queues at once (timed until the GPU has finished them),
/// and the timings at each size.
pub const SPLASH_GPU_TIMING_STEPS: usize = 4;
pub const SPLASH_GPU_REPEATS: usize = 3;

/// The splash's step-time sweep: [`SPLASH_SWEEP_SIZES`], grid against all pairs, slopes fitted
/// from 1,000 particles.
fn splash_sweep() -> StepTimeSweep {
    StepTimeSweep::with(
        &SPLASH_SWEEP_SIZES,
        ["grid", "all-pairs"],
        "particles",
        1000,
    )
}

/// The 3D splash's kernel radius for `count` particles.
fn splash_h(count: usize) -> f32 {
    SPLASH_H_SPACINGS * spacing_for(Dim::Three, Scene::Drop, count)
}

/// A 3D fluid for `count` particles: the splash's drop, or the sweep's pool.
fn fluid_3d(method: Method, scene: Scene, count: usize, vorticity: f32) -> Result<Fluid, String> {
    fluid_3d_capped(method, scene, count, vorticity, crate::fluid::MAX_PARTICLES)
}

/// [`fluid_3d`] with a cap of `max` particles (the GPU's start is larger than the CPU's cap).
fn fluid_3d_capped(
    method: Method,
    scene: Scene,
    count: usize,
    vorticity: f32,
    max: usize,
) -> Result<Fluid, String> {
    let mut params = FluidParams::default_3d(method);
    params.h = SPLASH_H_SPACINGS * spacing_for(Dim::Three, scene, count);
    params.vorticity = vorticity;
    params.s_corr = FIGURE_S_CORR;
    Fluid::with_cap(params, scene, count, 5, max)
}

/// A ball of water dropped into a pool in 3D, stepped by SPH or PBF with the grid or all pairs
/// on the CPU, or on the GPU grid (WebGPU compute: the page's binding holds the GPU fluid, this
/// figure its start, its clock and its note), and the step-time sweep the page runs beside it.
#[derive(Clone, Debug)]
pub struct SplashFigure {
    start: Fluid,
    fluid: Fluid,
    method: Method,
    count: usize,
    search: Search,
    vorticity: f32,
    sweep: StepTimeSweep,
    /// The fluid the sweep times, at the size it asked for.
    bench: Option<Fluid>,
    /// GPU mode: the particle count (0: the CPU steps the fluid) and the GPU fluid's start.
    gpu_count: usize,
    gpu_start: Option<Fluid>,
    /// The GPU fluid's clock: the time after the steps queued so far, seconds.
    gpu_time: f32,
    /// The GPU fluid's fastest particle at the last readback (m/s), and when and why it
    /// exploded (the CPU's verdict, [`crate::fluid::explosion_verdict`]).
    gpu_fastest: Option<f32>,
    gpu_exploded: Option<(f32, String)>,
    /// The GPU grid's timings, per size of [`SPLASH_SWEEP_SIZES`] (ms per step), once the page
    /// asked for them ([`SplashFigure::set_gpu_sweep`]).
    gpu_sweep: bool,
    gpu_times: Vec<Vec<f32>>,
}

impl Default for SplashFigure {
    fn default() -> Self {
        Self::new()
    }
}

fn parse_method(name: &str) -> Result<Method, String> {
    match name {
        "SPH" => Ok(Method::Sph),
        "PBF" => Ok(Method::Pbf),
        other => Err(format!("method must be \"SPH\" or \"PBF\", got {other:?}")),
    }
}

fn parse_search(name: &str) -> Result<Search, String> {
    match name {
        "grid" => Ok(Search::Grid),
        "all pairs" => Ok(Search::AllPairs),
        other => Err(format!(
            "search must be \"grid\" or \"all pairs\", got {other:?}"
        )),
    }
}

impl SplashFigure {
    pub fn new() -> Self {
        let start =
            fluid_3d(Method::Pbf, Scene::Drop, SPLASH_DEFAULT, 0.0).expect("valid defaults");
        Self {
            fluid: start.clone(),
            start,
            method: Method::Pbf,
            count: SPLASH_DEFAULT,
            search: Search::Grid,
            vorticity: 0.0,
            sweep: splash_sweep(),
            bench: None,
            gpu_count: 0,
            gpu_start: None,
            gpu_time: 0.0,
            gpu_fastest: None,
            gpu_exploded: None,
            gpu_sweep: false,
            gpu_times: vec![Vec::new(); SPLASH_SWEEP_SIZES.len()],
        }
    }

    /// Chooses the solver ("SPH" or "PBF"), about `count` particles (whole, from
    /// [`SPLASH_MIN`] to [`SPLASH_MAX`]), the search ("grid" or "all pairs") and PBF's
    /// vorticity confinement `ε` (0 to 0.5), and starts over; nothing changes on an error.
    pub fn set(
        &mut self,
        method: &str,
        count: f32,
        search: &str,
        vorticity: f32,
    ) -> Result<(), String> {
        let method = parse_method(method)?;
        let count = super::whole_number("particles", count, SPLASH_MIN, SPLASH_MAX)?;
        let search = parse_search(search)?;
        let vorticity = super::in_range("vorticity confinement", vorticity, 0.0, 0.5)?;
        if search == Search::AllPairs && count > SPLASH_ALL_PAIRS_MAX {
            return Err(format!(
                "all pairs takes at most {SPLASH_ALL_PAIRS_MAX} particles (it tests N² pairs a step), got {count}: use the grid, or fewer particles"
            ));
        }
        let same_fluid = (method, count, vorticity) == (self.method, self.count, self.vorticity);
        // The GPU's start follows the solver and ε; it is built first, so an error changes
        // nothing.
        let gpu_start =
            if self.gpu_count > 0 && (method, vorticity) != (self.method, self.vorticity) {
                Some(self.gpu_fluid(method, self.gpu_count, vorticity)?)
            } else {
                None
            };
        if !same_fluid {
            self.start = fluid_3d(method, Scene::Drop, count, vorticity)?;
        }
        if let Some(start) = gpu_start {
            self.gpu_start = Some(start);
        }
        self.restart_gpu_clock();
        self.start.set_search(search);
        (self.method, self.count, self.search, self.vorticity) = (method, count, search, vorticity);
        self.fluid = self.start.clone();
        Ok(())
    }

    pub fn fluid(&self) -> &Fluid {
        &self.fluid
    }

    /// The kernel radius at the present count, metres.
    pub fn h(&self) -> f32 {
        splash_h(self.count)
    }

    /// Steps towards `time_sec` (0 to [`SPLASH_DURATION_SEC`]), at most
    /// [`SPLASH_STEPS_PER_CALL`] steps; back in time starts over. Returns the steps taken.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, String> {
        let t = super::in_range("time (s)", time_sec, 0.0, SPLASH_DURATION_SEC)?;
        // A step is taken once less than half of it is left to `t`: only a time more than half
        // a step before the fluid's starts over.
        if t + 0.5 * self.fluid.params.dt + 1e-6 < self.fluid.time {
            self.fluid = self.start.clone();
        }
        let most = match self.search {
            Search::Grid => {
                (SPLASH_STEP_BUDGET / self.fluid.len().max(1)).clamp(1, SPLASH_STEPS_PER_CALL)
            }
            Search::AllPairs => 1,
        };
        let mut steps = 0;
        while steps < most
            && self.fluid.exploded().is_none()
            && self.fluid.time + 0.5 * self.fluid.params.dt <= t
        {
            self.fluid.step();
            steps += 1;
        }
        Ok(steps)
    }

    /// The particles coloured by speed (blue at rest, through white, to red at 3 m/s), the
    /// box's edges; returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        let f = &self.fluid;
        for (p, v) in f.positions.iter().zip(&f.velocities) {
            let speed = (v.length() / 3.0).min(1.0);
            let color = super::noise::diverging_color(1.2 * speed - 0.6).truncate();
            frame.point(*p, 0.45 * f.spacing, color);
        }
        draw_box(frame);
        let search = match self.search {
            Search::Grid => "neighbours from the grid",
            Search::AllPairs => "neighbours by testing all pairs",
        };
        let name = self.method_name();
        match f.exploded() {
            Some((t, why)) => format!("{name} stopped at t = {} s: {why}.", format_number(t)),
            None => {
                let s = f.stats();
                format!(
                    "{name}, {} particles, {search}, h = {} m, t = {} s: largest compression {:.1} %, fastest particle {} m/s.",
                    f.len(),
                    format_number(f.params.h),
                    format_number(f.time),
                    100.0 * s.density_error_max.max(0.0),
                    format_number(s.max_speed)
                )
            }
        }
    }

    /// The GPU fluid's start for `count` particles (the slider's count, or up to
    /// [`MAX_GPU_FLUID_PARTICLES`]).
    fn gpu_fluid(&self, method: Method, count: usize, vorticity: f32) -> Result<Fluid, String> {
        fluid_3d_capped(
            method,
            Scene::Drop,
            count,
            vorticity,
            MAX_GPU_FLUID_PARTICLES,
        )
    }

    /// GPU mode with about `count` particles (whole, from [`SPLASH_MIN`] to
    /// [`MAX_GPU_FLUID_PARTICLES`]), or the CPU with 0; the GPU fluid starts over. Nothing
    /// changes on an error (a count over the cap among them).
    pub fn set_gpu(&mut self, count: f32) -> Result<(), String> {
        if count == 0.0 {
            (self.gpu_count, self.gpu_start) = (0, None);
            return Ok(());
        }
        let n = super::whole_number(
            "GPU particles (0 for the CPU)",
            count,
            SPLASH_MIN,
            MAX_GPU_FLUID_PARTICLES,
        )?;
        if n != self.gpu_count {
            self.gpu_start = Some(self.gpu_fluid(self.method, n, self.vorticity)?);
            self.gpu_count = n;
        }
        self.restart_gpu_clock();
        Ok(())
    }

    /// The GPU fluid starts over from the same start: its clock at 0, no readback, no verdict.
    pub fn restart_gpu_clock(&mut self) {
        self.gpu_time = 0.0;
        self.gpu_fastest = None;
        self.gpu_exploded = None;
    }

    /// Records the GPU fluid's fastest particle, `speed` m/s (infinite or NaN: a position or
    /// velocity stopped being a number), read back after the steps up to `time_sec`; past
    /// [`crate::fluid::explosion_speed`] the GPU fluid has exploded, as the CPU's would, and
    /// stops. A readback from before a restart (later than the clock) is ignored.
    pub fn record_gpu_fastest(&mut self, time_sec: f32, speed: f32) -> Result<(), String> {
        let t = super::finite("time (s)", time_sec)?;
        let Some(start) = &self.gpu_start else {
            return Err("GPU mode is off: choose a GPU count first".into());
        };
        if self.gpu_exploded.is_some() || t > self.gpu_time + 1e-4 {
            return Ok(());
        }
        self.gpu_fastest = Some(speed);
        if let Some(why) = crate::fluid::explosion_verdict(&start.params, speed) {
            self.gpu_exploded = Some((t, why));
        }
        Ok(())
    }

    /// When and why the GPU fluid exploded, once a readback showed it.
    pub fn gpu_exploded(&self) -> Option<(f32, &str)> {
        self.gpu_exploded
            .as_ref()
            .map(|(t, why)| (*t, why.as_str()))
    }

    /// Whether the GPU steps the fluid.
    pub fn gpu_mode(&self) -> bool {
        self.gpu_count > 0
    }

    /// The GPU fluid's start (GPU mode only), for the binding to upload.
    pub fn gpu_start(&self) -> Option<&Fluid> {
        self.gpu_start.as_ref()
    }

    /// The GPU fluid's clock, seconds.
    pub fn gpu_time(&self) -> f32 {
        self.gpu_time
    }

    /// How far the drawn fluid has got, seconds: its time (the GPU's clock in GPU mode), or the
    /// end of the timeline once it has stopped (exploded). The page's timeline keeps at most a
    /// moment ahead of it, so that on a slow machine it waits for the fluid instead of wrapping
    /// and starting the run over before the splash.
    pub fn ready_sec(&self) -> f32 {
        let (time, stopped) = if self.gpu_mode() {
            (self.gpu_time, self.gpu_exploded.is_some())
        } else {
            (self.fluid.time, self.fluid.exploded().is_some())
        };
        if stopped {
            SPLASH_DURATION_SEC
        } else {
            time
        }
    }

    /// The GPU steps towards `time_sec`: `(start over, steps to queue)`. Back in time (more than
    /// half a step) starts over from the start; ahead, at most [`SPLASH_GPU_STEPS_PER_CALL`]
    /// steps (fewer with many particles: [`SPLASH_GPU_STEP_BUDGET`]), and none while `gpu_idle` is false (the GPU still runs the steps queued before).
    pub fn plan_gpu_steps(
        &mut self,
        time_sec: f32,
        gpu_idle: bool,
    ) -> Result<(bool, usize), String> {
        let t = super::in_range("time (s)", time_sec, 0.0, SPLASH_DURATION_SEC)?;
        let start = self
            .gpu_start
            .as_ref()
            .ok_or("GPU mode is off: choose a GPU count first")?;
        let dt = start.params.dt;
        let most =
            (SPLASH_GPU_STEP_BUDGET / start.len().max(1)).clamp(1, SPLASH_GPU_STEPS_PER_CALL);
        let restart = t + 0.5 * dt + 1e-6 < self.gpu_time;
        if restart {
            self.restart_gpu_clock();
        }
        let mut steps = 0;
        // An exploded fluid stops, as the CPU's does; its clock stays where it stopped.
        let going = (gpu_idle || restart) && self.gpu_exploded.is_none();
        while going && steps < most && self.gpu_time + 0.5 * dt <= t {
            self.gpu_time += dt;
            steps += 1;
        }
        Ok((restart, steps))
    }

    /// GPU mode: the box's edges (the particles are the GPU's sprites, coloured by speed as
    /// [`SplashFigure::draw`] colours them); returns the note, with the fastest particle of
    /// the last readback, or why the fluid stopped.
    pub fn draw_gpu(&self, frame: &mut Frame) -> String {
        draw_box(frame);
        let Some(f) = &self.gpu_start else {
            return "GPU mode is off.".into();
        };
        let name = self.method_name();
        if let Some((t, why)) = &self.gpu_exploded {
            return format!(
                "{name} on the GPU stopped at t = {} s: {why}.",
                format_number(*t)
            );
        }
        let fastest = match self.gpu_fastest {
            Some(v) => format!(" Fastest particle {} m/s.", format_number(v)),
            None => String::new(),
        };
        format!(
            "{name} on the GPU, {} particles, neighbours from the GPU grid, h = {} m, t = {} s.{fastest} The steps are queued and run beside the page, a few a frame once the GPU has finished the ones before (it falls behind the timeline when it is slower); the particles stay on the GPU, and only the fastest one's speed comes back, to stop the fluid if it explodes.",
            f.len(),
            format_number(f.params.h),
            format_number(self.gpu_time),
        )
    }

    /// The solver's name, with vorticity confinement when it is on.
    fn method_name(&self) -> String {
        match (self.method, self.vorticity > 0.0) {
            (Method::Sph, false) => "SPH".to_string(),
            (Method::Sph, true) => "SPH (vorticity confinement is PBF's)".to_string(),
            (Method::Pbf, false) => "PBF".to_string(),
            (Method::Pbf, true) => format!(
                "PBF with vorticity confinement ε = {}",
                format_number(self.vorticity)
            ),
        }
    }

    /// Starts the step-time sweep again (the page's "measure" button), the GPU's timings too.
    pub fn start_sweep(&mut self) {
        self.sweep = splash_sweep();
        self.gpu_times = vec![Vec::new(); SPLASH_SWEEP_SIZES.len()];
    }

    /// Whether the sweep times the GPU grid as well (the page says so where WebGPU is there);
    /// starts the sweep again.
    pub fn set_gpu_sweep(&mut self, on: bool) {
        self.gpu_sweep = on;
        self.start_sweep();
    }

    /// The size the sweep times the GPU grid at next, once the CPU's timings are done
    /// ([`SPLASH_GPU_REPEATS`] at each size, [`SPLASH_GPU_TIMING_STEPS`] steps each), or `None`.
    /// The binding uploads [`SplashFigure::gpu_timing_fluid`] of that size, times the steps,
    /// then calls [`SplashFigure::record_gpu_sweep`].
    pub fn next_gpu_timing(&mut self) -> Option<usize> {
        if !self.gpu_sweep || !self.sweep.done() {
            return None;
        }
        let k = self
            .gpu_times
            .iter()
            .position(|t| t.len() < SPLASH_GPU_REPEATS)?;
        Some(SPLASH_SWEEP_SIZES[k])
    }

    /// The fluid the GPU sweep times at `count` particles: the CPU sweep's 3D SPH pool.
    pub fn gpu_timing_fluid(count: usize) -> Result<Fluid, String> {
        fluid_3d(Method::Sph, Scene::Pool, count, 0.0)
    }

    /// Records the GPU timing [`SplashFigure::next_gpu_timing`] asked for, ms per step.
    pub fn record_gpu_sweep(&mut self, ms: f32) -> Result<(), String> {
        let ms = super::in_range("GPU step time (ms)", ms, 0.0, 1e6)?;
        let k = self
            .gpu_times
            .iter()
            .position(|t| t.len() < SPLASH_GPU_REPEATS)
            .filter(|_| self.gpu_sweep && self.sweep.done())
            .ok_or("no GPU timing is due")?;
        self.gpu_times[k].push(ms);
        Ok(())
    }

    /// The sweep's plot rows, flat: the CPU sweep's nine columns (see
    /// [`StepTimeSweep::plot_samples`]), then the GPU grid's median, fastest and slowest (NaN
    /// until timed).
    pub fn sweep_samples(&self) -> Vec<f32> {
        let cpu = self.sweep.plot_samples();
        let mut out = Vec::with_capacity(cpu.len() / 9 * 12);
        for row in cpu.chunks_exact(9) {
            out.extend_from_slice(row);
            let k = SPLASH_SWEEP_SIZES.iter().position(|&n| n as f32 == row[0]);
            let t = k
                .map(|k| &self.gpu_times[k])
                .filter(|t| t.len() == SPLASH_GPU_REPEATS);
            match t {
                Some(t) => {
                    let mut v = t.clone();
                    crate::order::sort_ascending(&mut v);
                    out.extend([v[v.len() / 2], v[0], v[v.len() - 1]]);
                }
                None => out.extend([f32::NAN; 3]),
            }
        }
        out
    }

    /// The sweep's note: the CPU's, then where the GPU grid stands.
    pub fn sweep_note(&mut self) -> String {
        let mut note = self.sweep.note();
        if !self.gpu_sweep {
            return note;
        }
        if let Some(n) = self.next_gpu_timing() {
            if self.sweep.done() {
                note.push_str(&format!(" Now timing the GPU grid at N = {n}…"));
            }
            return note;
        }
        let k = SPLASH_SWEEP_SIZES.len() - 1;
        let mut v = self.gpu_times[k].clone();
        if v.is_empty() {
            return note;
        }
        crate::order::sort_ascending(&mut v);
        note.push_str(&format!(
            " The GPU grid (WebGPU compute, {SPLASH_GPU_TIMING_STEPS} steps queued at once and timed until the GPU has finished them) takes {:.2} ms a step at N = {}. Its times depend on the adapter the browser gives the page: a software one, which runs the shaders on the CPU, can be slower than the CPU grid.",
            v[v.len() / 2],
            SPLASH_SWEEP_SIZES[k]
        ));
        note
    }

    /// The search the sweep times next ("grid" or "all-pairs"), with the timing fluid (a 3D
    /// SPH dam break) built at its size, or `None` when the sweep is done. The page times
    /// [`SplashFigure::timing_step`], then calls [`SplashFigure::record_sweep`].
    pub fn next_sweep_timing(&mut self) -> Result<Option<&'static str>, String> {
        let Some((n, search)) = self.sweep.next_timing() else {
            return Ok(None);
        };
        if self.bench.as_ref().map(|f| f.params.h) != Some(splash_h_pool(n)) {
            let mut fluid = fluid_3d(Method::Sph, Scene::Pool, n, 0.0)?;
            fluid.step(); // the neighbour lists' first allocation stays out of the timings
            self.bench = Some(fluid);
        }
        Ok(Some(search))
    }

    /// One SPH step of the timing fluid with `search` ("grid" or "all-pairs").
    pub fn timing_step(&mut self, search: &str) -> Result<(), String> {
        let search = match search {
            "all-pairs" => Search::AllPairs,
            other => parse_search(other)?,
        };
        let fluid = self.bench.as_mut().ok_or("ask for the next timing first")?;
        fluid.set_search(search);
        fluid.step();
        Ok(())
    }

    /// Records the timing of [`SplashFigure::next_sweep_timing`]: milliseconds per step.
    pub fn record_sweep(&mut self, ms: f32) -> Result<(), String> {
        self.sweep.record(ms)
    }

    /// The sweep, for its plot samples and note.
    pub fn sweep(&mut self) -> &mut StepTimeSweep {
        &mut self.sweep
    }
}

/// The 3D box's edges, and the box kept in view.
fn draw_box(frame: &mut Frame) {
    let size = box_size(Dim::Three);
    let corners = |i: usize| {
        Vec3::new(
            if i & 1 == 0 { 0.0 } else { size.x },
            if i & 2 == 0 { 0.0 } else { size.y },
            if i & 4 == 0 { 0.0 } else { size.z },
        )
    };
    for i in 0..8 {
        for bit in [1, 2, 4] {
            if i & bit == 0 {
                frame.wide_line(corners(i), corners(i | bit), palette::GREY, 1.5);
            }
        }
    }
    frame.keep_box_in_view(Vec3::ZERO, size);
}

/// The sweep's pool's kernel radius for `count` particles.
fn splash_h_pool(count: usize) -> f32 {
    SPLASH_H_SPACINGS * spacing_for(Dim::Three, Scene::Pool, count)
}
