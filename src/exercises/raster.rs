//! Exercises for lesson 00, "From triangles to pixels".
//!
//! Reference solutions: [`crate::raster::perspective_wgpu`], [`crate::raster::vertex_normals`] and
//! [`crate::raster::blinn_phong`]. Tick "use my exercise" in the lesson's figures to see yours at
//! work.

use super::{solution, Answer};
// What the stubs return; once every exercise here is done nothing uses it (no warning then).
#[allow(unused_imports)]
use super::NotDone;
use crate::raster::{self, Material};
use crate::Valid;
use glam::{Mat4, Vec3};

/// **Exercise 0.1: the perspective matrix (wgpu's depth range).**
///
/// Return the matrix that takes view space (camera at the origin, looking down −z) to clip space,
/// for a vertical field of view `fov_y_rad`, a width / height ratio `aspect` and the positive
/// distances `near` and `far` of the near and far planes, with depth in `[0, 1]` as wgpu (and
/// WebGPU, Direct3D, Vulkan) expect: `z = −near` must land on depth 0, `z = −far` on depth 1.
/// ```text
/// F = 1 / tan(fov_y / 2)
///     ⎡F/aspect  0       0              0         ⎤
/// P = ⎢   0      F       0              0         ⎥
///     ⎢   0      0   far/(near−far)  far·near/(near−far) ⎥
///     ⎣   0      0      −1              0         ⎦
/// ```
/// Hints: glam's `Mat4::from_cols` takes *columns* (`Vec4::new(...)` each); the −1 sits in the
/// third column, fourth row, so that `w_clip = −z`, the distance in front of the camera. The
/// course's OpenGL form differs in the third row only (`(f+n)/(n−f)` and `2fn/(n−f)`); check
/// yours by projecting `(0, 0, −near)` and `(0, 0, −far)`.
pub fn perspective_matrix(fov_y_rad: f32, aspect: f32, near: f32, far: f32) -> Answer<Mat4> {
    solution!(raster::perspective_wgpu(fov_y_rad, aspect, near, far).unwrap_or(Mat4::NAN));
    let _ = (fov_y_rad, aspect, near, far);
    Err(NotDone)
}

/// **Exercise 0.2: averaged vertex normals of an indexed mesh.**
///
/// `positions` holds each vertex once; `indices` holds three indices per triangle, counter-clockwise
/// seen from outside. Return one unit normal per position: the average of the unit normals of
/// the triangles that use the vertex, each triangle counting once whatever its size.
/// ```text
/// n̂_face = normalize((b − a) × (c − a))            (a, b, c: the triangle's corners, in order)
/// n_v    = normalize( Σ n̂_face over the triangles that use v )
/// ```
/// Hints: start from `vec![Vec3::ZERO; positions.len()]`, loop over `indices.chunks_exact(3)`,
/// add each triangle's unit normal to its three corners, then normalise every sum. A vertex that
/// no triangle uses has no normal, and a zero-area triangle has none either: use
/// `normalize_or_zero`, which gives `Vec3::ZERO` instead of NaN.
/// The indices are valid (the figures and the grader check them first).
pub fn vertex_normals(positions: &[Vec3], indices: &[u32]) -> Answer<Vec<Vec3>> {
    solution!({
        let mut out = vec![Vec3::ZERO; positions.len()];
        raster::vertex_normals(positions, indices, &mut out)
            .map(|()| out)
            .unwrap_or_default()
    });
    let _ = (positions, indices);
    Err(NotDone)
}

/// **Exercise 0.3: the Blinn-Phong colour of one fragment.**
///
/// `n` is the unit surface normal, `l` the unit direction from the surface to the light, `v` the
/// unit direction from the surface to the eye, `color` the surface colour (linear RGB), `weights`
/// = `[k_a, k_d, k_s]` and `shininess` the exponent `s`. The light is white, of intensity 1.
/// ```text
/// h = (l + v) / |l + v|                                  the halfway vector
/// colour = k_a C + k_d C max(n·l, 0) + k_s max(n·h, 0)^s (1, 1, 1)
/// ```
/// The specular term is 0 when the light is behind the surface (`n·l ≤ 0`), even if `n·h > 0`.
/// Hints: `Vec3::normalize_or_zero` (when `l = −v`, `l + v` is zero), `f32::powf`, `Vec3::splat`.
pub fn blinn_phong(
    n: Vec3,
    l: Vec3,
    v: Vec3,
    color: Vec3,
    weights: [f32; 3],
    shininess: f32,
) -> Answer<Vec3> {
    solution!(raster::blinn_phong(
        n,
        l,
        v,
        &material(color, weights, shininess)
    ));
    let _ = (n, l, v, color, weights, shininess);
    Err(NotDone)
}

/// The [`Material`] of exercise 0.3's arguments.
pub fn material(color: Vec3, [ambient, diffuse, specular]: [f32; 3], shininess: f32) -> Material {
    Material {
        color,
        ambient,
        diffuse,
        specular,
        shininess,
    }
}

fn unit(rng: &mut super::grade::Rng) -> Vec3 {
    loop {
        let v = rng.vec3(-1.0, 1.0);
        if v.length() > 0.1 {
            return v.normalize();
        }
    }
}

fn vec_close(a: &Vec3, b: &Vec3, eps: f32) -> bool {
    (*a - *b).abs().max_element() <= eps
}

/// Grades this file's exercises against the reference on edge cases and random inputs.
pub(super) fn grade(rng: &mut super::grade::Rng) -> Vec<super::grade::Report> {
    use super::grade::{check_cases, check_list_cases, mat4_close, RANDOM};
    use crate::raster::storage::{tetrahedron, uv_sphere_indexed};
    const L00: &str = "00-triangles-to-pixels";

    // 0.1: typical, narrow and wide views, tall and wide canvases, near close to far, a huge range.
    let mut frusta = vec![
        (
            "a typical camera: 60°, 16:9, 0.1 to 100",
            (1.047, 16.0 / 9.0, 0.1, 100.0),
        ),
        (
            "a square canvas, 90°: F = 1",
            (std::f32::consts::FRAC_PI_2, 1.0, 1.0, 10.0),
        ),
        ("a narrow telephoto view", (0.1, 1.5, 5.0, 500.0)),
        (
            "a wide view, taller than wide (aspect < 1)",
            (2.5, 0.6, 0.05, 20.0),
        ),
        ("near close to far: the depth row", (0.8, 1.0, 2.0, 2.5)),
        ("a huge far / near ratio", (1.0, 1.0, 0.01, 1e5)),
    ];
    for _ in 0..200 {
        let near = rng.range(0.01, 5.0);
        frusta.push((
            RANDOM,
            (
                rng.range(0.1, 2.8),
                rng.range(0.3, 3.0),
                near,
                near + rng.range(0.1, 1000.0),
            ),
        ));
    }
    let perspective = check_cases(
        L00,
        "perspective_matrix",
        ["fov_y_rad", "aspect", "near", "far"],
        &frusta,
        |&(fov, a, n, f)| perspective_matrix(fov, a, n, f),
        |&(fov, a, n, f)| raster::perspective_wgpu(fov, a, n, f).unwrap_or(Mat4::NAN),
        |a, b| mat4_close(a, b, 1e-4),
    );

    // 0.2: the tetrahedron, a flat strip, a sphere, triangles of very different areas (unit face
    // normals, not area-weighted), a degenerate triangle, a vertex no triangle uses, random
    // soups of triangles.
    let (tp, ti) = tetrahedron();
    let (sp, si) = uv_sphere_indexed(8, 5);
    let strip: Vec<Vec3> = (0..6)
        .map(|k| Vec3::new((k / 2) as f32, 0.3 * (k / 2) as f32, (k % 2) as f32))
        .collect();
    let strip_idx = vec![0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4];
    // A fan around vertex 0: one big triangle and one tiny one, at right angles.
    let fan = vec![
        Vec3::ZERO,
        Vec3::new(4.0, 0.0, 0.0),
        Vec3::new(0.0, 0.0, -4.0),
        Vec3::new(0.0, 0.1, 0.0),
    ];
    let fan_idx = vec![0, 1, 2, 0, 3, 1];
    let mut meshes = vec![
        (
            "a tetrahedron: each corner points away from the centre",
            (tp, ti),
        ),
        (
            "a flat strip: every normal equals the face normal",
            (strip, strip_idx),
        ),
        ("a sphere: close to the radial direction", (sp, si)),
        (
            "a big and a tiny triangle: each counts once, whatever its area",
            (fan, fan_idx),
        ),
        (
            "a zero-area triangle adds nothing (normalize_or_zero)",
            (
                vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::X * 2.0],
                vec![0, 1, 2, 0, 1, 3],
            ),
        ),
        (
            "a vertex that no triangle uses: Vec3::ZERO",
            (vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z], vec![0, 1, 2]),
        ),
    ];
    for _ in 0..50 {
        let n = 3 + rng.below(10);
        let positions: Vec<Vec3> = (0..n).map(|_| rng.vec3(-2.0, 2.0)).collect();
        let indices: Vec<u32> = (0..3 * (1 + rng.below(12)))
            .map(|_| rng.below(n) as u32)
            .collect();
        meshes.push((RANDOM, (positions, indices)));
    }
    let normals = check_list_cases(
        L00,
        "vertex_normals",
        ["positions", "indices"],
        &meshes,
        |(p, i)| vertex_normals(p, i),
        |(p, i)| {
            let mut out = vec![Vec3::ZERO; p.len()];
            raster::vertex_normals(p, i, &mut out).valid("the grader's meshes are valid");
            out
        },
        |a, b| vec_close(a, b, 2e-4),
    );

    // 0.3: head-on light and eye, the light behind the surface (no specular even when n·h > 0),
    // the eye on the light's mirror side, s = 1 and s = 0, l = −v, random.
    let c = Vec3::new(0.8, 0.3, 0.1);
    let k = [0.1, 0.7, 0.5];
    let tilted = Vec3::new(0.6, 0.8, 0.0);
    let mut fragments = vec![
        (
            "light and eye along the normal: every term at its peak",
            (Vec3::Y, Vec3::Y, Vec3::Y, c, k, 32.0),
        ),
        (
            "light behind the surface: ambient only, no specular even though n·h > 0",
            (
                Vec3::Y,
                Vec3::new(0.8, -0.6, 0.0),
                Vec3::new(-0.6, 0.8, 0.0),
                c,
                k,
                8.0,
            ),
        ),
        (
            "eye at the mirror direction of the light",
            (Vec3::Y, tilted, Vec3::new(-0.6, 0.8, 0.0), c, k, 16.0),
        ),
        (
            "eye off the highlight: the halfway vector, not the mirror",
            (Vec3::Y, tilted, Vec3::Z, c, k, 4.0),
        ),
        (
            "shininess 1",
            (Vec3::Y, tilted, Vec3::new(0.0, 0.6, 0.8), c, k, 1.0),
        ),
        (
            "light opposite the eye (l = −v): normalise l + v safely",
            (Vec3::Z, Vec3::Z, -Vec3::Z, c, k, 8.0),
        ),
        (
            "only ambient",
            (Vec3::X, Vec3::Y, Vec3::Z, c, [0.3, 0.0, 0.0], 8.0),
        ),
    ];
    for _ in 0..200 {
        let color = Vec3::new(
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
        );
        let w = [
            rng.range(0.0, 0.5),
            rng.range(0.0, 1.0),
            rng.range(0.0, 1.0),
        ];
        fragments.push((
            RANDOM,
            (
                unit(rng),
                unit(rng),
                unit(rng),
                color,
                w,
                rng.range(1.0, 128.0),
            ),
        ));
    }
    let shading = check_cases(
        L00,
        "blinn_phong",
        ["n", "l", "v", "color", "weights", "shininess"],
        &fragments,
        |&(n, l, v, c, w, s)| blinn_phong(n, l, v, c, w, s),
        |&(n, l, v, c, w, s)| raster::blinn_phong(n, l, v, &material(c, w, s)),
        |a, b| vec_close(a, b, 1e-4),
    );

    vec![perspective, normals, shading]
}
