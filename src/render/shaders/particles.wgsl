// The particle system of src/particles on the GPU (WebGPU compute): the same model as
// ParticleSystem::step (spawn from the emitters' distributions, age and kill, the exact ballistic
// path with bounces on the floor and on spheres, colour by age), one thread per particle slot.
// Differences, by design: the random numbers come from a hash of (slot, step), not the CPU's
// generator, and dead slots are refilled in ring order instead of by swapping (see
// src/figures/gpu.rs, ParticleGpuParams).
struct Particle {
    pos: vec4<f32>,   // xyz, w: age (s)
    vel: vec4<f32>,   // xyz, w: lifetime (s)
    info: vec4<f32>,  // x: radius, y: 1 = alive, z: 1 = resting, w: emitter
};
struct Emitter {
    pos: vec4<f32>,    // centre, w: ball radius
    dir: vec4<f32>,    // cone axis (unit), w: half-angle (rad)
    speed: vec4<f32>,  // min, max, kind (0 cone, 1 sphere), unused
    life: vec4<f32>,   // lifetime min, max; size min, max
    birth: vec4<f32>,
    death: vec4<f32>,
};
struct Params {
    gravity: vec4<f32>,       // xyz, w: dt
    floor: vec4<f32>,         // x: 1 = floor, y: floor height, z: restitution, w: friction
    counts: vec4<u32>,        // capacity, ring start of this step's spawns, spheres, seed
    spawn: vec4<u32>,         // particles to spawn per emitter this step
    spheres: array<vec4<f32>, 8>,
    emitters: array<Emitter, 4>,
};
struct Instance {          // the renderer's SpriteInstance: an atlas sprite
    center: vec3<f32>,
    half_size: f32,
    uv: vec4<f32>,
    color: vec4<f32>,
};
// The figure's sprites (src/figures/particles.rs, SPRITE_SCALE) and the smoke atlas's grid
// (src/particles/sprites.rs, SMOKE_ATLAS); a native test checks that these match.
const SPRITE_SCALE: f32 = 2.6;
const ATLAS_COLUMNS: u32 = 4u;
const ATLAS_ROWS: u32 = 4u;
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read_write> particles: array<Particle>;
@group(0) @binding(2) var<storage, read_write> instances: array<Instance>;

const TAU: f32 = 6.283185307;
const REST_SPEED: f32 = 0.05;
const MAX_BOUNCES: u32 = 8u;

fn pcg(v: u32) -> u32 {
    let state = v * 747796405u + 2891336453u;
    let word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
var<private> rng_state: u32;
fn unit() -> f32 {
    rng_state = pcg(rng_state);
    return f32(rng_state >> 8u) * (1.0 / 16777216.0);
}
fn range(lo: f32, hi: f32) -> f32 { return lo + (hi - lo) * unit(); }
fn on_unit_sphere() -> vec3<f32> {
    let z = range(-1.0, 1.0);
    let phi = range(0.0, TAU);
    let r = sqrt(max(1.0 - z * z, 0.0));
    return vec3<f32>(r * cos(phi), z, r * sin(phi));
}
// Rotation taking +z to the unit vector a, applied to v (Rodrigues; a = -z flips about x).
fn from_z(a: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    let c = a.z;
    if (c < -0.999999) { return vec3<f32>(v.x, -v.y, -v.z); }
    let k = vec3<f32>(-a.y, a.x, 0.0); // z × a
    return v * c + cross(k, v) + k * (dot(k, v) / (1.0 + c));
}

@compute @workgroup_size(64)
fn spawn(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    var e = 0u;
    var before = 0u;
    var total = 0u;
    for (var k = 0u; k < 4u; k++) {
        if (i >= total + params.spawn[k]) { e = k + 1u; before = total + params.spawn[k]; }
        total += params.spawn[k];
    }
    if (i >= total) { return; }
    let slot = (params.counts.y + i) % params.counts.x;
    rng_state = pcg(slot ^ pcg(params.counts.w + i * 1664525u));
    let em = params.emitters[e];
    let p = em.pos.xyz + em.pos.w * on_unit_sphere() * pow(unit(), 1.0 / 3.0);
    var v: vec3<f32>;
    if (em.speed.z < 0.5) {
        let cos_max = cos(clamp(em.dir.w, 0.0, 3.14159265));
        let z = range(cos_max, 1.0);
        let phi = range(0.0, TAU);
        let r = sqrt(max(1.0 - z * z, 0.0));
        v = from_z(em.dir.xyz, vec3<f32>(r * cos(phi), r * sin(phi), z)) * range(em.speed.x, em.speed.y);
    } else {
        v = on_unit_sphere() * range(em.speed.x, em.speed.y);
    }
    let life = range(em.life.x, em.life.y);
    let size = range(em.life.z, em.life.w);
    particles[slot] = Particle(vec4<f32>(p, 0.0), vec4<f32>(v, life), vec4<f32>(size, 1.0, 0.0, f32(e)));
}

// free_fall(p0, v0, g, t) = (g t²/2 + v0 t + p0, g t + v0)
fn fall_p(p: vec3<f32>, v: vec3<f32>, g: vec3<f32>, t: f32) -> vec3<f32> { return 0.5 * g * t * t + v * t + p; }

// crate::particles::floor_time_of_impact; -1 when none.
fn floor_toi(y0: f32, vy: f32, gy: f32, floor_y: f32, t_max: f32) -> f32 {
    let h = y0 - floor_y;
    if (h < 0.0 || (h == 0.0 && vy <= 0.0)) { return select(-1.0, 0.0, vy <= 0.0); }
    var t: f32;
    if (gy == 0.0) {
        if (vy >= 0.0) { return -1.0; }
        t = -h / vy;
    } else {
        let disc = vy * vy - 2.0 * gy * h;
        if (disc < 0.0) { return -1.0; }
        let root = sqrt(disc);
        if (vy > 0.0) {
            if (gy >= 0.0) { return -1.0; }
            t = (-vy - root) / gy;
        } else {
            let denom = -vy + root;
            if (denom <= 0.0) { return -1.0; }
            t = 2.0 * h / denom;
        }
    }
    return select(-1.0, t, t <= t_max);
}

fn sphere_f(p: vec3<f32>, v: vec3<f32>, g: vec3<f32>, s: vec4<f32>, t: f32) -> f32 {
    let d = fall_p(p, v, g, t) - s.xyz;
    return dot(d, d) - s.w * s.w;
}
// crate::particles::sphere_time_of_impact: 16 samples, then bisection; -1 when none.
fn sphere_toi(p: vec3<f32>, v: vec3<f32>, g: vec3<f32>, s: vec4<f32>, t_max: f32) -> f32 {
    if (sphere_f(p, v, g, s, 0.0) <= 0.0
        && (dot(p - s.xyz, v) < 0.0 || sphere_f(p, v, g, s, t_max / 16.0) < 0.0)) {
        return 0.0;
    }
    var lo = 0.0;
    for (var k = 1u; k <= 16u; k++) {
        let hi = t_max * f32(k) / 16.0;
        if (sphere_f(p, v, g, s, hi) <= 0.0) {
            var a = lo;
            var b = hi;
            for (var n = 0u; n < 40u; n++) {
                let m = 0.5 * (a + b);
                if (sphere_f(p, v, g, s, m) > 0.0) { a = m; } else { b = m; }
            }
            return a;
        }
        lo = hi;
    }
    return -1.0;
}

fn bounce(v: vec3<f32>, n: vec3<f32>, e: f32, mu: f32) -> vec3<f32> {
    let vn = dot(v, n) * n;
    let vt = v - vn;
    let dvn = (1.0 + e) * length(vn);
    let vt_len = length(vt);
    let keep = select(0.0, max(1.0 - mu * dvn / vt_len, 0.0), vt_len > 0.0);
    return -e * vn + keep * vt;
}

struct State { p: vec3<f32>, v: vec3<f32>, resting: bool };

// crate::particles::sphere_contact_force: how hard the sphere holds a particle moving along it.
fn contact_force(n: vec3<f32>, v: vec3<f32>, g: vec3<f32>, sp: vec4<f32>) -> f32 {
    return -dot(g, n) - dot(v, v) / sp.w;
}

// The sphere slide of crate::particles::ballistic_step: gravity along the surface, friction mu N,
// a step along the tangent plane, then back onto the surface.
fn sphere_slide(s: State, sp: vec4<f32>, dt: f32) -> State {
    var o = s;
    let g = params.gravity.xyz;
    let d = s.p - sp.xyz;
    let n = select(vec3<f32>(0.0, 1.0, 0.0), normalize(d), dot(d, d) > 0.0);
    let press = max(contact_force(n, s.v, g, sp), 0.0);
    var vt = s.v + (g - dot(g, n) * n) * dt;
    let slow = params.floor.w * press * dt;
    let len = length(vt);
    vt = select(vec3<f32>(0.0), vt * (1.0 - slow / len), len > slow);
    let d1 = s.p + vt * dt - sp.xyz;
    let n1 = select(n, normalize(d1), dot(d1, d1) > 0.0);
    o.p = sp.xyz + n1 * sp.w;
    o.v = vt - dot(vt, n1) * n1;
    return o;
}

// The resting branch of crate::particles::ballistic_step: slide on the floor with friction.
fn slide(s: State, dt: f32) -> State {
    var o = s;
    let g = params.gravity.xyz;
    var vt = vec3<f32>(s.v.x, 0.0, s.v.z) + vec3<f32>(g.x, 0.0, g.z) * dt;
    let slow = params.floor.w * (-g.y) * dt;
    let len = length(vt);
    vt = select(vec3<f32>(0.0), vt * (1.0 - slow / len), len > slow);
    o.p = s.p + vt * dt;
    o.p.y = params.floor.y;
    o.v = vt;
    return o;
}

// crate::particles::ballistic_step.
fn ballistic(s0: State, dt: f32) -> State {
    var s = s0;
    let g = params.gravity.xyz;
    let has_floor = params.floor.x > 0.5;
    if (s.resting) {
        if (has_floor && g.y <= 0.0) { return slide(s, dt); }
        s.resting = false;
    }
    var remaining = dt;
    for (var b = 0u; b < MAX_BOUNCES; b++) {
        var t_hit = 1e30;
        var which = -2; // -1 floor, k sphere
        if (has_floor) {
            let t = floor_toi(s.p.y, s.v.y, g.y, params.floor.y, remaining);
            if (t >= 0.0) { t_hit = t; which = -1; }
        }
        for (var k = 0u; k < params.counts.z; k++) {
            let t = sphere_toi(s.p, s.v, g, params.spheres[k], remaining);
            if (t >= 0.0 && t < t_hit) { t_hit = t; which = i32(k); }
        }
        if (which == -2) {
            s.p = fall_p(s.p, s.v, g, remaining);
            s.v = g * remaining + s.v;
            break;
        }
        let w = g * t_hit + s.v;
        s.p = fall_p(s.p, s.v, g, t_hit);
        remaining -= t_hit;
        if (which == -1) {
            s.p.y = params.floor.y;
            s.v = bounce(w, vec3<f32>(0.0, 1.0, 0.0), params.floor.z, params.floor.w);
            if (s.v.y < REST_SPEED && g.y < 0.0) {
                s.v.y = 0.0;
                s.resting = true;
                s = slide(s, remaining);
                remaining = 0.0;
            }
        } else {
            let sp = params.spheres[u32(which)];
            let d = s.p - sp.xyz;
            let n = select(vec3<f32>(0.0, 1.0, 0.0), normalize(d), dot(d, d) > 0.0);
            s.p = sp.xyz + n * sp.w;
            s.v = bounce(w, n, params.floor.z, params.floor.w);
            if (dot(s.v, n) < REST_SPEED) {
                s.v -= dot(s.v, n) * n;
                if (contact_force(n, s.v, g, sp) > 0.0) {
                    s = sphere_slide(s, sp, remaining);
                    remaining = 0.0;
                } else {
                    s.p = sp.xyz + n * (sp.w * (1.0 + 1e-6));
                }
            }
        }
        if (remaining <= 0.0) { break; }
    }
    if (has_floor) { s.p.y = max(s.p.y, params.floor.y); }
    return s;
}

@compute @workgroup_size(64)
fn update(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (i >= params.counts.x) { return; }
    var q = particles[i];
    let dt = params.gravity.w;
    if (q.info.y > 0.5) {
        q.pos.w += dt;
        if (q.pos.w >= q.vel.w) {
            q.info.y = 0.0;
        } else {
            let s = ballistic(State(q.pos.xyz, q.vel.xyz, q.info.z > 0.5), dt);
            q.pos = vec4<f32>(s.p, q.pos.w);
            q.vel = vec4<f32>(s.v, q.vel.w);
            q.info.z = select(0.0, 1.0, s.resting);
        }
        particles[i] = q;
    }
    let em = params.emitters[u32(q.info.w)];
    let t = clamp(q.pos.w / max(q.vel.w, 1e-6), 0.0, 1.0);
    let alive = q.info.y > 0.5;
    // As the CPU figure draws its sprites: the atlas frame for the life fraction (Atlas::frame_at),
    // the colour's alpha through a square root (the atlas thins the puff out on its own).
    let frames = ATLAS_COLUMNS * ATLAS_ROWS;
    let frame = min(u32(t * f32(frames)), frames - 1u);
    let cell = vec2<f32>(f32(frame % ATLAS_COLUMNS), f32(frame / ATLAS_COLUMNS));
    let size = vec2<f32>(1.0 / f32(ATLAS_COLUMNS), 1.0 / f32(ATLAS_ROWS));
    let uv = vec4<f32>(cell * size, (cell + 1.0) * size);
    let c = mix(em.birth, em.death, t);
    instances[i] = Instance(q.pos.xyz, select(0.0, SPRITE_SCALE * q.info.x, alive), uv,
        vec4<f32>(c.rgb, sqrt(max(c.a, 0.0))));
}
