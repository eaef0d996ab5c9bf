// Fails when the page's modules import each other in a cycle at run time.
// Reads every .ts module under src/ (tests excepted), follows its relative
// imports (`import ... from './x'`, `export ... from './x'`, `import('./x')`)
// and reports each cycle by its modules. Type-only imports (`import type`,
// `export type`) are erased by the compiler and load nothing, so they are not
// edges: a panel may name App's type, never import a value from app.ts.
// Run: node scripts/check-cycles.mjs (npm run check:cycles; CI runs it).
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..', 'src');

function modules(dir) {
  const out = [];
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) out.push(...modules(p));
    else if (name.endsWith('.ts') && !name.endsWith('.test.ts') && !name.endsWith('.d.ts'))
      out.push(p);
  }
  return out;
}

const IMPORT =
  /(?:^|\n)\s*(import|export)(\s+type)?\b[^'";]*?\bfrom\s*['"](\.[^'"]+)['"]|import\(\s*['"](\.[^'"]+)['"]\s*\)/g;

/** The relative run-time imports of a module, as module paths (each once). */
export function importsOf(file, text) {
  const out = new Set();
  for (const m of text.matchAll(IMPORT)) {
    if (m[2]) continue; // import type / export type: nothing is loaded
    const spec = m[3] ?? m[4];
    let target = resolve(dirname(file), spec);
    if (!target.endsWith('.ts')) target += '.ts';
    out.add(target);
  }
  return [...out];
}

/** Every elementary cycle found by a depth-first search, each as a list of modules. */
export function cycles(graph) {
  const found = [];
  const state = new Map(); // 1 on the stack, 2 done
  const stack = [];
  const visit = (n) => {
    state.set(n, 1);
    stack.push(n);
    for (const m of graph.get(n) ?? []) {
      if (state.get(m) === 1) found.push([...stack.slice(stack.indexOf(m)), m]);
      else if (!state.has(m)) visit(m);
    }
    stack.pop();
    state.set(n, 2);
  };
  for (const n of [...graph.keys()].sort()) if (!state.has(n)) visit(n);
  return found;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const graph = new Map();
  for (const f of modules(root)) graph.set(f, importsOf(f, readFileSync(f, 'utf8')));
  const found = cycles(graph);
  for (const c of found)
    console.error(`import cycle: ${c.map((f) => relative(root, f)).join(' → ')}`);
  if (found.length > 0) process.exit(1);
  console.log(`no import cycle among ${graph.size} modules`);
}
