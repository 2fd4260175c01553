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
