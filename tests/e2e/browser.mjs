// Launching Debian's Chromium with the flag sets from ../shared/TOOLCHAIN.md, one per backend.
import { chromium } from 'playwright-core';
import { before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { startServer } from '../../scripts/serve.mjs';

/** The built site the tests serve: dist/, or $INBETWEEN_DIST (scripts/build writes there too). */
export const DIST = process.env.INBETWEEN_DIST ?? 'dist';
/**
 * The test build whose course module carries planted bugs (tests/e2e-variant/): `$DIST-student-bugs`
 * as scripts/test makes it, or $INBETWEEN_VARIANT_DIST.
 */
export const VARIANT_DIST = process.env.INBETWEEN_VARIANT_DIST ?? `${DIST}-student-bugs`;

/**
 * Serves `dist` (`DIST` unless given) on a free port of 127.0.0.1 for the tests of the calling file
 * (registers its node:test `before` and `after` hooks). Returns an object whose `origin` is set once
 * the server listens, e.g. `site.origin + '/lessons/'` inside a test.
 */
export function serveDist(dist = DIST) {
  const site = { origin: '' };
  let server;
  before(async () => {
    if (!existsSync(join(dist, 'pkg'))) throw new Error(`no build in ${dist}/ (scripts/test makes it; see the test file's first lines)`);
    server = await startServer(dist, 0);
    site.origin = `http://127.0.0.1:${server.address().port}`;
  });
  after(() => server?.close());
  return site;
}

/**
 * Opens `url` in a new tab of `context` (at `width` x `height` when given) and waits until the
 * lesson page says it is ready. `problems` collects the page's uncaught errors and console
 * errors, for a test to assert there were none.
 */
export async function openPage(context, url, { width, height, timeout = 90_000 } = {}) {
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  if (width) await page.setViewportSize({ width, height });
  await page.goto(url);
  await page.waitForFunction(() => document.body.dataset.ready, null, { timeout });
  return { page, problems };
}

// 2D canvases are drawn by Skia on the CPU: on SwiftShader an accelerated 2D canvas makes every
// frame wait for the emulated GPU (a lesson page with a dozen plots and 2D figures would take
// about 180 ms a frame instead of 17, and its e2e pass four times as long). The page's own content
// (text, boxes) is rasterized on the CPU too, which costs the tests' two cores less than
// SwiftShader's GL does. The 3D canvases still go through WebGL2 or WebGPU on SwiftShader.
// Scrolls are instant: a smooth scroll (a quiz's "show me" brings its figure into view) would
// have every frame of the page's scroll drawn on SwiftShader while the test waits for it to end.
const BASE = ['--no-sandbox', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-quic', '--disable-dev-shm-usage',
  '--disable-accelerated-2d-canvas', '--disable-gpu-rasterization', '--disable-smooth-scrolling'];

export const PROFILES = {
  // SwiftShader through ANGLE; no WebGPU adapter, so "auto" falls back to WebGL2. The page is
  // composited in software: SwiftShader's GL would draw every composited frame of the page on the
  // CPU anyway, at a higher cost than the software compositor, which takes the WebGL canvases'
  // frames as they are drawn. (A WebGPU canvas needs GPU compositing: its profile keeps it.)
  webgl2: [...BASE, '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-compositing'],
  // WebGPU on SwiftShader's Vulkan (a CPU adapter: not for timings).
  webgpu: [...BASE, '--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-vulkan=swiftshader',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  // Neither API: the page must say so instead of showing a blank canvas.
  none: [...BASE, '--disable-3d-apis', '--disable-webgl', '--disable-gpu'],
};

/** The browsers this test file has started, one per profile (see `launch`). */
const browsers = {};
after(async () => {
  for (const browser of Object.values(browsers)) await (await browser).close();
});

/**
 * A new browser context (its own cookies, storage and pages, as a fresh profile has) in this test
 * file's Chromium with the flags of `profile` (webgl2, webgpu or none). The file's first call for
 * a profile starts that Chromium, which serves every later call and closes when the file's tests
 * are done: a start costs about a second of a core, and most test files open several contexts.
 */
export async function launch(profile) {
  browsers[profile] ??= chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: PROFILES[profile],
  });
  return (await browsers[profile]).newContext({ viewport: { width: 1100, height: 900 } });
}

/**
 * Pixel statistics of an element's screenshot, decoded in the page (no PNG library needed): the
 * fraction of pixels that differ from the top-left (background) colour and the number of distinct
 * colours (quantised). The pixels stay in the page under `key`, for `meanDifference`.
 */
export async function pixelStats(page, locator, key) {
  // JPEG: much faster to encode and decode than PNG for big figures, and deterministic, so an
  // unchanged image still compares equal. The caret is left as it is: hiding it would restyle the
  // whole page for each capture (a canvas has none).
  const png = await locator.screenshot({ type: 'jpeg', quality: 80, caret: 'initial' });
  return page.evaluate(async ([b64, key]) => {
    const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/jpeg' }));
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const ctx = canvas.getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    const { data } = ctx.getImageData(0, 0, bitmap.width, bitmap.height);
    (window.__shots ??= {})[key] = data;
    const bg = [data[0], data[1], data[2]];
    let different = 0;
    const colors = new Set();
    for (let i = 0; i < data.length; i += 4) {
      const d = Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]);
      if (d > 24) different++;
      colors.add(((data[i] >> 3) << 10) | ((data[i + 1] >> 3) << 5) | (data[i + 2] >> 3));
    }
    return { width: bitmap.width, height: bitmap.height, coverage: different / (data.length / 4), colors: colors.size };
  }, [png.toString('base64'), key]);
}

/**
 * How many pixels of `figure`'s 3D canvas are close to the figures' blue (#1f6fd6, shaded): the
 * particles and balls of lessons 11 and 15.
 */
export async function bluePixels(page, figure) {
  // pixelStats decodes the screenshot in the page and keeps its pixels under the key.
  await pixelStats(page, page.locator(`${figure} .stage canvas`).first(), 'blue');
  return page.evaluate(() => {
    const data = window.__shots.blue;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (b > 90 && b > r + 50 && b > g + 25) n++;
    }
    return n;
  });
}

/** Mean absolute difference per channel (0..255) between two screenshots kept by `pixelStats`. */
export function meanDifference(page, keyA, keyB) {
  return page.evaluate(([a, b]) => {
    const [x, y] = [window.__shots[a], window.__shots[b]];
    if (x.length !== y.length) return 255;
    let sum = 0;
    for (let i = 0; i < x.length; i++) sum += Math.abs(x[i] - y[i]);
    return sum / x.length;
  }, [keyA, keyB]);
}

/** Waits for `n` animation frames, so the figures show the latest state. */
export function frames(page, n = 6) {
  return page.evaluate((n) => new Promise((ok) => {
    const step = (k) => (k === 0 ? ok() : requestAnimationFrame(() => step(k - 1)));
    step(n);
  }), n);
}

/** Sets the lil-gui control named `name` in `figure` as a reader would (type, pick or tick). */
export async function setControl(page, figure, name, value) {
  const c = page.locator(`${figure} .lil-controller`, { hasText: name }).first();
  const classes = await c.getAttribute('class');
  if (classes.includes('option')) await c.locator('select').selectOption(String(value));
  else if (classes.includes('boolean')) await c.locator('input').setChecked(Boolean(value));
  else {
    const input = c.locator('input').first();
    await input.fill(String(value));
    await input.press('Enter');
  }
}

/**
 * The legend swatches of the plot in `plot` (a selector), by series name: the length of the first
 * dash of its pattern in CSS px, or null for a solid swatch.
 */
function legendDashes(page, plot) {
  return page.evaluate((plot) => Object.fromEntries([...document.querySelectorAll(`${plot} .u-legend .u-series`)].map((s) => {
    const image = getComputedStyle(s.querySelector('.u-marker')).backgroundImage;
    // "repeating-linear-gradient(90deg, C 0px, C 5px, transparent 5px, transparent 8px)": the dash
    // ends at the second stop.
    const stops = [...image.matchAll(/([\d.]+)px/g)].map((m) => Number(m[1]));
    const dash = image === 'none' ? null : stops[1] ?? -1;
    return [s.querySelector('.u-label').textContent, dash];
  })), plot);
}

/** A timing plot's median solid, its fastest dashed and its slowest dotted, in the legend too. */
export async function fastestDashedSlowestDotted(page, plot, searches) {
  const dashes = await legendDashes(page, plot);
  for (const search of searches) {
    const [median, fastest, slowest] = [`${search} (median)`, `${search} fastest`, `${search} slowest`].map((n) => dashes[n]);
    assert.equal(median, null, `${plot} ${search}: ${JSON.stringify(dashes)}`);
    assert.ok(fastest >= 4 && slowest > 0 && slowest <= 2, `${plot} ${search}: ${JSON.stringify(dashes)}`);
  }
}

/**
 * A log-y plot gives each decade of its y range at least `minPx` CSS pixels of height (uPlot's
 * plotting area, `.u-over`), so that its curves' slopes can be read: four decades squeezed into
 * 110 px draw every line nearly flat.
 */
export async function decadesReadable(page, plot, minPx = 40) {
  const el = page.locator(plot);
  const [lo, hi] = (await el.getAttribute('data-y-range')).split(' ').map(Number);
  const decades = Math.log10(hi / lo);
  const height = await el.locator('.u-over').evaluate((o) => o.getBoundingClientRect().height);
  assert.ok(height / decades >= minPx, `${plot}: ${decades} decades in ${height.toFixed(0)} px`);
}
