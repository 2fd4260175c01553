// The live dev loop: `node scripts/serve.mjs --watch` and www/devloop.js, in headless Chromium.
// The watching server runs in a throwaway project in a temporary directory whose scripts/build is
// a stand-in (it fails like cargo when src/lib.rs says BROKEN, else copies www/ to dist/), so the
// test needs no Rust build and never touches the real tree.
//   node --test tests/e2e/devloop.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn, execFileSync } from 'node:child_process';
import { chmodSync, copyFileSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { launch } from './browser.mjs';
import { startServer, compilerErrors, sourceChangeKind } from '../../scripts/serve.mjs';

const CARGO_FAILURE = `   Compiling inbetween v0.1.0 (/tmp/project)
warning: unused import: \`Mat4\`
 --> src/lib.rs:1:12
  |
1 | use glam::{Mat4, Vec3};
  |            ^^^^
  |
  = note: \`#[warn(unused_imports)]\` on by default

error[E0308]: mismatched types
  --> src/exercises/transforms.rs:42:5
   |
42 |     m
   |     ^ expected \`Result<Mat4, NotDone>\`, found \`Mat4\`
   |
help: try wrapping the expression in \`Ok\`
   |
42 |     Ok(m)
   |     +++ +

Some errors have detailed explanations: E0308.
For more information about an error, try \`rustc --explain E0308\`.
warning: \`inbetween\` (lib) generated 1 warning
error: could not compile \`inbetween\` (lib) due to 1 previous error; 1 warning emitted
`;

const FAKE_BUILD = `#!/usr/bin/env bash
# Stands in for scripts/build: fails like cargo when src/lib.rs says BROKEN (unless --assets-only),
# else copies www/ to dist/.
set -euo pipefail
if [ "\${1:-}" != --assets-only ] && grep -q BROKEN src/lib.rs; then
  cat >&2 <<'EOF'
${CARGO_FAILURE}EOF
  exit 101
fi
mkdir -p dist && rm -rf dist/www && cp -r www dist/
echo "build: ok"
`;

const page = (version) => `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>devloop test</title><link rel="icon" href="data:,">
<script type="module">import './devloop.js'; document.body.dataset.ready = '1';</script>
</head><body><p id="version">${version}</p></body></html>
`;

/** A throwaway project: src/, lessons/, www/ (the page and the real devloop.js), the fake build, dist/. */
function makeProject() {
  const dir = mkdtempSync(join(tmpdir(), 'inbetween-devloop-'));
  for (const sub of ['src', 'lessons', 'www', 'scripts']) mkdirSync(join(dir, sub));
  writeFileSync(join(dir, 'src/lib.rs'), '// fine\n');
  writeFileSync(join(dir, 'www/page.html'), page('version 1'));
  copyFileSync('www/devloop.js', join(dir, 'www/devloop.js'));
  writeFileSync(join(dir, 'scripts/build'), FAKE_BUILD);
  chmodSync(join(dir, 'scripts/build'), 0o755);
  execFileSync('scripts/build', { cwd: dir, stdio: 'ignore' });
  return dir;
}

/** Opens `url`, collecting console errors, page errors and requests to the dev loop endpoints. */
async function open(context, url) {
  const tab = await context.newPage();
  const problems = [];
  const devloopRequests = [];
  tab.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  tab.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  tab.on('request', (r) => { if (r.url().includes('__devloop')) devloopRequests.push(r.url()); });
  await tab.goto(url);
  await tab.waitForFunction(() => document.body.dataset.ready);
  return { tab, problems, devloopRequests };
}

test('compilerErrors keeps the errors with file:line and drops warnings and progress', () => {
  const text = compilerErrors(CARGO_FAILURE);
  assert.match(text, /^error\[E0308\]: mismatched types\n {2}--> src\/exercises\/transforms\.rs:42:5/);
  assert.match(text, /help: try wrapping the expression in `Ok`/);
  assert.match(text, /error: could not compile `inbetween`/);
  assert.doesNotMatch(text, /^warning|Compiling|unused import|Some errors|rustc --explain/m);
  assert.equal(compilerErrors('\x1b[1m\x1b[91merror\x1b[0m: boom\n'), 'error: boom');
  // Not a compiler failure: the end of the log.
  assert.equal(compilerErrors('copying\nError: lessons/x/meta.json lacks "title"\n'), 'copying\nError: lessons/x/meta.json lacks "title"');
});

test('a change to an exercise rebuilds the course module alone; run.rs, mod.rs and the rest rebuild every module', () => {
  for (const f of ['exercises/curves.rs', 'exercises/grade.rs', 'exercises\\noise.rs']) assert.equal(sourceChangeKind(f), 'exercises', f);
  for (const f of ['exercises/run.rs', 'exercises/mod.rs', 'lib.rs', 'figures/curves.rs', 'web/sandbox.rs', 'exercises', null]) {
    assert.equal(sourceChangeKind(f), 'rust', String(f));
  }
});

test('served without the watcher, devloop.js does nothing and makes no request', async () => {
  const dir = makeProject();
  const server = await startServer(join(dir, 'dist'), 0);
  const context = await launch('webgl2');
  try {
    const { tab, problems, devloopRequests } = await open(context, `http://127.0.0.1:${server.address().port}/www/page.html`);
    assert.equal(await tab.locator('meta[name="inbetween-devloop"]').count(), 0);
    assert.equal(await tab.evaluate(() => document.documentElement.dataset.devloop), undefined);
    assert.equal(await tab.locator('#devloop-errors, #devloop-building').count(), 0);
    assert.deepEqual(devloopRequests, []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
    server.close();
    rmSync(dir, { recursive: true, force: true });
  }
});

test('with --watch, pages reload after a rebuild and show a failed build\'s errors', { timeout: 90_000 }, async () => {
  const dir = makeProject();
  const server = spawn(process.execPath, [resolve('scripts/serve.mjs'), '--watch', '--port', '0'], { cwd: dir });
  let output = '';
  server.stderr.on('data', (d) => { output += d; });
  const context = await launch('webgl2');
  try {
    const origin = await new Promise((ok, fail) => {
      server.stdout.on('data', (d) => {
        output += d;
        const url = /http:\/\/127\.0\.0\.1:\d+/.exec(output);
        if (url && output.includes('serve: watching')) ok(url[0]);
      });
      server.on('exit', (code) => fail(new Error(`serve.mjs exited (${code}):\n${output}`)));
    });
    const status = async () => (await fetch(`${origin}/__devloop/status`)).json();
    const { tab, problems } = await open(context, `${origin}/www/page.html`);
    const watching = () => tab.waitForFunction(() => document.documentElement.dataset.devloop === 'watching');
    await watching();
    assert.equal(await tab.locator('meta[name="inbetween-devloop"]').count(), 1);
    assert.deepEqual({ ...(await status()), session: 'any' },
      { session: 'any', builds: 0, building: null, last: null, errors: '' });
    await tab.evaluate(() => { window.marker = 'loaded once'; });

    // A failed Rust build: the errors appear, the page stays as it is (no reload).
    writeFileSync(join(dir, 'src/lib.rs'), 'BROKEN\n');
    const panel = tab.locator('#devloop-errors');
    await panel.locator('pre', { hasText: 'src/exercises/transforms.rs:42:5' }).waitFor();
    const shown = await panel.textContent();
    assert.match(shown, /The build failed\..*still runs the previous build/);
    assert.match(shown, /expected `Result<Mat4, NotDone>`, found `Mat4`/);
    assert.doesNotMatch(shown, /unused import|Compiling/);
    assert.equal(await tab.evaluate(() => window.marker), 'loaded once');
    assert.equal(await tab.locator('#devloop-building').count(), 0);
    const failed = await status();
    assert.equal(failed.builds, 1);
    assert.deepEqual(failed.last, { kind: 'rust', ok: false });

    // A page edit while the Rust is still broken: the page reloads with the new text and the
    // errors are still shown.
    let reloaded = tab.waitForEvent('load');
    writeFileSync(join(dir, 'www/page.html'), page('version 2'));
    await reloaded;
    await watching();
    assert.equal(await tab.locator('#version').textContent(), 'version 2');
    await panel.locator('pre', { hasText: 'src/exercises/transforms.rs:42:5' }).waitFor();

    // The fix: the page reloads and the panel is gone.
    await tab.evaluate(() => { window.marker = 'loaded twice'; });
    reloaded = tab.waitForEvent('load');
    writeFileSync(join(dir, 'src/lib.rs'), '// fixed\n');
    await reloaded;
    await watching();
    assert.equal(await tab.evaluate(() => window.marker), undefined);
    assert.equal(await panel.count(), 0);
    const fixed = await status();
    assert.equal(fixed.errors, '');
    assert.deepEqual(fixed.last, { kind: 'rust', ok: true });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
    server.kill();
    rmSync(dir, { recursive: true, force: true });
  }
});
