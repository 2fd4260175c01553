//! Lesson 05 core: gradient noise and its fractal sums, for terrains and procedural textures.
//!
//! Perlin noise is a smooth pseudo-random function: a hash gives every integer lattice point a
//! gradient; inside a cell, each corner contributes the linear ramp `g · (p − corner)`, and the
//! ramps are blended with the [`fade`] curve. The result is zero at every lattice point, smooth
//! (C²), deterministic, and looks random with one dominant feature size (one cell). Sums of
//! scaled copies ([`Fractal`]) add detail at every scale.
//!
//! - [`perlin`]: Ken Perlin's improved noise (2002) in 1D, 2D, 3D, faithful to his reference,
//!   with analytic derivatives, seeded permutations and the double-precision transcription.
//! - [`fractal`]: fractal sum (fBm), ridge, inverted ridge, turbulence, marble.
//! - [`texture`]: marble, wood and clouds into RGBA buffers.
//! - [`simplex`]: simplex noise in 2D and 3D (Gustavson's `simplexnoise1234`), for comparison.
//! - [`fractals`]: Koch snowflake and Sierpinski triangle (the course's introduction to
//!   self-similar detail).
//!
//! Lesson: lessons/05-noise.

pub mod fractal;
pub mod fractals;
pub mod perlin;
pub mod simplex;
pub mod texture;

pub use fractal::{marble2, turbulence2, Fractal, Shape, MAX_N};
pub use perlin::{
    cell2, cell2_with_derivative, fade, fade_derivative, fade_second_derivative, grad1, grad2,
    noise3_f64, Permutation, GRAD3, PERLIN_PERMUTATION,
};
