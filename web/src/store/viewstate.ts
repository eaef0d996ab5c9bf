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

/** A curve's colour: fixed by its label, so it stays the same across reloads and tabs. */
export function curveColour(label: string): number {
  const n = Number(label);
  const i = Number.isInteger(n)
    ? Math.abs(n)
    : Array.from({ length: label.length }, (_, k) => label.charCodeAt(k)).reduce(
        (h, c) => (h * 31 + c) >>> 0,
        0,
      );
  return CURVE_PALETTE[i % CURVE_PALETTE.length]!;
}

export const hex = (c: number): string => `#${c.toString(16).padStart(6, '0')}`;
