// Lesson 09: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/skinning/, src/figures/skinning.rs).
import { startLesson, markDrawn, Timeline, Plot, columns, GUI, showNote } from '../../www/lesson.js';
import { SkinningCylinderScene, SkinningSignScene, SkinnedHumanScene, heatRampCss } from '../../pkg/inbetween.js';
import { gltfFigure } from '../../www/gltf-figure.js';

const lesson = await startLesson();

// The heat maps' legends: the meshes' own colour ramp (from Rust), shown only while a joint's
// weights are painted, naming the joint.
const ramp = heatRampCss();
function heatLegend(selector) {
  const legend = document.querySelector(`${selector} .heat-legend`);
  legend.querySelector('.ramp').style.background = ramp;
  return (joint) => {
    legend.style.display = joint === 'none' ? 'none' : '';
    legend.querySelector('.heat-joint').textContent = joint;
  };
}

/** Figure 2: the tube's weights along it, with a falloff slider of its own (Figure 1 has one
 * too) that calls `setFalloff`. It needs no GPU, so it is drawn on a page without one too. */
function weightsFigure(scene, p, setFalloff) {
  const plot = new Plot(document.getElementById('weights-plot'), {
    title: 'Weights along the tube', xLabel: 'distance from the shoulder end (m)', yLabel: 'weight (no unit)',
    series: ['shoulder', 'elbow'], colors: ['#1f6fd6', '#d62728'], yRange: [-0.02, 1.02], height: 200,
  });
  const update = () => {
    const [x, shoulder, elbow] = columns(scene.weightCurves(), 3);
    plot.setData([x, shoulder, elbow]);
  };
  const gui = new GUI({ container: document.querySelector('#fig-weights .weights-panel'), title: 'Weights' });
  const falloff = gui.add(p, 'falloff', 0.01, 1, 0.01).name('falloff (m)').onChange(setFalloff);
  update();
  markDrawn('#fig-weights');
  return { update, falloff };
}

// Figure 1: the bend-and-twist cylinder, LBS beside DQS.
const cylinderViewer = await lesson.figure('#fig-cylinder');
if (cylinderViewer) {
  cylinderViewer.setCamera(0.3, 0.7, 0, 5.0, 0.0, 0.2);
  const scene = new SkinningCylinderScene();
  const p = { bend: 90, twist: 0, falloff: 0.15, heat: 'none', ring: 20, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-cylinder .panel'), title: 'Elbow' });
  const plot = new Plot(document.getElementById('cyl-plot'), {
    title: 'Elbow cross-section against the angle', xLabel: 'bend or twist angle (°)', yLabel: 'area (% of rest)',
    series: ['LBS, bend', 'DQS, bend', 'LBS, twist', 'DQS, twist'],
    colors: ['#e68a00', '#17a2a8', '#8c564b', '#944fc9'], minSpan: 5, height: 180,
    // Both DQS curves lie at 100%: the purple one, drawn last, is dashed so the teal one shows.
    dashes: [null, null, null, [6, 4]],
  });
  const volumePlot = new Plot(document.getElementById('cyl-plot-volume'), {
    title: 'Tube volume against the bend', xLabel: 'bend angle (°)', yLabel: 'volume (% of rest)',
    series: ['LBS', 'DQS'], colors: ['#e68a00', '#17a2a8'], yRange: [0, 105], height: 180,
  });
  function updatePlot() {
    const pct = (a) => Array.from(a, (x) => 100 * x);
    const [angle, lbsBend, dqsBend, lbsTwist, dqsTwist] = columns(scene.areaCurves(91), 5);
    plot.setData([angle, pct(lbsBend), pct(dqsBend), pct(lbsTwist), pct(dqsTwist)]);
    const [bend, lbs, dqs] = columns(scene.volumeCurves(37), 3);
    volumePlot.setData([bend, pct(lbs), pct(dqs)]);
  }
  // The dashed lines: where the pose lies on each plot's curves (none while bent and twisted).
  const moveCursors = () => {
    const [area, volume] = scene.plotCursors();
    plot.setCursor(area);
    volumePlot.setCursor(volume);
  };
  gui.add(p, 'bend', 0, 180, 1).name('bend (°)').onChange((v) => { scene.setBendDeg(v); moveCursors(); });
  gui.add(p, 'twist', -180, 180, 1).name('twist (°)').onChange((v) => { scene.setTwistDeg(v); moveCursors(); });
  const falloffs = [];
  const setFalloff = (v) => {
    scene.setFalloff(v);
    p.falloff = v;
    for (const c of falloffs) c.updateDisplay();
    updatePlot();
    weights.update();
  };
  falloffs.push(gui.add(p, 'falloff', 0.01, 1, 0.01).name('falloff (m)').onChange(setFalloff));
  const showLegend = heatLegend('#fig-cylinder');
  gui.add(p, 'heat', ['none', 'shoulder', 'elbow']).name('weights of').onChange((v) => { scene.setHeatJoint(v); showLegend(v); });
  showLegend(p.heat);
  gui.add(p, 'ring', 0, 40, 1).name('followed vertex (ring)').onChange((r) => scene.setProbeRing(r));
  gui.add(p, 'useExercise').name('use my exercise').onChange((on) => scene.setUseExercise(on));
  // Figure 2: the same tube's weights.
  const weights = weightsFigure(scene, p, setFalloff);
  falloffs.push(weights.falloff);
  updatePlot();
  moveCursors();

  const note = document.getElementById('cyl-note');
  lesson.onFrame(() => {
    showNote(note, scene.draw(cylinderViewer));
    markDrawn('#fig-cylinder');
  });
}

// Without a 3D view Figure 2 still plots the tube's weights.
if (!cylinderViewer) {
  const scene = new SkinningCylinderScene();
  const p = { falloff: 0.15 };
  const weights = weightsFigure(scene, p, (v) => { scene.setFalloff(v); weights.update(); });
}

// Figure 3: the antipodality fix, the tube twisted 0 to 360° by DQS.
const signViewer = await lesson.figure('#fig-sign');
if (signViewer) {
  signViewer.setCamera(0.8, 1.0, 0, 5.5, 0.0, 0.1);
  const scene = new SkinningSignScene();
  const p = { twist: 300, fix: true };
  const gui = new GUI({ container: document.querySelector('#fig-sign .panel'), title: 'Twist' });
  // From 150°: below it the fix never matters, and the slider's travel goes to where it does.
  gui.add(p, 'twist', 150, 360, 1).name('twist (°)').onChange((v) => scene.setTwistDeg(v));
  gui.add(p, 'fix').name('antipodality fix').onChange((on) => scene.setFix(on));
  const note = document.getElementById('sign-note');
  lesson.onFrame(() => {
    showNote(note, scene.draw(signViewer));
    markDrawn('#fig-sign');
  });
}

// Figure 4: the built-in human, skinned by LBS and DQS side by side, playing a clip.
const humanViewer = await lesson.figure('#fig-human');
if (humanViewer) {
  // From the character's left, a little raised: both bodies side by side, knees in profile.
  humanViewer.setCamera(0, 0.9, 0, 3.2, 1.45, 0.15);
  const scene = new SkinnedHumanScene();
  const timeline = new Timeline(document.getElementById('human-timeline'), { duration: scene.durationSec(), playing: true });
  const p = { clip: 'walk', view: 'whole body', heat: 'none', falloff: 0.03, skeleton: false, on: 'CPU' };
  const plot = new Plot(document.getElementById('human-plot'), {
    title: 'Left leg volume over the clip', xLabel: 'time (s)', yLabel: 'volume (% of rest)',
    series: ['LBS', 'DQS'], colors: ['#e68a00', '#17a2a8'], widths: [2.5, 2.5], minSpan: 2, height: 200,
  });
  const replot = () => {
    const [t, lbs, dqs] = columns(scene.legVolumeCurves(41), 3);
    const pct = (a) => Array.from(a, (x) => 100 * x);
    plot.setData([t, pct(lbs), pct(dqs)]);
  };
  const gui = new GUI({ container: document.querySelector('#fig-human .panel'), title: 'Character' });
  gui.add(p, 'clip', scene.clipNames()).name('clip').onChange((name) => {
    scene.setClip(name);
    timeline.duration = scene.durationSec();
    timeline.time %= timeline.duration;
    timeline.show();
    replot();
  });
  gui.add(p, 'view', ['whole body', 'left legs']).name('view').onChange((v) => { scene.setView(v); humanViewer.frameAll(); });
  const showLegend = heatLegend('#fig-human');
  gui.add(p, 'heat', ['none', ...scene.jointNames()]).name('weights of').onChange((j) => {
    scene.setHeatJoint(j);
    showLegend(j);
    // The legs view holds the heat map's joint too: fit it again.
    if (p.view === 'left legs') humanViewer.frameAll();
  });
  showLegend(p.heat);
  const [lowest, highest] = scene.falloffRange();
  gui.add(p, 'falloff', lowest, highest, 0.005).name('falloff (m)').onChange((f) => { scene.setFalloff(f); replot(); });
  gui.add(p, 'skeleton').name('skeleton').onChange((on) => scene.setShowSkeleton(on));
  gui.add(p, 'on', ['CPU', 'GPU']).name('skin on').onChange((v) => { scene.setGpu(v === 'GPU'); times.length = 0; });
  replot();

  const note = document.getElementById('human-note');
  // performance.now() is coarse (0.1 ms, with jitter) next to one frame's work: the note gives the
  // mean over the last 60 frames, which the coarse steps average out of.
  const times = [];
  const MIN_FRAMES = 10;
  let frameMs = 0;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    // Paused with nothing changed, the scene has nothing to skin (undefined): the mean stays.
    const ms = scene.skin(t);
    if (ms !== undefined) times.push(ms);
    if (times.length > 60) times.shift();
    const mean = times.reduce((a, b) => a + b, 0) / times.length;
    frameMs = frameMs === 0 ? 1000 * dt : 0.9 * frameMs + 0.1 * 1000 * dt;
    // A mean of a few coarse samples is no measurement: below MIN_FRAMES the note says so.
    const work = times.length < MIN_FRAMES
      ? `Skinning on the ${p.on}: no measurement yet (${times.length} of ${MIN_FRAMES} frames skinned since it moved; play the clip)`
      : p.on === 'GPU'
        ? `Skinning on the GPU: the CPU spends ${mean.toFixed(2)} ms a frame on the clip and the palettes (mean of the last ${times.length} frames)`
        : `Skinning on the CPU: ${mean.toFixed(2)} ms a frame for the clip, the palettes and both bodies (mean of the last ${times.length} frames)`;
    showNote(note, `${scene.draw(humanViewer)} ${work}; frame time ${frameMs.toFixed(1)} ms.`);
    plot.setCursor(t);
    markDrawn('#fig-human');
  });
}

// Figure 5: a character from a glTF file, skinned (the shared glTF figure, www/gltf-figure.js).
await gltfFigure(lesson, '#fig-gltf', { skinning: 'lbs', gpuSwitch: true });
