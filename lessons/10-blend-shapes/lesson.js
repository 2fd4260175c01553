// Lesson 10: wires the page's controls to the wasm scene. No math here: it lives in Rust
// (src/blend_shapes/, src/figures/blend_shapes.rs).
import { startLesson, markDrawn, Timeline, Plot, columns, GUI, showNote } from '../../www/lesson.js';
import { BlendShapeFaceScene, BlendShapeTargetsScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// Figure 1: the base and each target alone, at one weight.
const targetsViewer = await lesson.figure('#fig-targets');
if (targetsViewer) {
  const scene = new BlendShapeTargetsScene();
  targetsViewer.setCamera(0, 0, 0, 9, 0.2, 0.05);
  const p = { weight: 1, deltas: true };
  const gui = new GUI({ container: document.querySelector('#fig-targets .panel'), title: 'Targets' });
  gui.add(p, 'weight', 0, 1.5, 0.01).name('weight w of each target').onChange((w) => scene.setWeight(w));
  gui.add(p, 'deltas').name('delta arrows').onChange((on) => scene.setShowDeltas(on));
  const note = document.getElementById('targets-note');
  lesson.onFrame(() => {
    showNote(note, scene.draw(targetsViewer));
    markDrawn('#fig-targets');
  });
}

// Figure 2: the two forms side by side.

const viewer = await lesson.figure('#fig-face');
if (viewer) {
  const scene = new BlendShapeFaceScene();
  // The figure declares the heads at their largest (from Rust): the camera fits them at every
  // canvas size, moves only when a control changes that size, and keeps the reader's orbit.
  viewer.setCamera(...scene.viewFit(), 0.15, 0.1);
  const timeline = new Timeline(document.getElementById('face-timeline'), { duration: 4, playing: true });
  const names = scene.targetNames();
  // Equal curves stay visible: each weight is drawn at least 2.5 px wider than the next (so
  // three weights on one value show as three bands), Σ w dotted and the full form's total
  // dashed over them, the curves under both showing through the gaps (with the base weight 0
  // by hand the two totals are the same curve).
  const plot = new Plot(document.getElementById('face-plot'), {
    title: 'Weights over the loop', xLabel: 'time (s)', yLabel: 'weight (no unit)',
    series: [...names, 'Σ w (targets)', 'full form: base + Σ w'],
    colors: ['#1f6fd6', '#d62728', '#2ca02c', '#944fc9', '#1f2430', '#e68a00'], minSpan: 1, height: 200,
    widths: [10, 7, 4, 1.5, 3, 1.5], dashes: [null, null, null, null, [2, 3], [6, 4]],
  });
  // The weights read against 0: the y axis always spans 0 (the four at 1.5 with the total at 7
  // would otherwise sit on the axis's floor and read as 0).
  const updatePlot = () => {
    const data = columns(scene.weightCurves(81), 7);
    const ys = data.slice(1).flat();
    plot.setYRange([Math.min(0, ...ys), Math.max(1, ...ys)]);
    plot.setData(data);
  };
  const p = { show: 'both', baseAuto: false, base: 0, animate: true, deltas: true, useExercise: false };
  const start = scene.weights();
  // The weights come as 32-bit floats: shown at the sliders' 0.01 steps.
  names.forEach((n, k) => { p[n] = Number(start[k].toFixed(2)); });
  const gui = new GUI({ container: document.querySelector('#fig-face .panel'), title: 'Face' });
  const weights = gui.addFolder('target weights');
  names.forEach((n, k) => weights.add(p, n, -0.5, 1.5, 0.01).name(n).onChange((w) => { scene.setWeight(k, w); updatePlot(); }));
  gui.add(p, 'show', ['both', 'differential', 'full']).name('show').onChange((f) => scene.setShow(f));
  const full = gui.addFolder('full form: base weight');
  const base = full.add(p, 'base', 0, 1, 0.05).name('base weight (by hand)').onChange((w) => { scene.setBaseWeight(w); updatePlot(); });
  full.add(p, 'baseAuto').name('automatic: 1 − Σw').onChange((on) => {
    scene.setBaseAuto(on);
    // The hand value is kept, but unused while the weight is automatic.
    base.enable(!on);
    updatePlot();
  });
  gui.add(p, 'animate').name('animate the weights').onChange((on) => { scene.setAnimate(on); updatePlot(); });
  gui.add(p, 'deltas').name('delta arrows (left)').onChange((on) => scene.setShowDeltas(on));
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  updatePlot();
  const note = document.getElementById('face-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    plot.setCursor(t);
    showNote(note, scene.draw(viewer, t));
    markDrawn('#fig-face');
  });
}
