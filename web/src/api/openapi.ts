// Generated from src/hula/server/openapi.json by src/api/openapi-types.ts; do not edit.
// Regenerate: HULA_REBASELINE=1 npx vitest run src/api/contract.test.ts

export type Error = {
  error: ErrorBody;
};

export type ErrorBody = {
  code: string;
  message: string;
  where: {
    field?: string;
    index?: number;
    component?: number;
    line?: number;
    column?: number;
  };
};

export type Health = {
  status: "ok";
  version: string;
};

export type LawRequest = {
  expression: string;
  parameter?: string;
  at?: number[];
  derivatives?: number;
};

export type LawResponse = {
  expression: string;
  parameter: string;
  dimension: number;
  results: {
    t: number;
    derivatives: number[][];
  }[];
};

export type ReconstructRequest = {
  kappa: string;
  tau: string;
  length: number;
  start_point?: number[];
  start_frame?: {
    tangent: number[];
    normal: number[];
  };
  tolerance?: number;
  fit_tolerance?: number;
  at?: number[];
};

export type FramePoint = {
  s: number;
  position: number[];
  T: number[];
  N: number[];
  B: number[];
};

export type ReconstructResponse = {
  points: FramePoint[];
  curve: CurveFile;
  max_deviation: number;
  integration: {
    method: "planar-exact-angle" | "planar-numeric-angle" | "frenet-serret";
    steps: number;
    rejected_steps: number;
    breakpoints: number;
  };
  fit: {
    control_points: number;
    segments: number;
    tolerance: number;
    max_deviation: number;
  };
};

export type IntersectRequest = {
  a: CurveFile;
  b?: CurveFile;
  tolerance?: number;
};

export type IntersectionResult = {
  tolerance: number;
  points: {
    s: number;
    t: number;
    point: number[];
    distance: number;
    angle: number;
    kind: "crossing" | "tangent";
  }[];
  overlaps: {
    s: number[];
    t: number[];
    start: number[];
    end: number[];
  }[];
  stand_in_deviation?: number;
};

export type DistanceRequest = {
  a: CurveFile;
  b: CurveFile;
  tolerance?: number;
};

export type DistanceResult = {
  distance: number;
  s: number;
  t: number;
  point_a: number[];
  point_b: number[];
  lower_bound: number;
  stand_in_deviation?: number;
};

export type CurveFile = {
  format?: string;
  kind: string;
  [key: string]: unknown;
};

export type JobRequest = {
  problem: {
    [key: string]: unknown;
  };
  algorithm?: "ga-real" | "ga-binary" | "nsga2";
  population?: number;
  generations?: number;
  seed?: number;
};

export type Solution = {
  variables: number[];
  objectives: (number | null)[];
  violation: number | null;
};

export type JobReport = {
  termination: "MaxGenerations" | "MaxEvaluations" | "TargetReached" | "Stagnation" | "WallTime" | "Cancelled" | "Converged";
  message: string;
  generations: number;
  evaluations: number;
  failed_evaluations: number;
  seconds: number;
  seed: number;
  algorithm: string;
  problem: string;
};

export type JobResult = {
  best?: Solution;
  front?: Solution[];
  document?: string;
  study?: number;
  curves?: number[];
  revision?: number;
  result?: {
    [key: string]: unknown;
  };
};

export type Job = {
  job: string;
  kind: "problem" | "study";
  state: "queued" | "running" | "done" | "failed" | "cancelled";
  report: JobReport | StudyJobReport | null;
  result: JobResult | null;
  error: ErrorBody | null;
};

export type GenerationEvent = {
  generation: number;
  evaluations: number;
  best: (number | null)[];
  front?: ((number | null)[])[];
  elapsed: number;
  study?: string;
};

export type ChangeSet = {
  cause: "commit" | "undo" | "redo";
  name: string;
  revision: number;
  added: number[];
  changed: number[];
  removed: number[];
  attributes_changed: number[];
  entities?: Entity[];
};

export type Change = {
  revision: number;
  changes: ChangeSet;
};

export type AddedEntity = {
  label: number;
  revision: number;
  changes: ChangeSet;
};

export type Attributes = {
  name: string;
  colour: string;
  visible: boolean;
  layer: string;
  locked: boolean;
  user: {
    [key: string]: unknown;
  };
  [key: string]: unknown;
};

export type EntitySummary = {
  label: number;
  kind: "curve" | "point-set" | "study";
  name: string;
  attributes: Attributes;
};

export type Document = {
  name: string;
  revision: number;
  backend: string;
  entities: EntitySummary[];
};

export type DocumentList = {
  documents: {
    name: string;
    open: boolean;
  }[];
};

export type NewDocument = {
  name: string;
  backend?: "native" | "occt";
};

export type Trashed = {
  name: string;
  trash: string;
};

export type History = {
  revision: number;
  history: {
    revision: number;
    name: string;
    time: string;
    changed: number[];
    applied: boolean;
  }[];
};

export type EntityWrite = {
  curve: CurveFile;
  name?: string;
  attributes?: {
    [key: string]: unknown;
  };
};

export type EntityPatch = {
  move?: {
    index: number;
    to: number[];
  }[];
  continue?: boolean;
  attributes?: {
    [key: string]: unknown;
  };
  analysis?: AnalysisRequest;
};

export type Entity = {
  label: number;
  kind: string;
  attributes: Attributes;
  [key: string]: unknown;
};

export type AnalysisRequest = {
  samples?: number;
  by?: "parameter" | "arclength";
  fins?: ("curvature" | "torsion" | "normal" | "binormal" | "bishop-u" | "bishop-v" | "combescure")[];
  scale?: number;
  features?: boolean;
  at?: number[];
  arc_lengths?: boolean;
  bishop?: boolean;
  fin_density?: number;
};

export type Analysis = {
  t: number[];
  s?: number[];
  points: (number[] | null)[];
  frames: {
    T: (number[] | null)[];
    N: (number[] | null)[];
    B: (number[] | null)[];
  };
  curvature: (number | null)[];
  torsion: (number | null)[];
  curvature_derivative: (number | null)[];
  speed: (number | null)[];
  bishop?: {
    U: (number[] | null)[];
    V: (number[] | null)[];
  };
  fins: {
    kind: "curvature" | "torsion" | "normal" | "binormal" | "bishop-u" | "bishop-v" | "combescure";
    scale: number;
    t: number[];
    base: (number[] | null)[];
    tip: (number[] | null)[];
  }[];
  planarity: {
    planar: boolean;
    normal: number[] | null;
    max_deviation: number;
    tolerance: number;
  };
  features?: {
    inflections: {
      t: number;
      point: number[] | null;
    }[];
    curvature_extrema: {
      kind: "maximum" | "minimum";
      t: number;
      point: number[] | null;
      curvature: number;
    }[];
    torsion_extrema: {
      kind: "maximum" | "minimum";
      t: number;
      point: number[] | null;
      torsion: number;
    }[];
    knots: {
      t: number;
      multiplicity: number;
      parametric: number | null;
      geometric: number | null;
      tangent_angle: number | null;
      curvature_left: number | null;
      curvature_right: number | null;
      left: (number[] | null)[];
      right: (number[] | null)[];
    }[];
    curvature_monotonicity: {
      monotone: boolean;
      pieces: {
        t0: number;
        t1: number;
        curvature0: number | null;
        curvature1: number | null;
        trend: "increasing" | "decreasing" | "constant";
      }[];
      violations: {
        kind: "maximum" | "minimum";
        t: number;
        curvature: number | null;
      }[];
    };
    maximum_curvature: {
      value: number | null;
      t: number | null;
    };
    self_intersections: IntersectionResult;
  };
  revision?: number;
};

export type StudyJobRequest = {
  document: string;
  study: {
    [key: string]: unknown;
  };
};

export type StudyJobReport = {
  study: string;
  termination: "Completed" | "Cancelled";
  generations: number;
  evaluations: number;
  seconds: number;
};

export type KnotInsertion = {
  u: number;
  times?: number;
};

export type DegreeElevation = {
  times?: number;
};

export type ImportRequest = unknown;

export type ImportResult = {
  labels: number[];
  revision: number;
  changes: ChangeSet;
  skipped?: number;
  warnings?: string[];
};

export type ExportRequest = {
  labels: number[];
  format: "json" | "dxf" | "step" | "step-ap214" | "step-ap242" | "iges";
};

export type ExportResult = {
  labels: number[];
  format: "json" | "dxf" | "step-ap214" | "step-ap242" | "iges";
  content: string;
  max_deviation?: number;
};

export type SplitRequest = {
  t: number;
};

export type SplitResult = {
  labels: number[];
  revision: number;
  changes: ChangeSet;
};

export type FairPreviewRequest = {
  tolerance: number;
  method?: "min-variation" | "knots";
  budget?: number;
  hold?: "free" | "points" | "tangents";
  analysis?: AnalysisRequest;
  curve?: CurveFile;
};

export type FairPreview = {
  revision: number;
  method: "min-variation" | "knots";
  tolerance: number;
  curve: CurveFile;
  energy_before: number;
  energy_after: number;
  max_deviation: number;
  data_points: number[][];
  faired_points: number[][];
  iterations: number;
  stopped: boolean;
  seconds: number;
  analysis?: Analysis;
  hold: "free" | "points" | "tangents";
};

export type ChangeWithAnalysis = {
  revision: number;
  changes: ChangeSet;
  analysis?: Analysis;
};

export type CurvatureEditRequest = {
  kappa: string;
  target?: "curvature" | "change";
  tau?: string;
  hold?: "free" | "tangent" | "curvature";
  max_handles_factor?: number;
};

export type CurvatureEditResult = {
  revision: number;
  changes: ChangeSet;
  edit: {
    kind: "nurbs" | "bezier" | "interpolated";
    handles_before: number;
    handles_after: number;
    planar: boolean;
    length_before: number;
    length_after: number;
    mean_curvature_deviation: number;
    max_curvature_deviation: number;
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
    reconstructed: boolean;
    reconstruction_max_deviation: number;
    reconstruction_mean_deviation: number;
  };
};

export type StudySeedRequest = {
  study: "match-curvature-torsion";
  population?: number;
  generations?: number;
};

export type OffsetRequest = {
  curve: CurveFile;
  distance: number;
  tolerance?: number;
  trim?: boolean;
};

export type OffsetResult = {
  distance: number;
  tolerance: number;
  exact: boolean;
  deviation: number;
  raw: CurveFile;
  cusps: number[];
  loops: {
    s: number;
    t: number;
    point: number[];
    angle: number;
    [key: string]: unknown;
  }[];
  trimmed: {
    spans: number[][];
    closed: boolean;
    curve: CurveFile;
  }[];
};

export type HelicalOffsetRequest = {
  curve: CurveFile;
  distance: string | number;
  twist?: string | number;
  frame?: "frenet" | "bishop";
  tolerance?: number;
};

export type HelicalOffsetResult = {
  frame: string;
  distance: string;
  twist: string;
  tolerance: number;
  exact: boolean;
  deviation: number;
  plane_normal?: number[];
  curve: CurveFile;
};

export type OrthotomicRequest = {
  curve: CurveFile;
  pole: number[];
  k?: number;
  tolerance?: number;
};

export type PolarRequest = {
  curve: CurveFile;
  centre: number[];
  radius?: number;
  tolerance?: number;
};

export type MappedCurve = {
  mapping: "orthotomic" | "polar";
  exact: boolean;
  deviation: number;
  tolerance: number;
  curve: CurveFile;
  pole?: number[];
  k?: number;
  centre?: number[];
  radius?: number;
};

export type MatchRequest = {
  a: CurveFile;
  b: CurveFile;
  continuity?: string;
  end?: "start" | "end";
  to_end?: "start" | "end";
  at?: number;
  tangent_scale?: number;
};

export type MatchResult = {
  curve: CurveFile;
  requested: string;
  geometric: string | null;
  parametric: string | null;
  tangent_angle: number | null;
  curvature_left: number | null;
  curvature_right: number | null;
  moved: number[];
  inserted_knots: number;
  degree_elevation: number;
  target_parameter: number;
  degree: number;
  control_points: number;
};

export type BlendRequest = {
  a: CurveFile;
  b: CurveFile;
  continuity?: string;
  end?: "start" | "end";
  to_end?: "start" | "end";
};

export type BlendResult = {
  curve: CurveFile;
  requested: string;
  start: {
    geometric: string | null;
    parametric: string | null;
  };
  end: {
    geometric: string | null;
    parametric: string | null;
  };
  scale: number;
  curvature_variation: {
    value: number;
    error_estimate: number;
    converged: boolean;
  };
  curvature_extrema: number;
  degree: number;
  control_points: number;
};

export type ClothoidRequest = {
  points?: number[][];
  closed?: boolean;
  fit?: "g1" | "g2" | "biarc";
  start_point?: number[];
  end_point?: number[];
  start_angle?: number;
  end_angle?: number;
  start_curvature?: number;
  end_curvature?: number;
  at?: number[];
};

export type ClothoidAnswer = {
  kind: "g1" | "g2" | "biarc";
  segments: {
    start: number[];
    theta0: number;
    kappa0: number;
    dkappa: number;
    length: number;
    end: number[];
    theta1: number;
    kappa1: number;
  }[];
  length: number;
  iterations: number;
  through?: number;
  closed?: boolean;
  points?: {
    s: number;
    point: number[];
    theta: number;
    kappa: number;
    [key: string]: unknown;
  }[];
  curve: CurveFile;
};

export type RebuildRequest = {
  curve: CurveFile;
  control_points: number;
  degree?: number;
  samples?: number;
};

export type RebuildResult = {
  operation: "rebuild";
  degree: number;
  control_points: number;
  samples: number;
  max_deviation: number;
  mean_deviation: number;
  at: number;
  curve: CurveFile;
};

export type ReduceDegreeRequest = {
  curve: CurveFile;
  tolerance: number;
};

export type DegreeReduction = {
  operation: "reduce-degree";
  error_bound: number;
  bezier_bound: number;
  tolerance: number;
  curve: CurveFile;
};

export type ClosedInterpolationRequest = {
  points: number[][];
  parameterisation?: "uniform" | "chord" | "centripetal" | "foley";
  parameters?: number[];
};

export type ClosedInterpolation = {
  kind: "nurbs";
  method: "closed";
  points: number;
  dimension: 2 | 3;
  degree: number;
  control_points: number;
  domain: number[];
  parameterisation: "uniform" | "chord" | "centripetal" | "foley" | "given";
  curve: CurveFile;
};

export type FrenetHandles = {
  handles: {
    point: number[];
    tangent: number[];
    normal?: number[];
    curvature?: number;
    torsion?: number;
  }[];
  parameters?: number[];
};

export type FrenetHermite = {
  degree: number;
  control_points: number;
  domain: number[];
  curve: CurveFile;
};
