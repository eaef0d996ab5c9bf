// Opening a document and keeping the page's view of it (after three.js's
// editor, whose Loader and Config are apart from the Editor): the document is
// fetched (or created when the workspace has none of that name), loaded into
// the store, its event stream subscribed, and the page's state of it —
// selection, fins, layout, snap, the graphs' abscissa, study results — is
// restored from and saved to localStorage, one key per document.

import { ApiError, type Client } from '../api/client';
import type { DocumentState } from '../api/types';
import type { DocumentStore } from '../store/store';
import type { ViewStore } from '../store/view';
import { loadViewState, saveViewState, type ViewState } from '../store/viewstate';
import type { Viewports } from '../viewport/viewports';
import type { Connection } from './connection';

/** What opening a document asks of the page around it (the App). */
export interface DocumentSessionHost {
  readonly client: Client;
  readonly store: DocumentStore;
  readonly view: ViewStore;
  readonly viewports: Viewports;
  readonly connection: Connection;
  readonly selected: string | null;
  select(label: string | null): void;
  redrawAll(): void;
  fitAll(): void;
}

export class DocumentSession {
  /** Set while a stored view state is applied: nothing is saved back meanwhile. */
  private restoring = false;
  /** Fit the views again once the curves' analyses are in (law and natural curves have no handles). */
  fitPending = false;

  constructor(private readonly host: DocumentSessionHost) {}

  /** Open a document; `prefetched` is its GET already under way (started before the views were built). */
  async open(name: string, prefetched?: Promise<DocumentState>): Promise<void> {
    const h = this.host;
    h.connection.close();
    h.select(null);
    h.view.clearCurves();
    for (const label of h.store.entities.keys()) h.viewports.removeCurve(label);
    h.store.entities.clear();
    h.store.revision = -1;
    h.store.name = name;
    let doc;
    try {
      doc = await (prefetched ?? h.client.getDocument(name));
    } catch (e) {
      if (e instanceof ApiError && e.status === 404) doc = await h.client.createDocument(name);
      else throw e;
    }
    h.store.load(doc);
    this.restore();
    document.getElementById('doc-name')!.textContent = name;
    location.hash = `doc=${encodeURIComponent(name)}`;
    h.connection.subscribe();
    h.fitAll();
    this.fitPending = h.store.entities.size > 0;
  }

  /** The page's state of this document as stored (selection, fins, layout, snap, objects). */
  get viewState(): ViewState {
    const h = this.host;
    const curves: ViewState['curves'] = {};
    for (const [label, s] of h.view.settings)
      if (h.store.entities.has(label))
        curves[label] = { fins: s.fins, scale: s.scale, samples: s.samples, frames: s.frames };
    return {
      selected: h.selected,
      layout: h.viewports.layout,
      active: h.viewports.active,
      snap: h.view.snap,
      objectSnap: h.view.objectSnap,
      abscissa: h.view.abscissa,
      curves,
      studyOf: Object.fromEntries(h.view.studyOf),
    };
  }

  /** Store the page's state of this document (localStorage, one key per document). */
  save(): void {
    if (this.restoring || this.host.store.revision < 0) return;
    saveViewState(localStorage, this.host.store.name, this.viewState);
  }

  private restore(): void {
    const h = this.host;
    const v = loadViewState(localStorage, h.store.name);
    this.restoring = true;
    try {
      for (const [label, c] of Object.entries(v.curves))
        h.view.settings.set(label, { ...c, fins: [...c.fins] });
      for (const [c, st] of Object.entries(v.studyOf)) h.view.studyOf.set(c, st);
      h.view.set({ snap: v.snap, objectSnap: v.objectSnap, abscissa: v.abscissa });
      h.viewports.setLayout(v.layout, v.active);
      if (v.selected !== null && h.store.entities.has(v.selected)) h.select(v.selected);
      h.redrawAll();
    } finally {
      this.restoring = false;
    }
  }
}
