// Lesson 02: wires the curve editor, the controls, the plots and the figures to the wasm scenes.
// No interpolation here: JavaScript only draws what Rust sampled and forwards the mouse edits.
import { startLesson, markDrawn, Timeline, Plot, GUI } from '../../www/lesson.js';
import { KeyframesScene, LagrangeScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// ---- Figure 1: curve editor + 3D view + plots. ----
const keysViewer = await lesson.figure('#fig-keys');
if (keysViewer) {
  keysViewer.setCamera(0, 1.0, 0, 6.8, 0.35, 0.22);
  const scene = new KeyframesScene();
  const timeline = new Timeline(document.getElementById('keys-timeline'), { duration: scene.durationSec });
  const message = document.getElementById('keys-message');
  const note = document.getElementById('keys-note');
  const p = { scheme: 'cardinal', tension: 1, ghosts: 24, arcLength: false, ease: 'none', useExercise: false };
  const schemes = {
    step: 'step', linear: 'linear', 'Lagrange (global)': 'lagrange', 'Hermite (your handles)': 'hermite',
    'cardinal (tension μ)': 'cardinal', 'natural (C2)': 'natural', 'centripetal Catmull-Rom': 'centripetal',
  };
  const eases = {
    none: 'none', smoothstep: 'smoothstep', smootherstep: 'smootherstep', sine: 'sine',
    'ease in (t²)': 'in', 'ease out': 'out', 'ease in-out (cubic)': 'inout',
  };
  const gui = new GUI({ container: document.querySelector('#fig-keys .panel'), title: 'Keyframes' });
  const schemeControl = gui.add(p, 'scheme', schemes).name('scheme').onChange((v) => edit(() => scene.setScheme(v)));
  gui.add(p, 'tension', 0, 2, 0.01).name('tension μ (cardinal)').onChange((v) => edit(() => scene.setTension(v)));
  gui.add(p, 'ghosts', 2, 60, 1).name('in-betweens').onChange((v) => edit(() => scene.setGhostCount(v)));
  gui.add(p, 'arcLength').name('constant speed (arc length)').onChange((v) => edit(() => scene.setArcLength(v)));
  gui.add(p, 'ease', eases).name('ease (slow in / out)').onChange((v) => edit(() => scene.setEase(v)));
  gui.add(p, 'useExercise').name('use my exercise').onChange((v) => edit(() => scene.setUseExercise(v)));

  const speedPlot = new Plot(document.getElementById('keys-speed'), {
    title: 'Speed |p′(t)|', xLabel: 'time (s)', series: ['keyed (m/s)', 'arc length (m/s)'],
  });
  const accelPlot = new Plot(document.getElementById('keys-accel'), {
    title: 'Acceleration |p″(t)| of the motion shown', xLabel: 'time (s)', series: ['|p″| (m/s²)'],
  });

  // What the editor draws, re-sampled from Rust after every edit.
  const editor = { path: [], ghosts: [], keys: [], tangents: [] };
  function refresh() {
    editor.path = scene.samplePath(300);
    editor.ghosts = scene.sampleGhosts();
    editor.keys = scene.keys();
    editor.tangents = scene.tangents();
    timeline.duration = scene.durationSec;
    timeline.time %= timeline.duration;
    timeline.show();
    const rows = scene.sampleMotion(400);
    const cols = [[], [], [], []];
    for (let i = 0; i < rows.length; i += 4) for (let c = 0; c < 4; c++) cols[c].push(rows[i + c]);
    speedPlot.setData(cols.slice(0, 3));
    accelPlot.setData([cols[0], cols[3]]);
    if (scene.scheme !== p.scheme) {
      p.scheme = scene.scheme;
      schemeControl.updateDisplay();
    }
  }
  /** Runs an edit; a rejected edit (the core's validation message) is shown under the editor. */
  function edit(action) {
    try {
      action();
      message.textContent = '';
    } catch (e) {
      message.textContent = `Edit rejected: ${e.message ?? e}`;
    }
    refresh();
  }

  const canvas = document.querySelector('#fig-keys .editor canvas');
  const ctx = canvas.getContext('2d');
  const STRIP = 46; // height of the time strip, CSS pixels
  const view = { x0: -3.3, x1: 3.3, y0: -0.5, y1: 2.7 };
  let size = { w: 1, h: 1, scale: 1, ox: 0, oy: 0 };
  function layout() {
    const r = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, Math.round(r.width * dpr));
    canvas.height = Math.max(1, Math.round(r.height * dpr));
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const h = r.height - STRIP;
    const scale = Math.min(r.width / (view.x1 - view.x0), h / (view.y1 - view.y0));
    size = { w: r.width, h: r.height, scale, ox: r.width / 2 - scale * (view.x0 + view.x1) / 2, oy: h / 2 + scale * (view.y0 + view.y1) / 2 };
  }
  new ResizeObserver(layout).observe(canvas);
  layout();
  const toPx = (x, y) => [size.ox + x * size.scale, size.oy - y * size.scale];
  const toWorld = (px, py) => [(px - size.ox) / size.scale, (size.oy - py) / size.scale];
  // The time strip spans [tMin, tMax] seconds.
  const timeSpan = () => {
    const t = editor.keys;
    const first = Math.min(0, t[0]);
    return [first, Math.max(first + 1, t[t.length - 3] + 0.6)];
  };
  const timeToPx = (t) => { const [a, b] = timeSpan(); return 16 + ((t - a) / (b - a)) * (size.w - 32); };
  const pxToTime = (px) => { const [a, b] = timeSpan(); return a + ((px - 16) / (size.w - 32)) * (b - a); };
  const keyCount = () => editor.keys.length / 3;
  const isCubic = () => ['hermite', 'cardinal', 'natural', 'centripetal'].includes(scene.scheme);

  function draw(timeSec) {
    const { w, h } = size;
    ctx.clearRect(0, 0, w, h);
    // Grid every half metre, axes darker.
    ctx.lineWidth = 1;
    for (let x = Math.ceil(view.x0 * 2) / 2; x <= view.x1; x += 0.5) {
      const [px] = toPx(x, 0);
      ctx.strokeStyle = x === 0 ? '#c9ccd3' : '#eceef1';
      ctx.beginPath(); ctx.moveTo(px, 0); ctx.lineTo(px, h - STRIP); ctx.stroke();
    }
    for (let y = Math.ceil(view.y0 * 2) / 2; y <= view.y1; y += 0.5) {
      const [, py] = toPx(0, y);
      ctx.strokeStyle = y === 0 ? '#c9ccd3' : '#eceef1';
      ctx.beginPath(); ctx.moveTo(0, py); ctx.lineTo(w, py); ctx.stroke();
    }
    // The path.
    ctx.strokeStyle = '#26408c';
    ctx.lineWidth = 2;
    ctx.beginPath();
    for (let i = 0; i < editor.path.length; i += 2) {
      const [px, py] = toPx(editor.path[i], editor.path[i + 1]);
      if (i === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    }
    ctx.stroke();
    // In-betweens, evenly spaced in time.
    ctx.fillStyle = '#8c8c99';
    for (let i = 0; i < editor.ghosts.length; i += 2) {
      const [px, py] = toPx(editor.ghosts[i], editor.ghosts[i + 1]);
      ctx.beginPath(); ctx.arc(px, py, 3, 0, 2 * Math.PI); ctx.fill();
    }
    // Tangent handles (solid for Hermite, faint when automatic).
    if (isCubic()) {
      const hs = scene.handleSec;
      ctx.strokeStyle = scene.scheme === 'hermite' ? '#1a9958' : 'rgba(26,153,88,0.4)';
      ctx.fillStyle = ctx.strokeStyle;
      ctx.lineWidth = 1.5;
      for (let k = 0; k < keyCount(); k++) {
        const [x, y] = [editor.keys[3 * k + 1], editor.keys[3 * k + 2]];
        const [ix, iy, ox, oy] = editor.tangents.slice(4 * k, 4 * k + 4);
        const a = toPx(x - ix * hs, y - iy * hs);
        const b = toPx(x + ox * hs, y + oy * hs);
        const c = toPx(x, y);
        ctx.beginPath(); ctx.moveTo(...a); ctx.lineTo(...c); ctx.lineTo(...b); ctx.stroke();
        for (const q of [a, b]) { ctx.beginPath(); ctx.arc(q[0], q[1], 4, 0, 2 * Math.PI); ctx.fill(); }
      }
    }
    // Keys, numbered in time order.
    ctx.font = '12px system-ui, sans-serif';
    for (let k = 0; k < keyCount(); k++) {
      const [px, py] = toPx(editor.keys[3 * k + 1], editor.keys[3 * k + 2]);
      ctx.fillStyle = drag?.kind === 'key' && drag.index === k ? '#b34700' : '#f28c1a';
      ctx.beginPath(); ctx.arc(px, py, 7, 0, 2 * Math.PI); ctx.fill();
      ctx.fillStyle = '#1f2430';
      ctx.fillText(String(k), px + 9, py - 8);
    }
    // The ball.
    const [bx, by] = toPx(...scene.position(timeSec));
    ctx.fillStyle = '#d9333f';
    ctx.beginPath(); ctx.arc(bx, by, 6, 0, 2 * Math.PI); ctx.fill();
    // Time strip: key ticks and the playhead.
    const top = h - STRIP;
    ctx.fillStyle = '#f4f5f7';
    ctx.fillRect(0, top, w, STRIP);
    ctx.strokeStyle = '#c9ccd3';
    ctx.beginPath(); ctx.moveTo(0, top + 0.5); ctx.lineTo(w, top + 0.5); ctx.stroke();
    const [a, b] = timeSpan();
    ctx.fillStyle = '#5b6270';
    for (let s = Math.ceil(a); s <= b; s++) {
      const x = timeToPx(s);
      ctx.fillRect(x, top + STRIP - 10, 1, 10);
      ctx.fillText(`${s} s`, x + 3, top + STRIP - 3);
    }
    for (let k = 0; k < keyCount(); k++) {
      const x = timeToPx(editor.keys[3 * k]);
      ctx.fillStyle = '#f28c1a';
      ctx.fillRect(x - 3, top + 6, 6, 18);
      ctx.fillStyle = '#1f2430';
      ctx.fillText(String(k), x + 5, top + 17);
    }
    const playhead = timeToPx(editor.keys[0] + timeSec);
    ctx.fillStyle = '#d9333f';
    ctx.fillRect(playhead - 1, top + 2, 2, STRIP - 14);
  }

  // ---- Editing with the mouse. ----
  let drag = null;
  const local = (e) => { const r = canvas.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; };
  function hit(px, py) {
    if (py > size.h - STRIP) {
      for (let k = 0; k < keyCount(); k++) if (Math.abs(timeToPx(editor.keys[3 * k]) - px) < 7) return { kind: 'time', index: k };
      return null;
    }
    for (let k = 0; k < keyCount(); k++) {
      const [kx, ky] = toPx(editor.keys[3 * k + 1], editor.keys[3 * k + 2]);
      if (Math.hypot(kx - px, ky - py) < 10) return { kind: 'key', index: k };
    }
    if (isCubic()) {
      const hs = scene.handleSec;
      for (let k = 0; k < keyCount(); k++) {
        const [x, y] = [editor.keys[3 * k + 1], editor.keys[3 * k + 2]];
        const [ix, iy, ox, oy] = editor.tangents.slice(4 * k, 4 * k + 4);
        const [ax, ay] = toPx(x - ix * hs, y - iy * hs);
        const [bx, by] = toPx(x + ox * hs, y + oy * hs);
        if (Math.hypot(bx - px, by - py) < 8) return { kind: 'out', index: k };
        if (Math.hypot(ax - px, ay - py) < 8) return { kind: 'in', index: k };
      }
    }
    return null;
  }
  function keysWith(change) {
    const times = [];
    const xy = [];
    for (let k = 0; k < keyCount(); k++) {
      times.push(editor.keys[3 * k]);
      xy.push(editor.keys[3 * k + 1], editor.keys[3 * k + 2]);
    }
    change(times, xy);
    return [times, xy];
  }
  canvas.addEventListener('pointerdown', (e) => {
    const [px, py] = local(e);
    drag = hit(px, py);
    if (drag) canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const [px, py] = local(e);
    const [x, y] = toWorld(px, py);
    const k = drag.index;
    if (drag.kind === 'key') {
      edit(() => scene.setKeys(...keysWith((times, xy) => { xy[2 * k] = x; xy[2 * k + 1] = y; })));
    } else if (drag.kind === 'time') {
      // Keep the order: a key stays between its neighbours (the core would reject it otherwise).
      const t = editor.keys;
      const lo = k > 0 ? t[3 * (k - 1)] + 0.05 : -Infinity;
      const hi = k < keyCount() - 1 ? t[3 * (k + 1)] - 0.05 : Infinity;
      const time = Math.min(Math.max(pxToTime(px), lo), hi);
      edit(() => scene.setKeys(...keysWith((times) => { times[k] = Math.round(time * 100) / 100; })));
    } else {
      const hs = scene.handleSec;
      const [kx, ky] = [editor.keys[3 * k + 1], editor.keys[3 * k + 2]];
      const d = drag.kind === 'out' ? [(x - kx) / hs, (y - ky) / hs] : [(kx - x) / hs, (ky - y) / hs];
      const [ix, iy, ox, oy] = editor.tangents.slice(4 * k, 4 * k + 4);
      // Alt breaks the tangent: only the dragged side changes.
      const din = drag.kind === 'in' || !e.altKey ? d : [ix, iy];
      const dout = drag.kind === 'out' || !e.altKey ? d : [ox, oy];
      edit(() => scene.setKeyTangent(k, din[0], din[1], dout[0], dout[1]));
    }
  });
  const release = () => { drag = null; };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('dblclick', (e) => {
    const [px, py] = local(e);
    if (py > size.h - STRIP) return;
    const target = hit(px, py);
    if (target?.kind === 'key') {
      if (keyCount() <= 2) { message.textContent = 'A motion needs at least two keys here.'; return; }
      edit(() => scene.setKeys(...keysWith((times, xy) => { times.splice(target.index, 1); xy.splice(2 * target.index, 2); })));
      return;
    }
    // A new key goes where the path passes closest, in time; past either end it extends the motion.
    const [x, y] = toWorld(px, py);
    let best = 0;
    let bestDistance = Infinity;
    for (let i = 0; i < editor.path.length; i += 2) {
      const dd = Math.hypot(editor.path[i] - x, editor.path[i + 1] - y);
      if (dd < bestDistance) { bestDistance = dd; best = i / 2; }
    }
    const samples = editor.path.length / 2;
    const first = editor.keys[0];
    const last = editor.keys[editor.keys.length - 3];
    let time = first + ((last - first) * best) / (samples - 1);
    if (best === samples - 1) time = last + 0.6;
    else if (best === 0) time = first - 0.6;
    time = Math.round(time * 100) / 100;
    edit(() => scene.setKeys(...keysWith((times, xy) => {
      let at = times.findIndex((t) => t > time);
      if (at < 0) at = times.length;
      times.splice(at, 0, time);
      xy.splice(2 * at, 0, x, y);
    })));
  });

  refresh();
  let lastNote = null;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    const text = scene.draw(keysViewer, t);
    if (text !== lastNote) { note.textContent = text; lastNote = text; }
    draw(t);
    markDrawn('#fig-keys');
  });
}

// ---- Figure 2: Lagrange through n and n + 2 keys. ----
const lagrangeViewer = await lesson.figure('#fig-lagrange');
if (lagrangeViewer) {
  lagrangeViewer.setCamera(0, 1.1, 0, 7.2, 0, 0.12);
  const scene = new LagrangeScene();
  const p = { keys: 10, spline: true };
  const gui = new GUI({ container: document.querySelector('#fig-lagrange .panel'), title: 'Lagrange' });
  gui.add(p, 'keys', 3, 14, 1).name('keys (blue)').onChange((v) => scene.setKeyCount(v));
  gui.add(p, 'spline').name('Catmull-Rom (green)').onChange((v) => scene.setShowSpline(v));
  lesson.onFrame(() => {
    scene.draw(lagrangeViewer);
    markDrawn('#fig-lagrange');
  });
}
