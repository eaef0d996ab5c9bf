import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { useFetchDouble, type Call } from '../testing/fetch-double';
import { cubic, editorWith, lastStatus, serverEntity } from '../testing/documents';
import type { ChangeSet } from '../api/types';
import { Connection, type EventStream } from './connection';

// The reconnection logic against the real Client and editor (fetch replaced:
// testing/fetch-double.ts; timers faked, so the polling runs without waiting).

const http = useFetchDouble();
beforeEach(() => {
  vi.useFakeTimers();
});
afterEach(() => {
  vi.useRealTimers();
});

class Stream implements EventStream {
  readyState = 1;
  closed = false;
  onmessage: ((ev: MessageEvent<string>) => void) | null = null;
  onerror: ((ev: Event) => void) | null = null;
  readonly listeners: ((ev: MessageEvent<string>) => void)[] = [];
  constructor(readonly url: string) {}
  addEventListener(_type: 'change', l: (ev: MessageEvent<string>) => void): void {
    this.listeners.push(l);
  }
  close(): void {
    this.closed = true;
    this.readyState = 2;
  }
}

const error = (code: string) => ({ error: { code, message: code, where: {} } });

function setup() {
  const { ed, events } = editorWith(4, [serverEntity(1, cubic)]);
  const streams: Stream[] = [];
  const reopen: boolean[] = [];
  const applied: ChangeSet[] = [];
  let reloads = 0;
  const conn = new Connection({
    editor: ed,
    reload: async () => {
      reloads++;
      await ed.client.health(); // stands for the document GET: any route that needs the token
      ed.store.revision = 9;
    },
    applyChanges: (c) => applied.push(c),
    offerReopen: (show) => reopen.push(show),
    openEvents: (url) => {
      const s = new Stream(url);
      streams.push(s);
      return s;
    },
  });
  return { ed, events, conn, streams, reopen, applied, reloads: () => reloads };
}

/** Let the polling loop run for `ms` of fake time. */
async function run(ms: number): Promise<void> {
  await vi.advanceTimersByTimeAsync(ms);
}

describe('the connection', () => {
  it('applies the change sets of the event stream', () => {
    const { conn, streams, applied } = setup();
    conn.subscribe();
    expect(streams[0]!.url).toBe('http://hula.test/api/documents/a.hula/events');
    streams[0]!.listeners[0]!({ data: '{"revision": 5, "changed": [1]}' } as MessageEvent<string>);
    expect(applied).toEqual([{ revision: 5, changed: [1] }]);
  });

  it('polls the health route while the server is down, then reloads and follows again', async () => {
    const { conn, streams, events, reopen, reloads } = setup();
    conn.subscribe();
    // The stream fails and the server does not answer.
    let down = true;
    http.auto = (c: Call) => {
      if (down) c.fail();
      else c.respond(200, { status: 'ok' });
    };
    streams[0]!.onerror!(new Event('error'));
    await run(0);
    expect(conn.offline).toBe(true);
    expect(streams[0]!.closed).toBe(true);
    expect(lastStatus(events)?.text).toMatch(/^Server unreachable: reconnecting…/);
    await run(3000);
    const polled = http.calls.length;
    expect(polled).toBeGreaterThan(3);
    expect(reloads()).toBe(0);
    // After ten attempts the page offers to re-open with a new address (a restart on another port).
    await run(20_000);
    expect(reopen).toContain(true);
    down = false;
    await run(2000);
    expect(reloads()).toBe(1);
    expect(conn.offline).toBe(false);
    expect(reopen[reopen.length - 1]).toBe(false);
    expect(streams).toHaveLength(2);
    expect(lastStatus(events)).toEqual({ text: 'Reconnected at revision 9', error: false });
    // Back: no more polling.
    const n = http.calls.length;
    await run(10_000);
    expect(http.calls.length).toBe(n);
  });

  it('stops and offers to re-open when the server answers but refuses the token', async () => {
    const { conn, streams, events, reopen, reloads } = setup();
    conn.subscribe();
    http.auto = (c: Call) => {
      if (c.path === '/api/health') c.respond(200, { status: 'ok' });
      else c.respond(401, error('Unauthorized'));
    };
    streams[0]!.onerror!(new Event('error'));
    await run(0);
    expect(conn.refused).toBe(true);
    expect(conn.offline).toBe(false);
    expect(streams[0]!.closed).toBe(true);
    expect(reopen).toEqual([true]);
    expect(lastStatus(events)).toEqual({
      text: "The server refused this page's token: it was restarted with a new one. Re-open with the address it printed",
      error: true,
    });
    const n = http.calls.length;
    await run(10_000);
    expect(http.calls.length).toBe(n);
    expect(reloads()).toBe(0);
  });
});
