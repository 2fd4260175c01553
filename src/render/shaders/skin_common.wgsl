// Skinning on the GPU, shared by the vertex shader (skin.wgsl) and the compute check
// (skin_compute.wgsl): linear blend (LBS) or dual quaternion (DQS) skinning of a bind-pose
// vertex. The palette is a uniform array (WebGL2 has no storage buffers in vertex shaders):
// three vec4 per joint, at most 128 joints
// (MAX_GPU_JOINTS in src/figures/gpu.rs, whose lbs_like_shader / dqs_like_shader are these
// formulas in Rust).
struct Skin {
    model: mat4x4<f32>,
    normal_matrix: mat4x4<f32>,
    color: vec4<f32>,
    flags: vec4<f32>,                 // x: 1 = per-vertex colour; y: 1 = DQS, 0 = LBS
    palette: array<vec4<f32>, 384>,   // LBS: rows of K_j (3 x 4); DQS: real, dual, unused
};
@group(1) @binding(0) var<uniform> skin: Skin;

struct Skinned {
    position: vec3<f32>,
    normal: vec3<f32>,
};

// p' = (sum_j w_j K_j) p; n' = linear part of the same blend applied to n.
fn skin_lbs(position: vec3<f32>, normal: vec3<f32>, joints: vec4<u32>, weights: vec4<f32>) -> Skinned {
    var r0 = vec4<f32>(0.0);
    var r1 = vec4<f32>(0.0);
    var r2 = vec4<f32>(0.0);
    for (var i = 0u; i < 4u; i++) {
        let j = joints[i] * 3u;
        let w = weights[i];
        r0 += w * skin.palette[j];
        r1 += w * skin.palette[j + 1u];
        r2 += w * skin.palette[j + 2u];
    }
    let p = vec4<f32>(position, 1.0);
    var out: Skinned;
    out.position = vec3<f32>(dot(r0, p), dot(r1, p), dot(r2, p));
    out.normal = vec3<f32>(dot(r0.xyz, normal), dot(r1.xyz, normal), dot(r2.xyz, normal));
    return out;
}

// Kavan et al.: blend with each real part aligned to the first joint's (antipodality), then
// rotate by the unnormalised blend with the factor 2 / |r|^2 (no square root) and translate.
fn skin_dqs(position: vec3<f32>, normal: vec3<f32>, joints: vec4<u32>, weights: vec4<f32>) -> Skinned {
    let pivot = skin.palette[joints[0] * 3u];
    var real = vec4<f32>(0.0);
    var dual = vec4<f32>(0.0);
    for (var i = 0u; i < 4u; i++) {
        let j = joints[i] * 3u;
        let r = skin.palette[j];
        let w = select(-weights[i], weights[i], dot(pivot, r) >= 0.0);
        real += w * r;
        dual += w * skin.palette[j + 1u];
    }
    let k = 2.0 / max(dot(real, real), 1e-24);
    let rv = real.xyz;
    let dv = dual.xyz;
    let t = k * (real.w * dv - dual.w * rv + cross(rv, dv));
    var out: Skinned;
    out.position = position + k * cross(rv, cross(rv, position) + real.w * position) + t;
    out.normal = normal + k * cross(rv, cross(rv, normal) + real.w * normal);
    return out;
}

