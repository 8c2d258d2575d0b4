// The cold path's fresh-memory figures (bench-cold.mjs): the memory a fresh instance reports, the
// page cost measured, and the arithmetic that turns them into the bench's "pages ms".
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { PAGE_BYTES, coldWasmOnce, freshMemory, freshPageMicros, warmed } from './bench-cold.mjs';

const glue = new URL('../packages/sylva-trees/src/wasm/sylva_wasm.js', import.meta.url);
const module = new WebAssembly.Module(
  readFileSync(new URL('../packages/sylva-trees/src/wasm/sylva_wasm_bg.wasm', import.meta.url)),
);

test('a fresh instance reports the memory it grew to, which holds at least the bark', async () => {
  const single = await import(glue.href);
  single.initSync({ module });
  const json = JSON.stringify({});
  const here = single.generate(json);
  const { hash } = JSON.parse(here.meta_json());
  here.free();
  const meta = await coldWasmOnce(module, glue.href, json);
  assert.equal(meta.hash, hash);
  // Positions, normals, uvs and wind records: 16 floats a bark vertex, all in the instance.
  assert.ok(meta.vertices > 10000, `${meta.vertices} vertices`);
  assert.ok(meta.memory_bytes >= meta.vertices * 64, `${meta.memory_bytes} bytes`);
  assert.equal(meta.memory_bytes % 65536, 0, 'whole wasm pages');
});

test('the fresh-page cost is measured, finite and positive', async () => {
  const us = await freshPageMicros(1, 16);
  assert.ok(Number.isFinite(us) && us > 0, `${us} µs a page`);
});

test('fresh memory: the median memory, its pages at the given cost, per bark vertex', () => {
  const metas = [3000, 1000, 2000].map((pages) => ({ memory_bytes: pages * PAGE_BYTES }));
  const m = freshMemory(metas, 1000, 1.5);
  assert.equal(m.memory_mb, (2000 * PAGE_BYTES) / 1e6);
  assert.ok(Math.abs(m.fresh_pages_ms - 3) < 1e-12);
  assert.ok(Math.abs(m.fresh_pages_us_per_vertex - 3) < 1e-12);
});

test('every cold figure follows one dropped generation, each awaited before the next', async () => {
  // The threaded module's first fresh generations once counted V8's tiering up: the default
  // tree's first cold figure was 45 ms, the later ones 15 to 19.
  const calls = [];
  let running = 0;
  const got = await warmed(3, async () => {
    assert.equal(running, 0, 'one at a time');
    running += 1;
    calls.push(calls.length);
    await new Promise((r) => setTimeout(r, 1));
    running -= 1;
    return calls.length;
  });
  assert.deepEqual(calls, [0, 1, 2, 3]);
  assert.deepEqual(got, [2, 3, 4], 'the first result dropped');
});
