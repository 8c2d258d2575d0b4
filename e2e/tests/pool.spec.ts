/**
 * The generation pool keeps the editor responsive: a large export runs in a pool worker (never
 * the editor's), and a slider dragged meanwhile is answered in the scene before the export ends.
 */
import { expect, test, type Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { waitForTree, watchErrors } from './helpers';

/** A tree whose GLB (about 40 MB) takes seconds to generate and write (live.spec.ts's heavy tree). */
const HEAVY = '/?debug=1&v=1&l2_branches=40&mesh_quality=2.5&leaves=8';

interface PoolState {
  size: number;
  started: number;
  load: number[];
  waiting: number;
  given: { lods: number; export: number };
}

/** The pool right after the export was asked for, and the drag's first answer in the scene. */
interface Run {
  exportAt: number;
  poolAtExport: PoolState;
  dragAt: number;
  answeredAt: number;
  preview: boolean;
  /** The toolbar's status when the answer was in the scene ("Exporting…" while it runs). */
  statusAtAnswer: string;
  poolAtAnswer: PoolState;
}

const poolState = (page: Page) =>
  page.evaluate(() => (window.__sylva as unknown as { pool(): PoolState }).pool());

test('a slider drag is answered while a large export runs in the pool', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = watchErrors(page);
  await page.goto(HEAVY);
  const before = await waitForTree(page);
  const cores = await page.evaluate(() => navigator.hardwareConcurrency);
  expect((await poolState(page)).size).toBe(Math.max(1, Math.min(4, cores)));
  // When the export ends (its status says "Saved …"), in page time.
  await page.evaluate(() => {
    const w = window as unknown as { __exportedAt?: number };
    new MutationObserver(() => {
      const text = document.querySelector('[data-testid=toolbar-status]')?.textContent ?? '';
      if (w.__exportedAt === undefined && text.startsWith('Saved')) {
        w.__exportedAt = performance.now();
      }
    }).observe(document.body, { subtree: true, childList: true, characterData: true });
  });

  await page.getByTestId('export-menu').click();
  await expect(page.getByTestId('export-glb')).toBeEnabled();
  const downloaded = page.waitForEvent('download', { timeout: 200_000 });
  const run = await page.evaluate(async () => {
    const pool = () => (window.__sylva as unknown as { pool(): PoolState }).pool();
    const status = () => document.querySelector('[data-testid=toolbar-status]')?.textContent ?? '';
    const input = document.querySelector<HTMLInputElement>(
      'input[type="range"][data-param-id="l1_length"]',
    );
    const setValue = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value')?.set;
    const item = document.querySelector<HTMLButtonElement>('[data-testid=export-glb]');
    if (!input || !setValue || !item) throw new Error('no slider or export item');
    const exportAt = performance.now();
    item.click();
    const poolAtExport = pool();
    // Then a drag, while the export runs.
    const dragAt = performance.now();
    const answered = new Promise<
      Pick<Run, 'answeredAt' | 'preview' | 'statusAtAnswer' | 'poolAtAnswer'>
    >((resolve) =>
      addEventListener(
        'sylva:applied',
        (e) =>
          resolve({
            answeredAt: performance.now(),
            preview: (e as CustomEvent<{ preview: boolean }>).detail.preview,
            statusAtAnswer: status(),
            poolAtAnswer: pool(),
          }),
        { once: true },
      ),
    );
    for (const v of [0.31, 0.32, 0.33]) {
      setValue.call(input, v.toFixed(2));
      input.dispatchEvent(new Event('input', { bubbles: true }));
    }
    const answer = await answered;
    input.dispatchEvent(new Event('change', { bubbles: true }));
    return { exportAt, poolAtExport, dragAt, ...answer };
  });
  const download = await downloaded;
  const exportedAt = await page.evaluate(
    () => (window as unknown as { __exportedAt?: number }).__exportedAt ?? null,
  );
  console.log(
    `export ${Math.round((exportedAt ?? NaN) - run.exportAt)} ms; the drag answered ` +
      `(${run.preview ? 'preview' : 'full tree'}) ${Math.round(run.answeredAt - run.dragAt)} ms ` +
      `after it began; pool then ${JSON.stringify(run.poolAtAnswer)}`,
  );
  // The export went to the pool (the editor's worker is not part of it) ...
  expect(run.poolAtExport.given.export).toBe(1);
  expect(run.poolAtExport.load.reduce((a, b) => a + b, 0)).toBe(1);
  // ... and the drag was answered in the scene while it still ran there.
  expect(run.statusAtAnswer).toContain('Exporting');
  expect(run.poolAtAnswer.given.export).toBe(1);
  expect(run.poolAtAnswer.load.reduce((a, b) => a + b, 0)).toBeGreaterThan(0);
  expect(exportedAt).not.toBeNull();
  expect(run.answeredAt).toBeLessThan(exportedAt!);
  // The drag's tree is a new one; the export is a whole GLB of the tree before the drag.
  expect(await waitForTree(page)).not.toBe(before);
  const file = readFileSync(await download.path());
  expect(file.subarray(0, 4).toString('latin1')).toBe('glTF');
  expect(file.readUInt32LE(8)).toBe(file.length);
  expect(file.length).toBeGreaterThan(10_000_000);
  expect(errors).toEqual([]);
});
