/** Issue 17 end to end: the close-up look, rendered (a tree hole reads as a dark opening). */
import { expect, test, type Page } from '@playwright/test';
import { execFileSync } from 'node:child_process';
import { nativeCli } from '../../scripts/native-cli.mjs';
import { decodePng } from './helpers';

const WIDTH = 480;
const HEIGHT = 360;
/** The viewer's vertical field of view (degrees). */
const FOV = 40;

test.use({ viewport: { width: WIDTH, height: HEIGHT } });

interface HoleReport {
  centre: [number, number, number];
  normal: [number, number, number];
  radius: number;
}

/**
 * Mean luminance of the page in each region `[x0, x1, y0, y1]`: the pixels with |dx| in
 * [x0, x1] and |dy| in [y0, y1], offsets from the image centre.
 */
async function luminance(page: Page, regions: [number, number, number, number][]) {
  const { data, width, height } = await decodePng(page, await page.screenshot());
  return regions.map(([x0, x1, y0, y1]) => {
    let sum = 0;
    let n = 0;
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        const dx = Math.abs(x + 0.5 - width / 2);
        const dy = Math.abs(y + 0.5 - height / 2);
        if (dx < x0 || dx > x1 || dy < y0 || dy > y1) continue;
        const i = (y * width + x) * 4;
        sum += 0.2126 * data[i]! + 0.7152 * data[i + 1]! + 0.0722 * data[i + 2]!;
        n++;
      }
    }
    return n > 0 ? sum / n : NaN;
  });
}

test("a tree hole's inside is darker than its rim in a rendered close-up", async ({ page }) => {
  test.setTimeout(240_000);
  // The hole and the default size; the native CLI says where the holes are.
  for (const values of [{ hole_count: 3, hole_size: 0.7, hole_depth: 0.8 }, { hole_count: 3 }]) {
    const sets = Object.entries(values).flatMap(([k, v]) => ['--set', `${k}=${v}`]);
    const report = JSON.parse(
      execFileSync(nativeCli(), ['generate', ...sets, '--report', 'mesh']).toString(),
    ) as { hole_list?: HoleReport[] };
    const hole = (report.hole_list ?? [])
      .filter((h) => h.centre[1] > 0.5)
      .sort((a, b) => b.radius - a.radius)[0];
    expect(hole, JSON.stringify(values)).toBeDefined();
    const { centre, normal, radius } = hole!;
    const query = Object.entries(values).map(([k, v]) => `${k}=${v}`);
    await page.goto(`/embed.html?${['v=1', ...query, 'wind=0', 'aa=1'].join('&')}`);
    await page.waitForFunction(() => document.body.dataset.status === 'ready', null, {
      timeout: 120_000,
    });
    await page.evaluate(() => document.getElementById('open-in-sylva')?.remove());
    // Straight at the opening from 8 of its half-widths away.
    const away = 8 * radius;
    const eye = centre.map((c, i) => c + normal[i]! * away);
    await page.evaluate(([from, to]) => window.__sylvaEmbed?.view(from, to), [eye, centre] as [
      number[],
      number[],
    ]);
    const px = HEIGHT / 2 / (away * Math.tan(((FOV / 2) * Math.PI) / 180));
    const r = radius * px; // the opening's half-width in pixels
    const [inside, rim] = await luminance(page, [
      [0, 0.25 * r, 0, 0.25 * r],
      [1.1 * r, 1.35 * r, 0, 0.2 * r],
    ]);
    console.log(
      `hole ${JSON.stringify(values)}: half-width ${r.toFixed(0)} px, inside ${inside!.toFixed(1)}, rim ${rim!.toFixed(1)}`,
    );
    expect(inside!, 'the inside against the rim').toBeLessThan(0.5 * rim!);
  }
});
