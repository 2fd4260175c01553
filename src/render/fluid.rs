//! A fluid stepped by compute shaders (WebGPU only): the SPH and PBF steps of
//! [`crate::fluid::Fluid::step`] in `shaders/fluid.wgsl`, one thread per particle, neighbours
//! from the [`GpuGrid`] rebuilt every step (on the positions for SPH, on the predicted positions
//! for PBF). What the shader receives is packed natively by [`crate::figures::gpu::fluid_rows`]
//! (caps included). Each step writes the renderer's point sprites, which
//! [`super::Renderer::gpu_points`] draws without a trip through the CPU.
//!
//! The CPU's step stops itself when it explodes; the GPU's cannot read its own result, so after
//! each step a pass (`shaders/fluid_speed.wgsl`) keeps the fastest particle's speed in a small
//! buffer that is read back without waiting ([`FluidCompute::fastest`]), and the caller gives
//! the CPU's verdict on it ([`crate::fluid::explosion_verdict`]).

use super::compute::{bind_entries, no_compute, read_buffer, storage, uniform, Kernels, ReadBack};
use super::grid::GpuGrid;
use super::Gpu;
use crate::figures::gpu::{fluid_layout, fluid_rows, GPU_FLUID_RED_SPEED, GPU_FLUID_ROWS};
use crate::fluid::{Fluid, Method};
use glam::Vec3;
use std::rc::Rc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

const WORKGROUP: u32 = 64;
/// One `vec4` per particle in each state buffer.
const VEC4_BYTES: u64 = 16;
/// `crate::draw::PointInstance`.
const INSTANCE_BYTES: u64 = 32;

/// The entry points of `fluid.wgsl`, in the order of [`FluidKernels`]' pipelines.
const ENTRY_POINTS: [&str; 12] = [
    "sph_density",
    "sph_force",
    "sph_move",
    "pbf_predict",
    "pbf_lambda",
    "pbf_delta",
    "pbf_apply",
    "pbf_density",
    "pbf_omega",
    "pbf_confine",
    "pbf_xsph",
    "pbf_finish",
];

/// The fluid's kernels, as the page caches them (one compile per page).
#[derive(Clone)]
struct FluidKernels(Rc<Kernels>);
/// The fastest-particle pass, as the page caches it.
#[derive(Clone)]
struct SpeedKernel(Rc<Kernels>);
/// The speed buffer: the largest `|v|²`'s bits in its first u32 (a whole `vec4<u32>`).
const SPEED_BYTES: u64 = 16;

/// A fluid on the GPU: its particles' state, the grid over them, and the step's passes.
pub struct FluidCompute {
    n: usize,
    method: Method,
    iterations: u32,
    vorticity: bool,
    xsph: bool,
    dt: f32,
    time: f32,
    pos: wgpu::Buffer,
    vel: wgpu::Buffer,
    aux: wgpu::Buffer,
    instances: wgpu::Buffer,
    /// Source 0 is `pos` (SPH), source 1 the predicted positions (PBF).
    grid: GpuGrid,
    group: wgpu::BindGroup,
    kernels: Rc<Kernels>,
    /// Set while steps submitted by [`FluidCompute::step`] have not finished on the GPU.
    busy: Arc<AtomicBool>,
    /// The largest `|v|²` since the last readback (`fluid_speed.wgsl`), its pass and bindings.
    speed: wgpu::Buffer,
    speed_kernel: Rc<Kernels>,
    speed_group: wgpu::BindGroup,
    /// The readback under way, and the fluid's time after the steps it covers.
    watch: Option<(ReadBack, f32)>,
    /// The speed buffer was copied for a readback: the next steps start it again from 0.
    restart_speed: bool,
}

impl FluidCompute {
    /// Uploads `fluid` (its particles, parameters, walls and obstacle) as it is now.
    ///
    /// # Errors
    /// No compute on this backend, what [`fluid_rows`] rejects (a count out of `[1,`
    /// [`crate::figures::gpu::MAX_GPU_FLUID_PARTICLES`]`]` among it), a fluid that has exploded.
    /// Nothing is made on an error.
    pub fn new(gpu: &Gpu, fluid: &Fluid) -> Result<Self, String> {
        no_compute(gpu)?;
        let rows = fluid_rows(fluid)?;
        debug_assert_eq!(rows.len(), GPU_FLUID_ROWS);
        let layout = fluid_layout(fluid)?;
        if let Some((t, _)) = fluid.exploded() {
            return Err(format!("GPU fluid: the fluid exploded at t = {t} s"));
        }
        let n = fluid.len();
        let none = wgpu::BufferUsages::empty();
        let size = n as u64 * VEC4_BYTES;
        let pos = storage(gpu, "fluid positions", size, none);
        let vel = storage(gpu, "fluid velocities", size, none);
        let pred = storage(gpu, "fluid predicted", size, none);
        let aux = storage(gpu, "fluid densities", size, none);
        let delta = storage(gpu, "fluid deltas", size, none);
        let instances = storage(
            gpu,
            "fluid sprites",
            n as u64 * INSTANCE_BYTES,
            wgpu::BufferUsages::VERTEX,
        );
        let vec4s =
            |v: &[Vec3]| -> Vec<[f32; 4]> { v.iter().map(|p| p.extend(0.0).into()).collect() };
        gpu.queue
            .write_buffer(&pos, 0, bytemuck::cast_slice(&vec4s(&fluid.positions)));
        gpu.queue
            .write_buffer(&vel, 0, bytemuck::cast_slice(&vec4s(&fluid.velocities)));
        // The predicted positions start as the positions: PBF's grid never sees garbage.
        gpu.queue
            .write_buffer(&pred, 0, bytemuck::cast_slice(&vec4s(&fluid.positions)));
        // The start's sprites, coloured by speed as the shader colours them: a fluid drawn
        // before its first step shows where it is.
        let radius = f32::from_bits(rows[5][2]);
        let sprites: Vec<[f32; 8]> = fluid
            .positions
            .iter()
            .zip(&fluid.velocities)
            .map(|(p, v)| {
                let s = (v.length() / GPU_FLUID_RED_SPEED).min(1.0);
                let c = crate::figures::noise::diverging_color(1.2 * s - 0.6);
                [p.x, p.y, p.z, radius, c.x, c.y, c.z, 1.0]
            })
            .collect();
        gpu.queue
            .write_buffer(&instances, 0, bytemuck::cast_slice(&sprites));
        let params = uniform(gpu, "fluid params", rows.len());
        gpu.queue
            .write_buffer(&params, 0, bytemuck::cast_slice(&rows));
        let FluidKernels(kernels) = gpu.cached(|| {
            let storage = |read_only| wgpu::BufferBindingType::Storage { read_only };
            let uniform = wgpu::BufferBindingType::Uniform;
            let mut bindings = vec![uniform, uniform, storage(true), storage(true)];
            bindings.extend([storage(false); 6]);
            FluidKernels(Rc::new(Kernels::new(
                gpu,
                "fluid",
                &format!(
                    "{}\n{}",
                    super::grid::GRID_COMMON,
                    super::shader_source!("fluid.wgsl")
                ),
                &bindings,
                &ENTRY_POINTS,
            )))
        });
        let grid = GpuGrid::new(gpu, &[&pos, &pred], n, 1, layout)?;
        let buffers = [
            &params,
            grid.params(),
            grid.cell_start(),
            grid.sorted(),
            &pos,
            &vel,
            &pred,
            &aux,
            &delta,
            &instances,
        ];
        let group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("fluid"),
            layout: &kernels.layout,
            entries: &bind_entries(&buffers),
        });
        let speed = storage(gpu, "fluid fastest", SPEED_BYTES, none);
        let SpeedKernel(speed_kernel) = gpu.cached(|| {
            let storage = |read_only| wgpu::BufferBindingType::Storage { read_only };
            SpeedKernel(Rc::new(Kernels::new(
                gpu,
                "fluid speed",
                super::shader_source!("fluid_speed.wgsl"),
                &[storage(true), storage(true), storage(false)],
                &["fastest"],
            )))
        });
        let speed_group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("fluid speed"),
            layout: &speed_kernel.layout,
            entries: &bind_entries(&[&pos, &vel, &speed]),
        });
        let p = &fluid.params;
        Ok(Self {
            n,
            method: p.method,
            iterations: p.iterations,
            vorticity: p.vorticity > 0.0,
            xsph: p.xsph > 0.0,
            dt: p.dt,
            time: fluid.time,
            pos,
            vel,
            aux,
            instances,
            grid,
            group,
            kernels,
            busy: Arc::new(AtomicBool::new(false)),
            speed,
            speed_kernel,
            speed_group,
            watch: None,
            restart_speed: false,
        })
    }

    /// Whether `other` steps with the same compiled kernels (two figures of one page do).
    pub fn shares_kernels(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.kernels, &other.kernels)
    }

    pub fn len(&self) -> usize {
        self.n
    }

    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The fluid's clock after the steps queued so far, seconds.
    pub fn time(&self) -> f32 {
        self.time
    }

    /// Queues `steps` steps of the fluid's method in one submission (each: the grid, then the
    /// method's passes in the CPU step's order).
    pub fn step(&mut self, gpu: &Gpu, steps: usize) {
        if steps == 0 {
            return;
        }
        let groups = (self.n as u32).div_ceil(WORKGROUP);
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        if self.restart_speed {
            encoder.clear_buffer(&self.speed, 0, None);
            self.restart_speed = false;
        }
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            let pipelines = &self.kernels.pipelines;
            let run = |pass: &mut wgpu::ComputePass<'_>, name: &str| {
                let k = ENTRY_POINTS
                    .iter()
                    .position(|e| *e == name)
                    .expect("an entry point");
                pass.set_pipeline(&pipelines[k]);
                pass.dispatch_workgroups(groups, 1, 1);
            };
            for _ in 0..steps {
                match self.method {
                    Method::Sph => {
                        self.grid.encode(&mut pass, 0);
                        pass.set_bind_group(0, &self.group, &[]);
                        for name in ["sph_density", "sph_force", "sph_move"] {
                            run(&mut pass, name);
                        }
                    }
                    Method::Pbf => {
                        pass.set_bind_group(0, &self.group, &[]);
                        run(&mut pass, "pbf_predict");
                        self.grid.encode(&mut pass, 1);
                        pass.set_bind_group(0, &self.group, &[]);
                        for _ in 0..self.iterations {
                            for name in ["pbf_lambda", "pbf_delta", "pbf_apply"] {
                                run(&mut pass, name);
                            }
                        }
                        run(&mut pass, "pbf_density");
                        if self.vorticity {
                            run(&mut pass, "pbf_omega");
                            run(&mut pass, "pbf_confine");
                        }
                        if self.xsph {
                            run(&mut pass, "pbf_xsph");
                        }
                        run(&mut pass, "pbf_finish");
                    }
                }
                // The fastest particle after the step, as the CPU checks after each of its own.
                pass.set_pipeline(&self.speed_kernel.pipelines[0]);
                pass.set_bind_group(0, &self.speed_group, &[]);
                pass.dispatch_workgroups(groups, 1, 1);
            }
        }
        gpu.queue.submit([encoder.finish()]);
        self.time += steps as f32 * self.dt;
        // One readback at a time; until it is taken, the next steps add to the same maximum.
        if self.watch.is_none() {
            self.watch = Some((ReadBack::start(gpu, &self.speed, SPEED_BYTES), self.time));
            self.restart_speed = true;
        }
        self.busy.store(true, Ordering::Relaxed);
        let busy = self.busy.clone();
        gpu.queue
            .on_submitted_work_done(move || busy.store(false, Ordering::Relaxed));
    }

    /// The fastest particle's speed (m/s) over the steps since the readback before, and the
    /// fluid's time after them, once their readback has arrived (`None` before; once each). The
    /// speed is infinite when a position or velocity stopped being a finite number. Never waits.
    pub fn fastest(&mut self, gpu: &Gpu) -> Option<Result<(f32, f32), String>> {
        let (watch, time) = self.watch.as_ref()?;
        let bytes = watch.try_take(gpu)?;
        let time = *time;
        self.watch = None;
        Some(bytes.map(|b| {
            let bits = u32::from_le_bytes([b[0], b[1], b[2], b[3]]);
            let speed = f32::from_bits(bits).sqrt();
            (time, if speed.is_nan() { f32::INFINITY } else { speed })
        }))
    }

    /// Whether the GPU has finished every step submitted so far (a page queues more only then).
    pub fn idle(&self) -> bool {
        !self.busy.load(Ordering::Relaxed)
    }

    /// A future that completes once the GPU has finished the steps submitted so far; it holds
    /// nothing of the fluid (a page awaits it while the fluid lives on). Polled every
    /// millisecond.
    pub fn settled(&self) -> impl std::future::Future<Output = ()> + 'static {
        let busy = self.busy.clone();
        async move {
            while busy.load(Ordering::Relaxed) {
                super::renderer::sleep_ms(1).await;
            }
        }
    }

    /// The sprites of the last step, for [`super::Renderer::gpu_points`].
    pub fn sprites(&self) -> (wgpu::Buffer, u32) {
        (self.instances.clone(), self.n as u32)
    }

    /// Reads the fluid back: positions, velocities and densities (for SPH the densities the last
    /// step computed its forces with, before it moved the particles, as on the CPU; tests; waits
    /// for the GPU).
    pub async fn read_back(&self, gpu: &Gpu) -> Result<(Vec<Vec3>, Vec<Vec3>, Vec<f32>), String> {
        let size = self.n as u64 * VEC4_BYTES;
        let xyz = |bytes: Vec<u8>| -> Vec<Vec3> {
            let floats: Vec<f32> = bytemuck::pod_collect_to_vec(&bytes);
            floats
                .chunks_exact(4)
                .map(|q| Vec3::new(q[0], q[1], q[2]))
                .collect()
        };
        let positions = xyz(read_buffer(gpu, &self.pos, size).await?);
        let velocities = xyz(read_buffer(gpu, &self.vel, size).await?);
        let densities = xyz(read_buffer(gpu, &self.aux, size).await?)
            .iter()
            .map(|a| a.x)
            .collect();
        Ok((positions, velocities, densities))
    }

    /// Waits until the GPU has finished every step submitted so far (benchmarks, the page's
    /// step-time sweep).
    pub async fn finish(&self, gpu: &Gpu) -> Result<(), String> {
        read_buffer(gpu, &self.instances, 16).await.map(|_| ())
    }
}
