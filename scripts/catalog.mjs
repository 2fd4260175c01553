// Writes dist/lessons/catalog.json (the gallery's list, from each lesson's meta.json) and copies
// the source files that lessons show into dist/source/ (into $INBETWEEN_DIST instead of dist/ when
// set, as scripts/build does).
import { readdirSync, readFileSync, writeFileSync, mkdirSync, copyFileSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';

const dist = process.env.INBETWEEN_DIST ?? 'dist';
// The lessons with exercises to grade: their ids as LESSONS in src/exercises/grade.rs lists them.
const grader = readFileSync('src/exercises/grade.rs', 'utf8');
const lessonsList = grader.slice(grader.indexOf('pub const LESSONS'), grader.indexOf('];', grader.indexOf('pub const LESSONS')));
const graded = new Set([...lessonsList.matchAll(/lesson\(\s*"([^"]+)"/g)].map((m) => m[1]));
const catalog = [];
for (const folder of readdirSync('lessons').sort()) {
  const metaPath = join('lessons', folder, 'meta.json');
  if (!existsSync(metaPath)) continue;
  const meta = JSON.parse(readFileSync(metaPath, 'utf8'));
  for (const key of ['title', 'summary', 'part', 'order']) {
    if (meta[key] === undefined) throw new Error(`${metaPath} lacks "${key}"`);
  }
  // A lesson without a thumbnail yet (THUMBNAILS=1 node --test tests/e2e/ makes one) gets a placeholder.
  const hasThumbnail = Boolean(meta.thumbnail) && existsSync(join('lessons', folder, meta.thumbnail));
  // The quiz's size, for the gallery's "quiz 3 of 5" (www/course.js renders the questions).
  const quizPath = join('lessons', folder, 'quiz.json');
  let quizQuestions = 0;
  if (existsSync(quizPath)) {
    const quiz = JSON.parse(readFileSync(quizPath, 'utf8'));
    checkQuiz(quizPath, quiz);
    quizQuestions = quiz.questions.length;
  }
  catalog.push({ folder, ...meta, hasThumbnail, hasExercises: graded.has(folder), quizQuestions });
  for (const { path } of meta.sources ?? []) {
    if (!existsSync(path)) throw new Error(`${metaPath} lists ${path}, which does not exist`);
    mkdirSync(dirname(join(dist, 'source', path)), { recursive: true });
    copyFileSync(path, join(dist, 'source', path));
  }
}
// The gallery lists lessons by their `order` (fractional orders slot a lesson between two others).
catalog.sort((a, b) => a.order - b.order);
writeFileSync(join(dist, 'lessons', 'catalog.json'), JSON.stringify(catalog, null, 2));

/** Fails the build on a quiz the page could not render: every question needs an id, a prompt and,
 * by its type, choices with one right and an explanation each, or a core to compute the answer. */
function checkQuiz(path, quiz) {
  const fail = (why) => { throw new Error(`${path}: ${why}`); };
  if (!Array.isArray(quiz.questions) || quiz.questions.length === 0) fail('"questions" must be a non-empty list');
  const ids = new Set();
  quiz.questions.forEach((q, i) => {
    const at = `question ${i + 1}`;
    if (typeof q.id !== 'string' || !q.id) fail(`${at} lacks an "id"`);
    if (ids.has(q.id)) fail(`${at}: the id "${q.id}" is used twice`);
    ids.add(q.id);
    if (typeof q.prompt !== 'string' || !q.prompt) fail(`${at} lacks a "prompt"`);
    if (q.type === 'choice') {
      if (!Array.isArray(q.choices) || q.choices.length < 2) fail(`${at}: a choice question needs two choices or more`);
      if (q.choices.filter((c) => c.correct).length !== 1) fail(`${at}: exactly one choice must be "correct"`);
      q.choices.forEach((c, k) => {
        if (typeof c.text !== 'string' || typeof c.why !== 'string' || !c.why) fail(`${at}, choice ${k + 1}: needs "text" and "why"`);
      });
    } else if (q.type === 'number') {
      if (typeof q.answer?.core !== 'string' || !Array.isArray(q.answer.args)) fail(`${at}: "answer" needs "core" and "args"`);
      if (!(q.tolerance > 0)) fail(`${at}: "tolerance" must be a positive number`);
      if (typeof q.why !== 'string') fail(`${at} lacks a "why"`);
    } else {
      fail(`${at}: "type" must be "choice" or "number"`);
    }
  });
}
