// Intersect: pick two curves (the selected one counts as the first), and the
// points where they meet are marked in the views and read out in the status
// line, each with its parameter on both curves and its coordinates; picking
// the same curve twice gives where it meets itself. The command
// (commands/intersect.ts) asks the server; nothing is stored.

import type { Meeting } from '../commands/intersect';
import type { Vec3, ViewName } from '../viewport/math';
import type { Tool } from './tools';

export interface IntersectHost {
  /** The selected curve (label, name) or null. */
  selected(): { label: string; name: string } | null;
  /** The visible curve under the pointer (selected then), or null. */
  pick(view: ViewName, ev: PointerEvent): { label: string; name: string } | null;
  /** Mark the points (empty: none). */
  mark(points: readonly Vec3[]): void;
  /** Ask where the curves meet (b null: where a meets itself); the status reads them out. */
  run(a: string, b: string | null): Promise<Meeting[] | undefined>;
  status(text: string, error?: boolean): void;
}

export class IntersectTool implements Tool {
  readonly name = 'intersect';
  private first: { label: string; name: string } | null;
  private busy = false;
  /** The last answer (the markers drawn). */
  meetings: readonly Meeting[] = [];

  constructor(private readonly host: IntersectHost) {
    this.first = host.selected();
    host.status(this.hint);
  }

  get hint(): string {
    return this.first === null
      ? 'Intersect: click the first curve'
      : `Intersect: ${this.first.name} picked; click the second curve (the same one: where it meets itself)`;
  }

  click(view: ViewName, ev: PointerEvent): void {
    if (this.busy) return;
    const hit = this.host.pick(view, ev);
    if (!hit) {
      this.host.status(`Intersect: no curve there; ${this.hint}`, true);
      return;
    }
    if (this.first === null) {
      this.first = hit;
      this.meetings = [];
      this.host.mark([]);
      this.host.status(this.hint);
      return;
    }
    const a = this.first.label;
    const b = hit.label === a ? null : hit.label;
    this.first = null;
    this.busy = true;
    void this.host
      .run(a, b)
      .then((m) => {
        this.meetings = m ?? [];
        this.host.mark(this.meetings.map((x) => x.point));
      })
      .finally(() => {
        this.busy = false;
      });
  }

  rightClick(): void {
    this.cancel();
    this.host.status(this.hint);
  }

  move(): void {}

  key(ev: KeyboardEvent): boolean {
    if (ev.key === 'Escape') {
      this.cancel();
      this.host.status(this.hint);
      return true;
    }
    return false;
  }

  cancel(): void {
    this.first = null;
    this.meetings = [];
    this.host.mark([]);
  }
}
