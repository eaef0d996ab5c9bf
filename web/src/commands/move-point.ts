// Move one handle of a curve in one request (one "move points" undo step);
// a drag goes through the viewport controller, which folds its moves into one.

import type { Editor } from '../editor/editor';
import type { Vec3 } from '../viewport/math';

export async function movePoint(ed: Editor, label: string, index: number, to: Vec3): Promise<void> {
  const reply = await ed.run(() =>
    ed.client.movePoints(ed.store.name, label, [{ index, to: [...to] }], false),
  );
  if (reply) ed.applyReply(reply);
}
