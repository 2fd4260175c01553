// One step of the fluid of src/fluid on the GPU (WebGPU compute): SPH (Müller et al. 2003) or
// PBF (Macklin and Müller 2013), the same kernels, equation of state, forces, collisions and
// Jacobi iterations as Fluid::step, one thread per particle. Neighbours come from the GPU grid
// (grid.wgsl; this file is prefixed by grid_common.wgsl) built just before on `pos` (SPH) or on
// the predicted positions `pred` (PBF): the 3 × 3 × 3 cells around a particle's own, cells one
// kernel radius wide. Each entry point is one of the CPU step's loops; a loop that reads its
// neighbours' results of the loop before runs as the next dispatch, which sees all of them.
//
// SPH:  sph_density, sph_force, sph_move.
// PBF:  pbf_predict, (grid on pred), iterations × (pbf_lambda, pbf_delta, pbf_apply),
//       pbf_density, [pbf_omega, pbf_confine], pbf_xsph, pbf_finish.
struct Params {
    step: vec4<f32>,      // h, h², particle mass m, dt
    kern: vec4<f32>,      // constants of poly6, spiky's gradient, the viscosity Laplacian; poly6 at 0.2 h
    sph: vec4<f32>,       // rest density ρ₀, stiffness k, viscosity μ, equation of state (0 ideal gas, 1 Tait)
    gravity: vec4<f32>,   // xyz, w: restitution
    pbf: vec4<f32>,       // friction, relaxation ε, s_corr's k times λ's unit, XSPH c
    misc: vec4<f32>,      // vorticity ε, 1 in 2D, sprite radius (m), the speed drawn red (m/s)
    obstacle: vec4<f32>,  // centre xyz, radius (0: none)
    counts: vec4<u32>,    // particles, walls, 1 for PBF, unused
    looks: array<vec4<f32>, 2>,   // rgb at rest and at the red speed, w: the grey between
    walls: array<vec4<f32>, 6>,   // unit normal xyz, offset: inside where n·x ≥ offset
};
struct Instance {
    center: vec3<f32>,
    radius: f32,
    color: vec4<f32>,
};
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<uniform> grid: GridParams;
@group(0) @binding(2) var<storage, read> cell_start: array<u32>;
@group(0) @binding(3) var<storage, read> sorted: array<u32>;
@group(0) @binding(4) var<storage, read_write> pos: array<vec4<f32>>;    // xyz
@group(0) @binding(5) var<storage, read_write> vel: array<vec4<f32>>;    // xyz
@group(0) @binding(6) var<storage, read_write> pred: array<vec4<f32>>;   // PBF: predicted xyz
@group(0) @binding(7) var<storage, read_write> aux: array<vec4<f32>>;    // density ρ, pressure (SPH) or λ (PBF)
@group(0) @binding(8) var<storage, read_write> delta: array<vec4<f32>>;  // a loop's result per particle
@group(0) @binding(9) var<storage, read_write> instances: array<Instance>;

const NONE: u32 = 0xffffffffu;

// The poly6 kernel at squared distance r2 (Kernels::poly6).
fn poly6(r2: f32) -> f32 {
    let h2 = params.step.y;
    if (!(r2 < h2)) { return 0.0; }
    let d = h2 - r2;
    return params.kern.x * d * d * d;
}

// The spiky kernel's gradient at rij = x_i − x_j (Kernels::spiky_gradient): odd, zero at 0.
fn spiky_gradient(rij: vec3<f32>) -> vec3<f32> {
    let h2 = params.step.y;
    let r2 = dot(rij, rij);
    if (!(r2 < h2) || r2 <= 1e-24 * h2) { return vec3<f32>(0.0); }
    let r = sqrt(r2);
    let q = params.step.x - r;
    return rij * (-params.kern.y * q * q / r);
}

fn viscosity_laplacian(r: f32) -> f32 {
    if (!(r < params.step.x)) { return 0.0; }
    return params.kern.z * (params.step.x - r);
}

// Fluid::pressure.
fn pressure(rho: f32) -> f32 {
    let k = params.sph.y;
    let rho0 = params.sph.x;
    if (params.sph.w < 0.5) { return k * (rho - rho0); }
    let x = rho / rho0;
    let x2 = x * x;
    return max(k * rho0 / 7.0 * (x2 * x2 * x2 * x - 1.0), 0.0);
}

// particles::collide::bounce_velocity.
fn bounce(v: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let e = params.gravity.w;
    let mu = params.pbf.x;
    let vn = dot(v, n) * n;
    let vt = v - vn;
    let dvn = (1.0 + e) * length(vn);
    let vt_len = length(vt);
    var keep = 0.0;
    if (vt_len > 0.0) { keep = max(1.0 - mu * dvn / vt_len, 0.0); }
    return -e * vn + keep * vt;
}

// Fluid::collide: p pushed back inside the box and out of the obstacle; with `bounce_v`, the part
// of v into the surface bounces.
fn collide(p: ptr<function, vec3<f32>>, v: ptr<function, vec3<f32>>, bounce_v: bool) {
    for (var k = 0u; k < params.counts.y; k++) {
        let w = params.walls[k];
        let d = dot(w.xyz, *p) - w.w;
        if (d < 0.0) {
            *p -= d * w.xyz;
            if (bounce_v && dot(*v, w.xyz) < 0.0) { *v = bounce(*v, w.xyz); }
        }
    }
    let s = params.obstacle;
    if (s.w > 0.0) {
        var q = *p - s.xyz;
        if (params.misc.y > 0.5) { q.z = 0.0; }
        let r = length(q);
        if (r < s.w && r > 0.0) {
            let n = q / r;
            *p += (s.w - r) * n;
            if (bounce_v && dot(*v, n) < 0.0) { *v = bounce(*v, n); }
        }
    }
}

// Walks the particles in the cells around a point's own: `next` gives their indices (the point's
// own among them) and NONE after the last.
struct Cursor {
    lo: vec3<u32>,
    hi: vec3<u32>,
    j: u32,
    k: u32,
    slot: u32,
    end: u32,
};

fn start_row(c: ptr<function, Cursor>) {
    let row = grid.dims.x * ((*c).j + grid.dims.y * (*c).k);
    (*c).slot = cell_start[row + (*c).lo.x];
    (*c).end = cell_start[row + (*c).hi.x + 1u];
}

fn cursor(p: vec3<f32>) -> Cursor {
    let c = grid_coords(grid, p);
    let lo = c - min(c, vec3<u32>(1u));
    let hi = min(c + 1u, grid.dims.xyz - vec3<u32>(1u));
    var cur = Cursor(lo, hi, lo.y, lo.z, 0u, 0u);
    start_row(&cur);
    return cur;
}

fn next(c: ptr<function, Cursor>) -> u32 {
    loop {
        if ((*c).slot < (*c).end) {
            let s = (*c).slot;
            (*c).slot++;
            return sorted[s];
        }
        (*c).j++;
        if ((*c).j > (*c).hi.y) {
            (*c).j = (*c).lo.y;
            (*c).k++;
            if ((*c).k > (*c).hi.z) { return NONE; }
        }
        start_row(c);
    }
}

// ρ_i = m (W(0) + Σ_j W(|x_i − x_j|)) at the positions of `pos` or of `pred`.
fn density_at(i: u32, predicted: bool) -> f32 {
    var xi = pos[i].xyz;
    if (predicted) { xi = pred[i].xyz; }
    var w = poly6(0.0);
    var c = cursor(xi);
    for (var j = next(&c); j != NONE; j = next(&c)) {
        if (j == i) { continue; }
        var xj = pos[j].xyz;
        if (predicted) { xj = pred[j].xyz; }
        let d = xi - xj;
        w += poly6(dot(d, d));
    }
    return params.step.z * w;
}

// The speed-coloured sprite of particle i (the CPU splash's colours).
fn sprite(i: u32, p: vec3<f32>, v: vec3<f32>) {
    let s = min(length(v) / params.misc.w, 1.0);
    let n = 1.2 * s - 0.6;
    let t = min(abs(n) / 0.6, 1.0);
    let end = select(params.looks[0].xyz, params.looks[1].xyz, n >= 0.0);
    let grey = vec3<f32>(params.looks[0].w);
    instances[i] = Instance(p, params.misc.z, vec4<f32>(mix(grey, end, t), 1.0));
}

@compute @workgroup_size(64)
fn sph_density(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let rho = density_at(i, false);
    aux[i] = vec4<f32>(rho, pressure(rho), 0.0, 0.0);
}

// F_i = Σ_j −m² (p_i + p_j) / (2 ρ_i ρ_j) ∇W_spiky(x_i − x_j) + μ m² (v_j − v_i) / (ρ_i ρ_j) ∇²W_visc,
// then the acceleration F_i / m + g into `delta`.
@compute @workgroup_size(64)
fn sph_force(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let m = params.step.z;
    let mu = params.sph.z;
    let xi = pos[i].xyz;
    let vi = vel[i].xyz;
    let ai = aux[i];
    var f = vec3<f32>(0.0);
    var c = cursor(xi);
    for (var j = next(&c); j != NONE; j = next(&c)) {
        if (j == i) { continue; }
        let aj = aux[j];
        let rij = xi - pos[j].xyz;
        let rr = ai.x * aj.x;
        f += -(m * m) * (ai.y + aj.y) / (2.0 * rr) * spiky_gradient(rij);
        f += mu * (m * m) / rr * viscosity_laplacian(length(rij)) * (vel[j].xyz - vi);
    }
    delta[i] = vec4<f32>(f / m + params.gravity.xyz, 0.0);
}

// Semi-implicit Euler (velocity first), then the collisions.
@compute @workgroup_size(64)
fn sph_move(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let dt = params.step.w;
    var v = vel[i].xyz + dt * delta[i].xyz;
    var p = pos[i].xyz + dt * v;
    collide(&p, &v, true);
    pos[i] = vec4<f32>(p, 0.0);
    vel[i] = vec4<f32>(v, 0.0);
    sprite(i, p, v);
}

// v += Δt g, x* = x + Δt v, pushed inside.
@compute @workgroup_size(64)
fn pbf_predict(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let dt = params.step.w;
    var v = vel[i].xyz + dt * params.gravity.xyz;
    var x = pos[i].xyz + dt * v;
    collide(&x, &v, false);
    vel[i] = vec4<f32>(v, 0.0);
    pred[i] = vec4<f32>(x, 0.0);
}

// C_i = max(ρ_i/ρ₀ − 1, 0), λ_i = −C_i / (Σ_k |∇_k C_i|² + ε) (pbf_lambda in src/fluid).
@compute @workgroup_size(64)
fn pbf_lambda(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let m = params.step.z;
    let rho0 = params.sph.x;
    let xi = pred[i].xyz;
    var w = poly6(0.0);
    var grad_i = vec3<f32>(0.0);
    var sum = 0.0;
    var c = cursor(xi);
    for (var j = next(&c); j != NONE; j = next(&c)) {
        if (j == i) { continue; }
        let d = xi - pred[j].xyz;
        w += poly6(dot(d, d));
        let g = m / rho0 * spiky_gradient(d);
        grad_i += g;
        sum += dot(g, g);
    }
    let rho = m * w;
    let constraint = max(rho / rho0 - 1.0, 0.0);
    var lambda = 0.0;
    if (constraint > 0.0) { lambda = -constraint / (sum + dot(grad_i, grad_i) + params.pbf.y); }
    aux[i] = vec4<f32>(rho, lambda, 0.0, 0.0);
}

// Δx_i = (m/ρ₀) Σ_j (λ_i + λ_j + s_corr) ∇W(x_i − x_j), s_corr = −k (W(r)/W(0.2 h))⁴.
@compute @workgroup_size(64)
fn pbf_delta(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let xi = pred[i].xyz;
    let li = aux[i].y;
    let k_corr = params.pbf.z;
    var dx = vec3<f32>(0.0);
    var c = cursor(xi);
    for (var j = next(&c); j != NONE; j = next(&c)) {
        if (j == i) { continue; }
        let rij = xi - pred[j].xyz;
        var s_corr = 0.0;
        if (k_corr > 0.0) {
            let ratio = poly6(dot(rij, rij)) / params.kern.w;
            s_corr = -k_corr * ratio * ratio * ratio * ratio;
        }
        dx += (li + aux[j].y + s_corr) * spiky_gradient(rij);
    }
    delta[i] = vec4<f32>(params.step.z / params.sph.x * dx, 0.0);
}

@compute @workgroup_size(64)
fn pbf_apply(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    var x = pred[i].xyz + delta[i].xyz;
    var unused = vec3<f32>(0.0);
    collide(&x, &unused, false);
    pred[i] = vec4<f32>(x, 0.0);
}

// v = (x* − x) / Δt and the density at x*.
@compute @workgroup_size(64)
fn pbf_density(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    vel[i] = vec4<f32>((pred[i].xyz - pos[i].xyz) / params.step.w, 0.0);
    aux[i] = vec4<f32>(density_at(i, true), aux[i].y, 0.0, 0.0);
}

// ω_i = Σ_j (m/ρ_j)(v_j − v_i) × ∇_j W_ij, into `delta` (∇_j W_ij = spiky_gradient(x_j − x_i)).
@compute @workgroup_size(64)
fn pbf_omega(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let m = params.step.z;
    let xi = pred[i].xyz;
    let vi = vel[i].xyz;
    var w = vec3<f32>(0.0);
    var c = cursor(xi);
    for (var j = next(&c); j != NONE; j = next(&c)) {
        if (j == i) { continue; }
        let xj = pred[j].xyz;
        w += m / aux[j].x * cross(vel[j].xyz - vi, spiky_gradient(xj - xi));
    }
    delta[i] = vec4<f32>(w, 0.0);
}

// η = Σ_j (m/ρ_j) |ω_j| ∇W(x_i − x_j), v_i += Δt ε (η/|η| × ω_i).
@compute @workgroup_size(64)
fn pbf_confine(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let m = params.step.z;
    let xi = pred[i].xyz;
    var eta = vec3<f32>(0.0);
    var c = cursor(xi);
    for (var j = next(&c); j != NONE; j = next(&c)) {
        if (j == i) { continue; }
        eta += m / aux[j].x * length(delta[j].xyz) * spiky_gradient(xi - pred[j].xyz);
    }
    let len = length(eta);
    if (len > 1e-9) {
        let dv = params.step.w * params.misc.x * cross(eta / len, delta[i].xyz);
        vel[i] = vec4<f32>(vel[i].xyz + dv, 0.0);
    }
}

// XSPH: Δv_i = c Σ_j (m/ρ_j)(v_j − v_i) W_ij, into `delta`.
@compute @workgroup_size(64)
fn pbf_xsph(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    let m = params.step.z;
    let xi = pred[i].xyz;
    let vi = vel[i].xyz;
    var dv = vec3<f32>(0.0);
    var c = cursor(xi);
    for (var j = next(&c); j != NONE; j = next(&c)) {
        if (j == i) { continue; }
        let d = xi - pred[j].xyz;
        dv += m / aux[j].x * (vel[j].xyz - vi) * poly6(dot(d, d));
    }
    delta[i] = vec4<f32>(params.pbf.w * dv, 0.0);
}

// v += XSPH's Δv (zero when c = 0), x = x*.
@compute @workgroup_size(64)
fn pbf_finish(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.counts.x) { return; }
    var v = vel[i].xyz;
    if (params.pbf.w > 0.0) { v += delta[i].xyz; }
    let x = pred[i].xyz;
    pos[i] = vec4<f32>(x, 0.0);
    vel[i] = vec4<f32>(v, 0.0);
    sprite(i, x, v);
}
