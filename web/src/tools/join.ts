// Match and Blend (what a CAD user reaches for first to join two curves): two
// clicks pick the curve ends, the command (commands/match.ts, commands/blend.ts)
// asks the server and stores the result as one undo step. Match: click curve A
// near the end that moves, then curve B near an end (matched to that end) or
// anywhere else on it (matched to B at that point). Blend: click the two ends.
// Keys 0–3 (or the toolbar's continuity menu) choose Gk; the tool never
// evaluates a curve, it reads the picked samples of the server's analyses.

import type { CurveEndName } from '../api/types';
import type { Vec3, ViewName } from '../viewport/math';
import type { Tool } from './tools';

/** A curve under the pointer: the nearest sample of its analysis, and the end it is near (else null). */
export interface CurvePick {
  readonly label: string;
  /** The picked sample's parameter t and position. */
  readonly t: number;
  readonly point: Vec3;
  /** The curve end within the pick radius of the pointer, or null on the curve between them. */
  readonly end: CurveEndName | null;
  /** The nearer end's position. */
  readonly endPoint: Vec3;
  /** Which end is nearer along the curve (by sample index), whatever the pointer's distance. */
  readonly nearerEnd: CurveEndName;
}

/** What Match and Blend ask: A's end joined to B's end or (Match only) to B at parameter `at`. */
export interface JoinRequest {
  readonly a: string;
  readonly end: CurveEndName;
  readonly b: string;
  readonly toEnd?: CurveEndName;
  readonly at?: number;
  readonly continuity: number;
}

export interface JoinHost {
  /** The visible curve under the pointer, or null. */
  pick(view: ViewName, ev: PointerEvent): CurvePick | null;
  /** Mark the picked points (empty: none). */
  mark(points: readonly Vec3[]): void;
  status(text: string, error?: boolean): void;
  /** Carry the join out (one undo step). */
  run(kind: 'match' | 'blend', request: JoinRequest): Promise<void>;
  /** The continuity chosen changed (the toolbar menu follows). */
  continuityChanged(k: number): void;
}

const ORDERS = { match: [0, 1, 2, 3], blend: [1, 2, 3] } as const;

export class JoinTool implements Tool {
  private first: { label: string; end: CurveEndName; point: Vec3 } | null = null;
  private k: number;
  private busy = false;

  constructor(
    readonly name: 'match' | 'blend',
    private readonly host: JoinHost,
    continuity = 2,
  ) {
    this.k = this.allowed(continuity) ? continuity : 2;
    host.continuityChanged(this.k);
    host.status(this.hint);
  }

  /** The continuity asked (k of Gk). */
  get continuity(): number {
    return this.k;
  }

  setContinuity(k: number): void {
    if (!this.allowed(k)) {
      this.host.status(`${this.title}: G${k} is not offered; choose ${this.range}`, true);
      return;
    }
    this.k = k;
    this.host.continuityChanged(k);
    this.host.status(this.hint);
  }

  private allowed(k: number): boolean {
    return (ORDERS[this.name] as readonly number[]).includes(k);
  }

  private get title(): string {
    return this.name === 'match' ? 'Match' : 'Blend';
  }

  private get range(): string {
    return this.name === 'match' ? 'G0–G3' : 'G1–G3';
  }

  get hint(): string {
    const g = `G${this.k}`;
    if (this.first === null)
      return this.name === 'match'
        ? `Match ${g}: click curve A near the end to move (keys 0-3 choose the continuity)`
        : `Blend ${g}: click the first curve near the end to leave (keys 1-3 choose the continuity)`;
    const a = `${this.first.label}'s ${this.first.end}`;
    return this.name === 'match'
      ? `Match ${g}: ${a} picked; click curve B near an end, or on it to match to that point (Esc cancels)`
      : `Blend ${g}: ${a} picked; click the second curve near the end to reach (Esc cancels)`;
  }

  click(view: ViewName, ev: PointerEvent): void {
    if (this.busy) return;
    const hit = this.host.pick(view, ev);
    if (!hit) {
      this.host.status(`${this.title}: no curve there; ${this.hint}`, true);
      return;
    }
    if (this.first === null) {
      // A's end: the end clicked, else the nearer one along the curve.
      const end = hit.end ?? hit.nearerEnd;
      this.first = { label: hit.label, end, point: hit.endPoint };
      this.host.mark([hit.endPoint]);
      this.host.status(this.hint);
      return;
    }
    if (hit.label === this.first.label) {
      this.host.status(`${this.title}: pick a second curve, not ${hit.label} again`, true);
      return;
    }
    const first = this.first;
    const base = { a: first.label, end: first.end, b: hit.label, continuity: this.k };
    let request: JoinRequest;
    if (this.name === 'blend') request = { ...base, toEnd: hit.end ?? hit.nearerEnd };
    else request = hit.end ? { ...base, toEnd: hit.end } : { ...base, at: hit.t };
    this.host.mark([first.point, hit.end ? hit.endPoint : hit.point]);
    this.busy = true;
    void this.host.run(this.name, request).finally(() => {
      this.busy = false;
      this.first = null;
      this.host.mark([]);
    });
  }

  rightClick(): void {
    this.cancel();
  }

  move(): void {}

  key(ev: KeyboardEvent): boolean {
    if (ev.key >= '0' && ev.key <= '3' && !ev.ctrlKey && !ev.metaKey && !ev.altKey) {
      this.setContinuity(Number(ev.key));
      return true;
    }
    if (ev.key === 'Escape') {
      this.cancel();
      return true;
    }
    return false;
  }

  cancel(): void {
    this.first = null;
    this.host.mark([]);
  }
}
