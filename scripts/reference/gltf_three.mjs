// Generates tests/data/gltf_three.json: the joint world matrices of the Khronos sample characters
// (../shared/assets/gltf: RiggedSimple, RiggedFigure, CesiumMan) as three.js (r170) computes
// them, in the rest pose and at several times of each file's first animation, and the skinned
// positions of 40 vertices of the first skinned mesh at the same times, for
// tests/gltf_import.rs. three.js is an independent glTF implementation (GLTFLoader,
// AnimationMixer, Object3D.matrixWorld).
//
//   npm install --prefix /tmp/three-ref three@0.170.0
//   THREE_DIR=/tmp/three-ref/node_modules/three \
//     node scripts/reference/gltf_three.mjs ../shared/assets/gltf > tests/data/gltf_three.json
//
// Images are removed from each file before loading (Node has no image decoder; textures do not
// move joints). Matrices are column-major, as glTF and three.js store them. The asset files are
// not committed (see their LICENSE.md); only these numbers are.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

// three's FileLoader reports progress with the browser's ProgressEvent (the buffers are data: URLs
// fetched by Node's fetch).
globalThis.ProgressEvent ??= class extends Event {
  constructor(type, init = {}) { super(type); Object.assign(this, init); }
};

const dir = process.env.THREE_DIR ?? 'three';
const THREE = await import(`${dir}/build/three.module.js`);
const { GLTFLoader } = await import(`${dir}/examples/jsm/loaders/GLTFLoader.js`);

const assets = process.argv[2] ?? '../shared/assets/gltf';
const names = ['RiggedSimple', 'RiggedFigure', 'CesiumMan'];
// Fractions of the first animation's duration (not its end: a looping mixer wraps there).
const fractions = [0, 0.3, 0.55, 0.85];

const round = (x) => Number(x.toPrecision(8));
const out = { tool: `three.js r${THREE.REVISION} (GLTFLoader, AnimationMixer, Object3D.matrixWorld)`, models: {} };

for (const name of names) {
  const json = JSON.parse(readFileSync(join(assets, `${name}.gltf`), 'utf8'));
  delete json.images;
  delete json.textures;
  delete json.samplers;
  for (const m of json.materials ?? []) {
    if (m.pbrMetallicRoughness) delete m.pbrMetallicRoughness.baseColorTexture;
    delete m.normalTexture;
    delete m.emissiveTexture;
    delete m.occlusionTexture;
  }
  const gltf = await new Promise((ok, fail) => new GLTFLoader().parse(JSON.stringify(json), '', ok, fail));
  let skinned = null;
  gltf.scene.traverse((o) => { if (o.isSkinnedMesh && !skinned) skinned = o; });
  const bones = skinned.skeleton.bones;
  const world = () => {
    gltf.scene.updateMatrixWorld(true);
    return bones.map((b) => b.matrixWorld.elements.map(round));
  };
  // Bones in the skin's `joints` order, named by their glTF node index (these files leave most
  // nodes unnamed).
  const nodes = bones.map((b) => gltf.parser.associations.get(b)?.nodes);
  // Skinned vertex positions (world space) of the first skinned mesh, for a spread of vertices:
  // SkinnedMesh.applyBoneTransform gives the mesh-local position, matrixWorld takes it to world.
  const count = skinned.geometry.attributes.position.count;
  const vertices = Array.from({ length: 40 }, (_, k) => Math.floor((k * count) / 40));
  const skinnedPositions = () => {
    gltf.scene.updateMatrixWorld(true);
    skinned.skeleton.update();
    return vertices.map((i) => {
      const v = new THREE.Vector3().fromBufferAttribute(skinned.geometry.attributes.position, i);
      skinned.applyBoneTransform(i, v);
      return v.applyMatrix4(skinned.matrixWorld).toArray().map(round);
    });
  };
  const model = { nodes, rest: world(), times: [], world: [], vertices, skinned: [] };
  const clip = gltf.animations[0];
  if (clip) {
    const mixer = new THREE.AnimationMixer(gltf.scene);
    mixer.clipAction(clip).play();
    model.animation = clip.name;
    model.duration = round(clip.duration);
    for (const f of fractions) {
      const t = f * clip.duration;
      mixer.setTime(t);
      model.times.push(round(t));
      model.world.push(world());
      model.skinned.push(skinnedPositions());
    }
  }
  out.models[name] = model;
}
console.log(JSON.stringify(out));
