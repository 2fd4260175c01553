// Lesson 13: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/cloth/, src/figures/cloth.rs), including picking and dragging a particle. The page only
// times the calls it makes.
import { startLesson, markDrawn, Timeline, Plot, GUI, columns, spanTimeline, guarded, showNote, cssVar, dragInCanvas } from '../../www/lesson.js';
import { ClothScene, SpringScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();
const ORANGE = cssVar('--orange');
const TEAL = cssVar('--teal');
// Every plot draws mass-spring wide under a narrow XPBD line, so the two stay visible where
// they coincide.
// Columns of flat samples, with NaN (after an explosion) as a gap.
const gaps = (flat, width) => columns(flat, width).map((c) => c.map((v) => (Number.isFinite(v) ? v : null)));

/**
 * Dragging a particle: taken only while the timeline plays and Rust finds a particle under the
 * pointer; otherwise the drag orbits the camera.
 */
function dragParticles(selector, scene, timeline) {
  dragInCanvas(document.querySelector(`${selector} .stage canvas`), {
    grab: (...at) => timeline.playing && scene.grab(...at),
    drag: (...at) => scene.drag(...at),
    release: () => scene.release(),
  });
}

// Figure 1: one spring, one constraint (the exercises).
const springViewer = await lesson.figure('#fig-spring');
if (springViewer) {
  springViewer.setCamera(0, 1.7, 0, 3.8, 0.1, 0.08);
  const scene = new SpringScene();
  const timeline = new Timeline(document.getElementById('spring-timeline'), { duration: scene.durationSec() });
  const p = { k: 40, c: 0.05, step: 16.7, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-spring .panel'), title: 'One spring' });
  gui.add(p, 'k', 1, 400, 1).name('stiffness k (N/m)');
  gui.add(p, 'c', 0, 1, 0.01).name('damping c (N·s/m)');
  gui.add(p, 'step', 2, 80, 0.1).name('step h (ms)');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('spring-plot'), {
    title: 'Distance from the anchor', xLabel: 'time (s)', yLabel: 'length (m)',
    series: ['mass-spring', 'XPBD'], colors: [ORANGE, TEAL], widths: [5, 1.5], minSpan: 0.1,
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setStiffness(p.k);
    scene.setDamping(p.c);
    scene.setStepMs(p.step);
    scene.setUseExercise(p.useExercise);
    plot.setData(gaps(scene.lengthSamples(), 3));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('spring-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(springViewer, t)].filter(Boolean).join(' '));
    plot.setCursor(t);
    markDrawn('#fig-spring');
  }, springViewer);
}

// Figure 2: two flags, mass-spring and XPBD, with energy and stretch plots.
const flagViewer = await lesson.figure('#fig-flag');
if (flagViewer) {
  flagViewer.setCamera(0, 1.9, 0, 5.0, 0.3, 0.18);
  const scene = new ClothScene('flag');
  const timeline = new Timeline(document.getElementById('flag-timeline'), { duration: scene.durationSec() });
  const defaults = { structural: 100, shear: 50, bending: 20, damping: 0.02, step: 16.7, substeps: 10, wind: 6, pins: 'whole edge' };
  const p = {
    ...defaults,
    explode: () => { Object.assign(p, { structural: 2000, substeps: 4 }); refresh(); apply(); },
    reset: () => { Object.assign(p, defaults); refresh(); apply(); scene.reset(); timeline.time = 0; timeline.show(); },
    measure: () => measure(),
  };
  const gui = new GUI({ container: document.querySelector('#fig-flag .panel'), title: 'Flags' });
  const refresh = () => gui.controllersRecursive().forEach((c) => c.updateDisplay());
  const springs = gui.addFolder('stiffness k (N/m)');
  // From 50 N/m (the figure's minimum: a flag without structural springs is not a cloth) to the
  // figure's maximum, so that the note's advice never names a setting already at its end.
  springs.add(p, 'structural', 50, 5000, 10).name('structural');
  springs.add(p, 'shear', 0, 1000, 5).name('shear');
  springs.add(p, 'bending', 0, 500, 5).name('bending');
  gui.add(p, 'damping', 0, 0.3, 0.005).name('damping c (N·s/m)');
  gui.add(p, 'step', 5, 50, 0.1).name('frame step Δt (ms)');
  gui.add(p, 'substeps', 1, 40, 1).name('substeps');
  gui.add(p, 'wind', 0, 20, 0.5).name('wind (m/s)');
  gui.add(p, 'pins', ['whole edge', 'two corners']).name('pins');
  gui.add(p, 'explode').name('push past the stability limit');
  gui.add(p, 'measure').name('measure the substeps needed');
  gui.add(p, 'reset').name('reset');
  const energy = new Plot(document.getElementById('flag-energy'), {
    title: 'Total energy (kinetic + gravity + springs)', xLabel: 'time (s)', yLabel: 'energy (J)',
    series: ['mass-spring', 'XPBD'], colors: [ORANGE, TEAL], widths: [5, 1.5], minSpan: 0.1,
  });
  const stretch = new Plot(document.getElementById('flag-stretch'), {
    title: 'Largest stretch of a structural spring', xLabel: 'time (s)', yLabel: 'stretch (%)',
    series: ['mass-spring', 'XPBD'], colors: [ORANGE, TEAL], widths: [5, 1.5], minSpan: 1,
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    for (const kind of ['structural', 'shear', 'bending']) scene.setStiffness(kind, p[kind]);
    scene.setDamping(p.damping);
    scene.setStepMs(p.step);
    scene.setSubsteps(p.substeps);
    scene.setWind(p.wind);
    scene.setPins(p.pins);
  }, (m) => { rejected = m; });
  // (lil-gui keeps one onChange handler per GUI: this one applies the settings, then marks the
  // third plot as measured at other settings when they changed.)
  gui.onChange(() => {
    apply();
    if (search?.done() === 6 && settings() !== measuredAt) substepsNote.textContent = stale;
  });
  apply();
  // The third plot: the fewest substeps that keep the mass-spring flag whole for the 6 s, against
  // the structural stiffness, at the settings of the last measurement. Rust runs the flag about
  // 36 times; it goes on a few frames of simulation per drawn frame, so the page stays live and
  // the points appear one by one. It starts at load and on the button, not on every change.
  const substeps = new Plot(document.getElementById('flag-substeps'), {
    title: 'Substeps the mass-spring flag needs', xLabel: 'structural stiffness k (N/m)', yLabel: 'substeps (per frame)',
    series: ['measured (fewest that hold)', 'c·√k fitted', 'conservative limit ⌈Δt/h⌉'],
    colors: [ORANGE, cssVar('--dark'), cssVar('--grey')], widths: [4, 1.5, 1.5], dashes: [null, [6, 4], [2, 3]],
    minSpan: 5,
  });
  const substepsNote = document.getElementById('flag-substeps-note');
  // What the plot depends on (the structural stiffness is its x axis).
  const settings = () => JSON.stringify(['shear', 'bending', 'damping', 'step', 'wind', 'pins'].map((k) => p[k]));
  let search = null;
  let measuredAt = '';
  const stale = 'The third plot shows the settings of its last measurement: press ' +
    '"measure the substeps needed" to measure at these.';
  const showSearch = () => {
    substeps.setData(gaps(search.rows(), 4));
    const missing = columns(search.rows(), 4)[1].some((v) => !Number.isFinite(v));
    if (search.done() < 6) {
      substepsNote.textContent = `Measuring the third plot: ${search.done()} of 6 stiffnesses done…`;
    } else if (settings() !== measuredAt) {
      substepsNote.textContent = stale;
    } else {
      substepsNote.textContent = 'The third plot is measured at these settings' +
        (missing ? '; a missing point needs more than 40 substeps.' : '.');
    }
  };
  const measure = () => {
    try {
      search?.free();
      search = scene.substepSearch();
      measuredAt = settings();
      showSearch();
    } catch (e) {
      search = null;
      substepsNote.textContent = `Not measured: ${e.message ?? e}`;
    }
  };
  measure();
  lesson.onFrame(() => {
    if (!search || search.done() === 6) return;
    // Batches of 10 frames of one small flag (well under a millisecond each) for up to 8 ms of
    // each drawn frame.
    const until = performance.now() + 8;
    while (search.done() < 6 && performance.now() < until) search.work(10);
    showSearch();
  });
  dragParticles('#fig-flag', scene, timeline);
  const note = document.getElementById('flag-note');
  let shown = -1;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(flagViewer, t)].filter(Boolean).join(' '));
    // A new frame, an explosion (the ranges follow the cloths that held) or a replay changes
    // the generation; only then are the samples copied out of the wasm.
    const key = scene.sampleGeneration();
    if (key !== shown) {
      shown = key;
      // The x axis spans the whole timeline: after a change, the first sample at 0 s alone.
      const [time, e0, e1, s0, s1] = spanTimeline(gaps(scene.samples(), 5), timeline.duration);
      // Scales that follow the cloths that held (Rust's choice): an explosion's last samples
      // would squash the other flag's curves onto a line.
      const r = scene.plotRanges();
      energy.setYRange([r[0], r[1]]);
      stretch.setYRange([r[2], r[3]]);
      energy.setData([time, e0, e1]);
      stretch.setData([time, s0, s1]);
    }
    energy.setCursor(t);
    stretch.setCursor(t);
    markDrawn('#fig-flag');
  }, flagViewer);
}

// Figure 3: a cloth falling on a sphere and a box, one method at a time, timed.
const drapeViewer = await lesson.figure('#fig-drape');
if (drapeViewer) {
  drapeViewer.setCamera(0.5, 0.6, 0, 5.0, 0.45, 0.5);
  const scene = new ClothScene('drape');
  const timeline = new Timeline(document.getElementById('drape-timeline'), { duration: scene.durationSec() });
  const p = {
    method: 'mass-spring', resolution: 20, sphereX: 0, boxX: -0.9, boxZ: 0.7, friction: 0.3,
    pins: 'none', reset: () => { scene.reset(); timeline.time = 0; timeline.show(); },
  };
  const gui = new GUI({ container: document.querySelector('#fig-drape .panel'), title: 'Drape' });
  gui.add(p, 'method', ['mass-spring', 'XPBD']).name('method');
  // A few resolutions rather than a slider: each costs a replay from the start.
  gui.add(p, 'resolution', [10, 20, 40, 100]).name('particles per side');
  gui.add(p, 'sphereX', -1.5, 1.5, 0.05).name('sphere x (m)');
  gui.add(p, 'boxX', -1.5, 1.5, 0.05).name('box x (m)');
  gui.add(p, 'boxZ', -1.5, 1.5, 0.05).name('box z (m)');
  gui.add(p, 'friction', 0, 2, 0.05).name('friction μ');
  gui.add(p, 'pins', ['none', 'two corners', 'whole edge']).name('pins');
  gui.add(p, 'reset').name('reset');
  const note = document.getElementById('drape-note');
  const timing = document.getElementById('drape-timing');
  let average = 0;
  // The first frames a cloth plays run while the browser is still compiling and warming its
  // caches (at the page's start up to twice as slow): they are left out of the average.
  const WARM_UP_FRAMES = 10;
  let warmUp = 0;
  let frame = 0;
  // The measurement belongs to one cloth: a new resolution or method starts it again (the old
  // line would name the new cloth with the old cloth's time).
  let timed = '';
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setMethod(p.method);
    scene.setResolution(p.resolution);
    scene.setObstacles(p.sphereX, p.boxX, p.boxZ);
    scene.setFriction(p.friction);
    scene.setPins(p.pins);
    const cloth = `${p.resolution} × ${p.resolution}, ${p.method}`;
    if (cloth !== timed) {
      timed = cloth;
      average = 0;
      warmUp = 0;
      showNote(timing, `Measuring the time per frame of the ${cloth} cloth while it plays…`);
    }
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  dragParticles('#fig-drape', scene, timeline);
  // The largest stretch over time, in the colour of the method that ran (the other series stays
  // empty): the note gives the value at the cursor, the plot its range over the run. The run of
  // the cloth shown before (another resolution or method) stays beside it, grey and dashed, so
  // two cloths compare on one plot.
  const stretch = new Plot(document.getElementById('drape-stretch'), {
    title: 'Largest stretch of a structural spring', xLabel: 'time (s)', yLabel: 'stretch (%)',
    series: ['mass-spring', 'XPBD', 'previous cloth'], colors: [ORANGE, TEAL, cssVar('--grey')],
    widths: [2.5, 2.5, 2], dashes: [null, null, [6, 4]], minSpan: 1,
  });
  stretch.setSeriesLabel(2, '');
  let plotted = -1;
  // The cloth plotted and its run (`time` and `largest`, one row a frame from 0 s; `held`: it
  // did not explode), and the previous cloth's run; the drape's frame step is fixed, so the two
  // runs' rows line up.
  let shownRun = null;
  let previous = null;
  const finite = (values) => values.filter(Number.isFinite);
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    const t0 = performance.now();
    const text = scene.draw(drapeViewer, t);
    const ms = performance.now() - t0;
    // The method picks the series' colour; changing it replays the run, a new generation.
    const key = scene.sampleGeneration();
    if (key !== plotted) {
      plotted = key;
      const cloth = `${p.resolution} × ${p.resolution} ${p.method}`;
      // A new cloth: the one before becomes the previous run if it ran a second or more. A
      // shorter run (a cloth that exploded at once, or one changed before it landed) would be a
      // stub along the axis under this run's start, named in the legend but not to be seen.
      if (shownRun && shownRun.cloth !== cloth) {
        const ran = shownRun.time.filter((_, i) => Number.isFinite(shownRun.largest[i])).at(-1) ?? 0;
        previous = ran >= 1 ? shownRun : null;
      }
      const [time, , largest] = columns(scene.samples(), 3);
      shownRun = { cloth, time, largest, held: scene.explodedAt(0) === undefined };
      const x = [...(previous?.time.length > time.length ? previous.time : time)];
      const column = (values) => x.map((_, i) => (Number.isFinite(values?.[i]) ? values[i] : null));
      const none = x.map(() => null);
      const mine = column(largest);
      const [x2, s0, s1, s2] = spanTimeline([x, ...(p.method === 'XPBD' ? [none, mine] : [mine, none]), column(previous?.largest)], timeline.duration);
      // The y range Rust picks for this run, widened to a previous run that held (an exploded
      // one's last samples before it shoot up and would squash this run onto a line).
      const r = scene.plotRanges();
      const before = previous?.held ? finite(previous.largest) : [];
      stretch.setYRange([Math.min(r[2], ...before), Math.max(r[3], ...before)]);
      stretch.setSeriesLabel(2, previous ? `previous: ${previous.cloth}` : '');
      stretch.setData([x2, s0, s1, s2]);
    }
    stretch.setCursor(t);
    // The frames this draw simulated (Rust counts them; 0 after a replay from the start): a
    // slow page simulates several per drawn frame, and each gets its share of the time.
    const frames = scene.lastStepFrames();
    // An exploded cloth is frozen (no more steps): its frames would time the drawing alone.
    const exploded = scene.explodedAt(0);
    if (exploded === undefined && timeline.playing && frames >= 1) {
      if (warmUp < WARM_UP_FRAMES) warmUp += 1;
      else average = average === 0 ? ms / frames : 0.9 * average + 0.1 * (ms / frames);
    }
    showNote(note, [rejected, text].filter(Boolean).join(' '));
    if (exploded !== undefined) {
      const before = average > 0 ? ` Before it, ${average.toFixed(2)} ms per frame.` : '';
      showNote(timing, `The timing stopped at t = ${exploded.toFixed(2)} s, when the ${p.resolution} × ${p.resolution} ${p.method} cloth exploded: nothing is simulated after that.${before}`);
    } else if (frame++ % 15 === 0 && average > 0) {
      showNote(timing, `Measured here: ${average.toFixed(2)} ms per simulated frame (${p.resolution} × ${p.resolution}, ${p.method}, 10 substeps, simulation and upload, this build of the wasm; the run's first ${WARM_UP_FRAMES} frames, the warm-up, left out).`);
    }
    markDrawn('#fig-drape');
  }, drapeViewer);
}
