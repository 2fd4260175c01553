//! Bindings for lesson 02, "Keyframes and splines".
//!
//! The curve editor edits the *path in a plane*: keys `(t_i, x_i, y_i)`, a [`Track<Vec2>`]. The
//! 3D view shows the same path in the world's XY plane (z = 0, Y up), so what the student drags in
//! 2D is exactly what the ball follows in 3D. Everything the page draws or plots is sampled here;
//! JavaScript never interpolates.

use super::{finite, in_range, Viewer};
use crate::curves::{
    self, ArcLengthTable, Ease, Interpolation, Sample, TimeWarp, Track, TrackError,
};
use crate::exercises::{self, NotDone};
use glam::{Mat4, Vec2, Vec3};
use wasm_bindgen::prelude::*;

fn js(e: TrackError) -> JsError {
    JsError::new(&e.to_string())
}

/// Builds `Vec2` keys from `[x0, y0, x1, y1, …]`. An odd count is a mismatch in its own right.
fn pairs(name: &str, xy: &[f32]) -> Result<Vec<Vec2>, JsError> {
    if !xy.len().is_multiple_of(2) {
        return Err(JsError::new(&format!(
            "{name} must hold (x, y) pairs, but it has {} numbers",
            xy.len()
        )));
    }
    Ok(xy.chunks_exact(2).map(|c| Vec2::new(c[0], c[1])).collect())
}

fn scheme_from_name(name: &str, tension: f32) -> Result<Interpolation, JsError> {
    Ok(match name {
        "step" => Interpolation::Step,
        "linear" => Interpolation::Linear,
        "lagrange" => Interpolation::Lagrange,
        "hermite" => Interpolation::Hermite,
        "cardinal" => Interpolation::Cardinal { tension },
        "natural" => Interpolation::Natural,
        "centripetal" => Interpolation::Centripetal,
        other => {
            return Err(JsError::new(&format!(
                "unknown scheme '{other}': use step, linear, lagrange, hermite, cardinal, natural or centripetal"
            )))
        }
    })
}

fn ease_from_name(name: &str) -> Result<Ease, JsError> {
    Ok(match name {
        "none" | "linear" => Ease::Linear,
        "smoothstep" => Ease::Smoothstep,
        "smootherstep" => Ease::Smootherstep,
        "sine" => Ease::Sine,
        "in" => Ease::In { power: 2.0 },
        "out" => Ease::Out { power: 2.0 },
        "inout" => Ease::InOut { power: 3.0 },
        other => {
            return Err(JsError::new(&format!(
                "unknown ease '{other}': use none, smoothstep, smootherstep, sine, in, out or inout"
            )))
        }
    })
}

const PATH_COLOR: Vec3 = Vec3::new(0.15, 0.25, 0.55);
const KEY_COLOR: Vec3 = Vec3::new(0.95, 0.55, 0.1);
const GHOST_COLOR: Vec3 = Vec3::new(0.55, 0.55, 0.6);
const BALL_COLOR: Vec3 = Vec3::new(0.85, 0.2, 0.25);
const TANGENT_COLOR: Vec3 = Vec3::new(0.1, 0.6, 0.35);
/// Seconds of motion a tangent handle stands for: the handle is `d · HANDLE_SEC` long.
const HANDLE_SEC: f32 = 0.25;
const ARC_TABLE_SUBDIVISIONS: usize = 24;

/// Figure 1: keys in a plane, the curve through them, and a ball moving along it.
#[wasm_bindgen]
pub struct KeyframesScene {
    track: Track<Vec2>,
    scheme_name: String,
    tension: f32,
    table: ArcLengthTable,
    arc_length: bool,
    ease: Ease,
    use_exercise: bool,
    ghost_count: usize,
    // Scratch, reused every frame (nothing allocated per frame once sized).
    path: Vec<Vec3>,
    ghosts: Vec<Vec2>,
    student_tangents: Vec<Vec2>,
    channel: [Vec<f32>; 3],
}

#[wasm_bindgen]
impl KeyframesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> KeyframesScene {
        let times = vec![0.0, 0.8, 1.6, 2.2, 3.2];
        let values = vec![
            Vec2::new(-2.4, 0.3),
            Vec2::new(-1.2, 1.7),
            Vec2::new(0.0, 0.5),
            Vec2::new(1.1, 1.9),
            Vec2::new(2.4, 0.6),
        ];
        let track = Track::new(times, values)
            .expect("valid default keys")
            .with_interpolation(Interpolation::CATMULL_ROM)
            .expect("valid tension");
        let table = ArcLengthTable::new(&track, ARC_TABLE_SUBDIVISIONS);
        KeyframesScene {
            track,
            scheme_name: "cardinal".into(),
            tension: 1.0,
            table,
            arc_length: false,
            ease: Ease::Linear,
            use_exercise: false,
            ghost_count: 24,
            path: Vec::new(),
            ghosts: Vec::new(),
            student_tangents: Vec::new(),
            channel: [Vec::new(), Vec::new(), Vec::new()],
        }
    }

    /// Replaces the keys: `times_sec` strictly increasing, `xy = [x0, y0, x1, y1, …]` (metres),
    /// one pair per time. Hermite tangents are kept when the number of keys is unchanged (a key was
    /// dragged), otherwise they restart as Catmull-Rom tangents. Errors name the rule broken (NaN,
    /// unsorted times, mismatched lengths); the scene is then unchanged.
    #[wasm_bindgen(js_name = setKeys)]
    pub fn set_keys(&mut self, times_sec: Vec<f32>, xy: Vec<f32>) -> Result<(), JsError> {
        let values = pairs("xy", &xy)?;
        let n = times_sec.len();
        let keep_tangents =
            self.track.interpolation() == Interpolation::Hermite && n == self.track.key_count();
        let track = if keep_tangents {
            let (tin, tout) = (
                self.track.tangents_in().to_vec(),
                self.track.tangents_out().to_vec(),
            );
            Track::new_hermite(times_sec, values, tin, tout).map_err(js)?
        } else {
            let scheme = scheme_from_name(&self.scheme_name, self.tension)?;
            let auto = if scheme == Interpolation::Hermite {
                Interpolation::CATMULL_ROM
            } else {
                scheme
            };
            let mut track = Track::new(times_sec, values)
                .map_err(js)?
                .with_interpolation(auto)
                .map_err(js)?;
            track.set_interpolation(scheme).map_err(js)?;
            track
        };
        self.install(track);
        Ok(())
    }

    /// Sets every key's in and out tangents (`[x0, y0, x1, y1, …]`, metres per second) and switches
    /// to Hermite. Errors: not one tangent of each kind per key, or NaN.
    #[wasm_bindgen(js_name = setTangents)]
    pub fn set_tangents(
        &mut self,
        tangents_in: Vec<f32>,
        tangents_out: Vec<f32>,
    ) -> Result<(), JsError> {
        let (tin, tout) = (
            pairs("tangentsIn", &tangents_in)?,
            pairs("tangentsOut", &tangents_out)?,
        );
        let track = Track::new_hermite(
            self.track.times().to_vec(),
            self.track.values().to_vec(),
            tin,
            tout,
        )
        .map_err(js)?;
        self.scheme_name = "hermite".into();
        self.install(track);
        Ok(())
    }

    /// Sets key `index`'s in and out tangents (metres per second) and switches to Hermite.
    #[wasm_bindgen(js_name = setKeyTangent)]
    pub fn set_key_tangent(
        &mut self,
        index: usize,
        in_x: f32,
        in_y: f32,
        out_x: f32,
        out_y: f32,
    ) -> Result<(), JsError> {
        let mut track = self.track.clone();
        track
            .set_tangents(index, Vec2::new(in_x, in_y), Vec2::new(out_x, out_y))
            .map_err(js)?;
        self.scheme_name = "hermite".into();
        self.install(track);
        Ok(())
    }

    /// "step", "linear", "lagrange", "hermite", "cardinal", "natural" or "centripetal".
    /// Switching to Hermite keeps the current curve and makes its tangents editable.
    #[wasm_bindgen(js_name = setScheme)]
    pub fn set_scheme(&mut self, name: &str) -> Result<(), JsError> {
        let scheme = scheme_from_name(name, self.tension)?;
        let mut track = self.track.clone();
        track.set_interpolation(scheme).map_err(js)?;
        self.scheme_name = name.to_string();
        self.install(track);
        Ok(())
    }

    /// The cardinal tension `μ ∈ [0, 2]` (1 = Catmull-Rom); used by the "cardinal" scheme.
    #[wasm_bindgen(js_name = setTension)]
    pub fn set_tension(&mut self, tension: f32) -> Result<(), JsError> {
        if !(0.0..=2.0).contains(&tension) {
            return Err(js(TrackError::TensionOutOfRange { tension }));
        }
        self.tension = tension;
        if self.scheme_name == "cardinal" {
            let mut track = self.track.clone();
            track
                .set_interpolation(Interpolation::Cardinal { tension })
                .map_err(js)?;
            self.install(track);
        }
        Ok(())
    }

    /// On: the ball travels the same path at constant speed (arc-length parametrisation).
    #[wasm_bindgen(js_name = setArcLength)]
    pub fn set_arc_length(&mut self, on: bool) {
        self.arc_length = on;
    }

    /// Timing over the whole motion: "none", "smoothstep", "smootherstep", "sine", "in", "out", "inout".
    #[wasm_bindgen(js_name = setEase)]
    pub fn set_ease(&mut self, name: &str) -> Result<(), JsError> {
        self.ease = ease_from_name(name)?;
        Ok(())
    }

    /// Number of in-betweens in the ghost trail (2 to 200).
    #[wasm_bindgen(js_name = setGhostCount)]
    pub fn set_ghost_count(&mut self, count: usize) -> Result<(), JsError> {
        if !(2..=200).contains(&count) {
            return Err(JsError::new(&format!(
                "the ghost count must be between 2 and 200, got {count}"
            )));
        }
        self.ghost_count = count;
        Ok(())
    }

    /// Swaps the reference core for the student's functions in `src/exercises/curves.rs`.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: bool) {
        self.use_exercise = on;
    }

    /// The current scheme's name (the tangent edits switch it to "hermite").
    #[wasm_bindgen(getter)]
    pub fn scheme(&self) -> String {
        self.scheme_name.clone()
    }

    /// Keys as `[t0, x0, y0, t1, x1, y1, …]`.
    pub fn keys(&self) -> Vec<f32> {
        self.track
            .times()
            .iter()
            .zip(self.track.values())
            .flat_map(|(t, p)| [*t, p.x, p.y])
            .collect()
    }

    /// Tangents as `[in_x0, in_y0, out_x0, out_y0, …]`, metres per second.
    pub fn tangents(&self) -> Vec<f32> {
        self.track
            .tangents_in()
            .iter()
            .zip(self.track.tangents_out())
            .flat_map(|(a, b)| [a.x, a.y, b.x, b.y])
            .collect()
    }

    /// Seconds a tangent handle stands for (handle end = key + d · handleSec).
    #[wasm_bindgen(getter, js_name = handleSec)]
    pub fn handle_sec(&self) -> f32 {
        HANDLE_SEC
    }

    /// Duration of the motion, from the first key to the last, in seconds.
    #[wasm_bindgen(getter, js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.track.duration_sec()
    }

    /// The path, `samples` points evenly spaced in time over the keys: `[x0, y0, x1, y1, …]`.
    #[wasm_bindgen(js_name = samplePath)]
    pub fn sample_path(&self, samples: usize) -> Result<Vec<f32>, JsError> {
        super::check_samples(samples)?;
        let mut out = vec![Vec2::ZERO; samples];
        self.track
            .positions_evenly(self.track.start_sec(), self.track.end_sec(), &mut out);
        Ok(out.iter().flat_map(|p| [p.x, p.y]).collect())
    }

    /// The in-betweens of the motion (arc length and ease applied), evenly spaced in time:
    /// `[x0, y0, …]`. Their spacing shows the speed.
    #[wasm_bindgen(js_name = sampleGhosts)]
    pub fn sample_ghosts(&mut self) -> Vec<f32> {
        self.fill_ghosts();
        self.ghosts.iter().flat_map(|p| [p.x, p.y]).collect()
    }

    /// Where the ball is at `time_sec` after the first key: `[x, y]`.
    pub fn position(&self, time_sec: f32) -> Result<Vec<f32>, JsError> {
        let p = self.motion(finite("time", time_sec)?).position;
        Ok(vec![p.x, p.y])
    }

    /// For the plots, `samples` rows over the motion: `[τ, speed keyed, speed arc length,
    /// |acceleration| of the motion shown, …]` (τ in seconds from the first key, speeds in m/s,
    /// acceleration in m/s²). "Keyed" is the track as keyed (with the ease), "arc length" the
    /// same path at constant speed (with the ease).
    #[wasm_bindgen(js_name = sampleMotion)]
    pub fn sample_motion(&self, samples: usize) -> Result<Vec<f32>, JsError> {
        super::check_samples(samples)?;
        let duration = self.track.duration_sec();
        let mut out = Vec::with_capacity(samples * 4);
        for k in 0..samples {
            let tau = duration * k as f32 / (samples - 1) as f32;
            let keyed = self.keyed_motion(tau);
            let arc = self.arc_motion(tau);
            let shown = if self.arc_length { arc } else { keyed };
            out.extend_from_slice(&[
                tau,
                keyed.velocity.length(),
                arc.velocity.length(),
                shown.acceleration.length(),
            ]);
        }
        Ok(out)
    }

    /// Draws the 3D view at `time_sec` (seconds after the first key; wraps around). Returns a
    /// note for the page: empty, or which exercises are not done yet.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let time_sec = finite("time", time_sec)?;
        let duration = self.track.duration_sec();
        let tau = if duration > 0.0 {
            time_sec.rem_euclid(duration)
        } else {
            0.0
        };
        let mut note = String::new();
        let ball;
        self.path.clear();
        const PATH_SAMPLES: usize = 200;
        if self.use_exercise {
            let mut missing = Vec::new();
            self.prepare_student_tangents(&mut missing);
            let (t0, t1) = (self.track.start_sec(), self.track.end_sec());
            for k in 0..PATH_SAMPLES {
                let t = t0 + (t1 - t0) * k as f32 / (PATH_SAMPLES - 1) as f32;
                let p = self.student_position(t, &mut missing);
                self.path.push(p.extend(0.0));
            }
            self.ghosts.resize(self.ghost_count, Vec2::ZERO);
            for k in 0..self.ghost_count {
                let tau_k = duration * k as f32 / (self.ghost_count - 1) as f32;
                self.ghosts[k] = self.student_motion(tau_k, &mut missing);
            }
            ball = self.student_motion(tau, &mut missing);
            missing.sort_unstable();
            missing.dedup();
            note = if missing.is_empty() {
                "Showing your exercises (the plots use the reference).".to_string()
            } else {
                format!("Not done yet: {} (src/exercises/curves.rs). The figure uses the reference for those steps.", missing.join(", "))
            };
        } else {
            let mut out = [Vec2::ZERO; PATH_SAMPLES];
            self.track
                .positions_evenly(self.track.start_sec(), self.track.end_sec(), &mut out);
            self.path.extend(out.iter().map(|p| p.extend(0.0)));
            self.fill_ghosts();
            ball = self.motion(tau).position;
        }

        let frame = &mut viewer.renderer.frame;
        frame.grid(12, 0.5);
        frame.polyline(&self.path, PATH_COLOR);
        for g in &self.ghosts {
            frame.point(g.extend(0.0), 0.045, GHOST_COLOR);
        }
        for (i, p) in self.track.values().iter().enumerate() {
            frame.point(p.extend(0.0), 0.07, KEY_COLOR);
            if self.track.interpolation() == Interpolation::Hermite {
                let (a, b) = (self.track.tangents_in()[i], self.track.tangents_out()[i]);
                frame.line(
                    (*p - a * HANDLE_SEC).extend(0.0),
                    p.extend(0.0),
                    TANGENT_COLOR,
                );
                frame.line(
                    p.extend(0.0),
                    (*p + b * HANDLE_SEC).extend(0.0),
                    TANGENT_COLOR,
                );
            }
            // A thin stem to the ground makes the plane's depth readable.
            frame.line(Vec3::new(p.x, 0.0, 0.0), p.extend(0.0), Vec3::splat(0.75));
        }
        frame.mesh(
            viewer.renderer.sphere,
            Mat4::from_translation(ball.extend(0.0)) * Mat4::from_scale(Vec3::splat(0.16)),
            BALL_COLOR,
        );
        viewer.present()?;
        Ok(note)
    }
}

impl Default for KeyframesScene {
    fn default() -> Self {
        Self::new()
    }
}

impl KeyframesScene {
    fn install(&mut self, track: Track<Vec2>) {
        self.table = ArcLengthTable::new(&track, ARC_TABLE_SUBDIVISIONS);
        self.track = track;
    }

    fn warp(&self) -> TimeWarp {
        TimeWarp::over(&self.track, self.ease)
    }

    /// The keyed motion with the ease, at `tau` seconds after the first key.
    fn keyed_motion(&self, tau: f32) -> Sample<Vec2> {
        self.track
            .evaluate_warped(&self.warp(), self.track.start_sec() + tau)
    }

    /// The same path at constant speed (times the ease): `s(τ) = L · (w(τ) − t0) / T`.
    /// Velocity: the unit direction times `ds/dτ`; acceleration by central differences of it.
    fn arc_motion(&self, tau: f32) -> Sample<Vec2> {
        let position = |tau: f32| self.arc_position(tau);
        let duration = self.track.duration_sec().max(1e-6);
        let h = 1e-3 * duration;
        let (lo, hi) = ((tau - h).max(0.0), (tau + h).min(duration));
        let (a, p, b) = (position(lo), position(tau), position(hi));
        let velocity = (b - a) / (hi - lo);
        let v_lo = (p - a) / (tau - lo).max(1e-9);
        let v_hi = (b - p) / (hi - tau).max(1e-9);
        let acceleration = if hi > tau && tau > lo {
            (v_hi - v_lo) / ((hi - lo) * 0.5)
        } else {
            Vec2::ZERO
        };
        Sample {
            position: p,
            velocity,
            acceleration,
        }
    }

    fn arc_position(&self, tau: f32) -> Vec2 {
        let s = self.arc_fraction(tau) * self.table.total_length();
        self.table.position_at_length(&self.track, s)
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

    fn motion(&self, tau: f32) -> Sample<Vec2> {
        if self.arc_length {
            Sample {
                position: self.arc_position(tau),
                ..Default::default()
            }
        } else {
            self.keyed_motion(tau)
        }
    }

    fn fill_ghosts(&mut self) {
        let duration = self.track.duration_sec();
        let n = self.ghost_count;
        self.ghosts.resize(n, Vec2::ZERO);
        for k in 0..n {
            let tau = duration * k as f32 / (n - 1) as f32;
            self.ghosts[k] = self.motion(tau).position;
        }
    }

    // ---- The same motion computed with the student's exercises (src/exercises/curves.rs). ----

    /// Tangents for the student path: exercise 2.2 for the cardinal scheme (one channel at a
    /// time), the track's own tangents otherwise.
    fn prepare_student_tangents(&mut self, missing: &mut Vec<&'static str>) {
        let n = self.track.key_count();
        self.student_tangents.clear();
        self.student_tangents
            .extend_from_slice(self.track.tangents_out());
        if self.scheme_name != "cardinal" {
            return;
        }
        let [xs, ys, out] = &mut self.channel;
        xs.clear();
        ys.clear();
        xs.extend(self.track.values().iter().map(|p| p.x));
        ys.extend(self.track.values().iter().map(|p| p.y));
        out.clear();
        out.resize(n, 0.0);
        let times = self.track.times();
        if exercises::curves::cardinal_tangents(times, xs, self.tension, out) == Err(NotDone) {
            missing.push("exercise 2.2 cardinal_tangents");
            return;
        }
        let dx = out.clone();
        if exercises::curves::cardinal_tangents(times, ys, self.tension, out) == Err(NotDone) {
            missing.push("exercise 2.2 cardinal_tangents");
            return;
        }
        for (i, d) in self.student_tangents.iter_mut().enumerate() {
            *d = Vec2::new(dx[i], out[i]);
        }
    }

    /// `p(t)` at a time inside the keys, with exercises 2.3 (segment) and 2.1 (basis).
    fn student_position(&self, t: f32, missing: &mut Vec<&'static str>) -> Vec2 {
        let (times, values) = (self.track.times(), self.track.values());
        let n = times.len();
        let cubic = matches!(
            self.track.interpolation(),
            Interpolation::Hermite
                | Interpolation::Cardinal { .. }
                | Interpolation::Natural
                | Interpolation::Centripetal
        );
        if n < 2
            || !(cubic
                || matches!(
                    self.track.interpolation(),
                    Interpolation::Step | Interpolation::Linear
                ))
        {
            return self.track.position(t);
        }
        let t = t.clamp(times[0], times[n - 1]);
        let i = match exercises::curves::find_segment(times, t) {
            // A wrong index must not crash the page: keep it inside the keys.
            Ok(i) => i.min(n - 2),
            Err(NotDone) => {
                missing.push("exercise 2.3 find_segment");
                curves::find_segment(times, t)
            }
        };
        let h = times[i + 1] - times[i];
        let s = (t - times[i]) / h;
        match self.track.interpolation() {
            Interpolation::Step => return if s >= 1.0 { values[i + 1] } else { values[i] },
            Interpolation::Linear => return values[i].lerp(values[i + 1], s),
            _ => {}
        }
        let [h00, h10, h01, h11] = exercises::curves::hermite_basis(s).unwrap_or_else(|NotDone| {
            missing.push("exercise 2.1 hermite_basis");
            curves::hermite_basis(s)
        });
        let d0 = self.student_tangents[i];
        // The in tangent of the next key: equal to its out tangent except for a broken Hermite key.
        let d1 = if self.scheme_name == "cardinal" {
            self.student_tangents[i + 1]
        } else {
            self.track.tangents_in()[i + 1]
        };
        values[i] * h00 + d0 * (h * h10) + values[i + 1] * h01 + d1 * (h * h11)
    }

    /// The ball's position at `τ`, with exercise 2.4 for the arc-length lookup.
    fn student_motion(&self, tau: f32, missing: &mut Vec<&'static str>) -> Vec2 {
        let t = if self.arc_length {
            let s = self.arc_fraction(tau) * self.table.total_length();
            let (params, lengths) = (self.table.times_sec(), self.table.lengths());
            match exercises::curves::arc_length_invert(params, lengths, s) {
                Ok(u) if u.is_finite() => u,
                Ok(_) => self.track.start_sec(),
                Err(NotDone) => {
                    missing.push("exercise 2.4 arc_length_invert");
                    curves::arc_length_invert(params, lengths, s)
                }
            }
        } else {
            self.warp().warp(self.track.start_sec() + tau)[0]
        };
        self.student_position(t, missing)
    }
}

/// Figure 2: one polynomial through all keys (Lagrange), with `n` keys and with two more.
#[wasm_bindgen]
pub struct LagrangeScene {
    keys: usize,
    show_spline: bool,
    base: Vec<Vec3>,
    more: Vec<Vec3>,
    spline: Vec<Vec3>,
}

#[wasm_bindgen]
impl LagrangeScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> LagrangeScene {
        let mut scene = LagrangeScene {
            keys: 10,
            show_spline: true,
            base: Vec::new(),
            more: Vec::new(),
            spline: Vec::new(),
        };
        scene.rebuild().expect("valid default keys");
        scene
    }

    /// Number of keys of the first curve (3 to 16); the second curve has two more.
    #[wasm_bindgen(js_name = setKeyCount)]
    pub fn set_key_count(&mut self, keys: f32) -> Result<(), JsError> {
        self.keys = in_range("key count", keys, 3.0, 16.0)?.round() as usize;
        self.rebuild()
    }

    /// Also draw a Catmull-Rom spline through the larger set of keys, for comparison.
    #[wasm_bindgen(js_name = setShowSpline)]
    pub fn set_show_spline(&mut self, on: bool) {
        self.show_spline = on;
    }

    /// Keys of the first curve then of the second, as `[n, t0, y0, …, m, t0, y0, …]`.
    pub fn keys(&self) -> Vec<f32> {
        let (a, b) = self.key_sets();
        let mut out = vec![a.0.len() as f32];
        out.extend(a.0.iter().zip(&a.1).flat_map(|(t, y)| [*t, *y]));
        out.push(b.0.len() as f32);
        out.extend(b.0.iter().zip(&b.1).flat_map(|(t, y)| [*t, *y]));
        out
    }

    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<(), JsError> {
        let frame = &mut viewer.renderer.frame;
        frame.grid(12, 0.5);
        frame.polyline(&self.base, Vec3::new(0.15, 0.3, 0.85));
        frame.polyline(&self.more, Vec3::new(0.85, 0.15, 0.15));
        if self.show_spline {
            frame.polyline(&self.spline, Vec3::new(0.2, 0.65, 0.3));
        }
        let (a, b) = self.key_sets();
        for (t, y) in b.0.iter().zip(&b.1) {
            let extra = !a.0.contains(t);
            let p = self.place(*t, *y);
            frame.point(
                p,
                if extra { 0.08 } else { 0.06 },
                if extra {
                    Vec3::new(0.85, 0.15, 0.15)
                } else {
                    KEY_COLOR
                },
            );
        }
        viewer.present()
    }
}

impl Default for LagrangeScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Key times and values of one Lagrange curve.
type KeySet = (Vec<f32>, Vec<f32>);

impl LagrangeScene {
    /// One curve-editor channel y(t): keys at t = 0, 1, …, n−1 on a gentle wave, and the same
    /// keys plus two more, a quarter and three quarters of the way, slightly off the wave.
    fn key_sets(&self) -> (KeySet, KeySet) {
        let n = self.keys;
        let wave = |t: f32| 0.9 + 0.55 * (0.55 * t).sin() + 0.12 * (1.7 * t).cos();
        let times: Vec<f32> = (0..n).map(|i| i as f32).collect();
        let values: Vec<f32> = times.iter().map(|&t| wave(t)).collect();
        let mut more: Vec<(f32, f32)> = times.iter().copied().zip(values.iter().copied()).collect();
        // Never on an integer time, and distinct for n ≥ 3.
        let (a, b) = ((n - 1) as f32 * 0.25 + 0.1, (n - 1) as f32 * 0.75 - 0.1);
        more.push((a, wave(a) + 0.08));
        more.push((b, wave(b) - 0.08));
        more.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (more_t, more_v) = more.into_iter().unzip();
        ((times, values), (more_t, more_v))
    }

    /// The channel drawn in the XY plane: time along x (scaled to a fixed width), value up.
    fn place(&self, t: f32, y: f32) -> Vec3 {
        Vec3::new((t / (self.keys - 1) as f32 - 0.5) * 5.6, y, 0.0)
    }

    fn rebuild(&mut self) -> Result<(), JsError> {
        let ((ta, ya), (tb, yb)) = self.key_sets();
        let a = Track::new(ta, ya)
            .map_err(js)?
            .with_interpolation(Interpolation::Lagrange)
            .map_err(js)?;
        let b = Track::new(tb, yb)
            .map_err(js)?
            .with_interpolation(Interpolation::Lagrange)
            .map_err(js)?;
        let spline = b
            .clone()
            .with_interpolation(Interpolation::CATMULL_ROM)
            .map_err(js)?;
        const SAMPLES: usize = 400;
        // The polynomial can shoot far off between keys: clip what we draw to a readable band.
        let clip = |y: f32| y.clamp(-0.8, 3.4);
        let mut lines = [
            std::mem::take(&mut self.base),
            std::mem::take(&mut self.more),
            std::mem::take(&mut self.spline),
        ];
        for (track, out) in [&a, &b, &spline].into_iter().zip(&mut lines) {
            out.clear();
            let (t0, t1) = (track.start_sec(), track.end_sec());
            out.extend((0..SAMPLES).map(|k| {
                let t = t0 + (t1 - t0) * k as f32 / (SAMPLES - 1) as f32;
                self.place(t, clip(track.position(t)))
            }));
        }
        [self.base, self.more, self.spline] = lines;
        Ok(())
    }
}
