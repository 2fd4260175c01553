// Lesson 10: wires the page's controls to the wasm scene. No math here: it lives in Rust
// (src/blend_shapes/, src/figures/blend_shapes.rs).
import { startLesson, markDrawn, Timeline, Plot, columns, GUI, showNote } from '../../www/lesson.js';
import { BlendShapeFaceScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

const viewer = await lesson.figure('#fig-face');
if (viewer) {
  const scene = new BlendShapeFaceScene();
  // The framing makes room for the heads at their largest (from Rust); it changes only with a
  // control, and keeps the direction the reader orbited to.
  let framed = scene.viewFit();
  viewer.setCamera(...framed, 0.15, 0.1);
  const reframe = () => {
    const fit = scene.viewFit();
    if (fit.every((x, i) => x === framed[i])) return;
    framed = fit;
    viewer.setTarget(...fit);
  };
  const timeline = new Timeline(document.getElementById('face-timeline'), { duration: 4, playing: true });
  const names = scene.targetNames();
  const plot = new Plot(document.getElementById('face-plot'), {
    title: 'Weights over the loop', xLabel: 'time (s)', yLabel: 'weight (no unit)',
    series: [...names, 'Σ w (targets)', 'full form: base + Σ w'],
    colors: ['#1f6fd6', '#d62728', '#2ca02c', '#944fc9', '#1f2430', '#e68a00'], minSpan: 1, height: 200,
  });
  const updatePlot = () => { plot.setData(columns(scene.weightCurves(81), 7)); reframe(); };
  const p = { show: 'both', base: -0.05, animate: true, useExercise: false };
  const start = [1, 0.6, 0.8, 0.7];
  names.forEach((n, k) => { p[n] = start[k]; });
  const gui = new GUI({ container: document.querySelector('#fig-face .panel'), title: 'Face' });
  const weights = gui.addFolder('target weights');
  names.forEach((n, k) => weights.add(p, n, -0.5, 1.5, 0.01).name(n).onChange((w) => { scene.setWeight(k, w); updatePlot(); }));
  gui.add(p, 'show', ['both', 'differential', 'full']).name('show').onChange((f) => { scene.setShow(f); reframe(); });
  gui.add(p, 'base', -0.05, 1, 0.05).name('full: base weight (left end: 1 − Σw)').onChange((w) => { scene.setBaseWeight(w); updatePlot(); });
  gui.add(p, 'animate').name('animate the weights').onChange((on) => { scene.setAnimate(on); updatePlot(); });
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
