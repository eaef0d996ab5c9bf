// The editor's state besides the document (after three.js's editor, whose
// Editor holds the scene, the selection and the signals): the client, the
// document store, the selection and the hovered sample, and the events the
// page's parts subscribe to. No DOM here: the status line and the toasts are
// events, drawn by whoever listens (the App), so the commands and the viewport
// controller run in unit tests against a Client whose fetch is replaced.

import { ApiError, type Client } from '../api/client';
import type { ChangeReply, Entity } from '../api/types';
import type { DocumentStore } from '../store/store';
import { curveColour } from '../store/viewstate';

export type EditorEvent =
  | { type: 'selection'; previous: string | null }
  | { type: 'status'; text: string; error: boolean }
  | { type: 'toast'; error: unknown }
  /** A curve's pending attributes changed (hidden or locked before the server answers). */
  | { type: 'pending'; label: string };
export type EditorListener = (e: EditorEvent) => void;

export class Editor {
  selected: string | null = null;
  /** The sample hovered on the selected curve (a graph or the curve), or null. */
  hovered: number | null = null;
  /**
   * Entities named by a change without their data are fetched unless this
   * says the caller fetches them itself (the curve of a drag, fetched once
   * when its last move is answered).
   */
  deferFetch: (label: string) => boolean = () => false;
  /**
   * Attributes asked of the server and not yet answered: a hide or lock shows
   * at once (a click just after "hide" must not pick the curve), and the
   * stored value comes back if the server refuses.
   */
  readonly pendingAttributes = new Map<string, Record<string, unknown>>();
  private readonly listeners = new Set<EditorListener>();

  constructor(
    readonly client: Client,
    readonly store: DocumentStore,
  ) {}

  subscribe(l: EditorListener): () => void {
    this.listeners.add(l);
    return () => this.listeners.delete(l);
  }

  private emit(e: EditorEvent): void {
    for (const l of this.listeners) l(e);
  }

  select(label: string | null): void {
    const previous = this.selected;
    this.selected = label;
    this.emit({ type: 'selection', previous });
  }

  get selectedEntity(): Entity | undefined {
    return this.selected ? this.store.entities.get(this.selected) : undefined;
  }

  setStatus(text: string, error = false): void {
    this.emit({ type: 'status', text, error });
  }

  /** An error for the user (a toast carrying the server's code, message and field). */
  toast(error: unknown): void {
    this.emit({ type: 'toast', error });
  }

  /**
   * Run a server call, turning a failure into a toast; with `what` (the
   * command's name) the status line says it failed, so it never keeps the
   * previous command's message.
   */
  async run<T>(f: () => Promise<T>, what?: string): Promise<T | undefined> {
    try {
      return await f();
    } catch (e) {
      if (!(e instanceof ApiError && e.offline)) this.toast(e);
      if (what)
        this.setStatus(
          `${what} failed: ${e instanceof ApiError ? (e.offline ? 'the server is unreachable' : e.body.message) : String(e)}`,
          true,
        );
      return undefined;
    }
  }

  /** The selected curve, or null with the status saying that `what` needs one. */
  needSelection(what: string): string | null {
    if (this.selected) return this.selected;
    this.setStatus(`${what}: nothing is selected; click a curve first (V)`, true);
    return null;
  }

  /** A curve's name for messages: its name, else its label. */
  nameOf(label: string): string {
    const e = this.store.entities.get(label);
    return e?.name ? `${e.name} (${label})` : label;
  }

  /** Whether a curve is hidden: the document's `visible` attribute (oli), set in the object list. */
  isHidden(label: string): boolean {
    const pending = this.pendingAttributes.get(label);
    if (pending && 'visible' in pending) return pending['visible'] === false;
    return this.store.entities.get(label)?.attributes['visible'] === false;
  }

  /** Whether a curve is locked: the document's `locked` attribute (oli), set in the object list. */
  isLocked(label: string): boolean {
    const pending = this.pendingAttributes.get(label);
    if (pending && 'locked' in pending) return pending['locked'] === true;
    return this.store.entities.get(label)?.attributes['locked'] === true;
  }

  /** A curve's drawn colour (its colour attribute, else its label's palette colour). */
  colourOf(label: string): number {
    return curveColour(label, this.store.entities.get(label)?.attributes);
  }

  /** Show a curve's attributes as asked (`attributes`) or as stored again (null). */
  setPending(label: string, attributes: Record<string, unknown> | null): void {
    if (attributes) this.pendingAttributes.set(label, attributes);
    else this.pendingAttributes.delete(label);
    this.emit({ type: 'pending', label });
  }

  /** Apply a change reply; entities named by label only are fetched. */
  applyReply(reply: ChangeReply, defer?: string): void {
    this.fetchStale(this.store.applyReply(reply, defer));
  }

  /** Fetch the entities a change named without their data (deleted meanwhile: removed). */
  fetchStale(labels: string[]): void {
    for (const label of labels) {
      if (this.deferFetch(label)) continue;
      void this.client
        .getEntity(this.store.name, label)
        .then((e) => {
          this.store.put(e);
        })
        .catch((e: unknown) => {
          if (e instanceof ApiError && e.status === 404) this.store.remove(label);
          else if (!(e instanceof ApiError && e.offline)) this.toast(e);
        });
    }
  }
}
