// The workbench's keyboard map (docs/workbench.md, the help dialog): which
// command a key press asks for. The App carries it out; a tool in use and an
// open dialog or text field see the key first (App.key).

import type { ToolName } from '../tools/tools';
import type { ViewName } from '../viewport/math';

export type KeyCommand =
  | { kind: 'undo' }
  | { kind: 'redo' }
  | { kind: 'tool'; tool: ToolName }
  /** A toolbar action (App.action). */
  | { kind: 'action'; action: string }
  /** One view, full size. */
  | { kind: 'view'; view: ViewName }
  | { kind: 'grid-snap' }
  | { kind: 'object-snap' }
  /** Left drag pans or orbits until pressed again (or Escape). */
  | { kind: 'navigate'; mode: 'pan' | 'orbit' }
  /** Leave the navigation mode, then clear the ghost, else the selection. */
  | { kind: 'escape' };

export interface KeyPress {
  readonly key: string;
  readonly ctrlKey: boolean;
  readonly metaKey: boolean;
  readonly altKey: boolean;
  readonly shiftKey: boolean;
}

const TOOLS: Record<string, ToolName> = {
  v: 'select',
  s: 'spline',
  b: 'bezier',
  n: 'nurbs',
  h: 'hermite',
  m: 'match',
  j: 'blend',
};
const ACTIONS: Record<string, string> = {
  l: 'law',
  k: 'natural',
  i: 'import',
  f: 'fit',
  q: 'layout',
  o: 'open',
  e: 'export',
  '?': 'help',
  delete: 'delete',
  backspace: 'delete',
  u: 'insert-knot',
  d: 'elevate',
  x: 'split',
  w: 'reverse',
  c: 'close',
  a: 'accept-fairing',
};
const VIEWS: Record<string, ViewName> = { '1': 'top', '2': 'front', '3': 'side', '4': 'persp' };

/** The command of a key press, or null for a key the workbench leaves alone. */
export function keyCommand(ev: KeyPress): KeyCommand | null {
  const k = ev.key.toLowerCase();
  const ctrl = ev.ctrlKey || ev.metaKey;
  if (ctrl && k === 'z') return { kind: ev.shiftKey ? 'redo' : 'undo' };
  if (ctrl && k === 'y') return { kind: 'redo' };
  if (ctrl || ev.altKey) return null;
  if (ev.shiftKey && k === 'r') return { kind: 'action', action: 'rebuild' };
  if (ev.shiftKey && k === 'o') return { kind: 'action', action: 'offset' };
  if (ev.shiftKey && k === 'c') return { kind: 'action', action: 'clothoid' };
  if (ev.shiftKey && k === 'i') return { kind: 'tool', tool: 'intersect' };
  if (ev.shiftKey && k === 'k') return { kind: 'tool', tool: 'knots' };
  const tool = TOOLS[k];
  if (tool) return { kind: 'tool', tool };
  const action = ACTIONS[k];
  if (action) return { kind: 'action', action };
  const view = VIEWS[k];
  if (view) return { kind: 'view', view };
  if (k === 'g') return { kind: ev.shiftKey ? 'object-snap' : 'grid-snap' };
  if (k === 'p') return { kind: 'navigate', mode: 'pan' };
  if (k === 'r') return { kind: 'navigate', mode: 'orbit' };
  if (k === 'escape') return { kind: 'escape' };
  return null;
}
