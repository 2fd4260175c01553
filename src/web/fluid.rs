//! Bindings for lesson 15, "Fluids": thin wrappers around [`crate::figures::fluid`].

use super::{js, Viewer};
use crate::figures::fluid::{DamBreakFigure, DensityFigure, KernelsFigure, SplashFigure};
use wasm_bindgen::prelude::*;

/// Samples of the kernel plots: a fixed count, as many as the plot has pixels to show.
const KERNEL_SAMPLES: usize = 241;

/// Flattens sample rows for JavaScript.
fn flat<const N: usize>(rows: &[[f32; N]]) -> Vec<f32> {
    rows.iter().flatten().copied().collect()
}

/// The four kernels of one support radius, and the student's poly6.
#[wasm_bindgen]
pub struct KernelsScene {
    scene: KernelsFigure,
}

#[wasm_bindgen]
impl KernelsScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> KernelsScene {
        let mut scene = KernelsFigure::new();
        scene.set_runner(super::sandbox::run);
        KernelsScene { scene }
    }
    /// The support radius `h` (m, 0.01 to 1) and the dimension (2 or 3).
    pub fn set(&mut self, h: f32, dim: f32) -> Result<(), JsError> {
        let dim = super::whole_in("dimension", dim as f64, 2, 3)?;
        self.scene.set(h, dim as u32).map_err(js)
    }
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    /// `[r (m), poly6, spiky, spiky's slope, viscosity's Laplacian]` per row, each kernel as a
    /// share of its peak.
    pub fn samples(&self) -> Result<Vec<f32>, JsError> {
        Ok(flat(&self.scene.plot_rows(KERNEL_SAMPLES).map_err(js)?))
    }
    /// The student's poly6 at the same rows, as a share of the reference's peak; empty when the
    /// exercise is off or gave no answer.
    #[wasm_bindgen(js_name = yourCurve)]
    pub fn your_curve(&self) -> Result<Vec<f32>, JsError> {
        Ok(self
            .scene
            .exercise(KERNEL_SAMPLES)
            .map_err(js)?
            .0
            .unwrap_or_default())
    }
    /// The kernels' peaks (what the plot's shares are shares of), then what the figure says
    /// about the student's poly6 (nothing more when the exercise is off).
    pub fn note(&self) -> Result<String, JsError> {
        let exercise = self.scene.exercise(KERNEL_SAMPLES).map_err(js)?.1;
        let peaks = self.scene.peaks_note();
        Ok(if exercise.is_empty() {
            peaks
        } else {
            format!("{peaks} {exercise}")
        })
    }
}

impl Default for KernelsScene {
    fn default() -> Self {
        Self::new()
    }
}

/// A pool at rest and one dragged particle: its neighbours, density, force and PBF move.
#[wasm_bindgen]
pub struct DensityScene {
    scene: DensityFigure,
    camera: Option<crate::camera::OrbitCamera>,
}

#[wasm_bindgen]
impl DensityScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> DensityScene {
        let mut scene = DensityFigure::new();
        scene.set_runner(super::sandbox::run);
        DensityScene {
            scene,
            camera: None,
        }
    }
    /// Moves the dragged particle to `(x, y)` metres inside the box (1.6 × 1 m).
    #[wasm_bindgen(js_name = setProbe)]
    pub fn set_probe(&mut self, x: f32, y: f32) -> Result<(), JsError> {
        self.scene.set_probe(x, y).map_err(js)
    }
    /// The dragged particle's `[x, y]`, metres.
    pub fn probe(&self) -> Vec<f32> {
        let p = self.scene.probe_position();
        vec![p.x, p.y]
    }
    #[wasm_bindgen(js_name = setUseExercise)]
    pub fn set_use_exercise(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.scene.set_use_exercise(on);
        Ok(())
    }
    /// `[distance / h, m W(r)]` per term of the density's sum, the particle's own first.
    pub fn terms(&self) -> Vec<f32> {
        flat(&self.scene.terms())
    }
    /// Whether a pointer at `(x, y)` CSS pixels of a `width` × `height` canvas is on the
    /// dragged particle.
    #[wasm_bindgen(js_name = hitsProbe)]
    pub fn hits_probe(&mut self, x: f32, y: f32, width: f32, height: f32) -> Result<bool, JsError> {
        self.use_view(width, height)?;
        self.scene.hits_probe(x, y).map_err(js)
    }
    /// Moves the dragged particle under the pointer.
    #[wasm_bindgen(js_name = dragProbe)]
    pub fn drag_probe(&mut self, x: f32, y: f32, width: f32, height: f32) -> Result<(), JsError> {
        self.use_view(width, height)?;
        self.scene.drag_probe(x, y).map_err(js)
    }
    fn use_view(&mut self, width: f32, height: f32) -> Result<(), JsError> {
        let w = super::in_range("width", width, 1.0, 1e5)?;
        let h = super::in_range("height", height, 1.0, 1e5)?;
        if let Some(camera) = self.camera {
            self.scene.set_view(camera, w, h);
        }
        Ok(())
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        self.camera = Some(viewer.camera);
        // The view the dragged particle's name is placed for (the last frame's camera).
        let (w, h) = viewer.css_size;
        self.scene.set_view(viewer.camera, w, h);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for DensityScene {
    fn default() -> Self {
        Self::new()
    }
}

/// SPH beside PBF on one dam break. The plots show what has run so far (a whole run computed
/// ahead would hold the page for seconds after every change).
#[wasm_bindgen]
pub struct DamBreakScene {
    scene: DamBreakFigure,
}

#[wasm_bindgen]
impl DamBreakScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> DamBreakScene {
        DamBreakScene {
            scene: DamBreakFigure::new(),
        }
    }
    /// SPH's stiffness `k` (10 to 10,000) and time step (ms, 0.25 to 16.7); both runs start
    /// over.
    #[wasm_bindgen(js_name = setSph)]
    pub fn set_sph(&mut self, stiffness: f32, dt_ms: f32) -> Result<(), JsError> {
        let dt = super::finite("time step (ms)", dt_ms)? / 1000.0;
        self.scene.set_sph(stiffness, dt).map_err(js)
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        crate::figures::fluid::DAM_DURATION_SEC
    }
    /// `[t, SPH's largest ρ/ρ₀ − 1, PBF's, SPH's kinetic energy, PBF's]` per frame run so far
    /// (NaN once SPH stopped).
    pub fn samples(&self) -> Vec<f32> {
        flat(self.scene.plot_rows())
    }
    /// Steps towards `time_sec` (at most two frames a call) and draws; returns the note.
    pub fn draw(&mut self, viewer: &mut Viewer, time_sec: f32) -> Result<String, JsError> {
        self.scene.advance_toward(time_sec, 2).map_err(js)?;
        // Seen from the side, the frame adds a view from the front (the last frame's camera).
        self.scene.set_view(viewer.camera);
        let note = self.scene.draw(&mut viewer.renderer.frame);
        viewer.present()?;
        Ok(note)
    }
}

impl Default for DamBreakScene {
    fn default() -> Self {
        Self::new()
    }
}

/// A 3D drop into a pool, on the CPU or on the GPU grid, and the step-time sweep of the CPU
/// grid against all pairs and the GPU grid.
#[wasm_bindgen]
pub struct SplashScene {
    scene: SplashFigure,
    /// The fluid on the GPU, in GPU mode (WebGPU only).
    gpu: Option<crate::render::FluidCompute>,
    /// The viewer's generation `gpu` was made in (see `Viewer::renewed`).
    gpu_seen: u32,
    /// The GPU sweep's fluid and its particle count.
    timing: Option<(usize, crate::render::FluidCompute)>,
}

#[wasm_bindgen]
impl SplashScene {
    #[wasm_bindgen(constructor)]
    pub fn new() -> SplashScene {
        SplashScene {
            scene: SplashFigure::new(),
            gpu: None,
            gpu_seen: 0,
            timing: None,
        }
    }
    /// Steps the splash on the GPU grid with about `count` particles (a whole number from 500 to
    /// 1,048,576), or on the CPU with 0; the GPU fluid starts over. An error on WebGL2 (no
    /// compute shaders), saying so, or for a count out of range; nothing changes on an error.
    #[wasm_bindgen(js_name = setGpu)]
    pub fn set_gpu(&mut self, viewer: &Viewer, count: f64) -> Result<(), JsError> {
        let count = if count == 0.0 {
            0
        } else {
            super::whole_in(
                "GPU particles (0 for the CPU)",
                count,
                crate::figures::fluid::SPLASH_MIN,
                crate::figures::gpu::MAX_GPU_FLUID_PARTICLES,
            )?
        };
        if count != 0 && !viewer.gpu.compute {
            return Err(JsError::new(&format!(
                "GPU compute needs WebGPU; this figure runs on {}",
                viewer.gpu.backend_name
            )));
        }
        self.scene.set_gpu(count as f32).map_err(js)?;
        self.gpu = None; // uploaded from the figure's start at the next step
        Ok(())
    }
    /// GPU mode's `advanceTo`: queues the steps towards `time_sec` on the GPU (they run while
    /// the page goes on), a few a call and only once the GPU has finished the ones before, and
    /// none once a readback of the fastest particle has shown that the fluid exploded. Returns
    /// the steps queued.
    #[wasm_bindgen(js_name = advanceOnGpu)]
    pub fn advance_on_gpu(&mut self, viewer: &Viewer, time_sec: f32) -> Result<usize, JsError> {
        if !self.scene.gpu_mode() {
            return Err(JsError::new(
                "GPU mode is off: call setGpu(viewer, count) first",
            ));
        }
        if viewer.renewed(&mut self.gpu_seen) {
            self.gpu = None;
        }
        if self.gpu.is_none() {
            // A new GPU fluid starts from the start: its clock too. (Asking `set_gpu` for the
            // start's length would build a new lattice for that smaller count.)
            self.scene.restart_gpu_clock();
        }
        // The fastest particle of the steps before, when its readback has come: past the
        // CPU's limit the fluid has exploded and the figure queues no more steps.
        if let Some(read) = self.gpu.as_mut().and_then(|g| g.fastest(&viewer.gpu)) {
            let (time, speed) = read.map_err(|e| JsError::new(&e))?;
            self.scene.record_gpu_fastest(time, speed).map_err(js)?;
        }
        let idle = self.gpu.as_ref().is_none_or(|g| g.idle());
        let (restart, steps) = self.scene.plan_gpu_steps(time_sec, idle).map_err(js)?;
        if restart || self.gpu.is_none() {
            let start = self
                .scene
                .gpu_start()
                .ok_or_else(|| JsError::new("GPU mode is off"))?;
            self.gpu = Some(
                crate::render::FluidCompute::new(&viewer.gpu, start)
                    .map_err(|e| JsError::new(&e))?,
            );
        }
        let gpu = self.gpu.as_mut().expect("made above");
        gpu.step(&viewer.gpu, steps);
        Ok(steps)
    }
    /// The solver ("SPH" or "PBF"), the particle count (500 to 10,000; all pairs at most 4,000),
    /// the search ("grid" or "all pairs") and PBF's vorticity confinement (0 to 0.5); starts
    /// over.
    pub fn set(
        &mut self,
        method: JsValue,
        count: f32,
        search: JsValue,
        vorticity: f32,
    ) -> Result<(), JsError> {
        let method = super::string("method", &method)?;
        let search = super::string("search", &search)?;
        self.scene
            .set(&method, count, &search, vorticity)
            .map_err(js)?;
        self.gpu = None; // the GPU fluid starts over from the figure's start too
        Ok(())
    }
    #[wasm_bindgen(js_name = durationSec)]
    pub fn duration_sec(&self) -> f32 {
        crate::figures::fluid::SPLASH_DURATION_SEC
    }
    /// How far the drawn fluid has got (seconds), or the timeline's end once it has stopped.
    #[wasm_bindgen(getter, js_name = readySec)]
    pub fn ready_sec(&self) -> f32 {
        self.scene.ready_sec()
    }
    /// Steps towards `time_sec` (at most a few steps a call); returns the steps taken.
    #[wasm_bindgen(js_name = advanceTo)]
    pub fn advance_to(&mut self, time_sec: f32) -> Result<usize, JsError> {
        self.scene.advance_to(time_sec).map_err(js)
    }
    pub fn draw(&mut self, viewer: &mut Viewer) -> Result<String, JsError> {
        let note = match (&self.gpu, self.scene.gpu_mode()) {
            (Some(gpu), true) => {
                viewer.renderer.gpu_points = vec![gpu.sprites()];
                self.scene.draw_gpu(&mut viewer.renderer.frame)
            }
            _ => {
                viewer.renderer.gpu_points.clear();
                self.scene.draw(&mut viewer.renderer.frame)
            }
        };
        viewer.present()?;
        Ok(note)
    }
    /// Starts the step-time sweep again.
    #[wasm_bindgen(js_name = startSweep)]
    pub fn start_sweep(&mut self) {
        self.scene.start_sweep();
    }
    /// Whether the sweep times the GPU grid as well: where `viewer` has WebGPU. Starts the
    /// sweep again.
    #[wasm_bindgen(js_name = setGpuSweep)]
    pub fn set_gpu_sweep(&mut self, viewer: &Viewer) {
        self.scene.set_gpu_sweep(viewer.gpu.compute);
        self.timing = None;
    }
    /// The size the sweep times the GPU grid at next (0: none due). Uploads that fluid (the
    /// CPU sweep's pool) and queues one step that is not timed.
    #[wasm_bindgen(js_name = gpuSweepNext)]
    pub fn gpu_sweep_next(&mut self, viewer: &Viewer) -> Result<f64, JsError> {
        let Some(n) = self.scene.next_gpu_timing() else {
            return Ok(0.0);
        };
        if self.timing.as_ref().map(|t| t.0) != Some(n) {
            let fluid = SplashFigure::gpu_timing_fluid(n).map_err(js)?;
            let gpu = crate::render::FluidCompute::new(&viewer.gpu, &fluid)
                .map_err(|e| JsError::new(&e))?;
            self.timing = Some((n, gpu));
        }
        let (_, gpu) = self.timing.as_mut().expect("made above");
        gpu.step(&viewer.gpu, 1);
        Ok(n as f64)
    }
    /// Queues the GPU sweep's timed steps (call once `gpuSettled` has resolved); returns how
    /// many.
    #[wasm_bindgen(js_name = gpuTimingSteps)]
    pub fn gpu_timing_steps(&mut self, viewer: &Viewer) -> Result<usize, JsError> {
        let (_, gpu) = self
            .timing
            .as_mut()
            .ok_or_else(|| JsError::new("ask gpuSweepNext first"))?;
        let steps = crate::figures::fluid::SPLASH_GPU_TIMING_STEPS;
        gpu.step(&viewer.gpu, steps);
        Ok(steps)
    }
    /// A promise that resolves once the GPU has finished the sweep's steps queued so far.
    #[wasm_bindgen(js_name = gpuSettled)]
    pub fn gpu_settled(&self) -> Result<js_sys::Promise, JsError> {
        let (_, gpu) = self
            .timing
            .as_ref()
            .ok_or_else(|| JsError::new("ask gpuSweepNext first"))?;
        let settled = gpu.settled();
        Ok(wasm_bindgen_futures::future_to_promise(async move {
            settled.await;
            Ok(JsValue::UNDEFINED)
        }))
    }
    /// Records the GPU timing `gpuSweepNext` asked for, milliseconds per step.
    #[wasm_bindgen(js_name = gpuSweepRecord)]
    pub fn gpu_sweep_record(&mut self, ms: f32) -> Result<(), JsError> {
        self.scene.record_gpu_sweep(ms).map_err(js)
    }
    /// The search the sweep times next ("grid" or "all-pairs"), or "" when it is done.
    #[wasm_bindgen(js_name = sweepNext)]
    pub fn sweep_next(&mut self) -> Result<String, JsError> {
        Ok(self
            .scene
            .next_sweep_timing()
            .map_err(js)?
            .unwrap_or("")
            .into())
    }
    /// One step of the timing fluid with `search`; the page times the call.
    #[wasm_bindgen(js_name = timingStep)]
    pub fn timing_step(&mut self, search: JsValue) -> Result<(), JsError> {
        let search = super::string("search", &search)?;
        self.scene.timing_step(&search).map_err(js)
    }
    /// Records the timing `sweepNext` asked for, milliseconds per step.
    #[wasm_bindgen(js_name = sweepRecord)]
    pub fn sweep_record(&mut self, ms: f32) -> Result<(), JsError> {
        self.scene.record_sweep(ms).map_err(js)
    }
    /// `[N, grid median, fastest, slowest, all-pairs median, fastest, slowest, slope-1 guide,
    /// slope-2 guide, GPU grid median, fastest, slowest]` per size, ms (NaN: not timed).
    #[wasm_bindgen(js_name = sweepSamples)]
    pub fn sweep_samples(&mut self) -> Vec<f32> {
        self.scene.sweep_samples()
    }
    #[wasm_bindgen(js_name = sweepNote)]
    pub fn sweep_note(&mut self) -> String {
        self.scene.sweep_note()
    }
}

impl Default for SplashScene {
    fn default() -> Self {
        Self::new()
    }
}
