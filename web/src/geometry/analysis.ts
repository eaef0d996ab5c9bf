// The server's curve analysis (POST …/analysis, src/hula/server/analysis.cpp)
// recomputed in the page for a NURBS curve being dragged: samples by
// parameter or arc length, Frenet quantities, fins. Same definitions and
// tolerances as the kernel (diffgeom/frenet.cpp, diffgeom/fins.cpp,
// diffgeom/bishop.cpp, nurbs/arc_length.cpp), so the preview drawn during a
// drag is the server's answer to rounding; features (inflections, extrema,
// knot continuity) are left to the server.
//
// Notation: r', r'', r''' derivatives in t; v = |r'|; a = r' × r'';
// κ = |a| / v³; τ = (a · r''') / |a|²; T, N, B the Frenet frame.

import { finLines, isPlanar } from '../api/adapt';
import type { Analysis, FinKind, Frame, Point } from '../api/types';
import { NurbsEvaluator } from './nurbs';

export interface LocalAnalysisOptions {
  samples: number;
  by: 'parameter' | 'arclength';
  fins: readonly FinKind[];
  /** Fin scale (the route's `scale`). */
  scale: number;
}

/** Tolerance{} of the kernel (core/tolerance.hpp). */
const RESABS = 1e-6;
const ANGULAR = 1e-10;
const RELATIVE_RESOLUTION = 1e-14;
/** Relative tolerance of the arc length (nurbs::ArcLengthOptions default). */
const LENGTH_TOLERANCE = 1e-12;

/** One Frenet sample (diffgeom::FrenetPoint). */
export interface FrenetSample {
  t: number;
  position: [number, number, number];
  tangent: [number, number, number];
  normal: [number, number, number];
  binormal: [number, number, number];
  /** n × T for the plane normal +Z (the Bishop frame's fallback start). */
  signedNormal: [number, number, number];
  curvature: number;
  torsion: number;
  speed: number;
  tangentDefined: boolean;
  frameDefined: boolean;
}

const NAN3 = (): [number, number, number] => [NaN, NaN, NaN];

/** Frenet quantities from r, r', r'', r''' (frenet_from_derivatives, same tests). */
function frenetSample(
  t: number,
  d: Float64Array,
  zeroSpeed: number,
  modelSize: number,
): FrenetSample {
  const f: FrenetSample = {
    t,
    position: [d[0]!, d[1]!, d[2]!],
    tangent: NAN3(),
    normal: NAN3(),
    binormal: NAN3(),
    signedNormal: NAN3(),
    curvature: NaN,
    torsion: NaN,
    speed: NaN,
    tangentDefined: false,
    frameDefined: false,
  };
  for (let i = 0; i < 12; i++) if (!Number.isFinite(d[i]!)) return f;
  // Scaled by 1/m, m = max |r'_i|, as the kernel does (no under- or overflow).
  const m = Math.max(Math.abs(d[3]!), Math.abs(d[4]!), Math.abs(d[5]!));
  if (!(m > zeroSpeed)) {
    f.speed = Math.hypot(d[3]!, d[4]!, d[5]!);
    return f;
  }
  const im = 1 / m;
  const r1x = d[3]! * im,
    r1y = d[4]! * im,
    r1z = d[5]! * im;
  const r2x = d[6]! * im,
    r2y = d[7]! * im,
    r2z = d[8]! * im;
  const r3x = d[9]! * im,
    r3y = d[10]! * im,
    r3z = d[11]! * im;
  const v2 = r1x * r1x + r1y * r1y + r1z * r1z;
  const v = Math.sqrt(v2);
  f.speed = v * m;
  if (!(f.speed > zeroSpeed)) return f;
  f.tangentDefined = true;
  const Tx = r1x / v,
    Ty = r1y / v,
    Tz = r1z / v;
  f.tangent = [Tx, Ty, Tz];
  f.signedNormal = [-Ty, Tx, 0];
  const ax = r1y * r2z - r1z * r2y;
  const ay = r1z * r2x - r1x * r2z;
  const az = r1x * r2y - r1y * r2x;
  const a2 = ax * ax + ay * ay + az * az;
  const an = Math.sqrt(a2);
  const v3 = v2 * v;
  const r2n = Math.sqrt(r2x * r2x + r2y * r2y + r2z * r2z);
  const bound = ANGULAR * v * Math.max(r2n, (v2 * m) / modelSize);
  if (!(an > bound)) {
    f.curvature = 0;
    return f;
  }
  f.curvature = (an / v3) * im;
  f.frameDefined = true;
  const Bx = ax / an,
    By = ay / an,
    Bz = az / an;
  f.binormal = [Bx, By, Bz];
  f.normal = [By * Tz - Bz * Ty, Bz * Tx - Bx * Tz, Bx * Ty - By * Tx];
  f.torsion = ((ax * r3x + ay * r3y + az * r3z) / a2) * im;
  return f;
}

/** The kernel's zero-speed bound: resolution_for_size(Tolerance{}, size) / domain length. */
function zeroSpeedOf(size: number, domainLength: number): number {
  const s = Number.isFinite(size) ? Math.abs(size) : 0;
  return Math.max(Math.min(RESABS, RESABS * s), RELATIVE_RESOLUTION * s) / domainLength;
}

/** Frenet samples of a NURBS curve at the parameters ts. */
export function frenetSamples(c: NurbsEvaluator, ts: ArrayLike<number>): FrenetSample[] {
  const [a, b] = c.domain;
  const size = c.modelSize();
  const model = size > 0 ? size : 1;
  const zero = zeroSpeedOf(model, b - a);
  const d = new Float64Array(12);
  const out: FrenetSample[] = [];
  for (let i = 0; i < ts.length; i++) {
    c.derivatives(ts[i]!, 3, d);
    out.push(frenetSample(ts[i]!, d, zero, model));
  }
  return out;
}

// ---- arc length (nurbs/arc_length.cpp: adaptive Gauss–Kronrod 7/15 per span) ----

// Kronrod nodes (non-negative half, decreasing); the odd indices are the Gauss nodes.
const XGK = [
  0.9914553711208126, 0.9491079123427585, 0.8648644233597691, 0.7415311855993945,
  0.5860872354676911, 0.4058451513773972, 0.20778495500789848, 0,
];
const WGK = [
  0.022935322010529224, 0.06309209262997856, 0.10479001032225019, 0.14065325971552592,
  0.1690047266392679, 0.19035057806478542, 0.20443294007529889, 0.20948214108472782,
];
const WG = [0.1294849661688697, 0.27970539148927664, 0.3818300505051189, 0.4179591836734694];

/** A piece of the domain on which the quadrature met the tolerance, with the length before it. */
interface Piece {
  x0: number;
  x1: number;
  s0: number;
  length: number;
}

class ArcLength {
  readonly pieces: Piece[] = [];
  readonly length: number;

  constructor(private readonly c: NurbsEvaluator) {
    const breaks = c.breakpoints();
    const first: { x0: number; x1: number; k: number; e: number }[] = [];
    let l0 = 0;
    for (let i = 0; i + 1 < breaks.length; i++) {
      const [k, e] = this.gk15(breaks[i]!, breaks[i + 1]!);
      first.push({ x0: breaks[i]!, x1: breaks[i + 1]!, k, e });
      l0 += k;
    }
    const [a, b] = c.domain;
    const density = (LENGTH_TOLERANCE * l0) / (b - a);
    let s = 0;
    for (const p of first) s = this.adapt(p.x0, p.x1, p.k, p.e, density, 0, s);
    this.length = s;
  }

  speed(t: number): number {
    return this.c.speed(t);
  }

  /** Kronrod 15-point value and |K15 − G7| on [x0, x1]. */
  gk15(x0: number, x1: number): [number, number] {
    const c = 0.5 * (x0 + x1);
    const h = 0.5 * (x1 - x0);
    const fc = this.speed(c);
    let k = fc * WGK[7]!;
    let g = fc * WG[3]!;
    for (let j = 0; j < 7; j++) {
      const dx = h * XGK[j]!;
      const f = this.speed(c - dx) + this.speed(c + dx);
      k += WGK[j]! * f;
      if (j % 2 === 1) g += WG[(j - 1) / 2]! * f;
    }
    return [k * h, Math.abs((k - g) * h)];
  }

  /** Bisect until the error estimate meets the budget; record the pieces; return the length so far. */
  private adapt(
    x0: number,
    x1: number,
    k: number,
    e: number,
    density: number,
    depth: number,
    s: number,
  ): number {
    const noise = 50 * Number.EPSILON * Math.abs(k);
    const mid = 0.5 * (x0 + x1);
    if (e <= Math.max(density * (x1 - x0), noise) || depth >= 48 || !(mid > x0 && mid < x1)) {
      this.pieces.push({ x0, x1, s0: s, length: k });
      return s + k;
    }
    const [kl, el] = this.gk15(x0, mid);
    const [kr, er] = this.gk15(mid, x1);
    const sl = this.adapt(x0, mid, kl, el, density, depth + 1, s);
    return this.adapt(mid, x1, kr, er, density, depth + 1, sl);
  }

  /** Gauss 7-point value on [x0, x1] (inside an accepted piece, within its tolerance). */
  g7(x0: number, x1: number): number {
    const c = 0.5 * (x0 + x1);
    const h = 0.5 * (x1 - x0);
    let g = this.speed(c) * WG[3]!;
    for (let j = 0; j < 3; j++) {
      const dx = h * XGK[2 * j + 1]!;
      g += WG[j]! * (this.speed(c - dx) + this.speed(c + dx));
    }
    return g * h;
  }

  /**
   * Parameters at increasing arc lengths (0 ≤ s ≤ length): on the piece holding
   * each s, Newton steps from the nearest known point (the piece's start or the
   * previous answer), each step integrating only the increment, with a
   * bisection safeguard; |s(t) − s| ≤ 1e-12 × length as the kernel's
   * parameter_at_length.
   */
  parametersAt(ss: readonly number[]): Float64Array {
    const out = new Float64Array(ss.length);
    const ps = this.pieces;
    const tol = LENGTH_TOLERANCE * Math.max(this.length, Number.MIN_VALUE);
    let piece = 0;
    let known = { t: ps[0]!.x0, s: 0 };
    ss.forEach((s, i) => {
      while (piece + 1 < ps.length && ps[piece + 1]!.s0 <= s) piece++;
      const p = ps[piece]!;
      if (known.t < p.x0 || known.t > p.x1) known = { t: p.x0, s: p.s0 };
      if (s >= p.s0 + p.length) {
        out[i] = p.x1;
        return;
      }
      let a = known.t;
      let b = p.x1;
      let t = known.t;
      let st = known.s;
      for (let it = 0; it < 60 && Math.abs(st - s) > tol; it++) {
        if (st > s) b = t;
        else a = t;
        const v = this.speed(t);
        let next = v > 0 ? t - (st - s) / v : NaN;
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (next === t) break;
        st += next > t ? this.g7(t, next) : -this.g7(next, t);
        t = next;
      }
      out[i] = t;
      known = { t, s: st };
    });
    return out;
  }
}

/** Arc length of the whole curve (relative tolerance 1e-12, as `hula info`). */
export function arcLength(c: NurbsEvaluator): number {
  return new ArcLength(c).length;
}

// ---- fins (diffgeom/fins.cpp) and the Bishop frame (diffgeom/bishop.cpp) ----

type V3 = [number, number, number];
const dot = (a: V3, b: V3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a: V3): number => Math.sqrt(dot(a, a));
const finite = (a: V3): boolean => a.every(Number.isFinite);

/** Double-reflection rotation-minimising frames u (Wang et al. 2008), as bishop_frame. */
function bishopU(samples: readonly FrenetSample[]): (V3 | null)[] {
  const out: (V3 | null)[] = samples.map(() => null);
  let prev = -1;
  for (let i = 0; i < samples.length; i++) {
    const p = samples[i]!;
    if (!p.tangentDefined) continue;
    const t1 = p.tangent;
    let r1: V3;
    if (prev < 0) {
      if (p.frameDefined) r1 = p.normal;
      else if (norm(p.signedNormal) > 1e-3) {
        const l = norm(p.signedNormal);
        r1 = [p.signedNormal[0] / l, p.signedNormal[1] / l, p.signedNormal[2] / l];
      } else r1 = anyNormal(t1);
    } else {
      const q = samples[prev]!;
      const r0 = out[prev]!;
      const t0 = q.tangent;
      const v1: V3 = [
        p.position[0] - q.position[0],
        p.position[1] - q.position[1],
        p.position[2] - q.position[2],
      ];
      const c1 = dot(v1, v1);
      let rL = r0;
      let tL = t0;
      if (c1 > 0) {
        const kr = (2 / c1) * dot(v1, r0);
        const kt = (2 / c1) * dot(v1, t0);
        rL = [r0[0] - v1[0] * kr, r0[1] - v1[1] * kr, r0[2] - v1[2] * kr];
        tL = [t0[0] - v1[0] * kt, t0[1] - v1[1] * kt, t0[2] - v1[2] * kt];
      }
      const v2: V3 = [t1[0] - tL[0], t1[1] - tL[1], t1[2] - tL[2]];
      const c2 = dot(v2, v2);
      if (c2 > 0) {
        const k = (2 / c2) * dot(v2, rL);
        r1 = [rL[0] - v2[0] * k, rL[1] - v2[1] * k, rL[2] - v2[2] * k];
      } else r1 = rL;
      const k = dot(r1, t1);
      const w: V3 = [r1[0] - t1[0] * k, r1[1] - t1[1] * k, r1[2] - t1[2] * k];
      const l = norm(w);
      r1 = [w[0] / l, w[1] / l, w[2] / l];
    }
    out[i] = r1;
    prev = i;
  }
  return out;
}

function anyNormal(T: V3): V3 {
  const [ax, ay, az] = T.map(Math.abs) as V3;
  const e: V3 = ax <= ay && ax <= az ? [1, 0, 0] : ay <= az ? [0, 1, 0] : [0, 0, 1];
  const k = dot(e, T);
  const w: V3 = [e[0] - T[0] * k, e[1] - T[1] * k, e[2] - T[2] * k];
  const l = norm(w);
  return [w[0] / l, w[1] / l, w[2] / l];
}

/** Fin tips of one kind at the samples (null where the fin is undefined), as diffgeom::fins. */
function finTips(kind: FinKind, samples: readonly FrenetSample[], scale: number): (Point | null)[] {
  const u = kind === 'bishop-u' || kind === 'bishop-v' ? bishopU(samples) : [];
  return samples.map((p, i) => {
    let dir: V3 = [0, 0, 0];
    let q = 1;
    let ok = p.frameDefined;
    switch (kind) {
      case 'combescure':
        // The server's alone (App keeps such a drag on the server's analysis).
        return null;
      case 'curvature':
        // κN is 0 (not undefined) where κ = 0: a fin of length 0.
        ok = p.tangentDefined;
        if (p.frameDefined) {
          dir = [-p.normal[0], -p.normal[1], -p.normal[2]];
          q = p.curvature;
        } else q = 0;
        break;
      case 'torsion':
        dir = p.binormal;
        q = p.torsion;
        break;
      case 'normal':
        dir = [-p.normal[0], -p.normal[1], -p.normal[2]];
        break;
      case 'binormal':
        dir = [-p.binormal[0], -p.binormal[1], -p.binormal[2]];
        break;
      case 'bishop-u':
      case 'bishop-v': {
        const r = u[i];
        ok = r !== null && r !== undefined;
        if (r) {
          const T = p.tangent;
          dir =
            kind === 'bishop-u'
              ? [-r[0], -r[1], -r[2]]
              : [
                  -(T[1] * r[2] - T[2] * r[1]),
                  -(T[2] * r[0] - T[0] * r[2]),
                  -(T[0] * r[1] - T[1] * r[0]),
                ];
        }
        break;
      }
    }
    if (!ok) return null;
    const l = scale * q;
    const tip: V3 = [
      p.position[0] + dir[0] * l,
      p.position[1] + dir[1] * l,
      p.position[2] + dir[2] * l,
    ];
    return finite(tip) ? tip : null;
  });
}

/** Evenly spaced parameters over the domain, the last one exactly its end (fins.cpp grid). */
function parameterGrid(c: NurbsEvaluator, n: number): Float64Array {
  const [a, b] = c.domain;
  const ts = new Float64Array(n);
  for (let i = 0; i < n; i++) ts[i] = i + 1 === n ? b : a + ((b - a) * i) / (n - 1);
  return ts;
}

/**
 * The analysis the route would answer for this curve and request, without
 * features: points, frames, κ, τ, speed, arc length and fins.
 */
export function analyseNurbs(c: NurbsEvaluator, o: LocalAnalysisOptions): Analysis {
  const n = Math.max(2, Math.round(o.samples));
  let ts: Float64Array;
  let s: number[] = [];
  if (o.by === 'parameter') ts = parameterGrid(c, n);
  else {
    const arc = new ArcLength(c);
    const [a, b] = c.domain;
    ts = new Float64Array(n);
    s = Array.from({ length: n }, (_, i) => (arc.length * i) / (n - 1));
    ts.set(arc.parametersAt(s));
    ts[0] = a;
    ts[n - 1] = b;
  }
  const samples = frenetSamples(c, ts);
  const nullable = (v: V3, ok: boolean): number[] => (ok && finite(v) ? v : [NaN, NaN, NaN]);
  const frames: Frame[] = samples.map((f) => ({
    T: nullable(f.tangent, f.tangentDefined),
    N: nullable(f.normal, f.frameDefined),
    B: nullable(f.binormal, f.frameDefined),
  }));
  const num = (x: number): number | null => (Number.isFinite(x) ? x : null);
  const kappa = samples.map((f) => (f.tangentDefined ? num(f.curvature) : null));
  const tau = samples.map((f) => (f.frameDefined ? num(f.torsion) : null));
  const combs: Analysis['combs'] = {};
  const fins: Analysis['fins'] = {};
  if (o.fins.length > 0) {
    // Fins are on the parameter grid (as the server's): the samples themselves when they are on it.
    const finSamples = o.by === 'parameter' ? samples : frenetSamples(c, parameterGrid(c, n));
    const base = finSamples.map((f) => f.position as Point);
    for (const kind of o.fins) {
      const tip = finTips(kind, finSamples, o.scale);
      combs[kind] = { base, tip };
      fins[kind] = finLines(base, tip, 1);
    }
  }
  return {
    t: Array.from(ts),
    s,
    points: samples.map((f) => f.position),
    kappa,
    tau,
    speed: samples.map((f) => f.speed),
    planar: isPlanar(kappa, tau),
    frames,
    fins,
    combs,
    features: [],
  };
}
