/**
 * Live editing: a drag is answered with previews when the full tree would take longer than a
 * frame, the overlay says so, the full tree follows on release; foliage edits update the leaves
 * in place (no new GPU geometry); viewer-only parameters regenerate nothing.
 */
import { expect, test } from '@playwright/test';
import { waitForTree, watchErrors } from './helpers';

/** A tree whose bark takes well over the worker's preview budget even on a fast machine. */
const HEAVY = '/?debug=1&v=1&l2_branches=40&mesh_quality=2.5&leaves=8';

interface Applied {
  kind: string;
  preview: boolean;
  at: number;
  /** Whether the overlay showed the preview badge right after this answer was applied. */
  badge?: boolean;
}

test('a drag shows previews, labelled as such, and the full tree follows on release', async ({
  page,
  browser,
}) => {
  test.setTimeout(180_000);
  const errors = watchErrors(page);
  await page.goto(HEAVY);
  await waitForTree(page);
  const answers = await page.evaluate(async () => {
    const input = document.querySelector<HTMLInputElement>(
      'input[type="range"][data-param-id="l1_length"]',
    );
    const setValue = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value')?.set;
    if (!input || !setValue) throw new Error('no slider');
    window.__sylva?.pauseRendering?.(true);
    const seen: Applied[] = [];
    addEventListener('sylva:applied', (e) => {
      const detail = (e as CustomEvent<Applied>).detail;
      // React shows the badge on its next render: read it a task later.
      setTimeout(() => {
        seen.push({ ...detail, badge: !!document.querySelector('[data-testid=stat-preview]') });
      }, 0);
    });
    for (let i = 1; i <= 6; i++) {
      const answered = new Promise((r) => addEventListener('sylva:applied', r, { once: true }));
      setValue.call(input, (0.3 + 0.01 * i).toFixed(2));
      input.dispatchEvent(new Event('input', { bubbles: true }));
      await answered;
    }
    const full = new Promise<void>((resolve) => {
      const on = (e: Event) => {
        if ((e as CustomEvent<Applied>).detail.preview) return;
        removeEventListener('sylva:applied', on);
        resolve();
      };
      addEventListener('sylva:applied', on);
    });
    const released = performance.now();
    input.dispatchEvent(new Event('change', { bubbles: true }));
    await full;
    const settleMs = performance.now() - released;
    await new Promise((r) => setTimeout(r, 50));
    window.__sylva?.pauseRendering?.(false);
    return { seen, settleMs };
  });
  const drag = answers.seen.slice(0, 6);
  expect(
    drag.some((a) => a.preview),
    JSON.stringify(drag),
  ).toBe(true);
  for (const a of answers.seen) expect(a.badge, JSON.stringify(a)).toBe(a.preview);
  const last = answers.seen.at(-1);
  expect(last?.preview).toBe(false);
  // The full tree has its hash, which a fresh page of the share link reproduces.
  const hash = await waitForTree(page);
  await expect(page.getByTestId('stat-preview')).toHaveCount(0);
  await page.waitForTimeout(800);
  const link = page.url();
  expect(errors).toEqual([]);
  // The first page closes first: two pages drawing a million-triangle tree share one software
  // GPU here, and the fresh page's start then waits on the other's frames (over 20 s under load).
  await page.close();
  const fresh = await browser.newPage({ reducedMotion: 'reduce' });
  await fresh.goto(link);
  expect(await waitForTree(fresh)).toBe(hash);
  await fresh.close();
});

test('leaf edits update the leaves in place; viewer-only edits regenerate nothing', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await page.goto('/?debug=1&v=1&levels=2');
  await waitForTree(page);
  const result = await page.evaluate(async () => {
    const hook = window.__sylva;
    if (!hook?.geometries || !hook.trees || !hook.probeFrame || !hook.settleWhenIdle)
      throw new Error('no debug hook');
    // Count after a drawn frame: three.js counts a geometry once it is uploaded, and under load
    // the first frame may not have been drawn when the hash shows.
    const drawnGeometries = () => {
      hook.probeFrame!();
      return hook.geometries!();
    };
    const input = document.querySelector<HTMLInputElement>(
      'input[type="range"][data-param-id="foliage_angle"]',
    );
    const setValue = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value')?.set;
    if (!input || !setValue) throw new Error('no slider');
    const before = drawnGeometries();
    // No settle by the clock while the test steps: under load a frame can take longer than the
    // scheduler's pause (150 ms), and a settle answered late (after the counts below) was
    // mistaken for the viewer-only edit's doing (a fresh CI run, 10 trees where 9 were expected).
    // The drag settles on release instead, as a user's does (the range input's native `change`).
    hook.settleWhenIdle(false);
    const applied = () => new Promise((r) => addEventListener('sylva:applied', r, { once: true }));
    for (let i = 1; i <= 5; i++) {
      const answered = applied();
      setValue.call(input, String(40 + i));
      input.dispatchEvent(new Event('input', { bubbles: true }));
      await answered;
      await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
    }
    const settled = applied();
    input.dispatchEvent(new Event('change', { bubbles: true }));
    await settled;
    hook.settleWhenIdle(true);
    const after = drawnGeometries();
    const trees = hook.trees().length;
    const check = document.querySelector<HTMLInputElement>(
      '[data-testid=param-check-show_preview]',
    );
    const toggledAt = performance.now();
    check?.click();
    await new Promise((r) => setTimeout(r, 300));
    const requestedAfterToggle = hook
      .trees()
      .filter((t) => t.requestedAt !== null && t.requestedAt >= toggledAt).length;
    return {
      before,
      after,
      trees,
      treesAfterToggle: hook.trees().length,
      requestedAfterToggle,
    };
  });
  // Same leaf count, new angles: the instance arrays are swapped into the same GPU buffers.
  expect(result.after).toBe(result.before);
  expect(result.requestedAfterToggle).toBe(0);
  expect(result.treesAfterToggle).toBe(result.trees);
});
