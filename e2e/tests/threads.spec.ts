/**
 * The threaded core (packages/sylva-trees/src/worker/threads.ts): `vite preview` sends the
 * cross-origin isolation headers, so the generator worker runs the core built with threads and a
 * helper worker; without the headers it runs the single-threaded core. Both give the same tree,
 * byte for byte (the content hash).
 */
import { expect, test, type Page } from '@playwright/test';
import { expectTreeOnCanvas, waitForNewTree, waitForTree, watchErrors } from './helpers';

/** Serves every response of `page` without the isolation headers (a plain static host). */
async function withoutIsolation(page: Page): Promise<void> {
  await page.route('**/*', async (route) => {
    const response = await route.fetch();
    const headers = { ...response.headers() };
    delete headers['cross-origin-opener-policy'];
    delete headers['cross-origin-embedder-policy'];
    await route.fulfill({ response, headers });
  });
}

test('an isolated page generates on two threads, a plain one on one, the same bytes', async ({
  browser,
}) => {
  // The default tree (primed on the worker before the page asks), then Black Tupelo.
  const trees = async (page: Page): Promise<[string, string]> => {
    await page.goto('/');
    const first = await waitForTree(page);
    await page.getByTestId('preset-picker').selectOption('black_tupelo');
    return [first, await waitForNewTree(page, first)];
  };
  const isolated = await browser.newPage();
  const errors = watchErrors(isolated);
  const [threadedDefault, threadedHash] = await trees(isolated);
  expect(await isolated.evaluate(() => self.crossOriginIsolated)).toBe(true);
  await expect(isolated.locator('.panel-header .version')).toHaveText(/· 2 threads$/);
  await expectTreeOnCanvas(isolated);
  expect(errors).toEqual([]);
  await isolated.close();

  const plain = await browser.newPage();
  await withoutIsolation(plain);
  const [plainDefault, plainHash] = await trees(plain);
  expect(await plain.evaluate(() => self.crossOriginIsolated)).toBe(false);
  await expect(plain.locator('.panel-header .version')).not.toHaveText(/threads/);
  await plain.close();

  expect(threadedHash).toBe(plainHash);
  expect(threadedDefault).toBe(plainDefault);
  expect(threadedHash).not.toBe(threadedDefault);
});
