//! Figure logic for lesson 12, "Boids" (see [`crate::figures`]).
//!
//! - [`FlockFigure`]: a flock with every rule's weight and radius, the field of view, the
//!   count, a force law, an obstacle, a leader and a predator; naive or grid search; one boid
//!   highlighted with its neighbours; a second flock the page times at several sizes.
//! - [`RulesFigure`]: one boid and its neighbours seen from above: radius, field of view, the
//!   three steering vectors (exercise 12.1) and the grid cells around it (exercise 12.2).

use super::particles::{steps_to, SIM_DT};
use super::FirstPanic;
use super::{format_number, in_range, palette, Frame, MeshId, Runner, DEFAULT_RUNNER};
use crate::boids::{cell_index, seeded_start, three_rules, BoidParams, Flock, ForceLaw, Search};
use crate::draw::inset::InsetView;
use crate::exercises::run;
use crate::figures::gpu::{check_gpu_boids, MAX_GPU_GRID_BOIDS};
use crate::particles::Sphere;
use crate::camera::OrbitCamera;
use crate::draw::{layout::Rect, Label};
use glam::{Mat4, Vec2, Vec3};

const FILE: &str = "src/exercises/boids.rs";
const TOLERANCE: f32 = 1e-4;
/// The most boids the page's flock may have (every boid is drawn; software rendering in the
/// tests draws them too). The core allows [`crate::boids::MAX_BOIDS`].
pub const PAGE_MAX_BOIDS: usize = 3000;
/// The most boids the page may time in one step (the naive search at this size takes a while in
/// a debug build).
pub const PAGE_MAX_TIMED_BOIDS: usize = 20_000;

/// The most steps the flock takes to catch up with the timeline in one call (a slow frame);
/// a longer jump (a scrub, the loop) restarts the flock. The page caps a frame at 0.1 s and
/// plays at up to 2×: 0.2 s of timeline, 12 steps of [`SIM_DT`], 13 where the frame's ends
/// round apart, so the slowest frame catches up instead of restarting.
pub const MAX_CATCH_UP: usize = 13;

/// GPU mode: the most steps queued in one call for a flock of `n` boids: 10 up to 10,000 boids,
/// fewer above, one from 100,000 on, so that a frame queues about the same work at any size.
pub fn max_gpu_steps(n: usize) -> usize {
    (100_000 / n.max(1)).clamp(1, 10)
}

/// Length of the flock figure's purple steering arrow per m/s² of steering acceleration, metres.
pub const STEER_ARROW_M_PER_MS2: f32 = 1.0;
/// The longest the steering arrow is drawn, metres (the note gives the value).
pub const STEER_ARROW_MAX_M: f32 = 1.5;
/// Width of a boid's tail (the line behind it along its velocity), in CSS pixels.
pub const TAIL_PX: f32 = 2.0;

/// The last frame's view-projection and canvas size (CSS pixels), which names are placed for.
fn view_of(view: Option<(OrbitCamera, Vec2)>) -> Option<(Mat4, Vec2)> {
    view.map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size))
}

/// Places the first of `candidates` that keeps [`NAME_CLEAR_PX`] off the frame's dots, lines and
/// names on the last frame's `view` (the first one without a view, or if none is clear). One
/// function for both figures' names, so `Frame::first_clear_label_by` is compiled once for them.
fn place_name(frame: &mut Frame, view: Option<(Mat4, Vec2)>, candidates: Vec<Label>) {
    fn anywhere(_: Rect) -> bool {
        true
    }
    frame.first_clear_label_by(view, NAME_CLEAR_PX, candidates, anywhere);
}

/// How wide the flock figure draws the leader's and the predator's dots, CSS pixels: they
/// stand out from the flock's 0.035 m dots at any distance.
pub const ROLE_DOT_PX: f32 = 16.0;

/// What a name keeps off the lines and dots around it, CSS pixels: 2 px, and 1 px more as the
/// clearance test samples each line at 17 points (a line can graze the box between two).
const NAME_CLEAR_PX: f32 = 3.0;

/// What the force-law dropdown offers.
pub const LAWS: [&str; 3] = ["none", "a1/x² − a2/x⁴", "Gaussian"];
/// The laws behind [`LAWS`]' names, with the flock's constants.
pub const FLOCK_LAWS: [ForceLaw; 3] = [
    ForceLaw::None,
    ForceLaw::InversePower { a1: 0.4, a2: 0.04 },
    // a2 = a1: the net law repels within x0 / 2 and attracts most near x0, as the lesson says
    // (with a2 = 3 a1 it would repel at x0 and barely attract anywhere).
    ForceLaw::Gaussian {
        a1: 1.0,
        a2: 1.0,
        k: 2.0,
        x0: 0.7,
    },
];

/// Where the force-law plot starts and ends, metres: the inverse-power law falls to −∞ at
/// contact, so the plot starts 5 mm from it, where the Gaussian law's finite push at contact
/// (the text's −0.86 m/s²) already shows; it ends at the law's reach in the flock
/// (`BoidParams::law_radius`' default).
pub const LAW_PLOT_X: (f32, f32) = (0.005, 1.5);

/// The force-law plot beside the formulas: `count ∈ [2, 1000]` distances from
/// [`LAW_PLOT_X`]'s start to its end, each as `[x, f(x) of a1/x² − a2/x⁴, f(x) of the
/// Gaussian law]` (flat), with the flock's constants ([`FLOCK_LAWS`]). Positive is attraction.
pub fn law_plot_samples(count: f32) -> Result<Vec<f32>, String> {
    let n = super::whole_number("samples", count, 2, 1000)?;
    let (lo, hi) = LAW_PLOT_X;
    Ok((0..n)
        .flat_map(|i| {
            let x = lo + (hi - lo) * i as f32 / (n - 1) as f32;
            [x, FLOCK_LAWS[1].f(x), FLOCK_LAWS[2].f(x)]
        })
        .collect())
}

/// What the search dropdown offers.
pub const SEARCHES: [&str; 2] = ["grid", "naive"];

// ---------------------------------------------------------------------------------------------
// Step time against N: the page times the steps, this keeps the schedule and sums them up.

/// The flock sizes the page times, doubling from 100 to 3,200.
pub const SWEEP_SIZES: [usize; 6] = [100, 200, 400, 800, 1600, 3200];
/// Timings per size and search; each point of the plot is their median, drawn with their
/// fastest and slowest.
pub const SWEEP_REPEATS: usize = 5;
/// A search whose median step at one size took longer than this (milliseconds) is not timed at
/// the larger sizes (a debug build's naive search at 3,200 boids would hold the page for seconds).
pub const SWEEP_LIMIT_MS: f32 = 60.0;
/// The smallest size the fitted slopes start at: below it a step's fixed costs blur the power.
pub const SWEEP_FIT_FROM: usize = 400;

/// The step-time sweep: which timing comes next, the timings so far, the plot's samples and
/// the note. Grid and naive take turns at each size, repeat by repeat, so a moment of load
/// falls on both searches alike.
/// The fluids lesson times its particles with the same sweep (see [`StepTimeSweep::with`]).
#[derive(Clone, Debug)]
pub struct StepTimeSweep {
    /// The sizes timed, smallest first.
    sizes: &'static [usize],
    /// The two searches' names, the fast one first ("grid", then "naive").
    names: [&'static str; 2],
    /// What is counted ("boids", "particles").
    noun: &'static str,
    /// The smallest size the fitted slopes start at.
    fit_from: usize,
    /// Per size, per search: the milliseconds per step of each timing.
    times: Vec<[Vec<f32>; 2]>,
    /// The next timing: (size index, repeat, search).
    next: (usize, usize, usize),
}

impl Default for StepTimeSweep {
    fn default() -> Self {
        Self::new()
    }
}

/// The median of `xs` (not empty).
fn median(xs: &[f32]) -> f32 {
    let mut v = xs.to_vec();
    crate::order::sort_ascending(&mut v);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

impl StepTimeSweep {
    /// The boids' sweep: [`SWEEP_SIZES`], grid against naive, fitted from [`SWEEP_FIT_FROM`].
    pub fn new() -> Self {
        Self::with(&SWEEP_SIZES, SEARCHES, "boids", SWEEP_FIT_FROM)
    }

    /// A sweep over `sizes` (smallest first) of two searches named `names` (the fast one
    /// first) counting `noun`, its slopes fitted from `fit_from` up.
    pub fn with(
        sizes: &'static [usize],
        names: [&'static str; 2],
        noun: &'static str,
        fit_from: usize,
    ) -> Self {
        Self {
            sizes,
            names,
            noun,
            fit_from,
            times: vec![Default::default(); sizes.len()],
            next: (0, 0, 0),
        }
    }

    /// Whether `search` (0 grid, 1 naive) is still timed at size index `size`: not once its
    /// median at a smaller size passed [`SWEEP_LIMIT_MS`].
    fn times_at(&self, size: usize, search: usize) -> bool {
        (0..size).all(|k| {
            let t = &self.times[k][search];
            t.is_empty() || median(t) <= SWEEP_LIMIT_MS
        })
    }

    /// The next timing to take, `(boids, search)` with search "grid" or "naive", or `None` when
    /// the sweep is done. The same answer until [`StepTimeSweep::record`] is called.
    pub fn next_timing(&mut self) -> Option<(usize, &'static str)> {
        loop {
            let (size, _, search) = self.next;
            if size >= self.sizes.len() {
                return None;
            }
            if self.times_at(size, search) {
                return Some((self.sizes[size], self.names[search]));
            }
            self.advance();
        }
    }

    fn advance(&mut self) {
        let (mut size, mut repeat, mut search) = self.next;
        search += 1;
        if search == 2 {
            search = 0;
            repeat += 1;
        }
        if repeat == SWEEP_REPEATS {
            repeat = 0;
            size += 1;
        }
        self.next = (size, repeat, search);
    }

    /// Records the timing [`StepTimeSweep::next_timing`] asked for: `ms` milliseconds per step
    /// (finite, ≥ 0).
    pub fn record(&mut self, ms: f32) -> Result<(), String> {
        let ms = in_range("step time", ms, 0.0, 1e6)?;
        if self.next_timing().is_none() {
            return Err("the sweep is done: start it again first".into());
        }
        let (size, _, search) = self.next;
        self.times[size][search].push(ms);
        self.advance();
        Ok(())
    }

    /// Whether every timing has been taken.
    pub fn done(&mut self) -> bool {
        self.next_timing().is_none()
    }

    /// `(median, fastest, slowest)` of `search` at size index `size`, if timed.
    fn summary(&self, size: usize, search: usize) -> Option<(f32, f32, f32)> {
        let t = &self.times[size][search];
        (!t.is_empty()).then(|| {
            let lo = t.iter().copied().fold(f32::INFINITY, f32::min);
            let hi = t.iter().copied().fold(0.0, f32::max);
            (median(t), lo, hi)
        })
    }

    /// The plot's samples, one row per size with every repeat of both searches done, flat:
    /// `[N, grid median, grid fastest, grid slowest, naive median, naive fastest, naive slowest,
    /// slope-1 guide, slope-2 guide]` (milliseconds per step; NaN where a search was not timed).
    /// The guides are `c·N` through the grid's median at the largest size timed and `c·N²`
    /// through the naive search's, each over the sizes its search was timed at: on log-log axes
    /// a power law `t ∝ Nᵖ` is a straight line of slope `p`.
    pub fn plot_samples(&self) -> Vec<f32> {
        let complete = |k: usize| {
            (0..2).all(|s| {
                self.times[k][s].len() == SWEEP_REPEATS
                    || (self.times[k][s].is_empty() && !self.times_at(k, s))
            })
        };
        let rows: Vec<usize> = (0..self.sizes.len()).take_while(|&k| complete(k)).collect();
        let anchor = |search: usize, power: i32| {
            rows.iter().rev().find_map(|&k| {
                self.summary(k, search)
                    .map(|(m, _, _)| m / (self.sizes[k] as f32).powi(power))
            })
        };
        let (c1, c2) = (anchor(0, 1), anchor(1, 2));
        let mut out = Vec::with_capacity(9 * rows.len());
        for k in rows {
            let n = self.sizes[k] as f32;
            out.push(n);
            for search in 0..2 {
                let (m, lo, hi) = self
                    .summary(k, search)
                    .unwrap_or((f32::NAN, f32::NAN, f32::NAN));
                out.extend([m, lo, hi]);
            }
            // Each guide spans the sizes its search was timed at.
            let timed = |search: usize| self.summary(k, search).is_some();
            out.push(c1.filter(|_| timed(0)).map_or(f32::NAN, |c| c * n));
            out.push(c2.filter(|_| timed(1)).map_or(f32::NAN, |c| c * n * n));
        }
        out
    }

    /// The least-squares slope of log(median time) against log N for `search` over the sizes
    /// from [`SWEEP_FIT_FROM`] up that are timed: the exponent `p` in `t ∝ Nᵖ`. `None` with
    /// fewer than two such sizes.
    pub fn fitted_slope(&self, search: usize) -> Option<f32> {
        let points: Vec<(f32, f32)> = self
            .sizes
            .iter()
            .enumerate()
            .filter(|&(_, &n)| n >= self.fit_from)
            .filter_map(|(k, &n)| {
                let (m, _, _) = self.summary(k, search)?;
                (self.times[k][search].len() == SWEEP_REPEATS && m > 0.0)
                    .then(|| ((n as f32).ln(), m.ln()))
            })
            .collect();
        if points.len() < 2 {
            return None;
        }
        let n = points.len() as f32;
        let (mx, my) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
        let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
            (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
        });
        Some(sxy / sxx)
    }

    /// What the sweep measured: each search's fitted slope and what it means per doubling, the
    /// ratio at the largest size both timed, how much the repeats spread, and a size left out.
    pub fn note(&mut self) -> String {
        if !self.done() {
            let (size, repeat, _) = self.next;
            return format!(
                "Measuring one step at N = {} {} (timing {} of {} at each size, {} and {} in \
                 turn)…",
                self.sizes[size.min(self.sizes.len() - 1)],
                self.noun,
                repeat + 1,
                SWEEP_REPEATS,
                self.names[0],
                self.names[1]
            );
        }
        let mut parts = Vec::new();
        for (search, name) in [(1, self.names[1]), (0, self.names[0])] {
            if let Some(p) = self.fitted_slope(search) {
                parts.push(format!(
                    "{name} slope {:.1} (×{:.1} per doubling of N)",
                    p,
                    2f32.powf(p)
                ));
            }
        }
        let mut note = format!(
            "Measured in this run, from N = {} up: {}.",
            self.fit_from,
            parts.join(", ")
        );
        let both = (0..self.sizes.len())
            .rev()
            .find_map(|k| Some((k, self.summary(k, 0)?, self.summary(k, 1)?)));
        if let Some((k, (g, _, _), (n, _, _))) = both {
            note.push_str(&format!(
                " At N = {} the {} search takes {:.1}× as long as the {}.",
                self.sizes[k],
                self.names[1],
                n / g.max(1e-6),
                self.names[0]
            ));
        }
        let spread = (0..self.sizes.len())
            .flat_map(|k| [(k, 0), (k, 1)])
            .filter_map(|(k, s)| self.summary(k, s))
            .map(|(m, lo, hi)| (hi - lo) / m.max(1e-6))
            .fold(0.0f32, f32::max);
        note.push_str(&format!(
            " The slowest of a point's {SWEEP_REPEATS} timings was up to {:.0} % above the \
             fastest{}.",
            100.0 * spread,
            if spread > 0.5 {
                ": the machine is busy, so press the button to measure again"
            } else {
                ""
            }
        ));
        for (search, name) in [(1, self.names[1]), (0, self.names[0])] {
            if let Some(k) = (0..self.sizes.len()).find(|&k| !self.times_at(k, search)) {
                note.push_str(&format!(
                    " The {name} search is not timed from N = {} on: a step took over {} ms \
                     (a debug build?).",
                    self.sizes[k], SWEEP_LIMIT_MS
                ));
            }
        }
        note
    }
}

pub fn parse_search(name: &str) -> Result<Search, String> {
    match name {
        "grid" => Ok(Search::Grid),
        "naive" => Ok(Search::Naive),
        _ => Err(format!("search: no search named {name:?} (grid or naive)")),
    }
}

/// The flock figure.
#[derive(Clone, Debug)]
pub struct FlockFigure {
    params: BoidParams,
    flock: Flock,
    search: Search,
    obstacle: bool,
    bench: Option<Flock>,
    neighbours: Vec<usize>,
    seed: u64,
    steps_done: usize,
    /// The order plot's samples since the flock (re)started, flat `[t (s), φ, speed ratio]`, one
    /// per step on the CPU, one per [`GPU_SAMPLE_SEC`] in GPU mode.
    history: Vec<f32>,
    /// How many times the plot has started again: a flock read back from the GPU for an
    /// earlier run is not plotted ([`GpuSample::run`]).
    run: u64,
    /// The step-time sweep the page runs beside the flock.
    sweep: StepTimeSweep,
    /// Whether the flock steps on the GPU (the web layer's compute shader).
    gpu_mode: bool,
    /// GPU mode: the flock's size, or 0 for the slider's flock (see [`FlockFigure::set_gpu_count`]).
    gpu_count: usize,
    /// The camera and canvas size (CSS pixels) of the last frame: the leader's and the
    /// predator's names are placed for it ([`FlockFigure::set_view`]).
    view: Option<(OrbitCamera, Vec2)>,
    /// The farthest any boid has flown from the centre since the flock started, per axis (m):
    /// the inset shows out to there ([`FlockFigure::inset_half`]).
    reach: Vec3,
}

/// GPU mode: the order plot's sampling interval, seconds of flock time (a read-back of the
/// flock from the GPU each).
pub const GPU_SAMPLE_SEC: f32 = 0.1;

/// GPU mode: a sample the order plot is due, handed back with the flock read from the GPU
/// ([`FlockFigure::gpu_sample_due`], [`FlockFigure::record_gpu_sample`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpuSample {
    /// The flock's clock when the read-back was queued, seconds.
    pub time_sec: f32,
    /// The plot's run it belongs to.
    pub run: u64,
}

/// The most samples the order plot keeps (one per step: the figure's 20 s timeline is
/// 1,200 steps; [`super::particles::MAX_SIM_TIME`] is 3,600).
pub const MAX_PLOT_SAMPLES: usize = 3601;

/// `reach` widened, per axis, to the farthest of the finite `positions` from the origin.
fn farthest(reach: Vec3, positions: &[Vec3]) -> Vec3 {
    positions
        .iter()
        .filter(|p| p.is_finite())
        .fold(reach, |r, p| r.max(p.abs()))
}

impl Default for FlockFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl FlockFigure {
    pub fn new() -> Self {
        let params = BoidParams {
            bounds: Vec3::new(3.0, 1.5, 3.0),
            max_speed: 1.8,
            min_speed: 1.2,
            ..Default::default()
        };
        let flock = Flock::new(300, &params, 1).expect("valid defaults");
        let mut f = Self {
            params,
            flock,
            search: Search::Grid,
            obstacle: true,
            bench: None,
            neighbours: Vec::new(),
            seed: 1,
            steps_done: 0,
            history: Vec::with_capacity(3 * MAX_PLOT_SAMPLES),
            run: 0,
            sweep: StepTimeSweep::new(),
            gpu_mode: false,
            gpu_count: 0,
            view: None,
            reach: Vec3::ZERO,
        };
        f.set_obstacle(true);
        f.restart_plot();
        f
    }

    /// The flock's polarisation (Vicsek's order parameter), the leader and predator left out:
    /// ```text
    /// φ = |Σᵢ v̂ᵢ| / N,   v̂ᵢ = vᵢ / |vᵢ|
    /// ```
    /// 1 when every boid heads the same way; about `1/√N` for random headings (0.06 for 300
    /// boids); in between for a flock that has split into groups heading different ways, or
    /// that mills about.
    pub fn polarisation(&self) -> f32 {
        self.order_of(&self.flock.velocities).0
    }

    /// The mean speed of the flock (the leader and predator left out) over the maximum speed,
    /// in `[0, 1]`.
    pub fn speed_ratio(&self) -> f32 {
        self.order_of(&self.flock.velocities).1
    }

    /// `(φ, mean speed / max speed)` of a flock with these velocities, one per boid in the
    /// flock's order, the leader and the predator left out.
    fn order_of(&self, velocities: &[Vec3]) -> (f32, f32) {
        let (leader, predator) = self.flock.roles(&self.params);
        let (heading, speed, n) = velocities
            .iter()
            .enumerate()
            .filter(|&(i, _)| Some(i) != leader && Some(i) != predator)
            .fold((Vec3::ZERO, 0.0, 0usize), |(h, s, n), (_, v)| {
                (h + v.normalize_or_zero(), s + v.length(), n + 1)
            });
        if n == 0 {
            (0.0, 0.0)
        } else {
            let n = n as f32;
            (heading.length() / n, speed / n / self.params.max_speed)
        }
    }

    /// GPU mode: the order plot's next sample, once the last is [`GPU_SAMPLE_SEC`] behind the
    /// flock's clock. The web layer then reads the flock back from the GPU (it arrives a frame
    /// or more later) and hands it to [`FlockFigure::record_gpu_sample`] with this ticket.
    pub fn gpu_sample_due(&self) -> Option<GpuSample> {
        let t = self.steps_done as f32 * SIM_DT;
        let last = self.history.len().checked_sub(3).map(|i| self.history[i]);
        match last {
            Some(last) if t - last < GPU_SAMPLE_SEC - 0.5 * SIM_DT => None,
            _ => Some(GpuSample {
                time_sec: t,
                run: self.run,
            }),
        }
    }

    /// GPU mode: adds the order plot's sample for `ticket` from the flock read back from the
    /// GPU (`velocities`, one per boid, in the flock's order). A ticket from before the plot
    /// started again (a scrub, the loop, a new count) is dropped; returns whether the sample
    /// was added.
    ///
    /// # Errors
    /// A count that is not the flock's, or a velocity that is not finite; nothing is added.
    pub fn record_gpu_sample(
        &mut self,
        ticket: GpuSample,
        velocities: &[Vec3],
    ) -> Result<bool, String> {
        if velocities.len() != self.gpu_len() {
            return Err(format!(
                "GPU sample: {} velocities for a flock of {} boids",
                velocities.len(),
                self.gpu_len()
            ));
        }
        if let Some(i) = velocities.iter().position(|v| !v.is_finite()) {
            return Err(format!("GPU sample: boid {i}'s velocity is not finite"));
        }
        let last = self.history.len().checked_sub(3).map(|i| self.history[i]);
        if ticket.run != self.run
            || last.is_some_and(|last| ticket.time_sec <= last)
            || self.history.len() >= 3 * MAX_PLOT_SAMPLES
        {
            return Ok(false);
        }
        let (phi, speed) = self.order_of(velocities);
        self.history.extend([ticket.time_sec, phi, speed]);
        Ok(true)
    }

    /// Widens the reach the inset shows to hold `positions` (the flock, or in GPU mode the
    /// flock read back from the GPU); positions that are not finite are skipped.
    pub fn widen_reach(&mut self, positions: &[Vec3]) {
        self.reach = farthest(self.reach, positions);
    }

    /// Half the box the inset shows, centred on the origin: the walls are a spring, not a wall,
    /// so boids overshoot them, by about 2 m at the page's settings. The box `[−b, b]` and a
    /// little more, widened to the farthest any boid has flown since the flock started
    /// ([`FlockFigure::widen_reach`]), rounded up to half metres so the inset grows in a few
    /// steps rather than every frame.
    pub fn inset_half(&self, b: Vec3) -> Vec3 {
        ((1.15 * b).max(self.reach) * 2.0).ceil() * 0.5
    }

    /// The order plot's samples, flat `[t (s), φ, mean speed / max speed]`
    /// ([`FlockFigure::polarisation`], [`FlockFigure::speed_ratio`]) after each step since the
    /// flock last started: a scrub, the timeline's loop or a new count starts it again; a
    /// changed weight shows from then on.
    pub fn plot_samples(&self) -> Vec<f32> {
        self.history.clone()
    }

    fn restart_plot(&mut self) {
        self.history.clear();
        self.reach = Vec3::ZERO;
        self.run += 1;
        self.record();
    }

    fn record(&mut self) {
        self.reach = farthest(self.reach, &self.flock.positions);
        if self.history.len() < 3 * MAX_PLOT_SAMPLES {
            let t = self.steps_done as f32 * SIM_DT;
            let sample = [t, self.polarisation(), self.speed_ratio()];
            self.history.extend(sample);
        }
    }

    pub fn len(&self) -> usize {
        self.flock.len()
    }

    pub fn is_empty(&self) -> bool {
        self.flock.is_empty()
    }

    pub fn params(&self) -> &BoidParams {
        &self.params
    }

    pub fn flock(&self) -> &Flock {
        &self.flock
    }

    /// A new flock of `count ∈ [2, PAGE_MAX_BOIDS]` boids.
    pub fn set_count(&mut self, count: f32) -> Result<(), String> {
        let n = super::whole_number("count", count, 2, PAGE_MAX_BOIDS)?;
        self.flock = Flock::new(n, &self.params, self.seed)?;
        self.restart_plot();
        Ok(())
    }

    /// Sets a rule's weight (in [0, 10]) and radius (metres, in [0.05, 3]); `rule` is
    /// "cohesion", "alignment" or "separation".
    pub fn set_rule(&mut self, rule: &str, weight: f32, radius: f32) -> Result<(), String> {
        let w = in_range(&format!("{rule} weight"), weight, 0.0, 10.0)?;
        let r = in_range(&format!("{rule} radius"), radius, 0.05, 3.0)?;
        let target = match rule {
            "cohesion" => &mut self.params.cohesion,
            "alignment" => &mut self.params.alignment,
            "separation" => &mut self.params.separation,
            _ => return Err(format!("rule: no rule named {rule:?}")),
        };
        target.weight = w;
        target.radius = r;
        Ok(())
    }

    /// Field of view, degrees in [0, 360].
    pub fn set_fov_deg(&mut self, fov: f32) -> Result<(), String> {
        self.params.fov_deg = in_range("field of view", fov, 0.0, 360.0)?;
        Ok(())
    }

    /// Maximum speed, m/s, in [0.1, 10] and not below the minimum speed.
    /// The flock's speeds are clamped into the new limits at once ([`Flock::clamp_speeds`]).
    pub fn set_max_speed(&mut self, speed: f32) -> Result<(), String> {
        let speed = in_range("max speed", speed, 0.1, 10.0)?;
        let min = self.params.min_speed;
        if speed < min {
            return Err(format!(
                "max speed must be at least the min speed, {min} m/s, got {speed}"
            ));
        }
        self.params.max_speed = speed;
        self.flock.clamp_speeds(&self.params);
        Ok(())
    }

    /// Minimum speed, m/s, in [0, 10] and not above the maximum speed.
    /// The flock's speeds are clamped into the new limits at once ([`Flock::clamp_speeds`]).
    pub fn set_min_speed(&mut self, speed: f32) -> Result<(), String> {
        let speed = in_range("min speed", speed, 0.0, 10.0)?;
        let max = self.params.max_speed;
        if speed > max {
            return Err(format!(
                "min speed must be at most the max speed, {max} m/s, got {speed}"
            ));
        }
        self.params.min_speed = speed;
        self.flock.clamp_speeds(&self.params);
        Ok(())
    }

    /// The speeds the boids keep, for the notes. A min speed above the max speed acts as the
    /// max (the panel still shows the number typed), so the note says so instead of showing
    /// "between 1.000 and 1.000".
    fn speed_range(&self) -> String {
        let (min, max) = (self.params.min_speed, self.params.max_speed);
        if min > max {
            format!(
                "every boid flies at the max speed, {} m/s (the min speed, {} m/s, is above it)",
                format_number(max),
                format_number(min)
            )
        } else {
            format!(
                "speed between {} and {} m/s",
                format_number(min),
                format_number(max)
            )
        }
    }

    /// Maximum steering acceleration, m/s², in [0.1, 50].
    pub fn set_max_force(&mut self, force: f32) -> Result<(), String> {
        self.params.max_force = in_range("max force", force, 0.1, 50.0)?;
        Ok(())
    }

    /// One of [`LAWS`].
    pub fn set_law(&mut self, name: &str) -> Result<(), String> {
        self.params.law = match LAWS.iter().position(|&l| l == name) {
            Some(k) => FLOCK_LAWS[k],
            _ => return Err(format!("force law: no law named {name:?}")),
        };
        Ok(())
    }

    pub fn set_leader(&mut self, on: bool) {
        self.params.leader = on.then_some(2.0);
    }

    pub fn set_predator(&mut self, on: bool) {
        self.params.predator = on.then_some((1.5, 6.0));
    }

    pub fn set_obstacle(&mut self, on: bool) {
        self.obstacle = on;
        self.params.obstacles = if on {
            vec![Sphere {
                center: Vec3::new(0.0, 0.0, 0.0),
                radius: 0.6,
            }]
        } else {
            Vec::new()
        };
    }

    /// "grid" or "naive". In GPU mode "naive" tests every pair on the GPU, which takes at most
    /// [`crate::figures::gpu::MAX_GPU_BOIDS`] boids: a larger GPU flock rejects it.
    pub fn set_search(&mut self, name: &str) -> Result<(), String> {
        let search = parse_search(name)?;
        if self.gpu_mode {
            check_gpu_boids(self.gpu_len(), search)?;
        }
        self.search = search;
        Ok(())
    }

    pub fn search(&self) -> Search {
        self.search
    }

    /// Steps the flock on the GPU (`true`: the web layer's compute shader, neighbours by the
    /// GPU grid or every pair as [`FlockFigure::set_search`] says) or on the CPU.
    ///
    /// # Errors
    /// A GPU flock that the search cannot step ([`check_gpu_boids`]); nothing changes.
    pub fn set_gpu_mode(&mut self, on: bool) -> Result<(), String> {
        if on {
            check_gpu_boids(self.gpu_len(), self.search)?;
        }
        self.gpu_mode = on;
        Ok(())
    }

    pub fn gpu_mode(&self) -> bool {
        self.gpu_mode
    }

    /// GPU mode: a flock of `count` boids instead of the slider's (`0`: the slider's flock), in
    /// a box grown with the count so that the density stays that of the page's 300 boids
    /// ([`FlockFigure::gpu_params`]); it starts afresh. `count` is 0 or in `[2,`
    /// [`MAX_GPU_GRID_BOIDS`]`]`, and at most [`crate::figures::gpu::MAX_GPU_BOIDS`] in GPU mode with every pair
    /// tested.
    ///
    /// # Errors
    /// A count out of range, or one the search cannot step in GPU mode; nothing changes.
    pub fn set_gpu_count(&mut self, count: usize) -> Result<(), String> {
        if count == 1 || count > MAX_GPU_GRID_BOIDS {
            return Err(format!(
                "GPU boids must be 0 (the slider's flock) or a whole number from 2 to \
                 {MAX_GPU_GRID_BOIDS}, got {count}"
            ));
        }
        let n = if count == 0 { self.flock.len() } else { count };
        if self.gpu_mode {
            check_gpu_boids(n, self.search)?;
        }
        self.gpu_count = count;
        self.restart_plot();
        Ok(())
    }

    /// The GPU flock's own size, 0 for the slider's flock.
    pub fn gpu_count(&self) -> usize {
        self.gpu_count
    }

    /// The number of boids GPU mode steps.
    pub fn gpu_len(&self) -> usize {
        if self.gpu_count == 0 {
            self.flock.len()
        } else {
            self.gpu_count
        }
    }

    /// The parameters GPU mode steps with: the figure's, and for a GPU flock of its own
    /// ([`FlockFigure::set_gpu_count`]) the box scaled by `∛(N / 300)` (at least 1).
    pub fn gpu_params(&self) -> BoidParams {
        let scale = if self.gpu_count == 0 {
            1.0
        } else {
            (self.gpu_count as f32 / 300.0).cbrt().max(1.0)
        };
        BoidParams {
            bounds: self.params.bounds * scale,
            ..self.params.clone()
        }
    }

    /// GPU mode: the flock to upload (positions, velocities, clock): the slider's flock, or a
    /// seeded start of the GPU flock's size in its box.
    pub fn gpu_start(&self) -> (Vec<Vec3>, Vec<Vec3>, f32) {
        if self.gpu_count == 0 {
            let f = &self.flock;
            (f.positions.clone(), f.velocities.clone(), f.time_sec)
        } else {
            let seed = self.seed.wrapping_add(self.steps_done as u64);
            let (p, v) = seeded_start(self.gpu_count, &self.gpu_params(), seed);
            (p, v, self.steps_done as f32 * SIM_DT)
        }
    }

    /// Brings the flock to `time_sec` by fixed steps of [`SIM_DT`]. A jump in time (the timeline
    /// looped or was scrubbed: back, or more than [`MAX_CATCH_UP`] steps forward) starts a fresh
    /// flock, seeded by the time it jumped to, instead of replaying thousands of boids (so a
    /// scrub shows a new flock and the same time shows the same one); changing a parameter acts
    /// from now on. Returns the steps taken, so the page can time one step.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, String> {
        let target = steps_to(time_sec)?;
        if target < self.steps_done || target - self.steps_done > MAX_CATCH_UP {
            let seed = self.seed.wrapping_add(target as u64);
            self.flock = Flock::new(self.flock.len(), &self.params, seed)?;
            self.steps_done = target;
            self.restart_plot();
        }
        let n = target - self.steps_done;
        for _ in 0..n {
            self.flock.step(&self.params, self.search, SIM_DT);
            self.steps_done += 1;
            self.record();
        }
        Ok(n)
    }

    /// GPU mode ([`crate::figures::gpu`]): what [`FlockFigure::advance_to`] would do, without
    /// stepping on the CPU. Returns `(restart, steps)`: on `restart` the flock was reset to a
    /// fresh seeded start (upload it, then step); then run `steps` steps of [`SIM_DT`] on the GPU,
    /// at most [`max_gpu_steps`] (a large flock then runs slower than the timeline).
    pub fn plan_gpu_steps(&mut self, time_sec: f32) -> Result<(bool, usize), String> {
        let target = steps_to(time_sec)?;
        let mut restart = false;
        if target < self.steps_done || target - self.steps_done > MAX_CATCH_UP {
            let seed = self.seed.wrapping_add(target as u64);
            self.flock = Flock::new(self.flock.len(), &self.params, seed)?;
            self.steps_done = target;
            self.restart_plot();
            restart = true;
        }
        let n = (target - self.steps_done).min(max_gpu_steps(self.gpu_len()));
        self.steps_done = target;
        Ok((restart, n))
    }

    /// GPU mode: the box and the obstacles (the boids themselves are the compute shader's
    /// sprites, drawn by the renderer); returns the note.
    pub fn draw_gpu(&mut self, frame: &mut Frame) -> String {
        let b = self.gpu_params().bounds;
        for (a, c) in box_edges(-b, b) {
            frame.wide_line(a, c, palette::GREY, 1.5);
        }
        // The flock from above, where its spread along the main view's depth can be read, out
        // to where a boid's overshoot past the walls can reach; the main view frames the same
        // reach (the box and every boid so far, growing in half metres), so no boid that
        // overshoots a wall leaves the canvas.
        let reach = self.inset_half(b);
        frame.keep_box_in_view(-reach, reach);
        frame.inset(InsetView::Top, "from above", -reach, reach);
        if self.obstacle {
            for o in &self.params.obstacles {
                frame.mesh(
                    MeshId::SPHERE,
                    Mat4::from_translation(o.center) * Mat4::from_scale(Vec3::splat(o.radius)),
                    palette::GREY,
                );
            }
        }
        // Only the roles that are on.
        let roles = match (self.params.leader.is_some(), self.params.predator.is_some()) {
            (true, true) => "; leader green, predator red",
            (true, false) => "; leader green",
            (false, true) => "; predator red",
            (false, false) => "",
        };
        let search = match self.search {
            Search::Grid => {
                "neighbours from a uniform grid built on the GPU every step (count, prefix sum, \
                 scatter), the 3 × 3 × 3 cells around each boid"
            }
            Search::Naive => "neighbours by testing every pair, in tiles",
        };
        let own = if self.gpu_count == 0 {
            String::new()
        } else {
            format!(
                " in a box {} m wide (the density of 300 boids in the figure's)",
                format_number(2.0 * b.x)
            )
        };
        format!(
            "{} boids{own} stepped on the GPU by a compute shader, at t = {} s (the same rules; \
             {search}, one thread per boid){roles}; {}. Each boid is a dot (the shader writes one \
             sprite per boid), without the heading tail of the CPU flock; the orange boid, its \
             neighbour lines and its steering arrow are not drawn: they need the flock on the CPU, and it stays on the \
             GPU. The order plot reads the flock back from the GPU every {} s.",
            self.gpu_len(),
            format_number(self.steps_done as f32 * SIM_DT),
            self.speed_range(),
            GPU_SAMPLE_SEC,
        )
    }

    /// Builds the flock the page times: `n ∈ [2, PAGE_MAX_TIMED_BOIDS]` boids at the same
    /// density as the figure's flock (the box grows with `n`), so the grid's cost stays O(N).
    pub fn prepare_timing(&mut self, n: f32) -> Result<(), String> {
        let n = super::whole_number("boids to time", n, 2, PAGE_MAX_TIMED_BOIDS)?;
        let scale = (n as f32 / 300.0).cbrt().max(1.0);
        let params = BoidParams {
            bounds: self.params.bounds * scale,
            ..self.params.clone()
        };
        let mut flock = Flock::new(n, &params, 77)?;
        flock.step(&params, Search::Grid, 1.0 / 60.0); // size the grid once, outside the timing
        self.bench = Some(flock);
        Ok(())
    }

    /// Starts the step-time sweep again (the page's "measure" button).
    pub fn start_sweep(&mut self) {
        self.sweep = StepTimeSweep::new();
    }

    /// The search the sweep times next ("grid" or "naive"), with the timing flock built at its
    /// size, or `None` when the sweep is done. The page times [`FlockFigure::timing_step`] with
    /// it, then calls [`FlockFigure::record_sweep`].
    pub fn next_sweep_timing(&mut self) -> Result<Option<&'static str>, String> {
        let Some((n, search)) = self.sweep.next_timing() else {
            return Ok(None);
        };
        if self.bench.as_ref().map(Flock::len) != Some(n) {
            self.prepare_timing(n as f32)?;
        }
        Ok(Some(search))
    }

    /// Records the timing of [`FlockFigure::next_sweep_timing`]: milliseconds per step.
    pub fn record_sweep(&mut self, ms: f32) -> Result<(), String> {
        self.sweep.record(ms)
    }

    /// The sweep, for its plot samples and note.
    pub fn sweep(&mut self) -> &mut StepTimeSweep {
        &mut self.sweep
    }

    /// One step of the timing flock with `search` ("grid" or "naive"); the page times the call.
    pub fn timing_step(&mut self, search: &str) -> Result<(), String> {
        let search = parse_search(search)?;
        let flock = self.bench.as_mut().ok_or("call prepareTiming first")?;
        let scale = (flock.len() as f32 / 300.0).cbrt().max(1.0);
        let params = BoidParams {
            bounds: self.params.bounds * scale,
            ..self.params.clone()
        };
        flock.step(&params, search, 1.0 / 60.0);
        Ok(())
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's).
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// The highlighted boid: the first that is neither leader nor predator.
    pub fn highlighted(&self) -> usize {
        let (l, p) = self.flock.roles(&self.params);
        (0..self.flock.len())
            .find(|&i| Some(i) != l && Some(i) != p)
            .unwrap_or(0)
    }

    pub fn draw(&mut self, frame: &mut Frame) -> String {
        let b = self.params.bounds;
        for (a, c) in box_edges(-b, b) {
            // In eight pieces: the names' clearance samples each piece along its length.
            let edge: Vec<Vec3> = (0..=8).map(|k| a.lerp(c, k as f32 / 8.0)).collect();
            frame.wide_polyline(&edge, palette::GREY, 1.5);
        }
        // The flock from above, where its spread along the main view's depth can be read, out
        // to where a boid's overshoot past the walls can reach; the main view frames the same
        // reach (the box and every boid so far, growing in half metres), so no boid that
        // overshoots a wall leaves the canvas.
        let reach = self.inset_half(b);
        frame.keep_box_in_view(-reach, reach);
        frame.inset(InsetView::Top, "from above", -reach, reach);
        if self.obstacle {
            for o in &self.params.obstacles {
                frame.mesh(
                    MeshId::SPHERE,
                    Mat4::from_translation(o.center) * Mat4::from_scale(Vec3::splat(o.radius)),
                    palette::GREY,
                );
            }
        }
        let (leader, predator) = self.flock.roles(&self.params);
        let h = self.highlighted();
        // The highlighted boid's neighbours (within the largest radius, in view).
        self.neighbours.clear();
        let radius = self.params.search_radius();
        let mut found = std::mem::take(&mut self.neighbours);
        // One boid's neighbours by the naive loop: O(N), and valid before the first step too.
        self.flock
            .for_each_neighbour(Search::Naive, h, radius, |j| found.push(j));
        found.retain(|&j| {
            self.flock
                .sees(h, self.flock.positions[j], self.params.fov_deg)
        });
        for &j in &found {
            frame.wide_line(
                self.flock.positions[h],
                self.flock.positions[j],
                palette::ORANGE,
                1.5,
            );
        }
        let count = found.len();
        self.neighbours = found;
        // Its steering acceleration now, with the current weights (visible while paused too), at
        // STEER_ARROW_M_PER_MS2: a quarter metre per m/s² would draw the usual 0.3–0.5 m/s² as a
        // few centimetres, lost under the neighbour lines.
        let steer = self.flock.steering_of(&self.params, h);
        let ph = self.flock.positions[h];
        let shown = (STEER_ARROW_M_PER_MS2 * steer).clamp_length_max(STEER_ARROW_MAX_M);
        frame.arrow(ph, ph + shown, palette::PURPLE, 0.08);
        let f = &self.flock;
        for i in 0..f.len() {
            let (p, v) = (f.positions[i], f.velocities[i]);
            let (color, r) = if Some(i) == leader {
                (palette::GREEN, 0.09)
            } else if Some(i) == predator {
                (palette::RED, 0.11)
            } else if i == h {
                (palette::ORANGE, 0.06)
            } else {
                (palette::BLUE, 0.035)
            };
            frame.point(p, r, color);
            // The tail shows which way a boid flies: wide enough to read at 800 x 600.
            frame.wide_line(p, p - v.normalize_or_zero() * 0.12, color, TAIL_PX);
        }
        // The leader and the predator as outlined dots over the flock, then their names at the
        // first place round their dots, above first, clear of the boids' tails, the neighbour
        // lines, the steering arrow, the box and the other dot (on the last frame's view).
        let view = view_of(self.view);
        let roles = [
            (leader, "leader", palette::GREEN),
            (predator, "predator", palette::RED),
        ];
        for (role, _, color) in roles {
            if let Some(i) = role {
                frame.marker_on_top(f.positions[i], ROLE_DOT_PX, color);
            }
        }
        for (role, text, color) in roles {
            if let Some(i) = role {
                let at = f.positions[i];
                place_name(
                    frame,
                    view,
                    Label::around_dot(at, ROLE_DOT_PX, -Vec2::Y, text, color, 0, 16, 10.0),
                );
            }
        }
        format!(
            "{} boids, {} search; the orange boid sees {count} {} within {} m and steers \
             at {} m/s² (purple arrow, {STEER_ARROW_M_PER_MS2} m per m/s², drawn at most {STEER_ARROW_MAX_M} m long; the steering is \
             capped at {} m/s²); {}. Polarisation φ = {:.2} (1: all head the same way), \
             mean speed {:.2} m/s.",
            self.flock.len(),
            if self.search == Search::Grid {
                "grid"
            } else {
                "naive"
            },
            if count == 1 { "neighbour" } else { "neighbours" },
            format_number(radius),
            format_number(steer.length()),
            format_number(self.params.max_force),
            self.speed_range(),
            self.polarisation(),
            self.speed_ratio() * self.params.max_speed,
        )
    }
}

/// How the student's three rules compare with the reference at the figure's boid, naming the
/// vectors that differ (a flat list of nine numbers would leave the reader to find which rule
/// is wrong) and saying which ones match.
fn rules_note(yours: &[Vec3], reference: &[Vec3; 3]) -> String {
    const NAMES: [&str; 3] = ["cohesion", "alignment", "separation"];
    if yours.len() != 3 {
        return format!(
            "Your three_rules returned {} vectors instead of 3 (cohesion, alignment, separation).",
            yours.len()
        );
    }
    let v = |x: Vec3| {
        format!(
            "({}, {}, {})",
            format_number(x.x),
            format_number(x.y),
            format_number(x.z)
        )
    };
    let (same, differ): (Vec<usize>, Vec<usize>) = (0..3).partition(|&i| {
        let e = (yours[i] - reference[i]).abs().max_element();
        e <= TOLERANCE // false for NaN
    });
    if differ.is_empty() {
        return "Your three_rules matches the reference at this boid.".to_string();
    }
    let list = |ids: &[usize]| {
        ids.iter()
            .map(|&i| NAMES[i])
            .collect::<Vec<_>>()
            .join(" and ")
    };
    let details = differ
        .iter()
        .map(|&i| {
            format!(
                "{} yours {}, reference {}",
                NAMES[i],
                v(yours[i]),
                v(reference[i])
            )
        })
        .collect::<Vec<_>>()
        .join("; ");
    let matching = if same.is_empty() {
        String::new()
    } else {
        format!(
            " ({} {}.)",
            list(&same),
            if same.len() == 1 { "matches" } else { "match" }
        )
    };
    format!(
        "Your three_rules differs at this boid in {}: {details}.{matching}",
        list(&differ)
    )
}

/// Metres per CSS pixel on the rules figure's plane when the camera fits a grid `extent` metres
/// across, rounded up: the fit keeps 32 px clear top and bottom, so the grid is 316 px tall on
/// the 760 × 380 canvas of an 800 × 600 page and 356 px on the 650 × 420 one of a 1600 × 1000
/// page.
fn rules_m_per_px(extent: f32) -> f32 {
    extent / 310.0
}

/// A label's box on the rules figure's plane, `(x0, z0, x1, z1)` in metres: the page draws a
/// label 0.35 em (4.5 px) to the right of its anchor (or ending that far to its left), 0.8 rem
/// bold (about 7.7 px a character) and 15 px high, from 9 px above the anchor; −z is up the
/// screen. Two pixels of padding all round.
fn label_box(anchor: Vec3, text: &str, left: bool, px: f32) -> (f32, f32, f32, f32) {
    let w = 7.7 * text.chars().count() as f32 * px;
    let (x0, x1) = if left {
        (anchor.x - 4.5 * px - w, anchor.x - 4.5 * px)
    } else {
        (anchor.x + 4.5 * px, anchor.x + 4.5 * px + w)
    };
    (
        x0 - 2.0 * px,
        anchor.z - 11.0 * px,
        x1 + 2.0 * px,
        anchor.z + 8.5 * px,
    )
}

fn boxes_overlap(a: (f32, f32, f32, f32), b: (f32, f32, f32, f32)) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

/// Where the rules figure's three labels go: each just past its arrow's tip, reading away from
/// the boid (leftwards for an arrow that points left), the longest arrow's first; a label that
/// would cover one already placed, or the boid, moves up or down the screen (along z) by as
/// little as clears them. At the tips alone, short cohesion and alignment arrows put their
/// labels on top of each other. Every label stays over the grid `(lo, hi)` (which the camera
/// fits) along z, and within 0.85 of the grid's width of its middle along x (the canvases are
/// at least 1.55 times as wide as tall). Returns `(anchor, reads leftwards, text, colour)`.
fn place_labels(
    boid: Vec3,
    tips: &[(Vec3, Vec3, &'static str, Vec3)],
    (lo, hi): (Vec3, Vec3),
) -> Vec<(Vec3, bool, &'static str, Vec3)> {
    let extent = (hi - lo).max_element();
    let px = rules_m_per_px(extent);
    let order = crate::order::order_by(tips.iter().map(|t| t.1.length()), true);
    let r = 12.0 * px; // the boid's dot and a margin
    let mut placed: Vec<(f32, f32, f32, f32)> =
        vec![(boid.x - r, boid.z - r, boid.x + r, boid.z + r)];
    // The boid and the labels placed so far: what a label must never cover.
    let mut labels = placed.clone();
    // The arrows' shafts, as small boxes along each: a label must not sit on another arrow.
    let m = 3.0 * px;
    for &(tip, _, _, _) in tips {
        for k in 1..=12 {
            let p = boid.lerp(tip, k as f32 / 12.0);
            placed.push((p.x - m, p.z - m, p.x + m, p.z + m));
        }
    }
    let mut out = Vec::with_capacity(tips.len());
    for i in order {
        let (tip, v, text, color) = tips[i];
        let dir = v.normalize_or_zero();
        let left = dir.x < -0.2;
        // Kept on the canvas: an arrow from a boid near the border can run past it.
        let mut base = tip + dir * (6.0 * px);
        let w = 7.7 * text.chars().count() as f32 * px;
        let (z_lo, z_hi) = (lo.z + 0.05 * extent, hi.z - 0.05 * extent);
        let middle = 0.5 * (lo.x + hi.x);
        let (x_lo, x_hi) = (middle - 0.85 * extent, middle + 0.85 * extent);
        base.z = base.z.clamp(z_lo, z_hi);
        base.x = if left {
            base.x.max(x_lo + w)
        } else {
            base.x.min(x_hi - w)
        };
        let step = 20.0 * px;
        let mut anchor = base;
        // Clear of the labels and the arrows if there is room; else clear of the labels.
        'search: for avoid in [&placed[..], &labels[..]] {
            for k in 0..=12u32 {
                // 0, +1, −1, +2, −2 … steps down and up the screen.
                let dz = if k % 2 == 1 { 1.0 } else { -1.0 } * k.div_ceil(2) as f32 * step;
                let mut a = base + Vec3::new(0.0, 0.0, dz);
                a.z = a.z.clamp(z_lo, z_hi);
                let b = label_box(a, text, left, px);
                if !avoid.iter().any(|&p| boxes_overlap(p, b)) {
                    anchor = a;
                    break 'search;
                }
            }
        }
        placed.push(label_box(anchor, text, left, px));
        labels.push(label_box(anchor, text, left, px));
        out.push((anchor, left, text, color));
    }
    out
}

/// The 12 edges of the box `[lo, hi]`.
pub(super) fn box_edges(lo: Vec3, hi: Vec3) -> Vec<(Vec3, Vec3)> {
    let c = |i: u32| {
        Vec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        )
    };
    let mut edges = Vec::with_capacity(12);
    for i in 0..8u32 {
        for bit in [1, 2, 4] {
            if i & bit == 0 {
                edges.push((c(i), c(i | bit)));
            }
        }
    }
    edges
}

// ---------------------------------------------------------------------------------------------
// One boid and its neighbours.

/// One boid (orange) at `boid` moving along +x, and fixed neighbours, on the plane y = 0.
#[derive(Clone, Debug)]
pub struct RulesFigure {
    pub boid: Vec3,
    velocity: Vec3,
    others: Vec<(Vec3, Vec3)>,
    radius: f32,
    fov_deg: f32,
    cell_size: f32,
    use_exercise: bool,
    runner: Runner,
    /// The first panics of the student's 12.1 and 12.2, with their inputs.
    rules_panic: FirstPanic,
    cell_panic: FirstPanic,
    /// The camera and canvas size (CSS pixels) of the last frame: the rules' names are placed
    /// for it ([`RulesFigure::set_view`]).
    view: Option<(OrbitCamera, Vec2)>,
}

/// Radius of the red ring round a neighbour a grid search would miss, metres.
pub const MISSED_RING_M: f32 = 0.16;

/// Metres of arrow per unit of a steering vector in the rules figure: at the defaults the
/// cohesion (0.36) points along the heading, and drawn 1 m per unit it ends inside the heading's
/// 0.5 m arrow.
const ARROW_M_PER_UNIT: f32 = 2.0;
/// The longest arrow the rules figure draws, metres.
const ARROW_MAX_M: f32 = 2.0;
/// Width of the rules figure's heading arrow, CSS pixels: wider than a steering arrow
/// ([`crate::draw::ARROW_PX`]), which is drawn over it.
pub const HEADING_PX: f32 = 6.0;

/// The grid of the rules figure: origin and cells per axis.
const GRID_ORIGIN: Vec3 = Vec3::new(-2.0, -0.5, -2.0);
const GRID_EXTENT: f32 = 4.0;

impl Default for RulesFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl RulesFigure {
    pub fn new() -> Self {
        let others = [
            (0.6, 0.3, 0.2, 0.5),
            (0.9, -0.5, 0.6, -0.3),
            (-0.4, 0.7, 1.0, 0.4),
            (0.3, -0.25, 0.9, 0.0),
            (-0.9, -0.4, 0.8, 0.3),
            (1.6, 0.9, 0.5, 0.6),
            (-1.5, 0.2, 1.0, -0.2),
            (0.2, 1.5, 0.7, 0.1),
        ]
        .map(|(x, z, vx, vz)| (Vec3::new(x, 0.0, z), Vec3::new(vx, 0.0, vz)))
        .to_vec();
        Self {
            boid: Vec3::ZERO,
            velocity: Vec3::new(1.0, 0.0, 0.0),
            others,
            radius: 1.2,
            fov_deg: 270.0,
            cell_size: 1.0,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            rules_panic: FirstPanic::default(),
            cell_panic: FirstPanic::default(),
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's).
    pub fn set_view(&mut self, camera: OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// A new runner (a rebuilt exercise) forgets earlier panics.
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.rules_panic.clear();
        self.cell_panic.clear();
    }

    /// How the notes name the figure's own boid as an exercise's input.
    fn this_boid(&self) -> String {
        format!(
            "the figure's boid at ({}, {})",
            format_number(self.boid.x),
            format_number(self.boid.z)
        )
    }

    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// Where the orange boid is, on the plane (x, z in [−1.9, 1.9] metres).
    pub fn set_position(&mut self, x: f32, z: f32) -> Result<(), String> {
        self.boid = Vec3::new(
            in_range("x", x, -1.9, 1.9)?,
            0.0,
            in_range("z", z, -1.9, 1.9)?,
        );
        Ok(())
    }

    /// Heading of the orange boid, degrees in [−180, 180] (0: along +x).
    pub fn set_heading_deg(&mut self, deg: f32) -> Result<(), String> {
        let a = in_range("heading", deg, -180.0, 180.0)?.to_radians();
        self.velocity = Vec3::new(a.cos(), 0.0, -a.sin());
        Ok(())
    }

    pub fn set_radius(&mut self, r: f32) -> Result<(), String> {
        self.radius = in_range("radius", r, 0.1, 3.0)?;
        Ok(())
    }

    pub fn set_fov_deg(&mut self, fov: f32) -> Result<(), String> {
        self.fov_deg = in_range("field of view", fov, 0.0, 360.0)?;
        Ok(())
    }

    pub fn set_cell_size(&mut self, size: f32) -> Result<(), String> {
        self.cell_size = in_range("cell size", size, 0.25, 2.0)?;
        Ok(())
    }

    /// The camera the page starts with, as `Viewer::setCamera`'s arguments (target x, y, z,
    /// distance in metres, yaw and pitch in radians): from straight above, +x to the right and
    /// −z up the screen. The viewer then fits its target and distance to
    /// [`RulesFigure::view_box`], keeping this direction.
    pub fn view(&self) -> [f32; 6] {
        [0.0, 0.0, 0.0, 5.2, 0.0, 1.45]
    }

    fn dims(&self) -> [u32; 3] {
        let n = (GRID_EXTENT / self.cell_size).ceil() as u32;
        [n, 1, n]
    }

    /// The grid's cells on the plane y = 0, `(min, max)`: whole cells from the grid's origin,
    /// so with cells that do not divide [`GRID_EXTENT`] the last row and column reach past it.
    /// The figure declares it as its view, so the camera fits the whole grid at every cell size.
    pub fn grid_box(&self) -> (Vec3, Vec3) {
        let [n, _, _] = self.dims();
        let lo = Vec3::new(GRID_ORIGIN.x, 0.0, GRID_ORIGIN.z);
        (
            lo,
            lo + Vec3::new(1.0, 0.0, 1.0) * (n as f32 * self.cell_size),
        )
    }

    /// What the figure keeps in view, `(min, max)` on the plane y = 0: the smallest square
    /// holding the grid ([`RulesFigure::grid_box`]) and the radius circle, which at 3 m reaches
    /// past the grid. A square, as the grid is, so the labels' placement (`place_labels`) knows
    /// how much of the plane the canvas shows from the square's side alone.
    pub fn view_box(&self) -> (Vec3, Vec3) {
        let (lo, hi) = self.grid_box();
        let reach = Vec3::new(self.radius, 0.0, self.radius);
        let (lo, hi) = (lo.min(self.boid - reach), hi.max(self.boid + reach));
        let (center, half) = (0.5 * (lo + hi), 0.5 * (hi - lo).max_element());
        let half = Vec3::new(half, 0.0, half);
        (center - half, center + half)
    }

    /// The neighbours the boid takes into account: within the radius and the field of view.
    pub fn neighbours(&self) -> (Vec<Vec3>, Vec<Vec3>) {
        let half = (0.5 * self.fov_deg).to_radians().cos();
        self.others
            .iter()
            .filter(|(q, _)| {
                let d = *q - self.boid;
                let l = d.length();
                l <= self.radius
                    && (self.fov_deg >= 360.0 || l == 0.0 || d.dot(self.velocity) >= half * l)
            })
            .copied()
            .unzip()
    }

    /// The neighbours (within the radius and the field of view) whose cells lie outside the
    /// 3 × 3 block around the boid's: those a grid search with these cells would miss. None
    /// when the cells are at least as wide as the radius.
    pub fn missed_neighbours(&self) -> Vec<Vec3> {
        let dims = self.dims();
        let ik = |p: Vec3| {
            let c = cell_index(p, GRID_ORIGIN, self.cell_size, dims);
            (
                (c % dims[0] as usize) as i64,
                (c / (dims[0] * dims[1]) as usize) as i64,
            )
        };
        let (bi, bk) = ik(self.boid);
        let (ps, _) = self.neighbours();
        ps.into_iter()
            .filter(|&q| {
                let (i, k) = ik(q);
                (i - bi).abs() > 1 || (k - bk).abs() > 1
            })
            .collect()
    }

    /// The three vectors drawn: the student's (exercise 12.1) when asked and usable.
    pub fn rules(&self) -> [Vec3; 3] {
        let (ps, vs) = self.neighbours();
        self.use_exercise
            .then(|| {
                run::three_rules(
                    self.runner,
                    self.boid,
                    self.velocity,
                    ps.clone(),
                    vs.clone(),
                )
                .map_err(|f| self.rules_panic.record(&self.this_boid(), &f))
                .ok()
            })
            .flatten()
            .filter(|r| r.len() == 3 && r.iter().all(|v| v.is_finite()))
            .map(|r| [r[0], r[1], r[2]])
            .unwrap_or_else(|| three_rules(self.boid, self.velocity, &ps, &vs))
    }

    pub fn draw(&self, frame: &mut Frame) -> String {
        let dims = self.dims();
        let s = self.cell_size;
        let (view_lo, view_hi) = self.view_box();
        frame.keep_box_in_view(view_lo, view_hi);
        // Grid lines on y = 0 (the grid's cells seen from above).
        for k in 0..=dims[0] {
            let x = GRID_ORIGIN.x + k as f32 * s;
            frame.line(
                Vec3::new(x, 0.0, GRID_ORIGIN.z),
                Vec3::new(x, 0.0, GRID_ORIGIN.z + dims[2] as f32 * s),
                palette::GRID,
            );
        }
        for k in 0..=dims[2] {
            let z = GRID_ORIGIN.z + k as f32 * s;
            frame.line(
                Vec3::new(GRID_ORIGIN.x, 0.0, z),
                Vec3::new(GRID_ORIGIN.x + dims[0] as f32 * s, 0.0, z),
                palette::GRID,
            );
        }
        // The boid's cell and the 3 × 3 block searched around it.
        let c = cell_index(self.boid, GRID_ORIGIN, s, dims);
        let (ci, ck) = (
            (c % dims[0] as usize) as i32,
            (c / (dims[0] * dims[1]) as usize) as i32,
        );
        for dk in -1..=1 {
            for di in -1..=1 {
                let (i, k) = (ci + di, ck + dk);
                if i < 0 || k < 0 || i >= dims[0] as i32 || k >= dims[2] as i32 {
                    continue;
                }
                // On the plane y = 0 with the grid lines and the boids (GRID_ORIGIN.y is −0.5:
                // squares drawn from it would sit half a metre below the grid and, in
                // perspective, look up to a cell away from the boid near the edges).
                let lo = Vec3::new(
                    GRID_ORIGIN.x + i as f32 * s,
                    0.0,
                    GRID_ORIGIN.z + k as f32 * s,
                );
                // The boid's own cell wider and over everything, the teal block's edges
                // beside it included.
                let own = di == 0 && dk == 0;
                let color = if own { palette::ORANGE } else { palette::TEAL };
                let inset = 0.03 * s;
                let corners = [
                    lo + Vec3::new(inset, 0.002, inset),
                    lo + Vec3::new(s - inset, 0.002, inset),
                    lo + Vec3::new(s - inset, 0.002, s - inset),
                    lo + Vec3::new(inset, 0.002, s - inset),
                    lo + Vec3::new(inset, 0.002, inset),
                ];
                let style = crate::draw::StrokeStyle {
                    on_top: own,
                    ..crate::draw::StrokeStyle::solid(if own { 3.0 } else { 2.0 })
                };
                frame.stroke(&corners, color, style);
            }
        }
        // The radius circle, solid over the field of view and dashed over the blind sector
        // behind, so that a narrow and a wide field of view read apart; then the sector's edges.
        let heading = self.velocity.normalize();
        let half = 0.5 * self.fov_deg.to_radians();
        let arc = |from: f32, to: f32| -> Vec<Vec3> {
            (0..=64)
                .map(|k| {
                    let a = from + (to - from) * k as f32 / 64.0;
                    self.boid + self.radius * (glam::Quat::from_rotation_y(a) * heading)
                })
                .collect()
        };
        if half > 0.0 {
            frame.wide_polyline(&arc(-half, half), palette::PURPLE, 2.0);
        }
        if self.fov_deg < 360.0 {
            let blind = arc(half, std::f32::consts::TAU - half);
            let dashed = crate::draw::StrokeStyle::dashed(1.5, 0.08, 0.06);
            frame.stroke(&blind, palette::PURPLE, dashed);
            for sign in [-1.0f32, 1.0] {
                let dir = glam::Quat::from_rotation_y(sign * half) * heading;
                frame.wide_line(
                    self.boid,
                    self.boid + dir * self.radius,
                    palette::PURPLE,
                    2.0,
                );
            }
        }
        let (ps, _) = self.neighbours();
        let missed = self.missed_neighbours();
        for (q, v) in &self.others {
            let seen = ps.iter().any(|p| p == q);
            let color = if seen { palette::BLUE } else { palette::GREY };
            if missed.contains(q) {
                // A red ring round the neighbour, which shows inside it: the 3 × 3 block never
                // reaches its cell.
                let ring: Vec<Vec3> = (0..=24)
                    .map(|k| {
                        let a = k as f32 / 24.0 * std::f32::consts::TAU;
                        *q + MISSED_RING_M * Vec3::new(a.cos(), 0.0, a.sin())
                    })
                    .collect();
                frame.wide_polyline(&ring, palette::RED, 2.5);
            }
            frame.point(*q, 0.07, color);
            frame.arrow(*q, *q + 0.35 * *v, color, 0.08);
        }
        // The heading wide under the steering arrows drawn next: where one of them points the
        // same way, both colours still show.
        let heading = self.boid + 0.5 * self.velocity;
        frame.stroke(
            &[self.boid, heading],
            palette::ORANGE,
            crate::draw::StrokeStyle::solid(HEADING_PX),
        );
        frame.arrow(self.boid, heading, palette::ORANGE, 0.1);
        let [co, al, se] = self.rules();
        let arrows = [
            (co, palette::GREEN, "cohesion"),
            (al, palette::PINK, "alignment"),
            (se, palette::RED, "separation"),
        ];
        // Shorter arrows over longer ones, each a centimetre higher above the plane (the camera
        // looks down): a short rule that points along a long one still shows.
        let shown = |v: Vec3| (ARROW_M_PER_UNIT * v).clamp_length_max(ARROW_MAX_M);
        let drawn = |i: usize| shown(arrows[i].0).length();
        let by_length = crate::order::order_by((0..3).map(drawn), true);
        let mut lift = [0.0f32; 3];
        for (rank, &i) in by_length.iter().enumerate() {
            lift[i] = 0.01 * (rank + 1) as f32;
        }
        let mut tips = Vec::with_capacity(3);
        for (&(v, color, name), up) in arrows.iter().zip(lift) {
            let up = Vec3::Y * up;
            let tip = self.boid + shown(v) + up;
            frame.arrow(self.boid + up, tip, color, 0.12);
            if v.length() > 1e-4 {
                tips.push((tip, v, name, color));
            }
        }
        // The boid over the arrows that start at it and the cells' squares.
        frame.marker_on_top(self.boid, 14.0, palette::ORANGE);
        // Each name where `place_labels` puts it past its arrow's tip, else (on the last frame's
        // view) at the first place round the tip, along the arrow first, clear of the cells'
        // squares, the circle, the arrows, the dots and the names placed before.
        let view = view_of(self.view);
        for (anchor, left, name, color) in place_labels(self.boid, &tips, (view_lo, view_hi)) {
            let (tip, v, _, _) = tips.iter().find(|t| t.2 == name).expect("a tip per name");
            let mut candidates =
                Label::around_dot(*tip, 10.0, Vec2::new(v.x, v.z), name, color, 0, 12, 12.0);
            candidates.insert(
                0,
                Label {
                    anchor,
                    text: name.to_string(),
                    color,
                    left,
                    priority: 0,
                    offset_px: Vec2::ZERO,
                    large: false,
                },
            );
            place_name(frame, view, candidates);
        }
        let mut note = format!(
            "{} {} in view within {} m; the orange boid is in cell {c} (of {} × {}).",
            ps.len(),
            if ps.len() == 1 {
                "neighbour"
            } else {
                "neighbours"
            },
            format_number(self.radius),
            dims[0],
            dims[2]
        );
        if !missed.is_empty() {
            note.push_str(&format!(
                " The cells ({} m) are narrower than the radius ({} m): the 3 × 3 block around \
                 the boid's cell misses {} of its neighbours (ringed in red), which a grid search \
                 would never see. Cells at least as wide as the radius never miss one.",
                format_number(self.cell_size),
                format_number(self.radius),
                missed.len()
            ));
        }
        // The arrows are cut at ARROW_MAX_M: say which ones are longer, so that a cut arrow is
        // not read at its drawn length.
        let long: Vec<String> = arrows
            .iter()
            .filter(|(v, _, _)| ARROW_M_PER_UNIT * v.length() > ARROW_MAX_M)
            .map(|(v, _, name)| format!("{name} {}", format_number(v.length())))
            .collect();
        if !long.is_empty() {
            note.push_str(&format!(
                " Arrows are {ARROW_M_PER_UNIT} m per unit, cut at {ARROW_MAX_M} m: {} long.",
                long.join(", ")
            ));
        }
        if self.use_exercise {
            note.push(' ');
            note.push_str(&self.exercise_note());
        }
        note
    }

    /// Compares the student's three rules and cell index with the reference at this boid, then
    /// at probe inputs the figure's boid never reaches (no neighbours, neighbours off the plane,
    /// a boid past the grid's far corner or below its origin, a grid several cells thick) and
    /// names those where an answer differs: at the default position, for one, no clamp is
    /// needed.
    pub fn exercise_note(&self) -> String {
        let (ps, vs) = self.neighbours();
        let rules = match run::three_rules(
            self.runner,
            self.boid,
            self.velocity,
            ps.clone(),
            vs.clone(),
        ) {
            Err(f) => {
                self.rules_panic
                    .note("exercise 12.1 three_rules", FILE, &self.this_boid(), &f)
            }
            Ok(yours) => {
                let reference = three_rules(self.boid, self.velocity, &ps, &vs);
                let mut note = rules_note(&yours, &reference);
                note.push(' ');
                note.push_str(&self.rules_probe_note());
                note
            }
        };
        let dims = self.dims();
        let dims_f = dims.map(|d| d as f32);
        let cell =
            match run::cell_index(self.runner, self.boid, GRID_ORIGIN, self.cell_size, dims_f) {
                Err(f) => {
                    self.cell_panic
                        .note("exercise 12.2 cell_index", FILE, &self.this_boid(), &f)
                }
                // An index is a whole number: "yours 272, reference 240", not "(272.000)", and
                // the reference's (i, j, k), to see which axis went wrong.
                Ok(yours) => {
                    let reference = cell_index(self.boid, GRID_ORIGIN, self.cell_size, dims);
                    let mut note = if yours == reference {
                        "Your cell_index matches the reference at this boid.".to_string()
                    } else {
                        let (nx, ny) = (dims[0] as usize, dims[1] as usize);
                        format!(
                            "Your cell_index differs at this boid: yours {yours}, reference \
                             {reference} (cell i = {}, j = {}, k = {} of {} × {} × {}).",
                            reference % nx,
                            reference / nx % ny,
                            reference / (nx * ny),
                            dims[0],
                            dims[1],
                            dims[2]
                        )
                    };
                    note.push(' ');
                    note.push_str(&self.cell_probe_note());
                    note
                }
            };
        format!("{rules} {cell}")
    }

    /// Exercise 12.1 at inputs beyond the figure's boid.
    fn rules_probe_note(&self) -> String {
        let v = |x: f32, y: f32, z: f32| Vec3::new(x, y, z);
        let probes: [(&str, Vec3, Vec3, Vec<Vec3>, Vec<Vec3>); 3] = [
            (
                "no neighbours (three zero vectors)",
                v(1.0, 0.0, 1.0),
                Vec3::X,
                vec![],
                vec![],
            ),
            (
                "a single neighbour",
                Vec3::ZERO,
                Vec3::X,
                vec![v(2.0, 0.0, 0.0)],
                vec![Vec3::Y],
            ),
            (
                "neighbours above and below the plane",
                v(0.5, 1.0, -0.5),
                v(0.0, 1.0, 1.0),
                vec![v(1.0, 2.0, 0.0), v(0.0, 0.2, -1.0), v(0.5, 1.5, 0.5)],
                vec![v(1.0, 0.0, 0.0), v(0.0, -1.0, 0.5), v(0.3, 0.3, 0.3)],
            ),
        ];
        let mut differ = Vec::new();
        for (name, p, vel, qs, ws) in probes {
            let yours = match run::three_rules(self.runner, p, vel, qs.clone(), ws.clone()) {
                Ok(yours) => yours,
                Err(f) => {
                    let at = format!("the probe input \"{name}\"");
                    return self
                        .rules_panic
                        .note("exercise 12.1 three_rules", FILE, &at, &f);
                }
            };
            let reference = three_rules(p, vel, &qs, &ws);
            let close = yours.len() == 3
                && yours
                    .iter()
                    .zip(&reference)
                    .all(|(a, b)| (*a - *b).abs().max_element() <= TOLERANCE * (1.0 + b.length()));
            if !close {
                differ.push(name);
            }
        }
        probe_summary("three_rules", 3, &differ)
    }

    /// Exercise 12.2 at inputs beyond the figure's boid, on its own grid and on a thicker one.
    fn cell_probe_note(&self) -> String {
        let dims = self.dims();
        let s = self.cell_size;
        let probes: [(&str, Vec3, Vec3, f32, [u32; 3]); 4] = [
            (
                "a boid past the grid's far corner (the upper clamp)",
                GRID_ORIGIN + Vec3::new(5.0, 0.5, 5.0),
                GRID_ORIGIN,
                s,
                dims,
            ),
            (
                "a boid below the grid's origin (the lower clamp)",
                GRID_ORIGIN - Vec3::new(0.7, 0.0, 0.3),
                GRID_ORIGIN,
                s,
                dims,
            ),
            (
                "a grid of 4 × 3 × 5 cells (j and k count)",
                Vec3::new(1.3, 0.7, 2.2),
                Vec3::ZERO,
                0.5,
                [4, 3, 5],
            ),
            (
                "a boid on a cell's corner (floor, not round)",
                GRID_ORIGIN + Vec3::new(s, 0.5, 2.0 * s),
                GRID_ORIGIN,
                s,
                dims,
            ),
        ];
        let mut differ = Vec::new();
        for (name, p, origin, size, d) in probes {
            let yours = match run::cell_index(self.runner, p, origin, size, d.map(|x| x as f32)) {
                Ok(yours) => yours,
                Err(f) => {
                    let at = format!("the probe input \"{name}\"");
                    return self
                        .cell_panic
                        .note("exercise 12.2 cell_index", FILE, &at, &f);
                }
            };
            if yours != cell_index(p, origin, size, d) {
                differ.push(name);
            }
        }
        probe_summary("cell_index", 4, &differ)
    }
}

/// The sentence after a student's answer at the figure's input: whether it matches at the
/// `asked` probe inputs too, or at which ones it differs.
fn probe_summary(what: &str, asked: usize, differ: &[&str]) -> String {
    if differ.is_empty() {
        format!("Your {what} also matches at {asked} probe inputs the figure does not show.")
    } else {
        format!(
            "Of {asked} probe inputs the figure does not show, your {what} differs at {}: {}.",
            differ.len(),
            differ.join("; ")
        )
    }
}
