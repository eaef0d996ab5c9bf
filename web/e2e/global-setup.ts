// Start one `hula serve` on a temporary workspace for the whole run; its
// address and token go to the tests through environment variables.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { randomBytes } from 'node:crypto';
import { startServer, type Served } from './server';

export default async function globalSetup(): Promise<void> {
  const workspace = mkdtempSync(join(tmpdir(), 'hula-e2e-'));
  const tokenFile = join(workspace, '..', `hula-e2e-token-${process.pid}`);
  writeFileSync(tokenFile, randomBytes(32).toString('hex'), { mode: 0o600 });
  const served = await startServer(workspace, tokenFile);
  process.env['HULA_E2E_BASE'] = served.base;
  process.env['HULA_E2E_TOKEN'] = served.token;
  process.env['HULA_E2E_WORKSPACE'] = workspace;
  process.env['HULA_E2E_PID'] = String(served.proc.pid);
  // Whether this server has the document routes yet (issue 12): the tests
  // that need them are reported as skipped, by name, when it has not.
  const probe = await fetch(`${served.base}/api/documents`, {
    headers: { Authorization: `Bearer ${served.token}` },
  });
  process.env['HULA_E2E_DOCUMENTS'] = probe.status === 404 ? '0' : '1';
  // The teardown runs in the same process and stops it.
  (globalThis as { __hulaServed?: Served }).__hulaServed = served;
}
