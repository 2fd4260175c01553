// Skinning in the vertex shader: linear blend (LBS) or dual quaternion (DQS) skinning of the
// bind-pose vertex, then the same lighting as mesh.wgsl. The palette is a uniform array (WebGL2
// has no storage buffers in vertex shaders): three vec4 per joint, at most 128 joints
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

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(3) joints: vec4<u32>,
    @location(4) weights: vec4<f32>,
};
struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world_pos: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};

struct Skinned {
    position: vec3<f32>,
    normal: vec3<f32>,
};

// p' = (sum_j w_j K_j) p; n' = linear part of the same blend applied to n.
fn skin_lbs(in: VertexIn) -> Skinned {
    var r0 = vec4<f32>(0.0);
    var r1 = vec4<f32>(0.0);
    var r2 = vec4<f32>(0.0);
    for (var i = 0u; i < 4u; i++) {
        let j = in.joints[i] * 3u;
        let w = in.weights[i];
        r0 += w * skin.palette[j];
        r1 += w * skin.palette[j + 1u];
        r2 += w * skin.palette[j + 2u];
    }
    let p = vec4<f32>(in.position, 1.0);
    var out: Skinned;
    out.position = vec3<f32>(dot(r0, p), dot(r1, p), dot(r2, p));
    out.normal = vec3<f32>(dot(r0.xyz, in.normal), dot(r1.xyz, in.normal), dot(r2.xyz, in.normal));
    return out;
}

// Kavan et al.: blend with each real part aligned to the first joint's (antipodality), then
// rotate by the unnormalised blend with the factor 2 / |r|^2 (no square root) and translate.
fn skin_dqs(in: VertexIn) -> Skinned {
    let pivot = skin.palette[in.joints[0] * 3u];
    var real = vec4<f32>(0.0);
    var dual = vec4<f32>(0.0);
    for (var i = 0u; i < 4u; i++) {
        let j = in.joints[i] * 3u;
        let r = skin.palette[j];
        let w = select(-in.weights[i], in.weights[i], dot(pivot, r) >= 0.0);
        real += w * r;
        dual += w * skin.palette[j + 1u];
    }
    let k = 2.0 / max(dot(real, real), 1e-24);
    let rv = real.xyz;
    let dv = dual.xyz;
    let t = k * (real.w * dv - dual.w * rv + cross(rv, dv));
    var out: Skinned;
    out.position = in.position + k * cross(rv, cross(rv, in.position) + real.w * in.position) + t;
    out.normal = in.normal + k * cross(rv, cross(rv, in.normal) + real.w * in.normal);
    return out;
}

@vertex
fn vs_main(in: VertexIn) -> VertexOut {
    var s: Skinned;
    if (skin.flags.y > 0.5) {
        s = skin_dqs(in);
    } else {
        s = skin_lbs(in);
    }
    var out: VertexOut;
    let world = skin.model * vec4<f32>(s.position, 1.0);
    out.clip = globals.proj * globals.view * world;
    out.world_pos = world.xyz;
    out.world_normal = (skin.normal_matrix * vec4<f32>(s.normal, 0.0)).xyz;
    out.color = select(skin.color, in.color, skin.flags.x > 0.5);
    return out;
}

// The lighting of mesh.wgsl's fs_main (lit only), so a GPU-skinned mesh looks like a CPU-skinned one.
@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let albedo = in.color.rgb;
    let n = normalize(in.world_normal);
    let l = globals.light_dir.xyz;
    let v = normalize(globals.eye.xyz - in.world_pos);
    let h = normalize(l + v);
    let ambient = mix(vec3<f32>(0.20, 0.19, 0.18), vec3<f32>(0.32, 0.36, 0.42), 0.5 + 0.5 * n.y);
    let diffuse = max(dot(n, l), 0.0);
    let specular = select(0.0, pow(max(dot(n, h), 0.0), 48.0), diffuse > 0.0);
    let lit = albedo * (ambient + 0.85 * diffuse) + vec3<f32>(0.25 * specular);
    return vec4<f32>(output_color(lit), in.color.a);
}
