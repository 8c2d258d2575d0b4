/**
 * Seasons end to end: the oak bearing acorns in September draws its acorns, cups and stalks as
 * instanced meshes that change the picture (a frame with and without them differs), from a
 * share link carrying the Season; the default tree in January shows winter buds and its fallen
 * leaves lying on the ground. Close-ups are saved under e2e/test-results/ (docs/img/ holds
 * the chosen ones).
 */
import { expect, test, type Page } from '@playwright/test';
import { decodePng, waitForNewTree, waitForTree, watchErrors } from './helpers';

type Vec3 = [number, number, number];

/** The debug hook's organ report (`TreeViewer.organs`). */
interface OrganReport {
  sets: { name: string; kind: string; count: number; visible: boolean; samples: Vec3[] }[];
  leaves: number;
  onGround: number;
}

/** The parts of the debug hook used here. */
interface SeasonHook {
  organs(): OrganReport | null;
  setOrgansVisible(visible: boolean): void;
  frameHash(): string | null;
  view(from: Vec3, to: Vec3): void;
  setWind(settings: { enabled: boolean }): void;
}

type HookWindow = { __sylva?: Partial<SeasonHook> };

async function organs(page: Page): Promise<OrganReport> {
  const report = await page.evaluate(() => (window as unknown as HookWindow).__sylva?.organs?.());
  if (!report) throw new Error('no organ debug hook');
  return report;
}

/** A frame's pixel hash with the organ meshes shown or hidden. */
async function frameWithOrgans(page: Page, visible: boolean): Promise<string> {
  return page.evaluate((visible) => {
    const h = (window as unknown as HookWindow).__sylva;
    h?.setOrgansVisible?.(visible);
    return h?.frameHash?.() ?? '';
  }, visible);
}

async function view(page: Page, from: Vec3, to: Vec3): Promise<void> {
  await page.evaluate(([from, to]) => (window as unknown as HookWindow).__sylva?.view?.(from, to), [
    from,
    to,
  ] as [Vec3, Vec3]);
}

/** Share of the canvas's pixels that change when the organ meshes are hidden. */
async function organShare(page: Page): Promise<number> {
  const shot = async (visible: boolean) => {
    await page.evaluate(
      (visible) => (window as unknown as HookWindow).__sylva?.setOrgansVisible?.(visible),
      visible,
    );
    await page.waitForTimeout(150);
    return decodePng(page, await page.getByTestId('viewer-canvas').screenshot());
  };
  const hidden = await shot(false);
  const shown = await shot(true);
  let changed = 0;
  for (let i = 0; i < shown.data.length; i += 4) {
    const d =
      Math.abs((shown.data[i] ?? 0) - (hidden.data[i] ?? 0)) +
      Math.abs((shown.data[i + 1] ?? 0) - (hidden.data[i + 1] ?? 0)) +
      Math.abs((shown.data[i + 2] ?? 0) - (hidden.data[i + 2] ?? 0));
    if (d > 30) changed++;
  }
  return changed / (shown.width * shown.height);
}

/** Saves the viewer canvas alone (the panels over it hidden through the CSSOM, as helpers.ts does). */
async function canvasShot(page: Page, path: string): Promise<void> {
  const overlays = (hide: boolean) =>
    page.evaluate((hide) => {
      for (const el of document.querySelectorAll<HTMLElement>('body *')) {
        if (el.tagName === 'CANVAS' || el.querySelector('canvas')) continue;
        el.style.visibility = hide ? 'hidden' : '';
      }
    }, hide);
  await overlays(true);
  await page.waitForTimeout(300);
  await page.getByTestId('viewer-canvas').screenshot({ path });
  await overlays(false);
}

/** The share link of preset `name` (its values, written into the URL when picked). */
async function presetLink(page: Page, name: string): Promise<URL> {
  await page.goto('/?debug=1');
  const first = await waitForTree(page);
  await page.getByTestId('preset-picker').selectOption(name);
  await waitForNewTree(page, first);
  await expect.poll(() => new URL(page.url()).searchParams.size).toBeGreaterThan(5);
  return new URL(page.url());
}

test.use({ viewport: { width: 1280, height: 800 } });

test('an oak in September bears acorns, drawn instanced and changing the picture', async ({
  page,
}, testInfo) => {
  test.setTimeout(180_000);
  const errors = watchErrors(page);
  const link = await presetLink(page, 'oak');
  // The Season and the Fruit travel in the share link (Fruit 1 = Acorns).
  link.searchParams.set('season', '9.5');
  link.searchParams.set('fruit', '1');
  link.searchParams.set('debug', '1');
  await page.goto(link.pathname + link.search);
  await waitForTree(page);
  await expect.poll(async () => (await organs(page)).sets.length).toBe(3);
  const report = await organs(page);
  expect(report.sets.map((s) => s.name).sort()).toEqual(['acorn cups', 'acorn stalks', 'acorns']);
  for (const set of report.sets) {
    expect(set.visible, set.name).toBe(true);
    expect(set.count, set.name).toBeGreaterThan(20);
  }
  // The sets are drawn: the frame without them differs from the frame with them. Up close on
  // an acorn at the edge of the crown: of a few candidates, the view where the parts cover the
  // most pixels (the crown is dense; most acorns hang behind leaves).
  const acorns = report.sets.find((s) => s.name === 'acorns');
  if (!acorns) throw new Error('no acorns');
  // Still air: the parts sit where their matrices put them.
  await page.evaluate(() =>
    (window as unknown as HookWindow).__sylva?.setWind?.({ enabled: false }),
  );
  const radial = (p: Vec3) => Math.hypot(p[0], p[2]);
  const candidates = [...acorns.samples].sort((a, b) => radial(b) - radial(a)).slice(0, 6);
  let best: { eye: Vec3; at: Vec3; share: number } | null = null;
  for (const at of candidates) {
    const r = radial(at) || 1;
    const eye: Vec3 = [at[0] + (at[0] / r) * 0.35, at[1] + 0.05, at[2] + (at[2] / r) * 0.35];
    await view(page, eye, at);
    const share = await organShare(page);
    if (!best || share > best.share) best = { eye, at, share };
  }
  if (!best) throw new Error('no candidate view');
  console.log(`acorn close-up: ${(100 * best.share).toFixed(2)} % of the pixels are parts`);
  expect(best.share, 'share of the close-up the acorns cover').toBeGreaterThan(0.001);
  await view(page, best.eye, best.at);
  const shown = await frameWithOrgans(page, true);
  const hidden = await frameWithOrgans(page, false);
  expect(hidden).not.toBe(shown);
  expect(await frameWithOrgans(page, true)).toBe(shown);
  await canvasShot(page, testInfo.outputPath('organs-acorns.png'));
  // The share link still carries the Season.
  expect(new URL(page.url()).searchParams.get('season')).toBe('9.5');
  expect(errors).toEqual([]);
});

test('a tree in January shows winter buds and its fallen leaves on the ground', async ({
  page,
}, testInfo) => {
  test.setTimeout(180_000);
  const errors = watchErrors(page);
  await page.goto('/?debug=1&v=1&season=1.5');
  await waitForTree(page);
  await expect.poll(async () => (await organs(page)).sets.length).toBeGreaterThan(0);
  const report = await organs(page);
  expect(report.sets.map((s) => s.kind)).toEqual(['bud']);
  expect(report.sets[0]?.count).toBeGreaterThan(50);
  // Bare in January: every leaf lies on the ground.
  expect(report.leaves).toBeGreaterThan(100);
  expect(report.onGround).toBe(report.leaves);
  // Low over the litter, looking at the foot of the trunk.
  await view(page, [7, 1.6, 9], [0, 0.4, 0]);
  const shown = await frameWithOrgans(page, true);
  expect(await frameWithOrgans(page, false)).not.toBe(shown);
  await frameWithOrgans(page, true);
  await canvasShot(page, testInfo.outputPath('organs-litter.png'));
  expect(errors).toEqual([]);
});

/** The leaf inspector's month tint (`data-month-tint` on its SVG: "r g b" or "none"). */
async function inspectorTint(page: Page): Promise<number[] | 'none'> {
  const value = await page.getByTestId('leaf-svg').getAttribute('data-month-tint');
  if (!value) throw new Error('the leaf drawing carries no month tint');
  return value === 'none' ? 'none' : value.split(' ').map(Number);
}

test('the leaf inspector shows the leaf in the colour of the Season', async ({ page }) => {
  const errors = watchErrors(page);
  // The default tree wears the aspen's calendar: green in July, golden in October, bare in January.
  const tints: Record<string, number[] | 'none'> = {};
  for (const [month, season] of [
    ['July', '7.5'],
    ['October', '10.3'],
    ['January', '1.5'],
  ] as const) {
    await page.goto(`/?debug=1&v=1&season=${season}`);
    await waitForTree(page);
    await page.getByTestId('tab-leaf').click();
    await expect(page.getByTestId('leaf-svg')).toBeVisible();
    await expect
      .poll(() => page.getByTestId('leaf-svg').getAttribute('data-month-tint'))
      .not.toBe(null);
    tints[month] = await inspectorTint(page);
    // A tinted drawing goes through a colour matrix in linear light; a bare tree's through none.
    const matrix = page.locator(
      '[data-testid="leaf-svg"] filter#sylva-month-tint[color-interpolation-filters="linearRGB"] feColorMatrix',
    );
    await expect(matrix).toHaveCount(month === 'January' ? 0 : 1);
  }
  // And it is seen: the October drawing (the last tinted one, drawn again) is a golden leaf on
  // white paper, not a blank page.
  await page.goto('/?debug=1&v=1&season=10.3');
  await waitForTree(page);
  await page.getByTestId('tab-leaf').click();
  await expect(page.getByTestId('leaf-svg')).toHaveAttribute('data-month-tint', /\d/);
  const shot = await decodePng(page, await page.getByTestId('leaf-svg').screenshot());
  let ink = 0;
  let [red, blue] = [0, 0];
  for (let i = 0; i < shot.data.length; i += 4) {
    const [r, g, b] = [shot.data[i]!, shot.data[i + 1]!, shot.data[i + 2]!];
    if (765 - r - g - b < 60) continue;
    ink++;
    red += r;
    blue += b;
  }
  expect(ink / (shot.width * shot.height), 'share of the drawing that is leaf').toBeGreaterThan(
    0.1,
  );
  expect(red / ink, 'the October leaf is warm').toBeGreaterThan(blue / ink + 60);
  const [july, october] = [tints.July, tints.October];
  if (!Array.isArray(july) || !Array.isArray(october)) throw new Error(JSON.stringify(tints));
  expect(Math.abs(july[0]! - july[2]!)).toBeLessThan(0.15);
  expect(october[0]!).toBeGreaterThan(2 * october[2]!);
  expect(tints.January).toBe('none');
  expect(errors).toEqual([]);
});
