/** Issue 6: the interactive growth editor (primitives, markers, progress and Cancel). */
import { expect, test, type Page } from '@playwright/test';
import {
  DEBOUNCE_WAIT_MS,
  dragSlider,
  expectTreeOnCanvas,
  waitForNewTree,
  waitForTree,
  watchErrors,
} from './helpers';

/** Opens a closed panel section by its group name. */
async function openGroup(page: Page, group: string): Promise<void> {
  const details = page.locator(`details.group[data-group="${group}"]`);
  if ((await details.getAttribute('open')) === null) await details.locator('summary').click();
}

async function growthOverlay(page: Page) {
  return page.evaluate(() => window.__sylva?.growth?.() ?? null);
}

test('switch to Space Colonization, add a sphere: the tree changes (hash, pixels, URL)', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto('/?debug=1');
  const first = await waitForTree(page);
  await openGroup(page, 'Growth');
  await page.getByTestId('param-select-growth_mode').selectOption({ label: 'Space Colonization' });
  const grown = await waitForNewTree(page, first);
  await expectTreeOnCanvas(page);
  const before = await page.getByTestId('viewer-canvas').screenshot();

  await openGroup(page, 'Growth Volume');
  await page.getByTestId('volume-group').selectOption('crown');
  await page.getByTestId('add-sphere').click();
  const withSphere = await waitForNewTree(page, grown);
  expect(withSphere).not.toBe(grown);
  // Crown Volume switched to the primitives and their wireframes are shown, gizmo attached.
  await expect(page.getByTestId('param-select-crown_volume')).toHaveValue('2');
  await expect(page.getByTestId('param-check-show_volumes')).toBeChecked();
  expect(await growthOverlay(page)).toMatchObject({ volumes: 1 });
  await page.waitForTimeout(300);
  const after = await page.getByTestId('viewer-canvas').screenshot();
  expect(after.equals(before)).toBe(false);
  await expectTreeOnCanvas(page);

  // The share URL carries the sphere; reloading it gives the same tree.
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  const url = new URL(page.url());
  expect(url.searchParams.get('vol')).toMatch(/^1;s:c:/);
  await page.goto(page.url());
  expect(await waitForTree(page)).toBe(withSphere);
  expect(errors).toEqual([]);
});

test('markers are drawn when Show Markers is on', async ({ page }) => {
  const errors = watchErrors(page);
  await page.goto('/?debug=1&v=1&growth_mode=1');
  await waitForTree(page);
  expect(await growthOverlay(page)).toMatchObject({ markers: 0 });
  const before = await page.getByTestId('viewer-canvas').screenshot();
  await openGroup(page, 'Growth Volume');
  await page.getByTestId('param-check-show_markers').check();
  await expect.poll(async () => (await growthOverlay(page))?.markers ?? 0).toBeGreaterThan(500);
  await page.waitForTimeout(300);
  const after = await page.getByTestId('viewer-canvas').screenshot();
  expect(after.equals(before)).toBe(false);
  expect(errors).toEqual([]);
});

test('a long growth shows progress; Cancel stops it and keeps the last tree', async ({ page }) => {
  const errors = watchErrors(page);
  // Heavy in everything but the influence radius: fast until the radius grows.
  await page.goto(
    '/?debug=1&v=1&growth_mode=1&iterations=5000&markers=50000&extra_markers=20000' +
      '&crown_radius=10&crown_height=15&influence_radius=1.5',
  );
  const last = await waitForTree(page);
  await openGroup(page, 'Growth');
  await dragSlider(page, 'influence_radius', [12]);
  const progress = page.getByTestId('growth-progress');
  await expect(progress).toBeVisible();
  await expect(progress.locator('progress')).toHaveAttribute('value', /\d+/);
  // (dispatched: Playwright's stability check waits for two equal frames, and the canvas
  // keeps the compositor busy while the bar moves)
  await page.getByTestId('cancel-generation').dispatchEvent('click');
  await expect(progress).toHaveCount(0);
  await expect(page.getByTestId('busy')).toHaveCount(0);
  await expect(page.getByTestId('stat-hash')).toHaveText(last);
  await expect(page.getByTestId('error-banner')).toHaveCount(0);
  await expectTreeOnCanvas(page);
  // The fresh worker serves the next request.
  await dragSlider(page, 'influence_radius', [1.6]);
  await waitForNewTree(page, last);
  expect(errors).toEqual([]);
});
