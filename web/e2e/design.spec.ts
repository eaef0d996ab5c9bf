// Design by curvature keeps the designer's constraints (issue 21 item 4): a
// drag of the κ graph up by 6 px at 30 % of the length of a 4-point S-spline
// and of the thesis's Example 1 corner keeps both end points and end tangents
// within 1e-9, keeps the inflection count, leaves a curve with at most twice
// the original's handles, and raises the curvature at the dragged arc length
// (the same fraction of the edited curve's own length) by about what the drag
// asked — every check over the server's API.
import { test } from '@playwright/test';
import type { Analysis, CurveFile } from '../src/api/types';
import {
  addCurve,
  analysis,
  api,
  entity,
  expect,
  fairingExamples,
  history,
  idle,
  needsDocuments,
  newDoc,
  openApp,
  shot,
} from './fixtures';

const sSpline: CurveFile = {
  kind: 'interpolated',
  points: [
    [0, 0],
    [40, 40],
    [80, -40],
    [120, -40],
  ],
};
// The issue's S: four points from (−120, 40) to (120, −40), one inflection.
const issueS: CurveFile = {
  kind: 'interpolated',
  points: [
    [-120, 40],
    [-40, 40],
    [40, -40],
    [120, -40],
  ],
};
// A space curve (a twisted cubic, ~1,000 units across: τ ≠ 0, κ > 0 everywhere).
const spaceBezier: CurveFile = {
  kind: 'bezier',
  control_points: [
    [0, 0, 0],
    [300, 400, 100],
    [700, 400, 300],
    [1000, 0, 600],
  ],
  weights: null,
};
// Thesis 7.4.2 Example 1 (examples/workspace/example1-corner.json): three points around a corner.
const example1 = fairingExamples.find((e) => e.name === 'example1')!.curve;

/** The S-spline scaled by `k` (sizes 1 and 1,000 units: the drag is in pixels of the graph's own scale). */
function scaled(c: CurveFile, k: number): CurveFile {
  return {
    ...c,
    points: (c as { points: number[][] }).points.map((p) => p.map((x) => x * k)),
  } as CurveFile;
}

/** The points a designer drags: an interpolated or Hermite curve's points, a Bézier's or NURBS's control points. */
function handlePoints(c: CurveFile): number[][] {
  if (c.kind === 'interpolated' || c.kind === 'hermite') return c.points;
  if (c.kind === 'nurbs' || c.kind === 'bezier') return c.control_points;
  return [];
}
const handles = (c: CurveFile): number => handlePoints(c).length || Infinity;

const inflections = (a: Analysis): number =>
  a.features.filter((f) => f.kind === 'inflection').length;

/** Column `ys` at abscissa x of the increasing column `xs`, linear between samples. */
function at(xs: readonly number[], ys: readonly (number | null)[], x: number): number {
  const i = Math.min(
    xs.length - 1,
    Math.max(
      1,
      xs.findIndex((v) => v >= x),
    ),
  );
  const f = (x - xs[i - 1]!) / (xs[i]! - xs[i - 1]!);
  return ys[i - 1]! + f * (ys[i]! - ys[i - 1]!);
}

const dist = (p: readonly number[], q: readonly number[]): number =>
  Math.hypot(...[0, 1, 2].map((k) => (p[k] ?? 0) - (q[k] ?? 0)));

const cases: [string, CurveFile, readonly ('tangent' | 'curvature')[]][] = [
  ['S-spline', sSpline, ['tangent', 'curvature']],
  ['Example 1', example1, ['tangent', 'curvature']],
  ["issue's S", issueS, ['tangent']],
  ['S-spline at 1 unit', scaled(sSpline, 1 / 120), ['tangent']],
  ['S-spline at 1,000 units', scaled(sSpline, 1000 / 120), ['tangent']],
  ['space Bézier', spaceBezier, ['tangent', 'curvature']],
];

for (const [name, curve, holds] of cases) {
  for (const hold of holds) {
    test(`κ-graph drag on the ${name} keeps its ends (${hold})`, async ({ page }) => {
      needsDocuments();
      const doc = await newDoc('design');
      const label = await addCurve(doc, name, curve);
      await openApp(page, doc);
      await page.evaluate((l) => {
        window.__hula.app.select(l);
      }, label);
      await idle(page);
      await page.locator('#design-drag').check();
      await page.locator('#design-hold').selectOption(hold);
      const a0 = await analysis(doc, label, { features: true });
      const length = a0.s[a0.s.length - 1]!;
      const s0 = 0.3 * length;
      const k0 = at(a0.s, a0.kappa, s0);
      // The drag: 6 px up at 30 % of the length; Δκ is what 6 px are on the graph's scale.
      const p0 = await page.evaluate(([s, k]) => window.__hula.app.graphs[0]!.toPixels(s, k), [
        s0,
        k0,
      ] as const);
      const p1 = await page.evaluate(([s, k]) => window.__hula.app.graphs[0]!.toPixels(s, k), [
        s0,
        k0 + 1e-3,
      ] as const);
      const asked = (6 / (p0!.top - p1!.top)) * 1e-3;
      const steps0 = (await history(doc)).steps.length;
      await page.mouse.move(p0!.left, p0!.top);
      await page.mouse.down();
      await page.mouse.move(p0!.left, p0!.top - 3);
      await page.mouse.move(p0!.left, p0!.top - 6);
      await page.mouse.up();
      await idle(page);

      // One undo step, and a curve of the same kind with at most twice the handles.
      expect((await history(doc)).steps.length).toBe(steps0 + 1);
      const edited = (await entity(doc, label)).curve!;
      // An interpolated spline stays one; a Bézier stays one unless it needed a knot (then a NURBS).
      expect([curve.kind, 'nurbs']).toContain(edited.kind);
      if (curve.kind === 'interpolated') expect(edited.kind).toBe('interpolated');
      expect(handles(edited)).toBeLessThanOrEqual(2 * handles(curve));
      const a1 = await analysis(doc, label, { features: true });
      // Both end points and end tangents within 1e-9.
      const n0 = a0.points.length - 1;
      const n1 = a1.points.length - 1;
      expect(dist(a1.points[0]!, a0.points[0]!)).toBeLessThan(1e-9);
      expect(dist(a1.points[n1]!, a0.points[n0]!)).toBeLessThan(1e-9);
      expect(dist(a1.frames[0]!.T, a0.frames[0]!.T)).toBeLessThan(1e-9);
      expect(dist(a1.frames[n1]!.T, a0.frames[n0]!.T)).toBeLessThan(1e-9);
      if (hold === 'curvature') {
        expect(Math.abs(a1.kappa[0]! - a0.kappa[0]!)).toBeLessThan(1e-9);
        expect(Math.abs(a1.kappa[n1]! - a0.kappa[n0]!)).toBeLessThan(1e-9);
      }
      // The S stays an S (one inflection), the corner stays convex (none).
      expect(inflections(a1)).toBe(inflections(a0));
      // |κ| where the drag was went up by about what the drag asked, where the κ(s) graph of the edited
      // curve shows the dragged point: at the same fraction (30 %) of its own length (holding the ends
      // changes the length), asked of the server's analysis by arc length at exactly that s.
      const l1 = a1.s[a1.s.length - 1]!;
      const [k1] = (await analysis(doc, label, { at: [0.3 * l1], by: 'arclength' })).kappa;
      const movedAtSameS = k1! - k0;
      // For comparison: at the parameter the dragged point had (the edit matches κ by arc length, so a
      // feature of the profile may move in t).
      const t0 = at(a0.s, a0.t, s0);
      const p = await analysis(doc, label, { samples: 2001, by: 'parameter' });
      const movedAtSameT = at(p.t, p.kappa, t0) - k0;
      // The measured numbers (the report's table).
      console.log(
        JSON.stringify({
          curve: name,
          hold,
          kind: `${curve.kind} -> ${edited.kind}`,
          handles: `${handles(curve)} -> ${handles(edited)}`,
          inflections: `${inflections(a0)} -> ${inflections(a1)}`,
          end: a1.points[n1],
          end_point_error: dist(a1.points[n1]!, a0.points[n0]!),
          start_tangent_error: dist(a1.frames[0]!.T, a0.frames[0]!.T),
          end_tangent_error: dist(a1.frames[n1]!.T, a0.frames[n0]!.T),
          end_curvature_errors: [a1.kappa[0]! - a0.kappa[0]!, a1.kappa[n1]! - a0.kappa[n0]!],
          kappa_asked: asked,
          kappa_moved: movedAtSameS,
          kappa_moved_at_same_s: movedAtSameS,
          kappa_moved_at_same_t: movedAtSameT,
          // The same from the 200 arc-length samples (linear between them).
          kappa_moved_at_same_u: at(a1.s, a1.kappa, 0.3 * a1.s[n1]!) - k0,
          length: [length, l1],
        }),
      );
      // Measured 0.65–1.08 of the drag on the planar curves (the held ends take back the bump's turning);
      // 0.5–0.9 before the fit weighed the dragged stretch of a planar curve more.
      expect(movedAtSameS).toBeGreaterThan(0.6 * asked);
      expect(movedAtSameS).toBeLessThan(1.5 * asked);
      // A space drag's height is corrected on what the fit reaches at the dragged spot: within 5 % of the
      // drag (0.65–0.71 of it before).
      if (name === 'space Bézier')
        expect(Math.abs(movedAtSameS - asked)).toBeLessThan(0.05 * asked);
      if (name === 'S-spline' && hold === 'tangent') await shot(page, 'design-by-curvature-s');

      // Undo gives the original back.
      await api('POST', `/api/documents/${encodeURIComponent(doc)}/undo`);
      expect(handlePoints((await entity(doc, label)).curve!)).toEqual(handlePoints(curve));
    });
  }
}
