// End-to-end: every lesson page in headless Chromium, on each backend, as a person would use it.
// The tests are registered by `lessonTests`, called by sweep-1.test.mjs and sweep-2.test.mjs, which
// share the pages so that scripts/test can run them at once (each file is a process with its own
// browser), and by lessons-no-gpu.test.mjs (the pages without a GPU API). Screenshots land in
// tests/screenshots/ (gitignored).
//   node --test tests/e2e/            all checks
//   THUMBNAILS=1 node --test tests/e2e/   also refresh lessons/*/thumbnail.png
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { tmpdir } from 'node:os';
import { launch, pixelStats, meanDifference, frames, serveDist, openPage, DIST } from './browser.mjs';
import { gpuNoiseMatchesCpu } from './noise_gpu.mjs';
import { normalsPlotKeepsTheArrowsColours, normalsPlotStartsAtZero } from './noise_page.mjs';
import { quizShowMeSetsFigures } from './quiz.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const catalog = JSON.parse(readFileSync(join(DIST, 'lessons/catalog.json'), 'utf8'));
const site = serveDist();

/**
 * CPU milliseconds used so far by this process and the browsers it started, by kind of process
 * (Chromium's gpu-process, renderer, browser ...; node), read from /proc (Linux; only node elsewhere).
 */
function cpuByKind() {
  const out = { node: Math.round((process.cpuUsage().user + process.cpuUsage().system) / 1000) };
  try {
    const procs = readdirSync('/proc').filter((d) => /^\d+$/.test(d)).flatMap((pid) => {
      try {
        const f = readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
        return [{ pid: Number(pid), ppid: Number(f[1]), ms: (Number(f[11]) + Number(f[12])) * 10 }];
      } catch { return []; }
    });
    const mine = new Set([process.pid]);
    for (let grew = true; grew;) {
      grew = false;
      for (const p of procs) if (!mine.has(p.pid) && mine.has(p.ppid)) { mine.add(p.pid); grew = true; }
    }
    for (const p of procs) {
      if (p.pid === process.pid || !mine.has(p.pid)) continue;
      const cmd = readFileSync(`/proc/${p.pid}/cmdline`, 'utf8');
      const kind = cmd.includes('chromium') ? /--type=([a-z-]+)/.exec(cmd)?.[1] ?? 'browser' : 'other';
      out[kind] = (out[kind] ?? 0) + p.ms;
    }
  } catch { /* no /proc */ }
  return out;
}

/**
 * With E2E_TIMING=1, `clock(what)` prints how long `what` took since the last call and the CPU time
 * the browser's processes and this one used meanwhile (to see where a page's test spends its time:
 * on two cores, mostly in SwiftShader, in Chromium's GPU process); otherwise it does nothing.
 */
function phaseClock(where) {
  let last = Date.now();
  let lastCpu = process.env.E2E_TIMING ? cpuByKind() : {};
  return (what) => {
    const now = Date.now();
    if (process.env.E2E_TIMING) {
      const cpu = cpuByKind();
      const d = (k) => (cpu[k] ?? 0) - (lastCpu[k] ?? 0);
      console.log(`${where}: ${what} took ${now - last} ms (CPU ms: gpu-process ${d('gpu-process')}, renderer ${d('renderer')}, browser ${d('browser')}, node ${d('node')})`);
      lastCpu = cpu;
    }
    last = now;
  };
}

const open = (context, path) => openPage(context, site.origin + path);

/** The 3D figures' render scale (`?render-scale`) while a lesson page's controls are moved. */
const SWEEP_RENDER_SCALE = Number(process.env.E2E_RENDER_SCALE ?? 0.5);

/**
 * Every plot on the page names the quantity and unit of both axes, as the lessons write them:
 * "time (s)", "slide (cm)", "weight (0 to 1)", "depth (no unit)": text, then a non-empty
 * parenthesis. uPlot draws the labels on its canvas; the shell's Plot copies them to the plot
 * element's data-x-label and data-y-label, and a .plot element that no Plot filled has neither.
 */
/** After the sweep moved a figure's controls, each of its drawn plots shows at least two numbers
 * on its y axis, and a log x axis (it records data-x-range) on its x axis: a log axis over many
 * decades, or over part of one, must still label some of its ticks. */
async function plotsShowNumbers(figure, i) {
  // A control may have restarted a measurement (lesson 15's "measure again" clears its plot, and
  // the sweep fills it in over the next frames): up to 10 s for the numbers to come.
  await figure.evaluate((f) => new Promise((ok) => {
    const started = performance.now();
    const look = () => {
      const shown = [...f.querySelectorAll('.plot[data-y-ticks]')].every((p) => Number(p.dataset.yTicks) >= 2);
      if (shown || performance.now() - started > 10_000) ok();
      else requestAnimationFrame(look);
    };
    look();
  }));
  const ticks = await figure.evaluate((f) => [...f.querySelectorAll('.plot[data-y-ticks]')]
    .map((p) => [p.dataset.plot, Number(p.dataset.yTicks), p.dataset.xRange ? Number(p.dataset.xTicks) : 2]));
  const bare = ticks.filter(([, y]) => y < 2);
  assert.deepEqual(bare, [], `figure ${i}: these plots show fewer than two numbers on their y axis`);
  const bareX = ticks.filter(([, , x]) => x < 2);
  assert.deepEqual(bareX, [], `figure ${i}: these log x axes show fewer than two numbers`);
}

async function plotsNameTheirUnits(page) {
  const plots = await page.evaluate(() => [...document.querySelectorAll('.plot')]
    .map((p) => ({ id: p.id, title: p.dataset.plot, x: p.dataset.xLabel, y: p.dataset.yLabel })));
  const named = (label) => /\S.*\(\s*[^\s)][^)]*\)/.test(label ?? '');
  const unnamed = plots.flatMap((p) => ['x', 'y']
    .filter((axis) => !named(p[axis]))
    .map((axis) => `${p.id || p.title || '(a plot)'}: ${axis} label ${JSON.stringify(p[axis] ?? null)}`));
  assert.deepEqual(unnamed, [], 'every plot labels both axes with a quantity and its unit in parentheses');
  // Every legend row shows its curve's colour in its swatch (a stroke given as a function too),
  // so that each curve can be matched to its name.
  const blank = await page.evaluate(() => [...document.querySelectorAll('.plot .u-legend .u-series')]
    .filter((row) => row.querySelector('.u-marker'))
    .filter((row) => {
      const m = getComputedStyle(row.querySelector('.u-marker'));
      return m.backgroundImage === 'none' && /^rgba\(\d+, \d+, \d+, 0\)$|^transparent$/.test(m.backgroundColor);
    })
    .map((row) => `${row.closest('.plot').id || row.closest('.plot').dataset.plot}: ${row.textContent.trim()}`));
  assert.deepEqual(blank, [], 'every legend swatch shows its curve\'s colour');
}

async function pauseTimelines(page) {
  await page.evaluate(() => {
    for (const button of document.querySelectorAll('.timeline .play')) {
      if (button.textContent.includes('pause')) button.click();
    }
  });
}

/**
 * Screenshots of the whole page with its figures drawn, from its top. Playwright's `fullPage`
 * capture resizes the page behind our back, which clears every canvas after the figures drew, so
 * the viewport is made as tall as the page instead: every figure is then on screen
 * (Viewer::set_visible), draws and places its labels, and an ordinary screenshot takes the lot.
 * Chromium's capture wraps round past about 8,000 px (the page's top reappears below), so a longer
 * page is taken in parts of equal height, up to 8,000 px each: `path` holds the first, `path` with -part2, -part3 ...
 * before its extension the rest, each in a viewport as tall as what is left. `check`, when given,
 * runs with the first part in view and every figure drawn, before the screenshots (the figures'
 * sizes depend on the page's width only, so what it sees is what the reader's viewport shows).
 */
async function fullPageShot(page, path, check = async () => {}) {
  const viewport = page.viewportSize();
  const height = await page.evaluate(() => document.documentElement.scrollHeight);
  const show = (top) => page.evaluate((top) => {
    window.scrollTo(0, top);
    window.__inbetween.figures.forEach((f) => f.viewer?.setVisible(true));
  }, top);
  // Parts of equal height, so that the last is not a sliver of a few pixels.
  const each = Math.ceil(height / Math.ceil(height / SHOT_PART));
  for (let top = 0, part = 1; top < height; top += each, part += 1) {
    await page.setViewportSize({ width: viewport.width, height: Math.min(height - top, each) });
    await show(top);
    await frames(page, 4);
    if (part === 1) await check();
    // JPEG (`path` ends in .jpg): a part of 8,000 px costs about half as long to capture as in
    // PNG. The caret is left as it is (hiding it restyles the whole page).
    await page.screenshot({ path: part === 1 ? path : path.replace(/(\.\w+)$/, `-part${part}$1`), type: 'jpeg', quality: 90, caret: 'initial' });
  }
  await page.setViewportSize(viewport);
}

/**
 * A screenshot of one figure. A figure taller than the window would be captured by Playwright
 * beyond the viewport, which lays the page out again at another size and clears the canvases it
 * resizes before their figures can draw again (lesson 02's Figure 1, 909 px tall in a 900 px
 * window, came out blank): the window is made tall enough first, and the figure draws in it.
 */
async function figureShot(page, figure, path) {
  const viewport = page.viewportSize();
  const box = await figure.boundingBox();
  const tall = box && box.height > viewport.height - 16;
  if (tall) await page.setViewportSize({ width: viewport.width, height: Math.ceil(box.height) + 32 });
  await boxInView(figure);
  await frames(page, tall ? 4 : 0);
  await figure.screenshot({ path, caret: 'initial' });
  if (tall) {
    await page.setViewportSize(viewport);
    await frames(page, 2);
  }
}

/** The tallest part of a page one screenshot takes (see `fullPageShot`). */
const SHOT_PART = 8000;

/**
 * A paused 3D figure's pixel statistics once it has settled, as a person would see it after
 * waiting a moment: a loaded machine may present a figure's first frames late (a blank or
 * half-loaded canvas), so up to five looks, a few frames apart, until one is drawn and it stays
 * the same. It stays the same when its renderer presents no frame during the look and the two
 * frames after it (the canvas then shows what was captured: `still` is 0), or when a second look
 * a few frames later differs from it by under 0.5 (`still`: the mean difference, 0..255).
 */
async function settledStats(page, canvas, i) {
  let stats;
  let still = 255;
  for (let look = 0; look < 5; look++) {
    const before = await presented(canvas);
    stats = await pixelStats(page, canvas, `before${i}`);
    await frames(page, 2);
    if (before >= 0 && stats.coverage > 0.02 && (await presented(canvas)) === before) {
      return { ...stats, still: 0, shot: { key: `before${i}`, presented: before } };
    }
    await frames(page);
    const nextPresented = await presented(canvas);
    const next = await pixelStats(page, canvas, `still${i}`);
    still = await meanDifference(page, `before${i}`, `still${i}`);
    if (next.coverage > 0.02 && still < 0.5) return { ...next, still, shot: { key: `still${i}`, presented: nextPresented } };
  }
  return { ...stats, still };
}

/**
 * How many frames the 3D figure around `canvas` has presented (Viewer::canvas_frames), -1 for a
 * canvas that is not a figure's.
 */
const presented = (canvas) => canvas.evaluate((c) => window.__inbetween.figures.find((f) => c.closest(f.selector))?.viewer.canvasFrames ?? -1);

/**
 * Waits until the 3D figure around `canvas` has presented more than `since` frames and at least two
 * animation frames have passed (the figure draws in the frame after an input event; the next one
 * shows it), or `maxFrames` frames when it presents nothing.
 */
function presentedSince(canvas, since, maxFrames = 6) {
  return canvas.evaluate((c, [since, maxFrames]) => new Promise((ok) => {
    const viewer = window.__inbetween.figures.find((f) => c.closest(f.selector))?.viewer;
    let seen = 0;
    const look = () => {
      seen += 1;
      if (seen >= maxFrames || (seen >= 2 && viewer && viewer.canvasFrames > since)) ok();
      else requestAnimationFrame(look);
    };
    requestAnimationFrame(look);
  }), [since, maxFrames]);
}

/**
 * A drag on the canvas orbits the camera: the image must change. `settled` (from settledStats)
 * names the pixels it captured and the figure's frame count then: while the figure has presented
 * no frame since, the canvas still shows those pixels, which are the image before the drag.
 */
async function orbitDrag(page, canvas, i, settled) {
  const box = await boxInView(canvas);
  let since = await presented(canvas);
  let before = settled?.key;
  if (!settled || since !== settled.presented) {
    before = `orbit-before${i}`;
    await pixelStats(page, canvas, before);
    since = await presented(canvas);
  }
  // Two moves while the button is down: Chromium delivers each in its own animation frame, and the
  // figure draws a frame for each (five moves cost five renders on SwiftShader for the same check).
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.5);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.7, box.y + box.height * 0.6, { steps: 2 });
  await page.mouse.up();
  // The new view may reach the screen a few frames late on a loaded machine: up to three looks,
  // the first once the figure has presented a new frame (at most 6 animation frames), the others
  // 6 frames apart.
  let change = 0;
  for (let look = 0; look < 3 && change <= 0.2; look++) {
    await (look === 0 ? presentedSince(canvas, since) : frames(page));
    await pixelStats(page, canvas, `orbit-after${i}`);
    change = await meanDifference(page, before, `orbit-after${i}`);
  }
  assert.ok(change > 0.2, `figure ${i}: dragging the canvas did not move the camera (an orbit, or a pan for a flat figure) (${change})`);
}

/**
 * Moves every control of a figure, one at a time, as a person would (sliders by a click on the
 * slider, checkboxes, dropdowns, buttons, the timeline's scrub, play and speed), and checks after
 * each that the figure (canvas, plots and notes) changed and that no error appeared.
 * Returns how many controls it moved.
 */
async function moveEveryControl(page, figure, where, limit = Infinity) {
  let moved = 0;
  // `act(k, before)` must change what the figure shows (`before`: its signature before the act);
  // with `again` (a toggle), a change in either
  // direction counts (turning a walk off while paused may keep the pose; turning it on moves it).
  // A dropdown passes `tries` > 1: the next options are tried in turn until one changes the
  // figure (a preset equal to the current keys changes nothing, rightly), each for up to 12 frames
  // (`waitFrames`), since an option may load a file first (the glTF figures' sample character).
  const check = async (what, act, again = false, tries = 1, waitFrames = 3) => {
    const started = Date.now();
    const before = await pausedSignature(figure);
    let changed = false;
    let after = before;
    for (let k = 0; k < tries && !changed; k++) {
      await act(k, before);
      after = await signatureAfter(figure, before, waitFrames);
      changed = after !== before;
    }
    if (again && !changed) {
      await act(0, after);
      changed = (await signatureAfter(figure, after)) !== after;
    }
    if (process.env.E2E_TIMING) console.log(`${where}: ${what} took ${Date.now() - started} ms`);
    assert.ok(changed, `${where}: ${what} did not change the figure`);
    assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), [], `${where}: ${what} raised an error`);
    moved += 1;
    if (moved >= limit) throw DONE;
  };
  try {
    await moveControls(page, figure, check);
  } catch (e) {
    if (e !== DONE) throw e;
  }
  return moved;
}

const DONE = Symbol('enough controls moved');

async function moveControls(page, figure, check) {
  const controllers = await figure.locator('.lil-controller').all();
  const buttons = [];
  for (const c of controllers) {
    // What the loop needs of a controller, read in one round trip to the page when the loop
    // reaches it (an earlier control may have shown, hidden or disabled it).
    const about = await c.evaluate((el) => {
      const slider = el.querySelector('.lil-slider');
      const fill = slider?.querySelector('.lil-fill');
      const select = el.querySelector('select');
      const box = el.getBoundingClientRect();
      return {
        // As Playwright's isVisible: a box of some size, and not `visibility: hidden`.
        visible: box.width > 0 && box.height > 0 && getComputedStyle(el).visibility !== 'hidden',
        name: el.querySelector('.lil-name')?.textContent || '?',
        classes: el.className,
        options: select ? select.options.length : 0,
        current: select ? select.selectedIndex : -1,
        slider: Boolean(slider),
        fill: slider && fill ? fill.getBoundingClientRect().width / slider.getBoundingClientRect().width : 0,
        value: Number(el.querySelector('input')?.value),
      };
    });
    if (!about.visible) continue;
    const { name, classes } = about;
    if (classes.includes('disabled')) continue; // e.g. a GPU switch without WebGPU
    if (classes.includes('function')) { buttons.push([name, c.locator('button')]); continue; }
    if (classes.includes('boolean')) {
      await check(`toggle "${name}"`, () => clickAt(page, c.locator('input[type="checkbox"]')), true);
      continue;
    }
    if (classes.includes('option')) {
      const select = c.locator('select');
      const { options, current } = about;
      await check(`dropdown "${name}"`, (k) => select.selectOption({ index: (current + 1 + k) % options }), false, options - 1, 12);
      continue;
    }
    if (classes.includes('number')) {
      if (about.slider) {
        const at = about.fill < 0.5 ? 0.8 : 0.2;
        await check(`slider "${name}"`, () => clickAt(page, c.locator('.lil-slider'), at));
      } else {
        const input = c.locator('input');
        const { value } = about;
        await check(`number "${name}"`, async () => {
          await input.fill(String(value === 0 ? 1 : -value));
          await input.press('Enter');
        });
      }
    }
  }
  // The timeline's scrub first, and back to the start after it, as a person drags it: a
  // simulation scrubbed ahead while paused catches up a frame's step budget at a time and draws
  // every frame until it gets there (lesson 15's splash at 8,000 particles: one step a frame,
  // about 270 frames for 1.1 s), which every later check would wait behind; going back restarts
  // it at once. The plays below then move it on from the start (so a "reset" after them has
  // something to undo).
  for (const scrub of await figure.locator('.timeline .scrub').all()) {
    // Several places: a ping-pong timeline shows the same moment at t and at duration − t.
    await check('timeline scrub', (k) => clickAt(page, scrub, [0.37, 0.81, 0.12][k]), false, 3);
    await scrub.evaluate((s) => {
      s.value = '0';
      s.dispatchEvent(new Event('input'));
    });
  }
  // Buttons and dropdowns outside the panels (presets, solo, timeline), then the panels' buttons.
  // The speed's check plays the timeline (pressing play, until the figure changes), which is the
  // play button's check as well: a figure with one timeline and a speed is not played twice.
  let playChecked = false;
  for (const select of await figure.locator('select:not(.lil-controller select)').all()) {
    if (!(await select.isVisible())) continue;
    const label = (await select.getAttribute('aria-label')) ?? 'select';
    const options = await select.locator('option').allTextContents();
    const current = await select.evaluate((s) => s.selectedIndex);
    if (label === 'speed') {
      // Speed shows only while playing: play a moment at the new speed (until the figure changes,
      // at most 10 frames), then pause; up to three plays, as for the play button below (a moment
      // of a clip may hold a pose).
      const play = figure.locator('.timeline .play');
      await check('timeline speed and play', async (k, before) => {
        if (k === 0) await select.selectOption({ index: (current + 1) % options.length });
        await clickAt(page, play);
        await signatureAfter(figure, before, 10);
        await clickAt(page, play);
      }, false, 3);
      playChecked = (await play.count()) === 1;
    } else {
      await check(`dropdown "${label}"`, (k) => select.selectOption({ index: (current + 1 + k) % options.length }), false, options.length - 1, 12);
    }
  }
  for (const play of playChecked ? [] : await figure.locator('.timeline .play').all()) {
    // Each play lasts until the figure changes, at most 10 frames, then pauses. Up to three plays:
    // a figure that draws its states after each step (lesson 11's free fall at a step of 0.24 s)
    // changes only when the time crosses a step, which 10 frames (about 0.17 s at 1x) may not do.
    await check('timeline play', async (k, before) => {
      await clickAt(page, play);
      await signatureAfter(figure, before, 10);
      await clickAt(page, play);
    }, false, 3);
  }
  // (Not "frame all": it moves the camera, which the figure's signature leaves out.)
  for (const button of await figure.locator('button:not(.lil-controller button):not(.timeline button):not(.lil-title):not(.frame-all)').all()) {
    if (!(await button.isVisible())) continue;
    buttons.push([(await button.textContent()).trim(), button]);
  }
  // Last in, first out: a "reset" after the changes above, then "zoom to fit" after the reset (in
  // DOM order a fit would come first, when the view may already fit).
  for (const [name, button] of buttons.reverse()) await check(`button "${name}"`, () => clickAt(page, button));
}

/**
 * Lesson 02's curve editor, used as a person would: a double-click before key 0 (after a reset),
 * then drags of a key across the canvas, a tangent handle, and the last key's time tick (which
 * must stay on the strip and keep its neighbours' order).
 */
async function editorDrags(page) {
  const canvas = page.locator('#fig-keys .editor canvas');
  await canvas.scrollIntoViewIfNeeded();
  let box = await canvas.boundingBox();
  const drag = async ([x0, y0], dx, dy) => {
    await page.mouse.move(box.x + x0, box.y + y0);
    await page.mouse.down();
    await page.mouse.move(box.x + x0 + dx, box.y + y0 + dy, { steps: 8 });
    await page.mouse.up();
    await frames(page, 3);
  };
  const ed = (expr) => page.evaluate(`window.__inbetween.editor.${expr}`);
  // A double-click up and left of key 0 adds a key before it: at the clock's zero, the others
  // moved later, and with both its handles inside the editor above the strip.
  await clickAt(page, page.locator('#fig-keys .reset'));
  await frames(page, 3);
  const reset = await ed('keys()');
  const at = await canvas.boundingBox();
  // 1.2 m left of and 1.2 m above key 0: nearer key 0 than key 1, and further from key 1 than
  // key 0 is, so the new key goes before key 0.
  const [k0, k1] = [await ed('keyPx(0)'), await ed('keyPx(1)')];
  const pxPerM = Math.hypot(k1[0] - k0[0], k1[1] - k0[1]) / Math.hypot(reset[4] - reset[1], reset[5] - reset[2]);
  const [cx, cy] = [k0[0] - 1.2 * pxPerM, k0[1] - 1.2 * pxPerM];
  assert.ok(cx > 0 && cy > 0, `the click at ${cx}, ${cy} is on the editor`);
  await page.mouse.dblclick(at.x + cx, at.y + cy);
  await frames(page, 3);
  const added = await ed('keys()');
  assert.equal(added.length, reset.length + 3, 'the double-click adds a key');
  assert.equal(added[0], 0, `the new key 0 is at the clock's zero (${added[0]} s)`);
  for (let k = 1; k < added.length / 3; k++) {
    assert.ok(Math.abs(added[3 * k] - reset[3 * (k - 1)] - 0.6) < 1e-4, `key ${k} moved 0.6 s later: ${added}`);
  }
  for (const handle of ['inHandlePx(0)', 'outHandlePx(0)']) {
    const [x, y] = await ed(handle);
    const inside = x >= 0 && x <= at.width && y >= 0 && y <= at.height - 46; // above the time strip
    assert.ok(inside, `the new key's ${handle} is in the editor: ${[x, y]} on ${at.width} x ${at.height}`);
  }
  box = at;
  const keys0 = await ed('keys()');
  await pixelStats(page, canvas, 'ed0');
  await drag(await ed('keyPx(2)'), 30, -25);
  const keys1 = await ed('keys()');
  assert.ok(Math.abs(keys1[7] - keys0[7]) > 0.05 && Math.abs(keys1[8] - keys0[8]) > 0.05, 'dragging key 2 moves it');
  await pixelStats(page, canvas, 'ed1');
  assert.ok(await meanDifference(page, 'ed0', 'ed1') > 0.2, 'the editor redraws a moved key');
  const tangents0 = await ed('tangents()');
  await drag(await ed('outHandlePx(1)'), 0, 30);
  const tangents1 = await ed('tangents()');
  assert.notDeepEqual(tangents1.slice(4, 8), tangents0.slice(4, 8), 'dragging a handle changes the tangent');
  const last = (await ed('keys()')).length / 3 - 1;
  const before = await ed('keys()');
  await drag(await ed(`timePx(${last})`), 400, 0);
  const after = await ed('keys()');
  assert.ok(after[3 * last] >= before[3 * last], 'the last key moves later');
  assert.ok(after[3 * last] < before[3 * last] + 3, `the last key stays on the strip (${after[3 * last]} s)`);
  for (let k = 1; k <= last; k++) assert.ok(after[3 * k] > after[3 * (k - 1)], 'key times stay in order');
  assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), []);
}

/**
 * Scrolls `locator`'s element into view unless it is wholly in view already (as a reader scrolls to
 * a control), and returns its box in the viewport: one round trip to the page. Playwright's own
 * scrollIntoViewIfNeeded and click also wait for the element to keep still over two animation
 * frames, which the page's controls and canvases do not need; a click that misses its control changes
 * nothing, and that fails the check.
 */
function boxInView(locator) {
  return locator.evaluate((el) => {
    let r = el.getBoundingClientRect();
    if (r.top < 0 || r.left < 0 || r.bottom > window.innerHeight || r.right > window.innerWidth) {
      el.scrollIntoView({ block: 'center', inline: 'nearest' });
      r = el.getBoundingClientRect();
    }
    return { x: r.left, y: r.top, width: r.width, height: r.height };
  });
}

/** Clicks `locator` with the mouse at the fraction `at` of its width (after scrolling it into view). */
async function clickAt(page, locator, at = 0.5) {
  const box = await boxInView(locator);
  await page.mouse.click(box.x + box.width * at, box.y + box.height / 2);
}

/**
 * What a figure shows, as a string that changes when anything in it changes: the fingerprint of
 * what its 3D view drew last (the viewer hashes its draw list; pixels are read separately, per
 * figure), the pixels of its 2D canvases and plots, and its text outside the controls (notes,
 * matrices, readouts). Much cheaper than two screenshots per control, so every control of every
 * figure can be moved. Runs in the page (it is passed there as source text).
 */
function signatureOf(fig) {
  const parts = [];
  const entry = window.__inbetween.figures.find((f) => fig.matches(f.selector));
  if (entry?.viewer) parts.push(entry.viewer.frameFingerprint());
  for (const canvas of fig.querySelectorAll('canvas')) {
    if (entry && canvas.closest('.stage') && !canvas.classList.contains('view2d') && canvas.parentElement.classList.contains('stage')) continue;
    const ctx = canvas.width && canvas.height ? canvas.getContext('2d', { willReadFrequently: true }) : null;
    if (!ctx) continue;
    const data = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
    let h = 2166136261;
    for (let i = 0; i < data.length; i += 7) h = Math.imul(h ^ data[i], 16777619);
    parts.push(`${canvas.width}x${canvas.height}:${h >>> 0}`);
  }
  const walker = document.createTreeWalker(fig, NodeFilter.SHOW_TEXT, {
    acceptNode: (n) => (n.parentElement.closest('.panel, .lil-gui, .timeline, select, option, button') ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT),
  });
  while (walker.nextNode()) parts.push(walker.currentNode.textContent);
  return parts.join('|');
}

/**
 * Pauses every timeline of the page, waits for the next frame and returns the figure's
 * signature: the state a control is moved from. One round trip to the page.
 */
function pausedSignature(figure) {
  return figure.evaluate((fig, source) => {
    const signature = (0, eval)(`(${source})`);
    for (const button of document.querySelectorAll('.timeline .play')) {
      if (button.textContent.includes('pause')) button.click();
    }
    return new Promise((ok) => requestAnimationFrame(() => ok(signature(fig))));
  }, signatureOf.toString());
}

/**
 * The figure's signature once it differs from `before`, looked at after each animation frame,
 * or after `maxFrames` frames when it does not change (the fixed wait a figure gets to show a
 * change: a control that changes nothing by then fails its check). Waiting for the change itself
 * instead of a fixed count of frames makes a control that changes the figure at once cost one frame.
 */
function signatureAfter(figure, before, maxFrames = 3) {
  return figure.evaluate((fig, [source, before, maxFrames]) => {
    const signature = (0, eval)(`(${source})`);
    return new Promise((ok) => {
      let seen = 0;
      const look = () => {
        const now = signature(fig);
        seen += 1;
        if (now !== before || seen >= maxFrames) ok(now);
        else requestAnimationFrame(look);
      };
      requestAnimationFrame(look);
    });
  }, [signatureOf.toString(), before, maxFrames]);
}

/**
 * At the page's current width, with every figure on screen and drawn (see `fullPageShot`): no
 * shown label of a figure may overlap another or leave its canvas (read from the boxes the shell
 * placed).
 */
async function labelsApart(page, where) {
  const figures = await page.evaluate(() => [...document.querySelectorAll('.figure')].map((figure) => {
    const canvas = figure.querySelector('.stage canvas');
    if (!canvas) return null;
    const c = canvas.getBoundingClientRect();
    const boxes = [...figure.querySelectorAll('.labels span')].filter((s) => !s.hidden).map((s) => {
      const r = s.getBoundingClientRect();
      return { text: s.textContent, l: r.left - c.left, r: r.right - c.left, t: r.top - c.top, b: r.bottom - c.top };
    });
    return { id: figure.id, w: c.width, h: c.height, boxes };
  }).filter(Boolean));
  for (const fig of figures) {
    const at = `${where}, #${fig.id}`;
    for (const b of fig.boxes) {
      assert.ok(b.l >= -1 && b.t >= -1 && b.r <= fig.w + 1 && b.b <= fig.h + 1,
        `${at}: label "${b.text}" (${b.l.toFixed(0)}..${b.r.toFixed(0)}, ${b.t.toFixed(0)}..${b.b.toFixed(0)}) leaves the ${fig.w} x ${fig.h} canvas`);
    }
    for (let i = 0; i < fig.boxes.length; i++) {
      for (let j = i + 1; j < fig.boxes.length; j++) {
        const [a, b] = [fig.boxes[i], fig.boxes[j]];
        const apart = a.r <= b.l + 0.5 || b.r <= a.l + 0.5 || a.b <= b.t + 0.5 || b.b <= a.t + 0.5;
        assert.ok(apart, `${at}: labels "${a.text}" and "${b.text}" overlap`);
      }
    }
  }
}

/**
 * Every figure of the page that declares what must stay in view starts fitted to it; a zoom
 * leaves the fit, and both "frame all" and a double-click bring it back.
 */
async function frameAllReturnsToTheFit(page, where) {
  const ids = await page.evaluate(() => window.__inbetween.figures
    .map((f, i) => (f.viewer.declaresView ? i : -1)).filter((i) => i >= 0));
  for (const i of ids) {
    const selector = await page.evaluate((i) => window.__inbetween.figures[i].selector, i);
    const canvas = page.locator(`${selector} .stage canvas`);
    const box = await boxInView(canvas);
    // The viewer's `fitting` flag changes as its event handlers run: each step waits, frame by
    // frame, until the flag reads as expected (for up to 10 s), instead of a fixed count of frames.
    const fitting = (want) => page.waitForFunction(([i, want]) => window.__inbetween.figures[i].viewer.fitting === want,
      [i, want], { polling: 'raf', timeout: 10_000 }).then(() => want, () => !want);
    assert.equal(await fitting(true), true, `${where} ${selector}: fits from the start`);
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.wheel(0, -600);
    assert.equal(await fitting(false), false, `${where} ${selector}: a zoom leaves the fit`);
    await clickAt(page, page.locator(`${selector} .frame-all`));
    assert.equal(await fitting(true), true, `${where} ${selector}: "frame all" returns to it`);
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.wheel(0, 600);
    assert.equal(await fitting(false), false, `${where} ${selector}: a second zoom leaves the fit`);
    await page.mouse.dblclick(box.x + box.width / 2, box.y + box.height / 2);
    assert.equal(await fitting(true), true, `${where} ${selector}: a double-click returns to it`);
  }
  return ids.length;
}

// E2E_BACKENDS=webgl2 E2E_LESSONS=03 narrows a run while iterating; scripts/test runs everything.
const BACKENDS = (process.env.E2E_BACKENDS ?? 'webgpu,webgl2').split(',');
// Every control is moved on WebGL2; the controls' logic is the same on both backends (only the
// renderer differs), so WebGPU moves the first control of each figure (E2E_FULL=1: all of them).
const sweepLimit = (backend) => (backend === 'webgl2' || process.env.E2E_FULL ? Infinity : 1);
// What does not depend on the backend (the page's layout at both sizes, the exercise switch, every
// control of every figure, "frame all") is checked on WebGL2. WebGPU checks that every figure draws, and that
// the first 3D figure of each page orbits and redraws after a control moves (E2E_FULL=1: all).
const light = (backend) => backend === 'webgpu' && !process.env.E2E_FULL;
const only = process.env.E2E_LESSONS?.split(',');
const lessons = catalog.filter((l) => !only || only.some((p) => l.folder.startsWith(p)));

/**
 * Seconds a lesson's page test may take on a quiet two-core machine running one other test file
 * beside it (as scripts/test does), per backend: what the README's test-time budget gives a
 * lesson. Reported, not asserted (a loaded machine is slower): a lesson over it is named in the
 * output, and a new lesson must fit it.
 */
export const LESSON_BUDGET_SEC = { webgl2: 80, webgpu: 20 };

function reportBudget(backend, seconds) {
  const budget = LESSON_BUDGET_SEC[backend];
  const total = seconds.reduce((sum, [, s]) => sum + s, 0);
  const over = seconds.filter(([, s]) => s > budget);
  console.log(`e2e time on ${backend}: ${seconds.map(([f, s]) => `${f} ${s.toFixed(0)} s`).join(', ')}; ` +
    `total ${total.toFixed(0)} s; budget ${budget} s a lesson` +
    (over.length ? `; OVER BUDGET: ${over.map(([f, s]) => `${f} (${s.toFixed(0)} s)`).join(', ')}` : ''));
}

/**
 * Registers the lesson tests of the calling file: every lesson on each backend (narrowed by
 * E2E_BACKENDS), and the gallery on each; `extras` registers the checks without a GPU API instead.
 * With `parts` > 1 the pages (a backend's gallery or lesson) are shared among that many files:
 * when scripts/test sets E2E_RUN_ID, each file takes the next page nobody has taken (a directory
 * created per page, which only one process can create), so the files finish together whatever
 * each page costs; otherwise part k takes the pages at positions k, k + parts, ... The pages come
 * in the order WebGL2's lessons, then WebGPU's (about a quarter as long each), so that the last
 * ones to be taken are short. A file opens a context in a backend's browser when it takes its
 * first page on that backend, and closes it when it takes one on the other.
 */
export function lessonTests({ part = 0, parts = 1, extras = false }) {
  if (extras) {
    registerExtras();
    return;
  }
  const runId = process.env.E2E_RUN_ID;
  const pages = ['webgl2', 'webgpu'].filter((b) => BACKENDS.includes(b))
    .flatMap((backend) => [{ backend, lesson: null }, ...lessons.map((lesson) => ({ backend, lesson }))]);
  const take = parts === 1 ? () => true
    : runId ? ({ backend, lesson }) => claim(runId, `${backend}-${lesson?.folder ?? 'gallery'}`)
      : (p) => pages.indexOf(p) % parts === part;
  test(`lesson pages${parts > 1 ? ` (part ${part + 1} of ${parts})` : ''}`, async (t) => {
    let browser = null;
    const seconds = { webgl2: [], webgpu: [] };
    let framesFitted = 0;
    try {
      for (const p of pages) {
        if (!take(p)) continue;
        if (browser?.backend !== p.backend) {
          await browser?.context.close();
          browser = null;
          browser = { backend: p.backend, context: await launch(p.backend) };
        }
        const { context } = browser;
        if (!p.lesson) {
          await t.test(`gallery lists every lesson, on ${p.backend}`, () => galleryPage(context, p.backend));
          continue;
        }
        await t.test(`${p.lesson.folder} on ${p.backend}`, async () => {
          const started = Date.now();
          framesFitted += await lessonPage(context, p.backend, p.lesson);
          seconds[p.backend].push([p.lesson.folder, (Date.now() - started) / 1000]);
        });
      }
      if (!only) {
        // The fit checks find something to check: some figure of the course declares its view.
        // Files that share the pages add up their counts (`fittedInRun`).
        const fitted = parts === 1 ? framesFitted : fittedInRun(runId, part, parts, framesFitted);
        if (fitted !== null) assert.ok(fitted > 0, 'some figure declares its view');
      }
      for (const backend of ['webgl2', 'webgpu']) if (seconds[backend].length) reportBudget(backend, seconds[backend]);
    } finally {
      await browser?.context.close();
    }
  });
}

/**
 * Records that part `part` of `parts` checked `count` figures' fit in the run `runId` (without one,
 * the run of the `node --test` process that started this file) and returns the total of every part,
 * or null while some part has not finished: the last part to finish gets the total.
 */
function fittedInRun(runId, part, parts, count) {
  const dir = join(tmpdir(), `inbetween-e2e-${runId ?? `runner-${process.ppid}`}`);
  mkdirSync(dir, { recursive: true });
  writeFileSync(join(dir, `fitted-${part}-of-${parts}`), String(count));
  let total = 0;
  for (let k = 0; k < parts; k++) {
    try {
      total += Number(readFileSync(join(dir, `fitted-${k}-of-${parts}`), 'utf8'));
    } catch {
      return null;
    }
  }
  return total;
}

/** Takes `what` for this process in the run `runId`: true for exactly one caller of the run. */
function claim(runId, what) {
  const dir = join(tmpdir(), `inbetween-e2e-${runId}`);
  mkdirSync(dir, { recursive: true });
  try {
    mkdirSync(join(dir, what));
    return true;
  } catch (e) {
    if (e.code === 'EEXIST') return false;
    throw e;
  }
}

/** The gallery lists every lesson of the catalog, without an error (a screenshot to look at). */
async function galleryPage(context, backend) {
  const { page, problems } = await open(context, '/lessons/');
  const cards = await page.locator('.card').count();
  assert.equal(cards, catalog.length);
  assert.deepEqual(problems, []);
  await page.screenshot({ path: `${SHOTS}/index-${backend}.png`, fullPage: true });
  await page.close();
}

/**
 * A lesson's page on `backend`, as a person uses it (see the file's first lines and the README).
 * Returns how many of its figures were checked to return to their fit ("frame all").
 */
async function lessonPage(context, backend, lesson) {
  const clock = phaseClock(`${lesson.folder} (${backend})`);
  // The checks before the page sizes' look at the figures' draw lists, text and plots, and at
  // their 3D pixels only through fractions and means (coverage, colours, a mean difference): they
  // run with the 3D figures drawn at half resolution (a quarter of SwiftShader's pixels), and the
  // page sizes' checks and screenshots at full resolution.
  const { page, problems } = await open(context, `/lessons/${lesson.folder}/?backend=${backend}&render-scale=${SWEEP_RENDER_SCALE}`);
  clock('load');
  const label = backend === 'webgpu' ? 'WebGPU' : 'WebGL2';
  assert.equal(await page.evaluate(() => document.body.dataset.backend), label);
  await pauseTimelines(page);
  await frames(page);
  // Paused, nothing a 3D figure draws changes, so its renderer draws no more frames (at
  // most a couple, should a late layout change resize a canvas).
  const drawn = () => page.evaluate(() => window.__inbetween.figures.map((f) => [f.selector, f.viewer.canvasFrames]));
  const drawnBefore = await drawn();
  await frames(page, 20);
  const stillDrawing = (await drawn()).filter(([, n], k) => n - drawnBefore[k][1] > 2);
  assert.deepEqual(stillDrawing.map(([s]) => s), [], 'these paused figures kept drawing');
  // Every figure as the page first shows it (timelines paused, the page's own cameras and
  // settings), before the sweep orbits any camera or moves any control (some figures share
  // their settings): the screenshots to review the looks by. Each is taken once the figure,
  // scrolled into view, has drawn again (a figure off screen keeps its last frame).
  if (!light(backend)) {
    for (const [i, figure] of (await page.locator('.figure').all()).entries()) {
      await boxInView(figure);
      await frames(page, 3);
      await figureShot(page, figure, `${SHOTS}/${lesson.folder}-fig${i}-default-${backend}.png`);
    }
    clock('default screenshots');
  }
  await plotsNameTheirUnits(page);
  // "Frame all" is checked through the viewer's `fitting` flag, which its event handlers set
  // whatever the backend draws with: on WebGL2, as the controls are (E2E_FULL=1: on both).
  const framesFitted = light(backend) ? 0 : await frameAllReturnsToTheFit(page, lesson.folder);
  clock('frame all');
  if (lesson.folder.startsWith('02-')) await editorDrags(page);
  if (lesson.folder.startsWith('05-')) {
    await gpuNoiseMatchesCpu(page, label);
    await normalsPlotKeepsTheArrowsColours(page);
    await normalsPlotStartsAtZero(page);
  }
  clock('editor drags, GPU noise check');
  const figures = await page.locator('.figure').all();
  assert.ok(figures.length > 0, 'a lesson has at least one figure');
  let interacted = false;
  for (const [i, figure] of figures.entries()) {
    // A figure is a 3D view (wgpu canvas), a 2D drawing (canvas.view2d) or plots only.
    const canvas = figure.locator('.stage > canvas').first();
    const kind = !(await canvas.count()) ? 'plots'
      : (await canvas.evaluate((c) => c.classList.contains('view2d'))) ? '2d' : '3d';
    if (kind !== '3d' && light(backend)) continue;
    if (kind !== '3d') {
      const stats = await pixelStats(page, kind === '2d' ? canvas : figure.locator('.plot, canvas').first(), `drawn${i}`);
      assert.ok(stats.coverage > 0.02, `figure ${i} (${kind}): looks blank (coverage ${stats.coverage})`);
      const moved = await moveEveryControl(page, figure, `${lesson.folder} figure ${i}`, sweepLimit(backend));
      assert.ok(moved > 0, `figure ${i}: no control was found to move`);
      await figureShot(page, figure, `${SHOTS}/${lesson.folder}-fig${i}-${backend}.png`);
      await plotsShowNumbers(figure, i);
      clock(`figure ${i} (${kind}): every control`);
      continue;
    }
    if (process.env.THUMBNAILS && i === (lesson.thumbnailFigure ?? 0)) {
      // Without the backend badge: the thumbnail shows the figure, not the test's backend.
      await page.evaluate(() => document.body.classList.add('thumbnail'));
      // A second of play first (a fountain 0.2 s after the page loads is a few specks), then the
      // gallery card's shape (16 : 10, www/style.css's `.card img`) at most, cut from the
      // canvas's middle: a wider canvas would leave bands above and below it in the card.
      const play = figure.locator('.timeline .play').first();
      if (await play.count()) {
        await clickAt(page, play);
        await frames(page, 60);
        await clickAt(page, play);
        await frames(page, 3);
      }
      const box = await canvas.boundingBox();
      const width = Math.min(box.width, (box.height * 16) / 10);
      const clip = { x: box.x + (box.width - width) / 2, y: box.y, width, height: box.height };
      writeFileSync(`lessons/${lesson.folder}/${lesson.thumbnail ?? 'thumbnail.png'}`, await page.screenshot({ clip }));
      await page.evaluate(() => document.body.classList.remove('thumbnail'));
    }
    assert.equal(await figure.locator('.backend-badge').textContent(), label);
    const before = await settledStats(page, canvas, i);
    assert.ok(before.coverage > 0.02, `figure ${i}: canvas looks blank (coverage ${before.coverage})`);
    assert.ok(before.colors > 20, `figure ${i}: too few colours (${before.colors}) for shaded geometry`);
    assert.ok(before.still < 0.5, `figure ${i}: image changes while paused (${before.still})`);
    clock(`figure ${i}: settled`);
    if (light(backend) && interacted) continue;
    interacted = true;
    await orbitDrag(page, canvas, i, before.shot);
    clock(`figure ${i}: orbit`);
    const moved = await moveEveryControl(page, figure, `${lesson.folder} figure ${i}`, sweepLimit(backend));
    assert.ok(moved > 0, `figure ${i}: no control was found to move`);
    await figureShot(page, figure, `${SHOTS}/${lesson.folder}-fig${i}-${backend}.png`);
    await plotsShowNumbers(figure, i);
    clock(`figure ${i}: every control`);
  }
  // The exercise switch: on the untouched stubs, the page must say the exercise is not done.
  const toggle = page.locator('.lil-controller', { hasText: 'use my exercise' }).locator('input[type="checkbox"]');
  if (!light(backend) && await toggle.count()) {
    // The page grades the exercises in a worker first (an endless loop must not reach the page).
    await page.waitForFunction(() => window.__inbetween.exerciseCheck.done, null, { timeout: 30_000 });
    await toggle.first().check();
    await frames(page);
    const notes = (await page.locator('.exercise-note').allTextContents()).join(' ');
    assert.match(notes, /not done yet/i, 'a stub exercise is reported in the page');
  }
  clock('exercise switch');
  // The quiz, on this page already loaded (WebGL2 only: it sets controls, which the sweep
  // has already checked on both backends).
  if (backend === 'webgl2') await quizShowMeSetsFigures(page, lesson.folder);
  clock('quiz');
  // Both page sizes the course supports, last: no sideways scrolling, no label over another or
  // off its canvas, and the page's screenshots to look at (in the state the controls and the quiz
  // left). A backend that skips them gets one screenshot at the test's own size.
  const sizes = light(backend) ? [] : [[800, 600], [1600, 1000]];
  await page.evaluate(() => window.__inbetween.setRenderScale(1));
  for (const [w, h] of sizes) {
    await page.setViewportSize({ width: w, height: h });
    await frames(page);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 0, `${w}x${h}: the page scrolls sideways by ${overflow} px`);
    // A displayed formula wider than its column scrolls inside its own box (style.css), which a
    // reader may not notice: every one must fit.
    const cut = await page.evaluate(() => [...document.querySelectorAll('.katex-display')]
      .filter((d) => d.scrollWidth > d.clientWidth + 1)
      .map((d) => d.querySelector('annotation')?.textContent.trim().slice(0, 60)));
    assert.deepEqual(cut, [], `${w}x${h}: these displayed formulas are wider than the text column`);
    await fullPageShot(page, `${SHOTS}/${lesson.folder}-${w}x${h}-${backend}.jpg`,
      () => labelsApart(page, `${lesson.folder} at ${w} x ${h}`));
    clock(`${w}x${h} page`);
  }
  if (!sizes.length) {
    await fullPageShot(page, `${SHOTS}/${lesson.folder}-${backend}.jpg`);
    clock('page screenshot');
  }
  assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), [], 'the error banner is empty');
  assert.deepEqual(problems, []);
  await page.close();
  return framesFitted;
}

function registerExtras() {
  test('a browser without WebGPU or WebGL2 gets a clear message', async () => {
    const context = await launch('none');
    try {
      for (const lesson of catalog) {
        const { page } = await open(context, `/lessons/${lesson.folder}/`);
        const notes = await page.locator('.no-gpu').allTextContents();
        assert.ok(notes.length > 0, 'each figure is replaced by a message');
        for (const note of notes) {
          assert.match(note, /Neither WebGPU nor WebGL2 is available/);
          // A sentence for the reader, not wgpu's debug print of its error (that goes to the console).
          assert.doesNotMatch(note, /[{}]|InstanceError|\.\./, note);
        }
        // The message stands alone: no empty timeline or plot boxes (bordered strips) under it.
        const strips = await page.locator('.figure :is(.timeline, .plot):empty:visible').count();
        assert.equal(strips, 0, `${lesson.folder}: empty timeline or plot boxes show`);
        const banner = await page.locator('#error-banner').textContent();
        assert.match(banner, /Neither WebGPU nor WebGL2/);
        assert.doesNotMatch(banner, /[{}]|InstanceError/, banner);
        await page.screenshot({ path: `${SHOTS}/${lesson.folder}-none.png` });
        await page.close();
      }
    } finally {
      await context.close();
    }
  });

  test('forcing WebGPU where there is none says so', async () => {
    const context = await launch('webgl2');
    try {
      const { page } = await open(context, `/lessons/${catalog[0].folder}/?backend=webgpu`);
      const note = await page.locator('.no-gpu').first().textContent();
      assert.match(note, /WebGPU was requested/);
    } finally {
      await context.close();
    }
  });
}
