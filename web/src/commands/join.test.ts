import { describe, expect, it } from 'vitest';
import type * as Api from '../api/openapi';
import type { CurveFile } from '../api/types';
import { useFetchDouble, settle } from '../testing/fetch-double';
import {
  attributes,
  change,
  cubic,
  editorWith,
  lastStatus,
  serverEntity,
} from '../testing/documents';
import { JoinTool, type CurvePick, type JoinHost, type JoinRequest } from '../tools/join';
import type { Vec3 } from '../viewport/math';
import { blendCurves } from './blend';
import { matchCurves } from './match';

// Match and Blend against the page's real Client, store and editor (only fetch is replaced:
// testing/fetch-double.ts), with the server's answers typed by its OpenAPI document; and the
// tool's two clicks against a host that records what the page was asked to do.

const http = useFetchDouble();

const tail: CurveFile = {
  kind: 'nurbs',
  degree: 3,
  knots: [0, 0, 0, 0, 0.4, 1, 1, 1, 1],
  control_points: [
    [50, -10, 0],
    [60, -30, 0],
    [80, -20, 0],
    [90, 10, 0],
    [100, 0, 0],
  ],
};

/** A's new curve as POST /api/match answers it (its end poles moved). */
const matched: CurveFile = {
  kind: 'nurbs',
  degree: 3,
  knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1],
  control_points: [
    [0, 0, 0],
    [10, 20, 0],
    [25, 25, 0],
    [40, 10, 0],
    [50, -10, 0],
  ],
};

function matchResult(
  geometric: string | null,
  more: Partial<Api.MatchResult> = {},
): Api.MatchResult {
  return {
    curve: matched,
    requested: 'G3',
    geometric,
    parametric: null,
    tangent_angle: 0,
    curvature_left: 0.01,
    curvature_right: 0.01,
    moved: [1, 2, 3, 4],
    inserted_knots: 1,
    degree_elevation: 0,
    target_parameter: 0,
    degree: 3,
    control_points: 5,
    ...more,
  };
}

const blendCurve: CurveFile = {
  kind: 'nurbs',
  degree: 5,
  knots: [0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1],
  control_points: [
    [40, 0, 0],
    [45, -5, 0],
    [48, -8, 0],
    [49, -9, 0],
    [49.5, -9.5, 0],
    [50, -10, 0],
  ],
};

function blendResult(): Api.BlendResult {
  return {
    curve: blendCurve,
    requested: 'G2',
    start: { geometric: 'G2', parametric: null },
    end: { geometric: 'G2', parametric: null },
    scale: 1.25,
    curvature_variation: { value: 0.000123456, error_estimate: 1e-12, converged: true },
    curvature_extrema: 3,
    degree: 5,
    control_points: 6,
  };
}

const request = (more: Partial<JoinRequest> = {}): JoinRequest => ({
  a: '1',
  end: 'end',
  b: '2',
  toEnd: 'start',
  continuity: 3,
  ...more,
});

describe('Match', () => {
  it("asks the server with both curve files and stores A's new curve in one PUT", async () => {
    const { ed, events } = editorWith(4, [
      serverEntity(1, cubic, attributes('head')),
      serverEntity(2, tail, attributes('tail')),
    ]);
    const done = matchCurves(ed, request());
    await settle();
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual(['POST /api/match']);
    expect(http.calls[0]!.body).toEqual({
      a: cubic,
      b: tail,
      continuity: 'G3',
      end: 'end',
      to_end: 'start',
    });
    http.calls[0]!.respond(200, matchResult('G3'));
    await settle();
    const put = http.calls[1]!;
    expect([put.method, put.path, put.body]).toEqual([
      'PUT',
      '/api/documents/a.hula/entities/1',
      { curve: matched },
    ]);
    put.respond(
      200,
      change(5, {
        name: 'replace',
        changed: [1],
        entities: [serverEntity(1, matched, attributes('head'))],
      }),
    );
    const result = await done;
    expect(result?.geometric).toBe('G3');
    // One request changed the document: one undo step; the entity came with the reply.
    expect(http.calls).toHaveLength(2);
    expect(ed.store.revision).toBe(5);
    expect(ed.store.entities.get('1')?.curve).toEqual(matched);
    expect(ed.store.entities.get('2')?.curve).toEqual(tail);
    expect(ed.selected).toBe('1');
    expect(lastStatus(events)).toEqual({
      text: "Matched head (1)'s end to tail (2)'s start: G3 reached (asked G3), 4 point(s) moved, 1 knot(s) inserted",
      error: false,
    });
  });

  it('matches to B at a parameter (no end sent) and says when less was reached than asked', async () => {
    const { ed, events } = editorWith(1, [serverEntity(1, cubic), serverEntity(2, tail)]);
    http.auto = (c) => {
      if (c.path === '/api/match')
        c.respond(200, matchResult('G1', { requested: 'G2', moved: [2, 3, 4], inserted_knots: 0 }));
      else
        c.respond(
          200,
          change(2, { name: 'replace', changed: [1], entities: [serverEntity(1, matched)] }),
        );
    };
    await matchCurves(ed, { a: '1', end: 'start', b: '2', at: 0.30000042, continuity: 2 });
    expect(http.calls[0]!.body).toEqual({
      a: cubic,
      b: tail,
      continuity: 'G2',
      end: 'start',
      at: 0.30000042,
    });
    expect(lastStatus(events)).toEqual({
      text: "Matched c1 (1)'s start to c2 (2) at t = 0.3: G1 reached (asked G2), 3 point(s) moved",
      error: true,
    });
  });

  it('changes nothing when the server refuses, and says why', async () => {
    const { ed, events } = editorWith(1, [serverEntity(1, cubic), serverEntity(2, tail)]);
    http.auto = (c) => {
      c.respond(501, {
        error: { code: 'Unsupported', message: 'A is rational', where: { field: 'a' } },
      });
    };
    expect(await matchCurves(ed, request())).toBeUndefined();
    expect(http.calls).toHaveLength(1);
    expect(ed.store.revision).toBe(1);
    expect(ed.store.entities.get('1')?.curve).toEqual(cubic);
    expect(lastStatus(events)).toEqual({ text: 'Match failed: A is rational', error: true });
  });

  it('sends nothing for a locked A', async () => {
    const { ed, events } = editorWith(1, [
      serverEntity(1, cubic, attributes('head', { locked: true })),
      serverEntity(2, tail),
    ]);
    expect(await matchCurves(ed, request())).toBeUndefined();
    expect(http.calls).toHaveLength(0);
    expect(lastStatus(events)).toEqual({
      text: 'Match: head (1) is locked: unlock it in the object list',
      error: true,
    });
  });
});

describe('Blend', () => {
  it('asks the server for the blend and stores it as one new, selected curve', async () => {
    const { ed, events } = editorWith(2, [
      serverEntity(1, cubic, attributes('head')),
      serverEntity(2, tail, attributes('tail')),
    ]);
    http.auto = (c) => {
      if (c.path === '/api/blend') c.respond(200, blendResult());
      else
        c.respond(201, {
          label: 3,
          ...change(3, {
            name: 'create',
            added: [3],
            entities: [serverEntity(3, blendCurve, attributes('blend'))],
          }),
        });
    };
    const made = await blendCurves(ed, request({ continuity: 2, end: 'start', toEnd: 'end' }));
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'POST /api/blend',
      'POST /api/documents/a.hula/entities',
    ]);
    expect(http.calls[0]!.body).toEqual({
      a: cubic,
      b: tail,
      continuity: 'G2',
      end: 'start',
      to_end: 'end',
    });
    expect((http.calls[1]!.body as { curve: unknown }).curve).toEqual(blendCurve);
    expect(made?.label).toBe('3');
    expect(made?.result.curvature_extrema).toBe(3);
    expect(ed.selected).toBe('3');
    expect(ed.store.entities.get('1')?.curve).toEqual(cubic);
    expect(lastStatus(events)).toEqual({
      text:
        "Blend blend (3) from head (1)'s start to tail (2)'s end: G2 and G2 at its ends (asked G2), " +
        '∫κ′² ds = 0.0001235, 3 curvature extrema, degree 5',
      error: false,
    });
  });

  it('stores nothing when the ends coincide', async () => {
    const { ed, events } = editorWith(2, [serverEntity(1, cubic), serverEntity(2, tail)]);
    http.auto = (c) => {
      c.respond(400, {
        error: {
          code: 'InvalidArgument',
          message: "A's end and B's start coincide",
          where: { field: 'b' },
        },
      });
    };
    expect(await blendCurves(ed, request({ continuity: 2 }))).toBeUndefined();
    expect(http.calls).toHaveLength(1);
    expect(ed.store.entities.size).toBe(2);
    expect(lastStatus(events)?.text).toBe("Blend failed: A's end and B's start coincide");
  });
});

/** A host that records what the tool asked; `picks` answers its clicks in turn. */
function recordingHost(picks: (CurvePick | null)[]): {
  host: JoinHost;
  runs: [string, JoinRequest][];
  marks: (readonly Vec3[])[];
  statuses: [string, boolean][];
  continuity: number[];
} {
  const runs: [string, JoinRequest][] = [];
  const marks: (readonly Vec3[])[] = [];
  const statuses: [string, boolean][] = [];
  const continuity: number[] = [];
  const host: JoinHost = {
    pick: () => picks.shift() ?? null,
    mark: (p) => marks.push(p),
    status: (t, e) => statuses.push([t, e ?? false]),
    run: (kind, r) => {
      runs.push([kind, r]);
      return Promise.resolve();
    },
    continuityChanged: (k) => continuity.push(k),
  };
  return { host, runs, marks, statuses, continuity };
}

const pick = (
  label: string,
  t: number,
  end: 'start' | 'end' | null,
  nearerEnd: 'start' | 'end' = 'end',
): CurvePick => ({
  label,
  t,
  point: [t, 0, 0],
  end,
  endPoint: nearerEnd === 'start' ? [0, 0, 0] : [1, 0, 0],
  nearerEnd,
});

const click = (tool: JoinTool): void => {
  tool.click('top', {} as PointerEvent);
};
const key = (k: string): KeyboardEvent =>
  ({ key: k, ctrlKey: false, metaKey: false, altKey: false }) as KeyboardEvent;

describe('the Match and Blend tool', () => {
  it("Match: A's clicked end, then B at the clicked point when no end is near", async () => {
    const { host, runs, marks, statuses } = recordingHost([
      pick('1', 0.9, 'end'),
      pick('1', 0.5, null),
      pick('2', 0.3, null, 'start'),
    ]);
    const tool = new JoinTool('match', host);
    expect(statuses.at(-1)![0]).toBe(
      'Match G2: click curve A near the end to move (keys 0-3 choose the continuity)',
    );
    expect(tool.key(key('3'))).toBe(true);
    click(tool);
    expect(marks.at(-1)).toEqual([[1, 0, 0]]);
    expect(statuses.at(-1)![0]).toBe(
      "Match G3: 1's end picked; click curve B near an end, or on it to match to that point (Esc cancels)",
    );
    click(tool);
    expect(statuses.at(-1)).toEqual(['Match: pick a second curve, not 1 again', true]);
    click(tool);
    expect(runs).toEqual([['match', { a: '1', end: 'end', b: '2', continuity: 3, at: 0.3 }]]);
    await settle();
    expect(marks.at(-1)).toEqual([]);
  });

  it('Blend: the nearer end of each curve when the click is between, and G0 refused', () => {
    const { host, runs, statuses, continuity } = recordingHost([
      pick('4', 0.2, null, 'start'),
      pick('5', 0.6, null, 'end'),
    ]);
    const tool = new JoinTool('blend', host, 0);
    // G0 is Match's only: the tool starts at G2.
    expect(tool.continuity).toBe(2);
    expect(tool.key(key('0'))).toBe(true);
    expect(statuses.at(-1)).toEqual(['Blend: G0 is not offered; choose G1–G3', true]);
    expect(tool.key(key('1'))).toBe(true);
    expect(continuity).toEqual([2, 1]);
    click(tool);
    click(tool);
    expect(runs).toEqual([
      ['blend', { a: '4', end: 'start', b: '5', continuity: 1, toEnd: 'end' }],
    ]);
  });

  it('says when the click misses, and Escape forgets the first end', () => {
    const { host, runs, statuses } = recordingHost([
      null,
      pick('1', 0, 'start'),
      pick('2', 1, 'end'),
    ]);
    const tool = new JoinTool('match', host);
    click(tool);
    expect(statuses.at(-1)![1]).toBe(true);
    expect(statuses.at(-1)![0]).toMatch(/^Match: no curve there; /);
    click(tool);
    expect(tool.key(key('Escape'))).toBe(true);
    click(tool);
    expect(runs).toEqual([]);
    expect(statuses.at(-1)![0]).toBe(
      "Match G2: 2's end picked; click curve B near an end, or on it to match to that point (Esc cancels)",
    );
  });
});
