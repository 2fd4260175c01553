// Lesson 06: wires the page's controls to the wasm scene. No math here: it lives in Rust
// (src/skeleton/, src/figures/skeleton.rs).
import { startLesson, markDrawn, Timeline, Plot, showMatrix, columns, GUI, showNote } from '../../www/lesson.js';
import { SkeletonScene } from '../../pkg/inbetween.js';
import { gltfFigure } from '../../www/gltf-figure.js';

const lesson = await startLesson();

/** An angle slider that shows whole degrees. */
function addAngle(folder, object, key, name) {
  const c = folder.add(object, key, -180, 180, 1).name(name);
  return c.decimals ? c.decimals(0) : c;
}

const viewer = await lesson.figure('#fig-skeleton');
if (viewer) {
  viewer.setCamera(0, 0.85, 0, 2.5, 0.5, 0.2);
  const scene = new SkeletonScene();
  const names = scene.jointNames();
  const parents = scene.parents();
  const groups = scene.groupSizes();
  const timeline = new Timeline(document.getElementById('skel-timeline'), { duration: scene.durationSec(), playing: true });
  const p = {
    clip: 'walk', keys: 9, interpolation: 'linear (slerp)', joint: 'thigh.L',
    x: 0, y: 0, z: 0, blend: 'none', weight: 0.5, boxes: false, axes: true, useExercise: false,
    reset: () => { scene.resetPose(); readJoint(); refresh(); update(); },
  };
  const index = () => names.indexOf(p.joint);
  const gui = new GUI({ container: document.querySelector('#fig-skeleton .panel'), title: 'Skeleton' });
  const refresh = () => gui.controllersRecursive().forEach((c) => c.updateDisplay());
  const readJoint = () => { [p.x, p.y, p.z] = scene.jointAnglesDeg(index()).map((v) => Math.round(v)); };

  // The joint table: rows built once from the skeleton's arrays; clicking a row selects its joint.
  const body = document.querySelector('#skel-table tbody');
  names.forEach((name, i) => {
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
  const strip = document.getElementById('skel-keys');
  function showKeys() {
    const scrub = document.querySelector('#skel-timeline .scrub');
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
  new ResizeObserver(showKeys).observe(strip);

  const anglePlot = new Plot(document.getElementById('skel-plot-angle'), {
    title: 'Selected joint: angle from rest', xLabel: 'time (s)', yLabel: 'angle (°)',
    series: ['angle'], colors: ['#e68a00'], minSpan: 5, height: 160,
  });
  const speedPlot = new Plot(document.getElementById('skel-plot-speed'), {
    title: 'Selected joint: turning speed', xLabel: 'time (s)', yLabel: 'speed (°/s)',
    series: ['speed'], colors: ['#944fc9'], minSpan: 5, height: 160,
  });
  function update() {
    const [time, angle, speed] = columns(scene.sampleSelected(241), 3);
    anglePlot.setData([time, angle]);
    speedPlot.setData([time, speed]);
    showKeys();
  }
  function selectJoint() {
    scene.select(index());
    readJoint();
    refresh();
    showSelectionInTable();
    update();
  }

  gui.add(p, 'clip', scene.clipNames()).name('clip').onChange(() => {
    scene.setClip(p.clip);
    timeline.duration = scene.durationSec();
    timeline.time %= timeline.duration;
    timeline.show();
    update();
  });
  gui.add(p, 'keys', 4, 25, 1).name('keys per cycle').onChange(() => { scene.setKeysPerCycle(p.keys); update(); });
  gui.add(p, 'interpolation', ['step', 'linear (nlerp)', 'linear (slerp)', 'cubic']).name('interpolation').onChange(() => {
    scene.setInterpolation(p.interpolation);
    update();
  });
  const blending = gui.addFolder('crossfade a second clip');
  const applyBlend = () => { scene.setBlend(p.blend, p.weight); update(); };
  blending.add(p, 'blend', ['none', ...scene.clipNames().slice(0, -1)]).name('with clip').onChange(applyBlend);
  blending.add(p, 'weight', 0, 1, 0.01).name('weight of it').onChange(applyBlend);
  gui.add(p, 'joint', names).name('joint').onChange(selectJoint);
  const angles = gui.addFolder('angles on top of the clip (°)');
  for (const axis of ['x', 'y', 'z']) {
    addAngle(angles, p, axis, `about ${axis}`).onChange(() => {
      scene.setJointAnglesDeg(index(), p.x, p.y, p.z);
      update();
    });
  }
  gui.add(p, 'axes').name('every joint\'s axes').onChange((on) => scene.setShowAxes(on));
  gui.add(p, 'boxes').name('body boxes').onChange((on) => scene.setShowBoxes(on));
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  gui.add(p, 'reset').name('reset the angles');
  selectJoint();

  const note = document.getElementById('skel-note');
  let frame = 0;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, scene.draw(viewer, t));
    anglePlot.setCursor?.(t);
    speedPlot.setCursor?.(t);
    if (frame++ % 6 === 0) {
      showMatrix(document.getElementById('skel-local'), scene.localMatrix(index()));
      showMatrix(document.getElementById('skel-model'), scene.modelMatrix(index()));
    }
    markDrawn('#fig-skeleton');
  });
}

// Figure 2: a character from a glTF file (the samples served with the site, or the reader's own).
await gltfFigure(lesson, '#fig-gltf');
