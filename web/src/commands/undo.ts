// Undo the document's last step (the server keeps the history).

import type { Editor } from '../editor/editor';

export async function undo(ed: Editor): Promise<void> {
  const reply = await ed.run(() => ed.client.undo(ed.store.name), 'Undo');
  if (!reply) return;
  ed.applyReply(reply);
  ed.setStatus(`Undone: ${reply.changes.name ?? 'last step'} (revision ${reply.revision})`);
}
