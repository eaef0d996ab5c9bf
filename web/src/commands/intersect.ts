// Intersect: where two curves of the document meet, or where one meets itself
// (POST /api/intersect, the server's `hula intersect`). Nothing is stored: the
// tool marks the points and the status line reads them out, each with its
// parameters (t1 on the first curve, t2 on the second) and its coordinates.

import type { IntersectionResult } from '../api/types';
import type { Editor } from '../editor/editor';

/** One meeting point: its parameter on each curve and where it is. */
export interface Meeting {
  readonly t1: number;
  readonly t2: number;
  readonly point: [number, number, number];
  readonly kind: 'crossing' | 'tangent';
}

const g = (x: number): string => String(Number(x.toPrecision(6)));

/** The status line's reading of the meeting points (the first `shown` of them, then how many more). */
export function meetingText(
  a: string,
  b: string | null,
  meetings: readonly Meeting[],
  overlaps: number,
  shown = 3,
): string {
  const head = b === null ? `Intersect ${a} with itself` : `Intersect ${a} × ${b}`;
  const over = overlaps > 0 ? `, ${overlaps} overlap(s)` : '';
  if (meetings.length === 0) return `${head}: no point${over}`;
  const list = meetings
    .slice(0, shown)
    .map((m) => `(t1 ${g(m.t1)}, t2 ${g(m.t2)}) at (${m.point.map(g).join(', ')})`)
    .join('; ');
  const more = meetings.length > shown ? `; … ${meetings.length - shown} more` : '';
  return `${head}: ${meetings.length} point(s)${over}: ${list}${more}`;
}

/** The server's answer as meeting points, in the order of the first curve's parameter. */
export function meetingsOf(result: IntersectionResult): Meeting[] {
  return result.points
    .map((p) => ({
      t1: p.s,
      t2: p.t,
      point: [p.point[0] ?? 0, p.point[1] ?? 0, p.point[2] ?? 0] as [number, number, number],
      kind: p.kind,
    }))
    .sort((x, y) => x.t1 - y.t1);
}

/** The meeting points of curves `a` and `b` (b null: a with itself), or undefined (the status says why). */
export async function intersectCurves(
  ed: Editor,
  a: string,
  b: string | null,
): Promise<Meeting[] | undefined> {
  const ca = ed.store.entities.get(a)?.curve;
  const cb = b === null ? undefined : ed.store.entities.get(b)?.curve;
  if (!ca || (b !== null && !cb)) {
    ed.setStatus(`Intersect: ${!ca ? a : String(b)} is not a curve of this document`, true);
    return undefined;
  }
  const result = await ed.run(
    () => ed.client.intersect(cb ? { a: ca, b: cb } : { a: ca }),
    'Intersect',
  );
  if (!result) return undefined;
  const meetings = meetingsOf(result);
  ed.setStatus(
    meetingText(ed.nameOf(a), b === null ? null : ed.nameOf(b), meetings, result.overlaps.length),
  );
  return meetings;
}
