// A student's progress through the course, kept in this browser's localStorage and nowhere else:
// each exercise's last verdict from the "Check my exercises" panel and each quiz answer, per lesson.
//
// One key, namespaced and versioned: `inbetween:progress:v1`, holding
//   { version: 1, lessons: { "03-rotations": { exercises: { slerp: "passed", … }, exerciseCount: 3,
//     checked: 1764790000000, quiz: { q1: { answer: "2", correct: true }, … }, quizCount: 5 } } }
// Anything else found there (text that is not JSON, a lesson entry of the wrong shape, the key of
// another version) is ignored, with a note that says so, and never stops the page.

export const KEY = 'inbetween:progress:v1';
const PREFIX = 'inbetween:progress:';
const VERDICTS = new Set(['passed', 'not-done', 'wrong', 'panicked', 'stopped']);

/** The notes about entries that could not be read, for the page to show (one per problem). */
export const notes = [];

function note(text) {
  if (!notes.includes(text)) notes.push(text);
}

function storage() {
  try {
    return window.localStorage;
  } catch {
    note('This browser does not let the page keep your progress (localStorage is off).');
    return null;
  }
}

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

/** `entry` if it has the shape of one lesson's progress, else null. */
function validLesson(entry) {
  if (!isObject(entry)) return null;
  const out = {};
  if (entry.exercises !== undefined) {
    if (!isObject(entry.exercises) || !Object.values(entry.exercises).every((v) => VERDICTS.has(v))) return null;
    out.exercises = entry.exercises;
  }
  for (const key of ['exerciseCount', 'quizCount', 'checked']) {
    if (entry[key] === undefined) continue;
    if (!Number.isFinite(entry[key]) || entry[key] < 0) return null;
    out[key] = entry[key];
  }
  if (entry.quiz !== undefined) {
    if (!isObject(entry.quiz)) return null;
    const ok = Object.values(entry.quiz).every((a) => isObject(a) && typeof a.answer === 'string' && typeof a.correct === 'boolean');
    if (!ok) return null;
    out.quiz = entry.quiz;
  }
  return out;
}

/** Every lesson's progress that could be read: `{ [lessonId]: { exercises, quiz, … } }`. */
export function loadProgress() {
  const store = storage();
  if (!store) return {};
  for (let i = 0; i < store.length; i++) {
    const key = store.key(i);
    if (key?.startsWith(PREFIX) && key !== KEY) {
      note(`Progress saved by another version of the course (${key}) is ignored.`);
    }
  }
  const text = store.getItem(KEY);
  if (text === null) return {};
  let saved;
  try {
    saved = JSON.parse(text);
  } catch {
    note('Your saved progress could not be read (it is not valid JSON) and is ignored; what you do from now on is saved afresh.');
    return {};
  }
  if (!isObject(saved) || saved.version !== 1 || !isObject(saved.lessons)) {
    note('Your saved progress has an unknown form and is ignored; what you do from now on is saved afresh.');
    return {};
  }
  const lessons = {};
  for (const [id, entry] of Object.entries(saved.lessons)) {
    const valid = validLesson(entry);
    if (valid) lessons[id] = valid;
    else note(`The saved progress of lesson ${id} could not be read and is ignored.`);
  }
  return lessons;
}

/** Merges `changes` into the saved progress of lesson `id` (entries that could not be read are
 * dropped on the way). */
export function saveLesson(id, changes) {
  const store = storage();
  if (!store) return;
  const lessons = loadProgress();
  const entry = { ...(lessons[id] ?? {}) };
  for (const [key, value] of Object.entries(changes)) {
    entry[key] = key === 'quiz' ? { ...(entry.quiz ?? {}), ...value } : value;
  }
  lessons[id] = entry;
  try {
    store.setItem(KEY, JSON.stringify({ version: 1, lessons }));
  } catch (e) {
    note(`Your progress could not be saved: ${e?.message ?? e}`);
  }
}

/** Forgets every lesson's progress (the gallery's "reset my progress"). */
export function resetProgress() {
  const store = storage();
  if (!store) return;
  const keys = [];
  for (let i = 0; i < store.length; i++) if (store.key(i)?.startsWith(PREFIX)) keys.push(store.key(i));
  for (const key of keys) store.removeItem(key);
  notes.length = 0;
}

/** A lesson's progress in numbers: exercises passed and known, quiz questions right and asked. */
export function summary(entry = {}) {
  const verdicts = Object.values(entry.exercises ?? {});
  const answers = Object.values(entry.quiz ?? {});
  return {
    passed: verdicts.filter((v) => v === 'passed').length,
    exercises: entry.exerciseCount ?? verdicts.length,
    checked: entry.checked ?? null,
    right: answers.filter((a) => a.correct).length,
    answered: answers.length,
    quiz: entry.quizCount ?? null,
  };
}
