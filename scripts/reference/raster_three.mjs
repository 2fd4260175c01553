// Generates tests/data/raster_three.txt: perspective matrices from three.js (r170), an
// independent implementation, for tests/raster.rs. three.js's PerspectiveCamera builds the
// OpenGL matrix (WebGLCoordinateSystem, depth in [-1, 1]) or the WebGPU one
// (WebGPUCoordinateSystem, depth in [0, 1]).
//
//   npm install --prefix /tmp/three-ref three@0.170.0
//   THREE=/tmp/three-ref/node_modules/three/build/three.module.js \
//     node scripts/reference/raster_three.mjs > tests/data/raster_three.txt
//
// Format: '#' lines are comments; every other line is
//   perspective gl|wgpu  fov_y_deg aspect near far  m00 m01 m02 m03 m10 ... m33   (row by row)
const THREE = await import(process.env.THREE ?? 'three');

const cases = [
  [60, 16 / 9, 0.1, 100],
  [90, 1, 1, 10],
  [10, 1.5, 5, 500],
  [140, 0.6, 0.05, 20],
  [45, 1, 2, 2.5],
  [50, 1.5, 1, 8],
  [75, 2.2, 0.01, 1e5],
];
console.log(`# three.js r${THREE.REVISION}, PerspectiveCamera(fov, aspect, near, far).projectionMatrix`);
for (const [name, system] of [['gl', THREE.WebGLCoordinateSystem], ['wgpu', THREE.WebGPUCoordinateSystem]]) {
  for (const [fov, aspect, near, far] of cases) {
    const camera = new THREE.PerspectiveCamera(fov, aspect, near, far);
    camera.coordinateSystem = system;
    camera.updateProjectionMatrix();
    const e = camera.projectionMatrix.elements; // column-major
    const rows = [0, 1, 2, 3].flatMap((r) => [0, 1, 2, 3].map((c) => e[c * 4 + r]));
    console.log(['perspective', name, fov, aspect, near, far, ...rows].map((x) => (typeof x === 'number' ? Number(x.toPrecision(9)) : x)).join(' '));
  }
}
