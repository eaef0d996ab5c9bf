// Blend: the fair G1–G3 curve between two curve ends (POST /api/blend, the
// server's answer of `hula blend`), stored as a new curve: one "create" undo
// step. The status line reports the continuity reached at both ends, ∫κ′² ds
// and the count of curvature extrema, as the server measured them.

import type { BlendResult } from '../api/types';
import type { Editor } from '../editor/editor';
import type { JoinRequest } from '../tools/join';
import { createCurve } from './create-curve';

/** The server's report of the blend stored and its label, or undefined (the status says why). */
export async function blendCurves(
  ed: Editor,
  r: JoinRequest,
): Promise<{ label: string; result: BlendResult } | undefined> {
  const a = ed.store.entities.get(r.a)?.curve;
  const b = ed.store.entities.get(r.b)?.curve;
  if (!a || !b) {
    ed.setStatus(`Blend: ${a ? r.b : r.a} is not a curve of this document`, true);
    return undefined;
  }
  const toEnd = r.toEnd ?? 'start';
  const result = await ed.run(
    () => ed.client.blend({ a, b, continuity: `G${r.continuity}`, end: r.end, to_end: toEnd }),
    'Blend',
  );
  if (!result) return undefined;
  const label = await createCurve(ed, 'blend', result.curve);
  if (!label) return undefined;
  const g = (x: string | null): string => x ?? 'below G0';
  const short = [result.start.geometric, result.end.geometric].some(
    (x) => x === null || Number(x.slice(1)) < r.continuity,
  );
  ed.setStatus(
    `Blend ${ed.nameOf(label)} from ${ed.nameOf(r.a)}'s ${r.end} to ${ed.nameOf(r.b)}'s ${toEnd}: ` +
      `${g(result.start.geometric)} and ${g(result.end.geometric)} at its ends (asked ${result.requested}), ` +
      `∫κ′² ds = ${Number(result.curvature_variation.value.toPrecision(4))}, ` +
      `${result.curvature_extrema} curvature extrem${result.curvature_extrema === 1 ? 'um' : 'a'}, ` +
      `degree ${result.degree}`,
    short,
  );
  return { label, result };
}
