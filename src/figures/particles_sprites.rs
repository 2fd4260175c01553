//! Lesson 11's sprite figure: a column of smoke drawn as camera-facing textured squares that play
//! the smoke atlas (`particles::sprites`) over their life, alpha-blended, twice side by side: on
//! the left sorted back to front, on the right the same puffs in storage order (to show why
//! sorting matters), with the atlas itself shown beside them.

use super::{format_number, in_range, palette, Frame, MeshId};
use crate::noise::Permutation;
use crate::particles::sprites::{fill_smoke_atlas, sort_back_to_front, SMOKE_ATLAS};
use crate::texture::{SpriteInstance, TextureId, UvRect};
use glam::{Mat4, Vec3, Vec4};

/// Texels per side of one atlas frame (the atlas is 4 × 4 frames: 128 × 128 texels).
pub const FRAME_SIDE: usize = 32;
/// Texels per side of the whole atlas.
pub const ATLAS_SIDE: usize = 4 * FRAME_SIDE;
/// The most puffs the figure shows.
pub const MAX_PUFFS: usize = 200;

/// Where the sorted column rises from.
const SOURCE: Vec3 = Vec3::new(-1.3, 0.1, -0.6);
/// How far right of the sorted column the unsorted one rises, metres: the same puffs, far
/// enough apart that the two columns never overlap on screen.
pub const COLUMN_GAP: Vec3 = Vec3::new(3.0, 0.0, 0.0);
/// Where the atlas is shown (a square of half-side [`ATLAS_HALF`], standing up, facing +z).
const ATLAS_AT: Vec3 = Vec3::new(-3.2, 1.0, 0.0);
const ATLAS_HALF: f32 = 0.6;

/// The smoke atlas every sprite figure of lesson 11 uses: `ATLAS_SIDE²` RGBA texels.
pub fn smoke_atlas_image() -> Vec<u8> {
    let mut atlas = vec![0; 4 * ATLAS_SIDE * ATLAS_SIDE];
    fill_smoke_atlas(&Permutation::perlin(), FRAME_SIDE, &mut atlas)
        .expect("the figure's atlas size is valid");
    atlas
}

/// The smoke column.
pub struct SmokeFigure {
    atlas: Vec<u8>,
    puffs: usize,
    lifetime_sec: f32,
    animate_frames: bool,
    show_atlas: bool,
    positions: Vec<Vec3>,
    ages: Vec<f32>,
    order: Vec<(f32, u32)>,
    /// The camera and canvas size (CSS pixels) the last frame was drawn with: the names take
    /// places that cover no puff's centre, the atlas's board or each other.
    view: Option<(crate::camera::OrbitCamera, glam::Vec2)>,
}

impl Default for SmokeFigure {
    fn default() -> Self {
        Self::new()
    }
}

impl SmokeFigure {
    pub fn new() -> Self {
        Self {
            atlas: smoke_atlas_image(),
            puffs: 30,
            lifetime_sec: 4.0,
            animate_frames: true,
            show_atlas: true,
            positions: Vec::with_capacity(MAX_PUFFS),
            ages: Vec::with_capacity(MAX_PUFFS),
            order: Vec::with_capacity(MAX_PUFFS),
            view: None,
        }
    }

    /// The camera and canvas size (CSS pixels) the frame is drawn for (the last frame's), which
    /// the names are placed for.
    pub fn set_view(&mut self, camera: crate::camera::OrbitCamera, width_px: f32, height_px: f32) {
        if width_px > 0.0 && height_px > 0.0 {
            self.view = Some((camera, glam::Vec2::new(width_px, height_px)));
        }
    }

    /// The atlas image: `ATLAS_SIDE²` RGBA texels, rows from the top.
    pub fn atlas(&self) -> &[u8] {
        &self.atlas
    }

    /// Puffs alive at once (1 to [`MAX_PUFFS`]) and their lifetime in seconds (0.5 to 10).
    pub fn set_params(&mut self, puffs: f32, lifetime_sec: f32) -> Result<(), String> {
        let n = in_range("puffs", puffs, 1.0, MAX_PUFFS as f32)?;
        if n.fract() != 0.0 {
            return Err(format!("puffs must be a whole number, got {puffs}"));
        }
        self.lifetime_sec = in_range("lifetime", lifetime_sec, 0.5, 10.0)?;
        self.puffs = n as usize;
        Ok(())
    }

    /// Plays the atlas over each puff's life, or shows its first frame only.
    pub fn set_animate_frames(&mut self, on: bool) {
        self.animate_frames = on;
    }

    pub fn set_show_atlas(&mut self, on: bool) {
        self.show_atlas = on;
    }

    /// Puff `k`'s age at time `t`. Each puff is reborn at the source when its life ends, with
    /// phases spread by the golden ratio: the column always holds puffs of every age, and the
    /// storage order (k) has nothing to do with the distance to the camera, as in a particle
    /// system that recycles slots.
    fn age(&self, k: usize, time_sec: f32) -> f32 {
        let phase = (k as f32 * 0.618_034).fract();
        (time_sec + phase * self.lifetime_sec).rem_euclid(self.lifetime_sec)
    }

    /// Where a puff of this age and index is: rising, drifting with the wind (towards +x and
    /// +z, so the column recedes from and approaches the camera), wobbling.
    fn position(&self, k: usize, age: f32) -> Vec3 {
        let wobble = (k as f32 * 2.39996).sin() * 0.6 * (age / self.lifetime_sec);
        SOURCE + Vec3::new(0.35 * age + wobble, 0.55 * age, 0.3 * age - wobble)
    }

    /// Fills `frame` at `time_sec` (seconds, ≥ 0) with the column, the floor grid and the atlas
    /// (`atlas` is the texture holding [`SmokeFigure::atlas`]); `eye` is the camera position and
    /// `target` the point it looks at. Returns the note.
    pub fn draw(
        &mut self,
        frame: &mut Frame,
        atlas: TextureId,
        eye: Vec3,
        target: Vec3,
        time_sec: f32,
    ) -> Result<String, String> {
        let t = in_range("time", time_sec, 0.0, 1e5)?;
        frame.grid(8, 0.5);
        self.positions.clear();
        self.ages.clear();
        for k in 0..self.puffs {
            let age = self.age(k, t);
            self.ages.push(age);
            self.positions.push(self.position(k, age));
        }
        // Every square faces the camera: sorted by depth along the view, the order the depth
        // test sees (sorted by distance from the eye, 23 overlapping pairs at 4 s in the page's
        // view would come out in the wrong order, each a hard-edged notch).
        let forward = (target - eye).normalize_or_zero();
        sort_back_to_front(&mut self.order, &self.positions, eye, forward);
        frame.sprite_texture = Some(atlas);
        // The sorted column, then the same puffs COLUMN_GAP to the right in storage order.
        let sorted: Vec<u32> = self.order.iter().map(|&(_, k)| k).collect();
        for (ks, offset) in [
            (sorted, Vec3::ZERO),
            ((0..self.puffs as u32).collect(), COLUMN_GAP),
        ] {
            for k in ks {
                let (p, age) = (self.positions[k as usize], self.ages[k as usize]);
                let s = age / self.lifetime_sec;
                let uv = if self.animate_frames {
                    SMOKE_ATLAS.frame_at(s)
                } else {
                    SMOKE_ATLAS.frame(0)
                };
                // Fade in over the first tenth of the life, so puffs do not pop into view.
                let alpha = (s / 0.1).min(1.0);
                frame.sprites.push(SpriteInstance {
                    center: (p + offset).to_array(),
                    half_size: 0.25 + 0.4 * s,
                    uv: uv.to_array(),
                    color: Vec4::new(0.3, 0.3, 0.33, alpha).to_array(),
                });
            }
        }
        let top = SOURCE + Vec3::new(0.0, 0.55 * self.lifetime_sec + 0.9, 0.0);
        let mut names = vec![
            (top, "sorted back to front"),
            (top + COLUMN_GAP, "unsorted (storage order)"),
        ];
        // What the names must not cover: the puffs' centres (in both columns) and, when shown,
        // the atlas's board at 7 × 7 points.
        let mut solid: Vec<Vec3> = self
            .positions
            .iter()
            .flat_map(|&p| [p, p + COLUMN_GAP])
            .collect();
        if self.show_atlas {
            // Stand the square up (its z = −1 edge, texel row 0, at the top) facing +z.
            let model = Mat4::from_translation(ATLAS_AT)
                * Mat4::from_rotation_x(std::f32::consts::FRAC_PI_2)
                * Mat4::from_scale(Vec3::splat(ATLAS_HALF));
            frame.textured_quad(atlas, model, UvRect::FULL);
            // A dark board behind it: the light, half-transparent puffs show against it.
            let board = Mat4::from_translation(ATLAS_AT - Vec3::Z * 0.03)
                * Mat4::from_scale(Vec3::new(ATLAS_HALF + 0.04, ATLAS_HALF + 0.04, 0.01));
            frame.mesh(MeshId::CUBE, board, palette::DARK);
            names.push((
                ATLAS_AT + Vec3::new(-ATLAS_HALF, ATLAS_HALF + 0.2, 0.0),
                "the atlas: 16 frames",
            ));
            solid.extend((0..49).map(|k| {
                let s = |i: i32| (i as f32 / 3.0 - 1.0) * (ATLAS_HALF + 0.04);
                ATLAS_AT + Vec3::new(s(k % 7), s(k / 7), 0.0)
            }));
        }
        // Each name at the first place round its spot (right first, then further out), on the
        // last frame's view, that covers no puff's centre, the board, a line or a name placed
        // before it: orbited, a column's name lands on the other column's top, and the atlas's
        // on its board.
        let view = self
            .view
            .map(|(camera, size)| (camera.projection(size.x / size.y) * camera.view(), size));
        for (at, text) in names {
            let candidates = crate::draw::Label::around_dot(
                at,
                0.0,
                glam::Vec2::X,
                text,
                palette::DARK,
                0,
                10,
                8.0,
            );
            frame.first_clear_label_by(view, 0.0, candidates, super::clear_of(view, &solid));
        }
        // The atlas, both columns over their whole life (the wind carries a puff 0.35 m/s along
        // x and 0.3 m/s along z, ±0.6 m of wobble) and their labels stay in view.
        let reach = self.lifetime_sec;
        frame.keep_box_in_view(
            Vec3::new(ATLAS_AT.x - ATLAS_HALF, 0.0, SOURCE.z - 0.7),
            SOURCE
                + COLUMN_GAP
                + Vec3::new(0.35 * reach + 1.3, 0.55 * reach + 0.7, 0.3 * reach + 1.3),
        );
        Ok(format!(
            "{} living {} s and playing {} of the atlas's {} frames. Left: drawn back to front \
             (sorted by depth along the view every frame). Right: the same puffs in storage \
             order (unsorted): near puffs drawn early hide the ones behind them.",
            if self.puffs == 1 {
                "1 puff,".to_string()
            } else {
                format!("{} puffs, each", self.puffs)
            },
            format_number(self.lifetime_sec),
            if self.animate_frames {
                "all"
            } else {
                "the first"
            },
            SMOKE_ATLAS.frames(),
        ))
    }

    /// The positions drawn last frame, in puff order (tests).
    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }
}
