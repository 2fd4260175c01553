// Times one boids step (the bench page's kernel, `benchBoids`) in headless Chromium for one or more
// builds side by side, for a machine whose speed swings while it runs: each build gets its own page,
// the builds take turns in six rounds, and every sample is a single step timed by the wasm itself
// (performance.now around the step, the flock's setup not included). The minimum of the samples is
// the figure to compare; the quartile and median show the spread.
//   node scripts/bench-boids-builds.mjs [dist ...]      # default: dist (after scripts/build)
// To compare with an older build: keep a copy of its dist/ (e.g. cp -r dist /tmp/dist-old), rebuild,
// then pass both folders.
import { existsSync, writeFileSync, rmSync } from 'node:fs';
import { resolve } from 'node:path';
import { launch } from '../tests/e2e/browser.mjs';
import { startServer } from './serve.mjs';

const dirs = (process.argv.length > 2 ? process.argv.slice(2) : ['dist']).map((d) => resolve(d));
const cases = [['grid', 100_000, 4], ['grid', 10_000, 10], ['naive', 10_000, 1]];
const context = await launch('webgl2');
const servers = [];
try {
  const pages = [];
  for (const d of dirs) {
    // The kernel is the bench module's; a build without one has it in the figures module.
    const module = existsSync(`${d}/pkg/bench.js`) ? 'bench' : 'inbetween';
    writeFileSync(`${d}/bench-boids.html`, '<!doctype html><body><script type="module">'
      + `import init, * as w from './pkg/${module}.js'; await init(); window.w = w;`
      + ' document.body.dataset.ready = 1;</script>');
    const server = await startServer(d, 0);
    servers.push(server);
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${server.address().port}/bench-boids.html`);
    await page.waitForFunction(() => document.body.dataset.ready);
    pages.push(page);
  }
  for (const [kernel, n, perRound] of cases) {
    const samples = dirs.map(() => []);
    for (let round = 0; round < 6; round++) {
      for (let i = 0; i < pages.length; i++) {
        samples[i].push(...await pages[i].evaluate(([k, size, m]) =>
          Array.from({ length: m }, () => window.w.benchBoids(k, size, 1)), [kernel, n, perRound]));
      }
    }
    for (let i = 0; i < dirs.length; i++) {
      const s = samples[i].sort((a, b) => a - b);
      const at = (q) => s[Math.floor(q * s.length)].toFixed(2);
      console.log(`${kernel} ${n} boids, ${dirs[i]}: min ${at(0)} ms, quartile ${at(0.25)}, median ${at(0.5)} (${s.length} steps)`);
    }
  }
} finally {
  await context.close();
  for (const s of servers) s.close();
  for (const d of dirs) rmSync(`${d}/bench-boids.html`, { force: true });
}
