// Lesson 04: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/figures/rigid.rs).
import { startLesson, markDrawn, Timeline, Plot, GUI, pingPong, columns, sentences } from '../../www/lesson.js';
import { RigidScene, AffineScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

/** Copies the accepted values back into `p` and the panel, after a setter rejected a change. */
function revert(gui, p, accepted) {
  Object.assign(p, accepted);
  gui.controllersRecursive().forEach((c) => c.updateDisplay());
}

// Figure 1: lerp + slerp, dual quaternion blending, screw motion.
const rigidViewer = await lesson.figure('#fig-rigid');
if (rigidViewer) {
  rigidViewer.setCamera(0, 1.0, 0, 6.5, 0.35, 0.4);
  const scene = new RigidScene();
  const timeline = new Timeline(document.getElementById('rigid-timeline'), { duration: 4 });
  // It opens at t = 0.3, where the three methods have parted: at the keys all three meet, and
  // half-way the blend's plane lies on the screw's and hides it.
  timeline.time = 0.6;
  timeline.show();
  const SHOW = { 'all three': 0, 'lerp + slerp': 1, 'dual quaternion blend': 2, screw: 3 };
  const p = {
    angle: 150, ax: 0.2, ay: 1, az: 0.3, tx: 1.5, ty: 1.4, tz: 0.3, pivot: 0, show: 0, thirds: false, useExercise: false,
  };
  let accepted = { ...p };
  const gui = new GUI({ container: document.querySelector('#fig-rigid .panel'), title: 'Key B' });
  gui.add(p, 'show', SHOW).name('show');
  const thirdsButton = gui.add({ toggle: () => { p.thirds = !p.thirds; thirdsButton.name(p.thirds ? 'hide the thirds' : 'a third, three times'); apply(); } }, 'toggle')
    .name('a third, three times');
  gui.add(p, 'angle', -180, 180, 1).name('angle (°)');
  const axis = gui.addFolder('rotation axis');
  axis.add(p, 'ax', -1, 1, 0.01);
  axis.add(p, 'ay', -1, 1, 0.01);
  axis.add(p, 'az', -1, 1, 0.01);
  const move = gui.addFolder('translation (m)');
  move.add(p, 'tx', -3, 3, 0.01);
  move.add(p, 'ty', 0, 3, 0.01);
  move.add(p, 'tz', -3, 3, 0.01);
  gui.add(p, 'pivot', -1.5, 1.5, 0.05).name('pivot x (m, along the body)');
  gui.add(p, 'useExercise').name('use my exercise');
  // Wide under narrow: at angle 0 the three curves are one, and all three stay visible. uPlot
  // draws the series in order, so the blend's narrow curve comes last (the core gives it second).
  const curves = {
    series: ['lerp + slerp', 'screw', 'dual quaternion blend'], colors: ['#e68a00', '#1f6fd6', '#2ca02c'], widths: [7, 4, 1.5],
  };
  // "show" one method: the plots keep only its curve too (the others become gaps).
  const blendLast = (rows) => {
    const [t, lerp, blend, screw] = columns(rows, 4);
    const keep = (c, k) => ([0, k].includes(Number(p.show)) ? c : c.map(() => null));
    return [t, keep(lerp, 1), keep(screw, 3), keep(blend, 2)];
  };
  const distance = new Plot(document.getElementById('rigid-distance'), {
    title: 'Distance travelled by the nose', xLabel: 't (0 to 1)', yLabel: 'distance (m)', minSpan: 0.5, ...curves,
  });
  const plot = new Plot(document.getElementById('rigid-plot'), {
    title: 'Speed of the nose', xLabel: 't (0 to 1)', yLabel: 'speed (m per unit of t)', minSpan: 0.5, ...curves,
  });
  const note = document.getElementById('rigid-note');
  let rejected = '';
  function apply() {
    try {
      scene.setEnd(p.ax, p.ay, p.az, p.angle, p.tx, p.ty, p.tz);
      scene.setPivot(p.pivot, 0, 0);
      accepted = { ...p };
      rejected = '';
    } catch (e) {
      // A zero axis: say so, and put the sliders back to the key the figure still shows.
      rejected = `Key B not changed: ${e.message ?? e}`;
      revert(gui, p, accepted);
    }
    scene.setShow(Number(p.show));
    scene.setThirds(p.thirds);
    scene.setUseExercise(p.useExercise);
    plot.setData(blendLast(scene.sampleSpeed(101)));
    distance.setData(blendLast(scene.sampleDistance(101)));
    // The legends grey out the methods "show" hides (series 1 to 3: lerp + slerp, screw, blend).
    [1, 3, 2].forEach((k, i) => {
      const show = [0, k].includes(Number(p.show));
      for (const q of [plot, distance]) if (q.plot.series[i + 1].show !== show) q.plot.setSeries(i + 1, { show });
    });
    const s = Array.from(scene.screwAxis());
    const f = (v) => v.map((x) => (Math.abs(x) < 5e-3 ? 0 : x).toFixed(2)).join(', ');
    document.getElementById('rigid-screw').textContent = s[6] < 0.05
      ? `Screw A → B: no turn, a pure slide of ${s[7].toFixed(2)} m along (${f(s.slice(0, 3))}); the axis is drawn through the middle of the keys.`
      : `Screw A → B: turn ${s[6].toFixed(1)}° about the line through (${f(s.slice(3, 6))}) ` +
        `along (${f(s.slice(0, 3))}), sliding ${s[7].toFixed(2)} m along it.`;
  }
  gui.onChange(apply);
  apply();
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const t = pingPong(timeline);
    const message = sentences(rejected, scene.draw(rigidViewer, t));
    if (note.textContent !== message) note.textContent = message;
    plot.setCursor?.(t);
    distance.setCursor?.(t);
    markDrawn('#fig-rigid');
  });
}

// Figure 2: affine keys, naive vs polar.
const affineViewer = await lesson.figure('#fig-affine');
if (affineViewer) {
  // From above and in front: the boxes' depth fills the canvas's height.
  affineViewer.setCamera(0, 0.7, 0, 6.5, 0.0, 0.6);
  const scene = new AffineScene();
  const timeline = new Timeline(document.getElementById('affine-timeline'), { duration: 4 });
  const p = { angle: 160, sx: 1.6, sy: 0.6, sz: 1, shear: 0.6, useExercise: false };
  let accepted = { ...p };
  const gui = new GUI({ container: document.querySelector('#fig-affine .panel'), title: 'Key B' });
  gui.add(p, 'angle', -180, 180, 1).name('angle about y (°)');
  gui.add(p, 'sx', -2, 2.5, 0.001).name('scale x');
  gui.add(p, 'sy', -2, 2.5, 0.001).name('scale y');
  gui.add(p, 'sz', -2, 2.5, 0.001).name('scale z');
  gui.add(p, 'shear', -1.5, 1.5, 0.01).name('shear x by y');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('affine-plot'), {
    title: 'Volume factor det M(t)', xLabel: 't (0 to 1)', yLabel: 'det M (volume ratio)',
    series: ['naive lerp', 'polar decomposition'], colors: ['#d62728', '#1f6fd6'], minSpan: 0.1,
    // Wide under narrow: with no rotation the two curves are one.
    widths: [6, 2],
  });
  const note = document.getElementById('affine-note');
  let rejected = '';
  const apply = () => {
    try {
      scene.setKeyB(p.angle, p.sx, p.sy, p.sz, p.shear);
      accepted = { ...p };
      rejected = '';
    } catch (e) {
      // A zero or negative scale makes a singular or mirroring key: the core says which, and
      // the sliders go back to the key the figure still shows.
      rejected = `Key B not changed: ${e.message ?? e}`;
      revert(gui, p, accepted);
    }
    scene.setUseExercise(p.useExercise);
    plot.setData(columns(scene.sampleDeterminant(101), 3));
  };
  gui.onChange(apply);
  apply();
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const t = pingPong(timeline);
    const message = sentences(rejected, scene.draw(affineViewer, t));
    if (note.textContent !== message) note.textContent = message;
    plot.setCursor?.(t);
    markDrawn('#fig-affine');
  });
}
