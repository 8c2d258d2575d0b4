// The cold path and the batch of `npm run bench`:
// - `cold`: one whole generation (skeleton, bark, foliage, hash) from the parameters alone, with
//   nothing kept from an earlier tree (no cached leaf, no memory the allocator already holds):
//   natively a fresh `sylva generate` process per run; in wasm a fresh instance of the module in
//   a worker thread per run (its memory is freed with the worker). The compiled module is shared,
//   so V8's compilation is not part of the figure, nor is its tiering up: the threaded module
//   generates six default trees first, and one generation of each tree in each module is run and
//   dropped (`warmed`). Reported in µs per bark vertex, with the milliseconds per stage.
// - `wasm_threads` in each `cold` record: the same in the threaded module (scripts/wasm-threads.sh)
//   with one helper worker started first, as a cross-origin isolated page runs it: a fresh
//   instance per run, and `repeated`, the same tree generated again in that instance.
// - `memory_mb` and `fresh_pages_ms` in each `cold` record's `wasm`: the memory the fresh instance
//   grew to by the end of the generation, and what touching that many fresh pages costs at
//   `freshPageMicros` (the machine's cost of one 4 KB page of a new wasm memory, written for the
//   first time): the part of a fresh generation that no faster code removes.
// - `batch`: `sylva batch` of 100 default trees with seeds 1 to 100 on every core (generation and
//   hash, no files), in trees per second.
// This file is also the worker's entry point.
import { execFileSync } from 'node:child_process';
import { Worker, isMainThread, parentPort, workerData } from 'node:worker_threads';
import { median } from './bench-stats.mjs';
import { runThreaded, threadedModule } from './wasm-threads-node.mjs';

if (!isMainThread && workerData?.coldTree) {
  const w = await import(workerData.glue);
  const exports = w.initSync({ module: workerData.module });
  const tree = w.generate(workerData.json);
  const meta = JSON.parse(tree.meta_json());
  tree.free();
  parentPort.postMessage({ ...meta, memory_bytes: exports.memory.buffer.byteLength });
}

/** Bytes in one page of the system's memory, the unit a fresh memory is faulted in by. */
export const PAGE_BYTES = 4096;

if (!isMainThread && workerData?.freshPages) {
  // A new wasm memory grown by `mb`, one byte written per page: the first pass faults every page
  // in, the second (the same pages, now present) is the loop's own cost, taken off.
  const mem = new WebAssembly.Memory({ initial: 1, maximum: 65536 });
  mem.grow((workerData.mb << 20) >> 16);
  const bytes = new Uint8Array(mem.buffer);
  const pass = (value) => {
    const t0 = performance.now();
    for (let i = 0; i < bytes.length; i += PAGE_BYTES) bytes[i] = value;
    return performance.now() - t0;
  };
  const first = pass(1);
  const again = pass(2);
  parentPort.postMessage({ us_per_page: (1000 * (first - again)) / (bytes.length / PAGE_BYTES) });
}

/** What one fresh page of wasm memory costs (µs): the median of `runs` fresh workers, each
 *  touching `mb` MB of a new memory for the first time. */
export async function freshPageMicros(runs = 5, mb = 64) {
  const each = [];
  for (let i = 0; i < runs; i++) {
    const worker = new Worker(new URL(import.meta.url), { workerData: { freshPages: true, mb } });
    each.push(
      await new Promise((resolve, reject) => {
        worker.once('message', (m) => resolve(m.us_per_page));
        worker.once('error', reject);
      }),
    );
    await worker.terminate();
  }
  return median(each);
}

/** The meta of one generation of `json` in a fresh instance of `module` (glue module `glue`),
 *  with `memory_bytes`, the instance's memory at the end. */
export function coldWasmOnce(module, glue, json) {
  return new Promise((resolve, reject) => {
    const worker = new Worker(new URL(import.meta.url), {
      workerData: { coldTree: true, module, glue, json },
    });
    // Resolved once the worker has ended, so that freeing its memory is not part of the next
    // run's figure.
    worker.once('message', (meta) => {
      worker.terminate().then(() => resolve(meta), reject);
    });
    worker.once('error', reject);
  });
}

/** Medians of `metas` (each `{ total_ms, stage_ms }`), per bark vertex too. */
function summary(metas, vertices) {
  const total = median(metas.map((m) => m.total_ms));
  const stages = Object.keys(metas[0].stage_ms);
  return {
    us_per_vertex: (1000 * total) / vertices,
    median_ms: total,
    stage_median_ms: Object.fromEntries(
      stages.map((k) => [k, median(metas.map((m) => m.stage_ms[k]))]),
    ),
  };
}

/** `runs` results of `once()` (each awaited before the next), after one more whose result is
 *  dropped: V8 compiles a module's functions lazily and tiers the hot ones up while they run (in
 *  every instance of the module), so the first generations of a tree after a module is compiled
 *  measure V8's compiler as much as the cold path (the default tree's first fresh threaded
 *  generation took 45 ms, its later ones 15 to 19). */
export async function warmed(runs, once) {
  await once();
  const out = [];
  for (let i = 0; i < runs; i++) out.push(await once());
  return out;
}

/** The cold generations' fresh memory: the median memory the instance grew to (MB), and what
 *  faulting in that many pages costs at `pageMicros` µs a page (ms, and µs per bark vertex). */
export function freshMemory(metas, vertices, pageMicros) {
  const bytes = median(metas.map((m) => m.memory_bytes));
  const ms = (bytes / PAGE_BYTES) * pageMicros * 1e-3;
  return {
    memory_mb: bytes / 1e6,
    fresh_pages_ms: ms,
    fresh_pages_us_per_vertex: (1000 * ms) / vertices,
  };
}

/** The `cold` record of each case (`{ name, values, args }`): native and wasm, `runs` each.
 *  `pageMicros`: the machine's cost of a fresh page ([`freshPageMicros`]). */
export async function benchCold(sylva, module, glue, cases, runs, pageMicros) {
  const threaded = threadedModule();
  // The threaded module is compiled here, and V8 tiers its functions up in the background while
  // they run: in a fresh process the default tree's first fresh generation took 71 ms, the next
  // five 17-20, then 15 (as every later compile of the same bytes does from its first run). A few
  // default trees first, then one dropped generation per tree (`warmed`).
  for (let i = 0; i < 6; i++) await runThreaded(threaded, { kind: 'generate', jsons: ['{}'] });
  const out = [];
  for (const c of cases) {
    const native = [];
    for (let i = 0; i < runs; i++) {
      const g = JSON.parse(execFileSync(sylva, ['generate', ...c.args], { encoding: 'utf8' }));
      native.push({ total_ms: g.total_ms, stage_ms: g.ms, vertices: g.vertices, hash: g.hash });
    }
    const json = JSON.stringify(c.values);
    const wasm = await warmed(runs, () => coldWasmOnce(module, glue, json));
    const pairs = await warmed(runs, async () => {
      const { metas } = await runThreaded(threaded, { kind: 'generate', jsons: [json, json] });
      return metas;
    });
    const fresh = pairs.map((m) => m[0]);
    const repeated = pairs.map((m) => m[1]);
    const vertices = wasm[0].vertices;
    out.push({
      preset: c.name,
      vertices,
      native: summary(native, vertices),
      wasm: { ...summary(wasm, vertices), ...freshMemory(wasm, vertices, pageMicros) },
      wasm_threads: { ...summary(fresh, vertices), repeated: summary(repeated, vertices) },
      same_hash: [...native, ...fresh, ...repeated].every((n) => n.hash === wasm[0].hash),
    });
  }
  return out;
}

/** `sylva batch` of `trees` default trees (seeds 1 to `trees`) on every core. */
export function benchBatch(sylva, trees) {
  const m = JSON.parse(
    execFileSync(sylva, ['batch', '--seeds', `1-${trees}`], {
      encoding: 'utf8',
      maxBuffer: 1 << 26,
    }),
  );
  return {
    trees: m.count,
    threads: m.threads,
    total_ms: m.total_ms,
    trees_per_second: m.trees_per_second,
    tree_median_ms: median(m.trees.map((t) => t.ms)),
  };
}
