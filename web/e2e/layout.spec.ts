// Issue 23 defect 1: the toolbar groups and wraps, so every command is on
// screen and clickable from 1280×720 up, and the status hint is visible.
import { test } from '@playwright/test';
import { expect, needsDocuments, newDoc, openApp, shot } from './fixtures';

for (const size of [
  { width: 1280, height: 720 },
  { width: 1366, height: 768 },
  { width: 1600, height: 1000 },
]) {
  test(`every command and the status hint are on screen at ${size.width}×${size.height}`, async ({
    page,
  }) => {
    needsDocuments();
    await page.setViewportSize(size);
    const doc = await newDoc('layout');
    await openApp(page, doc);
    const boxes = await page.evaluate(() =>
      [...document.querySelectorAll<HTMLElement>('.toolbar button, .toolbar input')].map((b) => {
        const r = b.getBoundingClientRect();
        // What is painted at the button's centre is the button (not covered, not clipped away).
        const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
        return {
          name: b.getAttribute('aria-label') ?? b.textContent,
          left: r.left,
          right: r.right,
          top: r.top,
          bottom: r.bottom,
          reachable: hit === b || b.contains(hit) || hit?.contains(b) === true,
        };
      }),
    );
    expect(boxes.length).toBeGreaterThanOrEqual(20);
    for (const b of boxes) {
      expect(b.left, b.name).toBeGreaterThanOrEqual(0);
      expect(b.right, b.name).toBeLessThanOrEqual(size.width);
      expect(b.bottom, b.name).toBeLessThanOrEqual(size.height);
      expect(b.reachable, b.name).toBe(true);
    }
    // The last command of the bar works by mouse: "?" opens the help.
    await page.getByRole('button', { name: 'Keyboard shortcuts (?)' }).click();
    await expect(page.locator('dialog[open]')).toContainText('Keyboard shortcuts');
    await page.keyboard.press('Escape');
    // The status hint: on screen, wide enough to read, its text not cut at the window's edge.
    const status = await page.locator('#status').boundingBox();
    expect(status).not.toBeNull();
    expect(status!.x + status!.width).toBeLessThanOrEqual(size.width);
    expect(status!.y + status!.height).toBeLessThanOrEqual(size.height);
    await expect(page.locator('#status')).toContainText('Select: click a curve');
    const fits = await page.locator('#status').evaluate((e) => e.scrollWidth <= e.clientWidth + 1);
    expect(fits).toBe(true);
    // The views keep most of the window.
    const views = await page.locator('#viewports').boundingBox();
    expect(views!.height).toBeGreaterThan(size.height * 0.45);
    await shot(page, `layout-${size.width}x${size.height}`);
  });
}
