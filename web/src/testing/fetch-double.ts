// The HTTP boundary of the unit tests of the commands and the viewport
// controller: a `fetch` that records each request the page's real Client
// sends and answers it when the test says (so a test can hold a reply in
// flight, refuse it with the server's error body, or fail it as a network
// error does). Everything above fetch is the page's own code; the e2e specs
// run the same code against the real `hula serve`.

import { afterEach, beforeEach, vi } from 'vitest';

export interface Call {
  readonly method: string;
  /** The path and query, without the origin. */
  readonly path: string;
  readonly body: unknown;
  /** Answer with a status and a JSON body. */
  respond(status: number, body: unknown): void;
  /** Fail as fetch does when the server is unreachable. */
  fail(): void;
  readonly answered: boolean;
}

export class FetchDouble {
  readonly calls: Call[] = [];
  /** Answers each request as it comes (else the test answers `calls[i]` itself). */
  auto: ((c: Call) => void) | null = null;

  readonly fetch = (input: string | URL | Request, init?: RequestInit): Promise<Response> =>
    new Promise<Response>((resolve, reject) => {
      const url = new URL(
        typeof input === 'string' ? input : input instanceof URL ? input : input.url,
      );
      let answered = false;
      const once = (f: () => void): void => {
        if (answered) throw new Error(`${url.pathname} answered twice`);
        answered = true;
        f();
      };
      const call: Call = {
        method: init?.method ?? 'GET',
        path: url.pathname + url.search,
        body: typeof init?.body === 'string' ? (JSON.parse(init.body) as unknown) : undefined,
        respond: (status, body) => {
          once(() => {
            resolve(new Response(JSON.stringify(body), { status }));
          });
        },
        fail: () => {
          once(() => {
            reject(new TypeError('fetch failed'));
          });
        },
        get answered() {
          return answered;
        },
      };
      this.calls.push(call);
      this.auto?.(call);
    });

  /** Forget the requests and the automatic answer (a new test). */
  reset(): void {
    this.calls.length = 0;
    this.auto = null;
  }

  /** The requests not answered yet. */
  get open(): Call[] {
    return this.calls.filter((c) => !c.answered);
  }
}

/** Let the page's promise chains run (each answer resolves through several awaits). */
export async function settle(): Promise<void> {
  for (let i = 0; i < 20; i++) await Promise.resolve();
  await new Promise((r) => setTimeout(r, 0));
}

/**
 * The global fetch replaced by one FetchDouble for every test of the calling file: emptied and
 * installed before each test, the real fetch restored after it.
 */
export function useFetchDouble(): FetchDouble {
  const http = new FetchDouble();
  beforeEach(() => {
    http.reset();
    vi.stubGlobal('fetch', http.fetch);
  });
  afterEach(() => {
    vi.unstubAllGlobals();
  });
  return http;
}
