//! Lesson 01 cores: homogeneous coordinates, local matrices, hierarchies, meshes, the camera.
//! Runs natively and, through wasm-bindgen-test, in headless Chromium.
mod support;

use glam::{Mat4, Vec3, Vec4};
use inbetween::camera::OrbitCamera;
use inbetween::mesh::{cone, cuboid, grid_lines, uv_sphere};
use inbetween::transform::*;
use std::f32::consts::{FRAC_PI_2, PI};

both! {
    fn points_move_and_directions_do_not() {
        let m = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0)) * Mat4::from_rotation_z(FRAC_PI_2);
        let p = m * point(Vec3::X);
        let v = m * direction(Vec3::X);
        assert_close!(p.to_array(), [1.0, 3.0, 3.0, 1.0], 1e-6);
        assert_close!(v.to_array(), [0.0, 1.0, 0.0, 0.0], 1e-6);
    }

    fn local_matrix_rotates_z_first_then_translates() {
        // Rz(90°) takes x to y; Ry(90°) then takes y to y; Rx(90°) takes y to z; then translate.
        let m = local_matrix(Vec3::new(10.0, 0.0, 0.0), Vec3::new(FRAC_PI_2, FRAC_PI_2, FRAC_PI_2));
        let expected = Mat4::from_translation(Vec3::new(10.0, 0.0, 0.0))
            * Mat4::from_rotation_x(FRAC_PI_2)
            * Mat4::from_rotation_y(FRAC_PI_2)
            * Mat4::from_rotation_z(FRAC_PI_2);
        assert_close!(m.to_cols_array(), expected.to_cols_array(), 1e-6);
        // By hand: Rz x = y, Ry y = y, Rx y = z.
        assert_close!(m.transform_point3(Vec3::X).to_array(), [10.0, 0.0, 1.0], 1e-6);
        // The pivot goes exactly to the translation, whatever the angles.
        assert_close!(m.transform_point3(Vec3::ZERO).to_array(), [10.0, 0.0, 0.0], 1e-6);
    }

    fn local_matrix_is_rigid() {
        let m = local_matrix(Vec3::new(0.3, -2.0, 5.0), Vec3::new(0.4, -1.3, 2.2));
        assert!((m.determinant() - 1.0).abs() < 1e-5);
        let r = glam::Mat3::from_mat4(m);
        assert_close!((r.transpose() * r).to_cols_array(), glam::Mat3::IDENTITY.to_cols_array(), 1e-5);
    }

    fn world_of_a_chain_is_the_product_of_locals() {
        let parents = [-1, 0, 1];
        let local = [
            local_matrix(Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 0.3)),
            local_matrix(Vec3::new(0.0, 0.5, 0.0), Vec3::new(0.2, 0.0, 0.0)),
            local_matrix(Vec3::new(0.1, 0.0, 0.0), Vec3::new(0.0, 0.7, 0.0)),
        ];
        let mut world = [Mat4::ZERO; 3];
        world_matrices(&parents, &local, &mut world);
        assert_close!(world[2].to_cols_array(), (local[0] * local[1] * local[2]).to_cols_array(), 1e-6);
    }

    fn two_roots_and_siblings() {
        let parents = [-1, 0, 0, -1, 3];
        let local: Vec<Mat4> = (0..5).map(|i| Mat4::from_translation(Vec3::splat(i as f32 + 1.0))).collect();
        let mut world = vec![Mat4::ZERO; 5];
        world_matrices(&parents, &local, &mut world);
        let origin = |m: Mat4| m.w_axis.truncate().to_array();
        assert_close!(origin(world[1]), [3.0; 3], 0.0);
        assert_close!(origin(world[2]), [4.0; 3], 0.0);
        assert_close!(origin(world[3]), [4.0; 3], 0.0);
        assert_close!(origin(world[4]), [9.0; 3], 0.0);
    }

    fn rest_pose_of_the_figure_stands_on_the_ground() {
        let (hierarchy, rest, shapes) = simple_human();
        let n = hierarchy.len();
        let (mut l, mut w, mut d) = (vec![Mat4::ZERO; n], vec![Mat4::ZERO; n], vec![Mat4::ZERO; n]);
        hierarchy.pose(&rest, ScaleMode::NotInherited, &mut l, &mut w, &mut d).unwrap();
        // The lowest box corner of all is at floor level (within 5 cm), none below it.
        let lowest = shapes
            .iter()
            .zip(&d)
            .map(|(s, m)| (*m * Mat4::from_translation(s.center)).transform_point3(-s.half_extents).y)
            .fold(f32::INFINITY, f32::min);
        assert!(lowest.abs() < 0.05, "lowest point {lowest}");
        // Left and right are mirror images.
        let l_hand = w[hierarchy.find("forearm.L").unwrap()].w_axis;
        let r_hand = w[hierarchy.find("forearm.R").unwrap()].w_axis;
        assert_close!([l_hand.x, l_hand.y], [-r_hand.x, r_hand.y], 1e-6);
    }

    fn scale_is_not_inherited_by_default() {
        let (hierarchy, mut pose, _) = simple_human();
        let arm = hierarchy.find("upper_arm.L").unwrap();
        let forearm = hierarchy.find("forearm.L").unwrap();
        let n = hierarchy.len();
        let run = |pose: &[LocalTransform], mode| {
            let (mut l, mut w, mut d) = (vec![Mat4::ZERO; n], vec![Mat4::ZERO; n], vec![Mat4::ZERO; n]);
            hierarchy.pose(pose, mode, &mut l, &mut w, &mut d).unwrap();
            (w, d)
        };
        let (w0, _) = run(&pose, ScaleMode::NotInherited);
        pose[arm].scale = Vec3::new(1.0, 2.0, 1.0);
        let (w1, d1) = run(&pose, ScaleMode::NotInherited);
        // The child's world matrix ignores the parent's scale; only the parent's drawing grows.
        assert_close!(w1[forearm].to_cols_array(), w0[forearm].to_cols_array(), 1e-6);
        assert_close!((d1[arm] * Vec4::Y).to_array(), [0.0, 2.0, 0.0, 0.0], 1e-6);
        // Inherited: the forearm's pivot moves down twice as far, and its frame is stretched.
        let (w2, _) = run(&pose, ScaleMode::Inherited);
        let drop0 = w0[arm].w_axis.y - w0[forearm].w_axis.y;
        let drop2 = w2[arm].w_axis.y - w2[forearm].w_axis.y;
        assert!((drop2 - 2.0 * drop0).abs() < 1e-5, "{drop0} {drop2}");
        assert!((w2[forearm].y_axis.length() - 2.0).abs() < 1e-5);
    }

    fn inherited_non_uniform_scale_shears_a_rotated_child() {
        let parent = Mat4::from_scale(Vec3::new(1.0, 3.0, 1.0));
        let child = parent * local_matrix(Vec3::ZERO, Vec3::new(0.0, 0.0, PI / 4.0));
        // The child's x and y axes are no longer perpendicular: a shear.
        let dot = child.x_axis.truncate().dot(child.y_axis.truncate());
        assert!(dot.abs() > 1.0, "axes dot {dot}");
    }

    fn hierarchy_validation_rules() {
        let names = |n: usize| (0..n).map(|i| format!("j{i}")).collect::<Vec<_>>();
        assert_eq!(Hierarchy::new(vec![], vec![]), Err(HierarchyError::Empty));
        assert_eq!(
            Hierarchy::new(names(3), vec![-1, 2, 0]),
            Err(HierarchyError::ParentNotBefore { joint: 1, parent: 2 })
        );
        assert_eq!(
            Hierarchy::new(names(2), vec![-1, 1]),
            Err(HierarchyError::ParentNotBefore { joint: 1, parent: 1 })
        );
        assert_eq!(
            Hierarchy::new(names(2), vec![-1, -7]),
            Err(HierarchyError::ParentNotBefore { joint: 1, parent: -7 })
        );
        assert!(matches!(Hierarchy::new(names(1), vec![-1, 0]), Err(HierarchyError::LengthMismatch { .. })));
        let message = HierarchyError::ParentNotBefore { joint: 1, parent: 2 }.to_string();
        assert!(message.contains("joint 1") && message.contains("before"), "{message}");

        let h = Hierarchy::new(names(2), vec![-1, 0]).unwrap();
        let mut bad = vec![LocalTransform::from_translation(Vec3::ZERO); 2];
        bad[1].euler_xyz_rad.y = f32::NAN;
        let mut m = vec![Mat4::ZERO; 2];
        let (mut w, mut d) = (m.clone(), m.clone());
        assert_eq!(h.pose(&bad, ScaleMode::NotInherited, &mut m, &mut w, &mut d), Err(HierarchyError::NonFinite { joint: 1 }));
        let short = vec![LocalTransform::from_translation(Vec3::ZERO); 1];
        assert!(matches!(h.pose(&short, ScaleMode::Inherited, &mut m, &mut w, &mut d), Err(HierarchyError::LengthMismatch { .. })));
    }

    fn walk_cycle_is_periodic_and_mirrored() {
        let (hierarchy, _, _) = simple_human();
        let n = hierarchy.len();
        let (mut a, mut b, mut c) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        walk_cycle(&hierarchy, 0.3, 1.2, &mut a);
        walk_cycle(&hierarchy, 1.5, 1.2, &mut b);
        walk_cycle(&hierarchy, 0.9, 1.2, &mut c); // half a period later
        for i in 0..n {
            assert_close!(a[i].to_array(), b[i].to_array(), 1e-5);
        }
        let (tl, tr) = (hierarchy.find("thigh.L").unwrap(), hierarchy.find("thigh.R").unwrap());
        assert!((a[tl].x - c[tr].x).abs() < 1e-5);
    }

    fn cuboid_normals_point_outwards() {
        let mesh = cuboid(Vec3::new(1.0, 2.0, 3.0));
        assert_eq!((mesh.positions.len(), mesh.triangle_count()), (24, 12));
        for tri in mesh.indices.chunks(3) {
            let [a, b, c] = [0, 1, 2].map(|k| mesh.positions[tri[k] as usize]);
            let face_normal = (b - a).cross(c - a).normalize();
            // Counter-clockwise from outside: the winding normal agrees with the stored normal.
            assert!(face_normal.dot(mesh.normals[tri[0] as usize]) > 0.999);
            assert!(face_normal.dot((a + b + c) / 3.0) > 0.0);
        }
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            assert!((p.abs() / Vec3::new(1.0, 2.0, 3.0)).dot(n.abs()) > 0.999, "corner on its face");
        }
    }

    fn cone_normals_point_outwards() {
        let (radius, height) = (0.5, 2.0);
        let mesh = cone(radius, height, 12);
        assert_eq!(mesh.triangle_count(), 24);
        let axis_point = Vec3::new(0.0, height / 3.0, 0.0); // inside the cone
        for tri in mesh.indices.chunks(3) {
            let [a, b, c] = [0, 1, 2].map(|k| mesh.positions[tri[k] as usize]);
            let face_normal = (b - a).cross(c - a).normalize();
            // Counter-clockwise from outside: the winding normal points away from the inside...
            assert!(face_normal.dot((a + b + c) / 3.0 - axis_point) > 0.0);
            // ...and every stored normal agrees with it (smooth sides lean by the half angle).
            for &index in tri {
                let n = mesh.normals[index as usize];
                assert!((n.length() - 1.0).abs() < 1e-5);
                assert!(n.dot(face_normal) > 0.9, "normal {n} vs face {face_normal}");
            }
        }
        // Side normals lean up by atan(r / h): perpendicular to the slant from rim to tip.
        let slant = Vec3::new(0.0, height, 0.0) - Vec3::new(radius, 0.0, 0.0);
        let side = mesh.normals[0];
        assert!(side.dot(slant).abs() < 1e-5, "{side}");
    }

    fn sphere_vertices_lie_on_the_sphere_with_radial_normals() {
        let mesh = uv_sphere(2.0, 12, 8);
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            assert!((p.length() - 2.0).abs() < 1e-5);
            assert!((*p / 2.0 - *n).length() < 1e-5);
        }
        for tri in mesh.indices.chunks(3) {
            let [a, b, c] = [0, 1, 2].map(|k| mesh.positions[tri[k] as usize]);
            let area = (b - a).cross(c - a);
            assert!(area.length() > 1e-6, "no degenerate triangles");
            assert!(area.dot(a + b + c) > 0.0, "outward winding");
        }
        assert_eq!(grid_lines(4, 0.5).count(), 10);
        assert!(grid_lines(4, 0.5).all(|[a, b]| a.y == 0.0 && b.y == 0.0 && (a - b).length() == 2.0));
    }

    fn camera_looks_at_its_target_from_its_distance() {
        let mut camera = OrbitCamera::default();
        camera.orbit(0.7, 0.2);
        let eye = camera.eye();
        assert!(((eye - camera.target).length() - camera.distance).abs() < 1e-5);
        let view = camera.view();
        assert!(view.transform_point3(eye).length() < 1e-4);
        let target_view = view.transform_point3(camera.target);
        assert!(target_view.z < 0.0 && target_view.truncate().length() < 1e-4, "target straight ahead on −z");
        // Depth: the near plane maps to 0, the far plane to 1 (wgpu convention).
        let proj = camera.projection(1.5);
        let ndc = |z: f32| proj.project_point3(Vec3::new(0.0, 0.0, -z)).z;
        assert!(ndc(camera.near).abs() < 1e-5 && (ndc(camera.far) - 1.0).abs() < 1e-4);
    }

    fn camera_pitch_is_clamped_and_zoom_stays_positive() {
        let mut camera = OrbitCamera::default();
        camera.orbit(0.0, 10.0);
        assert!(camera.pitch_rad < FRAC_PI_2);
        camera.orbit(0.0, -20.0);
        assert!(camera.pitch_rad > -FRAC_PI_2);
        camera.zoom(1e-9);
        assert!(camera.distance > 0.0);
        camera.zoom(f32::NAN);
        assert!(camera.distance.is_finite());
        let before = camera.target;
        camera.pan(0.1, 0.0);
        assert!((camera.target - before).length() > 0.0);
    }
}
