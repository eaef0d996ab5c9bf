import { describe, expect, it } from 'vitest';
import type * as Api from '../api/openapi';
import type { CurveFile } from '../api/types';
import { arch } from '../testing/curves';
import { useFetchDouble } from '../testing/fetch-double';
import {
  attributes,
  change,
  cubic,
  editorWith,
  lastStatus,
  serverEntity,
} from '../testing/documents';
import { closeCurve, closingPoints } from './close';
import { offsetCurve } from './offset';
import { clothoidThrough } from './clothoid';
import { intersectCurves, meetingText } from './intersect';
import { moveKnotValue } from './move-knot';
import { rebuildCurve, rebuildDefaults } from './rebuild';

// Rebuild, Close, Offset, Intersect, Clothoid and the knot move against the page's real Client, store and editor (only fetch is
// replaced: testing/fetch-double.ts), with the server's answers typed by its OpenAPI document.

const http = useFetchDouble();

const rebuilt: CurveFile = {
  kind: 'nurbs',
  degree: 3,
  knots: [0, 0, 0, 0, 1 / 3, 2 / 3, 1, 1, 1, 1],
  control_points: [
    [0, 0, 0],
    [4, 10, 0],
    [12, 15, 0],
    [28, 15, 0],
    [36, 10, 0],
    [40, 0, 0],
  ],
};

const through: CurveFile = {
  kind: 'interpolated',
  points: [
    [0, 0, 0],
    [10, 10, 0],
    [20, 0, 0],
    [10, -10, 0],
  ],
};

const closed: CurveFile = {
  kind: 'nurbs',
  degree: 3,
  knots: [-0.5, -0.25, 0, 0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75, 2],
  control_points: [
    [0, 5, 0],
    [10, 12, 0],
    [20, 5, 0],
    [10, -12, 0],
    [0, 5, 0],
    [10, 12, 0],
    [20, 5, 0],
  ],
};

describe('Rebuild', () => {
  it('offers the curve its degree and count, asks the server, stores the answer in one PUT and shows the deviation', async () => {
    const { ed, events } = editorWith(3, [serverEntity(1, cubic, attributes('arch'))]);
    // A Bézier cubic of four points: degree 3, four control points by default.
    expect(rebuildDefaults(ed, '1')).toEqual({ degree: 3, controlPoints: 4 });
    http.auto = (c) => {
      if (c.path === '/api/rebuild') {
        const answer: Api.RebuildResult = {
          operation: 'rebuild',
          degree: 3,
          control_points: 6,
          samples: 0,
          max_deviation: 0.000123456,
          mean_deviation: 0.0000234,
          at: 0.25,
          curve: rebuilt,
        };
        c.respond(200, answer);
      } else
        c.respond(
          200,
          change(4, {
            name: 'replace',
            changed: [1],
            entities: [serverEntity(1, rebuilt, attributes('arch'))],
          }),
        );
    };
    const result = await rebuildCurve(ed, '1', { degree: 3, controlPoints: 6 });
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'POST /api/rebuild',
      'PUT /api/documents/a.hula/entities/1',
    ]);
    expect(http.calls[0]!.body).toEqual({ curve: cubic, degree: 3, control_points: 6 });
    expect(http.calls[1]!.body).toEqual({ curve: rebuilt });
    expect(result?.max_deviation).toBe(0.000123456);
    expect(ed.store.revision).toBe(4);
    expect(ed.store.entities.get('1')?.curve).toEqual(rebuilt);
    expect(ed.selected).toBe('1');
    expect(lastStatus(events)).toEqual({
      text: 'Rebuilt arch (1): degree 3, 6 control points, max deviation 0.000123 (mean 0.0000234)',
      error: false,
    });
  });

  it('changes nothing when the server refuses the count, and says why', async () => {
    const { ed, events } = editorWith(3, [serverEntity(1, cubic)]);
    http.auto = (c) => {
      c.respond(400, {
        error: {
          code: 'InvalidOption',
          message: 'control_points: 2 is fewer than degree + 1',
          where: { field: 'control_points' },
        },
      });
    };
    expect(await rebuildCurve(ed, '1', { degree: 3, controlPoints: 2 })).toBeUndefined();
    expect(http.calls).toHaveLength(1);
    expect(ed.store.revision).toBe(3);
    expect(ed.store.entities.get('1')?.curve).toEqual(cubic);
    expect(lastStatus(events)).toEqual({
      text: 'Rebuild failed: control_points: 2 is fewer than degree + 1',
      error: true,
    });
  });
});

describe('Close', () => {
  it('closes through the points, dropping a repeated first point, and through control points otherwise', () => {
    expect(closingPoints(through)).toEqual((through as { points: number[][] }).points);
    expect(
      closingPoints({
        kind: 'interpolated',
        points: [
          [0, 0, 0],
          [5, 5, 0],
          [9, 0, 0],
          [0, 0, 0],
        ],
      }),
    ).toEqual([
      [0, 0, 0],
      [5, 5, 0],
      [9, 0, 0],
    ]);
    expect(closingPoints(cubic)).toHaveLength(4);
    expect(closingPoints({ kind: 'law', expression: 'vec(t, t)', domain: [0, 1] })).toBeNull();
  });

  it('asks the closed interpolation through the curve its points and stores it in one PUT', async () => {
    const { ed, events } = editorWith(7, [serverEntity(2, through, attributes('loop'))]);
    http.auto = (c) => {
      if (c.path === '/api/interpolate-closed') {
        const answer: Api.ClosedInterpolation = {
          kind: 'nurbs',
          method: 'closed',
          points: 4,
          dimension: 3,
          degree: 3,
          control_points: 7,
          domain: [0, 1],
          parameterisation: 'chord',
          curve: closed,
        };
        c.respond(200, answer);
      } else
        c.respond(
          200,
          change(8, { name: 'replace', changed: [2], entities: [serverEntity(2, closed)] }),
        );
    };
    await closeCurve(ed, '2');
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'POST /api/interpolate-closed',
      'PUT /api/documents/a.hula/entities/2',
    ]);
    expect(http.calls[0]!.body).toEqual({ points: (through as { points: number[][] }).points });
    expect(http.calls[1]!.body).toEqual({ curve: closed });
    expect(ed.store.revision).toBe(8);
    expect(ed.store.entities.get('2')?.curve).toEqual(closed);
    expect(lastStatus(events)).toEqual({
      text: 'Closed loop (2): periodic C2 cubic through its 4 points, 7 control points',
      error: false,
    });
  });

  it('sends nothing for a law curve or a locked one', async () => {
    const law: CurveFile = { kind: 'law', expression: 'vec(t, t*t)', domain: [0, 1] };
    const { ed, events } = editorWith(1, [
      serverEntity(1, law),
      serverEntity(2, through, attributes('held', { locked: true })),
    ]);
    expect(await closeCurve(ed, '1')).toBeUndefined();
    expect(lastStatus(events)?.error).toBe(true);
    expect(lastStatus(events)?.text).toContain('law curve');
    expect(await closeCurve(ed, '2')).toBeUndefined();
    expect(lastStatus(events)?.text).toBe(
      'Close: held (2) is locked: unlock it in the object list',
    );
    expect(http.calls).toHaveLength(0);
  });
});

describe('Offset', () => {
  const offsetAnswer = (pieces: number): Api.OffsetResult => ({
    distance: 2,
    tolerance: 1e-6,
    exact: false,
    deviation: 3.14159e-7,
    raw: rebuilt,
    cusps: [],
    loops: pieces === 1 ? [] : [{ s: 0.2, t: 0.8, point: [20, 10, 0], angle: 0.5 }],
    trimmed: Array.from({ length: pieces }, () => ({
      spans: [[0, 1]],
      closed: false,
      curve: closed,
    })),
  });

  it('adds the trimmed offset as a new selected curve (one POST) and reports the deviation', async () => {
    const { ed, events } = editorWith(2, [serverEntity(1, cubic, attributes('arch'))]);
    http.auto = (c) => {
      if (c.path === '/api/offset') c.respond(200, offsetAnswer(1));
      else
        c.respond(201, {
          label: 5,
          ...change(3, {
            name: 'create',
            added: [5],
            entities: [serverEntity(5, closed, attributes('offset'))],
          }),
        });
    };
    const made = await offsetCurve(ed, '1', 2);
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'POST /api/offset',
      'POST /api/documents/a.hula/entities',
    ]);
    expect(http.calls[0]!.body).toEqual({ curve: cubic, distance: 2 });
    expect((http.calls[1]!.body as { curve: CurveFile }).curve).toEqual(closed);
    expect(made?.label).toBe('5');
    expect(ed.selected).toBe('5');
    expect(ed.store.entities.get('1')?.curve).toEqual(cubic);
    expect(ed.store.entities.get('5')?.curve).toEqual(closed);
    expect(lastStatus(events)).toEqual({
      text: 'Offset offset (5) of arch (1) by 2: deviation 3.14e-7',
      error: false,
    });
  });

  it('keeps the raw offset when trimming leaves several pieces, and says so', async () => {
    const { ed, events } = editorWith(2, [serverEntity(1, cubic, attributes('arch'))]);
    http.auto = (c) => {
      if (c.path === '/api/offset') c.respond(200, offsetAnswer(2));
      else
        c.respond(201, {
          label: 6,
          ...change(3, { name: 'create', added: [6], entities: [serverEntity(6, rebuilt)] }),
        });
    };
    await offsetCurve(ed, '1', 2);
    expect((http.calls[1]!.body as { curve: CurveFile }).curve).toEqual(rebuilt);
    expect(lastStatus(events)).toEqual({
      text: 'Offset c6 (6) of arch (1) by 2: deviation 3.14e-7, 1 loop(s) left untrimmed (trimming gave 2 pieces)',
      error: true,
    });
  });

  it('sends nothing for a zero distance', async () => {
    const { ed, events } = editorWith(2, [serverEntity(1, cubic)]);
    expect(await offsetCurve(ed, '1', 0)).toBeUndefined();
    expect(http.calls).toHaveLength(0);
    expect(lastStatus(events)?.error).toBe(true);
  });
});

describe('Intersect', () => {
  const answer: Api.IntersectionResult = {
    tolerance: 1e-6,
    points: [
      {
        s: 0.875857,
        t: 0.808196,
        point: [86.98364, 9.519761, 0],
        distance: 0,
        angle: 0.7,
        kind: 'crossing',
      },
      {
        s: 0.0456669,
        t: 0.138969,
        point: [6.676251, 10.08546, 0],
        distance: 0,
        angle: 0.9,
        kind: 'tangent',
      },
    ],
    overlaps: [],
  };

  it('asks where the two curves meet, nothing stored, and reads the points out in the order of t1', async () => {
    const { ed, events } = editorWith(2, [
      serverEntity(1, cubic, attributes('arch')),
      serverEntity(2, rebuilt, attributes('bow')),
    ]);
    http.auto = (c) => {
      c.respond(200, answer);
    };
    const m = await intersectCurves(ed, '1', '2');
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual(['POST /api/intersect']);
    expect(http.calls[0]!.body).toEqual({ a: cubic, b: rebuilt });
    expect(m?.map((x) => x.t1)).toEqual([0.0456669, 0.875857]);
    expect(m?.[0]).toEqual({
      t1: 0.0456669,
      t2: 0.138969,
      point: [6.676251, 10.08546, 0],
      kind: 'tangent',
    });
    expect(ed.store.revision).toBe(2);
    expect(lastStatus(events)).toEqual({
      text:
        'Intersect arch (1) × bow (2): 2 point(s): (t1 0.0456669, t2 0.138969) at (6.67625, 10.0855, 0); ' +
        '(t1 0.875857, t2 0.808196) at (86.9836, 9.51976, 0)',
      error: false,
    });
  });

  it('asks a curve alone for where it meets itself, and says when nothing meets', async () => {
    const { ed, events } = editorWith(2, [serverEntity(1, cubic, attributes('arch'))]);
    http.auto = (c) => {
      c.respond(200, { tolerance: 1e-6, points: [], overlaps: [] });
    };
    expect(await intersectCurves(ed, '1', null)).toEqual([]);
    expect(http.calls[0]!.body).toEqual({ a: cubic });
    expect(lastStatus(events)?.text).toBe('Intersect arch (1) with itself: no point');
  });

  it('lists the first three points and counts the rest and the overlaps', () => {
    const p = {
      t1: 0.5,
      t2: 0.25,
      point: [1, 2, 3] as [number, number, number],
      kind: 'crossing' as const,
    };
    expect(meetingText('a', 'b', [p, p, p, p, p], 1)).toBe(
      'Intersect a × b: 5 point(s), 1 overlap(s): ' +
        '(t1 0.5, t2 0.25) at (1, 2, 3); (t1 0.5, t2 0.25) at (1, 2, 3); (t1 0.5, t2 0.25) at (1, 2, 3); … 2 more',
    );
  });
});

describe('Clothoid', () => {
  const natural: CurveFile = { kind: 'natural', curvature: '0.1', length: 10 };

  it('asks the spline through the curve its points and adds it as a new selected curve named after the fit', async () => {
    const { ed, events } = editorWith(5, [serverEntity(2, through, attributes('path'))]);
    http.auto = (c) => {
      if (c.path === '/api/clothoid')
        c.respond(200, {
          kind: 'biarc',
          segments: [],
          length: 57.123456,
          iterations: 0,
          through: 4,
          closed: true,
          curve: natural,
        });
      else
        c.respond(201, {
          label: 9,
          ...change(6, {
            name: 'create',
            added: [9],
            entities: [serverEntity(9, natural, attributes('biarc'))],
          }),
        });
    };
    const made = await clothoidThrough(ed, '2', { fit: 'biarc', closed: true });
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'POST /api/clothoid',
      'POST /api/documents/a.hula/entities',
    ]);
    expect(http.calls[0]!.body).toEqual({
      points: (through as { points: number[][] }).points,
      fit: 'biarc',
      closed: true,
    });
    expect((http.calls[1]!.body as { name: string }).name).toBe('biarc');
    expect(made?.label).toBe('9');
    expect(ed.selected).toBe('9');
    expect(lastStatus(events)).toEqual({
      text: 'Added the biarc spline biarc (9) through the 4 points of path (2) (closed): 0 segments, length 57.1235',
      error: false,
    });
  });

  it('sends nothing for a law curve', async () => {
    const { ed, events } = editorWith(1, [
      serverEntity(1, { kind: 'law', expression: 'vec(t, t)', domain: [0, 1] }),
    ]);
    expect(await clothoidThrough(ed, '1', { fit: 'g2', closed: false })).toBeUndefined();
    expect(http.calls).toHaveLength(0);
    expect(lastStatus(events)?.text).toContain('law curve, which has no points');
  });
});

describe('Move knot', () => {
  const moved: CurveFile = { ...arch, knots: [0, 0, 0, 0, 0.45, 0.6, 1, 1, 1, 1] };

  it('stores the curve with the new knot vector and its points as they were, in one PUT', async () => {
    const { ed, events } = editorWith(3, [serverEntity(1, arch, attributes('arch'))]);
    http.auto = (c) => {
      c.respond(
        200,
        change(4, {
          name: 'replace',
          changed: [1],
          entities: [serverEntity(1, moved, attributes('arch'))],
        }),
      );
    };
    expect(await moveKnotValue(ed, '1', [0, 0, 0, 0, 0.45, 0.6, 1, 1, 1, 1], 0.3, 0.45)).toBe(true);
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'PUT /api/documents/a.hula/entities/1',
    ]);
    expect(http.calls[0]!.body).toEqual({ curve: moved });
    expect(ed.store.entities.get('1')?.curve).toEqual(moved);
    expect(lastStatus(events)?.text).toBe('Moved a knot of arch (1) from 0.3 to 0.45');
  });

  it('sends nothing for a locked curve or one that is not NURBS', async () => {
    const { ed, events } = editorWith(3, [
      serverEntity(1, arch, attributes('arch', { locked: true })),
      serverEntity(2, cubic),
    ]);
    expect(await moveKnotValue(ed, '1', [0, 0, 0, 0, 0.45, 0.6, 1, 1, 1, 1], 0.3, 0.45)).toBe(
      false,
    );
    expect(lastStatus(events)?.text).toBe(
      'Knots: arch (1) is locked: unlock it in the object list',
    );
    expect(await moveKnotValue(ed, '2', [0, 1], 0, 1)).toBe(false);
    expect(http.calls).toHaveLength(0);
  });
});
