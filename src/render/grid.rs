//! A uniform grid built on the GPU every step (WebGPU compute), after Hoetzlein, "Fast
//! fixed-radius nearest neighbours: interactive million-particle fluids" (GTC 2014): the points'
//! indices sorted by cell with a counting sort, as the CPU's [`crate::boids::grid::Grid`] does,
//! so that a kernel finds a point's neighbours in the runs of the cells around it. The passes are
//! in `shaders/grid.wgsl`; the layout and its caps ([`MAX_GPU_GRID_CELLS`] cells,
//! [`MAX_GPU_GRID_BOIDS`] points) are [`crate::figures::gpu::GridLayout`] and
//! [`crate::figures::gpu::grid_rows`], natively. Any kernel whose points are `vec4`s with the
//! position first can use it, as the boids' `BoidsCompute` does.
//!
//! A kernel that searches the grid binds [`GpuGrid::params`], [`GpuGrid::cell_start`]
//! (`cell_start[c]..cell_start[c + 1]` is cell c's run, `cell_start[cells]` the point count) and
//! [`GpuGrid::sorted`] (point indices in cell order), and prefixes its shader with
//! `grid_common.wgsl` for the cells' arithmetic.

use super::compute::{bind_entries, storage, uniform, Kernels};
use super::Gpu;
use crate::figures::gpu::{grid_rows, GridLayout, GRID_SCAN_BLOCK};
#[cfg(doc)]
use crate::figures::gpu::{MAX_GPU_GRID_BOIDS, MAX_GPU_GRID_CELLS};
use std::rc::Rc;

const WORKGROUP: u32 = 256;

/// `grid_common.wgsl`, for the shaders that search a grid to prefix (one copy in the module).
pub(super) static GRID_COMMON: &str = super::shader_source!("grid_common.wgsl");

/// The grid's passes, as the page caches them (one compile per page).
#[derive(Clone)]
struct GridKernels(Rc<Kernels>);

/// A GPU grid over `n` points read from one of a few source buffers (a simulation's ping-pong
/// state), rebuilt by [`GpuGrid::encode`] inside the caller's compute pass.
pub struct GpuGrid {
    n: usize,
    stride: u32,
    layout: GridLayout,
    sources: Vec<wgpu::Buffer>,
    params: wgpu::Buffer,
    /// Per cell its count, then (after the prefix sum) its run's start; one more for the total.
    cells: wgpu::Buffer,
    /// Cells the buffers hold.
    capacity: usize,
    block_sums: wgpu::Buffer,
    rank: wgpu::Buffer,
    sorted: wgpu::Buffer,
    /// One per source.
    groups: Vec<wgpu::BindGroup>,
    kernels: Rc<Kernels>,
}

impl GpuGrid {
    /// A grid of `layout` over the `n` points of each buffer in `sources`, point i being the
    /// `stride` `vec4`s from `i · stride`, its position the first one's xyz.
    ///
    /// # Errors
    /// What [`grid_rows`] rejects.
    pub fn new(
        gpu: &Gpu,
        sources: &[&wgpu::Buffer],
        n: usize,
        stride: u32,
        layout: GridLayout,
    ) -> Result<Self, String> {
        super::compute::no_compute(gpu)?;
        let rows = grid_rows(&layout, n, stride)?;
        let GridKernels(kernels) = gpu.cached(|| {
            let rw = wgpu::BufferBindingType::Storage { read_only: false };
            GridKernels(Rc::new(Kernels::new(
                gpu,
                "grid",
                &format!("{GRID_COMMON}\n{}", super::shader_source!("grid.wgsl")),
                &[
                    wgpu::BufferBindingType::Uniform,
                    wgpu::BufferBindingType::Storage { read_only: true },
                    rw,
                    rw,
                    rw,
                    rw,
                ],
                &[
                    "clear",
                    "count",
                    "scan_blocks",
                    "scan_sums",
                    "add_sums",
                    "scatter",
                ],
            )))
        });
        let per_point = (n * 4) as u64;
        let mut grid = Self {
            n,
            stride,
            layout,
            sources: sources.iter().map(|&b| b.clone()).collect(),
            params: uniform(gpu, "grid params", rows.len()),
            cells: storage(gpu, "grid cells", 4, wgpu::BufferUsages::empty()),
            capacity: 0,
            block_sums: storage(gpu, "grid block sums", 4, wgpu::BufferUsages::empty()),
            rank: storage(gpu, "grid ranks", per_point, wgpu::BufferUsages::empty()),
            sorted: storage(gpu, "grid sorted", per_point, wgpu::BufferUsages::empty()),
            groups: Vec::new(),
            kernels,
        };
        grid.set_layout(gpu, layout)?;
        Ok(grid)
    }

    /// Moves the grid to `layout` from the next [`GpuGrid::encode`] on. Returns whether the
    /// buffers were made again (more cells than they held): a kernel that binds them must then
    /// make its bind groups again.
    ///
    /// # Errors
    /// What [`grid_rows`] rejects; the grid keeps its layout.
    pub fn set_layout(&mut self, gpu: &Gpu, layout: GridLayout) -> Result<bool, String> {
        let rows = grid_rows(&layout, self.n, self.stride)?;
        gpu.queue
            .write_buffer(&self.params, 0, bytemuck::cast_slice(&rows));
        self.layout = layout;
        let cells = layout.cells();
        if cells <= self.capacity {
            return Ok(false);
        }
        let none = wgpu::BufferUsages::empty();
        self.capacity = cells;
        self.cells = storage(gpu, "grid cells", (cells as u64 + 1) * 4, none);
        let blocks = cells.div_ceil(GRID_SCAN_BLOCK) as u64;
        self.block_sums = storage(gpu, "grid block sums", blocks * 4, none);
        self.groups = self
            .sources
            .iter()
            .map(|source| {
                let buffers = [
                    &self.params,
                    source,
                    &self.cells,
                    &self.block_sums,
                    &self.rank,
                    &self.sorted,
                ];
                gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("grid"),
                    layout: &self.kernels.layout,
                    entries: &bind_entries(&buffers),
                })
            })
            .collect();
        Ok(true)
    }

    pub fn layout(&self) -> &GridLayout {
        &self.layout
    }

    /// Queues the grid's passes on the points of `sources[source]` (as [`GpuGrid::new`] got
    /// them) into `pass`; a kernel dispatched after them in the same pass sees the grid.
    pub fn encode(&self, pass: &mut wgpu::ComputePass<'_>, source: usize) {
        let cells = self.layout.cells() as u32;
        let points = (self.n as u32).div_ceil(WORKGROUP);
        let blocks = cells.div_ceil(GRID_SCAN_BLOCK as u32);
        pass.set_bind_group(0, &self.groups[source], &[]);
        let sizes = [
            cells.div_ceil(WORKGROUP),
            points,
            blocks,
            1,
            cells.div_ceil(WORKGROUP),
            points,
        ];
        for (pipeline, groups) in self.kernels.pipelines.iter().zip(sizes) {
            pass.set_pipeline(pipeline);
            pass.dispatch_workgroups(groups, 1, 1);
        }
    }

    /// Builds the grid on `sources[source]` now (tests: a simulation encodes it in its step).
    pub fn build(&self, gpu: &Gpu, source: usize) {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        self.encode(&mut encoder.begin_compute_pass(&Default::default()), source);
        gpu.queue.submit([encoder.finish()]);
    }

    /// The grid's uniform block (`GridParams` in `grid_common.wgsl`).
    pub fn params(&self) -> &wgpu::Buffer {
        &self.params
    }

    /// `cell_start[c]`: where cell c's run starts in [`GpuGrid::sorted`]; one more entry, the
    /// point count.
    pub fn cell_start(&self) -> &wgpu::Buffer {
        &self.cells
    }

    /// The points' indices in cell order.
    pub fn sorted(&self) -> &wgpu::Buffer {
        &self.sorted
    }

    /// Reads the last build back: the cells' starts (cell count + 1 of them) and the sorted
    /// indices (tests; waits for the GPU).
    pub async fn read_back(&self, gpu: &Gpu) -> Result<(Vec<u32>, Vec<u32>), String> {
        let read =
            |buffer, count: usize| super::compute::read_buffer(gpu, buffer, count as u64 * 4);
        let starts = read(&self.cells, self.layout.cells() + 1).await?;
        let sorted = read(&self.sorted, self.n).await?;
        Ok((
            bytemuck::pod_collect_to_vec(&starts),
            bytemuck::pod_collect_to_vec(&sorted),
        ))
    }
}
