// Split and reverse from the toolbar (the Split and Reverse buttons) and the keyboard (X, W) in
// Debian's chromium against a real `hula serve`: the geometry checked over the API.
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
  shot,
} from './fixtures';

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

const distance = (p: readonly number[], q: readonly number[]): number =>
  Math.hypot(...p.map((x, k) => x - q[k]!));

async function steps(doc: string): Promise<[string, boolean][]> {
  const h = await api<{ history: { name: string; applied: boolean }[] }>(
    'GET',
    `/api/documents/${encodeURIComponent(doc)}/history`,
  );
  return h.history.map((s) => [s.name, s.applied]);
}

// Reverse (button): the curve at u is the old curve at 1 − u (1e-9 at 101 parameters) and the
// control points run backwards; W reverses it back to the original control points. Split (X key,
// nothing hovered: mid-domain t = 0.5): two pieces on [0, 0.5] and [0.5, 1] that meet at the old
// C(0.5), the first selected; the Split button splits that piece again. Each is one undo step, and
// undo brings back the original curve alone. The help panel lists both keys.
test('split and reverse the selected curve, then undo', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('split');
  const label = await addCurve(doc, 'rail', cubic);
  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
  const before = (await analysis(doc, label, { samples: 101, by: 'parameter' })).points;

  await page.getByRole('button', { name: 'Reverse curve (W)' }).click();
  await expect
    .poll(async () => ((await entity(doc, label)).curve as Nurbs).control_points)
    .toEqual([...cubic.control_points].reverse());
  const reversed = (await analysis(doc, label, { samples: 101, by: 'parameter' })).points;
  expect(Math.max(...reversed.map((p, i) => distance(p, before[100 - i]!)))).toBeLessThan(1e-9);
  await idle(page);
  await page.keyboard.press('w');
  await expect
    .poll(async () => ((await entity(doc, label)).curve as Nurbs).control_points)
    .toEqual(cubic.control_points);

  await idle(page);
  await page.keyboard.press('x');
  await expect.poll(async () => (await curves(doc)).length).toBe(2);
  await idle(page);
  const pieces = await curves(doc);
  const [first, second] = pieces.map((e) => e.curve as Nurbs);
  expect(pieces.map((e) => e.name)).toEqual(['rail (1)', 'rail (2)']);
  expect([first!.knots[0], first!.knots[first!.knots.length - 1]]).toEqual([0, 0.5]);
  expect([second!.knots[0], second!.knots[second!.knots.length - 1]]).toEqual([0.5, 1]);
  const a = (await analysis(doc, String(pieces[0]!.label), { samples: 51, by: 'parameter' }))
    .points;
  const b = (await analysis(doc, String(pieces[1]!.label), { samples: 51, by: 'parameter' }))
    .points;
  expect(distance(a[50]!, before[50]!)).toBeLessThan(1e-9);
  expect(distance(b[0]!, before[50]!)).toBeLessThan(1e-9);
  for (let i = 0; i <= 50; i++) {
    expect(distance(a[i]!, before[i]!)).toBeLessThan(1e-9);
    expect(distance(b[i]!, before[50 + i]!)).toBeLessThan(1e-9);
  }
  expect(await page.evaluate(() => window.__hula.app.selected)).toBe(String(pieces[0]!.label));
  await shot(page, 'split-curve');

  await page.getByRole('button', { name: 'Split curve (X)' }).click();
  await expect.poll(async () => (await curves(doc)).length).toBe(3);
  expect(await steps(doc)).toEqual([
    ['add curve', true],
    ['reverse', true],
    ['reverse', true],
    ['split', true],
    ['split', true],
  ]);

  await idle(page);
  await page.keyboard.press('Control+z');
  await idle(page);
  await page.keyboard.press('Control+z');
  await expect.poll(async () => (await curves(doc)).map((e) => e.label)).toEqual([label]);
  expect(((await entity(doc, label)).curve as Nurbs).control_points).toEqual(cubic.control_points);

  await page.keyboard.press('?');
  const help = page.getByRole('dialog');
  await expect(help.getByRole('row', { name: /^X split the selected curve/ })).toBeVisible();
  await expect(help.getByRole('row', { name: /^W reverse the direction/ })).toBeVisible();
});
