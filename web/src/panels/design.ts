// Design by curvature: drag the κ(s) graph or type κ(s), τ(s); the curve is
// rebuilt by the server's natural-equation solver (POST /api/reconstruct)
// from the selected curve's start point and frame, and replaces it as one
// undo step. The page only edits the profile (a function), never the curve.

import type { App } from '../app';
import type { Analysis } from '../api/types';
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
      <div class="row"><input id="design-kappa" aria-label="Curvature profile κ(s)" placeholder="κ(s), e.g. 0.02 + 0.0002*s"></div>
      <div class="row"><input id="design-tau" aria-label="Torsion profile τ(s)" placeholder="τ(s), e.g. 0" value="0"></div>
      <div class="row"><button id="design-apply" aria-label="Rebuild the selected curve from the typed profile">Rebuild from profile</button></div>
      <div class="row" id="design-info" aria-live="polite"></div>`;
    this.enabled = box.querySelector('#design-drag')!;
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
      const a = label ? this.app.store.analyses.get(label) : undefined;
      if (!label || !a) return;
      const tau = a.planar
        ? '0'
        : profileLaw(
            a.s,
            a.tau.map((v) => v ?? NaN),
            length,
          );
      void this.rebuild(label, a, profileLaw(b.xs, b.edited, length), tau, length);
    }
  }

  private async applyTyped(): Promise<void> {
    const label = this.app.selected;
    const a = label ? this.app.store.analyses.get(label) : undefined;
    if (!label || !a) {
      this.info.textContent = 'Select a curve first.';
      return;
    }
    const length = a.s[a.s.length - 1]! - a.s[0]!;
    await this.rebuild(label, a, this.kappaInput.value || '0', this.tauInput.value || '0', length);
  }

  /** Rebuild the curve from κ(s), τ(s) at its start point and start frame (initial-value route). */
  private async rebuild(
    label: string,
    a: Analysis,
    kappa: string,
    tau: string,
    length: number,
  ): Promise<void> {
    const p0 = a.points[0]!;
    // The server's start frame. Where N is undefined at the start (κ = 0 there,
    // e.g. a natural spline's end), the nearest sample with a defined N gives
    // the side the curve bends to (made normal to T); the left perpendicular
    // in X-Y, which turned such curves the wrong way, is the last resort.
    const f0 = a.frames[0];
    const tangent =
      f0 && f0.T.every(Number.isFinite) ? f0.T : direction(a.points[0]!, a.points[1]!);
    const bent = a.frames.find((f) => f.N.every(Number.isFinite))?.N;
    const normal = bent ? orthogonalTo(bent, tangent) : null;
    const startNormal = normal ?? perpendicular(tangent);
    this.busy = true;
    this.app.setGhost(label);
    try {
      const r = await this.app.run(() =>
        this.app.client.reconstruct({
          kappa,
          tau,
          length,
          start_point: [p0[0] ?? 0, p0[1] ?? 0, p0[2] ?? 0],
          start_frame: { tangent, normal: startNormal },
          // The fit within 1e-5 of the curve's size (the route's default is 1e-6): few handles
          // to drag, where an absolute 1e-10 gave 2,295 for a 130-long arch.
          fit_tolerance: 1e-5,
        }),
      );
      if (!r) return;
      this.info.textContent = `rebuilt: length ${length.toPrecision(5)}, fit deviation ${r.max_deviation.toExponential(2)}`;
      await this.app.replaceCurve(label, r.curve);
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

function direction(a: number[], b: number[]): number[] {
  const d = [0, 1, 2].map((k) => (b[k] ?? 0) - (a[k] ?? 0));
  const n = Math.hypot(...d) || 1;
  return d.map((x) => x / n);
}

/** The unit part of v normal to the unit vector t, or null when v ∥ t. */
export function orthogonalTo(v: number[], t: number[]): number[] | null {
  const d = [0, 1, 2].reduce((acc, k) => acc + (v[k] ?? 0) * (t[k] ?? 0), 0);
  const w = [0, 1, 2].map((k) => (v[k] ?? 0) - d * (t[k] ?? 0));
  const n = Math.hypot(...w);
  return n > 1e-9 ? w.map((x) => x / n) : null;
}

function perpendicular(t: number[]): number[] {
  // A unit vector normal to t in the plane of t and Z, or Y when t ∥ Z.
  const [x, y] = [t[0] ?? 0, t[1] ?? 0];
  const n = Math.hypot(x, y);
  return n > 1e-9 ? [-y / n, x / n, 0] : [0, 1, 0];
}
