//! The logic of the GPU paths (native, tested natively): what the skinning shader receives and
//! how it mixes it, the caps, and the statistics that compare a GPU simulation with the CPU one.
//!
//! **Skinning in the vertex shader** (`src/render/skin.rs`, `shaders/skin.wgsl`). The bind-pose
//! vertices, joints and weights are uploaded once; per frame only the palette travels, as a
//! uniform array, because WebGL2 has no storage buffers in vertex shaders. Each joint takes three
//! `vec4`s: for LBS the three rows of `K_j`'s 3 × 4 matrix, for DQS the real and the dual part
//! (and an unused row). A uniform block is at least 16 KiB everywhere, which bounds the palette:
//! [`MAX_GPU_JOINTS`] joints (6 KiB). A character with more joints stays on the CPU.
//! [`lbs_like_shader`] and [`dqs_like_shader`] are the shader's formulas in Rust, so a native
//! test checks the packing against [`crate::skinning`]'s skinning.

use super::Frame;
use crate::draw::{SkinMeshId, SkinnedDraw};
use crate::rigid::DualQuat;
use glam::{Affine3A, Mat4, Vec3, Vec4};

/// The most joints one GPU-skinned mesh may use (the uniform palette's size; see the module).
pub const MAX_GPU_JOINTS: usize = 128;

/// `vec4`s per joint in the palette.
pub const ROWS_PER_JOINT: usize = 3;

fn check_joints(n: usize) -> Result<(), String> {
    if n > MAX_GPU_JOINTS {
        Err(format!(
            "{n} joints is too many for GPU skinning (at most {MAX_GPU_JOINTS}, the size of the \
             shader's uniform palette): skinned on the CPU instead"
        ))
    } else {
        Ok(())
    }
}

/// The LBS palette as the shader reads it: per joint the three rows of `K_j` (3 × 4).
pub fn pack_lbs(palette: &[Affine3A]) -> impl Iterator<Item = [Vec4; 3]> + '_ {
    palette.iter().map(|k| {
        let m = Mat4::from(*k).transpose();
        [m.x_axis, m.y_axis, m.z_axis]
    })
}

/// The DQS palette as the shader reads it: per joint `[real (x, y, z, w), dual, unused]`.
pub fn pack_dqs(palette: &[DualQuat]) -> impl Iterator<Item = [Vec4; 3]> + '_ {
    palette
        .iter()
        .map(|q| [Vec4::from(q.real), Vec4::from(q.dual), Vec4::ZERO])
}

/// Adds a GPU-skinned draw of `mesh` by LBS with `palette` (`K_j = M_j B_j⁻¹`, from
/// [`crate::skinning::skinning_palette`]). `color`: `None` uses the mesh's vertex colours.
///
/// # Errors
/// More than [`MAX_GPU_JOINTS`] joints.
pub fn draw_skinned_lbs(
    frame: &mut Frame,
    mesh: SkinMeshId,
    model: Mat4,
    color: Option<Vec3>,
    palette: &[Affine3A],
) -> Result<(), String> {
    check_joints(palette.len())?;
    let start = frame.skin_palette.len();
    frame.skin_palette.extend(pack_lbs(palette));
    push(frame, mesh, model, color, false, start);
    Ok(())
}

/// As [`draw_skinned_lbs`], by DQS with the dual quaternions of
/// [`crate::skinning::dual_quat_palette`].
///
/// # Errors
/// More than [`MAX_GPU_JOINTS`] joints.
pub fn draw_skinned_dqs(
    frame: &mut Frame,
    mesh: SkinMeshId,
    model: Mat4,
    color: Option<Vec3>,
    palette: &[DualQuat],
) -> Result<(), String> {
    check_joints(palette.len())?;
    let start = frame.skin_palette.len();
    frame.skin_palette.extend(pack_dqs(palette));
    push(frame, mesh, model, color, true, start);
    Ok(())
}

fn push(
    frame: &mut Frame,
    mesh: SkinMeshId,
    model: Mat4,
    color: Option<Vec3>,
    dqs: bool,
    start: usize,
) {
    frame.skinned.push(SkinnedDraw {
        mesh,
        model,
        color: color.unwrap_or(Vec3::ONE).extend(1.0),
        vertex_colors: color.is_none(),
        dqs,
        joints: start..frame.skin_palette.len(),
    });
}

/// Whether a mesh whose weights name joints below `joint_bound` can be skinned on the GPU with a
/// palette of `joints` joints; the reason if not.
pub fn gpu_skinnable(joint_bound: usize, joints: usize) -> Result<(), String> {
    check_joints(joints)?;
    if joint_bound > joints {
        return Err(format!(
            "the weights name joint {} but the palette has {joints}",
            joint_bound - 1
        ));
    }
    Ok(())
}

/// `skin.wgsl`'s LBS for one vertex, in Rust: blend the rows, then apply them.
pub fn lbs_like_shader(
    rows: &[[Vec4; 3]],
    joints: [u16; 4],
    weights: [f32; 4],
    p: Vec3,
    n: Vec3,
) -> (Vec3, Vec3) {
    let mut r = [Vec4::ZERO; 3];
    for (j, w) in joints.iter().zip(weights) {
        for (acc, row) in r.iter_mut().zip(rows[*j as usize]) {
            *acc += w * row;
        }
    }
    let p4 = p.extend(1.0);
    (
        Vec3::new(r[0].dot(p4), r[1].dot(p4), r[2].dot(p4)),
        Vec3::new(
            r[0].truncate().dot(n),
            r[1].truncate().dot(n),
            r[2].truncate().dot(n),
        ),
    )
}

/// `skin.wgsl`'s DQS for one vertex, in Rust: signs against the first joint (the pivot), blend,
/// rotate by the unnormalised blend with the factor `2 / ‖r‖²`, translate.
pub fn dqs_like_shader(
    rows: &[[Vec4; 3]],
    joints: [u16; 4],
    weights: [f32; 4],
    p: Vec3,
    n: Vec3,
) -> (Vec3, Vec3) {
    let pivot = rows[joints[0] as usize][0];
    let (mut real, mut dual) = (Vec4::ZERO, Vec4::ZERO);
    for (j, w) in joints.iter().zip(weights) {
        let [r, d, _] = rows[*j as usize];
        let s = if pivot.dot(r) >= 0.0 { w } else { -w };
        real += s * r;
        dual += s * d;
    }
    let k = 2.0 / real.length_squared().max(1e-24);
    let (rv, w0, dv) = (real.truncate(), real.w, dual.truncate());
    let t = k * (w0 * dv - dual.w * rv + rv.cross(dv));
    let rotate = |v: Vec3| v + k * rv.cross(rv.cross(v) + w0 * v);
    (rotate(p) + t, rotate(n))
}
