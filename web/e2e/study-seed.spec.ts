// Studies seeded from the selected curve (issue 21 item 5): "From selection"
// for the curvature + torsion study on a space Bézier fills in that curve's
// end tangents, its own κ and τ profiles as the targets and points on it as
// the variables; the study job the page starts runs with exactly those
// (checked over the API: the job's resolved study and the curve's analysis).
import { test } from '@playwright/test';
import type { CurveFile } from '../src/api/types';
import { addCurve, analysis, api, expect, idle, needsDocuments, newDoc, openApp } from './fixtures';

// The twisted cubic of workbench.spec.ts: non-coplanar control points, so τ ≠ 0.
const P = [
  [0, 0, 0],
  [30, 40, 10],
  [70, 40, 30],
  [100, 0, 60],
];
const spaceBezier: CurveFile = { kind: 'bezier', control_points: P, weights: null };

const unit = (a: number[], b: number[]): number[] => {
  const d = [0, 1, 2].map((k) => b[k]! - a[k]!);
  const n = Math.hypot(...d);
  return d.map((x) => x / n);
};
const dist = (p: readonly number[], q: readonly number[]): number =>
  Math.hypot(...[0, 1, 2].map((k) => (p[k] ?? 0) - (q[k] ?? 0)));

interface Study {
  points: number[][];
  start_tangent: number[];
  end_tangent: number[];
  target: { samples: [number, number][] };
  torsion_target: { samples: [number, number][] };
  abscissa: string;
  nsga2: Record<string, unknown>;
  polish: boolean;
}

test('From selection seeds the curvature + torsion study from a space Bézier', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('seed');
  const label = await addCurve(doc, 'space', spaceBezier);
  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
  await page.locator('#opt-kind').selectOption('match-curvature-torsion');
  await page.locator('#opt-fill').click();
  await idle(page);
  const study = JSON.parse(await page.locator('#opt-study').inputValue()) as Study;

  // The Bézier's end tangents (closed form: along P1 − P0 and P3 − P2).
  expect(dist(study.start_tangent, unit(P[0]!, P[1]!))).toBeLessThan(1e-9);
  expect(dist(study.end_tangent, unit(P[2]!, P[3]!))).toBeLessThan(1e-9);
  // Its points lie on the curve, the first and last at its ends.
  expect(dist(study.points[0]!, P[0]!)).toBeLessThan(1e-9);
  expect(dist(study.points[study.points.length - 1]!, P[3]!)).toBeLessThan(1e-9);
  // Its own κ and τ by arc length (the server's analysis at the same abscissae) are the targets.
  expect(study.abscissa).toBe('arclength');
  const n = study.target.samples.length;
  const a = await analysis(doc, label, { samples: n, by: 'arclength' });
  const length = a.s[a.s.length - 1]!;
  let kmax = 0;
  let tmax = 0;
  for (let i = 0; i < n; i++) {
    const [u, k] = study.target.samples[i]!;
    const [, t] = study.torsion_target.samples[i]!;
    expect(Math.abs(u * length - a.s[i]!)).toBeLessThan(1e-6 * length);
    expect(Math.abs(k - a.kappa[i]!)).toBeLessThan(1e-6 * Math.abs(a.kappa[i]!) + 1e-12);
    expect(Math.abs(t - a.tau[i]!)).toBeLessThan(1e-6 * Math.abs(a.tau[i]!) + 1e-12);
    kmax = Math.max(kmax, Math.abs(k));
    tmax = Math.max(tmax, Math.abs(t));
  }
  // Not the old constant template (0.02 / 0.01): the Bézier's own maxima, closed form
  // |C′×C″|/|C′|³ and (C′×C″)·C‴/|C′×C″|² at 100,001 parameters: max κ 0.0172407, max |τ| 0.00196457.
  expect(kmax).toBeGreaterThan(0.95 * 0.017240712982831786);
  expect(kmax).toBeLessThan(1.000001 * 0.017240712982831786);
  expect(tmax).toBeGreaterThan(0.95 * 0.001964566936223929);
  expect(tmax).toBeLessThan(1.000001 * 0.001964566936223929);

  // A short run of that study: the job's resolved study carries the same tangents and targets.
  study.nsga2 = { population: 8, generations: 2 };
  study.polish = false;
  await page.locator('#opt-advanced').check(); // the study file as JSON
  await page.locator('#opt-study').fill(JSON.stringify(study));
  await page.locator('#opt-start').click();
  await expect(page.locator('#opt-info')).toHaveAttribute('data-state', 'done', {
    timeout: 45_000,
  });
  await idle(page);
  const job = await api<{ result: { result: { study: Study } } }>(
    'GET',
    `/api/jobs/${encodeURIComponent(String(await page.evaluate(() => window.__hula.app.optimise.job)))}`,
  );
  const ran = job.result.result.study;
  expect(dist(ran.start_tangent, unit(P[0]!, P[1]!))).toBeLessThan(1e-9);
  expect(dist(ran.end_tangent, unit(P[2]!, P[3]!))).toBeLessThan(1e-9);
  expect(ran.target).toEqual(study.target);
  expect(ran.torsion_target).toEqual(study.torsion_target);
  expect(ran.points).toEqual(study.points);
});
