// The cold path and the batch of `npm run bench`:
// - `cold`: one whole generation (skeleton, bark, foliage, hash) from the parameters alone, with
//   nothing kept from an earlier tree (no cached leaf, no memory the allocator already holds):
//   natively a fresh `sylva generate` process per run; in wasm a fresh instance of the module in
//   a worker thread per run (its memory is freed with the worker). The compiled module is shared,
//   so V8's compilation is not part of the figure. Reported in µs per bark vertex, with the
//   milliseconds per stage.
// - `wasm_threads` in each `cold` record: the same in the threaded module (scripts/wasm-threads.sh)
//   with one helper worker started first, as a cross-origin isolated page runs it: a fresh
//   instance per run, and `repeated`, the same tree generated again in that instance.
// - `batch`: `sylva batch` of 100 default trees with seeds 1 to 100 on every core (generation and
//   hash, no files), in trees per second.
// This file is also the worker's entry point.
import { execFileSync } from 'node:child_process';
import { Worker, isMainThread, parentPort, workerData } from 'node:worker_threads';
import { median } from './bench-stats.mjs';
import { runThreaded, threadedModule } from './wasm-threads-node.mjs';

if (!isMainThread && workerData?.coldTree) {
  const w = await import(workerData.glue);
  w.initSync({ module: workerData.module });
  const tree = w.generate(workerData.json);
  const meta = JSON.parse(tree.meta_json());
  tree.free();
  parentPort.postMessage(meta);
}

/** The meta of one generation of `json` in a fresh instance of `module` (glue module `glue`). */
function coldWasmOnce(module, glue, json) {
  return new Promise((resolve, reject) => {
    const worker = new Worker(new URL(import.meta.url), {
      workerData: { coldTree: true, module, glue, json },
    });
    worker.once('message', (meta) => {
      resolve(meta);
      void worker.terminate();
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

/** The `cold` record of each case (`{ name, values, args }`): native and wasm, `runs` each. */
export async function benchCold(sylva, module, glue, cases, runs) {
  const threaded = threadedModule();
  const out = [];
  for (const c of cases) {
    const native = [];
    for (let i = 0; i < runs; i++) {
      const g = JSON.parse(execFileSync(sylva, ['generate', ...c.args], { encoding: 'utf8' }));
      native.push({ total_ms: g.total_ms, stage_ms: g.ms, vertices: g.vertices, hash: g.hash });
    }
    const wasm = [];
    for (let i = 0; i < runs; i++)
      wasm.push(await coldWasmOnce(module, glue, JSON.stringify(c.values)));
    const fresh = [];
    const repeated = [];
    for (let i = 0; i < runs; i++) {
      const json = JSON.stringify(c.values);
      const { metas } = await runThreaded(threaded, { kind: 'generate', jsons: [json, json] });
      fresh.push(metas[0]);
      repeated.push(metas[1]);
    }
    const vertices = wasm[0].vertices;
    out.push({
      preset: c.name,
      vertices,
      native: summary(native, vertices),
      wasm: summary(wasm, vertices),
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
