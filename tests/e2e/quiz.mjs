// The quiz at the end of a lesson page, checked on the page the lesson sweep (lessons.mjs) has
// already loaded on WebGL2: every question renders, and each "show me" button finds every control
// it sets (course.js warns "no control named …" otherwise) and sets it without an error.
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

/** The quiz of the lesson in `lessons/<folder>/quiz.json`; every lesson has one. */
export function lessonQuiz(folder) {
  const path = join('lessons', folder, 'quiz.json');
  assert.ok(existsSync(path), `${folder}: every lesson has a quiz (${path})`);
  return JSON.parse(readFileSync(path, 'utf8'));
}

/**
 * Checks the quiz of `folder` on `page` (a lesson page that is ready): its questions render, and
 * each "show me" sets the numbers it names in its figure's panel, with no warning and no error.
 * Collects the page's console warnings from now on, so it must run before anything else warns.
 */
export async function quizShowMeSetsFigures(page, folder) {
  const quiz = lessonQuiz(folder);
  const warnings = [];
  const onConsole = (m) => { if (m.type() === 'warning') warnings.push(m.text()); };
  page.on('console', onConsole);
  try {
    await page.waitForFunction(() => document.body.dataset.course === 'ready');
    assert.equal(await page.locator('.quiz .quiz-question').count(), quiz.questions.length, `${folder}: quiz questions`);
    for (const q of quiz.questions.filter((x) => x.show)) {
      await page.locator(`#quiz-${q.id} .show-me`).click();
      // Two frames: the controls' handlers have run and the figure has redrawn.
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      // Each number it sets shows in the figure's panel: in a number input, or for a dropdown in
      // its display (a list of numbers) or its selected index (a map of names to 0, 1, 2 …).
      const inputs = await page.locator(`#${q.show.figure} .lil-controller`).evaluateAll((els) => els.flatMap((e) => [
        ...[...e.querySelectorAll('input')].map((i) => i.value),
        ...[...e.querySelectorAll('select')].map((i) => String(i.selectedIndex)),
        ...[...e.querySelectorAll('.lil-display')].map((d) => d.textContent.trim()),
      ]));
      for (const [key, value] of Object.entries(q.show.set)) {
        if (typeof value !== 'number') continue;
        assert.ok(inputs.some((v) => v !== '' && Math.abs(Number(v) - value) < 1e-6), `${folder} ${q.id}: ${key} = ${value} not shown (${inputs.join(' ')})`);
      }
    }
    assert.deepEqual(warnings.filter((w) => /no control named/.test(w)), [], folder);
  } finally {
    page.off('console', onConsole);
  }
}
