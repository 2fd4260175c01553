// Start-up time and memory of a lesson page, per backend: the time from navigation until every
// figure has drawn (`document.body.dataset.ready === '1'`), then, after `SETTLE_MS`, the browser's
// memory: the proportional set size (PSS, shared pages split between the processes that map them)
// of its renderer and GPU processes and of all of them together, and the page's JS heap.
// Each run starts a fresh browser, so one run's memory does not carry into the next.
//
//   node scripts/measure-page.mjs [DIST] [PAGE] [RUNS]
//   node scripts/measure-page.mjs dist /lessons/05-noise/ 3
import { chromium } from 'playwright-core';
import { mkdtempSync, readdirSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { startServer } from './serve.mjs';
import { PROFILES } from '../tests/e2e/browser.mjs';

const [dist = 'dist', path = '/lessons/05-noise/', runs = '3'] = process.argv.slice(2);
const SETTLE_MS = 2000;

/** pid -> { ppid, cmd } of every process. */
function processes() {
  const all = new Map();
  for (const name of readdirSync('/proc')) {
    if (!/^\d+$/.test(name)) continue;
    try {
      const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
      const ppid = Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]);
      const cmd = readFileSync(`/proc/${name}/cmdline`, 'utf8').replaceAll('\0', ' ');
      all.set(Number(name), { ppid, cmd });
    } catch { /* gone */ }
  }
  return all;
}

function pssKb(pid) {
  try {
    return Number(/^Pss:\s+(\d+)/m.exec(readFileSync(`/proc/${pid}/smaps_rollup`, 'utf8'))[1]);
  } catch {
    return 0;
  }
}

/** PSS in MB of the browser whose command line names `dir`, and of its descendants, by type. */
function browserMemory(dir) {
  const all = processes();
  const root = [...all].find(([, p]) => p.cmd.includes(dir) && !p.cmd.includes('--type='))?.[0];
  const tree = new Set([root]);
  for (let grew = true; grew;) {
    grew = false;
    for (const [pid, p] of all) if (!tree.has(pid) && tree.has(p.ppid)) { tree.add(pid); grew = true; }
  }
  const by = { renderer: 0, gpu: 0, total: 0 };
  for (const pid of tree) {
    const kb = pssKb(pid);
    const cmd = all.get(pid)?.cmd ?? '';
    by.total += kb;
    if (cmd.includes('--type=renderer')) by.renderer += kb;
    if (cmd.includes('--type=gpu-process')) by.gpu += kb;
  }
  return Object.fromEntries(Object.entries(by).map(([k, v]) => [k, Math.round(v / 1024)]));
}

const server = await startServer(dist, 0);
const origin = `http://127.0.0.1:${server.address().port}`;
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
for (const backend of ['webgl2', 'webgpu']) {
  const rows = [];
  for (let i = 0; i < Number(runs); i++) {
    const dir = mkdtempSync(join(tmpdir(), `measure-${backend}-`));
    const context = await chromium.launchPersistentContext(dir, {
      executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
      headless: true,
      args: PROFILES[backend],
      viewport: { width: 1100, height: 900 },
    });
    try {
      const page = await context.newPage();
      const cdp = await context.newCDPSession(page);
      await cdp.send('Performance.enable');
      const url = `${origin}${path}?backend=${backend}`;
      const started = Date.now();
      await page.goto(url);
      await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: 180_000, polling: 20 });
      const readyMs = Date.now() - started;
      const info = await page.evaluate(() => ({
        figures: window.__inbetween.figures.length,
        backends: [...new Set(window.__inbetween.figures.map((f) => f.backend))].join(','),
        errors: window.__inbetween.errors,
      }));
      await page.waitForTimeout(SETTLE_MS);
      const metrics = Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
      const memory = browserMemory(dir);
      rows.push({ readyMs, ...memory, jsHeapMb: Math.round(metrics.JSHeapUsedSize / 2 ** 20), ...info });
      console.log(backend, JSON.stringify(rows.at(-1)));
    } finally {
      await context.close();
    }
  }
  const keys = ['readyMs', 'renderer', 'gpu', 'total', 'jsHeapMb'];
  console.log(`${backend} median of ${rows.length}:`, JSON.stringify(Object.fromEntries(keys.map((k) => [k, median(rows.map((r) => r[k]))]))));
}
server.close();
