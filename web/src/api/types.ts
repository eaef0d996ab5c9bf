// JSON shapes of the `hula serve` API (docs/server.md, GET /api/openapi.json)
// and the page's own shapes built from them (api/adapt.ts). Every member the
// page reads from the server is checked against the OpenAPI document by
// api/contract.test.ts, so a member the server does not send cannot be
// expected. No geometry is computed from them on the page.

import type * as Api from './openapi';

export type Point = number[];

/** `{"error": {"code", "message", "where"}}` (docs/formats.md, Error JSON). */
export interface ErrorWhere {
  field?: string;
  index?: number;
  component?: number;
  line?: number;
  column?: number;
}
export interface ErrorBody {
  code: string;
  message: string;
  where: ErrorWhere;
}

export interface Health {
  status: 'ok';
  version: string;
}

/** A curve file (docs/formats.md, Curve files). */
export type CurveFile =
  | {
      kind: 'nurbs';
      degree: number;
      knots: number[];
      control_points: Point[];
      weights?: number[] | null;
    }
  | { kind: 'bezier'; control_points: Point[]; weights?: number[] | null }
  | {
      kind: 'interpolated';
      points: Point[];
      parameterisation?: Parameterisation;
      parameters?: number[];
      start?: EndCondition;
      end?: EndCondition;
    }
  | { kind: 'law'; expression: string; parameter?: string; domain: [number, number] }
  | {
      kind: 'hermite';
      points: Point[];
      tangents: Point[];
      second_derivatives?: Point[];
      parameters?: number[];
    }
  | {
      kind: 'natural';
      curvature: string;
      torsion?: string;
      parameter?: string;
      length: number;
      start?: { point?: Point; tangent?: Point; normal?: Point };
    };

export type Parameterisation = 'uniform' | 'chord' | 'centripetal';
export type EndCondition = 'natural' | 'bessel' | 'not-a-knot' | 'occt' | { tangent: Point };

/** One entity of a document: a stable label, a kind, a name, attributes. */
export interface Entity {
  label: Label;
  kind: string;
  name: string;
  attributes: Record<string, unknown>;
  /** The curve as a curve file, for curve entities. */
  curve?: CurveFile;
}

export interface DocumentSummary {
  name: string;
  /** Whether the server has the document open. */
  open: boolean;
}

export interface DocumentState {
  name: string;
  revision: number;
  entities: Entity[];
}

/**
 * What a change did (the Oli change set), pushed to every client on the
 * document's event stream; the reply of a change also carries the entities
 * it added or changed (`entities`, as GET .../entities/{label} gives them).
 */
export interface ChangeSet {
  revision: number;
  added?: Label[];
  changed?: Label[];
  removed?: Label[];
  attributes_changed?: Label[];
  entities?: Record<string, unknown>[];
  cause?: 'commit' | 'undo' | 'redo';
  /** Name of the step (e.g. "move points"). */
  name?: string;
}

/** Oli labels are integers; the page keys entities by their decimal text. */
export type Label = string | number;

/** The reply of every change: the new revision and its change set (with a PATCH's analysis when asked). */
export interface ChangeReply {
  revision: number;
  changes: ChangeSet;
  label?: Label;
  /** The moved curve's analysis (PATCH with "analysis"), as POST .../analysis answers it. */
  analysis?: Api.Analysis;
}

export interface HistoryStep {
  revision: number;
  name: string;
  time?: string;
  /** False for a step that was undone (it can be redone). */
  applied?: boolean;
}
export interface History {
  steps: HistoryStep[];
  /** Index of the current step in `steps` (steps after it can be redone), when the server gives it. */
  current?: number;
}

export type FinKind =
  'curvature' | 'torsion' | 'normal' | 'binormal' | 'bishop-u' | 'bishop-v' | 'combescure';

export interface AnalysisRequest {
  samples: number;
  by: 'parameter' | 'arclength';
  fins?: FinKind[];
  scale?: number;
  features?: boolean;
  /** The parameters (or arc lengths, by arc length) to sample instead of `samples` equally spaced. */
  at?: number[];
}

export interface Frame {
  T: number[];
  N: number[];
  B: number[];
}

export interface Feature {
  kind: string; // inflection | curvature-max | curvature-min | torsion-max | torsion-min | knot
  t: number;
  s?: number;
  value?: number;
  /** For knots: the continuity reached, e.g. "C2" or "G1". */
  continuity?: string;
}

/** What a viewport draws for one curve (POST .../analysis, regrouped by api/adapt.ts). */
export interface Analysis {
  t: number[];
  /** Arc length at each sample (empty when the samples are by parameter and the server sends none). */
  s: number[];
  points: Point[];
  kappa: (number | null)[];
  tau: (number | null)[];
  speed: number[];
  planar: boolean;
  frames: Frame[];
  /** Per fin kind: the hairs (base → tip) and the envelope through the tips, as polylines. */
  fins: Partial<Record<FinKind, Point[][]>>;
  /** The server's combs as sent: fin bases and tips (null where undefined). */
  combs: Partial<Record<FinKind, { base: Point[]; tip: (Point | null)[] }>>;
  features: Feature[];
}

/** POST .../entities/{label}/fair-preview (the fairing assistant). */
export interface FairPreviewRequest {
  /** Largest distance a data point may move, model units. */
  tolerance: number;
  method?: FairMethod;
  /** Wall-clock budget of the optimisation, seconds. */
  budget?: number;
  /** What stays at the ends: nothing, the end points, or the end points and tangents. */
  hold?: FairHold;
  analysis?: AnalysisRequest;
  /** Fair this curve instead of the entity's (the page's edit in flight: a drag's latest position). */
  curve?: CurveFile;
}
export type FairMethod = Api.FairPreview['method'];
export type FairHold = Api.FairPreview['hold'];

/** The fairing assistant's ghost: the server's reply, with its curve as the page's curve type and
 * its analysis (asked for or not) adapted as every analysis the page reads. */
export type FairPreview = Omit<Api.FairPreview, 'curve' | 'analysis'> & {
  curve: CurveFile;
  analysis: Analysis | undefined;
};

/** POST .../export: the entities written as a file (its text in the reply). */
export type ExportFormat = Api.ExportRequest['format'];
export type ExportResult = Api.ExportResult;

/** POST /api/match and /api/blend (docs/server.md): two curves joined; the document is not changed. */
export type CurveEndName = 'start' | 'end';
export type MatchRequest = Omit<Api.MatchRequest, 'a' | 'b'> & { a: CurveFile; b: CurveFile };
export type MatchResult = Omit<Api.MatchResult, 'curve'> & { curve: CurveFile };
export type BlendRequest = Omit<Api.BlendRequest, 'a' | 'b'> & { a: CurveFile; b: CurveFile };
export type BlendResult = Omit<Api.BlendResult, 'curve'> & { curve: CurveFile };

/** POST /api/rebuild, /api/interpolate-closed and /api/offset (docs/server.md): nothing is stored. */
export type RebuildRequest = Omit<Api.RebuildRequest, 'curve'> & { curve: CurveFile };
export type RebuildResult = Omit<Api.RebuildResult, 'curve'> & { curve: CurveFile };
export type ClosedInterpolationRequest = Api.ClosedInterpolationRequest;
export type ClosedInterpolation = Omit<Api.ClosedInterpolation, 'curve'> & { curve: CurveFile };
export type OffsetRequest = Omit<Api.OffsetRequest, 'curve'> & { curve: CurveFile };
export type OffsetResult = Omit<Api.OffsetResult, 'raw' | 'trimmed'> & {
  raw: CurveFile;
  trimmed: (Omit<Api.OffsetResult['trimmed'][number], 'curve'> & { curve: CurveFile })[];
};

/** POST /api/intersect and /api/clothoid (docs/server.md): nothing is stored. */
export type IntersectRequest = Omit<Api.IntersectRequest, 'a' | 'b'> & {
  a: CurveFile;
  b?: CurveFile;
};
export type IntersectionResult = Api.IntersectionResult;
export type ClothoidRequest = Api.ClothoidRequest;
export type ClothoidAnswer = Omit<Api.ClothoidAnswer, 'curve'> & { curve: CurveFile };

export interface LawRequest {
  expression: string;
  parameter?: string;
  at?: number[];
  derivatives?: number;
}
export interface LawResponse {
  expression: string;
  parameter: string;
  dimension: number;
  results: { t: number; derivatives: number[][] }[];
}

export interface ReconstructRequest {
  kappa: string;
  tau: string;
  length: number;
  start_point?: number[];
  start_frame?: { tangent: number[]; normal: number[] };
  tolerance?: number;
  fit_tolerance?: number;
  at?: number[];
}
export interface FramePoint {
  s: number;
  position: number[];
  T: number[];
  N: number[];
  B: number[];
}
export interface ReconstructResponse {
  points: FramePoint[];
  curve: CurveFile;
  max_deviation: number;
  integration: { method: string; steps: number; rejected_steps: number; breakpoints: number };
  fit: { control_points: number; segments: number; tolerance: number; max_deviation: number };
}

/** POST …/entities/{label}/curvature-edit (docs/server.md): design by curvature on a stored curve. */
export interface CurvatureEditRequest {
  /** A law of the curve's arc length s: the target κ (signed when planar) or, target 'change', a change of |κ|. */
  kappa: string;
  target?: 'curvature' | 'change';
  /** Space curves: the target τ(s); absent keeps the curve's torsion. */
  tau?: string;
  /** What the end keeps: 'tangent' (default: end point and tangent) or 'curvature' (also end curvatures). */
  hold?: 'free' | 'tangent' | 'curvature';
  max_handles_factor?: number;
}
export interface CurvatureEditReport {
  kind: string;
  handles_before: number;
  handles_after: number;
  planar: boolean;
  length_before: number;
  length_after: number;
  reconstructed: boolean;
  max_curvature_deviation: number;
  mean_curvature_deviation: number;
  reconstruction_max_deviation: number;
  reconstruction_mean_deviation: number;
  iterations: number;
  start_point_error: number;
  end_point_error: number;
  start_tangent_error: number;
  end_tangent_error: number;
  start_curvature_error: number;
  end_curvature_error: number;
  inflections_before: number;
  inflections_after: number;
  seconds: number;
}
export interface CurvatureEditReply extends ChangeReply {
  edit: CurvatureEditReport;
}

export type JobState = 'queued' | 'running' | 'done' | 'failed' | 'cancelled';
export interface Solution {
  variables: number[];
  objectives: (number | null)[];
  violation: number | null;
}
/** A point of the page's Pareto explorer: a solution, with its curve for a study's front member. */
export interface ParetoCandidate extends Solution {
  curve?: CurveFile;
}
/** One curve of a match-curvature-torsion study's Pareto set (docs/formats.md). */
export interface TorsionFrontMember {
  curvature: number;
  torsion: number;
  polished: boolean;
  points: number[][];
  curve: CurveFile;
}
/** The members of a study's result the page reads (the rest is shown as stored). */
export interface StudyResult {
  front?: TorsionFrontMember[];
}
export interface JobReport {
  termination: string;
  message: string;
  generations: number;
  evaluations: number;
  seconds: number;
  seed: number;
  algorithm: string;
}
export interface Job {
  job: string;
  kind: string;
  state: JobState;
  report: JobReport | null;
  /**
   * A problem job's best or front; a study job's stored entities and the
   * study's own result (docs/server.md "Study jobs").
   */
  result: {
    best?: Solution;
    front?: Solution[];
    curves?: string[];
    result?: StudyResult;
  } | null;
  error: ErrorBody | null;
}
export interface GenerationEvent {
  generation: number;
  evaluations: number;
  best: (number | null)[];
  front?: (number | null)[][];
  elapsed: number;
}

// ---- the contract -----------------------------------------------------------
// The server-facing types above against the types generated from the OpenAPI
// document (openapi.ts, kept generated by contract.test.ts): a member the page
// would read or send that the server's schema does not have fails to compile.

/** The members of T that schema S does not have. */
type Unsent<T, S> = Exclude<keyof T, keyof S>;
/** `true` when T has no member S lacks; otherwise a type naming the stray members. */
type Within<T, S> = [Unsent<T, S>] extends [never]
  ? true
  : { notInTheOpenApiDocument: Unsent<T, S> };

export const CONTRACT: [
  Within<ErrorBody, Api.ErrorBody>,
  Within<ErrorWhere, Api.ErrorBody['where']>,
  Within<Health, Api.Health>,
  Within<ChangeSet, Api.ChangeSet>,
  Within<ChangeReply, Api.ChangeWithAnalysis & Api.AddedEntity>,
  Within<HistoryStep, Api.History['history'][number]>,
  Within<AnalysisRequest, Api.AnalysisRequest>,
  Within<FairPreviewRequest, Api.FairPreviewRequest>,
  Within<FairPreview, Api.FairPreview>,
  Within<LawRequest, Api.LawRequest>,
  Within<LawResponse, Api.LawResponse>,
  Within<ReconstructRequest, Api.ReconstructRequest>,
  Within<FramePoint, Api.FramePoint>,
  Within<ReconstructResponse, Api.ReconstructResponse>,
  Within<Solution, Api.Solution>,
  Within<JobReport, Api.JobReport>,
  Within<Job, Api.Job>,
  Within<NonNullable<Job['result']>, Api.JobResult>,
  Within<GenerationEvent, Api.GenerationEvent>,
  Within<DocumentSummary, Api.DocumentList['documents'][number]>,
  Within<CurvatureEditRequest, Api.CurvatureEditRequest>,
  Within<CurvatureEditReport, Api.CurvatureEditResult['edit']>,
  Within<MatchRequest, Api.MatchRequest>,
  Within<MatchResult, Api.MatchResult>,
  Within<BlendRequest, Api.BlendRequest>,
  Within<BlendResult, Api.BlendResult>,
  Within<RebuildRequest, Api.RebuildRequest>,
  Within<RebuildResult, Api.RebuildResult>,
  Within<ClosedInterpolation, Api.ClosedInterpolation>,
  Within<OffsetRequest, Api.OffsetRequest>,
  Within<OffsetResult, Api.OffsetResult>,
  Within<IntersectRequest, Api.IntersectRequest>,
  Within<ClothoidAnswer, Api.ClothoidAnswer>,
] = [
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
  true,
];
