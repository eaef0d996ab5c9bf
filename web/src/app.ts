// The workbench: wires the client, the document store, the viewports, the
// tools, the graphs and the panels. State changes only through server
// replies and document events; the page draws, picks and snaps.

import { ApiError, Client } from './api/client';
import { Editor } from './editor/editor';
import { createCurve } from './commands/create-curve';
import { replaceCurve } from './commands/replace-curve';
import { patchEntity } from './commands/patch-entity';
import { setHidden, setLocked } from './commands/set-attributes';
import { movePoint } from './commands/move-point';
import { undo } from './commands/undo';
import { redo } from './commands/redo';
import { insertKnot } from './commands/insert-knot';
import { elevate } from './commands/elevate';
import { reverse } from './commands/reverse';
import { split } from './commands/split';
import { deleteSelected } from './commands/delete';
import { importFile } from './commands/import-file';
import { matchCurves } from './commands/match';
import { blendCurves } from './commands/blend';
import { rebuildCurve, type RebuildChoice } from './commands/rebuild';
import { closeCurve } from './commands/close';
import { offsetCurve } from './commands/offset';
import { clothoidThrough, type ClothoidChoice } from './commands/clothoid';
import { ClothoidTool } from './tools/clothoid';
import { IntersectTool } from './tools/intersect';
import { KnotTool } from './tools/knots';
import { clothoidHost, intersectHost, knotHost } from './controller/tool-hosts';
import { JoinTool, type JoinHost } from './tools/join';
import { finLines } from './api/adapt';
import type {
  Analysis,
  AnalysisRequest,
  ChangeReply,
  ChangeSet,
  CurveFile,
  DocumentState,
  Entity,
  FinKind,
  Job,
} from './api/types';
import { DocumentStore } from './store/store';
import { ViewStore, type ViewToggles } from './store/view';
import { DragController } from './controller/drag';
import { AnalysisScheduler } from './controller/analysis';
import { ViewportController } from './controller/viewport-input';
import { Connection } from './controller/connection';
import { SPACE_FINS, fixFinBase, handlesOf, type ViewSettings } from './store/curves';
import type { ViewState } from './store/viewstate';
import { DocumentSession } from './controller/document-session';
import type { Abscissa, Graph } from './graphs/graph';
import { GraphPanel } from './panels/graph-panel';
import { Viewports, toVec3 } from './viewport/viewports';
import type { Vec3, ViewName } from './viewport/math';
import {
  ControlPointTool,
  HermiteTool,
  SplineTool,
  type Tool,
  type ToolHost,
  type ToolName,
} from './tools/tools';
import { Panels } from './panels/panels';
import { Toolbar } from './panels/toolbar';
import { DesignByCurvature } from './panels/design';
import { OptimisePanel } from './panels/optimise';
import { FairingAssistant } from './tools/fairing';
import {
  EXPORT_FORMATS,
  ExportMenu,
  download,
  exportFileName,
  type MenuFormat,
} from './panels/export';

export class App {
  readonly store: DocumentStore;
  readonly viewports: Viewports;
  /** The linked graphs under the views. */
  readonly graphPanel: GraphPanel;
  get graphs(): readonly Graph[] {
    return this.graphPanel.graphs;
  }
  readonly panels: Panels;
  readonly design: DesignByCurvature;
  readonly optimise: OptimisePanel;
  readonly fairing: FairingAssistant;
  readonly exportMenu: ExportMenu;
  /** The toolbar's buttons and the keyboard. */
  readonly toolbar: Toolbar;
  /** The pointer in the views: picking, snapping, navigation, the drag's start. */
  readonly input: ViewportController;
  /** The client, the selection, the status and the commands' shared helpers. */
  readonly editor: Editor;

  get selected(): string | null {
    return this.editor.selected;
  }

  isHidden(label: string): boolean {
    return this.editor.isHidden(label);
  }

  isLocked(label: string): boolean {
    return this.editor.isLocked(label);
  }

  /** Result curves of the studies run from this page: curve label → study label. */
  get studyOf(): Map<string, string> {
    return this.view.studyOf;
  }
  tool: Tool | null = null;
  toolName: ToolName = 'select';
  /** The snap toggles, the graphs' abscissa, the curves' view settings: store/view.ts. */
  readonly view = new ViewStore();

  get abscissa(): Abscissa {
    return this.view.abscissa;
  }

  /** The drag of a handle: its moves, its PATCHes, its preview and its counters. */
  readonly drags: DragController;
  /** The server's analyses of the curves, one request per curve in flight. */
  readonly analyses: AnalysisScheduler;
  /** The event stream and what happens when the server goes away or refuses the token. */
  readonly connection: Connection;
  /**
   * The ghost: the selected curve's analysis before the last drag or rebuild,
   * drawn faintly in the views and overlaid on the graphs until another curve
   * is selected or Escape clears it.
   */
  ghost: { label: string; analysis: Analysis } | null = null;
  /** Pointer-to-frame latencies of the current drag (ms; DragController). */
  get latencies(): readonly number[] {
    return this.drags.latencies;
  }

  /** The pointer-to-frame latencies split into the wait for the frame and its work (ms). */
  get frameSplit(): DragController['frameSplit'] {
    return this.drags.frameSplit;
  }

  /** Pointer-to-reply latencies of the current drag's moves (ms). */
  get serverLatencies(): readonly number[] {
    return this.drags.serverLatencies;
  }

  /** The honest drag counters (read by e2e/bench.spec.ts; DragController.dragStats). */
  get dragStats(): DragController['dragStats'] {
    return this.drags.dragStats;
  }

  constructor(
    readonly client: Client,
    docName: string,
  ) {
    this.store = new DocumentStore(docName);
    this.editor = new Editor(client, this.store);
    this.session = new DocumentSession(this);
    this.drags = new DragController(this);
    this.analyses = new AnalysisScheduler(
      this.editor,
      (label) => this.analysisRequest(label),
      (label, seq) => {
        this.drags.analysisArrived(label, seq);
      },
      () => {
        if (this.session.fitPending && !this.analysisPending) {
          this.session.fitPending = false;
          this.fitAll();
        }
      },
    );
    this.editor.deferFetch = (label) => {
      // A curve being dragged is fetched once, when its last move is answered (dragSettled):
      // the page sent every position, and a fetch per move doubled the drag's requests.
      if (label !== this.drags.settling) return false;
      this.drags.panelsStale = true;
      return true;
    };
    this.viewports = new Viewports(document.getElementById('viewports')!);
    this.panels = new Panels(this, document.getElementById('side')!);
    this.design = new DesignByCurvature(this);
    this.optimise = new OptimisePanel(this);
    this.fairing = new FairingAssistant(this, document.getElementById('side')!);
    this.exportMenu = new ExportMenu((format) => void this.exportSelected(format));
    this.graphPanel = new GraphPanel(document.getElementById('graphs')!, {
      setAbscissa: (a) => {
        this.setAbscissa(a);
      },
      updateGraphs: () => {
        this.updateGraphs();
      },
      hoverSample: (index, from) => {
        this.hoverSample(index, from);
      },
    });
    this.design.attach(this.graphs[0]!);
    this.input = new ViewportController(this);
    this.input.bind();
    this.toolbar = new Toolbar(this);
    this.toolbar.bind();
    this.editor.subscribe((e) => {
      switch (e.type) {
        case 'selection':
          this.selectionChanged(e.previous);
          break;
        case 'status':
          this.showStatus(e.text, e.error);
          break;
        case 'toast':
          this.showToast(e.error);
          break;
        case 'pending':
          this.redrawCurve(e.label);
          break;
      }
    });
    this.view.subscribe((e) => {
      this.togglesChanged(e.changed);
    });
    this.store.subscribe((e) => {
      switch (e.type) {
        case 'document':
          this.drags.documentLoaded();
          for (const label of this.store.entities.keys()) this.refreshAnalysis(label);
          this.redrawAll();
          this.refreshHistory();
          this.fairing.edited(this.selected);
          break;
        case 'entity':
          if (this.drags.drag?.label === e.label) {
            // The server's echo of a drag move: analysed and listed once the drag ends
            // (a curve the page cannot evaluate is still analysed as it moves).
            if (!this.drags.drag.local) this.refreshAnalysis(e.label);
            this.drags.panelsStale = true;
            break;
          }
          // The store now has the curve as the server holds it, a drag's last move included.
          this.drags.entityStored(e.label);
          this.redrawCurve(e.label);
          // A drag's reply brought the analysis and the history step with the curve.
          if (!this.drags.takeFresh(e.label)) {
            this.refreshAnalysis(e.label);
            this.refreshHistory();
          }
          this.fairing.edited(e.label);
          if (this.tool instanceof KnotTool && e.label === this.selected) this.tool.refresh(true);
          break;
        case 'removed':
          this.viewports.removeCurve(e.label);
          if (this.selected === e.label) this.select(null);
          this.refreshHistory();
          break;
        case 'analysis':
          this.redrawCurve(e.label);
          if (e.label === this.selected) this.updateGraphs();
          break;
        case 'history':
          break;
      }
    });
    this.panels.listen();
    this.connection = new Connection({
      editor: this.editor,
      reload: () => this.reload(),
      applyChanges: (changes) => {
        this.applyChanges(changes);
      },
      offerReopen: (show) => {
        document.getElementById('reopen')!.hidden = !show;
      },
      openEvents: (url) => new EventSource(url, { withCredentials: true }),
    });
    document.getElementById('reopen')!.addEventListener('click', () => {
      this.panels.reopenDialog();
    });
    this.viewports.beforeFrame.add(() => {
      this.drags.frame();
    });
    this.viewports.afterFrame.add(() => {
      this.drags.frameDrawn(performance.now());
    });
    this.setTool('select');
    this.panels.update();
  }

  // ---- document ------------------------------------------------------------

  /** Opening documents and the page's stored view of each: controller/document-session.ts. */
  readonly session: DocumentSession;

  /** Open a document; `prefetched` is its GET already under way (started before the views were built). */
  open(name: string, prefetched?: Promise<DocumentState>): Promise<void> {
    return this.session.open(name, prefetched);
  }

  /** The page's state of this document as stored (selection, fins, layout, snap, objects). */
  get viewState(): ViewState {
    return this.session.viewState;
  }

  /** Store the page's state of this document (localStorage, one key per document). */
  viewStateChanged(): void {
    this.session.save();
  }

  /** Snap to existing points and curves (toggle "Objects", Shift+G). */
  get objectSnap(): boolean {
    return this.view.objectSnap;
  }

  /** What the last snapped point landed on, for the status line and tests. */
  get lastSnap(): ViewportController['lastSnap'] {
    return this.input.lastSnap;
  }

  setObjectSnap(on: boolean): void {
    this.view.set({ objectSnap: on });
  }

  setSnap(on: boolean): void {
    this.view.set({ snap: on });
  }

  setAbscissa(a: Abscissa): void {
    this.view.set({ abscissa: a });
  }

  /** The toggles changed (view store event): checkboxes, views and graphs follow, and are stored. */
  private togglesChanged(changed: readonly (keyof ViewToggles)[]): void {
    const v = this.view;
    if (changed.includes('snap')) {
      (document.getElementById('snap') as HTMLInputElement).checked = v.snap;
      this.viewports.snap = v.snap;
    }
    if (changed.includes('objectSnap'))
      (document.getElementById('osnap') as HTMLInputElement).checked = v.objectSnap;
    if (changed.includes('abscissa')) {
      this.graphPanel.setAbscissa(v.abscissa);
      for (const label of this.store.entities.keys()) this.refreshAnalysis(label);
    }
    this.viewStateChanged();
  }

  /** Show or hide a curve (object list): commands/set-attributes. */
  async setHidden(label: string, hidden: boolean): Promise<void> {
    await setHidden(this.editor, label, hidden);
  }

  /** Lock or unlock a curve (object list): commands/set-attributes. */
  async setLocked(label: string, locked: boolean): Promise<void> {
    await setLocked(this.editor, label, locked);
  }

  /**
   * A study job ended: the document is reloaded with what it stored, its
   * result curves are listed under the study that made them and the first is
   * selected and shown.
   */
  async studyFinished(job: Job): Promise<void> {
    await this.run(() => this.reload(), 'Reload after the study');
    const study = (job.result as { study?: string | number } | null)?.study;
    const curves = (job.result?.curves ?? []).map(String).filter((c) => this.store.entities.has(c));
    if (study === undefined || curves.length === 0) return;
    for (const c of curves) this.studyOf.set(c, String(study));
    this.select(curves[0]!);
    const studyName = this.store.entities.get(String(study))?.name ?? 'study';
    this.setStatus(
      `Study ${studyName} (${study}) ${job.state}: result curve${curves.length > 1 ? 's' : ''} ${curves.join(', ')}; ${curves[0]} selected`,
    );
    this.viewStateChanged();
    this.panels.update();
  }

  setLayout(layout: 'quad' | 'single', active?: ViewName): void {
    this.viewports.setLayout(layout, active);
    this.viewStateChanged();
  }

  async reload(): Promise<void> {
    const doc = await this.client.getDocument(this.store.name);
    this.store.load(doc);
  }

  /** Whether the server has refused the page's token (it restarted with a new one). */
  get refused(): boolean {
    return this.connection.refused;
  }

  setStatus(text: string, error = false): void {
    this.editor.setStatus(text, error);
  }

  private showStatus(text: string, error: boolean): void {
    const el = document.getElementById('status')!;
    el.textContent = text;
    el.classList.toggle('offline', error);
  }

  /** An error toast carrying the server's code, message and field. */
  toast(e: unknown): void {
    this.editor.toast(e);
  }

  private showToast(e: unknown): void {
    const box = document.getElementById('toasts')!;
    const t = document.createElement('div');
    t.className = 'toast';
    if (e instanceof ApiError) {
      const where = Object.entries(e.body.where)
        .map(([k, v]) => `${k} ${String(v)}`)
        .join(', ');
      t.innerHTML = '<code></code> <span></span> <em></em>';
      t.children[0]!.textContent = e.body.code;
      t.children[1]!.textContent = e.body.message;
      t.children[2]!.textContent = where ? `(${where})` : '';
      t.dataset['code'] = e.body.code;
      if (e.body.where.field) t.dataset['field'] = e.body.where.field;
    } else {
      t.textContent = e instanceof Error ? e.message : String(e);
    }
    box.appendChild(t);
    setTimeout(() => {
      t.remove();
    }, 8000);
  }

  /** Run a server call, turning a failure into a toast (and the status, with `what`). */
  run<T>(f: () => Promise<T>, what?: string): Promise<T | undefined> {
    return this.editor.run(f, what);
  }

  /** A curve's name for messages: its name, else its label. */
  nameOf(label: string): string {
    return this.editor.nameOf(label);
  }

  // ---- editing ---------------------------------------------------------------

  /** A curve's drawn colour (its colour attribute, else its label's palette colour). */
  colourOf(label: string): number {
    return this.editor.colourOf(label);
  }

  // The undoable actions are commands (src/commands/, one per file) on the editor.

  createCurve(name: string, curve: CurveFile): Promise<string | undefined> {
    return createCurve(this.editor, name, curve, this.tool?.hint);
  }

  /** Apply a change reply; entities named by label only are fetched. */
  applyReply(reply: ChangeReply): void {
    this.editor.applyReply(reply);
  }

  applyChanges(changes: ChangeSet): void {
    this.editor.fetchStale(this.store.apply(changes));
  }

  replaceCurve(label: string, curve: CurveFile): Promise<void> {
    return replaceCurve(this.editor, label, curve);
  }

  patch(label: string, body: Record<string, unknown>): Promise<void> {
    return patchEntity(this.editor, label, body);
  }

  movePoint(label: string, index: number, to: Vec3): Promise<void> {
    return movePoint(this.editor, label, index, to);
  }

  undo(): Promise<void> {
    return undo(this.editor);
  }

  redo(): Promise<void> {
    return redo(this.editor);
  }

  insertKnotSelected(): Promise<void> {
    return insertKnot(this.editor);
  }

  elevateSelected(): Promise<void> {
    return elevate(this.editor);
  }

  reverseSelected(): Promise<void> {
    return reverse(this.editor);
  }

  splitSelected(): Promise<void> {
    return split(this.editor);
  }

  async rebuildCurve(label: string, choice: RebuildChoice): Promise<void> {
    await rebuildCurve(this.editor, label, choice);
  }

  async closeSelected(): Promise<void> {
    const label = this.editor.needSelection('Close');
    if (label) await closeCurve(this.editor, label);
  }

  async offsetCurve(label: string, distance: number): Promise<void> {
    await offsetCurve(this.editor, label, distance);
  }

  async clothoidThrough(label: string, choice: ClothoidChoice): Promise<void> {
    await clothoidThrough(this.editor, label, choice);
  }

  deleteSelected(): Promise<void> {
    return deleteSelected(this.editor);
  }

  refreshHistory(): void {
    void this.run(async () => {
      this.store.setHistory(await this.client.history(this.store.name));
    });
  }

  // ---- interrogation -------------------------------------------------------

  settingsOf(label: string): ViewSettings {
    return this.view.settingsOf(label);
  }

  /** The drawing factors of a curve's fins (ViewSettings.finBase), from its analysis. */
  finBase(label: string, a: Analysis): Partial<Record<FinKind, number>> {
    return fixFinBase(this.settingsOf(label), a);
  }

  /** The analysis as drawn: its combs scaled by the fin factors. */
  drawnAnalysis(label: string): Analysis | undefined {
    const a = this.analysisOf(label);
    if (!a) return undefined;
    const base = this.finBase(label, a);
    const fins: Analysis['fins'] = {};
    for (const [kind, c] of Object.entries(a.combs) as [FinKind, Analysis['combs'][FinKind]][])
      if (c) fins[kind] = finLines(c.base, c.tip, base[kind] ?? 1);
    return { ...a, fins };
  }

  /** What the views and graphs draw for a curve: the drag's preview, else the server's analysis. */
  analysisOf(label: string): Analysis | undefined {
    return this.drags.analysisOf(label);
  }

  /** Ask the server for what the views draw; one request per curve in flight, the latest wins. */
  refreshAnalysis(label: string): void {
    this.analyses.refresh(label);
  }

  get analysisPending(): boolean {
    return this.analyses.pending;
  }

  get analysisSeq(): number {
    return this.analyses.seq;
  }

  /** The fins drawn for a curve: planar curves show only the meaningful ones (8.4, 8.6). */
  shownFins(label: string, a: Analysis | undefined): FinKind[] {
    const s = this.settingsOf(label);
    if (a?.planar) return s.fins.filter((f) => !SPACE_FINS.has(f));
    return s.fins;
  }

  redrawCurve(label: string, handlesOverride?: Vec3[]): void {
    const e = this.store.entities.get(label);
    if (!e) return;
    const a = this.analysisOf(label);
    const s = this.settingsOf(label);
    this.viewports.drawCurve(label, {
      analysis: this.drawnAnalysis(label),
      handles: handlesOverride ?? this.drags.handlesOf(label) ?? handlesOf(e.curve),
      polygon:
        e.curve?.kind === 'nurbs' || e.curve?.kind === 'bezier' || e.curve?.kind === 'hermite',
      selected: label === this.selected,
      fins: this.shownFins(label, a),
      frames: s.frames,
      colour: this.colourOf(label),
      visible: !this.isHidden(label),
    });
    const root = this.viewports.root;
    root.dataset['fins'] = this.selected
      ? this.shownFins(this.selected, this.analysisOf(this.selected)).join(' ')
      : '';
  }

  redrawAll(): void {
    for (const label of this.store.entities.keys()) this.redrawCurve(label);
  }

  select(label: string | null): void {
    this.editor.select(label);
  }

  /** The selection changed (editor event): views, graphs, panels and the stored view state follow. */
  private selectionChanged(previous: string | null): void {
    const label = this.selected;
    if (this.ghost && this.ghost.label !== label) this.setGhost(null);
    if (previous !== label) this.fairing.edited(label);
    if (previous) this.redrawCurve(previous);
    if (label) this.redrawCurve(label);
    if (this.tool instanceof KnotTool && previous !== label) this.tool.refresh();
    this.updateGraphs();
    this.viewStateChanged();
  }

  get selectedEntity(): Entity | undefined {
    return this.editor.selectedEntity;
  }

  // ---- graphs ----------------------------------------------------------------

  updateGraphs(): void {
    const a = this.selected ? this.analysisOf(this.selected) : undefined;
    // The fairing assistant's ghost, when there is one, else the curve before the last edit.
    const faired = this.fairing.analysis;
    const before = this.ghost?.label === this.selected ? this.ghost.analysis : undefined;
    this.graphPanel.show(a, faired ?? before, faired ? 'faired' : 'before');
  }

  /** Keep the curve's current analysis as the ghost (before an edit), or clear it. */
  setGhost(label: string | null): void {
    const a = label ? this.store.analyses.get(label) : undefined;
    this.ghost = label && a ? { label, analysis: a } : null;
    this.viewports.setGhost(this.ghost ? this.ghost.analysis.points : null);
    this.updateGraphs();
  }

  /** Linked hover: a sample index from a graph or the curve highlights both. */
  hoverSample(index: number | null, from?: Graph): void {
    this.editor.hovered = index;
    const a = this.selected ? this.store.analyses.get(this.selected) : undefined;
    const p = index !== null && a ? a.points[index] : undefined;
    this.viewports.setMarker(p ? toVec3(p) : null);
    this.graphPanel.highlight(index, from);
    this.viewports.root.dataset['hover'] = index === null ? '' : String(index);
    this.input.placeReadout(from !== undefined);
  }

  get hovered(): number | null {
    return this.editor.hovered;
  }

  // ---- viewport input ----------------------------------------------------

  setTool(name: ToolName): void {
    this.tool?.cancel();
    this.toolName = name;
    const host: ToolHost = {
      pointAt: (view, ev) => this.pointAt(view, ev),
      preview: (pts) => {
        this.viewports.setPreview(pts);
      },
      create: (n, c) => {
        void this.createCurve(n, c);
      },
      status: (t) => {
        this.setStatus(t);
      },
    };
    this.tool =
      name === 'spline'
        ? new SplineTool(host)
        : name === 'bezier' || name === 'nurbs'
          ? new ControlPointTool(name, host)
          : name === 'hermite'
            ? new HermiteTool(host)
            : name === 'match' || name === 'blend'
              ? new JoinTool(name, this.joinHost(), this.joinContinuity)
              : name === 'intersect'
                ? new IntersectTool(intersectHost(this))
                : name === 'knots'
                  ? new KnotTool(knotHost(this))
                  : name === 'clothoid'
                    ? new ClothoidTool(clothoidHost(this))
                    : null;
    const continuity = document.getElementById('join-continuity') as HTMLSelectElement | null;
    if (continuity) {
      continuity.hidden = name !== 'match' && name !== 'blend';
      // G0 is Match's only.
      const g0 = continuity.querySelector<HTMLOptionElement>('option[value="0"]');
      if (g0) g0.disabled = name === 'blend';
    }
    this.setStatus(
      this.tool?.hint ??
        'Select: click a curve; drag its points; wheel zooms, middle drag pans, Alt-drag orbits',
    );
    for (const b of document.querySelectorAll<HTMLButtonElement>('[data-tool]')) {
      b.classList.toggle('on', b.dataset['tool'] === name);
      b.setAttribute('aria-pressed', String(b.dataset['tool'] === name));
    }
  }

  pointAt(view: ViewName, ev: PointerEvent): Vec3 | null {
    return this.input.pointAt(view, ev);
  }

  /** The continuity Match and Blend ask (k of Gk), kept between uses of the tools. */
  private joinContinuity = 2;

  /** Set the continuity of the Match or Blend tool in use (the toolbar's menu). */
  setJoinContinuity(k: number): void {
    if (this.tool instanceof JoinTool) this.tool.setContinuity(k);
  }

  private joinHost(): JoinHost {
    return {
      pick: (view, ev) => this.input.pickCurve(view, ev),
      mark: (points) => {
        this.viewports.setPreview([], points);
      },
      status: (t, error) => {
        this.setStatus(t, error);
      },
      run: async (kind, request) => {
        if (kind === 'blend') {
          await blendCurves(this.editor, request);
          return;
        }
        // A as it was is the ghost (drawn faintly, overlaid on the graphs) once the match is stored.
        const before = this.store.analyses.get(request.a);
        if (!(await matchCurves(this.editor, request)) || !before) return;
        this.ghost = { label: request.a, analysis: before };
        this.viewports.setGhost(before.points);
        this.updateGraphs();
      },
      continuityChanged: (k) => {
        this.joinContinuity = k;
        const sel = document.getElementById('join-continuity') as HTMLSelectElement | null;
        if (sel) sel.value = String(k);
      },
    };
  }

  /** The analysis the views and graphs ask for a curve (its view settings). */
  analysisRequest(label: string): AnalysisRequest {
    const s = this.settingsOf(label);
    return {
      samples: s.samples,
      by: this.abscissa === 's' ? 'arclength' : 'parameter',
      fins: s.fins,
      scale: s.scale,
    };
  }

  get dragging(): boolean {
    return this.drags.dragging;
  }

  updatePanels(): void {
    this.panels.update();
  }

  requestRender(): void {
    this.viewports.requestRender();
  }

  /** The curve `label` as the page holds it (DragController.heldCurve). */
  heldCurve(label: string): CurveFile | undefined {
    return this.drags.heldCurve(label);
  }

  /** A drag position not yet answered by the server. */
  get dragPending(): boolean {
    return this.drags.pending;
  }

  fitAll(): void {
    const pts: Vec3[] = [];
    for (const [label, a] of this.store.analyses) {
      pts.push(...a.points.map(toVec3));
      pts.push(...handlesOf(this.store.entities.get(label)?.curve));
    }
    for (const e of this.store.entities.values()) pts.push(...handlesOf(e.curve));
    if (pts.length === 0) pts.push([0, -50, -50], [120, 50, 50]);
    this.viewports.fit(pts);
  }

  // ---- toolbar actions ------------------------------------------------------

  /** A toolbar action by name (the buttons' data-action, the keys' map): panels/toolbar.ts. */
  action(name: string): void {
    this.toolbar.action(name);
  }

  async importFile(file: File): Promise<void> {
    if (await importFile(this.editor, file.name, await file.text(), this.tool?.hint)) this.fitAll();
  }

  /** Writes the selected curve in `format` through the server and offers the file as a download. */
  async exportSelected(format: MenuFormat): Promise<void> {
    const label = this.editor.needSelection('Export');
    if (label === null) return;
    const what = `Export ${format.toUpperCase()}`;
    const reply = await this.run(
      () => this.client.exportFile(this.store.name, [label], format),
      `${what} of ${this.nameOf(label)}`,
    );
    if (!reply) return;
    const filename = exportFileName(this.store.entities.get(label)?.name ?? '', label, format);
    download(reply.content, filename, EXPORT_FORMATS[format].mime);
    const deviation =
      reply.max_deviation !== undefined && reply.max_deviation > 0
        ? ` (NURBS approximation within ${reply.max_deviation.toExponential(1)})`
        : '';
    this.setStatus(`Exported ${this.nameOf(label)} as ${filename}${deviation}`);
  }

  /** Quiet: no request in flight, no analysis queued, no frame scheduled, no drag. */
  isIdle(): boolean {
    return (
      this.client.pending === 0 &&
      !this.analysisPending &&
      !this.viewports.renderPending &&
      !this.drags.dragging &&
      !this.design.busy &&
      !this.fairing.busy &&
      !this.optimise.running
    );
  }
}

/** Wait for two consecutive idle animation frames. */
export function waitIdle(app: App): Promise<void> {
  return new Promise((resolve) => {
    let quiet = 0;
    const check = (): void => {
      quiet = app.isIdle() ? quiet + 1 : 0;
      if (quiet >= 2) resolve();
      else setTimeout(check, 16);
    };
    check();
  });
}
