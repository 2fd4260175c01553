// Lesson 11: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/particles/, src/figures/particles.rs).
import { startLesson, markDrawn, Timeline, Plot, GUI, columns, spanTimeline, guarded, showNote, cssVar } from '../../www/lesson.js';
import { EmitterScene, FreeFallScene, OscillatorScene, BounceScene, SquashScene, SmokeScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();

// Figure 1: emitters and sprites.
const emitterViewer = await lesson.figure('#fig-emitters');
if (emitterViewer) {
  emitterViewer.setCamera(0.2, 1.0, 0, 6.5, 0.35, 0.3);
  const scene = new EmitterScene();
  const timeline = new Timeline(document.getElementById('emitters-timeline'), { duration: 6 });
  const p = {
    mode: 'fountain', rate: 200, burst: 400, spread: 11, lifetime: 2.5, restitution: 0.7, gravity: 9.81,
    sort: true, fade: true, on: 'CPU', explode: () => scene.explode(emitterViewer),
  };
  const gui = new GUI({ container: document.querySelector('#fig-emitters .panel'), title: 'Emitters' });
  gui.add(p, 'mode', ['fountain', 'both', 'explosion']).name('emitter');
  gui.add(p, 'rate', 0, 1000, 10).name('fountain rate (1/s)');
  gui.add(p, 'burst', 0, 800, 10).name('particles per explosion');
  gui.add(p, 'spread', 0, 90, 1).name('cone half-angle (°)');
  gui.add(p, 'lifetime', 0.2, 6, 0.1).name('lifetime (s)');
  gui.add(p, 'restitution', 0, 1, 0.05).name('restitution e');
  gui.add(p, 'gravity', 0, 20, 0.01).name('gravity (m/s²)');
  // The GPU's sprites are drawn in storage order (they never come back to sort): the box is
  // greyed out while the GPU steps, so it does not look as if it still did something.
  const sortControl = gui.add(p, 'sort').name('sort back to front');
  gui.add(p, 'fade').name('fade with age');
  let rejected = '';
  // CPU or WebGPU compute shaders; WebGL2 has no compute shaders, so there the switch is off.
  const hasCompute = emitterViewer.backend === 'WebGPU';
  const COUNT_TITLE = 'Live particles';
  const onControl = gui.add(p, 'on', ['CPU', 'GPU']).name('step on').onChange((v) => {
    try {
      scene.setGpu(emitterViewer, v === 'GPU');
      sortControl.enable(v !== 'GPU');
      // The plot's legend still lists the counts, which the GPU does not give: its title says so.
      countPlot.setTitle(v === 'GPU' ? `${COUNT_TITLE}: not counted on the GPU, guides only` : COUNT_TITLE);
    } catch (e) { rejected = e.message; }
  });
  if (!hasCompute) onControl.disable();
  gui.add(p, 'explode').name('explode now');
  const apply = guarded(gui, p, () => {
    scene.setMode(p.mode);
    scene.setRate(p.rate);
    scene.setBurst(p.burst);
    scene.setSpreadDeg(p.spread);
    scene.setLifetime(p.lifetime);
    scene.setRestitution(p.restitution);
    scene.setGravity(p.gravity);
    scene.setSort(p.sort);
    scene.setFade(p.fade);
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('emitters-note');
  // Live particles against time, from Rust: one sample per step since the run started, with
  // rate × lifetime and the fountain's slots as guides.
  const countPlot = new Plot(document.getElementById('emitters-plot'), {
    title: COUNT_TITLE, xLabel: 'time (s)', yLabel: 'particles (count)',
    series: ['fountain', 'explosions', 'rate × lifetime', 'fountain\'s slots'],
    colors: [cssVar('--z-axis'), cssVar('--orange'), cssVar('--dark'), cssVar('--grey')],
    dashes: [null, null, [6, 4], [2, 3]], minSpan: 10, points: false,
  });
  let frame = 0;
  let plotTime = -1;
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(emitterViewer, t),
      hasCompute ? '' : '(Step on GPU needs WebGPU: this browser draws with WebGL2, which has no compute shaders.)',
      // Nothing comes back from the GPU: Rust's counts are NaN in this mode, the guides numbers.
      p.on === 'GPU' ? 'The GPU\'s particles are not read back, so they are not counted: the plot keeps only its guides until step on is CPU again.' : '',
    ].filter(Boolean).join(' '));
    // Whenever the time moves, so the curve reaches the playhead (every frame while playing:
    // the playhead's redraw redraws the plot anyway), and every sixth frame when paused, for a
    // setting that starts the run again; the x axis always spans the whole loop.
    if (t !== plotTime || frame++ % 6 === 0) {
      const cols = columns(Array.from(scene.countSamples(), (v) => (Number.isNaN(v) ? null : v)), 5);
      countPlot.setData(spanTimeline(cols, timeline.duration));
      plotTime = t;
    }
    countPlot.setCursor(t);
    markDrawn('#fig-emitters');
  }, emitterViewer);
}

// Figure 2: free fall, exact vs integrated.
const fallViewer = await lesson.figure('#fig-freefall');
if (fallViewer) {
  fallViewer.setCamera(-0.3, 1.3, 0, 5.5, 0.0, 0.1);
  const scene = new FreeFallScene();
  // A little longer than the throw: a playing timeline wraps before it reaches its duration, and
  // the throw's last step (at 1.3 s with Δt = 0.1 s, the plot's last point) must be shown too.
  const timeline = new Timeline(document.getElementById('freefall-timeline'), { duration: scene.durationSec() + 0.05 });
  const p = { dt: 0.1, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-freefall .panel'), title: 'Integrators' });
  gui.add(p, 'dt', 0.01, 0.3, 0.01).name('step size Δt (s)');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('freefall-plot'), {
    title: 'Height above the exact parabola (y − y_exact)', xLabel: 'time (s)', yLabel: 'height error (m)',
    series: ['explicit Euler', 'semi-implicit Euler', 'velocity Verlet'],
    colors: [cssVar('--x-axis'), cssVar('--z-axis'), cssVar('--y-axis')], minSpan: 0.01,
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setDt(p.dt);
    scene.setUseExercise(p.useExercise);
    plot.setData(columns(scene.errorSamples(), 4));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('freefall-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(fallViewer, t)].filter(Boolean).join(' '));
    plot.setCursor(t);
    markDrawn('#fig-freefall');
  }, fallViewer);
}

// Figure 3: a spring stepped by the three integrators, and their energy.
const springViewer = await lesson.figure('#fig-spring');
if (springViewer) {
  const scene = new OscillatorScene();
  springViewer.setCamera(...scene.view());
  const timeline = new Timeline(document.getElementById('spring-timeline'), { duration: 10 });
  const p = { dt: 0.02 };
  const gui = new GUI({ container: document.querySelector('#fig-spring .panel'), title: 'Spring' });
  gui.add(p, 'dt', 0.005, 0.2, 0.005).name('step size Δt (s)');
  // Semi-implicit Euler wide under Verlet's narrower line: the two nearly coincide. Tall, so that
  // semi-implicit Euler's swings show on the 0 to 4 scale that explicit Euler's growth needs.
  const plot = new Plot(document.getElementById('spring-plot'), {
    title: 'Energy over its starting value', xLabel: 'time (s)', yLabel: 'E / E₀ (no unit)',
    series: ['explicit Euler', 'semi-implicit Euler', 'velocity Verlet'],
    colors: [cssVar('--x-axis'), cssVar('--z-axis'), cssVar('--y-axis')], widths: [2, 6, 3], yRange: [0, 4], height: 240,
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setDt(p.dt);
    plot.setData(columns(scene.energySamples(), 4));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('spring-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(springViewer, t)].filter(Boolean).join(' '));
    plot.setCursor(t);
    markDrawn('#fig-spring');
  }, springViewer);
}

// Figure 4: bouncing balls.
const bounceViewer = await lesson.figure('#fig-bounce');
if (bounceViewer) {
  const scene = new BounceScene();
  bounceViewer.setCamera(...scene.view());
  const timeline = new Timeline(document.getElementById('bounce-timeline'), { duration: scene.durationSec() });
  const p = { restitution: 0.75, friction: 0.1, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-bounce .panel'), title: 'Bouncing' });
  gui.add(p, 'restitution', 0, 1, 0.05).name('restitution e');
  gui.add(p, 'friction', 0, 1, 0.05).name('friction μ');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('bounce-plot'), {
    title: 'The orange ball: height and energy', xLabel: 'time (s)', yLabel: 'height (m)',
    series: ['height above the floor h', 'energy as a height: h + |v|²/2g'],
    colors: [cssVar('--orange'), cssVar('--dark')], minSpan: 0.5,
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setRestitution(p.restitution);
    scene.setFriction(p.friction);
    scene.setUseExercise(p.useExercise);
    plot.setData(columns(scene.plotSamples(), 3));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('bounce-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(bounceViewer, t)].filter(Boolean).join(' '));
    plot.setCursor(t);
    markDrawn('#fig-bounce');
  }, bounceViewer);
}

// Figure 6: squash and stretch.
const squashViewer = await lesson.figure('#fig-squash');
if (squashViewer) {
  const scene = new SquashScene();
  squashViewer.setCamera(...scene.view());
  const timeline = new Timeline(document.getElementById('squash-timeline'), { duration: scene.durationSec() });
  const p = { stretch: 0.06, squash: 0.45, contact: 0.09 };
  const gui = new GUI({ container: document.querySelector('#fig-squash .panel'), title: 'Squash and stretch' });
  gui.add(p, 'stretch', 0, 0.3, 0.01).name('stretch k (per m/s)');
  gui.add(p, 'squash', 0, 0.8, 0.05).name('squash on impact');
  gui.add(p, 'contact', 0.02, 0.3, 0.01).name('squash time (s)');
  const plot = new Plot(document.getElementById('squash-plot'), {
    title: 'Stretch factor of the orange ball', xLabel: 'time (s)', yLabel: 'stretch s (1 = round)',
    series: ['s: above 1 stretched along v, below 1 squashed on the floor'], colors: [cssVar('--orange')], minSpan: 0.2,
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setStretch(p.stretch);
    scene.setSquash(p.squash);
    scene.setContact(p.contact);
    plot.setData(columns(scene.plotSamples(), 2));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('squash-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(squashViewer, t)].filter(Boolean).join(' '));
    plot.setCursor(t);
    markDrawn('#fig-squash');
  }, squashViewer);
}

// Figure 5: a column of smoke from the atlas, sorted and unsorted side by side.
const spriteViewer = await lesson.figure('#fig-sprites');
if (spriteViewer) {
  spriteViewer.setCamera(0.2, 1.3, 0, 8.0, 0.25, 0.15);
  const scene = new SmokeScene();
  const timeline = new Timeline(document.getElementById('sprites-timeline'), { duration: 8 });
  const p = { puffs: 30, animate: true };
  const gui = new GUI({ container: document.querySelector('#fig-sprites .panel'), title: 'Sprites' });
  gui.add(p, 'puffs', 1, 80, 1).name('puffs');
  gui.add(p, 'animate').name('play the atlas');
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setParams(p.puffs, 4);
    scene.setAnimateFrames(p.animate);
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('sprites-note');
  lesson.onFrame((dt) => {
    const t = timeline.advance(dt);
    showNote(note, [rejected, scene.draw(spriteViewer, t)].filter(Boolean).join(' '));
    markDrawn('#fig-sprites');
  }, spriteViewer);
}
