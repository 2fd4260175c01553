// The plain linear blend skinning loop in JavaScript (the same as `skin_lbs_plain_loop` in
// src/skinning/lbs.rs), positions and normals, typed arrays throughout: the baseline of the bench
// page's skinning suite (www/bench.js) and of scripts/bench-three-skinning.mjs.

/**
 * Unpacks `skinningBenchInput(vertices)` (the wasm bench's own input): the palette (12 floats per
 * joint: the three columns of the linear part, then the translation), joint indices and weights
 * (4 per vertex), positions and normals (3 per vertex); adds output arrays.
 */
export function skinningInput(flat, vertices, joints = 60) {
  let at = 0;
  const take = (n) => flat.subarray(at, (at += n));
  const input = {
    palette: take(12 * joints), jointIndex: Uint16Array.from(take(4 * vertices)),
    weights: take(4 * vertices), positions: take(3 * vertices), normals: take(3 * vertices),
    outP: new Float32Array(3 * vertices), outN: new Float32Array(3 * vertices),
  };
  if (at !== flat.length) throw new Error(`skinningBenchInput: ${flat.length} floats, expected ${at}`);
  return input;
}

/** `passes` passes of the loop over the first `vertices` vertices of `input`, into its outP / outN. */
export function skinLoop(input, vertices, passes) {
  const { palette: m, jointIndex, weights, positions, normals, outP, outN } = input;
  for (let it = 0; it < passes; it++) {
    for (let v = 0; v < vertices; v++) {
      const px = positions[3 * v], py = positions[3 * v + 1], pz = positions[3 * v + 2];
      const nx = normals[3 * v], ny = normals[3 * v + 1], nz = normals[3 * v + 2];
      let ox = 0, oy = 0, oz = 0, mx = 0, my = 0, mz = 0;
      for (let k = 0; k < 4; k++) {
        const w = weights[4 * v + k];
        const b = 12 * jointIndex[4 * v + k];
        ox += w * (m[b] * px + m[b + 3] * py + m[b + 6] * pz + m[b + 9]);
        oy += w * (m[b + 1] * px + m[b + 4] * py + m[b + 7] * pz + m[b + 10]);
        oz += w * (m[b + 2] * px + m[b + 5] * py + m[b + 8] * pz + m[b + 11]);
        mx += w * (m[b] * nx + m[b + 3] * ny + m[b + 6] * nz);
        my += w * (m[b + 1] * nx + m[b + 4] * ny + m[b + 7] * nz);
        mz += w * (m[b + 2] * nx + m[b + 5] * ny + m[b + 8] * nz);
      }
      outP[3 * v] = ox; outP[3 * v + 1] = oy; outP[3 * v + 2] = oz;
      outN[3 * v] = mx; outN[3 * v + 1] = my; outN[3 * v + 2] = mz;
    }
  }
}
