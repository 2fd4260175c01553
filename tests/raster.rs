//! Lesson 00 core (src/raster): mesh storage, the perspective matrix, normals, shading.
//! Reference values for the projection come from glam's `camera::rh::proj::directx::perspective` (Direct3D/wgpu depth)
//! and `opengl::perspective` (OpenGL depth), an independent, widely used implementation.

use glam::{Mat3, Mat4, Vec3};
use inbetween::raster::shading::{light_from_image, sphere_image, Term};
use inbetween::raster::storage::uv_sphere_indexed;
use inbetween::raster::*;

fn close(a: f32, b: f32, eps: f32) -> bool {
    (a - b).abs() <= eps * (1.0 + a.abs().max(b.abs()))
}

fn mat_close(a: Mat4, b: Mat4, eps: f32) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array())
        .all(|(x, y)| close(*x, y, eps))
}

#[test]
fn sizes_of_soup_and_indexed_forms() {
    let (p, i) = tetrahedron();
    let s = mesh_sizes(p.len(), i.len() / 3);
    assert_eq!((s.vertices, s.triangles), (4, 4));
    assert_eq!(s.soup_bytes, 4 * 3 * 12);
    assert_eq!(s.indexed_bytes, 4 * 12 + 12 * 4);
    // A closed sphere: Euler's formula V − E + F = 2 with E = 3T/2, and T ≈ 2V.
    let (p, i) = uv_sphere_indexed(24, 12);
    let (v, t) = (p.len() as i64, i.len() as i64 / 3);
    assert_eq!(v - 3 * t / 2 + t, 2);
    let s = mesh_sizes(p.len(), i.len() / 3);
    assert!(s.soup_bytes as f32 / s.indexed_bytes as f32 > 1.9);
}

#[test]
fn soup_and_weld_round_trip() {
    let (p, i) = tetrahedron();
    let soup = to_soup(&p, &i).unwrap();
    assert_eq!(soup.len(), 12);
    let (p2, i2) = weld(&soup).unwrap();
    assert_eq!(p2.len(), 4);
    assert_eq!(to_soup(&p2, &i2).unwrap(), soup);
    assert!(matches!(
        to_soup(&p, &[0, 1, 9]),
        Err(RasterError::IndexOutOfRange { index: 9, .. })
    ));
    assert!(matches!(
        to_soup(&p, &[0, 1]),
        Err(RasterError::NotTriangles(2))
    ));
}

#[test]
fn tetrahedron_and_sphere_wind_outwards() {
    for (p, i) in [tetrahedron(), uv_sphere_indexed(8, 5)] {
        for t in i.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|k| p[k as usize]);
            let n = face_normal(a, b, c);
            assert!(
                n.dot((a + b + c) / 3.0) > 0.0,
                "triangle {t:?} faces inwards"
            );
        }
    }
}

#[test]
fn perspective_matches_glam_in_both_depth_conventions() {
    for (fov, aspect, near, far) in [
        (1.0, 1.5, 0.1, 100.0),
        (0.3, 0.5, 2.0, 3.0),
        (2.5, 1.0, 0.01, 1e4),
    ] {
        let ours = perspective_wgpu(fov, aspect, near, far).unwrap();
        assert!(mat_close(
            ours,
            glam::camera::rh::proj::directx::perspective(fov, aspect, near, far),
            1e-5
        ));
        let gl = perspective_gl(fov, aspect, near, far).unwrap();
        assert!(mat_close(
            gl,
            glam::camera::rh::proj::opengl::perspective(fov, aspect, near, far),
            1e-5
        ));
    }
}

#[test]
fn near_maps_to_0_far_to_1_and_the_axis_stays_on_the_axis() {
    let (near, far) = (0.5, 40.0);
    let p = perspective_wgpu(1.0, 1.3, near, far).unwrap();
    let gl = perspective_gl(1.0, 1.3, near, far).unwrap();
    let at = |m: Mat4, d: f32, lo: f32| project(m, Vec3::new(0.0, 0.0, -d), lo);
    assert!(at(p, near, 0.0).ndc.z.abs() < 1e-6);
    assert!((at(p, far, 0.0).ndc.z - 1.0).abs() < 1e-5);
    assert!((at(gl, near, -1.0).ndc.z + 1.0).abs() < 1e-5);
    assert!((at(gl, far, -1.0).ndc.z - 1.0).abs() < 1e-5);
    for d in [0.6, 1.0, 7.0, 39.0] {
        let q = at(p, d, 0.0);
        assert_eq!((q.ndc.x, q.ndc.y), (0.0, 0.0));
        assert!(q.inside);
        assert!((q.clip.w - d).abs() < 1e-6, "w is the distance");
        assert!(close(q.ndc.z, ndc_depth_wgpu(d, near, far), 1e-5));
        assert!(close(
            at(gl, d, -1.0).ndc.z,
            ndc_depth_gl(d, near, far),
            1e-5
        ));
    }
    assert!(!at(p, near * 0.9, 0.0).inside && !at(p, far * 1.1, 0.0).inside);
    assert!(
        !project(p, Vec3::new(0.0, 0.0, 1.0), 0.0).inside,
        "behind the camera"
    );
}

#[test]
fn the_frustum_edge_maps_to_the_edge_of_ndc() {
    let fov: f32 = 0.9;
    let p = perspective_wgpu(fov, 2.0, 0.1, 10.0).unwrap();
    let d = 3.0;
    let top = d * (fov / 2.0).tan();
    let q = project(p, Vec3::new(2.0 * top, top, -d), 0.0);
    assert!((q.ndc.x - 1.0).abs() < 1e-5 && (q.ndc.y - 1.0).abs() < 1e-5);
}

#[test]
fn bad_projection_parameters_are_rejected_by_name() {
    let e = |r: Result<Mat4, RasterError>| r.unwrap_err().to_string();
    assert!(e(perspective_wgpu(0.0, 1.0, 0.1, 1.0)).contains("field of view"));
    assert!(e(perspective_wgpu(1.0, f32::NAN, 0.1, 1.0)).contains("aspect"));
    assert!(e(perspective_wgpu(1.0, 1.0, 0.0, 1.0)).contains("z_near"));
    assert!(e(perspective_gl(1.0, 1.0, 2.0, 1.0)).contains("z_far"));
}

#[test]
fn depth_is_spent_near_the_camera() {
    let (n, f) = (0.1, 1000.0);
    // Half of the depth range lies within about 2n of the near plane.
    assert!(ndc_depth_wgpu(2.0 * n, n, f) > 0.49);
    // The step grows with the square of the distance and with f / n.
    let a = depth_step(1.0, n, f, 24);
    assert!(close(depth_step(10.0, n, f, 24), 100.0 * a, 1e-5));
    assert!(depth_step(1.0, 1.0, f, 24) < a / 5.0);
    // It is the derivative: one step of depth is worth depth_step metres.
    let d = 50.0;
    let dz = ndc_depth_wgpu(d + 0.01, n, f) - ndc_depth_wgpu(d, n, f);
    let per_step = 0.01 / (dz * ((1u32 << 24) - 1) as f32);
    assert!(
        close(per_step, depth_step(d, n, f, 24), 1e-2),
        "{per_step} vs {}",
        depth_step(d, n, f, 24)
    );
}

#[test]
fn averaged_normals_are_unit_and_equal_the_face_normal_on_a_flat_mesh() {
    // A flat, tilted grid of 3 × 3 vertices.
    let (u, v) = (Vec3::new(1.0, 0.2, 0.0), Vec3::new(0.0, 0.3, -1.0));
    let p: Vec<Vec3> = (0..9)
        .map(|k| u * (k % 3) as f32 + v * (k / 3) as f32)
        .collect();
    let mut idx = Vec::new();
    for r in 0..2u32 {
        for c in 0..2u32 {
            let a = r * 3 + c;
            idx.extend([a, a + 1, a + 4, a, a + 4, a + 3]);
        }
    }
    let mut n = vec![Vec3::ZERO; 9];
    vertex_normals(&p, &idx, &mut n).unwrap();
    let face = u.cross(v).normalize();
    for x in &n {
        assert!((*x - face).length() < 1e-5, "{x} vs {face}");
    }
    // On a sphere: unit, and close to the radial direction.
    let (p, idx) = uv_sphere_indexed(32, 16);
    let mut n = vec![Vec3::ZERO; p.len()];
    vertex_normals(&p, &idx, &mut n).unwrap();
    for (x, q) in n.iter().zip(&p) {
        assert!((x.length() - 1.0).abs() < 1e-5);
        assert!(x.dot(*q) > 0.99);
    }
    assert!(vertex_normals(&p, &idx, &mut [Vec3::ZERO; 3]).is_err());
}

#[test]
fn flat_shading_gives_every_corner_its_face_normal() {
    let (p, i) = tetrahedron();
    let (fp, fn_) = flat_shaded(&p, &i).unwrap();
    assert_eq!(fp.len(), 12);
    for (t, n) in fp.chunks_exact(3).zip(fn_.chunks_exact(3)) {
        let face = face_normal(t[0], t[1], t[2]).normalize();
        assert!(n.iter().all(|x| (*x - face).length() < 1e-6));
    }
}

#[test]
fn the_normal_matrix_keeps_normals_perpendicular_under_non_uniform_scale() {
    let model = Mat4::from_scale_rotation_translation(
        Vec3::new(3.0, 1.0, 0.5),
        glam::Quat::from_rotation_z(0.4),
        Vec3::new(1.0, 2.0, 3.0),
    );
    let (t, n) = (
        Vec3::new(1.0, 1.0, 0.0).normalize(),
        Vec3::new(1.0, -1.0, 0.0).normalize(),
    );
    let t2 = model.transform_vector3(t);
    assert!((normal_matrix(model) * n).dot(t2).abs() < 1e-5);
    assert!(
        model.transform_vector3(n).dot(t2).abs() > 0.5,
        "M itself does not"
    );
    // For a rotation it is the rotation itself.
    let r = Mat4::from_rotation_y(0.7);
    assert!((normal_matrix(r) - Mat3::from_mat4(r)).abs_diff_eq(Mat3::ZERO, 1e-6));
}

#[test]
fn shading_terms_behave() {
    let m = Material::default();
    let n = Vec3::Y;
    // Light straight above, eye straight above: full diffuse, full specular in both models.
    for model in [ShadingModel::Phong, ShadingModel::BlinnPhong] {
        let t = shade(n, n, n, &m, model);
        assert!((t.diffuse - m.diffuse * m.color).length() < 1e-6);
        assert!((t.specular - Vec3::splat(m.specular)).length() < 1e-6);
        assert_eq!(t.ambient, m.ambient * m.color);
    }
    // Light below the surface: ambient only.
    let t = shade(n, -n, n, &m, ShadingModel::Phong);
    assert_eq!(t.diffuse + t.specular, Vec3::ZERO);
    // Diffuse follows the cosine (Lambert).
    let l = Vec3::new(0.6, 0.8, 0.0);
    let t = shade(n, l, Vec3::Z, &m, ShadingModel::Phong);
    assert!((t.diffuse - 0.8 * m.diffuse * m.color).length() < 1e-6);
    // Blinn-Phong's highlight is wider: off the mirror direction it is brighter.
    let v = Vec3::new(-0.5, 0.8, 0.3).normalize();
    assert!(blinn_phong(n, l, v, &m).x > phong(n, l, v, &m).x);
    // At the mirror direction both are at their peak and agree.
    let r = Vec3::new(-0.6, 0.8, 0.0);
    assert!((blinn_phong(n, l, r, &m) - phong(n, l, r, &m)).length() < 1e-5);
}

#[test]
fn sphere_images_are_brightest_towards_the_light() {
    let m = Material::default();
    let size = 32;
    let img = sphere_image(size, Vec3::X, &m, ShadingModel::Phong, Term::Diffuse);
    assert_eq!(img.len(), size * size * 4);
    let px = |i: usize, j: usize| img[(j * size + i) * 4] as u32;
    assert!(px(27, 16) > px(4, 16) + 50);
    // The light under the pointer: the centre of the image is straight at the viewer.
    assert!((light_from_image(0.5, 0.5) - Vec3::Z).length() < 1e-6);
    assert!(light_from_image(0.99, 0.5).x > 0.9);
    assert!((light_from_image(1.0, 0.0).length() - 1.0).abs() < 1e-5);
}

/// three.js's perspective matrices (tests/data/raster_three.txt, from
/// scripts/reference/raster_three.mjs) in both depth conventions.
#[test]
fn perspective_matches_three_js() {
    let data = include_str!("data/raster_three.txt");
    let mut checked = 0;
    for line in data
        .lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
    {
        let parts: Vec<&str> = line.split_whitespace().collect();
        let v: Vec<f32> = parts[2..].iter().map(|x| x.parse().unwrap()).collect();
        let (fov, aspect, near, far) = (v[0].to_radians(), v[1], v[2], v[3]);
        let three = Mat4::from_cols_array(&v[4..20].try_into().unwrap()).transpose();
        let ours = match parts[1] {
            "gl" => perspective_gl(fov, aspect, near, far).unwrap(),
            "wgpu" => perspective_wgpu(fov, aspect, near, far).unwrap(),
            other => panic!("unknown convention {other}"),
        };
        assert!(mat_close(ours, three, 1e-5), "{line}\nours: {ours}");
        checked += 1;
    }
    assert_eq!(checked, 14);
}
