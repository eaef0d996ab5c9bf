import { describe, expect, it } from 'vitest';
import { ViewStore, type ViewEvent } from './view';

describe('the view store', () => {
  it('names each toggle set, and the abscissa only when it changed', () => {
    const v = new ViewStore();
    const events: ViewEvent[] = [];
    v.subscribe((e) => events.push(e));
    v.set({ snap: false });
    v.set({ abscissa: 's' });
    v.set({ objectSnap: true, abscissa: 't' });
    v.set({ abscissa: 't' });
    expect(events.map((e) => e.changed)).toEqual([['snap'], ['objectSnap', 'abscissa']]);
    expect([v.snap, v.objectSnap, v.abscissa]).toEqual([false, true, 't']);
  });

  it('gives a curve the default settings once, and forgets them with its studies', () => {
    const v = new ViewStore();
    const s = v.settingsOf('3');
    expect(s).toEqual({ fins: [], scale: 1, samples: 200, frames: false });
    s.fins.push('curvature');
    expect(v.settingsOf('3').fins).toEqual(['curvature']);
    v.studyOf.set('3', '2');
    v.clearCurves();
    expect(v.settings.size).toBe(0);
    expect(v.studyOf.size).toBe(0);
    expect(v.settingsOf('3').fins).toEqual([]);
  });
});
