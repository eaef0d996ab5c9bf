// Match: curve A's end made G0–G3 to curve B's end or to a point on B (POST
// /api/match, the server's answer of `hula match`), stored over A with one PUT:
// one "replace curve" undo step. The status line reports the continuity reached, as
// the server measured it, beside the continuity asked.

import type { MatchRequest, MatchResult } from '../api/types';
import type { Editor } from '../editor/editor';
import type { JoinRequest } from '../tools/join';

/** The server's report of the match stored, or undefined when nothing changed (the status says why). */
export async function matchCurves(ed: Editor, r: JoinRequest): Promise<MatchResult | undefined> {
  const a = ed.store.entities.get(r.a)?.curve;
  const b = ed.store.entities.get(r.b)?.curve;
  if (!a || !b) {
    ed.setStatus(`Match: ${a ? r.b : r.a} is not a curve of this document`, true);
    return undefined;
  }
  if (ed.isLocked(r.a)) {
    ed.setStatus(`Match: ${ed.nameOf(r.a)} is locked: unlock it in the object list`, true);
    return undefined;
  }
  const body: MatchRequest = { a, b, continuity: `G${r.continuity}`, end: r.end };
  if (r.at !== undefined) body.at = r.at;
  else if (r.toEnd) body.to_end = r.toEnd;
  const result = await ed.run(() => ed.client.match(body), 'Match');
  if (!result) return undefined;
  // Named before the reply replaces the curve.
  const nameA = ed.nameOf(r.a);
  const target =
    r.at !== undefined
      ? `${ed.nameOf(r.b)} at t = ${Number(r.at.toPrecision(6))}`
      : `${ed.nameOf(r.b)}'s ${r.toEnd ?? 'start'}`;
  const reply = await ed.run(() => ed.client.putEntity(ed.store.name, r.a, result.curve), 'Match');
  if (!reply) return undefined;
  ed.applyReply(reply);
  ed.select(r.a);
  const reached = result.geometric ?? 'below G0';
  const short = result.geometric === null || Number(result.geometric.slice(1)) < r.continuity;
  ed.setStatus(
    `Matched ${nameA}'s ${r.end} to ${target}: ${reached} reached (asked ${result.requested}), ` +
      `${result.moved.length} point(s) moved` +
      (result.inserted_knots > 0 ? `, ${result.inserted_knots} knot(s) inserted` : '') +
      (result.degree_elevation > 0 ? `, degree raised to ${result.degree}` : ''),
    short,
  );
  return result;
}
