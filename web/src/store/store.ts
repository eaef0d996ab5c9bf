// One store per document, updated only from server replies and document
// events (STYLE.md, front ends): the page renders what the server says.

import type {
  Analysis,
  ChangeReply,
  ChangeSet,
  DocumentState,
  Entity,
  History,
} from '../api/types';

export type StoreListener = (what: StoreEvent) => void;
export type StoreEvent =
  | { type: 'document' }
  | { type: 'entity'; label: string }
  | { type: 'removed'; label: string }
  | { type: 'analysis'; label: string }
  | { type: 'history' };

export class DocumentStore {
  name: string;
  revision = -1;
  readonly entities = new Map<string, Entity>();
  readonly analyses = new Map<string, Analysis>();
  history: History | null = null;
  private readonly listeners = new Set<StoreListener>();

  constructor(name: string) {
    this.name = name;
  }

  subscribe(l: StoreListener): () => void {
    this.listeners.add(l);
    return () => this.listeners.delete(l);
  }

  private emit(e: StoreEvent): void {
    for (const l of this.listeners) l(e);
  }

  /** Replace everything with a full document reply (open, reload, reconnect). */
  load(doc: DocumentState): void {
    this.name = doc.name;
    this.revision = doc.revision;
    const seen = new Set<string>();
    for (const e of doc.entities) {
      seen.add(e.label);
      this.entities.set(e.label, e);
    }
    for (const label of [...this.entities.keys()]) {
      if (!seen.has(label)) {
        this.entities.delete(label);
        this.analyses.delete(label);
      }
    }
    this.emit({ type: 'document' });
  }

  /**
   * Apply a change set (a reply or an event). Returns false when it cannot be
   * applied in order (a gap in revisions): the caller reloads the document.
   * A change set at or below the current revision was already applied.
   */
  apply(changes: ChangeSet): boolean {
    if (changes.revision <= this.revision && this.revision >= 0) {
      // Undo may go back to an older revision number only through a newer
      // change set, so an old revision here is a duplicate (reply + event).
      return true;
    }
    for (const e of [...(changes.created ?? []), ...(changes.modified ?? [])]) {
      this.entities.set(e.label, e);
      this.analyses.delete(e.label);
      this.emit({ type: 'entity', label: e.label });
    }
    for (const label of changes.deleted ?? []) {
      this.entities.delete(label);
      this.analyses.delete(label);
      this.emit({ type: 'removed', label });
    }
    this.revision = changes.revision;
    return true;
  }

  applyReply(reply: ChangeReply): void {
    this.apply({ ...reply.changes, revision: reply.revision });
  }

  setAnalysis(label: string, a: Analysis): void {
    if (!this.entities.has(label)) return;
    this.analyses.set(label, a);
    this.emit({ type: 'analysis', label });
  }

  setHistory(h: History): void {
    this.history = h;
    this.emit({ type: 'history' });
  }
}
