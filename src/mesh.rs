//! Triangle meshes built in code: positions, per-vertex normals, indices.
//!
//! Flat-shaded shapes (a box) repeat each corner once per face so that every face gets its own
//! normal; smooth shapes (a sphere) share vertices and average nothing: their normal is analytic.
//! Triangles wind counter-clockwise seen from outside (the front face in wgpu's default state).

use glam::Vec3;

/// An indexed triangle mesh with one normal per vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    pub positions: Vec<Vec3>,
    /// Unit normals, one per position.
    pub normals: Vec<Vec3>,
    /// Three indices per triangle, counter-clockwise seen from outside.
    pub indices: Vec<u32>,
}

impl MeshData {
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }
}

/// An axis-aligned box centred at the origin, `2 · half_extents` wide, 24 vertices, 12 triangles.
pub fn cuboid(half_extents: Vec3) -> MeshData {
    let mut mesh = MeshData::default();
    // Each face: its outward normal and two in-plane axes u, v with u × v = normal.
    for normal in [
        Vec3::X,
        Vec3::NEG_X,
        Vec3::Y,
        Vec3::NEG_Y,
        Vec3::Z,
        Vec3::NEG_Z,
    ] {
        let u = if normal.y.abs() > 0.5 {
            Vec3::Z * normal.y.signum()
        } else {
            Vec3::Y
        };
        let u = u.cross(normal).normalize(); // in-plane, perpendicular to both
        let v = normal.cross(u);
        let base = mesh.positions.len() as u32;
        for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            mesh.positions.push((normal + u * a + v * b) * half_extents);
            mesh.normals.push(normal);
        }
        mesh.indices
            .extend_from_slice(&[base, base + 1, base + 2, base, base + 2, base + 3]);
    }
    mesh
}

/// A UV sphere of the given radius with `segments` around Y and `rings` from pole to pole.
///
/// # Panics
/// If `segments < 3` or `rings < 2` (a programming error, not caller data).
pub fn uv_sphere(radius: f32, segments: u32, rings: u32) -> MeshData {
    assert!(
        segments >= 3 && rings >= 2,
        "a sphere needs at least 3 segments and 2 rings"
    );
    let mut mesh = MeshData::default();
    for ring in 0..=rings {
        let polar = std::f32::consts::PI * ring as f32 / rings as f32;
        for segment in 0..=segments {
            let azimuth = std::f32::consts::TAU * segment as f32 / segments as f32;
            let n = Vec3::new(
                polar.sin() * azimuth.sin(),
                polar.cos(),
                polar.sin() * azimuth.cos(),
            );
            mesh.positions.push(n * radius);
            mesh.normals.push(n);
        }
    }
    let row = segments + 1;
    for ring in 0..rings {
        for segment in 0..segments {
            let a = ring * row + segment;
            let b = a + row;
            // Skip the degenerate triangle at each pole.
            if ring != 0 {
                mesh.indices.extend_from_slice(&[a, b, a + 1]);
            }
            if ring != rings - 1 {
                mesh.indices.extend_from_slice(&[a + 1, b, b + 1]);
            }
        }
    }
    mesh
}

/// A sphere like [`uv_sphere`] but closed: one vertex per pole and no seam (the meridian where
/// [`uv_sphere`] repeats its first column of vertices), so that every vertex is shared by all the
/// triangles around it. For meshes that are deformed and get their normals from their faces
/// ([`crate::raster::vertex_normals`]): on a seam or a pole of a UV sphere each copy of a vertex
/// sees only some of its triangles, and the shading shows a crease. `2 + segments · (rings − 1)`
/// vertices.
///
/// # Panics
/// If `segments < 3` or `rings < 2` (a programming error, not caller data).
pub fn closed_sphere(radius: f32, segments: u32, rings: u32) -> MeshData {
    assert!(
        segments >= 3 && rings >= 2,
        "a sphere needs at least 3 segments and 2 rings"
    );
    let mut mesh = MeshData::default();
    let mut push = |n: Vec3| {
        mesh.positions.push(n * radius);
        mesh.normals.push(n);
    };
    push(Vec3::Y);
    for ring in 1..rings {
        let polar = std::f32::consts::PI * ring as f32 / rings as f32;
        for segment in 0..segments {
            let azimuth = std::f32::consts::TAU * segment as f32 / segments as f32;
            push(Vec3::new(
                polar.sin() * azimuth.sin(),
                polar.cos(),
                polar.sin() * azimuth.cos(),
            ));
        }
    }
    push(Vec3::NEG_Y);
    let bottom = mesh.positions.len() as u32 - 1;
    // Vertex `segment` (wrapping round) of inner ring `ring` (1 to rings − 1).
    let at = |ring: u32, segment: u32| 1 + (ring - 1) * segments + segment % segments;
    for s in 0..segments {
        // The same winding as uv_sphere: counter-clockwise seen from outside.
        mesh.indices.extend_from_slice(&[0, at(1, s), at(1, s + 1)]);
        for ring in 1..rings - 1 {
            let (a, a1) = (at(ring, s), at(ring, s + 1));
            let (b, b1) = (at(ring + 1, s), at(ring + 1, s + 1));
            mesh.indices.extend_from_slice(&[a, b, a1, a1, b, b1]);
        }
        mesh.indices
            .extend_from_slice(&[at(rings - 1, s + 1), at(rings - 1, s), bottom]);
    }
    mesh
}

/// Line segments (pairs of endpoints) of a square grid on the plane y = 0, centred at the origin,
/// with `cells` cells of size `spacing` along each side. An iterator, so that drawing the grid
/// every frame allocates nothing.
pub fn grid_lines(cells: u32, spacing: f32) -> impl Iterator<Item = [Vec3; 2]> {
    let half = cells as f32 * spacing * 0.5;
    (0..=cells).flat_map(move |i| {
        let x = -half + i as f32 * spacing;
        [
            [Vec3::new(x, 0.0, -half), Vec3::new(x, 0.0, half)],
            [Vec3::new(-half, 0.0, x), Vec3::new(half, 0.0, x)],
        ]
    })
}

/// A cone with its base (a disc of `radius`) on y = 0 and its tip at `(0, height, 0)`, with
/// `segments` sides. The sides are smooth-shaded (normals tilted by the cone's half angle) and the
/// base is flat. Arrow heads use it.
pub fn cone(radius: f32, height: f32, segments: u32) -> MeshData {
    let mut mesh = MeshData::default();
    let n = segments.max(3);
    let slope = radius / height; // the side normal leans up by atan(r / h)
    for i in 0..n {
        let a0 = i as f32 / n as f32 * std::f32::consts::TAU;
        let a1 = (i + 1) as f32 / n as f32 * std::f32::consts::TAU;
        let am = 0.5 * (a0 + a1);
        let rim = |a: f32| Vec3::new(radius * a.cos(), 0.0, -radius * a.sin());
        let side_normal = |a: f32| Vec3::new(a.cos(), slope, -a.sin()).normalize();
        // Side: rim a0, rim a1, tip (counter-clockwise seen from outside).
        let base = mesh.positions.len() as u32;
        mesh.positions
            .extend([rim(a0), rim(a1), Vec3::new(0.0, height, 0.0)]);
        mesh.normals
            .extend([side_normal(a0), side_normal(a1), side_normal(am)]);
        mesh.indices.extend([base, base + 1, base + 2]);
        // Base: centre, rim a1, rim a0 (seen from below).
        let base = mesh.positions.len() as u32;
        mesh.positions.extend([Vec3::ZERO, rim(a1), rim(a0)]);
        mesh.normals.extend([Vec3::NEG_Y; 3]);
        mesh.indices.extend([base, base + 1, base + 2]);
    }
    mesh
}
