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
  // Change sets apply in revision order; a duplicate (reply then event) changes nothing.
  it('applies change sets once, in order', () => {
    const s = new DocumentStore('a.hula');
    s.load({ name: 'a.hula', revision: 1, entities: [] });
    const events: string[] = [];
    s.subscribe((e) => events.push(e.type));
    s.apply({
      revision: 2,
      created: [{ label: 'c1', kind: 'curve', name: 'c', attributes: {}, curve }],
    });
    s.apply({
      revision: 2,
      created: [{ label: 'c1', kind: 'curve', name: 'dup', attributes: {}, curve }],
    });
    expect(s.entities.get('c1')?.name).toBe('c');
    s.apply({ revision: 3, deleted: ['c1'] });
    expect(s.entities.size).toBe(0);
    expect(s.revision).toBe(3);
    expect(events).toEqual(['entity', 'removed']);
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
