// Rebuild, Close and Offset from the toolbar and the keyboard (Shift+R, C, Shift+O) in Debian's
// chromium against a real `hula serve`: every result is checked over the API, never by the page's
// own numbers, and each tool is one undo step.
import { test, type Page } from '@playwright/test';
import type { CurveFile } from '../src/api/types';
import {
  addCurve,
  analysis,
  api,
  curves,
  distanceToPolyline,
  entity,
  expect,
  idle,
  needsDocuments,
  newDoc,
  openApp,
} from './fixtures';
import { arch } from '../src/testing/curves';

type Nurbs = Extract<CurveFile, { kind: 'nurbs' }>;

// An open spline through five points, to be closed.
const through: CurveFile = {
  kind: 'interpolated',
  points: [
    [0, 60, 0],
    [20, 80, 0],
    [45, 75, 0],
    [50, 55, 0],
    [25, 45, 0],
  ],
};

const status = (page: Page) => page.locator('#status');

async function applied(doc: string): Promise<string[]> {
  const h = await api<{ history: { name: string; applied: boolean }[] }>(
    'GET',
    `/api/documents/${encodeURIComponent(doc)}/history`,
  );
  return h.history.filter((s) => s.applied).map((s) => s.name);
}

async function select(page: Page, label: string): Promise<void> {
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
}

/** Fill the open dialog's fields by name and press OK. */
async function fillDialog(page: Page, fields: Record<string, string>): Promise<void> {
  const dialog = page.locator('dialog[open]');
  await expect(dialog).toBeVisible();
  for (const [name, value] of Object.entries(fields))
    await dialog.locator(`input[name="${name}"]`).fill(value);
  await dialog.locator('button[value="ok"]').click();
}

test('rebuild, close and offset the selected curve, then undo each', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('tools26');
  const a = await addCurve(doc, 'arch', arch);
  const b = await addCurve(doc, 'loop', through);
  await openApp(page, doc);
  const original = (await analysis(doc, a, { samples: 2001 })).points;
  const steps = (await applied(doc)).length;

  // Rebuild (toolbar button): degree 3 on 9 control points. The stored curve has 9 control points
  // and degree 3; the deviation the status shows is the server's, and the rebuilt curve's samples
  // lie within it of the original (measured here against 2,001 samples of the original).
  await select(page, a);
  await page.getByRole('button', { name: 'Rebuild curve (Shift+R)' }).click();
  await fillDialog(page, { degree: '3', control_points: '9' });
  await expect(status(page)).toContainText('Rebuilt arch');
  const rebuilt = (await entity(doc, a)).curve as Nurbs;
  expect(rebuilt.kind).toBe('nurbs');
  expect(rebuilt.degree).toBe(3);
  expect(rebuilt.control_points).toHaveLength(9);
  const asked = await api<{ max_deviation: number; control_points: number }>(
    'POST',
    '/api/rebuild',
    {
      curve: arch,
      degree: 3,
      control_points: 9,
    },
  );
  expect(asked.control_points).toBe(9);
  const shown = Number(
    /max deviation ([0-9.e+-]+)/.exec((await status(page).textContent()) ?? '')![1],
  );
  expect(shown).toBeCloseTo(Number(asked.max_deviation.toPrecision(3)), 12);
  const samples = (await analysis(doc, a, { samples: 201 })).points;
  const measured = Math.max(...samples.map((p) => distanceToPolyline(p, original)));
  expect(measured).toBeLessThanOrEqual(asked.max_deviation * 1.01 + 1e-6);
  expect(measured).toBeGreaterThan(asked.max_deviation * 0.5);
  expect(await applied(doc)).toHaveLength(steps + 1);

  // Close (C key): the spline's own points, then back to the first; its first and last points
  // coincide, and it passes through every given point.
  await select(page, b);
  await page.keyboard.press('c');
  await expect(status(page)).toContainText('Closed loop');
  const closed = await analysis(doc, b, { samples: 401, by: 'parameter' });
  const first = closed.points[0]!;
  const lastP = closed.points[closed.points.length - 1]!;
  expect(Math.hypot(...first.map((x, k) => x - lastP[k]!))).toBeLessThan(1e-9);
  for (const p of (through as { points: number[][] }).points)
    expect(distanceToPolyline(p, closed.points)).toBeLessThan(0.05);
  // C2 at the closure: the same tangent at both ends.
  const t0 = closed.frames[0]!.T;
  const t1 = closed.frames[closed.frames.length - 1]!.T;
  expect(Math.hypot(...t0.map((x, k) => x - t1[k]!))).toBeLessThan(1e-9);
  expect(await applied(doc)).toHaveLength(steps + 2);

  // Offset (Shift+O) of the rebuilt arch by 4: a new curve, selected, every sample of which is
  // 4 from the arch (within the server's tolerance and the 2,001-sample polyline's chord error).
  await select(page, a);
  const beforeOffset = (await analysis(doc, a, { samples: 2001 })).points;
  await page.keyboard.press('Shift+O');
  await fillDialog(page, { distance: '4' });
  await expect(status(page)).toContainText('Offset');
  await expect.poll(async () => (await curves(doc)).length).toBe(3);
  const made = (await curves(doc)).find((e) => e.label !== a && e.label !== b)!;
  expect(await page.evaluate(() => window.__hula.app.editor.selected)).toBe(String(made.label));
  const off = (await analysis(doc, String(made.label), { samples: 301 })).points;
  const d = off.map((p) => distanceToPolyline(p, beforeOffset));
  expect(Math.min(...d)).toBeGreaterThan(4 - 1e-3);
  expect(Math.max(...d)).toBeLessThan(4 + 1e-3);
  expect(await applied(doc)).toHaveLength(steps + 3);

  // Undo three times: the offset goes, the loop is open again, the arch has its own poles.
  for (const n of [2, 2, 2]) {
    await idle(page);
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await curves(doc)).length).toBe(n);
  }
  await expect
    .poll(async () => ((await entity(doc, a)).curve as Nurbs).control_points)
    .toEqual(arch.control_points);
  expect(((await entity(doc, a)).curve as Nurbs).knots).toEqual(arch.knots);
  await expect.poll(async () => (await entity(doc, b)).curve?.kind).toBe('interpolated');
  expect(await applied(doc)).toHaveLength(steps);
});
