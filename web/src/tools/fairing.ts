// The fairing assistant: while the user edits the selected
// curve, a ghost of the faired curve — minimal curvature variation with every
// data point within the tolerance, or knot fairing — is asked of the server
// (POST .../fair-preview, which changes nothing) once the pointer stops, drawn
// dashed with its curvature comb, and its κ graph overlaid on the curve's. `A`
// accepts it: a PUT of the ghost's curve, one undo step. The numerics are the
// server's (studies::fair_within_tolerance); this module only asks and draws.
//
// The request carries the curve as the page holds it (App.heldCurve: a drag's
// latest position included), so the ghost of a drag's final position is asked
// for when the pointer is released (or has rested HOLD_MS while held), beside
// the PATCH that stores that position rather than after its answer: one round
// trip from the pointer stopping to the ghost. A ghost is drawn, and can be
// accepted, only while the page still holds the curve it was computed from.
//
// The ghost comes in two answers: the first with a short optimisation budget
// (FIRST_BUDGET_S), so a faired ghost within the tolerance — the server checks
// every data point's move — is on screen soon after the pointer stops (the
// latency figure is of this one); when the budget, not convergence, ended that
// optimisation, the same curve is asked for again with the full budget
// (BUDGET_S) and its ghost replaces the first, if the page still holds that
// curve. `A` accepts the best ghost there is: while the full-budget answer is
// on the way it waits for it (and takes the first if that request fails).
import { ApiError } from '../api/client';
import { finLines } from '../api/adapt';
import type { Analysis, CurveFile, FairHold, FairMethod, FairPreview } from '../api/types';
import type { App } from '../app';
import { el } from '../panels/dom';

/**
 * A held pointer that has not moved for this long has stopped (pointer events come every
 * 8–17 ms while it moves); a released one has stopped at once.
 */
const HOLD_MS = 20;
/**
 * The first answer's optimisation budget, seconds: with the round trip and a frame, ≤ 150 ms even
 * at a load of 3–4 on two cores (docs/benchmarks.md, "Fairing ghost in two answers").
 */
const FIRST_BUDGET_S = 0.025;
/** The full optimisation budget of the ghost that replaces the first one, seconds. */
const BUDGET_S = 0.08;

/** What a ghost is of: the curve and the assistant's settings (tolerance, method, held ends). */
function ghostKey(curve: CurveFile, tolerance: number, method: FairMethod, hold: FairHold): string {
  return `${tolerance} ${method} ${hold} ${JSON.stringify(curve)}`;
}

export class FairingAssistant {
  enabled = false;
  tolerance = 1;
  method: FairMethod = 'min-variation';
  /** What the ghost keeps at the curve's ends (the server's "hold"). */
  hold: FairHold = 'free';
  /** The ghost on screen: for which curve (label and ghostKey of the curve it fairs). */
  preview: { label: string; key: string; result: FairPreview; final: boolean } | null = null;
  /** Last pointer move of a drag to the frame that drew the ghost for its final position, ms. */
  readonly latencies: number[] = [];
  /** Per first ghost drawn (the latency's): the preview request's round trip and the server's optimisation time, ms. */
  readonly timings: { roundTripMs: number; serverMs: number }[] = [];
  /** Per full-budget ghost that replaced a first one: its round trip and optimisation time, ms. */
  readonly refineTimings: { roundTripMs: number; serverMs: number }[] = [];
  private timer = 0;
  /** The request on the way: what it is the ghost of, and how to call it off. */
  private inFlight: { key: string; abort: AbortController } | null = null;
  /** The full-budget request for the ghost on screen, and its end (whatever the outcome). */
  private refining: { key: string; abort: AbortController; done: Promise<void> } | null = null;
  private lastMove = 0;
  private readonly readout: HTMLElement;
  private readonly toggle: HTMLInputElement;

  constructor(
    private readonly app: App,
    side: HTMLElement,
  ) {
    const d = el('details', { id: 'panel-fairing', open: '' });
    d.appendChild(el('summary', {}, 'Fairing assistant'));
    const body = el('div', { class: 'body' });
    d.appendChild(body);
    // Beside the other design tools, above Optimise.
    side.insertBefore(d, document.getElementById('panel-optimise'));
    this.toggle = el('input', {
      type: 'checkbox',
      id: 'fair-on',
      'aria-label': 'Fairing assistant on',
    });
    const tol = el('input', {
      type: 'number',
      id: 'fair-tolerance',
      min: '0',
      step: 'any',
      value: String(this.tolerance),
      'aria-label': 'Fairing tolerance (model units)',
    });
    const method = el('select', { id: 'fair-method', 'aria-label': 'Fairing method' });
    method.innerHTML =
      '<option value="min-variation">minimal curvature variation</option><option value="knots">knot fairing</option>';
    const hold = el('select', { id: 'fair-hold', 'aria-label': 'Hold ends' });
    hold.innerHTML =
      '<option value="free">free</option><option value="points">end points</option><option value="tangents">end points and tangents</option>';
    const accept = el('button', { type: 'button', id: 'fair-accept' }, 'Accept (A)');
    this.readout = el('div', { id: 'fair-readout', class: 'readout', 'aria-live': 'polite' });
    const row = (label: string, input: HTMLElement): HTMLElement => {
      const l = el('label', {}, label + ' ');
      l.appendChild(input);
      return l;
    };
    body.append(
      row('on', this.toggle),
      row('tolerance', tol),
      row('method', method),
      row('hold ends', hold),
      accept,
      this.readout,
    );
    this.toggle.addEventListener('change', () => {
      this.enabled = this.toggle.checked;
      if (this.enabled) this.edited(this.app.selected);
      else this.clear();
    });
    tol.addEventListener('change', () => {
      const v = Number(tol.value);
      if (Number.isFinite(v) && v > 0) this.tolerance = v;
      this.edited(this.app.selected);
    });
    method.addEventListener('change', () => {
      this.method = method.value as FairMethod;
      this.edited(this.app.selected);
    });
    hold.addEventListener('change', () => {
      this.hold = hold.value as FairHold;
      this.edited(this.app.selected);
    });
    accept.addEventListener('click', () => {
      void this.accept();
    });
    app.viewports.afterFrame.add(() => {
      this.frameDrawn();
    });
  }

  /** The pointer moved a point of the selected curve (the latency clock starts here). */
  pointerMoved(): void {
    this.lastMove = performance.now();
    // A ghost drawn but not yet shown is of the position before this move: its frame is not the
    // one the clock waits for.
    this.pendingLatency = 0;
    if (this.enabled) this.schedule(HOLD_MS);
  }

  /**
   * The pointer was released after a drag: the ghost of its final position is asked for at once,
   * before the page redraws the curve and stores the position (App.endDrag).
   */
  dragEnded(): void {
    if (!this.enabled) return;
    window.clearTimeout(this.timer);
    this.timer = 0;
    this.request();
  }

  /**
   * Run `work` (the page's catching up after a drag: the stored curve, its analysis with
   * features, the history) once the ghost being asked for is on screen, so that its answer and
   * frame do not queue behind it; at once when no ghost is on the way.
   */
  afterGhost(work: () => void): void {
    if (!this.enabled || !this.busy) {
      work();
      return;
    }
    this.deferred.push(work);
  }

  /** The curve changed (an edit, an undo, another tab) or was selected: ask for a new ghost. */
  edited(label: string | null): void {
    if (!this.enabled || label === null || label !== this.app.selected) {
      if (label === null || label !== this.app.selected) this.clear();
      return;
    }
    // While the pointer drags it, the drag's own moves say when (pointerMoved, dragEnded).
    if (!this.app.dragging) this.schedule(0);
  }

  /** The ghost's analysis for the graph overlay, when it belongs to the selected curve. */
  get analysis(): Analysis | undefined {
    return this.preview && this.preview.label === this.app.selected
      ? this.preview.result.analysis
      : undefined;
  }

  get busy(): boolean {
    return this.inFlight !== null || this.timer !== 0 || this.graphsTimer !== 0;
  }

  /** What waits for the ghost to be shown (afterGhost). */
  private deferred: (() => void)[] = [];
  /** The graphs' overlay of a ghost just drawn, updated after the frame that shows it. */
  private graphsTimer = 0;

  private runDeferred(): void {
    const work = this.deferred;
    this.deferred = [];
    for (const w of work) w();
  }

  /** Nothing more is coming for the ghost the page wants: let the deferred work run. */
  private settled(): void {
    if (this.inFlight === null && this.timer === 0 && !this.shownPending) this.runDeferred();
  }

  private schedule(delay: number): void {
    window.clearTimeout(this.timer);
    this.timer = window.setTimeout(() => {
      this.timer = 0;
      this.request();
    }, delay);
  }

  /** The key of the ghost the page wants now: of the selected curve as the page holds it. */
  private wanted(): { label: string; curve: CurveFile; key: string } | null {
    const label = this.app.selected;
    const curve = label ? this.app.heldCurve(label) : undefined;
    if (!this.enabled || !label || !curve) return null;
    return { label, curve, key: ghostKey(curve, this.tolerance, this.method, this.hold) };
  }

  private request(): void {
    const want = this.wanted();
    if (!want) {
      this.settled();
      return;
    }
    if (this.preview?.key === want.key) {
      // The ghost on screen is already of this curve (the drag came back, or the store caught
      // up with the position the ghost was asked for): nothing to ask.
      this.pendingLatency = this.lastMove;
      this.shownPending = true;
      this.app.viewports.requestRender();
      return;
    }
    if (this.inFlight?.key === want.key) return;
    // A request for a curve the page no longer holds is called off (the server's few ms are lost,
    // not the round trip the new ghost would wait behind it).
    this.inFlight?.abort.abort();
    this.refining?.abort.abort();
    this.refining = null;
    const abort = new AbortController();
    const mine = { key: want.key, abort };
    this.inFlight = mine;
    const sent = performance.now();
    void this.ask(want, FIRST_BUDGET_S, abort.signal)
      .then((result) => {
        // Only a ghost of the curve as the page holds it now is drawn (and can be accepted).
        const now = this.wanted();
        if (!now || now.key !== want.key || now.label !== want.label) return;
        this.preview = { label: want.label, key: want.key, result, final: !result.stopped };
        this.timings.push({
          roundTripMs: performance.now() - sent,
          serverMs: 1000 * result.seconds,
        });
        this.draw();
        // The short budget ended the optimisation: the full budget's ghost replaces this one.
        if (result.stopped) this.refine(want);
      })
      .catch((e: unknown) => {
        if (e instanceof DOMException && e.name === 'AbortError') return;
        this.clear();
        if (!(e instanceof ApiError && (e.offline || e.status === 404))) this.app.toast(e);
      })
      .finally(() => {
        if (this.inFlight !== mine) return;
        this.inFlight = null;
        // The curve changed while this one was computed: ask for the current one.
        const now = this.wanted();
        if (now && now.key !== this.preview?.key && this.timer === 0) this.schedule(0);
        else this.settled();
      });
  }

  /** POST .../fair-preview of `want` with the optimisation budget `budget` (seconds). */
  private ask(
    want: { label: string; curve: CurveFile },
    budget: number,
    signal: AbortSignal,
  ): Promise<FairPreview> {
    const s = this.app.settingsOf(want.label);
    return this.app.client.fairPreview(
      this.app.store.name,
      want.label,
      {
        tolerance: this.tolerance,
        method: this.method,
        hold: this.hold,
        budget,
        curve: want.curve,
        analysis: {
          samples: s.samples,
          by: this.app.abscissa === 's' ? 'arclength' : 'parameter',
          fins: ['curvature'],
          scale: s.scale,
          features: false,
        },
      },
      signal,
    );
  }

  /**
   * Ask for the full-budget ghost of the curve whose first ghost is on screen; it replaces that
   * one if the page still holds the curve when it comes (the latency clock has stopped already).
   */
  private refine(want: { label: string; curve: CurveFile; key: string }): void {
    this.refining?.abort.abort();
    const abort = new AbortController();
    const sent = performance.now();
    const mine = { key: want.key, abort, done: Promise.resolve() };
    this.refining = mine;
    mine.done = this.ask(want, BUDGET_S, abort.signal)
      .then((result) => {
        const now = this.wanted();
        const first = this.preview;
        if (!now || now.key !== want.key || first?.key !== want.key) return;
        // The lower energy of the two is the ghost (a starved wall-clock budget could, in principle,
        // get fewer steps done than the short one did).
        const best = result.energy_after <= first.result.energy_after ? result : first.result;
        this.preview = { label: want.label, key: want.key, result: best, final: true };
        this.refineTimings.push({
          roundTripMs: performance.now() - sent,
          serverMs: 1000 * result.seconds,
        });
        this.show();
        // The κ overlay follows the frame (frameDrawn); no pointer move waits for this one.
        this.shownPending = true;
        this.app.viewports.requestRender();
      })
      .catch((e: unknown) => {
        // The first ghost stays (it is within the tolerance too); a failure is reported.
        if (e instanceof DOMException && e.name === 'AbortError') return;
        if (!(e instanceof ApiError && (e.offline || e.status === 404))) this.app.toast(e);
      })
      .finally(() => {
        if (this.refining === mine) this.refining = null;
      });
  }

  /** The pointer move whose ghost the next frame shows (performance.now() of it), or 0. */
  private pendingLatency = 0;

  private draw(): void {
    this.show();
    // The ghost is of the last pointer position (request() drew it only if so): the clock stops at
    // the frame that shows it.
    this.pendingLatency = this.lastMove;
    this.shownPending = true;
  }

  /** Put the ghost on screen (its curve and comb) and its figures in the readout. */
  private show(): void {
    const p = this.preview!;
    const a = p.result.analysis;
    const comb = a?.combs.curvature;
    const factor = a ? (this.app.finBase(p.label, a).curvature ?? 1) : 1;
    this.app.viewports.setFaired(
      a ? a.points : null,
      comb ? finLines(comb.base, comb.tip, factor) : [],
    );
    // The κ overlay follows in the task after the frame that shows the ghost (frameDrawn).
    const r = p.result;
    const drop =
      r.energy_before > 0 ? (100 * (r.energy_before - r.energy_after)) / r.energy_before : 0;
    this.readout.textContent =
      `∫κ′² ds ${r.energy_before.toPrecision(4)} → ${r.energy_after.toPrecision(4)} (−${drop.toFixed(1)} %), ` +
      `max deviation ${r.max_deviation.toPrecision(3)} ≤ ${r.tolerance}`;
    this.readout.dataset['before'] = String(r.energy_before);
    this.readout.dataset['after'] = String(r.energy_after);
    this.readout.dataset['revision'] = String(r.revision);
    this.readout.dataset['final'] = String(p.final);
  }

  /** A ghost was drawn (setFaired) and the frame that shows it has not come yet. */
  private shownPending = false;

  private frameDrawn(): void {
    if (!this.shownPending) return;
    this.shownPending = false;
    if (this.pendingLatency) {
      const ms = performance.now() - this.pendingLatency;
      this.pendingLatency = 0;
      this.lastMove = 0;
      this.latencies.push(ms);
      this.app.viewports.root.dataset['fairLatency'] = ms.toFixed(1);
    }
    // Not in this frame's task: the frame with the ghost is presented first.
    window.clearTimeout(this.graphsTimer);
    this.graphsTimer = window.setTimeout(() => {
      this.graphsTimer = 0;
      this.app.updateGraphs();
      this.settled();
    }, 0);
  }

  /** Hide the ghost. */
  clear(): void {
    window.clearTimeout(this.timer);
    this.timer = 0;
    this.refining?.abort.abort();
    this.refining = null;
    this.runDeferred();
    if (!this.preview) return;
    this.preview = null;
    this.app.viewports.setFaired(null);
    this.readout.textContent = '';
    this.app.updateGraphs();
  }

  /** Replace the curve by the ghost: one "replace curve" undo step. */
  async accept(): Promise<void> {
    // The best ghost there is: the full-budget one when it is on the way for the ghost on screen.
    const first = this.preview;
    if (first && !first.final && this.refining?.key === first.key) await this.refining.done;
    const p = this.preview;
    if (!p || p.label !== this.app.selected) {
      this.app.setStatus('Fairing: no ghost to accept (turn the assistant on and edit a curve)');
      return;
    }
    // The PUT must follow the drag's last PATCH and be of the curve the server now holds.
    const stored = this.app.store.entities.get(p.label)?.curve;
    if (
      this.app.dragPending ||
      this.app.heldCurve(p.label) !== stored ||
      !stored ||
      ghostKey(stored, this.tolerance, this.method, this.hold) !== p.key
    ) {
      this.app.setStatus('Fairing: the ghost is out of date; wait for the new one');
      return;
    }
    this.clear();
    await this.app.replaceCurve(p.label, p.result.curve);
    this.app.setStatus(
      `Faired: ∫κ′² ds ${p.result.energy_before.toPrecision(4)} → ${p.result.energy_after.toPrecision(4)}`,
    );
  }
}
