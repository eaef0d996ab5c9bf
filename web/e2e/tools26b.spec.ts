// Intersect (Shift+I), Knots (Shift+K) and Clothoid (Shift+C) in Debian's chromium against a real
// `hula serve`: each result is checked over the API (the analysis route evaluates the curves at the
// parameters and arc lengths the page reports), never by the page's own geometry.
import { test, type Page } from '@playwright/test';
import type { Analysis, CurveFile } from '../src/api/types';
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
  pixelOf,
  shot,
} from './fixtures';
import { arch } from '../src/testing/curves';

type Nurbs = Extract<CurveFile, { kind: 'nurbs' }>;
type Vec = [number, number, number];

// A quadratic that crosses the arch twice (the arch is below y = 12 only near its ends).
const bow: Nurbs = {
  kind: 'nurbs',
  degree: 2,
  knots: [0, 0, 0, 1, 1, 1],
  control_points: [
    [-10, 12, 0],
    [50, 4, 0],
    [110, 12, 0],
  ],
};

// An open spline through five points: the clothoid splines pass through them.
const through: CurveFile = {
  kind: 'interpolated',
  points: [
    [0, 60, 0],
    [20, 80, 0],
    [45, 75, 0],
    [60, 55, 0],
    [90, 50, 0],
  ],
};

const status = (page: Page) => page.locator('#status');
const dist = (a: readonly number[], b: readonly number[]): number =>
  Math.hypot(...a.map((x, k) => x - (b[k] ?? 0)));

async function applied(doc: string): Promise<number> {
  const h = await api<{ history: { applied: boolean }[] }>(
    'GET',
    `/api/documents/${encodeURIComponent(doc)}/history`,
  );
  return h.history.filter((s) => s.applied).length;
}

async function select(page: Page, label: string): Promise<void> {
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
}

/** The server's evaluation of an entity at parameters (or arc lengths). */
async function at(doc: string, label: string, xs: number[], by = 'parameter'): Promise<Analysis> {
  return analysis(doc, label, { at: xs, by, samples: xs.length });
}

test('intersect two curves: every point marked lies on both', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('tools26b-x');
  const a = await addCurve(doc, 'arch', arch);
  const b = await addCurve(doc, 'bow', bow);
  await openApp(page, doc);
  const steps = await applied(doc);

  // The arch selected, the Intersect button, then a click on the bow (at its middle, far from
  // where it meets the arch).
  await select(page, a);
  await page.getByRole('button', { name: 'Intersect curves (Shift+I)' }).click();
  await expect(status(page)).toContainText(/Intersect: arch .*picked/);
  const mid = (await at(doc, b, [0.5])).points[0]!;
  const click = await pixelOf(page, 'top', mid as Vec);
  await page.mouse.click(click.x, click.y);
  await expect(status(page)).toContainText(/Intersect arch .*× bow .*: 2 point\(s\)/);
  const meetings = await page.evaluate(
    () =>
      (window.__hula.app.tool as unknown as { meetings: { t1: number; t2: number; point: Vec }[] })
        .meetings,
  );
  expect(meetings).toHaveLength(2);
  const marked = await page.locator('#viewports').getAttribute('data-intersections');
  expect(marked!.split(';')).toHaveLength(2);
  for (const m of meetings) {
    const pa = (await at(doc, a, [m.t1])).points[0]!;
    const pb = (await at(doc, b, [m.t2])).points[0]!;
    expect(dist(pa, m.point)).toBeLessThan(1e-9);
    expect(dist(pb, m.point)).toBeLessThan(1e-9);
    // The bow is y = 12 - 16 u (1 - u) in its parameter: independent of the server's numbers.
    expect(pb[1]!).toBeCloseTo(12 - 16 * m.t2 * (1 - m.t2), 9);
    // The status reads out (t1, t2) and the coordinates to six digits.
    await expect(status(page)).toContainText(`t1 ${Number(m.t1.toPrecision(6))}`);
    await expect(status(page)).toContainText(`t2 ${Number(m.t2.toPrecision(6))}`);
  }
  // One crossing on each side of the middle; nothing is stored.
  expect(meetings[0]!.point[0]).toBeLessThan(50);
  expect(meetings[1]!.point[0]).toBeGreaterThan(50);
  expect(await applied(doc)).toBe(steps);
  // The top view alone at 1280×720: both curves, the two markers, the read-out.
  await page.setViewportSize({ width: 1280, height: 720 });
  await page.keyboard.press('1');
  await page.evaluate(() => {
    window.__hula.app.fitAll();
  });
  await shot(page, 'intersect-1280x720');
});

test('drag a knot marker along the curve: that knot moves, one undo step', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('tools26b-k');
  const a = await addCurve(doc, 'arch', arch);
  await openApp(page, doc);
  const steps = await applied(doc);
  await select(page, a);
  await page.keyboard.press('Shift+K');
  await expect(status(page)).toContainText(/drag one of the 2 knot markers of arch/);
  // The markers are at C(0.3) and C(0.6) as the server evaluates the curve.
  const want = (await at(doc, a, [0.3, 0.6])).points;
  await expect
    .poll(async () => (await page.locator('#viewports').getAttribute('data-knots')) ?? '')
    .not.toBe('');
  const markers = (await page.locator('#viewports').getAttribute('data-knots'))!
    .split(';')
    .map((s) => s.split(',').map(Number));
  expect(markers).toHaveLength(2);
  for (let i = 0; i < 2; i++) expect(dist(markers[i]!, want[i]!)).toBeLessThan(1e-9);

  // Drag the first marker to the curve's point at t = 0.45 (between its neighbours 0 and 0.6).
  const [from, to] = (await at(doc, a, [0.3, 0.45])).points;
  const p0 = await pixelOf(page, 'top', from as Vec);
  const p1 = await pixelOf(page, 'top', to as Vec);
  await page.mouse.move(p0.x, p0.y);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++)
    await page.mouse.move(p0.x + ((p1.x - p0.x) * i) / 8, p0.y + ((p1.y - p0.y) * i) / 8);
  await expect(status(page)).toContainText('Knot 1: 0.3 →');
  await shot(page, 'knot-drag');
  await page.mouse.up();
  await expect(status(page)).toContainText(/Moved a knot of arch .*from 0\.3 to/);
  await idle(page);
  const shown = Number(/to ([0-9.]+)/.exec((await status(page).textContent()) ?? '')![1]);
  const stored = (await entity(doc, a)).curve as Nurbs;
  // The knot is where the pointer left it on the curve (a pixel is ~0.003 in t here), the others
  // and the control points are untouched, and the shown value is the stored one.
  expect(Math.abs(stored.knots[4]! - 0.45)).toBeLessThan(0.01);
  expect(stored.knots[4]!).toBeCloseTo(shown, 5);
  expect([...stored.knots.slice(0, 4), ...stored.knots.slice(5)]).toEqual([
    ...arch.knots.slice(0, 4),
    ...arch.knots.slice(5),
  ]);
  expect(stored.control_points).toEqual(arch.control_points);
  expect(await applied(doc)).toBe(steps + 1);
  // The markers follow the stored curve: at C(new knot) and C(0.6) of the server's new curve.
  const now = (await at(doc, a, [stored.knots[4]!, 0.6])).points;
  await expect
    .poll(async () => {
      const m = ((await page.locator('#viewports').getAttribute('data-knots')) ?? '')
        .split(';')
        .map((s) => s.split(',').map(Number));
      return m.length === 2 ? Math.max(dist(m[0]!, now[0]!), dist(m[1]!, now[1]!)) : Infinity;
    })
    .toBeLessThan(1e-9);

  // A drag past the neighbour stops short of it: the knot stays strictly below 0.6.
  const q0 = await pixelOf(page, 'top', now[0] as Vec);
  const q1 = await pixelOf(page, 'top', (await at(doc, a, [0.9])).points[0] as Vec);
  await page.mouse.move(q0.x, q0.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++)
    await page.mouse.move(q0.x + ((q1.x - q0.x) * i) / 10, q0.y + ((q1.y - q0.y) * i) / 10);
  await page.mouse.up();
  await expect(status(page)).toContainText('Moved a knot of arch');
  await idle(page);
  const clamped = ((await entity(doc, a)).curve as Nurbs).knots;
  expect(clamped[4]!).toBeLessThan(0.6);
  expect(clamped[4]!).toBeGreaterThan(0.59);
  expect(await applied(doc)).toBe(steps + 2);

  // Undo twice: the knot is back at 0.3.
  await page.keyboard.press('Control+z');
  await idle(page);
  await page.keyboard.press('Control+z');
  await expect.poll(async () => ((await entity(doc, a)).curve as Nurbs).knots).toEqual(arch.knots);
});

test('clothoid and biarc splines through the selected curve’s points', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('tools26b-c');
  const src = await addCurve(doc, 'path', through);
  await openApp(page, doc);
  const steps = await applied(doc);
  const pts = (through as { points: number[][] }).points;

  /** Arc lengths of the joints (the segment lengths the server reports for the same points). */
  async function joints(fit: string): Promise<number[]> {
    const r = await api<{ segments: { length: number }[] }>('POST', '/api/clothoid', {
      points: pts,
      fit,
    });
    const s = [0];
    for (const g of r.segments) s.push(s[s.length - 1]! + g.length);
    return s;
  }

  for (const [fit, name, n] of [
    ['g2', 'clothoid-g2', 2],
    ['biarc', 'biarc', 3],
  ] as const) {
    await select(page, src);
    await page.keyboard.press('Shift+C');
    const dialog = page.locator('dialog[open]');
    await expect(dialog).toBeVisible();
    await dialog.locator('select[name="fit"]').selectOption(fit);
    await dialog.locator('button[value="ok"]').click();
    await expect.poll(async () => (await curves(doc)).length).toBe(n);
    const made = (await curves(doc)).find((e) => e.name === name)!;
    expect(made.curve?.kind).toBe('natural');
    const label = String(made.label);
    expect(await page.evaluate(() => window.__hula.app.editor.selected)).toBe(label);
    await idle(page);

    // Through every point: each lies at one of the joints' arc lengths (a clothoid per interval,
    // two arcs per interval for the biarcs), ends included.
    const s = await joints(fit);
    expect(s).toHaveLength(fit === 'g2' ? pts.length : 2 * pts.length - 1);
    const on = await at(doc, label, s, 'arclength');
    expect(dist(on.points[0]!, pts[0]!)).toBeLessThan(1e-6);
    expect(dist(on.points[s.length - 1]!, pts[pts.length - 1]!)).toBeLessThan(1e-6);
    for (const p of pts) expect(Math.min(...on.points.map((q) => dist(q, p)))).toBeLessThan(1e-6);
    // At each inner joint, just before and after: the same tangent (G1); the same curvature for
    // the G2 clothoids, a jump for the biarcs (whose arcs have constant curvature).
    const d = 1e-6;
    const near = await at(
      doc,
      label,
      s.slice(1, -1).flatMap((x) => [x - d, x + d]),
      'arclength',
    );
    let jump = 0;
    for (let j = 0; j < s.length - 2; j++) {
      const [t0, t1] = [near.frames[2 * j]!.T, near.frames[2 * j + 1]!.T];
      expect(dist(t0, t1)).toBeLessThan(1e-4);
      const [k0, k1] = [near.kappa[2 * j] ?? 0, near.kappa[2 * j + 1] ?? 0];
      jump = Math.max(jump, Math.abs(k1 - k0) / Math.max(Math.abs(k0), Math.abs(k1)));
    }
    if (fit === 'g2') expect(jump).toBeLessThan(1e-3);
    else expect(jump).toBeGreaterThan(0.01);
    await expect(status(page)).toContainText(/through the 5 points of path/);
    expect(await applied(doc)).toBe(steps + n - 1);
  }
  // With nothing selected, Shift+C is a tool: four clicks in the top view and Enter give the G2
  // clothoid spline through the clicked points (to the size of a pixel, the clicks being pixels).
  await page.keyboard.press('Escape');
  await idle(page);
  await page.keyboard.press('Shift+C');
  await expect(status(page)).toContainText('Clothoid (G2 clothoids): left-click points');
  // In the region the view was fitted to (the source spline's), so every click lands in the top view.
  const clicks: Vec[] = [
    [5, 50, 0],
    [30, 70, 0],
    [55, 58, 0],
    [85, 72, 0],
  ];
  const topBox = (await page.locator('.view[data-view="top"]').boundingBox())!;
  const o = await pixelOf(page, 'top', [0, 0, 0]);
  const u = await pixelOf(page, 'top', [1, 0, 0]);
  const pixel = 1 / Math.abs(u.x - o.x);
  for (const c of clicks) {
    const px = await pixelOf(page, 'top', c);
    expect(px.x).toBeGreaterThan(topBox.x);
    expect(px.x).toBeLessThan(topBox.x + topBox.width);
    expect(px.y).toBeGreaterThan(topBox.y);
    expect(px.y).toBeLessThan(topBox.y + topBox.height);
    await page.mouse.click(px.x, px.y);
  }
  await page.keyboard.press('Enter');
  await expect.poll(async () => (await curves(doc)).length).toBe(4);
  const clicked = (await curves(doc)).at(-1)!;
  expect(clicked.name).toBe('clothoid-g2');
  expect(clicked.curve?.kind).toBe('natural');
  await expect(status(page)).toContainText(/through 4 points: 3 segments/);
  const along = await analysis(doc, String(clicked.label), { samples: 2001 });
  for (const c of clicks)
    expect(Math.min(...along.points.map((q) => dist(q, c)))).toBeLessThan(pixel + 0.05);
  expect(await applied(doc)).toBe(steps + 3);
  await page.keyboard.press('v');

  // The top view alone at 1280×720: the source spline, the G2 clothoid spline and the biarcs.
  await page.setViewportSize({ width: 1280, height: 720 });
  await page.keyboard.press('1');
  await page.evaluate(() => {
    window.__hula.app.fitAll();
  });
  await shot(page, 'clothoid-1280x720');
});
