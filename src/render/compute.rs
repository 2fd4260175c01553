//! GPU compute for particles and boids (WebGPU only; WebGL2 has no compute shaders, and the
//! pages then keep the CPU path). The models are `crate::particles` and `crate::boids`; the
//! shaders (`shaders/particles.wgsl`, `shaders/boids.wgsl`) follow them line by line, and what
//! they receive is packed natively by [`crate::figures::gpu`] (caps included). Each step writes
//! the renderer's point sprites (`PointInstance` layout) into a buffer that
//! [`super::Renderer::gpu_points`] draws without a trip through the CPU.

use super::grid::GpuGrid;
use super::Gpu;
use crate::boids::{BoidParams, Search};
use crate::figures::gpu::{
    boid_rows, check_gpu_boids, GpuParticleClock, GridLayout, Row, MAX_GPU_EMITTERS,
    MAX_GPU_PARTICLES,
};
use crate::particles::{Emitter, Surfaces};
use glam::Vec3;
use std::cell::Cell;
use std::rc::Rc;

/// Raises `limits` to what the compute paths need: WebGPU's guaranteed minimums (8 storage
/// buffers per stage: the fluid's passes bind 8, the boids' grid step 5).
pub(super) fn add_compute_limits(limits: &mut wgpu::Limits) {
    let d = wgpu::Limits::downlevel_defaults();
    limits.max_storage_buffers_per_shader_stage =
        wgpu::Limits::default().max_storage_buffers_per_shader_stage;
    limits.max_storage_buffer_binding_size = d.max_storage_buffer_binding_size;
    limits.max_buffer_size = limits.max_buffer_size.max(d.max_buffer_size);
    limits.max_compute_workgroup_storage_size = d.max_compute_workgroup_storage_size;
    limits.max_compute_invocations_per_workgroup = d.max_compute_invocations_per_workgroup;
    limits.max_compute_workgroup_size_x = d.max_compute_workgroup_size_x;
    limits.max_compute_workgroup_size_y = d.max_compute_workgroup_size_y;
    limits.max_compute_workgroup_size_z = d.max_compute_workgroup_size_z;
    limits.max_compute_workgroups_per_dimension = d.max_compute_workgroups_per_dimension;
}

const WORKGROUP: u32 = 64;
/// One particle's state on the GPU: `pos` (xyz, age), `vel` (xyz, lifetime), `info` (radius,
/// alive, resting, emitter).
const PARTICLE_BYTES: u64 = 48;
const BOID_BYTES: u64 = 32;
/// `crate::draw::PointInstance` (boids).
const INSTANCE_BYTES: u64 = 32;
/// `crate::texture::SpriteInstance` (particles).
const SPRITE_BYTES: u64 = std::mem::size_of::<crate::texture::SpriteInstance>() as u64;

pub(super) fn no_compute(gpu: &Gpu) -> Result<(), String> {
    if gpu.compute {
        Ok(())
    } else {
        Err(format!(
            "GPU compute needs WebGPU; this figure runs on {}, so it stays on the CPU",
            gpu.backend_name
        ))
    }
}

pub(super) fn storage(
    gpu: &Gpu,
    label: &str,
    size: u64,
    extra: wgpu::BufferUsages,
) -> wgpu::Buffer {
    gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        usage: wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_SRC
            | wgpu::BufferUsages::COPY_DST
            | extra,
        mapped_at_creation: false,
    })
}

pub(super) fn uniform(gpu: &Gpu, label: &str, rows: usize) -> wgpu::Buffer {
    gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: (rows * 16) as u64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

fn entry(binding: u32, ty: wgpu::BufferBindingType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// A compute shader's bind group layout and pipelines (one per entry point): made once per page
/// (see `Gpu::cached`), so a second figure, or a restart that makes a new system, compiles no
/// shader.
pub(super) struct Kernels {
    pub(super) layout: wgpu::BindGroupLayout,
    pub(super) pipelines: Vec<wgpu::ComputePipeline>,
}

/// The particles' kernels (`spawn`, then `update`), as the page caches them.
#[derive(Clone)]
struct ParticleKernels(Rc<Kernels>);
/// The flock's kernel (`step`), as the page caches it.
#[derive(Clone)]
struct BoidKernels(Rc<Kernels>);

impl Kernels {
    /// `entry_points` of `source`, on a layout of `bindings` (binding i is `bindings[i]`).
    pub(super) fn new(
        gpu: &Gpu,
        label: &str,
        source: &str,
        bindings: &[wgpu::BufferBindingType],
        entry_points: &[&str],
    ) -> Self {
        let entries: Vec<_> = (0..).zip(bindings).map(|(i, ty)| entry(i, *ty)).collect();
        let layout = gpu
            .device
            .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some(label),
                entries: &entries,
            });
        let m = module(gpu, label, source);
        let pipelines = entry_points
            .iter()
            .map(|e| pipeline(gpu, &layout, &m, e))
            .collect();
        Self { layout, pipelines }
    }
}

fn module(gpu: &Gpu, label: &str, source: &str) -> wgpu::ShaderModule {
    gpu.device
        .create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(label),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        })
}

fn pipeline(
    gpu: &Gpu,
    layout: &wgpu::BindGroupLayout,
    module: &wgpu::ShaderModule,
    entry_point: &str,
) -> wgpu::ComputePipeline {
    let layout = gpu
        .device
        .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(entry_point),
            bind_group_layouts: &[Some(layout)],
            immediate_size: 0,
        });
    gpu.device
        .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry_point),
            layout: Some(&layout),
            module,
            entry_point: Some(entry_point),
            compilation_options: Default::default(),
            cache: None,
        })
}

/// Bind group entries 0, 1, … for `buffers`, whole.
pub(super) fn bind_entries<'a>(buffers: &[&'a wgpu::Buffer]) -> Vec<wgpu::BindGroupEntry<'a>> {
    (0..)
        .zip(buffers)
        .map(|(binding, b)| wgpu::BindGroupEntry {
            binding,
            resource: b.as_entire_binding(),
        })
        .collect()
}

fn rows_bytes(rows: &[Row]) -> &[u8] {
    bytemuck::cast_slice(rows)
}

/// Copies `size` bytes of `buffer` back to the CPU (tests, benchmarks: it waits for the GPU).
pub async fn read_buffer(gpu: &Gpu, buffer: &wgpu::Buffer, size: u64) -> Result<Vec<u8>, String> {
    let copy = ReadBack::start(gpu, buffer, size);
    loop {
        if let Some(bytes) = copy.try_take(gpu) {
            return bytes;
        }
        super::renderer::sleep_ms(1).await;
    }
}

/// A copy of a GPU buffer on its way to the CPU, taken without waiting: a page starts one and
/// asks [`ReadBack::try_take`] on later frames, so the GPU's queue never stalls a frame.
pub struct ReadBack {
    staging: wgpu::Buffer,
    done: Rc<Cell<Option<Result<(), String>>>>,
}

impl ReadBack {
    /// Queues a copy of the first `size` bytes of `buffer` (as it is after everything submitted
    /// so far) and asks for it to be mapped.
    pub fn start(gpu: &Gpu, buffer: &wgpu::Buffer, size: u64) -> Self {
        let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, size);
        gpu.queue.submit([encoder.finish()]);
        let done: Rc<Cell<Option<Result<(), String>>>> = Rc::new(Cell::new(None));
        let signal = done.clone();
        staging.map_async(wgpu::MapMode::Read, .., move |r| {
            signal.set(Some(r.map_err(|e| e.to_string())))
        });
        Self { staging, done }
    }

    /// The bytes once they have arrived, `None` before; once only.
    pub fn try_take(&self, gpu: &Gpu) -> Option<Result<Vec<u8>, String>> {
        let _ = gpu.device.poll(wgpu::PollType::Poll);
        let result = self.done.take()?;
        Some(
            result
                .map_err(|e| format!("reading the GPU buffer back failed: {e}"))
                .and_then(|()| {
                    let bytes = self
                        .staging
                        .get_mapped_range(..)
                        .map_err(|e| e.to_string())?
                        .to_vec();
                    self.staging.unmap();
                    Ok(bytes)
                }),
        )
    }
}

/// A particle system stepped by compute shaders. Same model as
/// [`crate::particles::ParticleSystem`]; the differences are in [`GpuParticleClock`].
pub struct ParticlesCompute {
    clock: GpuParticleClock,
    params: wgpu::Buffer,
    particles: wgpu::Buffer,
    instances: wgpu::Buffer,
    group: wgpu::BindGroup,
    /// `spawn` and `update`.
    kernels: Rc<Kernels>,
    /// Bursts requested for the next step, per emitter.
    bursts: [u32; MAX_GPU_EMITTERS],
}

impl ParticlesCompute {
    /// `capacity` slots, all dead.
    ///
    /// # Errors
    /// No compute on this backend, or `capacity` out of `[1,` [`MAX_GPU_PARTICLES`]`]`.
    pub fn new(gpu: &Gpu, capacity: usize, seed: u32) -> Result<Self, String> {
        no_compute(gpu)?;
        let clock = GpuParticleClock::new(capacity, seed)?;
        debug_assert!(capacity <= MAX_GPU_PARTICLES);
        let n = capacity as u64;
        let params = uniform(gpu, "particle params", 4 + 8 + 6 * MAX_GPU_EMITTERS);
        let particles = storage(
            gpu,
            "particles",
            n * PARTICLE_BYTES,
            wgpu::BufferUsages::empty(),
        );
        let instances = storage(
            gpu,
            "particle sprites",
            n * SPRITE_BYTES,
            wgpu::BufferUsages::VERTEX,
        );
        let ParticleKernels(kernels) = gpu.cached(|| {
            let rw = wgpu::BufferBindingType::Storage { read_only: false };
            ParticleKernels(Rc::new(Kernels::new(
                gpu,
                "particles",
                super::shader_source!("particles.wgsl"),
                &[wgpu::BufferBindingType::Uniform, rw, rw],
                &["spawn", "update"],
            )))
        });
        let group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("particles"),
            layout: &kernels.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: params.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: particles.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: instances.as_entire_binding(),
                },
            ],
        });
        Ok(Self {
            clock,
            kernels,
            params,
            particles,
            instances,
            group,
            bursts: [0; MAX_GPU_EMITTERS],
        })
    }

    /// Whether `other` steps with the same compiled kernels (two figures of one page do).
    pub fn shares_kernels(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.kernels, &other.kernels)
    }

    pub fn capacity(&self) -> usize {
        self.clock.capacity()
    }

    /// Spawns `count` particles from emitter `index` at the next step.
    pub fn burst(&mut self, index: usize, count: usize) {
        let mut b = self.bursts;
        self.clock.burst(&mut b, index, count);
        self.bursts = b;
    }

    /// One step of `dt` seconds (spawn, then age, kill, move, colour), submitted to the queue.
    ///
    /// # Errors
    /// What [`GpuParticleClock::step`] rejects.
    pub fn step(
        &mut self,
        gpu: &Gpu,
        emitters: &mut [Emitter],
        surfaces: &Surfaces,
        dt: f32,
    ) -> Result<(), String> {
        let rows = self
            .clock
            .step(emitters, surfaces, dt, std::mem::take(&mut self.bursts))?;
        let spawned: u32 = rows[3].iter().sum();
        gpu.queue.write_buffer(&self.params, 0, rows_bytes(&rows));
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_bind_group(0, &self.group, &[]);
            if spawned > 0 {
                pass.set_pipeline(&self.kernels.pipelines[0]);
                pass.dispatch_workgroups(spawned.div_ceil(WORKGROUP), 1, 1);
            }
            pass.set_pipeline(&self.kernels.pipelines[1]);
            pass.dispatch_workgroups((self.capacity() as u32).div_ceil(WORKGROUP), 1, 1);
        }
        gpu.queue.submit([encoder.finish()]);
        Ok(())
    }

    /// The atlas sprites of the last step (dead slots have size 0), for
    /// [`super::Renderer::gpu_sprites`].
    pub fn sprites(&self) -> (wgpu::Buffer, u32) {
        (self.instances.clone(), self.capacity() as u32)
    }

    /// Reads every slot back: positions, velocities, whether alive (tests; waits for the GPU).
    pub async fn read_back(&self, gpu: &Gpu) -> Result<(Vec<Vec3>, Vec<Vec3>, Vec<bool>), String> {
        let bytes = read_buffer(
            gpu,
            &self.particles,
            self.capacity() as u64 * PARTICLE_BYTES,
        )
        .await?;
        let floats: &[f32] = bytemuck::cast_slice(&bytes);
        let mut out = (Vec::new(), Vec::new(), Vec::new());
        for q in floats.chunks_exact(12) {
            out.0.push(Vec3::new(q[0], q[1], q[2]));
            out.1.push(Vec3::new(q[4], q[5], q[6]));
            out.2.push(q[9] > 0.5);
        }
        Ok(out)
    }

    /// Waits until the GPU has finished every step submitted so far (benchmarks).
    pub async fn finish(&self, gpu: &Gpu) -> Result<(), String> {
        read_buffer(gpu, &self.instances, 16).await.map(|_| ())
    }
}

/// A flock stepped by a compute shader: same model as [`crate::boids::Flock::step`], the
/// neighbours found by testing every pair or through a [`GpuGrid`] rebuilt every step (see
/// `shaders/boids.wgsl`).
pub struct BoidsCompute {
    n: usize,
    params: wgpu::Buffer,
    /// Ping-pong state: step k reads `state[k % 2]` and writes the other.
    state: [wgpu::Buffer; 2],
    instances: wgpu::Buffer,
    /// Built from `state[current]` at each grid step.
    grid: GpuGrid,
    groups: [wgpu::BindGroup; 2],
    /// `step` (every pair) and `step_grid`.
    kernels: Rc<Kernels>,
    current: usize,
    time_sec: f32,
}

impl BoidsCompute {
    /// Uploads a flock (positions and velocities, one each per boid) at clock `time_sec`.
    ///
    /// # Errors
    /// No compute on this backend, lengths that differ, a count out of `[1,`
    /// [`crate::figures::gpu::MAX_GPU_GRID_BOIDS`]`]`.
    pub fn new(
        gpu: &Gpu,
        positions: &[Vec3],
        velocities: &[Vec3],
        time_sec: f32,
    ) -> Result<Self, String> {
        no_compute(gpu)?;
        let n = positions.len();
        if velocities.len() != n {
            return Err(format!(
                "GPU boids: {n} positions but {} velocities",
                velocities.len()
            ));
        }
        check_gpu_boids(n, Search::Grid)?;
        let size = n as u64 * BOID_BYTES;
        let state = [
            storage(gpu, "boids a", size, wgpu::BufferUsages::empty()),
            storage(gpu, "boids b", size, wgpu::BufferUsages::empty()),
        ];
        let data: Vec<[f32; 8]> = positions
            .iter()
            .zip(velocities)
            .map(|(p, v)| [p.x, p.y, p.z, 0.0, v.x, v.y, v.z, 0.0])
            .collect();
        gpu.queue
            .write_buffer(&state[0], 0, bytemuck::cast_slice(&data));
        let instances = storage(
            gpu,
            "boid sprites",
            n as u64 * INSTANCE_BYTES,
            wgpu::BufferUsages::VERTEX,
        );
        let params = uniform(
            gpu,
            "boid params",
            12 + crate::figures::gpu::MAX_GPU_OBSTACLES,
        );
        let BoidKernels(kernels) = gpu.cached(|| {
            let storage = |read_only| wgpu::BufferBindingType::Storage { read_only };
            let uniform = wgpu::BufferBindingType::Uniform;
            BoidKernels(Rc::new(Kernels::new(
                gpu,
                "boids",
                &format!(
                    "{}\n{}",
                    super::grid::GRID_COMMON,
                    super::shader_source!("boids.wgsl")
                ),
                &[
                    uniform,
                    storage(true),
                    storage(false),
                    storage(false),
                    uniform,
                    storage(true),
                    storage(true),
                ],
                &["step", "step_grid"],
            )))
        });
        // One cell until the first grid step lays the grid over the flock's box.
        let one_cell = GridLayout {
            origin: Vec3::ZERO,
            cell_size: Vec3::ONE,
            dims: [1, 1, 1],
        };
        let grid = GpuGrid::new(gpu, &[&state[0], &state[1]], n, 2, one_cell)?;
        let groups = Self::groups(gpu, &kernels, &params, &state, &instances, &grid);
        Ok(Self {
            n,
            kernels,
            params,
            state,
            instances,
            grid,
            groups,
            current: 0,
            time_sec,
        })
    }

    fn groups(
        gpu: &Gpu,
        kernels: &Kernels,
        params: &wgpu::Buffer,
        state: &[wgpu::Buffer; 2],
        instances: &wgpu::Buffer,
        grid: &GpuGrid,
    ) -> [wgpu::BindGroup; 2] {
        let group = |from: &wgpu::Buffer, to: &wgpu::Buffer| {
            let buffers = [
                params,
                from,
                to,
                instances,
                grid.params(),
                grid.cell_start(),
                grid.sorted(),
            ];
            gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("boids"),
                layout: &kernels.layout,
                entries: &bind_entries(&buffers),
            })
        };
        [group(&state[0], &state[1]), group(&state[1], &state[0])]
    }

    /// Whether `other` steps with the same compiled kernel (two figures of one page do).
    pub fn shares_kernels(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.kernels, &other.kernels)
    }

    pub fn len(&self) -> usize {
        self.n
    }

    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The flock's clock, seconds.
    pub fn time_sec(&self) -> f32 {
        self.time_sec
    }

    /// One step of `dt` seconds, neighbours by `search` (on the grid: built first, in the same
    /// pass, over the bounds' box enlarged by a quarter and a cell, with cubic cells as wide as
    /// the widest rule's radius; boids outside it are clamped into its border cells, which
    /// keeps the search exact), submitted to the queue.
    ///
    /// # Errors
    /// What [`boid_rows`] rejects (every pair: at most [`crate::figures::gpu::MAX_GPU_BOIDS`]
    /// boids).
    pub fn step(
        &mut self,
        gpu: &Gpu,
        params: &BoidParams,
        dt: f32,
        search: Search,
    ) -> Result<(), String> {
        let mut rows = boid_rows(params, self.n, search, self.time_sec + dt, dt)?;
        if search == Search::Grid {
            let r = params.search_radius();
            let half = 1.25 * params.bounds + Vec3::splat(r);
            let layout = GridLayout::cubic(-half, half, r)?;
            // The predator chases prey up to 4 search radii away (`boid_rows`).
            rows[7][2] = layout.reach(4.0 * r);
            if self.grid.set_layout(gpu, layout)? {
                self.groups = Self::groups(
                    gpu,
                    &self.kernels,
                    &self.params,
                    &self.state,
                    &self.instances,
                    &self.grid,
                );
            }
        }
        gpu.queue.write_buffer(&self.params, 0, rows_bytes(&rows));
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            let kernel = match search {
                Search::Naive => 0,
                Search::Grid => {
                    self.grid.encode(&mut pass, self.current);
                    1
                }
            };
            pass.set_pipeline(&self.kernels.pipelines[kernel]);
            pass.set_bind_group(0, &self.groups[self.current], &[]);
            pass.dispatch_workgroups((self.n as u32).div_ceil(WORKGROUP), 1, 1);
        }
        gpu.queue.submit([encoder.finish()]);
        self.current = 1 - self.current;
        self.time_sec += dt;
        Ok(())
    }

    /// The grid of the last grid step (tests).
    pub fn grid(&self) -> &GpuGrid {
        &self.grid
    }

    /// The sprites of the last step, for [`super::Renderer::gpu_points`].
    pub fn sprites(&self) -> (wgpu::Buffer, u32) {
        (self.instances.clone(), self.n as u32)
    }

    /// Reads the flock back: positions and velocities (tests; waits for the GPU).
    pub async fn read_back(&self, gpu: &Gpu) -> Result<(Vec<Vec3>, Vec<Vec3>), String> {
        let bytes = read_buffer(gpu, &self.state[self.current], self.n as u64 * BOID_BYTES).await?;
        Ok(Self::unpack(&bytes))
    }

    /// Starts reading the flock back as it is after the steps submitted so far, without waiting
    /// (the page's order plot); [`BoidsCompute::unpack`] turns the bytes into the flock.
    pub fn start_read_back(&self, gpu: &Gpu) -> ReadBack {
        ReadBack::start(gpu, &self.state[self.current], self.n as u64 * BOID_BYTES)
    }

    /// Positions and velocities from the bytes of a read-back state buffer.
    pub fn unpack(bytes: &[u8]) -> (Vec<Vec3>, Vec<Vec3>) {
        let floats: Vec<f32> = bytemuck::pod_collect_to_vec(bytes);
        floats
            .chunks_exact(8)
            .map(|b| (Vec3::new(b[0], b[1], b[2]), Vec3::new(b[4], b[5], b[6])))
            .unzip()
    }

    /// Waits until the GPU has finished every step submitted so far (benchmarks).
    pub async fn finish(&self, gpu: &Gpu) -> Result<(), String> {
        read_buffer(gpu, &self.instances, 16).await.map(|_| ())
    }
}
