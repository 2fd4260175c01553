// Lesson 14 in Chromium: Figure 5's kinetic energy plot shows what a stack at rest does (a few
// µJ, on a log axis) and what a push does (joules), instead of a flat line at the bottom of a
// 0 to 0.1 J axis; Figure 4's arrows and names at both page sizes (screenshots to look at).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, serveDist, openPage, setControl } from './browser.mjs';

const site = serveDist();

/** Moves `figure`'s timeline to `at` (in 1/1000 of its duration) and waits for frames. */
async function scrubTo(page, figure, at) {
  const scrub = page.locator(`${figure} .scrub`);
  await scrub.fill(String(at));
  await scrub.dispatchEvent('input');
  // The live plot redraws every sixth frame.
  await frames(page, 8);
}

/** The plot's y range as the shell drew it, `[lo, hi]`. */
async function yRange(page, plot) {
  return (await page.locator(plot).getAttribute('data-y-range')).split(' ').map(Number);
}

test('lesson 14: the stack\'s energy plot shows the µJ a stack keeps at rest and the joules of a push', async () => {
  const context = await launch('webgl2');
  try {
    for (const [w, h] of [[800, 600], [1600, 1000]]) {
      const { page, problems } = await openPage(context, `${site.origin}/lessons/14-rigid-bodies/?backend=webgl2`, { width: w, height: h });
      const fig = '#fig-stack';
      await page.locator(fig).scrollIntoViewIfNeeded();
      // 3 s of the defaults: the stack stands with a few µJ; the axis spans their decades.
      await scrubTo(page, fig, 300);
      const [lo, hi] = await yRange(page, '#stack-plot');
      assert.ok(lo > 0 && lo <= 1e-6 && hi >= 1e-5 && hi <= 1e-3, `${w}x${h}: ${lo} ${hi}`);
      assert.ok(Number(await page.locator('#stack-plot').getAttribute('data-y-ticks')) >= 2);
      await page.locator(fig).screenshot({ path: `tests/screenshots/14-rigid-bodies-stack-rest-${w}x${h}-webgl2.png` });
      // A push at 3 s, seen at 4 s: the same axis reaches joules.
      await page.locator(`${fig} .lil-controller`, { hasText: 'push' }).locator('button').click();
      await scrubTo(page, fig, 400);
      const [, pushed] = await yRange(page, '#stack-plot');
      assert.ok(pushed >= 1, `${w}x${h}: ${pushed}`);
      await page.locator(fig).screenshot({ path: `tests/screenshots/14-rigid-bodies-stack-pushed-${w}x${h}-webgl2.png` });
      // At the end the pushed stack has settled: seven decades or more in under 100 px. The
      // axis labels every few decades, 13 px (a label's height) or more apart, in one notation.
      await scrubTo(page, fig, 1000);
      const plot = page.locator('#stack-plot');
      const [low] = await yRange(page, '#stack-plot');
      assert.ok(low <= 1e-6, `${w}x${h}: ${low}`);
      const gap = Number(await plot.getAttribute('data-y-label-gap'));
      const labels = (await plot.getAttribute('data-y-labels')).split(' ');
      assert.ok(labels.length >= 2 && gap >= 13, `${w}x${h}: ${labels} ${gap} px apart`);
      assert.ok(labels.every((l) => /^10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+$/.test(l)), `${w}x${h}: ${labels}`);
      await page.locator(fig).screenshot({ path: `tests/screenshots/14-rigid-bodies-stack-settled-${w}x${h}-webgl2.png` });
      // Reset: the run's only sample, its still start, has no place on a log axis; the axis
      // still shows numbers (a decade), not an empty 0 to 0.
      await page.locator(`${fig} .lil-controller`, { hasText: 'reset' }).locator('button').click();
      await frames(page, 8);
      assert.ok(Number(await page.locator('#stack-plot').getAttribute('data-y-ticks')) >= 2,
        `${w}x${h}: ${await page.locator('#stack-plot').getAttribute('data-y-range')}`);
      // Figure 4 after the hit, for a look at its arrows and names.
      await page.locator('#fig-impulse').scrollIntoViewIfNeeded();
      await scrubTo(page, '#fig-impulse', 1000);
      await page.locator('#fig-impulse').screenshot({ path: `tests/screenshots/14-rigid-bodies-impulse-${w}x${h}-webgl2.png` });
      // A level drop bounces straight back up: v before and v after side by side (a look).
      await setControl(page, '#fig-impulse', 'tilt', 0);
      await scrubTo(page, '#fig-impulse', 300);
      await page.locator('#fig-impulse').screenshot({ path: `tests/screenshots/14-rigid-bodies-impulse-tilt0-${w}x${h}-webgl2.png` });
      assert.deepEqual(problems, []);
      await page.close();
    }
  } finally {
    await context.close();
  }
});
