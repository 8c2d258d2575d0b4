/**
 * The core built with threads (`wasm-threads/`, scripts/wasm-threads.sh), where the page allows
 * it: in a cross-origin isolated page (served with `Cross-Origin-Opener-Policy: same-origin` and
 * `Cross-Origin-Embedder-Policy: require-corp`), a generation worker instantiates that module,
 * whose glue creates a shared memory, and starts one helper worker (`helper.ts`) on the same
 * module and memory. The helper runs the jobs the core hands out (the leaf placement beside the
 * bark, the bark occlusion's ranges: sylva-core `par::helpers`); the bytes are the same as the
 * single-threaded module's. Anywhere else (no isolation, no `SharedArrayBuffer`, a failed load)
 * the worker runs the single-threaded module, as before.
 *
 * The generation worker blocks (`Atomics.wait`) while it waits for its helper, which a worker may
 * do. Until the helper has started, the core runs everything on the generation worker.
 */
import type { WasmApi } from '../core/types';
import { threadsWasmUrl } from '../runtime/urls';

/** The threaded glue's extra exports. */
interface ThreadedGlue {
  initSync(options: { module: WebAssembly.Module; memory?: WebAssembly.Memory }): {
    memory: WebAssembly.Memory;
  };
  threads(): number;
}

/** How long the ready message waits for the helper to say it started (ms). */
const HELPER_START_MS = 5000;

/** The parts of a worker's global scope this file reads. */
interface IsolationScope {
  readonly crossOriginIsolated?: boolean;
}

/** Whether this worker may share memory with another (cross-origin isolated, with SABs). */
export function canShareMemory(scope: IsolationScope = globalThis): boolean {
  return scope.crossOriginIsolated === true && typeof SharedArrayBuffer === 'function';
}

/** The threaded core, ready, with the helper worker it started. */
export interface Threaded {
  api: WasmApi;
  helper: Worker;
  /** Threads once the helper answered: 2 when it started, 1 when it failed to. */
  threads: Promise<number>;
}

/**
 * The helper's messages: up (about to enter its loop), or why it could not start; then, only
 * if a job panicked, that its loop ended by a trap.
 */
export type HelperMessage =
  { type: 'started' } | { type: 'failed'; message: string } | { type: 'trapped'; message: string };

/**
 * Loads the threaded core and starts its helper; `null` where memory cannot be shared. Throws
 * when the module fails to load (the caller falls back to the single-threaded one).
 */
export async function loadThreaded(): Promise<Threaded | null> {
  if (!canShareMemory()) return null;
  const glue = await import('../wasm-threads/sylva_wasm.js');
  const module = await WebAssembly.compileStreaming(fetch(threadsWasmUrl()));
  const { memory } = (glue as unknown as ThreadedGlue).initSync({ module });
  // Vite reads `type` statically: the name comes after it.
  const helper = new Worker(new URL('./helper.ts', import.meta.url), {
    type: 'module',
    name: 'sylva-helper',
  });
  const threads = new Promise<number>((resolve) => {
    helper.onmessage = (event: MessageEvent<HelperMessage>) => {
      if (event.data.type === 'failed') console.warn('sylva: the helper worker failed', event.data);
      resolve(event.data.type === 'started' ? 2 : 1);
    };
    helper.onerror = (event) => {
      // A helper that fails to load: the core runs on this thread alone.
      event.preventDefault();
      resolve(1);
    };
    // Never wait on a helper that neither starts nor fails (the core works without it).
    setTimeout(() => resolve(1), HELPER_START_MS);
  });
  try {
    helper.postMessage({ module, memory });
  } catch (thrown) {
    helper.terminate();
    throw thrown;
  }
  return { api: glue as unknown as WasmApi, helper, threads };
}
