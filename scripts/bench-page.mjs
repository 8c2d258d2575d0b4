// The page the browser benchmarks measure: the built app on the default tree, with the app's
// debug hooks, its tree drawn, and then frames paused. Software WebGL draws a frame of this tree
// in seconds: frames are not drawn between timed steps (the answers are still set up, ready for
// a frame), and a drag settles only on its release, as on a real GPU, not by the pause a slow
// frame would read as.

/**
 * A new page at `url` + `query` (1000 × 700, reduced motion; crashes and page errors logged)
 * once its first tree has a hash, rendering paused; `init` runs before any app code.
 */
export async function openDefaultTree(browser, url, { query = '?debug=1', init } = {}) {
  const page = await browser.newPage({
    viewport: { width: 1000, height: 700 },
    reducedMotion: 'reduce',
  });
  page.on('crash', () => console.error('bench: the page crashed'));
  page.on('pageerror', (e) => console.error(`bench: page error: ${e.message}`));
  if (init) await page.addInitScript(init);
  await page.goto(`${url}${query}`);
  await page.waitForFunction(() =>
    /^[0-9a-f]{16}$/.test(
      document.querySelector('[data-testid=stat-hash]')?.textContent?.trim() ?? '',
    ),
  );
  await page.evaluate(() => {
    window.__sylva.pauseRendering(true);
    window.__sylva.settleWhenIdle(false);
  });
  return page;
}
