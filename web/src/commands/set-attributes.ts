// Show, hide, lock or unlock a curve (object list): the entity's `visible` and
// `locked` attributes, so the document and every client agree (one "edit
// attributes" step). The change shows at once and goes back if the server
// refuses; a hidden curve is neither drawn nor picked, a locked one not dragged.

import type { Editor } from '../editor/editor';
import { patchEntity } from './patch-entity';

async function patchAttributes(
  ed: Editor,
  label: string,
  attributes: Record<string, unknown>,
): Promise<void> {
  ed.setPending(label, { ...ed.pendingAttributes.get(label), ...attributes });
  try {
    await patchEntity(ed, label, { attributes });
  } finally {
    ed.setPending(label, null);
  }
}

export async function setHidden(ed: Editor, label: string, hidden: boolean): Promise<void> {
  await patchAttributes(ed, label, { visible: !hidden });
  ed.setStatus(`${ed.nameOf(label)} ${hidden ? 'hidden' : 'shown'}`);
}

export async function setLocked(ed: Editor, label: string, locked: boolean): Promise<void> {
  await patchAttributes(ed, label, { locked });
  ed.setStatus(`${ed.nameOf(label)} ${locked ? 'locked' : 'unlocked'}`);
}
