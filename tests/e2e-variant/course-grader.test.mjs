// The "Check my exercises" panel (www/course.js) on the student-bugs build: its table is the one the
// native grader prints for the same answers (tests/grader.rs's `grade_with_student_bugs`), a panic
// and an endless loop are each named in their row while the other exercises are graded, and the
// page's figures keep running. The build: a built dist/ whose course module is rebuilt with
// `INBETWEEN_FEATURES=solutions,student-bugs scripts/build --dev --course-only` (slerp panics,
// rodrigues_matrix is transposed, vertex_normals reverses the middle normal of its list, polar_step
// never returns in the browser, every other exercise is the reference).
//   node --test tests/e2e-variant/   (the copy is $INBETWEEN_DIST-student-bugs, or $INBETWEEN_VARIANT_DIST)
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { launch, serveDist, openPage, VARIANT_DIST } from '../e2e/browser.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const site = serveDist(VARIANT_DIST);

/**
 * What the native grader prints for `lesson` with the page's answers: the table alone, from the
 * test build's switches that stand for the features `solutions` and `student-bugs` (tests/grader.rs,
 * `grade_with_student_bugs`), so the native build the other tests use serves.
 */
function nativeTable(lesson) {
  let out;
  try {
    out = execFileSync('cargo', ['test', '--quiet', '--test', 'grader', '--', '--exact', 'grade_with_student_bugs', '--nocapture'],
    { env: { ...process.env, INBETWEEN_GRADE_LESSON: lesson }, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  } catch (e) {
    out = e.stdout; // the table is printed before the test's checks
  }
  const start = out.indexOf('lesson  ');
  const end = out.search(/ passed, .* of \d+\n/);
  assert.ok(start >= 0 && end > start, `no table in the native grader's output:\n${out}`);
  return out.slice(start, out.indexOf('\n', end) + 1);
}

let native = {};
before(() => {
  // Natively the grader cannot stop an endless loop, so the build's polar_step returns there
  // (src/exercises/grade.rs, with_student_bugs): lesson 04 is compared row by row below instead.
  for (const lesson of ['03', '01', '00']) native[lesson] = nativeTable(lesson);
});

/** Clicks "Check my exercises" and waits for the table; returns its rows and its text. */
async function check(page) {
  await page.locator('.grade-run').click();
  await page.waitForFunction(() => ['done', 'error'].includes(document.querySelector('.grade-panel')?.dataset.state),
    null, { timeout: 120_000 });
  return page.evaluate(() => ({
    state: document.querySelector('.grade-panel').dataset.state,
    status: document.querySelector('.grade-status').textContent,
    table: document.querySelector('.grade-text pre').textContent,
    rows: Object.fromEntries([...document.querySelectorAll('.grade-table tbody tr')]
      .map((tr) => [tr.dataset.exercise, { verdict: tr.dataset.verdict, text: tr.textContent }])),
  }));
}

test('the panel grades like the native grader, survives a panic and stops an endless loop', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/03-rotations/?backend=webgl2`);
    const got = await check(page);
    assert.equal(got.state, 'done', got.status);
    assert.equal(got.table, native['03'], 'the page prints the native grader\'s table');
    assert.equal(got.rows.quat_from_axis_angle.verdict, 'passed');
    assert.equal(got.rows.slerp.verdict, 'panicked');
    assert.match(got.rows.slerp.text, /index out of bounds.*src\/exercises\/run\.rs:\d+:\d+/s);
    assert.equal(got.rows.rodrigues_matrix.verdict, 'wrong');
    assert.match(got.rows.rodrigues_matrix.text, /expected.*yours/s);
    assert.match(got.status, /slerp panicked at case 1/);
    // The count names the panic as a panic, not as a wrong answer.
    assert.match(got.status, /^1 passed, 0 not yet implemented, 1 wrong, 1 panicked, of 3\./);
    // The figures still run in the page's own instance: a control still redraws, nothing died.
    assert.equal(await page.evaluate(() => window.__inbetween.dead), false);
    await page.locator('.grade-panel').screenshot({ path: `${SHOTS}/course-grader-03-student-bugs.png` });
    assert.deepEqual(problems.filter((p) => !/slerp panicked|index out of bounds/.test(p)), []);

    // Lesson 04: polar_step never returns in this build; the panel stops it after the time limit.
    const second = await openPage(context, `${site.origin}/lessons/04-rigid-motions/?backend=webgl2`);
    const started = Date.now();
    const loop = await check(second.page);
    assert.equal(loop.state, 'done', loop.status);
    assert.equal(loop.rows.dual_quat_apply.verdict, 'passed');
    assert.equal(loop.rows.polar_step.verdict, 'stopped');
    assert.match(loop.rows.polar_step.text, /no answer within 5 s/);
    assert.match(loop.status, /polar_step gave no answer within 5 s at case 1 and was stopped/);
    assert.match(loop.status, /^1 passed, 0 not yet implemented, 0 wrong, 1 stopped, of 2\./);
    assert.match(loop.table, /polar_step +STOPPED at case 1 \(.*\): no answer within 5 s/);
    assert.ok(Date.now() - started >= 5000, 'the time limit ran out before the verdict');
    assert.equal(await second.page.evaluate(() => window.__inbetween.dead), false);
    await second.page.locator('.grade-panel').screenshot({ path: `${SHOTS}/course-grader-04-endless-loop.png` });
    // Figure 2 runs polar_step: in this build it never returns in the page either, so the page
    // must not call it on its own thread. The grading done when the page opened stopped it; the
    // figure says so, uses the reference, and the page keeps responding (a hang would time out).
    await second.page.waitForFunction(() => window.__inbetween.exerciseCheck.done, null, { timeout: 60_000 });
    const affine = second.page.locator('#fig-affine');
    await affine.locator('.lil-controller', { hasText: 'use my exercise' }).locator('input[type="checkbox"]').check();
    const stoppedNote = await affine.locator('.exercise-note').textContent({ timeout: 10_000 });
    assert.match(stoppedNote, /polar_step: it gave no answer within 5 s at the grader's case 1 \(.*\), so the page does not run it/, stoppedNote);
    assert.match(stoppedNote, /uses the reference/, stoppedNote);
    assert.equal(await second.page.evaluate(() => 1 + 1), 2, 'the page still answers');
    await affine.screenshot({ path: `${SHOTS}/course-grader-04-figure-endless-loop.png` });

    // Lesson 01: every exercise is the reference's; the same table as natively.
    const third = await openPage(context, `${site.origin}/lessons/01-transforms/?backend=webgl2`);
    const solved = await check(third.page);
    assert.equal(solved.table, native['01']);
    assert.ok(Object.values(solved.rows).every((r) => r.verdict === 'passed'), solved.table);
    // The verdicts are remembered: the gallery counts lesson 01's as passed.
    await third.page.goto(`${site.origin}/lessons/`);
    await third.page.waitForFunction(() => document.body.dataset.ready);
    const card = third.page.locator('.card[data-lesson="01-transforms"] .progress');
    assert.match(await card.textContent(), /exercises 2 of 2 passed/);

    // Lesson 00: a wrong list answer names its first wrong element, in its row as in the table.
    const fourth = await openPage(context, `${site.origin}/lessons/00-triangles-to-pixels/?backend=webgl2`);
    const list = await check(fourth.page);
    assert.equal(list.table, native['00']);
    assert.equal(list.rows.vertex_normals.verdict, 'wrong');
    const wrong = /wrong\s*index 2 first, 1 of 4 elements in all: expected Vec3\(.*\), actual Vec3\(.*\)/;
    assert.match(list.rows.vertex_normals.text, wrong);
    assert.match(list.table, /\n {6}wrong: {4}index 2 first, 1 of 4 elements in all/);
    await fourth.page.locator('.grade-panel').screenshot({ path: `${SHOTS}/course-grader-00-list.png` });
  } finally {
    await context.close();
  }
});
