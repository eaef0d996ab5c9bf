// Move a knot value of a NURBS curve (the Knots tool's drag): the curve stored
// with the new knot vector and its control points and weights as they were, with
// one PUT: one "replace" undo step.

import type { Editor } from '../editor/editor';
import type { NurbsFile } from '../tools/knots';

/** Whether the curve was stored with `knots` (else the status says why). */
export async function moveKnotValue(
  ed: Editor,
  label: string,
  knots: number[],
  from: number,
  to: number,
): Promise<boolean> {
  const curve = ed.store.entities.get(label)?.curve;
  if (curve?.kind !== 'nurbs') {
    ed.setStatus(`Knots: ${label} is not a NURBS curve of this document`, true);
    return false;
  }
  if (ed.isLocked(label)) {
    ed.setStatus(`Knots: ${ed.nameOf(label)} is locked: unlock it in the object list`, true);
    return false;
  }
  const moved: NurbsFile = { ...curve, knots };
  const reply = await ed.run(() => ed.client.putEntity(ed.store.name, label, moved), 'Move knot');
  if (!reply) return false;
  ed.applyReply(reply);
  const g = (x: number): string => String(Number(x.toPrecision(6)));
  ed.setStatus(`Moved a knot of ${ed.nameOf(label)} from ${g(from)} to ${g(to)}`);
  return true;
}
