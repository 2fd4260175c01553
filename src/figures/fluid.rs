//! Figure logic for the fluids lesson (see [`crate::fluid`]); the lesson page is not written yet.
//!
//! - [`KernelsFigure`]: the four kernels of one support radius, as plot rows.
//! - [`DensityFigure`]: a 2D pool at rest; the reader drags one particle and sees the neighbours
//!   within `h`, each one's weight, and the density they add up to.
//! - [`DamBreakFigure`]: SPH and PBF on the same 2D dam break side by side, SPH's stiffness and
//!   time step the reader's (past its limit it stops, and says why).

use super::{format_number, palette, Frame};
use crate::draw::{StrokeStyle, DOT_PX};
use crate::fluid::kernels::{Dim, Kernels};
use crate::fluid::{density, spacing_for, Fluid, FluidParams, Method, Scene};
use glam::Vec3;

/// The kernels of support radius `h` in 2D or 3D, for the lesson's kernel plots.
#[derive(Clone, Debug)]
pub struct KernelsFigure {
    h: f32,
    dim: Dim,
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
        }
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

    /// `samples` rows from `r = 0` to `1.25 h`: `[r, poly6, spiky, −dW/dr of spiky, ∇²W of
    /// viscosity]`, each kernel as a share of its largest value, so one axis shows all four
    /// (they differ by orders of magnitude) and where each reaches zero: at `h`, and beyond.
    pub fn plot_rows(&self, samples: usize) -> Result<Vec<[f32; 5]>, String> {
        super::check_samples(samples)?;
        let k = Kernels::new(self.h, self.dim);
        let slope = |r: f32| -k.spiky_gradient(Vec3::X * r).x;
        // The spiky slope is largest as r → 0: its value at a millionth of h.
        let peaks = [
            k.poly6(0.0),
            k.spiky(0.0),
            slope(1e-6 * self.h),
            k.viscosity_laplacian(0.0),
        ];
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

/// Particles in the density figure's pool.
pub const DENSITY_PARTICLES: usize = 500;
/// The density figure's kernel radius, in particle spacings (about 23 neighbours in 2D).
pub const DENSITY_H_SPACINGS: f32 = 2.7;

/// A 2D pool at rest whose first particle the reader moves (the probe). Dropped into the
/// water, the probe takes the place of the particle nearest to it (within half a spacing).
#[derive(Clone, Debug)]
pub struct DensityFigure {
    fluid: Fluid,
    /// The probe's neighbours (indices) and their distances, after the last move.
    neighbours: Vec<(usize, f32)>,
    probe_density: f32,
    /// The particle the probe stands in for: the nearest one within half a spacing, left out of
    /// the sum and the drawing (two particles in one place would count the fluid there twice).
    replaced: Option<usize>,
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
            fluid,
            neighbours: Vec::new(),
            probe_density: 0.0,
            replaced: None,
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

    /// Moves the probe (particle 0) to `(x, y)` inside the box and recomputes every density;
    /// an error leaves the figure as it was.
    pub fn set_probe(&mut self, x: f32, y: f32) -> Result<(), String> {
        let size = crate::fluid::box_size(Dim::Two);
        let x = super::in_range("x (m)", x, 0.0, size.x)?;
        let y = super::in_range("y (m)", y, 0.0, size.y)?;
        self.fluid.positions[0] = Vec3::new(x, y, 0.0);
        self.fluid.search();
        self.fluid.refresh_densities();
        let p = self.fluid.positions[0];
        self.neighbours = self
            .fluid
            .neighbours(0)
            .iter()
            .map(|&j| (j as usize, (self.fluid.positions[j as usize] - p).length()))
            .collect();
        self.neighbours.sort_by(|a, b| a.1.total_cmp(&b.1));
        self.replaced = self
            .neighbours
            .first()
            .filter(|&&(_, r)| r < 0.5 * self.fluid.spacing)
            .map(|&(j, _)| j);
        if self.replaced.is_some() {
            self.neighbours.remove(0);
        }
        self.probe_density = density(
            p,
            self.neighbours
                .iter()
                .map(|&(j, _)| self.fluid.positions[j]),
            self.fluid.mass,
            self.h(),
            Dim::Two,
        );
        Ok(())
    }

    /// The probe's density, kg/m² (2D), and its neighbours' count.
    pub fn probe(&self) -> (f32, usize) {
        (self.probe_density, self.neighbours.len())
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

    /// The pool's particles coloured by density (white at the rest density, red above, blue
    /// below), the probe's support circle, lines to its neighbours (thicker for larger weights)
    /// and its label. Returns the note.
    pub fn draw(&self, frame: &mut Frame) -> String {
        let f = &self.fluid;
        let rho0 = f.params.rest_density;
        let h = self.h();
        let size = crate::fluid::box_size(Dim::Two);
        let radius = 0.35 * f.spacing;
        for (i, &p) in f.positions.iter().enumerate().skip(1) {
            if Some(i) == self.replaced {
                continue;
            }
            let ratio = f.densities[i] / rho0 - 1.0;
            // Full red or blue at ±50 % of the rest density.
            let color = super::noise::diverging_color(ratio / 0.5 * 0.6).truncate();
            frame.point(p, radius, color);
        }
        let p = f.positions[0];
        let k = Kernels::new(h, Dim::Two);
        let w0 = k.poly6(0.0);
        for &(j, r) in &self.neighbours {
            let share = k.poly6(r * r) / w0;
            frame.wide_line(p, f.positions[j], palette::PURPLE, 1.0 + 3.0 * share);
        }
        let circle: Vec<Vec3> = (0..=64)
            .map(|i| {
                let a = std::f32::consts::TAU * i as f32 / 64.0;
                p + h * Vec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        frame.stroke(
            &circle,
            palette::PURPLE,
            StrokeStyle::dashed(2.0, 0.02, 0.012),
        );
        frame.marker_on_top(p, 1.6 * DOT_PX, palette::PURPLE);
        frame.label(
            p + Vec3::new(0.0, h + 0.03, 0.0),
            "dragged particle",
            palette::PURPLE,
        );
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
        let (rho, n) = self.probe();
        format!(
            "ρ = {} kg/m² from {n} neighbours within h = {} m and itself: {} of the rest density {} kg/m².",
            format_number(rho),
            format_number(h),
            format_number(rho / rho0),
            format_number(rho0)
        )
    }
}

/// The dam-break figure's particles per fluid, and its kernel radius in spacings.
pub const DAM_PARTICLES: usize = 800;
/// The figure's frame: the fluids are stepped to the timeline's time at their own steps.
pub const DAM_FRAME_SEC: f32 = 1.0 / 60.0;
/// The longest the timeline runs, seconds (the samples of the plots cover it).
pub const DAM_DURATION_SEC: f32 = 6.0;

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
            Fluid::new(params, Scene::DamBreak, DAM_PARTICLES, 3).expect("valid defaults")
        };
        let start = [make(Method::Sph), make(Method::Pbf)];
        Self {
            fluids: start.clone(),
            start,
            samples: Vec::new(),
        }
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
        let t = super::in_range("time (s)", time_sec, 0.0, DAM_DURATION_SEC)?;
        if t + 1e-6 < self.fluids[1].time {
            self.reset();
        }
        while self.fluids[1].time + 0.5 * DAM_FRAME_SEC <= t {
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
        frame.side_by_side(
            Vec3::new(size.x + 0.3, 0.0, 0.0),
            &titles,
            size.y + 0.12,
            |frame, k| {
                let f = &self.fluids[k];
                let offset = Vec3::new(-0.5 * size.x, 0.0, 0.0);
                let rho0 = f.params.rest_density;
                for (p, rho) in f.positions.iter().zip(&f.densities) {
                    let color = super::noise::diverging_color((rho / rho0 - 1.0) / 0.5 * 0.6);
                    frame.point(*p + offset, 0.4 * f.spacing, color.truncate());
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
        let describe = |f: &Fluid, name: &str| match f.exploded() {
            Some((t, why)) => format!("{name} stopped at t = {} s: {why}.", format_number(t)),
            None => {
                let s = f.stats();
                format!(
                    "{name}: compressed at most {:.1} %, CFL {} ({} steps a frame).",
                    100.0 * s.density_error_max.max(0.0),
                    format_number(s.cfl),
                    (DAM_FRAME_SEC / f.params.dt).round()
                )
            }
        };
        format!(
            "{} {}",
            describe(&self.fluids[0], "SPH"),
            describe(&self.fluids[1], "PBF")
        )
    }
}
