// Offset: the selected planar curve offset by a distance (POST /api/offset, the
// server's `hula offset`, its loops trimmed), added as a new selected curve: one
// "create" undo step. The status line reports the deviation the server measured.

import type { CurveFile, OffsetResult } from '../api/types';
import type { Editor } from '../editor/editor';
import { createCurve } from './create-curve';

/** The offset stored and its label, or undefined (the status says why). */
export async function offsetCurve(
  ed: Editor,
  label: string,
  distance: number,
): Promise<{ label: string; result: OffsetResult } | undefined> {
  const curve = ed.store.entities.get(label)?.curve;
  if (!curve) {
    ed.setStatus(`Offset: ${label} is not a curve of this document`, true);
    return undefined;
  }
  if (!Number.isFinite(distance) || distance === 0) {
    ed.setStatus(`Offset: the distance must be a non-zero number`, true);
    return undefined;
  }
  const result = await ed.run(() => ed.client.offset({ curve, distance }), 'Offset');
  if (!result) return undefined;
  // Trimming may leave several pieces; only one can be a single undo step, so then the raw offset is kept.
  const piece: CurveFile = result.trimmed.length === 1 ? result.trimmed[0]!.curve : result.raw;
  const source = ed.nameOf(label);
  const made = await createCurve(ed, 'offset', piece);
  if (!made) return undefined;
  const loops = result.loops.length;
  ed.setStatus(
    `Offset ${ed.nameOf(made)} of ${source} by ${distance}: deviation ${Number(result.deviation.toPrecision(3))}` +
      (result.exact ? ' (exact)' : '') +
      (loops > 0
        ? result.trimmed.length === 1
          ? `, ${loops} loop(s) trimmed`
          : `, ${loops} loop(s) left untrimmed (trimming gave ${result.trimmed.length} pieces)`
        : ''),
    loops > 0 && result.trimmed.length !== 1,
  );
  return { label: made, result };
}
