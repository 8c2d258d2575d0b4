// The Chromium that the Playwright tests (e2e/playwright.config.ts) and the browser benchmark
// (bench-browser.mjs) launch: Debian's, or `$SYLVA_CHROMIUM` (the variable setup.sh checks), with
// the flags both need. Never Playwright's own browser download.

/** Path of the Chromium binary given the environment `env`. */
export function chromiumPath(env = process.env) {
  return env.SYLVA_CHROMIUM || '/usr/bin/chromium';
}

/** Launch flags: no sandbox (containers), no background traffic, WebGL2 through SwiftShader. */
export const CHROMIUM_ARGS = [
  '--no-sandbox',
  // (no --disable-gpu: with it the compositor is software and reads every WebGL frame back with
  // a blocking glReadPixels on the main thread, one long task per frame)
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--use-gl=angle',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
];
