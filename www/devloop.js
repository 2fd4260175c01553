// The live dev loop, page side: when the page comes from `scripts/serve` (node scripts/serve.mjs
// --watch), it reloads itself after each successful rebuild, and while a build has failed it shows
// the compiler's errors in a panel (the server keeps serving the previous build meanwhile).
//
// The watching server marks the HTML it serves with <meta name="inbetween-devloop" content="…">;
// without that tag (static serving, the tests) this module does nothing and makes no request.
// Import it for its effect: `import './devloop.js';`.

const meta = document.querySelector('meta[name="inbetween-devloop"]');
if (meta) connect(meta.content);

function connect(base) {
  const events = new EventSource(`${base}/events`);
  let seen = null; // the first status received: what this page was loaded with
  events.onmessage = (message) => {
    const status = JSON.parse(message.data);
    seen ??= status;
    document.documentElement.dataset.devloop = 'watching';
    const rebuilt = status.session !== seen.session || status.builds > seen.builds;
    if (rebuilt && status.building === null && status.last?.ok !== false) {
      // A restarted server (new session) has just built everything: reload as well.
      events.close();
      location.reload();
      return;
    }
    showBuilding(status.building);
    if (status.errors) showErrors(status.errors);
    else hideErrors();
  };
  // EventSource reconnects by itself when the server comes back; nothing to do here.
}

const STYLE = `
#devloop-errors {
  position: fixed; left: 1rem; right: 1rem; bottom: 1rem; z-index: 1000; max-height: 60vh;
  display: flex; flex-direction: column; background: #1f2430; color: #f3f4f6; border-radius: 8px;
  border-left: 6px solid #e02424; box-shadow: 0 8px 30px rgba(0, 0, 0, 0.35); font: 15px/1.5 system-ui, sans-serif;
}
#devloop-errors header { display: flex; gap: 1rem; align-items: baseline; padding: 0.6rem 1rem; }
#devloop-errors strong { color: #f98080; }
#devloop-errors button { margin-left: auto; }
#devloop-errors pre {
  margin: 0; padding: 0.6rem 1rem 1rem; overflow: auto; background: none; color: inherit; border-radius: 0;
  font: 13px/1.45 ui-monospace, Menlo, monospace; white-space: pre;
}
#devloop-building {
  position: fixed; right: 1rem; bottom: 1rem; z-index: 1001; background: #1f2430; color: white;
  font: 600 13px system-ui, sans-serif; padding: 0.3rem 0.7rem; border-radius: 999px; opacity: 0.85;
}
`;

function ensureStyle() {
  if (document.getElementById('devloop-style')) return;
  const style = document.createElement('style');
  style.id = 'devloop-style';
  style.textContent = STYLE;
  document.head.append(style);
}

function showErrors(text) {
  ensureStyle();
  let panel = document.getElementById('devloop-errors');
  if (!panel) {
    panel = document.createElement('section');
    panel.id = 'devloop-errors';
    panel.setAttribute('role', 'alert');
    panel.innerHTML = '<header><strong>The build failed.</strong><span>This page still runs the previous ' +
      'build; it reloads by itself when a build succeeds.</span><button type="button">hide</button></header><pre></pre>';
    panel.querySelector('button').onclick = () => { panel.hidden = true; };
    document.body.append(panel);
  }
  const pre = panel.querySelector('pre');
  if (pre.textContent !== text) {
    pre.textContent = text;
    panel.hidden = false;
  }
}

function hideErrors() {
  document.getElementById('devloop-errors')?.remove();
}

function showBuilding(kind) {
  let badge = document.getElementById('devloop-building');
  if (!kind) {
    badge?.remove();
    return;
  }
  ensureStyle();
  if (!badge) {
    badge = document.createElement('div');
    badge.id = 'devloop-building';
    badge.setAttribute('role', 'status');
    document.body.append(badge);
  }
  badge.textContent = kind === 'rust' ? 'rebuilding the wasm…' : 'copying the pages…';
}
