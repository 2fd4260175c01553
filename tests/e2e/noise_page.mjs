// Lesson 05's Figure 5: each colour has one meaning. Its 3D view draws the exact normals grey and
// the face-averaged ones orange (src/figures/noise.rs, `Normals::draw`, and the caption), so the
// plot of the angle between them uses neither colour for its curves.
import assert from 'node:assert/strict';

export async function normalsPlotKeepsTheArrowsColours(page) {
  const { swatches, arrows } = await page.evaluate(() => {
    const rgb = (css) => {
      const probe = document.createElement('span');
      probe.style.color = css;
      document.body.append(probe);
      const out = getComputedStyle(probe).color;
      probe.remove();
      return out;
    };
    const root = getComputedStyle(document.documentElement);
    return {
      swatches: [...document.querySelectorAll('#nor-plot .u-legend .u-marker')].map((m) => m.style.background),
      arrows: ['--grey', '--orange'].map((v) => rgb(root.getPropertyValue(v).trim())),
    };
  });
  assert.equal(swatches.length, 2, 'the plot has its two curves');
  for (const swatch of swatches) {
    for (const arrow of arrows) assert.ok(!swatch.includes(arrow), `a plot curve is drawn in an arrow's colour ${arrow}: ${swatch}`);
  }
}

/** At h = 0 every angle is 0: the plot's y axis starts at 0 (an angle is never negative). */
export async function normalsPlotStartsAtZero(page) {
  const box = page.locator('#fig-normals .lil-controller', { hasText: 'h (height)' }).locator('input').first();
  await box.fill('0');
  await box.press('Enter');
  await page.waitForFunction(() => document.getElementById('nor-plot').dataset.yRange?.startsWith('0 '), null, { timeout: 10_000 })
    .catch(() => {});
  const range = (await page.locator('#nor-plot').getAttribute('data-y-range')).split(' ').map(Number);
  assert.equal(range[0], 0, `the angle axis runs from ${range[0]}`);
  await box.fill('0.3');
  await box.press('Enter');
}
