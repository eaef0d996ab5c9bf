import { describe, expect, it } from 'vitest';
import type { CurveFile } from '../api/types';
import type { Vec3, ViewName } from '../viewport/math';
import {
  ControlPointTool,
  SplineTool,
  chordLength,
  clampedUniformKnots,
  midSpan,
  type ToolHost,
} from './tools';

/** A host that places each click at the next scripted point and records what the tool creates. */
function scriptedHost(points: Vec3[]): { host: ToolHost; created: CurveFile[] } {
  const created: CurveFile[] = [];
  let next = 0;
  const host: ToolHost = {
    pointAt: () => points[next++] ?? null,
    preview: () => undefined,
    create: (_name, curve) => created.push(curve),
    status: () => undefined,
  };
  return { host, created };
}

const ev = {} as PointerEvent;
const top: ViewName = 'top';

describe('creation tools', () => {
  // Piegl–Tiller clamped uniform knots: 5 points, degree 3 → [0,0,0,0,0.5,1,1,1,1] (n + p + 1 = 9 knots).
  it('builds clamped uniform knot vectors', () => {
    expect(clampedUniformKnots(5, 3)).toEqual([0, 0, 0, 0, 0.5, 1, 1, 1, 1]);
    expect(clampedUniformKnots(4, 3)).toEqual([0, 0, 0, 0, 1, 1, 1, 1]);
    expect(clampedUniformKnots(3, 1)).toEqual([0, 0, 0.5, 1, 1]);
  });

  // The widest span of [0,0,0,0,0.25,1,1,1,1] is [0.25, 1]: its middle is 0.625; one span: its middle.
  it('finds the middle of the widest knot span', () => {
    expect(midSpan([0, 0, 0, 0, 0.25, 1, 1, 1, 1])).toBe(0.625);
    expect(midSpan([0, 0, 2, 2])).toBe(1);
  });

  // Appendix 8.1: clicks, right-click, tangent click, right-click (natural end); the start
  // tangent points at the click with the chord length as magnitude (3-4-5 triangle: 5 + 5 = 10).
  it('spline: points, start tangent by click, natural end', () => {
    const { host, created } = scriptedHost([
      [0, 0, 0],
      [3, 4, 0],
      [6, 0, 0],
      [0, 2, 0], // start tangent click: straight up from the first point
    ]);
    const tool = new SplineTool(host);
    tool.click(top, ev);
    tool.click(top, ev);
    tool.click(top, ev);
    tool.rightClick();
    tool.click(top, ev);
    tool.rightClick();
    expect(
      chordLength([
        [0, 0, 0],
        [3, 4, 0],
        [6, 0, 0],
      ]),
    ).toBe(10);
    expect(created).toEqual([
      {
        kind: 'interpolated',
        points: [
          [0, 0, 0],
          [3, 4, 0],
          [6, 0, 0],
        ],
        parameterisation: 'chord',
        start: { tangent: [0, 10, 0] },
        end: 'natural',
      },
    ]);
  });

  // Appendix 8.2: a Bézier from four clicks (any views), finished by Enter.
  it('bezier: control points in order, Enter finishes', () => {
    const pts: Vec3[] = [
      [0, 0, 0],
      [30, 40, 0],
      [70, 40, 0],
      [100, 0, 40],
    ];
    const { host, created } = scriptedHost(pts);
    const tool = new ControlPointTool('bezier', host);
    for (let i = 0; i < 4; i++) tool.click(i < 3 ? 'top' : 'front', ev);
    expect(tool.key(new KeyboardEventLike('Enter') as unknown as KeyboardEvent)).toBe(true);
    expect(created).toEqual([
      { kind: 'bezier', control_points: pts.map((p) => [...p]), weights: null },
    ]);
  });
});

class KeyboardEventLike {
  constructor(readonly key: string) {}
}
