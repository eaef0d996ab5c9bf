import { describe, expect, it } from 'vitest';
import { NurbsEvaluator } from '../geometry/nurbs';
import type { Vec3 } from '../viewport/math';
import { IntersectTool, type IntersectHost } from './intersect';
import {
  KnotTool,
  clampBetween,
  interiorKnots,
  knotNeighbours,
  moveKnot,
  parameterOnScreen,
  type KnotHost,
  type NurbsFile,
} from './knots';
import { arch } from '../testing/curves';

describe('knot values', () => {
  it('lists the distinct interior knots with their multiplicity, not the end knots', () => {
    expect(interiorKnots(arch.knots, 3)).toEqual([
      { value: 0.3, index: 4, multiplicity: 1 },
      { value: 0.6, index: 5, multiplicity: 1 },
    ]);
    expect(interiorKnots([0, 0, 0, 0.5, 0.5, 2, 2, 2], 2)).toEqual([
      { value: 0.5, index: 3, multiplicity: 2 },
    ]);
    expect(interiorKnots([0, 0, 0, 0, 1, 1, 1, 1], 3)).toEqual([]);
    // An unclamped (periodic-style) vector: only values strictly inside [U[p], U[n]] = [0.25, 1.25].
    expect(interiorKnots([-0.5, -0.25, 0, 0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75, 2], 3)).toEqual([
      { value: 0.5, index: 4, multiplicity: 1 },
      { value: 0.75, index: 5, multiplicity: 1 },
      { value: 1, index: 6, multiplicity: 1 },
    ]);
  });

  it('moves every copy of a knot, only strictly between its neighbours', () => {
    expect(knotNeighbours(arch.knots, 3, 0)).toEqual([0, 0.6]);
    expect(knotNeighbours(arch.knots, 3, 1)).toEqual([0.3, 1]);
    expect(moveKnot(arch.knots, 3, 0, 0.45)).toEqual([0, 0, 0, 0, 0.45, 0.6, 1, 1, 1, 1]);
    expect(moveKnot(arch.knots, 3, 1, 0.9)).toEqual([0, 0, 0, 0, 0.3, 0.9, 1, 1, 1, 1]);
    expect(moveKnot(arch.knots, 3, 0, 0.6)).toBeNull();
    expect(moveKnot(arch.knots, 3, 0, 0)).toBeNull();
    expect(moveKnot(arch.knots, 3, 0, Number.NaN)).toBeNull();
    expect(moveKnot(arch.knots, 3, 2, 0.5)).toBeNull();
    expect(moveKnot([0, 0, 0, 0.5, 0.5, 2, 2, 2], 2, 0, 1.5)).toEqual([0, 0, 0, 1.5, 1.5, 2, 2, 2]);
  });

  it('keeps a dragged value a thousandth of the gap inside its neighbours', () => {
    expect(clampBetween(0.3, 1, 0.5)).toBe(0.5);
    expect(clampBetween(0.3, 1, 2)).toBeCloseTo(1 - 0.0007, 15);
    expect(clampBetween(0, 0.6, -1)).toBeCloseTo(0.0006, 15);
  });

  it('reads the parameter under the cursor off the nearest drawn segment', () => {
    const screen: ([number, number] | null)[] = [[0, 0], [10, 0], [20, 0], null, [40, 0]];
    const t = [0, 0.5, 1, 1.5, 2];
    expect(parameterOnScreen([5, 3], screen, t, 8)).toBeCloseTo(0.25, 15);
    expect(parameterOnScreen([17.5, -2], screen, t, 8)).toBeCloseTo(0.875, 15);
    // Past the last drawn vertex before the gap: the segment's end (the gap is not a segment).
    expect(parameterOnScreen([25, 0], screen, t, 8)).toBe(1);
    expect(parameterOnScreen([5, 30], screen, t, 8)).toBeNull();
  });
});

/** A host that records what the tool draws and stores; the pointer's parameter is set by the test. */
function knotHost(curve: NurbsFile | null) {
  const log = {
    shown: [] as { curve: number; markers: Vec3[] }[],
    commits: [] as { label: string; knots: number[]; from: number; to: number }[],
    status: [] as string[],
    release: null as (() => void) | null,
    pointer: 0,
    marker: 0 as number | null,
    asked: [] as number[][],
  };
  const evaluate = (c: NurbsFile, us: readonly number[]): Vec3[] => {
    const e = NurbsEvaluator.of(c)!;
    const out = new Float64Array(3);
    return us.map((u) => {
      e.derivatives(u, 0, out);
      return [out[0]!, out[1]!, out[2]!];
    });
  };
  const host: KnotHost = {
    target: () => (curve ? { label: '1', name: 'arch (1)', curve } : null),
    pick: () => null,
    pointsAt: (_label, us) => {
      log.asked.push([...us]);
      return Promise.resolve(curve ? evaluate(curve, us) : undefined);
    },
    evaluate,
    markerAt: () => log.marker,
    parameterAt: () => log.pointer,
    show: (c, markers) => log.shown.push({ curve: c.length, markers: [...markers] }),
    onRelease: (done) => {
      log.release = done;
    },
    commit: (label, knots, from, to) => {
      log.commits.push({ label, knots, from, to });
      return Promise.resolve(true);
    },
    status: (t) => log.status.push(t),
  };
  return { host, log };
}

const ev = {} as PointerEvent;
const flush = (): Promise<void> => new Promise((r) => setTimeout(r, 0));

describe('the Knots tool', () => {
  it('marks the interior knots, previews a drag and stores the moved knot once, on release', async () => {
    const { host, log } = knotHost(arch);
    const tool = new KnotTool(host);
    await flush();
    expect(log.asked).toEqual([[0.3, 0.6]]);
    expect(tool.knotValues).toEqual([0.3, 0.6]);
    expect(log.shown.at(-1)!.markers).toHaveLength(2);
    expect(log.status.at(-1)).toBe(
      'Knots: drag one of the 2 knot markers of arch (1) along the curve (Esc cancels a drag)',
    );

    log.marker = 0;
    tool.click('top', ev);
    log.pointer = 0.45;
    tool.move('top', ev);
    // The preview is the curve on the moved knot vector, its first marker at C(0.45) of that curve.
    const moved: NurbsFile = { ...arch, knots: [0, 0, 0, 0, 0.45, 0.6, 1, 1, 1, 1] };
    const e = NurbsEvaluator.of(moved)!;
    const want = new Float64Array(3);
    e.derivatives(0.45, 0, want);
    const last = log.shown.at(-1)!;
    expect(last.curve).toBeGreaterThan(100);
    expect(last.markers[0]).toEqual([want[0], want[1], want[2]]);
    expect(log.status.at(-1)).toBe('Knot 1: 0.3 → 0.45 (between 0 and 0.6)');
    // Past the neighbour: kept a thousandth of the gap short of 0.6.
    log.pointer = 0.95;
    tool.move('top', ev);
    expect(log.commits).toHaveLength(0);
    log.release!();
    await flush();
    expect(log.commits).toEqual([
      {
        label: '1',
        knots: [0, 0, 0, 0, 0.6 - 0.6e-3, 0.6, 1, 1, 1, 1],
        from: 0.3,
        to: 0.6 - 0.6e-3,
      },
    ]);
  });

  it('stores nothing for a drag released where it started or cancelled with Escape', async () => {
    const { host, log } = knotHost(arch);
    const tool = new KnotTool(host);
    await flush();
    log.marker = 1;
    tool.click('top', ev);
    log.release!();
    await flush();
    tool.click('top', ev);
    log.pointer = 0.8;
    tool.move('top', ev);
    expect(tool.key({ key: 'Escape' } as KeyboardEvent)).toBe(true);
    log.release!();
    await flush();
    expect(log.commits).toHaveLength(0);
    expect(log.shown.at(-1)!.markers).toHaveLength(2);
  });

  it('says what it needs without a NURBS curve or interior knots', async () => {
    const none = knotHost(null);
    new KnotTool(none.host);
    expect(none.log.status.at(-1)).toBe('Knots: click a NURBS curve to show its knots');
    const bare = knotHost({
      ...arch,
      knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1],
      control_points: arch.control_points.slice(1),
    });
    const tool = new KnotTool(bare.host);
    await flush();
    expect(tool.knotValues).toEqual([0.5]);
    const single = knotHost({
      kind: 'nurbs',
      degree: 3,
      knots: [0, 0, 0, 0, 1, 1, 1, 1],
      control_points: arch.control_points.slice(0, 4),
    });
    new KnotTool(single.host);
    expect(single.log.status.at(-1)).toBe(
      'Knots: arch (1) has no interior knot (insert one with U)',
    );
    expect(single.log.asked).toEqual([]);
  });
});

describe('the Intersect tool', () => {
  function intersectHost(selected: string | null, picks: (string | null)[]) {
    const runs: [string, string | null][] = [];
    const marks: Vec3[][] = [];
    const status: string[] = [];
    const host: IntersectHost = {
      selected: () => (selected ? { label: selected, name: selected } : null),
      pick: () => {
        const l = picks.shift() ?? null;
        return l ? { label: l, name: l } : null;
      },
      mark: (p) => marks.push([...p]),
      run: (a, b) => {
        runs.push([a, b]);
        return Promise.resolve([{ t1: 0.25, t2: 0.75, point: [1, 2, 0], kind: 'crossing' }]);
      },
      status: (t) => status.push(t),
    };
    return { host, runs, marks, status };
  }

  it('takes the selected curve first, then the clicked one, and marks the answer', async () => {
    const h = intersectHost('1', ['2']);
    const tool = new IntersectTool(h.host);
    expect(h.status.at(-1)).toContain('Intersect: 1 picked; click the second curve');
    tool.click('top', ev);
    await flush();
    expect(h.runs).toEqual([['1', '2']]);
    expect(h.marks.at(-1)).toEqual([[1, 2, 0]]);
    expect(tool.meetings).toHaveLength(1);
  });

  it('picks two curves without a selection; the same one twice asks where it meets itself', async () => {
    const h = intersectHost(null, [null, '3', '3']);
    const tool = new IntersectTool(h.host);
    expect(h.status.at(-1)).toBe('Intersect: click the first curve');
    tool.click('top', ev);
    expect(h.status.at(-1)).toBe('Intersect: no curve there; Intersect: click the first curve');
    tool.click('top', ev);
    tool.click('top', ev);
    await flush();
    expect(h.runs).toEqual([['3', null]]);
  });
});
