use inbetween::mesh::*;
use std::collections::HashMap;

/// Sum over triangles of (face normal · centroid): positive when they wind outwards.
fn outward(mesh: &MeshData) -> Vec<f32> {
    mesh.indices
        .chunks(3)
        .map(|t| {
            let [a, b, c] = [0, 1, 2].map(|k| mesh.positions[t[k] as usize]);
            (b - a).cross(c - a).dot(a + b + c)
        })
        .collect()
}

#[test]
fn the_closed_sphere_is_watertight_without_seam_and_winds_like_the_uv_sphere() {
    let (segments, rings) = (12, 7);
    let mesh = closed_sphere(2.0, segments, rings);
    assert_eq!(mesh.positions.len(), (2 + segments * (rings - 1)) as usize);
    assert_eq!(mesh.triangle_count(), (2 * segments * (rings - 1)) as usize);
    // Closed: every edge is used once in each direction.
    let mut edges = HashMap::new();
    for t in mesh.indices.chunks(3) {
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
        }
    }
    for (&(a, b), &n) in &edges {
        assert_eq!(n, 1, "edge {a}-{b} used {n} times in one direction");
        assert_eq!(edges.get(&(b, a)), Some(&1), "edge {a}-{b} has no twin");
    }
    // No two vertices at the same place (no seam), all on the sphere.
    for (i, p) in mesh.positions.iter().enumerate() {
        assert!((p.length() - 2.0).abs() < 1e-5);
        assert!((mesh.normals[i] - *p / 2.0).length() < 1e-5);
        for q in &mesh.positions[i + 1..] {
            assert!(p.distance(*q) > 1e-3, "two vertices at {p}");
        }
    }
    assert!(outward(&mesh).iter().all(|&d| d > 0.0));
    assert!(outward(&uv_sphere(2.0, segments, rings))
        .iter()
        .all(|&d| d > 0.0));
}
