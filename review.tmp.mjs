// Student-review screenshots (temporary, not committed).
import { launch, openPage } from './tests/e2e/browser.mjs';
import { startServer } from './scripts/serve.mjs';
const [lesson, size, profile = 'webgl2', ...steps] = process.argv.slice(2);
const [w, h] = size.split('x').map(Number);
const server = await startServer(process.env.INBETWEEN_DIST ?? 'dist', 0);
const origin = `http://127.0.0.1:${server.address().port}`;
const ctx = await launch(profile);
const { page, problems } = await openPage(ctx, `${origin}/lessons/${lesson}/`, { width: w, height: h });
await page.waitForTimeout(1500);
const out = `/tmp/rev/${lesson.slice(0, 3)}-${w}`;
// Steps: "set:#fig:label:value" sets a lil-gui controller by its name; "shot:#fig:name"; "page:name"; "wait:ms"; "eval:js"
for (const step of steps) {
  const [kind, ...rest] = step.split('|');
  if (kind === 'set') {
    const [fig, name, value] = rest;
    await page.evaluate(([fig, name, value]) => {
      const el = document.querySelector(fig);
      for (const row of el.querySelectorAll('.lil-gui .lil-controller')) {
        if (row.querySelector('.lil-name')?.textContent.trim() !== name) continue;
        const input = row.querySelector('input, select');
        if (input.type === 'checkbox') { input.checked = value === 'true'; input.dispatchEvent(new Event('change')); }
        else if (input.tagName === 'SELECT') { const opt = [...input.options].find((o) => o.textContent === value || o.value === value); input.value = opt.value; input.dispatchEvent(new Event('change')); }
        else { input.value = value; input.dispatchEvent(new Event('input')); input.dispatchEvent(new Event('change')); input.dispatchEvent(new Event('blur')); }
        return;
      }
      throw new Error(`no control ${name} in ${fig}`);
    }, [fig, name, value]);
    await page.waitForTimeout(300);
  } else if (kind === 'shot') {
    const [fig, name] = rest;
    const loc = page.locator(fig);
    await loc.scrollIntoViewIfNeeded();
    await page.waitForTimeout(400);
    await loc.screenshot({ path: `${out}-${name}.png` });
  } else if (kind === 'page') {
    await page.screenshot({ path: `${out}-${rest[0]}.png`, fullPage: true });
  } else if (kind === 'wait') {
    await page.waitForTimeout(Number(rest[0]));
  } else if (kind === 'eval') {
    console.log(await page.evaluate(rest.join('|')));
  } else if (kind === 'text') {
    console.log(rest[0], ':', await page.locator(rest[0]).innerText());
  }
}
console.log('problems:', problems);
await ctx.close();
server.close();
