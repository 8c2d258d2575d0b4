/**
 * A Web Worker as a worker client sees it ([`WorkerHandle`]): its messages, its load and
 * message errors, and the messages it sent before anyone listened (a worker started early).
 */
import type { WorkerHandle } from '../worker/client';

/** What a worker said before anyone listened. */
export interface EarlyMessages<Res> {
  messages: Res[];
  error: string | null;
}

/** Adapts `worker` to a client's handle, delivering `pending` (messages so far) first. */
export function adaptWorker<Req, Res>(
  worker: Worker,
  onMessage: (response: Res) => void,
  onError: (message: string) => void,
  pending: EarlyMessages<Res> = { messages: [], error: null },
  loadError = 'the generator worker failed to load',
): WorkerHandle<Req> {
  worker.onmessage = (event: MessageEvent<Res>) => onMessage(event.data);
  worker.onerror = (event: ErrorEvent) => {
    event.preventDefault();
    onError(event.message || loadError);
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
