import { describe, expect, it } from 'vitest';
import { graphMarkers, readout, spanOf, valueFloor } from './graph';
import type { Analysis } from '../api/types';
import { boxDiagonal, paddedRange } from './scale';

/** A seeded linear congruential generator in [-1, 1) (the noise is reproducible). */
function noise(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return (2 * s) / 2 ** 32 - 1;
  };
}

/** Share of the plotted height that a series' own variation takes. */
function heightShare(values: number[], range: { min: number; max: number }): number {
  return (Math.max(...values) - Math.min(...values)) / (range.max - range.min);
}

describe('value axis floor', () => {
  const rnd = noise(7);
  const n = 200;

  // A straight line 100 long whose κ carries 1e-7 of rounding noise: the axis spans at least
  // 5 % of 1/100 (the curve's scale), so the noise takes under 1e-3 of the height (< 1 px);
  // without the floor it filled 1/1.1 of it.
  it('draws a straight line as flat', () => {
    const points = Array.from({ length: n }, (_, i) => [(100 * i) / (n - 1), 0, 0]);
    const kappa = Array.from({ length: n }, () => 1e-7 * Math.abs(rnd()));
    const size = boxDiagonal(points);
    expect(size).toBeCloseTo(100, 12);
    expect(valueFloor('kappa', kappa, size)).toBeCloseTo(0.05 / 100, 15);
    expect(heightShare(kappa, paddedRange(kappa))).toBeGreaterThan(0.9);
    expect(
      heightShare(kappa, paddedRange(kappa, 0.05, valueFloor('kappa', kappa, size))),
    ).toBeLessThan(1e-3);
  });

  // A circle of radius 10 (κ = 0.1) with 1e-7 noise: floored by 5 % of max |κ| = 0.005, the noise
  // takes under 1e-4 of the height and the range is centred on κ = 0.1.
  it('draws a circle as flat at κ = 1/R', () => {
    const points = Array.from({ length: n }, (_, i) => {
      const a = (2 * Math.PI * i) / n;
      return [10 * Math.cos(a), 10 * Math.sin(a), 0];
    });
    const kappa = Array.from({ length: n }, () => 0.1 + 1e-7 * rnd());
    const r = paddedRange(kappa, 0.05, valueFloor('kappa', kappa, boxDiagonal(points)));
    expect(heightShare(kappa, r)).toBeLessThan(1e-4);
    expect((r.min + r.max) / 2).toBeCloseTo(0.1, 6);
    // Flatter than its floor: the graph marks no extrema of this noise.
    expect(spanOf(kappa)).toBeLessThan(valueFloor('kappa', kappa, boxDiagonal(points)));
    expect(spanOf([NaN, 2, -1])).toBe(3);
    expect(spanOf([])).toBe(0);
    // The radius (10 ± 1e-5) and speed graphs are floored by their own size the same way.
    const radius = kappa.map((k) => 1 / k);
    expect(
      heightShare(radius, paddedRange(radius, 0.05, valueFloor('radius', radius, 20))),
    ).toBeLessThan(1e-4);
    // log10 κ: the floor is 5 % of κ in decades, log10(1.05).
    expect(valueFloor('logkappa', kappa.map(Math.log10), 20)).toBeCloseTo(Math.log10(1.05), 15);
  });

  // A real variation (κ from 0.1 to 0.2 along the curve) is wider than its floor and keeps the
  // plain padded range: the floor changes nothing there.
  it('leaves a real variation at full height', () => {
    const kappa = Array.from({ length: n }, (_, i) => 0.1 + (0.1 * i) / (n - 1));
    const floor = valueFloor('kappa', kappa, 50);
    expect(floor).toBeCloseTo(0.05 * 0.2, 15);
    expect(paddedRange(kappa, 0.05, floor)).toEqual(paddedRange(kappa));
  });
});

describe('graph markers and readout', () => {
  // Five samples at t = 0, 0.25, …, 1 with arc lengths 0, 10, …, 40.
  const a: Analysis = {
    t: [0, 0.25, 0.5, 0.75, 1],
    s: [0, 10, 20, 30, 40],
    points: [],
    kappa: [0.1, 0.2, 0.5, 0.2, 0],
    tau: [0.01, 0.03, 0.02, -0.01, 0.02],
    speed: [],
    planar: false,
    frames: [],
    fins: {},
    combs: {},
    features: [
      { kind: 'inflection', t: 1, s: 40 },
      { kind: 'curvature-max', t: 0.5, s: 20 },
      { kind: 'curvature-max', t: 0.5000001, s: 20 }, // the same maximum listed twice
      { kind: 'torsion-max', t: 0.25, s: 10 },
      { kind: 'torsion-min', t: 0.75, s: 30 },
      { kind: 'knot', t: 0.5, s: 20 },
    ],
  };
  const xs = (by: 's' | 't'): Float64Array => Float64Array.from(by === 's' ? a.s : a.t);

  it('the τ graph marks τ extrema only (and knots), at τ values', () => {
    const m = graphMarkers(a, 'tau', 's', xs('s'), Float64Array.from(a.tau as number[]));
    expect(m.map((x) => x.kind)).toEqual(['torsion-max', 'torsion-min', 'knot']);
    expect(m[0]).toEqual({ x: 10, y: 0.03, kind: 'torsion-max' });
    expect(m[1]).toEqual({ x: 30, y: -0.01, kind: 'torsion-min' });
  });

  it('the κ graph marks one curvature maximum, inflections and knots, against t when asked', () => {
    const m = graphMarkers(a, 'kappa', 't', xs('t'), Float64Array.from(a.kappa as number[]));
    expect(m.map((x) => x.kind)).toEqual(['inflection', 'curvature-max', 'knot']);
    expect(m[1]).toEqual({ x: 0.5, y: 0.5, kind: 'curvature-max' });
  });

  it('reads s or t as plotted, κ, the radius and τ', () => {
    expect(readout(a, 2, 's')).toBe('s = 20 · κ = 0.5 · R = 2 · τ = 0.02');
    expect(readout(a, 4, 't')).toBe('t = 1 · κ = 0 · R = ∞ · τ = 0.02');
  });
});
