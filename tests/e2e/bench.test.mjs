// The bench page (www/bench.html) in headless Chromium: a smoke run (?quick) of every kernel.
// Run by scripts/test after scripts/build.
//   node --test tests/e2e/bench.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { launch } from './browser.mjs';
import { startServer } from '../../scripts/serve.mjs';

let server;
before(async () => {
  server = await startServer('dist', 0);
});
after(() => server?.close());

test('the bench page runs every kernel and reports finite results', async () => {
  const context = await launch('webgl2');
  try {
    const page = await context.newPage();
    const problems = [];
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    await page.goto(`http://127.0.0.1:${server.address().port}/www/bench.html?quick`);
    await page.waitForFunction(() => document.body.dataset.ready, null, { timeout: 120_000 });
    const results = await page.evaluate(() => window.__benchResults);
    assert.ok(Array.isArray(results) && results.length > 0, JSON.stringify(results));
    for (const r of results) {
      assert.ok(Number.isFinite(r.ns_per_item) && r.ns_per_item > 0, `${r.suite} / ${r.kernel}`);
      assert.ok(Number.isFinite(r.ratio_to_baseline) && r.ratio_to_baseline > 0, `${r.suite} / ${r.kernel}`);
    }
    assert.match(await page.locator('#progress').textContent(), new RegExp(`^done: ${results.length} kernels`));
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
