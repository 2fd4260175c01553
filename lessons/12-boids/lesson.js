// Lesson 12: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/boids/, src/figures/boids.rs). The page only times the calls it makes.
import { startLesson, markDrawn, Plot, GUI, Timeline, columns, spanTimeline, guarded, showNote, cssVar, timeSweepStep } from '../../www/lesson.js';
import { BoidRulesScene, FlockScene, lawPlotSamples } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// The two distance laws with the flock's constants, sampled in Rust (no canvas needed).
const lawPlot = new Plot(document.getElementById('law-plot'), {
  title: 'The force laws f(x) with the flock\'s constants (positive: attraction)',
  xLabel: 'distance x (m)', yLabel: 'f(x) (m/s²)',
  series: ['a1/x² − a2/x⁴', 'Gaussian'], colors: [cssVar('--purple'), cssVar('--teal')], yRange: [-1.5, 1.5],
  // About 190 px of plot area: the zero crossings and the peaks the text names read off it.
  height: 300,
});
lawPlot.setData(columns(lawPlotSamples(300), 3));

// Figure 1: one boid's rules and its grid cell.
const rulesViewer = await lesson.figure('#fig-rules');
if (rulesViewer) {
  const scene = new BoidRulesScene();
  rulesViewer.setCamera(...scene.view());
  const p = { x: 0, z: 0, heading: 0, radius: 1.2, fov: 270, cell: 1.2, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-rules .panel'), title: 'One boid' });
  gui.add(p, 'x', -1.9, 1.9, 0.05).name('position x (m)');
  gui.add(p, 'z', -1.9, 1.9, 0.05).name('position z (m)');
  gui.add(p, 'heading', -180, 180, 5).name('heading (°)');
  gui.add(p, 'radius', 0.2, 3, 0.05).name('radius (m)');
  gui.add(p, 'fov', 0, 360, 5).name('field of view (°)');
  gui.add(p, 'cell', 0.25, 2, 0.05).name('grid cell size (m)');
  gui.add(p, 'useExercise').name('use my exercise');
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setPosition(p.x, p.z);
    scene.setHeadingDeg(p.heading);
    scene.setRadius(p.radius);
    scene.setFovDeg(p.fov);
    scene.setCellSize(p.cell);
    scene.setUseExercise(p.useExercise);
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('rules-note');
  lesson.onFrame(() => {
    showNote(note, [rejected, scene.draw(rulesViewer)].filter(Boolean).join(' '));
    markDrawn('#fig-rules');
  }, rulesViewer);
}

// Figure 2: the flock, its live step time, and step time against N.
const flockViewer = await lesson.figure('#fig-flock');
if (flockViewer) {
  flockViewer.setCamera(0, 0, 0, 9, 0.5, 0.45);
  const scene = new FlockScene();
  const timeline = new Timeline(document.getElementById('flock-timeline'), { duration: 20 });
  const rules = {
    cohesion: { weight: 1, radius: 1.5 },
    alignment: { weight: 2, radius: 1.5 },
    separation: { weight: 1.5, radius: 0.5 },
  };
  const p = {
    count: 300, fov: 270, maxSpeed: 1.8, minSpeed: 1.2, law: 'none', search: 'grid',
    leader: false, predator: false, obstacle: true, on: 'CPU',
  };
  const gui = new GUI({ container: document.querySelector('#fig-flock .panel'), title: 'Flock' });
  gui.add(p, 'count', 20, 3000, 10).name('boids');
  // The three weights in one open folder, the radii and the field of view in a closed one: the
  // Try this below sends the reader to the alignment and separation weights, so all three are
  // in view at once, and a folder per rule, all open, would make the panel taller than the
  // canvas at 1600 x 1000. The two folders take turns (opening one closes the other), so the
  // panel stays beside the canvas when the first Try this sends the reader to the field of
  // view (both open, it would run 80 px below the canvas).
  const weights = gui.addFolder('rule weights');
  const radii = gui.addFolder('rule radii (m), field of view');
  for (const [name, rule] of Object.entries(rules)) {
    weights.add(rule, 'weight', 0, 10, 0.1).name(name);
    radii.add(rule, 'radius', 0.1, 3, 0.05).name(name);
  }
  radii.add(p, 'fov', 0, 360, 5).name('field of view (°)');
  radii.close();
  gui.onOpenClose((changed) => {
    if (changed === radii && !radii._closed) weights.close();
    if (changed === weights && !weights._closed) radii.close();
  });
  gui.add(p, 'maxSpeed', 0.2, 5, 0.1).name('max speed (m/s)');
  gui.add(p, 'minSpeed', 0, 5, 0.1).name('min speed (m/s)');
  gui.add(p, 'law', ['none', 'a1/x² − a2/x⁴', 'Gaussian']).name('force law');
  gui.add(p, 'search', ['grid', 'naive']).name('neighbour search');
  gui.add(p, 'obstacle').name('obstacle');
  gui.add(p, 'leader').name('leader');
  gui.add(p, 'predator').name('predator');
  // CPU or a WebGPU compute shader, with the slider's flock or a larger one of its own (up to a
  // million boids on the GPU grid, 65,536 with every pair); on the GPU the search dropdown picks
  // the GPU grid or every pair. WebGL2 has no compute shaders, so there the switch is off. One
  // dropdown, not two: the panel must fit beside the canvas at 1600 x 1000.
  const hasCompute = flockViewer.backend === 'WebGPU';
  const gpuFlocks = { GPU: 0, 'GPU, 10,000 boids': 10_000, 'GPU, 100,000 boids': 100_000, 'GPU, 1,000,000 boids': 1_000_000 };
  const onControl = gui.add(p, 'on', ['CPU', ...Object.keys(gpuFlocks)]).name('step on');
  if (!hasCompute) onControl.disable();
  // The sweep's button sits above the plot it fills (one row less in the panel).
  document.getElementById('flock-measure').addEventListener('click', () => startSweep());
  let rejected = '';
  let count = 0;
  let on = 'CPU';
  const apply = guarded(gui, p, () => {
    if (p.count !== count) { scene.setCount(p.count); count = p.count; }
    for (const [name, rule] of Object.entries(rules)) scene.setRule(name, rule.weight, rule.radius);
    scene.setFovDeg(p.fov);
    scene.setMaxSpeed(p.maxSpeed);
    scene.setMinSpeed(p.minSpeed);
    scene.setLaw(p.law);
    scene.setSearch(p.search);
    scene.setObstacle(p.obstacle);
    scene.setLeader(p.leader);
    scene.setPredator(p.predator);
    if (hasCompute) scene.setGpuCount(gpuFlocks[p.on] ?? 0);
    if ((p.on === 'CPU') !== (on === 'CPU')) {
      scene.setGpu(flockViewer, p.on !== 'CPU');
      frameMs = 0;
    }
    on = p.on;
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();

  // Step time against N (Figure 3): Rust keeps the schedule (sizes, repeats, grid and naive in
  // turn) and sums the timings up; the page only times the calls. One timing per frame, so the
  // page stays responsive.
  const plot = new Plot(document.getElementById('flock-plot'), {
    title: 'One step of the flock: grid vs naive search', xLabel: 'boids N (count)', yLabel: 'step time (ms)',
    series: ['grid (median)', 'grid fastest', 'grid slowest', 'naive (median)', 'naive fastest', 'naive slowest',
      'slope 1: t ∝ N', 'slope 2: t ∝ N²', 'previous run: grid', 'previous run: naive'],
    colors: [cssVar('--z-axis'), cssVar('--z-axis'), cssVar('--z-axis'), cssVar('--x-axis'), cssVar('--x-axis'),
      cssVar('--x-axis'), cssVar('--grey'), cssVar('--dark'), cssVar('--pale-grey'), cssVar('--pale-grey')],
    // Each search's fastest timings dashed and its slowest dotted, so that the legend tells
    // them apart; the slope guides' dashes are longer. The previous run's two medians, pale
    // grey and dashed under one name, stay while the button's run measures.
    widths: [2.5, 1.5, 2, 2.5, 1.5, 2, 1.5, 1.5, 2.5, 2.5],
    dashes: [null, [5, 3], [1.5, 3], null, [5, 3], [1.5, 3], [10, 5], [10, 5], [6, 4], [6, 4]],
    log: 'xy', height: 300,
  });
  plot.setSeriesLabel(9, '');
  const status = document.getElementById('flock-sweep');
  // The last run that finished, as plotted; `previous`: the one shown beside a run that is
  // measuring (the sizes are the same each run, so its rows line up with the new run's).
  let finished = null;
  let previous = null;
  let running = false;
  function showSweep() {
    // NaN marks a search not timed at that size: a gap in the plot.
    const cols = columns(scene.sweepSamples(), 9).map((c, k) => (k === 0 ? c : c.map((v) => (Number.isFinite(v) && v > 0 ? v : null))));
    const x = previous?.[0].length > cols[0].length ? previous[0] : cols[0];
    const pad = (c) => x.map((_, i) => c?.[i] ?? null);
    plot.setSeriesLabel(8, previous ? 'previous run (medians)' : '');
    plot.setData([x, ...cols.slice(1).map(pad), pad(previous?.[1]), pad(previous?.[4])]);
    showNote(status, [scene.sweepNote(), previous
      ? '(The last run\'s medians stay, pale grey and dashed, until this run has timed every size.)' : ''].filter(Boolean).join(' '));
    return cols;
  }
  function startSweep() {
    previous = finished;
    running = true;
    scene.startSweep();
    showSweep();
  }
  function sweepStep() {
    if (timeSweepStep(scene, 256)) showSweep();
    else if (running) {
      running = false;
      previous = null;
      finished = showSweep();
    }
  }
  startSweep();

  // The flock's order over time, from Rust: polarisation and speed after every step since the
  // flock started, with the playhead.
  const ORDER_TITLE = 'Order of the flock';
  let orderOnGpu = false;
  const orderPlot = new Plot(document.getElementById('flock-order-plot'), {
    title: ORDER_TITLE, xLabel: 'time (s)', yLabel: 'fraction (0 to 1)',
    series: ['polarisation φ = |Σ v̂| / N', 'mean speed / max speed'],
    colors: [cssVar('--purple'), cssVar('--orange')], yRange: [0, 1],
  });

  const note = document.getElementById('flock-note');
  const timing = document.getElementById('flock-timing');
  // The step time averaged over recent frames, for the search and count it was measured at
  // (`measured`): a new count or search starts a new average, so that a paused flock does not
  // show the old count's time under the new count.
  let average = 0;
  let measured = '';
  let frame = 0;
  let frameMs = 0;
  let plotTime = -1;
  const gpuNote = hasCompute ? '' : ' (Step on GPU needs WebGPU: this browser draws with WebGL2, which has no compute shaders.)';
  lesson.onFrame((dt) => {
    const time = timeline.advance(dt);
    const onGpu = p.on !== 'CPU' && hasCompute;
    const t0 = performance.now();
    const steps = onGpu ? scene.advanceOnGpu(flockViewer, time) : scene.advanceTo(time);
    const ms = performance.now() - t0;
    if (measured !== `${p.search} ${count}`) {
      measured = `${p.search} ${count}`;
      average = 0;
    }
    // Per step; a replay after a loop or a scrub takes many steps at once and is left out.
    if (!onGpu && steps > 0 && steps < 10) average = average === 0 ? ms / steps : 0.9 * average + 0.1 * (ms / steps);
    frameMs = frameMs === 0 ? 1000 * dt : 0.9 * frameMs + 0.1 * 1000 * dt;
    showNote(note, [rejected, scene.draw(flockViewer)].filter(Boolean).join(' '));
    // Whenever the time moves (a scrub or the loop starts a new flock, whose samples begin at
    // the time it starts), so the curves reach the playhead, and every sixth frame when paused;
    // the x axis always spans the whole loop.
    if (time !== plotTime || frame % 6 === 0) {
      // On the GPU the samples come from the flock read back every 0.1 s, which arrives a few
      // frames late: the curves end short of the playhead, and the title says why.
      orderPlot.setData(spanTimeline(columns(scene.plotSamples(), 3), timeline.duration));
      plotTime = time;
    }
    if (onGpu !== orderOnGpu) {
      orderOnGpu = onGpu;
      orderPlot.setTitle(onGpu ? `${ORDER_TITLE} (read back from the GPU every 0.1 s, a few frames late)` : ORDER_TITLE);
    }
    orderPlot.setCursor(time);
    if (frame++ % 10 === 0) {
      const gpuCount = gpuFlocks[p.on] || count;
      showNote(timing, onGpu
        ? `Stepping ${gpuCount.toLocaleString('en')} boids on the GPU (${p.search === 'grid' ? 'GPU grid' : 'every pair'}): the steps are queued and run beside the page (the bench page times them); frame time ${frameMs.toFixed(1)} ms.`
        : average > 0
          ? `Measured step time (${p.search} search, ${count} boids): ${average.toFixed(2)} ms per step, averaged over recent frames.${gpuNote}`
          : `Step time (${p.search} search, ${count} boids): play the flock to measure it.${gpuNote}`);
    }
    markDrawn('#fig-flock');
  }, flockViewer);
  // The step-time sweep (Figure 3) goes on while the flock is out of sight.
  lesson.onFrame(() => {
    sweepStep();
    markDrawn('#fig-timing');
  });
} else {
  // No canvas for the flock (no WebGPU or WebGL2): nothing to time with.
  markDrawn('#fig-timing');
}
