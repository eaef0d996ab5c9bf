import uPlot from 'uplot';
import { describe, expect, it } from 'vitest';
import {
  boxDiagonal,
  bumpProfile,
  logMagnitude,
  nearestIndex,
  niceTicks,
  paddedRange,
  pixelToValue,
  radius,
  spanFloor,
  stepDecimals,
  tickLabels,
} from './scale';

/** Tick positions as uPlot places them: multiples of the increment, rounded to its decimals. */
function uplotSplits(min: number, max: number, incr: number): number[] {
  const dec = Math.max(0, stepDecimals(incr));
  const out: number[] = [];
  for (let v = Math.ceil(min / incr) * incr; v <= max; v += incr) out.push(Number(v.toFixed(dec)));
  return out;
}

/** A seeded linear congruential generator in [0, 1) (property tests are reproducible). */
function lcg(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

describe('plot scaling', () => {
  // Padded range by hand: [0, 10] padded 5% is [-0.5, 10.5]; NaN samples are ignored.
  it('pads ranges and skips undefined samples', () => {
    expect(paddedRange([0, NaN, 10, 5])).toEqual({ min: -0.5, max: 10.5 });
    expect(paddedRange([2, 2])).toEqual({ min: 1.9, max: 2.1 });
    expect(paddedRange([0, 0])).toEqual({ min: -1, max: 1 });
    expect(paddedRange([NaN])).toEqual({ min: 0, max: 1 });
  });

  // Span floor by hand: [1, 1.001] floored to span 0.1 is centred, [0.9505, 1.0505], then padded
  // 5 % of 0.1; a constant series gets the floor; a range wider than the floor is untouched.
  it('widens a range to its floor about its centre', () => {
    const r = paddedRange([1, 1.001], 0.05, 0.1);
    expect(r.min).toBeCloseTo(0.9505 - 0.005, 12);
    expect(r.max).toBeCloseTo(1.0505 + 0.005, 12);
    expect(paddedRange([2, 2], 0.05, 1)).toEqual({ min: 1.45, max: 2.55 });
    expect(paddedRange([0, 10], 0.05, 1)).toEqual(paddedRange([0, 10]));
    // spanFloor: 5 % of the larger of max |v| and the reference; NaN skipped.
    expect(spanFloor([NaN, -4, 2])).toBeCloseTo(0.2, 15);
    expect(spanFloor([1e-7, 0], 0.01)).toBeCloseTo(5e-4, 15);
    expect(spanFloor([], Infinity)).toBe(0);
    // boxDiagonal of a 3-4-12 box is 13.
    expect(
      boxDiagonal([
        [0, 0, 0],
        [3, 4, 12],
        [1, 1, 1],
      ]),
    ).toBe(13);
    expect(boxDiagonal([])).toBe(0);
  });

  // 1-2-5 ticks: [0, 1] in ~5 ticks steps by 0.2; [-3, 7] by 2.
  it('places nice ticks inside the range', () => {
    expect(niceTicks({ min: 0, max: 1 })).toEqual([0, 0.2, 0.4, 0.6, 0.8, 1]);
    expect(niceTicks({ min: -3, max: 7 })).toEqual([-2, 0, 2, 4, 6]);
    expect(() => niceTicks({ min: 1, max: 1 })).toThrow(/empty/);
  });

  // log10|κ| of 0.01, -100 and 0 is -2, 2 and a gap; radius is 1/|κ| with a gap at 0.
  it('log axes and radius leave gaps, not infinities', () => {
    expect(Array.from(logMagnitude([0.01, -100, 0]))).toEqual([-2, 2, NaN]);
    expect(Array.from(radius([0.5, -4, 0]))).toEqual([2, 0.25, NaN]);
  });

  // Binary search against a linear scan over a sorted abscissa array.
  it('finds the nearest sample like a linear scan', () => {
    const xs = Array.from({ length: 101 }, (_, i) => (i * i) / 100);
    for (let x = -1; x <= 101; x += 0.37) {
      let best = 0;
      xs.forEach((v, i) => {
        if (Math.abs(v - x) < Math.abs(xs[best]! - x)) best = i;
      });
      expect(Math.abs(xs[nearestIndex(xs, x)]! - x)).toBe(Math.abs(xs[best]! - x));
    }
    expect(pixelToValue(50, 200, { min: 0, max: 4 })).toBe(1);
    expect(pixelToValue(50, 200, { min: 0, max: 4 }, true)).toBe(3);
  });

  // The cos² bump adds the full delta at its centre, nothing beyond its half-width.
  it('bumps a profile smoothly and locally', () => {
    const xs = [0, 0.25, 0.5, 0.75, 1];
    const out = bumpProfile(xs, [1, 1, 1, 1, 1], 0.5, 2, 0.5);
    expect(Array.from(out).map((v) => Number(v.toFixed(12)))).toEqual([1, 2, 3, 2, 1]);
  });

  // The torsion graph's bug: over [0.00201, 0.00249] with ticks 0.0001 apart, uPlot's default
  // formatter (3 decimals) prints "0.002" five times; tickLabels gives 4 decimals, all distinct.
  it('labels close ticks distinctly where the default repeats them', () => {
    const splits = uplotSplits(0.00201, 0.00249, 0.0001);
    expect(splits).toHaveLength(4);
    const defaults = splits.map((v) => uPlot.fmtNum(v));
    expect(new Set(defaults).size).toBeLessThan(splits.length);
    expect(tickLabels(splits)).toEqual(['0.0021', '0.0022', '0.0023', '0.0024']);
  });

  // Digits by hand from the spacing: 2.5 steps keep two decimals, round steps none, a zero computed
  // as 1e-19 prints "0.0000" (no "-0"), large and tiny values switch to scientific notation.
  it('takes its digits from the tick spacing', () => {
    expect(stepDecimals(0.0025)).toBe(4);
    expect(stepDecimals(0.2)).toBe(1);
    expect(stepDecimals(500)).toBe(-2);
    expect(tickLabels([0, 0.25, 0.5, 0.75])).toEqual(['0.00', '0.25', '0.50', '0.75']);
    expect(tickLabels([-20, 0, 20, 40])).toEqual(['-20', '0', '20', '40']);
    expect(tickLabels([-0.0002, -1e-19, 0.0002])).toEqual(['-0.0002', '0.0000', '0.0002']);
    expect(tickLabels([1e6, 1.5e6, 2e6])).toEqual(['1.0e+6', '1.5e+6', '2.0e+6']);
    expect(tickLabels([2e-7, 4e-7, 6e-7])).toEqual(['2e-7', '4e-7', '6e-7']);
    expect(tickLabels([1.2e-6, 1.4e-6])).toEqual(['1.2e-6', '1.4e-6']);
    expect(tickLabels([0.5])).toEqual(['0.5']);
  });

  // Property (seeded, 2000 ranges from 1e-9 to 1e8 wide, anywhere): for uPlot's 1, 2, 2.5, 5 × 10^k
  // steps the labels are distinct and each reads back as its own tick within 1e-6 of the spacing
  // (the labels stay aligned with their positions: only formatted, never moved).
  it('gives distinct labels that read back as their ticks', () => {
    const random = lcg(20261202);
    const repeated: string[] = [];
    let worst = 0;
    for (let n = 0; n < 2000; n++) {
      const incr = [1, 2, 2.5, 5][Math.floor(random() * 4)]! * 10 ** Math.floor(-9 + random() * 17);
      const min = (random() - 0.5) * incr * 10 ** Math.floor(random() * 4);
      const splits = uplotSplits(min, min + incr * (2 + Math.floor(random() * 8)), incr);
      const labels = tickLabels(splits);
      if (new Set(labels).size !== splits.length) repeated.push(labels.join(' '));
      labels.forEach((l, i) => {
        worst = Math.max(worst, Math.abs(Number(l) - splits[i]!) / incr);
      });
    }
    expect(repeated).toEqual([]);
    expect(worst).toBeLessThanOrEqual(1e-6);
  });
});
