/** Shared e2e helpers: waiting for trees, driving sliders, analysing the canvas pixels. */
import { expect, type ConsoleMessage, type Locator, type Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** Scene background colour of the viewer (web/src/viewer/TreeViewer.ts BACKGROUND_COLOR). */
export const BACKGROUND_RGB: [number, number, number] = [0xdc, 0xe6, 0xec];
/** The app's URL/localStorage write debounce is 300 ms; wait comfortably longer. */
export const DEBOUNCE_WAIT_MS = 800;

const HASH_RE = /^[0-9a-f]{16}$/;

/**
 * The app's debug build (web/dist-debug, served by playwright.config.ts on the port after the
 * app's): the same app, but its generator worker has the test hooks (`window.__sylva.panic()`
 * and `hang()` with `?debug=1`), which the shipped build (web/dist) leaves out.
 */
export const DEBUG_BUILD_URL = `http://127.0.0.1:${Number(process.env.SYLVA_E2E_PORT ?? 4317) + 1}`;

/** Collects uncaught page errors and console errors for the whole test. */
export function watchErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(`pageerror: ${error.message}`));
  page.on('console', (message: ConsoleMessage) => {
    if (message.type() === 'error') errors.push(`console.error: ${message.text()}`);
  });
  return errors;
}

/** Waits until no request is in flight and a tree hash is shown; returns the hash. */
export async function waitForTree(page: Page): Promise<string> {
  const hash = page.getByTestId('stat-hash');
  await expect(hash).toHaveText(HASH_RE);
  await expect(page.getByTestId('busy')).toHaveCount(0);
  return (await hash.textContent())?.trim() ?? '';
}

/** Waits for the tree to change away from `previousHash`; returns the new hash. */
export async function waitForNewTree(page: Page, previousHash: string): Promise<string> {
  await expect(page.getByTestId('stat-hash')).not.toHaveText(previousHash);
  return waitForTree(page);
}

/** Integer shown in a stat (strips thousands separators). */
export async function statNumber(page: Page, testId: string): Promise<number> {
  const text = (await page.getByTestId(testId).textContent()) ?? '';
  return Number(text.replace(/[^0-9.]/g, ''));
}

/** Ids of every registry-generated slider on the page, read from `data-param-id`. */
export async function sliderIds(page: Page): Promise<string[]> {
  return page
    .locator('input[type="range"][data-param-id]')
    .evaluateAll((inputs) => inputs.map((i) => i.getAttribute('data-param-id') ?? ''));
}

/** The slider for a param id. */
export function slider(page: Page, id: string): Locator {
  return page.locator(`input[type="range"][data-param-id="${id}"]`);
}

/** Sets a range input like a drag: one `input` event per value, without waiting in between. */
export async function dragSlider(page: Page, id: string, values: number[]): Promise<void> {
  await slider(page, id).evaluate((element, vals) => {
    const input = element as HTMLInputElement;
    const setter = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value')?.set;
    for (const v of vals) {
      setter?.call(input, String(v));
      input.dispatchEvent(new Event('input', { bubbles: true }));
    }
    input.dispatchEvent(new Event('change', { bubbles: true }));
  }, values);
}

/** Reads a slider's min/max/step attributes. */
export async function sliderRange(
  page: Page,
  id: string,
): Promise<{ min: number; max: number; step: number; value: number }> {
  return slider(page, id).evaluate((element) => {
    const input = element as HTMLInputElement;
    return {
      min: Number(input.min),
      max: Number(input.max),
      step: Number(input.step),
      value: Number(input.value),
    };
  });
}

/** Share of canvas pixels that differ from the background, and that look like bark/leaves. */
export interface CanvasPixels {
  width: number;
  height: number;
  nonBackground: number;
  treeLike: number;
  /** Share of clearly blue pixels: the crown envelope wireframe. */
  blueLike: number;
}

/** Screenshots the viewer canvas and classifies its pixels (decoded in the page, no deps). */
export async function analyseCanvas(page: Page): Promise<CanvasPixels> {
  // Only the WebGL canvas: the panels floating over it (wind, LOD, toolbar) are hidden for the
  // shot. (Through the CSSOM: the app's CSP refuses the <style> tag Playwright's `style` adds.)
  const overlays = (hide: boolean) =>
    page.evaluate((hide) => {
      for (const el of document.querySelectorAll<HTMLElement>('body *')) {
        if (el.tagName === 'CANVAS' || el.querySelector('canvas')) continue;
        el.style.visibility = hide ? 'hidden' : '';
      }
    }, hide);
  await overlays(true);
  const png = await page.getByTestId('viewer-canvas').screenshot();
  await overlays(false);
  return page.evaluate(
    async ({ base64, background }) => {
      // Decoded without fetch(): the app's CSP (connect-src 'self') forbids data: URLs.
      const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
      const blob = new Blob([bytes], { type: 'image/png' });
      const bitmap = await createImageBitmap(blob);
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const context = canvas.getContext('2d');
      if (!context) throw new Error('no 2d context');
      context.drawImage(bitmap, 0, 0);
      const data = context.getImageData(0, 0, bitmap.width, bitmap.height).data;
      let nonBackground = 0;
      let treeLike = 0;
      let blueLike = 0;
      const total = bitmap.width * bitmap.height;
      for (let i = 0; i < data.length; i += 4) {
        const r = data[i] ?? 0;
        const g = data[i + 1] ?? 0;
        const b = data[i + 2] ?? 0;
        const diff =
          Math.abs(r - background[0]) + Math.abs(g - background[1]) + Math.abs(b - background[2]);
        if (diff > 24) nonBackground++;
        const max = Math.max(r, g, b);
        const min = Math.min(r, g, b);
        // Bark (brown) and leaves (green) are saturated warm/green; sky and ground are greyish.
        if (max > 0 && (max - min) / max > 0.28 && r >= b && max < 235) treeLike++;
        if (b > r + 40 && b > g + 10) blueLike++;
      }
      return {
        width: bitmap.width,
        height: bitmap.height,
        nonBackground: nonBackground / total,
        treeLike: treeLike / total,
        blueLike: blueLike / total,
      };
    },
    { base64: png.toString('base64'), background: BACKGROUND_RGB },
  );
}

/** Asserts the canvas shows a tree (not just sky, not just ground). */
export async function expectTreeOnCanvas(page: Page): Promise<CanvasPixels> {
  const pixels = await analyseCanvas(page);
  expect(pixels.width).toBeGreaterThan(100);
  expect(pixels.nonBackground, 'share of non-background pixels').toBeGreaterThan(0.05);
  expect(pixels.treeLike, 'share of bark/leaf-coloured pixels').toBeGreaterThan(0.005);
  return pixels;
}

/** A param id present on the page, preferring the given candidates in order. */
export function pick(ids: string[], candidates: (string | RegExp)[]): string {
  for (const c of candidates) {
    const found = ids.find((id) => (typeof c === 'string' ? id === c : c.test(id)));
    if (found) return found;
  }
  throw new Error(`none of ${candidates.join(', ')} in ${ids.join(', ')}`);
}

/** A PNG (a screenshot) decoded by the page into RGBA bytes, row by row from the top. */
export async function decodePng(
  page: Page,
  png: Buffer,
): Promise<{ width: number; height: number; data: Uint8Array }> {
  const { width, height, base64 } = await page.evaluate(async (encoded) => {
    const bytes = Uint8Array.from(atob(encoded), (c) => c.charCodeAt(0));
    const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const context = canvas.getContext('2d');
    if (!context) throw new Error('no 2d context');
    context.drawImage(bitmap, 0, 0);
    const data = context.getImageData(0, 0, bitmap.width, bitmap.height).data;
    let binary = '';
    for (let i = 0; i < data.length; i += 0x8000) {
      binary += String.fromCharCode(...data.subarray(i, i + 0x8000));
    }
    return { width: bitmap.width, height: bitmap.height, base64: btoa(binary) };
  }, png.toString('base64'));
  return { width, height, data: new Uint8Array(Buffer.from(base64, 'base64')) };
}

/**
 * Serves a bare page (no app) at `/<prefix>/index.html` with `html`, the GLB as `tree.glb` and
 * three.js's files under `three/`, opens it, and returns its `window.report` once it is set (the
 * page's script loads the file with three.js's GLTFLoader and reports what it found).
 */
export async function bareGlbPage(
  page: Page,
  prefix: string,
  html: string,
  glb: Buffer,
): Promise<unknown> {
  const three = fileURLToPath(new URL('../../node_modules/three/', import.meta.url));
  await page.route(`**/${prefix}/**`, async (route) => {
    const path = new URL(route.request().url()).pathname.replace(`/${prefix}/`, '');
    if (path === 'index.html') {
      await route.fulfill({ contentType: 'text/html', body: html });
    } else if (path === 'tree.glb') {
      await route.fulfill({ contentType: 'model/gltf-binary', body: glb });
    } else if (path.startsWith('three/')) {
      const file = join(three, path.slice('three/'.length));
      await route.fulfill({ contentType: 'text/javascript', body: readFileSync(file) });
    } else {
      await route.fulfill({ status: 404 });
    }
  });
  await page.goto(`/${prefix}/index.html`);
  const report = await page.waitForFunction(() => (window as { report?: unknown }).report, null, {
    timeout: 120_000,
  });
  return report.jsonValue();
}
