// The course around the lessons (www/course.js, www/progress.js, www/gallery.js), on the build
// scripts/test makes (the exercises are stubs): navigation and the outline at both sizes, deep
// links, the "Check my exercises" panel on stubs, the quiz (a right and a wrong answer, numbers
// from the core), progress that survives a reload and shows in the gallery, a corrupt entry that
// is ignored with a note, and the reset. One browser, WebGL2, five page loads. The quizzes' data
// is checked without a browser: every numeric answer computes in the module (Node). Every quiz's
// questions and "show me" buttons are checked on each lesson page by the lesson sweep
// (lessons.mjs, through quiz.mjs), on the page it has loaded anyway.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readdirSync, readFileSync, existsSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launch, serveDist, openPage, DIST } from './browser.mjs';

const SHOTS = 'tests/screenshots';
mkdirSync(SHOTS, { recursive: true });
const site = serveDist();

const quizzes = readdirSync('lessons')
  .filter((f) => existsSync(join('lessons', f, 'quiz.json')))
  .map((folder) => ({ folder, quiz: JSON.parse(readFileSync(join('lessons', folder, 'quiz.json'), 'utf8')) }));

test('every quiz question has what the page needs, and every numeric answer comes from a core', async () => {
  const { initSync, quizAnswer } = await import(pathToFileURL(resolve(DIST, 'pkg', 'course.js')).href);
  initSync({ module: readFileSync(join(DIST, 'pkg', 'course_bg.wasm')) });
  assert.ok(quizzes.length > 0);
  for (const { folder, quiz } of quizzes) {
    assert.ok(quiz.questions.length >= 4 && quiz.questions.length <= 8, `${folder}: 4 to 8 questions`);
    for (const q of quiz.questions) {
      if (q.type === 'choice') {
        assert.equal(q.choices.filter((c) => c.correct).length, 1, `${folder} ${q.id}: one right choice`);
        for (const c of q.choices) assert.ok(c.why.length > 10, `${folder} ${q.id}: each choice explains itself`);
      } else {
        const value = quizAnswer(q.answer.core, new Float32Array(q.answer.args));
        assert.ok(Number.isFinite(value), `${folder} ${q.id}`);
        // The tolerance must tell a right answer from a near miss a student could make.
        assert.ok(q.tolerance < Math.max(Math.abs(value) * 0.2, 0.05), `${folder} ${q.id}: tolerance ${q.tolerance} for ${value}`);
      }
    }
  }
  // Known values through the bindings: a quarter of 120° at constant speed; the short way from
  // 170° to −170° passes 180°; a ball dropped from 4.905 m under g = 9.81 m/s² lands after 1 s.
  assert.ok(Math.abs(quizAnswer('slerp_angle_about_z_deg', new Float32Array([0, 120, 0.25])) - 30) < 1e-3);
  assert.ok(Math.abs(Math.abs(quizAnswer('slerp_angle_about_z_deg', new Float32Array([170, -170, 0.5]))) - 180) < 1e-3);
  assert.ok(Math.abs(quizAnswer('floor_time_of_impact', new Float32Array([4.905, 0, -9.81, 0])) - 1) < 1e-4);
  assert.throws(() => quizAnswer('nope', new Float32Array([])), /no quiz answer named "nope"/);
  assert.throws(() => quizAnswer('fade', new Float32Array([NaN])), /finite/);
});

/** The rectangles of `selector`'s elements in viewport pixels. */
const rects = (page, selector) => page.evaluate((s) => [...document.querySelectorAll(s)].map((e) => {
  const r = e.getBoundingClientRect();
  return { id: e.id, left: r.left, top: r.top, right: r.right, bottom: r.bottom };
}), selector);
const overlap = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

test('a "Your turn" names the grade command with its own lesson\'s number', () => {
  // As lessons 03 and 06 do: `./scripts/grade 07` grades that lesson's exercises alone, the
  // bare command every lesson's.
  for (const folder of ['03-rotations', '06-skeletons', '07-inverse-kinematics', '09-skinning']) {
    const page = readFileSync(join('lessons', folder, 'index.html'), 'utf8');
    const number = folder.split('-')[0];
    assert.ok(page.includes(`<code>./scripts/grade ${number}</code>`), `${folder}: no ./scripts/grade ${number}`);
  }
});

test('navigation, the grading panel, the quiz and progress, as a student uses them', async () => {
  const context = await launch('webgl2');
  try {
    const lesson = `${site.origin}/lessons/03-rotations/?backend=webgl2`;
    const { page, problems } = await openPage(context, `${lesson}#fig-rodrigues`, { width: 800, height: 600 });
    await page.waitForFunction(() => document.body.dataset.course === 'ready');
    // The deep link: the figure is at the top of the window once the page has settled.
    const fig = (await rects(page, '#fig-rodrigues'))[0];
    assert.ok(fig.top > -5 && fig.top < 120, `#fig-rodrigues at ${fig.top}`);
    // Its place in the course, and the lessons before and after it in catalog order.
    assert.match(await page.locator('header .course-place').textContent(), /^Part 3 · Rotations and rigid motion · lesson 1 of 2$/);
    assert.equal(await page.locator('header .course-nav a[rel="prev"]').getAttribute('href'), '../02b-expressive-animation/');
    assert.equal(await page.locator('header .course-nav a[rel="next"]').getAttribute('href'), '../04-rigid-motions/');
    assert.equal(await page.locator('.lesson-pager a[rel="next"]').getAttribute('href'), '../04-rigid-motions/');
    // The outline lists every section, each link leads to an id on the page, every figure has one.
    const outline = await page.evaluate(() => ({
      links: [...document.querySelectorAll('details.outline a')].map((a) => a.getAttribute('href')),
      sections: [...document.querySelectorAll('main h2')].map((h) => `#${h.id}`),
      figures: [...document.querySelectorAll('.figure')].map((f) => f.id),
    }));
    assert.deepEqual(outline.links, outline.sections);
    assert.ok(outline.links.includes('#check-yourself'));
    assert.ok(outline.figures.every((id) => id.startsWith('fig-')), outline.figures.join());
    // At 800 x 600 the outline is closed and in the flow: it covers no figure, open or closed.
    for (const open of [false, true]) {
      await page.evaluate((o) => { document.querySelector('details.outline').open = o; }, open);
      const [box] = await rects(page, 'details.outline');
      for (const f of await rects(page, '.figure')) assert.ok(!overlap(box, f), `outline over ${f.id} (open: ${open})`);
    }
    await page.screenshot({ path: `${SHOTS}/course-03-top-800.png` });
    // The sideways scroll stays off.
    assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth));

    // "Check my exercises" on the stubs: every exercise not yet implemented.
    await page.locator('.grade-run').scrollIntoViewIfNeeded();
    await page.locator('.grade-run').click();
    await page.waitForFunction(() => document.querySelector('.grade-panel').dataset.state === 'done', null, { timeout: 60_000 });
    const verdicts = await page.locator('.grade-table tbody tr').evaluateAll((rows) => rows.map((r) => r.dataset.verdict));
    assert.deepEqual(verdicts, ['not-done', 'not-done', 'not-done']);
    assert.match(await page.locator('.grade-text pre').textContent(), /0 passed, 3 not yet implemented, 0 wrong, of 3/);
    await page.locator('.grade-panel').screenshot({ path: `${SHOTS}/course-03-panel-stubs.png` });

    // The quiz: a wrong and a right choice each get their explanation; a number is checked by the
    // core (30° is a quarter of 120°), a wrong one is told so, text that is no number too.
    const quiz = quizzes.find((q) => q.folder === '03-rotations').quiz;
    const choice = quiz.questions.find((q) => q.type === 'choice');
    const box = page.locator(`#quiz-${choice.id}`);
    const wrong = choice.choices.findIndex((c) => !c.correct);
    const right = choice.choices.findIndex((c) => c.correct);
    await box.locator(`input[type="radio"][value="${wrong}"]`).check();
    assert.equal(await box.getAttribute('data-answered'), 'wrong');
    assert.ok((await box.locator('.feedback').textContent()).includes(choice.choices[wrong].why));
    await box.locator(`input[type="radio"][value="${right}"]`).check();
    assert.equal(await box.getAttribute('data-answered'), 'right');
    assert.ok((await box.locator('.feedback').textContent()).includes(choice.choices[right].why));
    // The right choice is not always shown first (quiz.json lists it first).
    const firstShown = await page.locator('.quiz-question').evaluateAll((boxes) => boxes
      .filter((b) => b.dataset.type === 'choice').map((b) => b.querySelector('input[type="radio"]').value));
    assert.ok(firstShown.some((v) => v !== '0'), `first choices shown: ${firstShown}`);
    const number = page.locator('#quiz-slerp-quarter');
    for (const [typed, verdict] of [['abc', 'unreadable'], ['45', 'wrong'], ['30', 'right']]) {
      await number.locator('input').fill(typed);
      await number.locator('button', { hasText: 'Check' }).click();
      assert.equal(await number.getAttribute('data-answered'), verdict, typed);
    }
    assert.match(await number.locator('.feedback').textContent(), /the core computes 30°/);
    // "show me" sets the figure's controls and brings the figure into view.
    await page.locator('#quiz-gimbal .show-me').click();
    await page.waitForFunction(() => {
      const r = document.getElementById('fig-gimbal').getBoundingClientRect();
      return r.top > -5 && r.top < 200;
    });
    const pitch = await page.locator('#fig-gimbal .lil-controller', { hasText: 'pitch' }).locator('input').first().inputValue();
    assert.equal(Number(pitch), 90);
    await page.locator('.quiz').screenshot({ path: `${SHOTS}/course-03-quiz.png` });

    // Progress survives a reload: the answers are back, the panel says when it last checked, and
    // (after one check in this tab) grades again by itself.
    await page.reload();
    await page.waitForFunction(() => document.body.dataset.course === 'ready');
    assert.equal(await page.locator('#quiz-slerp-quarter').getAttribute('data-answered'), 'right');
    assert.equal(await page.locator(`#quiz-${choice.id} input[type="radio"][value="${right}"]`).isChecked(), true);
    await page.waitForFunction(() => document.querySelector('.grade-panel').dataset.state === 'done', null, { timeout: 60_000 });
    assert.deepEqual(problems, []);

    // At 1600 x 1000 the outline stands open in the left margin, clear of every figure.
    await page.setViewportSize({ width: 1600, height: 1000 });
    await page.reload();
    await page.waitForFunction(() => document.body.dataset.course === 'ready');
    assert.equal(await page.evaluate(() => document.querySelector('details.outline').open), true);
    for (const id of outline.figures) {
      await page.locator(`#${id}`).scrollIntoViewIfNeeded();
      const [box1] = await rects(page, 'details.outline');
      const [f] = await rects(page, `#${id}`);
      assert.ok(!overlap(box1, f), `outline over ${id} at 1600 x 1000`);
    }
    await page.screenshot({ path: `${SHOTS}/course-03-1600.png` });

    // The gallery: lesson 03 started, with its numbers; the course total; nothing leaves the browser.
    await page.goto(`${site.origin}/lessons/`);
    await page.waitForFunction(() => document.body.dataset.ready);
    const card = page.locator('.card[data-lesson="03-rotations"]');
    assert.equal(await card.getAttribute('data-state'), 'started');
    assert.equal(await card.locator('.progress').textContent(), `exercises 0 of 3 passed · quiz 2 of ${quiz.questions.length}`);
    assert.equal(await page.locator('.card[data-lesson="01-transforms"]').getAttribute('data-state'), 'not-started');
    assert.match(await page.locator('.progress-bar').textContent(), /nothing leaves the browser/);
    assert.match(await page.locator('.progress-bar .total').textContent(), /· exercises 0 of 3 passed \(in the lessons checked\) · quiz 2 of \d+ right/);
    await page.screenshot({ path: `${SHOTS}/course-gallery.png` });

    // A corrupt entry is ignored with a note, never a crash; then the reset forgets everything.
    const gallery = await openPage(context, `${site.origin}/lessons/`);
    await gallery.page.evaluate(() => {
      localStorage.setItem('inbetween:progress:v1', JSON.stringify({ version: 1, lessons: {
        '03-rotations': { exercises: { slerp: 'maybe' } }, '01-transforms': { quiz: { a: { answer: '1', correct: true } } },
      } }));
    });
    await gallery.page.reload();
    await gallery.page.waitForFunction(() => document.body.dataset.ready);
    assert.match(await gallery.page.locator('.progress-note').textContent(), /lesson 03-rotations could not be read/);
    assert.equal(await gallery.page.locator('.card[data-lesson="01-transforms"]').getAttribute('data-state'), 'started');
    await gallery.page.evaluate(() => localStorage.setItem('inbetween:progress:v1', '{not json'));
    await gallery.page.reload();
    await gallery.page.waitForFunction(() => document.body.dataset.ready);
    assert.match(await gallery.page.locator('.progress-note').textContent(), /not valid JSON/);
    assert.equal(await gallery.page.locator('.card[data-state="not-started"]').count(), await gallery.page.locator('.card').count());
    gallery.page.once('dialog', (d) => d.accept());
    await gallery.page.locator('.progress-bar button', { hasText: 'reset my progress' }).click();
    assert.equal(await gallery.page.evaluate(() => localStorage.getItem('inbetween:progress:v1')), null);
    assert.equal(await gallery.page.locator('.progress-note').count(), 0);
    // Nothing checked or answered: the total says so rather than "0 of 0".
    await gallery.page.reload();
    await gallery.page.waitForFunction(() => document.body.dataset.ready);
    assert.match(await gallery.page.locator('.progress-bar .total').textContent(), /lessons done · no exercises checked yet · quiz 0 of \d+ right$/);
    assert.deepEqual(gallery.problems, []);
  } finally {
    await context.close();
  }
});

test('hovering one plot of a figure reads every plot of that figure at the same x', async () => {
  const context = await launch('webgl2');
  try {
    const { page, problems } = await openPage(context, `${site.origin}/lessons/02-keyframes/?backend=webgl2#fig-timing`, { width: 1280, height: 900 });
    await page.waitForFunction(() => document.body.dataset.ready === '1');
    const readout = (id) => page.locator(`#${id} .plot-readout`);
    assert.ok(await readout('keys-speed').isHidden(), 'no readout before the pointer comes');
    await page.locator('#keys-speed').scrollIntoViewIfNeeded();
    const box = await page.locator('#keys-speed .u-over').boundingBox();
    await page.mouse.move(box.x + box.width * 0.4, box.y + box.height * 0.5);
    await page.waitForFunction(() => !document.querySelector('#keys-accel .plot-readout').hidden);
    const read = async (id) => {
      const text = await readout(id).textContent();
      const m = text.match(/^time \(s\) = ([\d.]+)keyed: ([-\d.e]+)constant speed: ([-\d.e]+)$/);
      assert.ok(m, `${id} readout: ${text}`);
      return m.slice(1).map(Number);
    };
    const [speed, accel] = [await read('keys-speed'), await read('keys-accel')];
    // The same x in both (the cursor is synced), 40 % along a 3.2 s timeline; other values.
    assert.equal(speed[0], accel[0]);
    assert.ok(Math.abs(speed[0] - 0.4 * 3.2) < 0.1, `x = ${speed[0]}`);
    assert.notDeepEqual(speed.slice(1), accel.slice(1));
    // The readout takes the legend's place; both come back as they were when the pointer leaves.
    assert.equal(await page.locator('#keys-accel .u-legend').evaluate((e) => getComputedStyle(e).visibility), 'hidden');
    await page.mouse.move(2, 2);
    await page.waitForFunction(() => document.querySelector('#keys-speed .plot-readout').hidden
      && document.querySelector('#keys-accel .plot-readout').hidden);
    assert.equal(await page.locator('#keys-accel .u-legend').evaluate((e) => getComputedStyle(e).visibility), 'visible');
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
