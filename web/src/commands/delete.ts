// Delete the selected curve (one undo step).

import type { Editor } from '../editor/editor';

export async function deleteSelected(ed: Editor): Promise<void> {
  const label = ed.needSelection('Delete');
  if (!label) return;
  const name = ed.nameOf(label);
  const reply = await ed.run(() => ed.client.deleteEntity(ed.store.name, label), 'Delete');
  if (!reply) return;
  ed.applyReply(reply);
  ed.setStatus(`Deleted ${name} (Ctrl+Z undoes)`);
}
