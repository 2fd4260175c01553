// Lesson 01: wires the page's controls to the wasm scenes. No math here: it lives in Rust.
import { startLesson, markDrawn, Timeline, Plot, showMatrix, columns, GUI } from '../../www/lesson.js';
import { SingleShapeScene, HierarchyScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// Figure 1: one shape.
const shapeViewer = await lesson.figure('#fig-shape');
if (shapeViewer) {
  shapeViewer.setCamera(0.5, 0.3, 0, 5, 0.6, 0.45);
  const scene = new SingleShapeScene();
  const p = { tx: 1, ty: 0.5, tz: 0, rx: 0, ry: 0, rz: 30, translateFirst: false };
  const gui = new GUI({ container: document.querySelector('#fig-shape .panel'), title: 'Transform' });
  const apply = () => {
    scene.setTransform(p.tx, p.ty, p.tz, p.rx, p.ry, p.rz);
    scene.setTranslateFirst(p.translateFirst);
    showMatrix(document.getElementById('shape-matrix'), scene.matrix());
  };
  gui.add(p, 'tx', -2, 2, 0.01).name('translate x');
  gui.add(p, 'ty', -2, 2, 0.01).name('translate y');
  gui.add(p, 'tz', -2, 2, 0.01).name('translate z');
  gui.add(p, 'rx', -180, 180, 1).name('angle x (°)');
  gui.add(p, 'ry', -180, 180, 1).name('angle y (°)');
  gui.add(p, 'rz', -180, 180, 1).name('angle z (°)');
  gui.add(p, 'translateFirst').name('translate first (R·T)');
  gui.onChange(apply);
  apply();
  lesson.onFrame(() => {
    scene.draw(shapeViewer);
    markDrawn('#fig-shape');
  });
}

// Figure 2: the hierarchy.
const humanViewer = await lesson.figure('#fig-human');
if (humanViewer) {
  humanViewer.setCamera(0, 0.9, 0, 3.6, 0.7, 0.25);
  const scene = new HierarchyScene();
  const names = scene.jointNames();
  const timeline = new Timeline(document.getElementById('human-timeline'), { duration: 1.2 });
  const p = { joint: 'upper_arm.L', x: 0, y: 0, z: 0, sx: 1, sy: 1, sz: 1, walk: true, inheritScale: false, useExercise: false };
  const index = () => names.indexOf(p.joint);
  const gui = new GUI({ container: document.querySelector('#fig-human .panel'), title: 'Pose' });
  gui.add(p, 'walk').name('walk cycle (timeline)').onChange((on) => scene.setAnimate(on));
  gui.add(p, 'joint', names).name('joint').onChange(() => {
    scene.select(index());
    [p.x, p.y, p.z] = scene.jointAnglesDeg(index());
    [p.sx, p.sy, p.sz] = [1, 1, 1];
    scene.setJointScale(index(), 1, 1, 1);
    gui.controllersRecursive().forEach((c) => c.updateDisplay());
  });
  const angles = gui.addFolder('joint angles (°)');
  const setAngles = () => scene.setJointAnglesDeg(index(), p.x, p.y, p.z);
  for (const axis of ['x', 'y', 'z']) {
    angles.add(p, axis, -180, 180, 1).name(`about ${axis}`).onChange(() => {
      // Posing by hand: stop the walk so it does not overwrite the slider.
      if (p.walk) { p.walk = false; scene.setAnimate(false); gui.controllersRecursive().forEach((c) => c.updateDisplay()); }
      setAngles();
    });
  }
  const scale = gui.addFolder('joint scale');
  for (const axis of ['sx', 'sy', 'sz']) {
    scale.add(p, axis, 0.25, 3, 0.01).onChange(() => scene.setJointScale(index(), p.sx, p.sy, p.sz));
  }
  gui.add(p, 'inheritScale').name('children inherit scale').onChange((on) => {
    scene.setInheritScale(on);
    updatePlot();
  });
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  scene.select(index());

  const plot = new Plot(document.getElementById('human-plot'), {
    title: 'One walk cycle', xLabel: 'time (s)', series: ['left thigh angle (°)', 'left wrist height (cm)'],
  });
  function updatePlot() {
    const [time, thigh, wrist] = columns(scene.sampleCycle(121, 1.2), 3);
    plot.setData([time, thigh, wrist.map((h) => h * 100)]);
  }
  updatePlot();

  const note = document.getElementById('human-note');
  let frame = 0;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    const message = scene.draw(humanViewer, t);
    if (note.textContent !== message) note.textContent = message;
    if (frame++ % 6 === 0) {
      showMatrix(document.getElementById('human-local'), scene.localMatrix(index()));
      showMatrix(document.getElementById('human-world'), scene.worldMatrix(index()));
      if (p.walk) {
        [p.x, p.y, p.z] = scene.jointAnglesDeg(index()).map((v) => Math.round(v));
        angles.controllers.forEach((c) => c.updateDisplay());
      }
    }
    markDrawn('#fig-human');
  });
}
