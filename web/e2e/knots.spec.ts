// Knot insertion and degree elevation from the toolbar (the Knot and Degree buttons) and STEP
// import in Debian's chromium against a real `hula serve`: checked over the API.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from '@playwright/test';
import type { CurveFile } from '../src/api/types';
import {
  addCurve,
  analysis,
  api,
  curves,
  entity,
  expect,
  idle,
  needsDocuments,
  newDoc,
  openApp,
} from './fixtures';
import { hulaBinary } from './server';

const cubic: CurveFile = {
  kind: 'nurbs',
  degree: 3,
  knots: [0, 0, 0, 0, 0.25, 1, 1, 1, 1],
  control_points: [
    [0, 0, 0],
    [20, 30, 0],
    [50, 40, 10],
    [80, 10, 20],
    [100, 0, 30],
  ],
};

type Nurbs = Extract<CurveFile, { kind: 'nurbs' }>;

/** Max distance between the curve's points at 101 parameters before and after. */
async function shapeChange(doc: string, label: string, before: number[][]): Promise<number> {
  const after = (await analysis(doc, label, { samples: 101, by: 'parameter' })).points;
  expect(after).toHaveLength(before.length);
  return Math.max(...before.map((p, i) => Math.hypot(...p.map((x, k) => x - after[i]![k]!))));
}

// The Knot button adds one control point mid-span (0.625, the middle of [0.25, 1]) without moving
// the curve (1e-9 at 101 parameters); the Degree button raises the degree by one, likewise; undo
// twice restores the original control points and knots exactly.
test('insert a knot and elevate the degree of the selected curve, then undo', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('knots');
  const label = await addCurve(doc, 'cubic', cubic);
  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
  const before = (await analysis(doc, label, { samples: 101, by: 'parameter' })).points;

  await page.getByRole('button', { name: 'Insert knot (U)' }).click();
  await expect
    .poll(async () => ((await entity(doc, label)).curve as Nurbs).control_points.length)
    .toBe(6);
  expect(((await entity(doc, label)).curve as Nurbs).knots).toContain(0.625);
  expect(await shapeChange(doc, label, before)).toBeLessThan(1e-9);

  await page.getByRole('button', { name: 'Elevate degree (D)' }).click();
  await expect.poll(async () => ((await entity(doc, label)).curve as Nurbs).degree).toBe(4);
  expect(await shapeChange(doc, label, before)).toBeLessThan(1e-9);

  await page.keyboard.press('Control+z');
  await page.keyboard.press('Control+z');
  await expect
    .poll(async () => ((await entity(doc, label)).curve as Nurbs).control_points)
    .toEqual(cubic.control_points);
  expect(((await entity(doc, label)).curve as Nurbs).knots).toEqual(cubic.knots);
  const steps = await api<{ history: { name: string; applied: boolean }[] }>(
    'GET',
    `/api/documents/${encodeURIComponent(doc)}/history`,
  );
  expect(steps.history.map((h) => [h.name, h.applied])).toEqual([
    ['add curve', true],
    ['insert knot', false],
    ['elevate degree', false],
  ]);
});

// A STEP file (written by `hula doc export --format step` from the cubic above) picked in the
// Import file chooser becomes one NURBS entity through the server's exchange helper, with the
// cubic's control points (1e-9) and provenance import:step; the page selects it.
test('import a STEP file', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('step');
  await openApp(page, doc);
  const dir = mkdtempSync(join(tmpdir(), 'hula-step-'));
  const curveFile = join(dir, 'cubic.json');
  writeFileSync(curveFile, JSON.stringify(cubic));
  const scratch = join(dir, 's.hula');
  const step = join(dir, 'cubic.step');
  for (const args of [
    ['new', scratch],
    ['add', scratch, '--curve', curveFile],
    ['export', scratch, '1', '--format', 'step', '-o', step],
  ])
    execFileSync(hulaBinary(), ['doc', ...args]);
  await page.locator('#import-file').setInputFiles({
    name: 'cubic.step',
    mimeType: 'application/step',
    buffer: readFileSync(step),
  });
  rmSync(dir, { recursive: true });
  await expect.poll(async () => (await curves(doc)).length).toBe(1);
  await idle(page);
  const [e] = await curves(doc);
  const c = e!.curve as Nurbs;
  expect(c.control_points).toHaveLength(cubic.control_points.length);
  c.control_points.forEach((p, i) => {
    expect(Math.hypot(...p.map((x, k) => x - cubic.control_points[i]![k]!))).toBeLessThan(1e-9);
  });
  const raw = await api<{ provenance: { operation: string } }>(
    'GET',
    `/api/documents/${encodeURIComponent(doc)}/entities/${encodeURIComponent(String(e!.label))}`,
  );
  expect(raw.provenance.operation).toBe('import:step');
  expect(await page.evaluate(() => window.__hula.app.selected)).toBe(String(e!.label));
});
