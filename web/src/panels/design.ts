// Design by curvature: drag the κ(s) graph or type κ(s), τ(s); the server
// edits the selected curve (POST …/entities/{label}/curvature-edit,
// studies::edit_curvature) keeping its start, its end point and end tangent
// and, when asked, its end curvatures, and stores a compact curve of the same
// kind as one undo step. The page only sends the profile's change (a
// function of arc length), never a curve.

import type { App } from '../app';
import type { CurvatureEditRequest } from '../api/types';
import type { Graph } from '../graphs/graph';
import { bumpProfile } from '../graphs/scale';

/** Nodes of the piecewise-linear profile law built from samples. */
const NODES = 64;

/**
 * A law of s (docs/formats.md grammar) interpolating (xs, ys) linearly at
 * NODES uniform nodes over [0, length], written as α + β·s + Σ c_i·|s − s_i|
 * over the interior nodes s_i. Why this form: |linear| has a closed-form
 * antiderivative in the law engine, so the server's natural-equation solver
 * gets the exact tangent angle θ(s) = ∫κ ds (eq. 34); a sum of hat functions
 * max(0, 1 − |s − s_i|/h) has none and sent the solver into minutes of
 * adaptive quadrature over the kinks.
 */
export function profileLaw(
  xs: ArrayLike<number>,
  ys: ArrayLike<number>,
  length: number,
  variable = 's',
): string {
  const h = length / (NODES - 1);
  const v: number[] = [];
  let j = 0;
  for (let i = 0; i < NODES; i++) {
    const s = i * h;
    while (j + 1 < xs.length - 1 && xs[j + 1]! < s) j++;
    const x0 = xs[j]!;
    const x1 = xs[Math.min(j + 1, xs.length - 1)]!;
    const y0 = ys[j]!;
    const y1 = ys[Math.min(j + 1, ys.length - 1)]!;
    const f = x1 > x0 ? Math.min(1, Math.max(0, (s - x0) / (x1 - x0))) : 0;
    v.push(Number.isFinite(y0) && Number.isFinite(y1) ? y0 + f * (y1 - y0) : 0);
  }
  // Slopes of the pieces; the slope jumps by 2 c_i at node i.
  const m = v.slice(1).map((vi, i) => (vi - v[i]!) / h);
  const beta = (m[0]! + m[m.length - 1]!) / 2;
  let alpha = v[0]!;
  const terms: string[] = [];
  for (let i = 1; i < NODES - 1; i++) {
    const c = (m[i]! - m[i - 1]!) / 2;
    if (c === 0) continue;
    alpha -= c * i * h; // |0 − s_i| at s = 0
    terms.push(`${c.toPrecision(17)}*abs(${variable} - ${(i * h).toPrecision(17)})`);
  }
  return [alpha.toPrecision(17), `${beta.toPrecision(17)}*${variable}`, ...terms].join(' + ');
}

export class DesignByCurvature {
  private readonly enabled: HTMLInputElement;
  private readonly hold: HTMLSelectElement;
  private readonly kappaInput: HTMLInputElement;
  private readonly tauInput: HTMLInputElement;
  private readonly info: HTMLElement;
  private base: {
    xs: Float64Array;
    ys: Float64Array;
    at: number;
    y0: number;
    edited: Float64Array;
  } | null = null;
  busy = false;
  private graph: Graph | null = null;

  constructor(private readonly app: App) {
    const box = app.panels.designBox;
    box.innerHTML = `
      <div class="row"><label class="inline"><input type="checkbox" id="design-drag" aria-label="Drag the curvature graph to edit the curve"> drag the κ graph</label></div>
      <div class="row"><select id="design-hold" aria-label="What the edited curve keeps at its end">
        <option value="tangent">keep end point + tangent (G1)</option>
        <option value="curvature">keep end point, tangent + curvature (G2)</option>
        <option value="free">keep the start only</option>
      </select></div>
      <div class="row"><input id="design-kappa" aria-label="Curvature profile κ(s)" placeholder="κ(s), e.g. 0.02 + 0.0002*s"></div>
      <div class="row"><input id="design-tau" aria-label="Torsion profile τ(s)" placeholder="τ(s); empty keeps the torsion"></div>
      <div class="row"><button id="design-apply" aria-label="Rebuild the selected curve from the typed profile">Rebuild from profile</button></div>
      <div class="row" id="design-info" aria-live="polite"></div>`;
    this.enabled = box.querySelector('#design-drag')!;
    this.hold = box.querySelector('#design-hold')!;
    this.kappaInput = box.querySelector('#design-kappa')!;
    this.tauInput = box.querySelector('#design-tau')!;
    this.info = box.querySelector('#design-info')!;
    box.querySelector('#design-apply')!.addEventListener('click', () => {
      void this.applyTyped();
    });
    this.enabled.addEventListener('change', () => {
      this.app.graphs[0]!.el.classList.toggle('design', this.enabled.checked);
    });
  }

  attach(graph: Graph): void {
    this.graph = graph;
    graph.onDrag = (phase, x, y) => {
      if (!this.enabled.checked || graph.quantity !== 'kappa' || graph.abscissa !== 's') return;
      this.onDrag(phase, x, y);
    };
  }

  private onDrag(phase: 'start' | 'move' | 'end', x: number, y: number): void {
    const g = this.graph!;
    if (phase === 'start') {
      if (g.xs.length < 2) return;
      this.base = { xs: g.xs.slice(), ys: g.ys.slice(), at: x, y0: y, edited: g.ys.slice() };
      return;
    }
    const b = this.base;
    if (!b) return;
    const length = b.xs[b.xs.length - 1]! - b.xs[0]!;
    b.edited = bumpProfile(b.xs, b.ys, b.at, y - b.y0, length / 6);
    g.setValues(b.edited);
    if (phase === 'end') {
      this.base = null;
      const label = this.app.selected;
      if (!label) return;
      // The change of |κ| the drag asked for (the graph shows |κ|): the server signs it by the
      // side the curve bends to, so an S stays an S.
      const change = b.edited.map((v, i) => v - b.ys[i]!);
      void this.edit(label, { kappa: profileLaw(b.xs, change, length), target: 'change' });
    }
  }

  private async applyTyped(): Promise<void> {
    const label = this.app.selected;
    if (!label || !this.app.store.analyses.get(label)) {
      this.info.textContent = 'Select a curve first.';
      return;
    }
    const tau = this.tauInput.value.trim();
    await this.edit(label, {
      kappa: this.kappaInput.value || '0',
      target: 'curvature',
      ...(tau ? { tau } : {}),
    });
  }

  /** The server edits the stored curve (one undo step) and answers the change and its report. */
  private async edit(label: string, req: CurvatureEditRequest): Promise<void> {
    this.busy = true;
    this.app.setGhost(label);
    try {
      const hold = this.hold.value as NonNullable<CurvatureEditRequest['hold']>;
      const r = await this.app.run(() =>
        this.app.client.curvatureEdit(this.app.store.name, label, { ...req, hold }),
      );
      if (!r) return;
      this.app.applyReply(r);
      const e = r.edit;
      const ends = Math.max(e.end_point_error, e.start_point_error);
      this.info.textContent = `edited: ${e.handles_before} → ${e.handles_after} handles (${e.kind}), ends held to ${ends.toExponential(1)}, inflections ${e.inflections_before} → ${e.inflections_after}`;
      this.info.dataset['handles'] = String(e.handles_after);
    } finally {
      this.busy = false;
    }
  }

  async createNatural(kappa: string, tau: string, length: number): Promise<void> {
    this.busy = true;
    try {
      const r = await this.app.run(() =>
        this.app.client.reconstruct({
          kappa,
          tau,
          length,
          start_point: [0, 0, 0],
          start_frame: { tangent: [1, 0, 0], normal: [0, 1, 0] },
        }),
      );
      if (!r) return;
      await this.app.createCurve('natural', r.curve);
      this.app.fitAll();
    } finally {
      this.busy = false;
    }
  }
}
