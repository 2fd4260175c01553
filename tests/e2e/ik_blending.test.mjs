// Lessons 07 and 08 in Chromium, the points that only the pages show: the aim figure keeps
// its target in view over the sliders' whole range (each slider typed past its end, so it sits
// at its end), dragging lesson 07's target leaves the sliders at two decimals (not an f32's
// float noise), and the blend figure keeps a hand waved over the head inside a short, wide
// canvas (800 x 600: no figure pixel on the canvas's top rows at any time of the wave).
// Lesson 07's IK figures each stand in the section they illustrate, and the aim plot's red line
// shows where the blue one lies on it, and its plots' y axes end on labelled ticks; lesson 08's locomotion figure has its two plots with a
// playhead that follows the timeline, and its note does not count the snap-back of root motion
// left in the pose as sliding.
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

/** Scrubs `timeline` (its range runs 0-1000 over its `duration` seconds) to `t` seconds. */
async function scrub(page, timeline, t, duration) {
  const range = page.locator(`${timeline} input[type=range]`);
  // The range is in thousandths of the duration: a value in seconds would set 2 s as 0.016 s.
  await range.fill(String(Math.round((t / duration) * 1000)));
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
            await scrub(page, '#aim-timeline', t, 8);
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
    // The middle (CCD) chain's target: hover around its label until the page says the pointer
    // is on it.
    const [lx, ly] = await page.evaluate((fig) => {
      const label = [...document.querySelectorAll(`${fig} .labels span`)].find((e) => !e.hidden && e.textContent === 'CCD target');
      const m = /translate\(([-\d.]+)px, ([-\d.]+)px\)/.exec(label.style.transform);
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
      await scrub(page, '#blend-timeline', t, 1);
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

/**
 * Pixels of the plot canvas in `selector` (a .plot box) near each colour of `colors` (hex), and
 * with `columnsOf` set, the x of the column right of the y axis that holds most pixels of the
 * playhead's colour. Read from the 2D canvas itself (transparent where nothing is drawn).
 */
function plotPixels(page, selector, colors, columnsOf) {
  return page.evaluate(([selector, colors, columnsOf]) => {
    const canvas = document.querySelector(`${selector} canvas`);
    const { width, height } = canvas;
    const data = canvas.getContext('2d').getImageData(0, 0, width, height).data;
    const rgb = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
    const near = (i, c) => Math.abs(data[i] - c[0]) + Math.abs(data[i + 1] - c[1]) + Math.abs(data[i + 2] - c[2]) < 60;
    const counts = colors.map(() => 0);
    const wanted = colors.map(rgb);
    const column = new Array(width).fill(0);
    const cc = columnsOf && rgb('#1f2430');
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        const i = 4 * (y * width + x);
        wanted.forEach((c, k) => { if (near(i, c)) counts[k]++; });
        // The playhead: the shell draws it in #1f2430 (dashed, antialiased: alpha varies).
        if (cc && data[i + 3] > 30 && near(i, cc)) column[x]++;
      }
    }
    // Right of the y axis (its ticks and labels are dark too): the plot area starts about
    // 80 px in (56 px of axis, 22 of label).
    const from = 100 * devicePixelRatio;
    const inside = column.slice(from);
    const best = from + inside.indexOf(Math.max(...inside));
    return { counts, column: best, width, most: inside[best - from] };
  }, [selector, colors, columnsOf]);
}

test('lesson 07: each IK figure stands in the section it illustrates', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '07-inverse-kinematics');
    // For each figure, the heading of the section it sits in, and that it has drawn.
    const where = await page.evaluate(() => [...document.querySelectorAll('main .figure')].map((f) => {
      let h = f.previousElementSibling;
      while (h && h.tagName !== 'H2') h = h.previousElementSibling;
      // The shell adds a '#' link to each heading: the heading's own words come before it.
      return [f.id, h?.textContent.replace(/#$/, '') ?? null];
    }));
    assert.deepEqual(where, [
      ['fig-ik', 'Two joints: the law of cosines'],
      ['fig-ik-iterative', 'FABRIK: reach forward, then backward'],
      ['fig-ik-limits', 'Joint limits'],
      ['fig-aim', 'Aiming: look at the target'],
    ]);
    // Each starts from its section's settings and has the controls its section needs: Figure 1
    // two segments (no slider: the two-joint chain needs them), Figure 2 three segments, Figure 3
    // two segments and hinges (the only one with a limits dropdown).
    for (const [fig, segments, limits] of [['#fig-ik', null, null], ['#fig-ik-iterative', '3', null],
      ['#fig-ik-limits', '2', 'hinges (bend one way)']]) {
      await page.locator(fig).scrollIntoViewIfNeeded();
      await frames(page);
      const shown = await page.evaluate((fig) => {
        const control = (name) => [...document.querySelectorAll(`${fig} .lil-controller`)]
          .find((c) => c.querySelector('.lil-name')?.textContent === name);
        return {
          segments: control('segments')?.querySelector('input').value ?? null,
          limits: control('joint limits')?.querySelector('select').selectedOptions[0].textContent ?? null,
          note: document.querySelector(`${fig} .note`).textContent,
        };
      }, fig);
      assert.equal(shown.segments, segments, `${fig} segments`);
      assert.equal(shown.limits, limits, `${fig} limits`);
      if (fig === '#fig-ik') assert.match(shown.note, /Two-joint: reached in one step/);
      const { coverage } = await pixelStats(page, page.locator(`${fig} .stage canvas`), fig);
      assert.ok(coverage > 0.01, `${fig} draws (${coverage})`);
    }
    await page.locator('#fig-ik-limits').screenshot({ path: `${SHOTS}/07-inverse-kinematics-limits-webgl2.png` });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 07: inside the cone the aim plot shows the red line under the blue one', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '07-inverse-kinematics');
    const fig = '#fig-aim';
    await page.locator(fig).scrollIntoViewIfNeeded();
    // A 180° cone: the head follows the target all the way round, the two lines are one.
    await setControl(page, fig, 'largest turn', 180);
    await frames(page);
    const { counts: [red, blue] } = await plotPixels(page, '#aim-plot', ['#d62728', '#1f6fd6']);
    assert.ok(blue > 200, `the head's line is drawn (${blue} px)`);
    assert.ok(red > 0.5 * blue, `the target's line shows beside it: ${red} red px, ${blue} blue px`);
    await page.locator('#aim-plot').screenshot({ path: `${SHOTS}/07-inverse-kinematics-aim-plot-180-webgl2.png` });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 07: the error and angle plots end their y axes on labelled ticks', async () => {
  // A flat line near the top of a plot (2 segments at x = 0.01: CCD 10^-1.5 m short; FABRIK
  // with 5 segments; the head's 70° at z = -1.2) must have a labelled tick beyond it: the y
  // range's ends are whole decades, or multiples of 30°.
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '07-inverse-kinematics');
    const range = async (plot) => (await page.locator(plot).getAttribute('data-y-range')).split(' ').map(Number);
    const onTicks = (r, step, what) => assert.ok(r.every((v) => Math.abs(v / step - Math.round(v / step)) < 1e-9), `${what}: y range ${r}`);
    await setControl(page, '#fig-ik-iterative', 'segments', 2);
    await setControl(page, '#fig-ik-iterative', 'x', 0.01);
    await frames(page);
    onTicks(await range('#fig-ik-iterative .plot'), 1, 'Figure 2, 2 segments, x = 0.01');
    await setControl(page, '#fig-ik-limits', 'segments', 5);
    await frames(page);
    onTicks(await range('#fig-ik-limits .plot'), 1, 'Figure 3, 5 segments');
    await setControl(page, '#fig-aim', 'z', -1.2);
    await frames(page);
    onTicks(await range('#aim-plot'), 30, 'Figure 4, z = -1.2');
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 08: the locomotion plots follow the timeline; in the root-motion figure the snap-back is not sliding', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '08-blending');
    const fig = '#fig-locomotion';
    await page.locator(fig).scrollIntoViewIfNeeded();
    const titles = await page.evaluate((fig) => [...document.querySelectorAll(`${fig} .plot`)].map((p) => p.dataset.plot), fig);
    assert.deepEqual(titles, ['How far out of step', 'Slide in the last 1.5 s']);
    // The playhead (the shell's dark dashed line) moves along x with the timeline, linearly.
    for (const plot of ['#loco-phase-plot', '#loco-slide-plot']) {
      const at = [];
      for (const t of [3, 5, 7]) {
        await scrub(page, '#loco-timeline', t, 8);
        const { column, most } = await plotPixels(page, plot, [], true);
        assert.ok(most > 20, `${plot} at ${t} s: a playhead (${most} px in its column)`);
        at.push(column);
      }
      assert.ok(at[0] < at[1] && at[1] < at[2], `${plot}: playhead at x = ${at} for t = 3, 5, 7 s`);
      assert.ok(Math.abs((at[2] - at[1]) - (at[1] - at[0])) <= 3, `${plot}: evenly spaced: ${at}`);
    }
    // Both settings are plotted, whatever the checkbox: blue (synchronised) and red lines.
    const { counts: [blue, red] } = await plotPixels(page, '#loco-slide-plot', ['#1f6fd6', '#d62728']);
    assert.ok(blue > 100 && red > 100, `slide plot: ${blue} blue px, ${red} red px`);
    await page.locator(fig).screenshot({ path: `${SHOTS}/08-blending-locomotion-plots-webgl2.png` });
    // Root motion off (its own figure, beside its section): the same slide as with it on, and
    // the note gives the jump on its own.
    const slide = (note) => /slid ([\d.]+) cm/.exec(note)?.[1];
    await page.locator('#fig-root').scrollIntoViewIfNeeded();
    // Paused, so both notes describe the same moment.
    const play = page.locator('#root-timeline .play');
    if ((await play.textContent()).includes('pause')) await play.click();
    await scrub(page, '#root-timeline', 3, 8);
    const on = await page.locator('#root-note').textContent();
    await setControl(page, '#fig-root', 'root motion', false);
    await frames(page);
    const off = await page.locator('#root-note').textContent();
    assert.ok(slide(on) && Math.abs(slide(off) - slide(on)) <= 0.1, `slide with root motion on: ${slide(on)} cm, off: ${slide(off)} cm`);
    assert.match(off, /snaps back \d+ cm \(a jump, not counted as sliding\)/);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
