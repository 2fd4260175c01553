// A figure showing a character from a glTF file: the Khronos samples served with the site
// (dist/assets/gltf/index.json lists them) or the reader's own file, by file picker or dropped
// on the figure. Used by lesson 06 (the skeleton and the bind-pose vertices) and lesson 09 (the
// mesh skinned by LBS or DQS). No math here: it lives in Rust (src/gltf_import.rs,
// src/figures/gltf.rs). A file is imported by the glTF module (dist/pkg/gltf.js, loaded on the
// first file), which hands the result to the figure as bytes: the importer stays out of the
// figures module that every page loads. The figure's HTML needs a .stage with a canvas and a .panel, a
// .timeline, an input[type=file] and a .note, all inside `selector`.
import { markDrawn, Timeline, GUI, showNote } from './lesson.js';
import { GltfScene } from '../pkg/inbetween.js';

// The glTF module, instantiated once per page on first use: its `importGltf`.
let importer = null;
const gltfImporter = () => {
  importer ??= import('../pkg/gltf.js').then(async (glue) => {
    await glue.default();
    return glue.importGltf;
  }).catch((e) => {
    importer = null; // the next file tries again
    throw new Error(`the glTF importer could not be loaded (${e?.message ?? e})`);
  });
  return importer;
};

export async function gltfFigure(lesson, selector, { skinning = null, gpuSwitch = false } = {}) {
  const viewer = await lesson.figure(selector);
  if (!viewer) return;
  const box = document.querySelector(selector);
  const scene = new GltfScene();
  const note = box.querySelector('.note');
  const timeline = new Timeline(box.querySelector('.timeline'), { duration: 1, playing: true });
  let samples = [];
  try {
    const response = await fetch(new URL('../assets/gltf/index.json', import.meta.url));
    if (response.ok) samples = await response.json();
  } catch { /* no samples on this server */ }
  const p = {
    character: samples.includes('RiggedFigure.gltf') ? 'RiggedFigure.gltf' : samples[0] ?? '(none)',
    clip: '', mesh: true, skinning: skinning ?? 'dots', bindPose: false, on: 'CPU',
  };
  const gui = new GUI({ container: box.querySelector('.panel'), title: 'glTF character' });
  // The note after a load (the file's summary, or why it was rejected and what is still shown)
  // comes from the scene; this one is only about the server.
  const message = samples.length ? '' : 'The sample characters are not on this server (they are copied from ../shared when it is there); load your own file below.';
  let clipControl = null;
  let characterControl = null;
  scene.setSkinning(p.skinning);
  // After a file loads, from the dropdown, the picker or a drop: the dropdown names the character
  // shown (a file of the reader's own joins its options).
  const loaded = (name) => {
    p.character = name;
    characterControl?.options(samples.includes(name) ? samples : [...samples, name]);
    const [x, y, z, distance] = scene.fit();
    viewer.setCamera(x, y, z, distance, 0.6, 0.15);
    timeline.duration = scene.duration;
    timeline.time = 0;
    timeline.show();
    work.length = 0;
    clipControl?.destroy();
    clipControl = null;
    const names = scene.clipNames();
    p.clip = names[0] ?? '';
    if (names.length > 1) {
      clipControl = gui.add(p, 'clip', names).name('clip').onChange(() => {
        scene.setClip(names.indexOf(p.clip));
        timeline.duration = scene.duration;
      });
    }
  };
  const load = async (name, bytes) => {
    let imported;
    try {
      imported = (await gltfImporter())(bytes);
    } catch (e) {
      scene.reject(name, String(e?.message ?? e)); // the note says why, and what it still shows
      return;
    }
    try {
      scene.loadImported(name, imported);
    } catch {
      return; // rejected: the scene's note says why, and what it still shows
    }
    loaded(name);
  };
  const loadSample = async (file) => {
    if (!samples.includes(file)) return;
    const response = await fetch(new URL(`../assets/gltf/${file}`, import.meta.url));
    await load(file, new Uint8Array(await response.arrayBuffer()));
  };
  if (samples.length) characterControl = gui.add(p, 'character', samples).name('sample').onChange(() => loadSample(p.character));
  if (skinning) {
    gui.add(p, 'skinning', { 'linear blend (LBS)': 'lbs', 'dual quaternion (DQS)': 'dqs' })
      .name('mesh').onChange(() => scene.setSkinning(p.skinning));
    // The bind-pose vertices over the skinned mesh: what skinning moved leaves them.
    gui.add(p, 'bindPose').name('bind-pose vertices').onChange(() => scene.setShowBindPose(p.bindPose));
  } else {
    gui.add(p, 'mesh').name('mesh vertices').onChange(() => scene.setShowMesh(p.mesh));
  }
  // Skinning on the CPU or in the vertex shader, with the frame time (lesson 09). Both over the
  // same frames: each frame's work beside the time from its start to the next frame's, which
  // holds it (and any other figure's), as means over the last 60 frames since the character or
  // the switch changed.
  const work = [];
  let lastWorkMs = null;
  if (gpuSwitch) gui.add(p, 'on', ['CPU', 'GPU']).name('skin on').onChange(() => { scene.setGpu(p.on === 'GPU'); work.length = 0; });
  const readFile = async (file) => load(file.name, new Uint8Array(await file.arrayBuffer()));
  box.querySelector('input[type="file"]').addEventListener('change', (e) => {
    if (e.target.files[0]) readFile(e.target.files[0]);
  });
  const stage = box.querySelector('.stage');
  stage.addEventListener('dragover', (e) => e.preventDefault());
  stage.addEventListener('drop', (e) => {
    e.preventDefault();
    if (e.dataTransfer.files[0]) readFile(e.dataTransfer.files[0]);
  });
  if (samples.length) await loadSample(p.character);
  lesson.onFrame((dt) => {
    // The shell clamps dt at 0.1 s: a longer frame is left out.
    if (lastWorkMs !== null && dt > 0 && dt < 0.1) work.push([lastWorkMs, 1000 * dt]);
    if (work.length > 60) work.shift();
    timeline.advance(dt);
    const start = performance.now();
    const drawn = scene.draw(viewer, timeline.time);
    // The call skins, fills the draw list and renders the frame: its time includes the
    // renderer's (lesson 09's Figure 4 times the skinning alone).
    lastWorkMs = performance.now() - start;
    if (gpuSwitch) {
      const [cpu, frame] = [0, 1].map((i) => work.reduce((sum, w) => sum + w[i], 0) / work.length);
      showNote(note, message, work.length < 10
        ? `${drawn} Skinning and rendering: no measurement yet (${work.length} of 10 frames since the character or skin on changed).`
        : `${drawn} Skinning and rendering a frame (the renderer's work included) take ${cpu.toFixed(2)} ms on the CPU, of the ${frame.toFixed(1)} ms from its start to the next frame's (means of the last ${work.length} frames).`);
    } else {
      showNote(note, message, drawn);
    }
    markDrawn(selector);
  });
}
