// Clothoid: the G1 or G2 clothoid spline, or the biarc spline, through the
// selected curve's through-points or control points, open or closed (POST
// /api/clothoid, the server's `hula clothoid`), added as a new selected curve
// named after the fit: one "create" undo step; or through clicked points (the
// Clothoid tool, tools/clothoid.ts). The curve is a natural one,
// held by its curvature law (exact, not a NURBS stand-in).

import type { ClothoidAnswer, ClothoidRequest, Point } from '../api/types';
import type { Editor } from '../editor/editor';
import { closingPoints } from './close';
import { createCurve } from './create-curve';

export type ClothoidFit = NonNullable<ClothoidRequest['fit']>;

export interface ClothoidChoice {
  readonly fit: ClothoidFit;
  readonly closed: boolean;
}

/** The new curve's name: what the tool made. */
export function clothoidName(fit: ClothoidFit): string {
  return fit === 'biarc' ? 'biarc' : `clothoid-${fit}`;
}

/** The spline through the selected curve's points, added as a new curve; undefined when not (the status says why). */
export async function clothoidThrough(
  ed: Editor,
  label: string,
  choice: ClothoidChoice,
): Promise<{ label: string; answer: ClothoidAnswer } | undefined> {
  const curve = ed.store.entities.get(label)?.curve;
  if (!curve) {
    ed.setStatus(`Clothoid: ${label} is not a curve of this document`, true);
    return undefined;
  }
  const points = closingPoints(curve);
  if (!points) {
    ed.setStatus(
      `Clothoid: ${ed.nameOf(label)} is a ${curve.kind} curve, which has no points to pass through`,
      true,
    );
    return undefined;
  }
  return clothoidThroughPoints(
    ed,
    points,
    choice,
    `the ${points.length} points of ${ed.nameOf(label)}`,
  );
}

/** The spline through `points` (described as `through` in the status), added as a new selected curve. */
export async function clothoidThroughPoints(
  ed: Editor,
  points: Point[],
  choice: ClothoidChoice,
  through = `${points.length} points`,
): Promise<{ label: string; answer: ClothoidAnswer } | undefined> {
  const answer = await ed.run(
    () => ed.client.clothoid({ points, fit: choice.fit, closed: choice.closed }),
    'Clothoid',
  );
  if (!answer) return undefined;
  const made = await createCurve(ed, clothoidName(choice.fit), answer.curve);
  if (!made) return undefined;
  const what =
    choice.fit === 'biarc' ? 'biarc spline' : `${choice.fit.toUpperCase()} clothoid spline`;
  ed.setStatus(
    `Added the ${what} ${ed.nameOf(made)} through ${through}` +
      `${choice.closed ? ' (closed)' : ''}: ${answer.segments.length} segments, length ` +
      `${Number(answer.length.toPrecision(6))}`,
  );
  return { label: made, answer };
}
