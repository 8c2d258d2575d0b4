/**
 * `{ worker: false }`: the generator's request handler on the calling thread, behind the same
 * [`WorkerHandle`] a Web Worker gets (the scheduler and the export client cannot tell them
 * apart). Answers are delivered in a later task, as a worker's would be. In Node (tests, server
 * rendering) the wasm file is read from disk; in a browser it is fetched from next to the module.
 */
import type { WasmApi } from '../core/types';
import type { WorkerHandle } from '../worker/client';
import { createHandler, readyMessage } from '../worker/handler';
import type { WorkerRequest, WorkerResponse } from '../worker/protocol';
import { wasmUrl } from './urls';

let loading: Promise<WasmApi> | null = null;

function isNode(): boolean {
  const p = (globalThis as { process?: { versions?: { node?: string } } }).process;
  return typeof p?.versions?.node === 'string' && typeof window === 'undefined';
}

/** The wasm module on this thread, initialised once (shared by every in-process tree). */
export function loadWasmHere(): Promise<WasmApi> {
  loading ??= (async () => {
    const glue = await import('../wasm/sylva_wasm.js');
    const url = wasmUrl();
    if (isNode()) {
      // Named through a variable: bundlers leave Node's module to Node.
      const fsModule = 'node:fs/promises';
      const fs = (await import(/* @vite-ignore */ fsModule)) as {
        readFile(path: URL): Promise<Uint8Array>;
      };
      await glue.default({ module_or_path: await fs.readFile(url) });
    } else {
      await glue.default({ module_or_path: url });
    }
    return glue;
  })();
  loading.catch(() => {
    loading = null;
  });
  return loading;
}

/** A worker factory that runs the handler here (same messages, same order, a task later). */
export function inProcessFactory(
  onMessage: (response: WorkerResponse) => void,
  onError: (message: string) => void,
): WorkerHandle<WorkerRequest> {
  let alive = true;
  const deliver = (message: WorkerResponse): void => {
    setTimeout(() => {
      if (alive) onMessage(message);
    }, 0);
  };
  const handler = loadWasmHere().then(
    (wasm) => {
      const handle = createHandler(wasm, deliver);
      deliver(readyMessage(wasm));
      return handle;
    },
    (thrown: unknown) => {
      const message = thrown instanceof Error ? thrown.message : String(thrown);
      setTimeout(() => {
        if (alive) onError(`wasm init failed: ${message}`);
      }, 0);
      return null;
    },
  );
  return {
    post: (request) => {
      void handler.then((handle) => {
        if (alive) handle?.(request);
      });
    },
    terminate: () => {
      alive = false;
    },
  };
}
