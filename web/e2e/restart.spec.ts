// A server restart mid-session loses nothing: the page reconnects, reloads
// the document's revision and keeps editing (its own server, own workspace).
import { test } from '@playwright/test';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { randomBytes } from 'node:crypto';
import { expect, idle, needsDocuments, openApp } from './fixtures';
import { startServer, stopServer } from './server';

test('the page survives a server restart', async ({ page }) => {
  needsDocuments();
  const workspace = mkdtempSync(join(tmpdir(), 'hula-e2e-restart-'));
  const tokenFile = join(workspace, '..', `hula-e2e-restart-token-${process.pid}`);
  writeFileSync(tokenFile, randomBytes(32).toString('hex'), { mode: 0o600 });
  let s = await startServer(workspace, tokenFile);
  try {
    const doc = 'restart.hula';
    await openApp(page, doc, s.base, s.token);
    await page.keyboard.press('b');
    const click = async (x: number, y: number): Promise<void> => {
      const r = await page.evaluate(
        ([x, y]) => {
          const vp = window.__hula.app.viewports;
          const m = vp.viewProj('top');
          const el = vp.view('top').el.getBoundingClientRect();
          const cx = m[0]! * x + m[4]! * y + m[12]!;
          const cy = m[1]! * x + m[5]! * y + m[13]!;
          return { x: el.left + ((cx + 1) / 2) * el.width, y: el.top + ((1 - cy) / 2) * el.height };
        },
        [x, y] as const,
      );
      await page.mouse.click(r.x, r.y);
    };
    await click(0, 0);
    await click(40, 30);
    await click(80, 0);
    await page.keyboard.press('Enter');
    await idle(page);
    const revision = await page.evaluate(() => window.__hula.app.store.revision);
    await stopServer(s, 'SIGKILL');
    await expect(page.locator('#status')).toHaveClass(/offline/, { timeout: 15_000 });
    s = await startServer(workspace, tokenFile, s.port);
    await expect(page.locator('#status')).toContainText('Reconnected', { timeout: 20_000 });
    await idle(page);
    expect(await page.evaluate(() => window.__hula.app.store.revision)).toBe(revision);
    expect(await page.evaluate(() => window.__hula.app.store.entities.size)).toBe(1);
    // Editing goes on after the restart.
    await page.keyboard.press('Control+z');
    await idle(page);
    expect(await page.evaluate(() => window.__hula.app.store.entities.size)).toBe(0);
  } finally {
    await stopServer(s);
  }
});
