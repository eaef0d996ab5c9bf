// The page's own state of a document (not the document's): selection, fin
// settings per curve, layout, snap, abscissa, the studies its result curves
// came from. Kept in localStorage under one key per document, so a reload (or
// a reopened tab) finds the workbench as it was left. Visibility and lock are
// the document's own attributes (oli), not kept here.

import type { FinKind } from '../api/types';

export interface CurveViewState {
  fins: FinKind[];
  scale: number;
  samples: number;
  frames: boolean;
}

export interface ViewState {
  selected: string | null;
  layout: 'quad' | 'single';
  active: 'top' | 'front' | 'side' | 'persp';
  snap: boolean;
  /** Snap to existing points and curves (before the grid). */
  objectSnap: boolean;
  abscissa: 's' | 't';
  curves: Record<string, CurveViewState>;
  /** Result curves of the studies run from this page: curve label → study label. */
  studyOf: Record<string, string>;
}

export const DEFAULT_VIEW_STATE: ViewState = {
  selected: null,
  layout: 'quad',
  active: 'top',
  snap: false,
  objectSnap: false,
  abscissa: 's',
  curves: {},
  studyOf: {},
};

/** The storage key of a document's view state. */
export const viewStateKey = (doc: string): string => `hulahoops.view:${doc}`;

const FIN_KINDS = new Set<string>([
  'curvature',
  'torsion',
  'normal',
  'binormal',
  'bishop-u',
  'bishop-v',
  'combescure',
]);

const strings = (v: unknown): string[] =>
  Array.isArray(v) ? v.filter((x): x is string => typeof x === 'string') : [];

function curveState(v: unknown): CurveViewState | null {
  if (typeof v !== 'object' || v === null) return null;
  const o = v as Record<string, unknown>;
  const scale = Number(o['scale']);
  const samples = Number(o['samples']);
  return {
    fins: strings(o['fins']).filter((f): f is FinKind => FIN_KINDS.has(f)),
    scale: Number.isFinite(scale) && scale > 0 ? scale : 1,
    samples: Number.isInteger(samples) && samples >= 2 && samples <= 5000 ? samples : 200,
    frames: o['frames'] === true,
  };
}

/**
 * A document's stored view state, member by member: what is missing or not
 * of its type takes the default (a stored state from an older page, or text
 * edited by hand, never breaks the page).
 */
export function loadViewState(storage: Pick<Storage, 'getItem'>, doc: string): ViewState {
  let raw: unknown;
  try {
    raw = JSON.parse(storage.getItem(viewStateKey(doc)) ?? 'null');
  } catch {
    raw = null;
  }
  if (typeof raw !== 'object' || raw === null) return structuredClone(DEFAULT_VIEW_STATE);
  const o = raw as Record<string, unknown>;
  const curves: Record<string, CurveViewState> = {};
  if (typeof o['curves'] === 'object' && o['curves'] !== null)
    for (const [label, v] of Object.entries(o['curves'])) {
      const c = curveState(v);
      if (c) curves[label] = c;
    }
  const active = o['active'];
  return {
    selected: typeof o['selected'] === 'string' ? o['selected'] : null,
    layout: o['layout'] === 'single' ? 'single' : 'quad',
    active:
      active === 'front' || active === 'side' || active === 'persp' || active === 'top'
        ? active
        : 'top',
    snap: o['snap'] === true,
    objectSnap: o['objectSnap'] === true,
    abscissa: o['abscissa'] === 't' ? 't' : 's',
    curves,
    studyOf:
      typeof o['studyOf'] === 'object' && o['studyOf'] !== null
        ? Object.fromEntries(
            Object.entries(o['studyOf']).filter(
              (kv): kv is [string, string] => typeof kv[1] === 'string',
            ),
          )
        : {},
  };
}

export function saveViewState(
  storage: Pick<Storage, 'setItem'>,
  doc: string,
  state: ViewState,
): void {
  try {
    storage.setItem(viewStateKey(doc), JSON.stringify(state));
  } catch {
    // A full or disabled storage: the page works on, without memory.
  }
}

/**
 * The colours curves are drawn in, unselected, each told apart from the
 * others and from the selection's blue (#4da3ff), the fairing ghost's dashed
 * green and the grey "before" ghost.
 */
export const CURVE_PALETTE = [
  0xe8ecf1, 0xf2a65a, 0xf07fb0, 0xe6d36a, 0x5fd0c8, 0xb59cf0, 0xff8a7a, 0xa8c96a,
] as const;

/** The colour attribute the server gives a curve created without one (oli::Attributes). */
export const DEFAULT_COLOUR = '#1f77b4';

/** A palette colour fixed by the label: the colour of a curve whose colour attribute is the default. */
export function paletteColour(label: string): number {
  const n = Number(label);
  const i = Number.isInteger(n)
    ? Math.abs(n)
    : Array.from({ length: label.length }, (_, k) => label.charCodeAt(k)).reduce(
        (h, c) => (h * 31 + c) >>> 0,
        0,
      );
  return CURVE_PALETTE[i % CURVE_PALETTE.length]!;
}

/**
 * A curve's colour: its stored colour attribute ("#rrggbb", kept by the document, so the same
 * across reloads and tabs), or, while that is the server's default, the palette colour of its label.
 */
export function curveColour(label: string, attributes?: Readonly<Record<string, unknown>>): number {
  const c = attributes?.['colour'];
  if (typeof c === 'string' && /^#[0-9a-f]{6}$/.test(c) && c !== DEFAULT_COLOUR)
    return parseInt(c.slice(1), 16);
  return paletteColour(label);
}

/**
 * The colour for a new curve: the first palette colour none of `used` (the visible curves'
 * colours) is; when every one is taken, the one used least (the first such in palette order).
 */
export function freshColour(used: Iterable<number>): number {
  const count = new Map<number, number>(CURVE_PALETTE.map((c) => [c, 0]));
  for (const c of used) if (count.has(c)) count.set(c, count.get(c)! + 1);
  let best: number = CURVE_PALETTE[0];
  for (const c of CURVE_PALETTE) if (count.get(c)! < count.get(best)!) best = c;
  return best;
}

export const hex = (c: number): string => `#${c.toString(16).padStart(6, '0')}`;
