// Makes the JavaScript glue that wasm-bindgen writes refuse arguments of the wrong JavaScript type.
//
//   node scripts/strict-glue.mjs dist/pkg/inbetween.js     (scripts/build runs it on every module)
//
// wasm-bindgen hands an `f32` or `f64` argument to WebAssembly as it comes, so JavaScript's own
// conversion applies: "5" becomes 5, true 1, null 0, and a string such as "12" passed for a
// `&[f32]` becomes the array [1, 2]. A binding then accepts a value its caller never meant. This
// script puts a check in front of every exported function and method for each parameter the glue
// documents as `{number}` (a `typeof` test: NaN and ±Infinity are numbers, and the Rust side
// rejects them with its own message) or as `{Float32Array | number[]}` / `{Float64Array |
// number[]}` (that typed array, or an Array whose items are all numbers). A wrong type throws a TypeError naming the function, the
// parameter and what it got; nothing reaches the module.
//
// It reads the glue's own JSDoc (`@param {type} name`, which wasm-bindgen writes for every
// parameter) and the signature line that follows it, and fails loudly when a documented parameter
// is not in that signature, so a change in wasm-bindgen's output cannot pass unchecked.
import { readFileSync, writeFileSync } from 'node:fs';

const CHECKS = {
  number: (name, where) =>
    `if (typeof ${name} !== 'number') throw new TypeError(\`${where}: ${name} must be a number, got \${__describe(${name})}\`);`,
  'Float32Array | number[]': (name, where) =>
    `if (!(${name} instanceof Float32Array) && !(Array.isArray(${name}) && ${name}.every((v) => typeof v === 'number'))) throw new TypeError(\`${where}: ${name} must be a Float32Array or an array of numbers, got \${__describe(${name})}\`);`,
  'Float64Array | number[]': (name, where) =>
    `if (!(${name} instanceof Float64Array) && !(Array.isArray(${name}) && ${name}.every((v) => typeof v === 'number'))) throw new TypeError(\`${where}: ${name} must be a Float64Array or an array of numbers, got \${__describe(${name})}\`);`,
};

const DESCRIBE = `
/** A short description of a rejected argument, for the TypeErrors of the checks above each binding. */
function __describe(value) {
    if (typeof value === 'string') return \`the string \${JSON.stringify(value.length > 40 ? value.slice(0, 40) + '…' : value)}\`;
    if (value === null) return 'null';
    if (Array.isArray(value)) return 'an array';
    if (typeof value === 'object') return \`an object (\${Object.prototype.toString.call(value).slice(8, -1)})\`;
    return \`\${typeof value} \${String(value)}\`;
}
`;

/** The hardened glue and the number of checks it holds. */
export function harden(source) {
  const lines = source.split('\n');
  const out = [];
  let className = null;
  let params = null; // [type, name] pairs of the JSDoc block just read
  let checks = 0;
  for (let i = 0; i < lines.length; i++) {
    const line = lines[i];
    out.push(line);
    const cls = /^export class (\w+)/.exec(line);
    if (cls) className = cls[1];
    if (/^}/.test(line)) className = null;
    if (/^\s*\/\*\*/.test(line)) params = [];
    const param = /^\s*\* @param \{([^}]*)\} (\w+)/.exec(line);
    if (param && params) params.push([param[1], param[2]]);
    if (/\*\/\s*$/.test(line) && params) {
      // The signature follows the JSDoc block.
      const next = lines[i + 1] ?? '';
      const sig = /^(\s*)(?:export\s+)?(?:static\s+)?(?:async\s+)?(?:function\s+)?(\w+)\(([^)]*)\) \{$/.exec(next);
      const wanted = params.filter(([type]) => CHECKS[type]);
      params = null;
      if (!sig) {
        if (wanted.length) throw new Error(`strict-glue: no signature after the JSDoc above line ${i + 2}: ${next}`);
        continue;
      }
      const [, indent, fname, list] = sig;
      const names = list.split(',').map((s) => s.trim()).filter(Boolean);
      const where = fname === 'constructor' ? `new ${className}` : className && !/^export function/.test(next) ? `${className}.${fname}` : fname;
      out.push(next);
      i++;
      for (const [type, name] of wanted) {
        if (!names.includes(name)) throw new Error(`strict-glue: ${where} documents ${name}, which its signature (${list}) lacks`);
        out.push(`${indent}    ${CHECKS[type](name, where)}`);
        checks++;
      }
    }
  }
  return { source: out.join('\n') + DESCRIBE, checks };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  for (const file of process.argv.slice(2)) {
    const { source, checks } = harden(readFileSync(file, 'utf8'));
    writeFileSync(file, source);
    console.log(`strict-glue: ${file}: ${checks} argument checks`);
  }
}
