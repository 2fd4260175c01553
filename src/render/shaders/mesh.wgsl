// Lit triangle meshes, shaded by common.wgsl's `shade` (or unlit).
struct Object {
    model: mat4x4<f32>,
    normal_matrix: mat4x4<f32>, // inverse transpose of the model matrix (normals stay perpendicular)
    color: vec4<f32>,           // linear RGB, used when flags.x = 0
    flags: vec4<f32>,           // x: 1 = per-vertex colour; y: 1 = unlit
};
@group(1) @binding(0) var<uniform> object: Object;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};
struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world_pos: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};

@vertex
fn vs_main(in: VertexIn) -> VertexOut {
    var out: VertexOut;
    let world = object.model * vec4<f32>(in.position, 1.0);
    out.clip = globals.proj * globals.view * world;
    out.world_pos = world.xyz;
    out.world_normal = (object.normal_matrix * vec4<f32>(in.normal, 0.0)).xyz;
    out.color = select(object.color, in.color, object.flags.x > 0.5);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let albedo = in.color.rgb;
    if (object.flags.y > 0.5) {
        return vec4<f32>(output_color(albedo), in.color.a);
    }
    let lit = shade(albedo, in.world_pos, in.world_normal);
    return vec4<f32>(output_color(lit), in.color.a);
}
