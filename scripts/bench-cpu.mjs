// Times the bench page's wasm kernels in Node (the same V8 as Chromium) by process CPU time, for
// a machine shared with other jobs, where the page's wall-clock batches swing by several times.
// After `scripts/build` (release):
//   node scripts/bench-cpu.mjs [dist] [suite:kernel:size:passes ...]
// Each kernel runs once with 1 pass and once with 1 + passes; the difference divided by passes
// (best of three) is one pass without the kernel's own setup (input, warm-up calls). The wasm
// reads no clock here (no `window`), so its own timing returns 0 and is ignored.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const args = process.argv.slice(2);
const dir = resolve(args[0] && !args[0].includes(':') ? args.shift() : 'dist');
const cases = args.length ? args : [
  'boids:grid:10000:20', 'boids:naive:10000:3', 'boids:grid:100000:5',
  'terrain:fbm8_values:262144:5', 'terrain:terrain_with_normals:262144:5',
  'skinning:lbs:100000:20', 'skinning:dqs:100000:20',
];
const wasm = await import(pathToFileURL(`${dir}/pkg/bench.js`).href);
await wasm.default({ module_or_path: readFileSync(`${dir}/pkg/bench_bg.wasm`) });
const kernels = {
  skinning: wasm.benchSkinning, boids: wasm.benchBoids, terrain: wasm.benchTerrain, noise: wasm.benchNoise,
  // The fluid's kernels take the dimension too: fluid2 and fluid3 (size = particles).
  fluid2: (kernel, size, n) => wasm.benchFluid(kernel, 2, size, n),
  fluid3: (kernel, size, n) => wasm.benchFluid(kernel, 3, size, n),
  // The bench page's JavaScript noise baselines (www/noise-loop.js) on the wasm's own points:
  // kernels js_perlin_loop and js_simplex_noise_npm (size = points).
  noisejs: (kernel, size, n) => {
    const loop = kernel === 'js_perlin_loop' ? noiseLoop.perlinLoop : noiseLoop.simplexLoop;
    loop(wasm.noiseBenchInput(size), new Float64Array(size), n);
  },
};
const noiseLoop = await import(pathToFileURL(`${dir}/www/noise-loop.js`).href);
noiseLoop.setPermutation(wasm.perlinTable());

function cpuMs(f) {
  const start = process.cpuUsage();
  f();
  const d = process.cpuUsage(start);
  return (d.user + d.system) / 1000;
}
const best = (n, f) => Math.min(...Array.from({ length: n }, () => cpuMs(f)));

for (const c of cases) {
  const [suite, kernel, size, passes] = c.split(':');
  const run = (n) => kernels[suite](kernel, Number(size), n);
  run(1);
  const k = Number(passes);
  const ms = (best(3, () => run(1 + k)) - best(3, () => run(1))) / k;
  console.log(`${suite} ${kernel} ${size}: ${ms.toFixed(2)} ms per pass`);
}
