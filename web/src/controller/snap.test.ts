import { describe, expect, it } from 'vitest';
import type { Entity } from '../api/types';
import { snapToGrid, snapToObjects, workingPlane, type Vec3 } from '../viewport/math';
import { snapPoint, snapTargets, type SnapView } from './snap';

const entity = (label: string, control_points: number[][]): Entity => ({
  label,
  kind: 'curve',
  name: label,
  attributes: {},
  curve: { kind: 'bezier', control_points },
});

describe('object snap targets', () => {
  const entities = new Map<string, Entity>([
    [
      '1',
      entity('1', [
        [0, 0, 0],
        [10, 10, 0],
        [20, 0, 0],
      ]),
    ],
    [
      '2',
      entity('2', [
        [0, -10, 0],
        [20, -10, 0],
      ]),
    ],
    ['3', { label: '3', kind: 'study', name: 'study', attributes: {} }],
    [
      '4',
      entity('4', [
        [50, 50, 0],
        [60, 60, 0],
      ]),
    ],
  ]);
  const drawn = (l: string): number[][] | undefined =>
    l === '1'
      ? [
          [0, 0, 0],
          [10, 5, 0],
          [20, 0, 0],
        ]
      : l === '2'
        ? [
            [0, -10, 0],
            [20, -10, 0],
          ]
        : undefined;

  it('hold the visible curves’ handles and ends, and their polylines, each with its curve', () => {
    const t = snapTargets(entities, (l) => l === '4', drawn);
    // Curve 1: 3 handles + 2 ends; curve 2: 2 handles + 2 ends; the study and hidden curve 4: nothing.
    expect(t.points).toHaveLength(9);
    expect(t.pointOwner).toEqual(['1', '1', '1', '1', '1', '2', '2', '2', '2']);
    expect(t.polylines).toHaveLength(2);
    expect(t.lineOwner).toEqual(['1', '2']);
  });
  it('leave out the dragged handle and its curve’s polyline, keeping its other handles', () => {
    const t = snapTargets(entities, () => false, drawn, { label: '1', index: 2 });
    expect(t.pointOwner.filter((o) => o === '1')).toHaveLength(2);
    expect(t.points).not.toContainEqual([20, 0, 0]);
    expect(t.lineOwner).toEqual(['2', '4'].filter((l) => drawn(l)));
  });
  it('snap the dragged end of curve 1 onto curve 2’s start, not onto its own start', () => {
    // Identity view of [-50, 50]², 100 px: one unit per pixel.
    const m = [1 / 50, 0, 0, 0, 0, 1 / 50, 0, 0, 0, 0, -1 / 50, 0, 0, 0, 0, 1];
    const t = snapTargets(entities, () => false, drawn, { label: '1', index: 2 });
    const hit = snapToObjects([51, 57], t, m, 100, 100, 8)!;
    expect(hit.point).toEqual([0, -10, 0]);
    expect(t.pointOwner[hit.index]).toBe('2');
  });
});

describe('snapping a point as the toggles ask', () => {
  // The top view 200 × 200 px over [-100, 100]²: one model unit is one pixel (x right, y up).
  const top = workingPlane('top');
  const view = (grid: boolean): SnapView => ({
    w: 200,
    h: 200,
    viewProj: [0.01, 0, 0, 0, 0, 0.01, 0, 0, 0, 0, 0.01, 0, 0, 0, 0, 1],
    grid,
    onPlane: (p) => (grid ? snapToGrid(p, top, 10) : p),
  });
  const entities = new Map<string, Entity>([
    [
      '1',
      entity('1', [
        [0, 0, 0],
        [30, 40, 0],
        [60, 0, 0],
      ]),
    ],
    [
      '2',
      entity('2', [
        [0, -50, 0],
        [60, -50, 0],
      ]),
    ],
  ]);
  const hidden = new Set<string>();
  const drawn = (label: string) =>
    label === '2' ? Array.from({ length: 61 }, (_, i) => [i, -50, 0]) : undefined;
  const targets = (exclude?: { label: string; index: number }) => () =>
    snapTargets(entities, (l) => hidden.has(l), drawn, exclude);

  it('lands on a handle within 8 px, naming its curve, before the grid', () => {
    const r = snapPoint([34, 44, 0], view(true), true, targets());
    expect(r).toEqual({ point: [30, 40, 0], hit: { kind: 'point', label: '1' } });
  });

  it('lands on a curve as drawn when no handle is near', () => {
    const r = snapPoint([23.5, -46, 0], view(false), true, targets());
    expect(r.hit).toEqual({ kind: 'curve', label: '2' });
    expect(r.point[1]).toBe(-50);
    expect(r.point[0]).toBeCloseTo(23.5, 9);
  });

  it('does not snap a dragged handle onto itself, nor onto a hidden curve', () => {
    const own = snapPoint([33, 41, 0], view(false), true, targets({ label: '1', index: 1 }));
    expect(own).toEqual({ point: [33, 41, 0], hit: null });
    hidden.add('1');
    const r = snapPoint([34, 44, 0], view(true), true, targets());
    hidden.delete('1');
    expect(r).toEqual({ point: [30, 40, 0], hit: { kind: 'grid' } });
  });

  it('falls back to the grid beyond 8 px, and leaves the point as it is with both toggles off', () => {
    const far: Vec3 = [44, 17, 0];
    expect(snapPoint(far, view(true), true, targets())).toEqual({
      point: [40, 20, 0],
      hit: { kind: 'grid' },
    });
    let asked = false;
    const r = snapPoint([34, 44, 0], view(false), false, () => {
      asked = true;
      return targets()();
    });
    expect(r).toEqual({ point: [34, 44, 0], hit: null });
    expect(asked).toBe(false);
  });
});
