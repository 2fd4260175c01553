// Lesson 06's glTF figure in Chromium: the sample characters load and play, a file chosen with the
// picker or dropped on the figure loads, and a broken file gets a readable message while the page
// keeps working.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { launch, pixelStats, meanDifference, serveDist, openPage, DIST } from './browser.mjs';

const SAMPLES = existsSync(join(DIST, 'assets/gltf/index.json'));
const site = serveDist();

const noteText = (page) => page.locator('#gltf-note').textContent();

test('glTF characters load, play, and bad files say why', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/06-skeletons/?backend=webgl2`);
    const canvas = page.locator('#fig-gltf .stage canvas');
    await canvas.scrollIntoViewIfNeeded();
    if (SAMPLES) {
      await page.waitForFunction(() => /RiggedFigure\.gltf: 19 joints/.test(document.querySelector('#gltf-note').textContent));
      // It plays: a later moment of the walk differs from the first. A loaded machine may draw
      // only a frame or two in 400 ms, so the test looks again (for up to 10 s) before failing.
      await pixelStats(page, canvas, 'a');
      let difference = 0;
      for (let look = 0; look < 25 && difference <= 0.1; look++) {
        await page.waitForTimeout(400);
        await pixelStats(page, canvas, 'b');
        difference = await meanDifference(page, 'a', 'b');
      }
      assert.ok(difference > 0.1, `the walk moves (mean difference ${difference})`);
      // The picker, with another sample's bytes.
      const bytes = readFileSync(join(DIST, 'assets/gltf/CesiumMan.gltf'));
      await page.setInputFiles('#gltf-file', { name: 'CesiumMan.gltf', mimeType: 'model/gltf+json', buffer: bytes });
      await page.waitForFunction(() => /CesiumMan\.gltf: 19 joints/.test(document.querySelector('#gltf-note').textContent));
    } else {
      assert.match(await noteText(page), /not on this server/);
    }
    // A broken file, dropped on the figure: a message, no page error, the page keeps running.
    await page.evaluate(() => {
      const data = new DataTransfer();
      data.items.add(new File(['{"asset": {"version": "2.0"}, "nodes": [ oops'], 'broken.gltf'));
      document.querySelector('#fig-gltf .stage').dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    });
    await page.waitForFunction(() => /Could not load broken\.gltf: not a valid glTF/.test(document.querySelector('#gltf-note').textContent));
    // A valid glTF without a skin: says so.
    await page.setInputFiles('#gltf-file', { name: 'box.gltf', mimeType: 'model/gltf+json', buffer: Buffer.from('{"asset":{"version":"2.0"},"nodes":[{}],"scenes":[{"nodes":[0]}]}') });
    await page.waitForFunction(() => /box\.gltf: the file has no skin/.test(document.querySelector('#gltf-note').textContent));
    await page.locator('#fig-gltf').screenshot({ path: 'tests/screenshots/06-skeletons-gltf-webgl2.png' });
    assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
