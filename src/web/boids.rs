//! Bindings for lesson 12, "Boids": thin wrappers around [`crate::figures::boids`].

use super::{js, Viewer};
use crate::figures::boids::{FlockFigure, GpuSample, RulesFigure};
use wasm_bindgen::prelude::*;

/// The flock.
#[wasm_bindgen]
pub struct FlockScene {
    scene: FlockFigure,
    /// The flock on the GPU (compute shader), when that mode is on and WebGPU is there.
    gpu: Option<crate::render::BoidsCompute>,
    /// The flock on its way back from the GPU for the order plot, with its ticket.
    sample: Option<(GpuSample, crate::render::ReadBack)>,
    /// The viewer's generation `gpu` was made in (see `Viewer::renewed`).
    gpu_seen: u32,
}

#[wasm_bindgen]
impl FlockScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> FlockScene {
        FlockScene {
            scene: FlockFigure::new(),
            gpu: None,
            sample: None,
            gpu_seen: 0,
        }
    }

    /// Steps the flock by a compute shader (`true`) or on the CPU. An error on WebGL2 (no
    /// compute shaders), saying so, or for a GPU flock over the search's cap.
    #[wasm_bindgen(js_name = setGpu)]
    pub fn set_gpu(&mut self, viewer: &Viewer, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        if on && !viewer.gpu.compute {
            return Err(JsError::new(&format!(
                "GPU compute needs WebGPU; this figure runs on {}",
                viewer.gpu.backend_name
            )));
        }
        self.scene.set_gpu_mode(on).map_err(js)?;
        self.gpu = None; // uploaded from the CPU flock at the next step
        self.sample = None;
        Ok(())
    }

    /// GPU mode's [`FlockScene::advance_to`]: queues the steps on the GPU (they run while the
    /// page goes on; the bench page measures their time). Returns the steps queued.
    #[wasm_bindgen(js_name = advanceOnGpu)]
    pub fn advance_on_gpu(&mut self, viewer: &Viewer, time_sec: f32) -> Result<usize, JsError> {
        if !self.scene.gpu_mode() {
            return Err(JsError::new(
                "GPU mode is off: call setGpu(viewer, true) first",
            ));
        }
        if viewer.renewed(&mut self.gpu_seen) {
            (self.gpu, self.sample) = (None, None);
        }
        let (restart, steps) = self.scene.plan_gpu_steps(time_sec).map_err(js)?;
        if restart || self.gpu.is_none() {
            let (positions, velocities, time_sec) = self.scene.gpu_start();
            self.gpu = Some(
                crate::render::BoidsCompute::new(&viewer.gpu, &positions, &velocities, time_sec)
                    .map_err(|e| JsError::new(&e))?,
            );
        }
        let gpu = self.gpu.as_mut().expect("made above");
        let params = self.scene.gpu_params();
        for _ in 0..steps {
            gpu.step(
                &viewer.gpu,
                &params,
                crate::figures::particles::SIM_DT,
                self.scene.search(),
            )
            .map_err(|e| JsError::new(&e))?;
        }
        // The order plot: a read-back that has arrived is plotted (the figure drops one from
        // before a restart), then the next is queued when due.
        if let Some((ticket, copy)) = &self.sample {
            if let Some(bytes) = copy.try_take(&viewer.gpu) {
                let ticket = *ticket;
                self.sample = None;
                let bytes = bytes.map_err(|e| JsError::new(&e))?;
                let (positions, velocities) = crate::render::BoidsCompute::unpack(&bytes);
                self.scene.widen_reach(&positions);
                self.scene
                    .record_gpu_sample(ticket, &velocities)
                    .map_err(js)?;
            }
        }
        if self.sample.is_none() {
            if let Some(ticket) = self.scene.gpu_sample_due() {
                self.sample = Some((ticket, gpu.start_read_back(&viewer.gpu)));
            }
        }
        Ok(steps)
    }
    /// GPU mode: a flock of `count` boids of its own, in a box that keeps the figure's density,
    /// instead of the slider's (`0`): 0 or a whole number in [2, 1,048,576], at most 65,536 with
    /// the "naive" search (every pair). A rejected count changes nothing.
    #[wasm_bindgen(js_name = setGpuCount)]
    pub fn set_gpu_count(&mut self, count: f64) -> Result<(), JsError> {
        let n = super::whole_in(
            "GPU boids",
            count,
            0,
            crate::figures::gpu::MAX_GPU_GRID_BOIDS,
        )?;
        if n != self.scene.gpu_count() {
            self.scene.set_gpu_count(n).map_err(js)?;
            self.gpu = None;
            self.sample = None;
        }
        Ok(())
    }
    /// A new flock of `count` boids, in [2, 3000].
    #[wasm_bindgen(js_name = setCount)]
    pub fn set_count(&mut self, count: f32) -> Result<(), JsError> {
        self.scene.set_count(count).map_err(js)?;
        // Only a new flock drops the GPU's: a rejected count keeps the flock where it is.
        self.gpu = None;
        self.sample = None;
        Ok(())
    }
    /// `rule`: "cohesion", "alignment" or "separation"; weight in [0, 10], radius in [0.05, 3] m.
    #[wasm_bindgen(js_name = setRule)]
    pub fn set_rule(&mut self, rule: JsValue, weight: f32, radius: f32) -> Result<(), JsError> {
        let rule: &str = &super::string("rule", &rule)?;
        self.scene.set_rule(rule, weight, radius).map_err(js)
    }
    #[wasm_bindgen(js_name = setFovDeg)]
    pub fn set_fov_deg(&mut self, fov: f32) -> Result<(), JsError> {
        self.scene.set_fov_deg(fov).map_err(js)
    }
    #[wasm_bindgen(js_name = setMaxSpeed)]
    pub fn set_max_speed(&mut self, v: f32) -> Result<(), JsError> {
        self.scene.set_max_speed(v).map_err(js)
    }

    #[wasm_bindgen(js_name = setMinSpeed)]
    pub fn set_min_speed(&mut self, v: f32) -> Result<(), JsError> {
        self.scene.set_min_speed(v).map_err(js)
    }
    #[wasm_bindgen(js_name = setMaxForce)]
    pub fn set_max_force(&mut self, f: f32) -> Result<(), JsError> {
        self.scene.set_max_force(f).map_err(js)
    }
    /// "none", "a1/x² − a2/x⁴" or "Gaussian".
    #[wasm_bindgen(js_name = setLaw)]
    pub fn set_law(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_law(name).map_err(js)
    }
    #[wasm_bindgen(js_name = setLeader)]
    pub fn set_leader(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_leader(on);
        Ok(())
    }
    #[wasm_bindgen(js_name = setPredator)]
    pub fn set_predator(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_predator(on);
        Ok(())
    }
    #[wasm_bindgen(js_name = setObstacle)]
    pub fn set_obstacle(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_obstacle(on);
        Ok(())
    }
    /// "grid" or "naive" (in GPU mode: the GPU grid or every pair, at most 65,536 boids).
    #[wasm_bindgen(js_name = setSearch)]
    pub fn set_search(&mut self, name: JsValue) -> Result<(), JsError> {
        let name: &str = &super::string("name", &name)?;
        self.scene.set_search(name).map_err(js)
    }
    /// Brings the flock to `time_sec` by steps of 1/60 s; returns the number of steps taken (the
    /// page times this call and divides).
    #[wasm_bindgen(js_name = advanceTo)]
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, JsError> {
        self.scene.advance_to(time_sec).map_err(js)
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the leader's and the predator's names are placed for (the last frame's).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = match (&self.gpu, self.scene.gpu_mode()) {
            (Some(gpu), true) => {
                viewer.renderer.gpu_points = vec![gpu.sprites()];
                self.scene.draw_gpu(&mut viewer.renderer.frame)
            }
            _ => {
                viewer.renderer.gpu_points.clear(); // none left from GPU mode (hidden canvas)
                self.scene.draw(&mut viewer.renderer.frame)
            }
        };
        viewer.present()?;
        Ok(note)
    }
    /// `[t, φ, speed ratio, …]`: the flock's order after every step since it last started (in
    /// GPU mode every 0.1 s, read back from the GPU).
    #[wasm_bindgen(js_name = plotSamples)]
    pub fn plot_samples(&self) -> Vec<f32> {
        self.scene.plot_samples()
    }
    /// A separate flock of `n ∈ [2, 20000]` boids for the step-time plot.
    #[wasm_bindgen(js_name = prepareTiming)]
    pub fn prepare_timing(&mut self, n: f32) -> Result<(), JsError> {
        self.scene.prepare_timing(n).map_err(js)
    }
    /// One step of the timing flock with "grid" or "naive" search; the page times this call.
    #[wasm_bindgen(js_name = timingStep)]
    pub fn timing_step(&mut self, search: JsValue) -> Result<(), JsError> {
        let search: &str = &super::string("search", &search)?;
        self.scene.timing_step(search).map_err(js)
    }
    /// Starts the step-time sweep again.
    #[wasm_bindgen(js_name = startSweep)]
    pub fn start_sweep(&mut self) {
        self.scene.start_sweep();
    }
    /// The search the sweep times next ("grid" or "naive"; the timing flock is built at its
    /// size), or "" when the sweep is done.
    #[wasm_bindgen(js_name = sweepNext)]
    pub fn sweep_next(&mut self) -> Result<String, JsError> {
        Ok(self
            .scene
            .next_sweep_timing()
            .map_err(js)?
            .unwrap_or("")
            .into())
    }
    /// Records the timing `sweepNext` asked for, milliseconds per step.
    #[wasm_bindgen(js_name = sweepRecord)]
    pub fn sweep_record(&mut self, ms: f32) -> Result<(), JsError> {
        self.scene.record_sweep(ms).map_err(js)
    }
    /// `[N, grid median, fastest, slowest, naive median, fastest, slowest, slope-1 guide,
    /// slope-2 guide, …]` in ms (NaN: not timed); see `StepTimeSweep::plot_samples`.
    #[wasm_bindgen(js_name = sweepSamples)]
    pub fn sweep_samples(&mut self) -> Vec<f32> {
        self.scene.sweep().plot_samples()
    }
    /// What the sweep measured so far.
    #[wasm_bindgen(js_name = sweepNote)]
    pub fn sweep_note(&mut self) -> String {
        self.scene.sweep().note()
    }
}

impl Default for FlockScene {
    fn default() -> Self {
        Self::new()
    }
}

/// One boid, its neighbours, its three rules and its grid cell.
#[wasm_bindgen]
pub struct BoidRulesScene {
    scene: RulesFigure,
}

#[wasm_bindgen]
impl BoidRulesScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> BoidRulesScene {
        let mut scene = RulesFigure::new();
        scene.set_runner(super::sandbox::run);
        BoidRulesScene { scene }
    }
    /// The starting camera, as `Viewer.setCamera`'s six arguments.
    pub fn view(&self) -> Vec<f32> {
        self.scene.view().to_vec()
    }
    #[wasm_bindgen(js_name = setPosition)]
    pub fn set_position(&mut self, x: f32, z: f32) -> Result<(), JsError> {
        self.scene.set_position(x, z).map_err(js)
    }
    #[wasm_bindgen(js_name = setHeadingDeg)]
    pub fn set_heading_deg(&mut self, deg: f32) -> Result<(), JsError> {
        self.scene.set_heading_deg(deg).map_err(js)
    }
    #[wasm_bindgen(js_name = setRadius)]
    pub fn set_radius(&mut self, r: f32) -> Result<(), JsError> {
        self.scene.set_radius(r).map_err(js)
    }
    #[wasm_bindgen(js_name = setFovDeg)]
    pub fn set_fov_deg(&mut self, fov: f32) -> Result<(), JsError> {
        self.scene.set_fov_deg(fov).map_err(js)
    }
    #[wasm_bindgen(js_name = setCellSize)]
    pub fn set_cell_size(&mut self, s: f32) -> Result<(), JsError> {
        self.scene.set_cell_size(s).map_err(js)
    }
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        // The view the rules' names are placed for (the last frame's).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for BoidRulesScene {
    fn default() -> Self {
        Self::new()
    }
}

/// The force-law plot's samples, `[x, f of a1/x² − a2/x⁴, f of the Gaussian law]` per distance
/// (see [`crate::figures::boids::law_plot_samples`]; `count ∈ [2, 1000]`).
#[wasm_bindgen(js_name = lawPlotSamples)]
pub fn law_plot_samples(count: f32) -> Result<Vec<f32>, JsError> {
    crate::figures::boids::law_plot_samples(count).map_err(js)
}
