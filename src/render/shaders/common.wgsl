// Shared by every pipeline: the camera and light of the frame (bind group 0).
struct Globals {
    view: mat4x4<f32>,
    proj: mat4x4<f32>,
    eye: vec4<f32>,        // camera position, world space
    light_dir: vec4<f32>,  // unit vector towards the key light, world space
    params: vec4<f32>,     // x: 1 if the shader must encode sRGB itself
};
@group(0) @binding(0) var<uniform> globals: Globals;

// Colours are computed in linear RGB; the framebuffer stores sRGB-encoded values.
fn output_color(linear: vec3<f32>) -> vec3<f32> {
    if (globals.params.x > 0.5) {
        let c = clamp(linear, vec3<f32>(0.0), vec3<f32>(1.0));
        let lo = c * 12.92;
        let hi = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
        return select(hi, lo, c <= vec3<f32>(0.0031308));
    }
    return linear;
}

// The lit meshes' shading (mesh.wgsl, skin.wgsl): Blinn-Phong with a hemisphere ambient term, in
// linear RGB, for a surface of colour `albedo` at `world_pos` with normal `world_normal`.
fn shade(albedo: vec3<f32>, world_pos: vec3<f32>, world_normal: vec3<f32>) -> vec3<f32> {
    let n = normalize(world_normal);
    let l = globals.light_dir.xyz;
    let v = normalize(globals.eye.xyz - world_pos);
    let h = normalize(l + v);
    // Sky above, ground bounce below: cheap ambient that still shows the shape's orientation.
    let ambient = mix(vec3<f32>(0.20, 0.19, 0.18), vec3<f32>(0.32, 0.36, 0.42), 0.5 + 0.5 * n.y);
    let diffuse = max(dot(n, l), 0.0);
    let specular = select(0.0, pow(max(dot(n, h), 0.0), 48.0), diffuse > 0.0);
    return albedo * (ambient + 0.85 * diffuse) + vec3<f32>(0.25 * specular);
}
