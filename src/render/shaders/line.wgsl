// World-space line segments with per-vertex colour (curves, skeletons, gizmos, the grid).
struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) color: vec4<f32>,
    // Pulls axes and arrows in front of grid lines at the same place (no z-fighting); 1 draws
    // the line over everything (a skeleton inside a body).
    @location(2) depth_bias: f32,
};
struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
};

@vertex
fn vs_main(in: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = globals.proj * globals.view * vec4<f32>(in.position, 1.0);
    // Never pulled past the near plane; a vertex already in front of it stays clipped.
    out.clip.z = max(out.clip.z - in.depth_bias * out.clip.w, min(out.clip.z, 0.0));
    out.color = in.color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(output_color(in.color.rgb), in.color.a);
}
