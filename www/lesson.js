// Shared lesson shell: loads the wasm, shows errors, renders formulas, creates figures, runs the
// frame loop, places figure labels, and builds the timeline, plots and "view source" list. Lesson
// pages import it.
import init, { Viewer, buildInfo } from '../pkg/inbetween.js';
// The course module: the grader and the quizzes' answers here, student code in the sandboxes below.
import initCourse, { gradedLessons, quizAnswer, buildInfo as courseBuildInfo } from '../pkg/course.js';
import GUI, { NumberController } from '../vendor/lil-gui/lil-gui.esm.min.js';
// Under `scripts/serve`: reload after a rebuild, show a failed build's errors (idle otherwise).
import './devloop.js';
// The course around the page: navigation, outline, "Check my exercises", the quiz.
import { lessonId, setUpNavigation, addOutline, gradePanel, checkExercises, quiz, scrollToHash, showProgressNotes, typeset } from './course.js';

export { GUI };

// A value typed into a number box that lil-gui cannot take is otherwise dropped in silence: text
// that is not a number keeps the old value, a number outside the slider's range is clamped to it,
// one between the slider's steps (2.5 for a count) goes to the nearest step.
// Every number control of every panel (folders included: they are GUIs too) says so under itself
// until its next accepted value or a change of any other control.
const addControl = GUI.prototype.add;
/** Every control of the page's panels, so that a quiz's "show me" can set one by name. */
const controllers = [];
GUI.prototype.add = function add(...args) {
  const controller = addControl.apply(this, args);
  controllers.push(controller);
  if (controller instanceof NumberController) reportTypedValues(controller);
  else clearTypedNotesOnChange(controller);
  return controller;
};

// lil-gui counts a control's steps from its minimum in floating point, so a box from −2 in steps
// of 0.001 took a typed 0.001 as 0.00099999999999989 (and its note said the value fell between
// steps). The snapped value is rounded to the decimals of the step and of the minimum, where the
// steps lie, so a value on a step is taken as typed.
const snapToStep = NumberController.prototype._snap;
NumberController.prototype._snap = function snap(value) {
  const snapped = snapToStep.call(this, value);
  const digits = Math.max(decimals(this._step), decimals(this._min ?? this._max ?? 0));
  return digits <= 20 && Number.isFinite(snapped) ? Number(snapped.toFixed(digits)) : snapped;
};

/** How many decimals `x` is written with (0.05: 2, 1e-7: 7, 3: 0). */
function decimals(x) {
  if (!Number.isFinite(x)) return 0;
  const [mantissa, exponent] = String(x).toLowerCase().split('e');
  return Math.max(0, (mantissa.split('.')[1] ?? '').length - Number(exponent ?? 0));
}

/** A change of `controller` (a checkbox, a dropdown, a button) clears the page's typed-value notes. */
function clearTypedNotesOnChange(controller) {
  const callOnChange = controller._callOnChange.bind(controller);
  controller._callOnChange = () => {
    for (const open of [...openTypedNotes]) hideTypedNote(open);
    callOnChange();
  };
}

/** What became of `typed` (the number box's text when it was left) in `controller`, whose value
 * lil-gui has already set from it: '' when it was a number within the range, taken as typed,
 * else the sentence saying it was kept, clamped or moved to the nearest step. */
function typedValueNote(controller, typed) {
  const text = typed.trim();
  const value = parseFloat(text);
  const name = controller._name;
  if (Number.isNaN(value)) return `“${text}” is not a number: ${name} stays ${controller.getValue()}.`;
  // lil-gui reads the number at the start of the text ("0.5.5" as 0.5, "3px" as 3).
  if (Number.isNaN(Number(text))) {
    return `“${text}” is not a number; its start was read as ${value}: ${name} is set to ${controller.getValue()}.`;
  }
  const [lo, hi] = [controller._min, controller._max];
  if ((lo !== undefined && value < lo) || (hi !== undefined && value > hi)) {
    // The control took the nearest end of its range; a figure that rejects that too (its note
    // says why) puts the control back, and the sentence says so.
    const end = value < lo ? lo : hi;
    const now = controller.getValue();
    return now === end
      ? `${text} is outside ${lo ?? '−∞'} to ${hi ?? '∞'}: ${name} is set to ${now}.`
      : `${text} is outside ${lo ?? '−∞'} to ${hi ?? '∞'}, and the figure does not take the nearest end, ${end}: ${name} stays ${now}.`;
  }
  // A control with a step (a count's is 1) takes the nearest step to the number typed. (When the
  // figure rejected that value, the control went back and the note goes on to say why.)
  if (controller._stepExplicit) {
    const snapped = controller._snap(value);
    if (snapped !== value && controller.getValue() === snapped) {
      const step = controller._step;
      return step === 1
        ? `${text} is not a whole number: ${name} is set to ${snapped}.`
        : `${text} falls between the control's steps of ${step}: ${name} is set to ${snapped}.`;
    }
  }
  return '';
}

/** The typed-value notes on screen: a change of any control of the page clears them. */
const openTypedNotes = new Set();
/** Each number control's note under it. */
const typedNotes = new WeakMap();

function hideTypedNote(note) {
  note.hidden = true;
  openTypedNotes.delete(note);
}

function reportTypedValues(controller) {
  const note = document.createElement('div');
  note.className = 'typed-note';
  note.setAttribute('role', 'status');
  note.hidden = true;
  controller.domElement.after(note);
  // 'change' comes when the box is left or Enter pressed, before lil-gui's blur handler rewrites
  // the box with the value it took: the typed text is still there.
  typedNotes.set(controller, note);
  controller.$input.addEventListener('change', () => {
    // A new typed value: the other boxes' notes are about earlier edits.
    for (const open of [...openTypedNotes]) if (open !== note) hideTypedNote(open);
    // What the box did with the text, then why the figure refused the value it took (`guarded`).
    const text = controller.$input.value;
    const value = parseFloat(text);
    const tried = controller._clamp(controller._stepExplicit ? controller._snap(value) : value);
    const refused = controller.refused && tried === controller.refused.value ? controller.refused.reason : '';
    note.textContent = sentences(typedValueNote(controller, text), refused);
    if (note.textContent) {
      note.hidden = false;
      openTypedNotes.add(note);
    } else {
      hideTypedNote(note);
    }
  });
  // Typing in the box again means the student is fixing the value: the note has been read.
  controller.$input.addEventListener('input', () => hideTypedNote(note));
  // Any later change made otherwise (a drag of this slider, another control, a preset) clears
  // every note on the page: a note describes the last value typed, not the page's state. The
  // changes made while typing come with the box focused and keep this box's note. (The
  // instance's own _callOnChange, as the page's onChange replaces the callback it calls.)
  const callOnChange = controller._callOnChange.bind(controller);
  controller._callOnChange = () => {
    for (const open of [...openTypedNotes]) {
      if (open !== note || !controller._inputFocused) hideTypedNote(open);
    }
    callOnChange();
  };
}

const state = {
  errors: [], figures: [], frameCallbacks: [], running: true, dead: false,
  /** The last panic message of the figures' own instance (a bug, not student code). */
  panic: null,
  /** Exercises that panicked in the sandbox this page load: name -> message. */
  panickedExercises: {},
  /** The 3D figures' drawing-buffer pixels per device pixel (see `requestedRenderScale`). */
  renderScale: requestedRenderScale(),
  /** Sets `renderScale` and resizes every 3D figure's drawing buffer to it. */
  setRenderScale(scale) {
    state.renderScale = scale;
    for (const figure of state.figures) figure.resize();
  },
};
// For tests and for the curious: what went wrong, which backend each figure uses.
window.__inbetween = state;

/** Shows `message` in the red banner at the top of the page (and keeps it for the tests). */
export function showError(message) {
  const text = String(message?.message ?? message);
  if (state.errors.includes(text)) return; // one line per distinct problem (several figures may fail alike)
  state.errors.push(text);
  let banner = document.getElementById('error-banner');
  if (!banner) {
    banner = document.createElement('div');
    banner.id = 'error-banner';
    banner.setAttribute('role', 'alert');
    document.body.prepend(banner);
  }
  const line = document.createElement('div');
  line.textContent = text;
  banner.append(line);
  // The banner stays at the top of the window (sticky): what is fixed under the header (the
  // contents beside a wide page, www/style.css) moves down by its height.
  document.documentElement.style.setProperty('--banner-height', `${banner.offsetHeight}px`);
}

function installErrorHandlers() {
  window.addEventListener('error', (e) => {
    // Chromium reports this benign layout notice as an error event; it is not a failure.
    if (String(e.message).startsWith('ResizeObserver loop')) return;
    showError(e.error ?? e.message);
  });
  window.addEventListener('unhandledrejection', (e) => showError(e.reason));
}

/** `?backend=webgpu|webgl2|auto` from the page URL. */
export function requestedBackend() {
  return new URLSearchParams(location.search).get('backend') ?? 'auto';
}

/**
 * `?render-scale=S` from the page URL, S in [0.25, 1] (1 otherwise): the 3D figures' drawing
 * buffers get S times the canvas's device pixels in each direction, and the browser scales the
 * image up to the canvas. A software GPU (the tests' SwiftShader) or a slow machine then draws
 * S² of the pixels; what a figure draws (its draw list, its labels) does not change.
 */
function requestedRenderScale() {
  const scale = Number(new URLSearchParams(location.search).get('render-scale') ?? 1);
  return scale >= 0.25 && scale <= 1 ? scale : 1;
}

async function buildSourceView() {
  const list = document.getElementById('source-list');
  if (!list) return;
  const meta = await (await fetch('meta.json')).json();
  for (const file of meta.sources ?? []) {
    const item = document.createElement('details');
    const summary = document.createElement('summary');
    summary.innerHTML = `<code>${file.path}</code> — ${file.what}`;
    const pre = document.createElement('pre');
    item.append(summary, pre);
    item.addEventListener('toggle', async () => {
      if (item.open && !pre.textContent) {
        const response = await fetch(`../../source/${file.path}`);
        pre.textContent = response.ok ? await response.text() : `(could not load ${file.path})`;
      }
    });
    list.append(item);
  }
}

// ---- Student code in its own module instance --------------------------------------------------
//
// A Rust panic on wasm aborts its module instance: every object in it is stuck for good. So the
// page loads two modules (scripts/build): the figures module, where the figures live, and the
// course module (the cores and the exercises, no renderer), whose instances run the student's
// exercises: the *sandbox* (see src/exercises/run.rs and src/web/sandbox.rs). A figure calls
// `__inbetweenSandbox.call(name, args)` with the exercise's arguments as numbers. If the student's
// code panics, only the sandbox traps: we keep the panic message (the panic hook hands it to
// `__inbetweenPanic` before the trap), answer this call and every later call of that exercise with
// it (the figure falls back to the reference and says so beside itself), and swap in a spare
// sandbox, instantiated in advance so the swap is immediate, for the other exercises. Reloading the
// page after fixing the code starts clean. One more instance of the course module, never given
// student code, lists the graded lessons and computes the quizzes' answers.
/** `module`: the compiled course module, shared by the sandboxes and the grading worker. */
const sandbox = { module: null, current: null, spare: null, generation: 0, calling: null, lastPanic: null };
// For the tests and the curious.
state.sandbox = sandbox;

/**
 * A fresh sandbox: a new copy of the JS glue (each import URL is a separate module, with its own
 * instance), instantiated asynchronously (browsers refuse to instantiate large modules
 * synchronously on the main thread).
 */
async function newSandbox() {
  sandbox.generation += 1;
  const glue = await import(`../pkg/course.js?sandbox=${sandbox.generation}`);
  await glue.default({ module_or_path: sandbox.module });
  return glue;
}

/** Swaps in the spare sandbox (ready in advance, so the swap is immediate) and prepares another. */
function replaceSandbox() {
  sandbox.current = sandbox.spare;
  sandbox.spare = null;
  newSandbox().then((glue) => {
    if (sandbox.current) sandbox.spare = glue;
    else sandbox.current = glue;
  }).catch(showError);
}

// A figure's call runs on the page's thread, where nothing can stop an endless loop: the page
// would freeze for good. So the lesson's exercises are graded first in a worker, with the
// panel's time limit per case (www/course.js, `checkExercises`; it starts with the page), and an
// exercise runs in a figure only once it has returned from every case there. One that was stopped
// is never run in the page: its figure says so and uses the reference. (An exercise that returns
// on every grading case and loops only on a figure's input is not caught.)
const exerciseCheck = { done: false, returned: new Set(), stopped: new Map(), refused: false };
state.exerciseCheck = exerciseCheck;

function startExerciseCheck() {
  const id = lessonId();
  if (!gradedLessons().includes(id)) {
    exerciseCheck.done = true;
    return;
  }
  checkExercises(sandbox.module, id, (exercise) => exerciseCheck.returned.add(exercise)).then((result) => {
    if (result instanceof Map) exerciseCheck.stopped = result;
    else console.warn(`inbetween: the exercises could not be checked for endless loops first: ${result.error}`);
    exerciseCheck.done = true;
    // A figure that asked while the check ran showed the reference: its switch is applied again.
    if (exerciseCheck.refused) {
      for (const c of controllers) if (c._name === 'use my exercise' && c.getValue() === true) c._callOnChange();
    }
  }).catch(showError);
}

function callExercise(name, args) {
  const previous = state.panickedExercises[name];
  if (previous) throw { kind: 'panic', message: previous };
  const stopped = exerciseCheck.stopped.get(name);
  if (stopped) throw { kind: 'call', message: stopped };
  if (!exerciseCheck.done && !exerciseCheck.returned.has(name)) {
    exerciseCheck.refused = true;
    throw { kind: 'call', message: 'the page is grading it first (in a worker, where an endless loop can be stopped); the figure runs it once that is done' };
  }
  if (!sandbox.current) throw { kind: 'call', message: 'the exercise sandbox is starting; try again in a moment' };
  sandbox.calling = name;
  sandbox.lastPanic = null;
  try {
    return sandbox.current.runExercise(name, args);
  } catch (e) {
    if (e instanceof WebAssembly.RuntimeError) {
      const message = sandbox.lastPanic ?? String(e);
      state.panickedExercises[name] = message;
      // The hook's message already reads "panicked at file:line: …".
      console.warn(`inbetween: your exercise ${name} ${message.startsWith('panicked') ? message : `panicked: ${message}`}`);
      replaceSandbox();
      throw { kind: 'panic', message };
    }
    const message = String(e?.message ?? e);
    throw { kind: message === 'not-done' ? 'not-done' : 'call', message };
  } finally {
    sandbox.calling = null;
  }
}

/** Called by the Rust panic hook of either instance. True: the panic is the sandbox's, handled. */
// A GPU validation error no call caught (src/render/context.rs): a bug, shown like one.
globalThis.__inbetweenGpuError = (message) => showError(message);
globalThis.__inbetweenPanic = (message) => {
  if (sandbox.calling) {
    sandbox.lastPanic = message;
    return true;
  }
  state.panic = message;
  return false;
};

/** Fetches and compiles a module of dist/pkg/ (`inbetween` or `course`). */
async function compileModule(name) {
  const url = new URL(`../pkg/${name}_bg.wasm`, import.meta.url);
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url.pathname}: HTTP ${response.status}`);
  return WebAssembly.compile(await response.arrayBuffer());
}

async function loadModules() {
  const [figures, course] = await Promise.all([compileModule('inbetween'), compileModule('course')]);
  sandbox.module = course;
  await Promise.all([init({ module_or_path: figures }), initCourse({ module_or_path: course })]);
  [sandbox.current, sandbox.spare] = await Promise.all([newSandbox(), newSandbox()]);
  globalThis.__inbetweenSandbox = { call: callExercise };
  startExerciseCheck();
}

/**
 * Starts a lesson: loads the wasm module (and the sandbox for student code), installs the error
 * banner, renders formulas and the source list. Resolves to an object with `figure(selector)` and
 * `onFrame(callback)`.
 */
export async function startLesson() {
  installErrorHandlers();
  typeset(document.body);
  buildSourceView().catch(showError);
  const navigation = fetch('../catalog.json')
    .then((r) => (r.ok ? r.json() : []))
    .then((catalog) => {
      setUpNavigation(catalog, lessonId());
      return catalog;
    })
    .catch((e) => {
      showError(e);
      return [];
    });
  try {
    await loadModules();
  } catch (e) {
    showError(`Could not load the lesson's WebAssembly module: ${e}`);
    throw e;
  }
  // The two modules' builds; they differ when only the course module was rebuilt (an exercise
  // saved under `scripts/serve`, or the test build whose exercises carry planted bugs).
  const figuresBuild = buildInfo();
  const courseBuild = courseBuildInfo();
  document.getElementById('build-info')?.replaceChildren(
    figuresBuild === courseBuild ? figuresBuild : `${figuresBuild} · exercises: ${courseBuild}`);
  startCourse(navigation).catch(showError);
  styleExerciseNotes();
  document.addEventListener('visibilitychange', () => {
    state.running = !document.hidden;
    if (state.running) requestAnimationFrame(tick);
  });
  requestAnimationFrame(tick);
  return { figure: createFigure, onFrame };
}

/**
 * Calls `callback(dt)` every frame. Given the figure's viewer, only while that figure is on
 * screen (or about to be), once it has drawn its first frame: a simulation out of sight would
 * take the CPU from the figure the student looks at, so its timeline waits where it was.
 */
function onFrame(callback, viewer) {
  const figure = viewer && state.figures.find((f) => f.viewer === viewer);
  const box = figure?.canvas.closest('.figure');
  state.frameCallbacks.push(figure ? (dt) => {
    if (figure.visible || box.dataset.ready !== '1') callback(dt);
  } : callback);
}

/**
 * The course around the page, once the module is there: the grading panel (for a lesson with
 * exercises), the quiz, then the outline of every section and the scroll to the URL's #hash
 * (again once every figure has drawn, as figures above it change the layout while they start).
 */
async function startCourse(navigation) {
  const id = lessonId();
  if (gradedLessons().includes(id)) {
    state.grading = gradePanel(sandbox.module, id);
  }
  // Only a lesson whose folder has a quiz.json asks for it (the catalog says which do).
  const catalog = await navigation;
  if (catalog.find((l) => l.folder === id)?.quizQuestions) {
    await quiz(id, quizAnswer, controllers).catch(showError);
  }
  addOutline();
  showProgressNotes(document.querySelector('main'));
  document.body.dataset.course = 'ready';
  scrollToHash();
  if (location.hash && document.body.dataset.ready !== '1') {
    let scrolled = false;
    window.addEventListener('wheel', () => { scrolled = true; }, { once: true, passive: true });
    window.addEventListener('keydown', () => { scrolled = true; }, { once: true });
    new MutationObserver((_, observer) => {
      if (document.body.dataset.ready !== '1') return;
      observer.disconnect();
      if (!scrolled) scrollToHash();
    }).observe(document.body, { attributes: true, attributeFilter: ['data-ready'] });
  }
}

/**
 * Colours each figure's exercise note by what it says: green when the student's answer matches
 * the reference, red when it differs or panicked (the words come from src/figures/mod.rs).
 */
function styleExerciseNotes() {
  for (const note of document.querySelectorAll('.exercise-note, .note')) {
    const update = () => {
      const text = note.textContent;
      note.classList.toggle('matches', /matches the reference/.test(text) && !/differs|panicked/.test(text));
      note.classList.toggle('differs', /differs|not a rotation|not a unit/.test(text));
      note.classList.toggle('panicked', /panicked/.test(text));
    };
    new MutationObserver(update).observe(note, { childList: true, characterData: true, subtree: true });
    update();
  }
}

let lastMs = null;
function tick(nowMs) {
  if (!state.running || state.dead) {
    lastMs = null;
    return;
  }
  const dt = lastMs === null ? 0 : Math.min((nowMs - lastMs) / 1000, 0.1);
  lastMs = nowMs;
  if (renewLostFigures()) {
    requestAnimationFrame(tick);
    return;
  }
  try {
    for (const cb of state.frameCallbacks) cb(dt);
    for (const figure of state.figures) {
      // Off screen, the labels are placed again only after a resize (they must stay inside the
      // new canvas when it scrolls back into view).
      if (figure.visible || figure.labelsSized !== figure.sizeGeneration()) {
        figure.labelsSized = figure.sizeGeneration();
        figure.placeLabels?.();
      }
    }
  } catch (e) {
    // A panic in the figures' own instance (a bug, never student code: that runs in the sandbox)
    // leaves it unusable: stop drawing rather than flood the banner, and say what happened.
    state.dead = true;
    showError(state.panic ? `The figures stopped: ${state.panic}` : e);
    return;
  }
  requestAnimationFrame(tick);
}

/**
 * The browser can take the page's GPU away (a GPU process reset, a driver update): then no figure
 * draws. While any figure's GPU is lost, the figures' frames stop (their scenes would draw with the
 * lost device), each figure gets a new `Viewer` on its canvas, which makes a new device, and takes
 * its GPU objects (`Viewer.adopt`), and a note at the top of the page says so. Returns true while
 * that goes on.
 */
function renewLostFigures() {
  const lost = state.figures.filter((f) => f.viewer.lost);
  let note = document.getElementById('gpu-reset-note');
  if (!lost.length) {
    note?.remove();
    return false;
  }
  if (!note) {
    note = document.createElement('div');
    note.id = 'gpu-reset-note';
    note.setAttribute('role', 'status');
    note.textContent = 'The browser reset the GPU; the figures are being set up again…';
    document.body.prepend(note);
    state.gpuResets = (state.gpuResets ?? 0) + 1;
  }
  for (const f of lost) {
    f.renewing ??= Viewer.create(f.canvas, f.requested)
      .then((fresh) => f.viewer.adopt(fresh), (e) => {
        note.textContent = `The browser reset the GPU and it could not be set up again (${e.message ?? e}); ` +
          'the page tries again; reloading it may help.';
      })
      .finally(() => { f.renewing = null; });
  }
  return true;
}

/** Probes WebGPU once per page, so that WebGL2-only browsers log "No available adapters" once. */
let webgpuProbe = null;
function webgpuAvailable() {
  webgpuProbe ??= (async () => {
    try {
      return Boolean(navigator.gpu && (await navigator.gpu.requestAdapter()));
    } catch {
      return false;
    }
  })();
  return webgpuProbe;
}

/**
 * An HTML layer over the canvas with one element per label of the viewer's last frame (labels are
 * anchored at 3D points by the scene; the viewer projects them). The shell measures each label's
 * text once and the viewer's layout pass (src/draw/layout.rs) says where each box goes, so that no
 * two overlap and all stay inside the canvas; a label moved away from its anchor gets a leader
 * line, one with no room is hidden. Returns the per-frame updater.
 */
function labelLayer(canvas, viewer, sizeGeneration) {
  const layer = document.createElement('div');
  layer.className = 'labels';
  layer.setAttribute('aria-hidden', 'true');
  canvas.after(layer);
  const leaders = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
  leaders.classList.add('leaders');
  layer.append(leaders);
  // Each text's box in CSS pixels, measured the first time it is shown.
  const sizes = new Map();
  let shown = '';
  return () => {
    const json = viewer.labelsJson();
    // The viewer's own size counts too: the layout keeps labels inside the size it was last told,
    // which can lag the canvas's by a ResizeObserver callback, and an off-screen figure does not
    // redraw (so its labels' json stays the same) when it catches up.
    const key = `${json}|${canvas.clientWidth}x${canvas.clientHeight}|${sizeGeneration()}`;
    if (key === shown) return;
    shown = key;
    const labels = JSON.parse(json);
    layer.style.left = `${canvas.offsetLeft}px`;
    layer.style.top = `${canvas.offsetTop}px`;
    layer.style.width = `${canvas.clientWidth}px`;
    layer.style.height = `${canvas.clientHeight}px`;
    const spans = [...layer.querySelectorAll('span')];
    while (spans.length < labels.length) {
      const span = document.createElement('span');
      layer.append(span);
      spans.push(span);
    }
    if (sizes.size > 1000) sizes.clear(); // texts that change every frame (a clock) come and go
    const measured = [];
    labels.forEach((label, i) => {
      const el = spans[i];
      el.textContent = label.text;
      el.style.color = label.color;
      el.classList.toggle('large', Boolean(label.large));
      el.classList.toggle('inset-title', Boolean(label.title));
      const sizeKey = `${label.large ? 'L' : ''}|${label.text}`;
      let size = sizes.get(sizeKey);
      if (!size) {
        el.hidden = false;
        const r = el.getBoundingClientRect();
        size = [r.width, r.height];
        if (r.width > 0) sizes.set(sizeKey, size);
      }
      measured.push(...size);
    });
    const placed = JSON.parse(viewer.placeLabels(new Float32Array(measured)));
    const lines = [];
    spans.forEach((el, i) => {
      const p = placed[i];
      el.hidden = !p?.shown;
      if (el.hidden) return;
      el.style.transform = `translate(${p.x.toFixed(1)}px, ${p.y.toFixed(1)}px)`;
      if (p.lx !== undefined) {
        lines.push(`<line x1="${p.lx}" y1="${p.ly}" x2="${p.tx}" y2="${p.ty}" stroke="${labels[i].color}"/>`
          + `<circle cx="${p.lx}" cy="${p.ly}" r="2" fill="${labels[i].color}"/>`);
      }
    });
    leaders.innerHTML = lines.join('');
  };
}

/**
 * The figure's "frame all" button (and a double-click on a figure that declares what must stay
 * in view): the camera goes back to the view that fits the figure, keeping the reader's orbit.
 */
function frameAllButton(canvas, viewer) {
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'frame-all';
  button.textContent = '⤢';
  button.title = 'frame all: show the whole figure again (or double-click it)';
  button.setAttribute('aria-label', 'frame all');
  button.addEventListener('click', () => viewer.frameAll());
  canvas.after(button);
  // Only figures that declare their view: a double-click means something else in an editor.
  canvas.addEventListener('dblclick', () => {
    if (viewer.declaresView) viewer.frameAll();
  });
}

/**
 * Creates a live 3D figure on the <canvas> inside the element matched by `selector`:
 * orbit (drag), zoom (wheel, pinch), pan (right- or shift-drag), resize with devicePixelRatio.
 * Resolves to the wasm `Viewer`, or to null when neither WebGPU nor WebGL2 is available (the
 * figure then shows why).
 */
async function createFigure(selector) {
  const box = document.querySelector(selector);
  const canvas = box.querySelector('.stage canvas');
  const badge = document.createElement('span');
  badge.className = 'backend-badge';
  box.append(badge);
  let viewer;
  let backend = requestedBackend();
  try {
    if (backend === 'auto' && !(await webgpuAvailable())) backend = 'auto-no-webgpu';
    viewer = await Viewer.create(canvas, backend);
  } catch (e) {
    const note = document.createElement('div');
    note.className = 'no-gpu';
    note.textContent = `This figure cannot be drawn: ${e.message ?? e}. ` +
      'Try a browser with WebGPU or WebGL2 enabled (recent Chrome, Edge, Firefox or Safari).';
    canvas.replaceWith(note);
    box.dataset.ready = 'no-gpu';
    document.body.dataset.backend = 'none';
    showError(e);
    updateReady();
    return null;
  }
  badge.textContent = viewer.backend;
  badge.title = viewer.adapterName;
  document.body.dataset.backend = viewer.backend;
  attachCameraControls(canvas, viewer);
  frameAllButton(canvas, viewer);
  let resized = 0;
  const resize = () => {
    resized++;
    const r = canvas.getBoundingClientRect();
    const dpr = (window.devicePixelRatio || 1) * state.renderScale;
    canvas.width = Math.max(1, Math.round(r.width * dpr));
    canvas.height = Math.max(1, Math.round(r.height * dpr));
    viewer.resize(r.width, r.height, dpr);
  };
  new ResizeObserver(resize).observe(canvas);
  resize();
  // Off-screen figures keep their frames instead of rendering them (see Viewer::set_visible),
  // and their labels where they were until a resize: placing them reads the canvas's layout,
  // which a note changed by another figure would make the browser compute again, once per
  // figure a frame.
  const figure = {
    selector, backend: viewer.backend, viewer, canvas, requested: backend, resize, visible: true,
    sizeGeneration: () => resized, labelsSized: -1,
    placeLabels: labelLayer(canvas, viewer, () => resized),
  };
  new IntersectionObserver((entries) => {
    try {
      for (const entry of entries) {
        figure.visible = entry.isIntersecting;
        viewer.setVisible(entry.isIntersecting);
      }
    } catch (e) {
      showError(e);
    }
  }, { rootMargin: '100px' }).observe(canvas);
  state.figures.push(figure);
  return viewer;
}

/** Marks a figure as drawn (tests wait for every figure's first frame). */
export function markDrawn(selector) {
  const box = document.querySelector(selector);
  if (box && box.dataset.ready !== '1') {
    box.dataset.ready = '1';
    updateReady();
  }
}

function updateReady() {
  if ([...document.querySelectorAll('.figure')].every((f) => f.dataset.ready)) document.body.dataset.ready = '1';
}

function attachCameraControls(canvas, viewer) {
  const pointers = new Map();
  let pinch = null;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (e) => {
    canvas.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey });
  });
  canvas.addEventListener('pointermove', (e) => {
    const p = pointers.get(e.pointerId);
    if (!p) return;
    const dx = e.clientX - p.x;
    const dy = e.clientY - p.y;
    p.x = e.clientX;
    p.y = e.clientY;
    if (pointers.size === 2) {
      const [a, b] = [...pointers.values()];
      const d = Math.hypot(a.x - b.x, a.y - b.y);
      if (pinch) viewer.zoom(Math.min(Math.max(pinch / d, 0.5), 2));
      pinch = d;
    } else if (p.pan) {
      viewer.pan(dx, dy, canvas.clientHeight);
    } else {
      viewer.orbit(dx, dy);
    }
  });
  const up = (e) => {
    pointers.delete(e.pointerId);
    if (pointers.size < 2) pinch = null;
  };
  canvas.addEventListener('pointerup', up);
  canvas.addEventListener('pointercancel', up);
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    viewer.zoom(Math.exp(Math.max(-1, Math.min(1, e.deltaY * 0.001))));
  }, { passive: false });
}

/**
 * A timeline under a figure: play/pause, a scrub bar over [0, duration) seconds, and a speed menu.
 * `timeline.advance(dt)` moves time forward when playing; `timeline.time` is the current time.
 * `readout(timeline)`, if given, is text the clock shows after the seconds: the parameter the
 * figure reads from the time (lesson 03's "t = 0.50"), so the seconds are not taken for it.
 */
export class Timeline {
  constructor(element, { duration = 1, playing = true, readout = null } = {}) {
    this.duration = duration;
    this.readout = readout;
    this.time = 0;
    this.speed = 1;
    this.playing = playing;
    element.classList.add('timeline');
    element.innerHTML = `
      <button type="button" class="play" aria-label="play or pause"></button>
      <input type="range" class="scrub" min="0" max="1000" value="0" aria-label="time">
      <output class="clock">0.00 s</output>
      <select class="speed" aria-label="speed">
        <option value="0.1">0.1×</option><option value="0.25">0.25×</option>
        <option value="0.5">0.5×</option><option value="1" selected>1×</option><option value="2">2×</option>
      </select>`;
    this.button = element.querySelector('.play');
    this.scrub = element.querySelector('.scrub');
    this.clock = element.querySelector('.clock');
    this.button.addEventListener('click', () => this.setPlaying(!this.playing));
    this.scrub.addEventListener('input', () => {
      this.setPlaying(false);
      this.time = (this.scrub.value / 1000) * this.duration;
      this.show();
    });
    element.querySelector('.speed').addEventListener('change', (e) => { this.speed = Number(e.target.value); });
    this.setPlaying(playing);
    this.show();
  }
  setPlaying(playing) {
    this.playing = playing;
    this.button.textContent = playing ? '❚❚ pause' : '▶ play';
  }
  advance(dt) {
    if (this.playing) {
      this.time = (this.time + dt * this.speed) % this.duration;
      this.show();
    }
    return this.time;
  }
  show() {
    this.scrub.value = String(Math.round((this.time / this.duration) * 1000));
    this.clock.textContent = `${this.time.toFixed(2)} s${this.readout ? ` · ${this.readout(this)}` : ''}`;
  }
}

/**
 * The width inside an element's padding, CSS pixels: what a child may fill. (`clientWidth`
 * includes the padding: a plot that wide would overflow `.plot`'s right padding and the
 * figure's `overflow: hidden` would cut off its last x tick label, e.g. "1,60" for 1,600.)
 */
function contentWidth(element) {
  const style = getComputedStyle(element);
  return Math.max(0, Math.floor(element.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight)));
}

/**
 * A line plot (uPlot) of curves against time or a parameter.
 *   new Plot(element, { title, xLabel: 'time (s)', yLabel: 'height (m)', series: ['a', 'b'],
 *                       colors: ['#d62728', …], minSpan: 0.1, height: 180 })
 * `setData([xs, ys1, ys2…])` replaces the curves; `setCursor(x)` draws a vertical playhead at `x`
 * (call it every frame with the timeline's time; `null` hides it). Every y axis is labelled with its
 * quantity and unit; the y range is never smaller than `minSpan`, so a constant signal is not
 * autoscaled onto float noise. `yRange: [lo, hi]` fixes it instead (a percentage read against 0);
 * `setYRange([lo, hi])` sets the data range to show later (padded as autoscaling pads it; `null`
 * autoscales again), for a figure whose Rust side says which samples the scale should follow.
 * `from0: true` starts an autoscaled y axis at 0, for a magnitude (a speed, an angle between two
 * directions, a distance): its smallest values read against a 0 tick, and a flat 0 sits on the
 * axis's bottom instead of in its middle.
 * `points: false` never marks the samples with dots (`true` always; uPlot decides by default).
 * `yStep: 1` puts the y range's ends on labelled ticks, multiples of 1, 2, 10, 20, 100 or 200
 * times yStep (at most 4 ticks apart), so a flat line near an end still has a tick beyond it.
 * `log: 'xy'` makes both axes logarithmic (`'x'` or `'y'` one of them; the data must be positive).
 * `widths: [5, 1.5]` sets each series' line width in CSS pixels (default 2) and `dashes:
 * [null, [6, 4]]` its dash pattern (dash and gap lengths; `null` solid): a wide line under a
 * narrow one keeps two equal curves both visible. Each legend swatch is a short stretch of its
 * curve (colour, width, dashes). The element gets `data-plot` (the title), `data-x-label`
 * and `data-y-label` (the axis labels, which uPlot draws on its canvas, where tests cannot
 * read them), `data-y-range` (the y axis's range, "lo hi"; a log x axis's in `data-x-range`),
 * `data-y-labels` (the y axis's numbers), `data-y-label-gap` (the least room between two, px)
 * and `data-x-last` (the last x where a curve has a value).
 */
export class Plot {
  constructor(element, {
    title, xLabel, yLabel, series, colors = PLOT_COLORS, height = 180, minSpan = 1e-3, yRange = null,
    widths = [], dashes = [], log = '', points, yStep = null, from0 = false,
  }) {
    if (!yLabel) console.warn(`Plot "${title}": give the y axis a label with its quantity and unit`);
    // The y label is drawn along the plot area and clipped at the canvas: make the plot tall
    // enough for it (about 110 px of the default height are title, x axis and its label).
    height = Math.max(height, Math.ceil(textWidth(yLabel ?? '', '600 12px system-ui')) + 110);
    this.cursor = null;
    this.dataRange = null;
    // With `yStep`, the y ticks' steps: each divides the next, so a range whose ends are ticks of
    // one step has them as ticks of any smaller step uPlot picks.
    const yIncrs = yStep ? [1, 2, 10, 20, 100, 200].map((k) => k * yStep) : null;
    const cursorLine = (u) => {
      if (this.cursor === null || !Number.isFinite(this.cursor)) return;
      const x = u.valToPos(this.cursor, 'x', true);
      if (x < u.bbox.left || x > u.bbox.left + u.bbox.width) return;
      const ctx = u.ctx;
      ctx.save();
      ctx.strokeStyle = '#1f2430';
      ctx.lineWidth = 1.5 * devicePixelRatio;
      ctx.setLineDash([4 * devicePixelRatio, 3 * devicePixelRatio]);
      ctx.beginPath();
      ctx.moveTo(x, u.bbox.top);
      ctx.lineTo(x, u.bbox.top + u.bbox.height);
      ctx.stroke();
      ctx.restore();
    };
    this.plot = new window.uPlot({
      title,
      width: contentWidth(element) || 560,
      height,
      // `log: 'x'`, `'y'` or `'xy'`: those axes are logarithmic (base 10; y shows whole decades,
      // x the data's span: uPlot's own log range rounds the top up to a multiple of the next power
      // of ten, so a sweep ending at 3,200 would run to 10,000; one point or none gets its decade).
      scales: {
        x: log.includes('x') ? {
          time: false,
          distr: 3,
          log: 10,
          // The low end goes down to a whole multiple of its power of ten (250 to 200): uPlot's
          // log ticks start at the range's low end and step by that power, so 250 would put them
          // at 250, 350, ..., 1050, 2100, none of them a round number to label.
          range: (u, lo, hi) => {
            const p = 10 ** Math.floor(Math.log10(lo) + 1e-9);
            const r = lo > 0 && hi > lo
              ? [Math.floor(lo / p + 1e-9) * p, hi]
              : window.uPlot.rangeLog(lo || 1, hi || 10, 10, false);
            element.dataset.xRange = r.join(' ');
            return r;
          },
        } : { time: false, range: xRange },
        y: log.includes('y') ? {
          distr: 3,
          log: 10,
          // No data yet (a sweep just started, a run at its still first sample): the decade 1
          // to 10, as the x axis, not a range of 0 to 0 without a number.
          range: (u, lo, hi) => {
            const r = window.uPlot.rangeLog(lo || 1, hi || 10, 10, true);
            element.dataset.yRange = r.join(' ');
            return r;
          },
        } : {
          range: (u, lo, hi) => {
            let r = yRange ?? (this.dataRange
              ? paddedRange(this.dataRange[0], this.dataRange[1], minSpan)
              : paddedRange(lo, hi, minSpan));
            if (from0 && !yRange) r = [0, Math.max(r[1], minSpan)];
            if (yStep) {
              // Out to whole ticks, at most 4 apart: no line lies past the last labelled one.
              const ends = (i) => [Math.floor(r[0] / i) * i, Math.ceil(r[1] / i) * i];
              const step = yIncrs.find((i) => { const [a, b] = ends(i); return b - a <= 4 * i; }) ?? yIncrs.at(-1);
              r = ends(step);
            }
            element.dataset.yRange = r.join(' ');
            return r;
          },
        },
      },
      // Small label fonts: a y label such as "angle about x (°)" must fit a 160 px tall plot.
      axes: [
        {
          label: xLabel, labelFont: '600 12px system-ui', font: '11px system-ui', labelSize: 22,
          ...(log.includes('x') ? { values: logTicks, filter: (u, splits) => splits } : {}),
        },
        // A short plot keeps room for four ticks: uPlot's 30 px between y ticks would leave a plot
        // 80 px tall with a 2 J range one tick (incr 1 J) and no sense of scale.
        {
          label: yLabel, labelFont: '600 12px system-ui', font: '11px system-ui', labelSize: 22, size: 56,
          space: (u, i, min, max, dim) => Math.min(30, Math.max(16, dim / 4)),
          ...(log.includes('y') ? { values: logTicks, filter: (u, splits) => splits } : {}),
          ...(yStep ? { incrs: yIncrs } : {}),
        },
      ],
      // Series names only: a live legend shows "--" for every value until the pointer hovers.
      legend: { live: false },
      series: [{ label: xLabel }, ...series.map((label, i) => ({
        label,
        stroke: colors[i % colors.length],
        width: widths[i] ?? 2,
        // Curves at sub-pixel positions (uPlot rounds a series' points to whole pixels by default,
        // which draws a sloping or almost flat curve as a staircase of 1 px steps); the grid and
        // ticks stay on whole pixels, crisp.
        pxAlign: 0,
        // uPlot scales a width by the pixel ratio but draws a dash pattern in canvas pixels.
        ...(dashes[i] ? { dash: dashes[i].map((d) => d * devicePixelRatio) } : {}),
        // `points: false`: no dots on the samples (uPlot draws them while few samples are in
        // view, which hides a dashed guide's dashes); `true`: always.
        ...(points === undefined ? {} : { points: { show: points } }),
      }))],
      // Hovering one plot of a figure shows the same x in all of them (uPlot's cursor sync,
      // keyed by the figure) and each plot's readout reads its curves' values there.
      cursor: {
        ...(element.closest('.figure')?.id ? { sync: { key: `plots-${element.closest('.figure').id}`, setSeries: false } } : {}),
        points: { size: 7 },
      },
      // After each draw, how many numbers the y axis shows (the page test asks for two or more).
      hooks: {
        draw: [cursorLine, (u) => {
          const shown = (i) => u.axes[i]._values?.filter((v) => v !== '' && v != null).length ?? 0;
          element.dataset.yTicks = shown(1);
          element.dataset.xTicks = shown(0);
          // The y numbers and the least room between two of them (px): for the tests.
          const y = u.axes[1];
          const at = (y._splits ?? []).filter((v, i) => y._values?.[i]).map((v) => u.valToPos(v, 'y'));
          element.dataset.yLabels = (y._values ?? []).filter(Boolean).join(' ');
          element.dataset.yLabelGap = Math.min(...at.slice(1).map((p, i) => Math.abs(p - at[i])));
        }],
        setCursor: [(u) => this.showReadout(u)],
      },
    }, [[0], ...series.map(() => [0])], element);
    // Each legend swatch is a stretch of its curve, 28 px long: the series' colour, its width (3
    // to 7 px, so a thin line's colour still reads) and its dash pattern. A colour may be a
    // function (a stroke that changes with the figure's state): the swatch takes its colour now,
    // and the page repaints it (`marker.style.background`) when the state changes.
    element.querySelectorAll('.u-legend .u-marker').forEach((marker, i) => {
      const stroke = colors[i % colors.length];
      const color = typeof stroke === 'function' ? stroke() : stroke;
      const dash = dashes[i];
      Object.assign(marker.style, {
        width: '28px',
        height: `${Math.min(7, Math.max(3, widths[i] ?? 2))}px`,
        border: 'none',
        background: dash
          ? `repeating-linear-gradient(90deg, ${color} 0 ${dash[0]}px, transparent ${dash[0]}px ${dash[0] + dash[1]}px)`
          : color,
      });
    });
    // The readout covers the legend while the pointer is on a plot, so it never moves the page.
    this.readout = document.createElement('div');
    this.readout.className = 'plot-readout';
    this.readout.hidden = true;
    element.append(this.readout);
    this.xLabel = xLabel ?? 'x';
    this.colors = colors;
    this.element = element;
    element.dataset.plot = title ?? '';
    element.dataset.xLabel = xLabel ?? '';
    element.dataset.yLabel = yLabel ?? '';
    let width = contentWidth(element);
    new ResizeObserver(() => requestAnimationFrame(() => {
      if (contentWidth(element) !== width) {
        width = contentWidth(element);
        this.plot.setSize({ width, height });
      }
    })).observe(element);
  }
  setData(columns) {
    this.plot.setData(columns);
    // For the page tests: the last x at which a curve has a value (a playing figure's curves
    // must reach its playhead).
    let i = columns[0].length - 1;
    while (i >= 0 && columns.slice(1).every((c) => c[i] === null || c[i] === undefined)) i--;
    this.element.dataset.xLast = i >= 0 ? String(columns[0][i]) : '';
  }
  /** Names series `i` (from 0, as in `series`) in the legend; an empty name hides its entry.
   * (The legend has no row for x: it is not live.) */
  setSeriesLabel(i, label) {
    const row = this.plot.root.querySelectorAll('.u-legend .u-series')[i];
    if (row) {
      row.querySelector('.u-label').textContent = label;
      row.style.display = label ? '' : 'none';
    }
  }
  /** Replaces the title shown over the plot (its `data-plot` name stays). */
  setTitle(title) {
    this.plot.root.querySelector('.u-title').textContent = title;
  }
  /** Shows the data range `[lo, hi]` (both finite) from the next `setData` on; else autoscales. */
  setYRange(range) {
    this.dataRange = range && range.every(Number.isFinite) ? range : null;
  }
  /** Writes the values under the pointer (this plot's or a synced plot's) into the readout;
   * hides it when the pointer leaves. */
  showReadout(u) {
    const i = u.cursor.idx;
    const x = i === null || i === undefined ? undefined : u.data[0][i];
    const legend = (this.legend ??= u.root.querySelector('.u-legend'));
    if (x === undefined) {
      this.readout.hidden = true;
      if (legend) legend.style.visibility = '';
      return;
    }
    // In the legend's place (same names, now with values).
    if (legend) {
      legend.style.visibility = 'hidden';
      this.readout.style.top = `${legend.offsetTop}px`;
      this.readout.style.bottom = 'auto';
      this.readout.style.minHeight = `${legend.offsetHeight}px`;
    }
    const fmt = (v) => (Number.isFinite(v) ? Number(v.toPrecision(3)).toString() : '–');
    const span = (text, color) => {
      const el = document.createElement('span');
      el.textContent = text;
      if (color) el.style.color = typeof color === 'function' ? color() : color;
      return el;
    };
    const parts = [span(`${this.xLabel} = ${fmt(x)}`)];
    u.series.forEach((s, k) => {
      if (k > 0 && s.show) parts.push(span(`${s.label}: ${fmt(u.data[k][i])}`, this.colors[(k - 1) % this.colors.length]));
    });
    this.readout.replaceChildren(...parts);
    this.readout.hidden = false;
  }
  /** Moves the playhead to `x` (in the x axis's unit); redraws only when it moved. */
  setCursor(x) {
    if (x === this.cursor) return;
    this.cursor = x;
    this.plot.redraw(false, false);
  }
}

/** Width in CSS pixels of `text` drawn in `font`. */
function textWidth(text, font) {
  const ctx = (textWidth.canvas ??= document.createElement('canvas')).getContext('2d');
  ctx.font = font;
  return ctx.measureText(text).width;
}

/** The palette of www/palette.css, in the order plots use it. */
export const PLOT_COLORS = ['#1f6fd6', '#d62728', '#2ca02c', '#944fc9', '#e68a00', '#17a2a8', '#e35d9c', '#8c564b'];

/** Tick labels of a log axis (uPlot's own filter, which keeps every few powers of ten counted
 * from the top, is off): the powers of ten, every few where a decade is shorter than a label
 * (counted from 10⁰, so 1 is labelled whenever it is in range), and, where a decade is long
 * enough that their labels keep clear of the powers beside them (2 and 5 lie 0.3 of a decade from
 * 1 and 10), their 2 and 5 multiples; other ticks blank. One notation an axis: plain numbers
 * ("0.01", "200") while every power in range lies from 0.01 to 10,000, else powers of ten
 * ("10⁻⁶", "2×10³"), so an axis never reads "1e5, 1000, 10". */
function logTicks(u, splits, axisIdx) {
  const axis = u.axes[axisIdx];
  const parts = splits.map((v) => {
    if (!(v > 0)) return null;
    const k = Math.floor(Math.log10(v) + 1e-9);
    const m = Math.round(v / 10 ** k);
    return Math.abs(v / 10 ** k - m) > 1e-6 * m ? null : { m, k };
  });
  const plain = parts.every((p) => !p || (p.k >= -2 && p.k <= 4));
  const power = (k) => `10${k < 0 ? '⁻' : ''}${[...String(Math.abs(k))].map((d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[d]).join('')}`;
  const labels = parts.map((p) => p && {
    ...p,
    text: plain ? String(Number((p.m * 10 ** p.k).toPrecision(1))) : `${p.m === 1 ? '' : `${p.m}×`}${power(p.k)}`,
  });
  const decadePx = Math.abs(u.valToPos(10, axis.scale) - u.valToPos(1, axis.scale));
  // A label needs its width (x) or its height (y) and a gap.
  const room = axis.side % 2 === 0
    ? Math.max(0, ...labels.map((l) => (l ? textWidth(l.text, '11px system-ui') : 0))) + 8
    : 16;
  const shown = Math.log10(2) * decadePx >= room ? [1, 2, 5] : [1];
  const every = Math.ceil(room / Math.max(decadePx, 1));
  return labels.map((l) => (l && shown.includes(l.m) && l.k % every === 0 ? l.text : ''));
}

/** The x range: the data's, but one point (a series just started, one measurement so far) gets
 * 10 % of its value either side (0 to 1 at 0) and none 0 to 1, where uPlot shows 0 to 100. */
function xRange(u, lo, hi) {
  const xs = u.data?.[0] ?? [];
  if (xs.length > 1 && xs[0] !== xs[xs.length - 1]) return [lo, hi];
  const x = Number.isFinite(xs[0]) ? xs[0] : 0;
  return x === 0 ? [0, 1] : [x - 0.1 * Math.abs(x), x + 0.1 * Math.abs(x)];
}

/** The y range for data in [lo, hi]: at least `minSpan` tall, padded by 5 %. */
export function paddedRange(lo, hi, minSpan) {
  if (!Number.isFinite(lo) || !Number.isFinite(hi)) return [0, 1];
  if (hi - lo < minSpan) {
    const mid = (lo + hi) / 2;
    lo = mid - minSpan / 2;
    hi = mid + minSpan / 2;
  }
  const pad = (hi - lo) * 0.05;
  return [lo - pad, hi + pad];
}

/** Sets a note element to `parts` joined by spaces (empty parts dropped), touching the DOM only
 * when the text changed. */
/**
 * Dragging something in a figure's 3D canvas with the mouse (a target, a particle): listeners
 * in the capture phase on the canvas's stage run before the canvas's orbit controls, and take a
 * press only when `grab(x, y, width, height)` (canvas pixels; Rust decides) says the pointer is
 * on the thing. Then each move calls `drag(x, y, width, height)` and the release `release()`.
 * With `hover`, the canvas gets the class `over-target` while the pointer is over it.
 */
export function dragInCanvas(canvas, { grab, drag, release = () => {}, hover = null }) {
  const stage = canvas.parentElement;
  const local = (e) => {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top, r.width, r.height];
  };
  let dragging = null;
  stage.addEventListener('pointerdown', (e) => {
    if (e.target !== canvas || e.button !== 0 || e.shiftKey) return;
    if (!grab(...local(e))) return;
    e.stopPropagation();
    dragging = e.pointerId;
    canvas.setPointerCapture(e.pointerId);
    canvas.classList.add('dragging');
  }, { capture: true });
  stage.addEventListener('pointermove', (e) => {
    if (dragging === null) {
      if (hover && e.target === canvas) canvas.classList.toggle('over-target', hover(...local(e)));
      return;
    }
    if (e.pointerId !== dragging) return;
    e.stopPropagation();
    drag(...local(e));
  }, { capture: true });
  const end = (e) => {
    if (e.pointerId !== dragging) return;
    e.stopPropagation();
    dragging = null;
    release();
    canvas.classList.remove('dragging');
  };
  stage.addEventListener('pointerup', end, { capture: true });
  stage.addEventListener('pointercancel', end, { capture: true });
}

/** Parts of a note (a rejected setting's message, the figure's own note) as one text, each part
 * a sentence: a part without a full stop, question or exclamation mark at its end gets a full stop. */
export function sentences(...parts) {
  return parts.filter(Boolean).map((s) => (/[.!?]$/.test(s.trim()) ? s : `${s}.`)).join(' ');
}

export function showNote(element, ...parts) {
  const text = parts.filter(Boolean).join(' ');
  if (element.textContent !== text) element.textContent = text;
}

/** The value of a CSS custom property of the page (the palette in www/palette.css), or undefined. */
export function cssVar(name) {
  return getComputedStyle(document.documentElement).getPropertyValue(name).trim() || undefined;
}

/**
 * Wraps a figure's `apply` (which passes the panel's values `p` to the scene) for a lil-gui
 * `onChange`: a value the core rejects is put back to the last accepted one and the panel
 * redrawn. The reason goes under the number box that changed, as a typed value's note does (at
 * once after a drag, when the box is left after typing), or else to `onReject`; `onReject` gets
 * an empty string otherwise.
 */
export function guarded(gui, p, apply, onReject) {
  let accepted = { ...p };
  return (change) => {
    const controller = change?.controller;
    const note = typedNotes.get(controller);
    if (note) controller.refused = null;
    try {
      apply();
      accepted = { ...p };
      onReject('');
    } catch (e) {
      const reason = `Not changed: ${e.message ?? e}`;
      if (note) {
        controller.refused = { value: change.value, reason };
        if (!controller._inputFocused) {
          note.textContent = sentences(reason);
          note.hidden = false;
          openTypedNotes.add(note);
        }
      }
      onReject(note ? '' : reason);
      Object.assign(p, accepted);
      gui.controllersRecursive().forEach((c) => c.updateDisplay());
      apply();
    }
  };
}

/**
 * Takes the next timing of a step-time sweep kept in Rust (`scene.sweepNext()` names the search
 * to time, "" when the sweep is done; `scene.timingStep(search)` is one step; `scene.sweepRecord(ms)`
 * records milliseconds per step). The page's clock ticks in 0.1 ms (performance.now() is
 * coarsened without cross-origin isolation) and a small step takes less, so a timing repeats the
 * step for at least 2 ms, at most `maxRepeats` times. Returns whether a timing was recorded.
 */
export function timeSweepStep(scene, maxRepeats) {
  const search = scene.sweepNext();
  if (!search) return false;
  let k = 0;
  let elapsed = 0;
  const t0 = performance.now();
  do {
    scene.timingStep(search);
    k++;
    elapsed = performance.now() - t0;
  } while (elapsed < 2 && k < maxRepeats);
  scene.sweepRecord(elapsed / k);
  return true;
}

/** Splits `[a0, b0, c0, a1, b1, c1, …]` (a binding's flat samples) into columns `[[a…], [b…], [c…]]`. */
export function columns(flat, width) {
  const cols = Array.from({ length: width }, () => []);
  for (let i = 0; i < flat.length; i += width) for (let k = 0; k < width; k++) cols[k].push(flat[i + k]);
  return cols;
}

/**
 * Pads a live plot's columns (`cols[0]` the times, sorted) with empty rows so that its x axis
 * spans the whole timeline, 0 to `duration`: a row at 0 when the samples start later (a run
 * restarted after a scrub) or there are none, and one at `duration` after the last sample. A
 * plot with one sample would otherwise span a few tenths of a second about it and read as empty.
 */
export function spanTimeline(cols, duration) {
  const pad = (at, x) => cols.forEach((c, k) => c.splice(at, 0, k === 0 ? x : null));
  if (!(cols[0][0] <= 0)) pad(0, 0);
  if (cols[0][cols[0].length - 1] < duration) pad(cols[0].length, duration);
  return cols;
}

/** A timeline's time as t in [0, 1] going there and back, so a looping interpolation never jumps. */
export function pingPong(timeline) {
  return 1 - Math.abs(2 * (timeline.time / timeline.duration) - 1);
}

/** Formats a column-major n×n matrix (9 or 16 numbers) into the rows of an HTML table element. */
export function showMatrix(table, cols) {
  const n = Math.round(Math.sqrt(cols.length));
  const idx = [...Array(n).keys()];
  const rows = idx.map((r) => idx.map((c) => cols[c * n + r]));
  table.innerHTML = rows
    .map((row) => `<tr>${row.map((v) => `<td>${(Math.abs(v) < 5e-4 ? 0 : v).toFixed(3)}</td>`).join('')}</tr>`)
    .join('');
}
