// The threaded wasm module's helper thread (sylva-core `par::helpers`) in Node: work is handed to
// the helper and gives the single-threaded module's bytes, and a helper's panic wakes the thread
// waiting for it (which reports the helper's message) instead of leaving it blocked forever.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { runThreaded, threadedModule } from './wasm-threads-node.mjs';

const single = await import(
  new URL('../packages/sylva-trees/src/wasm/sylva_wasm.js', import.meta.url)
);
single.initSync({
  module: readFileSync(
    new URL('../packages/sylva-trees/src/wasm/sylva_wasm_bg.wasm', import.meta.url),
  ),
});
const hashOf = (json) => {
  const tree = single.generate(json);
  const { hash } = JSON.parse(tree.meta_json());
  tree.free();
  return hash;
};

test('a helper shares the work and the bytes stay the single-threaded ones', async () => {
  const presets = JSON.parse(single.presets_json());
  const jsons = ['default', 'black_tupelo'].map((n) =>
    JSON.stringify(presets.find((p) => p.name === n).values),
  );
  const r = await runThreaded(threadedModule(), { kind: 'generate', jsons });
  assert.equal(r.threads, 2);
  // Each tree hands its leaf placement (and the bark occlusion's ranges) to the helper.
  assert.ok(r.helperJobs >= 2, `the helper ran ${r.helperJobs} jobs`);
  assert.deepEqual(
    r.metas.map((m) => m.hash),
    jsons.map(hashOf),
  );
});

test("a helper's panic is reported by the waiting thread, with the helper's message", async () => {
  const r = await runThreaded(threadedModule('wasm-threads-debug'), { kind: 'panic-on-helper' });
  assert.match(r.error ?? '', /RuntimeError|unreachable/);
  assert.match(r.panic ?? '', /debug_panic_on_helper: deliberate panic/);
});
