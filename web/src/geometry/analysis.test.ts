import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { CurveFile, FinKind, Point } from '../api/types';
import { NurbsEvaluator } from './nurbs';
import { analyseNurbs } from './analysis';

const data = (name: string): unknown =>
  JSON.parse(readFileSync(new URL(`./testdata/${name}`, import.meta.url), 'utf8')) as unknown;

/** `hula analyse`'s answer (docs/formats.md "Curve analysis"): columns, one entry per sample. */
interface RefFin {
  kind: FinKind;
  t: number[];
  base: Point[];
  tip: (Point | null)[];
}
interface Ref {
  t: number[];
  s: number[];
  points: Point[];
  frames: { T: (Point | null)[]; N: (Point | null)[]; B: (Point | null)[] };
  curvature: (number | null)[];
  torsion: (number | null)[];
  speed: (number | null)[];
  fins?: RefFin[];
}

/** |a − b| ≤ tol × max(1, |b|) component-wise; null (undefined) must match NaN or null. */
function close(a: readonly number[] | undefined, b: readonly number[] | null, tol: number): void {
  if (b === null) {
    expect(a === undefined || a.every((x) => Number.isNaN(x))).toBe(true);
    return;
  }
  const size = Math.max(1, Math.hypot(...b));
  b.forEach((x, k) => {
    expect(Math.abs(a![k]! - x) / size).toBeLessThan(tol);
  });
}

function scalar(a: number | null | undefined, b: number | null, tol: number): void {
  if (b === null) {
    expect(a === null || a === undefined || Number.isNaN(a)).toBe(true);
    return;
  }
  expect(Math.abs(a! - b) / Math.max(1, Math.abs(b))).toBeLessThan(tol);
}

const ALL: FinKind[] = ['curvature', 'torsion', 'normal', 'binormal', 'bishop-u', 'bishop-v'];

describe('analysis in the page', () => {
  // Against the kernel (`hula analyse --by arclength`, testdata/generate.sh): the arc-length
  // samples, Frenet frame, κ, τ, speed and every kind of fin of a rational 3-D cubic and of a
  // cubic with a straight part (κ = 0, no normal, undefined torsion fins there).
  it('matches hula analyse by arc length, fins included', () => {
    for (const name of ['space', 'straight']) {
      const c = NurbsEvaluator.of(data(`${name}.json`) as CurveFile)!;
      const ref = data(`${name}.arclength.json`) as Ref;
      const a = analyseNurbs(c, { samples: 9, by: 'arclength', fins: ALL, scale: 0.5 });
      const length = ref.s[ref.s.length - 1]!;
      ref.t.forEach((t, i) => {
        expect(Math.abs(a.t[i]! - t)).toBeLessThan(1e-10);
        expect(Math.abs(a.s[i]! - ref.s[i]!) / length).toBeLessThan(1e-10);
        close(a.points[i], ref.points[i]!, 1e-10);
        close(a.frames[i]!.T, ref.frames.T[i]!, 1e-9);
        close(a.frames[i]!.N, ref.frames.N[i]!, 1e-9);
        close(a.frames[i]!.B, ref.frames.B[i]!, 1e-9);
        scalar(a.kappa[i], ref.curvature[i]!, 1e-9);
        scalar(a.tau[i], ref.torsion[i]!, 1e-8);
        scalar(a.speed[i], ref.speed[i]!, 1e-10);
      });
      for (const fin of ref.fins!) {
        const comb = a.combs[fin.kind]!;
        fin.base.forEach((b, i) => {
          close(comb.base[i], b, 1e-12);
          close(comb.tip[i] ?? undefined, fin.tip[i]!, 1e-9);
        });
      }
      expect(a.planar).toBe(name === 'straight');
    }
  });

  // Against the kernel (`hula analyse --by parameter`): evenly spaced parameters, no arc length.
  it('matches hula analyse by parameter', () => {
    const c = NurbsEvaluator.of(data('space.json') as CurveFile)!;
    const ref = data('space.parameter.json') as Ref;
    const a = analyseNurbs(c, { samples: 7, by: 'parameter', fins: [], scale: 1 });
    expect(a.s).toEqual([]);
    ref.t.forEach((t, i) => {
      expect(a.t[i]).toBe(t);
      close(a.points[i], ref.points[i]!, 1e-12);
      scalar(a.kappa[i], ref.curvature[i]!, 1e-10);
      scalar(a.tau[i], ref.torsion[i]!, 1e-9);
    });
    expect(a.fins).toEqual({});
  });
});
