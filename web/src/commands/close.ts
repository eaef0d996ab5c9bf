// Close: the selected curve replaced by the periodic C2 cubic through its
// through-points (an interpolated or Hermite curve) or its control points (a NURBS
// or Bézier curve) and back to the first (POST /api/interpolate-closed), stored
// over it with one PUT: one "replace" undo step.

import type { ClosedInterpolation, CurveFile, Point } from '../api/types';
import type { Editor } from '../editor/editor';

/** The points a curve is closed through (a repeated first point dropped), or null for a law or natural curve. */
export function closingPoints(c: CurveFile): Point[] | null {
  const pts = 'points' in c ? c.points : 'control_points' in c ? c.control_points : null;
  if (!pts) return null;
  const first = pts[0];
  const last = pts[pts.length - 1];
  const same =
    pts.length > 1 && first && last && first.every((x, i) => Math.abs(x - (last[i] ?? 0)) < 1e-12);
  return same ? pts.slice(0, -1) : [...pts];
}

export async function closeCurve(
  ed: Editor,
  label: string,
): Promise<ClosedInterpolation | undefined> {
  const curve = ed.store.entities.get(label)?.curve;
  if (!curve) {
    ed.setStatus(`Close: ${label} is not a curve of this document`, true);
    return undefined;
  }
  if (ed.isLocked(label)) {
    ed.setStatus(`Close: ${ed.nameOf(label)} is locked: unlock it in the object list`, true);
    return undefined;
  }
  const points = closingPoints(curve);
  if (!points) {
    ed.setStatus(
      `Close: ${ed.nameOf(label)} is a ${curve.kind} curve, which has no points to close through`,
      true,
    );
    return undefined;
  }
  const result = await ed.run(() => ed.client.interpolateClosed({ points }), 'Close');
  if (!result) return undefined;
  const name = ed.nameOf(label);
  const reply = await ed.run(
    () => ed.client.putEntity(ed.store.name, label, result.curve),
    'Close',
  );
  if (!reply) return undefined;
  ed.applyReply(reply);
  ed.select(label);
  ed.setStatus(
    `Closed ${name}: periodic C2 cubic through its ${result.points} ` +
      `${'points' in curve ? 'points' : 'control points'}, ${result.control_points} control points`,
  );
  return result;
}
