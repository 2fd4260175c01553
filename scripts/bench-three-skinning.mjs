// Times three.js's CPU skinning path, SkinnedMesh.getVertexPosition (r170: the bind-pose position
// through SkinnedMesh.applyBoneTransform, four influences, one bone matrix product per influence),
// against the release wasm LBS kernel and the bench page's plain JavaScript LBS loop, on the same
// workload in the same Node process: the bench page's skinning kernel, 100k vertices, 4 influences,
// 60 joints, on the wasm's own input (`skinningBenchInput`). three.js is an independent
// implementation; it is not a project dependency, so install it outside the repository:
//
//   npm install --prefix /tmp/three-bench three@0.170.0
//   node scripts/bench-three-skinning.mjs [dist] [passes]     # after `scripts/build` (release)
//
// THREE_DIR (default /tmp/three-bench/node_modules/three) says where three is; `dist` (default the
// repository's dist/) holds pkg/bench.js and pkg/bench_bg.wasm (the bench module); `passes` (default 20) is
// the wasm kernel's k below. Timing is process CPU time, best of three rounds (the rounds
// interleave the three kernels, for a machine shared with other jobs, where wall-clock time swings
// by several times). After warm-up passes, the JavaScript loop times `passes` passes per round and
// three.js a quarter as many (one pass of it takes about 25 ms); the wasm kernel runs once with
// 1 pass and once with 1 + k, and the difference divided by k is one pass without its own setup
// (input, warm-up calls): its own timer returns 0 in Node (no `window`).
//
// Not like for like, and in three's favour: our kernels skin positions AND normals, three's
// getVertexPosition positions only (three skins on the GPU when it draws; this is the CPU path it
// uses for raycasts and bounding volumes). Before timing, three's positions are checked against the
// JavaScript loop's (the loop is `skin_lbs_plain_loop`, which tests/skinning.rs checks against the
// wasm's `skin_lbs`) on every vertex.
import { existsSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { skinLoop, skinningInput } from '../www/skin-loop.js';

const VERTICES = 100000;
const JOINTS = 60;

const args = process.argv.slice(2);
const root = fileURLToPath(new URL('..', import.meta.url));
const dist = resolve(args[0] && !/^\d+$/.test(args[0]) ? args.shift() : resolve(root, 'dist'));
const passes = Number(args[0] ?? 20);

const threeDir = resolve(process.env.THREE_DIR ?? '/tmp/three-bench/node_modules/three');
if (!existsSync(`${threeDir}/build/three.module.js`)) {
  console.error(`bench-three-skinning: three.js not found at ${threeDir}. Install it outside the repository:
  npm install --prefix /tmp/three-bench three@0.170.0
(or set THREE_DIR to a three.js package directory).`);
  process.exit(2);
}
if (!existsSync(`${dist}/pkg/bench_bg.wasm`)) {
  console.error(`bench-three-skinning: no ${dist}/pkg/bench_bg.wasm: run scripts/build (release) first.`);
  process.exit(2);
}
const THREE = await import(pathToFileURL(`${threeDir}/build/three.module.js`).href);
const wasm = await import(pathToFileURL(`${dist}/pkg/bench.js`).href);
const wasmBytes = readFileSync(`${dist}/pkg/bench_bg.wasm`);
await wasm.default({ module_or_path: wasmBytes });
// scripts/build --dev skips wasm-opt, which is what drops the name section: a debug module times
// nothing worth reporting.
const debugBuild = WebAssembly.Module.customSections(new WebAssembly.Module(wasmBytes), 'name').length > 0;

// The wasm bench's input, unpacked as www/bench.js does (www/skin-loop.js): palette, joint
// indices, weights, positions, normals.
const jsInput = skinningInput(wasm.skinningBenchInput(VERTICES), VERTICES, JOINTS);
const { palette, jointIndex, weights, positions } = jsInput;

// --- three.js: a SkinnedMesh whose bone matrices are the palette. Bone inverses and the bind
// matrix are the identity, so matrixWorld × boneInverse is the palette matrix itself (exact: no
// rounding), and the bones' matrixWorld is set directly (not derived from position / quaternion /
// scale, so no update may overwrite it).
const geometry = new THREE.BufferGeometry();
geometry.setAttribute('position', new THREE.BufferAttribute(Float32Array.from(positions), 3));
geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(jointIndex, 4));
geometry.setAttribute('skinWeight', new THREE.BufferAttribute(Float32Array.from(weights), 4));
const bones = Array.from({ length: JOINTS }, (_, j) => {
  const bone = new THREE.Bone();
  bone.matrixAutoUpdate = false;
  bone.matrixWorldAutoUpdate = false;
  const m = palette.subarray(12 * j, 12 * j + 12);
  // Matrix4.set takes rows; elements are column-major.
  bone.matrixWorld.set(
    m[0], m[3], m[6], m[9],
    m[1], m[4], m[7], m[10],
    m[2], m[5], m[8], m[11],
    0, 0, 0, 1,
  );
  return bone;
});
const skeleton = new THREE.Skeleton(bones, bones.map(() => new THREE.Matrix4()));
const mesh = new THREE.SkinnedMesh(geometry);
mesh.bind(skeleton, new THREE.Matrix4());
for (let j = 0; j < JOINTS; j++) {
  const e = bones[j].matrixWorld.elements;
  for (let c = 0; c < 4; c++) {
    for (let r = 0; r < 3; r++) {
      if (e[4 * c + r] !== palette[12 * j + 3 * c + r]) throw new Error(`bone ${j}: matrixWorld is not the palette`);
    }
  }
}

const threeOut = new Float32Array(3 * VERTICES);
const target = new THREE.Vector3();
/** One frame of three's CPU skinning: the skeleton update, then every vertex's skinned position. */
function threePasses(n) {
  for (let it = 0; it < n; it++) {
    skeleton.update();
    for (let i = 0; i < VERTICES; i++) {
      mesh.getVertexPosition(i, target);
      threeOut[3 * i] = target.x; threeOut[3 * i + 1] = target.y; threeOut[3 * i + 2] = target.z;
    }
  }
}

// --- The plain LBS loop of the bench page (www/skin-loop.js), positions and normals.
const jsPasses = (n) => skinLoop(jsInput, VERTICES, n);

// --- Check: three's skinned positions against the loop's, every vertex.
threePasses(1);
jsPasses(1);
let maxDiff = 0, maxAbs = 0;
for (let i = 0; i < 3 * VERTICES; i++) {
  maxDiff = Math.max(maxDiff, Math.abs(threeOut[i] - jsInput.outP[i]));
  maxAbs = Math.max(maxAbs, Math.abs(jsInput.outP[i]));
}
const TOLERANCE = 1e-5;
console.log(`check: three.js getVertexPosition vs the JS LBS loop, ${VERTICES} vertices: max |difference| ${maxDiff.toExponential(2)} (positions up to ${maxAbs.toFixed(2)}; tolerance ${TOLERANCE})`);
if (!(maxDiff <= TOLERANCE)) {
  console.error('bench-three-skinning: three.js and the JS loop disagree');
  process.exit(1);
}

// --- Timing.
function cpuMs(f) {
  const start = process.cpuUsage();
  f();
  const d = process.cpuUsage(start);
  return (d.user + d.system) / 1000;
}
const wasmRun = (n) => wasm.benchSkinning('lbs', VERTICES, n);
const threeN = Math.max(1, Math.round(passes / 4));
const jsN = passes;
// Warm-up (the JS kernels' optimising tier; the wasm function's own warm-up is inside each call).
threePasses(3);
jsPasses(5);
wasmRun(1);

const best = { three: Infinity, js: Infinity, wasm1: Infinity, wasmK: Infinity };
for (let round = 0; round < 3; round++) {
  best.three = Math.min(best.three, cpuMs(() => threePasses(threeN)) / threeN);
  best.wasm1 = Math.min(best.wasm1, cpuMs(() => wasmRun(1)));
  best.wasmK = Math.min(best.wasmK, cpuMs(() => wasmRun(1 + passes)));
  best.js = Math.min(best.js, cpuMs(() => jsPasses(jsN)) / jsN);
}
const ms = { three: best.three, wasm: (best.wasmK - best.wasm1) / passes, js: best.js };
const mvs = (t) => VERTICES / t / 1000;

console.log(`three.js r${THREE.REVISION}, Node ${process.version}; ${VERTICES} vertices, 4 influences, ${JOINTS} joints; process CPU time, best of 3`);
if (debugBuild) console.warn('warning: this wasm has a name section (scripts/build --dev?): not a release build');
const row = (name, t, what) => console.log(`  ${name.padEnd(44)} ${t.toFixed(2).padStart(7)} ms per pass  ${mvs(t).toFixed(1).padStart(6)} M vertices/s  (${what})`);
row('three.js SkinnedMesh.getVertexPosition', ms.three, `positions only; skeleton.update() + every vertex, ${threeN} passes`);
row('wasm LBS (benchSkinning "lbs")', ms.wasm, `positions + normals; (1 + ${passes}) − (1) passes`);
row('JS plain LBS loop (www/skin-loop.js)', ms.js, `positions + normals, ${jsN} passes`);
console.log(`  wasm / three.js: ${(ms.three / ms.wasm).toFixed(1)}×   wasm / JS loop: ${(ms.js / ms.wasm).toFixed(1)}×   JS loop / three.js: ${(ms.three / ms.js).toFixed(1)}×`);
console.log('  (three.js skins positions only, our kernels positions and normals: the ratios are in three\'s favour)');
