//! Two ways to store the same triangles.
//!
//! A **triangle soup** lists three corner positions per triangle: simple, but a corner shared by
//! `k` triangles is stored `k` times. An **indexed mesh** stores each position once (the geometry)
//! and three indices per triangle (the connectivity), so shared corners are shared in memory too
//! and a program can find a vertex's neighbours.
//! ```text
//! soup bytes    = 3 T · 12                (3 corners of 3 f32 per triangle)
//! indexed bytes = V · 12 + 3 T · 4        (positions once, u32 indices)
//! ```
//! For a closed mesh of small triangles `T ≈ 2V` (Euler's formula), so the soup stores about six
//! copies of every position and the indexed form takes about 12V + 24V = 36V bytes against 72V.

use super::RasterError;
use glam::Vec3;

/// Bytes of one position (three `f32`).
pub const POSITION_BYTES: usize = 12;
/// Bytes of one index (`u32`).
pub const INDEX_BYTES: usize = 4;

/// What each storage costs for `V` distinct vertices and `T` triangles (positions only).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshSizes {
    pub triangles: usize,
    /// Distinct positions `V` (the indexed form's vertex count).
    pub vertices: usize,
    /// Positions stored by the soup: `3 T`.
    pub soup_positions: usize,
    pub soup_bytes: usize,
    /// Indices stored by the indexed form: `3 T`.
    pub indices: usize,
    pub indexed_bytes: usize,
}

/// The sizes of both storages for `vertices` distinct positions and `triangles` triangles.
pub fn mesh_sizes(vertices: usize, triangles: usize) -> MeshSizes {
    MeshSizes {
        triangles,
        vertices,
        soup_positions: 3 * triangles,
        soup_bytes: 3 * triangles * POSITION_BYTES,
        indices: 3 * triangles,
        indexed_bytes: vertices * POSITION_BYTES + 3 * triangles * INDEX_BYTES,
    }
}

/// A regular tetrahedron inscribed in the unit sphere: 4 positions, 4 triangles, counter-clockwise
/// seen from outside.
pub fn tetrahedron() -> (Vec<Vec3>, Vec<u32>) {
    let s = 1.0 / 3f32.sqrt();
    let positions = vec![
        Vec3::new(1.0, 1.0, 1.0) * s,
        Vec3::new(1.0, -1.0, -1.0) * s,
        Vec3::new(-1.0, 1.0, -1.0) * s,
        Vec3::new(-1.0, -1.0, 1.0) * s,
    ];
    let indices = vec![0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2];
    (positions, indices)
}

/// Checks that `indices` are whole triangles that point into `vertex_count` positions.
pub fn check_indices(indices: &[u32], vertex_count: usize) -> Result<(), RasterError> {
    if !indices.len().is_multiple_of(3) {
        return Err(RasterError::NotTriangles(indices.len()));
    }
    match indices.iter().find(|&&i| i as usize >= vertex_count) {
        Some(&index) => Err(RasterError::IndexOutOfRange {
            index,
            vertices: vertex_count,
        }),
        None => Ok(()),
    }
}

/// The triangle soup of an indexed mesh: three positions per triangle, in order.
pub fn to_soup(positions: &[Vec3], indices: &[u32]) -> Result<Vec<Vec3>, RasterError> {
    check_indices(indices, positions.len())?;
    Ok(indices.iter().map(|&i| positions[i as usize]).collect())
}

/// Indexed geometry from a soup: positions that are exactly equal become one vertex. Returns the
/// distinct positions (in order of first appearance) and three indices per triangle.
///
/// Quadratic in the number of distinct positions; meant for the lesson's small meshes.
pub fn weld(soup: &[Vec3]) -> Result<(Vec<Vec3>, Vec<u32>), RasterError> {
    if !soup.len().is_multiple_of(3) {
        return Err(RasterError::NotTriangles(soup.len()));
    }
    let mut positions: Vec<Vec3> = Vec::new();
    let mut indices = Vec::with_capacity(soup.len());
    for p in soup {
        let i = match positions.iter().position(|q| q == p) {
            Some(i) => i,
            None => {
                positions.push(*p);
                positions.len() - 1
            }
        };
        indices.push(i as u32);
    }
    Ok((positions, indices))
}

/// A closed UV sphere of radius 1 with every position stored once: one vertex per pole and
/// `segments` around each of the `rings − 1` inner rings, so `V = 2 + segments (rings − 1)` and
/// `T = 2 segments (rings − 1)`. (The renderer's [`crate::mesh::uv_sphere`] repeats the seam and
/// the poles, which texture coordinates need; this one does not.)
///
/// # Panics
/// If `segments < 3` or `rings < 2` (a programming error; the figures validate their input).
pub fn uv_sphere_indexed(segments: u32, rings: u32) -> (Vec<Vec3>, Vec<u32>) {
    assert!(
        segments >= 3 && rings >= 2,
        "a sphere needs 3 segments, 2 rings"
    );
    let mut positions = vec![Vec3::Y];
    for ring in 1..rings {
        let polar = std::f32::consts::PI * ring as f32 / rings as f32;
        for s in 0..segments {
            let azimuth = std::f32::consts::TAU * s as f32 / segments as f32;
            positions.push(Vec3::new(
                polar.sin() * azimuth.sin(),
                polar.cos(),
                polar.sin() * azimuth.cos(),
            ));
        }
    }
    positions.push(Vec3::NEG_Y);
    let south = positions.len() as u32 - 1;
    let at = |ring: u32, s: u32| 1 + (ring - 1) * segments + s % segments;
    let mut indices = Vec::new();
    for s in 0..segments {
        indices.extend([0, at(1, s), at(1, s + 1)]);
        indices.extend([south, at(rings - 1, s + 1), at(rings - 1, s)]);
    }
    for ring in 1..rings - 1 {
        for s in 0..segments {
            let (a, b) = (at(ring, s), at(ring, s + 1));
            let (c, d) = (at(ring + 1, s), at(ring + 1, s + 1));
            indices.extend([a, c, d, a, d, b]);
        }
    }
    (positions, indices)
}
