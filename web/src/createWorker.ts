/**
 * The real worker factories: start the module worker that runs the wasm generator. The app's
 * generator worker can be started before the app's code has loaded ([`prestartGenerator`]), so
 * that the worker and its wasm download and compile while the page parses three.js and React.
 */
import type { WorkerFactory } from './worker/scheduler';
import type { WorkerResponse } from './worker/protocol';

function newWorker(): Worker {
  return new Worker(new URL('./worker/worker.ts', import.meta.url), { type: 'module' });
}

/** Adapts `worker` to the scheduler's handle, delivering `pending` (messages so far) first. */
function adapt(
  worker: Worker,
  onMessage: (response: WorkerResponse) => void,
  onError: (message: string) => void,
  pending: { messages: WorkerResponse[]; error: string | null } = { messages: [], error: null },
): ReturnType<WorkerFactory> {
  worker.onmessage = (event: MessageEvent<WorkerResponse>) => onMessage(event.data);
  worker.onerror = (event: ErrorEvent) => {
    event.preventDefault();
    onError(event.message || 'the generator worker failed to load');
  };
  worker.onmessageerror = () => onError('the generator worker sent an unreadable message');
  // Replayed after the caller has its handle (the scheduler stores it before any message).
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

/** Starts `worker/worker.ts` as an ES module worker and adapts it to the scheduler's handle. */
export const createModuleWorker: WorkerFactory = (onMessage, onError) =>
  adapt(newWorker(), onMessage, onError);

/** A generator worker started early, and what it said before anyone listened. */
let early: {
  worker: Worker;
  pending: { messages: WorkerResponse[]; error: string | null };
} | null = null;

/** Starts the app's generator worker now; [`createGeneratorWorker`] takes it over later. */
export function prestartGenerator(): void {
  if (early !== null) return;
  const worker = newWorker();
  const pending = { messages: [] as WorkerResponse[], error: null as string | null };
  worker.onmessage = (event: MessageEvent<WorkerResponse>) => pending.messages.push(event.data);
  worker.onerror = (event: ErrorEvent) => {
    event.preventDefault();
    pending.error = event.message || 'the generator worker failed to load';
  };
  early = { worker, pending };
}

/**
 * The app generator's factory: the first call takes the prestarted worker (if any, with the
 * messages it already sent), later calls (a restart after a crash) start fresh workers.
 */
export const createGeneratorWorker: WorkerFactory = (onMessage, onError) => {
  const claimed = early;
  early = null;
  return claimed
    ? adapt(claimed.worker, onMessage, onError, claimed.pending)
    : createModuleWorker(onMessage, onError);
};
