// Runs www/bench.html in headless Chromium and prints its results as a table (after scripts/build).
//   node scripts/bench-browser.mjs
import { launch } from '../tests/e2e/browser.mjs';
import { startServer } from './serve.mjs';

const server = await startServer('dist', 0);
// BENCH_PROFILE=webgpu also runs the GPU compute benchmarks (WebGPU on SwiftShader here).
const context = await launch(process.env.BENCH_PROFILE ?? 'webgl2');
try {
  const page = await context.newPage();
  await page.goto(`http://127.0.0.1:${server.address().port}/www/bench.html`);
  await page.waitForFunction(() => document.body.dataset.ready, null, { timeout: 1_200_000 });
  const results = await page.evaluate(() => window.__benchResults);
  if (!Array.isArray(results)) throw new Error(`bench page failed: ${JSON.stringify(results)}`);
  const rows = results.map((r) => ({
    suite: r.suite, kernel: r.kernel, 'ns/item': r.ns_per_item.toFixed(2),
    'items/s': r.items_per_sec.toExponential(2), 'x baseline': r.ratio_to_baseline.toFixed(2),
  }));
  console.table(rows);
  console.log(JSON.stringify(results));
  const gpu = await page.evaluate(() => window.__benchGpuResults);
  if (gpu?.length) {
    console.table(gpu.map((r) => ({ suite: r.suite, N: r.size, 'ms/step': r.ms_per_step.toFixed(2), 'ns/item': r.ns_per_item.toFixed(2) })));
    console.log(JSON.stringify(gpu));
  }
} finally {
  await context.close();
  server.close();
}
