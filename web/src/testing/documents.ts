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
