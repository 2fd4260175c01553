// Lesson 13 in Chromium: the drape's timing line stops when its cloth explodes (a frozen cloth
// is not simulated, so its frames would time the drawing alone and the average would sink
// towards zero while still naming the cloth), and its stretch plot follows the run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, serveDist, openPage, setControl } from './browser.mjs';

const site = serveDist();

test('lesson 13: the drape stops timing an exploded cloth', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/13-cloth/?backend=webgl2`, { width: 1600, height: 1000 });
    const drape = '#fig-drape';
    await page.locator(drape).scrollIntoViewIfNeeded();
    // 40 x 40 mass-spring: past its stable substep, it explodes within half a second.
    await setControl(page, drape, 'particles per side', 40);
    await page.waitForFunction(() => /timing stopped/.test(document.querySelector('#drape-timing').textContent), null, { timeout: 60_000 });
    const stopped = await page.locator('#drape-timing').textContent();
    assert.match(stopped, /The timing stopped at t = \d\.\d\d s, when the 40 × 40 mass-spring cloth exploded/, stopped);
    await frames(page, 30);
    assert.equal(await page.locator('#drape-timing').textContent(), stopped, 'the line stays as it was');
    // XPBD at the same resolution holds, and is timed again.
    await setControl(page, drape, 'method', 'XPBD');
    await page.locator(`${drape} .lil-controller`, { hasText: 'reset' }).locator('button').click();
    await page.waitForFunction(() => /Measured here: [\d.]+ ms per simulated frame \(40 × 40, XPBD/.test(document.querySelector('#drape-timing').textContent), null, { timeout: 60_000 });
    // A run's first frames (the browser still compiling, at the page's start twice as slow) are
    // not in the average, and the note says so.
    assert.match(await page.locator('#drape-timing').textContent(), /the run's first 10 frames, the warm-up, left out\)\.$/);
    // The plot under the notes follows the largest stretch of the XPBD run over time.
    const range = (await page.locator('#drape-stretch').getAttribute('data-y-range')).split(' ').map(Number);
    assert.ok(range.length === 2 && range.every(Number.isFinite) && range[1] - range[0] >= 1, `drape stretch axis ${range}`);
    // The 40 x 40 mass-spring cloth before it exploded within its first second: too short a run
    // to see beside this one, so the legend names no previous run.
    const legend = await page.evaluate(() => [...document.querySelectorAll('#drape-stretch .u-legend .u-series')]
      .filter((row) => row.style.display !== 'none').map((row) => row.textContent.trim()));
    assert.ok(!legend.some((name) => /previous/.test(name)), `${legend}`);
    await page.locator(drape).screenshot({ path: 'tests/screenshots/13-cloth-drape-xpbd-40-webgl2.png' });
    // Pause the 40 x 40 drape: on a slow (debug or busy) machine its simulation takes most of
    // each frame, and the flag's screenshot below would wait for a stable element.
    await page.locator(`${drape} .timeline .play`).click();
    // The flags pushed past the limit: the mass-spring flag explodes, and the plots' scales
    // follow the XPBD flag (its stretch stays under 15 %; the mass-spring flag's last samples
    // before it explodes pass 70 % and would squash the XPBD curve onto a line).
    const flag = '#fig-flag';
    await page.locator(flag).scrollIntoViewIfNeeded();
    await page.locator(`${flag} .lil-controller`, { hasText: 'push past the stability limit' }).locator('button').click();
    await page.waitForFunction(() => /The plots' scales follow the XPBD cloth that held/.test(document.querySelector('#flag-note').textContent), null, { timeout: 60_000 });
    await frames(page, 10);
    const [lo, hi] = (await page.locator('#flag-stretch').getAttribute('data-y-range')).split(' ').map(Number);
    assert.ok(hi < 25 && lo > -2, `stretch axis ${lo}..${hi} %`);
    await page.locator(flag).screenshot({ path: 'tests/screenshots/13-cloth-flag-exploded-webgl2.png' });
    assert.deepEqual(problems, []);
    await page.close();
  } finally {
    await context.close();
  }
});

test('lesson 13: the flag takes no structural stiffness below 50 N/m, and its Try this comes in four short parts', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/13-cloth/?backend=webgl2`, { width: 1600, height: 1000 });
    const flag = '#fig-flag';
    await page.locator(flag).scrollIntoViewIfNeeded();
    // A typed -1 (or 0) lands on the slider's end, 50 N/m, which the figure accepts.
    await setControl(page, flag, 'structural', -1);
    await frames(page, 5);
    const input = page.locator(`${flag} .lil-controller`, { hasText: 'structural' }).first().locator('input').first();
    assert.equal(Number(await input.inputValue()), 50);
    const note = await page.locator('#flag-note').textContent();
    assert.doesNotMatch(note, /stiffness/i, note);
    assert.match(note, /the step is stable/, note);
    // The callouts between Figure 2 and the next section: four, none taller than 13 lines.
    const heights = await page.evaluate(() => {
      const out = [];
      for (let e = document.querySelector('#fig-flag').nextElementSibling; e && e.tagName !== 'H2'; e = e.nextElementSibling) {
        if (!e.classList.contains('callout')) continue;
        const p = e.querySelector('p');
        out.push(e.getBoundingClientRect().height / parseFloat(getComputedStyle(p).lineHeight));
      }
      return out;
    });
    assert.equal(heights.length, 4, `${heights}`);
    for (const lines of heights) assert.ok(lines < 13, `a callout ${lines.toFixed(1)} lines tall`);
    assert.deepEqual(problems, []);
    await page.close();
  } finally {
    await context.close();
  }
});

test('lesson 13: the drape plot redraws on a new sample, on a change replayed to the same time, and after a reset', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/13-cloth/?backend=webgl2`, { width: 1600, height: 1000 });
    const drape = '#fig-drape';
    await page.locator(drape).scrollIntoViewIfNeeded();
    const range = () => page.locator('#drape-stretch').getAttribute('data-y-range');
    // Played for a while, then paused: the plot stands still.
    await frames(page, 40);
    await page.locator(`${drape} .timeline .play`).click();
    await frames(page, 5);
    const paused = await range();
    await frames(page, 10);
    assert.equal(await range(), paused, 'paused, the plot stays');
    // A new setting replays the run to the same time: as many samples, other values (a hung
    // cloth stretches more than a falling one).
    await setControl(page, drape, 'pins', 'whole edge');
    await frames(page, 10);
    const pinned = await range();
    assert.notEqual(pinned, paused, 'the replayed run is plotted');
    // Reset: back to the first sample alone.
    await page.locator(`${drape} .lil-controller`, { hasText: 'reset' }).locator('button').click();
    await frames(page, 10);
    const reset = await range();
    assert.notEqual(reset, pinned, 'the reset run is plotted');
    // Playing on adds samples, and the plot follows them.
    await page.locator(`${drape} .timeline .play`).click();
    await page.waitForFunction((r) => document.querySelector('#drape-stretch').dataset.yRange !== r, reset, { timeout: 30_000 });
    assert.deepEqual(problems, []);
    await page.close();
  } finally {
    await context.close();
  }
});

test('lesson 13: the drape plot keeps the previous cloth dashed beside the current one, and its Try this comes in four short parts', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/13-cloth/?backend=webgl2`, { width: 1600, height: 1000 });
    const drape = '#fig-drape';
    await page.locator(drape).scrollIntoViewIfNeeded();
    const legend = () => page.evaluate(() => [...document.querySelectorAll('#drape-stretch .u-legend .u-series')]
      .filter((row) => row.style.display !== 'none').map((row) => row.textContent.trim()));
    // A run shorter than 1 s is not kept as the previous one (it would be a stub under the next
    // run's start): each run plays past 1 s, and past the run before it, before the next change.
    const xLast = async () => Number(await page.locator('#drape-stretch').getAttribute('data-x-last'));
    const ranPast = (t) => page.waitForFunction((t) => Number(document.getElementById('drape-stretch').dataset.xLast) > t, t, { timeout: 60_000 });
    // The first cloth: no previous run to show.
    await frames(page, 30);
    assert.ok(!(await legend()).some((name) => /previous/.test(name)), `${await legend()}`);
    await ranPast(1.05);
    const before = await xLast();
    // Another method: the 20 x 20 mass-spring run stays, named, beside the XPBD one.
    await setControl(page, drape, 'method', 'XPBD');
    await frames(page, 10);
    assert.ok((await legend()).includes('previous: 20 × 20 mass-spring'), `${await legend()}`);
    await ranPast(before + 0.1);
    // Another resolution: the previous is now the XPBD cloth.
    await setControl(page, drape, 'particles per side', 10);
    await frames(page, 10);
    assert.ok((await legend()).includes('previous: 20 × 20 XPBD'), `${await legend()}`);
    // The callouts between Figure 3 and the next section: four, none taller than 10 lines.
    const heights = await page.evaluate(() => {
      const out = [];
      for (let e = document.querySelector('#fig-drape').nextElementSibling; e && e.tagName !== 'H2'; e = e.nextElementSibling) {
        if (!e.classList.contains('callout')) continue;
        const p = e.querySelector('p');
        out.push(e.getBoundingClientRect().height / parseFloat(getComputedStyle(p).lineHeight));
      }
      return out;
    });
    assert.equal(heights.length, 4, `${heights}`);
    for (const lines of heights) assert.ok(lines < 10, `a callout ${lines.toFixed(1)} lines tall`);
    await page.locator(drape).screenshot({ path: 'tests/screenshots/13-cloth-drape-previous-webgl2.png' });
    assert.deepEqual(problems, []);
    await page.close();
  } finally {
    await context.close();
  }
});
