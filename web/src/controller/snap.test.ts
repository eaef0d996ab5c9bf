import { describe, expect, it } from 'vitest';
import type { Entity } from '../api/types';
import { snapToObjects } from '../viewport/math';
import { snapTargets } from './snap';

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
