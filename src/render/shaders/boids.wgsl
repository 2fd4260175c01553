// One step of the flock of src/boids on the GPU (WebGPU compute): the same model as Flock::step
// (cohesion, alignment, separation, force law, field of view, leader, predator, obstacles,
// bounds, semi-implicit Euler, speed clamp), one thread per boid. Forces read the previous
// state (buffer `src`) and the new state goes to `dst`, as the CPU computes every force before
// moving any boid. Neighbours: `step` tests every pair, through workgroup memory in tiles of
// 64; `step_grid` reads the 3 × 3 × 3 cells around the boid's own in the GPU grid built from
// `src` just before (grid.wgsl; this file is prefixed by grid_common.wgsl), a row of three
// cells along x being one run of `sorted`.
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
    counts: vec4<u32>,    // boids, obstacles, the predator's reach in grid cells, unused
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
@group(0) @binding(4) var<uniform> grid: GridParams;
@group(0) @binding(5) var<storage, read> cell_start: array<u32>;
@group(0) @binding(6) var<storage, read> sorted: array<u32>;

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

// What a boid gathers from its neighbours.
struct Sums {
    centre: vec3<f32>,
    mean_v: vec3<f32>,
    sep: vec3<f32>,
    law: vec3<f32>,
    n_c: u32,
    n_a: u32,
    best_d: f32,   // the predator: squared distance to the nearest prey so far
    best_q: vec3<f32>,
};

// The boid i in the flock: where it is, where the leader and the predator are (n when absent).
struct Me {
    i: u32,
    p: vec3<f32>,
    v: vec3<f32>,
    v_len: f32,
    leader: u32,
    predator: u32,
};

fn me_of(i: u32) -> Me {
    let n = params.counts.x;
    let b = src[min(i, n - 1u)];
    let has_leader = params.leader.w > 0.0;
    let first_free = select(0u, 1u, has_leader);
    let predator = select(n, first_free, params.predator.z > 0.5 && n > first_free);
    return Me(i, b.pos.xyz, b.vel.xyz, length(b.vel.xyz), select(n, 0u, has_leader), predator);
}

fn no_sums(p: vec3<f32>) -> Sums {
    return Sums(vec3<f32>(0.0), vec3<f32>(0.0), vec3<f32>(0.0), vec3<f32>(0.0), 0u, 0u, 1e30, p);
}

// Adds boid j (at q, velocity vq) to boid `me`'s sums.
fn visit(s: ptr<function, Sums>, me: Me, j: u32, q: vec3<f32>, vq: vec3<f32>) {
    if (j == me.i) { return; }
    let d = me.p - q;
    let d2 = dot(d, d);
    if (me.i == me.predator) {
        if (j != me.leader && d2 < (*s).best_d && d2 < params.predator.w) { (*s).best_d = d2; (*s).best_q = q; }
        return;
    }
    if (j == me.predator) { return; }
    if (params.misc.y > -1.5 && me.v_len > 0.0) {
        let l = sqrt(d2);
        if (l > 0.0 && dot(-d, me.v) < params.misc.y * l * me.v_len) { return; }
    }
    if (d2 <= params.radii.x) { (*s).centre += q; (*s).n_c++; }
    if (d2 <= params.radii.y) { (*s).mean_v += vq; (*s).n_a++; }
    if (d2 <= params.radii.z && d2 > 0.0) { (*s).sep += d / d2; }
    if (d2 <= params.radii.w && d2 > 0.0 && params.misc.x > 0.5) {
        let x = sqrt(d2);
        (*s).law += law_f(x) * (-d / x);
    }
}

@compute @workgroup_size(64)
fn step(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>) {
    let n = params.counts.x;
    let me = me_of(gid.x);
    var s = no_sums(me.p);
    for (var start = 0u; start < n; start += TILE) {
        let j_load = start + lid.x;
        if (j_load < n) { tile[lid.x] = src[j_load]; }
        workgroupBarrier();
        let count = min(TILE, n - start);
        for (var t = 0u; t < count; t++) {
            visit(&s, me, start + t, tile[t].pos.xyz, tile[t].vel.xyz);
        }
        workgroupBarrier();
    }
    if (me.i < n) { finish(me, s); }
}

@compute @workgroup_size(64)
fn step_grid(@builtin(global_invocation_id) gid: vec3<u32>) {
    if (gid.x >= params.counts.x) { return; }
    let me = me_of(gid.x);
    var s = no_sums(me.p);
    let c = grid_coords(grid, me.p);
    // The predator chases prey further than a cell away.
    let reach = select(1u, params.counts.z, me.i == me.predator);
    let lo = c - min(c, vec3<u32>(reach));
    let hi = min(c + reach, grid.dims.xyz - vec3<u32>(1u));
    for (var k = lo.z; k <= hi.z; k++) {
        for (var j = lo.y; j <= hi.y; j++) {
            let row = grid.dims.x * (j + grid.dims.y * k);
            let end = cell_start[row + hi.x + 1u];
            for (var slot = cell_start[row + lo.x]; slot < end; slot++) {
                let other = sorted[slot];
                let b = src[other];
                visit(&s, me, other, b.pos.xyz, b.vel.xyz);
            }
        }
    }
    finish(me, s);
}

// Boid `me`'s force from its sums, then its step, written to `dst` and to its sprite.
fn finish(me: Me, s: Sums) {
    let i = me.i;
    let p = me.p;
    let v = me.v;
    let predator = me.predator;
    let leader = me.leader;
    var force = vec3<f32>(0.0);
    if (i == predator) {
        if (s.best_d < 1e30) { force += 3.0 * (s.best_q - p); } else { force += -p * 0.5; }
    } else {
        if (s.n_c > 0u) { force += params.rules.x * (s.centre / f32(s.n_c) - p); }
        if (s.n_a > 0u) { force += params.rules.y * (s.mean_v / f32(s.n_a) - v); }
        force += params.rules.z * s.sep + s.law;
        if (leader < params.counts.x) { force += params.leader.w * clamp_length(src[0].pos.xyz - p, 2.0); }
        if (predator < params.counts.x) {
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
