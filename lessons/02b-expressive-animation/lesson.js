// Lesson 02b: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/expressive/ and src/figures/expressive.rs).
import { startLesson, markDrawn, Timeline, Plot, GUI, columns, guarded, cssVar } from '../../www/lesson.js';
import { SpacingScene, JumpScene, FollowThroughScene, StretchScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// Figure 1: timing and spacing.
const spacingViewer = await lesson.figure('#fig-spacing');
if (spacingViewer) {
  spacingViewer.setCamera(0, 0.9, 0, 7.5, 0.0, 0.35);
  const scene = new SpacingScene();
  // One loop: key 1 to key 2, then back with the same spacing (the scene says where the ball is).
  const timeline = new Timeline(document.getElementById('spacing-timeline'), { duration: scene.loopSec });
  const p = { ease: 'slow in and out', arc: 1.2, twin: true, ghosts: 12, squash: true, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-spacing .panel'), title: 'Spacing' });
  gui.add(p, 'ease', ['slow in and out', 'linear', 'ease in', 'ease out']).name('spacing');
  gui.add(p, 'arc', 0, 3, 0.05).name('arc height (m)');
  gui.add(p, 'twin').name('straight line beside');
  gui.add(p, 'ghosts', 2, 60, 1).name('ghosts');
  gui.add(p, 'squash').name('squash and stretch');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('spacing-plot'), {
    title: 'Spacing: how far along the path from key 1', xLabel: 'time (s)', yLabel: 'fraction of path (no unit)',
    series: ['this spacing', 'linear'], colors: [cssVar('--z-axis'), cssVar('--grey')], minSpan: 0.5,
    widths: [2.5, 5], // linear drawn wide underneath: with linear spacing the two coincide
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setEase(p.ease);
    scene.setArcHeight(p.arc);
    scene.setTwin(p.twin);
    scene.setGhosts(p.ghosts);
    scene.setSquash(p.squash);
    scene.setUseExercise(p.useExercise);
    plot.setData(columns(scene.sampleSpacing(101), 3));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('spacing-note');
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const message = [rejected, scene.draw(spacingViewer, timeline.time)].filter(Boolean).join(' ');
    if (note.textContent !== message) note.textContent = message;
    plot.setCursor(timeline.time);
    markDrawn('#fig-spacing');
  });
}

// Figure 2: squash and stretch with the volume kept, beside a stretch that keeps the width.
const stretchViewer = await lesson.figure('#fig-stretch');
if (stretchViewer) {
  stretchViewer.setCamera(0, 1.3, 0, 7, 0.0, 0.0);
  const scene = new StretchScene();
  const p = { stretch: 1.6, angle: 30 };
  const gui = new GUI({ container: document.querySelector('#fig-stretch .panel'), title: 'Stretch' });
  gui.add(p, 'stretch', 0.4, 2.5, 0.01).name('stretch s');
  gui.add(p, 'angle', -90, 90, 1).name('direction a (°)');
  let rejected = '';
  const apply = guarded(gui, p, () => scene.set(p.stretch, p.angle), (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('stretch-note');
  lesson.onFrame(() => {
    const message = [rejected, scene.draw(stretchViewer)].filter(Boolean).join(' ');
    if (note.textContent !== message) note.textContent = message;
    markDrawn('#fig-stretch');
  });
}

// Figure 3: the jump, side by side.
const jumpViewer = await lesson.figure('#fig-jump');
if (jumpViewer) {
  jumpViewer.setCamera(0, 1.1, 0, 6, 0.0, 0.15);
  const scene = new JumpScene();
  const timeline = new Timeline(document.getElementById('jump-timeline'), { duration: scene.duration });
  const p = { anticipation: 0.3, stretch: 0.06, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-jump .panel'), title: 'Principles' });
  gui.add(p, 'anticipation', 0, 0.6, 0.01).name('anticipation (crouch)');
  gui.add(p, 'stretch', 0, 0.2, 0.005).name('stretch k_s (per m/s)');
  gui.add(p, 'useExercise').name('use my exercise');
  // Two plots, one quantity each: height in metres, stretch as a ratio.
  const plot = new Plot(document.getElementById('jump-plot'), {
    title: 'Height of the ball', xLabel: 'time (s)', yLabel: 'height (m)',
    series: ['plain', 'with the principles'],
    colors: [cssVar('--grey'), cssVar('--orange')], minSpan: 1,
  });
  const stretchPlot = new Plot(document.getElementById('jump-stretch-plot'), {
    title: 'Stretch of the ball with the principles', xLabel: 'time (s)', yLabel: 'stretch s (ratio)',
    series: ['stretch s', 'plain (rigid, 1)'], colors: [cssVar('--orange'), cssVar('--grey')], minSpan: 0.5,
    widths: [4, 1.5], // at rest the stretch is 1: wide under the plain line, both stay visible
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setPrinciples(p.anticipation, p.stretch);
    scene.setUseExercise(p.useExercise);
    const [t, plain, principled, stretch] = columns(scene.sampleHeights(481), 4);
    plot.setData([t, plain, principled]);
    stretchPlot.setData([t, stretch, t.map(() => 1)]);
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('jump-note');
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const message = [rejected, scene.draw(jumpViewer, timeline.time)].filter(Boolean).join(' ');
    if (note.textContent !== message) note.textContent = message;
    plot.setCursor(timeline.time);
    stretchPlot.setCursor(timeline.time);
    markDrawn('#fig-jump');
  });
}

// Figure 4: follow-through.
const followViewer = await lesson.figure('#fig-follow');
if (followViewer) {
  // From the front left and above: the 3.7 m slide, seen at an angle, and the antenna fill the
  // canvas both ways at both page sizes, and the body starts (t = 0) at the near end.
  followViewer.setCamera(0, 1.3, 0, 4.2, -0.3, 0.35);
  const scene = new FollowThroughScene();
  const timeline = new Timeline(document.getElementById('follow-timeline'), { duration: 4 });
  const p = { stiffness: 150, damping: 10, joints: 6, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-follow .panel'), title: 'Antenna' });
  // The limits the scene takes (FollowThrough::MIN_STIFFNESS, MIN_DAMPING, MAX_JOINTS).
  gui.add(p, 'stiffness', 50, 600, 1).name('stiffness k (1/s²)');
  gui.add(p, 'damping', 8, 60, 0.5).name('damping c (1/s)');
  gui.add(p, 'joints', 2, 6, 1).name('joints');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('follow-plot'), {
    title: 'Base and tip, side to side', xLabel: 'time (s)', yLabel: 'x (m)',
    series: ['base', 'tip'], colors: [cssVar('--teal'), cssVar('--pink')], minSpan: 1,
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.set(p.stiffness, p.damping, p.joints);
    scene.setUseExercise(p.useExercise);
    plot.setData(columns(scene.sampleTip(201), 3));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('follow-note');
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const message = [rejected, scene.draw(followViewer, timeline.time)].filter(Boolean).join(' ');
    if (note.textContent !== message) note.textContent = message;
    plot.setCursor(timeline.time);
    markDrawn('#fig-follow');
  });
}
