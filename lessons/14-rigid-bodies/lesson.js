// Lesson 14: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/rigid_body/, src/figures/rigid_body.rs). Each scene steps to the timeline's time and its
// plots show the whole run at the figure's settings, with the cursor at the time.
import { startLesson, markDrawn, Timeline, Plot, GUI, columns, spanTimeline, guarded, showNote, cssVar } from '../../www/lesson.js';
import { ThrowScene, DriftScene, RacketScene, ImpulseScene, StackScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();
const ORANGE = cssVar('--orange');
const TEAL = cssVar('--teal');
const PURPLE = cssVar('--purple');
const DARK = cssVar('--dark');

/**
 * The common wiring of a figure: its panel, its timeline, its plots (each `{ id, options, cols }`:
 * `cols` picks the sample columns it shows, the first being time; `range: k` takes its y range from the scene's
 * `plotRanges()`, pair k; on a log y axis, `options.log`, a sample of 0 is a gap),
 * `apply` run on every change
 * (through `guarded`, so a rejected value shows in the note and changes nothing), and the frame
 * loop that draws the scene at the timeline's time. A `live` scene (one a button can push) plots
 * what it has run so far, refreshed ten times a second, instead of the whole run.
 */
async function wire(selector, { title, make, controls, apply, plots, width, camera, live = false }) {
  const viewer = await lesson.figure(selector);
  if (!viewer) return null;
  if (camera) viewer.setCamera(...camera);
  const state = { scene: make(), rejected: '' };
  const id = selector.slice(1).replace(/^fig-/, '');
  const timeline = new Timeline(document.getElementById(`${id}-timeline`), { duration: state.scene.durationSec() });
  const gui = new GUI({ container: document.querySelector(`${selector} .panel`), title });
  const p = controls(gui, state, timeline);
  const shown = plots.map((plot) => ({ ...plot, plot: new Plot(document.getElementById(plot.id), plot.options) }));
  const replot = () => {
    // A racket that exploded has NaN samples from then on: gaps in its curves.
    const all = columns(state.scene.samples(), width).map((c) => c.map((v) => (Number.isFinite(v) ? v : null)));
    // A live plot's x axis spans the whole timeline from the start.
    if (live) spanTimeline(all, timeline.duration);
    // Scales Rust chooses (an exploding racket's curve runs off the top instead of squashing the others).
    const ranges = shown.some((s) => s.range !== undefined) ? state.scene.plotRanges() : [];
    for (const { plot, cols, range, options } of shown) {
      if (range !== undefined) plot.setYRange([ranges[2 * range], ranges[2 * range + 1]]);
      // A log axis has no place for a zero (a run's still first sample): a gap there.
      const positive = options.log?.includes('y');
      const data = cols.map((c, k) => (positive && k > 0 ? all[c].map((v) => (v > 0 ? v : null)) : all[c]));
      plot.setData(data);
    }
  };
  const run = guarded(gui, p, () => { apply(state.scene, p); replot(); }, (m) => { state.rejected = m; });
  gui.onChange(run);
  run();
  const note = document.getElementById(`${id}-note`);
  let frame = 0;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [state.rejected, state.scene.draw(viewer, t)].filter(Boolean).join(' '));
    if (live && frame++ % 6 === 0) replot();
    for (const { plot } of shown) plot.setCursor(t);
    markDrawn(selector);
  }, viewer);
  return { viewer, state, timeline, replot, run };
}

// Figure 1: a box thrown with spin; L stands still, ω circles round it.
await wire('#fig-throw', {
  title: 'Throw',
  make: () => new ThrowScene(),
  controls: (gui) => {
    const p = { spin: 10, tilt: 20 };
    gui.add(p, 'spin', 0, 15, 0.5).name('spin (rad/s)');
    gui.add(p, 'tilt', 0, 80, 1).name('tilt of the spin axis (°)');
    return p;
  },
  apply: (scene, p) => scene.setThrow(p.spin, p.tilt),
  width: 4,
  plots: [
    {
      id: 'throw-plot', cols: [0, 1, 2],
      options: {
        title: 'Sizes over the flight', xLabel: 'time (s)', yLabel: 'size (share of the throw\'s)',
        series: ['|ω|', '|L|'], colors: [TEAL, PURPLE], widths: [2, 4], minSpan: 0.05,
      },
    },
    {
      id: 'throw-angle', cols: [0, 3],
      options: {
        title: 'Angle between ω and L', xLabel: 'time (s)', yLabel: 'angle (°)',
        series: ['angle'], colors: [DARK], minSpan: 5,
      },
    },
  ],
});

// Figure 2: quaternion drift, three orientation steps side by side.
await wire('#fig-drift', {
  title: 'Quaternion steps',
  // Square-on to the row, from far: the three boxes at the same size and seen alike.
  camera: [0, 1, 0, 6, 0, 0.12],
  make: () => new DriftScene(),
  controls: (gui) => {
    const p = { spin: 5, step: 10, useExercise: false };
    gui.add(p, 'spin', 1, 30, 0.5).name('spin (rad/s)');
    gui.add(p, 'step', 1, 50, 0.1).name('step Δt (ms)');
    gui.add(p, 'useExercise').name('use my exercise');
    return p;
  },
  apply: (scene, p) => { scene.setDrift(p.spin, p.step); scene.setUseExercise(p.useExercise); },
  width: 4,
  plots: [{
    id: 'drift-plot', cols: [0, 1, 2, 3],
    options: {
      title: 'Length of each quaternion', xLabel: 'time (s)', yLabel: '|q| (no unit)',
      // Logarithmic: the unnormalised length grows geometrically (a straight line here), from
      // 1 to the 10⁶ where the figure stops stepping it. The normalised and exponential lengths
      // both stay at 1: the exponential's line is dashed over the wider orange one, so both show.
      series: ['normalised', 'unnormalised', 'exponential'], colors: [ORANGE, TEAL, PURPLE], widths: [5, 2, 2],
      dashes: [null, null, [6, 5]], log: 'y',
    },
  }],
});

// Figure 3: the tennis racket, three angular integrators.
await wire('#fig-racket', {
  title: 'Racket',
  camera: [0, 0.9, 0, 5, 0, 0.15],
  make: () => new RacketScene(),
  controls: (gui) => {
    const p = { spin: 6, wobble: 0.05, useExercise: false };
    gui.add(p, 'spin', 0.5, 20, 0.5).name('spin (rad/s)');
    gui.add(p, 'wobble', 0, 1, 0.01).name('wobble (rad/s)');
    gui.add(p, 'useExercise').name('use my exercise');
    return p;
  },
  apply: (scene, p) => { scene.setSpin(p.spin, p.wobble); scene.setUseExercise(p.useExercise); },
  width: 7,
  plots: [
    {
      id: 'racket-energy', cols: [0, 1, 2, 3], range: 0,
      options: {
        title: 'Kinetic energy', xLabel: 'time (s)', yLabel: 'energy (share of the start)',
        series: ['L held', 'explicit', 'implicit'], colors: [PURPLE, ORANGE, TEAL], widths: [4, 2, 2], minSpan: 0.02,
      },
    },
    {
      id: 'racket-momentum', cols: [0, 4, 5, 6], range: 1,
      options: {
        title: 'Angular momentum |L|', xLabel: 'time (s)', yLabel: '|L| (share of the start)',
        series: ['L held', 'explicit', 'implicit'], colors: [PURPLE, ORANGE, TEAL], widths: [4, 2, 2], minSpan: 0.02,
      },
    },
  ],
});

// Figure 4: one impulse at a corner.
await wire('#fig-impulse', {
  title: 'Impulse',
  make: () => new ImpulseScene(),
  controls: (gui) => {
    const p = { tilt: 20, e: 0.5, height: 1, useExercise: false };
    gui.add(p, 'tilt', 0, 45, 1).name('tilt (°)');
    gui.add(p, 'e', 0, 1, 0.05).name('restitution e');
    gui.add(p, 'height', 0.2, 2, 0.05).name('drop height (m)');
    gui.add(p, 'useExercise').name('use my exercise');
    return p;
  },
  apply: (scene, p) => { scene.setDrop(p.tilt, p.e, p.height); scene.setUseExercise(p.useExercise); },
  width: 4,
  plots: [{
    id: 'impulse-plot', cols: [0, 2],
    options: {
      title: 'Normal velocity of the lowest corner, then of the one that hit', xLabel: 'time (s)', yLabel: 'velocity (m/s)',
      series: ['corner'], colors: [ORANGE], minSpan: 0.5,
    },
  }],
});

// Figure 5: a stack or a row of dominoes, sequential impulses.
await wire('#fig-stack', {
  title: 'Contacts',
  make: () => new StackScene('stack'),
  controls: (gui, state, timeline) => {
    const p = {
      preset: 'stack', iterations: 20, friction: 0.5, e: 0,
      push: () => { state.scene.push(); },
      reset: () => { state.scene.reset(); timeline.time = 0; timeline.show(); },
    };
    gui.add(p, 'preset', ['stack', 'dominoes']).name('scene').onChange((v) => {
      state.scene.free();
      state.scene = new StackScene(v);
      timeline.duration = state.scene.durationSec();
      timeline.time = 0;
      timeline.show();
    });
    gui.add(p, 'iterations', 1, 50, 1).name('solver iterations');
    gui.add(p, 'friction', 0, 1, 0.05).name('friction μ');
    gui.add(p, 'e', 0, 1, 0.05).name('restitution e');
    gui.add(p, 'push').name('push');
    gui.add(p, 'reset').name('reset');
    return p;
  },
  apply: (scene, p) => scene.setSolver(p.iterations, p.friction, p.e),
  width: 3,
  live: true,
  plots: [
    {
      // Logarithmic: a stack at rest keeps a few µJ (the passes' leftovers, which fall as the
      // passes grow), a push gives joules; on a linear axis either one is a flat line.
      id: 'stack-plot', cols: [0, 1],
      options: {
        title: 'Total kinetic energy', xLabel: 'time (s)', yLabel: 'energy (J)',
        series: ['energy'], colors: [ORANGE], log: 'y',
      },
    },
    {
      id: 'stack-drift', cols: [0, 2],
      options: {
        title: 'How far the top box (the last domino) has moved', xLabel: 'time (s)', yLabel: 'distance (m)',
        // Never negative: the axis starts at 0 instead of centring a flat start.
        series: ['distance'], colors: [TEAL], minSpan: 0.05, from0: true,
      },
    },
  ],
});
