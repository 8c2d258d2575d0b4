/**
 * Growth over years on the real app: dragging Age down makes a younger tree on screen (fewer
 * vertices, a lower crown, fewer tree pixels), the share link keeps the Age, and the play button
 * grows it back to the mature tree.
 */
import { expect, test } from '@playwright/test';
import {
  analyseCanvas,
  DEBOUNCE_WAIT_MS,
  dragSlider,
  slider,
  statNumber,
  waitForNewTree,
  waitForTree,
  watchErrors,
} from './helpers';

test('the Age slider grows the tree on screen; play grows it back to the mature tree', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto('/?debug=1');
  const mature = await waitForTree(page);
  const vertices = await statNumber(page, 'stat-vertices');
  const pixels = (await analyseCanvas(page)).treeLike;
  await expect(slider(page, 'age')).toHaveValue('40');

  await dragSlider(page, 'age', [30, 20, 12]);
  const young = await waitForNewTree(page, mature);
  expect(await statNumber(page, 'stat-vertices')).toBeLessThan(vertices / 2);
  await page.waitForTimeout(300);
  expect((await analyseCanvas(page)).treeLike).toBeLessThan(pixels);
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  expect(new URL(page.url()).searchParams.get('age')).toBe('12');

  // Play: the Age runs up from a seedling (a few seconds) and ends on the mature tree.
  await page.getByTestId('age-play').click();
  await expect(page.getByTestId('age-play')).toHaveAttribute('aria-pressed', 'true');
  await expect
    .poll(async () => Number(await slider(page, 'age').inputValue()), { timeout: 5_000 })
    .toBeGreaterThan(1);
  await expect(page.getByTestId('age-play')).toHaveAttribute('aria-pressed', 'false', {
    timeout: 30_000,
  });
  await expect(slider(page, 'age')).toHaveValue('40');
  expect(await waitForNewTree(page, young)).toBe(mature);
  expect(errors).toEqual([]);
});
