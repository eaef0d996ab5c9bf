import { describe, expect, it } from 'vitest';
import {
  bumpProfile,
  logMagnitude,
  nearestIndex,
  niceTicks,
  paddedRange,
  pixelToValue,
  radius,
} from './scale';

describe('plot scaling', () => {
  // Padded range by hand: [0, 10] padded 5% is [-0.5, 10.5]; NaN samples are ignored.
  it('pads ranges and skips undefined samples', () => {
    expect(paddedRange([0, NaN, 10, 5])).toEqual({ min: -0.5, max: 10.5 });
    expect(paddedRange([2, 2])).toEqual({ min: 1.9, max: 2.1 });
    expect(paddedRange([0, 0])).toEqual({ min: -1, max: 1 });
    expect(paddedRange([NaN])).toEqual({ min: 0, max: 1 });
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
});
