// Point sprites: one camera-facing quad per instance, shaded as a small sphere (billboard).
struct InstanceIn {
    @location(0) center: vec3<f32>,
    @location(1) radius: f32,      // world units; negative: drawn over everything
    @location(2) color: vec4<f32>,
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
    // Offset in view space, so the quad always faces the camera.
    let center_view = globals.view * vec4<f32>(in.center, 1.0);
    let pos_view = center_view + vec4<f32>(corner * abs(in.radius), 0.0, 0.0);
    var out: VertexOut;
    out.clip = globals.proj * pos_view;
    if (in.radius < 0.0) {
        // On top: the nearest depth, unless the disc is in front of the near plane (clipped).
        out.clip.z = min(out.clip.z, 0.0);
    }
    out.uv = corner;
    out.color = in.color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let r2 = dot(in.uv, in.uv);
    if (r2 > 1.0) {
        discard;
    }
    // Normal of the sphere this disc stands for, lit from the upper left of the view.
    let n = vec3<f32>(in.uv, sqrt(1.0 - r2));
    let shade = 0.45 + 0.55 * max(dot(n, normalize(vec3<f32>(-0.4, 0.5, 0.8))), 0.0);
    return vec4<f32>(output_color(in.color.rgb * shade), in.color.a);
}
