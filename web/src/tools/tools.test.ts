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
import { ClothoidTool, type ClothoidHost } from './clothoid';
import type { ClothoidChoice } from '../commands/clothoid';

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

describe('the Clothoid tool', () => {
  function clothoidHost(points: Vec3[]) {
    let next = 0;
    const made: { points: Vec3[]; choice: ClothoidChoice }[] = [];
    const status: string[] = [];
    const host: ClothoidHost = {
      pointAt: () => points[next++] ?? null,
      preview: () => undefined,
      status: (t) => status.push(t),
      make: (p, choice) => {
        made.push({ points: p, choice });
        return Promise.resolve();
      },
    };
    return { host, made, status };
  }
  const key = (k: string, shiftKey = false) => ({ key: k, shiftKey }) as KeyboardEvent;

  it('asks the spline through the clicked points, G2 and open by default, on right click', async () => {
    const pts: Vec3[] = [
      [0, 0, 0],
      [10, 5, 0],
      [20, 0, 0],
    ];
    const h = clothoidHost(pts);
    const tool = new ClothoidTool(h.host);
    tool.click(top, ev);
    tool.rightClick();
    expect(h.made).toHaveLength(0);
    expect(h.status.at(-1)).toBe('Clothoid: at least 2 points are needed');
    tool.click(top, ev);
    tool.click(top, ev);
    tool.rightClick();
    await Promise.resolve();
    expect(h.made).toEqual([{ points: pts, choice: { fit: 'g2', closed: false } }]);
  });

  it('takes 1, 2, 3 for G1, G2, biarcs and C for closed (three points at least), Enter to finish', async () => {
    const h = clothoidHost([
      [0, 0, 0],
      [10, 5, 0],
      [20, 0, 0],
    ]);
    const tool = new ClothoidTool(h.host);
    expect(tool.key(key('3'))).toBe(true);
    expect(tool.key(key('c'))).toBe(true);
    expect(tool.choice).toEqual({ fit: 'biarc', closed: true });
    expect(h.status.at(-1)).toContain('Clothoid (biarcs, closed)');
    // Shift+C is the command's, not the tool's toggle.
    expect(tool.key(key('C', true))).toBe(false);
    tool.click(top, ev);
    tool.click(top, ev);
    expect(tool.key(key('Enter'))).toBe(true);
    expect(h.status.at(-1)).toBe('Clothoid: at least 3 points are needed');
    tool.click(top, ev);
    tool.key(key('Enter'));
    await Promise.resolve();
    expect(h.made[0]!.choice).toEqual({ fit: 'biarc', closed: true });
    expect(h.made[0]!.points).toHaveLength(3);
    expect(tool.key(key('1'))).toBe(true);
    expect(tool.choice.fit).toBe('g1');
  });
});
