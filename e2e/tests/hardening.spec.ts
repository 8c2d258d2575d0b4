/**
 * Hardening end to end: the Content-Security-Policy, the generation time limit, undo/redo, and
 * a batch of hostile share links (the browser cases of web/src/app/hostileLinks.fixture.ts; Vitest
 * runs all of them through the codec). Each hostile link shows a message or ignores the junk, a
 * tree still renders (the exact tree of the equivalent clean link), and nothing uncaught
 * reaches the console.
 */
import { expect, test, type Page } from '@playwright/test';
import {
  DEBOUNCE_WAIT_MS,
  DEBUG_BUILD_URL,
  dragSlider,
  expectTreeOnCanvas,
  sliderRange,
  waitForNewTree,
  waitForTree,
  watchErrors,
} from './helpers';
import { DEFAULT, HOSTILE, SEED5, type HostileCase } from '../../web/src/app/hostileLinks.fixture';

/** Records CSP violations of every document of the page (before any app script runs). */
async function recordCspViolations(page: Page): Promise<void> {
  await page.addInitScript(() => {
    window.__cspViolations = [];
    document.addEventListener('securitypolicyviolation', (event) => {
      window.__cspViolations?.push(`${event.effectiveDirective} blocked ${event.blockedURI}`);
    });
  });
}

async function cspViolations(page: Page): Promise<string[]> {
  return page.evaluate(() => window.__cspViolations ?? []);
}

test('the app runs under its Content-Security-Policy without a single violation', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await recordCspViolations(page);
  // The debug build (the same page and policy; only its worker can be made to panic).
  await page.goto(`${DEBUG_BUILD_URL}/?debug=1`);
  const first = await waitForTree(page);
  const policy = await page
    .locator('meta[http-equiv="Content-Security-Policy"]')
    .getAttribute('content');
  expect(policy).toContain("script-src 'self' 'wasm-unsafe-eval'");
  expect(policy).toContain("default-src 'self'");
  // Exercise the worker, a preset, the envelope preview, a crash and its recovery.
  await page.getByTestId('preset-picker').selectOption('cypress');
  const cypress = await waitForNewTree(page, first);
  await page.locator('input[type="checkbox"][data-param-id="show_preview"]').check();
  // The page is cross-origin isolated: the core runs on two threads, and the panic happens on
  // its helper thread while the worker waits for it; the worker reports the helper's message.
  await expect(page.locator('.panel-header .version')).toHaveText(/· 2 threads$/);
  await page.evaluate(() => window.__sylva?.panic?.());
  await expect(page.getByTestId('error-generator')).toHaveAttribute('data-kind', 'panic');
  await expect(page.getByTestId('error-generator')).toContainText('debug_panic_on_helper');
  await page.getByTestId('reset').click();
  await waitForNewTree(page, cypress);
  await expectTreeOnCanvas(page);
  expect(await cspViolations(page)).toEqual([]);
  expect(errors).toEqual([]);

  // The policy is enforced (so the empty list above means something): an injected inline
  // script does not run, and the violation is reported.
  const ran = await page.evaluate(async () => {
    const script = document.createElement('script');
    script.textContent = 'window.__xss = 1';
    document.head.append(script);
    await new Promise((resolve) => setTimeout(resolve, 50));
    return window.__xss !== undefined;
  });
  expect(ran).toBe(false);
  await expect.poll(() => cspViolations(page)).toEqual([expect.stringMatching(/^script-src/)]);
});

test('a generation past the time limit is stopped, reported, and the previous tree stays', async ({
  page,
}) => {
  const errors = watchErrors(page);
  // The debug build: only its worker has the hang hook.
  await page.goto(`${DEBUG_BUILD_URL}/?debug=1`);
  const hash = await waitForTree(page);
  await page.waitForFunction(() => typeof window.__sylva?.hang === 'function');
  // A short limit keeps the test quick; the default 10 s is covered by the scheduler unit tests.
  await page.evaluate(() => {
    window.__sylva?.setTimeLimit?.(1500);
    window.__sylva?.hang?.(60_000);
  });
  await expect(page.getByTestId('busy')).toBeVisible();
  const message = page.getByTestId('error-generator');
  await expect(message).toHaveAttribute('data-kind', 'timeout');
  await expect(message).toContainText('took longer than 1.5 s and was stopped');
  await expect(message).toContainText('previous tree is kept');
  await expect(page.getByTestId('busy')).toHaveCount(0);
  await expect(page.getByTestId('stat-hash')).toHaveText(hash);
  await expectTreeOnCanvas(page);
  // The hung worker was terminated and replaced: the next change generates right away.
  const range = await sliderRange(page, 'l1_length');
  await dragSlider(page, 'l1_length', [range.value + range.step]);
  await waitForNewTree(page, hash);
  await expect(page.getByTestId('error-banner')).toHaveCount(0);
  expect(errors).toEqual([]);
});

test('undo/redo: a slider drag is one step; Reset and presets undo; keys and buttons', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto('/');
  const initial = await waitForTree(page);
  const undo = page.getByTestId('undo');
  const redo = page.getByTestId('redo');
  await expect(undo).toBeDisabled();
  await expect(redo).toBeDisabled();
  const number = page.getByTestId('param-number-l1_length');
  const start = await number.inputValue();

  // One drag through many values is a single undo step.
  const range = await sliderRange(page, 'l1_length');
  const values = Array.from({ length: 30 }, (_, i) =>
    Number((range.value + (i + 1) * range.step).toFixed(6)),
  );
  const last = values[values.length - 1] ?? 0;
  await dragSlider(page, 'l1_length', values);
  const dragged = await waitForNewTree(page, initial);
  await expect(number).toHaveValue(String(last));
  await expect(undo).toBeEnabled();

  await page.keyboard.press('Control+z');
  await expect(number).toHaveValue(start);
  expect(await waitForNewTree(page, dragged)).toBe(initial);
  await expect(undo).toBeDisabled();
  await expect(redo).toBeEnabled();
  await page.keyboard.press('Control+Shift+Z');
  await expect(number).toHaveValue(String(last));
  expect(await waitForNewTree(page, initial)).toBe(dragged);
  await page.keyboard.press('Control+z');
  await waitForNewTree(page, dragged);
  await page.keyboard.press('Control+y');
  expect(await waitForNewTree(page, initial)).toBe(dragged);

  // A preset switch and Reset are steps of their own, undone with the buttons.
  await page.getByTestId('preset-picker').selectOption('cypress');
  const cypress = await waitForNewTree(page, dragged);
  await page.getByTestId('reset').click();
  expect(await waitForNewTree(page, cypress)).toBe(initial);
  await undo.click();
  expect(await waitForNewTree(page, initial)).toBe(cypress);
  await expect(page.getByTestId('preset-picker')).toHaveValue('cypress');
  await undo.click();
  expect(await waitForNewTree(page, cypress)).toBe(dragged);
  await expect(number).toHaveValue(String(last));
  await redo.click();
  expect(await waitForNewTree(page, dragged)).toBe(cypress);

  // Undo also reaches the URL (and storage), and works with the focus in a number field.
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  expect(new URL(page.url()).searchParams.get('shape')).toBe('5');
  const seed = page.getByTestId('param-number-seed');
  await seed.fill('77');
  const seeded = await waitForNewTree(page, cypress);
  await seed.focus();
  await page.keyboard.press('Control+z');
  await expect(seed).toHaveValue('1');
  expect(await waitForNewTree(page, seeded)).toBe(cypress);
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  expect(new URL(page.url()).searchParams.get('seed')).toBeNull();
  expect(errors).toEqual([]);
});

/** Opens each link of `cases` in `page` and checks it against the reference trees. */
async function checkLinks(page: Page, cases: HostileCase[], reference: Map<string, string>) {
  const errors = watchErrors(page);
  for (const c of cases) {
    await page.goto(`/${c.query}`);
    const hash = await waitForTree(page);
    expect(hash, `${c.name}: the tree of ${c.same}`).toBe(reference.get(c.same));
    const banner = page.getByTestId('error-banner');
    if (c.notice) {
      await expect(banner, c.name).toContainText(c.notice);
      const text = (await banner.textContent()) ?? '';
      expect(text, c.name).not.toMatch(/[\u0000-\u0008\u200b-\u200f\u202a-\u202e]/);
    } else {
      await expect(banner, c.name).toHaveCount(0);
    }
    await expect(page.getByTestId('error-generator'), c.name).toHaveCount(0);
    const state = await page.evaluate(() => ({
      xss: window.__xss,
      scripts: document.scripts.length,
      hook: typeof window.__sylva,
      violations: window.__cspViolations ?? [],
    }));
    expect(state, c.name).toEqual({
      xss: undefined,
      scripts: 1,
      hook: 'undefined',
      violations: [],
    });
    expect(errors, c.name).toEqual([]);
  }
  await expectTreeOnCanvas(page);
}

/** The cases opened in the browser; Vitest runs every case of the table through the codec. */
const BROWSER_CASES = HOSTILE.filter((c) => c.browser);

test.describe('hostile share links', () => {
  // A small viewport: software WebGL renders each fresh page faster, and the links are many.
  test.use({ viewport: { width: 480, height: 360 } });

  test(`${BROWSER_CASES.length} hostile share links: message or ignored, a tree renders, nothing uncaught`, async ({
    context,
    page,
  }) => {
    test.setTimeout(240_000);
    await context.addInitScript(() => {
      // Each link is judged on its own: no fallback to what an earlier case saved.
      localStorage.clear();
      window.__cspViolations = [];
      document.addEventListener('securitypolicyviolation', (event) => {
        window.__cspViolations?.push(`${event.effectiveDirective} blocked ${event.blockedURI}`);
      });
    });
    // `vite preview` (Node) refuses request lines over 16 kB; serve the app for such a link the
    // way a permissive static host would, so the app itself meets the 100 kB query.
    await context.route(
      (url) => url.search.length > 8000,
      async (route) =>
        route.fulfill({
          response: await route.fetch({
            url: new URL('/', route.request().url()).href,
          }),
        }),
    );
    const reference = new Map<string, string>();
    for (const query of new Set([DEFAULT, SEED5, ...BROWSER_CASES.map((c) => c.same)])) {
      await page.goto(`/${query}`);
      reference.set(query, await waitForTree(page));
      await expect(page.getByTestId('error-banner')).toHaveCount(0);
    }
    expect(reference.get(SEED5)).not.toBe(reference.get(DEFAULT));
    // Two batches side by side, one page each.
    const second = await context.newPage();
    const half = Math.ceil(BROWSER_CASES.length / 2);
    await Promise.all([
      checkLinks(page, BROWSER_CASES.slice(0, half), reference),
      checkLinks(second, BROWSER_CASES.slice(half), reference),
    ]);
  });
});
