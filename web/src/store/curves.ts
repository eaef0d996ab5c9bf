// What the page keeps per curve besides the server's data (its view
// settings) and what it reads off a curve file without computing geometry:
// its handles and which fins carry nothing on a planar curve. Below the App,
// the panels and the tools, so they share it without importing app.ts.

import type { Analysis, CurveFile, FinKind } from '../api/types';
import { boxDiagonal } from '../graphs/scale';
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

/**
 * Fix the drawing factors (ViewSettings.finBase) of the fin kinds `a` carries
 * that have none yet, from this analysis: the longest curvature, torsion or
 * Combescure fin 15 % of the curve's extent, unit fins 10 %. A comb that is
 * zero everywhere gets its factor once it has a size. Returns the factors.
 */
export function fixFinBase(s: ViewSettings, a: Analysis): Partial<Record<FinKind, number>> {
  s.finBase ??= {};
  const extent = boxDiagonal(a.points) || 1;
  const largest = (v: (number | null)[]): number =>
    Math.max(0, ...v.map((x) => (x !== null && Number.isFinite(x) ? Math.abs(x) : 0)));
  for (const kind of Object.keys(a.combs) as FinKind[]) {
    if (s.finBase[kind] !== undefined) continue;
    const m =
      kind === 'curvature'
        ? largest(a.kappa)
        : kind === 'torsion'
          ? largest(a.tau)
          : kind === 'combescure'
            ? combescureSize(a.combs[kind]!, s.scale)
            : 1;
    if (m === 0) continue; // a zero comb: fix the factor once it has a size
    const quantity = kind === 'curvature' || kind === 'torsion' || kind === 'combescure';
    s.finBase[kind] = (quantity ? 0.15 : 0.1) * (extent / m);
  }
  return s.finBase;
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
