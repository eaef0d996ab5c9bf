import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { analysisFromServer } from '../api/adapt';
import type * as Api from '../api/openapi';
import type { CurveFile, FinKind, Point } from '../api/types';
import { analyseNurbs } from './analysis';
import { NurbsEvaluator } from './nurbs';

// The conformance corpus (tests/data/conformance, README.md there) through the page: the
// preview kernel against the kernel's own analysis of the same curves (`hula analyse`, the
// answer every door gives: testdata/conformance/, written by testdata/generate.sh), and the
// features the page shows, which are the server's, one for one.

const corpus = new URL('../../../tests/data/conformance/', import.meta.url);
const read = (url: URL): unknown => JSON.parse(readFileSync(url, 'utf8')) as unknown;
const names = readFileSync(new URL('corpus.txt', corpus), 'utf8').split('\n').filter(Boolean);

/** The analysis as every door writes it (docs/formats.md "Curve analysis"). */
interface Ref {
  t: number[];
  s: number[];
  points: Point[];
  frames: { T: (Point | null)[]; N: (Point | null)[]; B: (Point | null)[] };
  curvature: (number | null)[];
  torsion: (number | null)[];
  speed: (number | null)[];
  fins: { kind: FinKind; scale: number; t: number[]; base: Point[]; tip: (Point | null)[] }[];
  planarity: { planar: boolean };
  features: Record<string, { t: number }[]>;
}

const TOL = 1e-9;
/** |a − b| ≤ TOL × max(1, |b|) over a vector, null in the reference matching NaN or null. */
function vecClose(a: readonly number[] | null | undefined, b: readonly number[] | null): boolean {
  if (b === null) return !a || a.every((x) => Number.isNaN(x));
  if (!a) return false;
  const size = Math.max(1, Math.hypot(...b));
  return b.every((x, k) => Math.abs(a[k]! - x) <= TOL * size);
}
function close(a: number | null | undefined, b: number | null): boolean {
  if (b === null) return a === null || a === undefined || Number.isNaN(a);
  return Math.abs(a! - b) <= TOL * Math.max(1, Math.abs(b));
}

const SAMPLES = 33;
const FINS: FinKind[] = ['curvature', 'torsion'];
const previewable = names.filter((n) => {
  const c = read(new URL(`${n}.json`, corpus)) as CurveFile;
  return c.kind === 'nurbs' || c.kind === 'bezier';
});

describe('conformance corpus in the page', () => {
  it('has the NURBS and Bézier curves of the corpus to preview', () => {
    expect(previewable.length).toBeGreaterThanOrEqual(8);
  });

  for (const name of previewable) {
    for (const by of ['parameter', 'arclength'] as const) {
      // checks the preview's columns and fins within 1e-9 relative of the kernel's answer
      it(`previews ${name} by ${by} as the kernel analyses it`, () => {
        const curve = read(new URL(`${name}.json`, corpus)) as CurveFile;
        const ref = read(
          new URL(`./testdata/conformance/${name}.${by}.json`, import.meta.url),
        ) as Ref;
        const c = NurbsEvaluator.of(curve)!;
        const scale = ref.fins[0]!.scale;
        const a = analyseNurbs(c, { samples: SAMPLES, by, fins: FINS, scale: 1 });
        const bad: string[] = [];
        ref.t.forEach((t, i) => {
          if (!close(a.t[i], t)) bad.push(`t[${i}]`);
          if (by === 'arclength' && !close(a.s[i], ref.s[i]!)) bad.push(`s[${i}]`);
          if (!vecClose(a.points[i], ref.points[i]!)) bad.push(`points[${i}]`);
          if (!vecClose(a.frames[i]!.T, ref.frames.T[i]!)) bad.push(`T[${i}]`);
          if (!vecClose(a.frames[i]!.N, ref.frames.N[i]!)) bad.push(`N[${i}]`);
          if (!vecClose(a.frames[i]!.B, ref.frames.B[i]!)) bad.push(`B[${i}]`);
          if (!close(a.kappa[i], ref.curvature[i]!)) bad.push(`curvature[${i}]`);
          if (!close(a.tau[i], ref.torsion[i]!)) bad.push(`torsion[${i}]`);
          if (!close(a.speed[i], ref.speed[i]!)) bad.push(`speed[${i}]`);
        });
        // The page draws its fins at scale 1 and scales them by a drawing factor: compare the
        // directions scaled back to the kernel's comb (base + scale × (tip − base)).
        for (const fin of ref.fins) {
          const comb = a.combs[fin.kind]!;
          fin.base.forEach((b, i) => {
            if (!vecClose(comb.base[i], b)) bad.push(`${fin.kind} base[${i}]`);
            const q = comb.tip[i];
            const tip = q ? q.map((x, k) => b[k]! + fin.scale * (x - comb.base[i]![k]!)) : null;
            if (!vecClose(tip, fin.tip[i]!)) bad.push(`${fin.kind} tip[${i}]`);
          });
        }
        expect(scale).toBeGreaterThan(0);
        expect(bad).toEqual([]);
      });
    }
  }

  for (const name of names) {
    // checks that the page's features are the server's lists, one for one, in t
    it(`shows the server's features of ${name}`, () => {
      const ref = read(
        new URL(`./testdata/conformance/${name}.parameter.json`, import.meta.url),
      ) as Ref;
      const a = analysisFromServer(ref as unknown as Api.Analysis, 'parameter');
      const expected = [
        ...ref.features['inflections']!.map((f) => ['inflection', f.t]),
        ...ref.features['curvature_extrema']!.map((f) => ['curvature', f.t]),
        ...ref.features['torsion_extrema']!.map((f) => ['torsion', f.t]),
        ...ref.features['knots']!.map((f) => ['knot', f.t]),
      ];
      expect(a.features.map((f) => [f.kind.replace(/-(max|min)$/, ''), f.t])).toEqual(expected);
      expect(a.planar).toBe(ref.planarity.planar);
      if (name === 'space_bezier_issue22') expect(ref.features['inflections']).toEqual([]);
      if (name === 'law_helix') {
        expect(ref.features['curvature_extrema']).toEqual([]);
        expect(ref.features['knots']).toEqual([]);
      }
    });
  }
});
