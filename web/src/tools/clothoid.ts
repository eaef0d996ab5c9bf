// Clothoid by clicked points: left clicks in a view add points on its working
// plane, right click or Enter asks the server for the spline through them
// (commands/clothoid.ts) and adds it; keys 1, 2 and 3 choose G1 clothoids, G2
// clothoids or biarcs, C toggles a closed spline. With a curve selected, the
// Clothoid command goes through that curve's points instead (its dialog).

import type { ClothoidChoice, ClothoidFit } from '../commands/clothoid';
import type { Vec3, ViewName } from '../viewport/math';
import type { Tool } from './tools';

export interface ClothoidHost {
  /** The clicked point on the view's working plane (snapped), or null. */
  pointAt(view: ViewName, ev: PointerEvent): Vec3 | null;
  preview(points: readonly Vec3[]): void;
  status(text: string, error?: boolean): void;
  /** Ask for the spline through the points and add it (one undo step). */
  make(points: Vec3[], choice: ClothoidChoice): Promise<void>;
}

const FITS: Record<string, ClothoidFit> = { '1': 'g1', '2': 'g2', '3': 'biarc' };

export class ClothoidTool implements Tool {
  readonly name = 'clothoid';
  private points: Vec3[] = [];
  private cursor: Vec3 | null = null;
  private fit: ClothoidFit = 'g2';
  private closed = false;
  private busy = false;

  constructor(private readonly host: ClothoidHost) {
    host.status(this.hint);
  }

  get hint(): string {
    const what = this.fit === 'biarc' ? 'biarcs' : `${this.fit.toUpperCase()} clothoids`;
    return (
      `Clothoid (${what}${this.closed ? ', closed' : ''}): left-click points, right-click or Enter to finish ` +
      `(keys 1 G1, 2 G2, 3 biarcs, C closed)`
    );
  }

  /** What the next spline will be. */
  get choice(): ClothoidChoice {
    return { fit: this.fit, closed: this.closed };
  }

  click(view: ViewName, ev: PointerEvent): void {
    if (this.busy) return;
    const p = this.host.pointAt(view, ev);
    if (!p) return;
    this.points.push(p);
    this.host.status(`Clothoid: ${this.points.length} point(s); right-click or Enter to finish`);
    this.host.preview(this.points);
  }

  rightClick(): void {
    if (this.busy) return;
    const need = this.closed ? 3 : 2;
    if (this.points.length < need) {
      this.host.status(`Clothoid: at least ${need} points are needed`, true);
      return;
    }
    const points = this.points;
    this.points = [];
    this.busy = true;
    void this.host.make(points, this.choice).finally(() => {
      this.busy = false;
      this.host.preview([]);
    });
  }

  move(view: ViewName, ev: PointerEvent): void {
    if (this.busy || this.points.length === 0) return;
    this.cursor = this.host.pointAt(view, ev);
    this.host.preview(this.cursor ? [...this.points, this.cursor] : this.points);
  }

  key(ev: KeyboardEvent): boolean {
    if (ev.ctrlKey || ev.metaKey || ev.altKey) return false;
    const fit = FITS[ev.key];
    if (fit) {
      this.fit = fit;
      this.host.status(this.hint);
      return true;
    }
    if (ev.key.toLowerCase() === 'c' && !ev.shiftKey) {
      this.closed = !this.closed;
      this.host.status(this.hint);
      return true;
    }
    if (ev.key === 'Enter') {
      this.rightClick();
      return true;
    }
    if (ev.key === 'Escape') {
      this.cancel();
      this.host.status(this.hint);
      return true;
    }
    return false;
  }

  cancel(): void {
    this.points = [];
    this.cursor = null;
    this.host.preview([]);
  }
}
