//! Bindings for lesson 11, "Particles": thin wrappers around [`crate::figures::particles`].

use super::{js, Viewer};
use crate::figures::particles::{
    BounceFigure, EmitterFigure, FreeFallFigure, SpringFigure, SquashFigure,
};
use wasm_bindgen::prelude::*;

/// Fountain and explosion emitters drawn as sprites.
#[wasm_bindgen]
pub struct EmitterScene {
    scene: EmitterFigure,
    /// The smoke atlas, uploaded on the first draw.
    atlas: Option<crate::texture::TextureId>,
    /// The particles on the GPU (compute shaders), when that mode is on and WebGPU is there.
    gpu: Option<crate::render::ParticlesCompute>,
    gpu_on: bool,
    /// The viewer's generation the atlas and `gpu` were made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl EmitterScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> EmitterScene {
        EmitterScene {
            scene: EmitterFigure::new(),
            atlas: None,
            gpu: None,
            gpu_on: false,
            gpu_seen: 0,
        }
    }

    /// Steps the particles by compute shaders (`true`) or on the CPU. An error on WebGL2 (no
    /// compute shaders), saying so.
    #[wasm_bindgen(js_name = setGpu)]
    pub fn set_gpu(&mut self, viewer: &Viewer, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        if on && !viewer.gpu.compute {
            return Err(JsError::new(&format!(
                "GPU compute needs WebGPU; this figure runs on {}",
                viewer.gpu.backend_name
            )));
        }
        self.gpu_on = on;
        self.gpu = None;
        self.scene.restart(); // replay from the start on either side
        Ok(())
    }
    /// "fountain", "explosion" or "both".
    #[wasm_bindgen(js_name = setMode)]
    pub fn set_mode(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_mode(name).map_err(js)
    }
    /// The fountain's particles per second, in [0, 1000].
    #[wasm_bindgen(js_name = setRate)]
    pub fn set_rate(&mut self, rate: f32) -> Result<(), JsError> {
        self.scene.set_rate(rate).map_err(js)
    }
    /// Particles one explosion asks for, in [0, 800].
    #[wasm_bindgen(js_name = setBurst)]
    pub fn set_burst(&mut self, count: f32) -> Result<(), JsError> {
        self.scene.set_burst(count).map_err(js)
    }
    /// Seconds, in [0.1, 10].
    #[wasm_bindgen(js_name = setLifetime)]
    pub fn set_lifetime(&mut self, sec: f32) -> Result<(), JsError> {
        self.scene.set_lifetime(sec).map_err(js)
    }
    /// Degrees, in [0, 90].
    #[wasm_bindgen(js_name = setSpreadDeg)]
    pub fn set_spread_deg(&mut self, deg: f32) -> Result<(), JsError> {
        self.scene.set_spread_deg(deg).map_err(js)
    }
    #[wasm_bindgen(js_name = setRestitution)]
    pub fn set_restitution(&mut self, e: f32) -> Result<(), JsError> {
        self.scene.set_restitution(e).map_err(js)
    }
    /// m/s², in [0, 30].
    #[wasm_bindgen(js_name = setGravity)]
    pub fn set_gravity(&mut self, g: f32) -> Result<(), JsError> {
        self.scene.set_gravity(g).map_err(js)
    }
    #[wasm_bindgen(js_name = setSort)]
    pub fn set_sort(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_sort(on);
        Ok(())
    }
    #[wasm_bindgen(js_name = setFade)]
    pub fn set_fade(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_fade(on);
        Ok(())
    }
    /// Sets off the explosion now (on the GPU too, when the particles are stepped there).
    pub fn explode(&mut self, viewer: &Viewer) -> Result<(), JsError> {
        match (&mut self.gpu, self.gpu_on) {
            (Some(system), true) => self
                .scene
                .explode_gpu(|e, s, count| {
                    system.burst(1, count);
                    system.step(&viewer.gpu, e, s, 0.0) // spawn only: nothing moves in 0 s
                })
                .map_err(js),
            _ => {
                self.scene.explode();
                Ok(())
            }
        }
    }
    /// Simulates to `time_sec` on the CPU (fixed steps of 1/60 s, replayed from the start when
    /// needed) without drawing; returns the steps taken. `draw` does the same, then draws.
    #[wasm_bindgen(js_name = advanceTo)]
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, JsError> {
        self.scene.advance_to(time_sec).map_err(js)
    }
    /// `[t, fountain's particles, explosions', rate × lifetime, fountain's slots]` per step
    /// since the run started, flat (see `EmitterFigure::count_samples`); on the GPU the counts
    /// are NaN (not read back) and only the guides are numbers.
    #[wasm_bindgen(js_name = countSamples)]
    pub fn count_samples(&self) -> Vec<f32> {
        self.scene.count_samples()
    }
    /// Simulates to `time_sec` (fixed steps of 1/60 s, replayed from the start when needed) and
    /// draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        if viewer.renewed(&mut self.gpu_seen) {
            (self.atlas, self.gpu) = (None, None);
        }
        if self.atlas.is_none() {
            let side = crate::figures::particles_sprites::ATLAS_SIDE as u32;
            let image = crate::figures::particles_sprites::smoke_atlas_image();
            let id = viewer
                .renderer
                .create_texture(&viewer.gpu, side, side, &image)
                .map_err(js)?;
            self.atlas = Some(id);
            self.scene.set_sprite_texture(self.atlas);
        }
        if self.gpu_on {
            return self.draw_gpu(viewer, time_sec);
        }
        viewer.renderer.gpu_sprites.clear(); // none left from GPU mode (hidden canvas)
        let (eye, target) = (viewer.camera.eye(), viewer.camera.target);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, eye, target, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl EmitterScene {
    fn draw_gpu(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        use crate::figures::particles::PAGE_MAX_PARTICLES;
        use crate::render::ParticlesCompute;
        let err = |e: String| JsError::new(&e);
        let g = &viewer.gpu;
        let fresh = || ParticlesCompute::new(g, PAGE_MAX_PARTICLES, 11);
        if self.gpu.is_none() {
            self.scene.restart();
            self.gpu = Some(fresh().map_err(err)?);
        }
        let system = self.gpu.as_mut().expect("made above");
        // One GPU step per figure step, with the explosion's burst of that step (a step of 0 s
        // spawns a press without moving anything).
        fn step(
            system: &mut ParticlesCompute,
            gpu: &crate::render::Gpu,
            e: &mut [crate::particles::Emitter],
            s: &crate::particles::Surfaces,
            burst: usize,
            dt: f32,
        ) -> Result<(), String> {
            if burst > 0 {
                system.burst(1, burst);
            }
            system.step(gpu, e, s, dt)
        }
        let (restart, _) = self
            .scene
            .advance_gpu(time_sec, false, |e, s, b, dt| step(system, g, e, s, b, dt))
            .map_err(js)?;
        if restart {
            *system = fresh().map_err(err)?;
            self.scene
                .advance_gpu(time_sec, true, |e, s, b, dt| step(system, g, e, s, b, dt))
                .map_err(js)?;
        }
        viewer.renderer.gpu_sprites = vec![self.gpu.as_ref().expect("made above").sprites()];
        let note = self.scene.draw_gpu(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for EmitterScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Free fall: exact vs three integrators.
#[wasm_bindgen]
pub struct FreeFallScene {
    scene: FreeFallFigure,
}

#[wasm_bindgen]
impl FreeFallScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> FreeFallScene {
        let mut scene = FreeFallFigure::new();
        scene.set_runner(super::sandbox::run);
        FreeFallScene { scene }
    }
    /// Step size, seconds, in [0.005, 0.3].
    #[wasm_bindgen(js_name = setDt)]
    pub fn set_dt(&mut self, dt: f32) -> Result<(), JsError> {
        self.scene.set_dt(dt).map_err(js)
    }
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    /// Seconds the throw lasts.
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        crate::figures::particles::FREE_FALL_DURATION
    }
    /// `[t, error explicit Euler, error semi-implicit Euler, error Verlet, …]`, metres.
    #[wasm_bindgen(js_name = errorSamples)]
    pub fn error_samples(&self) -> Vec<f32> {
        self.scene.error_samples()
    }
    /// The note `draw` returns at `time_sec`, without a canvas (the figure is a function of the
    /// time: nothing is stepped).
    #[wasm_bindgen(js_name = noteAt)]
    pub fn note_at(&self, time_sec: f32) -> Result<String, JsError> {
        let mut scratch = crate::draw::Frame::default();
        self.scene.draw(&mut scratch, time_sec).map_err(js)
    }
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        // The view the integrators' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for FreeFallScene {
    fn default() -> Self {
        Self::new()
    }
}

/// A mass on a spring, stepped by three integrators.
#[wasm_bindgen]
pub struct OscillatorScene {
    scene: SpringFigure,
}

#[wasm_bindgen]
impl OscillatorScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> OscillatorScene {
        OscillatorScene {
            scene: SpringFigure::new(),
        }
    }
    /// Step size, seconds, in [0.005, 0.2].
    #[wasm_bindgen(js_name = setDt)]
    pub fn set_dt(&mut self, dt: f32) -> Result<(), JsError> {
        self.scene.set_dt(dt).map_err(js)
    }
    /// The starting camera, as `Viewer.setCamera`'s six arguments.
    pub fn view(&self) -> Vec<f32> {
        self.scene.view().to_vec()
    }
    /// `[t, E/E₀ explicit Euler, semi-implicit Euler, Verlet, …]` per step.
    #[wasm_bindgen(js_name = energySamples)]
    pub fn energy_samples(&self) -> Vec<f32> {
        self.scene.energy_samples()
    }
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        // The view the integrators' names are placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for OscillatorScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Balls bouncing on a sphere and the floor.
#[wasm_bindgen]
pub struct BounceScene {
    scene: BounceFigure,
}

#[wasm_bindgen]
impl BounceScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> BounceScene {
        let mut scene = BounceFigure::new();
        scene.set_runner(super::sandbox::run);
        BounceScene { scene }
    }
    #[wasm_bindgen(js_name = setRestitution)]
    pub fn set_restitution(&mut self, e: f32) -> Result<(), JsError> {
        self.scene.set_restitution(e).map_err(js)
    }
    #[wasm_bindgen(js_name = setFriction)]
    pub fn set_friction(&mut self, mu: f32) -> Result<(), JsError> {
        self.scene.set_friction(mu).map_err(js)
    }
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    /// The starting camera, as `Viewer.setCamera`'s six arguments.
    pub fn view(&self) -> Vec<f32> {
        self.scene.view().to_vec()
    }
    /// Seconds.
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        crate::figures::particles::BOUNCE_DURATION
    }
    /// `[t, h, E / (m g)]` per step, flat (see `BounceFigure::plot_samples`).
    #[wasm_bindgen(js_name = plotSamples)]
    pub fn plot_samples(&self) -> Vec<f32> {
        self.scene.plot_samples()
    }
    /// Simulates to `time_sec` (fixed steps, replayed from the start when needed) without
    /// drawing; returns the steps taken. `draw` does the same, then draws.
    #[wasm_bindgen(js_name = advanceTo)]
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, JsError> {
        self.scene.advance_to(time_sec).map_err(js)
    }
    /// Simulates to `time_sec` and draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for BounceScene {
    fn default() -> Self {
        Self::new()
    }
}

/// A rigid ball and a squash-and-stretch ball.
#[wasm_bindgen]
pub struct SquashScene {
    scene: SquashFigure,
}

#[wasm_bindgen]
impl SquashScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SquashScene {
        SquashScene {
            scene: SquashFigure::new(),
        }
    }
    #[wasm_bindgen(js_name = setStretch)]
    pub fn set_stretch(&mut self, k: f32) -> Result<(), JsError> {
        self.scene.set_stretch(k).map_err(js)
    }
    #[wasm_bindgen(js_name = setSquash)]
    pub fn set_squash(&mut self, s: f32) -> Result<(), JsError> {
        self.scene.set_squash(s).map_err(js)
    }
    #[wasm_bindgen(js_name = setContact)]
    pub fn set_contact(&mut self, sec: f32) -> Result<(), JsError> {
        self.scene.set_contact(sec).map_err(js)
    }
    /// The starting camera, as `Viewer.setCamera`'s six arguments.
    pub fn view(&self) -> Vec<f32> {
        self.scene.view().to_vec()
    }
    /// Seconds the timeline lasts.
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        crate::figures::particles::SQUASH_DURATION
    }
    /// `[t, s, …]`: the squash ball's stretch factor at every step of the timeline.
    #[wasm_bindgen(js_name = plotSamples)]
    pub fn plot_samples(&self) -> Vec<f32> {
        self.scene.plot_samples()
    }
    /// Simulates to `time_sec` (fixed steps, replayed from the start when needed) without
    /// drawing; returns the steps taken. `draw` does the same, then draws.
    #[wasm_bindgen(js_name = advanceTo)]
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, JsError> {
        self.scene.advance_to(time_sec).map_err(js)
    }
    /// Simulates to `time_sec` and draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        let note = self
            .scene
            .draw(&mut viewer.renderer.frame, time_sec)
            .map_err(js)?;
        viewer.present()?;
        Ok(note)
    }
}

impl Default for SquashScene {
    fn default() -> Self {
        Self::new()
    }
}

/// Builds a particle system of `capacity` particles and an emitter with this rate (particles/s)
/// and lifetime range (seconds), and says what is wrong, or "ok": the wasm-boundary check of
/// the core's validation rules and cap. Cap (the build allocates per particle): `capacity` at
/// most 100,000 (`particles::MAX_PARTICLES`), checked before anything is allocated.
#[wasm_bindgen(js_name = checkEmitter)]
pub fn check_emitter(
    capacity: f64,
    rate_per_sec: f32,
    lifetime_min_sec: f32,
    lifetime_max_sec: f32,
) -> Result<String, JsError> {
    let capacity = super::whole("capacity", capacity)?;
    use crate::particles::{Emitter, ParticleSystem};
    ParticleSystem::new(capacity, 1).map_err(|e| JsError::new(&e.to_string()))?;
    let e = Emitter {
        rate_per_sec,
        lifetime_sec: (lifetime_min_sec, lifetime_max_sec),
        ..Emitter::fountain(glam::Vec3::ZERO)
    };
    e.validate().map_err(|e| JsError::new(&e.to_string()))?;
    Ok("ok".into())
}
