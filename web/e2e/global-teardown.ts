// Stop the server started by global-setup.ts.
import { stopServer, type Served } from './server';

export default async function globalTeardown(): Promise<void> {
  const s = (globalThis as { __hulaServed?: Served }).__hulaServed;
  if (s) await stopServer(s);
}
