// What object snap can land on, gathered from the document as the page holds
// it: the handles of every visible curve (but the one being dragged) and each
// visible curve as drawn (its analysis polyline and its two ends; the dragged
// curve's own polyline moves with the drag and is left out). The viewport
// controller asks viewport/math's snapToObjects which of them is under the
// pointer; each target keeps the label of its curve for the status line.

import type { Entity } from '../api/types';
import { handlesOf } from '../store/curves';
import type { SnapTargets, Vec3 } from '../viewport/math';
import { toVec3 } from '../viewport/viewports';

export interface OwnedSnapTargets extends SnapTargets {
  /** The label of each point's curve. */
  readonly pointOwner: readonly string[];
  /** The label of each polyline's curve. */
  readonly lineOwner: readonly string[];
}

export function snapTargets(
  entities: ReadonlyMap<string, Entity>,
  isHidden: (label: string) => boolean,
  drawn: (label: string) => readonly (readonly number[])[] | undefined,
  exclude?: { label: string; index: number },
): OwnedSnapTargets {
  const points: Vec3[] = [];
  const pointOwner: string[] = [];
  const polylines: Vec3[][] = [];
  const lineOwner: string[] = [];
  for (const [label, e] of entities) {
    if (!e.curve || isHidden(label)) continue;
    handlesOf(e.curve).forEach((q, i) => {
      if (exclude?.label === label && exclude.index === i) return;
      points.push(q);
      pointOwner.push(label);
    });
    const line = drawn(label);
    if (line && line.length > 1 && exclude?.label !== label) {
      const l = line.map(toVec3);
      points.push(l[0]!, l[l.length - 1]!);
      pointOwner.push(label, label);
      polylines.push(l);
      lineOwner.push(label);
    }
  }
  return { points, polylines, pointOwner, lineOwner };
}
