// Lesson 05: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/noise, src/terrain, src/figures/noise.rs).
import { startLesson, markDrawn, Plot, GUI, columns, showNote, cssVar } from '../../www/lesson.js';
import {
  Noise1dScene, Noise2dScene, OctavesScene, TerrainFigureScene, TerrainNormalsScene, VariantsScene, TexturesScene,
  QuizScene, FractalsScene, NoiseImagesScene,
} from '../../pkg/inbetween.js';

const lesson = await startLesson();

/** Copies the accepted values back into `p` and the panel, after a setter rejected a change. */
function revert(gui, p, accepted) {
  Object.assign(p, accepted);
  gui.controllersRecursive().forEach((c) => c.updateDisplay());
}

/**
 * Calls `set()`; on an error, puts the controls back and returns the message for the note
 * ('' when accepted).
 */
function tryApply(gui, p, state, set) {
  try {
    set();
    state.accepted = { ...p };
    return '';
  } catch (e) {
    revert(gui, p, state.accepted);
    return `Not changed: ${e.message ?? e}`;
  }
}

/**
 * Whether a figure is on screen (or near it). Ten live canvases, four of them with meshes of
 * 16 000 to 100 000 vertices, are too much to redraw every frame on a software renderer, so each
 * figure draws only while it can be seen (and always for its first frame).
 */
function onScreen(selector) {
  const seen = { now: true, first: true };
  new IntersectionObserver((entries) => { seen.now = entries[entries.length - 1].isIntersecting; }, { rootMargin: '150px' })
    .observe(document.querySelector(selector));
  return () => {
    const draw = seen.now || seen.first;
    seen.first = false;
    return draw;
  };
}

const shown = Object.fromEntries(
  ['fig-1d', 'fig-2d', 'fig-octaves', 'fig-terrain', 'fig-normals', 'fig-variants', 'fig-quiz', 'fig-textures', 'fig-gpu', 'fig-fractals'].map((id) => [id, onScreen(`#${id}`)]),
);

// Figure 1: 1D noise.
const v1 = await lesson.figure('#fig-1d');
if (v1) {
  v1.setCamera(0, 0, 0, 7.5, 0, 0);
  const scene = new Noise1dScene();
  const p = { x: 2.35, seed: 0, ramps: true, useExercise: false };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-1d .panel'), title: '1D noise' });
  gui.add(p, 'x', 0, 7.99, 0.01).name('probe x');
  gui.add(p, 'seed', 0, 20, 1).name('seed (0: Perlin)');
  gui.add(p, 'ramps').name('show the two ramps');
  gui.add(p, 'useExercise').name('use my exercise');
  // The 1985 curve first and wide, so that fade(t), which nearly follows it, stays visible on top.
  // Tall enough for y ticks every 0.5: fade′ peaks at 1.875, and ticks at 0 and 1 alone hide it.
  const plot = new Plot(document.getElementById('n1-fade'), {
    title: 'The fade curve', xLabel: 't (position in the cell, 0 to 1)', yLabel: 'value (no unit)',
    series: ['3t² − 2t³ (1985)', 'fade(t)', 'fade′(t)'], colors: [cssVar('--grey'), cssVar('--z-axis'), cssVar('--orange')],
    widths: [5, 2, 2], minSpan: 0.5, height: 250,
  });
  const curvature = new Plot(document.getElementById('n1-curv'), {
    title: 'Second derivatives: the curvature at the ends of a cell', xLabel: 't (position in the cell, 0 to 1)',
    yLabel: 'second derivative (no unit)',
    series: ['(3t² − 2t³)″ = 6 − 12t (1985)', 'fade″(t)'], colors: [cssVar('--grey'), cssVar('--z-axis')],
    widths: [3, 2], minSpan: 1,
  });
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => {
      scene.setProbe(p.x);
      scene.setSeed(p.seed);
    });
    scene.setShowRamps(p.ramps);
    scene.setUseExercise(p.useExercise);
    // Rows [t, fade, fade′, 3t² − 2t³, fade″, (3t² − 2t³)″].
    const [t, f, d, cubic, f2, cubic2] = columns(scene.sampleFade(101), 6);
    plot.setData([t, cubic, f, d]);
    curvature.setData([t, cubic2, f2]);
    plot.setCursor(scene.probeT());
    curvature.setCursor(scene.probeT());
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('n1-note');
  lesson.onFrame(() => {
    if (!shown['fig-1d']()) return;
    showNote(note, rejected, scene.draw(v1));
    markDrawn('#fig-1d');
  });
}

// Figure 2: 2D noise and 3D slices.
const v2 = await lesson.figure('#fig-2d');
if (v2) {
  v2.setCamera(0, 0, 0, 2.9, 0.35, 0.75);
  const scene = new Noise2dScene();
  const p = { px: 0.4, py: 0.7, z: 0, seed: 0, useExercise: false };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-2d .panel'), title: '2D noise' });
  gui.add(p, 'px', -2, 1.99, 0.01).name('probe x');
  gui.add(p, 'py', -2, 1.99, 0.01).name('probe y');
  gui.add(p, 'z', 0, 2, 0.01).name('z slice (3D)');
  gui.add(p, 'seed', 0, 20, 1).name('seed (0: Perlin)');
  gui.add(p, 'useExercise').name('use my exercise');
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => {
      scene.setProbe(p.px, p.py);
      scene.setZ(p.z);
      scene.setSeed(p.seed);
    });
    scene.setUseExercise(p.useExercise);
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('n2-note');
  lesson.onFrame(() => {
    if (!shown['fig-2d']()) return;
    showNote(note, rejected, scene.draw(v2));
    markDrawn('#fig-2d');
  });
}

// Figure 3: octaves one by one.
const v3 = await lesson.figure('#fig-octaves');
if (v3) {
  v3.setCamera(0, 0, 0, 3.0, 0.3, 0.6);
  const scene = new OctavesScene();
  const p = { n: 3, alpha: 0.5, omega: 2, bandLimit: false, useExercise: false };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-octaves .panel'), title: 'Fractal sum' });
  gui.add(p, 'n', 0, 9, 1).name('N (last octave)');
  gui.add(p, 'alpha', 0, 1, 0.01).name('α (attenuation)');
  gui.add(p, 'omega', 1, 4, 0.01).name('ω (frequency gain)');
  gui.add(p, 'bandLimit').name('leave out octaves finer than the mesh');
  gui.add(p, 'useExercise').name('use my exercise');
  const names = [...Array(10).keys()].map((k) => `octave ${k}`);
  // The sum first and wide, so that octave 0 stays visible on top of it when N = 0. An octave
  // finer than the mesh (past scene.lastResolvedOctave()) is drawn in translucent grey (uPlot
  // calls a stroke function at every redraw): such octaves wiggle faster than the plot's pixels
  // and fill a band, through which the coloured octaves under it still show.
  const octaveColors = ['#1f6fd6', '#d62728', '#2ca02c', '#944fc9', '#17a2a8', '#e35d9c', '#8c564b', '#7f7f7f', '#bcbd22', '#9edae5'];
  let lastResolved = 9;
  const plot = new Plot(document.getElementById('oct-plot'), {
    title: 'The sum along v = 0.25, and each octave (grey: finer than the mesh)', xLabel: 'u (m)', yLabel: 'height (no unit)',
    series: ['sum', ...names],
    colors: [cssVar('--orange'), ...octaveColors.map((c, k) => () => (k > lastResolved ? 'rgba(128, 128, 128, 0.22)' : c))],
    widths: [5], minSpan: 0.2,
  });
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => scene.setParams(p.n, p.alpha, p.omega));
    scene.setBandLimit(p.bandLimit);
    scene.setUseExercise(p.useExercise);
    lastResolved = scene.lastResolvedOctave();
    // Rows [u, octave 0, …, octave 9, sum], 0.0005 m apart: fine enough for octave 9 itself.
    // Octaves above N come back as NaN: null leaves them out of the plot.
    const cols = columns(scene.sampleOctaves(4001), 12).map((c) => c.map((v) => (Number.isFinite(v) ? v : null)));
    plot.setData([cols[0], cols[11], ...cols.slice(1, 11)]);
    // Octaves above N are not in the sum: hidden, which dims their legend rows. An octave
    // finer than the mesh is grey: its swatch is repainted grey as its line.
    const rows = plot.plot.root.querySelectorAll('.u-legend .u-series');
    const skip = rows.length - (plot.plot.series.length - 1);
    for (let k = 0; k < names.length; k++) {
      const show = k <= p.n;
      if (plot.plot.series[k + 2].show !== show) plot.plot.setSeries(k + 2, { show });
      const marker = rows[k + 1 + skip]?.querySelector('.u-marker');
      if (marker) marker.style.background = k > lastResolved ? '#c8c8c8' : octaveColors[k];
    }
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('oct-note');
  lesson.onFrame(() => {
    if (!shown['fig-octaves']()) return;
    showNote(note, rejected, scene.draw(v3));
    markDrawn('#fig-octaves');
  });
}

// Figure 4: the course's terrain.
const v4 = await lesson.figure('#fig-terrain');
if (v4) {
  v4.setCamera(0, -0.05, 0, 3.0, 0.5, 0.6);
  const scene = new TerrainFigureScene();
  const variants = { sum: 0, ridge: 1, 'inverted ridge': 2, marble: 3, 'sliding f(x, y + t)': 4, 'evolving f(x, y, t)': 5 };
  const p = { n: 9, alpha: 0.4, omega: 2, h: 0.3, s: 1, o: 0, variant: 0, resolution: 128, seed: 0, bandLimit: false, useExercise: false };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-terrain .panel'), title: 'Terrain S(u, v)' });
  gui.add(p, 'n', 0, 12, 1).name('N (last octave)');
  gui.add(p, 'alpha', 0, 1, 0.01).name('α (attenuation)');
  gui.add(p, 'omega', 1, 4, 0.01).name('ω (frequency gain)');
  gui.add(p, 'h', 0, 1.5, 0.01).name('h (height)');
  gui.add(p, 's', 0.1, 6, 0.01).name('s (scale)');
  gui.add(p, 'o', -5, 5, 0.01).name('o (offset)');
  gui.add(p, 'variant', variants).name('variant');
  gui.add(p, 'resolution', { '64 × 64': 64, '128 × 128': 128, '256 × 256': 256, '512 × 512': 512 }).name('resolution');
  gui.add(p, 'seed', 0, 20, 1).name('seed (0: Perlin)');
  gui.add(p, 'bandLimit').name('leave out octaves finer than the mesh');
  gui.add(p, 'useExercise').name('use my exercise');
  const timing = document.getElementById('ter-timing');
  let shownMs = null;
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => {
      scene.setResolution(Number(p.resolution));
      scene.setSeed(p.seed);
      scene.setVariant(Number(p.variant));
      scene.setParams(p.n, p.alpha, p.omega, p.h, p.s, p.o);
    });
    scene.setBandLimit(p.bandLimit);
    scene.setUseExercise(p.useExercise);
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('ter-note');
  lesson.onFrame((dt) => {
    if (!shown['fig-terrain']()) return;
    scene.advance(Math.min(dt, 0.1));
    showNote(note, rejected, scene.draw(v4));
    const ms = scene.lastRegenerateMs;
    if (ms !== shownMs) {
      shownMs = ms;
      timing.textContent = `Last change: heights, exact normals and colours regenerated in ${ms.toFixed(1)} ms, then uploaded in place (this build, on the CPU).`;
    }
    markDrawn('#fig-terrain');
  });
}

// Figure 5: exact normals against averaged ones.
const vn = await lesson.figure('#fig-normals');
if (vn) {
  vn.setCamera(0, 0, 0, 3.0, 0.5, 0.6);
  const scene = new TerrainNormalsScene();
  const p = { resolution: 17, h: 0.3 };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-normals .panel'), title: 'Normals' });
  gui.add(p, 'resolution', { '9 × 9': 9, '17 × 17': 17, '33 × 33': 33, '65 × 65': 65, '129 × 129': 129 }).name('resolution');
  gui.add(p, 'h', 0, 1, 0.01).name('h (height)');
  // One sample per resolution offered, marked with dots. Brown, solid and dashed: the grey and
  // orange of the arrows name the two normals, and the angle between them is neither.
  const plot = new Plot(document.getElementById('nor-plot'), {
    title: 'Averaged against exact normals, by resolution', xLabel: 'vertices per side (count)',
    yLabel: 'angle between them (°)', series: ['mean', 'largest'], colors: [cssVar('--brown'), cssVar('--brown')],
    widths: [3, 2], dashes: [null, [6, 4]], minSpan: 1, points: true, from0: true,
  });
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => scene.setParams(Number(p.resolution), p.h));
    plot.setData(columns(scene.anglesByResolution(), 3));
    plot.setCursor(Number(state.accepted.resolution));
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('nor-note');
  lesson.onFrame(() => {
    if (!shown['fig-normals']()) return;
    showNote(note, rejected, scene.draw(vn));
    markDrawn('#fig-normals');
  });
}

// Figure 6: the variants side by side.
const vv = await lesson.figure('#fig-variants');
if (vv) {
  vv.setCamera(0, -0.1, 0.1, 6, 0, 0.8);
  const scene = new VariantsScene();
  const p = { n: 9, alpha: 0.4, h: 0.3 };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-variants .panel'), title: 'Variants' });
  gui.add(p, 'n', 0, 9, 1).name('N (last octave)');
  gui.add(p, 'alpha', 0, 1, 0.01).name('α (attenuation)');
  gui.add(p, 'h', 0, 1, 0.01).name('h (height)');
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => scene.setParams(p.n, p.alpha, p.h));
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('var-note');
  lesson.onFrame(() => {
    if (!shown['fig-variants']()) return;
    showNote(note, rejected, scene.draw(vv));
    markDrawn('#fig-variants');
  });
}

// Figure 7: the quiz.
const v5 = await lesson.figure('#fig-quiz');
if (v5) {
  v5.setCamera(0, -0.2, 0.2, 8.2, 0, 0.8);
  const scene = new QuizScene();
  const choices = { '?': 0, 'set 1': 1, 'set 2': 2, 'set 3': 3, 'set 4': 4, 'set 5': 5, 'set 6': 6 };
  const letters = ['a', 'b', 'c', 'd', 'e', 'f'];
  const p = {
    a: 0, b: 0, c: 0, d: 0, e: 0, f: 0,
    check: () => scene.check(),
    fresh: () => {
      scene.newRound();
      letters.forEach((l) => { p[l] = 0; });
      gui.controllersRecursive().forEach((c) => c.updateDisplay());
    },
  };
  const gui = new GUI({ container: document.querySelector('#fig-quiz .panel'), title: 'Your answers' });
  letters.forEach((l) => gui.add(p, l, choices).name(`terrain ${l}`));
  gui.add(p, 'check').name('check my answers');
  gui.add(p, 'fresh').name('new quiz (reshuffle)');
  gui.onChange((e) => {
    const i = letters.indexOf(e.property);
    if (i >= 0) scene.setAnswer(i, Number(p[e.property]));
  });
  const note = document.getElementById('quiz-note');
  lesson.onFrame(() => {
    if (!shown['fig-quiz']()) return;
    showNote(note, scene.draw(v5));
    markDrawn('#fig-quiz');
  });
}

// Figure 8: procedural textures.
const v6 = await lesson.figure('#fig-textures');
if (v6) {
  v6.setCamera(0, 0, 0.1, 6.2, 0, 1.3);
  const scene = new TexturesScene();
  const p = { scale: 4, turbulence: 5, n: 4, animate: false };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-textures .panel'), title: 'Textures' });
  gui.add(p, 'scale', 0.5, 12, 0.1).name('scale (cells across)');
  gui.add(p, 'turbulence', 0, 20, 0.1).name('turbulence τ');
  gui.add(p, 'n', 0, 8, 1).name('N (last octave)');
  gui.add(p, 'animate').name('animate (t)');
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => scene.setParams(p.scale, p.turbulence, p.n));
    scene.setAnimate(p.animate);
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('tex-note');
  lesson.onFrame((dt) => {
    if (!shown['fig-textures']()) return;
    scene.advance(Math.min(dt, 0.1));
    showNote(note, rejected, scene.draw(v6));
    markDrawn('#fig-textures');
  });
}

// Figure 9: Perlin and simplex noise, on the CPU and on the GPU (WGSL), with the GPU check.
const vg = await lesson.figure('#fig-gpu');
if (vg) {
  // Face on: the images stand in the plane z = 0 (src/figures/noise_images.rs).
  vg.setCamera(0, -0.15, 0, 6.2, 0, 0);
  const scene = new NoiseImagesScene();
  const p = { cells: 6, seed: 0, gpu: 'Perlin', lattice: false };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-gpu .panel'), title: 'Noise images' });
  gui.add(p, 'cells', 1, 32, 0.5).name('cells across');
  gui.add(p, 'gpu', ['Perlin', 'simplex']).name('GPU computes');
  gui.add(p, 'lattice').name('show the lattices');
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => scene.setParams(p.cells, p.seed));
    scene.setGpuSimplex(p.gpu === 'simplex');
    scene.setLattice(p.lattice);
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('gpu-note');
  const check = document.getElementById('gpu-check');
  lesson.onFrame(() => {
    if (!shown['fig-gpu']()) return;
    showNote(note, rejected, scene.draw(vg));
    const text = scene.gpuCheck || 'GPU check: reading the shader\'s image back…';
    if (check.textContent !== text) check.textContent = text;
    markDrawn('#fig-gpu');
  });
}

// Figure 10: fractals.
const v7 = await lesson.figure('#fig-fractals');
if (v7) {
  v7.setCamera(0, -0.1, 0, 5.6, 0, 0);
  const scene = new FractalsScene();
  const p = { depth: 3, previous: false };
  const state = { accepted: { ...p } };
  const gui = new GUI({ container: document.querySelector('#fig-fractals .panel'), title: 'Fractals' });
  gui.add(p, 'depth', 0, 7, 1).name('depth');
  gui.add(p, 'previous').name('show previous depth');
  let rejected = '';
  const apply = () => {
    rejected = tryApply(gui, p, state, () => scene.setDepth(p.depth));
    scene.setShowPrevious(p.previous);
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('frac-note');
  lesson.onFrame(() => {
    if (!shown['fig-fractals']()) return;
    showNote(note, rejected, scene.draw(v7));
    markDrawn('#fig-fractals');
  });
}
