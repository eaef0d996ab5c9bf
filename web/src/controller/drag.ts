// The drag of a handle, from the first pointer move that changes it to the
// server's answer to the last: the controller part of the viewport (the
// pointer-to-point part, picking and snapping, is in viewport-input.ts).
//
// Each move is drawn at the next frame, from the page's own evaluation for a
// NURBS or Bézier curve (`preview`), and sent as a PATCH; one PATCH is in
// flight at a time and the latest position waits behind it, so a drag costs
// one request per stored move. Every PATCH but the first carries `continue`:
// the server folds the drag into one "move points" undo step. The last
// reply's entity and analysis are applied once the drag settles (no fetch);
// a move the server did not answer ends the drag and puts the curve back as
// stored, visibly.

import { entityFromServer, analysisFromServer } from '../api/adapt';
import type { Analysis, AnalysisRequest, ChangeReply, CurveFile } from '../api/types';
import { withHandles } from '../api/adapt';
import type { Editor } from '../editor/editor';
import { analyseNurbs } from '../geometry/analysis';
import { NurbsEvaluator } from '../geometry/nurbs';
import type { Abscissa } from '../graphs/graph';
import { nearestIndex } from '../graphs/scale';
import type { ViewSettings } from '../store/curves';
import type { Vec3 } from '../viewport/math';

/** What the drag asks of the page around it (the App: views, graphs, panels, the fairing ghost). */
export interface DragHost {
  readonly editor: Editor;
  readonly abscissa: Abscissa;
  /** Analysis requests the page has started so far (AnalysisScheduler.seq). */
  readonly analysisSeq: number;
  settingsOf(label: string): ViewSettings;
  analysisRequest(label: string): AnalysisRequest;
  redrawCurve(label: string, handles?: Vec3[]): void;
  updateGraphs(): void;
  updatePanels(): void;
  /** Keep the curve's analysis before the drag as the ghost. */
  setGhost(label: string): void;
  requestRender(): void;
  /** The fairing assistant's ghost follows the drag (tools/fairing.ts). */
  readonly fairing: {
    pointerMoved(): void;
    dragEnded(): void;
    afterGhost(work: () => void): void;
  };
}

export interface Drag {
  readonly label: string;
  readonly index: number;
  first: boolean;
  inFlight: boolean;
  pending: Vec3 | null;
  pendingStamp: number;
  readonly handles: Vec3[];
  /** A NURBS or Bézier curve: drawn from the page's own evaluation while dragged. */
  readonly local: boolean;
  /** Moved since the last frame drew it. */
  dirty: boolean;
  /** A move was not stored (the server is unreachable): the drag is over and reverted. */
  failed: boolean;
  /**
   * The handle minus the pointer's point where the drag started: the handle
   * moves by what the pointer moved (a 2 px nudge moves it 2 px worth), it
   * does not jump to the pointer.
   */
  grab: Vec3;
  /**
   * The reply to the latest move: the dragged entity as the server stores it
   * and its analysis (asked for with the move), applied once the drag
   * settles, so a drag costs one request per stored move and nothing after.
   */
  lastReply?: ChangeReply;
}

/**
 * The dragged curve as the page computes it (geometry/analysis.ts), drawn
 * instead of the server's analysis from the first move until the server's
 * analysis of the final position arrives (request number `until` or later).
 */
export interface Preview {
  label: string;
  analysis: Analysis;
  handles: Vec3[];
  until: number;
}

export class DragController {
  drag: Drag | null = null;
  /** The handles of the last drag, until the store holds the curve with its final position. */
  moved: { label: string; handles: Vec3[] } | null = null;
  preview: Preview | null = null;
  /** The curve of the last drag until the server has answered all its moves. */
  settling: string | null = null;
  /** Curves whose entity comes with its analysis (a drag's reply): not asked for again. */
  private readonly fresh = new Set<string>();
  /** Panels and history wait for the end of a drag (rebuilding them per move cost whole frames). */
  panelsStale = false;
  /**
   * Benchmarks of the current drag (ms): from a pointer event (its timeStamp)
   * to the end of the frame that draws the curve moved there (the earliest
   * event not yet drawn, when several come in one frame) …
   */
  readonly latencies: number[] = [];
  /** … and from a pointer event to the server's reply to the move it sent. */
  readonly serverLatencies: number[] = [];
  /**
   * The latencies split at the start of the frame's work (ms): the wait from
   * the pointer event to the frame that draws it, and the frame's own work
   * (what prepare() left to it, and the views' render); and the work done
   * on the pointer events before their frame (prepare()).
   */
  readonly frameSplit = { waits: [] as number[], works: [] as number[], early: [] as number[] };
  private pointerStamp = 0;
  private frameStart = 0;
  /**
   * The honest drag counters (read by e2e/bench.spec.ts), reset when a drag
   * starts: pointer moves that changed the dragged point, and frames that drew
   * the curve, its fins and (when it is the selected curve) the graphs at a
   * new position of it, with the times of the first and last such move.
   */
  readonly dragStats = { moves: 0, redraws: 0, firstMove: 0, lastMove: 0 };
  /** The current frame draws a new drag position (set by frame(), counted after it). */
  private drewDrag = false;
  /**
   * A drag position put into curve, fins and graphs when its pointer event
   * came (prepare()), before the frame that draws it: the dragged point it is
   * of (that Vec3 object; a later move replaces it).
   */
  private prepared: { point: Vec3 } | null = null;

  constructor(private readonly host: DragHost) {}

  private get ed(): Editor {
    return this.host.editor;
  }

  /** Start dragging handle `index` of `label`, whose handles are `handles` (as drawn). */
  start(label: string, index: number, handles: readonly Vec3[], grab: Vec3 = [0, 0, 0]): Drag {
    const curve = this.ed.store.entities.get(label)?.curve;
    this.drag = {
      label,
      index,
      first: true,
      inFlight: false,
      pending: null,
      pendingStamp: 0,
      handles: handles.slice(),
      // Combescure fins are the server's alone: such a drag follows its analysis.
      local:
        curve !== undefined &&
        NurbsEvaluator.of(curve) !== null &&
        !this.host.settingsOf(label).fins.includes('combescure'),
      dirty: false,
      failed: false,
      grab,
    };
    this.settling = label;
    this.prepared = null;
    this.latencies.length = 0;
    this.serverLatencies.length = 0;
    this.frameSplit.waits.length = 0;
    this.frameSplit.works.length = 0;
    this.frameSplit.early.length = 0;
    Object.assign(this.dragStats, { moves: 0, redraws: 0, firstMove: 0, lastMove: 0 });
    this.host.setGhost(label);
    return this.drag;
  }

  /**
   * Move the dragged handle to `p` (the pointer's point, snapped), at the
   * pointer event's time `stamp`. A position equal to the handle's (a release,
   * a move within a snapped grid cell) is no move: nothing is drawn or sent.
   * The next frame draws it; the server hears of it through flush().
   */
  moveTo(p: Vec3 | null, stamp: number, early = false): boolean {
    const d = this.drag;
    if (!d) return false;
    const start = d.handles[d.index]!;
    if (!p || p.every((v, k) => v === start[k])) return false;
    d.handles[d.index] = p;
    this.dragStats.moves++;
    this.dragStats.firstMove ||= stamp;
    this.dragStats.lastMove = stamp;
    this.moved = { label: d.label, handles: d.handles };
    this.host.fairing.pointerMoved();
    // The event's own time: the latency includes the wait for the page to take the event.
    if (!this.pointerStamp) this.pointerStamp = stamp;
    d.pendingStamp = stamp;
    d.dirty = true;
    this.host.requestRender();
    d.pending = p;
    this.flush();
    if (early) this.prepare();
    return true;
  }

  /**
   * Put the dragged curve's new position into the curve, its fins and the
   * graphs now, between frames (the pointer's raw event: `pointerrawupdate`),
   * so the frame that shows it only renders. Once per frame: when more moves
   * come before the frame, the frame takes the last one itself.
   */
  prepare(): void {
    const d = this.drag;
    if (!d?.dirty || !d.local || this.prepared) return;
    const t0 = performance.now();
    if (this.show(d)) this.prepared = { point: d.handles[d.index]! };
    this.frameSplit.early.push(performance.now() - t0);
  }

  /**
   * Evaluate the dragged curve with its handles as they are and hand curve,
   * fins and (for the selected curve) graphs the result, for the next frame to
   * draw; false when the page does not evaluate this curve (its server
   * analysis follows).
   */
  private show(d: Drag): boolean {
    const analysis = this.evaluate(d);
    if (analysis) {
      this.preview = { label: d.label, analysis, handles: d.handles, until: Infinity };
      if (d.label === this.ed.selected) this.host.updateGraphs();
    }
    this.host.redrawCurve(d.label, d.handles);
    return analysis !== null;
  }

  /** The page's analysis of the dragged curve with its handles as they are (null: not a local drag). */
  private evaluate(d: Drag): Analysis | null {
    const e = this.ed.store.entities.get(d.label);
    const evaluator = d.local && e?.curve ? NurbsEvaluator.of(e.curve, d.handles) : null;
    if (!evaluator) return null;
    const s = this.host.settingsOf(d.label);
    const analysis = analyseNurbs(evaluator, {
      samples: s.samples,
      by: this.host.abscissa === 's' ? 'arclength' : 'parameter',
      fins: s.fins,
      scale: s.scale,
    });
    // Knots stay where they are in t; inflections and extrema wait for the server.
    const before = this.ed.store.analyses.get(d.label) ?? this.preview?.analysis;
    for (const f of before?.features ?? []) {
      if (f.kind !== 'knot') continue;
      const best = nearestIndex(analysis.t, f.t);
      analysis.features.push(analysis.s.length ? { ...f, s: analysis.s[best]! } : { ...f });
    }
    return analysis;
  }

  /**
   * Once per frame during a drag: the curve with the moved point, its fins and
   * graphs, evaluated in the page for a NURBS or Bézier curve (the server's
   * analysis for other kinds follows as it arrives).
   */
  frame(): void {
    const d = this.drag;
    if (!d?.dirty) return;
    d.dirty = false;
    this.frameStart = performance.now();
    // The position prepared when its event came, unless the pointer has moved on since.
    const ready = this.prepared?.point === d.handles[d.index];
    this.prepared = null;
    // Curve, fins and graphs now hold the new position: the frame about to be drawn shows it.
    if (ready || this.show(d)) this.drewDrag = true;
  }

  /** After a frame (at `now`): count a redraw of a new position and the pointer-to-frame latency. */
  frameDrawn(now: number): void {
    if (this.drewDrag) {
      this.drewDrag = false;
      this.dragStats.redraws++;
    }
    if (this.pointerStamp) {
      this.latencies.push(now - this.pointerStamp);
      if (this.frameStart) {
        this.frameSplit.waits.push(this.frameStart - this.pointerStamp);
        this.frameSplit.works.push(now - this.frameStart);
        this.frameStart = 0;
      }
      this.pointerStamp = 0;
    }
  }

  /** The pointer was released: the last position is drawn and stored. */
  end(): void {
    const d = this.drag;
    if (!d) return;
    // The fairing assistant's ghost of the final position is asked for first, the page's own
    // redrawing and storing of that position after.
    this.host.fairing.dragEnded();
    // The last position is drawn even when no frame came between it and the release.
    this.frame();
    this.drag = null;
    this.prepared = null;
    if (d.failed) return; // reverted already
    if (d.pending && !d.inFlight) this.flushOf(d);
    else if (!d.inFlight) this.settled(d);
    this.ed.setStatus(`Moved point ${d.index}`);
    this.host.redrawCurve(d.label);
  }

  get dragging(): boolean {
    return this.drag !== null;
  }

  /** A drag position not yet answered by the server. */
  get pending(): boolean {
    return this.drag !== null && (this.drag.inFlight || this.drag.pending !== null);
  }

  /** What the views and graphs draw for a curve: the drag's preview, else the server's analysis. */
  analysisOf(label: string): Analysis | undefined {
    return this.preview?.label === label
      ? this.preview.analysis
      : this.ed.store.analyses.get(label);
  }

  /** The handles drawn for a curve while a drag holds them (its own, else the last one's), else undefined. */
  handlesOf(label: string): Vec3[] | undefined {
    if (this.drag?.label === label) return this.drag.handles;
    if (this.preview?.label === label) return this.preview.handles;
    return undefined;
  }

  /**
   * The curve `label` as the page holds it: the store's, with the handles of a
   * drag whose final position the store has not fetched yet (the fairing
   * assistant asks for the ghost of this, beside the drag's PATCH).
   */
  heldCurve(label: string): CurveFile | undefined {
    const curve = this.ed.store.entities.get(label)?.curve;
    return curve && this.moved?.label === label ? withHandles(curve, this.moved.handles) : curve;
  }

  /** The server's analysis number `seq` of `label` arrived: it replaces a settled drag's preview. */
  analysisArrived(label: string, seq: number): void {
    const p = this.preview;
    if (p?.label === label && this.drag?.label !== label && seq >= p.until) this.preview = null;
  }

  /** Whether the store's new copy of `label` came with its analysis (a drag's reply); once. */
  takeFresh(label: string): boolean {
    return this.fresh.delete(label);
  }

  /** The document was loaded again: the last drag's handles go unless it is still answered. */
  documentLoaded(): void {
    if (!this.drag && this.settling === null) this.moved = null;
  }

  /** The store holds `label` as the server does, a drag's last move included. */
  entityStored(label: string): void {
    if (this.moved?.label === label && this.settling !== label) this.moved = null;
  }

  /** Send the latest position of the current drag. */
  private flush(): void {
    if (this.drag) this.flushOf(this.drag);
  }

  /** Send `d`'s latest position; one PATCH in flight, `continue` after the first. */
  private flushOf(d: Drag): void {
    if (d.inFlight || !d.pending) return;
    const to = d.pending;
    d.pending = null;
    const stamp = d.pendingStamp;
    d.inFlight = true;
    const continued = !d.first;
    d.first = false;
    this.ed.client
      .movePoints(
        this.ed.store.name,
        d.label,
        [{ index: d.index, to: [...to] }],
        continued,
        this.host.analysisRequest(d.label),
      )
      .then((reply) => {
        this.serverLatencies.push(performance.now() - stamp);
        d.lastReply = reply;
        this.ed.applyReply(reply, d.label);
        // A curve the page cannot evaluate follows through the server's analysis of each move.
        if (!d.local) this.settleFrom(d, false);
      })
      .catch((e: unknown) => {
        this.ed.toast(e);
        d.failed = true;
        d.pending = null;
      })
      .finally(() => {
        d.inFlight = false;
        if (d.failed) this.revert(d);
        else if (d.pending) this.flushOf(d);
        else if (this.drag !== d) this.settled(d);
      });
  }

  /**
   * A move of the drag was not stored: the drag ends here and the curve, its
   * fins and graphs go back to what the server holds (the last stored move of
   * this drag, else the curve before it), visibly, with the status saying so.
   * A later reconnection reloads the document and changes nothing more.
   */
  private revert(d: Drag): void {
    if (this.drag === d) this.drag = null;
    if (this.settling === d.label) this.settling = null;
    if (this.moved?.label === d.label) this.moved = null;
    if (this.preview?.label === d.label) this.preview = null;
    this.pointerStamp = 0;
    // The stored shape: the entity of the last answered move, else the store's (never replaced by the drag).
    if (d.lastReply) this.settleFrom(d, true);
    this.host.redrawCurve(d.label);
    if (d.label === this.ed.selected) this.host.updateGraphs();
    this.ed.setStatus(
      `Point ${d.index} was not moved: the server did not answer; the curve is back as stored`,
      true,
    );
    this.catchUp();
  }

  /**
   * The drag's last move is answered: the curve as the server holds it
   * (refused moves included) and its analysis, with features, replace the
   * preview; panels and history catch up.
   */
  private settled(d: Drag): void {
    if (this.settling === d.label) this.settling = null;
    if (!d.first) {
      if (this.preview?.label === d.label) this.preview.until = this.host.analysisSeq + 1;
      // The stored curve, its analysis with features and the history step, from the last move's
      // reply (no request), once the fairing assistant's ghost of the final position is on screen.
      this.host.fairing.afterGhost(() => {
        this.settleFrom(d, true);
      });
    }
    this.catchUp();
  }

  private catchUp(): void {
    if (this.panelsStale) {
      this.panelsStale = false;
      this.host.updatePanels();
    }
  }

  /**
   * The dragged curve as the last move's reply has it: the entity as the
   * server stores it (refused moves included), its analysis (features and
   * all), and, when the drag is over, its one "move points" history step.
   */
  private settleFrom(d: Drag, over: boolean): void {
    const reply = d.lastReply;
    const raw = reply?.changes.entities?.find((e) => String(e['label']) === d.label);
    if (!reply || !raw) return;
    const store = this.ed.store;
    if (reply.analysis) this.fresh.add(d.label);
    store.put(entityFromServer(raw));
    if (reply.analysis) {
      const by = this.host.abscissa === 's' ? 'arclength' : 'parameter';
      if (this.preview?.label === d.label && this.drag?.label !== d.label) this.preview = null;
      store.setAnalysis(d.label, analysisFromServer(reply.analysis, by));
    }
    if (over && store.history) {
      // The drag is one undo step (PATCH "continue"): undone steps go, the step is the last one.
      const steps = store.history.steps.filter((h) => h.applied !== false);
      steps.push({
        revision: reply.revision,
        name: reply.changes.name ?? 'move points',
        applied: true,
      });
      store.setHistory({ steps });
    }
  }
}
