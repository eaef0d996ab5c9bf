// Start and stop a real `hula serve` for the e2e tests (never a mock).
import { spawn, type ChildProcess } from 'node:child_process';
import { existsSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
export const repoRoot = resolve(here, '..', '..');

/** The hula binary: $HULA_BIN, else the ci build, else the release build. */
export function hulaBinary(): string {
  const candidates = [
    process.env['HULA_BIN'],
    resolve(repoRoot, 'build/ci/apps/hula/hula'),
    resolve(repoRoot, 'build/release/apps/hula/hula'),
  ].filter((p): p is string => typeof p === 'string' && p.length > 0);
  const found = candidates.find((p) => existsSync(p));
  if (!found)
    throw new Error(`no hula binary (tried ${candidates.join(', ')}); build it or set HULA_BIN`);
  return found;
}

export interface Served {
  proc: ChildProcess;
  url: string;
  port: number;
  token: string;
  base: string;
}

/** The one JSON line `hula serve` prints on start (issue 12). */
interface StartLine {
  url: string;
  port: number;
  token: string;
}

/**
 * Start `hula serve --workspace DIR --port PORT --token-file F` on loopback,
 * wait for its start line (20 s at most) and return it.
 */
export function startServer(workspace: string, tokenFile: string, port = 0): Promise<Served> {
  const bin = hulaBinary();
  const staticDir = resolve(here, '..', 'dist');
  const proc = spawn(
    bin,
    [
      'serve',
      '--workspace',
      workspace,
      '--host',
      '127.0.0.1',
      '--port',
      String(port),
      '--token-file',
      tokenFile,
      '--static',
      staticDir,
      '--jobs',
      '1',
    ],
    { stdio: ['ignore', 'pipe', 'pipe'] },
  );
  return new Promise((resolvePromise, reject) => {
    let out = '';
    let err = '';
    const timer = setTimeout(() => {
      proc.kill('SIGKILL');
      reject(new Error(`hula serve printed no start line in 20 s; stderr: ${err.slice(-2000)}`));
    }, 20_000);
    proc.stderr.on('data', (d: Buffer) => {
      err += d.toString();
      if (err.length > 100_000) err = err.slice(-50_000);
    });
    proc.stdout.on('data', (d: Buffer) => {
      out += d.toString();
      const nl = out.indexOf('\n');
      if (nl < 0) return;
      clearTimeout(timer);
      const line = JSON.parse(out.slice(0, nl)) as StartLine;
      resolvePromise({
        proc,
        url: line.url,
        port: line.port,
        token: line.token,
        base: `http://127.0.0.1:${line.port}`,
      });
    });
    proc.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`hula serve exited with ${code}; stderr: ${err.slice(-2000)}`));
    });
  });
}

/** SIGTERM, then wait for the exit (SIGKILL after 10 s). */
export async function stopServer(s: Served, signal: NodeJS.Signals = 'SIGTERM'): Promise<void> {
  if (s.proc.exitCode !== null) return;
  const exited = new Promise<void>((r) =>
    s.proc.once('exit', () => {
      r();
    }),
  );
  s.proc.kill(signal);
  const timer = setTimeout(() => s.proc.kill('SIGKILL'), 10_000);
  await exited;
  clearTimeout(timer);
}
