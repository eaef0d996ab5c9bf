// Import a file's curves (one undo step): STEP and IGES are read by the
// server's isolated Open CASCADE helper, a JSON curve file is created as a
// curve named after the file. The first imported curve is selected.

import type { CurveFile } from '../api/types';
import type { Editor } from '../editor/editor';
import { createCurve } from './create-curve';

/** Whether anything was imported (the caller fits the views to it). */
export async function importFile(
  ed: Editor,
  name: string,
  text: string,
  hint?: string,
): Promise<boolean> {
  if (/\.(step|stp|iges|igs)$/i.test(name)) {
    const reply = await ed.run(() => ed.client.importFile(ed.store.name, name, text));
    if (!reply) return false;
    ed.applyReply(reply);
    const first = reply.labels[0];
    if (first !== undefined) ed.select(String(first));
    return true;
  }
  let curve: CurveFile;
  try {
    curve = JSON.parse(text) as CurveFile;
  } catch (e) {
    ed.toast(new Error(`${name}: not JSON (${e instanceof Error ? e.message : String(e)})`));
    return false;
  }
  await createCurve(ed, name.replace(/\.[^.]*$/, ''), curve, hint);
  return true;
}
