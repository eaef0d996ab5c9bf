// One store per document, updated only from server replies and document
// events (STYLE.md, front ends): the page renders what the server says.

import type {
  Analysis,
  ChangeReply,
  ChangeSet,
  DocumentState,
  Entity,
  History,
  Label,
} from '../api/types';
import { entityFromServer } from '../api/adapt';

export type StoreListener = (what: StoreEvent) => void;
export type StoreEvent =
  | { type: 'document' }
  | { type: 'entity'; label: string }
  | { type: 'removed'; label: string }
  | { type: 'analysis'; label: string }
  | { type: 'history' };

/** Labels are keyed by their decimal text (Oli labels are integers on the wire). */
export const key = (label: Label): string => String(label);

export class DocumentStore {
  name: string;
  revision = -1;
  readonly entities = new Map<string, Entity>();
  readonly analyses = new Map<string, Analysis>();
  history: History | null = null;
  private readonly listeners = new Set<StoreListener>();
  /** Revisions whose change sets came with a reply: their events bring nothing new. */
  private readonly replied = new Set<number>();

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
      const k = key(e.label);
      seen.add(k);
      this.entities.set(k, { ...e, label: k });
    }
    for (const label of [...this.entities.keys()]) {
      if (!seen.has(label)) {
        this.entities.delete(label);
        this.analyses.delete(label);
      }
    }
    this.emit({ type: 'document' });
  }

  /** Set one entity (a change set's entity, or one fetched after a label-only change). */
  put(e: Entity): void {
    const k = key(e.label);
    this.entities.set(k, { ...e, label: k });
    this.analyses.delete(k);
    this.emit({ type: 'entity', label: k });
  }

  remove(label: Label): void {
    const k = key(label);
    if (!this.entities.delete(k)) return;
    this.analyses.delete(k);
    this.emit({ type: 'removed', label: k });
  }

  /**
   * Apply a change set (a reply or an event; applying one twice changes
   * nothing). The entities it carries (`entities`, as the server sends them
   * with the reply of a change) are stored, but `defer`'s (a drag in
   * progress: its entity is stored once, when the drag settles); labels that
   * changed without their entity are returned for the caller to fetch. An
   * event whose revision a reply has already brought is skipped; a reply
   * (`reply`) never is: undo lowers the revision, so the next change reuses
   * a revision number an earlier reply had.
   */
  apply(changes: ChangeSet, defer?: string, reply = false): string[] {
    if (!reply && this.replied.delete(changes.revision)) return [];
    const whole = new Set<string>();
    for (const raw of changes.entities ?? []) {
      const e = entityFromServer(raw);
      whole.add(key(e.label));
      if (key(e.label) !== defer) this.put(e);
    }
    for (const label of changes.removed ?? []) this.remove(label);
    const stale = [
      ...(changes.added ?? []),
      ...(changes.changed ?? []),
      ...(changes.attributes_changed ?? []),
    ]
      .map(key)
      .filter((k) => !whole.has(k));
    this.revision = changes.revision;
    return [...new Set(stale)];
  }

  /** Apply the reply of a change: its change set, whose event is then skipped. */
  applyReply(reply: ChangeReply, defer?: string): string[] {
    // When the change's event came first (the store is at its revision already), no event is to come.
    const eventFirst = this.revision === reply.revision;
    const stale = this.apply({ ...reply.changes, revision: reply.revision }, defer, true);
    if (eventFirst) this.replied.delete(reply.revision);
    else this.replied.add(reply.revision);
    return stale;
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
