// Reverse the direction of the selected curve (its graphs run the other way; one undo step).

import type { Editor } from '../editor/editor';

export async function reverse(ed: Editor): Promise<void> {
  const label = ed.needSelection('Reverse');
  if (!label) return;
  const reply = await ed.run(() => ed.client.reverse(ed.store.name, label), 'Reverse');
  if (!reply) return;
  ed.applyReply(reply);
  ed.setStatus(`Reversed ${ed.nameOf(label)}`);
}
