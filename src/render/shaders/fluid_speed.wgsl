// The fluid's fastest particle on the GPU (src/render/fluid.rs), for the explosion verdict that
// the CPU's step gives itself (Fluid::check_explosion): after each step, the largest |v|² of all
// particles goes into `stats[0]`, the running maximum since the buffer was last cleared.
//
// A non-negative f32's bits, read as a u32, order as its values, so atomicMax on the bits takes
// the largest speed². A particle whose position or velocity is no longer a finite number records
// 0xffffffff (a NaN's bits, above every finite value's), which the CPU reads as "not a number".
@group(0) @binding(0) var<storage, read> pos: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read> vel: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> stats: array<atomic<u32>, 4>;

// The workgroup's largest first, then one atomic per workgroup on the buffer (a million threads
// on one address would queue up).
var<workgroup> largest: atomic<u32>;

const NOT_FINITE: u32 = 0xffffffffu;

// Whether the f32 of bits `b` is infinite or NaN (its exponent all ones): a compiler may assume
// that `x != x` is false.
fn not_finite(b: u32) -> bool {
    return (b & 0x7f800000u) == 0x7f800000u;
}

@compute @workgroup_size(64)
fn fastest(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    let i = gid.x;
    if (i < arrayLength(&vel)) {
        let v = vel[i].xyz;
        let p = bitcast<vec3<u32>>(pos[i].xyz);
        var bits = bitcast<u32>(dot(v, v));
        if (not_finite(bits) || not_finite(p.x) || not_finite(p.y) || not_finite(p.z)) {
            bits = NOT_FINITE;
        }
        atomicMax(&largest, bits);
    }
    workgroupBarrier();
    if (li == 0u) {
        atomicMax(&stats[0], atomicLoad(&largest));
    }
}
