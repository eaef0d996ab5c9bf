import { describe, expect, it } from 'vitest';
import { ApiError } from '../api/client';
import { useFetchDouble, settle } from '../testing/fetch-double';
import {
  attributes,
  change,
  changeSet,
  cubic,
  editorWith,
  lastStatus,
  serverEntity,
} from '../testing/documents';
import { CURVE_PALETTE, curveColour, hex } from '../store/viewstate';
import { createCurve } from './create-curve';
import { deleteSelected } from './delete';
import { undo } from './undo';
import { redo } from './redo';
import { split } from './split';
import { insertKnot } from './insert-knot';
import { elevate } from './elevate';
import { reverse } from './reverse';
import { setHidden, setLocked } from './set-attributes';
import { importFile } from './import-file';
import { replaceCurve } from './replace-curve';
import { movePoint } from './move-point';
import type { Analysis } from '../api/types';

// Each command against the page's real Client, store and editor; only fetch is replaced
// (testing/fetch-double.ts), with answers typed by the server's OpenAPI document.

const http = useFetchDouble();

const nurbs = {
  kind: 'nurbs' as const,
  degree: 2,
  knots: [0, 0, 0, 0.25, 1, 1, 1],
  control_points: [
    [0, 0, 0],
    [1, 2, 0],
    [3, 2, 0],
    [4, 0, 0],
  ],
};

/** A sampled analysis as the store keeps it (only t matters to the commands that read it). */
function analysisAt(t: number[]): Analysis {
  return { t } as unknown as Analysis;
}

describe('commands', () => {
  it('creates a curve in a colour no visible curve has, stores and selects it', async () => {
    const first = hex(CURVE_PALETTE[0]);
    const { ed, events } = editorWith(1, [
      serverEntity(1, cubic, attributes('a', { colour: first })),
    ]);
    const made = createCurve(ed, 'b', cubic, 'click to add points');
    await settle();
    expect(http.calls).toHaveLength(1);
    const c = http.calls[0]!;
    expect([c.method, c.path]).toEqual(['POST', '/api/documents/a.hula/entities']);
    const body = c.body as { name: string; curve: unknown; attributes: { colour: string } };
    expect(body.name).toBe('b');
    expect(body.curve).toEqual(cubic);
    expect(body.attributes.colour).toBe(hex(CURVE_PALETTE[1]));
    c.respond(201, {
      label: 2,
      ...change(2, {
        added: [2],
        entities: [serverEntity(2, cubic, attributes('b', { colour: body.attributes.colour }))],
      }),
    });
    expect(await made).toBe('2');
    expect(ed.selected).toBe('2');
    expect(ed.store.revision).toBe(2);
    expect(curveColour('2', ed.store.entities.get('2')?.attributes)).toBe(CURVE_PALETTE[1]);
    expect(lastStatus(events)).toEqual({
      text: 'Created bezier curve b (2); click to add points',
      error: false,
    });
    // The entity came with the reply: nothing is fetched after it.
    expect(http.calls).toHaveLength(1);
  });

  it('says a command needs a selection and sends nothing', async () => {
    const { ed, events } = editorWith(1, [serverEntity(1, cubic)]);
    for (const [cmd, what] of [
      [deleteSelected, 'Delete'],
      [split, 'Split'],
      [insertKnot, 'Insert knot'],
      [elevate, 'Elevate degree'],
      [reverse, 'Reverse'],
    ] as const) {
      await cmd(ed);
      expect(lastStatus(events)).toEqual({
        text: `${what}: nothing is selected; click a curve first (V)`,
        error: true,
      });
    }
    expect(http.calls).toHaveLength(0);
    expect(ed.store.entities.size).toBe(1);
  });

  it('deletes the selected curve, which leaves the store and the selection', async () => {
    const { ed, events } = editorWith(4, [serverEntity(1, cubic, attributes('arc'))]);
    ed.select('1');
    http.auto = (c) => {
      c.respond(200, change(5, { name: 'delete', removed: [1] }));
    };
    await deleteSelected(ed);
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'DELETE /api/documents/a.hula/entities/1',
    ]);
    expect(ed.store.entities.has('1')).toBe(false);
    expect(ed.store.revision).toBe(5);
    expect(lastStatus(events)?.text).toBe('Deleted arc (1) (Ctrl+Z undoes)');
  });

  it('undoes and redoes, fetching a curve the change names without its data', async () => {
    const moved = {
      ...cubic,
      control_points: [
        [0, 0, 0],
        [10, 25, 0],
        [30, 20, 0],
        [40, 0, 0],
      ],
    };
    const { ed, events } = editorWith(3, [serverEntity(1, moved)]);
    http.auto = (c) => {
      if (c.method === 'POST' && c.path === '/api/documents/a.hula/undo')
        c.respond(200, change(2, { cause: 'undo', name: 'move points', changed: [1] }));
      else if (c.method === 'GET' && c.path === '/api/documents/a.hula/entities/1')
        c.respond(200, serverEntity(1, cubic));
      else if (c.path === '/api/documents/a.hula/redo')
        c.respond(200, {
          revision: 3,
          changes: changeSet(3, {
            cause: 'redo',
            name: 'move points',
            changed: [1],
            entities: [serverEntity(1, moved)],
          }),
        });
      else c.respond(404, { error: { code: 'NotFound', message: c.path, where: {} } });
    };
    await undo(ed);
    await settle();
    expect(lastStatus(events)?.text).toBe('Undone: move points (revision 2)');
    expect(ed.store.revision).toBe(2);
    expect(ed.store.entities.get('1')?.curve).toEqual(cubic);
    await redo(ed);
    await settle();
    expect(lastStatus(events)?.text).toBe('Redone: move points (revision 3)');
    expect(ed.store.entities.get('1')?.curve).toEqual(moved);
    expect(http.calls.map((c) => `${c.method} ${c.path}`)).toEqual([
      'POST /api/documents/a.hula/undo',
      'GET /api/documents/a.hula/entities/1',
      'POST /api/documents/a.hula/redo',
    ]);
  });

  it('splits at the hovered sample and selects the first piece', async () => {
    const { ed, events } = editorWith(1, [serverEntity(1, cubic)]);
    ed.select('1');
    ed.store.setAnalysis('1', analysisAt([0, 0.2, 0.4000771, 0.6, 1]));
    ed.hovered = 2;
    http.auto = (c) => {
      c.respond(200, {
        labels: [2, 3],
        ...change(2, {
          name: 'split',
          added: [2, 3],
          removed: [1],
          entities: [serverEntity(2, cubic), serverEntity(3, cubic)],
        }),
      });
    };
    await split(ed);
    expect(http.calls[0]!.path).toBe('/api/documents/a.hula/entities/1/split');
    expect(http.calls[0]!.body).toEqual({ t: 0.4000771 });
    expect(ed.selected).toBe('2');
    expect([...ed.store.entities.keys()].sort()).toEqual(['2', '3']);
    expect(lastStatus(events)?.text).toBe('Split c1 (1) at t = 0.400077 into 2 and 3');
  });

  it('inserts a knot mid-span of the longest span without a hover', async () => {
    const { ed } = editorWith(1, [serverEntity(1, nurbs)]);
    ed.select('1');
    http.auto = (c) => {
      c.respond(
        200,
        change(2, { name: 'insert knot', changed: [1], entities: [serverEntity(1, nurbs)] }),
      );
    };
    await insertKnot(ed);
    // Spans [0, 0.25] and [0.25, 1]: the middle of the longer.
    expect(http.calls[0]!.body).toEqual({ u: 0.625, times: 1 });
  });

  it('shows a hide at once and takes it back when the server refuses', async () => {
    const { ed, events } = editorWith(1, [serverEntity(1, cubic)]);
    const done = setHidden(ed, '1', true);
    expect(ed.isHidden('1')).toBe(true);
    await settle();
    expect(http.calls[0]!.body).toEqual({ attributes: { visible: false } });
    http.calls[0]!.respond(409, {
      error: { code: 'Conflict', message: 'the document changed', where: {} },
    });
    await done;
    expect(ed.isHidden('1')).toBe(false);
    const toast = events.find((e) => e.type === 'toast');
    expect(toast?.type === 'toast' && toast.error instanceof ApiError && toast.error.status).toBe(
      409,
    );
    // Each pending change and its end was announced, so the views redraw the curve both times.
    expect(events.filter((e) => e.type === 'pending')).toHaveLength(2);
  });

  it('locks a curve through its attribute, stored when the server answers', async () => {
    const { ed, events } = editorWith(1, [serverEntity(1, cubic, attributes('arc'))]);
    http.auto = (c) => {
      c.respond(
        200,
        change(2, {
          name: 'edit attributes',
          attributes_changed: [1],
          entities: [serverEntity(1, cubic, attributes('arc', { locked: true }))],
        }),
      );
    };
    await setLocked(ed, '1', true);
    expect(http.calls[0]!.body).toEqual({ attributes: { locked: true } });
    expect(ed.isLocked('1')).toBe(true);
    expect(ed.pendingAttributes.size).toBe(0);
    expect(lastStatus(events)?.text).toBe('arc (1) locked');
  });

  it('reports an unreachable server on the status line, without a toast, and changes nothing', async () => {
    const { ed, events } = editorWith(3, [serverEntity(1, cubic)]);
    http.auto = (c) => {
      c.fail();
    };
    await undo(ed);
    expect(lastStatus(events)).toEqual({
      text: 'Undo failed: the server is unreachable',
      error: true,
    });
    expect(events.some((e) => e.type === 'toast')).toBe(false);
    expect(ed.store.revision).toBe(3);
    expect(ed.store.entities.get('1')?.curve).toEqual(cubic);
  });

  it('imports a JSON curve file as a curve named after the file, and refuses text that is not JSON', async () => {
    const { ed, events } = editorWith(1, []);
    expect(await importFile(ed, 'broken.json', '{"kind": ')).toBe(false);
    expect(http.calls).toHaveLength(0);
    const toast = events.find((e) => e.type === 'toast');
    expect(toast?.type === 'toast' && String(toast.error)).toMatch(
      /^Error: broken\.json: not JSON/,
    );
    http.auto = (c) => {
      c.respond(201, {
        label: 1,
        ...change(2, { added: [1], entities: [serverEntity(1, cubic, attributes('arc'))] }),
      });
    };
    expect(await importFile(ed, 'arc.json', JSON.stringify(cubic))).toBe(true);
    expect((http.calls[0]!.body as { name: string }).name).toBe('arc');
    expect(ed.selected).toBe('1');
  });

  it('sends STEP and IGES files to the server and selects the first curve read', async () => {
    const { ed } = editorWith(1, []);
    http.auto = (c) => {
      c.respond(200, {
        labels: [1, 2],
        ...change(2, {
          name: 'import',
          added: [1, 2],
          entities: [serverEntity(1, cubic), serverEntity(2, cubic)],
        }),
      });
    };
    expect(await importFile(ed, 'part.STP', 'ISO-10303-21;')).toBe(true);
    expect(http.calls[0]!.path).toBe('/api/documents/a.hula/import');
    expect(http.calls[0]!.body).toEqual({ filename: 'part.STP', content: 'ISO-10303-21;' });
    expect(ed.selected).toBe('1');
  });

  it('replaces a curve and moves one point, one request each', async () => {
    const { ed } = editorWith(1, [serverEntity(1, cubic)]);
    http.auto = (c) => {
      c.respond(200, change(2, { changed: [1], entities: [serverEntity(1, nurbs)] }));
    };
    await replaceCurve(ed, '1', nurbs);
    await movePoint(ed, '1', 2, [3, 3, 0]);
    expect(http.calls.map((c) => [c.method, c.body])).toEqual([
      ['PUT', { curve: nurbs }],
      ['PATCH', { move: [{ index: 2, to: [3, 3, 0] }], continue: false }],
    ]);
    expect(ed.store.entities.get('1')?.curve).toEqual(nurbs);
  });
});
