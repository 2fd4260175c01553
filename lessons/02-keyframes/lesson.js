// Lesson 02: wires the curve editor, the controls, the plots and the figures to the wasm scenes.
// No interpolation here: JavaScript only draws what Rust sampled and forwards the mouse edits.
import { startLesson, markDrawn, Timeline, Plot, GUI, columns, guarded } from '../../www/lesson.js';
import {
  KeyframesScene, LagrangeScene, CardinalScene, hermiteBasisSamples, hermiteBasisNote, easeSamples, spacingTicks,
} from '../../pkg/inbetween.js';

const lesson = await startLesson();

// Colours of src/draw.rs `palette` (sRGB), so the 2D views match the 3D ones and the words.
const C = {
  path: '#1f6fd6', key: '#e68a00', ghost: '#7f7f7f', ball: '#d62728', tangent: '#17a2a8',
  a: '#1f6fd6', b: '#e35d9c', purple: '#944fc9', grid: '#eceef1', axis: '#c9ccd3', ink: '#1f2430',
};
const SCHEMES = {
  step: 'step', linear: 'linear', 'Lagrange (global)': 'lagrange', 'Hermite (your handles)': 'hermite',
  // "C-R": the panel's select has room for about 20 characters beside its chevron.
  'cardinal (tension μ)': 'cardinal', 'natural (C2)': 'natural', 'centripetal C-R': 'centripetal',
};
const EASES = {
  none: 'none', smoothstep: 'smoothstep', smootherstep: 'smootherstep', sine: 'sine',
  'ease in (t²)': 'in', 'ease out': 'out', 'ease in-out (cubic)': 'inout',
};
const cursor = (plot, x) => plot.setCursor?.(x);

// What the 2D figures draw depends on the timeline's time, their canvas's size and what the reader
// did (controls, drags, clicks: every change here comes from an input event). `inputs` counts
// those events, so a figure draws a frame only when one of the three changed: a paused page the
// reader does not touch draws nothing (each redrawn canvas costs a composited frame).
let inputs = 0;
for (const type of ['input', 'change', 'click', 'pointerdown', 'pointermove', 'pointerup', 'keydown', 'wheel']) {
  document.addEventListener(type, () => { inputs += 1; }, { capture: true, passive: true });
}

/** A timeline whose clock reads the keys' own seconds (`start` + time since the first key). */
class KeyTimeline extends Timeline {
  start = 0;
  show() {
    super.show();
    this.clock.textContent = `${(this.start + this.time).toFixed(2)} s`;
  }
}

// ---- 2D views: world metres to canvas pixels, fitted to a box. ----
function makeView(canvas, reserveBottom = 0) {
  const ctx = canvas.getContext('2d');
  const v = { box: { x0: -3.3, x1: 3.3, y0: -0.5, y1: 2.7 }, w: 1, h: 1, scale: 1, ox: 0, oy: 0, ctx, bottom: reserveBottom };
  v.layout = () => {
    const r = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, Math.round(r.width * dpr));
    canvas.height = Math.max(1, Math.round(r.height * dpr));
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const { x0, x1, y0, y1 } = v.box;
    const h = r.height - v.bottom;
    v.w = r.width; v.h = r.height;
    v.scale = Math.max(1e-3, Math.min(r.width / (x1 - x0), h / (y1 - y0)));
    v.ox = r.width / 2 - (v.scale * (x0 + x1)) / 2;
    v.oy = h / 2 + (v.scale * (y0 + y1)) / 2;
    drawn = '';
  };
  // Set by `layout`, which clears the canvas: the next frame must draw.
  let drawn = '';
  /** True when a frame at time `t` must be drawn: `t`, the size or the reader's input changed. */
  v.stale = (t) => {
    const key = `${t} ${inputs} ${v.w}x${v.h}`;
    if (key === drawn) return false;
    drawn = key;
    return true;
  };
  v.toPx = (x, y) => [v.ox + x * v.scale, v.oy - y * v.scale];
  v.toWorld = (px, py) => [(px - v.ox) / v.scale, (v.oy - py) / v.scale];
  /**
   * Fits the view to points `[x0, y0, x1, y1, …]` with a margin: 12 % of their extent, or
   * `marginPx` CSS pixels on every side when given (room for what is drawn beside the points,
   * such as a key's number, whatever the scale).
   */
  v.fit = (xy, marginPx = 0) => {
    let [x0, x1, y0, y1] = [Infinity, -Infinity, Infinity, -Infinity];
    for (let i = 0; i < xy.length; i += 2) {
      x0 = Math.min(x0, xy[i]); x1 = Math.max(x1, xy[i]);
      y0 = Math.min(y0, xy[i + 1]); y1 = Math.max(y1, xy[i + 1]);
    }
    if (!Number.isFinite(x0)) return;
    let m = 0.12 * Math.max(x1 - x0, y1 - y0, 1);
    if (marginPx > 0) {
      const r = canvas.getBoundingClientRect();
      const [w, h] = [Math.max(x1 - x0, 0.5), Math.max(y1 - y0, 0.5)];
      const scale = Math.min((r.width - 2 * marginPx) / w, (r.height - v.bottom - 2 * marginPx) / h);
      m = marginPx / Math.max(scale, 1e-3);
    }
    v.box = { x0: x0 - m, x1: x1 + m, y0: y0 - m, y1: y1 + m };
    v.layout();
  };
  v.grid = () => {
    const { x0, x1, y0, y1 } = v.box;
    const step = Math.max(0.5, 2 ** Math.ceil(Math.log2((x1 - x0) / 16)));
    ctx.lineWidth = 1;
    for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
      const [px] = v.toPx(x, 0);
      ctx.strokeStyle = x === 0 ? C.axis : C.grid;
      ctx.beginPath(); ctx.moveTo(px, 0); ctx.lineTo(px, v.h - v.bottom); ctx.stroke();
    }
    for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) {
      const [, py] = v.toPx(0, y);
      ctx.strokeStyle = y === 0 ? C.axis : C.grid;
      ctx.beginPath(); ctx.moveTo(0, py); ctx.lineTo(v.w, py); ctx.stroke();
    }
  };
  /** A path `[x0, y0, …]`; held values (step) as dots joined by dashed grey jumps. */
  v.path = (xy, color, held) => {
    ctx.strokeStyle = held ? C.ghost : color;
    ctx.lineWidth = 2; // held jumps as wide as a path: over another scheme's line they must still show
    ctx.setLineDash(held ? [4, 4] : []);
    ctx.beginPath();
    for (let i = 0; i < xy.length; i += 2) {
      const [px, py] = v.toPx(xy[i], xy[i + 1]);
      if (i === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    }
    ctx.stroke();
    ctx.setLineDash([]);
    // Held values a little larger than the key dots drawn over them, so their colour rings the key.
    if (held) for (let i = 0; i < xy.length; i += 2) v.dot(xy[i], xy[i + 1], 7, color);
  };
  v.dot = (x, y, r, color) => {
    const [px, py] = v.toPx(x, y);
    ctx.fillStyle = color;
    ctx.beginPath(); ctx.arc(px, py, r, 0, 2 * Math.PI); ctx.fill();
  };
  /**
   * In-between dots `[x0, y0, …]` moved by `[dx, dy]`, grey, `r` px across at most: smaller where
   * neighbours crowd (half the closest spacing, 2.5 px at least: wider than the curve drawn over
   * them, so each still shows beside it). Drawn before their curve, which runs through them on top.
   */
  v.ghosts = (xy, [dx, dy], r) => {
    const px = [];
    for (let i = 0; i < xy.length; i += 2) px.push(v.toPx(xy[i] + dx, xy[i + 1] + dy));
    let gap = Infinity;
    for (let i = 1; i < px.length; i++) gap = Math.min(gap, Math.hypot(px[i][0] - px[i - 1][0], px[i][1] - px[i - 1][1]));
    const radius = Math.max(2.5, Math.min(r, 0.5 * gap));
    ctx.fillStyle = C.ghost;
    for (const [x, y] of px) { ctx.beginPath(); ctx.arc(x, y, radius, 0, 2 * Math.PI); ctx.fill(); }
  };
  /** A ball: a dot with a white rim, which sets it apart from the key and held dots under it. */
  v.ball = (x, y, r, color) => {
    v.dot(x, y, r, color);
    const [px, py] = v.toPx(x, y);
    ctx.strokeStyle = '#ffffff';
    ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.arc(px, py, r, 0, 2 * Math.PI); ctx.stroke();
  };
  /** An arrow from (x0, y0) to (x1, y1), world metres, with a head of 8 px. */
  v.arrow = (x0, y0, x1, y1, color, width = 2) => {
    const [a, b] = [v.toPx(x0, y0), v.toPx(x1, y1)];
    const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
    if (len < 1) return;
    const [ux, uy] = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
    ctx.strokeStyle = color; ctx.fillStyle = color; ctx.lineWidth = width;
    ctx.beginPath(); ctx.moveTo(...a); ctx.lineTo(b[0] - 6 * ux, b[1] - 6 * uy); ctx.stroke();
    ctx.beginPath(); ctx.moveTo(...b);
    ctx.lineTo(b[0] - 9 * ux - 4 * uy, b[1] - 9 * uy + 4 * ux);
    ctx.lineTo(b[0] - 9 * ux + 4 * uy, b[1] - 9 * uy - 4 * ux);
    ctx.fill();
  };
  /** A dashed line between two world points. */
  v.dashed = (x0, y0, x1, y1, color) => {
    ctx.strokeStyle = color; ctx.lineWidth = 1.5; ctx.setLineDash([5, 4]);
    ctx.beginPath(); ctx.moveTo(...v.toPx(x0, y0)); ctx.lineTo(...v.toPx(x1, y1)); ctx.stroke();
    ctx.setLineDash([]);
  };
  /** Text at a world point, `liftPx` higher on the canvas. */
  v.text = (x, y, text, color = C.ink, liftPx = 0) => {
    const [px, py] = v.toPx(x, y);
    ctx.fillStyle = color;
    ctx.font = '12px system-ui, sans-serif';
    ctx.fillText(text, px, py - liftPx);
  };
  /**
   * A magnified copy of the world box `[x0, y0, x1, y1]` (centred, filling about 60 % of the inset's
   * width or height) in the corner of the canvas that covers the fewest of `avoid`'s world points
   * `[x, y, …]`, framed, with its source outlined in the view and joined to it; `drawInside()`
   * draws into it with the view's own helpers (`toPx` maps into the inset meanwhile). Returns the
   * inset's pixels per metre.
   */
  v.inset = (box, avoid, drawInside) => {
    const [w, h, m] = [Math.min(190, v.w * 0.3), Math.min(120, (v.h - v.bottom) * 0.5), 6];
    const [cx, cy] = [(box[0] + box[2]) / 2, (box[1] + box[3]) / 2];
    const scale = Math.min(w / Math.max(box[2] - box[0], 1e-3), h / Math.max(box[3] - box[1], 1e-3)) / 1.6;
    const bottom = v.h - v.bottom - h - m;
    const corners = [[v.w - w - m, bottom], [m, bottom], [v.w - w - m, m], [m, m]];
    const covered = ([x, y]) => {
      let n = 0;
      for (let i = 0; i < avoid.length; i += 2) {
        const [px, py] = v.toPx(avoid[i], avoid[i + 1]);
        if (px > x - m && px < x + w + m && py > y - m && py < y + h + m) n += 1;
      }
      return n;
    };
    const [x, y] = corners.reduce((best, c) => (covered(c) < covered(best) ? c : best));
    // The source: the part of the view the inset shows (at least 8 px, to be seen), and a line to it.
    const [sw, sh] = [Math.max(8, (w * v.scale) / scale), Math.max(8, (h * v.scale) / scale)];
    const [sx, sy] = v.toPx(cx, cy);
    const clamp = (a, lo, hi) => Math.min(Math.max(a, lo), hi);
    ctx.strokeStyle = C.ink; ctx.lineWidth = 1;
    ctx.strokeRect(sx - sw / 2, sy - sh / 2, sw, sh);
    ctx.beginPath();
    ctx.moveTo(clamp(x + w / 2, sx - sw / 2, sx + sw / 2), clamp(y + h / 2, sy - sh / 2, sy + sh / 2));
    ctx.lineTo(clamp(sx, x, x + w), clamp(sy, y, y + h));
    ctx.stroke();
    const saved = [v.scale, v.ox, v.oy];
    ctx.save();
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(x, y, w, h);
    ctx.beginPath(); ctx.rect(x, y, w, h); ctx.clip();
    [v.scale, v.ox, v.oy] = [scale, x + w / 2 - cx * scale, y + h / 2 + cy * scale];
    drawInside();
    [v.scale, v.ox, v.oy] = saved;
    ctx.restore();
    ctx.strokeStyle = C.ink; ctx.lineWidth = 1;
    ctx.strokeRect(x, y, w, h);
    ctx.fillStyle = C.ink;
    ctx.font = '12px system-ui, sans-serif';
    ctx.fillText(`×${Math.round(scale / v.scale)}`, x + 4, y + 14);
    return scale;
  };
  new ResizeObserver(v.layout).observe(canvas);
  v.layout();
  return v;
}

/**
 * The box `[x0, y0, x1, y1]` round the first loop of the sampled path `xy` (`[x0, y0, x1, y1, …]`,
 * metres): the crossing and the samples between the first two segments that cross, the pair
 * that closes a loop soonest along the path; null when no two cross (touching is not crossing).
 * Where the 2D views magnify, not a property of the curve: the curve is Rust's samples.
 */
function loopBox(xy) {
  const n = xy.length / 2;
  // Which side of the line through samples i → j sample k lies on (the sign), twice the area.
  const side = (i, j, k) => (xy[2 * j] - xy[2 * i]) * (xy[2 * k + 1] - xy[2 * i + 1])
    - (xy[2 * j + 1] - xy[2 * i + 1]) * (xy[2 * k] - xy[2 * i]);
  for (let j = 2; j < n - 1; j++) {
    for (let i = 0; i < j - 1; i++) {
      const [sa, sb] = [side(j, j + 1, i), side(j, j + 1, i + 1)];
      if (side(i, i + 1, j) * side(i, i + 1, j + 1) < 0 && sa * sb < 0) {
        const t = sa / (sa - sb);
        const x = xy[2 * i] + t * (xy[2 * i + 2] - xy[2 * i]);
        const y = xy[2 * i + 1] + t * (xy[2 * i + 3] - xy[2 * i + 1]);
        const box = [x, y, x, y];
        for (let k = i + 1; k <= j; k++) {
          box[0] = Math.min(box[0], xy[2 * k]); box[1] = Math.min(box[1], xy[2 * k + 1]);
          box[2] = Math.max(box[2], xy[2 * k]); box[3] = Math.max(box[3], xy[2 * k + 1]);
        }
        return box;
      }
    }
  }
  return null;
}

/**
 * Where the second copy of a pair of drawings goes, `[dx, dy]` metres: beside the first or under
 * it, whichever lets `view` draw both larger (a wide canvas puts them side by side, a tall one one
 * above the other). `xy` holds every point of one copy.
 */
function pairOffset(view, xy) {
  let [x0, x1, y0, y1] = [Infinity, -Infinity, Infinity, -Infinity];
  for (let i = 0; i < xy.length; i += 2) {
    x0 = Math.min(x0, xy[i]); x1 = Math.max(x1, xy[i]);
    y0 = Math.min(y0, xy[i + 1]); y1 = Math.max(y1, xy[i + 1]);
  }
  if (!Number.isFinite(x0)) return [6, 0];
  const [w, h] = [Math.max(x1 - x0, 0.5), Math.max(y1 - y0, 0.5)];
  const [gapX, gapY] = [w * 0.2 + 0.6, 0.9]; // room for the titles above each copy
  const side = Math.min(view.w / (2 * w + gapX), view.h / h);
  const stacked = Math.min(view.w / w, view.h / (2 * h + gapY));
  return side >= stacked ? [w + gapX, 0] : [0, -(h + gapY)];
}
/** `xy` plus a point 0.6 m above its highest, where a copy's title goes, so a fit keeps it. */
function withTitleRoom(xy) {
  let top = -Infinity; let x = 0;
  for (let i = 0; i < xy.length; i += 2) if (xy[i + 1] > top) { top = xy[i + 1]; x = xy[i]; }
  return Number.isFinite(top) ? [...xy, x, top + 0.6] : xy;
}
/** `[x0, y0, …]` moved by `[dx, dy]`. */
const shifted = (xy, [dx, dy]) => xy.map((v, i) => v + (i % 2 === 0 ? dx : dy));

// ---- Figure 1: curve editor + 3D view. Its scene and timeline drive Figures 2, 6, 7 and 8. ----
const keysViewer = await lesson.figure('#fig-keys');
const scene = new KeyframesScene();
const timeline = new KeyTimeline(document.getElementById('keys-timeline'), { duration: scene.loopSec });
const listeners = []; // figures that re-sample after an edit of the shared keys
/** Registers a figure's re-sampling and runs it once now (frames may come before any edit). */
const listen = (f) => { listeners.push(f); f(); };
const message = document.getElementById('keys-message');
const p = { scheme: 'cardinal', tension: 1, ghosts: 24, timeDepth: true, arcLength: false, ease: 'none', useExercise: false };
let schemeControl = null;
lesson.onFrame((dt) => timeline.advance(dt)); // first: every figure below reads timeline.time

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

// Every keys select (Figure 1's and each panel's "keys (all figures)") shows the preset the shared
// keys come from, or none once a key is edited by hand: a panel never names keys its figure does not draw.
const presetShows = [];
const showPreset = (v) => { for (const show of presetShows) show(v); };
/** Loads preset `v` ('' loads none) into the shared keys and shows it in every keys select. */
function loadPreset(v) {
  if (v) edit(() => scene.loadPreset(v));
  showPreset(v);
}
/** Adds a lil-gui "keys (all figures)" select for `state.preset` to `gui`, kept in step with the others. */
function addPresetControl(gui, state) {
  const c = gui.add(state, 'preset', { "Figure 1's keys": '', default: 'default', 'loop-prone': 'loop', 'uneven times': 'uneven', 'zig-zag': 'centripetal' })
    .name('keys (all figures)').onChange(loadPreset);
  presetShows.push((v) => { state.preset = v; c.updateDisplay(); });
}
function refresh() {
  timeline.start = scene.startSec;
  timeline.duration = scene.loopSec;
  timeline.time %= timeline.duration;
  timeline.show();
  if (schemeControl && scene.scheme !== p.scheme) {
    p.scheme = scene.scheme;
    schemeControl.updateDisplay();
  }
  for (const f of listeners) f();
}

if (keysViewer) {
  // Raised and turned further, and closer: the curves fill the canvas at both sizes and the
  // space-time curve's run into the depth (the clock's axis) shows.
  keysViewer.setCamera(0.3, 0.8, -1.3, 6.5, 0.75, 0.4);
  const note = document.getElementById('keys-note');
  const gui = new GUI({ container: document.querySelector('#fig-keys .panel'), title: 'Keyframes' });
  schemeControl = gui.add(p, 'scheme', SCHEMES).name('scheme').onChange((v) => edit(() => scene.setScheme(v)));
  gui.add(p, 'tension', 0, 2, 0.01).name('tension μ (cardinal)').onChange((v) => edit(() => scene.setTension(v)));
  gui.add(p, 'ghosts', 2, 60, 1).name('in-betweens').onChange((v) => edit(() => scene.setGhostCount(v)));
  gui.add(p, 'timeDepth').name('time as depth (3D)').onChange((v) => edit(() => scene.setTimeDepth(v)));
  gui.add(p, 'useExercise').name('use my exercise').onChange((v) => edit(() => scene.setUseExercise(v)));

  const canvas = document.querySelector('#fig-keys .editor canvas');
  const STRIP = 46; // height of the time strip, CSS pixels
  // A key's number sits 15 px off its dot and is 12 px tall: a fit leaves this much on every side.
  const LABEL_ROOM_PX = 30;
  const view = makeView(canvas, STRIP);
  const { ctx } = view;
  const editor = { path: [], ghosts: [], keys: [], tangents: [], held: false };
  listen(() => {
    editor.path = scene.samplePath();
    editor.ghosts = scene.sampleGhosts();
    editor.keys = scene.keys();
    editor.tangents = scene.tangents();
    editor.held = scene.isHeld;
  });
  const keyCount = () => editor.keys.length / 3;
  const isCubic = () => ['hermite', 'cardinal', 'natural', 'centripetal'].includes(scene.scheme);

  // The time strip spans [a, b] seconds; frozen while a key's time is dragged, so the strip does
  // not rescale under the pointer.
  let frozenSpan = null;
  const timeSpan = () => {
    if (frozenSpan) return frozenSpan;
    const t = editor.keys;
    const first = Math.min(0, t[0]);
    return [first, Math.max(first + 1, t[t.length - 3] + scene.loopSec - scene.durationSec + 0.2)];
  };
  const timeToPx = (t) => { const [a, b] = timeSpan(); return 16 + ((t - a) / (b - a)) * (view.w - 32); };
  const pxToTime = (px) => { const [a, b] = timeSpan(); return a + ((px - 16) / (view.w - 32)) * (b - a); };
  const handleEnds = (k) => {
    const hs = scene.handleSec;
    const [x, y] = [editor.keys[3 * k + 1], editor.keys[3 * k + 2]];
    const [ix, iy, ox, oy] = editor.tangents.slice(4 * k, 4 * k + 4);
    return { key: [x, y], in: [x - ix * hs, y - iy * hs], out: [x + ox * hs, y + oy * hs] };
  };
  function fitView() {
    const pts = [...editor.path];
    if (isCubic()) for (let k = 0; k < keyCount(); k++) { const h = handleEnds(k); pts.push(...h.in, ...h.out); }
    view.fit(pts, LABEL_ROOM_PX);
  }

  function draw(tau) {
    const { w, h } = view;
    ctx.clearRect(0, 0, w, h);
    view.grid();
    view.path(editor.path, C.path, editor.held);
    for (let i = 0; i < editor.ghosts.length; i += 2) view.dot(editor.ghosts[i], editor.ghosts[i + 1], 3, C.ghost);
    // Time strip: seconds, key ticks and the playhead (at the clock's time).
    const top = h - STRIP;
    ctx.fillStyle = '#f4f5f7';
    ctx.fillRect(0, top, w, STRIP);
    ctx.strokeStyle = C.axis;
    ctx.beginPath(); ctx.moveTo(0, top + 0.5); ctx.lineTo(w, top + 0.5); ctx.stroke();
    const [a, b] = timeSpan();
    ctx.font = '12px system-ui, sans-serif';
    ctx.fillStyle = '#5b6270';
    const every = Math.max(1, Math.ceil((b - a) / 10));
    for (let s = Math.ceil(a / every) * every; s <= b; s += every) {
      const x = timeToPx(s);
      ctx.fillRect(x, top + STRIP - 10, 1, 10);
      ctx.fillText(`${s} s`, x + 3, top + STRIP - 3);
    }
    for (let k = 0; k < keyCount(); k++) {
      const x = timeToPx(editor.keys[3 * k]);
      ctx.fillStyle = drag?.kind === 'time' && drag.index === k ? '#b34700' : C.key;
      ctx.fillRect(x - 3, top + 6, 6, 18);
      ctx.fillStyle = C.ink;
      ctx.fillText(String(k), x + 5, top + 17);
    }
    const playhead = timeToPx(scene.startSec + tau);
    ctx.fillStyle = C.ball;
    ctx.fillRect(playhead - 1, top + 2, 2, STRIP - 14);
    // Tangent handles over everything (solid for Hermite, faint when automatic): grabbable anywhere.
    if (isCubic()) {
      ctx.strokeStyle = scene.scheme === 'hermite' ? C.tangent : 'rgba(23,162,168,0.45)';
      ctx.fillStyle = ctx.strokeStyle;
      ctx.lineWidth = 1.5;
      for (let k = 0; k < keyCount(); k++) {
        const hd = handleEnds(k);
        const [pa, pc, pb] = [view.toPx(...hd.in), view.toPx(...hd.key), view.toPx(...hd.out)];
        ctx.beginPath(); ctx.moveTo(...pa); ctx.lineTo(...pc); ctx.lineTo(...pb); ctx.stroke();
        for (const q of [pa, pb]) { ctx.beginPath(); ctx.arc(q[0], q[1], 4, 0, 2 * Math.PI); ctx.fill(); }
      }
    }
    for (let k = 0; k < keyCount(); k++) {
      const [x, y] = [editor.keys[3 * k + 1], editor.keys[3 * k + 2]];
      view.dot(x, y, 7, drag?.kind === 'key' && drag.index === k ? '#b34700' : C.key);
      const [px, py] = view.toPx(x, y);
      // The number sits off the tangent handle's line, on its upper side (up and right without
      // handles), so a handle never crosses it.
      let [ox, oy] = [9, -8];
      if (isCubic()) {
        const hd = handleEnds(k);
        const [pa, pb] = [view.toPx(...hd.in), view.toPx(...hd.out)];
        const [tx, ty] = [pb[0] - pa[0], pb[1] - pa[1]];
        const len = Math.hypot(tx, ty);
        if (len > 1e-3) {
          let [nx, ny] = [ty / len, -tx / len];
          if (ny > 0) [nx, ny] = [-nx, -ny];
          [ox, oy] = [15 * nx - 4, 15 * ny + 4];
        }
      }
      ctx.fillStyle = C.ink;
      ctx.fillText(String(k), px + ox, py + oy);
    }
    view.dot(...scene.position(tau), 6, C.ball);
  }

  // ---- Editing with the mouse. Keys and handles first (even over the strip), then the strip. ----
  let drag = null;
  const local = (e) => { const r = canvas.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; };
  // Where the editor's handles are, in CSS pixels from the canvas's corner (for the page tests).
  window.__inbetween.editor = {
    keyPx: (k) => view.toPx(editor.keys[3 * k + 1], editor.keys[3 * k + 2]),
    outHandlePx: (k) => view.toPx(...handleEnds(k).out),
    inHandlePx: (k) => view.toPx(...handleEnds(k).in),
    timePx: (k) => [timeToPx(editor.keys[3 * k]), view.h - STRIP / 2],
    keys: () => Array.from(editor.keys),
    tangents: () => Array.from(editor.tangents),
  };
  function hit(px, py) {
    for (let k = 0; k < keyCount(); k++) {
      const [kx, ky] = view.toPx(editor.keys[3 * k + 1], editor.keys[3 * k + 2]);
      if (Math.hypot(kx - px, ky - py) < 10) return { kind: 'key', index: k };
    }
    if (isCubic()) {
      for (let k = 0; k < keyCount(); k++) {
        const hd = handleEnds(k);
        const [bx, by] = view.toPx(...hd.out);
        const [ax, ay] = view.toPx(...hd.in);
        if (Math.hypot(bx - px, by - py) < 8) return { kind: 'out', index: k };
        if (Math.hypot(ax - px, ay - py) < 8) return { kind: 'in', index: k };
      }
    }
    if (py > view.h - STRIP) {
      for (let k = 0; k < keyCount(); k++) if (Math.abs(timeToPx(editor.keys[3 * k]) - px) < 7) return { kind: 'time', index: k };
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
    if (drag?.kind === 'time') frozenSpan = timeSpan();
    if (drag) canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    showPreset('');
    const [px, py] = local(e);
    const [x, y] = view.toWorld(px, py);
    const k = drag.index;
    if (drag.kind === 'key') {
      edit(() => scene.setKeys(...keysWith((times, xy) => { xy[2 * k] = x; xy[2 * k + 1] = y; })));
    } else if (drag.kind === 'time') {
      // Keep the order (a key stays between its neighbours) and inside the frozen strip.
      const t = editor.keys;
      const [a, b] = frozenSpan;
      const lo = k > 0 ? t[3 * (k - 1)] + 0.05 : a;
      const hi = k < keyCount() - 1 ? t[3 * (k + 1)] - 0.05 : b;
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
  const release = () => { drag = null; frozenSpan = null; };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('dblclick', (e) => {
    const [px, py] = local(e);
    if (py > view.h - STRIP) return;
    showPreset('');
    const target = hit(px, py);
    if (target?.kind === 'key') {
      if (keyCount() <= 2) { message.textContent = 'A motion needs at least two keys here.'; return; }
      edit(() => scene.setKeys(...keysWith((times, xy) => { times.splice(target.index, 1); xy.splice(2 * target.index, 2); })));
      return;
    }
    // A new key goes after the key nearest in space, half-way in time; or before key 0, 0.6 s
    // earlier but not before the clock's zero: there the keys move later to make room.
    const [x, y] = view.toWorld(px, py);
    let near = 0;
    for (let k = 1; k < keyCount(); k++) {
      const d = (j) => Math.hypot(editor.keys[3 * j + 1] - x, editor.keys[3 * j + 2] - y);
      if (d(k) < d(near)) near = k;
    }
    const t = (k) => editor.keys[3 * k];
    let time;
    if (near === keyCount() - 1) time = t(near) + 0.6;
    else if (near === 0 && keyCount() > 1 && Math.hypot(editor.keys[4] - x, editor.keys[5] - y) > Math.hypot(editor.keys[1] - editor.keys[4], editor.keys[2] - editor.keys[5])) time = t(0) - 0.6;
    else time = (t(near) + t(near + 1)) / 2;
    time = Math.round(time * 100) / 100;
    const later = Math.max(0, -time);
    edit(() => scene.setKeys(...keysWith((times, xy) => {
      if (later > 0) for (let k = 0; k < times.length; k++) times[k] = Math.round((times[k] + later) * 100) / 100;
      let at = times.findIndex((tt) => tt > time + later);
      if (at < 0) at = times.length;
      times.splice(at, 0, time + later);
      xy.splice(2 * at, 0, x, y);
    })));
    // The new key's handles in view: the editor refits when one falls outside.
    const at = editor.keys.findIndex((v, i) => i % 3 === 0 && Math.abs(v - time - later) < 1e-3) / 3;
    if (at >= 0 && isCubic()) {
      const { x0, x1, y0, y1 } = view.box;
      const h = handleEnds(at);
      const out = [...h.in, ...h.out].some((v, i) => (i % 2 ? v < y0 || v > y1 : v < x0 || v > x1));
      if (out) fitView();
    }
  });

  const figure = document.getElementById('fig-keys');
  const presetSelect = figure.querySelector('.preset');
  presetShows.push((v) => { presetSelect.value = v; });
  presetSelect.addEventListener('change', () => {
    if (!presetSelect.value) return;
    loadPreset(presetSelect.value);
    fitView();
  });
  figure.querySelector('.fit').addEventListener('click', fitView);
  figure.querySelector('.reset').addEventListener('click', () => {
    p.scheme = 'cardinal'; p.tension = 1;
    gui.controllersRecursive().forEach((c) => c.updateDisplay());
    showPreset('');
    edit(() => { scene.setTension(1); scene.setScheme('cardinal'); scene.loadPreset('default'); });
    view.box = { x0: -3.3, x1: 3.3, y0: -0.5, y1: 2.7 };
    view.layout();
  });

  let lastNote = null;
  lesson.onFrame(() => {
    const tau = timeline.time;
    const text = scene.draw(keysViewer, tau);
    if (text !== lastNote) { note.textContent = text; lastNote = text; }
    if (view.stale(tau)) draw(tau);
    markDrawn('#fig-keys');
  });
}

/** Gives scene `s` Figure 1's keys, tension (and handles, for Hermite) under `scheme`. */
function mirror(s, scheme, times, xy) {
  s.setScheme('linear');
  s.setKeys(times, xy);
  s.setTension(p.tension);
  s.setScheme(scheme);
  if (scheme === 'hermite') {
    const d = scene.tangents();
    const tin = []; const tout = [];
    for (let i = 0; i < d.length; i += 4) { tin.push(d[i], d[i + 1]); tout.push(d[i + 2], d[i + 3]); }
    s.setTangents(tin, tout);
  }
}
/** Figure 1's keys as `[times, xy]`. */
function sharedKeys() {
  const keys = scene.keys();
  const times = []; const xy = [];
  for (let i = 0; i < keys.length; i += 3) { times.push(keys[i]); xy.push(keys[i + 1], keys[i + 2]); }
  return [times, xy];
}

// ---- Figures 2, 6, 7: two schemes on the same keys, at the same time. ----
function compareFigure(id) {
  const figure = document.getElementById(id);
  const schemes = { a: new KeyframesScene(), b: new KeyframesScene() };
  const q = { a: figure.dataset.a, b: figure.dataset.b, preset: '' };
  const speed = figure.dataset.quantity === 'speed';
  const gui = new GUI({ container: figure.querySelector('.panel'), title: 'Compare' });
  const layers = { a: { path: [] }, b: { path: [] } };
  const canvas = figure.querySelector('canvas');
  const view = makeView(canvas);
  const gapNote = figure.querySelector('.note'); // Figure 7's: how far apart A and B get
  // The box round the first loop of A's or B's path (both, when both loop), or null.
  let loop = null;
  const plot = new Plot(figure.querySelector('.plot'), {
    title: speed ? 'Speed |p′(t)|' : 'Acceleration |p″(t)|',
    xLabel: 'time (s)', yLabel: speed ? 'speed (m/s)' : 'acceleration (m/s²)',
    // Magnitudes, from 0: the slowest stretch reads against a 0 tick, linear's zero on the floor.
    series: ['A', 'B'], colors: [C.a, C.b], minSpan: 0.1, from0: true,
    widths: [5, 2], // A wide under B: the same scheme twice shows both lines
  });
  function sync() {
    const [times, xy] = sharedKeys();
    const cols = [[]];
    const all = [];
    for (const side of ['a', 'b']) {
      const s = schemes[side];
      try {
        mirror(s, q[side], times, xy);
      } catch (e) {
        message.textContent = `Figure comparison: ${e.message ?? e}`;
      }
      layers[side] = { path: s.samplePath(), held: s.isHeld };
      all.push(...layers[side].path);
      const rows = s.sampleMotion(400);
      const col = [];
      for (let i = 0; i < rows.length; i += 4) {
        if (side === 'a') cols[0].push(rows[i]);
        col.push(speed ? rows[i + 1] : rows[i + 3]);
      }
      cols.push(col);
    }
    plot.setData(cols);
    if (gapNote) gapNote.textContent = schemes.a.gapNote(schemes.b);
    view.fit(all);
    const loops = ['a', 'b'].filter((side) => !layers[side].held).map((side) => loopBox(layers[side].path)).filter(Boolean);
    loop = loops.length ? loops.reduce((u, b) => [Math.min(u[0], b[0]), Math.min(u[1], b[1]), Math.max(u[2], b[2]), Math.max(u[3], b[3])]) : null;
  }
  gui.add(q, 'a', SCHEMES).name('A (blue)').onChange(sync);
  gui.add(q, 'b', SCHEMES).name('B (pink)').onChange(sync);
  addPresetControl(gui, q);
  listen(sync);
  lesson.onFrame(() => {
    const tau = timeline.time;
    if (!view.stale(tau)) return;
    const { ctx } = view;
    ctx.clearRect(0, 0, view.w, view.h);
    view.grid();
    const keys = scene.keys();
    const at = { a: schemes.a.position(tau), b: schemes.b.position(tau) };
    const radius = { a: 11, b: 6 };
    const drawPaths = (ballScale) => {
      // A step's grey jumps run from key to key, where a linear path runs too: drawn last, on top.
      const order = ['a', 'b'].sort((p, q) => Number(layers[p].held) - Number(layers[q].held));
      for (const side of order) view.path(layers[side].path, C[side], layers[side].held);
      for (let i = 0; i < keys.length; i += 3) view.dot(keys[i + 1], keys[i + 2], 4, C.ink);
      // A's ball wider than B's, drawn first: where the two schemes agree (at the keys, and
      // everywhere for the same scheme twice) A rings B, as its wide line shows under B's in the plot.
      for (const side of ['a', 'b']) view.ball(...at[side], radius[side] * ballScale, C[side]);
    };
    drawPaths(1);
    // Each name over both balls, off its own path: 6 px past its ball along the path's normal there
    // (screen space), on the side away from the other ball (A above where they meet or where the
    // ball stands still), with a white edge that keeps it readable on the other lines.
    const { ctx: c } = view;
    c.font = 'bold 13px system-ui, sans-serif';
    c.textAlign = 'center';
    c.textBaseline = 'middle';
    c.lineWidth = 3;
    c.strokeStyle = '#ffffff';
    for (const [side, other] of [['a', 'b'], ['b', 'a']]) {
      const [p, q] = [view.toPx(...at[side]), view.toPx(...at[other])];
      const [u, v] = [view.toPx(...schemes[side].position(tau + 0.02)), view.toPx(...schemes[side].position(tau - 0.02))];
      const len = Math.hypot(u[0] - v[0], u[1] - v[1]);
      // The normal pointing up the screen (y grows downwards).
      const n = len > 0.5 ? [(v[1] - u[1]) / len, (u[0] - v[0]) / len].map((x) => (u[0] > v[0] ? -x : x)) : [0, -1];
      const away = (p[0] - q[0]) * n[0] + (p[1] - q[1]) * n[1];
      const d = (Math.abs(away) > 1 ? Math.sign(away) : side === 'a' ? 1 : -1) * (radius[side] + 13);
      const [x, y] = [p[0] + d * n[0], p[1] + d * n[1]];
      c.strokeText(side.toUpperCase(), x, y);
      c.fillStyle = C[side];
      c.fillText(side.toUpperCase(), x, y);
    }
    c.textAlign = 'start';
    c.textBaseline = 'alphabetic';
    // A loop a few centimetres across is a few pixels here, under A's ball: the inset magnifies
    // it, with balls small enough to see the loop round them.
    if (loop) {
      const scale = view.inset(loop, [...layers.a.path, ...layers.b.path], () => drawPaths(0.4));
      canvas.dataset.loopPx = Math.round(scale * Math.max(loop[2] - loop[0], loop[3] - loop[1]));
    } else {
      delete canvas.dataset.loopPx;
    }
    cursor(plot, scene.startSec + tau);
    markDrawn(`#${id}`);
  });
}
for (const id of ['fig-step', 'fig-natural', 'fig-centripetal']) compareFigure(id);

// ---- Figure 3: Lagrange through n and n + 2 keys, a graph seen straight on. ----
const lagrangeViewer = await lesson.figure('#fig-lagrange');
if (lagrangeViewer) {
  // Yaw 0, pitch 0: the camera looks straight at the graph's plane, so it is not foreshortened.
  lagrangeViewer.setCamera(0.15, 1.4, 0, 6.5, 0, 0);
  const lagrange = new LagrangeScene();
  const lp = { keys: 10, spline: true };
  const gui = new GUI({ container: document.querySelector('#fig-lagrange .panel'), title: 'Lagrange' });
  // The note (Rust's: the curves' largest gap, the red curve's reach) changes with the keys only.
  const note = document.getElementById('lagrange-note');
  const showLagrangeNote = () => { note.textContent = lagrange.note; };
  gui.add(lp, 'keys', 3, 16, 1).name('keys (blue)').onChange((v) => { lagrange.setKeyCount(v); showLagrangeNote(); });
  gui.add(lp, 'spline').name('Catmull-Rom (green)').onChange((v) => { lagrange.setShowSpline(v); showLagrangeNote(); });
  showLagrangeNote();
  lesson.onFrame(() => {
    lagrange.draw(lagrangeViewer);
    markDrawn('#fig-lagrange');
  });
}

// ---- Figure 4: the Hermite basis, with exercise 2.1 at the chosen s. ----
{
  const bp = { s: 0.3, useExercise: false };
  const plot = new Plot(document.getElementById('basis-plot'), {
    title: 'Hermite basis', xLabel: 's (segment parameter, 0 to 1)', yLabel: 'weight (unitless)',
    series: ['h00 (p_i)', 'h10 (h d_i)', 'h01 (p_i+1)', 'h11 (h d_i+1)'],
    colors: [C.key, C.tangent, C.b, C.purple], minSpan: 0.1,
  });
  const rows = hermiteBasisSamples(101);
  const cols = [[], [], [], [], []];
  for (let i = 0; i < rows.length; i += 5) for (let c = 0; c < 5; c++) cols[c].push(rows[i + c]);
  plot.setData(cols);
  const note = document.getElementById('basis-note');
  const update = () => {
    note.textContent = hermiteBasisNote(bp.s, bp.useExercise);
    cursor(plot, bp.s);
  };
  const gui = new GUI({ container: document.querySelector('#fig-basis .panel'), title: 'Basis' });
  gui.add(bp, 's', 0, 1, 0.01).name('s').onChange(update);
  gui.add(bp, 'useExercise').name('use my exercise').onChange(update);
  update();
  markDrawn('#fig-basis');
}

// ---- Figure 5: the cardinal tangent from the chord, by the time between neighbours and halved. ----
{
  const figure = document.getElementById('fig-cardinal');
  const cardinal = new CardinalScene();
  const cp = { preset: 'uneven', tension: 1 };
  const view = makeView(figure.querySelector('canvas'));
  const plot = new Plot(document.getElementById('cardinal-plot'), {
    title: 'Speed |p′(t)| by each rule', xLabel: 'time (s)', yLabel: 'speed (m/s)',
    series: ['divided by the time', 'halved'], colors: [C.a, C.b], minSpan: 0.1, from0: true,
    widths: [5, 2], // where the rules agree (keys 1 s apart) the wide blue line shows under the pink
  });
  const note = document.getElementById('cardinal-note');
  const RULES = [['time', C.a, 'divided by the time'], ['halved', C.b, 'halved']];
  let layer = null;
  const HANDLE_SEC = 0.25; // an arrow is the distance covered in 0.25 s at the key's velocity
  const update = () => {
    const keys = cardinal.keys();
    const sides = RULES.map(([rule, color, title]) => ({
      rule, color, title,
      path: cardinal.samplePath(rule, 240), ghosts: cardinal.samplePath(rule, 25), d: cardinal.tangents(rule),
    }));
    // Each side's extent: its path and the tips of its tangent arrows.
    const extent = (side) => {
      const pts = [...side.path];
      for (let k = 0; k < keys.length / 3; k++) {
        pts.push(keys[3 * k + 1] + side.d[2 * k] * HANDLE_SEC, keys[3 * k + 2] + side.d[2 * k + 1] * HANDLE_SEC);
      }
      return pts;
    };
    const [ea, eb] = sides.map(extent);
    layer = { keys, sides, extent: withTitleRoom([...ea, ...eb]), off: null, size: '' };
    plot.setData(columns(cardinal.sampleSpeeds(301), 3));
    layer.note = cardinal.note();
  };
  const gui = new GUI({ container: figure.querySelector('.panel'), title: 'Tangents' });
  gui.add(cp, 'preset', { 'uneven times': 'uneven', default: 'default', 'loop-prone (1 s apart)': 'loop', 'zig-zag': 'centripetal' })
    .name('keys');
  gui.add(cp, 'tension', 0, 2, 0.01).name('tension μ');
  // A typed value the scene refuses is named in the note and the controls go back.
  let rejected = '';
  const apply = guarded(gui, cp, () => {
    cardinal.setPreset(cp.preset);
    cardinal.setTension(cp.tension);
    update();
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  lesson.onFrame(() => {
    if (!view.stale(0)) return;
    const { ctx } = view;
    ctx.clearRect(0, 0, view.w, view.h);
    view.grid();
    // Beside or under each other, refitted when the data or the canvas's size changes.
    const size = `${view.w}x${view.h}`;
    if (layer.size !== size) {
      layer.off = pairOffset(view, layer.extent);
      view.fit([...layer.extent, ...shifted(layer.extent, layer.off)]);
      layer.size = size;
    }
    const { keys, sides, off: [ox, oy] } = layer;
    const text = [rejected, layer.note].filter(Boolean).join(' ');
    if (note.textContent !== text) note.textContent = text;
    const n = keys.length / 3;
    sides.forEach((side, j) => {
      const [dx, dy] = [j * ox, j * oy];
      view.ghosts(side.ghosts, [dx, dy], 3);
      view.path(shifted(side.path, [dx, dy]), side.color);
      for (let k = 0; k < n; k++) {
        const [x, y] = [keys[3 * k + 1] + dx, keys[3 * k + 2] + dy];
        const [b, a] = [Math.max(0, k - 1), Math.min(n - 1, k + 1)];
        view.dashed(keys[3 * b + 1] + dx, keys[3 * b + 2] + dy, keys[3 * a + 1] + dx, keys[3 * a + 2] + dy, C.ghost);
        view.arrow(x, y, x + side.d[2 * k] * HANDLE_SEC, y + side.d[2 * k + 1] * HANDLE_SEC, C.tangent, 2.5);
      }
      for (let k = 0; k < n; k++) {
        const [x, y] = [keys[3 * k + 1] + dx, keys[3 * k + 2] + dy];
        view.dot(x, y, 5, C.key);
        // The number 14 px off the dot across its tangent, on the upper side (as in Figure 1's
        // editor), so neither the dot nor the arrow covers it; up and right where μ = 0.
        const [px, py] = view.toPx(x, y);
        const [tx, ty] = [side.d[2 * k], -side.d[2 * k + 1]];
        const len = Math.hypot(tx, ty);
        let [nx, ny] = len > 1e-6 ? [ty / len, -tx / len] : [0.7, -0.7];
        if (ny > 0) [nx, ny] = [-nx, -ny];
        view.ctx.fillStyle = C.ink;
        view.ctx.font = '12px system-ui, sans-serif';
        view.ctx.fillText(`${k}`, px + 14 * nx - 4, py + 14 * ny + 4);
      }
      let top = -Infinity; let [x0, x1] = [Infinity, -Infinity];
      for (let i = 0; i < side.path.length; i += 2) {
        top = Math.max(top, side.path[i + 1]); x0 = Math.min(x0, side.path[i]); x1 = Math.max(x1, side.path[i]);
      }
      // The title's baseline 30 px above the path's top: a key's number sits up to 22 px above it.
      view.text((x0 + x1) / 2 + dx - 0.7, top + dy, side.title, side.color, 30);
    });
    markDrawn('#fig-cardinal');
  });
}

// ---- Figure 8: Figure 1's motion twice, keyed timing and constant speed, with the plots. ----
{
  const figure = document.getElementById('fig-timing');
  const view = makeView(figure.querySelector('canvas'));
  const twins = { keyed: new KeyframesScene(), even: new KeyframesScene() };
  const layers = { keyed: { path: [], ghosts: [] }, even: { path: [], ghosts: [] }, held: false, off: [0, 0], size: '' };
  const gui = new GUI({ container: figure.querySelector('.panel'), title: 'Timing' });
  gui.add(p, 'ease', EASES).name('ease (slow in / out)').onChange((v) => edit(() => scene.setEase(v)));
  gui.add(p, 'arcLength').name('Figure 1 at constant speed').onChange((v) => edit(() => scene.setArcLength(v)));
  const tp = { preset: '' };
  addPresetControl(gui, tp);
  const speedPlot = new Plot(document.getElementById('keys-speed'), {
    title: 'Speed |p′(t)|', xLabel: 'time (s)', yLabel: 'speed (m/s)',
    series: ['keyed', 'constant speed'], colors: [C.path, C.ball], minSpan: 0.1, from0: true,
    widths: [5, 2], // keyed wide under arc length: where the two speeds agree both stay visible
  });
  const accelPlot = new Plot(document.getElementById('keys-accel'), {
    title: 'Acceleration |p″(t)|', xLabel: 'time (s)', yLabel: 'acceleration (m/s²)',
    series: ['keyed', 'constant speed'], colors: [C.path, C.ball], minSpan: 0.1, from0: true,
    widths: [5, 2],
  });
  const timingNote = document.getElementById('timing-note');
  listen(() => {
    const [times, xy] = sharedKeys();
    const cols = [];
    for (const [name, s] of Object.entries(twins)) {
      try {
        mirror(s, scene.scheme, times, xy);
        s.setEase(p.ease);
        s.setGhostCount(p.ghosts);
        s.setArcLength(name === 'even');
      } catch (e) {
        message.textContent = `Figure 8: ${e.message ?? e}`;
      }
      layers[name] = { path: s.samplePath(), ghosts: s.sampleGhosts() };
      const rows = s.sampleMotion(400);
      const c = [[], [], [], []];
      for (let i = 0; i < rows.length; i += 4) for (let k = 0; k < 4; k++) c[k].push(rows[i + k]);
      cols.push(c);
    }
    layers.held = twins.keyed.isHeld;
    layers.size = ''; // refit on the next frame
    timingNote.textContent = [
      twins.even.timingNote,
      p.arcLength ? "Figure 1's ball follows the constant-speed timing (red)." : "Figure 1's ball follows the keyed timing (blue).",
    ].filter(Boolean).join(' ');
    const [k, e] = cols;
    speedPlot.setData([k[0], k[1], k[2]]);
    accelPlot.setData([k[0], k[3], e[3]]);
  });
  lesson.onFrame(() => {
    const tau = timeline.time;
    if (!view.stale(tau)) return;
    // Beside or under each other, refitted when the data or the canvas's size changes.
    const size = `${view.w}x${view.h}`;
    if (layers.size !== size) {
      const both = withTitleRoom([...layers.keyed.path, ...layers.even.path]);
      layers.off = pairOffset(view, both);
      view.fit([...both, ...shifted(both, layers.off)]);
      layers.size = size;
    }
    view.ctx.clearRect(0, 0, view.w, view.h);
    view.grid();
    [['keyed', C.path, 'keyed timing'], ['even', C.ball, 'constant speed']].forEach(([name, color, title], j) => {
      const off = [j * layers.off[0], j * layers.off[1]];
      const { path, ghosts } = layers[name];
      view.ghosts(ghosts, off, 3.5);
      view.path(shifted(path, off), color, layers.held);
      const [x, y] = twins[name].position(tau);
      view.dot(x + off[0], y + off[1], 7, color);
      let top = -Infinity; let [x0, x1] = [Infinity, -Infinity];
      for (let i = 0; i < path.length; i += 2) { top = Math.max(top, path[i + 1]); x0 = Math.min(x0, path[i]); x1 = Math.max(x1, path[i]); }
      view.text((x0 + x1) / 2 + off[0] - 0.6, top + off[1] + 0.35, title, color);
    });
    cursor(speedPlot, scene.startSec + tau);
    cursor(accelPlot, scene.startSec + tau);
    markDrawn('#fig-timing');
  });
}

// ---- Figure 9: the spacing chart of every ease, one row each, and the chosen ease's curve. ----
{
  const figure = document.getElementById('fig-ease');
  const canvas = figure.querySelector('canvas');
  const ctx = canvas.getContext('2d');
  const ep = { ease: 'smoothstep', frames: 7 };
  const plot = new Plot(document.getElementById('ease-plot'), {
    title: 'The chosen ease', xLabel: 'x, fraction of the time (no unit)', yLabel: 'e(x) and slope e′(x) (no unit)',
    series: ['e(x)', 'slope e′(x)', 'linear'], colors: [C.key, C.purple, C.ghost], minSpan: 0.5,
    widths: [3, 2, 1.5], dashes: [null, null, [6, 4]],
  });
  let rows = [];
  let rejected = '';
  const gui = new GUI({ container: figure.querySelector('.panel'), title: 'Spacing' });
  gui.add(ep, 'ease', EASES).name('ease');
  gui.add(ep, 'frames', 2, 30, 1).name('frames');
  const apply = guarded(gui, ep, () => {
    rows = Object.entries(EASES).map(([label, name]) => ({ label, name, ticks: spacingTicks(name, ep.frames) }));
    const c = columns(easeSamples(ep.ease, 101), 3);
    plot.setData([c[0], c[1], c[2], c[0]]);
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const easeNote = figure.querySelector('.note');
  const draw = () => {
    const r = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, Math.round(r.width * dpr));
    canvas.height = Math.max(1, Math.round(r.height * dpr));
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, r.width, r.height);
    ctx.font = '12px system-ui, sans-serif';
    const left = Math.min(150, r.width * 0.3); const right = r.width - 20;
    const rowH = (r.height - 16) / rows.length;
    rows.forEach((row, j) => {
      const y = 8 + rowH * (j + 0.5);
      const chosen = row.name === ep.ease;
      const color = chosen ? C.key : C.ink;
      if (chosen) { ctx.fillStyle = '#fdf1e0'; ctx.fillRect(0, y - rowH / 2, r.width, rowH); }
      ctx.fillStyle = color;
      ctx.fillText(row.label, 8, y + 4);
      ctx.strokeStyle = C.axis; ctx.lineWidth = 1;
      ctx.beginPath(); ctx.moveTo(left, y); ctx.lineTo(right, y); ctx.stroke();
      ctx.strokeStyle = chosen ? C.key : C.path; ctx.lineWidth = chosen ? 3 : 2;
      for (const f of row.ticks) {
        const x = left + f * (right - left);
        ctx.beginPath(); ctx.moveTo(x, y - rowH * 0.3); ctx.lineTo(x, y + rowH * 0.3); ctx.stroke();
      }
    });
  };
  let last = '';
  lesson.onFrame(() => {
    const r = canvas.getBoundingClientRect();
    const key = `${ep.ease} ${ep.frames} ${r.width} ${r.height}`;
    if (key !== last) { draw(); last = key; }
    // Each ease's first step, read off its chart (Rust's ticks): the numbers the Try this names.
    const first = rows.map((row) => `${row.label} ${row.ticks[1].toFixed(3)}`).join(', ');
    const text = [rejected, `First step of ${ep.frames} frames: ${first}.`].filter(Boolean).join(' ');
    if (easeNote.textContent !== text) easeNote.textContent = text;
    markDrawn('#fig-ease');
  });
}

refresh();
