// Skinning in the vertex shader (skin_common.wgsl's formulas), then the same lighting as
// mesh.wgsl. Prefixed by common.wgsl and skin_common.wgsl.
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

@vertex
fn vs_main(in: VertexIn) -> VertexOut {
    var s: Skinned;
    if (skin.flags.y > 0.5) {
        s = skin_dqs(in.position, in.normal, in.joints, in.weights);
    } else {
        s = skin_lbs(in.position, in.normal, in.joints, in.weights);
    }
    var out: VertexOut;
    let world = skin.model * vec4<f32>(s.position, 1.0);
    out.clip = globals.proj * globals.view * world;
    out.world_pos = world.xyz;
    out.world_normal = (skin.normal_matrix * vec4<f32>(s.normal, 0.0)).xyz;
    out.color = select(skin.color, in.color, skin.flags.x > 0.5);
    return out;
}

// Shaded like mesh.wgsl's lit meshes (common.wgsl's `shade`), so a GPU-skinned mesh looks like a
// CPU-skinned one.
@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let lit = shade(in.color.rgb, in.world_pos, in.world_normal);
    return vec4<f32>(output_color(lit), in.color.a);
}
