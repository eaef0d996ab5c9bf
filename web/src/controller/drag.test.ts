import { describe, expect, it } from 'vitest';
import { useFetchDouble, settle, type Call } from '../testing/fetch-double';
import {
  change,
  cubic,
  editorWith,
  lastStatus,
  lineAnalysis,
  serverEntity,
} from '../testing/documents';
import type { CurveFile } from '../api/types';
import type { ViewSettings } from '../store/curves';
import type { Vec3 } from '../viewport/math';
import { DragController, type DragHost } from './drag';

// The drag's logic against the page's real Client, store and editor (only fetch is replaced:
// testing/fetch-double.ts); the host records what the views, graphs and panels were asked to do.

const http = useFetchDouble();

const law: CurveFile = {
  kind: 'law',
  domain: [0, 1],
  x: 't',
  y: 't*t',
  z: '0',
} as unknown as CurveFile;

function setup(curve: CurveFile = cubic) {
  const { ed, events } = editorWith(5, [serverEntity(1, curve)]);
  ed.select('1');
  const settings: ViewSettings = { fins: ['curvature'], scale: 1, samples: 40, frames: false };
  const redraws: { label: string; handles?: Vec3[] }[] = [];
  const counts = { graphs: 0, panels: 0, render: 0, ghost: [] as string[] };
  const host: DragHost = {
    editor: ed,
    abscissa: 's',
    analysisSeq: 0,
    settingsOf: () => settings,
    analysisRequest: () => ({ samples: 40, by: 'arclength', fins: ['curvature'], scale: 1 }),
    redrawCurve: (label, handles) => redraws.push(handles ? { label, handles } : { label }),
    updateGraphs: () => counts.graphs++,
    updatePanels: () => counts.panels++,
    setGhost: (label) => counts.ghost.push(label),
    requestRender: () => counts.render++,
    fairing: {
      pointerMoved: () => undefined,
      dragEnded: () => undefined,
      afterGhost: (f) => {
        f();
      },
    },
  };
  const ctl = new DragController(host);
  ed.deferFetch = (label) => label === ctl.settling;
  return { ed, events, ctl, redraws, counts };
}

const handles = (c: CurveFile): Vec3[] =>
  c.kind === 'bezier' ? c.control_points.map((p) => [p[0]!, p[1]!, p[2]!] as Vec3) : [];

/** The cubic with control point `i` at `p`, as the server stores it after the move. */
function movedCubic(i: number, p: Vec3): CurveFile {
  if (cubic.kind !== 'bezier') throw new Error('cubic');
  return { ...cubic, control_points: cubic.control_points.map((q, k) => (k === i ? [...p] : q)) };
}

function moveBody(c: Call): { move: { index: number; to: number[] }[]; continue: boolean } {
  return c.body as { move: { index: number; to: number[] }[]; continue: boolean };
}

/** Answer a drag PATCH as the server does: the moved entity with the change. */
function store(c: Call, revision: number, withAnalysis = false): void {
  const b = moveBody(c);
  c.respond(200, {
    ...change(revision, {
      name: 'move points',
      changed: [1],
      entities: [serverEntity(1, movedCubic(b.move[0]!.index, b.move[0]!.to as unknown as Vec3))],
    }),
    ...(withAnalysis ? { analysis: lineAnalysis(9) } : {}),
  });
}

describe('the drag controller', () => {
  it('sends one PATCH per stored move: moves during a PATCH in flight collapse to the latest', async () => {
    const { ed, ctl } = setup();
    ctl.start('1', 1, handles(cubic));
    expect(ctl.moveTo([11, 21, 0], 1)).toBe(true);
    expect(ctl.moveTo([12, 22, 0], 2)).toBe(true);
    expect(ctl.moveTo([13, 23, 0], 3)).toBe(true);
    await settle();
    expect(http.calls).toHaveLength(1);
    expect(http.calls[0]!.method).toBe('PATCH');
    expect(http.calls[0]!.path).toBe('/api/documents/a.hula/entities/1');
    expect(http.calls[0]!.body).toEqual({
      move: [{ index: 1, to: [11, 21, 0] }],
      continue: false,
      analysis: { samples: 40, by: 'arclength', fins: ['curvature'], scale: 1 },
    });
    store(http.calls[0]!, 6);
    await settle();
    // The latest position only, folded into the same undo step.
    expect(http.calls).toHaveLength(2);
    expect(moveBody(http.calls[1]!)).toMatchObject({
      move: [{ index: 1, to: [13, 23, 0] }],
      continue: true,
    });
    ctl.end();
    expect(ctl.pending).toBe(false);
    store(http.calls[1]!, 7);
    await settle();
    // Settled from the last reply: no GET after the drag.
    expect(http.calls).toHaveLength(2);
    expect(ed.store.entities.get('1')?.curve).toEqual(movedCubic(1, [13, 23, 0]));
    expect(ctl.dragStats.moves).toBe(3);
    expect(ctl.settling).toBeNull();
  });

  it('sends nothing for a pointer move that leaves the point where it is (a snapped grid cell, a release)', async () => {
    const { ctl } = setup();
    ctl.start('1', 2, handles(cubic));
    expect(ctl.moveTo([30, 20, 0], 1)).toBe(false);
    expect(ctl.moveTo(null, 2)).toBe(false);
    ctl.end();
    await settle();
    expect(http.calls).toHaveLength(0);
    expect(ctl.dragStats.moves).toBe(0);
    expect(ctl.dragging).toBe(false);
    expect(ctl.settling).toBeNull();
  });

  it('makes the drag one undo step in the history it shows', async () => {
    const { ed, ctl } = setup();
    ed.store.setHistory({
      steps: [
        { revision: 5, name: 'create', applied: true },
        { revision: 6, name: 'reverse', applied: false },
      ],
    });
    ctl.start('1', 1, handles(cubic));
    ctl.moveTo([11, 21, 0], 1);
    await settle();
    store(http.calls[0]!, 6);
    await settle();
    ctl.moveTo([12, 22, 0], 2);
    await settle();
    store(http.calls[1]!, 6);
    ctl.end();
    await settle();
    // The undone step is gone; the drag's two PATCHes are the one "move points" step.
    expect(ed.store.history?.steps).toEqual([
      { revision: 5, name: 'create', applied: true },
      { revision: 6, name: 'move points', applied: true },
    ]);
  });

  it('puts the curve back as stored, visibly, when the server does not answer a move', async () => {
    const { ed, events, ctl, redraws } = setup();
    ctl.start('1', 1, handles(cubic));
    ctl.moveTo([11, 21, 0], 1);
    ctl.frame();
    expect(ctl.analysisOf('1')).toBeDefined();
    await settle();
    http.calls[0]!.fail();
    await settle();
    // The drag is over; the preview, held handles and drawn handles are the stored curve's.
    expect(ctl.dragging).toBe(false);
    expect(ctl.analysisOf('1')).toBeUndefined();
    expect(ctl.heldCurve('1')).toEqual(cubic);
    expect(ed.store.entities.get('1')?.curve).toEqual(cubic);
    expect(redraws[redraws.length - 1]).toEqual({ label: '1' });
    expect(ctl.handlesOf('1')).toBeUndefined();
    expect(lastStatus(events)).toEqual({
      text: 'Point 1 was not moved: the server did not answer; the curve is back as stored',
      error: true,
    });
    // Moves after the failure and the release send nothing more.
    ctl.moveTo([14, 24, 0], 2);
    ctl.end();
    await settle();
    expect(http.calls).toHaveLength(1);
  });

  it('keeps the moves the server stored when a later one fails', async () => {
    const { ed, ctl } = setup();
    ctl.start('1', 1, handles(cubic));
    ctl.moveTo([11, 21, 0], 1);
    await settle();
    ctl.moveTo([15, 25, 0], 2);
    store(http.calls[0]!, 6);
    await settle();
    http.calls[1]!.fail();
    await settle();
    expect(ed.store.entities.get('1')?.curve).toEqual(movedCubic(1, [11, 21, 0]));
    expect(ctl.heldCurve('1')).toEqual(movedCubic(1, [11, 21, 0]));
  });

  it('draws a Bézier drag from its own evaluation each frame, and counts the redraws', async () => {
    const { ctl, redraws, counts } = setup();
    ctl.start('1', 3, handles(cubic));
    ctl.moveTo([50, 10, 0], 1);
    ctl.frame();
    ctl.frameDrawn(5);
    const a = ctl.analysisOf('1')!;
    // The end point of a Bézier curve is its last control point.
    expect(a.points[a.points.length - 1]).toEqual([50, 10, 0]);
    expect(a.points).toHaveLength(40);
    expect(redraws[redraws.length - 1]?.handles?.[3]).toEqual([50, 10, 0]);
    expect(counts.graphs).toBe(1);
    // A frame with no new position draws nothing and counts nothing.
    ctl.frame();
    ctl.frameDrawn(6);
    expect(ctl.dragStats.redraws).toBe(1);
    expect(ctl.latencies).toEqual([4]);
    ctl.end();
    await settle();
    store(http.calls[0]!, 6);
    await settle();
  });

  it('evaluates a move when its event comes, and draws the latest one when more came before the frame', async () => {
    const { ctl } = setup();
    ctl.start('1', 3, handles(cubic));
    // Evaluated and handed to curve and graphs at the event (a raw pointer update); the frame
    // draws what was prepared without evaluating again.
    ctl.moveTo([50, 10, 0], 1, true);
    const early = ctl.analysisOf('1')!;
    expect(early.points[early.points.length - 1]).toEqual([50, 10, 0]);
    ctl.frame();
    ctl.frameDrawn(5);
    expect(ctl.analysisOf('1')).toBe(early);
    // Two moves before the next frame: the first is evaluated early, the frame draws the second.
    ctl.moveTo([60, 12, 0], 6, true);
    ctl.moveTo([70, 14, 0], 7, true);
    ctl.frame();
    ctl.frameDrawn(9);
    const late = ctl.analysisOf('1')!;
    expect(late.points[late.points.length - 1]).toEqual([70, 14, 0]);
    expect(ctl.dragStats).toMatchObject({ moves: 3, redraws: 2 });
    expect(ctl.latencies).toEqual([4, 3]);
    // The same position evaluated at the frame gives the same analysis as evaluated early.
    const { ctl: other } = setup();
    other.start('1', 3, handles(cubic));
    other.moveTo([70, 14, 0], 7);
    other.frame();
    expect(other.analysisOf('1')).toEqual(late);
    ctl.end();
    other.end();
    await settle();
  });

  it('follows the server for a curve the page cannot evaluate (no local preview)', async () => {
    const { ctl } = setup(law);
    ctl.start('1', 0, [[0, 0, 0]]);
    ctl.moveTo([1, 0, 0], 1);
    ctl.frame();
    ctl.frameDrawn(2);
    expect(ctl.analysisOf('1')).toBeUndefined();
    expect(ctl.dragStats.redraws).toBe(0);
    ctl.end();
    await settle();
    expect(http.calls).toHaveLength(1);
    http.calls[0]!.respond(200, change(6, { changed: [1], entities: [serverEntity(1, law)] }));
    await settle();
  });

  it('replaces the preview with the analysis the last reply brought, asking for nothing more', async () => {
    const { ed, ctl } = setup();
    ctl.start('1', 1, handles(cubic));
    ctl.moveTo([11, 21, 0], 1);
    ctl.frame();
    expect(ctl.analysisOf('1')?.points).toHaveLength(40);
    ctl.end();
    await settle();
    store(http.calls[0]!, 6, true);
    await settle();
    expect(ctl.analysisOf('1')?.points).toHaveLength(9);
    expect(ed.store.analyses.get('1')?.points[8]).toEqual([8, 0, 0]);
    // The page's store listener skips the analysis request for this entity once.
    expect(ctl.takeFresh('1')).toBe(true);
    expect(ctl.takeFresh('1')).toBe(false);
    expect(http.calls).toHaveLength(1);
  });
});
