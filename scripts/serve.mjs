// A static server for dist/ on 127.0.0.1 (WebGPU needs a secure context: localhost counts).
// With --watch, saving a file under src/ rebuilds the wasm (debug build), and saving under
// lessons/ or www/ re-copies the pages; open pages then reload themselves (www/devloop.js), or
// show the compiler's errors when the build failed (the previous build is still served).
//
//   node scripts/serve.mjs [--port 8000] [--watch] [--solutions] [--dist DIR] [--build-first release|dev]
//
// --build-first (with --watch) serves what dist/ holds at once and builds the current sources in
// the background with that profile; open pages reload when it is done.
// It serves dist/, or DIR (scripts/serve passes its INBETWEEN_DIST, the folder scripts/build
// writes; the rebuilds then write there too).
//
// The watching server tells pages about builds at /__devloop/events (Server-Sent Events, one JSON
// status per message) and /__devloop/status (the same JSON), and marks every HTML page it serves
// with <meta name="inbetween-devloop" content="/__devloop">: devloop.js connects only when it sees
// that tag, so pages served without --watch (and in the tests) make no request at all.
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { watch } from 'node:fs';
import { spawn } from 'node:child_process';
import { randomUUID } from 'node:crypto';
import { extname, join, normalize, resolve } from 'node:path';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.json': 'application/json', '.wasm': 'application/wasm',
  '.png': 'image/png', '.svg': 'image/svg+xml', '.woff2': 'font/woff2', '.woff': 'font/woff', '.ttf': 'font/ttf',
  '.rs': 'text/plain; charset=utf-8', '.wgsl': 'text/plain; charset=utf-8', '.txt': 'text/plain; charset=utf-8',
};

export const DEVLOOP_PATH = '/__devloop';

/**
 * Serves `root` on 127.0.0.1:`port` (0 = any free port). Resolves to the http.Server. With
 * `devloop` (a Devloop), also serves its endpoints and marks HTML pages for www/devloop.js (call
 * `devloop.close()` before `server.close()`: open event streams keep a server from closing).
 */
export function startServer(root = 'dist', port = 8000, { devloop = null } = {}) {
  const base = resolve(root);
  const server = createServer(async (req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (devloop && path.startsWith(`${DEVLOOP_PATH}/`)) {
      devloop.handle(path, res);
      return;
    }
    let file = normalize(join(base, path));
    if (!file.startsWith(base)) {
      res.writeHead(403).end();
      return;
    }
    try {
      if ((await stat(file)).isDirectory()) {
        if (!path.endsWith('/')) {
          res.writeHead(301, { Location: `${path}/` }).end();
          return;
        }
        file = join(file, 'index.html');
      }
      let body = await readFile(file);
      if (devloop && extname(file) === '.html') body = markForDevloop(body.toString('utf8'));
      res.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream', 'Cache-Control': 'no-store' });
      res.end(body);
    } catch {
      res.writeHead(404, { 'Content-Type': 'text/plain' }).end(`not found: ${path}`);
    }
  });
  return new Promise((ok, fail) => {
    server.once('error', fail);
    server.listen(port, '127.0.0.1', () => ok(server));
  });
}

function markForDevloop(html) {
  const meta = `<meta name="inbetween-devloop" content="${DEVLOOP_PATH}">`;
  const head = /<head[^>]*>/i.exec(html);
  return head ? html.slice(0, head.index + head[0].length) + meta + html.slice(head.index + head[0].length) : meta + html;
}

/**
 * The compiler's errors in a build log, for the page: each `error…` diagnostic of cargo/rustc up to
 * the blank line that ends it (so with its `--> file:line:column` and the code excerpt), without
 * warnings, progress lines or colour codes. When the log has no such diagnostic (a failure outside
 * the compiler), its last 30 lines.
 */
export function compilerErrors(log, maxChars = 12_000) {
  // eslint-disable-next-line no-control-regex
  const lines = log.replace(/\x1b\[[0-9;]*[A-Za-z]/g, '').replace(/\r/g, '').split('\n');
  const blocks = [];
  let block = null;
  for (const line of lines) {
    if (/^error(\[\w+\])?:/.test(line)) {
      block = [line];
      blocks.push(block);
    } else if (block && line.trim() !== '') {
      // A diagnostic goes on with indented lines, `NN |` excerpt lines (`NN +` / `NN -` in
      // suggestions), `= note` lines and `help:` / `note:` lines; any other line at column 0
      // (warning:, Compiling, Some errors have…) is not part of it.
      if (/^(\s|\d+\s*[|+~-]|\||=|help:|note:|\.\.\.)/.test(line)) block.push(line);
      else block = null;
    } else {
      block = null;
    }
  }
  let text = blocks.map((b) => b.join('\n')).join('\n\n');
  if (!text) text = lines.filter((l) => l.trim() !== '').slice(-30).join('\n');
  return text.length > maxChars ? `${text.slice(0, maxChars)}\n…` : text;
}

/**
 * What the watching server tells pages: `session` (changes when the server restarts), `builds`
 * (builds finished since it started), `building` (null, or "rust" / "pages" while one runs), `last`
 * (the outcome of the last build: { kind, ok }), and `errors`: the compiler's message of a failed
 * build that no later build has fixed yet ("" when there is none; meanwhile dist/ keeps the
 * previous build).
 */
export class Devloop {
  constructor() {
    this.status = { session: randomUUID(), builds: 0, building: null, last: null, errors: '' };
    // Outstanding failures by kind: a failed Rust build stays reported after a pages-only rebuild.
    this.failures = { rust: '', pages: '' };
    this.clients = new Set();
  }

  started(kind) {
    this.status.building = kind;
    this.#broadcast();
  }

  /** A build of `kind` ("rust", which also re-copies the pages, or "pages") ended; `log` is its output. */
  finished(kind, ok, log = '') {
    if (ok) {
      this.failures.pages = '';
      if (kind === 'rust') this.failures.rust = '';
    } else {
      this.failures[kind] = compilerErrors(log);
    }
    Object.assign(this.status, {
      builds: this.status.builds + 1, building: null, last: { kind, ok },
      errors: this.failures.rust || this.failures.pages,
    });
    this.#broadcast();
  }

  handle(path, res) {
    if (path === `${DEVLOOP_PATH}/status`) {
      res.writeHead(200, { 'Content-Type': 'application/json', 'Cache-Control': 'no-store' });
      res.end(JSON.stringify(this.status));
    } else if (path === `${DEVLOOP_PATH}/events`) {
      res.writeHead(200, { 'Content-Type': 'text/event-stream', 'Cache-Control': 'no-store', Connection: 'keep-alive' });
      res.write(`data: ${JSON.stringify(this.status)}\n\n`);
      this.clients.add(res);
      res.on('close', () => this.clients.delete(res));
    } else {
      res.writeHead(404, { 'Content-Type': 'text/plain' }).end(`not found: ${path}`);
    }
  }

  /** Ends the event streams (an http.Server does not close while they are open). */
  close() {
    for (const res of this.clients) res.end();
    this.clients.clear();
  }

  #broadcast() {
    const message = `data: ${JSON.stringify(this.status)}\n\n`;
    for (const res of this.clients) res.write(message);
  }
}

/** Runs scripts/build with `args`, echoing its output; resolves to { ok, log }. */
function runBuild(args) {
  // Cargo colours its messages only on a terminal; ours is behind a pipe, so ask for colours when
  // our own output is a terminal (compilerErrors strips them for the page).
  const env = { ...process.env };
  if (process.stdout.isTTY && !env.CARGO_TERM_COLOR) env.CARGO_TERM_COLOR = 'always';
  return new Promise((ok) => {
    const child = spawn('scripts/build', args, { stdio: ['ignore', 'pipe', 'pipe'], env });
    let log = '';
    const keep = (chunk, echo) => {
      echo.write(chunk);
      log = (log + chunk).slice(-1_000_000);
    };
    child.stdout.setEncoding('utf8').on('data', (c) => keep(c, process.stdout));
    child.stderr.setEncoding('utf8').on('data', (c) => keep(c, process.stderr));
    child.on('error', (e) => ok({ ok: false, log: `${log}\nerror: could not run scripts/build: ${e.message}` }));
    child.on('close', (code) => ok({ ok: code === 0, log }));
  });
}

/**
 * What a change to `file` (a path under src/) needs rebuilt: "exercises" when it is a student's
 * exercise or the grader (src/exercises/, except run.rs and mod.rs, which the figures module uses
 * too): the course module alone, since student code runs only there; "rust" otherwise: all three
 * modules.
 */
export function sourceChangeKind(file) {
  const path = String(file ?? '').split(/[\\/]/).join('/');
  return /^exercises\/(?!run\.rs$|mod\.rs$)[^/]+\.rs$/.test(path) ? 'exercises' : 'rust';
}

/**
 * Rebuilds when files change, one build at a time: a change under src/ rebuilds the debug wasm and
 * the pages (the course module alone when only exercises changed, see `sourceChangeKind`; the
 * figures module already served stays, release or debug), one under lessons/ or www/ the pages alone. With `first` ("release" or "dev"), it
 * first builds the current sources with that profile: the server is already serving what dist/
 * held, and open pages reload when the build is done.
 */
function watchAndRebuild(extra, devloop, first = null) {
  const args = {
    release: extra, dev: ['--dev', ...extra], rust: ['--dev', ...extra],
    exercises: ['--dev', '--course-only', ...extra], pages: ['--assets-only'],
  };
  // Builds waiting, in order. A Rust build also copies the pages and builds the course module, so
  // it takes a waiting pages or exercises build's place, and those wait behind it for nothing.
  const queue = [];
  let busy = false;
  const run = async () => {
    if (busy || !queue.length) return;
    busy = true;
    const what = queue.shift();
    if (what === 'release' || what === 'dev') {
      console.log(`serve: building the current sources (${what}) in the background; open pages reload when it is done`);
    } else {
      const where = { rust: 'src/', exercises: 'src/exercises/ (the course module alone)', pages: 'the pages' }[what];
      console.log(`\nserve: change in ${where}, rebuilding…`);
    }
    // For the pages, every build of the wasm is a Rust build.
    const kind = what === 'pages' ? 'pages' : 'rust';
    devloop.started(kind);
    const { ok, log } = await runBuild(args[what]);
    devloop.finished(kind, ok, log);
    console.log(ok ? 'serve: rebuilt; open pages reload themselves.'
      : 'serve: the build failed (see above); the old build is still served, and open pages show the errors.');
    busy = false;
    if (queue.length) setTimeout(run, 300);
  };
  const schedule = (kind) => {
    if (kind === 'rust') {
      for (const covered of ['pages', 'exercises']) {
        const i = queue.indexOf(covered);
        if (i >= 0) queue.splice(i, 1);
      }
    }
    if (kind === 'exercises') {
      const pages = queue.indexOf('pages');
      if (pages >= 0) queue.splice(pages, 1);
    }
    const covered = queue.includes('rust') && kind !== 'rust'
      || kind === 'pages' && queue.includes('exercises');
    if (!queue.includes(kind) && !covered) queue.push(kind);
    setTimeout(run, 300);
  };
  if (first) schedule(first);
  watch('src', { recursive: true }, (_event, file) => schedule(sourceChangeKind(file)));
  for (const dir of ['lessons', 'www']) watch(dir, { recursive: true }, () => schedule('pages'));
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const args = process.argv.slice(2);
  const portArg = args.indexOf('--port');
  let port = Number(portArg >= 0 ? args[portArg + 1] : process.env.PORT ?? 8000);
  const devloop = args.includes('--watch') ? new Devloop() : null;
  const distArg = args.indexOf('--dist');
  const dist = distArg >= 0 ? args[distArg + 1] : 'dist';
  if (distArg >= 0) process.env.INBETWEEN_DIST = dist;
  let server;
  for (let attempt = 0; !server; attempt++) {
    try {
      server = await startServer(dist, port, { devloop });
    } catch (e) {
      if (e.code !== 'EADDRINUSE' || attempt > 20) throw e;
      port += 1;
    }
  }
  console.log(`serve: lessons at http://127.0.0.1:${server.address().port}/lessons/  (Ctrl-C stops)`);
  if (devloop) {
    const firstArg = args.indexOf('--build-first');
    const first = firstArg >= 0 ? args[firstArg + 1] : null;
    if (first !== null && first !== 'release' && first !== 'dev') {
      console.error(`serve: --build-first takes release or dev, not ${first}`);
      process.exit(2);
    }
    watchAndRebuild(args.includes('--solutions') ? ['--solutions'] : [], devloop, first);
    console.log('serve: watching src/, lessons/ and www/ for changes; open pages reload after each rebuild');
  }
}
