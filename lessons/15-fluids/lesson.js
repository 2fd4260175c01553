// Lesson 15: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/fluid/, src/figures/fluid.rs), which also says what each figure draws and plots.
import { startLesson, markDrawn, Timeline, Plot, GUI, columns, spanTimeline, guarded, showNote, sentences, cssVar, timeSweepStep, dragInCanvas } from '../../www/lesson.js';
import { KernelsScene, DensityScene, DamBreakScene, SplashScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();
const ORANGE = cssVar('--orange');
const TEAL = cssVar('--teal');
const PURPLE = cssVar('--purple');
const BLUE = cssVar('--z-axis');
const RED = cssVar('--x-axis');
const DARK = cssVar('--dark');
const GREY = cssVar('--grey');

/** NaN (a curve that stops, a sample not taken) as uPlot's gap. */
const gaps = (cols) => cols.map((c, k) => (k === 0 ? c : c.map((v) => (Number.isFinite(v) ? v : null))));

// Figure 1: the kernels, plotted; no canvas.
{
  const scene = new KernelsScene();
  const gui = new GUI({ container: document.querySelector('#fig-kernels .panel'), title: 'Kernels' });
  const p = { h: 10, dim: '2D', useExercise: false };
  gui.add(p, 'h', 2, 30, 0.5).name('support radius h (cm)');
  gui.add(p, 'dim', ['2D', '3D']).name('dimension');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('kernels-plot'), {
    title: 'Kernels as shares of their peaks', xLabel: 'distance r (m)', yLabel: 'W (share of its peak)',
    series: ['poly6', 'spiky', 'spiky slope −dW/dr', 'viscosity ∇²W', 'your poly6 (use my exercise)'],
    colors: [PURPLE, BLUE, TEAL, ORANGE, DARK], widths: [3, 2, 2, 2, 2], dashes: [null, null, null, null, [6, 4]],
  });
  const note = document.getElementById('kernels-note');
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.set(p.h / 100, p.dim === '2D' ? 2 : 3);
    scene.setUseExercise(p.useExercise);
    const cols = columns(scene.samples(), 5);
    const yours = scene.yourCurve();
    cols.push(yours.length ? Array.from(yours, (v) => (Number.isFinite(v) ? v : null)) : cols[0].map(() => null));
    // 0 to 1, and as far as the student's curve goes beyond (a kernel that turns negative past h).
    const mine = cols[5].filter((v) => v !== null);
    plot.setYRange([Math.min(0, ...mine), Math.max(1, ...mine)]);
    plot.setData(cols);
  }, (m) => { rejected = m; });
  gui.onChange(() => { apply(); showNote(note, sentences(rejected, scene.note())); markDrawn('#fig-kernels'); });
  apply();
  showNote(note, scene.note());
  markDrawn('#fig-kernels');
}

// Figure 2: a pool at rest and one dragged particle.
{
  const viewer = await lesson.figure('#fig-density');
  if (viewer) {
    // Square-on to the slab, the whole box in view.
    viewer.setCamera(0.8, 0.5, 0, 2.6, 0, 0);
    const scene = new DensityScene();
    const gui = new GUI({ container: document.querySelector('#fig-density .panel'), title: 'Dragged particle' });
    const p = { x: 0.8, y: 0.2, useExercise: false };
    const xs = gui.add(p, 'x', 0, 1.6, 0.002).name('x (m)');
    const ys = gui.add(p, 'y', 0, 1, 0.002).name('y (m)');
    gui.add(p, 'useExercise').name('use my exercise');
    const terms = new Plot(document.getElementById('density-terms'), {
      title: 'Terms of the density sum, nearest first', xLabel: 'distance r / h (no unit)', yLabel: 'm W(r) (kg/m²)',
      // From 0 up (no term is negative): a lone term (the particle out of the water) would
      // otherwise sit in a range 0.1 wide round it, with nothing to compare it with.
      series: ['m W(r) of each term'], colors: [PURPLE], points: true, minSpan: 0.1, from0: true,
    });
    let rejected = '';
    const showTerms = () => terms.setData(columns(scene.terms(), 2));
    const apply = guarded(gui, p, () => {
      scene.setProbe(p.x, p.y);
      scene.setUseExercise(p.useExercise);
      showTerms();
    }, (m) => { rejected = m; });
    gui.onChange(apply);
    apply();

    // Dragging the particle with the mouse (the canvas's controls pan the flat pool on every other press).
    dragInCanvas(document.querySelector('#fig-density .stage canvas'), {
      grab: (...at) => scene.hitsProbe(...at),
      hover: (...at) => scene.hitsProbe(...at),
      drag: (...at) => {
        scene.dragProbe(...at);
        // Array.from: a Float32Array's own map would keep the rounded numbers as f32.
        [p.x, p.y] = Array.from(scene.probe(), (v) => Math.round(v * 1000) / 1000);
        xs.updateDisplay();
        ys.updateDisplay();
        showTerms();
      },
    });

    const note = document.getElementById('density-note');
    lesson.onFrame(() => {
      showNote(note, sentences(rejected, scene.draw(viewer)));
      markDrawn('#fig-density');
    }, viewer);
  }
}

// Figure 3: SPH beside PBF on one dam break; the plots show the run so far.
{
  const viewer = await lesson.figure('#fig-dam');
  if (viewer) {
    viewer.setCamera(0, 0.55, 0, 4, 0, 0);
    const scene = new DamBreakScene();
    const timeline = new Timeline(document.getElementById('dam-timeline'), { duration: scene.durationSec() });
    const gui = new GUI({ container: document.querySelector('#fig-dam .panel'), title: 'SPH' });
    const p = { k: 400, dt: 0.83 };
    gui.add(p, 'k', 25, 3200, 25).name('stiffness k');
    gui.add(p, 'dt', 0.25, 5, 0.01).name('SPH time step Δt (ms)');
    const compression = new Plot(document.getElementById('dam-compression'), {
      title: 'Largest compression', xLabel: 'time (s)', yLabel: 'max ρ/ρ₀ − 1 (share)',
      series: ['SPH', 'PBF'], colors: [BLUE, ORANGE], widths: [2, 3], minSpan: 0.05,
    });
    const energy = new Plot(document.getElementById('dam-energy'), {
      title: 'Kinetic energy', xLabel: 'time (s)', yLabel: 'energy (J per m of depth)',
      series: ['SPH', 'PBF'], colors: [BLUE, ORANGE], widths: [2, 3], minSpan: 1,
    });
    let rejected = '';
    // The fluids' time (the last sample's): on a slow machine it falls behind the timeline's, and
    // the plots' playhead shows where the drawn fluids are.
    let simulated = 0;
    const AHEAD = 0.25;
    const replot = () => {
      const all = gaps(columns(scene.samples(), 5));
      simulated = all[0].length ? all[0][all[0].length - 1] : 0;
      // The x axis spans the whole timeline from the start.
      spanTimeline(all, timeline.duration);
      compression.setData([all[0], all[1], all[2]]);
      energy.setData([all[0], all[3], all[4]]);
    };
    const apply = guarded(gui, p, () => {
      scene.setSph(p.k, p.dt);
      timeline.time = 0;
      timeline.show();
      replot();
    }, (m) => { rejected = m; });
    gui.onChange(apply);
    apply();
    const note = document.getElementById('dam-note');
    let frame = 0;
    lesson.onFrame((dt) => {
      timeline.advance(dt);
      // The timeline keeps at most AHEAD seconds ahead of the fluids: on a slow machine it waits
      // for them, so that a run reaches its end before the timeline wraps and starts it over.
      if (timeline.playing && timeline.time > simulated + AHEAD) {
        timeline.time = simulated + AHEAD;
        timeline.show();
      }
      const t = timeline.time;
      showNote(note, sentences(rejected, scene.draw(viewer, t)));
      if (frame++ % 6 === 0) replot();
      // Samples are read every 6 frames (0.1 s): within that the fluids keep up.
      const at = t - simulated < 0.15 ? t : simulated;
      compression.setCursor(at);
      energy.setCursor(at);
      markDrawn('#fig-dam');
    }, viewer);
  }
}

// Figures 4 and 5: the 3D splash, and the step time against N.
{
  const viewer = await lesson.figure('#fig-splash');
  if (viewer) {
    viewer.setCamera(0.8, 0.35, 0.3, 3, 0.5, 0.45);
    const scene = new SplashScene();
    const timeline = new Timeline(document.getElementById('splash-timeline'), { duration: scene.durationSec() });
    // A quarter of real speed: one PBF step of 1/240 s a 60 Hz frame.
    timeline.speed = 0.25;
    document.querySelector('#splash-timeline .speed').value = '0.25';
    const gui = new GUI({ container: document.querySelector('#fig-splash .panel'), title: 'Splash' });
    const p = { method: 'PBF', count: 3000, search: 'grid', vorticity: 0, on: 'CPU' };
    gui.add(p, 'method', ['PBF', 'SPH']).name('solver');
    gui.add(p, 'count', 500, 10000, 500).name('particles');
    gui.add(p, 'search', ['grid', 'all pairs']).name('neighbour search');
    gui.add(p, 'vorticity', 0, 0.5, 0.05).name('vorticity confinement ε (PBF)');
    // The CPU, or WebGPU compute shaders on the GPU grid with the slider's count or a larger
    // fluid of their own. WebGL2 has no compute shaders, so there the switch is off.
    const hasCompute = viewer.backend === 'WebGPU';
    const gpuFluids = { GPU: 0, 'GPU, 100,000 particles': 100_000, 'GPU, 1,000,000 particles': 1_000_000 };
    const onControl = gui.add(p, 'on', ['CPU', ...Object.keys(gpuFluids)]).name('step on');
    if (!hasCompute) onControl.disable();
    let rejected = '';
    const apply = guarded(gui, p, () => {
      scene.set(p.method, p.count, p.search, p.vorticity);
      if (hasCompute) scene.setGpu(viewer, p.on === 'CPU' ? 0 : (gpuFluids[p.on] || p.count));
      timeline.time = 0;
      timeline.show();
    }, (m) => { rejected = m; });
    gui.onChange(apply);
    apply();

    // Step time against N (Figure 5): Rust keeps the schedule and the statistics; the page only
    // times the calls, one timing per frame so the page stays responsive.
    // The GPU grid's three curves only where WebGPU times them: on WebGL2 their legend entries
    // would name curves that never come.
    const shown = hasCompute ? 11 : 8;
    const plot = new Plot(document.getElementById('splash-plot'), {
      title: hasCompute ? 'One SPH step in 3D: CPU grid vs all pairs vs GPU grid' : 'One SPH step in 3D: CPU grid vs all pairs',
      xLabel: 'particles N (count)', yLabel: 'step time (ms)',
      series: ['CPU grid (median)', 'CPU grid fastest', 'CPU grid slowest', 'all pairs (median)', 'all pairs fastest',
        'all pairs slowest', 'slope 1: t ∝ N', 'slope 2: t ∝ N²', 'GPU grid (median)', 'GPU grid fastest', 'GPU grid slowest'].slice(0, shown),
      colors: [BLUE, BLUE, BLUE, RED, RED, RED, GREY, DARK, TEAL, TEAL, TEAL].slice(0, shown),
      // As lesson 12's timing plot: fastest dashed, slowest dotted, the slope guides' dashes longer.
      widths: [2.5, 1.5, 2, 2.5, 1.5, 2, 1.5, 1.5, 2.5, 1.5, 2].slice(0, shown),
      dashes: [null, [5, 3], [1.5, 3], null, [5, 3], [1.5, 3], [10, 5], [10, 5], null, [5, 3], [1.5, 3]].slice(0, shown),
      log: 'xy', height: 300,
    });
    const status = document.getElementById('splash-sweep');
    const showSweep = () => {
      const cols = columns(scene.sweepSamples(), 12).slice(0, shown + 1)
        .map((c, k) => (k === 0 ? c : c.map((v) => (Number.isFinite(v) && v > 0 ? v : null))));
      plot.setData(cols);
      showNote(status, scene.sweepNote());
    };
    // The GPU grid's timings (WebGPU), after the CPU's: a few steps queued at once, timed until
    // the GPU has finished them; one timing at a time, beside the frames.
    let gpuTiming = false;
    const timeGpu = async () => {
      gpuTiming = true;
      try {
        if (!scene.gpuSweepNext(viewer)) return;
        await scene.gpuSettled();
        const t0 = performance.now();
        const steps = scene.gpuTimingSteps(viewer);
        await scene.gpuSettled();
        scene.gpuSweepRecord((performance.now() - t0) / steps);
        showSweep();
      } finally {
        gpuTiming = false;
      }
    };
    const sweepStep = () => {
      if (timeSweepStep(scene, 64)) showSweep();
      else if (hasCompute && !gpuTiming) timeGpu().catch((e) => showNote(status, String(e)));
    };
    document.getElementById('splash-measure').addEventListener('click', () => { scene.startSweep(); showSweep(); });
    scene.setGpuSweep(viewer);
    showSweep();

    const note = document.getElementById('splash-note');
    const gpuNote = hasCompute ? '' : 'Step on GPU needs WebGPU: this browser draws with WebGL2, which has no compute shaders.';
    // The timeline keeps at most AHEAD seconds ahead of the fluid, as the dam break's does: with
    // many particles a frame takes one step, and on a slow machine the timeline would wrap and
    // start the run over before the drop reached the pool. 0.05 s is 12 steps of 1/240 s, so a
    // paused fluid catches up with its clock within 12 frames.
    const AHEAD = 0.05;
    lesson.onFrame((dt) => {
      timeline.advance(dt);
      if (timeline.playing && timeline.time > scene.readySec + AHEAD) {
        timeline.time = scene.readySec + AHEAD;
        timeline.show();
      }
      const t = timeline.time;
      if (hasCompute && p.on !== 'CPU') scene.advanceOnGpu(viewer, t);
      else scene.advanceTo(t);
      showNote(note, sentences(rejected, scene.draw(viewer), gpuNote));
      markDrawn('#fig-splash');
    }, viewer);
    // The step-time sweep (Figure 5) goes on while the splash is out of sight.
    lesson.onFrame(() => {
      sweepStep();
      markDrawn('#fig-timing');
    });
  } else {
    markDrawn('#fig-timing');
  }
}
