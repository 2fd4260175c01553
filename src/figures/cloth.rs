//! Figure logic for lesson 13, "Cloth" (see [`crate::figures`]).
//!
//! - [`ClothFigure`]: a cloth simulated frame by frame; preset [`Preset::Flag`] (two flags in a
//!   gusty wind, mass-spring beside XPBD, with the same stiffness) or [`Preset::Drape`] (a cloth
//!   falling on a sphere and a box the reader moves, one method at a time, any resolution up to
//!   100 × 100). Energy and maximum stretch per frame for the plots; the explosion detected and
//!   reported; a particle dragged with the mouse.
//! - [`SpringFigure`]: one particle on a damped spring (mass-spring) beside one on a distance
//!   constraint (XPBD): the stability limit `ω h < 2` in its simplest form, and the student's
//!   exercises 13.1–13.3.
//!
//! Both are deterministic: the state at timeline time `t` is the state after `⌊t / Δt⌋` frames
//! from the start, replayed when the time goes back or a parameter changes (drags included: they
//! are recorded with the frame they happened at).

use super::{
    compare_note, failure_note, finite, format_number, in_range, not_done_note, palette, Failure,
    Frame, MeshId, Runner, DEFAULT_RUNNER,
};
use crate::camera::{point_on_view_plane, project_to_canvas, OrbitCamera};
use crate::cloth::{Cloth, ClothParams, ClothSpec, Colliders, Method, SpringKind};
use crate::draw::DOT_PX;
use crate::exercises::run;
use crate::mesh::MeshData;
use glam::{Mat4, Quat, Vec2, Vec3, Vec4};

const FILE: &str = "src/exercises/cloth.rs";
/// Length of the figures' timelines, seconds (bounds the work of one replay).
pub const DURATION: f32 = 6.0;
/// The softest structural springs a figure takes, N/m: a cloth without springs that resist
/// stretch is no cloth (the flag at 0 N/m shreds at any substep).
pub const MIN_STRUCTURAL_K: f32 = 50.0;
/// The stiffest springs a figure takes, N/m.
const MAX_K: f32 = 5000.0;
/// A held cloth's largest spring stretch, %, past which the note calls its springs too soft.
const SOFT_STRETCH_PERCENT: f32 = 50.0;

/// The structural stiffnesses, N/m, at which [`ClothFigure::substeps_plot`] measures the substeps
/// the mass-spring cloth needs (up to the slider's 5,000).
pub const SUBSTEP_PLOT_K: [f32; 6] = [250.0, 500.0, 1000.0, 2000.0, 3500.0, 5000.0];
/// The finest resolution the page offers (particles per side); the core allows
/// [`crate::cloth::MAX_SIDE`].
pub const PAGE_MAX_SIDE: usize = 100;
/// How close (CSS pixels) a pointer must be to a particle to grab it.
pub const GRAB_RADIUS_PX: f32 = 24.0;
/// Width of a guide line (a drag, an obstacle's way to its slider's place), CSS pixels.
pub const GUIDE_PX: f32 = 2.0;
/// Width of the spring figure's springs, CSS pixels.
pub const SPRING_PX: f32 = 3.0;
/// The most drag events a figure records for its replays.
pub const MAX_DRAG_EVENTS: usize = 4000;
/// How fast the sphere and the box move towards where their sliders put them, m/s. They never
/// jump: a jump of 0.5 m in one frame would land the sphere inside the cloth, and the collision
/// would then fling its particles out by half a metre in one step.
pub const OBSTACLE_SPEED: f32 = 1.5;
/// What the drape's camera keeps in view at least ([`ClothFigure::view_box`]): the 2 m cloth
/// where it starts (level, 1.5 m up) and its label above it, with a margin.
/// Its floor is a little under the ground, where the cloth lies by its collision thickness.
pub const DRAPE_VIEW: (Vec3, Vec3) = (Vec3::new(-1.1, -0.05, -1.1), Vec3::new(1.1, 1.9, 1.1));

/// The smallest box holding the finite ones of `points`; (+∞, −∞) when there are none, which
/// leaves a union unchanged.
fn bounds(points: &[Vec3]) -> (Vec3, Vec3) {
    points
        .iter()
        .filter(|p| p.is_finite())
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        })
}

/// What the cloth figure shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Preset {
    /// Two flags on poles in a gusty wind: mass-spring (left) and XPBD (right).
    Flag,
    /// A level cloth falling on a sphere, a box and the ground.
    Drape,
}

/// The pin choices of the dropdown.
pub const PINS: [&str; 3] = ["none", "two corners", "whole edge"];
/// The method choices of the drape's dropdown.
pub const METHODS: [&str; 2] = ["mass-spring", "XPBD"];

/// One simulated cloth and what is drawn of it.
#[derive(Clone, Debug)]
struct Sim {
    cloth: Cloth,
    method: Method,
    /// The last positions before an explosion (what is drawn after it).
    last_good: Vec<Vec3>,
    /// Per frame: `(time, energy, max stretch)`.
    samples: Vec<[f32; 3]>,
    /// Front and back faces: 2 × the particles.
    render_positions: Vec<Vec3>,
    render_normals: Vec<Vec3>,
    colors: Vec<Vec4>,
    color: Vec3,
    label: Vec3,
    /// It "exploded" while the reader held one of its particles: the drag pulled it apart (a
    /// held particle follows the pointer whatever the springs say), not the step.
    torn: bool,
    /// It exploded while the sphere or the box was moving.
    pushed: bool,
}

/// A held particle: `(cloth, particle index, target point)`.
type Grab = (usize, usize, Vec3);

/// The cloth figure (both presets).
#[derive(Clone, Debug)]
pub struct ClothFigure {
    preset: Preset,
    side: usize,
    params: ClothParams,
    colliders: Colliders,
    pins: usize,
    method: Method,
    wind_speed: f32,
    frame_dt: f32,
    sims: Vec<Sim>,
    frames_done: usize,
    dirty: bool,
    /// `(frame, grab)`: from that frame on, this particle (sim, index) is held at that point.
    drags: Vec<(usize, Option<Grab>)>,
    drag_cursor: usize,
    /// The particle being dragged now: `(sim, index, the point grabbed)`.
    dragging: Option<Grab>,
    view: Option<(OrbitCamera, Vec2)>,
    structure_changed: bool,
    /// Sphere and box centres at the start of a run.
    obstacles_start: (Vec3, Vec3),
    /// `(frame, sphere centre, box centre)`: from that frame on the obstacles head there (the
    /// reader moved the sliders then; replayed like drags).
    obstacle_moves: Vec<(usize, Vec3, Vec3)>,
    obstacle_cursor: usize,
    /// Where the obstacles are heading (the sliders' values as of the frame simulated last); the
    /// colliders move towards it at [`OBSTACLE_SPEED`].
    obstacle_targets: (Vec3, Vec3),
    /// The obstacles moved during the frame simulated last.
    obstacles_moving: bool,
    /// Frames simulated by the last [`ClothFigure::advance_to`] that went on from where the
    /// previous one stopped; 0 when it replayed from the start (a scrub back, a new setting).
    last_step_frames: usize,
    /// See [`ClothFigure::sample_generation`].
    sample_generation: u32,
}

impl ClothFigure {
    /// The figure of `preset` with its defaults.
    pub fn new(preset: Preset) -> Self {
        let mut params = ClothParams::default();
        let (side, pins, method) = match preset {
            Preset::Flag => (14, 2, Method::MassSpring),
            Preset::Drape => (20, 0, Method::MassSpring),
        };
        params.compliance_from_stiffness();
        let colliders = match preset {
            Preset::Flag => Colliders {
                ground_y: Some(0.0),
                ..Default::default()
            },
            Preset::Drape => Colliders {
                ground_y: Some(0.0),
                sphere: Some((Vec3::new(0.0, 0.55, 0.0), 0.55)),
                cuboid: Some((Vec3::new(-0.9, 0.2, 0.7), Vec3::splat(0.2))),
                friction: 0.3,
                thickness: 0.012,
            },
        };
        let mut f = Self {
            preset,
            side,
            params,
            colliders,
            pins,
            method,
            wind_speed: if preset == Preset::Flag { 6.0 } else { 0.0 },
            // The frame step the page starts the flags with, 16.7 ms, computed as `set_step_ms`
            // computes it, so that a test steps them exactly as the page does (the drape's page
            // sets no step and keeps 1/60 s).
            frame_dt: if preset == Preset::Drape {
                1.0 / 60.0
            } else {
                16.7 / 1000.0
            },
            sims: Vec::new(),
            frames_done: 0,
            dirty: false,
            drags: Vec::new(),
            drag_cursor: 0,
            dragging: None,
            view: None,
            structure_changed: true,
            obstacles_start: (Vec3::ZERO, Vec3::ZERO),
            obstacle_moves: Vec::new(),
            obstacle_cursor: 0,
            obstacle_targets: (Vec3::ZERO, Vec3::ZERO),
            obstacles_moving: false,
            last_step_frames: 0,
            sample_generation: 0,
        };
        f.obstacles_start = f.obstacles();
        f.obstacle_targets = f.obstacles_start;
        f.build();
        f
    }

    fn build(&mut self) {
        let side = self.side as i64;
        let specs: Vec<(ClothSpec, Method, Vec3)> = match self.preset {
            Preset::Flag => {
                let rows = ((side as f32) * 0.65).round().max(2.0) as i64;
                let flag = |x: f32| ClothSpec {
                    columns: side,
                    rows,
                    width_m: 1.5,
                    height_m: 1.0,
                    mass_kg: 0.25,
                    origin: Vec3::new(x, 2.4, 0.0),
                    across: Vec3::X,
                    down: Vec3::NEG_Y,
                };
                vec![
                    (flag(-1.9), Method::MassSpring, palette::ORANGE),
                    (flag(0.4), Method::Xpbd, palette::TEAL),
                ]
            }
            Preset::Drape => {
                let color = if self.method == Method::MassSpring {
                    palette::ORANGE
                } else {
                    palette::TEAL
                };
                vec![(ClothSpec::level(side, 1.5), self.method, color)]
            }
        };
        self.sims = specs
            .into_iter()
            .map(|(spec, method, color)| {
                let cloth = Cloth::new(&spec).expect("the page's resolutions are valid");
                let n = cloth.len();
                let label = match self.preset {
                    Preset::Flag => spec.origin + Vec3::new(0.75, 0.35, 0.0),
                    Preset::Drape => Vec3::new(0.0, 1.9, -1.0),
                };
                Sim {
                    last_good: cloth.positions.clone(),
                    samples: Vec::with_capacity(1024),
                    render_positions: vec![Vec3::ZERO; 2 * n],
                    render_normals: vec![Vec3::ZERO; 2 * n],
                    colors: vec![Vec4::ONE; 2 * n],
                    cloth,
                    method,
                    color,
                    label,
                    torn: false,
                    pushed: false,
                }
            })
            .collect();
        self.apply_pins();
        self.structure_changed = true;
        self.restart();
    }

    fn apply_pins(&mut self) {
        for sim in &mut self.sims {
            let c = &mut sim.cloth;
            c.unpin_all();
            let rows = c.rows;
            match self.pins {
                1 => {
                    let (a, b) = (c.index(0, 0), c.index(0, rows - 1));
                    c.set_pinned(a, true);
                    c.set_pinned(b, true);
                }
                2 => {
                    for r in 0..rows {
                        let i = c.index(0, r);
                        c.set_pinned(i, true);
                    }
                }
                _ => {}
            }
        }
    }

    fn restart(&mut self) {
        let params: Vec<ClothParams> = self
            .sims
            .iter()
            .map(|s| self.params_for(s.method, 0.0))
            .collect();
        for (sim, params) in self.sims.iter_mut().zip(&params) {
            sim.cloth.reset();
            sim.last_good.copy_from_slice(&sim.cloth.positions);
            sim.samples.clear();
            sim.torn = false;
            sim.pushed = false;
            // The start is a sample too: a cloth that explodes in its first frames still draws a
            // line (from here up to its last good frame) instead of one invisible point.
            sim.samples.push([
                0.0,
                sim.cloth.energy(params),
                100.0 * sim.cloth.max_stretch(),
            ]);
        }
        self.frames_done = 0;
        self.sample_generation = self.sample_generation.wrapping_add(1);
        self.drag_cursor = 0;
        self.obstacle_cursor = 0;
        let (sphere, cuboid) = self.obstacles_start;
        self.place_obstacles(sphere, cuboid);
        self.obstacle_targets = self.obstacles_start;
        self.obstacles_moving = false;
        self.dirty = false;
    }

    /// The sphere's and the box's centres now.
    pub fn obstacles(&self) -> (Vec3, Vec3) {
        (
            self.colliders.sphere.map_or(Vec3::ZERO, |s| s.0),
            self.colliders.cuboid.map_or(Vec3::ZERO, |b| b.0),
        )
    }

    fn place_obstacles(&mut self, sphere: Vec3, cuboid: Vec3) {
        if let Some((c, _)) = &mut self.colliders.sphere {
            *c = sphere;
        }
        if let Some((c, _)) = &mut self.colliders.cuboid {
            *c = cuboid;
        }
    }

    /// Where the obstacles are heading: the sliders' values as of the frame simulated last.
    pub fn obstacle_targets(&self) -> (Vec3, Vec3) {
        self.obstacle_targets
    }

    /// Takes the recorded obstacle moves up to `frame` as the targets.
    fn catch_up_obstacles(&mut self, frame: usize) {
        while self.obstacle_cursor < self.obstacle_moves.len()
            && self.obstacle_moves[self.obstacle_cursor].0 <= frame
        {
            let (_, sphere, cuboid) = self.obstacle_moves[self.obstacle_cursor];
            self.obstacle_targets = (sphere, cuboid);
            self.obstacle_cursor += 1;
        }
    }

    /// Moves the obstacles towards their targets by at most [`OBSTACLE_SPEED`] × Δt (one frame);
    /// returns whether they moved.
    fn move_obstacles(&mut self) -> bool {
        let step = OBSTACLE_SPEED * self.frame_dt;
        let toward = |from: Vec3, to: Vec3| {
            let d = to - from;
            if d.length() <= step {
                to
            } else {
                from + d * (step / d.length())
            }
        };
        let (sphere, cuboid) = self.obstacles();
        let (ts, tc) = self.obstacle_targets;
        let next = (toward(sphere, ts), toward(cuboid, tc));
        if next == (sphere, cuboid) {
            return false;
        }
        self.place_obstacles(next.0, next.1);
        true
    }

    /// Back to the start with no recorded drags or obstacle moves, the obstacles where they are
    /// now (the page also sets its timeline to 0).
    pub fn reset(&mut self) {
        self.forget_interaction();
        self.restart();
    }

    fn forget_interaction(&mut self) {
        self.drags.clear();
        self.dragging = None;
        // The next run starts with the obstacles where the sliders put them.
        self.obstacles_start = self.obstacle_targets;
        self.obstacle_moves.clear();
    }

    fn changed(&mut self) {
        self.dirty = true;
        self.forget_interaction();
    }

    pub fn preset(&self) -> Preset {
        self.preset
    }

    /// Stiffness `k` of one spring kind ("structural", "shear", "bending"), N/m in [0, 5000];
    /// structural in [[`MIN_STRUCTURAL_K`], 5000]. XPBD uses the compliance `α = 1/k`.
    pub fn set_stiffness(&mut self, kind: &str, k: f32) -> Result<(), String> {
        let i = kind_index(kind)?;
        let lo = if i == 0 { MIN_STRUCTURAL_K } else { 0.0 };
        let k = in_range(&format!("{kind} stiffness"), k, lo, MAX_K)?;
        if k != self.params.stiffness[i] {
            self.params.stiffness[i] = k;
            self.params.compliance_from_stiffness();
            self.changed();
        }
        Ok(())
    }

    /// Damping `c` of every spring, N·s/m in [0, 1].
    pub fn set_damping(&mut self, c: f32) -> Result<(), String> {
        let c = in_range("damping", c, 0.0, 1.0)?;
        if [c, c, 0.5 * c] != self.params.damping {
            self.params.damping = [c, c, 0.5 * c];
            self.changed();
        }
        Ok(())
    }

    /// The frame step Δt, milliseconds in [5, 50].
    pub fn set_step_ms(&mut self, ms: f32) -> Result<(), String> {
        let dt = in_range("step", ms, 5.0, 50.0)? / 1000.0;
        if dt != self.frame_dt {
            self.frame_dt = dt;
            self.changed();
        }
        Ok(())
    }

    /// Substeps per frame, a whole number in [1, 40] (a fraction is an error, not rounded).
    pub fn set_substeps(&mut self, n: f32) -> Result<(), String> {
        let n = super::whole_number("substeps", n, 1, 40)? as u32;
        if n != self.params.substeps {
            self.params.substeps = n;
            self.changed();
        }
        Ok(())
    }

    /// Mean wind speed, m/s in [0, 20] (gusts vary it by about ±30 %).
    pub fn set_wind(&mut self, speed: f32) -> Result<(), String> {
        let w = in_range("wind", speed, 0.0, 20.0)?;
        if w != self.wind_speed {
            self.wind_speed = w;
            self.changed();
        }
        Ok(())
    }

    /// "none", "two corners" or "whole edge".
    pub fn set_pins(&mut self, name: &str) -> Result<(), String> {
        let pins = PINS
            .iter()
            .position(|&p| p == name)
            .ok_or_else(|| format!("pins: no choice named {name:?}"))?;
        if pins != self.pins {
            self.pins = pins;
            self.apply_pins();
            self.changed();
        }
        Ok(())
    }

    /// "mass-spring" or "XPBD" (the drape; the flag always shows both).
    pub fn set_method(&mut self, name: &str) -> Result<(), String> {
        let method = match name {
            "mass-spring" => Method::MassSpring,
            "XPBD" => Method::Xpbd,
            _ => return Err(format!("method: no method named {name:?}")),
        };
        if self.preset == Preset::Drape && method != self.method {
            self.method = method;
            self.build();
            self.changed();
        }
        Ok(())
    }

    /// Particles per side, in [4, 100] (the flag has about two thirds as many rows).
    pub fn set_resolution(&mut self, side: f32) -> Result<(), String> {
        let side = super::whole_number("resolution", side, 4, PAGE_MAX_SIDE)?;
        if side != self.side {
            self.side = side;
            self.build();
            self.changed();
        }
        Ok(())
    }

    /// The sphere's centre x and the box's centre x and z, metres in [−1.5, 1.5]. From the
    /// current frame on they head there at [`OBSTACLE_SPEED`], and the cloth runs into them on
    /// the way (and so in every replay). At time 0, or once [`MAX_DRAG_EVENTS`] moves are
    /// recorded, the run starts again with them in their new places.
    pub fn set_obstacles(&mut self, sphere_x: f32, box_x: f32, box_z: f32) -> Result<(), String> {
        let sx = in_range("sphere x", sphere_x, -1.5, 1.5)?;
        let bx = in_range("box x", box_x, -1.5, 1.5)?;
        let bz = in_range("box z", box_z, -1.5, 1.5)?;
        let (mut sphere, mut cuboid) = self.obstacle_targets;
        (sphere.x, cuboid.x, cuboid.z) = (sx, bx, bz);
        if (sphere, cuboid) == self.obstacle_targets {
            return Ok(());
        }
        self.obstacle_targets = (sphere, cuboid);
        let frame = self.frames_done;
        if frame == 0 || self.dirty || self.obstacle_moves.len() >= MAX_DRAG_EVENTS {
            self.place_obstacles(sphere, cuboid);
            self.obstacles_start = (sphere, cuboid);
            self.obstacle_moves.clear();
            self.dirty = true;
        } else {
            match self.obstacle_moves.last_mut() {
                Some(last) if last.0 == frame => (last.1, last.2) = (sphere, cuboid),
                _ => self.obstacle_moves.push((frame, sphere, cuboid)),
            }
            self.obstacle_cursor = self.obstacle_moves.len();
        }
        Ok(())
    }

    /// Coulomb friction μ with the colliders, in [0, 2].
    pub fn set_friction(&mut self, mu: f32) -> Result<(), String> {
        let mu = in_range("friction", mu, 0.0, 2.0)?;
        if mu != self.colliders.friction {
            self.colliders.friction = mu;
            self.changed();
        }
        Ok(())
    }

    /// How many cloths (1 or 2) and, per cloth, its particle count.
    pub fn cloth_count(&self) -> usize {
        self.sims.len()
    }

    /// Whether the meshes must be (re)created: true once after the resolution or method changed.
    pub fn take_structure_changed(&mut self) -> bool {
        std::mem::replace(&mut self.structure_changed, false)
    }

    /// The double-sided mesh of cloth `k` (front faces, then the back faces reversed), for
    /// `Renderer::create_mesh`, and its vertex colours.
    pub fn mesh_data(&self, k: usize) -> (MeshData, Vec<Vec4>) {
        let sim = &self.sims[k];
        let n = sim.cloth.len() as u32;
        let mut indices = Vec::with_capacity(6 * sim.cloth.triangles.len());
        for t in &sim.cloth.triangles {
            indices.extend_from_slice(t);
        }
        for t in &sim.cloth.triangles {
            indices.extend_from_slice(&[t[0] + n, t[2] + n, t[1] + n]);
        }
        (
            MeshData {
                positions: sim.render_positions.clone(),
                normals: sim.render_normals.clone(),
                indices,
            },
            sim.colors.clone(),
        )
    }

    /// Positions, normals and colours of cloth `k` as drawn now (after [`ClothFigure::draw`]).
    pub fn render_buffers(&self, k: usize) -> (&[Vec3], &[Vec3], &[Vec4]) {
        let s = &self.sims[k];
        (&s.render_positions, &s.render_normals, &s.colors)
    }

    /// The wind at time `t`: the mean speed along +x, turned and strengthened by slow gusts
    /// (a fixed function of time, so a replay blows the same).
    pub fn wind_at(&self, t: f32) -> Vec3 {
        let turn = 0.25 + 0.35 * (0.7 * t).sin();
        let gust = 1.0 + 0.3 * (2.1 * t).sin() + 0.15 * (5.3 * t + 1.0).sin();
        self.wind_speed * gust * Vec3::new(turn.cos(), 0.05 * (1.3 * t).sin(), turn.sin())
    }

    fn params_for(&self, method: Method, t: f32) -> ClothParams {
        ClothParams {
            method,
            wind: self.wind_at(t),
            ..self.params
        }
    }

    /// Simulates to `time_sec` (replaying from the start when the time went back or something
    /// changed). Returns the frames taken.
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, String> {
        let t = in_range("time", time_sec, 0.0, DURATION)?;
        let target = (t / self.frame_dt + 1e-3).floor() as usize;
        let replay = self.dirty || target < self.frames_done;
        if replay {
            self.restart();
        }
        let n = target - self.frames_done;
        for _ in 0..n {
            self.step_frame()?;
        }
        self.last_step_frames = if replay { 0 } else { n };
        Ok(n)
    }

    /// How many frames the last draw simulated, going on from the previous one (0 when it
    /// replayed from the start or the time stood still): what a page divides its measured time
    /// by to time one simulated frame, whatever its own frame rate.
    pub fn last_step_frames(&self) -> usize {
        self.last_step_frames
    }

    fn step_frame(&mut self) -> Result<(), String> {
        let frame = self.frames_done;
        while self.drag_cursor < self.drags.len() && self.drags[self.drag_cursor].0 <= frame {
            self.drag_cursor += 1;
        }
        let grab = self
            .drag_cursor
            .checked_sub(1)
            .and_then(|k| self.drags[k].1);
        self.catch_up_obstacles(frame);
        self.obstacles_moving = self.move_obstacles();
        let t = frame as f32 * self.frame_dt;
        for k in 0..self.sims.len() {
            let params = self.params_for(self.sims[k].method, t);
            let sim = &mut self.sims[k];
            if sim.cloth.exploded().is_some() {
                continue;
            }
            sim.cloth.grab = grab.and_then(|(s, i, p)| (s == k).then_some((i, p)));
            sim.cloth
                .step(&params, &self.colliders, self.frame_dt)
                .map_err(|e| e.to_string())?;
            sim.torn = sim.cloth.exploded().is_some() && sim.cloth.grab.is_some();
            sim.pushed = sim.cloth.exploded().is_some() && self.obstacles_moving;
            // A new sample, or an explosion (which changes the plots' ranges).
            self.sample_generation = self.sample_generation.wrapping_add(1);
            if sim.cloth.exploded().is_none() {
                sim.last_good.copy_from_slice(&sim.cloth.positions);
                sim.samples.push([
                    t + self.frame_dt,
                    sim.cloth.energy(&params),
                    100.0 * sim.cloth.max_stretch(),
                ]);
            }
        }
        self.frames_done += 1;
        Ok(())
    }

    /// Plot samples, flat, one row per frame from the start (t = 0): `[t, energy of each cloth
    /// (J)…, max stretch of each (%)…]`; NaN where a cloth had exploded.
    pub fn samples(&self) -> Vec<f32> {
        let rows = self.sims.iter().map(|s| s.samples.len()).max().unwrap_or(0);
        let width = 1 + 2 * self.sims.len();
        let mut out = Vec::with_capacity(rows * width);
        for r in 0..rows {
            out.push(r as f32 * self.frame_dt);
            for column in [1, 2] {
                for s in &self.sims {
                    out.push(s.samples.get(r).map_or(f32::NAN, |x| x[column]));
                }
            }
        }
        out
    }

    /// A number that changes whenever [`ClothFigure::samples`] or [`ClothFigure::plot_ranges`]
    /// may have (a frame simulated, a replay from the start) and stays put otherwise: a page
    /// redraws its plots only when it changes, without copying the samples every frame.
    pub fn sample_generation(&self) -> u32 {
        self.sample_generation
    }

    /// The y ranges of the flag's two plots, `[energy lo, energy hi, stretch lo, stretch hi]`
    /// (J, %): over the samples of the cloths that held, so that one cloth's explosion (its
    /// last samples before it shoot up by orders of magnitude) does not flatten the other's
    /// curves onto a line; the exploded cloth's curve then runs off the plot. Over every cloth
    /// when none has exploded or none held; NaN before the first sample. The stretch range is
    /// at least 1 % tall, from its low end up.
    pub fn plot_ranges(&self) -> [f32; 4] {
        let held = self.held();
        let shown: Vec<&Sim> = if held.is_empty() {
            self.sims.iter().collect()
        } else {
            held
        };
        let mut out = [f32::NAN; 4];
        for (column, range) in [1, 2].into_iter().zip(out.chunks_mut(2)) {
            let values = shown
                .iter()
                .flat_map(|s| s.samples.iter().map(|r| r[column]));
            for x in values.filter(|x| x.is_finite()) {
                // min and max of NaN and x are x: the first finite value replaces the NaN.
                range[0] = range[0].min(x);
                range[1] = range[1].max(x);
            }
        }
        // The stretch axis spans at least 1 % up from its lowest sample: around the first
        // sample alone (0 %) the plot would centre a span reaching down to −0.5 %.
        out[3] = out[3].max(out[2] + 1.0);
        out
    }

    /// The cloths that have not exploded.
    fn held(&self) -> Vec<&Sim> {
        self.sims
            .iter()
            .filter(|s| s.cloth.exploded().is_none())
            .collect()
    }

    /// When cloth `k` exploded (seconds), if it did.
    pub fn exploded(&self, k: usize) -> Option<f32> {
        self.sims.get(k).and_then(|s| s.cloth.exploded())
    }

    /// The positions of cloth `k` (tests).
    pub fn positions(&self, k: usize) -> &[Vec3] {
        &self.sims[k].cloth.positions
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

    /// The free particle nearest to the pointer on screen, within [`GRAB_RADIUS_PX`]:
    /// `(cloth, index)`.
    pub fn pick(&self, x_px: f32, y_px: f32) -> Result<Option<(usize, usize)>, String> {
        let p = Vec2::new(finite("x", x_px)?, finite("y", y_px)?);
        let Some((view_proj, size)) = self.view_proj() else {
            return Ok(None);
        };
        let mut best = None;
        let mut best_d = GRAB_RADIUS_PX;
        for (k, sim) in self.sims.iter().enumerate() {
            if sim.cloth.exploded().is_some() {
                continue;
            }
            for (i, q) in sim.cloth.positions.iter().enumerate() {
                if sim.cloth.is_pinned(i) {
                    continue;
                }
                if let Some(s) = project_to_canvas(view_proj, size, *q) {
                    let d = s.distance(p);
                    if d < best_d {
                        best_d = d;
                        best = Some((k, i));
                    }
                }
            }
        }
        Ok(best)
    }

    /// Starts dragging the particle under the pointer, if any; returns whether one was grabbed.
    pub fn grab(&mut self, x_px: f32, y_px: f32) -> Result<bool, String> {
        let Some((k, i)) = self.pick(x_px, y_px)? else {
            return Ok(false);
        };
        let at = self.sims[k].cloth.positions[i];
        self.dragging = Some((k, i, at));
        self.record(Some((k, i, at)));
        Ok(true)
    }

    /// Moves the dragged particle's target under the pointer, in the plane through it that faces
    /// the camera.
    pub fn drag(&mut self, x_px: f32, y_px: f32) -> Result<(), String> {
        let p = Vec2::new(finite("x", x_px)?, finite("y", y_px)?);
        let (Some((k, i, anchor)), Some((view_proj, size))) = (self.dragging, self.view_proj())
        else {
            return Ok(());
        };
        if let Some(world) = point_on_view_plane(view_proj, size, anchor, p) {
            let world = world.clamp(Vec3::new(-4.0, 0.0, -4.0), Vec3::new(4.0, 4.0, 4.0));
            self.dragging = Some((k, i, world));
            self.record(Some((k, i, world)));
        }
        Ok(())
    }

    /// Lets go of the dragged particle.
    pub fn release(&mut self) {
        if self.dragging.take().is_some() {
            self.record(None);
        }
    }

    fn record(&mut self, grab: Option<Grab>) {
        let frame = self.frames_done;
        let len = self.drags.len();
        match self.drags.last_mut() {
            Some(last) if last.0 == frame => last.1 = grab,
            _ if len < MAX_DRAG_EVENTS => self.drags.push((frame, grab)),
            _ => {}
        }
    }

    /// Simulates to `time_sec`, fills the render buffers and `frame` (`meshes`: one per cloth,
    /// created from [`ClothFigure::mesh_data`]), and returns the note.
    pub fn draw(
        &mut self,
        frame: &mut Frame,
        meshes: &[MeshId],
        time_sec: f32,
    ) -> Result<String, String> {
        self.advance_to(time_sec)?;
        self.catch_up_obstacles(self.frames_done);
        frame.grid(10, 0.5);
        if let Some((c, r)) = self.colliders.sphere {
            let m = Mat4::from_translation(c) * Mat4::from_scale(Vec3::splat(r));
            frame.mesh(MeshId::SPHERE, m, palette::GREY);
            frame.contact_shadow(c - Vec3::Y * r, r);
        }
        if let Some((c, h)) = self.colliders.cuboid {
            frame.mesh(
                MeshId::CUBE,
                Mat4::from_translation(c) * Mat4::from_scale(h),
                palette::PURPLE,
            );
            frame.contact_shadow(c - Vec3::Y * h.y, h.x.max(h.z));
            // Its edges over everything, dashed as hidden edges are: a box under or behind the
            // cloth still shows where it is, and does not read as lying on the cloth.
            let hidden = crate::draw::StrokeStyle {
                on_top: true,
                ..crate::draw::StrokeStyle::dashed(1.5, 0.05, 0.04)
            };
            for (a, b) in super::boids::box_edges(c - h, c + h) {
                frame.stroke(&[a, b], palette::PURPLE, hidden);
            }
        }
        if self.preset == Preset::Drape {
            // Under the cloth, from its lowest point: how high it still is as it falls.
            for sim in &self.sims {
                let (lo, hi) = bounds(&sim.cloth.positions);
                let middle = 0.5 * (lo + hi);
                let radius = 0.5 * (hi.x - lo.x).max(hi.z - lo.z);
                frame.contact_shadow(Vec3::new(middle.x, lo.y.max(0.0), middle.z), radius);
            }
        }
        // An obstacle on its way to where its slider puts it: a line to that point.
        let (sphere, cuboid) = self.obstacles();
        let (to_sphere, to_cuboid) = self.obstacle_targets;
        for (at, to, color) in [
            (sphere, to_sphere, palette::GREY),
            (cuboid, to_cuboid, palette::PURPLE),
        ] {
            if at != to {
                frame.wide_line(at, to, color, GUIDE_PX);
                frame.point(to, 0.03, color);
            }
        }
        let rows_per_band = |rows: usize| (rows / 5).max(1);
        // From a cloth's name label to the label under it, metres. The flag's is centred
        // under the flag, half way from its pole to the next (2.3 m apart): the text is wider
        // than the flag, and starting at the flag's middle it would run across the next pole.
        let below = match self.preset {
            Preset::Flag => Vec3::new(0.4, -1.6, 0.0),
            Preset::Drape => Vec3::new(0.0, -0.2, 0.0),
        };
        let view = self.view_proj();
        for (k, sim) in self.sims.iter_mut().enumerate() {
            let exploded = sim.cloth.exploded().is_some();
            let n = sim.cloth.len();
            let positions = if exploded {
                &sim.last_good
            } else {
                &sim.cloth.positions
            };
            let normals = &sim.cloth.normals;
            let band = rows_per_band(sim.cloth.rows);
            let light = sim.color.lerp(Vec3::ONE, 0.55);
            for i in 0..n {
                let p = positions[i];
                let nrm = if normals[i].is_finite() {
                    normals[i]
                } else {
                    Vec3::Y
                };
                sim.render_positions[i] = p;
                sim.render_positions[i + n] = p;
                sim.render_normals[i] = nrm;
                sim.render_normals[i + n] = -nrm;
                let row = i / sim.cloth.columns;
                let c = if exploded {
                    palette::RED
                } else if (row / band) % 2 == 0 {
                    sim.color
                } else {
                    light
                };
                sim.colors[i] = c.extend(1.0);
                sim.colors[i + n] = c.extend(1.0);
            }
            if let Some(&id) = meshes.get(k) {
                frame.mesh_vertex_colors(id, Mat4::IDENTITY);
            }
            for (i, p) in positions.iter().enumerate() {
                if sim.cloth.is_pinned(i) {
                    frame.marker_on_top(*p, DOT_PX, palette::DARK);
                }
            }
            if self.preset == Preset::Flag {
                let foot = Vec3::new(sim.cloth.positions[0].x - 0.02, 0.0, 0.0);
                let m = Mat4::from_scale_rotation_translation(
                    Vec3::new(0.02, 1.3, 0.02),
                    Quat::IDENTITY,
                    foot + Vec3::new(0.0, 1.3, 0.0),
                );
                frame.mesh(MeshId::CUBE, m, palette::BROWN);
            }
            let name = sim.method.name();
            match sim.cloth.exploded() {
                // The name stays where it was, in red, and what happened goes under the cloth: one
                // long label above each flag would run into the other flag's.
                Some(t) => {
                    frame.label(sim.label, name, palette::RED);
                    let said = format!(
                        "{} at {} s",
                        if sim.torn {
                            "torn by the drag"
                        } else {
                            "exploded"
                        },
                        format_number(t)
                    );
                    let at = sim.label + below;
                    if self.preset == Preset::Flag {
                        frame.label_off_dot(at, 0.0, Vec2::ZERO, said, palette::RED, 0);
                    } else {
                        frame.label(at, said, palette::RED);
                    }
                }
                // The drape's name just above the cloth's topmost point on screen (its highest
                // without a view), wherever the cloth has fallen to.
                None if self.preset == Preset::Drape => {
                    let top = |p: &Vec3| match view {
                        Some((view_proj, size)) => {
                            project_to_canvas(view_proj, size, *p).map_or(f32::INFINITY, |s| s.y)
                        }
                        None => -p.y,
                    };
                    let at = sim
                        .cloth
                        .positions
                        .iter()
                        .min_by(|a, b| top(a).total_cmp(&top(b)))
                        .copied()
                        .unwrap_or(sim.label);
                    let up = Vec2::new(0.0, -1.0);
                    frame.label_off_dot(at, 0.0, up, name, sim.color, 0);
                }
                None => frame.label(sim.label, name, sim.color),
            }
        }
        if let Some((k, i, target)) = self.dragging {
            if let Some(sim) = self.sims.get(k) {
                let p = sim.cloth.positions[i];
                frame.wide_line(p, target, palette::PINK, GUIDE_PX);
                frame.point(target, 0.03, palette::PINK);
            }
        }
        let (lo, hi) = self.view_box();
        frame.keep_box_in_view(lo, hi);
        Ok(self.note())
    }

    /// The box the camera keeps in view ([`Frame::keep_in_view`]). The flags': the poles and
    /// where the flags fly. The drape's: [`DRAPE_VIEW`] (the cloth from its start to where it
    /// lies over the sphere, and its label), grown to hold the obstacles where they are and
    /// where their sliders send them, and the cloth wherever it is. The camera holds still while
    /// the cloth falls and drapes, and re-fits when a slider moves an obstacle or the cloth
    /// is pushed past that.
    pub fn view_box(&self) -> (Vec3, Vec3) {
        match self.preset {
            Preset::Flag => (Vec3::new(-2.05, 0.0, -1.2), Vec3::new(2.05, 2.8, 1.2)),
            Preset::Drape => {
                let (mut lo, mut hi) = DRAPE_VIEW;
                let (sphere, cuboid) = self.obstacles();
                let (to_sphere, to_cuboid) = self.obstacle_targets;
                if let Some((_, r)) = self.colliders.sphere {
                    for c in [sphere, to_sphere] {
                        (lo, hi) = (lo.min(c - r), hi.max(c + r));
                    }
                }
                if let Some((_, h)) = self.colliders.cuboid {
                    for c in [cuboid, to_cuboid] {
                        (lo, hi) = (lo.min(c - h), hi.max(c + h));
                    }
                }
                for sim in &self.sims {
                    let (a, b) = bounds(&sim.cloth.positions);
                    (lo, hi) = (lo.min(a), hi.max(b));
                }
                (
                    lo.max(Vec3::new(-4.0, -0.05, -4.0)),
                    hi.min(Vec3::splat(4.0)),
                )
            }
        }
    }

    /// A conservative stable substep for the mass-spring cloth, seconds.
    pub fn stable_substep(&self) -> f32 {
        self.sims[0].cloth.stable_substep_estimate(&self.params)
    }

    /// A measurement of the substeps this figure's mass-spring cloth needs against its structural
    /// stiffness (at [`SUBSTEP_PLOT_K`], every other setting as it is now), to be run a bounded
    /// amount of work at a time with [`SubstepSearch::work`] so a page stays responsive.
    pub fn substep_search(&self) -> Result<SubstepSearch, String> {
        let mut probe = self.clone();
        probe.forget_interaction();
        probe.sims.retain(|s| s.method == Method::MassSpring);
        if probe.sims.is_empty() {
            return Err("this figure has no mass-spring cloth to measure".into());
        }
        Ok(SubstepSearch {
            probe,
            results: Vec::with_capacity(SUBSTEP_PLOT_K.len()),
            lo: 0,
            hi: MAX_SEARCH_SUBSTEPS + 1,
            frame: None,
        })
    }

    /// The whole measurement at once: [`SubstepSearch::rows`] of a finished search.
    pub fn substeps_plot(&self) -> Result<Vec<f32>, String> {
        let mut search = self.substep_search()?;
        while !search.work(usize::MAX)? {}
        Ok(search.rows())
    }

    /// The substep h, seconds.
    pub fn substep(&self) -> f32 {
        self.frame_dt / self.params.substeps as f32
    }

    fn note(&self) -> String {
        let h = self.substep();
        let limit = self.stable_substep();
        let ms = |s: f32| format_number(1000.0 * s);
        let mut parts = Vec::new();
        let c = &self.sims[0].cloth;
        parts.push(format!(
            "{} × {} particles, {} springs per cloth; substep h = Δt / {} = {} ms.",
            c.columns,
            c.rows,
            c.springs.len(),
            self.params.substeps,
            ms(h),
        ));
        let any_spring = self.sims.iter().any(|s| s.method == Method::MassSpring);
        if any_spring {
            // A mass-spring cloth that exploded below the limit did so for another reason (soft
            // springs under load, said below): "stable" would read as a contradiction there.
            let exploded = self
                .sims
                .iter()
                .any(|s| s.method == Method::MassSpring && s.cloth.exploded().is_some());
            let verdict = if h <= limit && exploded {
                "below it: the step is within the limit"
            } else if h <= limit {
                "below it: the step is stable"
            } else if h <= 2.0 * limit {
                // The estimate is a sufficient condition only: above it a cloth may survive (the
                // flag at 2,000 N/m with 18 substeps) or explode (the drape at 40 × 40).
                "above it: no guarantee, it may explode"
            } else {
                "far above it: expect an explosion"
            };
            parts.push(format!(
                "Mass-spring stability estimate √(2m/Σk) = {} ms; h is {verdict}.",
                ms(limit)
            ));
        }
        for sim in &self.sims {
            let name = sim.method.name();
            match sim.cloth.exploded() {
                Some(t) if sim.torn => parts.push(format!(
                    "The {name} cloth was torn apart by the drag at t = {} s: the held particle \
                     follows the pointer whatever the springs say, and pulled a spring past {} × \
                     its rest length (not the step's fault). Drag less far from the pins, or \
                     press reset.",
                    format_number(t),
                    format_number(crate::cloth::EXPLODED_STRETCH),
                )),
                Some(t) => parts.push(format!(
                    "The {name} cloth exploded at t = {} s (a spring passed {} × its rest length){} \
                     {}",
                    format_number(t),
                    format_number(crate::cloth::EXPLODED_STRETCH),
                    if sim.pushed {
                        ", while the sphere or the box was moving through it: the collision \
                         pushed particles out faster than the springs could follow."
                    } else {
                        "."
                    },
                    // What this figure's controls can do about it; any change starts the run
                    // again (the flag's reset would also bring back every default).
                    match (self.preset, sim.method) {
                        (Preset::Flag, m) => self.flag_advice(m, h > limit),
                        (Preset::Drape, Method::MassSpring) => "Choose fewer particles per side \
                                                                (heavier particles) or XPBD."
                            .into(),
                        (Preset::Drape, Method::Xpbd) => "XPBD's projections cannot overshoot, \
                                                          so the step is not the cause: press \
                                                          reset."
                            .into(),
                    },
                )),
                None => {
                    if let Some(last) = sim.samples.last() {
                        parts.push(format!(
                            "{name}: max stretch {} %, energy {} J.",
                            format_number(last[2]),
                            format_number(last[1]),
                        ));
                        if last[2] > SOFT_STRETCH_PERCENT && self.preset == Preset::Flag {
                            parts.push(format!(
                                "Past {SOFT_STRETCH_PERCENT} %, the {name} flag's springs are \
                                 too soft for this load, whatever the step. {}",
                                self.flag_load_advice()
                            ));
                        }
                    }
                }
            }
        }
        let held = self.held();
        if !held.is_empty() && held.len() < self.sims.len() {
            parts.push(format!(
                "The plots' scales follow the {} cloth that held: the exploded one's curves run \
                 off them.",
                held[0].method.name()
            ));
        }
        if self.preset == Preset::Drape {
            parts.push(format!(
                "Friction μ = {} with the sphere, the box and the ground. No self-collision: the \
                 cloth can pass through itself.",
                format_number(self.colliders.friction)
            ));
        }
        parts.join(" ")
    }
}

impl ClothFigure {
    /// What the flag's controls can do about an explosion of the `method` flag, naming only
    /// settings that can still move that way. A mass-spring substep above the estimate
    /// (`above_limit`) calls for a smaller substep or softer springs; below it the step is not
    /// the cause and the springs are too soft for the load. An XPBD correction never overshoots,
    /// but one pass over the springs per substep can fall behind the load (at a 50 ms frame step
    /// with one substep the flag tears apart at any stiffness): more substeps first, then a
    /// stiffer flag or a lighter load.
    fn flag_advice(&self, method: Method, above_limit: bool) -> String {
        if method == Method::Xpbd {
            let mut moves = Vec::new();
            if self.params.substeps < MAX_SEARCH_SUBSTEPS {
                moves.push("raise the substeps");
            }
            if self.frame_dt > 0.005 {
                moves.push("lower the frame step");
            }
            moves.extend(self.flag_load_moves());
            return format!(
                "XPBD's corrections never overshoot, but one pass over the springs a substep \
                 fell behind this load. {}",
                if moves.is_empty() {
                    String::from("Press reset.")
                } else {
                    format!("{}.", capitalised_or(&moves))
                }
            );
        }
        if !above_limit {
            return format!(
                "The substep h is below the estimate, so the step is not the cause: the springs \
                 are too soft for this load. {}",
                self.flag_load_advice()
            );
        }
        let mut moves = Vec::new();
        let k = self.params.stiffness;
        if k[0] > MIN_STRUCTURAL_K || k[1] > 0.0 || k[2] > 0.0 {
            moves.push("lower the stiffness");
        }
        if self.frame_dt > 0.005 {
            moves.push("lower the frame step");
        }
        if self.params.substeps < MAX_SEARCH_SUBSTEPS {
            moves.push("raise the substeps");
        }
        if moves.is_empty() {
            return "Press reset.".into();
        }
        format!(
            "{}: the run starts again by itself.",
            capitalised_or(&moves)
        )
    }

    /// How to stiffen the flag against its load, naming only settings not at their ends.
    fn flag_load_advice(&self) -> String {
        let moves = self.flag_load_moves();
        if moves.is_empty() {
            return "Press reset.".into();
        }
        format!("{}.", capitalised_or(&moves))
    }

    /// The moves of [`Self::flag_load_advice`].
    fn flag_load_moves(&self) -> Vec<&'static str> {
        let mut moves = Vec::new();
        if self.params.stiffness[0] < MAX_K {
            moves.push("raise the structural stiffness");
        }
        if self.wind_speed > 0.0 {
            moves.push("lower the wind");
        }
        if self.pins != PINS.len() - 1 {
            moves.push("pin the whole edge");
        }
        moves
    }
}

/// "A, b or c", from ["a", "b", "c"].
fn capitalised_or(moves: &[&str]) -> String {
    let mut s = match moves.split_last() {
        Some((last, [])) => last.to_string(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    };
    // ASCII only: the moves are English words, and `to_uppercase` would bring Unicode's tables.
    if let Some(c) = s.get_mut(0..1) {
        c.make_ascii_uppercase();
    }
    s
}

fn kind_index(kind: &str) -> Result<usize, String> {
    SpringKind::ALL
        .iter()
        .position(|k| k.name() == kind)
        .ok_or_else(|| format!("no spring kind named {kind:?} (structural, shear, bending)"))
}

// ---------------------------------------------------------------------------------------------
// One spring, one constraint.

/// The most substeps a [`SubstepSearch`] tries: the substeps slider's end.
pub const MAX_SEARCH_SUBSTEPS: u32 = 40;

/// The fewest substeps (1 to [`MAX_SEARCH_SUBSTEPS`]) with which a mass-spring cloth runs the
/// whole [`DURATION`] without exploding, found for each stiffness of [`SUBSTEP_PLOT_K`] by a binary
/// search over fresh runs of a copy of the figure (drags and obstacle moves left out). The search
/// assumes that a smaller substep never makes the step less stable; the tests check the counts
/// around each answer.
#[derive(Clone, Debug)]
pub struct SubstepSearch {
    /// The figure's copy, with its mass-spring cloth only.
    probe: ClothFigure,
    /// The answers so far, in the order of [`SUBSTEP_PLOT_K`] (`None`: more than the maximum).
    results: Vec<Option<u32>>,
    /// The current stiffness's bracket: `lo` substeps explode (or `lo` is 0), `hi` hold (or `hi`
    /// is past the maximum).
    lo: u32,
    hi: u32,
    /// The frame the run being tried has reached, `None` before it starts.
    frame: Option<usize>,
}

impl SubstepSearch {
    /// Simulates at most `max_frames` frames of the runs the search needs; true when every
    /// stiffness has its answer.
    pub fn work(&mut self, max_frames: usize) -> Result<bool, String> {
        let frames = (DURATION / self.probe.frame_dt + 1e-3).floor() as usize;
        let mut budget = max_frames;
        while self.results.len() < SUBSTEP_PLOT_K.len() {
            let trying = (self.lo + self.hi) / 2;
            let frame = match self.frame {
                Some(f) => f,
                None => {
                    self.probe.params.stiffness[0] = SUBSTEP_PLOT_K[self.results.len()];
                    self.probe.params.compliance_from_stiffness();
                    self.probe.params.substeps = trying;
                    self.probe.restart();
                    0
                }
            };
            let mut f = frame;
            let mut exploded = false;
            while f < frames && budget > 0 {
                self.probe.step_frame()?;
                f += 1;
                budget -= 1;
                if self.probe.sims[0].cloth.exploded().is_some() {
                    exploded = true;
                    break;
                }
            }
            if !exploded && f < frames {
                self.frame = Some(f);
                return Ok(false);
            }
            self.frame = None;
            if exploded {
                self.lo = trying;
            } else {
                self.hi = trying;
            }
            if self.hi - self.lo <= 1 {
                self.results
                    .push((self.hi <= MAX_SEARCH_SUBSTEPS).then_some(self.hi));
                self.lo = 0;
                self.hi = MAX_SEARCH_SUBSTEPS + 1;
            }
            if budget == 0 {
                return Ok(self.results.len() == SUBSTEP_PLOT_K.len());
            }
        }
        Ok(true)
    }

    /// How many stiffnesses have their answer.
    pub fn done(&self) -> usize {
        self.results.len()
    }

    /// Flat rows of `[k (N/m), measured fewest substeps (NaN past the maximum or not yet
    /// measured), c·√k fitted to the measured points by least squares, ⌈Δt / h_limit⌉ from the
    /// conservative limit (NaN past the maximum)]`, one per stiffness of [`SUBSTEP_PLOT_K`].
    pub fn rows(&self) -> Vec<f32> {
        let measured = |i: usize| self.results.get(i).copied().flatten();
        // Least squares for n = c·√k: c = Σ n√k / Σ k over the measured points.
        let (num, den) = (0..SUBSTEP_PLOT_K.len())
            .filter_map(|i| {
                measured(i).map(|n| (n as f32 * SUBSTEP_PLOT_K[i].sqrt(), SUBSTEP_PLOT_K[i]))
            })
            .fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
        let c = if den > 0.0 { num / den } else { f32::NAN };
        let cloth = &self.probe.sims[0].cloth;
        let mut rows = Vec::with_capacity(4 * SUBSTEP_PLOT_K.len());
        for (i, &k) in SUBSTEP_PLOT_K.iter().enumerate() {
            let mut p = self.probe.params;
            p.stiffness[0] = k;
            let conservative = (self.probe.frame_dt / cloth.stable_substep_estimate(&p)).ceil();
            rows.extend([
                k,
                measured(i).map_or(f32::NAN, |n| n as f32),
                c * k.sqrt(),
                if conservative <= MAX_SEARCH_SUBSTEPS as f32 {
                    conservative
                } else {
                    f32::NAN
                },
            ]);
        }
        rows
    }
}

/// Mass of the swinging particles, kg.
pub const SPRING_MASS: f32 = 0.05;
/// Rest length, metres.
pub const SPRING_REST: f32 = 0.8;
/// How long the figure simulates, seconds.
pub const SPRING_DURATION: f32 = 6.0;
const ANCHORS: [Vec3; 2] = [Vec3::new(-0.9, 2.3, 0.0), Vec3::new(0.9, 2.3, 0.0)];
const START_OFFSET: Vec3 = Vec3::new(0.7, -0.9, 0.0);
/// What the spring figure keeps in view: both anchors and the particles' swings below them.
pub const SPRING_VIEW: (Vec3, Vec3) = (Vec3::new(-2.2, 1.0, -0.3), Vec3::new(2.2, 2.6, 0.3));
const GRAVITY: Vec3 = Vec3::new(0.0, -9.81, 0.0);

/// A particle hanging from a damped spring (integrated with semi-implicit Euler) beside one
/// hanging from an XPBD distance constraint of compliance `α = 1/k`, both released from the same
/// stretched, sideways start.
#[derive(Clone, Debug)]
pub struct SpringFigure {
    k: f32,
    c: f32,
    dt: f32,
    use_exercise: bool,
    runner: Runner,
    /// Positions after 0, 1, 2, … steps: [mass-spring, XPBD].
    paths: [Vec<Vec3>; 2],
    /// The step at which the mass-spring particle flew off (more than 4 m from its anchor, or not
    /// finite).
    exploded_at: Option<usize>,
    /// Its distance from its anchor at that step (m; NaN if it held or the distance is not
    /// finite): its plotted curve ends there.
    flew_m: f32,
}

impl Default for SpringFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl SpringFigure {
    pub fn new() -> Self {
        let mut f = Self {
            k: 40.0,
            c: 0.05,
            dt: 1.0 / 60.0,
            use_exercise: false,
            runner: DEFAULT_RUNNER,
            paths: Default::default(),
            exploded_at: None,
            flew_m: f32::NAN,
        };
        f.integrate();
        f
    }

    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.integrate();
    }

    /// Runs the student's 13.1 and 13.2 (left) and 13.3 (right).
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.integrate();
    }

    /// Stiffness k, N/m in [1, 400].
    pub fn set_stiffness(&mut self, k: f32) -> Result<(), String> {
        self.k = in_range("stiffness k", k, 1.0, 400.0)?;
        self.integrate();
        Ok(())
    }

    /// Damping c, N·s/m in [0, 1].
    pub fn set_damping(&mut self, c: f32) -> Result<(), String> {
        self.c = in_range("damping c", c, 0.0, 1.0)?;
        self.integrate();
        Ok(())
    }

    /// Step, milliseconds in [2, 80].
    pub fn set_step_ms(&mut self, ms: f32) -> Result<(), String> {
        self.dt = in_range("step", ms, 2.0, 80.0)? / 1000.0;
        self.integrate();
        Ok(())
    }

    /// `ω h` with `ω = √(k/m)`: semi-implicit Euler on an undamped spring is stable below 2.
    pub fn omega_h(&self) -> f32 {
        (self.k / SPRING_MASS).sqrt() * self.dt
    }

    pub fn exploded_at_sec(&self) -> Option<f32> {
        self.exploded_at.map(|s| s as f32 * self.dt)
    }

    fn steps(&self) -> usize {
        (SPRING_DURATION / self.dt).ceil() as usize
    }

    fn integrate(&mut self) {
        let steps = self.steps();
        let w = 1.0 / SPRING_MASS;
        let h = self.dt;
        (self.exploded_at, self.flew_m) = (None, f32::NAN);
        let student = self.use_exercise;
        let mut failed = [false; 3];
        // Left: forces and semi-implicit Euler.
        let anchor = ANCHORS[0];
        let (mut p, mut v) = (anchor + START_OFFSET, Vec3::ZERO);
        let path = &mut self.paths[0];
        path.clear();
        path.push(p);
        for step in 0..steps {
            let reference_f =
                -crate::cloth::spring_force(anchor, p, Vec3::ZERO, v, self.k, self.c, SPRING_REST);
            let mut f = reference_f;
            if student && !failed[0] {
                match run::spring_force(
                    self.runner,
                    anchor,
                    p,
                    Vec3::ZERO,
                    v,
                    self.k,
                    self.c,
                    SPRING_REST,
                ) {
                    Ok(x) if x.is_finite() => f = -x,
                    Ok(_) => failed[0] = true,
                    // Said by the note's comparison; the reference goes on.
                    Err(_) => failed[0] = true,
                }
            }
            let force = f + GRAVITY * SPRING_MASS;
            let (mut q, mut u) = (p, v);
            crate::cloth::particle_step(&mut q, &mut u, force, w, h);
            if student && !failed[1] {
                match run::cloth_euler_step(self.runner, p, v, force, w, h) {
                    Ok((a, b)) if a.is_finite() && b.is_finite() => (q, u) = (a, b),
                    Ok(_) => failed[1] = true,
                    // Said by the note's comparison; the reference goes on.
                    Err(_) => failed[1] = true,
                }
            }
            (p, v) = (q, u);
            if !p.is_finite() || (p - anchor).length() > 4.0 {
                self.exploded_at = Some(step + 1);
                self.flew_m = (p - anchor).length();
                break;
            }
            path.push(p);
        }
        // Right: XPBD, compliance 1/k.
        let anchor = ANCHORS[1];
        let alpha = 1.0 / self.k;
        let (mut p, mut v) = (anchor + START_OFFSET, Vec3::ZERO);
        let path = &mut self.paths[1];
        path.clear();
        path.push(p);
        for _ in 0..steps {
            let previous = p;
            v += GRAVITY * h;
            p += v * h;
            let (mut a, mut b) = (anchor, p);
            crate::cloth::project_distance(&mut a, &mut b, 0.0, w, SPRING_REST, alpha, h);
            if student && !failed[2] {
                match run::project_distance(self.runner, anchor, p, 0.0, w, SPRING_REST, alpha, h) {
                    Ok((_, y)) if y.is_finite() => b = y,
                    Ok(_) => failed[2] = true,
                    // Said by the note's comparison; the reference goes on.
                    Err(_) => failed[2] = true,
                }
            }
            p = b;
            v = (p - previous) / h;
            // The same damping along the constraint, implicit (stable for any c).
            let n = (p - anchor).normalize_or_zero();
            let dv = v.dot(n);
            v -= n * dv * (self.c * h * w) / (1.0 + self.c * h * w);
            path.push(p);
        }
    }

    /// Plot samples, flat: `[t, length mass-spring (m), length XPBD (m)]` per step (the
    /// mass-spring's curve ends at its explosion, past 4 m; NaN after it).
    pub fn length_samples(&self) -> Vec<f32> {
        let n = self.paths[1].len();
        let mut out = Vec::with_capacity(3 * n);
        for s in 0..n {
            out.push(s as f32 * self.dt);
            for (k, path) in self.paths.iter().enumerate() {
                let flew = if k == 0 && self.exploded_at == Some(s) {
                    self.flew_m
                } else {
                    f32::NAN
                };
                out.push(path.get(s).map_or(flew, |p| (*p - ANCHORS[k]).length()));
            }
        }
        out
    }

    /// Draws the two at `time_sec` and returns the note.
    pub fn draw(&self, frame: &mut Frame, time_sec: f32) -> Result<String, String> {
        let t = in_range("time", time_sec, 0.0, 1e6)?.min(SPRING_DURATION);
        frame.grid(8, 0.5);
        let s = (t / self.dt + 1e-3).floor() as usize;
        let colors = [palette::ORANGE, palette::TEAL];
        let names = ["mass-spring", "XPBD"];
        for k in 0..2 {
            let path = &self.paths[k];
            let anchor = ANCHORS[k];
            frame.point(anchor, 0.045, palette::DARK);
            let gone = k == 0 && self.exploded_at.is_some() && s >= path.len();
            let p = path[s.min(path.len() - 1)];
            let trail_start = s.min(path.len() - 1).saturating_sub(40);
            frame.wide_polyline(
                &path[trail_start..=s.min(path.len() - 1)],
                colors[k].lerp(Vec3::ONE, 0.5),
                crate::draw::CURVE_PX,
            );
            if gone {
                frame.label(
                    anchor + Vec3::new(0.0, -0.6, 0.0),
                    format!(
                        "exploded at {} s",
                        format_number(self.exploded_at_sec().unwrap_or(0.0))
                    ),
                    palette::RED,
                );
            } else {
                frame.wide_line(anchor, p, colors[k], SPRING_PX);
                frame.mesh(
                    MeshId::SPHERE,
                    Mat4::from_translation(p) * Mat4::from_scale(Vec3::splat(0.07)),
                    colors[k],
                );
            }
            frame.label(anchor + Vec3::new(0.0, 0.2, 0.0), names[k], colors[k]);
        }
        // A fixed box around both swings (a particle that flies off leaves it: the box does not
        // chase it), so the camera holds still.
        frame.keep_box_in_view(SPRING_VIEW.0, SPRING_VIEW.1);
        let oh = self.omega_h();
        let mut note = format!(
            "k = {} N/m, m = {} kg: ω = √(k/m) = {} rad/s, and with h = {} ms, ω h = {} \
             (semi-implicit Euler needs ω h < 2 without damping; here h must stay under {} ms).",
            format_number(self.k),
            format_number(SPRING_MASS),
            format_number((self.k / SPRING_MASS).sqrt()),
            format_number(1000.0 * self.dt),
            format_number(oh),
            format_number(2000.0 / (self.k / SPRING_MASS).sqrt()),
        );
        if let Some(t) = self.exploded_at_sec() {
            note.push_str(&format!(
                " The mass-spring particle{} flew off at t = {} s; XPBD (α = 1/k) stays bounded.",
                if self.use_exercise {
                    " (moved by your 13.1 and 13.2 where they answer)"
                } else {
                    ""
                },
                format_number(t)
            ));
        }
        if self.use_exercise {
            note.push(' ');
            note.push_str(&self.exercise_note());
        }
        Ok(note)
    }

    /// Compares the student's three functions with the reference at the start state.
    pub fn exercise_note(&self) -> String {
        // Each exercise on its own: a failure (not done, a panic) is said by its comparison.
        let (anchor, p) = (ANCHORS[0], ANCHORS[0] + START_OFFSET);
        let v = Vec3::new(0.3, -0.2, 0.0);
        let mut notes = Vec::new();
        // The stubs among the three, said in one sentence (first) instead of one each.
        let mut not_done = Vec::new();
        let at = "the start (p = anchor + (0.7, −0.9, 0), v = (0.3, −0.2, 0))";
        match run::spring_force(
            self.runner,
            anchor,
            p,
            Vec3::ZERO,
            v,
            self.k,
            self.c,
            SPRING_REST,
        ) {
            Err(Failure::NotDone) => not_done.push("exercise 13.1 spring_force"),
            Err(f) => notes.push(failure_note("exercise 13.1 spring_force", FILE, &f)),
            Ok(f) => {
                let r = crate::cloth::spring_force(
                    anchor,
                    p,
                    Vec3::ZERO,
                    v,
                    self.k,
                    self.c,
                    SPRING_REST,
                );
                notes.push(
                    compare_note(
                        "spring_force",
                        at,
                        &f.to_array(),
                        &r.to_array(),
                        1e-3 * (1.0 + r.length()),
                    )
                    .1,
                );
            }
        }
        let force = Vec3::new(1.0, -2.0, 0.5);
        let w = 1.0 / SPRING_MASS;
        match run::cloth_euler_step(self.runner, p, v, force, w, self.dt) {
            Err(Failure::NotDone) => not_done.push("exercise 13.2 cloth_euler_step"),
            Err(f) => notes.push(failure_note("exercise 13.2 cloth_euler_step", FILE, &f)),
            Ok((q, u)) => {
                let (mut rq, mut ru) = (p, v);
                crate::cloth::particle_step(&mut rq, &mut ru, force, w, self.dt);
                notes.push(
                    compare_note(
                        "cloth_euler_step",
                        "the start with f = (1, −2, 0.5) N",
                        &[q.to_array(), u.to_array()].concat(),
                        &[rq.to_array(), ru.to_array()].concat(),
                        1e-4,
                    )
                    .1,
                );
            }
        }
        let alpha = 1.0 / self.k;
        match run::project_distance(
            self.runner,
            ANCHORS[1],
            ANCHORS[1] + START_OFFSET,
            0.0,
            w,
            SPRING_REST,
            alpha,
            self.dt,
        ) {
            Err(Failure::NotDone) => not_done.push("exercise 13.3 project_distance"),
            Err(f) => notes.push(failure_note("exercise 13.3 project_distance", FILE, &f)),
            Ok((a, b)) => {
                let (mut ra, mut rb) = (ANCHORS[1], ANCHORS[1] + START_OFFSET);
                crate::cloth::project_distance(
                    &mut ra,
                    &mut rb,
                    0.0,
                    w,
                    SPRING_REST,
                    alpha,
                    self.dt,
                );
                notes.push(
                    compare_note(
                        "project_distance",
                        "the start (anchor pinned, α = 1/k)",
                        &[a.to_array(), b.to_array()].concat(),
                        &[ra.to_array(), rb.to_array()].concat(),
                        1e-4,
                    )
                    .1,
                );
            }
        }
        notes.insert(0, not_done_note(&not_done, FILE));
        notes.push(self.probe_note());
        notes.retain(|n| !n.is_empty());
        notes.join(" ")
    }

    /// Checks the student's three functions at inputs the figure's start never
    /// reaches (a compressed spring, damping alone, a pinned particle, a rigid constraint, …)
    /// and names those where an answer differs; failures are said by the start comparisons.
    fn probe_note(&self) -> String {
        let close = |a: &[f32], b: &[f32], tolerance: f32| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tolerance)
        };
        let w = 1.0 / SPRING_MASS;
        // Probes asked, and answered (a stub or a panic answers none: the start comparison says
        // so already).
        let mut total = 0;
        let mut answered = 0;
        let mut differing: Vec<String> = Vec::new();
        let force_probes: [(&str, [Vec3; 4], [f32; 3]); 3] = [
            (
                "a compressed spring (ℓ < ℓ₀)",
                [Vec3::ZERO, Vec3::new(0.5, 0.0, 0.0), Vec3::ZERO, Vec3::ZERO],
                [40.0, 0.0, 0.8],
            ),
            (
                "damping alone (ℓ = ℓ₀, b moving away)",
                [
                    Vec3::ZERO,
                    Vec3::new(0.8, 0.0, 0.0),
                    Vec3::ZERO,
                    Vec3::new(1.0, 0.5, 0.0),
                ],
                [40.0, 0.3, 0.8],
            ),
            (
                "a stretched spring along −y with both ends moving",
                [
                    Vec3::Y,
                    Vec3::ZERO,
                    Vec3::new(0.0, 0.4, 0.0),
                    Vec3::new(0.2, -0.3, 0.0),
                ],
                [25.0, 0.2, 0.5],
            ),
        ];
        for (name, [pa, pb, va, vb], [k, c, rest]) in force_probes {
            total += 1;
            if let Ok(f) = run::spring_force(self.runner, pa, pb, va, vb, k, c, rest) {
                answered += 1;
                let r = crate::cloth::spring_force(pa, pb, va, vb, k, c, rest);
                if !close(&f.to_array(), &r.to_array(), 1e-3 * (1.0 + r.length())) {
                    differing.push(format!("spring_force at {name}"));
                }
            }
        }
        let (p, v, f) = (
            Vec3::new(0.1, 1.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, -2.0, 1.0),
        );
        let step_probes: [(&str, f32, f32); 3] = [
            ("a pinned particle (w = 0)", 0.0, 0.02),
            ("a zero step (dt = 0)", w, 0.0),
            ("a long step (dt = 0.1 s)", w, 0.1),
        ];
        for (name, w, dt) in step_probes {
            total += 1;
            if let Ok((q, u)) = run::cloth_euler_step(self.runner, p, v, f, w, dt) {
                answered += 1;
                let (mut rq, mut ru) = (p, v);
                crate::cloth::particle_step(&mut rq, &mut ru, f, w, dt);
                if !close(
                    &[q.to_array(), u.to_array()].concat(),
                    &[rq.to_array(), ru.to_array()].concat(),
                    1e-4,
                ) {
                    differing.push(format!("cloth_euler_step at {name}"));
                }
            }
        }
        let (a, b) = (Vec3::ZERO, Vec3::new(1.0, 0.5, 0.0));
        let project_probes: [(&str, f32, f32, f32, f32); 4] = [
            ("both ends free and equal (wa = wb)", w, w, 0.8, 1.0 / 40.0),
            ("a rigid constraint (α = 0)", w, w, 0.8, 0.0),
            (
                "a compressed constraint (ℓ < ℓ₀)",
                w,
                2.0 * w,
                1.5,
                1.0 / 40.0,
            ),
            ("b pinned (wb = 0)", w, 0.0, 0.8, 0.0),
        ];
        for (name, wa, wb, rest, alpha) in project_probes {
            total += 1;
            if let Ok((x, y)) =
                run::project_distance(self.runner, a, b, wa, wb, rest, alpha, self.dt)
            {
                answered += 1;
                let (mut ra, mut rb) = (a, b);
                crate::cloth::project_distance(&mut ra, &mut rb, wa, wb, rest, alpha, self.dt);
                if !close(
                    &[x.to_array(), y.to_array()].concat(),
                    &[ra.to_array(), rb.to_array()].concat(),
                    1e-4,
                ) {
                    differing.push(format!("project_distance at {name}"));
                }
            }
        }
        if answered == 0 {
            String::new()
        } else if differing.is_empty() {
            format!(
                "At {answered} of {total} probe inputs beyond the start (compressed, pinned, rigid, \
                 zero step, …) your answers match too{}.",
                if answered < total {
                    " (the others are exercises not done yet)"
                } else {
                    ""
                }
            )
        } else {
            format!(
                "Of {total} probe inputs beyond the start, yours differ at: {}.",
                differing.join("; ")
            )
        }
    }
}
