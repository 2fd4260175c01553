// Lesson 01: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/figures/transforms.rs).
import { startLesson, markDrawn, Timeline, Plot, showMatrix, columns, GUI, showNote } from '../../www/lesson.js';
import { SingleShapeScene, HierarchyScene, ScaleComparisonScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

/** An angle slider that shows whole degrees (the value itself may carry decimals). */
function addAngle(folder, object, key, name) {
  const c = folder.add(object, key, -180, 180, 1).name(name);
  return c.decimals ? c.decimals(0) : c;
}

// Figure 1: one shape, T·R and R·T side by side.
const shapeViewer = await lesson.figure('#fig-shape');
if (shapeViewer) {
  shapeViewer.setCamera(0.5, 0.3, 0, 5, 0.6, 0.45);
  const scene = new SingleShapeScene();
  // Two steps of 2 s each (the right-hand factor, then the left-hand one), then 1 s at the end.
  const steps = new Timeline(document.getElementById('shape-timeline'), { duration: 5 });
  const p = { tx: 1, ty: 0.5, tz: 0, rx: 0, ry: 0, rz: 30, translateFirst: false };
  const gui = new GUI({ container: document.querySelector('#fig-shape .panel'), title: 'Transform' });
  const apply = () => {
    scene.setTransform(p.tx, p.ty, p.tz, p.rx, p.ry, p.rz);
    scene.setTranslateFirst(p.translateFirst);
    showMatrix(document.getElementById('shape-matrix-tr'), scene.matrixOf(false));
    showMatrix(document.getElementById('shape-matrix-rt'), scene.matrixOf(true));
  };
  gui.add(p, 'tx', -2, 2, 0.01).name('translate x (m)');
  gui.add(p, 'ty', -2, 2, 0.01).name('translate y (m)');
  gui.add(p, 'tz', -2, 2, 0.01).name('translate z (m)');
  addAngle(gui, p, 'rx', 'angle x (°)');
  addAngle(gui, p, 'ry', 'angle y (°)');
  addAngle(gui, p, 'rz', 'angle z (°)');
  gui.add(p, 'translateFirst').name('solid box: R·T (ghost T·R)');
  gui.onChange(apply);
  apply();
  const note = document.getElementById('shape-note');
  lesson.onFrame((dt) => {
    const stage = Math.min(2, steps.advance(dt) / 2);
    showNote(note, scene.draw(shapeViewer, stage));
    markDrawn('#fig-shape');
  });
}

// Figure 2: the hierarchy, its walk, and the student's exercises.
const humanViewer = await lesson.figure('#fig-human');
if (humanViewer) {
  humanViewer.setCamera(0, 0.9, 0, 3.6, 0.45, 0.2);
  const scene = new HierarchyScene();
  const names = scene.jointNames();
  const timeline = new Timeline(document.getElementById('human-timeline'), { duration: 1.2 });
  const p = { joint: 'upper_arm.L', x: 0, y: 0, z: 0, sx: 1, sy: 1, sz: 1, walk: true, inheritScale: false, useExercise: false };
  const index = () => names.indexOf(p.joint);
  const gui = new GUI({ container: document.querySelector('#fig-human .panel'), title: 'Pose' });
  const refresh = () => gui.controllersRecursive().forEach((c) => c.updateDisplay());
  const readJoint = () => {
    [p.x, p.y, p.z] = scene.jointAnglesDeg(index()).map((v) => Math.round(v));
    [p.sx, p.sy, p.sz] = scene.jointScale(index());
  };
  // The timeline drives the walk: with the walk off (a joint posed by hand) it is paused, and
  // playing or scrubbing it turns the walk back on.
  let pausedAt = timeline.time;
  const setWalk = (on) => {
    pausedAt = timeline.time;
    p.walk = on;
    scene.setAnimate(on);
    timeline.setPlaying(on);
    refresh();
  };
  gui.add(p, 'walk').name('walk cycle (timeline)').onChange(setWalk);
  gui.add(p, 'joint', names).name('joint').onChange(() => {
    scene.select(index());
    readJoint();
    refresh();
  });
  const angles = gui.addFolder('joint angles (°)');
  const setAngles = () => scene.setJointAnglesDeg(index(), p.x, p.y, p.z);
  for (const axis of ['x', 'y', 'z']) {
    addAngle(angles, p, axis, `about ${axis}`).onChange(() => {
      // Posing by hand: stop the walk so it does not overwrite the slider.
      if (p.walk) setWalk(false);
      setAngles();
      updatePlot();
    });
  }
  const scale = gui.addFolder('joint scale');
  for (const axis of ['sx', 'sy', 'sz']) {
    scale.add(p, axis, 0.25, 3, 0.01).onChange(() => {
      scene.setJointScale(index(), p.sx, p.sy, p.sz);
      updatePlot();
    });
  }
  gui.add(p, 'inheritScale').name('children inherit scale').onChange((on) => {
    scene.setInheritScale(on);
    updatePlot();
  });
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  scene.select(index());

  const thighPlot = new Plot(document.getElementById('human-plot-thigh'), {
    title: 'Left thigh angle', xLabel: 'time (s)', yLabel: 'angle about x (°)',
    series: ['left thigh'], colors: ['#944fc9'], minSpan: 10, height: 160,
  });
  const wristPlot = new Plot(document.getElementById('human-plot-wrist'), {
    title: 'Left wrist height', xLabel: 'time (s)', yLabel: 'height (m)',
    series: ['left wrist'], colors: ['#e35d9c'], minSpan: 0.1, height: 160,
  });
  // The plots sample one walk of the figure as it is now: pose, scales and scale mode.
  function updatePlot() {
    const [time, thigh, wrist] = columns(scene.sampleCycle(121, 1.2), 3);
    thighPlot.setData([time, thigh]);
    wristPlot.setData([time, wrist]);
  }
  updatePlot();

  const note = document.getElementById('human-note');
  let frame = 0;
  lesson.onFrame((dt) => {
    if (!p.walk && (timeline.playing || timeline.time !== pausedAt)) setWalk(true);
    const t = timeline.advance(dt);
    showNote(note, scene.draw(humanViewer, t));
    thighPlot.setCursor?.(t);
    wristPlot.setCursor?.(t);
    if (frame++ % 6 === 0) {
      showMatrix(document.getElementById('human-local'), scene.localMatrix(index()));
      showMatrix(document.getElementById('human-world'), scene.worldMatrix(index()));
      if (p.walk) {
        readJoint();
        angles.controllers.forEach((c) => c.updateDisplay());
      }
    }
    markDrawn('#fig-human');
  });
}

// Figure 3: scale not inherited and inherited, side by side.
const scaleViewer = await lesson.figure('#fig-scale');
if (scaleViewer) {
  // From the left side (+x), square to the plane in which the forearm bends and shears.
  scaleViewer.setCamera(0, 1.0, 0, 3.6, Math.PI / 2, 0.12);
  const scene = new ScaleComparisonScene();
  const p = { sx: 1, sy: 2, sz: 1, x: -70, y: 0, z: 0 };
  const gui = new GUI({ container: document.querySelector('#fig-scale .panel'), title: 'upper_arm.L and forearm.L' });
  const arm = gui.addFolder('upper_arm.L scale');
  for (const axis of ['sx', 'sy', 'sz']) arm.add(p, axis, 0.25, 3, 0.01);
  const elbow = gui.addFolder('forearm.L angles (°)');
  for (const axis of ['x', 'y', 'z']) addAngle(elbow, p, axis, `about ${axis}`);
  gui.onChange(() => {
    scene.setUpperArmScale(p.sx, p.sy, p.sz);
    scene.setForearmAnglesDeg(p.x, p.y, p.z);
  });
  const note = document.getElementById('scale-note');
  lesson.onFrame(() => {
    showNote(note, scene.draw(scaleViewer));
    markDrawn('#fig-scale');
  });
}
