// Exact NURBS evaluation in the page, for the live preview of a drag: the
// dragged curve, its curvature and its fins are redrawn every frame without
// waiting for the server, whose answer replaces the preview when it arrives
// (docs/workbench.md, "Live drag"). The kernel (src/hula/nurbs) stays the
// reference: the unit tests compare against `hula eval` / `hula analyse`.
//
// Notation (Piegl & Tiller, The NURBS Book, 2nd ed.): p degree, U knots,
// Pw homogeneous control points (w x, w y, w z, w), N basis functions;
// A2.1 FindSpan, A2.3 DersBasisFuns, A4.2 RatCurveDerivs.

import type { CurveFile } from '../api/types';

/** The largest derivative order the evaluator gives (what Frenet quantities need). */
const MAX_ORDER = 3;

export class NurbsEvaluator {
  readonly degree: number;
  readonly knots: Float64Array;
  /** Homogeneous control points, 4 numbers each (w x, w y, w z, w). */
  readonly pw: Float64Array;
  readonly rational: boolean;
  readonly count: number;
  /** The parameter domain [U[p], U[n]]. */
  readonly start: number;
  readonly end: number;
  // Scratch of A2.3 and A4.2, sized once for the degree (no allocation per evaluation).
  private readonly ndu: Float64Array;
  private readonly a: Float64Array;
  private readonly left: Float64Array;
  private readonly right: Float64Array;
  private readonly ders: Float64Array;
  private readonly aw: Float64Array;

  private constructor(degree: number, knots: Float64Array, pw: Float64Array, rational: boolean) {
    this.degree = degree;
    this.knots = knots;
    this.pw = pw;
    this.rational = rational;
    this.count = pw.length / 4;
    this.start = knots[degree]!;
    this.end = knots[this.count]!;
    const p1 = degree + 1;
    this.ndu = new Float64Array(p1 * p1);
    this.a = new Float64Array(2 * p1);
    this.left = new Float64Array(p1);
    this.right = new Float64Array(p1);
    this.ders = new Float64Array((MAX_ORDER + 1) * p1);
    this.aw = new Float64Array(4 * (MAX_ORDER + 1));
  }

  /**
   * The evaluator of a NURBS or Bézier curve file, with `points` in place of
   * its control points when given (a drag in progress); null for the other
   * kinds (interpolated, Hermite, law, natural: the server evaluates those)
   * and for a file that is not a valid NURBS (sizes, order of the knots,
   * non-finite or non-positive numbers), so bad input is never drawn.
   */
  static of(curve: CurveFile, points?: readonly (readonly number[])[]): NurbsEvaluator | null {
    if (curve.kind !== 'nurbs' && curve.kind !== 'bezier') return null;
    const cps = points ?? curve.control_points;
    const n = cps.length;
    if (n < 2) return null;
    const degree = curve.kind === 'nurbs' ? curve.degree : n - 1;
    const knots =
      curve.kind === 'nurbs'
        ? Float64Array.from(curve.knots)
        : Float64Array.from({ length: 2 * n }, (_, i) => (i < n ? 0 : 1));
    if (!Number.isInteger(degree) || degree < 1 || degree >= n) return null;
    if (knots.length !== n + degree + 1) return null;
    for (let i = 0; i < knots.length; i++) {
      if (!Number.isFinite(knots[i]!)) return null;
      if (i > 0 && knots[i]! < knots[i - 1]!) return null;
    }
    if (!(knots[n]! > knots[degree]!)) return null;
    const weights = curve.weights ?? null;
    if (weights && weights.length !== n) return null;
    const pw = new Float64Array(4 * n);
    let rational = false;
    for (let i = 0; i < n; i++) {
      const w = weights ? weights[i]! : 1;
      if (!(w > 0) || !Number.isFinite(w)) return null;
      if (w !== 1) rational = true;
      const p = cps[i]!;
      for (let k = 0; k < 3; k++) {
        const x = p[k] ?? 0;
        if (!Number.isFinite(x)) return null;
        pw[4 * i + k] = w * x;
      }
      pw[4 * i + 3] = w;
    }
    return new NurbsEvaluator(degree, knots, pw, rational);
  }

  get domain(): [number, number] {
    return [this.start, this.end];
  }

  /** Distinct knots inside the domain (span ends), increasing. */
  breakpoints(): number[] {
    const [a, b] = this.domain;
    const out: number[] = [a];
    for (let i = this.degree + 1; i < this.count; i++) {
      const u = this.knots[i]!;
      if (u > out[out.length - 1]! && u < b) out.push(u);
    }
    out.push(b);
    return out;
  }

  /** Diagonal of the control points' bounding box (the kernel's model_size). */
  modelSize(): number {
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < this.count; i++) {
      const w = this.pw[4 * i + 3]!;
      for (let k = 0; k < 3; k++) {
        const x = this.pw[4 * i + k]! / w;
        lo[k] = Math.min(lo[k]!, x);
        hi[k] = Math.max(hi[k]!, x);
      }
    }
    return Math.hypot(hi[0]! - lo[0]!, hi[1]! - lo[1]!, hi[2]! - lo[2]!);
  }

  /**
   * A2.1: the span index i with U[i] ≤ t < U[i+1], right-sided at interior
   * knots (as the kernel's default), the last non-empty span at the end.
   */
  span(t: number): number {
    const U = this.knots;
    const p = this.degree;
    const n = this.count - 1;
    if (t >= U[n + 1]!) {
      let i = n;
      while (i > p && !(U[i]! < U[i + 1]!)) i--;
      return i;
    }
    if (t <= U[p]!) {
      let i = p;
      while (i < n && !(U[i + 1]! > U[i]!)) i++;
      return i;
    }
    let lo = p;
    let hi = n + 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (t < U[mid]!) hi = mid;
      else lo = mid;
    }
    return lo;
  }

  /**
   * C(t) and its derivatives up to `order` (≤ 3) into out[3k .. 3k+2]
   * (k = 0 … order): A2.3 for the basis derivatives, A4.2 for the quotient
   * rule of a rational curve. t outside the domain is clamped to it.
   */
  derivatives(t: number, order: number, out: Float64Array): void {
    const p = this.degree;
    const u = t < this.start ? this.start : t > this.end ? this.end : t;
    const span = this.span(u);
    const nd = Math.min(order, p);
    this.basisDerivatives(span, u, nd);
    const ders = this.ders;
    const pw = this.pw;
    const aw = this.aw;
    const p1 = p + 1;
    for (let k = 0; k <= order; k++) {
      let x = 0;
      let y = 0;
      let z = 0;
      let w = 0;
      if (k <= nd) {
        for (let j = 0; j <= p; j++) {
          const b = ders[k * p1 + j]!;
          const q = 4 * (span - p + j);
          x += b * pw[q]!;
          y += b * pw[q + 1]!;
          z += b * pw[q + 2]!;
          w += b * pw[q + 3]!;
        }
      }
      aw[4 * k] = x;
      aw[4 * k + 1] = y;
      aw[4 * k + 2] = z;
      aw[4 * k + 3] = w;
    }
    if (!this.rational) {
      for (let k = 0; k <= order; k++) {
        out[3 * k] = aw[4 * k]!;
        out[3 * k + 1] = aw[4 * k + 1]!;
        out[3 * k + 2] = aw[4 * k + 2]!;
      }
      return;
    }
    // A4.2: C^(k) = (A^(k) − Σ_{i=1..k} binom(k, i) w^(i) C^(k−i)) / w.
    const w0 = aw[3]!;
    for (let k = 0; k <= order; k++) {
      for (let c = 0; c < 3; c++) {
        let v = aw[4 * k + c]!;
        for (let i = 1; i <= k; i++) v -= BINOMIAL[k]![i]! * aw[4 * i + 3]! * out[3 * (k - i) + c]!;
        out[3 * k + c] = v / w0;
      }
    }
  }

  /**
   * |C'(t)|, the integrand of the arc length: A2.2's triangle gives the basis
   * of degree p − 1 and p in one pass; C' = (A' − w' C) / w with
   * A' = Σ N_{j,p−1} p (Pw_j − Pw_{j−1}) / (U_{j+p} − U_j) (The NURBS Book
   * eq. 3.4 on the homogeneous points). Cheaper than derivatives(t, 1).
   */
  speed(t: number): number {
    const p = this.degree;
    const u = t < this.start ? this.start : t > this.end ? this.end : t;
    const span = this.span(u);
    const U = this.knots;
    const { left, right, ders: N } = this;
    // N[0..p] ends as N_{span−p+j, p}; lower holds N_{span−p+1+j, p−1}, j = 0 … p−1.
    const lower = this.a;
    N[0] = 1;
    for (let j = 1; j <= p; j++) {
      if (j === p) for (let r = 0; r < p; r++) lower[r] = N[r]!;
      left[j] = u - U[span + 1 - j]!;
      right[j] = U[span + j]! - u;
      let saved = 0;
      for (let r = 0; r < j; r++) {
        const temp = N[r]! / (right[r + 1]! + left[j - r]!);
        N[r] = saved + right[r + 1]! * temp;
        saved = left[j - r]! * temp;
      }
      N[j] = saved;
    }
    const pw = this.pw;
    let x = 0,
      y = 0,
      z = 0,
      w = 0,
      dx = 0,
      dy = 0,
      dz = 0,
      dw = 0;
    const first = span - p;
    for (let j = 0; j <= p; j++) {
      const q = 4 * (first + j);
      const b = N[j]!;
      x += b * pw[q]!;
      y += b * pw[q + 1]!;
      z += b * pw[q + 2]!;
      w += b * pw[q + 3]!;
      if (j === 0) continue;
      const i = first + j;
      const c = (p * lower[j - 1]!) / (U[i + p]! - U[i]!);
      dx += c * (pw[q]! - pw[q - 4]!);
      dy += c * (pw[q + 1]! - pw[q - 3]!);
      dz += c * (pw[q + 2]! - pw[q - 2]!);
      dw += c * (pw[q + 3]! - pw[q - 1]!);
    }
    if (!this.rational) return Math.hypot(dx, dy, dz);
    const iw = 1 / w;
    return Math.hypot(dx - dw * x * iw, dy - dw * y * iw, dz - dw * z * iw) * iw;
  }

  /** A2.3: ders[k][j] = N^(k)_{span−p+j, p}(u), k = 0 … nd. */
  private basisDerivatives(span: number, u: number, nd: number): void {
    const p = this.degree;
    const p1 = p + 1;
    const U = this.knots;
    const { ndu, a, left, right, ders } = this;
    ndu[0] = 1;
    for (let j = 1; j <= p; j++) {
      left[j] = u - U[span + 1 - j]!;
      right[j] = U[span + j]! - u;
      let saved = 0;
      for (let r = 0; r < j; r++) {
        // Lower triangle: knot differences; upper: basis functions.
        ndu[j * p1 + r] = right[r + 1]! + left[j - r]!;
        const temp = ndu[r * p1 + j - 1]! / ndu[j * p1 + r]!;
        ndu[r * p1 + j] = saved + right[r + 1]! * temp;
        saved = left[j - r]! * temp;
      }
      ndu[j * p1 + j] = saved;
    }
    for (let j = 0; j <= p; j++) ders[j] = ndu[j * p1 + p]!;
    for (let r = 0; r <= p; r++) {
      let s1 = 0;
      let s2 = 1;
      a[0] = 1;
      for (let k = 1; k <= nd; k++) {
        let d = 0;
        const rk = r - k;
        const pk = p - k;
        if (r >= k) {
          a[s2 * p1] = a[s1 * p1]! / ndu[(pk + 1) * p1 + rk]!;
          d = a[s2 * p1]! * ndu[rk * p1 + pk]!;
        }
        const j1 = rk >= -1 ? 1 : -rk;
        const j2 = r - 1 <= pk ? k - 1 : p - r;
        for (let j = j1; j <= j2; j++) {
          a[s2 * p1 + j] = (a[s1 * p1 + j]! - a[s1 * p1 + j - 1]!) / ndu[(pk + 1) * p1 + rk + j]!;
          d += a[s2 * p1 + j]! * ndu[(rk + j) * p1 + pk]!;
        }
        if (r <= pk) {
          a[s2 * p1 + k] = -a[s1 * p1 + k - 1]! / ndu[(pk + 1) * p1 + r]!;
          d += a[s2 * p1 + k]! * ndu[r * p1 + pk]!;
        }
        ders[k * p1 + r] = d;
        const t = s1;
        s1 = s2;
        s2 = t;
      }
    }
    let f = p;
    for (let k = 1; k <= nd; k++) {
      for (let j = 0; j <= p; j++) ders[k * p1 + j] = ders[k * p1 + j]! * f;
      f *= p - k;
    }
  }
}

const BINOMIAL = [[1], [1, 1], [1, 2, 1], [1, 3, 3, 1]];
