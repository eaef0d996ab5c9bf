// Colours of new curves in Debian's chromium against a real `hula serve`: each curve drawn on
// the page gets a colour no visible curve has, stored as its colour attribute, so the colours
// are the same after a reload.
import { test, type Page } from '@playwright/test';
import type { Vec3 } from '../src/viewport/math';
import {
  addCurve,
  curves,
  expect,
  idle,
  needsDocuments,
  newDoc,
  openApp,
  pixelOf,
} from './fixtures';

const line = (y: number): { kind: 'bezier'; control_points: number[][] } => ({
  kind: 'bezier',
  control_points: [
    [0, y, 0],
    [40, y + 10, 0],
    [80, y, 0],
  ],
});

/** The drawn colour of every curve of the document, none selected, keyed by label. */
async function drawn(page: Page): Promise<Record<string, number>> {
  // The select tool (a drawing tool keeps Escape for itself), then Escape clears the selection.
  await page.keyboard.press('v');
  await page.keyboard.press('Escape');
  await idle(page);
  expect(await page.evaluate(() => window.__hula.app.selected)).toBeNull();
  return page.evaluate(() => {
    const app = window.__hula.app;
    const out: Record<string, number> = {};
    for (const label of app.store.entities.keys()) out[label] = app.viewports.drawnColour(label)!;
    return out;
  });
}

test('a new curve takes a colour no visible curve has, kept across a reload', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('colours');
  // Two curves from elsewhere (no colour attribute): drawn in their labels' palette colours.
  await addCurve(doc, 'first', line(-60));
  await addCurve(doc, 'second', line(60));
  await openApp(page, doc);
  const before = await drawn(page);
  expect(new Set(Object.values(before)).size).toBe(2);
  // Three Béziers drawn in the top view between them (inside the view the page fitted), one after another.
  for (const [i, y] of [-30, 0, 30].entries()) {
    await page.keyboard.press('b');
    let px = { x: 0, y: 0 };
    for (const x of [0, 40, 80]) {
      px = await pixelOf(page, 'top', [x, y, 0] as Vec3);
      await page.mouse.click(px.x, px.y);
    }
    await page.mouse.click(px.x, px.y, { button: 'right' });
    await expect.poll(async () => (await curves(doc)).length).toBe(3 + i);
    await idle(page);
    const colours = await drawn(page);
    // Every curve's colour differs from every other's.
    expect(new Set(Object.values(colours)).size).toBe(Object.keys(colours).length);
  }
  const after = await drawn(page);
  expect(Object.keys(after)).toHaveLength(5);
  // The page's colours are stored with the new curves (server-side, "#rrggbb").
  const stored = await curves(doc);
  for (const e of stored.filter((x) => !['first', 'second'].includes(x.name))) {
    const c = e.attributes['colour'] as string;
    expect(parseInt(c.slice(1), 16)).toBe(after[String(e.label)]);
  }
  // The object list's swatches are the drawn colours.
  const swatches = await page
    .locator('ul.objects li')
    .evaluateAll((rows) =>
      rows.map((r) => [
        (r as HTMLElement).dataset['label']!,
        getComputedStyle(r.querySelector('.swatch')!).backgroundColor,
      ]),
    );
  for (const [label, css] of swatches) {
    const c = after[label!]!;
    expect(css).toBe(`rgb(${(c >> 16) & 255}, ${(c >> 8) & 255}, ${c & 255})`);
  }
  await page.reload();
  await idle(page);
  expect(await drawn(page)).toEqual(after);
});
