// Where a figure's parts sit at the two page sizes (www/style.css): a canvas stacked over its
// panel keeps its 420 px; a "stacked" figure (lesson 11's short panels) puts its controls under a
// full-width canvas at 1600 px too, leaving no empty column beside it; a "notes-first" figure
// (lesson 13's drape) shows its note right under the canvas and timeline at 800 px, before its
// controls; a "caption-first" figure (lesson 09's Figure 1) shows its caption there. The page's
// own helpers spanTimeline and sentences (www/lesson.js) are checked on the first page.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, serveDist, openPage, frames } from './browser.mjs';

const site = serveDist();

/** Boxes of `selectors` (CSS px, page coordinates) inside the figure `figure`. */
function boxes(page, figure, selectors) {
  return page.evaluate(([figure, selectors]) => Object.fromEntries(selectors.map((s) => {
    const r = document.querySelector(`${figure} ${s}`).getBoundingClientRect();
    return [s, { top: r.top + scrollY, bottom: r.bottom + scrollY, left: r.left, right: r.right, width: r.width, height: r.height }];
  })), [figure, selectors]);
}

test('figures keep their canvas height, and short or tall panels sit where the page reads best', async () => {
  const context = await launch('webgl2');
  try {
    const open = (lesson, width, height) =>
      openPage(context, `${site.origin}/lessons/${lesson}/?backend=webgl2`, { width, height });
    {
      const { page } = await open('09-skinning', 800, 600);
      const b = await boxes(page, '#fig-human', ['.stage canvas', '.panel']);
      assert.equal(b['.stage canvas'].height, 420, '800 px: the canvas over its panel keeps 420 px');
      assert.ok(b['.panel'].top >= b['.stage canvas'].bottom - 1, '800 px: the panel is under the canvas');
      // The shell's spanTimeline, on the page's own copy of www/lesson.js: a live plot's x axis
      // spans the whole timeline whatever samples it has (rows of nulls at 0 and at the end).
      const spans = await page.evaluate(async () => {
        const { spanTimeline, sentences } = await import('/www/lesson.js');
        return [
          spanTimeline([[0.5, 0.7], [1, 2]], 3),
          spanTimeline([[], []], 3),
          spanTimeline([[0, 1.5, 3], [4, 5, 6]], 3),
          spanTimeline([[1.3], [7]], 2),
          sentences('Key B not changed: the axis has zero length', '', 'Screw: a slide.', 'Why?'),
        ];
      });
      assert.deepEqual(spans, [
        [[0, 0.5, 0.7, 3], [null, 1, 2, null]],
        [[0, 3], [null, null]],
        [[0, 1.5, 3], [4, 5, 6]],
        [[0, 1.3, 2], [null, 7, null]],
        'Key B not changed: the axis has zero length. Screw: a slide. Why?',
      ]);
      // A "caption-first" figure (lesson 09's Figure 1): the caption that says what the dots are
      // comes right under the canvas, before the controls, and both fit on the 600 px screen.
      const c = await boxes(page, '#fig-cylinder', ['.stage canvas', 'figcaption', '.panel']);
      assert.ok(Math.abs(c['figcaption'].top - c['.stage canvas'].bottom) < 2, `800 px: the caption is under the canvas ${JSON.stringify(c)}`);
      assert.ok(c['figcaption'].bottom - c['.stage canvas'].top <= 600, `800 px: canvas and caption take ${c['figcaption'].bottom - c['.stage canvas'].top} px`);
      assert.ok(c['.panel'].top >= c['figcaption'].bottom - 1, '800 px: the controls come after the caption');
      await page.close();
    }
    {
      const { page } = await open('11-particles', 1600, 1000);
      const figure = await boxes(page, '#fig-freefall', ['.stage canvas', '.panel', '.note']);
      const canvas = figure['.stage canvas'];
      assert.ok(figure['.panel'].top >= canvas.bottom - 1, `1600 px: the short panel is under the canvas ${JSON.stringify(figure)}`);
      assert.ok(canvas.width > 880, `1600 px: the canvas takes the figure's width (${canvas.width} px)`);
      // The figure with many controls keeps its panel beside the canvas.
      const emitters = await boxes(page, '#fig-emitters', ['.stage canvas', '.panel']);
      assert.ok(emitters['.panel'].left >= emitters['.stage canvas'].right - 1, '1600 px: a tall panel stays beside');
      await page.close();
    }
    for (const [width, height] of [[800, 600], [1600, 1000]]) {
      const { page } = await open('13-cloth', width, height);
      const b = await boxes(page, '#fig-drape', ['.stage canvas', '.panel', '#drape-timeline', '#drape-note']);
      const canvas = b['.stage canvas'];
      // The timeline, then the note, right under the canvas (on a wide page the panel is beside).
      assert.ok(b['#drape-note'].top - canvas.bottom < 80,
        `${width} px: the note starts ${b['#drape-note'].top - canvas.bottom} px under the canvas`);
      if (width === 800) assert.ok(b['.panel'].top >= b['#drape-note'].bottom - 1, '800 px: the controls come after the note');
      else assert.ok(b['.panel'].left >= canvas.right - 1, '1600 px: the panel is beside the canvas');
      await page.close();
    }
  } finally {
    await context.close();
  }
});

test('a number typed between a control\'s steps says which step it took (a count\'s 2.5, lesson 15\'s 1234 particles)', async () => {
  // lil-gui moves a typed number to the nearest step without a word: a count typed as 2.5
  // became 3 silently. The shell says so under the control, as it does for text and for numbers
  // out of range.
  const context = await launch('webgl2');
  try {
    const page = (await openPage(context, `${site.origin}/lessons/02b-expressive-animation/?backend=webgl2`, { width: 1280, height: 900 })).page;
    const typed = async (control, text) => {
      const box = control.locator('input');
      await box.fill(text);
      await box.press('Enter');
      await page.evaluate(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok))));
      return [await control.locator('xpath=following-sibling::*[1]').textContent(), await box.inputValue()];
    };
    const ghosts = page.locator('.lil-controller', { hasText: 'ghosts' }).first();
    assert.deepEqual(await typed(ghosts, '2.5'), ['2.5 is not a whole number: ghosts is set to 3.', '3']);
    const accepted = await typed(ghosts, '7');
    assert.equal(accepted[1], '7');
    assert.ok(!(await ghosts.locator('xpath=following-sibling::*[1]').isVisible()), 'a value on a step takes the note away');
    const other = await openPage(context, `${site.origin}/lessons/15-fluids/?backend=webgl2`, { width: 1280, height: 900 });
    const particles = other.page.locator('#fig-splash .lil-controller', { hasText: 'particles' }).first();
    const box = particles.locator('input');
    await box.fill('1234');
    await box.press('Enter');
    await other.page.evaluate(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok))));
    assert.equal(await particles.locator('xpath=following-sibling::*[1]').textContent(),
      '1234 falls between the control\'s steps of 500: particles is set to 1000.');
    // A value on a step of a range that starts off the origin (lesson 04's scale y: from -2 in
    // steps of 0.001) is taken as typed, without a note: lil-gui's count of steps from the
    // minimum gave 0.00099999999999989 for 0.001.
    const affine = await openPage(context, `${site.origin}/lessons/04-rigid-motions/?backend=webgl2`, { width: 1280, height: 900 });
    const scaleY = affine.page.locator('#fig-affine .lil-controller', { hasText: 'scale y' }).first();
    for (const value of ['0.001', '0.01', '1.234']) {
      await scaleY.locator('input').fill(value);
      await scaleY.locator('input').press('Enter');
      await affine.page.evaluate(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok))));
      assert.equal(await scaleY.locator('input').inputValue(), value);
      assert.ok(!(await scaleY.locator('xpath=following-sibling::*[1]').isVisible()), `${value}: no note`);
    }
  } finally {
    await context.close();
  }
});

test('a plot draws a straight line straight, not as a staircase of whole pixels', async () => {
  // The shell's Plot, on a page's own copy of www/lesson.js, drawing y = 6 - 12 t over 101
  // samples (lesson 05's 1985 curvature line): down each column of the plot's canvas, the
  // line's centre (its coverage-weighted row) lies on one straight line to within 0.4 px (about
  // 0.25 px measured: antialiasing moves a 1.5 px line's centre a little). uPlot rounds a series'
  // points to whole pixels unless told not to, which drew it as 1 px steps (0.65 px off).
  const context = await launch('webgl2');
  try {
    const { page } = await openPage(context, `${site.origin}/lessons/05-noise/?backend=webgl2`, { width: 1280, height: 900 });
    const columns = await page.evaluate(async () => {
      const { Plot } = await import('/www/lesson.js');
      const host = document.createElement('div');
      host.style.width = '600px';
      document.body.prepend(host);
      const plot = new Plot(host, { title: 'line', xLabel: 't', yLabel: 'y (no unit)', series: ['line'], colors: ['#000'], widths: [1.5] });
      const t = Array.from({ length: 101 }, (_, i) => i / 100);
      plot.setData([t, t.map((x) => 6 - 12 * x)]);
      await new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok)));
      const canvas = host.querySelector('canvas');
      const u = plot.plot;
      const { left, top, width, height } = u.bbox;
      const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
      const out = [];
      // The inner 80 % of the plot's width, away from the axes' ends.
      for (let x = Math.round(left + 0.1 * width); x < left + 0.9 * width; x += 1) {
        let sum = 0;
        let weight = 0;
        for (let y = Math.floor(top); y < top + height; y++) {
          const i = (y * canvas.width + x) * 4;
          // The black line's coverage (the canvas is transparent under it), ignoring the grid's
          // faint lines.
          const alpha = data[i + 3];
          const d = alpha < 40 ? 0 : alpha * (1 - (data[i] + data[i + 1] + data[i + 2]) / 765);
          sum += d * y;
          weight += d;
        }
        if (weight > 0) out.push([x, sum / weight]);
      }
      return out;
    });
    assert.ok(columns.length > 300, `${columns.length} columns with the line`);
    const n = columns.length;
    const mx = columns.reduce((s, [x]) => s + x, 0) / n;
    const my = columns.reduce((s, [, y]) => s + y, 0) / n;
    const slope = columns.reduce((s, [x, y]) => s + (x - mx) * (y - my), 0) / columns.reduce((s, [x]) => s + (x - mx) ** 2, 0);
    const worst = Math.max(...columns.map(([x, y]) => Math.abs(y - (my + slope * (x - mx)))));
    assert.ok(worst < 0.4, `the line's centre leaves the straight line by ${worst.toFixed(2)} px`);
  } finally {
    await context.close();
  }
});

test('a simulation out of sight stands still and plays again in view (lesson 13\'s flag)', async () => {
  const context = await launch('webgl2');
  try {
    const { page } = await openPage(context, `${site.origin}/lessons/13-cloth/?backend=webgl2`, { width: 800, height: 600 });
    const clock = () => page.evaluate(() => document.querySelector('#flag-timeline .clock').textContent);
    await page.evaluate(() => window.scrollTo(0, 0));
    await frames(page, 6);
    const inView = () => page.evaluate(() => {
      const r = document.querySelector('#fig-flag .stage canvas').getBoundingClientRect();
      return r.bottom > -100 && r.top < innerHeight + 100;
    });
    assert.equal(await inView(), false, 'the flag is out of sight at the top of the page');
    const before = await clock();
    await frames(page, 30);
    assert.equal(await clock(), before, 'the flag\'s timeline stood still out of sight');
    await page.locator('#fig-flag .stage canvas').scrollIntoViewIfNeeded();
    await frames(page, 30);
    assert.notEqual(await clock(), before, 'the flag\'s timeline plays in view');
    await page.close();
  } finally {
    await context.close();
  }
});
