/** The real worker factory: starts the module worker that runs the wasm generator. */
import type { WorkerFactory } from './worker/scheduler';
import type { WorkerResponse } from './worker/protocol';

/** Starts `worker/worker.ts` as an ES module worker and adapts it to the scheduler's handle. */
export const createModuleWorker: WorkerFactory = (onMessage, onError) => {
  const worker = new Worker(new URL('./worker/worker.ts', import.meta.url), { type: 'module' });
  worker.onmessage = (event: MessageEvent<WorkerResponse>) => onMessage(event.data);
  worker.onerror = (event: ErrorEvent) => {
    event.preventDefault();
    onError(event.message || 'the generator worker failed to load');
  };
  worker.onmessageerror = () => onError('the generator worker sent an unreadable message');
  return {
    post: (request) => worker.postMessage(request),
    terminate: () => worker.terminate(),
  };
};
