// TypeScript types generated from the server's OpenAPI document
// (src/hula/server/openapi.json, GET /api/openapi.json): one type per
// component schema. `schemaTypes` writes src/api/openapi.ts; contract.test.ts
// regenerates it and fails when the committed file differs (rebaseline with
// HULA_REBASELINE=1 npx vitest run src/api/contract.test.ts), so the page's
// server types are the server's.

type Schema = Record<string, unknown>;

const HEADER = `// Generated from src/hula/server/openapi.json by src/api/openapi-types.ts; do not edit.
// Regenerate: HULA_REBASELINE=1 npx vitest run src/api/contract.test.ts
`;

const isSchema = (v: unknown): v is Schema =>
  typeof v === 'object' && v !== null && !Array.isArray(v);

function wrap(t: string): string {
  return /[|&]/.test(t) && !/^\{[\s\S]*\}$/.test(t) ? `(${t})` : t;
}

/** The TypeScript type of one JSON schema (the subset the document uses). */
function typeOf(s: unknown, indent: string): string {
  if (!isSchema(s)) return 'unknown';
  const ref = s['$ref'];
  if (typeof ref === 'string') return ref.replace('#/components/schemas/', '');
  for (const key of ['oneOf', 'anyOf'] as const) {
    const list = s[key];
    if (Array.isArray(list)) return [...new Set(list.map((x) => typeOf(x, indent)))].join(' | ');
  }
  const values: unknown = s['enum'];
  if (Array.isArray(values)) return values.map((v: unknown) => JSON.stringify(v)).join(' | ');
  if ('const' in s) return JSON.stringify(s['const']);
  const type: unknown = s['type'];
  if (Array.isArray(type))
    return type.map((t: unknown) => typeOf({ ...s, type: t }, indent)).join(' | ');
  switch (type) {
    case 'string':
      return 'string';
    case 'number':
    case 'integer':
      return 'number';
    case 'boolean':
      return 'boolean';
    case 'null':
      return 'null';
    case 'array':
      return `${wrap(typeOf(s['items'], indent))}[]`;
    case 'object':
      return objectType(s, indent);
    default:
      return isSchema(s['properties']) ? objectType(s, indent) : 'unknown';
  }
}

function objectType(s: Schema, indent: string): string {
  const props = isSchema(s['properties']) ? s['properties'] : {};
  const required = new Set(Array.isArray(s['required']) ? (s['required'] as string[]) : []);
  const inner = `${indent}  `;
  const lines = Object.entries(props).map(
    ([name, p]) =>
      `${inner}${/^[A-Za-z_$][\w$]*$/.test(name) ? name : JSON.stringify(name)}${required.has(name) ? '' : '?'}: ${typeOf(p, inner)};`,
  );
  const extra = s['additionalProperties'];
  if (extra !== false) lines.push(`${inner}[key: string]: unknown;`);
  if (lines.length === 0) return 'Record<string, never>';
  return `{\n${lines.join('\n')}\n${indent}}`;
}

/** The module text: `export type Name = ...;` for every component schema, in the document's order. */
export function schemaTypes(document: unknown): string {
  const components = isSchema(document) ? document['components'] : undefined;
  const schemas =
    isSchema(components) && isSchema(components['schemas']) ? components['schemas'] : {};
  let out = HEADER;
  for (const [name, schema] of Object.entries(schemas))
    out += `\nexport type ${name} = ${typeOf(schema, '')};\n`;
  return out;
}
