// The server's JSON (docs/server.md, /api/openapi.json) turned into the
// page's shapes: entities with their curve file, the analysis columns as
// drawable polylines, the history list. Renaming and regrouping only.

import type * as Api from './openapi';
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

const nan3 = [NaN, NaN, NaN];

/**
 * POST …/analysis (io::curve_analysis_json, docs/formats.md "Curve analysis"):
 * columns t, s?, points, frames {T, N, B}, curvature, torsion, speed (null
 * where undefined), fins [{kind, scale, t, base, tip}], planarity, features
 * {inflections, curvature_extrema, torsion_extrema, knots, …}. The features
 * and the planarity are the server's, taken as they are. `by` is what was
 * asked: with arclength samples the abscissa s is the server's `s` column.
 */
export function analysisFromServer(j: Api.Analysis, by: 'parameter' | 'arclength'): Analysis {
  const t = j.t;
  const pts = j.points.map((p) => p ?? nan3);
  const frames: Frame[] = pts.map((_, i) => ({
    T: j.frames.T[i] ?? nan3,
    N: j.frames.N[i] ?? nan3,
    B: j.frames.B[i] ?? nan3,
  }));
  const kappa = j.curvature;
  const tau = j.torsion;
  const speed = j.speed.map((v) => v ?? NaN);
  // By arc length the server sends the arc length of every sample (`s`).
  const s = by === 'arclength' || j.s ? (j.s ?? []) : [];
  const fins: Partial<Record<FinKind, Point[][]>> = {};
  const combs: Analysis['combs'] = {};
  for (const comb of j.fins) {
    const base = comb.base.map((p) => p ?? nan3);
    combs[comb.kind] = { base, tip: comb.tip };
    fins[comb.kind] = finLines(base, comb.tip, 1);
  }
  const features = j.features ? featuresFromServer(j.features) : [];
  // Feature abscissae in s: the sample nearest in t (for the graph markers).
  for (const feat of features) {
    let best = 0;
    for (let i = 1; i < t.length; i++)
      if (Math.abs(t[i]! - feat.t) < Math.abs(t[best]! - feat.t)) best = i;
    if (s.length) feat.s = s[best]!;
  }
  const planar = j.planarity.planar;
  return { t, s, points: pts, kappa, tau, speed, planar, frames, fins, combs, features };
}

/**
 * The server's feature lists as the page's markers, one for one and in the
 * server's order: inflections, curvature extrema ("curvature-max"/"-min"),
 * torsion extrema ("torsion-max"/"-min"), knots with the continuity reached.
 */
export function featuresFromServer(f: NonNullable<Api.Analysis['features']>): Feature[] {
  const features: Feature[] = f.inflections.map((x) => ({ kind: 'inflection', t: x.t }));
  for (const x of f.curvature_extrema)
    features.push({
      kind: `curvature-${x.kind === 'maximum' ? 'max' : 'min'}`,
      t: x.t,
      value: x.curvature,
    });
  for (const x of f.torsion_extrema)
    features.push({
      kind: `torsion-${x.kind === 'maximum' ? 'max' : 'min'}`,
      t: x.t,
      value: x.torsion,
    });
  for (const x of f.knots) {
    const c = x.parametric === null ? 'C–' : `C${x.parametric}`;
    const g = x.geometric === null ? 'G–' : `G${x.geometric}`;
    features.push({ kind: 'knot', t: x.t, continuity: `${c}/${g}` });
  }
  return features;
}

/**
 * A curve is planar when its torsion is zero (or undefined) at every sample:
 * the page's preview only (the server's analysis says so itself).
 */
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
