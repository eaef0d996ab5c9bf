// Raise the degree of the selected curve by one (its shape stays; one undo step).

import type { Editor } from '../editor/editor';

export async function elevate(ed: Editor): Promise<void> {
  const label = ed.needSelection('Elevate degree');
  if (!label) return;
  const reply = await ed.run(() => ed.client.elevate(ed.store.name, label), 'Elevate degree');
  if (!reply) return;
  ed.applyReply(reply);
  ed.setStatus(`Raised the degree of ${ed.nameOf(label)} by one`);
}
