// Noise images computed on the GPU: one fragment per texel of the target texture, with the same
// permutation, gradients and arithmetic as the CPU (src/noise/perlin.rs, src/noise/simplex.rs).
// A fragment shader rendering into a texture runs on WebGL2 as well as WebGPU.
struct NoiseParams {
    perm: array<vec4<u32>, 64>, // the 256 entries of the permutation, four per vector
    area: vec4<f32>,            // x0, y0: noise coordinates of the image's top-left corner; dx, dy per texel
    params: vec4<f32>,          // x: z (3D slice); y: 0 = grey image, 1 = 16-bit packed in r, g; z: 0 = Perlin 3D, 1 = simplex 2D
};
@group(0) @binding(0) var<uniform> noise: NoiseParams;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    // One triangle covering the whole target.
    let x = f32(i32(vertex & 1u) * 4 - 1);
    let y = f32(i32(vertex >> 1u) * 4 - 1);
    return vec4<f32>(x, y, 0.0, 1.0);
}

fn perm_at(i: i32) -> i32 {
    let k = u32(i & 255);
    return i32(noise.perm[k >> 2u][k & 3u]);
}

fn fade(t: f32) -> f32 {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

fn lerp(t: f32, a: f32, b: f32) -> f32 {
    return a + t * (b - a);
}

// Perlin's grad(hash, x, y, z): one of twelve cube-edge directions dotted with (x, y, z).
fn grad(hash: i32, x: f32, y: f32, z: f32) -> f32 {
    let h = hash & 15;
    let u = select(y, x, h < 8);
    let v = select(select(z, x, h == 12 || h == 14), y, h < 4);
    return select(-u, u, (h & 1) == 0) + select(-v, v, (h & 2) == 0);
}

// Ken Perlin's improved noise (2002), as his reference.
fn perlin3(p: vec3<f32>) -> f32 {
    let cell = floor(p);
    let xi = i32(cell.x) & 255;
    let yi = i32(cell.y) & 255;
    let zi = i32(cell.z) & 255;
    let x = p.x - cell.x;
    let y = p.y - cell.y;
    let z = p.z - cell.z;
    let u = fade(x);
    let v = fade(y);
    let w = fade(z);
    let a = perm_at(xi) + yi;
    let aa = perm_at(a) + zi;
    let ab = perm_at(a + 1) + zi;
    let b = perm_at(xi + 1) + yi;
    let ba = perm_at(b) + zi;
    let bb = perm_at(b + 1) + zi;
    return lerp(w,
        lerp(v, lerp(u, grad(perm_at(aa), x, y, z), grad(perm_at(ba), x - 1.0, y, z)),
                lerp(u, grad(perm_at(ab), x, y - 1.0, z), grad(perm_at(bb), x - 1.0, y - 1.0, z))),
        lerp(v, lerp(u, grad(perm_at(aa + 1), x, y, z - 1.0), grad(perm_at(ba + 1), x - 1.0, y, z - 1.0)),
                lerp(u, grad(perm_at(ab + 1), x, y - 1.0, z - 1.0), grad(perm_at(bb + 1), x - 1.0, y - 1.0, z - 1.0))));
}

// Gustavson's 2D simplex noise (simplexnoise1234), as src/noise/simplex.rs.
fn grad2s(hash: i32, x: f32, y: f32) -> f32 {
    let h = hash & 7;
    let u = select(y, x, h < 4);
    let v = select(x, y, h < 4);
    return select(u, -u, (h & 1) != 0) + select(2.0 * v, -2.0 * v, (h & 2) != 0);
}

fn bump(d: vec2<f32>, hash: i32) -> f32 {
    let t = 0.5 - dot(d, d);
    if (t < 0.0) {
        return 0.0;
    }
    let t2 = t * t;
    return t2 * t2 * grad2s(hash, d.x, d.y);
}

fn simplex2(p: vec2<f32>) -> f32 {
    let f2 = 0.366025403;
    let g2 = 0.211324865;
    let s = (p.x + p.y) * f2;
    let i = i32(floor(p.x + s));
    let j = i32(floor(p.y + s));
    let t = f32(i + j) * g2;
    let d0 = p - vec2<f32>(f32(i) - t, f32(j) - t);
    var o = vec2<i32>(0, 1);
    if (d0.x > d0.y) {
        o = vec2<i32>(1, 0);
    }
    let d1 = d0 - vec2<f32>(o) + vec2<f32>(g2);
    let d2 = d0 - vec2<f32>(1.0) + vec2<f32>(2.0 * g2);
    let n = bump(d0, perm_at(i + perm_at(j)))
        + bump(d1, perm_at(i + o.x + perm_at(j + o.y)))
        + bump(d2, perm_at(i + 1 + perm_at(j + 1)));
    return 45.23 * n;
}

@fragment
fn fs_main(@builtin(position) frag: vec4<f32>) -> @location(0) vec4<f32> {
    // frag.xy is the texel's centre, (i + 0.5, j + 0.5), row j = 0 at the top.
    let x = noise.area.x + frag.x * noise.area.z;
    let y = noise.area.y + frag.y * noise.area.w;
    var n: f32;
    if (noise.params.z > 0.5) {
        n = simplex2(vec2<f32>(x, y));
    } else {
        n = perlin3(vec3<f32>(x, y, noise.params.x));
    }
    let v = clamp(0.5 + 0.5 * n, 0.0, 1.0);
    if (noise.params.y > 0.5) {
        // 16 bits: high byte in r, low byte in g (an 8-bit target keeps only 1/255 otherwise).
        let q = u32(round(v * 65535.0));
        return vec4<f32>(f32(q >> 8u) / 255.0, f32(q & 255u) / 255.0, 0.0, 1.0);
    }
    return vec4<f32>(v, v, v, 1.0);
}
