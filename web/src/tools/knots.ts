// Knot-value handles (thesis 7.2): the selected NURBS curve's interior knots are
// drawn as markers at C(knot); dragging one along the curve moves that knot value
// (every copy of it, so its multiplicity stays), kept strictly between its
// neighbours. While the marker moves the page previews the curve on the moved
// knot vector; on release the curve is stored with one PUT (one undo step).
// The tool asks its host for every position: the markers come from the
// server's analysis at the knots, the preview from the page's drag evaluator.

import type { CurveFile } from '../api/types';
import type { Vec3, ViewName } from '../viewport/math';
import type { Tool } from './tools';

export type NurbsFile = Extract<CurveFile, { kind: 'nurbs' }>;

/** A distinct interior knot value: where its first copy is and how many copies there are. */
export interface InteriorKnot {
  readonly value: number;
  readonly index: number;
  readonly multiplicity: number;
}

/** The distinct knot values strictly inside the domain [U[p], U[n]], increasing. */
export function interiorKnots(knots: readonly number[], degree: number): InteriorKnot[] {
  const n = knots.length - degree - 1;
  const a = knots[degree]!;
  const b = knots[n]!;
  const out: InteriorKnot[] = [];
  for (let i = degree + 1; i < n; i++) {
    const u = knots[i]!;
    if (!(u > a && u < b)) continue;
    const last = out[out.length - 1];
    if (last && last.value === u)
      out[out.length - 1] = { ...last, multiplicity: last.multiplicity + 1 };
    else out.push({ value: u, index: i, multiplicity: 1 });
  }
  return out;
}

/** The neighbouring distinct values of interior knot `k` (the domain's ends for the first and last). */
export function knotNeighbours(
  knots: readonly number[],
  degree: number,
  k: number,
): [number, number] {
  const inner = interiorKnots(knots, degree);
  const n = knots.length - degree - 1;
  const prev = k > 0 ? inner[k - 1]!.value : knots[degree]!;
  const next = k + 1 < inner.length ? inner[k + 1]!.value : knots[n]!;
  return [prev, next];
}

/** `t` kept strictly inside (prev, next): at least a thousandth of the gap from either neighbour. */
export function clampBetween(prev: number, next: number, t: number): number {
  const margin = 1e-3 * (next - prev);
  return Math.min(next - margin, Math.max(prev + margin, t));
}

/**
 * The knot vector with every copy of interior knot `k` moved to `to`, or null when `to`
 * is not strictly between its neighbours (the vector would not increase).
 */
export function moveKnot(
  knots: readonly number[],
  degree: number,
  k: number,
  to: number,
): number[] | null {
  const inner = interiorKnots(knots, degree);
  const knot = inner[k];
  if (!knot || !Number.isFinite(to)) return null;
  const [prev, next] = knotNeighbours(knots, degree, k);
  if (!(to > prev && to < next)) return null;
  const out = [...knots];
  for (let i = knot.index; i < knot.index + knot.multiplicity; i++) out[i] = to;
  return out;
}

/**
 * The parameter under a screen point: the cursor projected onto the nearest segment of a
 * polyline drawn on screen (null vertices: behind the camera), its parameter interpolated
 * linearly between the segment's ends; null when no segment is within `radius` pixels.
 */
export function parameterOnScreen(
  cursor: readonly [number, number],
  screen: readonly ([number, number] | null)[],
  t: readonly number[],
  radius: number,
): number | null {
  let best: { d: number; t: number } | null = null;
  for (let i = 1; i < screen.length; i++) {
    const a = screen[i - 1];
    const b = screen[i];
    if (!a || !b) continue;
    const ex = b[0] - a[0];
    const ey = b[1] - a[1];
    const len2 = ex * ex + ey * ey;
    const f =
      len2 > 0
        ? Math.min(1, Math.max(0, ((cursor[0] - a[0]) * ex + (cursor[1] - a[1]) * ey) / len2))
        : 0;
    const d = Math.hypot(a[0] + f * ex - cursor[0], a[1] + f * ey - cursor[1]);
    if (d <= radius && (!best || d < best.d)) best = { d, t: t[i - 1]! + f * (t[i]! - t[i - 1]!) };
  }
  return best ? best.t : null;
}

export interface KnotHost {
  /** The selected curve if it is a NURBS curve the tool can edit (not locked, not hidden), else null. */
  target(): { label: string; name: string; curve: NurbsFile } | null;
  /** Select the curve under the pointer (or none); its label. */
  pick(view: ViewName, ev: PointerEvent): string | null;
  /** C(u) on the stored curve at each u (the server's analysis), or undefined when it failed. */
  pointsAt(label: string, us: readonly number[]): Promise<Vec3[] | undefined>;
  /** C(u) of a curve file at each u (the page's drag evaluator: the live preview). */
  evaluate(curve: NurbsFile, us: readonly number[]): Vec3[];
  /** The index of the marker under the pointer (within a few pixels), or null. */
  markerAt(view: ViewName, ev: PointerEvent, markers: readonly Vec3[]): number | null;
  /** The parameter of the polyline (points and their parameters) under the pointer, or null. */
  parameterAt(
    view: ViewName,
    ev: PointerEvent,
    points: readonly Vec3[],
    t: readonly number[],
  ): number | null;
  /** Draw the preview curve (empty: none) and the knot markers. */
  show(curve: readonly Vec3[], markers: readonly Vec3[]): void;
  /** Call `done` once when the button is released, wherever the pointer is. */
  onRelease(done: () => void): void;
  /** Store the curve with the moved knot vector (one undo step); whether it was stored. */
  commit(label: string, knots: number[], from: number, to: number): Promise<boolean>;
  status(text: string, error?: boolean): void;
}

/** The samples of the preview curve and of the grab's parameter map. */
const SAMPLES = 240;

interface Grab {
  readonly label: string;
  readonly curve: NurbsFile;
  readonly k: number;
  readonly from: number;
  readonly prev: number;
  readonly next: number;
  /** The curve as it was when grabbed, sampled: the pointer's position along it gives the new value. */
  readonly t: number[];
  readonly points: Vec3[];
  to: number;
}

const g = (x: number): string => String(Number(x.toPrecision(6)));

export class KnotTool implements Tool {
  readonly name = 'knots';
  private markers: Vec3[] = [];
  private values: number[] = [];
  private shownFor: string | null = null;
  private grab: Grab | null = null;
  private busy = false;
  /** Bumped at every refresh, so a late answer for an older curve is dropped. */
  private seq = 0;

  constructor(private readonly host: KnotHost) {
    this.refresh();
  }

  get hint(): string {
    const t = this.host.target();
    if (!t) return 'Knots: click a NURBS curve to show its knots';
    const n = interiorKnots(t.curve.knots, t.curve.degree).length;
    return n === 0
      ? `Knots: ${t.name} has no interior knot (insert one with U)`
      : `Knots: drag one of the ${n} knot markers of ${t.name} along the curve (Esc cancels a drag)`;
  }

  /** The knot values marked now (tests and the status). */
  get knotValues(): readonly number[] {
    return this.values;
  }

  /** Show the markers of the selected curve as the server holds it (after a selection or an edit). */
  refresh(keepStatus = false): void {
    if (this.grab) return;
    const seq = ++this.seq;
    const t = this.host.target();
    if (!keepStatus) this.host.status(this.hint);
    if (!t) {
      this.markers = [];
      this.values = [];
      this.shownFor = null;
      this.host.show([], []);
      return;
    }
    const values = interiorKnots(t.curve.knots, t.curve.degree).map((k) => k.value);
    if (values.length === 0) {
      this.markers = [];
      this.values = [];
      this.shownFor = t.label;
      this.host.show([], []);
      return;
    }
    void this.host.pointsAt(t.label, values).then((pts) => {
      if (seq !== this.seq || this.grab || !pts) return;
      this.markers = pts;
      this.values = values;
      this.shownFor = t.label;
      this.host.show([], pts);
    });
  }

  click(view: ViewName, ev: PointerEvent): void {
    if (this.busy || this.grab) return;
    const t = this.host.target();
    if (t && this.shownFor === t.label && this.markers.length > 0) {
      const k = this.host.markerAt(view, ev, this.markers);
      if (k !== null) {
        this.start(t, k);
        return;
      }
    }
    this.host.pick(view, ev);
    this.refresh();
  }

  private start(t: { label: string; curve: NurbsFile }, k: number): void {
    const { curve } = t;
    const [prev, next] = knotNeighbours(curve.knots, curve.degree, k);
    const a = curve.knots[curve.degree]!;
    const b = curve.knots[curve.knots.length - curve.degree - 1]!;
    const ts = Array.from({ length: SAMPLES + 1 }, (_, i) => a + ((b - a) * i) / SAMPLES);
    const from = this.values[k]!;
    this.grab = {
      label: t.label,
      curve,
      k,
      from,
      prev,
      next,
      t: ts,
      points: this.host.evaluate(curve, ts),
      to: from,
    };
    this.host.onRelease(() => {
      void this.release();
    });
    this.host.status(`Knot ${k + 1}: ${g(from)}, between ${g(prev)} and ${g(next)}`);
  }

  move(view: ViewName, ev: PointerEvent): void {
    const d = this.grab;
    if (!d) return;
    const t = this.host.parameterAt(view, ev, d.points, d.t);
    if (t === null) return;
    d.to = clampBetween(d.prev, d.next, t);
    const knots = moveKnot(d.curve.knots, d.curve.degree, d.k, d.to);
    if (!knots) return;
    const moved: NurbsFile = { ...d.curve, knots };
    this.host.show(
      this.host.evaluate(moved, d.t),
      this.host.evaluate(
        moved,
        this.values.map((v, i) => (i === d.k ? d.to : v)),
      ),
    );
    this.host.status(
      `Knot ${d.k + 1}: ${g(d.from)} → ${g(d.to)} (between ${g(d.prev)} and ${g(d.next)})`,
    );
  }

  private async release(): Promise<void> {
    const d = this.grab;
    if (!d) return;
    this.grab = null;
    const knots = d.to === d.from ? null : moveKnot(d.curve.knots, d.curve.degree, d.k, d.to);
    if (!knots) {
      this.host.show([], this.markers);
      this.host.status(this.hint);
      return;
    }
    this.busy = true;
    try {
      await this.host.commit(d.label, knots, d.from, d.to);
    } finally {
      this.busy = false;
      this.refresh(true);
    }
  }

  rightClick(): void {
    this.drop();
  }

  key(ev: KeyboardEvent): boolean {
    if (ev.key === 'Escape' && this.grab) {
      this.drop();
      return true;
    }
    return false;
  }

  /** Forget the drag in progress: the curve stays as stored. */
  private drop(): void {
    if (!this.grab) return;
    this.grab = null;
    this.host.show([], this.markers);
    this.host.status(this.hint);
  }

  cancel(): void {
    this.grab = null;
    this.seq++;
    this.host.show([], []);
  }
}
