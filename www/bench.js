// Runs every suite's kernels, median of several runs, and reports per-item time and the ratio to
// each suite's baseline kernel. Results: the table, the JSON block, and window.__benchResults.
import init, * as wasm from '../pkg/inbetween.js';

/**
 * A suite: `run(kernel, size, iterations)` returns milliseconds for `iterations` passes over `size`
 * items. Lessons add their suites here (one entry each).
 */
export const SUITES = [
  {
    name: 'hierarchy (forward kinematics)',
    run: (kernel, size, iterations) => wasm.benchHierarchy(kernel, size, iterations),
    kernels: ['copy_baseline', 'world_matrices', 'local_matrix_from_euler'],
    baseline: 'copy_baseline',
    size: 1024,
    iterations: 2000,
    unit: 'joint',
  },
  {
    name: 'quaternion interpolation',
    run: (kernel, size, iterations) => wasm.benchQuatInterpolation(kernel, size, iterations),
    kernels: ['nlerp', 'slerp'],
    baseline: 'nlerp',
    size: 4096,
    iterations: 500,
    unit: 'key pair',
  },
  {
    name: 'one rigid motion on 1e6 points',
    run: (kernel, size, iterations) => wasm.benchRigidPoints(kernel, size, iterations),
    kernels: ['factored', 'sandwich'],
    baseline: 'factored',
    size: 1_000_000,
    iterations: 10,
    unit: 'point',
  },
  {
    name: 'keyframe sampling (100-key Vec3 track, 1e6 samples)',
    run: (kernel, size, iterations) => wasm.benchCurves(kernel, size, iterations),
    kernels: ['copy_baseline', 'linear_cursor', 'linear_binary_search', 'catmull_rom_cursor', 'catmull_rom_binary_search'],
    baseline: 'copy_baseline',
    size: 1_000_000,
    iterations: 2,
    unit: 'sample',
  },
];

const QUICK = new URLSearchParams(location.search).has('quick');
const REPEATS = QUICK ? 1 : 5;

function median(values) {
  const s = [...values].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

async function main() {
  await init();
  const results = [];
  for (const suite of SUITES) {
    const rows = [];
    for (const kernel of suite.kernels) {
      suite.run(kernel, suite.size, Math.max(1, Math.round(suite.iterations / (QUICK ? 100 : 10)))); // warm-up
      const times = [];
      // ?quick (the page test): a smoke run, a twentieth of the work, one repeat.
      const iterations = QUICK ? Math.max(1, Math.round(suite.iterations / 20)) : suite.iterations;
      for (let r = 0; r < REPEATS; r++) times.push(suite.run(kernel, suite.size, iterations));
      const ms = median(times);
      const items = suite.size * iterations;
      rows.push({ suite: suite.name, kernel, ns_per_item: (ms * 1e6) / items, items_per_sec: items / (ms / 1000) });
      await new Promise((ok) => setTimeout(ok, 0)); // let the page breathe between kernels
    }
    const base = rows.find((r) => r.kernel === suite.baseline);
    for (const row of rows) row.ratio_to_baseline = row.ns_per_item / base.ns_per_item;
    results.push(...rows);
  }
  const table = document.getElementById('results');
  table.innerHTML = '<tr><th>suite</th><th>kernel</th><th>ns / item</th><th>items / s</th><th>× baseline</th></tr>' +
    results.map((r) => `<tr><td>${r.suite}</td><td>${r.kernel}</td><td>${r.ns_per_item.toFixed(2)}</td>` +
      `<td>${r.items_per_sec.toExponential(2)}</td><td>${r.ratio_to_baseline.toFixed(2)}</td></tr>`).join('');
  document.getElementById('json').textContent = JSON.stringify(results, null, 2);
  window.__benchResults = results;
  document.body.dataset.ready = '1';
}

main().catch((e) => {
  document.getElementById('json').textContent = `failed: ${e}`;
  window.__benchResults = { error: String(e) };
  document.body.dataset.ready = '1';
});
