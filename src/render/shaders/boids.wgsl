// One step of the flock of src/boids on the GPU (WebGPU compute): the same model as Flock::step
// (cohesion, alignment, separation, force law, field of view, leader, predator, obstacles,
// bounds, semi-implicit Euler, speed clamp), one thread per boid. Forces read the previous
// state (buffer `src`) and the new state goes to `dst`, as the CPU computes every force before
// moving any boid. Neighbours: the naive O(N²) loop, through workgroup memory in tiles of 64.
struct Boid {
    pos: vec4<f32>,  // xyz, w unused
    vel: vec4<f32>,
};
struct Params {
    rules: vec4<f32>,     // cohesion weight, alignment weight, separation weight, dt
    radii: vec4<f32>,     // squared radii: cohesion, alignment, separation, force law
    law: vec4<f32>,       // a1, a2, k, x0
    misc: vec4<f32>,      // law kind (0 none, 1 inverse power, 2 Gaussian), cos(fov / 2) (or -2 for all round), max speed, max force
    bounds: vec4<f32>,    // xyz, w: bounds weight
    leader: vec4<f32>,    // target xyz of the leader this step, w: leader weight (0: none)
    predator: vec4<f32>,  // flee radius², flee weight, 1 = on, predator search radius²
    counts: vec4<u32>,    // boids, obstacles, unused, unused
    avoid: vec4<f32>,     // x: avoid weight, y: min speed
    looks: array<vec4<f32>, 3>,  // boid, leader, predator: linear RGB, w: sprite radius (m)
    obstacles: array<vec4<f32>, 8>,
};
struct Instance {
    center: vec3<f32>,
    radius: f32,
    color: vec4<f32>,
};
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> src: array<Boid>;
@group(0) @binding(2) var<storage, read_write> dst: array<Boid>;
@group(0) @binding(3) var<storage, read_write> instances: array<Instance>;

const TILE: u32 = 64u;
var<workgroup> tile: array<Boid, 64>;

fn clamp_length(v: vec3<f32>, max_len: f32) -> vec3<f32> {
    let l2 = dot(v, v);
    if (l2 > max_len * max_len) { return v * (max_len / sqrt(l2)); }
    return v;
}

// v with its length clamped into [lo, hi] (BoidParams::min_speed and max_speed, clamp_speed in
// src/boids/mod.rs); a boid at rest stays at rest.
fn clamp_speed(v: vec3<f32>, lo: f32, hi: f32) -> vec3<f32> {
    let l2 = dot(v, v);
    if (l2 > hi * hi) { return v * (hi / sqrt(l2)); }
    if (l2 < lo * lo && l2 > 0.0) { return v * (lo / sqrt(l2)); }
    return v;
}

fn law_f(x: f32) -> f32 {
    let kind = params.misc.x;
    if (kind < 0.5) { return 0.0; }
    if (kind < 1.5) {
        let x2 = x * x;
        return params.law.x / x2 - params.law.y / (x2 * x2);
    }
    let u = (x - params.law.w) / params.law.w;
    return params.law.x * exp(-params.law.z * u * u) - params.law.y * exp(-x / params.law.w);
}

@compute @workgroup_size(64)
fn step(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>) {
    let n = params.counts.x;
    let i = gid.x;
    let me = src[min(i, n - 1u)];
    let p = me.pos.xyz;
    let v = me.vel.xyz;
    let has_leader = params.leader.w > 0.0;
    let leader = select(n, 0u, has_leader);
    let predator = select(n, select(0u, 1u, has_leader), params.predator.z > 0.5 && n > select(0u, 1u, has_leader));
    var centre = vec3<f32>(0.0);
    var mean_v = vec3<f32>(0.0);
    var sep = vec3<f32>(0.0);
    var law = vec3<f32>(0.0);
    var n_c = 0u;
    var n_a = 0u;
    var best_d = 1e30;
    var best_q = p;
    let v_len = length(v);
    let cos_half = params.misc.y;
    for (var start = 0u; start < n; start += TILE) {
        let j_load = start + lid.x;
        if (j_load < n) { tile[lid.x] = src[j_load]; }
        workgroupBarrier();
        let count = min(TILE, n - start);
        for (var t = 0u; t < count; t++) {
            let j = start + t;
            if (j == i) { continue; }
            let q = tile[t].pos.xyz;
            let d = p - q;
            let d2 = dot(d, d);
            if (i == predator) {
                if (j != leader && d2 < best_d && d2 < params.predator.w) { best_d = d2; best_q = q; }
                continue;
            }
            if (j == predator) { continue; }
            if (cos_half > -1.5 && v_len > 0.0) {
                let l = sqrt(d2);
                if (l > 0.0 && dot(-d, v) < cos_half * l * v_len) { continue; }
            }
            if (d2 <= params.radii.x) { centre += q; n_c++; }
            if (d2 <= params.radii.y) { mean_v += tile[t].vel.xyz; n_a++; }
            if (d2 <= params.radii.z && d2 > 0.0) { sep += d / d2; }
            if (d2 <= params.radii.w && d2 > 0.0 && params.misc.x > 0.5) {
                let x = sqrt(d2);
                law += law_f(x) * (-d / x);
            }
        }
        workgroupBarrier();
    }
    if (i >= n) { return; }
    var force = vec3<f32>(0.0);
    if (i == predator) {
        if (best_d < 1e30) { force += 3.0 * (best_q - p); } else { force += -p * 0.5; }
    } else {
        if (n_c > 0u) { force += params.rules.x * (centre / f32(n_c) - p); }
        if (n_a > 0u) { force += params.rules.y * (mean_v / f32(n_a) - v); }
        force += params.rules.z * sep + law;
        if (has_leader) { force += params.leader.w * clamp_length(src[0].pos.xyz - p, 2.0); }
        if (predator < n) {
            let d = p - src[predator].pos.xyz;
            let d2 = dot(d, d);
            if (d2 < params.predator.x && d2 > 0.0) { force += params.predator.y * d / d2; }
        }
    }
    for (var k = 0u; k < params.counts.y; k++) {
        let o = params.obstacles[k];
        let d = p - o.xyz;
        let dist = length(d);
        let margin = o.w + 0.6;
        if (dist < margin && dist > 0.0) { force += params.avoid.x * (margin - dist) / 0.6 * (d / dist); }
    }
    let b = params.bounds.xyz;
    force -= params.bounds.w * (p - clamp(p, -b, b));
    force = clamp_length(force, params.misc.w);

    let dt = params.rules.w;
    var np = p;
    var nv = v;
    if (i == leader) {
        nv = clamp_length((params.leader.xyz - p) / max(dt, 1e-6), params.misc.z * 1.5);
        np = p + nv * dt;
    } else {
        nv = v + force * dt;
        np = p + nv * dt;
        let top = params.misc.z * select(1.0, 1.3, i == predator);
        let clamped = clamp_speed(nv, min(params.avoid.y, top), top);
        np += (clamped - nv) * dt;
        nv = clamped;
    }
    dst[i] = Boid(vec4<f32>(np, 0.0), vec4<f32>(nv, 0.0));
    let look = params.looks[select(select(0u, 2u, i == predator), 1u, i == leader)];
    instances[i] = Instance(np, look.w, vec4<f32>(look.xyz, 1.0));
}
