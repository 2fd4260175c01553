//! One live figure: a canvas with its GPU context, renderer and orbit camera.

use crate::camera::OrbitCamera;
use crate::render::{BackendChoice, Gpu, Renderer};
use wasm_bindgen::prelude::*;

/// A 3D figure. JavaScript owns the frame loop and the pointer events; a lesson scene fills
/// `renderer.frame` and calls [`Viewer::present`].
#[wasm_bindgen]
pub struct Viewer {
    pub(crate) gpu: Gpu,
    pub(crate) renderer: Renderer,
    pub(crate) camera: OrbitCamera,
    /// The canvas's size in CSS pixels (labels are placed in these units).
    pub(crate) css_size: (f32, f32),
    /// The last frame's labels, projected, for the page's HTML overlay.
    labels: Vec<crate::draw::ScreenLabel>,
    /// [`crate::draw::Frame::fingerprint`] of the last presented frame.
    last_fingerprint: u64,
    /// Whether the canvas is on screen (the page tells, from an `IntersectionObserver`). Off
    /// screen, [`Viewer::present`] keeps the frame instead of rendering it: a page with ten
    /// figures then renders the one or two the reader sees, not all ten, every frame.
    visible: bool,
    /// The last frame presented while off screen, drawn when the canvas comes back.
    hidden: crate::draw::Frame,
    /// Whether `hidden` holds a frame not drawn yet.
    pending: bool,
    /// The last frame had an inset: its title is the last of `labels`.
    inset_title: bool,
    /// Whether the camera fits the frame's declared points ([`crate::draw::Frame::keep_in_view`])
    /// at every present: on until the reader zooms or pans (orbiting keeps it), back on with
    /// [`Viewer::frame_all`].
    fitting: bool,
    /// Whether the last presented frame declared points to keep in view.
    declares_view: bool,
    /// Whether the last presented frame was flat: a drag pans it.
    flat: bool,
    /// The camera the figure placed with `setCamera` (or the default): "frame all" returns to it
    /// when the figure declares nothing to keep in view.
    home: OrbitCamera,
    /// How many times the figure took new GPU objects ([`Viewer::adopt`]): a scene that keeps
    /// meshes or textures on the GPU uploads them again when it changes (see [`Viewer::renewed`]).
    generation: u32,
}

#[wasm_bindgen]
impl Viewer {
    /// Creates the figure's context on `canvas`. `backend` is "auto", "webgpu" or "webgl2".
    /// Rejects with a readable message when the browser offers neither API.
    pub async fn create(canvas: JsValue, backend: JsValue) -> Result<Viewer, JsError> {
        let canvas = super::canvas("canvas", canvas)?;
        let backend: &str = &super::string("backend", &backend)?;
        let choice = BackendChoice::parse(&backend).map_err(|e| JsError::new(&e))?;
        let gpu = Gpu::new(canvas, choice)
            .await
            .map_err(|e| JsError::new(&e))?;
        let renderer = Renderer::new(&gpu);
        Ok(Viewer {
            gpu,
            renderer,
            camera: OrbitCamera::default(),
            css_size: (1.0, 1.0),
            labels: Vec::new(),
            last_fingerprint: 0,
            visible: true,
            hidden: crate::draw::Frame::default(),
            pending: false,
            inset_title: false,
            fitting: true,
            declares_view: false,
            flat: false,
            home: OrbitCamera::default(),
            generation: 0,
        })
    }

    /// Whether the page's GPU was lost (a GPU reset, a driver update): the page then stops the
    /// figures' frames, makes a new `Viewer` on the figure's canvas (which gets a new device) and
    /// passes it to [`Viewer::adopt`].
    #[wasm_bindgen(getter)]
    pub fn lost(&self) -> bool {
        self.gpu.lost()
    }

    /// Takes the GPU objects of `fresh` (just made on this figure's canvas, after a loss),
    /// keeping this figure's camera, size and settings; the lost ones go with `fresh`. The scene
    /// uploads its meshes and textures again at its next draw (see [`Viewer::renewed`]).
    pub fn adopt(&mut self, mut fresh: Viewer) {
        fresh.renderer.keep_settings_of(&self.renderer);
        std::mem::swap(&mut self.gpu, &mut fresh.gpu);
        std::mem::swap(&mut self.renderer, &mut fresh.renderer);
        // The kept frame names the lost renderer's meshes.
        self.pending = false;
        self.generation += 1;
    }

    /// "WebGPU" or "WebGL2".
    #[wasm_bindgen(getter)]
    pub fn backend(&self) -> String {
        self.gpu.backend_name.to_string()
    }

    #[wasm_bindgen(getter, js_name = adapterName)]
    pub fn adapter_name(&self) -> String {
        self.gpu.adapter_name.clone()
    }

    /// Matches the drawing buffer to the canvas's CSS size times `device_pixel_ratio`.
    pub fn resize(
        &mut self,
        css_width: f32,
        css_height: f32,
        device_pixel_ratio: f32,
    ) -> Result<(), JsError> {
        let w = super::in_range("width", css_width, 0.0, 1e5)?;
        let h = super::in_range("height", css_height, 0.0, 1e5)?;
        let dpr = super::in_range("devicePixelRatio", device_pixel_ratio, 0.1, 8.0)?;
        self.gpu
            .resize((w * dpr).round() as u32, (h * dpr).round() as u32);
        // The page set the canvas's width and height, which clears it.
        self.renderer.canvas_cleared();
        self.renderer.px_per_css = dpr;
        self.css_size = (w.max(1.0), h.max(1.0));
        Ok(())
    }

    /// Rotates the camera by a pointer drag of `(dx, dy)` CSS pixels; pans it for a flat figure
    /// ([`crate::draw::Frame::flat`]).
    pub fn orbit(&mut self, dx_px: f32, dy_px: f32) -> Result<(), JsError> {
        let (dx, dy) = (super::finite("dx", dx_px)?, super::finite("dy", dy_px)?);
        if self.camera.drag(dx, dy, self.css_size.1, self.flat) {
            self.fitting = false;
        }
        Ok(())
    }

    /// Scales the camera distance: `factor < 1` zooms in.
    pub fn zoom(&mut self, factor: f32) -> Result<(), JsError> {
        self.camera
            .zoom(super::in_range("zoom factor", factor, 0.01, 100.0)?);
        self.fitting = false;
        Ok(())
    }

    /// Moves the camera target by a drag of `(dx, dy)` CSS pixels on a canvas `height_px` tall.
    pub fn pan(&mut self, dx_px: f32, dy_px: f32, height_px: f32) -> Result<(), JsError> {
        let h = super::in_range("height", height_px, 1.0, 1e5)?;
        let (dx, dy) = (super::finite("dx", dx_px)?, super::finite("dy", dy_px)?);
        self.camera.pan(dx / h, dy / h);
        self.fitting = false;
        Ok(())
    }

    /// Places the camera: target point, distance (metres), yaw and pitch (radians).
    #[wasm_bindgen(js_name = setCamera)]
    pub fn set_camera(
        &mut self,
        x: f32,
        y: f32,
        z: f32,
        distance: f32,
        yaw_rad: f32,
        pitch_rad: f32,
    ) -> Result<(), JsError> {
        for (name, v) in [
            ("x", x),
            ("y", y),
            ("z", z),
            ("yaw", yaw_rad),
            ("pitch", pitch_rad),
        ] {
            super::finite(name, v)?;
        }
        let distance = super::in_range("distance", distance, 0.01, 1e4)?;
        let placed = OrbitCamera::from_view([x, y, z, distance, yaw_rad, pitch_rad]);
        (self.camera.target, self.camera.distance) = (placed.target, placed.distance);
        (self.camera.yaw_rad, self.camera.pitch_rad) = (placed.yaw_rad, placed.pitch_rad);
        self.home = self.camera;
        Ok(())
    }

    /// Aims the camera at a new target from a new distance (metres), keeping the direction the
    /// reader orbited to: for a figure that reframes when what it shows grows.
    #[wasm_bindgen(js_name = setTarget)]
    pub fn set_target(&mut self, x: f32, y: f32, z: f32, distance: f32) -> Result<(), JsError> {
        for (name, v) in [("x", x), ("y", y), ("z", z)] {
            super::finite(name, v)?;
        }
        let distance = super::in_range("distance", distance, 0.01, 1e4)?;
        self.camera.target = glam::Vec3::new(x, y, z);
        self.camera.distance = distance;
        // The figure aims the camera itself from now on.
        self.fitting = false;
        Ok(())
    }

    /// Draws what the scene put in the frame, then clears it. The frame's labels are projected
    /// first and kept for [`Viewer::labels_json`].
    pub fn present(&mut self) -> Result<(), JsError> {
        let (w, h) = self.css_size;
        let frame = &self.renderer.frame;
        self.declares_view = !frame.keep_in_view.is_empty();
        self.flat = frame.flat;
        self.camera.limit_pitch(frame.max_pitch_rad);
        self.camera.limit_yaw(frame.max_yaw_rad);
        if self.fitting && self.declares_view {
            let points: Vec<glam::Vec3> = frame.fit_points();
            let size = glam::Vec2::new(w, h);
            let pad = crate::camera::FIT_PAD_PX;
            // With an inset, the figure fits beside it (left of or above its square), so the
            // inset hides nothing the figure declared.
            let fitted = frame.inset.as_ref().is_some_and(|inset| {
                crate::draw::inset::fit_beside(&mut self.camera, inset, &points, size, pad)
            });
            if !fitted {
                self.camera.fit(&points, size, pad);
            }
        } else if self.flat && self.declares_view {
            // A pan or zoom leaves the declared box in view.
            self.camera.clamp_pan(&frame.fit_points(), glam::Vec2::new(w, h));
        }
        let view_proj = self.camera.projection(w / h) * self.camera.view();
        self.labels = crate::draw::project_labels(&self.renderer.frame.labels, view_proj, w, h);
        // The inset's title is the last label; the layout puts it inside the inset and keeps
        // the others off the inset (`place_labels`).
        self.inset_title = false;
        if let Some(inset) = &frame.inset {
            let at = crate::draw::inset::title_top_left(glam::Vec2::new(w, h));
            self.labels.push(crate::draw::ScreenLabel {
                x_px: at.x,
                y_px: at.y,
                dot_px: at,
                visible: true,
                text: inset.title.clone(),
                css_color: crate::draw::palette::css(crate::draw::palette::DARK),
                left: false,
                priority: i32::MAX,
                large: false,
            });
            self.inset_title = true;
        }
        self.last_fingerprint = self.renderer.frame.fingerprint();
        if !self.visible {
            // Keep it for when the canvas comes back (swapping reuses both frames' buffers).
            std::mem::swap(&mut self.renderer.frame, &mut self.hidden);
            self.renderer.frame.clear();
            self.pending = true;
            return Ok(());
        }
        self.pending = false;
        self.renderer
            .render(&self.gpu, &self.camera, self.last_fingerprint)
            .map_err(|e| JsError::new(&e))
    }

    /// Returns to the fit view: the camera fits what the figure declares must stay in view
    /// (keeping the reader's orbit) and follows it again; a figure that declares nothing gets
    /// back the camera it placed. The page calls it from the "frame all" button and on a
    /// double-click.
    #[wasm_bindgen(js_name = frameAll)]
    pub fn frame_all(&mut self) {
        self.fitting = true;
        if !self.declares_view {
            self.camera = self.home;
        }
    }

    /// Whether the last frame declared what must stay in view (the page's double-click returns
    /// to the fit view only then: an editor figure has its own use for a double-click).
    #[wasm_bindgen(getter, js_name = declaresView)]
    pub fn declares_view(&self) -> bool {
        self.declares_view
    }

    /// Whether the camera follows the figure's declared view (for the page and its tests).
    #[wasm_bindgen(getter)]
    pub fn fitting(&self) -> bool {
        self.fitting && self.declares_view
    }

    /// Tells the figure whether its canvas is on screen; coming back, it draws the frame it kept.
    #[wasm_bindgen(js_name = setVisible)]
    pub fn set_visible(&mut self, on: JsValue) -> Result<(), JsError> {
        let on = super::boolean("on", &on)?;
        self.visible = on;
        if on && self.pending {
            std::mem::swap(&mut self.renderer.frame, &mut self.hidden);
            self.pending = false;
            self.renderer
                .render(&self.gpu, &self.camera, self.last_fingerprint)
                .map_err(|e| JsError::new(&e))?;
        }
        Ok(())
    }
}

#[wasm_bindgen]
impl Viewer {
    /// How many frames the figure has drawn into its canvas: frames it already showed are not
    /// drawn again (see `Renderer::render`). For the page tests.
    #[wasm_bindgen(getter, js_name = canvasFrames)]
    pub fn canvas_frames(&self) -> f64 {
        self.renderer.canvas_frames() as f64
    }

    /// What the last presented frame drew, as a hex fingerprint (changes whenever anything drawn
    /// changes; the camera is not part of it). For the page tests.
    #[wasm_bindgen(js_name = frameFingerprint)]
    pub fn frame_fingerprint(&self) -> String {
        format!("{:016x}", self.last_fingerprint)
    }

    /// The last presented frame's labels as JSON:
    /// `[{"x":…,"y":…,"visible":…,"left":…,"large":…,"title":…,"text":…,"color":…}]`,
    /// x and y in CSS pixels from the canvas's top-left corner. The shell (`www/lesson.js`) places
    /// one HTML element per label over the canvas.
    #[wasm_bindgen(js_name = labelsJson)]
    pub fn labels_json(&self) -> String {
        let mut out = String::from("[");
        for (i, l) in self.labels.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let text: String = l
                .text
                .chars()
                .flat_map(|c| match c {
                    '"' | '\\' => vec!['\\', c],
                    c if c.is_control() => vec![' '],
                    c => vec![c],
                })
                .collect();
            // "title": the inset's title (the last label when there is one, as `place_labels`
            // takes it), which the page backs with a white plate: what the inset draws can run
            // under it.
            out += &format!(
                r#"{{"x":{:.1},"y":{:.1},"visible":{},"left":{},"large":{},"title":{},"text":"{}","color":"{}"}}"#,
                l.x_px,
                l.y_px,
                l.visible,
                l.left,
                l.large,
                self.inset_title && i + 1 == self.labels.len(),
                text,
                l.css_color
            );
        }
        out.push(']');
        out
    }

    /// Lays the last frame's labels out (see [`crate::draw::layout`]): `sizes` holds each
    /// label's measured width and height in CSS pixels, in the order of [`Viewer::labels_json`].
    /// Returns JSON, one entry per label: `{"shown":…,"x":…,"y":…}` (the box's top-left corner),
    /// with `"lx","ly"` (the anchor) and `"tx","ty"` (the box's nearest point) when a leader
    /// line joins a moved label to its anchor.
    #[wasm_bindgen(js_name = placeLabels)]
    pub fn place_labels(&self, sizes: Vec<f32>) -> Result<String, JsError> {
        if sizes.len() != 2 * self.labels.len() {
            return Err(JsError::new(&format!(
                "placeLabels needs a width and a height for each of the {} labels, got {} numbers",
                self.labels.len(),
                sizes.len()
            )));
        }
        for (i, v) in sizes.iter().enumerate() {
            super::in_range(&format!("label size {i}"), *v, 0.0, 1e5)?;
        }
        use crate::draw::layout::{place, LabelBox};
        let boxes: Vec<LabelBox> = self
            .labels
            .iter()
            .zip(sizes.chunks_exact(2))
            .map(|(l, s)| LabelBox {
                anchor: glam::Vec2::new(l.x_px, l.y_px),
                size: glam::Vec2::new(s[0], s[1]),
                left: l.left,
                visible: l.visible,
                priority: l.priority,
            })
            .collect();
        let canvas = glam::Vec2::new(self.css_size.0, self.css_size.1);
        let placements = if self.inset_title {
            // Every label but the title keeps off the inset; the title sits inside it.
            let inset = crate::draw::inset::inset_rect(canvas);
            let n = boxes.len() - 1;
            let mut p = crate::draw::layout::place_avoiding(&boxes[..n], canvas, &[inset]);
            p.push(crate::draw::layout::Placement {
                top_left: crate::draw::inset::title_top_left(canvas),
                shown: true,
                leader_to: None,
            });
            p
        } else {
            place(&boxes, canvas)
        };
        let mut out = String::from("[");
        for (i, ((p, b), l)) in placements.iter().zip(&boxes).zip(&self.labels).enumerate() {
            if i > 0 {
                out.push(',');
            }
            out += &format!(
                r#"{{"shown":{},"x":{:.1},"y":{:.1}"#,
                p.shown, p.top_left.x, p.top_left.y
            );
            let rect = crate::draw::layout::Rect {
                min: p.top_left,
                size: b.size,
            };
            let leader = p.shown.then(|| crate::draw::layout::leader(rect, l.dot_px, p.leader_to.is_some()));
            if let Some(t) = leader.flatten() {
                out += &format!(
                    r#","lx":{:.1},"ly":{:.1},"tx":{:.1},"ty":{:.1}"#,
                    l.dot_px.x, l.dot_px.y, t.x, t.y
                );
            }
            out.push('}');
        }
        out.push(']');
        Ok(out)
    }
}

impl Viewer {
    /// True once after each [`Viewer::adopt`] for a scene that last saw generation `seen` (and
    /// updates it): the scene's meshes, textures and compute buffers were on the lost device, and
    /// it makes them again.
    pub(crate) fn renewed(&self, seen: &mut u32) -> bool {
        std::mem::replace(seen, self.generation) != self.generation
    }

    /// Draws the current frame offscreen and returns RGBA bytes (tests).
    pub async fn read_pixels(&mut self, width: u32, height: u32) -> Result<Vec<u8>, String> {
        self.renderer
            .render_to_rgba(&self.gpu, &self.camera, width, height)
            .await
    }
}
