// Replace a curve's file (PUT: one "replace" undo step), as the fairing
// assistant and design by curvature accept their result.

import type { CurveFile } from '../api/types';
import type { Editor } from '../editor/editor';

export async function replaceCurve(ed: Editor, label: string, curve: CurveFile): Promise<void> {
  const reply = await ed.run(() => ed.client.putEntity(ed.store.name, label, curve));
  if (reply) ed.applyReply(reply);
}
