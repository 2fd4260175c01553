// Lesson 08: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/skeleton/, src/figures/blending.rs).
import { startLesson, markDrawn, Timeline, Plot, columns, GUI, showNote } from '../../www/lesson.js';
import { BlendScene, LocomotionScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// The arm plots' colours: clip A grey, clip B teal, the mix dark, the layered pose orange.
const GREY = '#7f7f7f';
const TEAL = '#17a2a8';
const DARK = '#333333';
const ORANGE = '#e68a00';
const ARM_SAMPLES = 61;

// Figures 1 and 2: the simple human, a BlendScene each. `controls` adds the figure's own
// controls; `series` picks the columns of armSamples() the plot shows.
async function blendFigure(id, { title, setup, controls, series, names, colors, widths, dashes }) {
  const viewer = await lesson.figure(`#${id}`);
  if (!viewer) return;
  // Orbit only: the camera fits the body (raised hand included) that the figure keeps in view.
  viewer.setCamera(0, 1.0, 0, 3.7, 0.6, 0.15);
  const scene = new BlendScene();
  setup(scene);
  const timeline = new Timeline(document.querySelector(`#${id} .timeline`), { duration: scene.durationSec(), playing: true });
  const plot = new Plot(document.querySelector(`#${id} .plot`), {
    title: 'Right upper arm over one cycle', xLabel: 'time (s)', yLabel: 'arm raised (°)',
    series: names, colors, widths, dashes, yRange: [0, 180], height: 200,
  });
  const replot = () => {
    const cols = columns(scene.armSamples(ARM_SAMPLES), 6);
    plot.setData([cols[0], ...series.map((i) => cols[i])]);
  };
  const retime = () => {
    timeline.duration = scene.durationSec();
    timeline.time %= timeline.duration;
    timeline.show();
    replot();
  };
  const gui = new GUI({ container: document.querySelector(`#${id} .panel`), title });
  controls(gui, scene, { replot, retime });
  replot();
  const note = document.querySelector(`#${id} .note`);
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, scene.draw(viewer, t));
    plot.setCursor(t);
    markDrawn(`#${id}`);
  });
}

await blendFigure('fig-blend', {
  title: 'Blend',
  setup: () => {},
  // A, B and the mix; the mix narrower on top, so where it equals A or B both stay visible.
  series: [1, 2, 3],
  names: ['clip A', 'clip B', 'the mix'],
  colors: [GREY, TEAL, DARK],
  widths: [6, 6, 3],
  controls: (gui, scene, { replot, retime }) => {
    const p = { a: 'walk', b: 'wave', weight: 0.5, mask: 'whole body', useExercise: false };
    const clips = scene.clipNames();
    const applyClips = () => { scene.setClips(p.a, p.b); retime(); };
    gui.add(p, 'a', clips).name('clip A').onChange(applyClips);
    gui.add(p, 'b', clips).name('clip B').onChange(applyClips);
    gui.add(p, 'weight', 0, 1, 0.01).name('weight of B').onChange(() => { scene.setWeight(p.weight); replot(); });
    gui.add(p, 'mask', ['whole body', 'upper body from B', 'lower body from B']).name('mask')
      .onChange(() => { scene.setMask(p.mask); replot(); });
    gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  },
});

await blendFigure('fig-additive', {
  title: 'Additive layer',
  // The base plays alone (clip B's weight 0): the layer is all that is added.
  setup: (scene) => {
    scene.setClips('walk', 'wave');
    scene.setWeight(0);
    scene.setAdditive('wave (a clip)', 1);
  },
  // The base, the chosen layer alone (on the rest pose) and the base with the layer.
  series: [1, 5, 4],
  names: ['base clip', 'layer alone', 'base + layer'],
  // As in the view: the orange stick figure is the base, the grey body the base with the layer.
  // The wave alone and with the base lie within a few degrees of each other: the layer alone a
  // 5 px teal band, the base with the layer a dashed grey line over it, so both read where they
  // meet (a lean lowers the arm onto the 6 px base the same way).
  colors: [ORANGE, TEAL, GREY],
  widths: [6, 5, 2.5],
  dashes: [null, null, [6, 4]],
  controls: (gui, scene, { replot, retime }) => {
    const p = { base: 'walk', additive: 'wave (a clip)', additiveWeight: 1 };
    gui.add(p, 'base', scene.clipNames()).name('base clip').onChange(() => { scene.setClips(p.base, 'wave'); retime(); });
    const apply = () => { scene.setAdditive(p.additive, p.additiveWeight); replot(); };
    gui.add(p, 'additive', ['lean forward (a pose)', 'wave (a clip)']).name('additive layer').onChange(apply);
    gui.add(p, 'additiveWeight', 0, 1, 0.01).name('layer weight').onChange(apply);
  },
});

// Figures 3 and 4: the travelling walk and run blended for a speed.
function speedSlider(gui, scene, p, after) {
  const [lo, hi] = scene.speedRange();
  // The slider's ends, rounded to its step, stand for the clips' own speeds (Rust snaps them).
  const round = (v) => Math.round(v * 100) / 100;
  gui.add(p, 'speed', round(lo), round(hi), 0.01).name('speed (m/s)').onChange(() => { scene.setSpeed(p.speed); after(); });
  return [lo, hi];
}

const locoViewer = await lesson.figure('#fig-locomotion');
if (locoViewer) {
  // A low view from in front of the walk and a little to its right: the synchronised character
  // stands left and the other right with their footprints between (tests/figures_blending.rs,
  // LOCOMOTION_VIEW), and the characters fill the canvas's height even in an 800 px window.
  locoViewer.setCamera(0, 0.8, 0, 5.0, 0.5, 0.35);
  const scene = new LocomotionScene();
  const p = { speed: 0, useExercise: false };
  // The loop's length comes from Rust (the plots' samples cover it); then the walk starts again.
  const timeline = new Timeline(document.getElementById('loco-timeline'), { duration: scene.loopSec(), playing: true });
  // Both settings, as in the view: the synchronised line is drawn wide underneath and the other
  // narrower on top, so where they agree both stay visible; the narrower one still 2.5 px, as
  // wide as the figure's curves, so it reads as a line of its own beside the wide one.
  const series = ['synchronised', 'same clock time'];
  const colors = ['#1f6fd6', '#d62728'];
  // Fixed y ranges (from Rust): the same scale at every speed, so a small slide looks small.
  const ranges = scene.plotRanges();
  const widths = [6, 2.5];
  const gapPlot = new Plot(document.getElementById('loco-phase-plot'), {
    title: 'How far out of step', xLabel: 'time (s)', yLabel: 'phase gap (cycles)',
    series, colors, widths, height: 240, yRange: [ranges[0], ranges[1]],
  });
  const slidePlot = new Plot(document.getElementById('loco-slide-plot'), {
    title: 'Slide in the last 1.5 s', xLabel: 'time (s)', yLabel: 'slide (cm)',
    series, colors, widths, height: 240, yRange: [ranges[2], ranges[3]],
  });
  const replot = () => {
    const [t, gapOn, gapOff, slideOn, slideOff] = columns(scene.plotSamples(), 5);
    gapPlot.setData([t, gapOn, gapOff]);
    slidePlot.setData([t, slideOn, slideOff]);
  };
  const gui = new GUI({ container: document.querySelector('#fig-locomotion .panel'), title: 'Locomotion' });
  const [lo, hi] = scene.speedRange();
  p.speed = Math.round(50 * (lo + hi)) / 100;
  scene.setSpeed(p.speed);
  speedSlider(gui, scene, p, replot);
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => { scene.setUseExercise(on); replot(); });
  replot();
  const note = document.getElementById('loco-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, scene.draw(locoViewer, t));
    gapPlot.setCursor(t);
    slidePlot.setCursor(t);
    markDrawn('#fig-locomotion');
  });
}

const rootViewer = await lesson.figure('#fig-root');
if (rootViewer) {
  rootViewer.setCamera(0, 0.8, 0, 4.5, 1.3, 0.3);
  const scene = new LocomotionScene();
  scene.setCompare(false);
  const p = { speed: 0, rootMotion: true };
  const timeline = new Timeline(document.getElementById('root-timeline'), { duration: scene.loopSec(), playing: true });
  const gui = new GUI({ container: document.querySelector('#fig-root .panel'), title: 'Root motion' });
  const [lo, hi] = scene.speedRange();
  p.speed = Math.round(50 * (lo + hi)) / 100;
  scene.setSpeed(p.speed);
  speedSlider(gui, scene, p, () => {});
  gui.add(p, 'rootMotion').name('root motion').onChange((on) => scene.setRootMotion(on));
  const note = document.getElementById('root-note');
  lesson.onFrame((dt) => {
    showNote(note, scene.draw(rootViewer, timeline.advance(dt)));
    markDrawn('#fig-root');
  });
}
