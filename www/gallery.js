import './devloop.js';
import { loadProgress, resetProgress, summary, notes } from './progress.js';
// The lesson index: one card per lesson, grouped by part, from the catalog the build writes, with
// the student's progress from this browser's localStorage (www/progress.js).
const catalog = await (await fetch('catalog.json')).json();
const root = document.getElementById('gallery');

/** What a card says of a lesson's progress, and whether it is done, started or not started. */
function lessonProgress(lesson, entry) {
  const s = summary(entry);
  const parts = [];
  if (lesson.hasExercises) {
    parts.push(s.checked === null ? 'exercises not checked yet' : `exercises ${s.passed} of ${s.exercises} passed`);
  }
  if (lesson.quizQuestions) parts.push(`quiz ${s.right} of ${lesson.quizQuestions}`);
  const exercisesDone = !lesson.hasExercises || (s.checked !== null && s.passed === s.exercises && s.exercises > 0);
  const quizDone = !lesson.quizQuestions || s.right >= lesson.quizQuestions;
  const anything = s.checked !== null || s.answered > 0;
  const state = anything && exercisesDone && quizDone ? 'done' : anything ? 'started' : 'not-started';
  return { text: parts.join(' · '), state, s };
}

function render() {
  const progress = loadProgress();
  root.replaceChildren();
  const totals = { done: 0, passed: 0, exercises: 0, right: 0, questions: 0 };
  const bar = document.createElement('section');
  bar.className = 'progress-bar';
  bar.id = 'progress';
  const parts = [...new Set(catalog.map((l) => l.part))];
  const sections = [];
  for (const part of parts) {
    const heading = document.createElement('h2');
    heading.textContent = part;
    const grid = document.createElement('div');
    grid.className = 'gallery';
    for (const lesson of catalog.filter((l) => l.part === part).sort((a, b) => a.order - b.order)) {
      const card = document.createElement('a');
      card.className = 'card';
      card.href = `${lesson.folder}/`;
      card.dataset.lesson = lesson.folder;
      const image = lesson.hasThumbnail ? `<img alt="" src="${lesson.folder}/${lesson.thumbnail}">` : '<img alt="">';
      card.innerHTML = `${image}<span class="state"></span><div class="text"><h3></h3><p></p><p class="progress"></p></div>`;
      card.querySelector('h3').textContent = lesson.title;
      card.querySelector('p').textContent = lesson.summary;
      const { text, state, s } = lessonProgress(lesson, progress[lesson.folder]);
      card.dataset.state = state;
      card.querySelector('.state').textContent = { done: 'done', started: 'started', 'not-started': 'not started' }[state];
      card.querySelector('.progress').textContent = text;
      totals.done += state === 'done';
      totals.passed += s.passed;
      totals.exercises += s.exercises;
      totals.right += s.right;
      totals.questions += lesson.quizQuestions ?? 0;
      grid.append(card);
    }
    sections.push(heading, grid);
  }
  const total = document.createElement('span');
  total.className = 'total';
  // Before any lesson's exercises are checked there is no count to give ("0 of 0 passed").
  const exercises = totals.exercises === 0 ? 'no exercises checked yet'
    : `exercises ${totals.passed} of ${totals.exercises} passed (in the lessons checked)`;
  total.textContent = `Your progress: ${totals.done} of ${catalog.length} lessons done · ${exercises} · ` +
    `quiz ${totals.right} of ${totals.questions} right`;
  const reset = document.createElement('button');
  reset.type = 'button';
  reset.textContent = 'reset my progress';
  reset.addEventListener('click', () => {
    if (window.confirm('Forget every exercise verdict and quiz answer saved in this browser?')) {
      resetProgress();
      render();
    }
  });
  const privacy = document.createElement('p');
  privacy.className = 'private';
  privacy.textContent = 'Your progress is kept in this browser only (its localStorage): nothing leaves the browser, ' +
    'no server sees it, and another browser or a private window starts afresh.';
  bar.append(total, reset, privacy);
  if (notes.length) {
    const note = document.createElement('p');
    note.className = 'progress-note';
    note.setAttribute('role', 'status');
    note.textContent = notes.join(' ');
    bar.append(note);
  }
  root.append(bar, ...sections);
}

render();
// Progress made in another tab shows when this one is looked at again.
window.addEventListener('storage', render);
document.body.dataset.ready = '1';
