//! An orbit camera: it circles a target point at some distance, looking at it.
//!
//! ```text
//! eye = target + distance · (cos φ · sin θ,  sin φ,  cos φ · cos θ)      θ = yaw, φ = pitch
//! ```
//! Dragging changes yaw and pitch, the wheel scales the distance, panning moves the target in the
//! view plane. Projection is perspective with depth in `[0, 1]` (wgpu's convention).

use glam::{Mat4, Vec3};

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
