import { describe, expect, it } from 'vitest';
import { profileLaw } from './design';

/** Evaluate a profile law of s: terms "a", "b*s" and "c*abs(s - d)" joined by " + ". */
function evaluate(law: string, s: number): number {
  let sum = 0;
  for (const term of law.split(' + ')) {
    const abs = /^(\S+)\*abs\(s - (\S+)\)$/.exec(term);
    const lin = /^(\S+)\*s$/.exec(term);
    if (abs) sum += Number(abs[1]) * Math.abs(s - Number(abs[2]));
    else if (lin) sum += Number(lin[1]) * s;
    else {
      expect(Number.isFinite(Number(term))).toBe(true);
      sum += Number(term);
    }
  }
  return sum;
}

describe('profileLaw', () => {
  // The law equals the piecewise-linear interpolant of the samples at the 64 nodes and between them.
  it('interpolates the samples linearly', () => {
    const length = 130;
    const xs = Float64Array.from({ length: 200 }, (_, i) => (length * i) / 199);
    const ys = xs.map((s) => 0.005 + 0.001 * Math.sin(s / 9));
    const law = profileLaw(xs, ys, length);
    const h = length / 63;
    for (let i = 0; i < 63; i++) {
      const node = (s: number): number => {
        let j = 0;
        while (j + 2 < xs.length && xs[j + 1]! < s) j++;
        const f = (s - xs[j]!) / (xs[j + 1]! - xs[j]!);
        return ys[j]! + f * (ys[j + 1]! - ys[j]!);
      };
      const a = node(i * h);
      const b = node((i + 1) * h);
      expect(evaluate(law, i * h)).toBeCloseTo(a, 12);
      expect(evaluate(law, (i + 0.5) * h)).toBeCloseTo((a + b) / 2, 12);
    }
  });

  // A constant profile is one constant term: no kinks for the solver.
  it('keeps a constant profile constant', () => {
    const law = profileLaw([0, 50, 100], [0.01, 0.01, 0.01], 100);
    expect(law).not.toContain('abs');
    for (const s of [0, 33, 100]) expect(evaluate(law, s)).toBeCloseTo(0.01, 15);
  });
});
