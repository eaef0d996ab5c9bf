import { describe, expect, it } from 'vitest';
import { useFetchDouble, settle } from '../testing/fetch-double';
import { cubic, editorWith, lineAnalysis, serverEntity } from '../testing/documents';
import type { AnalysisRequest } from '../api/types';
import { AnalysisScheduler } from './analysis';

// The analysis scheduling against the real Client and store (fetch replaced: testing/fetch-double.ts).

const http = useFetchDouble();

const request: AnalysisRequest = { samples: 5, by: 'parameter', fins: [], scale: 1 };

describe('the analysis scheduler', () => {
  it('keeps one request per curve in flight and asks once more for what changed meanwhile', async () => {
    const { ed } = editorWith(1, [serverEntity(1, cubic), serverEntity(2, cubic)]);
    const arrived: [string, number][] = [];
    let ended = 0;
    const s = new AnalysisScheduler(
      ed,
      () => request,
      (label, seq) => arrived.push([label, seq]),
      () => ended++,
    );
    s.refresh('1');
    s.refresh('1');
    s.refresh('1');
    s.refresh('2');
    await settle();
    expect(http.calls.map((c) => c.path)).toEqual([
      '/api/documents/a.hula/entities/1/analysis',
      '/api/documents/a.hula/entities/2/analysis',
    ]);
    expect(http.calls[0]!.body).toEqual(request);
    expect(s.pending).toBe(true);
    http.calls[0]!.respond(200, lineAnalysis(5));
    await settle();
    // Curve 1 changed while its request was out: one more request, not two.
    expect(http.calls).toHaveLength(3);
    expect(ed.store.analyses.get('1')?.points[4]).toEqual([4, 0, 0]);
    http.calls[1]!.respond(200, lineAnalysis(5));
    http.calls[2]!.respond(200, lineAnalysis(7));
    await settle();
    expect(s.pending).toBe(false);
    expect(ed.store.analyses.get('1')?.t).toHaveLength(7);
    expect(arrived).toEqual([
      ['1', 1],
      ['2', 2],
      ['1', 3],
    ]);
    expect(ended).toBe(3);
  });

  it('asks nothing for an entity without a curve, and says nothing of a curve deleted meanwhile', async () => {
    const { ed, events } = editorWith(1, [
      { label: 1, kind: 'study', attributes: serverEntity(2, cubic).attributes },
      serverEntity(2, cubic),
    ]);
    const s = new AnalysisScheduler(ed, () => request);
    s.refresh('1');
    s.refresh('2');
    await settle();
    expect(http.calls).toHaveLength(1);
    http.calls[0]!.respond(404, { error: { code: 'NotFound', message: 'no entity 2', where: {} } });
    await settle();
    expect(events.filter((e) => e.type === 'toast')).toHaveLength(0);
    s.refresh('2');
    await settle();
    http.calls[1]!.respond(422, {
      error: { code: 'InvalidArgument', message: 'samples', where: { field: 'samples' } },
    });
    await settle();
    expect(events.filter((e) => e.type === 'toast')).toHaveLength(1);
    expect(ed.store.analyses.has('2')).toBe(false);
  });
});
