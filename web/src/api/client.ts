// The HTTP client of the workbench: one place that talks to `hula serve`.
// Requests are authorised by the server's HttpOnly cookie; errors become ApiError with the
// server's code, message and where; the pending count feeds __hula.idle().

import type {
  Analysis,
  AnalysisRequest,
  ChangeReply,
  CurveFile,
  CurvatureEditReply,
  CurvatureEditRequest,
  DocumentState,
  DocumentSummary,
  Entity,
  ErrorBody,
  FairPreview,
  FairPreviewRequest,
  ExportFormat,
  ExportResult,
  Health,
  History as DocHistory,
  Label,
  Job,
  LawRequest,
  LawResponse,
  ReconstructRequest,
  ReconstructResponse,
  MatchRequest,
  MatchResult,
  BlendRequest,
  ClosedInterpolation,
  ClosedInterpolationRequest,
  OffsetRequest,
  OffsetResult,
  IntersectRequest,
  IntersectionResult,
  ClothoidRequest,
  ClothoidAnswer,
  RebuildRequest,
  RebuildResult,
  BlendResult,
} from './types';
import type * as Api from './openapi';
import { analysisFromServer, entityFromServer, historyFromServer, isCurveKind } from './adapt';

/** An error answer of the server, or a network failure (status 0). */
export class ApiError extends Error {
  readonly status: number;
  readonly body: ErrorBody;
  constructor(status: number, body: ErrorBody) {
    super(`${body.code}: ${body.message}`);
    this.name = 'ApiError';
    this.status = status;
    this.body = body;
  }
  /** True when the server could not be reached (restart, network). */
  get offline(): boolean {
    return this.status === 0;
  }
}

function isErrorBody(x: unknown): x is { error: ErrorBody } {
  if (typeof x !== 'object' || x === null || !('error' in x)) return false;
  const e = x.error;
  return typeof e === 'object' && e !== null && 'code' in e && 'message' in e;
}

export type Listener = () => void;

export class Client {
  private pendingCount = 0;
  private readonly listeners = new Set<Listener>();
  /** Called when a request fails because the server is unreachable. */
  onOffline: (() => void) | null = null;
  /** Called when the server refuses the page's token (401: restarted with a new one). */
  onUnauthorized: (() => void) | null = null;

  /**
   * `token` is sent as a Bearer token when given; the page itself gives none:
   * `hula serve` turns `?token=` into an HttpOnly cookie and redirects, so
   * the token never reaches script.
   */
  constructor(
    readonly base: string,
    readonly token = '',
  ) {}

  get pending(): number {
    return this.pendingCount;
  }

  /** Subscribe to changes of the pending count. */
  watch(listener: Listener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  private bump(delta: number): void {
    this.pendingCount += delta;
    for (const l of this.listeners) l();
  }

  /** One JSON request; resolves to the parsed body or throws ApiError. */
  async request<T>(method: string, path: string, body?: unknown, signal?: AbortSignal): Promise<T> {
    this.bump(1);
    try {
      let response: Response;
      try {
        const init: RequestInit = {
          method,
          headers: {
            ...(this.token ? { Authorization: `Bearer ${this.token}` } : {}),
            ...(body === undefined ? {} : { 'Content-Type': 'application/json' }),
          },
          credentials: 'same-origin',
        };
        if (body !== undefined) init.body = JSON.stringify(body);
        if (signal) init.signal = signal;
        response = await fetch(this.base + path, init);
      } catch (e) {
        if (e instanceof DOMException && e.name === 'AbortError') throw e;
        this.onOffline?.();
        throw new ApiError(0, {
          code: 'Offline',
          message: `the server did not answer ${method} ${path}`,
          where: {},
        });
      }
      const text = await response.text();
      let parsed: unknown = null;
      if (text.length > 0) {
        try {
          parsed = JSON.parse(text);
        } catch {
          throw new ApiError(response.status, {
            code: 'BadResponse',
            message: `${method} ${path}: the server answered ${response.status} with non-JSON text`,
            where: {},
          });
        }
      }
      if (!response.ok) {
        if (response.status === 401) this.onUnauthorized?.();
        if (isErrorBody(parsed)) throw new ApiError(response.status, parsed.error);
        throw new ApiError(response.status, {
          code: `Http${response.status}`,
          message: `${method} ${path}: HTTP ${response.status}`,
          where: {},
        });
      }
      return parsed as T;
    } finally {
      this.bump(-1);
    }
  }

  health(): Promise<Health> {
    return this.request('GET', '/api/health');
  }

  private doc(name: string): string {
    return `/api/documents/${encodeURIComponent(name)}`;
  }

  listDocuments(): Promise<{ documents: DocumentSummary[] }> {
    return this.request('GET', '/api/documents');
  }
  createDocument(name: string): Promise<DocumentState> {
    return this.request('POST', '/api/documents', { name });
  }
  /** The document with every curve entity's curve file (the summary names them; each is fetched). */
  async getDocument(name: string): Promise<DocumentState> {
    const summary = await this.request<DocumentState>('GET', this.doc(name));
    const entities = await Promise.all(
      summary.entities.map((e) =>
        isCurveKind(e.kind)
          ? this.getEntity(name, String(e.label))
          : Promise.resolve({ ...e, label: String(e.label) }),
      ),
    );
    return { name: summary.name, revision: summary.revision, entities };
  }
  deleteDocument(name: string): Promise<unknown> {
    return this.request('DELETE', this.doc(name));
  }

  async getEntity(doc: string, label: string): Promise<Entity> {
    return entityFromServer(
      await this.request('GET', `${this.doc(doc)}/entities/${encodeURIComponent(label)}`),
    );
  }
  createEntity(
    doc: string,
    name: string,
    curve: CurveFile,
    attributes?: Record<string, unknown>,
  ): Promise<ChangeReply> {
    return this.request('POST', `${this.doc(doc)}/entities`, {
      name,
      curve,
      ...(attributes ? { attributes } : {}),
    });
  }
  putEntity(doc: string, label: string, curve: CurveFile): Promise<ChangeReply> {
    return this.request('PUT', `${this.doc(doc)}/entities/${encodeURIComponent(label)}`, { curve });
  }
  /** Move points; `continued` folds the move into the previous step (one drag, one undo step). */
  movePoints(
    doc: string,
    label: string,
    moves: { index: number; to: number[] }[],
    continued: boolean,
    analysis?: AnalysisRequest,
  ): Promise<ChangeReply> {
    return this.request('PATCH', `${this.doc(doc)}/entities/${encodeURIComponent(label)}`, {
      move: moves,
      continue: continued,
      ...(analysis ? { analysis } : {}),
    });
  }
  patchEntity(doc: string, label: string, patch: Record<string, unknown>): Promise<ChangeReply> {
    return this.request('PATCH', `${this.doc(doc)}/entities/${encodeURIComponent(label)}`, patch);
  }
  /** Insert knot u `times` times (the curve keeps its shape; one undo step). */
  insertKnot(doc: string, label: string, u: number, times = 1): Promise<ChangeReply> {
    return this.request(
      'POST',
      `${this.doc(doc)}/entities/${encodeURIComponent(label)}/insert-knot`,
      { u, times },
    );
  }
  /** Raise the degree by `times` (the curve keeps its shape; one undo step). */
  elevate(doc: string, label: string, times = 1): Promise<ChangeReply> {
    return this.request('POST', `${this.doc(doc)}/entities/${encodeURIComponent(label)}/elevate`, {
      times,
    });
  }
  /** Reverse the direction of traversal, C*(u) = C(a + b − u) (one undo step). */
  reverse(doc: string, label: string): Promise<ChangeReply> {
    return this.request('POST', `${this.doc(doc)}/entities/${encodeURIComponent(label)}/reverse`);
  }
  /** Split at t into pieces on [a, t] and [t, b], whose labels come back in that order (one undo step). */
  split(doc: string, label: string, t: number): Promise<ChangeReply & { labels: Label[] }> {
    return this.request('POST', `${this.doc(doc)}/entities/${encodeURIComponent(label)}/split`, {
      t,
    });
  }
  /** Import an uploaded STEP, IGES or JSON file's curves (one undo step); their labels come back. */
  importFile(
    doc: string,
    filename: string,
    content: string,
  ): Promise<ChangeReply & { labels: Label[] }> {
    return this.request('POST', `${this.doc(doc)}/import`, { filename, content });
  }
  /** The entities written as a JSON, STEP or IGES file by the server (the document is only read). */
  exportFile(doc: string, labels: Label[], format: ExportFormat): Promise<ExportResult> {
    return this.request('POST', `${this.doc(doc)}/export`, {
      labels: labels.map(Number),
      format,
    });
  }
  deleteEntity(doc: string, label: string): Promise<ChangeReply> {
    return this.request('DELETE', `${this.doc(doc)}/entities/${encodeURIComponent(label)}`);
  }
  undo(doc: string): Promise<ChangeReply> {
    return this.request('POST', `${this.doc(doc)}/undo`);
  }
  redo(doc: string): Promise<ChangeReply> {
    return this.request('POST', `${this.doc(doc)}/redo`);
  }
  async history(doc: string): Promise<DocHistory> {
    return historyFromServer(await this.request('GET', `${this.doc(doc)}/history`));
  }
  async analysis(
    doc: string,
    label: string,
    req: AnalysisRequest,
    signal?: AbortSignal,
  ): Promise<Analysis> {
    const j = await this.request<Api.Analysis>(
      'POST',
      `${this.doc(doc)}/entities/${encodeURIComponent(label)}/analysis`,
      req,
      signal,
    );
    return analysisFromServer(j, req.by);
  }

  /** The fairing assistant's ghost of an entity (the document is not changed). */
  async fairPreview(
    doc: string,
    label: string,
    req: FairPreviewRequest,
    signal?: AbortSignal,
  ): Promise<FairPreview> {
    const j = await this.request<Omit<FairPreview, 'analysis'> & { analysis?: Api.Analysis }>(
      'POST',
      `${this.doc(doc)}/entities/${encodeURIComponent(label)}/fair-preview`,
      req,
      signal,
    );
    const a = j.analysis;
    return {
      ...j,
      analysis: a && req.analysis ? analysisFromServer(a, req.analysis.by) : undefined,
    };
  }

  /** Design by curvature on a stored curve: one "edit curvature" undo step (docs/server.md). */
  curvatureEdit(
    doc: string,
    label: string,
    req: CurvatureEditRequest,
  ): Promise<CurvatureEditReply> {
    return this.request(
      'POST',
      `${this.doc(doc)}/entities/${encodeURIComponent(label)}/curvature-edit`,
      req,
    );
  }
  /** A study file seeded from a stored curve ("From selection"); the document is not changed. */
  studySeed(
    doc: string,
    label: string,
    req: { study: 'match-curvature-torsion'; population?: number; generations?: number },
  ): Promise<Record<string, unknown>> {
    return this.request(
      'POST',
      `${this.doc(doc)}/entities/${encodeURIComponent(label)}/study-seed`,
      req,
    );
  }

  law(req: LawRequest): Promise<LawResponse> {
    return this.request('POST', '/api/law', req);
  }
  reconstruct(req: ReconstructRequest): Promise<ReconstructResponse> {
    return this.request('POST', '/api/reconstruct', req);
  }

  /** A's end made G0–G3 to B (`hula match`); the document is not changed. */
  match(req: MatchRequest): Promise<MatchResult> {
    return this.request('POST', '/api/match', req);
  }
  /** The fair G1–G3 blend between two curve ends (`hula blend`); the document is not changed. */
  blend(req: BlendRequest): Promise<BlendResult> {
    return this.request('POST', '/api/blend', req);
  }
  /** The curve rebuilt with a chosen degree and control-point count (`hula edit rebuild`); nothing is stored. */
  rebuild(req: RebuildRequest): Promise<RebuildResult> {
    return this.request('POST', '/api/rebuild', req);
  }
  /** The periodic C2 cubic through the points and back to the first (`hula interpolate --closed`). */
  interpolateClosed(req: ClosedInterpolationRequest): Promise<ClosedInterpolation> {
    return this.request('POST', '/api/interpolate-closed', req);
  }
  /** A planar curve's offset by a distance, loops trimmed (`hula offset`); nothing is stored. */
  offset(req: OffsetRequest): Promise<OffsetResult> {
    return this.request('POST', '/api/offset', req);
  }
  /** Where two curves meet, or without b where one meets itself (`hula intersect`); nothing is stored. */
  intersect(req: IntersectRequest): Promise<IntersectionResult> {
    return this.request('POST', '/api/intersect', req);
  }
  /** G1/G2 clothoids or biarcs through points (`hula clothoid`): the curve a natural one; nothing is stored. */
  clothoid(req: ClothoidRequest): Promise<ClothoidAnswer> {
    return this.request('POST', '/api/clothoid', req);
  }

  startJob(body: Record<string, unknown>): Promise<Job> {
    return this.request('POST', '/api/jobs', body);
  }
  getJob(id: string): Promise<Job> {
    return this.request('GET', `/api/jobs/${encodeURIComponent(id)}`);
  }
  cancelJob(id: string): Promise<Job> {
    return this.request('DELETE', `/api/jobs/${encodeURIComponent(id)}`);
  }

  /** URL of an SSE stream (authorised by the HttpOnly cookie set on page open). */
  eventsUrl(path: string): string {
    return this.base + path;
  }
  documentEventsUrl(doc: string): string {
    return this.eventsUrl(`${this.doc(doc)}/events`);
  }
  jobEventsUrl(id: string): string {
    return this.eventsUrl(`/api/jobs/${encodeURIComponent(id)}/events`);
  }
}
