import { describe, expect, it } from 'vitest';
import {
  CURVE_PALETTE,
  DEFAULT_VIEW_STATE,
  curveColour,
  DEFAULT_COLOUR,
  freshColour,
  hex,
  loadViewState,
  saveViewState,
  viewStateKey,
  type ViewState,
} from './viewstate';

/** A Storage of a Map (the page's localStorage has the same two methods). */
function memory(): Pick<Storage, 'getItem' | 'setItem'> & { map: Map<string, string> } {
  const map = new Map<string, string>();
  return {
    map,
    getItem: (k) => map.get(k) ?? null,
    setItem: (k, v) => {
      map.set(k, v);
    },
  };
}

describe('view state per document', () => {
  const state: ViewState = {
    selected: '3',
    layout: 'single',
    active: 'front',
    snap: true,
    objectSnap: true,
    abscissa: 't',
    curves: { '3': { fins: ['curvature', 'torsion'], scale: 2.5, samples: 300, frames: true } },
    studyOf: { '9': '8' },
  };

  it('reads back what was stored, under its own document only', () => {
    const s = memory();
    saveViewState(s, 'a.hula', state);
    expect(loadViewState(s, 'a.hula')).toEqual(state);
    expect(loadViewState(s, 'b.hula')).toEqual(DEFAULT_VIEW_STATE);
    expect([...s.map.keys()]).toEqual([viewStateKey('a.hula')]);
  });

  it('snap is off by default', () => {
    expect(loadViewState(memory(), 'x').snap).toBe(false);
  });

  it('takes the default for what is broken or of the wrong type', () => {
    const s = memory();
    s.setItem(viewStateKey('d'), '{not json');
    expect(loadViewState(s, 'd')).toEqual(DEFAULT_VIEW_STATE);
    s.setItem(
      viewStateKey('d'),
      JSON.stringify({
        selected: 7,
        layout: 'triple',
        snap: 'yes',
        curves: { '1': { fins: ['curvature', 'nonsense'], scale: -1, samples: 1.5 }, '2': 3 },
        studyOf: { '1': 2, '3': '4' },
      }),
    );
    const got = loadViewState(s, 'd');
    expect(got.selected).toBeNull();
    expect(got.layout).toBe('quad');
    expect(got.snap).toBe(false);
    expect(got.curves).toEqual({
      '1': { fins: ['curvature'], scale: 1, samples: 200, frames: false },
    });
    expect(got.studyOf).toEqual({ '3': '4' });
  });
});

describe('curve colours', () => {
  it('are fixed by the label and differ for consecutive labels', () => {
    expect(curveColour('1')).toBe(curveColour('1'));
    const first = Array.from({ length: CURVE_PALETTE.length }, (_, i) => curveColour(String(i)));
    expect(new Set(first).size).toBe(CURVE_PALETTE.length);
    // None is the selection's blue.
    expect(first).not.toContain(0x4da3ff);
  });
});

describe('colours of new curves', () => {
  it('take the stored colour attribute over the label, unless it is the server default', () => {
    expect(curveColour('1', { colour: '#5fd0c8' })).toBe(0x5fd0c8);
    expect(curveColour('1', { colour: DEFAULT_COLOUR })).toBe(curveColour('1'));
    expect(curveColour('1', { colour: 'red' })).toBe(curveColour('1'));
    expect(curveColour('1', {})).toBe(curveColour('1'));
  });
  it('give each new curve a colour no visible curve has, while the palette lasts', () => {
    const used: number[] = [];
    for (let i = 0; i < CURVE_PALETTE.length; i++) {
      const c = freshColour(used);
      expect(used).not.toContain(c);
      used.push(c);
    }
    expect(new Set(used).size).toBe(CURVE_PALETTE.length);
    // Past the palette: the least used, in palette order; a colour outside the palette counts for nothing.
    expect(freshColour([...used, CURVE_PALETTE[0], 0x123456])).toBe(CURVE_PALETTE[1]);
    // A hidden curve does not count: only what the caller passes (the visible curves) does.
    expect(freshColour([CURVE_PALETTE[0], CURVE_PALETTE[2]])).toBe(CURVE_PALETTE[1]);
    // The choice survives the trip through the stored "#rrggbb" attribute.
    const c = freshColour([CURVE_PALETTE[0]]);
    expect(curveColour('9', { colour: hex(c) })).toBe(c);
  });
});
