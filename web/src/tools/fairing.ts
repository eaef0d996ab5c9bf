// The fairing assistant (issue 13 item 6): while the user edits the selected
// curve, a ghost of the faired curve — minimal curvature variation with every
// data point within the tolerance, or knot fairing — is asked of the server
// (POST .../fair-preview, which changes nothing) once the pointer stops, drawn
// dashed with its curvature comb, and its κ graph overlaid on the curve's. `A`
// accepts it: a PUT of the ghost's curve, one undo step. The numerics are the
// server's (studies::fair_within_tolerance); this module only asks and draws.
import { ApiError } from '../api/client';
import { finLines } from '../api/adapt';
import type { Analysis, FairMethod, FairPreview } from '../api/types';
import type { App } from '../app';
import { el } from '../panels/dom';

/** Pause after the last edit before the preview is asked for (the pointer has stopped). */
const DEBOUNCE_MS = 10;
/** The optimisation budget the page asks for, seconds: with the round trip and a frame, ≤ 150 ms. */
const BUDGET_S = 0.08;

export class FairingAssistant {
  enabled = false;
  tolerance = 1;
  method: FairMethod = 'min-variation';
  /** The ghost on screen: for which curve and document revision. */
  preview: { label: string; result: FairPreview } | null = null;
  /** Last pointer move of a drag to the frame that drew the ghost for its final position, ms. */
  readonly latencies: number[] = [];
  /** Per ghost drawn: the preview request's round trip and the server's optimisation time, ms. */
  readonly timings: { roundTripMs: number; serverMs: number }[] = [];
  private timer = 0;
  private inFlight = false;
  private again = false;
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
    window.clearTimeout(this.timer);
    this.timer = 0;
  }

  /** The curve changed (an edit, an undo, another tab) or was selected: ask for a new ghost. */
  edited(label: string | null): void {
    if (!this.enabled || label === null || label !== this.app.selected) {
      if (label === null || label !== this.app.selected) this.clear();
      return;
    }
    window.clearTimeout(this.timer);
    this.timer = window.setTimeout(() => {
      this.timer = 0;
      this.request();
    }, DEBOUNCE_MS);
  }

  /** The ghost's analysis for the graph overlay, when it belongs to the selected curve. */
  get analysis(): Analysis | undefined {
    return this.preview && this.preview.label === this.app.selected
      ? this.preview.result.analysis
      : undefined;
  }

  get busy(): boolean {
    return this.inFlight || this.timer !== 0;
  }

  private request(): void {
    const label = this.app.selected;
    if (!this.enabled || !label || !this.app.store.entities.get(label)?.curve) return;
    if (this.inFlight || this.app.dragPending) {
      this.again = true;
      return;
    }
    this.inFlight = true;
    const s = this.app.settingsOf(label);
    const revision = this.app.store.revision;
    const sent = performance.now();
    void this.app.client
      .fairPreview(this.app.store.name, label, {
        tolerance: this.tolerance,
        method: this.method,
        budget: BUDGET_S,
        analysis: {
          samples: s.samples,
          by: this.app.abscissa === 's' ? 'arclength' : 'parameter',
          fins: ['curvature'],
          scale: s.scale,
          features: false,
        },
      })
      .then((result) => {
        // Only a ghost of the curve as the page has it is drawn (and can be accepted); another
        // revision means an edit came in meanwhile, and `finally` asks again.
        if (
          result.revision !== this.app.store.revision ||
          label !== this.app.selected ||
          !this.enabled
        )
          return;
        this.preview = { label, result };
        this.timings.push({
          roundTripMs: performance.now() - sent,
          serverMs: 1000 * result.seconds,
        });
        this.draw();
      })
      .catch((e: unknown) => {
        this.clear();
        if (!(e instanceof ApiError && (e.offline || e.status === 404))) this.app.toast(e);
      })
      .finally(() => {
        this.inFlight = false;
        if (this.again || this.app.store.revision !== revision) {
          this.again = false;
          this.edited(this.app.selected);
        }
      });
  }

  private pendingLatency = false;

  private draw(): void {
    const p = this.preview!;
    const a = p.result.analysis;
    const comb = a?.combs.curvature;
    const factor = a ? (this.app.finBase(p.label, a).curvature ?? 1) : 1;
    this.app.viewports.setFaired(
      a ? a.points : null,
      comb ? finLines(comb.base, comb.tip, factor) : [],
    );
    this.app.updateGraphs();
    const r = p.result;
    const drop =
      r.energy_before > 0 ? (100 * (r.energy_before - r.energy_after)) / r.energy_before : 0;
    this.readout.textContent =
      `∫κ′² ds ${r.energy_before.toPrecision(4)} → ${r.energy_after.toPrecision(4)} (−${drop.toFixed(1)} %), ` +
      `max deviation ${r.max_deviation.toPrecision(3)} ≤ ${r.tolerance}`;
    this.readout.dataset['before'] = String(r.energy_before);
    this.readout.dataset['after'] = String(r.energy_after);
    this.readout.dataset['revision'] = String(r.revision);
    // The latency clock stops only for the ghost of the last pointer position (no move pending).
    this.pendingLatency = this.lastMove > 0 && !this.app.dragPending;
  }

  private frameDrawn(): void {
    if (!this.pendingLatency) return;
    this.pendingLatency = false;
    const ms = performance.now() - this.lastMove;
    this.lastMove = 0;
    this.latencies.push(ms);
    this.app.viewports.root.dataset['fairLatency'] = ms.toFixed(1);
  }

  /** Hide the ghost. */
  clear(): void {
    window.clearTimeout(this.timer);
    this.timer = 0;
    if (!this.preview) return;
    this.preview = null;
    this.app.viewports.setFaired(null);
    this.readout.textContent = '';
    this.app.updateGraphs();
  }

  /** Replace the curve by the ghost: one "replace curve" undo step. */
  async accept(): Promise<void> {
    const p = this.preview;
    if (!p || p.label !== this.app.selected) {
      this.app.setStatus('Fairing: no ghost to accept (turn the assistant on and edit a curve)');
      return;
    }
    if (p.result.revision !== this.app.store.revision) {
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
