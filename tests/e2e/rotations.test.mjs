// Lesson 03 in Chromium, where only the page decides: the timelines of Figures 1 and 4 show,
// beside the seconds, the parameter the figure reads from them (t = time / 2 there and back in
// Figure 1's 4 s, the fraction of θ in Figure 4's 3 s), and it is the t the note reports.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, serveDist, openPage } from './browser.mjs';

const site = serveDist();

test('lesson 03: the timelines show the t the figures read, beside the seconds', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/03-rotations/?backend=webgl2`, { width: 1600, height: 1000 });
    /** Scrubs a figure's timeline to a fraction of its duration; returns its clock's text. */
    const scrub = async (id, fraction) => {
      await page.evaluate(([id, value]) => {
        const scrub = document.querySelector(`#${id} .scrub`);
        scrub.value = String(value);
        scrub.dispatchEvent(new Event('input'));
      }, [id, Math.round(fraction * 1000)]);
      await frames(page);
      return page.locator(`#${id} .clock`).textContent();
    };
    // Figure 1: 1 s of 4 is t = 0.5, and 3 s (on the way back) is t = 0.5 too.
    assert.equal(await scrub('interp-timeline', 0.25), '1.00 s · t = 0.50');
    assert.match(await page.locator('#interp-note').textContent(), /at t = 0\.50\b/);
    assert.equal(await scrub('interp-timeline', 0.75), '3.00 s · t = 0.50');
    assert.equal(await scrub('interp-timeline', 0.125), '0.50 s · t = 0.25');
    // Figure 4: 0.75 s of 3 is half of θ.
    assert.equal(await scrub('rodrigues-timeline', 0.25), '0.75 s · 0.50 θ');
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
