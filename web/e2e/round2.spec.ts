// Issue 23, the workbench's second round: feedback (defect 6), the graphs
// (defect 5), the object list and the view state kept per document (defect 4),
// snap off by default and a nudge that moves what the pointer moved (defect 7).
// Every document value is read back through the server's API.
import { test, type Page } from '@playwright/test';
import type { CurveFile } from '../src/api/types';
import type { Vec3 } from '../src/viewport/math';
import {
  addCurve,
  analysis,
  curves,
  entity,
  expect,
  idle,
  needsDocuments,
  newDoc,
  openApp,
  pixelOf,
  shot,
} from './fixtures';

// A twisted cubic (non-coplanar control points): τ ≠ 0 with its own extrema.
const twisted: CurveFile = {
  kind: 'bezier',
  control_points: [
    [0, 0, 0],
    [30, 40, 10],
    [70, 40, 30],
    [100, 0, 60],
  ],
  weights: null,
};
const arch: CurveFile = {
  kind: 'bezier',
  control_points: [
    [0, -60, 0],
    [40, -20, 0],
    [80, -60, 0],
  ],
  weights: null,
};

const SIZES = [
  { width: 1280, height: 720 },
  { width: 1600, height: 1000 },
];

async function select(page: Page, label: string): Promise<void> {
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
}

const status = (page: Page) => page.locator('#status');

test('the status line says what the last command did, and when nothing is selected', async ({
  page,
}) => {
  needsDocuments();
  await page.setViewportSize(SIZES[0]!);
  const doc = await newDoc('status');
  await openApp(page, doc);
  // Delete with nothing selected says so (it used to say nothing).
  await page.keyboard.press('Delete');
  await expect(status(page)).toContainText('Delete: nothing is selected');
  await expect(status(page)).toHaveClass(/offline/);
  // A finished Bézier: the status names the curve made, not "Bézier: 3 point(s)…".
  await page.keyboard.press('b');
  for (const p of [
    [0, 0, 0],
    [40, 30, 0],
    [80, 0, 0],
  ] as Vec3[]) {
    const px = await pixelOf(page, 'top', p);
    await page.mouse.click(px.x, px.y);
  }
  await expect(status(page)).toContainText('3 point(s)');
  await page.keyboard.press('Enter');
  await idle(page);
  const made = await curves(doc);
  expect(made).toHaveLength(1);
  const label = String(made[0]!.label);
  await expect(status(page)).toContainText(`Created bezier curve bezier (${label})`);
  await expect(status(page)).not.toContainText('point(s)');
  // Split, then Delete: the status follows each.
  await page.keyboard.press('v');
  await select(page, label);
  await page.keyboard.press('x');
  await idle(page);
  await expect(status(page)).toContainText('Split');
  await page.keyboard.press('Delete');
  await idle(page);
  await expect(status(page)).toContainText('Deleted');
  await expect(status(page)).not.toContainText('Split');
  expect((await curves(doc)).length).toBe(1);
});

for (const size of SIZES)
  test(`fin legend, invalid fin settings reported, NSGA-II without the GA method at ${size.width}×${size.height}`, async ({
    page,
  }) => {
    needsDocuments();
    await page.setViewportSize(size);
    const doc = await newDoc('fins');
    const label = await addCurve(doc, 'twisted', twisted);
    await openApp(page, doc);
    await select(page, label);
    // The legend: each fin kind's swatch is the colour the views draw it in.
    const swatches = await page.evaluate(() =>
      [...document.querySelectorAll<HTMLElement>('[data-swatch]')].map((s) => [
        s.dataset['swatch'],
        getComputedStyle(s).backgroundColor,
      ]),
    );
    expect(swatches).toHaveLength(7);
    expect(Object.fromEntries(swatches)).toMatchObject({
      curvature: 'rgb(214, 75, 214)',
      torsion: 'rgb(60, 191, 90)',
    });
    await page.locator('[data-fin="curvature"]').check();
    await idle(page);
    // A bad scale is reported and kept on screen; the fins keep the last valid scale.
    const scale = page.getByRole('spinbutton', { name: 'Fin scale' });
    await scale.fill('-2');
    await scale.press('Enter');
    await scale.blur();
    await idle(page);
    await expect(status(page)).toContainText('Fin scale must be a number > 0');
    await expect(scale).toHaveValue('-2');
    await expect(scale).toHaveAttribute('aria-invalid', 'true');
    expect(await page.evaluate((l) => window.__hula.app.settingsOf(l).scale, label)).toBe(1);
    const samples = page.getByRole('spinbutton', { name: 'Fin density (samples)' });
    await samples.fill('1');
    await samples.blur();
    await idle(page);
    await expect(status(page)).toContainText('Fin samples must be a whole number from 2 to 5000');
    await expect(samples).toHaveValue('1');
    await scale.fill('2');
    await scale.blur();
    await idle(page);
    await expect(scale).toHaveAttribute('aria-invalid', 'false');
    expect(await page.evaluate((l) => window.__hula.app.settingsOf(l).scale, label)).toBe(2);
    // The GA method selector belongs to curvature matching only.
    const kind = page.getByRole('combobox', { name: 'Study kind' });
    const method = page.getByRole('combobox', { name: 'Matching method' });
    await expect(method).toBeVisible();
    await kind.selectOption('match-curvature-torsion');
    await expect(method).toBeHidden();
    await kind.selectOption('match-curvature');
    await expect(method).toBeVisible();
    await shot(page, `fin-legend-${size.width}x${size.height}`);
  });

test('the τ graph marks τ extrema, reads t or s as plotted, and hover reads values', async ({
  page,
}) => {
  needsDocuments();
  await page.setViewportSize(SIZES[1]!);
  const doc = await newDoc('graphs');
  const label = await addCurve(doc, 'twisted', twisted);
  await openApp(page, doc);
  await select(page, label);
  const server = await analysis(doc, label);
  const tauExtrema = server.features.filter((f) => f.kind.startsWith('torsion-')).length;
  const kappaExtrema = server.features.filter((f) => f.kind.startsWith('curvature-')).length;
  expect(tauExtrema).toBeGreaterThan(0);
  const markers = async (i: number): Promise<string[]> =>
    ((await page.locator(`[data-graph="g${i}"]`).getAttribute('data-markers')) ?? '')
      .split(' ')
      .filter(Boolean);
  const tau = await markers(1);
  expect(tau.filter((k) => k.startsWith('torsion-'))).toHaveLength(tauExtrema);
  expect(tau.filter((k) => k.startsWith('curvature-') || k === 'inflection')).toHaveLength(0);
  const kappa = await markers(0);
  expect(kappa.filter((k) => k.startsWith('curvature-'))).toHaveLength(kappaExtrema);
  expect(kappa.filter((k) => k.startsWith('torsion-'))).toHaveLength(0);
  // The axis reads what is plotted.
  const axisLabels = (): Promise<(string | undefined)[]> =>
    page.evaluate(() => window.__hula.app.graphs.map((g) => g.xAxisLabel));
  expect(await axisLabels()).toEqual(['arc length s', 'arc length s']);
  await page.getByRole('combobox', { name: 'Graph abscissa' }).selectOption('t');
  await idle(page);
  expect(await axisLabels()).toEqual(['parameter t', 'parameter t']);
  // Hover on the graph: a readout of t, κ, R and τ; the same sample on the curve.
  const box = (await page.locator('[data-graph="g1"] .u-over').boundingBox())!;
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.5);
  await expect(page.locator('[data-readout="g1"]')).toHaveText(
    /^t = [-0-9.e]+ · κ = [-0-9.e]+ · R = [-0-9.e]+ · τ = [-0-9.e]+$/,
  );
  const i = Number(await page.locator('#viewports').getAttribute('data-hover'));
  const a = await analysis(doc, label, { by: 'parameter' });
  const shown = await page.locator('[data-readout="g1"]').textContent();
  expect(shown).toContain(`τ = ${Number(a.tau[i]!.toPrecision(4))}`);
  // Hover on the curve in the top view: the readout at the cursor.
  const p = server.points[120]!;
  const px = await pixelOf(page, 'top', [p[0]!, p[1]!, p[2]!]);
  await page.mouse.move(px.x, px.y);
  await expect(page.locator('[data-readout="curve"]')).toBeVisible();
  await expect(page.locator('[data-readout="curve"]')).toHaveText(/^t = .* · κ = .* · τ = /);
  await shot(page, 'graph-readout-1600x1000');
});

test('the object list names, colours, hides and locks curves; the view state survives a reload', async ({
  page,
}) => {
  needsDocuments();
  await page.setViewportSize(SIZES[0]!);
  const doc = await newDoc('objects');
  const a = await addCurve(doc, 'twisted', twisted);
  const b = await addCurve(doc, 'arch', arch);
  await openApp(page, doc);
  const rows = page.locator('ul.objects li');
  await expect(rows).toHaveCount(2);
  await expect(rows.nth(0)).toContainText(`twisted · ${a}`);
  await expect(rows.nth(1)).toContainText(`arch · ${b}`);
  const colours = await rows
    .locator('.swatch')
    .evaluateAll((s) => s.map((x) => getComputedStyle(x).backgroundColor));
  expect(new Set(colours).size).toBe(2);
  // A click on a name selects the curve.
  await page.getByRole('button', { name: 'Select arch' }).click();
  await idle(page);
  expect(await page.evaluate(() => window.__hula.app.selected)).toBe(b);
  // Locked: its points are not dragged (the server's curve is unchanged).
  await page.getByRole('checkbox', { name: 'Lock arch' }).check();
  await idle(page);
  const cp: Vec3 = [40, -20, 0];
  const from = await pixelOf(page, 'top', cp);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x + 30, from.y - 30, { steps: 5 });
  await page.mouse.up();
  await idle(page);
  await expect(status(page)).toContainText('is locked');
  const stored = (await entity(doc, b)).curve as { control_points: number[][] };
  expect(stored.control_points[1]).toEqual([40, -20, 0]);
  await page.getByRole('checkbox', { name: 'Lock arch' }).uncheck();
  // Hidden: not drawn, not picked by a click on it.
  await page.getByRole('checkbox', { name: 'Show twisted' }).uncheck();
  await page.keyboard.press('Escape');
  // No wait for the server: a hide shows at once.
  const on = await pixelOf(page, 'top', [0, 0, 0]);
  await page.mouse.click(on.x, on.y);
  await idle(page);
  expect(await page.evaluate(() => window.__hula.app.selected)).toBeNull();
  // View state: selection, fins, layout and snap, per document, across a reload.
  await select(page, b);
  await page.locator('[data-fin="curvature"]').check();
  await page.evaluate(() => {
    (document.activeElement as HTMLElement | null)?.blur();
  });
  await page.keyboard.press('g');
  await page.keyboard.press('2');
  await idle(page);
  await shot(page, 'objects-1280x720');
  await page.reload();
  await idle(page);
  const state = await page.evaluate(
    ([l, other]) => {
      const app = window.__hula.app;
      return {
        selected: app.selected,
        fins: app.settingsOf(l).fins,
        layout: app.viewports.layout,
        active: app.viewports.active,
        snap: app.viewports.snap,
        snapBox: (document.getElementById('snap') as HTMLInputElement).checked,
        hidden: app.isHidden(other),
      };
    },
    [b, a] as const,
  );
  expect(state).toEqual({
    selected: b,
    fins: ['curvature'],
    layout: 'single',
    active: 'front',
    snap: true,
    snapBox: true,
    hidden: true,
  });
  // Visibility and lock are the document's attributes, seen by every client.
  expect((await entity(doc, a)).attributes['visible']).toBe(false);
  await expect(page.locator('[data-fin="curvature"]')).toBeChecked();
  // Another document starts from the defaults.
  const fresh = await newDoc('objects-other');
  await openApp(page, fresh);
  expect(await page.evaluate(() => window.__hula.app.viewports.snap)).toBe(false);
});

test('snap is off by default and a 2 px nudge moves the point 2 px worth', async ({ page }) => {
  needsDocuments();
  await page.setViewportSize(SIZES[1]!);
  const doc = await newDoc('nudge');
  const label = await addCurve(doc, 'arch', arch);
  await openApp(page, doc);
  await expect(page.locator('#snap')).not.toBeChecked();
  await select(page, label);
  const cp: Vec3 = [40, -20, 0];
  const from = await pixelOf(page, 'top', cp);
  const perPixel = await page.evaluate(() => {
    const vp = window.__hula.app.viewports;
    return vp.worldPerPixel(vp.view('top'));
  });
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x + 2, from.y);
  await page.mouse.up();
  await idle(page);
  const stored = (await entity(doc, label)).curve as { control_points: number[][] };
  const moved = stored.control_points[1]!;
  // 2 px to the right in the top view is +x by 2 × (world units per pixel), to a pixel's rounding.
  expect(Math.abs(moved[0]! - 40 - 2 * perPixel)).toBeLessThan(0.6 * perPixel);
  expect(Math.abs(moved[1]! + 20)).toBeLessThan(0.6 * perPixel);
});
