// Lesson 00: wires the page's controls to the wasm scenes. No math here: it lives in Rust
// (src/raster/ and src/figures/raster.rs); the images are computed there and only copied here.
import { startLesson, markDrawn, Timeline, Plot, GUI, pingPong, columns, showMatrix, guarded, cssVar, sentences } from '../../www/lesson.js';
import { MeshStorageScene, FrustumScene, DepthPrecisionScene, NormalsScene, ShadingScene } from '../../pkg/inbetween.js';

const lesson = await startLesson();
const num = (x) => (Math.abs(x) < 5e-5 ? 0 : x).toFixed(3);

/** Copies Rust's RGBA bytes into a canvas. */
function blit(canvas, bytes, width, height) {
  canvas.width = width;
  canvas.height = height;
  canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(bytes), width, height), 0, 0);
}

// Figure 1: one mesh, two storages.
const meshViewer = await lesson.figure('#fig-mesh');
if (meshViewer) {
  meshViewer.setCamera(0, 1.2, 0, 5.6, 0.0, 0.3);
  const scene = new MeshStorageScene();
  const p = { segments: 8, shape: 'sphere' };
  const gui = new GUI({ container: document.querySelector('#fig-mesh .panel'), title: 'Mesh' });
  const segments = gui.add(p, 'segments', 3, 64, 1).name('sphere segments');
  gui.add(p, 'shape', ['sphere', 'tetrahedron']).name('shape');
  const apply = () => {
    scene.setSegments(p.segments);
    scene.setShape(p.shape);
    // The tetrahedron has no segments: the slider would change nothing.
    segments.enable(p.shape === 'sphere');
  };
  gui.onChange(apply);
  apply();
  const note = document.getElementById('mesh-note');
  const listing = document.getElementById('mesh-listing');
  lesson.onFrame(() => {
    const message = scene.draw(meshViewer);
    if (note.textContent !== message) note.textContent = message;
    const text = scene.listing();
    if (listing.textContent !== text) listing.textContent = text;
    markDrawn('#fig-mesh');
  });
}

// Figure 2: the frustum.
const frustumViewer = await lesson.figure('#fig-frustum');
if (frustumViewer) {
  frustumViewer.setCamera(4.5, 1.2, -4, 17, 0.45, 0.45);
  const scene = new FrustumScene();
  const timeline = new Timeline(document.getElementById('frustum-timeline'), { duration: 6 });
  const p = { fov: 50, near: 1, far: 8, x: 0.6, y: 0.3, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-frustum .panel'), title: 'Frustum' });
  gui.add(p, 'fov', 10, 150, 1).name('field of view θ (°)');
  gui.add(p, 'near', 0.05, 5, 0.05).name('z_near (m)');
  gui.add(p, 'far', 0.5, 20, 0.1).name('z_far (m)');
  gui.add(p, 'x', -3, 3, 0.05).name('point x (m)');
  gui.add(p, 'y', -3, 3, 0.05).name('point y (m)');
  gui.add(p, 'useExercise').name('use my exercise');
  const plot = new Plot(document.getElementById('frustum-depth'), {
    title: 'Depth against distance', xLabel: 'distance d in front of the camera (m)', yLabel: 'depth (no unit)',
    series: ['wgpu, [0, 1]', 'OpenGL, [−1, 1]', 'depth 0.5'], colors: [cssVar('--z-axis'), cssVar('--grey'), cssVar('--orange')],
    dashes: [null, null, [6, 4]], widths: [2.5, 2.5, 1.5],
    // Both depth ranges, [0, 1] and [−1, 1]: the samples follow the point from half of z_near,
    // where the depths run far below them (the point is clipped there), to past z_far.
    yRange: [-1.1, 1.1],
  });
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setFrustum(p.fov, p.near, p.far);
    scene.setOffset(p.x, p.y);
    scene.setUseExercise(p.useExercise);
    // A dashed guide at depth 0.5, so the reader sees where the wgpu curve is half-way.
    const [d, wgpu, gl] = columns(scene.sampleDepth(201), 3);
    plot.setData([d, wgpu, gl, d.map(() => 0.5)]);
    showMatrix(document.getElementById('frustum-wgpu'), scene.matrix(false));
    showMatrix(document.getElementById('frustum-gl'), scene.matrix(true));
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  const note = document.getElementById('frustum-note');
  const table = document.getElementById('frustum-readout');
  lesson.onFrame((dt) => {
    timeline.advance(dt);
    const s = pingPong(timeline);
    const message = sentences(rejected, scene.draw(frustumViewer, s));
    if (note.textContent !== message) note.textContent = message;
    const r = Array.from(scene.readout(s));
    const html = '<tr><th></th><th>x</th><th>y</th><th>z</th><th>w</th></tr>'
      + `<tr><th>clip (wgpu)</th>${r.slice(0, 4).map((v) => `<td>${num(v)}</td>`).join('')}</tr>`
      + `<tr><th>NDC (wgpu)</th>${r.slice(4, 7).map((v) => `<td>${num(v)}</td>`).join('')}<td></td></tr>`
      + `<tr><th>clip (OpenGL)</th>${r.slice(7, 11).map((v) => `<td>${num(v)}</td>`).join('')}</tr>`
      + `<tr><th>NDC (OpenGL)</th>${r.slice(11, 14).map((v) => `<td>${num(v)}</td>`).join('')}<td></td></tr>`;
    if (table.innerHTML !== html) table.innerHTML = html;
    plot.setCursor(scene.distanceAt(s));
    markDrawn('#fig-frustum');
  });
}

// Figure 3: depth precision.
const depthViewer = await lesson.figure('#fig-depth');
if (depthViewer) {
  depthViewer.setCamera(0, 3, -20, 30, 1.2, 0.45);
  const scene = new DepthPrecisionScene();
  const p = { near: 0.1, far: 1000, gap: 0.01, bits: 16 };
  const gui = new GUI({ container: document.querySelector('#fig-depth .panel'), title: 'Depth buffer' });
  gui.add(p, 'near', 0.01, 2, 0.01).name('z_near (m)');
  gui.add(p, 'far', 20, 5000, 10).name('z_far (m)');
  gui.add(p, 'gap', 0.001, 0.1, 0.001).name('gap between floors (m)');
  gui.add(p, 'bits', [16, 24]).name('depth bits');
  // Log-log axes: each step is a line of slope 2, the separation one of slope 1; the dashed
  // vertical line marks where the chosen bits' step crosses the separation.
  const plot = new Plot(document.getElementById('depth-step'), {
    title: 'What one depth step is worth (log-log)', xLabel: 'distance d (m)', yLabel: 'length (m)',
    series: ['step Δd, 16 bits', 'step Δd, 24 bits', 'separation d·gap/h'],
    colors: [cssVar('--orange'), cssVar('--y-axis'), cssVar('--grey')], widths: [2.5, 2.5, 2.5], log: 'xy', height: 300,
  });
  const image = document.getElementById('depth-image');
  let rejected = '';
  const note = document.getElementById('depth-note');
  const apply = guarded(gui, p, () => {
    scene.set(p.near, p.far, p.gap, Number(p.bits));
    plot.setData(columns(scene.sampleStep(200), 4));
    const from = scene.fightingFrom();
    plot.setCursor(from <= p.far ? from : null);
    blit(image, scene.image(320, 240), 320, 240);
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  lesson.onFrame(() => {
    const message = sentences(rejected, scene.draw(depthViewer));
    if (note.textContent !== message) note.textContent = message;
    markDrawn('#fig-depth');
  });
}

// Figure 4: normals.
const normalsViewer = await lesson.figure('#fig-normals');
if (normalsViewer) {
  normalsViewer.setCamera(0, 1.3, 0, 5.5, 0.3, 0.3);
  const scene = new NormalsScene();
  const p = { scaleX: 3, flat: false, showWrong: true, useExercise: false };
  const gui = new GUI({ container: document.querySelector('#fig-normals .panel'), title: 'Normals' });
  gui.add(p, 'scaleX', 0.2, 4, 0.05).name('scale along x');
  gui.add(p, 'flat').name('flat shading');
  gui.add(p, 'showWrong').name('show M·n (wrong)');
  gui.add(p, 'useExercise').name('use my exercise');
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setScaleX(p.scaleX);
    scene.setFlat(p.flat);
    scene.setShowWrong(p.showWrong);
  }, (m) => { rejected = m; });
  gui.onChange((e) => {
    if (e.property === 'useExercise') scene.setUseExercise(p.useExercise);
    apply();
  });
  apply();
  const note = document.getElementById('normals-note');
  lesson.onFrame(() => {
    const message = sentences(rejected, scene.draw(normalsViewer));
    if (note.textContent !== message) note.textContent = message;
    markDrawn('#fig-normals');
  });
}

// Figure 5: shading.
const shadingViewer = await lesson.figure('#fig-shading');
if (shadingViewer) {
  shadingViewer.setCamera(0, 1.5, 0, 7.5, -0.5, 0.55);
  const scene = new ShadingScene();
  const p = {
    lightAzimuth: 40, lightElevation: 35, ka: 0.15, kd: 0.7, ks: 0.5, shininess: 32,
    model: 'blinn-phong', fragAzimuth: 30, fragElevation: 10, useExercise: false,
  };
  const gui = new GUI({ container: document.querySelector('#fig-shading .panel'), title: 'Shading' });
  // The material and the model first: on a narrow page the panel sits under the canvas and the
  // images, and the Try this's shininess slider must be on the same screen as them.
  const terms = gui.addFolder('material');
  terms.add(p, 'ka', 0, 1, 0.01).name('ambient k_a');
  terms.add(p, 'kd', 0, 1, 0.01).name('diffuse k_d');
  terms.add(p, 'ks', 0, 1, 0.01).name('specular k_s');
  terms.add(p, 'shininess', 1, 256, 1).name('shininess s');
  gui.add(p, 'model', { 'Blinn-Phong': 'blinn-phong', Phong: 'phong' }).name('model (vectors, terms)');
  const light = gui.addFolder('light');
  light.add(p, 'lightAzimuth', -180, 180, 1).name('azimuth (°)');
  light.add(p, 'lightElevation', -89, 89, 1).name('elevation (°)');
  const frag = gui.addFolder('marked fragment');
  frag.add(p, 'fragAzimuth', -90, 90, 1).name('azimuth (°)');
  frag.add(p, 'fragElevation', -89, 89, 1).name('elevation (°)');
  gui.add(p, 'useExercise').name('use my exercise');
  const SIZE = 128;
  const holder = document.getElementById('shading-images');
  const images = [['ambient', 'ambient'], ['diffuse', 'diffuse'], ['specular', 'specular'],
    ['phong', 'Phong total, per pixel'], ['blinn-phong', 'Blinn-Phong total, per pixel'],
    ['gouraud', 'chosen model, per vertex (as in 3D)']].map(([key, label]) => {
    const fig = document.createElement('figure');
    const canvas = document.createElement('canvas');
    canvas.setAttribute('aria-label', `${label}: drag to move the light`);
    const caption = document.createElement('figcaption');
    caption.textContent = label;
    fig.append(canvas, caption);
    holder.append(fig);
    return [key, canvas];
  });
  const redraw = () => {
    for (const [key, canvas] of images) blit(canvas, scene.image(key, SIZE), SIZE, SIZE);
  };
  let rejected = '';
  const apply = guarded(gui, p, () => {
    scene.setLightDeg(p.lightAzimuth, p.lightElevation);
    scene.setMaterial(p.ka, p.kd, p.ks, p.shininess);
    scene.setModel(p.model);
    scene.setFragmentDeg(p.fragAzimuth, p.fragElevation);
    scene.setUseExercise(p.useExercise);
    redraw();
  }, (m) => { rejected = m; });
  gui.onChange(apply);
  apply();
  // Dragging on an image puts the light where the pointer is (the core maps the point to a direction).
  for (const [, canvas] of images) {
    const move = (e) => {
      if (!(e.buttons & 1)) return;
      const box = canvas.getBoundingClientRect();
      const u = Math.min(1, Math.max(0, (e.clientX - box.left) / box.width));
      const v = Math.min(1, Math.max(0, (e.clientY - box.top) / box.height));
      scene.setLightFromImage(u, v);
      [p.lightAzimuth, p.lightElevation] = Array.from(scene.lightDeg(), (x) => Math.round(x));
      gui.controllersRecursive().forEach((c) => c.updateDisplay());
      redraw();
    };
    canvas.addEventListener('pointerdown', (e) => { canvas.setPointerCapture(e.pointerId); move(e); });
    canvas.addEventListener('pointermove', move);
  }
  const note = document.getElementById('shading-note');
  lesson.onFrame(() => {
    const message = sentences(rejected, scene.draw(shadingViewer));
    if (note.textContent !== message) note.textContent = message;
    markDrawn('#fig-shading');
  });
}
