// The linked graphs (κ, radius, τ, speed, log κ, log τ against t or s) drawn
// with uPlot from the server's analysis, with min/max/inflection markers and
// hover linking; the κ graph can be dragged to design by curvature.

import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import type { Analysis } from '../api/types';
import {
  boxDiagonal,
  finiteExtent,
  logMagnitude,
  nearestIndex,
  paddedRange,
  radius,
  spanFloor,
  SPAN_FLOOR_FRACTION,
  tickLabels,
  type Range,
} from './scale';

export type Quantity = 'kappa' | 'radius' | 'tau' | 'speed' | 'logkappa' | 'logtau';
export type Abscissa = 't' | 's';

export const QUANTITY_LABELS: Record<Quantity, string> = {
  kappa: 'curvature κ',
  radius: 'radius 1/κ',
  tau: 'torsion τ',
  speed: 'speed |C′|',
  logkappa: 'log10 |κ|',
  logtau: 'log10 |τ|',
};

function nums(xs: readonly (number | null)[]): Float64Array {
  const out = new Float64Array(xs.length);
  xs.forEach((v, i) => (out[i] = v ?? NaN));
  return out;
}

/** The plotted values of a quantity from an analysis (no geometry: a change of units). */
export function quantityValues(a: Analysis, q: Quantity): Float64Array {
  switch (q) {
    case 'kappa':
      return nums(a.kappa);
    case 'radius':
      return radius(nums(a.kappa));
    case 'tau':
      return nums(a.tau);
    case 'speed':
      return nums(a.speed);
    case 'logkappa':
      return logMagnitude(nums(a.kappa));
    case 'logtau':
      return logMagnitude(nums(a.tau));
  }
}

/**
 * The least span of a quantity's value axis (paddedRange's `minSpan`), so the
 * rounding noise of a straight line's or a circle's κ is not stretched to the
 * graph's height: κ and τ are floored by a fraction of max(max |v|, 1/size),
 * size the curve's bounding-box diagonal; radius and speed by a fraction of
 * their largest value; the log graphs by the same fraction of |κ| in decades.
 */
export function valueFloor(q: Quantity, values: ArrayLike<number>, size: number): number {
  switch (q) {
    case 'kappa':
    case 'tau':
      return spanFloor(values, size > 0 ? 1 / size : 0);
    case 'radius':
    case 'speed':
      return spanFloor(values);
    case 'logkappa':
    case 'logtau':
      return Math.log10(1 + SPAN_FLOOR_FRACTION);
  }
}

/** max − min of the finite values (0 for none). */
export function spanOf(values: ArrayLike<number>): number {
  const extent = finiteExtent(values);
  return extent ? extent.max - extent.min : 0;
}

export interface Marker {
  x: number;
  y: number;
  kind: string;
}

/** Which of the server's features a graph marks: its own quantity's extrema, and the knots. */
export function ownsFeature(q: Quantity, kind: string): boolean {
  if (kind === 'knot') return true;
  switch (q) {
    case 'tau':
    case 'logtau':
      return kind.startsWith('torsion-');
    case 'kappa':
    case 'logkappa':
    case 'radius':
      // Inflections are where κ changes sign: a κ feature, not a τ one.
      return kind.startsWith('curvature-') || kind === 'inflection';
    case 'speed':
      return false;
  }
}

/**
 * The markers of a graph: the features it owns (ownsFeature) at their
 * abscissa (s or t as plotted), at the plotted value of the nearest sample;
 * one marker per kind and sample (a feature the server lists twice, or two
 * that fall on one sample, is drawn once).
 */
export function graphMarkers(
  a: Analysis,
  q: Quantity,
  abscissa: Abscissa,
  xs: Float64Array,
  ys: Float64Array,
): Marker[] {
  const byS = abscissa === 's' && a.s.length === a.t.length;
  const seen = new Set<string>();
  const out: Marker[] = [];
  for (const f of a.features) {
    if (!ownsFeature(q, f.kind)) continue;
    const x = byS ? (f.s ?? NaN) : f.t;
    if (!Number.isFinite(x) || xs.length === 0) continue;
    const i = nearestIndex(xs, x);
    const k = `${f.kind}@${i}`;
    if (seen.has(k)) continue;
    seen.add(k);
    out.push({ x, y: ys[i]!, kind: f.kind });
  }
  return out;
}

const fmt = (v: number | null | undefined): string =>
  v === null || v === undefined || !Number.isFinite(v) ? '—' : String(Number(v.toPrecision(4)));

/**
 * The hover readout of sample `i`: the abscissa as plotted (s or t), κ, the
 * radius 1/|κ| and τ, e.g. "s = 12.5 · κ = 0.0123 · R = 81.3 · τ = 0".
 */
export function readout(a: Analysis, i: number, abscissa: Abscissa): string {
  const byS = abscissa === 's' && a.s.length === a.t.length;
  const x = byS ? a.s[i] : a.t[i];
  const k = a.kappa[i];
  const r = k === null || k === undefined || k === 0 ? null : 1 / Math.abs(k);
  return `${byS ? 's' : 't'} = ${fmt(x)} · κ = ${fmt(k)} · R = ${r === null ? '∞' : fmt(r)} · τ = ${fmt(a.tau[i])}`;
}

/** What a graph's overlay is: the curve before the last edit, or the fairing assistant's ghost. */
export type OverlayKind = 'before' | 'faired';

/** Set an attribute unless it already has that value (no style invalidation for nothing). */
function setAttr(el: HTMLElement, name: string, value: string): void {
  if (el.getAttribute(name) !== value) el.setAttribute(name, value);
}

export class Graph {
  readonly el: HTMLElement;
  private plot: uPlot | null = null;
  quantity: Quantity;
  abscissa: Abscissa = 's';
  xs: Float64Array = new Float64Array();
  ys: Float64Array = new Float64Array();
  overlay: Float64Array | null = null;
  markers: Marker[] = [];
  /** Hover on the graph: the sample index, or null when the pointer leaves. */
  onHover: ((index: number | null) => void) | null = null;
  /** Drag on the graph (design by curvature): abscissa and value at the pointer. */
  onDrag: ((phase: 'start' | 'move' | 'end', x: number, y: number) => void) | null = null;
  private yRange: Range = { min: 0, max: 1 };
  /** The curve's size (bounding-box diagonal of the shown analysis), for valueFloor. */
  private size = 0;
  private dragging = false;
  private plotShape = '';

  constructor(
    parent: HTMLElement,
    quantity: Quantity,
    readonly id: string,
  ) {
    this.quantity = quantity;
    this.el = document.createElement('div');
    this.el.className = 'graph';
    this.el.dataset['graph'] = id;
    this.el.setAttribute('role', 'img');
    parent.appendChild(this.el);
    this.readoutEl = document.createElement('div');
    this.readoutEl.className = 'readout';
    this.readoutEl.dataset['readout'] = id;
    this.readoutEl.setAttribute('aria-live', 'off');
    parent.appendChild(this.readoutEl);
    new ResizeObserver(() => {
      this.plot?.setSize(this.sizeOf());
    }).observe(this.el);
  }

  private sizeOf(): { width: number; height: number } {
    return {
      width: Math.max(120, this.el.clientWidth),
      height: Math.max(80, this.el.clientHeight - 4),
    };
  }

  /** The analysis shown (for the hover readout). */
  private shown: Analysis | undefined;
  private overlayKind: OverlayKind = 'before';
  /** The readout line under the graph's selectors (hover). */
  readonly readoutEl: HTMLElement;

  /**
   * Show an analysis, and optionally an overlay series: the curve before the
   * last edit (grey, solid, as its ghost in the views) or the fairing
   * assistant's ghost (green, dashed, as in the views).
   */
  show(a: Analysis | undefined, overlay?: Analysis, overlayKind: OverlayKind = 'before'): void {
    this.shown = a;
    this.overlayKind = overlayKind;
    if (!a) {
      this.xs = new Float64Array();
      this.ys = new Float64Array();
    } else {
      this.xs = Float64Array.from(this.abscissa === 's' && a.s.length === a.t.length ? a.s : a.t);
      this.ys = quantityValues(a, this.quantity);
      this.size = boxDiagonal(a.points);
    }
    this.overlay = null;
    if (a && overlay && overlay.points.length > 0) {
      // Overlay on the same abscissa range: resampled by index onto the main xs.
      const oy = quantityValues(overlay, this.quantity);
      const ox = Float64Array.from(
        this.abscissa === 's' && overlay.s.length === overlay.t.length ? overlay.s : overlay.t,
      );
      const scaleX =
        (ox[ox.length - 1]! - ox[0]!) / (this.xs[this.xs.length - 1]! - this.xs[0]! || 1);
      this.overlay = this.xs.map((x) => oy[nearestIndex(ox, ox[0]! + (x - this.xs[0]!) * scaleX)]!);
    }
    this.markers = a ? graphMarkers(a, this.quantity, this.abscissa, this.xs, this.ys) : [];
    // Written only when they change: a drag shows a new analysis every frame, with the same ones.
    setAttr(this.el, 'data-markers', this.markers.map((m) => m.kind).join(' '));
    setAttr(this.el, 'data-overlay', this.overlay ? overlayKind : '');
    setAttr(this.el, 'aria-label', `${QUANTITY_LABELS[this.quantity]} against ${this.plotted}`);
    setAttr(this.el, 'data-samples', String(this.xs.length));
    this.redraw();
  }

  /** Replace the plotted values only (live profile editing). */
  setValues(ys: Float64Array): void {
    this.ys = ys;
    this.redraw();
  }

  private redraw(): void {
    // The value axis stays put while the graph is dragged: rescaling it under
    // the pointer made each move read a larger value than the last (the edit
    // ran away: a 0.01 pull set κ 0.06 higher). It refits on the next show().
    if (!this.dragging) {
      let ys = this.ys;
      if (this.overlay) {
        ys = new Float64Array(this.ys.length + this.overlay.length);
        ys.set(this.ys);
        ys.set(this.overlay, this.ys.length);
      }
      this.yRange = paddedRange(ys, 0.05, valueFloor(this.quantity, ys, this.size));
    }
    const data: uPlot.AlignedData = [this.xs, this.ys, ...(this.overlay ? [this.overlay] : [])];
    const seriesCount = this.overlay ? 3 : 2;
    // A new abscissa, quantity or overlay kind rebuilds the plot (its axis label and series styles).
    const shape = `${seriesCount} ${this.plotted} ${this.quantity} ${this.overlayKind}`;
    if (this.plot && this.plotShape === shape) {
      // Drawn now, not in uPlot's microtask after the caller's task: a drag's frame shows the
      // graph with the curve, and the frame's clock (DragController.frameDrawn) includes it.
      const plot = this.plot;
      plot.batch(() => {
        plot.setData(data);
      });
      return;
    }
    this.plotShape = shape;
    this.plot?.destroy();
    this.plot = new uPlot(this.options(seriesCount), data, this.el);
    this.attachDrag();
  }

  private options(seriesCount: number): uPlot.Options {
    const series: uPlot.Series[] = [
      { label: this.plotted },
      { label: QUANTITY_LABELS[this.quantity], stroke: '#d64bd6', width: 1.5, spanGaps: false },
    ];
    // One meaning per line style: grey solid is the curve before the edit (its ghost in the views),
    // green dashed the fairing assistant's ghost (dashed green in the views).
    if (seriesCount === 3)
      series.push(
        this.overlayKind === 'faired'
          ? { label: 'faired', stroke: '#7fe3a0', width: 1, dash: [4, 3] }
          : { label: 'before', stroke: 'rgba(200, 210, 224, 0.55)', width: 1 },
      );
    return {
      ...this.sizeOf(),
      legend: { show: false },
      scales: {
        x: { time: false },
        y: { range: () => [this.yRange.min, this.yRange.max] },
      },
      // Tick labels with the digits their spacing needs (tickLabels): uPlot's default keeps three
      // decimals, so a torsion axis over [0.0020, 0.0025] read "0.002" at several ticks.
      axes: [
        {
          stroke: '#aab4c3',
          grid: { stroke: '#2b323d' },
          label: this.plotted === 's' ? 'arc length s' : 'parameter t',
          labelSize: 14,
          size: 30,
          values: (_u, splits) => tickLabels(splits),
        },
        {
          stroke: '#aab4c3',
          grid: { stroke: '#2b323d' },
          values: (_u, splits) => tickLabels(splits),
          // Wide enough for the longest label: 8 px a character (DejaVu Sans digits at uPlot's 12 px
          // font are 7.6 px) plus the tick (10 px) and gap (5 px); uPlot asks once with null before
          // the labels exist (its typings omit the null).
          size: (_u, values: string[] | null) =>
            Math.max(50, 16 + 8 * Math.max(0, ...(values ?? []).map((v) => v.length))),
        },
      ],
      series,
      cursor: { drag: { x: false, y: false }, points: { size: 6 } },
      hooks: {
        setCursor: [
          (u) => {
            if (this.dragging) return;
            const i = u.cursor.idx;
            this.onHover?.(i ?? null);
            this.showReadout(i ?? null);
          },
        ],
        draw: [
          (u) => {
            this.drawMarkers(u);
          },
        ],
      },
    };
  }

  private drawMarkers(u: uPlot): void {
    const ctx = u.ctx;
    ctx.save();
    for (const m of this.markers) {
      if (!Number.isFinite(m.y)) continue;
      const x = u.valToPos(m.x, 'x', true);
      const y = u.valToPos(m.y, 'y', true);
      ctx.fillStyle =
        m.kind === 'inflection'
          ? '#ffe14d'
          : m.kind.endsWith('max')
            ? '#ff6b6b'
            : m.kind.endsWith('min')
              ? '#4da3ff'
              : '#aab4c3';
      ctx.beginPath();
      if (m.kind === 'knot') ctx.rect(x - 3, u.bbox.top + u.bbox.height - 6, 6, 6);
      else ctx.arc(x, y, 4 * devicePixelRatio, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.restore();
  }

  private attachDrag(): void {
    const over = this.plot?.over;
    if (!over) return;
    const at = (ev: PointerEvent): [number, number] => {
      const r = over.getBoundingClientRect();
      return [
        this.plot!.posToVal(ev.clientX - r.left, 'x'),
        this.plot!.posToVal(ev.clientY - r.top, 'y'),
      ];
    };
    over.addEventListener('pointerdown', (ev) => {
      if (!this.onDrag || ev.button !== 0) return;
      this.dragging = true;
      over.setPointerCapture(ev.pointerId);
      this.onDrag('start', ...at(ev));
    });
    over.addEventListener('pointermove', (ev) => {
      if (this.dragging) this.onDrag?.('move', ...at(ev));
    });
    const end = (ev: PointerEvent): void => {
      if (!this.dragging) return;
      this.onDrag?.('end', ...at(ev));
      this.dragging = false;
    };
    over.addEventListener('pointerup', end);
    over.addEventListener('pointercancel', end);
  }

  /** The label the plot draws under its abscissa axis (what the user reads). */
  get xAxisLabel(): string | undefined {
    const label = this.plot?.axes[0]?.label;
    return typeof label === 'string' ? label : undefined;
  }

  /** The abscissa as plotted: s when asked and the analysis has it, else t. */
  get plotted(): Abscissa {
    const a = this.shown;
    return this.abscissa === 's' && (!a || a.s.length === a.t.length) ? 's' : 't';
  }

  /** The readout of a sample (hover), or none. */
  showReadout(index: number | null): void {
    const a = this.shown;
    this.readoutEl.textContent =
      a && index !== null && index < a.t.length ? readout(a, index, this.abscissa) : '';
  }

  /** Show the cursor at a sample (hover on the curve). */
  highlight(index: number | null): void {
    this.showReadout(index);
    if (!this.plot) return;
    if (index === null || index >= this.xs.length) {
      this.plot.setCursor({ left: -10, top: -10 }, false);
      return;
    }
    const left = this.plot.valToPos(this.xs[index]!, 'x');
    const top = Number.isFinite(this.ys[index]) ? this.plot.valToPos(this.ys[index]!, 'y') : 0;
    this.plot.setCursor({ left, top }, false);
  }

  /** Pixel position of a value pair inside the plotting area (tests, drag). */
  toPixels(x: number, y: number): { left: number; top: number } | null {
    if (!this.plot) return null;
    const r = this.plot.over.getBoundingClientRect();
    return { left: r.left + this.plot.valToPos(x, 'x'), top: r.top + this.plot.valToPos(y, 'y') };
  }
}
