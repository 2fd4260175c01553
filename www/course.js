// The course around a lesson page, added by the shell (www/lesson.js) from data, never written
// into each page: its place in the course and the links to the lessons before and after it (from
// the catalog the build writes), an outline of its sections, ids on every section and figure for
// deep links, the "Check my exercises" panel (the grader in a worker, with a time limit) and the
// quiz (the lesson folder's quiz.json, numeric answers computed by the cores through the bindings).
import { loadProgress, saveLesson, notes as progressNotes, summary } from './progress.js';

/** The lesson's folder name (`03-rotations`), from the page's URL. */
export function lessonId() {
  const parts = location.pathname.split('/').filter(Boolean);
  const at = parts.lastIndexOf('lessons');
  return at >= 0 ? parts[at + 1] ?? '' : '';
}

const slug = (text) => text.toLowerCase().normalize('NFKD').replace(/[^\w\s-]/g, '')
  .trim().replace(/[\s_]+/g, '-').replace(/-+/g, '-').slice(0, 48);

/** Gives every section heading and figure an id (kept where the page has one) and each heading a
 * link to itself. */
function addIds(main) {
  const taken = new Set([...document.querySelectorAll('[id]')].map((e) => e.id));
  const unique = (base) => {
    let id = base;
    for (let n = 2; taken.has(id); n++) id = `${base}-${n}`;
    taken.add(id);
    return id;
  };
  main.querySelectorAll('.figure').forEach((figure, i) => {
    if (!figure.id) figure.id = unique(`fig-${i + 1}`);
  });
  for (const h of main.querySelectorAll('h2, h3')) {
    if (!h.id) h.id = unique(`sec-${slug(h.textContent) || 'section'}`);
    if (!h.querySelector('a.anchor')) {
      const a = document.createElement('a');
      a.className = 'anchor';
      a.href = `#${h.id}`;
      a.textContent = '#';
      a.setAttribute('aria-label', `link to “${h.textContent}”`);
      h.append(a);
    }
  }
}

/** Scrolls to the element the URL's #hash names (ids added by the shell did not exist when the
 * browser looked). */
export function scrollToHash() {
  const id = decodeURIComponent(location.hash.slice(1));
  if (id) document.getElementById(id)?.scrollIntoView({ block: 'start' });
}

function link(href, text, rel) {
  const a = document.createElement('a');
  a.href = href;
  a.textContent = text;
  if (rel) a.rel = rel;
  return a;
}

/**
 * Navigation from the catalog: "Part 3 · Rotations and rigid motion · lesson 1 of 2" in the header,
 * the previous and next lessons (catalog order) in the header and at the end of the page, and an
 * outline of the page's sections (collapsible; beside the text on wide screens only, where it
 * covers nothing).
 */
export function setUpNavigation(catalog, id) {
  const main = document.querySelector('main');
  if (!main) return;
  const index = catalog.findIndex((l) => l.folder === id);
  const header = document.querySelector('header.site');
  if (index >= 0 && header) {
    const lesson = catalog[index];
    const parts = [...new Set(catalog.map((l) => l.part))];
    const inPart = catalog.filter((l) => l.part === lesson.part);
    const place = `Part ${parts.indexOf(lesson.part) + 1} · ${lesson.part} · lesson ${inPart.indexOf(lesson) + 1} of ${inPart.length}`;
    let span = header.querySelector('span:not(.build)');
    if (!span) {
      span = document.createElement('span');
      header.querySelector('a')?.after(span);
    }
    span.className = 'course-place';
    span.textContent = place;
    const prev = catalog[index - 1];
    const next = catalog[index + 1];
    const nav = document.createElement('nav');
    nav.className = 'course-nav';
    nav.setAttribute('aria-label', 'previous and next lesson');
    if (prev) nav.append(link(`../${prev.folder}/`, `‹ ${prev.title}`, 'prev'));
    if (next) nav.append(link(`../${next.folder}/`, `${next.title} ›`, 'next'));
    span.after(nav);
    const bottom = document.createElement('nav');
    bottom.className = 'lesson-pager';
    bottom.setAttribute('aria-label', 'previous and next lesson');
    bottom.append(
      prev ? link(`../${prev.folder}/`, `‹ Previous: ${prev.title}`, 'prev') : document.createElement('span'),
      link('../', 'All lessons'),
      next ? link(`../${next.folder}/`, `Next: ${next.title} ›`, 'next') : document.createElement('span'),
    );
    main.append(bottom);
  }
}

/** The outline of the page's sections, after the lede (call once every section is in place). */
export function addOutline() {
  const main = document.querySelector('main');
  if (!main || document.querySelector('details.outline')) return;
  addIds(main);
  const outline = document.createElement('details');
  outline.className = 'outline';
  const summaryEl = document.createElement('summary');
  summaryEl.textContent = 'On this page';
  const list = document.createElement('ol');
  for (const h of main.querySelectorAll('h2')) {
    const item = document.createElement('li');
    item.append(link(`#${h.id}`, h.firstChild?.textContent?.trim() || h.textContent));
    list.append(item);
  }
  outline.append(summaryEl, list);
  // Open beside the text when the window leaves room for it (style.css places it there).
  if (window.matchMedia('(min-width: 1400px)').matches) outline.open = true;
  (main.querySelector('.lede') ?? main.querySelector('h1'))?.after(outline);
}

/** A note about saved progress that could not be read (see www/progress.js), once per page. */
function showProgressNotes(where) {
  if (!progressNotes.length || document.querySelector('.progress-note')) return;
  const p = document.createElement('p');
  p.className = 'progress-note';
  p.setAttribute('role', 'status');
  p.textContent = progressNotes.join(' ');
  where.prepend(p);
}

// ---- Check my exercises -------------------------------------------------------------------------

/** How long a case may run before the panel stops it (an endless loop, most likely). */
export const CASE_LIMIT_S = 5;
/** How long a worker may take to start its module (no student code runs then). */
const START_LIMIT_S = 60;

/** "panicked at src/x.rs:3:5:\nmessage" (Rust's panic hook) as { message, location }. */
function splitPanic(text) {
  const m = /^panicked at (.+?:\d+:\d+):\n([\s\S]*)$/.exec(text);
  return m ? { location: m[1], message: m[2] } : { message: text };
}

/**
 * Runs one grading in a fresh worker. Resolves to { kind: 'done', rows, table }, { kind:
 * 'panicked', exercise, case, message, location }, { kind: 'stopped', exercise, case } or
 * { kind: 'error', message }; the worker is ended in every case but 'done'. `onCase(exercise,
 * previous)` hears of each case as it starts; `quiet` keeps the grader's console lines out.
 */
function gradeInWorker(module, lesson, known, onCase = () => {}, quiet = false) {
  return new Promise((resolve) => {
    const worker = new Worker(new URL('./grade-worker.js', import.meta.url), { type: 'module' });
    let current = null; // { exercise, case } the grader last said it started
    let panic = null;
    let timer = null;
    const finish = (result) => {
      clearTimeout(timer);
      worker.terminate();
      resolve(result);
    };
    const watch = (seconds, onTimeout) => {
      clearTimeout(timer);
      timer = setTimeout(onTimeout, seconds * 1000);
    };
    const stop = () => finish(current
      ? { kind: 'stopped', ...current }
      : { kind: 'error', message: `the grader gave no sign of life within ${CASE_LIMIT_S} s` });
    watch(START_LIMIT_S, () => finish({ kind: 'error', message: `the grader did not start within ${START_LIMIT_S} s` }));
    worker.onerror = (e) => finish({ kind: 'error', message: e.message || 'the grading worker failed to load' });
    worker.onmessage = ({ data }) => {
      switch (data.kind) {
        case 'ready':
          watch(CASE_LIMIT_S, stop);
          worker.postMessage({ lesson, known, quiet });
          break;
        case 'case':
          onCase(data.exercise, current?.exercise);
          current = { exercise: data.exercise, case: data.case };
          watch(CASE_LIMIT_S, stop);
          break;
        case 'panic':
          panic = splitPanic(data.message);
          break;
        case 'done':
          finish({ kind: 'done', rows: data.rows, table: data.table });
          break;
        case 'trapped':
          finish(panic && current
            ? { kind: 'panicked', ...current, ...panic }
            : { kind: 'error', message: `the grader stopped: ${data.message}` });
          break;
        default:
          finish({ kind: 'error', message: data.message });
      }
    };
    worker.postMessage({ module });
  });
}

/**
 * Grades lesson `id` round after round, each round in a fresh worker that replays the failures
 * the rounds before met (a panic ends its module, a stopped case its worker), until a round
 * finishes; each round either finishes or learns one more failure, so there is at most one round
 * per exercise. Resolves to `{ result, known }`: `result` the last round's ({ kind: 'done', rows,
 * table } or { kind: 'error', message }), `known` the failures met, in order. `onRound(known)` runs
 * before every round after the first; `onCase` and `quiet` are `gradeInWorker`'s.
 */
async function gradeRounds(module, id, { onCase, quiet = false, onRound = () => {} } = {}) {
  const known = [];
  for (let round = 0; round < 64; round++) {
    if (round > 0) onRound(known);
    const result = await gradeInWorker(module, id, known, onCase, quiet);
    if (result.kind === 'panicked') {
      known.push({ exercise: result.exercise, case: result.case, kind: 'panicked', message: result.message, location: result.location });
    } else if (result.kind === 'stopped') {
      known.push({ exercise: result.exercise, case: result.case, kind: 'stopped', seconds: CASE_LIMIT_S });
    } else {
      return { result, known };
    }
  }
  return { result: { kind: 'error', message: 'the grader went round too many times' }, known };
}

/** What the panel's status line says of a failure a round met. */
function failureEvent(k) {
  return k.kind === 'panicked'
    ? `${k.exercise} panicked at case ${k.case}`
    : `${k.exercise} gave no answer within ${CASE_LIMIT_S} s at case ${k.case} and was stopped`;
}

/**
 * Grades lesson `id`'s exercises as the panel does (`gradeRounds`, quietly), for the figures
 * (www/lesson.js): an exercise runs in the page only once it has returned from every grading
 * case here, since an endless loop on the page's own thread could never be stopped. Calls
 * `returned(exercise)` as each exercise gets through its cases (a panic counts: the page's sandbox
 * survives one) and resolves to a Map from each stopped exercise to a sentence saying where it
 * was stopped, or, when the grader cannot run, to `{ error }`. Nothing is saved to the student's
 * progress.
 */
export async function checkExercises(module, id, returned) {
  const { result } = await gradeRounds(module, id, {
    quiet: true,
    // The grader moved on to the next exercise: the one before returned.
    onCase: (exercise, previous) => { if (previous && previous !== exercise) returned(previous); },
    onRound: (known) => { if (known.at(-1).kind === 'panicked') returned(known.at(-1).exercise); },
  });
  if (result.kind !== 'done') return { error: result.message };
  const stopped = new Map();
  for (const row of result.rows) {
    if (row.verdict === 'stopped') {
      stopped.set(row.exercise, `it gave no answer within ${CASE_LIMIT_S} s at the grader's case ${row.case} (${row.what}), `
        + 'so the page does not run it (an endless loop would freeze the page); fix it and reload');
    } else returned(row.exercise);
  }
  return stopped;
}

const VERDICT_WORDS = {
  passed: 'passed', 'not-done': 'not yet implemented', wrong: 'WRONG', panicked: 'PANICKED', stopped: 'STOPPED',
};

/** One exercise's row: its name, then the verdict and what the case tested, its input, for a list
 * answer where it is wrong, and expected and actual (or the panic's message and place, or the
 * time limit). */
function resultRow(row) {
  const tr = document.createElement('tr');
  tr.dataset.exercise = row.exercise;
  tr.dataset.verdict = row.verdict;
  tr.className = `verdict-${row.verdict}`;
  const name = document.createElement('td');
  name.innerHTML = '<code></code>';
  name.firstChild.textContent = row.exercise;
  const cell = document.createElement('td');
  const head = document.createElement('div');
  head.className = 'verdict';
  const add = (label, value, cls) => {
    const line = document.createElement('div');
    line.className = cls ?? 'detail';
    const b = document.createElement('span');
    b.className = 'label';
    b.textContent = label;
    const v = document.createElement('code');
    v.textContent = value;
    line.append(b, v);
    cell.append(line);
  };
  if (row.verdict === 'passed') head.textContent = `passed (${row.cases} cases)`;
  else if (row.verdict === 'not-done') head.textContent = 'not yet implemented';
  else head.textContent = `${VERDICT_WORDS[row.verdict]} at case ${row.case} (${row.what})`;
  cell.append(head);
  const input = (row.input ?? []).map(([n, v]) => `${n} = ${v}`).join(', ');
  if (row.verdict === 'wrong') {
    add('input', input);
    if (row.list) add('wrong', row.list);
    add('expected', row.expected);
    add('yours', row.actual);
  } else if (row.verdict === 'panicked') {
    add('message', row.message);
    if (row.location) add('at', row.location);
    add('input', input);
  } else if (row.verdict === 'stopped') {
    add('why', `no answer within ${row.seconds} s: an endless loop? The page stopped it and graded the others.`);
    add('input', input);
  }
  tr.append(name, cell);
  return tr;
}

/** "1 passed, 1 not yet implemented, 1 wrong, 1 panicked, of 4": a panic or a stopped case is
 * named as such (it is not a wrong answer), and only when there is one. */
function countLine(rows) {
  const count = (verdict) => rows.filter((r) => r.verdict === verdict).length;
  const parts = [`${count('passed')} passed`, `${count('not-done')} not yet implemented`, `${count('wrong')} wrong`];
  if (count('panicked')) parts.push(`${count('panicked')} panicked`);
  if (count('stopped')) parts.push(`${count('stopped')} stopped`);
  return `${parts.join(', ')}, of ${rows.length}`;
}

/**
 * The "Check my exercises" panel under the lesson's "Your turn" section. It grades in a worker
 * (a fresh module instance), with CASE_LIMIT_S per case: a panic or a case that never ends is
 * reported in its row, and the grading goes on in a fresh worker that replays it (see
 * src/exercises/grade.rs, `Known`). Re-runs by itself when the page loads under `scripts/serve`
 * (which reloads it after each rebuild) or after the student has checked once in this tab.
 */
export function gradePanel(module, id) {
  const main = document.querySelector('main');
  if (!main || document.getElementById('check-exercises')) return null;
  const turn = [...main.querySelectorAll('h2')].find((h) => /^your turn/i.test(h.textContent.trim()));
  const section = document.createElement('section');
  section.className = 'grade-panel';
  section.id = 'check-exercises';
  section.innerHTML = `
    <h3>Check my exercises</h3>
    <p class="grade-intro">Runs the grader of <code>scripts/grade</code> on the exercises of this
    lesson as this page's build has them (under <code>scripts/serve</code>, a save rebuilds it and the
    page reloads). Each case gets ${CASE_LIMIT_S} s; one that runs longer is stopped.</p>
    <div class="grade-actions"><button type="button" class="grade-run">Check my exercises</button>
    <span class="grade-status" role="status"></span></div>
    <table class="grade-table" hidden><thead><tr><th>exercise</th><th>result</th></tr></thead><tbody></tbody></table>
    <details class="grade-text" hidden><summary>the same table as <code>scripts/grade</code> prints it</summary><pre></pre></details>`;
  let anchor = turn;
  if (anchor?.nextElementSibling?.classList.contains('callout')) anchor = anchor.nextElementSibling;
  if (anchor) anchor.after(section);
  else (main.querySelector('#source-list')?.previousElementSibling ?? main.lastElementChild).before(section);
  const button = section.querySelector('.grade-run');
  const status = section.querySelector('.grade-status');
  const table = section.querySelector('.grade-table');
  const tbody = table.querySelector('tbody');
  const text = section.querySelector('.grade-text');
  const saved = loadProgress()[id];
  if (saved?.checked) {
    const s = summary(saved);
    status.textContent = `Last checked ${new Date(saved.checked).toLocaleString()}: ${s.passed} of ${s.exercises} passed.`;
  }
  const seenKey = `inbetween:checked:${id}`;

  async function run() {
    button.disabled = true;
    section.dataset.state = 'running';
    try {
      sessionStorage.setItem(seenKey, '1');
    } catch { /* no session storage: no automatic re-run, nothing else lost */ }
    status.textContent = 'Grading…';
    const { result, known } = await gradeRounds(module, id, {
      onRound: (k) => { status.textContent = `Grading again in a fresh module (${failureEvent(k.at(-1))})…`; },
    });
    if (result.kind === 'done') {
      tbody.replaceChildren(...result.rows.map(resultRow));
      table.hidden = false;
      text.hidden = false;
      text.querySelector('pre').textContent = result.table;
      const events = known.map(failureEvent);
      status.textContent = `${countLine(result.rows)}.${events.length ? ` ${events.join('; ')}.` : ''}`;
      section.dataset.state = 'done';
      const exercises = Object.fromEntries(result.rows.map((r) => [r.exercise, r.verdict]));
      saveLesson(id, { exercises, exerciseCount: result.rows.length, checked: Date.now() });
    } else {
      status.textContent = `The grader could not run: ${result.message}`;
      section.dataset.state = 'error';
    }
    button.disabled = false;
  }
  button.addEventListener('click', () => run());
  let again = false;
  try {
    again = sessionStorage.getItem(seenKey) === '1';
  } catch { /* see above */ }
  if (again || document.querySelector('meta[name="inbetween-devloop"]')) run();
  return { run };
}

// ---- The quiz -----------------------------------------------------------------------------------

/** The page's figure controls by figure id and name (registered by www/lesson.js). */
function findControl(controllers, figureId, key) {
  const figure = document.getElementById(figureId);
  if (!figure) return null;
  return controllers.find((c) => figure.contains(c.domElement) && (c.property === key || c._name === key)) ?? null;
}

/** A fixed pseudo-random number for `text` (FNV-1a), to order a question's choices. */
function mix(text) {
  let h = 0x811c9dc5;
  for (const c of text) h = Math.imul(h ^ c.codePointAt(0), 0x01000193) >>> 0;
  return h;
}

/** A number to four significant digits with its unit ("30°", "1.01 s"). */
function withUnit(value, unit) {
  const number = String(Number(value.toPrecision(4)));
  if (!unit) return number;
  return unit === '°' ? `${number}°` : `${number} ${unit}`;
}

/** Parses what a student typed as a number: "0.25", "0,25", "-3", "1e-3", "30°"; NaN otherwise. */
function parseAnswer(text) {
  const cleaned = text.trim().replace(/\s+/g, '').replace(',', '.').replace(/[°a-zA-Z/]+$/, '');
  if (!/^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(cleaned)) return NaN;
  return Number(cleaned);
}

/** Typesets the formulas in `element` (KaTeX's auto-render, where the page loaded it): \( … \)
 * inline, $$ … $$ displayed. */
export function typeset(element) {
  window.renderMathInElement?.(element, {
    delimiters: [
      { left: '$$', right: '$$', display: true },
      { left: '\\(', right: '\\)', display: false },
    ],
    throwOnError: false,
  });
}

/**
 * The lesson's quiz (`quiz.json` beside the page), as the last section before the source list:
 * multiple choice (each choice explains itself once picked) and numeric questions whose answer
 * `quizAnswer(core, args)` computes with the lesson's core. Answers are remembered (www/progress.js).
 */
export async function quiz(id, quizAnswer, controllers) {
  const response = await fetch('quiz.json');
  if (!response.ok) return null;
  const data = await response.json();
  const questions = data.questions ?? [];
  const main = document.querySelector('main');
  const source = [...main.querySelectorAll('h2')].find((h) => /^source/i.test(h.textContent.trim()));
  const section = document.createElement('section');
  section.className = 'quiz';
  section.id = 'quiz';
  const h2 = document.createElement('h2');
  h2.textContent = data.title ?? 'Check yourself';
  h2.id = 'check-yourself';
  const intro = document.createElement('p');
  intro.className = 'quiz-intro';
  intro.textContent = data.intro ?? 'A few questions on this lesson. Your answers stay in this browser.';
  section.append(h2, intro);
  const saved = loadProgress()[id]?.quiz ?? {};
  const record = (q, answer, correct) => saveLesson(id, { quiz: { [q.id]: { answer, correct } }, quizCount: questions.length });

  questions.forEach((q, n) => {
    const box = document.createElement('div');
    box.className = 'quiz-question';
    box.id = `quiz-${q.id}`;
    box.dataset.type = q.type;
    const prompt = document.createElement('p');
    prompt.className = 'prompt';
    prompt.innerHTML = `<strong>${n + 1}.</strong> `;
    prompt.append(document.createTextNode(q.prompt));
    box.append(prompt);
    const feedback = document.createElement('p');
    feedback.className = 'feedback';
    feedback.setAttribute('role', 'status');
    // The feedback's text as written (its formulas typeset): what a later sentence is added to.
    let said = '';
    const say = (text) => {
      said = text;
      feedback.textContent = text;
      typeset(feedback);
    };
    const verdict = (correct, textOut) => {
      box.dataset.answered = correct ? 'right' : 'wrong';
      feedback.className = `feedback ${correct ? 'right' : 'wrong'}`;
      say(textOut);
    };
    if (q.type === 'choice') {
      const list = document.createElement('div');
      list.className = 'choices';
      // Shown in an order fixed by the question's id (the same on every visit), not the file's:
      // quiz.json may list the right choice first.
      const order = q.choices.map((_, i) => i).sort((a, b) => mix(`${q.id}/${a}`) - mix(`${q.id}/${b}`));
      order.forEach((i) => {
        const choice = q.choices[i];
        const label = document.createElement('label');
        const input = document.createElement('input');
        input.type = 'radio';
        input.name = `quiz-${q.id}`;
        input.value = String(i);
        label.append(input, document.createTextNode(` ${choice.text}`));
        input.addEventListener('change', () => {
          verdict(Boolean(choice.correct), `${choice.correct ? 'Right.' : 'Not quite.'} ${choice.why}`);
          record(q, String(i), Boolean(choice.correct));
        });
        list.append(label);
        if (saved[q.id]?.answer === String(i)) {
          input.checked = true;
          verdict(Boolean(choice.correct), `${choice.correct ? 'Right.' : 'Not quite.'} ${choice.why}`);
        }
      });
      box.append(list);
    } else if (q.type === 'number') {
      const row = document.createElement('div');
      row.className = 'number-answer';
      const input = document.createElement('input');
      input.type = 'text';
      input.inputMode = 'decimal';
      input.setAttribute('aria-label', `answer to question ${n + 1}`);
      const unit = document.createElement('span');
      unit.textContent = q.unit ?? '';
      const check = document.createElement('button');
      check.type = 'button';
      check.textContent = 'Check';
      const reveal = document.createElement('button');
      reveal.type = 'button';
      reveal.className = 'reveal';
      reveal.textContent = 'show the answer';
      reveal.hidden = true;
      row.append(input, unit, check, reveal);
      box.append(row);
      const expected = () => quizAnswer(q.answer.core, new Float32Array(q.answer.args));
      const judge = (text, store) => {
        const given = parseAnswer(text);
        if (!Number.isFinite(given)) {
          box.dataset.answered = 'unreadable';
          feedback.className = 'feedback wrong';
          say(`“${text}” is not a number I can read; type digits, e.g. 0.25.`);
          return;
        }
        let value;
        try {
          value = expected();
        } catch (e) {
          feedback.className = 'feedback wrong';
          say(`This question's answer could not be computed: ${e.message ?? e}`);
          return;
        }
        const correct = Math.abs(given - value) <= q.tolerance;
        verdict(correct, correct
          ? `Right: the core computes ${withUnit(value, q.unit)}. ${q.why}`
          : `Not yet (within ${withUnit(q.tolerance, q.unit)} counts). ${q.hint ?? ''}`);
        reveal.hidden = correct;
        if (store) record(q, text, correct);
      };
      check.addEventListener('click', () => judge(input.value, true));
      input.addEventListener('keydown', (e) => { if (e.key === 'Enter') judge(input.value, true); });
      reveal.addEventListener('click', () => {
        reveal.hidden = true;
        try {
          say(`${said} The core computes ${withUnit(expected(), q.unit)}. ${q.why}`);
        } catch (e) {
          say(`${said} This question's answer could not be computed: ${e.message ?? e}`);
        }
      });
      if (saved[q.id]) {
        input.value = saved[q.id].answer;
        judge(saved[q.id].answer, false);
      }
    }
    if (q.show) {
      const show = document.createElement('button');
      show.type = 'button';
      show.className = 'show-me';
      show.textContent = q.show.label ?? 'show me';
      show.addEventListener('click', () => {
        const missing = [];
        for (const [key, value] of Object.entries(q.show.set ?? {})) {
          const c = findControl(controllers, q.show.figure, key);
          if (c) c.setValue(value);
          else missing.push(key);
        }
        if (missing.length) console.warn(`quiz ${q.id}: no control named ${missing.join(', ')} in #${q.show.figure}`);
        document.getElementById(q.show.figure)?.scrollIntoView({ block: 'start', behavior: 'smooth' });
      });
      box.append(show);
    }
    box.append(feedback);
    section.append(box);
  });
  if (source) source.before(section);
  else main.append(section);
  typeset(section);
  showProgressNotes(section);
  return section;
}

export { showProgressNotes };
