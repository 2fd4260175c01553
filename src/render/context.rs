//! The page's adapter and device, shared by every figure, and each canvas's surface on it.
//!
//! WebGPU draws each figure into its own canvas (one canvas context each, on the one device).
//! WebGL2 cannot: a WebGL2 context draws into its own canvas only. There the device is the context
//! of one hidden canvas, which takes each figure's size in turn and draws its frame, and each
//! figure's canvas has a `'2d'` context into which that frame is copied.

use std::any::{Any, TypeId};
use std::cell::{Cell, RefCell};
use std::rc::Rc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

#[wasm_bindgen]
extern "C" {
    /// `__inbetweenGpuError(message)`: the lesson shell shows it in the error banner (absent on
    /// other pages: the call then fails, and the console has the message).
    #[wasm_bindgen(catch, js_name = __inbetweenGpuError)]
    fn report_gpu_error(message: &str) -> Result<JsValue, JsValue>;
}

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

/// The page's GPU: one instance, adapter, device and queue shared by every figure of the page
/// (Chromium keeps at most 16 WebGL contexts a page, and each device costs start-up time and
/// memory), and the pipelines compiled for it (see [`Gpu::cached`]).
struct PageGpu {
    /// Set when the browser reports the WebGPU device lost.
    device_lost: Arc<AtomicBool>,
    instance: wgpu::Instance,
    device: wgpu::Device,
    queue: wgpu::Queue,
    /// The surface settings every canvas starts from (format, usage, alpha).
    config: wgpu::SurfaceConfiguration,
    backend_name: &'static str,
    adapter_name: String,
    encode_srgb_in_shader: bool,
    compute: bool,
    /// WebGL2: the hidden canvas whose context draws every figure (a WebGL2 context draws into
    /// its own canvas only), its surface, the size that surface is configured at, and its
    /// context (asked whether it is lost).
    gl: Option<(
        HtmlCanvasElement,
        wgpu::Surface<'static>,
        Cell<(u32, u32)>,
        GlContext,
    )>,
    /// Pipelines and layouts, one entry per type (see [`Gpu::cached`]).
    cache: RefCell<Vec<(TypeId, wgpu::TextureFormat, Rc<dyn Any>)>>,
    /// Multisampled colour and depth targets by size and format, most recently used last (see
    /// [`Gpu::shared_targets`]).
    targets: RefCell<Vec<SharedTargets>>,
}

/// A size, a colour format, and the multisampled colour and depth views of that size.
type SharedTargets = ((u32, u32), wgpu::TextureFormat, [wgpu::TextureView; 2]);

/// The most target sets a page keeps for figures to share (a figure keeps the set it uses).
const MAX_SHARED_TARGETS: usize = 4;

/// The page's GPU for a backend choice: being created (`None`) or ready.
type PageSlot = (BackendChoice, Option<Rc<PageGpu>>);

thread_local! {
    static PAGE_GPUS: RefCell<Vec<PageSlot>> = const { RefCell::new(Vec::new()) };
}

#[wasm_bindgen]
extern "C" {
    /// A figure's canvas's `'2d'` context (WebGL2: the page's canvas is copied into it).
    type Context2d;
    /// Copies the top-left `width × height` of `image` to the top-left of the context's canvas
    /// (the whole of `image`, which has that size).
    #[wasm_bindgen(method, catch, js_name = drawImage)]
    #[allow(clippy::too_many_arguments)]
    fn draw_image(
        this: &Context2d,
        image: &HtmlCanvasElement,
        sx: f64,
        sy: f64,
        width: f64,
        height: f64,
        dx: f64,
        dy: f64,
        dw: f64,
        dh: f64,
    ) -> Result<(), JsValue>;

    /// The hidden canvas's WebGL2 context.
    type GlContext;
    #[wasm_bindgen(method, js_name = isContextLost)]
    fn is_context_lost(this: &GlContext) -> bool;
}

/// Where a figure's frames go.
enum Target {
    /// WebGPU: the canvas's own surface on the page's device.
    Surface(wgpu::Surface<'static>),
    /// WebGL2: the canvas and its `'2d'` context, into which the page's canvas is copied.
    Copy(HtmlCanvasElement, Context2d),
}

/// The GPU objects of one canvas: the page's device and queue, and the canvas's surface.
pub struct Gpu {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    /// The canvas's surface settings; `width` and `height` are its drawing buffer's size.
    pub config: wgpu::SurfaceConfiguration,
    /// "WebGPU" or "WebGL2", for the page to display.
    pub backend_name: &'static str,
    pub adapter_name: String,
    /// True when the surface format stores sRGB-encoded values without converting them,
    /// so the shaders must encode (see `common.wgsl`).
    pub encode_srgb_in_shader: bool,
    /// Compute shaders and storage buffers are on (WebGPU only; see `compute.rs`).
    pub compute: bool,
    target: Target,
    page: Rc<PageGpu>,
}

impl PageGpu {
    /// The page's GPU for `choice`, made by the first canvas that asks; a canvas that asks while
    /// it is being made waits for it. A failure is not kept: the next canvas tries again. A lost
    /// one is dropped (with its pipelines and shared targets) and made again.
    async fn get(choice: BackendChoice) -> Result<Rc<Self>, String> {
        loop {
            let slot = PAGE_GPUS.with_borrow_mut(|slots| {
                slots.retain(|(_, page)| !page.as_ref().is_some_and(|p| p.lost()));
                match slots.iter().find(|(c, _)| *c == choice) {
                    Some((_, page)) => Some(page.clone()),
                    None => {
                        slots.push((choice, None));
                        None
                    }
                }
            });
            match slot {
                Some(Some(page)) => return Ok(page),
                Some(None) => super::renderer::sleep_ms(2).await,
                None => break,
            }
        }
        let made = Self::new(choice).await.map(Rc::new);
        PAGE_GPUS.with_borrow_mut(|slots| {
            slots.retain(|(c, _)| *c != choice);
            if let Ok(page) = &made {
                slots.push((choice, Some(page.clone())));
            }
        });
        made
    }

    /// Creates the instance, adapter and device on a hidden canvas (WebGL2 needs a canvas's
    /// context to find an adapter; on WebGL2 that canvas draws every figure). The error says
    /// which backend was missing and what to try.
    async fn new(choice: BackendChoice) -> Result<Self, String> {
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
        let canvas: HtmlCanvasElement = web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.create_element("canvas").ok())
            .and_then(|c| c.dyn_into().ok())
            .ok_or("no document to create a canvas in")?;
        // The reader gets the sentence; wgpu's own error (a Rust debug print) goes to the console
        // for whoever debugs the browser.
        let unavailable = |e: &dyn std::fmt::Display| {
            web_sys::console::warn_1(&format!("inbetween: {missing}: {e}").into());
            missing.to_string()
        };
        let surface = create_surface(&instance, canvas.clone()).map_err(|e| unavailable(&e))?;
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: false,
                compatible_surface: Some(&surface),
                apply_limit_buckets: false,
            })
            .await
            .map_err(|e| unavailable(&e))?;
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
        let mut config = surface.get_default_config(&adapter, 1, 1).ok_or_else(|| {
            format!("The {backend_name} surface is not supported by its adapter")
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
        config.usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
        config.alpha_mode = wgpu::CompositeAlphaMode::Auto;
        config.view_formats = vec![];
        let gl = match info.backend {
            wgpu::Backend::Gl => {
                configure(&surface, &device, &config);
                // The context wgpu made on the canvas: asking again returns it.
                let context = canvas.get_context("webgl2").ok().flatten();
                let context = context.ok_or("the WebGL2 canvas lost its context")?;
                Some((canvas, surface, Cell::new((1, 1)), context.unchecked_into()))
            }
            _ => None,
        };
        let device_lost = Arc::new(AtomicBool::new(false));
        let flag = device_lost.clone();
        device.set_device_lost_callback(move |_, _| flag.store(true, Ordering::Relaxed));
        // A validation error no call caught (an invalid pipeline or bind group: a bug here) goes
        // to the console as an error, where the page tests look, instead of the browser's
        // warning, which they would not see, while the figure silently draws or computes nothing.
        // The lesson shell's `__inbetweenGpuError` shows it in the page's error banner too.
        device.on_uncaptured_error(Arc::new(|e: wgpu::Error| {
            let message = format!("GPU error (a bug in inbetween): {e}");
            web_sys::console::error_1(&message.as_str().into());
            let _ = report_gpu_error(&message);
        }));
        Ok(Self {
            device_lost,
            instance,
            device,
            queue,
            encode_srgb_in_shader: !config.format.is_srgb(),
            config,
            backend_name,
            adapter_name: info.name,
            compute,
            gl,
            cache: RefCell::new(Vec::new()),
            targets: RefCell::new(Vec::new()),
        })
    }

    /// Whether the browser took the device (WebGPU) or the hidden canvas's context (WebGL2)
    /// away: a GPU process that crashed or was reset, a driver update, `device.destroy()`,
    /// `WEBGL_lose_context`. Nothing drawn with it shows any more.
    fn lost(&self) -> bool {
        match &self.gl {
            Some((.., context)) => context.is_context_lost(),
            None => self.device_lost.load(Ordering::Relaxed),
        }
    }
}

impl Gpu {
    /// The GPU objects of `canvas` on the page's device (made by the first canvas). The error
    /// says which backend was missing and what to try.
    pub async fn new(canvas: HtmlCanvasElement, choice: BackendChoice) -> Result<Self, String> {
        let page = PageGpu::get(choice).await?;
        let mut config = page.config.clone();
        config.width = canvas.width().max(1);
        config.height = canvas.height().max(1);
        let target = if page.gl.is_some() {
            let context = canvas
                .get_context("2d")
                .ok()
                .flatten()
                .ok_or("the figure's canvas has no 2d context (it has another kind already)")?;
            canvas.set_width(config.width);
            canvas.set_height(config.height);
            Target::Copy(canvas, context.unchecked_into())
        } else {
            let surface = create_surface(&page.instance, canvas)
                .map_err(|e| format!("The {} canvas: {e}.", page.backend_name))?;
            configure(&surface, &page.device, &config);
            Target::Surface(surface)
        };
        Ok(Self {
            device: page.device.clone(),
            queue: page.queue.clone(),
            config,
            backend_name: page.backend_name,
            adapter_name: page.adapter_name.clone(),
            encode_srgb_in_shader: page.encode_srgb_in_shader,
            compute: page.compute,
            target,
            page,
        })
    }

    /// Whether the page's device or WebGL2 context was lost: frames are then skipped and resizes
    /// ignored, and a new `Gpu` on the same canvas ([`Gpu::new`]) gets a new device.
    pub fn lost(&self) -> bool {
        self.page.lost()
    }

    /// Resizes the surface to `width × height` physical pixels (at least 1 × 1, at most the
    /// device's texture limit).
    pub fn resize(&mut self, width: u32, height: u32) {
        let max = self.device.limits().max_texture_dimension_2d;
        let (width, height) = (width.clamp(1, max), height.clamp(1, max));
        // A lost WebGL2 context cannot make the surface's textures (wgpu would panic).
        if (width, height) != (self.config.width, self.config.height) && !self.lost() {
            self.config.width = width;
            self.config.height = height;
            match &self.target {
                Target::Surface(surface) => configure(surface, &self.device, &self.config),
                Target::Copy(canvas, _) => {
                    canvas.set_width(width);
                    canvas.set_height(height);
                }
            }
        }
    }

    /// The texture to draw the canvas's next frame into, `None` for a skipped frame. On WebGL2
    /// it is the page canvas's, resized to this figure's size when the last frame drawn there
    /// had another size. Everything a frame costs there grows with the page canvas's whole area,
    /// not the figure's: the multisampled pass clears and resolves all of it, the present blits
    /// all of it, and the copy into the figure's canvas reads all of it back (`drawImage` of a
    /// 400 x 250 corner took 13 ms from a 1600 x 1000 canvas on SwiftShader, 1.4 ms from a
    /// 400 x 250 one). A resize costs about 1.5 ms there, and only when figures of different
    /// sizes draw one after another.
    pub(super) fn next_frame(&self) -> Option<wgpu::SurfaceTexture> {
        if self.lost() {
            return None;
        }
        let config = &self.config;
        let surface = match &self.target {
            Target::Surface(surface) => surface,
            Target::Copy(..) => {
                let (_, surface, size, _) = self.page.gl.as_ref()?;
                if size.get() != (config.width, config.height) {
                    configure(surface, &self.device, config);
                    size.set((config.width, config.height));
                }
                surface
            }
        };
        match surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f)
            | wgpu::CurrentSurfaceTexture::Suboptimal(f) => Some(f),
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                configure(surface, &self.device, config);
                None
            }
            // Timeout, occluded: draw the next one.
            _ => None,
        }
    }

    /// Shows `frame` (drawn and submitted) in the canvas: on WebGL2, copies the page's canvas
    /// into this one in the same task, before the browser clears the page's canvas.
    pub(super) fn show(&self, frame: wgpu::SurfaceTexture) -> Result<(), String> {
        self.queue.present(frame);
        let (w, h) = (self.config.width as f64, self.config.height as f64);
        match (&self.target, &self.page.gl) {
            (Target::Copy(_, context), Some((page_canvas, ..))) => context
                .draw_image(page_canvas, 0.0, 0.0, w, h, 0.0, 0.0, w, h)
                .map_err(|_| "copying the frame into the figure's canvas failed".to_string()),
            _ => Ok(()),
        }
    }

    /// The page's multisampled colour and depth targets of `size` and `format`, made by `make`
    /// when the page has none: every pass clears them first and discards them after resolving,
    /// so figures of the same size drawn one after another can share them.
    pub(super) fn shared_targets(
        &self,
        size: (u32, u32),
        format: wgpu::TextureFormat,
        make: impl FnOnce() -> [wgpu::TextureView; 2],
    ) -> [wgpu::TextureView; 2] {
        let mut list = self.page.targets.borrow_mut();
        if let Some(i) = list.iter().position(|(s, f, _)| (*s, *f) == (size, format)) {
            let entry = list.remove(i);
            let views = entry.2.clone();
            list.push(entry);
            return views;
        }
        let views = make();
        list.push((size, format, views.clone()));
        if list.len() > MAX_SHARED_TARGETS {
            list.remove(0);
        }
        views
    }

    /// The page's one `T` (pipelines and their layouts) for this canvas's format, made by
    /// `make` the first time: the second figure of a page compiles no shader.
    pub(super) fn cached<T: Clone + 'static>(&self, make: impl FnOnce() -> T) -> T {
        let key = (TypeId::of::<T>(), self.config.format);
        let found = self
            .page
            .cache
            .borrow()
            .iter()
            .find_map(|(t, f, v)| ((*t, *f) == key).then(|| v.downcast_ref::<T>().cloned()));
        if let Some(Some(value)) = found {
            return value;
        }
        let value = make();
        let boxed: Rc<dyn Any> = Rc::new(value.clone());
        self.page.cache.borrow_mut().push((key.0, key.1, boxed));
        value
    }
}

// `create_surface` and `configure`, each called from one place: the crate is optimised for speed,
// and each call site would otherwise get its own inlined copy of wgpu's code for both backends.
#[inline(never)]
fn create_surface(
    instance: &wgpu::Instance,
    canvas: HtmlCanvasElement,
) -> Result<wgpu::Surface<'static>, wgpu::CreateSurfaceError> {
    instance.create_surface(wgpu::SurfaceTarget::Canvas(canvas))
}

#[inline(never)]
fn configure(surface: &wgpu::Surface, device: &wgpu::Device, config: &wgpu::SurfaceConfiguration) {
    surface.configure(device, config);
}
