// Redo the document's last undone step.

import type { Editor } from '../editor/editor';

export async function redo(ed: Editor): Promise<void> {
  const reply = await ed.run(() => ed.client.redo(ed.store.name), 'Redo');
  if (!reply) return;
  ed.applyReply(reply);
  ed.setStatus(`Redone: ${reply.changes.name ?? 'step'} (revision ${reply.revision})`);
}
