/**
 * The real worker factories: start the module worker that runs the wasm generator. The app's
 * generator worker can be started before the app's code has loaded ([`prestartGenerator`]), so
 * that the worker and its wasm download and compile while the page parses three.js and React.
 * A debug worker (tests, `?debug=1`) is started under [`DEBUG_WORKER_NAME`].
 */
import {
  adaptWorker,
  DEBUG_WORKER_NAME,
  type EarlyMessages,
  startGeneratorWorker,
  type WorkerHandle,
  type WorkerStartOptions,
} from 'sylva-trees/worker';

function newWorker(debug: boolean): Worker {
  return startGeneratorWorker(debug ? DEBUG_WORKER_NAME : '');
}

/** Starts the package's generator worker as an ES module worker and adapts it to a client's handle. */
export function createModuleWorker<Req, Res>(
  onMessage: (response: Res) => void,
  onError: (message: string) => void,
  options: WorkerStartOptions = {},
): WorkerHandle<Req> {
  return adaptWorker(newWorker(options.debug === true), onMessage, onError);
}

/** A generator worker started early, and what it said before anyone listened. */
let early: { worker: Worker; debug: boolean; pending: EarlyMessages<unknown> } | null = null;

/** Starts the app's generator worker now; [`createGeneratorWorker`] takes it over later. */
export function prestartGenerator(options: WorkerStartOptions = {}): void {
  if (early !== null) return;
  const debug = options.debug === true;
  const worker = newWorker(debug);
  const pending: EarlyMessages<unknown> = { messages: [], error: null };
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
    return adaptWorker(claimed.worker, onMessage, onError, claimed.pending as EarlyMessages<Res>);
  }
  claimed?.worker.terminate();
  return createModuleWorker(onMessage, onError, options);
}
