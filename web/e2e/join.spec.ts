// Match and Blend on the page (toolbar, keys and two clicks in the top view) in
// Debian's chromium against a real `hula serve`. The continuity is checked
// through the API, never by the page's own numbers: the curves are laid end to
// end as one NURBS in a scratch document, whose analysis route reports the
// continuity at the join knots (features.knots, the document's continuity
// analysis); the blend's curvature extrema are counted by the same route.
import { test, type Page } from '@playwright/test';
import type * as Api from '../src/api/openapi';
import type { CurveFile } from '../src/api/types';
import {
  addCurve,
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

type Nurbs = Extract<CurveFile, { kind: 'nurbs' }>;

// Two plane cubics in the X-Y plane (the top view) with a gap between A's end and B's start.
const head: Nurbs = {
  kind: 'nurbs',
  degree: 3,
  knots: [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1],
  control_points: [
    [0, 0, 0],
    [10, 15, 0],
    [25, 22, 0],
    [40, 20, 0],
    [52, 12, 0],
    [60, 5, 0],
    [66, 0, 0],
  ],
};
const tail: Nurbs = {
  kind: 'nurbs',
  degree: 3,
  knots: [0, 0, 0, 0, 0.4, 1, 1, 1, 1],
  control_points: [
    [85, -10, 0],
    [95, -22, 0],
    [110, -28, 0],
    [130, -18, 0],
    [150, -20, 0],
  ],
};

const status = (page: Page) => page.locator('#status');

/** The names of the document's applied history steps. */
async function applied(doc: string): Promise<string[]> {
  const h = await api<{ history: { name: string; applied: boolean }[] }>(
    'GET',
    `/api/documents/${encodeURIComponent(doc)}/history`,
  );
  return h.history.filter((s) => s.applied).map((s) => s.name);
}

/** Click a world point of the top view (an end or a point of a curve). */
async function clickAt(page: Page, p: readonly number[]): Promise<void> {
  const { x, y } = await pixelOf(page, 'top', [p[0]!, p[1]!, p[2] ?? 0]);
  await page.mouse.click(x, y);
}

const last = (c: Nurbs): number[] => c.control_points[c.control_points.length - 1]!;

/** Same-degree clamped NURBS laid end to end as one (each starts where the previous ends), and the join knots. */
function joined(...pieces: Nurbs[]): { curve: Nurbs; at: number[] } {
  const p = pieces[0]!.degree;
  const knots = pieces[0]!.knots.slice(0, -1);
  const points = [...pieces[0]!.control_points];
  const at: number[] = [];
  for (const c of pieces.slice(1)) {
    expect(c.degree).toBe(p);
    const u = knots[knots.length - 1]!;
    at.push(u);
    knots.push(...c.knots.slice(p + 1, -1).map((k) => k - c.knots[0]! + u));
    points.push(...c.control_points.slice(1));
  }
  knots.push(knots[knots.length - 1]!);
  return { curve: { kind: 'nurbs', degree: p, knots, control_points: points }, at };
}

/** The geometric continuity (k of Gk) the analysis route reports at each join of the pieces laid end to end. */
async function joinOrders(scratch: string, ...pieces: Nurbs[]): Promise<(number | null)[]> {
  const { curve, at } = joined(...pieces);
  const label = await addCurve(scratch, 'joined', curve);
  const a = await api<Api.Analysis>(
    'POST',
    `/api/documents/${encodeURIComponent(scratch)}/entities/${label}/analysis`,
    { samples: 3 },
  );
  return at.map((u) => {
    const k = a.features!.knots.find((k) => Math.abs(k.t - u) < 1e-12);
    expect(k, `a knot at the join t = ${u}`).toBeDefined();
    return k!.geometric;
  });
}

/** A curve of the scratch document raised to `degree` by the server's elevate route (its shape kept). */
async function raised(scratch: string, c: Nurbs, degree: number): Promise<Nurbs> {
  const label = await addCurve(scratch, 'raised', c);
  await api('POST', `/api/documents/${encodeURIComponent(scratch)}/entities/${label}/elevate`, {
    times: degree - c.degree,
  });
  return (await entity(scratch, label)).curve as Nurbs;
}

async function matchOnce(page: Page, doc: string, a: string, k: number): Promise<Nurbs> {
  await page.keyboard.press(String(k));
  await expect(page.getByLabel('Continuity of Match and Blend (keys 0-3)')).toHaveValue(String(k));
  await clickAt(page, last(head));
  await expect(status(page)).toContainText(`Match G${k}: ${a}'s end picked`);
  await clickAt(page, tail.control_points[0]!);
  await expect(status(page)).toContainText(` reached (asked G${k})`);
  await idle(page);
  // The continuity the server measured, at least the one asked.
  const text = (await status(page).textContent()) ?? '';
  expect(Number(/: G(\d) reached/.exec(text)?.[1])).toBeGreaterThanOrEqual(k);
  return (await entity(doc, a)).curve as Nurbs;
}

// Match (M key): head's end made G2, then (after undo) G3 to tail's start by two clicks; each is
// one "replace curve" step that undo takes back to the original poles; the join of the stored curve
// with tail is G2 / G3 by the analysis route, and head's first pole never moves.
test('Match reaches G2 and G3 at the other curve, checked by the analysis route; undo restores', async ({
  page,
}) => {
  needsDocuments();
  const doc = await newDoc('match');
  const scratch = await newDoc('match-check');
  const a = await addCurve(doc, 'head', head);
  const b = await addCurve(doc, 'tail', tail);
  await page.setViewportSize({ width: 1600, height: 1000 });
  await openApp(page, doc);
  await page.keyboard.press('1');
  await page.keyboard.press('f');
  await idle(page);

  await page.keyboard.press('m');
  await expect(status(page)).toHaveText(
    'Match G2: click curve A near the end to move (keys 0-3 choose the continuity)',
  );
  for (const k of [2, 3]) {
    const before = await applied(doc);
    const matched = await matchOnce(page, doc, a, k);
    expect(await applied(doc)).toEqual([...before, 'replace curve']);
    expect(matched.control_points[0]).toEqual(head.control_points[0]);
    expect(
      Math.hypot(...last(matched).map((x, i) => x - tail.control_points[0]![i]!)),
    ).toBeLessThan(1e-9);
    expect((await joinOrders(scratch, matched, tail))[0]).toBeGreaterThanOrEqual(k);
    expect(((await entity(doc, b)).curve as Nurbs).control_points).toEqual(tail.control_points);
    if (k === 3) {
      await page.keyboard.press('f');
      await shot(page, 'match-g3-1600x1000');
    }
    await page.keyboard.press('Control+z');
    await expect
      .poll(async () => ((await entity(doc, a)).curve as Nurbs).control_points)
      .toEqual(head.control_points);
    expect(await applied(doc)).toEqual(before);
    await idle(page);
  }
});

// Blend (the toolbar button, G2 by key then G3 from the toolbar's menu): a new curve from head's
// end to tail's start, one "add curve" step; at both joins of head + blend + tail (head and tail
// raised to the blend's degree by the server) the analysis route finds the asked Gk, and the
// curvature extrema count the status line reports is the count the analysis route finds.
test('Blend has the asked continuity at both ends and reports the extrema the analysis finds', async ({
  page,
}) => {
  needsDocuments();
  const doc = await newDoc('blend');
  const scratch = await newDoc('blend-check');
  await addCurve(doc, 'head', head);
  await addCurve(doc, 'tail', tail);
  await page.setViewportSize({ width: 1280, height: 720 });
  await openApp(page, doc);
  await page.keyboard.press('1');
  await page.keyboard.press('f');
  await idle(page);

  await page.getByRole('button', { name: 'Blend two curve ends (J)' }).click();
  for (const k of [2, 3]) {
    if (k === 2) await page.keyboard.press('2');
    else await page.getByLabel('Continuity of Match and Blend (keys 0-3)').selectOption('3');
    await expect(status(page)).toContainText(`Blend G${k}: click the first curve`);
    await clickAt(page, last(head));
    await clickAt(page, tail.control_points[0]!);
    await expect(status(page)).toContainText(`at its ends (asked G${k})`);
    await idle(page);
    const text = (await status(page).textContent()) ?? '';
    const ends = /: G(\d) and G(\d) at its ends/.exec(text);
    expect(ends, text).not.toBeNull();
    expect(Math.min(Number(ends![1]), Number(ends![2]))).toBeGreaterThanOrEqual(k);
    const reported = Number(/(\d+) curvature extrem/.exec(text)![1]);
    const all = await curves(doc);
    expect(all).toHaveLength(3);
    const made = all[2]!;
    const blend = made.curve as Nurbs;
    expect(blend.degree).toBe(2 * k + 1);
    expect(await page.evaluate(() => window.__hula.app.selected)).toBe(String(made.label));
    const orders = await joinOrders(
      scratch,
      await raised(scratch, head, blend.degree),
      blend,
      await raised(scratch, tail, blend.degree),
    );
    expect(
      orders.every((g) => g !== null && g >= k),
      `G${k} at both joins: ${JSON.stringify(orders)}`,
    ).toBe(true);
    const features = (
      await api<Api.Analysis>(
        'POST',
        `/api/documents/${encodeURIComponent(doc)}/entities/${made.label}/analysis`,
        { samples: 3 },
      )
    ).features!;
    expect(features.curvature_extrema.length).toBe(reported);
    if (k === 3) {
      await page.keyboard.press('f');
      await shot(page, 'blend-g3-1280x720');
    }
    // One undo step takes the blend away.
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await curves(doc)).length).toBe(2);
    await idle(page);
  }
  await page.keyboard.press('?');
  const help = page.getByRole('dialog');
  await expect(help.getByRole('row', { name: /^M match: click curve A/ })).toBeVisible();
  await expect(help.getByRole('row', { name: /^J blend: click two curve ends/ })).toBeVisible();
});
