/**
 * The impostor shows one trunk: with the camera between two atlas frames (the blend's worst
 * case: two views weighted ½ each, 16° apart in elevation and 11° in azimuth), a row of pixels
 * across the trunk below the crown has one run of tree pixels, as LOD0 has from the same camera,
 * and no wider than LOD0's (a trunk seen twice, or smeared, is two runs or a wide one).
 */
import { expect, test, type Page } from '@playwright/test';
import { writeFileSync } from 'node:fs';
import { waitForTree, watchErrors } from './helpers';

type Vec3 = [number, number, number];

interface Hook {
  lod(): { radius: number };
  edits(): { bounds: { min: number[]; max: number[] } | null };
  view(from: Vec3, to: Vec3): void;
  setLodMode(mode: 'auto' | 'hidden' | number): void;
  project(p: Vec3): [number, number];
}

/**
 * Unit direction halfway between frames (1, 3) and (0, 4) of the 8 × 8 hemi-octahedral atlas
 * (web/src/lod/hemiOct.ts: decode(0.5 / 7, 3.5 / 7)); the 3rd frame's weight is 0 there.
 */
function betweenFrames(): Vec3 {
  const a = (0.5 / 7) * 2 - 1;
  const b = (3.5 / 7) * 2 - 1;
  const px = (a + b) / 2;
  const pz = (a - b) / 2;
  const y = 1 - Math.abs(px) - Math.abs(pz);
  const len = Math.hypot(px, y, pz);
  return [px / len, y / len, pz / len];
}

/** The canvas as PNG after the next two frames, the overlays hidden. */
async function frame(page: Page): Promise<Buffer> {
  await page.evaluate(
    () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(null)))),
  );
  const overlays = page.locator('.stage > :not(.viewport)');
  await overlays.evaluateAll((els) =>
    els.forEach((e) => ((e as HTMLElement).style.visibility = 'hidden')),
  );
  const png = await page.getByTestId('viewer-canvas').screenshot({ animations: 'allow' });
  await overlays.evaluateAll((els) =>
    els.forEach((e) => ((e as HTMLElement).style.visibility = '')),
  );
  return png;
}

/**
 * Runs of tree pixels (differing from the empty frame by more than 30 summed over RGB) along
 * canvas row `y`, gaps of one pixel bridged: [start, end] pairs.
 */
async function rowRuns(page: Page, tree: Buffer, empty: Buffer, y: number): Promise<number[][]> {
  return page.evaluate(
    async ({ tree, empty, y }) => {
      const decode = async (base64: string) => {
        const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
        const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
        const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
        const context = canvas.getContext('2d')!;
        context.drawImage(bitmap, 0, 0);
        return context.getImageData(0, 0, bitmap.width, bitmap.height);
      };
      const a = await decode(tree);
      const b = await decode(empty);
      const runs: number[][] = [];
      for (let x = 0; x < a.width; x++) {
        const i = (y * a.width + x) * 4;
        let d = 0;
        for (let c = 0; c < 3; c++) d += Math.abs(a.data[i + c]! - b.data[i + c]!);
        if (d <= 30) continue;
        const last = runs[runs.length - 1];
        if (last && x - last[1]! <= 2) last[1] = x;
        else runs.push([x, x]);
      }
      return runs;
    },
    { tree: tree.toString('base64'), empty: empty.toString('base64'), y },
  );
}

test.use({ viewport: { width: 900, height: 560 } });

test('the impostor between two atlas frames shows one trunk, as LOD0 does', async ({ page }) => {
  test.setTimeout(180_000);
  const errors = watchErrors(page);
  await page.goto('/?debug=1');
  await waitForTree(page);
  const levels = page.getByTestId('lod-levels');
  await expect(levels).toHaveAttribute('data-ready', 'true', { timeout: 60_000 });
  const { radius, bounds } = await page.evaluate(() => {
    const s = window.__sylva as unknown as Hook;
    return { radius: s.lod().radius, bounds: s.edits().bounds };
  });
  const { min, max } = bounds!;
  const centre = [0, 1, 2].map((k) => (min[k]! + max[k]!) / 2) as Vec3;
  const dir = betweenFrames();
  // Up close: the tree fills 90 % of the half view height (fov 40°).
  const distance = radius / (0.9 * Math.tan((20 * Math.PI) / 180));
  const from = centre.map((c, k) => c + dir[k]! * distance) as Vec3;
  // The row: across the trunk at 15 % of the tree's height, below the crown.
  const row = await page.evaluate(
    ({ from, centre, foot }) => {
      const s = window.__sylva as unknown as Hook;
      s.view(from, centre);
      const [, y] = s.project(foot);
      const box = document.querySelector('[data-testid="viewer-canvas"]')!.getBoundingClientRect();
      return Math.round(y - box.top);
    },
    { from, centre, foot: [centre[0], min[1]! + (max[1]! - min[1]!) * 0.15, centre[2]] as Vec3 },
  );
  const setMode = (mode: 'auto' | 'hidden' | number) =>
    page.evaluate((m) => (window.__sylva as unknown as Hook).setLodMode(m), mode);
  await setMode('hidden');
  const empty = await frame(page);
  const shots: Record<string, Buffer> = {};
  for (const level of [0, 3]) {
    await setMode(level);
    // The impostor is baked the first time it is shown.
    await expect(levels).toHaveAttribute('data-level', String(level), { timeout: 60_000 });
    shots[level] = await frame(page);
  }
  const lod0 = await rowRuns(page, shots[0]!, empty, row);
  const impostor = await rowRuns(page, shots[3]!, empty, row);
  console.log(
    `row ${row}: LOD0 runs ${JSON.stringify(lod0)}, impostor ${JSON.stringify(impostor)}`,
  );
  if (process.env.SYLVA_IMPOSTOR_SHOT) writeFileSync(process.env.SYLVA_IMPOSTOR_SHOT, shots[3]!);
  expect(lod0).toHaveLength(1);
  expect(impostor, 'the impostor shows the trunk once').toHaveLength(1);
  const width = (runs: number[][]) => runs[0]![1]! - runs[0]![0]! + 1;
  expect(width(impostor)).toBeLessThanOrEqual(width(lod0) * 2 + 2);
  // Where LOD0's trunk is: the runs overlap.
  expect(impostor[0]![0]!).toBeLessThanOrEqual(lod0[0]![1]! + 2);
  expect(impostor[0]![1]!).toBeGreaterThanOrEqual(lod0[0]![0]! - 2);
  await setMode('auto');
  expect(errors).toEqual([]);
});
