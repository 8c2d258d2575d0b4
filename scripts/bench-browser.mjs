// Browser part of `npm run bench`: the worker round trip in the real app (built `web/dist`,
// served by `vite preview`, headless Chromium). For each of N slider changes it reads the figures
// the app itself measures (stats overlay): request -> geometry built on the main thread
// (generation in the worker + transfer + BufferGeometry), and the GPU upload + draw after it.
// Exports `benchBrowser()`; run directly it prints the result.
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, chromiumPath } from './chromium.mjs';
import { serve, stop } from './preview-server.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const CHROMIUM = chromiumPath();
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};

/** Median round trip of `runs` regenerations of the default tree; null when no browser. */
export async function benchBrowser(runs = 25) {
  if (!existsSync(CHROMIUM)) return null;
  if (!existsSync(`${root}/web/dist/index.html`))
    throw new Error('web/dist is missing: npm run build first');
  const { server, url } = await serve(4391);
  const browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: CHROMIUM_ARGS,
  });
  try {
    // Wind paused (reduced motion): software WebGL would otherwise spend the CPU on animation
    // frames that a real GPU draws for free, and the round trip would measure SwiftShader.
    const page = await browser.newPage({
      viewport: { width: 1000, height: 700 },
      reducedMotion: 'reduce',
    });
    await page.goto(`${url}?v=1`);
    const stat = page.getByTestId('stat-roundtrip');
    const hash = page.getByTestId('stat-hash');
    await page.waitForFunction(() =>
      /^[0-9a-f]{16}$/.test(
        document.querySelector('[data-testid=stat-hash]')?.textContent?.trim() ?? '',
      ),
    );
    const slider = page.locator('input[type="range"][data-param-id="l1_length"]');
    const trips = [];
    const draws = [];
    let vertices = 0;
    for (let i = 0; i < runs + 3; i++) {
      const before = (await hash.textContent())?.trim();
      await slider.evaluate(
        (el, v) => {
          const input = el;
          Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value')?.set?.call(
            input,
            String(v),
          );
          input.dispatchEvent(new Event('input', { bubbles: true }));
        },
        0.3 + 0.01 * ((i % 7) + 1),
      );
      await page.waitForFunction((b) => {
        const h = document.querySelector('[data-testid=stat-hash]')?.textContent?.trim();
        return h !== b && !document.querySelector('[data-testid=busy]');
      }, before);
      const trip = Number(await stat.getAttribute('data-roundtrip-ms'));
      const draw = Number((await stat.getAttribute('data-draw-ms')) || 0);
      vertices = Number(
        ((await page.getByTestId('stat-vertices').textContent()) ?? '').replace(/[^0-9]/g, ''),
      );
      if (i >= 3) {
        trips.push(trip);
        draws.push(draw);
      }
    }
    return { runs, vertices, round_trip_median_ms: median(trips), draw_median_ms: median(draws) };
  } finally {
    await browser.close();
    stop(server);
  }
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  console.log(JSON.stringify(await benchBrowser(), null, 2));
}
