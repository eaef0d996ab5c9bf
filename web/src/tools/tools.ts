// Creation and edit tools (appendix 8.1–8.3). Each tool turns clicks in a
// viewport into points on that view's working plane and hands a curve file
// to the app, which sends it to the server. Tools never evaluate curves.

import type { CurveFile, EndCondition } from '../api/types';
import { norm, sub, type Vec3, type ViewName } from '../viewport/math';

export type ToolName =
  | 'select'
  | 'spline'
  | 'bezier'
  | 'nurbs'
  | 'hermite'
  | 'match'
  | 'blend'
  | 'intersect'
  | 'knots'
  | 'clothoid';

export interface ToolHost {
  /** The clicked point on the view's working plane (snapped), or null. */
  pointAt(view: ViewName, ev: PointerEvent): Vec3 | null;
  preview(points: readonly Vec3[]): void;
  create(name: string, curve: CurveFile): void;
  status(text: string): void;
}

export interface Tool {
  readonly name: ToolName;
  /** What the tool wants next, for the status line when it starts and after it made a curve. */
  readonly hint: string;
  /** Left click; returns true when handled. */
  click(view: ViewName, ev: PointerEvent): void;
  /** Right click (finish / natural tangent). */
  rightClick(view: ViewName, ev: PointerEvent): void;
  move(view: ViewName, ev: PointerEvent): void;
  /** Enter finishes, Escape cancels. */
  key(ev: KeyboardEvent): boolean;
  cancel(): void;
}

/** A clamped uniform knot vector of n control points and degree p (construction data). */
export function clampedUniformKnots(n: number, p: number): number[] {
  const knots: number[] = [];
  for (let i = 0; i <= p; i++) knots.push(0);
  const inner = n - p - 1;
  for (let i = 1; i <= inner; i++) knots.push(i / (inner + 1));
  for (let i = 0; i <= p; i++) knots.push(1);
  return knots;
}

/** The chord length of a polygon: the scale of an end tangent dC/dt on t ∈ [0, 1]. */
/** The middle of the widest knot span of a knot vector (where "Insert knot" puts a knot). */
export function midSpan(knots: readonly number[]): number {
  let best = 0;
  let at = knots.length > 0 ? knots[0]! : 0;
  for (let i = 1; i < knots.length; i++) {
    const width = knots[i]! - knots[i - 1]!;
    if (width > best) {
      best = width;
      at = 0.5 * (knots[i]! + knots[i - 1]!);
    }
  }
  return at;
}

export function chordLength(points: readonly Vec3[]): number {
  let l = 0;
  for (let i = 1; i < points.length; i++) l += norm(sub(points[i]!, points[i - 1]!));
  return l;
}

const fmt = (p: Vec3): string => p.map((x) => Number(x.toPrecision(6))).join(', ');

/**
 * Interpolated spline (8.1): left clicks enter data points, right click ends;
 * then a left click sets the start tangent (towards the click) or a right
 * click leaves it natural; the same for the end tangent.
 */
export class SplineTool implements Tool {
  readonly name = 'spline';
  readonly hint = 'Spline: left-click data points, right-click to finish';
  private points: Vec3[] = [];
  private phase: 'points' | 'start' | 'end' = 'points';
  private start: EndCondition = 'natural';
  private cursor: Vec3 | null = null;

  constructor(private readonly host: ToolHost) {
    host.status(this.hint);
  }

  click(view: ViewName, ev: PointerEvent): void {
    const p = this.host.pointAt(view, ev);
    if (!p) return;
    if (this.phase === 'points') {
      this.points.push(p);
      this.host.status(
        `Spline: ${this.points.length} point(s), last (${fmt(p)}); right-click to finish`,
      );
    } else {
      const anchor =
        this.phase === 'start' ? this.points[0]! : this.points[this.points.length - 1]!;
      const d = sub(p, anchor);
      const len = norm(d);
      if (len === 0) return;
      const k = chordLength(this.points) / len;
      const tangent: EndCondition = { tangent: [d[0] * k, d[1] * k, d[2] * k] };
      this.nextTangent(tangent);
      return;
    }
    this.draw();
  }

  rightClick(): void {
    if (this.phase === 'points') {
      if (this.points.length < 2) {
        this.host.status('Spline: at least two data points are needed');
        return;
      }
      this.phase = 'start';
      this.host.status('Spline: left-click the start tangent, right-click for natural');
      return;
    }
    this.nextTangent('natural');
  }

  private nextTangent(c: EndCondition): void {
    if (this.phase === 'start') {
      this.start = c;
      this.phase = 'end';
      this.host.status('Spline: left-click the end tangent, right-click for natural');
      return;
    }
    const curve: CurveFile = {
      kind: 'interpolated',
      points: this.points.map((p) => [...p]),
      parameterisation: 'chord',
      start: this.start,
      end: c,
    };
    this.host.create('spline', curve);
    this.reset();
  }

  move(view: ViewName, ev: PointerEvent): void {
    this.cursor = this.host.pointAt(view, ev);
    this.draw();
  }

  private draw(): void {
    const pts =
      this.phase === 'points' && this.cursor ? [...this.points, this.cursor] : this.points;
    this.host.preview(pts);
  }

  key(ev: KeyboardEvent): boolean {
    if (ev.key === 'Enter') {
      this.rightClick();
      return true;
    }
    if (ev.key === 'Escape') {
      this.cancel();
      return true;
    }
    return false;
  }

  private reset(): void {
    this.points = [];
    this.phase = 'points';
    this.start = 'natural';
    this.host.preview([]);
    this.host.status(this.hint);
  }

  cancel(): void {
    this.reset();
  }
}

/**
 * Bézier or NURBS by control points (8.2): left clicks in any view add points
 * on that view's working plane (top: X-Y, front: Z-X), right click or Enter ends.
 */
export class ControlPointTool implements Tool {
  private points: Vec3[] = [];
  private cursor: Vec3 | null = null;

  constructor(
    readonly name: 'bezier' | 'nurbs',
    private readonly host: ToolHost,
    private readonly degree = 3,
  ) {
    host.status(this.hint);
  }

  get hint(): string {
    return `${this.title}: left-click control points in any view, right-click to finish`;
  }

  private get title(): string {
    return this.name === 'bezier' ? 'Bézier' : 'NURBS';
  }

  click(view: ViewName, ev: PointerEvent): void {
    const p = this.host.pointAt(view, ev);
    if (!p) return;
    this.points.push(p);
    const plane = view === 'front' ? 'Z-X' : view === 'side' ? 'Y-Z' : 'X-Y';
    this.host.status(`${this.title}: ${this.points.length} point(s), last (${fmt(p)}) in ${plane}`);
    this.host.preview(this.points);
  }

  rightClick(): void {
    if (this.points.length < 2) {
      this.host.status(`${this.title}: at least two control points are needed`);
      return;
    }
    const cps = this.points.map((p) => [...p]);
    if (this.name === 'bezier') {
      this.host.create('bezier', { kind: 'bezier', control_points: cps, weights: null });
    } else {
      const p = Math.min(this.degree, cps.length - 1);
      this.host.create('nurbs', {
        kind: 'nurbs',
        degree: p,
        knots: clampedUniformKnots(cps.length, p),
        control_points: cps,
        weights: null,
      });
    }
    this.cancel();
  }

  move(view: ViewName, ev: PointerEvent): void {
    this.cursor = this.host.pointAt(view, ev);
    this.host.preview(this.cursor ? [...this.points, this.cursor] : this.points);
  }

  key(ev: KeyboardEvent): boolean {
    if (ev.key === 'Enter') {
      this.rightClick();
      return true;
    }
    if (ev.key === 'Escape') {
      this.cancel();
      return true;
    }
    return false;
  }

  cancel(): void {
    this.points = [];
    this.host.preview([]);
  }
}

/**
 * Hermite curve: click a point, then click the tip of its tangent handle;
 * repeat; right click ends. Sent as an interpolated curve whose data points
 * carry their tangents (the server builds the piecewise cubic Hermite).
 */
export class HermiteTool implements Tool {
  readonly name = 'hermite';
  readonly hint = 'Hermite: click a point, then its tangent handle; right-click to finish';
  private points: Vec3[] = [];
  private tangents: Vec3[] = [];
  private cursor: Vec3 | null = null;

  constructor(private readonly host: ToolHost) {
    host.status(this.hint);
  }

  click(view: ViewName, ev: PointerEvent): void {
    const p = this.host.pointAt(view, ev);
    if (!p) return;
    if (this.points.length === this.tangents.length) this.points.push(p);
    else this.tangents.push(sub(p, this.points[this.points.length - 1]!));
    this.draw();
  }

  private draw(): void {
    const pts: Vec3[] = [];
    this.points.forEach((p, i) => {
      pts.push(p);
      const t = this.tangents[i];
      if (t) pts.push([p[0] + t[0], p[1] + t[1], p[2] + t[2]], p);
    });
    if (this.cursor) pts.push(this.cursor);
    this.host.preview(pts);
  }

  rightClick(): void {
    const n = Math.min(this.points.length, this.tangents.length);
    if (n < 2) {
      this.host.status('Hermite: at least two points with tangents are needed');
      return;
    }
    this.host.create('hermite', {
      kind: 'hermite',
      points: this.points.slice(0, n).map((p) => [...p]),
      tangents: this.tangents.slice(0, n).map((t) => [...t]),
    });
    this.cancel();
  }

  move(view: ViewName, ev: PointerEvent): void {
    this.cursor = this.host.pointAt(view, ev);
    this.draw();
  }

  key(ev: KeyboardEvent): boolean {
    if (ev.key === 'Enter') {
      this.rightClick();
      return true;
    }
    if (ev.key === 'Escape') {
      this.cancel();
      return true;
    }
    return false;
  }

  cancel(): void {
    this.points = [];
    this.tangents = [];
    this.host.preview([]);
  }
}
