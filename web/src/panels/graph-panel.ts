// The linked graphs under the views (appendix 8.5): two graphs whose quantity
// each picks (κ, radius, τ, speed, log κ, log τ) against arc length s or the
// parameter t (the first graph's abscissa menu). The panel draws what it is
// given and reports the user's choices and hovers; the App decides what the
// graphs show (the selected curve, the ghost, the fairing assistant's ghost).

import type { Analysis } from '../api/types';
import { Graph, type Abscissa, type OverlayKind, type Quantity } from '../graphs/graph';

/** What the graph panel asks of the page around it. */
export interface GraphPanelHost {
  /** The abscissa menu changed. */
  setAbscissa(a: Abscissa): void;
  /** A graph's quantity changed: show the graphs again. */
  updateGraphs(): void;
  /** A sample is hovered on graph `from` (null: none). */
  hoverSample(index: number | null, from: Graph): void;
}

const QUANTITIES: Record<Quantity, string> = {
  kappa: 'κ curvature',
  radius: 'radius of curvature',
  tau: 'τ torsion',
  speed: 'speed',
  logkappa: 'log curvature',
  logtau: 'log torsion',
};

export class GraphPanel {
  readonly graphs: Graph[] = [];

  constructor(root: HTMLElement, host: GraphPanelHost, quantities: Quantity[] = ['kappa', 'tau']) {
    quantities.forEach((q, i) => {
      const box = document.createElement('div');
      box.className = 'graph-box';
      const row = document.createElement('div');
      row.className = 'row';
      const sel = document.createElement('select');
      sel.setAttribute('aria-label', `Quantity of graph ${i + 1}`);
      for (const [value, text] of Object.entries(QUANTITIES)) {
        const o = document.createElement('option');
        o.value = value;
        o.textContent = text;
        sel.appendChild(o);
      }
      sel.value = q;
      row.appendChild(sel);
      if (i === 0) {
        const ab = document.createElement('select');
        ab.id = 'abscissa';
        ab.setAttribute('aria-label', 'Graph abscissa');
        ab.innerHTML =
          '<option value="s">against arc length s</option><option value="t">against parameter t</option>';
        ab.addEventListener('change', () => {
          host.setAbscissa(ab.value as Abscissa);
        });
        row.appendChild(ab);
      }
      box.appendChild(row);
      root.appendChild(box);
      const g = new Graph(box, q, `g${i}`);
      sel.addEventListener('change', () => {
        g.quantity = sel.value as Quantity;
        host.updateGraphs();
      });
      g.onHover = (index) => {
        host.hoverSample(index, g);
      };
      this.graphs.push(g);
    });
  }

  /** Show a curve's analysis, overlaid with `compare` drawn as `kind` ("before" an edit, or "faired"). */
  show(a: Analysis | undefined, compare: Analysis | undefined, kind: OverlayKind): void {
    for (const g of this.graphs) g.show(a, compare, kind);
  }

  /** The graphs' abscissa (s or t) and the menu showing it. */
  setAbscissa(a: Abscissa): void {
    const sel = document.getElementById('abscissa') as HTMLSelectElement | null;
    if (sel) sel.value = a;
    for (const g of this.graphs) g.abscissa = a;
  }

  /** Highlight a sample on every graph but `from` (the one hovered). */
  highlight(index: number | null, from?: Graph): void {
    for (const g of this.graphs) if (g !== from) g.highlight(index);
  }
}
