import { chromium } from 'playwright-core';
import { openDefaultTree } from './bench-page.mjs';
import { CHROMIUM_ARGS, chromiumPath } from './chromium.mjs';
import { freePort, serve } from './preview-server.mjs';
const { url, stop } = await serve(await freePort());
const browser = await chromium.launch({ executablePath: chromiumPath(), args: CHROMIUM_ARGS });
try {
  const page = await openDefaultTree(browser, url, {});
  const r = await page.evaluate(() => {
    const c = document.querySelector('canvas[data-testid="viewer-canvas"]').getBoundingClientRect();
    const pts = [];
    for (let i = 0; i < 40; i++) pts.push([c.left + c.width * (0.3 + 0.4 * (i % 8) / 8), c.top + c.height * (0.2 + 0.6 * Math.floor(i / 8) / 5)]);
    const t0 = performance.now(); let hits = 0;
    for (const [x, y] of pts) if (window.__sylva.pickBark(x, y)) hits++;
    const t1 = performance.now();
    return { barkMs: (t1 - t0) / pts.length, hits };
  });
  console.log(JSON.stringify(r));
} finally { await browser.close(); await stop(); }
