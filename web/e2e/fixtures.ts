// Shared helpers of the e2e tests: the server's API over HTTP (Node's fetch,
// with the token) and the page's own hooks (window.__hula).
import type * as Api from '../src/api/openapi';
import { expect, type Page } from '@playwright/test';
import type { Analysis, CurveFile, DocumentState, Entity, History } from '../src/api/types';
import type { Vec3, ViewName } from '../src/viewport/math';
import {
  analysisFromServer,
  entityFromServer,
  historyFromServer,
  isCurveKind,
} from '../src/api/adapt';

export const base = (): string => process.env['HULA_E2E_BASE']!;
export const token = (): string => process.env['HULA_E2E_TOKEN']!;

export async function api<T>(
  method: string,
  path: string,
  body?: unknown,
  at = base(),
): Promise<T> {
  const init: RequestInit = {
    method,
    headers: { Authorization: `Bearer ${token()}`, 'Content-Type': 'application/json' },
  };
  if (body !== undefined) init.body = JSON.stringify(body);
  const r = await fetch(at + path, init);
  const text = await r.text();
  if (!r.ok) throw new Error(`${method} ${path} → ${r.status}: ${text}`);
  return (text ? JSON.parse(text) : null) as T;
}

export const getDoc = (doc: string): Promise<DocumentState> =>
  api<DocumentState>('GET', `/api/documents/${encodeURIComponent(doc)}`);

/** The document's curve entities, each with its curve file. */
export async function curves(doc: string): Promise<Entity[]> {
  // The listing and the GETs are separate requests: a change the page makes in between (a split, an
  // undo) can remove a listed entity, so a 404 re-reads the listing (a bounded number of times).
  for (let attempt = 1; ; attempt++) {
    const summary = await getDoc(doc);
    try {
      return await Promise.all(
        summary.entities
          .filter((e) => isCurveKind(e.kind))
          .map((e) => entity(doc, String(e.label))),
      );
    } catch (e) {
      if (attempt >= 5 || !(e instanceof Error) || !e.message.includes('→ 404')) throw e;
    }
  }
}

export async function history(doc: string): Promise<History> {
  return historyFromServer(
    await api<Record<string, unknown>>('GET', `/api/documents/${encodeURIComponent(doc)}/history`),
  );
}

/** The server's analysis of an entity, regrouped as the page does (arc-length samples by default). */
export async function analysis(
  doc: string,
  label: string,
  body: Record<string, unknown> = {},
): Promise<Analysis> {
  const req = { samples: 200, by: 'arclength', ...body };
  const j = await api<Api.Analysis>(
    'POST',
    `/api/documents/${encodeURIComponent(doc)}/entities/${encodeURIComponent(label)}/analysis`,
    req,
  );
  return analysisFromServer(j, req.by === 'parameter' ? 'parameter' : 'arclength');
}

/** A curve entity with its curve file (GET …/entities/{label}). */
export async function entity(doc: string, label: string): Promise<Entity> {
  return entityFromServer(
    await api<Record<string, unknown>>(
      'GET',
      `/api/documents/${encodeURIComponent(doc)}/entities/${encodeURIComponent(label)}`,
    ),
  );
}

export async function addCurve(doc: string, name: string, curve: CurveFile): Promise<string> {
  const r = await api<{
    label?: string | number;
    changes: { created?: Entity[]; added?: (string | number)[] };
  }>('POST', `/api/documents/${encodeURIComponent(doc)}/entities`, { name, curve });
  return String(r.label ?? r.changes.created?.[0]?.label ?? r.changes.added?.[0]);
}

/** A fresh document per test, so tests do not see each other's curves. */
export async function newDoc(prefix: string): Promise<string> {
  const name = `${prefix}-${Date.now().toString(36)}.hula`;
  await api('POST', '/api/documents', { name });
  return name;
}

/** Open the workbench on a document and wait until it is idle. */
export async function openApp(page: Page, doc: string, at = base(), tok = token()): Promise<void> {
  await page.goto(`${at}/?token=${tok}#doc=${encodeURIComponent(doc)}`);
  await idle(page);
}

export async function idle(page: Page): Promise<void> {
  await page.waitForFunction(() => typeof window.__hula === 'object');
  await page.evaluate(() => window.__hula.idle());
}

/**
 * A new document (named from `prefix`) holding `curve`, opened in the workbench with that curve selected
 * and the fairing assistant on at `tolerance`. @returns the document and the curve's label.
 */
export async function openFairing(
  page: Page,
  prefix: string,
  name: string,
  curve: CurveFile,
  tolerance: number,
): Promise<{ doc: string; label: string }> {
  const doc = await newDoc(prefix);
  const label = await addCurve(doc, name, curve);
  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
  await page.locator('#fair-tolerance').fill(String(tolerance));
  await page.locator('#fair-tolerance').dispatchEvent('change');
  await page.locator('#fair-on').check();
  return { doc, label };
}

/** Client (page) pixel of a world point in a view, through the page's camera. */
export async function pixelOf(
  page: Page,
  view: ViewName,
  p: Vec3,
): Promise<{ x: number; y: number }> {
  return page.evaluate(
    ([view, p]) => {
      const vp = window.__hula.app.viewports;
      const v = vp.view(view);
      const m = vp.viewProj(view);
      const x = m[0]! * p[0] + m[4]! * p[1] + m[8]! * p[2] + m[12]!;
      const y = m[1]! * p[0] + m[5]! * p[1] + m[9]! * p[2] + m[13]!;
      const w = m[3]! * p[0] + m[7]! * p[1] + m[11]! * p[2] + m[15]!;
      const r = v.el.getBoundingClientRect();
      return { x: r.left + ((x / w + 1) / 2) * r.width, y: r.top + ((1 - y / w) / 2) * r.height };
    },
    [view, p] as const,
  );
}

/** Distance from a point to the nearest sample of a polyline. */
export function distanceToPolyline(p: readonly number[], pts: readonly number[][]): number {
  let best = Infinity;
  for (let i = 0; i + 1 < pts.length; i++) {
    const a = pts[i]!;
    const b = pts[i + 1]!;
    const d = [0, 1, 2].map((k) => (b[k] ?? 0) - (a[k] ?? 0));
    const len2 = d.reduce((s, x) => s + x * x, 0);
    const t =
      len2 === 0
        ? 0
        : Math.max(
            0,
            Math.min(
              1,
              [0, 1, 2].reduce((s, k) => s + ((p[k] ?? 0) - (a[k] ?? 0)) * d[k]!, 0) / len2,
            ),
          );
    const q = [0, 1, 2].map((k) => (a[k] ?? 0) + t * d[k]!);
    best = Math.min(best, Math.hypot(...[0, 1, 2].map((k) => (p[k] ?? 0) - q[k]!)));
  }
  return best;
}

export async function shot(
  page: Page,
  name: string,
  clip?: { x: number; y: number; width: number; height: number },
): Promise<void> {
  await idle(page);
  await page.screenshot({
    path: `../docs/figures/workbench/${name}.png`,
    ...(clip ? { clip } : {}),
  });
}

export { expect };

// examples/workspace/example{1,2,3}-corner.json (thesis 7.4.2 Examples 1–3, the thesis's knots) and
// the data point each drag moves: the corner.
export const fairingExamples: { name: string; curve: CurveFile; point: number }[] = [
  {
    name: 'example1',
    curve: {
      kind: 'interpolated',
      points: [
        [0, 0],
        [100, 0],
        [100, 100],
      ],
      parameters: [0, 0.5, 1],
    },
    point: 1,
  },
  {
    name: 'example2',
    curve: {
      kind: 'interpolated',
      points: [
        [0, 0],
        [50, 0],
        [100, 0],
        [100, 50],
        [100, 100],
      ],
      parameters: [0, 0.286111, 0.50371, 0.713889, 1],
    },
    point: 2,
  },
  {
    name: 'example3',
    curve: {
      kind: 'interpolated',
      points: [
        [0, 0],
        [10, 0],
        [29, 0],
        [31, 2],
        [31, 31],
        [31, 41],
      ],
      parameters: [0, 0.125303, 0.419407, 0.492229, 0.777902, 1],
    },
    point: 3,
  },
];

/**
 * Marks a test that needs the document routes. global-setup.ts has already refused a server whose
 * /api/documents does not answer 200, so this fails (never skips) if that check was bypassed: a
 * missing route must fail the tests that need it, not hide them.
 */
export function needsDocuments(): void {
  if (process.env['HULA_E2E_DOCUMENTS'] !== '1') {
    throw new Error('hula serve did not answer GET /api/documents with 200 (global-setup.ts)');
  }
}
