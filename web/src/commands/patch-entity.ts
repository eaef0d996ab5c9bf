// A PATCH of an entity (name, attributes, knots…: one undo step), its reply applied.

import type { Editor } from '../editor/editor';

export async function patchEntity(
  ed: Editor,
  label: string,
  body: Record<string, unknown>,
): Promise<void> {
  const reply = await ed.run(() => ed.client.patchEntity(ed.store.name, label, body));
  if (reply) ed.applyReply(reply);
}
