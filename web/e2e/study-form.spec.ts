// The study setup as a form (one field per documented member of the study kind) in Debian's
// chromium against a real `hula serve`: a refused value is named at its field and nothing runs;
// the form's study runs as a job whose resolved study (the server's echo) carries the form's
// values; the JSON stays available as "advanced" and edits there come back into the form.
import { test, type Page } from '@playwright/test';
import { addCurve, api, expect, idle, needsDocuments, newDoc, openApp, shot } from './fixtures';

type Study = Record<string, unknown> & { ga?: Record<string, unknown> };

const field = (page: Page, path: string) => page.getByLabel(path, { exact: true });

test('the study form names a refused field, runs what it shows, and keeps the JSON as advanced', async ({
  page,
}) => {
  needsDocuments();
  const doc = await newDoc('study-form');
  const label = await addCurve(doc, 'pts', {
    kind: 'interpolated',
    points: [
      [0, 0],
      [5, 20],
      [40, 0],
    ],
  });
  await openApp(page, doc);
  await page.evaluate((l) => {
    window.__hula.app.select(l);
  }, label);
  await idle(page);
  await page.locator('#opt-kind').selectOption('match-curvature');
  await page.locator('#opt-fill').click();
  // A form, not a text area: the JSON is hidden until "advanced" is ticked.
  await expect(page.getByRole('group', { name: 'Study settings' })).toBeVisible();
  await expect(page.locator('#opt-study')).toBeHidden();
  // An odd population is refused at its field, by name, and Run starts nothing.
  await field(page, 'ga.population').fill('41');
  await expect(page.locator('[data-for="ga.population"]')).toHaveText(
    'ga.population = 41 must be an even integer ≥ 2',
  );
  await page.locator('#opt-start').click();
  await expect(page.locator('#status')).toContainText(
    'Study not started: ga.population = 41 must be an even integer ≥ 2',
  );
  expect(await page.evaluate(() => window.__hula.app.optimise.job)).toBeNull();
  await shot(page, 'study-form-refused', { x: 1100, y: 0, width: 300, height: 860 });
  // Valid values: a small real-coded GA over 24 samples, points free by ±3.
  await field(page, 'ga.population').fill('12');
  await expect(page.locator('[data-for="ga.population"]')).toBeEmpty();
  await field(page, 'ga.generations').fill('4');
  await field(page, 'ga.algorithm').selectOption('real');
  await field(page, 'samples').fill('24');
  await field(page, 'upper').fill('3');
  await field(page, 'seed').fill('7');
  // The advanced view is that study as JSON; an edit there comes back into the form.
  await page.locator('#opt-advanced').check();
  const shown = JSON.parse(await page.locator('#opt-study').inputValue()) as Study;
  expect(shown['samples']).toBe(24);
  expect(shown['seed']).toBe(7);
  expect(shown.ga).toMatchObject({ algorithm: 'real', population: 12, generations: 4 });
  expect(shown['lower']).toEqual([
    [0, 0],
    [3, 3],
    [3, 3],
  ]);
  expect(shown['upper']).toEqual(shown['lower']);
  await page.locator('#opt-study').fill(JSON.stringify({ ...shown, samples: 30 }));
  await page.locator('#opt-advanced').uncheck();
  await expect(field(page, 'samples')).toHaveValue('30');
  await page.locator('#opt-start').click();
  await expect(page.locator('#opt-info')).toHaveAttribute('data-state', 'done', {
    timeout: 45_000,
  });
  await idle(page);
  // The server ran exactly the form's study: its resolved echo carries every value.
  const job = await api<{ result: { result: { study: Study } } }>(
    'GET',
    `/api/jobs/${encodeURIComponent(String(await page.evaluate(() => window.__hula.app.optimise.job)))}`,
  );
  const ran = job.result.result.study;
  expect(ran['samples']).toBe(30);
  expect(ran['seed']).toBe(7);
  expect(ran.ga).toMatchObject({ algorithm: 'real', population: 12, generations: 4 });
  expect(ran['lower']).toEqual(shown['lower']);
  expect(ran['upper']).toEqual(shown['upper']);
});
