// The page's view state of the open document, with events: the snap
// toggles, the graphs' abscissa, each curve's view settings (fins, scale,
// samples, frames) and the studies the result curves came from. The App
// draws what changes (toggles, graphs, analyses) and stores it per document
// (store/viewstate.ts); the viewport controller reads the snap toggles here.

import type { ViewSettings } from './curves';

export interface ViewToggles {
  /** Grid snap (Snap, G). */
  snap: boolean;
  /** Snap to existing points and curves (Objects, Shift+G). */
  objectSnap: boolean;
  /** What the graphs plot against: arc length s or the parameter t. */
  abscissa: 's' | 't';
}

export type ViewEvent = { type: 'toggles'; changed: (keyof ViewToggles)[] };
export type ViewListener = (e: ViewEvent) => void;

export class ViewStore implements ViewToggles {
  snap = false;
  objectSnap = false;
  abscissa: 's' | 't' = 's';
  readonly settings = new Map<string, ViewSettings>();
  /** Result curves of the studies run from this page: curve label → study label. */
  readonly studyOf = new Map<string, string>();
  private readonly listeners = new Set<ViewListener>();

  subscribe(l: ViewListener): () => void {
    this.listeners.add(l);
    return () => this.listeners.delete(l);
  }

  /**
   * Set toggles; the event names each one set (a snap toggle set to its own
   * value too, so its checkbox is drawn; the abscissa only when it changed,
   * since a new one asks every curve's analysis again).
   */
  set(patch: Partial<ViewToggles>): void {
    const changed: (keyof ViewToggles)[] = [];
    if (patch.snap !== undefined) {
      this.snap = patch.snap;
      changed.push('snap');
    }
    if (patch.objectSnap !== undefined) {
      this.objectSnap = patch.objectSnap;
      changed.push('objectSnap');
    }
    if (patch.abscissa !== undefined && patch.abscissa !== this.abscissa) {
      this.abscissa = patch.abscissa;
      changed.push('abscissa');
    }
    if (changed.length === 0) return;
    for (const l of this.listeners) l({ type: 'toggles', changed });
  }

  /** A curve's view settings, made with the defaults when it has none. */
  settingsOf(label: string): ViewSettings {
    let s = this.settings.get(label);
    if (!s) {
      s = { fins: [], scale: 1, samples: 200, frames: false };
      this.settings.set(label, s);
    }
    return s;
  }

  /** Forget the curves' settings and studies (another document is opened). */
  clearCurves(): void {
    this.settings.clear();
    this.studyOf.clear();
  }
}
