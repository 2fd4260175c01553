//! Skinning on the GPU, in the vertex shader (`shaders/skin.wgsl`): works on WebGPU and WebGL2.
//!
//! A skinned mesh is uploaded once (bind-pose positions and normals, colours, four joints and
//! weights per vertex); each frame the draw list carries its palette
//! ([`crate::draw::SkinnedDraw`], packed by [`crate::figures::gpu`]) and the shader skins every
//! vertex as it draws it. The palette is a uniform array, at most
//! [`crate::figures::gpu::MAX_GPU_JOINTS`] joints.

use super::renderer::scene_pipeline;
use super::Gpu;
use crate::draw::{Frame, SkinMeshId};
use crate::figures::gpu::{gpu_skinnable, MAX_GPU_JOINTS, ROWS_PER_JOINT};
use crate::mesh::MeshData;
use crate::skinning::SkinWeights;
use bytemuck::{Pod, Zeroable};
use glam::Vec4;

/// What `skin.wgsl`'s `Skin` uniform holds for one draw.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct SkinHeader {
    model: [f32; 16],
    normal_matrix: [f32; 16],
    color: [f32; 4],
    flags: [f32; 4],
}

const PALETTE_BYTES: usize = MAX_GPU_JOINTS * ROWS_PER_JOINT * 16;
const UNIFORM_BYTES: u64 = (std::mem::size_of::<SkinHeader>() + PALETTE_BYTES) as u64;
/// Draws sit at multiples of the dynamic-offset alignment (256 on both backends).
const STRIDE: u64 = UNIFORM_BYTES.next_multiple_of(256);

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct RestVertex {
    position: [f32; 3],
    normal: [f32; 3],
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Influence {
    joints: [u16; 4],
    weights: [f32; 4],
}

struct SkinMesh {
    rest: wgpu::Buffer,
    colors: wgpu::Buffer,
    influences: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    vertex_count: usize,
    joint_bound: usize,
}

/// The GPU-skinning pipeline and its meshes; owned by the [`super::Renderer`] as `skin`.
pub struct SkinPass {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    uniforms: wgpu::Buffer,
    capacity: u64,
    group: wgpu::BindGroup,
    /// Indexed by `SkinMeshId`; `None` once freed (ids are never reused).
    meshes: Vec<Option<SkinMesh>>,
    scratch: Vec<u8>,
    /// Per draw of the frame: its slot in `uniforms`, or `None` when it was skipped.
    slots: Vec<Option<u32>>,
    /// Counts the changes to the meshes (see [`super::Renderer::render`]'s unchanged-canvas test).
    pub(super) revision: u64,
}

/// The skinning pipeline's bind group layout and pipeline.
#[derive(Clone)]
struct SkinPipeline(wgpu::BindGroupLayout, wgpu::RenderPipeline);

impl SkinPass {
    pub(super) fn new(
        gpu: &Gpu,
        globals_layout: &wgpu::BindGroupLayout,
        format: wgpu::TextureFormat,
    ) -> Self {
        let device = &gpu.device;
        // The pipeline and its layout: once per page and format (see `Gpu::cached`).
        let SkinPipeline(layout, pipeline) = gpu.cached(|| {
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("skin"),
                entries: &[wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: true,
                        min_binding_size: wgpu::BufferSize::new(UNIFORM_BYTES),
                    },
                    count: None,
                }],
            });
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("skin"),
                source: wgpu::ShaderSource::Wgsl(
                    format!(
                        "{}\n{}\n{}",
                        super::shader_source!("common.wgsl"),
                        super::shader_source!("skin_common.wgsl"),
                        super::shader_source!("skin.wgsl")
                    )
                    .into(),
                ),
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("skin"),
                bind_group_layouts: &[Some(globals_layout), Some(&layout)],
                immediate_size: 0,
            });
            let rest_attributes = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
            let color_attributes = wgpu::vertex_attr_array![2 => Float32x4];
            let influence_attributes = wgpu::vertex_attr_array![3 => Uint16x4, 4 => Float32x4];
            let buffers = [
                Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<RestVertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &rest_attributes,
                }),
                Some(wgpu::VertexBufferLayout {
                    array_stride: 16,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &color_attributes,
                }),
                Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<Influence>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &influence_attributes,
                }),
            ];
            let pipeline = scene_pipeline(
                device,
                format,
                "skin",
                &pipeline_layout,
                &module,
                &buffers,
                wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
                    cull_mode: Some(wgpu::Face::Back),
                    ..Default::default()
                },
            );
            SkinPipeline(layout, pipeline)
        });
        let capacity = STRIDE * 2;
        let uniforms = Self::uniform_buffer(device, capacity);
        let group = Self::group(device, &layout, &uniforms);
        Self {
            pipeline,
            layout,
            uniforms,
            capacity,
            group,
            meshes: Vec::new(),
            scratch: Vec::new(),
            slots: Vec::new(),
            revision: 0,
        }
    }

    fn uniform_buffer(device: &wgpu::Device, size: u64) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("skin uniforms"),
            size,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    fn group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        buffer: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("skin"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(UNIFORM_BYTES),
                }),
            }],
        })
    }

    /// Uploads a mesh to be skinned on the GPU: bind-pose `data`, per-vertex `colors` (white when
    /// `None`) and `weights`.
    ///
    /// # Errors
    /// Lengths that differ, or weights naming a joint past [`MAX_GPU_JOINTS`].
    pub fn create(
        &mut self,
        gpu: &Gpu,
        data: &MeshData,
        colors: Option<&[Vec4]>,
        weights: &SkinWeights,
    ) -> Result<SkinMeshId, String> {
        self.revision += 1;
        use wgpu::util::DeviceExt;
        let n = data.positions.len();
        if data.normals.len() != n || weights.len() != n || colors.is_some_and(|c| c.len() != n) {
            return Err(format!(
                "skinned mesh: {n} positions but {} normals, {} weights{}",
                data.normals.len(),
                weights.len(),
                colors.map_or(String::new(), |c| format!(", {} colours", c.len()))
            ));
        }
        gpu_skinnable(weights.joint_bound(), MAX_GPU_JOINTS)?;
        let rest: Vec<RestVertex> = data
            .positions
            .iter()
            .zip(&data.normals)
            .map(|(p, n)| RestVertex {
                position: p.to_array(),
                normal: n.to_array(),
            })
            .collect();
        let colors: Vec<[f32; 4]> = match colors {
            Some(c) => c.iter().map(|c| c.to_array()).collect(),
            None => vec![[1.0; 4]; n],
        };
        let init = |label, contents: &[u8], usage| {
            gpu.device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents,
                    usage,
                })
        };
        let mut vertex = wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST;
        if gpu.compute {
            vertex |= wgpu::BufferUsages::STORAGE; // for the compute check, WebGPU only
        }
        let mesh = SkinMesh {
            rest: init("skin rest", bytemuck::cast_slice(&rest), vertex),
            colors: init("skin colours", bytemuck::cast_slice(&colors), vertex),
            influences: init(
                "skin influences",
                bytemuck::cast_slice(&influences(weights)),
                vertex,
            ),
            indices: init(
                "skin indices",
                bytemuck::cast_slice(&data.indices),
                wgpu::BufferUsages::INDEX,
            ),
            index_count: data.indices.len() as u32,
            vertex_count: n,
            joint_bound: weights.joint_bound(),
        };
        self.meshes.push(Some(mesh));
        Ok(SkinMeshId(self.meshes.len() - 1))
    }

    /// Releases a skinned mesh's GPU buffers; drawing a freed id draws nothing.
    pub fn free(&mut self, id: SkinMeshId) {
        self.revision += 1;
        if let Some(mesh) = self.meshes.get_mut(id.0).and_then(Option::take) {
            for buffer in [&mesh.rest, &mesh.colors, &mesh.influences, &mesh.indices] {
                buffer.destroy();
            }
        }
    }

    /// Replaces a skinned mesh's colours (a weight heat map) in place.
    pub fn update_colors(
        &mut self,
        gpu: &Gpu,
        id: SkinMeshId,
        colors: &[Vec4],
    ) -> Result<(), String> {
        self.revision += 1;
        let mesh = self
            .meshes
            .get(id.0)
            .and_then(Option::as_ref)
            .ok_or("unknown skinned mesh")?;
        if colors.len() != mesh.vertex_count {
            return Err(format!(
                "skinned mesh has {} vertices, got {} colours",
                mesh.vertex_count,
                colors.len()
            ));
        }
        let colors: Vec<[f32; 4]> = colors.iter().map(|c| c.to_array()).collect();
        gpu.queue
            .write_buffer(&mesh.colors, 0, bytemuck::cast_slice(&colors));
        Ok(())
    }

    /// Replaces a skinned mesh's joints and weights in place (new automatic weights).
    pub fn update_weights(
        &mut self,
        gpu: &Gpu,
        id: SkinMeshId,
        weights: &SkinWeights,
    ) -> Result<(), String> {
        self.revision += 1;
        let mesh = self
            .meshes
            .get_mut(id.0)
            .and_then(Option::as_mut)
            .ok_or("unknown skinned mesh")?;
        if weights.len() != mesh.vertex_count {
            return Err(format!(
                "skinned mesh has {} vertices, got {} weights",
                mesh.vertex_count,
                weights.len()
            ));
        }
        gpu_skinnable(weights.joint_bound(), MAX_GPU_JOINTS)?;
        mesh.joint_bound = weights.joint_bound();
        gpu.queue.write_buffer(
            &mesh.influences,
            0,
            bytemuck::cast_slice(&influences(weights)),
        );
        Ok(())
    }

    /// Writes the frame's skinned draws' uniforms (before the render pass). A draw whose palette
    /// is too short for its mesh's weights, or too long, is skipped.
    pub(super) fn prepare(&mut self, gpu: &Gpu, frame: &Frame) {
        self.scratch.clear();
        self.slots.clear();
        let mut slot = 0u32;
        for draw in &frame.skinned {
            let ok = self
                .meshes
                .get(draw.mesh.0)
                .and_then(Option::as_ref)
                .is_some_and(|m| {
                    gpu_skinnable(m.joint_bound, draw.joints.len()).is_ok()
                        && draw.joints.end <= frame.skin_palette.len()
                });
            if !ok {
                self.slots.push(None);
                continue;
            }
            let header = SkinHeader {
                model: draw.model.to_cols_array(),
                normal_matrix: draw.model.inverse().transpose().to_cols_array(),
                color: draw.color.to_array(),
                flags: [
                    if draw.vertex_colors { 1.0 } else { 0.0 },
                    if draw.dqs { 1.0 } else { 0.0 },
                    0.0,
                    0.0,
                ],
            };
            let start = self.scratch.len();
            self.scratch.extend_from_slice(bytemuck::bytes_of(&header));
            for joint in &frame.skin_palette[draw.joints.clone()] {
                for row in joint {
                    self.scratch
                        .extend_from_slice(bytemuck::bytes_of(&row.to_array()));
                }
            }
            self.scratch.resize(start + STRIDE as usize, 0);
            self.slots.push(Some(slot));
            slot += 1;
        }
        let needed = self.scratch.len() as u64;
        if needed > self.capacity {
            self.capacity = needed.next_power_of_two();
            self.uniforms = Self::uniform_buffer(&gpu.device, self.capacity);
            self.group = Self::group(&gpu.device, &self.layout, &self.uniforms);
        }
        if needed > 0 {
            gpu.queue.write_buffer(&self.uniforms, 0, &self.scratch);
        }
    }

    /// Records the frame's skinned draws into `pass` (group 0, the globals, is already set).
    pub(super) fn draw(&self, pass: &mut wgpu::RenderPass<'_>, frame: &Frame) {
        if !self.slots.iter().any(Option::is_some) {
            return;
        }
        pass.set_pipeline(&self.pipeline);
        for (draw, slot) in frame.skinned.iter().zip(&self.slots) {
            let Some(slot) = slot else { continue };
            let Some(Some(mesh)) = self.meshes.get(draw.mesh.0) else {
                continue;
            };
            pass.set_bind_group(1, &self.group, &[(*slot as u64 * STRIDE) as u32]);
            pass.set_vertex_buffer(0, mesh.rest.slice(..));
            pass.set_vertex_buffer(1, mesh.colors.slice(..));
            pass.set_vertex_buffer(2, mesh.influences.slice(..));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..mesh.index_count, 0, 0..1);
        }
    }
}

impl SkinPass {
    /// WebGPU only, for tests: skins the mesh of `frame`'s skinned draw `k` in a compute shader
    /// with the vertex shader's own formulas (`skin_common.wgsl`) and reads back its positions and
    /// normals (mesh space), to compare with the CPU's skinning number by number.
    ///
    /// # Errors
    /// No compute on this backend, no such draw, or a draw the renderer would skip.
    pub async fn skin_on_compute(
        &mut self,
        gpu: &Gpu,
        frame: &Frame,
        k: usize,
    ) -> Result<(Vec<glam::Vec3>, Vec<glam::Vec3>), String> {
        if !gpu.compute {
            return Err(format!(
                "the compute check needs WebGPU, not {}",
                gpu.backend_name
            ));
        }
        self.prepare(gpu, frame);
        let draw = frame.skinned.get(k).ok_or("no such skinned draw")?;
        let slot = self.slots[k].ok_or("this draw would be skipped")?;
        let mesh = self.meshes[draw.mesh.0]
            .as_ref()
            .ok_or("this mesh was freed")?;
        let size = (mesh.vertex_count * 24) as u64;
        let out = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("skinned (compute check)"),
            size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let entry = |binding, read_only| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let device = &gpu.device;
        let buffers_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("skin check buffers"),
            entries: &[entry(0, true), entry(1, true), entry(2, false)],
        });
        let skin_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("skin check uniform"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: true,
                    min_binding_size: wgpu::BufferSize::new(UNIFORM_BYTES),
                },
                count: None,
            }],
        });
        let buffers = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("skin check buffers"),
            layout: &buffers_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: mesh.rest.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: mesh.influences.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: out.as_entire_binding(),
                },
            ],
        });
        let uniform = Self::group(device, &skin_layout, &self.uniforms);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("skin check"),
            source: wgpu::ShaderSource::Wgsl(
                format!(
                    "{}\n{}",
                    super::shader_source!("skin_common.wgsl"),
                    super::shader_source!("skin_compute.wgsl")
                )
                .into(),
            ),
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("skin check"),
            bind_group_layouts: &[Some(&buffers_layout), Some(&skin_layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("skin check"),
            layout: Some(&layout),
            module: &module,
            entry_point: Some("skin_vertices"),
            compilation_options: Default::default(),
            cache: None,
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &buffers, &[]);
            pass.set_bind_group(1, &uniform, &[(slot as u64 * STRIDE) as u32]);
            pass.dispatch_workgroups((mesh.vertex_count as u32).div_ceil(64), 1, 1);
        }
        gpu.queue.submit([encoder.finish()]);
        let bytes = super::compute::read_buffer(gpu, &out, size).await?;
        let floats: &[f32] = bytemuck::cast_slice(&bytes);
        Ok(floats
            .chunks_exact(6)
            .map(|c| {
                (
                    glam::Vec3::new(c[0], c[1], c[2]),
                    glam::Vec3::new(c[3], c[4], c[5]),
                )
            })
            .unzip())
    }
}

fn influences(weights: &SkinWeights) -> Vec<Influence> {
    weights
        .joints()
        .iter()
        .zip(weights.weights())
        .map(|(&joints, &weights)| Influence { joints, weights })
        .collect()
}
