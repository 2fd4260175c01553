// Textured squares: the square [-1, 1]² of the xz plane placed by a model matrix, unlit.
struct Quad {
    model: mat4x4<f32>,
    tint: vec4<f32>,  // linear RGBA multiplying the texel
    uv: vec4<f32>,    // u0, v0 (texel row 0 is v = 0, at z = -1), u1, v1
    flags: vec4<f32>, // x: 1 = the texture holds sRGB-encoded bytes in a plain (non-sRGB) format
};
@group(1) @binding(0) var<uniform> quad: Quad;
@group(2) @binding(0) var image: texture_2d<f32>;
@group(2) @binding(1) var image_sampler: sampler;

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> VertexOut {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(0.0, 1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(1.0, 0.0),
    );
    let c = corners[vertex % 6u];
    let local = vec4<f32>(2.0 * c.x - 1.0, 0.0, 2.0 * c.y - 1.0, 1.0);
    var out: VertexOut;
    out.clip = globals.proj * globals.view * quad.model * local;
    out.uv = mix(quad.uv.xy, quad.uv.zw, c);
    return out;
}

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let lo = c / 12.92;
    let hi = pow((c + 0.055) / 1.055, vec3<f32>(2.4));
    return select(hi, lo, c <= vec3<f32>(0.04045));
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    var texel = textureSample(image, image_sampler, in.uv);
    if (quad.flags.x > 0.5) {
        texel = vec4<f32>(srgb_to_linear(texel.rgb), texel.a);
    }
    let c = texel * quad.tint;
    return vec4<f32>(output_color(c.rgb), c.a);
}
