// Lesson 07: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/ik/, src/figures/ik.rs), including picking and dragging the target.
import { startLesson, markDrawn, Timeline, Plot, columns, GUI, showNote, dragInCanvas } from '../../www/lesson.js';
import { IkScene, AimScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// Two series that can coincide: the first 5 px wide underneath, the second 1.5 px on top.
const UNDER_AND_OVER = [5, 1.5];

// Figures 1-3: the same three solvers side by side, each beside the section it illustrates,
// starting from that section's settings. The plot of the error per iteration is in the
// figures that have a .plot (2 and 3: the iterative solvers' sections).
// Figure 1 keeps two segments (the two-joint chain needs them) and has the pole; Figures 2 and 3
// let the number of segments change, which hides the two-joint chain and so its pole.
await ikFigure('#fig-ik', { segments: 2, limits: 'none', controls: ['pole'] });
await ikFigure('#fig-ik-iterative', { segments: 3, limits: 'none', controls: ['segments'] });
// Figure 3 is seen from the front right: its hinges keep the chains in the z = 0 plane, and the
// target's distance from that plane (along z) must show, which a view from the front hides.
await ikFigure('#fig-ik-limits', {
  segments: 2, limits: 'hinges (bend one way)', controls: ['segments', 'limits'], yaw: 0.5, pitch: 0.3,
});

async function ikFigure(id, start) {
  const viewer = await lesson.figure(id);
  if (!viewer) return;
  const figure = document.querySelector(id);
  // From the front (unless the figure says otherwise), a little above; the scene declares what stays in view (each chain's reach
  // and its target), and the camera fits it.
  viewer.setCamera(0.25, 0.45, 0, 4.3, start.yaw ?? 0.1, start.pitch ?? 0.25);
  const scene = new IkScene();
  const home = { x: 0.55, y: 0.65, z: 0.15, pole: 0 };
  const p = {
    segments: start.segments, ...home, iterations: 10, limits: start.limits, useExercise: false,
    reset: () => { Object.assign(p, home); applyTarget(); scene.setPoleAngleDeg(0); refresh(); },
  };
  scene.setSegments(p.segments);
  scene.setLimits(p.limits);
  const gui = new GUI({ container: figure.querySelector('.panel'), title: 'Inverse kinematics' });
  const refresh = () => gui.controllersRecursive().forEach((c) => c.updateDisplay());
  const plotElement = figure.querySelector('.plot');
  const plot = plotElement && new Plot(plotElement, {
    title: 'Error after each iteration', xLabel: 'iteration (count)', yLabel: 'log₁₀ error (m)',
    series: ['CCD', 'FABRIK'], colors: ['#e68a00', '#17a2a8'], minSpan: 1, height: 170, yStep: 1,
    // CCD drawn wide underneath, FABRIK narrow on top: where they agree (a target out of reach)
    // both lines show, the second inside a border of the first.
    widths: UNDER_AND_OVER,
  });
  const update = () => {
    if (!plot) return;
    plot.setData(columns(scene.errorSamples(), 3));
    plot.setCursor(p.iterations);
  };
  const applyTarget = () => { scene.setTarget(p.x, p.y, p.z); update(); };

  const has = (name) => start.controls.includes(name);
  if (has('segments')) gui.add(p, 'segments', 2, 8, 1).name('segments').onChange(() => { scene.setSegments(p.segments); update(); });
  const target = gui.addFolder('target (m, from each root)');
  for (const axis of ['x', 'y', 'z']) target.add(p, axis, -1.5, 1.5, 0.01).name(axis).onChange(applyTarget);
  if (has('pole')) gui.add(p, 'pole', -180, 180, 1).name('pole angle (°)').onChange(() => { scene.setPoleAngleDeg(p.pole); update(); });
  gui.add(p, 'iterations', 1, 50, 1).name('iterations').onChange(() => { scene.setIterations(p.iterations); update(); });
  if (has('limits')) {
    gui.add(p, 'limits', ['none', 'hinges (bend one way)', 'cones (40°)']).name('joint limits').onChange(() => {
      scene.setLimits(p.limits);
      update();
    });
  }
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => { scene.setUseExercise(on); update(); });
  gui.add(p, 'reset').name('reset the target');
  update();

  // Dragging a target with the mouse (the canvas's orbit controls get every other press).
  dragInCanvas(figure.querySelector('.stage canvas'), {
    grab: (...at) => scene.hitsTarget(...at),
    hover: (...at) => scene.hitsTarget(...at),
    drag: (...at) => {
      scene.dragTarget(...at);
      // Array.from: a Float32Array's own map would store the rounded numbers back as f32, and the
      // sliders would show -0.5199999809265137 for -0.52.
      [p.x, p.y, p.z] = Array.from(scene.target(), (v) => Math.round(v * 100) / 100);
      refresh();
      update();
    },
  });

  const note = figure.querySelector('.note');
  lesson.onFrame(() => {
    showNote(note, scene.draw(viewer));
    markDrawn(id);
  });
}

const aimViewer = await lesson.figure('#fig-aim');
if (aimViewer) {
  // From the front left, with the cone seen from the side; the scene declares what stays in
  // view (the body and the target's loop), and the camera fits it.
  aimViewer.setCamera(0, 1.5, 0, 5.2, -0.95, 0.15);
  const scene = new AimScene();
  const p = { x: 1.2, y: 1.9, z: 0.4, cone: 70 };
  const gui = new GUI({ container: document.querySelector('#fig-aim .panel'), title: 'Aim' });
  const target = gui.addFolder('target (m)');
  const plot = new Plot(document.getElementById('aim-plot'), {
    title: 'Angle from straight ahead', xLabel: 'time (s)', yLabel: 'angle (°)',
    series: ['to the target', 'head turn'], colors: ['#d62728', '#1f6fd6'], minSpan: 10, height: 170, yStep: 30,
    // The target's line wide underneath, the head's narrow on top: inside the cone the head's
    // line lies exactly on the target's, and at one width the red would hide under the blue.
    widths: UNDER_AND_OVER,
  });
  const replot = () => plot.setData(columns(scene.plotSamples(), 3));
  const applyTarget = () => { scene.setTarget(p.x, p.y, p.z); replot(); };
  target.add(p, 'x', -1.2, 1.2, 0.05).onChange(applyTarget);
  target.add(p, 'y', 0.6, 2.6, 0.05).onChange(applyTarget);
  target.add(p, 'z', -1.2, 1.2, 0.05).onChange(applyTarget);
  gui.add(p, 'cone', 0, 180, 1).name('largest turn (°)').onChange(() => { scene.setMaxAngleDeg(p.cone); replot(); });
  replot();
  const timeline = new Timeline(document.getElementById('aim-timeline'), { duration: 8, playing: true });
  const note = document.getElementById('aim-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, scene.draw(aimViewer, t));
    plot.setCursor(t);
    markDrawn('#fig-aim');
  });
}
