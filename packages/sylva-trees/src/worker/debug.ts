/**
 * Test hooks of the generator worker, kept out of the production protocol: these messages are
 * accepted only by a worker started with the debug flag (the app's `?debug=1` or a dev build;
 * the flag travels as the worker's name), and only a scheduler created with `debug: true` sends
 * them. They drive the e2e tests of the crash recovery and of the time limit.
 */
import type { WasmApi } from '../core/types';

/** The name a worker is started with when it accepts the debug messages. */
export const DEBUG_WORKER_NAME = 'sylva-debug';

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

/** Makes the wasm core panic; throws its trap (the caller reports it as fatal). */
export function panicOnPurpose(wasm: WasmApi): never {
  wasm.debug_panic();
  throw new Error('debug_panic() returned without panicking');
}
