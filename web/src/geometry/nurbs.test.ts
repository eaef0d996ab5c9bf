import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { CurveFile } from '../api/types';
import { NurbsEvaluator } from './nurbs';
import { arcLength, frenetSamples } from './analysis';

const data = (name: string): unknown =>
  JSON.parse(readFileSync(new URL(`./testdata/${name}`, import.meta.url), 'utf8')) as unknown;

const curve = (name: string): CurveFile => data(`${name}.json`) as CurveFile;

/** The rational quadratic quarter circle of radius 10 about the origin, t ∈ [0, 1]. */
const quarter: CurveFile = {
  kind: 'nurbs',
  degree: 2,
  knots: [0, 0, 0, 1, 1, 1],
  control_points: [
    [10, 0, 0],
    [10, 10, 0],
    [0, 10, 0],
  ],
  weights: [1, Math.SQRT1_2, 1],
};

function evaluate(c: NurbsEvaluator, t: number, order = 3): number[][] {
  const out = new Float64Array(3 * (order + 1));
  c.derivatives(t, order, out);
  return Array.from({ length: order + 1 }, (_, k) => Array.from(out.subarray(3 * k, 3 * k + 3)));
}

describe('NURBS evaluation', () => {
  // Closed form: every point of the rational quarter circle is at distance 10 from the origin, its
  // curvature is 1/10 and its length is 5π.
  it('evaluates the rational quarter circle exactly', () => {
    const c = NurbsEvaluator.of(quarter)!;
    for (const t of [0, 0.1, 0.37, 0.5, 0.81, 1]) {
      const [p] = evaluate(c, t);
      expect(Math.hypot(...p!)).toBeCloseTo(10, 12);
    }
    for (const f of frenetSamples(c, [0, 0.25, 0.5, 0.9, 1]))
      expect(f.curvature).toBeCloseTo(0.1, 13);
    expect(arcLength(c)).toBeCloseTo(5 * Math.PI, 10);
  });

  // Closed form: the Bernstein form of a cubic Bézier, C = Σ B_i,3 P_i, and its derivatives
  // C' = 3 Σ B_i,2 ΔP_i, C'' = 6 Σ B_i,1 Δ²P_i, C''' = 6 Δ³P_0.
  it('evaluates a Bézier curve and its derivatives in Bernstein form', () => {
    const P = [
      [0, 0, 0],
      [1, 3, 2],
      [4, -1, 5],
      [6, 2, -1],
    ];
    const c = NurbsEvaluator.of({ kind: 'bezier', control_points: P })!;
    const d1 = [0, 1, 2].map((i) => P[i + 1]!.map((x, k) => x - P[i]![k]!));
    const d2 = [0, 1].map((i) => d1[i + 1]!.map((x, k) => x - d1[i]![k]!));
    const d3 = d2[1]!.map((x, k) => x - d2[0]![k]!);
    for (const t of [0, 0.3, 0.5, 0.77, 1]) {
      const s = 1 - t;
      const expected = [0, 1, 2].map((k) => [
        s ** 3 * P[0]![k]! +
          3 * s * s * t * P[1]![k]! +
          3 * s * t * t * P[2]![k]! +
          t ** 3 * P[3]![k]!,
        3 * (s * s * d1[0]![k]! + 2 * s * t * d1[1]![k]! + t * t * d1[2]![k]!),
        6 * (s * d2[0]![k]! + t * d2[1]![k]!),
        6 * d3[k]!,
      ]);
      const got = evaluate(c, t);
      for (let order = 0; order <= 3; order++)
        for (let k = 0; k < 3; k++) expect(got[order]![k]!).toBeCloseTo(expected[k]![order]!, 11);
    }
  });

  // Against the kernel (`hula eval --derivatives 3`, testdata/generate.sh): a rational 3-D cubic
  // with a double interior knot, and a cubic with a straight part, right-sided at the knots.
  it('matches the kernel’s derivatives to order 3', () => {
    for (const name of ['space', 'straight']) {
      const c = NurbsEvaluator.of(curve(name))!;
      const ref = data(`${name}.eval.json`) as {
        results: { t: number; derivatives: number[][] }[];
      };
      for (const r of ref.results) {
        const got = evaluate(c, r.t);
        r.derivatives.forEach((d, order) => {
          const size = Math.max(1, Math.hypot(...d));
          for (let k = 0; k < 3; k++)
            expect(Math.abs(got[order]![k]! - d[k]!) / size).toBeLessThan(1e-12);
        });
      }
    }
  });

  // |C'| two ways: the speed (degree p − 1 basis) against the first derivative of A2.3/A4.2.
  it('gives the speed of the first derivative', () => {
    for (const name of ['space', 'straight']) {
      const c = NurbsEvaluator.of(curve(name))!;
      for (const t of [0, 0.13, 0.2, 0.5, 0.77, 1]) {
        const d1 = evaluate(c, t, 1)[1]!;
        expect(c.speed(t)).toBeCloseTo(Math.hypot(...d1), 10);
      }
    }
  });

  // Derivatives above the degree vanish: a quadratic's third derivative is zero everywhere.
  it('gives zero derivatives above the degree', () => {
    const c = NurbsEvaluator.of({ ...quarter, weights: null })!;
    expect(evaluate(c, 0.4)[3]).toEqual([0, 0, 0]);
  });

  // Bad files have no evaluator (the page then waits for the server), never a crash.
  it('refuses what is not a valid NURBS', () => {
    const good = curve('space') as Extract<CurveFile, { kind: 'nurbs' }>;
    expect(NurbsEvaluator.of(good)).not.toBeNull();
    expect(NurbsEvaluator.of({ ...good, knots: good.knots.slice(1) })).toBeNull();
    expect(NurbsEvaluator.of({ ...good, knots: [...good.knots].reverse() })).toBeNull();
    expect(NurbsEvaluator.of({ ...good, degree: 8 })).toBeNull();
    expect(
      NurbsEvaluator.of({ ...good, weights: good.weights!.map((w, i) => (i ? w : 0)) }),
    ).toBeNull();
    expect(
      NurbsEvaluator.of(good, [[0, 0, 0], [NaN, 1, 2], ...good.control_points.slice(2)]),
    ).toBeNull();
    expect(
      NurbsEvaluator.of({
        kind: 'interpolated',
        points: [
          [0, 0, 0],
          [1, 1, 0],
        ],
      }),
    ).toBeNull();
  });

  // The span search: right-sided at an interior knot, the last non-empty span at the domain's end.
  it('finds spans as the kernel does', () => {
    const c = NurbsEvaluator.of(curve('space'))!;
    expect(c.span(0)).toBe(3);
    expect(c.span(0.2)).toBe(4);
    expect(c.span(0.5)).toBe(6);
    expect(c.span(0.49)).toBe(4);
    expect(c.span(1)).toBe(7);
    expect(c.breakpoints()).toEqual([0, 0.2, 0.5, 0.8, 1]);
  });
});
