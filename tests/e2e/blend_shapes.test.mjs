// Lesson 10's face figure in Chromium: at the defaults the two heads differ (the full form's base
// weight is 0 by hand) and the automatic base weight makes them agree, as the note says; with the
// full form's base weight set by hand and a total far above 1, both heads stay
// whole in view, side by side (checked by pixels: two separate heads on the row through their
// centres, neither touching the canvas's edges).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { launch, pixelStats, frames, setControl, serveDist, openPage } from './browser.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const site = serveDist();

/**
 * The runs of non-background pixels along rows of the last `pixelStats` image (`key`), at the
 * fractions `rows` of its height: `[[start, end], …]` per row, runs under 4 px and gaps under
 * 3 px ignored (antialiasing, thin lines).
 */
function runsAlongRows(page, key, width, rows) {
  return page.evaluate(([key, width, rows]) => {
    const data = window.__shots[key];
    const height = data.length / 4 / width;
    const bg = [data[0], data[1], data[2]];
    return rows.map((fraction) => {
      const y = Math.floor(fraction * height);
      const runs = [];
      let start = -1;
      let gap = 0;
      for (let x = 0; x <= width; x++) {
        const i = 4 * (y * width + x);
        const inside = x < width && Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]) > 40;
        if (inside) {
          if (start < 0) start = x;
          gap = 0;
        } else if (start >= 0 && ++gap >= 3) {
          const end = x - gap;
          if (end - start >= 4) runs.push([start, end]);
          start = -1;
          gap = 0;
        }
      }
      return runs;
    });
  }, [key, width, rows]);
}

test('lesson 10: the heads differ at the defaults and agree with the automatic base weight; both in view at a total far above 1', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/10-blend-shapes/?backend=webgl2`);
    const fig = '#fig-face';
    const canvas = page.locator(`${fig} .stage canvas`);
    await canvas.scrollIntoViewIfNeeded();
    // The defaults: base weight 0 by hand, so the full form's total is the targets' sum, not 1;
    // "automatic" makes the weights sum to 1 and the note says the two forms agree.
    const note = () => page.locator('#face-note').textContent();
    assert.match(await note(), /Full \(right\): base weight 0\.000 \+ targets [\d.]+ = [\d.]+, not 1: p = /);
    await page.locator(`${fig} .timeline .play`).click();
    await setControl(page, fig, 'automatic: 1 − Σw', true);
    await frames(page, 5);
    assert.match(await note(), /\(1 − Σw\) \+ targets [\d.]+ = 1\.000: the weights sum to 1, so the full form is the differential form/);
    await setControl(page, fig, 'automatic: 1 − Σw', false);
    // A total of 7: base weight 1 by hand, every target at 1.5, still.
    await setControl(page, fig, 'animate the weights', false);
    await setControl(page, fig, 'base weight (by hand)', 1);
    for (const name of ['smile', 'jaw open', 'brows up', 'puff cheeks']) await setControl(page, fig, name, 1.5);
    await frames(page, 10);
    assert.match(await note(), /= 7(\.0+)?, not 1/);
    const { width } = await pixelStats(page, canvas, 'big');
    await canvas.screenshot({ path: `${SHOTS}/10-blend-shapes-total7-webgl2.png` });
    // Rows through the heads' middle (above the small grid under the left head): two heads,
    // apart, the big one not cut off by the edges.
    const rows = await runsAlongRows(page, 'big', width, [0.46, 0.5]);
    const separate = rows.filter((runs) => runs.length >= 2);
    assert.ok(separate.length > 0, `two separate heads on a middle row: ${JSON.stringify(rows)}`);
    for (const runs of separate) {
      const [left, right] = [runs[0], runs[runs.length - 1]];
      assert.ok(left[0] > 2 && right[1] < width - 3, `a head touches the canvas's edge: ${JSON.stringify(runs)} of ${width}`);
      assert.ok(left[1] - left[0] >= 12, `the differential head is visible: ${JSON.stringify(runs)}`);
      assert.ok(right[1] - right[0] > 3 * (left[1] - left[0]), `the full head is the larger: ${JSON.stringify(runs)}`);
    }
    // The differential head's label ends before the full head begins (it reads leftwards).
    const label = await page.evaluate((fig) => {
      const canvas = document.querySelector(`${fig} .stage canvas`).getBoundingClientRect();
      const span = [...document.querySelectorAll(`${fig} .labels span`)].find((s) => s.textContent === 'differential');
      const r = span.getBoundingClientRect();
      return { left: r.left - canvas.left, right: r.right - canvas.left };
    }, fig);
    for (const runs of separate) {
      const full = runs[runs.length - 1];
      assert.ok(label.left >= 0 && label.right < full[0], `the 'differential' label (${label.left}-${label.right} px) runs into the full head (from ${full[0]} px)`);
    }
    await page.locator(fig).screenshot({ path: `${SHOTS}/10-blend-shapes-total7-figure-webgl2.png` });
    assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
