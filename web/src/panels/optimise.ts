// Optimise: run a study (docs/formats.md study files) or a problem on the
// selected curve as a server job; a live convergence graph from the job's
// SSE events; for two objectives a Pareto explorer whose points preview their
// curve on hover and apply it on click (one undo step); cancel keeps the best.

import uPlot from 'uplot';
import type { App } from '../app';
import { handlesOf } from '../store/curves';
import type {
  CurveFile,
  GenerationEvent,
  Job,
  ParetoCandidate,
  TorsionFrontMember,
} from '../api/types';
import { NurbsEvaluator } from '../geometry/nurbs';
import { logMagnitude, paddedRange, tickLabels } from '../graphs/scale';
import type { Vec3 } from '../viewport/math';
import { toVec3 } from '../viewport/viewports';
import { StudyForm, studyTemplate, type Study, type StudyKind } from './study-form';

/**
 * An `optimise` job request (POST /api/jobs): a problem file (docs/formats.md
 * "Problem files") with the algorithm and its budget; two objectives so the
 * Pareto explorer has a front to show.
 */
export const PROBLEM_TEMPLATE = {
  problem: {
    name: 'two-objective',
    variables: [
      { name: 'x', lower: -2, upper: 2 },
      { name: 'y', lower: -2, upper: 2 },
    ],
    objectives: ['x^2 + y^2', '(x - 1)^2 + (y - 1)^2'],
  },
  algorithm: 'nsga2',
  population: 40,
  generations: 40,
  seed: 1,
};

/** The start points of docs/formats.md's curvature-matching example (thesis Example 1). */
const DEFAULT_POINTS = [
  [0, 0],
  [5, 20],
  [40, 0],
];

export class OptimisePanel {
  private readonly kind: HTMLSelectElement;
  private readonly method: HTMLSelectElement;
  private readonly text: HTMLTextAreaElement;
  private readonly advanced: HTMLInputElement;
  readonly form: StudyForm;
  private readonly start: HTMLButtonElement;
  private readonly cancel: HTMLButtonElement;
  private readonly info: HTMLElement;
  private readonly runs: HTMLElement;
  private readonly convEl: HTMLElement;
  private readonly paretoEl: HTMLElement;
  private conv: uPlot | null = null;
  private pareto: uPlot | null = null;
  private es: EventSource | null = null;
  job: string | null = null;
  running = false;
  readonly generations: GenerationEvent[] = [];
  front: ParetoCandidate[] = [];
  private label: string | null = null;

  constructor(private readonly app: App) {
    const box = app.panels.optimiseBox;
    box.innerHTML = `
      <div class="row">
        <select id="opt-kind" aria-label="Study kind">
          <option value="match-curvature">curvature matching</option>
          <option value="match-curvature-torsion">curvature + torsion (NSGA-II)</option>
          <option value="fair-knots">knot fairing</option>
          <option value="problem">optimise problem</option>
        </select>
        <select id="opt-method" aria-label="Matching method">
          <option value="ga">ga</option><option value="hybrid">hybrid</option><option value="direct">direct</option>
        </select>
      </div>
      <div id="opt-form" class="study-form" role="group" aria-label="Study settings"></div>
      <label class="inline"><input type="checkbox" id="opt-advanced" aria-label="Advanced: edit the study file as JSON" /> advanced (JSON)</label>
      <textarea id="opt-study" aria-label="Study file (JSON)" spellcheck="false" hidden></textarea>
      <div class="row"><button id="opt-fill" aria-label="Fill the study from the selected curve">From selection</button>
      <button id="opt-start" aria-label="Start the optimisation">Run</button>
      <button id="opt-cancel" aria-label="Cancel the optimisation (keeps the best so far)" disabled>Cancel</button></div>
      <div class="row" id="opt-info" aria-live="polite"></div>
      <div id="opt-conv" class="pareto" aria-label="Convergence graph" role="img"></div>
      <div id="opt-pareto" class="pareto" aria-label="Pareto explorer" role="img" hidden></div>
      <ol id="opt-runs" class="history" aria-label="Study history"></ol>`;
    this.kind = box.querySelector('#opt-kind')!;
    this.method = box.querySelector('#opt-method')!;
    this.text = box.querySelector('#opt-study')!;
    this.advanced = box.querySelector('#opt-advanced')!;
    this.form = new StudyForm(box.querySelector('#opt-form')!, (study) => {
      this.text.value = JSON.stringify(study, null, 1);
    });
    this.advanced.addEventListener('change', () => {
      this.setAdvanced(this.advanced.checked);
    });
    this.start = box.querySelector('#opt-start')!;
    this.cancel = box.querySelector('#opt-cancel')!;
    this.info = box.querySelector('#opt-info')!;
    this.runs = box.querySelector('#opt-runs')!;
    this.convEl = box.querySelector('#opt-conv')!;
    this.paretoEl = box.querySelector('#opt-pareto')!;
    box.querySelector('#opt-fill')!.addEventListener('click', () => {
      void this.fill();
    });
    this.kind.addEventListener('change', () => {
      // ga / hybrid / direct are curvature matching's methods only (NSGA-II has its own).
      this.method.hidden = this.kind.value !== 'match-curvature';
      void this.fill();
    });
    this.method.addEventListener('change', () => {
      void this.fill();
    });
    this.start.addEventListener('click', () => {
      void this.run();
    });
    this.cancel.addEventListener('click', () => {
      if (this.job) void this.app.run(() => this.app.client.cancelJob(this.job!));
    });
    // Until "From selection": the documented example's points (docs/formats.md).
    this.setStudy(studyTemplate('match-curvature', DEFAULT_POINTS, this.method.value));
  }

  /**
   * Fill the study text from the selected curve: the curvature + torsion study is
   * seeded by the server (POST …/study-seed: the curve's points as variables, its
   * end tangents, its κ and τ profiles as targets); the others from its handles.
   */
  async fill(): Promise<void> {
    const e = this.app.selectedEntity;
    const label = this.app.selected;
    if (this.kind.value === 'match-curvature-torsion' && e?.curve && label) {
      const doc = this.app.store.name;
      const study = await this.app.run(() =>
        this.app.client.studySeed(doc, label, { study: 'match-curvature-torsion' }),
      );
      // A newer choice (another kind or curve) made while the seed was on its way wins.
      if (study && this.kindName() === 'match-curvature-torsion' && this.app.selected === label)
        this.setStudy(study);
      return;
    }
    const pts = handlesOf(e?.curve).map((p) =>
      e?.curve && isPlanar(e.curve) ? [p[0], p[1]] : [...p],
    );
    const kind = this.kind.value;
    if (kind === 'problem') {
      this.setStudy(PROBLEM_TEMPLATE);
      return;
    }
    this.setStudy(
      studyTemplate(kind as StudyKind, pts.length ? pts : DEFAULT_POINTS, this.method.value),
    );
  }

  /**
   * Shows a study: in the form (a study kind) and in the JSON text. An optimise problem has no
   * form: its JSON is always shown.
   */
  setStudy(study: Record<string, unknown>): void {
    this.text.value = JSON.stringify(study, null, 1);
    const kind = this.kindName();
    if (kind === 'problem') this.form.show(null, {});
    else this.form.show(kind as StudyKind, structuredClone(study));
    this.showMode();
  }

  /**
   * The advanced view: the study file as JSON text. Leaving it reads the text back into the form;
   * text that is not a JSON object keeps the JSON view open, with a toast saying why.
   */
  setAdvanced(on: boolean): void {
    if (!on && this.kindName() !== 'problem') {
      let parsed: unknown;
      try {
        parsed = JSON.parse(this.text.value);
      } catch (e) {
        parsed = e;
      }
      if (typeof parsed !== 'object' || parsed === null || Array.isArray(parsed)) {
        this.app.toast(
          new Error(
            `the study text is not a JSON object${parsed instanceof Error ? ` (${parsed.message})` : ''}: fix it or fill the study again`,
          ),
        );
        this.advanced.checked = true;
        return;
      }
      this.form.show(this.kindName() as StudyKind, parsed as Study);
    }
    this.advanced.checked = on;
    this.showMode();
  }

  private showMode(): void {
    const json = this.advanced.checked || this.kindName() === 'problem';
    this.text.hidden = !json;
    this.form.root.hidden = json;
  }

  /** The chosen study kind (read afresh: it may change while a request is on its way). */
  private kindName(): string {
    return this.kind.value;
  }

  /** Start the job, follow its events, show its result. */
  async run(): Promise<void> {
    let body: Record<string, unknown>;
    if (this.kindName() !== 'problem' && !this.advanced.checked) {
      const { study, errors } = this.form.read();
      if (errors.length > 0) {
        this.app.setStatus(`Study not started: ${errors.join('; ')}`, true);
        return;
      }
      this.text.value = JSON.stringify(study, null, 1);
    }
    try {
      const parsed = JSON.parse(this.text.value) as Record<string, unknown>;
      body =
        this.kind.value === 'problem'
          ? parsed
          : // docs/server.md: exactly {"document", "study"}; the study file carries the
            // selected curve's data ("From selection"), an extra "entity" member is refused.
            { study: parsed, document: this.app.store.name };
    } catch (e) {
      this.app.toast(
        new Error(`study text is not JSON: ${e instanceof Error ? e.message : String(e)}`),
      );
      return;
    }
    this.label = this.app.selected;
    this.running = true;
    this.generations.length = 0;
    this.front = [];
    const job = await this.app.run(() => this.app.client.startJob(body));
    if (!job) {
      this.running = false;
      return;
    }
    this.job = job.job;
    this.start.disabled = true;
    this.cancel.disabled = false;
    this.info.textContent = `job ${job.job}: ${job.state}`;
    this.follow(job.job);
  }

  private follow(id: string): void {
    this.es?.close();
    const es = new EventSource(this.app.client.jobEventsUrl(id), { withCredentials: true });
    this.es = es;
    es.addEventListener('generation', (ev: MessageEvent<string>) => {
      const g = JSON.parse(ev.data) as GenerationEvent;
      this.generations.push(g);
      this.info.textContent = `generation ${g.generation} · ${g.evaluations} evaluations · best ${g.best.map((b) => (b ?? NaN).toExponential(3)).join(', ')}`;
      this.info.dataset['generations'] = String(this.generations.length);
      this.drawConvergence();
      if (g.front)
        this.drawPareto(g.front.map((o) => ({ objectives: o, variables: [], violation: null })));
    });
    const final = (ev: MessageEvent<string>): void => {
      es.close();
      this.es = null;
      const job = JSON.parse(ev.data) as Job;
      this.finish(job);
    };
    for (const k of ['done', 'failed', 'cancelled']) es.addEventListener(k, final);
    es.onerror = () => {
      if (es.readyState === EventSource.CLOSED && this.running) {
        // The stream ended without a final event (server restart): ask for the job's state.
        void this.app
          .run(() => this.app.client.getJob(id))
          .then((job) => {
            if (job && job.state !== 'running' && job.state !== 'queued') this.finish(job);
            else if (!job) this.finish(null);
          });
      }
    };
  }

  private finish(job: Job | null): void {
    this.running = false;
    this.start.disabled = false;
    this.cancel.disabled = true;
    this.info.dataset['state'] = job?.state ?? 'lost';
    if (!job) {
      this.info.textContent = 'the job was lost (server restarted?)';
      return;
    }
    const best = job.result?.best?.objectives ?? [];
    this.info.textContent = `job ${job.job}: ${job.state}${job.report ? ` after ${job.report.generations} generations, ${job.report.evaluations} evaluations (${job.report.termination})` : ''}${best.length ? ` · best ${best.map((b) => (b ?? NaN).toExponential(3)).join(', ')}` : ''}${job.error ? ` · ${job.error.code}: ${job.error.message}` : ''}`;
    if (job.result?.front && job.result.front.length > 0) this.drawPareto(job.result.front);
    const members = job.result?.result?.front;
    if (members && members.length > 0) this.drawPareto(members.map(studySolution));
    const li = document.createElement('li');
    li.textContent = `${job.job} ${job.state}`;
    const again = document.createElement('button');
    again.textContent = 'Re-run';
    again.setAttribute('aria-label', `Re-run job ${job.job}`);
    const text = this.text.value;
    again.addEventListener('click', () => {
      // The exact JSON that ran, shown as such.
      this.text.value = text;
      this.advanced.checked = true;
      this.showMode();
      void this.run();
    });
    li.appendChild(again);
    this.runs.prepend(li);
    // A study's result curves are stored by the server: listed under the study and selected.
    void this.app.studyFinished(job);
  }

  private drawConvergence(): void {
    const xs = this.generations.map((g) => g.generation);
    const n = this.generations[0]?.best.length ?? 1;
    // Objectives span decades: plotted as log10 (a gap where an objective is 0 or undefined).
    const series = Array.from({ length: n }, (_, k) =>
      Array.from(logMagnitude(this.generations.map((g) => g.best[k] ?? NaN))),
    );
    const data = [xs, ...series] as unknown as uPlot.AlignedData;
    if (this.conv && this.conv.series.length === n + 1) {
      this.conv.setData(data);
      return;
    }
    this.conv?.destroy();
    this.conv = new uPlot(
      {
        width: Math.max(200, this.convEl.clientWidth),
        height: 170,
        legend: { show: false },
        scales: { x: { time: false }, y: {} },
        axes: [
          { stroke: '#aab4c3', label: 'generation', size: 30 },
          { stroke: '#aab4c3', label: 'log10 best', size: 55 },
        ],
        series: [
          {},
          ...series.map((_, k) => ({
            stroke: k ? '#3cbf5a' : '#d64bd6',
            label: `objective ${k + 1}`,
          })),
        ],
      },
      data,
      this.convEl,
    );
  }

  /** The Pareto explorer: objective 1 against objective 2, hover previews, click applies. */
  private drawPareto(front: ParetoCandidate[]): void {
    this.front = front
      .filter((s) => s.objectives.length >= 2)
      .sort((a, b) => (a.objectives[0] ?? 0) - (b.objectives[0] ?? 0));
    if (this.front.length === 0) return;
    this.paretoEl.hidden = false;
    const xs = this.front.map((s) => s.objectives[0] ?? NaN);
    const ys = this.front.map((s) => s.objectives[1] ?? NaN);
    const data = [xs, ys] as unknown as uPlot.AlignedData;
    const xr = paddedRange(xs);
    const yr = paddedRange(ys);
    this.pareto?.destroy();
    this.pareto = new uPlot(
      {
        width: Math.max(200, this.paretoEl.clientWidth),
        height: 170,
        legend: { show: false },
        scales: { x: { time: false, range: [xr.min, xr.max] }, y: { range: [yr.min, yr.max] } },
        // Tick labels with the digits their spacing needs: a study's front can span 1e-5.
        axes: [
          {
            stroke: '#aab4c3',
            label: this.objectiveNames[0],
            size: 30,
            values: (_u, splits) => tickLabels(splits),
          },
          {
            stroke: '#aab4c3',
            label: this.objectiveNames[1],
            size: 65,
            values: (_u, splits) => tickLabels(splits),
          },
        ],
        series: [
          {},
          {
            stroke: '#ffe14d',
            paths: () => null,
            points: { show: true, size: 7, fill: '#ffe14d' },
          },
        ],
        cursor: {
          drag: { x: false, y: false },
          // The member nearest the pointer in the plane: uPlot's own choice is the nearest along x,
          // and two members of a front can stand a pixel apart in x and far apart in y.
          dataIdx: (u, _series, closest) => this.nearestParetoPoint(u) ?? closest,
        },
        hooks: {
          setCursor: [
            (u) => {
              this.preview(u.cursor.idx ?? null);
            },
          ],
        },
      },
      data,
      this.paretoEl,
    );
    this.paretoEl.dataset['points'] = String(this.front.length);
    this.pareto.over.addEventListener('click', () => {
      const i = this.pareto?.cursor.idx;
      if (i !== null && i !== undefined) void this.apply(i);
    });
  }

  /** Axis names of the Pareto explorer: the study's errors, or the problem's objectives. */
  private get objectiveNames(): [string, string] {
    return this.kind.value === 'match-curvature-torsion'
      ? ['curvature error', 'torsion error']
      : ['objective 1', 'objective 2'];
  }

  /** Index of the front member nearest the cursor (plot pixels, both axes), or null off the plot. */
  private nearestParetoPoint(u: uPlot): number | null {
    const { left, top } = u.cursor;
    if (left === undefined || top === undefined || left < 0 || top < 0) return null;
    let best: number | null = null;
    let bestD = Infinity;
    for (let i = 0; i < this.front.length; i++) {
      const o = this.front[i]!.objectives;
      const d = Math.hypot(u.valToPos(o[0] ?? NaN, 'x') - left, u.valToPos(o[1] ?? NaN, 'y') - top);
      if (d < bestD) {
        bestD = d;
        best = i;
      }
    }
    return best;
  }

  /** Page coordinates of Pareto point i (tests, keyboard users' focus ring). */
  paretoPixel(i: number): { x: number; y: number } | null {
    const u = this.pareto;
    const sol = this.front[i];
    if (!u || !sol) return null;
    const r = u.over.getBoundingClientRect();
    return {
      x: r.left + u.valToPos(sol.objectives[0] ?? NaN, 'x'),
      y: r.top + u.valToPos(sol.objectives[1] ?? NaN, 'y'),
    };
  }

  /** Hover: show the candidate's curve (its polyline and handles) as a preview. */
  private preview(i: number | null): void {
    const c = i === null ? undefined : this.front[i]?.curve;
    if (c) this.app.viewports.setPreview(curvePolyline(c), handlesOf(c));
    else this.app.viewports.setPreview([]);
    this.paretoEl.dataset['hover'] = i === null ? '' : String(i);
  }

  /** Click: replace the curve by the candidate (one undo step). */
  async apply(i: number): Promise<void> {
    const s = this.front[i];
    const label = this.label ?? this.app.selected;
    if (!s) return;
    this.paretoEl.dataset['picked'] = String(i);
    if (!s.curve || !label) {
      this.info.textContent = `Pareto point ${i}: objectives ${s.objectives.map((o) => (o ?? NaN).toExponential(3)).join(', ')}; variables ${s.variables.map((v) => v.toPrecision(5)).join(', ')}`;
      return;
    }
    this.app.viewports.setPreview([]);
    await this.app.replaceCurve(label, s.curve);
    this.info.textContent = `applied Pareto point ${i}: ${s.objectives.map((o) => (o ?? NaN).toExponential(3)).join(', ')}`;
  }
}

/**
 * A match-curvature-torsion front member as a Pareto point: its two errors,
 * its data coordinates as the variables, and its spline (the curve the errors
 * were measured on) to preview and apply.
 */
function studySolution(m: TorsionFrontMember): ParetoCandidate {
  return {
    objectives: [m.curvature, m.torsion],
    variables: m.points.flat(),
    violation: null,
    curve: m.curve,
  };
}

/** The preview polyline of a curve: 200 points along a NURBS, else its handles. */
function curvePolyline(c: CurveFile): Vec3[] {
  const e = NurbsEvaluator.of(c);
  if (!e) return handlesOf(c);
  const [a, b] = e.domain;
  const out = new Float64Array(3);
  return Array.from({ length: 200 }, (_, i) => {
    e.derivatives(a + ((b - a) * i) / 199, 0, out);
    return [out[0]!, out[1]!, out[2]!] as Vec3;
  });
}

function isPlanar(c: CurveFile): boolean {
  const pts = handlesOf(c);
  return pts.every((p) => toVec3(p)[2] === 0);
}
