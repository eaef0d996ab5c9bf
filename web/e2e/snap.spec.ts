// Object snap (the toolbar's Objects, Shift+G) in Debian's chromium against a real `hula serve`:
// a dragged handle released a few pixels from another curve's end lands exactly on it, one released
// near the middle of a curve lands on that curve; without it, the same drag lands where the pointer
// left it. The toggle is kept with the document's view state.
import { test, type Page } from '@playwright/test';
import type { Vec3 } from '../src/viewport/math';
import {
  addCurve,
  analysis,
  distanceToPolyline,
  entity,
  expect,
  idle,
  needsDocuments,
  newDoc,
  openApp,
  pixelOf,
  shot,
} from './fixtures';

const arch = {
  kind: 'bezier' as const,
  control_points: [
    [0, 0, 0],
    [30, 40, 0],
    [70, 40, 0],
    [100, 0, 0],
  ],
};
const hook = {
  kind: 'bezier' as const,
  control_points: [
    [-40, -50, 0],
    [-10, -60, 0],
    [20, -40, 0],
  ],
};

/** Drags a handle of the selected curve from `from` to a few pixels off `to` in the top view. */
async function drag(page: Page, from: Vec3, to: Vec3): Promise<void> {
  const a = await pixelOf(page, 'top', from);
  const b = await pixelOf(page, 'top', to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  for (let i = 1; i <= 5; i++)
    await page.mouse.move(a.x + ((b.x + 4 - a.x) * i) / 5, a.y + ((b.y - 3 - a.y) * i) / 5);
  await page.mouse.up();
  await idle(page);
}

const points = async (doc: string, label: string): Promise<number[][]> =>
  ((await entity(doc, label)).curve as { control_points: number[][] }).control_points;

test('object snap puts a dragged handle on another curve’s end or on the curve', async ({
  page,
}) => {
  needsDocuments();
  const doc = await newDoc('osnap');
  const a = await addCurve(doc, 'arch', arch);
  const h = await addCurve(doc, 'hook', hook);
  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, h);
  await idle(page);
  // Off: the hook's end lands a few pixels from the arch's start, not on it.
  await drag(page, [20, -40, 0], [0, 0, 0]);
  const off = (await points(doc, h))[2]!;
  expect(Math.hypot(off[0]!, off[1]!)).toBeGreaterThan(0.1);
  // On (Shift+G): the same drag from there lands exactly on the arch's start.
  await page.keyboard.press('Shift+G');
  await expect(page.locator('#osnap')).toBeChecked();
  await drag(page, [off[0]!, off[1]!, off[2]!], [0, 0, 0]);
  expect((await points(doc, h))[2]).toEqual([0, 0, 0]);
  expect(await page.evaluate(() => window.__hula.app.lastSnap)).toEqual({
    kind: 'point',
    label: a,
  });
  // Near the middle of the arch (no handle within reach): onto the arch as drawn.
  const onArch = (await analysis(doc, a, { samples: 2001, by: 'parameter' })).points;
  const mid = onArch[1000]!;
  await drag(page, [-40, -50, 0], [mid[0]!, mid[1]!, 0]);
  const start = (await points(doc, h))[0]!;
  expect(await page.evaluate(() => window.__hula.app.lastSnap?.kind)).toBe('curve');
  // On the drawn polyline of the arch: within its chord sag of the exact curve.
  expect(distanceToPolyline(start, onArch)).toBeLessThan(0.05);
  await page.keyboard.press('Escape');
  await shot(page, 'object-snap');
  // The toggle is part of the document's view state.
  await page.reload();
  await idle(page);
  await expect(page.locator('#osnap')).toBeChecked();
});
