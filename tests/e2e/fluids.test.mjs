// Lesson 15 in Chromium: the dragged particle of Figure 2 follows the mouse (the sweep moves its
// sliders; the drag is the canvas's own path), and the note follows it out of the water.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, serveDist, openPage, setControl, pixelStats, meanDifference, bluePixels, fastestDashedSlowestDotted, decadesReadable } from './browser.mjs';

const site = serveDist();

test('lesson 15: the density figure\'s particle is dragged with the mouse; its note lists the exercises not done a line each', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/15-fluids/?backend=webgl2`, { width: 1280, height: 900 });
    // The other figures' timelines pause: their fluids step every frame while they play, and
    // this test waits on frames and mouse moves only.
    await page.evaluate(() => {
      for (const button of document.querySelectorAll('.timeline .play')) {
        if (button.textContent.includes('pause')) button.click();
      }
    });
    const canvas = page.locator('#fig-density .stage canvas');
    await canvas.scrollIntoViewIfNeeded();
    // With "use my exercise" on the stubs, the note reads as a list: the particle's numbers,
    // then a line for each exercise not done (the page keeps the note's line breaks).
    await page.waitForFunction(() => window.__inbetween.exerciseCheck.done, null, { timeout: 30_000 });
    await setControl(page, '#fig-density', 'use my exercise', true);
    await frames(page, 4);
    const lines = (await page.locator('#density-note').innerText()).split('\n');
    assert.equal(lines.length, 4, lines.join(' | '));
    for (const [k, exercise] of ['15.2 sph_density', '15.3 pressure_force', '15.4 pbf_lambda'].entries()) {
      assert.ok(lines[k + 1].startsWith(`Not done yet: exercise ${exercise} (`), lines.join(' | '));
    }
    await page.locator('#fig-density').screenshot({ path: 'tests/screenshots/15-fluids-density-not-done-webgl2.png' });
    const box = await canvas.boundingBox();
    // Find the particle: hovering it marks the canvas (`over-target`); it starts below the middle.
    let grab = null;
    for (let dy = 0; dy < box.height / 2 && !grab; dy += 4) {
      const at = { x: box.x + box.width / 2, y: box.y + box.height / 2 + dy };
      await page.mouse.move(at.x, at.y);
      if (await canvas.evaluate((c) => c.classList.contains('over-target'))) grab = at;
    }
    assert.ok(grab, 'hovering the canvas finds the dragged particle');
    const slider = (name) => page.locator('#fig-density .lil-controller', { hasText: name }).locator('input').last().inputValue();
    const before = [await slider('x (m)'), await slider('y (m)')];
    // Up and out of the water: the sliders follow, and the note says it has no neighbours.
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(grab.x + 6 * k, grab.y - 0.05 * box.height * k);
    await page.mouse.up();
    await frames(page, 4);
    const after = [await slider('x (m)'), await slider('y (m)')];
    assert.ok(Number(after[0]) > Number(before[0]) && Number(after[1]) > Number(before[1]) + 0.2, `${before} -> ${after}`);
    const note = await page.locator('#density-note').textContent();
    assert.match(note, /from 0 neighbours/, note);
    // Its density's sum is its own term alone, plotted from 0 up (not in a range 0.1 wide round it).
    const [lo, hi] = (await page.locator('#density-terms').getAttribute('data-y-range')).split(' ').map(Number);
    assert.ok(lo <= 0 && lo > -0.1 * hi && hi > 150, `${lo} ${hi}`);
    // Out of the water, 15.3's sum of pairs has none to add.
    assert.match(note, /\nExercise 15\.3 pressure_force is not called: the dragged particle has no neighbours\.\n/, note);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

/** Moves the splash's timeline to `at` (in 1/1000 of its duration) and waits for frames. */
async function scrubTo(page, at) {
  const scrub = page.locator('#fig-splash .scrub');
  await scrub.fill(String(at));
  await scrub.dispatchEvent('input');
  await frames(page, 4);
}

test('lesson 15 on WebGPU: step on GPU draws the splash from the GPU, with the slider\'s count or 100,000; the step-time sweep times the GPU grid after the CPU grid and all pairs', async () => {
  const context = await launch('webgpu');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/15-fluids/?backend=webgpu`, { width: 1280, height: 900 });
    const fig = '#fig-splash';
    await page.locator(fig).scrollIntoViewIfNeeded();
    // Paused, so both counts see the fluid at rest; 1,500 particles, so that the GPU's steps
    // (SwiftShader's, on the CPU) catch up with the splash in a few seconds.
    const play = page.locator('#splash-timeline .play');
    if ((await play.textContent()).includes('pause')) await play.click();
    await setControl(page, fig, 'particles', 1500);
    await scrubTo(page, 0);
    const cpu = await bluePixels(page, fig);
    const cpuCount = /(\d+) particles/.exec(await page.locator('#splash-note').textContent())?.[1];
    await setControl(page, fig, 'step on', 'GPU');
    await scrubTo(page, 0);
    await page.waitForTimeout(1000);
    await frames(page, 4);
    const note = await page.locator('#splash-note').textContent();
    assert.match(note, /^PBF on the GPU, \d+ particles, neighbours from the GPU grid/, note);
    // The slider's count: the same lattice as the CPU's fluid.
    assert.equal(/(\d+) particles/.exec(note)?.[1], cpuCount, note);
    // The same fluid at rest drawn from the GPU's sprites: about as many blue pixels.
    const gpu = await bluePixels(page, fig);
    await page.locator(`${fig} .stage canvas`).first().screenshot({ path: 'tests/screenshots/15-fluids-splash-gpu-webgpu.png' });
    assert.ok(cpu > 2000 && gpu > 0.7 * cpu && gpu < 1.4 * cpu, `blue pixels: CPU ${cpu}, GPU ${gpu}`);
    // Figure 5's sweep started with the page: the CPU's 60 timings, then the GPU's 18 (each a few
    // queued steps of up to 8,000 particles). It shares the GPU's queue with the splash, so the
    // splash plays once it is done.
    await page.waitForFunction(() => /The GPU grid \(WebGPU compute/.test(document.getElementById('splash-sweep').textContent), null, { timeout: 300_000 });
    const sweep = await page.locator('#splash-sweep').textContent();
    assert.match(sweep, /takes [\d.]+ ms a step at N = 8000/, sweep);
    await fastestDashedSlowestDotted(page, '#splash-plot', ['CPU grid', 'all pairs', 'GPU grid']);
    await decadesReadable(page, '#splash-plot');
    await page.locator('#fig-timing').screenshot({ path: 'tests/screenshots/15-fluids-timing-gpu-webgpu.png' });
    // The splash: at 0.3 s the drop has hit the pool (it falls 0.28 m, 0.24 s), once the GPU's
    // steps have caught up with the timeline (the note's time): the picture is no longer the
    // fluid at rest.
    await page.locator(fig).scrollIntoViewIfNeeded();
    await pixelStats(page, page.locator(`${fig} .stage canvas`).first(), 'rest');
    await scrubTo(page, 100);
    await page.waitForFunction(() => {
      const t = /t = ([\d.]+) s/.exec(document.getElementById('splash-note').textContent);
      return t && Number(t[1]) >= 0.29;
    }, null, { timeout: 120_000 });
    // The GPU's fastest particle, read back after the steps (the explosion verdict's input).
    assert.match(await page.locator('#splash-note').textContent(), /Fastest particle [\d.]+ m\/s/);
    await frames(page, 4);
    await pixelStats(page, page.locator(`${fig} .stage canvas`).first(), 'splash');
    await page.locator(`${fig} .stage canvas`).first().screenshot({ path: 'tests/screenshots/15-fluids-splash-gpu-0.3s-webgpu.png' });
    const change = await meanDifference(page, 'rest', 'splash');
    assert.ok(change > 3, `the splash differs from the rest by ${change} per channel`);
    // A larger fluid of its own: the note gives its count.
    await setControl(page, fig, 'step on', 'GPU, 100,000 particles');
    await frames(page, 4);
    await page.waitForFunction(() => /on the GPU, \d+ particles/.test(document.getElementById('splash-note').textContent)
      && !/on the GPU, 1\d{3} particles/.test(document.getElementById('splash-note').textContent), null, { timeout: 30_000 });
    const big = await page.locator('#splash-note').textContent();
    const n = Number(/on the GPU, (\d+) particles/.exec(big)?.[1]);
    assert.ok(n > 70_000 && n <= 100_000, big);
    await page.locator(`${fig} .stage canvas`).first().screenshot({ path: 'tests/screenshots/15-fluids-splash-gpu-100k-webgpu.png' });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test('lesson 15 on WebGL2: Figure 1\'s controls beside its plot; the GPU switch is off and the note says why; the step-time legend tells the fastest from the slowest; the dam break\'s timeline waits for its fluids', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/15-fluids/?backend=webgl2`, { width: 1280, height: 900 });
    // The step-time plot: which line is the fastest and which the slowest reads from the legend.
    await fastestDashedSlowestDotted(page, '#splash-plot', ['CPU grid', 'all pairs']);
    // Figure 1's controls sit beside its plot, not over it in a strip with the rest of the row empty.
    const [kernelsPlot, kernelsPanel] = await Promise.all(['#kernels-plot', '#fig-kernels .panel']
      .map((s) => page.locator(s).evaluate((e) => e.getBoundingClientRect().toJSON())));
    assert.ok(kernelsPanel.left >= kernelsPlot.right - 1 && kernelsPanel.top < kernelsPlot.bottom,
      `panel ${JSON.stringify(kernelsPanel)}, plot ${JSON.stringify(kernelsPlot)}`);
    await page.locator('#fig-splash').scrollIntoViewIfNeeded();
    await frames(page, 4);
    const control = page.locator('#fig-splash .lil-controller', { hasText: 'step on' }).first();
    assert.match(await control.getAttribute('class'), /disabled/);
    const note = await page.locator('#splash-note').textContent();
    assert.match(note, /Step on GPU needs WebGPU: this browser draws with WebGL2/, note);
    // The dam break's timeline waits for the fluids: scrubbed to 2 s of 4 and played, it goes
    // back to a quarter of a second ahead of them (they catch up two frames a frame) instead of
    // wrapping at 4 s, which would start the run over before it got there.
    await page.locator('#fig-dam').scrollIntoViewIfNeeded();
    const dam = page.locator('#dam-timeline');
    for (const at of ['0', '500']) {
      // At 0 the run starts over; at 2 s the fluids are far behind the timeline.
      await dam.locator('.scrub').fill(at);
      await dam.locator('.scrub').dispatchEvent('input');
      await frames(page, 2);
    }
    await dam.locator('.play').click();
    await frames(page, 6);
    const clock = Number.parseFloat(await dam.locator('.clock').textContent());
    const damNote = await page.locator('#dam-note').textContent();
    const simulated = Number(/Simulated so far: ([\d.]+) s/.exec(damNote)?.[1]);
    assert.ok(clock <= simulated + 0.26, `the timeline at ${clock} s, the fluids at ${simulated} s`);
    // The splash's timeline waits for its fluid too: 8,000 particles take one step (1/240 s) a
    // frame, and played at 1x the clock would run ahead of them by most of each frame's time.
    await page.locator('#fig-splash').scrollIntoViewIfNeeded();
    await setControl(page, '#fig-splash', 'particles', 8000);
    const splash = page.locator('#splash-timeline');
    await splash.locator('.speed').selectOption('1');
    if (!(await splash.locator('.play').textContent()).includes('pause')) await splash.locator('.play').click();
    await frames(page, 20);
    const [splashClock, splashNote] = await page.evaluate(() => [
      Number.parseFloat(document.querySelector('#splash-timeline .clock').textContent),
      document.getElementById('splash-note').textContent]);
    const water = Number(/t = ([\d.]+) s/.exec(splashNote)?.[1]);
    assert.ok(splashClock > 0 && splashClock <= water + 0.06, `the splash's timeline at ${splashClock} s, its fluid at ${water} s`);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
