// Lesson 05's GPU check: the WGSL noise image, read back, must match the CPU's noise at every
// texel within the tolerance stated in src/figures/noise_images.rs (GPU_TOLERANCE = 2e-4), for
// Perlin and for simplex noise, on the backend under test.
import assert from 'node:assert/strict';

async function waitForCheck(page, kind) {
  await page.locator('#fig-gpu').scrollIntoViewIfNeeded();
  await page.waitForFunction((kind) => {
    const text = document.getElementById('gpu-check')?.textContent ?? '';
    return text.includes(`, ${kind})`) && text.includes('largest difference');
  }, kind, { timeout: 90_000 });
  return page.locator('#gpu-check').textContent();
}

export async function gpuNoiseMatchesCpu(page, label) {
  const select = page.locator('#fig-gpu .panel select').first();
  for (const kind of ['Perlin', 'simplex']) {
    await select.selectOption(kind);
    const text = await waitForCheck(page, kind === 'Perlin' ? 'Perlin' : '2D simplex');
    assert.match(text, new RegExp(`GPU check \\(${label}, `), text);
    assert.match(text, /matches the CPU's at all 16384 texels/, `${kind}: ${text}`);
  }
}
