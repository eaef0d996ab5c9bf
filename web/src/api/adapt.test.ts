import { describe, expect, it } from 'vitest';
import { analysisFromServer, entityFromServer, historyFromServer, withHandles } from './adapt';
import type { CurveFile } from './types';

describe('server JSON adapters', () => {
  // A curve entity (curve file members + label/attributes) splits into entity and curve file.
  it('splits an entity into its curve file', () => {
    const e = entityFromServer({
      format: 'hula-curve',
      version: 1,
      kind: 'bezier',
      control_points: [
        [0, 0],
        [1, 1],
      ],
      label: 3,
      attributes: { name: 'b', colour: '#1f77b4' },
      provenance: null,
      constraints: [],
    });
    expect(e.label).toBe('3');
    expect(e.name).toBe('b');
    expect(e.curve).toEqual({
      format: 'hula-curve',
      version: 1,
      kind: 'bezier',
      control_points: [
        [0, 0],
        [1, 1],
      ],
    });
  });

  // Analysis columns of a straight segment of length 2 sampled by arc length (the server's s column); fins
  // become hairs plus an envelope split at undefined tips; knots become C/G badges; planarity is the server's.
  it('regroups the analysis columns', () => {
    const a = analysisFromServer(
      {
        t: [0, 0.5, 1],
        s: [0, 1, 2],
        points: [
          [0, 0, 0],
          [1, 0, 0],
          [2, 0, 0],
        ],
        frames: {
          T: [
            [1, 0, 0],
            [1, 0, 0],
            [1, 0, 0],
          ],
          N: [null, null, null],
          B: [null, null, null],
        },
        curvature: [0, 0, 0],
        torsion: [null, null, null],
        curvature_derivative: [null, null, null],
        speed: [2, 2, 2],
        fins: [
          {
            kind: 'curvature',
            scale: 1,
            t: [0, 0.5, 1],
            base: [
              [0, 0, 0],
              [1, 0, 0],
              [2, 0, 0],
            ],
            tip: [[0, 1, 0], null, [2, 1, 0]],
          },
        ],
        planarity: { planar: true, normal: null, max_deviation: 0, tolerance: 1e-10 },
        features: {
          inflections: [],
          curvature_extrema: [],
          torsion_extrema: [],
          knots: [
            {
              t: 0.5,
              multiplicity: 1,
              parametric: 2,
              geometric: 2,
              tangent_angle: 0,
              curvature_left: 0,
              curvature_right: 0,
              left: [],
              right: [],
            },
          ],
          curvature_monotonicity: { monotone: true, pieces: [], violations: [] },
          maximum_curvature: { value: 0, t: 0 },
          self_intersections: { tolerance: 1e-9, points: [], overlaps: [] },
        },
      },
      'arclength',
    );
    expect(a.s).toEqual([0, 1, 2]);
    expect(a.planar).toBe(true);
    expect(a.frames[1]!.N.every(Number.isNaN)).toBe(true);
    expect(a.fins.curvature).toEqual([
      [
        [0, 0, 0],
        [0, 1, 0],
      ],
      [
        [2, 0, 0],
        [2, 1, 0],
      ],
    ]);
    expect(a.features).toEqual([{ kind: 'knot', t: 0.5, continuity: 'C2/G2', s: 1 }]);
  });

  // History entries keep revision, name and applied.
  it('reads the history list', () => {
    const h = historyFromServer({
      revision: 2,
      history: [{ revision: 1, name: 'add curve', time: 'x', changed: [1], applied: true }],
    });
    expect(h.steps).toEqual([{ revision: 1, name: 'add curve', time: 'x', applied: true }]);
  });

  // withHandles against the server's move semantics by hand: an interpolated 2-D curve's data point 1
  // moves (its z dropped, parameters kept); a NURBS curve's control point; a law curve has no handles.
  it('moves the handles a drag moves', () => {
    const spline: CurveFile = {
      kind: 'interpolated',
      points: [
        [0, 0],
        [10, 0],
        [20, 5],
      ],
      parameters: [0, 0.4, 1],
    };
    expect(
      withHandles(spline, [
        [0, 0, 0],
        [12, -3, 0],
        [20, 5, 0],
      ]),
    ).toEqual({
      ...spline,
      points: [
        [0, 0],
        [12, -3],
        [20, 5],
      ],
    });
    // The original is not changed.
    expect(spline).toEqual({
      ...spline,
      points: [
        [0, 0],
        [10, 0],
        [20, 5],
      ],
    });
    const nurbs: CurveFile = {
      kind: 'nurbs',
      degree: 1,
      knots: [0, 0, 1, 1],
      control_points: [
        [0, 0, 0],
        [1, 1, 1],
      ],
    };
    const n = withHandles(nurbs, [
      [0, 0, 0],
      [2, 2, 2],
    ]);
    expect(n.kind === 'nurbs' && n.control_points).toEqual([
      [0, 0, 0],
      [2, 2, 2],
    ]);
    const law: CurveFile = { kind: 'law', expression: 'vec(t, t^2)', domain: [0, 1] };
    expect(withHandles(law, [])).toBe(law);
  });
});
