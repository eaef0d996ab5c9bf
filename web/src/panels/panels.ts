// Side panels: properties with numeric entry (points, weights; knots and
// degree shown, end conditions), interrogation (fins, frames, continuity
// badges), history; and the dialogs (law curve, natural equations, open/new, help).

import type { App } from '../app';
import { ALL_FINS, SPACE_FINS, handlesOf } from '../store/curves';
import type { CurveFile, EndCondition, FinKind, Parameterisation } from '../api/types';
import { el } from './dom';
import { FIN_COLOURS } from '../viewport/viewports';
import { hex } from '../store/viewstate';
import { rebuildDefaults } from '../commands/rebuild';

function section(parent: HTMLElement, title: string, id: string): HTMLElement {
  const d = el('details', { id, open: '' });
  d.appendChild(el('summary', {}, title));
  const body = el('div', { class: 'body' });
  d.appendChild(body);
  parent.appendChild(d);
  return body;
}

export const SHORTCUTS: [string, string][] = [
  ['V', 'select / modify: click a curve, drag its points'],
  ['S', 'interpolated spline: left-click points, right-click to finish, then tangents'],
  ['B', 'Bézier by control points (any view)'],
  ['N', 'NURBS by control points (cubic, uniform clamped knots)'],
  ['H', 'Hermite: point, tangent handle, … right-click to finish'],
  ['L', 'law curve from an expression'],
  ['K', 'curve from κ(s), τ(s) (natural equations)'],
  ['I', 'import a curve file (JSON, STEP or IGES)'],
  ['Enter / right-click', 'finish the current tool'],
  ['Escape', 'cancel the tool, clear the ghost (the faint previous curve), then the selection'],
  ['Ctrl+Z / Ctrl+Shift+Z', 'undo / redo'],
  ['Delete', 'delete the selected curve'],
  ['U', 'insert a knot into the selected curve (at the hovered point, else mid-span)'],
  ['D', 'raise the degree of the selected curve by one'],
  ['X', 'split the selected curve in two (at the hovered point, else mid-domain)'],
  ['W', 'reverse the direction of the selected curve'],
  [
    'Shift+R',
    'rebuild the selected curve with a chosen degree and control-point count (the status shows the deviation; one undo step)',
  ],
  [
    'C',
    'close the selected curve: the periodic cubic through its points or control points (one undo step)',
  ],
  ['Shift+O', 'offset the selected planar curve by a distance: a new curve (one undo step)'],
  [
    'Shift+C',
    'clothoid: the G2 / G1 clothoid or biarc spline through the selected curve’s points, open or closed (with nothing selected: through clicked points; keys 1 2 3 and C choose); a new curve (one undo step)',
  ],
  [
    'Shift+I',
    'intersect: click two curves (the selected one first), or one twice for where it meets itself; the points are marked and read out',
  ],
  [
    'Shift+K',
    'knots: the selected NURBS curve’s interior knots as markers; drag one along the curve to move that knot value (one undo step)',
  ],
  [
    'M',
    "match: click curve A near the end to move, then B near an end or on it (A's end made Gk to it; one undo step)",
  ],
  ['J', 'blend: click two curve ends; a fair curve joins them Gk at both ends (one undo step)'],
  ['0 1 2 3', 'while matching or blending: the continuity G0 … G3 (Blend: G1 … G3)'],
  ['A', "accept the fairing assistant's ghost (one undo step; turn the assistant on in its panel)"],
  ['F', 'fit all'],
  ['Q', 'single / four views'],
  ['1 2 3 4', 'top, front, side, 3-D view alone'],
  ['G', 'grid snapping on/off'],
  ['Shift+G', 'snapping to points and curves on/off (before the grid)'],
  ['P / R', 'pan / orbit with the left button (right-click ends)'],
  ['Wheel, middle drag, Alt-drag', 'zoom, pan, orbit (3-D view)'],
  ['O', 'open or create a document'],
  ['E', 'export the selected curve: menu of JSON (J), STEP (S), IGES (I)'],
  ['?', 'this help'],
];

export class Panels {
  private readonly objects: HTMLElement;
  private objectsKey = '-';
  private readonly props: HTMLElement;
  private readonly interrogate: HTMLElement;
  private readonly historyBox: HTMLElement;
  readonly designBox: HTMLElement;
  readonly optimiseBox: HTMLElement;
  private propsKey = '-';

  constructor(
    private readonly app: App,
    root: HTMLElement,
  ) {
    this.objects = section(root, 'Objects', 'panel-objects');
    this.props = section(root, 'Curve', 'panel-curve');
    this.interrogate = section(root, 'Interrogate', 'panel-interrogate');
    this.designBox = section(root, 'Design by curvature', 'panel-design');
    this.optimiseBox = section(root, 'Optimise', 'panel-optimise');
    this.historyBox = section(root, 'History', 'panel-history');
    this.buildInterrogate();
  }

  /**
   * Follow the document and the selection (called after the App has
   * subscribed, so the views are drawn before the panels): a change during a
   * drag waits for its end (rebuilding the panels per move cost whole frames).
   */
  listen(): void {
    this.app.store.subscribe(() => {
      if (this.app.drags.dragging) this.app.drags.panelsStale = true;
      else this.update();
    });
    this.app.editor.subscribe((e) => {
      if (e.type === 'selection') this.update();
    });
  }

  update(): void {
    this.updateObjects();
    this.updateProps();
    this.updateInterrogate();
    this.updateHistory();
  }

  // ---- object list ----------------------------------------------------------

  /**
   * Every entity of the document: its colour, name and label, and for a curve
   * visibility and lock; a study's result curves say which study made them.
   * A click on a row selects the curve.
   */
  private updateObjects(): void {
    const app = this.app;
    const entities = [...app.store.entities.values()];
    const key = JSON.stringify([
      app.selected,
      entities.map((e) => [
        e.label,
        e.name,
        e.kind,
        e.attributes['visible'],
        e.attributes['locked'],
        app.studyOf.get(String(e.label)),
      ]),
    ]);
    if (key === this.objectsKey) return;
    this.objectsKey = key;
    const box = this.objects;
    box.replaceChildren();
    if (entities.length === 0) {
      box.appendChild(el('p', {}, 'No objects yet: draw a curve (S, B, N, H) or import one (I).'));
      return;
    }
    const list = el('ul', { class: 'objects', 'aria-label': 'Objects' });
    for (const e of entities) {
      const label = String(e.label);
      const isCurve = e.curve !== undefined;
      const li = el('li', { 'data-label': label });
      if (label === app.selected) li.classList.add('selected');
      const swatch = el('span', { class: 'swatch' });
      if (isCurve) swatch.style.background = hex(app.colourOf(label));
      const study = app.studyOf.get(label);
      const studyName = study ? app.store.entities.get(study)?.name : undefined;
      const name = el(
        'button',
        {
          class: 'object-name',
          'aria-label': `Select ${e.name || label}`,
          title: `${e.kind} ${label}`,
        },
        `${e.name || '(unnamed)'} · ${label}${study ? ` ← ${studyName ?? 'study'} ${study}` : ''}`,
      );
      name.addEventListener('click', () => {
        if (isCurve) app.select(label);
      });
      li.append(swatch, name);
      if (isCurve) {
        const vis = el('input', {
          type: 'checkbox',
          'aria-label': `Show ${e.name || label}`,
          title: 'visible',
          'data-visible': label,
        });
        vis.checked = !app.isHidden(label);
        vis.addEventListener('change', () => {
          void app.setHidden(label, !vis.checked);
        });
        const lock = el('input', {
          type: 'checkbox',
          'aria-label': `Lock ${e.name || label}`,
          title: 'locked: not picked in the views, not dragged',
          'data-locked': label,
        });
        lock.checked = app.isLocked(label);
        lock.addEventListener('change', () => {
          void app.setLocked(label, lock.checked);
        });
        const vl = el('label', { class: 'inline', title: 'visible' });
        vl.append(vis, document.createTextNode('show'));
        const ll = el('label', { class: 'inline', title: 'locked' });
        ll.append(lock, document.createTextNode('lock'));
        li.append(vl, ll);
      }
      list.appendChild(li);
    }
    box.appendChild(list);
  }

  // ---- properties ---------------------------------------------------------

  private updateProps(): void {
    const e = this.app.selectedEntity;
    const key = e ? `${e.label}@${JSON.stringify(e.curve)}` : '';
    if (key === this.propsKey) return;
    this.propsKey = key;
    const box = this.props;
    box.replaceChildren();
    if (!e) {
      box.appendChild(el('p', {}, 'No curve selected. Click a curve in a view (V).'));
      return;
    }
    const c = e.curve;
    const label = String(e.label);
    box.appendChild(
      el(
        'div',
        { class: 'row', 'data-testid': 'curve-info' },
        `${e.name} · ${e.label} · ${c?.kind ?? e.kind}`,
      ),
    );
    if (!c) return;
    const pts = handlesOf(c);
    const table = el('table', { 'aria-label': 'Point coordinates' });
    const size = Math.max(1, ...pts.flat().map(Math.abs));
    pts.forEach((p, i) => {
      const tr = el('tr');
      tr.appendChild(el('td', {}, String(i)));
      p.forEach((v, k) => {
        const td = el('td');
        const input = el('input', {
          type: 'number',
          step: 'any',
          value: coordinateText(v, size),
          'aria-label': `point ${i} ${'xyz'[k]!}`,
          'data-point': String(i),
          'data-axis': String(k),
        });
        input.addEventListener('change', () => {
          const to: [number, number, number] = [p[0], p[1], p[2]];
          to[k] = Number(input.value);
          if (Number.isFinite(to[k])) void this.app.movePoint(label, i, to);
        });
        td.appendChild(input);
        tr.appendChild(td);
      });
      if (c.kind === 'nurbs' || c.kind === 'bezier') {
        const td = el('td');
        const w = c.weights?.[i] ?? 1;
        const input = el('input', {
          type: 'number',
          step: 'any',
          min: '0',
          value: String(w),
          'aria-label': `weight ${i}`,
          title: 'weight',
        });
        input.addEventListener('change', () => {
          // A weight is construction data: the curve file with this weight replaces the curve.
          const weights = c.control_points.map((_, k) => c.weights?.[k] ?? 1);
          weights[i] = Number(input.value);
          void this.app.replaceCurve(label, { ...c, weights });
        });
        td.appendChild(input);
        tr.appendChild(td);
      }
      table.appendChild(tr);
    });
    box.appendChild(table);
    if (c.kind === 'nurbs' || c.kind === 'bezier') {
      if (c.kind === 'nurbs')
        box.appendChild(
          el(
            'div',
            { class: 'row' },
            `degree ${c.degree}, knots ${c.knots.map((k) => Number(k.toFixed(4))).join(' ')}`,
          ),
        );
    }
    if (c.kind === 'interpolated') this.interpolatedControls(label, c, box);
  }

  private interpolatedControls(
    label: string,
    c: Extract<CurveFile, { kind: 'interpolated' }>,
    box: HTMLElement,
  ): void {
    const row = el('div', { class: 'row' });
    const par = el('select', { 'aria-label': 'Parameterisation' });
    for (const p of ['uniform', 'chord', 'centripetal'])
      par.appendChild(el('option', { value: p }, p));
    par.value = c.parameterisation ?? 'chord';
    const endSel = (which: 'start' | 'end'): HTMLSelectElement => {
      const s = el('select', { 'aria-label': `${which} condition` });
      const cur = c[which];
      for (const p of ['natural', 'bessel', 'not-a-knot', 'occt'])
        s.appendChild(el('option', { value: p }, `${which}: ${p}`));
      if (typeof cur === 'object')
        s.appendChild(el('option', { value: 'tangent' }, `${which}: tangent`));
      s.value = typeof cur === 'object' ? 'tangent' : (cur ?? 'natural');
      return s;
    };
    const start = endSel('start');
    const end = endSel('end');
    const apply = (): void => {
      const cond = (s: HTMLSelectElement, cur: EndCondition | undefined): EndCondition =>
        s.value === 'tangent' && typeof cur === 'object' ? cur : (s.value as EndCondition);
      const next: CurveFile = {
        kind: 'interpolated',
        points: c.points,
        parameterisation: par.value as Parameterisation,
        start: cond(start, c.start),
        end: cond(end, c.end),
      };
      void this.app.replaceCurve(label, next);
    };
    for (const s of [par, start, end]) s.addEventListener('change', apply);
    row.append(par, start, end);
    box.appendChild(row);
  }

  // ---- interrogation ------------------------------------------------------

  private readonly finBoxes = new Map<FinKind, HTMLInputElement>();
  private scaleInput!: HTMLInputElement;
  private samplesInput!: HTMLInputElement;
  private framesBox!: HTMLInputElement;
  private badges!: HTMLElement;

  private buildInterrogate(): void {
    const box = this.interrogate;
    const row = el('div', { class: 'row', role: 'group', 'aria-label': 'Fins' });
    for (const f of ALL_FINS) {
      const label = el('label', { class: 'inline' });
      const cb = el('input', { type: 'checkbox', 'data-fin': f, 'aria-label': `${f} fins` });
      cb.addEventListener('change', () => {
        this.applySettings();
      });
      // The legend: each fin kind's colour in the views, beside its name.
      const swatch = el('span', {
        class: 'swatch',
        'data-swatch': f,
        title: `${f} fins are drawn in this colour`,
      });
      swatch.style.background = `#${FIN_COLOURS[f].toString(16).padStart(6, '0')}`;
      label.append(cb, swatch, document.createTextNode(f));
      row.appendChild(label);
      this.finBoxes.set(f, cb);
    }
    box.appendChild(row);
    const r2 = el('div', { class: 'row' });
    this.scaleInput = el('input', {
      type: 'number',
      step: 'any',
      value: '1',
      min: '0',
      'aria-label': 'Fin scale',
    });
    this.samplesInput = el('input', {
      type: 'number',
      step: '1',
      value: '200',
      min: '2',
      max: '5000',
      'aria-label': 'Fin density (samples)',
    });
    r2.append(
      el('span', {}, 'scale'),
      this.scaleInput,
      el('span', {}, 'samples'),
      this.samplesInput,
    );
    box.appendChild(r2);
    const r3 = el('div', { class: 'row' });
    const cl = el('label', { class: 'inline' });
    this.framesBox = el('input', {
      type: 'checkbox',
      'aria-label': 'Frenet frames along the curve',
    });
    cl.append(this.framesBox, document.createTextNode('Frenet frames (T N B)'));
    r3.append(cl);
    box.appendChild(r3);
    for (const i of [this.scaleInput, this.samplesInput, this.framesBox]) {
      i.addEventListener('change', () => {
        this.applySettings();
      });
    }
    this.badges = el('div', {
      class: 'row',
      'aria-label': 'Continuity at knots',
      'data-testid': 'continuity',
    });
    box.appendChild(this.badges);
  }

  /**
   * The fin settings from the inputs. An invalid scale or sample count is
   * reported (the input is marked, the status line says what is allowed) and
   * kept on screen for correction; the curve keeps its last valid setting.
   */
  private applySettings(): void {
    const label = this.app.selected;
    if (!label) return;
    const s = this.app.settingsOf(label);
    s.fins = ALL_FINS.filter((f) => this.finBoxes.get(f)!.checked);
    const scale = Number(this.scaleInput.value);
    const samples = Number(this.samplesInput.value);
    const errors: string[] = [];
    const check = (input: HTMLInputElement, ok: boolean, message: string): void => {
      input.classList.toggle('invalid', !ok);
      input.setAttribute('aria-invalid', String(!ok));
      input.title = ok ? '' : message;
      if (!ok) errors.push(message);
    };
    const scaleOk = this.scaleInput.value.trim() !== '' && Number.isFinite(scale) && scale > 0;
    const samplesOk =
      this.samplesInput.value.trim() !== '' &&
      Number.isInteger(samples) &&
      samples >= 2 &&
      samples <= 5000;
    check(
      this.scaleInput,
      scaleOk,
      `Fin scale must be a number > 0 (got "${this.scaleInput.value}"); the fins keep scale ${s.scale}`,
    );
    check(
      this.samplesInput,
      samplesOk,
      `Fin samples must be a whole number from 2 to 5000 (got "${this.samplesInput.value}"); the fins keep ${s.samples}`,
    );
    if (scaleOk) s.scale = scale;
    if (samplesOk) s.samples = samples;
    s.frames = this.framesBox.checked;
    if (errors.length) this.app.setStatus(errors.join('; '), true);
    this.app.viewStateChanged();
    this.app.refreshAnalysis(label);
  }

  private updateInterrogate(): void {
    const label = this.app.selected;
    const a = label ? this.app.store.analyses.get(label) : undefined;
    if (label) {
      const s = this.app.settingsOf(label);
      for (const [f, cb] of this.finBoxes) {
        cb.checked = s.fins.includes(f);
        // Planar curves: torsion, binormal and Combescure fins carry nothing (8.3–8.6).
        cb.disabled = a?.planar === true && SPACE_FINS.has(f);
      }
      // An input marked invalid keeps what the user typed until it is corrected.
      if (!this.scaleInput.classList.contains('invalid')) this.scaleInput.value = String(s.scale);
      if (!this.samplesInput.classList.contains('invalid'))
        this.samplesInput.value = String(s.samples);
      this.framesBox.checked = s.frames;
    }
    this.badges.replaceChildren();
    for (const f of a?.features ?? []) {
      if (f.kind !== 'knot' || !f.continuity) continue;
      const b = el(
        'span',
        {
          class: `badge ${f.continuity.split(/[ /]/)[0]!.toLowerCase()}`,
          title: `knot t = ${f.t}`,
        },
        `t=${Number(f.t.toFixed(3))} ${f.continuity}`,
      );
      this.badges.appendChild(b);
    }
    const infl = (a?.features ?? []).filter((f) => f.kind === 'inflection').length;
    if (a)
      this.badges.appendChild(
        el('span', { class: 'badge' }, `${a.planar ? 'planar' : 'space'} · ${infl} inflection(s)`),
      );
  }

  // ---- history --------------------------------------------------------------

  private updateHistory(): void {
    const h = this.app.store.history;
    const box = this.historyBox;
    box.replaceChildren();
    box.classList.add('history');
    const row = el('div', { class: 'row' });
    const u = el('button', { 'aria-label': 'Undo' }, 'Undo');
    u.addEventListener('click', () => void this.app.undo());
    const r = el('button', { 'aria-label': 'Redo' }, 'Redo');
    r.addEventListener('click', () => void this.app.redo());
    row.append(u, r, el('span', {}, `revision ${this.app.store.revision}`));
    box.appendChild(row);
    if (!h) return;
    const ol = el('ol', { 'aria-label': 'Undo history' });
    const current = h.current ?? h.steps.reduce((c, s, i) => (s.applied === false ? c : i), -1);
    h.steps.forEach((s, i) => {
      const li = el('li', { 'data-revision': String(s.revision) }, `${s.revision}: ${s.name}`);
      if (i === current) li.classList.add('current');
      if (i > current) li.classList.add('redo');
      ol.appendChild(li);
    });
    box.appendChild(ol);
  }

  // ---- dialogs ----------------------------------------------------------------

  private dialog(
    title: string,
    build: (form: HTMLFormElement) => void,
    onOk: (form: HTMLFormElement) => void,
  ): void {
    const d = document.getElementById('dialog') as HTMLDialogElement;
    d.replaceChildren();
    const form = el('form', { method: 'dialog', 'aria-label': title });
    form.appendChild(el('h3', {}, title));
    build(form);
    const row = el('div', { class: 'row' });
    const ok = el('button', { value: 'ok', type: 'submit' }, 'OK');
    const cancel = el('button', { value: 'cancel', type: 'button' }, 'Cancel');
    cancel.addEventListener('click', () => {
      d.close();
    });
    row.append(ok, cancel);
    form.appendChild(row);
    form.addEventListener('submit', (ev) => {
      ev.preventDefault();
      d.close();
      onOk(form);
    });
    d.appendChild(form);
    d.showModal();
  }

  private field(
    form: HTMLFormElement,
    label: string,
    name: string,
    value: string,
    textarea = false,
  ): void {
    const l = el('label', {}, label);
    const i = textarea ? el('textarea', { name }) : el('input', { name, value });
    if (textarea) i.textContent = value;
    i.setAttribute('aria-label', label);
    l.appendChild(i);
    form.appendChild(l);
  }

  lawDialog(): void {
    this.dialog(
      'Law curve',
      (f) => {
        this.field(
          f,
          'Expression vec(x, y[, z]) of the parameter',
          'expression',
          'vec(30*cos(t), 30*sin(t), 8*t)',
        );
        this.field(f, 'Parameter', 'parameter', 't');
        this.field(f, 'Domain start', 'from', '0');
        this.field(f, 'Domain end', 'to', '12.566370614359172');
      },
      (f) => {
        const v = (n: string): string => (f.elements.namedItem(n) as HTMLInputElement).value;
        void this.app
          .createCurve('law', {
            kind: 'law',
            expression: v('expression'),
            parameter: v('parameter'),
            domain: [Number(v('from')), Number(v('to'))],
          })
          .then(() => {
            this.app.fitAll();
          });
      },
    );
  }

  rebuildDialog(): void {
    const label = this.app.editor.needSelection('Rebuild');
    if (!label) return;
    const d = rebuildDefaults(this.app.editor, label);
    this.dialog(
      `Rebuild ${this.app.editor.nameOf(label)}`,
      (f) => {
        this.field(f, 'Degree', 'degree', String(d.degree));
        this.field(f, 'Control points', 'control_points', String(d.controlPoints));
      },
      (f) => {
        const v = (n: string): number =>
          Number((f.elements.namedItem(n) as HTMLInputElement).value);
        void this.app.rebuildCurve(label, {
          degree: v('degree'),
          controlPoints: v('control_points'),
        });
      },
    );
  }

  offsetDialog(): void {
    const label = this.app.editor.needSelection('Offset');
    if (!label) return;
    this.dialog(
      `Offset ${this.app.editor.nameOf(label)}`,
      (f) => {
        this.field(
          f,
          'Distance (positive: to the left of the direction of travel)',
          'distance',
          '5',
        );
      },
      (f) => {
        const v = (f.elements.namedItem('distance') as HTMLInputElement).value;
        void this.app.offsetCurve(label, Number(v));
      },
    );
  }

  clothoidDialog(): void {
    const label = this.app.editor.needSelection('Clothoid');
    if (!label) return;
    this.dialog(
      `Clothoid spline through the points of ${this.app.editor.nameOf(label)}`,
      (f) => {
        const l = el('label', {}, 'Fit');
        const s = el('select', { name: 'fit', 'aria-label': 'Fit' });
        for (const [v, text] of [
          ['g2', 'G2 clothoids'],
          ['g1', 'G1 clothoids'],
          ['biarc', 'biarcs'],
        ] as const)
          s.appendChild(el('option', { value: v }, text));
        l.appendChild(s);
        f.appendChild(l);
        const c = el('label', {}, 'Closed');
        c.appendChild(el('input', { name: 'closed', type: 'checkbox', 'aria-label': 'Closed' }));
        f.appendChild(c);
      },
      (f) => {
        const fit = (f.elements.namedItem('fit') as HTMLSelectElement).value as
          'g1' | 'g2' | 'biarc';
        const closed = (f.elements.namedItem('closed') as HTMLInputElement).checked;
        void this.app.clothoidThrough(label, { fit, closed });
      },
    );
  }

  naturalDialog(): void {
    this.dialog(
      'Curve from natural equations κ(s), τ(s)',
      (f) => {
        this.field(f, 'Curvature κ(s)', 'kappa', '0.02 + 0.0004*s');
        this.field(f, 'Torsion τ(s)', 'tau', '0');
        this.field(f, 'Length', 'length', '120');
      },
      (f) => {
        const v = (n: string): string => (f.elements.namedItem(n) as HTMLInputElement).value;
        void this.app.design.createNatural(v('kappa'), v('tau'), Number(v('length')));
      },
    );
  }

  async openDialog(): Promise<void> {
    const list = await this.app.run(() => this.app.client.listDocuments());
    this.dialog(
      'Open or create a document',
      (f) => {
        const sel = el('select', { name: 'existing', 'aria-label': 'Existing documents' });
        sel.appendChild(el('option', { value: '' }, '(new document)'));
        for (const d of list?.documents ?? [])
          sel.appendChild(el('option', { value: d.name }, d.name));
        const l = el('label', {}, 'Document');
        l.appendChild(sel);
        f.appendChild(l);
        this.field(f, 'New document name', 'name', 'untitled.hula');
      },
      (f) => {
        const existing = (f.elements.namedItem('existing') as HTMLSelectElement).value;
        const name = existing || (f.elements.namedItem('name') as HTMLInputElement).value;
        void this.app.run(() => this.app.open(name));
      },
    );
  }

  /**
   * Re-open the workbench at the address a restarted server printed (its
   * start line's url, token included), on the same document.
   */
  reopenDialog(): void {
    this.dialog(
      "Re-open with the server's new address",
      (f) => {
        f.appendChild(
          el(
            'p',
            {},
            'The server was restarted (new token or port). Paste the address it printed, e.g. http://127.0.0.1:PORT/?token=TOKEN',
          ),
        );
        this.field(f, 'Address', 'address', '');
      },
      (f) => {
        const text = (f.elements.namedItem('address') as HTMLInputElement).value.trim();
        let url: URL;
        try {
          url = new URL(text);
        } catch {
          this.app.setStatus(
            `Re-open: "${text}" is not an address (http://127.0.0.1:PORT/?token=…)`,
            true,
          );
          return;
        }
        if (!url.searchParams.get('token')) {
          this.app.setStatus(
            'Re-open: the address has no ?token= (copy the whole line the server printed)',
            true,
          );
          return;
        }
        url.hash = `doc=${encodeURIComponent(this.app.store.name)}`;
        location.assign(url.toString());
      },
    );
  }

  helpDialog(): void {
    this.dialog(
      'Keyboard shortcuts',
      (f) => {
        const t = el('table', { class: 'help-table' });
        for (const [k, what] of SHORTCUTS) {
          const tr = el('tr');
          tr.append(el('td', {}, k), el('td', {}, what));
          t.appendChild(tr);
        }
        f.appendChild(t);
      },
      () => undefined,
    );
  }
}

/**
 * A coordinate as the point table shows it: rounding noise (below 1e-12 of the
 * curve's size, e.g. z = 3e-15 on a planar curve) reads 0, and no more than 12
 * significant digits, so a narrow field never shows "3.00708" for 3.00708e-15.
 * Only the text is rounded; an edit of another axis keeps the stored value.
 */
export function coordinateText(v: number, size: number): string {
  if (Math.abs(v) < 1e-12 * size) return '0';
  return String(Number(v.toPrecision(12)));
}
