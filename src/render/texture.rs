//! Textures: RGBA8 images uploaded from Rust buffers (rewritten in place when they change), the
//! textured quads and sprites of the draw list (`crate::texture`), and noise images rendered by
//! a WGSL fragment shader into a texture (works on WebGL2 as on WebGPU) and read back.

use super::renderer::Renderer;
use super::Gpu;
use crate::draw::Frame;
use crate::texture::{validate_rgba, SpriteInstance, TextureId};
use bytemuck::{Pod, Zeroable};
use std::cell::Cell;
use std::rc::Rc;

/// Per-quad uniforms sit at multiples of the dynamic-offset alignment (as the renderer's objects).
const QUAD_STRIDE: u64 = 256;

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct QuadUniform {
    model: [f32; 16],
    tint: [f32; 4],
    uv: [f32; 4],
    flags: [f32; 4],
}

unsafe impl Zeroable for SpriteInstance {}
unsafe impl Pod for SpriteInstance {}

/// What the noise shader computes (see `shaders/noise.wgsl`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoiseImage {
    /// Noise coordinates of the image's top-left corner.
    pub origin: [f32; 2],
    /// Noise units per texel along x and y (rows run downwards).
    pub step: [f32; 2],
    /// The slice of 3D Perlin noise.
    pub z: f32,
    /// Simplex (2D) instead of Perlin (3D).
    pub simplex: bool,
    /// 16-bit values packed in red (high byte) and green (low byte), for reading back; grey
    /// otherwise.
    pub packed: bool,
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct NoiseUniform {
    perm: [u32; 256],
    area: [f32; 4],
    params: [f32; 4],
}

struct GpuTexture {
    texture: wgpu::Texture,
    group: wgpu::BindGroup,
    size: (u32, u32),
    /// Holds sRGB bytes in a plain format (shader output): the quad shader decodes them.
    encoded_srgb: bool,
}

/// A buffer that grows (to the next power of two) only when it must.
struct Growable {
    buffer: wgpu::Buffer,
    usage: wgpu::BufferUsages,
}

impl Growable {
    fn new(device: &wgpu::Device, usage: wgpu::BufferUsages, size: u64) -> Self {
        let usage = usage | wgpu::BufferUsages::COPY_DST;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("textured"),
            size,
            usage,
            mapped_at_creation: false,
        });
        Self { buffer, usage }
    }
    /// Returns true when the buffer was replaced.
    fn write(&mut self, gpu: &Gpu, bytes: &[u8]) -> bool {
        let grew = bytes.len() as u64 > self.buffer.size();
        if grew {
            *self = Self::new(
                &gpu.device,
                self.usage,
                (bytes.len() as u64).next_power_of_two(),
            );
        }
        if !bytes.is_empty() {
            gpu.queue.write_buffer(&self.buffer, 0, bytes);
        }
        grew
    }
}

/// The textured part of a [`Renderer`]: pipelines, the textures, per-frame buffers.
pub(super) struct Textured {
    quad_pipeline: wgpu::RenderPipeline,
    sprite_pipeline: wgpu::RenderPipeline,
    noise_pipeline: wgpu::RenderPipeline,
    globals_group: wgpu::BindGroup,
    quad_layout: wgpu::BindGroupLayout,
    texture_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    quads: Growable,
    quad_group: wgpu::BindGroup,
    sprites: Growable,
    noise_uniform: wgpu::Buffer,
    noise_group: wgpu::BindGroup,
    textures: Vec<GpuTexture>,
    scratch: Vec<u8>,
}

fn uniform_entry(
    binding: u32,
    dynamic: bool,
    size: u64,
    visibility: wgpu::ShaderStages,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: dynamic,
            min_binding_size: wgpu::BufferSize::new(size),
        },
        count: None,
    }
}

/// The textured pipelines, their layouts and the sampler: made once per page and format (see
/// `Gpu::cached`).
#[derive(Clone)]
struct TexturedPipelines {
    globals_layout: wgpu::BindGroupLayout,
    quad_layout: wgpu::BindGroupLayout,
    texture_layout: wgpu::BindGroupLayout,
    noise_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    quad: wgpu::RenderPipeline,
    sprite: wgpu::RenderPipeline,
    noise: wgpu::RenderPipeline,
}

impl TexturedPipelines {
    fn new(device: &wgpu::Device, format: wgpu::TextureFormat, globals_size: u64) -> Self {
        let vf = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("textured globals"),
            entries: &[uniform_entry(0, false, globals_size, vf)],
        });
        let quad_size = std::mem::size_of::<QuadUniform>() as u64;
        let quad_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("quad"),
            entries: &[uniform_entry(0, true, quad_size, vf)],
        });
        let texture_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("texture"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: true },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let noise_size = std::mem::size_of::<NoiseUniform>() as u64;
        let noise_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("noise"),
            entries: &[uniform_entry(
                0,
                false,
                noise_size,
                wgpu::ShaderStages::FRAGMENT,
            )],
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("texture"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let shader = |label: &str, source: &str, common: bool| {
            let text = if common {
                format!("{}\n{}", super::shader_source!("common.wgsl"), source)
            } else {
                source.to_string()
            };
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(label),
                source: wgpu::ShaderSource::Wgsl(text.into()),
            })
        };
        let quad_shader = shader("quad", super::shader_source!("quad.wgsl"), true);
        let sprite_shader = shader("sprite", super::shader_source!("sprite.wgsl"), true);
        let noise_shader = shader("noise", super::shader_source!("noise.wgsl"), false);
        let layout = |layouts: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: None,
                bind_group_layouts: layouts,
                immediate_size: 0,
            })
        };
        let sprite_attributes = wgpu::vertex_attr_array![
            0 => Float32x3, 1 => Float32, 2 => Float32x4, 3 => Float32x4
        ];
        // Sprites write depth too, as the point sprites do: that is why unsorted transparent
        // sprites hide the ones behind them (lesson 11).
        let scene_pipeline =
            |label: &str,
             layout: &wgpu::PipelineLayout,
             module: &wgpu::ShaderModule,
             buffers: &[Option<wgpu::VertexBufferLayout>]| {
                super::renderer::scene_pipeline(
                    device,
                    format,
                    label,
                    layout,
                    module,
                    buffers,
                    wgpu::PrimitiveState::default(),
                )
            };
        let quad_pipeline = scene_pipeline(
            "quad",
            &layout(&[
                Some(&globals_layout),
                Some(&quad_layout),
                Some(&texture_layout),
            ]),
            &quad_shader,
            &[],
        );
        let sprite_pipeline = scene_pipeline(
            "sprite",
            &layout(&[Some(&globals_layout), Some(&texture_layout)]),
            &sprite_shader,
            &[Some(wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<SpriteInstance>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &sprite_attributes,
            })],
        );
        let noise_pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("noise"),
            layout: Some(&layout(&[Some(&noise_layout)])),
            vertex: wgpu::VertexState {
                module: &noise_shader,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &noise_shader,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: wgpu::TextureFormat::Rgba8Unorm,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        Self {
            globals_layout,
            quad_layout,
            texture_layout,
            noise_layout,
            sampler,
            quad: quad_pipeline,
            sprite: sprite_pipeline,
            noise: noise_pipeline,
        }
    }
}

impl Textured {
    /// `globals` is the renderer's camera buffer (bind group 0 of every pipeline); `globals_size`
    /// its size.
    pub(super) fn new(gpu: &Gpu, globals: &wgpu::Buffer, globals_size: u64) -> Self {
        let device = &gpu.device;
        let format = gpu.config.format;
        let TexturedPipelines {
            globals_layout,
            quad_layout,
            texture_layout,
            noise_layout,
            sampler,
            quad: quad_pipeline,
            sprite: sprite_pipeline,
            noise: noise_pipeline,
        } = gpu.cached(|| TexturedPipelines::new(device, format, globals_size));
        let globals_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("textured globals"),
            layout: &globals_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals.as_entire_binding(),
            }],
        });
        let quads = Growable::new(device, wgpu::BufferUsages::UNIFORM, QUAD_STRIDE * 16);
        let quad_group = Self::quad_group(device, &quad_layout, &quads.buffer);
        let noise_uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("noise"),
            size: std::mem::size_of::<NoiseUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let noise_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("noise"),
            layout: &noise_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: noise_uniform.as_entire_binding(),
            }],
        });
        Self {
            quad_pipeline,
            sprite_pipeline,
            noise_pipeline,
            globals_group,
            quad_layout,
            texture_layout,
            sampler,
            quads,
            quad_group,
            sprites: Growable::new(device, wgpu::BufferUsages::VERTEX, 1 << 12),
            noise_uniform,
            noise_group,
            textures: Vec::new(),
            scratch: Vec::new(),
        }
    }

    fn quad_group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        buffer: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("quads"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<QuadUniform>() as u64),
                }),
            }],
        })
    }

    fn make_texture(
        &self,
        gpu: &Gpu,
        size: (u32, u32),
        format: wgpu::TextureFormat,
        usage: wgpu::TextureUsages,
        encoded_srgb: bool,
    ) -> GpuTexture {
        let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("image"),
            size: wgpu::Extent3d {
                width: size.0,
                height: size.1,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: usage | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let view = texture.create_view(&Default::default());
        let group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("image"),
            layout: &self.texture_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&self.sampler),
                },
            ],
        });
        GpuTexture {
            texture,
            group,
            size,
            encoded_srgb,
        }
    }

    fn texture(&self, id: TextureId) -> Result<&GpuTexture, String> {
        self.textures
            .get(id.0)
            .ok_or_else(|| format!("unknown texture {}", id.0))
    }

    /// Uploads this frame's quads and sprites (before the render pass).
    pub(super) fn prepare(&mut self, gpu: &Gpu, frame: &Frame) {
        self.scratch.clear();
        for q in &frame.quads {
            let encoded = self
                .textures
                .get(q.texture.0)
                .is_some_and(|t| t.encoded_srgb);
            let u = QuadUniform {
                model: q.model.to_cols_array(),
                tint: q.tint.to_array(),
                uv: q.uv.to_array(),
                flags: [if encoded { 1.0 } else { 0.0 }, 0.0, 0.0, 0.0],
            };
            self.scratch.extend_from_slice(bytemuck::bytes_of(&u));
            self.scratch
                .resize(self.scratch.len().next_multiple_of(QUAD_STRIDE as usize), 0);
        }
        if self.quads.write(gpu, &self.scratch) {
            self.quad_group = Self::quad_group(&gpu.device, &self.quad_layout, &self.quads.buffer);
        }
        self.sprites
            .write(gpu, bytemuck::cast_slice(&frame.sprites));
    }

    /// Draws this frame's textured quads. They are opaque images (noise pictures, the sprite
    /// atlas on a board) and write depth, so the renderer draws them with the other opaque
    /// geometry, before the wide lines and markers that lie on them and only test depth.
    /// Unknown texture ids are skipped.
    pub(super) fn draw_quads<'a>(&'a self, pass: &mut wgpu::RenderPass<'a>, frame: &Frame) {
        if frame.quads.is_empty() {
            return;
        }
        pass.set_pipeline(&self.quad_pipeline);
        pass.set_bind_group(0, &self.globals_group, &[]);
        for (i, q) in frame.quads.iter().enumerate() {
            let Some(t) = self.textures.get(q.texture.0) else {
                continue;
            };
            pass.set_bind_group(1, &self.quad_group, &[(i as u64 * QUAD_STRIDE) as u32]);
            pass.set_bind_group(2, &t.group, &[]);
            pass.draw(0..6, 0..1);
        }
    }

    /// Draws this frame's sprites, then the sprites compute shaders wrote (`gpu_sprites`:
    /// buffers and counts, with the frame's atlas). They come last: they blend over everything.
    pub(super) fn draw_sprites<'a>(
        &'a self,
        pass: &mut wgpu::RenderPass<'a>,
        frame: &Frame,
        gpu_sprites: &'a [(wgpu::Buffer, u32)],
    ) {
        let atlas = frame.sprite_texture.and_then(|id| self.textures.get(id.0));
        let Some(t) = atlas else { return };
        if frame.sprites.is_empty() && gpu_sprites.is_empty() {
            return;
        }
        // One pipeline and atlas binding for both: the frame's sprites, then the GPU's.
        pass.set_pipeline(&self.sprite_pipeline);
        pass.set_bind_group(0, &self.globals_group, &[]);
        pass.set_bind_group(1, &t.group, &[]);
        let frame_sprites = (!frame.sprites.is_empty())
            .then_some((&self.sprites.buffer, frame.sprites.len() as u32));
        let gpu = gpu_sprites.iter().map(|(buffer, count)| (buffer, *count));
        for (buffer, count) in frame_sprites.into_iter().chain(gpu) {
            pass.set_vertex_buffer(0, buffer.slice(..));
            pass.draw(0..6, 0..count);
        }
    }
}

fn write_rgba(gpu: &Gpu, texture: &wgpu::Texture, width: u32, height: u32, rgba: &[u8]) {
    gpu.queue.write_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        rgba,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(4 * width),
            rows_per_image: Some(height),
        },
        wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
    );
}

impl Renderer {
    /// Uploads a `width × height` RGBA8 image (sRGB bytes, rows from the top; see
    /// [`validate_rgba`]) and returns its id for the draw list.
    pub fn create_texture(
        &mut self,
        gpu: &Gpu,
        width: u32,
        height: u32,
        rgba: &[u8],
    ) -> Result<TextureId, String> {
        self.revision += 1;
        validate_rgba(width, height, rgba)?;
        let t = self.textured.make_texture(
            gpu,
            (width, height),
            wgpu::TextureFormat::Rgba8UnormSrgb,
            wgpu::TextureUsages::COPY_DST,
            false,
        );
        write_rgba(gpu, &t.texture, width, height, rgba);
        self.textured.textures.push(t);
        Ok(TextureId(self.textured.textures.len() - 1))
    }

    /// Replaces texture `id`'s image. The same size rewrites the GPU texture in place (no
    /// allocation); another size replaces it (the id stays valid).
    pub fn update_texture(
        &mut self,
        gpu: &Gpu,
        id: TextureId,
        width: u32,
        height: u32,
        rgba: &[u8],
    ) -> Result<(), String> {
        self.revision += 1;
        validate_rgba(width, height, rgba)?;
        let t = self.textured.texture(id)?;
        if t.encoded_srgb {
            return Err(format!(
                "texture {} is a shader's target, not an uploaded image",
                id.0
            ));
        }
        if t.size != (width, height) {
            let fresh = self.textured.make_texture(
                gpu,
                (width, height),
                wgpu::TextureFormat::Rgba8UnormSrgb,
                wgpu::TextureUsages::COPY_DST,
                false,
            );
            self.textured.textures[id.0] = fresh;
        }
        write_rgba(
            gpu,
            &self.textured.textures[id.0].texture,
            width,
            height,
            rgba,
        );
        Ok(())
    }

    /// Creates a `width × height` texture that [`Renderer::render_noise`] draws into.
    pub fn create_noise_texture(
        &mut self,
        gpu: &Gpu,
        width: u32,
        height: u32,
    ) -> Result<TextureId, String> {
        self.revision += 1;
        validate_rgba(width, height, &vec![0; 4 * (width * height) as usize])?;
        let t = self.textured.make_texture(
            gpu,
            (width, height),
            wgpu::TextureFormat::Rgba8Unorm,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            true,
        );
        self.textured.textures.push(t);
        Ok(TextureId(self.textured.textures.len() - 1))
    }

    /// Computes a noise image on the GPU into texture `id` (from
    /// [`Renderer::create_noise_texture`]), with permutation `table`.
    pub fn render_noise(
        &mut self,
        gpu: &Gpu,
        id: TextureId,
        table: &[u8],
        image: &NoiseImage,
    ) -> Result<(), String> {
        self.revision += 1;
        if table.len() != 256 {
            return Err(format!(
                "a permutation has 256 entries, got {}",
                table.len()
            ));
        }
        let t = self.textured.texture(id)?;
        if !t.encoded_srgb {
            return Err(format!(
                "texture {} is an uploaded image, not a shader's target",
                id.0
            ));
        }
        let mut uniform = NoiseUniform {
            perm: [0; 256],
            area: [
                image.origin[0],
                image.origin[1],
                image.step[0],
                image.step[1],
            ],
            params: [
                image.z,
                if image.packed { 1.0 } else { 0.0 },
                if image.simplex { 1.0 } else { 0.0 },
                0.0,
            ],
        };
        for (dst, &src) in uniform.perm.iter_mut().zip(table) {
            *dst = src as u32;
        }
        gpu.queue.write_buffer(
            &self.textured.noise_uniform,
            0,
            bytemuck::bytes_of(&uniform),
        );
        let view = t.texture.create_view(&Default::default());
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("noise"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(&self.textured.noise_pipeline);
            pass.set_bind_group(0, &self.textured.noise_group, &[]);
            pass.draw(0..3, 0..1);
        }
        gpu.queue.submit([encoder.finish()]);
        Ok(())
    }

    /// Starts reading a shader-written texture back; [`PendingRead::poll`] returns its RGBA
    /// bytes (rows from the top) once the GPU is done. Nothing waits: the page polls each frame.
    pub fn start_read_texture(&mut self, gpu: &Gpu, id: TextureId) -> Result<PendingRead, String> {
        let t = self.textured.texture(id)?;
        if !t.encoded_srgb {
            return Err(format!("texture {} cannot be read back", id.0));
        }
        let (width, height) = t.size;
        let padded_row = (width * 4).div_ceil(256) * 256;
        let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("texture readback"),
            size: (padded_row * height) as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &t.texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
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
        gpu.queue.submit([encoder.finish()]);
        let done = Rc::new(Cell::new(None));
        let signal = done.clone();
        buffer.map_async(wgpu::MapMode::Read, .., move |r| {
            signal.set(Some(r.map_err(|e| e.to_string())))
        });
        Ok(PendingRead {
            buffer,
            done,
            width,
            padded_row,
        })
    }
}

/// A texture on its way back from the GPU (see [`Renderer::start_read_texture`]).
pub struct PendingRead {
    buffer: wgpu::Buffer,
    done: Rc<Cell<Option<Result<(), String>>>>,
    width: u32,
    padded_row: u32,
}

impl PendingRead {
    /// The pixels once mapped (None while the GPU is still busy).
    pub fn poll(&self, gpu: &Gpu) -> Option<Result<Vec<u8>, String>> {
        // WebGPU completes the mapping from the browser's event loop, WebGL2 when polled.
        let _ = gpu.device.poll(wgpu::PollType::Poll);
        let result = self.done.take()?;
        Some(result.and_then(|()| {
            let mapped = self
                .buffer
                .get_mapped_range(..)
                .map_err(|e| e.to_string())?;
            let row = (self.width * 4) as usize;
            let mut pixels = Vec::with_capacity(mapped.len());
            for r in mapped.chunks(self.padded_row as usize) {
                pixels.extend_from_slice(&r[..row]);
            }
            drop(mapped);
            self.buffer.unmap();
            Ok(pixels)
        }))
    }
}
