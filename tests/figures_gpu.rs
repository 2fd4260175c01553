//! The GPU paths' logic, natively (`src/figures/gpu.rs`): the palette the skinning shader gets,
//! mixed by the shader's formulas written in Rust, skins like the CPU cores; caps give errors;
//! the figures put GPU draws (not CPU meshes) in the frame when GPU skinning is on.

use glam::{Affine3A, Mat4, Vec3};
use inbetween::draw::{Frame, MeshId, SkinMeshId};
use inbetween::figures::gpu::{
    draw_skinned_dqs, draw_skinned_lbs, dqs_like_shader, gpu_skinnable, lbs_like_shader, pack_dqs,
    pack_lbs, MAX_GPU_JOINTS,
};
use inbetween::figures::skinning::HumanFigure;
use inbetween::rigid::DualQuat;
use inbetween::skinning::rigs::benchmark_input;
use inbetween::skinning::{dual_quat_palette, skin_dqs, skin_lbs};

fn max_error(a: &[Vec3], b: &[Vec3]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (*x - *y).length())
        .fold(0.0, f32::max)
}

#[test]
fn shader_formulas_on_the_packed_palette_match_the_cpu_skinning() {
    // 60 joints, 4 random influences per vertex, a real pose (the benchmark's input).
    let input = benchmark_input(2_000, 7);
    let n = input.positions.len();
    let (mut p, mut nn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    skin_lbs(
        &input.palette,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut p,
        &mut nn,
    )
    .unwrap();
    let rows: Vec<_> = pack_lbs(&input.palette).collect();
    let (gp, gn): (Vec<Vec3>, Vec<Vec3>) = (0..n)
        .map(|v| {
            lbs_like_shader(
                &rows,
                input.skin.joints()[v],
                input.skin.weights()[v],
                input.positions[v],
                input.normals[v],
            )
        })
        .unzip();
    assert!(max_error(&p, &gp) < 1e-4, "LBS positions");
    assert!(max_error(&nn, &gn) < 1e-4, "LBS normals");

    let mut dq = vec![DualQuat::IDENTITY; input.palette.len()];
    dual_quat_palette(&input.palette, &mut dq).unwrap();
    skin_dqs(
        &dq,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut p,
        &mut nn,
    )
    .unwrap();
    let rows: Vec<_> = pack_dqs(&dq).collect();
    let (gp, gn): (Vec<Vec3>, Vec<Vec3>) = (0..n)
        .map(|v| {
            dqs_like_shader(
                &rows,
                input.skin.joints()[v],
                input.skin.weights()[v],
                input.positions[v],
                input.normals[v],
            )
        })
        .unzip();
    assert!(max_error(&p, &gp) < 1e-4, "DQS positions");
    assert!(max_error(&nn, &gn) < 1e-4, "DQS normals");
}

#[test]
fn dqs_shader_formula_fixes_antipodal_quaternions() {
    // Joint 1 is joint 0's rotation with the quaternion negated: the same motion. Without the
    // sign fix a 50/50 blend would cancel; with it the vertex moves rigidly with both.
    let k = Affine3A::from_rotation_translation(
        glam::Quat::from_rotation_y(0.8),
        Vec3::new(0.1, 0.2, 0.3),
    );
    let mut dq = [DualQuat::IDENTITY; 2];
    dual_quat_palette(&[k, k], &mut dq).unwrap();
    dq[1].real = -dq[1].real;
    dq[1].dual = -dq[1].dual;
    let rows: Vec<_> = pack_dqs(&dq).collect();
    let p = Vec3::new(0.5, -0.2, 0.7);
    let (q, n) = dqs_like_shader(&rows, [0, 1, 0, 0], [0.5, 0.5, 0.0, 0.0], p, Vec3::X);
    assert!((q - k.transform_point3(p)).length() < 1e-5, "{q}");
    assert!((n - k.transform_vector3(Vec3::X)).length() < 1e-5, "{n}");
}

#[test]
fn palettes_over_the_cap_are_errors_and_draws_record_their_range() {
    let mut frame = Frame::default();
    let big = vec![Affine3A::IDENTITY; MAX_GPU_JOINTS + 1];
    let e = draw_skinned_lbs(&mut frame, SkinMeshId(0), Mat4::IDENTITY, None, &big).unwrap_err();
    assert!(e.contains("too many") && e.contains("128"), "{e}");
    assert!(frame.skinned.is_empty() && frame.skin_palette.is_empty());
    let small = vec![Affine3A::IDENTITY; 5];
    draw_skinned_lbs(&mut frame, SkinMeshId(0), Mat4::IDENTITY, None, &small).unwrap();
    draw_skinned_dqs(
        &mut frame,
        SkinMeshId(1),
        Mat4::IDENTITY,
        Some(Vec3::X),
        &[DualQuat::IDENTITY; 3],
    )
    .unwrap();
    assert_eq!(frame.skinned[0].joints, 0..5);
    assert_eq!(frame.skinned[1].joints, 5..8);
    assert!(frame.skinned[1].dqs && !frame.skinned[0].dqs);
    assert!(frame.skinned[0].vertex_colors && !frame.skinned[1].vertex_colors);
    // The identity packs to the identity rows (LBS) and the unit quaternion (DQS).
    assert_eq!(frame.skin_palette[0][0].to_array(), [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(frame.skin_palette[5][0].to_array(), [0.0, 0.0, 0.0, 1.0]);
    let before = frame.fingerprint();
    frame.skin_palette[1][0].w = 0.5;
    assert_ne!(before, frame.fingerprint(), "the palette is part of the fingerprint");
    frame.clear();
    assert!(frame.skinned.is_empty() && frame.skin_palette.is_empty());
    assert!(gpu_skinnable(10, 10).is_ok());
    assert!(gpu_skinnable(11, 10).unwrap_err().contains("joint 10"));
    assert!(gpu_skinnable(3, 200).is_err());
}

#[test]
fn the_human_figure_draws_a_gpu_skinned_body_when_asked() {
    let mut figure = HumanFigure::new();
    figure.set_gpu(true);
    figure.skin(0.3).unwrap();
    let mut frame = Frame::default();
    let note = figure.draw_gpu(&mut frame, SkinMeshId(0)).unwrap();
    assert!(note.contains("on the GPU"), "{note}");
    assert_eq!(frame.skinned.len(), 1);
    assert!(frame.skinned[0].dqs, "the figure starts with DQS");
    assert_eq!(
        frame.skinned[0].joints.len(),
        figure.character().skeleton.len()
    );
    // The palette moved: the walk at 0.3 s is not the bind pose.
    assert!(frame
        .skin_palette
        .iter()
        .any(|r| (r[0] - glam::Vec4::new(0.0, 0.0, 0.0, 1.0)).length() > 1e-3));
    // CPU mode: a plain mesh, no GPU draws.
    figure.set_gpu(false);
    figure.skin(0.3).unwrap();
    let mut frame = Frame::default();
    let note = figure.draw(&mut frame, MeshId(3));
    assert!(note.contains("on the CPU"), "{note}");
    assert!(frame.skinned.is_empty() && frame.meshes.len() == 1);
    // Heat map changes reach the GPU copy once.
    figure.take_gpu_dirty();
    figure.set_heat_joint("none").unwrap();
    assert!(figure.take_gpu_dirty() && !figure.take_gpu_dirty());
}
