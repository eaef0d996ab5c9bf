// Export from the toolbar's Export menu (JSON, STEP, IGES, DXF) in Debian's chromium against a
// real `hula serve`: the downloaded STEP and IGES files are read back by `hula doc import` (Open
// CASCADE's reader in the exchange helper), the DXF by dxflib, and compared with the curve the
// document holds.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test, type Page } from '@playwright/test';
import { addCurve, expect, needsDocuments, newDoc, openApp, shot } from './fixtures';
import { hulaBinary } from './server';

// A rational cubic with an inner knot off the middle: weights, knots and points all have to
// survive the trip.
const rail = {
  kind: 'nurbs' as const,
  degree: 3,
  knots: [0, 0, 0, 0, 0.3, 1, 1, 1, 1],
  control_points: [
    [0, 0, 0],
    [10, 20, 0],
    [30, 20, 5],
    [40, 0, 5],
    [55, -3, 2],
  ],
  weights: [1, 1.5, 0.8, 1, 1],
};

interface Shown {
  control_points: number[][];
  knots: number[];
  weights?: number[];
  attributes: { name: string };
  provenance: { operation: string };
}

/** The downloaded file read back by `hula doc import` into a scratch document: its first entity. */
function readBack(file: string): { labels: number[]; first: Shown } {
  const dir = mkdtempSync(join(tmpdir(), 'hula-export-'));
  try {
    const scratch = join(dir, 's.hula');
    execFileSync(hulaBinary(), ['doc', 'new', scratch]);
    const imported = JSON.parse(
      execFileSync(hulaBinary(), ['doc', 'import', scratch, file]).toString(),
    ) as { labels: number[] };
    const first = JSON.parse(
      execFileSync(hulaBinary(), ['doc', 'show', scratch, String(imported.labels[0])]).toString(),
    ) as Shown;
    return { labels: imported.labels, first };
  } finally {
    rmSync(dir, { recursive: true });
  }
}

function expectRail(got: Shown, operation: string): void {
  expect(got.provenance.operation).toBe(operation);
  expect(got.attributes.name).toBe('rail');
  expect(got.control_points).toHaveLength(rail.control_points.length);
  got.control_points.forEach((p, i) => {
    expect(Math.hypot(...p.map((x, k) => x - rail.control_points[i]![k]!))).toBeLessThan(1e-9);
  });
  expect(got.knots).toHaveLength(rail.knots.length);
  got.knots.forEach((u, i) => {
    expect(Math.abs(u - rail.knots[i]!)).toBeLessThan(1e-12);
  });
  expect(got.weights).toHaveLength(rail.weights.length);
  got.weights!.forEach((w, i) => {
    expect(Math.abs(w - rail.weights[i]!)).toBeLessThan(1e-12);
  });
}

async function openWithRail(page: Page, prefix: string): Promise<string> {
  needsDocuments();
  const doc = await newDoc(prefix);
  const label = await addCurve(doc, 'rail', rail);
  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  return label;
}

// The menu by mouse: Export ▾ then STEP gives rail.step, whose one B-spline `hula doc import`
// reads back with the same knots, weights and control points (1e-9) and the curve's name.
test('export STEP from the menu, read back by hula doc import', async ({ page }) => {
  await openWithRail(page, 'export-step');
  await page.getByRole('button', { name: 'Export selected curve (E)' }).click();
  await expect(page.getByRole('menu', { name: 'Export format' })).toBeVisible();
  const box = (await page.locator('#export-button').boundingBox())!;
  await shot(page, 'export-menu', {
    x: Math.max(0, box.x + box.width - 420),
    y: 0,
    width: 480,
    height: box.y + box.height + 110,
  });
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('menuitem', { name: 'STEP' }).click(),
  ]);
  expect(download.suggestedFilename()).toBe('rail.step');
  await expect(page.getByRole('menu', { name: 'Export format' })).toBeHidden();
  const file = join(mkdtempSync(join(tmpdir(), 'hula-dl-')), 'rail.step');
  await download.saveAs(file);
  expect(readFileSync(file, 'latin1')).toMatch(/^ISO-10303-21;/);
  const { labels, first } = readBack(file);
  expect(labels).toHaveLength(1);
  expectRail(first, 'import:step');
  await expect(page.locator('#status')).toContainText('Exported rail');
});

// The menu by keys: E opens it, I picks IGES; JSON (J) is the curve file itself.
test('export IGES and JSON by keys', async ({ page }) => {
  await openWithRail(page, 'export-iges');
  await page.keyboard.press('e');
  await expect(page.getByRole('menuitem', { name: 'JSON' })).toBeFocused();
  const [iges] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('i')]);
  expect(iges.suggestedFilename()).toBe('rail.igs');
  const file = join(mkdtempSync(join(tmpdir(), 'hula-dl-')), 'rail.igs');
  await iges.saveAs(file);
  expectRail(readBack(file).first, 'import:iges');
  await page.keyboard.press('e');
  const [json] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('j')]);
  expect(json.suggestedFilename()).toBe('rail.json');
  const jsonFile = join(mkdtempSync(join(tmpdir(), 'hula-dl-')), 'rail.json');
  await json.saveAs(jsonFile);
  const written = JSON.parse(readFileSync(jsonFile, 'utf8')) as typeof rail;
  expect(written).toMatchObject(rail);
});

// DXF by key D: one SPLINE with the curve's name, read back exactly (dxf writes every digit).
test('export DXF by key, read back by hula doc import', async ({ page }) => {
  await openWithRail(page, 'export-dxf');
  await page.keyboard.press('e');
  const [dxf] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('d')]);
  expect(dxf.suggestedFilename()).toBe('rail.dxf');
  const file = join(mkdtempSync(join(tmpdir(), 'hula-dl-')), 'rail.dxf');
  await dxf.saveAs(file);
  expect(readFileSync(file, 'latin1')).toMatch(/SPLINE/);
  const { labels, first } = readBack(file);
  expect(labels).toHaveLength(1);
  expectRail(first, 'import:dxf');
});

// With nothing selected the status line says so and nothing is downloaded; Escape closes the menu.
test('export with nothing selected says so', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('export-none');
  await addCurve(doc, 'rail', rail);
  await openApp(page, doc);
  let downloads = 0;
  page.on('download', () => downloads++);
  await page.keyboard.press('e');
  await page.keyboard.press('Escape');
  await expect(page.getByRole('menu', { name: 'Export format' })).toBeHidden();
  await page.keyboard.press('e');
  await page.getByRole('menuitem', { name: 'STEP' }).click();
  await expect(page.locator('#status')).toContainText('Export: nothing is selected');
  expect(downloads).toBe(0);
});
