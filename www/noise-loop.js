// Noise at scattered points in plain JavaScript, the baselines of the bench page's noise suite
// (www/bench.js): Perlin's improved noise in 3D written as his reference is (a loop a JavaScript
// user would write, with his permutation table), and the `simplex-noise` npm package (4.0.3), the
// library JavaScript users pick, whose 3D simplex noise is a different function of the same kind.
import { createNoise3D } from '../vendor/simplex-noise/simplex-noise.js';

// Perlin's permutation, read from the wasm module's own table, twice over (no wrap-around).
let perm = null;

/** Sets the permutation from the 256 entries of `table` (Permutation::perlin's, from the wasm). */
export function setPermutation(table) {
  perm = new Uint8Array(512);
  perm.set(table, 0);
  perm.set(table, 256);
}

const fade = (t) => t * t * t * (t * (t * 6 - 15) + 10);
const lerp = (t, a, b) => a + t * (b - a);
// The reference's gradient: the hash's low four bits pick ±u ± v among the coordinates.
function grad(hash, x, y, z) {
  const h = hash & 15;
  const u = h < 8 ? x : y;
  const v = h < 4 ? y : h === 12 || h === 14 ? x : z;
  return ((h & 1) === 0 ? u : -u) + ((h & 2) === 0 ? v : -v);
}

/** Perlin's improved noise at (x, y, z), as his reference computes it (in doubles). */
export function perlin3(x, y, z) {
  const p = perm;
  const fx = Math.floor(x), fy = Math.floor(y), fz = Math.floor(z);
  const X = fx & 255, Y = fy & 255, Z = fz & 255;
  x -= fx; y -= fy; z -= fz;
  const u = fade(x), v = fade(y), w = fade(z);
  const A = p[X] + Y, AA = p[A] + Z, AB = p[A + 1] + Z;
  const B = p[X + 1] + Y, BA = p[B] + Z, BB = p[B + 1] + Z;
  return lerp(w,
    lerp(v, lerp(u, grad(p[AA], x, y, z), grad(p[BA], x - 1, y, z)),
      lerp(u, grad(p[AB], x, y - 1, z), grad(p[BB], x - 1, y - 1, z))),
    lerp(v, lerp(u, grad(p[AA + 1], x, y, z - 1), grad(p[BA + 1], x - 1, y, z - 1)),
      lerp(u, grad(p[AB + 1], x, y - 1, z - 1), grad(p[BB + 1], x - 1, y - 1, z - 1))));
}

/** `passes` passes of perlin3 over the points `xyz` ([x0, y0, z0, x1, …]) into `out`. */
export function perlinLoop(xyz, out, passes) {
  for (let it = 0; it < passes; it++) {
    for (let k = 0; k < out.length; k++) out[k] = perlin3(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
  }
}

// One simplex-noise function, its table shuffled by a fixed sequence (mulberry32 from seed 77),
// so every run times the same field.
let seed = 77;
function mulberry32() {
  seed = (seed + 0x6d2b79f5) | 0;
  let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
}
const simplex3 = createNoise3D(mulberry32);

/** `passes` passes of simplex-noise's 3D noise over the points `xyz` into `out`. */
export function simplexLoop(xyz, out, passes) {
  for (let it = 0; it < passes; it++) {
    for (let k = 0; k < out.length; k++) out[k] = simplex3(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
  }
}
