// The study setup as a form: one field per documented member of a study
// file (docs/formats.md "Study files"), per study kind. The form edits a
// study object (from the selection or the server's seed) in place and gives
// back the same JSON a study file holds; a value out of its documented range
// is refused with a message naming the member's JSON path, as the server's
// own errors do. The JSON stays editable as the panel's "advanced" view.

import { el } from './dom';

export type StudyKind = 'match-curvature' | 'match-curvature-torsion' | 'fair-knots';
export type Study = Record<string, unknown>;

export interface FieldSpec {
  /** The member's JSON path in the study file ("ga.population"). */
  path: string;
  label: string;
  type: 'integer' | 'number' | 'choice' | 'boolean' | 'text';
  /** Inclusive bounds; `above`: the value must be greater than it. */
  min?: number;
  max?: number;
  above?: number;
  even?: boolean;
  choices?: readonly string[];
  /** An empty field removes the member (the server's default applies), shown as the placeholder. */
  optional?: string;
  /** Shown only when this holds for the study (e.g. the GA's settings when there is a GA). */
  when?: (s: Study) => boolean;
  /** A field standing for several members: reads and writes them itself. */
  get?: (s: Study) => unknown;
  set?: (s: Study, v: unknown) => void;
  help: string;
}

/** A study file for the selected curve's points (the fields come from docs/formats.md). */
export function studyTemplate(
  kind: StudyKind,
  points: number[][],
  method = 'ga',
): Record<string, unknown> {
  const pts = points.map((p) => [...p]);
  const zero = pts.map((p) => p.map(() => 0));
  const free = pts.map((p, i) => p.map(() => (i === 0 ? 0 : 5)));
  const envelope = { format: 'hula-study', version: 1, study: kind, seed: 1, threads: 1 };
  switch (kind) {
    case 'match-curvature':
      return {
        ...envelope,
        points: pts,
        lower: free,
        upper: free,
        target: { of_points: pts, mirror: true },
        samples: 100,
        method,
        ...(method === 'direct' ? { abscissa: 'arclength' } : {}),
        ...(method === 'direct'
          ? {}
          : { ga: { algorithm: 'real', population: 40, generations: 40 } }),
      };
    case 'match-curvature-torsion':
      return {
        ...envelope,
        points: pts.map((p) => [p[0] ?? 0, p[1] ?? 0, p[2] ?? 0]),
        lower: free.map((p) => [p[0] ?? 0, p[1] ?? 0, p[2] ?? 0]),
        upper: free.map((p) => [p[0] ?? 0, p[1] ?? 0, p[2] ?? 0]),
        start_tangent: [1, 0, 0],
        end_tangent: [1, 0, 0],
        target: { law: '0.02' },
        torsion_target: { law: '0.01' },
        samples: 60,
        nsga2: { population: 40, generations: 40 },
      };
    case 'fair-knots':
      return { ...envelope, points: pts, lower: zero, upper: zero };
  }
}

const isObject = (v: unknown): v is Record<string, unknown> =>
  typeof v === 'object' && v !== null && !Array.isArray(v);

export function getPath(s: Study, path: string): unknown {
  let v: unknown = s;
  for (const k of path.split('.')) {
    if (!isObject(v)) return undefined;
    v = v[k];
  }
  return v;
}

/** Sets (or, for `undefined`, removes) a member, creating the objects on its path; an object left empty is removed. */
export function setPath(s: Study, path: string, value: unknown): void {
  const keys = path.split('.');
  const parents: Record<string, unknown>[] = [s];
  for (const k of keys.slice(0, -1)) {
    const o = parents[parents.length - 1]!;
    if (!isObject(o[k])) {
      if (value === undefined) return;
      o[k] = {};
    }
    parents.push(o[k] as Record<string, unknown>);
  }
  const remove = (o: Record<string, unknown>, k: string): void => {
    Reflect.deleteProperty(o, k);
  };
  const last = keys[keys.length - 1]!;
  if (value === undefined) remove(parents[parents.length - 1]!, last);
  else parents[parents.length - 1]![last] = value;
  for (let i = parents.length - 1; i > 0; i--)
    if (Object.keys(parents[i]!).length === 0) remove(parents[i - 1]!, keys[i - 1]!);
}

/** The offsets of every point but the first (fixed by every study): `lower` and `upper` alike. */
const offsetField: FieldSpec = {
  path: 'upper',
  label: 'move points by ±',
  type: 'number',
  min: 0,
  get: (s) => {
    const upper = s['upper'];
    if (!Array.isArray(upper)) return undefined;
    const all: unknown[] = (upper as unknown[]).slice(1).flat();
    return all.reduce<number>((m, v) => Math.max(m, typeof v === 'number' ? v : 0), 0);
  },
  set: (s, v) => {
    const points = Array.isArray(s['points']) ? (s['points'] as unknown[][]) : [];
    const offsets = points.map((p, i) => p.map(() => (i === 0 ? 0 : (v as number))));
    s['lower'] = offsets;
    s['upper'] = offsets.map((p) => [...p]);
  },
  help: 'lower, upper: how far each coordinate of every data point but the first (fixed) may move, model units; 0 fixes them',
};

const seedField: FieldSpec = {
  path: 'seed',
  label: 'seed',
  type: 'integer',
  min: 0,
  max: 2 ** 32 - 1,
  optional: '1',
  help: 'seeds every random stream of the run (the same seed gives the same answer)',
};

const samplesField = (dflt: string): FieldSpec => ({
  path: 'samples',
  label: 'samples',
  type: 'integer',
  min: 2,
  optional: dflt,
  help: 'N samples of the profiles at u = i/(N − 1)',
});

const abscissaField: FieldSpec = {
  path: 'abscissa',
  label: 'abscissa',
  type: 'choice',
  choices: ['parameter', 'arclength'],
  optional: 'parameter',
  help: 'u is the curve parameter mapped onto [0, 1] (the thesis) or the arc length over the length',
};

const recentresField: FieldSpec = {
  path: 'max_recentres',
  label: 're-centred re-runs',
  type: 'integer',
  min: 0,
  max: 1000,
  optional: '0',
  help: 're-runs with the bounds re-centred on a result that sits on a bound (thesis 7.4.1)',
};

const hasGa = (s: Study): boolean => s['method'] !== 'direct';

/** The form's fields per study kind, each a documented member (docs/formats.md). */
export const STUDY_FIELDS: Record<StudyKind, readonly FieldSpec[]> = {
  'match-curvature': [
    seedField,
    offsetField,
    samplesField('200'),
    abscissaField,
    {
      path: 'target.mirror',
      label: 'mirror the target',
      type: 'boolean',
      when: (s) => isObject(s['target']) && 'of_points' in s['target'],
      help: "target: the selected curve's own κ profile, reversed (κ(1 − u)) when ticked",
    },
    {
      path: 'ga.algorithm',
      label: 'GA coding',
      type: 'choice',
      choices: ['binary', 'real'],
      optional: 'binary',
      when: hasGa,
      help: 'binary-coded or real-coded genetic algorithm',
    },
    {
      path: 'ga.population',
      label: 'GA population',
      type: 'integer',
      min: 2,
      even: true,
      optional: '50',
      when: hasGa,
      help: 'individuals per generation (even)',
    },
    {
      path: 'ga.generations',
      label: 'GA generations',
      type: 'integer',
      min: 1,
      optional: '50',
      when: hasGa,
      help: 'generations of the GA',
    },
    {
      path: 'lm.max_iterations',
      label: 'LM iterations',
      type: 'integer',
      min: 1,
      optional: '200',
      when: (s) => s['method'] === 'hybrid',
      help: 'most Levenberg–Marquardt iterations of the hybrid refinement',
    },
    { ...recentresField, when: hasGa },
  ],
  'match-curvature-torsion': [
    seedField,
    offsetField,
    samplesField('200'),
    abscissaField,
    {
      path: 'nsga2.population',
      label: 'NSGA-II population',
      type: 'integer',
      min: 4,
      even: true,
      optional: '100',
      help: 'individuals per generation (even, ≥ 4)',
    },
    {
      path: 'nsga2.generations',
      label: 'NSGA-II generations',
      type: 'integer',
      min: 1,
      optional: '250',
      help: 'generations of NSGA-II',
    },
    {
      path: 'polish',
      label: 'polish the compromise',
      type: 'boolean',
      help: 'refine the best compromise by Levenberg–Marquardt on both residuals (default on)',
    },
    {
      path: 'torsion_weight',
      label: 'torsion weight',
      type: 'number',
      above: 0,
      optional: '1',
      help: 'weight of the torsion residuals in the polish',
    },
    recentresField,
  ],
  'fair-knots': [
    seedField,
    {
      path: 'energy',
      label: 'energy',
      type: 'choice',
      choices: ['bending', 'variation'],
      optional: 'bending',
      help: 'bending = ∫κ² ds (eq. 30), variation = ∫(dκ/ds)² ds',
    },
    {
      path: 'method',
      label: 'method',
      type: 'choice',
      choices: ['ga', 'deterministic', 'both', 'none'],
      optional: 'both',
      help: 'GA, Nelder–Mead on the interval widths, both, or evaluate only',
    },
    ...(['start', 'end'] as const).map((end): FieldSpec => ({
      path: end,
      label: `${end} condition`,
      type: 'choice',
      choices: ['natural', 'bessel', 'not-a-knot', 'occt'],
      optional: 'natural',
      when: (s) => s[end] === undefined || typeof s[end] === 'string',
      help: `the spline's ${end} condition`,
    })),
    {
      path: 'ga.population',
      label: 'GA population',
      type: 'integer',
      min: 2,
      even: true,
      optional: '50',
      when: (s) => s['method'] !== 'deterministic' && s['method'] !== 'none',
      help: 'individuals per generation (even)',
    },
    {
      path: 'ga.generations',
      label: 'GA generations',
      type: 'integer',
      min: 1,
      optional: '50',
      when: (s) => s['method'] !== 'deterministic' && s['method'] !== 'none',
      help: 'generations of the GA',
    },
  ],
};

/** The range of a numeric field in words ("an even integer ≥ 2", "an integer in [0, 1000]"). */
function rangeText(f: FieldSpec): string {
  const what = f.type === 'integer' ? (f.even ? 'an even integer' : 'an integer') : 'a number';
  if (f.min !== undefined && f.max !== undefined) return `${what} in [${f.min}, ${f.max}]`;
  const parts: string[] = [];
  if (f.min !== undefined) parts.push(`≥ ${f.min}`);
  if (f.above !== undefined) parts.push(`> ${f.above}`);
  if (f.max !== undefined) parts.push(`≤ ${f.max}`);
  return [what, ...parts].join(' ');
}

/**
 * The value of a field's text (or tick) as the study holds it, or a message naming the member:
 * `undefined` for an empty optional field (the member is left out).
 */
export function parseField(
  f: FieldSpec,
  raw: string | boolean,
): { value: unknown; error?: undefined } | { value?: undefined; error: string } {
  if (f.type === 'boolean') return { value: raw === true };
  const text = String(raw).trim();
  if (text === '') {
    if (f.optional !== undefined) return { value: undefined };
    return { error: `${f.path}: a value is required` };
  }
  if (f.type === 'choice') {
    if (!f.choices!.includes(text))
      return { error: `${f.path} = "${text}" is not one of ${f.choices!.join(', ')}` };
    return { value: text };
  }
  if (f.type === 'text') return { value: text };
  const v = Number(text);
  const bad = (): { error: string } => ({ error: `${f.path} = ${text} must be ${rangeText(f)}` });
  if (!Number.isFinite(v)) return bad();
  if (f.type === 'integer' && !Number.isInteger(v)) return bad();
  if (f.even && v % 2 !== 0) return bad();
  if (f.min !== undefined && v < f.min) return bad();
  if (f.max !== undefined && v > f.max) return bad();
  if (f.above !== undefined && !(v > f.above)) return bad();
  return { value: v };
}

/** The text a field shows for the study's current value. */
export function fieldText(f: FieldSpec, s: Study): string | boolean {
  const v = f.get ? f.get(s) : getPath(s, f.path);
  if (f.type === 'boolean') return v === undefined ? f.path === 'polish' : v === true;
  return typeof v === 'number' || typeof v === 'string' ? String(v) : '';
}

/** Writes a parsed value into the study. */
export function applyField(f: FieldSpec, s: Study, value: unknown): void {
  if (f.set) {
    if (value !== undefined) f.set(s, value);
  } else setPath(s, f.path, value);
}

/** The form itself: one labelled input per visible field, its message beside it. */
export class StudyForm {
  private kind: StudyKind | null = null;
  private study: Study = {};
  private readonly inputs = new Map<string, HTMLInputElement | HTMLSelectElement>();
  private readonly messages = new Map<string, HTMLElement>();

  constructor(
    readonly root: HTMLElement,
    private readonly changed: (study: Study) => void,
  ) {}

  /** Shows the fields of `kind` for `study` (which the form then edits). */
  show(kind: StudyKind | null, study: Study): void {
    this.kind = kind;
    this.study = study;
    this.render();
  }

  /** The study as the form has it, with the messages of every field that is refused. */
  read(): { study: Study; errors: string[] } {
    const errors: string[] = [];
    for (const m of this.messages.values()) if (m.textContent) errors.push(m.textContent);
    return { study: this.study, errors };
  }

  private render(): void {
    this.root.replaceChildren();
    this.inputs.clear();
    this.messages.clear();
    if (!this.kind) return;
    for (const f of STUDY_FIELDS[this.kind]) {
      if (f.when && !f.when(this.study)) continue;
      const id = `study-field-${f.path.replace(/\./g, '-')}`;
      const row = el('div', { class: 'study-field' });
      const label = el('label', { for: id, title: f.help }, f.label);
      let input: HTMLInputElement | HTMLSelectElement;
      const current = fieldText(f, this.study);
      if (f.type === 'choice') {
        const select = el('select', { id, 'data-path': f.path, 'aria-label': f.path });
        if (f.optional !== undefined)
          select.appendChild(el('option', { value: '' }, `default (${f.optional})`));
        for (const c of f.choices!) select.appendChild(el('option', { value: c }, c));
        select.value = String(current);
        input = select;
      } else {
        const box = el('input', {
          id,
          'data-path': f.path,
          'aria-label': f.path,
          type: f.type === 'boolean' ? 'checkbox' : 'text',
          inputmode: f.type === 'text' ? 'text' : 'decimal',
        });
        if (f.type === 'boolean') box.checked = current === true;
        else {
          box.value = String(current);
          if (f.optional !== undefined) box.placeholder = f.optional;
        }
        input = box;
      }
      const message = el('div', { class: 'field-error', role: 'alert', 'data-for': f.path });
      input.addEventListener(
        f.type === 'boolean' || f.type === 'choice' ? 'change' : 'input',
        () => {
          const raw =
            input instanceof HTMLInputElement && f.type === 'boolean' ? input.checked : input.value;
          const parsed = parseField(f, raw);
          message.textContent = parsed.error ?? '';
          input.toggleAttribute('aria-invalid', parsed.error !== undefined);
          if (parsed.error !== undefined) return;
          applyField(f, this.study, parsed.value);
          this.changed(this.study);
          // A choice can show or hide other fields (the GA's settings under method "direct").
          if (f.type === 'choice') this.render();
        },
      );
      this.inputs.set(f.path, input);
      this.messages.set(f.path, message);
      row.append(label, input, message);
      this.root.appendChild(row);
    }
  }
}
