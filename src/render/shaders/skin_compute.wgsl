// The compute check of GPU skinning (WebGPU only; prefixed by skin_common.wgsl): skins every
// bind-pose vertex with the vertex shader's own formulas into a storage buffer, which a browser
// test reads back and compares with the CPU's skinning, number by number. Mesh space (the draw's
// model matrix is not applied).
@group(0) @binding(0) var<storage, read> rest: array<f32>;        // per vertex: position, normal
@group(0) @binding(1) var<storage, read> influences: array<u32>;  // per vertex: 4 × u16 joints, 4 × f32 weights
@group(0) @binding(2) var<storage, read_write> skinned: array<f32>;  // per vertex: position, normal

@compute @workgroup_size(64)
fn skin_vertices(@builtin(global_invocation_id) id: vec3<u32>) {
    let v = id.x;
    if (v >= arrayLength(&rest) / 6u) { return; }
    let p = vec3<f32>(rest[6u * v], rest[6u * v + 1u], rest[6u * v + 2u]);
    let n = vec3<f32>(rest[6u * v + 3u], rest[6u * v + 4u], rest[6u * v + 5u]);
    let a = influences[6u * v];
    let b = influences[6u * v + 1u];
    let joints = vec4<u32>(a & 0xffffu, a >> 16u, b & 0xffffu, b >> 16u);
    let weights = vec4<f32>(
        bitcast<f32>(influences[6u * v + 2u]), bitcast<f32>(influences[6u * v + 3u]),
        bitcast<f32>(influences[6u * v + 4u]), bitcast<f32>(influences[6u * v + 5u]));
    var s: Skinned;
    if (skin.flags.y > 0.5) {
        s = skin_dqs(p, n, joints, weights);
    } else {
        s = skin_lbs(p, n, joints, weights);
    }
    skinned[6u * v] = s.position.x;
    skinned[6u * v + 1u] = s.position.y;
    skinned[6u * v + 2u] = s.position.z;
    skinned[6u * v + 3u] = s.normal.x;
    skinned[6u * v + 4u] = s.normal.y;
    skinned[6u * v + 5u] = s.normal.z;
}
