#!/usr/bin/env node
// The bindings' hostile-input probe: calls every export of the built modules (every class's
// constructor, static functions and prototype methods, every free function) with hostile arguments
// and fails on a panic, a hang, a non-finite output or a half-applied rejected call.
//
//   node scripts/probe-bindings.mjs [dist]        (dist defaults to dist/, after scripts/build)
//
// For each callable it first looks for baseline arguments the call accepts (numbers 1, 0, 2, ...;
// flags and names true, "default", ...), then replaces one argument at a time by each hostile value
// (NaN, ±Infinity, 1e38, -1, 1.5, 2^32 + 3, a string, an object, undefined, null, a boolean, a
// 1-million-element array). Calls run in worker threads on one shared compiled module; a watchdog
// ends a worker whose call runs past CALL_LIMIT_MS (a hang) and the next call starts a fresh
// worker. After each call the worker checks that the module still works (a panic can leave it
// trapped or with a borrow held), that the output holds no NaN or ±Infinity, and, when the call
// was rejected, that the object reads the same as before (its getters and its zero-argument
// reading methods). Objects that need a canvas or a GPU cannot be made in Node: their methods are
// still called on hostile receivers and arguments, and their logic is covered by native tests.
//
// Every callable is covered on every run. By default every hostile call is made (about a minute
// on two loaded cores with the debug module); PROBE_FRACTION=f (0 < f < 1) makes a random
// sample of each callable's hostile calls instead, at least one per argument (the seed is
// printed; PROBE_SEED=n repeats a run). Prints counts and exits non-zero on any panic, hang,
// non-finite output, half-applied call or error that is not an Error with a message.
import { Worker, isMainThread, parentPort, workerData } from 'node:worker_threads';
import { readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import path from 'node:path';

const CALL_LIMIT_MS = 5000;
const WORKERS = Number(process.env.PROBE_WORKERS || 2);

const HOSTILE = [
  ['NaN', () => NaN],
  ['Infinity', () => Infinity],
  ['-Infinity', () => -Infinity],
  ['1e38', () => 1e38],
  ['-1', () => -1],
  ['1.5', () => 1.5],
  ['2**32+3', () => 2 ** 32 + 3],
  ['"abc"', () => 'abc'],
  ['{}', () => ({})],
  ['undefined', () => undefined],
  ['null', () => null],
  ['true', () => true],
  ['hugeArray', () => HUGE],
];
let HUGE = null;

// Baseline candidates, tried in order until a call is accepted.
const NUMBER_BASES = [1, 0, 2, 0.5, 3, 10, 100];
const ANY_BASES = [true, false, 'default', 'linear', 'none', 'grid', 'flag'];
const ARRAY_BASES = [[0, 0, 1, 1], [0, 1, 2]];

// Zero-argument methods that change state (not used as readers of the object's state).
const MUTATING = /^(reset|step|advance|explode|free|clear|restart|play|toggle|release|grab|drop|start|stop|tick|update|random|regenerate|shuffle|next|prev|burst|replay|rebuild|frameAll|timing)/i;

/**
 * Whether accepting `value` for a parameter the glue documents as `type` is a silent coercion: a
 * value that is not a number for `number`, or neither a typed array nor an array of numbers for
 * `Float32Array | number[]` (JavaScript would turn "5" into 5 and "12" into [1, 2]).
 */
function coerced(type, value) {
  if (type === 'number') return typeof value !== 'number';
  if (/^Float(32|64)Array \| number\[\]$/.test(type ?? '')) {
    return !(ArrayBuffer.isView(value) || (Array.isArray(value) && value.every((v) => typeof v === 'number')));
  }
  return false;
}

/** Every non-finite number in `value` (a number, an array, a typed array or a plain object). */
function nonFinite(value, depth = 0) {
  if (typeof value === 'number') return Number.isFinite(value) ? 0 : 1;
  if (value == null || depth > 2) return 0;
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) {
    if (value instanceof Float32Array || value instanceof Float64Array) {
      let n = 0;
      for (const v of value) if (!Number.isFinite(v)) n++;
      return n;
    }
    return 0;
  }
  if (Array.isArray(value)) return value.reduce((n, v) => n + nonFinite(v, depth + 1), 0);
  return 0;
}

function describe(v) {
  if (v === HUGE && HUGE) return 'hugeArray';
  if (typeof v === 'string') return JSON.stringify(v);
  if (Array.isArray(v)) return `[${v.join(', ')}]`;
  if (typeof v === 'object' && v !== null) return '{}';
  return String(v);
}

/** A plain comparable copy of a reader's result. */
function snap(v) {
  if (ArrayBuffer.isView(v)) return Array.from(v, (x) => (typeof x === 'bigint' ? String(x) : x));
  if (Array.isArray(v)) return v.map(snap);
  if (v && typeof v === 'object') return '[object]';
  return v;
}
const same = (a, b) => JSON.stringify(a, (k, v) => (Number.isNaN(v) ? 'NaN' : v)) ===
  JSON.stringify(b, (k, v) => (Number.isNaN(v) ? 'NaN' : v));

// ---------------------------------------------------------------------------------------------
// Worker: runs a list of jobs (one callable each) on its own instance of the module.
// ---------------------------------------------------------------------------------------------
async function workerMain() {
  const { gluePath, module, jobs } = workerData;
  let panicMessage = null;
  // The panic hook reports here first; answering true keeps the console quiet.
  globalThis.__inbetweenPanic = (message) => { panicMessage = message; return true; };
  const wasm = await import(pathToFileURL(gluePath).href);
  wasm.initSync({ module });
  HUGE = new Array(1 << 20).fill(0.5);
  const post = (m) => parentPort.postMessage(m);

  const isPanic = (e) => e instanceof WebAssembly.RuntimeError || panicMessage !== null;
  const messageOf = (e) => (e && e.message) || String(e);

  function moduleWorks() {
    try {
      if (typeof wasm.buildInfo() !== 'string') return false;
      // The course module has no figures: its health check is a grader list and a quiz core.
      if (wasm.gradedLessons) {
        return wasm.gradedLessons().length > 0 && Math.abs(wasm.quizAnswer('fade', new Float32Array([0.5])) - 0.5) < 1e-6;
      }
      // Nor has the bench module: its health check is a small kernel run (0 ms in Node, no clock).
      if (wasm.benchHierarchy) return Number.isFinite(wasm.benchHierarchy('world_matrices', 4, 1));
      // Nor has the glTF module: its health check is an empty file, which must be refused with
      // the importer's message (a trap would be a RuntimeError without it).
      if (wasm.importGltf) {
        try {
          wasm.importGltf(new Uint8Array(0));
          return false;
        } catch (e) {
          return /not a valid glTF/.test(e.message);
        }
      }
      const s = new wasm.LagrangeScene();
      const keys = s.keys();
      s.free();
      return keys.length > 0;
    } catch {
      return false;
    }
  }

  /** The object's readers: getters and zero-argument methods that do not look like mutations. */
  function readersOf(cls, obj) {
    const out = [];
    const proto = cls.prototype;
    for (const name of Object.getOwnPropertyNames(proto)) {
      if (name === 'constructor' || name.startsWith('__') || name === 'free') continue;
      const d = Object.getOwnPropertyDescriptor(proto, name);
      if (d.get) out.push([name, () => obj[name]]);
      else if (typeof d.value === 'function' && d.value.length === 0 && !MUTATING.test(name)) {
        out.push([name, () => obj[name]()]);
      }
    }
    return out;
  }

  function snapshot(readers) {
    const s = {};
    for (const [name, read] of readers) {
      try { s[name] = snap(read()); } catch (e) { s[name] = `throws ${messageOf(e)}`; }
    }
    return s;
  }

  async function call(fn, args) {
    let value = fn(...args);
    if (value && typeof value.then === 'function') value = await value;
    return value;
  }

  for (const job of jobs) {
    const cls = job.cls ? wasm[job.cls] : null;
    const label = job.label;
    // Objects: a receiver made by the constructor's baseline, if any (else the method still gets
    // its hostile arguments on a wrong receiver).
    const makeReceiver = () => {
      if (!job.method || job.static) return null;
      for (const args of job.ctorBases) {
        try {
          const r = new cls(...args);
          return r;
        } catch (e) {
          if (isPanic(e)) throw e;
        }
      }
      return null;
    };
    let receiver = null;
    try {
      receiver = makeReceiver();
    } catch (e) {
      post({ type: 'result', label, args: 'constructor baseline', kind: 'panic', detail: panicMessage || messageOf(e) });
      post({ type: 'fatal' });
      return;
    }
    const target = () => {
      if (!job.method) return (...a) => new cls(...a);
      if (job.static) return (...a) => cls[job.method](...a);
      if (!cls) return (...a) => wasm[job.method](...a);
      return (...a) => cls.prototype[job.method].apply(receiver ?? Object.create(cls.prototype), a);
    };
    const readers = receiver ? readersOf(cls, receiver) : [];
    // Readers must be deterministic to compare states: drop those that differ on a second read.
    if (readers.length) {
      const a = snapshot(readers), b = snapshot(readers);
      for (let i = readers.length - 1; i >= 0; i--) if (!same(a[readers[i][0]], b[readers[i][0]])) readers.splice(i, 1);
      for (const [name] of readers) {
        const n = nonFinite(a[name]);
        if (n) post({ type: 'result', label: `${job.cls}.${name}`, args: 'at rest', kind: 'nonfinite', detail: `${n} non-finite values after construction`, counted: false });
      }
    }

    // Baselines: the first two candidate argument lists the call accepts. The hostile calls take
    // their other arguments from the first while the object holds the second's state, so that a
    // setter which assigns some arguments before rejecting another changes what the readers see.
    const accepted = [];
    for (const args of job.bases) {
      try {
        post({ type: 'start', label, args: args.map(describe).join(', ') });
        const v = await call(target(), args);
        post({ type: 'done' });
        accepted.push(args);
        const n = nonFinite(v);
        post({ type: 'result', label, args: args.map(describe).join(', '), ...(n ? { kind: 'nonfinite', detail: `${n} non-finite values in the result` } : { kind: 'accepted' }) });
        if (!job.method && v && typeof v.free === 'function') v.free();
        if (accepted.length === 2) break;
      } catch (e) {
        post({ type: 'done' });
        if (!isPanic(e)) post({ type: 'result', label, args: args.map(describe).join(', '), kind: 'error' });
        if (isPanic(e)) {
          post({ type: 'result', label, args: args.map(describe).join(', '), kind: 'panic', detail: panicMessage || messageOf(e) });
          post({ type: 'fatal' });
          return;
        }
      }
    }

    // The object's state as last read: a rejected call must leave it so, an accepted one may
    // change it (one read per call instead of two).
    const base = accepted[0] ?? job.bases[0];
    const restore = accepted.length === 2 && job.method && !job.static ? accepted[1] : null;
    let state = readers.length ? snapshot(readers) : null;
    for (const [position, hostileIndex] of job.calls) {
      const args = base.slice();
      while (args.length < job.arity) args.push(undefined);
      const [hostileName, make] = HOSTILE[hostileIndex];
      args[position] = make();
      const shown = args.map(describe).join(', ');
      const before = state;
      let outcome;
      post({ type: 'start', label, args: shown });
      try {
        const v = await call(target(), args);
        post({ type: 'done' });
        const n = nonFinite(v);
        const after = readers.length ? snapshot(readers) : null;
        state = after;
        const newlyBad = readers.filter(([name]) => nonFinite(after[name]) > nonFinite(before[name])).map(([name]) => name);
        if (n) outcome = { kind: 'nonfinite', detail: `${n} non-finite values in the result` };
        else if (newlyBad.length) outcome = { kind: 'nonfinite', detail: `accepted, then ${newlyBad.join(', ')} read non-finite values` };
        else if (coerced(job.types[position], args[position])) {
          outcome = { kind: 'coerced', detail: `accepted ${describe(args[position])} for a parameter of type ${job.types[position]}` };
        } else outcome = { kind: 'accepted' };
        if (!job.method && v && typeof v.free === 'function') v.free();
        if (restore) {
          // Back to the second baseline's state for the next call.
          try { await call(target(), restore); } catch { /* it was accepted before */ }
          state = readers.length ? snapshot(readers) : null;
        }
      } catch (e) {
        post({ type: 'done' });
        if (isPanic(e)) {
          post({ type: 'result', label, args: shown, kind: 'panic', detail: panicMessage || messageOf(e) });
          post({ type: 'fatal' });
          return;
        }
        const after = readers.length ? snapshot(readers) : null;
        state = after;
        const changed = readers.filter(([name]) => !same(before[name], after[name])).map(([name]) => name);
        if (changed.length) outcome = { kind: 'half', detail: `rejected (${messageOf(e)}) but changed ${changed.join(', ')}` };
        else if (e instanceof Error && messageOf(e).length > 0) outcome = { kind: 'error' };
        else outcome = { kind: 'unclear', detail: `threw ${describe(e)}` };
      }
      if (!moduleWorks()) {
        post({ type: 'result', label, args: shown, kind: 'panic', detail: `the module no longer works after the call${panicMessage ? `: ${panicMessage}` : ''}` });
        post({ type: 'fatal' });
        return;
      }
      post({ type: 'result', label, args: shown, hostile: hostileName, ...outcome });
    }
    if (receiver) {
      try { receiver.free(); } catch { /* already freed by the call under test */ }
    }
    post({ type: 'job-done', label });
  }
  post({ type: 'all-done' });
}

// ---------------------------------------------------------------------------------------------
// Main thread: enumerates the exports, plans the calls, runs the workers, counts.
// ---------------------------------------------------------------------------------------------
function mulberry32(seed) {
  return () => {
    seed |= 0; seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** JSDoc `@param {type} name` lists of each function in the glue, keyed "Class.method" or "fn". */
function paramTypes(glue) {
  const types = new Map();
  const re = /\/\*\*((?:(?!\*\/)[\s\S])*?)\*\/\s*\n\s*(?:export )?(?:static )?(?:async )?(?:function )?(\w+)\s*\(/g;
  let cls = null;
  const classAt = [...glue.matchAll(/^export class (\w+)/gm)].map((m) => [m.index, m[1]]);
  for (const m of glue.matchAll(re)) {
    cls = null;
    for (const [at, name] of classAt) if (at < m.index) cls = name;
    const isFree = /\n\s*export function/.test(glue.slice(m.index, m.index + m[0].length + 20)) ||
      glue.slice(m.index + m[0].length - m[2].length - 20, m.index + m[0].length).includes('export function');
    const list = [...m[1].matchAll(/@param \{([^}]*)\} (\w+)/g)].map((p) => p[1]);
    types.set(isFree ? m[2] : `${cls}.${m[2]}`, list);
  }
  return types;
}

function basesFor(types, arity) {
  const out = [];
  for (let k = 0; k < Math.max(NUMBER_BASES.length, ANY_BASES.length); k++) {
    const args = [];
    for (let i = 0; i < arity; i++) {
      const t = types[i] || 'any';
      if (t === 'number') args.push(NUMBER_BASES[k % NUMBER_BASES.length]);
      else if (/Array|\[\]/.test(t)) args.push(ARRAY_BASES[k % ARRAY_BASES.length]);
      else args.push(ANY_BASES[k % ANY_BASES.length]);
    }
    out.push(args);
    if (arity === 0) break;
  }
  return out;
}

async function main() {
  const dist = process.argv[2] || 'dist';
  // The four modules of the build (scripts/build): the figures, course, bench and glTF modules.
  let bad = 0;
  for (const name of ['inbetween', 'course', 'bench', 'gltf']) bad += await probeModule(dist, name);
  process.exit(bad ? 1 : 0);
}

/** Probes the module `name` of dist/pkg/; resolves to the number of failed calls. */
async function probeModule(dist, name) {
  const gluePath = path.resolve(dist, `pkg/${name}.js`);
  const glue = readFileSync(gluePath, 'utf8');
  const module = new WebAssembly.Module(readFileSync(path.resolve(dist, `pkg/${name}_bg.wasm`)));
  const wasm = await import(pathToFileURL(gluePath).href);
  const types = paramTypes(glue);
  const seed = Number(process.env.PROBE_SEED || Date.now() % 1e9);
  const random = mulberry32(seed);

  // Every callable: constructors, static functions, prototype methods, free functions.
  const callables = [];
  for (const [name, value] of Object.entries(wasm)) {
    if (typeof value !== 'function' || name === 'default' || name === 'initSync' || name.startsWith('__')) continue;
    const isClass = /^class\b/.test(Function.prototype.toString.call(value));
    if (!isClass) {
      callables.push({ label: `${name}()`, cls: null, method: name, arity: value.length, types: types.get(name) || [] });
      continue;
    }
    const ctorTypes = types.get(`${name}.constructor`) || [];
    const ctorBases = basesFor(ctorTypes, value.length);
    const hasCtor = /\n\s*constructor\s*\(/.test(Function.prototype.toString.call(value));
    if (hasCtor) callables.push({ label: `new ${name}()`, cls: name, method: null, arity: value.length, types: ctorTypes, ctorBases });
    for (const s of Object.getOwnPropertyNames(value)) {
      if (['length', 'name', 'prototype'].includes(s) || s.startsWith('__')) continue;
      if (typeof value[s] !== 'function') continue;
      callables.push({ label: `${name}.${s}()`, cls: name, method: s, static: true, arity: value[s].length, types: types.get(`${name}.${s}`) || [] });
    }
    for (const m of Object.getOwnPropertyNames(value.prototype)) {
      if (m === 'constructor' || m === 'free' || m.startsWith('__')) continue;
      const d = Object.getOwnPropertyDescriptor(value.prototype, m);
      if (typeof d.value !== 'function') continue;
      callables.push({ label: `${name}.prototype.${m}()`, cls: name, method: m, arity: d.value.length, types: types.get(`${name}.${m}`) || [], ctorBases: hasCtor ? ctorBases : [] });
    }
  }

  // The calls: every argument position × every hostile value; a random sample of them per
  // callable when all would not fit in the time budget (every callable keeps at least one call
  // per argument).
  const full = callables.reduce((n, c) => n + c.arity * HOSTILE.length, 0);
  const fraction = Number(process.env.PROBE_FRACTION || 1);
  const jobs = callables.map((c) => {
    let calls = [];
    for (let p = 0; p < c.arity; p++) for (let h = 0; h < HOSTILE.length; h++) calls.push([p, h]);
    if (fraction < 1) {
      const keep = calls.filter(() => random() < fraction);
      for (let p = 0; p < c.arity; p++) {
        if (!keep.some(([q]) => q === p)) keep.push([p, Math.floor(random() * HOSTILE.length)]);
      }
      calls = keep;
    }
    return { ...c, bases: basesFor(c.types, c.arity), ctorBases: c.ctorBases || [], calls };
  });

  const counts = { calls: 0, error: 0, accepted: 0, panic: 0, hang: 0, nonfinite: 0, half: 0, unclear: 0, coerced: 0 };
  const failures = [];
  const started = Date.now();
  // A queue of jobs shared by WORKERS runners; a runner whose worker dies restarts from the job
  // after the failing call's.
  let next = 0;
  const queue = jobs.slice();
  async function runner() {
    while (next < queue.length) {
      const batch = [];
      while (next < queue.length && batch.length < 8) batch.push(queue[next++]);
      await runBatch(batch);
    }
  }
  function runBatch(batch) {
    return new Promise((resolve) => {
      const worker = new Worker(fileURLToPath(import.meta.url), { workerData: { gluePath, module, jobs: batch } });
      let current = null, timer = null, finished = false;
      const doneJobs = new Set();
      const finish = (restartFrom) => {
        if (finished) return;
        finished = true;
        clearTimeout(timer);
        worker.terminate().then(async () => {
          if (restartFrom) await runBatch(restartFrom);
          resolve();
        });
      };
      const rest = () => {
        // The rest of this batch, minus the jobs that finished, starting after the failing job.
        const i = batch.findIndex((j) => current && j.label === current.label);
        return batch.slice(i + 1).filter((j) => !doneJobs.has(j.label));
      };
      worker.on('message', (m) => {
        if (m.type === 'start') {
          current = m;
          clearTimeout(timer);
          timer = setTimeout(() => {
            counts.calls++; counts.hang++;
            failures.push(`HANG ${current.label}(${current.args}): no answer in ${CALL_LIMIT_MS} ms`);
            finish(rest());
          }, CALL_LIMIT_MS);
        } else if (m.type === 'done') {
          clearTimeout(timer);
        } else if (m.type === 'result') {
          if (m.counted === false) {
            counts.nonfinite++;
            failures.push(`NON-FINITE ${m.label} ${m.args}: ${m.detail}`);
            return;
          }
          counts.calls++;
          counts[m.kind]++;
          if (m.kind !== 'error' && m.kind !== 'accepted') {
            failures.push(`${m.kind.toUpperCase()} ${m.label}(${m.args}): ${m.detail}`);
          }
        } else if (m.type === 'job-done') {
          doneJobs.add(m.label);
        } else if (m.type === 'fatal') {
          finish(rest());
        } else if (m.type === 'all-done') {
          finish(null);
        }
      });
      worker.on('error', (e) => {
        counts.calls++; counts.panic++;
        failures.push(`PANIC ${current ? `${current.label}(${current.args})` : 'worker'}: ${e.message}`);
        finish(rest());
      });
    });
  }
  await Promise.all(Array.from({ length: WORKERS }, runner));
  const seconds = ((Date.now() - started) / 1000).toFixed(1);

  for (const f of failures.slice(0, 60)) console.log(f);
  if (failures.length > 60) console.log(`... and ${failures.length - 60} more`);
  console.log(`probe: ${name}_bg.wasm: ${callables.length} callables (${callables.filter((c) => !c.cls).length} free functions), ` +
    `${jobs.reduce((n, j) => n + j.calls.length, 0)} of ${full} hostile calls planned (plus the baseline calls), seed ${seed}, ${seconds} s`);
  console.log(`probe: calls ${counts.calls}, clear errors ${counts.error}, accepted ${counts.accepted}, ` +
    `panics ${counts.panic}, hangs ${counts.hang}, non-finite outputs ${counts.nonfinite}, ` +
    `half-applied ${counts.half}, unclear errors ${counts.unclear}, silent coercions ${counts.coerced}`);
  return counts.panic + counts.hang + counts.nonfinite + counts.half + counts.unclear;
}

if (isMainThread) await main();
else await workerMain();
