// Rebuild: the selected curve's shape on a chosen degree and control-point count
// (POST /api/rebuild, the server's `hula edit rebuild`), stored over it with one PUT:
// one "replace" undo step. The status line reports the deviation the server measured.

import type { RebuildResult } from '../api/types';
import type { Editor } from '../editor/editor';

export interface RebuildChoice {
  degree: number;
  controlPoints: number;
}

/** The degree and control-point count a curve has now (the rebuild dialog's defaults). */
export function rebuildDefaults(ed: Editor, label: string): RebuildChoice {
  const c = ed.store.entities.get(label)?.curve;
  const n =
    c && 'control_points' in c ? c.control_points.length : c && 'points' in c ? c.points.length : 8;
  const degree = c?.kind === 'nurbs' ? c.degree : c?.kind === 'bezier' ? n - 1 : 3;
  return { degree: Math.min(degree, 9), controlPoints: Math.max(n, degree + 1) };
}

/** The server's report of the rebuild stored, or undefined when nothing changed (the status says why). */
export async function rebuildCurve(
  ed: Editor,
  label: string,
  choice: RebuildChoice,
): Promise<RebuildResult | undefined> {
  const curve = ed.store.entities.get(label)?.curve;
  if (!curve) {
    ed.setStatus(`Rebuild: ${label} is not a curve of this document`, true);
    return undefined;
  }
  if (ed.isLocked(label)) {
    ed.setStatus(`Rebuild: ${ed.nameOf(label)} is locked: unlock it in the object list`, true);
    return undefined;
  }
  const result = await ed.run(
    () => ed.client.rebuild({ curve, degree: choice.degree, control_points: choice.controlPoints }),
    'Rebuild',
  );
  if (!result) return undefined;
  const name = ed.nameOf(label);
  const reply = await ed.run(
    () => ed.client.putEntity(ed.store.name, label, result.curve),
    'Rebuild',
  );
  if (!reply) return undefined;
  ed.applyReply(reply);
  ed.select(label);
  const g = (x: number): number => Number(x.toPrecision(3));
  ed.setStatus(
    `Rebuilt ${name}: degree ${result.degree}, ${result.control_points} control points, ` +
      `max deviation ${g(result.max_deviation)} (mean ${g(result.mean_deviation)})`,
  );
  return result;
}
