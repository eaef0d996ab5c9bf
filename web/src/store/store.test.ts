import { describe, expect, it } from 'vitest';
import { DocumentStore } from './store';

const curve = {
  kind: 'bezier' as const,
  control_points: [
    [0, 0, 0],
    [1, 1, 0],
  ],
};

describe('DocumentStore', () => {
  // Whole entities are stored (twice is the same as once); deletions remove; revision follows the change set.
  it('applies change sets idempotently', () => {
    const s = new DocumentStore('a.hula');
    s.load({ name: 'a.hula', revision: 1, entities: [] });
    const events: string[] = [];
    s.subscribe((e) => events.push(e.type));
    const set = {
      revision: 2,
      added: [7],
      entities: [{ label: 7, attributes: { name: 'c' }, ...curve }],
    };
    expect(s.apply(set)).toEqual([]);
    s.apply(set);
    expect([...s.entities.keys()]).toEqual(['7']);
    expect(s.entities.get('7')?.label).toBe('7');
    s.apply({ revision: 1, removed: [7], cause: 'undo' });
    expect(s.entities.size).toBe(0);
    expect(s.revision).toBe(1);
    expect(events).toEqual(['entity', 'entity', 'removed']);
  });

  // A reply's change set is not applied again when its event comes; a deferred entity (a drag) is not stored.
  it('skips the event of a reply and defers a dragged entity', () => {
    const s = new DocumentStore('a.hula');
    s.load({ name: 'a.hula', revision: 1, entities: [] });
    const changes = {
      revision: 2,
      changed: [7],
      entities: [{ label: 7, attributes: {}, ...curve }],
    };
    expect(s.applyReply({ revision: 2, changes }, '7')).toEqual([]);
    expect(s.entities.has('7')).toBe(false);
    expect(s.apply({ revision: 2, changed: [7] })).toEqual([]);
    expect(s.apply({ revision: 3, changed: [7] })).toEqual(['7']);
  });

  // Undo lowers the revision, so a later change reuses an earlier reply's revision: that reply is stored,
  // whether the earlier change's event came before its reply or after it.
  it('stores a reply whose revision an earlier reply had (after an undo)', () => {
    for (const eventFirst of [true, false]) {
      const s = new DocumentStore('a.hula');
      s.load({ name: 'a.hula', revision: 2, entities: [] });
      const made = (label: number) => ({
        revision: 3,
        changes: { revision: 3, added: [label], entities: [{ label, attributes: {}, ...curve }] },
      });
      if (eventFirst) s.apply({ revision: 3, added: [3] });
      s.applyReply(made(3));
      if (!eventFirst) expect(s.apply({ revision: 3, added: [3] })).toEqual([]);
      s.applyReply({ revision: 2, changes: { revision: 2, removed: [3], cause: 'undo' } });
      s.apply({ revision: 2, removed: [3], cause: 'undo' });
      s.applyReply(made(4));
      expect([...s.entities.keys()]).toEqual(['4']);
      expect(s.revision).toBe(3);
      // Its own event is skipped; another tab's change of the next revision is not.
      expect(s.apply({ revision: 3, added: [4] })).toEqual([]);
      expect(s.apply({ revision: 4, added: [9] })).toEqual(['9']);
    }
  });

  // Oli-style change sets name labels only: they come back to be fetched.
  it('returns the labels to fetch for label-only change sets', () => {
    const s = new DocumentStore('a.hula');
    expect(s.apply({ revision: 3, added: [4], changed: [5, 4], attributes_changed: [6] })).toEqual([
      '4',
      '5',
      '6',
    ]);
  });

  // A full reload drops entities the server no longer has.
  it('load replaces the entity set', () => {
    const s = new DocumentStore('a.hula');
    s.load({
      name: 'a.hula',
      revision: 4,
      entities: [{ label: 'x', kind: 'curve', name: 'x', attributes: {} }],
    });
    s.load({ name: 'a.hula', revision: 5, entities: [] });
    expect([...s.entities.keys()]).toEqual([]);
  });
});
