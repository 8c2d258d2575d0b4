// Hand-edit part of the browser benchmark (`npm run bench`), on the built app and the default
// tree, with the app's debug events (`?debug=1`). As in the slider drags (bench-browser.mjs), the
// input events are dispatched in the page (pointer events on the viewer's canvas, as a mouse
// makes them) and timed from the dispatch to the answer in the scene (`sylva:applied`: buffers
// received, attributes set, ready for the next frame):
//   - paint: a 40-point stroke through the side of the crown, from inside it out into the sky,
//     seen from the side: the press (its first brush point; answered before the hand moves), then
//     per pointer move (each adds a brush point) the time to the answer; settle_ms = release to
//     the full tree.
//   - cut: 10 clicks with the Cut tool on main branches (bark 4 to 9 m up, near 1 m from the
//     trunk's axis, away from earlier cuts), 0.3 s apart; per click, the release (which cuts; the
//     press a tenth of a second before it found the branch) to the answer, and settle_ms =
//     release to the full tree.
// Frames are not drawn between the timed steps (software WebGL takes seconds per frame); the
// answers are set up, ready for the next frame.
// Exports `benchPaint(browser, url)` and `benchCut(browser, url)`.
import { openDefaultTree } from './bench-page.mjs';
import { median, percentile, round } from './bench-stats.mjs';

const STROKE_POINTS = 40;
const CUTS = 10;

/** The default tree's page (`openDefaultTree`) with a log of the trees applied. */
function openApp(browser, url) {
  return openDefaultTree(browser, url, {
    init: () => {
      window.__benchApplied = [];
      addEventListener('sylva:applied', (e) => window.__benchApplied.push(e.detail));
      /**
       * Dispatches pointer event `type` at client `(x, y)` on the viewer's canvas and resolves
       * with `{ first, full, parts }`: ms from the dispatch to the next tree applied and to the
       * next full one (`wait`: 'first' or 'full'), or null at once (`wait` 'none', or a move
       * that adds no brush point: it asks for nothing).
       */
      window.__benchPointer = (type, x, y, wait) =>
        new Promise((resolve, reject) => {
          const canvas = document.querySelector('canvas[data-testid="viewer-canvas"]');
          const n = window.__benchApplied.length;
          const timer = setTimeout(() => reject(new Error(`no answer to ${type}`)), 30_000);
          const t0 = performance.now();
          const poll = () => {
            const after = window.__benchApplied.slice(n);
            const full = after.find((a) => !a.preview);
            if (after.length && (full || wait === 'first')) {
              clearTimeout(timer);
              const a = after[0];
              resolve({
                first: a.at - t0,
                full: full ? full.at - t0 : null,
                parts: [
                  a.requestedAt - t0,
                  a.workerMs,
                  a.received - a.requestedAt,
                  a.at - a.received,
                ],
              });
            } else setTimeout(poll, 1);
          };
          const points = window.__sylva.edits().strokePoints;
          for (const t of type.split('+')) {
            canvas.dispatchEvent(
              new PointerEvent(t, {
                clientX: x,
                clientY: y,
                pointerId: 1,
                pointerType: 'mouse',
                isPrimary: true,
                button: 0,
                buttons: t === 'pointerup' ? 0 : 1,
                bubbles: true,
                cancelable: true,
              }),
            );
          }
          if (wait === 'none') {
            clearTimeout(timer);
            resolve(null);
          } else if (wait === 'first' && window.__sylva.edits().strokePoints === points) {
            // A move that adds no brush point asks for nothing.
            clearTimeout(timer);
            resolve(null);
          } else poll();
        });
    },
  });
}

/** Dispatches pointer events `type` (`+`-joined) at `(x, y)`: see `__benchPointer`. */
const pointer = (page, type, x, y, wait) =>
  page.evaluate(
    ([type, x, y, wait]) => window.__benchPointer(type, x, y, wait),
    [type, x, y, wait],
  );

/** The 40-point paint stroke (see the header). */
export async function benchPaint(browser, url) {
  const page = await openApp(browser, url);
  try {
    const bounds = (await page.evaluate(() => window.__sylva.edits())).bounds;
    const height = bounds.max[1];
    const edge = bounds.max[0];
    const midY = height * 0.6;
    await page.evaluate(
      ([y, d]) => window.__sylva.view([0, y, d], [0, y, 0]),
      [midY, height * 2.2],
    );
    const project = (p) => page.evaluate((q) => window.__sylva.project(q), p);
    // From 4 m inside the crown's edge to 4 m beyond it, rising 2 m: brush points about 0.2 m
    // apart, more than the quarter brush radius (0.15 m) a point needs.
    const [sx, sy] = await project([edge - 4, midY - 1, 0]);
    const [ex, ey] = await project([edge + 4, midY + 1, 0]);
    await page.keyboard.press('p');
    // The press starts the stroke (its first brush point grows); the hand moves after its answer.
    const press = await pointer(page, 'pointerdown', sx, sy, 'first');
    const times = [];
    const parts = [];
    let skipped = 0;
    for (let k = 1; k <= STROKE_POINTS; k++) {
      const t = k / STROKE_POINTS;
      // A gap between moves, as a hand makes (and the tools take at most one move a frame).
      await page.waitForTimeout(20);
      const r = await pointer(page, 'pointermove', sx + (ex - sx) * t, sy + (ey - sy) * t, 'first');
      if (!r) {
        skipped++;
        continue;
      }
      times.push(r.first);
      parts.push(r.parts);
    }
    const { full } = await pointer(page, 'pointerup', ex, ey, 'full');
    if (process.env.SYLVA_BENCH_VERBOSE) {
      const m = (k) => median(parts.map((p) => p[k]))?.toFixed(1);
      console.error(
        `bench: paint press ${press?.first.toFixed(1)} (${press?.parts.map((x) => x.toFixed(1)).join(' / ')}), moves ${times.map((t) => t.toFixed(1)).join(' ')} (skipped ${skipped})\n` +
          `  medians: input to request ${m(0)}, request to answer ${m(2)} (core ${m(1)}), viewer ${m(3)} ms`,
      );
    }
    return {
      steps: times.length,
      median_ms: round(median(times)),
      p95_ms: round(percentile(times, 95)),
      settle_ms: round(full),
    };
  } finally {
    await page.close();
  }
}

/**
 * A main branch's bark under the cursor: of the bark points 4 to 9 m up, the one nearest to
 * 1 m from the trunk's axis, at least 1 m from every earlier cut. Null when none is left.
 */
function findBranch(page, cuts) {
  return page.evaluate((done) => {
    const box = document
      .querySelector('canvas[data-testid="viewer-canvas"]')
      .getBoundingClientRect();
    let best = null;
    for (let y = box.y + 20; y < box.y + box.height - 20; y += 10) {
      for (let x = box.x + 20; x < box.x + box.width - 20; x += 10) {
        const at = window.__sylva.pickBark(x, y);
        if (!at || at[1] < 4 || at[1] > 9) continue;
        if (done.some((c) => Math.hypot(c[0] - at[0], c[1] - at[1], c[2] - at[2]) < 1)) continue;
        const r = Math.abs(Math.hypot(at[0], at[2]) - 1);
        if (!best || r < best.r) best = { x, y, at, r };
      }
    }
    return best;
  }, cuts);
}

/** Ten click-cuts on main branches (see the header). */
export async function benchCut(browser, url) {
  const page = await openApp(browser, url);
  try {
    await page.keyboard.press('c');
    const firsts = [];
    const fulls = [];
    const parts = [];
    const cuts = [];
    for (let i = 0; i < CUTS; i++) {
      const branch = await findBranch(page, cuts);
      if (!branch) break;
      cuts.push(branch.at);
      // A click: the press (it finds the branch), a tenth of a second, the release (it cuts).
      await pointer(page, 'pointerdown', branch.x, branch.y, 'none');
      await page.waitForTimeout(100);
      const r = await pointer(page, 'pointerup', branch.x, branch.y, 'full');
      // A user looks at the result before the next cut.
      await page.waitForTimeout(300);
      firsts.push(r.first);
      fulls.push(r.full);
      parts.push(r.parts);
    }
    if (process.env.SYLVA_BENCH_VERBOSE) {
      const m = (k) => median(parts.map((p) => p[k]))?.toFixed(1);
      const f = (k) => parts[0]?.[k]?.toFixed(1);
      console.error(
        `bench: cut ${firsts.map((t) => t.toFixed(1)).join(' ')}\n` +
          `  medians: input to request ${m(0)}, request to answer ${m(2)} (core ${m(1)}), viewer ${m(3)} ms\n` +
          `  first cut: input to request ${f(0)}, request to answer ${f(2)} (core ${f(1)}), viewer ${f(3)} ms`,
      );
    }
    return {
      cuts: firsts.length,
      median_ms: round(median(firsts)),
      p95_ms: round(percentile(firsts, 95)),
      settle_ms: round(median(fulls)),
    };
  } finally {
    await page.close();
  }
}
