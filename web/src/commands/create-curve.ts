// Create a curve (one "create" undo step) in a colour no visible curve has,
// stored with it so it stays across reloads and tabs; the new curve is selected.

import type { CurveFile } from '../api/types';
import type { Editor } from '../editor/editor';
import { freshColour, hex } from '../store/viewstate';

/** The new curve's label, or undefined when the server refused it (the status says why). */
export async function createCurve(
  ed: Editor,
  name: string,
  curve: CurveFile,
  hint?: string,
): Promise<string | undefined> {
  const visible = [...ed.store.entities.values()]
    .filter((e) => e.curve !== undefined && !ed.isHidden(String(e.label)))
    .map((e) => ed.colourOf(String(e.label)));
  const colour = hex(freshColour(visible));
  const reply = await ed.run(
    () => ed.client.createEntity(ed.store.name, name, curve, { colour }),
    `Create ${curve.kind} curve`,
  );
  if (!reply) return undefined;
  ed.applyReply(reply);
  const made = reply.label ?? reply.changes.added?.[0];
  const label = made === undefined ? undefined : String(made);
  if (label) {
    ed.select(label);
    ed.setStatus(`Created ${curve.kind} curve ${name} (${label})${hint ? `; ${hint}` : ''}`);
  }
  return label;
}
