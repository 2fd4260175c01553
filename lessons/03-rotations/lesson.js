// Lesson 03: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/figures/rotations.rs).
import { startLesson, markDrawn, Timeline, Plot, GUI, pingPong, cssVar, columns } from '../../www/lesson.js';
import { InterpolationScene, GimbalScene, RodriguesScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// Three decimals, and no "-0.000": a component that rounds to zero reads 0.000.
const fmt = (v) => Array.from(v, (x) => (Math.abs(x) < 5e-4 ? 0 : x).toFixed(3)).join(', ');

/** A 3×3 column-major matrix as a table, three decimals, no "-0.000". */
function showMatrix3(table, cols) {
  const rows = [0, 1, 2].map((r) => [0, 1, 2].map((c) => cols[c * 3 + r]));
  table.innerHTML = rows
    .map((row) => `<tr>${row.map((v) => `<td>${(Math.abs(v) < 5e-4 ? 0 : v).toFixed(3)}</td>`).join('')}</tr>`)
    .join('');
}

/** Copies the accepted values back into `p` and the panel, after a setter rejected a change. */
function revert(gui, p, accepted) {
  Object.assign(p, accepted);
  gui.controllersRecursive().forEach((c) => c.updateDisplay());
}

// Figure 1: matrix lerp, Euler lerp, nlerp, slerp side by side.
const interpViewer = await lesson.figure('#fig-interp');
if (interpViewer) {
  // From the front left and above: the row runs away to the right, so its image fills the
  // canvas both ways, the matrix lerp's plane (whose shrink the text is about) nearest and
  // largest, and the noses' paths read in depth.
  interpViewer.setCamera(0, 1.1, 0, 7.5, -0.6, 0.7);
  const scene = new InterpolationScene();
  const timeline = new Timeline(document.getElementById('interp-timeline'), {
    duration: 4, readout: (tl) => `t = ${pingPong(tl).toFixed(2)}`,
  });
  const p = { ex: 120, ey: 70, ez: -120, sx: 0, sy: 0, sz: 0, longArc: false, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-interp .panel'), title: 'Keys (Euler X-Y′-Z″, °)' });
  const end = gui.addFolder('end key');
  end.add(p, 'ex', -180, 180, 1).name('end angle x');
  end.add(p, 'ey', -90, 90, 1).name('end angle y');
  end.add(p, 'ez', -180, 180, 1).name('end angle z');
  const start = gui.addFolder('start key');
  start.add(p, 'sx', -180, 180, 1).name('start angle x');
  start.add(p, 'sy', -90, 90, 1).name('start angle y');
  start.add(p, 'sz', -180, 180, 1).name('start angle z');
  gui.add(p, 'useExercise').name('use my exercise');
  const det = new Plot(document.getElementById('interp-det'), {
    title: 'Matrix lerp: is it still a rotation?', xLabel: 't (0 to 1)', yLabel: 'det M, ‖MᵀM − I‖ (no unit)',
    series: ['determinant', '‖MᵀM − I‖'], colors: [cssVar('--x-axis') ?? '#d62728', '#7a2a24'], minSpan: 0.1,
  });
  const speed = new Plot(document.getElementById('interp-speed'), {
    title: 'Angular speed', xLabel: 't (0 to 1)', yLabel: 'angular speed (° per unit of t)',
    series: ['Euler lerp', 'nlerp', 'slerp'], colors: ['#e68a00', '#2ca02c', '#1f6fd6'], minSpan: 10,
    // Wide under narrow: equal curves (Euler lerp and slerp about one axis) stay visible, and
    // so do nlerp and slerp where they cross.
    widths: [7, 4, 1.5],
  });
  const apply = () => {
    scene.setKeysEulerDeg(p.sx, p.sy, p.sz, p.ex, p.ey, p.ez);
    scene.setLongArc(p.longArc);
    scene.setUseExercise(p.useExercise);
    const d = scene.sampleDeterminant(101);
    const dc = [[], [], []];
    for (let i = 0; i < d.length; i += 3) for (let k = 0; k < 3; k++) dc[k].push(d[i + k]);
    det.setData(dc);
    const s = scene.sampleAngularSpeed(101);
    const sc = [[], [], [], []];
    for (let i = 0; i < s.length; i += 4) for (let k = 0; k < 4; k++) sc[k].push(s[i + k]);
    speed.setData(sc);
    const [short, long] = Array.from(scene.arcAnglesDeg());
    document.getElementById('interp-quat').textContent =
      `End key as used by nlerp and slerp: b = (${fmt(scene.endQuatUsed())}) (x, y, z, w). ` +
      `Short arc ${short.toFixed(1)}°, long arc ${long.toFixed(1)}° the other way round.`;
  };
  gui.onChange(apply);
  const note = document.getElementById('interp-note');

  // Figure 2: the keys' circle of unit quaternions. It draws Figure 1's scene (same keys, same t),
  // and its controls set Figure 1's keys and the arc.
  const circleViewer = await lesson.figure('#fig-circle');
  const circleNote = document.getElementById('circle-note');
  if (circleViewer) {
    circleViewer.setCamera(0, 1.3, 0, 5, 0, 0);
    const setKeys = (keys) => {
      Object.assign(p, keys);
      gui.controllersRecursive().forEach((c) => c.updateDisplay());
      apply();
    };
    const q = {
      longArc: false,
      across: () => setKeys({ sx: 170, sy: 0, sz: 0, ex: -170, ey: 0, ez: 0 }),
      defaults: () => setKeys({ sx: 0, sy: 0, sz: 0, ex: 120, ey: 70, ez: -120 }),
    };
    const cgui = new GUI({ container: document.querySelector('#fig-circle .panel'), title: 'Keys of Figure 1' });
    cgui.add(q, 'across').name('keys 170° and −170° about x');
    cgui.add(q, 'defaults').name('default keys');
    cgui.add(q, 'longArc').name('long arc (use the far one of ±b)');
    cgui.onChange(() => { p.longArc = q.longArc; apply(); });
  }
  apply();
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const t = pingPong(timeline);
    const message = scene.draw(interpViewer, t);
    if (note.textContent !== message) note.textContent = message;
    det.setCursor?.(t);
    speed.setCursor?.(t);
    markDrawn('#fig-interp');
    if (circleViewer) {
      const said = scene.drawCircle(circleViewer, t);
      if (circleNote.textContent !== said) circleNote.textContent = said;
      markDrawn('#fig-circle');
    }
  });
} else {
  // Figure 2 draws Figure 1's scene; without a GPU it gets the same message as the others.
  await lesson.figure('#fig-circle');
}

// Figure 3: the gimbal.
const gimbalViewer = await lesson.figure('#fig-gimbal');
if (gimbalViewer) {
  gimbalViewer.setCamera(0, 1.4, 0, 5.2, 0.7, 0.35);
  const scene = new GimbalScene();
  // The timeline drives the steady turn only: it plays while the turn is ticked, and playing
  // or scrubbing it ticks the turn (otherwise nothing in the view would follow it).
  const timeline = new Timeline(document.getElementById('gimbal-timeline'), { duration: 6, playing: false });
  const p = {
    yaw: 30, pitch: 0, roll: 20, fly: false, miss: 5,
    lock: () => { p.fly = false; timeline.setPlaying(false); p.pitch = 90; refresh(); apply(); },
  };
  const gui = new GUI({ container: document.querySelector('#fig-gimbal .panel'), title: 'Gimbal (°)' });
  const angles = [
    gui.add(p, 'yaw', -180, 180, 1).name('yaw (outer, y)'),
    gui.add(p, 'pitch', -90, 90, 1).name('pitch (middle, x′)'),
    gui.add(p, 'roll', -180, 180, 1).name('roll (inner, z″)'),
  ];
  gui.add(p, 'lock').name('go to gimbal lock');
  gui.add(p, 'fly').name('fly a steady turn past the pole').onChange((on) => timeline.setPlaying(on));
  gui.add(p, 'miss', 0, 45, 1).name('distance from the pole (°)');
  const refresh = () => gui.controllersRecursive().forEach((c) => c.updateDisplay());
  const plot = new Plot(document.getElementById('gimbal-plot'), {
    title: 'A steady turn past the pole: the angles the rings need', xLabel: 't (0 to 1)', yLabel: 'angle (°)',
    series: ['yaw', 'pitch', 'roll'], colors: [cssVar('--y-axis') ?? '#2ca02c', cssVar('--orange') ?? '#e68a00', cssVar('--z-axis') ?? '#1f6fd6'],
    // Wide under narrow: yaw and roll swing together and would hide each other. As tall as
    // the plots of Figure 1: at the default height the swing past the pole is 90 px high.
    minSpan: 10, widths: [6, 2, 2], height: 240,
  });
  const note = document.getElementById('gimbal-note');
  function apply() {
    scene.setPoleMissDeg(p.miss);
    // Flying, the sliders show the angles the turn needs and cannot be moved.
    angles.forEach((c) => c.enable(!p.fly));
    if (!p.fly) scene.setAnglesDeg(p.yaw, p.pitch, p.roll);
    plot.setData(columns(scene.samplePoleTurn(241), 4));
    note.textContent = scene.note();
  }
  gui.onChange(apply);
  apply();
  let shownTime = timeline.time;
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const t = pingPong(timeline);
    if (!p.fly && timeline.time !== shownTime) {
      p.fly = true;
      refresh();
      apply();
    }
    shownTime = timeline.time;
    if (p.fly) {
      [p.yaw, p.pitch, p.roll] = Array.from(scene.flyAt(t), (x) => Math.round(x * 10) / 10);
      angles.forEach((c) => c.updateDisplay());
      const said = scene.note();
      if (note.textContent !== said) note.textContent = said;
    }
    plot.setCursor?.(p.fly ? t : null);
    scene.draw(gimbalViewer);
    markDrawn('#fig-gimbal');
  });
}

// Figure 3: Rodrigues' formula.
const rodViewer = await lesson.figure('#fig-rodrigues');
if (rodViewer) {
  rodViewer.setCamera(0, 0.3, 0, 4.2, 0.5, 0.35);
  const scene = new RodriguesScene();
  const timeline = new Timeline(document.getElementById('rodrigues-timeline'), {
    duration: 3, readout: (tl) => `${pingPong(tl).toFixed(2)} θ`,
  });
  const p = { angle: 120, nx: 0.3, ny: 1, nz: 0.2, vx: 1.2, vy: 0.4, vz: 0.3, useExercise: false };
  let accepted = { ...p };
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
  let rejected = '';
  const apply = () => {
    try {
      scene.setAxisAngle(p.nx, p.ny, p.nz, p.angle);
      scene.setVector(p.vx, p.vy, p.vz);
      accepted = { ...p };
      rejected = '';
    } catch (e) {
      // A zero axis is a mistake a reader can make with the sliders: say so, and put the
      // controls back to the values the figure still shows.
      rejected = `Not changed: ${e.message ?? e}`;
      revert(gui, p, accepted);
    }
    scene.setUseExercise(p.useExercise);
    showMatrix3(document.getElementById('rodrigues-matrix'), scene.matrix());
    document.getElementById('rodrigues-quat').textContent = `q = (${fmt(scene.quaternion())}) (x, y, z, w)`;
  };
  gui.onChange(apply);
  apply();
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const message = [rejected, scene.draw(rodViewer, pingPong(timeline))].filter(Boolean).join(' ');
    if (note.textContent !== message) note.textContent = message;
    markDrawn('#fig-rodrigues');
  });
}
