// The viewport controller: what the pointer does in the views (after
// three.js's editor, whose Viewport turns pointer events into selection and
// transforms). It picks (a handle of the selected curve to drag, else the
// nearest curve to select), turns the pointer into a point on the working or
// drag plane, snaps it (objects, grid), navigates (pan, orbit, zoom) and
// shows the hover readout; the drag itself is DragController's.

import type { Analysis } from '../api/types';
import type { Editor } from '../editor/editor';
import { readout, type Abscissa } from '../graphs/graph';
import { handlesOf } from '../store/curves';
import type { ViewStore } from '../store/view';
import type { Tool } from '../tools/tools';
import type { CurvePick } from '../tools/join';
import {
  dragPlane,
  pickNearest,
  pickPolyline,
  workingPlane,
  type Vec3,
  type ViewName,
  type WorkingPlane,
} from '../viewport/math';
import { toVec3, type Viewports } from '../viewport/viewports';
import type { DragController } from './drag';
import { snapPoint, snapTargets, type SnapHit } from './snap';

/** What the controller asks of the page around it (the App). */
export interface ViewportHost {
  readonly viewports: Viewports;
  readonly editor: Editor;
  readonly drags: DragController;
  /** The drawing tool in use, or null for select. */
  readonly tool: Tool | null;
  readonly abscissa: Abscissa;
  /** The snap toggles. */
  readonly view: ViewStore;
  select(label: string | null): void;
  /** A sample of the selected curve is hovered on it (the graphs follow). */
  hoverSample(index: number | null): void;
}

export class ViewportController {
  private navigating: { view: ViewName; x: number; y: number; mode: 'pan' | 'orbit' } | null = null;
  /** The hover readout at the cursor on the curve (s or t, κ, R, τ). */
  private readonly curveReadout: HTMLElement;

  constructor(private readonly host: ViewportHost) {
    this.curveReadout = document.createElement('div');
    this.curveReadout.className = 'readout curve-readout';
    this.curveReadout.dataset['readout'] = 'curve';
    this.curveReadout.hidden = true;
    this.viewports.root.appendChild(this.curveReadout);
  }

  private get viewports(): Viewports {
    return this.host.viewports;
  }
  private get editor(): Editor {
    return this.host.editor;
  }
  private get drags(): DragController {
    return this.host.drags;
  }
  private get tool(): Tool | null {
    return this.host.tool;
  }
  private get store(): Editor['store'] {
    return this.host.editor.store;
  }
  private get selected(): string | null {
    return this.host.editor.selected;
  }
  private get abscissa(): Abscissa {
    return this.host.abscissa;
  }
  private isHidden(label: string): boolean {
    return this.editor.isHidden(label);
  }
  private isLocked(label: string): boolean {
    return this.editor.isLocked(label);
  }
  private analysisOf(label: string): Analysis | undefined {
    return this.drags.analysisOf(label);
  }
  private setStatus(text: string, error = false): void {
    this.editor.setStatus(text, error);
  }
  private nameOf(label: string): string {
    return this.editor.nameOf(label);
  }

  /** Snap to existing points and curves (toggle "Objects", Shift+G): the view store's. */
  get objectSnap(): boolean {
    return this.host.view.objectSnap;
  }

  /** What the last snapped point landed on, for the status line and tests. */
  lastSnap: SnapHit = null;

  /**
   * A point of `plane` (the pointer's, or a dragged handle's) snapped as the toggles ask: with object
   * snap, onto the nearest handle of a visible curve, else the nearest point of a visible curve as
   * drawn, within 8 pixels (`exclude`: the handle being dragged and its curve's polyline, which move
   * with it); else onto the grid when grid snap is on; else as it is.
   */
  snapPoint(
    view: ViewName,
    p: Vec3,
    plane: WorkingPlane,
    exclude?: { label: string; index: number },
  ): Vec3 {
    const { w, h } = this.viewports.size(view);
    const { point, hit } = snapPoint(
      p,
      {
        w,
        h,
        viewProj: this.viewports.viewProj(view),
        grid: this.host.view.snap,
        onPlane: (q) => this.viewports.snapped(view, q, plane),
      },
      this.objectSnap,
      () =>
        snapTargets(
          this.store.entities,
          (l) => this.isHidden(l),
          (l) => this.analysisOf(l)?.points,
          exclude,
        ),
    );
    this.lastSnap = hit;
    return point;
  }

  private local(view: ViewName, ev: PointerEvent | MouseEvent): [number, number] {
    const r = this.viewports.view(view).el.getBoundingClientRect();
    return [ev.clientX - r.left, ev.clientY - r.top];
  }

  pointAt(view: ViewName, ev: PointerEvent): Vec3 | null {
    const [x, y] = this.local(view, ev);
    const plane = workingPlane(view);
    const p = this.viewports.pointOn(view, x, y, plane, false);
    return p && this.snapPoint(view, p, plane);
  }

  /** Listen to the pointer on every view. */
  bind(): void {
    for (const v of this.viewports.views) {
      const el = v.el;
      el.addEventListener('contextmenu', (ev) => {
        ev.preventDefault();
      });
      el.addEventListener('pointerdown', (ev) => {
        el.focus();
        this.viewports.active = v.name;
        if (
          ev.button === 1 ||
          (ev.button === 0 && (ev.shiftKey || ev.altKey)) ||
          (ev.button === 0 && this.navMode)
        ) {
          const mode = ev.altKey || this.navMode === 'orbit' ? 'orbit' : 'pan';
          this.navigating = { view: v.name, x: ev.clientX, y: ev.clientY, mode };
          el.setPointerCapture(ev.pointerId);
          return;
        }
        if (ev.button === 2) {
          this.tool?.rightClick(v.name, ev);
          if (!this.tool && this.navMode) this.navMode = null;
          return;
        }
        if (ev.button !== 0) return;
        if (this.tool) {
          this.tool.click(v.name, ev);
          return;
        }
        this.selectOrDrag(v.name, ev);
        if (this.drags.dragging) el.setPointerCapture(ev.pointerId);
      });
      el.addEventListener('pointermove', (ev) => {
        if (this.navigating) {
          const dx = ev.clientX - this.navigating.x;
          const dy = ev.clientY - this.navigating.y;
          this.navigating.x = ev.clientX;
          this.navigating.y = ev.clientY;
          if (this.navigating.mode === 'orbit' && v.name === 'persp')
            this.viewports.orbit(v.name, dx, dy);
          else this.viewports.pan(v.name, dx, dy);
          return;
        }
        if (this.drags.dragging) {
          // Where the browser sends raw pointer updates, the drag follows those instead.
          if (!this.rawUpdates) this.dragTo(v.name, ev);
          return;
        }
        if (this.tool) {
          this.tool.move(v.name, ev);
          return;
        }
        this.hoverCurve(v.name, ev);
      });
      // A drag takes each move as it comes (`pointerrawupdate`, not aligned to frames as
      // `pointermove` is): the moved curve is evaluated before the frame that draws it.
      el.addEventListener('pointerrawupdate', (ev) => {
        if (!(ev instanceof PointerEvent) || this.navigating || !this.drags.dragging) return;
        this.rawUpdates = true;
        this.dragTo(v.name, ev, true);
      });
      const up = (ev: PointerEvent): void => {
        if (this.navigating) {
          this.navigating = null;
          return;
        }
        if (this.drags.dragging && ev.button === 0) this.drags.end();
      };
      el.addEventListener('pointerup', up);
      el.addEventListener('pointercancel', up);
      el.addEventListener(
        'wheel',
        (ev) => {
          ev.preventDefault();
          this.viewports.zoom(v.name, Math.exp(ev.deltaY * 0.0015));
        },
        { passive: false },
      );
    }
  }

  navMode: 'pan' | 'orbit' | null = null;

  private selectOrDrag(view: ViewName, ev: PointerEvent): void {
    const [x, y] = this.local(view, ev);
    const { w, h } = this.viewports.size(view);
    const vp = this.viewports.viewProj(view);
    // A handle of the selected curve first (drag), then any curve (select).
    if (this.selected && !this.isHidden(this.selected)) {
      // The last drag's points until the server's copy of the curve is back.
      const handles =
        this.drags.preview?.label === this.selected
          ? this.drags.preview.handles
          : handlesOf(this.store.entities.get(this.selected)?.curve);
      const hit = pickNearest([x, y], handles, vp, w, h, 8);
      if (hit && this.isLocked(this.selected)) {
        this.setStatus(
          `${this.nameOf(this.selected)} is locked: unlock it in the object list`,
          true,
        );
        return;
      }
      if (hit) {
        const h0 = handles[hit.index]!;
        const at = this.viewports.pointOn(view, x, y, dragPlane(view, h0), false);
        const grab: Vec3 = at ? [h0[0] - at[0], h0[1] - at[1], h0[2] - at[2]] : [0, 0, 0];
        this.drags.start(this.selected, hit.index, handles, grab);
        this.setStatus(`Dragging point ${hit.index}`);
        return;
      }
    }
    let best: { label: string; d: number } | null = null;
    for (const [label, a] of this.store.analyses) {
      if (this.isHidden(label) || this.isLocked(label)) continue;
      const hit = pickPolyline([x, y], a.points.map(toVec3), vp, w, h, 6);
      if (hit && (!best || hit.distance < best.d)) best = { label, d: hit.distance };
    }
    this.host.select(best?.label ?? null);
  }

  /**
   * The visible curve nearest the pointer within 8 pixels (Match and Blend pick ends with it): its nearest
   * sample, and the end whose drawn point is within 12 pixels of the pointer, if one is.
   */
  pickCurve(view: ViewName, ev: PointerEvent): CurvePick | null {
    const [x, y] = this.local(view, ev);
    const { w, h } = this.viewports.size(view);
    const vp = this.viewports.viewProj(view);
    let best: { label: string; a: Analysis; index: number; d: number } | null = null;
    for (const [label, a] of this.store.analyses) {
      if (this.isHidden(label) || !this.store.entities.has(label)) continue;
      const hit = pickPolyline([x, y], a.points.map(toVec3), vp, w, h, 8);
      if (hit && (!best || hit.distance < best.d))
        best = { label, a, index: hit.index, d: hit.distance };
    }
    if (!best) return null;
    const points = best.a.points.map(toVec3);
    const last = points.length - 1;
    const ends = pickNearest([x, y], [points[0]!, points[last]!], vp, w, h, 12);
    const nearerEnd = best.index * 2 < last ? 'start' : 'end';
    const end = ends === null ? null : ends.index === 0 ? 'start' : 'end';
    return {
      label: best.label,
      t: best.a.t[best.index]!,
      point: points[best.index]!,
      end,
      endPoint: points[(end ?? nearerEnd) === 'start' ? 0 : last]!,
      nearerEnd,
    };
  }

  private hoverCurve(view: ViewName, ev: PointerEvent): void {
    if (!this.selected) return;
    const a = this.store.analyses.get(this.selected);
    if (!a) return;
    const [x, y] = this.local(view, ev);
    const { w, h } = this.viewports.size(view);
    const hit = pickPolyline([x, y], a.points.map(toVec3), this.viewports.viewProj(view), w, h, 8);
    if ((hit?.index ?? null) !== this.editor.hovered) this.host.hoverSample(hit?.index ?? null);
    // The readout follows the cursor on the curve.
    const box = this.viewports.root.getBoundingClientRect();
    this.readoutAt = hit ? [ev.clientX - box.left + 14, ev.clientY - box.top + 10] : null;
    this.placeReadout();
  }

  /** Where the curve's hover readout is drawn (view-root pixels), or null off the curve. */
  private readoutAt: [number, number] | null = null;

  /** Draw the hover readout at the cursor (after a hover from a graph, `fromGraph`: hidden). */
  placeReadout(fromGraph = false): void {
    if (fromGraph) this.readoutAt = null;
    const el = this.curveReadout;
    const a = this.selected ? this.store.analyses.get(this.selected) : undefined;
    const i = this.editor.hovered;
    if (!this.readoutAt || !a || i === null || i >= a.t.length) {
      el.hidden = true;
      return;
    }
    el.hidden = false;
    el.textContent = readout(a, i, this.abscissa);
    el.style.left = `${this.readoutAt[0]}px`;
    el.style.top = `${this.readoutAt[1]}px`;
  }

  /**
   * Move the dragged point on the plane through it parallel to the view. The
   * next frame draws it, and the server hears of it (DragController.moveTo).
   */
  /** The browser sends `pointerrawupdate` (seen once): drags follow those, not `pointermove`. */
  private rawUpdates = false;

  private dragTo(view: ViewName, ev: PointerEvent, early = false): void {
    const d = this.drags.drag!;
    const [x, y] = this.local(view, ev);
    const start = d.handles[d.index]!;
    const plane = dragPlane(view, start);
    const at = this.viewports.pointOn(view, x, y, plane, false);
    const g = d.grab;
    const p = at
      ? this.snapPoint(view, [at[0] + g[0], at[1] + g[1], at[2] + g[2]], plane, {
          label: d.label,
          index: d.index,
        })
      : null;
    this.drags.moveTo(p, ev.timeStamp, early);
  }
}
