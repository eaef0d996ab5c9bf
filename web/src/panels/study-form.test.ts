import { describe, expect, it } from 'vitest';
import {
  STUDY_FIELDS,
  applyField,
  fieldText,
  getPath,
  parseField,
  setPath,
  studyTemplate,
  type FieldSpec,
  type StudyKind,
} from './study-form';

const field = (kind: StudyKind, path: string): FieldSpec =>
  STUDY_FIELDS[kind].find((f) => f.path === path)!;

const KINDS: StudyKind[] = ['match-curvature', 'match-curvature-torsion', 'fair-knots'];
const POINTS = [
  [0, 0, 0],
  [5, 20, 1],
  [40, 0, 2],
];

describe('study JSON paths', () => {
  it('set a nested member, creating its objects, and remove it, pruning objects left empty', () => {
    const s: Record<string, unknown> = { seed: 1 };
    setPath(s, 'ga.population', 40);
    expect(s).toEqual({ seed: 1, ga: { population: 40 } });
    setPath(s, 'ga.generations', 10);
    setPath(s, 'ga.population', undefined);
    expect(getPath(s, 'ga.generations')).toBe(10);
    setPath(s, 'ga.generations', undefined);
    expect(s).toEqual({ seed: 1 });
    setPath(s, 'lm.max_iterations', undefined);
    expect(s).toEqual({ seed: 1 });
  });
});

describe('study form fields', () => {
  it('refuse values outside the documented range with a message naming the member', () => {
    expect(parseField(field('match-curvature', 'ga.population'), '41').error).toBe(
      'ga.population = 41 must be an even integer ≥ 2',
    );
    expect(parseField(field('match-curvature', 'samples'), '1').error).toBe(
      'samples = 1 must be an integer ≥ 2',
    );
    expect(parseField(field('match-curvature', 'samples'), '2.5').error).toMatch(/^samples = 2.5 /);
    expect(parseField(field('match-curvature-torsion', 'nsga2.population'), '2').error).toBe(
      'nsga2.population = 2 must be an even integer ≥ 4',
    );
    expect(parseField(field('match-curvature-torsion', 'torsion_weight'), '0').error).toBe(
      'torsion_weight = 0 must be a number > 0',
    );
    expect(parseField(field('match-curvature', 'upper'), '-1').error).toBe(
      'upper = -1 must be a number ≥ 0',
    );
    expect(parseField(field('fair-knots', 'energy'), 'stretch').error).toBe(
      'energy = "stretch" is not one of bending, variation',
    );
    expect(parseField(field('match-curvature', 'seed'), 'x').error).toMatch(/^seed = x /);
  });
  it('accept values in range; an empty optional field leaves the member out', () => {
    expect(parseField(field('match-curvature', 'ga.population'), ' 40 ').value).toBe(40);
    expect(parseField(field('match-curvature', 'samples'), '').value).toBeUndefined();
    expect(parseField(field('fair-knots', 'energy'), 'variation').value).toBe('variation');
    expect(parseField(field('match-curvature-torsion', 'polish'), false).value).toBe(false);
  });
  it('give back the same study when nothing is edited, for every kind and field', () => {
    for (const kind of KINDS)
      for (const method of ['ga', 'hybrid', 'direct']) {
        const study = studyTemplate(kind, POINTS, method);
        const copy = structuredClone(study);
        for (const f of STUDY_FIELDS[kind]) {
          if (f.when && !f.when(copy)) continue;
          const parsed = parseField(f, fieldText(f, copy));
          expect(parsed.error, `${kind} ${f.path}`).toBeUndefined();
          // A boolean shown ticked by default writes itself; every other field is unchanged.
          if (f.type !== 'boolean' || getPath(copy, f.path) !== undefined)
            applyField(f, copy, parsed.value);
        }
        expect(copy, `${kind} ${method}`).toEqual(study);
      }
  });
  it('write the offsets of every point but the first into lower and upper alike', () => {
    const study = studyTemplate('match-curvature', POINTS, 'ga');
    const f = field('match-curvature', 'upper');
    applyField(f, study, parseField(f, '2.5').value);
    const want = [
      [0, 0, 0],
      [2.5, 2.5, 2.5],
      [2.5, 2.5, 2.5],
    ];
    expect(study['lower']).toEqual(want);
    expect(study['upper']).toEqual(want);
    expect(fieldText(f, study)).toBe('2.5');
  });
  it('show the GA settings only with a GA and the LM settings only for the hybrid', () => {
    const shown = (method: string): string[] =>
      STUDY_FIELDS['match-curvature']
        .filter((f) => !f.when || f.when(studyTemplate('match-curvature', POINTS, method)))
        .map((f) => f.path);
    expect(shown('direct')).not.toContain('ga.population');
    expect(shown('ga')).toContain('ga.population');
    expect(shown('ga')).not.toContain('lm.max_iterations');
    expect(shown('hybrid')).toContain('lm.max_iterations');
  });
});
