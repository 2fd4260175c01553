// Lesson 03: wires the page's controls to the wasm scenes. No math here: it lives in Rust.
import { startLesson, markDrawn, Timeline, Plot, showMatrix, GUI, pingPong } from '../../www/lesson.js';
import { InterpolationScene, GimbalScene, RodriguesScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

/** Time on the timeline as t in [0, 1], going there and back so the motion never jumps. */
const fmt = (v) => Array.from(v, (x) => x.toFixed(3)).join(', ');

// Figure 1: matrix lerp, Euler lerp, nlerp, slerp side by side.
const interpViewer = await lesson.figure('#fig-interp');
if (interpViewer) {
  interpViewer.setCamera(0, 1.1, 0, 6.2, 0.0, 0.25);
  const scene = new InterpolationScene();
  const timeline = new Timeline(document.getElementById('interp-timeline'), { duration: 4 });
  const p = { ex: 150, ey: 20, ez: 120, sx: -20, sy: 10, sz: 0, longArc: false, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-interp .panel'), title: 'Keys (Euler X-Y′-Z″, °)' });
  const end = gui.addFolder('end key');
  end.add(p, 'ex', -180, 180, 1).name('end angle x');
  end.add(p, 'ey', -90, 90, 1).name('end angle y');
  end.add(p, 'ez', -180, 180, 1).name('end angle z');
  const start = gui.addFolder('start key');
  start.add(p, 'sx', -180, 180, 1).name('start angle x');
  start.add(p, 'sy', -90, 90, 1).name('start angle y');
  start.add(p, 'sz', -180, 180, 1).name('start angle z');
  gui.add(p, 'longArc').name('long arc (use −q)');
  gui.add(p, 'useExercise').name('use my exercise');
  const det = new Plot(document.getElementById('interp-det'), {
    title: 'Matrix lerp: is it still a rotation?', xLabel: 't', series: ['determinant', '‖MᵀM − I‖'], colors: ['#c4443a', '#7a2a24'],
  });
  const speed = new Plot(document.getElementById('interp-speed'), {
    title: 'Angular speed (° per unit of t)', xLabel: 't', series: ['Euler lerp', 'nlerp', 'slerp'], colors: ['#d99a1a', '#33a65a', '#3373e6'],
  });
  const apply = () => {
    scene.setKeysEulerDeg(p.sx, p.sy, p.sz, p.ex, p.ey, p.ez);
    scene.setLongArc(p.longArc);
    scene.setUseExercise(p.useExercise);
    const d = scene.sampleDeterminant(101);
    const dc = [[], [], []];
    for (let i = 0; i < d.length; i += 3) { dc[0].push(d[i]); dc[1].push(d[i + 1]); dc[2].push(d[i + 2]); }
    det.setData(dc);
    const s = scene.sampleAngularSpeed(101);
    const sc = [[], [], [], []];
    for (let i = 0; i < s.length; i += 4) for (let k = 0; k < 4; k++) sc[k].push(s[i + k]);
    speed.setData(sc);
    document.getElementById('interp-quat').textContent = `end key as used by nlerp and slerp: q₁ = (${fmt(scene.endQuatUsed())}) (x, y, z, w)`;
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('interp-note');
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const message = scene.draw(interpViewer, pingPong(timeline));
    if (note.textContent !== message) note.textContent = message;
    markDrawn('#fig-interp');
  });
}

// Figure 2: the gimbal.
const gimbalViewer = await lesson.figure('#fig-gimbal');
if (gimbalViewer) {
  gimbalViewer.setCamera(0, 1.4, 0, 5.2, 0.7, 0.35);
  const scene = new GimbalScene();
  const p = { yaw: 30, pitch: 0, roll: 20, lock: () => { p.pitch = 90; gui.controllersRecursive().forEach((c) => c.updateDisplay()); apply(); } };
  const gui = new GUI({ container: document.querySelector('#fig-gimbal .panel'), title: 'Gimbal (°)' });
  gui.add(p, 'yaw', -180, 180, 1).name('yaw (outer, y)');
  gui.add(p, 'pitch', -90, 90, 1).name('pitch (middle, x′)');
  gui.add(p, 'roll', -180, 180, 1).name('roll (inner, z″)');
  gui.add(p, 'lock').name('go to gimbal lock');
  const note = document.getElementById('gimbal-note');
  function apply() {
    scene.setAnglesDeg(p.yaw, p.pitch, p.roll);
    const angle = scene.axesAngleDeg();
    const [y, x, z, locked] = Array.from(scene.decomposedDeg());
    note.textContent = `Angle between the yaw and roll axles: ${angle.toFixed(1)}°. ` +
      (locked ? 'Gimbal lock: read back from the matrix, only yaw + roll is determined, so roll is set to 0: ' : 'Read back from the matrix: ') +
      `yaw ${y.toFixed(1)}°, pitch ${x.toFixed(1)}°, roll ${z.toFixed(1)}°.`;
  }
  gui.onChange(apply);
  apply();
  lesson.onFrame(() => {
    scene.draw(gimbalViewer);
    markDrawn('#fig-gimbal');
  });
}

// Figure 3: Rodrigues' formula.
const rodViewer = await lesson.figure('#fig-rodrigues');
if (rodViewer) {
  rodViewer.setCamera(0, 0.3, 0, 4.2, 0.5, 0.35);
  const scene = new RodriguesScene();
  const timeline = new Timeline(document.getElementById('rodrigues-timeline'), { duration: 3 });
  const p = { angle: 120, nx: 0.3, ny: 1, nz: 0.2, vx: 1.2, vy: 0.4, vz: 0.3, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-rodrigues .panel'), title: 'Axis and angle' });
  gui.add(p, 'angle', -360, 360, 1).name('angle θ (°)');
  const axis = gui.addFolder('axis n (normalised)');
  axis.add(p, 'nx', -1, 1, 0.01);
  axis.add(p, 'ny', -1, 1, 0.01);
  axis.add(p, 'nz', -1, 1, 0.01);
  const vec = gui.addFolder('vector v');
  vec.add(p, 'vx', -2, 2, 0.01);
  vec.add(p, 'vy', -2, 2, 0.01);
  vec.add(p, 'vz', -2, 2, 0.01);
  gui.add(p, 'useExercise').name('use my exercise');
  const note = document.getElementById('rodrigues-note');
  const apply = () => {
    try {
      scene.setAxisAngle(p.nx, p.ny, p.nz, p.angle);
      note.textContent = '';
    } catch (e) {
      // A zero axis is a mistake a reader can make with the sliders: say so, keep the last axis.
      note.textContent = `Axis not changed: ${e.message ?? e}`;
    }
    scene.setVector(p.vx, p.vy, p.vz);
    scene.setUseExercise(p.useExercise);
    showMatrix(document.getElementById('rodrigues-matrix'), scene.matrix());
    document.getElementById('rodrigues-quat').textContent = `q = (${fmt(scene.quaternion())}) (x, y, z, w)`;
  };
  gui.onChange(apply);
  apply();
  let shown = '';
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const message = scene.draw(rodViewer, pingPong(timeline));
    if (message && message !== shown) { note.textContent = message; shown = message; }
    markDrawn('#fig-rodrigues');
  });
}
