//! Bindings for lesson 02, "Keyframes and splines": thin wrappers over
//! [`crate::figures::curves`], which holds the scenes' logic and is tested natively.
//! Flat arrays cross the boundary (`[x0, y0, x1, y1, …]`); errors become `JsError`s.

use super::{js, Viewer};
use crate::figures::curves as fig;
use glam::Vec2;
use wasm_bindgen::prelude::*;

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

fn flat(points: &[Vec2]) -> Vec<f32> {
    points.iter().flat_map(|p| [p.x, p.y]).collect()
}

/// Figure 1 (and the comparisons): keys in a plane, the curve through them, a moving ball.
#[wasm_bindgen]
pub struct KeyframesScene {
    scene: fig::KeyframesScene,
}

#[wasm_bindgen]
impl KeyframesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> KeyframesScene {
        let mut scene = fig::KeyframesScene::new();
        scene.set_runner(super::sandbox::run);
        KeyframesScene { scene }
    }

    /// Replaces the keys: `times_sec` strictly increasing, `xy = [x0, y0, x1, y1, …]` (metres).
    /// Errors name the rule broken (NaN, unsorted times, mismatched lengths, too many keys); the
    /// scene is then unchanged. Cap (the curve's work grows with the keys): at most 1000 keys
    /// (`figures::curves::MAX_KEYS`).
    #[wasm_bindgen(js_name = setKeys)]
    pub fn set_keys(&mut self, times_sec: Vec<f32>, xy: Vec<f32>) -> Result<(), JsError> {
        let values = pairs("xy", &xy)?;
        self.scene.set_keys(times_sec, values).map_err(js)
    }

    /// Loads the keys of a preset: "default", "loop", "uneven" or "centripetal".
    #[wasm_bindgen(js_name = loadPreset)]
    pub fn load_preset(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        let (times, values) = fig::preset(name).map_err(js)?;
        self.scene.set_keys(times, values).map_err(js)
    }

    /// Sets every key's in and out tangents (`[x0, y0, …]`, m/s) and switches to Hermite.
    #[wasm_bindgen(js_name = setTangents)]
    pub fn set_tangents(
        &mut self,
        tangents_in: Vec<f32>,
        tangents_out: Vec<f32>,
    ) -> Result<(), JsError> {
        let tin = pairs("tangentsIn", &tangents_in)?;
        let tout = pairs("tangentsOut", &tangents_out)?;
        self.scene.set_tangents(tin, tout).map_err(js)
    }

    /// Sets key `index`'s in and out tangents (m/s) and switches to Hermite.
    #[wasm_bindgen(js_name = setKeyTangent)]
    pub fn set_key_tangent(
        &mut self,
        index: f64,
        in_x: f32,
        in_y: f32,
        out_x: f32,
        out_y: f32,
    ) -> Result<(), JsError> {
        let index = super::whole("index", index)?;
        let (tin, tout) = (Vec2::new(in_x, in_y), Vec2::new(out_x, out_y));
        self.scene.set_key_tangent(index, tin, tout).map_err(js)
    }

    /// "step", "linear", "lagrange", "hermite", "cardinal", "natural" or "centripetal".
    #[wasm_bindgen(js_name = setScheme)]
    pub fn set_scheme(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_scheme(name).map_err(js)
    }

    /// The cardinal tension `μ ∈ [0, 2]` (1 = Catmull-Rom).
    #[wasm_bindgen(js_name = setTension)]
    pub fn set_tension(&mut self, tension: f32) -> Result<(), JsError> {
        self.scene.set_tension(tension).map_err(js)
    }

    /// On: the ball travels the same path at constant speed (arc-length parametrisation).
    #[wasm_bindgen(js_name = setArcLength)]
    pub fn set_arc_length(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_arc_length(on);
        Ok(())
    }

    /// "none", "smoothstep", "smootherstep", "sine", "in", "out" or "inout".
    #[wasm_bindgen(js_name = setEase)]
    pub fn set_ease(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_ease(name).map_err(js)
    }

    /// Number of in-betweens in the ghost trail (2 to 200).
    #[wasm_bindgen(js_name = setGhostCount)]
    pub fn set_ghost_count(&mut self, count: f64) -> Result<(), JsError> {
        let count = super::whole("count", count)?;
        self.scene.set_ghost_count(count).map_err(js)
    }

    /// Draws and checks with the student's functions in `src/exercises/curves.rs`.
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }

    /// The current scheme's name (the tangent edits switch it to "hermite").
    #[wasm_bindgen(getter)]
    pub fn scheme(&self) -> String {
        self.scene.scheme().to_string()
    }

    /// Keys as `[t0, x0, y0, t1, x1, y1, …]`.
    pub fn keys(&self) -> Vec<f32> {
        let track = self.scene.track();
        let keys = track.times().iter().zip(track.values());
        keys.flat_map(|(t, p)| [*t, p.x, p.y]).collect()
    }

    /// Tangents as `[in_x0, in_y0, out_x0, out_y0, …]`, metres per second.
    pub fn tangents(&self) -> Vec<f32> {
        let track = self.scene.track();
        let pairs = track.tangents_in().iter().zip(track.tangents_out());
        pairs.flat_map(|(a, b)| [a.x, a.y, b.x, b.y]).collect()
    }

    /// Seconds a tangent handle stands for (handle end = key + d · handleSec).
    #[wasm_bindgen(getter, js_name = handleSec)]
    pub fn handle_sec(&self) -> f32 {
        fig::HANDLE_SEC
    }

    /// From the first key to the last, in seconds.
    #[wasm_bindgen(getter, js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        self.scene.track().duration_sec()
    }

    /// The time of the first key, in seconds: the scene's clock `τ` is measured from it.
    #[wasm_bindgen(getter, js_name = startSec)]
    pub fn start_sec(&self) -> f32 {
        self.scene.track().start_sec()
    }

    /// How long the clock runs before it loops: the duration plus a short hold on the last key.
    #[wasm_bindgen(getter, js_name = loopSec)]
    pub fn loop_sec(&self) -> f32 {
        self.scene.loop_sec()
    }

    /// True for step: the path is the held values (the keys), joined by jumps, not a curve.
    #[wasm_bindgen(getter, js_name = isHeld)]
    pub fn is_held(&self) -> bool {
        self.scene.is_held()
    }

    /// On: the 3D view also draws the motion in space and time (the clock along the depth).
    #[wasm_bindgen(js_name = setTimeDepth)]
    pub fn set_time_depth(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_time_depth(on);
        Ok(())
    }

    /// The largest distance between this motion and `other` at the same moment (Figure 7).
    #[wasm_bindgen(js_name = gapNote)]
    pub fn gap_note(&self, other: &KeyframesScene) -> String {
        self.scene.gap_note(&other.scene)
    }

    /// Empty, or why "constant speed" does not apply to the current scheme (step).
    #[wasm_bindgen(getter, js_name = timingNote)]
    pub fn timing_note(&self) -> String {
        self.scene.timing_note()
    }

    /// The path through every key, sampled segment by segment: `[x0, y0, x1, y1, …]` (for step,
    /// the held values).
    #[wasm_bindgen(js_name = samplePath)]
    pub fn sample_path(&self) -> Vec<f32> {
        let mut out = Vec::new();
        self.scene.path(&mut out);
        flat(&out)
    }

    /// The in-betweens (arc length and ease applied), evenly spaced in time: `[x0, y0, …]`.
    #[wasm_bindgen(js_name = sampleGhosts)]
    pub fn sample_ghosts(&self) -> Vec<f32> {
        let mut out = Vec::new();
        self.scene.ghosts(&mut out);
        flat(&out)
    }

    /// Where the ball is at `tau` seconds after the first key (wrapped into the loop): `[x, y]`.
    pub fn position(&self, tau: f32) -> Result<Vec<f32>, JsError> {
        let tau = super::finite("time", tau)?; // before wrapping: NaN.min(x) is x
        let p = self.scene.position(self.scene.wrap(tau)).map_err(js)?;
        Ok(vec![p.x, p.y])
    }

    /// `samples` rows `[t, speed keyed, speed arc length, |acceleration| shown, …]`, `t` in the
    /// keys' seconds, speeds in m/s, acceleration in m/s².
    /// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
    #[wasm_bindgen(js_name = sampleMotion)]
    pub fn sample_motion(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        let rows = self.scene.sample_motion(samples).map_err(js)?;
        Ok(rows.concat())
    }

    /// Draws the 3D view at `tau` seconds after the first key; returns the note for the page.
    pub fn draw(&mut self, viewer: &mut Viewer, tau: f32) -> Result<String, JsError> {
        // The time axis's labels are placed for the last frame's view.
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, tau)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for KeyframesScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Rows `[s, h00, h10, h01, h11, …]` of the Hermite basis over `s ∈ [0, 1]`.
/// `samples` in [2, 10000] (the plots' cap, `figures::MAX_SAMPLES`; the work grows with it).
#[wasm_bindgen(js_name = hermiteBasisSamples)]
pub fn hermite_basis_samples(samples: f64) -> Result<Vec<f32>, JsError> {
    let samples = super::whole("samples", samples)?;
    Ok(fig::hermite_basis_samples(samples).map_err(js)?.concat())
}

/// The note beside the basis plot at `s` (exercise 2.1 checked with `use_exercise`).
#[wasm_bindgen(js_name = hermiteBasisNote)]
pub fn hermite_basis_note(s: f32, use_exercise: JsValue) -> Result<String, JsError> {
    let use_exercise = super::boolean("use_exercise", &use_exercise)?;
    fig::hermite_basis_note(super::sandbox::run, s, use_exercise).map_err(js)
}

/// Figure 3: one polynomial through all keys (Lagrange), with `n` keys and with two more.
#[wasm_bindgen]
pub struct LagrangeScene {
    scene: fig::LagrangeScene,
}

#[wasm_bindgen]
impl LagrangeScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> LagrangeScene {
        LagrangeScene {
            scene: fig::LagrangeScene::new(),
        }
    }

    /// Number of keys of the first curve (3 to 16); the second curve has two more.
    #[wasm_bindgen(js_name = setKeyCount)]
    pub fn set_key_count(&mut self, keys: f32) -> Result<(), JsError> {
        self.scene.set_key_count(keys).map_err(js)
    }

    /// Also draw a Catmull-Rom spline through the larger set of keys, for comparison.
    #[wasm_bindgen(js_name = setShowSpline)]
    pub fn set_show_spline(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_show_spline(on);
        Ok(())
    }

    /// Keys of the first curve then of the second, as `[n, t0, y0, …, m, t0, y0, …]`.
    pub fn keys(&self) -> Vec<f32> {
        let (a, b) = self.scene.key_sets();
        let mut out = Vec::new();
        for (times, values) in [a, b] {
            out.push(times.len() as f32);
            out.extend(times.iter().zip(&values).flat_map(|(t, y)| [*t, *y]));
        }
        out
    }

    /// The largest gap between the curves and the red polynomial's largest |y| (see the core).
    #[wasm_bindgen(getter)]
    pub fn note(&self) -> String {
        self.scene.note().to_string()
    }

    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<(), JsError> {
        // The time axis's numbers are placed for the last frame's view.
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()
    }
}

impl Default for LagrangeScene {
    fn default() -> Self {
        Self::new()
    }
}

/// The cardinal figure: a spline whose tangents come from the chord between each key's
/// neighbours, divided by the time between them (left) or halved (right).
#[wasm_bindgen]
pub struct CardinalScene {
    scene: fig::CardinalScene,
}

#[wasm_bindgen]
impl CardinalScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> CardinalScene {
        CardinalScene {
            scene: fig::CardinalScene::new(),
        }
    }

    /// "default", "loop", "uneven" or "centripetal".
    #[wasm_bindgen(js_name = setPreset)]
    pub fn set_preset(&mut self, name: JsValue) -> Result<(), JsError> {
        let name = super::string("name", &name)?;
        self.scene.set_preset(&name).map_err(js)
    }

    /// The tension μ, 0 to 2.
    #[wasm_bindgen(js_name = setTension)]
    pub fn set_tension(&mut self, tension: f32) -> Result<(), JsError> {
        self.scene.set_tension(tension).map_err(js)
    }

    /// `[t0, x0, y0, t1, …]`: the keys.
    pub fn keys(&self) -> Vec<f32> {
        let (times, values) = self.scene.keys();
        times
            .iter()
            .zip(values)
            .flat_map(|(t, p)| [*t, p.x, p.y])
            .collect()
    }

    /// `[dx0, dy0, dx1, …]`: one tangent per key (m/s) by `rule`, "time" or "halved".
    pub fn tangents(&self, rule: JsValue) -> Result<Vec<f32>, JsError> {
        let rule = fig::ChordRule::from_name(&super::string("rule", &rule)?).map_err(js)?;
        Ok(flat(&self.scene.tangents(rule)))
    }

    /// `[x0, y0, x1, …]`: the path by `rule`, `samples` points evenly spaced in time.
    #[wasm_bindgen(js_name = samplePath)]
    pub fn sample_path(&self, rule: JsValue, samples: f64) -> Result<Vec<f32>, JsError> {
        let rule = fig::ChordRule::from_name(&super::string("rule", &rule)?).map_err(js)?;
        let samples = super::whole("samples", samples)?;
        Ok(flat(&self.scene.path(rule, samples).map_err(js)?))
    }

    /// `[t, speed by time, speed halved, …]` (s, m/s, m/s).
    #[wasm_bindgen(js_name = sampleSpeeds)]
    pub fn sample_speeds(&self, samples: f64) -> Result<Vec<f32>, JsError> {
        let samples = super::whole("samples", samples)?;
        Ok(self.scene.sample_speeds(samples).map_err(js)?.concat())
    }

    /// Each rule's top speed and bulge, in words.
    pub fn note(&self) -> String {
        self.scene.note()
    }
}

impl Default for CardinalScene {
    fn default() -> Self {
        Self::new()
    }
}

/// `[x, e(x), e′(x), …]` for the ease `name` (see `figures::curves::EASE_NAMES`).
#[wasm_bindgen(js_name = easeSamples)]
pub fn ease_samples(name: JsValue, samples: f64) -> Result<Vec<f32>, JsError> {
    let name = super::string("name", &name)?;
    let samples = super::whole("samples", samples)?;
    Ok(fig::ease_samples(&name, samples).map_err(js)?.concat())
}

/// The spacing chart of the ease `name`: `frames` fractions of the way at equal time steps.
#[wasm_bindgen(js_name = spacingTicks)]
pub fn spacing_ticks(name: JsValue, frames: f64) -> Result<Vec<f32>, JsError> {
    let name = super::string("name", &name)?;
    let frames = super::whole_in("frames", frames, 2, 60)?;
    fig::spacing_ticks(&name, frames).map_err(js)
}
