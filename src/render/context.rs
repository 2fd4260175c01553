//! Surface, adapter and device for one HTML canvas.

use web_sys::HtmlCanvasElement;

/// Which graphics API to ask the browser for (`?backend=` in a lesson's URL).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BackendChoice {
    /// WebGPU when the browser offers an adapter, WebGL2 otherwise.
    Auto,
    /// Auto, where the page has already found that WebGPU offers no adapter (it probes once per
    /// page, so the browser's "No available adapters" notice appears once, not once per figure).
    AutoWithoutWebGpu,
    WebGpu,
    WebGl2,
}

impl BackendChoice {
    /// Parses `"auto"`, `"webgpu"` or `"webgl2"`.
    pub fn parse(name: &str) -> Result<Self, String> {
        match name {
            "" | "auto" => Ok(Self::Auto),
            "auto-no-webgpu" => Ok(Self::AutoWithoutWebGpu),
            "webgpu" => Ok(Self::WebGpu),
            "webgl2" | "webgl" => Ok(Self::WebGl2),
            other => Err(format!(
                "unknown backend '{other}': use auto, webgpu or webgl2"
            )),
        }
    }
}

/// The GPU objects of one canvas.
pub struct Gpu {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub surface: wgpu::Surface<'static>,
    pub config: wgpu::SurfaceConfiguration,
    /// "WebGPU" or "WebGL2", for the page to display.
    pub backend_name: &'static str,
    pub adapter_name: String,
    /// True when the surface format stores sRGB-encoded values without converting them,
    /// so the shaders must encode (see `common.wgsl`).
    pub encode_srgb_in_shader: bool,
    /// Compute shaders and storage buffers are on (WebGPU only; see `compute.rs`).
    pub compute: bool,
}

impl Gpu {
    /// Creates the context. The error says which backend was missing and what to try.
    pub async fn new(canvas: HtmlCanvasElement, choice: BackendChoice) -> Result<Self, String> {
        let width = canvas.width().max(1);
        let height = canvas.height().max(1);
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = match choice {
            BackendChoice::Auto => wgpu::Backends::BROWSER_WEBGPU | wgpu::Backends::GL,
            BackendChoice::WebGpu => wgpu::Backends::BROWSER_WEBGPU,
            BackendChoice::WebGl2 | BackendChoice::AutoWithoutWebGpu => wgpu::Backends::GL,
        };
        let instance = match choice {
            // Drops WebGPU when `navigator.gpu` exists but offers no adapter.
            BackendChoice::Auto => wgpu::util::new_instance_with_webgpu_detection(desc).await,
            _ => wgpu::Instance::new(desc),
        };
        let missing = match choice {
            BackendChoice::Auto | BackendChoice::AutoWithoutWebGpu => {
                "Neither WebGPU nor WebGL2 is available in this browser"
            }
            BackendChoice::WebGpu => "WebGPU was requested (?backend=webgpu) but this browser offers no WebGPU adapter",
            BackendChoice::WebGl2 => "WebGL2 was requested (?backend=webgl2) but this browser cannot create a WebGL2 context",
        };
        let surface = instance
            .create_surface(wgpu::SurfaceTarget::Canvas(canvas))
            .map_err(|e| format!("{missing} ({e})."))?;
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: false,
                compatible_surface: Some(&surface),
                apply_limit_buckets: false,
            })
            .await
            .map_err(|e| format!("{missing} ({e})."))?;
        let info = adapter.get_info();
        let backend_name = match info.backend {
            wgpu::Backend::Gl => "WebGL2",
            _ => "WebGPU",
        };
        // WebGL2's limits, raised to what the adapter allows for texture sizes only: a lesson that
        // runs here runs on both backends.
        let mut required_limits =
            wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits());
        // On WebGPU, add compute shaders and storage buffers (the GPU particles and boids of
        // `compute.rs`), with WebGPU's guaranteed limits; everything else stays WebGL2's.
        let compute = info.backend != wgpu::Backend::Gl;
        if compute {
            super::compute::add_compute_limits(&mut required_limits);
        }
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("inbetween device"),
                required_features: wgpu::Features::empty(),
                required_limits,
                ..Default::default()
            })
            .await
            .map_err(|e| format!("The {backend_name} adapter refused to create a device: {e}"))?;
        let mut config = surface
            .get_default_config(&adapter, width, height)
            .ok_or_else(|| {
                format!("The {backend_name} surface is not supported by its adapter.")
            })?;
        // Prefer a plain 8-bit format on both backends, so pixels agree; encode sRGB ourselves.
        let formats = surface.get_capabilities(&adapter).formats;
        let plain = formats.iter().copied().find(|f| {
            matches!(
                f,
                wgpu::TextureFormat::Rgba8Unorm | wgpu::TextureFormat::Bgra8Unorm
            )
        });
        config.format = plain.unwrap_or(config.format);
        let encode_srgb_in_shader = !config.format.is_srgb();
        config.usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
        config.alpha_mode = wgpu::CompositeAlphaMode::Auto;
        config.view_formats = vec![];
        surface.configure(&device, &config);
        Ok(Self {
            device,
            queue,
            surface,
            config,
            backend_name,
            adapter_name: info.name,
            encode_srgb_in_shader,
            compute,
        })
    }

    /// Resizes the surface to `width × height` physical pixels (at least 1 × 1, at most the
    /// device's texture limit).
    pub fn resize(&mut self, width: u32, height: u32) {
        let max = self.device.limits().max_texture_dimension_2d;
        let (width, height) = (width.clamp(1, max), height.clamp(1, max));
        if (width, height) != (self.config.width, self.config.height) {
            self.config.width = width;
            self.config.height = height;
            self.surface.configure(&self.device, &self.config);
        }
    }
}
