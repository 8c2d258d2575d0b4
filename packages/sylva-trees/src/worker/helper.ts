/**
 * The helper worker of the threaded core (`threads.ts`): instantiates the module it is sent on
 * the generation worker's shared memory and runs the core's jobs forever (`helperLoop`). A trap
 * here (a panic in a job) wakes the generation worker, which reports it as its own crash and is
 * restarted with a new helper (sylva-core `par::helpers::poison`).
 */
import * as glue from '../wasm-threads/sylva_wasm.js';
import type { HelperMessage } from './threads';

/** The parts of the dedicated-worker global scope this file uses. */
interface HelperScope {
  postMessage(message: HelperMessage): void;
  onmessage:
    | ((event: MessageEvent<{ module: WebAssembly.Module; memory: WebAssembly.Memory }>) => void)
    | null;
}

const scope = self as unknown as HelperScope;
scope.onmessage = (event) => {
  scope.onmessage = null;
  try {
    glue.initSync({ module: event.data.module, memory: event.data.memory });
  } catch (thrown) {
    scope.postMessage({ type: 'failed', message: String(thrown) });
    return;
  }
  scope.postMessage({ type: 'started' });
  try {
    glue.helperLoop();
  } catch (thrown) {
    // Only a trap ends the loop: a panic in a job, which the generation worker reports (with
    // the panic's message) as its own crash, and is restarted with a new helper. Nothing more
    // to say here, and nothing uncaught.
    scope.postMessage({ type: 'trapped', message: String(thrown) });
  }
};
