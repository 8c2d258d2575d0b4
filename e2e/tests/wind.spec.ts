/** Wind animation and bark material: deterministic frames through the debug hook, controls. */
import { expect, test, type Page } from '@playwright/test';
import { waitForTree, watchErrors } from './helpers';

interface WindState {
  enabled: boolean;
  paused: boolean;
  strength: number;
  direction: number;
  gust: number;
  time: number;
  vertexData: boolean;
}

/** The wind parts of the debug hook (`?debug=1`). */
interface WindHook {
  setWindTime(seconds: number): void;
  setWind(settings: Partial<WindState>): void;
  pauseWind(paused: boolean): void;
  wind(): WindState;
  frameHash(): string | null;
  barkTexture(): { width: number; height: number } | null;
}

/** A small tree (two levels, ~4k vertices): software rendering keeps each frame short. */
const SMALL_TREE = '/?debug=1&v=1&levels=2';

/** The hook, inside page functions (they are serialised: no closures over test code). */
type HookWindow = { __sylva?: Partial<WindHook> };

async function windState(page: Page): Promise<WindState> {
  const state = await page.evaluate(() => (window as unknown as HookWindow).__sylva?.wind?.());
  if (!state) throw new Error('no wind debug hook');
  return state;
}

/** Renders the frames at the given wind times (one page task each) and returns their hashes. */
async function framesAt(page: Page, times: number[]): Promise<string[]> {
  return page.evaluate((times) => {
    const h = (window as unknown as HookWindow).__sylva;
    return times.map((t) => {
      h?.setWindTime?.(t);
      return h?.frameHash?.() ?? '';
    });
  }, times);
}

async function setWind(page: Page, settings: Partial<WindState>): Promise<void> {
  await page.evaluate((settings) => {
    (window as unknown as HookWindow).__sylva?.setWind?.(settings);
  }, settings);
}

// A smaller canvas: every frame here is rendered in software (SwiftShader). The suite runs
// with prefers-reduced-motion (playwright.config.ts), so the wind starts paused.
test.use({ viewport: { width: 1280, height: 600 } });

test('frames differ with wind on, are equal with wind off; the bark has a texture', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto(SMALL_TREE);
  await waitForTree(page);
  await page.waitForFunction(() => {
    const h = (window as unknown as HookWindow).__sylva;
    return h?.barkTexture?.() != null && h.frameHash !== undefined;
  });

  // The suite runs with prefers-reduced-motion: the wind starts paused (still blowing).
  expect(await windState(page)).toMatchObject({ enabled: true, paused: true });

  // The core's procedural bark maps arrived and are on the bark material.
  const bark = await page.evaluate(() =>
    (window as unknown as HookWindow).__sylva?.barkTexture?.(),
  );
  expect(bark).toEqual({ width: 256, height: 256 });

  // Wind on, clock paused: the frame depends only on the time uniform.
  await setWind(page, { enabled: true, strength: 1, gust: 0.5 });
  await page.evaluate(() => (window as unknown as HookWindow).__sylva?.pauseWind?.(true));
  const [a, b, again] = await framesAt(page, [0, 1.3, 0]);
  expect(a).toMatch(/^\d+x\d+:[0-9a-f]{8}$/);
  expect(b, 'wind on: t = 0 and t = 1.3 look different').not.toBe(a);
  expect(again, 'the same time renders the same frame').toBe(a);

  // Wind off: time changes nothing.
  await setWind(page, { enabled: false });
  const [offA, offB] = await framesAt(page, [0, 1.3]);
  expect(offB, 'wind off: t = 0 and t = 1.3 are the same frame').toBe(offA);
  expect(offA).not.toBe(b);

  // Strength 0 is the same still tree as wind off.
  await setWind(page, { enabled: true, strength: 0 });
  expect(await framesAt(page, [2.6])).toEqual([offA]);
  expect(errors).toEqual([]);
});

test('wind controls: resume runs the clock, pause stops it, settings survive a reload', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto(SMALL_TREE);
  await waitForTree(page);
  const panel = page.getByRole('region', { name: 'Wind' });
  await expect(panel).toBeVisible();
  await expect(panel.getByLabel('Wind', { exact: true })).toBeChecked();
  const pause = page.getByTestId('wind-pause');

  // Reduced motion: paused at first; Resume lets the clock follow real time.
  await expect(pause).toHaveAttribute('aria-pressed', 'true');
  await expect(pause).toHaveText('Resume');
  const t0 = (await windState(page)).time;
  await pause.click();
  await expect(pause).toHaveAttribute('aria-pressed', 'false');
  await expect.poll(async () => (await windState(page)).time).toBeGreaterThan(t0);

  // Pause: the time stands still.
  await pause.click();
  await expect(pause).toHaveAttribute('aria-pressed', 'true');
  const paused = (await windState(page)).time;
  expect(paused).toBeGreaterThan(t0);
  await page.waitForTimeout(300);
  expect((await windState(page)).time).toBe(paused);

  // Strength and direction through the labelled sliders.
  await page.getByTestId('wind-more').click();
  await panel.getByLabel('Strength').fill('1.5');
  await expect(page.getByTestId('wind-strength-value')).toHaveText('1.50');
  await panel.getByLabel('Direction').fill('120');
  await expect(page.getByTestId('wind-direction-value')).toHaveText('120°');
  expect(await windState(page)).toMatchObject({ strength: 1.5, direction: 120, paused: true });

  // Viewer settings, not tree params: the share URL carries no wind.
  expect(new URL(page.url()).search).not.toMatch(/wind|strength|gust/);

  await page.reload();
  await waitForTree(page);
  await page.waitForFunction(() => (window as unknown as HookWindow).__sylva?.wind !== undefined);
  expect(await windState(page)).toMatchObject({ strength: 1.5, direction: 120, paused: true });
  await expect(pause).toHaveAttribute('aria-pressed', 'true');

  // Wind off disables the other controls.
  await panel.getByLabel('Wind', { exact: true }).uncheck();
  await expect(pause).toBeDisabled();
  expect((await windState(page)).enabled).toBe(false);
  expect(errors).toEqual([]);
});
