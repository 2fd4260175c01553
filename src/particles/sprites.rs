//! Sprites: the images particles are drawn with, and the order they are drawn in.
//!
//! - [`fill_smoke_atlas`]: a puff of smoke in [`SMOKE_ATLAS`]'s 16 frames (4 × 4), made from
//!   fractal noise, growing, thinning and fading over its life: frame `k` shows the puff at life
//!   fraction `k / 15`. Opacity is 0 on every frame's border, so filtering never bleeds one frame
//!   into the next.
//! - [`sort_back_to_front`]: the draw order of transparent sprites, deepest along the view first.
//!   Blending `c = α c_sprite + (1 − α) c_behind` needs what is behind already in the image; a
//!   near sprite drawn first also writes its depth, and a farther one then fails the depth test
//!   and is never blended in.
//!
//! Lesson: lessons/11-particles.

use crate::noise::{Fractal, Permutation};
use crate::texture::Atlas;
use glam::{Vec2, Vec3};

/// The smoke atlas's layout: 16 frames, row by row.
pub const SMOKE_ATLAS: Atlas = Atlas {
    columns: 4,
    rows: 4,
};

/// The largest frame side [`fill_smoke_atlas`] accepts, in texels.
pub const MAX_FRAME_SIDE: usize = 256;

/// The opacity of the puff at `p ∈ [−1, 1]²` of a frame (centre 0) at life fraction `s ∈ [0, 1]`.
pub fn smoke_opacity(perm: &Permutation, p: Vec2, s: f32) -> f32 {
    // The puff's radius grows from 0.5 to 0.9 of the frame; its edge is soft.
    let radius = 0.5 + 0.4 * s;
    let r = p.length() / radius;
    let edge = 1.0 - smoothstep(0.35, 1.0, r);
    // Billows: a fractal sum that drifts as the puff ages (a slice of 3D noise).
    let f = Fractal {
        n: 3,
        alpha: 0.5,
        omega: 2.0,
    };
    let g = f.sum3(perm, Vec3::new(2.5 * p.x + 7.3, 2.5 * p.y + 1.9, 1.5 * s));
    let density = (0.75 + 1.1 * g).clamp(0.0, 1.0);
    // Thins out with age.
    let fade = 1.0 - 0.75 * s;
    (edge * density * fade).clamp(0.0, 1.0)
}

fn smoothstep(a: f32, b: f32, x: f32) -> f32 {
    let t = ((x - a) / (b - a)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Writes the smoke atlas: `SMOKE_ATLAS` frames of `frame_side²` texels into `rgba`
/// (`4 · (4 frame_side)²` bytes, RGBA, rows from the top). Colour is a light grey, brighter where
/// the puff is dense; the sprite's tint multiplies it.
pub fn fill_smoke_atlas(
    perm: &Permutation,
    frame_side: usize,
    rgba: &mut [u8],
) -> Result<(), String> {
    if !(4..=MAX_FRAME_SIDE).contains(&frame_side) {
        return Err(format!(
            "an atlas frame must be 4 to {MAX_FRAME_SIDE} texels on a side, got {frame_side}"
        ));
    }
    let (cols, rows) = (SMOKE_ATLAS.columns as usize, SMOKE_ATLAS.rows as usize);
    let width = cols * frame_side;
    let needed = 4 * width * rows * frame_side;
    if rgba.len() != needed {
        return Err(format!(
            "the atlas needs {needed} bytes, got {}",
            rgba.len()
        ));
    }
    let last = (SMOKE_ATLAS.frames() - 1) as f32;
    for frame in 0..SMOKE_ATLAS.frames() as usize {
        let s = frame as f32 / last;
        let (c, r) = (frame % cols, frame / cols);
        for j in 0..frame_side {
            for i in 0..frame_side {
                let p = Vec2::new(
                    2.0 * (i as f32 + 0.5) / frame_side as f32 - 1.0,
                    1.0 - 2.0 * (j as f32 + 0.5) / frame_side as f32,
                );
                let a = smoke_opacity(perm, p, s);
                // Lit from above: a little brighter in the upper half.
                let grey = (0.78 + 0.12 * p.y.clamp(-1.0, 1.0) + 0.1 * a).clamp(0.0, 1.0);
                let at = 4 * ((r * frame_side + j) * width + c * frame_side + i);
                let g = crate::noise::texture::to_srgb8(grey);
                rgba[at..at + 4].copy_from_slice(&[g, g, g, (255.0 * a).round() as u8]);
            }
        }
    }
    Ok(())
}

/// Fills `order` with `(depth, index)` for every position, deepest first (ties keep index
/// order), where the depth is `(p − eye) · forward` along the camera's unit view direction
/// `forward`. Camera-facing squares all lie parallel to the image plane, so this is exactly the
/// depth the depth test compares; sorted by distance from the eye instead, two overlapping
/// sprites off to the side of the view can come out in the wrong order. With `forward = 0` (no
/// view direction) the key is the squared distance from the eye. Reuses `order`'s storage: no
/// allocation once it is large enough.
pub fn sort_back_to_front(
    order: &mut Vec<(f32, u32)>,
    positions: &[Vec3],
    eye: Vec3,
    forward: Vec3,
) {
    order.clear();
    let key = |p: Vec3| {
        if forward == Vec3::ZERO {
            (p - eye).length_squared()
        } else {
            (p - eye).dot(forward)
        }
    };
    order.extend(
        positions
            .iter()
            .enumerate()
            .map(|(i, &p)| (key(p), i as u32)),
    );
    // A stable sort on a total order (NaN depths go first, as if infinitely far).
    crate::order::sort_desc(order);
}
