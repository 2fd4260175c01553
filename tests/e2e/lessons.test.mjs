// End-to-end: every lesson page in headless Chromium, on each backend, as a person would use it.
// Run by scripts/test after scripts/build; screenshots land in tests/screenshots/ (gitignored).
//   node --test tests/e2e/            all checks
//   THUMBNAILS=1 node --test tests/e2e/   also refresh lessons/*/thumbnail.png
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { launch, pixelStats, meanDifference } from './browser.mjs';
import { startServer } from '../../scripts/serve.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const catalog = JSON.parse(readFileSync('dist/lessons/catalog.json', 'utf8'));
let server;
let origin;

before(async () => {
  server = await startServer('dist', 0);
  origin = `http://127.0.0.1:${server.address().port}`;
});
after(() => server?.close());

/** Opens `path`, collecting console errors and page errors; waits until every figure is ready. */
async function open(context, path) {
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(origin + path);
  await page.waitForFunction(() => document.body.dataset.ready, null, { timeout: 90_000 });
  return { page, problems };
}

async function pauseTimelines(page) {
  for (const button of await page.locator('.timeline .play').all()) {
    if ((await button.textContent()).includes('pause')) await button.click();
  }
}

/** Waits for a few animation frames so the figures show the latest state. */
async function frames(page, n = 6) {
  await page.evaluate((n) => new Promise((ok) => {
    const step = (k) => (k === 0 ? ok() : requestAnimationFrame(() => step(k - 1)));
    step(n);
  }), n);
}

for (const backend of ['webgpu', 'webgl2']) {
  test(`lessons on ${backend}`, async (t) => {
    const context = await launch(backend);
    try {
      const gallery = await open(context, '/lessons/');
      await t.test('gallery lists every lesson', async () => {
        const cards = await gallery.page.locator('.card').count();
        assert.equal(cards, catalog.length);
        assert.deepEqual(gallery.problems, []);
        await gallery.page.screenshot({ path: `${SHOTS}/index-${backend}.png`, fullPage: true });
      });
      for (const lesson of catalog) {
        await t.test(lesson.folder, async () => {
          const { page, problems } = await open(context, `/lessons/${lesson.folder}/?backend=${backend}`);
          const label = backend === 'webgpu' ? 'WebGPU' : 'WebGL2';
          assert.equal(await page.evaluate(() => document.body.dataset.backend), label);
          await pauseTimelines(page);
          await frames(page);
          const figures = await page.locator('.figure').all();
          assert.ok(figures.length > 0, 'a lesson has at least one figure');
          for (const [i, figure] of figures.entries()) {
            const canvas = figure.locator('.stage canvas');
            if (process.env.THUMBNAILS && i === (lesson.thumbnailFigure ?? 0)) {
              writeFileSync(`lessons/${lesson.folder}/${lesson.thumbnail}`, await canvas.screenshot());
            }
            assert.equal(await figure.locator('.backend-badge').textContent(), label);
            const before = await pixelStats(page, canvas, `before${i}`);
            assert.ok(before.coverage > 0.02, `figure ${i}: canvas looks blank (coverage ${before.coverage})`);
            assert.ok(before.colors > 20, `figure ${i}: too few colours (${before.colors}) for shaded geometry`);
            await frames(page);
            await pixelStats(page, canvas, `still${i}`);
            assert.ok(await meanDifference(page, `before${i}`, `still${i}`) < 0.5, `figure ${i}: image changes while paused`);
            // Move the first numeric control of the figure's panel.
            const input = figure.locator('.panel input[type="text"], .panel input[inputmode]').first();
            const value = Number(await input.inputValue());
            await input.fill(String(value === 0 ? 45 : -value));
            await input.press('Enter');
            await frames(page);
            await pixelStats(page, canvas, `after${i}`);
            const change = await meanDifference(page, `still${i}`, `after${i}`);
            assert.ok(change > 0.2, `figure ${i}: moving a control did not change the image (${change})`);
          }
          // The exercise switch: on the untouched stubs, the page must say the exercise is not done.
          const toggle = page.locator('.lil-controller', { hasText: 'use my exercise' }).locator('input[type="checkbox"]');
          if (await toggle.count()) {
            await toggle.first().check();
            await frames(page);
            const notes = (await page.locator('.exercise-note').allTextContents()).join(' ');
            assert.match(notes, /not done yet/i, 'a stub exercise is reported in the page');
          }
          await page.screenshot({ path: `${SHOTS}/${lesson.folder}-${backend}.png`, fullPage: true });
          assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), [], 'the error banner is empty');
          assert.deepEqual(problems, []);
          await page.close();
        });
      }
    } finally {
      await context.close();
    }
  });
}

test('a browser without WebGPU or WebGL2 gets a clear message', async () => {
  const context = await launch('none');
  try {
    for (const lesson of catalog) {
      const { page } = await open(context, `/lessons/${lesson.folder}/`);
      const notes = await page.locator('.no-gpu').allTextContents();
      assert.ok(notes.length > 0, 'each figure is replaced by a message');
      for (const note of notes) assert.match(note, /Neither WebGPU nor WebGL2 is available/);
      assert.match(await page.locator('#error-banner').textContent(), /Neither WebGPU nor WebGL2/);
      await page.screenshot({ path: `${SHOTS}/${lesson.folder}-none.png` });
      await page.close();
    }
  } finally {
    await context.close();
  }
});

test('forcing WebGPU where there is none says so', async () => {
  const context = await launch('webgl2');
  try {
    const { page } = await open(context, `/lessons/${catalog[0].folder}/?backend=webgpu`);
    const note = await page.locator('.no-gpu').first().textContent();
    assert.match(note, /WebGPU was requested/);
  } finally {
    await context.close();
  }
});
