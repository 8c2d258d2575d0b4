// Browser bench `forest_unique`: the default forest (16 unique trees with their levels of detail
// and impostors, generated in the studio's generation pool), timed in the page from the click on
// Forest to the last tree shown (added to the scene, then the next frame drawn), in a fresh page
// per run; the median over runs.
import { openDefaultTree } from './bench-page.mjs';
import { median, round } from './bench-stats.mjs';

/** One run: ms from the click to the last of the forest's trees shown, and the pool size. */
async function forestRun(browser, url) {
  const page = await openDefaultTree(browser, url);
  try {
    // The editor's viewer stays paused: the forest has its own canvas and loop.
    const clickAt = await page.evaluate(() => {
      const at = performance.now();
      document.querySelector('[data-testid=forest-toggle]').click();
      return at;
    });
    await page.waitForFunction(
      () => {
        const el = document.querySelector('[data-testid=forest-varieties]');
        const total = el?.getAttribute('data-total');
        return total && total !== '0' && el.getAttribute('data-loaded') === total;
      },
      undefined,
      { timeout: 600_000, polling: 100 },
    );
    const { last, pool, trees } = await page.evaluate(
      () =>
        new Promise((resolve) =>
          requestAnimationFrame(() => {
            const f = window.__sylva.forest();
            resolve({ last: Math.max(...f.shownAt), pool: f.poolSize, trees: f.varieties });
          }),
        ),
    );
    return { ms: last - clickAt, pool, trees };
  } finally {
    await page.close();
  }
}

/** `forest_unique`: the median of `runs` runs (see the file's comment). */
export async function benchForestUnique(browser, url, runs = 3) {
  const all = [];
  for (let i = 0; i < runs; i++) all.push(await forestRun(browser, url));
  return {
    trees: all[0].trees,
    pool: all[0].pool,
    runs: all.map((r) => round(r.ms)),
    median_ms: round(median(all.map((r) => r.ms))),
  };
}
