//! Textures in the draw list: RGBA8 images made on the CPU (procedural textures, sprite atlases)
//! or by a shader, shown on quads placed in the scene and on camera-facing sprites.
//!
//! A scene uploads an image once with `Renderer::create_texture` (wasm only) and gets a
//! [`TextureId`]; when the image changes it calls `Renderer::update_texture`, which rewrites the
//! same GPU texture in place when the size is unchanged. What is drawn is plain data in
//! [`crate::draw::Frame`] ([`TexturedQuad`], [`SpriteInstance`]), so native tests can check it.
//!
//! Texel rows run from the top of the image (row 0) down, as in every image file; a quad shows
//! row 0 at its far edge (`z = −1` in the quad's own frame), so an image laid on the ground reads
//! as it does on screen from the default camera.

use glam::{Mat4, Vec4};

/// A texture known to a renderer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TextureId(pub usize);

/// The largest side of a texture a scene may upload (WebGL2 guarantees 2048; 2048² RGBA is
/// 16 MiB).
pub const MAX_TEXTURE_SIDE: u32 = 2048;

/// Checks that `rgba` holds a `width × height` RGBA8 image (4 bytes a texel, rows from the top)
/// within [`MAX_TEXTURE_SIDE`].
pub fn validate_rgba(width: u32, height: u32, rgba: &[u8]) -> Result<(), String> {
    if !(1..=MAX_TEXTURE_SIDE).contains(&width) || !(1..=MAX_TEXTURE_SIDE).contains(&height) {
        return Err(format!(
            "a texture must be between 1 and {MAX_TEXTURE_SIDE} texels on a side, got \
             {width} × {height}"
        ));
    }
    let needed = 4 * width as usize * height as usize;
    if rgba.len() != needed {
        return Err(format!(
            "a {width} × {height} RGBA image needs {needed} bytes, got {}",
            rgba.len()
        ));
    }
    Ok(())
}

/// A part of a texture: `(u0, v0)` top-left and `(u1, v1)` bottom-right, in `[0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvRect {
    pub u0: f32,
    pub v0: f32,
    pub u1: f32,
    pub v1: f32,
}

impl UvRect {
    /// The whole texture.
    pub const FULL: UvRect = UvRect {
        u0: 0.0,
        v0: 0.0,
        u1: 1.0,
        v1: 1.0,
    };

    pub fn to_array(self) -> [f32; 4] {
        [self.u0, self.v0, self.u1, self.v1]
    }
}

/// A grid of equal frames in one texture (a sprite atlas), numbered row by row from the top
/// left.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Atlas {
    pub columns: u32,
    pub rows: u32,
}

impl Atlas {
    pub fn frames(&self) -> u32 {
        self.columns * self.rows
    }

    /// Where frame `index` lies (indices wrap around, so an animation loops).
    pub fn frame(&self, index: u32) -> UvRect {
        let i = index % self.frames().max(1);
        let (c, r) = (i % self.columns, i / self.columns);
        let (w, h) = (1.0 / self.columns as f32, 1.0 / self.rows as f32);
        UvRect {
            u0: c as f32 * w,
            v0: r as f32 * h,
            u1: (c + 1) as f32 * w,
            v1: (r + 1) as f32 * h,
        }
    }

    /// The frame for a life fraction `s ∈ [0, 1]` (birth to death), played once: 0 is the first
    /// frame, values near 1 the last.
    pub fn frame_at(&self, s: f32) -> UvRect {
        let n = self.frames();
        let s = if s.is_nan() { 0.0 } else { s.clamp(0.0, 1.0) };
        self.frame(((s * n as f32) as u32).min(n - 1))
    }
}

/// A textured square: the square `[−1, 1]²` of the xz plane (y up, like a terrain's plane) placed
/// by `model`, showing `uv` of `texture` (texel row 0 at `z = −1`), unlit, times `tint`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexturedQuad {
    pub texture: TextureId,
    /// Quad space to world space.
    pub model: Mat4,
    /// Linear RGBA multiplying the texel.
    pub tint: Vec4,
    pub uv: UvRect,
}

/// A camera-facing textured square, laid out as the GPU reads it. All sprites of a frame share
/// one texture ([`crate::draw::Frame::sprite_texture`]), usually an [`Atlas`]; they are
/// alpha-blended in the order they are listed (sort them back to front).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpriteInstance {
    /// World space.
    pub center: [f32; 3],
    /// Half the side, world units.
    pub half_size: f32,
    /// `[u0, v0, u1, v1]`: the frame of the atlas to show.
    pub uv: [f32; 4],
    /// Linear RGBA multiplying the texel.
    pub color: [f32; 4],
}
