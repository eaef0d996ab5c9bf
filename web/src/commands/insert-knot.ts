// Insert a knot into the selected curve at the hovered sample's parameter,
// else mid-span (the curve keeps its shape; one undo step).

import type { Editor } from '../editor/editor';
import { midSpan } from '../tools/tools';

export async function insertKnot(ed: Editor): Promise<void> {
  const label = ed.needSelection('Insert knot');
  if (!label) return;
  const a = ed.store.analyses.get(label);
  const hovered = ed.hovered !== null && a ? a.t[ed.hovered] : undefined;
  const c = ed.store.entities.get(label)?.curve;
  const t = a?.t ?? [];
  const u =
    hovered ??
    (c?.kind === 'nurbs' ? midSpan(c.knots) : 0.5 * ((t[0] ?? 0) + (t[t.length - 1] ?? 1)));
  const reply = await ed.run(() => ed.client.insertKnot(ed.store.name, label, u), 'Insert knot');
  if (!reply) return;
  ed.applyReply(reply);
  ed.setStatus(`Inserted a knot at t = ${Number(u.toPrecision(6))} into ${ed.nameOf(label)}`);
}
