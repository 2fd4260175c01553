//! Figure logic for lesson 11, "Particles" (see [`crate::figures`]).
//!
//! - [`EmitterFigure`]: a fountain and an explosion, particles drawn as camera-facing sprites
//!   that fade with age, bouncing on the floor and on a sphere; sprites sorted back to front or
//!   not, to show why transparent sprites are sorted.
//! - [`FreeFallFigure`]: one throw, the exact parabola next to explicit Euler, semi-implicit Euler
//!   and velocity Verlet at a chosen step; the error of each over time (the plot's samples); the
//!   student's semi-implicit step (exercise 11.2).
//! - [`SpringFigure`]: a mass on a spring stepped by the same three integrators: explicit Euler
//!   gains energy every step, semi-implicit Euler and Verlet keep it bounded.
//! - [`BounceFigure`]: balls dropped on a sphere and the floor with restitution and friction; the
//!   predicted time and place of the next floor impact (exercise 11.1).
//! - [`SquashFigure`]: the same bounce without and with squash and stretch, side by side.

use super::curves::{probe_note, Probe};
use super::{
    failure_note, format_number, in_range, palette, Frame, MeshId, Runner, DEFAULT_RUNNER,
};
use crate::draw::PointInstance;
use crate::exercises::run;
use crate::particles::sprites::{sort_back_to_front, SMOKE_ATLAS};
use crate::particles::{
    floor_time_of_impact, free_fall, free_fall_errors, Emitter, FreeFallError, Integrator,
    ParticleSystem, Plane, PositionDist, Sphere, SquashBall, Surfaces, VelocityDist,
};
use crate::texture::{SpriteInstance, TextureId};
use crate::Valid;
use glam::{Mat4, Vec3, Vec4};

const FILE: &str = "src/exercises/particles.rs";
const TOLERANCE: f32 = 1e-4;
/// Fixed step of the animated figures, seconds. A figure's state at timeline time `t` is the
/// state after `⌊t / SIM_DT⌋` steps from its start, so a paused figure stands still, a scrub
/// replays, and changing a parameter replays from the start with the new value.
pub const SIM_DT: f32 = 1.0 / 60.0;
/// The latest time a figure simulates to (bounds the work of one replay), seconds.
pub const MAX_SIM_TIME: f32 = 60.0;

/// The number of fixed steps that reach `time_sec ∈ [0, MAX_SIM_TIME]`.
pub fn steps_to(time_sec: f32) -> Result<usize, String> {
    let t = in_range("time", time_sec, 0.0, MAX_SIM_TIME)?;
    Ok((t / SIM_DT + 1e-3).floor() as usize)
}

/// The most particles the emitter figure holds (software rendering in the tests draws them all).
pub const PAGE_MAX_PARTICLES: usize = 2000;
/// The emitter figure's slots for the fountain when it runs ("fountain" and "both"); the rest,
/// [`EXPLOSION_SLOTS`], are the explosions'. In "explosion" mode the explosions have them all.
/// With a share each, one emitter never starves the other: a burst cannot take the fountain's
/// slots, and a fast fountain cannot leave an explosion without any.
pub const FOUNTAIN_SLOTS: usize = 1200;
/// The explosions' share of the slots next to a fountain.
pub const EXPLOSION_SLOTS: usize = PAGE_MAX_PARTICLES - FOUNTAIN_SLOTS;
/// The most particles one explosion may ask for (the burst slider's top).
pub const MAX_BURST: usize = EXPLOSION_SLOTS;

// ---------------------------------------------------------------------------------------------
// Emitters and sprites.

/// `n` with a comma every three digits, as the page's text writes numbers (100,000).
fn with_commas(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// What the emitter figure's dropdown offers.
pub const EMITTER_MODES: [&str; 3] = ["fountain", "explosion", "both"];

/// A fountain and an explosion over a floor and a sphere.
#[derive(Clone, Debug)]
pub struct EmitterFigure {
    system: ParticleSystem,
    emitters: [Emitter; 2],
    surfaces: Surfaces,
    mode: usize,
    sort: bool,
    fade: bool,
    /// Particles one explosion asks for (its own slider, not tied to the fountain's rate: twice
    /// that rate, at 1000/s, would take all 2000 slots in one burst).
    burst_size: usize,
    /// The lifetime slider's value, seconds (the emitters get at most
    /// [`EmitterFigure::lifetime_sec`]).
    lifetime_slider_sec: f32,
    /// The reader's presses of "explode" (replayed with the rest): the step each spawns at, the
    /// timeline's time it was pressed at (s), and whether it has been spawned in the current run
    /// (a press spawns at once; the step it was pressed before must not spawn it a second time,
    /// while a replay must). Two moments of the timeline within one step (its scrub moves
    /// 6 ms a notch, a step is 1/60 s) are two presses, spawned at the same step.
    bursts: Vec<(usize, f32, bool)>,
    /// The timeline's time of the latest press that set off nothing (one at a moment already
    /// set one off, or one past [`MAX_BURSTS`]): the note says why while the timeline stays there.
    ignored_press: Option<f32>,
    /// The timeline's time of the last advance (s): where a press of "explode" belongs.
    time_sec: f32,
    /// The explosions of this run still holding slots: (step, particles spawned).
    spent: Vec<(usize, usize)>,
    /// The latest explosion: (particles spawned, particles asked for).
    last_burst: Option<(usize, usize)>,
    steps_done: usize,
    dirty: bool,
    order: Vec<(f32, u32)>,
    /// The smoke atlas's texture: when set, particles are textured sprites playing it over
    /// their life; otherwise shaded discs.
    sprite_texture: Option<TextureId>,
    /// The live-particle plot's samples since the run started, flat `[t (s), fountain's,
    /// explosions']`, one per step; empty in GPU mode (the particles stay on the GPU).
    history: Vec<f32>,
}

/// The most samples the live-particle plot keeps: one per step up to [`MAX_SIM_TIME`].
pub const MAX_COUNT_SAMPLES: usize = (MAX_SIM_TIME / SIM_DT) as usize + 1;

/// A sprite's half side over its particle's radius. The atlas's young puff is dense out to about
/// a third of its frame's half side (`smoke_opacity`: radius 0.5 at birth, its edge fading from
/// 0.35 of that), so a square 2.6 times the disc shows a puff about the disc's size, growing as
/// it ages (at 1.8 the puffs are specks).
pub const SPRITE_SCALE: f32 = 2.6;

/// A fountain particle this high (metres) is above the top of the emitter figure's view at
/// the page's camera on either canvas: the note says when the fountain rises past it.
pub const FOUNTAIN_VIEW_TOP_M: f32 = 4.0;

/// Steps between two automatic explosions (2.5 s).
const BURST_EVERY: usize = 150;
/// The most "explode now" presses a figure remembers.
const MAX_BURSTS: usize = 16;

impl Default for EmitterFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl EmitterFigure {
    pub fn new() -> Self {
        let surfaces = Surfaces {
            spheres: vec![Sphere {
                center: Vec3::new(0.9, 0.5, 0.0),
                radius: 0.5,
            }],
            ..Default::default()
        };
        let mut fountain = Emitter::fountain(Vec3::new(-0.6, 0.05, 0.0));
        fountain.velocity = VelocityDist::Cone {
            axis: Vec3::new(0.25, 1.0, 0.0).normalize(),
            half_angle_rad: 0.2,
            speed_min: 5.0,
            speed_max: 5.8,
        };
        Self {
            system: ParticleSystem::new(PAGE_MAX_PARTICLES, 11).valid("under the cap"),
            emitters: [fountain, Emitter::explosion(Vec3::new(-0.3, 2.2, 0.0))],
            surfaces,
            mode: 0,
            sort: true,
            fade: true,
            burst_size: 400,
            lifetime_slider_sec: 2.5,
            bursts: Vec::with_capacity(MAX_BURSTS),
            ignored_press: None,
            time_sec: 0.0,
            spent: Vec::with_capacity(MAX_BURSTS + 8),
            last_burst: None,
            steps_done: 0,
            dirty: false,
            order: Vec::with_capacity(PAGE_MAX_PARTICLES),
            sprite_texture: None,
            history: Vec::with_capacity(3 * MAX_COUNT_SAMPLES),
        }
        .with_budget()
    }

    fn with_budget(mut self) -> Self {
        self.apply_budget();
        self.record();
        self
    }

    pub fn len(&self) -> usize {
        self.system.len()
    }

    pub fn is_empty(&self) -> bool {
        self.system.is_empty()
    }

    /// Marks the run for a replay from the start when a setter changed something. The page
    /// re-applies every control after any of them moves, the "explode now" button included:
    /// a value set again unchanged must not replay, or every press of the button would replay
    /// the run.
    fn changed(&mut self, changed: bool) {
        self.dirty |= changed;
    }

    /// "fountain", "explosion" or "both".
    pub fn set_mode(&mut self, name: &str) -> Result<(), String> {
        let mode = EMITTER_MODES
            .iter()
            .position(|&m| m == name)
            .ok_or_else(|| format!("emitter: no mode named {name:?}"))?;
        self.changed(mode != self.mode);
        self.mode = mode;
        self.apply_budget();
        Ok(())
    }

    /// The fountain's rate, particles per second, in [0, 1000].
    pub fn set_rate(&mut self, rate: f32) -> Result<(), String> {
        let rate = in_range("rate", rate, 0.0, 1000.0)?;
        self.changed(rate != self.emitters[0].rate_per_sec);
        self.emitters[0].rate_per_sec = rate;
        self.apply_budget();
        Ok(())
    }

    /// Particles one explosion asks for, in [0, [`MAX_BURST`]] (rounded to a whole number).
    pub fn set_burst(&mut self, count: f32) -> Result<(), String> {
        let n = super::whole_number("particles per explosion", count, 0, MAX_BURST)?;
        self.changed(n != self.burst_size);
        self.burst_size = n;
        Ok(())
    }

    /// Lifetime of new particles, seconds, in [0.1, 10] (a ±20 % spread around it); the
    /// emitters get at most [`EmitterFigure::lifetime_sec`].
    pub fn set_lifetime(&mut self, lifetime_sec: f32) -> Result<(), String> {
        let l = in_range("lifetime", lifetime_sec, 0.1, 10.0)?;
        self.changed(l != self.lifetime_slider_sec);
        self.lifetime_slider_sec = l;
        self.apply_budget();
        Ok(())
    }

    /// The fountain's and the explosions' shares of the [`PAGE_MAX_PARTICLES`] slots.
    pub fn slots(&self) -> (usize, usize) {
        if self.mode == 1 {
            (0, PAGE_MAX_PARTICLES)
        } else {
            (FOUNTAIN_SLOTS, EXPLOSION_SLOTS)
        }
    }

    /// The mean lifetime the particles get, seconds: the slider's, or less when the fountain
    /// would need more than its slots. A steady stream at `rate` particles per second, each
    /// living up to `1.2 l`, holds about `rate · 1.2 l` particles at once (and one step's more
    /// while the oldest die), so with `F` slots
    /// ```text
    /// l ≤ ((F − 2) / rate − Δt) / 1.2
    /// ```
    /// The fountain then flows at its full rate and its particles die younger (what "recycle the
    /// oldest" does in engines), instead of filling every slot and stopping until some die. The
    /// explosions get the same lifetime, so the GPU's ring of slots never reaches a live one.
    pub fn lifetime_sec(&self) -> f32 {
        let l = self.lifetime_slider_sec;
        let rate = self.emitters[0].rate_per_sec;
        let (fountain, _) = self.slots();
        if fountain == 0 || rate <= 0.0 {
            return l;
        }
        let most = ((fountain as f32 - 2.0) / rate - SIM_DT) / 1.2;
        l.min(most)
    }

    fn apply_budget(&mut self) {
        let l = self.lifetime_sec();
        for e in &mut self.emitters {
            e.lifetime_sec = (0.8 * l, 1.2 * l);
        }
    }

    /// Steps an explosion's particles may still be alive: they live less than `1.2 l`.
    fn burst_window_steps(&self) -> usize {
        (1.2 * self.lifetime_sec() / SIM_DT).ceil() as usize + 1
    }

    /// How many particles an explosion set off at step `k` gets: what it asks for, or what is
    /// left of the explosions' slots by the explosions of the last `1.2 l` seconds (counted by
    /// what they spawned, not by which sparks died, so the CPU and the GPU, whose sparks stay on
    /// the GPU, count the same). Records it.
    fn next_burst(&mut self, k: usize) -> usize {
        let window = self.burst_window_steps();
        self.spent.retain(|&(at, _)| k < at + window);
        let (_, share) = self.slots();
        let used: usize = self.spent.iter().map(|&(_, n)| n).sum();
        let n = self.burst_size.min(share.saturating_sub(used));
        self.spent.push((k, n));
        self.last_burst = Some((n, self.burst_size));
        n
    }

    /// The explosions due at the start of step `k` (the presses not spawned yet in this run,
    /// together, then the automatic one), each with its particle count.
    fn bursts_at(&mut self, k: usize) -> [usize; 2] {
        let mut out = [self.pending_presses(k).unwrap_or(0), 0];
        if self.mode >= 1 && k.is_multiple_of(BURST_EVERY) {
            out[1] = self.next_burst(k);
        }
        out
    }

    /// Half-angle of the fountain's cone, degrees in [0, 90].
    pub fn set_spread_deg(&mut self, spread_deg: f32) -> Result<(), String> {
        let s = in_range("spread", spread_deg, 0.0, 90.0)?.to_radians();
        let mut changed = false;
        if let VelocityDist::Cone { half_angle_rad, .. } = &mut self.emitters[0].velocity {
            changed = *half_angle_rad != s;
            *half_angle_rad = s;
        }
        self.changed(changed);
        Ok(())
    }

    /// Restitution in [0, 1].
    pub fn set_restitution(&mut self, e: f32) -> Result<(), String> {
        let e = in_range("restitution", e, 0.0, 1.0)?;
        self.changed(e != self.surfaces.restitution);
        self.surfaces.restitution = e;
        Ok(())
    }

    /// Gravity's magnitude, m/s², in [0, 30].
    pub fn set_gravity(&mut self, g: f32) -> Result<(), String> {
        let g = Vec3::new(0.0, -in_range("gravity", g, 0.0, 30.0)?, 0.0);
        self.changed(g != self.surfaces.gravity);
        self.surfaces.gravity = g;
        Ok(())
    }

    /// Draw sprites back to front (correct blending) or in storage order.
    pub fn set_sort(&mut self, on: bool) {
        self.sort = on;
    }

    /// Fade sprites out with age (alpha) or keep them opaque. A change replays the run, since
    /// in GPU mode the compute shader colours the sprites as it steps.
    pub fn set_fade(&mut self, on: bool) {
        self.dirty |= self.fade != on;
        self.fade = on;
    }

    /// Draws the particles as sprites playing the smoke atlas held by `texture`
    /// ([`crate::particles::sprites::fill_smoke_atlas`]), or as shaded discs (None).
    pub fn set_sprite_texture(&mut self, texture: Option<TextureId>) {
        self.sprite_texture = texture;
    }

    /// Sets off the explosion now (and at this moment in every replay).
    pub fn explode(&mut self) {
        if let Some(n) = self.press() {
            self.system.burst(&self.emitters, 1, n);
            if self.history.len() >= 3 {
                self.history.truncate(self.history.len() - 3);
            }
            self.record();
        }
    }

    /// Records a press of "explode now" at the timeline's time (spawning at the current step)
    /// and returns its particle count, or `None` (remembered for the note) when that moment has
    /// one already or the list is full.
    fn press(&mut self) -> Option<usize> {
        let (k, t) = (self.steps_done, self.time_sec);
        if self.bursts.len() < MAX_BURSTS && !self.bursts.iter().any(|b| b.1 == t) {
            self.bursts.push((k, t, true));
            self.ignored_press = None;
            Some(self.next_burst(k))
        } else {
            self.ignored_press = Some(t);
            None
        }
    }

    /// The highest a fountain particle can rise before it dies, metres above the floor: the
    /// steepest direction of its cone at its top speed, for up to 1.2 × the lifetime `l`.
    /// ```text
    /// h = y₀ + v_y t − g t²/2,   t = min(v_y / g, 1.2 l)
    /// ```
    pub fn fountain_top_m(&self) -> f32 {
        let e = &self.emitters[0];
        let (
            PositionDist::Ball(o, r),
            VelocityDist::Cone {
                axis,
                half_angle_rad,
                speed_max,
                ..
            },
        ) = (e.position, e.velocity)
        else {
            return 0.0;
        };
        let vy = speed_max * (axis.y.acos() - half_angle_rad).max(0.0).cos();
        let g = -self.surfaces.gravity.y;
        let life = 1.2 * self.lifetime_sec();
        let t = if g > 0.0 { (vy / g).min(life) } else { life };
        o.y + r + vy * t - 0.5 * g * t * t
    }

    /// The notes' last sentences: a fountain that rises out of the view, how many presses, and
    /// why the latest did nothing, if it did.
    fn presses_note(&self) -> String {
        let top = self.fountain_top_m();
        let mut note = if self.mode != 1 && top > FOUNTAIN_VIEW_TOP_M {
            format!(
                " At g = {} m/s² the fountain's highest particles rise up to {} m before they \
                 die, out of the top of the view.",
                format_number(-self.surfaces.gravity.y),
                format_number(top),
            )
        } else {
            String::new()
        };
        if !self.bursts.is_empty() {
            note.push_str(&format!(
                " Explosions set off by hand: {}.",
                self.bursts.len()
            ));
        }
        if self.ignored_press == Some(self.time_sec) {
            note.push_str(&if self.bursts.len() >= MAX_BURSTS {
                format!(
                    " The last press did nothing: the figure remembers at most {MAX_BURSTS} \
                     presses."
                )
            } else {
                " The last press did nothing: an explosion was set off at this moment already; \
                 move the timeline a little, then press again."
                    .to_string()
            });
        }
        note
    }

    fn reset(&mut self) {
        self.system.reset(11);
        for e in &mut self.emitters {
            e.carry = 0.0;
        }
        for b in &mut self.bursts {
            b.2 = false;
        }
        self.spent.clear();
        self.last_burst = None;
        self.steps_done = 0;
        self.dirty = false;
        self.history.clear();
        self.record();
    }

    /// Live particles now: (the fountain's, the explosions').
    pub fn counts(&self) -> (usize, usize) {
        let sys = &self.system;
        let fountain = sys.emitter_of[..sys.len()]
            .iter()
            .filter(|&&e| e == 0)
            .count();
        (fountain, sys.len() - fountain)
    }

    fn record(&mut self) {
        if self.history.len() < 3 * MAX_COUNT_SAMPLES {
            let (f, e) = self.counts();
            self.history
                .extend([self.steps_done as f32 * SIM_DT, f as f32, e as f32]);
        }
    }

    /// The live-particle plot's samples, flat `[t (s), the fountain's particles, the
    /// explosions', rate × lifetime, the fountain's slots]` after each step since the run
    /// started (a scrub back, a changed setting or the timeline's loop starts it again); the
    /// last two are constant guides ([`EmitterFigure::steady_count`], [`EmitterFigure::slots`]).
    /// In GPU mode the counts after step 0 are NaN: the particles are not read back.
    pub fn count_samples(&self) -> Vec<f32> {
        let steady = if self.mode == 1 {
            0.0
        } else {
            self.steady_count()
        };
        let slots = self.slots().0 as f32;
        self.history
            .chunks_exact(3)
            .flat_map(|c| [c[0], c[1], c[2], steady, slots])
            .collect()
    }

    /// The fountain's steady count: a stream of `rate` particles per second, each living
    /// `l` seconds on average, holds `rate · l` particles once the first have died.
    pub fn steady_count(&self) -> f32 {
        self.emitters[0].rate_per_sec * self.lifetime_sec()
    }

    fn step(&mut self) {
        let k = self.steps_done;
        for n in self.bursts_at(k) {
            if n > 0 {
                self.system.burst(&self.emitters, 1, n);
            }
        }
        let rate = self.emitters[0].rate_per_sec;
        if self.mode == 1 {
            self.emitters[0].rate_per_sec = 0.0;
        }
        self.system.step(&mut self.emitters, &self.surfaces, SIM_DT);
        self.emitters[0].rate_per_sec = rate;
        self.steps_done += 1;
        self.record();
    }

    /// Brings the simulation to `time_sec` (replaying from the start when the time went back or a
    /// parameter changed). Returns the steps taken.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, String> {
        let target = steps_to(time_sec)?;
        if self.dirty || target < self.steps_done {
            self.reset();
        }
        self.time_sec = time_sec;
        let n = target - self.steps_done;
        for _ in 0..n {
            self.step();
        }
        if let Some(count) = self.pending_presses(target) {
            self.system.burst(&self.emitters, 1, count);
            // The press's sparks count at this step.
            if self.history.len() >= 3 {
                self.history.truncate(self.history.len() - 3);
            }
            self.record();
        }
        Ok(n)
    }

    /// The presses at step `k` not spawned yet in this run: marks them spawned and returns
    /// their particles (each press an explosion of its own, [`EmitterFigure::next_burst`]), or
    /// `None` when there are none. A press at the step a run stops at belongs to it already
    /// (explode spawns at once): a replay that ends there spawns it too, or a paused figure would
    /// hide it until played.
    fn pending_presses(&mut self, k: usize) -> Option<usize> {
        let mut total = None;
        for i in 0..self.bursts.len() {
            if self.bursts[i].0 == k && !self.bursts[i].2 {
                self.bursts[i].2 = true;
                *total.get_or_insert(0) += self.next_burst(k);
            }
        }
        total
    }

    /// GPU mode's [`EmitterFigure::explode`]: records the explosion the same way and hands it to
    /// `burst` (emitters, surfaces, particles) at once, so it shows even while paused.
    pub fn explode_gpu(
        &mut self,
        burst: impl FnOnce(&mut [Emitter], &Surfaces, usize) -> Result<(), String>,
    ) -> Result<(), String> {
        if let Some(n) = self.press() {
            let (fade, surfaces) = (self.fade, &self.surfaces);
            gpu_colours(&mut self.emitters, fade, |e| burst(e, surfaces, n))?;
        }
        Ok(())
    }

    /// Replays from the start at the next advance (the page switched between CPU and GPU).
    pub fn restart(&mut self) {
        self.dirty = true;
    }

    /// GPU mode ([`crate::figures::gpu`]): brings the clock to `time_sec` as
    /// [`EmitterFigure::advance_to`] does, but hands each step to `step` (emitters, surfaces,
    /// particles the explosion bursts this step, seconds to step: [`SIM_DT`]) instead of stepping
    /// the CPU system. A press at the step the run stops at is handed over last, as a step of 0 s
    /// (it spawns and moves nothing), as the CPU run spawns it. Returns `(restart, steps)`; on
    /// `restart` (time went back, a parameter changed) `step` was not called yet: the caller
    /// clears its GPU system first, then calls again.
    pub fn advance_gpu(
        &mut self,
        time_sec: f32,
        restarted: bool,
        mut step: impl FnMut(&mut [Emitter], &Surfaces, usize, f32) -> Result<(), String>,
    ) -> Result<(bool, usize), String> {
        let target = steps_to(time_sec)?;
        if !restarted && (self.dirty || target < self.steps_done) {
            self.reset();
            return Ok((true, 0));
        }
        self.time_sec = time_sec;
        let n = target - self.steps_done;
        for _ in 0..n {
            let k = self.steps_done;
            let burst = self.bursts_at(k).iter().sum();
            let rate = self.emitters[0].rate_per_sec;
            if self.mode == 1 {
                self.emitters[0].rate_per_sec = 0.0;
            }
            let (fade, surfaces) = (self.fade, &self.surfaces);
            let result = gpu_colours(&mut self.emitters, fade, |e| {
                step(e, surfaces, burst, SIM_DT)
            });
            self.emitters[0].rate_per_sec = rate;
            result?;
            self.steps_done += 1;
            // The GPU's particles never come back, so their counts are unknown (NaN, a gap in
            // the plot); the times keep the plot's guides drawn over the run.
            if self.history.len() < 3 * MAX_COUNT_SAMPLES {
                self.history
                    .extend([self.steps_done as f32 * SIM_DT, f32::NAN, f32::NAN]);
            }
        }
        if let Some(count) = self.pending_presses(target) {
            let (fade, surfaces) = (self.fade, &self.surfaces);
            gpu_colours(&mut self.emitters, fade, |e| step(e, surfaces, count, 0.0))?;
        }
        Ok((false, n))
    }

    /// GPU mode: the floor grid and the spheres, and the atlas for the compute shader's sprites
    /// (the particles are written on the GPU); returns the note.
    pub fn draw_gpu(&mut self, frame: &mut Frame) -> String {
        frame.grid(8, 0.5);
        frame.sprite_texture = self.sprite_texture;
        for s in &self.surfaces.spheres {
            let model =
                Mat4::from_translation(s.center) * Mat4::from_scale(Vec3::splat(s.radius * 0.98));
            frame.mesh(MeshId::SPHERE, model, palette::GREY);
        }
        format!(
            "Stepped on the GPU by compute shaders, at t = {} s: {} slots refilled \
             in ring order, one thread per particle (the same emitters, exact bounces and colours). \
             The sprites stay on the GPU, so they are drawn in storage order (not sorted); they \
             play the same atlas and {}. {}{}",
            format_number(self.steps_done as f32 * SIM_DT),
            with_commas(PAGE_MAX_PARTICLES),
            if self.fade {
                "fade with age"
            } else {
                "stay opaque (fade off)"
            },
            self.budget_note(),
            self.presses_note(),
        )
    }

    /// Simulates to `time_sec` and fills `frame`; `eye` is the camera position and `target` the
    /// point it looks at (for sorting). Returns the note.
    pub fn draw(
        &mut self,
        frame: &mut Frame,
        eye: Vec3,
        target: Vec3,
        time_sec: f32,
    ) -> Result<String, String> {
        self.advance_to(time_sec)?;
        frame.grid(8, 0.5);
        for s in &self.surfaces.spheres {
            let model =
                Mat4::from_translation(s.center) * Mat4::from_scale(Vec3::splat(s.radius * 0.98));
            frame.mesh(MeshId::SPHERE, model, palette::GREY);
        }
        let sys = &self.system;
        let n = sys.len();
        if self.sort {
            // Deepest first: each sprite blends over what is already behind it.
            let forward = (target - eye).normalize_or_zero();
            sort_back_to_front(&mut self.order, &sys.positions[..n], eye, forward);
        } else {
            self.order.clear();
            self.order.extend((0..n as u32).map(|i| (0.0, i)));
        }
        frame.sprite_texture = self.sprite_texture;
        for &(_, i) in &self.order {
            let i = i as usize;
            let mut color = sys.colors[i];
            if !self.fade {
                color.w = 1.0;
            }
            if self.sprite_texture.is_some() {
                let life = sys.ages[i] / sys.lifetimes[i].max(1e-6);
                // The atlas's frames thin out with age on their own: the colour's alpha, which
                // falls from 1 to 0 over the life, applied as well would make every puff past
                // mid-life nearly invisible. Its square root falls later (0.71 at mid-life, 0.5
                // at three quarters) and still reaches 0 at death.
                color.w = color.w.max(0.0).sqrt();
                frame.sprites.push(SpriteInstance {
                    center: sys.positions[i].to_array(),
                    half_size: SPRITE_SCALE * sys.sizes[i],
                    uv: SMOKE_ATLAS.frame_at(life).to_array(),
                    color: color.to_array(),
                });
            } else {
                frame.points.push(PointInstance {
                    center: sys.positions[i].to_array(),
                    radius: sys.sizes[i],
                    color: color.to_array(),
                });
            }
        }
        let e = self.surfaces.restitution;
        Ok(format!(
            "{n} particles alive; sprites {}. {} With e = {}, a particle that hits the floor at \
             5 m/s leaves it at {} m/s.{}",
            if self.sort {
                "sorted back to front"
            } else {
                "in storage order (unsorted)"
            },
            self.budget_note(),
            format_number(e),
            format_number(5.0 * e),
            self.presses_note(),
        ))
    }

    /// What the slots allow: each emitter's share, a lifetime shortened to fit the fountain's,
    /// and an explosion that got fewer particles than it asked for.
    pub fn budget_note(&self) -> String {
        let (fountain, explosions) = self.slots();
        let (all, core) = (
            with_commas(PAGE_MAX_PARTICLES),
            with_commas(crate::particles::MAX_PARTICLES),
        );
        let mut note = if fountain == 0 {
            format!("The explosions have all {all} slots here (the core allows {core}).")
        } else {
            format!(
                "Of the {all} slots here (the core allows {core}), {} are the fountain's and {} \
                 the explosions'.",
                with_commas(fountain),
                with_commas(explosions),
            )
        };
        let (l, asked) = (self.lifetime_sec(), self.lifetime_slider_sec);
        if l < asked {
            let rate = self.emitters[0].rate_per_sec;
            note.push_str(&format!(
                " A stream of {} particles/s living {asked:.2} s would need about {} slots. The \
                 fountain's {} hold {:.2} s of it (less a step and two spare slots), and a \
                 particle lives up to 1.2 × the set lifetime, so its particles live {l:.2} s \
                 (± 20 %): the fountain keeps flowing, its arcs end sooner, and rate × \
                 lifetime (the plot's dashed guide) is {}.",
                with_commas(rate.round() as usize),
                with_commas((rate * asked).round() as usize),
                with_commas(fountain),
                1.2 * l,
                with_commas(self.steady_count().round() as usize),
            ));
        }
        if let Some((got, asked)) = self.last_burst {
            if got < asked {
                note.push_str(&format!(
                    " The last explosion got {got} of its {asked} particles: the sparks of \
                     the ones before still hold the explosions' slots."
                ));
            }
        }
        note
    }

    /// The particles (their emitter, age, position…), for tests.
    pub fn system(&self) -> &ParticleSystem {
        &self.system
    }

    /// Linear RGBA of the live particles, for tests.
    pub fn colors(&self) -> &[Vec4] {
        &self.system.colors[..self.system.len()]
    }
}

// ---------------------------------------------------------------------------------------------
// Free fall: exact vs integrated.

/// Colours of the integrators, in [`Integrator::ALL`] order, and of the exact solution.
pub const INTEGRATOR_COLORS: [Vec3; 3] = [palette::RED, palette::BLUE, palette::GREEN];
pub const EXACT_COLOR: Vec3 = palette::DARK;

/// One throw integrated three ways, against the exact parabola.
#[derive(Clone, Debug)]
pub struct FreeFallFigure {
    pub p0: Vec3,
    pub v0: Vec3,
    pub g: Vec3,
    dt_sec: f32,
    use_exercise: bool,
    runner: Runner,
    /// Each integrator's positions after 0, 1, 2, … steps.
    paths: [Vec<Vec3>; 3],
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the integrators'
    /// names take the sides of their dots that keep them apart and off the paths.
    view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
}

/// How long the throw is shown, seconds.
pub const FREE_FALL_DURATION: f32 = 1.3;
/// Radius of the exact ball, metres: larger than [`STEP_BALL_M`], so the integrators' balls,
/// drawn over it, leave a dark ring where they sit on the exact position.
pub const EXACT_BALL_M: f32 = 0.11;
/// Radius of each integrator's ball at its latest step, metres.
pub const STEP_BALL_M: f32 = 0.06;
/// Each integrator's dot at its latest step, CSS pixels across, outline included: drawn over
/// its ball so that it reads at any zoom.
pub const STEP_DOT_PX: f32 = 14.0;
/// Each integrator's dots at its earlier steps, CSS pixels across.
pub const PAST_DOT_PX: f32 = 11.0;

impl Default for FreeFallFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl FreeFallFigure {
    pub fn new() -> Self {
        let mut f = Self {
            p0: Vec3::new(-2.0, 0.5, 0.0),
            v0: Vec3::new(3.0, 6.0, 0.0),
            g: Vec3::new(0.0, -9.81, 0.0),
            dt_sec: 0.1,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            paths: Default::default(),
            view: None,
        };
        f.integrate();
        f
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the integrators' names are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.integrate();
    }

    /// Runs the student's exercise 11.2 for the semi-implicit Euler path.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.integrate();
    }

    /// Step size, seconds, in [0.005, 0.3].
    pub fn set_dt(&mut self, dt_sec: f32) -> Result<(), String> {
        self.dt_sec = in_range("step size dt", dt_sec, 0.005, 0.3)?;
        self.integrate();
        Ok(())
    }

    pub fn dt(&self) -> f32 {
        self.dt_sec
    }

    /// The whole steps inside the timeline: the plot's last sample is what the figure shows at
    /// its end (a step past [`FREE_FALL_DURATION`] would be plotted but never drawn).
    fn steps(&self) -> usize {
        (FREE_FALL_DURATION / self.dt_sec + 1e-3).floor() as usize
    }

    fn integrate(&mut self) {
        let steps = self.steps();
        for (k, integrator) in Integrator::ALL.iter().enumerate() {
            let path = &mut self.paths[k];
            path.clear();
            let (mut p, mut v) = (self.p0, self.v0);
            path.push(p);
            for _ in 0..steps {
                let student = (self.use_exercise && *integrator == Integrator::SemiImplicitEuler)
                    .then(|| {
                        run::semi_implicit_euler_step(self.runner, p, v, self.g, self.dt_sec).ok()
                    })
                    .flatten()
                    .filter(|(p, v)| p.is_finite() && v.is_finite());
                match student {
                    Some((q, w)) => (p, v) = (q, w),
                    None => integrator.step(&mut p, &mut v, self.dt_sec, |_| self.g),
                }
                path.push(p);
            }
        }
    }

    /// Plot samples, flat: `[t, y error explicit Euler, y error semi-implicit, y error Verlet]`
    /// after each step, from the paths the figure draws: the signed height error `y − y_exact`
    /// in metres (positive: above the parabola). Gravity is vertical, so x is exact for every
    /// integrator and the height error is the whole position error; its sign is what tells the
    /// two Euler steps apart (explicit Euler is above by ½ g t Δt, semi-implicit below by as
    /// much), which a plot of distances would draw as one line over the other.
    pub fn error_samples(&self) -> Vec<f32> {
        let mut out = Vec::with_capacity(4 * (self.steps() + 1));
        for k in 0..=self.steps() {
            let t = k as f32 * self.dt_sec;
            out.push(t);
            out.extend(self.height_errors(k));
        }
        out
    }

    /// Each integrator's signed height error `y − y_exact` (metres) after `k` steps.
    fn height_errors(&self, k: usize) -> [f32; 3] {
        let (exact, _) = free_fall(self.p0, self.v0, self.g, k as f32 * self.dt_sec);
        [0, 1, 2].map(|i| self.paths[i][k].y - exact.y)
    }

    /// The errors at the end of the throw computed by [`free_fall_errors`] (for tests).
    pub fn final_errors(&self) -> FreeFallError {
        let mut out = vec![
            FreeFallError {
                time_sec: 0.0,
                error_m: [0.0; 3]
            };
            self.steps()
        ];
        free_fall_errors(self.p0, self.v0, self.g, self.dt_sec, &mut out);
        out[out.len() - 1]
    }

    /// Draws the throw at `time_sec` and returns the note.
    pub fn draw(&self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let t = in_range("time", time_sec, 0.0, 1e6)?.min(FREE_FALL_DURATION);
        frame.grid(8, 0.5);
        let exact: Vec<Vec3> = (0..=60)
            .map(|k| {
                free_fall(
                    self.p0,
                    self.v0,
                    self.g,
                    FREE_FALL_DURATION * k as f32 / 60.0,
                )
                .0
            })
            .collect();
        frame.wide_polyline(&exact, EXACT_COLOR, crate::draw::CURVE_PX);
        // The integrators exist only after whole steps: the exact ball is shown at the same
        // instant as their big dots (the latest step), so the gaps drawn are their errors and
        // not the time since that step (Verlet's dot sits on it).
        let k_now = ((t / self.dt_sec + 1e-4).floor() as usize).min(self.steps());
        let t_now = k_now as f32 * self.dt_sec;
        // The exact ball is larger than the integrators' balls, which are drawn over it: where
        // one sits on the exact position (Verlet always does) it shows as a dark ring around it.
        frame.point(
            free_fall(self.p0, self.v0, self.g, t_now).0,
            EXACT_BALL_M,
            EXACT_COLOR,
        );
        for (path, &color) in self.paths.iter().zip(&INTEGRATOR_COLORS) {
            frame.wide_polyline(&path[..=k_now], color, crate::draw::CURVE_PX);
            // One outlined dot per step before the latest (the big dot), the same size at any zoom.
            for p in &path[..k_now] {
                frame.marker(*p, PAST_DOT_PX, color);
            }
            frame.point_on_top(path[k_now], STEP_BALL_M, color);
            frame.marker_on_top(path[k_now], STEP_DOT_PX, color);
        }
        self.name_integrators(frame, k_now);
        // The whole throw stays in view at every step size: the camera fits the paths' box
        // (fixed for a given Δt, so it does not move while the throw plays).
        let (lo, hi) = self.paths.iter().flatten().chain(&exact).fold(
            (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        let pad = Vec3::new(EXACT_BALL_M, EXACT_BALL_M, 0.3);
        frame.keep_box_in_view(Vec3::new(lo.x, lo.y.min(0.0), lo.z) - pad, hi + pad);
        let [e0, e1, e2] = self.height_errors(k_now).map(|e| {
            // Below 10 µm is float rounding (Verlet is exact here): say so instead of a sign.
            if e.abs() < 1e-5 {
                "on the parabola (rounding only)".to_string()
            } else {
                let side = if e > 0.0 { "above" } else { "below" };
                format!("{} m {side}", format_number(e.abs()))
            }
        });
        let mut note = format!(
            "After {k_now} {} of dt = {} s (t = {} s): explicit Euler is {e0}, semi-implicit \
             Euler {e1}, velocity Verlet {e2}.",
            if k_now == 1 { "step" } else { "steps" },
            format_number(self.dt_sec),
            format_number(t_now),
        );
        if self.use_exercise {
            note.push(' ');
            note.push_str(&self.exercise_note());
        }
        Ok(note)
    }

    /// Names each integrator beside its latest dot, as the text names it, on the last frame's
    /// view: the first place round the dot (then 12, 24, … 84 px further out) that keeps 2 px off
    /// every dot and path and off the names already placed. Up to 24 px out, each name tries
    /// the sides it belongs on first: velocity Verlet's dot is on the parabola and its name
    /// beside it (placed first), explicit Euler's dot is above the parabola and its name above,
    /// semi-implicit Euler's below and its name below. Where the three dots lie on one spot
    /// (the first steps) the names then stack in the order of their dots.
    fn name_integrators(&self, frame: &mut Frame, k_now: usize) {
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        // Verlet, explicit Euler, semi-implicit Euler: the sign of the name's offset down the
        // screen from its dot that it tries first.
        for (k, down) in [(2, 0.0), (0, -1.0), (1, 1.0)] {
            let all = crate::draw::Label::around_dot(
                self.paths[k][k_now],
                STEP_DOT_PX,
                glam::Vec2::new(1.0, down),
                Integrator::ALL[k].name(),
                INTEGRATOR_COLORS[k],
                0,
                8,
                12.0,
            );
            let own = |l: &&crate::draw::Label| {
                let y = l.offset_px.y;
                (y.abs() < 1.0) == (down == 0.0) && y * down >= 0.0
            };
            // The own sides 0, 12 and 24 px out (the first 24 places, 8 sides each), then every
            // place (an own place tried twice is no clearer the second time).
            let ordered = all[..24].iter().filter(own).chain(&all).cloned();
            frame.first_clear_label_by(view, 2.0, ordered, |_| true);
        }
    }

    /// Compares the student's semi-implicit step with the reference at the figure's first step
    /// and at probe inputs the figure's throw never reaches (a step from rest, an acceleration
    /// with sideways parts, a zero step), naming those where it differs.
    pub fn exercise_note(&self) -> String {
        let probes = [
            (
                format!(
                    "the first step (dt = {} s), as (p′, v′)",
                    format_number(self.dt_sec)
                ),
                self.p0,
                self.v0,
                self.g,
                self.dt_sec,
            ),
            (
                "a step from rest (dt = 0.1 s)".to_string(),
                Vec3::new(0.0, 1.0, 0.0),
                Vec3::ZERO,
                self.g,
                0.1,
            ),
            (
                "an acceleration with sideways parts, a = (2, −9.81, 1) m/s²".to_string(),
                Vec3::new(0.5, 1.0, 0.0),
                Vec3::new(1.0, -2.0, 0.5),
                Vec3::new(2.0, -9.81, 1.0),
                0.05,
            ),
            (
                "dt = 0 (nothing may change)".to_string(),
                self.p0,
                self.v0,
                self.g,
                0.0,
            ),
        ];
        let mut checked = Vec::with_capacity(probes.len());
        for (at, p, v, a, dt) in probes {
            match run::semi_implicit_euler_step(self.runner, p, v, a, dt) {
                Err(f) => return failure_note("exercise 11.2 semi_implicit_euler_step", FILE, &f),
                Ok((q, w)) => {
                    let (rq, rw) =
                        crate::exercises::particles::reference_semi_implicit(p, v, a, dt);
                    checked.push(Probe {
                        at,
                        yours: [q.to_array(), w.to_array()].concat(),
                        reference: [rq.to_array(), rw.to_array()].concat(),
                    });
                }
            }
        }
        probe_note("semi_implicit_euler_step", &checked, TOLERANCE).1
    }
}

// ---------------------------------------------------------------------------------------------
// A spring: where explicit Euler gains energy and semi-implicit Euler does not.

/// The spring figure's angular frequency ω = √(k/m), rad/s: π, one swing there and back in 2 s.
pub const SPRING_OMEGA: f32 = std::f32::consts::PI;
/// How far from rest each mass starts, metres (at rest, v = 0).
pub const SPRING_X0_M: f32 = 1.0;
/// The spring figure's timeline, seconds.
pub const SPRING_DURATION: f32 = 10.0;
/// The spring figure's default step, seconds.
pub const SPRING_DEFAULT_DT: f32 = 0.02;
/// Drawn positions are cut at this distance from rest, metres (explicit Euler's grow without
/// bound; the note gives the true value).
pub const SPRING_DRAW_MAX_M: f32 = 2.4;
/// Where the wall each spring hangs from stands, metres along x.
const SPRING_WALL_X: f32 = -2.8;
/// The rows of the three masses, metres along z (explicit Euler at the back).
const SPRING_ROWS_Z: [f32; 3] = [-0.9, 0.0, 0.9];
/// Radius of each spring's mass, metres.
const SPRING_MASS_M: f32 = 0.15;

/// One mass on a spring (`a = −ω² x`, no damping) stepped by each integrator, side by side, with
/// the exact motion `x(t) = x₀ cos ωt` marked in each row.
#[derive(Clone, Debug)]
pub struct SpringFigure {
    dt_sec: f32,
    /// Each integrator's (x, v) after 0, 1, 2, … steps, in [`Integrator::ALL`] order.
    states: [Vec<(f32, f32)>; 3],
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the integrators'
    /// names take places that cover no wall, mass, coil, bar or other name.
    view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
}

impl Default for SpringFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl SpringFigure {
    pub fn new() -> Self {
        let mut f = Self {
            dt_sec: SPRING_DEFAULT_DT,
            states: Default::default(),
            view: None,
        };
        f.integrate();
        f
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the integrators' names are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    /// The camera the page starts with (target x, y, z, distance in metres, yaw and pitch in
    /// radians): from the front and above, the three rows one behind the other.
    pub fn view(&self) -> [f32; 6] {
        [0.0, 0.0, 0.0, 8.0, 0.0, 1.0]
    }

    /// Step size, seconds, in [0.005, 0.2] (ω Δt stays below 2, where semi-implicit Euler is
    /// stable).
    pub fn set_dt(&mut self, dt_sec: f32) -> Result<(), String> {
        self.dt_sec = in_range("step size dt", dt_sec, 0.005, 0.2)?;
        self.integrate();
        Ok(())
    }

    fn steps(&self) -> usize {
        (SPRING_DURATION / self.dt_sec + 1e-3).floor() as usize
    }

    fn integrate(&mut self) {
        let steps = self.steps();
        let w2 = SPRING_OMEGA * SPRING_OMEGA;
        for (k, integrator) in Integrator::ALL.iter().enumerate() {
            let out = &mut self.states[k];
            out.clear();
            let (mut p, mut v) = (Vec3::X * SPRING_X0_M, Vec3::ZERO);
            out.push((p.x, v.x));
            for _ in 0..steps {
                integrator.step(&mut p, &mut v, self.dt_sec, |q| -w2 * q);
                out.push((p.x, v.x));
            }
        }
    }

    /// The energy of a state over the starting energy (per unit mass both):
    /// ```text
    /// E = ½ v² + ½ ω² x²,   E₀ = ½ ω² x₀²
    /// ```
    pub fn energy_ratio(x: f32, v: f32) -> f32 {
        let w2 = SPRING_OMEGA * SPRING_OMEGA;
        (v * v + w2 * x * x) / (w2 * SPRING_X0_M * SPRING_X0_M)
    }

    /// Plot samples after each step, flat: `[t (s), E/E₀ explicit Euler, semi-implicit Euler,
    /// velocity Verlet]` ([`SpringFigure::energy_ratio`]). The exact motion keeps 1.
    pub fn energy_samples(&self) -> Vec<f32> {
        let steps = self.steps();
        let mut out = Vec::with_capacity(4 * (steps + 1));
        for k in 0..=steps {
            out.push(k as f32 * self.dt_sec);
            for states in &self.states {
                let (x, v) = states[k];
                out.push(Self::energy_ratio(x, v));
            }
        }
        out
    }

    /// Each integrator's (x, v) after `k` steps (tests).
    pub fn state(&self, integrator: usize, k: usize) -> (f32, f32) {
        self.states[integrator][k.min(self.steps())]
    }

    /// Draws the three springs at `time_sec` (their latest step) and returns the note.
    pub fn draw(&self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let t = in_range("time", time_sec, 0.0, 1e6)?.min(SPRING_DURATION);
        let k = ((t / self.dt_sec + 1e-4).floor() as usize).min(self.steps());
        let t_now = k as f32 * self.dt_sec;
        let exact = SPRING_X0_M * (SPRING_OMEGA * t_now).cos();
        let y = 0.25;
        // The rest position and the two turning points of the exact motion: a short solid
        // tick across each row on the ground, leaving the gaps between rows to the rows' names.
        for x in [-SPRING_X0_M, 0.0, SPRING_X0_M] {
            for z in SPRING_ROWS_Z {
                frame.wide_line(
                    Vec3::new(x, 0.0, z - 0.16),
                    Vec3::new(x, 0.0, z + 0.16),
                    palette::GRID,
                    2.0,
                );
            }
        }
        let mut energies = [0.0; 3];
        for (i, &color) in INTEGRATOR_COLORS.iter().enumerate() {
            let z = SPRING_ROWS_Z[i];
            let (x, v) = self.states[i][k];
            energies[i] = Self::energy_ratio(x, v);
            let shown = x.clamp(-SPRING_DRAW_MAX_M, SPRING_DRAW_MAX_M);
            // The wall, and the spring as a zigzag of 12 coils from the wall to the mass.
            let wall = Mat4::from_translation(Vec3::new(SPRING_WALL_X - 0.05, y, z))
                * Mat4::from_scale(Vec3::new(0.05, 0.3, 0.3));
            frame.mesh(MeshId::CUBE, wall, palette::GREY);
            let (from, to) = (SPRING_WALL_X, shown - 0.15);
            let coils: Vec<Vec3> = (0..=24)
                .map(|j| {
                    let s = j as f32 / 24.0;
                    let bump = if j == 0 || j == 24 {
                        0.0
                    } else if j % 2 == 0 {
                        0.1
                    } else {
                        -0.1
                    };
                    Vec3::new(from + (to - from) * s, y, z + bump)
                })
                .collect();
            frame.wide_polyline(&coils, palette::GREY, 2.0);
            // The exact mass's place in this row: a dark bar across it.
            frame.wide_line(
                Vec3::new(exact, y, z - 0.32),
                Vec3::new(exact, y, z + 0.32),
                EXACT_COLOR,
                5.0,
            );
            frame.point_on_top(Vec3::new(shown, y, z), SPRING_MASS_M, color);
        }
        // Each name beside its mass, above and right of it first (behind its row, up the screen
        // from the front, clear of its coil on the left); on the last frame's view, the first
        // place round the mass (then further out) that covers no wall (its corners and centre),
        // mass (its centre and six points of its rim), coil, bar, tick or name placed before
        // it: orbited, the rows line up and the walls and other masses come near the names.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let mut solid = Vec::new();
        for (i, z) in SPRING_ROWS_Z.into_iter().enumerate() {
            let wall = Vec3::new(SPRING_WALL_X - 0.05, y, z);
            let half = Vec3::new(0.05, 0.3, 0.3);
            solid.push(wall);
            solid.extend((0..8).map(|c| {
                let s = |bit: i32| if c & bit == 0 { -1.0 } else { 1.0 };
                wall + half * Vec3::new(s(1), s(2), s(4))
            }));
            let x = self.states[i][k]
                .0
                .clamp(-SPRING_DRAW_MAX_M, SPRING_DRAW_MAX_M);
            let mass = Vec3::new(x, y, z);
            solid.push(mass);
            solid.extend([Vec3::X, Vec3::Y, Vec3::Z].map(|d| mass + d * SPRING_MASS_M));
            solid.extend([Vec3::X, Vec3::Y, Vec3::Z].map(|d| mass - d * SPRING_MASS_M));
        }
        // Each mass's centre and width on the canvas (its rim's farthest projection from its
        // centre, twice): each place starts off its ball, and keeps 2 px off every ball's disc.
        let masses: [_; 3] = std::array::from_fn(|i| {
            let x = self.states[i][k].0;
            let mass = Vec3::new(
                x.clamp(-SPRING_DRAW_MAX_M, SPRING_DRAW_MAX_M),
                y,
                SPRING_ROWS_Z[i],
            );
            let disc = view.and_then(|(view_proj, size)| {
                let at = |p: Vec3| crate::camera::project_to_canvas(view_proj, size, p);
                let c = at(mass)?;
                let across = [Vec3::X, Vec3::Y, Vec3::Z]
                    .iter()
                    .filter_map(|&d| at(mass + d * SPRING_MASS_M))
                    .fold(0.0, |w: f32, p| w.max(2.0 * p.distance(c)));
                Some((c, across))
            });
            (mass, x.abs() > SPRING_DRAW_MAX_M, disc)
        });
        let off_solid = super::clear_of(view, &solid);
        let clear = |r: crate::draw::layout::Rect| {
            off_solid(r)
                && masses.iter().all(|(_, _, disc)| {
                    disc.is_none_or(|(c, w)| r.nearest(c).distance(c) > 0.5 * w + 2.0)
                })
        };
        // "exact" straight below the front row's bar, whose near end is the lowest on screen at
        // the page's camera (the three bars stand in one column, which the name heads from
        // below), else round it where it covers no coil, ball or wall.
        let candidates = crate::draw::Label::around_dot(
            Vec3::new(exact, y, SPRING_ROWS_Z[2] + 0.32),
            5.0,
            glam::Vec2::Y,
            "exact",
            EXACT_COLOR,
            1,
            8,
            8.0,
        );
        frame.first_clear_label_by(view, 0.0, candidates, &clear);
        // The boxes of the names placed so far ("exact" first) and the leader lines the page
        // draws to those placed further than LEADER_PX from their mass (mass, box's nearest
        // point): a later name keeps off both.
        let place_of = |l: Option<&crate::draw::Label>| {
            view.zip(l)
                .and_then(|((view_proj, size), l)| l.first_place(view_proj, size))
        };
        let mut taken: Vec<crate::draw::layout::Rect> =
            place_of(frame.labels.last()).into_iter().collect();
        let mut leaders: Vec<(glam::Vec2, glam::Vec2)> = Vec::new();
        for (i, &(mass, cut, disc)) in masses.iter().enumerate() {
            // A mass drawn cut short says so in its name.
            let name = Integrator::ALL[i].name();
            let name = if cut {
                format!("{name} (drawn cut)")
            } else {
                name.to_string()
            };
            let candidates = crate::draw::Label::around_dot(
                mass,
                disc.map_or(0.0, |d| d.1),
                glam::Vec2::new(1.0, -1.0),
                &name,
                INTEGRATOR_COLORS[i],
                0,
                16,
                8.0,
            );
            // A name by its mass (no leader line) has its middle nearer its own mass than any
            // other, so it does not read as naming the next row's; a name further off gets a
            // leader line, which must pass no other name and no other mass's disc. Orbited
            // along the springs, the rows stand side by side and close on the screen.
            let reads_as_own = |r: crate::draw::layout::Rect| {
                let Some((c, _)) = disc else { return true };
                let near = r.nearest(c);
                let others = masses.iter().enumerate().filter(|&(j, _)| j != i);
                let own = if near.distance(c) <= crate::draw::layout::LEADER_PX {
                    let middle = r.min + 0.5 * r.size;
                    let d = middle.distance(c);
                    others
                        .filter_map(|(_, m)| m.2)
                        .all(|(o, _)| middle.distance(o) > d)
                } else {
                    taken
                        .iter()
                        .all(|t| !crate::draw::segment_enters(c, near, t.min, t.max()))
                        && others.filter_map(|(_, m)| m.2).all(|(o, w)| {
                            let h = glam::Vec2::splat(0.36 * w);
                            !crate::draw::segment_enters(c, near, o - h, o + h)
                        })
                };
                own && leaders
                    .iter()
                    .all(|&(a, b)| !crate::draw::segment_enters(a, b, r.min, r.max()))
            };
            frame.first_clear_label_by(view, 0.0, candidates, |r| clear(r) && reads_as_own(r));
            if let (Some(r), Some((c, _))) = (place_of(frame.labels.last()), disc) {
                taken.push(r);
                let near = r.nearest(c);
                if near.distance(c) > crate::draw::layout::LEADER_PX {
                    leaders.push((c, near));
                }
            }
        }
        frame.keep_box_in_view(
            Vec3::new(SPRING_WALL_X - 0.2, 0.0, SPRING_ROWS_Z[0] - 0.5),
            Vec3::new(SPRING_DRAW_MAX_M + 0.2, 0.5, SPRING_ROWS_Z[2] + 0.6),
        );
        let amplitude = |i: usize| {
            Self::energy_ratio(self.states[i][k].0, self.states[i][k].1).sqrt() * SPRING_X0_M
        };
        let mut note = format!(
            "After {k} {} of dt = {} s (t = {} s), energy over the start: explicit Euler ×{},              semi-implicit Euler ×{}, velocity Verlet ×{}.",
            if k == 1 { "step" } else { "steps" },
            format_number(self.dt_sec),
            format_number(t_now),
            format_number(energies[0]),
            format_number(energies[1]),
            format_number(energies[2]),
        );
        if amplitude(0) > SPRING_DRAW_MAX_M {
            note.push_str(&format!(
                " Explicit Euler now swings {} m from rest (drawn cut at {} m).",
                format_number(amplitude(0)),
                format_number(SPRING_DRAW_MAX_M)
            ));
        }
        Ok(note)
    }
}

// ---------------------------------------------------------------------------------------------
// Bouncing balls.

/// Radius of the bouncing balls, metres.
const BALL_RADIUS: f32 = 0.08;
/// The bounce figure's glass box: walls at x, z = ±`BOX_HALF_M` metres. A ball that leaves the
/// sphere sideways bounces back off them with the same restitution and friction as the floor;
/// without them, at e = 1 and μ = 0 nothing slows a ball's horizontal speed and it would leave
/// the view for good.
pub const BOX_HALF_M: f32 = 1.5;
/// How high the box's edges are drawn, metres (the walls themselves have no top; no ball rises
/// above its drop height, 3.1 m, since a bounce never adds energy).
pub const BOX_DRAWN_HEIGHT_M: f32 = 3.3;
/// How many balls the bounce figure drops.
pub const BOUNCE_BALLS: usize = 7;
/// The bounce figure's timeline, seconds.
pub const BOUNCE_DURATION: f32 = 6.0;

/// Balls dropped onto a sphere and the floor.
#[derive(Clone, Debug)]
pub struct BounceFigure {
    sphere: Sphere,
    restitution: f32,
    friction: f32,
    positions: Vec<Vec3>,
    velocities: Vec<Vec3>,
    resting: Vec<bool>,
    steps_done: usize,
    dirty: bool,
    use_exercise: bool,
    runner: Runner,
}

impl Default for BounceFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl BounceFigure {
    pub fn new() -> Self {
        let mut f = Self {
            sphere: Sphere {
                center: Vec3::new(0.0, 0.6, 0.0),
                radius: 0.6,
            },
            restitution: 0.75,
            friction: 0.1,
            positions: Vec::new(),
            velocities: Vec::new(),
            resting: Vec::new(),
            steps_done: 0,
            dirty: false,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
        };
        f.drop_balls();
        f
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
    }

    /// The camera the page starts with, as `Viewer::setCamera`'s arguments: target x, y, z
    /// (metres), distance (metres), yaw and pitch (radians). It frames every ball at its drop
    /// height (up to 3.1 m), the sphere and the floor under them at the page's canvas sizes (a
    /// test checks it); a camera aimed 0.9 m up from 4.5 m away would start with the highest
    /// balls above the canvas.
    pub fn view(&self) -> [f32; 6] {
        [0.0, 1.4, 0.0, 6.4, 0.3, 0.2]
    }

    /// Uses the student's exercise 11.1 for the predicted impact.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    pub fn set_restitution(&mut self, e: f32) -> Result<(), String> {
        self.restitution = in_range("restitution", e, 0.0, 1.0)?;
        self.dirty = true;
        Ok(())
    }

    pub fn set_friction(&mut self, mu: f32) -> Result<(), String> {
        self.friction = in_range("friction", mu, 0.0, 2.0)?;
        self.dirty = true;
        Ok(())
    }

    /// Drops every ball again from its starting height.
    pub fn drop_balls(&mut self) {
        self.positions = (0..BOUNCE_BALLS)
            .map(|i| {
                Vec3::new(
                    -0.75 + 0.25 * i as f32,
                    2.2 + 0.15 * i as f32,
                    0.05 * i as f32 - 0.15,
                )
            })
            .collect();
        self.velocities = vec![Vec3::ZERO; BOUNCE_BALLS];
        self.resting = vec![false; BOUNCE_BALLS];
        self.steps_done = 0;
        self.dirty = false;
    }

    /// The surfaces the balls' centres bounce on: the floor, the sphere and the box's four walls,
    /// grown by the ball's radius (a ball touches them when its centre is one radius away).
    fn surfaces(&self) -> Surfaces {
        let inner = BOX_HALF_M - BALL_RADIUS;
        Surfaces {
            floor_y: Some(BALL_RADIUS),
            spheres: vec![Sphere {
                center: self.sphere.center,
                radius: self.sphere.radius + BALL_RADIUS,
            }],
            walls: [Vec3::X, Vec3::NEG_X, Vec3::Z, Vec3::NEG_Z]
                .map(|n| Plane::through(-inner * n, n))
                .to_vec(),
            restitution: self.restitution,
            friction: self.friction,
            ..Default::default()
        }
    }

    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }

    /// Brings the balls to `time_sec` after their drop (replaying when the time went back or a
    /// parameter changed). Returns the steps taken.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, String> {
        let target = steps_to(time_sec)?;
        if self.dirty || target < self.steps_done {
            self.drop_balls();
        }
        let s = self.surfaces();
        let n = target - self.steps_done;
        for _ in 0..n {
            self.step(&s);
        }
        Ok(n)
    }

    /// One step of every ball.
    fn step(&mut self, s: &Surfaces) {
        for i in 0..self.positions.len() {
            crate::particles::ballistic_step(
                &mut self.positions[i],
                &mut self.velocities[i],
                &mut self.resting[i],
                SIM_DT,
                s,
            );
        }
        self.steps_done += 1;
    }

    /// Plot samples over the figure's timeline ([`BOUNCE_DURATION`]), one per step, flat:
    /// `[t (s), h (m), E / (m g) (m)]` for the orange ball (ball 0), from a replay of the steps
    /// the figure takes with the current settings. `h` is its lowest point's height above the
    /// floor; the second curve is its energy per unit weight, the height it would reach if all
    /// its speed went upwards:
    /// ```text
    /// E / (m g) = h + |v|² / (2 g)
    /// ```
    /// In flight the energy curve is flat (the parabola is exact); each bounce lowers it by the
    /// part of the speed that restitution and friction take, and with e = 1 and μ = 0 it stays
    /// flat throughout.
    pub fn plot_samples(&self) -> Vec<f32> {
        let mut f = self.clone();
        f.drop_balls();
        let s = f.surfaces();
        let g = -s.gravity.y;
        let steps = (BOUNCE_DURATION / SIM_DT).round() as usize;
        let mut out = Vec::with_capacity(3 * (steps + 1));
        for k in 0..=steps {
            if k > 0 {
                f.step(&s);
            }
            let (p, v) = (f.positions[0], f.velocities[0]);
            let h = p.y - BALL_RADIUS;
            out.extend([k as f32 * SIM_DT, h, h + v.length_squared() / (2.0 * g)]);
        }
        out
    }

    /// The time until ball 0's centre reaches the floor height (ignoring the sphere), the
    /// student's (exercise 11.1) when asked and usable.
    fn impact_time(&self) -> Option<f32> {
        let (p, v) = (self.positions[0], self.velocities[0]);
        if self.resting[0] || p.y <= BALL_RADIUS {
            return None;
        }
        let g = self.surfaces().gravity.y;
        let student = self
            .use_exercise
            .then(|| run::time_of_impact(self.runner, p.y, v.y, g, BALL_RADIUS).ok())
            .flatten()
            .filter(|t| t.is_finite() && *t >= 0.0 && *t < 100.0);
        student.or_else(|| floor_time_of_impact(p.y, v.y, g, BALL_RADIUS, f32::INFINITY))
    }

    /// Simulates to `time_sec`, draws, and returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        self.advance_to(time_sec)?;
        frame.grid(8, 0.5);
        // The glass box: its bottom and top rims and its four vertical edges.
        let (w, h) = (BOX_HALF_M, BOX_DRAWN_HEIGHT_M);
        let corners = [(-w, -w), (w, -w), (w, w), (-w, w)];
        for (k, &(x, z)) in corners.iter().enumerate() {
            let (x2, z2) = corners[(k + 1) % 4];
            for y in [0.003, h] {
                frame.wide_line(Vec3::new(x, y, z), Vec3::new(x2, y, z2), palette::GREY, 1.5);
            }
            frame.wide_line(Vec3::new(x, 0.0, z), Vec3::new(x, h, z), palette::GREY, 1.5);
        }
        let model = Mat4::from_translation(self.sphere.center)
            * Mat4::from_scale(Vec3::splat(self.sphere.radius));
        frame.mesh(MeshId::SPHERE, model, palette::GREY);
        let sphere_bottom = self.sphere.center - Vec3::Y * self.sphere.radius;
        frame.contact_shadow(sphere_bottom, self.sphere.radius);
        for (i, p) in self.positions.iter().enumerate() {
            let color = if i == 0 {
                palette::ORANGE
            } else {
                palette::BLUE
            };
            frame.mesh(
                MeshId::SPHERE,
                Mat4::from_translation(*p) * Mat4::from_scale(Vec3::splat(BALL_RADIUS)),
                color,
            );
            // A shadow on the floor shows how high each ball is and when it lands.
            frame.contact_shadow(*p - Vec3::Y * BALL_RADIUS, BALL_RADIUS);
        }
        let mut note = String::new();
        if let Some(t) = self.impact_time() {
            let (hit, _) = free_fall(
                self.positions[0],
                self.velocities[0],
                self.surfaces().gravity,
                t,
            );
            let mark = Vec3::new(hit.x, 0.002, hit.z);
            frame.marker(mark, 10.0, palette::ORANGE);
            frame.stroke(
                &[self.positions[0], mark],
                palette::ORANGE,
                crate::draw::StrokeStyle::dashed(2.0, 0.06, 0.04),
            );
            // Leftwards from the mark: the orange ball falls left of the sphere, and a label
            // running right would cover it. The label ends a ball's radius and a gap left of
            // the mark, so the ball, landing on the mark, does not cover its end either.
            frame.label_left(
                mark + Vec3::new(-(BALL_RADIUS + 0.05), 0.15, 0.0),
                format!("floor in {} s", format_number(t)),
                palette::ORANGE,
            );
            note = format!(
                "The orange ball reaches the floor in t = {} s if the sphere is not in its way.",
                format_number(t)
            );
        } else {
            note.push_str("The orange ball is on the floor.");
        }
        note.push_str(&format!(
            " Each bounce keeps e = {} of the normal speed; friction μ = {} takes μ(1 + e) times \
             the normal speed off the sliding speed.",
            format_number(self.restitution),
            format_number(self.friction)
        ));
        if self.use_exercise {
            note.push(' ');
            note.push_str(&self.exercise_note());
        }
        Ok(note)
    }

    /// Compares the student's time of impact with the reference for ball 0 (or a fixed drop when
    /// it rests), then at probe drops the figure's balls never make (thrown up, thrown down, a
    /// floor above 0, the Moon's gravity), naming those where it differs: a ball dropped from
    /// rest cannot tell a formula that forgets `vy`.
    pub fn exercise_note(&self) -> String {
        let (mut y, mut vy) = (self.positions[0].y, self.velocities[0].y);
        if self.resting[0] || y <= BALL_RADIUS {
            (y, vy) = (2.0, 0.0);
        }
        let g = self.surfaces().gravity.y;
        let shown = format!(
            "y0 = {} m, vy = {} m/s",
            format_number(y),
            format_number(vy)
        );
        let probes = [
            (shown, y, vy, g, BALL_RADIUS),
            (
                "a ball thrown up (y0 = 1 m, vy = 5 m/s)".to_string(),
                1.0,
                5.0,
                g,
                0.0,
            ),
            (
                "a ball thrown down (y0 = 1 m, vy = −5 m/s)".to_string(),
                1.0,
                -5.0,
                g,
                0.0,
            ),
            (
                "a floor at 1 m (y0 = 3 m, vy = 0)".to_string(),
                3.0,
                0.0,
                g,
                1.0,
            ),
            (
                "the Moon's gravity (gy = −1.62 m/s²)".to_string(),
                2.0,
                1.0,
                -1.62,
                0.0,
            ),
        ];
        let mut checked = Vec::with_capacity(probes.len());
        for (at, y, vy, g, floor) in probes {
            match run::time_of_impact(self.runner, y, vy, g, floor) {
                Err(f) => return failure_note("exercise 11.1 time_of_impact", FILE, &f),
                Ok(t) => {
                    let reference =
                        crate::exercises::particles::reference_time_of_impact(y, vy, g, floor);
                    checked.push(Probe {
                        at,
                        yours: vec![t],
                        reference: vec![reference],
                    });
                }
            }
        }
        // Relative to the largest reference time (about 3.2 s on the Moon).
        probe_note("time_of_impact", &checked, TOLERANCE * 4.0).1
    }
}

// ---------------------------------------------------------------------------------------------
// Squash and stretch.

/// The squash figure's timeline, seconds.
pub const SQUASH_DURATION: f32 = 4.0;

/// How far apart (along z) the squash figure shows its two balls, metres.
pub const SQUASH_SPACING: f32 = 1.2;

/// The same bounce twice: a rigid ball and one that squashes and stretches.
#[derive(Clone, Debug)]
pub struct SquashFigure {
    plain: SquashBall,
    squash: SquashBall,
    surfaces: Surfaces,
    steps_done: usize,
    /// Where the balls' centres pass over the timeline, every 0.1 s (the same for both: the
    /// squash only changes the shape), which the camera fits.
    path: Vec<Vec3>,
}

impl Default for SquashFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl SquashFigure {
    pub fn new() -> Self {
        let surfaces = Surfaces {
            restitution: 0.8,
            friction: 0.0,
            ..Default::default()
        };
        let plain = SquashBall::new(0.25, 2.0, 0.6);
        let mut ball = plain.clone();
        let mut path = vec![ball.position];
        let every = (0.1 / SIM_DT).round() as usize;
        for k in 1..=(SQUASH_DURATION / SIM_DT).round() as usize {
            ball.step(&surfaces, SIM_DT);
            if k % every == 0 {
                path.push(ball.position);
            }
        }
        Self {
            plain,
            squash: SquashBall::new(0.25, 2.0, 0.6),
            surfaces,
            steps_done: 0,
            path,
        }
    }

    /// The camera the page starts with, as `Viewer::setCamera`'s arguments (target x, y, z,
    /// distance in metres, yaw and pitch in radians): both balls side by side, the rigid one on
    /// the left. The viewer then fits the balls' whole path ([`SquashFigure::draw`] declares it).
    pub fn view(&self) -> [f32; 6] {
        [-0.1, 0.9, 0.0, 5.0, 0.9, 0.15]
    }

    /// Stretch per m/s of speed, in [0, 0.3].
    pub fn set_stretch(&mut self, k: f32) -> Result<(), String> {
        self.squash.stretch_per_speed = in_range("stretch", k, 0.0, 0.3)?;
        self.restart();
        Ok(())
    }

    /// Deepest squash on impact, in [0, 0.8].
    pub fn set_squash(&mut self, squash: f32) -> Result<(), String> {
        self.squash.squash = in_range("squash", squash, 0.0, 0.8)?;
        self.restart();
        Ok(())
    }

    /// Seconds a squash lasts, in [0.02, 0.3].
    pub fn set_contact(&mut self, sec: f32) -> Result<(), String> {
        self.squash.contact_sec = in_range("contact time", sec, 0.02, 0.3)?;
        self.restart();
        Ok(())
    }

    /// Back to the start of the drop, keeping the parameters.
    fn restart(&mut self) {
        let fresh = Self::new();
        self.plain = fresh.plain;
        let (k, s, c) = (
            self.squash.stretch_per_speed,
            self.squash.squash,
            self.squash.contact_sec,
        );
        self.squash = fresh.squash;

        (
            self.squash.stretch_per_speed,
            self.squash.squash,
            self.squash.contact_sec,
        ) = (k, s, c);
        self.steps_done = 0;
    }

    /// Brings both balls to `time_sec` after the drop. Returns the steps taken.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, String> {
        let target = steps_to(time_sec)?;
        if target < self.steps_done {
            self.restart();
        }
        let n = target - self.steps_done;
        for _ in 0..n {
            self.plain.step(&self.surfaces, SIM_DT);
            self.squash.step(&self.surfaces, SIM_DT);
        }
        self.steps_done = target;
        Ok(n)
    }

    /// The squashing ball's `(axis, s)` now.
    pub fn stretch(&self) -> (Vec3, f32) {
        self.squash.stretch()
    }

    /// Plot samples over the figure's timeline ([`SQUASH_DURATION`]), one per step, flat:
    /// `[t (s), s of the squash-and-stretch ball]`. `s > 1` is a stretch along the velocity,
    /// `s < 1` a squash along the floor's normal; the volume is 1 either way. From a replay of
    /// the same steps the figure takes, with the current settings.
    pub fn plot_samples(&self) -> Vec<f32> {
        let mut f = self.clone();
        f.restart();
        let steps = (SQUASH_DURATION / SIM_DT).round() as usize;
        let mut out = Vec::with_capacity(2 * (steps + 1));
        for k in 0..=steps {
            if k > 0 {
                f.squash.step(&f.surfaces, SIM_DT);
            }
            out.extend([k as f32 * SIM_DT, f.squash.stretch().1]);
        }
        out
    }

    /// Simulates to `time_sec`, draws, and returns the note.
    pub fn draw(&mut self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        self.advance_to(time_sec)?;
        frame.grid(8, 0.5);
        let offset = |x: f32| Vec3::new(-1.2, 0.0, x);
        // Both balls' whole path stays in view, as far as a stretched ball reaches and with
        // the labels above: the camera fits these points, not the 4 m grid.
        let reach = self.plain.radius * self.squash.max_stretch;
        for &p in &self.path {
            for z in [-0.5 * SQUASH_SPACING, 0.5 * SQUASH_SPACING] {
                let c = p + offset(z);
                frame.keep_box_in_view(
                    Vec3::new(c.x - reach, 0.0, c.z - reach),
                    c + Vec3::new(reach, reach.max(0.45), reach),
                );
            }
        }
        // The rigid ball, in front: at the page's camera it is the left one, so its short label
        // ends before the squash ball's long one begins (labels run rightwards from their
        // anchors; with the long label on the left, "squash and stretch" would run into
        // "rigid").
        let p = self.plain.position + offset(0.5 * SQUASH_SPACING);
        frame.mesh(
            MeshId::SPHERE,
            Mat4::from_translation(p) * Mat4::from_scale(Vec3::splat(self.plain.radius)),
            palette::GREY,
        );
        // The squashing ball: keep its lowest point on the floor while squashed.
        let (axis, s) = self.squash.stretch();
        let mut c = self.squash.position + offset(-0.5 * SQUASH_SPACING);
        if axis == Vec3::Y && s < 1.0 {
            c.y = self.squash.radius * s;
        }
        let m = Mat4::from_translation(c) * Mat4::from_mat3(self.squash.shape_matrix());
        frame.mesh(MeshId::SPHERE, m, palette::ORANGE);
        // Shadows on the floor: each ball's height, and the moment it lands, from one view.
        // A dashed line drops from each ball to the floor: the shadows fade out above
        // `Frame::shadow_reach` (1.5 m), and the balls start higher.
        let r = self.plain.radius;
        for bottom in [p - Vec3::Y * r, Vec3::new(c.x, (c.y - r).max(0.0), c.z)] {
            frame.contact_shadow(bottom, r);
            frame.stroke(
                &[bottom, bottom * Vec3::new(1.0, 0.0, 1.0)],
                palette::GREY,
                crate::draw::StrokeStyle::dashed(1.5, 0.08, 0.06),
            );
        }
        frame.label(p + Vec3::new(0.0, 0.45, 0.0), "rigid", palette::DARK);
        frame.label(
            c + Vec3::new(0.0, 0.45, 0.0),
            "squash and stretch",
            palette::ORANGE,
        );
        let what = if s < 1.0 { "squashed" } else { "stretched" };
        Ok(format!(
            "Orange ball: {what} by s = {} along {}; its volume stays {} of the round ball's.",
            format_number(s),
            if axis == Vec3::Y && s < 1.0 {
                "the floor's normal".to_string()
            } else {
                "its velocity".to_string()
            },
            format_number(self.squash.shape_matrix().determinant() / self.squash.radius.powi(3)),
        ) + &format!(
            " It stretches by k = {} per m/s in flight and squashes down to s = {} for {} s \
             after each impact.",
            format_number(self.squash.stretch_per_speed),
            format_number(1.0 - self.squash.squash),
            format_number(self.squash.contact_sec),
        ))
    }
}

/// Calls `f` with the emitters as GPU mode should colour its sprites: as they are with the fade
/// on; without it opaque at birth and at death, as [`EmitterFigure::draw`] makes every CPU sprite
/// (the compute shader mixes the two colours by age). The alphas are put back afterwards.
fn gpu_colours<T>(emitters: &mut [Emitter], fade: bool, f: impl FnOnce(&mut [Emitter]) -> T) -> T {
    if fade {
        return f(emitters);
    }
    let alphas: Vec<(f32, f32)> = emitters
        .iter_mut()
        .map(|e| {
            let a = (e.color_birth.w, e.color_death.w);
            (e.color_birth.w, e.color_death.w) = (1.0, 1.0);
            a
        })
        .collect();
    let result = f(emitters);
    for (e, (birth, death)) in emitters.iter_mut().zip(alphas) {
        (e.color_birth.w, e.color_death.w) = (birth, death);
    }
    result
}
