// The fairing assistant (issue 13 item 6), in chromium against the real
// server, on the thesis's 7.4.2 Example 1–3 point sets (examples/workspace):
// drag a data point twice with the assistant on (minimal curvature variation,
// tolerance 1), released at once after the last move and then held still; the
// ghost of the final position (its data points are the
// entity's, read over the API) is drawn with its comb and its κ overlaid on the
// graph; `A` accepts it as one undo step, and the API confirms the lower
// ∫κ′² ds and every data point within the tolerance. The latency from the last
// pointer move to the frame that draws the ghost of the final position is
// recorded in test-results/fairing-bench.json (docs/benchmarks.md); no timing
// assertion.
import { test } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import { loadavg } from 'node:os';
import type { CurveFile } from '../src/api/types';
import {
  addCurve,
  analysis,
  api,
  entity,
  expect,
  fairingExamples as examples,
  history,
  idle,
  needsDocuments,
  newDoc,
  openApp,
  openFairing,
  pixelOf,
  shot,
} from './fixtures';

interface Preview {
  revision: number;
  energy_before: number;
  energy_after: number;
  max_deviation: number;
}

const preview = (doc: string, label: string, tolerance: number): Promise<Preview> =>
  api<Preview>('POST', `/api/documents/${encodeURIComponent(doc)}/entities/${label}/fair-preview`, {
    tolerance,
  });

const pointsOf = (c: CurveFile): number[][] =>
  (c as { points: number[][] }).points.map((p) => [p[0] ?? 0, p[1] ?? 0, p[2] ?? 0]);

test('fairing assistant: ghost after a drag, accepted with A (Examples 1–3)', async ({ page }) => {
  needsDocuments();
  // Each pointer move takes seconds of a core when the 2-core machine is shared (load 20+).
  test.setTimeout(360_000);
  const tolerance = 1;
  const latencies: number[] = [];
  const roundTrips: number[] = [];
  const server: number[] = [];
  const energies: { example: string; before: number; after: number }[] = [];
  for (const example of examples) {
    const { doc, label } = await openFairing(
      page,
      `fair-${example.name}`,
      example.name,
      example.curve,
      tolerance,
    );
    // Small drags off the grid: with Snap on, a few pixels can land on the same grid point.
    await page.locator('#snap').uncheck();
    await idle(page);

    // Two drags of the corner; after each, the ghost of the final position and its latency.
    const steps0 = (await history(doc)).steps.length;
    let point = pointsOf(example.curve)[example.point]!;
    for (let drag = 0; drag < 2; drag++) {
      const from = await pixelOf(page, 'top', point as [number, number, number]);
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      for (let i = 1; i <= 4; i++) await page.mouse.move(from.x + 2 * i, from.y - 3 * i);
      // The second drag rests with the button held: the ghost of the held position comes once the
      // pointer stops, before the release (which then asks nothing more: the ghost is of that position).
      let held = 0;
      if (drag === 1) {
        await expect
          .poll(() =>
            page.evaluate(
              ([l, k]) => {
                const app = window.__hula.app;
                const ghost = app.fairing.preview?.result.data_points[k];
                const curve = app.heldCurve(l) as { points: number[][] } | undefined;
                const p = curve?.points[k];
                // ... and drawn: nothing asked or scheduled, no frame pending.
                return (
                  !!ghost &&
                  !!p &&
                  Math.hypot(ghost[0]! - p[0]!, ghost[1]! - p[1]!) < 1e-9 &&
                  !app.fairing.busy &&
                  !app.viewports.renderPending
                );
              },
              [label, example.point] as const,
            ),
          )
          .toBe(true);
        held = await page.evaluate(() => window.__hula.app.fairing.latencies.length);
      }
      await page.mouse.up();
      await idle(page);
      const state = await page.evaluate(() => {
        const f = window.__hula.app.fairing;
        return {
          dataPoints: f.preview?.result.data_points,
          latency: f.latencies[f.latencies.length - 1],
          timing: f.timings[f.timings.length - 1],
        };
      });
      // The ghost on screen is of the curve the server now holds: its data points are the entity's.
      const stored = pointsOf((await entity(doc, label)).curve!);
      expect(stored[example.point]).not.toEqual(point);
      if (drag === 1)
        expect(await page.evaluate(() => window.__hula.app.fairing.latencies.length)).toBe(held);
      expect(state.dataPoints).toHaveLength(stored.length);
      state.dataPoints!.forEach((p, k) => {
        expect(Math.hypot(...p.map((x, j) => x - stored[k]![j]!))).toBeLessThan(1e-9);
      });
      latencies.push(state.latency!);
      roundTrips.push(state.timing!.roundTripMs);
      server.push(state.timing!.serverMs);
      point = stored[example.point]!;
    }
    expect((await history(doc)).steps.length).toBe(steps0 + 2);

    // The ghost is drawn with its comb, its κ is overlaid on the κ graph, and it is fairer (API).
    const edited = pointsOf((await entity(doc, label)).curve!);
    const ghost = await page.evaluate(() => window.__hula.app.fairing.preview!.result);
    expect(ghost.energy_after).toBeLessThan(ghost.energy_before);
    const overlay = await page.evaluate(() =>
      Array.from(window.__hula.app.graphs[0]!.overlay ?? []),
    );
    const kappaGhost = ghost.analysis!.kappa;
    expect(overlay.length).toBeGreaterThan(0);
    expect(Math.abs(overlay[0]! - kappaGhost[0]!)).toBeLessThan(1e-9);
    const api0 = await preview(doc, label, tolerance);
    expect(api0.energy_before).toBeCloseTo(ghost.energy_before, 9);
    if (example.name === 'example3') await shot(page, 'fairing-ghost');

    // Accept with A: one new history step; the stored curve has the ghost's lower energy and every
    // data point within the tolerance of the edited curve's.
    await page.locator('#viewports .view[data-view="top"]').focus();
    await page.keyboard.press('a');
    await idle(page);
    expect((await history(doc)).steps.length).toBe(steps0 + 3);
    const accepted = pointsOf((await entity(doc, label)).curve!);
    expect(accepted).toHaveLength(edited.length);
    accepted.forEach((p, k) => {
      expect(Math.hypot(...p.map((x, j) => x - edited[k]![j]!))).toBeLessThanOrEqual(tolerance);
    });
    const after = await preview(doc, label, tolerance);
    expect(after.energy_before).toBeLessThan(api0.energy_before);
    expect(after.energy_before).toBeCloseTo(ghost.energy_after, 6);
    energies.push({
      example: example.name,
      before: api0.energy_before,
      after: after.energy_before,
    });
  }

  const sorted = [...latencies].sort((a, b) => a - b);
  const mid = sorted.length / 2;
  const results = {
    fairing_ghost_latency_ms: latencies,
    fairing_ghost_latency_median_ms:
      (sorted[Math.floor(mid - 0.5)]! + sorted[Math.ceil(mid - 0.5)]!) / 2,
    fairing_ghost_latency_max_ms: sorted[sorted.length - 1]!,
    fairing_preview_round_trip_ms: roundTrips,
    fairing_preview_server_ms: server,
    fairing_energies: energies,
    load_average_1min: loadavg()[0]!,
  };
  mkdirSync('test-results', { recursive: true });
  writeFileSync('test-results/fairing-bench.json', JSON.stringify(results, null, 2));
  console.log('fairing', JSON.stringify(results));
});

// Hold ends: with "end points and tangents" the accepted ghost of a wavy clamped cubic NURBS keeps its
// first two and last two control points within 1e-9 (so its end points and, C′(a) ∝ P1 − P0 and
// C′(b) ∝ Pn − Pn−1 on the same knots, its end tangents), while inner points move and ∫κ′² ds drops;
// with "end points", Example 3's accepted ghost starts and ends where it did (server analysis, 1e-9).
test('fairing assistant: hold ends keeps the end points and tangents', async ({ page }) => {
  needsDocuments();
  test.setTimeout(180_000);
  const n = 12;
  const wavy: CurveFile = {
    kind: 'nurbs',
    degree: 3,
    knots: [0, 0, 0, 0, ...Array.from({ length: n - 4 }, (_, i) => (i + 1) / (n - 3)), 1, 1, 1, 1],
    control_points: Array.from({ length: n }, (_, i) => [
      10 * i,
      12 * Math.sin(0.9 * i) + (i % 3),
      0,
    ]),
  };
  const cases: { curve: CurveFile; hold: string; name: string }[] = [
    { curve: wavy, hold: 'tangents', name: 'wavy' },
    { curve: examples[2]!.curve, hold: 'points', name: 'example3' },
  ];
  for (const c of cases) {
    const doc = await newDoc(`fair-hold-${c.name}`);
    const label = await addCurve(doc, c.name, c.curve);
    await openApp(page, doc);
    await page.evaluate((l) => {
      window.__hula.app.select(l);
    }, label);
    await page.locator('#fair-tolerance').fill('2');
    await page.locator('#fair-tolerance').dispatchEvent('change');
    await page.locator('#fair-hold').selectOption(c.hold);
    await page.locator('#fair-on').check();
    await expect
      .poll(() =>
        page.evaluate(() => {
          const r = window.__hula.app.fairing.preview?.result;
          return r ? r.energy_after < r.energy_before && r.hold : null;
        }),
      )
      .toBe(c.hold);
    await idle(page);
    if (c.name === 'wavy') await shot(page, 'fairing-hold-ends');
    const ghostBefore = await page.evaluate(
      () => window.__hula.app.fairing.preview!.result.energy_before,
    );
    const before = await analysis(doc, label, { by: 'parameter', samples: 3 });
    await page.locator('#viewports .view[data-view="top"]').focus();
    await page.keyboard.press('a');
    await idle(page);
    const after = await analysis(doc, label, { by: 'parameter', samples: 3 });
    for (const i of [0, 2])
      expect(Math.hypot(...after.points[i]!.map((x, k) => x - before.points[i]![k]!))).toBeLessThan(
        1e-9,
      );
    // The stored curve is the fairer ghost.
    expect((await preview(doc, label, 2)).energy_before).toBeLessThan(0.999 * ghostBefore);
    if (c.name === 'wavy') {
      const got = (await entity(doc, label)).curve as { control_points: number[][] };
      const want = (wavy as { control_points: number[][] }).control_points;
      for (const k of [0, 1, n - 2, n - 1])
        expect(Math.hypot(...got.control_points[k]!.map((x, j) => x - want[k]![j]!))).toBeLessThan(
          1e-9,
        );
      const moved = got.control_points.map((p, k) =>
        Math.hypot(...p.map((x, j) => x - want[k]![j]!)),
      );
      expect(Math.max(...moved)).toBeGreaterThan(1e-3);
    }
  }
});
