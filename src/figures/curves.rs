//! Figures of lesson 02, "Keyframes and splines" (native logic; `web/curves.rs` wraps it).
//!
//! [`KeyframesScene`] holds the keys the curve editor edits, a path in a plane: keys
//! `(t_i, x_i, y_i)`, a [`Track<Vec2>`]. The 3D view shows the same path in the world's XY plane
//! (z = 0, Y up), so what the student drags in 2D is what the ball follows in 3D. Everything the
//! page draws or plots is sampled here; JavaScript never interpolates.
//!
//! Time: the scene's clock `τ` runs from 0 at the first key to `duration + HOLD_SEC`; the
//! motion holds the last key for [`HOLD_SEC`] before it loops, so every key, the last one
//! included, is seen (a step motion would otherwise never show its last key).

use super::{check_samples, compare_note, failure_note, finite, format_number, in_range, palette};
use super::{Failure, Frame, MeshId, Runner, DEFAULT_RUNNER};
use crate::curves::{
    self, ArcLengthTable, Ease, Interpolation, Sample, TimeWarp, Track, MAX_LAGRANGE_KEYS,
};
use crate::exercises::run;
use crate::Valid;
use glam::{Mat4, Vec2, Vec3};

/// The path, blue in the text.
pub const PATH_COLOR: Vec3 = palette::BLUE;
/// Keys, orange.
pub const KEY_COLOR: Vec3 = palette::ORANGE;
/// In-betweens (the ghost trail), grey.
pub const GHOST_COLOR: Vec3 = palette::GREY;
/// The ball, red.
pub const BALL_COLOR: Vec3 = palette::RED;
/// Tangent handles, teal.
pub const TANGENT_COLOR: Vec3 = palette::TEAL;
/// The motion in space and time (Figure 1's time-as-depth view), purple.
pub const SPACETIME_COLOR: Vec3 = palette::PURPLE;
/// Figure 1's time-as-depth view: metres of depth (−z) per second of the clock.
pub const TIME_DEPTH_M_PER_SEC: f32 = 0.8;
/// Points of the space-time curve.
const SPACETIME_POINTS: usize = 200;
/// The jumps of a step motion (drawn thin, not part of the path).
pub const JUMP_COLOR: Vec3 = palette::GREY;
/// Seconds of motion a tangent handle stands for: the handle is `d · HANDLE_SEC` long.
pub const HANDLE_SEC: f32 = 0.25;
/// How long the motion rests on its last key before it loops, in seconds.
pub const HOLD_SEC: f32 = 0.5;
/// The most keys the editor takes (Lagrange takes at most [`MAX_LAGRANGE_KEYS`]).
pub const MAX_KEYS: usize = 1000;
/// The editor's keys lie in a documented physical range, so that every derived quantity (spline
/// coefficients, arc length, speeds) stays finite in `f32`: times within ±[`KEY_TIME_LIMIT_SEC`]
/// and at least [`MIN_KEY_SPACING_SEC`] apart, positions within ±[`KEY_VALUE_LIMIT_M`] on each
/// axis, tangents within ±[`KEY_TANGENT_LIMIT_M_PER_SEC`] on each axis.
pub const MIN_KEY_SPACING_SEC: f32 = 1e-3;
/// See [`MIN_KEY_SPACING_SEC`].
pub const KEY_TIME_LIMIT_SEC: f32 = 1e4;
/// See [`MIN_KEY_SPACING_SEC`].
pub const KEY_VALUE_LIMIT_M: f32 = 1e4;
/// See [`MIN_KEY_SPACING_SEC`].
pub const KEY_TANGENT_LIMIT_M_PER_SEC: f32 = 1e6;
/// About how many points the drawn path has in all (at least one per segment).
pub const PATH_POINTS: usize = 400;
const ARC_TABLE_SUBDIVISIONS: usize = 24;
const EXERCISES_FILE: &str = "src/exercises/curves.rs";

/// A scheme by the name the page uses.
pub fn scheme_from_name(name: &str, tension: f32) -> Result<Interpolation, String> {
    Ok(match name {
        "step" => Interpolation::Step,
        "linear" => Interpolation::Linear,
        "lagrange" => Interpolation::Lagrange,
        "hermite" => Interpolation::Hermite,
        "cardinal" => Interpolation::Cardinal { tension },
        "natural" => Interpolation::Natural,
        "centripetal" => Interpolation::Centripetal,
        other => {
            return Err(format!(
                "unknown scheme '{other}': use step, linear, lagrange, hermite, cardinal, natural or centripetal"
            ))
        }
    })
}

/// An ease by the name the page uses.
pub fn ease_from_name(name: &str) -> Result<Ease, String> {
    Ok(match name {
        "none" | "linear" => Ease::Linear,
        "smoothstep" => Ease::Smoothstep,
        "smootherstep" => Ease::Smootherstep,
        "sine" => Ease::Sine,
        "in" => Ease::In { power: 2.0 },
        "out" => Ease::Out { power: 2.0 },
        "inout" => Ease::InOut { power: 3.0 },
        other => {
            return Err(format!(
                "unknown ease '{other}': use none, smoothstep, smootherstep, sine, in, out or inout"
            ))
        }
    })
}

/// Keys of a preset, by name: `(times, positions)`.
/// - `"default"`: five keys on a gentle wave.
/// - `"loop"`: two keys close in space but far apart in time; cardinal tangents make a loop.
/// - `"uneven"`: one long and one very short interval; halving instead of dividing by the time
///   between neighbours (exercise 2.2's classic mistake) bulges here.
/// - `"centripetal"`: a zig-zag where the two Catmull-Rom variants' paths differ by up to
///   7.5 cm and centripetal's speed jumps at every key.
pub fn preset(name: &str) -> Result<(Vec<f32>, Vec<Vec2>), String> {
    let v = |xy: &[(f32, f32)]| xy.iter().map(|&(x, y)| Vec2::new(x, y)).collect();
    Ok(match name {
        "default" => (
            vec![0.0, 0.8, 1.6, 2.2, 3.2],
            v(&[(-2.4, 0.3), (-1.2, 1.7), (0.0, 0.5), (1.1, 1.9), (2.4, 0.6)]),
        ),
        "loop" => (
            vec![0.0, 1.0, 2.0, 3.0],
            v(&[(-2.4, 0.4), (0.2, 1.6), (0.5, 1.5), (2.4, 0.4)]),
        ),
        "uneven" => (
            vec![0.0, 0.3, 2.8, 3.0],
            v(&[(-2.4, 0.5), (-1.6, 1.8), (1.4, 1.9), (2.4, 0.4)]),
        ),
        "centripetal" => (
            vec![0.0, 0.5, 1.0, 1.5, 2.0, 2.5],
            v(&[
                (-2.4, 0.2),
                (-2.2, 2.2),
                (-0.2, 0.3),
                (0.0, 2.3),
                (2.2, 0.4),
                (2.4, 2.2),
            ]),
        ),
        other => {
            return Err(format!(
                "unknown preset '{other}': use default, loop, uneven or centripetal"
            ))
        }
    })
}

/// Figure 1 and its companions: keys in a plane, the curve through them, a ball moving along
/// it, and the samples behind the lesson's plots.
pub struct KeyframesScene {
    track: Track<Vec2>,
    scheme_name: String,
    tension: f32,
    table: ArcLengthTable,
    arc_length: bool,
    ease: Ease,
    use_exercise: bool,
    ghost_count: usize,
    time_depth: bool,
    runner: Runner,
    /// The student's path and ghosts, recomputed only after an edit (they do not depend on time).
    student: Option<StudentCache>,
    /// The last frame's camera and canvas size (CSS pixels), for placing the time axis's labels.
    view: Option<(crate::camera::OrbitCamera, Vec2)>,
}

/// What the student's exercises drew, and how each exercise fared while drawing it.
struct StudentCache {
    path: Vec<Vec2>,
    ghosts: Vec<Vec2>,
    /// Where the ball is at [`SPACETIME_POINTS`] equal steps of the clock.
    spacetime: Vec<Vec2>,
    tangents: Vec<Vec2>,
    failures: Failures,
}

/// The first failure of each exercise 2.1 to 2.4 (index 0 to 3).
#[derive(Default, Clone)]
struct Failures([Option<Failure>; 4]);

impl Failures {
    fn record(&mut self, exercise: usize, failure: Failure) {
        self.0[exercise].get_or_insert(failure);
    }
}

const EXERCISE_NAMES: [&str; 4] = [
    "exercise 2.1 hermite_basis",
    "exercise 2.2 cardinal_tangents",
    "exercise 2.3 find_segment",
    "exercise 2.4 arc_length_invert",
];

/// An error unless every key of `track` lies in the editor's range (see [`MIN_KEY_SPACING_SEC`]).
fn check_keys(track: &Track<Vec2>) -> Result<(), String> {
    let times = track.times();
    if let Some(t) = times.iter().find(|t| t.abs() > KEY_TIME_LIMIT_SEC) {
        return Err(format!(
            "key times must lie in [-{KEY_TIME_LIMIT_SEC}, {KEY_TIME_LIMIT_SEC}] s, got {t}"
        ));
    }
    if let Some(w) = times.windows(2).find(|w| w[1] - w[0] < MIN_KEY_SPACING_SEC) {
        return Err(format!(
            "keys must be at least {MIN_KEY_SPACING_SEC} s apart, got {} and {}",
            w[0], w[1]
        ));
    }
    let beyond = |v: &Vec2, limit: f32| v.x.abs() > limit || v.y.abs() > limit;
    if let Some(p) = track.values().iter().find(|p| beyond(p, KEY_VALUE_LIMIT_M)) {
        return Err(format!(
            "key positions must lie in [-{KEY_VALUE_LIMIT_M}, {KEY_VALUE_LIMIT_M}] m on each axis, got ({}, {})",
            p.x, p.y
        ));
    }
    let tangents = track.tangents_in().iter().chain(track.tangents_out());
    if let Some(d) = tangents
        .into_iter()
        .find(|d| beyond(d, KEY_TANGENT_LIMIT_M_PER_SEC))
    {
        return Err(format!(
            "tangents must lie in [-{KEY_TANGENT_LIMIT_M_PER_SEC}, {KEY_TANGENT_LIMIT_M_PER_SEC}] m/s on each axis, got ({}, {})",
            d.x, d.y
        ));
    }
    Ok(())
}

impl Default for KeyframesScene {
    fn default() -> Self {
        Self::new()
    }
}

impl KeyframesScene {
    /// The default preset with Catmull-Rom tangents.
    pub fn new() -> Self {
        let (times, values) = preset("default").expect("a known preset");
        let track = Track::new(times, values)
            .and_then(|t| t.with_interpolation(Interpolation::CATMULL_ROM))
            .valid("valid default keys");
        KeyframesScene {
            table: ArcLengthTable::new(&track, ARC_TABLE_SUBDIVISIONS),
            track,
            scheme_name: "cardinal".into(),
            tension: 1.0,
            arc_length: false,
            ease: Ease::Linear,
            use_exercise: false,
            ghost_count: 24,
            time_depth: true,
            runner: DEFAULT_RUNNER,
            student: None,
            view: None,
        }
    }

    /// How the student's exercises are called (the page passes its sandbox).
    pub fn set_runner(&mut self, runner: Runner) {
        self.runner = runner;
        self.student = None;
    }

    /// The last frame's camera and canvas size (CSS pixels): the time axis's labels take places
    /// clear of the path, the curve and the keys on it. A size that is not positive is ignored.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, Vec2::new(width_px, height_px)));
        }
    }

    /// Replaces the keys (times in seconds, strictly increasing; positions in metres). Hermite
    /// tangents are kept when the number of keys is unchanged (a key was dragged), otherwise
    /// they restart as Catmull-Rom tangents. Errors name the rule broken; the scene is then
    /// unchanged.
    pub fn set_keys(&mut self, times_sec: Vec<f32>, values: Vec<Vec2>) -> Result<(), String> {
        if times_sec.len() > MAX_KEYS {
            return Err(format!(
                "the editor takes at most {MAX_KEYS} keys, got {}",
                times_sec.len()
            ));
        }
        let n = times_sec.len();
        let track = if self.track.interpolation() == Interpolation::Hermite
            && n == self.track.key_count()
        {
            let tin = self.track.tangents_in().to_vec();
            let tout = self.track.tangents_out().to_vec();
            Track::new_hermite(times_sec, values, tin, tout).map_err(|e| e.to_string())?
        } else {
            let scheme = scheme_from_name(&self.scheme_name, self.tension)?;
            // A fresh Hermite track starts from Catmull-Rom tangents.
            let first = if scheme == Interpolation::Hermite {
                Interpolation::CATMULL_ROM
            } else {
                scheme
            };
            Track::new(times_sec, values)
                .and_then(|t| t.with_interpolation(first))
                .map_err(|e| e.to_string())?
        };
        self.install(track)
    }

    /// Sets every key's in and out tangents (metres per second) and switches to Hermite.
    pub fn set_tangents(&mut self, tin: Vec<Vec2>, tout: Vec<Vec2>) -> Result<(), String> {
        let (times, values) = (self.track.times().to_vec(), self.track.values().to_vec());
        let track = Track::new_hermite(times, values, tin, tout).map_err(|e| e.to_string())?;
        self.install(track)?;
        self.scheme_name = "hermite".into();
        Ok(())
    }

    /// Sets key `index`'s in and out tangents (metres per second) and switches to Hermite.
    pub fn set_key_tangent(&mut self, index: usize, tin: Vec2, tout: Vec2) -> Result<(), String> {
        let mut track = self.track.clone();
        track
            .set_tangents(index, tin, tout)
            .map_err(|e| e.to_string())?;
        self.install(track)?;
        self.scheme_name = "hermite".into();
        Ok(())
    }

    /// "step", "linear", "lagrange", "hermite", "cardinal", "natural" or "centripetal".
    /// Switching to Hermite keeps the current curve and makes its tangents editable.
    pub fn set_scheme(&mut self, name: &str) -> Result<(), String> {
        let scheme = scheme_from_name(name, self.tension)?;
        let mut track = self.track.clone();
        track.set_interpolation(scheme).map_err(|e| e.to_string())?;
        self.install(track)?;
        self.scheme_name = name.to_string();
        Ok(())
    }

    /// The cardinal tension `μ ∈ [0, 2]` (1 = Catmull-Rom); used by the "cardinal" scheme.
    pub fn set_tension(&mut self, tension: f32) -> Result<(), String> {
        if !(0.0..=2.0).contains(&tension) {
            return Err(format!(
                "the tension must be between 0 and 2, but it is {tension}"
            ));
        }
        let previous = self.tension;
        self.tension = tension;
        if self.scheme_name == "cardinal" {
            if let Err(e) = self.set_scheme("cardinal") {
                self.tension = previous;
                return Err(e);
            }
        }
        Ok(())
    }

    /// On: the ball travels the same path at constant speed (arc-length parametrisation).
    pub fn set_arc_length(&mut self, on: bool) {
        self.arc_length = on;
        self.student = None;
    }

    /// Timing over the whole motion, by name (see [`ease_from_name`]).
    pub fn set_ease(&mut self, name: &str) -> Result<(), String> {
        self.ease = ease_from_name(name)?;
        self.student = None;
        Ok(())
    }

    /// Number of in-betweens in the ghost trail (2 to 200).
    pub fn set_ghost_count(&mut self, count: usize) -> Result<(), String> {
        if !(2..=200).contains(&count) {
            return Err(format!(
                "the ghost count must be between 2 and 200, got {count}"
            ));
        }
        self.ghost_count = count;
        self.student = None;
        Ok(())
    }

    /// On: the 3D view also draws the motion in space and time, the clock along the depth
    /// (−z, [`TIME_DEPTH_M_PER_SEC`]), with the in-betweens and the ball on that curve.
    pub fn set_time_depth(&mut self, on: bool) {
        self.time_depth = on;
        self.student = None;
    }

    /// The clock time `τ` of the space-time curve's `k`-th of `n` points.
    fn spacetime_tau(&self, k: usize) -> f32 {
        self.track.duration_sec() * k as f32 / (SPACETIME_POINTS - 1) as f32
    }

    /// Where the ball is at [`SPACETIME_POINTS`] equal steps of the clock (reference functions).
    pub fn spacetime(&self, out: &mut Vec<Vec2>) {
        out.clear();
        out.extend((0..SPACETIME_POINTS).map(|k| self.motion(self.spacetime_tau(k)).position));
    }

    /// Draw (and check) with the student's functions in `src/exercises/curves.rs`.
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
        self.student = None;
    }

    pub fn scheme(&self) -> &str {
        &self.scheme_name
    }

    pub fn track(&self) -> &Track<Vec2> {
        &self.track
    }

    /// Seconds the scene's clock runs before it loops: the keys' duration plus [`HOLD_SEC`].
    pub fn loop_sec(&self) -> f32 {
        self.track.duration_sec() + HOLD_SEC
    }

    /// True when the motion holds values (step): its "path" is the keys, not a curve.
    pub fn is_held(&self) -> bool {
        self.track.interpolation() == Interpolation::Step
    }

    /// The path through every key: each segment sampled on its own, from its start key to its
    /// end key, so no key is ever skipped (about [`PATH_POINTS`] points in all). A step motion
    /// has no path between keys: it returns the held values, the keys themselves.
    pub fn path(&self, out: &mut Vec<Vec2>) {
        out.clear();
        if self.is_held() {
            out.extend_from_slice(self.track.values());
            return;
        }
        let times = self.track.times();
        let per_segment = (PATH_POINTS / times.len().max(2)).max(1);
        for w in times.windows(2) {
            for k in 0..per_segment {
                let t = w[0] + (w[1] - w[0]) * k as f32 / per_segment as f32;
                out.push(self.track.position(t));
            }
        }
        out.push(self.track.position(self.track.end_sec()));
    }

    /// The in-betweens (arc length and ease applied), evenly spaced in time.
    pub fn ghosts(&self, out: &mut Vec<Vec2>) {
        let n = self.ghost_count;
        out.clear();
        out.extend((0..n).map(|k| self.motion(self.ghost_tau(k, n)).position));
    }

    fn ghost_tau(&self, k: usize, n: usize) -> f32 {
        self.track.duration_sec() * k as f32 / (n - 1) as f32
    }

    /// Where the ball is at `tau` seconds after the first key.
    pub fn position(&self, tau: f32) -> Result<Vec2, String> {
        Ok(self.motion(finite("time", tau)?).position)
    }

    /// For the plots, `samples` rows over the motion: `[t, speed keyed, speed arc length,
    /// |acceleration| of the motion shown]`, `t` in the keys' own seconds (from the first key's
    /// time), speeds in m/s, acceleration in m/s². "Keyed" is the track as keyed, "arc length"
    /// the same path at constant speed, both with the ease. Both are exact derivatives (no
    /// finite differences), so a corner of the path does not dent the constant speed.
    pub fn sample_motion(&self, samples: usize) -> Result<Vec<[f32; 4]>, String> {
        check_samples(samples)?;
        let duration = self.track.duration_sec();
        Ok((0..samples)
            .map(|k| {
                let tau = duration * k as f32 / (samples - 1) as f32;
                let (keyed, arc) = (self.keyed_motion(tau), self.arc_motion(tau));
                let shown = if self.constant_speed() { arc } else { keyed };
                [
                    self.track.start_sec() + tau,
                    keyed.velocity.length(),
                    arc.velocity.length(),
                    shown.acceleration.length(),
                ]
            })
            .collect())
    }

    /// `τ` wrapped into the loop and clamped to the keys (the hold at the end rests on the last
    /// key).
    pub fn wrap(&self, tau: f32) -> f32 {
        let period = self.loop_sec();
        tau.rem_euclid(period).min(self.track.duration_sec())
    }

    /// Draws the 3D view at `tau` seconds after the first key (wraps around) and returns the
    /// note for the page: empty, or what the student's exercises did.
    pub fn draw(&mut self, frame: &mut Frame, tau: f32) -> Result<String, String> {
        let tau = self.wrap(finite("time", tau)?);
        let (mut path, mut ghosts, mut spacetime) = (Vec::new(), Vec::new(), Vec::new());
        let (ball, note) = if self.use_exercise {
            if self.student.is_none() {
                self.student = Some(self.student_cache());
            }
            let cache = self.student.as_ref().expect("just filled");
            path.clone_from(&cache.path);
            ghosts.clone_from(&cache.ghosts);
            spacetime.clone_from(&cache.spacetime);
            let mut failures = cache.failures.clone();
            let ball = self.student_motion(tau, &cache.tangents, &mut failures);
            (ball, self.exercise_note(tau, &failures))
        } else {
            self.path(&mut path);
            self.ghosts(&mut ghosts);
            if self.time_depth {
                self.spacetime(&mut spacetime);
            }
            (self.motion(tau).position, String::new())
        };
        self.draw_scene(frame, &path, &ghosts, ball);
        if self.time_depth {
            self.draw_spacetime(frame, &spacetime, &ghosts, ball, tau);
        }
        Ok(note)
    }

    fn draw_scene(&self, frame: &mut Frame, path: &[Vec2], ghosts: &[Vec2], ball: Vec2) {
        let at = |p: Vec2| p.extend(0.0);
        frame.grid(12, 0.5);
        if self.is_held() {
            // Held values: the ball sits on a key, then jumps. The jumps are not a path.
            for w in path.windows(2) {
                frame.line(at(w[0]), at(w[1]), JUMP_COLOR);
            }
        } else {
            let points: Vec<Vec3> = path.iter().map(|&p| at(p)).collect();
            frame.wide_polyline(&points, PATH_COLOR, crate::draw::CURVE_PX);
        }
        if !self.time_depth {
            for &g in ghosts {
                frame.point(at(g), 0.045, GHOST_COLOR);
            }
        }
        let hermite = self.track.interpolation() == Interpolation::Hermite;
        for (i, &p) in self.track.values().iter().enumerate() {
            frame.point(at(p), 0.07, KEY_COLOR);
            if hermite {
                let (a, b) = (self.track.tangents_in()[i], self.track.tangents_out()[i]);
                frame.line(at(p - a * HANDLE_SEC), at(p), TANGENT_COLOR);
                frame.line(at(p), at(p + b * HANDLE_SEC), TANGENT_COLOR);
            }
            // A thin stem to the ground makes the plane's depth readable.
            frame.line(Vec3::new(p.x, 0.0, 0.0), at(p), palette::GRID);
        }
        if self.time_depth {
            // The ball's place on the path, under the ball on the space-time curve.
            frame.point(at(ball), 0.06, BALL_COLOR);
        } else {
            let model = Mat4::from_translation(at(ball)) * Mat4::from_scale(Vec3::splat(0.16));
            frame.mesh(MeshId::SPHERE, model, BALL_COLOR);
        }
    }

    /// The motion in space and time: `(x(τ), y(τ), −D τ)` with `D` =
    /// [`TIME_DEPTH_M_PER_SEC`]. The in-betweens lie on it at equal steps of depth (equal
    /// time), so where the curve runs steeply into the depth the ball is slow; the ball rides
    /// it, joined by a thin line to its place on the path; a time axis with a tick per second
    /// runs into the depth beside the path.
    fn draw_spacetime(
        &self,
        frame: &mut Frame,
        spacetime: &[Vec2],
        ghosts: &[Vec2],
        ball: Vec2,
        tau: f32,
    ) {
        let depth = |t: f32| -TIME_DEPTH_M_PER_SEC * t;
        let points: Vec<Vec3> = spacetime
            .iter()
            .enumerate()
            .map(|(k, p)| p.extend(depth(self.spacetime_tau(k))))
            .collect();
        frame.wide_polyline(&points, SPACETIME_COLOR, crate::draw::CURVE_PX);
        let n = ghosts.len();
        for (k, g) in ghosts.iter().enumerate() {
            frame.point(g.extend(depth(self.ghost_tau(k, n))), 0.065, GHOST_COLOR);
        }
        let on_curve = ball.extend(depth(tau));
        frame.line(ball.extend(0.0), on_curve, palette::GRID);
        let model = Mat4::from_translation(on_curve) * Mat4::from_scale(Vec3::splat(0.16));
        frame.mesh(MeshId::SPHERE, model, BALL_COLOR);
        // The time axis, on the ground right of the rightmost key: from the page's camera the
        // depth runs up and to the right, so an axis left of the path would run under the curves
        // and its labels over them.
        // Its ticks are the clock's whole seconds (the keys' own times), placed at their depth
        // after key 0: with key 0 at 2.2 s the first tick reads "3 s", as the clock does.
        let right = self.track.values().iter().fold(f32::MIN, |m, p| m.max(p.x)) + 0.8;
        let (start, duration) = (self.track.start_sec(), self.track.duration_sec());
        let axis = |t: f32| Vec3::new(right, 0.0, depth(t));
        let end = axis(duration + 0.4);
        frame.arrow(axis(0.0), end, palette::DARK, 0.12);
        let tick = |second: i32| axis(second as f32 - start);
        let seconds = start.ceil() as i32..=(start + duration).floor() as i32;
        for p in seconds.clone().map(tick) {
            frame.line(p - Vec3::X * 0.08, p + Vec3::X * 0.08, palette::DARK);
        }
        // The labels, once the curves are down, each at the first place round its point on the
        // last frame's view that covers no line, dot or key (orbited, the path and the curve
        // pass over the axis): the numbers all on the side of the axis away from the curve and
        // the keys, so that they read in order along it whatever the orbit, and the name past the
        // last tick.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        let px = |p: Vec3| {
            view.and_then(|(view_proj, size)| {
                crate::camera::project_to_canvas(view_proj, size, p)
            })
        };
        let start_px = px(axis(0.0)).unwrap_or_default();
        let along = (px(end).unwrap_or_default() - start_px).try_normalize().unwrap_or(Vec2::X);
        let last_px = px(tick(*seconds.end())).unwrap_or_default();
        let keys: Vec<Vec3> = self.track.values().iter().map(|p| p.extend(0.0)).collect();
        let lean: f32 = points
            .iter()
            .chain(&keys)
            .filter_map(|&p| px(p))
            .map(|c| (c - start_px).dot(along.perp()).signum())
            .sum();
        let away = along.perp() * -lean.signum();
        // Every 1, 2, 5 or 10 s, whichever first puts the labelled ticks 30 px apart on the last
        // frame's canvas: when the camera backs away to fit a tall path, a label a second would
        // crowd into its neighbours' places and read out of order.
        let px_per_sec = px(axis(duration.max(1.0)))
            .map_or(0.0, |p| p.distance(start_px) / duration.max(1.0));
        let stride = [1, 2, 5, 10]
            .into_iter()
            .find(|&n| n as f32 * px_per_sec >= 30.0)
            .unwrap_or(10);
        let labels = seconds
            .filter(|second| second.rem_euclid(stride) == 0)
            .map(|second| (tick(second), away, start_px, format!("{second} s")))
            .chain([(end, along, last_px, "time (s)".into())]);
        for (at, toward, from, text) in labels {
            let candidates =
                crate::draw::Label::around_dot(at, 12.0, toward, &text, palette::DARK, 0, 16, 6.0);
            let clear = super::clear_of(view, &keys);
            frame.first_clear_label_by(view, 2.0, candidates, |rect| {
                clear(rect) && lies_beyond(rect, from, toward, 2.0)
            });
        }
        // The camera fits the curve, the path's keys and the axis at every canvas size.
        frame.keep_in_view.extend(points);
        frame
            .keep_in_view
            .extend(self.track.values().iter().map(|p| p.extend(0.0)));
        frame.keep_in_view.extend([axis(0.0), axis(duration + 0.9)]);
    }

    /// Makes `track` the scene's track if its keys lie in the editor's range (see
    /// [`MIN_KEY_SPACING_SEC`]) and its path has a finite length; otherwise the scene is unchanged.
    fn install(&mut self, track: Track<Vec2>) -> Result<(), String> {
        check_keys(&track)?;
        let table = ArcLengthTable::new(&track, ARC_TABLE_SUBDIVISIONS);
        if !table.total_length().is_finite() {
            return Err("the path's length overflows: bring the keys closer together".into());
        }
        self.table = table;
        self.track = track;
        self.student = None;
        Ok(())
    }

    fn warp(&self) -> TimeWarp {
        TimeWarp::over(&self.track, self.ease)
    }

    /// The keyed motion with the ease, at `tau` seconds after the first key.
    fn keyed_motion(&self, tau: f32) -> Sample<Vec2> {
        self.track
            .evaluate_warped(&self.warp(), self.track.start_sec() + tau)
    }

    /// The same path at constant speed (times the ease), with exact derivatives:
    /// ```text
    /// σ(τ) = L (w(τ) − t0) / T          distance along the path, σ′ = L w′ / T, σ″ = L w″ / T
    /// velocity     = σ′ T̂               T̂ = p′(u) / |p′(u)| at the time u where L(u) = σ
    /// acceleration = σ″ T̂ + σ′² κN      κN = (p″ − (p″·T̂) T̂) / |p′|²  (the curvature vector)
    /// ```
    fn arc_motion(&self, tau: f32) -> Sample<Vec2> {
        let duration = self.track.duration_sec();
        let length = self.table.total_length();
        if duration <= 0.0 || length <= 0.0 {
            return Sample::at_rest(self.track.values()[0]);
        }
        let [w, dw, ddw] = self.warp().warp(self.track.start_sec() + tau);
        let sigma = length * ((w - self.track.start_sec()) / duration).clamp(0.0, 1.0);
        let (dsigma, ddsigma) = (length * dw / duration, length * ddw / duration);
        let u = self.table.time_at_length(&self.track, sigma);
        let curve = self.track.evaluate(u);
        let speed = curve.velocity.length();
        let tangent = curve.velocity.normalize_or_zero();
        let curvature = if speed > 1e-6 {
            (curve.acceleration - tangent * curve.acceleration.dot(tangent)) / (speed * speed)
        } else {
            Vec2::ZERO
        };
        Sample {
            position: curve.position,
            velocity: tangent * dsigma,
            acceleration: tangent * ddsigma + curvature * (dsigma * dsigma),
        }
    }

    /// `(w(τ) − t0) / T ∈ [0, 1]`: the fraction of the path covered at `τ`.
    fn arc_fraction(&self, tau: f32) -> f32 {
        let duration = self.track.duration_sec();
        if duration <= 0.0 {
            return 0.0;
        }
        let [w, _, _] = self.warp().warp(self.track.start_sec() + tau);
        ((w - self.track.start_sec()) / duration).clamp(0.0, 1.0)
    }

    /// True when the ball really travels at constant speed: arc length is ticked and the path
    /// has a length. A step motion jumps from key to key, so its path has no length to spread
    /// the time over; it keeps its keyed timing and [`KeyframesScene::timing_note`] says why.
    pub fn constant_speed(&self) -> bool {
        self.arc_length && !self.is_held() && self.table.total_length() > 0.0
    }

    /// The sentence under the timing figure: empty, or why "constant speed" does not apply.
    pub fn timing_note(&self) -> String {
        if self.arc_length && !self.constant_speed() {
            "Constant speed needs a path with a length. A step motion has none: it holds each key \
             and jumps to the next, so the ball keeps the keyed timing (it shows key i from t_i \
             on). Pick another scheme to see constant speed."
                .into()
        } else {
            String::new()
        }
    }

    /// How far apart this motion and `other` are at the same moment, at most, over this one's
    /// keys (401 equal steps of the clock): "A and B are at most … cm apart".
    pub fn gap_note(&self, other: &Self) -> String {
        let duration = self.track.duration_sec();
        let gap = (0..=400)
            .map(|k| {
                let tau = duration * k as f32 / 400.0;
                (self.motion(tau).position - other.motion(tau).position).length()
            })
            .fold(0.0, f32::max);
        format!(
            "At the same moment A and B are at most {} cm apart.",
            format_number(100.0 * gap)
        )
    }

    fn motion(&self, tau: f32) -> Sample<Vec2> {
        if self.constant_speed() {
            self.arc_motion(tau)
        } else {
            self.keyed_motion(tau)
        }
    }

    // ---- The same motion computed with the student's exercises (src/exercises/curves.rs). ----

    fn student_cache(&self) -> StudentCache {
        let mut failures = Failures::default();
        let tangents = self.student_tangents(&mut failures);
        let mut path = Vec::new();
        self.path(&mut path); // the sample times and the step case come from the reference
        if !self.is_held() && self.is_piecewise() {
            let times = self.track.times();
            let per_segment = (PATH_POINTS / times.len().max(2)).max(1);
            path.clear();
            for w in times.windows(2) {
                for k in 0..per_segment {
                    let t = w[0] + (w[1] - w[0]) * k as f32 / per_segment as f32;
                    path.push(self.student_position(t, &tangents, &mut failures));
                }
            }
            let end = self.track.end_sec();
            path.push(self.student_position(end, &tangents, &mut failures));
        }
        let n = self.ghost_count;
        let ghosts = (0..n)
            .map(|k| self.student_motion(self.ghost_tau(k, n), &tangents, &mut failures))
            .collect();
        let spacetime = if self.time_depth {
            (0..SPACETIME_POINTS)
                .map(|k| self.student_motion(self.spacetime_tau(k), &tangents, &mut failures))
                .collect()
        } else {
            Vec::new()
        };
        StudentCache {
            path,
            ghosts,
            spacetime,
            tangents,
            failures,
        }
    }

    fn is_piecewise(&self) -> bool {
        !matches!(self.track.interpolation(), Interpolation::Lagrange)
    }

    fn is_cubic(&self) -> bool {
        matches!(
            self.track.interpolation(),
            Interpolation::Hermite
                | Interpolation::Cardinal { .. }
                | Interpolation::Natural
                | Interpolation::Centripetal
        )
    }

    /// The out tangents for the student path: exercise 2.2 (one channel at a time) for the
    /// cardinal scheme, the track's own tangents otherwise.
    fn student_tangents(&self, failures: &mut Failures) -> Vec<Vec2> {
        let reference = self.track.tangents_out().to_vec();
        if self.scheme_name != "cardinal" {
            return reference;
        }
        let times = self.track.times().to_vec();
        let channel = |f: fn(&Vec2) -> f32| self.track.values().iter().map(f).collect();
        let xs = run::cardinal_tangents(self.runner, times.clone(), channel(|p| p.x), self.tension);
        let ys = run::cardinal_tangents(self.runner, times, channel(|p| p.y), self.tension);
        match (xs, ys) {
            (Ok(dx), Ok(dy)) if dx.len() == reference.len() && dy.len() == reference.len() => {
                dx.iter().zip(&dy).map(|(&x, &y)| Vec2::new(x, y)).collect()
            }
            (Ok(_), Ok(_)) => {
                failures.record(1, Failure::Call("not one tangent per key".into()));
                reference
            }
            (Err(f), _) | (_, Err(f)) => {
                failures.record(1, f);
                reference
            }
        }
    }

    /// The segment containing `t`, with exercise 2.3 (kept inside the keys: a wrong index must
    /// not crash the page).
    fn student_segment(&self, t: f32, failures: &mut Failures) -> usize {
        let times = self.track.times();
        match run::find_segment(self.runner, times.to_vec(), t) {
            Ok(i) => i.min(times.len() - 2),
            Err(f) => {
                failures.record(2, f);
                curves::find_segment(times, t)
            }
        }
    }

    /// `p(t)` at a time inside the keys, with exercises 2.3 (segment) and 2.1 (basis).
    fn student_position(&self, t: f32, tangents: &[Vec2], failures: &mut Failures) -> Vec2 {
        let (times, values) = (self.track.times(), self.track.values());
        let n = times.len();
        if n < 2 || !self.is_piecewise() {
            return self.track.position(t);
        }
        let t = t.clamp(times[0], times[n - 1]);
        let i = self.student_segment(t, failures);
        let h = times[i + 1] - times[i];
        let s = (t - times[i]) / h;
        match self.track.interpolation() {
            Interpolation::Step => return if s >= 1.0 { values[i + 1] } else { values[i] },
            Interpolation::Linear => return values[i].lerp(values[i + 1], s),
            _ => {}
        }
        let [h00, h10, h01, h11] = run::hermite_basis(self.runner, s).unwrap_or_else(|f| {
            failures.record(0, f);
            curves::hermite_basis(s)
        });
        let d0 = tangents[i];
        // The in tangent of the next key: its out tangent except at a broken Hermite key.
        let d1 = if self.scheme_name == "cardinal" {
            tangents[i + 1]
        } else {
            self.track.tangents_in()[i + 1]
        };
        values[i] * h00 + d0 * (h * h10) + values[i + 1] * h01 + d1 * (h * h11)
    }

    /// The time the ball is at after `tau` seconds: the eased time, or, at constant speed, the
    /// time where the arc length reaches `σ` (exercise 2.4).
    fn student_time(&self, tau: f32, failures: &mut Failures) -> f32 {
        if !self.constant_speed() {
            return self.warp().warp(self.track.start_sec() + tau)[0];
        }
        let sigma = self.arc_fraction(tau) * self.table.total_length();
        let (params, lengths) = (self.table.times_sec(), self.table.lengths());
        match run::arc_length_invert(self.runner, params.to_vec(), lengths.to_vec(), sigma) {
            Ok(u) if u.is_finite() => u,
            Ok(_) => self.track.start_sec(),
            Err(f) => {
                failures.record(3, f);
                curves::arc_length_invert(params, lengths, sigma)
            }
        }
    }

    fn student_motion(&self, tau: f32, tangents: &[Vec2], failures: &mut Failures) -> Vec2 {
        let t = self.student_time(tau, failures);
        self.student_position(t, tangents, failures)
    }

    /// One line per exercise: not done / panicked, or matches / differs at the current inputs.
    fn exercise_note(&self, tau: f32, failures: &Failures) -> String {
        let mut lines = Vec::new();
        for (k, name) in EXERCISE_NAMES.iter().enumerate() {
            let line = match &failures.0[k] {
                Some(f) => Some(failure_note(name, EXERCISES_FILE, f)),
                None => self.compare(k, tau),
            };
            lines.extend(line);
        }
        lines.join("\n")
    }

    /// Compares exercise `k` (0 = 2.1 … 3 = 2.4) with the reference where the ball is now, and
    /// at a few more inputs where typical mistakes show; `None` when the current scheme does
    /// not use it.
    fn compare(&self, k: usize, tau: f32) -> Option<String> {
        let times = self.track.times();
        let t = self.warp().warp(self.track.start_sec() + tau)[0];
        let i = curves::find_segment(times, t);
        let s = if times.len() > 1 {
            (t - times[i]) / (times[i + 1] - times[i])
        } else {
            0.0
        };
        let result = match k {
            0 if self.is_cubic() => hermite_basis_probes(self.runner, s)
                .map(|probes| probe_note("hermite_basis", &probes, 1e-4).1),
            1 if self.scheme_name == "cardinal" => self.compare_tangents(),
            2 if self.is_piecewise() && times.len() > 1 => self.compare_segments(t),
            3 if self.constant_speed() => {
                let sigma = self.arc_fraction(tau) * self.table.total_length();
                self.compare_invert(sigma)
            }
            _ => return None,
        };
        Some(result.unwrap_or_else(|f| failure_note(EXERCISE_NAMES[k], EXERCISES_FILE, &f)))
    }

    /// Exercise 2.3 at the ball's time `t`, then before the first key, on the first, a middle
    /// and the last key exactly (the boundaries of `t_i ≤ t < t_{i+1}`) and after the last.
    fn compare_segments(&self, t: f32) -> Result<String, Failure> {
        let times = self.track.times();
        let n = times.len();
        let mut inputs = vec![t, times[0] - 0.5, times[0], times[n / 2], times[n - 1]];
        inputs.push(times[n - 1] + 0.5);
        let probes = inputs
            .iter()
            .map(|&u| {
                let yours = run::find_segment(self.runner, times.to_vec(), u)?;
                Ok(Probe {
                    at: format!("t = {} s", format_number(u)),
                    yours: vec![yours as f32],
                    reference: vec![curves::find_segment(times, u) as f32],
                })
            })
            .collect::<Result<Vec<_>, Failure>>()?;
        Ok(probe_note("find_segment", &probes, 0.0).1)
    }

    /// Exercise 2.4 at the ball's distance `sigma`, then at both ends of the table, exactly on
    /// a middle entry and half-way between two entries.
    fn compare_invert(&self, sigma: f32) -> Result<String, Failure> {
        let (params, lengths) = (self.table.times_sec(), self.table.lengths());
        let m = lengths.len() / 2;
        let total = self.table.total_length();
        let inputs = [
            sigma,
            0.0,
            total,
            lengths[m],
            0.5 * (lengths[m] + lengths[m + 1]),
        ];
        let probes = inputs
            .iter()
            .map(|&u| {
                let yours =
                    run::arc_length_invert(self.runner, params.to_vec(), lengths.to_vec(), u)?;
                Ok(Probe {
                    at: format!("s = {} m", format_number(u)),
                    yours: vec![yours],
                    reference: vec![curves::arc_length_invert(params, lengths, u)],
                })
            })
            .collect::<Result<Vec<_>, Failure>>()?;
        Ok(probe_note("arc_length_invert", &probes, 1e-3).1)
    }

    /// Exercise 2.2 against the reference, key by key at the figure's keys and tension (the
    /// note names the first key that differs), then on three more inputs: the same keys at
    /// μ = 0.5, the uneven-times preset (where halving instead of dividing by the time fails)
    /// and two keys only (both ends, no interior key).
    fn compare_tangents(&self) -> Result<String, Failure> {
        let mut failures = Failures::default();
        let yours = self.student_tangents(&mut failures);
        if let Some(f) = failures.0[1].take() {
            return Err(f);
        }
        let reference = self.track.tangents_out();
        let mu = format_number(self.tension);
        for (i, (a, b)) in yours.iter().zip(reference).enumerate() {
            let at = format!("key {i} (μ = {mu})");
            let (ok, note) = compare_note("cardinal_tangents", &at, &[a.x, a.y], &[b.x, b.y], 1e-3);
            if !ok {
                return Ok(note);
            }
        }
        let xs = |v: &[Vec2]| v.iter().map(|p| p.x).collect::<Vec<f32>>();
        let (uneven_t, uneven_v) = preset("uneven").expect("a known preset");
        let inputs = [
            (
                self.track.times().to_vec(),
                xs(self.track.values()),
                0.5,
                "the figure's keys' x at μ = 0.5",
            ),
            (
                uneven_t,
                xs(&uneven_v),
                1.0,
                "the uneven-times preset's x at μ = 1",
            ),
            (
                vec![0.0, 2.0],
                vec![1.0, 3.0],
                1.0,
                "two keys (0 s, 1) and (2 s, 3) at μ = 1",
            ),
        ];
        let mut probes = vec![Probe {
            at: format!("all {} keys (μ = {mu})", reference.len()),
            yours: Vec::new(),
            reference: Vec::new(),
        }];
        for (times, values, mu, at) in inputs {
            let yours = run::cardinal_tangents(self.runner, times.clone(), values.clone(), mu)?;
            let mut expected = vec![0.0; times.len()];
            curves::cardinal_tangents(&times, &values, mu, &mut expected);
            probes.push(Probe {
                at: at.to_string(),
                yours,
                reference: expected,
            });
        }
        Ok(probe_note("cardinal_tangents", &probes, 1e-3).1)
    }
}

/// Exercise 2.1 at `s` (the figure's input), then at 0, ¼, ½, ¾ and 1.
fn hermite_basis_probes(runner: Runner, s: f32) -> Result<Vec<Probe>, Failure> {
    std::iter::once(s)
        .chain([0.0, 0.25, 0.5, 0.75, 1.0].into_iter().filter(|&u| u != s))
        .map(|u| {
            Ok(Probe {
                at: format!("s = {}", format_number(u)),
                yours: run::hermite_basis(runner, u)?.to_vec(),
                reference: curves::hermite_basis(u).to_vec(),
            })
        })
        .collect()
}

/// Figure 2: the four Hermite basis functions over `s ∈ [0, 1]` and exercise 2.1 at one `s`.
/// Returns rows `[s, h00, h10, h01, h11]`.
pub fn hermite_basis_samples(samples: usize) -> Result<Vec<[f32; 5]>, String> {
    check_samples(samples)?;
    Ok((0..samples)
        .map(|k| {
            let s = k as f32 / (samples - 1) as f32;
            let [a, b, c, d] = curves::hermite_basis(s);
            [s, a, b, c, d]
        })
        .collect())
}

/// The note beside the basis plot: the four weights at `s` (the reference's, which the plot
/// draws), and with `use_exercise`, first, whether exercise 2.1 matches them.
pub fn hermite_basis_note(runner: Runner, s: f32, use_exercise: bool) -> Result<String, String> {
    let s = in_range("s", s, 0.0, 1.0)?;
    let [a, b, c, d] = curves::hermite_basis(s).map(format_number);
    let weights = format!(
        "At s = {}: h00 = {a}, h10 = {b}, h01 = {c}, h11 = {d}.",
        format_number(s)
    );
    if !use_exercise {
        return Ok(weights);
    }
    let verdict = match hermite_basis_probes(runner, s) {
        Ok(probes) => probe_note("hermite_basis", &probes, 1e-4).1,
        Err(f) => failure_note(EXERCISE_NAMES[0], EXERCISES_FILE, &f),
    };
    Ok(format!("{verdict}\n{weights}"))
}

/// Figure 3: one polynomial through all keys (Lagrange), with `n` keys and with two more, drawn
/// as a graph `y(t)` on labelled axes in the XY plane (seen straight on).
pub struct LagrangeScene {
    keys: usize,
    show_spline: bool,
    /// The drawn pieces of each curve: the polynomial is cut where it leaves the graph.
    base: Vec<Vec<Vec3>>,
    more: Vec<Vec<Vec3>>,
    spline: Vec<Vec<Vec3>>,
    note: String,
    /// The last frame's view-projection and canvas size (CSS pixels): the time axis's numbers
    /// are placed off the curves for it.
    view: Option<(Mat4, Vec2)>,
}

/// Colours of the Lagrange figure: blue through `n` keys, red through `n + 2`, green spline.
pub const LAGRANGE_BASE: Vec3 = palette::BLUE;
pub const LAGRANGE_MORE: Vec3 = palette::RED;
pub const LAGRANGE_SPLINE: Vec3 = palette::GREEN;
/// The graph's value range, in metres: the polynomial is clipped to it.
const Y_RANGE: (f32, f32) = (-0.8, 3.4);
/// Width of the graph in world units.
const GRAPH_WIDTH: f32 = 5.6;

/// Key times and values of one Lagrange curve.
type KeySet = (Vec<f32>, Vec<f32>);

impl Default for LagrangeScene {
    fn default() -> Self {
        Self::new()
    }
}

impl LagrangeScene {
    pub fn new() -> Self {
        let mut scene = LagrangeScene {
            keys: 10,
            show_spline: true,
            base: Vec::new(),
            more: Vec::new(),
            spline: Vec::new(),
            note: String::new(),
            view: None,
        };
        scene.rebuild().expect("valid default keys");
        scene
    }

    /// Number of keys of the first curve (3 to 16); the second curve has two more.
    pub fn set_key_count(&mut self, keys: f32) -> Result<(), String> {
        let keys = super::whole_number("key count", keys, 3, 16)?;
        let before = self.keys;
        self.keys = keys;
        // A rebuild that fails leaves the figure as it was (the old count rebuilt before).
        if let Err(e) = self.rebuild() {
            self.keys = before;
            self.rebuild()?;
            return Err(e);
        }
        Ok(())
    }

    /// The camera of the frame the page draws next, on a `width_px × height_px` canvas.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            let view_proj = camera.projection(width_px / height_px) * camera.view();
            self.view = Some((view_proj, Vec2::new(width_px, height_px)));
        }
    }

    /// Also draw a Catmull-Rom spline through the larger set of keys, for comparison.
    pub fn set_show_spline(&mut self, on: bool) {
        self.show_spline = on;
    }

    pub fn key_count(&self) -> usize {
        self.keys
    }

    /// What the caption's Try this reads: the largest gap between any two of the three curves
    /// and the red polynomial's largest |y|, over the sampled time range, in metres.
    pub fn note(&self) -> &str {
        &self.note
    }

    /// The keys of the first curve and of the second.
    pub fn key_sets(&self) -> (KeySet, KeySet) {
        let n = self.keys;
        let wave = |t: f32| 0.9 + 0.55 * (0.55 * t).sin() + 0.12 * (1.7 * t).cos();
        let times: Vec<f32> = (0..n).map(|i| i as f32).collect();
        let values: Vec<f32> = times.iter().map(|&t| wave(t)).collect();
        let mut more: Vec<(f32, f32)> = times.iter().copied().zip(values.iter().copied()).collect();
        // Never on an integer time, and distinct for n ≥ 3.
        let (a, b) = ((n - 1) as f32 * 0.25 + 0.1, (n - 1) as f32 * 0.75 - 0.1);
        // Each inserted after the keys at or before its time: the times stay sorted.
        for key in [(a, wave(a) + 0.08), (b, wave(b) - 0.08)] {
            let at = more.partition_point(|k| k.0 <= key.0);
            more.insert(at, key);
        }
        let (more_t, more_v) = more.into_iter().unzip();
        ((times, values), (more_t, more_v))
    }

    /// Where the graph puts `(t, y)`: time along x (scaled to a fixed width), value up.
    pub fn place(&self, t: f32, y: f32) -> Vec3 {
        Vec3::new((t / (self.keys - 1) as f32 - 0.5) * GRAPH_WIDTH, y, 0.0)
    }

    pub fn draw(&self, frame: &mut Frame) {
        // A graph in the plane z = 0, seen straight on: a drag pans it rather than turning it
        // edge-on.
        frame.flat = true;
        // Wide curves, each narrower than the one under it: where two run together (blue
        // under green at 10 keys), the lower one shows as a rim on both sides.
        let spline: &[Vec<Vec3>] = if self.show_spline { &self.spline } else { &[] };
        for (pieces, color, width) in [
            (&self.base[..], LAGRANGE_BASE, 5.0),
            (&self.more, LAGRANGE_MORE, 3.5),
            (spline, LAGRANGE_SPLINE, 2.0),
        ] {
            for piece in pieces {
                frame.wide_polyline(piece, color, width);
            }
        }
        let (a, b) = self.key_sets();
        for (t, y) in b.0.iter().zip(&b.1) {
            let extra = !a.0.contains(t);
            let (size, color) = if extra {
                (12.0, LAGRANGE_MORE)
            } else {
                (crate::draw::DOT_PX, KEY_COLOR)
            };
            frame.marker(self.place(*t, *y), size, color);
        }
        // The axes after the curves: a stroke drawn later covers one at the same depth, so the
        // polynomial that runs along the value axis does not hide it.
        self.draw_axes(frame);
    }

    /// A time axis along y = 0 with a tick and a label every second, a value axis at t = 0 with
    /// a tick every metre, each named with its quantity and unit. Each time number goes to the
    /// first place round its tick (below first, then above, then further out) that the curves
    /// already in `frame` leave clear on the last view's canvas: the polynomial plunges through
    /// the axis between keys.
    fn draw_axes(&self, frame: &mut Frame) {
        let axis = palette::DARK;
        let last = (self.keys - 1) as f32;
        let (x0, x1) = (self.place(0.0, 0.0), self.place(last, 0.0));
        frame.arrow(x0, x1 + Vec3::X * 0.35, axis, 0.12);
        frame.arrow(
            self.place(0.0, Y_RANGE.0),
            self.place(0.0, Y_RANGE.1),
            axis,
            0.12,
        );
        let tick = 0.06;
        // The value ticks' numbers left of the axis, clear of the key dot at t = 0; the time
        // axis's "0" under the origin names both zeros. They outrank the time numbers: where
        // two crowd, the page's layout moves the time number (placed clear of the curves
        // above), never a value number out past the axis into the polynomial.
        for y in [-0.5_f32, 1.0, 2.0, 3.0] {
            let p = self.place(0.0, y);
            frame.line(p - Vec3::X * tick, p + Vec3::X * tick, axis);
            frame.label_left(p - Vec3::X * 0.15, format!("{y}"), axis);
            if let Some(value) = frame.labels.last_mut() {
                value.priority = 1;
            }
        }
        let step = if self.keys > 10 { 2 } else { 1 };
        for t in (0..self.keys).step_by(step) {
            let p = self.place(t as f32, 0.0);
            frame.line(p - Vec3::Y * tick, p + Vec3::Y * tick, axis);
            let text = format!("{t}");
            let around =
                crate::draw::Label::around_dot(p, 8.0, Vec2::new(0.3, 1.0), &text, axis, 0, 3, 6.0);
            frame.first_clear_label_by(self.view, 2.0, around, |_| true);
        }
        frame.label(x1 + Vec3::new(0.35, -0.3, 0.0), "time t (s)", axis);
        frame.label(
            self.place(0.0, Y_RANGE.1) + Vec3::new(0.1, 0.15, 0.0),
            "value y (m)",
            axis,
        );
        // Both axes with their numbers and names stay in view at any canvas size and after an
        // orbit (the value axis's foot otherwise leaves the canvas's bottom).
        frame.keep_box_in_view(
            self.place(0.0, Y_RANGE.0) - Vec3::new(0.5, 0.0, 0.1),
            self.place(last, Y_RANGE.1) + Vec3::new(1.5, 0.4, 0.1),
        );
    }

    fn rebuild(&mut self) -> Result<(), String> {
        let ((ta, ya), (tb, yb)) = self.key_sets();
        let lagrange =
            |t, y| Track::new(t, y).and_then(|k| k.with_interpolation(Interpolation::Lagrange));
        let a = lagrange(ta, ya).map_err(|e| e.to_string())?;
        let b = lagrange(tb, yb).map_err(|e| e.to_string())?;
        let spline = b
            .clone()
            .with_interpolation(Interpolation::CATMULL_ROM)
            .map_err(|e| e.to_string())?;
        debug_assert!(b.key_count() <= MAX_LAGRANGE_KEYS);
        const SAMPLES: usize = 400;
        // The polynomial can shoot far off between keys: cut what we draw at the graph's edge
        // (a clamped curve would run along the edge and read as a value that saturates).
        let graphs = [&a, &b, &spline].map(|track| -> Vec<(f32, f32)> {
            let (t0, t1) = (track.start_sec(), track.end_sec());
            (0..SAMPLES)
                .map(|k| {
                    let t = t0 + (t1 - t0) * k as f32 / (SAMPLES - 1) as f32;
                    (t, track.position(t))
                })
                .collect()
        });
        let (mut gap, mut red) = (0.0f32, 0.0f32);
        for k in 0..SAMPLES {
            let [ya, yb, yg] = graphs.each_ref().map(|g| g[k].1);
            gap = gap
                .max((ya - yb).abs())
                .max((yb - yg).abs())
                .max((ya - yg).abs());
            red = red.max(yb.abs());
        }
        self.note = format!(
            "The three curves are at most {} m apart; the red one reaches |y| = {} m.",
            format_number(gap),
            format_number(red)
        );
        [self.base, self.more, self.spline] = graphs.map(|graph| {
            clip_graph(&graph, Y_RANGE)
                .into_iter()
                .map(|piece| piece.iter().map(|&(t, y)| self.place(t, y)).collect())
                .collect()
        });
        Ok(())
    }
}

/// The pieces of a sampled graph `(t, y)` that lie inside `y ∈ [lo, hi]`: a piece ends where the
/// graph leaves the band and the next starts where it comes back, each at the crossing point
/// (interpolated linearly between the two samples on either side). Nothing is clamped.
pub fn clip_graph(graph: &[(f32, f32)], (lo, hi): (f32, f32)) -> Vec<Vec<(f32, f32)>> {
    let inside = |y: f32| (lo..=hi).contains(&y);
    // Where the segment from a to b crosses the band's edge nearest to `from`.
    let crossing = |a: (f32, f32), b: (f32, f32), edge: f32| {
        let f = (edge - a.1) / (b.1 - a.1);
        (a.0 + (b.0 - a.0) * f, edge)
    };
    let mut pieces: Vec<Vec<(f32, f32)>> = Vec::new();
    let mut current: Vec<(f32, f32)> = Vec::new();
    for (k, &p) in graph.iter().enumerate() {
        let prev = k.checked_sub(1).map(|j| graph[j]);
        match (prev, inside(p.1)) {
            (Some(a), true) if !inside(a.1) => {
                // Coming back in: start at the edge it crosses.
                let edge = if a.1 > hi { hi } else { lo };
                current.push(crossing(a, p, edge));
                current.push(p);
            }
            (_, true) => current.push(p),
            (Some(a), false) if inside(a.1) => {
                if !p.1.is_nan() {
                    let edge = if p.1 > hi { hi } else { lo };
                    current.push(crossing(a, p, edge));
                }
                pieces.push(std::mem::take(&mut current));
            }
            (_, false) => {}
        }
    }
    if !current.is_empty() {
        pieces.push(current);
    }
    pieces.retain(|piece| piece.len() > 1);
    pieces
}

/// One input at which a figure checks a student's function: where (as the note names it), the
/// student's answer and the reference's.
pub struct Probe {
    pub at: String,
    pub yours: Vec<f32>,
    pub reference: Vec<f32>,
}

/// The verdict on a student's function at the input the figure shows (the first probe) and at a
/// few more chosen where mistakes show (ends, keys, edge cases): the displayed input alone
/// often cannot tell. Returns whether every probe matches, and the note: "matches at … and at
/// N more inputs (…)", or where it differs first with both values, naming the other inputs
/// that differ too.
pub fn probe_note(what: &str, probes: &[Probe], tolerance: f32) -> (bool, String) {
    let Some((shown, more)) = probes.split_first() else {
        return (true, String::new());
    };
    let check = |p: &Probe| compare_note(what, &p.at, &p.yours, &p.reference, tolerance);
    let (shown_ok, shown_note) = check(shown);
    let wrong: Vec<&Probe> = more.iter().filter(|p| !check(p).0).collect();
    let names = |ps: &[&Probe]| {
        ps.iter()
            .map(|p| p.at.as_str())
            .collect::<Vec<_>>()
            .join("; ")
    };
    match (shown_ok, wrong.split_first()) {
        (true, None) => {
            let all: Vec<&Probe> = more.iter().collect();
            let tail = if all.is_empty() {
                String::new()
            } else {
                format!(" and at {} more inputs ({})", all.len(), names(&all))
            };
            (
                true,
                format!("Your {what} matches the reference at {}{tail}.", shown.at),
            )
        }
        (true, Some((first, rest))) => {
            let (_, differs) = check(first);
            let also = if rest.is_empty() {
                String::new()
            } else {
                format!(" It also differs at {}.", names(rest))
            };
            (
                false,
                format!(
                    "Your {what} matches the reference at {} (the figure's input), but {}{also}",
                    shown.at,
                    differs.trim_start_matches(&format!("Your {what} "))
                ),
            )
        }
        (false, _) => {
            let also = if wrong.is_empty() {
                String::new()
            } else {
                format!(" It also differs at {}.", names(&wrong))
            };
            (false, format!("{shown_note}{also}"))
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The cardinal figure: a key's tangent from the chord between its neighbours, by two rules.

/// How a cardinal tangent turns the chord between a key's neighbours into a velocity.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChordRule {
    /// The course's rule: the chord divided by the time between the neighbours (m/s).
    ByTime,
    /// The classic mistake: the chord halved, as if every key were one second from the next.
    Halved,
}

impl ChordRule {
    /// The rule by the name the page uses: "time" or "halved".
    pub fn from_name(name: &str) -> Result<Self, String> {
        match name {
            "time" => Ok(ChordRule::ByTime),
            "halved" => Ok(ChordRule::Halved),
            other => Err(format!("unknown rule '{other}': use time or halved")),
        }
    }
}

/// The cardinal figure: one set of keys, and the cardinal spline through them with its tangents
/// made by both [`ChordRule`]s, side by side. Each key's construction is drawn: the chord between
/// its neighbours and the tangent `d_i` parallel to it.
pub struct CardinalScene {
    times: Vec<f32>,
    values: Vec<Vec2>,
    tension: f32,
}

impl Default for CardinalScene {
    fn default() -> Self {
        Self::new()
    }
}

impl CardinalScene {
    /// The "uneven" preset (segments of 0.3 s, 2.5 s and 0.2 s) at tension 1 (Catmull-Rom).
    pub fn new() -> Self {
        let (times, values) = preset("uneven").expect("a built-in preset");
        Self {
            times,
            values,
            tension: 1.0,
        }
    }

    /// Loads one of [`preset`]'s key sets.
    pub fn set_preset(&mut self, name: &str) -> Result<(), String> {
        let (times, values) = preset(name)?;
        self.times = times;
        self.values = values;
        Ok(())
    }

    /// The tension `μ`, 0 to 2.
    pub fn set_tension(&mut self, tension: f32) -> Result<(), String> {
        self.tension = in_range("tension", tension, 0.0, 2.0)?;
        Ok(())
    }

    /// Key times (s) and positions (m).
    pub fn keys(&self) -> (&[f32], &[Vec2]) {
        (&self.times, &self.values)
    }

    /// One tangent per key (m/s) by `rule`. [`ChordRule::ByTime`] is the core's
    /// [`curves::cardinal_tangents`]; [`ChordRule::Halved`] divides the chord by the number of
    /// key steps it spans (2 inside, 1 at an end) instead of by seconds.
    pub fn tangents(&self, rule: ChordRule) -> Vec<Vec2> {
        let n = self.times.len();
        let mut out = vec![Vec2::ZERO; n];
        match rule {
            ChordRule::ByTime => {
                curves::cardinal_tangents(&self.times, &self.values, self.tension, &mut out)
            }
            ChordRule::Halved => {
                for (i, d) in out.iter_mut().enumerate() {
                    let (before, after) = (i.saturating_sub(1), (i + 1).min(n - 1));
                    let steps = (after - before) as f32;
                    *d = (self.values[after] - self.values[before]) * (self.tension / steps);
                }
            }
        }
        out
    }

    /// The Hermite track through the keys with `rule`'s tangents.
    pub fn track(&self, rule: ChordRule) -> Track<Vec2> {
        let d = self.tangents(rule);
        Track::new_hermite(self.times.clone(), self.values.clone(), d.clone(), d)
            .valid("preset keys and finite tangents")
    }

    /// The path by `rule`, `samples` points evenly spaced in time.
    pub fn path(&self, rule: ChordRule, samples: usize) -> Result<Vec<Vec2>, String> {
        check_samples(samples)?;
        let track = self.track(rule);
        let mut out = vec![Vec2::ZERO; samples];
        track.positions_evenly(track.start_sec(), track.end_sec(), &mut out);
        Ok(out)
    }

    /// Rows `[t, speed by time, speed halved]` over the keys (s, m/s, m/s).
    pub fn sample_speeds(&self, samples: usize) -> Result<Vec<[f32; 3]>, String> {
        check_samples(samples)?;
        let (a, b) = (self.track(ChordRule::ByTime), self.track(ChordRule::Halved));
        let (t0, t1) = (a.start_sec(), a.end_sec());
        Ok((0..samples)
            .map(|k| {
                let t = t0 + (t1 - t0) * k as f32 / (samples - 1) as f32;
                [t, a.velocity(t).length(), b.velocity(t).length()]
            })
            .collect())
    }

    /// How far the path by `rule` strays from the straight segments between the keys, at most
    /// (metres): the bulge a wrong tangent adds.
    pub fn max_bulge(&self, rule: ChordRule) -> f32 {
        let path = self.path(rule, 2001).expect("a valid sample count");
        path.iter()
            .map(|&p| {
                self.values
                    .windows(2)
                    .map(|w| distance_to_segment(p, w[0], w[1]))
                    .fold(f32::INFINITY, f32::min)
            })
            .fold(0.0, f32::max)
    }

    /// The note under the figure: each rule's largest speed and bulge.
    pub fn note(&self) -> String {
        let line = |rule: ChordRule, name: &str| {
            let top = self
                .sample_speeds(401)
                .expect("a valid sample count")
                .iter()
                .map(|r| {
                    if rule == ChordRule::ByTime {
                        r[1]
                    } else {
                        r[2]
                    }
                })
                .fold(0.0, f32::max);
            // Rounded to the millimetre, so a straight path reads 0 and not 6e-7.
            let bulge = (self.max_bulge(rule) * 1000.0).round() / 1000.0;
            format!(
                "{name}: top speed {} m/s, strays up to {} m from the straight segments.",
                format_number(top),
                format_number(bulge)
            )
        };
        format!(
            "μ = {}. {} {}",
            format_number(self.tension),
            line(ChordRule::ByTime, "Divided by the time (blue)"),
            line(ChordRule::Halved, "Halved (pink)")
        )
    }
}

/// The distance from `p` to the segment `[a, b]`.
fn distance_to_segment(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 {
        ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * t)).length()
}

// ---------------------------------------------------------------------------------------------
// The ease figure: spacing charts of every ease, side by side, and one ease's curve.

/// The eases the page offers, by the names [`ease_from_name`] takes, in the order it lists them.
pub const EASE_NAMES: [&str; 7] = [
    "none",
    "smoothstep",
    "smootherstep",
    "sine",
    "in",
    "out",
    "inout",
];

/// Rows `[x, e(x), e′(x)]` over `x ∈ [0, 1]` for the ease `name`.
pub fn ease_samples(name: &str, samples: usize) -> Result<Vec<[f32; 3]>, String> {
    let ease = ease_from_name(name)?;
    check_samples(samples)?;
    Ok((0..samples)
        .map(|k| {
            let x = k as f32 / (samples - 1) as f32;
            let [e, de, _] = ease.apply_with_derivatives(x);
            [x, e, de]
        })
        .collect())
}

/// The spacing chart of the ease `name`: where `count` frames at equal time steps land, as
/// fractions of the way, `e(k / (count − 1))`.
pub fn spacing_ticks(name: &str, count: usize) -> Result<Vec<f32>, String> {
    let ease = ease_from_name(name)?;
    if !(2..=60).contains(&count) {
        return Err(format!("frames must be from 2 to 60, got {count}"));
    }
    Ok((0..count)
        .map(|k| ease.apply(k as f32 / (count - 1) as f32))
        .collect())
}

/// Whether all of `rect` lies at least `by` px past the line through `from` across `dir` (a unit
/// screen direction): a label on its own side of an axis, or past its tip.
fn lies_beyond(rect: crate::draw::layout::Rect, from: Vec2, dir: Vec2, by: f32) -> bool {
    let nearest = Vec2::select(dir.cmpgt(Vec2::ZERO), rect.min, rect.max());
    (nearest - from).dot(dir) >= by
}
