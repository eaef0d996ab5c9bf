// Performance figures of issues 13 and 23, measured in chromium against the
// real server and written to test-results/bench.json (docs/benchmarks.md
// quotes them): the drag of a 100-control-point curve with 200 curvature fins
// and the κ graph, snap off, counted by the page's own counters (frames that
// redrew curve, fins and graph at a new position, per second of drag and per
// pointer move that changed the point; pointer-to-redraw p95), asserted against
// issue 23's targets; the old rAF probe's figure beside them; the fairing
// assistant's ghost after the pointer stops (24 drags, asserted at load ≤ 4);
// first load; the gzipped bundle size.
import { test } from '@playwright/test';
import { readdirSync, readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import { loadavg } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import {
  addCurve,
  analysis,
  base,
  entity,
  expect,
  fairingExamples,
  idle,
  needsDocuments,
  newDoc,
  openApp,
  openFairing,
  pixelOf,
  token,
} from './fixtures';

const results: Record<string, number> = {};

// The machine is shared: its load (1-minute average, as `uptime`) goes with the figures.
test.beforeAll(() => {
  results['load_average_start'] = loadavg()[0]!;
});

test.afterAll(() => {
  results['load_average_end'] = loadavg()[0]!;
  mkdirSync('test-results', { recursive: true });
  writeFileSync('test-results/bench.json', JSON.stringify(results, null, 2));
  console.log('bench', JSON.stringify(results));
});

test('bundle size, gzipped', () => {
  const dir = join('dist', 'assets');
  let total = 0;
  for (const f of readdirSync(dir))
    total += gzipSync(readFileSync(join(dir, f)), { level: 9 }).length;
  total += gzipSync(readFileSync(join('dist', 'index.html')), { level: 9 }).length;
  results['bundle_gzip_bytes'] = total;
  expect(total).toBeGreaterThan(0);
});

test('first load', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('load');
  const label = await addCurve(doc, 'arch', {
    kind: 'bezier',
    control_points: [
      [0, 0, 0],
      [40, 40, 0],
      [80, 0, 0],
    ],
    weights: null,
  });
  // Warm the server once, then measure navigation start to the idle document.
  await openApp(page, doc);
  const times: number[] = [];
  for (let i = 0; i < 5; i++) {
    const t0 = Date.now();
    await page.goto(`${base()}/?token=${token()}#doc=${doc}`);
    await idle(page);
    times.push(Date.now() - t0);
  }
  // Loaded means drawn: the curve is in the store with the server's analysis of it.
  expect(
    await page.evaluate((l) => window.__hula.app.store.analyses.get(l)?.points.length, label),
  ).toBe(200);
  times.sort((a, b) => a - b);
  results['first_load_ms_median'] = times[2]!;
  results['first_load_ms_max'] = times[4]!;
});

test('drag a point of a 100-control-point curve with fins and the κ graph', async ({ page }) => {
  needsDocuments();
  // Each pointer move waits for the page to take it: on a loaded 2-core machine with software
  // WebGL, 180 moves can outlast the default 60 s.
  test.setTimeout(240_000);
  const doc = await newDoc('perf');
  const n = 100;
  const cps = Array.from({ length: n }, (_, i) => [i * 2, 20 * Math.sin(i / 7), 0]);
  const knots = [
    0,
    0,
    0,
    0,
    ...Array.from({ length: n - 4 }, (_, i) => (i + 1) / (n - 3)),
    1,
    1,
    1,
    1,
  ];
  const label = await addCurve(doc, 'c100', {
    kind: 'nurbs',
    degree: 3,
    knots,
    control_points: cps,
    weights: null,
  });
  await openApp(page, doc);
  await page.evaluate((l) => {
    const app = window.__hula.app;
    app.select(l);
    const s = app.settingsOf(l);
    s.fins = ['curvature'];
    s.samples = 200;
    app.refreshAnalysis(l);
  }, label);
  await idle(page);
  await page.keyboard.press('1'); // the top view alone, as a designer drags
  await idle(page);
  await page.evaluate(() => {
    window.__hula.app.fitAll();
  });
  await idle(page);
  const start = await pixelOf(page, 'top', cps[50] as [number, number, number]);
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  // A rAF probe counts the frames the page manages while the drag runs (the
  // display rate is the ceiling) and the longest gap between two frames.
  await page.evaluate(() => {
    const probe = { frames: 0, maxGap: 0, last: performance.now(), on: true };
    (window as unknown as { __probe: typeof probe }).__probe = probe;
    const tick = (t: number): void => {
      if (!probe.on) return;
      probe.frames++;
      probe.maxGap = Math.max(probe.maxGap, t - probe.last);
      probe.last = t;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  // The load the drag itself ran under (the 1-minute average when it starts), beside the figures.
  results['drag_load_average'] = loadavg()[0]!;
  const frames0 = await page.evaluate(() => window.__hula.app.viewports.frames);
  expect(await page.evaluate(() => window.__hula.app.viewports.snap)).toBe(false);
  const t0 = Date.now();
  const moves = 180;
  // Paced at 50 moves a second (a hand's drag), each to a new pixel.
  for (let i = 1; i <= moves; i++) {
    await page.mouse.move(start.x + 60 * Math.sin(i / 15), start.y + 40 * Math.sin(i / 9));
    const wait = t0 + i * 20 - Date.now();
    if (wait > 0) await page.waitForTimeout(wait);
  }
  const elapsed = (Date.now() - t0) / 1000;
  // Let the last frame land before the counters are read.
  await page.evaluate(
    () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))),
  );
  const stats = await page.evaluate(() => ({ ...window.__hula.app.dragStats }));
  const frames1 = await page.evaluate(() => window.__hula.app.viewports.frames);
  const probe = await page.evaluate(() => {
    const p = (window as unknown as { __probe: { frames: number; maxGap: number; on: boolean } })
      .__probe;
    p.on = false;
    return { frames: p.frames, maxGap: p.maxGap };
  });
  const lat = await page.evaluate(() => [...window.__hula.app.latencies]);
  const preview = await page.evaluate((l) => {
    const a = window.__hula.app.analysisOf(l)!;
    return { kappa: a.kappa, points: a.points };
  }, label);
  const split = await page.evaluate(() => {
    const f = window.__hula.app.frameSplit;
    return { waits: [...f.waits], works: [...f.works], early: [...f.early] };
  });
  for (const [name, xs] of [
    ['pointer_to_frame_start_ms', split.waits],
    ['frame_work_ms', split.works],
    ['work_before_frame_ms', split.early],
  ] as const) {
    xs.sort((a, b) => a - b);
    results[`${name}_p50`] = xs[Math.floor(xs.length * 0.5)] ?? NaN;
    results[`${name}_p95`] = xs[Math.floor(xs.length * 0.95)] ?? NaN;
  }
  const serverLat = await page.evaluate(() => [...window.__hula.app.serverLatencies]);
  serverLat.sort((a, b) => a - b);
  await page.mouse.up();
  await idle(page);
  lat.sort((a, b) => a - b);
  // The honest figures: frames that redrew curve, fins and κ graph at a new position.
  const dragSeconds = (stats.lastMove - stats.firstMove) / 1000;
  results['drag_changed_moves'] = stats.moves;
  results['drag_changed_moves_per_second'] = stats.moves / dragSeconds;
  results['drag_position_redraws'] = stats.redraws;
  results['drag_position_redraws_per_second'] = stats.redraws / dragSeconds;
  results['drag_redraws_per_changed_move'] = stats.redraws / stats.moves;
  results['drag_moves'] = moves;
  results['drag_seconds'] = elapsed;
  // The old figure (issue 13): a rAF probe that ticks whether or not anything is redrawn.
  results['drag_frames_per_second_raf_probe'] = probe.frames / elapsed;
  results['drag_longest_frame_gap_ms'] = probe.maxGap;
  results['drag_redraws_per_second'] = (frames1 - frames0) / elapsed;
  results['drag_moves_per_second'] = moves / elapsed;
  results['pointer_to_redraw_ms_p50'] = lat[Math.floor(lat.length * 0.5)] ?? NaN;
  results['pointer_to_redraw_ms_p95'] = lat[Math.floor(lat.length * 0.95)] ?? NaN;
  results['pointer_to_server_reply_ms_p50'] = serverLat[Math.floor(serverLat.length * 0.5)] ?? NaN;
  results['pointer_to_server_reply_ms_p95'] = serverLat[Math.floor(serverLat.length * 0.95)] ?? NaN;
  results['server_replies_during_drag'] = serverLat.length;
  expect(lat.length).toBeGreaterThan(10);
  // Issue 23's targets: snap off, every move changes the point; one redraw per such move up to
  // 50 a second (at least 50 a second when the pointer moves faster); p95 pointer-to-redraw ≤ 25 ms.
  expect(stats.moves).toBeGreaterThanOrEqual(moves - 2);
  const owed = Math.min(stats.moves, 50 * dragSeconds);
  expect(stats.redraws).toBeGreaterThanOrEqual(Math.floor(0.95 * owed));
  // What the frame itself still does once prepare() has taken the pointer event (evaluation,
  // graphs, the curve's buffers): the views' render.
  expect(results['frame_work_ms_p95']).toBeLessThanOrEqual(8);
  // p95 pointer-to-redraw ≤ 25 ms. The wait for the frame is up to one display period (16.7 ms)
  // plus however long the machine's other work holds the page back. With two to four CPU or
  // memory burners beside it (load 2.3–6.6) the p95 was 16.0–19.8 ms, at the 60 Hz floor; other
  // sessions' builds beside it gave 26.1 ms at load 4.7 and 27–29 ms at 6–9 (docs/benchmarks.md).
  // So the target is asserted up to a load of 4 on the two cores, and a regression bound of three
  // display periods above that; the figures and the load are reported either way.
  const quiet = results['drag_load_average'] <= 4;
  results['pointer_to_redraw_target_asserted'] = quiet ? 1 : 0;
  expect(results['pointer_to_redraw_ms_p95']).toBeLessThanOrEqual(quiet ? 25 : 50);
  // The curve drawn at the last move (the page's own evaluation) is the server's analysis of
  // the final position, to rounding.
  const server = await analysis(doc, label);
  expect(preview.kappa).toHaveLength(server.kappa.length);
  preview.kappa.forEach((k, i) => {
    expect(Math.abs(k! - server.kappa[i]!)).toBeLessThan(1e-9 * Math.max(1, Math.abs(k!)));
  });
  preview.points.forEach((p, i) => {
    for (let k = 0; k < 3; k++) expect(Math.abs(p[k]! - server.points[i]![k]!)).toBeLessThan(1e-8);
  });
});

// The fairing assistant's ghost (issue 13 item 6, issue 23): from the last pointer move of a drag to the
// frame that draws the first ghost of that final position (FairingAssistant's short-budget answer,
// within the tolerance; the full budget's replaces it afterwards), over 24 drags (8 of each of the thesis's 7.4.2
// Examples 1–3, minimal curvature variation, tolerance 1, released at once after 4 moves), so that the
// p95 is not the largest sample. Issue 23's target, p95 ≤ 150 ms, is asserted when the load at the
// first drag is ≤ 4 (two cores); the figures and the load are reported either way.
test('fairing ghost after the pointer stops, 24 drags', async ({ page }) => {
  needsDocuments();
  test.setTimeout(300_000);
  const latencies: number[] = [];
  const roundTrips: number[] = [];
  const serverMs: number[] = [];
  const refineRoundTrips: number[] = [];
  const refineServerMs: number[] = [];
  let refines = 0;
  const perExample = 8;
  for (const example of fairingExamples) {
    const { doc, label } = await openFairing(
      page,
      `ghost-${example.name}`,
      example.name,
      example.curve,
      1,
    );
    await idle(page);
    if (!('ghost_load_average' in results)) results['ghost_load_average'] = loadavg()[0]!;
    const pointOf = async (): Promise<[number, number, number]> => {
      const c = (await entity(doc, label)).curve as { points: number[][] };
      const p = c.points[example.point]!;
      return [p[0] ?? 0, p[1] ?? 0, p[2] ?? 0];
    };
    for (let drag = 0; drag < perExample; drag++) {
      const point = await pointOf();
      const from = await pixelOf(page, 'top', point);
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      // Out and back on alternate drags: the point stays near where it started.
      const sign = drag % 2 === 0 ? 1 : -1;
      for (let i = 1; i <= 4; i++)
        await page.mouse.move(from.x + sign * 2 * i, from.y - sign * 3 * i);
      const before = await page.evaluate(() => window.__hula.app.fairing.latencies.length);
      await page.mouse.up();
      await idle(page);
      const state = await page.evaluate(() => {
        const f = window.__hula.app.fairing;
        return {
          count: f.latencies.length,
          dataPoints: f.preview?.result.data_points,
          latency: f.latencies[f.latencies.length - 1],
          timing: f.timings[f.timings.length - 1],
          final: f.preview?.final,
          refines: f.refineTimings.length,
          refine: f.refineTimings[f.refineTimings.length - 1],
        };
      });
      // The latest ghost is of the curve the server holds after the drag (its data points), and its
      // latency was recorded after the release or while the pointer rested before it.
      const stored = ((await entity(doc, label)).curve as { points: number[][] }).points;
      expect(stored[example.point]).not.toEqual(point);
      expect(state.count).toBeGreaterThanOrEqual(before);
      expect(state.count).toBeGreaterThan(0);
      state.dataPoints!.forEach((p, k) => {
        const q = stored[k]!;
        expect(Math.hypot(p[0]! - (q[0] ?? 0), p[1]! - (q[1] ?? 0))).toBeLessThan(1e-9);
      });
      // Once quiet, the ghost on screen is the full budget's (the short budget's first ghost was
      // replaced) or the first one when its optimisation converged within the short budget.
      expect(state.final).toBe(true);
      latencies.push(state.latency!);
      roundTrips.push(state.timing!.roundTripMs);
      serverMs.push(state.timing!.serverMs);
      if (state.refines > refines) {
        refineRoundTrips.push(state.refine!.roundTripMs);
        refineServerMs.push(state.refine!.serverMs);
      }
      refines = state.refines;
    }
  }
  results['ghost_load_average_end'] = loadavg()[0]!;
  const sorted = [...latencies].sort((a, b) => a - b);
  const rt = [...roundTrips].sort((a, b) => a - b);
  const n = sorted.length;
  results['ghost_drags'] = n;
  results['ghost_latency_ms_p50'] = sorted[Math.floor(n * 0.5)]!;
  results['ghost_latency_ms_p95'] = sorted[Math.floor(n * 0.95)]!;
  results['ghost_latency_ms_max'] = sorted[n - 1]!;
  results['ghost_round_trip_ms_p50'] = rt[Math.floor(n * 0.5)]!;
  results['ghost_round_trip_ms_p95'] = rt[Math.floor(n * 0.95)]!;
  results['ghost_server_ms_max'] = Math.max(...serverMs);
  // The full-budget ghosts that replaced a first one (after the latency clock stopped).
  const rr = [...refineRoundTrips].sort((a, b) => a - b);
  results['ghost_refined'] = rr.length;
  results['ghost_refine_round_trip_ms_p50'] = rr[Math.floor(rr.length * 0.5)] ?? NaN;
  results['ghost_refine_round_trip_ms_p95'] = rr[Math.floor(rr.length * 0.95)] ?? NaN;
  results['ghost_refine_server_ms_max'] = rr.length ? Math.max(...refineServerMs) : NaN;
  console.log('ghost latencies', JSON.stringify(latencies.map((x) => Math.round(x))));
  console.log('ghost round trips', JSON.stringify(roundTrips.map((x) => Math.round(x))));
  console.log('ghost server ms', JSON.stringify(serverMs.map((x) => Math.round(x))));
  expect(n).toBe(3 * perExample);
  // Above load 4 a regression bound only (at load 16–28 the ghost took 290–520 ms, docs/benchmarks.md).
  const load = results['ghost_load_average']!;
  results['ghost_target_asserted'] = load <= 4 ? 1 : 0;
  expect(sorted[Math.floor(n * 0.95)]!).toBeLessThanOrEqual(load <= 4 ? 150 : 1000);
});
