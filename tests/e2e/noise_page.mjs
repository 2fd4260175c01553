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
