/**
 * Playwright config: Debian's Chromium (software WebGL2 via SwiftShader) against `vite preview` of
 * web/dist, and of web/dist-debug (the app's debug build, whose worker has the test hooks) on the
 * next port for the tests of the crash recovery and the time limit (`DEBUG_BUILD_URL`).
 */
import { defineConfig, devices } from '@playwright/test';
import { fileURLToPath } from 'node:url';
import { CHROMIUM_ARGS, chromiumPath } from '../scripts/chromium.mjs';

// SYLVA_E2E_PORT / SYLVA_DIST let several builds be tested side by side (default: web/dist on 4317).
const PORT = Number(process.env.SYLVA_E2E_PORT ?? 4317);
const DIST = process.env.SYLVA_DIST ? ` --outDir ${process.env.SYLVA_DIST}` : '';
const repoRoot = fileURLToPath(new URL('..', import.meta.url));
// helpers.ts `DEBUG_BUILD_URL` is the same port.
const DEBUG_PORT = PORT + 1;

export default defineConfig({
  testDir: './tests',
  timeout: 90_000,
  expect: { timeout: 20_000 },
  retries: 0,
  workers: 1,
  fullyParallel: false,
  forbidOnly: !!process.env.CI,
  reporter: 'list',
  outputDir: './test-results',
  use: {
    baseURL: `http://127.0.0.1:${PORT}`,
    viewport: { width: 1280, height: 800 },
    // The app then starts with the wind paused: no continuous software-WebGL rendering in the
    // background of every test (wind.spec.ts opts back in where it needs the live clock).
    reducedMotion: 'reduce',
    trace: 'off',
    screenshot: 'only-on-failure',
  },
  projects: [
    {
      name: 'chromium',
      use: {
        ...devices['Desktop Chrome'],
        viewport: { width: 1280, height: 800 },
        launchOptions: {
          executablePath: chromiumPath(),
          args: CHROMIUM_ARGS,
        },
      },
    },
  ],
  webServer: [
    {
      // web/dist must already be built (`npm run build -w web`); this only serves it.
      command: `npm run preview -w web -- --port ${PORT} --strictPort${DIST}`,
      cwd: repoRoot,
      url: `http://127.0.0.1:${PORT}/`,
      reuseExistingServer: !process.env.CI,
      timeout: 60_000,
      stdout: 'ignore',
      stderr: 'pipe',
    },
    {
      // web/dist-debug must already be built (`npm run build:debug -w web`, after
      // `scripts/setup.sh --test` built the debug core); `npm test` builds both.
      command: `npm run preview -w web -- --port ${DEBUG_PORT} --strictPort --outDir dist-debug`,
      cwd: repoRoot,
      url: `http://127.0.0.1:${DEBUG_PORT}/`,
      reuseExistingServer: !process.env.CI,
      timeout: 60_000,
      stdout: 'ignore',
      stderr: 'pipe',
    },
  ],
});
