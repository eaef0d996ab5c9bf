// Plot scaling for the linked graphs: ranges, ticks, axis labels, log axes,
// hover lookup, and the profile edit of the design-by-curvature graph. Pure functions.

/** A closed range [min, max] with min < max. */
export interface Range {
  readonly min: number;
  readonly max: number;
}

/** The least and greatest finite values of `values` (NaN and ±Infinity skipped); null when there is none. */
export function finiteExtent(values: ArrayLike<number>): { min: number; max: number } | null {
  let min = Infinity;
  let max = -Infinity;
  for (let i = 0; i < values.length; i++) {
    const v = values[i]!;
    if (!Number.isFinite(v)) continue;
    if (v < min) min = v;
    if (v > max) max = v;
  }
  return min === Infinity ? null : { min, max };
}

/**
 * The range of the finite values of `values`, padded by `pad` of its span on
 * each side. A constant series gets ±(|v|·pad or 1); no finite value gives [0, 1].
 * NaN marks undefined samples (torsion where κ = 0) and is skipped. With
 * `minSpan` > 0 the range, before padding, is at least `minSpan` wide, centred
 * on the values (see spanFloor): rounding noise is then drawn as the flat line it is.
 */
export function paddedRange(values: ArrayLike<number>, pad = 0.05, minSpan = 0): Range {
  const extent = finiteExtent(values);
  if (!extent) return { min: 0, max: 1 };
  let { min, max } = extent;
  if (max - min < minSpan) {
    const mid = (min + max) / 2;
    min = mid - minSpan / 2;
    max = mid + minSpan / 2;
  }
  if (min === max) {
    const h = Math.abs(min) * pad || 1;
    return { min: min - h, max: max + h };
  }
  const h = (max - min) * pad;
  return { min: min - h, max: max + h };
}

/** The share of a graph's scale below which a variation is not stretched to full height. */
export const SPAN_FLOOR_FRACTION = 0.05;

/**
 * The least span of a graph's value axis (paddedRange's `minSpan`): a fraction
 * of the quantity's own scale, max |v| over the finite values, or of
 * `reference` when that is larger — 1 / (the curve's size) for κ and τ, so a
 * straight line (κ ≈ 1e-7 of rounding) is not drawn as wild wiggles, while a
 * circle's constant κ = 1/R is floored by R itself. A variation of the curve's
 * scale still fills the graph; one of 1e-7 of it stays below a pixel.
 */
export function spanFloor(
  values: ArrayLike<number>,
  reference = 0,
  fraction = SPAN_FLOOR_FRACTION,
): number {
  let largest = 0;
  for (let i = 0; i < values.length; i++) {
    const a = Math.abs(values[i]!);
    if (Number.isFinite(a) && a > largest) largest = a;
  }
  return fraction * Math.max(largest, Number.isFinite(reference) ? Math.abs(reference) : 0);
}

/** The diagonal of the bounding box of `points` (a curve's size for spanFloor); 0 for none. */
export function boxDiagonal(points: readonly (readonly number[])[]): number {
  if (points.length === 0) return 0;
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (const p of points)
    for (let j = 0; j < 3; j++) {
      const v = p[j] ?? 0;
      if (v < lo[j]!) lo[j] = v;
      if (v > hi[j]!) hi[j] = v;
    }
  return Math.hypot(hi[0]! - lo[0]!, hi[1]! - lo[1]!, hi[2]! - lo[2]!);
}

/**
 * "Nice" tick positions (1, 2 or 5 × 10^k apart) covering a range with about
 * `count` ticks; every tick lies within the range.
 */
export function niceTicks(range: Range, count = 5): number[] {
  if (!(range.max > range.min)) throw new RangeError(`range [${range.min}, ${range.max}] is empty`);
  const raw = (range.max - range.min) / Math.max(1, count);
  const exp = Math.floor(Math.log10(raw));
  const base = 10 ** exp;
  const frac = raw / base;
  const step = (frac <= 1 ? 1 : frac <= 2 ? 2 : frac <= 5 ? 5 : 10) * base;
  const first = Math.ceil(range.min / step - 1e-9);
  const ticks: number[] = [];
  for (let k = first; k * step <= range.max * (1 + 1e-12) + 1e-300; k++) {
    // Multiply rather than accumulate, so 0.1·3 prints as 0.3.
    ticks.push(Number((k * step).toPrecision(12)));
  }
  return ticks;
}

/**
 * The power of ten of a tick spacing's last significant digit: the smallest
 * d with `step` · 10^d an integer (to 1e-9 relative), so 0.0025 gives 4,
 * 0.2 gives 1, 500 gives −2. uPlot's steps are 1, 2, 2.5 or 5 × 10^k.
 */
export function stepDecimals(step: number): number {
  // One below the leading digit's power, so a spacing computed as 9.999999999999998e-5 (0.0023 −
  // 0.0022) finds 4 like 1e-4 does.
  let d = -Math.floor(Math.log10(step)) - 1;
  for (let i = 0; i < 18; i++, d++) {
    const x = step * 10 ** d;
    if (Math.abs(x - Math.round(x)) <= 1e-9 * x) return d;
  }
  return d;
}

/**
 * Axis labels of uPlot tick positions (the `values` formatter of an axis),
 * with as many digits as the spacing of the ticks needs, so neighbouring
 * labels never read the same (uPlot's default keeps 3 decimals: ticks
 * 0.0021 and 0.0024 both read "0.002"). Fixed notation while that needs at
 * most 6 decimals and the values are below 10^6, else the mantissa of
 * scientific notation has the digits down to the spacing's. Each label
 * belongs to its own tick position; labels are only formatted, never moved.
 * If rounding still makes two labels equal, one more digit is used.
 */
export function tickLabels(splits: readonly number[]): string[] {
  let step = Infinity;
  for (let i = 1; i < splits.length; i++) {
    const d = Math.abs(splits[i]! - splits[i - 1]!);
    if (d > 0 && d < step) step = d;
  }
  const finite = splits.filter((v) => Number.isFinite(v));
  const largest = Math.max(0, ...finite.map(Math.abs));
  if (!Number.isFinite(step)) return splits.map((v) => String(v));
  // A tick at zero computed as 1e-19 (k · step in floating point) prints as "0", not "-0.000".
  const clean = splits.map((v) => (Math.abs(v) < step * 1e-6 ? 0 : v));
  let decimals = stepDecimals(step);
  const scientific = decimals > 6 || largest >= 1e6;
  const exponent = largest > 0 ? Math.floor(Math.log10(largest)) : 0;
  for (let extra = 0; extra < 4; extra++) {
    const labels = clean.map((v) =>
      scientific
        ? v.toExponential(Math.min(20, Math.max(0, exponent + decimals)))
        : v.toFixed(Math.max(0, decimals)),
    );
    if (new Set(labels).size === labels.length) return labels;
    decimals++;
  }
  return clean.map((v) => String(v));
}

/**
 * log10 of |v| for the log-curvature / log-torsion graphs (thesis 6.3): zero
 * and undefined values become NaN (a gap in the plot), never −∞.
 */
export function logMagnitude(values: ArrayLike<number>): Float64Array {
  const out = new Float64Array(values.length);
  for (let i = 0; i < values.length; i++) {
    const a = Math.abs(values[i]!);
    out[i] = a > 0 && Number.isFinite(a) ? Math.log10(a) : NaN;
  }
  return out;
}

/** Radius of curvature 1/κ; infinite radius (κ = 0) is NaN, a gap. */
export function radius(kappa: ArrayLike<number>): Float64Array {
  const out = new Float64Array(kappa.length);
  for (let i = 0; i < kappa.length; i++) {
    const k = Math.abs(kappa[i]!);
    out[i] = k > 0 && Number.isFinite(k) ? 1 / k : NaN;
  }
  return out;
}

/**
 * Index of the sample whose abscissa is nearest `x` in a non-decreasing array
 * (binary search): links a hover on the graph to a point of the curve.
 */
export function nearestIndex(xs: ArrayLike<number>, x: number): number {
  const n = xs.length;
  if (n === 0) throw new RangeError('no samples');
  let lo = 0;
  let hi = n - 1;
  if (x <= xs[0]!) return 0;
  if (x >= xs[hi]!) return hi;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (xs[mid]! <= x) lo = mid;
    else hi = mid;
  }
  return x - xs[lo]! <= xs[hi]! - x ? lo : hi;
}

/** Map a pixel coordinate along an axis of `pixels` length to a value of `range`. */
export function pixelToValue(px: number, pixels: number, range: Range, flip = false): number {
  const f = px / pixels;
  return range.min + (flip ? 1 - f : f) * (range.max - range.min);
}

/**
 * Drag a profile (design by curvature): add `delta` at abscissa `at` with a
 * smooth cos² bump of half-width `width`, so the edited profile stays C1 and
 * untouched outside [at − width, at + width]. Returns new values.
 */
export function bumpProfile(
  xs: ArrayLike<number>,
  values: ArrayLike<number>,
  at: number,
  delta: number,
  width: number,
): Float64Array {
  if (!(width > 0)) throw new RangeError(`bump width ${width} must be positive`);
  const out = new Float64Array(values.length);
  for (let i = 0; i < values.length; i++) {
    const d = Math.abs(xs[i]! - at) / width;
    const w = d < 1 ? Math.cos((d * Math.PI) / 2) ** 2 : 0;
    out[i] = values[i]! + delta * w;
  }
  return out;
}
