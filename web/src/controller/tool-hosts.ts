// What the Intersect, Knots and Clothoid tools ask of the page (their hosts): picking in
// the views, the markers and preview drawn, the server's answers, the page's
// drag evaluator for the knot preview. The tools themselves hold no page state.

import type { App } from '../app';
import { clothoidThroughPoints } from '../commands/clothoid';
import { intersectCurves } from '../commands/intersect';
import { moveKnotValue } from '../commands/move-knot';
import { NurbsEvaluator } from '../geometry/nurbs';
import type { ClothoidHost } from '../tools/clothoid';
import type { IntersectHost } from '../tools/intersect';
import { parameterOnScreen, type KnotHost, type NurbsFile } from '../tools/knots';
import { pickNearest, projectToScreen, type Vec3, type ViewName } from '../viewport/math';
import { toVec3 } from '../viewport/viewports';

function local(app: App, view: ViewName, ev: PointerEvent): [number, number] {
  const r = app.viewports.view(view).el.getBoundingClientRect();
  return [ev.clientX - r.left, ev.clientY - r.top];
}

/** Set on the views' root for tests: the marked points as "x,y,z" joined by ";" (empty: none). */
function markData(app: App, key: string, points: readonly Vec3[]): void {
  app.viewports.root.dataset[key] = points.map((p) => p.join(',')).join(';');
}

export function intersectHost(app: App): IntersectHost {
  const named = (label: string | null) => (label ? { label, name: app.nameOf(label) } : null);
  return {
    selected: () => named(app.selected),
    pick: (view, ev) => {
      const hit = app.input.pickCurve(view, ev);
      if (hit) app.select(hit.label);
      return named(hit?.label ?? null);
    },
    mark: (points) => {
      app.viewports.setPreview([], points);
      markData(app, 'intersections', points);
    },
    run: (a, b) => intersectCurves(app.editor, a, b),
    status: (t, error) => {
      app.setStatus(t, error);
    },
  };
}

export function knotHost(app: App): KnotHost {
  return {
    target: () => {
      const label = app.selected;
      if (!label || app.isHidden(label) || app.isLocked(label)) return null;
      const curve = app.store.entities.get(label)?.curve;
      return curve?.kind === 'nurbs' ? { label, name: app.nameOf(label), curve } : null;
    },
    pick: (view, ev) => {
      const label = app.input.pickCurve(view, ev)?.label ?? null;
      app.select(label);
      return label;
    },
    pointsAt: async (label, us) => {
      const a = await app.run(
        () =>
          app.client.analysis(app.store.name, label, {
            samples: us.length,
            by: 'parameter',
            features: false,
            at: [...us],
          }),
        'Knot markers',
      );
      return a?.points.map(toVec3);
    },
    evaluate: (curve: NurbsFile, us) => {
      const e = NurbsEvaluator.of(curve);
      if (!e) return [];
      const out = new Float64Array(3);
      return us.map((u) => {
        e.derivatives(u, 0, out);
        return [out[0]!, out[1]!, out[2]!] as Vec3;
      });
    },
    markerAt: (view, ev, markers) => {
      const { w, h } = app.viewports.size(view);
      return (
        pickNearest(local(app, view, ev), markers, app.viewports.viewProj(view), w, h, 8)?.index ??
        null
      );
    },
    parameterAt: (view, ev, points, t) => {
      const { w, h } = app.viewports.size(view);
      const vp = app.viewports.viewProj(view);
      const screen = points.map((p) => projectToScreen(p, vp, w, h));
      return parameterOnScreen(local(app, view, ev), screen, t, 40);
    },
    show: (curve, markers) => {
      app.viewports.setPreview(curve, markers);
      markData(app, 'knots', markers);
    },
    onRelease: (done) => {
      window.addEventListener('pointerup', done, { once: true });
    },
    commit: (label, knots, from, to) => moveKnotValue(app.editor, label, knots, from, to),
    status: (t, error) => {
      app.setStatus(t, error);
    },
  };
}

export function clothoidHost(app: App): ClothoidHost {
  return {
    pointAt: (view, ev) => app.pointAt(view, ev),
    preview: (pts) => {
      app.viewports.setPreview(pts);
    },
    status: (t, error) => {
      app.setStatus(t, error);
    },
    make: async (points, choice) => {
      await clothoidThroughPoints(
        app.editor,
        points.map((p) => [...p]),
        choice,
      );
    },
  };
}
