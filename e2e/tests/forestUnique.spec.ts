/**
 * A forest link opens the forest view with its recipe: 16 unique trees (each its own species and
 * seed), generated in the studio's generation pool, all shown; the link keeps the recipe, and a
 * hostile recipe falls back with a notice.
 */
import { expect, test, type Page } from '@playwright/test';
import { waitForTree, watchErrors } from './helpers';

interface ForestDebug {
  instances: number;
  varieties: number;
  expectedVarieties: number;
  openedAt: number;
  shownAt: number[];
  poolSize: number;
  bound: number;
  drawCalls: number;
}

const forest = (page: Page) =>
  page.evaluate(() => (window.__sylva as unknown as { forest(): ForestDebug }).forest());

test.use({ viewport: { width: 640, height: 400 } });

test('a forest link with count=16 shows 16 unique trees from the pool', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = watchErrors(page);
  const recipe = '16:7:quaking_aspen,fir,oak,cypress';
  await page.goto(`/?debug=1&forest=${recipe}`);
  await waitForTree(page);
  await expect(page.getByTestId('forest-view')).toBeVisible();
  const trees = page.getByTestId('forest-varieties');
  await expect(trees).toHaveAttribute('data-total', '16');
  await expect(trees).toHaveAttribute('data-loaded', '16', { timeout: 200_000 });
  const f = await forest(page);
  console.log(
    `pool ${f.poolSize}, shown at ${f.shownAt.map((t) => Math.round(t - f.openedAt)).join(', ')} ms`,
  );
  expect(f.varieties).toBe(16);
  expect(f.shownAt).toHaveLength(16);
  expect(f.poolSize).toBe(
    Math.max(1, Math.min(4, await page.evaluate(() => navigator.hardwareConcurrency))),
  );
  expect(f.instances).toBe(1000);
  expect(f.bound).toBe(16 * 7 + 1);
  expect(new URL(page.url()).searchParams.get('forest')).toBe(recipe);
  expect(errors).toEqual([]);
});

test('a hostile forest recipe falls back to the defaults with a notice', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto('/?debug=1&forest=999:-1:%3Cscript%3E');
  await waitForTree(page);
  await expect(page.getByTestId('forest-view')).toBeVisible();
  await expect(page.getByRole('alert')).toContainText('tree count "999" is not 1..64');
  await expect(page.getByTestId('forest-varieties')).toHaveAttribute('data-total', '16');
  expect(new URL(page.url()).searchParams.get('forest')).toMatch(/^16:1:/);
});
