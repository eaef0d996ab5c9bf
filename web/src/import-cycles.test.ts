import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { cycles, importsOf } from '../scripts/check-cycles.mjs';

describe('the import-cycle check', () => {
  it('follows value imports and re-exports, not type-only ones', () => {
    const text = [
      "import type { App } from '../app';",
      "import { handlesOf } from '../store/curves';",
      "export { x } from './x';",
      "export type { Y } from './y';",
      "const m = import('./lazy');",
    ].join('\n');
    expect(importsOf('/w/src/panels/p.ts', text)).toEqual([
      '/w/src/store/curves.ts',
      '/w/src/panels/x.ts',
      '/w/src/panels/lazy.ts',
    ]);
  });
  it('finds a cycle through several modules and none in a tree', () => {
    const g = new Map([
      ['a', ['b']],
      ['b', ['c']],
      ['c', ['a', 'd']],
      ['d', []],
    ]);
    expect(cycles(g)).toEqual([['a', 'b', 'c', 'a']]);
    g.set('c', ['d']);
    expect(cycles(g)).toEqual([]);
  });
  it('finds no cycle among the page’s modules', () => {
    const root = resolve(import.meta.dirname, '.');
    const files: string[] = [];
    const walk = (dir: string): void => {
      for (const n of readdirSync(dir)) {
        const p = join(dir, n);
        if (statSync(p).isDirectory()) walk(p);
        else if (n.endsWith('.ts') && !n.endsWith('.test.ts')) files.push(p);
      }
    };
    walk(root);
    const graph = new Map(files.map((f) => [f, importsOf(f, readFileSync(f, 'utf8'))]));
    expect(cycles(graph)).toEqual([]);
    // The panels and the fairing tool name the App only as a type (matched below src/, so a
    // checkout whose own path says "tools" does not pull in main.ts).
    for (const f of files.filter((x) => /^[/\\](panels|tools)[/\\]/.test(x.slice(root.length))))
      expect(importsOf(f, readFileSync(f, 'utf8'))).not.toContain(join(root, 'app.ts'));
  });
});
