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

// The browser can take the page's GPU away (a GPU process reset, a driver update). The page then
// says so, makes its device again and every figure draws again, a lesson's uploaded meshes
// included. The loss is forced through the objects the page made, reached by wrapping the calls
// that make them: WebGL2, WEBGL_lose_context's loseContext() on the hidden canvas's context (and
// restoreContext() afterwards, which the page ignores: it has moved to a new context); WebGPU,
// destroy() on the page's device, which the browser reports as that device lost.
for (const backend of ['webgl2', 'webgpu']) {
  test(`a page whose GPU is lost on ${backend} draws every figure again`, async () => {
    const context = await launch(backend);
    try {
      await context.route((url) => url.pathname === '/lessons/many-figures/', (route) =>
        route.fulfill({ contentType: 'text/html', body: PAGE }));
      await context.addInitScript(() => {
        window.__gpus = [];
        const keep = (gpu) => { if (gpu && !window.__gpus.includes(gpu)) window.__gpus.push(gpu); };
        const getContext = HTMLCanvasElement.prototype.getContext;
        HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
          const made = getContext.call(this, kind, ...rest);
          if (kind === 'webgl2') keep(made);
          return made;
        };
        if (self.GPUAdapter) {
          const requestDevice = GPUAdapter.prototype.requestDevice;
          GPUAdapter.prototype.requestDevice = async function (...args) {
            const device = await requestDevice.apply(this, args);
            keep(device);
            return device;
          };
        }
      });
      for (const path of ['/lessons/many-figures/', '/lessons/10-blend-shapes/']) {
        const { page, problems } = await openPage(context, `${site.origin}${path}?backend=${backend}`,
          { width: 1100, height: 900 });
        await frames(page, 4);
        const selectors = await page.evaluate(() => window.__inbetween.figures.map((f) => f.selector));
        const canvases = selectors.slice(0, 6).map((s) => page.locator(`${s} .stage canvas`).first());
        const gpus = await page.evaluate(() => window.__gpus.length);
        assert.equal(gpus, 1, `${path}: one GPU device or context for the page`);
        await page.evaluate(() => {
          const gpu = window.__gpus[0];
          if (gpu.destroy) gpu.destroy();
          else gpu.getExtension('WEBGL_lose_context').loseContext();
        });
        // The note shows while the figures are set up again, and goes when they are.
        await page.waitForFunction(() => window.__inbetween.gpuResets === 1, null, { timeout: 10_000 });
        await page.waitForFunction(() => !document.getElementById('gpu-reset-note'), null, { timeout: 30_000 });
        await page.evaluate(() => window.__gpus[0].getExtension?.('WEBGL_lose_context')?.restoreContext());
        await frames(page, 6);
        const after = await page.evaluate(() => ({
          gpus: window.__gpus.length,
          resets: window.__inbetween.gpuResets,
          errors: window.__inbetween.errors,
          lost: window.__inbetween.figures.filter((f) => f.viewer.lost).length,
        }));
        assert.deepEqual(after, { gpus: 2, resets: 1, errors: [], lost: 0 }, `${path}: one new device, no error`);
        for (const [i, canvas] of canvases.entries()) {
          // A figure scrolled into view draws at its next frame; a loaded machine may take a few.
          let s;
          for (let tries = 0; tries < 10; tries++) {
            s = await pixelStats(page, canvas, `after${i}`);
            if (s.coverage > 0.02 && s.colors > 8) break;
            await frames(page, 6);
          }
          assert.ok(s.coverage > 0.02 && s.colors > 8, `${path}: figure ${selectors[i]} draws again: ${JSON.stringify(s)}`);
        }
        assert.deepEqual(problems, []);
        await page.screenshot({ path: `${SHOTS}/gpu-lost-${backend}${path.replaceAll('/', '-')}.png` });
        await page.close();
      }
    } finally {
      await context.close();
    }
  });
}
