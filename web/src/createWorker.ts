/**
 * The real worker factories: start the module worker that runs the wasm generator. The app's
 * generator worker can be started before the app's code has loaded ([`prestartGenerator`]), so
 * that the worker and its wasm download and compile while the page parses three.js and React.
 * A debug worker (tests, `?debug=1`) is started under [`DEBUG_WORKER_NAME`].
 */
import type { WorkerHandle, WorkerStartOptions } from './worker/client';
import { DEBUG_WORKER_NAME } from './worker/debug';

function newWorker(debug: boolean): Worker {
  // Vite reads `type` statically: the name (empty for a production worker) comes after it.
  return new Worker(new URL('./worker/worker.ts', import.meta.url), {
    type: 'module',
    name: debug ? DEBUG_WORKER_NAME : '',
  });
}

/** What a worker said before anyone listened. */
interface Early<Res> {
  messages: Res[];
  error: string | null;
}

/** Adapts `worker` to a client's handle, delivering `pending` (messages so far) first. */
function adapt<Req, Res>(
  worker: Worker,
  onMessage: (response: Res) => void,
  onError: (message: string) => void,
  pending: Early<Res> = { messages: [], error: null },
): WorkerHandle<Req> {
  worker.onmessage = (event: MessageEvent<Res>) => onMessage(event.data);
  worker.onerror = (event: ErrorEvent) => {
    event.preventDefault();
    onError(event.message || 'the generator worker failed to load');
  };
  worker.onmessageerror = () => onError('the generator worker sent an unreadable message');
  // Replayed after the caller has its handle (the client stores it before any message).
  if (pending.messages.length > 0 || pending.error !== null) {
    queueMicrotask(() => {
      for (const message of pending.messages) onMessage(message);
      if (pending.error !== null) onError(pending.error);
    });
  }
  return {
    post: (request) => worker.postMessage(request),
    terminate: () => worker.terminate(),
  };
}

/** Starts `worker/worker.ts` as an ES module worker and adapts it to a client's handle. */
export function createModuleWorker<Req, Res>(
  onMessage: (response: Res) => void,
  onError: (message: string) => void,
  options: WorkerStartOptions = {},
): WorkerHandle<Req> {
  return adapt(newWorker(options.debug === true), onMessage, onError);
}

/** A generator worker started early, and what it said before anyone listened. */
let early: { worker: Worker; debug: boolean; pending: Early<unknown> } | null = null;

/** Starts the app's generator worker now; [`createGeneratorWorker`] takes it over later. */
export function prestartGenerator(options: WorkerStartOptions = {}): void {
  if (early !== null) return;
  const debug = options.debug === true;
  const worker = newWorker(debug);
  const pending: Early<unknown> = { messages: [], error: null };
  worker.onmessage = (event: MessageEvent<unknown>) => pending.messages.push(event.data);
  worker.onerror = (event: ErrorEvent) => {
    event.preventDefault();
    pending.error = event.message || 'the generator worker failed to load';
  };
  early = { worker, debug, pending };
}

/**
 * The app generator's factory: the first call takes the prestarted worker (if any, with the
 * messages it already sent, and if it was started with the same debug flag); later calls (a
 * restart after a crash) start fresh workers.
 */
export function createGeneratorWorker<Req, Res>(
  onMessage: (response: Res) => void,
  onError: (message: string) => void,
  options: WorkerStartOptions = {},
): WorkerHandle<Req> {
  const claimed = early;
  early = null;
  if (claimed && claimed.debug === (options.debug === true)) {
    return adapt(claimed.worker, onMessage, onError, claimed.pending as Early<Res>);
  }
  claimed?.worker.terminate();
  return createModuleWorker(onMessage, onError, options);
}
