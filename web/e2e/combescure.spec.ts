// Combescure compound fins (thesis 8.3 eq. 44, appendix 8.5) in Debian's chromium against a real
// `hula serve`: selectable for a space curve, drawn in the scene, refused for a planar one.
import { test } from '@playwright/test';
import type { CurveFile } from '../src/api/types';
import { FIN_COLOURS } from '../src/viewport/viewports';
import {
  addCurve,
  analysis,
  expect,
  idle,
  needsDocuments,
  newDoc,
  openApp,
  shot,
} from './fixtures';

// The law dialog's helix (a cos t, a sin t, b t), a = 30, b = 8, two turns.
const helix: CurveFile = {
  kind: 'law',
  expression: 'vec(30*cos(t), 30*sin(t), 8*t)',
  parameter: 't',
  domain: [0, 4 * Math.PI],
};
const planar: CurveFile = {
  kind: 'interpolated',
  points: [
    [0, 0, 0],
    [40, 25, 0],
    [80, -25, 0],
    [120, 0, 0],
  ],
};

// On the helix τ/κ = b/a, so every Combescure fin Q − P = C (b/a T + B) = (0, 0, C √(a² + b²)/a) is
// the same vertical segment (the compound is the helix lifted along its axis): the server's comb at
// C = 2 against that closed form (1e-9), then the segments drawn in the scene in the Combescure
// colour: one per sample, vertical, all of the same length, 15 % of the curve's extent (the drawing
// factor of the quantity fins). A planar curve cannot select the Combescure fins (8.3: undefined).
test('Combescure fins of a space curve', async ({ page }) => {
  needsDocuments();
  const doc = await newDoc('combescure');
  const label = await addCurve(doc, 'helix', helix);
  const flat = await addCurve(doc, 'planar', planar);
  const a = await analysis(doc, label, {
    samples: 50,
    by: 'parameter',
    fins: ['combescure'],
    scale: 2,
  });
  const shift = (2 * Math.hypot(30, 8)) / 30;
  const comb = a.combs.combescure!;
  expect(comb.tip).toHaveLength(50);
  comb.tip.forEach((q, i) => {
    const p = comb.base[i]!;
    expect(Math.hypot(q![0]! - p[0]!, q![1]! - p[1]!, q![2]! - p[2]! - shift)).toBeLessThan(1e-9);
  });

  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, flat);
  await idle(page);
  await expect(page.getByRole('checkbox', { name: 'combescure fins' })).toBeDisabled();

  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
  const box = page.getByRole('checkbox', { name: 'combescure fins' });
  await expect(box).toBeEnabled();
  await box.check();
  await idle(page);
  await expect(page.locator('#viewports')).toHaveAttribute('data-fins', 'combescure');

  const drawn = await page.evaluate((l) => window.__hula.app.viewports.finSegments(l), label);
  const points = (await analysis(doc, label)).points;
  const lo = [0, 1, 2].map((k) => Math.min(...points.map((p) => p[k]!)));
  const hi = [0, 1, 2].map((k) => Math.max(...points.map((p) => p[k]!)));
  const extent = Math.hypot(...hi.map((h, k) => h - lo[k]!));
  const combescure = drawn.filter((s) => s.colour === FIN_COLOURS.combescure);
  expect(combescure.length).toBe(drawn.length);
  // The hairs: segments from a curve point straight up (the envelope's segments join two tips).
  const hairs = combescure.filter(
    (s) => Math.hypot(s.to[0] - s.from[0], s.to[1] - s.from[1]) < 1e-3,
  );
  expect(hairs).toHaveLength(200);
  for (const h of hairs) expect((h.to[2] - h.from[2]) / extent).toBeCloseTo(0.15, 4);
  await shot(page, 'combescure-helix');
});
