// Lesson 15 in Chromium: the dragged particle of Figure 2 follows the mouse (the sweep moves its
// sliders; the drag is the canvas's own path), and the note follows it out of the water.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { launch, frames, serveDist, openPage } from './browser.mjs';

const site = serveDist();

test('lesson 15: the density figure\'s particle is dragged with the mouse', async () => {
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
    await frames(page, 4);
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
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
