// Runs every suite's kernels and reports per-item time and the ratio to each suite's baseline
// kernel. Results: the table, the JSON block, and window.__benchResults.
//
// How a kernel is timed: the kernel times itself inside wasm with performance.now(), whose ticks
// are coarse in browsers (0.1 ms or more, with jitter), so a fast kernel can read 0 ms. Each timed
// batch therefore repeats the kernel until it lasts at least MIN_BATCH_MS, and the time is divided
// by the iterations actually run. A full run takes the median over REPEATS such batches. Between
// batches the page yields to the event loop, so it stays responsive and shows its progress.
// The CPU kernels are the bench module's (built at the figures module's profile, so their times
// stand for the figures' code); the GPU kernels need the renderer, so they are the figures module's.
import init, * as wasm from '../pkg/bench.js';
import initFigures, * as figures from '../pkg/inbetween.js';
import './devloop.js';
import { skinLoop, skinningInput } from './skin-loop.js';
import { perlin3, perlinLoop, setPermutation, simplexLoop } from './noise-loop.js';

/**
 * A suite: `run(kernel, size, iterations)` returns milliseconds for `iterations` passes over `size`
 * items. The baseline kernel's time is the denominator of the suite's ratios. Lessons add their
 * suites here (one entry each).
 */
export const SUITES = [
  {
    name: 'hierarchy (forward kinematics)',
    run: (kernel, size, iterations) => wasm.benchHierarchy(kernel, size, iterations),
    kernels: ['copy_baseline', 'world_matrices', 'local_matrix_from_euler'],
    baseline: 'copy_baseline',
    size: 1024,
    unit: 'joint',
  },
  {
    name: 'quaternion interpolation',
    run: (kernel, size, iterations) => wasm.benchQuatInterpolation(kernel, size, iterations),
    kernels: ['nlerp', 'slerp'],
    baseline: 'nlerp',
    size: 4096,
    unit: 'key pair',
  },
  {
    name: 'one rigid motion on 1e6 points',
    run: (kernel, size, iterations) => wasm.benchRigidPoints(kernel, size, iterations),
    kernels: ['factored', 'sandwich'],
    baseline: 'factored',
    size: 1_000_000,
    unit: 'point',
  },
  {
    name: 'keyframe sampling (100-key Vec3 track, 1e6 samples)',
    run: (kernel, size, iterations) => wasm.benchCurves(kernel, size, iterations),
    kernels: ['copy_baseline', 'linear_cursor', 'linear_binary_search', 'catmull_rom_cursor', 'catmull_rom_binary_search'],
    baseline: 'copy_baseline',
    size: 1_000_000,
    unit: 'sample',
  },
  {
    name: 'skeleton: sample + local-to-model, 60 joints, 30 keys (per frame; /60 for joints)',
    run: (kernel, size, iterations) => wasm.benchSkeleton(kernel, size, iterations),
    kernels: ['track_baseline', 'runtime_clip', 'runtime_sample_only', 'local_to_model_only'],
    baseline: 'track_baseline',
    size: 600,
    unit: 'frame of 60 joints',
  },
  {
    name: 'crowd: 1000 characters of 60 joints (per character per frame)',
    run: (kernel, size, iterations) => wasm.benchCrowd(kernel, size, iterations),
    kernels: ['track_baseline', 'runtime_clip'],
    baseline: 'track_baseline',
    size: 1000,
    unit: 'character',
  },
  {
    name: 'boids: one step, 10k boids, naive O(N²) vs grid (lesson 12)',
    run: (kernel, size, iterations) => wasm.benchBoids(kernel, size, iterations),
    kernels: ['grid', 'naive'],
    baseline: 'grid',
    size: 10_000,
    unit: 'boid',
  },
  {
    name: 'boids: one step, 100k boids, grid (lesson 12; target under 16 ms per step)',
    run: (kernel, size, iterations) => wasm.benchBoids(kernel, size, iterations),
    kernels: ['grid'],
    baseline: 'grid',
    size: 100_000,
    unit: 'boid',
  },
  {
    name: 'cloth: one frame of 10 substeps, 100 × 100 particles (lesson 13; target under 16 ms per frame)',
    // One item is one frame of the 100 × 100 cloth (the side is fixed; size counts frames).
    run: (kernel, size, iterations) => wasm.benchCloth(kernel, 100, size * iterations),
    kernels: ['xpbd', 'mass_spring'],
    baseline: 'xpbd',
    size: 1,
    unit: 'frame',
  },
  {
    name: 'rigid bodies: one step of a 1,000-body heap in contact, grid vs every pair (target under 4 ms per step)',
    // One item is one step of the 1,000-body heap (the heap is fixed; size counts steps).
    run: (kernel, size, iterations) => wasm.benchRigidBodies(kernel, 1000, size * iterations),
    kernels: ['grid', 'all_pairs'],
    baseline: 'all_pairs',
    size: 1,
    unit: 'step',
  },
  {
    name: 'fluid 3D: one step of a 20,000-particle dam break, SPH vs PBF with 4 iterations (lesson 15; target under 16 ms per step)',
    // One item is one step of the fluid (the count is fixed; size counts steps).
    run: (kernel, size, iterations) => wasm.benchFluid(kernel, 3, 20_000, size * iterations),
    kernels: ['sph', 'pbf'],
    baseline: 'sph',
    size: 1,
    unit: 'step',
  },
  {
    name: 'fluid 2D: one step of a 10,000-particle dam break, SPH vs PBF with 4 iterations (lesson 15; target under 16 ms per step)',
    run: (kernel, size, iterations) => wasm.benchFluid(kernel, 2, 10_000, size * iterations),
    kernels: ['sph', 'pbf'],
    baseline: 'sph',
    size: 1,
    unit: 'step',
  },
  {
    name: 'fluid 3D: the neighbour search of 10,000 particles, grid vs every pair (lesson 15)',
    run: (kernel, size, iterations) => wasm.benchFluid(kernel, 3, 10_000, size * iterations),
    kernels: ['search_grid', 'search_all_pairs'],
    baseline: 'search_all_pairs',
    size: 1,
    unit: 'search',
  },
  {
    name: 'terrain 512 × 512, 8 octaves (lesson 05)',
    run: (kernel, size, iterations) => wasm.benchTerrain(kernel, size, iterations),
    kernels: ['fbm8_values', 'fbm8_rows', 'fbm8_batch', 'terrain_with_normals'],
    baseline: 'fbm8_values',
    size: 512 * 512,
    unit: 'vertex',
  },
  {
    name: 'Perlin 3D noise at 65,536 scattered points (lesson 05)',
    run: (kernel, size, iterations) => (kernel.startsWith('js_')
      ? jsNoise(kernel, size, iterations) : wasm.benchNoise(kernel, size, iterations)),
    kernels: ['js_perlin_loop', 'js_simplex_noise_npm', 'noise3_per_point', 'noise3_batch'],
    baseline: 'js_perlin_loop',
    size: 65_536,
    unit: 'point',
  },
  {
    name: 'skinning: 100k vertices, 4 influences, 60 joints, positions and normals (lesson 09)',
    run: (kernel, size, iterations) => (kernel === 'js_plain_loop'
      ? jsSkinning(size, iterations) : wasm.benchSkinning(kernel, size, iterations)),
    kernels: ['js_plain_loop', 'wasm_plain_loop', 'lbs', 'lbs_interleaved', 'dqs'],
    baseline: 'js_plain_loop',
    size: 100_000,
    unit: 'vertex',
  },
];

/**
 * The plain LBS loop in JavaScript (www/skin-loop.js) on the wasm bench's own input. Returns
 * milliseconds for `iterations` passes.
 */
const jsSkinInputs = new Map();
function jsSkinning(vertices, iterations) {
  if (!jsSkinInputs.has(vertices)) {
    jsSkinInputs.set(vertices, skinningInput(wasm.skinningBenchInput(vertices), vertices));
  }
  const input = jsSkinInputs.get(vertices);
  const start = performance.now();
  skinLoop(input, vertices, iterations);
  return performance.now() - start;
}

/**
 * The JavaScript noise kernels (www/noise-loop.js) on the wasm bench's own points: Perlin's
 * reference in plain JavaScript, or the simplex-noise package. Returns milliseconds for
 * `iterations` passes.
 */
const jsNoiseInputs = new Map();
function jsNoise(kernel, points, iterations) {
  if (!jsNoiseInputs.has(points)) {
    setPermutation(wasm.perlinTable());
    const xyz = wasm.noiseBenchInput(points);
    // The JavaScript loop computes the wasm's function (in doubles): checked on the first points.
    const few = xyz.subarray(0, 3 * Math.min(points, 1000));
    const reference = wasm.perlinNoise3(few);
    const worst = reference.reduce((m, v, k) => Math.max(m, Math.abs(v - perlin3(few[3 * k], few[3 * k + 1], few[3 * k + 2]))), 0);
    if (!(worst < 1e-5)) throw new Error(`the JavaScript Perlin loop differs from the wasm noise3 by ${worst}`);
    jsNoiseInputs.set(points, { xyz, out: new Float64Array(points) });
  }
  const { xyz, out } = jsNoiseInputs.get(points);
  const loop = kernel === 'js_perlin_loop' ? perlinLoop : simplexLoop;
  const start = performance.now();
  loop(xyz, out, iterations);
  return performance.now() - start;
}

// ?quick (the page test): a smoke run, one batch of at least 20 ms per kernel.
const QUICK = new URLSearchParams(location.search).has('quick');
const MIN_BATCH_MS = QUICK ? 20 : 100;
const REPEATS = QUICK ? 1 : 5;
// The kernels accept up to 2^20 iterations (the smallest of their limits).
const MAX_ITERATIONS = 1 << 20;

function median(values) {
  const s = [...values].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

/**
 * Lets the page handle input and paint between timed batches: a message task queues behind what
 * is already waiting, and unlike a chain of setTimeout(0) it is not slowed to one per second when
 * the tab is in the background.
 */
const channel = new MessageChannel();
function yieldToPage() {
  return new Promise((ok) => {
    channel.port1.onmessage = () => ok();
    channel.port2.postMessage(null);
  });
}

/**
 * Times one kernel: a warm-up call (lets the wasm engine tier up), then batches that grow until one
 * lasts at least MIN_BATCH_MS, then REPEATS batches of that many iterations (the calibrating batch
 * counts as the first). Returns milliseconds per iteration (median) and the batch size.
 */
async function timeKernel(suite, kernel) {
  const run = (n) => suite.run(kernel, suite.size, n);
  let ms = run(1);
  let iterations = ms > MIN_BATCH_MS / 20 ? Math.ceil((1.25 * MIN_BATCH_MS) / ms) : 1;
  for (;;) {
    iterations = Math.min(iterations, MAX_ITERATIONS);
    await yieldToPage();
    ms = run(iterations);
    if (ms >= MIN_BATCH_MS || iterations === MAX_ITERATIONS) break;
    // Each round grows the batch by at least 1.25×, so the loop ends. Below a twentieth of the
    // target the reading is mostly clock granularity: grow tenfold.
    iterations = ms > MIN_BATCH_MS / 20 ? Math.ceil((iterations * 1.25 * MIN_BATCH_MS) / ms) : iterations * 10;
  }
  if (!(ms > 0)) throw new Error(`${suite.name} / ${kernel}: the clock did not advance in ${iterations} iterations`);
  const perIteration = [ms / iterations];
  for (let r = 1; r < REPEATS; r++) {
    await yieldToPage();
    perIteration.push(run(iterations) / iterations);
  }
  return { ms: median(perIteration), iterations };
}

function showProgress(done, total, text) {
  document.getElementById('progress-bar').max = total;
  document.getElementById('progress-bar').value = done;
  document.getElementById('progress').textContent = text;
}

function showResults(results) {
  const table = document.getElementById('results');
  table.innerHTML = '<tr><th>suite</th><th>kernel</th><th>ns / item</th><th>items / s</th><th>× baseline</th></tr>' +
    results.map((r) => `<tr><td>${r.suite}</td><td>${r.kernel}</td><td>${r.ns_per_item.toFixed(2)}</td>` +
      `<td>${r.items_per_sec.toExponential(2)}</td><td>${r.ratio_to_baseline.toFixed(2)}</td></tr>`).join('');
}

async function main() {
  showProgress(0, 1, 'loading the wasm modules…');
  await Promise.all([init(), initFigures()]);
  const total = SUITES.reduce((n, s) => n + s.kernels.length, 0);
  const started = performance.now();
  const results = [];
  let done = 0;
  for (const suite of SUITES) {
    const rows = [];
    for (const kernel of suite.kernels) {
      showProgress(done, total, `running ${suite.name}: ${kernel} (kernel ${done + 1} of ${total})`);
      await yieldToPage();
      const { ms, iterations } = await timeKernel(suite, kernel);
      rows.push({
        suite: suite.name, kernel, ns_per_item: (ms * 1e6) / suite.size, items_per_sec: suite.size / (ms / 1000),
        iterations_per_batch: iterations, repeats: REPEATS,
      });
      done += 1;
    }
    const base = rows.find((r) => r.kernel === suite.baseline);
    for (const row of rows) row.ratio_to_baseline = row.ns_per_item / base.ns_per_item;
    results.push(...rows);
    showResults(results);
  }
  const seconds = (performance.now() - started) / 1000;
  showProgress(total, total, `done: ${total} kernels in ${seconds.toFixed(1)} s` +
    ` (batches of at least ${MIN_BATCH_MS} ms, ${REPEATS === 1 ? 'one batch' : `median of ${REPEATS}`} per kernel)`);
  document.getElementById('json').textContent = JSON.stringify(results, null, 2);
  window.__benchResults = results;
  await gpuBenches();
  document.body.dataset.ready = '1';
}

/**
 * GPU compute (lessons 11, 12 and 15), where the browser offers WebGPU: milliseconds per GPU step,
 * timed until the GPU has finished the queued steps. Kept apart from the CPU table (its own table
 * and window.__benchGpuResults), since the kernels are asynchronous and need an adapter.
 */
const GPU_SUITES = [
  { name: 'particles, GPU step (fall, floor and sphere bounces)', run: figures.benchGpuParticles, sizes: QUICK ? [100_000] : [100_000, 1_000_000], unit: 'particle' },
  { name: 'boids, GPU step (naive O(N²) neighbours, tiled)', run: (c, n, k) => figures.benchGpuBoids(c, n, k, 'naive'), sizes: QUICK ? [1_000] : [1_000, 4_096], unit: 'boid' },
  // Two steps: a step of a million boids takes about 20 s on SwiftShader (headless WebGPU here).
  { name: 'boids, GPU step (GPU grid built each step)', run: (c, n, k) => figures.benchGpuBoids(c, n, k, 'grid'), sizes: QUICK ? [10_000] : [100_000, 1_000_000], unit: 'boid', steps: 2 },
  // A 3D dam break let go (lesson 15), the GPU grid built every step; one step at a million.
  { name: 'fluid 3D, GPU step (SPH, GPU grid built each step)', run: (c, n, k) => figures.benchGpuFluid(c, 'sph', n, k), sizes: QUICK ? [10_000] : [100_000, 1_000_000], unit: 'particle', steps: 1 },
  { name: 'fluid 3D, GPU step (PBF, 4 iterations, GPU grid built each step)', run: (c, n, k) => figures.benchGpuFluid(c, 'pbf', n, k), sizes: QUICK ? [10_000] : [100_000, 1_000_000], unit: 'particle', steps: 1 },
];
async function gpuBenches() {
  const status = document.getElementById('gpu-status');
  const adapter = navigator.gpu ? await navigator.gpu.requestAdapter().catch(() => null) : null;
  if (!adapter) {
    status.textContent = 'No WebGPU adapter in this browser: the GPU compute benchmarks are skipped.';
    window.__benchGpuResults = [];
    return;
  }
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 4;
  const rows = [];
  for (const suite of GPU_SUITES) {
    for (const size of suite.sizes) {
      status.textContent = `running ${suite.name} at ${size.toLocaleString('en')} ${suite.unit}s…`;
      await yieldToPage();
      const steps = QUICK ? 2 : (suite.steps ?? 5);
      const ms = await suite.run(canvas, size, steps);
      rows.push({ suite: suite.name, size, ms_per_step: ms, ns_per_item: (ms * 1e6) / size, steps, adapter: adapter.info?.description || adapter.info?.vendor || '' });
      document.getElementById('gpu-results').innerHTML = '<tr><th>suite</th><th>N</th><th>ms / step</th><th>ns / item</th></tr>' +
        rows.map((r) => `<tr><td>${r.suite}</td><td>${r.size.toLocaleString('en')}</td><td>${r.ms_per_step.toFixed(2)}</td><td>${r.ns_per_item.toFixed(2)}</td></tr>`).join('');
    }
  }
  status.textContent = `done: ${rows.length} GPU runs (${QUICK ? 2 : '1 to 5'} steps each, timed until the GPU finished).`;
  window.__benchGpuResults = rows;
}

main().catch((e) => {
  document.getElementById('progress').textContent = 'failed';
  document.getElementById('json').textContent = `failed: ${e}`;
  window.__benchResults = { error: String(e) };
  document.body.dataset.ready = '1';
});
