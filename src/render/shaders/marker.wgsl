// Markers of a fixed size on screen: dots (a disc) and ticks (a short bar across a path), each
// filled with its colour inside a thin dark rim (a dot also inside a white ring), so they show on
// light backgrounds and dark meshes alike. globals.params: y, z = the target's size in device pixels,
// w = device pixels per CSS pixel.
struct InstanceIn {
    @location(0) center: vec3<f32>,
    @location(1) size_px: f32,      // CSS pixels; negative: drawn over everything
    @location(2) color: vec4<f32>,
    @location(3) tangent: vec3<f32>,
    @location(4) shape: f32,        // 0: dot, 1: tick, 2: contact shadow (size_px in metres)
};
struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
    // Device pixels from the centre along (x) and across (y) the tick's path.
    @location(1) local: vec2<f32>,
    // Half the size in device pixels, the device pixels per CSS pixel, the shape.
    @location(2) params: vec3<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, in: InstanceIn) -> VertexOut {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, -1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, 1.0), vec2<f32>(-1.0, 1.0),
    );
    let corner = corners[vertex % 6u];
    let view_proj = globals.proj * globals.view;
    var out: VertexOut;
    if (in.shape > 1.5) {
        // A contact shadow: a square of the given radius on the ground plane around the centre.
        let world = in.center + vec3<f32>(corner.x, 0.0, corner.y) * in.size_px;
        out.clip = view_proj * vec4<f32>(world, 1.0);
        out.color = in.color;
        out.local = corner;
        out.params = vec3<f32>(1.0, 1.0, in.shape);
        return out;
    }
    var clip = view_proj * vec4<f32>(in.center, 1.0);
    let half_viewport = 0.5 * globals.params.yz;
    let scale = globals.params.w;
    let half_size = 0.5 * abs(in.size_px) * scale;
    // A tick lies across the path: its screen direction from the centre and a point a little
    // further along the tangent. A dot's axes are the screen's.
    var dir = vec2<f32>(1.0, 0.0);
    if (in.shape > 0.5) {
        let ahead = view_proj * vec4<f32>(in.center + in.tangent * 1e-3, 1.0);
        let d = (ahead.xy / ahead.w - clip.xy / clip.w) * half_viewport;
        if (length(d) > 1e-6 && ahead.w > 0.0) {
            dir = normalize(d);
        }
    }
    let normal = vec2<f32>(-dir.y, dir.x);
    let reach = half_size + 1.0;
    let offset = (dir * corner.x + normal * corner.y) * reach;
    if (clip.w <= 0.0) {
        out.clip = vec4<f32>(0.0, 0.0, -1.0, 1.0); // behind the eye
        return out;
    }
    clip = vec4<f32>(clip.xy + offset / half_viewport * clip.w, clip.zw);
    if (in.size_px < 0.0) {
        // On top: the nearest depth, unless the marker is in front of the near plane (clipped).
        clip.z = min(clip.z, 0.0);
    }
    out.clip = clip;
    out.color = in.color;
    out.local = corner * reach;
    out.params = vec3<f32>(half_size, scale, in.shape);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    if (in.params.z > 1.5) {
        // A contact shadow: darkest in the middle, fading smoothly to nothing at the rim.
        let r2 = dot(in.local, in.local);
        if (r2 >= 1.0) {
            discard;
        }
        let fade = (1.0 - r2) * (1.0 - r2);
        return vec4<f32>(output_color(in.color.rgb), in.color.a * fade);
    }
    let half_size = in.params.x;
    let scale = in.params.y;
    // Signed distance to the shape's outline, device pixels (negative inside).
    var d: f32;
    if (in.params.z > 0.5) {
        // A bar 6 CSS pixels thick along the path (4.5 of colour inside the dark rim), `size`
        // long across it.
        let half_extent = vec2<f32>(3.0 * scale, half_size);
        let q = abs(in.local) - half_extent;
        d = length(max(q, vec2<f32>(0.0))) + min(max(q.x, q.y), 0.0);
    } else {
        d = length(in.local) - half_size;
    }
    let coverage = clamp(0.5 - d, 0.0, 1.0);
    if (coverage <= 0.0) {
        discard;
    }
    // From the outside in: 0.75 CSS pixel of dark rim, 1 of white ring (dots only: in a tick's
    // 6 px bar it would leave a 1 px line of colour in a white box), then the colour.
    let rim = 0.75 * scale;
    let ring = select(1.75, 0.0, in.params.z > 0.5) * scale;
    let dark = vec3<f32>(0.02, 0.02, 0.025);
    var rgb = mix(in.color.rgb, vec3<f32>(1.0), clamp(d + ring + 0.5, 0.0, 1.0));
    rgb = mix(rgb, dark, clamp(d + rim + 0.5, 0.0, 1.0));
    return vec4<f32>(output_color(rgb), in.color.a * coverage);
}
