// Lessons 11 and 12 in Chromium: the squash figure's two labels never overlap (at both page
// sizes, over its timeline), the free-fall plot shows signed heights (the two Euler lines on
// either side of zero) and its note says which side each is on, the flock note gives the
// steering arrow's scale, and a plot fits inside its box (its last tick label included); a
// fountain at 1000/s beside explosions never fills the system (a burst never takes every slot)
// and the note says how long its particles live; the bouncing balls stay in the picture at
// e = 1, μ = 0; the boid rules' three labels stay apart; the flock's rule weights are in view
// with a panel no taller than the canvas; the flock's order plot is drawn from its samples.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, serveDist, openPage, setControl, bluePixels, fastestDashedSlowestDotted, decadesReadable } from './browser.mjs';

const site = serveDist();
const open = (context, path, width, height) => openPage(context, site.origin + path, { width, height });

/**
 * How many pixels of the flock's order plot are the polarisation line's purple (#944fc9). Runs in
 * the page (passed as source text), so that a test can wait for the line instead of a fixed time.
 */
function purplePixels() {
  const c = document.querySelector('#flock-order-plot canvas');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - 0x94) < 40 && Math.abs(d[i + 1] - 0x4f) < 40 && Math.abs(d[i + 2] - 0xc9) < 40) n++;
  return n;
}

/**
 * Waits (every 100 ms, for up to 30 s) until the order plot shows more than 50 purple pixels and
 * `note` matches the flock's note, then returns the purple count (the caller asserts on it).
 */
async function orderLineDrawn(page, note) {
  await page.waitForFunction(([count, note]) => (0, eval)(`(${count})`)() > 50
    && new RegExp(note).test(document.getElementById('flock-note').textContent),
  [purplePixels.toString(), note.source], { polling: 100, timeout: 30_000 }).catch(() => {});
  return page.evaluate((count) => (0, eval)(`(${count})`)(), purplePixels.toString());
}

/** The visible label boxes of `figure`, as the reader sees them. */
function labelBoxes(page, figure) {
  return page.evaluate((figure) => [...document.querySelectorAll(`${figure} .labels span`)]
    .filter((s) => !s.hidden)
    .map((s) => { const r = s.getBoundingClientRect(); return { text: s.textContent, l: r.left, r: r.right, t: r.top, b: r.bottom }; }), figure);
}

test('lesson 12: the flock note gives the steering arrow scale', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '/lessons/12-boids/?backend=webgl2', 800, 600);
    await frames(page, 4);
    const note = await page.locator('#flock-note').textContent();
    assert.match(note, /purple arrow, 1 m per m\/s²/, note);
    // The step-time plot fits inside its box's padding, so its last x tick (1,600) is not cut
    // off by the figure's edge (the shell sizes plots by the box's content width, not its
    // clientWidth, which includes the padding).
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

/** Moves a figure's timeline to `at` (0–1000 of its length) and lets it draw. */
async function scrubTo(page, figure, at) {
  const scrub = page.locator(`${figure} .scrub`);
  await scrub.fill(String(at));
  await scrub.dispatchEvent('input');
  await frames(page, 4);
}

/** Lesson 11's squash figure: its two labels stay apart over its timeline; the free-fall note says
 * which side of the parabola each Euler ends on. */
async function squashAndFreefall(page, w, h) {
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
  // Just before the timeline's end, where a playing timeline wraps, the throw's last step (the
  // plot's last point, 13 steps at Δt = 0.1 s) is shown too.
  await fallScrub.fill('990');
  await fallScrub.dispatchEvent('input');
  await frames(page, 4);
  const nearEnd = await page.locator('#freefall-note').textContent();
  assert.match(nearEnd, /^After 13 steps of dt = 0\.1\d* s \(t = 1\.3\d* s\)/, nearEnd);
  assert.match(await page.locator('#freefall-plot').getAttribute('data-plot'), /Height above the exact parabola/);
}

/** Lesson 11's emitters at 1000/s beside explosions never fill the system; the bouncing balls stay
 * in view at e = 1, μ = 0. */
async function fountainAndBounce(page, w, h) {
  const fig = '#fig-emitters';
  await page.locator(fig).scrollIntoViewIfNeeded();
  // The explosion has its own slider, so at 1000/s in "both" mode with a 6 s lifetime a
  // burst does not scale with the rate (2 × the rate would take all 2000 slots).
  await setControl(page, fig, 'emitter', 'both');
  await setControl(page, fig, 'fountain rate', 1000);
  await setControl(page, fig, 'lifetime', 6);
  assert.equal(await page.locator(`${fig} .lil-controller`, { hasText: 'particles per explosion' }).count(), 1);
  for (const at of [40, 300, 600, 950]) {
    await scrubTo(page, fig, at);
    const note = await page.locator('#emitters-note').textContent();
    const alive = Number(/^(\d+) particles alive/.exec(note)?.[1]);
    assert.ok(alive > 0 && alive < 2000, `${w}x${h}, scrub ${at}: ${note}`);
    assert.doesNotMatch(note, /full/, note);
    assert.match(note, /A stream of 1,000 particles\/s living 6\.00 s would need about 6,000 slots\. The fountain's 1,200 hold 1\.18 s of it .* so its particles live 0\.98 s \(± 20 %\): .* rate × lifetime \(the plot.s dashed guide\) is \d/, note);
  }
  // Bouncing at e = 1, μ = 0: the blue balls that the sphere throws sideways stay in the
  // picture: a glass box bounces them back (without it they leave within the 6 s timeline).
  const bounce = '#fig-bounce';
  await page.locator(bounce).scrollIntoViewIfNeeded();
  await setControl(page, bounce, 'restitution', 1);
  await setControl(page, bounce, 'friction', 0);
  // The plot of the orange ball's height and energy: its y axis spans the drop height
  // (2.12 m above the floor) and not much more, since the energy never grows.
  const plot = page.locator('#bounce-plot');
  assert.equal(await plot.getAttribute('data-plot'), 'The orange ball: height and energy');
  const [lo, hi] = (await plot.getAttribute('data-y-range')).split(' ').map(Number);
  assert.ok(lo <= 0 && hi >= 2.1 && hi < 2.8, `bounce plot y range ${lo} ${hi}`);
  await scrubTo(page, bounce, 0);
  const start = await bluePixels(page, bounce);
  for (const at of [500, 750, 999]) {
    await scrubTo(page, bounce, at);
    const now = await bluePixels(page, bounce);
    assert.ok(now > 0.6 * start, `${w}x${h}, scrub ${at}: ${now} blue pixels, ${start} at the start`);
  }
}

// Lesson 11 at both page sizes: one page per size serves the squash, free-fall, fountain and
// bouncing checks (each a subtest, on figures the others do not set): two page loads, not four.
test('lesson 11 at 800 x 600 and 1600 x 1000', async (t) => {
  const context = await launch('webgl2');
  try {
    for (const [w, h] of [[800, 600], [1600, 1000]]) {
      const { page, problems } = await open(context, '/lessons/11-particles/?backend=webgl2', w, h);
      await t.test(`squash labels apart, free-fall plot signed and its note says the side (${w}x${h})`, () => squashAndFreefall(page, w, h));
      await t.test(`a fast fountain keeps flowing beside its own-sized explosions; bouncing balls stay in view at e = 1 (${w}x${h})`, () => fountainAndBounce(page, w, h));
      assert.deepEqual(problems, []);
      await page.close();
    }
  } finally {
    await context.close();
  }
});

test('lesson 11: explode now on a paused figure shows its sparks at once, and counts after a move of one notch', async () => {
  // A paused figure shows the sparks of a press at once, not only once played (a replay that
  // stopped short of the press would hide them until then).
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '/lessons/11-particles/?backend=webgl2', 800, 600);
    const fig = '#fig-emitters';
    await page.locator(fig).scrollIntoViewIfNeeded();
    // Playing, the live-particle curves reach the playhead: at each look (between frames), at
    // most a step (1/60 s) and the clock's rounding behind it, whatever the frame rate.
    await frames(page, 20);
    let gap = 0;
    for (let k = 0; k < 24; k++) {
      const [clock, last] = await page.evaluate(() => [document.querySelector('#fig-emitters .clock').textContent,
        document.getElementById('emitters-plot').dataset.xLast]);
      if (parseFloat(clock) > 0.3) gap = Math.max(gap, parseFloat(clock) - Number(last));
      await page.waitForTimeout(23);
    }
    assert.ok(gap < 0.03, `the fountain's curve ends up to ${gap.toFixed(3)} s before the playhead`);
    await scrubTo(page, fig, 300);
    const text = () => page.locator('#emitters-note').textContent();
    const alive = async () => Number(/^(\d+) particles alive/.exec(await text())?.[1]);
    const before = await alive();
    const explode = page.locator(`${fig} .lil-controller`, { hasText: 'explode now' }).locator('button');
    await explode.click();
    await frames(page, 4);
    assert.equal(await alive(), before + 400, await text());
    assert.match(await text(), /Explosions set off by hand: 1\./);
    // The timeline moved one notch with the keyboard (6 ms of its 6 s, inside the figure's
    // step of 1/60 s), then "explode now" at once: a press of its own, not "did nothing".
    await page.locator(`${fig} .scrub`).focus();
    await page.keyboard.press('ArrowRight');
    await explode.click();
    await frames(page, 4);
    assert.equal(await page.locator(`${fig} .clock`).textContent(), '1.81 s');
    assert.match(await text(), /Explosions set off by hand: 2\./);
    assert.doesNotMatch(await text(), /did nothing/);
    assert.equal(await alive(), before + 800, await text());
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('a typed value a number box cannot take says what became of it (lesson 11)', async () => {
  // lil-gui keeps the old value for text that is not a number and clamps a number outside the
  // slider's range, both without a word; the shell says so under the control, until the
  // next accepted value. A second "explode now" at the same paused moment says why it did nothing.
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '/lessons/11-particles/?backend=webgl2', 800, 600);
    const fig = '#fig-emitters';
    await page.locator(fig).scrollIntoViewIfNeeded();
    const gravity = page.locator(`${fig} .lil-controller`, { hasText: 'gravity' });
    const box = gravity.locator('input');
    // Each number control has its note right after it.
    const note = gravity.locator('xpath=following-sibling::*[1]');
    const type = async (text) => {
      await box.fill(text);
      await box.press('Enter');
      await frames(page, 2);
    };
    await type('abc');
    assert.equal(await note.getAttribute('class'), 'typed-note');
    assert.match(await note.textContent(), /“abc” is not a number: gravity \(m\/s²\) stays 9\.81\./);
    assert.equal(await box.inputValue(), '9.81', 'the old value back in the box');
    await type('-50');
    assert.match(await note.textContent(), /-50 is outside 0 to 20: gravity \(m\/s²\) is set to 0\./);
    assert.ok(await note.isVisible());
    await page.locator(fig).screenshot({ path: 'tests/screenshots/11-particles-typed-value-webgl2.png' });
    // Text that starts with a number: lil-gui takes the start, and the note says so.
    await type('4.5.5');
    assert.match(await note.textContent(), /“4\.5\.5” is not a number; its start was read as 4\.5: gravity \(m\/s²\) is set to 4\.5\./);
    await type('4.5');
    assert.ok(!(await note.isVisible()), 'an accepted value takes the note away');
    // The figure took the accepted value (the note's bounce sentence is unaffected; the
    // panel shows it).
    assert.equal(await box.inputValue(), '4.5');
    // Out of range, then a drag of the slider: the note goes.
    await type('1e30');
    assert.match(await note.textContent(), /1e30 is outside 0 to 20: gravity \(m\/s²\) is set to 20\./);
    const slider = gravity.locator('.lil-slider');
    const r = await slider.boundingBox();
    await page.mouse.click(r.x + r.width * 0.5, r.y + r.height / 2);
    await frames(page, 2);
    assert.ok(!(await note.isVisible()), 'a drag takes the note away');
    // A note says what became of the last value typed: a change of another control clears it.
    await type('abc');
    assert.ok(await note.isVisible());
    const fade = page.locator(`${fig} .lil-controller`, { hasText: 'fade with age' }).locator('input[type="checkbox"]');
    await fade.click();
    await frames(page, 2);
    assert.ok(!(await note.isVisible()), 'another control\'s change takes the note away');
    await fade.click();
    // Two presses of "explode now" at one paused moment: the second says why it did nothing.
    await scrubTo(page, fig, 300);
    const explode = page.locator(`${fig} .lil-controller`, { hasText: 'explode now' }).locator('button');
    await explode.click();
    await frames(page, 2);
    await explode.click();
    await frames(page, 2);
    assert.match(await page.locator('#emitters-note').textContent(), /The last press did nothing: an explosion was set off at this moment already/);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 12: the step-time sweep ends on log-log axes with a note of the slopes it measured; its legend tells the fastest from the slowest; Figure 2 measures the step time of the count it shows', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await open(context, '/lessons/12-boids/?backend=webgl2', 1280, 800);
    // Which line is the fastest and which the slowest reads from the legend.
    await fastestDashedSlowestDotted(page, '#flock-plot', ['grid', 'naive']);
    const sweep = page.locator('#flock-sweep');
    await page.waitForFunction(() => document.getElementById('flock-sweep').textContent.startsWith('Measured in this run'), null, { timeout: 60_000 });
    assert.match(await sweep.textContent(), /slope \d\.\d \(×\d+\.\d per doubling of N\)/);
    // Log axes: the y range runs between powers of ten, both positive.
    const [lo, hi] = (await page.locator('#flock-plot').getAttribute('data-y-range')).split(' ').map(Number);
    assert.ok(lo > 0 && hi > lo && Number.isInteger(Math.log10(lo)) && Number.isInteger(Math.log10(hi)), `${lo} ${hi}`);
    await decadesReadable(page, '#flock-plot');
    // The x axis spans the sizes timed, from 100 boids to the largest (the one the note names,
    // or the next, where only the grid was timed), not up to the next power of ten.
    const largest = Number(/At N = (\d+)/.exec(await sweep.textContent())?.[1]);
    const [xLo, xHi] = (await page.locator('#flock-plot').getAttribute('data-x-range')).split(' ').map(Number);
    assert.ok(xLo === 100 && (xHi === largest || xHi === 2 * largest), `${xLo} ${xHi}, largest ${largest}`);
    // The button starts it again.
    await page.locator('#flock-measure').click();
    await frames(page, 2);
    assert.match(await sweep.textContent(), /^Measuring one step at N = /);
    // The last run's medians stay on the plot, named in the legend, up to the largest size it
    // timed, while the new run measures from the smallest; the note says so.
    assert.match(await sweep.textContent(), /The last run's medians stay, pale grey and dashed, until this run has timed every size\./);
    const legend = () => page.evaluate(() => [...document.querySelectorAll('#flock-plot .u-legend .u-series')]
      .filter((row) => row.style.display !== 'none').map((row) => row.textContent.trim()));
    assert.ok((await legend()).includes('previous run (medians)'), `${await legend()}`);
    const xLast = Number(await page.locator('#flock-plot').getAttribute('data-x-last'));
    assert.ok(xLast >= largest, `the plot's curves end at ${xLast}, the last run reached ${largest}`);
    await page.locator('#fig-timing').screenshot({ path: 'tests/screenshots/12-boids-timing-remeasuring-webgl2.png' });
    // Figure 2's step time belongs to the count it was measured at: paused, a new count asks to
    // play instead of showing the old count's time; played, it is measured.
    const play = page.locator('#flock-timeline .play');
    if ((await play.textContent()).includes('pause')) await play.click();
    await setControl(page, '#fig-flock', 'boids', 600);
    const timing = (re) => page.waitForFunction((re) => new RegExp(re).test(document.getElementById('flock-timing').textContent), re.source, { timeout: 10_000 }).catch(async (e) => { throw new Error(`${e.message}: ${await page.locator('#flock-timing').textContent()}`); });
    await timing(/\(grid search, 600 boids\): play the flock to measure it/);
    await play.click();
    await timing(/^Measured step time \(grid search, 600 boids\): \d+\.\d+ ms per step/);
    // The new run, once done, replaces the last one: its entry leaves the legend (the frame
    // after the last timing, when the sweep has nothing left to time).
    await page.waitForFunction(() => {
      const text = document.getElementById('flock-sweep').textContent;
      return text.startsWith('Measured in this run') && !text.includes('medians stay');
    }, null, { timeout: 60_000 });
    assert.ok(!(await legend()).some((name) => /previous/.test(name)), `${await legend()}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 12: the order plot, the rules labels apart, the rule weights in view', async () => {
  const context = await launch('webgl2');
  try {
    for (const [w, h] of [[800, 600], [1600, 1000]]) {
      const { page, problems } = await open(context, '/lessons/12-boids/?backend=webgl2', w, h);
      // The rules figure's three labels do not cover each other, at the defaults too.
      const rules = '#fig-rules';
      await frames(page, 4);
      const boxes = await labelBoxes(page, rules);
      assert.equal(boxes.length, 3, JSON.stringify(boxes));
      for (let i = 0; i < boxes.length; i++) {
        for (let j = 0; j < i; j++) {
          const [a, b] = [boxes[i], boxes[j]];
          const apart = a.r <= b.l || b.r <= a.l || a.b <= b.t || b.b <= a.t;
          assert.ok(apart, `${w}x${h}: ${a.text} and ${b.text} overlap ${JSON.stringify(boxes)}`);
        }
      }
      // The flock's weights for all three rules are visible (the Try this names alignment and
      // separation), and the panel is no taller than the canvas.
      const flock = '#fig-flock';
      await page.locator(flock).scrollIntoViewIfNeeded();
      // Playing, the order curves reach the playhead (a step and the clock's rounding behind
      // it at most, at each look between frames).
      if (w === 800) {
        await frames(page, 20);
        let gap = 0;
        for (let k = 0; k < 24; k++) {
          const [clock, last] = await page.evaluate((flock) => [document.querySelector(`${flock} .clock`).textContent,
            document.getElementById('flock-order-plot').dataset.xLast], flock);
          if (parseFloat(clock) > 0.3) gap = Math.max(gap, parseFloat(clock) - Number(last));
          await page.waitForTimeout(23);
        }
        assert.ok(gap < 0.03, `the order curves end up to ${gap.toFixed(3)} s before the playhead`);
      }
      for (const name of ['cohesion', 'alignment', 'separation']) {
        const weight = page.locator(`${flock} .lil-gui .lil-gui`, { hasText: 'rule weights' }).locator('.lil-controller', { hasText: name });
        assert.ok(await weight.isVisible(), `${w}x${h}: the ${name} weight is hidden`);
      }
      const fit = await page.evaluate((flock) => {
        const canvas = document.querySelector(`${flock} .stage canvas`).getBoundingClientRect();
        const panel = document.querySelector(`${flock} .panel`).getBoundingClientRect();
        return { canvas: canvas.bottom, panel: panel.bottom, beside: panel.left >= canvas.right - 1 };
      }, flock);
      if (fit.beside) assert.ok(fit.panel <= fit.canvas + 1, `${w}x${h}: panel below the canvas ${JSON.stringify(fit)}`);
      // The first Try this sends the reader into the closed radii folder, by the name it has in
      // the panel. Opening it closes the weights (both open, the panel would run 80 px below the
      // canvas at 1600 x 1000), and the field of view is there; opening the weights closes it.
      const radiiName = 'rule radii (m), field of view';
      assert.ok((await page.locator('.callout', { hasText: radiiName }).count()) > 0, 'no text names the radii folder');
      const folder = (name) => page.locator(`${flock} .lil-gui .lil-gui`, { hasText: name }).first();
      const fov = folder(radiiName).locator('.lil-controller', { hasText: 'field of view' });
      assert.ok(!(await fov.isVisible()), `${w}x${h}: the radii folder starts open`);
      await folder(radiiName).locator('.lil-title').click();
      // lil-gui opens and closes a folder with a transition: each look waits for its end state
      // (up to 5 s), then asserts it.
      const settle = (locator, state) => locator.waitFor({ state, timeout: 5_000 }).catch(() => {});
      await settle(fov, 'visible');
      assert.ok(await fov.isVisible(), `${w}x${h}: the field of view is not in the radii folder`);
      const alignment = folder('rule weights').locator('.lil-controller', { hasText: 'alignment' });
      await settle(alignment, 'hidden');
      assert.ok(!(await alignment.isVisible()), `${w}x${h}: the weights stayed open beside the radii`);
      const fitOpen = await page.evaluate((flock) => {
        const canvas = document.querySelector(`${flock} .stage canvas`).getBoundingClientRect();
        const panel = document.querySelector(`${flock} .panel`).getBoundingClientRect();
        return { canvas: canvas.bottom, panel: panel.bottom, beside: panel.left >= canvas.right - 1 };
      }, flock);
      if (fitOpen.beside) assert.ok(fitOpen.panel <= fitOpen.canvas + 1, `${w}x${h}: radii open, panel below the canvas ${JSON.stringify(fitOpen)}`);
      await folder('rule weights').locator('.lil-title').click();
      await settle(alignment, 'visible');
      await settle(fov, 'hidden');
      assert.ok(await alignment.isVisible() && !(await fov.isVisible()), `${w}x${h}: the folders do not take turns`);
      // The order plot: titled, both series named, and drawn from the flock's samples once it
      // has flown (its canvas shows the purple polarisation line, and the note the value).
      const plot = page.locator('#flock-order-plot');
      assert.equal(await plot.getAttribute('data-plot'), 'Order of the flock');
      const legend = await plot.locator('.u-legend').textContent();
      assert.match(legend, /polarisation φ/);
      assert.match(legend, /mean speed \/ max speed/);
      const purple = await orderLineDrawn(page, /Polarisation φ = \d\.\d\d/);
      assert.ok(purple > 50, `${w}x${h}: the polarisation line is not drawn (${purple} purple pixels)`);
      assert.match(await page.locator('#flock-note').textContent(), /Polarisation φ = \d\.\d\d/);
      assert.deepEqual(problems, []);
      await page.close();
    }
  } finally {
    await context.close();
  }
});

test('lesson 11 on WebGPU: the GPU-stepped particles are drawn as atlas sprites, like the CPU ones', async () => {
  // GPU mode draws smoke puffs like the CPU's, not solid discs: the compute shader writes the
  // renderer's sprite rows (atlas frame by age), drawn with the CPU figure's atlas.
  const context = await launch('webgpu');
  try {
    const { page, problems } = await open(context, '/lessons/11-particles/?backend=webgpu', 800, 600);
    const fig = '#fig-emitters';
    await page.locator(fig).scrollIntoViewIfNeeded();
    // The GPU's sprites are drawn in storage order: compare with the CPU's, unsorted.
    await setControl(page, fig, 'sort back to front', false);
    await scrubTo(page, fig, 300);
    const cpu = await bluePixels(page, fig);
    await page.locator(`${fig} .stage canvas`).first().screenshot({ path: 'tests/screenshots/11-particles-emitters-cpu-webgpu.png' });
    await setControl(page, fig, 'step on', 'GPU');
    await scrubTo(page, fig, 300);
    await frames(page, 4);
    const note = await page.locator('#emitters-note').textContent();
    assert.match(note, /Stepped on the GPU .* play the same atlas/, note);
    // Nothing is read back, so nothing is counted: the note says so, and the plot keeps its
    // guides from 0 to the playhead (the dashed rate × lifetime line: a dense row of dark grey
    // pixels, wider than any tick label; the row's longest such stretch, as a share of the plot).
    assert.match(note, /not read back, so they are not counted: the plot keeps only its guides/, note);
    // The legend still lists the counts: the plot's title says they are not drawn.
    const title = await page.locator('#emitters-plot .u-title').textContent();
    assert.equal(title, 'Live particles: not counted on the GPU, guides only');
    await frames(page, 8);
    const guide = await page.evaluate(() => {
      const c = document.querySelector('#emitters-plot canvas');
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let best = 0;
      for (let y = 0; y < c.height; y++) {
        let [n, first, last] = [0, -1, -1];
        for (let x = 0; x < c.width; x++) {
          const i = 4 * (y * c.width + x);
          if (d[i] < 0x90 && Math.abs(d[i] - d[i + 1]) < 20 && Math.abs(d[i + 1] - d[i + 2]) < 20 && d[i + 3] > 128) {
            n++;
            if (first < 0) first = x;
            last = x;
          }
        }
        if (n > 0.4 * (last - first + 1)) best = Math.max(best, (last - first) / c.width);
      }
      return best;
    });
    await page.locator('#emitters-plot').screenshot({ path: 'tests/screenshots/11-particles-emitters-plot-gpu-webgpu.png' });
    assert.ok(guide > 0.1, `no guide line across the live-particle plot on the GPU (${guide})`);
    const gpu = await bluePixels(page, fig);
    await page.locator(`${fig} .stage canvas`).first().screenshot({ path: 'tests/screenshots/11-particles-emitters-gpu-webgpu.png' });
    // Other particles from the same distributions: about as many blue pixels.
    assert.ok(cpu > 200 && gpu > 0.5 * cpu && gpu < 2 * cpu, `blue pixels: CPU ${cpu}, GPU ${gpu}`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 12 on WebGPU: the order plot goes on while the GPU steps the flock', async () => {
  // The flock stays on the GPU; the page reads its velocities back every 0.1 s of flight and the
  // plot draws their polarisation, so a GPU run is a line, not empty axes.
  const context = await launch('webgpu');
  try {
    const { page, problems } = await open(context, '/lessons/12-boids/?backend=webgpu', 1600, 1000);
    const fig = '#fig-flock';
    await page.locator(fig).scrollIntoViewIfNeeded();
    await setControl(page, fig, 'step on', 'GPU');
    // A new count starts the flock and its plot again, so every sample after it is the GPU's.
    await setControl(page, fig, 'boids', 310);
    // The plot redraws every six frames: after eight it shows the new (GPU) flock's samples
    // only, so the line waited for is the GPU flock's.
    await frames(page, 8);
    const purple = await orderLineDrawn(page, /order plot reads the flock back from the GPU every 0\.1 s/);
    const note = await page.locator('#flock-note').textContent();
    assert.match(note, /order plot reads the flock back from the GPU every 0\.1 s/, note);
    await page.locator(fig).screenshot({ path: 'tests/screenshots/12-boids-flock-gpu-webgpu.png' });
    assert.ok(purple > 50, `the polarisation line is not drawn on the GPU (${purple} purple pixels)`);
    // The GPU grid (the default search) with a flock of its own, in a box that keeps the density.
    await setControl(page, fig, 'step on', 'GPU, 10,000 boids');
    await frames(page, 2);
    const grid = await page.locator('#flock-note').textContent();
    assert.match(grid, /^10000 boids in a box .* uniform grid built on the GPU every step/, grid);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
