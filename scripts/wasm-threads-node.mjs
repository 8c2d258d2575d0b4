// The threaded wasm module (packages/sylva-trees/src/wasm-threads, scripts/wasm-threads.sh) in
// Node, as the browser runs it: a generating worker instantiates the module (its glue creates the
// shared memory) and starts one helper worker, which instantiates the same module on that memory
// and enters `helperLoop()`. For the parity test (scripts/wasm-parity.mjs), the cold bench
// (scripts/bench-cold.mjs) and the test of a helper's panic (wasm-threads-node.test.mjs).
// This file is also both workers' entry point.
import { readFileSync } from 'node:fs';
import { Worker, isMainThread, parentPort, workerData } from 'node:worker_threads';

const DIR = new URL('../packages/sylva-trees/src/', import.meta.url);

/** The glue's URL and the compiled module of `folder` (`wasm-threads`, `wasm-threads-debug`). */
export function threadedModule(folder = 'wasm-threads') {
  const dir = new URL(`${folder}/`, DIR);
  return {
    glue: new URL('sylva_wasm.js', dir).href,
    module: new WebAssembly.Module(readFileSync(new URL('sylva_wasm_bg.wasm', dir))),
  };
}

/** Resolves when `worker` posts its first message (with it); rejects on its error or exit. */
function firstMessage(worker) {
  return new Promise((resolve, reject) => {
    worker.once('message', resolve);
    worker.once('error', reject);
    worker.once('exit', (code) => reject(new Error(`worker exited (${code}) before answering`)));
  });
}

/**
 * Runs `task` in a fresh generating worker with `helpers` helper workers started first (each has
 * entered its loop before the task starts): `{ kind: 'generate', jsons }` answers
 * `{ metas, threads, helperJobs }`; `{ kind: 'panic-on-helper' }` answers `{ error, panic }` (the
 * debug module's `debug_panic_on_helper`). Every worker is ended before it resolves.
 */
export async function runThreaded({ glue, module }, task, helpers = 1) {
  const worker = new Worker(new URL(import.meta.url), {
    workerData: { role: 'generating', glue, module, task, helpers },
  });
  try {
    const answer = await firstMessage(worker);
    if (answer.failed) throw new Error(answer.failed);
    return answer;
  } finally {
    await worker.terminate();
  }
}

if (!isMainThread && workerData?.role === 'helper') {
  const w = await import(workerData.glue);
  w.initSync({ module: workerData.module, memory: workerData.memory });
  parentPort.postMessage('started');
  w.helperLoop();
}

if (!isMainThread && workerData?.role === 'generating') {
  const { glue, module, task, helpers } = workerData;
  const w = await import(glue);
  const { memory } = w.initSync({ module });
  const started = [];
  for (let i = 0; i < helpers; i++) {
    const helper = new Worker(new URL(import.meta.url), {
      workerData: { role: 'helper', glue, module, memory },
    });
    started.push(helper);
    await firstMessage(helper);
  }
  // `started` is posted just before the loop is entered: wait until it counts.
  const t0 = Date.now();
  while (w.threads() < 1 + helpers && Date.now() - t0 < 10_000) {
    await new Promise((r) => setTimeout(r, 1));
  }
  try {
    if (w.threads() < 1 + helpers) throw new Error(`only ${w.threads()} threads after 10 s`);
    if (task.kind === 'generate') {
      const metas = task.jsons.map((json) => {
        const tree = w.generate(json);
        const meta = JSON.parse(tree.meta_json());
        tree.free();
        return meta;
      });
      parentPort.postMessage({ metas, threads: w.threads(), helperJobs: w.helperJobs() });
    } else if (task.kind === 'panic-on-helper') {
      let error = null;
      try {
        w.debug_panic_on_helper();
      } catch (thrown) {
        error = String(thrown);
      }
      parentPort.postMessage({ error, panic: w.take_panic() ?? null });
    }
  } catch (thrown) {
    parentPort.postMessage({ failed: String(thrown?.stack ?? thrown) });
  }
  await Promise.all(started.map((h) => h.terminate()));
}
