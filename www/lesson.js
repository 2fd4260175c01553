// Shared lesson shell: loads the wasm, shows errors, renders formulas, creates figures, runs the
// frame loop, and builds the timeline, plots and "view source" list. Lesson pages import it.
import init, { Viewer, buildInfo } from '../pkg/inbetween.js';
import GUI from '../vendor/lil-gui/lil-gui.esm.min.js';

export { GUI };

const state = { errors: [], figures: [], frameCallbacks: [], running: true, dead: false };
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

function renderMath() {
  if (window.renderMathInElement) {
    window.renderMathInElement(document.body, {
      delimiters: [
        { left: '$$', right: '$$', display: true },
        { left: '\\(', right: '\\)', display: false },
      ],
      throwOnError: false,
    });
  }
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

/**
 * Starts a lesson: loads the wasm module, installs the error banner, renders formulas and the
 * source list. Resolves to an object with `figure(selector)` and `onFrame(callback)`.
 */
export async function startLesson() {
  installErrorHandlers();
  renderMath();
  buildSourceView().catch(showError);
  try {
    await init();
  } catch (e) {
    showError(`Could not load the lesson's WebAssembly module: ${e}`);
    throw e;
  }
  document.getElementById('build-info')?.replaceChildren(buildInfo());
  document.addEventListener('visibilitychange', () => {
    state.running = !document.hidden;
    if (state.running) requestAnimationFrame(tick);
  });
  requestAnimationFrame(tick);
  return { figure: createFigure, onFrame: (cb) => state.frameCallbacks.push(cb) };
}

let lastMs = null;
function tick(nowMs) {
  if (!state.running || state.dead) {
    lastMs = null;
    return;
  }
  const dt = lastMs === null ? 0 : Math.min((nowMs - lastMs) / 1000, 0.1);
  lastMs = nowMs;
  try {
    for (const cb of state.frameCallbacks) cb(dt);
  } catch (e) {
    // A panic leaves the wasm module unusable: stop drawing rather than flood the banner.
    state.dead = true;
    showError(e);
    return;
  }
  requestAnimationFrame(tick);
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
  try {
    viewer = await Viewer.create(canvas, requestedBackend());
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
  const resize = () => {
    const r = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, Math.round(r.width * dpr));
    canvas.height = Math.max(1, Math.round(r.height * dpr));
    viewer.resize(r.width, r.height, dpr);
  };
  new ResizeObserver(resize).observe(canvas);
  resize();
  state.figures.push({ selector, backend: viewer.backend });
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
 */
export class Timeline {
  constructor(element, { duration = 1, playing = true } = {}) {
    this.duration = duration;
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
    this.clock.textContent = `${this.time.toFixed(2)} s`;
  }
}

/**
 * A line plot of curves over time (uPlot). `series` names the curves, `colors` (optional) matches
 * them to the figure's colours; `setData([xs, ys1, ys2…])`.
 * A vertical cursor can follow the timeline with `setCursor(x)`.
 */
export class Plot {
  constructor(element, { title, xLabel, series, colors = ['#2563eb', '#dc2626', '#059669', '#9333ea'], height = 180 }) {
    this.plot = new window.uPlot({
      title,
      width: element.clientWidth || 560,
      height,
      scales: { x: { time: false } },
      axes: [{ label: xLabel }, {}],
      series: [{ label: xLabel }, ...series.map((label, i) => ({ label, stroke: colors[i % colors.length], width: 2 }))],
    }, [[0], ...series.map(() => [0])], element);
    let width = element.clientWidth;
    new ResizeObserver(() => requestAnimationFrame(() => {
      if (element.clientWidth !== width) {
        width = element.clientWidth;
        this.plot.setSize({ width, height });
      }
    })).observe(element);
  }
  setData(columns) {
    this.plot.setData(columns);
  }
}

/** Splits `[a0, b0, c0, a1, b1, c1, …]` (a binding's flat samples) into columns `[[a…], [b…], [c…]]`. */
export function columns(flat, width) {
  const cols = Array.from({ length: width }, () => []);
  for (let i = 0; i < flat.length; i += width) for (let k = 0; k < width; k++) cols[k].push(flat[i + k]);
  return cols;
}

/** A timeline's time as t in [0, 1] going there and back, so a looping interpolation never jumps. */
export function pingPong(timeline) {
  return 1 - Math.abs(2 * (timeline.time / timeline.duration) - 1);
}

/** Formats a column-major 4×4 matrix into the rows of an HTML table element. */
export function showMatrix(table, cols) {
  const rows = [0, 1, 2, 3].map((r) => [0, 1, 2, 3].map((c) => cols[c * 4 + r]));
  table.innerHTML = rows
    .map((row) => `<tr>${row.map((v) => `<td>${(Math.abs(v) < 5e-5 ? 0 : v).toFixed(3)}</td>`).join('')}</tr>`)
    .join('');
}
