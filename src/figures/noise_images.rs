//! Lesson 05's figure "Perlin, simplex, and the GPU": the same window of noise as three images,
//! Perlin noise and simplex noise computed on the CPU, and one computed by a WGSL fragment shader
//! (`src/render/shaders/noise.wgsl`) with the same permutation. The GPU's image is read back and
//! compared texel by texel with the CPU's ([`NoiseImages::compare_gpu`]).

use super::{format_number, in_range, palette, Frame};
use crate::figures::noise::permutation_for_seed;
use crate::noise::Permutation;
use crate::texture::{TextureId, UvRect};
use glam::{Mat4, Vec3};

/// Texels per side of each image (and of the GPU image that is read back).
pub const IMAGE_SIZE: usize = 128;
/// The largest difference allowed between a GPU texel and the CPU value, in noise units: the
/// GPU writes 16-bit values (a step of 3·10⁻⁵) and may round or fuse operations differently
/// (about 10⁻⁶ each at these coordinates).
pub const GPU_TOLERANCE: f32 = 2e-4;

/// What a GPU image shows: plain data the web layer hands to the renderer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpuNoiseSpec {
    /// Noise coordinates of the top-left corner of the image.
    pub origin: [f32; 2],
    /// Noise units per texel (rows run downwards, +y).
    pub step: [f32; 2],
    /// The slice of Perlin's 3D noise (0: the 2D noise).
    pub z: f32,
    pub simplex: bool,
}

/// The result of comparing the GPU's image with the CPU.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpuComparison {
    /// What the GPU computed.
    pub kind: NoiseKind,
    pub texels: usize,
    pub max_error: f32,
    /// Texel `(i, j)` where the difference is largest.
    pub worst: (usize, usize),
}

impl GpuComparison {
    pub fn matches(&self) -> bool {
        self.max_error <= GPU_TOLERANCE
    }

    pub fn note(&self, backend: &str) -> String {
        format!(
            "GPU check ({backend}, {}): the shader's image, read back, {} the CPU's at all {} \
             texels: largest difference {} at texel ({}, {}) (tolerance {}).",
            match self.kind {
                NoiseKind::Perlin => "Perlin",
                NoiseKind::Simplex => "2D simplex",
            },
            if self.matches() {
                "matches"
            } else {
                "DIFFERS from"
            },
            self.texels,
            format_number(self.max_error),
            self.worst.0,
            self.worst.1,
            format_number(GPU_TOLERANCE),
        )
    }
}

/// Perlin or simplex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoiseKind {
    Perlin,
    Simplex,
}

/// The figure's state.
pub struct NoiseImages {
    perm: Permutation,
    seed: u32,
    /// Noise cells across an image.
    cells: f32,
    gpu_kind: NoiseKind,
    lattice: bool,
    images: [Vec<u8>; 2],
    dirty: bool,
    gpu_dirty: bool,
}

impl Default for NoiseImages {
    fn default() -> Self {
        Self::new()
    }
}

/// Where the three squares stand (x of their centres).
const PLACES: [f32; 3] = [-2.2, 0.0, 2.2];

/// A square's model matrix: the quad's `[−1, 1]²` of the xz plane stood up in the plane z = 0,
/// facing +z (the page's camera looks along −z), its z = −1 edge (texel row 0) at the top, and
/// centred at `x`. Seen face on, the images are as large as the canvas's width allows and
/// square on screen.
pub fn image_model(x: f32) -> Mat4 {
    Mat4::from_translation(Vec3::new(x, 0.0, 0.0))
        * Mat4::from_rotation_x(std::f32::consts::FRAC_PI_2)
}
/// Width of the lattice lines in CSS pixels at up to 6 cells across: wide enough to read over the
/// noise's greys. Finer lattices get thinner lines ([`lattice_px`]).
pub const LATTICE_PX: f32 = 2.0;

/// The lattice lines' width for `cells` cells across: [`LATTICE_PX`] up to 6 cells, then
/// thinner down to 1 px from 12 cells, so that a fine lattice (simplex noise draws three
/// directions of lines) does not cover the image it explains.
pub fn lattice_px(cells: f32) -> f32 {
    (LATTICE_PX * 6.0 / cells).clamp(1.0, LATTICE_PX)
}

/// The most cells across that the lattices cover, from the image's top-left corner: at 25 cells
/// across, lines over the whole image (three directions for simplex noise) hide the noise.
pub const LATTICE_CELLS: f32 = 6.0;

impl NoiseImages {
    pub fn new() -> Self {
        let image = || vec![0; 4 * IMAGE_SIZE * IMAGE_SIZE];
        let mut s = Self {
            perm: Permutation::perlin(),
            seed: 0,
            cells: 6.0,
            gpu_kind: NoiseKind::Perlin,
            lattice: false,
            images: [image(), image()],
            dirty: true,
            gpu_dirty: true,
        };
        s.regenerate();
        s
    }

    /// Cells across an image (1 to 32) and the seed (0: Perlin's table).
    pub fn set_params(&mut self, cells: f32, seed: f32) -> Result<(), String> {
        let cells = in_range("cells", cells, 1.0, 32.0)?;
        let seed = in_range("seed", seed, 0.0, 1e6)?;
        if seed.fract() != 0.0 {
            return Err(format!("seed must be a whole number, got {seed}"));
        }
        if seed as u32 != self.seed {
            self.seed = seed as u32;
            self.perm = permutation_for_seed(self.seed);
        }
        self.cells = cells;
        self.regenerate();
        Ok(())
    }

    pub fn set_gpu_kind(&mut self, kind: NoiseKind) {
        self.gpu_kind = kind;
        self.gpu_dirty = true;
    }

    pub fn set_lattice(&mut self, on: bool) {
        self.lattice = on;
    }

    /// The noise value at texel `(i, j)` (row `j` from the top), as the shader computes it:
    /// 2D Perlin noise (the reference's 3D noise on the plane z = 0) or 2D simplex noise.
    pub fn value(&self, kind: NoiseKind, i: usize, j: usize) -> f32 {
        let s = self.spec();
        let x = s.origin[0] + (i as f32 + 0.5) * s.step[0];
        let y = s.origin[1] + (j as f32 + 0.5) * s.step[1];
        match kind {
            NoiseKind::Perlin => self.perm.noise3(x, y, 0.0),
            NoiseKind::Simplex => self.perm.simplex2(x, y),
        }
    }

    fn regenerate(&mut self) {
        for (k, kind) in [NoiseKind::Perlin, NoiseKind::Simplex]
            .into_iter()
            .enumerate()
        {
            for j in 0..IMAGE_SIZE {
                for i in 0..IMAGE_SIZE {
                    let v = self.value(kind, i, j);
                    let b = (255.0 * (0.5 + 0.5 * v).clamp(0.0, 1.0)).round() as u8;
                    let at = 4 * (j * IMAGE_SIZE + i);
                    self.images[k][at..at + 4].copy_from_slice(&[b, b, b, 255]);
                }
            }
        }
        self.dirty = true;
        self.gpu_dirty = true;
    }

    /// The CPU images (Perlin, simplex): `IMAGE_SIZE²` RGBA texels, grey `0.5 + 0.5 n`.
    pub fn images(&self) -> [&[u8]; 2] {
        [&self.images[0], &self.images[1]]
    }

    /// True once after the CPU images changed.
    pub fn take_dirty(&mut self) -> bool {
        std::mem::take(&mut self.dirty)
    }

    /// True once after what the GPU must draw changed.
    pub fn take_gpu_dirty(&mut self) -> bool {
        std::mem::take(&mut self.gpu_dirty)
    }

    /// What the GPU draws (its simplex noise is the 2D one, as the CPU image's).
    pub fn spec(&self) -> GpuNoiseSpec {
        let step = self.cells / IMAGE_SIZE as f32;
        GpuNoiseSpec {
            origin: [0.0, 0.0],
            step: [step, step],
            z: 0.0,
            simplex: self.gpu_kind == NoiseKind::Simplex,
        }
    }

    /// Compares the GPU's read-back image (16-bit values packed in red, high byte, and green,
    /// low byte) with the CPU's noise at every texel.
    pub fn compare_gpu(&self, rgba: &[u8]) -> Result<GpuComparison, String> {
        crate::texture::validate_rgba(IMAGE_SIZE as u32, IMAGE_SIZE as u32, rgba)?;
        let mut out = GpuComparison {
            kind: self.gpu_kind,
            texels: IMAGE_SIZE * IMAGE_SIZE,
            max_error: 0.0,
            worst: (0, 0),
        };
        for j in 0..IMAGE_SIZE {
            for i in 0..IMAGE_SIZE {
                let at = 4 * (j * IMAGE_SIZE + i);
                let q = (rgba[at] as u32) << 8 | rgba[at + 1] as u32;
                let gpu = 2.0 * (q as f32 / 65535.0) - 1.0;
                let cpu = self.value(self.gpu_kind, i, j);
                let e = (gpu - cpu).abs();
                if e > out.max_error || e.is_nan() {
                    out.max_error = if e.is_nan() { f32::INFINITY } else { e };
                    out.worst = (i, j);
                }
            }
        }
        Ok(out)
    }

    /// The permutation's 256 entries, for the shader.
    pub fn table(&self) -> &[u8] {
        self.perm.table()
    }

    /// Draws the three squares (`textures`: CPU Perlin, CPU simplex, GPU) with labels and,
    /// optionally, each noise's lattice over them. Returns the note.
    pub fn draw(&self, frame: &mut Frame, textures: [TextureId; 3]) -> String {
        let names = [
            "Perlin (CPU)".to_string(),
            "simplex (CPU)".to_string(),
            match self.gpu_kind {
                NoiseKind::Perlin => "Perlin (GPU)",
                NoiseKind::Simplex => "simplex (GPU)",
            }
            .to_string(),
        ];
        // The three squares and their labels stay whole at any canvas size.
        frame.keep_box_in_view(Vec3::new(-3.2, -1.3, 0.0), Vec3::new(3.2, 1.0, 0.0));
        // Images facing the camera: a drag pans them rather than turning them edge-on.
        frame.flat = true;
        for ((&x, texture), name) in PLACES.iter().zip(textures).zip(&names) {
            frame.textured_quad(texture, image_model(x), UvRect::FULL);
            // Labels read rightwards from their anchor: start each at its square's left edge,
            // under the square.
            frame.label(Vec3::new(x - 1.0, -1.2, 0.0), name.as_str(), palette::DARK);
        }
        let mut part = String::new();
        if self.lattice {
            self.draw_lattices(frame);
            if self.cells > LATTICE_CELLS {
                part = format!(
                    " The lattices cover the top-left {0} × {0} cells, so the noise shows beside them{1}.",
                    LATTICE_CELLS,
                    // Past 12 cells across the lines are 1 px and the cells a few pixels wide:
                    // the lattice reads as a solid patch (a flat figure zooms in no further
                    // than its fit, `OrbitCamera::clamp_pan`).
                    if self.cells > 12.0 {
                        "; a cell is a few pixels across and the lines run together: at 12 cells or fewer they stand apart"
                    } else {
                        ""
                    }
                );
            }
        }
        format!(
            "{} noise cells across each image, {}. Perlin's cells are squares, simplex noise's are \
             triangles (a skewed grid); Perlin noise is 0 at every lattice point.{part}",
            format_number(self.cells),
            if self.seed == 0 {
                "Perlin's permutation".to_string()
            } else {
                format!("the permutation of seed {}", self.seed)
            },
        )
    }

    /// Lattice lines over the first two squares, [`lattice_px`] wide: Perlin's square cells and simplex
    /// noise's triangles (a square grid in skewed coordinates, unskewed), clipped to the image's
    /// top-left [`LATTICE_CELLS`] cells square.
    fn draw_lattices(&self, frame: &mut Frame) {
        let lift = 0.01;
        let width = lattice_px(self.cells);
        let span = self.cells.min(LATTICE_CELLS);
        // Image point (x, y) in noise units (y down the image) -> world on the square at `cx`,
        // just in front of it.
        let world = |cx: f32, x: f32, y: f32| {
            Vec3::new(
                cx - 1.0 + 2.0 * x / self.cells,
                1.0 - 2.0 * y / self.cells,
                lift,
            )
        };
        let n = span.ceil() as i32;
        for k in 0..=n {
            let t = (k as f32).min(span);
            frame.wide_line(
                world(PLACES[0], t, 0.0),
                world(PLACES[0], t, span),
                palette::ORANGE,
                width,
            );
            frame.wide_line(
                world(PLACES[0], 0.0, t),
                world(PLACES[0], span, t),
                palette::ORANGE,
                width,
            );
        }
        // Simplex: lines i = const, j = const and i − j = const of the skewed grid, clipped to
        // the square [0, cells]² by sampling (short segments keep it simple and exact enough).
        let g2 = (3.0 - 3f32.sqrt()) / 6.0;
        let unskew = |i: f32, j: f32| {
            let t = (i + j) * g2;
            (i - t, j - t)
        };
        let inside = |(x, y): (f32, f32)| (0.0..=span).contains(&x) && (0.0..=span).contains(&y);
        let m = (2.0 * span).ceil() as i32 + 2;
        let steps = 4 * m;
        let mut segment = |a: (f32, f32), b: (f32, f32)| {
            if inside(a) && inside(b) {
                frame.wide_line(
                    world(PLACES[1], a.0, a.1),
                    world(PLACES[1], b.0, b.1),
                    palette::TEAL,
                    width,
                );
            }
        };
        for c in -m..=m {
            for s in -steps..steps {
                let (u0, u1) = (s as f32 * 0.5, (s + 1) as f32 * 0.5);
                let c = c as f32;
                segment(unskew(c, u0), unskew(c, u1));
                segment(unskew(u0, c), unskew(u1, c));
                segment(unskew(u0 + c, u0), unskew(u1 + c, u1));
            }
        }
    }
}
