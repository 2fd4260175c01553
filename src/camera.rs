//! An orbit camera: it circles a target point at some distance, looking at it.
//!
//! ```text
//! eye = target + distance · (cos φ · sin θ,  sin φ,  cos φ · cos θ)      θ = yaw, φ = pitch
//! ```
//! Dragging changes yaw and pitch, the wheel scales the distance, panning moves the target in the
//! view plane. Projection is perspective with depth in `[0, 1]` (wgpu's convention).

use glam::{Mat4, Vec2, Vec3};

/// A camera orbiting `target`. Angles in radians, distances in metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    pub target: Vec3,
    pub distance: f32,
    /// Rotation about the world Y axis; 0 looks from +Z towards −Z.
    pub yaw_rad: f32,
    /// Elevation above the horizontal plane, kept inside (−π/2, π/2) so "up" stays defined.
    pub pitch_rad: f32,
    /// Vertical field of view.
    pub fov_y_rad: f32,
    pub near: f32,
    pub far: f32,
}

/// How far pitch may go towards a pole: looking straight down would make the up vector undefined.
const PITCH_LIMIT_RAD: f32 = 1.55;
const MIN_DISTANCE: f32 = 0.05;

impl Default for OrbitCamera {
    fn default() -> Self {
        Self {
            target: Vec3::new(0.0, 1.0, 0.0),
            distance: 4.0,
            yaw_rad: 0.5,
            pitch_rad: 0.3,
            fov_y_rad: 45f32.to_radians(),
            near: 0.05,
            far: 200.0,
        }
    }
}

impl OrbitCamera {
    /// The camera that the page's `viewer.setCamera(x, y, z, distance, yaw, pitch)` places (a
    /// figure's `view()` returns these six numbers): aimed at `(x, y, z)` from `distance`, turned
    /// by yaw and pitch from the view along −Z (pitch clamped as by [`OrbitCamera::orbit`]).
    pub fn from_view([x, y, z, distance, yaw_rad, pitch_rad]: [f32; 6]) -> Self {
        let mut camera = Self {
            target: Vec3::new(x, y, z),
            distance,
            yaw_rad: 0.0,
            pitch_rad: 0.0,
            ..Self::default()
        };
        camera.orbit(yaw_rad, pitch_rad);
        camera
    }

    /// Position of the eye in world space.
    pub fn eye(&self) -> Vec3 {
        let (sy, cy) = self.yaw_rad.sin_cos();
        let (sp, cp) = self.pitch_rad.sin_cos();
        self.target + self.distance * Vec3::new(cp * sy, sp, cp * cy)
    }

    /// World-to-view matrix (right-handed, the camera looks down −Z).
    pub fn view(&self) -> Mat4 {
        glam::camera::rh::view::look_at_mat4(self.eye(), self.target, Vec3::Y)
    }

    /// View-to-clip matrix for a viewport of the given width / height ratio.
    pub fn projection(&self, aspect: f32) -> Mat4 {
        // wgpu's clip space is Y-up with depth in [0, 1]: glam's "directx" convention.
        glam::camera::rh::proj::directx::perspective(
            self.fov_y_rad,
            aspect.max(1e-3),
            self.near,
            self.far,
        )
    }

    /// Turns the camera: `d_yaw` and `d_pitch` in radians. Pitch is clamped short of the poles.
    pub fn orbit(&mut self, d_yaw_rad: f32, d_pitch_rad: f32) {
        self.yaw_rad = (self.yaw_rad + d_yaw_rad) % std::f32::consts::TAU;
        self.pitch_rad = (self.pitch_rad + d_pitch_rad).clamp(-PITCH_LIMIT_RAD, PITCH_LIMIT_RAD);
    }

    /// Lowers the camera to at most `max_pitch_rad` above the horizon, if given (a figure's
    /// [`crate::draw::Frame::max_pitch_rad`]); the yaw and the distance stay.
    pub fn limit_pitch(&mut self, max_pitch_rad: Option<f32>) {
        if let Some(max) = max_pitch_rad {
            self.pitch_rad = self.pitch_rad.min(max);
        }
    }

    /// Turns the camera back to at most `max_yaw_rad` either side of the front (yaw 0), if given
    /// (a figure's [`crate::draw::Frame::max_yaw_rad`]); the pitch and the distance stay.
    pub fn limit_yaw(&mut self, max_yaw_rad: Option<f32>) {
        if let Some(max) = max_yaw_rad {
            let pi = std::f32::consts::PI;
            // The same direction in (−π, π], then clamped.
            let yaw = (self.yaw_rad + pi).rem_euclid(std::f32::consts::TAU) - pi;
            self.yaw_rad = yaw.clamp(-max, max);
        }
    }

    /// A pointer drag of `(dx_px, dy_px)` CSS pixels on a canvas `height_px` tall: turns the
    /// camera round its target, or, for a `flat` figure ([`crate::draw::Frame::flat`]), pans,
    /// keeping the figure facing the camera. Returns whether it panned.
    pub fn drag(&mut self, dx_px: f32, dy_px: f32, height_px: f32, flat: bool) -> bool {
        if flat {
            self.pan(dx_px / height_px, dy_px / height_px);
        } else {
            self.orbit(-dx_px * 0.008, dy_px * 0.008);
        }
        flat
    }

    /// Multiplies the distance by `factor` (< 1 zooms in), keeping it inside [near·1, far/2].
    pub fn zoom(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance =
                (self.distance * factor).clamp(MIN_DISTANCE.max(self.near), self.far * 0.5);
        }
    }

    /// Moves the target in the view plane by `(dx, dy)` in units of the distance, so a drag
    /// moves the scene by a similar fraction of the screen at any zoom.
    pub fn pan(&mut self, dx: f32, dy: f32) {
        let view = self.view();
        let right = view.row(0).truncate();
        let up = view.row(1).truncate();
        self.target += (right * -dx + up * dy) * self.distance;
    }
}

impl OrbitCamera {
    /// Keeps a panned or zoomed flat figure's `points` in view on a canvas of `size_px`: the
    /// distance stays at least [`OrbitCamera::fit`]'s (a zoom in stops where the points fill the
    /// canvas, and a canvas made smaller zooms out to fit them), and the target stays where
    /// every point is on the canvas, its image within [`PAN_ROOM_PX`] of the middle (the drag
    /// shows, and the figure does not end against one edge with the rest of the canvas empty).
    /// The check is in perspective: a pan moves the eye by `s` in the view plane, and a point
    /// `x` across and `d` deep is on the canvas while `x − v·d ≤ s ≤ x + v·d`, `v` the view's
    /// half extent at unit depth; a deep figure seen at an angle shows its near end larger.
    /// Where the points cannot fit (a canvas too small for the padding), the target moves just
    /// enough that they cover the canvas.
    pub fn clamp_pan(&mut self, points: &[Vec3], size_px: Vec2) {
        if !(size_px.y > 0.0) {
            return;
        }
        let mut fitted = *self;
        if fitted.fit(points, size_px, FIT_PAD_PX) {
            self.distance = self.distance.max(fitted.distance);
        }
        let view = self.view();
        let (right, up, back) = (
            view.row(0).truncate(),
            view.row(1).truncate(),
            view.row(2).truncate(),
        );
        let eye = self.eye();
        let v = (0.5 * self.fov_y_rad).tan() * Vec2::new(size_px.x / size_px.y, 1.0);
        // Per axis, the pan's limits and the depths of the points that set them.
        let (mut lo, mut hi) = (Vec2::MIN, Vec2::MAX);
        let (mut d_lo, mut d_hi) = (Vec2::ONE, Vec2::ONE);
        for p in points.iter().filter(|p| p.is_finite()) {
            let r = *p - eye;
            let d = -r.dot(back);
            if d > 0.0 {
                let x = Vec2::new(r.dot(right), r.dot(up));
                let (a, b, dd) = (x - v * d, x + v * d, Vec2::splat(d));
                (d_lo, lo) = (Vec2::select(a.cmpgt(lo), dd, d_lo), lo.max(a));
                (d_hi, hi) = (Vec2::select(b.cmplt(hi), dd, d_hi), hi.min(b));
            }
        }
        // The pan that leaves equal margins on both sides, and the room round it at the
        // target's depth.
        let middle = (hi * d_lo + lo * d_hi) / (d_lo + d_hi);
        let room = PAN_ROOM_PX * 2.0 * v.y * self.distance / size_px.y;
        let fits = lo.cmple(hi);
        let min = Vec2::select(fits, lo.max(middle - room), hi);
        let max = Vec2::select(fits, hi.min(middle + room), lo);
        if lo.cmpgt(Vec2::MIN).all() && min.cmple(max).all() {
            let s = Vec2::ZERO.clamp(min, max);
            self.target += right * s.x + up * s.y;
        }
    }
}

/// How far a drag may move a flat figure that fits its canvas off the middle, CSS pixels.
pub const PAN_ROOM_PX: f32 = 8.0;

/// Space kept between the points a camera fits and the canvas's edges, CSS pixels (room for a
/// label beside an anchor near the edge).
pub const FIT_PAD_PX: f32 = 32.0;

impl OrbitCamera {
    /// Aims the camera so that every one of `points` lies inside a canvas of `size_px` CSS
    /// pixels, at least `pad_px` from its edges, keeping the yaw and pitch (the reader's orbit):
    /// the target moves to the middle of the points as seen from this direction and the
    /// distance becomes the smallest that fits them all. Returns false, changing nothing, when
    /// there are no finite points or the canvas is too small for the padding.
    pub fn fit(&mut self, points: &[Vec3], size_px: Vec2, pad_px: f32) -> bool {
        self.fit_offset(points, size_px, size_px.y, pad_px, Vec2::ZERO, 2)
    }

    /// [`OrbitCamera::fit`] into a part of a canvas `canvas_h` pixels tall, `size_px` in size,
    /// whose centre is `off` right of and above the canvas's (in units of the view's tangent at
    /// unit depth, `off = Δpx / (canvas_h / 2) · tan(fov/2)`): a point at `a` along the view's right and
    /// `depth` in front fits when `|a / depth − off.x| ≤ tan_x`, and likewise up the view.
    fn fit_offset(
        &mut self,
        points: &[Vec3],
        size_px: Vec2,
        canvas_h: f32,
        pad_px: f32,
        off: Vec2,
        rounds: usize,
    ) -> bool {
        let points: Vec<Vec3> = points.iter().copied().filter(|p| p.is_finite()).collect();
        if points.is_empty() || !size_px.is_finite() || !pad_px.is_finite() {
            return false;
        }
        let usable = Vec2::ONE - 2.0 * pad_px.max(0.0) / size_px;
        if usable.min_element() <= 0.05 {
            return false;
        }
        let (sy, cy) = self.yaw_rad.sin_cos();
        let (sp, cp) = self.pitch_rad.sin_cos();
        // Unit vectors of the view: `back` points from the target to the eye.
        let back = Vec3::new(cp * sy, sp, cp * cy);
        let right = Vec3::Y.cross(back).normalize();
        let up = back.cross(right);
        let tan_px = (0.5 * self.fov_y_rad).tan() / canvas_h;
        let tan_y = tan_px * size_px.y * usable.y;
        let tan_x = tan_px * size_px.x * usable.x;
        if !(tan_x > off.x.abs() && tan_y > off.y.abs()) {
            return false;
        }
        let (lo, hi) = points.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        let mut target = 0.5 * (lo + hi);
        // The smallest distance from `target` that shows every point: a point at (x, y) in the
        // view plane and `z` towards the eye is seen at depth distance − z, and fits when
        // |x − off.x · depth| ≤ tan_x · depth, that is depth ≥ x / (tan_x + off.x) and depth ≥
        // −x / (tan_x − off.x), and likewise for y. The depth also stays past the near plane.
        let needed = |target: Vec3| {
            points.iter().fold(MIN_DISTANCE.max(self.near), |d, p| {
                let v = *p - target;
                let z = v.dot(back);
                let x = v.dot(right);
                let y = v.dot(up);
                let fit = (x / (tan_x + off.x))
                    .max(-x / (tan_x - off.x))
                    .max(y / (tan_y + off.y))
                    .max(-y / (tan_y - off.y));
                d.max(fit + z).max(2.0 * self.near + z)
            })
        };
        // `rounds` times: centre the points' image on the part (in the view plane), then fit again.
        for _ in 0..rounds {
            let distance = needed(target);
            let eye = target + back * distance;
            let (mut x_lo, mut x_hi, mut y_lo, mut y_hi) = (f32::MAX, f32::MIN, f32::MAX, f32::MIN);
            for p in &points {
                let v = *p - eye;
                let depth = -v.dot(back);
                let (x, y) = (v.dot(right) / depth, v.dot(up) / depth);
                (x_lo, x_hi, y_lo, y_hi) = (x_lo.min(x), x_hi.max(x), y_lo.min(y), y_hi.max(y));
            }
            // Shift by the middle of the image (less where it should be), scaled back to the
            // target's depth.
            let shift = right * (0.5 * (x_lo + x_hi) - off.x) + up * (0.5 * (y_lo + y_hi) - off.y);
            target += shift * distance;
        }
        let distance = needed(target);
        if !target.is_finite() || !distance.is_finite() {
            return false;
        }
        self.target = target;
        self.distance = distance.min(self.far * 0.5);
        true
    }
}

impl OrbitCamera {
    /// As [`OrbitCamera::fit`], into the canvas's left part, `width_px` of its `size_px.x` (a
    /// figure's inset takes the right), as tall as the canvas. False (nothing changed) when the
    /// fit is impossible.
    pub fn fit_left_of(
        &mut self,
        points: &[Vec3],
        size_px: Vec2,
        width_px: f32,
        pad_px: f32,
    ) -> bool {
        if !(width_px > 0.0 && width_px <= size_px.x) {
            return false;
        }
        // The part's centre is half the strip left of the canvas's.
        let shift_px = -0.5 * (size_px.x - width_px);
        let x_off = shift_px / (0.5 * size_px.y) * (0.5 * self.fov_y_rad).tan();
        let part = Vec2::new(width_px, size_px.y);
        self.fit_offset(points, part, size_px.y, pad_px, Vec2::new(x_off, 0.0), 2)
    }

    /// As [`OrbitCamera::fit`], into the canvas's top part, `height_px` of its `size_px.y` (for
    /// a wide, low figure whose inset takes the bottom right), as wide as the canvas. False
    /// (nothing changed) when the fit is impossible.
    pub fn fit_above(
        &mut self,
        points: &[Vec3],
        size_px: Vec2,
        height_px: f32,
        pad_px: f32,
    ) -> bool {
        if !(height_px > 0.0 && height_px <= size_px.y) {
            return false;
        }
        // The part's centre is half the strip above the canvas's.
        let shift_px = 0.5 * (size_px.y - height_px);
        let y_off = shift_px / (0.5 * size_px.y) * (0.5 * self.fov_y_rad).tan();
        let part = Vec2::new(size_px.x, height_px);
        // A strip far off the canvas's centre and short against that offset takes more
        // rounds of centring to settle than a centred fit's two.
        self.fit_offset(points, part, size_px.y, pad_px, Vec2::new(0.0, y_off), 32)
    }
}

/// Where `world` lands on a canvas of `size` CSS pixels seen through `view_proj`, in pixels from
/// the top-left; `None` behind the camera. (Picking in the figures: what is under the mouse.)
pub fn project_to_canvas(view_proj: Mat4, size: Vec2, world: Vec3) -> Option<Vec2> {
    let clip = view_proj * world.extend(1.0);
    if clip.w <= 1e-6 {
        return None;
    }
    let ndc = clip.truncate() / clip.w;
    Some(Vec2::new(
        (ndc.x * 0.5 + 0.5) * size.x,
        (0.5 - ndc.y * 0.5) * size.y,
    ))
}

/// The point under the pixel `p` on the plane through `anchor` that faces the camera (normal
/// along the line of sight through `anchor`): where a dragged point goes. `None` if the ray
/// misses the plane.
pub fn point_on_view_plane(view_proj: Mat4, size: Vec2, anchor: Vec3, p: Vec2) -> Option<Vec3> {
    let inverse = view_proj.inverse();
    let unproject = |px: Vec2, z: f32| {
        let ndc = Vec3::new(2.0 * px.x / size.x - 1.0, 1.0 - 2.0 * px.y / size.y, z);
        inverse.project_point3(ndc)
    };
    let near = unproject(p, 0.0);
    let dir = unproject(p, 1.0) - near;
    let anchor_px = project_to_canvas(view_proj, size, anchor)?;
    let normal = (unproject(anchor_px, 1.0) - unproject(anchor_px, 0.0)).try_normalize()?;
    let denominator = dir.dot(normal);
    if denominator.abs() < 1e-9 {
        return None;
    }
    let s = (anchor - near).dot(normal) / denominator;
    let hit = near + dir * s;
    hit.is_finite().then_some(hit)
}
