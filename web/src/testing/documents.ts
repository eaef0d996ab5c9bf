// Server answers for the unit tests, typed by the server's OpenAPI document
// (src/api/openapi.ts is generated from it), so a reply a test makes up has
// the shape `hula serve` sends: a wrong member does not compile.

import type * as Api from '../api/openapi';
import type { CurveFile } from '../api/types';
import { Client } from '../api/client';
import { Editor } from '../editor/editor';
import { DocumentStore } from '../store/store';
import { entityFromServer } from '../api/adapt';
import type { EditorEvent } from '../editor/editor';

export function attributes(name: string, more: Partial<Api.Attributes> = {}): Api.Attributes {
  return {
    name,
    colour: '#1f77b4',
    visible: true,
    layer: '',
    locked: false,
    user: {},
    ...more,
  };
}

/** An entity as GET …/entities/{label} and change sets carry it: its curve file's members inline. */
export function serverEntity(
  label: number,
  curve: CurveFile,
  attrs: Api.Attributes = attributes(`c${label}`),
): Api.Entity {
  return { label, attributes: attrs, ...curve };
}

export function changeSet(
  revision: number,
  c: Partial<Omit<Api.ChangeSet, 'revision'>> = {},
): Api.ChangeSet {
  return {
    cause: 'commit',
    name: 'edit',
    added: [],
    changed: [],
    removed: [],
    attributes_changed: [],
    ...c,
    revision,
  };
}

export function change(
  revision: number,
  c: Partial<Omit<Api.ChangeSet, 'revision'>> = {},
): Api.Change {
  return { revision, changes: changeSet(revision, c) };
}

export const cubic: CurveFile = {
  kind: 'bezier',
  control_points: [
    [0, 0, 0],
    [10, 20, 0],
    [30, 20, 0],
    [40, 0, 0],
  ],
};

/** An editor on document "a.hula" at `revision` holding `entities` (its Client calls the global fetch). */
export function editorWith(
  revision: number,
  entities: Api.Entity[],
): { ed: Editor; events: EditorEvent[] } {
  const store = new DocumentStore('a.hula');
  store.load({ name: 'a.hula', revision, entities: entities.map((e) => entityFromServer(e)) });
  const ed = new Editor(new Client('http://hula.test'), store);
  const events: EditorEvent[] = [];
  ed.subscribe((e) => events.push(e));
  return { ed, events };
}

/** The last status line the editor set, and whether it was an error. */
export function lastStatus(events: EditorEvent[]): { text: string; error: boolean } | undefined {
  for (let i = events.length - 1; i >= 0; i--) {
    const e = events[i]!;
    if (e.type === 'status') return { text: e.text, error: e.error };
  }
  return undefined;
}

/** POST …/analysis's answer for the segment from (0,0,0) to (n−1,0,0) sampled at n points (κ = 0). */
export function lineAnalysis(n: number): Api.Analysis {
  const t = Array.from({ length: n }, (_, i) => i / (n - 1));
  const none = t.map(() => null);
  return {
    t,
    s: t.map((_, i) => i),
    points: t.map((_, i) => [i, 0, 0]),
    frames: { T: t.map(() => [1, 0, 0]), N: none, B: none },
    curvature: t.map(() => 0),
    torsion: none,
    curvature_derivative: none,
    speed: t.map(() => n - 1),
    fins: [],
    planarity: { planar: true, normal: null, max_deviation: 0, tolerance: 1e-10 },
    features: {
      inflections: [],
      curvature_extrema: [],
      torsion_extrema: [],
      knots: [],
      curvature_monotonicity: { monotone: true, pieces: [], violations: [] },
      maximum_curvature: { value: 0, t: 0 },
      self_intersections: { tolerance: 1e-9, points: [], overlaps: [] },
    },
  };
}
