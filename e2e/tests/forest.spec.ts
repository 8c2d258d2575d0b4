/**
 * Forest view: 1,000 trees of several unique trees render without console errors, with draw calls
 * under the fixed bound (varieties × 7 + 1), and raising N to 5,000 does not raise them past it.
 */
import { expect, test, type Page } from '@playwright/test';
import { waitForTree, watchErrors } from './helpers';

interface ForestDebug {
  drawCalls: number;
  bound: number;
  instances: number;
  visible: number;
  perLevel: number[];
  frameMs: number;
  varieties: number;
  expectedVarieties: number;
  bakeMs: number[];
}

const forest = (page: Page) =>
  page.evaluate(() => (window.__sylva as unknown as { forest(): ForestDebug }).forest());

/** Waits for `n` more animation frames of the forest's render loop. */
const frames = (page: Page, n: number) =>
  page.evaluate(
    (k) =>
      new Promise<void>((resolve) => {
        let left = k;
        const step = () => (--left <= 0 ? resolve() : requestAnimationFrame(step));
        requestAnimationFrame(step);
      }),
    n,
  );

test.use({ viewport: { width: 640, height: 400 } });

test('a forest of 1,000 then 5,000 trees keeps draw calls under the bound', async ({ page }) => {
  const errors = watchErrors(page);
  // A light tree in the editor; a forest link of 4 unique trees of 2 species (fast enough), which
  // opens the forest view.
  await page.goto('/?debug=1&v=1&levels=2&forest=4:1:quaking_aspen,fir');
  await waitForTree(page);
  await expect(page.getByTestId('forest-view')).toBeVisible();
  const varieties = page.getByTestId('forest-varieties');
  await expect(varieties).toHaveAttribute('data-total', '4');
  await expect(varieties).toHaveAttribute('data-loaded', '4', { timeout: 45_000 });
  await expect(page.getByTestId('forest-count')).toHaveText('1,000');

  await frames(page, 3);
  if (process.env.SYLVA_FOREST_SHOT) {
    await page.getByTestId('forest-view').screenshot({ path: process.env.SYLVA_FOREST_SHOT });
  }
  const small = await forest(page);
  console.log('forest 1,000:', JSON.stringify(small));
  expect(small.instances).toBe(1000);
  expect(small.varieties).toBe(4);
  expect(small.bound).toBe(4 * 7 + 1);
  expect(small.visible).toBeGreaterThan(0);
  expect(small.perLevel.reduce((a, b) => a + b, 0)).toBe(small.visible);
  // Impostors carry the distance; nearer levels are in use too.
  expect(small.perLevel[3]!).toBeGreaterThan(0);
  expect(small.perLevel[0]! + small.perLevel[1]! + small.perLevel[2]!).toBeGreaterThan(0);
  expect(small.drawCalls).toBeGreaterThan(1);
  expect(small.drawCalls).toBeLessThanOrEqual(small.bound);
  expect(small.frameMs).toBeGreaterThan(0);
  // The stats overlay shows the same numbers.
  await expect(page.getByTestId('forest-draw-calls')).toContainText(`≤ ${small.bound}`);

  // Something is drawn: the canvas is not all sky.
  const png = await page.getByTestId('forest-canvas').screenshot();
  const drawn = await page.evaluate(async (base64) => {
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const context = canvas.getContext('2d')!;
    context.drawImage(bitmap, 0, 0);
    const { data } = context.getImageData(0, 0, bitmap.width, bitmap.height);
    let green = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i]!, data[i + 1]!, data[i + 2]!];
      if (g > b + 10 && g >= r - 10) green++;
    }
    return green / (data.length / 4);
  }, png.toString('base64'));
  expect(drawn, 'share of green (tree or ground) pixels').toBeGreaterThan(0.05);

  // Five times the trees: same bound, draw calls do not grow past it.
  await page.evaluate(() =>
    (window.__sylva as unknown as { setForestTrees(n: number): void }).setForestTrees(5000),
  );
  await expect(page.getByTestId('forest-count')).toHaveText('5,000');
  await frames(page, 3);
  const large = await forest(page);
  console.log('forest 5,000:', JSON.stringify(large));
  expect(large.instances).toBe(5000);
  expect(large.bound).toBe(small.bound);
  expect(large.drawCalls).toBeLessThanOrEqual(small.bound);
  expect(large.visible).toBeGreaterThan(small.visible);

  // Leaving the forest returns to the tree viewer.
  await page.getByTestId('forest-toggle').click();
  await expect(page.getByTestId('forest-view')).toHaveCount(0);
  expect(errors).toEqual([]);
});

test("the forest view lies over the editor's hand tools", async ({ page }) => {
  // Opened from the LOD panel, the forest once left the Shape tools over its stats.
  const errors = watchErrors(page);
  await page.goto('/?debug=1&v=1&levels=2');
  await waitForTree(page);
  await page.getByTestId('forest-toggle').click();
  await expect(page.getByTestId('forest-view')).toBeVisible();
  const onTop = await page.evaluate(() => {
    const r = document.querySelector('[data-testid=tool-paint]')!.getBoundingClientRect();
    const top = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
    return top?.closest('[data-testid]')?.getAttribute('data-testid') ?? null;
  });
  expect(onTop, 'what is drawn where the Paint button is').not.toBe('tool-paint');
  expect(errors).toEqual([]);
});
