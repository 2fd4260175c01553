// Lessons 07 and 08 in Chromium, the review's points that live in the pages: the aim figure
// keeps its target in view over the sliders' whole range (each slider typed past its end, so
// it sits at its end), dragging lesson 07's target leaves the sliders at two decimals (not an
// f32's float noise), and the blend figure keeps a hand waved over the head inside a short,
// wide canvas (800 x 600: no figure pixel on the canvas's top rows at any time of the wave).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { launch, pixelStats, frames, setControl, serveDist, openPage } from './browser.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const site = serveDist();

/** `lesson`'s page at 800 x 600 on WebGL2, every timeline paused. */
async function open(context, lesson) {
  const { page, problems } = await openPage(context, `${site.origin}/lessons/${lesson}/?backend=webgl2`,
    { width: 800, height: 600 });
  await page.evaluate(() => {
    for (const b of document.querySelectorAll('.timeline .play')) if (b.textContent.includes('pause')) b.click();
  });
  return { page, problems };
}

async function scrub(page, timeline, t) {
  const range = page.locator(`${timeline} input[type=range]`);
  await range.fill(String(t));
  await range.dispatchEvent('input');
  await frames(page);
}

test('lesson 07: the aim figure shows its target at every corner of the sliders', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '07-inverse-kinematics');
    const fig = '#fig-aim';
    await page.locator(fig).scrollIntoViewIfNeeded();
    const canvas = await page.locator(`${fig} .stage canvas`).boundingBox();
    for (const x of [-9, 9]) {
      for (const y of [-9, 9]) {
        for (const z of [-9, 9]) {
          await setControl(page, fig, 'x', x);
          await setControl(page, fig, 'y', y);
          await setControl(page, fig, 'z', z);
          for (const t of [0, 2, 4, 6]) {
            await scrub(page, '#aim-timeline', t);
            const label = await page.evaluate((fig) => {
              const el = [...document.querySelectorAll(`${fig} .labels span`)].find((e) => e.textContent === 'target');
              const m = el && !el.hidden && /translate\(([-\d.]+)px, ([-\d.]+)px\)/.exec(el.style.transform);
              return m ? [Number(m[1]), Number(m[2])] : null;
            }, fig);
            const where = `target at sliders (${x}, ${y}, ${z}), t = ${t} s`;
            assert.ok(label, `${where}: the target's label is shown`);
            assert.ok(label[0] > 0 && label[0] < canvas.width - 40 && label[1] > 0 && label[1] < canvas.height,
              `${where}: its label at ${label} lies inside the ${canvas.width} x ${canvas.height} canvas`);
          }
        }
      }
    }
    await page.locator(fig).screenshot({ path: `${SHOTS}/07-inverse-kinematics-aim-corner-webgl2.png` });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 07: dragging a target leaves two-decimal numbers in the sliders', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '07-inverse-kinematics');
    const fig = '#fig-ik';
    const canvas = page.locator(`${fig} .stage canvas`);
    await canvas.scrollIntoViewIfNeeded();
    await frames(page);
    const box = await canvas.boundingBox();
    // The middle chain's target: hover around its label until the page says the pointer is on it.
    const [lx, ly] = await page.evaluate((fig) => {
      const labels = [...document.querySelectorAll(`${fig} .labels span`)].filter((e) => !e.hidden && e.textContent === 'target');
      const m = /translate\(([-\d.]+)px, ([-\d.]+)px\)/.exec(labels[1].style.transform);
      return [Number(m[1]), Number(m[2])];
    }, fig);
    let grab = null;
    for (let dy = -24; dy <= 24 && !grab; dy += 3) {
      for (let dx = -24; dx <= 24 && !grab; dx += 3) {
        await page.mouse.move(box.x + lx + dx, box.y + ly + dy);
        if (await canvas.evaluate((c) => c.classList.contains('over-target'))) grab = [box.x + lx + dx, box.y + ly + dy];
      }
    }
    assert.ok(grab, 'found the target under the pointer');
    await page.mouse.down();
    for (let i = 1; i <= 8; i++) await page.mouse.move(grab[0] - 7 * i, grab[1] - 3 * i);
    await page.mouse.up();
    await frames(page);
    const values = await page.evaluate((fig) => [...document.querySelectorAll(`${fig} .lil-controller.lil-number input`)].slice(1, 4).map((i) => i.value), fig);
    assert.notDeepEqual(values, ['0.55', '0.65', '0.15'], 'the drag moved the target');
    for (const v of values) assert.match(v, /^-?\d+(\.\d{1,2})?$/, `slider shows ${values}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 08: a hand waved over the head stays inside an 800 x 600 canvas', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '08-blending');
    const fig = '#fig-blend';
    await setControl(page, fig, 'weight of B', 1);
    await setControl(page, fig, 'mask', 'upper body from B');
    const canvas = page.locator(`${fig} .stage canvas`);
    await canvas.scrollIntoViewIfNeeded();
    // The wave clip is 2 s long; the walk (clip A, the timeline's) 1 s: B plays at A's phase.
    for (const t of [0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875]) {
      await scrub(page, '#blend-timeline', t);
      const { width } = await pixelStats(page, canvas, `blend-${t}`);
      // Pixels on the top 6 rows, right of the backend badge and left of the rounded corner,
      // that differ from the background (read at 10 px from the top right).
      const touching = await page.evaluate(([key, width]) => {
        const data = window.__shots[key];
        const at = 4 * (10 * width + width - 10);
        const bg = [data[at], data[at + 1], data[at + 2]];
        let n = 0;
        for (let y = 0; y < 6; y++) {
          for (let x = 100; x < width - 10; x++) {
            const i = 4 * (y * width + x);
            if (Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]) > 40) n++;
          }
        }
        return n;
      }, [`blend-${t}`, width]);
      assert.equal(touching, 0, `at ${t} s the figure reaches the canvas's top edge (${touching} pixels)`);
    }
    await page.locator(fig).screenshot({ path: `${SHOTS}/08-blending-wave-800-webgl2.png` });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
