// Does unrelated code change a kernel's speed? Times the same wasm kernels built three ways, by
// process CPU time in Node (the same V8 as Chromium; a shared machine disturbs it less than the
// page's wall clock):
//   full   the figures module with the bench kernels added (feature `bench-full`): the kernel
//          inside the full release build, beside every lesson's figures and the renderer
//   bench  the bench page's module (`dist/pkg/bench_bg.wasm`): every CPU kernel of the bench page
//   alone  the bench module with the kernel's family only (feature `bench-alone-FAMILY`)
// Build the variants first (release, LTO, wasm-opt, as the site's modules; several minutes):
//   INBETWEEN_DIST=target/bench-variants scripts/build --bench-variants
//   node scripts/bench-alone.mjs [variants dir] [site dist] [rounds]
// Each kernel is timed as scripts/bench-cpu.mjs does (one call of 1 + passes less one call of 1
// pass, divided by passes), the three builds in turn, `rounds` times (default 5); the best time
// of each build is reported, with full / alone (over 1: slower in the full build).
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [variants = 'target/bench-variants', site = 'dist', roundsArg = '5'] = process.argv.slice(2);
const rounds = Number(roundsArg);

async function load(js, wasmFile) {
  const m = await import(pathToFileURL(resolve(js)).href);
  await m.default({ module_or_path: readFileSync(resolve(wasmFile)) });
  return m;
}

// family, binding, kernel, size, passes: the bench page's sizes.
const CASES = [
  ['skeleton', 'benchSkeleton', 'runtime_clip', 600, 200],
  ['skeleton', 'benchSkeleton', 'local_to_model_only', 600, 200],
  ['skinning', 'benchSkinning', 'lbs', 100_000, 50],
  ['skinning', 'benchSkinning', 'dqs', 100_000, 50],
  ['boids', 'benchBoids', 'naive', 10_000, 3],
  ['boids', 'benchBoids', 'grid', 10_000, 50],
  ['noise', 'benchNoise', 'noise3_batch', 65_536, 50],
  ['noise', 'benchTerrain', 'fbm8_rows', 512 * 512, 10],
];

function cpuMs(f) {
  const start = process.cpuUsage();
  f();
  const d = process.cpuUsage(start);
  return (d.user + d.system) / 1000;
}

const full = await load(`${variants}/pkg/bench_full.js`, `${variants}/pkg/bench_full_bg.wasm`);
const bench = await load(`${site}/pkg/bench.js`, `${site}/pkg/bench_bg.wasm`);
const alone = {};
for (const family of new Set(CASES.map(([f]) => f))) {
  alone[family] = await load(`${variants}/pkg/bench_alone_${family}.js`, `${variants}/pkg/bench_alone_${family}_bg.wasm`);
}

console.log('kernel | full build, ms | bench module, ms | alone, ms | full / alone | bench / alone');
console.log('---|---|---|---|---|---');
for (const [family, binding, kernel, size, passes] of CASES) {
  const builds = { full, bench, alone: alone[family] };
  const best = { full: Infinity, bench: Infinity, alone: Infinity };
  for (const m of Object.values(builds)) m[binding](kernel, size, 1); // warm-up (tier-up)
  for (let r = 0; r < rounds; r++) {
    for (const [name, m] of Object.entries(builds)) {
      const run = (n) => m[binding](kernel, size, n);
      const ms = (cpuMs(() => run(1 + passes)) - cpuMs(() => run(1))) / passes;
      best[name] = Math.min(best[name], ms);
    }
  }
  const f = (x) => x.toFixed(3);
  console.log(`${family} ${kernel} ${size} | ${f(best.full)} | ${f(best.bench)} | ${f(best.alone)} | ` +
    `${(best.full / best.alone).toFixed(2)} | ${(best.bench / best.alone).toFixed(2)}`);
}
