import { describe, expect, it } from 'vitest';
import type { Analysis } from '../api/types';
import { fixFinBase, type ViewSettings } from './curves';

// A quarter circle of radius r sampled at n points: κ = 1/r, τ as given, combs of each kind.
function quarterCircle(r: number, tau: number, n = 9): Analysis {
  const angles = Array.from({ length: n }, (_, i) => (Math.PI / 2) * (i / (n - 1)));
  const points = angles.map((a) => [r * Math.cos(a), r * Math.sin(a), 0]);
  const comb = { base: points, tip: points };
  return {
    points,
    kappa: angles.map(() => 1 / r),
    tau: angles.map(() => tau),
    combs: { curvature: comb, torsion: comb, normal: comb },
  } as unknown as Analysis;
}

describe('fin drawing factors', () => {
  it('draws the longest curvature fin at 15 % of the extent and unit fins at 10 %, once', () => {
    const s: ViewSettings = { fins: ['curvature'], scale: 1, samples: 9, frames: false };
    const r = 10;
    const extent = Math.hypot(r, r); // the quarter circle's bounding box diagonal
    const base = fixFinBase(s, quarterCircle(r, 0));
    expect(base.curvature! * (1 / r)).toBeCloseTo(0.15 * extent, 12);
    expect(base.normal).toBeCloseTo(0.1 * extent, 12);
    // τ = 0 everywhere: no factor yet (it would be infinite) …
    expect(base.torsion).toBeUndefined();
    // … until the comb has a size; the curvature factor stays as first fixed, so combs compare across edits.
    const again = fixFinBase(s, quarterCircle(2 * r, 0.05));
    expect(again.curvature).toBe(base.curvature);
    expect(again.torsion! * 0.05).toBeCloseTo(0.15 * Math.hypot(2 * r, 2 * r), 12);
  });
});
