// Lesson 09 in Chromium: the heat legends (shown while a joint is painted, naming it, in the
// meshes' colours), the character's falloff slider range, what the area plot's dashed line
// follows (the note says), and the glTF figure's notes: its CPU and frame times, and after a
// rejected file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { launch, pixelStats, meanDifference, frames, setControl, serveDist, openPage, DIST } from './browser.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const SAMPLES = existsSync(join(DIST, 'assets/gltf/index.json'));
const site = serveDist();

test('lesson 09: heat legends, falloff range, plot cursor note, rejected glTF note', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/09-skinning/?backend=webgl2`);
    await page.evaluate(() => {
      for (const b of document.querySelectorAll('.timeline .play')) if (b.textContent.includes('pause')) b.click();
    });

    // Figure 1: the legend names the joint; the note says what the dashed lines mark.
    const cyl = '#fig-cylinder';
    const cylNote = () => page.locator('#cyl-note').textContent();
    assert.match(await cylNote(), /dashed lines mark this bend/);
    await setControl(page, cyl, 'twist', 45);
    await frames(page);
    assert.match(await cylNote(), /on none of the plots' curves/);
    await setControl(page, cyl, 'bend', 0);
    await frames(page);
    assert.match(await cylNote(), /area plot's dashed line marks this twist/);
    await setControl(page, cyl, 'weights of', 'elbow');
    await frames(page);
    assert.equal((await page.locator(`${cyl} .heat-legend`).textContent()).replace(/\s+/g, ' ').trim(), 'weight of the elbow: 0 1');

    // Figure 2: no legend until a joint is painted; then one naming it, with the meshes' ramp.
    const human = '#fig-human';
    const legend = page.locator(`${human} .heat-legend`);
    await page.locator(human).scrollIntoViewIfNeeded();
    assert.equal(await legend.isVisible(), false, 'no legend without a heat map');
    await setControl(page, human, 'weights of', 'forearm.L');
    await frames(page, 8);
    assert.equal(await legend.isVisible(), true, 'the legend shows with the heat map');
    assert.match(await legend.textContent(), /weight of forearm\.L: 0\s*1/);
    const ramp = await legend.locator('.ramp').evaluate((e) => e.style.background);
    assert.match(ramp, /linear-gradient/, ramp);
    const bar = await legend.locator('.ramp').boundingBox();
    assert.ok(bar.width > 80 && bar.height > 6, `a visible bar: ${JSON.stringify(bar)}`);
    // The falloff slider spans 0.005 to 0.06 m, and its two ends paint visibly different maps.
    const falloff = page.locator(`${human} .lil-controller`, { hasText: 'falloff' });
    const canvas = page.locator(`${human} .stage canvas`);
    await setControl(page, human, 'falloff', 0.005);
    await frames(page, 8);
    await pixelStats(page, canvas, 'narrow');
    await setControl(page, human, 'falloff', 1);
    await frames(page, 8);
    assert.equal(await falloff.locator('input').first().inputValue(), '0.06', 'clamped to the range');
    assert.match(await page.locator('#human-note').textContent(), /at falloff 0\.060 m/);
    await pixelStats(page, canvas, 'wide');
    const change = await meanDifference(page, 'narrow', 'wide');
    assert.ok(change > 0.05, `the heat map changes across the slider (${change})`);
    await page.locator(human).screenshot({ path: `${SHOTS}/09-skinning-human-legend-webgl2.png` });

    // Figure 3: a bad file after a good one. The note says it was rejected, why, and what is
    // still shown.
    const gltfNote = () => page.locator('#fig-gltf .note').textContent();
    await page.locator('#fig-gltf').scrollIntoViewIfNeeded();
    if (SAMPLES) {
      await page.waitForFunction(() => document.querySelector('#fig-gltf .note').textContent.startsWith('RiggedFigure.gltf: '));
    }
    if (SAMPLES) {
      // The CPU time and the frame time are means over the same frames, each frame's work
      // against the time to the next frame, which holds it: never the larger.
      const timed = /take ([\d.]+) ms on the CPU, of the ([\d.]+) ms from its start to the next frame's \(means of the last (\d+) frames\)/;
      await page.waitForFunction((re) => new RegExp(re).test(document.querySelector('#fig-gltf .note').textContent), timed.source);
      for (let i = 0; i < 8; i++) {
        const [, cpu, frame, n] = (await gltfNote()).match(timed);
        assert.ok(Number(cpu) <= Number(frame) && Number(n) >= 10, `${cpu} ms of CPU in a ${frame} ms frame (${n} frames)`);
        await frames(page, 3);
      }
    }
    await page.evaluate(() => {
      const data = new DataTransfer();
      data.items.add(new File(['{"asset": {"version": "2.0"}, "nodes": [ oops'], 'broken.gltf'));
      document.querySelector('#fig-gltf .stage').dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    });
    await page.waitForFunction(() => /^Could not load broken\.gltf: not a valid glTF/.test(document.querySelector('#fig-gltf .note').textContent));
    const note = await gltfNote();
    if (SAMPLES) {
      assert.ok(note.includes('The file was rejected: the figure still shows RiggedFigure.gltf, loaded before.'), note);
      assert.ok(!note.includes('RiggedFigure.gltf: '), `the old summary no longer reads as the file's: ${note}`);
    } else {
      assert.ok(note.includes('No character loaded'), note);
    }
    await page.locator('#fig-gltf').screenshot({ path: `${SHOTS}/09-skinning-gltf-rejected-webgl2.png` });

    assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
