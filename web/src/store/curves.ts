// What the page keeps per curve besides the server's data (its view
// settings) and what it reads off a curve file without computing geometry:
// its handles and which fins carry nothing on a planar curve. Below the App,
// the panels and the tools, so they share it without importing app.ts.

import type { CurveFile, FinKind } from '../api/types';
import { toVec3 } from '../viewport/viewports';
import type { Vec3 } from '../viewport/math';

export interface ViewSettings {
  fins: FinKind[];
  /** The user's fin scale, relative to `finBase`. */
  scale: number;
  /**
   * Drawing factor per fin kind, fixed when first needed (so combs compare
   * across edits): the longest curvature (torsion, Combescure) fin is 15 % of
   * the curve's extent, unit fins (normal, binormal, Bishop) 10 %. Without it a fin of
   * κ = 0.01 at scale 1 is 0.01 long: invisible.
   */
  finBase?: Partial<Record<FinKind, number>>;
  samples: number;
  frames: boolean;
}

export const ALL_FINS: FinKind[] = [
  'curvature',
  'torsion',
  'normal',
  'binormal',
  'bishop-u',
  'bishop-v',
  'combescure',
];

/** Fins that carry nothing on a planar curve (τ = 0): torsion, binormal (8.4, 8.6), Combescure (8.3, 8.5). */
export const SPACE_FINS: ReadonlySet<FinKind> = new Set<FinKind>([
  'torsion',
  'binormal',
  'combescure',
]);

/**
 * The largest Combescure fin of a comb per unit of scale, max |Q − P| / scale = max √(1 + (τ/κ)²):
 * the server's fins measured, as the curvature fins' factor uses the server's κ.
 */
export function combescureSize(
  comb: { base: readonly (readonly number[])[]; tip: readonly (readonly number[] | null)[] },
  scale: number,
): number {
  let m = 0;
  comb.tip.forEach((q, i) => {
    const b = comb.base[i];
    if (q && b) m = Math.max(m, Math.hypot(...[0, 1, 2].map((k) => (q[k] ?? 0) - (b[k] ?? 0))));
  });
  return scale > 0 ? m / scale : 0;
}

/** Handles (control points or data points) of a curve file: what a drag moves. */
export function handlesOf(curve: CurveFile | undefined): Vec3[] {
  if (!curve) return [];
  switch (curve.kind) {
    case 'nurbs':
    case 'bezier':
      return curve.control_points.map(toVec3);
    case 'interpolated':
    case 'hermite':
      return curve.points.map(toVec3);
    case 'law':
    case 'natural':
      return [];
  }
}
