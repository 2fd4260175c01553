// The bench page (www/bench.html) in headless Chromium: a smoke run (?quick) of every kernel.
// Run by scripts/test after scripts/build.
//   node --test tests/e2e/bench.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, serveDist, openPage } from './browser.mjs';

const site = serveDist();

test('the bench page runs every kernel and reports finite results', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/www/bench.html?quick`, { timeout: 120_000 });
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
