/** Generator Web Worker: initialises the wasm once and answers requests with transferred buffers. */
import init, * as wasm from '../wasm/sylva_wasm.js';
import type { DebugRequest, DebugResponse } from './debug';
import { DEBUG_WORKER_NAME } from './debugName';
import { debugHooks } from './debugHooks';
import { createHandler, readyMessage, type HandlerPost } from './handler';
import type { WorkerRequest, WorkerResponse } from './protocol';
import { wasmUrl } from '../runtime/urls';
import type { WasmApi } from '../core/types';
import { loadThreaded } from './threads';

/** The parts of the dedicated-worker global scope this file uses. */
interface WorkerScope {
  /** The name the worker was started with: [`DEBUG_WORKER_NAME`] accepts the debug messages. */
  readonly name: string;
  postMessage(message: WorkerResponse | DebugResponse, transfer: Transferable[]): void;
  onmessage: ((event: MessageEvent<WorkerRequest | DebugRequest>) => void) | null;
}

const scope = self as unknown as WorkerScope;
const post: HandlerPost = (message, transfer) => scope.postMessage(message, transfer);
// The test hooks: only in the app's debug build, and only for a worker started as a debug one.
const debug = scope.name === DEBUG_WORKER_NAME ? (debugHooks ?? undefined) : undefined;

/**
 * The core: the threaded one with its helper where the page is cross-origin isolated
 * (`threads.ts`), else (or if it fails to load) the single-threaded one.
 */
async function loadCore(): Promise<{ api: WasmApi; threads: Promise<number> | number }> {
  try {
    const threaded = await loadThreaded();
    if (threaded) return threaded;
  } catch (thrown) {
    console.warn('sylva: the threaded core did not load; generating on one thread', thrown);
  }
  await init({ module_or_path: wasmUrl() });
  return { api: wasm, threads: 1 };
}

const handlerPromise = loadCore()
  .then(async ({ api, threads }) => {
    // The default tree is generated before anyone asks (while the page loads three.js and
    // React): the module's code is compiled and warm, and a first request for the default tree
    // (a new visitor's) only copies the arrays out. The helper starts meanwhile.
    const handle = createHandler(api, post, { prime: {}, debug });
    post({ ...readyMessage(api), threads: await threads }, []);
    return handle;
  })
  .catch((thrown: unknown) => {
    const message = thrown instanceof Error ? thrown.message : String(thrown);
    post({ type: 'fatal', message: `wasm init failed: ${message}` }, []);
    return null;
  });

scope.onmessage = (event) => {
  void handlerPromise
    .then((handle) => handle?.(event.data))
    .catch((thrown: unknown) => {
      // Anything the handler did not turn into a response (e.g. a failed postMessage) would
      // leave the request unanswered: report it as fatal so the scheduler recreates the worker.
      const message = thrown instanceof Error ? thrown.message : String(thrown);
      post({ type: 'fatal', message: `the generator worker failed: ${message}` }, []);
    });
};
