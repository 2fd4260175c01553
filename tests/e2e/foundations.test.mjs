// Lessons 00 and 02 in Chromium, where only the page decides: lesson 00's Figure 5 layout at
// both page sizes (the two per-pixel totals side by side; at 800 x 600 the sphere, the six images
// and the shininess slider on one screen; at 1600 x 1000 the images in one row), Figure 1's
// segments slider off for the tetrahedron, Figure 2's refused z_far explained under its box; lesson 02's
// Figure 7 inset, magnifying the loop of the loop-prone keys; its keys selects kept in step; Figures 5
// and 8's curves over their in-between dots; its speed and acceleration plots' axes from 0.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, setControl, serveDist, openPage } from './browser.mjs';

const site = serveDist();

/** Viewport boxes of every element matching `selector`. */
const boxes = (page, selector) => page.evaluate((s) => [...document.querySelectorAll(s)].map((e) => {
  const r = e.getBoundingClientRect();
  return { top: r.top, bottom: r.bottom, left: r.left, right: r.right, label: e.getAttribute('aria-label') ?? e.textContent };
}), selector);

test('lesson 00: Figure 5 keeps its totals side by side and its Try this on one screen; Figures 1 and 2 controls and notes', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/00-triangles-to-pixels/?backend=webgl2`);
    for (const [w, h] of [[800, 600], [1600, 1000]]) {
      await page.setViewportSize({ width: w, height: h });
      await page.locator('#fig-shading').evaluate((f) => f.scrollIntoView());
      await frames(page, 2);
      const images = await boxes(page, '#shading-images canvas');
      const [sphere] = await boxes(page, '#fig-shading .stage > canvas');
      const [slider] = (await boxes(page, '#fig-shading .lil-controller')).filter((c) => c.label.startsWith('shininess'));
      const named = (start) => images.find((b) => b.label.startsWith(start));
      const [phong, blinn] = [named('Phong total'), named('Blinn-Phong total')];
      assert.ok(Math.abs(phong.top - blinn.top) < 1, `${w}: the totals share a row ${JSON.stringify([phong, blinn])}`);
      const between = images.filter((b) => b.top === phong.top && b.left > phong.right && b.right < blinn.left);
      assert.ok(blinn.left > phong.right && between.length === 0, `${w}: the totals side by side ${JSON.stringify(images)}`);
      const bottom = Math.max(...images.map((b) => b.bottom), w === 800 ? slider.bottom : 0);
      assert.ok(bottom - sphere.top <= h, `${w}: sphere to ${w === 800 ? 'slider' : 'images'} ${bottom - sphere.top} px, over one screen of ${h}`);
      if (w === 1600) assert.ok(images.every((b) => b.top === images[0].top), `1600: the images in one row ${JSON.stringify(images)}`);
    }

    // Figure 1: the tetrahedron has no segments; the slider says so by being off.
    const segments = page.locator('#fig-mesh .lil-controller', { hasText: 'sphere segments' });
    await setControl(page, '#fig-mesh', 'shape', 'tetrahedron');
    assert.match(await segments.getAttribute('class'), /lil-disabled/);
    await setControl(page, '#fig-mesh', 'shape', 'sphere');
    assert.doesNotMatch(await segments.getAttribute('class'), /lil-disabled/);

    // Figure 2: a value the figure refuses is explained under its box, as a value the box cannot
    // take is, not in the figure's note; the next edit of another box takes the sentence away.
    await setControl(page, '#fig-frustum', 'z_far', 0.5);
    await frames(page);
    const farNote = page.locator('#fig-frustum .lil-controller', { hasText: 'z_far' }).locator('xpath=following-sibling::*[1]');
    assert.equal(await farNote.getAttribute('class'), 'typed-note');
    assert.ok(await farNote.isVisible());
    assert.match(await farNote.textContent(), /^Not changed: z_far \(0\.5\) must be greater than z_near \(1\)\.$/);
    assert.doesNotMatch(await page.locator('#frustum-note').textContent(), /must be greater/);
    await setControl(page, '#fig-frustum', 'z_near', 'NaN');
    await frames(page);
    assert.ok(!(await farNote.isVisible()), 'an edit of z_near takes the z_far sentence away');
    const nearNote = page.locator('#fig-frustum .lil-controller', { hasText: 'z_near' }).locator('xpath=following-sibling::*[1]');
    assert.match(await nearNote.textContent(), /“NaN” is not a number: z_near \(m\) stays 1\./);
    assert.doesNotMatch(await page.locator('#frustum-note').textContent(), /Not changed/);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 02: Figure 7 magnifies the loop-prone loop in an inset, and shows none without a loop', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/02-keyframes/?backend=webgl2`, { width: 1600, height: 1000 });
    const canvas = page.locator('#fig-centripetal .stage > canvas');
    await canvas.evaluate((c) => c.scrollIntoView());
    await frames(page);
    assert.equal(await canvas.getAttribute('data-loop-px'), null, 'the default keys do not loop');
    await setControl(page, '#fig-centripetal', 'keys (all figures)', 'loop-prone');
    await frames(page);
    // The loop, about 3 cm and a few pixels across in the view, at least 60 px across in the inset.
    const px = Number(await canvas.getAttribute('data-loop-px'));
    assert.ok(px >= 60, `the loop is ${px} px across in the inset`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 02: notes give the numbers Figures 3, 7 and 9 name; zoom to fit keeps every key number in the editor', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/02-keyframes/?backend=webgl2`, { width: 1600, height: 1000 });
    // Figure 3: the largest gap at 3 keys (within 12 cm) and the red curve's reach at 16 (beyond 100 m).
    const lagrangeNote = async (keys) => {
      await setControl(page, '#fig-lagrange', 'keys (blue)', keys);
      await frames(page);
      const text = await page.locator('#lagrange-note').textContent();
      const [gap, red] = [/at most ([\d.]+) m/, /\|y\| = ([\d.]+) m/].map((re) => Number(text.match(re)?.[1]));
      return { gap, red, text };
    };
    const three = await lagrangeNote(3);
    assert.ok(three.gap > 0.1 && three.gap < 0.12, three.text);
    const sixteen = await lagrangeNote(16);
    assert.ok(sixteen.red > 100, sixteen.text);
    // Figure 7: on zig-zag the balls are up to 7.5 cm apart.
    await setControl(page, '#fig-centripetal', 'keys (all figures)', 'zig-zag');
    await frames(page);
    const gapText = await page.locator('#centripetal-note').textContent();
    const gap = Number(gapText.match(/at most ([\d.]+) cm/)?.[1]);
    assert.ok(Math.abs(gap - 7.5) < 0.5, gapText);
    // Figure 9: the first steps of 7 frames the caption names.
    await setControl(page, '#fig-ease', 'frames', 7);
    await frames(page);
    const easeText = await page.locator('#ease-note').textContent();
    for (const part of ['none 0.167', 'smoothstep 0.074', 'ease in (t²) 0.028', 'ease out 0.306']) {
      assert.ok(easeText.includes(part), `${part} in "${easeText}"`);
    }
    // Figure 1: key 1 dragged far up, then "zoom to fit": every key at least 24 px inside the
    // drawing above the time strip, so the number over it (15 px off, 12 px tall) is not cut.
    await setControl(page, '#fig-centripetal', 'keys (all figures)', 'default');
    const canvas = page.locator('#fig-keys .editor canvas');
    await canvas.evaluate((c) => c.scrollIntoView({ block: 'end' })); // room above for the drag
    await frames(page);
    const box = await canvas.boundingBox();
    const ed = (expr) => page.evaluate(`window.__inbetween.editor.${expr}`);
    const [x, y] = await ed('keyPx(1)');
    await page.mouse.move(box.x + x, box.y + y);
    await page.mouse.down();
    await page.mouse.move(box.x + x, box.y + y - 360, { steps: 8 });
    await page.mouse.up();
    await frames(page);
    const keys = await ed('keys()');
    assert.ok(keys[5] > 5, `key 1 is dragged far up: ${keys[5]} m`);
    await page.locator('#fig-keys .fit').click();
    await frames(page);
    for (let k = 0; k < keys.length / 3; k++) {
      const [px, py] = await ed(`keyPx(${k})`);
      const inside = px >= 24 && px <= box.width - 24 && py >= 24 && py <= box.height - 46 - 24;
      assert.ok(inside, `key ${k} at ${[px, py]} on ${box.width} x ${box.height}`);
    }
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 02: every keys select names the preset the shared keys come from', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/02-keyframes/?backend=webgl2`, { width: 1600, height: 1000 });
    // Figure 1's select and each panel's "keys (all figures)": the value each one shows.
    const shown = () => page.evaluate(() => {
      const selects = [document.querySelector('#fig-keys select.preset'),
        ...[...document.querySelectorAll('.lil-controller')].filter((c) => c.textContent.includes('keys (all figures)')).map((c) => c.querySelector('select'))];
      return selects.map((s) => [s.closest('.figure')?.id, s.selectedIndex < 0 ? null : s.options[s.selectedIndex].textContent]);
    });
    const panels = (await shown()).length;
    assert.ok(panels >= 5, `Figure 1's select and four panels' ${JSON.stringify(await shown())}`);
    for (const [figure, option, name] of [['#fig-step', 'loop-prone', /^loop-prone/], ['#fig-timing', 'default', /^default/], ['#fig-keys', 'uneven', /^uneven times/]]) {
      if (figure === '#fig-keys') await page.locator('#fig-keys select.preset').selectOption(option);
      else await setControl(page, figure, 'keys (all figures)', option);
      await frames(page);
      const all = await shown();
      assert.ok(all.every(([, text]) => name.test(text)), `after ${figure} chose ${option}: ${JSON.stringify(all)}`);
    }
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 02: Figures 5 and 8 draw their curves over the grey in-between dots', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/02-keyframes/?backend=webgl2`, { width: 1600, height: 1000 });
    // Every column of the 2D view that holds in-between grey has a curve's colour within 4 px (a
    // dot at a curve's end reaches past it): a run of dots drawn over the curve hides it for its
    // whole length (Figure 5's 2.5 s segment). Columns within 8 px of an orange key dot are left out (a key covers its curve, and its chords start
    // there), and a teal tangent arrow, drawn over the curve, counts as covering it.
    for (const [figure, curves] of [['#fig-cardinal', ['#1f6fd6', '#e35d9c']], ['#fig-timing', ['#1f6fd6', '#d62728']]]) {
      const canvas = page.locator(`${figure} canvas.view2d`);
      await canvas.evaluate((c) => c.scrollIntoView());
      await frames(page, 3);
      const hidden = await canvas.evaluate((c, curves) => {
        const { width, height } = c;
        const data = c.getContext('2d').getImageData(0, 0, width, height).data;
        const rgb = curves.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
        const near = (k, [r, g, b], tol) => Math.abs(data[k] - r) <= tol && Math.abs(data[k + 1] - g) <= tol && Math.abs(data[k + 2] - b) <= tol;
        const [grey, curve, key] = [[], [], []];
        for (let x = 0; x < width; x++) {
          for (let y = 0; y < height; y++) {
            const k = 4 * (y * width + x);
            grey[x] ||= near(k, [127, 127, 127], 6);
            curve[x] ||= [...rgb, [23, 162, 168]].some((c) => near(k, c, 40));
            key[x] ||= near(k, [230, 138, 0], 30);
          }
        }
        const within = (of, x, d) => of.slice(Math.max(0, x - d), x + d + 1).some(Boolean);
        return grey.map((g, x) => (g && !within(curve, x, 4) && !within(key, x, 8) ? x : -1)).filter((x) => x >= 0);
      }, curves);
      assert.deepEqual(hidden, [], `${figure}: columns with dots and no curve`);
    }
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 02: every panel choice fits beside its chevron, and without a GPU no blank editor stays under the message', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/02-keyframes/?backend=webgl2`, { width: 1600, height: 1000 });
    // Each option's text, in the select's font, against the room its display leaves beside the
    // chevron (lil-gui pads the display's right for it and hides what runs past).
    const tooWide = await page.evaluate(() => {
      const out = [];
      const ctx = document.createElement('canvas').getContext('2d');
      for (const display of document.querySelectorAll('.lil-option .lil-display')) {
        const css = getComputedStyle(display);
        ctx.font = `${css.fontWeight} ${css.fontSize} ${css.fontFamily}`;
        const room = display.parentElement.clientWidth - parseFloat(css.paddingLeft) - parseFloat(css.paddingRight);
        for (const option of display.parentElement.querySelector('select').options) {
          const width = ctx.measureText(option.textContent).width;
          if (width > room) out.push(`${option.textContent}: ${width.toFixed(0)} px in ${room.toFixed(0)}`);
        }
      }
      return out;
    });
    assert.deepEqual(tooWide, []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
  const none = await launch('none');
  try {
    const { page } = await openPage(none, `${site.origin}/lessons/02-keyframes/`, { width: 1600, height: 1000 });
    await page.waitForFunction(() => document.body.dataset.backend === 'none', null, { timeout: 30_000 });
    assert.ok(await page.locator('.no-gpu').count() > 0, 'the figures say why they are not drawn');
    assert.equal(await page.locator('#fig-keys :is(.editor, .timeline):visible').count(), 0, 'no blank curve editor or idle timeline under the message');
    // The contents beside the wide page, opened, sit under the header that the red banner pushed down.
    await page.locator('details.outline').evaluate((d) => { d.open = true; });
    const [header, outline] = await Promise.all(['header.site', 'details.outline']
      .map((s) => page.locator(s).evaluate((e) => e.getBoundingClientRect().toJSON())));
    assert.ok(outline.top >= header.bottom - 1, `contents at ${outline.top} px, the header ends at ${header.bottom} px`);
    await page.screenshot({ path: 'tests/screenshots/02-keyframes-none-editor.png' });
  } finally {
    await none.close();
  }
});

test('lesson 02: the speed and acceleration plots start their axes at 0 and label it', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/02-keyframes/?backend=webgl2`, { width: 1600, height: 1000 });
    for (const preset of ['zig-zag', 'default']) {
      await setControl(page, '#fig-centripetal', 'keys (all figures)', preset);
      for (const selector of ['#fig-step .plot', '#fig-natural .plot', '#fig-centripetal .plot', '#cardinal-plot', '#keys-speed', '#keys-accel']) {
        const plot = page.locator(selector);
        await plot.scrollIntoViewIfNeeded();
        await frames(page);
        const [range, labels] = await plot.evaluate((e) => [e.dataset.yRange, e.dataset.yLabels]);
        const [lo, hi] = range.split(' ').map(Number);
        assert.ok(lo <= 0 && lo > -0.1 * hi, `${selector} on ${preset}: y from ${lo} to ${hi}`);
        assert.ok(labels.split(' ').includes('0'), `${selector} on ${preset}: y labels ${labels}`);
      }
    }
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
