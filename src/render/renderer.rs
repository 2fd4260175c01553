//! Pipelines, buffers and the per-frame draw list.

use super::Gpu;
use crate::camera::OrbitCamera;
pub use crate::draw::{Frame, MeshId};
use crate::draw::{LineVertex, MarkerInstance, PointInstance, StrokeSegment};
use crate::mesh::MeshData;
use bytemuck::{Pod, Zeroable};
use glam::{Vec3, Vec4};
use std::cell::Cell;
use std::rc::Rc;

pub(super) const SAMPLE_COUNT: u32 = 4;
pub(super) const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24Plus;

/// A pipeline that draws into the renderer's scene pass: `vs_main` / `fs_main` of `module`, depth
/// tested and written (`DEPTH_FORMAT`), `SAMPLE_COUNT` samples, alpha blending into `format`.
/// Meshes, lines, points, GPU-skinned meshes, textured quads and sprites all share it.
pub(super) fn scene_pipeline(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    label: &str,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    buffers: &[Option<wgpu::VertexBufferLayout>],
    primitive: wgpu::PrimitiveState,
) -> wgpu::RenderPipeline {
    let depth_write = true;
    scene_pipeline_with(
        device,
        format,
        label,
        layout,
        module,
        buffers,
        primitive,
        depth_write,
    )
}

/// [`scene_pipeline`], choosing whether it writes depth. Wide lines and markers only test it:
/// their antialiased edges are translucent, and an edge that wrote depth would hide the next
/// segment of the same line wherever it lies a little further away (a receding curve would
/// come out striped).
#[allow(clippy::too_many_arguments)]
pub(super) fn scene_pipeline_with(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    label: &str,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    buffers: &[Option<wgpu::VertexBufferLayout>],
    primitive: wgpu::PrimitiveState,
    depth_write: bool,
) -> wgpu::RenderPipeline {
    let compare = wgpu::CompareFunction::LessEqual;
    scene_pipeline_depth(
        device,
        format,
        label,
        layout,
        module,
        buffers,
        primitive,
        depth_write,
        compare,
    )
}

/// [`scene_pipeline_with`], choosing the depth test too (the inset's background passes it
/// always, to reset the depth inside the inset).
#[allow(clippy::too_many_arguments)]
pub(super) fn scene_pipeline_depth(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    label: &str,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    buffers: &[Option<wgpu::VertexBufferLayout>],
    primitive: wgpu::PrimitiveState,
    depth_write: bool,
    depth_compare: wgpu::CompareFunction,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers,
        },
        primitive,
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(depth_write),
            depth_compare: Some(depth_compare),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: wgpu::MultisampleState {
            count: SAMPLE_COUNT,
            ..Default::default()
        },
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format,
                blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}
/// Per-object uniforms sit at multiples of WebGL2's (and WebGPU's) dynamic-offset alignment.
const OBJECT_STRIDE: u64 = 256;

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Globals {
    view: [f32; 16],
    proj: [f32; 16],
    eye: [f32; 4],
    light_dir: [f32; 4],
    params: [f32; 4],
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct ObjectUniform {
    model: [f32; 16],
    normal_matrix: [f32; 16],
    color: [f32; 4],
    flags: [f32; 4],
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct MeshVertex {
    position: [f32; 3],
    normal: [f32; 3],
    color: [f32; 4],
}

// The draw list's GPU-facing structs are plain `#[repr(C)]` f32 data (see src/draw.rs).
unsafe impl Zeroable for LineVertex {}
unsafe impl Pod for LineVertex {}
unsafe impl Zeroable for PointInstance {}
unsafe impl Pod for PointInstance {}
unsafe impl Zeroable for StrokeSegment {}
unsafe impl Pod for StrokeSegment {}
unsafe impl Zeroable for MarkerInstance {}
unsafe impl Pod for MarkerInstance {}

struct GpuMesh {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    /// Kept so that positions and normals can be replaced without touching colours.
    colors: Vec<[f32; 4]>,
}

/// A growable GPU buffer that is reallocated only when it must grow (to the next power of two).
struct StreamBuffer {
    buffer: wgpu::Buffer,
    capacity: u64,
    usage: wgpu::BufferUsages,
    label: &'static str,
}

impl StreamBuffer {
    fn new(
        device: &wgpu::Device,
        label: &'static str,
        usage: wgpu::BufferUsages,
        capacity: u64,
    ) -> Self {
        let usage = usage | wgpu::BufferUsages::COPY_DST;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: capacity,
            usage,
            mapped_at_creation: false,
        });
        Self {
            buffer,
            capacity,
            usage,
            label,
        }
    }

    /// Uploads `bytes`; returns true when the buffer had to be replaced (bind groups must follow).
    fn write(&mut self, gpu: &Gpu, bytes: &[u8]) -> bool {
        let needed = bytes.len() as u64;
        let grew = needed > self.capacity;
        if grew {
            self.capacity = needed.next_power_of_two();
            self.buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(self.label),
                size: self.capacity,
                usage: self.usage,
                mapped_at_creation: false,
            });
        }
        if !bytes.is_empty() {
            gpu.queue.write_buffer(&self.buffer, 0, bytes);
        }
        grew
    }
}

struct Targets {
    size: (u32, u32),
    color: wgpu::TextureView,
    depth: wgpu::TextureView,
}

/// Draws [`Frame`]s into one [`Gpu`]'s canvas (or into an offscreen texture, for tests).
pub struct Renderer {
    mesh_pipeline: wgpu::RenderPipeline,
    line_pipeline: wgpu::RenderPipeline,
    point_pipeline: wgpu::RenderPipeline,
    stroke_pipeline: wgpu::RenderPipeline,
    marker_pipeline: wgpu::RenderPipeline,
    globals: wgpu::Buffer,
    globals_group: wgpu::BindGroup,
    /// The inset's camera ([`crate::draw::inset`]): the same layout as `globals`, its own buffer
    /// (both are written before the pass runs), and the pipeline of its background.
    inset_globals: wgpu::Buffer,
    inset_globals_group: wgpu::BindGroup,
    inset_pipeline: wgpu::RenderPipeline,
    object_layout: wgpu::BindGroupLayout,
    objects: StreamBuffer,
    object_group: wgpu::BindGroup,
    lines: StreamBuffer,
    points: StreamBuffer,
    strokes: StreamBuffer,
    markers: StreamBuffer,
    /// Device pixels per CSS pixel: wide lines and markers are sized in CSS pixels.
    pub px_per_css: f32,
    /// Indexed by `MeshId`; `None` once freed (ids are never reused, so a stale id draws nothing).
    meshes: Vec<Option<GpuMesh>>,
    targets: Option<Targets>,
    format: wgpu::TextureFormat,
    encode_srgb: bool,
    scratch_vertices: Vec<MeshVertex>,
    scratch_objects: Vec<u8>,
    /// Textures, textured quads, sprites, noise images (src/render/texture.rs).
    pub(super) textured: super::texture::Textured,
    /// A unit cube (half-extent 1) and a unit sphere, ready for any lesson.
    pub cube: MeshId,
    pub sphere: MeshId,
    /// Background colour, sRGB-encoded.
    pub clear_srgb: Vec3,
    /// Direction towards the key light, world space.
    pub light_dir: Vec3,
    pub frame: Frame,
    /// Meshes skinned in the vertex shader (`frame.skinned`), see `skin.rs`.
    pub skin: super::skin::SkinPass,
    /// Point sprites written by compute shaders (`compute.rs`): buffer and count, drawn after
    /// `frame.points` and cleared with the frame.
    pub gpu_points: Vec<(wgpu::Buffer, u32)>,
    /// Atlas sprites written by compute shaders (`crate::texture::SpriteInstance` layout): buffer
    /// and count, drawn with `frame.sprite_texture` after the frame's sprites and cleared with
    /// the frame.
    pub gpu_sprites: Vec<(wgpu::Buffer, u32)>,
    /// Counts the changes to what a frame can name besides itself (meshes' vertices, textures):
    /// part of [`Renderer::render`]'s test for an unchanged canvas.
    pub(super) revision: u64,
    /// The [`Renderer::canvas_key`] of what the canvas shows, `None` when unknown (nothing
    /// drawn yet, a skipped frame, or a resize, which clears the canvas).
    shown: Option<u64>,
    /// How many frames [`Renderer::render`] drew into the canvas (for tests).
    canvas_frames: u64,
}

/// The renderer's pipelines and bind group layouts: made once per page and format, shared by
/// every figure (see `Gpu::cached`).
#[derive(Clone)]
struct Pipelines {
    globals_layout: wgpu::BindGroupLayout,
    object_layout: wgpu::BindGroupLayout,
    mesh: wgpu::RenderPipeline,
    line: wgpu::RenderPipeline,
    point: wgpu::RenderPipeline,
    stroke: wgpu::RenderPipeline,
    marker: wgpu::RenderPipeline,
    inset: wgpu::RenderPipeline,
}

impl Pipelines {
    fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let uniform_entry = |dynamic: bool, size: u64| wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: dynamic,
                min_binding_size: wgpu::BufferSize::new(size),
            },
            count: None,
        };
        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("globals"),
            entries: &[uniform_entry(false, std::mem::size_of::<Globals>() as u64)],
        });
        let object_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("object"),
            entries: &[uniform_entry(
                true,
                std::mem::size_of::<ObjectUniform>() as u64,
            )],
        });
        let shader = |label: &str, source: &str| {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(label),
                source: wgpu::ShaderSource::Wgsl(
                    format!("{}\n{}", super::shader_source!("common.wgsl"), source).into(),
                ),
            })
        };
        let mesh_shader = shader("mesh", super::shader_source!("mesh.wgsl"));
        let line_shader = shader("line", super::shader_source!("line.wgsl"));
        let point_shader = shader("point", super::shader_source!("point.wgsl"));
        let stroke_shader = shader("stroke", super::shader_source!("stroke.wgsl"));
        let marker_shader = shader("marker", super::shader_source!("marker.wgsl"));
        let inset_shader = shader("inset", super::shader_source!("inset.wgsl"));
        let layout_with = |layouts: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: None,
                bind_group_layouts: layouts,
                immediate_size: 0,
            })
        };
        let mesh_layout = layout_with(&[Some(&globals_layout), Some(&object_layout)]);
        let plain_layout = layout_with(&[Some(&globals_layout)]);

        let mesh_attributes =
            wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x4];
        let line_attributes =
            wgpu::vertex_attr_array![0 => Float32x3, 2 => Float32, 1 => Float32x4];
        let point_attributes =
            wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32, 2 => Float32x4];
        let stroke_attributes = wgpu::vertex_attr_array![
            0 => Float32x3, 1 => Float32, 2 => Float32x3, 3 => Float32, 4 => Float32x4, 5 => Float32x4
        ];
        let marker_attributes = wgpu::vertex_attr_array![
            0 => Float32x3, 1 => Float32, 2 => Float32x4, 3 => Float32x3, 4 => Float32
        ];
        let make_with = |label: &str,
                         layout: &wgpu::PipelineLayout,
                         module: &wgpu::ShaderModule,
                         buffer: wgpu::VertexBufferLayout,
                         topology: wgpu::PrimitiveTopology,
                         cull: Option<wgpu::Face>,
                         depth_write: bool| {
            scene_pipeline_with(
                device,
                format,
                label,
                layout,
                module,
                &[Some(buffer)],
                wgpu::PrimitiveState {
                    topology,
                    cull_mode: cull,
                    ..Default::default()
                },
                depth_write,
            )
        };
        let make = |label: &str,
                    layout: &wgpu::PipelineLayout,
                    module: &wgpu::ShaderModule,
                    buffer: wgpu::VertexBufferLayout,
                    topology: wgpu::PrimitiveTopology,
                    cull: Option<wgpu::Face>| {
            make_with(label, layout, module, buffer, topology, cull, true)
        };
        let mesh_pipeline = make(
            "mesh",
            &mesh_layout,
            &mesh_shader,
            wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<MeshVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &mesh_attributes,
            },
            wgpu::PrimitiveTopology::TriangleList,
            Some(wgpu::Face::Back),
        );
        let line_pipeline = make(
            "line",
            &plain_layout,
            &line_shader,
            wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<LineVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &line_attributes,
            },
            wgpu::PrimitiveTopology::LineList,
            None,
        );
        let point_pipeline = make(
            "point",
            &plain_layout,
            &point_shader,
            wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<PointInstance>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &point_attributes,
            },
            wgpu::PrimitiveTopology::TriangleList,
            None,
        );
        let stroke_pipeline = make_with(
            "stroke",
            &plain_layout,
            &stroke_shader,
            wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<StrokeSegment>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &stroke_attributes,
            },
            wgpu::PrimitiveTopology::TriangleList,
            None,
            false,
        );
        let marker_pipeline = make_with(
            "marker",
            &plain_layout,
            &marker_shader,
            wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<MarkerInstance>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &marker_attributes,
            },
            wgpu::PrimitiveTopology::TriangleList,
            None,
            false,
        );
        // The inset's background writes its colour (opaque) and the far depth whatever lies there.
        let inset_pipeline = scene_pipeline_depth(
            device,
            format,
            "inset background",
            &plain_layout,
            &inset_shader,
            &[],
            wgpu::PrimitiveState::default(),
            true,
            wgpu::CompareFunction::Always,
        );
        Self {
            globals_layout,
            object_layout,
            mesh: mesh_pipeline,
            line: line_pipeline,
            point: point_pipeline,
            stroke: stroke_pipeline,
            marker: marker_pipeline,
            inset: inset_pipeline,
        }
    }
}

impl Renderer {
    pub fn new(gpu: &Gpu) -> Self {
        let device = &gpu.device;
        let format = gpu.config.format;
        let Pipelines {
            globals_layout,
            object_layout,
            mesh: mesh_pipeline,
            line: line_pipeline,
            point: point_pipeline,
            stroke: stroke_pipeline,
            marker: marker_pipeline,
            inset: inset_pipeline,
        } = gpu.cached(|| Pipelines::new(device, format));
        // A camera's uniform buffer and its bind group: the main view's, and the inset's.
        let globals_with_group = |label: &str| {
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: std::mem::size_of::<Globals>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(label),
                layout: &globals_layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: buffer.as_entire_binding(),
                }],
            });
            (buffer, group)
        };
        let (globals, globals_group) = globals_with_group("globals");
        let (inset_globals, inset_globals_group) = globals_with_group("inset globals");
        let objects = StreamBuffer::new(
            device,
            "objects",
            wgpu::BufferUsages::UNIFORM,
            OBJECT_STRIDE * 64,
        );
        let object_group = Self::object_group(device, &object_layout, &objects.buffer);

        let textured =
            super::texture::Textured::new(gpu, &globals, std::mem::size_of::<Globals>() as u64);
        let mut renderer = Self {
            textured,
            mesh_pipeline,
            line_pipeline,
            point_pipeline,
            stroke_pipeline,
            marker_pipeline,
            globals,
            globals_group,
            inset_globals,
            inset_globals_group,
            inset_pipeline,
            object_layout,
            objects,
            object_group,
            lines: StreamBuffer::new(device, "lines", wgpu::BufferUsages::VERTEX, 1 << 16),
            points: StreamBuffer::new(device, "points", wgpu::BufferUsages::VERTEX, 1 << 12),
            strokes: StreamBuffer::new(device, "strokes", wgpu::BufferUsages::VERTEX, 1 << 14),
            markers: StreamBuffer::new(device, "markers", wgpu::BufferUsages::VERTEX, 1 << 12),
            px_per_css: 1.0,
            meshes: Vec::new(),
            targets: None,
            format,
            encode_srgb: gpu.encode_srgb_in_shader,
            scratch_vertices: Vec::new(),
            scratch_objects: Vec::new(),
            cube: MeshId(0),
            sphere: MeshId(0),
            clear_srgb: Vec3::new(0.96, 0.96, 0.97),
            light_dir: Vec3::new(0.4, 0.8, 0.45).normalize(),
            frame: Frame::default(),
            skin: super::skin::SkinPass::new(gpu, &globals_layout, format),
            gpu_points: Vec::new(),
            gpu_sprites: Vec::new(),
            revision: 0,
            shown: None,
            canvas_frames: 0,
        };
        // The draw list names these three by fixed ids (`MeshId::CUBE`, `SPHERE`, `CONE`).
        renderer.cube = renderer.create_mesh(gpu, &crate::mesh::cuboid(Vec3::ONE), None);
        renderer.sphere = renderer.create_mesh(gpu, &crate::mesh::uv_sphere(1.0, 24, 16), None);
        let cone = renderer.create_mesh(gpu, &crate::mesh::cone(1.0, 1.0, 20), None);
        debug_assert_eq!(
            (renderer.cube, renderer.sphere, cone),
            (MeshId::CUBE, MeshId::SPHERE, MeshId::CONE)
        );
        renderer
    }

    /// Takes `old`'s pixel ratio, background, light and frame count (a renderer made anew after
    /// the page's GPU was lost).
    pub fn keep_settings_of(&mut self, old: &Renderer) {
        self.px_per_css = old.px_per_css;
        self.clear_srgb = old.clear_srgb;
        self.light_dir = old.light_dir;
        self.canvas_frames = old.canvas_frames;
    }

    fn object_group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        buffer: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("objects"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<ObjectUniform>() as u64),
                }),
            }],
        })
    }

    /// Uploads a mesh; `colors` (linear RGBA, one per vertex) defaults to white.
    pub fn create_mesh(&mut self, gpu: &Gpu, data: &MeshData, colors: Option<&[Vec4]>) -> MeshId {
        self.revision += 1;
        use wgpu::util::DeviceExt;
        let colors: Vec<[f32; 4]> = match colors {
            Some(c) => c.iter().map(|c| c.to_array()).collect(),
            None => vec![[1.0; 4]; data.positions.len()],
        };
        let vertices: Vec<MeshVertex> = data
            .positions
            .iter()
            .zip(&data.normals)
            .zip(&colors)
            .map(|((p, n), c)| MeshVertex {
                position: p.to_array(),
                normal: n.to_array(),
                color: *c,
            })
            .collect();
        let vertices = gpu
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh vertices"),
                contents: bytemuck::cast_slice(&vertices),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            });
        let indices = gpu
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh indices"),
                contents: bytemuck::cast_slice(&data.indices),
                usage: wgpu::BufferUsages::INDEX,
            });
        self.meshes.push(Some(GpuMesh {
            vertices,
            indices,
            index_count: data.indices.len() as u32,
            colors,
        }));
        MeshId(self.meshes.len() - 1)
    }

    /// Releases a mesh's GPU buffers (a page that loads one glTF file after another frees the
    /// last file's meshes). Drawing a freed id draws nothing; freeing twice is harmless.
    pub fn free_mesh(&mut self, id: MeshId) {
        self.revision += 1;
        if let Some(slot) = self.meshes.get_mut(id.0) {
            if let Some(mesh) = slot.take() {
                mesh.vertices.destroy();
                mesh.indices.destroy();
            }
        }
    }

    /// Replaces a mesh's positions and normals in place (skinning, cloth): same vertex count, no
    /// reallocation on the GPU.
    pub fn update_mesh(
        &mut self,
        gpu: &Gpu,
        id: MeshId,
        positions: &[Vec3],
        normals: &[Vec3],
    ) -> Result<(), String> {
        self.revision += 1;
        let mesh = self
            .meshes
            .get(id.0)
            .and_then(Option::as_ref)
            .ok_or("unknown mesh")?;
        if positions.len() != mesh.colors.len() || normals.len() != mesh.colors.len() {
            return Err(format!(
                "mesh has {} vertices, got {} positions and {} normals",
                mesh.colors.len(),
                positions.len(),
                normals.len()
            ));
        }
        self.scratch_vertices.clear();
        self.scratch_vertices
            .extend(
                positions
                    .iter()
                    .zip(normals)
                    .zip(&mesh.colors)
                    .map(|((p, n), c)| MeshVertex {
                        position: p.to_array(),
                        normal: n.to_array(),
                        color: *c,
                    }),
            );
        gpu.queue.write_buffer(
            &mesh.vertices,
            0,
            bytemuck::cast_slice(&self.scratch_vertices),
        );
        Ok(())
    }

    /// Replaces a mesh's positions, normals and colours in place (terrains whose colour follows
    /// height and slope): same vertex count, no reallocation on the GPU.
    pub fn update_mesh_with_colors(
        &mut self,
        gpu: &Gpu,
        id: MeshId,
        positions: &[Vec3],
        normals: &[Vec3],
        colors: &[Vec4],
    ) -> Result<(), String> {
        self.revision += 1;
        let mesh = self
            .meshes
            .get_mut(id.0)
            .and_then(Option::as_mut)
            .ok_or("unknown mesh")?;
        if colors.len() != mesh.colors.len() {
            return Err(format!(
                "mesh has {} vertices, got {} colours",
                mesh.colors.len(),
                colors.len()
            ));
        }
        for (dst, src) in mesh.colors.iter_mut().zip(colors) {
            *dst = src.to_array();
        }
        self.update_mesh(gpu, id, positions, normals)
    }

    /// Draws and clears `self.frame` into the canvas; `fingerprint` is the frame's
    /// [`Frame::fingerprint`] (the caller has it already).
    ///
    /// When the canvas already shows this frame, it is not drawn again: same fingerprint, same
    /// camera, size, light and background, no mesh or texture changed since (`revision`), and
    /// nothing from compute shaders (`gpu_points`, whose buffers change without the frame
    /// knowing). A paused figure then costs its scene's frame and a hash, not a GPU frame: the
    /// canvas keeps its last image (WebGPU and WebGL2 both present only what was drawn).
    pub fn render(
        &mut self,
        gpu: &Gpu,
        camera: &OrbitCamera,
        fingerprint: u64,
    ) -> Result<(), String> {
        let key = self.canvas_key(gpu, camera, fingerprint);
        if self.gpu_points.is_empty() && self.gpu_sprites.is_empty() && self.shown == Some(key) {
            self.frame.clear();
            return Ok(());
        }
        self.shown = None;
        let Some(frame) = gpu.next_frame() else {
            self.frame.clear();
            self.gpu_points.clear();
            self.gpu_sprites.clear();
            return Ok(());
        };
        let view = frame.texture.create_view(&Default::default());
        // The target has the figure's size on both backends (see `Gpu::next_frame`); `encode`
        // takes both sizes and sets a viewport only where they differ.
        let target_size = (frame.texture.width(), frame.texture.height());
        let size = (gpu.config.width, gpu.config.height);
        let commands = self.encode(gpu, camera, &view, size, target_size);
        gpu.queue.submit([commands]);
        gpu.show(frame)?;
        self.shown = Some(key);
        self.canvas_frames += 1;
        Ok(())
    }

    /// How many frames [`Renderer::render`] has drawn into the canvas (not the ones it found
    /// already shown).
    pub fn canvas_frames(&self) -> u64 {
        self.canvas_frames
    }

    /// Forgets what the canvas shows, so that the next [`Renderer::render`] draws (after a resize,
    /// which clears the canvas).
    pub fn canvas_cleared(&mut self) {
        self.shown = None;
    }

    /// Everything a frame drawn into the canvas depends on, hashed: the frame's fingerprint, the
    /// camera's matrices, the canvas size, light, background and the mesh and texture changes.
    fn canvas_key(&self, gpu: &Gpu, camera: &OrbitCamera, fingerprint: u64) -> u64 {
        let (w, h) = (gpu.config.width, gpu.config.height);
        let aspect = w.max(1) as f32 / h.max(1) as f32;
        let matrices = [camera.view(), camera.projection(aspect)];
        let words = matrices
            .iter()
            .flat_map(|m| m.to_cols_array())
            .chain(self.light_dir.to_array())
            .chain(self.clear_srgb.to_array())
            .chain([self.px_per_css])
            .map(|x| x.to_bits() as u64)
            .chain([
                fingerprint,
                self.revision,
                self.skin.revision,
                w as u64,
                h as u64,
            ]);
        words.fold(0xcbf2_9ce4_8422_2325u64, |h, x| {
            (h ^ x).wrapping_mul(0x0100_0000_01b3)
        })
    }

    /// Draws and clears `self.frame` into an offscreen `width × height` texture and returns its
    /// pixels as sRGB-encoded RGBA bytes, row by row from the top. For tests and thumbnails.
    pub async fn render_to_rgba(
        &mut self,
        gpu: &Gpu,
        camera: &OrbitCamera,
        width: u32,
        height: u32,
    ) -> Result<Vec<u8>, String> {
        let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("offscreen"),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: self.format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&Default::default());
        let draw = self.encode(gpu, camera, &view, (width, height), (width, height));
        let padded_row = (width * 4).div_ceil(256) * 256;
        let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: (padded_row * height) as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row),
                    rows_per_image: Some(height),
                },
            },
            wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
        );
        gpu.queue.submit([draw, encoder.finish()]);
        let done: Rc<Cell<Option<Result<(), String>>>> = Rc::new(Cell::new(None));
        let signal = done.clone();
        readback.map_async(wgpu::MapMode::Read, .., move |r| {
            signal.set(Some(r.map_err(|e| e.to_string())))
        });
        // WebGPU completes the mapping from the browser's event loop, WebGL2 when polled: do both.
        let result = loop {
            let _ = gpu.device.poll(wgpu::PollType::Poll);
            if let Some(r) = done.take() {
                break r;
            }
            sleep_ms(5).await;
        };
        result.map_err(|e| format!("reading pixels back failed: {e}"))?;
        let mapped = readback.get_mapped_range(..).map_err(|e| e.to_string())?;
        let mut pixels = Vec::with_capacity((width * height * 4) as usize);
        for row in mapped.chunks(padded_row as usize) {
            pixels.extend_from_slice(&row[..(width * 4) as usize]);
        }
        drop(mapped);
        readback.unmap();
        if self.format == wgpu::TextureFormat::Bgra8Unorm {
            pixels.chunks_mut(4).for_each(|p| p.swap(0, 2));
        }
        Ok(pixels)
    }

    fn ensure_targets(&mut self, gpu: &Gpu, size: (u32, u32)) {
        if self.targets.as_ref().is_some_and(|t| t.size == size) {
            return;
        }
        let make = |format, label| {
            gpu.device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size: wgpu::Extent3d {
                        width: size.0,
                        height: size.1,
                        depth_or_array_layers: 1,
                    },
                    mip_level_count: 1,
                    sample_count: SAMPLE_COUNT,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                    view_formats: &[],
                })
                .create_view(&Default::default())
        };
        let [color, depth] = gpu.shared_targets(size, self.format, || {
            [make(self.format, "msaa color"), make(DEPTH_FORMAT, "depth")]
        });
        self.targets = Some(Targets { size, color, depth });
    }

    /// Records the frame into the top-left `size` of `target`, which is `target_size`.
    fn encode(
        &mut self,
        gpu: &Gpu,
        camera: &OrbitCamera,
        target: &wgpu::TextureView,
        size: (u32, u32),
        target_size: (u32, u32),
    ) -> wgpu::CommandBuffer {
        self.ensure_targets(gpu, target_size);
        let aspect = size.0 as f32 / size.1.max(1) as f32;
        let globals = Globals {
            view: camera.view().to_cols_array(),
            proj: camera.projection(aspect).to_cols_array(),
            eye: camera.eye().extend(1.0).to_array(),
            light_dir: self.light_dir.normalize().extend(0.0).to_array(),
            params: [
                if self.encode_srgb { 1.0 } else { 0.0 },
                size.0 as f32,
                size.1 as f32,
                self.px_per_css,
            ],
        };
        gpu.queue
            .write_buffer(&self.globals, 0, bytemuck::bytes_of(&globals));
        // The inset: its square in device pixels (inside the target) and its own camera.
        let inset = self.frame.inset.as_ref().and_then(|inset| {
            let (view, proj, eye) = crate::draw::inset::inset_camera(inset)?;
            let scale = self.px_per_css.max(1e-3);
            let css = glam::Vec2::new(size.0 as f32, size.1 as f32) / scale;
            let rect = crate::draw::inset::inset_rect(css);
            let border = (crate::draw::inset::INSET_BORDER_PX * scale)
                .round()
                .max(1.0) as u32;
            let x = (rect.min.x * scale).round().max(0.0) as u32;
            let y = (rect.min.y * scale).round().max(0.0) as u32;
            let side = (rect.size.x * scale).round() as u32;
            let side = side
                .min(size.0.saturating_sub(x))
                .min(size.1.saturating_sub(y));
            (side > 2 * border + 2).then_some((view, proj, eye, [x, y, side, border]))
        });
        if let Some((view, proj, eye, [_, _, side, border])) = inset {
            let inner = (side - 2 * border) as f32;
            let inset_globals = Globals {
                view: view.to_cols_array(),
                proj: proj.to_cols_array(),
                eye: eye.extend(1.0).to_array(),
                params: [globals.params[0], inner, inner, self.px_per_css],
                ..globals
            };
            gpu.queue
                .write_buffer(&self.inset_globals, 0, bytemuck::bytes_of(&inset_globals));
        }

        self.scratch_objects.clear();
        for draw in &self.frame.meshes {
            let object = ObjectUniform {
                model: draw.model.to_cols_array(),
                normal_matrix: draw.model.inverse().transpose().to_cols_array(),
                color: draw.color.to_array(),
                flags: [
                    if draw.vertex_colors { 1.0 } else { 0.0 },
                    if draw.unlit { 1.0 } else { 0.0 },
                    0.0,
                    0.0,
                ],
            };
            self.scratch_objects
                .extend_from_slice(bytemuck::bytes_of(&object));
            self.scratch_objects.resize(
                self.scratch_objects
                    .len()
                    .next_multiple_of(OBJECT_STRIDE as usize),
                0,
            );
        }
        if self.objects.write(gpu, &self.scratch_objects) {
            self.object_group =
                Self::object_group(&gpu.device, &self.object_layout, &self.objects.buffer);
        }
        self.lines
            .write(gpu, bytemuck::cast_slice(&self.frame.lines));
        self.points
            .write(gpu, bytemuck::cast_slice(&self.frame.points));
        self.strokes
            .write(gpu, bytemuck::cast_slice(&self.frame.strokes));
        self.markers
            .write(gpu, bytemuck::cast_slice(&self.frame.markers));
        self.skin.prepare(gpu, &self.frame);

        self.textured.prepare(gpu, &self.frame);
        let clear = if self.encode_srgb {
            self.clear_srgb
        } else {
            srgb_to_linear(self.clear_srgb)
        };
        let targets = self.targets.as_ref().expect("targets were just ensured");
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("frame"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &targets.color,
                    depth_slice: None,
                    resolve_target: Some(target),
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color {
                            r: clear.x as f64,
                            g: clear.y as f64,
                            b: clear.z as f64,
                            a: 1.0,
                        }),
                        store: wgpu::StoreOp::Discard,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &targets.depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_bind_group(0, &self.globals_group, &[]);
            if size != target_size {
                pass.set_viewport(0.0, 0.0, size.0 as f32, size.1 as f32, 0.0, 1.0);
            }
            self.draw_scene(&mut pass, None);
            if let Some((_, _, _, [x, y, side, border])) = inset {
                // The border's square, then the fill's inside it, then the frame again with the
                // inset's camera (group 0), clipped to the fill.
                pass.set_pipeline(&self.inset_pipeline);
                for (i, (at, width)) in [(0, side), (border, side - 2 * border)]
                    .into_iter()
                    .enumerate()
                {
                    let (ix, iy) = (x + at, y + at);
                    pass.set_viewport(ix as f32, iy as f32, width as f32, width as f32, 0.0, 1.0);
                    pass.set_scissor_rect(ix, iy, width, width);
                    let first = 3 * i as u32;
                    pass.draw(first..first + 3, 0..1);
                }
                pass.set_bind_group(0, &self.inset_globals_group, &[]);
                self.draw_scene(&mut pass, self.frame.inset.as_ref());
                // The whole target again: WebGL2 resolves the multisampled colour with a blit
                // that the scissor rectangle would clip to the inset.
                pass.set_scissor_rect(0, 0, target_size.0, target_size.1);
            }
        }
        self.gpu_points.clear();
        self.gpu_sprites.clear();
        self.frame.clear();
        encoder.finish()
    }

    /// Records the frame's draws into `pass` (group 0, the camera, is already set): the opaque
    /// geometry (meshes, GPU-skinned meshes, lines, points, textured squares), then the wide
    /// lines and markers, then, outside an `inset`, the sprites. In the inset (whose camera is
    /// not the textured pipelines' group 0) the squares and sprites are left out, and all but
    /// the strokes and markers it names where it names some ([`crate::draw::inset::Inset::only`]).
    fn draw_scene<'a>(
        &'a self,
        pass: &mut wgpu::RenderPass<'a>,
        inset: Option<&crate::draw::inset::Inset>,
    ) {
        let with_textures = inset.is_none();
        let only = inset.and_then(|i| i.only.clone());
        if only.is_none() {
            if !self.frame.meshes.is_empty() {
                pass.set_pipeline(&self.mesh_pipeline);
                for (i, draw) in self.frame.meshes.iter().enumerate() {
                    let Some(Some(mesh)) = self.meshes.get(draw.mesh.0) else {
                        continue;
                    };
                    pass.set_bind_group(
                        1,
                        &self.object_group,
                        &[(i as u64 * OBJECT_STRIDE) as u32],
                    );
                    pass.set_vertex_buffer(0, mesh.vertices.slice(..));
                    pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                    pass.draw_indexed(0..mesh.index_count, 0, 0..1);
                }
            }
            self.skin.draw(pass, &self.frame);
            if !self.frame.lines.is_empty() {
                pass.set_pipeline(&self.line_pipeline);
                pass.set_vertex_buffer(0, self.lines.buffer.slice(..));
                pass.draw(0..self.frame.lines.len() as u32, 0..1);
            }
            if !self.frame.points.is_empty() {
                pass.set_pipeline(&self.point_pipeline);
                pass.set_vertex_buffer(0, self.points.buffer.slice(..));
                pass.draw(0..6, 0..self.frame.points.len() as u32);
            }
            for (buffer, count) in &self.gpu_points {
                pass.set_pipeline(&self.point_pipeline);
                pass.set_vertex_buffer(0, buffer.slice(..));
                pass.draw(0..6, 0..*count);
            }
        }
        if with_textures && !self.frame.quads.is_empty() {
            self.textured.draw_quads(pass, &self.frame);
            // The quads bind their own group 0 (the same camera buffer): back to the renderer's.
            pass.set_bind_group(0, &self.globals_group, &[]);
        }
        // Wide lines and markers after everything opaque: their antialiased edges blend over
        // what lies behind them, and they test depth without writing it (later ones draw over
        // earlier ones; markers over lines).
        let [strokes, markers] =
            only.unwrap_or([0..self.frame.strokes.len(), 0..self.frame.markers.len()]);
        if !strokes.is_empty() {
            pass.set_pipeline(&self.stroke_pipeline);
            pass.set_vertex_buffer(0, self.strokes.buffer.slice(..));
            pass.draw(0..6, strokes.start as u32..strokes.end as u32);
        }
        if !markers.is_empty() {
            pass.set_pipeline(&self.marker_pipeline);
            pass.set_vertex_buffer(0, self.markers.buffer.slice(..));
            pass.draw(0..6, markers.start as u32..markers.end as u32);
        }
        if with_textures {
            self.textured
                .draw_sprites(pass, &self.frame, &self.gpu_sprites);
        }
    }
}

fn srgb_to_linear(c: Vec3) -> Vec3 {
    let f = |x: f32| {
        if x <= 0.04045 {
            x / 12.92
        } else {
            ((x + 0.055) / 1.055).powf(2.4)
        }
    };
    Vec3::new(f(c.x), f(c.y), f(c.z))
}

/// Resolves after `ms` milliseconds (a JavaScript timer), letting the browser run its event loop.
pub(crate) async fn sleep_ms(ms: i32) {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        let window = web_sys::window().expect("a browser window");
        let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, ms);
    });
    let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
}
