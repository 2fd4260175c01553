// 24 live figures on one page (tests/e2e/many-figures.html, served here at
// /lessons/many-figures/), on both backends, at one size and at two sizes: every figure draws its
// own image and keeps it. The page has one GPU device (src/render/context.rs): on WebGL2 one
// WebGL2 context, where a context per figure would pass Chromium's 16 and lose the oldest.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { launch, frames, serveDist, openPage, pixelStats, meanDifference } from './browser.mjs';

const site = serveDist();
const PAGE = readFileSync(new URL('./many-figures.html', import.meta.url), 'utf8');
const COUNT = 24;
const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });

for (const backend of ['webgl2', 'webgpu']) {
  test(`${COUNT} figures on ${backend}: each draws its own image and none is lost`, async () => {
    const context = await launch(backend);
    try {
      await context.route((url) => url.pathname === '/lessons/many-figures/', (route) =>
        route.fulfill({ contentType: 'text/html', body: PAGE }));
      // Counted from the start: a lost context fires at its canvas, before any test code runs.
      await context.addInitScript(() => {
        window.__lost = 0;
        addEventListener('webglcontextlost', () => { window.__lost++; }, true);
      });
      for (const sizes of ['same', 'mixed']) {
        const warnings = [];
        const page0 = `${site.origin}/lessons/many-figures/?backend=${backend}&sizes=${sizes}`;
        const { page, problems } = await openPage(context, page0, { width: 1100, height: 900 });
        page.on('console', (m) => { if (/WebGL contexts|context lost/i.test(m.text())) warnings.push(m.text()); });
        await frames(page, 10);
        const state = await page.evaluate(() => ({
          figures: window.__inbetween.figures.map((f) => f.backend),
          errors: window.__inbetween.errors,
          lost: window.__lost,
          // WebGL2 figures' canvases hold a '2d' context (the page's one WebGL2 context is copied
          // into them): read their pixels directly; the fraction off the background colour.
          direct: [...document.querySelectorAll('.figure canvas')].map((c) => {
            const g = c.getContext('2d');
            if (!g) return null;
            const { data } = g.getImageData(0, 0, c.width, c.height);
            let off = 0;
            for (let i = 0; i < data.length; i += 4) off += Math.abs(data[i] - data[0]) + Math.abs(data[i + 2] - data[2]) > 24;
            return off / (data.length / 4);
          }),
        }));
        const expected = backend === 'webgl2' ? 'WebGL2' : 'WebGPU';
        assert.deepEqual(state.figures, Array(COUNT).fill(expected), `${sizes}: every figure got ${expected}`);
        assert.deepEqual(state.errors, []);
        assert.equal(state.lost, 0, `${sizes}: no context was lost`);
        if (backend === 'webgl2') {
          state.direct.forEach((off, i) => assert.ok(off > 0.02, `${sizes}: figure ${i}'s 2d canvas shows the box (${off})`));
        }
        for (let i = 0; i < COUNT; i++) {
          const s = await pixelStats(page, page.locator(`#fig-${i} canvas`), `f${i}`);
          assert.ok(s.coverage > 0.02 && s.colors > 8, `${sizes}: figure ${i} draws: ${JSON.stringify(s)}`);
          if (i > 0) {
            const d = await meanDifference(page, `f${i - 1}`, `f${i}`);
            assert.ok(d > 0.5, `${sizes}: figures ${i - 1} and ${i} differ (mean difference ${d})`);
          }
        }
        assert.deepEqual(warnings, []);
        assert.deepEqual(problems, []);
        await page.screenshot({ path: `${SHOTS}/many-figures-${backend}-${sizes}.png` });
        await page.close();
      }
    } finally {
      await context.close();
    }
  });
}
