use glam::Vec3;
use inbetween::rigid::DualQuat;
use inbetween::skinning::rigs::benchmark_input;
use inbetween::skinning::*;

/// The four-lane path gives every vertex what the one-vertex formula gives (blend with the
/// sign fix, then the rigid motion), on the benchmark's humanoid with a vertex count that
/// leaves a remainder.
#[test]
fn four_lane_dqs_matches_one_vertex_at_a_time() {
    let input = benchmark_input(1003, 7);
    let mut dq = vec![DualQuat::IDENTITY; input.palette.len()];
    dual_quat_palette(&input.palette, &mut dq).unwrap();
    let n = input.positions.len();
    let (mut op, mut on) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    skin_dqs(
        &dq,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut op,
        &mut on,
    )
    .unwrap();
    // The portable loop too, whatever kernel `skin_dqs` picked on this CPU.
    let (mut pp, mut pn) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    skin_dqs_with(
        LbsKernel::Portable,
        &dq,
        &input.skin,
        &input.positions,
        &input.normals,
        &mut pp,
        &mut pn,
    )
    .unwrap();
    for v in 0..n {
        assert!((op[v] - pp[v]).length() < 1e-4 * (1.0 + pp[v].length()));
        assert!((on[v] - pn[v]).length() < 1e-4);
        let j = input.skin.joints()[v];
        let w = input.skin.weights()[v];
        let qs = j.map(|j| dq[j as usize]);
        let b = blend_dual_quats(&qs, &w);
        let p = b.transform_point(input.positions[v]);
        assert!(
            (op[v] - p).length() < 1e-4 * (1.0 + p.length()),
            "vertex {v}: {} vs {p}",
            op[v]
        );
        let nrm = b.transform_point(input.normals[v]) - b.transform_point(Vec3::ZERO);
        assert!(
            (on[v] - nrm).length() < 1e-4,
            "normal {v}: {} vs {nrm}",
            on[v]
        );
    }
}
