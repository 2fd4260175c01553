// Lesson 08: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/skeleton/, src/figures/blending.rs).
import { startLesson, markDrawn, Timeline, Plot, columns, GUI, showNote } from '../../www/lesson.js';
import { BlendScene, LocomotionScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

const blendViewer = await lesson.figure('#fig-blend');
if (blendViewer) {
  // Far enough back that a hand raised over the head stays in view in a wide, short canvas.
  blendViewer.setCamera(0, 1.0, 0, 3.7, 0.6, 0.15);
  const scene = new BlendScene();
  const timeline = new Timeline(document.getElementById('blend-timeline'), { duration: scene.durationSec(), playing: true });
  const p = { a: 'walk', b: 'wave', weight: 0.5, mask: 'whole body', additive: 'none', additiveWeight: 1, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-blend .panel'), title: 'Blend' });
  const clips = scene.clipNames();
  const applyClips = () => {
    scene.setClips(p.a, p.b);
    timeline.duration = scene.durationSec();
    timeline.time %= timeline.duration;
    timeline.show();
  };
  gui.add(p, 'a', clips).name('clip A').onChange(applyClips);
  gui.add(p, 'b', clips).name('clip B').onChange(applyClips);
  gui.add(p, 'weight', 0, 1, 0.01).name('weight of B').onChange(() => scene.setWeight(p.weight));
  gui.add(p, 'mask', ['whole body', 'upper body from B', 'lower body from B']).name('mask').onChange(() => scene.setMask(p.mask));
  const applyAdditive = () => scene.setAdditive(p.additive, p.additiveWeight);
  gui.add(p, 'additive', ['none', 'lean forward (a pose)', 'wave (a clip)']).name('additive layer').onChange(applyAdditive);
  gui.add(p, 'additiveWeight', 0, 1, 0.01).name('additive weight').onChange(applyAdditive);
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  const note = document.getElementById('blend-note');
  lesson.onFrame((dt) => {
    showNote(note, scene.draw(blendViewer, timeline.advance(dt)));
    markDrawn('#fig-blend');
  });
}

const locoViewer = await lesson.figure('#fig-locomotion');
if (locoViewer) {
  // Far enough back that the whole 4 m track stays in a 650 px wide canvas (1600 x 1000 page):
  // at 4.2 m the character near the track's +z end would touch the left edge.
  locoViewer.setCamera(0, 0.8, 0, 4.8, 1.2, 0.25);
  const scene = new LocomotionScene();
  const [lo, hi] = scene.speedRange();
  const round = (v) => Math.round(v * 100) / 100;
  const p = { speed: round((lo + hi) / 2), synchronised: true, rootMotion: true };
  scene.setSpeed(p.speed);
  // The loop's length comes from Rust (the plots' samples cover it); then the walk starts again.
  const timeline = new Timeline(document.getElementById('loco-timeline'), { duration: scene.loopSec(), playing: true });
  // Both settings at once, whatever the checkbox says: the synchronised line is drawn wide
  // underneath and the other narrow on top, so where they agree both stay visible. Both plots
  // as tall as the longer y label needs (the shell sizes each plot by its own label).
  const series = ['synchronised', 'same clock time'];
  const colors = ['#1f6fd6', '#d62728'];
  // Fixed y ranges (from Rust): the same scale at every speed, so a small slide looks small.
  const ranges = scene.plotRanges();
  const widths = [5, 1.5];
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
  gui.add(p, 'speed', Math.ceil(lo * 100) / 100, Math.floor(hi * 100) / 100, 0.01).name('speed (m/s)').onChange(() => { scene.setSpeed(p.speed); replot(); });
  gui.add(p, 'synchronised').name('synchronised').onChange((on) => scene.setSynchronised(on));
  gui.add(p, 'rootMotion').name('root motion').onChange((on) => scene.setRootMotion(on));
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
