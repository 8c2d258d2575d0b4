// Browser part of `npm run bench`: the built app (`web/dist`, served by `vite preview`) in
// headless Chromium, measured end to end with the app's own debug events (`?debug=1`):
//   - first_tree_ms: navigation to the first tree drawn (median over fresh pages; in software
//     WebGL that frame is drawn at half resolution), first_tree_in_scene_ms: to its arrays in
//     the scene, ready for that frame, and first_shadowed_ms: to the end of the next frame, the
//     first with the tree's shadows and at full resolution;
//   - drag: 20-step drags of each control of DRAG_PARAMS; per step, the time from the input event
//     to the answer (preview or full) being in the scene (`sylva:applied`: buffers received,
//     attributes set, ready for the next frame); after each drag, settle_ms = release to the
//     full-quality tree in the scene; frame_ms = a frame's upload + draw (the GPU waited for),
//     drawn after each drag and each release (no frames are drawn between the timed steps);
//   - age: a 20-step drag of Age on the default tree, toward younger trees (the growth replay);
//   - paint and cut: the hand-edit tools (bench-edits.mjs);
//   - forest_unique: 16 unique trees with their LODs from the studio's generation pool, click to
//     the last tree shown (bench-forest.mjs).
// Exports `benchBrowser()`; run directly it prints the result.
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { benchCut, benchPaint } from './bench-edits.mjs';
import { benchForestUnique } from './bench-forest.mjs';
import { openDefaultTree } from './bench-page.mjs';
import { CHROMIUM_ARGS, chromiumPath } from './chromium.mjs';
import { freePort, serve } from './preview-server.mjs';
import { median, percentile, round } from './bench-stats.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const CHROMIUM = chromiumPath();

/** The sliders (and other controls) the drag benchmark moves, in order. */
export const DRAG_PARAMS = [
  'l1_branches',
  'l1_length',
  'attraction_up',
  'shape',
  'leaves',
  'foliage_angle',
  'leaf_teeth',
  'mesh_quality',
  'seed',
  'show_preview',
];
const STEPS = 20;

/**
 * Navigation to the first tree in the scene (its arrays set up), to its first frame drawn by
 * the GPU, and to the next frame, the first with the tree's shadows (ms), in a fresh page each
 * time.
 */
async function firstTree(browser, url, runs) {
  const times = [];
  for (let i = 0; i < runs; i++) {
    const context = await browser.newContext({
      viewport: { width: 1000, height: 700 },
      reducedMotion: 'reduce',
    });
    const page = await context.newPage();
    // Before any app code runs: resolve with the time the first tree's arrays were in the
    // scene and the end of the first frame after it.
    await page.addInitScript(() => {
      window.__firstTree = new Promise((resolve) => {
        addEventListener(
          'sylva:applied',
          () => {
            const inScene = performance.now();
            // After the app's frame: wait until the GPU has drawn it (a one-pixel read-back
            // finishes every command before it), not only until the frame was sent to it.
            const drawnNow = () => {
              const gl = document
                .querySelector('canvas[data-testid="viewer-canvas"]')
                ?.getContext('webgl2');
              gl?.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
              return performance.now();
            };
            // The first frame draws the tree; the viewer casts its shadows from the next one.
            requestAnimationFrame(() =>
              setTimeout(() => {
                const drawn = drawnNow();
                requestAnimationFrame(() =>
                  setTimeout(() => resolve({ inScene, drawn, shadowed: drawnNow() }), 0),
                );
              }, 0),
            );
          },
          { once: true },
        );
      });
    });
    await page.goto(`${url}?debug=1`);
    times.push(await page.evaluate(() => window.__firstTree));
    await context.close();
  }
  return times;
}

/**
 * Applies `value` to the control of `id` in the page and resolves with the time from the input
 * event to the answer in the scene (`{ ms, preview }`).
 */
function step(page, id, value) {
  return page.evaluate(
    ([id, value]) =>
      new Promise((resolve, reject) => {
        const el =
          id === 'seed'
            ? document.querySelector('#seed-field')
            : document.querySelector(
                `input[type="range"][data-param-id="${id}"], select[data-param-id="${id}"], input[type="checkbox"][data-param-id="${id}"]`,
              );
        if (!el) return reject(new Error(`no control for ${id}`));
        const timer = setTimeout(() => reject(new Error(`no answer for ${id}=${value}`)), 20_000);
        addEventListener(
          'sylva:applied',
          (e) => {
            clearTimeout(timer);
            const d = e.detail;
            resolve({
              ms: d.at - t0,
              preview: d.preview,
              // Where the time went: the core's stages in the worker, input to the message on
              // the main thread, and the viewer setting the arrays up.
              parts: d.received
                ? [d.workerMs, d.received - t0, d.at - d.received, handled - t0]
                : null,
            });
          },
          { once: true },
        );
        const t0 = performance.now();
        if (el instanceof HTMLInputElement && el.type === 'checkbox') {
          el.click();
        } else {
          const proto = el instanceof HTMLSelectElement ? HTMLSelectElement : HTMLInputElement;
          Object.getOwnPropertyDescriptor(proto.prototype, 'value').set.call(el, String(value));
          el.dispatchEvent(
            new Event(el instanceof HTMLSelectElement ? 'change' : 'input', { bubbles: true }),
          );
        }
        // The app's input handling (its React render included) ends here or in a microtask.
        let handled = performance.now();
        queueMicrotask(() => (handled = performance.now()));
      }),
    [id, value],
  );
}

/** The release at the end of a drag: resolves with the time to the full-quality tree. */
function release(page) {
  return page.evaluate(
    () =>
      new Promise((resolve, reject) => {
        const timer = setTimeout(() => reject(new Error('no full tree after the drag')), 20_000);
        const t0 = performance.now();
        const onApplied = (e) => {
          if (e.detail.preview) return;
          removeEventListener('sylva:applied', onApplied);
          clearTimeout(timer);
          resolve(e.detail.at - t0);
        };
        addEventListener('sylva:applied', onApplied);
        dispatchEvent(new PointerEvent('pointerup', { bubbles: true }));
      }),
  );
}

/** The values of a 20-step drag of the control of `spec`, from its current `value`. */
function dragValues(spec, value) {
  if (spec.id === 'seed') return Array.from({ length: STEPS }, (_, i) => value + i + 1);
  if (spec.kind === 'bool') return Array.from({ length: STEPS }, (_, i) => (value + i + 1) % 2);
  if (spec.kind === 'enum') {
    const n = spec.max + 1;
    return Array.from({ length: STEPS }, (_, i) => (value + i + 1) % n);
  }
  // Ten moves one way and ten back, each about a pixel of a 250 px slider (at least one step):
  // a steady drag, one input event per move.
  const delta = Math.max(spec.step, (spec.max - spec.min) / 250);
  // Age drags toward younger trees: past its Mature Age a tree is the mature one.
  const dir = spec.id !== 'age' && value + (delta * STEPS) / 2 <= spec.max ? 1 : -1;
  return Array.from({ length: STEPS }, (_, i) => {
    const k = i < STEPS / 2 ? i + 1 : STEPS - i - 1;
    const v = value + dir * k * delta;
    const snapped = Math.round((v - spec.min) / spec.step) * spec.step + spec.min;
    return Math.min(spec.max, Math.max(spec.min, Number(snapped.toFixed(6))));
  });
}

/** 20-step drags of every control of `ids` (DRAG_PARAMS) on the default tree. */
async function drag(browser, url, ids = DRAG_PARAMS) {
  // Frames are drawn and timed only after each drag and each release (frame_ms).
  const page = await openDefaultTree(browser, url, { query: '?debug=1&v=1' });
  const probe = () => page.evaluate(() => window.__sylva.probeFrame());
  const per = {};
  const all = [];
  const frames = [];
  const settles = [];
  for (const id of ids) {
    const spec = await page.evaluate((id) => {
      const el =
        id === 'seed'
          ? document.querySelector('#seed-field')
          : document.querySelector(`[data-param-id="${id}"]:not([type=number])`);
      if (!el) return null;
      if (el instanceof HTMLSelectElement) {
        return { id, kind: 'enum', max: el.options.length - 1, value: Number(el.value) };
      }
      if (el.type === 'checkbox') return { id, kind: 'bool', value: el.checked ? 1 : 0 };
      return {
        id,
        kind: 'float',
        min: Number(el.min),
        max: Number(el.max),
        step: Number(el.step) || 1,
        value: Number(el.value),
      };
    }, id);
    if (!spec) throw new Error(`no control for ${id}`);
    const times = [];
    const parts = [];
    for (const v of dragValues(spec, spec.value)) {
      const r = await step(page, id, v);
      times.push(r.ms);
      if (r.parts) parts.push(r.parts);
    }
    frames.push(await probe());
    per[id] = round(median(times));
    if (process.env.SYLVA_BENCH_VERBOSE) {
      const m = (k) => median(parts.map((p) => p[k]))?.toFixed(1);
      console.error(
        `bench: ${id} ${times.map((t) => t.toFixed(1)).join(' ')}\n` +
          `  medians: input handling ${m(3)}, core ${m(0)}, input to message ${m(1)}, viewer ${m(2)} ms`,
      );
    }
    all.push(...times);
    // A viewer-only control regenerates nothing: there is nothing to settle.
    if (id !== 'show_preview') {
      settles.push(await release(page));
      frames.push(await probe());
    }
    await page.waitForTimeout(200);
  }
  await page.close();
  return {
    steps: all.length,
    median_ms: round(median(all)),
    p95_ms: round(percentile(all, 95)),
    per_param: per,
    settle_ms: round(median(settles)),
    frame_ms: round(median(frames)),
  };
}

/** The browser benchmark; null when there is no Chromium. */
export async function benchBrowser(runs = 7) {
  if (!existsSync(CHROMIUM)) return null;
  if (!existsSync(`${root}/web/dist/index.html`))
    throw new Error('web/dist is missing: npm run build first');
  const { url, stop } = await serve(await freePort());
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
  try {
    const first = await firstTree(browser, url, Math.max(3, Math.min(runs, 7)));
    const dragged = await drag(browser, url);
    // A 20-step Age drag: the growth replay scrubbed toward a younger tree.
    const aged = await drag(browser, url, ['age']);
    const paint = await benchPaint(browser, url);
    const cut = await benchCut(browser, url);
    const forestUnique = await benchForestUnique(browser, url, Math.min(runs, 3));
    return {
      first_tree_ms: round(median(first.map((t) => t.drawn))),
      first_tree_in_scene_ms: round(median(first.map((t) => t.inScene))),
      first_shadowed_ms: round(median(first.map((t) => t.shadowed))),
      drag: dragged,
      age: { median_ms: aged.median_ms, p95_ms: aged.p95_ms, settle_ms: aged.settle_ms },
      paint,
      cut,
      forest_unique: forestUnique,
    };
  } finally {
    await browser.close();
    await stop();
  }
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  console.log(JSON.stringify(await benchBrowser(), null, 2));
}
