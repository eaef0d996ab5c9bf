// Split the selected curve at the hovered sample's parameter, else
// mid-domain (one undo step); the first piece is selected.

import type { Editor } from '../editor/editor';

export async function split(ed: Editor): Promise<void> {
  const label = ed.needSelection('Split');
  if (!label) return;
  const t = ed.store.analyses.get(label)?.t ?? [];
  const hovered = ed.hovered !== null ? t[ed.hovered] : undefined;
  const at = hovered ?? 0.5 * ((t[0] ?? 0) + (t[t.length - 1] ?? 1));
  // Named before the reply removes it from the store.
  const name = ed.nameOf(label);
  const reply = await ed.run(() => ed.client.split(ed.store.name, label, at), 'Split');
  if (!reply) return;
  ed.applyReply(reply);
  const first = reply.labels[0];
  if (first !== undefined) ed.select(String(first));
  ed.setStatus(
    `Split ${name} at t = ${Number(at.toPrecision(6))} into ${reply.labels.join(' and ')}`,
  );
}
