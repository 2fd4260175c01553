// Lesson 06: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/skeleton/, src/figures/skeleton.rs), including which joint is under the pointer.
import { startLesson, markDrawn, Timeline, Plot, showMatrix, columns, GUI, showNote } from '../../www/lesson.js';
import { SkeletonScene } from '../../pkg/inbetween.js';
import { gltfFigure } from '../../www/gltf-figure.js';

const lesson = await startLesson();

// Two series that can coincide: the first 5 px wide underneath, the second 1.5 px on top.
const UNDER_AND_OVER = [5, 1.5];
const PURPLE = '#944fc9';
const BLUE = '#1f6fd6';
const ORANGE = '#e68a00';
const BROWN = '#8c564b';

/** An angle slider that shows whole degrees. */
function addAngle(folder, object, key, name) {
  const c = folder.add(object, key, -180, 180, 1).name(name);
  return c.decimals ? c.decimals(0) : c;
}

// Figures 1-3: the same skeleton scene, each beside the section it illustrates and starting
// from that section's settings, with the controls that section needs.
// Figure 1 starts with the selected joint's axes only: 21 triads crowd the skeleton, the group
// and the path (the checkbox shows them all).
await skeletonFigure('#fig-skeleton', {
  clip: 'walk', keys: 9, joint: 'thigh.L', axes: false,
  controls: ['clip', 'joint', 'angles', 'axes', 'boxes'], table: true, matrices: true,
});
await skeletonFigure('#fig-interpolation', {
  clip: 'arm circles', keys: 4, joint: 'upper_arm.L', interpolation: 'linear (slerp)',
  compare: 'linear (nlerp)', axes: false, camera: [1.2, 0.15],
  controls: ['clip', 'keys', 'interpolation', 'compare', 'joint'], plots: true,
});
await skeletonFigure('#fig-crossfade', {
  clip: 'walk', keys: 9, joint: 'upper_arm.R', blend: 'wave', weight: 0.5, axes: false,
  controls: ['clip', 'blend', 'joint'],
});

async function skeletonFigure(id, start) {
  const viewer = await lesson.figure(id);
  if (!viewer) return;
  const figure = document.querySelector(id);
  const has = (name) => start.controls.includes(name);
  // Yaw and pitch: from the front right, or (Figure 2) from the left, where the arm's circle
  // faces the camera; the scene declares what stays in view and the camera fits it.
  const [yaw, pitch] = start.camera ?? [0.5, 0.2];
  viewer.setCamera(0, 0.85, 0, 2.5, yaw, pitch);
  const scene = new SkeletonScene();
  const names = scene.jointNames();
  const parents = scene.parents();
  const groups = scene.groupSizes();
  const p = {
    clip: start.clip, keys: start.keys, interpolation: start.interpolation ?? 'linear (slerp)',
    compare: start.compare ?? 'none', joint: start.joint, x: 0, y: 0, z: 0,
    blend: start.blend ?? 'none', weight: start.weight ?? 0.5, boxes: false, axes: start.axes, useExercise: false,
    reset: () => { scene.resetPose(); readJoint(); refresh(); update(); },
  };
  scene.setClip(p.clip);
  scene.setKeysPerCycle(p.keys);
  scene.setInterpolation(p.interpolation);
  scene.setCompare(p.compare);
  scene.setBlend(p.blend, p.weight);
  scene.setShowAxes(p.axes);
  const timeline = new Timeline(figure.querySelector('.timeline'), { duration: scene.durationSec(), playing: true });
  const index = () => names.indexOf(p.joint);
  const gui = new GUI({ container: figure.querySelector('.panel'), title: 'Skeleton' });
  const refresh = () => gui.controllersRecursive().forEach((c) => c.updateDisplay());
  const readJoint = () => { [p.x, p.y, p.z] = scene.jointAnglesDeg(index()).map((v) => Math.round(v)); };

  // The joint table (Figure 1): rows built once from the skeleton's arrays; clicking a row
  // selects its joint.
  const body = start.table ? figure.querySelector('table.joints tbody') : null;
  names.forEach((name, i) => {
    if (!body) return;
    const row = document.createElement('tr');
    for (const [text, cls] of [[i, ''], [name, 'name'], [parents[i], ''], [groups[i], '']]) {
      const cell = document.createElement('td');
      cell.textContent = String(text);
      if (cls) cell.className = cls;
      row.appendChild(cell);
    }
    row.addEventListener('click', () => { p.joint = name; selectJoint(); });
    body.appendChild(row);
  });
  function showSelectionInTable() {
    if (!body) return;
    const s = index();
    [...body.rows].forEach((row, i) => {
      row.classList.toggle('selected', i === s);
      row.classList.toggle('group', i > s && i < s + groups[s]);
    });
    // Scroll the table's own box (not the page) so the selected row shows.
    const box = body.closest('.joint-table-box');
    const row = body.rows[s];
    const head = body.parentElement.tHead.offsetHeight;
    if (row.offsetTop < box.scrollTop + head || row.offsetTop + row.offsetHeight > box.scrollTop + box.clientHeight) {
      box.scrollTop = Math.max(0, row.offsetTop - head - 2 * row.offsetHeight);
    }
  }

  // Key marks under the timeline's scrub.
  const strip = figure.querySelector('.key-strip');
  function showKeys() {
    if (!strip) return;
    const scrub = figure.querySelector('.timeline .scrub');
    const area = strip.getBoundingClientRect();
    const box = scrub.getBoundingClientRect();
    const inset = 8; // half the slider thumb: where 0 and the end sit on the track
    const x0 = box.left - area.left + inset;
    const width = box.width - 2 * inset;
    const duration = scene.durationSec();
    strip.replaceChildren(...Array.from(scene.keyTimes(), (t) => {
      const mark = document.createElement('span');
      mark.style.left = `${x0 + (width * t) / duration}px`;
      mark.title = `key at ${t.toFixed(3)} s`;
      return mark;
    }));
  }
  if (strip) new ResizeObserver(showKeys).observe(strip);

  // Figure 1 plots the selected joint's angle; Figure 2 the angle and speed under both
  // interpolations (purple wide underneath, blue narrow on top: where they agree both show).
  const plots = [];
  // Figure 3 plots the angle under clip A alone, the blend and clip B alone.
  const angleBox = figure.querySelector('.plot-angle');
  const angleSeries = start.plots ? [['purple path', PURPLE, 1], ['blue path', BLUE, 3]]
    : start.blend ? [['clip A alone', BLUE, 5], ['blend', ORANGE, 1], ['clip B alone', BROWN, 6]]
      : [['angle', ORANGE, 1]];
  if (angleBox) {
    plots.push([new Plot(angleBox, {
      title: 'Selected joint: angle from rest', xLabel: 'time (s)', yLabel: 'angle (°)',
      series: angleSeries.map((a) => a[0]), colors: angleSeries.map((a) => a[1]),
      widths: start.blend ? [2.5, 2.5, 2.5] : UNDER_AND_OVER, minSpan: 5, height: 160,
    }), angleSeries.map((a) => a[2]), true]);
  }
  const speedBox = figure.querySelector('.plot-speed');
  if (speedBox) {
    plots.push([new Plot(speedBox, {
      title: 'Selected joint: turning speed', xLabel: 'time (s)', yLabel: 'speed (°/s)',
      series: ['purple path', 'blue path'], colors: [PURPLE, BLUE], widths: UNDER_AND_OVER, minSpan: 5, height: 160,
    }), [2, 4]]);
  }
  function update() {
    const cols = columns(scene.sampleSelected(241), 7);
    for (const [plot, which, fromZero] of plots) {
      const ys = which.map((k) => cols[k]);
      // An angle from rest is never negative: its axis starts at 0 (at rest), which a curve
      // that lies there a long time reads against. The speeds keep their own range, where
      // slerp's and nlerp's differ.
      if (fromZero) plot.setYRange([0, Math.max(...ys.map((c) => Math.max(...c)))]);
      plot.setData([cols[0], ...ys]);
    }
    showKeys();
  }
  function selectJoint() {
    scene.select(index());
    readJoint();
    refresh();
    showSelectionInTable();
    update();
  }

  if (has('clip')) {
    // Figure 2 samples keys: the rest pose (no keys) is not offered there.
    const clips = has('keys') ? scene.clipNames().slice(0, -1) : scene.clipNames();
    gui.add(p, 'clip', clips).name(start.blend ? 'clip A' : 'clip').onChange(() => {
      scene.setClip(p.clip);
      timeline.duration = scene.durationSec();
      timeline.time %= timeline.duration;
      timeline.show();
      update();
    });
  }
  if (has('keys')) gui.add(p, 'keys', 4, 25, 1).name('keys per cycle').onChange(() => { scene.setKeysPerCycle(p.keys); update(); });
  const methods = ['step', 'linear (nlerp)', 'linear (slerp)', 'cubic'];
  if (has('interpolation')) {
    gui.add(p, 'interpolation', methods).name('purple path').onChange(() => { scene.setInterpolation(p.interpolation); update(); });
  }
  if (has('compare')) {
    gui.add(p, 'compare', ['none', ...methods]).name('blue path').onChange(() => { scene.setCompare(p.compare); update(); });
  }
  if (has('blend')) {
    const applyBlend = () => { scene.setBlend(p.blend, p.weight); update(); };
    gui.add(p, 'blend', ['none', ...scene.clipNames().slice(0, -1)]).name('clip B').onChange(applyBlend);
    gui.add(p, 'weight', 0, 1, 0.01).name('weight of B').onChange(applyBlend);
  }
  gui.add(p, 'joint', names).name('joint').onChange(selectJoint);
  if (has('angles')) {
    const angles = gui.addFolder('angles on top of the clip (°)');
    for (const axis of ['x', 'y', 'z']) {
      addAngle(angles, p, axis, `about ${axis}`).onChange(() => {
        scene.setJointAnglesDeg(index(), p.x, p.y, p.z);
        update();
      });
    }
  }
  if (has('axes')) gui.add(p, 'axes').name('every joint\'s axes').onChange((on) => scene.setShowAxes(on));
  if (has('boxes')) gui.add(p, 'boxes').name('body boxes').onChange((on) => scene.setShowBoxes(on));
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  if (has('angles')) gui.add(p, 'reset').name('reset the angles');
  selectJoint();

  // A click (not a drag) on a joint selects it: the scene casts the pointer's ray at the joints.
  const canvas = figure.querySelector('.stage canvas');
  let down = null;
  canvas.addEventListener('pointerdown', (e) => { down = [e.clientX, e.clientY]; });
  canvas.addEventListener('pointerup', (e) => {
    if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    down = null;
    const r = canvas.getBoundingClientRect();
    const j = scene.pickJoint(e.clientX - r.left, e.clientY - r.top, r.width, r.height);
    if (j >= 0) {
      p.joint = names[j];
      selectJoint();
    }
  });

  const note = figure.querySelector('.note');
  const local = figure.querySelector('.matrix-local');
  const model = figure.querySelector('.matrix-model');
  let frame = 0;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, scene.draw(viewer, t));
    for (const [plot] of plots) plot.setCursor?.(t);
    if (local && frame++ % 6 === 0) {
      showMatrix(local, scene.localMatrix(index()));
      showMatrix(model, scene.modelMatrix(index()));
    }
    markDrawn(id);
  });
}

// Figure 4: a character from a glTF file (the samples served with the site, or the reader's own).
await gltfFigure(lesson, '#fig-gltf');
