// The inset's background (crate::draw::inset): one screen-filling triangle drawn inside the
// inset's viewport and scissor rectangle, at the far plane, writing depth whatever was there so
// the inset's own draws start from a cleared depth. Vertices 0-2 draw the border colour, 3-5 the
// fill (the renderer draws the border's rectangle first, then the fill's, one pixel in).
struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec3<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) index: u32) -> VertexOut {
    let corner = index % 3u;
    let uv = vec2<f32>(f32((corner << 1u) & 2u), f32(corner & 2u));
    var out: VertexOut;
    out.clip = vec4<f32>(uv * 2.0 - 1.0, 1.0, 1.0);
    // Linear RGB: a mid grey border around a white fill.
    out.color = select(vec3<f32>(0.32), vec3<f32>(1.0), index >= 3u);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(output_color(in.color), 1.0);
}
