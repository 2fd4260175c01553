// Student code cannot take the page down, and the page checks the student's answer.
// Runs on a special build (scripts/test makes it: a copy of a built dist/ whose course module is
// rebuilt with `INBETWEEN_FEATURES=solutions,student-bugs scripts/build --dev --course-only`), in
// which exercise 3.2 slerp panics (an index out of bounds), 3.3 rodrigues_matrix returns the
// transpose of the right matrix, 0.2 vertex_normals reverses the middle normal of its list, and
// every other exercise is right.
//   node --test tests/e2e-variant/   (the copy is $INBETWEEN_DIST-student-bugs, or $INBETWEEN_VARIANT_DIST)
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { launch, pixelStats, meanDifference, frames, serveDist, openPage, VARIANT_DIST } from '../e2e/browser.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const site = serveDist(VARIANT_DIST);

/** Ticks the figure's "use my exercise" box. */
async function useMyExercise(figure) {
  // The page grades the exercises in a worker first (an endless loop must not reach the page).
  await figure.page().waitForFunction(() => window.__inbetween.exerciseCheck.done, null, { timeout: 60_000 });
  await figure.locator('.lil-controller', { hasText: 'use my exercise' }).locator('input[type="checkbox"]').check();
}

/** Moves the figure's first slider and returns how much its canvas changed. */
async function sliderChangesCanvas(page, figure, key) {
  const canvas = figure.locator('.stage canvas');
  await pixelStats(page, canvas, `${key}-before`);
  const slider = figure.locator('.lil-slider').first();
  await slider.scrollIntoViewIfNeeded();
  const box = await slider.boundingBox();
  await page.mouse.click(box.x + box.width * 0.15, box.y + box.height / 2);
  await frames(page);
  await pixelStats(page, canvas, `${key}-after`);
  return meanDifference(page, `${key}-before`, `${key}-after`);
}

for (const backend of ['webgl2', 'webgpu']) {
  test(`a panicking exercise stays in its figure, on ${backend}`, async () => {
    const context = await launch(backend);
    try {
      const { page, problems } = await openPage(context, `${site.origin}/lessons/03-rotations/?backend=${backend}`);
      assert.match(await page.evaluate(() => document.getElementById('build-info').textContent), /solutions/);
      for (const button of await page.locator('.timeline .play').all()) {
        if ((await button.textContent()).includes('pause')) await button.click();
      }

      // Slerp panics: its figure says so, with the message, and keeps drawing the reference.
      const interp = page.locator('#fig-interp');
      await useMyExercise(interp);
      await frames(page);
      const note = await interp.locator('.exercise-note').textContent();
      assert.match(note, /slerp panicked at src\//, note);
      // Each verdict in its own colour (the exercise-note rule has the same specificity, so placed
      // after the verdicts it would paint all three beige): red for a panic or a difference, green
      // for a match.
      const background = (locator) => locator.evaluate((e) => getComputedStyle(e).backgroundColor);
      assert.equal(await background(interp.locator('.exercise-note')), 'rgb(253, 232, 232)', 'a panic is red');
      assert.match(note, /index out of bounds/, note);
      assert.match(note, /reference/, note);
      assert.ok(await page.evaluate(() => Boolean(window.__inbetween.panickedExercises.slerp)));
      assert.ok(await sliderChangesCanvas(page, interp, 'interp') > 0.2, 'the panicking figure still responds');

      // Every other figure keeps running.
      assert.ok(await sliderChangesCanvas(page, page.locator('#fig-gimbal'), 'gimbal') > 0.2, 'the gimbal still responds');
      const rodrigues = page.locator('#fig-rodrigues');
      assert.ok(await sliderChangesCanvas(page, rodrigues, 'rod') > 0.2, 'the Rodrigues figure still responds');

      // A wrong answer (a transposed matrix) is reported as differing, with both values.
      await useMyExercise(rodrigues);
      await frames(page);
      const rodNote = await rodrigues.locator('.exercise-note').textContent();
      assert.match(rodNote, /differs/, rodNote);
      assert.equal(await background(rodrigues.locator('.exercise-note')), 'rgb(253, 232, 232)', 'a difference is red');
      assert.match(rodNote, /yours \(.*\), reference \(/, rodNote);
      // As tests/e2e/lessons.mjs's fullPageShot: Playwright's fullPage capture clears the
      // canvases behind our back, and a figure off screen keeps its last drawn frame (while its
      // labels, HTML over the canvas, follow the scene): the viewport is made as tall as the
      // page, so every figure is on screen and draws its current frame before the capture.
      const viewport = page.viewportSize();
      const height = await page.evaluate(() => document.documentElement.scrollHeight);
      await page.setViewportSize({ width: viewport.width, height: Math.min(height, 8000) });
      await page.evaluate(() => window.__inbetween.figures.forEach((f) => f.viewer?.setVisible(true)));
      await frames(page, 4);
      await page.screenshot({ path: `${SHOTS}/student-bugs-03-${backend}.png` });
      await page.setViewportSize(viewport);

      assert.deepEqual(await page.evaluate(() => window.__inbetween.errors), [], 'nothing reached the error banner');
      assert.deepEqual(problems, []);

      // A right answer is reported as matching (lesson 04's exercises are right in this build).
      const { page: page4 } = await openPage(context, `${site.origin}/lessons/04-rigid-motions/?backend=${backend}`);
      const first = page4.locator('.figure').first();
      await useMyExercise(first);
      await frames(page4);
      const note4 = await first.locator('.exercise-note').textContent();
      assert.match(note4, /matches the reference/, note4);
      assert.equal(await background(first.locator('.exercise-note')), 'rgb(233, 247, 238)', 'a match is green');
    } finally {
      await context.close();
    }
  });
}
