/**
 * Shape by hand on the real app, with Playwright's mouse: a paint stroke beside the tree makes
 * it grow there (the bounds and the pixels), a click cuts a branch (fewer vertices), the share
 * link reproduces the edited tree's hash in a fresh page (a younger Age has the branch whole, an
 * older one a callus over the cut), and undo restores the hash. The cut faces' end grain is in
 * the viewer as soon as the Cut tool is chosen.
 *
 * Needs a core that reads the edit list (`SkeletonParams::edits`, the `"edits"` key of the
 * generate JSON): a core without it rejects the key and the edited tree never comes.
 */
import { expect, test, type Page } from '@playwright/test';
import {
  BACKGROUND_RGB,
  DEBOUNCE_WAIT_MS,
  decodePng,
  statNumber,
  waitForNewTree,
  waitForTree,
  watchErrors,
} from './helpers';

type Point = [number, number, number];

/** The debug hook's view of the hand edits (present with `?debug=1`). */
async function editsState(page: Page) {
  const state = await page.evaluate(() => window.__sylva?.edits?.() ?? null);
  if (!state) throw new Error('the edits debug hook is missing');
  return state;
}

/** The bark type of the end grain in the viewer (-1: none yet; the debug hook). */
function endGrainKind(page: Page): Promise<number | null> {
  return page.evaluate(() => window.__sylva?.endGrainKind?.() ?? null);
}

/** Client pixel of tree-space point `p`. */
async function project(page: Page, p: Point): Promise<[number, number]> {
  return page.evaluate((q) => window.__sylva?.project?.(q) ?? [0, 0], p);
}

/** Pixels of the page clip around `(x, y)` that are not the sky. */
async function treePixelsAround(page: Page, x: number, y: number, r = 40): Promise<number> {
  const png = await page.screenshot({ clip: { x: x - r, y: y - r, width: 2 * r, height: 2 * r } });
  const { data } = await decodePng(page, png);
  let count = 0;
  for (let i = 0; i < data.length; i += 4) {
    const d =
      Math.abs((data[i] ?? 0) - BACKGROUND_RGB[0]) +
      Math.abs((data[i + 1] ?? 0) - BACKGROUND_RGB[1]) +
      Math.abs((data[i + 2] ?? 0) - BACKGROUND_RGB[2]);
    if (d > 60) count++;
  }
  return count;
}

/**
 * A bark point of a main branch and its client pixel: of the bark under the cursor in the
 * lower crown (5 to 8 m up), the point nearest to 1 m from the trunk's axis: a main branch
 * near its base, so the cut takes a limb with its twigs rather than a twig's tip.
 */
async function findBranch(page: Page): Promise<{ x: number; y: number; at: Point }> {
  const box = await page.getByTestId('viewer-canvas').boundingBox();
  if (!box) throw new Error('no canvas');
  const found = await page.evaluate((b) => {
    let best: { x: number; y: number; at: Point; r: number } | null = null;
    for (let y = b.y + 20; y < b.y + b.height - 20; y += 8) {
      for (let x = b.x + 20; x < b.x + b.width - 20; x += 8) {
        const at = window.__sylva?.pickBark?.(x, y) ?? null;
        if (!at || at[1] < 5 || at[1] > 8) continue;
        const r = Math.abs(Math.hypot(at[0], at[2]) - 1);
        if (!best || r < best.r) best = { x, y, at, r };
      }
    }
    return best;
  }, box);
  if (!found) throw new Error('no branch under the cursor anywhere');
  return found;
}

test('paint a stroke beside the tree: it grows toward it; undo restores the hash', async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto('/?debug=1');
  const original = await waitForTree(page);
  // From the side, looking along -z: the trunk plane is z = 0.
  const before = (await editsState(page)).bounds;
  if (!before) throw new Error('no bounds');
  const height = before.max[1] ?? 10;
  const midY = height * 0.6;
  await page.evaluate(([y, d]) => window.__sylva?.view?.([0, y, d], [0, y, 0]), [
    midY,
    height * 2.2,
  ] as const);
  await page.waitForTimeout(300);
  const edge = before.max[0] ?? 2;
  const start: Point = [edge - 0.3, midY, 0];
  const end: Point = [edge + 2.5, midY + 0.5, 0];
  const [ex, ey] = await project(page, end);
  const skyBefore = await treePixelsAround(page, ex, ey);

  await page.keyboard.press('p');
  await expect(page.getByTestId('tool-paint')).toHaveAttribute('aria-pressed', 'true');
  const [sx, sy] = await project(page, start);
  await page.mouse.move(sx, sy);
  await page.mouse.down();
  for (let k = 1; k <= 40; k++) {
    const t = k / 40;
    await page.mouse.move(sx + (ex - sx) * t, sy + (ey - sy) * t);
    await page.waitForTimeout(16);
  }
  await page.mouse.up();
  await page.keyboard.press('Escape');
  const painted = await waitForNewTree(page, original);
  expect((await editsState(page)).count).toBe(1);
  await expect(page.getByTestId('edit-row')).toHaveCount(1);
  const after = (await editsState(page)).bounds;
  expect(after?.max[0] ?? 0).toBeGreaterThan(edge + 0.5);
  await page.waitForTimeout(300);
  expect(await treePixelsAround(page, ex, ey)).toBeGreaterThan(skyBefore + 50);

  await page.keyboard.press('Control+z');
  expect(await waitForNewTree(page, painted)).toBe(original);
  expect((await editsState(page)).count).toBe(0);
  expect(errors).toEqual([]);
});

test('click-cut a branch: fewer vertices; the share link gives the same tree; undo restores', async ({
  page,
  browser,
}) => {
  const errors = watchErrors(page);
  await page.goto('/?debug=1');
  const original = await waitForTree(page);
  const vertices = await statNumber(page, 'stat-vertices');
  const branch = await findBranch(page);

  // Choosing the Cut tool has the worker bake the end grain while the user aims (it once took
  // the first cut 0.25-0.3 s): it is in the viewer before any cut.
  expect(await endGrainKind(page)).toBe(-1);
  await page.keyboard.press('c');
  await expect.poll(() => endGrainKind(page)).toBeGreaterThanOrEqual(0);
  await page.mouse.click(branch.x, branch.y);
  const cut = await waitForNewTree(page, original);
  expect(await statNumber(page, 'stat-vertices')).toBeLessThan(vertices);
  await expect(page.getByTestId('edit-row')).toHaveCount(1);
  await expect(page.getByTestId('edit-unresolved')).toHaveCount(0);

  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  const link = page.url();
  // The cut carries the tree's Age (40) as its year.
  expect(new URL(link).searchParams.get('e')).toMatch(/^1~c-?\d+\.\d+\.-?\d+\.40$/);
  const fresh = await browser.newPage();
  await fresh.goto(link);
  expect(await waitForTree(fresh)).toBe(cut);
  await expect(fresh.getByTestId('edit-row')).toHaveCount(1);
  // Younger than the cut: the branch is whole (the uncut tree of that age), the cut pending.
  const at = (age: number, edits: boolean) => {
    const u = new URL(link);
    if (!edits) u.searchParams.delete('e');
    u.searchParams.set('age', String(age));
    // Past the Mature Age, only the callus: no shedding, thickening or drooping.
    if (age > 40)
      for (const id of ['shed_light', 'ring_width', 'droop']) u.searchParams.set(id, '0');
    return u.toString();
  };
  await fresh.goto(at(30, false));
  const young = await waitForTree(fresh);
  await fresh.goto(at(30, true));
  expect(await waitForTree(fresh)).toBe(young);
  await expect(fresh.getByTestId('edit-pending')).toHaveText('in year 40');
  // Fifteen years on (the life over decades off, so the tree keeps its mature form): woundwood
  // rolls over the face, one more ring of vertices around the stump.
  await fresh.goto(at(55, true));
  expect(await waitForTree(fresh)).not.toBe(cut);
  await expect(fresh.getByTestId('edit-pending')).toHaveCount(0);
  const extra =
    (await statNumber(fresh, 'stat-vertices')) - (await statNumber(page, 'stat-vertices'));
  expect(extra).toBeGreaterThanOrEqual(5);
  expect(extra).toBeLessThanOrEqual(65);
  await fresh.close();

  await page.keyboard.press('Control+z');
  expect(await waitForNewTree(page, cut)).toBe(original);
  await page.waitForTimeout(DEBOUNCE_WAIT_MS);
  expect(new URL(page.url()).searchParams.get('e')).toBeNull();
  expect(errors).toEqual([]);
});

test("with the Cut tool on, another preset's bark brings its end grain before any cut", async ({
  page,
}) => {
  const errors = watchErrors(page);
  await page.goto('/?debug=1');
  const original = await waitForTree(page);
  const barkType = async () =>
    Number(await page.locator('select[data-param-id="bark_type"]').inputValue());
  await page.keyboard.press('c');
  const first = await barkType();
  await expect.poll(() => endGrainKind(page)).toBe(first);
  // A preset of another bark type (its maps and its end grain, still no cut).
  const names = await page
    .getByTestId('preset-picker')
    .locator('option')
    .evaluateAll((options) => options.map((o) => (o as HTMLOptionElement).value));
  let shown = original;
  for (const name of names.filter((n) => n && n !== 'default')) {
    await page.getByTestId('preset-picker').selectOption(name);
    shown = await waitForNewTree(page, shown);
    if ((await barkType()) !== first) break;
  }
  const other = await barkType();
  expect(other).not.toBe(first);
  await expect.poll(() => endGrainKind(page)).toBe(other);
  await expect(page.getByTestId('edit-row')).toHaveCount(0);
  expect(errors).toEqual([]);
});
