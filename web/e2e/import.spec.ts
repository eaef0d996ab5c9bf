// Import of a curve file (the toolbar's Import, key I) in Debian's chromium against a real
// `hula serve`: the document then holds that curve, checked over the API.
import { test } from '@playwright/test';
import { analysis, curves, expect, idle, needsDocuments, newDoc, openApp } from './fixtures';

// A JSON NURBS file picked in the file chooser becomes one entity with the same construction
// data, and the server's analysis of it ends at the file's end control points (clamped knots).
test('import a JSON curve file', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('import');
  await openApp(page, doc);
  const curve = {
    kind: 'nurbs',
    degree: 2,
    knots: [0, 0, 0, 0.5, 1, 1, 1],
    control_points: [
      [0, 0, 0],
      [10, 20, 0],
      [30, 20, 5],
      [40, 0, 5],
    ],
    weights: [1, 2, 1, 1],
  };
  await page.locator('#import-file').setInputFiles({
    name: 'quad.json',
    mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify(curve)),
  });
  await expect.poll(async () => (await curves(doc)).length).toBe(1);
  await idle(page);
  const [e] = await curves(doc);
  expect(e!.name).toBe('quad');
  const c = e!.curve as typeof curve;
  expect(c.kind).toBe('nurbs');
  expect(c.degree).toBe(2);
  expect(c.knots).toEqual(curve.knots);
  expect(c.control_points).toEqual(curve.control_points);
  expect(c.weights).toEqual(curve.weights);
  const a = await analysis(doc, String(e!.label));
  const ends = [a.points[0]!, a.points[a.points.length - 1]!];
  for (const [p, q] of [
    [ends[0]!, curve.control_points[0]!],
    [ends[1]!, curve.control_points[3]!],
  ] as const)
    for (let k = 0; k < 3; k++) expect(Math.abs(p[k]! - q[k]!)).toBeLessThan(1e-9);
  // The page selected the new curve.
  expect(await page.evaluate(() => window.__hula.app.selected)).toBe(String(e!.label));
});

// A file that is not JSON is refused with a toast naming the file; the document stays empty.
test('import refuses a file that is not JSON', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('import-bad');
  await openApp(page, doc);
  await page.locator('#import-file').setInputFiles({
    name: 'broken.json',
    mimeType: 'application/json',
    buffer: Buffer.from('{"kind": "nurbs", '),
  });
  await expect(page.locator('.toast').last()).toContainText('broken.json');
  expect(await curves(doc)).toHaveLength(0);
});
