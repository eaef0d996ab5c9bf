// Issue 23 defects 2 and 3, each on its own server and workspace: a drag
// while the server is down reverts visibly to the stored curve (and stays so
// when the server is back); a restart with a new token is told apart from an
// unreachable server and the page re-opens at the address the server printed.
import { test, type Page } from '@playwright/test';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { randomBytes } from 'node:crypto';
import { expect, idle, needsDocuments, openApp, pixelOf, shot } from './fixtures';
import { startServer, stopServer, type Served } from './server';

function workspace(tag: string): { dir: string; tokenFile: string } {
  const dir = mkdtempSync(join(tmpdir(), `hula-e2e-${tag}-`));
  const tokenFile = join(dir, '..', `hula-e2e-${tag}-token-${process.pid}-${Date.now()}`);
  writeFileSync(tokenFile, randomBytes(32).toString('hex'), { mode: 0o600 });
  return { dir, tokenFile };
}

async function put(s: Served, doc: string): Promise<string> {
  const h = { Authorization: `Bearer ${s.token}`, 'Content-Type': 'application/json' };
  await fetch(`${s.base}/api/documents`, {
    method: 'POST',
    headers: h,
    body: JSON.stringify({ name: doc }),
  });
  const r = await fetch(`${s.base}/api/documents/${doc}/entities`, {
    method: 'POST',
    headers: h,
    body: JSON.stringify({
      name: 'arch',
      curve: {
        kind: 'bezier',
        control_points: [
          [0, 0, 0],
          [40, 40, 0],
          [80, 0, 0],
        ],
        weights: null,
      },
    }),
  });
  return String(((await r.json()) as { label: number }).label);
}

/** The curve as the page draws it: its analysed points (the drag's preview or the stored analysis). */
const drawn = (page: Page, label: string): Promise<number[][]> =>
  page.evaluate((l) => window.__hula.app.analysisOf(l)!.points, label);

test('a drag while the server is down reverts to the stored curve, and stays so', async ({
  page,
}) => {
  needsDocuments();
  await page.setViewportSize({ width: 1280, height: 720 });
  const w = workspace('offline');
  let s = await startServer(w.dir, w.tokenFile);
  try {
    const doc = 'offline.hula';
    const label = await put(s, doc);
    await openApp(page, doc, s.base, s.token);
    await page.evaluate((l) => {
      window.__hula.app.select(l);
    }, label);
    await idle(page);
    const stored = await drawn(page, label);
    const graph0 = await page.evaluate(() => Array.from(window.__hula.app.graphs[0]!.ys));
    await stopServer(s, 'SIGKILL');
    const from = await pixelOf(page, 'top', [40, 40, 0]);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(from.x + 4 * i, from.y + 3 * i);
    await page.mouse.up();
    // The curve, its graph and its handles are back as stored; the status says the move was not stored.
    await expect(page.locator('#status')).toContainText('was not moved', { timeout: 15_000 });
    await expect(page.locator('#status')).not.toContainText('Moved point');
    expect(await drawn(page, label)).toEqual(stored);
    expect(await page.evaluate(() => Array.from(window.__hula.app.graphs[0]!.ys))).toEqual(graph0);
    await shot(page, 'offline-drag-reverted');
    // The server returns (same port, same token): the page reconnects and the curve is unchanged.
    s = await startServer(w.dir, w.tokenFile, s.port);
    await expect(page.locator('#status')).toContainText('Reconnected', { timeout: 20_000 });
    await idle(page);
    expect(await drawn(page, label)).toEqual(stored);
  } finally {
    await stopServer(s);
  }
});

test('after a restart with a new token the page says so and re-opens at the new address', async ({
  page,
}) => {
  needsDocuments();
  await page.setViewportSize({ width: 1280, height: 720 });
  const w = workspace('token');
  let s = await startServer(w.dir, w.tokenFile);
  try {
    const doc = 'token.hula';
    await put(s, doc);
    await openApp(page, doc, s.base, s.token);
    await stopServer(s, 'SIGKILL');
    await expect(page.locator('#status')).toHaveClass(/offline/, { timeout: 15_000 });
    // The same port, a new token (as a restart without --token-file).
    writeFileSync(w.tokenFile, randomBytes(32).toString('hex'), { mode: 0o600 });
    s = await startServer(w.dir, w.tokenFile, s.port);
    await expect(page.locator('#status')).toContainText('refused this page', { timeout: 20_000 });
    await expect(page.locator('#status')).not.toContainText('reconnecting');
    await expect(page.locator('#reopen')).toBeVisible();
    await shot(page, 'restart-new-token');
    await page.locator('#reopen').click();
    await page.getByRole('textbox', { name: 'Address' }).fill(`${s.base}/?token=${s.token}`);
    await page.getByRole('button', { name: 'OK' }).click();
    await page.waitForURL(/#doc=token\.hula/);
    await idle(page);
    expect(await page.evaluate(() => window.__hula.app.store.entities.size)).toBe(1);
    await expect(page.locator('#reopen')).toBeHidden();
  } finally {
    await stopServer(s);
  }
});

test('a server restarted on another port: the page offers to re-open there', async ({ page }) => {
  needsDocuments();
  await page.setViewportSize({ width: 1600, height: 1000 });
  const w = workspace('port');
  let s = await startServer(w.dir, w.tokenFile);
  try {
    const doc = 'port.hula';
    await put(s, doc);
    await openApp(page, doc, s.base, s.token);
    const old = s.port;
    await stopServer(s, 'SIGKILL');
    s = await startServer(w.dir, w.tokenFile, 0);
    expect(s.port).not.toBe(old);
    await expect(page.locator('#reopen')).toBeVisible({ timeout: 30_000 });
    await expect(page.locator('#status')).toContainText('another port');
    await page.locator('#reopen').click();
    await page.getByRole('textbox', { name: 'Address' }).fill(s.url);
    await page.getByRole('button', { name: 'OK' }).click();
    await page.waitForURL(new RegExp(`:${s.port}/.*#doc=port\\.hula`));
    await idle(page);
    expect(await page.evaluate(() => window.__hula.app.store.entities.size)).toBe(1);
  } finally {
    await stopServer(s);
  }
});
