// Sprites: one camera-facing textured square per instance, showing one frame of an atlas.
@group(1) @binding(0) var atlas: texture_2d<f32>;
@group(1) @binding(1) var atlas_sampler: sampler;

struct InstanceIn {
    @location(0) center: vec3<f32>,
    @location(1) half_size: f32,   // world units
    @location(2) uv: vec4<f32>,    // u0, v0, u1, v1 of the frame
    @location(3) color: vec4<f32>, // linear RGBA multiplying the texel
};
struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
    @location(1) color: vec4<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, in: InstanceIn) -> VertexOut {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, -1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, 1.0), vec2<f32>(-1.0, 1.0),
    );
    let corner = corners[vertex % 6u];
    // Offset in view space, so the square always faces the camera.
    let center_view = globals.view * vec4<f32>(in.center, 1.0);
    var out: VertexOut;
    out.clip = globals.proj * (center_view + vec4<f32>(corner * in.half_size, 0.0, 0.0));
    // Image rows run downwards: the top of the square (corner.y = 1) shows v0.
    let s = vec2<f32>(0.5 * corner.x + 0.5, 0.5 - 0.5 * corner.y);
    out.uv = mix(in.uv.xy, in.uv.zw, s);
    out.color = in.color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let c = textureSample(atlas, atlas_sampler, in.uv) * in.color;
    if (c.a < 0.004) {
        discard; // fully clear texels write neither colour nor depth
    }
    return vec4<f32>(output_color(c.rgb), c.a);
}
