// Wide lines: each instance is one segment, expanded here into a screen-space quad `width_px`
// CSS pixels wide with half a width of round cap past each end (so the segments of a polyline
// overlap at their joins and leave no gap at any angle). The same expansion, natively, is
// `crate::draw::stroke_corners`. globals.params: y, z = the target's size in device pixels,
// w = device pixels per CSS pixel.
struct SegmentIn {
    @location(0) a: vec3<f32>,
    @location(1) width_px: f32,
    @location(2) b: vec3<f32>,
    @location(3) depth_bias: f32,
    @location(4) color: vec4<f32>,
    @location(5) dash: vec4<f32>,   // distance along the line at a and b, dash, gap (metres)
};
struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
    // (along, across) in device pixels from `a`, times w, and w itself: dividing by w in the
    // fragment shader undoes the perspective-correct interpolation (WebGL2 has no noperspective).
    @location(1) local_w: vec3<f32>,
    // Segment length and half width in device pixels.
    @location(2) shape: vec2<f32>,
    // The distance along the line (metres), dash and gap lengths.
    @location(3) dash: vec3<f32>,
};

// Moves `p` towards `q` onto the near plane (clip z = 0) when it lies in front of it.
fn clip_to_near(p: vec4<f32>, q: vec4<f32>) -> vec4<f32> {
    if (p.z >= 0.0) {
        return p;
    }
    return mix(p, q, p.z / (p.z - q.z));
}

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, in: SegmentIn) -> VertexOut {
    // Corner k of the quad: end (0 at a, 1 at b) and side (-1, 1), as two triangles.
    var ends = array<f32, 6>(0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
    var sides = array<f32, 6>(-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    let end = ends[vertex % 6u];
    let side = sides[vertex % 6u];
    var out: VertexOut;
    let view_proj = globals.proj * globals.view;
    let ca0 = view_proj * vec4<f32>(in.a, 1.0);
    let cb0 = view_proj * vec4<f32>(in.b, 1.0);
    if (ca0.z < 0.0 && cb0.z < 0.0) {
        out.clip = vec4<f32>(0.0, 0.0, -1.0, 1.0); // wholly in front of the near plane
        return out;
    }
    let ca = clip_to_near(ca0, cb0);
    let cb = clip_to_near(cb0, ca0);
    let half_viewport = 0.5 * globals.params.yz;
    let sa = ca.xy / ca.w * half_viewport;
    let sb = cb.xy / cb.w * half_viewport;
    let length_px = distance(sa, sb);
    let dir = select(vec2<f32>(1.0, 0.0), (sb - sa) / length_px, length_px > 1e-4);
    let normal = vec2<f32>(-dir.y, dir.x);
    let half_width = 0.5 * in.width_px * globals.params.w;
    // One more pixel all round for the antialiased edge.
    let reach = half_width + 1.0;
    let along = select(-reach, length_px + reach, end > 0.5);
    let offset = dir * select(-reach, reach, end > 0.5) + normal * side * reach;
    var clip = select(ca, cb, end > 0.5);
    clip = vec4<f32>(clip.xy + offset / half_viewport * clip.w, clip.zw);
    // Never pulled past the near plane (as line.wgsl).
    clip.z = max(clip.z - in.depth_bias * clip.w, min(clip.z, 0.0));
    out.clip = clip;
    out.color = in.color;
    out.local_w = vec3<f32>(vec2<f32>(along, side * reach) * clip.w, clip.w);
    out.shape = vec2<f32>(length_px, half_width);
    out.dash = vec3<f32>(select(in.dash.x, in.dash.y, end > 0.5), in.dash.z, in.dash.w);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let local = in.local_w.xy / in.local_w.z;
    let length_px = in.shape.x;
    let half_width = in.shape.y;
    // Distance from the segment in device pixels: round caps past either end.
    let along = clamp(local.x, 0.0, length_px);
    let d = distance(local, vec2<f32>(along, 0.0));
    var coverage = clamp(half_width + 0.5 - d, 0.0, 1.0);
    if (in.dash.z > 0.0) {
        // Where this fragment falls in the dash-and-gap period: past the dash, it is a gap.
        let period = in.dash.y + in.dash.z;
        if (in.dash.x - period * floor(in.dash.x / period) > in.dash.y) {
            coverage = 0.0;
        }
    }
    if (coverage <= 0.0) {
        discard;
    }
    return vec4<f32>(output_color(in.color.rgb), in.color.a * coverage);
}
