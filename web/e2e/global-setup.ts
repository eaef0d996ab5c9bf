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
  // The document routes must answer: a 404 (or any other status) fails the run here instead of
  // letting the tests that need them skip.
  const probe = await fetch(`${served.base}/api/documents`, {
    headers: { Authorization: `Bearer ${served.token}` },
  });
  if (probe.status !== 200) {
    served.proc.kill();
    throw new Error(
      `GET /api/documents answered ${probe.status}, not 200: the e2e tests need the document routes`,
    );
  }
  process.env['HULA_E2E_DOCUMENTS'] = '1';
  // The teardown runs in the same process and stops it.
  (globalThis as { __hulaServed?: Served }).__hulaServed = served;
}
