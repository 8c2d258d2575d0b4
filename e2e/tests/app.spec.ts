/** End-to-end tests of the Sylva app in headless Chromium (SwiftShader WebGL2). */
import { expect, test } from '@playwright/test';
import {
  analyseCanvas,
  DEBOUNCE_WAIT_MS,
  dragSlider,
  DEBUG_BUILD_URL,
  expectTreeOnCanvas,
  pick,
  sliderIds,
  sliderRange,
  statNumber,
  waitForNewTree,
  waitForTree,
  watchErrors,
} from './helpers';

/** A slider that changes the vertex count: a branch count if there is one, else a length. */
const VERTEX_PARAM = [/^l1_branches$/, /branches$/, 'l1_length'];

test('(a) loads and the canvas shows a tree, without uncaught errors', async ({ page }) => {
  const errors = watchErrors(page);
  await page.goto('/');
  const hash = await waitForTree(page);
  expect(hash).toMatch(/^[0-9a-f]{16}$/);
  expect(await statNumber(page, 'stat-vertices')).toBeGreaterThan(100);
  expect(await statNumber(page, 'stat-triangles')).toBeGreaterThan(100);
  await expect(page.getByTestId('stat-ms')).toHaveText(/ms/);
  await expect(page.getByTestId('error-banner')).toHaveCount(0);
  // Every registry group has a section, and seed/scale/l1_length have controls.
  await expect(page.locator('details.group').first()).toBeVisible();
  const ids = await sliderIds(page);
  expect(ids).toEqual(expect.arrayContaining(['scale', 'l1_length']));
  await expect(page.locator('[data-param-id="seed"]').first()).toBeVisible();
  await page.waitForTimeout(300);
  await expectTreeOnCanvas(page);
  expect(errors).toEqual([]);
});

test('(a2) in software WebGL the first tree frame is half resolution, the next one sharp', async ({
  page,
}) => {
  // The viewer canvas's drawing-buffer width at each of its draw calls, recorded before any app
  // code runs, one entry per change. Until the first tree the canvas is only cleared, so the
  // first entry is the first tree frame's width, whatever the timing of the frames.
  await page.addInitScript(() => {
    const widths: number[] = [];
    (window as unknown as { __drawWidths: number[] }).__drawWidths = widths;
    const proto = WebGL2RenderingContext.prototype as unknown as Record<
      'drawElements' | 'drawArrays',
      (this: WebGL2RenderingContext, ...args: unknown[]) => void
    >;
    for (const name of ['drawElements', 'drawArrays'] as const) {
      const original = proto[name];
      proto[name] = function (this: WebGL2RenderingContext, ...args: unknown[]) {
        const canvas = this.canvas as HTMLCanvasElement;
        if (
          canvas.dataset?.testid === 'viewer-canvas' &&
          widths.at(-1) !== this.drawingBufferWidth
        ) {
          widths.push(this.drawingBufferWidth);
        }
        original.apply(this, args);
      };
    }
  });
  await page.goto('/?debug=1');
  await waitForTree(page);
  const sizes = () =>
    page.evaluate(() => {
      const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="viewer-canvas"]');
      return {
        widths: (window as unknown as { __drawWidths: number[] }).__drawWidths,
        full: Math.round((canvas?.clientWidth ?? 0) * Math.min(devicePixelRatio, 2)),
      };
    });
  // Headless Chromium draws with SwiftShader: the next frame (the first with shadows, which can
  // take seconds on a loaded machine) draws at the full resolution.
  await expect.poll(async () => (await sizes()).widths.length, { timeout: 30_000 }).toBe(2);
  const { widths, full } = await sizes();
  expect(full).toBeGreaterThan(100);
  expect(Math.abs(widths[0]! - full / 2)).toBeLessThanOrEqual(1);
  expect(widths[1]).toBe(full);
  await expectTreeOnCanvas(page);
});

test('(b) dragging a slider updates the vertex stat and the URL', async ({ page }) => {
  const errors = watchErrors(page);
  await page.goto('/');
  const firstHash = await waitForTree(page);
  const vertices = await statNumber(page, 'stat-vertices');
  const id = pick(await sliderIds(page), VERTEX_PARAM);
  const range = await sliderRange(page, id);
  const span = range.max - range.min;
  const target = Number((range.value + Math.max(range.step, Math.round(span * 0.1))).toFixed(6));
  const steps = [range.value + range.step, range.value + 2 * range.step, target];
  await dragSlider(page, id, steps);
  await waitForNewTree(page, firstHash);
  await expect(page.getByTestId(`param-number-${id}`)).toHaveValue(String(target));
  await expect.poll(() => statNumber(page, 'stat-vertices')).not.toBe(vertices);
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  const url = new URL(page.url());
  expect(url.searchParams.get('v')).toBe('1');
  expect(url.searchParams.get(id)).toBe(String(target));
  expect(errors).toEqual([]);
});

test('(c) opening a share URL in a fresh page gives the same tree hash', async ({
  page,
  browser,
}) => {
  await page.goto('/');
  const defaultHash = await waitForTree(page);
  const id = pick(await sliderIds(page), ['l1_length']);
  const range = await sliderRange(page, id);
  const target = Number((range.value + 5 * range.step).toFixed(6));
  await dragSlider(page, id, [target]);
  const seedField = page.getByTestId('param-number-seed');
  await seedField.fill('7');
  await seedField.press('Enter');
  const hash = await waitForNewTree(page, defaultHash);
  await expect.poll(() => new URL(page.url()).searchParams.get('seed')).toBe('7');
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  const shareUrl = page.url();
  expect(new URL(shareUrl).searchParams.get(id)).toBe(String(target));

  // Closed first, so the fresh page does not share the software GPU with it (slow under load).
  await page.close();
  const context = await browser.newContext({ reducedMotion: 'reduce' });
  const fresh = await context.newPage();
  await fresh.goto(shareUrl);
  expect(await waitForTree(fresh)).toBe(hash);
  await expect(fresh.getByTestId('param-number-seed')).toHaveValue('7');
  await expect(fresh.getByTestId('error-banner')).toHaveCount(0);
  await context.close();
});

test('(d) a broken URL shows the error banner and still renders a tree', async ({ page }) => {
  await page.goto('/?v=1&scale=abc&l1_length=NaN&seed=%E0%A4%A&<script>alert(1)</script>=1');
  await waitForTree(page);
  const banner = page.getByTestId('error-banner');
  await expect(banner).toBeVisible();
  await expect(banner).toContainText('"scale"');
  await expect(banner).toContainText('"l1_length"');
  await expect(banner).toContainText('"seed"');
  expect(await page.locator('script:has-text("alert(1)")').count()).toBe(0);
  await page.waitForTimeout(300);
  await expectTreeOnCanvas(page);
  // Bad keys fell back to defaults, so the tree is the default tree.
  const context = await page.context().browser()?.newContext();
  if (context) {
    const clean = await context.newPage();
    await clean.goto('/?v=1');
    expect(await waitForTree(clean)).toBe(await page.getByTestId('stat-hash').textContent());
    await context.close();
  }
  // An unsupported version is reported too.
  await page.goto('/?v=99&seed=3');
  await waitForTree(page);
  await expect(page.getByTestId('error-banner')).toContainText(/version/i);
});

test('(e) a worker panic is reported, the tree stays, and the worker is recreated', async ({
  page,
}) => {
  // The debug build: only its worker can be made to panic.
  await page.goto(`${DEBUG_BUILD_URL}/?debug=1`);
  const hash = await waitForTree(page);
  await page.waitForFunction(() => typeof window.__sylva?.panic === 'function');
  await page.evaluate(() => window.__sylva?.panic?.());
  const banner = page.getByTestId('error-banner');
  await expect(banner).toContainText(/crash|panic/i);
  await expect(banner).toContainText(/panic/i);
  await expect(page.getByTestId('stat-hash')).toHaveText(hash);
  await expect(page.getByTestId('busy')).toHaveCount(0);
  await expectTreeOnCanvas(page);

  const id = pick(await sliderIds(page), VERTEX_PARAM);
  const range = await sliderRange(page, id);
  await dragSlider(page, id, [range.value + range.step]);
  const newHash = await waitForNewTree(page, hash);
  expect(newHash).not.toBe(hash);
  await expect(banner).toHaveCount(0);
  expect(new URL(page.url()).searchParams.get('debug')).toBe('1');
});

test('(e2) the debug hook is absent without debug=1', async ({ page }) => {
  await page.goto('/');
  await waitForTree(page);
  expect(await page.evaluate(() => typeof window.__sylva)).toBe('undefined');
});

test('(f) a reload with no query restores the last params from localStorage', async ({ page }) => {
  await page.goto('/');
  const defaultHash = await waitForTree(page);
  const seedField = page.getByTestId('param-number-seed');
  await seedField.fill('42');
  await seedField.press('Enter');
  const hash = await waitForNewTree(page, defaultHash);
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  const stored = await page.evaluate(() => localStorage.getItem('sylva.params.v1'));
  expect(stored).toContain('seed=42');

  await page.goto('/');
  expect(await waitForTree(page)).toBe(hash);
  await expect(seedField).toHaveValue('42');
  await expect.poll(() => new URL(page.url()).searchParams.get('seed')).toBe('42');
});

test('presets, randomize and reset drive the generator', async ({ page }) => {
  await page.goto('/');
  const defaultHash = await waitForTree(page);
  await page.getByTestId('randomize').click();
  const randomHash = await waitForNewTree(page, defaultHash);
  expect(randomHash).not.toBe(defaultHash);
  await page.getByTestId('reset').click();
  expect(await waitForNewTree(page, randomHash)).toBe(defaultHash);
  const presetNames = await page
    .getByTestId('preset-picker')
    .locator('option:not([disabled])')
    .evaluateAll((options) => options.map((o) => (o as HTMLOptionElement).value));
  expect(presetNames.length).toBeGreaterThan(0);
  const last = presetNames[presetNames.length - 1] ?? '';
  await page.getByTestId('preset-picker').selectOption(last);
  await waitForTree(page);
  await expect(page.getByTestId('preset-picker')).toHaveValue(last);
});

test('crown: the shape dropdown and Show Preview update the tree, the envelope and the URL', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto('/');
  const first = await waitForTree(page);
  const shape = page.locator('select[data-param-id="shape"]');
  await expect(shape.locator('option')).toHaveCount(9);
  await shape.selectOption({ label: 'Conical' });
  const conical = await waitForNewTree(page, first);
  await expect.poll(() => new URL(page.url()).searchParams.get('shape')).toBe('0');
  await page.waitForTimeout(300);
  const before = await analyseCanvas(page);
  expect(before.blueLike).toBeLessThan(0.001);
  await page.locator('input[type="checkbox"][data-param-id="show_preview"]').check();
  await expect.poll(() => new URL(page.url()).searchParams.get('show_preview')).toBe('1');
  // The preview is viewer-only: same tree, plus a blue wireframe envelope around it.
  expect(await waitForTree(page)).toBe(conical);
  await expect.poll(async () => (await analyseCanvas(page)).blueLike).toBeGreaterThan(0.002);
  expect(errors).toEqual([]);
});

test('picking a preset writes its values into the URL', async ({ page }) => {
  await page.goto('/');
  const first = await waitForTree(page);
  await page.getByTestId('preset-picker').selectOption('cypress');
  await waitForNewTree(page, first);
  await expect.poll(() => new URL(page.url()).searchParams.get('shape')).toBe('5');
  expect(new URL(page.url()).searchParams.get('l1_branches')).toBe('140');
});

test('the stats, the toolbar and the wind card never cover each other, wide or narrow', async ({
  page,
}) => {
  // They share the stage's top: side by side on a wide stage, wrapped into rows on a narrow one
  // (they overlapped below a stage of about 780 px).
  const errors = watchErrors(page);
  await page.goto('/');
  await waitForTree(page);
  for (const width of [1440, 1100, 900, 700, 400]) {
    await page.setViewportSize({ width, height: 800 });
    await expect(page.getByTestId('copy-embed')).toBeVisible();
    const boxes = await Promise.all(
      ['.stats', '.toolbar', '.wind-controls'].map(async (s) => {
        const box = await page.locator(s).boundingBox();
        if (!box) throw new Error(`${s} is not laid out at ${width} px`);
        return { s, ...box };
      }),
    );
    for (const [i, a] of boxes.entries()) {
      for (const b of boxes.slice(i + 1)) {
        const apart =
          a.x + a.width <= b.x ||
          b.x + b.width <= a.x ||
          a.y + a.height <= b.y ||
          b.y + b.height <= a.y;
        expect(apart, `${a.s} and ${b.s} overlap at ${width} px`).toBe(true);
      }
    }
  }
  expect(errors).toEqual([]);
});
