// The page's link to the server: the document's event stream (change sets
// from other tabs, clients and jobs), and what happens when the server goes
// away (poll its health until it is back, then reload the document) or
// comes back refusing the page's token (restarted with a new one: say so,
// stop, and offer to re-open with the address it printed).

import { ApiError } from '../api/client';
import type { ChangeSet } from '../api/types';
import type { Editor } from '../editor/editor';

/** The part of the browser's EventSource the page uses. */
export interface EventStream {
  readonly readyState: number;
  onmessage: ((ev: MessageEvent<string>) => void) | null;
  onerror: ((ev: Event) => void) | null;
  addEventListener(type: 'change', listener: (ev: MessageEvent<string>) => void): void;
  close(): void;
}

/** EventSource.CLOSED. */
const CLOSED = 2;

export interface ConnectionHost {
  readonly editor: Editor;
  /** Fetch the document again and load it into the store. */
  reload(): Promise<void>;
  applyChanges(changes: ChangeSet): void;
  /** Show (or hide) the button that re-opens the page with the server's new address. */
  offerReopen(show: boolean): void;
  /** Open the event stream at `url` (the browser's EventSource in the page). */
  openEvents(url: string): EventStream;
}

export class Connection {
  private events: EventStream | null = null;
  /** The server did not answer: polling its health. */
  offline = false;
  /** Whether the server has refused the page's token (it restarted with a new one). */
  refused = false;

  constructor(private readonly host: ConnectionHost) {
    const client = host.editor.client;
    client.onOffline = () => {
      this.goOffline();
    };
    client.onUnauthorized = () => {
      this.unauthorized();
    };
  }

  private get editor(): Editor {
    return this.host.editor;
  }

  close(): void {
    this.events?.close();
    this.events = null;
  }

  /** Follow the document's change sets (other tabs, other clients, jobs). */
  subscribe(): void {
    const { client, store } = this.editor;
    const es = this.host.openEvents(client.documentEventsUrl(store.name));
    const onChange = (ev: MessageEvent<string>): void => {
      try {
        this.host.applyChanges(JSON.parse(ev.data) as ChangeSet);
      } catch (e) {
        this.editor.toast(e);
      }
    };
    es.addEventListener('change', onChange);
    es.onmessage = onChange;
    es.onerror = () => {
      if (es.readyState === CLOSED || !this.offline) void this.checkServer();
    };
    this.events = es;
  }

  private goOffline(): void {
    if (this.offline) return;
    this.offline = true;
    this.editor.setStatus(
      'Server unreachable: reconnecting… (if it restarted on another port, Re-open with its new address)',
      true,
    );
    void this.reconnect();
  }

  /**
   * The event stream failed: is the server down (health fails), or up but
   * refusing the page's token (a restart with a new one: 401 on a route that
   * needs it)?
   */
  private async checkServer(): Promise<void> {
    const client = this.editor.client;
    try {
      await client.health();
      await client.listDocuments();
    } catch (e) {
      if (!(e instanceof ApiError && e.status === 401)) this.goOffline();
    }
  }

  /**
   * The server answers but refuses the token this page was opened with: it
   * was restarted with a new token (or on a new port). Say so, stop polling,
   * and offer to re-open the page with the address the server printed.
   */
  private unauthorized(): void {
    if (this.refused) return;
    this.refused = true;
    this.close();
    this.editor.setStatus(
      "The server refused this page's token: it was restarted with a new one. Re-open with the address it printed",
      true,
    );
    this.host.offerReopen(true);
  }

  /** Poll the health route until the server is back, then reload the document's revision. */
  private async reconnect(): Promise<void> {
    this.close();
    for (let attempt = 0; attempt < 600; attempt++) {
      await new Promise((r) => setTimeout(r, Math.min(2000, 200 + attempt * 100)));
      // A server that moved to another port never answers here: offer the new address.
      if (attempt === 10) this.host.offerReopen(true);
      try {
        await this.editor.client.health();
        await this.host.reload();
        this.offline = false;
        this.host.offerReopen(false);
        this.subscribe();
        this.editor.setStatus(`Reconnected at revision ${this.editor.store.revision}`);
        return;
      } catch (e) {
        // Up but refusing the token (unauthorized() has said so), else still down.
        if (e instanceof ApiError && e.status === 401) {
          this.offline = false;
          return;
        }
      }
    }
    this.editor.setStatus('Server unreachable: reload the page once it runs again', true);
  }
}
