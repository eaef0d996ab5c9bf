// Load the thesis's curves (examples/workspace/*.json) into the document
// thesis.hula of a running `hula serve`, once: a document that already exists
// is left as it is. Usage: node seed-workspace.mjs BASE_URL TOKEN CURVE_DIR
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

const [base, token, dir] = process.argv.slice(2);
if (!base || !token || !dir) {
  console.error('usage: node seed-workspace.mjs BASE_URL TOKEN CURVE_DIR');
  process.exit(2);
}
const doc = 'thesis.hula';
const call = async (method, path, body) => {
  const r = await fetch(base + path, {
    method,
    headers: { Authorization: `Bearer ${token}`, 'Content-Type': 'application/json' },
    ...(body === undefined ? {} : { body: JSON.stringify(body) }),
  });
  const text = await r.text();
  return { status: r.status, body: text ? JSON.parse(text) : null };
};

const existing = await call('GET', `/api/documents/${doc}`);
if (existing.status === 200) {
  console.error(`seed: ${doc} exists (revision ${existing.body.revision}), left as it is`);
  process.exit(0);
}
const created = await call('POST', '/api/documents', { name: doc });
if (created.status >= 300) {
  console.error(`seed: creating ${doc} failed: ${JSON.stringify(created.body)}`);
  process.exit(1);
}
for (const f of readdirSync(dir)
  .filter((n) => n.endsWith('.json'))
  .sort()) {
  const curve = JSON.parse(readFileSync(join(dir, f), 'utf8'));
  delete curve.comment;
  const r = await call('POST', `/api/documents/${doc}/entities`, {
    name: f.replace(/\.json$/, ''),
    curve,
  });
  if (r.status >= 300) {
    console.error(`seed: ${f}: ${JSON.stringify(r.body)}`);
    process.exit(1);
  }
}
console.error(`seed: ${doc} holds the thesis's curves`);
