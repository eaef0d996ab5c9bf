// The server's JSON (docs/server.md, /api/openapi.json) turned into the
// page's shapes: entities with their curve file, the analysis columns as
// drawable polylines, the history list. Renaming and regrouping only.

import type { Analysis, CurveFile, Entity, Feature, FinKind, Frame, History, Point } from './types';

type Json = Record<string, unknown>;

const CURVE_KINDS = new Set(['nurbs', 'bezier', 'interpolated', 'hermite', 'law', 'natural']);
const ENTITY_MEMBERS = new Set(['label', 'attributes', 'provenance', 'constraints', 'name']);

/**
 * The curve file with its construction points (a NURBS or Bézier curve's
 * control points, an interpolated or Hermite curve's data points: the handles
 * a drag moves) replaced by `handles`, each keeping its original dimension;
 * what the server holds once PATCH {"move"} has moved them (oli::Edit::move_point).
 * A law or natural-equation curve has no handles and comes back as it was.
 */
export function withHandles(curve: CurveFile, handles: readonly (readonly number[])[]): CurveFile {
  const moved = (points: Point[]): Point[] =>
    points.map((p, i) => (handles[i] ? handles[i].slice(0, p.length) : p));
  switch (curve.kind) {
    case 'nurbs':
    case 'bezier':
      return { ...curve, control_points: moved(curve.control_points) };
    case 'interpolated':
    case 'hermite':
      return { ...curve, points: moved(curve.points) };
    case 'law':
    case 'natural':
      return curve;
  }
}

/** GET …/entities/{label}: the curve file's members with label, attributes, provenance, constraints. */
export function entityFromServer(j: Json): Entity {
  const attributes = (j['attributes'] ?? {}) as Record<string, unknown>;
  const kind = typeof j['kind'] === 'string' ? j['kind'] : 'unknown';
  const e: Entity = {
    label: String(j['label']),
    kind,
    name:
      typeof attributes['name'] === 'string'
        ? attributes['name']
        : typeof j['name'] === 'string'
          ? j['name']
          : '',
    attributes,
  };
  if (CURVE_KINDS.has(kind)) {
    const curve: Json = {};
    for (const [k, v] of Object.entries(j)) if (!ENTITY_MEMBERS.has(k)) curve[k] = v;
    e.curve = curve as unknown as CurveFile;
  }
  return e;
}

/** Whether a document summary's entity is a curve (its kind is "curve" or a curve file kind). */
export function isCurveKind(kind: string): boolean {
  return kind === 'curve' || CURVE_KINDS.has(kind);
}

function column(j: Json, name: string): (number | null)[] {
  const c = j[name];
  return Array.isArray(c) ? (c as (number | null)[]) : [];
}

function points(c: unknown): Point[] {
  return Array.isArray(c) ? (c as Point[]) : [];
}

const nan3 = [NaN, NaN, NaN];

/**
 * POST …/analysis: columns t, points, frames {T, N, B}, curvature, torsion,
 * speed (null where undefined), fins [{kind, t, base, tip}], features
 * {inflections, curvature_extrema, knots}. `by` is what was asked: with
 * arclength samples the abscissa s is the server's `s` column when given.
 */
export function analysisFromServer(j: Json, by: 'parameter' | 'arclength'): Analysis {
  const t = column(j, 't').map((v) => v ?? NaN);
  const pts = points(j['points']);
  const framesJ = (j['frames'] ?? {}) as Json;
  const T = points(framesJ['T']);
  const N = points(framesJ['N']);
  const B = points(framesJ['B']);
  const frames: Frame[] = pts.map((_, i) => ({
    T: T[i] ?? nan3,
    N: N[i] ?? nan3,
    B: B[i] ?? nan3,
  }));
  const kappa = column(j, 'curvature');
  const tau = column(j, 'torsion');
  const speed = column(j, 'speed').map((v) => v ?? NaN);
  const s = arcLength(j, pts, by);
  const fins: Partial<Record<FinKind, Point[][]>> = {};
  const combs: Analysis['combs'] = {};
  const finList = Array.isArray(j['fins']) ? (j['fins'] as Json[]) : [];
  for (const comb of finList) {
    const kind = comb['kind'] as FinKind;
    const base = points(comb['base']);
    const tip = points(comb['tip']) as (Point | null)[];
    combs[kind] = { base, tip };
    fins[kind] = finLines(base, tip, 1);
  }
  const features: Feature[] = [];
  const f = (j['features'] ?? {}) as Json;
  for (const x of (f['inflections'] ?? []) as Json[])
    features.push({ kind: 'inflection', t: x['t'] as number });
  for (const x of (f['curvature_extrema'] ?? []) as Json[]) {
    features.push({
      kind: `curvature-${String(x['kind']).includes('max') ? 'max' : 'min'}`,
      t: x['t'] as number,
      value: x['curvature'] as number,
    });
  }
  for (const x of (f['knots'] ?? []) as Json[]) {
    const c = x['parametric'] as number;
    const g = x['geometric'] as number;
    features.push({
      kind: 'knot',
      t: x['t'] as number,
      continuity: `${c < 0 ? 'C–' : `C${c}`}/${g < 0 ? 'G–' : `G${g}`}`,
    });
  }
  // Feature abscissae in s: the sample nearest in t (for the graph markers).
  for (const feat of features) {
    let best = 0;
    for (let i = 1; i < t.length; i++)
      if (Math.abs(t[i]! - feat.t) < Math.abs(t[best]! - feat.t)) best = i;
    if (s.length) feat.s = s[best]!;
  }
  const planar = isPlanar(kappa, tau);
  return { t, s, points: pts, kappa, tau, speed, planar, frames, fins, combs, features };
}

/** A curve is planar when its torsion is zero (or undefined) at every sample. */
export function isPlanar(
  kappa: readonly (number | null)[],
  tau: readonly (number | null)[],
): boolean {
  let kmax = 1e-300;
  for (const k of kappa) kmax = Math.max(kmax, Math.abs(k ?? 0));
  return tau.every((v) => v === null || Math.abs(v) <= 1e-9 * Math.max(1, kmax));
}

/**
 * A comb as polylines: one segment per fin from its base to base + factor ×
 * (tip − base), and the envelope through the scaled tips, broken where a fin
 * is undefined (null tip). The factor is a drawing scale only.
 */
export function finLines(base: Point[], tip: (Point | null)[], factor: number): Point[][] {
  const lines: Point[][] = [];
  let envelope: Point[] = [];
  base.forEach((b, i) => {
    const q = tip[i];
    if (!q) {
      if (envelope.length > 1) lines.push(envelope);
      envelope = [];
      return;
    }
    const t =
      factor === 1 ? q : [0, 1, 2].map((k) => (b[k] ?? 0) + factor * ((q[k] ?? 0) - (b[k] ?? 0)));
    lines.push([b, t]);
    envelope.push(t);
  });
  if (envelope.length > 1) lines.push(envelope);
  return lines;
}

/**
 * Arc length at each sample: the server's `s` column when it sends one; else,
 * for samples equally spaced in arc length, i/(n−1) of the server's `length`,
 * or of the sampled polygon's length (within the sampling's chord error) when
 * no length is sent. Parameter samples without `s` get no arc length.
 */
function arcLength(j: Json, pts: Point[], by: 'parameter' | 'arclength'): number[] {
  const s = column(j, 's');
  if (s.length === pts.length && s.length > 0) return s.map((v) => v ?? NaN);
  if (by !== 'arclength' || pts.length < 2) return [];
  let length = typeof j['length'] === 'number' ? j['length'] : 0;
  if (!(length > 0)) {
    for (let i = 1; i < pts.length; i++) {
      const a = pts[i - 1]!;
      const b = pts[i]!;
      length += Math.hypot(
        (b[0] ?? 0) - (a[0] ?? 0),
        (b[1] ?? 0) - (a[1] ?? 0),
        (b[2] ?? 0) - (a[2] ?? 0),
      );
    }
  }
  return pts.map((_, i) => (length * i) / (pts.length - 1));
}

/** GET …/history: {revision, history: [{revision, name, time, changed, applied}]}. */
export function historyFromServer(j: Json): History {
  const list = (j['history'] ?? j['steps'] ?? []) as Json[];
  return {
    steps: list.map((h) => ({
      revision: h['revision'] as number,
      name: h['name'] as string,
      ...(typeof h['time'] === 'string' ? { time: h['time'] } : {}),
      ...(typeof h['applied'] === 'boolean' ? { applied: h['applied'] } : {}),
    })),
  };
}
