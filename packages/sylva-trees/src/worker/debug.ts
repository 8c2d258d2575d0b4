/**
 * Test hooks of the generator worker, kept out of the production protocol and out of the shipped
 * worker: only the app's debug build (`npm run build:debug -w web`, web/dist-debug, which the
 * e2e tests of the crash recovery and the time limit open) links them in, by resolving the
 * worker's `./debugHooks` to this module and its wasm to the `debug-hooks` build of the core
 * (packages/sylva-trees/src/wasm-debug, built by `scripts/setup.sh --test`). There they are
 * accepted only by a worker started with the debug flag (`?debug=1`; the flag travels as the
 * worker's name), and only a scheduler created with `debug: true` sends them.
 */
import type { WasmApi } from '../core/types';

export { DEBUG_WORKER_NAME } from './debugName';

/** Ask the worker to panic on purpose (tests of the recovery path). */
export interface DebugPanicRequest {
  type: 'debug-panic';
}

/** Ask the worker to busy-loop for `ms` (tests of the time limit). */
export interface DebugHangRequest {
  type: 'debug-hang';
  ms: number;
}

/** Main thread → debug worker, besides the production requests. */
export type DebugRequest = DebugPanicRequest | DebugHangRequest;

/** A `debug-hang` request ended (it ran shorter than the time limit). */
export interface IdleResponse {
  type: 'idle';
}

/** Debug worker → main thread, besides the production responses. */
export type DebugResponse = IdleResponse;

/** Blocks the worker thread for `ms` (lets tests hit the scheduler's time limit). */
export function busyWait(ms: number, now: () => number): void {
  const end = now() + ms;
  while (now() < end) {
    // spin
  }
}

/**
 * The core built with the `debug-hooks` feature: the production API and `debug_panic`; the
 * threaded one also `debug_panic_on_helper` and `threads`.
 */
interface DebugWasm extends WasmApi {
  debug_panic?: () => void;
  debug_panic_on_helper?: () => void;
  threads?: () => number;
}

/**
 * Makes the wasm core panic; throws its trap (the caller reports it as fatal). The threaded
 * core with its helper started panics on the helper, while this worker waits for it (the
 * recovery must not hang). A core without the hook (the shipped one) throws an error saying
 * so, which is fatal as well.
 */
export function panicOnPurpose(wasm: WasmApi): never {
  const core = wasm as DebugWasm;
  if (typeof core.debug_panic_on_helper === 'function' && (core.threads?.() ?? 1) > 1) {
    core.debug_panic_on_helper();
    throw new Error('debug_panic_on_helper() returned without panicking');
  }
  if (typeof core.debug_panic !== 'function') {
    throw new Error('this core has no debug_panic (built without the debug-hooks feature)');
  }
  core.debug_panic();
  throw new Error('debug_panic() returned without panicking');
}

/** What the handler lends a debug request. */
export interface DebugContext {
  wasm: WasmApi;
  /** Posts a debug response. */
  post: (message: DebugResponse, transfer: Transferable[]) => void;
  /** The handler's clock. */
  now: () => number;
  /** Runs `work` as the handler runs a request with no id: a throw is fatal. */
  fatalOnThrow: (work: () => void) => void;
}

/** The debug messages' handling, which a debug worker passes to `createHandler`. */
export interface DebugHooks {
  handle(request: DebugRequest, context: DebugContext): void;
}

/** The test hooks: a busy loop answered with `idle`, and a deliberate panic. */
export const debugHooks: DebugHooks = {
  handle(request, { wasm, post, now, fatalOnThrow }) {
    if (request.type === 'debug-hang') {
      busyWait(request.ms, now);
      post({ type: 'idle' }, []);
    } else {
      fatalOnThrow(() => panicOnPurpose(wasm));
    }
  },
};
