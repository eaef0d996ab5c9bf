import { describe, expect, it } from 'vitest';
import type * as Api from '../api/openapi';
import type { CurveFile } from '../api/types';
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
import { rebuildCurve, rebuildDefaults } from './rebuild';

// Rebuild, Close and Offset against the page's real Client, store and editor (only fetch is
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
