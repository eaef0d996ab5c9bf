import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { schemaTypes } from './openapi-types';

// The page's server types against the server's own contract (GET /api/openapi.json, the file the server
// embeds): src/api/openapi.ts is generated from it, and types.ts builds the page's API types on the
// generated ones (the compile-time checks at its end refuse a member the server does not send).

const openapi = new URL('../../../src/hula/server/openapi.json', import.meta.url);
const generated = new URL('./openapi.ts', import.meta.url);

describe('the API contract', () => {
  // checks the committed types are the ones the OpenAPI document gives (regenerate with HULA_REBASELINE=1)
  it('keeps src/api/openapi.ts generated from the OpenAPI document', () => {
    const text = schemaTypes(JSON.parse(readFileSync(openapi, 'utf8')) as unknown);
    if (process.env['HULA_REBASELINE'] === '1') writeFileSync(generated, text);
    expect(readFileSync(generated, 'utf8')).toBe(text);
  });

  // checks the generator on a schema of each kind the document uses
  it('writes objects, arrays, unions, enums and references', () => {
    const text = schemaTypes({
      components: {
        schemas: {
          A: {
            type: 'object',
            additionalProperties: false,
            required: ['x'],
            properties: {
              x: { type: 'array', items: { oneOf: [{ type: 'number' }, { type: 'null' }] } },
              k: { enum: ['a', 'b'] },
              r: { $ref: '#/components/schemas/B' },
              n: { type: ['integer', 'null'] },
            },
          },
          B: { type: 'object', properties: { y: { type: 'string' } } },
        },
      },
    });
    expect(text).toContain(
      'export type A = {\n  x: (number | null)[];\n  k?: "a" | "b";\n  r?: B;\n  n?: number | null;\n};',
    );
    expect(text).toContain('export type B = {\n  y?: string;\n  [key: string]: unknown;\n};');
  });
});
