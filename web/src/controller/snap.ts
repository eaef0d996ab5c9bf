// What object snap can land on, gathered from the document as the page holds
// it: the handles of every visible curve (but the one being dragged) and each
// visible curve as drawn (its analysis polyline and its two ends; the dragged
// curve's own polyline moves with the drag and is left out). The viewport
// controller asks viewport/math's snapToObjects which of them is under the
// pointer; each target keeps the label of its curve for the status line.

import type { Entity } from '../api/types';
import { handlesOf } from '../store/curves';
import {
  projectToScreen,
  snapToObjects,
  type Mat4,
  type SnapTargets,
  type Vec3,
} from '../viewport/math';
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

/** What a snapped point landed on (the status line and the tests read it), or null: nothing. */
export type SnapHit = { kind: 'point' | 'curve' | 'grid'; label?: string } | null;

/** The view a point is snapped in: its size in pixels, its view-projection, its grid. */
export interface SnapView {
  readonly w: number;
  readonly h: number;
  readonly viewProj: Mat4;
  /** Whether grid snap is on. */
  readonly grid: boolean;
  /** The point on the view's plane, on its grid when grid snap is on. */
  onPlane(p: Vec3): Vec3;
}

/**
 * A point snapped as the toggles ask: with object snap, onto the nearest
 * target (a handle or end point first, else a curve as drawn) within 8 pixels
 * on screen; else onto the grid when grid snap is on; else onto the plane as
 * it is. `targets` is asked only when object snap is on.
 */
export function snapPoint(
  p: Vec3,
  view: SnapView,
  objectSnap: boolean,
  targets: () => OwnedSnapTargets,
): { point: Vec3; hit: SnapHit } {
  if (objectSnap) {
    const at = projectToScreen(p, view.viewProj, view.w, view.h);
    if (at) {
      const t = targets();
      const hit = snapToObjects(at, t, view.viewProj, view.w, view.h, 8);
      if (hit) {
        const owner = (hit.kind === 'point' ? t.pointOwner : t.lineOwner)[hit.index]!;
        return { point: hit.point, hit: { kind: hit.kind, label: owner } };
      }
    }
  }
  return { point: view.onPlane(p), hit: view.grid ? { kind: 'grid' } : null };
}
