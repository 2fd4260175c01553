// Lessons 11 and 12 in Chromium, the review's points: the squash figure's two labels never
// overlap (at both page sizes, over its timeline), the free-fall plot shows signed heights (the
// two Euler lines on either side of zero) and its note says which side each is on, the flock
// note gives the steering arrow's scale, and a plot fits inside its box (its last tick label
// was cut off).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, serveDist, openPage } from './browser.mjs';

const site = serveDist();
const open = (context, path, width, height) => openPage(context, site.origin + path, { width, height });

/** The visible label boxes of `figure`, as the reader sees them. */
function labelBoxes(page, figure) {
  return page.evaluate((figure) => [...document.querySelectorAll(`${figure} .labels span`)]
    .filter((s) => !s.hidden)
    .map((s) => { const r = s.getBoundingClientRect(); return { text: s.textContent, l: r.left, r: r.right, t: r.top, b: r.bottom }; }), figure);
}

test('lesson 11: squash labels apart, free-fall plot signed and its note says the side', async () => {
  const context = await launch('webgl2');
  try {
    for (const [w, h] of [[800, 600], [1600, 1000]]) {
      const { page, problems } = await open(context, '/lessons/11-particles/?backend=webgl2', w, h);
      const squash = '#fig-squash';
      await page.locator(squash).scrollIntoViewIfNeeded();
      const scrub = page.locator(`${squash} .scrub`);
      for (const at of [0, 150, 330, 500, 720, 1000]) {
        await scrub.fill(String(at));
        await scrub.dispatchEvent('input');
        await frames(page, 4);
        const boxes = await labelBoxes(page, squash);
        assert.equal(boxes.length, 2, JSON.stringify(boxes));
        const [a, b] = boxes;
        const apart = a.r <= b.l || b.r <= a.l || a.b <= b.t || b.b <= a.t;
        assert.ok(apart, `${w}x${h}, scrub ${at}: the labels overlap ${JSON.stringify(boxes)}`);
      }
      // Free fall at the end of the throw: explicit Euler above the parabola, semi-implicit below.
      const fall = '#fig-freefall';
      await page.locator(fall).scrollIntoViewIfNeeded();
      const fallScrub = page.locator(`${fall} .scrub`);
      await fallScrub.fill('1000');
      await fallScrub.dispatchEvent('input');
      await frames(page, 4);
      const note = await page.locator('#freefall-note').textContent();
      assert.match(note, /explicit Euler is 0\.638 m above, semi-implicit Euler 0\.638 m below, velocity Verlet on the parabola/, note);
      assert.match(await page.locator('#freefall-plot').getAttribute('data-plot'), /Height above the exact parabola/);
      assert.deepEqual(problems, []);
      await page.close();
    }
  } finally {
    await context.close();
  }
});

test('lesson 12: the flock note gives the steering arrow scale', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '/lessons/12-boids/?backend=webgl2', 800, 600);
    await frames(page, 4);
    const note = await page.locator('#flock-note').textContent();
    assert.match(note, /purple arrow, 1 m per m\/s²/, note);
    // The step-time plot fits inside its box's padding, so its last x tick (1,600) is not cut
    // off by the figure's edge (the shell sized plots by clientWidth, padding included).
    const fit = await page.evaluate(() => {
      const box = document.getElementById('flock-plot');
      const style = getComputedStyle(box);
      const inner = box.getBoundingClientRect().right - parseFloat(style.paddingRight);
      const plot = box.querySelector('.uplot').getBoundingClientRect().right;
      const figure = box.closest('.figure').getBoundingClientRect().right;
      return { inner, plot, figure };
    });
    assert.ok(fit.plot <= fit.inner + 0.5 && fit.plot < fit.figure, JSON.stringify(fit));
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
