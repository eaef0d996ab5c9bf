// Asks the server for what the views and graphs draw of each curve (its
// analysis with the fins its view settings show): one request per curve in
// flight; a curve that changes meanwhile is asked for once more when that
// request ends, so the latest state wins without a queue of stale requests.

import { ApiError } from '../api/client';
import type { AnalysisRequest } from '../api/types';
import type { Editor } from '../editor/editor';

export class AnalysisScheduler {
  private readonly busy = new Set<string>();
  private readonly dirty = new Set<string>();
  /** Requests started so far (a drag's preview waits for a request number). */
  seq = 0;

  /**
   * `request`: what to ask for a curve; `arrived`: called with request number
   * `seq` before its analysis is stored; `ended`: after each request, answered
   * or not.
   */
  constructor(
    private readonly editor: Editor,
    private readonly request: (label: string) => AnalysisRequest,
    private readonly arrived: (label: string, seq: number) => void = () => undefined,
    private readonly ended: () => void = () => undefined,
  ) {}

  /** Whether a request is in flight. */
  get pending(): boolean {
    return this.busy.size > 0;
  }

  refresh(label: string): void {
    const { client, store } = this.editor;
    // Only curves have an analysis (a study entity is refused by the route).
    if (!store.entities.get(label)?.curve) return;
    if (this.busy.has(label)) {
      this.dirty.add(label);
      return;
    }
    this.busy.add(label);
    const seq = ++this.seq;
    void client
      .analysis(store.name, label, this.request(label))
      .then((a) => {
        this.arrived(label, seq);
        store.setAnalysis(label, a);
      })
      .catch((e: unknown) => {
        if (!(e instanceof ApiError && (e.offline || e.status === 404))) this.editor.toast(e);
      })
      .finally(() => {
        this.busy.delete(label);
        if (this.dirty.delete(label)) this.refresh(label);
        this.ended();
      });
  }
}
