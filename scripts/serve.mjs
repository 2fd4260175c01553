// A static server for dist/ on 127.0.0.1 (WebGPU needs a secure context: localhost counts).
// With --watch, saving a file under src/ rebuilds the wasm (debug build), and saving under
// lessons/ or www/ re-copies the pages; reload the browser tab to see the result.
//
//   node scripts/serve.mjs [--port 8000] [--watch] [--solutions]
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { watch } from 'node:fs';
import { spawn } from 'node:child_process';
import { extname, join, normalize, resolve } from 'node:path';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.json': 'application/json', '.wasm': 'application/wasm',
  '.png': 'image/png', '.svg': 'image/svg+xml', '.woff2': 'font/woff2', '.woff': 'font/woff', '.ttf': 'font/ttf',
  '.rs': 'text/plain; charset=utf-8', '.wgsl': 'text/plain; charset=utf-8', '.txt': 'text/plain; charset=utf-8',
};

/** Serves `root` on 127.0.0.1:`port` (0 = any free port). Resolves to the http.Server. */
export function startServer(root = 'dist', port = 8000) {
  const base = resolve(root);
  const server = createServer(async (req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
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
      const body = await readFile(file);
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

function run(args) {
  return new Promise((ok) => spawn('scripts/build', args, { stdio: 'inherit' }).on('exit', (code) => ok(code === 0)));
}

function watchAndRebuild(extra) {
  let pending = null;
  let busy = false;
  const schedule = (kind) => {
    pending = pending === 'rust' ? 'rust' : kind;
    setTimeout(async () => {
      if (busy || !pending) return;
      busy = true;
      const what = pending;
      pending = null;
      console.log(`\nserve: change in ${what === 'rust' ? 'src/' : 'the pages'}, rebuilding…`);
      const ok = await run(what === 'rust' ? ['--dev', ...extra] : ['--assets-only']);
      console.log(ok ? 'serve: rebuilt; reload the page.' : 'serve: the build failed (see above); the old build is still served.');
      busy = false;
      if (pending) schedule(pending);
    }, 300);
  };
  watch('src', { recursive: true }, () => schedule('rust'));
  for (const dir of ['lessons', 'www']) watch(dir, { recursive: true }, () => schedule('pages'));
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const args = process.argv.slice(2);
  const portArg = args.indexOf('--port');
  let port = Number(portArg >= 0 ? args[portArg + 1] : process.env.PORT ?? 8000);
  let server;
  for (let attempt = 0; !server; attempt++) {
    try {
      server = await startServer('dist', port);
    } catch (e) {
      if (e.code !== 'EADDRINUSE' || attempt > 20) throw e;
      port += 1;
    }
  }
  console.log(`serve: lessons at http://127.0.0.1:${server.address().port}/lessons/  (Ctrl-C stops)`);
  if (args.includes('--watch')) {
    watchAndRebuild(args.includes('--solutions') ? ['--solutions'] : []);
    console.log('serve: watching src/, lessons/ and www/ for changes');
  }
}
